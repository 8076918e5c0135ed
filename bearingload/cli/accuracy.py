"""``bearingload accuracy``: the work-precision report of every method for Q_max."""

from __future__ import annotations

import click

from bearingload.cli.options import CONTEXT, emit, library_errors, output_options


@click.command(context_settings=CONTEXT)
@click.option(
    "--repeats",
    type=click.IntRange(1, 100),
    default=5,
    show_default=True,
    help="Timing: best of this many runs.",
)
@click.option(
    "--timing/--no-timing",
    default=True,
    show_default=True,
    help="Measure run times (they vary from run to run; without them the report is the "
    "committed tables/accuracy.*).",
)
@click.option(
    "--plot",
    "plot_file",
    type=click.Path(dir_okay=False, writable=True),
    help="Also draw the work-precision diagram (log error against log time per case) as PNG "
    "into FILE; needs the plot extra (matplotlib).",
)
@output_options
@library_errors
def accuracy(
    repeats: int, timing: bool, plot_file: str | None, fmt: str, output: str | None
) -> None:
    """Error of Q_max against run time for every method, on fixed sets of cases.

    Methods on 50 radial cases: the exact solver at tolerances 1e-2 to 1e-14, Kuzmenko's (2010)
    trial angles at 1°, 0.1° and 0.01°, the continuum model at several quadrature orders, a
    J_r(eps) table read by linear interpolation, Stribeck (4.37/z) and Palmgren (5/z); errors
    relative to the exact ring equilibrium at 50 digits (mpmath). The combined-load solver (the
    ISO/TS 16281 ring equilibrium of 'solve' with --axial-load, --moment, --misalignment) on 12
    cases of a 6305-size bearing in three groups, with clearance, under preload (to -30 µm) and
    with an imposed misalignment (0.05° and exactly 0), against the same model at 40 digits
    (mpmath); per case the worse of one case per call and the group in one call. Times are per
    case, one case per call and vectorised.

    \b
    Examples:
      bearingload accuracy
      bearingload accuracy --format json -o accuracy.json
      bearingload accuracy --no-timing --format markdown
      bearingload accuracy --plot work-precision.png
    """
    if plot_file is not None and not timing:
        raise click.UsageError("Invalid value for '--plot': the diagram needs --timing")
    if plot_file == "":
        raise click.UsageError("Invalid value for '--plot': the file name is empty")
    from bearingload.quality.accuracy import measure
    from bearingload.reports.accuracy import accuracy_table
    from bearingload.reports.render import render

    rows = measure(timing=timing, repeats=repeats)
    text = render([accuracy_table(rows)], fmt)
    if plot_file is not None:
        from bearingload.reports.accuracy_plot import plot_work_precision

        try:
            plot_work_precision(rows, plot_file)
        except OSError as exc:
            raise click.UsageError(
                f"Invalid value for '--plot': cannot write {plot_file!r}: {exc.strerror}"
            ) from exc
    emit(text, output)
