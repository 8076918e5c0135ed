"""Reference rating life L10r of a ball bearing from its ball loads (ISO/TS 16281:2008).

ISO/TS 16281:2008, *Rolling bearings - Methods for calculating the modified reference rating
life for universally loaded bearings*, clause 4 (ball bearings): 4.2 gives the internal load
distribution (here :mod:`bearingload.models.combined`), 4.3 the rating life from it; clause 6.3
gives the reference geometry of deep-groove ball bearings (groove radii 0.52 and 0.53 D_w, the
defaults of this package). The equations followed, for one row (i = 1) of Z balls, nominal
contact angle alpha (0 for a deep-groove bearing), gamma = D_w cos(alpha)/D_pw:

Dynamic load ratings of the raceway contacts, from the basic dynamic load rating C_r::

    X    = ((1 - gamma)/(1 + gamma))^1.72 * (r_i (2 r_e - D_w) / (r_e (2 r_i - D_w)))^0.41
    Q_ci = C_r / (0.407 Z i^0.7 cos^0.7 alpha) * (1 + (1.044 X)^(10/3))^0.3
    Q_ce = C_r / (0.389 Z i^0.7 cos^0.7 alpha) * (1 + (1.044 X)^(-10/3))^0.3

(X = Q_ci/Q_ce is Lundberg and Palmgren's ratio of the contact ratings; 0.389 is 0.407/1.044
rounded, so Q_ci/Q_ce = 0.99782 X, not X exactly.)

Equivalent ball loads: the ring that rotates relative to the load sees every ball at every
point (cubic mean), the stationary ring keeps its load zone (exponent 10/3)::

    rotating ring:   Q_e = (sum Q_j^3 / Z)^(1/3)
    stationary ring: Q_e = (sum Q_j^(10/3) / Z)^(3/10)

Reference rating life [10^6 revolutions]::

    L10r = ((Q_ci/Q_ei)^(-10/3) + (Q_ce/Q_ee)^(-10/3))^(-9/10)

The dynamic equivalent reference load is P_ref = C_r / L10r^(1/3).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload import validate
from bearingload.errors import InputError
from bearingload.numerics import scalar_out

if TYPE_CHECKING:
    from numpy.typing import ArrayLike

#: Which ring rotates relative to the load: the values ``rotating`` accepts.
ROTATING = ("inner", "outer")


def contact_ratings(
    dynamic_rating: ArrayLike,
    balls: ArrayLike,
    ball_diameter: ArrayLike,
    pitch_diameter: ArrayLike,
    f_i: ArrayLike = 0.52,
    f_o: ArrayLike = 0.53,
    contact_angle: ArrayLike = 0.0,
    rows: int = 1,
) -> tuple[Any, Any]:
    """Dynamic load ratings Q_ci, Q_ce of the inner and outer raceway contacts (ISO/TS 16281, 4.3).

    Parameters
    ----------
    dynamic_rating : array_like
        Basic dynamic radial load rating C_r of the bearing (ISO 281). [N]
    balls : array_like
        Balls per row Z. [-]
    ball_diameter, pitch_diameter : array_like
        D_w and D_pw. [mm]
    f_i, f_o : array_like
        Groove conformities r_i/D_w and r_e/D_w. [-]
    contact_angle : array_like
        Nominal contact angle alpha (0 for deep-groove bearings). [°]
    rows : int
        Number of rows i. [-]

    Returns
    -------
    (Q_ci [N], Q_ce [N])

    >>> qci, qce = contact_ratings(23400.0, 7, 11.5, 43.5)
    >>> round(float(qci)), round(float(qce))
    (8423, 18289)
    """
    c = validate.positive("dynamic_rating", dynamic_rating, "N")
    z = validate.ball_count(balls).astype(float)
    dw = validate.positive("ball_diameter", ball_diameter, "mm")
    dpw = validate.positive("pitch_diameter", pitch_diameter, "mm")
    fi = validate.conformity("f_i", f_i)
    fo = validate.conformity("f_o", f_o)
    alpha = np.deg2rad(validate.finite("contact_angle", contact_angle))
    cos_a = np.cos(alpha)
    if np.any(cos_a <= 0):
        raise InputError(
            "contact_angle", "must lie between -90 and 90 degrees for a radial bearing"
        )
    gamma = dw * cos_a / dpw
    if np.any(gamma >= 1):
        raise InputError("ball_diameter", "must be smaller than the pitch diameter")
    ri, re = fi * dw, fo * dw
    x = ((1.0 - gamma) / (1.0 + gamma)) ** 1.72 * (
        ri * (2 * re - dw) / (re * (2 * ri - dw))
    ) ** 0.41
    base = c / (z * rows**0.7 * cos_a**0.7)
    q_ci = base / 0.407 * (1.0 + (1.044 * x) ** (10.0 / 3.0)) ** 0.3
    q_ce = base / 0.389 * (1.0 + (1.044 * x) ** (-10.0 / 3.0)) ** 0.3
    return scalar_out(q_ci), scalar_out(q_ce)


def equivalent_ball_loads(ball_loads: ArrayLike, rotating: str = "inner") -> tuple[Any, Any]:
    """Equivalent ball loads Q_ei, Q_ee of the inner and outer ring (ISO/TS 16281, 4.3). [N]

    Parameters
    ----------
    ball_loads : array_like, last axis the Z balls
        Q_j >= 0. [N]
    rotating : {"inner", "outer"}
        The ring that rotates relative to the load (cubic mean); the other one keeps its load
        zone (exponent 10/3).

    >>> qei, qee = equivalent_ball_loads([3.0, 0.0, 0.0], "inner")
    >>> round(float(qei), 6), round(float(qee), 6)
    (2.080084, 2.157669)
    """
    if rotating not in ROTATING:
        raise InputError("rotating", f"must be one of {', '.join(ROTATING)}; got {rotating!r}")
    q = validate.finite("ball_loads", ball_loads)
    if q.ndim == 0 or np.any(q < 0):
        raise InputError("ball_loads", "must be an array of loads >= 0 N, one per ball")
    peak = np.max(q, axis=-1, keepdims=True)
    safe = np.where(peak > 0, peak, 1.0)
    rel = q / safe  # scaled by the peak: no overflow for huge loads
    cubic = peak[..., 0] * np.mean(rel**3, axis=-1) ** (1.0 / 3.0)
    ten_thirds = peak[..., 0] * np.mean(rel ** (10.0 / 3.0), axis=-1) ** 0.3
    if rotating == "inner":
        return scalar_out(cubic), scalar_out(ten_thirds)
    return scalar_out(ten_thirds), scalar_out(cubic)


def reference_rating_life(
    ball_loads: ArrayLike,
    q_ci: ArrayLike,
    q_ce: ArrayLike,
    rotating: str = "inner",
    outer_loads: ArrayLike | None = None,
) -> Any:
    """Basic reference rating life L10r from the ball loads (ISO/TS 16281, 4.3). [10^6 rev]

    Parameters
    ----------
    ball_loads : array_like, last axis the Z balls
        Q_j. [N]
    q_ci, q_ce : array_like
        Dynamic load ratings of the inner and outer contacts, :func:`contact_ratings`. [N]
    rotating : {"inner", "outer"}
        The ring that rotates relative to the load.
    outer_loads : array_like, optional
        The balls' outer contact loads where they differ from ``ball_loads`` (the inner
        contacts' then; ball dynamics at speed): Q_ee is taken from them. [N]

    Returns
    -------
    L10r; infinite where no ball carries load. [10^6 revolutions]

    >>> round(float(reference_rating_life([1000.0, 0.0, 0.0], 10000.0, 15000.0)), 3)
    2381.501
    """
    q_ei, q_ee = equivalent_ball_loads(ball_loads, rotating)
    if outer_loads is not None:
        q_ee = equivalent_ball_loads(outer_loads, rotating)[1]
    ci = validate.positive("q_ci", q_ci, "N")
    ce = validate.positive("q_ce", q_ce, "N")
    q_ei, q_ee = np.asarray(q_ei), np.asarray(q_ee)
    with np.errstate(divide="ignore", over="ignore"):
        inner = (q_ei / ci) ** (10.0 / 3.0)
        outer = (q_ee / ce) ** (10.0 / 3.0)
        life = (inner + outer) ** (-0.9)
    return scalar_out(life)
