"""The plan of one case: which engine solves it, what it refuses, and the lives and warnings of
the answer, once for the library, the command line and batch.

:func:`solve_case` takes a :class:`~bearingload.plan.case.Case` and returns a
:class:`~bearingload.plan.solution.Solution`:

* a pair (``7205BDB``, or an arrangement given) is solved by the pair's shaft equilibrium, with
  the ball dynamics of both bearings at a speed (unless quasi-static);
* a load beyond the radial one (axial load, moment, misalignment, a contact angle given) or an
  angular-contact designation takes the combined engine; a radial case of a ball bearing at a
  speed too (the ball dynamics at F_a = 0), unless quasi-static;
* the rest, the radial engine (the exact ring equilibrium, or another method by name).

Every refusal is a typed error (:mod:`bearingload.errors`) naming the input by its library name;
where another engine would solve a refused case, its way out names the input that selects it.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from typing import Any

from bearingload.errors import ConflictError, ConvergenceError, InputError
from bearingload.plan.bearing import (
    check_rotating,
    pair_bearing,
    refuse_tilt_radius,
    refuse_unused,
    resolve_bearings,
    ring_by_hand,
    with_contact_angle,
    with_ratings,
)
from bearingload.plan.case import Case
from bearingload.plan.solution import Solution

#: The way out of a radial case at speed the ball dynamics cannot solve.
QUASI_STATIC_WAY = "'quasi_static' gives the static radial engine (the ball dynamics left out)"
#: The way out of a speed beyond the ball dynamics' limit (n d_m).
STATIC_AT_ANY_SPEED = "'quasi_static' gives the static model at any speed (the lives in hours)"
#: The way out of a pair at speed the ball dynamics cannot solve.
STATIC_PAIR_WAY = "'quasi_static' gives the static model"


def solve_case(
    case: Case,
    *,
    method: str = "exact",
    revolutions: float | None = None,
    spell: Any = str,
) -> Solution:
    """Solve one case by the engine its inputs choose, with its lives and warnings.

    Parameters
    ----------
    case : Case
        The inputs.
    method : str
        The radial engine's method (``exact``, ``continuum``, ``stribeck``, ``palmgren`` or
        ``all``); the combined engine, pairs and the ball dynamics are exact only.
    revolutions : float, optional
        Life L [rev] of the radial engine's allowable load C/(L/10^6)^(1/3); None: 36e6, and
        refused where no allowable load is computed only when given.
    spell : callable
        Writes the inputs a note names as the user typed them (the command line: its options).
    """
    from bearingload.models.registry import list_methods

    check_revolutions(revolutions)
    check_method(method)
    given = case
    case, engine, at_speed = engine_of(case, method, revolutions)
    case.check_load(radial=engine == "radial", combined=given.takes_combined)
    methods = list_methods() if method == "all" else [method]
    try:
        if engine == "pair":
            refuse_pair_options(case, method, revolutions)
            return _pair(case, spell)
        if engine == "combined":
            return _combined(case, method, revolutions, at_speed, spell)
        return _radial(case, methods, revolutions, spell)
    except ConvergenceError as exc:
        raise in_case_terms(exc, given) from exc


def check_method(method: Any) -> None:
    """Refuse a ``method`` that is neither a registered one nor ``all``."""
    from bearingload.models.registry import list_methods

    allowed = (*list_methods(), "all")
    if method not in allowed:
        raise InputError("method", f"unknown method {method!r}; allowed: {', '.join(allowed)}")


def in_case_terms(exc: ConvergenceError, case: Case, cage_given: bool = True) -> ConvergenceError:
    """The solver's ConvergenceError naming the inputs of its cases as the case names them:
    the library's argument names (``radial_load`` -> ``load``, :func:`bearingload.plan.inputs.
    argument_of`), those the user gave only (not the defaults the solver filled in), and, with
    ``cage_given``, the cage angle as given (``half``, or -10° that the solver reduced to
    350°; the solver's where it is the same angle: a -1e-320 it used as 0) where the cases
    were solved at that one cage angle (a sweep's cases
    are solved at other cage angles than its case's: ``cage_given`` False keeps the solver's).
    An input given with a unit is written as typed (``0.1kN``: ``0.1 kN``) where every failing
    case has its value (:func:`typed_of`)."""
    import numpy as np

    from bearingload.plan.inputs import argument_of

    named = {argument_of(k): v for k, v in exc.cases.items()}
    # the inputs the user gave, none the solver filled in; a sweep's cage angle where it failed
    kept = [k for k in named if k in case.given or (k == "cage_angle" and not cage_given)]
    cases = {k: named[k] for k in kept or named}
    units = {argument_of(k): u for k, u in (exc.units or {}).items() if argument_of(k) in cases}
    cage = np.asarray(cases.get("cage_angle", []), dtype=float).reshape(-1)
    own = case.cage_angle  # as given where it is another angle than the solver's (-10°: 350°)
    other = (
        own == "half" or isinstance(own, (int, float)) and cage.size and abs(own - cage[0]) > 1e-9
    )
    if cage_given and cage.size and np.all(cage == cage[0]) and other:
        cases["cage_angle"] = own
        if case.cage_angle == "half":
            units.pop("cage_angle", None)
    texts = typed_of(cases, case)
    return ConvergenceError(
        exc.solver, exc.iterations, exc.residual, cases, units, exc.way_out, texts or None
    )


def typed_of(cases: dict[str, Any], case: Case) -> dict[str, str]:
    """Of the inputs of failing ``cases`` (by argument name), the text the user gave each with
    a unit (``case.typed``) where every case has the value of that text (a sweep's other
    values keep their numbers)."""
    import numpy as np

    from bearingload.units import as_written

    texts = dict(case.typed)
    out = {}
    for name, values in cases.items():
        given = getattr(case, name, None)
        given = getattr(given, "length", given)  # a clearance: its length, or a class's None
        if name not in texts or not isinstance(given, (int, float)):
            continue
        if np.all(np.asarray(values, dtype=float) == float(given)):
            out[name] = as_written(texts[name])  # number, space, unit: 0.1 kN
    return out


def engine_of(
    case: Case, method: str = "exact", revolutions: float | None = None
) -> tuple[Case, str, bool]:
    """(the case as its engine solves it, the engine: ``"pair"``, ``"combined"`` or
    ``"radial"``, whether a radial case of a ball bearing is solved at its speed by the ball
    dynamics: the combined engine at F_a = 0, :func:`radial_at_speed`); such a case's method
    other than exact and life ``revolutions`` refused (:func:`refuse_radial_options`). The one
    engine choice of solve, the library and batch."""
    case, at_speed = radial_at_speed(case)
    if at_speed:
        refuse_radial_options(method, revolutions)
    pair = case.as_pair()
    if pair is not None:
        return pair, "pair", False
    return case, "combined" if case.wants_combined else "radial", at_speed


def check_revolutions(revolutions: float | None) -> None:
    """Refuse a life ``revolutions`` of the allowable load that is not a number > 0."""
    if revolutions is not None and not (math.isfinite(revolutions) and revolutions > 0):
        raise InputError("revolutions", f"must be a number of revolutions > 0, got {revolutions:g}")


def radial_at_speed(case: Case) -> tuple[Case, bool]:
    """(the case, True) with F_a = 0 given where a radial case of a ball bearing (a bearing or
    the ball geometry, not an angular-contact designation) has a speed and is not quasi-static:
    the combined engine then solves it with the ball dynamics (docs/speed.md); otherwise (the
    case, False): rollers, quasi-static, no speed, a pair."""
    from bearingload.bearings.designation import contact_exponent
    from bearingload.constants import ROLLER_EXPONENT

    if case.speed is None or case.quasi_static or case.wants_combined:
        return case, False
    if case.arrangement is not None or case.as_pair() is not None:
        return case, False  # a pair: its own path, the ball dynamics of both bearings
    if case.by_hand or contact_exponent(case.bearing) == ROLLER_EXPONENT:
        return case, False  # speed refused without the geometry; rollers: the radial engine
    given = case.given | {"axial_load"}
    return dataclasses.replace(case, axial_load=0.0, given=given), True


def refuse_radial_options(method: str, revolutions: float | None) -> None:
    """Refuse, for a radial case of a ball bearing at a speed (the ball dynamics, by the combined
    engine at F_a = 0), a method other than exact and a life ``revolutions`` of the allowable
    load, which only the static radial engine takes."""
    if method != "exact":
        raise InputError(
            "method",
            "at 'speed' the ball dynamics of a ball bearing are solved by the exact model only "
            "(the combined engine at F_a = 0)",
            way_out=f"give 'quasi_static' for the static model, where 'method' {method} is allowed",
        )
    refuse_revolutions(
        revolutions,
        "the ball dynamics at 'speed' (a ball bearing is solved by the combined engine at F_a = 0)",
        "give 'quasi_static' for the static radial engine",
    )


def refuse_revolutions(revolutions: float | None, where: str, instead: str) -> None:
    """Refuse a life ``revolutions`` given where no allowable load is computed."""
    if revolutions is not None:
        raise ConflictError(
            "revolutions",
            where,
            "it sets the life L of the allowable radial load C/(L/10^6)^(1/3), which only the "
            f"radial engine prints for a bearing with a dynamic load rating C; {instead}",
        )


def refuse_static_dynamics(case: Case) -> None:
    """A ball density and quasi-static on the radial engine: refused for a roller bearing (no
    ball dynamics) and without a speed, the ball density also when quasi-static."""
    from bearingload.bearings.designation import contact_exponent
    from bearingload.constants import ROLLER_EXPONENT

    if not case.by_hand and contact_exponent(case.bearing) == ROLLER_EXPONENT:
        case.refuse(
            ("ball_density",),
            f"a roller bearing ({case.bearing})",
            "the radial engine solves it by the static model at any speed: the ball dynamics at "
            "'speed' are coded for ball bearings",
        )
    case.check_dynamics_flags()


def _radial(case: Case, methods: list[str], revolutions: float | None, spell: Any) -> Solution:
    """The radial engine: a ring by hand, or the resolved bearings with their lives."""
    refuse_tilt_radius(case)
    refuse_static_dynamics(case)
    k_given = case.stiffness_value()
    service = None
    if case.by_hand:
        refuse_unused(case)
        refuse_revolutions(revolutions, "a ring given by its balls and stiffness", "it has no C")
        cases = _by_hand(methods, case, k_given)
    else:
        from bearingload.studies.life_basis import radial_basis
        from bearingload.studies.loaded_bearing import DEFAULT_REVOLUTIONS, solve_bearing
        from bearingload.studies.reference_life import with_reference_lives

        bearings = with_ratings(resolve_bearings(case, k_given), case)
        if case.dynamic_rating is not None:
            bearings = [b.with_dynamic_rating(case.dynamic_rating) for b in bearings]
        if not any(b.C for b in bearings):
            refuse_revolutions(
                revolutions, "a bearing without a dynamic load rating C", "give 'dynamic_rating'"
            )
        check_rotating(case, bearings[0], methods)
        angle = case.cage_angle_deg(bearings[0].balls)
        life = DEFAULT_REVOLUTIONS if revolutions is None else revolutions
        solved = solve_bearing(bearings, case.radial_load, angle, methods, life)
        solved = with_reference_lives(solved, case.rotating or "inner")
        cases = with_speed_warnings(solved, case.speed)
        service = service_lives(case, [radial_basis(c, case.rotating) for c in cases], spell)
    return Solution("radial", tuple(cases), None if service is None else tuple(service))


def _by_hand(methods: list[str], case: Case, k_given: float | None) -> list[Any]:
    """The radial engine on a ring given by z and K."""
    from bearingload.bearings.clearance import clearance_length
    from bearingload.studies.loaded_bearing import solve_ring

    z, k = ring_by_hand(case, k_given)
    angle = case.cage_angle_deg(z)
    g_r = clearance_length(case.clearance)
    return solve_ring(methods, z, case.radial_load, k, g_r, angle, case.exponent_or(1.5))


def _combined(
    case: Case, method: str, revolutions: float | None, at_speed: bool, spell: Any
) -> Solution:
    """The combined engine (a load beyond the radial one, an angular-contact bearing, or a
    radial ball bearing at speed) on the resolved bearings."""
    from bearingload.bearings.angular import parse_angular
    from bearingload.studies.combined_bearing import solve_combined_bearing
    from bearingload.studies.life_basis import combined_basis

    angular = case.bearing is not None and parse_angular(case.bearing) is not None
    refuse_revolutions(
        revolutions,
        "the combined engine (a load beyond the radial one, or an angular-contact bearing)",
        "it prints L10 = (C/P)^3 at P = X F_r + Y F_a and L10r instead",
    )
    if method != "exact":
        what = (
            f"an angular-contact bearing ({case.bearing})"
            if angular
            else "the combined load ('axial_load', 'moment', 'moment_cross', 'misalignment')"
        )
        raise InputError("method", f"{what} is solved by the exact model only")
    bearings = with_ratings(resolve_bearings(case, case.stiffness_value()), case)
    if bearings[0].kind == "ball" and bearings[0].has_geometry:
        check_rotating(case, bearings[0], ["exact"])
    bearings = with_contact_angle(bearings, case, "'contact_angle'")
    dynamics = case.dynamics_arguments()
    try:
        solved = solve_combined_bearing(
            bearings,
            case.radial_load,
            cage_angle=case.cage_angle_deg(bearings[0].balls),
            **case.combined_arguments(),
            **dynamics,
        )
    except InputError as exc:
        hinted = speed_hint(exc, at_speed) if dynamics["speed"] is not None else None
        if hinted is None:
            raise
        raise hinted from exc
    except ConvergenceError as exc:  # a radial case at speed: the static engine solves it
        if not at_speed:
            raise
        raise exc.with_way_out(QUASI_STATIC_WAY) from exc
    cases = with_speed_warnings(solved, case.speed)
    service = service_lives(case, [combined_basis(c) for c in cases], spell)
    return Solution("combined", tuple(cases), tuple(service))


def speed_hint(exc: InputError, radial: bool) -> InputError | None:
    """A refusal of the ball dynamics with the way to the static engine: a speed too high, or
    loads too light for the ball dynamics where the radial engine would take them (``radial``:
    F_a = 0 was set for a radial case, no axial load given)."""
    from bearingload.models.combined import TOO_LIGHT
    from bearingload.models.high_speed import too_fast

    if too_fast(exc):
        return exc.with_way_out(STATIC_AT_ANY_SPEED)
    if exc.reason != TOO_LIGHT:
        return None
    way = (
        "'quasi_static' gives the static radial engine, which takes any load"
        if radial
        else "'quasi_static' without an axial load gives the static radial engine, which takes "
        "any load"
    )
    return exc.with_way_out(
        f"at 'speed' a ball bearing is solved by the combined engine (the ball dynamics); {way}"
    )


def refuse_pair_options(case: Case, method: str, revolutions: float | None) -> None:
    """Refuse for a pair (``case``, as :func:`engine_of` gives it) what it does not take: a life
    of the allowable radial load, a method other than exact, a misalignment, a clearance."""
    refuse_revolutions(revolutions, "a bearing pair", "it prints L10r and L10 of the pair")
    if method != "exact":
        raise InputError("method", "a bearing pair is solved by the exact model only")
    tilt = "the shaft's tilt follows from the loads; give 'moment'"
    case.refuse(("misalignment",), "a bearing pair", tilt)
    why = "the design contact angle fixes the geometry of an angular-contact bearing"
    case.refuse(("clearance",), "a bearing pair", why + " (no clearance)")


def _pair(case: Case, spell: Any) -> Solution:
    """A pair of angular-contact ball bearings (an arrangement, or 7205BDB), its options
    checked (:func:`refuse_pair_options`)."""
    from bearingload.studies.bearing_pair import pair_lives, solve_bearing_pair
    from bearingload.studies.life_basis import combined_basis

    b = pair_bearing(case)
    dynamics = case.dynamics_arguments()  # at a speed the ball dynamics, unless quasi-static
    try:
        arguments = case.pair_arguments(b.balls)
        pc = solve_bearing_pair(
            b, case.radial_load, case.axial_load or 0.0, **arguments, **dynamics
        )
    except (ConvergenceError, InputError) as exc:
        hinted = pair_speed_hint(exc) if dynamics["speed"] is not None else None
        if hinted is None:
            raise
        raise hinted from exc
    pc = with_speed_warnings([pc], case.speed)[0]  # the bearing's limiting speeds
    # each bearing's service lives as one bearing's from its own loads; the pair's from them
    service = service_lives(case, [combined_basis(c) for c in pc.bearings], spell)
    return Solution("pair", (pc,), tuple(service), pair_lives(pc, service))


def pair_speed_hint(exc: ConvergenceError | InputError) -> Exception | None:
    """A pair at speed the ball dynamics leave unbalanced, refuse as too light (the library's
    way out) or as too fast, with the way to the static model; None for another refusal."""
    from bearingload.models.high_speed import too_fast
    from bearingload.models.pair_speed import TOO_LIGHT_PAIR

    if isinstance(exc, ConvergenceError):
        return exc.with_way_out(STATIC_PAIR_WAY)
    if too_fast(exc):
        return exc.with_way_out(STATIC_AT_ANY_SPEED)
    if exc.reason != TOO_LIGHT_PAIR:
        return None
    return exc.with_way_out(STATIC_PAIR_WAY)


def service_lives(case: Case, bases: list[Any], spell: Any = str) -> list[Any]:
    """The lives the case's operating conditions make meaningful, one
    :class:`bearingload.bearings.service_life.ServiceLife` per basis."""
    from bearingload.bearings.service_life import service_values

    op = case.operating(spell)
    return [service_values(op, b) for b in bases]


def speed_pair_lives(cases: Sequence[Any], speed: float | None) -> tuple[Any, ...]:
    """The service values of each solved pair of ``cases`` as solve gives them with ``speed``
    [rpm] alone (C_0; with a speed the lives in hours): the rows of a pair's sweep and table
    life (:class:`bearingload.studies.bearing_pair.PairLives`)."""
    from bearingload.bearings.service_life import Operating, service_values
    from bearingload.studies.bearing_pair import pair_lives
    from bearingload.studies.life_basis import combined_basis

    op = Operating(speed=speed)
    return tuple(
        pair_lives(c, [service_values(op, combined_basis(b)) for b in c.bearings]) for c in cases
    )


def with_speed_warnings(cases: list[Any], speed: float | None) -> list[Any]:
    """The solved cases with the warning on a speed above the limiting speed the catalogue
    gives for their bearing added to theirs (:func:`speed_warnings`)."""
    out = []
    for c in cases:
        found = speed_warnings(c.warnings, speed, c.bearing)
        out.append(c if found is c.warnings else dataclasses.replace(c, warnings=found))
    return out


def with_solver_findings(result: Any, flags: Any, axial_load: float, radial_load: float) -> Any:
    """``result`` (a study's answer with its ``warnings``) with the warnings on what the
    combined solver did in any of its cases (``flags``: the solver's ``thrust_neglected``,
    ``tilt_undetermined`` and, at speed, ``displacement_undetermined``, None where it gives
    none) added once each, in solve's words: a thrust it left out, a tilt or a position the
    loads do not determine; ``result`` itself where there is none."""
    import numpy as np

    from bearingload.studies.combined_bearing import (
        POSITION_UNDETERMINED,
        TILT_UNDETERMINED,
        thrust_neglected_warning,
    )

    found = list(result.warnings)
    if np.any(getattr(flags, "tilt_undetermined", None)):
        found.append(TILT_UNDETERMINED)
    if np.any(getattr(flags, "displacement_undetermined", None)):
        found.append(POSITION_UNDETERMINED)
    if np.any(getattr(flags, "thrust_neglected", None)):
        found.append(thrust_neglected_warning(axial_load, radial_load))
    new = tuple(w for w in dict.fromkeys(found) if w not in result.warnings)
    return dataclasses.replace(result, warnings=(*result.warnings, *new)) if new else result


def speed_warnings(warnings: Any, speed: float | None, bearing: Any) -> Any:
    """``warnings`` (a tuple) with the warning on a ``speed`` [rpm] above the limiting speed the
    catalogue gives for ``bearing`` added once (:func:`bearingload.bearings.checks.
    speed_findings`); ``warnings`` itself where there is none."""
    from bearingload.bearings.checks import speed_findings

    if speed is None or bearing is None:
        return warnings
    new = [w for w in speed_findings(speed, bearing) if w not in warnings]
    return (*warnings, *new) if new else warnings
