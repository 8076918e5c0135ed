"""The report of a cage sweep: a summary over one pitch and one row per cage position.

Human formats (table, markdown) show lengths in µm; csv and json in mm, like every report. csv is
one rectangular table: one row per cage angle with the case's inputs as constant columns (the
summary is in the table and json formats).
"""

from __future__ import annotations

from typing import Any

from bearingload.reports.parts import summary_table
from bearingload.reports.render import Column, Table, render
from bearingload.studies.sweep import CageSweep
from bearingload.units import KGF

#: Quantities summarised over the sweep: key, label, unit of the human formats, factor from the
#: library unit (mm, N, N/mm) to it.
SPREADS = (
    ("x", "ring displacement along the load x", "µm", 1e3),
    ("y", "ring displacement across the load y", "µm", 1e3),
    ("q_max", "heaviest ball load Q_max", "N", 1.0),
    ("stiffness_radial", "radial stiffness dF_r/dx", "N/mm", 1.0),
)


def sweep_report(s: CageSweep, fmt: str, context: str = "") -> str:
    """Render a sweep in ``fmt``; ``context`` (e.g. the bearing and its sources) is noted."""
    if fmt == "json":
        return render([], "json", document=sweep_json(s))
    if fmt == "csv":
        return render([_csv_table(s)], "csv")
    return render([_spread_table(s, context), _figures_table(s), _rows_table(s)], fmt)


def inputs_text(s: CageSweep) -> str:
    """One line naming the sweep's inputs with units."""
    return (
        f"z = {s.balls}, F_r = {s.load:.6g} N ({s.load / KGF:.6g} kgf), "
        f"K = {s.stiffness:.6g} N/mm^{s.exponent:g}, G_r = {s.clearance * 1e3:.6g} µm "
        f"(gap per side {s.clearance * 500:.6g} µm), m = {s.exponent:.6g}; cage angle 0 to "
        f"{360 / s.balls:.6g}° in {s.cage_angle.size} positions"
    )


def _spread_table(s: CageSweep, context: str) -> Table:
    rows = []
    for key, label, unit, factor in SPREADS:
        sp = s.spread(key)
        rows.append(
            {
                "quantity": label,
                "min": sp.min * factor,
                "mean": sp.mean * factor,
                "max": sp.max * factor,
                "ptp": sp.peak_to_peak * factor,
                "unit": unit,
            }
        )
    notes = ["mean: over one period (the last position, equal to the first, left out)."]
    if context:
        notes.append(context)
    return Table(
        title=f"Over one ball pitch ({inputs_text(s)})",
        columns=[
            Column("quantity", "quantity", align="left"),
            Column("min", "min", digits=6),
            Column("mean", "mean", digits=6),
            Column("max", "max", digits=6),
            Column("ptp", "peak-to-peak", digits=4),
            Column("unit", "unit", align="left"),
        ],
        rows=rows,
        notes=notes,
    )


def _figures_table(s: CageSweep) -> Table:
    rows: list[tuple[str, Any, str]] = [
        ("ripple frequency (periods per cage revolution)", s.ripple_order, "1/rev"),
    ]
    if s.compensating_clearance:
        for g in s.compensating_clearance:
            rows.append(("compensating clearance G_r", g * 1e3, "µm"))
    else:
        rows.append(("compensating clearance G_r", "none", ""))
    return summary_table(
        "Ripple",
        rows,
        notes=[
            "compensating clearance: every G_r at which the ring sits at the same x with a ball "
            "under the load and with the load between two balls (no kinematic excitation)."
        ],
    )


