"""The rows of a file of bearing pairs (a column ``arrangement``, ``preload`` or ``width``: the
options of ``solve 7205BDB --preload 500N`` ...).

Each row is a pair of two identical angular-contact ball bearings (docs/angular_contact.md): its
``bearing`` names one bearing (``7205B`` with an ``arrangement`` cell) or the pair
(``7205BDB``, the arrangement cell blank or the same), or its ``contact_angle`` and ball set
give the ring by hand. Rows of one bearing, arrangement, width, rotating ring, C_r and lever
of the tilt, with or without a moment, are one call of
:func:`bearingload.models.pair.solve_pair` on arrays (their loads, preloads, moments and cage
angles), through :func:`bearingload.studies.bearing_pair.solve_bearing_pairs`, each case solved
on its own; each row then writes solve's csv rows of the pair (one per bearing, ``bearing_number``
1 and 2; :func:`bearingload.reports.pair.csv_rows`). A failing call is split in halves until the
failing row stands alone, named; the others are written.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from bearingload.batch.read import SERVICE_COLUMNS, row_message
from bearingload.batch.solve import (
    BatchSolver,
    Chunk,
    cage_angles,
    check_load,
    row_case,
    taken,
    with_oil_viscosity,
)
from bearingload.errors import BearingloadError, ConvergenceError, InputError

#: Rows times balls solved per pair call (about as many contacts as a combined call).
CALL_BALLS = 2**14


class PairSolver(BatchSolver):
    """Solve the blocks of a file of pairs: read as every file is, each row a pair, two output
    rows per pair."""

    def _solved(self, cols: dict[str, list[Any]], numbers: list[int], errors: dict[int, str],
                bad: dict[int, str]) -> Chunk:  # fmt: skip
        from bearingload.bearings.oil import OIL_INPUTS

        with_oil_viscosity(cols, [i for i in range(len(numbers)) if i not in bad], bad)
        solved = solve_pairs(self, cols, len(numbers), bad)
        out = Chunk()
        keys = [c.key for c in pair_columns(None)] + [k for k in OIL_INPUTS if k in cols]
        out.rows, out.values = pair_values(keys, solved, numbers, cols, bad)
        errors |= {numbers[i]: message for i, message in bad.items()}
        out.errors = sorted(errors.items())
        return out


def pair_columns(service: set[str] | None) -> list[Any]:
    """The output columns of a file of pairs: ``row``, then those ``solve 7205BDB --format
    csv`` writes with the service options the file's columns give (``service``: the service
    keys they make, :func:`bearingload.batch.report.batch_columns`; None: every one), the
    pair's as ``pair_...`` (the pair's cross moment in ``pair_moment_cross``; a bearing's
    record has no ``moment_cross``)."""
    from bearingload.bearings.mounting import RESULT_KEYS
    from bearingload.reports.pair import OWN_KEYS, PAIR_SERVICE, csv_columns
    from bearingload.reports.quantities import SERVICE_KEYS
    from bearingload.reports.solve import column

    unused = {*SERVICE_KEYS, "ball_density", "rating_life_hours", "reference_rating_life_hours"}
    # a pair takes no mounting (bearings.mounting refuses it): no operating clearance
    unused = {"moment_cross", *RESULT_KEYS} | (set() if service is None else unused - service)
    pair = [k for k in PAIR_SERVICE if service is None or k in service]
    return [column("row"), *csv_columns(pair, [k for k in OWN_KEYS if k not in unused])]


def pair_key(solver: Any, v: dict[str, Any]) -> tuple[Any, ...]:
    """The group of a row of cells ``v`` (blank cells left out): (resolved bearing,
    arrangement, width, rotating ring, C_r, a moment given, the tilt radius, the ball
    dynamics), planned once for the rows of the same plan; its load and bare numbers checked."""
    b, *key = solver.planned(v, _pair_plan)
    check_load(v)
    tilted = "moment" in v or bool(v.get("moment_cross"))
    return (b, *key[:4], tilted, *key[4:])


def _pair_plan(v: dict[str, Any]) -> tuple[Any, ...]:
    """The group of a row of cells ``v`` but whether a moment is given, by the plan's rules for
    a pair (:func:`~bearingload.plan.solve.engine_of`, :func:`~bearingload.plan.bearing.
    pair_bearing`)."""
    from bearingload.plan.bearing import check_rotating, pair_bearing
    from bearingload.plan.inputs import READERS
    from bearingload.plan.solve import engine_of

    if "arrangement" in v:
        v = v | {"arrangement": READERS["arrangement"](v["arrangement"], "arrangement")}
    pair, engine, _ = engine_of(row_case(v))
    if engine != "pair":
        raise InputError("arrangement", "missing: a file of pairs gives each row's arrangement "
                         "(DB, DF or DT) or a designation with it (7205BDB)")  # fmt: skip
    if pair.by_hand:
        raise InputError("bearing", "missing: a pair needs a bearing or its ball geometry")
    b = pair_bearing(pair)
    check_rotating(pair, b, ["exact"])
    dynamics = pair.dynamics_arguments()["speed"] is not None, pair.ball_density is not None
    rotating = pair.rotating or "inner"
    return (
        b,
        pair.arrangement,
        pair.width,
        rotating,
        pair.dynamic_rating,
        pair.tilt_radius,
        dynamics,
    )


def row_preload(v: dict[str, Any], b: Any) -> float:
    """The preload F_p [N] of a row of cells ``v`` (blank cells left out) of a pair of ``b``:
    its ``preload`` cell (a force, or a class resolved by
    :func:`bearingload.bearings.preload.resolve_preload`), the class its designation carries
    (7205CDBL), else 0."""
    from bearingload.bearings.preload import resolve_preload
    from bearingload.plan.case import pair_of

    value = pair_of(v.get("bearing"), None, v.get("preload"))[2]
    return 0.0 if value is None else resolve_preload(value, b).force


def solve_pairs(solver: Any, cols: dict[str, list[Any]], n: int,
                bad: dict[int, str]) -> list[tuple[int, Any]]:  # fmt: skip
    """Each good row's solved pair (row index, :class:`~bearingload.studies.bearing_pair.
    PairCase`), in input order; a row that cannot be solved goes to ``bad``."""
    groups: dict[tuple[Any, ...], list[int]] = {}
    for i in range(n):
        if i in bad:
            continue
        try:
            row = {k: c[i] for k, c in cols.items() if c[i] is not None}
            key = pair_key(solver, row)
            solver.refuse_bare(row, i, key[0])
            preload = row_preload(row, key[0])
        except BearingloadError as exc:
            bad[i] = row_message(exc)
            continue
        cols.setdefault("preload", [None] * n)[i] = preload  # a class: its table's force
        groups.setdefault(key, []).append(i)
    solved: list[tuple[int, Any]] = []
    for key, idx in groups.items():
        size = max(1, CALL_BALLS // int(key[0].balls))
        for start in range(0, len(idx), size):
            solved += _split(key, idx[start : start + size], cols, bad)
    return sorted(solved, key=lambda s: s[0])


def _split(key: tuple[Any, ...], idx: list[int], cols: dict[str, list[Any]],
           bad: dict[int, str]) -> list[tuple[int, Any]]:  # fmt: skip
    """The rows ``idx`` of one group in one call; if that fails, each half on its own."""
    try:
        with np.errstate(all="ignore"):
            return list(zip(idx, _call(key, idx, cols), strict=True))
    except (BearingloadError, ValueError, ArithmeticError) as exc:
        if len(idx) == 1:
            bad[idx[0]] = row_message(exc)
            return []
    half = len(idx) // 2
    return _split(key, idx[:half], cols, bad) + _split(key, idx[half:], cols, bad)


def _call(key: tuple[Any, ...], idx: list[int], cols: dict[str, list[Any]]) -> list[Any]:
    """One vectorised pair solve of the rows ``idx`` of the group ``key``."""
    from bearingload.studies.bearing_pair import solve_bearing_pairs

    b, arrangement, width, rotating, c_r, tilted, lever, (at_speed, density) = key
    moment = np.array(taken(cols, "moment", idx, 0.0), dtype=float)
    dynamics: dict[str, Any] = {"speed": None, "ball_density": None}
    if at_speed:  # the ball dynamics of both bearings (ball_density as --ball-density, kg/m^3)
        dynamics["speed"] = np.array(taken(cols, "speed", idx), dtype=float)
        if density:
            dynamics["ball_density"] = np.array(taken(cols, "ball_density", idx), float)
    try:
        return solve_bearing_pairs(
            b, np.array(taken(cols, "load", idx), dtype=float),
            np.array(taken(cols, "axial_load", idx, 0.0), dtype=float), arrangement=arrangement,
            preload=np.array(taken(cols, "preload", idx, 0.0), dtype=float), width=width,
            cage_angle=cage_angles(taken(cols, "cage_angle", idx, 0.0), b.balls),
            moment=moment if tilted else None,
            moment_cross=np.array(taken(cols, "moment_cross", idx, 0.0), dtype=float),
            tilt_radius=lever, rotating=rotating, dynamic_rating=c_r, **dynamics,
        )  # fmt: skip
    except (InputError, ConvergenceError) as exc:
        from bearingload.plan.solve import pair_speed_hint

        hinted = pair_speed_hint(exc) if at_speed else None
        if hinted is None:
            raise
        raise hinted from exc


def pair_values(
    keys: list[str],
    solved: list[tuple[int, Any]],
    numbers: list[int],
    cols: dict[str, list[Any]],
    bad: dict[int, str],
) -> tuple[list[int], dict[str, list[Any]]]:
    """The output rows of the solved pairs (two per pair: its row number twice) and the values
    of the columns ``keys`` over them (None: blank), as solve gives the pair with the row's
    service cells as its options (the plan's :func:`~bearingload.plan.solve.with_speed_warnings`
    and :func:`~bearingload.plan.solve.service_lives`: each bearing's lives from its own loads,
    the pair's from them); ``warnings`` (the pair's, its speed's and its lives') on the first
    row of each pair; each bearing's model and contacts (json:
    :data:`bearingload.batch.report.HELD_KEYS`), as a combined file's rows. A row whose lives
    solve would refuse (a speed so small that its life in hours overflows) goes to ``bad`` with
    its reason, the others are written."""
    from bearingload.bearings.oil import OIL_INPUTS
    from bearingload.plan.solve import service_lives, with_speed_warnings
    from bearingload.reports.combined import contact_values
    from bearingload.reports.pair import csv_rows, pair_records
    from bearingload.reports.solve import printed_warnings
    from bearingload.studies.life_basis import combined_basis

    keys = [k for k in keys if k != "row"]
    oil = [k for k in keys if k in OIL_INPUTS]  # written as given (the viscosity is nu's)
    service_cells = [c for c in SERVICE_COLUMNS if c in cols and c not in OIL_INPUTS]
    rows: list[int] = []
    values: dict[str, list[Any]] = {k: [] for k in [*keys, "warnings"]}
    for i, pc in solved:
        case = row_case({c: cols[c][i] for c in service_cells if cols[c][i] is not None})
        pc = with_speed_warnings([pc], case.speed)[0]
        try:
            service = service_lives(case, [combined_basis(c) for c in pc.bearings])
            pair, records = pair_records(pc, service)
        except BearingloadError as exc:
            bad[i] = row_message(exc)
            continue
        for j, out in enumerate(csv_rows(pc, pair, records, keys)):
            rows.append(numbers[i])
            for k in keys:
                values[k].append(cols[k][i] if k in oil else out[k])
            said = printed_warnings(pc.warnings, service) if j == 0 else ()
            values["warnings"].append(tuple(said))
            held = contact_values(pc.bearings[j].result, pc.bearing.contact_angle)
            for k, v in held.items():
                values.setdefault(k, []).append(v)
    return rows, values
