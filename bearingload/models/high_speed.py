"""Ball dynamics at speed: centrifugal force and gyroscopic moment of every ball, outer-raceway
control (Jones 1960; Harris & Kotzalas, *Rolling Bearing Analysis*, 5th ed., vol. 2 "Advanced
Concepts of Bearing Technology", ch. 2-3).

Units: N, mm, kg, s (the shaft speed in rpm at the input, rad/s inside); ball density in kg/m^3.
The geometry, loads and conventions are those of
:func:`bearingload.models.combined.solve_combined`, whose static answer is the start; each ball
has its own centre ``(delta_o, alpha_o)`` from the outer groove curvature centre, and the inner
ring sees the inner contacts only. The model, its equations and the numerics (the compiled core's
sections at speed; the rescues of this module: :func:`_dynamic_start`,
:func:`_carry_small_loads`, :func:`_off_symmetry`) are stated in docs/speed.md ("The model",
"Numerics"), with the constants of this module by name.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from bearingload import validate
from bearingload.constants import STEEL_MODULUS
from bearingload.errors import ConvergenceError, InputError
from bearingload.models import _core
from bearingload.models import combined as _combined
from bearingload.models.combined import CombinedDistribution

__all__ = ["HighSpeedDistribution", "solve_high_speed", "STEEL_DENSITY", "MAX_SPEED_PITCH",
           "MODEL"]  # fmt: skip

#: Bearing steel (100Cr6) density. [kg/m^3]
STEEL_DENSITY = 7850.0
#: mm^3 per m^3: a density in kg/m^3 over this is in kg/mm^3. [-]
_MM3 = 1e9
#: Largest n d_m accepted (n the shaft speed [rpm], d_m [mm]). [mm/min]
MAX_SPEED_PITCH = 2.0e6
#: The words of the refusal of a speed beyond :data:`MAX_SPEED_PITCH` (the command line adds
#: its way to the static model after them: :func:`too_fast`).
TOO_FAST = "mm/min for the ball-dynamics model"


#: The reason of the refusal of a speed beyond :data:`MAX_SPEED_PITCH`.
TOO_FAST_REASON = "too_fast"


def too_fast(exc: BaseException) -> bool:
    """Whether ``exc`` is the refusal of a speed beyond :data:`MAX_SPEED_PITCH`."""
    return isinstance(exc, InputError) and exc.reason == TOO_FAST_REASON


#: The model, as the outputs name it.
MODEL = "ball dynamics: centrifugal force and gyroscopic moment, outer-raceway control"
#: Relative residual of the ring equilibrium (of the largest applied load). [-]
TOLERANCE = 1e-12
#: Largest ring residual accepted at the end. [-]
ACCEPT = 1e-9
#: A ring residual within this times the sum of the magnitudes of its terms is their rounding
#: (the static model's :data:`bearingload.models._combined_ring.ROUNDING`). [-]
ROUNDING = 64.0 * float(np.finfo(float).eps)
_EPS = float(np.finfo(float).eps)
#: Largest rounding level of the ring forces (the core's ``score``) over the largest applied load
#: solved; above it the load is refused (the answer balances it to about a tenth of that). [-]
LEVEL_MAX = 1e-5
#: A free direction of the ring (one no symmetry or misalignment holds) whose stiffness, the
#: diagonal entry of the tangent in consistent units (the tilts as R_i times their angle: N/mm),
#: is at most this times the largest diagonal entry is one the loads do not determine: a range
#: of positions balances them (one ball loaded on the load line leaves y free). [-]
SINGULAR = 1e-9
#: Largest ring residual accepted, over the largest applied load, where the balls' own residuals
#: (each balanced to BALL_TOLERANCE of its forces) move the ring forces more than ACCEPT of it:
#: a light load against the balls' centrifugal forces (a tenth of LEVEL_MAX). [-]
NOISE_MAX = 1e-6
#: Ring Newton steps; trial steps of each: the Newton step halved HALVINGS times, then
#: Levenberg-Marquardt steps. [-]
RING_ITERATIONS = 200
LM_TRIALS = 12
HALVINGS = 6
#: Relative residual of each ball's equations (of the sum of its force magnitudes). [-]
BALL_TOLERANCE = 1e-13
#: Newton steps of a ball from its warm start, and from the loose / touching starts; halvings
#: of a ball's Newton step. [-]
BALL_ITERATIONS = 12
FALLBACK_ITERATIONS = 60
BALL_HALVINGS = 30
#: Rounding of an approach over its length's (of the ball tolerance). [-]
_ROUND = 16.0 * _EPS / BALL_TOLERANCE
#: An applied component is carried where the answer balances it to this share of itself (or
#: the case to TOLERANCE); a component not carried is solved by continuation from SMALL_LOAD
#: of the largest applied load (:func:`_carry_small_loads`). [-]
CARRIED = 1e-3
SMALL_LOAD = 1e-6
#: A case left unbalanced with the cage closer than this to a symmetric angle is solved by
#: continuation in the offset from it (:func:`_off_symmetry`). [°]
OFF_SYMMETRY = 0.1
#: Stages of the continuation in speed of a case the direct solve leaves unbalanced. [-]
CONTINUATION_STAGES = 200
#: N mm per kg mm^2/s^2 (forces from kg, mm, s). [-]
_KG_MM = 1e-3


@dataclass(frozen=True)
class HighSpeedDistribution(CombinedDistribution):
    """The combined-load answer with each ball's dynamics; arrays as in CombinedDistribution.

    ``contact_angles``, ``ball_loads`` and ``ball_stiffnesses`` are the inner contacts' (those
    the inner ring sees); ``stiffness_matrix`` the tangent of the ring forces with the ball
    equations eliminated (not symmetric at speed: the gyroscopic terms have no potential).

    Attributes
    ----------
    speed : ndarray
        Shaft (inner ring) speed n. [rpm]
    ball_density : ndarray
        [kg/m^3]
    contact_angles_inner, contact_angles_outer : ndarray (..., z)
        alpha_i, alpha_o. [°]
    ball_loads_inner, ball_loads_outer : ndarray (..., z)
        Q_i, Q_o. [N]
    ball_stiffnesses_outer : ndarray (..., z)
        K_o (``ball_stiffnesses`` holds K_i). [N/mm^1.5]
    approaches_inner, approaches_outer : ndarray (..., z)
        delta_i, delta_o (negative: a gap). [mm]
    ball_offsets_axial, ball_offsets_radial : ndarray (..., z)
        X_1, X_2: the ball centre from the outer groove curvature centre. [mm]
    orbit_speeds, spin_speeds : ndarray (..., z)
        omega_c (cage) and omega_R of every ball. [rad/s]
    attitude_angles : ndarray (..., z)
        beta. [°]
    centrifugal_forces : ndarray (..., z)
        F_c. [N]
    gyroscopic_moments : ndarray (..., z)
        M_g. [N mm]
    displacement_undetermined : ndarray of bool
        The loads do not determine the ring's position in a free direction (its stiffness there
        at most :data:`SINGULAR` of the largest, :func:`undetermined`): a range of positions
        balances them; the one given is where the solver stopped.
    model : str
        :data:`MODEL`.
    """

    speed: Any = None
    ball_density: Any = None
    contact_angles_inner: Any = None
    contact_angles_outer: Any = None
    ball_loads_inner: Any = None
    ball_loads_outer: Any = None
    ball_stiffnesses_outer: Any = None
    approaches_inner: Any = None
    approaches_outer: Any = None
    ball_offsets_axial: Any = None
    ball_offsets_radial: Any = None
    orbit_speeds: Any = None
    spin_speeds: Any = None
    attitude_angles: Any = None
    centrifugal_forces: Any = None
    gyroscopic_moments: Any = None
    displacement_undetermined: Any = None
    model: str = MODEL


@dataclass
class BallSet:
    """Constants of every ball per case, physical units: ``consts`` (n, 6) r'_i = (f_i - 1/2)
    D_w, r'_o, D_w, d_m [mm], the shaft speed omega [rad/s], the ball mass [kg] (the core's
    layout); ``ki``, ``ko`` K_i and K_o at the Chebyshev nodes of cos(alpha) (n, 1, NODES)
    [N/mm^1.5]."""

    consts: np.ndarray
    ki: np.ndarray
    ko: np.ndarray

    def take(self, idx: np.ndarray) -> BallSet:
        return BallSet(self.consts[idx], self.ki[idx], self.ko[idx])


def ball_set(
    geo: Any, modulus: np.ndarray, poisson: np.ndarray, speed: np.ndarray, density: np.ndarray
) -> BallSet:
    """The balls of every case of the geometry ``geo`` (flat, n) turning at ``speed`` [rpm],
    of ``density`` [kg/m^3], with the Hertz stiffness of ``modulus``, ``poisson``."""
    ki, ko = stiffness_nodes(geo, modulus, poisson)
    radii = [(geo.f_i - 0.5) * geo.D_w, (geo.f_o - 0.5) * geo.D_w, geo.D_w, geo.d_m]
    mass = density / _MM3 * math.pi / 6.0 * geo.D_w**3
    return BallSet(np.stack(radii + [speed * math.pi / 30.0, mass], axis=1), ki, ko)


def stiffness(nodes: np.ndarray, cos_alpha: np.ndarray) -> np.ndarray:
    """K(cos alpha) from its values ``nodes`` (n, 1, NODES) at the Chebyshev nodes (barycentric
    interpolation, as the core's ``stiffness_at``); below cos = 0.05 (a loose ball pointing
    across the groove: no load) the value at 0.05. [N/mm^1.5]"""
    terms = (2.0 * np.maximum(cos_alpha, 0.05) - 1.0)[..., None] - _NODE_X  # x - x_k
    np.divide(_NODE_W, terms, out=terms)  # w_k / (x - x_k)
    return (terms @ np.swapaxes(nodes, -1, -2))[..., 0] / terms.sum(axis=-1)


def stiffness_nodes(geo: Any, e: np.ndarray, nu: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """K_i and K_o of every case at the Chebyshev nodes of cos(alpha) (n, 1, NODES): exact
    Hertz (:func:`bearingload.contact.hertz.ball_stiffness` at the pitch diameter
    d_m / cos alpha, the static model's curvature rule), once per distinct geometry (cached,
    the cache changes no bit). [N/mm^1.5]"""
    from bearingload.contact.hertz import ball_stiffness

    columns = (geo.D_w, geo.d_m, geo.f_i, geo.f_o, e, nu)
    rows_i, rows_o = [], []
    for key in zip(*(a.tolist() for a in columns), strict=True):
        nodes = _NODE_CACHE.get(key)
        if nodes is None:  # (kept here: another thread may drop it from the cache)
            dw, dm, fi, fo, ee, nn = key
            k = ball_stiffness(dw, dm / _NODE_COS, fi, fo, ee, nn)
            nodes = (np.asarray(k.inner, float), np.asarray(k.outer, float))
            _NODE_CACHE[key] = nodes
            _combined.trim_cache(_NODE_CACHE)
        k_i, k_o = nodes
        rows_i.append(k_i)
        rows_o.append(k_o)
    return np.stack(rows_i)[:, None, :], np.stack(rows_o)[:, None, :]


_NODE_COS = _combined.NODE_COS
_NODE_X = _combined.NODE_X
_NODE_W = _combined.NODE_W
_NODE_CACHE: dict[tuple[float, ...], tuple[np.ndarray, np.ndarray]] = {}


def check_speed(speed: Any, density: Any, dm: Any) -> tuple[np.ndarray, np.ndarray]:
    """The shaft ``speed`` [rpm] and ball ``density`` [kg/m^3] as float arrays, refused
    (:class:`~bearingload.errors.InputError`) outside their ranges: a speed of 0 or more,
    n d_m at most :data:`MAX_SPEED_PITCH` with the pitch diameters ``dm`` [mm]."""
    n = validate.finite("speed", speed)
    if np.any(n < 0):
        raise InputError(
            "speed",
            "must be >= 0 rpm (the inner ring's speed)",
            element=validate.element(n, n < 0, "rpm"),
        )
    rho = validate.positive("ball_density", density, "kg/m^3")
    if np.any((rho < 1.0) | (rho > 1e5)):
        raise InputError(
            "ball_density",
            "must be in kg/m^3 (steel 7850, silicon nitride 3200), between 1 and 1e5",
            element=validate.element(rho, (rho < 1.0) | (rho > 1e5), "kg/m^3"),
        )
    n_b, dm_b = np.broadcast_arrays(n, np.asarray(dm, dtype=float))
    with np.errstate(over="ignore"):
        too_fast = n_b * dm_b > MAX_SPEED_PITCH
    if np.any(too_fast):
        first = np.flatnonzero(too_fast)[0]
        given, pitch = float(n_b.flat[first]), float(dm_b.flat[first])
        raise InputError(
            "speed",
            f"n d_m must be at most {MAX_SPEED_PITCH:.0e} {TOO_FAST} "
            f"(n = {_digits(given, MAX_SPEED_PITCH / pitch)} rpm with d_m = {pitch:.6g} mm: at "
            f"most {MAX_SPEED_PITCH / pitch:.10g} rpm; beyond, ring expansion, cage "
            "and lubricant forces it leaves out matter)",
            reason=TOO_FAST_REASON,
            element=validate.element_at(n, too_fast, too_fast.shape, "rpm"),
        )
    return n, rho


def _digits(value: float, other: float) -> str:
    """``value`` with 6 significant digits, more where 6 do not tell it from ``other``."""
    for digits in range(6, 13):
        text, twin = f"{value:.{digits}g}", f"{other:.{digits}g}"
        if text != twin:
            return text
    return f"{value:.12g}"


def solve_high_speed(
    balls: int,
    radial_load: Any,
    axial_load: Any = 0.0,
    *,
    speed: Any,
    ball_density: Any = STEEL_DENSITY,
    ball_diameter: Any,
    pitch_diameter: Any,
    f_i: Any = 0.52,
    f_o: Any = 0.53,
    clearance: Any = 0.0,
    cage_angle: Any = 0.0,
    moment: Any = None,
    misalignment: Any = None,
    modulus: Any = STEEL_MODULUS,
    poisson: Any = 0.3,
    tilt_radius: Any = None,
    moment_cross: Any = 0.0,
    contact_angle: Any = None,
) -> HighSpeedDistribution:
    """Equilibrium of the inner ring turning at ``speed`` with every ball's centrifugal force and
    gyroscopic moment (outer-raceway control); see docs/speed.md.

    Parameters as :func:`bearingload.models.combined.solve_combined` (a constant ``stiffness``
    is not taken: the two contacts need their own Hertz stiffness), and

    speed : array_like
        Shaft speed n of the inner ring, >= 0, n d_m <= :data:`MAX_SPEED_PITCH`. [rpm]
    ball_density : array_like, default :data:`STEEL_DENSITY`
        Density of the balls. [kg/m^3]

    Raises
    ------
    InputError
        As solve_combined; a speed or density outside its range.
    ConvergenceError
        A ball or the ring left unbalanced; the message names the inputs of the cases.

    At speed the outer contacts take the centrifugal force (7205B-sized, 20 000 rpm, thrust):

    >>> r = solve_high_speed(13, 0.0, 1000.0, speed=20000.0, ball_diameter=7.938,
    ...                      pitch_diameter=38.5, contact_angle=40.0)
    >>> bool((r.ball_loads_outer > r.ball_loads_inner).all())
    True
    """
    n_rpm, density = check_speed(speed, ball_density, pitch_diameter)
    if n_rpm.ndim or density.ndim or np.ndim(radial_load):
        validate.broadcast_shape(
            {"radial_load": radial_load, "speed": n_rpm, "ball_density": density}
        )
        wide = np.broadcast_shapes(np.shape(radial_load), n_rpm.shape, density.shape)
        if wide != np.shape(radial_load):
            radial_load = np.broadcast_to(np.asarray(radial_load, dtype=float), wide)
    try:
        static = _combined.solve_combined(
            balls,
            radial_load,
            axial_load,
            ball_diameter=ball_diameter,
            pitch_diameter=pitch_diameter,
            f_i=f_i,
            f_o=f_o,
            clearance=clearance,
            cage_angle=cage_angle,
            moment=moment,
            misalignment=misalignment,
            modulus=modulus,
            poisson=poisson,
            tilt_radius=tilt_radius,
            moment_cross=moment_cross,
            contact_angle=contact_angle,
        )
    except ConvergenceError as exc:
        loads = (radial_load, axial_load, moment, misalignment, moment_cross, tilt_radius)
        ring = (ball_diameter, pitch_diameter, f_i, f_o, clearance, cage_angle, modulus)
        inputs = (*loads, *ring, poisson, contact_angle)
        raise _with_speed(exc, n_rpm, inputs) from None
    shape = np.shape(static.x)
    z = static.balls
    given = {"radial_load": radial_load, "axial_load": axial_load,
             "moment": 0.0 if moment is None else moment, "moment_cross": moment_cross,
             "clearance": clearance, "cage_angle": cage_angle, "speed": n_rpm}  # fmt: skip
    if misalignment is not None:
        given["misalignment"] = misalignment
    at_rest = ("x", "y", "axial", "tilt", "tilt_cross", "tilt_radius")
    columns = flat_columns(
        shape,
        *given.values(),
        *(getattr(static, k) for k in at_rest),
        ball_diameter,
        pitch_diameter,
        f_i,
        f_o,
        modulus,
        poisson,
        density,
        0.0 if contact_angle is None else contact_angle,
    )
    flat = dict(zip(given, columns, strict=False))
    case_arrays: dict[str, Any] = dict(zip(at_rest, columns[len(given) :], strict=False))
    dw, dm, fi, fo, e, nu, rho_b, alpha_d = columns[len(given) + len(at_rest) :]
    geo = (
        _combined.ring_geometry(dw, dm, fi, fo, flat["clearance"])
        if contact_angle is None
        else _combined.angular_geometry(dw, dm, fi, fo, alpha_d)
    )
    geo = dataclasses.replace(geo, R_i=case_arrays["tilt_radius"])
    one_sided = np.full(dw.shape, contact_angle is not None)
    static_kw = dict(ball_diameter=dw, pitch_diameter=dm, f_i=fi, f_o=fo, modulus=e,
                     poisson=nu, cage_angle=flat["cage_angle"], moment_cross=flat["moment_cross"],
                     tilt_radius=None if tilt_radius is None else case_arrays["tilt_radius"],
                     moment=None if moment is None else flat["moment"],
                     misalignment=flat.get("misalignment"))  # fmt: skip
    case_arrays["shifted"] = lambda rows: _dynamic_start(
        z, geo, flat, case_arrays, (e, nu, rho_b), static_kw, contact_angle, rows
    )
    named = {"speed": (n_rpm, "rpm"), "radial_load": (radial_load, "N")}
    case_arrays["refused"] = functools.partial(refused_case, named, shape)
    with np.errstate(all="ignore"):
        out = _solve(z, geo, flat, case_arrays, (e, nu, rho_b), one_sided,
                     misalignment is not None)  # fmt: skip
    return bearing_result(static, shape, z, geo, flat, density, out, one_sided, misalignment)


def flat_columns(shape: tuple[int, ...], *values: Any) -> list[np.ndarray]:
    """Each of ``values`` (numbers or arrays that broadcast to the case ``shape``) as a flat
    float array (n,): the rows of one array."""
    rows = np.empty((len(values),) + shape)
    for i, value in enumerate(values):
        rows[i] = value
    return list(rows.reshape(len(values), -1))


def _dynamic_start(
    z: int, geo: Any, flat: dict, pos: dict, material: tuple[np.ndarray, ...], static_kw: dict,
    contact_angle: Any, rows: np.ndarray,
) -> dict[str, np.ndarray]:  # fmt: skip
    """The second start of the ring Newton (cases ``rows`` the static start leaves
    unbalanced): the static answer of the bearing whose balls are pushed out by their
    rigid-rolling centrifugal approach ``delta_c = (F_c/K_o)^(2/3)`` (docs/speed.md,
    "Numerics"): ring position, tilts [°], ``u`` the axial offset of the groove centres [mm].
    Cases at speed 0, or whose shifted bearing the static model refuses, keep the static
    answer."""
    shift = np.where(contact_angle is not None, geo.A * np.sin(geo.alpha0), 0.0)
    out = {name: pos[name].copy() for name in ("x", "y", "tilt", "tilt_cross")}
    out["u"] = pos["axial"] + shift
    moving = rows[flat["speed"][rows] > 0]
    if moving.size == 0:
        return out
    ki, ko = stiffness_nodes(geo, *material[:2])
    cos0 = np.cos(geo.alpha0)
    omega = flat["speed"] * math.pi / 30.0
    mass = material[2] / _MM3 * math.pi / 6.0 * geo.D_w**3
    wc = 0.5 * omega * (1.0 - geo.D_w / geo.d_m * cos0)
    fc = 0.5 * mass * geo.d_m * wc * wc * _KG_MM
    delta_c = (fc / stiffness(ko, cos0[:, None])[:, 0]) ** (2.0 / 3.0)
    kw = {k: (v if v is None else v[moving]) for k, v in static_kw.items()}
    cos1 = np.maximum(cos0 - delta_c / geo.A, 1e-3)[moving]
    if contact_angle is None:
        kw["clearance"] = 2.0 * np.minimum(geo.g + delta_c, geo.A * (1.0 - 1e-6))[moving]
    else:
        kw["contact_angle"] = np.rad2deg(np.arccos(cos1))
    try:
        s = _combined.solve_combined(z, flat["radial_load"][moving], flat["axial_load"][moving],
                                     **kw)  # fmt: skip
    except (InputError, ConvergenceError):
        return out
    new_shift = geo.A[moving] * np.sqrt(1.0 - cos1**2) if contact_angle is not None else 0.0
    for name in ("x", "y", "tilt", "tilt_cross"):
        out[name][moving] = np.ravel(getattr(s, name))
    out["u"][moving] = np.ravel(s.axial) + new_shift
    return out


@dataclass
class Ring:
    """The bearings of n cases at speed, each in its own frame, as the core's
    :func:`~bearingload.models._core.solve_speed` takes them (physical units)."""

    b: BallSet
    c: np.ndarray  # cos phi_j (n, z)
    s: np.ndarray
    geo: np.ndarray  # (n, 4): A - G_r/2 [mm], f_ref [N], A [mm], 1.0 where one-sided

    @property
    def f_ref(self) -> np.ndarray:
        """The largest applied load of each case (n,). [N]"""
        return self.geo[:, 1]

    def take(self, idx: np.ndarray) -> Ring:
        return Ring(self.b.take(idx), self.c[idx], self.s[idx], self.geo[idx])


def ring(b: BallSet, directions: tuple, geo: Any, f_ref: np.ndarray, one_sided: np.ndarray) -> Ring:
    """The :class:`Ring` of the balls ``b`` at the ``directions`` (cos, sin (n, z)) in the
    bearings ``geo`` (flat), ``f_ref`` the largest applied load [N]."""
    c, s = (np.ascontiguousarray(a, dtype=float) for a in directions)
    return Ring(b, c, s, np.stack([geo.A - geo.g, f_ref, geo.A, one_sided.astype(float)], axis=1))


@dataclass
class BallState:
    """Every ball and the ring's forces at a position v (n, 5)."""

    do: np.ndarray
    ao: np.ndarray
    gen: np.ndarray  # (n, 5) generalised ring forces [N]
    jac: np.ndarray  # (n, 5, 5) d gen / d v
    merit: np.ndarray  # (n,) largest free residual over f_ref (inf: a ball unsolved)
    terms: tuple[np.ndarray, ...]
    score: np.ndarray  # (n,) the residual over f_ref or, where larger, its rounding (or the
    # balls' own residuals on it, up to NOISE_MAX of f_ref) over ACCEPT
    level: np.ndarray  # (n,) the largest rounding level over f_ref

    @property
    def accepted(self) -> np.ndarray:
        """(n,) bool: every free component balanced to ACCEPT of the largest applied load or
        to the rounding of its terms and of the ball positions."""
        return self.score <= ACCEPT


