"""The report of one solved case: a summary with units, every ball's load, or the JSON document."""

from __future__ import annotations

import numpy as np

from bearingload.models.equilibrium import solve
from bearingload.reports.parts import (
    JSON_UNITS,
    cage_angle_deg,
    distribution_json,
    distribution_rows,
    inputs_json,
    inputs_text,
    summary_table,
)
from bearingload.reports.render import Column, Table, render


def solve_report(
    balls: int,
    load: float,
    stiffness: float,
    clearance: float,
    cage_angle: float | str,
    exponent: float,
    fmt: str,
) -> str:
    """Solve one case and render it in ``fmt``. Inputs in N, N/mm^m, mm, degrees or ``"half"``."""
    return solve_report_with_warnings(balls, load, stiffness, clearance, cage_angle, exponent, fmt)[
        0
    ]


def solve_report_with_warnings(
    balls: int,
    load: float,
    stiffness: float,
    clearance: float,
    cage_angle: float | str,
    exponent: float,
    fmt: str,
) -> tuple[str, list[str]]:
    """:func:`solve_report` and the case's warnings (:func:`bearingload.bearings.checks.element_warnings`)."""
    from bearingload.bearings.checks import element_warnings

    angle = cage_angle_deg(cage_angle, balls)
    args = (balls, load, stiffness, clearance, angle, exponent)
    r = solve(*args)
    warnings = element_warnings(r, balls)
    if fmt == "json":
        doc = inputs_json(*args) | distribution_json(r) | {"warnings": warnings}
        doc["units"] = JSON_UNITS | {"stiffness": f"N/mm^{exponent:g}"}
        return render([], "json", document=doc), warnings
    q = r.ball_loads()
    approach = np.maximum(q / stiffness, 0.0) ** (1.0 / exponent)
    balls_table = Table(
        title="Ball loads (ball 1 at the cage angle; angles from the load line)",
        columns=[
            Column("ball", "ball"),
            Column("angle", "angle", "°", 6),
            Column("approach", "approach delta", "µm", 6),
            Column("load", "load Q", "N", 6),
        ],
        rows=[
            {"ball": i + 1, "angle": float(a), "approach": float(d) * 1e3, "load": float(f)}
            for i, (a, d, f) in enumerate(zip(r.ball_angles(), approach, q, strict=True))
        ],
    )
    summary = summary_table(f"Summary ({inputs_text(*args)})", distribution_rows(r))
    return render([summary, balls_table], fmt), warnings
