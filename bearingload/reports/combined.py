"""The report of ``bearingload solve`` under a combined load: one or more cases in every format.

Cases come from :mod:`bearingload.studies.combined_bearing` (one per clearance); every quantity is
named through :mod:`bearingload.reports.quantities`. The layout and formats of the radial report
(:mod:`bearingload.reports.solve`, docs/guide.md), each ball with its contact angle too.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from typing import Any

from bearingload.bearings.mounting import RESULT_KEYS, mounting_notes
from bearingload.reports.quantities import MATRIX_UNITS, SERVICE_KEYS, column, units
from bearingload.reports.render import Column, Table, render
from bearingload.reports.solve import (
    balls_table,
    blank,
    case_warnings,
    given_keys,
    noted_once,
    per_ball_table,
    present,
    printed_warnings,
    quantity_rows,
    service_notes,
    set_note,
    with_service,
)
from bearingload.studies.combined_bearing import CombinedCase, combined_values
from bearingload.studies.matrix import MATRIX_COLUMNS, MATRIX_KEYS, MATRIX_ROWS
from bearingload.units import turn_angle

INPUT_KEYS = (
    "bearing",
    "method",
    "balls",
    "load",
    "axial_load",
    "moment",
    "moment_cross",
    "misalignment",
    "tilt_radius",
    "rotating",
    "stiffness",
    "clearance",
    "clearance_pick",
    "cage_angle",
    "contact_angle",
)
ANSWER_KEYS = (
    *RESULT_KEYS,  # a mounted bearing's operating clearance and its reductions
    "q_max",
    "k",
    "K_Q",
    "loaded_balls",
    "load_zone",
    "p_max_inner",
    "p_max_outer",
    "static_equivalent_load",
    "static_safety",
    "static_rating",
    "contact_angle_max",
    "free_contact_angle",
    "axial_play",
    "x",
    "y",
    "axial",
    "tilt",
    "tilt_cross",
    "stiffness_radial",
    "stiffness_axial",
    "stiffness_tilt",
    "moment",
    "moment_cross",
    "reference_rating_life",
    "reference_rating_life_hours",
    "dynamic_rating",
    "equivalent_load",
    "rating_life",
    "rating_life_hours",
    *SERVICE_KEYS[:1],  # the shaft speed, then the ball density the ball dynamics used
    "ball_density",
    *SERVICE_KEYS[1:],
)
#: Each ball's inner and outer contact (equal without the ball dynamics): json and csv names.
CONTACT_KEYS = ("contact_angles_inner", "contact_angles_outer", "ball_loads_inner",
                "ball_loads_outer")  # fmt: skip
#: The ``units`` entries of the two matrices: the true tangent and its symmetric part.
MATRIX_UNITS_OF = {"stiffness_matrix": MATRIX_UNITS, "stiffness_matrix_symmetric": MATRIX_UNITS}
PER_BALL_KEYS = (
    "ball",
    "ball_angles",
    "contact_angles",
    "ball_approaches",
    "ball_loads",
    *CONTACT_KEYS,
)
NOTES = (
    "Outer ring fixed; F_r along the load line (ball angles from it), F_a towards +axial.",
    "Axial displacement from the centred rings (half the axial play included, as MASTA "
    "reports it). Without --moment or --misalignment the inner ring is free to tilt (M = 0).",
    "Ball stiffness: exact Hertz at each ball's contact angle (unless --stiffness is given).",
    "L10r: ISO/TS 16281:2008, 4.3 (Q_ci, Q_ce from C_r; cubic mean on the rotating ring, "
    "exponent 10/3 on the stationary one). L10: ISO 281:2007, 5.2-5.3, P = X F_r + Y F_a.",
)
#: What the one-case report adds to :data:`NOTES` (the sweep does not give these quantities).
STATIC_NOTE = (
    "Contact pressures: exact Hertz, every ball at its load and contact angle, the largest of "
    "each contact. s0 = C0/P0, P0 = max(F_r, 0.6 F_r + 0.5 F_a) (ISO 76:2006, 7.1)."
)


#: What replaces the second of :data:`NOTES` for an angular-contact bearing.
ANGULAR_NOTE = (
    "Angular contact (docs/angular_contact.md): one-sided, F_a >= 0 only; the axial displacement "
    "is measured from the zero-load position (every ball at the design angle). Without --moment "
    "or --misalignment the inner ring is free to tilt (M = 0). L10 and P0 at the nominal contact "
    "angle (ISO 281 Table 3: P = F_r for F_a/F_r <= e, else X F_r + Y F_a; ISO 76: "
    "P0 = max(F_r, 0.5 F_r + Y0 F_a)); coded for 15, 20, 25, 30, 35, 40 and 45° only, none "
    "between them (L10 at 15° needs C_0: e and Y there depend on F_a/C_0)."
)
#: The label of ``axial`` for an angular-contact bearing (its origin: every ball at the design
#: angle, not the centred rings).
ANGULAR_LABELS = {"axial": "axial displacement from zero-load position"}
#: What replaces :data:`STATIC_NOTE` for an angular-contact bearing.
ANGULAR_STATIC_NOTE = (
    "Contact pressures: exact Hertz, every ball at its load and contact angle, the largest of "
    "each contact. s0 = C0/P0."
)


def tilt_text(inputs: dict[str, Any]) -> str:
    """', imposed misalignment 0.05°' or ', M = 2000 N mm' (or nothing), then the moment about
    the load line and the lever of the tilt where given, for a title."""
    if inputs.get("misalignment") is not None:
        text = f", imposed misalignment {inputs['misalignment']:.6g}°"
    else:
        text = f", M = {inputs['moment']:.6g} N mm" if inputs["moment"] else ""
    if inputs.get("moment_cross") is not None:
        text += f", M_cross = {inputs['moment_cross']:.6g} N mm"
    if inputs.get("tilt_radius") is not None:
        text += f", tilt lever {inputs['tilt_radius']:.6g} mm"
    return text


def combined_report(
    cases: Sequence[CombinedCase],
    fmt: str,
    *,
    per_ball: bool = False,
    show_geometry: bool = False,
    service: Sequence[Any] | None = None,
) -> str:
    """Render solved combined-load cases in ``fmt`` (table, csv, markdown, json); ``service``
    the lives of each case (:class:`bearingload.bearings.service_life.ServiceLife`)."""
    records = with_service([combined_values(c) for c in cases], service)
    if fmt == "json":
        return render([], "json", document=bearings_document(cases, records, service))
    if fmt == "csv":
        table = _per_ball_table(cases, records) if per_ball else _case_table(records)
        return render([table], "csv")
    tables = []
    if show_geometry:
        from bearingload.reports.bearing import geometry_table

        tables.append(geometry_table(cases[0].bearing))
    summary = _summary(records, cases[0].bearing, getattr(cases[0].result, "model", None))
    summary = dataclasses.replace(summary, notes=[*summary.notes, *service_notes(service)])
    tables.append(summary)
    several = len(cases) > 1
    matrices = [
        matrix_table(
            c.result.stiffness_matrix,
            "tangent stiffness matrix" + (f" (G_r {c.bearing.clearance_pick})" if several else ""),
        )
        for c in cases
    ]
    tables += noted_once(matrices)
    tables.append(_balls_human(cases, records))
    return render(tables, fmt)


def combined_document(
    cases: Sequence[CombinedCase], service: Sequence[Any] | None = None
) -> dict[str, Any]:
    """The json document of solved combined-load cases, before the json's rounding."""
    records = with_service([combined_values(c) for c in cases], service)
    return bearings_document(cases, records, service)


