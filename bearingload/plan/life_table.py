"""The plan of ``table life``: one bearing's lives against its radial clearance, or a pair's
against its preload, each row solved as :func:`bearingload.plan.solve.solve_case` solves that
case (the ball dynamics at a speed unless quasi-static), with the rows' service lives."""

from __future__ import annotations

from typing import Any

from bearingload.errors import ConvergenceError, InputError
from bearingload.plan.bearing import pair_bearing, resolve_bearings, with_ratings
from bearingload.plan.case import SERVICE_PARAMS, Case
from bearingload.plan.solve import (
    STATIC_AT_ANY_SPEED,
    pair_speed_hint,
    service_lives,
    with_solver_findings,
    with_speed_warnings,
)

#: What a row the ball dynamics cannot solve can do.
QUASI_STATIC_WAY = "'quasi_static' gives the static model (the ball dynamics left out)"


def life_against_clearance_case(
    case: Case, clearances: list[float] | None, spell: Any = str
) -> tuple[Any, list[Any] | None]:
    """(the :class:`~bearingload.studies.life_clearance.LifeAgainstClearance` of the case's
    bearing over ``clearances`` [mm] (None: the default rows), its rows' service lives or None
    without a life input)."""
    from bearingload.studies.life_clearance import life_against_clearance

    b = with_ratings(resolve_bearings(case, case.stiffness_value()), case)[0]
    dynamics = case.dynamics_arguments() if b.kind == "ball" else {}  # ball dynamics at speed
    try:
        result = life_against_clearance(
            b,
            case.radial_load,
            clearances=clearances,
            cage_angle=case.cage_angle_deg(b.balls),
            **case.combined_arguments(),
            **dynamics,
        )
    except InputError as exc:
        raise _row_error(exc, dynamics.get("speed") is not None, clearances is not None) from exc
    except ConvergenceError as exc:
        if dynamics.get("speed") is None:
            raise
        raise exc.with_way_out(QUASI_STATIC_WAY) from exc
    result = with_solver_findings(result, result, case.axial_load or 0.0, case.radial_load)
    (result,) = with_speed_warnings([result], case.speed)
    return result, _service(case, result, spell)


def _row_error(exc: InputError, dynamics: bool, rows_given: bool) -> InputError:
    """The refusal of a row: a bad clearance of the rows given names them (``clearances``); the loads too
    small for the combined solver name no radial solver (table life has none: the static rows
    are the combined solver's too); a speed the ball dynamics refuse names quasi-static."""
    from bearingload.models.combined import TOO_LIGHT
    from bearingload.models.high_speed import too_fast

    if exc.parameter == "clearance" and rows_given:
        return exc.named("clearances")
    if exc.reason == TOO_LIGHT:
        return exc.with_way_out(
            "table life solves every row by it, at any speed; 'bearingload solve' without an "
            "axial load (at a speed with 'quasi_static') takes any load"
        )
    if dynamics and too_fast(exc):
        return exc.with_way_out(STATIC_AT_ANY_SPEED)
    return exc


def _service(case: Case, t: Any, spell: Any) -> list[Any] | None:
    """The lives of every row of a life-against-clearance table (the heaviest ball at its
    contact angle for the film, as solve takes it)."""
    from bearingload.bearings.service_life import LifeBasis
    from bearingload.studies.life_basis import life_geometry

    if all(getattr(case, n) is None for n in SERVICE_PARAMS):
        return None  # C_0 feeds no column of this table (no s0): only with a life option
    bases = [
        LifeBasis(
            C=t.dynamic_rating,
            equivalent_load=t.equivalent_load,
            rating_life=t.rating_life,
            reference_rating_life=float(t.reference_rating_life[i]),
            q_max=float(t.q_max[i]),
            contact_angle=float(t.heaviest_contact_angle[i]),
            **life_geometry(t.bearing),
        )
        for i in range(t.clearance.size)
    ]
    return service_lives(case, bases, spell)


def life_against_preload_case(case: Case, preloads: list[float]) -> Any:
    """The :class:`~bearingload.studies.pair_life.LifeAgainstPreload` of the case's pair over
    ``preloads`` [N], each row as solve solves the pair at that preload."""
    from bearingload.models.pair_speed import TOO_LIGHT_PAIR
    from bearingload.studies.pair_life import life_against_preload

    tilt = "the shaft's tilt follows from the loads; give 'moment'"
    case.refuse(("misalignment",), "a bearing pair", tilt)
    fixed = "the design contact angle fixes the geometry of an angular-contact bearing"
    case.refuse(("clearance",), "a bearing pair", fixed + " (no clearance)")
    lives = tuple(p for p in SERVICE_PARAMS if p != "speed")  # speed: the hours, the dynamics
    case.refuse(
        lives,
        "table life of a pair",
        "its service lives beyond the hours are not yet tabulated; 'bearingload solve 7205BDB "
        "--preload ...' gives them for one preload",
    )
    negative = [p for p in preloads if not p >= 0]
    if negative:
        raise InputError("preloads", f"each must be 0 N or more (got {negative[0]:g} N)")
    b = pair_bearing(case)
    args = case.pair_arguments(b.balls)
    del args["preload"]
    dynamics = case.dynamics_arguments()
    try:
        result = life_against_preload(
            b, case.radial_load, case.axial_load or 0.0, preloads=preloads, **args, **dynamics
        )
    except (ConvergenceError, InputError) as exc:
        # at speed: unbalanced, or too light for the ball dynamics, in solve's words
        hinted = pair_speed_hint(exc) if dynamics["speed"] is not None else None
        if hinted is not None:
            raise hinted from exc
        if (
            isinstance(exc, InputError)
            and exc.parameter == "preload"
            and exc.reason != TOO_LIGHT_PAIR
        ):
            raise exc.named("preloads") from exc
        raise
    return with_speed_warnings([result], case.speed)[0]  # the bearing's limiting speeds
