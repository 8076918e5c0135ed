"""``bearingload table``: the classical design tables, regenerated exactly."""

from __future__ import annotations

from typing import Any

import click

from bearingload.cli.bearing_options import CLEARANCE_HELP, Clearance, geometry_options
from bearingload.cli.options import (
    CONTEXT,
    Quantity,
    cage_angle_option,
    emit,
    exponent_option,
    library_errors,
    maker_option,
    method_option,
    output_options,
    stiffness_value,
)

TABLES = ("k", "kq")


@click.command(context_settings=CONTEXT)
@click.argument("name", type=click.Choice(TABLES))
@click.option(
    "--z-max", type=click.IntRange(1, 1000), default=30, show_default=True, help="Largest z."
)
@click.option(
    "--load",
    "-F",
    type=Quantity("force"),
    default="1000",
    show_default=True,
    help="Radial load F_r (matters only with clearance). Bare number: N.",
)
@click.option(
    "--bearing",
    "-b",
    help="Catalogue designation (306, 6306): K is the exact Hertz stiffness of its ball and "
    "raceways, a clearance class is resolved by its bore.",
)
@click.option(
    "--stiffness",
    "-K",
    type=Quantity("stiffness"),
    help="Ball stiffness K (matters only with clearance); default 1e5 N/mm^1.5, or the Hertz "
    "value of --bearing. Bare number: N/mm^1.5.",
)
@click.option("--clearance", "-G", type=Clearance(), help=CLEARANCE_HELP + " Default: 0.")
@click.option(
    "--clearance-pick",
    type=click.Choice(["min", "mean", "max"]),
    default="mean",
    show_default=True,
    help="Where in a clearance class to take G_r.",
)
@geometry_options
@cage_angle_option
@exponent_option
@method_option(
    "The model the table is computed with (see 'bearingload solve --help'); all: one table "
    "comparing every method with its error against the exact answer."
)
@maker_option
@output_options
@library_errors
def table(
    name: str,
    z_max: int,
    load: float,
    bearing: str | None,
    stiffness: str | None,
    clearance: Any,
    clearance_pick: str,
    ball_diameter: float | None,
    pitch_diameter: float | None,
    inner_conformity: float | None,
    outer_conformity: float | None,
    modulus: float | None,
    poisson: float | None,
    cage_angle: Any,
    exponent: float,
    method: str,
    maker: str | None,
    fmt: str,
    output: str | None,
) -> None:
    """Print a design table for z = 1..z-max balls.

    \b
    NAME  k   Table 1 of Kuzmenko (2010): k = Q_max/F_r and loaded balls n
          kq  Table 2.2 of Kuzmenko & Sabadash (2014): K_Q = k z/2

    By default the paper's conditions: zero clearance, a ball under the load. With --clearance the
    answer depends on load and stiffness, so give those too.

    \b
    Examples:
      bearingload table k
      bearingload table kq --format csv -o kq.csv
      bearingload table k --clearance 20um --load 300kgf --stiffness 4700kgf/mm^1.5
      bearingload table k --cage-angle half --z-max 40
      # Table 1 for the ball and raceways of bearing 306 (exact Hertz K), 300 kgf, 20 µm
      bearingload table k --bearing 306 --load 300kgf --clearance 20um
      # exact, continuum, Stribeck and Palmgren side by side for z = 1-30
      bearingload table k --method all
    """
    from bearingload.reports.render import render
    from bearingload.reports.tables import design_table

    k_given = stiffness_value(stiffness, exponent)  # N/mm^m
    geometry = dict(ball_diameter=ball_diameter, pitch_diameter=pitch_diameter,
                    f_i=inner_conformity, f_o=outer_conformity, modulus=modulus, poisson=poisson)  # fmt: skip
    if bearing is not None:
        cond = _bearing_conditions(bearing, load, k_given, clearance, clearance_pick, cage_angle,
                                   exponent, dict(geometry, maker=maker))  # fmt: skip
    elif any(v is not None for v in geometry.values()):
        raise click.UsageError(
            "the geometry and material options (--ball-diameter ... --poisson) need --bearing"
        )
    else:
        from bearingload.bearings.clearance import clearance_length
        from bearingload.studies.tables import Conditions

        k = 1e5 if k_given is None else k_given
        cond = Conditions(load, k, clearance_length(clearance), cage_angle, exponent)
    emit(render([design_table(name, z_max, cond, method)], fmt), output)


def _bearing_conditions(
    bearing: str,
    load: float,
    k_given: float | None,
    clearance: Any,
    clearance_pick: str,
    cage_angle: Any,
    exponent: float,
    geometry: dict[str, Any],
) -> Any:
    """The conditions of a catalogue bearing's ball and raceways (Hertz K, its clearance)."""
    from bearingload.bearings.resolve import resolve_bearing
    from bearingload.studies.tables import for_bearing

    if exponent != 1.5:
        raise click.UsageError(
            "Invalid value for '--exponent': a ball bearing (Hertz point contact) has m = 1.5"
        )
    resolved = resolve_bearing(
        bearing,
        stiffness=k_given,
        clearance=clearance if clearance is not None else 0.0,
        clearance_pick=clearance_pick,
        **geometry,
    )
    if resolved.kind != "ball":
        raise click.UsageError(
            "Invalid value for '--bearing': the tables take ball bearings; for a roller "
            "bearing use 'bearingload solve' or --exponent 10/9 with --stiffness"
        )
    return for_bearing(resolved, load, cage_angle)