def _case_table(records: Sequence[dict[str, Any]]) -> Table:
    keys = given_keys(records, tuple(dict.fromkeys(INPUT_KEYS + ANSWER_KEYS + MATRIX_KEYS)))
    return Table("cases", [column(k, 1.5) for k in keys], [blank(r, keys) for r in records])


def matrix_table(
    matrix: Any, title: str = "tangent stiffness matrix", csv: str = "stiffness_matrix"
) -> Table:
    """A 5x5 ``stiffness_matrix`` of the combined engine as people read it: a row per force or
    moment, a column per displacement or tilt, each entry d(row)/d(column) in the units the row
    and column name; ``csv``: the stem of its csv columns (``pair_stiffness_matrix`` for a
    pair's shaft)."""
    columns = [Column("row", "", align="left")]
    columns += [Column(m, f"d/d({m}) [1/{u}]", "", 6) for m, u in MATRIX_COLUMNS]
    moves = [m for m, _ in MATRIX_COLUMNS]
    rows = []
    for (force, unit), row in zip(MATRIX_ROWS, matrix, strict=True):
        rows.append({"row": f"{force} [{unit}]"} | dict(zip(moves, map(float, row), strict=True)))
    note = (
        "Entry: the change of the row's force or moment per unit of the column's motion "
        f"({MATRIX_UNITS}); the true tangent, not quite symmetric (its symmetric part: json "
        f"stiffness_matrix_symmetric); json: stiffness_matrix, csv: {csv}_11 ... _55."
    )
    return Table(title, columns, rows, [note])


