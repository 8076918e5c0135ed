"""Combined radial, axial and moment load of a deep-groove ball bearing: the 3-D ring equilibrium.

The inner ring moves as a rigid body: radially by ``(x, y)`` (``x`` along the radial load),
axially by ``a`` and tilts by ``theta`` about the axis across the load line and ``theta_c``
about the load line itself. The outer ring is fixed. This is the model of ISO/TS 16281:2008
(its equations for the ball deflection, the operating contact angle and the equilibrium of the
inner ring) and of Jones/Harris (Harris & Kotzalas, *Rolling Bearing Analysis*, 5th ed., ch. 8).

Geometry (deep-groove ball bearing, one row)
--------------------------------------------
* Groove radii ``r_i = f_i D_w``, ``r_o = f_o D_w``; the distance of the two groove curvature
  centres when a ball touches both grooves is ``A = (f_i + f_o - 1) D_w``.
* At centred rings the centres of ball ``j``'s grooves lie ``A - G_r/2`` apart radially and
  0 apart axially (``G_r`` the radial internal clearance, total play). Taking up the play
  axially gives the free contact angle ``alpha_0 = arccos(1 - G_r/(2 A))`` and the axial play
  ``2 A sin(alpha_0)`` (ISO/TS 16281; Harris & Kotzalas). Negative ``G_r`` = preload:
  ``alpha_0 = 0``, no axial play.
* The inner groove centre of ball ``j`` (at ``phi_j`` from the load line) lies at radius
  ``R_i = d_m/2 + (r_i - D_w/2) cos(alpha_0)``. Small-tilt kinematics (ISO/TS 16281): its
  radial separation from the outer groove centre is ``rho_j = A - G_r/2 + x cos phi_j +
  y sin phi_j``, its axial one ``u_j = a + R_i (theta cos phi_j + theta_c sin phi_j)``; the
  ball is compressed by ``delta_j = sqrt(rho_j^2 + u_j^2) - A`` and its contact angle is
  ``alpha_j = atan2(u_j, rho_j)``.
* Ball load ``Q_j = K(alpha_j) max(delta_j, 0)^1.5`` with ``K(alpha)`` the exact Hertz stiffness
  of both contacts in series (:func:`bearingload.contact.hertz.ball_stiffness`) with the
  contact-angle-dependent curvatures: ``1/R_x = 2/D_w +- 2 cos(alpha)/(d_m -+ D_w cos(alpha))``,
  i.e. the zero-angle curvatures of a bearing of pitch diameter ``d_m / cos(alpha)``.

Conventions
-----------
* The axial displacement ``a`` is measured from the centred rings: it includes half the axial
  play, as MASTA reports it (the ISO/TS 16281 equations measure it from the ring that has taken
  up the play; the two differ by ``A sin(alpha_0)``).
* Positive ``F_a`` pushes the inner ring towards +axial. The moment ``M`` [N mm] is the
  generalised force of ``theta``: positive ``M`` pushes the load-line side of the inner ring
  towards +axial. Without a moment and without a misalignment the ring is free to tilt (``M =
  0``), as ISO/TS 16281 and MASTA treat a single bearing; an imposed misalignment fixes
  ``theta`` (and ``theta_c = 0``) and the moment it needs is reported.
* Which ring rotates does not enter the equilibrium (no centrifugal or gyroscopic terms); it
  enters the life, :mod:`bearingload.bearings.iso16281`.
* Misalignment and the gaps: to second order in the tilt, ``delta_j`` loses
  ``R_i^2 theta^2 cos^2(phi_j) / (2 A) = R_i^2 theta^2 (1 + cos 2 phi_j) / (4 A)`` of gap, a
  constant part plus a ``cos 2 phi_j`` part, the structure of the gap law with misalignment in
  the abstract on clearance and vibration (eqs. 3a-4); the exact square root is used.

Numerics. With ``K`` frozen per ball, the equilibrium is the minimum of the convex potential
``sum K_j/2.5 max(delta_j, 0)^2.5 - F_r x - F_a a - M theta`` (``delta_j`` is a norm of an
affine function minus a constant, so convex). Lengths are scaled by ``(F/K)^(2/3)`` with ``F``
the load size; Newton with an Armijo line search minimises it, started from the radial engine's
solution and the axial closed form; then ``K_j`` is updated to the new contact angles and the
minimisation repeated until the stiffnesses stop changing. Cases that do not reach the tolerance
raise :class:`~bearingload.errors.ConvergenceError`.
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

#: Relative equilibrium residual every case is driven below (or to rounding). [-]
TOLERANCE = 1e-12
#: Largest relative residual accepted at the end; above it ConvergenceError. [-]
ACCEPT = 1e-8
#: Newton iterations per stiffness update (a load near the smallest accepted with a clearance of
#: about A takes up to some hundreds: about 25 more per decade of lower load); outer updates.
MAX_ITERATIONS = 2000
MAX_STIFFNESS_UPDATES = 40


@dataclass(frozen=True)
class CombinedDistribution:
    """Solution of the combined-load equilibrium; arrays of the case shape, ball arrays (..., z).

    Attributes
    ----------
    balls : int
        Number of balls z. [-]
    radial_load, axial_load : ndarray
        F_r and F_a. [N]
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
        Operating contact angle alpha_j of every ball. [°]
    ball_approaches : ndarray (..., z)
        delta_j (negative: the gap left). [mm]
    ball_stiffnesses : ndarray (..., z)
        K(alpha_j), both contacts in series. [N/mm^1.5]
    ball_loads : ndarray (..., z)
        Q_j. [N]
    iterations : ndarray of int
        Newton iterations summed over the stiffness updates. [-]
    """

    balls: int
    radial_load: np.ndarray
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
    iterations: np.ndarray

    @property
    def q_max(self) -> np.ndarray:
        """Load of the most heavily loaded ball. [N]"""
        return self.ball_loads.max(axis=-1)

    @property
    def loaded_balls(self) -> np.ndarray:
        """Number of balls carrying load. [-]"""
        return (self.ball_loads > 0).sum(axis=-1)


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
        Radial internal clearance G_r (negative = preload), below 2 A. [mm]

    Returns
    -------
    (A [mm], alpha_0 [°], axial play [mm])

    >>> A, a0, sa = groove_geometry(11.5, 43.5, 0.52, 0.53, 0.01)
    >>> round(float(A), 4), round(float(a0), 4), round(float(sa), 5)
    (0.575, 7.5614, 0.15133)
    """
    geo = _geometry(ball_diameter, pitch_diameter, f_i, f_o, clearance)
    play = 2.0 * geo.A * np.sin(geo.alpha0)
    return _out(geo.A), _out(np.rad2deg(geo.alpha0)), _out(play)


