"""``bearingload sweep``: the ring equilibrium over one ball pitch of cage positions."""

from __future__ import annotations

from typing import Any

import click

from bearingload.bearings.mounting import MOUNTING_PARAMS
from bearingload.cli.case_options import case_options
from bearingload.cli.options import CONTEXT, LibraryOption, emit, library_errors, output_options
from bearingload.cli.plot import check_plot, save_plot
from bearingload.plan.bearing import refuse_range, refuse_tilt_radius, resolve_case
from bearingload.plan.case import COMBINED_PARAMS, MOUNTING_REFUSAL, SERVICE_PARAMS, Case

#: The case options the dimensionless mode refuses (P = K = 1, the gap from T).
KUROCHKIN_REFUSES = ("bearing", "load", "stiffness", "clearance", "plot", "ball_diameter",
                     "pitch_diameter", "inner_conformity", "outer_conformity", "modulus",
                     "poisson", "ball_material", "maker", *COMBINED_PARAMS)  # fmt: skip

#: Why sweep refuses the operating conditions of the modified lives (:data:`SERVICE_PARAMS`
#: but --speed, which gives L10h and L10rh at every cage position).
SERVICE_REFUSAL = (
    "the sweep shows how the ring position, Q_max and L10r (in hours with --speed) ripple over "
    "one ball pitch; C_0, a_1, a_ISO, the modified lives and the film are those of the case: "
    "give the same options to 'bearingload solve' (or 'table life' against the clearance)"
)


