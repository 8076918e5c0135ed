"""The report of ``bearingload solve``: one or more solved cases in every format.

Cases come from :mod:`bearingload.studies.loaded_bearing` (one per model and per clearance);
every quantity is named through :mod:`bearingload.reports.quantities`. The formats are those
docs/guide.md describes (csv: one row per case, or per ball; json: ``cases``, ``units``,
``warnings`` and, for a catalogue bearing, ``bearing``).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from typing import Any

from bearingload.bearings.mounting import RESULT_KEYS, mounting_notes
from bearingload.reports.quantities import (
    MATRIX_UNITS,
    QUANTITIES,
    SERVICE_KEYS,
    column,
    element_words,
    for_elements,
    units,
)
from bearingload.reports.render import Column, Table, render
from bearingload.studies.loaded_bearing import (
    LoadedCase,
    case_values,
    collect_warnings,
    with_relative_errors,
)
from bearingload.studies.matrix import MATRIX_KEYS
from bearingload.units import turn_angle

#: Inputs of a case (the csv columns that say which case a row is).
INPUT_KEYS = (
    "bearing",
    "method",
    "balls",
    "load",
    "stiffness",
    "clearance",
    "clearance_pick",
    "cage_angle",
    "exponent",
    "rotating",
)
#: The answer, in the order the terminal shows it.
ANSWER_KEYS = (
    "q_max",
    "k",
    "K_Q",
    "loaded_balls",
    "load_zone",
    "x",
    "y",
    "stiffness_radial",
    "approach_max",
    "epsilon",
    "p_max_inner",
    "p_max_outer",
    "static_safety",
    "rating_life",
    "reference_rating_life",
    "revolutions",
    "allowable_load",
    "relative_error",
)
#: The answer of solve's own report: :data:`ANSWER_KEYS` (batch's columns too) with the lives of
#: :func:`bearingload.bearings.service_life.service_values` (C_0, hours, a_ISO, film) beside them.
REPORT_KEYS = (
    *RESULT_KEYS,  # a mounted bearing's operating clearance and its reductions
    *ANSWER_KEYS[: ANSWER_KEYS.index("static_safety") + 1],
    "static_rating",
    "rating_life",
    "rating_life_hours",
    "reference_rating_life",
    "reference_rating_life_hours",
    *SERVICE_KEYS,
    *ANSWER_KEYS[ANSWER_KEYS.index("revolutions") :],
)
PER_BALL_KEYS = ("ball", "ball_angles", "ball_approaches", "ball_loads")


def solve_report(
    cases: Sequence[LoadedCase],
    fmt: str,
    *,
    per_ball: bool = False,
    show_geometry: bool = False,
    service: Sequence[Any] | None = None,
) -> str:
    """Render solved cases in ``fmt`` (table, csv, markdown, json); ``service`` the lives of
    each case (:class:`bearingload.bearings.service_life.ServiceLife`), merged into its record
    and its notes into the summary's."""
    records = _records(cases, service)
    exponent = float(cases[0].result.case.exponent)
    if fmt == "json":
        return render([], "json", document=_document(cases, records, exponent, service))
    if fmt == "csv":
        table = _per_ball_table(cases, records) if per_ball else _case_table(records)
        return render([table], "csv")
    tables = []
    if show_geometry and cases[0].bearing is not None:
        from bearingload.reports.bearing import geometry_table

        tables.append(geometry_table(cases[0].bearing))
    tables.append(_summary(cases, records, service_notes(service)))
    if per_ball or any(c.result.method == "exact" for c in cases):
        tables.append(_balls_human(cases, records))
    return render([for_elements(t, exponent) for t in tables], fmt)  # rollers: 'roller loads'


def _records(cases: Sequence[LoadedCase], service: Sequence[Any] | None) -> list[dict[str, Any]]:
    """Each case's record with its service values; beside the exact model, every other
    method's relative errors."""
    records = with_service([case_values(c) for c in cases], service)
    if len({r["method"] for r in records}) > 1 and any(r["method"] == "exact" for r in records):
        records = with_relative_errors(records)
    return records


