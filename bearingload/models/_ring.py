"""Internals of the ring-equilibrium engine: rings of balls, scaled forces and the Newton solvers.

Everything here works in scaled units: lengths over the one-ball approach ``s = (F_r/K)^(1/m)``,
forces over ``F_r``. Two formulations keep the digits (see :mod:`bearingload.models.equilibrium`):

* clearance >= 0: the unknown ``(xi, eta)`` is the displacement from the reference position
  where the balls nearest the load line just touch; ball approach ``xi c + eta s - e_hat u``.
* preload (clearance < 0, z >= 2): the unknown is the displacement from the centred ring; ball
  approach ``p + xi c + eta s`` with ``p = -e_hat``, and the ball forces are summed as
  ``p^m ((1 + t)^m - 1)``, ``t = (xi c + eta s)/p`` (the ``p^m`` terms cancel exactly around a
  full ring), so a heavy preload does not swamp the load.

Every operation is row-wise (one case per row, sums along the row), so a case's answer does not
depend on the other cases solved with it.

A general cage angle: ball ``j`` sits at ``phi_1 + j pitch``. The Newton iterations work in the
frame of the ball nearest the load line (turned by its angle ``tau``, at most half a pitch, per
case), where the ball angles and their cosines and sines are the same for every case of one
``z``: one shared row instead of a row per case, gathered again at every evaluation. The forces
and the Jacobian are turned back; the rounding this adds is ``eps |sin(tau)|`` of the sums, and
``tau`` is the angle of a ball that carries load at the equilibrium, so it stays proportional
to the angles of the loaded balls, as in the load frame. The result quantities (:func:`derived`)
are computed in the load frame, with the cosines of the one-case path.
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np

from bearingload.errors import ConvergenceError

EPS = float(np.finfo(float).eps)
#: Iteration cap of every Newton loop; reaching it raises ConvergenceError.
MAX_ITERATIONS = 200
#: At tolerances up to this the converged point gets one more Newton step (rounding level). [-]
POLISH = 1e-13
#: Preloads |e|/s above this are solved from the centred ring (below, from the touching one). [-]
PRELOAD_CENTRED = 1e-50
#: Trials of a general ring's line search after which its step becomes the x part alone: where
#: the loaded balls barely resist a move across the load line the Newton step there is huge,
#: and halving the whole step takes x's part down with it (3 or 4 balls under preload, the cage
#: 1e-11° off the load line: x stalled 5e-7 of the load off its equilibrium). [-]
DECOUPLE = 12
#: A cage angle within this of 0 or half pitch is symmetric: 4 ulps of 360°, the rounding of
#: reducing an angle to one turn and one pitch. [°]
SYMMETRY_SNAP_DEG = 4.0 * EPS * 360.0
#: Cosines and sines below this are rounding of an exact zero. [-]
SNAP = 1e-14
#: Range of the one-ball approach (F_r/K)^(1/m) the solver accepts, and of the clearance in
#: units of it: inside it every intermediate value is a normal double. [mm], [-]
APPROACH_RANGE = (1e-100, 1e100)
CLEARANCE_RATIO_MAX = 1e100
#: Largest and smallest magnitude of a result (ball load [N], stiffness [N/mm]) accepted. [-]
RESULT_RANGE = (1e-300, 1e300)


def snapped_cos(phi: np.ndarray) -> np.ndarray:
    c = np.cos(phi)
    return np.where(np.abs(c) < SNAP, 0.0, c)


def snapped_sin(phi: np.ndarray) -> np.ndarray:
    s = np.sin(phi)
    return np.where(np.abs(s) < SNAP, 0.0, s)


def gap_factor(theta: np.ndarray, h: float) -> np.ndarray:
    """``u = 1 - cos(theta)/cos(h)`` without cancellation; rounding of an exact 0 is 0."""
    u = 2.0 * np.sin((theta + h) / 2.0) * np.sin((theta - h) / 2.0) / np.cos(h)
    return np.where(u < 1e-13, 0.0, u)


class Ring:
    """A set of ball angles and the reference position of its formulation (read-only).

    ``c, s``: cosine and sine of each angle; ``u``: gap factor of each ball (the reference
    formulation; all 1 for a preload); ``w``: multiplicity of each angle. Arrays are shared,
    shape (k,), or per case, shape (n, k). ``x0, y0``: reference position over ``e`` (0 under
    preload); ``mu, h``: the straddling balls nearest the load line sit at ``mu -+ h``.
    ``turn``: per case, (cos, sin) of the angle of the ball nearest the load line and the sign of
    y (-1: the mirror image) when c, s are shared in its frame (a general ring), else None.

    A plain class, not a dataclass: a frozen dataclass of these fields costs about 0.5 ms of
    every terminal command's start-up to create.
    """

    __slots__ = ("c", "s", "u", "w", "x0", "y0", "c_max", "w_max", "mu", "h", "preload", "turn",
                 "_products")  # fmt: skip

    def __init__(
        self,
        *,
        c: np.ndarray,
        s: np.ndarray,
        u: np.ndarray,
        w: np.ndarray,
        x0: Any,
        y0: Any,
        c_max: Any,
        w_max: Any,
        mu: Any,
        h: float,
        preload: bool,
        turn: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None,
    ) -> None:
        self.c, self.s, self.u, self.w = c, s, u, w
        self.x0, self.y0, self.c_max, self.w_max = x0, y0, c_max, w_max
        self.mu, self.h, self.preload, self.turn = mu, h, preload, turn
        self._products: tuple[np.ndarray, ...] | None = None

    def replace(self, **changes: Any) -> Ring:
        """A copy with ``changes`` (field name -> value)."""
        fields = {name: getattr(self, name) for name in self.__slots__[:-1]}
        return Ring(**{**fields, **changes})

    @staticmethod
    def build(
        phi: np.ndarray, w: np.ndarray, mu: Any, h: float, front: bool, preload: bool
    ) -> Ring:
        """``phi``: angles, shape (k,) shared or (n, k) per case; ``mu``: scalar or (n,)."""
        mu = np.asarray(mu, dtype=float)
        if front:  # clearance >= 0: balls at 90 degrees or beyond can never carry load
            keep = np.cos(phi) > SNAP
            phi, w = phi[keep], w[keep]
        c, s = snapped_cos(phi), snapped_sin(phi)
        theta = phi - (mu[..., None] if mu.ndim else mu)
        top = np.argmax(c, axis=-1)
        c_max = np.take_along_axis(c, top[..., None], -1)[..., 0] if c.ndim == 2 else c[top]
        w_max = np.take_along_axis(w, top[..., None], -1)[..., 0] if w.ndim == 2 else w[top]
        zero = np.zeros_like(mu)
        return Ring(
            c=c,
            s=s,
            u=np.ones_like(c) if preload else gap_factor(theta, h),
            w=w,
            x0=zero if preload else np.cos(mu) / np.cos(h),
            y0=zero if preload else np.sin(mu) / np.cos(h),
            c_max=np.asarray(c_max, dtype=float),
            w_max=np.asarray(w_max, dtype=float),
            mu=mu,
            h=h,
            preload=preload,
        )

    @property
    def products(self) -> tuple[np.ndarray, ...]:
        """(c, s, w, wc, ws, wcc, wcs, wss): the weighted products the sums use, once per ring."""
        if self._products is None:
            wc, ws = self.w * self.c, self.w * self.s
            self._products = (self.c, self.s, self.w, wc, ws, wc * self.c, wc * self.s,
                              ws * self.s)  # fmt: skip
        return self._products

    @classmethod
    @functools.lru_cache(maxsize=4096)
    def symmetric(cls, z: int, half_pitch: bool, preload: bool) -> Ring:
        """Half of a ring symmetric about the load line, each angle with its multiplicity."""
        j = np.arange(z)
        phi = (j + (0.5 if half_pitch else 0.0)) * 2.0 * np.pi / z
        phi = np.minimum(phi, 2.0 * np.pi - phi)  # fold the lower half onto the upper half
        uniq, counts = np.unique(np.round(phi / np.pi * 2 * z) / (2 * z), return_counts=True)
        h = np.pi / z if half_pitch else 0.0
        return cls.build(uniq * np.pi, counts.astype(float), 0.0, h, not preload, preload)

    @classmethod
    def general(cls, z: int, frac: np.ndarray, preload: bool) -> Ring:
        """All z balls of each case, ball 1 at ``frac`` of a pitch from the load line, frac in
        (0, 1), shape (n,).

        Shared ``c, s, u`` (:func:`pitch_table`) in the frame of the ball nearest the load
        line; ``turn``: per case, cos and sin of its angle ``tau`` (made >= 0 by the mirror
        image when it is ball z) and the sign of ``y`` in the mirror image (-1: mirrored).
        :meth:`in_load_frame` gives the per-case cosines and sines.
        """
        h = np.pi / z
        last = frac > 0.5
        # the mirror image of a ring whose ball z is nearest: its ball 1 at 1 - frac (exact),
        # so the angle of the nearest ball keeps its digits however near the load line
        tau = np.where(last, 1.0 - frac, frac) * 2.0 * np.pi / z
        mu = frac * 2.0 * np.pi / z - h
        cj, sj, u = pitch_table(z, preload)
        zero = np.zeros_like(mu)
        ct = np.cos(tau)
        return Ring(
            c=cj,
            s=sj,
            u=u,
            w=np.ones(z),
            x0=zero if preload else np.cos(mu) / math.cos(h),
            y0=zero if preload else np.sin(mu) / math.cos(h),
            c_max=_snap(ct),
            w_max=np.ones_like(mu),
            mu=mu,
            h=h,
            preload=preload,
            turn=(ct, np.sin(tau), np.where(last, -1.0, 1.0)),
        )

    def in_load_frame(self) -> Ring:
        """The same ring with per-case cosines and sines, ``cos(tau + k pitch)`` from the turn
        and the shared table (sines negated in a mirror image), as the one-case path computes
        them; itself when not turned."""
        if self.turn is None:
            return self
        ct, st, sign = (a[:, None] for a in self.turn)
        c = _snap(ct * self.c - st * self.s)
        s = sign * _snap(st * self.c + ct * self.s)
        return self.replace(c=c, s=s, turn=None)


def _snap(a: np.ndarray) -> np.ndarray:
    """Cosines and sines below SNAP set to an exact zero."""
    return np.where(np.abs(a) < SNAP, 0.0, a)


@functools.lru_cache(maxsize=1024)
def pitch_table(z: int, preload: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """cos and sin of ``k pitch`` and the gap factors of a general ring (z alone), k = 0..z-1.

    Entry ``k`` is ball ``k + 1``, at ``theta = (k + 1/2) pitch`` from the reference angle
    ``mu`` whatever the cage angle. With ``math`` (the one-case path uses the same numbers);
    read-only arrays.
    """
    pitch = 2.0 * math.pi / z
    h = pitch / 2.0
    theta = [(j + 0.5) * pitch for j in range(z)]
    u = [2.0 * math.sin((t + h) / 2.0) * math.sin((t - h) / 2.0) / math.cos(h) for t in theta]
    u = [1.0 if preload else (0.0 if v < 1e-13 else v) for v in u]
    tables = (
        np.array([math.cos(j * pitch) for j in range(z)]),
        np.array([math.sin(j * pitch) for j in range(z)]),
        np.array(u),
    )
    for a in tables:
        a.flags.writeable = False
    return tables


#: Cases of a ring: indices, or ``slice(None)`` for all of them (a view, no copy).
Index = np.ndarray | slice
ALL: slice = slice(None)


def rows(a: np.ndarray, idx: Index) -> np.ndarray:
    """Rows ``idx`` of a per-case (2-D) ring array; a shared (1-D) ring array as it is."""
    return a if a.ndim == 1 else a[idx]


class State:
    """Scaled forces at a ring position: residual ``(gx, gy)``, Hessian, size, energy, loads.

    ``gx`` ... ``energy`` per case, ``q, dq, delta`` per ball (a plain class: see Ring).
    """

    __slots__ = ("gx", "gy", "hxx", "hxy", "hyy", "size", "energy", "q", "dq", "delta")

    def __init__(
        self,
        gx: np.ndarray,
        gy: np.ndarray,
        hxx: np.ndarray,
        hxy: np.ndarray,
        hyy: np.ndarray,
        size: np.ndarray,
        energy: np.ndarray,
        q: np.ndarray,
        dq: np.ndarray,
        delta: np.ndarray,
    ) -> None:
        self.gx, self.gy, self.hxx, self.hxy, self.hyy = gx, gy, hxx, hxy, hyy
        self.size, self.energy, self.q, self.dq, self.delta = size, energy, q, dq, delta


def dot(a: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Row sums of ``a * v`` (``v`` shared (k,) or per case (n, k)).

    einsum, not BLAS: a matrix-vector product may sum a row in an order that depends on the
    number of rows, and a case's answer must not depend on its batch.
    """
    return np.einsum("ij,j->i", a, v) if v.ndim == 1 else np.einsum("ij,ij->i", a, v)


