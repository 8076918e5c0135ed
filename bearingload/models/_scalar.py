"""One case of the ring equilibrium in pure Python: the fast path of ``solve`` for scalar input.

Python users call ``solve`` in loops (optimisers, time-stepping rotor models); for one case the
numpy machinery costs more than the arithmetic. This module solves the same equations as
:mod:`bearingload.models._ring` (same formulations, starts, acceptance rules and loaded-ball
rule) with ``math`` on Python floats, and builds the same LoadDistribution. Any input it does not
take as plainly valid goes back to the vectorised path, which raises the proper InputError.
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np

from bearingload.errors import ConvergenceError
from bearingload.models import _ring

EPS = _ring.EPS
_NUMBER = (int, float, np.integer, np.floating)


def is_one_case(*values: Any) -> bool:
    """True when every input is a plain real scalar (no array, no bool)."""
    for v in values:
        kind = type(v)
        if kind is not float and kind is not int:
            if not isinstance(v, _NUMBER) or isinstance(v, (bool, np.bool_)):
                return False
    return True


@functools.lru_cache(maxsize=4096)
def _symmetric(z: int, half: bool, preload: bool) -> tuple[Any, ...]:
    ring = _ring.Ring.symmetric(z, half, preload)
    return (
        ring.c.tolist(),
        ring.s.tolist(),
        ring.u.tolist(),
        ring.w.tolist(),
        float(ring.x0),
        float(ring.y0),
        float(ring.mu),
        float(ring.h),
        float(ring.c_max),
        float(ring.w_max),
    )


@functools.lru_cache(maxsize=1024)
def _general(z: int, frac: float, preload: bool) -> tuple[Any, ...]:
    """All z balls, ball 1 at ``frac`` of a pitch, frac in (0, 1): ``Ring.general`` for one case,
    its cosines and sines those of ``Ring.in_load_frame`` (from the ball nearest the load line,
    whose angle keeps its digits however near the load line)."""
    pitch = 2.0 * math.pi / z
    mu, h = frac * 2.0 * math.pi / z - pitch / 2.0, pitch / 2.0
    last = frac > 0.5
    tau = (1.0 - frac if last else frac) * 2.0 * math.pi / z
    sign = -1.0 if last else 1.0
    cj, sj, u = (a.tolist() for a in _ring.pitch_table(z, preload))
    ct, st = math.cos(tau), math.sin(tau)
    snap = _ring.SNAP
    c = [ct * a - st * b for a, b in zip(cj, sj, strict=True)]
    s = [st * a + ct * b for a, b in zip(cj, sj, strict=True)]
    c = [0.0 if -snap < v < snap else v for v in c]
    s = [0.0 if -snap < v < snap else sign * v for v in s]
    cos_h = math.cos(h)
    x0 = 0.0 if preload else math.cos(mu) / cos_h
    y0 = 0.0 if preload else math.sin(mu) / cos_h
    return c, s, u, [1.0] * z, x0, y0, mu, h, c[0], 1.0


def _state(
    ring: tuple[Any, ...], xi: float, eta: float, e_hat: float, m: float, pre: bool
) -> tuple:
    """(gx, gy, hxx, hxy, hyy, size, energy) at (xi, eta): ``_ring.state`` for one case."""
    c, s, u, w = ring[:4]
    gx = gy = hxx = hxy = hyy = qsum = en = 0.0
    if pre:
        p = -e_hat
        pm, pm1 = p**m, p ** (m - 1.0)
        for ci, si, wi in zip(c, s, w, strict=True):
            t = (xi * ci + eta * si) / p
            if t > -1.0:
                lg = math.log1p(t)
                term, q = pm * math.expm1(m * lg), pm * math.exp(m * lg)
                dq = m * pm1 * math.exp((m - 1.0) * lg)
                br = math.expm1((m + 1.0) * lg) - (m + 1.0) * t
            else:
                term, q, dq, br = -pm, 0.0, 0.0, -1.0 - (m + 1.0) * t
            wt, wdq = wi * term, wi * dq
            gx, gy, qsum = gx + wt * ci, gy + wt * si, qsum + abs(wt)
            hxx, hxy, hyy = hxx + wdq * ci * ci, hxy + wdq * ci * si, hyy + wdq * si * si
            en += wi * pm * (p * br)
    else:
        sqrt, power = m == 1.5, m - 1.0
        for ci, si, ui, wi in zip(c, s, u, w, strict=True):
            d = xi * ci + eta * si - e_hat * ui
            if d <= 0.0:
                continue
            r = math.sqrt(d) if sqrt else d**power
            q = wi * (d * r)
            dq = wi * (m * r)
            gx += q * ci
            gy += q * si
            qsum += q
            en += q * d
            dc = dq * ci
            hxx += dc * ci
            hxy += dc * si
            hyy += dq * si * si
    return gx - 1.0, gy, hxx, hxy, hyy, max(1.0, qsum), en / (m + 1.0) - xi


@functools.lru_cache(maxsize=4096)
def _ring_sums(z: int, half: bool, preload: bool, m: float) -> tuple[float, float, float]:
    """(xi0, slope, sum w c^2) of the symmetric start, from the same numpy sums as ``_starts``."""
    ring = _ring.Ring.symmetric(z, half, preload)
    c, u, w = ring.c, ring.u, ring.w
    front = c > 0
    sum_c = float(np.sum(w[front] * c[front] ** (m + 1.0)))
    slope = float(np.sum(w[front] * c[front] ** m * u[front])) / sum_c
    return sum_c ** (-1.0 / m), slope, float(np.sum(w * c * c))


def _solve_x(ring: tuple, key: Any, e_hat: float, m: float, pre: bool, tol: float) -> tuple:
    """Bracketed Newton on the x-equilibrium (``_ring.solve_x`` for one case): (xi, its)."""
    c_max, w_max = ring[8], ring[9]
    hi = (1.0 / (w_max * c_max)) ** (1.0 / m) / c_max
    start = hi
    if key is not None:
        xi0, slope, sum_c2 = _ring_sums(*key, m)
        if pre:
            start = min(1.0 / (m * (-e_hat) ** (m - 1.0) * sum_c2), hi)
        else:
            start = min(xi0 + slope * e_hat, hi)
    if pre:
        for _ in range(2100):
            if _state(ring, hi, 0.0, e_hat, m, pre)[0] >= 0:
                break
            hi *= 2.0
    lo, x = 0.0, start
    for it in range(1, _ring.MAX_ITERATIONS + 1):
        g, _, dg, _, _, size, _ = _state(ring, x, 0.0, e_hat, m, pre)
        if g < 0:
            lo = x
        elif g > 0:
            hi = x
        new = x - g / dg if dg != 0 else math.nan
        if not lo < new < hi:
            new = 0.5 * (lo + hi)
        met = abs(g / size) <= tol
        if met or abs(new - x) <= 4 * EPS * abs(x):
            polish = met and tol <= _ring.POLISH and new == x - g / dg
            return (new if polish else x), it
        x = new
    raise ConvergenceError("symmetric ring equilibrium", it, math.inf, {"e_hat": e_hat, "m": m})


def _start_xy(ring: tuple, e_hat: float, m: float, pre: bool) -> float:
    """Start of the general path: the half-pitch ring's start (its reference is alike)."""
    z = len(ring[0])
    c_max = ring[8]
    hi = (1.0 / c_max) ** (1.0 / m) / c_max
    xi0, slope, sum_c2 = _ring_sums(z, True, pre, m)
    if pre:
        return min(1.0 / (m * (-e_hat) ** (m - 1.0) * sum_c2), hi)
    return min(xi0 + slope * e_hat, hi)


