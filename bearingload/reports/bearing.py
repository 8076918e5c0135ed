"""The geometry block of a catalogue (or hand-described) bearing: every value used and its source.

``bearingload solve BEARING --show-geometry`` prints :func:`geometry_table`; the JSON of every
``solve BEARING`` carries :func:`geometry_document`.
"""

from __future__ import annotations

from typing import Any

from bearingload.bearings.resolve import ResolvedBearing
from bearingload.reports.render import Column, Table


def geometry_table(b: ResolvedBearing) -> Table:
    """quantity | value | unit | source of every geometry and stiffness value used."""
    name = f"Bearing {b.designation}" if b.designation else "Bearing (given by hand)"
    if b.geometry is not None:
        name += f" ({b.geometry.standard})"
    rows = []
    for p in b.provenance:
        if p.key == "clearance" or p.value is None:
            continue
        rows.append({"quantity": p.label, "value": p.value, "unit": p.unit, "source": p.source})
    return Table(
        title=f"{name}: geometry and stiffness used",
        columns=[
            Column("quantity", "quantity", align="left"),
            Column("value", "value", digits=6),
            Column("unit", "unit", align="left"),
            Column("source", "source", align="left"),
        ],
        rows=rows,
        notes=list(b.sources),
    )


def geometry_document(b: ResolvedBearing) -> dict[str, Any]:
    """The bearing's JSON object: designation, ratings, clearance class, geometry with sources."""
    k_unit = "N/mm^(10/9)" if b.kind == "roller" else "N/mm^1.5"
    return {
        "designation": b.designation,
        "standard": None if b.geometry is None else b.geometry.standard,
        "kind": b.kind,
        "maker": None if b.geometry is None else b.geometry.maker,
        "stiffness_inner": b.stiffness_inner,
        "stiffness_outer": b.stiffness_outer,
        "stiffness_given": b.stiffness_given,
        "C": b.C,
        "C0": b.C0,
        "clearance_class": b.clearance_class,
        "clearance_range": list(b.clearance_range) if b.clearance_range else None,
        "geometry": {
            p.key: {"value": p.value, "unit": p.unit, "source": p.source} for p in b.provenance
        },
        "sources": list(b.sources),
        "units": {
            "stiffness_inner": k_unit,
            "stiffness_outer": k_unit,
            "C": "N",
            "C0": "N",
            "clearance_range": "mm",
        },
    }
