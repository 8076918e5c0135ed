"""Solving the rows of a block: each column read by :mod:`bearingload.batch.read`, the cases
solved by the plan of many cases (:class:`bearingload.plan.many.Planner`, as solve plans one);
each refusal a skipped row with its reason, ``column: message``."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from bearingload.batch.read import Block, Header, library_name, read_column, row_message
from bearingload.plan.many import Planner


@dataclass
class Chunk:
    """The answer for one block: the solved ``rows`` (row numbers), their ``values`` (key ->
    array or list over them; ``warnings`` a tuple each) and the skipped rows (number, reason)."""

    rows: list[int] = field(default_factory=list)
    values: dict[str, Any] = field(default_factory=dict)
    errors: list[tuple[int, str]] = field(default_factory=list)


class BatchSolver:
    """Solve the blocks of one case file; the plans of its rows are kept from block to block."""

    def __init__(self, header: Header) -> None:
        self.header = header
        self.planner = Planner([library_name(n) for n in header.names])

    def solve(self, block: Block) -> Chunk:
        """Solve one block of rows."""
        errors, width = dict(block.errors), len(self.header.names)
        numbers, rows = [], []  # a line with another number of cells is a bad row
        for number, cells in zip(block.numbers, block.cells, strict=True):
            message = self._malformed(cells)
            if message is None:
                numbers.append(number)
                rows.append(cells[:width])
            else:
                errors[number] = message
        cols, bad, bare = self._columns(rows)
        if self.header.pairs:
            from bearingload.batch.report import pair_rows
            from bearingload.plan.many_pairs import solve_pair_cases

            many = solve_pair_cases(self.planner, cols, len(numbers), bad, bare)
            solved, values = pair_rows(self.header, many, numbers, cols, errors)
        else:
            many = self.planner.solve(cols, len(numbers), bad, bare, self.typed)
            solved, values = [numbers[i] for i in many.rows], many.values
        for i, why in many.errors.items():
            errors[numbers[i]] = why if isinstance(why, str) else row_message(why)
        return Chunk(solved, values, sorted(errors.items()))

    def _malformed(self, cells: list[str]) -> str | None:
        """Why a row's cells do not fit the header, or None: one cell per named column, and
        up to the header's empty trailing columns more, left empty."""
        width, tail = len(self.header.names), self.header.blank_tail
        if not width <= len(cells) <= width + tail:
            named = f" (and {tail} unnamed empty one(s) after them)" if tail else ""
            return f"malformed line: {len(cells)} cells, the header names {width} columns{named}"
        extra = next((c for c in cells[width:] if c.strip()), None)
        if extra is None:
            return None
        return (
            f"a value ({extra!r}) in a column the header gives no name (after its last column "
            f"'{self.header.names[-1]}'); name the column or leave it empty"
        )

    def _columns(self, rows: list[list[str]]) -> tuple[dict[str, list[Any]], dict[int, Any], Any]:
        """Every column's values by its input's name (None: blank), each failing row's first
        error (the exponent first: a stiffness unit depends on it, then in file order), and
        whether each cell of a column judged against the bearing's size had no unit."""
        from bearingload.bearings.designation import contact_exponent
        from bearingload.bearings.plausible import BEARING_SCALE
        from bearingload.plan.case import TypedRows, negative_load
        from bearingload.units import is_bare

        names, units = self.header.names, self.header.units
        texts = dict(zip(names, zip(*rows, strict=True), strict=True)) if rows else {}
        self.typed = TypedRows(names, rows, units)  # each row's, read when a row is named
        cols: dict[str, list[Any]] = {}
        bad: dict[int, Any] = {}
        kinds = {t: contact_exponent(t) for t in set(texts.get("bearing", ()))}
        m = [kinds[t] for t in texts["bearing"]] if "bearing" in texts else None  # 10/9: rollers
        for name in sorted(names, key=lambda n: n != "exponent"):
            values, failed = read_column(name, units.get(name), texts.get(name, ()), m)
            if name == "load":  # -0 is 0; below 0: refused as typed by its bearing's rule
                values = [None if f is None else f + 0.0 for f in values]
                for i in [i for i, f in enumerate(values) if f is not None and f < 0]:
                    cells = dict(zip(names, rows[i], strict=True))
                    failed[i] = row_message(negative_load(cells, values[i], units.get(name, "")))
            bad = failed | bad  # a row's first error kept
            cols[library_name(name)] = values
            if name == "exponent":  # the given exponents, else the bearings'
                m = [(m[i] if m else 1.5) if x is None else x for i, x in enumerate(values)]
        judged = self.header.has_bearing  # bare numbers judged against a bearing's size
        scale = [n for n in BEARING_SCALE if judged and n in texts and n not in units]
        return cols, bad, {n: [is_bare(t) for t in texts[n]] for n in scale}