def _geometry(dw: Any, dm: Any, fi: Any, fo: Any, clearance: Any) -> _Geometry:
    dw = validate.positive("ball_diameter", dw, "mm")
    dm = validate.positive("pitch_diameter", dm, "mm")
    fi = validate.finite("f_i", fi)
    fo = validate.finite("f_o", fo)
    g = validate.finite("clearance", clearance) / 2.0
    if np.any(dw >= dm):
        raise InputError("ball_diameter", "must be smaller than the pitch diameter")
    for name, f in (("f_i", fi), ("f_o", fo)):
        if np.any(f <= 0.5):
            raise InputError(name, "must be greater than 0.5 (groove radius above ball radius)")
    A = (fi + fo - 1.0) * dw
    if np.any(g >= A):
        raise InputError(
            "clearance",
            "must be smaller than 2 (f_i + f_o - 1) D_w, the clearance at which the ball "
            "would leave the grooves axially",
        )
    # cos(alpha0) = 1 - g/A; alpha0 = 2 asin(sqrt(g/(2A))) keeps the digits of a small g
    alpha0 = 2.0 * np.arcsin(np.sqrt(np.clip(g / (2.0 * A), 0.0, 1.0)))
    R_i = dm / 2.0 + (fi - 0.5) * dw * np.cos(alpha0)
    return _Geometry(dw, dm, fi, fo, A, g, alpha0, R_i)


