"""Reading a csv file of cases: the header, chunks of rows by the ``csv`` module, the cells.

Columns are named like the options of ``bearingload solve`` (``load``, ``clearance``,
``ball_diameter`` ...); a unit in the header (``load [kN]``) is the unit of the column's bare
numbers, a unit in a cell (``300kgf``) is that cell's own. One reader turns a column of cells
into values (:func:`read_column`): bare numbers at once by numpy, any other cell by the parser
of its kind (:class:`CellParser`), each distinct text once.
"""

from __future__ import annotations

import csv
import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from typing import Any, BinaryIO

from bearingload.bearings.mounting import MOUNTING_PARAMS
from bearingload.errors import InputError, UnusedError

#: Rows read, solved and written at a time (memory stays flat however long the file).
CHUNK_ROWS = 10_000
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
    "ball_material": "text",
    "shaft_fit": "text",
    "housing_fit": "text",
    "shaft_bore": "length",
    "housing_diameter": "length",
    "inner_ring_temperature": "temperature",
    "outer_ring_temperature": "temperature",
    "clearance": "clearance",
    "clearance_pick": "pick",
    "cage_angle": "cage_angle",
    "exponent": "exponent",
    "method": "text",
    "revolutions": "revolutions",
    "axial_load": "force",
    "moment": "moment",
    "moment_cross": "moment",
    "misalignment": "angle",
    "contact_angle": "angle",
    "tilt_radius": "tilt_radius",
    "dynamic_rating": "force",
    "rotating": "ring",
    "static_rating": "force",
    "speed": "speed",
    "reliability": "number",
    "viscosity": "viscosity",
    "oil": "text",
    "viscosity_40": "viscosity",
    "viscosity_100": "viscosity",
    "viscosity_index": "number",
    "temperature": "temperature",
    "contamination": "level",
    "ec": "number",
    "fatigue_load_limit": "force",
    "roughness": "length",
    "pressure_viscosity": "number",
    "ball_density": "number",
    "quasi_static": "flag",
    "arrangement": "text",
    "preload": "preload",
    "width": "length",
}
#: The operating conditions of the lives (solve's options of the same names; ``eC`` is read as
#: ``ec``): they feed the lives in hours, a_ISO, the modified lives and the film, never a load.
#: The oil columns (``bearings.oil.OIL_INPUTS``) give the viscosity instead of ``viscosity``.
SERVICE_COLUMNS = ("speed", "reliability", "oil", "viscosity_40", "viscosity_100",
                   "viscosity_index", "temperature", "viscosity", "contamination", "ec",
                   "fatigue_load_limit", "roughness", "pressure_viscosity")  # fmt: skip
#: The words of a flag column (case-insensitive; csv output writes True and False).
FLAGS = {"true": True, "false": False}
#: The load columns: a row with a cell in one of them is a combined-load case (3-D equilibrium),
#: as solve's load options choose its engine (``contact_angle``: an angular-contact ring given
#: by its ball set, as solve's --contact-angle); the others are radial cases.
LOAD_COLUMNS = ("axial_load", "moment", "moment_cross", "misalignment", "contact_angle")
#: The columns of a bearing pair (solve's --arrangement, --preload, --width): a file with one of
#: them is a file of pairs, every row a pair (``batch/pairs.py``).
PAIR_COLUMNS = ("arrangement", "preload", "width")
#: Columns a file of pairs cannot have (a pair takes no clearance, misalignment, method ...).
NOT_PAIRS = ("method", "revolutions", "exponent", "clearance", "clearance_pick", "misalignment")
#: Columns that belong to the combined load (tilt_radius: the lever of its tilt).
COMBINED_COLUMNS = (*LOAD_COLUMNS, "tilt_radius")
#: Columns a file with combined-load columns cannot have: its combined rows are solved by the
#: 3-D equilibrium (m = 1.5), their lives in 10^6 revolutions.
NOT_COMBINED = ("method", "revolutions", "exponent")
#: Columns that make a row a bearing (resolved by bearings.resolve) rather than a bare ring.
BEARING_COLUMNS = ("bearing", "ball_diameter", "pitch_diameter", "inner_conformity",
                   "outer_conformity", "modulus", "poisson", "ball_material", "clearance_pick",
                   "revolutions", *MOUNTING_PARAMS)  # fmt: skip
_HEADER = re.compile(r"^\s*([^\[\]]*?)\s*(?:\[\s*([^\]]*?)\s*\])?\s*$")