def _newton_step(st: tuple) -> tuple[float, float]:
    gx, gy, hxx, hxy, hyy = st[:5]
    reg = 1e-12 * (hxx + hyy) + 1e-300
    hxx, hyy = hxx + reg, hyy + reg
    det = hxx * hyy - hxy * hxy
    return -(hyy * gx - hxy * gy) / det, -(hxx * gy - hxy * gx) / det


def _solve_xy(ring: tuple, e_hat: float, m: float, pre: bool, tol: float) -> tuple:
    """Damped Newton in (xi, eta) (``_ring.solve_xy`` for one case): (xi, eta, iterations)."""
    xi, eta, its = _start_xy(ring, e_hat, m, pre), 0.0, 0
    gx, gy, hxx, hxy, hyy, size, energy = _state(ring, xi, eta, e_hat, m, pre)
    polish = tol <= _ring.POLISH
    previous = math.inf
    hypot = math.hypot
    for _ in range(_ring.MAX_ITERATIONS):
        gnorm = hypot(gx, gy)
        reg = 1e-12 * (hxx + hyy) + 1e-300
        hxx, hyy = hxx + reg, hyy + reg
        det = hxx * hyy - hxy * hxy
        dx, dy = -(hyy * gx - hxy * gy) / det, -(hxx * gy - hxy * gx) / det
        if gnorm <= tol * size:
            if its and polish:  # the last Newton step too, as the vector path
                return xi + dx, eta + dy, its
            return xi, eta, its
        step = hypot(dx, dy) / hypot(xi, eta)
        if its and polish and step <= 1e-9 and step <= 1e-3 * previous:
            # quadratic convergence seen (steps 1e-3 times the last, <= 1e-9): the next error
            # is below step^3/previous^2 <= 1e-15; the residual at the point returned is
            # checked by the caller (else the vectorised path solves the case)
            return xi + dx, eta + dy, its + 1
        previous = step
        slope = gx * dx + gy * dy
        t = 1.0
        for _ in range(81):
            trial = _state(ring, xi + t * dx, eta + t * dy, e_hat, m, pre)
            if hypot(trial[0], trial[1]) < 0.5 * gnorm or trial[6] <= energy + 1e-4 * t * slope:
                break
            t *= 0.5
        na, nb = xi + t * dx, eta + t * dy
        small = hypot(na - xi, nb - eta) <= 4 * EPS * hypot(na, nb) + 1e-300
        xi, eta, its = na, nb, its + 1
        gx, gy, hxx, hxy, hyy, size, energy = trial
        if small:
            if hypot(gx, gy) <= tol * size and polish:
                dx, dy = _newton_step(trial)
                return xi + dx, eta + dy, its
            return xi, eta, its
    raise ConvergenceError("ring equilibrium at a general cage angle", its, math.nan, {})


