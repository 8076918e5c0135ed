"""``bearingload fit``: fit Q = C u^n to a measured load-displacement curve (Kuzmenko & Sabadash 2014)."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import click

from bearingload.cli.options import CONTEXT, LibraryOption, emit, output_options, usage_error
from bearingload.errors import BearingloadError, InputError
from bearingload.units import UNITS


def fit_errors(func: Callable[..., Any]) -> Callable[..., Any]:
    """Turn library errors into one ``Error:`` line; file errors name FILE, the row and the column.

    :func:`bearingload.studies.fit.read_measurements` names the parameter ``"<path> row N, column 'c'"``;
    that becomes ``Invalid value for 'FILE': row N, column 'c': <message>`` (exit status 2).
    """

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        path = str(kwargs.get("file", ""))
        try:
            return func(*args, **kwargs)
        except InputError as exc:
            if path and exc.parameter.startswith(path):
                message = exc.message
                where = exc.parameter[len(path) :].strip()
                text = f"{where}: {message}" if where else message
                raise click.UsageError(f"Invalid value for 'FILE': {text}") from exc
            raise usage_error(exc) from exc
        except BearingloadError as exc:
            raise click.ClickException(str(exc)) from exc

    return wrapper


@click.command(context_settings=CONTEXT)
@click.argument("file", type=click.Path(dir_okay=False))
@click.option(
    "--base",
    "base",
    cls=LibraryOption,
    library=("base_points",),
    multiple=True,
    metavar="LOAD:DISPLACEMENT",
    help="A base point of the two-point fit, e.g. 200kgf:0.8mm; give it twice (bare numbers are "
    "in the file's units). Default: the rows of lowest and highest load.",
)
@click.option(
    "--balls",
    "-z",
    type=click.IntRange(1, 100_000),
    default=None,
    help="Number of balls z, for the theoretical K_Q(z) (bearing 208: 9).",
)
@click.option(
    "--load-unit",
    type=click.Choice(list(UNITS["force"])),
    default="N",
    show_default=True,
    help="Unit of the 'load' column.",
)
@click.option(
    "--displacement-unit",
    type=click.Choice(list(UNITS["length"])),
    default="mm",
    show_default=True,
    help="Unit of the 'displacement' column.",
)
@click.option(
    "--points",
    is_flag=True,
    help="csv: the measured points with the fitted values (one row per point) instead of the "
    "fits (one row per method).",
)
@output_options
@fit_errors
def fit(
    file: str,
    base: tuple[str, ...],
    balls: int | None,
    load_unit: str,
    displacement_unit: str,
    points: bool,
    fmt: str,
    output: str | None,
) -> None:
    """Fit Q = C u^n to measured load-displacement pairs and compare n with K_Q(z).

    FILE is a CSV file with a header naming the columns 'load' and 'displacement' (other columns
    are ignored). The law is fitted through two base points (Kuzmenko & Sabadash 2014, eq. 2.1),
    by least squares on ln Q and by least squares on Q; the report lists R², the residuals, the
    normalised distribution sigma_bar = (u/u_max)^(n-1), and the paper's claim K_Q = n next to the
    theoretical K_Q(z) and the Hertz exponent 3/2 of an ideal clearance-free bearing.

    \b
    Examples:
      # bearing 208, Table 2.1 of Kuzmenko & Sabadash (2014), the paper's base points
      bearingload fit examples/bearing208_kuzmenko2014.csv --load-unit kgf \\
          --base 200kgf:0.8mm --base 1000kgf:1.67mm --balls 9
      # as json (a file of displacements in micrometres takes --displacement-unit um)
      bearingload fit examples/bearing208_kuzmenko2014.csv --load-unit kgf --format json
      # the measured points with the fitted values, as csv
      bearingload fit examples/bearing208_kuzmenko2014.csv --load-unit kgf --format csv --points
    """
    from bearingload.reports.fit import fit_report
    from bearingload.studies.fit_comparison import parse_base_point

    base_points = None
    if base:
        if len(base) != 2:
            raise InputError("base", f"give --base exactly twice or not at all (got {len(base)})")
        base_points = [parse_base_point(b, load_unit, displacement_unit) for b in base]
    text = fit_report(
        file,
        base=base_points,
        points=points,
        balls=balls,
        load_unit=load_unit,
        displacement_unit=displacement_unit,
        fmt=fmt,
    )
    emit(text, output)
