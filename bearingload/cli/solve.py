"""``bearingload solve``: one case, every ball's load and a summary with units.

The command parses its options into a :class:`~bearingload.plan.case.Case`, hands it to the plan
(:func:`bearingload.plan.solve.solve_case`: the engine, the refusals, the lives and warnings) and
renders the :class:`~bearingload.plan.solution.Solution`."""

from __future__ import annotations

import click

from bearingload.cli.case_options import case_options
from bearingload.cli.options import (
    CONTEXT,
    Quantity,
    emit,
    library_errors,
    method_option,
    option_message,
    output_options,
    print_warnings,
    quiet_option,
)
from bearingload.cli.plot import ball_loads_plot_option, check_plot, save_plot
from bearingload.plan.case import Case
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
    case: Case,
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
    from bearingload.plan.solve import solve_case

    given = click.get_current_context().get_parameter_source("revolutions")
    life = revolutions if given not in (None, click.core.ParameterSource.DEFAULT) else None
    if plot is not None:  # the file name before any work
        check_plot(plot)
    solution = solve_case(case, method=method, revolutions=life, spell=option_message)
    if plot is not None:
        _check_plot(solution.engine, method)
    text = solution.report(fmt, per_ball=per_ball, show_geometry=show_geometry)
    if plot is not None:
        save_plot(solution.figure, plot)  # the figure of this very solution, written whole
    emit(text, output)
    print_warnings(solution.warnings, quiet)


def _check_plot(engine: str, method: str) -> None:
    """Refuse --plot where the solution has no ball loads of one bearing to draw."""
    if engine == "pair":
        raise click.UsageError(
            "Invalid value for '--plot': it draws the ball loads of one bearing, not of a pair"
        )
    if engine == "radial" and method not in ("exact", "all"):
        raise click.UsageError(
            f"Invalid value for '--plot': it draws the ball loads of the exact model; "
            f"--method {method} gives none (use --method exact or all)"
        )
