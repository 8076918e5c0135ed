"""``bearingload solve``: one case, every ball's load and a summary with units."""

from __future__ import annotations

from typing import Any

import click

from bearingload.cli.bearing_options import CLEARANCE_HELP, Clearance, geometry_options
from bearingload.cli.options import (
    CONTEXT,
    Quantity,
    cage_angle_deg,
    cage_angle_option,
    emit,
    exponent_option,
    library_errors,
    method_option,
    output_options,
    stiffness_value,
    units_help,
)


@click.command(context_settings=CONTEXT)
@click.argument("bearing", required=False, metavar="[BEARING]")
@click.option(
    "--balls",
    "-z",
    type=int,
    help="Number of balls z (1 to 100000); required without a BEARING, else an override.",
)
@click.option(
    "--load",
    "-F",
    type=Quantity("force"),
    required=True,
    help=f"Radial load F_r > 0. Units: {units_help('force')} (bare number: N).",
)
@click.option(
    "--stiffness",
    "-K",
    type=Quantity("stiffness"),
    help="Ball stiffness K of both contacts in series, Q = K delta^m; required without a "
    "BEARING or ball geometry, else it replaces the Hertz value. "
    f"Units: {units_help('stiffness')} (bare number: N/mm^1.5).",
)
@click.option(
    "--clearance",
    "-G",
    type=Clearance(),
    help=CLEARANCE_HELP + " Default: without a BEARING 0; with one, the class its designation "
    "marks, else CN (an unmarked designation means the normal group).",
)
@click.option(
    "--clearance-pick",
    type=click.Choice(["min", "mean", "max", "range"]),
    default="mean",
    show_default=True,
    help="Where in a clearance class to take G_r; 'range' solves at min, mean and max and "
    "prints them side by side.",
)
@geometry_options
@click.option(
    "--revolutions",
    type=click.FloatRange(min=0, max=1e30, min_open=True),
    default=36e6,
    show_default=True,
    help="Life L [revolutions] for the allowable load C/(L/10^6)^(1/3). The default is the "
    "worked value of Kuzmenko (2010) §3.2 (36e6 rev, e.g. 1000 h at 600 rpm); set your own.",
)
@cage_angle_option
@exponent_option
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
@output_options
@library_errors
def solve(
    bearing: str | None,
    balls: int | None,
    load: float,
    stiffness: str | None,
    clearance: Any,
    clearance_pick: str,
    ball_diameter: float | None,
    pitch_diameter: float | None,
    inner_conformity: float | None,
    outer_conformity: float | None,
    modulus: float | None,
    poisson: float | None,
    revolutions: float,
    cage_angle: Any,
    exponent: float,
    method: str,
    per_ball: bool,
    show_geometry: bool,
    fmt: str,
    output: str | None,
) -> None:
    """Solve the ring equilibrium of one bearing: the heaviest ball load, how many balls carry,
    the load zone, the ring displacement and stiffness, and every ball's load.

    The inner ring moves until the ball forces balance the radial load (Kurochkin 1973,
    Kuzmenko 2010). Ball 1 sits at the cage angle; balls are numbered counter-clockwise.

    BEARING is a catalogue designation (306, 6306-2RS/C3, 75-313; see 'bearingload catalog'):
    its ball set gives the exact Hertz ball stiffness, its bore resolves a clearance class, its
    rating C gives the life (C/F_r)^3; --show-geometry prints the source of every value.
    Without a BEARING give --balls and --stiffness (or the ball geometry).

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
    """
    from bearingload.models.registry import list_methods
    from bearingload.reports.solve import solve_report

    if not revolutions == revolutions:  # NaN passes click's range check
        raise click.UsageError(
            "Invalid value for '--revolutions': must be a number of revolutions > 0, got nan"
        )
    k_given = stiffness_value(stiffness, exponent)  # N/mm^m
    methods = list_methods() if method == "all" else [method]
    if bearing is None and ball_diameter is None and pitch_diameter is None:
        cases = _by_hand(methods, balls, load, k_given, clearance, cage_angle, exponent)
    else:
        cases = _catalogue(methods, bearing, load, k_given, clearance, clearance_pick, cage_angle,
                           exponent, revolutions, balls=balls, ball_diameter=ball_diameter,
                           pitch_diameter=pitch_diameter, f_i=inner_conformity,
                           f_o=outer_conformity, modulus=modulus, poisson=poisson)  # fmt: skip
    emit(solve_report(cases, fmt, per_ball=per_ball, show_geometry=show_geometry), output)


def _by_hand(
    methods: list[str],
    balls: int | None,
    load: float,
    k_given: float | None,
    clearance: Any,
    cage_angle: Any,
    exponent: float,
) -> list[Any]:
    from bearingload.bearings.clearance import clearance_length
    from bearingload.studies.loaded_bearing import solve_ring

    if balls is None:
        raise click.UsageError("Missing option '--balls' / '-z' (or give a BEARING designation)")
    if k_given is None:
        raise click.UsageError(
            "Missing option '--stiffness' / '-K' (or give a BEARING designation, or "
            "--ball-diameter and --pitch-diameter)"
        )
    angle = cage_angle_deg(cage_angle, balls)
    return solve_ring(methods, balls, load, k_given, clearance_length(clearance), angle, exponent)


def _catalogue(
    methods: list[str],
    bearing: str | None,
    load: float,
    k_given: float | None,
    clearance: Any,
    clearance_pick: str,
    cage_angle: Any,
    exponent: float,
    revolutions: float,
    **geometry: Any,
) -> list[Any]:
    from bearingload.bearings.resolve import resolve_bearing
    from bearingload.studies.loaded_bearing import solve_bearing

    if exponent != 1.5:
        raise click.UsageError(
            "Invalid value for '--exponent': a ball bearing (Hertz point contact) has m = 1.5; "
            "other exponents need --balls and --stiffness without a BEARING"
        )
    resolved = resolve_bearing(
        bearing,
        stiffness=k_given,
        clearance=clearance,
        clearance_pick="mean" if clearance_pick == "range" else clearance_pick,
        **geometry,
    )
    if clearance_pick == "range" and resolved.clearance_range is None:
        raise click.UsageError(
            "Invalid value for '--clearance-pick': 'range' needs a clearance class "
            "(C2 CN C3 C4 C5), not a clearance length"
        )
    picks = ["min", "mean", "max"] if clearance_pick == "range" else []
    bearings = [resolved.with_clearance(p) for p in picks] or [resolved]
    angle = cage_angle_deg(cage_angle, resolved.balls)
    return solve_bearing(bearings, load, angle, methods, revolutions)