def products(ring: Ring, idx: Index) -> tuple[np.ndarray, ...]:
    """(c, s, w, wc, ws, wcc, wcs, wss) of the ring for the cases ``idx``."""
    return tuple(rows(a, idx) for a in ring.products)


def state(
    ring: Ring,
    idx: Index,
    xi: np.ndarray,
    eta: np.ndarray | None,
    e_hat: np.ndarray,
    m: np.ndarray,
) -> State:
    """Scaled ball loads, the force residual and its Jacobian at ``(xi, eta)`` (``eta`` None: 0).

    A turned ring (``ring.turn``) is evaluated in the frame of the ball nearest the load line
    (of the mirror image where that is ball z) and its forces and Jacobian turned back to the
    load frame; ``q``, ``dq``, ``delta`` are per ball either way.
    """
    c, s, w, wc, ws, wcc, wcs, wss = products(ring, idx)
    mm = m[:, None]
    a, b = xi, eta
    if ring.turn is not None and eta is not None:
        cp, sp, sign = (t[idx] for t in ring.turn)
        mirrored = sign * eta
        a, b = cp * xi + sp * mirrored, cp * mirrored - sp * xi
    move = a[:, None] * c
    if b is not None:
        move = move + b[:, None] * s
    with np.errstate(all="ignore"):
        if ring.preload:
            p = -e_hat[:, None]
            t = move / p
            touching = t > -1.0
            lg = np.log1p(np.where(touching, t, 0.0))
            pm = p**mm
            terms = np.where(touching, pm * np.expm1(mm * lg), -pm)  # q - p^m
            q = np.where(touching, pm * np.exp(mm * lg), 0.0)
            dq = np.where(touching, mm * p ** (mm - 1.0) * np.exp((mm - 1.0) * lg), 0.0)
            bracket = np.where(touching, np.expm1((mm + 1.0) * lg), -1.0) - (mm + 1.0) * t
            energy = dot(pm * (p * bracket), w) / (m + 1.0) - xi
            delta = p + move
            size = np.maximum(1.0, dot(np.abs(terms), w))
        else:
            delta = move - e_hat[:, None] * rows(ring.u, idx)
            pos = np.maximum(delta, 0.0)
            q, dq = _powers(pos, m)
            terms = q
            energy = dot(q * pos, w) / (m + 1.0) - xi
            size = np.maximum(1.0, dot(q, w))
        gx = dot(terms, wc)
        zero = np.zeros_like(gx)
        gy = dot(terms, ws) if eta is not None else zero
        hxx = dot(dq, wcc)
        hxy = dot(dq, wcs) if eta is not None else zero
        hyy = dot(dq, wss)
        if ring.turn is not None and eta is not None:
            gx, gy, hxx, hxy, hyy = _turned_back(cp, sp, gx, gy, hxx, hxy, hyy)
            gy, hxy = sign * gy, sign * hxy
        gx = gx - 1.0
    return State(gx, gy, hxx, hxy, hyy, size, energy, q, dq, delta)


