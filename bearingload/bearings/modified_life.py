"""Life in hours, reliability and the modified rating life of ISO 281:2007 (a_1, a_ISO).

ISO 281:2007, *Rolling bearings - Dynamic load ratings and rating life*:

* Life in operating hours (clause 3 and the makers' catalogues): ``L_h = L 10^6 / (60 n)``
  with L in 10^6 revolutions and the shaft speed n in r/min.
* Life modification factor for reliability a_1, Table 12: 1 at 90 % ... 0.077 at 99.95 %.
  Between the listed reliabilities this module uses the formula the table is derived from
  (a two-parameter Weibull distribution of slope 1.5 with the minimum life 0.05 L10):
  ``a_1 = 0.95 (ln(100/R) / ln(100/90))^(2/3) + 0.05``; at a listed reliability it returns the
  table's value.
* Modified rating life, clause 9.1: ``L_nm = a_1 a_ISO L_10``.
* Life modification factor a_ISO, clause 9.3.3 (radial ball bearings, eq. for 0.1 <= kappa < 0.4,
  0.4 <= kappa < 1, 1 <= kappa <= 4)::

      a_ISO = 0.1 [1 - (2.5671 - 2.2649 / kappa^0.054381)^0.83 (e_C C_u/P)^(1/3)]^(-9.3)
      a_ISO = 0.1 [1 - (2.5671 - 1.9987 / kappa^0.190870)^0.83 (e_C C_u/P)^(1/3)]^(-9.3)
      a_ISO = 0.1 [1 - (2.5671 - 1.9987 / kappa^0.071739)^0.83 (e_C C_u/P)^(1/3)]^(-9.3)

  and radial roller bearings::

      a_ISO = 0.1 [1 - (1.5859 - 1.3993 / kappa^0.054381) (e_C C_u/P)^0.4]^(-9.185)
      a_ISO = 0.1 [1 - (1.5859 - 1.2348 / kappa^0.190870) (e_C C_u/P)^0.4]^(-9.185)
      a_ISO = 0.1 [1 - (1.5859 - 1.2348 / kappa^0.071739) (e_C C_u/P)^0.4]^(-9.185)

  with ``a_ISO <= 50`` (the standard's limit; also where the bracket reaches 0), kappa > 4 taken
  as 4; kappa < 0.1 is outside the standard (this module takes 0.1 and the caller says so).
  The branches meet at kappa = 1 exactly and at 0.4 to the printed digits: within 0.1 % up to
  e_C C_u/P = 1, 0.3 % where a_ISO reaches its limit (balls; rollers 4e-5).
* Contamination factor e_C, Table 13, by level and pitch diameter D_pw (< 100 mm, >= 100 mm).
  The standard gives ranges for the intermediate levels; this module takes the middle of the range
  (:data:`CONTAMINATION`); give e_C itself where it is known better.
* Fatigue load limit C_u where the maker gives none: ISO 281:2007, Annex B (approximate)::

      ball bearings:   C_u = C_0 / 22               (D_pw <= 100 mm)
                       C_u = C_0 / 22 (100/D_pw)^0.5 (D_pw > 100 mm)
      roller bearings: C_u = C_0 / 8.2              (D_pw <= 100 mm)
                       C_u = C_0 / 8.2 (100/D_pw)^0.3 (D_pw > 100 mm)

The modified reference rating life of ISO/TS 16281:2008 (L_nmr) is here a_1 a_ISO L10r with a_ISO
evaluated at the dynamic equivalent reference load ``P_ref = C L10r^(-1/p)`` (the commonly
published form; the TS evaluates the contamination and lubrication term from the same ball loads
that give L10r, which P_ref sums up).

>>> round(float(reliability_factor(99.0)), 3)
0.25
>>> round(float(life_hours(169.0, 3000.0)), 1)
938.9
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload.errors import InputError
from bearingload.numerics import scalar_out
from bearingload.validate import finite_positive

if TYPE_CHECKING:
    from numpy.typing import ArrayLike

#: ISO 281:2007 Table 12: reliability [%] -> a_1 [-].
RELIABILITY_TABLE: dict[float, float] = {
    90.0: 1.0,
    95.0: 0.64,
    96.0: 0.55,
    97.0: 0.47,
    98.0: 0.37,
    99.0: 0.25,
    99.2: 0.22,
    99.4: 0.19,
    99.6: 0.16,
    99.8: 0.12,
    99.9: 0.093,
    99.92: 0.087,
    99.94: 0.080,
    99.95: 0.077,
}

#: ISO 281:2007 Table 13: level -> (e_C for D_pw < 100 mm, e_C for D_pw >= 100 mm) as ranges
#: (low, high) [-]; the middle of each range is used.
CONTAMINATION_RANGES: dict[str, tuple[tuple[float, float], tuple[float, float]]] = {
    "extreme": ((1.0, 1.0), (1.0, 1.0)),
    "high": ((0.6, 0.8), (0.8, 0.9)),
    "normal": ((0.5, 0.6), (0.6, 0.8)),
    "slight": ((0.3, 0.5), (0.4, 0.6)),
    "typical": ((0.1, 0.3), (0.2, 0.4)),
    "severe": ((0.0, 0.1), (0.0, 0.1)),
    "very-severe": ((0.0, 0.0), (0.0, 0.0)),
}
#: What each level means (ISO 281:2007 Table 13, abridged).
CONTAMINATION_WORDS: dict[str, str] = {
    "extreme": "extreme cleanliness (particles about the film thickness; laboratory)",
    "high": "high cleanliness (oil through an extremely fine filter; sealed, greased for life)",
    "normal": "normal cleanliness (oil through a fine filter; shielded, greased for life)",
    "slight": "slight contamination (slight contamination in the lubricant)",
    "typical": "typical contamination (no integral seals, coarse filter, wear particles)",
    "severe": "severe contamination (environment highly contaminated, insufficient sealing)",
    "very-severe": "very severe contamination",
}
#: The largest a_ISO the standard allows. [-]
A_ISO_MAX = 50.0
#: The range of kappa the a_ISO equations cover (ISO 281:2007, 9.3.3). [-]
KAPPA_RANGE = (0.1, 4.0)

#: (A, B_low, B_mid, B_high, outer exponent on the first bracket, load exponent, -final exponent)
_BALL = (2.5671, 2.2649, 1.9987, 1.9987, 0.83, 1.0 / 3.0, 9.3)
_ROLLER = (1.5859, 1.3993, 1.2348, 1.2348, 1.0, 0.4, 9.185)
_KAPPA_EXPONENTS = (0.054381, 0.190870, 0.071739)


def life_hours(revolutions: ArrayLike, speed: ArrayLike) -> Any:
    """Life in operating hours at a constant speed, L_h = L 10^6 / (60 n). [h]

    Parameters
    ----------
    revolutions : array_like
        Life L. [10^6 revolutions]
    speed : array_like
        Shaft speed n > 0 (of the rotating ring relative to the other). [r/min]

    >>> float(life_hours(60.0, 1000.0))
    1000.0
    """
    n = finite_positive("speed", speed)
    life = np.asarray(revolutions, dtype=float)
    with np.errstate(over="ignore"):
        hours = life * 1e6 / (60.0 * n)
    if np.any(np.isinf(hours) & np.isfinite(life)):
        raise InputError("speed", "is so small that the life in hours L 10^6/(60 n) overflows")
    return scalar_out(hours)


def reliability_factor(reliability: ArrayLike) -> Any:
    """Life modification factor for reliability a_1 (ISO 281:2007, Table 12). [-]

    Parameters
    ----------
    reliability : array_like
        Reliability R, 90 to 99.95. [%]

    Returns
    -------
    a_1: the table's value at a listed R; between two listed rows the Weibull law the table
    rounds, 0.95 (ln(100/R)/ln(100/90))^(2/3) + 0.05, times a factor interpolated linearly
    between the table-over-law ratios of the two rows (continuous, falling, exact at the rows).

    Raises
    ------
    InputError
        For R outside 90 to 99.95 %.

    >>> float(reliability_factor(90)), float(reliability_factor(99.95))
    (1.0, 0.077)
    >>> round(float(reliability_factor(93.0)), 4)
    0.7925
    """
    r = np.asarray(reliability, dtype=float)
    good = np.isfinite(r) & (r >= 90.0) & (r <= 99.95)
    if not np.all(good):
        worst = float(np.atleast_1d(r)[~np.atleast_1d(good)][0])
        raise InputError(
            "reliability", f"must lie between 90 and 99.95 % (ISO 281 Table 12); got {worst:g}"
        )
    listed = np.array(list(RELIABILITY_TABLE))
    values = np.array(list(RELIABILITY_TABLE.values()))
    # the Weibull law, scaled between two listed rows so that it meets the table at both: the
    # printed values are the law rounded, and taking the law as it is between them would jump
    # at each row (a_1(94.9999) = 0.6379 < a_1(95) = 0.64)
    between = _weibull(r) * np.interp(r, listed, values / _weibull(listed))
    exact = np.interp(r, listed, values)  # (equal to the table at a row, to the last bit)
    at_row = np.isin(r, listed)
    return scalar_out(np.asarray(np.where(at_row, exact, between), dtype=float))


def _weibull(r: np.ndarray) -> np.ndarray:
    """0.95 (ln(100/R)/ln(100/90))^(2/3) + 0.05, the law ISO 281's Table 12 rounds. [-]"""
    return 0.95 * (np.log(100.0 / r) / np.log(100.0 / 90.0)) ** (2.0 / 3.0) + 0.05


