"""``bearingload solve``: one case, every ball's load and a summary with units."""

from __future__ import annotations

from typing import Any

import click

from .options import CONTEXT, CageAngle, Quantity, emit, library_errors, output_options, units_help


@click.command(context_settings=CONTEXT)
@click.option("--balls", "-z", type=int, required=True, help="Number of balls z (1 to 100000).")
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
    required=True,
    help="Ball stiffness K of both contacts in series, Q = K delta^m. "
    f"Units: {units_help('stiffness')} (bare number: N/mm^1.5).",
)
@click.option(
    "--clearance",
    "-G",
    type=Quantity("length"),
    default="0",
    show_default=True,
    help="Radial internal clearance G_r, total play (gap per side G_r/2); negative = preload. "
    f"Units: {units_help('length')} (bare number: mm).",
)
@click.option(
    "--cage-angle",
    type=CageAngle(),
    default="0",
    show_default=True,
    help="Angle of ball 1 from the load line in degrees; 0 = a ball under the load, "
    "'half' = the load between two balls.",
)
@click.option(
    "--exponent",
    "-m",
    type=float,
    default=1.5,
    show_default=True,
    help="Load-deflection exponent m: 1.5 for balls, 1.1111 (10/9) for rollers.",
)
@output_options
@library_errors
def solve(
    balls: int,
    load: float,
    stiffness: float,
    clearance: float,
    cage_angle: Any,
    exponent: float,
    fmt: str,
    output: str | None,
) -> None:
    """Solve the exact ring equilibrium of one bearing: every ball's load and a summary.

    The inner ring moves until the ball forces balance the radial load (DOMAIN: Kurochkin 1973,
    Kuzmenko 2010). Ball 1 sits at the cage angle; balls are numbered counter-clockwise.

    \b
    Examples:
      # bearing 306 of Kuzmenko (2010): 8 balls, 300 kgf, the paper's stiffness, G_r = 20 µm
      bearingload solve -z 8 --load 300kgf --stiffness 4700kgf/mm^1.5 --clearance 20um
      # the load between two balls, 50 µm preload, JSON for a script
      bearingload solve -z 12 -F 5kN -K 3.8e5 -G -50um --cage-angle half --format json
    """
    from ..solve_report import solve_report

    emit(solve_report(balls, load, stiffness, clearance, cage_angle, exponent, fmt), output)
