"""Reading a csv file of cases (docs/batch.md): the header, chunks of rows by the ``csv``
module, the cells, each by its input's reader (:data:`bearingload.plan.inputs.READERS`: the
units, ranges and messages of solve's options), a column at a time (:func:`read_column`).
"""

from __future__ import annotations

import csv
import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from typing import Any, BinaryIO

from bearingload.bearings.mounting import MOUNTING_PARAMS
from bearingload.errors import InputError, UnusedError
from bearingload.plan.case import LOAD_PARAMS
from bearingload.plan.inputs import READERS, Reader, count, quantity, text
from bearingload.plan.many import GEOMETRY, PAIR_PARAMS
from bearingload.validate import known_columns

#: Rows read, solved and written at a time (memory stays flat however long the file).
CHUNK_ROWS = 10_000
#: Accepted columns: the inputs of a case (:data:`bearingload.plan.inputs.READERS`; ``eC`` read
#: as ``ec``), the bearing, and the radial engine's method and life.
COLUMNS = tuple(["bearing", *("ec" if n == "e_c" else n for n in READERS), "method", "revolutions"])
#: Columns of the combined load (a cell in one makes its row a combined case) and their lever.
COMBINED_COLUMNS = (*LOAD_PARAMS, "tilt_radius")
#: Columns that make a row a bearing (resolved by bearings.resolve) rather than a bare ring.
BEARING_COLUMNS = (
    *(*GEOMETRY, "inner_conformity", "outer_conformity", "modulus", "poisson", "ball_material"),
    *("clearance_pick", "revolutions", *MOUNTING_PARAMS),
)
_HEADER = re.compile(r"^\s*([^\[\]]*?)\s*(?:\[\s*([^\]]*?)\s*\])?\s*$")


@dataclass(frozen=True)
class Header:
    """The columns of a batch file: ``names`` in file order and each one's header ``units``;
    ``blank_tail`` empty header cells after the last name (a spreadsheet's trailing comma), whose
    cells a row may have and must leave empty; what kind of rows the columns make."""

    names: tuple[str, ...]
    units: dict[str, str]
    blank_tail: int = 0
    combined: bool = False  # rows may be combined-load cases (an axial load, moment ... column)
    pairs: bool = False  # every row is a bearing pair (an arrangement, preload or width column)
    has_bearing: bool = False  # some column can make a row a catalogue or geometry bearing


def read_header(fields: list[str]) -> Header:
    """The header row: column names (``-`` or spaces read as ``_``) and their ``[unit]``;
    InputError (``columns``) for an unknown, unnamed or duplicated column, a missing ``load``,
    a file of columns that cannot go together, or a header unit that does not fit its column."""
    blank_tail = 0  # empty cells at the end (``balls,load,``), a column at least left
    while len(fields) - blank_tail > 1 and not fields[-1 - blank_tail].strip():
        blank_tail += 1
    names, units = [], {}
    for raw in fields[: len(fields) - blank_tail]:
        match = _HEADER.match(raw)
        names.append(
            (match[1] if match else raw).strip().lower().replace("-", "_").replace(" ", "_")
        )
        if match and match[2]:
            units[names[-1]] = match[2]
    if "" in names:
        raise InputError(
            "columns",
            f"the header's column {names.index('') + 1} has no name (only empty columns at the "
            "end of the header are allowed, and their cells must be empty)",
        )
    known_columns("columns", names, COLUMNS)
    for kind in _FILE_KINDS:
        _check_file(names, *kind)
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise InputError("columns", f"column(s) given twice: {', '.join(twice)}")
    if "load" not in names:
        raise InputError("columns", "the column 'load' is required")
    for name, unit in units.items():
        _check_header_unit(name, unit)
    given = set(names).intersection
    kinds = (COMBINED_COLUMNS, PAIR_PARAMS, BEARING_COLUMNS)
    return Header(tuple(names), units, blank_tail, *(bool(given(k)) for k in kinds))


