"""Ball dynamics at speed: centrifugal force and gyroscopic moment of every ball, outer-raceway
control (Jones 1960; Harris & Kotzalas, *Rolling Bearing Analysis*, 5th ed., vol. 2 "Advanced
Concepts of Bearing Technology", ch. 2 "Bearing component motions and speeds" and ch. 3 "High-speed
operation: ball and roller dynamics").

Units: N, mm, kg, s (the shaft speed in rpm at the input, rad/s inside); ball density in kg/mm^3
(bearing steel 7.85e-6; silicon nitride 3.2e-6).

Model (one ball ``j`` at ``phi_j``; the geometry, loads and conventions of
:func:`bearingload.models.combined.solve_combined`, whose static answer is the start):

* The outer groove curvature centre is fixed; the inner one lies ``rho_j`` radially outward and
  ``u_j`` axially from it (``rho_j = A - G_r/2 + x cos phi_j + y sin phi_j``, ``u_j = a +
  R_i (theta cos phi_j + theta_c sin phi_j)``; one-sided angular contact: ``u'_j = max(u_j, 0)``,
  as in the static model). The ball centre is no longer on the line joining them: it lies at
  ``(X_1, X_2) = (r'_o + delta_o)(sin alpha_o, cos alpha_o)`` (axial, radial) from the outer
  centre, ``r'_o = (f_o - 1/2) D_w``; the unknowns of each ball are ``delta_o`` and
  ``alpha_o``. The inner contact follows: ``(u' - X_1, max(rho - X_2, 0)) = (r'_i +
  delta_i)(sin alpha_i, cos alpha_i)``. ``Q_i = K_i max(delta_i, 0)^1.5``, ``Q_o = K_o
  max(delta_o, 0)^1.5``. The inner raceway is the half of the inner groove facing the balls
  (``cos alpha_i >= 0``; the static model's ``max(rho, 0)``): a ball whose centre lies radially
  outward of its inner groove centre touches the groove's side at most (at 90°), never the
  far side of the groove circle, where the ring has no surface.
* A ball without inner contact (loose) rests on the outer raceway: ``alpha_o = 0`` (then beta
  = 0, no gyroscopic friction) and ``Q_o = F_c``.
* Kinematics, outer-raceway control (Jones; Harris & Kotzalas vol. 2, ch. 2): the ball rolls
  without spinning on the outer raceway; with ``gamma = D_w/d_m`` and the inner ring at
  ``omega`` (outer ring still) the attitude angle is ``tan beta = sin alpha_o / (cos alpha_o +
  gamma)`` and, with ``c_o = (cos alpha_o + tan beta sin alpha_o)/(1 + gamma cos alpha_o)`` and
  ``c_i = (cos alpha_i + tan beta sin alpha_i)/(1 - gamma cos alpha_i)``, the orbit (cage) speed
  ``omega_c = omega c_o/(c_o + c_i)`` and the ball's spin ``omega_R = omega/(gamma cos beta
  (c_o + c_i))``. (Both contacts at alpha: ``omega_c = omega (1 - gamma cos alpha)/2``, the
  rolling speeds.) Each ball's speeds follow its own two contact angles.
* Forces on the ball (Harris & Kotzalas vol. 2, ch. 3, with lambda_o = 2, lambda_i = 0): the
  centrifugal force ``F_c = m d_m omega_c^2 / 2`` outward; the gyroscopic moment ``M_g = J
  omega_R omega_c sin beta``, ``J = m D_w^2/10``, held by friction at the outer contact only,
  a force ``2 M_g / D_w`` along the outer raceway. Equilibrium, axial and radial::

      Q_i sin a_i - Q_o sin a_o + (2 M_g/D_w) cos a_o = 0
      Q_i cos a_i - Q_o cos a_o - (2 M_g/D_w) sin a_o + F_c = 0

* The inner ring sees the inner contacts only (lambda_i = 0): ``F_a = sum Q_i sin a_i``,
  ``F_r`` along ``x``: ``sum Q_i cos a_i cos phi_j``, the moments with the lever ``R_i``, as in
  the static model.
* Hertz: ``K_i`` and ``K_o`` of each ball are the exact Hertz stiffnesses of its inner and outer
  contact at its own angle (:func:`bearingload.contact.hertz.ball_stiffness` at the pitch
  diameter ``d_m / cos alpha``, the static model's curvature rule), a Chebyshev interpolant in
  ``cos alpha`` (24 nodes, once per geometry) inside the equations; at speed 0 (alpha_i =
  alpha_o) their series value is the static model's ``K(alpha)``.
* Not modelled: ring expansion, cage and lubricant forces, the inner contact's friction; the
  ring rotating is the inner one.

Numerics. A first stage takes Newton steps on the ring and every ball together (the balls'
2x2 blocks eliminated, :func:`_coupled`); a case it brings near balance goes on from there to
the nested solver below, which decides (the others start it from the static answer). For given
ring positions each ball's two equations are solved by Newton on its centre
(X_1, X_2), all balls of all cases at once (each until it is balanced), from the ball's last
position moved to first order with the ring (its sensitivity), with the Jacobians
analytic (the compiled ball evaluator, :mod:`bearingload.models._core`); a ball left unbalanced is solved alone from its
loose state (:mod:`bearingload.models._ball_dynamics`). The ring equilibrium: Newton on ``(x,
y, a, R_i theta, R_i theta_c)`` from the static answer (a case left unbalanced: again from the
static answer of the bearing whose balls are pushed out by their centrifugal approach), the
tangent of the ball forces by the implicit function theorem
(the ball equations eliminated per ball); the step halved, then Levenberg-Marquardt steps (a
nearly singular tangent), none longer than A/10 or to a position where no ball touches the
inner ring. A case left unbalanced is solved again by continuation in omega^2 from the static
answer. The components
the static model holds by symmetry are held (the speed terms keep those symmetries: ``M_g`` is
odd in ``alpha_o``). A case stops when each applied component is balanced to ``TOLERANCE`` of
the largest applied load and every ball to ``BALL_TOLERANCE`` of its forces, or when no step
lowers the residual; it is accepted when each component is balanced to ``ACCEPT`` of the largest
applied load or to the rounding level of its terms (:func:`_rounding`: a light load against a
preload or the balls' centrifugal forces, as the static model measures a load against the
rounding of its terms) or, up to ``NOISE_MAX`` of that load, to the change of the ring forces over
the balls' own residuals (each ball balanced to ``BALL_TOLERANCE`` of its forces); otherwise :class:`~bearingload.errors.ConvergenceError` names its
inputs. A load whose rounding level is above ``LEVEL_MAX`` of it is refused
(:class:`~bearingload.errors.InputError`, naming the smallest load accepted). At speed 0 the answer is the static one (no step is taken from it).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from bearingload import validate
from bearingload.constants import STEEL_MODULUS
from bearingload.errors import ConvergenceError, InputError
from bearingload.models import combined as _combined
from bearingload.models._ball_dynamics import (
    BALL_TOLERANCE,
    _ball_norm,
    _line_start,
    _Set,
    _stiffness,
    ball_partials,
    solve_balls,
    static_partials,
)
from bearingload.models.combined import CombinedDistribution

__all__ = ["HighSpeedDistribution", "solve_high_speed", "STEEL_DENSITY", "MAX_SPEED_PITCH",
           "MODEL"]  # fmt: skip

#: Bearing steel (100Cr6) density. [kg/mm^3]
STEEL_DENSITY = 7.85e-6
#: Largest n d_m accepted (n the shaft speed [rpm], d_m [mm]). [mm/min]
MAX_SPEED_PITCH = 2.0e6
#: The words of the refusal of a speed beyond :data:`MAX_SPEED_PITCH` (the command line adds
#: its way to the static model after them: :func:`too_fast`).
TOO_FAST = "mm/min for the ball-dynamics model"


def too_fast(exc: BaseException) -> bool:
    """Whether ``exc`` is the refusal of a speed beyond :data:`MAX_SPEED_PITCH`."""
    return isinstance(exc, InputError) and exc.parameter == "speed" and TOO_FAST in str(exc)


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
#: Largest rounding level of the ring forces (:func:`_rounding`) over the largest applied load
#: solved; above it the load is refused (the answer balances it to about a tenth of that). [-]
LEVEL_MAX = 1e-5
#: Largest ring residual accepted, over the largest applied load, where the balls' own residuals
#: (each balanced to BALL_TOLERANCE of its forces) move the ring forces more than ACCEPT of it:
#: a light load against the balls' centrifugal forces (a tenth of LEVEL_MAX). [-]
NOISE_MAX = 1e-6
#: Ring Newton steps; trial steps of each: the Newton step halved HALVINGS times, then
#: Levenberg-Marquardt steps. [-]
RING_ITERATIONS = 200
LM_TRIALS = 12
HALVINGS = 6
#: The coupled first stage (:func:`_coupled`): steps at most; trials of a step (the step and
#: its halvings); halved steps after which a case stops; steps after which a case whose
#: combined residual has not halved over the last three stops. A case it leaves within
#: FAST_HAND_ON (ring, of the largest applied load; each ball, of its forces) goes on from its
#: answer, the others from the static answer as before. [-]
FAST_ITERATIONS = 12
FAST_HALVINGS = 3
FAST_DAMPED = 3
FAST_SLOW = 3
FAST_HAND_ON = 1e-6
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
        [kg/mm^3]
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
    model: str = MODEL


def _ring_forces(
    b: _Set, rho: np.ndarray, u: np.ndarray, do: np.ndarray, ao: np.ndarray, one_sided: np.ndarray
) -> tuple[Any, ...]:
    """The ball forces on the ring (axial, radial) (n, z), their total derivatives by (rho, u)
    with the ball equations eliminated: ((dFa/drho, dFa/du), (dFr/drho, dFr/du)), the terms,
    each ball's (rho, u', d(do, ao)/drho, d(do, ao)/du') (n, z, 6), and the largest change of
    its (Fa, Fr) per unit residual of its equations, ``|dF/dX (dg/dX)^-1|`` (2, n, z) (0 at
    speed 0: no ball equations). [-]"""
    up = np.where(one_sided[:, None], np.maximum(u, 0.0), u)
    dup = np.where(one_sided[:, None], (u > 0).astype(float), 1.0)
    t0, d = ball_partials(b, rho, up, do, ao)  # rows: g1, g2, Fa, Fr; columns: do, ao, rho, u
    moving = np.broadcast_to(b.omega > 0, do.shape)
    det = d[0][0] * d[1][1] - d[0][1] * d[1][0]
    with np.errstate(all="ignore"):
        inv = np.stack([[d[1][1], -d[0][1]], [-d[1][0], d[0][0]]]) / det
    out = np.zeros((2, 2) + do.shape)
    # the ball's own sensitivity dX/dp = -(dg/dX)^-1 dg/dp (the next ring position's start)
    sens = np.zeros(do.shape + (6,))
    sens[..., 0], sens[..., 1] = rho, up
    for c in (2, 3):
        for k in range(2):
            sens[..., 2 * c - 2 + k] = -(inv[k, 0] * d[0][c] + inv[k, 1] * d[1][c])
    sens = np.where(np.isfinite(sens), sens, 0.0)
    for r in (2, 3):
        for c, chain in ((2, 1.0), (3, dup)):
            # dF/dp - dF/dX (dg/dX)^-1 dg/dp
            dxp = [inv[k, 0] * d[0][c] + inv[k, 1] * d[1][c] for k in range(2)]
            total = d[r][c] - (d[r][0] * dxp[0] + d[r][1] * dxp[1])
            if moving.all():
                out[r - 2, c - 2] = total * chain
            else:
                static = _static_derivative(b, rho, up, r, c)
                out[r - 2, c - 2] = np.where(moving, total, static) * chain
    with np.errstate(all="ignore"):
        gain = np.stack([np.abs(d[r][0] * inv[0, 0] + d[r][1] * inv[1, 0])
                         + np.abs(d[r][0] * inv[0, 1] + d[r][1] * inv[1, 1])
                         for r in (2, 3)])  # fmt: skip
    gain = np.where(moving & np.isfinite(gain), gain, 0.0)
    return t0[12], t0[13], out, t0, sens, gain


def _static_derivative(b: _Set, rho: np.ndarray, up: np.ndarray, r: int, c: int) -> np.ndarray:
    """d(F_a or F_r)/d(rho or u) of a ball at speed 0 (on its line, K in series)."""
    return static_partials(b, rho, up)[2 + 2 * (r - 2) + (c - 2)]


def _stiffness_nodes(geo: Any, e: np.ndarray, nu: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """K_i and K_o of every case at the Chebyshev nodes of cos(alpha) (n, 1, NODES): exact
    Hertz (:func:`bearingload.contact.hertz.ball_stiffness` at the pitch diameter
    d_m / cos alpha, the static model's curvature rule), once per distinct geometry (cached,
    the cache changes no bit). [N/mm^1.5]"""
    from bearingload.contact.hertz import ball_stiffness

    params = np.stack([geo.D_w, geo.d_m, geo.f_i, geo.f_o, e, nu], axis=1)
    rows_i, rows_o = [], []
    for key in map(tuple, params.tolist()):
        if key not in _NODE_CACHE:
            dw, dm, fi, fo, ee, nn = key
            k = ball_stiffness(dw, dm / _NODE_COS, fi, fo, ee, nn)
            _NODE_CACHE[key] = (np.asarray(k.inner, float), np.asarray(k.outer, float))
            while len(_NODE_CACHE) > _combined.SETUP_CACHE_SIZE:
                _NODE_CACHE.pop(next(iter(_NODE_CACHE)))
        k_i, k_o = _NODE_CACHE[key]
        rows_i.append(k_i)
        rows_o.append(k_o)
    return np.stack(rows_i)[:, None, :], np.stack(rows_o)[:, None, :]


_NODE_COS = _combined._NODE_COS
_NODE_CACHE: dict[tuple[float, ...], tuple[np.ndarray, np.ndarray]] = {}


def _check_speed(speed: Any, density: Any, dm: Any) -> tuple[np.ndarray, np.ndarray]:
    n = validate.finite("speed", speed)
    if np.any(n < 0):
        raise InputError("speed", "must be >= 0 rpm (the inner ring's speed)")
    rho = validate.positive("ball_density", density, "kg/mm^3")
    if np.any(rho > 1e-4):
        raise InputError(
            "ball_density", "must be in kg/mm^3 (steel 7.85e-6, silicon nitride 3.2e-6), below 1e-4"
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
    gyroscopic moment (outer-raceway control); see the module docstring.

    Parameters as :func:`bearingload.models.combined.solve_combined` (a constant ``stiffness``
    is not taken: the two contacts need their own Hertz stiffness), and

    speed : array_like
        Shaft speed n of the inner ring, >= 0, n d_m <= :data:`MAX_SPEED_PITCH`. [rpm]
    ball_density : array_like, default :data:`STEEL_DENSITY`
        Density of the balls. [kg/mm^3]

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
    n_rpm, density = _check_speed(speed, ball_density, pitch_diameter)
    validate.broadcast_shape({"radial_load": radial_load, "speed": n_rpm,
                              "ball_density": density})  # fmt: skip
    wide = np.broadcast_shapes(np.shape(radial_load), n_rpm.shape, density.shape)
    if wide != np.shape(radial_load):
        radial_load = np.broadcast_to(np.asarray(radial_load, dtype=float), wide)
    static = _combined.solve_combined(
        balls, radial_load, axial_load, ball_diameter=ball_diameter,
        pitch_diameter=pitch_diameter, f_i=f_i, f_o=f_o, clearance=clearance,
        cage_angle=cage_angle, moment=moment, misalignment=misalignment, modulus=modulus,
        poisson=poisson, tilt_radius=tilt_radius, moment_cross=moment_cross,
        contact_angle=contact_angle,
    )  # fmt: skip
    shape = np.shape(static.x)
    z = static.balls
    given = {"balls": z, "radial_load": radial_load, "axial_load": axial_load,
             "moment": 0.0 if moment is None else moment, "moment_cross": moment_cross,
             "clearance": clearance, "cage_angle": cage_angle, "speed": n_rpm}  # fmt: skip
    if misalignment is not None:
        given["misalignment"] = misalignment
    flat = {k: np.broadcast_to(np.asarray(v, dtype=float), shape).ravel()
            for k, v in given.items() if k != "balls"}  # fmt: skip
    case_arrays: dict[str, Any] = {
        name: np.broadcast_to(np.asarray(getattr(static, name), dtype=float), shape).ravel()
        for name in ("x", "y", "axial", "tilt", "tilt_cross", "tilt_radius")
    }
    angles = np.broadcast_to(static.contact_angles, shape + (z,)).reshape(-1, z)
    d = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (ball_diameter, pitch_diameter, f_i, f_o,
                                               modulus, poisson, density)),
        np.zeros(()) if contact_angle is None else np.asarray(contact_angle, dtype=float),
        np.zeros(shape),
    )  # fmt: skip
    dw, dm, fi, fo, e, nu, rho_b, alpha_d = (np.broadcast_to(a, shape).ravel() for a in d[:8])
    geo = (_combined._geometry(dw, dm, fi, fo, flat["clearance"]) if contact_angle is None
           else _combined._angular_geometry(dw, dm, fi, fo, alpha_d))  # fmt: skip
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
    with np.errstate(all="ignore"):
        out = _solve(z, geo, flat, case_arrays, angles, (e, nu, rho_b), one_sided,
                     misalignment is not None)  # fmt: skip
    return _result(static, shape, z, geo, flat, density, out, one_sided, misalignment)


def _dynamic_start(
    z: int, geo: Any, flat: dict, pos: dict, material: tuple[np.ndarray, ...], static_kw: dict,
    contact_angle: Any, rows: np.ndarray,
) -> dict[str, np.ndarray]:  # fmt: skip
    """The second start of the ring Newton (cases ``rows`` the static start leaves
    unbalanced; light loads at speed): the static answer of the bearing whose balls are pushed
    out by their rigid-rolling centrifugal force (ring position, tilts [°]; ``u`` the axial
    offset of the groove centres [mm]). A ball at speed sits ``delta_c = (F_c/K_o)^(2/3)``
    further out in its outer groove; for the inner ring this is the inner groove centre moved
    in by delta_c: a clearance larger by 2 delta_c (deep groove), ``cos alpha_0`` smaller by
    delta_c/A (angular contact). Cases at speed 0, or whose shifted bearing the static model
    refuses, keep the static answer. [mm]"""
    shift = np.where(contact_angle is not None, geo.A * np.sin(geo.alpha0), 0.0)
    out = {name: pos[name].copy() for name in ("x", "y", "tilt", "tilt_cross")}
    out["u"] = pos["axial"] + shift
    moving = rows[flat["speed"][rows] > 0]
    if moving.size == 0:
        return out
    ki, ko = _stiffness_nodes(geo, *material[:2])
    cos0 = np.cos(geo.alpha0)
    omega = flat["speed"] * math.pi / 30.0
    mass = material[2] * math.pi / 6.0 * geo.D_w**3
    wc = 0.5 * omega * (1.0 - geo.D_w / geo.d_m * cos0)
    fc = 0.5 * mass * geo.d_m * wc * wc * _KG_MM
    delta_c = (fc / _stiffness(ko, cos0[:, None])[:, 0]) ** (2.0 / 3.0)
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
class _Ring:
    """The ring problem of n cases (physical units; tilts as R_i theta [mm])."""

    b: _Set
    c: np.ndarray  # cos phi_j (n, z)
    s: np.ndarray
    base: np.ndarray  # A - G_r/2 (n,)
    f: np.ndarray  # applied generalised forces (n, 5) [N]
    f_ref: np.ndarray  # (n,) [N]
    held: np.ndarray  # (n, 5) bool
    one_sided: np.ndarray  # (n,) bool
    length: np.ndarray  # A = (f_i + f_o - 1) D_w (n,) [mm]

    def take(self, idx: np.ndarray) -> _Ring:
        if np.array_equal(idx, np.arange(self.f.shape[0])):
            return self  # every case in order (one case alone, always): the same arrays, read only
        out = {f.name: getattr(self, f.name) for f in dataclasses.fields(self)}
        return _Ring(out.pop("b").take(idx), **{k: v[idx] for k, v in out.items()})


@dataclass
class _State:
    """Every ball and the ring's forces at a position v (n, 5)."""

    do: np.ndarray
    ao: np.ndarray
    balls_ok: np.ndarray  # (n,) bool
    gen: np.ndarray  # (n, 5) generalised ring forces [N]
    jac: np.ndarray  # (n, 5, 5) d gen / d v
    merit: np.ndarray  # (n,) largest free residual over f_ref (inf: a ball unsolved)
    terms: tuple[np.ndarray, ...]
    sens: np.ndarray  # (n, z, 6) each ball's rho, u', d(do, ao)/drho, d(do, ao)/du'
    score: np.ndarray  # (n,) the residual over f_ref or, where larger, its rounding (or the
    # balls' own residuals on it, up to NOISE_MAX of f_ref) over ACCEPT
    level: np.ndarray  # (n,) the largest rounding level (:func:`_rounding`) over f_ref

    @property
    def accepted(self) -> np.ndarray:
        """(n,) bool: every free component balanced to ACCEPT of the largest applied load or
        to the rounding of its terms and of the ball positions (:func:`_rounding`)."""
        return self.score <= ACCEPT