def _balls(c: CombinedCase) -> list[tuple[float, float, float, float]]:
    r = c.result
    return list(
        zip(
            r.ball_angles.tolist(),
            r.contact_angles.tolist(),
            r.ball_approaches.tolist(),
            r.ball_loads.tolist(),
            strict=True,
        )
    )


def _per_ball_table(cases: Sequence[CombinedCase], records: Sequence[dict[str, Any]]) -> Table:
    per = [ball_values(c) for c in cases]
    return per_ball_table(records, given_keys(records, INPUT_KEYS), per, PER_BALL_KEYS, 1.5)


def ball_values(c: CombinedCase) -> list[dict[str, Any]]:
    """Each ball's values of a solved case as the csv writes them (:data:`PER_BALL_KEYS` but
    its number): angle, contact angle, approach, load and each contact's angle and load."""
    found = contact_values(c.result, c.bearing.contact_angle)
    balls = [dict(zip(PER_BALL_KEYS[1:5], values, strict=True)) for values in _balls(c)]
    return [b | {k: float(found[k][i]) for k in CONTACT_KEYS} for i, b in enumerate(balls)]


#: The note of a solve with the ball dynamics at speed (the model's name filled in).
DYNAMICS_NOTE = (
    "Speed: {} (Jones 1960; Harris & Kotzalas; docs/speed.md): each ball has its own inner and "
    "outer contact angle and load (json: contact_angles_inner, contact_angles_outer, "
    "ball_loads_inner, ball_loads_outer); the ball table shows the inner contacts; L10r takes "
    "the inner loads for the inner ring, the outer loads for the outer ring."
)


#: How a radial load alone on the combined engine gives the radial engine's k and K_Q.
RADIAL_FACTORS_NOTE = (
    "k = Q_max/F_r and K_Q = k z/2 as the radial engine gives them (a radial load alone)."
)
#: How a radial load alone at speed gives the radial engine's k and K_Q.
RADIAL_AT_SPEED_NOTE = (
    "k = Q_max/F_r and K_Q = k z/2 as the radial engine gives them, from the inner contacts, "
    "which carry the shaft's load (the outer ones also carry each ball's centrifugal force); "
    "the static model's load zone (the arc where the ring's displacement closes the "
    "clearance) has no counterpart when every ball presses the outer ring: balls carrying "
    "load counts the loaded inner contacts."
)


