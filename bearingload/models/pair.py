"""A pair of identical angular-contact ball bearings on one shaft: back-to-back (DB), face-to-face
(DF) or tandem (DT), with an axial preload.

Model (Harris & Kotzalas, *Rolling Bearing Analysis*, 5th ed., ch. 8 for each bearing, as
:mod:`bearingload.models.combined`; the pair is two such bearings on one rigid shaft, as the
commercial tools model a bearing set):

* The shaft (both inner rings) moves as one rigid body about the pair's centre: ``v = (x, y,
  a, theta, theta_c)``. Bearing ``k`` sits at the axial position ``z_k = -+B/2`` (B the width
  of one bearing: the rings abut). A rigid tilt moves its inner groove centres radially by
  ``-z_k theta`` (``-z_k theta_c`` across the load line) and axially by ``R_i (theta cos phi
  + theta_c sin phi)`` (the conventions of :mod:`bearingload.models.combined`: a positive tilt
  pushes the load-line side towards +axial).
* Bearing 1 takes the shaft's thrust towards +axial (its local axes are the pair's); in DB and
  DF bearing 2 is mirrored (``sigma_2 = -1``: its local axial displacement and tilts are the
  negatives of the pair's), in DT it faces the same way (``sigma_2 = +1``). The local
  displacement of bearing k is ``L_k v``: ``(x - z_k theta, y - z_k theta_c, sigma_k a,
  sigma_k theta, sigma_k theta_c)``, plus its built-in axial preload offset. DB: bearing 1 at
  ``-B/2``, its contact lines meet the axis further out (pressure centres apart); DF: bearing 1
  at ``+B/2`` (pressure centres between the bearings); DT: bearing 1 at ``-B/2``.
* Forces by virtual work: the pair's generalised force is ``sum_k L_k^T f_k`` (``f_k`` the
  bearing's (F_x, F_y, F_a, M, M_c) on its inner ring), its stiffness ``sum_k L_k^T K_k L_k``:
  each bearing's moment plus the lever of its radial force about the centre.
* Preload ``F_p`` (DB, DF): the rings are ground so that, clamped together with no external
  load, each bearing carries the axial force ``F_p`` (every ball at the same approach; solved
  from the single bearing's pure-thrust equation with the Hertz K(alpha)). Lift-off: the
  external axial load alone at which the bearing opposite to it carries nothing, when the
  loaded one sits at twice the preload offset (for a Hertz contact at a constant angle
  ``2^1.5 F_p = 2.83 F_p``, the limit of a light preload; the contact angle growing under the
  load gives a little more: 2.885 F_p for a 7205B at F_p = 500 N).

Numerics: damped Newton on the pair's five unknowns, each case alone in the compiled core
(:func:`bearingload.models._core.solve_pair`, a C loop over the cases): a first stage in plain
doubles to a residual of 1e-9, then the balls of each bearing evaluated by the single bearing's
kernels in double-double arithmetic at the local position, the step solving the pair's tangent
(with the change of K with the angle), the line search taking a step where the potential
(stiffness frozen) falls or the residual halves. A case stops when every component is balanced
to 1e-12 of its load (or to the rounding of its terms), the measure of
:func:`~bearingload.models._combined_ring.residual_of`; a case left above 1e-8 raises
:class:`~bearingload.errors.ConvergenceError` naming its inputs. This module keeps the checks,
the set-up (the preload approach and offset, the start) and the results.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from bearingload import numerics, validate
from bearingload.constants import STEEL_MODULUS
from bearingload.errors import ConvergenceError, InputError
from bearingload.models import _core
from bearingload.models import combined as _comb
from bearingload.models._combined_ring import ACCEPT, Problem
from bearingload.models.combined import CombinedDistribution, StiffnessViews

__all__ = [
    "ARRANGEMENTS",
    "LIFE_EXPONENT",
    "PairDistribution",
    "solve_pair",
    "pair_life",
    "signs",
    "levers",
    "shaft_maps",
    "held_components",
]

#: The arrangements: back-to-back, face-to-face, tandem.
ARRANGEMENTS = ("DB", "DF", "DT")
#: Weibull exponent e of a ball bearing's life, combining the lives of its parts: ISO/TS
#: 16281:2008, 4.3 (the rings' lives, ``L = (L_i^-e + L_e^-e)^(-1/e)``, written there as the
#: exponent -9/10 = -1/e) and ISO 281:2007's system rule (Lundberg-Palmgren). [-]
LIFE_EXPONENT = 10.0 / 9.0


@dataclass(frozen=True)
class PairDistribution(StiffnessViews):
    """Solution of a bearing pair; arrays of the case shape.

    Attributes
    ----------
    arrangement : str
        "DB", "DF" or "DT".
    bearings : tuple of two CombinedDistribution
        Each bearing in its own frame (bearing 2 of DB/DF mirrored): ``load``, ``axial_load``
        and ``moment`` are the forces its balls carry (the size of its radial force, F_a >= 0
        its thrust, M its own moment), ``x``..``tilt_cross`` its local displacement, ``axial``
        from its zero-load position (the preload offset included). [N, N mm, mm, °]
    load, axial_load, moment, moment_cross : ndarray
        The loads applied to the shaft. [N, N mm]
    preload : ndarray
        F_p, the axial force each bearing of DB/DF carries with no external load. [N]
    preload_offset : ndarray
        The axial approach of each bearing at the preload. [mm]
    width : ndarray
        B; the bearings' centres lie B/2 either side of the pair's centre. [mm]
    x, y, axial, tilt, tilt_cross : ndarray
        The shaft's displacement at the pair's centre. [mm, °]
    stiffness_matrix : ndarray (..., 5, 5)
        d(F_x, F_y, F_a, M, M_c)/d(x, y, axial, tilt, tilt_cross) of the shaft at the pair's
        centre, the true tangent (its symmetric part: ``stiffness_matrix_symmetric``). [N/mm,
        N/rad, N mm/mm, N mm/rad]
    unloaded : ndarray (..., 2) of bool
        Whether each bearing carries no load.
    lift_off_axial_load : ndarray or None
        DB/DF: the external axial load alone (the sign of the given one, + if 0) at which the
        opposite bearing carries nothing (0 without preload). None for DT. [N]
    residual : ndarray
        The largest residual of the pair's equilibrium over its applied load (or the rounding
        of its terms). [-]
    iterations : ndarray of int
        Newton steps. [-]
    """

    arrangement: str
    bearings: tuple[CombinedDistribution, CombinedDistribution]
    load: Any
    axial_load: Any
    moment: Any
    moment_cross: Any
    preload: Any
    preload_offset: Any
    width: Any
    x: Any
    y: Any
    axial: Any
    tilt: Any
    tilt_cross: Any
    stiffness_matrix: np.ndarray
    unloaded: np.ndarray
    lift_off_axial_load: Any
    residual: Any
    iterations: Any


def pair_life(life_1: Any, life_2: Any, exponent: float = LIFE_EXPONENT) -> Any:
    """The life of two bearings that both must survive: ``(L1^-e + L2^-e)^(-1/e)`` (ISO/TS
    16281:2008, 4.3, the same rule for the rings of one bearing; Lundberg-Palmgren's system
    life, e = 10/9 for ball bearings). An infinite life (an unloaded bearing) drops out.
    [the unit of the lives]

    >>> round(float(pair_life(1000.0, 1000.0)), 3)
    535.887
    """
    a = np.asarray(life_1, dtype=float)
    b = np.asarray(life_2, dtype=float)
    with np.errstate(divide="ignore", over="ignore"):
        total = a ** (-exponent) + b ** (-exponent)
        out = np.where(total > 0, total ** (-1.0 / exponent), np.inf)
    out = np.where(np.isinf(a), b, np.where(np.isinf(b), a, out))  # exactly the other one
    return numerics.scalar_out(out)


@dataclass(frozen=True)
class _Pair:
    """The scaled pair problem of n cases: the balls, the maps' signs and levers, the loads."""

    prob: Problem  # the balls of either bearing
    sigma: np.ndarray  # (2,) +1 or -1
    lever: np.ndarray  # (n, 2) z_k / R_i
    preload: np.ndarray  # (n,) F_p, scaled
    f: np.ndarray  # (n, 5) applied, scaled
    held: np.ndarray  # (n, 5) bool: y and theta_c of a case symmetric about the load line, 0


