"""The ring-equilibrium engine: the exact discrete load distribution of a radial bearing.

Every discrete model of the package is a case of this one (Kurochkin 1973, eqs. 1.1-1.8;
Kuzmenko 2010, §1-3). Conventions:

* Outer ring fixed, radial load ``F_r`` on the inner ring; angles measured from the load line.
* ``z`` balls equally spaced; ball 1 sits at the cage angle ``phi_1``, ball ``i`` at
  ``phi_i = phi_1 + 2*pi*(i - 1)/z``. Cage angle 0: a ball under the load; ``180/z`` degrees
  ("half pitch"): the load acts between two balls.
* ``clearance`` is the radial internal clearance ``G_r`` (total radial play, as in ISO 5753-1);
  the gap per side is ``e = G_r/2``. Negative = preload.
* Ball ``i`` is compressed by ``delta_i = x cos(phi_i) + y sin(phi_i) - e`` and carries
  ``Q_i = K max(delta_i, 0)^m`` (``m`` = 3/2 balls, 10/9 rollers). The inner ring displacement
  ``(x, y)`` minimises the convex potential ``sum K/(m+1) max(delta_i, 0)^(m+1) - F_r x``.

Numerics. Lengths are scaled by ``s = (F_r/K)^(1/m)``, the approach one ball would have under the
whole load, so every case is solved at unit load. The unknown is the approach of the ball nearest
to the load line (not the ring position), so that a huge clearance with a small load loses no digits.
Cages at 0 or half pitch are symmetric (``y = 0``): one unknown, solved by a bracketed Newton
iteration over half the ring, vectorised over all cases with the same ``z``. Any other cage angle:
a damped Newton iteration on the potential in two unknowns.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np

from bearingload import validate
from bearingload.errors import ConvergenceError, InputError

#: Relative equilibrium residual the solver drives every case below. [-]
TOLERANCE = 1e-13
#: Iteration cap of every Newton loop; reaching it raises ConvergenceError.
MAX_ITERATIONS = 200
#: Cage angles within this fraction of a pitch of 0 or 1/2 are treated as symmetric. [-]
SYMMETRY_SNAP = 1e-12


@dataclass(frozen=True)
class LoadDistribution:
    """Solution of the ring equilibrium for one case or an array of cases.

    Every attribute is a numpy array of the broadcast input shape (0-d for scalar input).

    Attributes
    ----------
    balls : ndarray of int
        Number of balls ``z``. [-]
    load : ndarray
        Radial load ``F_r``. [N]
    stiffness : ndarray
        Ball stiffness ``K`` of both contacts in series, ``Q = K delta^m``. [N/mm^m]
    clearance : ndarray
        Radial internal clearance ``G_r`` (total play; negative = preload). [mm]
    cage_angle : ndarray
        Angle of ball 1 from the load line, reduced to [0, 360). [°]
    exponent : ndarray
        Load-deflection exponent ``m``. [-]
    x, y : ndarray
        Inner-ring displacement along and across the load. [mm]
    q_max : ndarray
        Load of the most heavily loaded ball. [N]
    loaded_balls : ndarray of int
        Number of balls carrying load. [-]
    load_zone : ndarray
        Half-angle of the load zone, ``arccos(e/|d|)`` around the displacement ``d``. [°]
    stiffness_matrix : ndarray, shape (..., 2, 2)
        Tangent stiffness ``dF/dd`` of the bearing in the (along, across) axes. [N/mm]
    iterations : ndarray of int
        Newton iterations spent on each case. [-]
    offset : ndarray, shape (..., 2)
        Displacement from the reference position where the balls nearest the load line just
        touch; with it each ball's approach is computed without cancellation. [mm]
    reference : ndarray, shape (..., 2)
        ``(mu, h)``: the straddling balls nearest the load line sit at ``mu -+ h``. [rad]
    """

    balls: np.ndarray
    load: np.ndarray
    stiffness: np.ndarray
    clearance: np.ndarray
    cage_angle: np.ndarray
    exponent: np.ndarray
    x: np.ndarray
    y: np.ndarray
    q_max: np.ndarray
    loaded_balls: np.ndarray
    load_zone: np.ndarray
    stiffness_matrix: np.ndarray
    iterations: np.ndarray
    offset: np.ndarray
    reference: np.ndarray

    @property
    def k(self) -> np.ndarray:
        """Load factor ``k = Q_max/F_r`` (Kuzmenko 2010, eq. 1.17). [-]"""
        return self.q_max / self.load

    @property
    def K_Q(self) -> np.ndarray:
        """Load-concentration factor ``K_Q = Q_max/Q_mean = k z/2`` (Kuzmenko & Sabadash 2014). [-]"""
        return self.k * self.balls / 2.0

    @property
    def stiffness_radial(self) -> np.ndarray:
        """Tangent radial stiffness ``dF_r/dx`` with the transverse force held at zero. [N/mm]

        The Schur complement ``K_xx - K_xy^2/K_yy``; where only one ball carries (``K_yy = 0``, no
        transverse stiffness) it is ``K_xx``.
        """
        kxx = self.stiffness_matrix[..., 0, 0]
        kxy = self.stiffness_matrix[..., 0, 1]
        kyy = self.stiffness_matrix[..., 1, 1]
        with np.errstate(divide="ignore", invalid="ignore"):
            schur = kxx - np.where(kyy > 0, kxy**2 / np.where(kyy > 0, kyy, 1.0), 0.0)
        return schur

    def ball_angles(self) -> np.ndarray:
        """Angles ``phi_i`` of balls 1..z from the load line, in [0, 360), for one case. [°]"""
        return np.rad2deg(self._ball_angles_rad())

    def _ball_angles_rad(self) -> np.ndarray:
        z = int(self._one(self.balls))
        phi1 = np.deg2rad(float(self._one(self.cage_angle)))
        return np.mod(phi1 + 2.0 * np.pi * np.arange(z) / z, 2 * np.pi)

    def ball_approaches(self) -> np.ndarray:
        """Approach ``delta_i`` of balls 1..z (negative: the gap left), for one case. [mm]

        Computed as ``offset . n_i - e u_i`` from the reference position, so that a clearance
        much larger than the elastic approach costs no digits.
        """
        phi = self._ball_angles_rad()
        mu, h = (float(v) for v in np.asarray(self.reference).reshape(2))
        dx, dy = (float(v) for v in np.asarray(self.offset).reshape(2))
        e = float(self._one(self.clearance)) / 2.0
        theta = phi - mu
        u = 2.0 * np.sin((theta + h) / 2.0) * np.sin((theta - h) / 2.0) / np.cos(h)
        u = np.where(np.abs(u) < 1e-13, 0.0, u)
        return dx * _snapped_cos(phi) + dy * _snapped_sin(phi) - e * u

    def ball_loads(self) -> np.ndarray:
        """Load ``Q_i`` of balls 1..z (ball 1 at the cage angle), for one case. [N]"""
        delta = self.ball_approaches()
        m = float(self._one(self.exponent))
        return float(self._one(self.stiffness)) * np.maximum(delta, 0.0) ** m

    def _one(self, arr: np.ndarray) -> Any:
        if np.size(arr) != 1:
            raise ValueError(
                "ball_loads() and ball_angles() describe one case; index the result first"
            )
        return np.asarray(arr).reshape(())

    def __getitem__(self, index: Any) -> LoadDistribution:
        """The distribution of the cases selected by ``index`` (numpy indexing of the case shape)."""
        fields = {name: getattr(self, name)[index] for name in self.__dataclass_fields__}
        for name in ("stiffness_matrix", "offset", "reference"):
            fields[name] = getattr(self, name)[index]
        return LoadDistribution(**fields)


def solve(
    balls: Any,
    load: Any,
    stiffness: Any,
    clearance: Any = 0.0,
    cage_angle: Any = 0.0,
    exponent: Any = 1.5,
    *,
    tolerance: float = TOLERANCE,
) -> LoadDistribution:
    """Solve the equilibrium of the inner ring: the exact discrete load distribution.

    Parameters
    ----------
    balls : int or array_like
        Number of rolling elements ``z``, 1 to 100 000. [-]
    load : float or array_like
        Radial load ``F_r``, > 0. [N]
    stiffness : float or array_like
        Rolling-element stiffness ``K`` of both contacts in series, ``Q = K delta^m``, > 0. [N/mm^m]
    clearance : float or array_like, default 0
        Radial internal clearance ``G_r`` (total play; gap per side ``G_r/2``; negative = preload). [mm]
    cage_angle : float or array_like, default 0
        Angle of ball 1 from the load line; 0 = a ball under the load, ``180/z`` = half pitch. [°]
    exponent : float or array_like, default 1.5
        Load-deflection exponent ``m``: 3/2 for balls (point contact), 10/9 for rollers. [-]
    tolerance : float, keyword-only, default 1e-13
        Relative equilibrium residual each case is driven below, 1e-15 to 1e-1: the force
        residual over the larger of the load and the ball forces (preload). Each case stops as
        soon as its own residual is below it (``iterations`` counts per case); below about 1e-14
        a case may instead stop where the Newton step no longer changes the displacement. [-]

    Returns
    -------
    LoadDistribution
        Arrays of the broadcast shape of the inputs.

    Raises
    ------
    InputError
        A parameter outside its domain; with fewer than 3 balls, a cage angle that puts no ball on
        the load line (no equilibrium exists).
    ConvergenceError
        A case did not reach the tolerance (never observed; reported with its data).

    Examples
    --------
    Bearing 306 of Kuzmenko (2010), zero clearance, a ball under the load (Table 1: k = 0.5435):

    >>> r = solve(8, 300.0, 4700.0)
    >>> round(float(r.k), 4), int(r.loaded_balls)
    (0.5432, 3)
    """
    z = validate.ball_count(balls)
    f = validate.positive("load", load, "N")
    kk = validate.positive("stiffness", stiffness, "N/mm^m")
    g = validate.finite("clearance", clearance)
    # reduce in degrees first (exact), so a huge angle keeps its position on the ring
    phi1_deg = np.mod(validate.finite("cage_angle", cage_angle), 360.0)
    phi1 = np.deg2rad(phi1_deg)
    m = validate.exponent(exponent)
    tol = _tolerance(tolerance)
    z, f, kk, g, phi1, phi1_deg, m = np.broadcast_arrays(z, f, kk, g, phi1, phi1_deg, m)
    shape = z.shape
    z, f, kk, g, phi1, phi1_deg, m = (a.ravel() for a in (z, f, kk, g, phi1, phi1_deg, m))

    with np.errstate(all="ignore"):
        scale = (f / kk) ** (1.0 / m)  # approach of one ball carrying the whole load [mm]
        e_hat = (g / 2.0) / scale
    _check_range(scale, e_hat)
    pitch = 2.0 * np.pi / z
    frac = np.mod(phi1, pitch) / pitch
    frac = np.where(frac > 1.0 - SYMMETRY_SNAP, 0.0, frac)
    kind = np.full(z.shape, 2, dtype=np.int8)  # 0: ball under load, 1: half pitch, 2: general
    kind[frac < SYMMETRY_SNAP] = 0
    kind[np.abs(frac - 0.5) < SYMMETRY_SNAP] = 1
    few = (z < 3) & (kind != 0)
    if np.any(few):
        raise InputError(
            "cage_angle",
            "with 1 or 2 balls a ball must sit on the load line (cage angle 0), "
            "otherwise no equilibrium exists",
        )

    n = z.size
    # per-case results, one row each, in group order until every group is solved (columns: _COL)
    res = np.zeros((n, len(_COL)))

    # one group per (z, cage kind, clearance sign): the cases of a group share their ring.
    # Work in group order (contiguous slices), and put the cases back in their order once.
    keys = (z.astype(np.int64) * 3 + kind) * 2 + (e_hat < 0)
    # small keys sort by radix in numpy (int16): 6x faster than a comparison sort of int64
    order = np.argsort(keys.astype(np.int16) if keys.max() < 2**15 else keys, kind="stable")
    group_keys, starts = np.unique(keys[order], return_index=True)
    ends = np.append(starts[1:], n)
    e_sorted, m_sorted, frac_sorted = e_hat[order], m[order], frac[order]
    for key, start, end in zip(group_keys, starts, ends, strict=True):
        zz, kd, preload = int(key // 6), int(key // 2 % 3), bool(key % 2)
        part = slice(int(start), int(end))
        eh, mm = e_sorted[part], m_sorted[part]
        if kd == 2:
            ring = _Ring.general(zz, frac_sorted[part] * 2.0 * np.pi / zz)
            _store(_solve_general(ring, eh, mm, tol), ring, part, eh, mm, False, res)
        else:
            ring = _Ring.symmetric(zz, half_pitch=kd == 1, front=not preload)
            _store(_solve_symmetric(ring, eh, mm, tol), ring, part, eh, mm, True, res)
    rows = np.empty_like(res)
    rows[order] = res  # back to the order of the cases, all columns at once
    xi, eta, x0, y0 = (rows[:, _COL[k]] for k in ("xi", "eta", "x0", "y0"))
    hxx, hxy, hyy = (rows[:, _COL[k]] for k in ("hxx", "hxy", "hyy"))
    e = g / 2.0
    x = e * x0 + xi * scale
    y = e * y0 + eta * scale
    r = np.hypot(x, y)
    # half-angle of the load zone: arccos(e/r) = 2 arcsin(sqrt((1 - e/r)/2)), with 1 - e/r for
    # e > 0 from r^2 - e^2 = e^2 (|d0|^2 - 1) + 2 e s (d0 . zeta) + s^2 |zeta|^2 (no cancellation)
    with np.errstate(divide="ignore", invalid="ignore"):
        r2_e2 = (
            e**2 * (x0**2 + y0**2 - 1.0)
            + 2.0 * e * scale * (x0 * xi + y0 * eta)
            + scale**2 * (xi**2 + eta**2)
        )
        one_minus = np.where(e > 0, np.maximum(r2_e2, 0.0) / (r * (r + e)), 1.0 - e / r)
    one_minus = np.clip(one_minus, 0.0, 2.0)
    zone = 2.0 * np.arcsin(np.sqrt(one_minus / 2.0))
    to_n_mm = f / scale  # scaled stiffness -> N/mm
    matrix = np.empty((n, 2, 2))
    matrix[:, 0, 0] = hxx * to_n_mm
    matrix[:, 0, 1] = matrix[:, 1, 0] = hxy * to_n_mm
    matrix[:, 1, 1] = hyy * to_n_mm

    def shaped(a: np.ndarray) -> np.ndarray:
        return a.reshape(shape)

    return LoadDistribution(
        balls=shaped(z),
        load=shaped(f),
        stiffness=shaped(kk),
        clearance=shaped(g),
        cage_angle=shaped(phi1_deg),
        exponent=shaped(m),
        x=shaped(x),
        y=shaped(y),
        q_max=shaped(rows[:, _COL["q_hat"]] * f),
        loaded_balls=shaped(rows[:, _COL["loaded"]].astype(np.int64)),
        load_zone=shaped(np.rad2deg(zone)),
        stiffness_matrix=matrix.reshape(shape + (2, 2)),
        iterations=shaped(rows[:, _COL["iterations"]].astype(np.int64)),
        offset=np.stack([xi * scale, eta * scale], axis=-1).reshape(shape + (2,)),
        reference=rows[:, [_COL["mu"], _COL["h"]]].reshape(shape + (2,)),
    )


#: Range of the ``tolerance`` argument of :func:`solve`. [-]
TOLERANCE_RANGE = (1e-15, 1e-1)


def _tolerance(value: Any) -> float:
    """The relative residual tolerance as a float inside TOLERANCE_RANGE, or InputError."""
    lo, hi = TOLERANCE_RANGE
    try:
        tol = float(value)
    except (TypeError, ValueError):
        msg = f"must be a number from {lo:g} to {hi:g} (got {value!r})"
        raise InputError("tolerance", msg) from None
    if not lo <= tol <= hi:
        raise InputError("tolerance", f"must be from {lo:g} to {hi:g} (got {tol!r})")
    return tol


#: Range of the one-ball approach (F_r/K)^(1/m) the solver accepts, and of the clearance in
#: units of it: inside it every intermediate value is a normal double. [mm], [-]
APPROACH_RANGE = (1e-100, 1e100)
CLEARANCE_RATIO_MAX = 1e100


def _check_range(scale: np.ndarray, e_hat: np.ndarray) -> None:
    """Reject finite inputs whose scaled problem would overflow or underflow double precision."""
    lo, hi = APPROACH_RANGE
    bad = ~((scale >= lo) & (scale <= hi))
    if np.any(bad):
        raise InputError(
            "load",
            f"load and stiffness give a one-ball approach (F_r/K)^(1/m) = "
            f"{np.asarray(scale)[bad].flat[0]:.3g} mm, outside the {lo:g} to {hi:g} mm the "
            "solver resolves; check the units of the load and the stiffness",
        )
    bad = ~(np.abs(e_hat) <= CLEARANCE_RATIO_MAX)
    if np.any(bad):
        raise InputError(
            "clearance",
            f"must be at most {CLEARANCE_RATIO_MAX:g} times the one-ball approach "
            "(F_r/K)^(1/m) in size; check its unit",
        )


def _snapped_cos(phi: np.ndarray) -> np.ndarray:
    c = np.cos(phi)
    return np.where(np.abs(c) < 1e-14, 0.0, c)


def _snapped_sin(phi: np.ndarray) -> np.ndarray:
    s = np.sin(phi)
    return np.where(np.abs(s) < 1e-14, 0.0, s)


@dataclass(frozen=True)
class _Ring:
    """A set of ball angles, with the reference ring position where the nearest balls just touch.

    The reference position ``d0 = e (x0, y0)`` is where the two balls straddling the load line,
    at ``mu - h`` and ``mu + h``, both just touch (for a ball on the load line, ``h = 0``). Each
    ball's scaled approach is ``delta = xi c + eta s - e_hat u`` with ``(xi, eta)`` the scaled
    displacement from ``d0`` and ``u = 1 - cos(phi - mu)/cos h >= 0`` computed without
    cancellation, so a huge clearance costs no digits. ``w``: multiplicity of each angle.
    """

    c: np.ndarray
    s: np.ndarray
    u: np.ndarray
    w: np.ndarray
    x0: np.ndarray
    y0: np.ndarray
    c_max: np.ndarray
    w_max: np.ndarray
    mu: np.ndarray
    h: float

    @staticmethod
    def _build(phi: np.ndarray, w: np.ndarray, mu: Any, h: float, front: bool = False) -> _Ring:
        """``phi``: angles, shape (k,) shared or (n, k) per case; ``mu``: scalar or (n,)."""
        mu = np.asarray(mu, dtype=float)
        if front:  # clearance >= 0: balls at 90 degrees or beyond can never carry load
            keep = np.cos(phi) > 1e-14
            phi, w = phi[keep], w[keep]
        c, s = _snapped_cos(phi), _snapped_sin(phi)
        theta = phi - (mu[..., None] if mu.ndim else mu)
        u = 2.0 * np.sin((theta + h) / 2.0) * np.sin((theta - h) / 2.0) / np.cos(h)
        top = np.argmax(c, axis=-1)
        c_max = np.take_along_axis(c, top[..., None], -1)[..., 0] if c.ndim == 2 else c[top]
        w_max = np.take_along_axis(w, top[..., None], -1)[..., 0] if w.ndim == 2 else w[top]
        return _Ring(
            c=c,
            s=s,
            # the straddling balls have u = 0 exactly; rounding must not leave e_hat * 1e-17
            u=np.where(u < 1e-13, 0.0, u),
            w=w,
            x0=np.cos(mu) / np.cos(h),
            y0=np.sin(mu) / np.cos(h),
            c_max=np.asarray(c_max, dtype=float),
            w_max=np.asarray(w_max, dtype=float),
            mu=mu,
            h=h,
        )

    @classmethod
    @functools.lru_cache(maxsize=4096)
    def symmetric(cls, z: int, half_pitch: bool, front: bool) -> _Ring:
        """Half of a ring symmetric about the load line, each angle with its multiplicity.

        ``front``: keep only the balls ahead of 90 degrees (enough when the clearance is >= 0).
        """
        j = np.arange(z)
        phi = (j + (0.5 if half_pitch else 0.0)) * 2.0 * np.pi / z
        phi = np.minimum(phi, 2.0 * np.pi - phi)  # fold the lower half onto the upper half
        uniq, counts = np.unique(np.round(phi / np.pi * 2 * z) / (2 * z), return_counts=True)
        h = np.pi / z if half_pitch else 0.0
        return cls._build(uniq * np.pi, counts.astype(float), 0.0, h, front)

    @classmethod
    def general(cls, z: int, phi1: np.ndarray) -> _Ring:
        """All z balls of each case, ball 1 at ``phi1`` in (0, 2 pi/z) [rad], shape (n,).

        Balls 1 and z straddle the load line; the ring arrays are per case, shape (n, z).
        """
        pitch = 2.0 * np.pi / z
        phi = phi1[:, None] + np.arange(z) * pitch
        phi = np.where(phi > np.pi, phi - 2.0 * np.pi, phi)
        return cls._build(phi, np.ones_like(phi), phi1 - pitch / 2.0, pitch / 2.0)


def _rows(a: np.ndarray, idx: np.ndarray) -> np.ndarray:
    """Rows ``idx`` of a per-case (2-D) ring array; a shared (1-D) ring array as it is."""
    return a if a.ndim == 1 else a[idx]


def _dot(q: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Sum over the balls of ``q * v`` where ``v`` is shared (1-D) or per case (2-D)."""
    return q @ v if v.ndim == 1 else np.einsum("ij,ij->i", q, v)


