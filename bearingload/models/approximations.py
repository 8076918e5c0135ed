"""Classical one-line estimates of the maximum rolling-element load: Stribeck and Palmgren.

Both give ``Q_max = C F_r / (i z cos(alpha))`` with a constant ``C``: Stribeck's 4.37 is the zero-
clearance value for point contact (``1/J_r(1/2)`` of the continuum model, see
:mod:`bearingload.models.continuum`), Palmgren's 5 allows for a normal operating clearance. They ignore
the clearance, the load level and the cage position; use :mod:`bearingload.models.equilibrium` or
:mod:`bearingload.models.continuum` when those matter.

References
----------
.. [1] Stribeck R. Kugellager für beliebige Belastungen. Zeitschrift des Vereines deutscher
   Ingenieure, 1901, vol. 45, pp. 73-79, 118-125 (cited as ref. [2] by Kuzmenko 2010).
.. [2] Palmgren A. Ball and Roller Bearing Engineering, 3rd ed. Philadelphia: SKF Industries,
   1959 (the factor 5 for bearings with normal clearance).
.. [3] Radial stiffness of rolling bearings for crane dynamics (in Russian). Eastern-European
   Journal of Enterprise Technologies, 2009, no. 1/5(37), pp. 47-50, eq. (2):
   ``Q = 5 F_r / (i z cos(alpha))``.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from bearingload import validate
from bearingload.errors import InputError

#: Stribeck's constant: Q_max = 4.37 F_r / z (point contact, zero clearance). [-]
STRIBECK_CONSTANT = 4.37
#: Palmgren's constant: Q_max = 5 F_r / (i z cos alpha) (normal clearance). [-]
PALMGREN_CONSTANT = 5.0


class Approximation(NamedTuple):
    """Result of a one-line estimate.

    Attributes
    ----------
    k : float or ndarray
        Load factor ``Q_max/F_r``. [-]
    q_max : float or ndarray
        Load on the most loaded rolling element. [N]
    """

    k: Any
    q_max: Any


def stribeck(balls: Any, load: Any, constant: Any = STRIBECK_CONSTANT) -> Approximation:
    """Stribeck's estimate ``Q_max = 4.37 F_r / z`` (Stribeck 1901).

    Valid for a single-row radial ball bearing with zero clearance (the exact continuum value of the
    constant is ``1/J_r(1/2) = 4.3701``; the discrete sums give 4.08-4.54 for z = 5-30, Kuzmenko
    2010, Table 1).

    Parameters
    ----------
    balls : int or array_like
        Number of balls ``z`` (whole number >= 1). [-]
    load : float or array_like
        Radial load ``F_r > 0``. [N]
    constant : float or array_like, default 4.37
        Stribeck's constant. [-]

    Returns
    -------
    Approximation
        ``k = constant/z`` [-] and ``q_max = k F_r`` [N]; floats for scalar input.

    Examples
    --------
    >>> stribeck(8, 1000.0)
    Approximation(k=0.54625, q_max=546.25)
    """
    return _estimate(balls, load, constant, 1, 0.0)


def palmgren(
    balls: Any,
    load: Any,
    constant: Any = PALMGREN_CONSTANT,
    *,
    rows: Any = 1,
    contact_angle: Any = 0.0,
) -> Approximation:
    """Palmgren's estimate ``Q_max = 5 F_r / (i z cos(alpha))`` (Palmgren 1959; the crane paper (2009), eq. 2).

    The factor 5 instead of Stribeck's 4.37 allows for a normal radial clearance.

    Parameters
    ----------
    balls : int or array_like
        Number of rolling elements per row ``z`` (whole number >= 1). [-]
    load : float or array_like
        Radial load ``F_r > 0``. [N]
    constant : float or array_like, default 5
        Palmgren's constant. [-]
    rows : int or array_like, default 1
        Number of rows ``i`` (whole number >= 1). [-]
    contact_angle : float or array_like, default 0
        Contact angle ``alpha``, 0 <= alpha < 90. [°]

    Returns
    -------
    Approximation
        ``k = constant/(i z cos alpha)`` [-] and ``q_max = k F_r`` [N].

    Examples
    --------
    >>> palmgren(8, 1000.0)
    Approximation(k=0.625, q_max=625.0)
    """
    return _estimate(balls, load, constant, rows, contact_angle)


def _estimate(balls: Any, load: Any, constant: Any, rows: Any, angle: Any) -> Approximation:
    z = validate.ball_count(balls)
    force = validate.positive("load", load, "N")
    c = validate.positive("constant", constant, "")
    i = validate.ball_count(rows, name="rows")
    alpha = validate.finite("contact_angle", angle)
    if np.any((alpha < 0) | (alpha >= 90.0)):
        raise InputError("contact_angle", "must be at least 0° and less than 90°")
    k = c / (i * z * np.cos(np.deg2rad(alpha)))
    q = k * force
    if np.ndim(q) == 0:  # one case (z alone an array, or the load alone: arrays)
        return Approximation(float(k), float(q))
    return Approximation(np.broadcast_to(k, q.shape).copy(), q)