def _derived(
    ring: tuple, xi: float, eta: float, e_hat: float, m: float, pre: bool, folded: bool
) -> tuple:
    """(q_hat, loaded, hxx, hxy, hyy, residual) with the loaded-ball rule of ``_ring.derived``.

    ``residual``: the relative force residual at the point, the proof of an early last step;
    ``folded``: a symmetric half ring, whose transverse forces cancel with the mirror half.
    """
    c, s, u, w = ring[:4]
    q_hat = loaded = hxx = hxy = hyy = gx = gy = size = 0.0
    p = -e_hat
    # a ball clears every rounding bound when its approach exceeds this (u <= 1 + 1/cos h <= 3)
    clear = 8 * EPS * (abs(xi) + abs(eta) + 4.0 * abs(e_hat))
    for ci, si, ui, wi in zip(c, s, u, w, strict=True):
        move = xi * ci + eta * si
        if pre:
            t = move / p
            if not t > -1.0:
                continue
            lg = math.log1p(t)
            d, q = p + move, p**m * math.exp(m * lg)
            dq = m * p ** (m - 1.0) * math.exp((m - 1.0) * lg)
            term = wi * p**m * math.expm1(m * lg)
        else:
            d = move - e_hat * ui
            if d <= 0.0:
                continue
            if m == 1.5:
                r = math.sqrt(d)
                q, dq = d * r, 1.5 * r
            else:
                pm1 = d ** (m - 1.0)
                q, dq = d * pm1, m * pm1
            term = wi * q
        gx, gy, size = gx + term * ci, gy + term * si, size + abs(term)
        if not d > clear and not d > 8 * EPS * (abs(xi * ci) + abs(eta * si) + abs(e_hat * ui)):
            continue
        q_hat, loaded = max(q_hat, q), loaded + wi
        wdq = wi * dq
        hxx, hxy, hyy = hxx + wdq * ci * ci, hxy + wdq * ci * si, hyy + wdq * si * si
    if pre:  # the balls left out above each add -p^m to the sums
        for ci, si, wi in zip(c, s, w, strict=True):
            if not (xi * ci + eta * si) / p > -1.0:
                gx, gy, size = gx - wi * p**m * ci, gy - wi * p**m * si, size + wi * p**m
    residual = math.hypot(gx - 1.0, 0.0 if folded else gy) / max(1.0, size)
    return q_hat, loaded, hxx, hxy, hyy, residual


def _plain(balls: Any, load: Any, stiffness: Any, clearance: Any, cage: Any, m: Any) -> Any:
    """The inputs as Python numbers when each is plainly valid, else None (the vector path)."""
    try:
        z, f, k, g, a, mm = (float(v) for v in (balls, load, stiffness, clearance, cage, m))
    except (TypeError, ValueError, OverflowError):
        return None
    finite = all(math.isfinite(v) for v in (f, k, g, a))
    if not (finite and z == int(z) and 1 <= z <= 100_000 and f > 0 and k > 0 and 1 <= mm <= 3):
        return None
    return int(z), f, k, g, a, mm


def _kind(z: int, cage: float, phi1_deg: float) -> tuple[float, int]:
    """``_cage_kind`` of the vectorised path for one case (same operations)."""
    pitch_deg = 360.0 / z
    frac = (phi1_deg % pitch_deg) / pitch_deg
    mirror = (math.fmod(abs(cage), 360.0) % pitch_deg) / pitch_deg
    snap = _ring.SYMMETRY_SNAP_DEG / pitch_deg
    if mirror <= snap or mirror >= 1.0 - snap:
        return frac, 0
    return frac, 1 if abs(mirror - 0.5) <= snap else 2


