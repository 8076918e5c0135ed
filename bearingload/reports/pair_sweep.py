"""The report of a cage sweep of a bearing pair (``bearingload sweep 7205BDB --preload ...``).

* ``table`` / ``markdown``: min, mean, max and peak-to-peak over the pitch of the shaft's
  displacement, the pair's stiffness, each bearing's Q_max and loaded balls and the pair's L10r;
  then one row per cage position.
* ``csv``: one rectangular table, the csv of ``solve 7205BDB --cage-angle A --format csv`` at
  every cage position (one row per bearing, ``bearing_number`` 1 and 2, the pair's values in
  ``pair_...`` columns): the same columns and values.
* ``json``: the pair's inputs, ``steps``, ``rows`` (at each position the pair's keys of
  ``solve``'s json case and ``bearings``, each bearing's keys), ``summary``, ``units``,
  ``warnings``.
"""

from __future__ import annotations

import dataclasses
from dataclasses import asdict
from typing import Any

from bearingload.reports.combined import ANGULAR_LABELS
from bearingload.reports.pair import (
    CSV_INPUTS,
    OWN_KEYS,
    PAIR_ANSWERS,
    PAIR_INPUTS,
    PAIR_SERVICE,
    STATIC_AT_SPEED,
    csv_columns,
    csv_rows,
    pair_records,
)
from bearingload.reports.quantities import QUANTITIES, Quantity, units
from bearingload.reports.render import Column, Table, render
from bearingload.studies.bearing_pair import ARRANGEMENT_NAMES
from bearingload.studies.pair_sweep import BEARING_KEYS, PAIR_KEYS, PairSweep

#: The note under a pair sweep.
NOTES = (
    "mean: over one period (the last position, equal to the first, left out).",
    "Both bearings' cages at the same angle (ball 1 of each at the cage angle, as solve "
    "--cage-angle); the pair: the shaft's displacement at the pair's centre and its stiffness "
    "(docs/angular_contact.md); L10r: the pair's, (L1^-e + L2^-e)^(-1/e), e = 10/9.",
)
#: The note of a pair sweep at --speed with --quasi-static (as one bearing's: the static model).
HOURS_NOTE = (
    "Speed: --quasi-static: the pair is solved by the static model (the ball dynamics left "
    "out); the speed gives the lives in hours only."
)
#: The per-position columns of the human table: (key, bearing or None, header).
ROW_KEYS = (
    ("cage_angle", None, "cage angle"), ("x", None, "x"), ("y", None, "y"),
    ("axial", None, "axial"), ("tilt", None, "tilt"), ("q_max", 1, "Q_max 1"),
    ("q_max", 2, "Q_max 2"), ("loaded_balls", 1, "loaded 1"), ("loaded_balls", 2, "loaded 2"),
    ("stiffness_radial", None, "k_r"), ("stiffness_axial", None, "k_a"),
    ("stiffness_tilt", None, "k_tilt"), ("reference_rating_life", None, "L10r"),
    ("reference_rating_life_hours", None, "L10rh"),
)  # fmt: skip


def pair_sweep_report(s: PairSweep, fmt: str, context: str = "") -> str:
    """Render a pair sweep in ``fmt``; ``context`` (the bearing and its sources) is noted."""
    if fmt == "json":
        return render([], "json", document=pair_sweep_json(s))
    if fmt == "csv":
        return render([_csv_table(s)], "csv")
    return render([_spread_table(s, context), _rows_table(s)], fmt)


def _csv_table(s: Any) -> Table:
    """solve's csv of the pair of every row of ``s`` (its ``cases``: the cage positions of a
    sweep, the preloads of table life; its ``speed``, if any), one table."""
    speed = getattr(s, "speed", None)
    records = [pair_records(c, _c0(c, speed)) for c in s.cases]
    own = [k for k in OWN_KEYS if any(k in r for _, rs in records for r in rs)]
    cols = csv_columns(tuple(k for k in PAIR_SERVICE if k in records[0][0]), own)
    keys = [c.key for c in cols]
    rows = []
    for c, (pair, recs) in zip(s.cases, records, strict=True):
        rows += csv_rows(c, pair, recs, keys)
    blank = [{k: "" if r[k] is None else r[k] for k in keys} for r in rows]
    return Table("sweep", cols, blank)


def _c0(c: Any, speed: float | None = None) -> list[Any]:
    """Each bearing's service values as solve gives them with ``--speed`` alone (C_0; with a
    speed the lives in hours)."""
    from bearingload.bearings.service_life import Operating, service_values
    from bearingload.studies.life_basis import combined_basis

    return [service_values(Operating(speed=speed), combined_basis(b)) for b in c.bearings]