def library_name(column: str) -> str:
    """The input a column gives (``ec``: ``e_c``)."""
    return "e_c" if column == "ec" else column


def reader(column: str) -> Reader:
    """The reader of a column's cells: its input's (:data:`bearingload.plan.inputs.READERS`)."""
    return _READERS.get(column) or READERS[library_name(column)]


#: The readers of the columns that are no input of a case.
_READERS = {"bearing": text, "method": text, "revolutions": quantity("revolutions")}


def _check_file(
    names: list[str], kinds: Sequence[str], needs: str, refused: Sequence[str], why: str
) -> None:
    """A file with a column of ``kinds`` names its bearings or ball geometry (else: ``needs``)
    and has no column of ``refused`` (``why``, the first of ``kinds`` given in its braces)."""
    given, bad = [n for n in names if n in kinds], [n for n in names if n in refused]
    if given and not any(n in GEOMETRY for n in names):
        raise InputError("columns", f"{given[0]}: {needs}")
    if given and bad:
        raise InputError("columns", f"{bad[0]}: not used {why.format(given[0])}")


#: (columns, what they need, columns refused beside them, why) of a combined file, of pairs.
_FILE_KINDS = (
    (
        COMBINED_COLUMNS,
        "the combined load needs ball bearings: add a 'bearing' column (a "
        "designation) or 'ball_diameter' and 'pitch_diameter'",
        ("method", "revolutions", "exponent"),
        "with the combined load ({}): its rows are solved by the 3-D equilibrium of a ball "
        "bearing (m = 1.5), lives in 10^6 rev",
    ),
    (
        PAIR_PARAMS,
        "a file of bearing pairs needs angular-contact ball bearings: add a 'bearing' column "
        "(7205B, 7205BDB) or 'ball_diameter', 'pitch_diameter' and 'contact_angle'",
        ("method", "revolutions", "exponent", "clearance", "clearance_pick", "misalignment"),
        "in a file of bearing pairs ({}): a pair is solved by the exact model of its "
        "angular-contact bearings, no clearance (the contact angle fixes the geometry), no "
        "misalignment (give the moment)",
    ),
)


def _check_header_unit(name: str, unit: str) -> None:
    from bearingload.units import TEMPERATURE_UNITS, UNITS, parse_quantity, stiffness_factor

    kind, where = getattr(reader(name), "kind", None), f"{name} [{unit}]"  # its unit's kind
    if kind == "temperature":
        if unit not in TEMPERATURE_UNITS:
            raise InputError(where, f"allowed units: {', '.join(TEMPERATURE_UNITS)}")
    elif kind == "stiffness":
        stiffness_factor(unit, None, parameter=where)
    elif kind in UNITS:
        parse_quantity("1" + unit, kind, parameter=where)
    else:
        raise InputError(where, "this column takes no unit")


@dataclass
class Block:
    """A chunk of data rows as read: row numbers, cells, rows not read (number -> reason)."""

    numbers: list[int] = field(default_factory=list)
    cells: list[list[str]] = field(default_factory=list)
    errors: dict[int, str] = field(default_factory=dict)


def read_cases(stream: BinaryIO, size: int = CHUNK_ROWS) -> tuple[Header, Iterator[Block]]:
    """The header of a csv file read as bytes (row 1), and its blocks of up to ``size`` rows:
    a record's row number is that of its first line, blank lines count; each line is decoded
    as UTF-8 on its own (a line that is not is a bad row). Raises InputError (``CASES`` or
    ``columns``) for a header that cannot be read."""
    lines = iter(stream)
    return _header(next(lines, None)), _blocks(lines, size)


