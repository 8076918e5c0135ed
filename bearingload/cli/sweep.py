"""``bearingload sweep``: the ring equilibrium over one ball pitch of cage positions."""

from __future__ import annotations

from typing import Any

import click

from bearingload.cli.bearing_options import CLEARANCE_HELP, Clearance, geometry_options
from bearingload.cli.cases import resolve_case
from bearingload.cli.options import (
    CONTEXT,
    Quantity,
    emit,
    exponent_option,
    library_errors,
    output_options,
    units_help,
)
from bearingload.cli.plot import check_plot, write_plot


@click.command(context_settings=CONTEXT)
@click.argument("bearing", required=False, metavar="[BEARING]")
@click.option(
    "--balls",
    "-z",
    type=int,
    help="Number of balls z (3 to 100000); required without a BEARING, else an override.",
)
@click.option(
    "--load",
    "-F",
    type=Quantity("force"),
    help=f"Radial load F_r > 0 (required unless --kurochkin-T). Units: {units_help('force')} "
    "(bare number: N).",
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
    "marks, else CN.",
)
@click.option(
    "--clearance-pick",
    type=click.Choice(["min", "mean", "max"]),
    default="mean",
    show_default=True,
    help="Where in a clearance class to take G_r.",
)
@geometry_options
@exponent_option
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
    help="Also draw x, y, Q_max and stiffness over the cage angle into FILE.png "
    "(needs matplotlib: pip install 'bearingload[plot]').",
)
@click.option(
    "--kurochkin-T",
    "kurochkin_t",
    type=float,
    help="Kurochkin's dimensionless mode (1973): P = K = 1 and the gap from his parameter T, "
    "eq. (1.13); rows give F0 = x0 and F0' = -y0, the summary the contact sequence, exit angle "
    "and Fourier coefficients F0j'. Needs --balls (>= 5) only.",
)
@output_options
@library_errors
def sweep(
    bearing: str | None,
    balls: int | None,
    load: float | None,
    stiffness: str | None,
    clearance: Any,
    clearance_pick: str,
    ball_diameter: float | None,
    pitch_diameter: float | None,
    inner_conformity: float | None,
    outer_conformity: float | None,
    modulus: float | None,
    poisson: float | None,
    exponent: float,
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

    The bearing and condition options are those of 'bearingload solve'. csv: one row per cage
    angle with the inputs as columns; json: rows, a summary and units.

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
    """
    if kurochkin_t is not None:
        given = dict(bearing=bearing, load=load, stiffness=stiffness, clearance=clearance,
                     plot=plot, ball_diameter=ball_diameter, pitch_diameter=pitch_diameter,
                     inner_conformity=inner_conformity, outer_conformity=outer_conformity,
                     modulus=modulus, poisson=poisson)  # fmt: skip
        _kurochkin(balls, kurochkin_t, steps, exponent, given, fmt, output)
        return
    if load is None:
        raise click.UsageError("Missing option '--load' / '-F' (or give --kurochkin-T).")
    if plot is not None:
        check_plot(plot)
    z, k, g_r, m, context = resolve_case(
        bearing,
        balls,
        stiffness,
        clearance,
        clearance_pick,
        exponent,
        dict(
            ball_diameter=ball_diameter,
            pitch_diameter=pitch_diameter,
            f_i=inner_conformity,
            f_o=outer_conformity,
            modulus=modulus,
            poisson=poisson,
        ),
    )
    from bearingload.reports.sweep import sweep_report
    from bearingload.studies.sweep import sweep as run_sweep

    result = run_sweep(z, load, k, g_r, m, steps)
    text = sweep_report(result, fmt, context)
    from bearingload.reports.sweep import sweep_warnings

    for warning in sweep_warnings(result):
        click.echo(f"Warning: {warning}", err=True)
    if plot is not None:
        from bearingload.reports.plots import save_png, sweep_figure

        write_plot(lambda: save_png(sweep_figure(result), plot), plot)
    emit(text, output)


def _kurochkin(
    balls: int | None,
    t: float,
    steps: int,
    exponent: float,
    given: dict[str, Any],
    fmt: str,
    output: str | None,
) -> None:
    """The dimensionless mode: refuse the options it does not use, then sweep and emit."""
    extra = [k for k, v in given.items() if v is not None]
    if extra:
        name = extra[0].replace("_", "-")
        option = "BEARING" if name == "bearing" else f"--{name}"
        raise click.UsageError(f"{option} cannot be used with --kurochkin-T (P = K = 1).")
    if balls is None:
        raise click.UsageError("--kurochkin-T needs --balls.")
    if exponent != 1.5:
        raise click.UsageError("--kurochkin-T is for balls: --exponent must be 3/2.")
    from bearingload.reports.kurochkin import kurochkin_report
    from bearingload.studies.kurochkin import kurochkin_sweep

    emit(kurochkin_report(kurochkin_sweep(balls, t, steps), fmt), output)
