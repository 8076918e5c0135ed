"""Reading a csv file of cases for ``bearingload batch``: the header, the cells, one chunk at a time.

Columns are named like the options of ``bearingload solve`` (``load``, ``clearance``,
``ball_diameter`` ...); a unit in the header (``load [kN]``) is the unit of the column's bare
numbers, a unit in a cell (``300kgf``) is that cell's own. Each distinct cell text is parsed once
(a cache per column), so a column of repeated values costs one parse; bare numbers are read by
``float`` before the unit parser (:func:`bearingload.units.parse_quantity`) is tried.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any, BinaryIO

from bearingload.errors import InputError

#: Rows read, solved and written at a time (memory stays flat however long the file): radial
#: cases, and combined-load cases (whose 3-D solver needs more memory per case).
CHUNK_ROWS = 50_000
CHUNK_ROWS_COMBINED = 10_000
#: Accepted columns -> kind of value (a units.py kind, or how the cell is read).
COLUMNS: dict[str, str] = {
    "bearing": "text",
    "balls": "count",
    "load": "force",
    "stiffness": "stiffness",
    "ball_diameter": "length",
    "pitch_diameter": "length",
    "inner_conformity": "number",
    "outer_conformity": "number",
    "modulus": "modulus",
    "poisson": "number",
    "clearance": "clearance",
    "clearance_pick": "pick",
    "cage_angle": "cage_angle",
    "exponent": "exponent",
    "method": "text",
    "revolutions": "number",
    "axial_load": "force",
    "moment": "moment",
    "moment_cross": "moment",
    "misalignment": "angle",
    "tilt_radius": "tilt_radius",
    "dynamic_rating": "force",
    "rotating": "ring",
}
#: Columns that make every row of a file a combined-load case (3-D equilibrium, ISO/TS 16281).
COMBINED_COLUMNS = ("axial_load", "moment", "moment_cross", "misalignment", "tilt_radius",
                    "dynamic_rating", "rotating")  # fmt: skip
#: Columns a combined-load file cannot have: its method is the 3-D equilibrium, and its life is
#: L10r in 10^6 revolutions.
NOT_COMBINED = ("method", "revolutions", "exponent")
#: Columns that make a row a bearing (resolved by bearings.resolve) rather than a bare ring.
BEARING_COLUMNS = (
    "bearing",
    "ball_diameter",
    "pitch_diameter",
    "inner_conformity",
    "outer_conformity",
    "modulus",
    "poisson",
    "clearance_pick",
    "revolutions",
)
#: Library parameter names -> the column of a batch file they come from: a skipped row's
#: reason names the column the user wrote (as the command line names the option).
_COLUMN_OF = {
    "radial_load": "load",
    "D_w": "ball_diameter",
    "ball-diameter": "ball_diameter",
    "d_m": "pitch_diameter",
    "pitch-diameter": "pitch_diameter",
    "f_i": "inner_conformity",
    "f_o": "outer_conformity",
    "E1": "modulus",
    "nu1": "poisson",
    "pick": "clearance_pick",
    "bore": "clearance",
}
_HEADER = re.compile(r"^\s*([^\[\]]*?)\s*(?:\[\s*([^\]]*?)\s*\])?\s*$")


@dataclass(frozen=True)
class Header:
    """The columns of a batch file: ``names`` in file order and each one's header ``units``."""

    names: tuple[str, ...]
    units: dict[str, str]

    @property
    def combined(self) -> bool:
        """True when the rows are combined-load cases (an axial load, moment ... column)."""
        return any(n in COMBINED_COLUMNS for n in self.names)

    @property
    def has_bearing(self) -> bool:
        """True when some column can make a row a catalogue or geometry bearing."""
        return any(n in BEARING_COLUMNS for n in self.names)


def read_header(fields: list[str]) -> Header:
    """The header row: column names (``-`` or spaces read as ``_``) and their ``[unit]``.

    Raises
    ------
    InputError
        (parameter ``columns``) naming unknown, duplicated or not-yet-supported columns, a
        missing ``load``, or a header unit that does not fit its column.
    """
    names, units = [], {}
    for raw in fields:
        match = _HEADER.match(raw)
        name = (match.group(1) if match else raw).strip().lower().replace("-", "_")
        name = name.replace(" ", "_")
        names.append(name)
        if match and match.group(2):
            units[name] = match.group(2)
    unknown = [n for n in names if n not in COLUMNS]
    if unknown:
        raise InputError(
            "columns",
            f"unknown column(s) {', '.join(repr(n) for n in unknown)}; "
            f"allowed: {', '.join(COLUMNS)}",
        )
    _check_combined(names)
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise InputError("columns", f"column(s) given twice: {', '.join(twice)}")
    if "load" not in names:
        raise InputError("columns", "the column 'load' is required")
    for name, unit in units.items():
        _check_header_unit(name, unit)
    return Header(tuple(names), units)


