"""The report of one solved case: per-ball rows, a summary with units, and the JSON document."""

from __future__ import annotations

from typing import Any

import numpy as np

from .equilibrium import solve
from .render import Column, Table, render
from .units import KGF


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
    angle = 180.0 / balls if cage_angle == "half" else float(cage_angle)
    r = solve(balls, load, stiffness, clearance, angle, exponent)
    q = r.ball_loads()
    phi = np.rad2deg(r.ball_angles())
    delta = np.maximum(q / stiffness, 0.0) ** (1.0 / exponent)
    ball_rows = [
        {"ball": i + 1, "angle": float(a), "approach": float(d) * 1e3, "load": float(f)}
        for i, (a, d, f) in enumerate(zip(phi, delta, q, strict=True))
    ]
    summary: list[tuple[str, str, Any, str, int | None]] = [
        ("k", "load factor k = Q_max/F_r", float(r.k), "-", 6),
        ("K_Q", "load concentration K_Q = k z/2", float(r.K_Q), "-", 6),
        ("q_max", "heaviest ball load Q_max", float(r.q_max), "N", 6),
        ("q_max_kgf", "heaviest ball load Q_max", float(r.q_max) / KGF, "kgf", 6),
        ("loaded_balls", "balls carrying load", int(r.loaded_balls), "", None),
        ("load_zone_deg", "load zone half-angle", float(np.rad2deg(r.load_zone)), "°", 6),
        ("deflection", "ring displacement along the load x", float(r.x) * 1e3, "µm", 6),
        ("deflection_across", "ring displacement across the load y", float(r.y) * 1e3, "µm", 6),
        ("stiffness_radial", "radial stiffness dF_r/dx", float(r.stiffness_radial), "N/mm", 6),
    ]
    inputs = (
        f"z = {balls}, F_r = {load:.6g} N ({load / KGF:.6g} kgf), K = {stiffness:.6g} N/mm^{exponent:g}, "
        f"G_r = {clearance * 1e3:.6g} µm (gap per side {clearance * 500:.6g} µm), "
        f"cage angle {angle:.6g}°, m = {exponent:.6g}"
    )
    if fmt == "json":
        doc = {
            "balls": balls,
            "load": load,
            "stiffness": stiffness,
            "clearance": clearance,
            "cage_angle_deg": angle,
            "exponent": exponent,
            "k": float(r.k),
            "K_Q": float(r.K_Q),
            "q_max": float(r.q_max),
            "loaded_balls": int(r.loaded_balls),
            "load_zone_deg": float(np.rad2deg(r.load_zone)),
            "deflection": float(r.x),
            "deflection_across": float(r.y),
            "stiffness_radial": float(r.stiffness_radial),
            "stiffness_matrix": r.stiffness_matrix.tolist(),
            "ball_angles_deg": phi,
            "ball_loads": q,
            "units": {
                "load": "N",
                "stiffness": f"N/mm^{exponent:g}",
                "clearance": "mm (G_r, total radial play)",
                "q_max": "N",
                "ball_loads": "N",
                "deflection": "mm",
                "deflection_across": "mm",
                "stiffness_radial": "N/mm",
                "stiffness_matrix": "N/mm",
            },
        }
        return render([], "json", document=doc)
    summary_table = Table(
        title=f"Summary ({inputs})",
        columns=[
            Column("quantity", "quantity", align="left"),
            Column("value", "value", digits=6),
            Column("unit", "unit", align="left"),
        ],
        rows=[{"quantity": label, "value": v, "unit": unit} for _, label, v, unit, _ in summary],
    )
    balls_table = Table(
        title="Ball loads (ball 1 at the cage angle; angles from the load line)",
        columns=[
            Column("ball", "ball"),
            Column("angle", "angle", "°", 6),
            Column("approach", "approach delta", "µm", 6),
            Column("load", "load Q", "N", 6),
        ],
        rows=ball_rows,
    )
    return render([summary_table, balls_table], fmt)
