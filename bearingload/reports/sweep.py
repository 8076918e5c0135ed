"""The report of a cage sweep: a summary over one pitch and one row per cage position, in the
formats docs/guide.md ("The turning cage") describes; lengths in µm for people, mm in csv and json.
"""

from __future__ import annotations

from dataclasses import asdict
from typing import Any

from bearingload.reports.quantities import (
    MATRIX_UNITS,
    QUANTITIES,
    column,
    for_elements,
    units,
)
from bearingload.reports.render import Column, Table, render
from bearingload.reports.solve import blank
from bearingload.studies.matrix import matrix_key, radial_matrix
from bearingload.studies.sweep import CageSweep
from bearingload.units import KGF

#: Quantities summarised over the sweep (min, mean, max, peak-to-peak).
SPREADS = ("x", "y", "q_max", "stiffness_radial")
#: Per cage position: the quantity and its short header in the human table.
ROW_KEYS = (
    ("cage_angle", "cage angle"),
    ("x", "x"),
    ("y", "y"),
    ("q_max", "Q_max"),
    ("q_max_ball", "ball"),
    ("loaded_balls", "loaded"),
    ("stiffness_matrix_11", "K_xx"),
    ("stiffness_matrix_12", "K_xy"),
    ("stiffness_matrix_21", "K_yx"),
    ("stiffness_matrix_22", "K_yy"),
    ("stiffness_radial", "K_r"),
)
INPUT_KEYS = ("balls", "load", "stiffness", "clearance", "exponent")
#: The first note of every sweep's summary (:func:`spread_table`).
MEAN_NOTE = "mean: over one period (the last position, equal to the first, left out)."
#: The lives at each cage position, where asked for (--dynamic-rating, --rotating, --speed).
LIFE_ROW_KEYS = (("reference_rating_life", "L10r"), ("reference_rating_life_hours", "L10rh"))


def _life_rows(s: CageSweep) -> list[tuple[str, str]]:
    """The per-position life columns the sweep has: L10r where computed, in hours at a speed."""
    if s.reference_rating_life is None:
        return []
    return list(LIFE_ROW_KEYS if s.speed is not None else LIFE_ROW_KEYS[:1])


def _fixed_lives(s: CageSweep) -> dict[str, Any]:
    """The lives the cage does not change (ISO 281's L10 at P = F_r, in hours at a speed),
    where asked for; empty for a plain sweep."""
    if s.dynamic_rating is None and s.speed is None:
        return {}
    out: dict[str, Any] = {"dynamic_rating": s.dynamic_rating, "rating_life": s.rating_life}
    if s.speed is not None:
        out |= {"speed": s.speed, "rating_life_hours": s.hours(s.rating_life)}
    return out


#: The note of sweep and table life at a speed with --quasi-static: the static model
#: (docs/speed.md).
STATIC_AT_SPEED = (
    "Ball dynamics left out: the static model (--quasi-static; --speed gives the lives in hours "
    "only); without --quasi-static a ball bearing is solved with each ball's centrifugal force "
    "and gyroscopic moment, as 'bearingload solve --speed' solves it (docs/speed.md)."
)


def static_at_speed(speed: float | None, balls: bool = True) -> dict[str, str]:
    """The json key ``ball_dynamics`` (:data:`STATIC_AT_SPEED`) of a static report of ball
    bearings at a ``speed``; none without a speed or for rollers (no ball dynamics)."""
    return {"ball_dynamics": STATIC_AT_SPEED} if speed is not None and balls else {}


def _life_notes(s: CageSweep) -> list[str]:
    static = list(static_at_speed(s.speed, s.exponent == 1.5).values())
    if s.rotating is None:
        return static
    return static + [
        f"L10r: ISO/TS 16281:2008, 4.3, from the exact ball loads at each cage position, every "
        f"ball at the contact angle 0 (Q_ci, Q_ce from C; {s.rotating} ring rotating; "
        "--rotating), as solve gives it; L10: ISO 281 at P = F_r, the same at every position."
    ]