def _state(part: tuple[np.ndarray, ...], out: np.ndarray) -> BallState:
    """A bearing's :class:`BallState` from the core's (balls, terms, ring) (``store_dyn``), the
    measures of its case (merit, score, level) from ``out`` (``store_case``)."""
    balls, terms, ring = part
    n = ring.shape[0]
    return BallState(
        balls[0],
        balls[1],
        ring[:, :5].copy(),
        ring[:, 5:30].reshape(n, 5, 5),
        out[:, 35].copy(),
        tuple(terms),
        out[:, 36].copy(),
        out[:, 37].copy(),
    )


def core_solve(
    r: Ring,
    shaft: tuple[np.ndarray, ...],
    limits: np.ndarray,
    v0: np.ndarray,
    v_static: np.ndarray,
    continued: bool,
) -> tuple[np.ndarray, list[BallState], np.ndarray]:
    """The core's solve (``solve_speed``) of n cases of bearings ``r``: one bearing, or a pair's
    shaft, ``shaft`` = (maps (n, k, 5, 5), offset (n, k, 5), f (n, 5), held (n, 5) uint8) and
    its ``limits`` (4,: iterations, stages, warm stages, the state at rest); the Newton from v0,
    where left unbalanced and ``continued`` the continuation from v_static. Returns (v, each
    bearing's state, the core's out (n, 45): out[:, 38] the iterations, 39 accepted, 40-41 the
    state at rest)."""
    flags = np.full(v0.shape[0], 1 if continued else 0, dtype=np.uint8)
    cont = np.ascontiguousarray
    b = r.b
    args = [b.consts, cont(b.ki[:, 0]), cont(b.ko[:, 0]), _NODE_X, _NODE_W, r.c, r.s, r.geo]
    args += [_limits(), *(cont(a) for a in shaft), limits, cont(v0, dtype=float)]
    v, parts, out = _core.solve_speed(*args, cont(v_static, dtype=float), flags)
    if out[:, 42].any():
        raise MemoryError("the ball dynamics' work space")
    return v, [_state(p, out) for p in parts], out


