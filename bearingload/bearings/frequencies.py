"""Defect frequencies of a rolling bearing: cage (FTF), ball pass outer and inner (BPFO, BPFI)
and ball spin (BSF), in Hz, from the kinematics of its rolling elements.

**One contact angle, pure rolling** (both contacts of the ball at ``alpha``; the quasi-static
model, a radial bearing at 0°). With ``gamma = D_w cos(alpha) / d_m`` and the rings turning at
``f_i``, ``f_o`` (Hz), rolling without slip on both raceways gives (Harris & Kotzalas, *Rolling
Bearing Analysis*, 5th ed., vol. 1, the kinematic speeds of the rolling elements; the same
formulas the defect-frequency tables of vibration analysis use)::

    FTF  = f_i (1 - gamma)/2 + f_o (1 + gamma)/2          (the cage, absolute)
    BPFO = z |f_o - FTF|,   BPFI = z |f_i - FTF|
    BSF  = d_m / (2 D_w) |f_i - f_o| (1 - gamma^2)        (the ball about its axis, in the cage)

so with the inner ring turning at ``f = n/60`` (outer still) ``FTF = f (1 - gamma)/2``, ``BPFO =
z FTF``, ``BPFI = z (f - FTF)``; with the outer ring turning (inner still) ``FTF = f (1 +
gamma)/2``: the rotating ring matters, the relative speed of the rings alone does not fix the
cage's.

**Two contact angles, outer-raceway control** (the ball dynamics of
:mod:`bearingload.models.high_speed`: each ball at ``alpha_i`` and ``alpha_o``). With
``g = D_w / d_m``, the attitude angle ``tan beta = sin alpha_o / (cos alpha_o + g)``, ``c_o =
(cos alpha_o + tan beta sin alpha_o)/(1 + g cos alpha_o)`` and ``c_i = (cos alpha_i + tan beta
sin alpha_i)/(1 - g cos alpha_i)`` (Jones 1960; Harris & Kotzalas, 5th ed., vol. 2, ch. 2), in
the frame of the outer ring the cage turns at ``(f_i - f_o) c_o/(c_o + c_i)`` and the ball at
``(f_i - f_o)/(g cos beta (c_o + c_i))`` about its own axis::

    FTF  = f_o + (f_i - f_o) c_o/(c_o + c_i)
    BPFO = z |f_o - FTF|,   BPFI = z |f_i - FTF|
    BSF  = |f_i - f_o| / (g cos beta (c_o + c_i))

At ``alpha_i = alpha_o = alpha`` the cage's reduces to the one-angle formula exactly (``c_o/(c_o
+ c_i) = (1 - gamma)/2`` whatever beta); the ball's spin to it times ``1/cos(alpha - beta)``
(the spin axis of outer-raceway control is tilted from the contact line).

Examples reproduced (tests/test_frequencies.py): the Case Western Reserve University bearing
data centre's orders of SKF 6205-2RS JEM (9 balls of 7.940 mm on 39.040 mm, 0°: BPFI 5.4152,
BPFO 3.5848, FTF 0.39828, 2 BSF 4.7135 times the shaft frequency).

>>> f = defect_frequencies(9, 7.94, 39.04, 1800.0, 0.0)
>>> [round(float(v), 3) for v in (f.cage_frequency, f.ball_pass_frequency_outer,
...                               f.ball_pass_frequency_inner, f.ball_spin_frequency)]
[11.949, 107.544, 162.456, 70.702]
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.validate import finite_positive

if TYPE_CHECKING:
    from numpy.typing import ArrayLike

#: The rings a bearing may turn (the other one still). [-]
ROTATING_RINGS = ("inner", "outer")


@dataclass(frozen=True)
class DefectFrequencies:
    """Defect frequencies (floats, or arrays over cases). [Hz]

    Attributes
    ----------
    cage_frequency : FTF, the cage's rotation (fundamental train frequency).
    ball_pass_frequency_outer : BPFO, balls passing a point of the outer ring.
    ball_pass_frequency_inner : BPFI, balls passing a point of the inner ring.
    ball_spin_frequency : BSF, a ball's rotation about its own axis, relative to the cage.
    """

    cage_frequency: Any
    ball_pass_frequency_outer: Any
    ball_pass_frequency_inner: Any
    ball_spin_frequency: Any

    def values(self) -> dict[str, Any]:
        """The four under their keys (:mod:`bearingload.reports.quantities`)."""
        return dict(self.__dict__)


def defect_frequencies(
    balls: int,
    ball_diameter: float,
    pitch_diameter: float,
    speed: ArrayLike,
    contact_angle: ArrayLike,
    contact_angle_outer: ArrayLike | None = None,
    rotating: str = "inner",
) -> DefectFrequencies:
    """FTF, BPFO, BPFI and BSF of a bearing turning at ``speed`` (see the module). [Hz]

    Parameters
    ----------
    balls : int
        Number of rolling elements z >= 1.
    ball_diameter, pitch_diameter : float
        D_w < d_m. [mm]
    speed : array_like
        n >= 0 of the rotating ring, the other one still. [rpm]
    contact_angle : array_like
        alpha of both contacts; with ``contact_angle_outer`` the inner contact's alpha_i, -90 to
        90 (negative: the groove's other flank). [°]
    contact_angle_outer : array_like, optional
        alpha_o: the two-angle kinematics under outer-raceway control. [°]
    rotating : {"inner", "outer"}
        The ring turning at ``speed``.

    >>> f = defect_frequencies(9, 7.94, 39.04, 1800.0, 0.0, rotating="outer")
    >>> round(float(f.cage_frequency), 3), round(float(f.ball_spin_frequency), 3)
    (18.051, 70.702)
    """
    z, dw, dm = _geometry(balls, ball_diameter, pitch_diameter)
    n = np.asarray(speed, dtype=float)
    if not np.all(np.isfinite(n) & (n >= 0)):
        raise InputError("speed", f"must be a finite number >= 0 rpm; got {speed!r}")
    if rotating not in ROTATING_RINGS:
        raise InputError(
            "rotating", f"must be one of {', '.join(ROTATING_RINGS)}; got {rotating!r}"
        )
    f_i, f_o = (n / 60.0, 0.0 * n) if rotating == "inner" else (0.0 * n, n / 60.0)
    a_i = _angle("contact_angle", contact_angle)
    if contact_angle_outer is None:
        gamma = dw * np.cos(a_i) / dm
        cage = f_i * (1 - gamma) / 2 + f_o * (1 + gamma) / 2
        spin = dm / (2 * dw) * np.abs(f_i - f_o) * (1 - gamma**2)
    else:
        a_o = _angle("contact_angle_outer", contact_angle_outer)
        g = dw / dm
        beta = np.arctan2(np.sin(a_o), np.cos(a_o) + g)
        c_o = (np.cos(a_o) + np.tan(beta) * np.sin(a_o)) / (1 + g * np.cos(a_o))
        c_i = (np.cos(a_i) + np.tan(beta) * np.sin(a_i)) / (1 - g * np.cos(a_i))
        cage = f_o + (f_i - f_o) * c_o / (c_o + c_i)
        spin = np.abs(f_i - f_o) / (g * np.cos(beta) * (c_o + c_i))
    return DefectFrequencies(
        cage_frequency=_out(cage),
        ball_pass_frequency_outer=_out(z * np.abs(f_o - cage)),
        ball_pass_frequency_inner=_out(z * np.abs(f_i - cage)),
        ball_spin_frequency=_out(spin),
    )


def _geometry(balls: int, ball_diameter: float, pitch_diameter: float) -> tuple[int, float, float]:
    """z, D_w, d_m checked: z a whole number >= 1, 0 < D_w < d_m."""
    if isinstance(balls, bool) or int(balls) != balls or balls < 1:
        raise InputError("balls", f"must be a whole number >= 1; got {balls!r}")
    dw = float(finite_positive("ball_diameter", ball_diameter))
    dm = float(finite_positive("pitch_diameter", pitch_diameter))
    if dw >= dm:
        raise InputError("ball_diameter", f"must be below the pitch diameter {dm:g} mm; got {dw:g}")
    return int(balls), dw, dm


def _angle(name: str, value: ArrayLike) -> Any:
    """A contact angle in radians, checked to lie in -90 to 90° (a negative angle: the ball on
    the groove's other flank, the mirror image, as a deep-groove ball under a thrust the other
    way)."""
    a = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(a) & (np.abs(a) <= 90)):
        raise InputError(name, f"must lie between -90 and 90°; got {value!r}")
    return np.deg2rad(a)


def _out(x: Any) -> Any:
    """A float for one case, else the array."""
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x