def _summary(records: Sequence[dict[str, Any]], bearing: Any, dynamics: str | None = None) -> Table:
    keys = present(records, ANSWER_KEYS)
    if len({r["clearance"] for r in records}) > 1:
        keys.insert(0, "clearance")
    heads = ["value"] if len(records) == 1 else [f"G_r {r['clearance_pick']}" for r in records]
    angular = records[0].get("contact_angle") is not None
    columns, rows = quantity_rows(keys, heads, records, ANGULAR_LABELS if angular else None)
    notes = [*NOTES, STATIC_NOTE, *set_note(bearing), *mounting_notes(bearing)]
    if angular:
        notes[1], notes[len(NOTES)] = ANGULAR_NOTE, ANGULAR_STATIC_NOTE
    if dynamics is not None:
        notes.append(DYNAMICS_NOTE.format(dynamics))
    if "k" in keys:
        notes.append(RADIAL_AT_SPEED_NOTE if dynamics is not None else RADIAL_FACTORS_NOTE)
    return Table(_title(records), columns, rows, notes)


def _title(records: Sequence[dict[str, Any]]) -> str:
    r = records[0]
    who = f"Bearing {r['bearing']}, " if r["bearing"] != "given by hand" else ""
    clear = (
        f"G_r = {r['clearance'] * 1e3:.6g} µm"
        if len({x["clearance"] for x in records}) == 1
        else "G_r: class range"
    )
    lever = f", tilt lever {r['tilt_radius']:.6g} mm" if r.get("tilt_radius") is not None else ""
    if r.get("contact_angle") is not None:  # angular contact: the design angle, no clearance
        clear = f"angular contact, contact angle {r['contact_angle']:.6g}°"
    return (
        f"{who}z = {r['balls']}, F_r = {r['load']:.6g} N, F_a = {r['axial_load']:.6g} N, "
        f"{clear}, cage angle {turn_angle(r['cage_angle'], 6):.6g}°, {r['rotating']} ring rotating{lever}"
    )


def _balls_human(cases: Sequence[CombinedCase], records: Sequence[dict[str, Any]]) -> Table:
    per = [
        [
            {"angle": a, "alpha": contact_angle_shown(alpha, q), "approach": d * 1e3, "q": q}
            for a, alpha, d, q in _balls(c)
        ]
        for c in cases
    ]
    dynamics = getattr(cases[0].result, "model", None) is not None  # the inner contacts shown
    loose = any(ball["q"] <= 0.0 for balls in per for ball in balls)
    notes = [LOOSE_NOTE_AT_SPEED if dynamics else LOOSE_NOTE] if loose else []
    return balls_table(per, [f"G_r {r['clearance_pick']}" for r in records], notes)


#: The per-ball table's note where a ball carries no load.
LOOSE_NOTE = (
    "Contact angle '-': the ball carries no load, so it has no contact angle (a ball whose "
    "groove centres have crossed is loose, not at the groove edge). csv and json keep the "
    "direction of its groove-centre line, atan2(u, max(rho, 0)): up to ±90° for a loose ball."
)
#: :data:`LOOSE_NOTE` with the ball dynamics at speed: the table shows the inner contacts, and
#: a ball whose inner contact carries nothing is still pressed on the outer raceway by its
#: centrifugal force (json: ball_loads_outer).
LOOSE_NOTE_AT_SPEED = (
    "Contact angle '-': the ball's inner contact carries no load, so it has no inner contact "
    "angle; its outer contact still carries the centrifugal force (json: ball_loads_outer, "
    "contact_angles_outer)."
)


def contact_angle_shown(alpha: float, load: float) -> Any:
    """A ball's contact angle [°] as the human table shows it: '-' for a ball carrying no load
    (no contact; a loose ball's ±90° would read as a ball at the groove edge)."""
    return alpha if load > 0.0 else "-"