def _out(x: np.ndarray) -> Any:
    x = np.asarray(x)
    return x[()] if x.ndim == 0 else x


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
    for _ in range(200):
        open_ = hi - lo > 4e-16 * hi  # each case stops on its own
        if not open_.any():
            break
        mid = 0.5 * (lo + hi)
        below = excess(mid) < 0
        lo = np.where(open_ & below, mid, lo)
        hi = np.where(open_ & ~below, mid, hi)
    u = 0.5 * (lo + hi)
    return _out(u), _out(np.rad2deg(np.arctan2(u, c))), _out(k * approach(u) ** 1.5)


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
) -> CombinedDistribution:
    """Equilibrium of the inner ring of a deep-groove ball bearing under F_r, F_a and a moment.

    Conventions and model: see the module docstring. Arrays broadcast over cases; ``balls`` is
    one number per call (the ball arrays of the result have the last axis z).

    Parameters
    ----------
    balls : int
        Number of balls z, 1 to 1000. [-]
    radial_load : array_like
        F_r >= 0, along the load line (phi = 0). [N]
    axial_load : array_like, default 0
        F_a (either sign). [N]
    ball_diameter, pitch_diameter : array_like
        D_w and d_m. [mm]
    f_i, f_o : array_like, default 0.52, 0.53
        Groove conformities r_i/D_w, r_o/D_w. [-]
    clearance : array_like, default 0
        Radial internal clearance G_r, total play; negative = preload. [mm]
    cage_angle : array_like, default 0
        Angle of ball 1 from the load line. [°]
    moment : array_like, optional
        Moment tilting the inner ring in the plane of the load line (see the module docstring);
        default: the ring is free to tilt (M = 0). [N mm]
    misalignment : array_like, optional
        Imposed tilt of the inner ring in the plane of the load line, instead of a moment. [°]
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

    Returns
    -------
    CombinedDistribution

    Raises
    ------
    InputError
        A parameter outside its domain, no load at all, both a moment and a misalignment.
    ConvergenceError
        No equilibrium reached (e.g. a load the balls cannot carry).

    Pure radial load, zero clearance: the contact angles stay 0 and the radial engine's answer
    comes back (peer 6305 geometry, ISO/TS 16281 example):

    >>> r = solve_combined(7, 1000.0, ball_diameter=11.5, pitch_diameter=43.5, modulus=210000.0)
    >>> round(float(r.x) * 1e3, 4), float(r.axial), float(r.contact_angles.max())
    (15.1102, 0.0, 0.0)
    """
    z = int(validate.ball_count(balls, maximum=1000).reshape(-1)[0])
    if np.size(balls) != 1:
        raise InputError("balls", "must be one number per call (group the cases by z)")
    if moment is not None and misalignment is not None:
        raise InputError("moment", "give a moment or a misalignment, not both")
    fr = validate.finite("radial_load", radial_load)
    if np.any(fr < 0):
        raise InputError("radial_load", "must be >= 0 N")
    fa = validate.finite("axial_load", axial_load)
    mm = validate.finite("moment", 0.0 if moment is None else moment)
    mc = validate.finite("moment_cross", moment_cross)
    tilt_deg = validate.finite("misalignment", 0.0 if misalignment is None else misalignment)
    cage = np.mod(validate.finite("cage_angle", cage_angle), 360.0)
    e = validate.positive("modulus", modulus, "MPa")
    nu = validate.finite("poisson", poisson)
    k_given = None if stiffness is None else validate.positive("stiffness", stiffness, "N/mm^1.5")
    validate.broadcast_shape(
        {"radial_load": fr, "axial_load": fa, "moment": mm, "misalignment": tilt_deg,
         "cage_angle": cage, "modulus": e, "poisson": nu, "moment_cross": mc,
         "ball_diameter": ball_diameter, "pitch_diameter": pitch_diameter, "f_i": f_i,
         "f_o": f_o, "clearance": clearance}
    )  # fmt: skip
    arrays = np.broadcast_arrays(
        fr,
        fa,
        mm,
        tilt_deg,
        cage,
        e,
        nu,
        mc,
        *(np.asarray(v, dtype=float) for v in (ball_diameter, pitch_diameter, f_i, f_o, clearance)),
        *(() if k_given is None else (k_given,)),
    )
    shape = arrays[0].shape
    flat = [a.ravel() for a in arrays]
    fr, fa, mm, tilt_deg, cage, e, nu, mc, dw, dm, fi, fo, gr = flat[:13]
    geo = _geometry(dw, dm, fi, fo, gr)
    if tilt_radius is not None:
        radius = validate.positive("tilt_radius", tilt_radius, "mm")
        geo = dataclasses.replace(geo, R_i=np.broadcast_to(radius, dw.shape).astype(float))
    phi = np.deg2rad(cage)[:, None] + 2.0 * np.pi * np.arange(z) / z
    if z < 3 and np.any((np.mod(cage, 360.0 / z) != 0) & (fr > 0)):
        raise InputError(
            "cage_angle",
            "with 1 or 2 balls a ball must sit on the load line (cage angle 0), "
            "otherwise no equilibrium exists",
        )
    k_ref = flat[13] if k_given is not None else ball_stiffness_at(0.0, dw, dm, fi, fo, e, nu)
    k_ref = np.asarray(k_ref, dtype=float)
    f_ref = np.maximum(np.maximum(fr, np.abs(fa)), np.hypot(mm, mc) / geo.R_i)
    if np.any(f_ref <= 0):
        raise InputError("radial_load", "give a radial load, an axial load or a moment")
    _check_scale(f_ref, k_ref, geo.A)
    problem = _Problem.build(z, phi, geo, fr, fa, mm, mc, np.deg2rad(tilt_deg), f_ref, k_ref)
    with np.errstate(all="ignore"):
        v, k_hat, its = _solve_with_stiffness(problem, geo, e, nu, k_given is None, misalignment)
    return _result(problem, geo, v, k_hat, its, shape, fr, fa, mm, gr, cage, misalignment)


