"""Combined radial, axial and moment load of a deep-groove (or angular-contact) ball bearing:
the 3-D equilibrium of the inner ring (ISO/TS 16281:2008; Harris & Kotzalas, 5th ed., ch. 8).

The model, its geometry, conventions and numerics: docs/models.md, "Combined radial, axial and
moment load"; angular contact (one-sided): docs/angular_contact.md, "The model". A call is one
core call where its cases need no more (:func:`_one_call`); the rest (refusals, retries, the
least tilt) is :func:`_general`'s.
"""

from __future__ import annotations

import dataclasses
import math
import operator
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

from bearingload import numerics, validate
from bearingload.constants import STEEL_MODULUS
from bearingload.errors import ConvergenceError, InputError
from bearingload.models import _combined_ring as _ring
from bearingload.models import _core
from bearingload.models._combined_ring import ACCEPT, MAX_ITERATIONS, TOLERANCE, Problem
from bearingload.models._ring import CAGE_OFF_LINE, SYMMETRY_SNAP_DEG

__all__ = ["CombinedDistribution", "solve_combined", "axial_only", "groove_geometry",
           "ball_stiffness_at", "TOLERANCE", "ACCEPT", "MAX_ITERATIONS"]  # fmt: skip
#: Stiffness updates (each followed by a minimisation) before ConvergenceError. [-]
MAX_STIFFNESS_UPDATES = 40


class StiffnessViews:
    """The diagonal terms of a result's 5×5 ``stiffness_matrix`` (x, y, axial, tilt,
    tilt_cross) as engineers read them: a bearing's (:class:`CombinedDistribution`) or a
    pair's (:class:`bearingload.models.pair.PairDistribution`)."""

    stiffness_matrix: np.ndarray

    @property
    def stiffness_radial(self) -> Any:
        """dF_x/dx with the transverse force F_y held at zero (the ring free across the load
        line, its other displacements held), as the radial engine gives it: the Schur
        complement ``K_xx - K_xy K_yx / K_yy``; ``K_xx`` where nothing stiffens y
        (:func:`bearingload.numerics.radial_stiffness`). [N/mm]"""
        k = self.stiffness_matrix
        return numerics.radial_stiffness(k[..., 0, 0], k[..., 0, 1], k[..., 1, 0], k[..., 1, 1])

    @property
    def stiffness_axial(self) -> Any:
        """dF_a/d(axial), the axial stiffness. [N/mm]"""
        return numerics.scalar_out(self.stiffness_matrix[..., 2, 2])

    @property
    def stiffness_tilt(self) -> Any:
        """dM/d(tilt), the tilting stiffness in the plane of the load. [N mm/rad]"""
        return numerics.scalar_out(self.stiffness_matrix[..., 3, 3])

    @property
    def stiffness_matrix_symmetric(self) -> np.ndarray:
        """The symmetric part of ``stiffness_matrix``, ``(K + K^T)/2``, for a rotor code that
        needs a symmetric bearing matrix. The matrix itself is the true tangent: with the Hertz
        stiffness changing with the contact angle (and at speed, the ball dynamics) it is not
        quite symmetric; the part this leaves out is about 1e-5 of the largest entry at rest
        (docs/models.md). [N/mm, N/rad, N mm/mm, N mm/rad]"""
        k = np.asarray(self.stiffness_matrix)
        return 0.5 * (k + np.swapaxes(k, -1, -2))


@dataclass(frozen=True)
class CombinedDistribution(StiffnessViews):
    """Solution of the combined-load equilibrium; arrays of the case shape, ball arrays (..., z).

    For one case given as scalars every case quantity is a Python ``float`` (``iterations`` an
    ``int``; :func:`bearingload.numerics.scalar_out`), as in
    :class:`~bearingload.models.equilibrium.LoadDistribution`; the ball arrays stay (z,) arrays.

    Attributes
    ----------
    balls : int
        Number of balls z. [-]
    load, axial_load : ndarray
        Radial load F_r (the keyword ``radial_load`` of :func:`solve_combined`; ``load`` as in
        :class:`~bearingload.models.equilibrium.LoadDistribution` and the JSON key) and axial
        load F_a. [N]
    moment : ndarray
        Moment on the inner ring, applied or (imposed misalignment) needed. [N mm]
    clearance : ndarray
        Radial internal clearance G_r (total play). [mm]
    cage_angle : ndarray
        Angle of ball 1 from the load line. [°]
    free_contact_angle : ndarray
        alpha_0 = arccos(1 - G_r/(2A)) (0 under preload). [°]
    axial_play : ndarray
        2 A sin(alpha_0). [mm]
    x, y : ndarray
        Radial displacement of the inner ring along and across the load line. [mm]
    axial : ndarray
        Axial displacement from the centred rings (half the axial play included). [mm]
    tilt, tilt_cross : ndarray
        Tilt about the axis across the load line and about the load line. [°]
    ball_angles : ndarray (..., z)
        phi_j from the load line. [°]
    contact_angles : ndarray (..., z)
        Operating contact angle alpha_j of every ball; for a ball carrying no load the
        direction of its groove-centre line, ``atan2(u_j, max(rho_j, 0))``, which is ±90° for
        a loose ball (groove centres crossed) and never NaN. [°]
    ball_approaches : ndarray (..., z)
        delta_j (negative: the gap left). [mm]
    ball_stiffnesses : ndarray (..., z)
        K(alpha_j), both contacts in series. [N/mm^1.5]
    ball_loads : ndarray (..., z)
        Q_j. [N]
    tilt_radius : ndarray
        The lever of the tilt used: the ``tilt_radius`` given, or R_i, the radius of the inner
        groove curvature centres (ISO/TS 16281). [mm]
    stiffness_matrix : ndarray (..., 5, 5)
        The bearing's stiffness at the equilibrium, the true tangent: d(F_x, F_y, F_a, M,
        M_c)/d(x, y, axial, tilt, tilt_cross), forces [N] and moments [N mm] on the inner ring
        per displacement [mm] and tilt [rad] of it (x along the load line, tilts in radians, as
        a rotor model takes them); with the Hertz K(alpha) not quite symmetric (its symmetric
        part: ``stiffness_matrix_symmetric``). See ``stiffness_radial``, ``stiffness_axial``,
        ``stiffness_tilt``. [N/mm, N/rad, N mm/mm, N mm/rad]
    iterations : ndarray of int
        Newton steps: those of the double-precision first stage and of the double-double
        minimisations, summed over the stiffness updates. [-]
    tilt_undetermined : ndarray of bool
        The loads do not determine the ring's tilt: a range of tilts balances them (see
        :func:`_least_norm_tilt`); the least of them is the one returned.
    thrust_neglected : ndarray of bool or None
        The thrust, below :data:`NEGLIGIBLE_THRUST` of the largest load, was beyond what the
        ring's axial position resolves: the case is its neighbour with that share of the
        largest load as its thrust (the limit of a thrust going to 0), the difference its
        error.
    """

    balls: int
    load: np.ndarray
    axial_load: np.ndarray
    moment: np.ndarray
    clearance: np.ndarray
    cage_angle: np.ndarray
    free_contact_angle: np.ndarray
    axial_play: np.ndarray
    x: np.ndarray
    y: np.ndarray
    axial: np.ndarray
    tilt: np.ndarray
    tilt_cross: np.ndarray
    ball_angles: np.ndarray
    contact_angles: np.ndarray
    ball_approaches: np.ndarray
    ball_stiffnesses: np.ndarray
    ball_loads: np.ndarray
    tilt_radius: np.ndarray
    stiffness_matrix: np.ndarray
    iterations: np.ndarray
    tilt_undetermined: np.ndarray
    thrust_neglected: np.ndarray | None = None

    @property
    def q_max(self) -> Any:
        """Load of the most heavily loaded ball. [N]"""
        return numerics.scalar_out(self.ball_loads.max(axis=-1))

    @property
    def loaded_balls(self) -> Any:
        """Number of balls carrying load. [-]"""
        return numerics.scalar_out((self.ball_loads > 0).sum(axis=-1))


@dataclass(frozen=True)
class _Geometry:
    """Deep-groove geometry per case (arrays of the case shape), lengths in mm."""

    D_w: np.ndarray
    d_m: np.ndarray
    f_i: np.ndarray
    f_o: np.ndarray
    A: np.ndarray
    g: np.ndarray  # G_r / 2
    alpha0: np.ndarray  # [rad]
    R_i: np.ndarray


def groove_geometry(
    ball_diameter: Any, pitch_diameter: Any, f_i: Any, f_o: Any, clearance: Any = 0.0
) -> tuple[Any, Any, Any]:
    """A = (f_i + f_o - 1) D_w, free contact angle and axial play of a deep-groove ball bearing.

    Parameters
    ----------
    ball_diameter : array_like
        D_w. [mm]
    pitch_diameter : array_like
        d_m. [mm]
    f_i, f_o : array_like
        Groove conformities r_i/D_w, r_o/D_w, > 0.5. [-]
    clearance : array_like
        Radial internal clearance G_r (negative = preload), below 2 A, and |G_r| < D_w/2
        (:func:`bearingload.validate.clearance_fits`). [mm]

    Returns
    -------
    (A [mm], alpha_0 [°], axial play [mm])

    >>> A, a0, sa = groove_geometry(11.5, 43.5, 0.52, 0.53, 0.01)
    >>> round(float(A), 4), round(float(a0), 4), round(float(sa), 5)
    (0.575, 7.5614, 0.15133)
    """
    dw, dm, gr = validate.each_finite(  # refused in solve_combined's order, by element
        ball_diameter=ball_diameter, pitch_diameter=pitch_diameter, clearance=clearance
    )
    fi, fo = validate.conformity("f_i", f_i), validate.conformity("f_o", f_o)
    named = {"ball_diameter": dw, "pitch_diameter": dm, "clearance": gr}

    def at(name: str, bad: Any, unit: str = "") -> str:  # the input's element of a bad case
        return validate.element_at(named[name], bad, np.shape(bad), unit)

    validate.broadcast_shape(named | {"f_i": fi, "f_o": fo})
    check_cases(_CASE_RULES, named, at)  # (as solve_combined, before the geometry)
    geo = ring_geometry(dw, dm, fi, fo, gr, at=at)
    play = 2.0 * geo.A * np.sin(geo.alpha0)
    return (
        numerics.scalar_out(geo.A),
        numerics.scalar_out(np.rad2deg(geo.alpha0)),
        numerics.scalar_out(play),
    )


def _no_element(name: str, bad: Any, unit: str = "") -> str:
    return ""


def ring_geometry(
    dw: Any,
    dm: Any,
    fi: Any,
    fo: Any,
    clearance: Any,
    angular: bool = False,
    at: Callable[..., str] = _no_element,
) -> _Geometry:
    """The geometry of finite arrays (:func:`bearingload.validate.finite`, broadcast together),
    refused where it is not one of a deep-groove ball bearing; ``angular``: ``clearance`` is the
    design contact angle alpha_0 [°] of an angular-contact bearing (:func:`angular_geometry`).
    The arithmetic is the compiled core's ``groove``, one loop over the cases; ``at(name, bad,
    unit)`` names the input's element of the first case refused (``clearance[1] = 5 mm``)."""
    columns: tuple[np.ndarray, ...] = (dw, dm, fi, fo, clearance)
    shape = columns[0].shape
    if any(v.shape != shape for v in columns) or len(shape) != 1:
        shape = np.broadcast_shapes(*(v.shape for v in columns))
        columns = tuple(np.broadcast_to(v, shape).reshape(-1) for v in columns)
    big_a, g, alpha0, r_i, fits = _core.groove(
        np.array(columns, dtype=float).reshape(5, -1), angular, *validate.CONFORMITY_RANGE
    )
    if np.count_nonzero(fits) < fits.size:
        _refuse_geometry(dw, dm, fi, fo, (g >= big_a).reshape(shape), at)
    cut = (big_a, g, alpha0, r_i)  # (n,): the shape of flat arrays, else reshaped to it
    return _Geometry(dw, dm, fi, fo, *(cut if len(shape) == 1 else (a.reshape(shape) for a in cut)))


def _refuse_geometry(dw: Any, dm: Any, fi: Any, fo: Any, out: Any, at: Callable[..., str]) -> None:
    """InputError naming the first parameter of a geometry that does not fit
    (:func:`ring_geometry`) and, by ``at``, its element; ``out``: where the clearance is too
    large."""
    for name, value in (("ball_diameter", dw), ("pitch_diameter", dm)):
        try:
            validate.positive(name, value, "mm")
        except InputError as exc:  # its element as given (``at``), not of the cases broadcast
            raise InputError(name, exc.problem, element=at(name, value <= 0, "mm")) from None
    if np.any(dw >= dm):
        raise InputError(
            "ball_diameter",
            "must be smaller than the pitch diameter",
            element=at("ball_diameter", dw >= dm, "mm"),
        )
    validate.conformity("f_i", fi)
    validate.conformity("f_o", fo)
    if np.any(out):
        raise InputError(
            "clearance",
            "must be smaller than 2 (f_i + f_o - 1) D_w, the clearance at which the ball "
            "would leave the grooves axially",
            element=at("clearance", out, "mm"),
        )


