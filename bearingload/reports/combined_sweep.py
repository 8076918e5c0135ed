"""The report of a cage sweep under a combined load (``bearingload sweep`` with ``--axial-load``...):
the layout of the radial sweep (:mod:`bearingload.reports.sweep`) with the keys of ``solve``'s
combined report, in the formats docs/guide.md describes.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from bearingload.reports.combined import ANGULAR_LABELS, ANGULAR_NOTE, NOTES, tilt_text
from bearingload.reports.quantities import QUANTITIES, column, units
from bearingload.reports.render import Table, render
from bearingload.reports.solve import blank
from bearingload.studies.combined_sweep import SPREAD_KEYS, CombinedSweep

#: Per cage position: the quantity and its short header in the human table.
ROW_KEYS = (
    ("cage_angle", "cage angle"),
    ("x", "x"),
    ("y", "y"),
    ("axial", "axial"),
    ("tilt", "tilt"),
    ("tilt_cross", "tilt cross"),
    ("moment", "M"),
    ("q_max", "Q_max"),
    ("q_max_ball", "ball"),
    ("loaded_balls", "loaded"),
    ("contact_angle_max", "alpha_max"),
    ("reference_rating_life", "L10r"),
    ("reference_rating_life_hours", "L10rh"),
)


def combined_sweep_report(s: CombinedSweep, fmt: str, context: str = "") -> str:
    """Render a combined sweep in ``fmt``; ``context`` (the bearing and its sources) is noted."""
    if fmt == "json":
        return render([], "json", document=combined_sweep_json(s))
    if fmt == "csv":
        return render([_csv_table(s)], "csv")
    return render([_spread_table(s, context), _fixed_table(s), _rows_table(s)], fmt)


def inputs(s: CombinedSweep) -> dict[str, Any]:
    """The sweep's inputs under their quantity keys (a moment only where it is one; the moment
    about the load line and the lever of the tilt where given)."""
    b, r = s.bearing, s.result
    out: dict[str, Any] = {
        "bearing": b.designation or "given by hand",
        "balls": s.balls,
        "load": float(r.load[0]),
        "axial_load": float(r.axial_load[0]),
    }
    if s.misalignment is None:
        out["moment"] = float(r.moment[0])
    if s.moment_cross is not None:
        out["moment_cross"] = float(s.moment_cross)
    if s.misalignment is not None:
        out["misalignment"] = float(s.misalignment)
    if s.tilt_radius is not None:
        out["tilt_radius"] = float(s.tilt_radius)
    return out | {
        "rotating": s.rotating,
        "stiffness": float(b.stiffness),
        "clearance": float(b.clearance),
        "clearance_pick": b.clearance_pick,
    }


def _row_keys(s: CombinedSweep) -> list[tuple[str, str]]:
    """The per-position columns: the moment only where it is an answer (imposed misalignment),
    L10r only where C_r is known."""
    skip = {"moment"} if s.misalignment is None else set()
    if s.reference_rating_life is None:
        skip.add("reference_rating_life")
    if s.reference_rating_life is None or s.speed is None:
        skip.add("reference_rating_life_hours")
    return [(k, h) for k, h in ROW_KEYS if k not in skip]


def _spread_keys(s: CombinedSweep) -> list[str]:
    keys = {k for k, _ in _row_keys(s)}
    return [k for k in SPREAD_KEYS if k in keys]


def fixed(s: CombinedSweep) -> dict[str, Any]:
    """The figures the cage does not change, under their quantity keys."""
    r = s.result
    return (
        {
            "free_contact_angle": float(r.free_contact_angle[0]),
            "axial_play": float(r.axial_play[0]),
            "dynamic_rating": s.dynamic_rating,
            "equivalent_load": s.equivalent_load,
            "rating_life": s.rating_life,
        }
        | (
            {}
            if s.speed is None
            else {"speed": s.speed, "rating_life_hours": s.hours(s.rating_life)}
        )
        | _density(s)
    )


def _density(s: CombinedSweep) -> dict[str, float]:
    """The ball density of the ball dynamics, as solve gives it (``ball_density`` [kg/m^3]);
    none for the static model."""
    density = getattr(s.result, "ball_density", None)
    return {} if density is None else {"ball_density": float(np.ravel(density)[0])}


def rows(s: CombinedSweep) -> list[dict[str, Any]]:
    """One dict per cage position, machine units (mm, °, N, N mm, 10^6 rev)."""
    keys = [k for k, _ in _row_keys(s)]
    r = s.result
    data: dict[str, Any] = {
        "cage_angle": r.cage_angle,
        "q_max_ball": s.q_max_ball,
    } | {k: s.values(k) for k in keys if k in SPREAD_KEYS}
    whole = ("q_max_ball", "loaded_balls")  # counts, the rest floats
    return [
        {k: int(data[k][i]) if k in whole else float(data[k][i]) for k in keys}
        for i in range(s.cage_angle.size)
    ]


def title(s: CombinedSweep) -> str:
    """One line naming the sweep's inputs with units."""
    i = inputs(s)
    who = f"bearing {i['bearing']}, " if i["bearing"] != "given by hand" else ""
    tilt = tilt_text(i)
    return (
        f"{who}z = {s.balls}, F_r = {i['load']:.6g} N, F_a = {i['axial_load']:.6g} N{tilt}, "
        f"G_r = {i['clearance'] * 1e3:.6g} µm, {s.rotating} ring rotating; cage angle 0 to "
        f"{360 / s.balls:.6g}° in {s.cage_angle.size} positions"
    )


