"""``bearingload solve``: one case, every ball's load and a summary with units."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import click

from bearingload.cli.case_options import CaseOptions, case_options
from bearingload.cli.cases import (
    check_rotating,
    refuse_tilt_radius,
    refuse_unused,
    resolve_bearings,
)
from bearingload.cli.options import (
    CONTEXT,
    Quantity,
    emit,
    library_errors,
    method_option,
    output_options,
    print_warnings,
    quiet_option,
)
from bearingload.cli.plot import ball_loads_plot_option, check_plot, save_plot
from bearingload.errors import ConvergenceError, InputError
from bearingload.studies.life_basis import combined_basis, radial_basis
from bearingload.units import plausible_ranges_help


@click.command(context_settings=CONTEXT)
@case_options(required=("load",), pair=True)
@click.option(
    "--revolutions",
    type=Quantity("revolutions", positive=True),
    default=36e6,
    show_default=True,
    help="Life L [revolutions] for the allowable load C/(L/10^6)^(1/3). The default is the "
    "worked value of Kuzmenko (2010) §3.2 (36e6 rev, e.g. 1000 h at 600 rpm); set your own. "
    f"Units: rev, Mrev = 10^6 rev (bare number: rev; {plausible_ranges_help('revolutions')}: "
    "36 -> did you mean 36Mrev?).",
)
@method_option(
    "exact: ring equilibrium, every ball; continuum: loads smeared over the raceway; "
    "stribeck: 4.37 F_r/z; palmgren: 5 F_r/z (these two ignore stiffness, clearance, cage "
    "angle and exponent); all: every method side by side with its error against exact."
)
@click.option(
    "--per-ball",
    is_flag=True,
    help="csv: one row per ball (angle, approach, load) instead of one row per case.",
)
@click.option(
    "--show-geometry",
    is_flag=True,
    help="With a BEARING: also print the geometry used and the source of every value "
    "(JSON always carries it).",
)
@quiet_option
@output_options
@ball_loads_plot_option
@library_errors
def solve(
    case: CaseOptions,
    revolutions: float,
    method: str,
    per_ball: bool,
    show_geometry: bool,
    quiet: bool,
    fmt: str,
    output: str | None,
    plot: str | None,
) -> None:
    """Solve the ring equilibrium of one bearing: the heaviest ball load, how many balls carry,
    the load zone, the ring displacement and stiffness, and every ball's load.

    The inner ring moves until the ball forces balance the radial load (Kurochkin 1973,
    Kuzmenko 2010). Ball 1 sits at the cage angle; balls are numbered counter-clockwise.

    BEARING is a catalogue designation (306, 6306-2RS/C3, 75-313, 61806, 16005; see 'bearingload
    catalog'): its ball set (NSK's unless --maker names another) gives the exact Hertz ball
    stiffness, its bore resolves a clearance class, its rating C gives the life (C/P)^p;
    --show-geometry prints the source of every value. A cylindrical roller bearing (NU206,
    N 306) is solved with line contact (m = 10/9, Palmgren). Without a BEARING give --balls and
    --stiffness (or the ball geometry).

    A case outside what the bearing supports (s0 = C0/P0 below 1, F_r above C0, contact pressure
    above 4200 MPa for balls or 4000 MPa for rollers as in ISO 76, one element carrying the load,
    clearance beyond the ISO 5753-1 classes) prints 'Warning: ...' lines on stderr; the result is
    printed and the exit status is 0. JSON carries them as 'warnings'.

    With --axial-load, --moment, --moment-cross or --misalignment the inner ring of a deep-groove
    ball bearing moves radially, axially and tilts about both axes (ISO/TS 16281): every ball gets
    its contact angle; the axial displacement is measured from the centred rings (half the axial
    play included, as MASTA reports it); the ring is free to tilt unless a moment or a
    misalignment is given, and --tilt-radius sets the lever of the tilt (default groove, the
    radius of the inner groove centres; pitch: d_m/2, as MASTA); the report adds the contact
    pressures at every ball's contact angle, the static safety s0 (ISO 76) and ISO 281's
    (C_r/P)^3 with P = X F_r + Y F_a. The reference rating life L10r (ISO/TS 16281, from the ball
    loads) is given wherever the ball geometry and C_r are known, radial load or not; --rotating
    (default inner) and --dynamic-rating feed the lives only and change no load.

    At --speed a ball bearing is solved with each ball's centrifugal force and gyroscopic
    moment (docs/speed.md): by the combined engine, at F_a = 0 without a load option, the exact
    model only; --quasi-static: the static model (the radial engine without a load option). A
    roller bearing keeps the static radial engine; a pair (7205BDB) takes them in both
    bearings (--quasi-static: the static pair).

    Lives as engineers use them (docs/life.md): --speed gives every life in hours; --reliability
    a_1 (ISO 281 Table 12); --viscosity (needs --speed) nu_1, kappa, a_ISO (ISO 281, with
    --contamination or --eC and C_u: --fatigue-load-limit or the estimate from C_0,
    --static-rating) and the modified lives L_nm = a_1 a_ISO L10 and L_nmr (ISO/TS 16281, a_ISO at
    P_ref = C L10r^(-1/p)), and the minimum film thickness at the heaviest contact
    (Hamrock-Dowson; Dowson-Higginson for rollers) with the film ratio for --roughness. Only what
    the given inputs make meaningful is printed.

    \b
    Examples:
      # bearing 306 of the catalogue, 300 kgf, ISO clearance class C3 (mean of its range)
      bearingload solve 306 --load 300kgf --clearance C3
      # the whole C3 range side by side, the paper's modulus, with the geometry used
      bearingload solve 6306 -F 3kN -G C3 --clearance-pick range --modulus 2.1e4kgf/mm^2 --show-geometry
      # bearing 306 of Kuzmenko (2010): 8 balls, 300 kgf, the paper's stiffness, G_r = 20 µm
      bearingload solve -z 8 --load 300kgf --stiffness 4700kgf/mm^1.5 --clearance 20um
      # the load between two balls, 50 µm preload, JSON for a script
      bearingload solve -z 12 -F 5kN -K 3.8e5 -G -50um --cage-angle half --format json
      # exact, continuum, Stribeck and Palmgren side by side, errors against the exact answer
      bearingload solve -z 8 -F 300kgf -K 4700kgf/mm^1.5 -G 20um --method all
      # every ball's load as csv, one row per ball
      bearingload solve -z 8 -F 300kgf -K 4700kgf/mm^1.5 --format csv --per-ball
      # combined load on a 6205 with C3 clearance: contact angles, tilt, L10r
      bearingload solve 6205 -F 1.4kN --axial-load 700N -G C3
      # a hand-given ball set under a pure axial load, its C_r, the outer ring rotating
      bearingload solve -z 7 --ball-diameter 11.5 --pitch-diameter 43.5 -F 0 -A 1kN -G 10um -C 23.4kN --rotating outer
      # a moment of 2 N m about the load line (MASTA's M_x), the tilt at the pitch radius
      bearingload solve 6205 -F 1kN -A 500N --moment-cross 2Nm --tilt-radius pitch
      # a back-to-back pair of 7205B with 500 N preload (or 7205B --arrangement DB)
      bearingload solve 7205BDB --preload 500N -F 2kN -A 1kN
      # a pair as bought: NSK's light preload class L of a 7205C pair (or --preload L)
      bearingload solve 7205CDBL -F 1kN -A 200N
      # SKF's ball set of a 6208 instead of NSK's; a cylindrical roller bearing
      bearingload solve 6208 -F 5kN --maker SKF
      bearingload solve NU206 --load 5kN
      # hours, a_ISO and the modified lives at 3000 rpm, 20 cSt, 99 % reliability
      bearingload solve 6205 -F 1.4kN --speed 3000 --viscosity 20cSt --reliability 99
      # the ball loads and contact angles of this solution drawn into a PDF
      bearingload solve 6205 -F 5kN -A 2kN --plot loads.pdf
    """
    from bearingload.models.registry import list_methods

    if not revolutions == revolutions:  # NaN passes click's range check
        raise click.UsageError(
            "Invalid value for '--revolutions': must be a number of revolutions > 0, got nan"
        )
    case, at_speed = _radial_at_speed(case)
    methods = list_methods() if method == "all" else [method]
    if at_speed and method != "exact":
        raise click.UsageError(
            f"Invalid value for '--method': at --speed the ball dynamics of a ball bearing are "
            f"solved by the exact model only (the combined engine at F_a = 0); give "
            f"--quasi-static for the static model, where --method {method} is allowed"
        )
    if plot is not None:  # before any work
        check_plot(plot)
        if "exact" not in methods and not case.wants_combined:
            raise click.UsageError(
                f"Invalid value for '--plot': it draws the ball loads of the exact model; "
                f"--method {method} gives none (use --method exact or all)"
            )
    k_given = case.stiffness_value()  # N/mm^m
    pair = case.as_pair()
    if pair is not None:
        _refuse_revolutions("a bearing pair", "it prints L10r and L10 of the pair instead")
        text, found = _pair(pair, k_given, method, plot, fmt, per_ball, show_geometry)
        emit(text, output)
        print_warnings(found, quiet)
        return
    from bearingload.bearings.angular import parse_angular

    angular = case.bearing is not None and parse_angular(case.bearing) is not None
    # the load chooses the engine, and --speed on a ball bearing (the ball dynamics: F_a = 0
    # set above), never another life option; an angular-contact designation always takes the
    # combined engine (its balls sit at the contact angle)
    if case.wants_combined or angular:
        if at_speed:
            _refuse_revolutions(
                "the ball dynamics at --speed (a ball bearing is solved by the combined engine "
                "at F_a = 0)",
                "give --quasi-static for the static radial engine",
            )
        _refuse_revolutions(
            "the combined engine (a load option, or an angular-contact bearing)",
            "it prints L10 = (C/P)^3 at P = X F_r + Y F_a and L10r instead",
        )
        if method != "exact":
            what = (f"an angular-contact bearing ({case.bearing})" if angular else "the combined "
                    "load (--axial-load, --moment, --moment-cross, --misalignment)")  # fmt: skip
            raise click.UsageError(
                f"Invalid value for '--method': {what} is solved by the exact model only"
            )
        bearings = with_ratings(resolve_bearings(case, k_given), case)
        if bearings[0].kind == "ball" and bearings[0].has_geometry:
            check_rotating(case, bearings[0], methods)
        text, found, figure = _combined(bearings, case, fmt, per_ball, show_geometry, at_speed)
    else:
        from bearingload.reports.solve import printed_warnings, solve_report
        from bearingload.studies.loaded_bearing import collect_warnings

        refuse_tilt_radius(case)
        _refuse_static_dynamics(case)
        service = None
        if case.by_hand:
            refuse_unused(case)
            _refuse_revolutions("a ring given by its balls and stiffness", "it has no C")
            cases = _by_hand(methods, case, k_given)
        else:
            bearings = with_ratings(resolve_bearings(case, k_given), case)
            cases = with_speed_warnings(_radial(bearings, case, methods, revolutions), case.speed)
            service = service_lives(case, [radial_basis(c, case.rotating) for c in cases])
        text = solve_report(
            cases, fmt, per_ball=per_ball, show_geometry=show_geometry, service=service
        )
        found = printed_warnings(collect_warnings(cases), service)
        figure = functools.partial(_figure, "solve_figure", cases)
    if plot is not None:
        save_plot(figure, plot)  # the figure of this very solution, written whole
    emit(text, output)
    print_warnings(found, quiet)


def _radial_at_speed(case: CaseOptions) -> tuple[CaseOptions, bool]:
    """(the case, True) with F_a = 0 given where a radial case of a ball bearing (a BEARING or
    the ball geometry, not an angular-contact designation) has --speed without --quasi-static:
    the combined engine then solves it with the ball dynamics, as --axial-load 0 does
    (docs/speed.md); otherwise (the case, False): rollers, --quasi-static, no speed, a pair."""
    import dataclasses

    from bearingload.bearings.designation import contact_exponent
    from bearingload.constants import ROLLER_EXPONENT

    if case.speed is None or case.quasi_static or case.wants_combined:
        return case, False
    if case.arrangement is not None or case.as_pair() is not None:
        return case, False  # a pair: its own path (_pair), the ball dynamics of both bearings
    if case.by_hand or contact_exponent(case.bearing) == ROLLER_EXPONENT:
        return case, False  # --speed refused without the geometry; rollers: the radial engine
    given = case.given | {"axial_load"}
    return dataclasses.replace(case, axial_load=0.0, given=given), True


#: What a radial solve of a ball bearing at --speed the ball dynamics cannot solve can do.
QUASI_STATIC_WAY = "--quasi-static gives the static radial engine (the ball dynamics left out)"


def _quasi_static_hint(exc: InputError, radial: bool = True) -> InputError | None:
    """The combined solver's refusal of loads too small for it, at --speed: it named 'the
    radial solver, without an axial load', which at a speed is the ball dynamics too. On a radial
    solve (``radial``: F_a = 0 set, no axial load given) --quasi-static is the way to the radial
    engine; with an axial load given, --quasi-static and no axial load are."""
    from bearingload.models.combined import RADIAL_TAKES_ANY_LOAD
    from bearingload.models.high_speed import too_fast

    message = exc.message
    if too_fast(exc):
        return InputError(exc.parameter, f"{message}; {STATIC_AT_ANY_SPEED}")
    if RADIAL_TAKES_ANY_LOAD not in message:
        return None
    way = ("--quasi-static gives the static radial engine, which takes any load" if radial
           else "--quasi-static without an axial load gives the static radial engine, which "
           "takes any load")  # fmt: skip
    hint = f"at --speed a ball bearing is solved by the combined engine (the ball dynamics); {way}"
    return InputError(exc.parameter, message.replace(RADIAL_TAKES_ANY_LOAD, hint))


def _refuse_static_dynamics(case: CaseOptions) -> None:
    """--ball-density and --quasi-static on the radial engine: refused for a roller bearing
    (no ball dynamics) and without a speed, --ball-density also under --quasi-static."""
    from bearingload.bearings.designation import contact_exponent
    from bearingload.constants import ROLLER_EXPONENT

    if not case.by_hand and contact_exponent(case.bearing) == ROLLER_EXPONENT:
        case.refuse(("ball_density",), f"a roller bearing ({case.bearing})", "the radial engine "
                    "solves it by the static model at any speed: the ball dynamics at --speed "
                    "are coded for ball bearings")  # fmt: skip
    case.check_dynamics_flags()


def _refuse_revolutions(where: str, instead: str) -> None:
    """Refuse a --revolutions given on the command line where no allowable load is printed: it
    sets the life L of the radial engine's allowable load C/(L/10^6)^(1/3) of a bearing with C."""
    ctx = click.get_current_context()
    if ctx.get_parameter_source("revolutions") not in (None, click.core.ParameterSource.DEFAULT):
        raise click.UsageError(
            f"--revolutions cannot be used with {where}: it sets the life L of the allowable "
            f"radial load C/(L/10^6)^(1/3), which only the radial engine prints for a bearing "
            f"with a dynamic load rating C; {instead}"
        )


