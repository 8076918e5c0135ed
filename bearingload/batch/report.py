"""The report of ``bearingload batch``: ``row`` (the input file's row, header = 1), then the
columns ``solve --format csv`` writes for one case (with a combined-load column, those it
writes with an axial load), fixed by the header (:data:`NEEDS`) so that every chunk of a long
file has the same columns.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from bearingload.batch.read import BEARING_COLUMNS, Header, row_message
from bearingload.bearings.mounting import MOUNTING_PARAMS, RESULT_KEYS
from bearingload.bearings.oil import OIL_INPUTS
from bearingload.errors import BearingloadError
from bearingload.reports.combined import ANSWER_KEYS as COMBINED_ANSWERS
from bearingload.reports.combined import CONTACT_KEYS, contact_values
from bearingload.reports.combined import INPUT_KEYS as COMBINED_INPUTS
from bearingload.reports.quantities import units
from bearingload.reports.render import Column, Table, csv_block, render
from bearingload.reports.solve import INPUT_KEYS, REPORT_KEYS, column, printed_warnings
from bearingload.studies.matrix import MATRIX_KEYS

#: The most rows json, markdown and table hold in memory (csv is streamed without a limit).
MAX_HELD_ROWS = 100_000
#: The output columns of a combined-load file: solve's csv with an axial load (the contact
#: angle, an input, after the misalignment), then the 5x5 tangent stiffness matrix.
_INPUTS = [k for k in COMBINED_INPUTS if k != "contact_angle"]
_INPUTS.insert(_INPUTS.index("misalignment") + 1, "contact_angle")
COMBINED_KEYS = (*_INPUTS, *(k for k in COMBINED_ANSWERS if k not in _INPUTS), *MATRIX_KEYS)
#: The radial output columns: solve's, with the ball dynamics' density after the speed.
_RADIAL = [k for k in REPORT_KEYS if k != "relative_error"]
_RADIAL.insert(_RADIAL.index("speed") + 1, "ball_density")
RADIAL_KEYS = (*INPUT_KEYS, *_RADIAL, "valid", *MATRIX_KEYS)
_VISCOSITY = ("viscosity", *OIL_INPUTS)  # the oil gives the viscosity
_LIFE = (BEARING_COLUMNS,)  # the lives are a bearing's
_BY_SPEED = (
    "speed preload_at_speed ball_density cage_frequency ball_pass_frequency_outer "
    "ball_pass_frequency_inner ball_spin_frequency rating_life_hours reference_rating_life_hours"
).split()
_BY_VISCOSITY = (
    "viscosity rated_viscosity kappa contamination_factor fatigue_load_limit a_iso "
    "modified_rating_life modified_rating_life_hours reference_equivalent_load a_iso_reference "
    "modified_reference_rating_life modified_reference_rating_life_hours film_thickness"
).split()
_BEARING_ONLY = (
    "bearing clearance_pick p_max_inner p_max_outer static_safety static_rating rating_life "
    "reference_rating_life revolutions rotating allowable_load"
).split()
#: The output columns written only where the header gives, of each group of input columns of
#: theirs, one (as solve prints a quantity only where its option is given): a bearing's, the
#: mounting's results, the lives each operating input makes meaningful (the modified lives need
#: the viscosity, or an oil; the film ratio the roughness too), the inputs solve echoes if given.
NEEDS: dict[str, tuple[Sequence[str], ...]] = {
    **dict.fromkeys(_BEARING_ONLY, _LIFE),
    **dict.fromkeys(RESULT_KEYS, (MOUNTING_PARAMS,)),
    **dict.fromkeys(_BY_SPEED, (*_LIFE, ("speed",))),
    **dict.fromkeys(("reliability", "reliability_factor"), (*_LIFE, ("reliability",))),
    **dict.fromkeys(_BY_VISCOSITY, (*_LIFE, _VISCOSITY)),
    **dict.fromkeys(("roughness", "film_ratio"), (*_LIFE, _VISCOSITY, ("roughness",))),
    **{k: ((k,),) for k in ("moment_cross", "contact_angle")},
    "epsilon": (("method",),),
}
#: What json adds to a row of the combined engine, as solve's json names it: the model and each
#: ball's inner and outer contact angle [°] and load [N] (null for a radial row).
HELD_KEYS = ("model", *CONTACT_KEYS)
#: The note of a table or markdown report with rows solved with the ball dynamics.
DYNAMICS_NOTE = (
    "Rows with a speed (quasi_static not true) on the combined engine: {} (Jones 1960; Harris & "
    "Kotzalas; docs/speed.md); every ball has its own inner and outer contact angle and load "
    "(json: contact_angles_inner, contact_angles_outer, ball_loads_inner, ball_loads_outer); the "
    "columns give the inner contacts; L10r takes the inner loads for the inner ring, the outer "
    "loads for the outer ring."
)
#: The note of a file of pairs with rows at speed: what the pair's columns give there.
PAIR_AT_SPEED_NOTE = (
    "Pairs at a speed: preload the preload ground in at rest, pair_preload_at_speed each "
    "bearing's thrust with no external load at the speed (ball dynamics), "
    "pair_lift_off_axial_load the lift-off at rest (docs/speed.md); rows with quasi_static true: "
    "the static pair, the speed giving the lives in hours only."
)
#: The last csv column: why a row was skipped (json: ``skipped``; table, markdown: the notes).
SKIPPED = Column("skipped", "skipped: the reason", "", None, "left")


def batch_columns(header: Header) -> list[Column]:
    """The output columns for a file with ``header`` (its oil columns, as given, before the
    operating viscosity they give)."""
    written = {k for k, needs in NEEDS.items() if all(set(header.names) & set(g) for g in needs)}
    keys: Sequence[str] = COMBINED_KEYS if header.combined else RADIAL_KEYS
    keys = [k for k in keys if k not in NEEDS or k in written]
    # rows of roller bearings (m = 10/9) or an exponent column mix exponents: N/mm^m then
    mixed = not header.combined and ("exponent" in header.names or header.has_bearing)
    columns = [column(k, None if mixed else 1.5) for k in ("row", *keys)]
    columns = pair_columns(written) if header.pairs else columns
    oil = [column(k) for k in OIL_INPUTS if k in header.names]
    at = next((i for i, c in enumerate(columns) if c.key == "viscosity"), len(columns))
    return columns[:at] + oil + columns[at:]


def pair_columns(written: set[str] | None) -> list[Column]:
    """The output columns of a file of pairs: ``row``, then those ``solve 7205BDB --format
    csv`` writes, of :data:`NEEDS` those in ``written`` (None: every one), the pair's as
    ``pair_...`` (its cross moment ``pair_moment_cross``; a bearing has no ``moment_cross``, a
    pair no mounting)."""
    from bearingload.reports.pair import OWN_KEYS, PAIR_SERVICE, csv_columns

    kept = [
        k for k in (*PAIR_SERVICE, *OWN_KEYS) if written is None or k in written or k not in NEEDS
    ]
    own = [k for k in OWN_KEYS if k in kept and k not in ("moment_cross", *RESULT_KEYS)]
    return [column("row"), *csv_columns([k for k in PAIR_SERVICE if k in kept], own, True)]


def pair_rows(
    header: Any, many: Any, numbers: list[int], cols: dict[str, list[Any]], errors: dict[int, str]
) -> tuple[list[int], dict[str, list[Any]]]:
    """The output rows of the pairs solved by the plan (:mod:`bearingload.plan.many_pairs`):
    solve's csv rows of each (:func:`bearingload.reports.pair.csv_rows`, one per bearing, its
    row number twice) with the row's oil cells, ``warnings`` (the pair's, its speed's and its
    lives') on the first, each bearing's model and contacts (:data:`HELD_KEYS`). A pair whose
    records solve would refuse is a skipped row with its reason (in ``errors``)."""
    from bearingload.reports.pair import csv_rows, pair_records

    keys = [c.key for c in pair_columns(None) if c.key != "row"]
    oil = [k for k in OIL_INPUTS if k in header.names]  # written as given (nu is the oil's)
    rows: list[int] = []
    values: dict[str, list[Any]] = {k: [] for k in [*keys, *oil, "warnings"]}
    solved = many.values.get("pair", []), many.values.get("lives", [])
    for i, pc, lives in zip(many.rows, *solved, strict=True):
        try:
            pair, records = pair_records(pc, lives)
        except BearingloadError as exc:
            errors[numbers[i]] = row_message(exc)
            continue
        warned = tuple(printed_warnings(pc.warnings, lives.bearings))
        for j, row in enumerate(csv_rows(pc, pair, records, keys)):
            rows.append(numbers[i])
            row |= {k: cols[k][i] for k in oil} | {"warnings": () if j else warned}
            row |= contact_values(pc.bearings[j].result, pc.bearing.contact_angle)
            for k, v in row.items():
                values.setdefault(k, []).append(v)
    return rows, values


def csv_chunk(columns: Sequence[Column], part: Any) -> str:
    """The csv lines of a chunk (:class:`~bearingload.batch.solve.Chunk`) in row order
    (``columns`` ending with :data:`SKIPPED`): each solved row, and each skipped row with its
    number and its reason, its other cells blank."""
    rows, values, skipped = part.rows, part.values, part.errors
    data: dict[str, Any] = {"row": rows} | row_values(columns, len(rows), values)
    if skipped or list(rows) != sorted(rows):  # in row order, a skipped row blank but its reason
        blank: dict[str, list[Any]] = {"row": [r for r, _ in skipped]}
        blank["skipped"], none = [m for _, m in skipped], [None] * len(skipped)
        order = sorted(range(len(rows) + len(skipped)), key=[*rows, *blank["row"]].__getitem__)
        for k, v in data.items():
            cells = [*(v.tolist() if hasattr(v, "tolist") else v), *blank.get(k, none)]
            data[k] = [cells[i] for i in order]
    return csv_block(columns, data)


def row_values(columns: Sequence[Column], n: int, values: dict[str, Any]) -> dict[str, Any]:
    """The values of ``columns`` but the row number, blank (None) where the rows have none."""
    return {c.key: values.get(c.key, [None] * n) for c in columns if c.key != "row"}


class Held:
    """The solved rows of a file that json, markdown and table hold (at most
    :data:`MAX_HELD_ROWS`), with :data:`HELD_KEYS` for a file of combined loads, of pairs, or
    of bearings with a speed column (whose ball bearings at speed have the ball dynamics)."""

    def __init__(self, header: Header, columns: list[Column]) -> None:
        at_speed = "speed" in header.names and header.has_bearing  # ball bearings: dynamics
        self.columns = columns
        self.extra = HELD_KEYS if header.combined or header.pairs or at_speed else ()
        self.rows: list[int] = []
        self.values: dict[str, list[Any]] = {c.key: [] for c in columns if c.key != "row"}

    def add(self, part: Any) -> bool:
        """Hold a chunk's solved rows: each column's, the warnings, json's model and per-ball
        contacts (as solve's json); False beyond :data:`MAX_HELD_ROWS` rows."""
        self.rows += part.rows
        n = len(part.rows)
        values = row_values(self.columns, n, part.values)
        values["warnings"] = part.values.get("warnings", [()] * n)
        values |= {k: part.values.get(k, [None] * n) for k in self.extra}
        for k, v in values.items():
            self.values.setdefault(k, []).extend(v.tolist() if hasattr(v, "tolist") else v)
        return len(self.rows) <= MAX_HELD_ROWS

    def report(self, skipped: Sequence[tuple[int, str]], fmt: str) -> str:
        """The whole report in ``fmt`` (json, markdown, table) from every solved row."""
        keys, values = [c.key for c in self.columns], self.values
        data = {"row": self.rows} | values
        records = [dict(zip(keys, r, strict=True)) for r in zip(*map(data.get, keys), strict=True)]
        held = [k for k in HELD_KEYS if k in values]
        if fmt == "json":
            for i, record in enumerate(records):
                record |= {k: values[k][i] for k in held}
                record["warnings"] = list(values["warnings"][i])
            doc = {
                "cases": records,
                "skipped": [{"row": r, "reason": m} for r, m in skipped],
                "units": {c.key: c.unit for c in self.columns if c.unit} | units(held, 1.5),
            }
            return render([], "json", document=doc)
        rows = [
            {k: "" if v is None else str(v) if isinstance(v, bool) else v for k, v in r.items()}
            for r in records
        ]
        short = [Column(c.key, c.key, c.unit, c.digits, c.align) for c in self.columns]
        dynamics = [m for m in values.get("model", []) if m is not None and "; ball dynamics" in m]
        models = sorted(set(dynamics))  # not the radial engine's model, which has a '; ' too
        notes = [DYNAMICS_NOTE.format(m.split("; ", 1)[1]) for m in models]
        if models and "pair_lift_off_axial_load" in keys:  # pairs at speed: what is at rest
            notes.append(PAIR_AT_SPEED_NOTE)
        notes += [f"Row {r} skipped: {m}" for r, m in skipped]
        title = f"{len(records)} cases (row: the input file's row, the header is row 1)"
        return render([Table(title, short, rows, notes)], fmt)