def _limits() -> np.ndarray:
    """The limits of the core's solve_speed: this module's constants at the call, in its
    order."""
    tolerances = [TOLERANCE, ACCEPT, ROUNDING, NOISE_MAX, BALL_TOLERANCE, _ROUND]
    counts = [LM_TRIALS, HALVINGS, BALL_ITERATIONS, FALLBACK_ITERATIONS, BALL_HALVINGS]
    return np.array(tolerances + counts + [SINGULAR], dtype=float)


def _newton(
    r: Ring,
    f: np.ndarray,
    held: np.ndarray,
    v0: np.ndarray,
    v_static: np.ndarray,
    continued: bool,
) -> tuple[np.ndarray, BallState, np.ndarray]:
    """Every case of the bearings ``r`` under ``f`` (n, 5) [N], ``held`` (n, 5) by the core: the
    ring Newton from v0, the balls on their lines; where left unbalanced and ``continued``, the
    continuation in speed from v_static. Returns (v, state, iterations (n,))."""
    n = v0.shape[0]
    maps = np.zeros((n, 1, 5, 5))
    maps[:, 0] = _EYE
    one = (maps, np.zeros((n, 1, 5)), f, held.view(np.uint8))
    limits = np.array([RING_ITERATIONS, CONTINUATION_STAGES, 0, 0], dtype=float)
    v, parts, out = core_solve(r, one, limits, v0, v_static, continued)
    return v, parts[0], out[:, 38].astype(int)