@dataclass(frozen=True)
class Header:
    """The columns of a batch file: ``names`` in file order and each one's header ``units``;
    ``blank_tail`` empty header cells after the last name (a spreadsheet's trailing comma), whose
    cells a row may have and must leave empty."""

    names: tuple[str, ...]
    units: dict[str, str]
    blank_tail: int = 0

    @property
    def combined(self) -> bool:
        """True when rows may be combined-load cases (an axial load, moment ... column)."""
        return any(n in COMBINED_COLUMNS for n in self.names)

    @property
    def pairs(self) -> bool:
        """True when every row is a bearing pair (an arrangement, preload or width column)."""
        return any(n in PAIR_COLUMNS for n in self.names)

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
    blank_tail = len(fields) - len(_without_blank_tail(fields))
    fields = fields[: len(fields) - blank_tail]
    names, units = [], {}
    for raw in fields:
        match = _HEADER.match(raw)
        name = (match.group(1) if match else raw).strip().lower().replace("-", "_")
        name = name.replace(" ", "_")
        names.append(name)
        if match and match.group(2):
            units[name] = match.group(2)
    if "" in names:
        raise InputError(
            "columns",
            f"the header's column {names.index('') + 1} has no name (only empty columns at the "
            "end of the header are allowed, and their cells must be empty)",
        )
    unknown = [n for n in names if n not in COLUMNS]
    if unknown:
        raise InputError(
            "columns",
            f"unknown column(s) {', '.join(repr(n) for n in unknown)}; "
            f"allowed: {', '.join(COLUMNS)}",
        )
    _check_combined(names)
    _check_pairs(names)
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise InputError("columns", f"column(s) given twice: {', '.join(twice)}")
    if "load" not in names:
        raise InputError("columns", "the column 'load' is required")
    for name, unit in units.items():
        _check_header_unit(name, unit)
    return Header(tuple(names), units, blank_tail)


def _without_blank_tail(fields: list[str]) -> list[str]:
    """The header cells without the empty ones at its end (``balls,load,`` -> balls, load)."""
    end = len(fields)
    while end > 1 and not fields[end - 1].strip():
        end -= 1
    return fields[:end]


def unit_kind(kind: str) -> str:
    """The units.py kind of a column kind: a clearance is a length, a cage angle an angle."""
    kinds = {"clearance": "length", "cage_angle": "angle", "tilt_radius": "length"}
    return (kinds | {"preload": "force"}).get(kind, kind)


def _check_combined(names: list[str]) -> None:
    """A file with combined-load columns names its bearings (or ball geometry) and no
    radial-only column."""
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


def _check_pairs(names: list[str]) -> None:
    """A file of pairs names its bearings (or ball geometry) and no column a pair cannot take."""
    given = [n for n in names if n in PAIR_COLUMNS]
    if not given:
        return
    if not any(n in ("bearing", "ball_diameter", "pitch_diameter") for n in names):
        raise InputError(
            "columns",
            f"{given[0]}: a file of bearing pairs needs angular-contact ball bearings: add a "
            "'bearing' column (7205B, 7205BDB) or 'ball_diameter', 'pitch_diameter' and "
            "'contact_angle'",
        )
    refused = [n for n in names if n in NOT_PAIRS]
    if refused:
        raise InputError(
            "columns",
            f"{refused[0]}: not used in a file of bearing pairs ({given[0]}): a pair is solved "
            "by the exact model of its angular-contact bearings, no clearance (the contact "
            "angle fixes the geometry), no misalignment (give the moment)",
        )


def _check_header_unit(name: str, unit: str) -> None:
    from bearingload.units import UNITS, parse_quantity, stiffness_factor

    kind = unit_kind(COLUMNS[name])
    if kind == "temperature":
        from bearingload.units import TEMPERATURE_UNITS

        if unit not in TEMPERATURE_UNITS:
            raise InputError(f"{name} [{unit}]", f"allowed units: {', '.join(TEMPERATURE_UNITS)}")
    elif kind == "stiffness":
        stiffness_factor(unit, None, parameter=f"{name} [{unit}]")
    elif kind in UNITS:
        parse_quantity("1" + unit, kind, parameter=f"{name} [{unit}]")
    else:
        raise InputError(f"{name} [{unit}]", "this column takes no unit")


@dataclass
class Block:
    """One chunk of data rows as read: their row numbers (the header is row 1), their cells,
    and the rows that could not be read (row number -> reason)."""

    numbers: list[int] = field(default_factory=list)
    cells: list[list[str]] = field(default_factory=list)
    errors: dict[int, str] = field(default_factory=dict)


def read_cases(stream: BinaryIO, size: int = CHUNK_ROWS) -> tuple[Header, Iterator[Block]]:
    """The header of a csv file read as bytes (row 1), and its blocks of up to ``size`` rows.

    The rows are read by the ``csv`` module (a quoted cell may hold commas and line breaks; a
    record's row number is that of its last line). Each line is decoded as UTF-8 on its own (a
    byte order mark before the header is dropped): a line that is not UTF-8 is a bad row named
    by its number, not the end of the file. Blank lines are skipped (they still count as rows).

    Raises
    ------
    InputError
        (parameter ``CASES`` or ``columns``) for a header that cannot be read.
    """
    lines = iter(stream)
    return _header(next(lines, None)), _blocks(lines, size)