def ball_stiffness_at(
    contact_angle: Any,
    ball_diameter: Any,
    pitch_diameter: Any,
    f_i: Any,
    f_o: Any,
    modulus: Any = STEEL_MODULUS,
    poisson: Any = 0.3,
) -> Any:
    """Hertz stiffness of a ball (inner and outer contact in series) at a contact angle. [N/mm^1.5]

    The curvature sums across the rolling direction depend on the angle through
    ``gamma = D_w cos(alpha)/d_m`` (ISO/TS 16281; Harris & Kotzalas): they are those of a
    zero-angle bearing of pitch diameter ``d_m / cos(alpha)``.

    Parameters
    ----------
    contact_angle : array_like
        alpha, |alpha| < 90. [°]
    ball_diameter, pitch_diameter : array_like
        D_w and d_m. [mm]
    f_i, f_o : array_like
        Groove conformities. [-]
    modulus, poisson : array_like
        E [MPa] and nu [-] of balls and rings.

    >>> k0 = ball_stiffness_at(0.0, 11.5, 43.5, 0.52, 0.53, 210000.0)
    >>> k20 = ball_stiffness_at(20.0, 11.5, 43.5, 0.52, 0.53, 210000.0)
    >>> round(float(k0), -2), round(float(k20 / k0), 5)
    (333600.0, 1.00041)
    """
    from bearingload.contact.hertz import ball_stiffness

    cos_a = np.cos(np.deg2rad(validate.finite("contact_angle", contact_angle)))
    return ball_stiffness(
        ball_diameter, np.asarray(pitch_diameter) / cos_a, f_i, f_o, modulus, poisson
    ).ball


def axial_only(
    balls: Any, axial_load: Any, stiffness: Any, A: Any, clearance: Any = 0.0
) -> tuple[Any, Any, Any]:
    """Closed form of a purely axially loaded deep-groove ball bearing: every ball alike.

    ``Q = F_a / (z sin(alpha))`` and ``Q = K (A/cos(alpha) (1 - G_r/(2A)) - A)^1.5`` fix the
    contact angle alpha (Harris & Kotzalas, *Rolling Bearing Analysis*, 5th ed., §8.3: the
    deep-groove ball bearing under thrust); solved here by bisection in the axial offset.

    Parameters
    ----------
    balls : array_like
        z. [-]
    axial_load : array_like
        F_a > 0. [N]
    stiffness : array_like
        Ball stiffness K (both contacts, taken constant). [N/mm^1.5]
    A : array_like
        (f_i + f_o - 1) D_w. [mm]
    clearance : array_like
        G_r, below 2A. [mm]

    Returns
    -------
    (axial displacement from the centred rings [mm], contact angle [°], ball load [N])

    >>> a, alpha, q = axial_only(7, 1000.0, 5.89e5, 0.575)
    >>> round(float(q * 7 * np.sin(np.radians(alpha))), 6)
    1000.0
    """
    z = validate.ball_count(balls).astype(float)
    f = validate.positive("axial_load", axial_load, "N")
    k = validate.positive("stiffness", stiffness, "N/mm^1.5")
    big_a = validate.positive("A", A, "mm")
    g = validate.finite("clearance", clearance) / 2.0
    validate.broadcast_shape({"axial_load": f, "stiffness": k, "A": big_a, "clearance": g})
    z, f, k, big_a, g = np.broadcast_arrays(z, f, k, big_a, g)
    c = big_a - g  # radial distance of the groove centres
    gap2 = g * (2.0 * big_a - g)  # A^2 - c^2: u^2 at first contact (negative under preload)
    u0 = np.sqrt(np.maximum(gap2, 0.0))
    target = f / (z * k)

    def approach(u: np.ndarray) -> np.ndarray:
        return np.maximum((u * u - gap2) / (np.hypot(c, u) + big_a), 0.0)

    def excess(u: np.ndarray) -> np.ndarray:
        return approach(u) ** 1.5 * (u / np.hypot(c, u)) - target

    lo = u0.copy()
    hi = u0 + np.cbrt(target) ** 2 + np.sqrt(np.cbrt(target) * big_a) + 1e-300
    for _ in range(2000):
        short = excess(hi) < 0
        if not short.any():
            break
        hi = np.where(short, 2.0 * hi, hi)
    for _ in range(200):  # bisection, each case stopped when 4e-16 of u wide
        open_ = hi - lo > 4e-16 * hi
        if not open_.any():
            break
        mid = 0.5 * (lo + hi)
        below = excess(mid) < 0
        lo = np.where(open_ & below, mid, lo)
        hi = np.where(open_ & ~below, mid, hi)
    u = 0.5 * (lo + hi)
    return (
        numerics.scalar_out(u),
        numerics.scalar_out(np.rad2deg(np.arctan2(u, c))),
        numerics.scalar_out(k * approach(u) ** 1.5),
    )


def solve_combined(
    balls: int,
    radial_load: Any,
    axial_load: Any = 0.0,
    *,
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
    stiffness: Any = None,
    tilt_radius: Any = None,
    moment_cross: Any = 0.0,
    contact_angle: Any = None,
) -> CombinedDistribution:
    """Equilibrium of the inner ring of a deep-groove (or, given ``contact_angle``, an
    angular-contact) ball bearing under F_r, F_a and a moment.

    Conventions and model: docs/models.md, "Combined radial, axial and moment load". Arrays
    broadcast over cases; ``balls`` is one number per call (the ball arrays of the result have
    the last axis z).

    Parameters
    ----------
    balls : int
        Number of balls z, 1 to 1000. [-]
    radial_load : array_like
        F_r >= 0, along the load line (phi = 0). [N]
    axial_load : array_like, default 0
        F_a (either sign). [N]
    ball_diameter, pitch_diameter : array_like
        D_w and d_m; the z balls must fit on the pitch circle, D_w <= d_m sin(180°/z)
        (:func:`bearingload.validate.ball_spacing`), and D_w >= 1e-3 d_m
        (:func:`bearingload.validate.ball_size_fits`), as the command line checks. [mm]
    f_i, f_o : array_like, default 0.52, 0.53
        Groove conformities r_i/D_w, r_o/D_w. [-]
    clearance : array_like, default 0
        Radial internal clearance G_r, total play; negative = preload; |G_r| < D_w/2
        (:func:`bearingload.validate.clearance_fits`, as the command line checks). [mm]
    cage_angle : array_like, default 0
        Angle of ball 1 from the load line. [°]
    moment : array_like, optional
        Moment tilting the inner ring in the plane of the load line (docs/models.md, "Conventions");
        default: the ring is free to tilt (M = 0). [N mm]
    misalignment : array_like, optional
        Imposed tilt of the inner ring in the plane of the load line, instead of a moment; 0
        holds the ring aligned (the moment that takes is reported); within ±2°
        (:data:`bearingload.validate.MISALIGNMENT_MAX`). [°]
    modulus, poisson : array_like, default 208 000 MPa, 0.3
        E [MPa] and nu [-] of balls and rings.
    stiffness : array_like, optional
        A constant ball stiffness K for every ball instead of the Hertz K(alpha_j). [N/mm^1.5]
    tilt_radius : array_like, optional
        Radius at which the tilt moves the inner groove centres axially (and the arm of the
        moment); default R_i, the radius of the inner groove curvature centres (ISO/TS 16281).
        MASTA's published tilts fit d_m/2. [mm]
    moment_cross : array_like, default 0
        Moment tilting the ring about the load line (generalised force of ``tilt_cross``);
        the ring stays free to tilt that way when a misalignment is imposed. [N mm]
    contact_angle : array_like, optional
        Design contact angle alpha_0 of an angular-contact ball bearing, 0 to 60: the groove
        centres offset so that every ball touches both grooves at alpha_0 with no load, the
        contact one-sided (a thrust F_a >= 0 only; docs/angular_contact.md). ``clearance``
        must then be 0 and ``axial`` is measured from that position; ``axial_play`` is 0.
        Default: a deep-groove bearing. [°]

    Returns
    -------
    CombinedDistribution

    Raises
    ------
    InputError
        A parameter outside its domain (overlapping balls: ``ball_diameter``, with the largest
        diameter that fits), no load at all, both a moment and a misalignment; a
        case whose equilibrium leaves a loaded ball at the groove edge (contact angle 90°).
    ConvergenceError
        No equilibrium reached (e.g. a load the balls cannot carry); the message names the
        inputs of the failing cases.

    Pure radial load, zero clearance: the contact angles stay 0 and the radial engine's answer
    comes back (peer 6305 geometry, ISO/TS 16281 example):

    >>> r = solve_combined(7, 1000.0, ball_diameter=11.5, pitch_diameter=43.5, modulus=210000.0)
    >>> round(float(r.x) * 1e3, 4), float(r.axial), float(r.contact_angles.max())
    (15.1102, 0.0, 0.0)
    """
    z = call_balls(balls)
    if moment is not None and misalignment is not None:
        raise InputError("moment", "give a moment or a misalignment, not both")
    raw = dict(
        radial_load=radial_load,
        axial_load=axial_load,
        moment=moment,
        misalignment=misalignment,
        cage_angle=cage_angle,
        modulus=modulus,
        poisson=poisson,
        moment_cross=moment_cross,
        ball_diameter=ball_diameter,
        pitch_diameter=pitch_diameter,
        f_i=f_i,
        f_o=f_o,
        clearance=clearance,
        contact_angle=contact_angle,
        stiffness=stiffness,
    )
    shape, cols, named = _inputs(raw)
    kinds = (contact_angle is not None, misalignment is not None, stiffness is None)
    solved = None
    if tilt_radius is None:  # the common path: one core call (_one_call)
        state, solved, result, r_i = _one_call(z, cols, *kinds)
        if state == _ANSWERED:
            return _answered(z, shape, cols, solved, result, r_i)
        solved = _core.answers_of(solved) if state == _SOLVED else None
    return _general(z, shape, cols, named, (kinds, tilt_radius), solved)


#: The core's CallState of :func:`_one_call` as plain numbers.
_ANSWERED, _SOLVED, _APART = (
    int(_core.CallState.ANSWERED),
    int(_core.CallState.SOLVED),
    int(_core.CallState.SET_UP_APART),
)


def _one_call(
    z: int, cols: np.ndarray, angular: bool, imposed: bool, hertz: bool
) -> tuple[int, tuple, tuple, np.ndarray]:
    """The compiled core's ``combined_call`` of the packed inputs ``cols`` (17, n): set-up,
    solve and results in one (its CallState says where it stopped; the general path,
    :func:`_general`, takes the call from there), the Hertz set-up of one case from the cache
    of :func:`hertz_setup` (and into it). Returns (the state, the solve's output arrays (the
    core's ``answers_arrays``), the results, R_i (n,))."""
    key = cols[7:13].tobytes() if hertz and cols.shape[1] == 1 else None
    known = known_setup(key)
    state, solved, result, geo, _, _, _, k0_values = _core.combined_call(
        z,
        cols,
        angular,
        imposed,
        known,
        hertz,
        _call_limits(z),
        NODE_X,
        NODE_W,
        _ring.MAX_ITERATIONS,
        _ring.FIRST_STAGE_STEPS,
    )
    if key is not None and known is _UNKNOWN and state != _APART:
        remember_setup(key, k0_values)  # (K_0 and the values, one array)
    return state, solved, result, geo[2]


def _call_limits(z: int) -> np.ndarray:
    """The limits of the core's ``combined_call`` (its docstring), of the module constants as
    they are at the call: sin(180°/z) as :func:`bearingload.validate.ball_spacing` takes it
    (the chord of the pitch circle between adjacent balls over d_m)."""
    low, high = validate.CONFORMITY_RANGE
    key: tuple[float, ...] = (z, SYMMETRY_SNAP_DEG, GEOMETRY_RATIO_MAX, ANGULAR_RATIO_MIN)
    key += (low, high, LIGHT_RATIO, ACCEPT)
    limits = _LIMITS.get(key)
    if limits is None:
        limits = np.array(key[1:6] + (float(np.sin(np.pi / z)),) + key[6:])
        _LIMITS[key] = limits
    return limits


#: The arrays of :func:`_call_limits` by their values (a few z in a session).
_LIMITS: dict[tuple[float, ...], np.ndarray] = {}


def _answered(
    z: int, shape: tuple[int, ...], cols: np.ndarray, solved: tuple, result: tuple, r_i: Any
) -> CombinedDistribution:
    """The result of a call the core answered whole (:func:`_one_call`)."""
    rows, per_ball, overflow = result
    if np.count_nonzero(overflow):
        refuse_overflow()
    loads = (cols[0], cols[1], cols[_CLEARANCE], cols[_CAGE])  # (F_r, F_a: the first rows)
    tangent, its = solved[2][0], solved[6]  # (the core's answers_arrays)
    return distribution_of(shape, z, (rows, per_ball, tangent, its), loads, r_i, None)