_EYE = np.eye(5)
_STATE_ARRAYS = tuple(f.name for f in dataclasses.fields(BallState) if f.name != "terms")


def _take_state(st: BallState, idx: np.ndarray) -> BallState:
    out = {name: getattr(st, name)[idx] for name in _STATE_ARRAYS}
    return BallState(terms=tuple(t[idx] for t in st.terms), **out)


def _put_state(st: BallState, rows: np.ndarray, new: BallState) -> None:
    for name in _STATE_ARRAYS:
        getattr(st, name)[rows] = getattr(new, name)
    for mine, theirs in zip(st.terms, new.terms, strict=True):
        mine[rows] = theirs


def _solve(
    z: int, geo: Any, flat: dict, pos: dict, material: tuple[np.ndarray, ...],
    one_sided: np.ndarray, imposed_tilt: bool,
) -> tuple[Any, ...]:  # fmt: skip
    """Set up the ring problem at the static answer and solve it in the core: from the static
    answer; a case left unbalanced again from the shifted start (:func:`_dynamic_start`), then
    by the continuation in speed."""
    n = geo.D_w.shape[0]
    c, s, mirror = _combined.ball_directions(z, np.mod(flat["cage_angle"], 360.0))
    fr, fa, mm, mc = (flat[k] for k in ("radial_load", "axial_load", "moment", "moment_cross"))
    rr = geo.R_i
    t_imp = rr * np.deg2rad(flat["misalignment"]) if imposed_tilt else np.zeros(n)
    held, fixed = _combined.symmetry_locks(z, mirror, (fr, fa, mm, mc), t_imp, imposed_tilt)
    f_ref = _combined.reference_force(fr, fa, mm, mc, rr)
    f = np.zeros((n, 5))
    f[:, 0], f[:, 2], f[:, 3], f[:, 4] = fr, fa, mm / rr, mc / rr
    shift = np.where(one_sided, geo.A * np.sin(geo.alpha0), 0.0)
    v_static = np.stack([pos["x"], pos["y"], pos["axial"] + shift, rr * np.deg2rad(pos["tilt"]),
                         rr * np.deg2rad(pos["tilt_cross"])], axis=1)  # fmt: skip
    # x, y and the tilts a symmetry holds are 0 exactly at speed (the static answer's can be
    # 1e-14 mm: a y of 3e-14 moved an ill-conditioned mirror pair's inner loads 4e-9 N apart,
    # an unbalance across the load line the held y never sees); at speed 0 the static answer
    zero = held & ~fixed & (flat["speed"] > 0)[:, None]
    zero[:, 2] = False
    v_static[zero] = 0.0
    b = ball_set(geo, material[0], material[1], flat["speed"], material[2])
    bearings = ring(b, (c, s), geo, f_ref, one_sided)
    v, st, total = _newton(bearings, f, held, v_static, v_static, False)
    bad = np.flatnonzero(~st.accepted)
    if bad.size:
        start = pos["shifted"](bad)
        v2 = np.stack([start["x"], start["y"], start["u"], rr * np.deg2rad(start["tilt"]),
                       rr * np.deg2rad(start["tilt_cross"])], axis=1)[bad]  # fmt: skip
        v2 = np.where(zero[bad], 0.0, v2)
        v2, st2, its2 = _newton(bearings.take(bad), f[bad], held[bad], v2, v_static[bad], True)
        total[bad] += its2
        won = np.flatnonzero(st2.accepted)
        v[bad[won]] = v2[won]
        _put_state(st, bad[won], _take_state(st2, won))
    cage = (z, np.mod(flat["cage_angle"], 360.0))
    _carry_small_loads(bearings, cage, f, held, (v, st, total, v_static))
    free = undetermined(st.jac, held)
    for i in np.flatnonzero(~st.accepted | free).tolist():  # near a symmetric cage
        near = _off_symmetry(bearings, i, cage, f[i : i + 1], held[i : i + 1], v[i : i + 1])
        if near is None:
            continue
        total[i] += near[2]
        if near[1].accepted[0] and not (
            st.accepted[i] and undetermined(near[1].jac, held[i : i + 1])[0]
        ):
            v[i] = near[0][0]  # (a y left in its range either way: the first answer kept)
            _put_state(st, np.array([i]), near[1])
    _check_resolved(st, bearings, flat, pos["refused"])
    check_balanced("ball-dynamics ring and ball equilibrium", st, total, flat)
    return bearings, v, st, total, undetermined(st.jac, held)