def _pair(
    case: CaseOptions, k_given: float | None, method: str, plot: str | None, fmt: str,
    per_ball: bool, show_geometry: bool,
) -> tuple[str, list[str]]:  # fmt: skip
    """A pair of angular-contact ball bearings (--arrangement, or 7205BDB): (report, warnings)."""
    import dataclasses

    from bearingload.reports.pair import pair_report
    from bearingload.reports.solve import printed_warnings
    from bearingload.studies.bearing_pair import solve_bearing_pair

    if method != "exact":
        raise click.UsageError(
            "Invalid value for '--method': a bearing pair is solved by the exact model only"
        )
    if plot is not None:
        raise click.UsageError(
            "Invalid value for '--plot': it draws the ball loads of one bearing, not of a pair"
        )
    case.refuse(("misalignment",), "a bearing pair", "the shaft's tilt follows from the "
                "loads; give --moment")  # fmt: skip
    why = "the design contact angle fixes the geometry of an angular-contact bearing"
    case.refuse(("clearance",), "a bearing pair", why + " (no clearance)")
    b = with_ratings(resolve_bearings(case, k_given), case)[0]
    if case.contact_angle is not None:
        if case.bearing is not None:
            raise click.UsageError(
                "--contact-angle cannot be used with a bearing designation: give the "
                "angular-contact ring by hand (--balls, --ball-diameter, --pitch-diameter)"
            )
        b = dataclasses.replace(b, contact_angle=case.contact_angle, clearance=0.0)
    if b.contact_angle is None:
        raise click.UsageError(
            f"Invalid value for '--arrangement': a pair {case.arrangement} is two "
            "angular-contact ball bearings; give an angular-contact designation (7205B, "
            "7205BDB) or a ring by hand with --contact-angle"
        )
    dynamics = case.dynamics_arguments()  # at --speed the ball dynamics, unless --quasi-static
    try:
        pc = solve_bearing_pair(b, case.radial_load, case.axial_load or 0.0,
                                **case.pair_arguments(b.balls), **dynamics)  # fmt: skip
    except (ConvergenceError, InputError) as exc:
        hinted = pair_speed_hint(exc) if dynamics["speed"] is not None else None
        if hinted is None:
            raise
        raise hinted from exc
    pc = with_speed_warnings([pc], case.speed)[0]  # the bearing's limiting speeds
    # each bearing's service lives as one bearing's from its own loads; the pair's from them
    service = service_lives(case, [combined_basis(c) for c in pc.bearings])
    text = pair_report(pc, fmt, per_ball=per_ball, show_geometry=show_geometry, service=service)
    return text, printed_warnings(pc.warnings, service)