def _general(
    z: int,
    shape: tuple[int, ...],
    cols: np.ndarray,
    named: dict[str, Any],
    given_as: tuple[tuple[bool, bool, bool], Any],
    solved: tuple | None,
) -> CombinedDistribution:
    """:func:`solve_combined` of the packed inputs a step at a time: each refusal in its
    order, the rare paths (:func:`_equilibrium`); ``solved``: the core's solve of these cases
    (:func:`_one_call`), else solved here. ``given_as``: (whether the contact angle and the
    misalignment were given and the stiffness not), the tilt radius given (or None)."""
    (angular_given, imposed, hertz), tilt_radius = given_as
    angular = cols[_ROW["contact_angle"]] if angular_given else None
    misalignment = True if imposed else None
    fr, fa, mm, mc, tilt_deg, _, cage, e, nu, dw, dm, fi, fo, _, gr, alpha_d, k_in = cols

    def at(name: str, bad: Any, unit: str = "") -> str:  # the input's element of a bad case
        return validate.element_at(named[name], bad, shape, unit)

    geo = ring_geometry(dw, dm, fi, fo, cols[_ROW["groove"]], angular is not None, at)
    validate.ball_spacing(z, geo.D_w, geo.d_m)  # (z balls must fit on the pitch circle)
    if tilt_radius is not None:
        radius = validate.positive("tilt_radius", tilt_radius, "mm")
        geo = dataclasses.replace(geo, R_i=np.broadcast_to(radius, dw.shape).astype(float))
    _check_few_balls(z, cage, (fr, fa, mm, mc), imposed)
    if angular is not None:
        _check_one_sided_moment(z, cage, fa, (mm, mc), geo.R_i, imposed)
    curve = None
    if hertz:
        k_ref, curve = hertz_setup(geo, e, nu)
    else:
        k_ref = k_in
    problem, mirror = _problem(z, cols[:6], cage, geo, k_ref, (angular, misalignment), at)
    given = {"balls": z, "radial_load": fr, "axial_load": fa, "moment": mm, "moment_cross": mc,
             "clearance": gr, "cage_angle": cage}  # fmt: skip
    if imposed:  # the moment is then the reaction, not an input
        given["misalignment"] = tilt_deg
    with np.errstate(all="ignore"):
        vh, vl, kappa, its, end, tangent, flags = _equilibrium(problem, geo, curve, given, solved)
        answer = (vh + vl, kappa, its, _checked(problem, end, its, given), tangent[0])
        mirrored = mirror & (mc == 0)  # (the scaled tangent: made physical by distribution)
        return distribution(problem, geo, answer, shape, given, misalignment, flags, mirrored)


#: The inputs of one call of :func:`solve_combined` packed, a row each (the cases along it), as
#: the compiled core's set-up takes them: the loads (F_r, F_a, M, M_c, the misalignment and a
#: force the reference force is at least, 0 here: ``combined_problem``), the cage angle, E and
#: nu, the groove's five (D_w, d_m, f_i, f_o and the clearance or, angular contact, the design
#: contact angle: ``groove``), the clearance, the contact angle and the stiffness (0 where
#: not given).
INPUT_ROWS = (
    "radial_load",
    "axial_load",
    "moment",
    "moment_cross",
    "misalignment",
    "",
    "cage_angle",
    "modulus",
    "poisson",
    "ball_diameter",
    "pitch_diameter",
    "f_i",
    "f_o",
    "groove",
    "clearance",
    "contact_angle",
    "stiffness",
)
_ROW = {name: i for i, name in enumerate(INPUT_ROWS) if name}
_CLEARANCE, _CAGE = _ROW["clearance"], _ROW["cage_angle"]
#: The rows of one case of plain numbers by name (:func:`_plain_inputs`).
_PLAIN_ROWS = operator.itemgetter(*INPUT_ROWS)


def _inputs(raw: dict[str, Any]) -> tuple[tuple[int, ...], np.ndarray, dict[str, Any]]:
    """The inputs of :func:`solve_combined` by name (None: not given) checked and packed: (the
    case shape, the rows of :data:`INPUT_ROWS` (17, n), the inputs by name as the refusals
    name their elements). One case of plain numbers that passes every check skips the array
    machinery (:func:`_plain_inputs`); any other goes through :func:`_checked_inputs`, which
    names what it refuses."""
    cols = _plain_inputs(raw)
    if cols is not None:
        return (), cols, raw
    return _checked_inputs(raw)


#: The inputs of :func:`solve_combined` whose None means not given (0 in their rows); any
#: other None is refused by :func:`_checked_inputs`.
_OPTIONAL = ("moment", "misalignment", "contact_angle", "stiffness")
#: The types of plain numbers :func:`_plain_inputs` takes: floats, or floats and ints.
_FLOAT, _NUMBER = frozenset((float,)), frozenset((float, int))
#: The largest design contact angle taken. [°]
CONTACT_ANGLE_MAX = 60.0


class Rule(NamedTuple):
    """A rule of a solver's inputs (:func:`solve_combined`'s, a pair's): ``holds(v)`` of the
    inputs by name (``v``: plain floats of one case, or arrays; the same test, written with
    ``&`` and ``|``) is where a case passes, ``refusal(v, bad, at)`` the InputError of the cases
    ``bad`` where it does not (``at(name, bad, unit)`` names the input's element of the first).
    ``reads``: the inputs it reads, each refused first if not finite (:func:`check_rules`); a
    rule without ``holds`` only does that. ``given``: the condition (an optional input given,
    :data:`_OPTIONAL`; a pair's arrangement) without which the rule does not apply."""

    reads: tuple[str, ...]
    holds: Callable[[dict[str, Any]], Any] | None = None
    refusal: Callable[..., InputError] | None = None
    given: str | None = None


def positive_rule(name: str, unit: str, given: str | None = None) -> Rule:
    """The rule of an input [``unit``] that must be > 0 (:func:`bearingload.validate.positive`'s
    refusal)."""
    return Rule(
        (name,),
        lambda v: v[name] > 0.0,
        lambda v, bad, at: validate.not_positive(name, v[name], bad, unit),
        given,
    )


def conformity_rule(name: str) -> Rule:
    """The rule of a groove conformity ``name`` (``f_i``, ``f_o``):
    :data:`bearingload.validate.CONFORMITY_RANGE`."""
    return Rule(
        (name,),
        lambda v: validate.conforms(v[name]),
        lambda v, bad, at: validate.nonconforming(name, v[name], bad),
    )


#: F_r >= 0 N, the rule of a single bearing and a pair.
RADIAL_LOAD_RULE = Rule(
    ("radial_load",),
    lambda v: v["radial_load"] >= 0.0,
    lambda v, bad, at: validate.below("radial_load", v["radial_load"], bad, 0.0, "N"),
)


def _refuse_contact_angle(v: dict[str, Any], bad: Any, at: Callable[..., str]) -> InputError:
    return InputError(
        "contact_angle",
        f"must be from 0 to {CONTACT_ANGLE_MAX:g}°",
        element=at("contact_angle", bad, "°"),
    )


def _refuse_angular_clearance(v: dict[str, Any], bad: Any, at: Callable[..., str]) -> InputError:
    return InputError(
        "clearance",
        "must be 0 with a contact angle: the design contact angle fixes the geometry of an "
        "angular-contact bearing",
        element=at("clearance", bad, "mm"),
    )


def _refuse_angular_thrust(v: dict[str, Any], bad: Any, at: Callable[..., str]) -> InputError:
    return InputError(
        "axial_load",
        "must be >= 0 N for an angular-contact bearing: its balls take thrust one way only "
        "(a reversed load lifts every ball off its groove; mount the bearing the other way "
        "round, or give the load to its partner)",
        element=at("axial_load", bad, "N"),
    )


def _refuse_clearance(v: dict[str, Any], bad: Any, at: Callable[..., str]) -> InputError:
    g_r, d_w = validate.first_refused(bad, v["clearance"], v["ball_diameter"])
    return validate.clearance_beyond_ball(g_r, d_w, element=at("clearance", bad, "mm"))


def _refuse_ball_size(v: dict[str, Any], bad: Any, at: Callable[..., str]) -> InputError:
    d_w, d_m = validate.first_refused(bad, v["ball_diameter"], v["pitch_diameter"])
    return validate.ball_too_small(d_w, d_m, element=at("ball_diameter", bad, "mm"))


#: D_w >= 1e-3 d_m (validate.ball_size_fits), a rule of the cases of a single bearing and a pair.
BALL_SIZE_RULE = Rule(
    ("ball_diameter", "pitch_diameter"),
    lambda v: validate.ball_size_fits(v["ball_diameter"], v["pitch_diameter"]),
    _refuse_ball_size,
)

#: The rules of the inputs of :func:`solve_combined`, each input's in the order they are
#: checked (the first refused is named): of one input each, then of the cases (several inputs
#: broadcast together). :func:`_checked_inputs` checks them one at a time, naming the first
#: refused; :func:`_plain_inputs` all at once on one case of plain numbers.
_INPUT_RULES = (
    RADIAL_LOAD_RULE,
    Rule(("axial_load",)),
    Rule(
        ("contact_angle",),
        lambda v: (0.0 <= v["contact_angle"]) & (v["contact_angle"] <= CONTACT_ANGLE_MAX),
        _refuse_contact_angle,
        "contact_angle",
    ),
    Rule(
        ("clearance",), lambda v: v["clearance"] == 0.0, _refuse_angular_clearance, "contact_angle"
    ),
    Rule(
        ("axial_load",), lambda v: v["axial_load"] >= 0.0, _refuse_angular_thrust, "contact_angle"
    ),
    Rule(("moment", "moment_cross")),
    Rule(
        ("misalignment",),
        lambda v: validate.misalignment_fits(v["misalignment"]),
        lambda v, bad, at: validate.misalignment_beyond(v["misalignment"], bad),
    ),
    Rule(("cage_angle",)),
    positive_rule("modulus", "MPa"),
    Rule(("poisson",)),
    positive_rule("stiffness", "N/mm^1.5", "stiffness"),
    Rule(("ball_diameter", "pitch_diameter", "clearance")),
    conformity_rule("f_i"),
    conformity_rule("f_o"),
)
_CASE_RULES = (
    BALL_SIZE_RULE,
    Rule(
        ("clearance", "ball_diameter"),
        lambda v: validate.clearance_fits(v["clearance"], v["ball_diameter"]),
        _refuse_clearance,
    ),
)


def gate(rules: tuple[Rule, ...], given: set[str | None]) -> tuple[Callable[..., Any], ...]:
    """The tests of the ``rules`` that apply where the conditions ``given`` hold (None among
    them: the rules of every case), in their order: a case of plain floats passing each passes
    the rules (a fast path's gate)."""
    return tuple(r.holds for r in rules if r.holds is not None and r.given in given)


#: The gates of :data:`_INPUT_RULES` and :data:`_CASE_RULES` by (a contact angle given, a
#: stiffness given).
_GATES = {
    (a, k): gate(
        _INPUT_RULES + _CASE_RULES,
        {None, *(("contact_angle",) if a else ()), *(("stiffness",) if k else ())},
    )
    for a in (False, True)
    for k in (False, True)
}


def _plain_inputs(raw: dict[str, Any]) -> np.ndarray | None:
    """The rows (17, 1) of one case whose inputs are all plain numbers (``float`` or ``int``)
    passing every rule (:data:`_INPUT_RULES`, :data:`_CASE_RULES`), the cage angle taken mod
    360°; None for any other (:func:`_checked_inputs` then names what it refuses)."""
    v = raw.copy()
    for name in _OPTIONAL:
        if v[name] is None:
            v[name] = 0.0
    if not _FLOAT.issuperset(map(type, v.values())):  # (a bool is neither)
        if not _NUMBER.issuperset(map(type, v.values())):
            return None
        try:
            v = {name: float(x) for name, x in v.items()}
        except OverflowError:
            return None
    if not math.isfinite(sum(v.values())):  # a NaN or infinity among them (or a sum beyond)
        return None
    angular = raw["contact_angle"] is not None
    for holds in _GATES[angular, raw["stiffness"] is not None]:
        if not holds(v):
            return None
    v["cage_angle"] = validate.reduced_angle(v["cage_angle"])  # (as validate.cage_angle)
    v[""], v["groove"] = 0.0, v["contact_angle" if angular else "clearance"]
    return np.array(_PLAIN_ROWS(v)).reshape(-1, 1)