def signs(kind: str) -> np.ndarray:
    """sigma_k (2,): +1, or -1 for bearing 2 of DB and DF, mirrored."""
    return np.array([1.0, 1.0 if kind == "DT" else -1.0])


def levers(kind: str, width: np.ndarray, radius: np.ndarray) -> np.ndarray:
    """z_k / R_i (n, 2): each bearing's centre from the pair's, over the tilt lever ``radius``;
    bearing 1 at -B/2 in DB and DT, at +B/2 in DF (``width`` B)."""
    first = -0.5 if kind in ("DB", "DT") else 0.5
    return np.array([first, -first]) * width[:, None] / radius[:, None]


def shaft_maps(sigma: np.ndarray, lever: np.ndarray) -> np.ndarray:
    """L_k (n, 2, 5, 5): each bearing's local displacement per shaft displacement (x, y, a,
    t, t_c), t the tilt times the lever; ``sigma`` (2,) +1, or -1 for a mirrored bearing;
    ``lever`` (n, 2) z_k over the tilt lever (:func:`levers`)."""
    diagonal = np.ones((2, 5))
    diagonal[:, 2:] = sigma[:, None]
    m = np.zeros((lever.shape[0], 2, 5, 5))
    m.reshape(-1, 2, 25)[:, :, ::6] = diagonal  # (the diagonal: every sixth of the 25)
    m[:, :, 0, 3] = m[:, :, 1, 4] = -lever
    return m