#: The way out of a speed beyond the ball dynamics' limit (n d_m).
STATIC_AT_ANY_SPEED = "--quasi-static gives the static model at any speed (the lives in hours)"


def pair_speed_hint(exc: ConvergenceError | InputError) -> Exception | None:
    """A pair at --speed the ball dynamics leave unbalanced, refuse as too light (the library's
    way out) or as too fast, with --quasi-static named; None for another refusal."""
    from bearingload.models.high_speed import too_fast
    from bearingload.models.pair_speed import STATIC_WAY

    way = "--quasi-static gives the static model"
    if isinstance(exc, ConvergenceError):
        return click.ClickException(f"{exc}; {way}")
    if too_fast(exc):
        return InputError(exc.parameter, f"{exc.message}; {STATIC_AT_ANY_SPEED}")
    if STATIC_WAY not in str(exc):
        return None
    return InputError(exc.parameter, exc.message.replace(STATIC_WAY, way))


def _radial(
    bearings: list[Any], case: CaseOptions, methods: list[str], revolutions: float
) -> list[Any]:
    """The radial engine on resolved bearings: C replaced by --dynamic-rating, and L10r from the
    exact ball loads for the ring --rotating names (default inner) where it can be computed."""
    from bearingload.studies.loaded_bearing import solve_bearing
    from bearingload.studies.reference_life import with_reference_lives

    if case.dynamic_rating is not None:
        bearings = [b.with_dynamic_rating(case.dynamic_rating) for b in bearings]
    if not any(b.C for b in bearings):
        _refuse_revolutions("a bearing without a dynamic load rating C", "give --dynamic-rating")
    check_rotating(case, bearings[0], methods)
    angle = case.cage_angle_deg(bearings[0].balls)
    cases = solve_bearing(bearings, case.radial_load, angle, methods, revolutions)
    return with_reference_lives(cases, case.rotating or "inner")