def _blocks(lines: Iterator[bytes], size: int) -> Iterator[Block]:
    errors: dict[int, str] = {}
    lines_read: dict[int, str] = {}  # row -> text, of the record being read
    records = csv.reader(_decoded(lines, errors, lines_read))
    block, last = Block(), 1
    while (cells := _record(records)) is not None:
        start, last = last + 1, records.line_num + 1  # the record's first and last lines
        if _unclosed("".join(lines_read.pop(r, "") for r in range(start, last + 1))):
            cells = []  # the reader took every line to the end into a cell, as if closed
            why = f"rows {start} to {last} (the end of the file) were read as one cell"
            why = why if last > start else "the file ends in its cell"
            errors[start] = f"a quote opened in this row is never closed: {why}"
        block.errors |= errors
        errors.clear()
        if cells:
            block.numbers.append(start)
            block.cells.append(cells)
        if len(block.numbers) + len(block.errors) >= size:
            yield block
            block = Block()
    block.errors |= errors
    if block.numbers or block.errors:
        yield block


def _record(records: Any) -> list[str] | None:
    """The next record's cells (None: the end; an unreadable one a cell count that never fits)."""
    try:
        return next(records, None)
    except csv.Error:
        return ["\0"]


def _unclosed(text: str) -> bool:
    """Whether a record's text ends in a quoted cell: csv's strict mode reads it only closed."""
    for end in ("", '"') if '"' in text else ():  # as it is, then closed by a quote at its end
        try:
            list(csv.reader([text + end], strict=True))
        except csv.Error:
            continue
        return end == '"'
    return False


def _header(first: bytes | None) -> Header:
    if first is None:
        raise InputError("CASES", "the file is empty; its first line names the columns")
    try:
        text = first.decode("utf-8").removeprefix("\ufeff").rstrip("\r\n")
    except UnicodeDecodeError as exc:
        raise InputError("CASES", f"the header line is not UTF-8 text ({_where(exc)})") from None
    if "\r" in text:
        raise InputError("CASES", "lines end in CR alone; write LF or CR LF line ends")
    try:
        fields = next(csv.reader([text]), [])
    except csv.Error as exc:
        raise InputError("CASES", f"cannot read the header line: {exc}") from None
    if not fields:
        raise InputError("CASES", "the first line is blank; it must name the columns")
    return read_header(fields)


def _decoded(lines: Iterator[bytes], errors: dict[int, str], read: dict[int, str]) -> Any:
    """The text of each line after the header (row 2 on), kept in ``read`` by its row until its
    record is checked; a line that is not UTF-8 goes to ``errors`` and reads as a blank line."""
    for row, raw in enumerate(lines, start=2):
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError as exc:
            errors[row] = f"not UTF-8 text ({_where(exc)})"
            text = "\n"
        read[row] = text
        yield text


def _where(exc: UnicodeDecodeError) -> str:
    return f"{exc.reason} at byte {exc.start + 1} of the line"


def row_message(exc: Exception) -> str:
    """The reason a row is skipped, ``column: message``, every column of a refusal named, a
    model's name of an input (``f_i``) as its column (:func:`~.plan.inputs.argument_of`)."""
    if not isinstance(exc, InputError):
        return str(exc)
    from bearingload.plan.inputs import argument_of

    names = [argument_of(n) for n in getattr(exc, "parameters", None) or (exc.parameter,)]
    joint = ", " if isinstance(exc, UnusedError) else " / "
    return f"{joint.join('eC' if n == 'e_c' else n for n in names)}: {exc.message}"


def read_column(
    name: str, unit: str | None, texts: Sequence[str], exponents: Sequence[float] | None = None
) -> tuple[list[Any], dict[int, str]]:
    """The values of one column's cells read by its input's reader (:func:`reader`; a bare
    number with the header's ``unit`` as if written with it), None for a blank cell, and the
    reasons of the cells that cannot be read (index -> ``column: reason``). ``exponents``: each
    row's m, which a stiffness unit needs (default 1.5). A column of bare numbers is read by
    numpy at once (:func:`_bare_numbers`), any other each distinct cell text once."""
    fast = _bare_numbers(name, unit, texts, exponents)
    if fast is not None:
        return fast, {}
    keys = list(zip(texts, [1.5] * len(texts) if exponents is None else exponents, strict=True))
    seen: dict[tuple[str, float], tuple[Any, str | None]] = {}
    for key in keys:
        if key not in seen:
            try:
                seen[key] = (_cell(name, unit, key[0].strip(), key[1]), None)
            except InputError as exc:
                seen[key] = (None, row_message(exc))
    read = [seen[key] for key in keys]
    return [v for v, _ in read], {i: why for i, (_, why) in enumerate(read) if why is not None}


