"""``bearingload errata``: every number the papers print that the project recomputes."""

from __future__ import annotations

import click

from bearingload.cli.options import CONTEXT, emit, library_errors, output_options


@click.command(context_settings=CONTEXT)
@click.option(
    "--paper",
    help="Only the papers whose name contains this text (any case), e.g. 'Sabadash', '2010'.",
)
@click.option("--only-differing", is_flag=True, help="Only the printed numbers that differ.")
@click.option(
    "--summary",
    is_flag=True,
    help="Per paper and table: how many are checked, how many differ (with --only-differing: "
    "only the tables where some differ).",
)
@output_options
@library_errors
def errata(
    paper: str | None, only_differing: bool, summary: bool, fmt: str, output: str | None
) -> None:
    """List every printed number of the papers that the project recomputes.

    One row each: paper, table (or equation, section), cell, the value as printed, the value
    computed by this package, their difference, the verdict (agrees within the printed rounding,
    or differs) and the cause where it is known. Nothing is fitted to a printed number.

    \b
    Examples:
      bearingload errata
      bearingload errata --only-differing
      bearingload errata --summary
      bearingload errata --summary --only-differing
      bearingload errata --paper sabadash --format csv -o errata.csv
    """
    from bearingload.reports.errata import errata_report

    emit(errata_report(fmt, only_differing=only_differing, summary=summary, paper=paper), output)
