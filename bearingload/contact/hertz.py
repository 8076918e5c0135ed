"""Hertz contact of the rolling elements: ellipticity, approach, stiffness, pressure.

Units throughout: force [N], length [mm], modulus and pressure [MPa] = [N/mm^2],
curvature [1/mm], ball stiffness [N/mm^1.5], roller stiffness [N/mm^(10/9)].

Point contact (balls). Two bodies touch at a point; their *curvature sums* in the two
principal planes are ``rho_x`` and ``rho_y`` [1/mm] (convex positive, a concave groove
negative, e.g. ``rho_y = 2/D_w - 1/r_groove``). Hertz's solution (Johnson, *Contact Mechanics*,
1985, §4.2; Harris & Kotzalas, *Rolling Bearing Analysis*, ch. 6) gives an elliptical contact
with semi-major axis ``a`` (in the plane of the *smaller* curvature sum) and semi-minor axis
``b``. With the ellipticity ``kappa = a/b >= 1``, the eccentricity ``e`` (``e^2 = 1 - 1/kappa^2``)
and the complete elliptic integrals ``K(e)``, ``E(e)``, kappa solves::

    F(rho) = |rho_x - rho_y| / (rho_x + rho_y) = ((kappa^2 + 1) E - 2 K) / ((kappa^2 - 1) E)

and, with ``sum_rho = rho_x + rho_y``, ``1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2`` and
``X = 3 Q / (2 sum_rho E*)``::

    a = a* X^(1/3),  b = b* X^(1/3),  delta = delta* X^(2/3) sum_rho / 2,  p_max = 3 Q / (2 pi a b)
    a* = (2 kappa^2 E / pi)^(1/3),  b* = (2 E / (pi kappa))^(1/3),
    delta* = (2 K / pi) (pi / (2 kappa^2 E))^(1/3).

``a*, b*, delta*`` are Harris's dimensionless coefficients; the same numbers are Timoshenko's
``m, n`` (argument ``cos theta = F(rho)``) and the Russian handbooks' ``n_a, n_b, n_delta``
(argument ``A/B = (1 - F)/(1 + F)``), the latter written ``delta = 0.655 n_delta
(Q^2 sum_rho / E*^2)^(1/3)`` with ``0.655 = (9/32)^(1/3)``. The stiffness ``Q = K delta^(3/2)``
does not depend on the load: ``K = (4 sqrt(2) / 3) E* / (delta*^(3/2) sqrt(sum_rho))``.

A note on scipy: ``scipy.special.ellipk(m)`` and ``ellipe(m)`` take the *parameter*
``m = e^2``, not the modulus ``e``. This module does not call scipy (its import alone cost a
terminal calculation 0.18 s): it evaluates ``K``, ``E`` and ``(K - E)/m`` by the
arithmetic-geometric mean in ``kappa`` (``p = 1 - m = 1/kappa^2``), in a form that keeps full
precision both near the circle (``kappa -> 1``, where ``K - E`` cancels) and for very long
ellipses (``m -> 1``). One contact, one C function (:mod:`bearingload._elliptic`, which the
compiled core's Hertz stiffness curve shares): Newton on the ellipticity equation from a fitted
start, then the coefficients and the stiffness; an array is a C loop over its elements, each the
same bits as alone.

Line contact (rollers) uses Palmgren's empirical steel formula, see
:func:`palmgren_line_deflection`.

Kuzmenko (2010, §3.4.2) computes the ball stiffness of bearing 306 by a table
procedure; :func:`kuzmenko2010_ball_constant` repeats it step by step so it can be compared
with the exact solution.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np

from bearingload import _elliptic, validate
from bearingload.constants import BALL_EXPONENT, ROLLER_EXPONENT, STEEL_MODULUS, STEEL_POISSON
from bearingload.errors import ConvergenceError, InputError
from bearingload.numerics import elliptic_integrals, scalar_out

if TYPE_CHECKING:
    from numpy.typing import ArrayLike

#: Young's modulus and Poisson's ratio of bearing steel (bearingload.constants). [MPa], [-]
E_STEEL = STEEL_MODULUS
NU_STEEL = STEEL_POISSON
#: Palmgren's coefficient of the roller-raceway approach delta = c Q^0.9 / l^0.8 (steel, mm, N).
PALMGREN_LINE_COEFFICIENT = 3.84e-5
#: Load-deflection exponents Q = K delta^n: point contact (balls) and line contact (rollers).
POINT_EXPONENT = BALL_EXPONENT
LINE_EXPONENT = ROLLER_EXPONENT
#: Beyond this ratio of curvature sums the contact is a line contact for every practical
#: purpose (kappa ~ 1e7); the point-contact solution is refused rather than returned inexact.
MAX_CURVATURE_RATIO = _elliptic.MAX_RATIO

#: Newton steps of the ellipticity at the most (bearingload/_elliptic.pyx). [-]
_MAX_ITERATIONS = _elliptic.HERTZ_STEPS


# The result types here use typing.NamedTuple's call form: under the module's postponed
# annotations its class form compiles every field's annotation text when the module is imported
# (a ForwardRef each, about 0.2 ms per class of every command that imports this module).


class HertzCoefficients(
    NamedTuple(
        "HertzCoefficients",
        [
            ("kappa", Any),
            ("a_star", Any),
            ("b_star", Any),
            ("delta_star", Any),
            ("ellipk", Any),
            ("ellipe", Any),
        ],
    )
):
    """Dimensionless solution of the Hertz point contact (all [-]).

    Attributes
    ----------
    kappa
        Ellipticity a/b >= 1.
    a_star
        Harris a* (Timoshenko m, Russian n_a).
    b_star
        Harris b* (Timoshenko n, Russian n_b).
    delta_star
        Harris delta* (Russian n_delta).
    ellipk
        Complete elliptic integral of the first kind K(e), e^2 = 1 - 1/kappa^2.
    ellipe
        Complete elliptic integral of the second kind E(e).
    """

    __slots__ = ()


class PointContact(
    NamedTuple(
        "PointContact",
        [
            ("kappa", Any),
            ("a", Any),
            ("b", Any),
            ("delta", Any),
            ("stiffness", Any),
            ("p_max", Any),
        ],
    )
):
    """Hertz solution of one loaded point contact.

    Attributes
    ----------
    kappa
        Ellipticity a/b. [-]
    a
        Semi-major axis, in the plane of the smaller curvature sum. [mm]
    b
        Semi-minor axis. [mm]
    delta
        Elastic approach of the two bodies. [mm]
    stiffness
        K = Q / delta^1.5, independent of the load. [N/mm^1.5]
    p_max
        Maximum contact pressure 3Q / (2 pi a b). [MPa]
    """

    __slots__ = ()


class RacewayCurvatures(
    NamedTuple(
        "RacewayCurvatures",
        [("inner_x", Any), ("inner_y", Any), ("outer_x", Any), ("outer_y", Any)],
    )
):
    """Curvature sums of the ball-inner and ball-outer raceway contacts. [1/mm]"""

    __slots__ = ()


class BallStiffness(NamedTuple("BallStiffness", [("inner", Any), ("outer", Any), ("ball", Any)])):
    """Contact stiffnesses of one ball. [N/mm^1.5]

    Attributes
    ----------
    inner
        Ball-inner raceway contact.
    outer
        Ball-outer raceway contact.
    ball
        Both contacts in series: Q = ball * (delta_i + delta_o)^1.5.
    """

    __slots__ = ()


class BallContacts(NamedTuple("BallContacts", [("inner", PointContact), ("outer", PointContact)])):
    """Hertz solution of both contacts of one ball under the same load."""

    __slots__ = ()


def _plain(*values: object) -> list[float] | None:
    """The values as finite Python floats when every one is a plain real scalar, else None.

    The scalar fast path (one contact straight to :mod:`bearingload._elliptic`) takes such
    calls; anything else, or anything it would refuse, goes through the array path (which says
    why).
    """
    out = []
    for v in values:
        kind = type(v)
        if kind is not float and kind is not int:
            if not isinstance(v, (np.floating, np.integer)) or isinstance(v, bool):
                return None
        f = float(v)  # type: ignore[arg-type]
        if not math.isfinite(f):
            return None
        out.append(f)
    return out


def _scalar_modulus(E: float, nu: float) -> float | None:
    """:func:`reduced_modulus` of two equal bodies for plain floats, or None if refused."""
    if not (E > 0 and -1.0 < nu <= 0.5):
        return None
    return 1.0 / ((1.0 - nu**2) / E + (1.0 - nu**2) / E)


def _sorted(rho_x: float, rho_y: float) -> tuple[float, float]:
    return min(rho_x, rho_y), max(rho_x, rho_y)


def reduced_modulus(
    modulus: ArrayLike = E_STEEL,
    poisson: ArrayLike = NU_STEEL,
    modulus2: ArrayLike | None = None,
    poisson2: ArrayLike | None = None,
) -> Any:
    """Contact modulus E* of two bodies, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.

    This is Johnson's E* (Hamrock's E' = 2 E*). For two identical steel bodies
    E* = E / (2 (1 - nu^2)).

    Parameters
    ----------
    modulus, poisson : array_like
        Young's modulus E1 [MPa] and Poisson's ratio nu1 [-] of body 1.
    modulus2, poisson2 : array_like, optional
        The same for body 2 (E2, nu2); default: equal to body 1.

    Returns
    -------
    E_star : numpy scalar or ndarray
        [MPa]

    >>> round(float(reduced_modulus(2.1e4, 0.3)), 1)  # Kuzmenko (2010), kgf/mm^2
    11538.5
    """
    e1 = validate.positive_number("modulus", modulus)
    n1 = validate.finite("poisson", poisson)
    e2 = e1 if modulus2 is None else validate.positive_number("modulus2", modulus2)
    n2 = n1 if poisson2 is None else validate.finite("poisson2", poisson2)
    for name, nu in (("poisson", n1), ("poisson2", n2)):
        validate.require(name, nu, "between -1 and 0.5", (nu > -1.0) & (nu <= 0.5))
    return scalar_out(1.0 / ((1.0 - n1**2) / e1 + (1.0 - n2**2) / e2))


def equivalent_material(
    ring_modulus: float, ring_poisson: float, ball_modulus: float, ball_poisson: float
) -> tuple[float, float]:
    """One material (E_eq, nu_eq) whose contact with itself has the E* of a ball of one
    material on rings of another (a hybrid bearing: silicon-nitride balls, steel rings).

    Hertz's contact depends on the two materials only through
    1/E* = (1 - nu_r^2)/E_r + (1 - nu_b^2)/E_b (:func:`reduced_modulus`); a body of
    (E_eq, nu_eq) against itself gives 1/E* = 2 (1 - nu_eq^2)/E_eq, so nu_eq = nu_r and
    E_eq = 2 (1 - nu_r^2) E* give the same E*, exactly, to every function that takes a
    (modulus, poisson) pair and uses it only through E* (the stiffness, the pressures, the
    film's E' = 2 E*). Balls of the rings' own material return the rings' pair unchanged.

    >>> e, nu = equivalent_material(208000.0, 0.3, 310000.0, 0.26)
    >>> round(e), nu
    (246521, 0.3)
    >>> abs(reduced_modulus(e, nu) / reduced_modulus(208000.0, 0.3, 310000.0, 0.26) - 1) < 1e-15
    True
    """
    if (ball_modulus, ball_poisson) == (ring_modulus, ring_poisson):
        return float(ring_modulus), float(ring_poisson)
    e_star = float(reduced_modulus(ring_modulus, ring_poisson, ball_modulus, ball_poisson))
    return 2.0 * (1.0 - ring_poisson**2) * e_star, float(ring_poisson)


def _contact_modulus(
    modulus: ArrayLike, poisson: ArrayLike, e_star: ArrayLike | None
) -> np.ndarray:
    if e_star is not None:
        return validate.positive_number("e_star", e_star)
    return np.asarray(reduced_modulus(modulus, poisson), dtype=float)


def curvature_difference(rho_x: ArrayLike, rho_y: ArrayLike) -> Any:
    """Curvature difference F(rho) = |rho_x - rho_y| / (rho_x + rho_y). [-]

    Parameters
    ----------
    rho_x, rho_y : array_like
        Curvature sums of the contact in its two principal planes, both positive. [1/mm]

    >>> float(curvature_difference(0.2, 0.2))
    0.0
    """
    small, large = _curvature_pair(rho_x, rho_y)
    return scalar_out((large - small) / (large + small))


def _curvature_pair(rho_x: ArrayLike, rho_y: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    rx = validate.positive_number("rho_x", rho_x)
    ry = validate.positive_number("rho_y", rho_y)
    small, large = np.broadcast_arrays(np.minimum(rx, ry), np.maximum(rx, ry))
    # (inf beyond 1.8e308/1e15: the ratio is then within; the ratio shown inf where it overflows)
    with np.errstate(over="ignore"):
        ok = large <= MAX_CURVATURE_RATIO * small
        if not np.all(ok):
            validate.require(
                "rho_x/rho_y",
                large / small,
                f"a ratio of at most {MAX_CURVATURE_RATIO:g} (beyond it use the line-contact "
                "model)",
                ok,
            )
    return small, large


def _not_settled(log_ratio: np.ndarray, t: np.ndarray) -> ConvergenceError:
    """The error of the contacts whose Newton did not settle (their last ln kappa ``t``)."""
    _, _, n, d, _, _ = elliptic_integrals(t)
    residual = np.abs(np.log(n) - np.log(d) + 2.0 * t - log_ratio) / log_ratio
    return ConvergenceError(
        "Hertz ellipticity (Newton)",
        _MAX_ITERATIONS,
        float(np.max(residual)),
        {"B/A": np.exp(log_ratio)},
    )


def hertz_coefficients(rho_x: ArrayLike, rho_y: ArrayLike) -> HertzCoefficients:
    """Dimensionless Hertz solution for the curvature sums rho_x, rho_y.

    Solves the transcendental Hertz equation for the ellipticity kappa = a/b (each element
    alone, to rounding level) and returns kappa, Harris's a*, b*, delta* and K(e), E(e).
    Equal curvature sums give the circle exactly: kappa = 1, K = E = pi/2, a* = b* =
    delta* = 1.

    Parameters
    ----------
    rho_x, rho_y : array_like
        Curvature sums in the two principal planes, both positive. [1/mm]

    Returns
    -------
    HertzCoefficients
        ``kappa, a_star, b_star, delta_star, ellipk, ellipe``, all [-].

    Raises
    ------
    InputError
        For a non-positive or non-finite curvature sum, or a ratio above
        ``MAX_CURVATURE_RATIO``.
    ConvergenceError
        If the root finder fails (not observed for any admissible input).

    >>> c = hertz_coefficients(1.0, 1.0)
    >>> float(c.kappa), float(c.delta_star)
    (1.0, 1.0)
    """
    plain = _plain(rho_x, rho_y)
    one = None if plain is None else _elliptic.point(*_sorted(*plain))
    if one is not None:
        return HertzCoefficients(*one)
    small, large = _curvature_pair(rho_x, rho_y)
    values, failed = _elliptic.points(small, large, _MAX_ITERATIONS)
    if failed.any():
        raise _not_settled(np.log(large[failed]) - np.log(small[failed]), values[0][failed])
    return HertzCoefficients(*(scalar_out(v) for v in values))


def ellipticity(rho_x: ArrayLike, rho_y: ArrayLike) -> Any:
    """Ellipticity kappa = a/b >= 1 of the Hertz contact. [-]

    See :func:`hertz_coefficients`.

    >>> float(ellipticity(0.25, 0.25))
    1.0
    """
    return hertz_coefficients(rho_x, rho_y).kappa


def point_contact(
    rho_x: ArrayLike,
    rho_y: ArrayLike,
    load: ArrayLike,
    modulus: ArrayLike = E_STEEL,
    poisson: ArrayLike = NU_STEEL,
    *,
    e_star: ArrayLike | None = None,
) -> PointContact:
    """Exact Hertz solution of a point contact under the load Q.

    Parameters
    ----------
    rho_x, rho_y : array_like
        Curvature sums in the two principal planes, both positive. [1/mm]
    load : array_like
        Normal load Q >= 0. [N]
    modulus, poisson : array_like
        Young's modulus E [MPa] and Poisson's ratio nu [-] of both (identical) bodies;
        default bearing steel.
    e_star : array_like, optional
        Contact modulus E* [MPa] (see :func:`reduced_modulus` for two different
        materials); overrides ``modulus`` and ``poisson``.

    Returns
    -------
    PointContact
        ``kappa`` [-], ``a``, ``b`` [mm], ``delta`` [mm], ``stiffness`` [N/mm^1.5],
        ``p_max`` [MPa]; arrays broadcast from the inputs.

    Sphere of radius 10 mm on a flat, E* = 1e5 MPa, Q = 1000 N:
    a = (3QR/(4E*))^(1/3), delta = a^2/R.

    >>> c = point_contact(0.1, 0.1, 1000.0, e_star=1e5)
    >>> round(float(c.a), 6), round(float(c.delta), 7), round(float(c.p_max), 1)
    (0.421716, 0.0177845, 2684.7)
    """
    fast = _point_contact_scalar(rho_x, rho_y, load, modulus, poisson, e_star)
    if fast is not None:
        return fast
    q = validate.non_negative("load", load)
    es = _contact_modulus(modulus, poisson, e_star)
    coeffs = hertz_coefficients(rho_x, rho_y)
    kappa = np.asarray(coeffs.kappa)
    a_star = np.asarray(coeffs.a_star)
    b_star = np.asarray(coeffs.b_star)
    d_star = np.asarray(coeffs.delta_star)
    with np.errstate(over="ignore", invalid="ignore"):  # (refused below, by name)
        sum_rho = np.asarray(rho_x, dtype=float) + np.asarray(rho_y, dtype=float)
        x = np.cbrt(1.5 * q / (sum_rho * es))  # X^(1/3), [mm]
        a = a_star * x
        b = b_star * x
        delta = 0.5 * d_star * sum_rho * x**2
        stiffness = 4.0 * math.sqrt(2.0) / 3.0 * es / (d_star**1.5 * np.sqrt(sum_rho))
        # 3Q/(2 pi a b) written with X so that Q = 0 gives 0, not 0/0
        p_max = sum_rho * es * x / (math.pi * a_star * b_star)
    values = np.broadcast_arrays(kappa, a, b, delta, stiffness, p_max)
    bad = ~np.logical_and.reduce([np.isfinite(v) for v in values])
    if bad.any():
        huge = ~np.isfinite(np.broadcast_to(sum_rho, bad.shape))
        name, given = ("rho_x", rho_x) if (huge & bad).any() else ("load", load)
        raise InputError(
            name,
            "with these curvature sums, load and contact modulus the contact's size, approach "
            "or pressure is beyond the largest double: no contact of a bearing",
            element=validate.element(
                np.broadcast_to(np.asarray(given, dtype=float), bad.shape), bad
            ),
        )
    return PointContact(*(scalar_out(v) for v in values))


def _point_contact_scalar(
    rho_x: Any, rho_y: Any, load: Any, E: Any, nu: Any, e_star: Any
) -> PointContact | None:
    """:func:`point_contact` for plain scalars (same formulas, the contact in C), else None."""
    plain = _plain(rho_x, rho_y, load, E, nu, 1.0 if e_star is None else e_star)
    if plain is None:
        return None
    rx, ry, q, e, n, es_given = plain
    es = _scalar_modulus(e, n) if e_star is None else (es_given if es_given > 0 else None)
    if es is None or not q >= 0:
        return None
    one = _elliptic.point(*_sorted(rx, ry))
    if one is None:
        return None
    kappa, a_star, b_star, d_star, _, _ = one
    sum_rho = rx + ry
    x = (1.5 * q / (sum_rho * es)) ** (1.0 / 3.0)
    values = (
        kappa,
        a_star * x,
        b_star * x,
        0.5 * d_star * sum_rho * x**2,
        4.0 * math.sqrt(2.0) / 3.0 * es / (d_star**1.5 * math.sqrt(sum_rho)),
        sum_rho * es * x / (math.pi * a_star * b_star),
    )
    if not all(math.isfinite(v) for v in values):
        return None  # (refused by the array path, which names the input)
    return PointContact(*(float(v) for v in values))


def point_contact_stiffness(
    rho_x: ArrayLike,
    rho_y: ArrayLike,
    modulus: ArrayLike = E_STEEL,
    poisson: ArrayLike = NU_STEEL,
    *,
    e_star: ArrayLike | None = None,
) -> Any:
    """Hertz stiffness K of one point contact, Q = K delta^1.5. [N/mm^1.5]

    K = (4 sqrt(2)/3) E* / (delta*^1.5 sqrt(sum_rho)); for a sphere of radius R on a flat
    this is the textbook (4/3) E* sqrt(R).

    Parameters as in :func:`point_contact` (no load: K does not depend on it).

    >>> round(float(point_contact_stiffness(0.1, 0.1, e_star=1e5)))  # (4/3) 1e5 sqrt(10)
    421637
    """
    return point_contact(rho_x, rho_y, 1.0, modulus, poisson, e_star=e_star).stiffness


def series_stiffness(k1: ArrayLike, k2: ArrayLike, exponent: float = POINT_EXPONENT) -> Any:
    """Stiffness of two contacts in series under the same load, Q = K (delta1 + delta2)^n.

    K = (k1^(-1/n) + k2^(-1/n))^(-n). Two equal contacts give k / 2^n (2^1.5 = 2.83 for
    balls), not k/2: the compliances delta/Q^(1/n) add, not 1/k.

    Parameters
    ----------
    k1, k2 : array_like
        Stiffnesses of the two contacts. [N/mm^n]
    exponent : float
        Load-deflection exponent n: 1.5 for balls, 10/9 for rollers. [-]

    >>> round(float(series_stiffness(1.0, 1.0)), 6)
    0.353553
    """
    a = validate.positive_number("k1", k1)
    b = validate.positive_number("k2", k2)
    return scalar_out((a ** (-1.0 / exponent) + b ** (-1.0 / exponent)) ** (-exponent))


def ball_raceway_curvatures(
    ball_diameter: ArrayLike, pitch_diameter: ArrayLike, f_i: ArrayLike, f_o: ArrayLike
) -> RacewayCurvatures:
    """Curvature sums of a radial ball bearing's raceway contacts (contact angle 0). [1/mm]

    inner: rho_x = 2/D_w + 2/(d_m - D_w),  rho_y = 2/D_w - 1/(f_i D_w);
    outer: rho_x = 2/D_w - 2/(d_m + D_w),  rho_y = 2/D_w - 1/(f_o D_w).

    Parameters
    ----------
    ball_diameter : array_like
        Ball diameter D_w. [mm]
    pitch_diameter : array_like
        Pitch diameter d_m, greater than D_w. [mm]
    f_i, f_o : array_like
        Groove conformities r_i/D_w and r_o/D_w, in (0.5, 1) (:func:`bearingload.validate.
        conformity`). [-]

    >>> c = ball_raceway_curvatures(12.3, 51.0, 0.515, 0.515)
    >>> round(float(c.inner_x + c.inner_y), 4)
    0.219
    """
    dw = validate.positive_number("ball_diameter", ball_diameter)
    dm = validate.positive_number("pitch_diameter", pitch_diameter)
    validate.require("ball_diameter", ball_diameter, "smaller than the pitch diameter", dw < dm)
    fi = validate.conformity("f_i", f_i)
    fo = validate.conformity("f_o", f_o)
    # the forms below avoid the cancellations 2/D - 1/(f D) and 2/D -/+ 2/(d_m -/+ D)
    return RacewayCurvatures(
        inner_x=scalar_out(2.0 * dm / (dw * (dm - dw))),
        inner_y=scalar_out((2.0 * fi - 1.0) / (fi * dw)),
        outer_x=scalar_out(2.0 * dm / (dw * (dm + dw))),
        outer_y=scalar_out((2.0 * fo - 1.0) / (fo * dw)),
    )


def ball_contacts(
    load: ArrayLike,
    ball_diameter: ArrayLike,
    pitch_diameter: ArrayLike,
    f_i: ArrayLike,
    f_o: ArrayLike,
    modulus: ArrayLike = E_STEEL,
    poisson: ArrayLike = NU_STEEL,
    *,
    e_star: ArrayLike | None = None,
) -> BallContacts:
    """Hertz solution of the inner and outer raceway contacts of a ball under the load Q.

    Gives the semi-axes, approaches, stiffnesses and the maximum pressures p_max of both
    contacts. Parameters as in :func:`ball_raceway_curvatures` and :func:`point_contact`.

    >>> c = ball_contacts(1000.0, 12.3, 51.0, 0.515, 0.515)
    >>> round(float(c.inner.p_max)), round(float(c.outer.p_max))
    (1858, 1483)
    """
    rho = ball_raceway_curvatures(ball_diameter, pitch_diameter, f_i, f_o)
    return BallContacts(
        inner=point_contact(rho.inner_x, rho.inner_y, load, modulus, poisson, e_star=e_star),
        outer=point_contact(rho.outer_x, rho.outer_y, load, modulus, poisson, e_star=e_star),
    )


def ball_stiffness(
    ball_diameter: ArrayLike,
    pitch_diameter: ArrayLike,
    f_i: ArrayLike,
    f_o: ArrayLike,
    modulus: ArrayLike = E_STEEL,
    poisson: ArrayLike = NU_STEEL,
    *,
    e_star: ArrayLike | None = None,
) -> BallStiffness:
    """Hertz stiffness of a ball's inner and outer contacts and of both in series.

    K = (K_i^(-2/3) + K_o^(-2/3))^(-3/2), so that Q = K delta^1.5 with delta the total
    approach of the rings. Parameters as in :func:`ball_raceway_curvatures` and
    :func:`point_contact`; ``modulus`` E [MPa] and ``poisson`` nu [-] default to bearing steel
    (NSK: 208 000 MPa, 0.3).

    Returns
    -------
    BallStiffness
        ``inner``, ``outer``, ``ball`` [N/mm^1.5].

    >>> k = ball_stiffness(12.3, 51.0, 0.515, 0.515)
    >>> round(float(k.ball), -2)
    404600.0
    """
    fast = _ball_stiffness_scalar(ball_diameter, pitch_diameter, f_i, f_o, modulus, poisson, e_star)
    if fast is not None:
        return fast
    rho = ball_raceway_curvatures(ball_diameter, pitch_diameter, f_i, f_o)
    k_i = point_contact_stiffness(rho.inner_x, rho.inner_y, modulus, poisson, e_star=e_star)
    k_o = point_contact_stiffness(rho.outer_x, rho.outer_y, modulus, poisson, e_star=e_star)
    return BallStiffness(inner=k_i, outer=k_o, ball=series_stiffness(k_i, k_o))


def _ball_stiffness_scalar(
    D_w: Any, d_m: Any, f_i: Any, f_o: Any, E: Any, nu: Any, e_star: Any
) -> BallStiffness | None:
    """:func:`ball_stiffness` for plain scalars, else None: both contacts and the series in C
    (:mod:`bearingload._elliptic`, the compiled core's K_0 too: the same bits)."""
    plain = _plain(D_w, d_m, f_i, f_o, E, nu, 1.0 if e_star is None else e_star)
    if plain is None:
        return None
    dw, dm, fi, fo, e, n, es_given = plain
    low, high = validate.CONFORMITY_RANGE  # outside: the array path says why
    if not (0 < dw < dm and low < fi < high and low < fo < high):
        return None
    es = _scalar_modulus(e, n) if e_star is None else (es_given if es_given > 0 else None)
    inner = (2.0 * dm / (dw * (dm - dw)), (2.0 * fi - 1.0) / (fi * dw))
    outer = (2.0 * dm / (dw * (dm + dw)), (2.0 * fo - 1.0) / (fo * dw))
    if es is None:
        return None
    three = _elliptic.ball(*inner, *outer, es)
    return None if three is None else BallStiffness(*three)


def palmgren_line_deflection(
    load: ArrayLike, length: ArrayLike, coefficient: float = PALMGREN_LINE_COEFFICIENT
) -> Any:
    """Approach of one roller-raceway line contact, Palmgren: delta = c Q^0.9 / l^0.8. [mm]

    Empirical formula for steel rollers on steel raceways, c = 3.84e-5 with Q in N and l in
    mm (Palmgren, *Ball and Roller Bearing Engineering*, 3rd ed., Burbank, Philadelphia,
    1959; quoted by Harris & Kotzalas, *Rolling Bearing Analysis*, ch. 6, for one
    roller-raceway contact). It does not depend on the roller or raceway diameter nor on E,
    which is why the coefficient is steel-only. Some authors apply the same constant to the
    whole roller (both contacts in one), which makes the roller about 2.2 times stiffer than
    :func:`roller_stiffness`; pass ``coefficient`` to change it.

    Parameters
    ----------
    load : array_like
        Roller load Q >= 0. [N]
    length : array_like
        Effective contact length l > 0. [mm]
    coefficient : float
        c, default 3.84e-5. [mm N^-0.9 mm^0.8]

    >>> round(float(palmgren_line_deflection(1000.0, 10.0)), 7)
    0.0030502
    """
    q = validate.non_negative("load", load)
    length_ = validate.positive_number("length", length)
    return scalar_out(coefficient * q**0.9 / length_**0.8)


def palmgren_line_stiffness(
    length: ArrayLike, coefficient: float = PALMGREN_LINE_COEFFICIENT
) -> Any:
    """Stiffness of one roller-raceway contact, Q = K delta^(10/9). [N/mm^(10/9)]

    K = l^(8/9) / c^(10/9) = 8.06e4 l^(8/9) for c = 3.84e-5.

    Parameters as in :func:`palmgren_line_deflection`.

    >>> round(float(palmgren_line_stiffness(1.0)), -1)
    80590.0
    """
    length_ = validate.positive_number("length", length)
    return scalar_out(length_ ** (8.0 / 9.0) / coefficient ** (10.0 / 9.0))


def roller_stiffness(
    length_inner: ArrayLike,
    length_outer: ArrayLike | None = None,
    coefficient: float = PALMGREN_LINE_COEFFICIENT,
) -> Any:
    """Stiffness of a roller between two raceways, both contacts in series. [N/mm^(10/9)]

    K = (K_i^(-0.9) + K_o^(-0.9))^(-10/9) with the per-contact Palmgren stiffness of
    :func:`palmgren_line_stiffness`; equal lengths give K_i / 2^(10/9).

    Parameters
    ----------
    length_inner : array_like
        Effective length of the inner contact. [mm]
    length_outer : array_like, optional
        Effective length of the outer contact; default: same as inner. [mm]

    >>> round(float(roller_stiffness(1.0)), -1)
    37310.0
    """
    k_i = palmgren_line_stiffness(length_inner, coefficient)
    k_o = k_i if length_outer is None else palmgren_line_stiffness(length_outer, coefficient)
    return series_stiffness(k_i, k_o, LINE_EXPONENT)


class Kuzmenko2010BallConstant(
    NamedTuple(
        "Kuzmenko2010BallConstant",
        [
            ("e_star", float),
            ("sum_rho", float),
            ("A", float),
            ("B", float),
            ("A_over_B", float),
            ("n_delta", float),
            ("c1", float),
            ("c_v", float),
            ("c", float),
            ("k_contact", float),
            ("k_pair", float),
        ],
    )
):
    """Kuzmenko (2010), §3.4.2, step by step (kgf, mm, as in the paper).

    Attributes
    ----------
    e_star
        E* = E / (2 (1 - nu^2)); printed 1.1538e4. [kgf/mm^2]
    sum_rho
        2/R1 - 1/R2 + 1/R3; printed 0.2189. [1/mm]
    A
        (1/R1 - 1/R2)/2; printed 0.0023. [1/mm]
    B
        (1/R2 + 1/R3)/2 as printed (Hertz's B is (1/R1 + 1/R3)/2); printed 0.1048. [1/mm]
    A_over_B
        A/B; printed 0.0219 (= 0.0023/0.1048 with the rounded A and B). [-]
    n_delta
        Coefficient read from the printed table ([20], table 61): 0.55. [-]
    c1
        Compliance of one contact, delta = c1 Q^(2/3); printed 0.000425. [mm/kgf^(2/3)]
    c_v
        What the paper calls the ball constant: 1/c1; printed 2350. [kgf/mm^1.5 as labelled]
    c
        The paper's total, 2 c_v; printed 4700. [kgf/mm^1.5 as labelled]
    k_contact
        What c1 actually implies for one contact: c1^(-3/2). [kgf/mm^1.5]
    k_pair
        Two such contacts in series: (2 c1)^(-3/2). [kgf/mm^1.5]
    """

    __slots__ = ()


def kuzmenko2010_ball_constant(
    R1: float = 6.15,
    R2: float = 6.33,
    R3: float = 19.35,
    modulus: float = 2.1e4,
    poisson: float = 0.3,
    n_delta: float = 0.55,
) -> Kuzmenko2010BallConstant:
    """Repeat the ball-stiffness procedure of Kuzmenko (2010), §3.4.2, bearing 306.

    Kuzmenko, *Load distribution between balls in a radial ball bearing*, Problems of
    Tribology, 2010 (eq. 3.3 and the worked example after it). The paper writes
    the Hertz approach of the ball-inner ring contact as u0 = c1 Q^(2/3) with
    c1 = 0.655 n_delta (sum_rho / E*^2)^(1/3), takes n_delta = 0.55 from a printed table at
    A/B = 0.0219, obtains c1 = 0.000425 and then reports c_v = 2350 = 1/c1 and
    c = 2 c_v = 4700 kgf/mm^1.5 "doubling for the outer ring".

    Two steps do not follow from the formula: Q = K delta^(3/2) needs K = c1^(-3/2)
    (1.14e5 kgf/mm^1.5), not 1/c1; and two contacts in series add compliances,
    delta = (c1 + c1_o) Q^(2/3), which lowers the stiffness to (2 c1)^(-3/2) for two equal
    contacts instead of doubling it. Both alternatives are returned beside the paper's
    numbers; the exact Hertz value is :func:`ball_stiffness`.

    Parameters
    ----------
    R1, R2, R3 : float
        Ball, groove and inner-raceway radii. [mm]
    modulus, poisson : float
        Young's modulus E [kgf/mm^2] and Poisson's ratio nu [-].
    n_delta : float
        The table coefficient the paper used. [-]

    >>> k = kuzmenko2010_ball_constant()
    >>> round(k.c1, 6), round(k.c_v), round(k.c)
    (0.000425, 2352, 4704)
    """
    e_star = modulus / (2.0 * (1.0 - poisson**2))
    sum_rho = 2.0 / R1 - 1.0 / R2 + 1.0 / R3
    A = 0.5 * (1.0 / R1 - 1.0 / R2)
    B = 0.5 * (1.0 / R2 + 1.0 / R3)
    c1 = 0.655 * n_delta * (sum_rho / e_star**2) ** (1.0 / 3.0)
    return Kuzmenko2010BallConstant(
        e_star=e_star,
        sum_rho=sum_rho,
        A=A,
        B=B,
        A_over_B=A / B,
        n_delta=n_delta,
        c1=c1,
        c_v=1.0 / c1,
        c=2.0 / c1,
        k_contact=c1**-1.5,
        k_pair=(2.0 * c1) ** -1.5,
    )