def solve_document(
    cases: Sequence[LoadedCase], service: Sequence[Any] | None = None
) -> dict[str, Any]:
    """The json document of solved radial cases (``cases``, ``units``, ``warnings``, and the
    ``bearing`` of a catalogue bearing), before the json's rounding."""
    exponent = float(cases[0].result.case.exponent)
    return _document(cases, _records(cases, service), exponent, service)


def present(records: Sequence[dict[str, Any]], keys: Sequence[str]) -> list[str]:
    """The ``keys`` some record has a value of (not None), as the human summary shows them."""
    return [k for k in keys if any(r.get(k) is not None for r in records)]


def given_keys(records: Sequence[dict[str, Any]], keys: Sequence[str]) -> list[str]:
    """The ``keys`` the records carry (a value or None, as the JSON document carries them)."""
    return [k for k in keys if any(k in r for r in records)]


def _case_table(records: Sequence[dict[str, Any]]) -> Table:
    keys = given_keys(records, INPUT_KEYS + REPORT_KEYS + ("valid",) + MATRIX_KEYS)
    exponent = records[0]["exponent"]
    return Table("cases", [column(k, exponent) for k in keys], [blank(r, keys) for r in records])


def blank(record: dict[str, Any], keys: Sequence[str] | None = None) -> dict[str, Any]:
    """A csv row of ``record`` under ``keys`` (default its own): None as an empty cell."""
    return {
        k: "" if record.get(k) is None else record[k] for k in (record if keys is None else keys)
    }


def _per_ball_table(cases: Sequence[LoadedCase], records: Sequence[dict[str, Any]]) -> Table:
    per = [[dict(zip(PER_BALL_KEYS[1:], ball, strict=True)) for ball in _balls(c)] for c in cases]
    inputs = given_keys(records, INPUT_KEYS)
    return per_ball_table(records, inputs, per, PER_BALL_KEYS, records[0]["exponent"])


def per_ball_table(
    records: Sequence[dict[str, Any]],
    inputs: Sequence[str],
    per: Sequence[Sequence[dict[str, Any]]],
    keys: Sequence[str],
    exponent: float,
) -> Table:
    """The csv of solved cases with ``per_ball``: a row per ball (``per``: each case's balls'
    values), each with its case's ``inputs`` (of its record) and its number, ``ball``."""
    rows = [
        blank(r, inputs) | {"ball": i + 1} | ball
        for r, balls in zip(records, per, strict=True)
        for i, ball in enumerate(balls)
    ]
    return Table("balls", [column(k, exponent) for k in (*inputs, *keys)], rows)


def _balls(c: LoadedCase) -> list[tuple[float, float, float]]:
    """(angle [°], approach [mm], load [N]) of every ball; the exact model only."""
    model = c.result.model
    if c.result.method != "exact":
        return []
    return list(
        zip(
            model.ball_angles.tolist(),
            model.ball_approaches.tolist(),
            model.ball_loads.tolist(),
            strict=True,
        )
    )


def _heading(r: dict[str, Any]) -> str:
    """A short name of one case among several: its method and/or clearance pick."""
    parts = []
    if r["clearance_pick"] is not None:
        parts.append(f"G_r {r['clearance_pick']}")
    if r["method"] != "exact" or not parts:
        parts.insert(0, r["method"])
    return ", ".join(parts)


def _summary(
    cases: Sequence[LoadedCase],
    records: Sequence[dict[str, Any]],
    extra_notes: Sequence[str] = (),
) -> Table:
    keys = present(records, REPORT_KEYS)
    if len({r["clearance"] for r in records}) > 1:
        keys.insert(0, "clearance")
    matrix = present(records, MATRIX_KEYS)  # (the radial engine's 2x2 block, after k_r)
    at = keys.index("stiffness_radial") + 1 if "stiffness_radial" in keys else len(keys)
    keys[at:at] = matrix
    heads = ["value"] if len(records) == 1 else [_heading(r) for r in records]
    columns, rows = quantity_rows(keys, heads, records)
    notes = _notes(cases, records) + [RADIAL_MATRIX_NOTE] * bool(matrix) + list(extra_notes)
    return Table(_title(cases, records), columns, rows, notes)