def held_components(kind: str, mirror: np.ndarray, loads: tuple[np.ndarray, ...]) -> np.ndarray:
    """(n, 5) bool: the components of the shaft's (x, y, a, t, t_c) 0 by a symmetry of the case,
    exactly: y and t_c where the balls are symmetric about the load line (``mirror``) and no
    moment acts across it; the z-fold symmetry (z >= 3) without a radial load or moment; the
    bearings' mirror image across the pair's mid-plane (not DT's) without a thrust or moment.
    ``loads`` = (F_r, F_a, M, M_c) (n,) each."""
    fr, fa, mm, mc = loads
    no_moment = (mm == 0) & (mc == 0)
    axial = (fa == 0) & no_moment if kind != "DT" else np.zeros(fa.shape, dtype=bool)
    which = np.array([mirror & (mc == 0), (fr == 0) & no_moment, axial])  # (3, n)
    return which.T @ _HELD  # (booleans: each component held where any symmetry holds it)


#: The components of (x, y, a, t, t_c) each symmetry of :func:`held_components` holds: the
#: mirror about the load line, the z-fold symmetry, the mirror across the mid-plane.
_HELD = np.array([[0, 1, 0, 0, 1], [1, 1, 0, 1, 1], [0, 0, 1, 1, 1]], dtype=bool)


#: The ball arrays of a point as the core gives them (rho, u, d, eps, up, ca, sa, cam1, q, dq,
#: root, tau, sig). [-]
BALL_ROWS = 13


@dataclass
class _State:
    """The balls of both bearings at the answer: their geometry, stiffness and loads."""

    block: np.ndarray  # the balls and their loads (13, 2, n, z), as the core gives them
    kappa: np.ndarray  # their stiffness deviations (2, n, z)
    gen: np.ndarray  # each bearing's generalised forces, local and scaled (2, n, 5)
    tangents: np.ndarray  # each bearing's true tangent, local and scaled (2, n, 5, 5)
    local: np.ndarray  # each bearing's local position, scaled (2, n, 5)


def _solve_stages(pp: _Pair, v0: np.ndarray, curve: Any) -> tuple[Any, ...]:
    """Every case solved from ``v0`` in the compiled core (:func:`bearingload.models._core.
    solve_pair`: Newton in plain doubles to a residual of 1e-9, then with the balls in
    double-double to the tolerance): (position hi, lo, residual, steps, the balls, their loads
    and forces there, the preload approach)."""
    p = pp.prob
    values = np.zeros((v0.shape[0], 0)) if curve is None else curve.values
    cont = np.ascontiguousarray
    args = [cont(a, dtype=float) for a in (pp.sigma, -pp.lever, pp.preload, pp.f)]
    args += [cont(pp.held).view(np.uint8), cont(values, dtype=float), _comb.NODE_X]
    out = _core.solve_pair(p.c, p.s, p.lengths, *args, _comb.NODE_W, cont(v0, dtype=float))
    vh, vl, res, its, _, balls, kappa, gen, tangents, local, delta_p = out
    st = _State(balls, kappa, gen, tangents, local)
    return vh, vl, res, its, st, delta_p


#: Largest width B of one bearing (the distance of the two bearings' centres) over the pitch
#: diameter d_m that a pair takes; measured: 1e8 mm on a 38.5 mm pitch solves, 1e9 mm did not
#: converge. [-]
WIDTH_MAX = 1000.0