def _turned_back(
    cp: np.ndarray,
    sp: np.ndarray,
    gx: np.ndarray,
    gy: np.ndarray,
    hxx: np.ndarray,
    hxy: np.ndarray,
    hyy: np.ndarray,
) -> tuple[np.ndarray, ...]:
    """Force ``g`` and Jacobian ``H`` of the frame of ball 1 in the load frame: ``R g``,
    ``R H R^T``, ``R`` the turn by ``phi_1`` (cos ``cp``, sin ``sp``)."""
    cc, ss, cs = cp * cp, sp * sp, cp * sp
    two_cs_hxy = 2.0 * cs * hxy
    return (
        cp * gx - sp * gy,
        sp * gx + cp * gy,
        cc * hxx - two_cs_hxy + ss * hyy,
        cs * (hxx - hyy) + (cc - ss) * hxy,
        ss * hxx + two_cs_hxy + cc * hyy,
    )


def _powers(pos: np.ndarray, m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``pos^m`` and ``m pos^(m-1)`` (a square root for m = 3/2; one rule per group of cases)."""
    if np.all(m == 1.5):
        root = np.sqrt(pos)
        return pos * root, 1.5 * root
    mm = m[:, None]
    with np.errstate(all="ignore"):
        pm1 = np.where(pos > 0, pos ** (mm - 1.0), 0.0)
    return pos * pm1, mm * pm1


def x_state(
    ring: Ring, idx: np.ndarray, xi: np.ndarray, e_hat: np.ndarray, m: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(gx, dgx/dxi, size) with ``eta = 0``: the lean evaluation of the symmetric solver."""
    if ring.preload:
        st = state(ring, idx, xi, None, e_hat, m)
        return st.gx, st.hxx, st.size
    c, _, w, wc, _, wcc, _, _ = products(ring, idx)
    delta = xi[:, None] * c
    delta -= e_hat[:, None] * rows(ring.u, idx)
    np.maximum(delta, 0.0, out=delta)
    q, dq = _powers(delta, m)
    return dot(q, wc) - 1.0, dot(dq, wcc), np.maximum(1.0, dot(q, w))


def _starts(ring: Ring, e_hat: np.ndarray, m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Start and upper bound of the symmetric x-equilibrium, each from the case's data alone."""
    with np.errstate(all="ignore"):
        hi = (1.0 / (ring.w_max * ring.c_max)) ** (1.0 / m) / ring.c_max
    start = hi.copy()
    if ring.c.ndim == 1:
        c, u, w = ring.c, ring.u, ring.w
        front = c > 0
        # ring sums per exponent: the same numbers whatever the batch (sorted(set()), not
        # np.unique, which imports numpy.ma: 7 ms of a terminal command's start-up)
        for m0 in sorted(set(m.ravel().tolist())):
            sel = m == m0
            sum_c = float(np.sum(w[front] * c[front] ** (m0 + 1.0)))
            if ring.preload:
                p = -e_hat[sel]
                lin = 1.0 / (m0 * p ** (m0 - 1.0) * float(np.sum(w * c * c)))
                start[sel] = np.minimum(lin, hi[sel])
            else:
                xi0 = sum_c ** (-1.0 / m0)
                slope = float(np.sum(w[front] * c[front] ** m0 * u[front])) / sum_c
                start[sel] = np.minimum(xi0 + slope * e_hat[sel], hi[sel])
    return start, hi


def solve_x(ring: Ring, e_hat: np.ndarray, m: np.ndarray, tol: float) -> tuple[np.ndarray, ...]:
    """Solve the x-equilibrium ``gx(xi, 0) = 0`` by bracketed Newton; returns (xi, iterations).

    ``gx`` rises with ``xi``; ``gx(0) = -1`` (no ball pushes at the reference or centred position),
    and the one-ball bound ``hi`` holds the root for a clearance >= 0 (widened under preload).
    """
    n = e_hat.size
    everyone = np.arange(n)
    start, hi = _starts(ring, e_hat, m)
    lo = np.zeros(n)
    if ring.preload:
        for _ in range(2100):
            short = x_state(ring, everyone, hi, e_hat, m)[0] < 0
            if not short.any():
                break
            hi = np.where(short, 2.0 * hi, hi)
    xi = start
    iterations = np.zeros(n, dtype=np.int64)
    last = np.full(n, np.inf)
    active = everyone
    for it in range(1, MAX_ITERATIONS + 1):
        x = xi[active]
        g, dg, size = x_state(ring, active, x, e_hat[active], m[active])
        lo_a = np.where(g < 0, x, lo[active])
        hi_a = np.where(g > 0, x, hi[active])
        with np.errstate(all="ignore"):
            new = x - g / dg
        outside = ~((new > lo_a) & (new < hi_a))
        new = np.where(outside, 0.5 * (lo_a + hi_a), new)
        rel = g / size
        met = np.abs(rel) <= tol
        done = met | (np.abs(new - x) <= 4 * EPS * np.abs(x))
        # at full-precision tolerances the last Newton step is taken too (checked at the result)
        xi[active] = np.where(done & ~(met & (tol <= POLISH) & ~outside), x, new)
        last[active], lo[active], hi[active], iterations[active] = rel, lo_a, hi_a, it
        active = active[~done]
        if active.size == 0:
            break
    last[active] = np.inf
    check(last, "symmetric ring equilibrium", iterations, e_hat, m, tol)
    return xi, iterations


def solve_xy(ring: Ring, e_hat: np.ndarray, m: np.ndarray, tol: float) -> tuple[np.ndarray, ...]:
    """Minimise the scaled potential in (xi, eta): damped Newton, Armijo or gradient-halving steps.

    Starts where the half-pitch ring starts (its reference, two balls straddling the load line,
    is alike), capped by the one-ball bound. The state of an accepted trial point is the next
    iterate's state (one evaluation per step when the full step is taken).
    """
    n = e_hat.size
    half = Ring.symmetric(ring.c.shape[-1], True, ring.preload)
    start, _ = _starts(half, e_hat, m)
    with np.errstate(all="ignore"):
        hi = (1.0 / ring.c_max) ** (1.0 / m) / ring.c_max
    xi = np.minimum(start, hi)
    iterations = np.zeros(n, dtype=np.int64)
    eta = np.zeros(n)
    cur = state(ring, ALL, xi, eta, e_hat, m)
    gnorm_all = np.hypot(cur.gx, cur.gy) / cur.size
    active = np.nonzero(~(gnorm_all <= tol))[0]
    cur = _take(cur, active)
    for _ in range(MAX_ITERATIONS):
        if active.size == 0:
            break
        a, b, eh, mv = xi[active], eta[active], e_hat[active], m[active]
        gnorm = np.hypot(cur.gx, cur.gy)
        dx, dy = newton_step(cur)
        slope = cur.gx * dx + cur.gy * dy
        t = np.ones(active.size)
        trial = state(ring, active, a + dx, b + dy, eh, mv)
        pending = ~_accept(trial, cur, t, slope, gnorm)
        for k in range(80):
            if not pending.any():
                break
            sub = np.nonzero(pending)[0]
            if k == 0:  # just past the first contact along the step, or half
                reach = _first_contact(ring, active[sub], cur.delta[sub], dx[sub], dy[sub])
                t[sub] = np.minimum(0.5, reach)
            elif k == DECOUPLE:  # the x part alone, where x is out of balance (a huge y
                off = np.abs(cur.gx[sub]) > POLISH * cur.size[sub]  # part held it back)
                took, kept = sub[off], sub[~off]
                dx[took], dy[took], t[took] = _x_step(_take(cur, took)), 0.0, 1.0
                slope[took] = cur.gx[took] * dx[took]
                t[kept] *= 0.5
            else:
                t = np.where(pending, 0.5 * t, t)
            part = state(ring, active[sub], a[sub] + t[sub] * dx[sub], b[sub] + t[sub] * dy[sub],
                         eh[sub], mv[sub])  # fmt: skip
            ok = _accept(part, _take(cur, sub), t[sub], slope[sub], gnorm[sub])
            _put(trial, sub[ok], _take(part, np.nonzero(ok)[0]))
            pending[sub[ok]] = False
        na, nb = a + t * dx, b + t * dy
        small = np.hypot(na - a, nb - b) <= 4 * EPS * np.hypot(na, nb) + 1e-300
        xi[active], eta[active] = na, nb
        iterations[active] += 1
        conv = np.hypot(trial.gx, trial.gy) <= tol * trial.size
        if tol <= POLISH and conv.any():  # the last Newton step too, where it does not
            fin = np.nonzero(conv)[0]  # raise the residual (across a flat valley it may jump)
            _polish(ring, active[fin], _take(trial, fin), (xi, eta), (e_hat, m))
        keep = ~(conv | small)
        active, cur = active[keep], _take(trial, np.nonzero(keep)[0])
    if active.size:  # (a case that converged on the last iteration is done)
        final = state(ring, active, xi[active], eta[active], e_hat[active], m[active])
        raise ConvergenceError(
            "ring equilibrium at a general cage angle",
            MAX_ITERATIONS,
            float(np.max(np.hypot(final.gx, final.gy) / final.size)),
            {"e_hat": e_hat[active], "exponent": m[active], "rows": active},
        )
    final = state(ring, ALL, xi, eta, e_hat, m)
    residual = np.hypot(final.gx, final.gy) / final.size
    check(residual, "ring equilibrium at a general cage angle", iterations, e_hat, m, tol)
    return xi, eta, iterations


def _x_step(st: State) -> np.ndarray:
    """The Newton step in x alone, y held (regularised as :func:`newton_step`)."""
    with np.errstate(all="ignore"):
        return -st.gx / (st.hxx + 1e-12 * (st.hxx + st.hyy) + 1e-300)


def _polish(
    ring: Ring,
    idx: np.ndarray,
    st: State,
    position: tuple[np.ndarray, np.ndarray],
    data: tuple[np.ndarray, np.ndarray],
) -> None:
    """One more Newton step from the converged state ``st`` of the cases ``idx``, taken (in
    place in ``position``) where it does not raise the residual. Why: a ring whose loaded balls
    barely resist a move across the load line (3 balls under preload, the cage 5e-12° off it)
    converges to the tolerance on a flat valley, where a full Newton step jumps so far that a
    ball lifted off comes into contact: 0.01 of the load left (solve(3, 1.0, 1.0,
    clearance=-0.4, cage_angle=5e-12) raised ConvergenceError)."""
    xi, eta = position
    e_hat, m = data
    px, py = newton_step(st)
    nx, ny = xi[idx] + px, eta[idx] + py
    new = state(ring, idx, nx, ny, e_hat[idx], m[idx])
    better = np.hypot(new.gx, new.gy) / new.size <= np.hypot(st.gx, st.gy) / st.size
    xi[idx[better]], eta[idx[better]] = nx[better], ny[better]


def _first_contact(
    ring: Ring, idx: np.ndarray, delta: np.ndarray, dx: np.ndarray, dy: np.ndarray
) -> np.ndarray:
    """Per case, the step fraction (1.001 times it, to first order) at which the first ball not
    in contact (``delta`` < 0, per ball) would touch moving by ``(dx, dy)``; 1 where none would
    before the full step. Why: where only the balls near the load line carry load and the ring
    is near-symmetric (3 or 4 balls under preload, the cage 1e-9° off the load line), the
    Newton step across the load line is huge (only the loaded balls' tiny transverse curvature
    resists it) and halving it from 1 takes x's part down with it: the iteration stalled. The
    equilibrium lies where the next ball touches, as the combined solver's search finds it."""
    c, s = rows(ring.c, idx), rows(ring.s, idx)
    a, b = dx, dy
    if ring.turn is not None:
        cp, sp, sign = (t[idx] for t in ring.turn)
        a, b = cp * dx + sp * sign * dy, cp * sign * dy - sp * dx
    rate = a[:, None] * c + b[:, None] * s
    # a ball a rounding short of contact (3 balls, one at 90° to the load: delta = -7e-16) is in
    # contact already: the next one bounds the step (else t = 1e-27, and the search stalls)
    short = delta < -1e-12  # (scaled: 1e-12 of the one-ball approach)
    with np.errstate(divide="ignore", invalid="ignore"):
        reach = np.where((rate > 0) & short, -delta / rate, np.inf)
    return np.minimum(1.001 * np.min(reach, axis=1), 1.0)


def newton_step(st: State) -> tuple[np.ndarray, np.ndarray]:
    """The (regularised) Newton step from a state."""
    with np.errstate(all="ignore"):
        reg = 1e-12 * (st.hxx + st.hyy) + 1e-300
        hxx, hyy = st.hxx + reg, st.hyy + reg
        det = hxx * hyy - st.hxy * st.hxy
        dx = -(hyy * st.gx - st.hxy * st.gy) / det
        dy = -(hxx * st.gy - st.hxy * st.gx) / det
    return dx, dy


def _accept(new: State, cur: State, t: np.ndarray, slope: np.ndarray, gnorm: np.ndarray) -> Any:
    """Armijo decrease of the energy, or the gradient at least halved (rounding-level energy)."""
    return (new.energy <= cur.energy + 1e-4 * t * slope) | (np.hypot(new.gx, new.gy) < 0.5 * gnorm)


#: The per-case fields of a State (the rest are per ball).
_PER_CASE = ("gx", "gy", "hxx", "hxy", "hyy", "size", "energy")
_NO_BALLS = np.empty((0, 0))


def _take(st: State, sel: np.ndarray) -> State:
    """The cases ``sel`` of a state, per-case sums and the ball approaches (the iterations need
    no other ball arrays)."""
    case = {f: getattr(st, f)[sel] for f in _PER_CASE}
    return State(**case, q=_NO_BALLS, dq=_NO_BALLS, delta=st.delta[sel])


def _put(st: State, sel: np.ndarray, part: State) -> None:
    for f in _PER_CASE:
        getattr(st, f)[sel] = getattr(part, f)
    st.delta[sel] = part.delta


def check(
    residual: np.ndarray,
    solver: str,
    iterations: np.ndarray,
    e_hat: np.ndarray,
    m: np.ndarray,
    tol: float,
) -> None:
    """Raise ConvergenceError where the residual is not small; never return a silent wrong number.

    A case may stop where the Newton step no longer moves it, short of a tolerance below what
    double precision resolves; 1e-11 is the most such a stop may leave.
    """
    bad = ~(np.abs(residual) <= max(tol, 1e-11))
    if np.any(bad):
        worst = np.abs(residual[bad])
        raise ConvergenceError(
            solver,
            int(iterations[bad].max()),
            float(np.max(np.where(np.isfinite(worst), worst, np.inf))),
            {"e_hat": e_hat[bad], "exponent": m[bad], "rows": np.flatnonzero(bad)},
        )


def derived(
    ring: Ring, xi: np.ndarray, eta: np.ndarray | None, e_hat: np.ndarray, m: np.ndarray
) -> tuple[np.ndarray, ...]:
    """(q_hat, loaded, hxx, hxy, hyy, residual) at the solution, scaled.

    A ball counts as loaded when its approach exceeds the rounding of its own computation
    (8 eps of the terms summed); a ball touching to within rounding counts as unloaded and adds
    nothing to the stiffness, so the count is one decision per case, not a rounding accident.
    """
    ring = ring.in_load_frame()
    idx = ALL
    st = state(ring, idx, xi, eta, e_hat, m)
    c, s, w = rows(ring.c, idx), rows(ring.s, idx), rows(ring.w, idx)
    noise = np.abs(xi[:, None] * c)
    if eta is not None:
        noise = noise + np.abs(eta[:, None] * s)
    noise = noise + np.abs(e_hat[:, None] * rows(ring.u, idx))
    loaded = st.delta > 8 * EPS * noise
    wdq = np.where(loaded, st.dq, 0.0)
    q_hat = np.where(loaded, st.q, 0.0).max(axis=1)
    _, _, _, _, _, wcc, wcs, wss = products(ring, idx)
    return (
        q_hat,
        dot(loaded.astype(float), w),
        dot(wdq, wcc),
        dot(wdq, wcs) if eta is not None else np.zeros_like(q_hat),
        dot(wdq, wss),
        np.hypot(st.gx, st.gy) / st.size,
    )