def with_service(
    records: list[dict[str, Any]], service: Sequence[Any] | None
) -> list[dict[str, Any]]:
    """The records with each case's service lives merged in."""
    if not service:
        return records
    return [r | s.values for r, s in zip(records, service, strict=True)]


def case_warnings(found: Sequence[Sequence[str]], service: Sequence[Any] | None) -> list[list[str]]:
    """Each case's warnings ``found`` followed by those of its service lives (a kappa outside
    ISO 281's range ...), each once: json's ``warnings`` of the case, as the terminal prints them."""
    lives = [[]] * len(found) if not service else [list(s.warnings) for s in service]
    return [list(dict.fromkeys([*f, *w])) for f, w in zip(found, lives, strict=True)]


def printed_warnings(found: Sequence[str], service: Sequence[Any] | None) -> list[str]:
    """The warnings of several cases as the terminal prints them and json's document lists them:
    ``found`` (the cases' own, labelled where there are several), then their lives', each once."""
    return list(dict.fromkeys([*found, *(w for s in service or [] for w in s.warnings)]))


def service_notes(service: Sequence[Any] | None) -> list[str]:
    """The notes of the service lives of several cases, each once."""
    return list(dict.fromkeys(n for s in service or [] for n in s.notes))


def quantity_rows(
    keys: Sequence[str], heads: Sequence[str], records: Sequence[dict[str, Any]],
    labels: dict[str, str] | None = None,
) -> tuple[list[Column], list[dict[str, Any]]]:  # fmt: skip
    """quantity | one column per case | unit: each quantity in its display unit, and again in
    its second unit where it has one (Q_max in kgf); '-' where a case does not give it;
    ``labels`` replaces the label of a key (the angular-contact axial origin)."""
    rows = []
    for key in keys:
        q = QUANTITIES[key]
        label = (labels or {}).get(key, q.label)
        for unit, factor in [q.shown()] + ([q.also] if q.also else []):
            row: dict[str, Any] = {"quantity": label, "unit": unit or ""}
            for h, r in zip(heads, records, strict=True):
                v = r.get(key)
                row[h] = "-" if v is None else (v * factor if q.digits else v)
            rows.append(row)
    columns = [Column("quantity", "quantity", align="left")]
    columns += [Column(h, h, digits=6) for h in heads]
    columns.append(Column("unit", "unit", align="left"))
    return columns, rows


def _title(cases: Sequence[LoadedCase], records: Sequence[dict[str, Any]]) -> str:
    r, c = records[0], cases[0]
    m = r["exponent"]
    who = f"Bearing {r['bearing']}, " if r["bearing"] and r["bearing"] != "given by hand" else ""
    clear = (
        f"G_r = {r['clearance'] * 1e3:.6g} µm (gap per side {r['clearance'] * 500:.6g} µm)"
        if len(records) == 1 or len({x["clearance"] for x in records}) == 1
        else f"G_r: {c.bearing.clearance_class if c.bearing else ''} range"
    )
    return (
        f"{who}z = {r['balls']}, F_r = {r['load']:.6g} N ({r['load'] / 9.80665:.6g} kgf), "
        f"K = {r['stiffness']:.6g} N/mm^{m:g}, {clear}, cage angle {turn_angle(r['cage_angle'], 6):.6g}°, "
        f"m = {m:.6g}"
    )


