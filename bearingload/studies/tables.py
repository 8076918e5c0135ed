"""The design tables' numbers: every registered model over z = 1..z_max under one set of conditions.

Table 1 of Kuzmenko (2010) lists ``k = Q_max/F_r`` and the number of loaded balls ``n`` for
z = 1-30 at zero clearance with a ball under the load; Table 2.2 of Kuzmenko & Sabadash (2014)
lists ``K_Q = k z/2`` for the same cases. :func:`over_z` computes them (and the other models'
answers) under the papers' conditions by default or under any load, stiffness, clearance and cage
angle; :mod:`bearingload.reports.tables` lays them out.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload.lazy_dataclass import dataclass
from bearingload.models.case import Case, Result
from bearingload.models.registry import get_method
from bearingload.units import turn_angle

if TYPE_CHECKING:  # the table command without a bearing does not load the catalogue
    from bearingload.bearings.resolve import ResolvedBearing


@dataclass(frozen=True)
class Conditions:
    """The conditions a table is computed under.

    Attributes
    ----------
    load : float
        Radial load F_r. [N]
    stiffness : float
        Ball stiffness K. [N/mm^m]
    clearance : float
        Radial internal clearance G_r (total play). [mm]
    cage_angle : float or "half"
        Angle of ball 1 from the load line [°], or half a pitch (180/z) for every z.
    exponent : float
        Load-deflection exponent m. [-]
    bearing : ResolvedBearing or None
        The bearing whose ball and raceways give K and G_r, if any.
    """

    load: float = 1000.0
    stiffness: float = 1.0e5
    clearance: float = 0.0
    cage_angle: float | str = 0.0
    exponent: float = 1.5
    bearing: ResolvedBearing | None = None

    def describe(self) -> str:
        if self.clearance == 0:
            gap = "zero clearance"
        else:
            gap = f"clearance G_r = {self.clearance * 1e3:.6g} µm"
        cage = (
            "load between two balls (half pitch)"
            if self.cage_angle == "half"
            else "a ball under the load"
            if self.cage_angle == 0
            else f"cage angle {turn_angle(self.cage_angle, 6):.6g}°"
        )
        text = f"{gap}, {cage}, m = {self.exponent:.6g}"
        if self.clearance != 0:
            text += f", F_r = {self.load:.6g} N, K = {self.stiffness:.6g} N/mm^m"
        return text


def for_bearing(bearing: ResolvedBearing, load: float, cage_angle: float | str = 0.0) -> Conditions:
    """The conditions of a bearing's ball and raceways: its Hertz K and its clearance G_r."""
    return Conditions(load, bearing.stiffness, bearing.clearance, cage_angle, 1.5, bearing)


def balls_and_angles(z_max: int, cage_angle: float | str) -> tuple[np.ndarray, np.ndarray]:
    """z = 1..z_max and the cage angle of each [°], leaving out z = 1-2 where no equilibrium exists.

    With one ball, equilibrium needs it on the load line (cage angle 0 mod 360°); with two, one of
    them (0 mod 180°). ``"half"`` means half a pitch, 180/z degrees.
    """
    z = np.arange(1, z_max + 1)
    if cage_angle == "half":
        z = z[z >= 3]
        return z, 180.0 / z
    angle = float(cage_angle)
    keep = (z >= 3) | ((z == 2) & (angle % 180.0 == 0)) | ((z == 1) & (angle % 360.0 == 0))
    z = z[keep]
    return z, np.full(z.shape, angle)


def omitted(z_max: int, cage_angle: float | str) -> list[int]:
    """The z of 1..z_max that :func:`balls_and_angles` leaves out."""
    z, _ = balls_and_angles(z_max, cage_angle)
    return sorted(set(range(1, min(z_max, 2) + 1)) - {int(v) for v in z})


def over_z(
    z_max: int, cond: Conditions, methods: Sequence[str] = ("exact",)
) -> tuple[np.ndarray, dict[str, Result]]:
    """Every model of ``methods`` (and always ``exact``, which counts the loaded balls) for
    z = 1..z_max under ``cond``, each in one vectorised call on one checked case."""
    z, angle = balls_and_angles(z_max, cond.cage_angle)
    case = Case.of(z, cond.load, cond.stiffness, cond.clearance, angle, cond.exponent)
    names = list(dict.fromkeys(["exact", *methods]))
    return z, {name: get_method(name).run(case) for name in names}


def column_of(result: Result, key: str, z: np.ndarray) -> Any:
    """``result``'s quantity ``key`` as an array over ``z``."""
    return np.broadcast_to(np.asarray(getattr(result, key)), z.shape)