def unit_kind(kind: str) -> str:
    """The units.py kind of a column kind: a clearance is a length, a cage angle an angle."""
    return {"clearance": "length", "cage_angle": "angle", "tilt_radius": "length"}.get(kind, kind)


def _check_combined(names: list[str]) -> None:
    """A combined-load file names its bearings (or ball geometry) and no radial-only column."""
    combined = [n for n in names if n in COMBINED_COLUMNS]
    if not combined:
        return
    if not any(n in ("bearing", "ball_diameter", "pitch_diameter") for n in names):
        raise InputError(
            "columns",
            f"{combined[0]}: the combined load needs deep-groove ball bearings: add a 'bearing' "
            "column (a designation) or 'ball_diameter' and 'pitch_diameter'",
        )
    refused = [n for n in names if n in NOT_COMBINED]
    if refused:
        raise InputError(
            "columns",
            f"{refused[0]}: not used with the combined load ({combined[0]}): its rows are "
            "solved by the 3-D equilibrium of a ball bearing (m = 1.5), lives in 10^6 rev",
        )


def _check_header_unit(name: str, unit: str) -> None:
    from bearingload.units import UNITS, parse_quantity, stiffness_factor

    kind = COLUMNS[name]
    kind = unit_kind(kind)
    if kind == "stiffness":
        stiffness_factor(unit, None, parameter=f"{name} [{unit}]")
    elif kind in UNITS:
        parse_quantity("1" + unit, kind, parameter=f"{name} [{unit}]")
    else:
        raise InputError(f"{name} [{unit}]", "this column takes no unit")


@dataclass
class Block:
    """One chunk of data rows as read: their row numbers (the header is row 1), their text, and
    the lines that could not be read (row number -> reason).

    ``lines`` holds each row's line when the chunk has no quote character (its cells are the
    line split at commas, and bare numbers can be read by numpy at once); a chunk with quotes
    comes already split by the csv module (``parsed``).
    """

    numbers: list[int]
    lines: list[str] | None = None
    parsed: list[list[str]] | None = None
    errors: dict[int, str] = field(default_factory=dict)

    def __len__(self) -> int:
        return len(self.numbers) + len(self.errors)

    def cells(self) -> list[tuple[int, list[str]]]:
        """(row number, cells) of every readable row."""
        if self.parsed is None:
            self.parsed = [line.split(",") for line in self.lines or ()]
        return list(zip(self.numbers, self.parsed, strict=True))


def chunks(stream: BinaryIO, size: int | None = None) -> Iterator[tuple[Header, Block]]:
    """The header and then blocks of up to ``size`` rows of a csv file read as bytes (default
    :data:`CHUNK_ROWS`, or :data:`CHUNK_ROWS_COMBINED` for a file of combined-load cases); the
    header is row 1. A file with a header and no rows yields the header once with an empty block.

    Each line is decoded as UTF-8 on its own (a byte order mark before the header is dropped):
    a line that is not UTF-8 is a bad row named by its number, not the end of the file. Blank
    lines are skipped (they still count as rows). Once a quote character appears, the rest of
    the file is read by the csv module (a quoted cell may hold commas and line breaks); a line
    the csv module cannot read comes as one cell, so that its cell count does not fit.
    """
    header = _header(next(_numbered(stream, 0), None))
    if size is None:
        size = CHUNK_ROWS_COMBINED if header.combined else CHUNK_ROWS
    any_rows = False
    for block in _blocks(stream, size):
        any_rows = True
        yield header, block
    if not any_rows:
        yield header, Block([])


def _header(first: tuple[int, str] | None) -> Header:
    import csv

    if first is None:
        raise InputError("CASES", "the file is empty; its first line names the columns")
    number, text = first
    if number < 0:
        raise InputError("CASES", f"the header line is not UTF-8 text ({text})")
    if "\r" in text:
        raise InputError("CASES", "lines end in CR alone; write LF or CR LF line ends")
    try:
        fields = next(csv.reader([text.removeprefix("\ufeff")]), [])
    except csv.Error as exc:
        raise InputError("CASES", f"cannot read the header line: {exc}") from None
    if not fields:
        raise InputError("CASES", "the first line is blank; it must name the columns")
    return read_header(fields)


def _numbered(lines: Iterator[bytes], last: int) -> Iterator[tuple[int, str]]:
    """(row number, text without its line end) of each line after row ``last``; a line that is
    not UTF-8 comes with a negative row number and the reason as its text."""
    for number, raw in enumerate(lines, start=last + 1):
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError as exc:
            yield -number, f"{exc.reason} at byte {exc.start + 1} of the line"
            continue
        yield number, text.rstrip("\r\n")


