"""The plan of a sweep over one ball pitch of cage positions: the engine the case's inputs
choose (the radial ring, the combined 3-D load, a pair; the ball dynamics at a speed, as
:func:`bearingload.plan.solve.solve_case` chooses it), its refusals and the lives and warnings
of every position."""

from __future__ import annotations

import dataclasses
from typing import Any

from bearingload.errors import ConvergenceError, InputError
from bearingload.plan.bearing import (
    bearing_context,
    check_rotating,
    pair_bearing,
    refuse_tilt_radius,
    resolve_bearings,
    resolve_case,
    with_ratings,
)
from bearingload.plan.case import Case
from bearingload.plan.solve import (
    QUASI_STATIC_WAY,
    STATIC_PAIR_WAY,
    in_case_terms,
    pair_speed_hint,
    radial_at_speed,
    refuse_pair_options,
    refuse_static_dynamics,
    speed_hint,
    speed_pair_lives,
    speed_warnings,
    with_solver_findings,
)


@dataclasses.dataclass(frozen=True)
class Swept:
    """A solved sweep: ``engine`` (radial, combined, pair), the study's ``result``, the note
    naming where z, K and G_r come from (``context``), the bearing's designation and, for a
    pair, the service values of each position (:class:`bearingload.studies.bearing_pair.
    PairLives`)."""

    engine: str
    result: Any
    context: str
    designation: str | None = None
    lives: tuple[Any, ...] = ()


def sweep_case(case: Case, steps: int) -> Swept:
    """Sweep the case over one ball pitch by the engine its inputs choose; a failure names the
    inputs as the case does (:func:`bearingload.plan.solve.in_case_terms`)."""
    try:
        return _swept(case, steps)
    except ConvergenceError as exc:
        raise in_case_terms(exc, case, cage_given=False) from exc


def _swept(case: Case, steps: int) -> Swept:
    case.check_load(radial=not case.wants_combined, combined=case.takes_combined)
    pair = case.as_pair()
    if pair is not None:
        return _pair(pair, steps)
    refuse_static_dynamics(case)
    case, radial = radial_at_speed(case)  # a radial ball bearing at speed: F_a = 0, dynamics
    if case.wants_combined:  # the load alone chooses the engine, never a life option
        return _combined(case, steps, radial)
    from bearingload.studies.sweep import sweep

    refuse_tilt_radius(case)
    z, k, g_r, m, context = resolve_case(case)
    life, lives = _radial_lives(case) if case.lives_given else (None, {})
    result = sweep(z, case.radial_load, k, g_r, m, steps, life=life)
    result = dataclasses.replace(result, **lives)
    if not case.by_hand:  # solve's checks on the bearing, as solve makes them
        result = dataclasses.replace(result, warnings=_bearing_checks(case, result))
    return Swept("radial", result, context, case.bearing)


def _bearing_checks(case: Case, result: Any) -> tuple[str, ...]:
    """The warnings solve gives on the bearing of the case (s0, C0, contact pressure, clearance),
    at the heaviest ball load of the sweep ``result``, and on a speed above its limiting speed;
    then the sweep's own (one loaded ball)."""
    from bearingload.studies.sweep import bearing_checks

    b = with_ratings(resolve_bearings(case, case.stiffness_value()), case)[0]
    return speed_warnings(bearing_checks(b, result), case.speed, b) + result.warnings


def _radial_lives(case: Case) -> tuple[Any, dict[str, Any]]:
    """The lives of a radial sweep (a dynamic rating, a rotating ring or a speed given, no load
    beyond the radial one): L10r at each cage position from the radial engine's ball loads,
    every ball at the contact angle 0, as solve's radial path gives it; ISO 281's L10 where C_r
    is known; hours with a speed. (the ``life`` of the sweep, the fields of its result)"""
    import functools

    from bearingload.bearings.life import BALL_LIFE_EXPONENT, ROLLER_LIFE_EXPONENT
    from bearingload.studies.reference_life import ball_reference_life, has_reference_life

    b = with_ratings(resolve_bearings(case, case.stiffness_value()), case)[0]
    check_rotating(case, b, ["exact"])
    c_r = case.dynamic_rating or b.C or None
    rotating = case.rotating or "inner"
    life = None
    if c_r is not None and has_reference_life(b, c_r):
        life = functools.partial(ball_reference_life, b, rotating=rotating, c_r=float(c_r))
    exponent = ROLLER_LIFE_EXPONENT if b.kind == "roller" else BALL_LIFE_EXPONENT
    return life, {
        "dynamic_rating": None if c_r is None else float(c_r),
        "life_exponent": exponent,
        "rotating": None if life is None else rotating,
        "speed": case.speed,
    }


def _combined(case: Case, steps: int, radial: bool) -> Swept:
    """The sweep under a combined load: one vectorised 3-D solve over the pitch (at a speed the
    ball dynamics, unless quasi-static; ``radial``: a radial case at speed, F_a = 0 set)."""
    from bearingload.studies.combined_sweep import combined_sweep

    b = with_ratings(resolve_bearings(case, case.stiffness_value()), case)[0]
    dynamics = case.dynamics_arguments()
    try:
        result = combined_sweep(
            b, case.radial_load, steps=steps, **case.combined_arguments(), **dynamics
        )
    except InputError as exc:
        hinted = speed_hint(exc, radial) if dynamics["speed"] is not None else None
        if hinted is None:
            raise
        raise hinted from exc
    except ConvergenceError as exc:
        if dynamics["speed"] is None:
            raise
        raise exc.with_way_out(QUASI_STATIC_WAY if radial else STATIC_PAIR_WAY) from exc
    result = with_solver_findings(result, result.result, case.axial_load or 0.0, case.radial_load)
    if case.speed is not None:  # the hours (and the dynamics' speed); the limiting speed
        found = speed_warnings(result.warnings, case.speed, b)
        result = dataclasses.replace(result, speed=case.speed, warnings=found)
    return Swept("combined", result, bearing_context(b), b.designation)


def _pair(case: Case, steps: int) -> Swept:
    """The sweep of a bearing pair (7205BDB, an arrangement): one vectorised pair solve over
    the pitch."""
    from bearingload.studies.pair_sweep import pair_sweep

    refuse_pair_options(case, "exact", None)  # a misalignment, a clearance
    b = pair_bearing(case)
    args = case.pair_arguments(b.balls)
    del args["cage_angle"]
    dynamics = case.dynamics_arguments()  # at a speed both bearings' ball dynamics
    try:
        result = pair_sweep(
            b, case.radial_load, case.axial_load or 0.0, steps=steps, **args, **dynamics
        )
    except (ConvergenceError, InputError) as exc:
        hinted = pair_speed_hint(exc) if dynamics["speed"] is not None else None
        if hinted is None:
            raise
        raise hinted from exc
    if case.speed is not None:  # the lives in hours (and the dynamics' speed); the limit
        found = speed_warnings(result.warnings, case.speed, b)
        result = dataclasses.replace(result, speed=case.speed, warnings=found)
    lives = speed_pair_lives(result.cases, case.speed)
    return Swept("pair", result, bearing_context(b), b.designation, lives)
