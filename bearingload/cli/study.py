"""``bearingload study``: the project's fixed studies of the papers, one table each."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import click

from bearingload.cli.options import CONTEXT, emit, library_errors, output_options


def _studies() -> dict[str, Callable[[], Any]]:
    """Study name -> function building its :class:`~bearingload.reports.render.Table`."""
    from bearingload.reports.life_clearance import life_vs_clearance_table
    from bearingload.reports.papers import (
        compliance_fits_table,
        crane_stiffness_table,
        kurochkin1973_differences_table,
        kurochkin1973_example1_table,
    )

    return {
        "kurochkin1973-differences": kurochkin1973_differences_table,
        "kurochkin1973-example1": kurochkin1973_example1_table,
        "compliance-fits": compliance_fits_table,
        "crane2009-stiffness": crane_stiffness_table,
        "life-vs-clearance-6205": life_vs_clearance_table,
    }


#: The names of :func:`_studies`, without importing the studies (the help lists them).
STUDIES = (
    "kurochkin1973-differences",
    "kurochkin1973-example1",
    "compliance-fits",
    "crane2009-stiffness",
    "life-vs-clearance-6205",
)


@click.command(context_settings=CONTEXT)
@click.argument("name", type=click.Choice(STUDIES), metavar="NAME")
@output_options
@library_errors
def study(name: str, fmt: str, output: str | None) -> None:
    """Print one of the project's fixed studies of the papers (no inputs: a fixed set of cases).

    \b
    NAME  kurochkin1973-differences  the printed cells of Kurochkin (1973), Tables 1-4 and
                                     Example 1, that differ from the exact model
          kurochkin1973-example1     his Example 1: the conservative moment over one pitch
          compliance-fits            the compliance abstract's fits (7), (8) against the exact
                                     ring equilibrium
          crane2009-stiffness        the crane paper's (2009) radial stiffness against the
                                     exact equilibrium
          life-vs-clearance-6205     L10r (ISO/TS 16281) of a 6205 against its clearance,
                                     radial load alone and with an axial load side by side

    These are the tables committed under tables/ (see tables/manifest.toml); 'table life'
    computes the life against clearance for any bearing and load.

    \b
    Examples:
      bearingload study kurochkin1973-differences
      bearingload study life-vs-clearance-6205 --format csv -o life.csv
    """
    from bearingload.reports.render import render

    emit(render([_studies()[name]()], fmt), output)