def _combined(
    bearings: list[Any], case: CaseOptions, fmt: str, per_ball: bool, show_geometry: bool,
    at_speed: bool = False,
) -> tuple[str, list[str], Callable[[], Any]]:  # fmt: skip
    """The combined-load engine on resolved bearings: (report, warnings, its figure);
    ``at_speed``: a radial case of a ball bearing solved with the ball dynamics at F_a = 0."""
    from bearingload.cli.cases import combined_cases
    from bearingload.reports.combined import collect_combined_warnings, combined_report
    from bearingload.reports.solve import printed_warnings

    try:
        solved = combined_cases(bearings, case)
    except InputError as exc:
        dynamics = case.speed is not None and not case.quasi_static
        hinted = _quasi_static_hint(exc, radial=at_speed) if dynamics else None
        if hinted is None:
            raise
        raise hinted from exc
    except ConvergenceError as exc:  # a radial case at speed: the static engine solves it
        if not at_speed:
            raise
        raise click.ClickException(f"{exc}; {QUASI_STATIC_WAY}") from exc
    cases = with_speed_warnings(solved, case.speed)
    service = service_lives(case, [combined_basis(c) for c in cases])
    text = combined_report(
        cases, fmt, per_ball=per_ball, show_geometry=show_geometry, service=service
    )
    found = printed_warnings(collect_combined_warnings(cases), service)
    return text, found, functools.partial(_figure, "combined_loads_figure", cases)