def _carry_small_loads(
    r: Ring, cage: tuple[int, np.ndarray], f: np.ndarray, held: np.ndarray, out: tuple
) -> None:
    """A case left above TOLERANCE with a free applied component unbalanced by more than
    CARRIED of itself, solved again by continuation in that component from SMALL_LOAD of the
    largest applied load down to it, a decade a stage (the first by :func:`_alone`, each next
    from the last position); taken where every stage is accepted and the residual is lower
    (docs/speed.md, "Numerics"). ``out`` = (v, state, iterations, v_static), in place."""
    v, st, total, v_static = out
    res = np.where(held, 0.0, np.abs(f - st.gen))
    small = ~held & (f != 0.0) & (res > CARRIED * np.abs(f))
    rows = np.flatnonzero((st.merit > TOLERANCE) & small.any(axis=1))
    for i in rows:
        one = r.take(np.array([i]))
        decades = _decades(SMALL_LOAD * float(r.f_ref[i]), float(np.abs(f[i, small[i]]).min()))
        stage = np.where(small[i], _times_decades(f[i], decades), f[i])[None, :]
        pos, got, its = _alone(r, int(i), cage, stage, held[i : i + 1], v_static[i : i + 1])
        for k in range(decades - 1, -1, -1):
            if not got.accepted[0]:
                break
            stage = np.where(small[i], _times_decades(f[i], k), f[i])[None, :]
            pos, got, n = _newton(one, stage, held[i : i + 1], pos, pos, False)
            its += int(n[0])
        total[i] += its
        if got.accepted[0] and got.merit[0] < st.merit[i]:
            v[i] = pos[0]
            _put_state(st, np.array([i]), got)