def solve_pair(
    balls: int,
    radial_load: Any,
    axial_load: Any = 0.0,
    *,
    arrangement: str = "DB",
    preload: Any = 0.0,
    contact_angle: Any,
    ball_diameter: Any,
    pitch_diameter: Any,
    width: Any,
    f_i: Any = 0.52,
    f_o: Any = 0.53,
    cage_angle: Any = 0.0,
    moment: Any = 0.0,
    moment_cross: Any = 0.0,
    modulus: Any = STEEL_MODULUS,
    poisson: Any = 0.3,
    stiffness: Any = None,
    tilt_radius: Any = None,
) -> PairDistribution:
    """Equilibrium of the shaft in a pair of identical angular-contact ball bearings.

    Model and conventions: the module docstring. Arrays broadcast over cases.

    Parameters
    ----------
    balls : int
        Balls per bearing z, 3 to 1000. [-]
    radial_load : array_like
        F_r >= 0 on the shaft at the pair's centre, along the load line. [N]
    axial_load : array_like, default 0
        F_a on the shaft, towards +axial (bearing 1's thrust); DT: > 0. [N]
    arrangement : {"DB", "DF", "DT"}
        Back-to-back, face-to-face, tandem.
    preload : array_like, default 0
        F_p >= 0, the axial force each bearing carries with no external load (DB, DF). [N]
    contact_angle : array_like
        Design contact angle alpha_0, above 0 to 60. [°]
    ball_diameter, pitch_diameter : array_like
        D_w and d_m. [mm]
    width : array_like
        B of one bearing, at least D_w and at most :data:`WIDTH_MAX` times d_m: their centres
        lie B/2 either side of the pair's centre. [mm]
    f_i, f_o : array_like, default 0.52, 0.53
        Groove conformities. [-]
    cage_angle : array_like, default 0
        Angle of ball 1 from the load line (both bearings). [°]
    moment, moment_cross : array_like, default 0
        Moments on the shaft in and across the plane of the load line. [N mm]
    modulus, poisson : array_like
        E [MPa] and nu [-].
    stiffness : array_like, optional
        A constant ball stiffness K instead of the Hertz K(alpha). [N/mm^1.5]
    tilt_radius : array_like, optional
        The lever of the tilt at each bearing (default R_i). [mm]

    Returns
    -------
    PairDistribution

    >>> r = solve_pair(12, 0.0, 0.0, preload=500.0, contact_angle=40.0, ball_diameter=8.7312,
    ...                pitch_diameter=38.5, width=15.0)
    >>> [round(float(b.axial_load), 6) for b in r.bearings]
    [500.0, 500.0]
    """
    kind = _arrangement(arrangement)
    z = _comb.call_balls(balls)
    if z < 3:
        raise InputError(
            "balls",
            "must be at least 3 per bearing of a pair: 1 or 2 balls leave the shaft free to "
            "turn about their line (a real bearing has many more)",
        )
    # every parameter by name, in the order the checks take them
    named = dict(radial_load=radial_load, axial_load=axial_load, preload=preload)
    named |= dict(contact_angle=contact_angle, ball_diameter=ball_diameter)
    named |= dict(pitch_diameter=pitch_diameter, width=width, f_i=f_i, f_o=f_o)
    named |= dict(cage_angle=cage_angle, moment=moment, moment_cross=moment_cross)
    named |= dict(modulus=modulus, poisson=poisson)
    if stiffness is not None:
        named["stiffness"] = stiffness
    if tilt_radius is not None:
        named["tilt_radius"] = tilt_radius
    if _plain(kind, named):  # one case of plain numbers, every check passed
        shape: tuple[int, ...] = ()
        plain = named | {"cage_angle": validate.reduced_angle(named["cage_angle"])}
        c = dict(zip(named, np.array(list(plain.values()))[:, None], strict=True))
    else:
        shape, c = _checked(kind, named)
        c["cage_angle"] = validate.cage_angle(c["cage_angle"])
    narrow = c["width"] < c["ball_diameter"]
    if np.count_nonzero(narrow):  # no ring holds its balls so; the shaft's tilt then has no lever
        i = int(np.argmax(narrow))
        raise InputError(
            "width",
            f"must be at least the ball diameter D_w (a bearing is wider than its balls): "
            f"B = {c['width'][i]:.6g} mm, D_w = {c['ball_diameter'][i]:.6g} mm",
            element=validate.element_at(named["width"], narrow, shape, "mm"),
        )
    wide = c["width"] > WIDTH_MAX * c["pitch_diameter"]
    if np.count_nonzero(
        wide
    ):  # a shaft between two supports, not a pair (a width of 1e9 mm diverged)
        i = int(np.argmax(wide))
        raise InputError(
            "width",
            f"must be at most {WIDTH_MAX:g} times the pitch diameter d_m (two bearings that far "
            "apart are two supports of a shaft, not one pair): B = "
            f"{c['width'][i]:.6g} mm, d_m = {c['pitch_diameter'][i]:.6g} mm",
            element=validate.element_at(named["width"], wide, shape, "mm"),
        )
    with np.errstate(all="ignore"):
        return _solve(z, kind, c, shape)