def with_ratings(bearings: list[Any], case: CaseOptions) -> list[Any]:
    """The resolved bearings with C_0 replaced by --static-rating where given; --dynamic-rating
    checked for its range (the combined engines take it as an argument: 1e300 N overflowed its
    L10, refused as a bad --load)."""
    if case.dynamic_rating is not None:
        bearings[0].with_dynamic_rating(case.dynamic_rating)
    if case.static_rating is None:
        return bearings
    return [b.with_static_rating(case.static_rating) for b in bearings]


def pair_bearing(case: CaseOptions) -> Any:
    """One bearing of the pair of ``sweep`` and ``table life`` (resolved, with its ratings);
    refused unless it is an angular-contact designation."""
    from bearingload.cli.cases import resolve_bearings

    b = with_ratings(resolve_bearings(case, case.stiffness_value()), case)[0]
    if b.contact_angle is None:
        raise click.UsageError(
            f"Invalid value for '--arrangement': a pair {case.arrangement} is two "
            "angular-contact ball bearings; give an angular-contact designation (7205B, 7205BDB)"
        )
    return b


def service_lives(case: CaseOptions, bases: list[Any]) -> list[Any]:
    """The lives the case's operating conditions make meaningful, one
    :class:`bearingload.bearings.service_life.ServiceLife` per basis: C_0 wherever it is known
    (catalogue or --static-rating), the rest as the options of
    :data:`bearingload.cli.case_options.SERVICE_PARAMS` given make it meaningful."""
    from bearingload.bearings.service_life import service_values

    op = case.operating()
    return [service_values(op, b) for b in bases]


