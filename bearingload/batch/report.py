"""The report of ``bearingload batch``: one row per solved case, the columns of ``solve``.

The columns are ``row`` (the input file's row, header = 1) and then those ``bearingload solve
--format csv`` writes for one case (:data:`bearingload.reports.solve.INPUT_KEYS` and
``ANSWER_KEYS``; headers through
:mod:`bearingload.reports.quantities`). They are fixed by the file's header, so that every
chunk of a long file has the same columns: the bearing columns (``bearing``,
``clearance_pick``, contact pressures, static safety, lives, ``rotating``) only when the file can name a bearing or a ball
geometry, ``epsilon`` only with a ``method`` column. A file with a combined-load column
(``axial_load``, ``moment``, ``moment_cross``, ``misalignment``, ``tilt_radius``) has the columns
``solve`` writes with an axial load; its rows without a load cell, solved by the radial engine,
fill the columns the two engines share.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from bearingload.batch.read import Header
from bearingload.bearings.mounting import MOUNTING_PARAMS, RESULT_KEYS
from bearingload.bearings.oil import OIL_INPUTS
from bearingload.reports.quantities import SERVICE_KEYS, units
from bearingload.reports.render import Column, Table, csv_block, csv_header, render
from bearingload.reports.solve import INPUT_KEYS, REPORT_KEYS, column
from bearingload.studies.matrix import MATRIX_KEYS

#: The most rows json, markdown and table hold in memory (csv is streamed without a limit).
MAX_HELD_ROWS = 100_000
_BEARING_ONLY = (
    "bearing",
    "clearance_pick",
    "p_max_inner",
    "p_max_outer",
    "static_safety",
    "static_rating",
    "rating_life",
    "reference_rating_life",
    "revolutions",
    "rotating",
    "allowable_load",
)


#: Columns of a combined-load file written only when the file has them (as solve writes them
#: only when given).
_COMBINED_IF_GIVEN = ("moment_cross", "contact_angle")
#: The output columns of a combined-load file (those of ``solve --format csv`` with an axial
#: load), after the row number.
COMBINED_KEYS: tuple[str, ...] = (
    "bearing", "method", "balls", "load", "axial_load", "moment", "moment_cross",
    "misalignment", "contact_angle", "tilt_radius", "rotating", "stiffness", "clearance",
    "clearance_pick", "cage_angle", *RESULT_KEYS, "q_max", "k", "K_Q", "loaded_balls", "load_zone",
    "p_max_inner", "p_max_outer", "static_equivalent_load", "static_safety", "static_rating", "contact_angle_max",
    "free_contact_angle", "axial_play", "x", "y", "axial", "tilt", "tilt_cross",
    "stiffness_radial", "stiffness_axial", "stiffness_tilt", "reference_rating_life",
    "reference_rating_life_hours", "dynamic_rating", "equivalent_load", "rating_life",
    "rating_life_hours", *SERVICE_KEYS[:1], "ball_density", *SERVICE_KEYS[1:],
)  # fmt: skip
#: ... then the entries of the 5x5 tangent stiffness matrix, as solve's csv writes them.
COMBINED_KEYS += MATRIX_KEYS
#: What the rows of a combined-load file carry beyond the columns, as solve's json names it:
#: the model (the ball dynamics added at a speed) and each ball's inner and outer contact angle
#: [°] and load [N] (json only; null for a radial row, whose model is the radial engine's).
HELD_KEYS = ("model", "contact_angles_inner", "contact_angles_outer", "ball_loads_inner",
             "ball_loads_outer")  # fmt: skip
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
#: The output columns each service input column can give (solve prints them when the option is
#: given); a file without the column has none of them.
SERVICE_OUTPUT = {
    "speed": ("speed", "preload_at_speed", "ball_density", "cage_frequency",
              "ball_pass_frequency_outer", "ball_pass_frequency_inner", "ball_spin_frequency",
              "rating_life_hours",
              "reference_rating_life_hours",
              "modified_rating_life_hours", "modified_reference_rating_life_hours"),
    "reliability": ("reliability", "reliability_factor"),
    "viscosity": ("viscosity", "rated_viscosity", "kappa", "contamination_factor",
                  "fatigue_load_limit", "a_iso", "modified_rating_life",
                  "modified_rating_life_hours", "reference_equivalent_load", "a_iso_reference",
                  "modified_reference_rating_life", "modified_reference_rating_life_hours",
                  "film_thickness"),
    "roughness": ("roughness", "film_ratio"),
}  # fmt: skip


def _service_outputs(header: Header) -> set[str]:
    """The service columns a file with ``header`` writes."""
    names = set(header.names)
    if names & set(OIL_INPUTS):  # the oil gives the viscosity, and what it feeds
        names.add("viscosity")
    keys = {k for c, ks in SERVICE_OUTPUT.items() if c in names for k in ks}
    if "viscosity" not in names:  # the modified lives need a_ISO, the film ratio the film
        keys -= {"modified_rating_life_hours", "modified_reference_rating_life_hours",
                 "film_ratio", "roughness"}  # fmt: skip
    return keys


def batch_columns(header: Header) -> list[Column]:
    """The output columns for a file with ``header`` (its oil columns, as given, before the
    operating viscosity they give)."""
    if header.pairs:
        from bearingload.batch.pairs import pair_columns

        columns = pair_columns(_service_outputs(header))
    else:
        columns = _columns(header)
    oil = [column(k) for k in OIL_INPUTS if k in header.names]
    at = next((i for i, c in enumerate(columns) if c.key == "viscosity"), len(columns))
    return columns[:at] + oil + columns[at:]


def _columns(header: Header) -> list[Column]:
    service = set(SERVICE_KEYS) | {"rating_life_hours", "reference_rating_life_hours",
                                   "ball_density"}  # fmt: skip
    if not any(n in header.names for n in MOUNTING_PARAMS):  # no mounting: as bought
        service |= set(RESULT_KEYS)
    wanted = _service_outputs(header)
    if header.combined:  # the columns of solve's csv with an axial load, every one
        given = [k for k in COMBINED_KEYS if k not in _COMBINED_IF_GIVEN or k in header.names]
        given = [k for k in given if k not in service or k in wanted]
        return [column(k, 1.5) for k in ("row", *given)]
    answer = [k for k in REPORT_KEYS if k != "relative_error"]
    answer = [k for k in answer if k not in service or k in wanted]
    keys = ["row", *INPUT_KEYS, *answer, "valid"]
    if not header.has_bearing:
        keys = [k for k in keys if k not in _BEARING_ONLY and k not in service]
    if "method" not in header.names:
        keys.remove("epsilon")
    # rows of roller bearings (m = 10/9) or an exponent column mix exponents: N/mm^m then
    exponent = None if "exponent" in header.names or header.has_bearing else 1.5
    return [column(k, exponent) for k in keys]


def held_keys(header: Header) -> tuple[str, ...]:
    """The keys beyond the columns that json, markdown and table hold for a file with
    ``header`` (:data:`HELD_KEYS` for a combined-load file or a file of pairs, and for a file
    of bearings with a speed column, whose ball bearings at speed solve gives the ball
    dynamics)."""
    at_speed = "speed" in header.names and header.has_bearing
    return HELD_KEYS if header.combined or header.pairs or at_speed else ()


def csv_head(columns: Sequence[Column]) -> str:
    """The csv header line."""
    return csv_header(columns)


def csv_rows(columns: Sequence[Column], rows: Sequence[int], values: dict[str, Any]) -> str:
    """The csv lines of one solved chunk."""
    return csv_block(columns, {"row": rows} | row_values(columns, len(rows), values))


#: The last csv column: why a row was skipped (blank where it was solved); json lists the
#: skipped rows under ``skipped``, table and markdown in the notes.
SKIPPED = Column("skipped", "skipped: the reason", "", None, "left")


def csv_chunk(
    columns: Sequence[Column],
    rows: Sequence[int],
    values: dict[str, Any],
    skipped: Sequence[tuple[int, str]],
) -> str:
    """The csv lines of one chunk in row order (``columns`` ending with :data:`SKIPPED`): each
    solved row, and each skipped row with its number and its reason, its other cells blank."""
    solved = csv_rows(columns, rows, values).splitlines(keepends=True) if len(rows) else []
    numbers = [r for r, _ in skipped]
    blank: dict[str, list[Any]] = {c.key: [None] * len(skipped) for c in columns}
    blank |= {"row": numbers, "skipped": [m for _, m in skipped]}
    refused = csv_block(columns, blank).splitlines(keepends=True) if skipped else []
    lines = list(zip(rows, solved, strict=True)) + list(zip(numbers, refused, strict=True))
    return "".join(line for _, line in sorted(lines, key=lambda pair: pair[0]))


def row_values(columns: Sequence[Column], n: int, values: dict[str, Any]) -> dict[str, Any]:
    """The values of ``columns`` but the row number, blank (None) where the rows have none."""
    return {c.key: values.get(c.key, [None] * n) for c in columns if c.key != "row"}


def held_report(
    columns: Sequence[Column],
    rows: Sequence[int],
    values: dict[str, list[Any]],
    skipped: Sequence[tuple[int, str]],
    fmt: str,
) -> str:
    """The whole report in ``fmt`` (json, markdown, table) from every solved row."""
    keys = [c.key for c in columns]
    data = {"row": list(rows)} | values
    records = [dict(zip(keys, r, strict=True)) for r in zip(*(data[k] for k in keys), strict=True)]
    held = [k for k in HELD_KEYS if k in values]
    if fmt == "json":
        for i, record in enumerate(records):
            record |= {k: values[k][i] for k in held}
        for record, found in zip(records, values.get("warnings", []), strict=False):
            record["warnings"] = list(found)
        doc = {
            "cases": records,
            "skipped": [{"row": r, "reason": m} for r, m in skipped],
            "units": {c.key: c.unit for c in columns if c.unit} | units(held, 1.5),
        }
        return render([], "json", document=doc)
    rows_out = [
        {k: "" if v is None else str(v) if isinstance(v, bool) else v for k, v in r.items()}
        for r in records
    ]
    columns = [Column(c.key, c.key, c.unit, c.digits, c.align) for c in columns]  # short heads
    dynamics = [m for m in values.get("model", []) if m is not None and "; ball dynamics" in m]
    models = sorted(set(dynamics))  # not the radial engine's model, which has a '; ' too
    notes = [DYNAMICS_NOTE.format(m.split("; ", 1)[1]) for m in models]
    if models and "pair_lift_off_axial_load" in keys:  # pairs at speed: what is at rest
        notes.append(PAIR_AT_SPEED_NOTE)
    notes += [f"Row {r} skipped: {m}" for r, m in skipped]
    title = f"{len(records)} cases (row: the input file's row, the header is row 1)"
    return render([Table(title, columns, rows_out, notes)], fmt)
