"""``bearingload stability``: numerical stability of the solvers on stiff and extreme cases."""

from __future__ import annotations

import click

from bearingload.cli.options import CONTEXT, LibraryOption, emit, library_errors, output_options


@click.command(context_settings=CONTEXT)
@click.option(
    "--size",
    type=click.Choice(["quick", "full"]),
    default="quick",
    show_default=True,
    help="quick: the reduced grid of the test suite (seconds); full: the grid of 'make bench'.",
)
@click.option(
    "--family",
    "families",
    cls=LibraryOption,
    library=("family",),
    multiple=True,
    help="Run only this family (repeatable); default: every family.",
)
@output_options
@library_errors
def stability(size: str, families: tuple[str, ...], fmt: str, output: str | None) -> None:
    """Run the solvers over a grid of stiff and extreme cases and summarise each family.

    Families: clearance through 0, clearance up to 1e12 elastic approaches, load ratios 1e-12 to
    1e12, 1 to 1000 (and 1e5) balls, light to heavy preload, one loaded ball, cage angles at
    load-zone edges, rollers and m = 1, the continuum model near eps = 0, 1, inf, Hertz contact
    for curvature ratios 1 to 1e15, and one family per defect of issue 9's review (d1-d8).
    Per family: cases, largest equilibrium residual (recomputed from the ball loads), largest
    jump between neighbours, batch dependence, iterations, NaN/inf, warnings, refusals, failures
    and the family's own check against its limit.

    \b
    Examples:
      bearingload stability
      bearingload stability --size full --format json -o stability.json
      bearingload stability --family d1_heavy_preload_x --family preload
    """
    from bearingload.reports.render import render
    from bearingload.studies.stability import run, stability_table

    rows = run(size, list(families) or None)
    emit(render([stability_table(rows)], fmt), output)