def _notes(cases: Sequence[LoadedCase], records: Sequence[dict[str, Any]]) -> list[str]:
    from bearingload.models.registry import METHODS

    notes = []
    methods = list(dict.fromkeys(r["method"] for r in records))
    if methods != ["exact"]:
        for name in methods:
            m = METHODS[name]
            ignored = ", ".join(i.replace("_", " ") for i in m.ignores) or "nothing"
            notes.append(f"{name}: {m.title}; ignores {ignored}.")
    for r in records:
        if r["valid"] is False:
            notes.append(
                f"Warning: {_heading(r)}: the case is outside the {r['method']} model's range "
                f"({METHODS[r['method']].validity})."
            )
    if "relative_error" in records[0]:
        notes.append(
            element_words(
                "Q_max/Q_max,exact - 1: the heaviest ball load against the exact model.",
                records[0]["exponent"],
            )
        )
    rotating = next((r["rotating"] for r in records if r["rotating"] is not None), None)
    if rotating is not None:
        notes.append(
            f"L10r: ISO/TS 16281:2008, 4.3, from the exact ball loads at the contact angle 0 "
            f"(Q_ci, Q_ce from C; {rotating} ring rotating: cubic mean on it, exponent 10/3 on "
            "the stationary one; --rotating)."
        )
    b = cases[0].bearing
    if b is not None and b.kind == "roller":
        notes.append(
            "Cylindrical roller bearing: line contact, m = 10/9 (Palmgren); "
            "life L10 = (C/F_r)^(10/3) and allowable load C/L^(3/10) (ISO 281, p = 10/3)."
        )
    if b is not None:
        notes += set_note(b) + mounting_notes(b)
        src = next((p.source for p in b.provenance if p.key == "clearance"), "")
        notes.append(f"G_r: {src}.")
        notes.append("--show-geometry lists the geometry used and the source of every value.")
    return notes


def set_note(b: Any) -> list[str]:
    """Where a catalogue bearing's ball (or roller) set comes from, in one line; and the balls'
    material where one was given (a hybrid bearing)."""
    return material_note(b) + _set_note(b)


def material_note(b: Any) -> list[str]:
    """The balls' material of ``b`` in one line, where --ball-material gave one."""
    if getattr(b, "ball_material", None) is None:
        return []
    values = {p.key: p.value for p in b.provenance}
    if "ball_modulus" not in values:
        return []
    return [
        f"Balls: {values['ball_material']} (E = {values['ball_modulus']:.6g} MPa, nu = "
        f"{values['ball_poisson']:.6g}, rho = {values['ball_material_density']:.6g} kg/m^3) on "
        f"rings of E = {values['modulus']:.6g} MPa, nu = {values['poisson']:.6g}: contact "
        f"modulus E* = {values['contact_modulus']:.6g} MPa (--ball-material)."
    ]


def _set_note(b: Any) -> list[str]:
    g = b.geometry
    if b.kind == "roller":
        z = next(p.source for p in b.provenance if p.key == "balls")
        return [f"Rollers: D_w and d_m exact (SKF raceway diameters); z {z.split(': ')[-1]}."]
    if g is None or g.maker is None:
        return []
    how = f"{g.method}" + (f", {g.confidence} confidence" if g.method == "derived" else "")
    others = [m for m in g.makers if m != g.maker]
    more = f"; other makers' sets: --maker {' | '.join(others)}" if others else ""
    if g.only_maker:
        more = f"; the only maker with a ball set for {g.designation} in the catalogue"
    return [f"Ball set: {g.maker} ({how}){more}."]


def _balls_human(cases: Sequence[LoadedCase], records: Sequence[dict[str, Any]]) -> Table:
    exact = [(c, r) for c, r in zip(cases, records, strict=True) if c.result.method == "exact"]
    per = [[{"angle": a, "approach": d * 1e3, "q": q} for a, d, q in _balls(c)] for c, _ in exact]
    return balls_table(per, [_heading(r) for _, r in exact])