def _checked_inputs(raw: dict[str, Any]) -> tuple[tuple[int, ...], np.ndarray, dict[str, Any]]:
    """:func:`_inputs` of any inputs: each rule of :data:`_INPUT_RULES` checked in its order
    (:func:`check_rules`), the inputs broadcast together (:func:`_cases`), the rules of
    :data:`_CASE_RULES` checked on the cases; packed."""
    given = {name: raw[name] is not None for name in _OPTIONAL}
    conditions = {None, *(name for name in _OPTIONAL if given[name])}
    v = check_rules(
        _INPUT_RULES, conditions, lambda name: 0.0 if given.get(name) is False else raw[name]
    )
    v["cage_angle"] = np.asarray(validate.reduced_angle(v["cage_angle"]))
    if not given["contact_angle"]:
        v["contact_angle"] = np.zeros(())
    named = {name: v[name] for name in raw if name in v}  # (in the order of solve_combined's)
    shape, flat = _cases(named)
    cols = np.zeros((len(INPUT_ROWS), flat[0].size))
    for name, col in zip(named, flat, strict=True):
        cols[_ROW[name]] = col
    cases = dict(zip(named, cols[[_ROW[name] for name in named]], strict=True))

    def at(name: str, bad: Any, unit: str = "") -> str:  # the input's element of a bad case
        return validate.element_at(named[name], bad, shape, unit)

    check_cases(_CASE_RULES, cases, at)
    cols[_ROW["groove"]] = cols[_ROW["contact_angle" if given["contact_angle"] else "clearance"]]
    return shape, cols, named


def check_rules(
    rules: tuple[Rule, ...], given: set[str | None], value_of: Callable[[str], Any]
) -> dict[str, np.ndarray]:
    """Each of the ``rules`` that applies where the conditions ``given`` hold (:func:`gate`),
    in its order: every input it reads (``value_of(name)``) refused first if not finite
    (:func:`bearingload.validate.finite`), then its test; the first refused raises its
    InputError, naming the input's element. Returns the inputs read, as float arrays."""
    v: dict[str, Any] = {}

    def own(name: str, bad: Any, unit: str = "") -> str:  # the element of one input's rule
        return validate.element(v[name], bad, unit)

    for rule in rules:
        if rule.given not in given:
            continue
        for name in rule.reads:
            if name not in v:
                v[name] = validate.finite(name, value_of(name))
        if rule.holds is not None and rule.refusal is not None:
            bad = np.logical_not(rule.holds(v))
            if bad.any():
                raise rule.refusal(v, bad, own)
    return v


def check_cases(rules: tuple[Rule, ...], cases: dict[str, Any], at: Callable[..., str]) -> None:
    """Refuse the first of the ``rules`` the inputs ``cases`` (arrays broadcast together) break;
    ``at`` names the input's element of the first case refused."""
    for rule in rules:
        if rule.holds is not None and rule.refusal is not None:
            bad = np.logical_not(rule.holds(cases))
            if bad.any():
                raise rule.refusal(cases, bad, at)


#: Positions per revolution at which :func:`load_zone` first looks for the zone's ends, beside
#: the balls' own: an arc of the zone narrower than their spacing (0.5°) that holds no ball
#: is not seen. [-]
ZONE_GRID = 720


def load_zone(r: CombinedDistribution, big_a: Any, one_sided: bool = False) -> Any:
    """The load zone half-angle of every case of the static solution ``r``: half the total
    angle of the positions where a ball would carry load (the arcs summed where a moment makes
    two), by the kinematics of the model (docs/models.md)
    (the balls' own): loaded where ``rho > 0`` and ``|(rho, u')| > A``. Under a radial load
    alone it is the radial engine's ``arccos(G_r / (2 |(x, y)|))``; 180 where every position
    is loaded (a thrust, a preload). ``big_a`` = A = (f_i + f_o - 1) D_w [mm]; ``one_sided``:
    an angular-contact bearing (``u' = max(u, 0)``, its geometry from the design angle).

    The ends of the zone are found on :data:`ZONE_GRID` positions and the balls' own, then to
    the last digits by bisection, :data:`ZONE_BLOCK` cases at a time; an arc narrower than
    0.5° that holds no ball is not seen. [°]"""
    shape = np.shape(r.q_max)
    case = [
        np.broadcast_to(np.asarray(v, dtype=float), shape).reshape(-1, 1)
        for v in (
            r.x,
            r.y,
            r.axial,
            r.tilt,
            r.tilt_cross,
            r.tilt_radius,
            r.clearance,
            r.free_contact_angle,
            big_a,
        )
    ]
    x, y, axial, tilt, tilt_c, lever, g_r, alpha0, a = case
    alpha0 = np.deg2rad(alpha0)
    rho0 = np.where(one_sided, a * np.cos(alpha0), a - g_r / 2.0)
    u0 = axial + np.where(one_sided, a * np.sin(alpha0), 0.0)
    t, tc = lever * np.deg2rad(tilt), lever * np.deg2rad(tilt_c)
    balls = np.mod(
        np.deg2rad(np.asarray(r.ball_angles, dtype=float).reshape(len(x), -1)), 2.0 * np.pi
    )
    zone = np.empty(len(x))
    for at in range(0, len(x), ZONE_BLOCK):
        block = slice(at, at + ZONE_BLOCK)
        kinematics = (rho0[block], x[block], y[block], u0[block], t[block], tc[block], a[block])
        zone[block] = _zone_length(kinematics, balls[block], one_sided)
    out = np.rad2deg(zone / 2.0).reshape(shape)
    return out[()] if out.ndim == 0 else out


#: Cases :func:`load_zone` treats at once (its positions: about 730 per case). [-]
ZONE_BLOCK = 256


def _zone_length(kinematics: tuple[np.ndarray, ...], balls: np.ndarray, one_sided: bool) -> Any:
    """The angle [rad] of the loaded arc of each case of a block (:func:`load_zone`)."""
    rho0, x, y, u0, t, tc, a = kinematics

    def h(phi: np.ndarray, i: Any = slice(None)) -> np.ndarray:  # > 0: a ball there is loaded
        c, s = np.cos(phi), np.sin(phi)
        rho = rho0[i] + x[i] * c + y[i] * s
        u = u0[i] + t[i] * c + tc[i] * s
        u = np.maximum(u, 0.0) if one_sided else u
        return np.minimum(np.hypot(np.maximum(rho, 0.0), u) - a[i], rho)

    n = len(x)
    grid = np.broadcast_to(np.linspace(0.0, 2.0 * np.pi, ZONE_GRID, endpoint=False), (n, ZONE_GRID))
    phi = np.sort(np.concatenate([grid, balls], axis=1), axis=1)
    nxt = np.concatenate([phi[:, 1:], phi[:, :1] + 2.0 * np.pi], axis=1)
    on = h(phi) > 0
    on_next = np.roll(on, -1, axis=1)
    rows, cols = np.nonzero(on != on_next)
    lo, hi = phi[rows, cols], nxt[rows, cols]
    start_on = on[rows, cols]
    for _ in range(60):  # the end of the zone between the two positions, to the last digits
        mid = 0.5 * (lo + hi)
        same = (h(mid[:, None], rows)[:, 0] > 0) == start_on
        lo, hi = np.where(same, mid, lo), np.where(same, hi, mid)
    end = 0.5 * (lo + hi)
    length = np.where(on & on_next, nxt - phi, 0.0).sum(axis=1)
    np.add.at(length, rows, np.where(start_on, end - phi[rows, cols], nxt[rows, cols] - end))
    return length


def _problem(
    z: int,
    loads: np.ndarray,
    cage: np.ndarray,
    geo: _Geometry,
    k_ref: np.ndarray,
    given: tuple[Any, Any],
    at: Callable[..., str] = _no_element,
) -> tuple[Problem, np.ndarray]:
    """The scaled problem of the cases (the compiled core's ``combined_problem``: the largest
    load, the scale, the ball directions, the symmetry locks, the forces) and which cases are
    mirrored about the load line; the loads (6, n) (F_r, F_a, M, M_c, misalignment [°], 0: the
    rows of :data:`INPUT_ROWS`) refused as
    :func:`reference_force`, :func:`check_scale` and :func:`check_angular_scale` state.
    ``given``: the contact angle and the misalignment as given (None: not given); ``at``
    names the element of a refused case (:func:`ring_geometry`)."""
    angular, imposed = (v is not None for v in given)
    n = cage.shape[0]
    lengths = np.array((geo.A, geo.g, geo.R_i), dtype=float)
    limits = np.array([SYMMETRY_SNAP_DEG, GEOMETRY_RATIO_MAX, ANGULAR_RATIO_MIN])
    k_ref = np.ascontiguousarray(k_ref, dtype=float)
    status, c, s, mirror, held, f, out = _core.combined_problem(
        z, loads, cage, lengths, k_ref, angular, imposed, limits
    )
    if np.count_nonzero(status):
        _refuse_loads(loads, geo, k_ref, angular, at, status)
    fixed = np.zeros((n, 5), dtype=bool)
    fixed[:, 3] = imposed
    one_sided = np.zeros(n, dtype=bool)
    one_sided[:] = angular
    # out: the scale, the lengths (a_hat, pre, gap, b_hi, b_lo, t_imp), F
    scaled = (out[0], out[1:7], f, held, fixed, out[7], k_ref)
    return Problem(z, c, s, *scaled, one_sided), mirror


def _refuse_loads(
    loads: np.ndarray,
    geo: _Geometry,
    k_ref: np.ndarray,
    angular: bool,
    at: Callable[..., str],
    status: np.ndarray,
) -> None:
    """InputError on the loads the core's ``combined_problem`` flagged (``status``: no load, a
    moment over its lever beyond the largest number, loads too small or, angular contact, too
    large); the core's flags decide, these checks word the refusal."""
    fr, fa, mm, mc = loads[:4]
    f_ref = reference_force(fr, fa, mm, mc, geo.R_i)
    if (f_ref <= 0).any():
        raise InputError(
            "radial_load",
            "give a radial load, an axial load or a moment",
            element=at("radial_load", f_ref <= 0, "N"),
        )
    sizes = lambda: load_sizes(fr, fa, mm, mc, geo.R_i)  # noqa: E731
    check_scale(f_ref, k_ref, geo.A, angular, sizes, status == _core.SetupStatus.TOO_LIGHT, at)
    if angular:
        named = {"radial_load": fr, "axial_load": fa, "moment": np.hypot(mm, mc) / geo.R_i}
        heavy = status == _core.SetupStatus.TOO_HEAVY
        check_angular_scale(f_ref, k_ref, geo.A, named, heavy, at, (mm, mc))


def call_balls(balls: Any) -> int:
    """The ball count z of one call of a solver: one whole number from 1 to 1000
    (:func:`bearingload.validate.ball_count` refuses any other)."""
    if type(balls) is int and 1 <= balls <= 1000:  # a plain number: no array machinery
        return balls
    z = int(validate.ball_count(balls, maximum=1000).reshape(-1)[0])
    if np.size(balls) != 1:
        raise InputError("balls", "must be one number per call (group the cases by z)")
    return z


def _cases(named: dict[str, np.ndarray]) -> tuple[tuple[int, ...], list[np.ndarray]]:
    """The case shape the named inputs broadcast to (:func:`bearingload.validate.
    broadcast_shape` names those that do not fit) and each input flat over the cases; one case
    (every input a number) as arrays of one element, without numpy's broadcasting."""
    values = list(named.values())
    if all(v.ndim == 0 for v in values):
        return (), [v.reshape(1) for v in values]
    validate.broadcast_shape(named)
    arrays = np.broadcast_arrays(*values)
    return arrays[0].shape, [a.ravel() for a in arrays]


def _equilibrium(
    p: Problem, geo: _Geometry, curve: np.ndarray | None, given: dict, solved: Any = None
) -> tuple:
    """Every case solved (:func:`_thrust_retry`), a tilt the loads do not determine taken at
    its least (:func:`_least_norm_tilt`): as :func:`_solve_with_stiffness`, and which cases'
    tilts are undetermined and which thrusts neglected. A case whose stiffness updates run out
    raises ConvergenceError naming its inputs (``given``). ``solved``: the core's outputs of
    the first solve where the caller has them (:func:`_one_call`)."""
    try:
        got = _solve_with_stiffness(p, geo, curve) if solved is None else _solved(solved)
        neglected = np.zeros(p.f.shape[0], dtype=bool)
        res = got[4].checks[0]  # (the residual with the imposed components held)
        if np.count_nonzero(res <= ACCEPT) < res.size:
            got = _thrust_retry(p, geo, curve, got)  # (each retry needs an unbalanced case)
            neglected = _neglect_thrust(p, geo, curve, got)
            _near_symmetric(p, geo, curve, got, given["cage_angle"])
        vh, vl, kappa, its, end, tangent = got
    except ConvergenceError as exc:
        rows = np.asarray(exc.cases["rows"])
        raise ConvergenceError(
            exc.solver,
            exc.iterations,
            exc.residual,
            _described(given, rows),
            units=INPUT_UNITS,
            rows=rows,
        ) from None
    undetermined = np.zeros(vh.shape[0], dtype=bool)
    if np.count_nonzero(tangent[1][1]):  # (no case whose Hessian may be flat: none to move)
        vh, vl, end, undetermined = _least_norm_tilt(p, (vh, vl), kappa, end, tangent[1])
    return vh, vl, kappa, its, end, tangent, (undetermined, neglected)