@click.command(context_settings=CONTEXT)
@case_options(
    omit=("cage_angle",),
    hidden=[n for n in SERVICE_PARAMS if n != "speed"],
    pair=True,
)
@click.option(
    "--steps",
    "-n",
    type=int,
    default=37,
    show_default=True,
    help="Cage positions over one ball pitch, both ends included (2 to 1000000).",
)
@click.option(
    "--plot",
    type=click.Path(dir_okay=False),
    help="Also draw x, y, Q_max and stiffness over the cage angle into FILE; its extension "
    "gives the format (.png, .pdf, .svg ...). Needs matplotlib: pip install matplotlib.",
)
@click.option(
    "--kurochkin-T",
    "kurochkin_t",
    type=float,
    cls=LibraryOption,
    library=("T",),
    help="Kurochkin's dimensionless mode (1973): P = K = 1 and the gap from his parameter T, "
    "eq. (1.13); rows give F0 = x0 and F0' = -y0, the summary the contact sequence, exit angle "
    "and Fourier coefficients F0j'. Needs --balls (>= 5) only.",
)
@output_options
@library_errors
def sweep(
    case: Case,
    steps: int,
    plot: str | None,
    kurochkin_t: float | None,
    fmt: str,
    output: str | None,
) -> None:
    """Turn the cage one ball pitch: ring position, Q_max and stiffness at every cage angle.

    As the cage turns one pitch 360/z the load passes from a ball under the load (cage angle 0)
    to the load between two balls (180/z) and back: the inner ring moves along and across the
    load, the heaviest ball load and the stiffness ripple z times per cage revolution (the
    varying compliance that excites vibration; Kurochkin 1973). Every cage position is solved
    exactly, in one vectorised call. The summary gives min, mean, max and peak-to-peak over the
    pitch, and every compensating clearance: the G_r at which the ring sits at the same x with a
    ball under the load and with the load between two balls.

    The bearing and condition options are those of 'bearingload solve' (the cage angle is what
    turns). csv: one row per cage angle with the inputs as columns; json: rows, a summary and
    units.

    With --axial-load, --moment, --moment-cross or --misalignment (a deep-groove ball bearing: a
    catalogue designation, or --balls with --ball-diameter and --pitch-diameter) every cage
    position is solved by the 3-D ring equilibrium of 'solve' (ISO/TS 16281), all in one
    vectorised call: per position x, y, the axial displacement (from the centred rings, half the
    axial play included), the tilts about both axes (the ring is free to tilt unless a moment or
    a misalignment is given; --tilt-radius sets the lever), Q_max and its ball, the loaded balls,
    the largest contact angle and the reference rating life L10r of the rotating ring (default
    inner); beside them ISO 281's (C_r/P)^3, the same at every position. Not for roller bearings
    or --kurochkin-T. The life options alone (--dynamic-rating, --rotating) never change the
    engine: the radial sweep adds L10r at each position (ball bearings) and L10.

    With --speed a ball bearing is swept as 'solve --speed' solves it: every position with the
    ball dynamics (each ball's centrifugal force and gyroscopic moment, outer-raceway control;
    a radial load on the 3-D engine at F_a = 0; --ball-density for ceramic balls), the lives
    also in hours; a pair (7205BDB): both bearings' ball dynamics. --quasi-static keeps the
    static model (the speed then gives the hours only), as do roller bearings.

    \b
    Examples:
      # nine balls, 1 kN, K = 1e5 N/mm^1.5, G_r = 10 µm, 19 cage positions
      bearingload sweep -z 9 -F 1kN -K 1e5 -G 10um --steps 19
      # catalogue bearing 306 at 300 kgf, clearance class C3, a plot of the ripple
      bearingload sweep 306 --load 300kgf --clearance C3 --plot sweep306.png
      # one csv row per cage angle for a spreadsheet
      bearingload sweep -z 12 -F 5kN -K 3.8e5 -G -20um --format csv -o sweep.csv
      # Kurochkin's dimensionless statics: 7 balls, T = 0.567 (his Table 3)
      bearingload sweep --balls 7 --kurochkin-T 0.567 --steps 21
      # combined load on a 6205 (C3): F_r 1.4 kN, F_a 700 N, L10r at every cage position
      bearingload sweep 6205 -F 1.4kN --axial-load 700N -G C3 --steps 9
      # a hand-given ball set, C_r 23.4 kN, outer ring rotating, imposed 2 mrad tilt, as csv
      bearingload sweep -z 7 --ball-diameter 11.5 --pitch-diameter 43.5 -F 1kN -G 10um -C 23.4kN --rotating outer --misalignment 2mrad --format csv
      # a moment of 5 N m in the load plane, json for a script
      bearingload sweep 6205 -F 1kN -A 300N --moment 5Nm --format json
      # a moment of 2 N m about the load line, the tilt at the pitch radius as MASTA
      bearingload sweep 6205 -F 1kN -A 300N --moment-cross 2Nm --tilt-radius pitch --steps 9
      # a 6205 at 10000 rpm: the ball dynamics at every cage position, L10r also in hours
      bearingload sweep 6205 -F 1kN -A 300N --speed 10000 --steps 9
      # a back-to-back pair of 7205B, 300 N preload: the shaft, each bearing's Q_max, stiffness
      bearingload sweep 7205BDB --preload 300N -F 1kN -A 200N --steps 7
    """
    case.refuse(
        ("contact_angle",),
        "sweep",
        "a ring given by hand with its contact angle is solved by 'solve' only; sweep takes "
        "an angular-contact designation (7205B; docs/angular_contact.md)",
    )
    case.refuse([n for n in SERVICE_PARAMS if n != "speed"], "sweep", SERVICE_REFUSAL)
    case.refuse(MOUNTING_PARAMS, "sweep", MOUNTING_REFUSAL)
    if kurochkin_t is not None:
        _kurochkin(case, kurochkin_t, steps, plot, fmt, output)
        return
    if case.load is None:
        raise click.UsageError("Missing option '--load' / '-F' (or give --kurochkin-T).")
    refuse_range(case, "sweep")
    pair = case.as_pair()
    if pair is not None:
        _pair(pair, steps, plot, fmt, output)
        return
    if plot is not None:
        check_plot(plot)
    from bearingload.plan.solve import radial_at_speed, refuse_static_dynamics

    refuse_static_dynamics(case)
    case, radial = radial_at_speed(case)  # a radial ball bearing at speed: F_a = 0, dynamics
    if case.wants_combined:  # the load alone chooses the engine, never a life option
        _combined(case, steps, plot, fmt, output, radial)
        return
    refuse_tilt_radius(case)
    z, k, g_r, m, context = resolve_case(case)
    import dataclasses

    from bearingload.reports.sweep import sweep_report, sweep_warnings
    from bearingload.studies.sweep import sweep as run_sweep

    life, lives = _radial_lives(case) if case.lives_given else (None, {})
    result = run_sweep(z, case.radial_load, k, g_r, m, steps, life=life)
    result = dataclasses.replace(result, **lives)
    if not case.by_hand:  # solve's checks on the bearing, as solve makes them
        result = dataclasses.replace(result, warnings=_bearing_checks(case, result))
    text = sweep_report(result, fmt, context)
    for warning in sweep_warnings(result):
        click.echo(f"Warning: {warning}", err=True)
    if plot is not None:
        from bearingload.reports.plots import sweep_figure

        save_plot(lambda: sweep_figure(result, case.bearing), plot)
    emit(text, output)