def _entries(s: PairSweep) -> list[tuple[str, Quantity, int | None]]:
    """(label, quantity, bearing) of every summarised quantity the sweep has."""
    out: list[tuple[str, Quantity, int | None]] = []
    for key in PAIR_KEYS:
        q = QUANTITIES[key]
        if s.values(key) is not None:
            out.append((f"{ANGULAR_LABELS.get(key, q.label)}, pair", q, None))
    for key in BEARING_KEYS:
        q = QUANTITIES[key]
        out += [(f"{q.label}, bearing {k}", q, k) for k in (1, 2)]
    return out


def _spread_table(s: PairSweep, context: str) -> Table:
    from bearingload.reports.sweep import spread_table

    entries = []
    for label, q, k in _entries(s):
        sp = s.spread(q.key, k)
        assert sp is not None
        entries.append((dataclasses.replace(q, label=label), sp, q.shown()))
    notes = [*NOTES, *_speed_notes(s)]
    return spread_table(f"Over one ball pitch ({title(s)})", entries, notes, context)


def _speed_notes(s: PairSweep) -> list[str]:
    """The note of a pair sweep at a speed: the ball dynamics of both bearings, or the static
    model (--quasi-static)."""
    if s.dynamics is not None:
        return [SWEEP_DYNAMICS_NOTE.format(s.dynamics)]
    return [HOURS_NOTE] if s.speed is not None else []


#: The note of a pair sweep with the ball dynamics (the model's name filled in).
SWEEP_DYNAMICS_NOTE = (
    "Speed: {} in both bearings at every cage position (Jones 1960; Harris & Kotzalas; "
    "docs/speed.md): Q_max and the loaded balls are the inner contacts'; each bearing's L10r "
    "takes the inner loads for the inner ring, the outer loads for the outer ring."
)


def title(s: PairSweep) -> str:
    """One line naming the sweep's inputs with units."""
    p = pair_records(s.cases[0])[0]
    who = f"bearings {p['bearing']}, " if p["bearing"] != "given by hand" else ""
    return (
        f"{who}pair {p['arrangement']} ({ARRANGEMENT_NAMES[p['arrangement']]}), z = {s.balls} "
        f"per bearing, F_r = {p['load']:.6g} N, F_a = {p['axial_load']:.6g} N, preload "
        f"{p['preload']:.6g} N, {p['rotating']} ring rotating; cage angle 0 to "
        f"{360 / s.balls:.6g}° in {len(s.cases)} positions"
    )


def _rows_table(s: PairSweep) -> Table:
    keys = [(k, b, h) for k, b, h in ROW_KEYS
            if k == "cage_angle" or s.values(k, b) is not None]  # fmt: skip
    columns, factors = [], {}
    for key, b, header in keys:
        q = QUANTITIES[key]
        unit, factors[key] = q.shown()
        columns.append(Column(f"{key}{b or ''}", header, unit, q.digits))
    data: dict[str, Any] = {f"{k}{b or ''}": s.cage_angle if k == "cage_angle" else
                            s.values(k, b) for k, b, _ in keys}  # fmt: skip
    rows = []
    for i in range(len(s.cases)):
        row: dict[str, Any] = {}
        for key, b, _ in keys:
            v = float(data[f"{key}{b or ''}"][i])
            row[f"{key}{b or ''}"] = int(v) if key == "loaded_balls" else v * factors[key]
        rows.append(row)
    return Table(
        "Per cage position (ball 1 at the cage angle; angles from the load line)",
        columns, rows,
        ["x, y, axial, tilt: the shaft at the pair's centre; Q_max k, loaded k: bearing k's "
         "heaviest ball load and its loaded balls; k_r, k_a, k_tilt: the pair's stiffness."],
    )  # fmt: skip


def pair_sweep_json(s: PairSweep) -> dict[str, Any]:
    """The JSON document: the pair's inputs, ``model``, ``steps``, ``rows`` (the pair's keys of
    solve's json at each position and ``bearings``), ``summary``, ``units``, ``warnings``."""
    rows = []
    for c in s.cases:
        pair, recs = pair_records(c, _c0(c, s.speed))
        answers = {k: pair[k] for k in ("cage_angle", *PAIR_ANSWERS, *PAIR_SERVICE) if k in pair}
        rows.append(answers | {"bearings": recs})
    head = {k: v for k, v in pair_records(s.cases[0])[0].items()
            if k in PAIR_INPUTS and k != "cage_angle"}  # fmt: skip
    summary: dict[str, Any] = {"bearings": [{}, {}]}
    for _, q, k in _entries(s):
        sp = s.spread(q.key, k)
        assert sp is not None
        (summary if k is None else summary["bearings"][k - 1])[q.key] = asdict(sp)
    keys = [*head, *rows[0], *(k for r in rows[0]["bearings"] for k in r), *CSV_INPUTS]
    return {
        **head,
        "model": "pair of angular-contact ball bearings on one rigid shaft (ISO/TS 16281 each), "
        "both cages at the cage angle" + _model_end(s),
        "steps": len(s.cases),
        "rows": rows,
        "summary": summary,
        "units": units(list(dict.fromkeys(keys)), 1.5),
        "warnings": list(s.warnings),
    }


