"""The report of ``bearingload table life``: L10r against the radial internal clearance.

The numbers come from :func:`bearingload.studies.life_clearance.life_against_clearance`; this
module lays them out. One row per clearance; the bearing, loads and ratings are the table's
conditions (the title for people, leading columns in csv, fields in json, with ``units`` and the
``warnings`` of the checks). Human formats show G_r in µm, csv and json in mm. At a speed the
model is named: with the ball dynamics a note and the json key ``model`` (solve's), the ball
density among the conditions; the static model (``--quasi-static``) a note and the json key
``ball_dynamics``.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from typing import Any

from bearingload.reports.combined import tilt_text
from bearingload.reports.quantities import QUANTITIES, SERVICE_KEYS, column, units
from bearingload.reports.render import Column, Table, render
from bearingload.reports.solve import blank, printed_warnings
from bearingload.studies.life_clearance import (
    AXIAL_LOAD,
    DESIGNATION,
    RADIAL_LOAD,
    LifeAgainstClearance,
    life_vs_clearance,
)
from bearingload.units import turn_angle

#: The row quantities and their short headers in the human table.
ROW_KEYS = (
    ("clearance", "G_r"),
    ("free_contact_angle", "alpha_0"),
    ("loaded_balls", "n"),
    ("contact_angle_max", "alpha_max"),
    ("q_max", "Q_max"),
    ("reference_rating_life", "L10r"),
    ("relative_life", "L10r/L10r(0)"),
    ("rating_life", "L10 ISO 281"),
)
#: The service lives that differ from row to row (the others are the table's conditions), with
#: their short headers.
SERVICE_ROW_KEYS = (
    ("reference_rating_life_hours", "L10rh"),
    ("reference_equivalent_load", "P_ref"),
    ("a_iso_reference", "a_ISO(P_ref)"),
    ("modified_reference_rating_life", "L_nmr"),
    ("modified_reference_rating_life_hours", "L_nmrh"),
    ("film_thickness", "h_min"),
    ("film_ratio", "h_min/sigma"),
)


def life_report(t: LifeAgainstClearance, fmt: str, service: Sequence[Any] | None = None) -> str:
    """Render the life-against-clearance table in ``fmt`` (table, csv, markdown, json);
    ``service`` the lives of each row (:class:`bearingload.bearings.service_life.ServiceLife`):
    those that differ by row are columns, the others conditions."""
    if fmt == "json":
        return render([], "json", document=life_document(t, service))
    return render([life_table(t, human=fmt in ("table", "markdown"), service=service)], fmt)


def _service_rows(service: Sequence[Any] | None) -> list[tuple[str, str]]:
    """The row keys of :data:`SERVICE_ROW_KEYS` the service lives give."""
    if not service:
        return []
    return [(k, h) for k, h in SERVICE_ROW_KEYS if service[0].values.get(k) is not None]


def service_conditions(service: Sequence[Any] | None) -> dict[str, Any]:
    """The service quantities the same in every row, in the reports' order."""
    if not service:
        return {}
    rows = {k for k, _ in SERVICE_ROW_KEYS}
    first = service[0].values
    order = ("static_rating", "rating_life_hours", *SERVICE_KEYS)
    return {k: first[k] for k in order if k in first and k not in rows}


def _tilted(t: LifeAgainstClearance) -> bool:
    """True when the balls take contact angles beyond alpha_0's play (an axial load, a moment
    about either axis or a misalignment): the largest contact angle is then a column."""
    return bool(t.axial_load or t.moment or t.moment_cross or t.misalignment)


def _keys(t: LifeAgainstClearance) -> list[tuple[str, str]]:
    skip = set() if _tilted(t) else {"contact_angle_max"}
    if t.rating_life is None:
        skip.add("rating_life")
    return [(k, h) for k, h in ROW_KEYS if k not in skip]


def conditions(t: LifeAgainstClearance) -> dict[str, Any]:
    """The table's conditions under their quantity keys."""
    out: dict[str, Any] = {
        "bearing": t.bearing.designation or "given by hand",
        "balls": int(t.bearing.balls),
        "load": t.load,
        "axial_load": t.axial_load,
    }
    if t.misalignment is not None:
        out["misalignment"] = float(t.misalignment)
    else:
        out["moment"] = float(t.moment or 0.0)
    if t.moment_cross is not None:
        out["moment_cross"] = float(t.moment_cross)
    if t.tilt_radius is not None:
        out["tilt_radius"] = float(t.tilt_radius)
    return out | {
        "rotating": t.rotating,
        "cage_angle": t.cage_angle,
        "dynamic_rating": t.dynamic_rating,
        "equivalent_load": t.equivalent_load,
    }