def _evaluate(
    r: _Ring, v: np.ndarray, do: np.ndarray, ao: np.ndarray, sens: np.ndarray | None = None
) -> _State:
    """Solve every ball at the ring position v from (do, ao) (moved to first order by the
    balls' sensitivities ``sens`` of a previous state); the ring forces and tangent."""
    rho, u, up = _centres(r, v)
    if sens is not None:
        dr, du = rho - sens[..., 0], up - sens[..., 1]
        do = do + sens[..., 2] * dr + sens[..., 4] * du
        ao = ao + sens[..., 3] * dr + sens[..., 5] * du
    moving = np.broadcast_to(r.b.omega > 0, do.shape)
    fresh = ~moving | ~np.isfinite(do)
    if fresh.any():
        line = _line_start(r.b, rho, up)
        do, ao = np.where(fresh, line[0], do), np.where(fresh, line[1], ao)
    # a ball at speed always touches its outer groove: start it pressed by about F_c
    fc = 0.125 * r.b.mass * r.b.dm * r.b.omega**2 * _KG_MM
    ao = np.where(moving & fresh & (do <= 0), 0.0, ao)
    do = np.where(moving, np.maximum(do, (fc / r.b.ko[..., -1]) ** (2.0 / 3.0)), do)
    do, ao, ok = solve_balls(r.b, rho, up, do, ao)
    fa, fr, d, terms, sens, gain = _ring_forces(r.b, rho, u, do, ao, r.one_sided)
    arm_r, arm_a, gen, jac = _assemble(r, fr, fa, d)
    res = np.where(r.held, 0.0, r.f - gen)
    merit = np.abs(res).max(axis=1) / r.f_ref
    floor = _rounding(arm_r, arm_a, fr, fa, d, np.abs(rho) + np.abs(up))
    # each ball's own residual (its equations, balanced to BALL_TOLERANCE of its forces) moves
    # its ring forces by gain: they are known to that only (a light load against the centrifugal
    # forces); accepted up to NOISE_MAX of the load at most
    g = gain * np.hypot(terms[0], terms[1])
    noise = np.abs(arm_a) * g[0][:, None, :] + np.abs(arm_r) * g[1][:, None, :]
    noise = np.minimum(np.where(np.isfinite(noise), noise, 0.0).sum(-1),
                       NOISE_MAX * r.f_ref[:, None])  # fmt: skip
    score = (np.abs(res) / np.maximum(r.f_ref[:, None], np.maximum(floor, noise) / ACCEPT)).max(
        axis=1
    )
    balls_ok = np.asarray(ok.all(axis=1))
    merit = np.where(balls_ok & np.isfinite(merit), merit, np.inf)
    score = np.where(balls_ok & np.isfinite(score), score, np.inf)
    level = floor.max(axis=1) / r.f_ref
    return _State(do, ao, balls_ok, gen, jac, merit, tuple(terms), sens, score, level)


