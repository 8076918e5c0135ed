"""The report of Kurochkin's dimensionless sweep (``bearingload sweep --kurochkin-T``).

Rows: ``cage_angle``, ``F0`` (= x0), ``F0_prime`` (= -y0) with P = K = 1; summary: the
contact sequence, the exit angle ψ and the Fourier sine coefficients F0j' (j = 1-5) of F0' over
the cage angle (Kurochkin 1973, eqs. 1.13, 2.1-2.3; bearingload.papers.kurochkin).
"""

from __future__ import annotations

from typing import Any

from bearingload.papers.kurochkin import KurochkinSweep
from bearingload.reports.quantities import QUANTITIES, units
from bearingload.reports.render import Column, Table, render

ROW_KEYS = ("cage_angle", "F0", "F0_prime")
NOTE = (
    "F0' Fourier coefficients: Gauss-Legendre quadrature over each smooth piece of half a pitch "
    "(split where a ball enters or leaves contact, kinks mapped out); error < 1e-12."
)


def _rows(s: KurochkinSweep) -> list[dict[str, Any]]:
    return [
        {"cage_angle": float(a), "F0": float(f), "F0_prime": float(p)}
        for a, f, p in zip(s.cage_angle, s.F0, s.F0_prime, strict=True)
    ]


def kurochkin_json(s: KurochkinSweep) -> dict[str, Any]:
    """JSON document: inputs, ``rows``, ``summary`` and ``units``."""
    summary = {
        "contact_sequence": s.contact_sequence,
        "exit_angle": s.exit_angle,
        "F0j_prime": [float(v) for v in s.fourier],
    }
    keys = ["balls", "kurochkin_T", "clearance", *ROW_KEYS, *summary]
    doc: dict[str, Any] = {"balls": s.balls, "kurochkin_T": s.T, "clearance": s.clearance}
    doc["load"] = 1.0
    doc |= {"stiffness": 1.0, "steps": len(s.cage_angle), "rows": _rows(s), "summary": summary}
    unit_map = units(keys)
    # P = K = 1: the load and the stiffness are their own units, the clearance in (P/K)^(2/3)
    unit_map |= {"load": "P", "stiffness": "K", "clearance": "(P/K)^(2/3)"}
    return doc | {"units": unit_map}


def kurochkin_report(s: KurochkinSweep, fmt: str) -> str:
    """Render the sweep in ``fmt`` (table, csv, markdown, json)."""
    if fmt == "json":
        return render([], "json", document=kurochkin_json(s))
    cols = [Column(k, QUANTITIES[k].label, QUANTITIES[k].unit, 10) for k in ROW_KEYS]
    if fmt == "csv":
        extra = [Column("balls", "balls z"), Column("kurochkin_T", "T", "-", 10)]
        rows = [{"balls": s.balls, "kurochkin_T": s.T} | r for r in _rows(s)]
        return render([Table("kurochkin", [*extra, *cols], rows)], "csv")
    psi: Any = "none (every ball loaded)" if s.exit_angle is None else s.exit_angle
    summary: list[dict[str, Any]] = [
        {"quantity": QUANTITIES["contact_sequence"].label, "value": s.contact_sequence},
        {"quantity": "exit angle psi [°]", "value": psi},
        {"quantity": "clearance G_r = 2e [(P/K)^(2/3)]", "value": s.clearance},
    ]
    summary += [
        {"quantity": f"F0{j}' (x 10^3)", "value": 1e3 * float(v)}
        for j, v in enumerate(s.fourier, start=1)
    ]
    head = Table(
        title=f"Kurochkin (1973), n = {s.balls} balls, T = {s.T:.6g}, P = K = 1",
        columns=[Column("quantity", "quantity", align="left"), Column("value", "value", "", 7)],
        rows=summary,
        notes=[NOTE],
    )
    per = Table(title="Per cage position (x0 = F0, y0 = -F0')", columns=cols, rows=_rows(s))
    return render([head, per], fmt)