def all_conditions(t: LifeAgainstClearance, service: Sequence[Any] | None) -> dict[str, Any]:
    """The table's conditions, those of the service lives and, with the ball dynamics, the
    ball density [kg/m^3] (as solve's json and csv give it)."""
    density = {} if t.ball_density is None else {"ball_density": t.ball_density}
    return conditions(t) | service_conditions(service) | density


def _rows(t: LifeAgainstClearance, service: Sequence[Any] | None = None) -> list[dict[str, Any]]:
    """One dict per clearance in machine units: the quantities of :func:`_keys`, then the
    service lives that differ from row to row."""
    data: dict[str, Any] = {
        "clearance": t.clearance,
        "free_contact_angle": t.free_contact_angle,
        "loaded_balls": t.loaded_balls,
        "contact_angle_max": t.contact_angle_max,
        "q_max": t.q_max,
        "reference_rating_life": t.reference_rating_life,
        "relative_life": t.relative_life,
        "rating_life": [t.rating_life] * t.clearance.size,
    }
    keys = [k for k, _ in _keys(t)]
    rows = [
        {k: int(data[k][i]) if k == "loaded_balls" else float(data[k][i]) for k in keys}
        for i in range(t.clearance.size)
    ]
    for row, lives in zip(rows, service or [], strict=False):
        row |= {k: lives.values.get(k) for k, _ in _service_rows(service)}
    return rows


def title(t: LifeAgainstClearance) -> str:
    c = conditions(t)
    who = f"bearing {c['bearing']}" if c["bearing"] != "given by hand" else "ball set given by hand"
    tilt = tilt_text(c)
    return (
        f"L10r against radial internal clearance: {who}, z = {c['balls']}, "
        f"F_r = {t.load:.6g} N, F_a = {t.axial_load:.6g} N{tilt}, {t.rotating} ring rotating, "
        f"cage angle {turn_angle(t.cage_angle, 6):.6g}°, C_r = {t.dynamic_rating:.6g} N"
    )


def _notes(t: LifeAgainstClearance) -> list[str]:
    best = int(t.reference_rating_life.argmax())
    p = t.equivalent_load
    iso281 = (
        f"L10 ISO 281: ISO 281:2007 basic life (C_r/P)^3 with P = X F_r + Y F_a = {p:.6g} N "
        "(5.2, Table 3, normal clearance), the same in every row: it does not see the clearance."
        if t.rating_life is not None and p is not None
        else "ISO 281's basic life: none under a moment alone (P = X F_r + Y F_a = 0 N)."
        if p == 0
        else "ISO 281's basic life needs P = X F_r + Y F_a, i.e. C0r and f0 of a catalogue "
        "bearing: not given for a ball set given by hand."
    )
    return [
        "G_r: radial internal clearance, total play (negative = preload); alpha_0: free contact "
        "angle; n: balls carrying load; alpha_max: largest contact angle of a loaded ball.",
        "L10r: ISO/TS 16281:2008, 4.3, from the ball loads of the 3-D ring equilibrium (exact "
        "Hertz stiffness at each contact angle; the ring free to tilt unless a moment or a "
        "misalignment is given); L10r(0): at G_r = 0.",
        iso281,
        f"Longest L10r of the rows: G_r = {t.clearance[best] * 1e3:.6g} µm, "
        f"{t.relative_life[best]:.4g} times that at G_r = 0.",
        "Question after Oswald, Zaretsky & Poplawski, NASA TM-2012-217115 (2012).",
    ]


def life_table(
    t: LifeAgainstClearance, human: bool = True, service: Sequence[Any] | None = None
) -> Table:
    """The table: display units (µm) for people, machine units (mm) for csv."""
    columns = [column(k, header=h, shown=True) for k, h in _keys(t) + _service_rows(service)]
    columns[0] = dataclasses.replace(columns[0], digits=4)  # G_r to 0.1 µm
    conds = all_conditions(t, service)
    fixed = [] if human else [(column(k), v) for k, v in blank(conds).items()]
    notes = _notes(t) + _service_notes(service) + _speed_notes(t, service) if human else []
    return Table(title(t), columns, _rows(t, service), notes, fixed)


#: The note of a table with the ball dynamics at --speed (the model's name, the density).
DYNAMICS_NOTE = (
    "Speed: {} (Jones 1960; Harris & Kotzalas; docs/speed.md), balls of {:.6g} kg/m^3: every "
    "row as 'bearingload solve --speed' solves it; alpha_0: at rest; n, alpha_max and Q_max: the "
    "inner contacts'; L10r takes the inner loads for the inner ring, the outer loads for the "
    "outer ring."
)