def _centres(r: _Ring, v: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Each ball's inner groove centre from its outer one at the ring position v: radial
    ``rho``, axial ``u`` and ``u'`` (``max(u, 0)`` for angular contact) (n, z). [mm]"""
    c, s = r.c, r.s
    rho = r.base[:, None] + v[:, 0, None] * c + v[:, 1, None] * s
    u = v[:, 2, None] + v[:, 3, None] * c + v[:, 4, None] * s
    up = np.where(r.one_sided[:, None], np.maximum(u, 0.0), u)
    return rho, u, up


def _assemble(
    r: _Ring, fr: np.ndarray, fa: np.ndarray, d: np.ndarray,
    arms: tuple[np.ndarray, np.ndarray] | None = None,
) -> tuple[np.ndarray, ...]:  # fmt: skip
    """The arms of the balls' radial and axial forces (n, 5, z) (``arms``, if at hand: those of
    :func:`_arms`), the generalised ring forces (n, 5) [N] and their tangent (n, 5, 5) [N/mm]
    from the balls' forces (n, z) and their total derivatives ``d`` (:func:`_ring_forces`)."""
    arm_r, arm_a = _arms(r) if arms is None else arms  # (n, 5, z)
    gen = (arm_r * fr[:, None, :] + arm_a * fa[:, None, :]).sum(-1)
    d_fr = d[1, 0][:, None, :] * arm_r + d[1, 1][:, None, :] * arm_a  # (n, 5 = l, z)
    d_fa = d[0, 0][:, None, :] * arm_r + d[0, 1][:, None, :] * arm_a
    jac = np.einsum("nkz,nlz->nkl", arm_r, d_fr) + np.einsum("nkz,nlz->nkl", arm_a, d_fa)
    return arm_r, arm_a, gen, jac


def _rounding(
    arm_r: np.ndarray, arm_a: np.ndarray, fr: np.ndarray, fa: np.ndarray, d: np.ndarray,
    length: np.ndarray,
) -> np.ndarray:  # fmt: skip
    """The rounding level of each generalised ring force (n, 5): ROUNDING times the sum of its
    terms' magnitudes (as the static model, :mod:`bearingload.models._combined_ring`), plus the
    force change over one rounding of each ball's groove-centre position (``rho``, ``u'``: lengths
    near A held in one double; the inner approach, a difference of such lengths, is known to
    eps A only) - the level a light load against a preload or the centrifugal forces cannot be
    balanced below. [N]"""
    terms = np.abs(arm_r) * np.abs(fr)[:, None, :] + np.abs(arm_a) * np.abs(fa)[:, None, :]
    stiff_r = (np.abs(d[1, 0]) + np.abs(d[1, 1]))[:, None, :] * np.abs(arm_r)
    stiff_a = (np.abs(d[0, 0]) + np.abs(d[0, 1]))[:, None, :] * np.abs(arm_a)
    moved = (stiff_r + stiff_a) * (_EPS * length[:, None, :])
    out = ROUNDING * terms.sum(-1) + moved.sum(-1)
    return np.where(np.isfinite(out), out, 0.0)


def _newton(r: _Ring, v: np.ndarray, do: np.ndarray, ao: np.ndarray) -> tuple[Any, ...]:
    """Newton on the ring equilibrium with a Levenberg-Marquardt safeguard, each case on its
    own: the Newton step, halved, then steps of ``(J^T J + mu diag J^T J) s = J^T res`` with mu
    growing (a tangent nearly singular - two balls alike carrying the axial force and the
    moment - damped in its null direction instead of a step out of the bearing), each no longer
    than a tenth of A; a step is taken when it lowers the residual's 2-norm and some ball
    touches the inner ring. The balls start from the current ones. Returns (v, state,
    iterations (n,))."""
    its = np.zeros(v.shape[0], dtype=int)
    st = _evaluate(r, v, do, ao)
    todo = np.flatnonzero(~(st.merit <= TOLERANCE))
    for _ in range(RING_ITERATIONS):
        if todo.size == 0:
            break
        sub = r.take(todo)
        cur = _take_state(st, todo)
        jac = np.where(sub.held[:, :, None] | sub.held[:, None, :], 0.0, cur.jac)
        jac[:, np.arange(5), np.arange(5)] += sub.held
        res = np.where(sub.held, 0.0, sub.f - cur.gen)
        size = _norm2(sub, cur)
        pending = np.arange(todo.size)
        for k in range(LM_TRIALS):
            step = trial_step(jac[pending], res[pending], sub.held[pending], sub.length[pending], k)
            trial = v[todo[pending]] + step
            got = _evaluate(sub.take(pending), trial, cur.do[pending], cur.ao[pending],
                            cur.sens[pending])  # fmt: skip
            better = (_norm2(sub.take(pending), got) < (1.0 - 1e-4) * size[pending]) | (
                got.merit <= TOLERANCE
            )
            # no ball touching the inner ring: a plateau without tangent, never the answer
            better &= np.any(got.terms[2] > 0, axis=1)
            rows = todo[pending[better]]
            v[rows] = trial[better]
            _put_state(st, rows, _take_state(got, np.flatnonzero(better)))
            pending = pending[~better]
            if pending.size == 0:
                break
        its[todo] += 1
        stalled = np.zeros(todo.size, dtype=bool)
        stalled[pending] = True  # no step lowered the residual: its rounding
        todo = todo[~stalled & ~(st.merit[todo] <= TOLERANCE)]
    return v, st, its


def _coupled(r: _Ring, v: np.ndarray) -> tuple[np.ndarray, ...]:
    """The fast first stage: Newton on the ring and every ball together (5 + 2z unknowns a
    case), each ball's 2x2 block eliminated (the Schur complement, :func:`_coupled_step`): one
    ball Newton step per ring step instead of every ball solved at every ring iterate. From the
    static answer ``v``, the balls on their lines pressed by about F_c (as :func:`_evaluate`
    starts them); each step halved until the combined residual (:func:`_coupled_residual`)
    falls. Each case until it is balanced (TOLERANCE, BALL_TOLERANCE), or no step lowers its
    residual, or after FAST_DAMPED halved steps, or when its residual has not halved over three
    steps (from the FAST_SLOW-th on), or after FAST_ITERATIONS steps; cases at speed 0 are not
    moved. It decides nothing: the nested solver (:func:`_newton`) goes on from its answer.
    Returns (v, do, ao, handed_on (n,) bool: balanced to FAST_HAND_ON, ring and balls, a ball
    touching the inner ring; steps (n,)). [mm, rad]"""
    n = v.shape[0]
    v = v.copy()
    rho, _, up = _centres(r, v)
    do, ao = _line_start(r.b, rho, up)
    fc = 0.125 * r.b.mass * r.b.dm * r.b.omega**2 * _KG_MM
    ao = np.where(do <= 0, 0.0, ao)
    do = np.maximum(do, (fc / r.b.ko[..., -1]) ** (2.0 / 3.0))
    arms = _arms(r)
    cur = list(_coupled_residual(r, arms, v, do, ao))
    going = (r.b.omega[:, 0] > 0) & cur[-1]
    steps, damped = np.zeros(n, dtype=int), np.zeros(n, dtype=int)
    past = [cur[3].copy()] * 3  # the combined residual at the last iterations
    for _ in range(FAST_ITERATIONS):
        going &= (damped < FAST_DAMPED) & ~((cur[1] <= TOLERANCE) & (cur[2] <= BALL_TOLERANCE))
        going &= ~((steps >= FAST_SLOW) & (cur[3] > 0.5 * past[-3]))  # not halved in three
        past.append(cur[3].copy())
        rows = np.flatnonzero(going)
        if rows.size == 0:
            break
        sub, sub_arms, t = r, arms, cur[0]
        if rows.size < n:  # (one case alone, always every case: no copies)
            sub, sub_arms = r.take(rows), (arms[0][rows], arms[1][rows])
            t = tuple(a[rows] for a in t)
        dv, y0, dy = _coupled_step(sub, sub_arms, v[rows], do[rows], ao[rows], t)
        pending, lam = np.arange(rows.size), 1.0
        for _ in range(FAST_HALVINGS):
            every = pending.size == n
            part, part_arms = (r, arms) if every else (
                sub.take(pending), (sub_arms[0][pending], sub_arms[1][pending]))  # fmt: skip
            y1, y2 = y0[0][pending] + lam * dy[0][pending], y0[1][pending] + lam * dy[1][pending]
            v2, do2, ao2 = (
                v[rows[pending]] + lam * dv[pending],
                np.hypot(y1, y2) - part.b.ro,
                np.arctan2(y1, y2),
            )
            got = _coupled_residual(part, part_arms, v2, do2, ao2)
            better = got[-1] & (got[3] < (1.0 - 1e-4 * lam) * cur[3][rows[pending]])
            won = rows[pending[better]]
            if every and better.all():
                v, do, ao, cur = v2, do2, ao2, list(got)
            else:
                v[won], do[won], ao[won] = v2[better], do2[better], ao2[better]
                for mine, theirs in zip(cur[0] + tuple(cur[1:]), got[0] + got[1:], strict=True):
                    mine[won] = theirs[better]
            steps[won] += 1
            damped[won] += lam < 1.0
            pending, lam = pending[~better], 0.5 * lam
            if pending.size == 0:
                break
        going[rows[pending]] = False  # no step lowered the residual
    near = cur[-1] & (cur[1] <= FAST_HAND_ON) & (cur[2] <= FAST_HAND_ON)
    return v, do, ao, near & (r.b.omega[:, 0] > 0), steps


def _coupled_residual(
    r: _Ring, arms: tuple[np.ndarray, np.ndarray], v: np.ndarray, do: np.ndarray, ao: np.ndarray
) -> tuple[Any, ...]:
    """The residuals of the coupled stage at (v, do, ao): (the balls' terms and, last, their partial derivatives (n, z, 4, 4) (rows g1, g2, Fa, Fr; columns do, ao,
    rho, u'), the ring residual over f_ref, the largest ball residual over its forces, the
    combined 2-norm of the free ring residual over f_ref and of every ball's over its forces
    (n,), whether all are finite and some ball touches the inner ring (n,)). One call of the ball
    evaluator with its analytic derivatives (at hand when the trial is taken). [-]"""
    rho, _, up = _centres(r, v)
    terms, d = ball_partials(r.b, rho, up, do, ao)  # d[row, col]: g1, g2, Fa, Fr; do, ao, rho, u'
    t = terms + (d.transpose(2, 3, 0, 1),)
    arm_r, arm_a = arms
    gen = (arm_r * t[13][:, None, :] + arm_a * t[12][:, None, :]).sum(-1)
    res = np.where(r.held, 0.0, r.f - gen) / r.f_ref[:, None]
    norm = _ball_norm(r.b, t, do, np.ones(do.shape, dtype=bool))[0]
    combined = np.sqrt((res * res).sum(axis=1) + (norm * norm).sum(axis=1))
    finite = np.isfinite(combined) & np.any(t[2] > 0, axis=1)
    return t, np.abs(res).max(axis=1), norm.max(axis=1), combined, finite


def _coupled_step(
    r: _Ring, arms: tuple[np.ndarray, np.ndarray], v: np.ndarray, do: np.ndarray, ao: np.ndarray,
    t: tuple[Any, ...],
) -> tuple[Any, ...]:  # fmt: skip
    """The coupled Newton step at (v, do, ao), the balls' terms ``t`` there: the ring step from
    ``J dv = f - F + sum dF/dX (dg/dX)^-1 g`` (J the tangent with the balls eliminated, held
    components not moved, no longer than A/10), each ball's step ``-(dg/dX)^-1 g`` plus its
    sensitivity times its groove centre's move, no longer than r'_o/4 and cut where it would
    press the ball into the inner ring by more than twice its inner approach or the approach
    ``(F_c/K_i)^(2/3)`` (Newton's overshoot on ``delta^1.5`` near 0). The partial derivatives
    are the last of ``t`` (:func:`_coupled_residual`). Returns (dv (n, 5), the ball centres
    (X_1, X_2) and their steps (n, z)). [mm]"""
    rho, u, up = _centres(r, v)
    d = t[14].transpose(2, 3, 0, 1)  # d[row, col]: rows g1, g2, Fa, Fr; columns do, ao, rho, u'
    det = d[0, 0] * d[1, 1] - d[0, 1] * d[1, 0]
    inv = np.stack([[d[1, 1], -d[0, 1]], [-d[1, 0], d[0, 0]]]) / det
    xg = inv[:, 0] * t[0] + inv[:, 1] * t[1]  # (dg/dX)^-1 g (2, n, z)
    sens = -np.einsum("kmnz,mpnz->kpnz", inv, d[:2, 2:])  # dX/d(rho, u')
    dup = np.where(r.one_sided[:, None], (u > 0).astype(float), 1.0)
    tot = d[2:, 2:] + np.einsum("rknz,kpnz->rpnz", d[2:, :2], sens)
    tot[:, 1] *= dup
    arm_r, arm_a, gen, jac = _assemble(r, t[13], t[12], tot, arms)
    corr = np.einsum("rknz,knz->rnz", d[2:, :2], xg)  # dF/dX (dg/dX)^-1 g (Fa, Fr)
    rhs = r.f - gen + (arm_a * corr[0][:, None, :] + arm_r * corr[1][:, None, :]).sum(-1)
    rhs = np.where(r.held | ~np.isfinite(rhs), 0.0, rhs)
    jac = np.where(r.held[:, :, None] | r.held[:, None, :], 0.0, jac)
    jac[:, np.arange(5), np.arange(5)] += r.held
    dv = trial_step(jac, rhs, r.held, r.length, 0)
    rho2, _, up2 = _centres(r, v + dv)
    s = -xg + sens[:, 0] * (rho2 - rho) + sens[:, 1] * (up2 - up)  # d(do, ao)
    lo, so, co = r.b.ro + do, np.sin(ao), np.cos(ao)
    x1, x2 = so * s[0] + lo * co * s[1], co * s[0] - lo * so * s[1]  # the ball centre's step
    cut = np.minimum(1.0, 0.25 * r.b.ro / np.maximum(np.hypot(x1, x2), 1e-300))
    y0 = (lo * so, lo * co)
    x1, x2 = np.where(np.isfinite(x1), x1 * cut, 0.0), np.where(np.isfinite(x2), x2 * cut, 0.0)
    di0 = np.maximum(t[11], 0.0)
    di1 = np.hypot(up2 - y0[0] - x1, np.maximum(rho2 - y0[1] - x2, 0.0)) - r.b.ri
    fc = 0.125 * r.b.mass * r.b.dm * r.b.omega**2 * _KG_MM
    bound = np.maximum(2.0 * di0, 2.0 * (fc / r.b.ki[..., -1]) ** (2.0 / 3.0))
    kap = np.where(di1 > bound, (bound - di0) / np.where(di1 > bound, di1 - di0, 1.0), 1.0)
    kap = np.clip(np.where(np.isfinite(kap), kap, 1.0), 0.0, 1.0)
    return dv, y0, (x1 * kap, x2 * kap)


def _arms(r: _Ring) -> tuple[np.ndarray, np.ndarray]:
    """The arms of the balls' radial and axial forces in the generalised ring forces (n, 5,
    z). [-]"""
    c, s = r.c, r.s
    zero, one = np.zeros_like(c), np.ones_like(c)
    return np.stack([c, s, zero, zero, zero], axis=1), np.stack([zero, zero, one, c, s], axis=1)


def _norm2(r: _Ring, st: _State) -> np.ndarray:
    """The 2-norm of the free residual over f_ref (inf: a ball unsolved). [-]"""
    res = np.where(r.held, 0.0, r.f - st.gen)
    return np.where(np.isfinite(st.merit), np.sqrt((res * res).sum(axis=1)) / r.f_ref, np.inf)


def trial_step(
    jac: np.ndarray, res: np.ndarray, held: np.ndarray, length: np.ndarray, k: int
) -> np.ndarray:
    """Trial ``k`` of the safeguarded Newton of the ring (or of a pair's shaft): the Newton step
    halved k times up to HALVINGS, then Levenberg-Marquardt steps with mu growing; the components
    ``held`` by a symmetry not moved (LAPACK's solve moved them by 1e-13); no longer than a tenth
    of ``length`` (A). [mm]"""
    lam, mu = (0.5**k, 0.0) if k < HALVINGS else (1.0, 1e-6 * 100.0 ** (k - HALVINGS))
    step = np.where(held, 0.0, lam * _lm_step(jac, res, mu))
    longest = np.abs(step).max(axis=1)
    return step * np.minimum(1.0, 0.1 * length / np.maximum(longest, 1e-300))[:, None]


def _lm_step(jac: np.ndarray, res: np.ndarray, mu: float) -> np.ndarray:
    """The Newton step (mu = 0) or the Levenberg-Marquardt step of every case. [mm]"""
    if mu == 0.0:
        step = _ring_step(jac, res)
    else:
        jt = jac.transpose(0, 2, 1)
        jtj = jt @ jac
        diag = np.einsum("nii->ni", jtj)
        diag = np.maximum(diag, 1e-12 * diag.max(axis=1, keepdims=True))
        a = jtj + mu * diag[:, :, None] * np.eye(5)
        step = _ring_step(a, (jt @ res[..., None])[..., 0])
    return np.where(np.isfinite(step), step, 0.0)


def _ring_step(jac: np.ndarray, res: np.ndarray) -> np.ndarray:
    """The solution of jac step = res of every case; a singular tangent (no ball touching along
    a direction) gives the least-squares step. [mm]"""
    try:
        return np.linalg.solve(jac, res[..., None])[..., 0]
    except np.linalg.LinAlgError:  # case by case: no case's step depends on another's
        out = np.empty_like(res)
        for k in range(res.shape[0]):
            try:
                out[k] = np.linalg.solve(jac[k], res[k])
            except np.linalg.LinAlgError:
                out[k] = np.linalg.pinv(jac[k]) @ res[k]
        return out


def _take_state(st: _State, idx: np.ndarray) -> _State:
    return _State(st.do[idx], st.ao[idx], st.balls_ok[idx], st.gen[idx], st.jac[idx],
                  st.merit[idx], tuple(t[idx] for t in st.terms), st.sens[idx],
                  st.score[idx], st.level[idx])  # fmt: skip


def _put_state(st: _State, rows: np.ndarray, new: _State) -> None:
    for name in ("do", "ao", "balls_ok", "gen", "jac", "merit", "sens", "score", "level"):
        getattr(st, name)[rows] = getattr(new, name)
    for mine, theirs in zip(st.terms, new.terms, strict=True):
        mine[rows] = theirs


def _solve(
    z: int, geo: Any, flat: dict, pos: dict, angles: np.ndarray, material: tuple[np.ndarray, ...],
    one_sided: np.ndarray, imposed_tilt: bool,
) -> tuple[Any, ...]:  # fmt: skip
    """Set up the ring problem at the static answer and solve it with the stiffness updates."""
    e, nu, dens = material
    n = geo.D_w.shape[0]
    c, s, mirror = _combined._directions(z, np.mod(flat["cage_angle"], 360.0))
    fr, fa, mm, mc = (flat[k] for k in ("radial_load", "axial_load", "moment", "moment_cross"))
    rr = geo.R_i
    t_imp = rr * np.deg2rad(flat.get("misalignment", np.zeros(n)))
    held, fixed = _combined._locks(z, mirror, (fr, fa, mm, mc), t_imp, imposed_tilt)
    f_ref = _combined._reference_force(fr, fa, mm, mc, rr)
    f = np.stack([fr, np.zeros(n), fa, mm / rr, mc / rr], axis=1)
    shift = np.where(one_sided, geo.A * np.sin(geo.alpha0), 0.0)
    v_static = np.stack([pos["x"], pos["y"], pos["axial"] + shift, rr * np.deg2rad(pos["tilt"]),
                         rr * np.deg2rad(pos["tilt_cross"])], axis=1)  # fmt: skip
    # x, y and the tilts a symmetry holds are 0 exactly at speed (the static answer's can be
    # 1e-14 mm: a y of 3e-14 moved an ill-conditioned mirror pair's inner loads 4e-9 N apart,
    # an unbalance across the load line the held y never sees); at speed 0 the static answer
    zero = held & ~fixed & (flat["speed"] > 0)[:, None]
    zero[:, 2] = False
    v_static = np.where(zero, 0.0, v_static)
    ki, ko = _stiffness_nodes(geo, e, nu)
    col = [(geo.f_i - 0.5) * geo.D_w, (geo.f_o - 0.5) * geo.D_w, geo.D_w, geo.d_m,
           flat["speed"] * math.pi / 30.0, dens * math.pi / 6.0 * geo.D_w**3]  # fmt: skip
    ri, ro, dwc, dmc, omega, mass = (a[:, None] for a in col)
    b = _Set(ri, ro, dwc, dmc, omega, mass, ki, ko)
    ring = _Ring(b, c, s, geo.A - geo.g, f, f_ref, held, one_sided, geo.A)
    nan = np.full((n, z), np.nan)
    v, st, total = _first_solve(ring, v_static, nan)
    bad = np.flatnonzero(~st.accepted)
    if bad.size:
        start = pos["shifted"](bad)
        v2 = np.stack([start["x"], start["y"], start["u"], rr * np.deg2rad(start["tilt"]),
                       rr * np.deg2rad(start["tilt_cross"])], axis=1)[bad]  # fmt: skip
        v2 = np.where(zero[bad], 0.0, v2)
        v2, st2, its2 = _newton(ring.take(bad), v2, nan[bad], nan[bad])
        total[bad] += its2
        won = np.flatnonzero(st2.accepted)
        v[bad[won]] = v2[won]
        _put_state(st, bad[won], _take_state(st2, won))
    for i in np.flatnonzero(~st.accepted):
        _continuation(ring, int(i), v, st, total, v_static[i])
    _check_resolved(st, ring, flat)
    _check(st, total, flat, one_sided)
    return ring, v, st, total


def _first_solve(r: _Ring, v_static: np.ndarray, nan: np.ndarray) -> tuple[Any, ...]:
    """The nested Newton (:func:`_newton`) from the coupled stage's answer (:func:`_coupled`)
    where it came within FAST_HAND_ON, from the static answer elsewhere and where the first
    leaves a case unbalanced. Returns (v, state, iterations (n,))."""
    fv, fdo, fao, handed, steps = _coupled(r, v_static)
    v0 = np.where(handed[:, None], fv, v_static)
    do0, ao0 = np.where(handed[:, None], fdo, nan), np.where(handed[:, None], fao, nan)
    v, st, total = _newton(r, v0, do0, ao0)
    total += steps
    bad = np.flatnonzero(handed & ~st.accepted)
    if bad.size:
        v2, st2, its2 = _newton(r.take(bad), v_static[bad].copy(), nan[bad], nan[bad])
        total[bad] += its2
        won = np.flatnonzero(st2.accepted)
        v[bad[won]] = v2[won]
        _put_state(st, bad[won], _take_state(st2, won))
    return v, st, total


def _continuation(
    ring: _Ring, i: int, v: np.ndarray, st: _State, its: np.ndarray, v_static: np.ndarray
) -> None:
    """Case i again, by continuation in the centrifugal and gyroscopic terms (both in omega^2):
    from the static answer, the speed raised in stages of omega^2 (a quarter, halved on a
    stage that does not converge, doubled after one that does), each started from the last
    balls and the ring position extrapolated from the last two stages (the balls move out with
    the speed: from the last position alone the loaded ones can lose the inner ring). A stage
    converges when balanced to ACCEPT, as the last must: a stage stalled above it (a ring
    nearly free across, on a plateau) passed on left the next stages on the plateau. The
    answer, if any, replaces case i's in v, st, its."""
    one = ring.take(np.array([i]))
    omega = one.b.omega
    x, do = v_static[None, :].copy(), np.full((1, st.do.shape[1]), np.nan)
    ao, rate = do.copy(), np.zeros_like(x)
    done, step = 0.0, 0.25
    for _ in range(CONTINUATION_STAGES):
        frac = min(1.0, done + step)
        stage = dataclasses.replace(one, b=dataclasses.replace(one.b, omega=omega * frac**0.5))
        x1, st1, its1 = _newton(stage, x + rate * (frac - done), do, ao)
        its[i] += its1[0]
        if st1.accepted[0]:
            if done > 0.0:
                rate = (x1 - x) / (frac - done)
            done, x, do, ao = frac, x1, st1.do, st1.ao
            if done == 1.0:
                v[i] = x1[0]
                _put_state(st, np.array([i]), st1)
                return
            step = min(2.0 * step, 1.0 - done)
        else:
            step *= 0.5
            if step < 1e-6:
                return


def _check_resolved(st: _State, ring: _Ring, flat: dict) -> None:
    """InputError where the rounding level of the ring forces at the end is above LEVEL_MAX of
    the largest applied load (a load tiny against a preload or the balls' centrifugal forces:
    the double cannot balance it to the digits given). The smallest load accepted: the level
    grows at most as the load^(1/3) (the contact stiffness; constant under a preload), so
    ``F (level/LEVEL_MAX)^1.5`` is resolved."""
    level = np.where(np.isfinite(st.level), st.level, 0.0)
    bad = np.flatnonzero(level > LEVEL_MAX)
    if bad.size == 0:
        return
    i = int(bad[np.argmax(level[bad])])
    f_min = float(ring.f_ref[i] * (level[i] / LEVEL_MAX) ** 1.5)
    f_min = float(f"{f_min * 1.05:.2g}")  # two digits, rounded up
    raise InputError(
        "radial_load",
        f"the loads are too small against the ball forces at this speed for the ball dynamics "
        f"(the largest of F_r, |F_a| and M/R_i is {float(ring.f_ref[i]):.3g} N; the rounding of "
        f"the ball forces on the ring is {level[i] * float(ring.f_ref[i]):.2g} N, more than "
        f"{LEVEL_MAX:.0e} of it; it takes at least {f_min:.2g} N at speed "
        f"{float(flat['speed'][i]):.6g} rpm and clearance {float(flat['clearance'][i]):.6g} mm "
        f"for this bearing); {_combined.RADIAL_TAKES_ANY_LOAD}",
    )


def _rel(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.max(np.abs(a - b) / np.abs(b), initial=0.0))


def _check(st: _State, its: np.ndarray, flat: dict, one_sided: np.ndarray) -> None:
    """ConvergenceError naming the inputs of the cases left unbalanced."""
    bad = ~st.accepted
    if np.any(bad):
        known = st.merit[bad][np.isfinite(st.merit[bad])]
        raise ConvergenceError(
            "ball-dynamics ring and ball equilibrium",
            int(its[bad].max()),
            float(known.max()) if known.size else math.nan,
            {k: v[bad] for k, v in flat.items()},
        )


def _result(
    static: CombinedDistribution, shape: tuple[int, ...], z: int, geo: Any, flat: dict,
    density: np.ndarray, out: tuple[Any, ...], one_sided: np.ndarray, misalignment: Any,
) -> HighSpeedDistribution:  # fmt: skip
    """The static answer's fields with the dynamic ring position, balls and tangent."""
    from bearingload import numerics

    ring, v, st, its = out
    g1, g2, qi, qo, si, ci, fc, mg, wc, wr, beta, di = st.terms[:12]
    rr = geo.R_i

    def case(a: Any) -> Any:
        a = np.asarray(a, dtype=float)
        return numerics.scalar_out(
            a.reshape(shape) if a.size == math.prod(shape) else np.broadcast_to(a, shape).copy()
        )

    def ball(a: Any) -> np.ndarray:
        return np.asarray(a, dtype=float).reshape(shape + (z,))

    fields = {f.name: getattr(static, f.name) for f in dataclasses.fields(CombinedDistribution)}
    for name, value in fields.items():
        if isinstance(value, np.ndarray) or isinstance(value, float):
            tail = np.shape(value)[len(np.shape(static.x)) :]
            fields[name] = np.broadcast_to(value, shape + tail).copy()
            if not tail:
                fields[name] = case(fields[name])
    ai = np.rad2deg(np.arctan2(si, ci))
    ao = np.rad2deg(st.ao)

    lever = np.stack([np.ones_like(rr)] * 3 + [rr, rr], axis=1)
    tangent = st.jac * lever[:, :, None] * lever[:, None, :]

    shift = np.where(one_sided, geo.A * np.sin(geo.alpha0), 0.0)
    moment = rr * st.gen[:, 3] if misalignment is not None else flat["moment"]
    fields.update(
        x=case(v[:, 0]), y=case(v[:, 1]), axial=case(v[:, 2] - shift),
        tilt=case(np.rad2deg(v[:, 3] / rr)), tilt_cross=case(np.rad2deg(v[:, 4] / rr)),
        moment=case(moment),
        contact_angles=ball(ai), ball_loads=ball(qi), ball_stiffnesses=ball(_stiffness(ring.b.ki, ci)),
        ball_approaches=ball(di + st.do), stiffness_matrix=tangent.reshape(shape + (5, 5)),
        iterations=case(np.asarray(fields["iterations"]).ravel() + its),
    )  # fmt: skip
    return HighSpeedDistribution(
        **fields,
        speed=case(flat["speed"]),
        ball_density=case(np.broadcast_to(density, shape)),
        contact_angles_inner=ball(ai),
        contact_angles_outer=ball(ao),
        ball_loads_inner=ball(qi),
        ball_loads_outer=ball(qo),
        ball_stiffnesses_outer=ball(_stiffness(ring.b.ko, np.cos(st.ao))),
        approaches_inner=ball(di),
        approaches_outer=ball(st.do),
        ball_offsets_axial=ball((ring.b.ro + st.do) * np.sin(st.ao)),
        ball_offsets_radial=ball((ring.b.ro + st.do) * np.cos(st.ao)),
        orbit_speeds=ball(wc),
        spin_speeds=ball(wr),
        attitude_angles=ball(np.rad2deg(beta)),
        centrifugal_forces=ball(fc),
        gyroscopic_moments=ball(mg),
    )