def _arrangement(arrangement: Any) -> str:
    kind = str(arrangement).upper()
    if kind not in ARRANGEMENTS:
        raise InputError(
            "arrangement",
            f"must be DB (back-to-back), DF (face-to-face) or DT (tandem), not {arrangement!r}",
        )
    return kind


def _plain(kind: str, named: dict[str, Any]) -> bool:
    """Whether every value is a plain float that passes every check of :func:`_checked` (a case
    that does not is checked there, which names what it refuses)."""
    if not all(type(v) is float and math.isfinite(v) for v in named.values()):
        return False
    low, high = validate.CONFORMITY_RANGE
    fa, fp = named["axial_load"], named["preload"]
    positive = ("width", "modulus", "stiffness", "tilt_radius")
    ok = named["radial_load"] >= 0.0 and 0.0 < named["contact_angle"] <= 60.0 and fp >= 0.0
    ok = ok and (kind != "DT" or (fp == 0.0 and fa > 0.0))
    ok = ok and low < named["f_i"] < high and low < named["f_o"] < high
    return ok and all(named.get(k, 1.0) > 0.0 for k in positive)


def _checked(kind: str, named: dict[str, Any]) -> tuple[tuple[int, ...], dict[str, np.ndarray]]:
    """The values ``named`` checked, broadcast together: (the case shape, each flat)."""
    fr = validate.at_least("radial_load", named["radial_load"], 0.0, "N")
    fa = validate.finite("axial_load", named["axial_load"])
    fp = validate.finite("preload", named["preload"])
    _check_pair(kind, fa, fp, named["contact_angle"])
    units = {"width": "mm", "modulus": "MPa", "stiffness": "N/mm^1.5", "tilt_radius": "mm"}
    arrays = {"radial_load": fr, "axial_load": fa, "preload": fp}
    for name, value in named.items():
        if name in units:
            arrays[name] = validate.positive(name, value, units[name])
        elif name in ("f_i", "f_o"):
            arrays[name] = validate.conformity(name, value)
        elif name not in arrays:
            arrays[name] = validate.finite(name, value)
    validate.broadcast_shape(arrays)
    flat = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in arrays.values()))
    return flat[0].shape, dict(zip(arrays, (a.ravel() for a in flat), strict=True))


def _check_pair(kind: str, fa: np.ndarray, fp: np.ndarray, contact_angle: Any) -> None:
    """Refuse what a pair of this arrangement cannot take."""
    alpha = validate.finite("contact_angle", contact_angle)
    if ((alpha <= 0) | (alpha > 60)).any():
        raise InputError(
            "contact_angle",
            "must be above 0 and at most 60° for a bearing pair",
            element=validate.element(alpha, (alpha <= 0) | (alpha > 60), "°"),
        )
    if (fp < 0).any():
        raise InputError("preload", "must be >= 0 N", element=validate.element(fp, fp < 0, "N"))
    if kind == "DT" and (fp > 0).any():
        raise InputError(
            "preload",
            "a tandem pair (DT) is not preloaded in itself: both bearings face the same way, "
            "so it is preloaded against another bearing; give 0, or use DB or DF",
            element=validate.element(fp, fp > 0, "N"),
        )
    if kind == "DT" and (fa <= 0).any():
        raise InputError(
            "axial_load",
            "must be > 0 N for a tandem pair (DT): both bearings take thrust towards +axial only "
            "(a reversed load lifts every ball; with none the axial position is held by "
            "another bearing)",
            element=validate.element(fa, fa <= 0, "N"),
        )


#: The inputs a pair's refusal or failure names (their units: combined.INPUT_UNITS).
NAMED = (
    "radial_load",
    "axial_load",
    "moment",
    "moment_cross",
    "preload",
    "contact_angle",
    "width",
    "cage_angle",
)