def _blocks(lines: Iterator[bytes], size: int) -> Iterator[Block]:
    errors: dict[int, str] = {}
    quotes: dict[int, int] = {}  # row -> quote characters, of the lines that have any
    reader = csv.reader(_decoded(lines, errors, quotes))
    block, last = Block(), 1
    while True:
        try:
            cells = next(reader)
        except StopIteration:
            break
        except csv.Error:
            cells = ["\0"]  # unreadable: a cell count that never fits
        row = reader.line_num + 1
        if row > last + 1 and sum(quotes.pop(r, 0) for r in range(last + 1, row + 1)) % 2:
            start = last + 1  # an odd count: the reader took every line to the end into a cell
            errors[start] = (f"a quote opened in this row is never closed: rows {start} to {row} "
                             "(the end of the file) were read as one cell")  # fmt: skip
            cells = []
        quotes.pop(row, None)
        last = row
        block.errors |= errors
        errors.clear()
        if cells:
            block.numbers.append(row)
            block.cells.append(cells)
        if len(block.numbers) + len(block.errors) >= size:
            yield block
            block = Block()
    block.errors |= errors
    if block.numbers or block.errors:
        yield block


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


def _decoded(lines: Iterator[bytes], errors: dict[int, str], quotes: dict[int, int]) -> Any:
    """The text of each line after the header (row 2 on); a line that is not UTF-8 goes to
    ``errors`` and reads as a blank line. Lines with quote characters are counted in
    ``quotes``."""
    for row, raw in enumerate(lines, start=2):
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError as exc:
            errors[row] = f"not UTF-8 text ({_where(exc)})"
            text = "\n"
        if '"' in text:
            quotes[row] = text.count('"')
        yield text


def _where(exc: UnicodeDecodeError) -> str:
    return f"{exc.reason} at byte {exc.start + 1} of the line"


def row_message(exc: Exception) -> str:
    """The reason a row is skipped, ``column: message``, from a library error's fields (the
    columns of inputs a case would ignore, or of an oil's inputs refused together, all named;
    a model's name of an input, ``f_i``, as its column: :func:`bearingload.plan.inputs.
    argument_of`)."""
    if not isinstance(exc, InputError):
        return str(exc)
    from bearingload.plan.inputs import argument_of

    names = [argument_of(n) for n in getattr(exc, "parameters", None) or (exc.parameter,)]
    joint = ", " if isinstance(exc, UnusedError) else " / "
    return f"{joint.join('eC' if n == 'e_c' else n for n in names)}: {exc.message}"


def read_column(
    parser: CellParser, texts: Sequence[str], exponents: Sequence[float] | None = None
) -> tuple[list[Any], dict[int, str]]:
    """The values of one column's cells in package units (None: a blank cell) and the reasons
    of the cells that cannot be read (index -> ``column: reason``). ``exponents``: each row's
    m, which a stiffness unit needs (default 1.5).

    A column of bare numbers is read by numpy at once (a header unit scales it); otherwise, or
    when some number is implausible without a unit, each distinct cell text is parsed once."""
    fast = parser.bare_numbers(texts, exponents)
    if fast is not None:
        return fast, {}
    values: list[Any] = []
    bad: dict[int, str] = {}
    seen: dict[tuple[str, float], tuple[bool, Any]] = {}
    for i, text in enumerate(texts):
        key = (text, 1.5 if exponents is None else exponents[i])
        hit = seen.get(key)
        if hit is None:
            t = text.strip()
            try:
                hit = seen[key] = (True, parser.parse(t, key[1]) if t else None)
            except InputError as exc:
                hit = seen[key] = (False, row_message(exc))
        if not hit[0]:
            bad[i] = hit[1]
        values.append(hit[1] if hit[0] else None)
    return values, bad


