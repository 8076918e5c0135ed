"""Basic rating life of a rolling bearing and the load it may carry for a wanted life.

Lundberg-Palmgren / ISO 281 basic rating life, in millions of revolutions::

    L10 = (C / P)^p,    p = 3 for ball bearings, 10/3 for roller bearings

with the basic dynamic load rating C and the equivalent dynamic load P (P = F_r for a purely
radial load on a radial bearing). Solved for the load it gives the load a bearing may carry for
L millions of revolutions, P = C / L^(1/p); Kuzmenko (2010, §3.2) writes this as the
allowable load Q = C / N^(1/3) and works it for bearing 306 (C = 2200 kgf): 666 kgf for
N = 36 x 10^6 revolutions.

Units: C and P in any one force unit (the result is in the same unit); life in
[10^6 revolutions].

>>> round(float(rating_life(2200.0, 300.0)), 1)
394.4
>>> round(float(allowable_load(2200.0, 36.0)), 1)
666.3
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from bearingload.constants import BALL_LIFE_EXPONENT, ROLLER_LIFE_EXPONENT  # noqa: E402,F401
from bearingload.errors import InputError
from bearingload.numerics import scalar_out
from bearingload.validate import finite_positive


def rating_life(C: ArrayLike, P: ArrayLike, exponent: ArrayLike = BALL_LIFE_EXPONENT) -> Any:
    """Basic rating life L10 = (C/P)^p. [10^6 revolutions]

    Parameters
    ----------
    C : array_like
        Basic dynamic load rating. [N, or any force unit]
    P : array_like
        Equivalent dynamic load, in the unit of ``C``; F_r for a purely radial load.
    exponent : float, default 3
        Life exponent p: 3 for balls, 10/3 for rollers. [-]

    Returns
    -------
    numpy scalar or ndarray
        Life reached or exceeded by 90 % of a large group of bearings. [10^6 rev]

    Raises
    ------
    InputError
        For a non-positive or non-finite C, P or exponent.

    >>> float(rating_life(3000.0, 300.0))
    1000.0
    """
    c = finite_positive("C", C)
    p = finite_positive("load", P)
    e = finite_positive("exponent", exponent)
    with np.errstate(over="ignore"):
        life = (c / p) ** e
    if not np.all(np.isfinite(life)):
        raise InputError("load", "is so small that the rating life (C/P)^p overflows")
    return scalar_out(life)


def allowable_load(
    C: ArrayLike, revolutions: ArrayLike, exponent: ArrayLike = BALL_LIFE_EXPONENT
) -> Any:
    """Equivalent load that gives a basic rating life of ``revolutions``: P = C / L^(1/p).

    Kuzmenko (2010), §3.2: Q = C / N^(1/3); for C = 2200 kgf and N = 36 (10^6 rev) the paper
    prints 666 kgf (2200 / 36^(1/3) = 666.3).

    Parameters
    ----------
    C : array_like
        Basic dynamic load rating. [N, or any force unit]
    revolutions : array_like
        Wanted basic rating life L. [10^6 revolutions]
    exponent : float, default 3
        Life exponent p: 3 for balls, 10/3 for rollers. [-]

    Returns
    -------
    numpy scalar or ndarray
        Allowable equivalent load, in the unit of ``C``.

    Raises
    ------
    InputError
        For a non-positive or non-finite argument.

    >>> round(float(allowable_load(2200.0, 360.0)), 1)
    309.3
    """
    c = finite_positive("C", C)
    n = finite_positive("revolutions", revolutions)
    e = finite_positive("exponent", exponent)
    return scalar_out(c / n ** (1.0 / e))


#: ISO 281:2007, 5.2 (dynamic equivalent radial load of radial ball bearings), Table 3, single-row
#: radial (deep-groove) ball bearings with normal clearance: rows of f0 F_a / C0r with e and Y
#: (X = 0.56) for F_a/F_r > e; for F_a/F_r <= e, X = 1 and Y = 0. Intermediate values by linear
#: interpolation, as the standard says.
ISO281_DEEP_GROOVE_F0FA_C0R = (0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89)
ISO281_DEEP_GROOVE_E = (0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44)
ISO281_DEEP_GROOVE_Y = (2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00)
ISO281_DEEP_GROOVE_X = 0.56


def equivalent_load_deep_groove(
    radial_load: ArrayLike, axial_load: ArrayLike, C0: ArrayLike, f0: ArrayLike
) -> Any:
    """Dynamic equivalent radial load P = X F_r + Y F_a of a deep-groove ball bearing. [N]

    ISO 281:2007, clause 5.2, Table 3 (single row, normal clearance): with
    ``r = f0 F_a / C0r`` the factor ``e`` and ``Y`` are interpolated linearly in the table;
    ``F_a/F_r <= e`` gives ``P = F_r``, else ``P = 0.56 F_r + Y F_a``. Outside the table
    (``r < 0.172`` or ``r > 6.89``) the end rows are used. Only the normal-clearance columns are
    implemented: the standard's factors for other clearance groups were not checked against a
    source for this package.

    Parameters
    ----------
    radial_load : array_like
        F_r >= 0. [N]
    axial_load : array_like
        F_a (its size is used). [N]
    C0 : array_like
        Basic static radial load rating C0r. [N]
    f0 : array_like
        Factor f0 of the bearing (catalogue; ISO 76). [-]

    >>> round(float(equivalent_load_deep_groove(1000.0, 1000.0, 11200.0, 13.2)), 1)
    2067.6
    >>> float(equivalent_load_deep_groove(1000.0, 100.0, 11200.0, 13.2))
    1000.0
    """
    fr = np.asarray(radial_load, dtype=float)
    if not np.all(np.isfinite(fr) & (fr >= 0)):
        raise InputError("radial_load", f"must be a finite number >= 0; got {radial_load!r}")
    fa = np.abs(np.asarray(axial_load, dtype=float))
    if not np.all(np.isfinite(fa)):
        raise InputError("axial_load", f"must be a finite number; got {axial_load!r}")
    c0 = finite_positive("C0", C0)
    f_0 = finite_positive("f0", f0)
    ratio = f_0 * fa / c0
    e = np.interp(ratio, ISO281_DEEP_GROOVE_F0FA_C0R, ISO281_DEEP_GROOVE_E)
    y = np.interp(ratio, ISO281_DEEP_GROOVE_F0FA_C0R, ISO281_DEEP_GROOVE_Y)
    with np.errstate(divide="ignore", invalid="ignore"):
        small = np.where(fr > 0, fa / np.where(fr > 0, fr, 1.0) <= e, fa == 0)
    p = np.where(small, fr, ISO281_DEEP_GROOVE_X * fr + y * fa)
    return scalar_out(np.asarray(p, dtype=float))


#: ISO 281:2007, 5.2, Table 3, single-row angular-contact ball bearings (single bearing or
#: tandem), F_a/F_r > e: contact angle [°] -> (e, X, Y); F_a/F_r <= e gives X = 1, Y = 0.
#: Only the rows checked against a public restatement are coded, each with its source:
#: 25°: LYC Bearing, "Equivalent dynamic load - angular contact ball bearings", Table 2
#: (e 0.68, P = 0.41 F_r + 0.87 F_a); 30°: JTEKT/Koyo technical section 3.1 "Calculation of
#: equivalent radial / axial load" (e 0.8, X 0.39, Y 0.76; NTN's catalogue prints the same);
#: 40°: Koyo (e 1.14, X 0.35, Y 0.57), LYC Table 2 (the same) and NSK's BEA leaflet. The 20°,
#: 35° and 45° rows of the standard were not found in a public restatement: not coded.
ISO281_ANGULAR_FACTORS: dict[float, tuple[float, float, float]] = {
    25.0: (0.68, 0.41, 0.87),
    30.0: (0.80, 0.39, 0.76),
    40.0: (1.14, 0.35, 0.57),
}
#: The 15° row depends on the axial load: X = 0.44 and e, Y interpolated linearly in
#: i f0 F_a / C0r (i = 1 for a single bearing) as the standard's note says. Source: Koyo's
#: technical section 3.1 (above): i f0 F_a/C0r 0.178, 0.357, 0.714, 1.07, 1.43, 2.14, 3.57,
#: 5.35, with e 0.38 ... 0.56 and Y 1.47 ... 1.00; LYC's Table 3 prints the same e, Y against
#: F_a/C0 (0.015 ... 0.44, the column of ISO 281:1990). Koyo's last row is misprinted (5.35
#: twice, NSK prints 7.14); its e and Y equal those of 5.35 (0.56, 1.00), so beyond 5.35 the
#: end row holds and the 7.14 knot changes nothing.
ISO281_ANGULAR_15_F0FA_C0R = (0.178, 0.357, 0.714, 1.07, 1.43, 2.14, 3.57, 5.35)
ISO281_ANGULAR_15_E = (0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56)
ISO281_ANGULAR_15_Y = (1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00)
ISO281_ANGULAR_15_X = 0.44
#: The same 15° row against F_a/C0r (LYC Table 3; ISO 281:1990), used where f0 is not known.
ISO281_ANGULAR_15_FA_C0R = (0.015, 0.029, 0.058, 0.087, 0.12, 0.17, 0.29, 0.44)


def angular_contact_tabulated(contact_angle: float) -> bool:
    """Whether ISO 281's X, Y of a single-row angular-contact ball bearing of this nominal
    contact angle are coded (15°, 25°, 30°, 40°; see :data:`ISO281_ANGULAR_FACTORS`). [°]"""
    return any(abs(contact_angle - a) < 1e-9 for a in (15.0, *ISO281_ANGULAR_FACTORS))


def equivalent_load_angular_contact(
    radial_load: ArrayLike,
    axial_load: ArrayLike,
    contact_angle: float,
    C0: float | None = None,
    f0: float | None = None,
) -> Any:
    """Dynamic equivalent load P = X F_r + Y F_a of a single-row angular-contact ball bearing
    (single, or tandem). [N]

    ISO 281:2007, 5.2, Table 3: ``F_a/F_r <= e`` gives ``P = F_r``, else ``P = X F_r + Y F_a``
    with the (e, X, Y) of :data:`ISO281_ANGULAR_FACTORS`; at 15° e and Y are interpolated
    linearly in ``f0 F_a/C0r`` (or in ``F_a/C0r`` where f0 is not known), the end rows held
    outside the table. F_a >= 0 is the thrust the bearing takes.

    Parameters
    ----------
    radial_load, axial_load : array_like
        F_r >= 0, F_a >= 0. [N]
    contact_angle : float
        Nominal contact angle: 15, 25, 30 or 40. [°]
    C0, f0 : float, optional
        Basic static radial load rating [N] and factor f0 [-]; C0 is needed at 15°.

    >>> float(equivalent_load_angular_contact(1000.0, 2000.0, 40.0))
    1490.0
    >>> float(equivalent_load_angular_contact(1000.0, 1000.0, 40.0))
    1000.0
    """
    fr = np.asarray(radial_load, dtype=float)
    fa = np.asarray(axial_load, dtype=float)
    for name, v in (("radial_load", fr), ("axial_load", fa)):
        if not np.all(np.isfinite(v) & (v >= 0)):
            raise InputError(name, "must be a finite number >= 0 for an angular-contact bearing")
    if not angular_contact_tabulated(contact_angle):
        raise InputError(
            "contact_angle",
            f"ISO 281's X, Y are coded for 15, 25, 30 and 40°; got {contact_angle:g}°",
        )
    if abs(contact_angle - 15.0) < 1e-9:
        c0 = finite_positive("C0", C0)
        if f0 is None:
            ratio, knots = fa / c0, ISO281_ANGULAR_15_FA_C0R
        else:
            ratio, knots = finite_positive("f0", f0) * fa / c0, ISO281_ANGULAR_15_F0FA_C0R
        e = np.interp(ratio, knots, ISO281_ANGULAR_15_E)
        x, y = ISO281_ANGULAR_15_X, np.interp(ratio, knots, ISO281_ANGULAR_15_Y)
    else:
        key = min(ISO281_ANGULAR_FACTORS, key=lambda a: abs(a - contact_angle))
        e, x, y = ISO281_ANGULAR_FACTORS[key]
    with np.errstate(divide="ignore", invalid="ignore"):
        small = np.where(fr > 0, fa / np.where(fr > 0, fr, 1.0) <= e, fa == 0)
    p = np.where(small, fr, x * fr + y * fa)
    return scalar_out(np.asarray(p, dtype=float))