def _bearing_checks(case: Case, result: Any) -> tuple[str, ...]:
    """The warnings solve gives on the bearing of the case (s0, C0, contact pressure, clearance),
    at the heaviest ball load of the sweep ``result``, and on --speed above its limiting speed."""
    from bearingload.bearings.checks import speed_findings
    from bearingload.plan.bearing import resolve_bearings, with_ratings
    from bearingload.studies.sweep import bearing_checks

    b = with_ratings(resolve_bearings(case, case.stiffness_value()), case)[0]
    return bearing_checks(b, result) + tuple(speed_findings(case.speed, b))


def _radial_lives(case: Case) -> tuple[Any, dict[str, Any]]:
    """The lives of a radial sweep (--dynamic-rating, --rotating, --speed given, no load
    option): L10r at each cage position from the radial engine's ball loads, every ball at the
    contact angle 0, as solve's radial path gives it (a ball bearing with its geometry and C_r;
    --rotating refused where none is computed, as solve refuses it); ISO 281's L10 where C_r is
    known; hours with --speed. (the ``life`` of the sweep, the fields of its result)"""
    import functools

    from bearingload.bearings.life import BALL_LIFE_EXPONENT, ROLLER_LIFE_EXPONENT
    from bearingload.plan.bearing import check_rotating, resolve_bearings, with_ratings
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


def _combined(
    case: Case, steps: int, plot: str | None, fmt: str, output: str | None,
    radial: bool = False,
) -> None:  # fmt: skip
    """The sweep under a combined load: one vectorised 3-D solve over the pitch (at --speed the
    ball dynamics, unless --quasi-static; ``radial``: a radial case at speed, F_a = 0 set),
    then emit."""
    import dataclasses

    from bearingload.bearings.checks import speed_findings
    from bearingload.cli.options import print_warnings
    from bearingload.plan.bearing import bearing_context, resolve_bearings, with_ratings
    from bearingload.reports.combined_sweep import combined_sweep_report

    b = with_ratings(resolve_bearings(case, case.stiffness_value()), case)[0]
    result = _combined_sweep(b, case, steps, radial)
    if case.speed is not None:  # the hours (and the dynamics' speed); the limiting speed
        found = (*result.warnings, *speed_findings(case.speed, b))
        result = dataclasses.replace(result, speed=case.speed, warnings=found)
    text = combined_sweep_report(result, fmt, bearing_context(b))
    print_warnings(list(result.warnings), False)
    if plot is not None:
        from bearingload.reports.plots import combined_sweep_figure

        save_plot(lambda: combined_sweep_figure(result, b.designation), plot)
    emit(text, output)