class CellParser:
    """Parse the cells of one column: ``parse(text)`` returns the value in the package unit, or
    raises :class:`InputError` named after the column."""

    def __init__(self, name: str, unit: str | None) -> None:
        self.name = name
        self.kind = COLUMNS[name]
        self.unit = unit

    def bare_numbers(self, texts: Sequence[str], m: Sequence[float] | None) -> list[Any] | None:
        """Every cell a bare number (no unit, word or blank), read at once and in package units
        as :meth:`parse` reads each; None when some cell needs :meth:`parse` (also to be named:
        a fraction of a ball, a number implausible without a unit, infinity)."""
        import numpy as np

        words = ("text", "pick", "ring", "level", "exponent", "tilt_radius", "flag", "temperature")
        if not texts or self.kind in words:
            return None
        if "_" in "".join(texts):  # numpy reads '1_000' as Python does; the parser refuses it
            return None
        try:
            v = np.array(texts, dtype=float)
        except ValueError:
            return None
        if not np.all(np.isfinite(v)) or (self.kind == "count" and np.any(v != np.round(v))):
            return None
        if self.kind in ("count", "number"):
            return v.tolist()
        if not self.unit:
            return None if _implausible(self.name, self.kind, v) else v.tolist()
        from bearingload import units

        if self.kind == "stiffness":
            exponents = np.full(v.size, 1.5) if m is None else np.asarray(m, dtype=float)
            try:  # a unit of another exponent: the parser names the row
                factor = {e: units.stiffness_factor(self.unit, e, parameter=self.name)
                          for e in set(exponents.tolist())}  # fmt: skip
            except InputError:
                return None
            return (v * np.array([factor[e] for e in exponents.tolist()])).tolist()
        if self.kind == "cage_angle":
            return (v * float(units.parse_cage_angle("1" + self.unit))).tolist()
        return (v * units.parse_quantity("1" + self.unit, unit_kind(self.kind))).tolist()

    def parse(self, text: str, exponent: float = 1.5) -> Any:
        from bearingload import units

        kind, name = self.kind, self.name
        if kind in ("text", "pick"):
            return _choice(name, text) if kind == "pick" else text
        if kind == "level":
            from bearingload.constants import CONTAMINATION_LEVELS

            if text not in CONTAMINATION_LEVELS:
                raise InputError(
                    name, f"unknown level {text!r}; allowed: {', '.join(CONTAMINATION_LEVELS)}"
                )
            return text
        if kind == "flag":
            if text.lower() not in FLAGS:
                raise InputError(
                    name, f"cannot read {text!r}; allowed: true, false (or blank: false)"
                )
            return FLAGS[text.lower()]
        if kind == "ring":
            if text not in ("inner", "outer"):
                raise InputError(name, f"unknown ring {text!r}; allowed: inner, outer")
            return text
        if kind in ("number", "count"):
            return _number(name, text, whole=kind == "count")
        if kind == "exponent":
            return _exponent(text)
        plain = _plain(name, text)
        if kind == "temperature":  # °C, K with a unit: the one reading of --temperature
            suffix = self.unit if self.unit and plain is not None else ""
            return units.parse_temperature(text + suffix, parameter=name)
        if kind == "tilt_radius":  # groove, pitch or a length, as --tilt-radius reads it
            from bearingload.bearings.tilt import parse_tilt_radius

            return parse_tilt_radius(text + (self.unit if self.unit and plain is not None else ""))
        if kind == "cage_angle":  # the one reading of solve, sweep and table
            if plain is None:
                return units.parse_cage_angle(text, parameter=name)
            if not self.unit:
                return plain
            return plain * float(units.parse_cage_angle("1" + self.unit, parameter=name))
        if kind == "preload" and plain is None:  # a class letter or a force with its unit
            from bearingload.bearings.preload import parse_preload

            return parse_preload(text, parameter=name)
        if kind == "clearance" and re.fullmatch(r"(?i)c[2-5n]|g[6-9]|cn|normal", text):
            from bearingload.bearings.clearance import parse_clearance

            return parse_clearance(text)
        if kind == "stiffness":
            if plain is not None and self.unit:
                return plain * units.stiffness_factor(self.unit, exponent, parameter=name)
            return units.parse_stiffness(text, exponent, parameter=name)
        if plain is not None and self.unit:
            return plain * units.parse_quantity("1" + self.unit, unit_kind(kind), parameter=name)
        # a bare number: refused when implausible for its quantity, as on the command line
        return units.parse_quantity(text, unit_kind(kind), parameter=name)


def _implausible(name: str, kind: str, values: Any) -> bool:
    """Whether some bare number lies outside the plausible range of its quantity
    (:data:`bearingload.units.PLAUSIBLE_BARE`)."""
    import numpy as np

    from bearingload.units import PLAUSIBLE_BARE

    kind = unit_kind(kind)
    rule = PLAUSIBLE_BARE.get((kind, name)) or PLAUSIBLE_BARE.get((kind, None))
    if rule is None:
        return False
    low, high, _ = rule
    return bool(np.any((values < low) | (values >= high)))


def _float(text: str) -> float:
    """``float(text)`` without the underscores Python allows ('1_000'): the command line's
    unit parser refuses them, and so must every cell."""
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


def _number(name: str, text: str, *, whole: bool) -> float:
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
    """A clearance pick: min, mean or max (the pick 'range' refused by the plan's rule)."""
    from bearingload.plan.bearing import refuse_range
    from bearingload.plan.case import Case

    if text == "range":
        refuse_range(Case(clearance_pick=text), "batch")
    if text not in ("min", "mean", "max"):
        raise InputError(name, f"unknown pick {text!r}; allowed: min, mean, max")
    return text