#: Largest groove-geometry length A over the one-ball approach (F/K)^(2/3) the combined solver
#: takes: beyond it a load is a vanishing fraction of what moves the ring in its groove, and the
#: ball approaches, small differences of lengths this much larger, lose the digits Newton needs
#: (at 7e7, 9 of 60 loadings of a 6313 stalled at a residual of 1e-8; up to 2e7 every one of
#: 1620 loadings of five bearings near the limit converges). [-]
GEOMETRY_RATIO_MAX = 2e7


def _check_scale(f_ref: np.ndarray, k_ref: np.ndarray, big_a: np.ndarray) -> None:
    """Refuse loads so small against the groove geometry that the scaled problem loses its
    digits (the radial solver, without an axial load, takes any ratio)."""
    scale = (f_ref / k_ref) ** (2.0 / 3.0)
    bad = np.broadcast_to(big_a, scale.shape) / scale > GEOMETRY_RATIO_MAX
    if np.any(bad):
        f_min = float(
            np.max(k_ref * (np.broadcast_to(big_a, scale.shape) / GEOMETRY_RATIO_MAX) ** 1.5)
        )
        raise InputError(
            "radial_load",
            f"the loads are too small for the combined solver (the largest of F_r, |F_a| and "
            f"M/R_i is {float(np.min(f_ref)):.3g} N; it takes at least {f_min:.2g} N for this "
            "bearing); the radial solver, without an axial load, takes any load",
        )


