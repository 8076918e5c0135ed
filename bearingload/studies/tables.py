"""The design tables: rows and columns for Table 1 (k) and Table 2.2 (K_Q), for any conditions.

Table 1 of Kuzmenko (2010) lists ``k = Q_max/F_r`` and the number of loaded balls ``n`` for
z = 1-30 at zero clearance with a ball under the load; Table 2.2 of Kuzmenko & Sabadash (2014)
lists ``K_Q = k z/2`` for the same cases. Both are built here from the exact equilibrium engine,
under the paper's conditions by default or under any load, stiffness, clearance and cage angle.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingload.models.equilibrium import LoadDistribution, solve
from bearingload.reports.render import Column, Table


@dataclass(frozen=True)
class Conditions:
    """The conditions a table is computed under (internal units)."""

    load: float = 1000.0  # [N]
    stiffness: float = 1.0e5  # [N/mm^m]
    clearance: float = 0.0  # [mm], G_r total play
    cage_angle: float | str = 0.0  # [°] or "half"
    exponent: float = 1.5  # [-]

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
            else f"cage angle {self.cage_angle:.6g}°"
        )
        text = f"{gap}, {cage}, m = {self.exponent:.6g}"
        if self.clearance != 0:
            text += f", F_r = {self.load:.6g} N, K = {self.stiffness:.6g} N/mm^m"
        return text


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


def omitted_note(z_max: int, cage_angle: float | str) -> list[str]:
    """A note naming the z left out by :func:`balls_and_angles`, if any."""
    z, _ = balls_and_angles(z_max, cage_angle)
    missing = sorted(set(range(1, min(z_max, 2) + 1)) - {int(v) for v in z})
    if not missing:
        return []
    listed = " and ".join(str(v) for v in missing)
    return [
        f"z = {listed} left out: with one or two balls equilibrium needs a ball on the load line "
        "(cage angle 0)."
    ]


def distribution_over_z(z_max: int, cond: Conditions) -> LoadDistribution:
    """Solve the cases z = 1..z_max under ``cond`` in one vectorised call."""
    z, angle = balls_and_angles(z_max, cond.cage_angle)
    return solve(z, cond.load, cond.stiffness, cond.clearance, angle, cond.exponent)


def _exact_table(
    key: str, digits: int, title: str, note: str, z_max: int, cond: Conditions
) -> Table:
    """One column ``key`` (an attribute of the solution: ``k`` or ``K_Q``) and ``n`` over z."""
    r = distribution_over_z(z_max, cond)
    rows = [
        {"z": int(z), "n": int(n), key: float(v)}
        for z, n, v in zip(r.balls, r.loaded_balls, getattr(r, key), strict=True)
    ]
    return Table(
        title=f"{title} (exact discrete model; {cond.describe()})",
        columns=[Column("z", "z"), Column("n", "n"), Column(key, key, "-", digits)],
        rows=rows,
        notes=[note, *omitted_note(z_max, cond.cage_angle)],
    )


def table_k(z_max: int = 30, cond: Conditions | None = None) -> Table:
    """Table 1 of Kuzmenko (2010): ``k = Q_max/F_r`` and loaded balls ``n`` for z = 1..z_max."""
    return _exact_table(
        "k",
        4,
        "Load factor k = Q_max/F_r",
        "z: balls; n: balls carrying load; k: heaviest ball load over the radial load.",
        z_max,
        cond or Conditions(),
    )


def table_kq(z_max: int = 30, cond: Conditions | None = None) -> Table:
    """Table 2.2 of Kuzmenko & Sabadash (2014): ``K_Q = Q_max/Q_mean = k z/2`` for z = 1..z_max."""
    return _exact_table(
        "K_Q",
        5,
        "Load-concentration factor K_Q = k z/2",
        "K_Q: heaviest ball load over the mean load F_r/(z/2).",
        z_max,
        cond or Conditions(),
    )
