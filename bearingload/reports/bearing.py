"""The report of one catalogued (or hand-described) bearing under a radial load.

Blocks: the geometry used and where each value came from; the summary (load factor, heaviest
ball load, load zone, ring displacement, contact pressures, rating life, allowable load); the
per-ball loads. With several clearances (a class evaluated at its min, mean and max) every
result becomes one column per clearance, side by side.

Units: N, mm, µm in the human formats where labelled, MPa, N/mm^1.5; life in 10^6 revolutions.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from bearingload.bearings.life import (
    BALL_LIFE_EXPONENT,
    ROLLER_LIFE_EXPONENT,
    allowable_load,
    rating_life,
)
from bearingload.bearings.resolve import ResolvedBearing
from bearingload.models.equilibrium import LoadDistribution, solve
from bearingload.reports.parts import (
    JSON_UNITS,
    cage_angle_deg,
    distribution_json,
    distribution_rows,
    summary_table,
)
from bearingload.reports.render import Column, Table, render
from bearingload.units import KGF


@dataclass(frozen=True)
class BearingCase:
    """One solved case: the bearing (at one clearance), its load distribution and derived values."""

    bearing: ResolvedBearing
    load: float  # [N]
    cage_angle: float  # [°]
    result: LoadDistribution
    p_max_inner: float | None  # [MPa]
    p_max_outer: float | None  # [MPa]
    rating_life: float | None  # [10^6 rev]
    allowable_load: float | None  # [N]
    revolutions: float  # [rev]
    warnings: tuple[str, ...] = ()  # bearingload.bearings.checks.case_warnings


def solve_bearing(
    bearing: ResolvedBearing,
    load: float,
    cage_angle: float | str = 0.0,
    revolutions: float = 36e6,
) -> BearingCase:
    """Solve the ring equilibrium of ``bearing`` under the radial load ``load`` [N].

    Parameters
    ----------
    bearing : ResolvedBearing
        From :func:`bearingload.bearings.resolve.resolve_bearing`.
    load : float
        Radial load F_r. [N]
    cage_angle : float or "half"
        Angle of ball 1 from the load line [°]; ``"half"`` = half a pitch.
    revolutions : float
        Life for the allowable load C / (L/10^6)^(1/3). [rev]

    Returns
    -------
    BearingCase
        p_max of both contacts at the heaviest ball load (when the geometry is known), the basic
        rating life (C/F_r)^p (p = 3 balls, 10/3 rollers) and the allowable load (when C is
        known), and the warnings of :func:`bearingload.bearings.checks.case_warnings`.
    """
    from bearingload.bearings.checks import case_warnings, max_contact_pressures

    z = bearing.balls
    angle = cage_angle_deg(cage_angle, z)
    r = solve(z, load, bearing.stiffness, bearing.clearance, angle, bearing.exponent)
    pressures = max_contact_pressures(bearing, float(r.q_max))
    p_i, p_o = pressures if pressures is not None else (None, None)
    life = allow = None
    if bearing.C:
        p = ROLLER_LIFE_EXPONENT if bearing.kind == "roller" else BALL_LIFE_EXPONENT
        life = float(rating_life(bearing.C, load, p))
        allow = float(allowable_load(bearing.C, revolutions / 1e6, p))
    warnings = tuple(case_warnings(bearing, load, r))
    return BearingCase(bearing, load, angle, r, p_i, p_o, life, allow, revolutions, warnings)


def _summary(case: BearingCase) -> list[tuple[str, Any, str]]:
    rows: list[tuple[str, Any, str]] = [
        ("radial clearance G_r", case.bearing.clearance * 1e3, "µm")
    ]
    rows += distribution_rows(case.result)
    if case.p_max_inner is not None:
        rows += [
            ("max contact pressure, inner", case.p_max_inner, "MPa"),
            ("max contact pressure, outer", case.p_max_outer, "MPa"),
        ]
    if case.rating_life is not None:
        roller = case.bearing.kind == "roller"
        power, root = ("(10/3)", "(3/10)") if roller else ("3", "(1/3)")
        label = f"allowable load C/L^{root}, L = {case.revolutions:.4g} rev"
        rows += [
            (f"basic rating life L10 = (C/F_r)^{power}", case.rating_life, "10^6 rev"),
            (label, case.allowable_load, "N"),
            (label, (case.allowable_load or 0.0) / KGF, "kgf"),
        ]
    return rows


def _geometry_table(b: ResolvedBearing) -> Table:
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


def _inputs(case: BearingCase) -> str:
    b = case.bearing
    return (
        f"F_r = {case.load:.6g} N ({case.load / KGF:.6g} kgf), cage angle {case.cage_angle:.6g}°; "
        f"G_r: {next(p.source for p in b.provenance if p.key == 'clearance')}"
    )


def bearing_report(cases: list[BearingCase], fmt: str) -> str:
    """Render one case, or the same bearing at several clearances side by side, in ``fmt``."""
    if fmt == "json":
        return render([], "json", document=_document(cases))
    first = cases[0]
    summaries = [_summary(c) for c in cases]
    if len(cases) == 1:
        summary = summary_table(f"Summary ({_inputs(first)})", summaries[0])
    else:
        picks = [c.bearing.clearance_pick or str(i) for i, c in enumerate(cases)]
        rows = []
        for i, (lab, _, unit) in enumerate(summaries[0]):
            row: dict[str, Any] = {"quantity": lab, "unit": unit}
            for pick, s in zip(picks, summaries, strict=True):
                row[pick] = s[i][1]
            rows.append(row)
        summary = Table(
            title=(
                f"Summary at the {first.bearing.clearance_class} clearance range "
                f"(F_r = {first.load:.6g} N, {first.load / KGF:.6g} kgf; "
                f"cage angle {first.cage_angle:.6g}°)"
            ),
            columns=[Column("quantity", "quantity", align="left")]
            + [Column(p, f"G_r {p}", digits=6) for p in picks]
            + [Column("unit", "unit", align="left")],
            rows=rows,
        )
    return render([_geometry_table(first.bearing), summary, _balls_table(cases)], fmt)


def _balls_table(cases: list[BearingCase]) -> Table:
    first = cases[0].result
    phi = first.ball_angles()
    loads = [c.result.ball_loads() for c in cases]
    columns = [Column("ball", "ball"), Column("angle", "angle", "°", 6)]
    if len(cases) == 1:
        columns.append(Column("load", "load Q", "N", 6))
        keys = ["load"]
    else:
        keys = [c.bearing.clearance_pick or str(i) for i, c in enumerate(cases)]
        columns += [Column(k, f"Q at G_r {k}", "N", 6) for k in keys]
    rows = []
    for j, a in enumerate(phi):
        row: dict[str, Any] = {"ball": j + 1, "angle": float(a)}
        for k, q in zip(keys, loads, strict=True):
            row[k] = float(q[j])
        rows.append(row)
    return Table(
        title="Ball loads (ball 1 at the cage angle; angles from the load line)",
        columns=columns,
        rows=rows,
    )


def _case_document(case: BearingCase) -> dict[str, Any]:
    return (
        {"clearance": case.bearing.clearance, "clearance_pick": case.bearing.clearance_pick}
        | distribution_json(case.result)
        | {
            "p_max_inner": case.p_max_inner,
            "p_max_outer": case.p_max_outer,
            "rating_life": case.rating_life,
            "allowable_load": case.allowable_load,
            "warnings": list(case.warnings),
        }
    )


def _document(cases: list[BearingCase]) -> dict[str, Any]:
    first = cases[0]
    b = first.bearing
    doc: dict[str, Any] = {
        "bearing": b.designation,
        "balls": b.balls,
        "load": first.load,
        "cage_angle_deg": first.cage_angle,
        "kind": b.kind,
        "maker": b.geometry.maker if b.geometry is not None else None,
        "exponent": b.exponent,
        "stiffness": b.stiffness,
        "stiffness_ball": b.stiffness,
        "stiffness_inner": b.stiffness_inner,
        "stiffness_outer": b.stiffness_outer,
        "revolutions": first.revolutions,
        "C": b.C,
        "C0": b.C0,
        "clearance_class": b.clearance_class,
        "clearance_range": list(b.clearance_range) if b.clearance_range else None,
        "geometry": {
            p.key: {"value": p.value, "unit": p.unit, "source": p.source} for p in b.provenance
        },
        "sources": list(b.sources),
    }
    if len(cases) == 1:
        doc.update(_case_document(first))
    else:
        doc["cases"] = [_case_document(c) for c in cases]
        doc["warnings"] = collect_warnings(cases)
    k_unit = "N/mm^(10/9)" if b.kind == "roller" else "N/mm^1.5"
    doc["units"] = JSON_UNITS | {
        "stiffness": k_unit,
        "stiffness_ball": k_unit,
        "stiffness_inner": k_unit,
        "stiffness_outer": k_unit,
        "clearance_range": "mm",
        "p_max_inner": "MPa (at the heaviest ball load)",
        "p_max_outer": "MPa (at the heaviest ball load)",
        "rating_life": "10^6 revolutions, (C/F_r)^(10/3)"
        if b.kind == "roller"
        else "10^6 revolutions, (C/F_r)^3",
        "allowable_load": "N, C/(revolutions/10^6)^(3/10)"
        if b.kind == "roller"
        else "N, C/(revolutions/10^6)^(1/3)",
        "revolutions": "revolutions",
        "C": "N",
        "C0": "N",
    }
    return doc


def collect_warnings(cases: list[BearingCase]) -> list[str]:
    """The warnings of several cases (a clearance range), each once, in order."""
    seen: list[str] = []
    for c in cases:
        seen += [w for w in c.warnings if w not in seen]
    return seen
