"""The report of ``bearingload solve`` for a pair of angular-contact ball bearings (DB, DF, DT):
the terminal table, json and csv that docs/angular_contact.md ("Outputs") describes.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from typing import Any

from bearingload.bearings.preload import Preload
from bearingload.reports.combined import (
    ANGULAR_LABELS,
    MATRIX_UNITS_OF,
    ball_values,
    contact_angle_shown,
)
from bearingload.reports.quantities import MATRIX_UNITS, SERVICE_KEYS, column, units
from bearingload.reports.render import Column, Table, render
from bearingload.reports.solve import (
    blank,
    material_note,
    noted_once,
    printed_warnings,
    quantity_rows,
    service_notes,
    with_service,
)
from bearingload.studies.bearing_pair import ARRANGEMENT_NAMES, PairCase, PairLives
from bearingload.studies.combined_bearing import combined_values
from bearingload.studies.matrix import MATRIX_KEYS, matrix_columns
from bearingload.units import turn_angle

#: The pair's inputs (every row of the csv, the JSON case).
PAIR_INPUTS = ("bearing", "arrangement", "balls", "load", "axial_load", "moment", "moment_cross",
               "preload", "width", "contact_angle", "cage_angle", "rotating")  # fmt: skip
#: The pair's answers (``pair_`` columns in the csv).
PAIR_ANSWERS = ("x", "y", "axial", "tilt", "tilt_cross", "stiffness_radial", "stiffness_axial",
                "stiffness_tilt", "lift_off_axial_load", "unloaded_bearings",
                "reference_rating_life", "rating_life")  # fmt: skip
#: The pair's service values (:func:`bearingload.studies.bearing_pair.pair_service_values`):
#: ``pair_`` columns in the csv where given.
PAIR_SERVICE = ("speed", "preload_at_speed", "reliability", "reference_rating_life_hours",
                "rating_life_hours",
                "modified_rating_life", "modified_rating_life_hours",
                "modified_reference_rating_life", "modified_reference_rating_life_hours")  # fmt: skip
#: The rows of the human summary (the pair's column shows what it has).
SUMMARY_KEYS = ("load", "axial_load", "moment", "q_max", "loaded_balls", "p_max_inner",
                "p_max_outer", "static_equivalent_load", "static_safety", "contact_angle_max",
                "x", "y", "axial", "tilt", "tilt_cross", "stiffness_radial", "stiffness_axial",
                "stiffness_tilt", "preload", "preload_at_speed", "lift_off_axial_load",
                "unloaded_bearings", "reference_rating_life", "reference_rating_life_hours",
                "equivalent_load",
                "rating_life", "rating_life_hours", *SERVICE_KEYS)  # fmt: skip
NOTES = (
    "The pair: the loads applied to the shaft at the pair's centre (x along F_r, +axial the "
    "thrust of bearing 1) and the shaft's displacement there; a bearing: the forces its balls "
    "carry (F_r the size of its radial force) and its own displacement, from its zero-load "
    "position (the preload offset included), bearing 2 of DB and DF facing the other way.",
    "Pair model (docs/angular_contact.md): one rigid shaft, the bearings' centres B/2 either "
    "side of the pair's centre; preload F_p: the axial force each bearing of DB/DF carries with "
    "no external load; lift-off: the axial load alone at which the other bearing carries nothing.",
    "Pair lives: (L1^-e + L2^-e)^(-1/e), e = 10/9 (ISO/TS 16281 4.3's rule for the rings of a "
    "bearing; Lundberg-Palmgren system life); L10r from the ball loads, L10 from P = X F_r + Y "
    "F_a of each bearing (ISO 281 Table 3, single row).",
)
#: The note of a pair at --speed with --quasi-static.
SPEED_NOTE = (
    "Speed: --quasi-static: the pair is solved by the static model (the ball dynamics left "
    "out); the speed enters the lives only (hours, nu_1, the film)."
)
#: The note of a pair's sweep or table life at --speed with --quasi-static (the static model).
HOURS_NOTE = (
    "Speed: --quasi-static: the pair is solved by the static model (the ball dynamics left "
    "out); the speed gives the lives in hours only."
)
#: The end of the JSON's ``model`` of a pair solved by the static model at a speed (solve
#: --quasi-static; sweep).
STATIC_AT_SPEED = "; the static model at the speed given (the ball dynamics left out)"
#: The note of a pair with the ball dynamics at --speed (the model's name filled in).
DYNAMICS_NOTE = (
    "Speed: {} in both bearings (Jones 1960; Harris & Kotzalas; docs/speed.md): each ball has "
    "its own inner and outer contact angle and load (json: each bearing's "
    "contact_angles_inner, contact_angles_outer, ball_loads_inner, ball_loads_outer); the ball "
    "table shows the inner contacts; each bearing's L10r takes the inner loads for the inner "
    "ring, the outer loads for the outer ring; the preload F_p is ground in at rest (at the "
    "speed each bearing carries 'preload at the speed' with no external load); the lift-off is "
    "the one at rest (docs/speed.md)."
)


def _speed_note(c: PairCase, pair: dict[str, Any]) -> list[str]:
    """The note under the table of a pair at --speed: the ball dynamics (the result's
    ``model``) or the static model (--quasi-static); none without a speed."""
    dynamics = getattr(c.result, "model", None)
    if dynamics is not None:
        return [DYNAMICS_NOTE.format(dynamics)]
    return [SPEED_NOTE] if "speed" in pair else []


#: The JSON ``model`` of a pair (:func:`model_end` follows).
PAIR_MODEL = "pair of angular-contact ball bearings on one rigid shaft (ISO/TS 16281 each)"


def model_end(dynamics: str | None, speed: bool) -> str:
    """The end of a pair's JSON ``model``: the ball ``dynamics`` of both bearings (the result's
    ``model``), or the static model at a ``speed``; none without a speed."""
    if dynamics is not None:
        return f"; {dynamics} in both bearings"
    return STATIC_AT_SPEED if speed else ""


def pairs_document(
    records: Sequence[Any],
    rows: list[dict[str, Any]],
    varying: str,
    model: str,
    warnings: Sequence[str],
    steps: int | None = None,
    summary: dict[str, Any] | None = None,
) -> dict[str, Any]:
    """The JSON document of a pair solved row by row (a sweep's cage positions, table life's
    preloads; :func:`pair_records` of each in ``records``): the pair's inputs but the
    ``varying`` one, ``model``, ``steps``, ``rows``, ``summary`` (where given), ``units`` of
    every key (each bearing's too), ``warnings``."""
    head = {k: v for k, v in records[0][0].items() if k in PAIR_INPUTS and k != varying}
    keys = [*head, *rows[0], *(k for r in rows[0]["bearings"] for k in r)]
    doc = {**head, "model": model} | ({} if steps is None else {"steps": steps})
    doc |= {"rows": rows} | ({} if summary is None else {"summary": summary})
    matrix = {"stiffness_matrix": MATRIX_UNITS} if "stiffness_matrix" in keys else {}
    doc |= {"units": units(list(dict.fromkeys(keys)), 1.5) | matrix}
    return doc | {"warnings": list(warnings)}


def with_matrices(c: PairCase, row: dict[str, Any]) -> dict[str, Any]:
    """A json row of :func:`pairs_document` with the shaft's ``stiffness_matrix`` and each of
    its ``bearings``', as solve's json gives them (csv: :func:`csv_columns`, ``matrix``)."""
    bearings = [
        r | {"stiffness_matrix": b.result.stiffness_matrix.tolist()}
        for r, b in zip(row["bearings"], c.bearings, strict=True)
    ]
    return row | {"stiffness_matrix": c.result.stiffness_matrix.tolist(), "bearings": bearings}


#: The note of a pair's modified lives.
MODIFIED_NOTE = (
    "Pair modified lives: the same rule on the bearings' L_nm (L_nmr), an unloaded bearing "
    "dropping out; the system rule (ISO/TS 16281, Lundberg-Palmgren) holds for Weibull lives of "
    "one slope, so on the modified lives it is an approximation."
)


def pair_record(c: PairCase) -> dict[str, Any]:
    """The pair's values under their quantity keys."""
    r = c.result
    unloaded = [str(k + 1) for k in range(2) if r.unloaded[k]]
    first = combined_values(c.bearings[0])
    return {
        "bearing": first["bearing"], "arrangement": r.arrangement, "balls": first["balls"],
        "load": r.load, "axial_load": r.axial_load, "moment": r.moment,
        "moment_cross": r.moment_cross, "preload": r.preload, "width": r.width,
        "contact_angle": first.get("contact_angle"), "cage_angle": first["cage_angle"],
        "rotating": c.rotating, "x": r.x, "y": r.y, "axial": r.axial, "tilt": r.tilt,
        "tilt_cross": r.tilt_cross, "stiffness_radial": r.stiffness_radial,
        "stiffness_axial": r.stiffness_axial, "stiffness_tilt": r.stiffness_tilt,
        "lift_off_axial_load": r.lift_off_axial_load,
        "unloaded_bearings": ", ".join(unloaded) or "none",
        "reference_rating_life": c.reference_rating_life, "rating_life": c.rating_life,
    } | _at_speed(r)  # fmt: skip


def _at_speed(r: Any) -> dict[str, Any]:
    """``preload_at_speed`` of a DB/DF pair solved with the ball dynamics (none otherwise)."""
    thrust = getattr(r, "preload_at_speed", None)
    return {} if thrust is None else {"preload_at_speed": thrust}


def pair_records(
    c: PairCase, lives: PairLives | None = None
) -> tuple[dict[str, Any], list[dict[str, Any]]]:
    """The pair's values (with its service values) and each bearing's record, as every format
    of :func:`pair_report` and ``batch`` show them; ``lives``: the pair's and each bearing's
    service values as the plan gives them (:class:`bearingload.studies.bearing_pair.
    PairLives`)."""
    service = None if lives is None else lives.bearings
    pair = pair_record(c) | ({} if lives is None else lives.pair)
    # each bearing's record without its own matrix (the pair's is the shaft's: json, terminal)
    singles = [
        {k: v for k, v in combined_values(b).items() if k not in MATRIX_KEYS} for b in c.bearings
    ]
    records = with_service(singles, service)
    for k in range(2):
        if c.result.unloaded[k]:  # no loaded ball: no largest angle of one
            records[k]["contact_angle_max"] = None
    return pair, records


def pair_report(
    c: PairCase, fmt: str, *, per_ball: bool = False, show_geometry: bool = False,
    lives: PairLives | None = None,
) -> str:  # fmt: skip
    """Render a solved pair in ``fmt`` (table, csv, markdown, json); ``lives``: each bearing's
    service values, merged into its record as a single bearing's, and the pair's from them
    (its lives in hours, its modified lives), as the plan gives them
    (:class:`bearingload.studies.bearing_pair.PairLives`)."""
    pair, records = pair_records(c, lives)
    service = None if lives is None else lives.bearings
    if fmt == "json":
        return render([], "json", document=_document(c, pair, records, service))
    if fmt == "csv":
        return render([_csv_table(c, pair, records, per_ball)], "csv")
    tables = []
    if show_geometry:
        from bearingload.reports.bearing import geometry_table

        tables.append(geometry_table(c.bearing))
    heads = ["pair", "bearing 1", "bearing 2"]
    rows_of = [pair, *records]
    keys = [k for k in SUMMARY_KEYS if any(r.get(k) is not None for r in rows_of)]
    columns, rows = quantity_rows(keys, heads, rows_of, ANGULAR_LABELS)
    notes = [*NOTES, *_speed_note(c, pair), *material_note(c.bearing)]
    notes += [MODIFIED_NOTE] if any(k.startswith("modified_") for k in pair) else []
    from bearingload.reports.combined import matrix_table

    notes += [] if c.preload_class is None else [f"Preload: {c.preload_class.source}."]
    summary = Table(_title(pair, c.preload_class), columns, rows, notes + service_notes(service))
    shaft = c.result.stiffness_matrix
    tables += [
        summary,
        matrix_table(shaft, "tangent stiffness matrix of the shaft", "pair_stiffness_matrix"),
    ]
    tables += noted_once(
        [
            matrix_table(b.result.stiffness_matrix, f"tangent stiffness matrix of bearing {n}")
            for n, b in enumerate(c.bearings, start=1)
        ]
    )
    tables.append(_balls_table(c))
    return render(tables, fmt)


def pair_document(c: PairCase, lives: PairLives | None = None) -> dict[str, Any]:
    """The json document of a solved pair, before the json's rounding (``lives``: as in
    :func:`pair_report`)."""
    pair, records = pair_records(c, lives)
    return _document(c, pair, records, None if lives is None else lives.bearings)


def _title(p: dict[str, Any], setting: Preload | None = None) -> str:
    """The pair's title line; ``setting``: the preload class it was solved at (None: a force)."""
    who = f"Bearings {p['bearing']}, " if p["bearing"] != "given by hand" else ""
    preload = f"{p['preload']:.6g} N" if setting is None else setting.text
    return (
        f"{who}pair {p['arrangement']} ({ARRANGEMENT_NAMES[p['arrangement']]}), z = "
        f"{p['balls']} per bearing, contact angle {p['contact_angle']:.6g}°, F_r = "
        f"{p['load']:.6g} N, F_a = {p['axial_load']:.6g} N, preload {preload}, width "
        f"B = {p['width']:.6g} mm, cage angle {turn_angle(p['cage_angle'], 6):.6g}°, {p['rotating']} ring rotating"
    )


def _balls_table(c: PairCase) -> Table:
    columns = [column("ball"), Column("ball_angles", "angle", "°", 6)]
    for k in (1, 2):
        columns += [Column(f"a{k}", f"contact angle, bearing {k}", "°", 6),
                    Column(f"q{k}", f"load Q, bearing {k}", "N", 6)]  # fmt: skip
    b1, b2 = (b.result for b in c.bearings)
    rows = []
    for j in range(len(b1.ball_loads)):
        row: dict[str, Any] = {"ball": j + 1, "ball_angles": float(b1.ball_angles[j])}
        for k, b in ((1, b1), (2, b2)):
            q = float(b.ball_loads[j])
            row |= {f"a{k}": contact_angle_shown(float(b.contact_angles[j]), q), f"q{k}": q}
        rows.append(row)
    return Table("Ball loads of both bearings (ball 1 at the cage angle; angles from the load "
                 "line; contact angle '-': the ball carries no load)", columns, rows)  # fmt: skip


def _document(
    c: PairCase,
    pair: dict[str, Any],
    records: list[dict[str, Any]],
    service: Sequence[Any] | None = None,
) -> dict[str, Any]:
    from bearingload.reports.bearing import geometry_document
    from bearingload.reports.combined import bearings_document

    singles = bearings_document(list(c.bearings), records, service)
    # as the terminal prints them: the pair's and each bearing's labelled (each bearing's own
    # object lists its own unlabelled), then their lives'; each once
    said = printed_warnings(c.warnings, service)
    doc = pair | {
        "model": PAIR_MODEL + model_end(getattr(c.result, "model", None), "speed" in pair),
        "stiffness_matrix": c.result.stiffness_matrix.tolist(),
        "stiffness_matrix_symmetric": c.result.stiffness_matrix_symmetric.tolist(),
        "bearings": singles["cases"],
        "warnings": said,
    }
    keys = list(dict.fromkeys([*doc, *(k for s in singles["cases"] for k in s)]))
    return {
        "cases": [doc],
        "units": units(keys, 1.5) | MATRIX_UNITS_OF,
        "bearing": geometry_document(c.bearing),
        "warnings": said,
    }


def _csv_table(c: PairCase, pair: dict[str, Any], records: list[dict[str, Any]],
               per_ball: bool) -> Table:  # fmt: skip
    from bearingload.reports.combined import PER_BALL_KEYS

    service = tuple(k for k in PAIR_SERVICE if k in pair)
    own = [k for k in OWN_KEYS if any(k in r for r in records)]
    cols = csv_columns(service, own, matrix=not per_ball)
    if per_ball:
        cols += [column(k) for k in PER_BALL_KEYS]
    rows = csv_rows(c, pair, records, [col.key for col in cols], per_ball)
    return Table("pair", cols, rows)


#: The csv columns of the pair's inputs (every row).
CSV_INPUTS = tuple(k for k in PAIR_INPUTS
                   if k not in ("load", "axial_load", "moment", "moment_cross"))  # fmt: skip
#: The csv columns of the loads applied to the shaft.
CSV_APPLIED = tuple(f"pair_{k}" for k in ("load", "axial_load", "moment", "moment_cross"))


#: A radial load alone on one bearing's factors (k, K_Q): never a pair's bearing's (json keeps
#: them as a single bearing's keys, null; csv leaves their columns out).
RADIAL_KEYS = ("k", "K_Q")


def _own_keys() -> tuple[str, ...]:
    from bearingload.reports.combined import ANSWER_KEYS, INPUT_KEYS

    keys = dict.fromkeys(INPUT_KEYS + ANSWER_KEYS)
    return tuple(k for k in keys if k not in CSV_INPUTS and k not in RADIAL_KEYS)


#: A bearing's own csv columns (those of a single bearing's case but the pair's inputs), in
#: order; a table writes those its records have.
OWN_KEYS = _own_keys()


def csv_columns(service: Sequence[str], own: Sequence[str], matrix: bool = False) -> list[Column]:
    """The csv columns of a pair: its inputs, the loads on the shaft, its answers and the
    ``service`` values of :data:`PAIR_SERVICE` as ``pair_...``, ``bearing_number``, then each
    bearing's ``own`` keys (a single bearing's); ``matrix``: the shaft's stiffness matrix after
    the pair's answers (``pair_stiffness_matrix_11`` ...), each bearing's after its own keys (as
    solve's json gives them). ``batch`` writes these for a file of pairs."""
    matrices = MATRIX_KEYS if matrix else ()
    answers = [f"pair_{k}" for k in (*PAIR_ANSWERS, *service, *matrices)]
    cols = [column(k, 1.5) for k in CSV_INPUTS]  # ball bearings: N/mm^1.5, as one bearing's
    cols += [_pair_column(k) for k in (*CSV_APPLIED, *answers)] + [column("bearing_number")]
    return cols + [column(k, 1.5) for k in (*own, *matrices)]


def csv_rows(c: PairCase, pair: dict[str, Any], records: list[dict[str, Any]],
             keys: Sequence[str], per_ball: bool = False) -> list[dict[str, Any]]:  # fmt: skip
    """The csv rows of a pair under ``keys`` (:func:`csv_columns`, with the per-ball keys when
    ``per_ball``): one per bearing (``per_ball``: per ball of each bearing), '' where none."""
    rows = []
    if MATRIX_KEYS[0] in keys:  # the matrices of csv_columns(matrix=True)
        pair = pair | _matrix_entries(c.result)
        records = [r | _matrix_entries(b.result) for r, b in zip(records, c.bearings, strict=True)]
    for n, (b, rec) in enumerate(zip(c.bearings, records, strict=True), start=1):
        base = {k: pair.get(k[5:]) if k.startswith("pair_") else rec.get(k) for k in keys}
        base |= {k: pair.get(k) for k in CSV_INPUTS} | {"bearing_number": n}
        if per_ball:
            rows += [base | {"ball": j + 1} | ball for j, ball in enumerate(ball_values(b))]
        else:
            rows.append(base)
    return [blank(r, keys) for r in rows]


def _matrix_entries(result: Any) -> dict[str, float]:
    """The 25 entries of a result's ``stiffness_matrix`` under :data:`MATRIX_KEYS`."""
    return {k: float(v[0]) for k, v in matrix_columns(result).items()}


def _pair_column(key: str) -> Column:
    """The csv column of the pair's value of a quantity (``pair_x``)."""
    col = column(key[5:])
    return dataclasses.replace(col, key=key, header=f"pair: {col.header}")


def pairs_csv(title: str, cases: Sequence[PairCase], records: list[Any]) -> Table:
    """solve's csv of each pair of ``cases`` (:func:`pair_records` of each in ``records``), one
    table: the rows of a pair's sweep (cage positions) and table life (preloads)."""
    own = [k for k in OWN_KEYS if any(k in r for _, rs in records for r in rs)]
    cols = csv_columns(tuple(k for k in PAIR_SERVICE if k in records[0][0]), own, matrix=True)
    keys = [c.key for c in cols]
    rows = []
    for c, (pair, recs) in zip(cases, records, strict=True):
        rows += csv_rows(c, pair, recs, keys)
    return Table(title, cols, rows)
