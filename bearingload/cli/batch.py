"""``bearingload batch``: many cases from a csv file, one output row per case."""

from __future__ import annotations

import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from itertools import compress
from typing import Any, BinaryIO

import click

from bearingload.cli.options import CONTEXT, library_errors, output_options

#: Rows of a first chunk from which the run is tuned for a long file (:func:`_tuned`).
LONG_CHUNK = 20_000

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
    "Default: 50000, or 10000 for combined-load cases.",
)
@output_options
@library_errors
def batch(
    cases: BinaryIO, strict: bool, chunk_size: int | None, fmt: str, output: str | None
) -> None:
    """Solve every case (row) of a csv file: one output row per case, in input order, with the
    input file's row number (the header is row 1), the inputs and the columns that
    'bearingload solve --format csv' writes for one case.

    CASES.csv ('-': standard input) names its columns like the options of 'solve': load
    (required), balls and stiffness, or bearing (a catalogue designation) and/or the ball
    geometry (ball_diameter, pitch_diameter, inner_conformity, outer_conformity, modulus,
    poisson), clearance (a length or a class C2 CN C3 C4 C5) with clearance_pick (min, mean,
    max), cage_angle (degrees or 'half'), exponent, method, revolutions. A missing column or
    an empty cell takes solve's default. A unit in the header (load [kN]) is the unit of the
    column's bare numbers; a number with its own unit (300kgf) keeps it. An unknown column is
    an error (exit 2).

    A column axial_load, moment, moment_cross, misalignment, tilt_radius (groove, pitch or a
    length), dynamic_rating or rotating (inner, outer) makes every row a combined-load case of a
    deep-groove ball bearing, as 'solve --axial-load ...' solves it (3-D ring equilibrium,
    ISO/TS 16281 L10r, ISO 281 L10; load may then be 0), with every column solve writes (the
    largest contact pressures, every ball at its contact angle, and ISO 76's P0 and s0 among
    them): the file names a bearing or the ball geometry, and has no method, exponent or
    revolutions column. A tilt_radius cell needs an axial_load, moment, moment_cross or
    misalignment cell on its row (as --tilt-radius needs a combined load); a row without is
    skipped. The rows of one bearing are solved together by one vectorised call.

    A bad row (a negative load, an unknown unit or bearing, z = 0, a line with the wrong
    number of cells, a line that is not UTF-8 text) is named on standard error with its row number and the reason; the other
    rows are still solved and written, and the exit status is 1 when any row was skipped
    (0: every row solved; 2: bad command line or header, or a bad row with --strict).

    The rows of one method are solved together, chunk by chunk, by one vectorised call of
    the model. csv is streamed (any number of rows, -o written whole at the end); json,
    markdown and table hold every row and refuse files over 100000 rows.

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
    """
    from bearingload.errors import InputError
    from bearingload.reports.batch import MAX_HELD_ROWS, batch_columns, csv_head, csv_rows
    from bearingload.studies.batch import BatchSolver
    from bearingload.studies.batch_input import chunks

    if output == "":
        raise click.UsageError("Invalid value for '-o' / '--output': the file name is empty")
    try:
        stream = chunks(cases, chunk_size)
        first = next(stream, None)
    except InputError as exc:
        raise click.UsageError(_header_message(exc)) from exc
    assert first is not None  # chunks() yields the header at least once
    header = first[0]
    columns = batch_columns(header)
    solver = BatchSolver(header)
    held: dict[str, list[Any]] = {}
    held_rows: list[int] = []
    skipped: list[tuple[int, str]] = []
    warned = 0
    progress = _Progress()
    total = 0
    long_file = len(first[1]) >= LONG_CHUNK
    with _Sink(fmt, output, strict) as sink, _tuned(long_file, _own_process()):
        if fmt == "csv":
            sink.write(csv_head(columns))
        for _, lines in _all(first, stream):
            total += len(lines)
            part = solver.solve(lines)
            if part.errors and strict:
                sink.fail()
                row, message = part.errors[0]
                raise click.UsageError(f"Invalid value in row {row}: {message}")
            skipped += part.errors
            warned = _row_messages(part, warned, progress)
            if fmt == "csv":
                if part.rows:
                    sink.write(csv_rows(columns, part.rows, part.values))
            else:
                held_rows += part.rows
                if len(held_rows) > MAX_HELD_ROWS:
                    sink.fail()
                    raise click.UsageError(
                        f"Invalid value for '--format': {fmt} holds every row and takes at most "
                        f"{MAX_HELD_ROWS} rows; write --format csv for longer files"
                    )
                for k, v in part.values.items():
                    held.setdefault(k, []).extend(v.tolist() if hasattr(v, "tolist") else v)
            progress.update(total)
        progress.clear()
        if fmt != "csv":
            from bearingload.reports.batch import held_report

            if not held_rows:
                held = {c.key: [] for c in columns if c.key != "row"}
            sink.write(held_report(columns, held_rows, held, skipped, fmt))
    if warned > MAX_WARNINGS_SHOWN:
        click.echo(
            f"Warning: {warned - MAX_WARNINGS_SHOWN} more warnings not shown (--format json "
            "lists every row's warnings)",
            err=True,
        )
    if skipped:
        click.echo(f"Warning: {len(skipped)} of {total} rows skipped (exit status 1)", err=True)
        click.get_current_context().exit(1)