def _combined_sweep(b: Any, case: Case, steps: int, radial: bool) -> Any:
    """:func:`bearingload.studies.combined_sweep.combined_sweep` of the case, a refusal of the
    ball dynamics naming --quasi-static as solve's does."""
    from bearingload.errors import ConvergenceError, InputError
    from bearingload.plan.solve import QUASI_STATIC_WAY, STATIC_PAIR_WAY, speed_hint
    from bearingload.studies.combined_sweep import combined_sweep

    dynamics = case.dynamics_arguments()
    try:
        return combined_sweep(b, case.radial_load, steps=steps, **case.combined_arguments(),
                              **dynamics)  # fmt: skip
    except InputError as exc:
        hinted = speed_hint(exc, radial) if dynamics["speed"] is not None else None
        if hinted is None:
            raise
        raise hinted from exc
    except ConvergenceError as exc:
        if dynamics["speed"] is None:
            raise
        raise exc.with_way_out(QUASI_STATIC_WAY if radial else STATIC_PAIR_WAY) from exc


def _pair(case: Case, steps: int, plot: str | None, fmt: str, output: str | None) -> None:
    """The sweep of a bearing pair (7205BDB, --arrangement): one vectorised pair solve over the
    pitch, then emit."""
    from bearingload.cli.options import print_warnings
    from bearingload.errors import ConvergenceError, InputError
    from bearingload.plan.bearing import bearing_context, pair_bearing
    from bearingload.plan.solve import pair_speed_hint
    from bearingload.reports.pair_sweep import pair_sweep_report
    from bearingload.studies.pair_sweep import pair_sweep

    if plot is not None:
        raise click.UsageError(
            "Invalid value for '--plot': it draws one bearing's ripple, not a pair's; "
            "--format csv gives the pair at every cage position"
        )
    tilt = "the shaft's tilt follows from the loads; give 'moment'"
    case.refuse(("misalignment",), "a bearing pair", tilt)
    fixed = "the design contact angle fixes the geometry of an angular-contact bearing"
    case.refuse(("clearance",), "a bearing pair", fixed + " (no clearance)")
    b = pair_bearing(case)
    args = case.pair_arguments(b.balls)
    del args["cage_angle"]
    dynamics = case.dynamics_arguments()  # at --speed both bearings' ball dynamics
    try:
        result = pair_sweep(b, case.radial_load, case.axial_load or 0.0, steps=steps, **args,
                            **dynamics)  # fmt: skip
    except (ConvergenceError, InputError) as exc:
        hinted = pair_speed_hint(exc) if dynamics["speed"] is not None else None
        if hinted is None:
            raise
        raise hinted from exc
    if case.speed is not None:  # the lives in hours (and the dynamics' speed); the limit
        import dataclasses

        from bearingload.bearings.checks import speed_findings

        found = (*result.warnings, *speed_findings(case.speed, b))
        result = dataclasses.replace(result, speed=case.speed, warnings=found)
    text = pair_sweep_report(result, fmt, bearing_context(b))
    print_warnings(list(result.warnings), False)
    emit(text, output)


def _kurochkin(
    case: Case, t: float, steps: int, plot: str | None, fmt: str, output: str | None
) -> None:
    """The dimensionless mode: refuse the options it does not use, then sweep and emit."""
    extra = [
        n for n in KUROCHKIN_REFUSES if (plot if n == "plot" else getattr(case, n)) is not None
    ]
    if extra:
        name = extra[0].replace("_", "-")
        option = "BEARING" if name == "bearing" else f"--{name}"
        raise click.UsageError(f"{option} cannot be used with --kurochkin-T (P = K = 1).")
    if case.balls is None:
        raise click.UsageError("--kurochkin-T needs --balls.")
    if case.exponent_or(1.5) != 1.5:
        raise click.UsageError("--kurochkin-T is for balls: --exponent must be 3/2.")
    from bearingload.papers.kurochkin import kurochkin_sweep
    from bearingload.reports.kurochkin import kurochkin_report

    emit(kurochkin_report(kurochkin_sweep(case.balls, t, steps), fmt), output)