def _decades(top: float, low: float) -> int:
    """The decades (>= 0) from a load ``low`` > 0 up to ``top``: a subnormal ``low`` (a thrust
    of 1e-320 N) too, whose quotient overflows."""
    ratio = top / low
    if math.isinf(ratio):
        return max(math.ceil(math.log10(top) - math.log10(low)), 0)
    return max(math.ceil(math.log10(ratio)), 0)


def _times_decades(x: np.ndarray, k: int) -> np.ndarray:
    """``x * 10**k``, where 10**k is beyond a double (k > 308) too (a subnormal ``x``)."""
    if k <= 300:
        return x * 10.0**k
    return x * 10.0 ** (k - 300) * 1e300


def _alone(
    r: Ring, i: int, cage: tuple, f: np.ndarray, held: np.ndarray, start: np.ndarray
) -> tuple[np.ndarray, BallState, int]:
    """Case ``i`` of the bearings ``r`` under ``f`` (1, 5) as a case of its own: the Newton
    from ``start`` (1, 5), where left unbalanced the continuation in speed from it, and where
    still unbalanced (:func:`_off_symmetry`) the continuation in the cage's offset from
    symmetry. Returns (v, state, iterations)."""
    pos, got, n = _newton(r.take(np.array([i])), f, held, start, start, True)
    near = None if got.accepted[0] else _off_symmetry(r, i, cage, f, held, start)
    if near is None or not near[1].accepted[0]:
        return pos, got, int(n[0]) + (0 if near is None else near[2])
    return near[0], near[1], int(n[0]) + near[2]