def _cell(name: str, unit: str | None, cell: str, exponent: float) -> Any:
    """One cell's value (None: blank) by its input's reader, in the package's units."""
    from bearingload import units

    if not cell:
        return None
    lib = library_name(name)
    if "_" in cell and _is_number(cell):  # numbers as the command line reads them: no '1_000'
        raise InputError(name, f"cannot read {cell!r} as a number")
    if name == "quasi_static":  # a word of the csv file (any case; csv output writes True)
        if cell.lower() not in ("true", "false"):
            raise InputError(name, f"cannot read {cell!r}; allowed: true, false (or blank: false)")
        return cell.lower() == "true"
    if unit and units.is_bare(cell):  # the header's unit, a stiffness's of this exponent
        if name == "stiffness":
            return float(cell) * units.stiffness_factor(unit, exponent, parameter=name)
        cell += unit
    value = reader(name)(cell, lib)
    if name == "stiffness":
        return units.parse_stiffness(value, exponent, parameter=name)
    if name == "clearance_pick":
        from bearingload.plan.bearing import refuse_range
        from bearingload.plan.case import Case

        refuse_range(Case(clearance_pick=value), "batch")
    return value


def _is_number(cell: str) -> bool:
    try:
        float(cell)
    except ValueError:
        return False
    return True


def _bare_numbers(
    name: str, unit: str | None, texts: Sequence[str], m: Sequence[float] | None
) -> list[Any] | None:
    """Every cell a bare number, read at once in package units; None when some cell needs
    :func:`_cell`. The reader's checks of a number are ranges on each side of 0 (and a whole
    number of balls, checked here): where it takes the smallest and the largest cell (of each
    exponent m) above 0 and at most 0, as :func:`_cell` reads them, it takes every one (a
    modulus or revolutions <= 0 passes the reader, left to the model, where a bare 210 or 36
    between them is refused as implausible); a header unit scales each by the value
    :func:`_cell` reads for a 1."""
    import numpy as np

    read = reader(name)
    kind = getattr(read, "kind", None)
    numeric = kind not in (None, "temperature") or hasattr(read, "range") or name in _NUMBERS
    if not texts or not numeric or name == "tilt_radius" or "_" in "".join(texts):
        return None  # numpy reads '1_000' as Python does; the readers refuse it
    try:
        v = np.array(texts, dtype=float)
    except ValueError:
        return None
    if not np.all(np.isfinite(v)) or read is count and not np.all(v == np.round(v)):
        return None
    ms = [1.5] * v.size if m is None else list(m)
    groups = [
        np.flatnonzero((np.asarray(ms) == e) & side) for e in set(ms) for side in (v > 0, v <= 0)
    ]
    ends = {int(g[end(v[g])]) for g in groups if g.size for end in (np.argmin, np.argmax)}
    try:  # the reader names a bad end: then cell by cell, each named
        for i in ends:
            _cell(name, unit, texts[i].strip(), ms[i])
        one = {e: _cell(name, unit, "1", e) for e in set(ms)} if unit else {}
        one = {e: getattr(x, "length", x) for e, x in one.items()}  # a clearance's length
    except InputError:
        return None
    return (v * np.array([one.get(e, 1.0) for e in ms])).tolist()  # 1.0: no unit


#: Columns of plain numbers (no unit, no range).
_NUMBERS = ("balls", "inner_conformity", "outer_conformity", "poisson", "viscosity_index")