def sweep_report(s: CageSweep, fmt: str, context: str = "") -> str:
    """Render a sweep in ``fmt``; ``context`` (e.g. the bearing and its sources) is noted."""
    if fmt == "json":
        return render([], "json", document=sweep_json(s))
    if fmt == "csv":
        return render([_csv_table(s)], "csv")
    tables = [_spread_table(s, context), _figures_table(s), _rows_table(s)]
    return render([for_elements(t, s.exponent, notes=True) for t in tables], fmt)


def inputs_text(s: CageSweep) -> str:
    """One line naming the sweep's inputs with units."""
    return (
        f"z = {s.balls}, F_r = {s.load:.6g} N ({s.load / KGF:.6g} kgf), "
        f"K = {s.stiffness:.6g} N/mm^{s.exponent:g}, G_r = {s.clearance * 1e3:.6g} µm "
        f"(gap per side {s.clearance * 500:.6g} µm), m = {s.exponent:.6g}; cage angle 0 to "
        f"{360 / s.balls:.6g}° in {s.cage_angle.size} positions"
    )


def _spread_table(s: CageSweep, context: str) -> Table:
    keys = [*SPREADS, *(k for k, _ in _life_rows(s))]
    entries = [(QUANTITIES[k].label, s.spread(k), QUANTITIES[k].shown()) for k in keys]
    return spread_table(f"Over one ball pitch ({inputs_text(s)})", entries, _life_notes(s), context)


def spread_table(title: str, entries: Any, notes: list[str], context: str) -> Table:
    """The min/mean/max/peak-to-peak table of a sweep: ``entries`` are (label, spread,
    (unit, factor)) rows; the note on the mean first, ``context`` (if any) last."""
    rows = [
        {"quantity": label, "min": sp.min * factor, "mean": sp.mean * factor,
         "max": sp.max * factor, "ptp": sp.peak_to_peak * factor, "unit": unit or ""}
        for label, sp, (unit, factor) in entries
    ]  # fmt: skip
    return Table(
        title=title,
        columns=[
            Column("quantity", "quantity", align="left"),
            Column("min", "min", digits=6),
            Column("mean", "mean", digits=6),
            Column("max", "max", digits=6),
            Column("ptp", "peak-to-peak", digits=4),
            Column("unit", "unit", align="left"),
        ],
        rows=rows,
        notes=[MEAN_NOTE, *notes, *([context] if context else [])],
    )


def _figures_table(s: CageSweep) -> Table:
    comp = QUANTITIES["compensating_clearance"]
    clearances = value_rows(("compensating_clearance", g) for g in s.compensating_clearance)
    none = {"quantity": comp.label, "value": "none", "unit": ""}
    return value_table(
        "Ripple, and the lives the cage does not change" if _fixed_lives(s) else "Ripple",
        [ripple_row(s.ripple_order), *(clearances or [none]), *value_rows(_fixed_lives(s).items())],
        [
            "compensating clearance: every G_r at which the ring sits at the same x with a ball "
            "under the load and with the load between two balls (no kinematic excitation; "
            "negative = preload). The varying-compliance paper's delta_alpha = delta_S is the "
            "smallest positive one."
        ],
    )


def ripple_row(order: int) -> dict[str, Any]:
    """The row of :func:`value_table` of a sweep's ripple order (periods per cage revolution)."""
    ripple = QUANTITIES["ripple_per_cage_revolution"]
    label = f"{ripple.label} (periods per cage revolution)"
    return {"quantity": label, "value": order, "unit": ripple.unit}


def value_rows(values: Any) -> list[dict[str, Any]]:
    """Rows of :func:`value_table` of (quantity key, value in its machine unit) pairs: the
    label, the value in the display unit ('-' where none), the unit."""
    rows = []
    for key, value in values:
        unit, factor = QUANTITIES[key].shown()
        shown = "-" if value is None else value * factor
        rows.append({"quantity": QUANTITIES[key].label, "value": shown, "unit": unit})
    return rows


