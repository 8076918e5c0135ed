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
from dataclasses import dataclass
from typing import Any, TextIO

from bearingload.errors import InputError

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
}
#: Options of ``solve`` that a batch file cannot carry yet (the combined-load path).
NOT_YET = ("axial_load", "moment", "misalignment", "dynamic_rating", "rotating")
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
_HEADER = re.compile(r"^\s*([^\[\]]*?)\s*(?:\[\s*([^\]]*?)\s*\])?\s*$")


@dataclass(frozen=True)
class Header:
    """The columns of a batch file: ``names`` in file order and each one's header ``units``."""

    names: tuple[str, ...]
    units: dict[str, str]

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
    unknown = [n for n in names if n not in COLUMNS and n not in NOT_YET]
    if unknown:
        raise InputError(
            "columns",
            f"unknown column(s) {', '.join(repr(n) for n in unknown)}; "
            f"allowed: {', '.join(COLUMNS)}",
        )
    later = [n for n in names if n in NOT_YET]
    if later:
        raise InputError(
            "columns",
            f"{', '.join(later)}: the combined load is not solved by batch yet; "
            "use 'bearingload solve' for it",
        )
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise InputError("columns", f"column(s) given twice: {', '.join(twice)}")
    if "load" not in names:
        raise InputError("columns", "the column 'load' is required")
    for name, unit in units.items():
        _check_header_unit(name, unit)
    return Header(tuple(names), units)


def _check_header_unit(name: str, unit: str) -> None:
    from bearingload.units import UNITS, parse_quantity, stiffness_factor

    kind = COLUMNS[name]
    kind = "length" if kind == "clearance" else "angle" if kind == "cage_angle" else kind
    if kind == "stiffness":
        stiffness_factor(unit, None, parameter=f"{name} [{unit}]")
    elif kind in UNITS:
        parse_quantity("1" + unit, kind, parameter=f"{name} [{unit}]")
    else:
        raise InputError(f"{name} [{unit}]", "this column takes no unit")


def chunks(stream: TextIO, size: int) -> Iterator[tuple[Header, list[tuple[int, list[str]]]]]:
    """The header and then lists of up to ``size`` (row number, cells); the header is row 1.
    A file with a header and no rows yields the header once with no rows.

    Blank lines are skipped (they still count as rows); a line the csv reader cannot read
    comes with one cell, so that its cell count does not fit the header.
    """
    import csv

    reader = csv.reader(stream)
    try:
        first = next(reader)
    except StopIteration:
        raise InputError("CASES", "the file is empty; its first line names the columns") from None
    except csv.Error as exc:
        raise InputError("CASES", f"cannot read the header line: {exc}") from None
    header = read_header(first)
    batch: list[tuple[int, list[str]]] = []
    any_rows = False
    while True:
        try:
            row = next(reader)
        except StopIteration:
            break
        except csv.Error:
            row = ["\0"]  # unreadable: a cell count that never fits
        if not row:
            continue
        batch.append((reader.line_num, row))
        any_rows = True
        if len(batch) >= size:
            yield header, batch
            batch = []
    if batch or not any_rows:
        yield header, batch


class CellParser:
    """Parse the cells of one column, each distinct text once.

    ``parse(text)`` returns the value in the package unit, or raises :class:`InputError` named
    after the column; results and errors are cached.
    """

    def __init__(self, name: str, unit: str | None) -> None:
        self.name = name
        self.kind = COLUMNS[name]
        self.unit = unit
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
        if kind in ("number", "count"):
            return _number(name, text, self.unit, whole=kind == "count")
        if kind == "exponent":
            return _exponent(text)
        if kind == "cage_angle" and text.lower() == "half":
            return "half"
        if kind == "clearance" and re.fullmatch(r"(?i)c[2-5n]|g[6-9]|cn|normal", text):
            from bearingload.bearings.clearance import parse_clearance

            return parse_clearance(text)
        plain = _plain(name, text)
        if kind == "stiffness":
            if plain is not None and self.unit:
                return plain * units.stiffness_factor(self.unit, exponent, parameter=name)
            return units.parse_stiffness(text, exponent, parameter=name)
        kind = "length" if kind == "clearance" else "angle" if kind == "cage_angle" else kind
        if plain is not None and self.unit:
            return units.parse_quantity(f"{plain!r}{self.unit}", kind, parameter=name)
        # a bare number: refused when implausible for its quantity, as on the command line
        return units.parse_quantity(text, kind, parameter=name)


def _plain(name: str, text: str) -> float | None:
    """A bare finite number, or None (then the unit parser reads the text)."""
    try:
        v = float(text)
    except ValueError:
        return None
    if v != v or v in (float("inf"), float("-inf")):
        raise InputError(name, f"{text!r} is not a finite number")
    return v


def _number(name: str, text: str, unit: str | None, *, whole: bool) -> float:
    try:
        v = float(text)
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
        return float(num) / float(den) if slash else float(text)
    except (ValueError, ZeroDivisionError):
        raise InputError(
            "exponent", f"{text!r} is neither a number nor a fraction like 10/9"
        ) from None


def _choice(name: str, text: str) -> str:
    if text not in ("min", "mean", "max"):
        raise InputError(name, f"unknown pick {text!r}; allowed: min, mean, max")
    return text