def _speed_model(t: LifeAgainstClearance, service: Sequence[Any] | None) -> dict[str, str]:
    """The json key naming the model at a speed: ``model`` (solve's name) with the ball
    dynamics, ``ball_dynamics`` (:data:`STATIC_AT_SPEED`) for the static model; none
    without a speed."""
    from bearingload.reports.combined import model_name
    from bearingload.reports.sweep import static_at_speed

    if t.model is not None:
        return {"model": model_name(t.model)}
    return static_at_speed(service[0].values.get("speed") if service else None)


def _speed_notes(t: LifeAgainstClearance, service: Sequence[Any] | None) -> list[str]:
    """The note naming the model at a speed (none without one)."""
    if t.model is not None and t.ball_density is not None:
        return [DYNAMICS_NOTE.format(t.model, t.ball_density)]
    return list(_speed_model(t, service).values())


def _service_notes(service: Sequence[Any] | None) -> list[str]:
    """The conditions of the service lives, one line, and their notes."""
    from bearingload.reports.solve import service_notes

    conds = service_conditions(service)
    if not conds:
        return []
    parts = []
    for key, value in conds.items():
        q = QUANTITIES[key]
        unit, factor = q.shown()
        parts.append(f"{q.label} = {value * factor:.6g}{' ' + unit if unit != '-' else ''}")
    return ["; ".join(parts) + "."] + service_notes(service)


def life_document(t: LifeAgainstClearance, service: Sequence[Any] | None = None) -> dict[str, Any]:
    """The JSON document: the conditions, ``rows``, ``units``, ``geometry`` (the bearing's, with
    the source of every value), ``warnings``."""
    from bearingload.reports.bearing import geometry_document

    conds = all_conditions(t, service)
    body = _rows(t, service)
    return {
        "title": title(t),
        **conds,
        "rows": body,
        "units": units([*conds, *body[0]], 1.5),
        "geometry": geometry_document(t.bearing),
        "warnings": printed_warnings(t.warnings, service),
    } | _speed_model(t, service)


def life_vs_clearance_table() -> Table:
    """The committed table ``tables/life_vs_clearance_6205``."""
    rows, radial, combined = life_vs_clearance()
    b, p = combined.bearing, combined.equivalent_load
    assert b.C is not None and b.C0 is not None and b.geometry is not None and p is not None
    f0 = b.geometry.f0
    best_r = max(rows, key=lambda r: r["life_r"])
    best_c = max(rows, key=lambda r: r["life_c"])
    columns = [
        Column("clearance_um", "G_r", "um", 3),
        Column("free_contact_angle", "alpha_0", "°", 4),
        Column("loaded_r", "n (F_r)"),
        Column("q_max_r", "Q_max (F_r)", "N", 5),
        Column("life_r", "L10r (F_r)", "10^6 rev", 5),
        Column("ratio_r", "L10r/L10r(0) (F_r)", "-", 4),
        Column("loaded_c", "n (F_r+F_a)"),
        Column("alpha_max_c", "alpha_max (F_r+F_a)", "°", 4),
        Column("q_max_c", "Q_max (F_r+F_a)", "N", 5),
        Column("life_c", "L10r (F_r+F_a)", "10^6 rev", 5),
        Column("ratio_c", "L10r/L10r(0) (F_r+F_a)", "-", 4),
    ]
    notes = [
        f"Bearing {DESIGNATION}: z = {b.balls}, D_w = {b.ball_diameter} mm, "
        f"d_m = {b.pitch_diameter} mm, f_i = {b.f_i}, f_o = {b.f_o}, E = {b.modulus:g} MPa, "
        f"C_r = {b.C:g} N; F_r = {RADIAL_LOAD:g} N, F_a = {AXIAL_LOAD:g} N; inner ring rotating; "
        "negative G_r = preload.",
        "L10r: ISO/TS 16281:2008 clause 4.3 from the ball loads of the 3-D ring equilibrium "
        "(exact Hertz stiffness at each contact angle, ring free to tilt).",
        f"Longest life: F_r alone at G_r = {best_r['clearance_um']:g} um, "
        f"F_r + F_a at G_r = {best_c['clearance_um']:g} um (of the rows).",
        f"ISO 281:2007 basic life, blind to clearance: F_r alone (C_r/F_r)^3 = "
        f"{radial.rating_life:.5g}; F_r + F_a: P = X F_r + Y F_a = "
        f"{p:.5g} N (5.2, Table 3, f0 = {f0:g}, C0r = {b.C0:g} N), "
        f"(C_r/P)^3 = {combined.rating_life:.5g} (10^6 rev).",
        "Question after Oswald, Zaretsky & Poplawski, NASA TM-2012-217115 (2012).",
    ]
    return Table("L10r against radial internal clearance, 6205", columns, rows, notes)