def _solve(
    z: int, kind: str, c: dict, shape: tuple[int, ...], snap: bool = True
) -> PairDistribution:
    """The pair of the flat, checked cases ``c``; with ``snap``, the cases left unbalanced with
    a cage within :data:`~bearingload.models.combined.NEAR_SYMMETRIC_DEG` of a symmetric
    position and no moment across the load line solved at that position, as the single
    bearing solves them (the cages of the answer are then that position)."""
    geo = _comb.angular_geometry(c["ball_diameter"], c["pitch_diameter"], c["f_i"], c["f_o"],
                                  c["contact_angle"])  # fmt: skip
    if "tilt_radius" in c:
        geo = dataclasses.replace(geo, R_i=c["tilt_radius"].astype(float))
    curve = None
    if "stiffness" in c:
        k_ref = c["stiffness"]
    else:
        k_ref, values = _comb.hertz_setup(geo, c["modulus"], c["poisson"])
        curve = _comb.StiffnessCurve(values)
    fr, fa, mm, mc, fp = (c[k] for k in ("radial_load", "axial_load", "moment", "moment_cross",
                                         "preload"))  # fmt: skip
    prob, f, mirror = _scaled(z, c, geo, k_ref)
    held = held_components(kind, mirror, (fr, fa, mm, mc))
    pp = _Pair(prob, signs(kind), levers(kind, c["width"], geo.R_i), fp / prob.f_ref, f, held)
    vh, vl, res, its, st, delta_p = _solve_stages(pp, _start(pp, z, geo, pp.preload), curve)
    given = {k: c[k] for k in NAMED}
    unbalanced = ~(res <= ACCEPT)
    near = (
        _near_symmetric(z, c["cage_angle"], mc) & unbalanced
        if snap and np.count_nonzero(unbalanced)
        else None
    )
    if near is not None and np.count_nonzero(near):
        return _solve(
            z, kind, c | {"cage_angle": _symmetric(z, c["cage_angle"], near)}, shape, False
        )
    _accepted(res, its, given)
    _check_edge(st, given)
    return _result(
        kind, pp, geo, (vh, vl, res, its, st), c, shape, curve, mirror & (mc == 0), delta_p
    )


def _scaled(z: int, c: dict, geo: Any, k_ref: np.ndarray) -> tuple[Problem, np.ndarray, Any]:
    """The scaled problem of the bearings' balls, the applied forces over the largest load or
    the preload (n, 5) and which cases are mirrored about the load line: the compiled core's
    ``combined_problem`` (one loop over the cases); the loads it flags refused by
    :func:`_refuse_scale`."""
    from bearingload.models._ring import SYMMETRY_SNAP_DEG

    names = ("radial_load", "axial_load", "moment", "moment_cross", "preload")
    n = c["preload"].shape[0]
    rows = np.zeros((6, n))
    rows[:4], rows[5] = [c[k] for k in names[:4]], c["preload"]
    lengths = np.array((geo.A, geo.g, geo.R_i), dtype=float)
    limits = np.array([SYMMETRY_SNAP_DEG, _comb.GEOMETRY_RATIO_MAX, 0.0])
    k_ref = np.ascontiguousarray(k_ref, dtype=float)
    cage = np.ascontiguousarray(c["cage_angle"], dtype=float)
    status, cos_, sin_, mirror, _, f, out = _core.combined_problem(
        z, rows, cage, lengths, k_ref, False, False, limits
    )
    if np.count_nonzero(status):
        _refuse_scale(geo, k_ref, status == _core.SetupStatus.TOO_LIGHT, *(c[k] for k in names))
    none = np.zeros((n, 5), dtype=bool)
    # out: the scale, the lengths (a_hat, pre, gap, b_hi, b_lo, t_imp), F
    scaled = (out[0], out[1:7], np.zeros((n, 5)), none, none, out[7], k_ref)
    one_sided = np.zeros(n, dtype=bool)
    one_sided[:] = True  # (np.ones is a Python function: ten times the cost on one case)
    return Problem(z, cos_, sin_, *scaled, one_sided), f, mirror


def _refuse_scale(geo: Any, k_ref: np.ndarray, flagged: np.ndarray, *loads: np.ndarray) -> None:
    """InputError on the loads of a pair the core flags: none at all, or too small for the
    groove geometry (``flagged``: the core decides; the combined model's check words it, its
    advice replaced)."""
    fr, fa, mm, mc, fp = loads
    f_ref = np.maximum(_comb.reference_force(fr, fa, mm, mc, geo.R_i), fp)
    if (f_ref <= 0).any():
        raise InputError(
            "radial_load",
            "give a radial load, an axial load, a moment or a preload",
            element=validate.element(fr, f_ref <= 0, "N"),
        )

    # the first case refused names the parameter of its largest load, the preload among them
    def sizes() -> dict[str, np.ndarray]:
        return {"preload": fp} | _comb.load_sizes(fr, fa, mm, mc, geo.R_i)

    try:
        _comb.check_scale(f_ref, k_ref, geo.A, sizes=sizes, flagged=flagged)
    except InputError as exc:  # its advice (the radial solver) does not apply to a pair
        if exc.reason not in (_comb.TOO_LIGHT, _comb.TOO_LIGHT_ANGULAR):
            raise
        f_min = float(np.max(k_ref * (geo.A / _comb.GEOMETRY_RATIO_MAX) ** 1.5))
        raise InputError(
            exc.parameter,
            f"the loads are too small for the pair solver (the largest of F_r, |F_a|, M/R_i and "
            f"the preload is {float(np.min(f_ref)):.3g} N; it takes at least {f_min:.2g} N for "
            "this bearing)",
        ) from exc


