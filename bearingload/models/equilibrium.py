"""The ring-equilibrium engine: the exact discrete load distribution of a radial bearing.

Every discrete model of the package is a case of this one (Kurochkin 1973, eqs. 1.1-1.8;
Kuzmenko 2010, §1-3). Outer ring fixed, radial load ``F_r`` on the inner ring, angles from the
load line; ball 1 at the cage angle ``phi_1`` (0: a ball under the load; ``180/z``: half pitch);
``clearance`` is the radial internal clearance ``G_r`` (total play, ISO 5753-1; the gap per side
``e = G_r/2``; negative = preload); ``Q_i = K max(delta_i, 0)^m`` (``m`` = 3/2 balls, 10/9
rollers). The model, the numerics and the near-symmetric cage angles: docs/models.md ("The
model", "Range of the exact solver"). The solver is the compiled core's (``models/_radial.pxi``);
one case given as numbers is a batch of one, so its answer is the same bits alone or in any batch.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

import bearingload.models._core as _core
from bearingload import numerics, validate
from bearingload.errors import ConvergenceError, InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.models import _ring
from bearingload.models._ring import (
    APPROACH_RANGE,
    CLEARANCE_RATIO_MAX,
    RESULT_RANGE,
    gap_factor,
    snapped_cos,
    snapped_sin,
)
from bearingload.models.case import INPUTS, checked

#: Relative equilibrium residual the solver drives every case below. [-]
TOLERANCE = 1e-13
#: Iteration cap of every Newton loop; reaching it raises ConvergenceError (read per call).
MAX_ITERATIONS = _ring.MAX_ITERATIONS
#: A cage angle within this of 0 or half pitch is symmetric (rounding; docs/models.md). [°]
SYMMETRY_SNAP_DEG = _ring.SYMMETRY_SNAP_DEG
#: A case the Newton cannot balance with its cage this close to a symmetric position (a ball on
#: the load line, or the load between two balls) is answered as symmetric, as the combined
#: solver does (3 balls, a preload of 3e-9 mm, exponent 10/9 and a cage 3e-11° off stalled at
#: a residual of 1.2e-10). [°]
NEAR_SYMMETRIC_DEG = 1e-9
__all__ = ["LoadDistribution", "solve", "MAX_ITERATIONS", "TOLERANCE"]


@dataclass(frozen=True)
class LoadDistribution:
    """Solution of the ring equilibrium for one case or an array of cases.

    Every attribute is a numpy array of the broadcast input shape; for one case given as
    scalars, a Python ``int`` or ``float`` (the 2x2 and per-ball arrays stay arrays).

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
    def stiffness_radial(self) -> Any:
        """Tangent radial stiffness ``dF_r/dx`` with the transverse force held at zero. [N/mm]

        The Schur complement ``K_xx - K_xy (K_xy/K_yy)`` (no squared term, so neither overflow
        nor underflow); where only one ball carries (``K_yy`` about 0, no transverse stiffness)
        it is ``K_xx`` (:func:`bearingload.numerics.radial_stiffness`).
        """
        k = self.stiffness_matrix
        return numerics.radial_stiffness(k[..., 0, 0], k[..., 0, 1], k[..., 1, 0], k[..., 1, 1])

    @property
    def ball_angles(self) -> np.ndarray:
        """Angles ``phi_i`` of balls 1..z from the load line, in [0, 360) as the cage angle is
        reduced (:func:`bearingload.validate.reduced_angle`), for one case. [°]"""
        phi = _ball_phi(int(self._one(self.balls)), float(self._one(self.cage_angle)))
        return validate.reduced_angle(np.rad2deg(phi))

    @property
    def ball_approaches(self) -> np.ndarray:
        """Approach ``delta_i`` of balls 1..z (negative: the gap left), for one case. [mm]

        See :func:`ball_approaches` (the same over many cases).
        """
        one = self._one
        return ball_approaches(
            int(one(self.balls)),
            float(one(self.cage_angle)),
            float(one(self.clearance)),
            float(one(self.x)),
            float(one(self.y)),
            np.asarray(self.reference).reshape(2),
            np.asarray(self.offset).reshape(2),
        )

    @property
    def ball_loads(self) -> np.ndarray:
        """Load ``Q_i`` of balls 1..z (ball 1 at the cage angle), for one case. [N]"""
        delta = self.ball_approaches
        m = float(self._one(self.exponent))
        return float(self._one(self.stiffness)) * np.maximum(delta, 0.0) ** m

    def _one(self, arr: np.ndarray) -> Any:
        if np.size(arr) != 1:
            raise ValueError(
                "ball_loads, ball_approaches and ball_angles describe one case; index the result first"
            )
        return np.asarray(arr).reshape(())

    def __getitem__(self, index: Any) -> LoadDistribution:
        """The distribution of the cases selected by ``index`` (numpy indexing of the case shape)."""
        fields = {name: getattr(self, name)[index] for name in self.__dataclass_fields__}
        return LoadDistribution(**fields)