def _off_symmetry(
    r: Ring, i: int, cage: tuple, f: np.ndarray, held: np.ndarray, start: np.ndarray
) -> tuple[np.ndarray, BallState, int] | None:
    """Case ``i`` of the bearings ``r`` under ``f`` (1, 5) with the cage (``cage``: z and
    every case's angle [°]) less than OFF_SYMMETRY off a symmetric angle, by continuation in
    that offset (docs/speed.md, "Numerics"): from the offset a whole number of decades up, just
    under OFF_SYMMETRY (from ``start`` (1, 5)), a decade down each stage from the last position,
    until a stage is not accepted. Returns (v, state, iterations), or None where the cage is
    not so near."""
    z, angle = cage[0], float(cage[1][i])
    sym = round(angle * z / 180.0) * 180.0 / z
    offset = angle - sym
    if offset == 0.0 or abs(offset) >= OFF_SYMMETRY:
        return None
    one = r.take(np.array([i]))
    decades = math.floor(math.log10(OFF_SYMMETRY / abs(offset)))
    pos, its = start.copy(), 0
    for k in range(decades, -1, -1):
        c, s, _ = _combined.ball_directions(z, np.array([sym + offset * 10.0**k]))
        stage = Ring(one.b, c, s, one.geo) if k else one  # the last: the cage given
        pos, got, n = _newton(stage, f, held, pos, pos, k == decades)
        its += int(n[0])
        if not got.accepted[0]:
            break
    return pos, got, its


def undetermined(jac: np.ndarray, held: np.ndarray) -> np.ndarray:
    """(n,) bool: a direction of the ring not ``held`` (n, 5) whose stiffness, the diagonal of
    the tangent ``jac`` (n, 5, 5) in consistent units, is at most SINGULAR of its largest."""
    k = np.abs(np.diagonal(jac, axis1=1, axis2=2))
    top = k.max(axis=1, initial=0.0)[:, None]
    return np.any(~held.astype(bool) & (k <= SINGULAR * top) & (top > 0), axis=1)


def _check_resolved(st: BallState, ring: Ring, flat: dict, refused: Any) -> None:
    """InputError where the rounding level of the ring forces at the end is above LEVEL_MAX of
    the largest applied load (a load tiny against a preload or the balls' centrifugal forces:
    the double cannot balance it to the digits given). The smallest load accepted: the level
    grows at most as the load^(1/3) (the contact stiffness; constant under a preload), so
    ``F (level/LEVEL_MAX)^1.5`` is resolved. Not at speed 0: there the static solver (in
    double-double) has answered, and refused what it does not resolve. ``refused(i, load)``:
    the input and element that name case ``i`` (:func:`refused_case`)."""
    level = np.where(np.isfinite(st.level) & (flat["speed"] > 0), st.level, 0.0)
    bad = np.flatnonzero(level > LEVEL_MAX)
    if bad.size == 0:
        return
    i = int(bad[np.argmax(level[bad])])
    f_min = float(ring.f_ref[i] * (level[i] / LEVEL_MAX) ** 1.5)
    f_min = float(f"{f_min * 1.05:.2g}")  # two digits, rounded up
    parameter, element = refused(i, "radial_load")
    raise InputError(
        parameter,
        f"the loads are too small against the ball forces at this speed for the ball dynamics "
        f"(the largest of F_r, |F_a| and M/R_i is {float(ring.f_ref[i]):.3g} N; the rounding of "
        f"the ball forces on the ring is {level[i] * float(ring.f_ref[i]):.2g} N, more than "
        f"{LEVEL_MAX:.0e} of it; it takes at least {f_min:.2g} N at speed "
        f"{float(flat['speed'][i]):.6g} rpm and clearance {float(flat['clearance'][i]):.6g} mm "
        f"for this bearing)",
        way_out=_combined.RADIAL_TAKES_ANY_LOAD,
        reason=_combined.TOO_LIGHT,
        element=element,
    )


def refused_case(
    given: dict[str, tuple[Any, str]], shape: tuple[int, ...], i: int, parameter: str
) -> tuple[str, str]:
    """The input that names the refused case ``i`` (flat, of the cases of ``shape``) and its
    element: the speed, by its own element (``speed[1] = 3000 rpm``), where the speeds differ
    over the cases (an array of mixed speeds: the speed tells the case apart); else
    ``parameter``, by its own element where it is an array (:func:`bearingload.validate.
    element_at`). ``given``: name -> (the input as given, its unit)."""
    bad = np.zeros(int(np.prod(shape)), dtype=bool)
    bad[i] = True
    speed, unit = given["speed"]
    if np.size(speed) > 1 and np.ptp(speed) > 0:
        return "speed", validate.element_at(speed, bad, shape, unit)
    value, unit = given[parameter]
    return parameter, validate.element_at(value, bad, shape, unit)