def _blocks(stream: BinaryIO, size: int) -> Iterator[Block]:
    """Blocks of rows after the header: a block of UTF-8 lines without quotes is decoded and
    split at once; from the first quote on, the csv module reads the rest."""
    last = 1  # row number of the last line read
    pieces = _pieces(stream, size)
    for whole in pieces:
        try:
            text = whole.decode("utf-8")
        except UnicodeDecodeError:
            text = None
        if text is None or '"' in text:
            raw = _lines_of(whole)
            taken = list(_numbered(iter(raw), last))
            if text is not None or any('"' in t for n, t in taken if n > 0):
                after = (line for piece in pieces for line in _lines_of(piece))
                rest = _numbered(after, last + len(raw))
                yield from _quoted_blocks(iter(taken), rest, size)
                return
            yield _block(taken)
            last += len(raw)
            continue
        texts = (text[:-1] if text.endswith("\n") else text).split("\n")
        if "\r" in text:
            texts = [t.rstrip("\r") for t in texts]
        numbers = range(last + 1, last + 1 + len(texts))
        if "" in texts:
            yield _block(list(zip(numbers, texts, strict=True)))
        else:
            yield Block(list(numbers), lines=texts)
        last += len(texts)


#: Bytes asked of the stream at a time (reading a line at a time costs more than the rest of
#: reading).
READ_BYTES = 1 << 22


def _pieces(stream: BinaryIO, size: int) -> Iterator[bytes]:
    """Pieces of ``size`` whole lines each (the last: what is left) of a binary stream, read
    :data:`READ_BYTES` at a time. The line ends of what has been read are found once, and every
    piece they complete is cut from it (a small ``size`` costs no search per piece)."""
    import numpy as np

    read = getattr(stream, "read1", stream.read)
    parts: list[bytes] = []
    lines = 0
    while data := read(READ_BYTES):
        parts.append(data)
        lines += data.count(b"\n")
        if lines < size:
            continue
        whole = b"".join(parts)
        ends = np.flatnonzero(np.frombuffer(whole, np.uint8) == ord("\n"))
        start = 0
        for cut in (ends[size - 1 :: size] + 1).tolist():  # after every size-th line end
            yield whole[start:cut]
            start = cut
        parts, lines = [whole[start:]], lines % size
    if any(parts):
        yield b"".join(parts)


def _lines_of(whole: bytes) -> list[bytes]:
    """The lines of a piece, each with its line end (the last one may have none)."""
    lines = [line + b"\n" for line in whole.split(b"\n")]
    lines[-1] = lines[-1][:-1]
    return lines if lines[-1] else lines[:-1]


def _block(taken: list[tuple[int, str]]) -> Block:
    """A block of (row number, text) pairs: blank lines skipped, lines not UTF-8 named."""
    block = Block([], lines=[])
    for number, text in taken:
        if number < 0:
            block.errors[-number] = f"not UTF-8 text ({text})"
        elif text:
            block.numbers.append(number)
            block.lines.append(text)  # type: ignore[union-attr]
    return block


def _quoted_blocks(
    first: Iterator[tuple[int, str]], rest: Iterator[tuple[int, str]], size: int
) -> Iterator[Block]:
    """Blocks read by the csv module from ``first`` and then ``rest``; a record's row number is
    the number of its last line. A quote never closed (an odd number of quote characters in a
    record of several lines: the reader took every line to the end of the file into one cell)
    is a bad row named by the row where it opened."""
    import csv
    from itertools import chain

    errors: dict[int, str] = {}
    last = [0]
    opened = [0, 0]  # the first row of the record being read, and its quote characters

    def texts() -> Iterator[str]:
        for number, text in chain(first, rest):
            if number < 0:
                errors[-number] = f"not UTF-8 text ({text})"
                last[0] = -number
                yield ""  # a blank line: skipped by the reader
            else:
                last[0] = number
                opened[0] = opened[0] or number
                opened[1] += text.count('"')
                yield text + "\n"

    reader = csv.reader(texts())
    block = Block([], parsed=[])
    while True:
        try:
            row = next(reader)
        except StopIteration:
            break
        except csv.Error:
            row = ["\0"]  # unreadable: a cell count that never fits
        start, quotes = opened
        opened[:] = [0, 0]
        if quotes % 2 and start < last[0]:
            errors[start] = (
                f"a quote opened in this row is never closed: rows {start} to {last[0]} (the end "
                "of the file) were read as one cell"
            )
            row = []
        block.errors.update(errors)
        errors.clear()
        if row:
            block.numbers.append(last[0])
            assert block.parsed is not None
            block.parsed.append(row)
        if len(block) >= size:
            yield block
            block = Block([], parsed=[])
    block.errors.update(errors)
    if len(block):
        yield block