def _spread_table(s: CombinedSweep, context: str) -> Table:
    from bearingload.reports.sweep import STATIC_AT_SPEED, spread_table

    angular = s.bearing.contact_angle is not None
    entries = []
    for key in _spread_keys(s):
        q = QUANTITIES[key]
        label = ANGULAR_LABELS.get(key, q.label) if angular else q.label
        entries += [(label, s.spread(key), shown) for shown in [q.shown(), q.also] if shown]
    notes = list(NOTES)
    if angular:  # the axial origin: the zero-load position, not the centred rings
        notes[1] = ANGULAR_NOTE
    dynamics = _dynamics(s)
    if dynamics is not None:
        notes.append(DYNAMICS_NOTE.format(dynamics, _density(s)["ball_density"]))
    elif s.speed is not None:
        notes.append(STATIC_AT_SPEED)
    return spread_table(f"Over one ball pitch ({title(s)})", entries, notes, context)


def _fixed_table(s: CombinedSweep) -> Table:
    from bearingload.reports.sweep import ripple_row, value_rows, value_table

    return value_table(
        "The same at every cage position",
        [ripple_row(s.ripple_order), *value_rows(fixed(s).items())],
        [
            "ISO 281's basic life (C_r/P)^3 does not see the cage position, the clearance or the "
            "load distribution; L10r (ISO/TS 16281) does, per cage position above."
        ],
    )


def _rows_table(s: CombinedSweep) -> Table:
    from bearingload.reports.sweep import positions_table

    return positions_table(
        [column(k, header=h, shown=True) for k, h in _row_keys(s)],
        rows(s),
        [
            f"axial: {_axial_origin(s)}; tilt: about the axis across the load; tilt cross: "
            "about the load line; ball: the ball carrying Q_max (of two equal, the lower "
            "number); alpha_max: the largest contact angle of a loaded ball."
        ],
    )


def _axial_origin(s: CombinedSweep) -> str:
    """Where the axial displacement is measured from (docs/angular_contact.md)."""
    if s.bearing.contact_angle is None:
        return "from the centred rings"
    return "from the zero-load position (every ball at the design contact angle)"


def _model(s: CombinedSweep) -> str:
    """The model as solve's json names it (:func:`bearingload.reports.combined.contact_values`):
    at a speed the ball dynamics added."""
    from bearingload.reports.combined import contact_values

    return str(contact_values(s.result, s.bearing.contact_angle)["model"])


def _dynamics(s: CombinedSweep) -> str | None:
    """The ball dynamics' model of a sweep at speed (None: the static model)."""
    return getattr(s.result, "model", None)


#: The note of a sweep with the ball dynamics (the model's name filled in).
DYNAMICS_NOTE = (
    "Speed: {} at every cage position (Jones 1960; Harris & Kotzalas; docs/speed.md), balls of "
    "{:.6g} kg/m^3: Q_max, its ball, the loaded balls and alpha_max are the inner contacts'; L10r "
    "takes each ball's inner load for the inner ring, its outer load for the outer ring."
)


def _csv_table(s: CombinedSweep) -> Table:
    head = inputs(s)
    tail = fixed(s)
    keys = [*head, *(k for k, _ in _row_keys(s)), *tail]
    const = blank(head | tail)
    return Table(
        title="sweep",
        columns=[column(k, 1.5) for k in keys],
        rows=[const | r for r in rows(s)],
    )


def combined_sweep_json(s: CombinedSweep) -> dict[str, Any]:
    """The JSON document: inputs, ``steps``, ``rows``, ``summary``, ``units``, ``geometry`` (the
    bearing's, with the source of every value), ``warnings``."""
    from bearingload.reports.bearing import geometry_document
    from bearingload.reports.sweep import spreads, static_at_speed

    summary = spreads(s, _spread_keys(s)) | fixed(s)
    head = inputs(s)
    body = rows(s)
    keys = [*head, *body[0], *summary]
    return {
        **head,
        "model": _model(s),
        "steps": int(s.cage_angle.size),
        "rows": body,
        "summary": summary,
        "units": units(keys, 1.5),
        "geometry": geometry_document(s.bearing),
        "warnings": list(s.warnings),
    } | (static_at_speed(s.speed) if _dynamics(s) is None else {})