def value_table(title: str, rows: list[dict[str, Any]], notes: list[str]) -> Table:
    """A table of single figures of a sweep: rows of quantity, value, unit."""
    return Table(
        title=title,
        columns=[
            Column("quantity", "quantity", align="left"),
            Column("value", "value", digits=6),
            Column("unit", "unit", align="left"),
        ],
        rows=rows,
        notes=notes,
    )


def _rows_table(s: CageSweep) -> Table:
    return positions_table(
        [column(k, header=h, shown=True) for k, h in [*ROW_KEYS, *_life_rows(s)]],
        _flat_rows(s),
        ["ball: the ball carrying Q_max (of two equal, the lower number)."],
    )


def positions_table(columns: list[Column], rows: list[dict[str, Any]], notes: list[str]) -> Table:
    """The per-position table of a sweep: ``columns`` of :func:`bearingload.reports.quantities.
    column` (``shown``), ``rows`` in machine units."""
    title = "Per cage position (ball 1 at the cage angle; angles from the load line)"
    return Table(title, columns, rows, notes)


def _flat_rows(s: CageSweep) -> list[dict[str, Any]]:
    """One dict per cage position, the stiffness matrix as the four entries of its radial block
    under solve's csv names (``stiffness_matrix_11`` ... ``_22``; mm, N, N/mm)."""
    rows = []
    for row in _json_rows(s):
        matrix = row.pop("stiffness_matrix")
        row |= {matrix_key(i, j): matrix[i][j] for i in range(2) for j in range(2)}
        rows.append(row)
    return rows


def _csv_table(s: CageSweep) -> Table:
    fixed = blank(_fixed_lives(s))
    keys = [*INPUT_KEYS, *(k for k, _ in [*ROW_KEYS, *_life_rows(s)]), *fixed]
    inputs = {k: getattr(s, k) for k in INPUT_KEYS}
    rows = [inputs | r | fixed for r in _flat_rows(s)]
    return Table("sweep", [column(k, s.exponent) for k in keys], rows)


def _json_rows(s: CageSweep) -> list[dict[str, Any]]:
    lives = {k: s.values(k) for k, _ in _life_rows(s)}
    return [
        {k: float(v[i]) for k, v in lives.items()}
        | {
            "cage_angle": float(s.cage_angle[i]),
            "x": float(s.x[i]),
            "y": float(s.y[i]),
            "q_max": float(s.q_max[i]),
            "q_max_ball": int(s.q_max_ball[i]),
            "loaded_balls": int(s.loaded_balls[i]),
            "stiffness_matrix": radial_matrix(s.stiffness_matrix[i]),
            "stiffness_radial": float(s.stiffness_radial[i]),
        }
        for i in range(s.cage_angle.size)
    ]


def sweep_json(s: CageSweep) -> dict[str, Any]:
    """The JSON document of a sweep: inputs, ``rows``, ``summary`` and ``units``."""
    summary = spreads(s, [*SPREADS, *(k for k, _ in _life_rows(s))])
    summary["compensating_clearance"] = list(s.compensating_clearance)
    summary |= _fixed_lives(s)
    rows = _json_rows(s)
    keys = [*INPUT_KEYS, *rows[0], *summary]
    return {
        **{k: getattr(s, k) for k in INPUT_KEYS},
        "steps": int(s.cage_angle.size),
        "rows": rows,
        "summary": summary,
        "units": units(keys, s.exponent) | {"stiffness_matrix": MATRIX_UNITS},
        "warnings": list(s.warnings),
    } | static_at_speed(s.speed, s.exponent == 1.5)


def spreads(s: Any, keys: Any) -> dict[str, Any]:
    """The json ``summary`` of a sweep ``s``: min, mean, max and peak_to_peak of each of
    ``keys``, then the ripple order."""
    return {k: asdict(s.spread(k)) for k in keys} | {"ripple_per_cage_revolution": s.ripple_order}
