"""Basic rating life of a rolling bearing and the load it may carry for a wanted life.

Lundberg-Palmgren / ISO 281 basic rating life, in millions of revolutions::

    L10 = (C / P)^p,    p = 3 for ball bearings, 10/3 for roller bearings

with the basic dynamic load rating C and the equivalent dynamic load P (P = F_r for a purely
radial load on a radial bearing). Solved for the load it gives the load a bearing may carry for
L millions of revolutions, P = C / L^(1/p); Kuzmenko (2010, seed 000, §3.2) writes this as the
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

from bearingload.errors import InputError
from bearingload.validate import finite_positive

#: Life exponent p of ball bearings (ISO 281). [-]
BALL_LIFE_EXPONENT = 3.0
#: Life exponent p of roller bearings (ISO 281). [-]
ROLLER_LIFE_EXPONENT = 10.0 / 3.0


def _out(x: np.ndarray) -> Any:
    return x[()] if x.ndim == 0 else x


def rating_life(C: ArrayLike, P: ArrayLike, exponent: float = BALL_LIFE_EXPONENT) -> Any:
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
    return _out(life)


def allowable_load(
    C: ArrayLike, revolutions: ArrayLike, exponent: float = BALL_LIFE_EXPONENT
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
    return _out(c / n ** (1.0 / e))
