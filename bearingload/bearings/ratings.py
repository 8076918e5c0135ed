"""ISO 281 / ISO 76 load ratings of deep groove ball bearings, and their inversion to a ball set.

Catalogue load ratings of single-row deep groove ball bearings (contact angle alpha = 0, one
row i = 1) are computed by the makers from the ball set z x D_w on the pitch diameter d_m:

* dynamic, ISO 281:2007 clause 6.1.1 (radial ball bearings), with b_m = 1.3 from ISO 281
  Table 1 (deep groove ball bearings) and f_c from ISO 281 Table 2 at gamma = D_w cos(alpha)/d_m::

      C_r = b_m f_c (i cos alpha)^0.7 z^(2/3) D_w^1.8              (D_w <= 25.4 mm)
      C_r = 3.647 b_m f_c (i cos alpha)^0.7 z^(2/3) D_w^1.4        (D_w >  25.4 mm)

* static, ISO 76:2006 clause 6.1.1 (radial ball bearings), f_0 from the ISO 76 table of f_0
  for deep groove ball bearings::

      C_0r = f_0 i z D_w^2 cos alpha

Both tables are tabulated in steps of 0.01 in gamma; between steps ISO allows linear
interpolation, which :func:`f_c` and :func:`f_0` do.

Inverting two ratings for the integer z and a standard ball size D_w (ISO 3290: inch sizes in
1/64" steps, metric sizes in 0.5 mm steps) pins the ball set of most catalogue rows; with
NSK's printed f_0 the fingerprint z D_w^2 = C_0r / f_0 is read almost directly. This is how
the derived ball sets of ``data/ball_sets.csv`` were obtained; :func:`invert_ball_set`
repeats the search so that a test re-derives every derived row from its ratings.

Units: N, mm.

>>> round(float(dynamic_rating(9, 7.938, 38.5)))  # NSK 6205: C_r 14 000 N
14014
>>> round(float(static_rating(9, 7.938, 38.5)))  # NSK 6205: C_0r 7 850 N
7834
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.numerics import scalar_out

if TYPE_CHECKING:
    from numpy.typing import ArrayLike

#: ISO 281:2007 Table 1: b_m of radial ball bearings (deep groove, angular contact). [-]
B_M = 1.3

#: ISO 281:2007 Table 2, single-row radial deep groove ball bearings: f_c at
#: gamma = 0.01, 0.02, ..., 0.40. [N/mm^1.8]
FC_TABLE: tuple[float, ...] = (
    29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5,
    56.6, 57.5, 58.2, 58.8, 59.3, 59.6, 59.8, 59.9, 60.0, 59.9,
    59.8, 59.6, 59.3, 59.0, 58.6, 58.2, 57.7, 57.1, 56.6, 56.0,
    55.3, 54.6, 53.9, 53.2, 52.4, 51.7, 50.9, 50.0, 49.2, 48.4,
)  # fmt: skip

#: ISO 76:2006, f_0 of deep groove ball bearings at gamma = 0.00, 0.01, ..., 0.40. [N/mm^2]
F0_TABLE: tuple[float, ...] = (
    14.7, 14.9, 15.1, 15.3, 15.5, 15.7, 15.9, 16.1, 16.3, 16.5,
    16.4, 16.1, 15.9, 15.6, 15.4, 15.2, 14.9, 14.7, 14.4, 14.2,
    14.0, 13.7, 13.5, 13.2, 13.0, 12.8, 12.5, 12.3, 12.1, 11.8,
    11.6, 11.4, 11.2, 10.9, 10.7, 10.5, 10.3, 10.0, 9.8, 9.6, 9.4,
)  # fmt: skip

_INCH = 25.4


def _gamma(ball_diameter: ArrayLike, pitch_diameter: ArrayLike) -> np.ndarray:
    dw = np.asarray(ball_diameter, dtype=float)
    dm = np.asarray(pitch_diameter, dtype=float)
    if not (np.all(np.isfinite(dw)) and np.all(dw > 0)):
        raise InputError("ball_diameter", f"must be finite and > 0 mm, not {ball_diameter!r}")
    if not (np.all(np.isfinite(dm)) and np.all(dm > dw)):
        raise InputError("pitch_diameter", f"must exceed the ball diameter, not {pitch_diameter!r}")
    g = dw / dm
    if np.any(g > 0.40) or np.any(g < 0.01):
        raise InputError(
            "ball_diameter", "D_w/d_m must lie in 0.01 ... 0.40, the range of the ISO tables"
        )
    return g


def f_c(ball_diameter: ArrayLike, pitch_diameter: ArrayLike) -> Any:
    """Factor f_c of ISO 281:2007 Table 2 (single-row deep groove), linearly interpolated.

    Parameters
    ----------
    ball_diameter : array_like
        D_w. [mm]
    pitch_diameter : array_like
        d_m. [mm]

    Returns
    -------
    float or ndarray
        f_c. [N/mm^1.8]

    >>> round(float(f_c(7.938, 38.5)), 3)  # gamma = 0.2062, between 59.9 and 59.8
    59.838
    """
    g = _gamma(ball_diameter, pitch_diameter)
    return scalar_out(np.interp(g, np.arange(1, 41) / 100.0, FC_TABLE))


def f_0(ball_diameter: ArrayLike, pitch_diameter: ArrayLike) -> Any:
    """Factor f_0 of ISO 76:2006 (deep groove ball bearings), linearly interpolated.

    Parameters
    ----------
    ball_diameter : array_like
        D_w. [mm]
    pitch_diameter : array_like
        d_m. [mm]

    Returns
    -------
    float or ndarray
        f_0. [N/mm^2]

    >>> round(float(f_0(7.938, 38.5)), 3)  # gamma = 0.2062, between 14.0 and 13.7
    13.815
    """
    g = _gamma(ball_diameter, pitch_diameter)
    return scalar_out(np.interp(g, np.arange(41) / 100.0, F0_TABLE))


def dynamic_rating(
    balls: ArrayLike,
    ball_diameter: ArrayLike,
    pitch_diameter: ArrayLike,
    contact_angle: float = 0.0,
) -> Any:
    """Basic dynamic radial load rating C_r of a single-row radial ball bearing, ISO 281:2007
    6.1.1 (Table 2's column covers deep groove and angular contact ball bearings alike).

    Parameters
    ----------
    balls : array_like
        Number of balls z. [-]
    ball_diameter : array_like
        D_w. [mm]
    pitch_diameter : array_like
        d_m. [mm]
    contact_angle : float
        Nominal contact angle alpha; 0 for a deep groove ball bearing. [°]

    Returns
    -------
    float or ndarray
        C_r = b_m f_c (cos alpha)^0.7 z^(2/3) D_w^1.8 (D_w <= 25.4 mm), 3.647 b_m f_c
        (cos alpha)^0.7 z^(2/3) D_w^1.4 above, f_c at gamma = D_w cos alpha / d_m. [N]
    """
    z = np.asarray(balls, dtype=float)
    dw = np.asarray(ball_diameter, dtype=float)
    cos_a = math.cos(math.radians(contact_angle))
    fc = np.asarray(f_c(dw * cos_a, pitch_diameter))
    power = np.where(dw <= _INCH, dw**1.8, 3.647 * dw**1.4)
    return scalar_out(B_M * fc * cos_a**0.7 * z ** (2.0 / 3.0) * power)


def static_rating(
    balls: ArrayLike,
    ball_diameter: ArrayLike,
    pitch_diameter: ArrayLike,
    contact_angle: float = 0.0,
) -> Any:
    """Basic static radial load rating C_0r = f_0 z D_w^2 cos alpha of a single-row radial ball
    bearing, f_0 at gamma = D_w cos alpha / d_m. [N]

    ISO 76:2006 clause 6.1.1 with i = 1. Parameters as :func:`dynamic_rating`.
    """
    z = np.asarray(balls, dtype=float)
    dw = np.asarray(ball_diameter, dtype=float)
    cos_a = math.cos(math.radians(contact_angle))
    return scalar_out(np.asarray(f_0(dw * cos_a, pitch_diameter)) * z * dw**2 * cos_a)


def standard_ball_sizes(miniature: bool = False) -> np.ndarray:
    """Nominal ball sizes searched by the inversion (ISO 3290), sorted. [mm]

    Inch sizes 6/64" (3/32") to 128/64" (2") in 1/64" steps, and metric sizes 2.5 to 32 mm in
    0.5 mm steps; ``miniature``: the same steps down to 1/64" and 0.5 mm (the balls of the
    bearings with a bore below 10 mm, ISO 15's one-digit bore codes).
    """
    first_inch, first_metric = (1, 1) if miniature else (6, 5)
    inch = np.arange(first_inch, 129) * _INCH / 64.0
    metric = np.arange(first_metric, 65) * 0.5
    return np.unique(np.concatenate([inch, metric]))


@dataclass(frozen=True)
class BallSetFit:
    """One candidate ball set of :func:`invert_ball_set` and how well it reproduces the ratings.

    Attributes
    ----------
    balls : int
        z.
    ball_diameter : float
        D_w, a standard ball size. [mm]
    score : float
        Largest relative residual of the matched ratings (a fraction; 0.01 = 1 %), scaled as
        described in :func:`invert_ball_set`. [-]
    """

    balls: int
    ball_diameter: float
    score: float


def invert_ball_set(
    pitch_diameter: float,
    C: float,
    C0: float,
    *,
    f0: float | None = None,
    use_f0: bool = True,
    rating_factor: float | None = None,
    balls: range = range(5, 46),
    contact_angle: float = 0.0,
    miniature: bool = False,
) -> list[BallSetFit]:
    """Ball sets z x D_w that reproduce a catalogue's ratings, best first.

    Every z in ``balls`` and every standard ball size (:func:`standard_ball_sizes`) that fits
    (z D_w < pi d_m) is scored by its largest relative residual:

    * with ``f0`` (NSK prints it): the fingerprint z D_w^2 against C0/f0, the ISO 281 C_r
      against ``C``, and (``use_f0``) the ISO 76 f_0(gamma) against the printed f0;
    * without: the ISO 281 C_r against ``C`` and the ISO 76 C_0r against ``C0``;
    * with ``rating_factor`` k_0 (a maker rating above ISO 281 by a roughly constant factor,
      e.g. SKF Explorer 1.052): the C_0r residual in units of 1 % and |C/C_r - k_0| in units
      of 2 %, the larger of the two (so a score of 1 means 1 % on C_0 or 2 % on k).

    Parameters
    ----------
    pitch_diameter : float
        d_m, taken as (d + D)/2 for a catalogue row. [mm]
    C, C0 : float
        Catalogue dynamic and static radial ratings. [N]
    f0 : float, optional
        Printed factor f0 of C0 = f0 z D_w^2. [N/mm^2]
    use_f0 : bool
        Also match the printed f0 against ISO 76's (not for NSK 618xx, whose f0 exceed the
        ISO table).
    rating_factor : float, optional
        k_0, see above. [-]
    balls : range
        Ball counts searched.
    contact_angle : float
        Nominal contact angle alpha of an angular-contact row (ISO 281 and ISO 76 at alpha,
        gamma = D_w cos alpha / d_m); 0 for a deep groove ball bearing. [°]
    miniature : bool
        Search the ball sizes of :func:`standard_ball_sizes` down to 1/64" and 0.5 mm.

    Returns
    -------
    list of BallSetFit
        Sorted by score, best first.

    >>> best = invert_ball_set(38.5, 14000.0, 7850.0, f0=13.9)[0]  # NSK 6205
    >>> best.balls, round(best.ball_diameter, 3)
    (9, 7.938)
    """
    sizes = standard_ball_sizes(miniature)
    z = np.array(list(balls), dtype=float)[:, None]
    dw = sizes[None, :]
    gamma = dw * math.cos(math.radians(contact_angle)) / pitch_diameter
    ok = (z * dw < np.pi * pitch_diameter) & (gamma <= 0.40) & (gamma >= 0.01)
    zz, dd = np.broadcast_arrays(z, dw)
    zz, dd = zz[ok], dd[ok]
    cr = np.asarray(dynamic_rating(zz, dd, pitch_diameter, contact_angle))
    if rating_factor is not None:
        c0 = np.asarray(static_rating(zz, dd, pitch_diameter, contact_angle))
        score = np.maximum(np.abs(c0 / C0 - 1.0) / 0.01, np.abs(C / cr - rating_factor) / 0.02)
        score = score * 0.01
    elif f0 is not None:
        parts = [np.abs(zz * dd**2 * f0 / C0 - 1.0), np.abs(cr / C - 1.0)]
        if use_f0:
            parts.append(np.abs(np.asarray(f_0(dd, pitch_diameter)) / f0 - 1.0))
        score = np.max(parts, axis=0)
    else:
        c0 = np.asarray(static_rating(zz, dd, pitch_diameter, contact_angle))
        score = np.maximum(np.abs(cr / C - 1.0), np.abs(c0 / C0 - 1.0))
    order = np.argsort(score, kind="stable")
    return [BallSetFit(int(zz[i]), float(dd[i]), float(score[i])) for i in order]
