"""``bearingload batch``: many cases from a csv file, one output row per case."""

from __future__ import annotations

import contextlib
import sys
import time
from collections.abc import Callable, Iterator
from itertools import compress
from typing import Any, BinaryIO

import click

from bearingload.cli.options import CONTEXT, library_errors, output_options, quiet_option

#: Warnings shown on the terminal; json lists every row's warnings.
MAX_WARNINGS_SHOWN = 20


@click.command(context_settings=CONTEXT)
@click.argument("cases", type=click.File("rb"), metavar="CASES.csv")
@click.option(
    "--strict",
    is_flag=True,
    help="Stop at the first bad row (exit 2) and write nothing, instead of skipping it.",
)
@click.option(
    "--chunk-size",
    type=click.IntRange(min=1),
    default=None,
    help="Rows read, solved and written at a time; the output does not depend on it. "
    "Default: 10000.",
)
@output_options
@quiet_option
@library_errors
def batch(
    cases: BinaryIO, strict: bool, chunk_size: int | None, fmt: str, output: str | None, quiet: bool
) -> None:
    """Solve every case (row) of a csv file: one output row per case, in input order, with the
    input file's row number (the header is row 1), the inputs and the columns that
    'bearingload solve --format csv' writes for one case (docs/batch.md).

    CASES.csv ('-': standard input) names its columns like the options of 'solve', each cell
    read as solve reads the option: load (required), balls and stiffness, or bearing (a
    catalogue designation) and/or the ball geometry (ball_diameter, pitch_diameter,
    inner_conformity, outer_conformity, modulus, poisson, ball_material: steel or si3n4), the
    mounting (shaft_fit, housing_fit, shaft_bore, housing_diameter, inner_ring_temperature,
    outer_ring_temperature), clearance (a length or a class C2 CN C3 C4 C5) with clearance_pick
    (min, mean, max), cage_angle (degrees or 'half'), exponent, method, revolutions. A missing
    column or an empty cell takes solve's default. A unit in the header (load [kN]) is the unit
    of the column's bare numbers; a number with its own unit (300kgf) keeps it. An unknown
    column is an error (exit 2).

    As for 'solve', the load alone chooses a row's engine: a cell in axial_load, moment,
    moment_cross or misalignment makes the row a combined-load case (3-D ring equilibrium,
    ISO/TS 16281 L10r, ISO 281 L10; load may then be 0), with tilt_radius (groove, pitch or a
    length) the lever of its tilt. A file with one of these columns writes the columns solve
    writes with an axial load, names a bearing or the ball geometry, and has no method,
    exponent or revolutions column. A column arrangement, preload or width makes every row a
    bearing pair (two output rows, as solve 7205BDB).

    dynamic_rating and rotating feed the lives only, as do the operating conditions
    (static_rating, speed, reliability, viscosity, contamination, eC, fatigue_load_limit,
    roughness, pressure_viscosity; or the oil: oil or viscosity_40 with temperature, and
    viscosity_100 or viscosity_index). A row of a ball bearing with a speed is solved with the
    ball dynamics (docs/speed.md): quasi_static (true or false; blank: false) true keeps the
    static model; ball_density (kg/m^3, bare numbers; default bearing steel 7850) gives the
    ball mass. json adds to such rows their model and every ball's inner and outer contact
    angle and load (contact_angles_inner, contact_angles_outer, ball_loads_inner,
    ball_loads_outer).

    A bad row (a negative load, an unknown unit or bearing, a line with the wrong number of
    cells or not UTF-8 text) is skipped: the output keeps it with its row number and reason
    (csv: the last column, skipped; json: skipped; table and markdown: the notes) and standard
    error names it ('Skipped: row N: reason', apart from the warnings of the solved rows); the
    exit status is then 1 (2: a bad command line or header, or a bad row with --strict). A last
    line on standard error counts the rows solved and skipped and the warnings (where a row was
    skipped or warned, or the file has no data rows); -q leaves that line alone.

    Rows that share a bearing and an engine are solved together, chunk by chunk, by one
    vectorised call; each row's answer depends on its own cells only. csv is streamed (-o
    written whole at the end); json, markdown and table hold every row (at most 100000).

    \b
    Examples:
      # the example file: rings given by hand, catalogue bearings 306 and 6306, two methods
      bearingload batch examples/cases.csv --format csv
      # a design sweep from a script, read from standard input, written whole to a file
      python make_cases.py | bearingload batch - --format csv -o results.csv
      # stop at the first bad row, write nothing
      bearingload batch examples/cases.csv --strict --format json
      # combined loads: axial load, moment or misalignment, L10r (ISO/TS 16281) per row
      bearingload batch examples/combined_cases.csv --format csv
      # a speed column: the ball dynamics (quasi_static, ball_density), per-ball contacts in json
      bearingload batch examples/speed_cases.csv --format json
    """
    from bearingload.batch import report
    from bearingload.batch.read import CHUNK_ROWS, read_cases
    from bearingload.batch.solve import BatchSolver
    from bearingload.errors import InputError
    from bearingload.reports.render import csv_header

    if output == "":
        raise click.UsageError("Invalid value for '-o' / '--output': the file name is empty")
    try:
        header, blocks = read_cases(cases, chunk_size or CHUNK_ROWS)
    except InputError as exc:  # a column's unit is named with it ('load [kN]: ...')
        own = exc.parameter in ("CASES", "columns")
        where, message = ("", exc.message) if own else (" header", str(exc))
        raise click.UsageError(f"Invalid value for 'CASES.csv'{where}: {message}") from exc
    columns, solver = report.batch_columns(header), BatchSolver(header)
    written, held = [*columns, report.SKIPPED], report.Held(header, columns)  # csv's; the others'
    skipped: list[tuple[int, str]] = []
    warned = total = 0
    progress = _Progress()
    with _sink(output, strict) as write:
        if fmt == "csv":
            write(csv_header(written))
        for block in blocks:
            total += len(block.numbers) + len(block.errors)
            part = solver.solve(block)
            if part.errors and strict:
                row, message = part.errors[0]
                raise click.UsageError(f"Invalid value in row {row}: {message}")
            skipped += part.errors
            warned = _row_messages(part, warned, progress, quiet)
            if fmt == "csv":
                write(report.csv_chunk(written, part))
            elif not held.add(part):
                raise click.UsageError(
                    f"Invalid value for '--format': {fmt} holds every row and takes at most "
                    f"{report.MAX_HELD_ROWS} rows; write --format csv for longer files"
                )
            progress.update(total)
        progress.clear()
        if fmt != "csv":
            write(held.report(skipped, fmt))
    _summary(total, len(skipped), warned, quiet)
    if skipped:
        click.get_current_context().exit(1)