#: A free direction of the ring along which its stiffness (the frozen-K Hessian of the
#: potential, scaled) is below FLAT times its largest is one the loads do not determine. [-]
FLAT = 1e-12


def _least_norm_tilt(
    p: Problem,
    v: tuple[np.ndarray, np.ndarray],
    kappa: np.ndarray,
    end: _ring.Point,
    held: tuple[np.ndarray, np.ndarray],
) -> tuple[np.ndarray, np.ndarray, _ring.Point, np.ndarray]:
    """The answers whose tilt the loads do not determine, moved to the least tilt of those that
    balance them; and which cases those are (n,) bool. ``held``: the core's Hessian of the
    balls that hold the ring (n, 5, 5) and whether it may have a null direction (n,).

    The valley of tilts is the null direction of the potential's Hessian from the balls
    carrying more than the tolerance (1e-12 of the largest load; a ball below it bounds the
    valley as a loose one); its ends are where the first ball changes state along it (to first
    order, within 1e-6 of the range). The tilt returned is the least of the valley, kept only
    where the equilibrium there is balanced to the tolerance (docs/angular_contact.md, "A tilt
    the loads do not determine")."""
    vh, vl = v
    holding, maybe = held
    undetermined = np.zeros(vh.shape[0], dtype=bool)
    if not maybe.any():
        return vh, vl, end, undetermined
    rows = np.flatnonzero(maybe & np.any(~p.locked[:, 3:], axis=1))
    if not rows.size:
        return vh, vl, end, undetermined
    free = ~p.locked[rows]
    hess = np.where(free[:, :, None] & free[:, None, :], holding[rows], 0.0)
    hess[:, range(5), range(5)] += np.where(free, 0.0, np.abs(hess).max(axis=(1, 2))[:, None])
    lam, vec = np.linalg.eigh(hess)
    flat = (lam[:, 0] <= FLAT * lam[:, -1]) & np.any(np.abs(vec[:, 3:, 0]) > 0.5, axis=1)
    undetermined[rows] = flat
    lam_of, vec_of = (
        dict(zip(rows.tolist(), lam, strict=True)),
        dict(zip(rows.tolist(), vec, strict=True)),
    )
    for i in np.flatnonzero(undetermined).tolist():
        lam_i, vec_i = lam_of[i], vec_of[i]
        holds_above = float(TOLERANCE)  # the load above which a ball holds the ring
        if np.count_nonzero(lam_i <= FLAT * lam_i[-1]) > 1:
            lam_t, vec_t = _touching_valley(p, i, end, kappa[i])
            if np.count_nonzero(lam_t <= FLAT * lam_t[-1]) == 1:
                lam_i, vec_i, holds_above = lam_t, vec_t, 0.0
        d = vec_i[:, 0] * ~p.locked[i]
        along = _least_tilt_step(p, i, end, vh[i] + vl[i], d, holds_above)
        _move_along(p, i, (vh, vl), kappa, end, (lam_i, vec_i, along))
    return vh, vl, end, undetermined


