"""Many bearing pairs at once (cases with an ``arrangement``, ``preload`` or ``width``: the
inputs of ``solve 7205BDB --preload 500N`` ...), each planned as :func:`bearingload.plan.solve.
solve_case` plans one pair.

Each case is a pair of two identical angular-contact ball bearings (docs/angular_contact.md):
its ``bearing`` names one bearing (``7205B`` with an ``arrangement``) or the pair (``7205BDB``),
or its ``contact_angle`` and ball set give the ring by hand. Cases of one bearing, arrangement,
width, rotating ring, C_r and lever of the tilt, with or without a moment, are one call of
:func:`bearingload.studies.bearing_pair.solve_bearing_pairs` on arrays (their loads, preloads,
moments and cage angles), each case solved on its own; each pair's lives then as one pair's
(:func:`bearingload.plan.solve.service_lives`).
"""

from __future__ import annotations

from functools import partial
from typing import Any

from bearingload.errors import BearingloadError, ConvergenceError, InputError
from bearingload.plan.many import (
    Many,
    cage_angles,
    case_of,
    check_load,
    floats,
    split,
    taken,
    with_oil_viscosity,
)

#: Cases times balls solved per pair call (about as many contacts as a combined call).
CALL_BALLS = 2**14


def solve_pair_cases(
    planner: Any,
    cols: dict[str, list[Any]],
    n: int,
    bad: dict[int, Any],
    bare: dict[str, list[bool]] | None = None,
) -> Many:
    """The ``n`` pairs of ``cols`` but those in ``bad``: ``rows`` the pairs solved, ``values``
    ``pair`` (:class:`~bearingload.studies.bearing_pair.PairCase`, the limiting speed's
    warnings added) and ``lives`` (:class:`~bearingload.studies.bearing_pair.PairLives`) over
    them."""
    planner.bare = planner.bare if bare is None else bare
    with_oil_viscosity(cols, [i for i in range(n) if i not in bad], bad)
    groups: dict[tuple[Any, ...], list[int]] = {}
    for i in range(n):
        if i in bad:
            continue
        try:
            row = {k: c[i] for k, c in cols.items() if c[i] is not None}
            key = _pair_key(planner, row)
            planner.refuse_bare(row, i, key[0])
            preload = _preload(row, key[0])
        except BearingloadError as exc:
            bad[i] = exc
            continue
        cols.setdefault("preload", [None] * n)[i] = preload  # a class: its table's force
        groups.setdefault(key, []).append(i)
    solved: list[tuple[int, Any]] = []
    for key, idx in groups.items():
        size = max(1, CALL_BALLS // int(key[0].balls))
        for start in range(0, len(idx), size):
            for part, pcs in split(_call, key, idx[start : start + size], cols, bad):
                solved += zip(part, pcs, strict=True)
    out = Many()
    for i, pc in sorted(solved, key=lambda s: s[0]):
        try:
            pc, lives = _lives(pc, cols, i)
        except BearingloadError as exc:
            bad[i] = exc
            continue
        out.rows.append(i)
        out.values.setdefault("pair", []).append(pc)
        out.values.setdefault("lives", []).append(lives)
    out.errors = dict(bad)
    return out


def _lives(pc: Any, cols: dict[str, list[Any]], i: int) -> tuple[Any, Any]:
    """The pair with its limiting speed's warnings, and its lives: each bearing's from its own
    loads and the pair's from them, as solve gives them for the pair
    (:class:`bearingload.studies.bearing_pair.PairLives`)."""
    from bearingload.bearings.oil import OIL_INPUTS
    from bearingload.plan.many_lives import SERVICE
    from bearingload.plan.solve import service_lives, with_speed_warnings
    from bearingload.studies.bearing_pair import pair_lives
    from bearingload.studies.life_basis import combined_basis

    given = [c for c in SERVICE if c in cols and c not in OIL_INPUTS]
    case = case_of({c: cols[c][i] for c in given if cols[c][i] is not None})
    pc = with_speed_warnings([pc], case.speed)[0]
    return pc, pair_lives(pc, service_lives(case, [combined_basis(c) for c in pc.bearings]))


def _pair_key(planner: Any, v: dict[str, Any]) -> tuple[Any, ...]:
    """The group of a case of inputs ``v``: (resolved bearing, arrangement, width, rotating
    ring, C_r, a moment given, the tilt radius, the ball dynamics), planned once for the cases
    of the same plan; its load checked."""
    b, *key = planner.planned(v, partial(_pair_plan, per_case=planner.per_case))
    if not planner.per_case:
        check_load(v)
    tilted = "moment" in v or bool(v.get("moment_cross"))
    return (b, *key[:4], tilted, *key[4:])


def _pair_plan(v: dict[str, Any], per_case: bool = False) -> tuple[Any, ...]:
    """The group of a case of inputs ``v`` but whether a moment is given, by the plan's rules
    for a pair (:func:`~bearingload.plan.solve.engine_of`, :func:`~bearingload.plan.bearing.
    pair_bearing`); a ``per_case`` case's (the library's) options of a single bearing refused
    as solve refuses them (:func:`~bearingload.plan.solve.refuse_pair_options`; a file of
    pairs has no column of them)."""
    from bearingload.plan.bearing import check_rotating, pair_bearing
    from bearingload.plan.solve import engine_of, refuse_pair_options

    pair, engine, _ = engine_of(case_of(v))
    if per_case and engine == "pair":
        refuse_pair_options(pair, v.get("method", "exact"), v.get("revolutions"))
    if engine != "pair":
        raise InputError(
            "arrangement",
            "missing: a file of pairs gives each row's arrangement (DB, DF or DT) or a "
            "designation with it (7205BDB)",
        )
    if pair.by_hand:
        raise InputError("bearing", "missing: a pair needs a bearing or its ball geometry")
    b = pair_bearing(pair)
    check_rotating(pair, b, ["exact"])
    dynamics = pair.dynamics_arguments()["speed"] is not None, pair.ball_density is not None
    rotating = pair.rotating or "inner"
    tilt = pair.tilt_radius
    return (b, pair.arrangement, pair.width, rotating, pair.dynamic_rating, tilt, dynamics)


def _preload(v: dict[str, Any], b: Any) -> float:
    """The preload F_p [N] of a case of inputs ``v`` of a pair of ``b``: its ``preload`` (a
    force, or a class resolved by :func:`bearingload.bearings.preload.resolve_preload`), the
    class its designation carries (7205CDBL), else 0."""
    from bearingload.bearings.preload import resolve_preload
    from bearingload.plan.case import pair_of

    value = pair_of(v.get("bearing"), None, v.get("preload"))[2]
    return 0.0 if value is None else resolve_preload(value, b).force


def _call(key: tuple[Any, ...], idx: list[int], cols: dict[str, list[Any]]) -> list[Any]:
    """One vectorised pair solve of the cases ``idx`` of the group ``key``."""
    from bearingload.studies.bearing_pair import solve_bearing_pairs

    b, arrangement, width, rotating, c_r, tilted, lever, (at_speed, density) = key
    dynamics: dict[str, Any] = {"speed": None, "ball_density": None}
    if at_speed:  # the ball dynamics of both bearings (ball_density in kg/m^3)
        dynamics["speed"] = floats(cols, "speed", idx)
        if density:
            dynamics["ball_density"] = floats(cols, "ball_density", idx)
    try:
        return solve_bearing_pairs(
            b,
            floats(cols, "load", idx),
            floats(cols, "axial_load", idx, 0.0),
            arrangement=arrangement,
            preload=floats(cols, "preload", idx, 0.0),
            width=width,
            cage_angle=cage_angles(taken(cols, "cage_angle", idx, 0.0), b.balls),
            moment=floats(cols, "moment", idx, 0.0) if tilted else None,
            moment_cross=floats(cols, "moment_cross", idx, 0.0),
            tilt_radius=lever,
            rotating=rotating,
            dynamic_rating=c_r,
            **dynamics,
        )
    except (InputError, ConvergenceError) as exc:
        from bearingload.plan.solve import pair_speed_hint

        hinted = pair_speed_hint(exc) if at_speed else None
        if hinted is None:
            raise
        raise hinted from exc