def _rows_table(s: CageSweep) -> Table:
    return Table(
        title="Per cage position (ball 1 at the cage angle; angles from the load line)",
        columns=[
            Column("cage_angle", "cage angle", "°", 6),
            Column("x", "x", "µm", 7),
            Column("y", "y", "µm", 6),
            Column("q_max", "Q_max", "N", 6),
            Column("ball", "ball"),
            Column("loaded", "loaded"),
            Column("kxx", "K_xx", "N/mm", 6),
            Column("kxy", "K_xy", "N/mm", 6),
            Column("kyy", "K_yy", "N/mm", 6),
            Column("kr", "K_r", "N/mm", 6),
        ],
        rows=[
            {
                "cage_angle": float(s.cage_angle[i]),
                "x": float(s.x[i]) * 1e3,
                "y": float(s.y[i]) * 1e3,
                "q_max": float(s.q_max[i]),
                "ball": int(s.q_max_ball[i]),
                "loaded": int(s.loaded_balls[i]),
                "kxx": float(s.stiffness_matrix[i, 0, 0]),
                "kxy": float(s.stiffness_matrix[i, 0, 1]),
                "kyy": float(s.stiffness_matrix[i, 1, 1]),
                "kr": float(s.stiffness_radial[i]),
            }
            for i in range(s.cage_angle.size)
        ],
        notes=["ball: the ball carrying Q_max (of two equal, the lower number)."],
    )


def _csv_table(s: CageSweep) -> Table:
    k_unit = f"N/mm^{s.exponent:g}"
    columns = [
        Column("balls", "balls"),
        Column("load", "load", "N"),
        Column("stiffness", "stiffness", k_unit),
        Column("clearance", "clearance", "mm"),
        Column("exponent", "exponent"),
        Column("cage_angle_deg", "cage angle", "°"),
        Column("x", "x", "mm"),
        Column("y", "y", "mm"),
        Column("q_max", "Q_max", "N"),
        Column("q_max_ball", "ball"),
        Column("loaded_balls", "loaded balls"),
        Column("stiffness_xx", "K_xx", "N/mm"),
        Column("stiffness_xy", "K_xy", "N/mm"),
        Column("stiffness_yy", "K_yy", "N/mm"),
        Column("stiffness_radial", "K_r", "N/mm"),
    ]
    inputs = {
        "balls": s.balls,
        "load": s.load,
        "stiffness": s.stiffness,
        "clearance": s.clearance,
        "exponent": s.exponent,
    }
    rows = []
    for row in _json_rows(s):
        matrix = row.pop("stiffness_matrix")
        row |= {
            "stiffness_xx": matrix[0][0],
            "stiffness_xy": matrix[0][1],
            "stiffness_yy": matrix[1][1],
        }
        rows.append(inputs | row)
    return Table(title="sweep", columns=columns, rows=rows)


def _json_rows(s: CageSweep) -> list[dict[str, Any]]:
    return [
        {
            "cage_angle_deg": float(s.cage_angle[i]),
            "x": float(s.x[i]),
            "y": float(s.y[i]),
            "q_max": float(s.q_max[i]),
            "q_max_ball": int(s.q_max_ball[i]),
            "loaded_balls": int(s.loaded_balls[i]),
            "stiffness_matrix": s.stiffness_matrix[i].tolist(),
            "stiffness_radial": float(s.stiffness_radial[i]),
        }
        for i in range(s.cage_angle.size)
    ]


def sweep_json(s: CageSweep) -> dict[str, Any]:
    """The JSON document of a sweep: inputs, ``rows``, ``summary`` and ``units``."""
    summary: dict[str, Any] = {}
    for key, *_ in SPREADS:
        sp = s.spread(key)
        summary[key] = {
            "min": sp.min,
            "mean": sp.mean,
            "max": sp.max,
            "peak_to_peak": sp.peak_to_peak,
        }
    summary["ripple_per_cage_revolution"] = s.ripple_order
    summary["compensating_clearance"] = list(s.compensating_clearance)
    return {
        "balls": s.balls,
        "load": s.load,
        "stiffness": s.stiffness,
        "clearance": s.clearance,
        "exponent": s.exponent,
        "steps": int(s.cage_angle.size),
        "rows": _json_rows(s),
        "summary": summary,
        "units": {
            "load": "N",
            "stiffness": f"N/mm^{s.exponent:g}",
            "clearance": "mm (G_r, total radial play)",
            "cage_angle_deg": "°",
            "x": "mm",
            "y": "mm",
            "q_max": "N",
            "stiffness_matrix": "N/mm",
            "stiffness_radial": "N/mm",
            "ripple_per_cage_revolution": "1/rev (periods per cage revolution)",
            "compensating_clearance": "mm (G_r, total radial play)",
        },
    }
