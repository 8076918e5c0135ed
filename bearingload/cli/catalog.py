"""``bearingload catalog``: list and filter the bearing catalogue, show one entry with sources."""

from __future__ import annotations

import click

from bearingload.cli.case_options import maker_option
from bearingload.cli.options import (
    CONTEXT,
    LibraryArgument,
    Quantity,
    emit,
    library_errors,
    output_options,
)


@click.group(context_settings=CONTEXT, invoke_without_command=True)
@click.option(
    "--series",
    help="Dimension series: 60, 62, 63, 64, 618 (68), 619 (69), 160 (or GOST style 2, 3, 4; 62xx).",
)
@click.option("--standard", help="GOST or ISO (any case).")
@click.option(
    "--type",
    "kind",
    type=click.Choice(["deep-groove", "angular"]),
    default="deep-groove",
    show_default=True,
    help="Which rows: deep groove ball bearings, or single-row angular-contact ball bearings "
    "(with their contact angle; --bore filters them, --series and --standard do not apply).",
)
@click.option("--bore", type=Quantity("length"), help="Bore diameter d. Bare number: mm.")
@output_options
@click.pass_context
@library_errors
def catalog(
    ctx: click.Context,
    series: str | None,
    standard: str | None,
    kind: str,
    bore: float | None,
    fmt: str,
    output: str | None,
) -> None:
    """List the deep groove ball bearings of the catalogue, optionally filtered.

    Each row carries its boundary dimensions, ball set (where known), groove conformities and
    load ratings; 'catalog show DESIGNATION' prints one entry with the sources of its numbers.

    \b
    Examples:
      bearingload catalog
      bearingload catalog --series 63 --standard ISO --format csv
      bearingload catalog --bore 30
      bearingload catalog --type angular
      bearingload catalog show 306
      bearingload catalog show 7205B
    """
    if ctx.invoked_subcommand is not None:
        return
    from bearingload.reports.catalog import angular_list, catalog_list

    if kind == "angular":
        if series is not None or standard is not None:
            raise click.UsageError(
                "Invalid value for '--type': the angular-contact rows are filtered by --bore "
                "only (not --series or --standard)"
            )
        emit(angular_list(fmt, bore=bore), output)
        return
    emit(catalog_list(fmt, series=series, standard=standard, bore=bore), output)


@catalog.command(context_settings=CONTEXT)
@click.argument("designation", cls=LibraryArgument, library=("bearing",))
@maker_option
@output_options
@library_errors
def show(designation: str, maker: str | None, fmt: str, output: str | None) -> None:
    """Print one catalogue entry: dimensions, ball set, ratings, and where each came from.

    \b
    Examples:
      bearingload catalog show 306
      bearingload catalog show 6306-2RS/C3 --format json
      bearingload catalog show 6208 --maker SKF
      bearingload catalog show 7205B
    """
    from bearingload.reports.catalog import catalog_entry

    text = catalog_entry(designation, fmt, maker)
    emit(text, output)