def _summary(total: int, skipped: int, warned: int, quiet: bool) -> None:
    """The last line on stderr: the rows solved and skipped and the warnings (said where there
    were skipped rows or warnings, or no rows), after the count of warnings not shown."""
    if warned > MAX_WARNINGS_SHOWN and not quiet:
        click.echo(
            f"Warning: {warned - MAX_WARNINGS_SHOWN} more warnings not shown (--format json "
            "lists every row's warnings)",
            err=True,
        )
    if skipped or warned or not total:
        where = "; the output names each skipped row and its reason" if skipped else ""
        where = where if total else "; the file has no data rows"
        status = " (exit status 1)" if skipped else ""
        click.echo(
            f"{total - skipped} of {total} rows solved, {skipped} skipped{status}, "
            f"{warned} warning{'' if warned == 1 else 's'}{where}",
            err=True,
        )


def _row_messages(part: Any, warned: int, progress: _Progress, quiet: bool) -> int:
    """Print the chunk's ``Skipped: row N: reason`` and ``Warning: row N: ...`` lines in row
    order (stderr does not depend on --chunk-size), at most :data:`MAX_WARNINGS_SHOWN` warnings
    in all (``quiet``: no line); return the number of warnings so far."""
    found = part.values.get("warnings", [])
    messages = [(row, text, False) for row, text in part.errors]
    for i in compress(range(len(found)), found):
        messages += [(part.rows[i], text, True) for text in found[i]]
    for row, text, warning in sorted(messages, key=lambda m: m[0]):  # stable: a row's order
        warned += warning
        if not quiet and (not warning or warned <= MAX_WARNINGS_SHOWN):
            progress.clear()
            click.echo(f"{'Warning' if warning else 'Skipped'}: row {row}: {text}", err=True)
    return warned


@contextlib.contextmanager
def _sink(output: str | None, strict: bool) -> Iterator[Callable[[str], Any]]:
    """``write(text)`` of the report: to ``-o FILE`` (atomic_file), to a spool copied to
    standard output at the end (``--strict``), or to standard output chunk by chunk; an error
    inside the block writes nothing (a file is left as it was; an OSError of it a bad -o)."""
    if output not in (None, "-"):
        from bearingload.reports.render import atomic_file

        try:
            with atomic_file(output) as fh:
                yield fh.write
        except OSError as exc:
            raise click.UsageError(
                f"Invalid value for '-o' / '--output': cannot write {output!r}: {exc.strerror}"
            ) from exc
    elif strict:
        import tempfile

        with tempfile.TemporaryFile("w+", encoding="utf-8", newline="\n") as spool:
            yield spool.write
            spool.seek(0)
            while block := spool.read(1 << 20):
                click.echo(block, nl=False)
    else:
        yield lambda text: click.echo(text, nl=False)


class _Progress:
    """Rows done, on standard error when it is a terminal and the run has taken over a second."""

    def __init__(self) -> None:
        self.start, self.tty, self.shown = time.monotonic(), sys.stderr.isatty(), False

    def update(self, rows: int) -> None:
        if self.tty and time.monotonic() - self.start > 1.0:
            click.echo(f"\rbatch: {rows} rows solved or skipped", err=True, nl=False)
            self.shown = True

    def clear(self) -> None:
        if self.shown:
            click.echo("\r" + " " * 40 + "\r", err=True, nl=False)
            self.shown = False