def _start(pp: _Pair, z: int, geo: Any, pre: np.ndarray) -> np.ndarray:
    """A start: the shares of the loads a rigid ring would give (Stribeck's 5 for the radial
    load), or the preloaded position where the preload is the larger."""
    f = pp.f
    n = f.shape[0]
    v = np.zeros((n, 5))
    ca, sa = np.cos(geo.alpha0), np.sin(geo.alpha0)
    share = (0.5 if pp.sigma[1] > 0 else 1.0) * np.abs(f[:, 2])
    v[:, 2] = np.sign(f[:, 2]) * np.cbrt(share / (z * sa)) ** 2 / sa
    v[:, 0] = np.cbrt(2.5 * f[:, 0] / (z * ca)) ** 2 / ca
    v[pre >= np.maximum.reduce(np.abs(f), axis=1)] = 0.0  # (the largest load: the preload)
    return v


def _near_symmetric(z: int, cage: np.ndarray, mc: np.ndarray) -> np.ndarray:
    """Which cases have a cage [°] within NEAR_SYMMETRIC_DEG of a symmetric position and no
    moment across the load line (the core's symmetry rule, ``directions``, at that snap)."""
    near = _core.directions(z, np.ascontiguousarray(cage, dtype=float), _comb.NEAR_SYMMETRIC_DEG)
    return near[2] & (mc == 0)