def row_message(exc: Exception) -> str:
    """The reason a row is skipped, ``column: message``, from a library error."""
    column = _COLUMN_OF.get(getattr(exc, "parameter", ""))
    return str(exc) if column is None else f"{column}: {str(exc).split(': ', 1)[-1]}"


class CellParser:
    """Parse the cells of one column, each distinct text once.

    ``parse(text)`` returns the value in the package unit, or raises :class:`InputError` named
    after the column; results and errors are cached.
    """

    def __init__(self, name: str, unit: str | None) -> None:
        self.name = name
        self.kind = COLUMNS[name]
        self.unit = unit
        self.factor: float | None = None  # of the header's unit to the package unit
        self.cache: dict[Any, Any] = {}

    def parse(self, text: str, exponent: float = 1.5) -> Any:
        key = (text, exponent) if self.kind == "stiffness" else text
        hit = self.cache.get(key)
        if hit is None:
            try:
                hit = (True, self._parse(text.strip(), exponent))
            except InputError as exc:
                hit = (False, exc)
            if len(self.cache) < 100_000:
                self.cache[key] = hit
        ok, value = hit
        if not ok:
            raise value
        return value

    def _parse(self, text: str, exponent: float) -> Any:
        from bearingload import units

        kind, name = self.kind, self.name
        if kind in ("text", "pick"):
            return _choice(name, text) if kind == "pick" else text
        if kind == "ring":
            if text not in ("inner", "outer"):
                raise InputError(name, f"unknown ring {text!r}; allowed: inner, outer")
            return text
        if kind in ("number", "count"):
            return _number(name, text, self.unit, whole=kind == "count")
        if kind == "exponent":
            return _exponent(text)
        if kind == "tilt_radius":  # groove, pitch or a length, as --tilt-radius reads it
            from bearingload.bearings.tilt import parse_tilt_radius

            unit = self.unit if self.unit and _plain(name, text) is not None else ""
            return parse_tilt_radius(text + unit)
        if kind == "cage_angle":  # the one reading of solve, sweep and table
            plain = _plain(name, text)
            if plain is None:
                return units.parse_cage_angle(text, parameter=name)
            if not self.unit:
                return plain
            if self.factor is None:
                self.factor = float(units.parse_cage_angle("1" + self.unit, parameter=name))
            return plain * self.factor
        if kind == "clearance" and re.fullmatch(r"(?i)c[2-5n]|g[6-9]|cn|normal", text):
            from bearingload.bearings.clearance import parse_clearance

            return parse_clearance(text)
        plain = _plain(name, text)
        if kind == "stiffness":
            if plain is not None and self.unit:
                return plain * units.stiffness_factor(self.unit, exponent, parameter=name)
            return units.parse_stiffness(text, exponent, parameter=name)
        kind = unit_kind(kind)
        if plain is not None and self.unit:  # the header's unit: its factor, found once
            if self.factor is None:
                self.factor = units.parse_quantity("1" + self.unit, kind, parameter=name)
            return plain * self.factor
        # a bare number: refused when implausible for its quantity, as on the command line
        return units.parse_quantity(text, kind, parameter=name)


def _float(text: str) -> float:
    """``float(text)`` without the underscores Python allows ('1_000'): the command line's
    unit parser refuses them, and so must every cell, however its chunk is read."""
    if "_" in text:
        raise ValueError(text)
    return float(text)


def _plain(name: str, text: str) -> float | None:
    """A bare finite number, or None (then the unit parser reads the text)."""
    try:
        v = _float(text)
    except ValueError:
        return None
    if v != v or v in (float("inf"), float("-inf")):
        raise InputError(name, f"{text!r} is not a finite number")
    return v


def _number(name: str, text: str, unit: str | None, *, whole: bool) -> float:
    try:
        v = _float(text)
    except ValueError:
        raise InputError(name, f"cannot read {text!r} as a number") from None
    if v != v or v in (float("inf"), float("-inf")):
        raise InputError(name, f"{text!r} is not a finite number")
    if whole and v != round(v):
        raise InputError(name, f"must be a whole number (got {text})")
    return v


def _exponent(text: str) -> float:
    num, slash, den = text.partition("/")
    try:
        return _float(num) / _float(den) if slash else _float(text)
    except (ValueError, ZeroDivisionError):
        raise InputError(
            "exponent", f"{text!r} is neither a number nor a fraction like 10/9"
        ) from None


def _choice(name: str, text: str) -> str:
    if text not in ("min", "mean", "max"):
        raise InputError(name, f"unknown pick {text!r}; allowed: min, mean, max")
    return text