def model_name(dynamics: str | None, contact_angle: float | None = None) -> str:
    """The ``model`` of a combined-load case as json names it: the 3-D ring equilibrium of a
    bearing of the design ``contact_angle`` [°] (None: deep groove), with ``dynamics`` (the
    ball dynamics' ``model`` at speed, :mod:`bearingload.models.high_speed`) added."""
    kind = ("deep-groove ball bearing" if contact_angle is None
            else f"single-row angular-contact ball bearing, {contact_angle:g}°")  # fmt: skip
    model = f"3-D ring equilibrium, {kind} (ISO/TS 16281)"
    return model if dynamics is None else f"{model}; {dynamics}"


def contact_values(res: Any, contact_angle: float | None = None) -> dict[str, Any]:
    """The ``model`` of a solved combined-load result (one case or many) of a bearing of the
    design ``contact_angle`` [°] (None: deep groove) and each ball's inner and outer contact
    angle [°] and load [N], as json names them: at speed those of
    :class:`bearingload.models.high_speed.HighSpeedDistribution`, else inner = outer."""
    dynamics = getattr(res, "model", None)  # at speed (models.high_speed)
    if dynamics is None:
        angles, loads = (res.contact_angles,) * 2, (res.ball_loads,) * 2
    else:
        angles = (res.contact_angles_inner, res.contact_angles_outer)
        loads = (res.ball_loads_inner, res.ball_loads_outer)
    return {
        "model": model_name(dynamics, contact_angle),
        "contact_angles_inner": angles[0],
        "contact_angles_outer": angles[1],
        "ball_loads_inner": loads[0],
        "ball_loads_outer": loads[1],
    }


def bearings_document(
    cases: Sequence[CombinedCase],
    records: Sequence[dict[str, Any]],
    service: Sequence[Any] | None = None,
) -> dict[str, Any]:
    """The json document of solved combined-load cases of their ``records`` (one bearing, or
    each bearing of a pair), before the json's rounding."""
    from bearingload.reports.bearing import geometry_document

    said = case_warnings([c.warnings for c in cases], service)

    docs: list[dict[str, Any]] = []
    for c, r in zip(cases, records, strict=True):
        res = c.result
        found = contact_values(res, c.bearing.contact_angle)
        docs.append(
            {k: v for k, v in r.items() if k not in MATRIX_KEYS}  # json: the matrix whole
            | {
                "model": found["model"],
                "ball_angles": res.ball_angles,
                "contact_angles": res.contact_angles,
                "contact_angles_inner": found["contact_angles_inner"],
                "contact_angles_outer": found["contact_angles_outer"],
                "ball_approaches": res.ball_approaches,
                "ball_loads": res.ball_loads,
                "ball_loads_inner": found["ball_loads_inner"],
                "ball_loads_outer": found["ball_loads_outer"],
                "stiffness_matrix": res.stiffness_matrix.tolist(),
                "stiffness_matrix_symmetric": res.stiffness_matrix_symmetric.tolist(),
                "warnings": said[len(docs)],
            }
        )
    keys = list(dict.fromkeys(k for d in docs for k in d))
    return {
        "cases": docs,
        "units": units(keys, 1.5) | MATRIX_UNITS_OF,
        "bearing": geometry_document(cases[0].bearing),
        "warnings": printed_warnings(collect_combined_warnings(cases), service),
    }


def collect_combined_warnings(cases: Sequence[CombinedCase]) -> list[str]:
    """The warnings of several cases (the picks of a clearance range), each once, in order, as
    the radial engine's :func:`bearingload.studies.loaded_bearing.collect_warnings` gives them:
    one that only some picks carry is prefixed with its pick (``"G_r max: ..."``)."""
    from bearingload.studies.loaded_bearing import labelled_warnings

    picks = len({c.bearing.clearance_pick for c in cases}) > 1
    labels = [f"G_r {c.bearing.clearance_pick}" if picks else "" for c in cases]
    return labelled_warnings([c.warnings for c in cases], labels)