def _touching_valley(
    p: Problem, i: int, end: _ring.Point, kappa: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The eigenvalues and eigenvectors of case ``i``'s Hessian of the potential (the
    stiffness frozen, the held components decoupled) from every ball that touches (the core's
    ``holding`` with every load): where the balls carrying more than the tolerance leave more
    than one direction free, those below it hold the ring as much as it matters
    (docs/angular_contact.md)."""
    b, lo, c, s = end.b, end.lo, p.c[i], p.s[i]
    ca, sa = lo.ca[i], lo.sa[i]
    touch = lo.q[i] > 0.0
    turns = (b.rho[i] > 0) & (~p.one_sided[i] | (b.u[i] > 0))
    w1 = np.where(touch, 1.5 * (1.0 + kappa) * lo.root[i], 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        w2 = np.where(touch & turns, lo.q[i] / b.d[i], 0.0)
    g = np.stack([ca * c, ca * s, sa, sa * c, sa * s])
    h = np.stack([-sa * c, -sa * s, ca, ca * c, ca * s])
    hess = (g * w1) @ g.T + (h * w2) @ h.T
    free = ~p.locked[i]
    hess = np.where(free[:, None] & free[None, :], hess, 0.0)
    hess[range(5), range(5)] += np.where(free, 0.0, np.abs(hess).max())
    return np.linalg.eigh(hess)


#: Bisections of the move along a valley whose first-order end is not balanced. [-]
VALLEY_BISECTIONS = 40


def _move_along(
    p: Problem,
    i: int,
    v: tuple[np.ndarray, np.ndarray],
    kappa: np.ndarray,
    end: _ring.Point,
    valley: tuple[np.ndarray, np.ndarray, float],
) -> None:
    """Case ``i`` moved by ``s`` along the valley's direction (``valley`` = the Hessian's
    eigenvalues, eigenvectors and ``s``) or, where the equilibrium there is not balanced, by
    the furthest fraction of ``s`` that is (bisection, VALLEY_BISECTIONS halvings: 1e-12 of
    the move), in place in ``v`` and ``end``: the valley is curved and its ends are
    first-order estimates (docs/angular_contact.md)."""
    lam, vec, s = valley
    one = np.array([i])
    got = _valley_point(p, i, v, kappa, (lam, vec, s))
    if got is None:
        inside, outside = 0.0, 1.0
        for _ in range(VALLEY_BISECTIONS):
            mid = 0.5 * (inside + outside)
            trial = _valley_point(p, i, v, kappa, (lam, vec, mid * s))
            if trial is None:
                outside = mid
            else:
                inside, got = mid, trial
    if got is not None:
        v[0][one], v[1][one] = got[0], got[1]
        end.put(one, got[2])


def _valley_point(
    p: Problem,
    i: int,
    v: tuple[np.ndarray, np.ndarray],
    kappa: np.ndarray,
    valley: tuple[np.ndarray, np.ndarray, float],
) -> tuple | None:
    """Case ``i`` at ``v`` moved by ``s`` along the valley's direction, then by Newton steps
    across the valley (not along it): (vh, vl, point) of one row, or None where the equilibrium
    there is not balanced to the tolerance within 4 steps."""
    lam, vec, s = valley
    one = np.array([i])
    sub = p.take(one)
    wh, wl = v[0][one], v[1][one]
    step = s * vec[:, 0] * ~p.locked[i]
    for _ in range(4):
        hi, lo = _ring.two_sum(wh, step[None, :])
        wh, wl = _ring.fast_two_sum(hi, lo + wl)
        moved = _ring.Point.at(sub, kappa[one], wh, wl)
        if moved.res[0] <= TOLERANCE:
            return wh, wl, moved
        left = np.where(sub.locked[0], 0.0, moved.gen[0] - sub.f[0])
        across = vec[:, 1:]
        step = -across @ ((across.T @ left) / lam[1:])
    return None


def _least_tilt_step(
    p: Problem,
    i: int,
    end: _ring.Point,
    v: np.ndarray,
    d: np.ndarray,
    holding: float = float(TOLERANCE),
) -> float:
    """The move along the valley direction ``d`` (scaled, of case ``i`` at ``v``) to the least
    tilt within the valley: its ends where a ball that does not hold the ring (its load at
    most ``holding``) would touch (to first order from its approach, which may be a rounding
    above 0) or a loaded one-sided ball at the groove bottom (u <= 0) would leave it; 0 where
    the valley has no end both ways."""
    c, s = p.c[i], p.s[i]
    dr = d[0] * c + d[1] * s
    du = d[2] + d[3] * c + d[4] * s
    b, lo = end.b, end.lo
    delta = p.pre[i] + b.eps[i]
    rate = lo.ca[i] * dr + lo.sa[i] * du
    holds = lo.q[i] > holding
    value = np.where(holds, b.u[i], delta)  # each ball's quantity kept <= 0
    speed = np.where(holds, du, rate)
    bound = ~holds | (p.one_sided[i] & (b.u[i] <= 0))
    with np.errstate(divide="ignore", invalid="ignore"):
        reach = np.where(bound & (speed != 0), -value / speed, np.nan)
    upper = np.min(reach[bound & (speed > 0)], initial=np.inf)
    lower = np.max(reach[bound & (speed < 0)], initial=-np.inf)
    if not (np.isfinite(upper) and np.isfinite(lower)):
        return 0.0
    tilt = d[3:] @ d[3:]
    best = -(v[3:] @ d[3:]) / tilt if tilt > 0 else 0.0
    margin = 1e-6 * (upper - lower)
    return float(np.clip(best, lower + margin, upper - margin))


def angular_geometry(dw: Any, dm: Any, fi: Any, fo: Any, alpha_deg: np.ndarray) -> _Geometry:
    """The deep-groove geometry whose free contact angle is the design angle alpha_0 [°]:
    ``G_r = 2A (1 - cos alpha_0) = 4A sin^2(alpha_0/2)``, alpha_0 kept as given."""
    return ring_geometry(dw, dm, fi, fo, alpha_deg, angular=True)


def _check_one_sided_moment(
    z: int,
    cage: np.ndarray,
    fa: np.ndarray,
    moments: tuple[np.ndarray, np.ndarray],
    radius: np.ndarray,
    imposed: bool,
) -> None:
    """Refuse a moment a single angular-contact bearing cannot hold with its ring free to tilt
    (``imposed``: the tilt in the plane of the load imposed, its moment a reaction, the cross
    tilt still free).

    Every ball pushes the ring axially one way only, ``Q_j sin(alpha_j) >= 0``, at the arm
    ``R_i (cos phi_j, sin phi_j)``: the thrust and the moments it makes, ``(F_a, M/R_i,
    M_c/R_i)``, lie in the cone of the vectors ``(1, cos phi_j, sin phi_j)``. An equilibrium
    needs ``(M, M_c)/(F_a R_i)`` strictly inside the regular z-gon of the ball positions: on
    every edge, its component along the edge's normal (at ``phi_j + 180°/z``) below
    ``cos(180°/z)``. Outside, the balls on the far side would lift off and nothing holds the
    tilt. With the tilt imposed, some reaction M balances any ``M_c`` whose ratio lies strictly
    within the z-gon's extent across the load line, ``min_j sin phi_j < M_c/(F_a R_i) <
    max_j sin phi_j``; beyond it the cross tilt is held by nothing.
    """
    mm, mc = moments
    if imposed:
        _check_one_sided_cross(z, cage, fa, mc, radius)
        return
    tilting = (mm != 0) | (mc != 0)
    if not tilting.any():
        return
    half = math.pi / z
    normals = np.deg2rad(cage)[:, None] + 2.0 * math.pi * np.arange(z) / z + half
    with np.errstate(divide="ignore", invalid="ignore"):
        reach = (mm[:, None] * np.cos(normals) + mc[:, None] * np.sin(normals)).max(axis=1)
        bad = tilting & ~(reach < math.cos(half) * fa * radius)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        limit = math.cos(half) * fa[i] * radius[i]
        raise InputError(
            "moment" if mm[i] != 0 else "moment_cross",
            f"an angular-contact bearing alone holds a moment only below about F_a R_i "
            f"cos(180°/z) = {limit:.4g} N mm here (F_a = {fa[i]:.4g} N, R_i = "
            f"{radius[i]:.4g} mm): its balls push the ring one way only, the far ones would "
            "lift off; raise the axial load or impose the tilt (misalignment)",
        )


def _check_one_sided_cross(
    z: int, cage: np.ndarray, fa: np.ndarray, mc: np.ndarray, radius: np.ndarray
) -> None:
    """Refuse a moment across the load line that a single angular-contact bearing with its tilt
    imposed cannot hold (:func:`_check_one_sided_moment`)."""
    if not mc.any():
        return
    sines = np.sin(np.deg2rad(cage)[:, None] + 2.0 * math.pi * np.arange(z) / z)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = mc / (fa * radius)
        bad = (mc != 0) & ~((ratio < sines.max(axis=1)) & (ratio > sines.min(axis=1)))
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        limit = float(np.max(np.abs(sines[i]))) * fa[i] * radius[i]
        raise InputError(
            "moment_cross",
            f"with the tilt imposed, an angular-contact bearing alone holds a moment across the "
            f"load line only below about {limit:.4g} N mm here (F_a = {fa[i]:.4g} N, R_i = "
            f"{radius[i]:.4g} mm): its balls push the ring one way only, nothing holds the "
            "cross tilt beyond; raise the axial load",
        )


def _check_few_balls(z: int, cage: np.ndarray, loads: tuple[np.ndarray, ...], locked: bool) -> None:
    """Refuse the loads that 1 or 2 balls cannot hold with the ring free to tilt, and a radial
    load (``loads`` = F_r, F_a, M, M_c) with no ball on the load line.

    One ball carries one force: a free tilt turns the ring about it under any axial load or
    moment, and nothing holds a moment about the ball's own line. Two balls (at the cage angle c
    and c + 180°) hold a moment only about the axis across their line: the component
    ``M sin c - M_c cos c`` about the line itself turns the ring freely, and with the tilt
    imposed so does ``M_c`` when the balls sit on the load line.
    """
    if z >= 3:
        return
    fr, fa, mm, mc = loads
    if np.any((np.mod(cage, 360.0 / z) != 0) & (fr > 0)):
        raise InputError("cage_angle", CAGE_OFF_LINE)
    c = np.deg2rad(cage)
    size = np.maximum(np.hypot(mm, mc), 1e-300)
    if z == 1:
        free = np.abs(mc) > 0 if locked else (fa != 0) | (mm != 0) | (mc != 0)
    elif locked:
        free = (np.abs(np.sin(c)) < 1e-12) & (mc != 0)
    else:
        free = np.abs(mm * np.sin(c) - mc * np.cos(c)) > 1e-9 * size
    if np.any(free):
        what = "an axial load or a moment" if z == 1 and not locked else "this moment"
        raise InputError(
            "balls",
            f"{z} ball{'s' if z > 1 else ''} cannot hold the ring under {what}: nothing stops it "
            "turning about the balls' line (no equilibrium exists); give at least 3 balls"
            + ("" if locked else ", or impose the tilt with a misalignment (0: aligned)"),
        )


#: Largest groove-geometry length A over the one-ball approach (F/K)^(2/3) the combined solver
#: takes: beyond it a load is a vanishing fraction of what moves the ring in its groove (before
#: the ball approaches were computed in double-double, at 7e7, 9 of 60 loadings of a 6313 stalled
#: at a residual of 1e-8; 4 of 1200 near 2e7 too). Since then every loading of the random
#: campaign (tests/campaign_combined.py: 10^4 cases, loads down to this limit, clearances up to
#: 2A) and of the tests near the limit converges. [-]
GEOMETRY_RATIO_MAX = 2e7


def reference_force(
    fr: np.ndarray, fa: np.ndarray, mm: np.ndarray, mc: np.ndarray, lever: np.ndarray
) -> np.ndarray:
    """The largest of F_r, |F_a| and the moments over the tilt lever, per case. [N]"""
    with np.errstate(over="ignore"):  # a moment over a lever of 1e-300 mm: refused
        f_ref = np.maximum(np.maximum(fr, np.abs(fa)), np.hypot(mm, mc) / lever)
    if not np.isfinite(f_ref).all():
        raise InputError(
            "moment" if np.any(mm) else "moment_cross",
            "over the tilt lever (tilt_radius) it is a force beyond the largest number",
        )
    return f_ref


def check_scale(
    f_ref: np.ndarray,
    k_ref: np.ndarray,
    big_a: np.ndarray,
    angular: bool = False,
    sizes: Callable[[], dict[str, np.ndarray]] | None = None,
    flagged: Any = False,
    at: Callable[..., str] = _no_element,
) -> None:
    """Refuse loads so small against the groove geometry that the scaled problem loses its
    digits (the radial solver, without an axial load, takes any ratio; an angular-contact
    bearing, ``angular``, has no other solver: the message gives the smallest load taken).
    ``sizes`` (called on a refusal: :func:`load_sizes`, by parameter [N]) name the parameter of
    the largest load of the first case refused (the first named among equals); without them,
    ``radial_load``; ``at`` names its element (:func:`ring_geometry`: ``radial_load[3] =
    1e-09 N``). ``flagged``: the cases the compiled core judged too light (its scale by
    libm's pow may differ from numpy's in the last bit at the limit: the core decides)."""
    with np.errstate(over="ignore", divide="ignore"):
        scale = (f_ref / k_ref) ** (2.0 / 3.0)
    if not (scale <= 1e100).all():  # the radial engine's bound of the one-ball approach
        raise InputError(
            "radial_load",
            f"the loads and the ball stiffness give a one-ball approach (F/K)^(2/3) = "
            f"{float(np.max(scale)):.3g} mm, beyond 1e100 mm; check the units of the loads, "
            "the modulus and the tilt lever",
        )
    a = big_a if np.shape(big_a) == scale.shape else np.broadcast_to(big_a, scale.shape)
    bad = (a / scale > GEOMETRY_RATIO_MAX) | flagged
    if bad.any():  # the first case refused: its loads, its least load, its element
        i = int(np.argmax(bad))
        f_min = float(np.broadcast_to(k_ref * (a / GEOMETRY_RATIO_MAX) ** 1.5, bad.shape)[i])
        step = 10.0 ** (math.floor(math.log10(f_min)) - 1)  # shown to 2 digits, rounded up
        f_min = math.ceil(f_min / step * (1 - 1e-12)) * step
        name = _largest_load(None if sizes is None else sizes(), i)
        raise InputError(
            name,
            f"the loads are too small for the combined solver (the largest of F_r, |F_a| and "
            f"M/R_i is {float(f_ref[i]):.3g} N; it takes at least {f_min:.2g} N for this "
            "bearing)",
            way_out=ANGULAR_NO_OTHER_SOLVER if angular else RADIAL_TAKES_ANY_LOAD,
            reason=TOO_LIGHT_ANGULAR if angular else TOO_LIGHT,
            element=at(name, bad, INPUT_UNITS[name]),
        )


def load_sizes(
    fr: np.ndarray, fa: np.ndarray, mm: np.ndarray, mc: np.ndarray, lever: np.ndarray
) -> dict[str, np.ndarray]:
    """The applied loads as forces by parameter: F_r, |F_a| and the moments over the tilt lever
    (per case, flat). [N]"""
    shape = np.shape(fr)
    return {"radial_load": fr, "axial_load": np.abs(fa),
            "moment": np.abs(mm) / np.broadcast_to(lever, shape),
            "moment_cross": np.abs(mc) / np.broadcast_to(lever, shape)}  # fmt: skip


def _largest_load(sizes: dict[str, np.ndarray] | None, i: int) -> str:
    """The parameter of the largest of ``sizes`` in case ``i`` (the first named among equals)."""
    if sizes is None:
        return "radial_load"
    return max(sizes, key=lambda name: float(np.reshape(sizes[name], -1)[i]))


#: The reason of the refusal of loads too small for the combined solver (or the ball dynamics):
#: the plan, which can solve the case by another engine, replaces its way out.
TOO_LIGHT = "too_light"
#: The reason of the same refusal for an angular-contact bearing, which no other solver takes.
TOO_LIGHT_ANGULAR = "too_light_angular"

#: The way out of loads too small for the combined solver (the library's: the radial solver).
RADIAL_TAKES_ANY_LOAD = "the radial solver, without an axial load, takes any load"

#: Its end for an angular-contact bearing, which only the combined solver solves (the radial
#: solver has no contact angle): the smallest load it takes is the advice.
ANGULAR_NO_OTHER_SOLVER = (
    "an angular-contact bearing is solved by this solver only (at any speed, quasi-static or "
    "not): give at least that load"
)


#: Smallest groove-centre distance A over the one-ball approach (F/K)^(2/3) an angular-contact
#: case is solved at. Measured (12 balls, 10-55°, F_a/F_r 0 to 1000): below 2e-5 every case
#: with a radial load either drives a ball to 90° (refused) or does not converge (4e-6), pure
#: thrust converges down to 2e-9; 1e-4 keeps a margin. It is a load of 10^7 C_0r and more.
ANGULAR_RATIO_MIN = 1e-4


#: The words of a load of :func:`check_angular_scale`'s ``sizes`` in its refusal.
_SIZE_WORDS = {
    "radial_load": "F_r",
    "axial_load": "F_a",
    "moment": "M/R_i",
    "preload": "the preload",
}


def check_angular_scale(
    f_ref: np.ndarray,
    k_ref: np.ndarray,
    big_a: np.ndarray,
    sizes: dict[str, np.ndarray],
    flagged: Any = False,
    at: Callable[..., str] = _no_element,
    moments: tuple[np.ndarray, np.ndarray] | None = None,
) -> None:
    """Refuse loads so large against an angular-contact bearing's groove geometry A that its
    one-sided equilibrium is not solved reliably (see :data:`ANGULAR_RATIO_MIN`): a single
    bearing's and each of a pair's. ``sizes``: the loads as forces by parameter (flat, of
    :data:`_SIZE_WORDS`; ``moment`` the size of both moments), the largest of the first case
    refused named, the larger of ``moments`` (M, M_c, flat) where it is the moment;
    ``flagged``: the cases the compiled core judged so, ``at`` names the element (as
    :func:`check_scale`)."""
    a = big_a if np.shape(big_a) == f_ref.shape else np.broadcast_to(big_a, f_ref.shape)
    with np.errstate(over="ignore", divide="ignore"):
        bad = (a / (f_ref / k_ref) ** (2.0 / 3.0) < ANGULAR_RATIO_MIN) | flagged
    if bad.any():
        i = int(np.argmax(bad))
        f_max = float(k_ref[i] * (a[i] / ANGULAR_RATIO_MIN) ** 1.5)
        name = _largest_load(sizes, i)
        if name == "moment" and moments is not None:
            mm, mc = (abs(float(np.reshape(m, -1)[i])) for m in moments)
            name = "moment_cross" if mc > mm else name
        *most, last = (_SIZE_WORDS[k] for k in sizes)
        raise InputError(
            name,
            f"too large for the angular-contact model: the largest of {', '.join(most)} and "
            f"{last} is {float(f_ref[i]):.4g} N; above {f_max:.3g} N on this bearing (a ball "
            f"approach of {1 / ANGULAR_RATIO_MIN:.0e} times the groove-centre distance A = "
            f"{float(a[i]):.4g} mm, the contact angles next to 90°, the groove edge) the "
            "one-sided equilibrium is not solved reliably and the loads are refused",
            element=at(name, bad, INPUT_UNITS[name]),
        )


def ball_directions(z: int, cage: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """cos and sin of every ball's angle (n, z), and which cases are symmetric about the load
    line (n,): a cage at 0 or half a pitch, within the radial engine's snap (rounding); the
    compiled core's ``directions``.

    The directions of a symmetric case are exactly mirrored (the angle folded onto [0, 180°]
    before its cosine is taken, as the radial engine does): cos(phi_j) and cos(-phi_j) computed
    apart differ in their last bit, which at a clearance of millions of elastic approaches
    unbalances the mirror balls' loads by 1e-5, against a y held at 0 by the symmetry.
    """
    return _core.directions(z, np.ascontiguousarray(cage, dtype=float), SYMMETRY_SNAP_DEG)


def symmetry_locks(
    z: int, mirror: np.ndarray, loads: tuple[np.ndarray, ...], t_imp: np.ndarray, imposed: bool
) -> tuple[np.ndarray, np.ndarray]:
    """Which of (x, y, a, t, t_c) each case holds: (held (n, 5), imposed (n, 5)).

    The tilt when a misalignment is given (at any value, 0 included); and the components that
    are 0 by a symmetry of the case, exactly rather than to rounding: ``y`` and ``t_c`` when the
    balls are symmetric about the load line (cage at 0 or half a pitch, within the radial
    engine's snap) and no moment acts across it; ``a``, ``t``, ``t_c`` without an axial load,
    moment or tilt (the mirror image across the mid-plane); ``x``, ``y``, ``t``, ``t_c`` without
    a radial load, moment or tilt (the ring's z-fold symmetry, z >= 2). The potential is convex
    and has the symmetry, so a minimum with these components 0 exists. The rule is the compiled
    core's (``symmetry_locks``, also of :func:`solve_combined`'s set-up).
    """
    rows = np.array((*loads, t_imp), dtype=float)
    held = _core.locks(z, np.ascontiguousarray(mirror, dtype=np.uint8), rows, imposed)
    fixed = np.zeros(held.shape, dtype=bool)
    fixed[:, 3] = imposed
    return held, fixed


#: An angular-contact case whose groove-centre distance A exceeds LIGHT_RATIO times its one-ball
#: approach (F/K)^(2/3) starts from the answer of the same case at a heavier load, the ratio
#: STAGE times smaller (but not below HEAVY_RATIO), itself so started while above LIGHT_RATIO:
#: a continuation in the load (:func:`_light_start`). [-]
LIGHT_RATIO = 1e3
HEAVY_RATIO = 1e2
STAGE = 3.0


def _light_start(
    p: Problem, geo: _Geometry, curve: np.ndarray | None
) -> tuple[np.ndarray, np.ndarray]:
    """The light angular-contact cases (ratio A/(F/K)^(2/3) above LIGHT_RATIO) and their starts
    (rows, (rows, 5)): the answer of the same case (the same load directions, misalignment and
    geometry) at a load STAGE^1.5 times heavier (the ratio STAGE times smaller, not below
    HEAVY_RATIO), in the scaled units of ``p``; that case is started the same way while its
    ratio is above LIGHT_RATIO. A case whose heavier one does not converge is left out (it keeps
    the standard start). The start is the heavier answer as it is (rounded, the far balls'
    approaches would be lost). Why (the standard start a large part of A from the answer of a
    light case): docs/angular_contact.md, "Light loads"."""
    if not np.count_nonzero(p.one_sided):
        return np.zeros(0, dtype=np.int64), np.zeros((0, 5))
    rows = np.flatnonzero(p.one_sided & (p.a_hat > LIGHT_RATIO))
    if not rows.size:
        return rows, np.zeros((0, 5))
    sub = _geo_take(geo, rows)
    ratio = np.maximum(p.a_hat[rows] / STAGE, HEAVY_RATIO)
    f_ref = p.k_ref[rows] * (sub.A / ratio) ** 1.5
    heavy = Problem.make(
        p.z, (p.c[rows], p.s[rows]), (sub.A, sub.g), f=p.f[rows],
        t_imp=p.t_imp[rows] * p.scale[rows], locked=p.locked[rows], imposed=p.imposed[rows],
        f_ref=f_ref, k_ref=p.k_ref[rows], one_sided=p.one_sided[rows],
    )  # fmt: skip
    own = None if curve is None else curve[rows]
    vh, vl, *_, failed = _solve_with_stiffness(heavy, sub, own, strict=False)
    v = (vh + vl) * (heavy.scale / p.scale[rows])[:, None]
    kept = ~failed  # (a start only: where the heavier case fails, the standard one stays)
    return rows[kept], np.where(p.locked[rows], 0.0, v)[kept]


#: An angular-contact case under F_r and a thrust F_a below THRUST_RATIO F_r whose first
#: attempt does not converge is solved again by a continuation in the thrust
#: (:func:`_thrust_retry`): from F_a = THRUST_RATIO F_r down to its own, each stage dividing
#: the thrust by THRUST_STAGE, a stage that does not converge retried from the last one that
#: did at the square root of its factor, down to a factor of THRUST_STAGE_MIN. [-]
THRUST_RATIO = 0.1
THRUST_STAGE = 3.0
THRUST_STAGE_MIN = 1.01
#: Stages of one case's continuation (those that converge and those that do not) before it is
#: given up (its first answer, and ConvergenceError, kept). [-]
THRUST_STAGES_MAX = 200


def _thrust_retry(p: Problem, geo: _Geometry, curve: np.ndarray | None, got: tuple) -> tuple:
    """``got``, :func:`_solve_with_stiffness` of ``p``, with the angular-contact cases that did not
    converge (residual above ACCEPT), under F_r and 0 < F_a < THRUST_RATIO F_r, solved
    again by :func:`_thrust_path`, each alone; a case keeps its first answer (and so its
    ConvergenceError) where that does not converge either. Only such cases are touched: a case
    that converges at once keeps its bits, and a retried case's answer is a function of its own
    inputs (the same alone or in any batch). Why (a near-singular tilt with two or three balls
    loaded): docs/angular_contact.md, "Small thrusts at normal loads"."""
    vh, vl, kappa, total, end, tangent = got
    if not p.one_sided.any():
        return vh, vl, kappa, total, end, tangent
    res = _ring.residual_of(p.f, end.gen, end.size, p.imposed)
    f0, f2 = p.f[:, 0], p.f[:, 2]
    rows = np.flatnonzero(
        ~(res <= ACCEPT) & p.one_sided & (f0 > 0) & (f2 > 0) & (f2 < THRUST_RATIO * f0)
        & ~p.locked[:, 2]
    )  # fmt: skip
    for i in rows.tolist():
        one = np.array([i])
        own = None if curve is None else curve[one]
        again = _thrust_path(p.take(one), _geo_take(geo, one), own)
        if again is not None:
            _put_row((vh, vl, kappa, total, end, tangent), i, again)
    return vh, vl, kappa, total, end, tangent


def _put_row(got: tuple, i: int, again: tuple) -> None:
    """Case ``i`` of the answers ``got`` (as :func:`_solve_with_stiffness` returns them,
    updated in place) replaced by ``again``, the answer of that case solved alone; its
    iterations added to those already spent."""
    vh, vl, kappa, total, end, tangent = got
    vh[i], vl[i], kappa[i], total[i] = again[0][0], again[1][0], again[2][0], total[i] + again[3][0]
    end.put(np.array([i]), again[4])
    tangent[0][i] = again[5][0][0]
    tangent[1][0][i], tangent[1][1][i] = again[5][1][0][0], again[5][1][1][0]


def _solve_row(q: Problem, geo: _Geometry, curve: np.ndarray | None, i: int) -> tuple:
    """Case ``i``'s problem ``q`` (one row, changed by the caller) solved alone with its own
    geometry and stiffness curve (:func:`_solve_with_stiffness`)."""
    one = np.array([i])
    own = None if curve is None else curve[one]
    return _solve_with_stiffness(q, _geo_take(geo, one), own)


#: A thrust below this share of the largest applied load (the equilibrium's tolerance) may be
#: beyond what the ring's axial position resolves: a 6205 at G_r = 0.2 mm with one ball
#: loaded under F_r = 1 kN balances 1e-11 N of thrust, not 1e-12 N. A case the solver cannot
#: balance with such a thrust is solved as its neighbour with this share of the largest load
#: as its thrust (the same sign), the difference left as its error: the limit of a thrust
#: going to 0, not the case without one (a thrust, however small, pushes the ring across its
#: axial play). [-]
NEGLIGIBLE_THRUST = 1e-12


def _neglect_thrust(p: Problem, geo: _Geometry, curve: np.ndarray | None, got: tuple) -> Any:
    """The cases of ``got`` (as :func:`_thrust_retry` returns them, updated in place) left
    unbalanced with a thrust below :data:`NEGLIGIBLE_THRUST` of their largest load, solved
    each alone with that share as its thrust (``p.f`` then holds it); which cases those are
    (n,) bool."""
    neglected = np.zeros(p.f.shape[0], dtype=bool)
    f2 = p.f[:, 2]
    small = (f2 != 0) & (np.abs(f2) < NEGLIGIBLE_THRUST) & ~p.locked[:, 2]
    if not small.any():
        return neglected
    end = got[4]
    res = _ring.residual_of(p.f, end.gen, end.size, p.imposed)
    for i in np.flatnonzero(small & ~(res <= ACCEPT)).tolist():
        q = p.take(np.array([i]))
        q.f[:, 2] = np.copysign(NEGLIGIBLE_THRUST, f2[i])
        _put_row(got, i, _solve_row(q, geo, curve, i))
        p.f[i, 2] = q.f[0, 2]
        neglected[i] = True
    return neglected


#: A cage angle this close to a symmetric one (a ball on the load line, or the load between two
#: balls) is answered as symmetric where the solver cannot balance it otherwise: at tiny loads
#: (F_r = 0.01 N on a 6205 at G_r = 20 µm) the direction across the load is nearly free within
#: 1e-12° of symmetry and the Newton stalls. The ball angles differ from the symmetric ones by
#: less than this. [°]
NEAR_SYMMETRIC_DEG = 1e-9


def _near_symmetric(
    p: Problem, geo: _Geometry, curve: np.ndarray | None, got: tuple, cage: np.ndarray
) -> None:
    """The cases of ``got`` (updated in place) left unbalanced with a cage within
    :data:`NEAR_SYMMETRIC_DEG` of a symmetric position and no moment across the load line,
    solved each alone with the balls at the symmetric position (``p`` then holds it)."""
    end = got[4]
    res = _ring.residual_of(p.f, end.gen, end.size, p.imposed)
    rows = np.flatnonzero(~(res <= ACCEPT) & (p.f[:, 4] == 0) & ~p.imposed.any(axis=1))
    for i in rows.tolist():
        one = np.array([i])
        c, s, mirror = _core.directions(p.z, np.ascontiguousarray(cage[one]), NEAR_SYMMETRIC_DEG)
        if not mirror[0]:
            continue
        q = dataclasses.replace(p.take(one), c=c, s=s)
        q.locked[0, 1] = q.locked[0, 4] = True  # y and the tilt across: 0 by the symmetry
        _put_row(got, i, _solve_row(q, geo, curve, i))
        p.c[i], p.s[i], p.locked[i] = c[0], s[0], q.locked[0]


def _thrust_path(q: Problem, geo: _Geometry, curve: np.ndarray | None) -> tuple | None:
    """One case (``q`` of one row) solved by the continuation in the thrust of
    :func:`_thrust_retry`: the answer (as :func:`_solve_with_stiffness`, the iterations of
    every stage summed) at its own F_a, or None where a stage at THRUST_RATIO F_r, or one whose
    factor fell below THRUST_STAGE_MIN, does not converge, or after THRUST_STAGES_MAX stages.
    The thrust of a stage is the case's own times exp(e), e from log(THRUST_RATIO F_r / F_a)
    down to exactly 0."""
    want = q.f[0, 2]
    e_next = math.log(THRUST_RATIO * q.f[0, 0] / want)
    e_done, step = math.inf, math.log(THRUST_STAGE)
    v0, its = None, 0
    for _ in range(THRUST_STAGES_MAX):
        f = q.f.copy()
        f[0, 2] = want * math.exp(e_next)
        stage = dataclasses.replace(q, f=f)
        try:
            got = _solve_with_stiffness(stage, geo, curve, v0)
            ok = bool(
                _ring.residual_of(stage.f, got[4].gen, got[4].size, stage.imposed)[0] <= ACCEPT
            )
            its += int(got[3][0])
        except ConvergenceError:
            ok = False
        if ok and e_next == 0.0:
            return got[0], got[1], got[2], np.array([its]), got[4], got[5]
        if ok:
            e_done, v0 = e_next, np.where(q.locked, 0.0, got[0] + got[1])
        elif math.isinf(e_done) or step < math.log(THRUST_STAGE_MIN):
            return None
        else:
            step /= 2.0
        e_next = max(e_done - step, 0.0)
    return None


def _geo_take(geo: _Geometry, rows: np.ndarray) -> _Geometry:
    """The cases ``rows`` of a geometry."""
    return _Geometry(*(getattr(geo, f.name)[rows] for f in dataclasses.fields(geo)))


#: Chebyshev nodes of the stiffness curve (first kind) on [-1, 1], their barycentric weights
#: and cos(alpha) at each. [-]
NODES = 24
NODE_THETA = (2.0 * np.arange(NODES) + 1.0) * np.pi / (2.0 * NODES)
NODE_X = np.cos(NODE_THETA)
NODE_W = np.where(np.arange(NODES) % 2 == 0, 1.0, -1.0) * np.sin(NODE_THETA)
NODE_COS = (NODE_X + 1.0) / 2.0
#: Distinct geometries whose Hertz set-up the speed model (:mod:`bearingload.models.high_speed`)
#: and :func:`hertz_setup` of one case keep across calls, the oldest dropped first. [-]
SETUP_CACHE_SIZE = 256
#: :func:`hertz_setup` of the last one-case calls, by the bits of their six parameters in the
#: order of :data:`INPUT_ROWS` (E, nu, D_w, d_m, f_i, f_o): K_0 and the curve's values
#: (1 + NODES), the values the core gives that geometry every time, kept so a call on a known
#: bearing skips them.
_SETUP_CACHE: dict[bytes, np.ndarray] = {}
#: The Hertz set-up of :func:`_one_call` where the cache does not hold it.
_UNKNOWN = np.zeros(0)


def known_setup(key: bytes | None) -> np.ndarray:
    """The Hertz set-up (K_0 and the curve's values) the cache holds for one case's geometry,
    ``key`` the bits of its six parameters in the order of :data:`INPUT_ROWS`; empty where it
    holds none (or ``key`` is None). The pair's one core call takes it as this one's does."""
    return _SETUP_CACHE.get(key, _UNKNOWN) if key is not None else _UNKNOWN


def remember_setup(key: bytes, known: np.ndarray) -> None:
    """Keep one geometry's Hertz set-up (K_0 and the curve's values) in the cache, the
    oldest dropped first beyond SETUP_CACHE_SIZE."""
    _SETUP_CACHE[key] = known
    trim_cache(_SETUP_CACHE)


def trim_cache(cache: dict) -> None:
    """Drop the oldest entries of a cache beyond SETUP_CACHE_SIZE. Threads may share it: one
    may drop the entry another is dropping, or change the cache while another looks for its
    oldest (a KeyError, or the RuntimeError of a dict changed during its iteration, raised
    from solve_combined): then it looks again."""
    while len(cache) > SETUP_CACHE_SIZE:
        try:
            del cache[next(iter(cache))]
        except (KeyError, RuntimeError, StopIteration):  # (another thread was first)
            continue


def hertz_setup(geo: _Geometry, e: np.ndarray, nu: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per case, K_0 = K(alpha = 0) [N/mm^1.5] (n,) and the stiffness curve: the divided
    differences ``D(c) = (K(c)/K_0 - 1)/(c - 1)`` at the nodes NODE_X (n, NODES) of the
    interpolant of K(alpha)/K_0 - 1 in cos(alpha) (docs/models.md, "The stiffness curve";
    evaluated in the compiled core, ``curve_kappa``), in the compiled core
    (``hertz_curves``: K_0 the scalar path of :func:`bearingload.contact.hertz.ball_stiffness`,
    its bits, the nodes within rounding of it; a case of the geometry before takes its values). A
    geometry the core cannot set up goes through the vectorised path of ``ball_stiffness``,
    which refuses it with the reason (or, where only the core's Newton did not settle, sets it
    up)."""
    params = np.array((e, nu, geo.D_w, geo.d_m, geo.f_i, geo.f_o), dtype=float)  # (6, n)
    key = params.tobytes() if params.shape[1] == 1 else None  # (one case: its six in order)
    known = known_setup(key)
    if known.size:
        return known[:1].copy(), known[None, 1:].copy()
    params = params[[2, 3, 4, 5, 0, 1]].T.copy()  # (the core's order: D_w, d_m, f_i, f_o, E, nu)
    k0, values, bad = _core.hertz_curves(params, NODE_X)
    for i in np.flatnonzero(bad).tolist():
        from bearingload.contact.hertz import ball_stiffness

        dw, dm, fi, fo, ee, nn = params[i]
        k = ball_stiffness(dw, dm / np.append(NODE_COS, 1.0), fi, fo, ee, nn).ball
        k0[i], values[i] = k[-1], (k[:-1] / k[-1] - 1.0) / (NODE_COS - 1.0)
    if key is not None:
        remember_setup(key, np.concatenate((k0, values[0])))
    return k0, values


def _solve_with_stiffness(
    p: Problem,
    geo: _Geometry,
    curve: np.ndarray | None,
    v0: np.ndarray | None = None,
    strict: bool = True,
) -> tuple[Any, ...]:
    """Minimise with frozen ball stiffnesses, update them to the contact angles, repeat until
    the update leaves the equilibrium (to the tolerance), each case in the compiled core
    (:mod:`bearingload.models._core`). Returns (v_hi, v_lo, kappa, iterations, the point there:
    the balls at the position, the loads with kappa; the tangent of the ring forces there and
    the Hessian of the balls that hold the ring, scaled, (n, 5, 5) each). ``v0``: the start
    (scaled units of ``p``); default the core's standard start, light angular-contact cases
    :func:`_light_start`. ``strict``: a case whose stiffness updates ran out raises
    ConvergenceError naming its row (``rows``); else the cases that failed (n,) bool come last,
    each case's fate its own."""
    n = p.f.shape[0]
    given = np.zeros(n, dtype=np.uint8)
    start0 = np.zeros((n, 5))
    if v0 is None:
        rows, light = _light_start(p, geo, curve)
        if rows.size:
            given[rows], start0[rows] = 1, light
    else:
        given[:], start0[:] = 1, v0
    values = np.zeros((n, 0)) if curve is None else curve
    vh, vl, kappa, total, status, at, tangent, holding, checks = _core.solve(
        p.c,
        p.s,
        p.lengths,
        p.f,
        p.locked.view(np.uint8),
        p.imposed.view(np.uint8),
        p.one_sided.view(np.uint8),
        values,
        NODE_X,
        NODE_W,
        start0,
        given,
        max_iterations=_ring.MAX_ITERATIONS,
        first_stage_steps=_ring.FIRST_STAGE_STEPS,
    )
    return _solved((vh, vl, kappa, total, status, at, tangent, holding, checks), strict)


def _solved(out: tuple, strict: bool = True) -> tuple[Any, ...]:
    """:func:`_solve_with_stiffness`'s answer from the outputs of the core's ``solve`` (or of
    its ``combined_call``, the same)."""
    vh, vl, kappa, total, status, at, tangent, holding, checks = out
    balls, gen, size, res = at
    if strict and np.count_nonzero(status):  # by their rows: the caller names their inputs
        failed = status != _ring.OK
        raise ConvergenceError(
            "combined-load ball stiffness update",
            MAX_STIFFNESS_UPDATES,
            float(np.max(res[failed])),
            {"rows": np.flatnonzero(failed)},
        )
    point = _ring.Point(balls, gen, size, res, checks)
    if not strict:
        return vh, vl, kappa, total, point, (tangent, holding), status != _ring.OK
    return vh, vl, kappa, total, point, (tangent, holding)


def _checked(p: Problem, end: _ring.Point, its: np.ndarray, given: dict) -> tuple[Any, ...]:
    """The balls and their loads (``end.block``) and the forces at the answer;
    ConvergenceError where the residual (held components but an imposed tilt included) is
    above ACCEPT, InputError where a loaded ball sits at the groove edge (its groove centres
    crossed, or its contact angle 90° to the digits of a double). ``end``: the point at the
    answer (:func:`_solve_with_stiffness`), with the core's checks of it where known (else
    measured here)."""
    res, near_edge = (None, None) if end.checks is None else end.checks
    if res is None:
        res = _ring.residual_of(p.f, end.gen, end.size, p.imposed)
    bad = ~(res <= ACCEPT)
    if np.count_nonzero(bad):
        known = res[bad][~np.isnan(res[bad])]  # nanmax of all-NaN would warn on the terminal
        raise ConvergenceError(
            "combined-load ring equilibrium",
            int(its[bad].max()),
            float(known.max()) if known.size else math.nan,
            _described(given, bad),
            units=INPUT_UNITS,
            rows=np.flatnonzero(bad),
        )
    if near_edge is None or np.count_nonzero(near_edge):
        _check_edge(end, given, p.one_sided)
    return end.block, end.gen


def _check_edge(end: _ring.Point, given: dict, one_sided: np.ndarray) -> None:
    """InputError where a loaded ball of ``end`` sits at the groove edge: crossed groove
    centres, or a contact angle that rounds to 90° (a minimum may sit at the edge: there the
    potential's curvature across the groove ends). ``one_sided`` (n,): the angular-contact
    cases."""
    b, lo = end.b, end.lo
    near = (lo.root > 0) & ((b.rho <= 0) | (lo.ca < 1e-8))  # (elsewhere below 90° - 5e-7°)
    if near.any():
        edge = near & ((b.rho <= 0) | (np.rad2deg(np.arctan2(np.abs(lo.sa), lo.ca)) >= 90.0))
        if edge.any():
            case, ball = (int(i[0]) for i in np.nonzero(edge))
            _refuse_edge(case, ball, given, bool(one_sided[case]))


def _described(given: dict, rows: np.ndarray) -> dict:
    """The inputs of the cases ``rows``, for a message: without a moment none of them has (or,
    under an imposed misalignment, that is a reaction)."""
    out = {k: v[rows] if np.ndim(v) else v for k, v in given.items()}
    for key in ("moment", "moment_cross"):
        if "misalignment" in out and key == "moment" or not np.any(out[key]):
            del out[key]
    return out


#: The unit of every input a solver names in a refusal or a failure (one table for the
#: combined, pair and speed solvers).
INPUT_UNITS = {
    "radial_load": "N",
    "axial_load": "N",
    "moment": "N mm",
    "moment_cross": "N mm",
    "misalignment": "°",
    "clearance": "mm",
    "cage_angle": "°",
    "preload": "N",
    "contact_angle": "°",
    "width": "mm",
    "speed": "rpm",
}


def _refuse_edge(case: int, ball: int, given: dict, angular: bool = False) -> None:
    """InputError: ball ``ball`` of case ``case`` would carry load past the groove edge.
    ``angular``: an angular-contact case, whose clearance is not an input (0: its design
    contact angle fixes the geometry), so neither named nor advised."""
    from bearingload.errors import format_cases

    one = _described(given, np.array([case]))
    if angular:
        del one["clearance"]
    if one["axial_load"] != 0:
        name = "axial_load"
    else:
        name = next(
            (k for k in ("misalignment", "moment", "moment_cross") if k in one),
            "radial_load" if angular else "clearance",
        )
    clearance = "" if angular else " and the clearance"
    if "misalignment" in one:
        way = "lower the axial load, moment or tilt" + ("" if angular else ", or the clearance")
    else:  # a free ring's tilt may seat the balls under more thrust as well as under less
        way = (
            ("change" if angular else "lower the clearance, change")
            + " the axial load or moment (the inner ring is free to tilt: more thrust may seat "
            "the balls, as less may), or impose the tilt with a misalignment (0: aligned)"
        )
    raise InputError(
        name,
        f"the loads{clearance} drive ball {ball + 1} to a contact angle of 90°, the "
        "edge of its groove (the centres of its two grooves cross): it would ride over the "
        f"groove shoulder, which the model does not describe; {way} "
        f"({format_cases(one, INPUT_UNITS)})",
    )


def refuse_overflow() -> None:
    """InputError: a lever of 1e300 mm, whose square times K overflows."""
    raise InputError("tilt_radius", "is so large that the tilting stiffness (lever^2 K) overflows")


def distribution(
    p: Problem,
    geo: _Geometry,
    answer: tuple[Any, ...],
    shape: tuple[int, ...],
    given: dict,
    misalignment: Any,
    flags: tuple[np.ndarray, np.ndarray] | None,
    mirrored: np.ndarray,
) -> CombinedDistribution:
    """Back to physical units and the case shape; ``flags``: the cases whose tilt the loads do
    not determine and those whose negligible thrust was left out (None: none). The stiffness
    of ``answer`` is the core's scaled tangent, made physical here in place in the same loop
    as the other results (the core's ``physical_case``: in a case ``mirrored`` about the load
    line the couplings of (x, axial, tilt) with (y, tilt_cross) exactly 0)."""
    v, kappa, its, (block, gen), tangent = answer
    z = kappa.shape[1]
    case_in = np.array(  # (the case rows of the core's combined_result: its docstring)
        (p.t_imp, p.scale, geo.R_i, geo.alpha0, geo.A, p.one_sided, p.f_ref)
        + (given["moment"], given["cage_angle"], p.pre, p.k_ref),
        dtype=float,
    )
    rows, per_ball, overflow = _core.combined_result(
        np.ascontiguousarray(v),
        case_in,
        np.ascontiguousarray(gen),
        block,
        np.ascontiguousarray(kappa),
        misalignment is not None,
        tangent,
        mirrored.view(np.uint8),
    )
    if np.count_nonzero(overflow):
        refuse_overflow()
    loads = (given["radial_load"], given["axial_load"], given["clearance"], given["cage_angle"])
    return distribution_of(shape, z, (rows, per_ball, tangent, its), loads, geo.R_i, flags)


def distribution_of(
    shape: tuple[int, ...],
    z: int,
    answer: tuple[np.ndarray, ...],
    loads: tuple[np.ndarray, ...],
    r_i: np.ndarray,
    flags: tuple[np.ndarray, np.ndarray] | None,
) -> CombinedDistribution:
    """The result of :func:`distribution` from the core's results ``answer`` (the case rows
    (8, n), the ball rows (5, n, z), the physical stiffness (n, 5, 5), the iterations (n,)),
    the inputs ``loads`` (F_r, F_a, G_r, the cage angle, (n,) each), R_i and the flags."""
    rows, per_ball, tangent, its = answer
    undetermined, neglected = (None, None) if flags is None else flags
    # one case of plain numbers: Python floats, as numerics.scalar_out gives them
    cases = rows.reshape((8,) + shape) if shape else rows[:, 0].tolist()
    x, y, axial, tilt, tilt_cross, alpha0, play, moment = cases
    phi, alpha, approach, k_ball, q = per_ball.reshape((5,) + shape + (z,))
    fr, fa, gr, cage = loads

    def case(a: np.ndarray) -> Any:
        return np.asarray(a).reshape(shape) if shape else a.item()

    return CombinedDistribution(
        balls=z,
        load=case(fr),
        axial_load=case(fa),
        moment=moment,
        clearance=case(gr),
        cage_angle=case(cage),
        free_contact_angle=alpha0,
        axial_play=play,
        x=x,
        y=y,
        axial=axial,
        tilt=tilt,
        tilt_cross=tilt_cross,
        ball_angles=phi,
        contact_angles=alpha,
        ball_approaches=approach,
        ball_stiffnesses=k_ball,
        ball_loads=q,
        tilt_radius=case(r_i),
        stiffness_matrix=tangent.reshape(shape + (5, 5)),
        iterations=case(its),
        tilt_undetermined=np.zeros(shape, dtype=bool)
        if undetermined is None
        else undetermined.reshape(shape),
        thrust_neglected=np.zeros(shape, dtype=bool)
        if neglected is None
        else neglected.reshape(shape),
    )
