"""Lubrication of a rolling bearing: rated viscosity, viscosity ratio and the EHL film thickness.

* Rated viscosity nu_1, the viscosity needed for adequate lubrication, ISO 281:2007, 9.3.3
  (eq. for n < 1000 r/min and n >= 1000 r/min; the two meet within 2.4 % at 1000 r/min)::

      nu_1 = 45000 n^-0.83 D_pw^-0.5    (n < 1000 r/min)
      nu_1 = 4500 n^-0.5 D_pw^-0.5      (n >= 1000 r/min)      [mm^2/s, n in r/min, D_pw in mm]

  and the viscosity ratio kappa = nu / nu_1 (nu the operating kinematic viscosity).

* Minimum film thickness of an elliptical (point) contact, Hamrock and Dowson (1977), as given
  in Hamrock, Schmid and Jacobson, *Fundamentals of Machine Elements* (eq. for the fully flooded
  elastohydrodynamic contact)::

      h_min / R_x = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k)),   k = 1.03 (R_y/R_x)^0.64

  with U = eta_0 u / (E' R_x), G = alpha E', W = Q / (E' R_x^2), E' = 2 / ((1 - nu_a^2)/E_a +
  (1 - nu_b^2)/E_b) (twice Hertz's E*), u the mean rolling (entraining) speed of the surfaces.

* Minimum film thickness of a line contact, Dowson and Higginson (1977 form, same book)::

      h_min / R_x = 2.65 U^0.70 G^0.54 W'^-0.13,   W' = (Q / l) / (E' R_x)

* Entraining speed of a ball or roller between the rings, one ring fixed, the other turning at
  n [r/min] (Harris and Kotzalas, *Essential Concepts of Bearing Technology*, ch. 7; Hamrock,
  *Fundamentals of Fluid Film Lubrication*, ch. 24)::

      u = (D_pw^2 - D_w^2 cos^2 alpha) / (4 D_pw) * 2 pi n / 60

Dynamic viscosity eta_0 = rho nu, rho the oil's density (:data:`OIL_DENSITY` unless given);
the pressure-viscosity coefficient alpha of a mineral oil is about 2e-8 Pa^-1
(:data:`PRESSURE_VISCOSITY`).

>>> round(float(rated_viscosity(3000.0, 72.5)), 3)
9.649
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload.errors import InputError
from bearingload.numerics import scalar_out
from bearingload.validate import finite_positive

if TYPE_CHECKING:
    from numpy.typing import ArrayLike


def speed_needed(parameter: str) -> InputError:
    """The refusal of an operating viscosity without a shaft speed, naming ``parameter``: the
    viscosity, or the oil input that gives it (``oil``, ``viscosity_40`` ...), as the user typed
    it. The rated viscosity nu_1 (:func:`rated_viscosity`), which kappa compares the viscosity
    with, needs the speed. One message for solve's options, table life and batch's cells."""
    return InputError(parameter, "needs the shaft speed ('speed') for the rated viscosity nu_1")


#: Pressure-viscosity coefficient alpha of a mineral oil (default). [1/Pa]
PRESSURE_VISCOSITY = 2.2e-8
#: Density of a mineral oil at its operating temperature (default). [kg/m^3]
OIL_DENSITY = 870.0


def rated_viscosity(speed: ArrayLike, pitch_diameter: ArrayLike) -> Any:
    """Rated viscosity nu_1 of ISO 281:2007, 9.3.3. [mm^2/s]

    Parameters
    ----------
    speed : array_like
        Shaft speed n > 0. [r/min]
    pitch_diameter : array_like
        D_pw. [mm]

    >>> round(float(rated_viscosity(500.0, 38.5)), 3)
    41.719
    """
    n = finite_positive("speed", speed)
    dpw = finite_positive("pitch_diameter", pitch_diameter)
    slow = 45000.0 * n**-0.83 * dpw**-0.5
    fast = 4500.0 * n**-0.5 * dpw**-0.5
    return scalar_out(np.where(n < 1000.0, slow, fast))


def entraining_speed(
    speed: ArrayLike, ball_diameter: ArrayLike, pitch_diameter: ArrayLike, contact_angle: Any = 0.0
) -> Any:
    """Mean rolling speed u of the contacts, one ring fixed. [mm/s]

    Parameters
    ----------
    speed : array_like
        Speed n of the turning ring relative to the other. [r/min]
    ball_diameter, pitch_diameter : array_like
        D_w, D_pw. [mm]
    contact_angle : array_like
        alpha. [°]

    >>> round(float(entraining_speed(60.0 / (2 * np.pi), 10.0, 50.0)), 3)
    12.0
    """
    n = finite_positive("speed", speed)
    dw = finite_positive("ball_diameter", ball_diameter)
    dpw = finite_positive("pitch_diameter", pitch_diameter)
    c = np.cos(np.deg2rad(np.asarray(contact_angle, dtype=float)))
    return scalar_out((dpw**2 - (dw * c) ** 2) / (4.0 * dpw) * 2.0 * np.pi * n / 60.0)


def reduced_modulus(modulus: ArrayLike, poisson: ArrayLike) -> Any:
    """E' = E / (1 - nu^2) of two bodies of one material (Hamrock's E', twice Hertz's E*). [MPa]

    >>> round(float(reduced_modulus(208000.0, 0.3)), 1)
    228571.4
    """
    e = finite_positive("modulus", modulus)
    nu = np.asarray(poisson, dtype=float)
    return scalar_out(e / (1.0 - nu**2))


def _dimensionless(
    viscosity: ArrayLike, density: ArrayLike, u: ArrayLike, e_prime: ArrayLike, rx: ArrayLike
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(U, E' [Pa], R_x [m]) from mm^2/s, kg/m^3, mm/s, MPa, mm."""
    nu = finite_positive("viscosity", viscosity)
    eta = nu * 1e-6 * finite_positive("density", density)  # Pa s
    ep = finite_positive("modulus", e_prime) * 1e6
    r = finite_positive("R_x", rx) * 1e-3
    speed = finite_positive("speed", u) * 1e-3
    return eta * speed / (ep * r), ep, r