@dataclass(frozen=True)
class _Problem:
    """The scaled problem: lengths in units of s = (F/K)^(2/3), forces in units of F."""

    z: int
    c: np.ndarray  # cos phi_j, (n, z)
    s: np.ndarray  # sin phi_j, (n, z)
    scale: np.ndarray  # s [mm], (n,)
    a_hat: np.ndarray  # A / s
    g_hat: np.ndarray  # (G_r/2) / s
    f_hat: np.ndarray  # generalised forces of (x, y, a, t, t_c), (n, 5)
    t_imp: np.ndarray  # imposed R_i theta / s, (n,)
    locked: np.ndarray  # (5,) bool: the tilt is imposed
    f_ref: np.ndarray  # F [N]
    k_ref: np.ndarray  # K [N/mm^1.5]

    @staticmethod
    def build(
        z: int,
        phi: np.ndarray,
        geo: _Geometry,
        fr: np.ndarray,
        fa: np.ndarray,
        mm: np.ndarray,
        mc: np.ndarray,
        tilt: np.ndarray,
        f_ref: np.ndarray,
        k_ref: np.ndarray,
    ) -> _Problem:
        scale = (f_ref / k_ref) ** (2.0 / 3.0)
        c, s = np.cos(phi), np.sin(phi)
        c = np.where(np.abs(c) < 1e-15, 0.0, c)
        s = np.where(np.abs(s) < 1e-15, 0.0, s)
        zero = np.zeros_like(fr)
        f_hat = np.stack([fr, zero, fa, mm / geo.R_i, mc / geo.R_i], axis=1) / f_ref[:, None]
        locked = np.array([False, False, False, True, False]) if np.any(tilt) else None
        return _Problem(
            z=z,
            c=c,
            s=s,
            scale=scale,
            a_hat=geo.A / scale,
            g_hat=geo.g / scale,
            f_hat=f_hat,
            t_imp=geo.R_i * tilt / scale,
            locked=np.zeros(5, bool) if locked is None else locked,
            f_ref=f_ref,
            k_ref=k_ref,
        )

    def sub(self, idx: np.ndarray) -> _Problem:
        """The cases ``idx`` only."""
        return _Problem(
            self.z,
            self.c[idx],
            self.s[idx],
            self.scale[idx],
            self.a_hat[idx],
            self.g_hat[idx],
            self.f_hat[idx],
            self.t_imp[idx],
            self.locked,
            self.f_ref[idx],
            self.k_ref[idx],
        )


def _balls(p: _Problem, v: np.ndarray) -> tuple[np.ndarray, ...]:
    """Scaled approach, cos and sin of the contact angle, centre distance of every ball."""
    r = v[:, 0, None] * p.c + v[:, 1, None] * p.s
    u = v[:, 2, None] + (v[:, 3, None] + p.t_imp[:, None]) * p.c + v[:, 4, None] * p.s
    a, g = p.a_hat[:, None], p.g_hat[:, None]
    rho = a - g + r
    d = np.hypot(rho, u)
    # d - A without cancellation: (rho^2 - A^2 + u^2)/(d + A), rho^2 - A^2 = (r - g)(2A - g + r)
    delta = ((r - g) * (2.0 * a - g + r) + u * u) / (d + a)
    safe = np.where(d > 0, d, 1.0)
    return delta, np.where(d > 0, rho / safe, 1.0), np.where(d > 0, u / safe, 0.0), safe


def _state(p: _Problem, v: np.ndarray, k: np.ndarray, hessian: bool = True) -> tuple[Any, ...]:
    """Scaled potential, its gradient (n, 5) and Hessian (n, 5, 5), and the force size (n,)."""
    delta, ca, sa, d = _balls(p, v)
    pos = np.maximum(delta, 0.0)
    root = np.sqrt(pos)
    q = k * pos * root
    energy = (q * pos).sum(1) / 2.5 - (p.f_hat * v).sum(1)
    c, s = p.c, p.s
    grad = (
        np.stack(
            [
                (q * ca * c).sum(1),
                (q * ca * s).sum(1),
                (q * sa).sum(1),
                (q * sa * c).sum(1),
                (q * sa * s).sum(1),
            ],
            axis=1,
        )
        - p.f_hat
    )
    grad[:, p.locked] = 0.0
    size = np.maximum(1.0, q.sum(1))
    if not hessian:
        return energy, grad, None, size
    g_vec = np.stack([ca * c, ca * s, sa, sa * c, sa * s], axis=2)
    h_vec = np.stack([-sa * c, -sa * s, ca, ca * c, ca * s], axis=2)
    hess = np.einsum("nz,nzi,nzj->nij", 1.5 * k * root, g_vec, g_vec)
    hess += np.einsum("nz,nzi,nzj->nij", q / d, h_vec, h_vec)
    hess[:, p.locked, :] = 0.0
    hess[:, :, p.locked] = 0.0
    hess[:, p.locked, p.locked] = 1.0
    return energy, grad, hess, size