def _power_terms(delta: np.ndarray, m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Scaled ball load ``delta_+^m`` and its derivative ``m delta_+^(m-1)``."""
    pos = np.maximum(delta, 0.0)
    mm = m[:, None]
    if np.all(m == 1.5):
        root = np.sqrt(pos)
        return pos * root, 1.5 * root
    with np.errstate(divide="ignore", invalid="ignore"):
        pm1 = np.where(pos > 0, pos ** (mm - 1.0), 0.0)
    return pos * pm1, mm * pm1


@dataclass
class _Solved:
    xi: np.ndarray
    eta: np.ndarray
    iterations: np.ndarray
    #: (loaded balls, Hxx, Hyy) when the solver already has them at the solution, else None
    derived: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None


def _solve_symmetric(
    ring: _Ring, e_hat: np.ndarray, m: np.ndarray, tol: float = TOLERANCE
) -> _Solved:
    """Solve ``sum w Q(delta) c = 1`` for the scaled approach ``xi`` with ``eta = 0``.

    Bracketed Newton: the bracket [lo, hi] always holds the root; a Newton step leaving it is
    replaced by bisection. For ``e >= 0`` the residual is convex and increasing in ``xi``, ``lo = 0``
    and the one-ball bound ``hi`` hold the root, and Newton from ``hi`` descends monotonically.
    """
    c, u, w = ring.c, ring.u, ring.w
    cw = c * w
    c2w = c * cw
    abs_cw = np.abs(cw)
    preloaded = bool(np.any(e_hat < 0))

    def residual(
        xi: np.ndarray, eh: np.ndarray, mm: np.ndarray, idx: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """Force residual relative to the larger of the load and the ball forces, and its slope.

        Under a heavy preload the ball forces dwarf the load and cancel; the residual is measured
        against them, the only scale at which floating point can resolve it.
        """
        delta = xi[:, None] * _rows(c, idx) - eh[:, None] * _rows(u, idx)
        q, dq = _power_terms(delta, mm)
        g, dg = _dot(q, _rows(cw, idx)) - 1.0, _dot(dq, _rows(c2w, idx))
        if preloaded:
            size = np.maximum(1.0, _dot(q, _rows(abs_cw, idx)))
            return g / size, dg / size
        return g, dg

    n = e_hat.size
    everyone = np.arange(n)
    # one ball (pair) nearest the load carrying everything: an upper bound when e >= 0
    hi = (1.0 / (ring.w_max * ring.c_max)) ** (1.0 / m) / ring.c_max
    x0 = ring.x0
    lo = np.zeros(n)
    pre = np.nonzero(e_hat < 0)[0]
    if pre.size:
        # preload: widen the bracket until it holds the root, starting from the centred ring
        hi[pre] = hi[pre] - e_hat[pre] * (x0[pre] if x0.ndim else x0)
        for _ in range(400):
            g_lo, _ = residual(lo[pre], e_hat[pre], m[pre], pre)
            g_hi, _ = residual(hi[pre], e_hat[pre], m[pre], pre)
            bad_lo, bad_hi = g_lo > 0, g_hi < 0
            if not (bad_lo.any() or bad_hi.any()):
                break
            width = hi[pre] - lo[pre]
            lo[pre] = np.where(bad_lo, lo[pre] - 2 * width, lo[pre])
            hi[pre] = np.where(bad_hi, hi[pre] + 2 * width, hi[pre])
    xi = hi.copy()
    if c.ndim == 1 and n > 1 and np.all(m == m[0]):
        # start on the tangent of xi(e_hat) at zero clearance, below the one-ball bound: xi is
        # concave in e_hat >= 0, so the start lies above the root and Newton descends at once
        front = c > 0
        m0 = float(m[0])
        sum_c = float(np.sum(w[front] * c[front] ** (m0 + 1.0)))
        xi0 = sum_c ** (-1.0 / m0)
        slope = float(np.sum(w[front] * c[front] ** m0 * u[front])) / sum_c
        xi = np.where(e_hat >= 0, np.minimum(xi0 + slope * e_hat, hi), hi)
        if not preloaded:
            return _newton_convex(ring, e_hat, m0, xi, tol)
    last = np.full(n, np.inf)
    iterations = np.zeros(n, dtype=np.int64)
    active = everyone
    for it in range(1, MAX_ITERATIONS + 1):
        x, lo_a, hi_a = xi[active], lo[active], hi[active]
        g, dg = residual(x, e_hat[active], m[active], active)
        lo_a = np.where(g < 0, x, lo_a)
        hi_a = np.where(g > 0, x, hi_a)
        with np.errstate(divide="ignore", invalid="ignore"):
            new = x - g / dg
        outside = ~((new > lo_a) & (new < hi_a))
        new = np.where(outside, 0.5 * (lo_a + hi_a), new)
        done = (np.abs(g) <= tol) | (np.abs(new - x) <= 4e-16 * np.abs(x))
        xi[active] = np.where(done, x, new)
        last[active] = g
        lo[active], hi[active] = lo_a, hi_a
        iterations[active] = it
        active = active[~done]
        if active.size == 0:
            break
    # each case stopped at a point whose residual was evaluated: that residual is the proof
    last[active] = np.inf
    _check(last, "symmetric ring equilibrium", iterations, e_hat, m, tol)
    return _Solved(xi=xi, eta=np.zeros(n), iterations=iterations)


def _newton_convex(
    ring: _Ring, e_hat: np.ndarray, m: float, start: np.ndarray, tol: float = TOLERANCE
) -> _Solved:
    """Plain Newton for a shared ring with clearance >= 0: the fast path of the symmetric solver.

    With ``e >= 0`` only balls ahead of 90° are in the ring, the residual is convex and increasing
    in ``xi`` and its slope is positive wherever ``xi > 0`` (the reference ball, ``u = 0``, is
    then loaded), so Newton converges from any positive start, monotonically after the first step.
    """
    c, u, w = ring.c, ring.u, ring.w
    cw, c2w, s2w = c * w, c * c * w, ring.s * ring.s * w
    xi = start.copy()
    n = xi.size
    last = np.full(n, np.inf)
    iterations = np.zeros(n, dtype=np.int64)
    loaded, hxx, hyy = np.zeros(n), np.zeros(n), np.zeros(n)
    active = np.arange(n)
    for it in range(1, MAX_ITERATIONS + 1):
        xa = xi[active]
        delta = xa[:, None] * c
        delta -= e_hat[active][:, None] * u
        np.maximum(delta, 0.0, out=delta)
        if m == 1.5:
            root = np.sqrt(delta)
            g = (delta * root) @ cw - 1.0
            dq = 1.5 * root
        else:
            q, dq = _power_terms(delta, np.full(xa.size, m))
            g = q @ cw - 1.0
        dg = dq @ c2w
        step = g / dg
        done = (np.abs(g) <= tol) | (np.abs(step) <= 4e-16 * xa)
        xi[active] = np.where(done, xa, xa - step)
        last[active] = g
        iterations[active] = it
        # the cases that stop here stop at this very point: keep what the output needs
        fin = active[done]
        loaded[fin] = (delta[done] > 0) @ w
        hxx[fin] = dg[done]
        hyy[fin] = dq[done] @ s2w
        active = active[~done]
        if active.size == 0:
            break
    last[active] = np.inf
    _check(last, "symmetric ring equilibrium", iterations, e_hat, np.full(n, m), tol)
    return _Solved(xi=xi, eta=np.zeros(n), iterations=iterations, derived=(loaded, hxx, hyy))


def _solve_general(
    ring: _Ring, e_hat: np.ndarray, m: np.ndarray, tol: float = TOLERANCE
) -> _Solved:
    """Minimise the scaled potential in (xi, eta) by damped Newton with an Armijo line search."""
    c, s, u = ring.c, ring.s, ring.u
    cc, cs, ss = c * c, c * s, s * s
    first = _solve_symmetric(ring, e_hat, m, tol)  # x-equilibrium alone, y = 0: the starting point
    xi, eta = first.xi.copy(), np.zeros(e_hat.size)
    iterations = first.iterations.copy()
    mm = m

    def state(
        a: np.ndarray, b: np.ndarray, eh: np.ndarray, mv: np.ndarray, idx: np.ndarray
    ) -> tuple[np.ndarray, ...]:
        cr, sr = _rows(c, idx), _rows(s, idx)
        delta = a[:, None] * cr + b[:, None] * sr - eh[:, None] * _rows(u, idx)
        q, dq = _power_terms(delta, mv)
        pos = np.maximum(delta, 0.0)
        energy = (q * pos).sum(1) / (mv + 1.0) - a
        gx, gy = _dot(q, cr) - 1.0, _dot(q, sr)
        hxx, hxy = _dot(dq, _rows(cc, idx)), _dot(dq, _rows(cs, idx))
        size = np.maximum(1.0, q.sum(1))  # residual scale: the load or, under preload, the balls
        return energy, gx, gy, hxx, hxy, _dot(dq, _rows(ss, idx)), size

    active = np.arange(e_hat.size)
    for _ in range(MAX_ITERATIONS):
        a, b, eh, mv = xi[active], eta[active], e_hat[active], mm[active]
        energy, gx, gy, hxx, hxy, hyy, size = state(a, b, eh, mv, active)
        gnorm = np.hypot(gx, gy)
        done = gnorm <= tol * size
        reg = 1e-12 * (hxx + hyy) + 1e-300
        hxx, hyy = hxx + reg, hyy + reg
        det = hxx * hyy - hxy * hxy
        dx = -(hyy * gx - hxy * gy) / det
        dy = -(hxx * gy - hxy * gx) / det
        slope = gx * dx + gy * dy
        t = np.ones_like(a)
        pending = ~done
        for _ in range(80):
            if not pending.any():
                break
            na, nb = a + t * dx, b + t * dy
            e_new, ngx, ngy, *_ = state(na, nb, eh, mv, active)
            ok = (e_new <= energy + 1e-4 * t * slope) | (np.hypot(ngx, ngy) < 0.5 * gnorm)
            pending &= ~ok
            t = np.where(pending, 0.5 * t, t)
        small = np.hypot(t * dx, t * dy) <= 4e-16 * np.hypot(a, b) + 1e-300
        xi[active] = np.where(done, a, a + t * dx)
        eta[active] = np.where(done, b, b + t * dy)
        iterations[active] += 1
        active = active[~(done | small)]
        if active.size == 0:
            break
    else:
        raise ConvergenceError(
            "ring equilibrium at a general cage angle",
            MAX_ITERATIONS,
            float("nan"),
            {"e_hat": e_hat[active], "exponent": m[active]},
        )
    _, gx, gy, *_, size = state(xi, eta, e_hat, mm, np.arange(e_hat.size))
    _check(
        np.hypot(gx, gy) / size,
        "ring equilibrium at a general cage angle",
        iterations,
        e_hat,
        m,
        tol,
    )
    return _Solved(xi=xi, eta=eta, iterations=iterations)


def _check(
    residual: np.ndarray,
    solver: str,
    iterations: np.ndarray,
    e_hat: np.ndarray,
    m: np.ndarray,
    tol: float = TOLERANCE,
) -> None:
    """Raise ConvergenceError where the residual is not small; never return a silent wrong number.

    A case may stop where the Newton step no longer moves it, short of a tolerance below what
    double precision resolves; 1e-11 is the most such a stop may leave.
    """
    bad = ~(np.abs(residual) <= max(tol, 1e-11))
    if np.any(bad):
        raise ConvergenceError(
            solver,
            int(iterations[bad].max()),
            float(np.nanmax(np.abs(residual[bad]))),
            {"e_hat": e_hat[bad], "exponent": m[bad]},
        )


#: Columns of the per-case result rows of :func:`solve`.
_COL = {
    name: i
    for i, name in enumerate(
        ("xi", "eta", "x0", "y0", "q_hat", "loaded", "hxx", "hxy", "hyy", "mu", "h", "iterations")
    )
}


def _store(
    out: _Solved,
    ring: _Ring,
    part: slice,
    e_hat: np.ndarray,
    m: np.ndarray,
    symmetric: bool,
    res: np.ndarray,
) -> None:
    """Write one group's solution and the quantities derived from it into its rows of ``res``.

    ``xi, eta``: scaled displacement from the reference position ``e (x0, y0)``; ``q_hat``: the
    heaviest scaled ball load; ``hxx, hxy, hyy``: scaled stiffness; ``mu, h``: reference angles.
    """
    rows = res[part]
    col = _COL
    rows[:, col["xi"]], rows[:, col["eta"]] = out.xi, out.eta
    rows[:, col["x0"]], rows[:, col["y0"]] = ring.x0, ring.y0
    rows[:, col["mu"]], rows[:, col["h"]] = ring.mu, ring.h
    rows[:, col["iterations"]] = out.iterations
    if out.derived is not None:  # symmetric ring: the reference ball carries the most
        loaded, hxx, hyy = out.derived
        rows[:, col["q_hat"]] = (out.xi * ring.c_max) ** m
        rows[:, col["loaded"]] = np.rint(loaded)
        rows[:, col["hxx"]], rows[:, col["hyy"]] = hxx, hyy
        return
    delta = out.xi[:, None] * ring.c
    if not symmetric:
        delta += out.eta[:, None] * ring.s
    delta -= e_hat[:, None] * ring.u
    loaded_mask = delta > 0
    np.maximum(delta, 0.0, out=delta)
    if np.all(m == 1.5):
        dq = 1.5 * np.sqrt(delta)
    else:
        _, dq = _power_terms(delta, m)
    if symmetric:  # the reference ball (u = 0, largest cos) carries the most
        rows[:, col["q_hat"]] = (out.xi * ring.c_max) ** m
    else:
        rows[:, col["q_hat"]] = delta.max(axis=1) ** m
    rows[:, col["loaded"]] = np.rint(_dot(loaded_mask.astype(float), ring.w))
    rows[:, col["hxx"]] = _dot(dq, ring.w * ring.c * ring.c)
    if not symmetric:
        rows[:, col["hxy"]] = _dot(dq, ring.w * ring.c * ring.s)
    rows[:, col["hyy"]] = _dot(dq, ring.w * ring.s * ring.s)