#: The columns of :func:`balls_table`: key -> (header of one case, of several, unit).
BALL_COLUMNS = {
    "alpha": ("contact angle", "contact angle", "°"),
    "approach": ("approach delta (< 0: gap)", "", "µm"),
    "q": ("load Q", "Q", "N"),
}


def balls_table(
    per: Sequence[Sequence[dict[str, Any]]], heads: Sequence[str], notes: Sequence[str] = ()
) -> Table:
    """The human table of every ball of solved cases, ``per`` each case's balls (``angle`` [°]
    and the keys of :data:`BALL_COLUMNS`, as shown): one case all of them, several (headed by
    ``heads``) their contact angles and loads side by side."""
    one = len(per) == 1
    keys = [k for k in BALL_COLUMNS if k in per[0][0] and (one or BALL_COLUMNS[k][1])]
    columns = [column("ball"), Column("ball_angles", "angle", "°", 6)]
    for k in keys:
        header, several, unit = BALL_COLUMNS[k]
        if one:
            columns.append(Column(k, header, unit, 6))
        else:
            columns += [
                Column(f"{k}{i}", f"{several} at {h}", unit, 6) for i, h in enumerate(heads)
            ]
    rows = []
    for j, ball in enumerate(per[0]):
        side = ball if one else {f"{k}{i}": b[j][k] for k in keys for i, b in enumerate(per)}
        rows.append({"ball": j + 1, "ball_angles": ball["angle"]} | side)
    title = "Ball loads (ball 1 at the cage angle; angles from the load line)"
    return Table(title, columns, rows, notes)


#: The note under the radial engine's summary, of the stiffness matrix entries it lists.
RADIAL_MATRIX_NOTE = (
    "stiffness dF_x/d(x) ... dF_y/d(y): the entries of the tangent stiffness matrix the radial "
    "engine determines (it holds the ring axially and untilted; deep-groove ball bearings "
    "solved with a load option, -A 0 too, give all 25); json: stiffness_matrix, csv: "
    "stiffness_matrix_11 ... _55."
)


def noted_once(tables: list[Table]) -> list[Table]:
    """Tables of one kind in a row (a matrix per case) with their shared note under the last
    only."""
    return [dataclasses.replace(t, notes=[]) for t in tables[:-1]] + tables[-1:]


def _matrix_units(keys: Sequence[str]) -> dict[str, str]:
    """The ``units`` of the 5x5 ``stiffness_matrix`` where the document has one."""
    return {"stiffness_matrix": MATRIX_UNITS} if "stiffness_matrix" in keys else {}


def _document(
    cases: Sequence[LoadedCase],
    records: Sequence[dict[str, Any]],
    exponent: float,
    service: Sequence[Any] | None = None,
) -> dict[str, Any]:
    from bearingload.models.registry import METHODS

    said = case_warnings([c.warnings for c in cases], service)
    docs: list[dict[str, Any]] = []
    for c, r in zip(cases, records, strict=True):
        doc = {k: v for k, v in r.items() if k not in MATRIX_KEYS}  # json: the matrix whole
        doc["model"] = METHODS[r["method"]].title
        doc["ignores"] = list(METHODS[r["method"]].ignores)
        if c.result.method == "exact":
            model = c.result.model
            from bearingload.studies.matrix import radial_matrix

            doc["stiffness_matrix"] = radial_matrix(model.stiffness_matrix)
            doc["ball_angles"] = model.ball_angles
            doc["ball_approaches"] = model.ball_approaches
            doc["ball_loads"] = model.ball_loads
        doc["warnings"] = said[len(docs)]
        docs.append(doc)
    keys = list(dict.fromkeys(k for d in docs for k in d))
    out: dict[str, Any] = {
        "cases": docs,
        "units": units(keys, exponent) | _matrix_units(keys),
        "warnings": printed_warnings(collect_warnings(cases), service),
    }
    if cases[0].bearing is not None:
        from bearingload.reports.bearing import geometry_document

        out["bearing"] = geometry_document(cases[0].bearing)
    return out