def _row_messages(part: Any, warned: int, progress: _Progress) -> int:
    """Print the chunk's skipped rows and the checks' warnings in row order (so that stderr
    does not depend on --chunk-size), the warnings up to :data:`MAX_WARNINGS_SHOWN` in all;
    return the number of warnings so far."""
    found = part.values.get("warnings", [])
    messages = [(row, text, False) for row, text in part.errors]
    messages += [(part.rows[i], text, True)
                 for i in compress(range(len(found)), found) for text in found[i]]  # fmt: skip
    for row, text, warning in sorted(messages, key=lambda m: m[0]):  # stable: a row's order
        warned += warning
        if not warning or warned <= MAX_WARNINGS_SHOWN:
            progress.clear()
            click.echo(f"Warning: row {row}: {text}", err=True)
    return warned


@contextmanager
def _tuned(long_file: bool, own_process: bool) -> Iterator[None]:
    """A long file allocates and frees the same large arrays chunk after chunk, and makes many
    small objects (cells, row numbers): let the garbage collector pass less often over the
    objects of start-up (its settings given back at the end, and objects someone else froze
    left frozen: the command may run inside a Python program); and, on Linux and only in a
    process of its own (:data:`bearingload.cli.OWN_PROCESS`), ask glibc's malloc to keep freed
    memory for reuse (in one arena, which the writer threads share) rather than give it back
    to the system and fault it in again. That cannot be undone: a program running batch would
    keep every megabyte it frees afterwards. About 7 % of a 10^5-row run; the output does not
    change."""
    if not long_file:
        yield
        return
    import gc

    threshold = gc.get_threshold()
    freeze = gc.get_freeze_count() == 0  # gc.unfreeze() would thaw the caller's objects too
    if freeze:
        gc.freeze()
    gc.set_threshold(50_000, 20, 20)
    if own_process:
        _keep_freed_memory()
    try:
        yield
    finally:
        gc.set_threshold(*threshold)
        if freeze:
            gc.unfreeze()


def _own_process() -> bool:
    from bearingload.cli import OWN_PROCESS

    return click.get_current_context().obj == OWN_PROCESS


def _keep_freed_memory() -> None:
    """glibc's malloc: keep freed memory, and one arena (process-wide, for good)."""
    if not sys.platform.startswith("linux"):
        return
    try:
        import ctypes

        libc = ctypes.CDLL(None)
        libc.mallopt(-1, 1 << 30)  # M_TRIM_THRESHOLD
        libc.mallopt(-3, 1 << 25)  # M_MMAP_THRESHOLD: arrays up to 32 MB from the heap
        libc.mallopt(-8, 1)  # M_ARENA_MAX: one arena, shared by the writer threads
    except (OSError, AttributeError):  # not glibc
        pass


def _all(first: Any, rest: Any) -> Any:
    yield first
    yield from rest


def _header_message(exc: Exception) -> str:
    """'Invalid value for ...' of an error in the header line (a column's unit names it)."""
    if getattr(exc, "parameter", None) in ("CASES", "columns"):
        return f"Invalid value for 'CASES.csv': {str(exc).split(': ', 1)[-1]}"
    return f"Invalid value for 'CASES.csv' header: {exc}"


class _Sink:
    """Where the report goes: a temporary file renamed over ``-o FILE`` at the end, a spool
    copied to standard output at the end (``--strict``: nothing is written before the last row
    is known to be good), or standard output chunk by chunk."""

    def __init__(self, fmt: str, output: str | None, strict: bool) -> None:
        self.output = None if output in (None, "-") else output
        self.spool = strict and self.output is None
        self.failed = False

    def __enter__(self) -> _Sink:
        if self.output is not None:
            from bearingload.reports.render import atomic_file

            self.atomic: Any = atomic_file(self.output)
            try:
                self.fh = self.atomic.__enter__()
            except OSError as exc:
                raise click.UsageError(
                    f"Invalid value for '-o' / '--output': cannot write {self.output!r}: "
                    f"{exc.strerror}"
                ) from exc
        elif self.spool:
            import tempfile

            self.fh = tempfile.TemporaryFile("w+", encoding="utf-8", newline="\n")
        return self

    def write(self, text: str | bytes | bytearray) -> None:
        """Write text, or csv lines already encoded as UTF-8 (written as they are)."""
        if self.output is None and not self.spool:
            click.echo(text, nl=False)
        elif not isinstance(text, str):
            self.fh.flush()
            self.fh.buffer.write(text)
        else:
            self.fh.write(text)

    def fail(self) -> None:
        self.failed = True

    def __exit__(self, kind: Any, exc: Any, tb: Any) -> None:
        bad = kind is not None or self.failed
        if self.output is not None:
            try:
                self.atomic.__exit__(RuntimeError if bad else None, None, None)
            except OSError as error:
                raise click.UsageError(
                    f"Invalid value for '-o' / '--output': cannot write {self.output!r}: "
                    f"{error.strerror}"
                ) from error
        elif self.spool:
            if not bad:
                self.fh.seek(0)
                while block := self.fh.read(1 << 20):
                    click.echo(block, nl=False)
            self.fh.close()


class _Progress:
    """Rows done, on standard error when it is a terminal and the run has taken over a second."""

    def __init__(self) -> None:
        self.start = time.monotonic()
        self.tty = sys.stderr.isatty()
        self.shown = False

    def update(self, rows: int) -> None:
        if self.tty and time.monotonic() - self.start > 1.0:
            click.echo(f"\rbatch: {rows} rows solved or skipped", err=True, nl=False)
            self.shown = True

    def clear(self) -> None:
        if self.shown:
            click.echo("\r" + " " * 40 + "\r", err=True, nl=False)
            self.shown = False