def _symmetric(z: int, cage: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """``cage`` [°] with the ``rows`` moved to their nearest symmetric position."""
    half = 180.0 / z
    return np.where(rows, np.round(cage / half) * half, cage)


def _accepted(res: np.ndarray, its: np.ndarray, given: dict) -> None:
    bad = ~(res <= ACCEPT)
    if np.count_nonzero(bad):  # (np.count_nonzero: a fifth of .any()'s time on one case)
        known = res[bad][np.isfinite(res[bad])]
        cases = {k: v[bad] for k, v in given.items()}
        raise ConvergenceError(
            "bearing-pair shaft equilibrium", int(its[bad].max()),
            float(known.max()) if known.size else math.nan, cases, units=_comb.INPUT_UNITS,
        )  # fmt: skip


def _check_edge(st: _State, given: dict) -> None:
    """Refuse a loaded ball at the groove edge (contact angle 90°), as the single bearing."""
    b = st.block  # rho, ca, sa, root: rows 0, 5, 6, 10 (2, n, z)
    near = (b[10] > 0) & ((b[0] <= 0) | (b[5] < 1e-8))  # (elsewhere below 90° - 5e-7°)
    if not np.count_nonzero(near):
        return
    edge = near & ((b[0] <= 0) | (np.rad2deg(np.arctan2(np.abs(b[6]), b[5])) >= 90.0))
    for k in range(2):
        if edge[k].any():
            from bearingload.errors import format_cases

            case = int(np.nonzero(edge[k])[0][0])
            one = {key: v[[case]] for key, v in given.items()}
            raise InputError(
                "axial_load",
                f"the loads drive a ball of bearing {k + 1} to a contact angle of 90°, the edge of "
                f"its groove, which the model does not describe ({format_cases(one, _comb.INPUT_UNITS)})",
            )


#: The couplings of (x, axial, tilt) with (y, tilt_cross): 0 in a case symmetric about the
#: load line.
_COUPLING = np.zeros((5, 5), dtype=bool)
_COUPLING[np.ix_([0, 2, 3], [1, 4])] = _COUPLING[np.ix_([1, 4], [0, 2, 3])] = True


def _result(kind: str, pp: _Pair, geo: Any, answer: tuple[Any, ...], c: dict,
            shape: tuple[int, ...], curve: Any, mirrored: np.ndarray,
            delta_p: np.ndarray) -> PairDistribution:  # fmt: skip
    """Back to physical units: each bearing as a CombinedDistribution, the pair's values."""
    vh, vl, res, its, st = answer
    p = pp.prob
    scale, f_ref, radius = p.scale, p.f_ref, geo.R_i
    n = vh.shape[0]
    maps = shaft_maps(pp.sigma, pp.lever * radius[:, None])  # physical: tilts in radians
    axisymmetric = pp.held[:, 0]  # no radial force nor moment on a bearing, exactly
    (radial, thrust, moment), unloaded = _core.pair_loads(
        st.gen, st.block, np.ascontiguousarray(axisymmetric).view(np.uint8), f_ref, radius
    )
    z = p.z
    # both bearings in one call of the core's combined_result (2n cases, bearing-major), their
    # tangents made physical there (as physical_tangent)
    one = _comb.result_inputs(p, geo, moment[0], c["cage_angle"])
    case_in = np.concatenate((one, one), axis=1)
    case_in[7] = moment.reshape(-1)
    tangents = st.tangents.reshape(2 * n, 5, 5).copy()
    rows, per_ball, overflow = _core.combined_result(
        np.ascontiguousarray(st.local).reshape(2 * n, 5),
        case_in,
        np.ascontiguousarray(st.gen).reshape(2 * n, 5),
        st.block.reshape(BALL_ROWS, 2 * n, z),
        np.ascontiguousarray(st.kappa).reshape(2 * n, z),
        False,
        tangents,
        np.concatenate((mirrored, mirrored)).view(np.uint8),
    )
    if np.count_nonzero(overflow):
        _comb.refuse_overflow()
    bearings = []
    total = np.zeros((n, 5, 5))
    for k in range(2):
        part = slice(k * n, (k + 1) * n)
        tangent = tangents[part].copy()
        answer = (rows[:, part], per_ball[:, part], tangent, its)
        loads = (radial[k], thrust[k], np.zeros(n), c["cage_angle"])
        bearings.append(_comb.distribution_of(shape, z, answer, loads, geo.R_i, None))
        total += maps[:, k].transpose(0, 2, 1) @ tangent @ maps[:, k]
    total[mirrored[:, None, None] & _COUPLING] = 0.0
    offset, lift_off = _lift_off(pp, curve, delta_p)
    lift = None if kind == "DT" else np.where(c["axial_load"] < 0, -lift_off, lift_off)
    moved = (vh + vl) * scale[:, None]  # (x, y, axial, and the tilts times their lever)
    tilts = np.rad2deg(moved[:, 3:] / radius[:, None])
    rows = np.array(
        [c[k] for k in ("radial_load", "axial_load", "moment", "moment_cross", "preload")]
        + [offset * scale, c["width"], *moved[:, :3].T, *tilts.T, res]
    )  # one case of plain numbers: Python floats, as numerics.scalar_out gives them
    cases = rows.reshape((13,) + shape) if shape else rows[:, 0].tolist()
    load, axial_load, moment_, moment_cross, preload, offset_, width = cases[:7]
    x, y, axial, tilt, tilt_cross, residual = cases[7:]

    def case(a: Any) -> Any:
        return np.asarray(a).reshape(shape) if shape else np.asarray(a).item()

    return PairDistribution(
        arrangement=kind,
        bearings=(bearings[0], bearings[1]),
        load=load,
        axial_load=axial_load,
        moment=moment_,
        moment_cross=moment_cross,
        preload=preload,
        preload_offset=offset_,
        width=width,
        x=x,
        y=y,
        axial=axial,
        tilt=tilt,
        tilt_cross=tilt_cross,
        stiffness_matrix=total.reshape(shape + (5, 5)),
        unloaded=unloaded.reshape(shape + (2,)),
        lift_off_axial_load=None if lift is None else case(lift),
        residual=residual,
        iterations=case(its),
    )


def _lift_off(pp: _Pair, curve: Any, delta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The axial approach of a bearing from its zero-load position to every ball at ``delta``
    (scaled), ``u_p - u_0 = delta (2A + delta)/(u_p + u_0)`` without cancellation, and the
    external axial load alone at which one bearing of a preloaded DB/DF pair carries nothing
    (the other then at twice that offset from its zero-load position) [N], its magnitude: the
    compiled core's ``pair_lift_off``."""
    p = pp.prob
    values = np.zeros((delta.shape[0], 0)) if curve is None else curve.values
    cont = np.ascontiguousarray
    rows = (cont(a, dtype=float) for a in (p.a_hat, p.gap, delta, p.f_ref, values))
    return _core.pair_lift_off(p.z, *rows, _comb.NODE_X, _comb.NODE_W)