def with_speed_warnings(cases: list[Any], speed: float | None) -> list[Any]:
    """The solved cases (one each) with the warning on a --speed above the limiting speed the
    catalogue gives for their bearing added to theirs
    (:func:`bearingload.bearings.checks.speed_findings`): stderr and json both list it."""
    import dataclasses

    from bearingload.bearings.checks import speed_findings

    if speed is None:
        return cases
    out = []
    for c in cases:
        new = [] if c.bearing is None else speed_findings(speed, c.bearing)
        out.append(dataclasses.replace(c, warnings=(*c.warnings, *new)) if new else c)
    return out


def _figure(name: str, cases: list[Any]) -> Any:
    """The figure ``name`` of :mod:`bearingload.reports.plots` of the solved ``cases``
    (imported only when a plot is drawn)."""
    from bearingload.reports import plots

    return getattr(plots, name)(cases)


def _by_hand(methods: list[str], case: CaseOptions, k_given: float | None) -> list[Any]:
    """The radial engine on a ring given by z and K."""
    from bearingload.bearings.clearance import clearance_length
    from bearingload.cli.cases import ring_by_hand
    from bearingload.studies.loaded_bearing import solve_ring

    z, k = ring_by_hand(case, k_given)
    angle = case.cage_angle_deg(z)
    g_r = clearance_length(case.clearance)
    return solve_ring(methods, z, case.radial_load, k, g_r, angle, case.exponent_or(1.5))