def film_point(
    load: ArrayLike,
    rx: ArrayLike,
    ry: ArrayLike,
    e_prime: ArrayLike,
    viscosity: ArrayLike,
    u: ArrayLike,
    pressure_viscosity: ArrayLike = PRESSURE_VISCOSITY,
    density: ArrayLike = OIL_DENSITY,
) -> Any:
    """Minimum film thickness of an elliptical contact, Hamrock and Dowson (1977). [mm]

    Parameters
    ----------
    load : array_like
        Contact load Q > 0. [N]
    rx, ry : array_like
        Effective radii across and along the rolling direction (R_x in the rolling direction's
        plane of curvature: 1/R_x = 1/r_ax + 1/r_bx). [mm]
    e_prime : array_like
        E' of the pair (:func:`reduced_modulus`). [MPa]
    viscosity : array_like
        Kinematic viscosity nu of the oil at the inlet. [mm^2/s]
    u : array_like
        Mean rolling speed. [mm/s]
    pressure_viscosity : array_like
        alpha. [1/Pa]
    density : array_like
        rho. [kg/m^3]

    >>> h = film_point(1000.0, 5.0, 50.0, 228571.4, 20.0, 5000.0)
    >>> round(float(h) * 1e3, 4)  # µm
    0.2788
    """
    big_u, ep, r = _dimensionless(viscosity, density, u, e_prime, rx)
    q = finite_positive("load", load)
    g = finite_positive("pressure_viscosity", pressure_viscosity) * ep
    w = q / (ep * r**2)
    k = 1.03 * (finite_positive("R_y", ry) / (r * 1e3)) ** 0.64
    h = 3.63 * big_u**0.68 * g**0.49 * w**-0.073 * (1.0 - np.exp(-0.68 * k))
    return scalar_out(h * r * 1e3)


def film_line(
    load: ArrayLike,
    length: ArrayLike,
    rx: ArrayLike,
    e_prime: ArrayLike,
    viscosity: ArrayLike,
    u: ArrayLike,
    pressure_viscosity: ArrayLike = PRESSURE_VISCOSITY,
    density: ArrayLike = OIL_DENSITY,
) -> Any:
    """Minimum film thickness of a line contact, Dowson and Higginson (1977 form). [mm]

    Parameters as :func:`film_point`, with ``length`` the contact length l [mm] instead of R_y.

    >>> h = film_line(5000.0, 10.0, 4.0, 228571.4, 20.0, 5000.0)
    >>> round(float(h) * 1e3, 4)  # µm
    0.2711
    """
    big_u, ep, r = _dimensionless(viscosity, density, u, e_prime, rx)
    w_line = finite_positive("load", load) / (finite_positive("length", length) * 1e-3)
    g = finite_positive("pressure_viscosity", pressure_viscosity) * ep
    w = w_line / (ep * r)
    h = 2.65 * big_u**0.70 * g**0.54 * w**-0.13
    return scalar_out(h * r * 1e3)


def rolling_radii(
    ball_diameter: float, pitch_diameter: float, contact_angle: ArrayLike = 0.0
) -> tuple[Any, Any]:
    """(R_x inner, R_x outer) in the rolling direction of a ball or roller. [mm]

    R_x = D_w (D_pw -+ D_w cos alpha) / (2 D_pw) (inner -, outer +).

    >>> rolling_radii(10.0, 50.0)
    (4.0, 6.0)
    """
    c = scalar_out(np.cos(np.deg2rad(np.asarray(contact_angle, dtype=float))))
    rx_i = ball_diameter * (pitch_diameter - ball_diameter * c) / (2.0 * pitch_diameter)
    rx_o = ball_diameter * (pitch_diameter + ball_diameter * c) / (2.0 * pitch_diameter)
    return rx_i, rx_o


def ball_radii(
    ball_diameter: float, pitch_diameter: float, f_i: float, f_o: float, contact_angle: ArrayLike
) -> tuple[tuple[Any, float], tuple[Any, float]]:
    """((R_x, R_y) inner, (R_x, R_y) outer) of a ball in its grooves. [mm]

    >>> [tuple(round(v, 3) for v in r) for r in ball_radii(10.0, 50.0, 0.52, 0.53, 0.0)]
    [(4.0, 130.0), (6.0, 88.333)]
    """
    rx_i, rx_o = rolling_radii(ball_diameter, pitch_diameter, contact_angle)
    ry_i = f_i * ball_diameter / (2.0 * f_i - 1.0)
    ry_o = f_o * ball_diameter / (2.0 * f_o - 1.0)
    return (rx_i, ry_i), (rx_o, ry_o)
