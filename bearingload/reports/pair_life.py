"""The report of ``table life`` of a bearing pair (``table life 7205BDB --preloads ...``): one
row per preload in every format, as docs/angular_contact.md ("table life") describes it.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from bearingload.reports.pair import (
    PAIR_ANSWERS,
    PAIR_MODEL,
    PAIR_SERVICE,
    model_end,
    pair_records,
    pairs_csv,
    pairs_document,
    with_matrices,
)
from bearingload.reports.quantities import column
from bearingload.reports.render import Table, render
from bearingload.studies.bearing_pair import ARRANGEMENT_NAMES, PairLives
from bearingload.studies.pair_life import LifeAgainstPreload

#: The columns of the human table: (key, bearing or None, header).
PRELOAD_KEYS = (
    ("preload", None, "F_p"), ("preload_at_speed", None, "F_p at n"), ("q_max", 1, "Q_max 1"), ("q_max", 2, "Q_max 2"),
    ("loaded_balls", 1, "n 1"), ("loaded_balls", 2, "n 2"), ("stiffness_axial", None, "k_a"),
    ("stiffness_radial", None, "k_r"), ("lift_off_axial_load", None, "lift-off"),
    ("reference_rating_life", None, "L10r"), ("rating_life", None, "L10 ISO 281"),
    ("reference_rating_life_hours", None, "L10rh"),
)  # fmt: skip
#: The note of the rows solved with the ball dynamics (the model's name and density filled in).
DYNAMICS_NOTE = (
    "Speed: {} in both bearings (Jones 1960; Harris & Kotzalas; docs/speed.md), balls of {:.6g} "
    "kg/m^3: every row as 'bearingload solve --preload F_p --speed' solves it; Q_max k and n k: "
    "the inner contacts'; each bearing's L10r takes the inner loads for the inner ring, the "
    "outer loads for the outer ring; lift-off: at rest."
)


def preload_life_report(
    t: LifeAgainstPreload, fmt: str, lives: Sequence[PairLives], speed: float | None = None
) -> str:
    """Render ``t`` in ``fmt`` (table, markdown, csv, json): one row per preload, ``lives`` its
    service values as the plan gives them (:class:`bearingload.studies.bearing_pair.
    PairLives`); ``speed`` [rpm]: the shaft speed of the lives in hours (solve's with
    ``--speed`` alone; the rows were
    solved with the ball dynamics where ``t.model`` says so)."""
    records = [pair_records(c, life) for c, life in zip(t.cases, lives, strict=True)]
    if fmt == "csv":
        return render([pairs_csv("life against the preload", t.cases, records)], "csv")
    if fmt == "json":
        return render([], "json", document=_json(t, records, speed))
    at_speed = ("reference_rating_life_hours", "preload_at_speed")  # columns at a speed only
    keys = [(k, b, h) for k, b, h in PRELOAD_KEYS if k not in at_speed or k in records[0][0]]
    columns = [column(k, header=h, name=f"{k}{b or ''}", shown=True) for k, b, h in keys]
    rows = []
    for pair, recs in records:
        got = {f"{k}{b or ''}": recs[b - 1].get(k) if b else pair.get(k) for k, b, _ in keys}
        rows.append({name: "-" if v is None else v for name, v in got.items()})
    notes = _notes(t, records) + _speed_notes(t, records, speed)
    return render([Table(_title(records[0][0], t), columns, rows, notes)], fmt)


def _title(p: dict[str, Any], t: LifeAgainstPreload) -> str:
    who = f"bearings {p['bearing']}, " if p["bearing"] != "given by hand" else ""
    return (
        f"Life against the preload: {who}pair {p['arrangement']} "
        f"({ARRANGEMENT_NAMES[p['arrangement']]}), z = {t.bearing.balls} per bearing, F_r = "
        f"{p['load']:.6g} N, F_a = {p['axial_load']:.6g} N, {p['rotating']} ring rotating"
    )


def _notes(t: LifeAgainstPreload, records: list[Any]) -> list[str]:
    """The note under the table: what the rows are, and the preload of the longest L10r."""
    at_n = ("; F_p at n: the same at the speed, with the ball dynamics"
            if "preload_at_speed" in records[0][0] else "")  # fmt: skip
    notes = [
        f"F_p: the axial force each bearing carries with no external load (solve --preload), "
        f"ground in at rest{at_n}; Q_max k, n k: bearing k's heaviest ball load and loaded "
        "balls; k_a, k_r: the pair's axial and radial stiffness; lift-off: the axial load alone that unloads a bearing; "
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


def _speed_notes(t: LifeAgainstPreload, records: list[Any], speed: float | None) -> list[str]:
    """The note naming the model at a speed: the ball dynamics, or the static model
    (--quasi-static); none without a speed."""
    from bearingload.reports.pair import HOURS_NOTE

    if t.model is not None:
        density = records[0][1][0].get("ball_density")
        return [DYNAMICS_NOTE.format(t.model, density)]
    return [] if speed is None else [HOURS_NOTE]


def _json(t: LifeAgainstPreload, records: list[Any], speed: float | None) -> dict[str, Any]:
    rows = []
    for c, (pair, recs) in zip(t.cases, records, strict=True):
        answers = {k: pair[k] for k in ("preload", *PAIR_ANSWERS)}
        service = {k: v for k, v in pair.items() if k in PAIR_SERVICE}  # solve's, at a speed
        rows.append(with_matrices(c, answers | service | {"bearings": recs}))
    model = PAIR_MODEL + model_end(t.model, speed is not None)
    return pairs_document(records, rows, "preload", model, t.warnings)