def ball_approaches(
    z: int,
    cage_angle: Any,
    clearance: Any,
    x: Any,
    y: Any,
    reference: np.ndarray,
    offset: np.ndarray,
) -> np.ndarray:
    """Approaches ``delta_i`` of balls 1..z (ball 1 at the cage angle; negative: the gap left)
    of one case, or of many given as columns: ``cage_angle`` [°], ``clearance`` G_r [mm], ``x``,
    ``y`` [mm] of shape (n, 1), ``reference`` and ``offset`` of :class:`LoadDistribution` of shape
    (n, 2); returns (n, z). [mm]

    Computed as ``offset . n_i - e u_i`` from the reference position, so that a clearance much
    larger than the elastic approach costs no digits; under preload (e < 0, z >= 2) as
    ``x cos phi_i + y sin phi_i - e`` from the centred ring.
    """
    phi = _ball_phi(z, cage_angle)
    e = np.asarray(clearance) / 2.0
    cos, sin = snapped_cos(phi), snapped_sin(phi)
    mu = reference[..., :1]
    h: Any = reference[..., 1:]  # gap_factor works elementwise
    dx, dy = offset[..., :1], offset[..., 1:]
    with np.errstate(all="ignore"):  # the branch not taken may see a gap factor of a preload
        free = dx * cos + dy * sin - e * gap_factor(phi - mu, h)
        return np.where((e < 0) & (z >= 2), x * cos + y * sin - e, free)


def _ball_phi(z: int, cage_angle: Any) -> np.ndarray:
    """Angles of balls 1..z from the load line in [0, 2 pi), ball 1 at ``cage_angle`` [°] (a
    number, or a column of cases). [rad]"""
    return np.mod(np.deg2rad(cage_angle) + 2.0 * np.pi * np.arange(z) / z, 2 * np.pi)


def _lazy_field(name: str) -> property:
    def get(self: Any) -> Any:
        cache = self.__dict__["_arrays"]
        arr = cache.get(name)
        if arr is None:
            value = self.__dict__["_values"][name]
            arr = np.asarray(value)
            # one case: a Python int or float for each quantity (arrays stay arrays)
            arr = cache[name] = numerics.scalar_out(arr)
        return arr

    return property(get, doc=f"``{name}`` of the case (see LoadDistribution).")


class OneCase(LoadDistribution):
    """The LoadDistribution of one case from the scalar path, its arrays built on first access.

    A call from a Python loop pays for the arrays it reads, not for all fifteen; every
    attribute is the same 0-d (or (2,), (2, 2)) array the vectorised path gives.
    """

    @classmethod
    def of(cls, values: dict[str, Any]) -> OneCase:
        obj = object.__new__(cls)
        obj.__dict__["_values"], obj.__dict__["_arrays"] = values, {}
        return obj