def contamination_factor(level: str, pitch_diameter: ArrayLike) -> Any:
    """Contamination factor e_C of a level of ISO 281:2007 Table 13, the middle of its range. [-]

    Parameters
    ----------
    level : str
        One of :data:`CONTAMINATION_RANGES` (extreme, high, normal, slight, typical, severe,
        very-severe).
    pitch_diameter : array_like
        D_pw; the table has a column for D_pw < 100 mm and one for D_pw >= 100 mm. [mm]

    >>> float(contamination_factor("normal", 38.5)), float(contamination_factor("normal", 150.0))
    (0.55, 0.7)
    """
    if level not in CONTAMINATION_RANGES:
        raise InputError(
            "contamination",
            f"unknown level {level!r}; allowed: {', '.join(CONTAMINATION_RANGES)}",
        )
    dpw = finite_positive("pitch_diameter", pitch_diameter)
    small, large = (sum(r) / 2.0 for r in CONTAMINATION_RANGES[level])
    return scalar_out(np.where(dpw < 100.0, small, large))


def fatigue_load_limit(static_rating: ArrayLike, pitch_diameter: ArrayLike, kind: str) -> Any:
    """Fatigue load limit C_u estimated from C_0 (ISO 281:2007, Annex B, approximate). [N]

    Parameters
    ----------
    static_rating : array_like
        Basic static load rating C_0. [N]
    pitch_diameter : array_like
        D_pw. [mm]
    kind : {"ball", "roller"}

    >>> round(float(fatigue_load_limit(7850.0, 38.5, "ball")), 2)
    356.82
    >>> round(float(fatigue_load_limit(22000.0, 400.0, "ball")), 2)
    500.0
    """
    c0 = finite_positive("static_rating", static_rating)
    dpw = finite_positive("pitch_diameter", pitch_diameter)
    divisor, power = (22.0, 0.5) if kind == "ball" else (8.2, 0.3)
    size = np.where(dpw > 100.0, (100.0 / dpw) ** power, 1.0)
    return scalar_out(c0 / divisor * size)


