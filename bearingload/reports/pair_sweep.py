"""The report of a cage sweep of a bearing pair (``bearingload sweep 7205BDB --preload ...``):
its summary, rows, csv and json as docs/angular_contact.md ("Pairs in sweep") describes them.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import asdict
from typing import Any

from bearingload.reports.combined import ANGULAR_LABELS
from bearingload.reports.pair import (
    HOURS_NOTE,
    PAIR_ANSWERS,
    PAIR_MODEL,
    PAIR_SERVICE,
    model_end,
    pair_records,
    pairs_csv,
    pairs_document,
    with_matrices,
)
from bearingload.reports.quantities import QUANTITIES, Quantity, column
from bearingload.reports.render import Table, render
from bearingload.studies.bearing_pair import ARRANGEMENT_NAMES, PairLives
from bearingload.studies.pair_sweep import BEARING_KEYS, PAIR_KEYS, PairSweep

#: The note under a pair sweep.
NOTES = (
    "Both bearings' cages at the same angle (ball 1 of each at the cage angle, as solve "
    "--cage-angle); the pair: the shaft's displacement at the pair's centre and its stiffness "
    "(docs/angular_contact.md); L10r: the pair's, (L1^-e + L2^-e)^(-1/e), e = 10/9.",
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


def pair_sweep_report(s: PairSweep, fmt: str, lives: Sequence[PairLives], context: str = "") -> str:
    """Render a pair sweep in ``fmt``, ``lives`` the service values of its positions as the
    plan gives them (:class:`bearingload.studies.bearing_pair.PairLives`); ``context`` (the
    bearing and its sources) is noted."""
    if fmt == "json":
        return render([], "json", document=pair_sweep_json(s, lives))
    if fmt == "csv":
        return render([_csv_table(s, lives)], "csv")
    return render([_spread_table(s, context), _rows_table(s)], fmt)


def _csv_table(s: PairSweep, lives: Sequence[PairLives]) -> Table:
    """solve's csv of the pair at every cage position (with its ``speed``, if any), one table."""
    records = [pair_records(c, life) for c, life in zip(s.cases, lives, strict=True)]
    return pairs_csv("sweep", s.cases, records)


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

    entries = [(label, s.spread(q.key, k), q.shown()) for label, q, k in _entries(s)]
    setting = s.cases[0].preload_class
    notes = [
        *NOTES,
        *_speed_notes(s),
        *([] if setting is None else [f"Preload: {setting.source}."]),
    ]
    return spread_table(f"Over one ball pitch ({title(s)})", entries, notes, context)


def _speed_notes(s: PairSweep) -> list[str]:
    """The note of a pair sweep at a speed: the ball dynamics of both bearings, or the static
    model (--quasi-static)."""
    if s.model is not None:
        r = s.cases[0].result
        rest = "" if r.lift_off_axial_load is None else (
            f"; lift-off {abs(float(r.lift_off_axial_load)):.6g} N at rest")  # fmt: skip
        thrust = getattr(r, "preload_at_speed", None)  # DB/DF at speed
        held = "" if thrust is None else (
            f"; preload at the speed {float(thrust):.6g} N each bearing (F_p "
            f"{float(r.preload):.6g} N ground in at rest){rest}")  # fmt: skip
        return [SWEEP_DYNAMICS_NOTE.format(s.model) + held + "."]
    return [HOURS_NOTE] if s.speed is not None else []


#: The note of a pair sweep with the ball dynamics (the model's name filled in; the preload at
#: the speed and the lift-off at rest follow).
SWEEP_DYNAMICS_NOTE = (
    "Speed: {} in both bearings at every cage position (Jones 1960; Harris & Kotzalas; "
    "docs/speed.md): Q_max and the loaded balls are the inner contacts'; each bearing's L10r "
    "takes the inner loads for the inner ring, the outer loads for the outer ring"
)


def title(s: PairSweep) -> str:
    """One line naming the sweep's inputs with units."""
    p = pair_records(s.cases[0])[0]
    who = f"bearings {p['bearing']}, " if p["bearing"] != "given by hand" else ""
    setting = s.cases[0].preload_class
    preload = f"{p['preload']:.6g} N" if setting is None else setting.text
    return (
        f"{who}pair {p['arrangement']} ({ARRANGEMENT_NAMES[p['arrangement']]}), z = {s.balls} "
        f"per bearing, F_r = {p['load']:.6g} N, F_a = {p['axial_load']:.6g} N, preload "
        f"{preload}, {p['rotating']} ring rotating; cage angle 0 to "
        f"{360 / s.balls:.6g}° in {len(s.cases)} positions"
    )


def _rows_table(s: PairSweep) -> Table:
    from bearingload.reports.sweep import positions_table

    keys = [(k, b, h) for k, b, h in ROW_KEYS
            if k == "cage_angle" or s.values(k, b) is not None]  # fmt: skip
    data: dict[str, Any] = {
        f"{k}{b or ''}": s.cage_angle if k == "cage_angle" else s.values(k, b) for k, b, _ in keys
    }
    whole = {k for k in data if k.startswith("loaded_balls")}  # counts, the rest floats
    rows = [
        {k: int(v[i]) if k in whole else float(v[i]) for k, v in data.items()}
        for i in range(len(s.cases))
    ]
    return positions_table(
        [column(k, header=h, name=f"{k}{b or ''}", shown=True) for k, b, h in keys],
        rows,
        [
            "x, y, axial, tilt: the shaft at the pair's centre; Q_max k, loaded k: bearing k's "
            "heaviest ball load and its loaded balls; k_r, k_a, k_tilt: the pair's stiffness."
        ],
    )


def pair_sweep_json(s: PairSweep, lives: Sequence[PairLives]) -> dict[str, Any]:
    """The JSON document: the pair's inputs, ``model``, ``steps``, ``rows`` (the pair's keys of
    solve's json at each position and ``bearings``), ``summary``, ``units``, ``warnings``."""
    records = [pair_records(c, life) for c, life in zip(s.cases, lives, strict=True)]
    answers = ("cage_angle", *PAIR_ANSWERS, *PAIR_SERVICE)
    rows = [
        with_matrices(c, {k: p[k] for k in answers if k in p} | {"bearings": recs})
        for c, (p, recs) in zip(s.cases, records, strict=True)
    ]
    summary: dict[str, Any] = {"bearings": [{}, {}]}
    for _, q, k in _entries(s):
        sp = s.spread(q.key, k)
        assert sp is not None
        (summary if k is None else summary["bearings"][k - 1])[q.key] = asdict(sp)
    model = f"{PAIR_MODEL}, both cages at the cage angle{model_end(s.model, s.speed is not None)}"
    return pairs_document(records, rows, "cage_angle", model, s.warnings, len(s.cases), summary)