for _name in LoadDistribution.__dataclass_fields__:
    setattr(OneCase, _name, _lazy_field(_name))


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
        residual over the larger of the load and the sum of the ball-force terms it is computed
        from (the ball loads; under preload their changes from the centred ring). Each case stops as
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

    Notes
    -----
    Accepted range (beyond it an InputError says which parameter and why): the one-ball
    approach ``(F_r/K)^(1/m)`` from 1e-100 to 1e100 mm; ``|G_r|/2`` up to 1e100 times it, so
    preloads from the lightest to 1e100 times the elastic approach keep ``x`` to about 1e-14
    relative; the ball loads ``F_r max(1, |e|/s)^m`` and the stiffness ``m z F_r/s
    max(1, |e|/s)^(m-1)`` within 1e-300 to 1e300 (N, N/mm), so that no result overflows or
    underflows. A cage angle within 3.2e-13° (rounding) of 0 or half pitch is symmetric; at
    exactly 0 with one ball loaded, ``y = 0`` (docs/models.md).

    Examples
    --------
    Bearing 306 of Kuzmenko (2010), zero clearance, a ball under the load (Table 1: k = 0.5435):

    >>> r = solve(8, 300.0, 4700.0)
    >>> round(float(r.k), 4), int(r.loaded_balls)
    (0.5432, 3)
    """
    tol = _tolerance(tolerance)
    plain = _plain(balls, load, stiffness, clearance, cage_angle, exponent)
    if plain is not None:
        one = _solve_one(plain, tol)
        if one is not None:
            return OneCase.of(one)
    inputs = _validated(balls, load, stiffness, clearance, cage_angle, exponent)
    shape = inputs[0].shape
    z, f, kk, g, cage, m = (a.ravel() for a in inputs)
    # reduce in degrees (exact), so a huge angle keeps its position on the ring
    phi1_deg = validate.reduced_angle(cage)
    with np.errstate(all="ignore"):
        scale = (f / kk) ** (1.0 / m)  # approach of one ball carrying the whole load [mm]
        e_hat = (g / 2.0) / scale
    given = {"load": load, "clearance": clearance}
    check_range(f, scale, e_hat, m, z, (given, shape))
    frac, kind = _cage_kind(z, cage, phi1_deg)
    try:
        rows = _solve_groups(z, kind, frac, e_hat, (f / kk, g, m), tol)
    except ConvergenceError as exc:
        # cases just off a symmetric cage answered as symmetric, if that balances them all
        near_frac, near_kind = _cage_kind(z, cage, phi1_deg, NEAR_SYMMETRIC_DEG)
        failing = np.asarray(exc.cases["case"])
        if np.any(near_kind[failing] == 2):
            raise _in_user_terms(exc, (z, f, kk, g, cage, m)) from None
        kind[failing] = near_kind[failing]
        frac[failing] = np.where(near_kind[failing] == 1, 0.5, 0.0)
        try:
            rows = _solve_groups(z, kind, frac, e_hat, (f / kk, g, m), tol)
        except ConvergenceError as again:
            raise _in_user_terms(again, (z, f, kk, g, cage, m)) from None
    # the core's scale: the same bits as for the case alone
    return _assemble(shape, z, f, kk, g, phi1_deg, m, rows[:, _COL["scale"]], rows)


_NUMBER = (int, float, np.integer, np.floating)


def _plain(*values: Any) -> tuple[Any, ...] | None:
    """The six inputs as Python numbers when each is a plain real scalar inside the solver's
    range with room to spare, else None (the vectorised path checks it, or says why not)."""
    for v in values:
        kind = type(v)
        if kind is not float and kind is not int:
            if not isinstance(v, _NUMBER) or isinstance(v, (bool, np.bool_)):
                return None
    try:
        z, f, k, g, cage, m = (float(v) for v in values)
        finite = all(math.isfinite(v) for v in (f, k, g, cage))
        if not (finite and z == int(z) and 1 <= z <= 100_000 and f > 0 and k > 0 and 1 <= m <= 3):
            return None
        scale = (f / k) ** (1.0 / m)
        e_hat = (g / 2.0) / scale
    except (TypeError, ValueError, OverflowError, ZeroDivisionError):
        return None
    # inside every bound of check_range with room to spare
    if not (-1.0 <= e_hat <= 1e90 and 1e-90 <= scale <= 1e90 and 1e-250 <= f <= 1e250):
        return None
    if not 1e-250 <= f / scale <= 1e250:
        return None
    return int(z), f, k, g, cage, m, scale, e_hat


def _solve_one(plain: tuple[Any, ...], tol: float) -> dict[str, Any] | None:
    """One case through the core (its kernel, a batch of one): the fields of its ``OneCase``,
    or None where it is not proven (the vectorised path names the case)."""
    z, f, k, g, cage, m, _, e_hat = plain
    phi1_deg = validate.reduced_angle(cage)
    pitch_deg = 360.0 / z
    frac = (phi1_deg % pitch_deg) / pitch_deg
    mirror = (math.fmod(abs(cage), 360.0) % pitch_deg) / pitch_deg
    snap = SYMMETRY_SNAP_DEG / pitch_deg
    kind = 0 if (mirror <= snap or mirror >= 1.0 - snap) else 1 if abs(mirror - 0.5) <= snap else 2
    if z < 3 and kind != 0:
        return None
    pre = e_hat < -_ring.PRELOAD_CENTRED and z >= 2
    tables = _ring.tables(z, kind, pre)
    row = _core.radial_one(*tables, frac, f / k, g, m, tol, MAX_ITERATIONS, _ring.POLISH)
    xi, eta, its, q_hat, loaded, hxx, hxy, hyy, residual, status, scale = row[:11]
    if status != 0 or not residual <= max(tol, 1e-11):
        return None
    x0, y0, mu, h = _reference(row[11:], z, kind, pre)
    e = g / 2.0
    x, y = e * x0 + xi * scale, e * y0 + eta * scale
    # the load zone as _load_zone (numpy's hypot, tan and arcsin: the same bits as an array)
    r = float(np.hypot(x, y))
    if e > 0:
        r2_e2 = (e * float(np.tan(h))) ** 2 + 2.0 * e * scale * (x0 * xi + y0 * eta)
        one_minus = max(r2_e2 + (scale * xi) ** 2 + (scale * eta) ** 2, 0.0) / (r * (r + e))
    else:
        one_minus = 1.0 - e / r
    zone = math.degrees(2.0 * float(np.arcsin(math.sqrt(min(max(one_minus, 0.0), 2.0) / 2.0))))
    kn = f / scale
    return {
        "balls": z,
        "load": f,
        "stiffness": k,
        "clearance": g,
        "cage_angle": phi1_deg,
        "exponent": m,
        "x": x,
        "y": y,
        "q_max": q_hat * f,
        "loaded_balls": round(loaded),
        "load_zone": zone,
        "stiffness_matrix": [[hxx * kn, hxy * kn], [hxy * kn, hyy * kn]],
        "iterations": int(its),
        "offset": [xi * scale, eta * scale],
        "reference": [mu, h],
    }


def _reference(geo: Any, z: int, kind: int, pre: bool) -> tuple[Any, Any, Any, float]:
    """(x0, y0, mu, h) of a case: the reference position over e (0 under preload), the angle
    ``mu`` of the reference and the half-angle ``h`` of its straddling balls; ``geo`` the
    core's (x0, y0, mu) of a general ring (arrays of a group, or one case's numbers)."""
    if kind == 2:
        h = math.pi / z
        return (0.0, 0.0, geo[2], h) if pre else (geo[0], geo[1], geo[2], h)
    h = math.pi / z if kind == 1 else 0.0
    return 0.0 if pre else 1.0 / math.cos(h), 0.0, 0.0, h


def _in_user_terms(exc: ConvergenceError, inputs: tuple[np.ndarray, ...]) -> ConvergenceError:
    """The engine's ConvergenceError (its cases named by their index in the call, ``case``) as
    one naming the inputs of those cases: balls, load, stiffness, clearance, cage angle and
    exponent."""
    failing = np.asarray(exc.cases.get("case", []), dtype=np.intp)
    z, f, kk, g, cage, m = inputs
    cases = {
        "balls": z[failing],
        "load": f[failing],
        "stiffness": kk[failing],
        "clearance": g[failing],
        "cage_angle": cage[failing],
        "exponent": m[failing],
    }
    exponents = sorted(set(cases["exponent"].tolist()))
    stiffness = f"N/mm^{exponents[0]:g}" if len(exponents) == 1 else "N/mm^m"
    units = {"load": "N", "stiffness": stiffness, "clearance": "mm", "cage_angle": "°"}
    return ConvergenceError(exc.solver, exc.iterations, exc.residual, cases, units=units)


def _validated(*values: Any) -> list[np.ndarray]:
    """The six inputs checked (none empty) and broadcast to one shape."""
    arrays = checked(**dict(zip(INPUTS, values, strict=True)))
    for name, arr in zip(INPUTS, arrays, strict=True):
        if arr.size == 0:
            raise InputError(name, f"is an empty array (shape {arr.shape}); give at least one case")
    shape: tuple[int, ...] = ()
    for name, arr in zip(INPUTS, arrays, strict=True):
        try:
            shape = np.broadcast_shapes(shape, arr.shape)
        except ValueError:
            raise InputError(
                name,
                f"has shape {arr.shape}, which does not broadcast with the shape {shape} of the "
                "parameters before it; give arrays of one shape (or scalars)",
            ) from None
    return list(np.broadcast_arrays(*arrays))


def _cage_kind(
    z: np.ndarray, cage: np.ndarray, phi1_deg: np.ndarray, snap_deg: float = SYMMETRY_SNAP_DEG
) -> tuple[np.ndarray, np.ndarray]:
    """Cage position within one pitch, ``frac`` in [0, 1), and its kind per case.

    Kind 0: a ball under the load; 1: half pitch; 2: general. Symmetric only within
    ``snap_deg`` (default ``SYMMETRY_SNAP_DEG``) of 0 or half pitch, judged on ``|cage angle|``
    reduced by ``fmod`` (exact), so that an angle and its mirror image get the same kind.
    """
    pitch_deg = 360.0 / z
    frac = np.mod(phi1_deg, pitch_deg) / pitch_deg
    mirror = np.mod(np.fmod(np.abs(cage), 360.0), pitch_deg) / pitch_deg
    snap = snap_deg / pitch_deg
    near_zero = (mirror <= snap) | (mirror >= 1.0 - snap)
    kind = np.full(z.shape, 2, dtype=np.int8)
    kind[near_zero] = 0
    kind[np.abs(mirror - 0.5) <= snap] = 1
    if np.any((z < 3) & (kind != 0)):
        raise InputError("cage_angle", _ring.CAGE_OFF_LINE)
    return frac, kind


#: Columns of the per-case result rows of :func:`_solve_groups`: the core's row
#: (``_core.radial``: scaled offset, iterations, scaled Q_max, loaded balls, scaled tangent,
#: residual, status, scale), then the reference of :func:`_reference` (x0, y0, mu, h).
_CORE_ROW = "xi eta iterations q_hat loaded hxx hxy hyy residual status scale".split()
_COL = {name: i for i, name in enumerate([*_CORE_ROW, "x0", "y0", "mu", "h"])}


def _solve_groups(
    z: np.ndarray,
    kind: np.ndarray,
    frac: np.ndarray,
    e_hat: np.ndarray,
    data: tuple[np.ndarray, ...],
    tol: float,
) -> np.ndarray:
    """Solve every case, one core call per (z, cage kind, preload) sharing its ring's tables;
    ``data``: F_r/K, G_r and m per case (the core scales them, as for one case alone).

    Returns one row per case (columns ``_COL``) in the order of the cases; raises
    ConvergenceError naming the failing cases by their index in the call (``case``).
    """
    n = z.size
    # the centred formulation for a preload of any consequence; a preload below 1e-50 of the
    # elastic approach costs no digits in the reference formulation (and p^m would underflow)
    preload = (e_hat < -_ring.PRELOAD_CENTRED) & (z >= 2)
    keys = (z.astype(np.int64) * 3 + kind) * 2 + preload
    if keys.min() == keys.max():  # one group (one case, or a sweep of one bearing)
        order, group_keys, starts = None, keys[:1], np.zeros(1, dtype=np.intp)
    else:  # small keys sort by radix in numpy (int16): 6x faster than a comparison sort
        order = np.argsort(keys.astype(np.int16) if keys.max() < 2**15 else keys, kind="stable")
        group_keys, starts = np.unique(keys[order], return_index=True)
        frac, data = frac[order], tuple(a[order] for a in data)
    ends = np.append(starts[1:], n)
    res = np.empty((n, len(_COL)))
    bad = []
    for key, start, end in zip(group_keys.tolist(), starts.tolist(), ends.tolist(), strict=True):
        part = slice(start, end)
        zz, kd, pre = key // 6, key // 2 % 3, bool(key % 2)
        rows, geo = _core.radial(
            *_ring.tables(zz, kd, pre),
            frac[part],
            *(a[part] for a in data),
            tol,
            MAX_ITERATIONS,
            _ring.POLISH,
        )
        failed = (rows[:, _COL["status"]] != 0) | ~(rows[:, _COL["residual"]] <= max(tol, 1e-11))
        if failed.any():
            bad.append((start + np.flatnonzero(failed), rows[failed]))
        res[part, : len(_CORE_ROW)] = rows
        res[part, _COL["loaded"]] = np.rint(rows[:, _COL["loaded"]])
        for i, value in enumerate(_reference(geo.T, zz, kd, pre), len(_CORE_ROW)):
            res[part, i] = value
    if bad:
        failing = np.concatenate([b[0] for b in bad])
        worst = np.concatenate([b[1] for b in bad])
        residual = worst[:, _COL["residual"]]
        raise ConvergenceError(
            "ring equilibrium",
            int(worst[:, _COL["iterations"]].max()),
            float(np.max(np.where(np.isfinite(residual), residual, np.inf))),
            {"case": failing if order is None else order[failing]},
        )
    if order is None:
        return res
    out = np.empty_like(res)
    out[order] = res  # back to the order of the cases, all columns at once
    return out


def _assemble(
    shape: tuple[int, ...],
    z: np.ndarray,
    f: np.ndarray,
    kk: np.ndarray,
    g: np.ndarray,
    phi1_deg: np.ndarray,
    m: np.ndarray,
    scale: np.ndarray,
    rows: np.ndarray,
) -> LoadDistribution:
    """Scaled per-case rows -> the LoadDistribution in physical units and the input shape."""
    xi, eta, x0, y0 = (rows[:, _COL[k]] for k in ("xi", "eta", "x0", "y0"))
    e = g / 2.0
    x = e * x0 + xi * scale
    y = e * y0 + eta * scale
    zone = _load_zone(e, scale, x, y, xi, eta, x0, y0, rows[:, _COL["h"]])
    to_n_mm = f / scale  # scaled stiffness -> N/mm
    n = z.size
    matrix = np.empty((n, 2, 2))
    matrix[:, 0, 0] = rows[:, _COL["hxx"]] * to_n_mm
    matrix[:, 0, 1] = matrix[:, 1, 0] = rows[:, _COL["hxy"]] * to_n_mm
    matrix[:, 1, 1] = rows[:, _COL["hyy"]] * to_n_mm

    def shaped(a: np.ndarray) -> Any:  # one case: Python scalars, as the one-case path gives
        return numerics.scalar_out(a.reshape(shape))

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
        load_zone=shaped(zone),
        stiffness_matrix=matrix.reshape(shape + (2, 2)),
        iterations=shaped(rows[:, _COL["iterations"]].astype(np.int64)),
        offset=np.stack([xi * scale, eta * scale], axis=-1).reshape(shape + (2,)),
        reference=rows[:, [_COL["mu"], _COL["h"]]].reshape(shape + (2,)),
    )


def _load_zone(
    e: np.ndarray,
    scale: np.ndarray,
    x: np.ndarray,
    y: np.ndarray,
    xi: np.ndarray,
    eta: np.ndarray,
    x0: np.ndarray,
    y0: np.ndarray,
    h: np.ndarray,
) -> np.ndarray:
    """Half-angle of the load zone ``arccos(e/r)`` [°], without cancellation.

    ``arccos(e/r) = 2 arcsin(sqrt((1 - e/r)/2))``, with ``1 - e/r`` for ``e > 0`` from
    ``r^2 - e^2 = e^2 tan^2 h + 2 e s (d0 . zeta) + s^2 |zeta|^2`` (``|d0|^2 - 1 = tan^2 h``
    exactly, taken from ``h``, not from a difference).
    """
    r = np.hypot(x, y)
    with np.errstate(all="ignore"):
        r2_e2 = (
            (e * np.tan(h)) ** 2
            + 2.0 * e * scale * (x0 * xi + y0 * eta)
            + (scale * xi) ** 2
            + (scale * eta) ** 2
        )
        one_minus = np.where(e > 0, np.maximum(r2_e2, 0.0) / (r * (r + e)), 1.0 - e / r)
    one_minus = np.clip(one_minus, 0.0, 2.0)
    return np.rad2deg(2.0 * np.arcsin(np.sqrt(one_minus / 2.0)))


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


def check_range(
    f: np.ndarray,
    scale: np.ndarray,
    e_hat: np.ndarray,
    m: np.ndarray,
    z: np.ndarray,
    given: tuple[dict[str, Any], tuple[int, ...]] | None = None,
) -> None:
    """Reject finite inputs whose scaled problem or results would leave double precision
    (``scale`` = (F/K)^(1/m) [mm], ``e_hat`` = (G_r/2)/scale [-]); the continuum model uses the
    same range. ``given``: the inputs as given (name -> value) and the case shape, so that a
    refusal names the input's element of the first case refused (``load[2] = 1e-30 N``)."""

    def at(name: str, bad: np.ndarray, unit: str) -> str:
        return "" if given is None else validate.element_at(given[0][name], bad, given[1], unit)

    lo, hi = APPROACH_RANGE
    bad = ~((scale >= lo) & (scale <= hi))
    if np.any(bad):
        raise InputError(
            "load",
            f"load and stiffness give a one-ball approach (F_r/K)^(1/m) = "
            f"{_first(scale, bad)} mm, outside the {lo:g} to {hi:g} mm the "
            "solver resolves; check the units of the load and the stiffness",
            element=at("load", bad, "N"),
        )
    bad = ~(np.abs(e_hat) <= CLEARANCE_RATIO_MAX)
    if np.any(bad):
        raise InputError(
            "clearance",
            f"must be at most {CLEARANCE_RATIO_MAX:g} times the one-ball approach "
            f"(F_r/K)^(1/m) in size (got {_first(e_hat, bad)} times); check its unit",
            element=at("clearance", bad, "mm"),
        )
    r_lo, r_hi = (math.log10(v) for v in RESULT_RANGE)
    with np.errstate(all="ignore"):
        log_p = np.log10(np.maximum(1.0, -e_hat))
        log_q = np.log10(f) + m * log_p
        log_k = np.log10(f / scale) + np.log10(m * z) + (m - 1.0) * log_p
    bad = ~(log_q <= r_hi)
    if np.any(bad):
        raise InputError(
            "clearance",
            f"a preload of {_first(e_hat, bad)} times the one-ball approach loads the balls with "
            f"about 1e{_first(log_q, bad, '.0f')} N, beyond the {RESULT_RANGE[1]:g} N a double "
            "holds; reduce the preload (check its unit)",
            element=at("clearance", bad, "mm"),
        )
    bad = ~((log_k <= r_hi) & (np.log10(f / scale) >= r_lo) & (np.log10(f) >= r_lo))
    if np.any(bad):
        raise InputError(
            "load",
            f"load and stiffness give a bearing stiffness of about 1e{_first(log_k, bad, '.0f')} "
            f"N/mm, outside the {RESULT_RANGE[0]:g} to {RESULT_RANGE[1]:g} a double resolves; "
            "check the units of the load, the stiffness and the clearance",
            element=at("load", bad, "N"),
        )


def _first(values: np.ndarray, bad: np.ndarray, fmt: str = "") -> str:
    """The first offending value, unrounded (shortest repr) unless a format is given."""
    v = float(np.asarray(values)[bad].flat[0])
    return format(v, fmt) if fmt else repr(v)