def _with_speed(exc: ConvergenceError, n_rpm: np.ndarray, inputs: tuple) -> ConvergenceError:
    """The failure of the static start (the cases at rest, from which the ball dynamics start)
    naming the speed of its cases too: the one speed where every case has it (one case:
    solve's, a batch row's), else the speed of each failing case, by the failure's ``rows``
    among the cases of the static call's ``inputs`` broadcast together."""
    if n_rpm.size == 0:
        return exc
    speed: Any = float(n_rpm.flat[0])
    if np.any(n_rpm != speed):
        if exc.rows is None:
            return exc
        shape = np.broadcast_shapes(*(np.shape(v) for v in inputs if v is not None))
        speed = np.broadcast_to(n_rpm, shape).reshape(-1)[exc.rows]
    cases = exc.cases | {"speed": speed}
    units = (exc.units or {}) | {"speed": _combined.INPUT_UNITS["speed"]}
    return ConvergenceError(
        exc.solver, exc.iterations, exc.residual, cases, units, exc.way_out, rows=exc.rows
    )


def check_balanced(solver: str, st: BallState, its: np.ndarray, cases: dict) -> None:
    """ConvergenceError of ``solver`` naming the inputs (``cases``: name -> (n,)) of the cases
    ``st`` leaves unbalanced, ``its`` their iterations (a bearing's, or a pair's shaft)."""
    bad = ~st.accepted
    if np.any(bad):
        known = st.merit[bad][np.isfinite(st.merit[bad])]
        raise ConvergenceError(
            solver,
            int(its[bad].max()),
            float(known.max()) if known.size else math.nan,
            {k: v[bad] for k, v in cases.items()},
            units=_combined.INPUT_UNITS,
            rows=np.flatnonzero(bad),
        )


#: The fields of the static answer the answer at speed replaces.
_MOVED = set("x y axial tilt tilt_cross moment contact_angles ball_loads".split())
_MOVED |= set("ball_stiffnesses ball_approaches stiffness_matrix iterations".split())
_KEPT = tuple(f.name for f in dataclasses.fields(CombinedDistribution) if f.name not in _MOVED)


def _kept(value: Any) -> Any:
    """A field of the static answer in the answer at speed: its own copy of an array, a Python
    scalar for one case (the flags bools, the counts integers)."""
    if isinstance(value, (np.ndarray, np.generic)):
        return value.item() if value.ndim == 0 else value.copy()
    return value


def bearing_result(
    static: CombinedDistribution, shape: tuple[int, ...], z: int, geo: Any, flat: dict,
    density: np.ndarray, out: tuple[Any, ...], one_sided: np.ndarray, misalignment: Any,
    **given: Any,
) -> HighSpeedDistribution:  # fmt: skip
    """The answer at speed of one bearing (n cases of the ``shape``): the static answer's fields
    (or those ``given``) with the dynamic ring position, balls and tangent; ``out`` = (ring, v,
    state, iterations, undetermined (n,) bool) of the core's solve, ``flat`` the cases' ``speed`` and ``moment`` (n,)."""
    ring, v, st, its, loose = out
    g1, g2, qi, qo, si, ci, fc, mg, wc, wr, beta, di = st.terms[:12]
    rr = geo.R_i

    def case(a: Any) -> Any:
        return a.item() if not shape else a.reshape(shape)

    def ball(a: Any) -> np.ndarray:
        return a.reshape(shape + (z,))

    ai = np.rad2deg(np.arctan2(si, ci))
    lever = np.ones((rr.shape[0], 5))
    lever[:, 3] = lever[:, 4] = rr
    tangent = st.jac * lever[:, :, None] * lever[:, None, :]
    shift = np.where(one_sided, geo.A * np.sin(geo.alpha0), 0.0)
    moment = rr * st.gen[:, 3] if misalignment is not None else flat["moment"]
    offset = ring.b.consts[:, 1:2] + st.do  # r'_o + delta_o
    cos_o, sin_o = np.cos(st.ao), np.sin(st.ao)
    fields = {name: _kept(getattr(static, name)) for name in _KEPT} | given
    fields.update(x=case(v[:, 0]), y=case(v[:, 1]), axial=case(v[:, 2] - shift))
    fields.update(tilt=case(np.rad2deg(v[:, 3] / rr)), tilt_cross=case(np.rad2deg(v[:, 4] / rr)))
    fields.update(moment=case(moment), contact_angles=ball(ai), ball_loads=ball(qi))
    fields.update(ball_stiffnesses=ball(stiffness(ring.b.ki, ci)), ball_approaches=ball(di + st.do))
    fields.update(stiffness_matrix=tangent.reshape(shape + (5, 5)))
    fields.update(iterations=case(np.ravel(static.iterations) + its), speed=case(flat["speed"]))
    fields.update(ball_density=_kept(np.broadcast_to(density, shape)))
    fields.update(contact_angles_inner=ball(ai), contact_angles_outer=ball(np.rad2deg(st.ao)))
    fields.update(ball_loads_inner=ball(qi), ball_loads_outer=ball(qo))
    fields.update(ball_stiffnesses_outer=ball(stiffness(ring.b.ko, cos_o)))
    fields.update(approaches_inner=ball(di), approaches_outer=ball(st.do))
    fields.update(ball_offsets_axial=ball(offset * sin_o), ball_offsets_radial=ball(offset * cos_o))
    fields.update(
        orbit_speeds=ball(wc), spin_speeds=ball(wr), attitude_angles=ball(np.rad2deg(beta))
    )
    fields.update(centrifugal_forces=ball(fc), gyroscopic_moments=ball(mg))
    fields.update(displacement_undetermined=case(loose))
    return HighSpeedDistribution(**fields)