def _minimise(p: _Problem, v: np.ndarray, k: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Damped Newton with an Armijo line search on the convex potential; every case to TOLERANCE.

    Returns the displacements and the iterations per case; raises ConvergenceError for a case
    whose residual stays above ACCEPT.
    """
    v = v.copy()
    n = v.shape[0]
    iterations = np.zeros(n, dtype=np.int64)
    active = np.arange(n)
    eye = np.eye(5)
    for _ in range(MAX_ITERATIONS):
        q = p.sub(active)
        va, ka = v[active], k[active]
        energy, grad, hess, size = _state(q, va, ka)
        gnorm = np.linalg.norm(grad, axis=1)
        done = gnorm <= TOLERANCE * size
        trace = np.trace(hess, axis1=1, axis2=2)
        hess += (1e-13 * trace + 1e-300)[:, None, None] * eye
        step = -np.linalg.solve(hess, grad[:, :, None])[:, :, 0]
        loose = np.flatnonzero(~(trace > 1.0 * q.locked.sum()) & ~done)  # no ball in contact
        if loose.size:  # Newton has no curvature there: move along the load to the first contact
            step[loose] = _to_contact(q.sub(loose), va[loose])
        slope = (grad * step).sum(1)
        t = np.ones(len(active))
        pending = ~done
        for _ in range(60):
            if not pending.any():
                break
            trial = va + t[:, None] * step
            e_new, g_new, _, _ = _state(q, trial, ka, hessian=False)
            ok = (e_new <= energy + 1e-4 * t * slope) | (
                np.linalg.norm(g_new, axis=1) < 0.5 * gnorm
            )
            pending &= ~ok
            t = np.where(pending, 0.5 * t, t)
        moved = t[:, None] * step
        tiny = np.linalg.norm(moved, axis=1) <= 1e-14 * (
            np.linalg.norm(va, axis=1) + q.a_hat + np.abs(q.g_hat)
        )
        v[active] = np.where(done[:, None], va, va + moved)
        iterations[active] += 1
        active = active[~(done | tiny)]
        if active.size == 0:
            break
    _, grad, _, size = _state(p, v, k, hessian=False)
    residual = np.linalg.norm(grad, axis=1) / size
    bad = ~(residual <= ACCEPT)
    if np.any(bad) or active.size:
        found = residual[bad] if np.any(bad) else residual
        known = found[~np.isnan(found)]  # nanmax of all-NaN would warn on the terminal
        worst = float(known.max()) if known.size else math.nan
        if np.any(bad):
            raise ConvergenceError(
                "combined-load ring equilibrium",
                int(iterations.max()),
                worst,
                {"f_hat": p.f_hat[bad], "clearance_hat": 2.0 * p.g_hat[bad]},
            )
    return v, iterations


def _to_contact(p: _Problem, v: np.ndarray) -> np.ndarray:
    """For rings that touch no ball: the step along the generalised load (the potential falls
    along it while no ball is loaded) that brings the nearest ball, to first order, a little
    into contact; zero where no ball comes nearer that way."""
    delta, ca, sa, _ = _balls(p, v)
    direction = np.where(p.locked, 0.0, p.f_hat)
    direction /= np.maximum(np.linalg.norm(direction, axis=1, keepdims=True), 1e-300)
    c, s = p.c, p.s
    rate = (
        ca * c * direction[:, 0, None]
        + ca * s * direction[:, 1, None]
        + sa * direction[:, 2, None]
        + sa * c * direction[:, 3, None]
        + sa * s * direction[:, 4, None]
    )  # d(delta_j)/dt along the direction
    with np.errstate(divide="ignore", invalid="ignore"):
        reach = np.where(rate > 0, -delta / rate, np.inf)
    t = np.min(reach, axis=1)
    t = np.where(np.isfinite(t), 1.001 * t + 1e-9, 0.0)
    return direction * t[:, None]


def _start(p: _Problem, geo: _Geometry, cage: np.ndarray) -> np.ndarray:
    """Radial engine for F_r alone, the axial closed form for F_a (or the moment) alone."""
    from bearingload.models.equilibrium import solve

    n = p.f_hat.shape[0]
    v = np.zeros((n, 5))
    f = p.f_hat * p.f_ref[:, None]  # [N]
    # a load component below 1e-3 of the largest does not pick the start (a vanishing F_r beside
    # a moment would otherwise start the tilt from the radial solution, far from the answer)
    radial = p.f_hat[:, 0] > 1e-3
    if radial.any():
        r = solve(p.z, f[radial, 0], p.k_ref[radial], 2.0 * geo.g[radial], cage[radial])
        v[radial, 0] = r.x / p.scale[radial]
        v[radial, 1] = r.y / p.scale[radial]
    axial = np.abs(p.f_hat[:, 2]) > 1e-3
    if axial.any():
        u, _, _ = axial_only(
            p.z, np.abs(f[axial, 2]), p.k_ref[axial], geo.A[axial], 2.0 * geo.g[axial]
        )
        v[axial, 2] = np.sign(f[axial, 2]) * u / p.scale[axial]
    size = np.hypot(f[:, 3] * (not p.locked[3]), f[:, 4])
    pure = (~radial) & (~axial) & (size > 0) & (p.t_imp == 0)
    if pure.any():  # a moment alone: the ring tilts as if twice it were an axial load
        u, _, _ = axial_only(p.z, 2.0 * size[pure], p.k_ref[pure], geo.A[pure], 2.0 * geo.g[pure])
        for col in (3, 4):
            v[pure, col] = u * f[pure, col] / size[pure] / p.scale[pure]
    # the start only needs a few digits: rounded to single precision, it does not depend on
    # the last bits the radial engine and the bisection leave, which may vary with the batch
    with np.errstate(over="ignore"):
        single = v.astype(np.float32).astype(float)
    return np.where(np.abs(v) < 1e30, single, v)


class _StiffnessCurve:
    """K(alpha) of each case's geometry as a Chebyshev interpolant in cos(alpha), scaled by K_ref.

    ``K`` depends on the angle only through ``cos(alpha)`` in the curvature sums, smoothly (the
    nearest singularity, ``cos(alpha) = +-d_m/D_w``, lies far outside [cos 89°, 1]); 17 Chebyshev
    points reproduce the exact Hertz value to rounding (checked in the tests against
    :func:`ball_stiffness_at`). One Hertz evaluation per distinct geometry instead of one per
    ball and stiffness update.
    """

    NODES = 17
    LOW = math.cos(math.radians(89.0))

    def __init__(self, geo: _Geometry, e: np.ndarray, nu: np.ndarray, k_ref: np.ndarray) -> None:
        params = np.stack([geo.D_w, geo.d_m, geo.f_i, geo.f_o, e, nu], axis=1)
        uniq, inverse = np.unique(params, axis=0, return_inverse=True)
        n = self.NODES - 1
        j = np.arange(self.NODES)
        self.x = np.cos(np.pi * j / n)
        self.w = np.where(j % 2 == 0, 1.0, -1.0) * np.where((j == 0) | (j == n), 0.5, 1.0)
        cos_nodes = self.LOW + (1.0 - self.LOW) * (self.x + 1.0) / 2.0
        alpha = np.degrees(np.arccos(np.minimum(cos_nodes, 1.0)))
        values = ball_stiffness_at(
            alpha[None, :], *(uniq[:, i, None] for i in range(6))
        )  # (unique geometries, nodes)
        self.values = values[inverse.reshape(-1)] / k_ref[:, None]

    def __call__(self, idx: np.ndarray, cos_alpha: np.ndarray) -> np.ndarray:
        """Scaled K of the cases ``idx`` at ``cos_alpha`` (shape (len(idx), z))."""
        c = np.clip(cos_alpha, self.LOW, 1.0)
        t = 2.0 * (c - self.LOW) / (1.0 - self.LOW) - 1.0
        diff = t[..., None] - self.x
        hit = diff == 0.0
        with np.errstate(divide="ignore", invalid="ignore"):
            terms = self.w / np.where(hit, 1.0, diff)
        f = self.values[idx][:, None, :]
        value = (terms * f).sum(-1) / terms.sum(-1)
        exact = (hit * f).sum(-1)
        return np.where(hit.any(-1), exact, value)


def _solve_with_stiffness(
    p: _Problem, geo: _Geometry, e: np.ndarray, nu: np.ndarray, hertz: bool, tilt: Any
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Minimise with frozen ball stiffnesses, update them to the contact angles, repeat."""
    cage = np.rad2deg(np.arctan2(p.s[:, 0], p.c[:, 0]))
    v = _start(p, geo, cage)
    k = np.ones_like(p.c)
    total = np.zeros(v.shape[0], dtype=np.int64)
    todo = np.arange(v.shape[0])  # each case stops on its own: no case depends on the batch
    change = np.inf
    curve: _StiffnessCurve | None = None
    for _ in range(MAX_STIFFNESS_UPDATES):
        sub = p.sub(todo)
        v[todo], its = _minimise(sub, v[todo], k[todo])
        total[todo] += its
        if not hertz:
            return v, k, total
        if curve is None:
            curve = _StiffnessCurve(geo, e, nu, p.k_ref)
        delta, ca, _, _ = _balls(sub, v[todo])
        loaded = delta > 0
        k_new = np.where(loaded, curve(todo, ca), k[todo])
        rel = np.max(np.where(loaded, np.abs(k_new / k[todo] - 1.0), 0.0), axis=1)
        k[todo] = k_new
        change = float(rel.max())
        todo = todo[rel > 1e-13]
        if todo.size == 0:
            return v, k, total
    raise ConvergenceError("combined-load ball stiffness update", MAX_STIFFNESS_UPDATES, change, {})


def _result(
    p: _Problem,
    geo: _Geometry,
    v: np.ndarray,
    k: np.ndarray,
    its: np.ndarray,
    shape: tuple[int, ...],
    fr: np.ndarray,
    fa: np.ndarray,
    mm: np.ndarray,
    gr: np.ndarray,
    cage: np.ndarray,
    misalignment: Any,
) -> CombinedDistribution:
    """Back to physical units and the case shape."""
    # components left at rounding noise by a symmetric case (|v| < 1e-12 of the largest) are 0
    big = np.maximum(np.abs(v).max(axis=1, keepdims=True), 1.0)
    v = np.where(np.abs(v) < 1e-12 * big, 0.0, v)
    delta, ca, sa, _ = _balls(p, v)
    s = p.scale[:, None]
    q = p.f_ref[:, None] * k * np.maximum(delta, 0.0) ** 1.5
    t = v[:, 3] + p.t_imp
    moment = geo.R_i * (q * sa * p.c).sum(1) if misalignment is not None else mm
    z = p.z

    def case(a: np.ndarray) -> np.ndarray:
        return a.reshape(shape)

    def ball(a: np.ndarray) -> np.ndarray:
        return a.reshape(shape + (z,))

    phi = np.mod(cage[:, None] + 360.0 * np.arange(z) / z, 360.0)
    return CombinedDistribution(
        balls=z,
        radial_load=case(fr),
        axial_load=case(fa),
        moment=case(moment),
        clearance=case(gr),
        cage_angle=case(cage),
        free_contact_angle=case(np.rad2deg(geo.alpha0)),
        axial_play=case(2.0 * geo.A * np.sin(geo.alpha0)),
        x=case(v[:, 0] * p.scale),
        y=case(v[:, 1] * p.scale),
        axial=case(v[:, 2] * p.scale),
        tilt=case(np.rad2deg(t * p.scale / geo.R_i)),
        tilt_cross=case(np.rad2deg(v[:, 4] * p.scale / geo.R_i)),
        ball_angles=ball(phi),
        contact_angles=ball(np.rad2deg(np.arctan2(sa, ca))),
        ball_approaches=ball(delta * s),
        ball_stiffnesses=ball(k * p.k_ref[:, None]),
        ball_loads=ball(q),
        iterations=case(its),
    )
