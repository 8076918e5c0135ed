"""The viscosity of an oil at its operating temperature: ISO 3448 grades and ASTM D341 (Walther).

* ISO 3448 viscosity grades (ISO VG): the grade's number is the mid-point kinematic viscosity at
  40 °C in mm^2/s, within +-10 % (ISO 3448:1992, Table 1; reproduced e.g. in AIMS Industrial's
  "Oil viscosity chart", VG 22 = 19.8-24.2 ... VG 460 = 414-506 cSt at 40 °C). The mid-points of
  the 20 grades are :data:`ISO_VG`.
* ASTM D341 viscosity-temperature relation (Walther's equation), for kinematic viscosities of
  2 mm^2/s and more::

      log10 log10(nu + 0.7) = A - B log10 T        (nu in mm^2/s, T in K = °C + 273.15)

  A and B from two known points (nu_1, T_1), (nu_2, T_2)::

      B = (log log(nu_1 + 0.7) - log log(nu_2 + 0.7)) / (log T_2 - log T_1)
      A = log log(nu_1 + 0.7) + B log T_1

  The form and this solution are as ASTM D341 prints them (and as a published worked example:
  nu = 32 cSt at 40 °C, 5.4 cSt at 100 °C, T = °C + 273: A = 9.5259, B = 3.7449, 8.5 cSt at
  80 °C; the tests check it).

Why nu_100 is an input rather than a viscosity index: the kinematic viscosity at 100 °C of an oil
of a given VI follows from ASTM D2270's Table 1 (the L and H reference viscosities for nu_100 =
2 to 70 mm^2/s), which is not reproduced here from a source that could be checked (see
docs/life.md). An oil maker's datasheet prints nu_40 and nu_100; give both, or the grade and
nu_100.

>>> round(viscosity_at(68.0, 8.6, 70.0), 2)  # VG68, nu_100 = 8.6 mm^2/s, at 70 °C
19.97
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from bearingload.errors import InputError
from bearingload.numerics import scalar_out

#: ISO 3448 grades: VG number -> mid-point kinematic viscosity at 40 °C. [mm^2/s]
ISO_VG: dict[int, float] = {
    2: 2.2, 3: 3.2, 5: 4.6, 7: 6.8, 10: 10.0, 15: 15.0, 22: 22.0, 32: 32.0, 46: 46.0, 68: 68.0,
    100: 100.0, 150: 150.0, 220: 220.0, 320: 320.0, 460: 460.0, 680: 680.0, 1000: 1000.0,
    1500: 1500.0, 2200: 2200.0, 3200: 3200.0,
}  # fmt: skip
#: The tolerance of a grade's viscosity at 40 °C about its mid-point (ISO 3448). [-]
ISO_VG_TOLERANCE = 0.10
#: 0 °C in kelvin (ASTM D341 takes T = t + 273.15). [K]
ZERO_CELSIUS = 273.15
#: The smallest kinematic viscosity the plain Walther form (the constant 0.7) covers. [mm^2/s]
WALTHER_MIN = 2.0


def iso_grade(text: str) -> float:
    """The mid-point viscosity at 40 °C of an ISO 3448 grade written VG68, ISO VG 68 or 68.
    [mm^2/s]

    >>> iso_grade("VG68"), iso_grade("iso vg 1000")
    (68.0, 1000.0)
    """
    match = re.fullmatch(r"\s*(?:iso\s*)?(?:vg\s*)?(\d+)\s*", str(text), flags=re.IGNORECASE)
    grade = int(match.group(1)) if match else None
    if grade not in ISO_VG:
        raise InputError(
            "oil",
            f"unknown ISO 3448 grade {text!r}; allowed: " + ", ".join(f"VG{g}" for g in ISO_VG),
        )
    return ISO_VG[grade]


def walther_constants(
    nu_1: ArrayLike, t_1: ArrayLike, nu_2: ArrayLike, t_2: ArrayLike
) -> tuple[Any, Any]:
    """(A, B) of ASTM D341's log log(nu + 0.7) = A - B log T through two points. [-]

    Parameters
    ----------
    nu_1, nu_2 : array_like
        Kinematic viscosities at T_1 and T_2, at least 2. [mm^2/s]
    t_1, t_2 : array_like
        Absolute temperatures, T_1 != T_2. [K]

    >>> [round(v, 4) for v in walther_constants(32.0, 313.0, 5.4, 373.0)]
    [9.5259, 3.7449]
    """
    n1, n2 = np.asarray(nu_1, dtype=float), np.asarray(nu_2, dtype=float)
    k1, k2 = np.asarray(t_1, dtype=float), np.asarray(t_2, dtype=float)
    if not np.all(np.isfinite(n1) & np.isfinite(n2) & (n1 >= WALTHER_MIN) & (n2 >= WALTHER_MIN)):
        raise InputError(
            "viscosity_100",
            f"ASTM D341's Walther form needs viscosities of {WALTHER_MIN:g} mm^2/s or more; got "
            f"{n1} and {n2}",
        )
    if not np.all(np.isfinite(k1) & np.isfinite(k2) & (k1 > 0) & (k2 > 0) & (k1 != k2)):
        raise InputError("temperature", "needs two different absolute temperatures > 0 K")
    y1, y2 = np.log10(np.log10(n1 + 0.7)), np.log10(np.log10(n2 + 0.7))
    b = (y1 - y2) / (np.log10(k2) - np.log10(k1))
    return scalar_out(y1 + b * np.log10(k1)), scalar_out(b)


def viscosity_at(nu_40: ArrayLike, nu_100: ArrayLike, temperature: ArrayLike) -> Any:
    """Kinematic viscosity at ``temperature`` from those at 40 and 100 °C (ASTM D341). [mm^2/s]

    Parameters
    ----------
    nu_40, nu_100 : array_like
        Kinematic viscosities at 40 °C and 100 °C, nu_40 > nu_100 >= 2. [mm^2/s]
    temperature : array_like
        Operating temperature. [°C]

    >>> round(viscosity_at(32.0, 5.4, 40.0), 9), round(viscosity_at(32.0, 5.4, 100.0), 9)
    (32.0, 5.4)
    """
    n40, n100 = np.asarray(nu_40, dtype=float), np.asarray(nu_100, dtype=float)
    if not np.all(n40 > n100):
        raise InputError(
            "viscosity_100",
            f"must be below the viscosity at 40 °C (an oil thins as it warms); got {n100} "
            f"against {n40} mm^2/s",
        )
    t = np.asarray(temperature, dtype=float) + ZERO_CELSIUS
    a, b = walther_constants(n40, 40.0 + ZERO_CELSIUS, n100, 100.0 + ZERO_CELSIUS)
    nu = np.asarray(walther_viscosity(a, b, t), dtype=float)
    # the form's range, as for its inputs (a rounding below nu_100 = 2 itself is kept)
    if not np.all(np.isfinite(nu) & (nu >= WALTHER_MIN * (1.0 - 1e-12))):
        raise InputError(
            "temperature",
            f"ASTM D341's Walther form covers {WALTHER_MIN:g} mm^2/s or more and finite; at "
            f"{np.asarray(temperature, dtype=float)} °C it gives {nu} mm^2/s for this oil: give "
            "a temperature where it stays in that range, or the operating viscosity itself",
        )
    return scalar_out(nu)


def walther_viscosity(a: ArrayLike, b: ArrayLike, temperature: ArrayLike) -> Any:
    """nu = 10^(10^(A - B log10 T)) - 0.7 of ASTM D341 at the absolute ``temperature`` [K].
    [mm^2/s]

    >>> round(walther_viscosity(9.5259, 3.7449, 353.0), 1)  # 80 °C of the worked example
    8.5
    """
    t = np.asarray(temperature, dtype=float)
    if not np.all(np.isfinite(t) & (t > 0)):
        raise InputError("temperature", f"must be an absolute temperature > 0 K; got {t}")
    with np.errstate(over="ignore"):
        nu = 10.0 ** (
            10.0 ** (np.asarray(a, dtype=float) - np.asarray(b, dtype=float) * np.log10(t))
        )
    return scalar_out(nu - 0.7)