def _in_range(f: float, scale: float, e_hat: float, m: float, z: int) -> bool:
    """``check_range`` of the vectorised path, as a test (False: let it raise)."""
    if -1.0 <= e_hat <= 1e90 and 1e-90 <= scale <= 1e90 and 1e-250 <= f <= 1e250:
        if 1e-250 <= f / scale <= 1e250:  # inside every bound with room to spare
            return True
    lo, hi = _ring.APPROACH_RANGE
    if not (lo <= scale <= hi and abs(e_hat) <= _ring.CLEARANCE_RATIO_MAX):
        return False
    log_p = math.log10(max(1.0, -e_hat))
    log_q = math.log10(f) + m * log_p
    log_k = math.log10(f / scale) + math.log10(m * z) + (m - 1.0) * log_p
    r_lo, r_hi = (math.log10(v) for v in _ring.RESULT_RANGE)
    return (
        log_q <= r_hi and log_k <= r_hi and math.log10(f / scale) >= r_lo and math.log10(f) >= r_lo
    )


def solve_one(*values: Any) -> Any:
    """Solve one case (inputs as for ``solve``, then the tolerance): the fields of its
    ``OneCase`` (``equilibrium.solve`` builds it), or None: use the vector path."""
    plain = _plain(*values[:6])
    if plain is None:
        return None
    z, f, k, g, cage, m = plain
    tol = values[6]
    phi1_deg = cage % 360.0
    try:
        scale = (f / k) ** (1.0 / m)
        e_hat = (g / 2.0) / scale
        if not _in_range(f, scale, e_hat, m, z):
            return None
    except (ZeroDivisionError, OverflowError, ValueError):
        return None  # outside the range: the vectorised path says why
    frac, kind = _kind(z, cage, phi1_deg)
    if z < 3 and kind != 0:
        return None
    pre = e_hat < -_ring.PRELOAD_CENTRED and z >= 2
    try:  # where this one stalls the vectorised path's search goes on (or names the case)
        if kind == 2:
            ring = _general(z, frac, pre)
            xi, eta, its = _solve_xy(ring, e_hat, m, pre, tol)
        else:
            ring = _symmetric(z, kind == 1, pre)
            xi, its = _solve_x(ring, (z, kind == 1, pre), e_hat, m, pre, tol)
            eta = 0.0
    except ConvergenceError:
        return None
    q_hat, loaded, hxx, hxy, hyy, residual = _derived(ring, xi, eta, e_hat, m, pre, kind != 2)
    if not residual <= max(tol, 1e-11):
        return None  # not proven here: the vectorised path solves it (or says why not)
    if kind != 2:
        hxy = 0.0  # a folded symmetric ring: the mirror halves cancel exactly
    return _result(plain, phi1_deg, scale, ring, (xi, eta, its), (q_hat, loaded, hxx, hxy, hyy))


def _result(
    plain: tuple, phi1_deg: float, scale: float, ring: tuple, sol: tuple, der: tuple
) -> Any:
    """The fields of one case's LoadDistribution, as ``_assemble`` builds them (the class builds
    the arrays on access)."""
    z, f, k, g, _, m = plain
    xi, eta, its = sol
    q_hat, loaded, hxx, hxy, hyy = der
    x0, y0, mu, h = ring[4:8]
    e = g / 2.0
    x, y = e * x0 + xi * scale, e * y0 + eta * scale
    r = math.hypot(x, y)
    if e > 0:
        r2_e2 = (
            (e * math.tan(h)) ** 2
            + 2.0 * e * scale * (x0 * xi + y0 * eta)
            + (scale * xi) ** 2
            + (scale * eta) ** 2
        )
        one_minus = max(r2_e2, 0.0) / (r * (r + e))
    else:
        one_minus = 1.0 - e / r
    zone = math.degrees(2.0 * math.asin(math.sqrt(min(max(one_minus, 0.0), 2.0) / 2.0)))
    kn = f / scale
    kxy = hxy * kn
    values = {
        "balls": z,
        "load": f,
        "stiffness": k,
        "clearance": g,
        "cage_angle": phi1_deg,
        "exponent": m,
        "x": x,
        "y": y,
        "q_max": q_hat * f,
        "loaded_balls": int(round(loaded)),
        "load_zone": zone,
        "stiffness_matrix": [[hxx * kn, kxy], [kxy, hyy * kn]],
        "iterations": its,
        "offset": [xi * scale, eta * scale],
        "reference": [mu, h],
    }
    return values
