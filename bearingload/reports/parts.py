"""Pieces every case report shares: the inputs line, the summary rows of a solved ring, the
quantity/value/unit table, and the JSON keys of a solution with their units.

``solve``, ``solve BEARING`` and ``solve --method`` print through these, so one quantity has one
label, one unit and one JSON key everywhere.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from bearingload.models.equilibrium import LoadDistribution
from bearingload.reports.render import Column, Table
from bearingload.units import KGF

#: Units of the JSON keys of a solved case.
JSON_UNITS = {
    "load": "N",
    "clearance": "mm (G_r, total radial play)",
    "q_max": "N",
    "ball_loads": "N",
    "load_zone_deg": "°",
    "deflection": "mm",
    "deflection_across": "mm",
    "stiffness_radial": "N/mm",
    "stiffness_matrix": "N/mm",
}


def cage_angle_deg(cage_angle: float | str, balls: int) -> float:
    """The cage angle in [0, 360) degrees; ``"half"`` is half a pitch, 180/z."""
    return 180.0 / balls if cage_angle == "half" else float(cage_angle) % 360.0


def inputs_text(
    balls: int, load: float, stiffness: float, clearance: float, angle: float, exponent: float
) -> str:
    """One line naming a case's inputs with units: N, kgf, N/mm^m, µm, degrees."""
    return (
        f"z = {balls}, F_r = {load:.6g} N ({load / KGF:.6g} kgf), "
        f"K = {stiffness:.6g} N/mm^{exponent:g}, G_r = {clearance * 1e3:.6g} µm "
        f"(gap per side {clearance * 500:.6g} µm), cage angle {angle:.6g}°, m = {exponent:.6g}"
    )


def inputs_json(
    balls: int, load: float, stiffness: float, clearance: float, angle: float, exponent: float
) -> dict[str, Any]:
    """A case's inputs under the JSON keys of every solve report (N, N/mm^m, mm, °)."""
    return {
        "balls": balls,
        "load": load,
        "stiffness": stiffness,
        "clearance": clearance,
        "cage_angle_deg": angle,
        "exponent": exponent,
    }


def distribution_rows(r: LoadDistribution) -> list[tuple[str, Any, str]]:
    """Summary rows (label, value, unit) of one solved case of the exact engine."""
    return [
        ("load factor k = Q_max/F_r", float(r.k), "-"),
        ("load concentration K_Q = k z/2", float(r.K_Q), "-"),
        ("heaviest ball load Q_max", float(r.q_max), "N"),
        ("heaviest ball load Q_max", float(r.q_max) / KGF, "kgf"),
        ("balls carrying load", int(r.loaded_balls), ""),
        ("load zone half-angle", float(r.load_zone), "°"),
        ("ring displacement along the load x", float(r.x) * 1e3, "µm"),
        ("ring displacement across the load y", float(r.y) * 1e3, "µm"),
        ("radial stiffness dF_r/dx", float(r.stiffness_radial), "N/mm"),
    ]


def distribution_json(r: LoadDistribution) -> dict[str, Any]:
    """The JSON keys of one solved case of the exact engine (units: :data:`JSON_UNITS`)."""
    return {
        "k": float(r.k),
        "K_Q": float(r.K_Q),
        "q_max": float(r.q_max),
        "loaded_balls": int(r.loaded_balls),
        "load_zone_deg": float(r.load_zone),
        "deflection": float(r.x),
        "deflection_across": float(r.y),
        "stiffness_radial": float(r.stiffness_radial),
        "stiffness_matrix": r.stiffness_matrix.tolist(),
        "ball_angles_deg": r.ball_angles(),
        "ball_loads": r.ball_loads(),
    }


def summary_table(
    title: str, rows: Sequence[tuple[str, Any, str]], notes: Sequence[str] = ()
) -> Table:
    """A quantity | value | unit table."""
    return Table(
        title=title,
        columns=[
            Column("quantity", "quantity", align="left"),
            Column("value", "value", digits=6),
            Column("unit", "unit", align="left"),
        ],
        rows=[{"quantity": q, "value": v, "unit": u} for q, v, u in rows],
        notes=list(notes),
    )