def _model_end(s: PairSweep) -> str:
    """The end of the json's ``model``: the ball dynamics, or the static model at a speed."""
    if s.dynamics is not None:
        return f"; {s.dynamics} in both bearings"
    return STATIC_AT_SPEED if s.speed is not None else ""


#: The columns of ``table life`` of a pair: (key, bearing or None, header).
PRELOAD_KEYS = (
    ("preload", None, "F_p"), ("q_max", 1, "Q_max 1"), ("q_max", 2, "Q_max 2"),
    ("loaded_balls", 1, "n 1"), ("loaded_balls", 2, "n 2"), ("stiffness_axial", None, "k_a"),
    ("stiffness_radial", None, "k_r"), ("lift_off_axial_load", None, "lift-off"),
    ("reference_rating_life", None, "L10r"), ("rating_life", None, "L10 ISO 281"),
)  # fmt: skip


def preload_life_report(t: Any, fmt: str) -> str:
    """Render ``table life`` of a pair (:class:`bearingload.studies.pair_sweep.
    LifeAgainstPreload`) in ``fmt``: one row per preload; csv: solve's pair csv at every
    preload (one row per bearing); json: the pair's inputs, ``rows`` (the pair's keys of
    solve's json and ``bearings``), ``units``, ``warnings``."""
    if fmt == "csv":
        return render([_csv_table(t)], "csv")
    if fmt == "json":
        return render([], "json", document=_preload_json(t))
    records = [pair_records(c) for c in t.cases]
    columns = []
    for key, b, header in PRELOAD_KEYS:
        q = QUANTITIES[key]
        columns.append(Column(f"{key}{b or ''}", header, q.shown()[0], q.digits))
    rows = []
    for pair, recs in records:
        row: dict[str, Any] = {}
        for key, b, _ in PRELOAD_KEYS:
            v = pair.get(key) if b is None else recs[b - 1].get(key)
            row[f"{key}{b or ''}"] = "-" if v is None else v * QUANTITIES[key].shown()[1]
        rows.append(row)
    return render([Table(_preload_title(records[0][0], t), columns, rows,
                         _preload_notes(t, records))], fmt)  # fmt: skip


def _preload_title(p: dict[str, Any], t: Any) -> str:
    who = f"bearings {p['bearing']}, " if p["bearing"] != "given by hand" else ""
    return (
        f"Life against the preload: {who}pair {p['arrangement']} "
        f"({ARRANGEMENT_NAMES[p['arrangement']]}), z = {t.bearing.balls} per bearing, F_r = "
        f"{p['load']:.6g} N, F_a = {p['axial_load']:.6g} N, {p['rotating']} ring rotating"
    )


def _preload_notes(t: Any, records: list[Any]) -> list[str]:
    """The note under the table: what the rows are, and the preload of the longest L10r."""
    notes = [
        "F_p: the axial force each bearing carries with no external load (solve --preload); "
        "Q_max k, n k: bearing k's heaviest ball load and loaded balls; k_a, k_r: the pair's "
        "axial and radial stiffness; lift-off: the axial load alone that unloads a bearing; "
        "L10r: the pair's (L1^-e + L2^-e)^(-1/e), e = 10/9, from the ball loads (ISO/TS "
        "16281); L10: the same rule on each bearing's ISO 281 (C/P)^3.",
    ]
    lives = [pair.get("reference_rating_life") for pair, _ in records]
    if all(v is not None for v in lives) and len(lives) > 1:
        best = int(max(range(len(lives)), key=lambda i: lives[i]))
        notes.append(
            f"Among these rows the pair's L10r is longest at F_p = {t.preloads[best]:.6g} N "
            f"({lives[best]:.6g} 10^6 rev): too little preload lets a bearing unload (its balls "
            "may skid), too much loads both; the stiffness grows with the preload."
        )
    return notes


def _preload_json(t: Any) -> dict[str, Any]:
    rows = []
    for c in t.cases:
        pair, recs = pair_records(c, _c0(c))
        rows.append({k: pair[k] for k in ("preload", *PAIR_ANSWERS)} | {"bearings": recs})
    head = {k: v for k, v in pair_records(t.cases[0])[0].items()
            if k in PAIR_INPUTS and k != "preload"}  # fmt: skip
    keys = [*head, *rows[0], *(k for r in rows[0]["bearings"] for k in r)]
    return {
        **head,
        "model": "pair of angular-contact ball bearings on one rigid shaft (ISO/TS 16281 each)",
        "rows": rows,
        "units": units(list(dict.fromkeys(keys)), 1.5),
        "warnings": list(t.warnings),
    }