def clamp_kappa(kappa: ArrayLike) -> tuple[Any, list[str]]:
    """kappa limited to 0.1 ... 4 as ISO 281:2007 9.3.3 does, and a warning for each end met.

    >>> clamp_kappa(6.0)[0], clamp_kappa(0.05)[1][0][:28]
    (4.0, 'viscosity ratio kappa = 0.05')
    """
    k = np.asarray(kappa, dtype=float)
    low, high = KAPPA_RANGE
    out = []
    if np.any(k > high):
        out.append(
            f"viscosity ratio kappa = {np.max(k):.4g} is above 4: a_ISO uses kappa = 4 "
            "(ISO 281:2007, 9.3.3)"
        )
    if np.any(k < low):
        out.append(
            f"viscosity ratio kappa = {np.min(k):.4g} is below 0.1, outside ISO 281's a_ISO "
            "(9.3.3): a_ISO uses kappa = 0.1; expect a shorter life than printed"
        )
    return scalar_out(np.clip(k, low, high)), out


def life_modification_factor(kappa: ArrayLike, ec_cu_over_p: ArrayLike, kind: str = "ball") -> Any:
    """Life modification factor a_ISO of ISO 281:2007, 9.3.3, radial bearings. [-]

    Parameters
    ----------
    kappa : array_like
        Viscosity ratio nu/nu_1; limited to 0.1 ... 4 (:func:`clamp_kappa`). [-]
    ec_cu_over_p : array_like
        e_C C_u / P >= 0. [-]
    kind : {"ball", "roller"}

    Returns
    -------
    a_ISO, at most 50. [-]

    >>> round(float(life_modification_factor(1.0, 0.0)), 3)
    0.1
    >>> float(life_modification_factor(4.0, 5.0))
    50.0
    """
    if kind not in ("ball", "roller"):
        raise InputError("kind", f"must be 'ball' or 'roller'; got {kind!r}")
    k = np.clip(np.asarray(kappa, dtype=float), *KAPPA_RANGE)
    x = np.asarray(ec_cu_over_p, dtype=float)
    if not np.all(np.isfinite(x) & (x >= 0)):
        raise InputError("contamination", f"e_C C_u/P must be a finite number >= 0; got {x}")
    a, b_low, b_mid, b_high, outer, load_power, final = _BALL if kind == "ball" else _ROLLER
    e_low, e_mid, e_high = _KAPPA_EXPONENTS
    b = np.where(k < 0.4, b_low / k**e_low, np.where(k < 1.0, b_mid / k**e_mid, b_high / k**e_high))
    d = a - b  # > 0 for balls over 0.1 ... 4; for rollers -6e-5 at kappa = 0.1 (as printed)
    bracket = 1.0 - np.sign(d) * np.abs(d) ** outer * x**load_power
    with np.errstate(divide="ignore", over="ignore"):
        factor = np.where(
            bracket > 0, 0.1 * np.where(bracket > 0, bracket, 1.0) ** (-final), np.inf
        )
    return scalar_out(np.minimum(factor, A_ISO_MAX))
