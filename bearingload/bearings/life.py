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

from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload.constants import BALL_LIFE_EXPONENT, ROLLER_LIFE_EXPONENT  # noqa: E402,F401
from bearingload.errors import InputError
from bearingload.numerics import scalar_out
from bearingload.validate import finite_positive

if TYPE_CHECKING:
    from numpy.typing import ArrayLike


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


def angular_contact_tabulated(contact_angle: float) -> bool:
    """Whether ISO 281's X, Y of a single-row angular-contact ball bearing of this nominal
    contact angle are coded (15°, 20°, 25°, 30°, 35°, 40°, 45°; the table with its sources:
    :mod:`bearingload.bearings.angular_factors`). [°]"""
    from bearingload.bearings import angular_factors  # angular bearings only

    return angular_factors.tabulated(contact_angle)


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
    with the (e, X, Y) of :data:`bearingload.bearings.angular_factors.ANGULAR_FACTORS`; at 15°
    e and Y are interpolated linearly in ``f0 F_a/C0r`` (or in ``F_a/C0r`` where f0 is not
    known), the end rows held outside the table. F_a >= 0 is the thrust the bearing takes.

    Parameters
    ----------
    radial_load, axial_load : array_like
        F_r >= 0, F_a >= 0. [N]
    contact_angle : float
        Nominal contact angle: 15, 20, 25, 30, 35, 40 or 45. [°]
    C0, f0 : float, optional
        Basic static radial load rating [N] and factor f0 [-]; C0 is needed at 15°.

    >>> float(equivalent_load_angular_contact(1000.0, 2000.0, 40.0))
    1490.0
    >>> float(equivalent_load_angular_contact(1000.0, 1000.0, 40.0))
    1000.0
    >>> float(equivalent_load_angular_contact(1000.0, 2000.0, 20.0))
    2430.0
    """
    from bearingload.bearings import angular_factors  # angular bearings only

    fr, fa = _angular_loads(radial_load, axial_load)
    if abs(contact_angle - 15.0) < 1e-9:
        e, y, _, _ = _row_15(fa, C0, f0, 1)
        return _two_branches(fr, fa, e, (1.0, 0.0), (angular_factors.ANGULAR_15_X, y))
    row = angular_factors.fixed_row(contact_angle)
    return _two_branches(fr, fa, row.e, (1.0, 0.0), (row.x, row.y))


def equivalent_load_angular_pair(
    radial_load: ArrayLike,
    axial_load: ArrayLike,
    contact_angle: float,
    C0: float | None = None,
    f0: float | None = None,
) -> Any:
    """Dynamic equivalent load of a back-to-back or face-to-face pair of single-row
    angular-contact ball bearings taken as one bearing. [N]

    ISO 281:2007, 5.2, Table 3 (the pair as one double-row bearing): ``F_a/F_r <= e`` gives
    ``P = F_r + Y1 F_a``, else ``P = X2 F_r + Y2 F_a``
    (:data:`bearingload.bearings.angular_factors.ANGULAR_FACTORS`). At 15° e, Y1 and Y2 are
    interpolated linearly in ``i f0 F_a/C0r`` with i = 2 and C0r the pair's rating (twice one
    bearing's, ISO 76), or in ``i F_a/C0r`` where f0 is not known. At 45° the second branch is
    refused: its one printed Y2 is a misprint (:mod:`bearingload.bearings.angular_factors`).

    Parameters
    ----------
    radial_load, axial_load : array_like
        F_r >= 0 and F_a >= 0 on the pair. [N]
    contact_angle : float
        Nominal contact angle of both bearings: 15, 20, 25, 30, 35, 40 or 45. [°]
    C0, f0 : float, optional
        The pair's basic static radial load rating [N] and f0 [-]; C0 is needed at 15°.

    >>> float(equivalent_load_angular_pair(1000.0, 500.0, 40.0))
    1275.0
    >>> float(equivalent_load_angular_pair(1000.0, 2000.0, 40.0))
    2430.0
    """
    from bearingload.bearings import angular_factors  # angular bearings only

    fr, fa = _angular_loads(radial_load, axial_load)
    if abs(contact_angle - 15.0) < 1e-9:
        e, _, y1, y2 = _row_15(fa, C0, f0, 2)
        return _two_branches(fr, fa, e, (1.0, y1), (angular_factors.ANGULAR_15_PAIR_X2, y2))
    row = angular_factors.fixed_row(contact_angle)
    if row.pair_y2 is None:
        with np.errstate(divide="ignore", invalid="ignore"):
            beyond = np.any(np.where(fr > 0, fa > row.e * fr, fa > 0))
        if beyond:
            raise InputError(
                "axial_load",
                f"a pair at {contact_angle:g}° with F_a/F_r > e = {row.e:g} needs Y2, whose only "
                "printed value (PBF) is a misprint (docs/angular_contact.md): not computed",
            )
        return _two_branches(fr, fa, row.e, (1.0, row.pair_y1), (1.0, row.pair_y1))
    return _two_branches(fr, fa, row.e, (1.0, row.pair_y1), (row.pair_x2, row.pair_y2))


def _angular_loads(radial_load: ArrayLike, axial_load: ArrayLike) -> tuple[Any, Any]:
    """F_r, F_a as arrays, each finite and >= 0 (InputError naming the load otherwise)."""
    fr = np.asarray(radial_load, dtype=float)
    fa = np.asarray(axial_load, dtype=float)
    for name, v in (("radial_load", fr), ("axial_load", fa)):
        if not np.all(np.isfinite(v) & (v >= 0)):
            raise InputError(name, "must be a finite number >= 0 for an angular-contact bearing")
    return fr, fa


def _row_15(fa: Any, C0: float | None, f0: float | None, rows: int) -> tuple[Any, ...]:
    """e, Y, Y1, Y2 of the 15° row at the relative axial load ``i f0 F_a/C0r`` (or ``i F_a/C0r``
    without f0), ``i = rows``, linearly interpolated, the end rows held outside."""
    from bearingload.bearings import angular_factors  # angular bearings only

    c0 = finite_positive("C0", C0)
    if f0 is None:
        ratio, knots = rows * fa / c0, angular_factors.ANGULAR_15_FA_C0R
    else:
        ratio, knots = (
            rows * finite_positive("f0", f0) * fa / c0,
            angular_factors.ANGULAR_15_F0FA_C0R,
        )
    return tuple(
        np.interp(ratio, knots, col)
        for col in (
            angular_factors.ANGULAR_15_E,
            angular_factors.ANGULAR_15_Y,
            angular_factors.ANGULAR_15_PAIR_Y1,
            angular_factors.ANGULAR_15_PAIR_Y2,
        )
    )


def _two_branches(
    fr: Any, fa: Any, e: Any, within: tuple[Any, Any], beyond: tuple[Any, Any]
) -> Any:
    """``X F_r + Y F_a`` with (X, Y) = ``within`` for ``F_a/F_r <= e``, else ``beyond``. [N]"""
    with np.errstate(divide="ignore", invalid="ignore"):
        small = np.where(fr > 0, fa / np.where(fr > 0, fr, 1.0) <= e, fa == 0)
    p = np.where(small, within[0] * fr + within[1] * fa, beyond[0] * fr + beyond[1] * fa)
    return scalar_out(np.asarray(p, dtype=float))
