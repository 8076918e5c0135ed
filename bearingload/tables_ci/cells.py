"""Two texts of one table compared cell by cell: numbers within a tolerance, text exactly.

* csv: read with :mod:`csv`; the first line is the header (text), a cell is named by its data
  row (1 = the first row under the header) and its column's header.
* markdown: every line that is not part of a pipe table (title, notes) is text, compared whole;
  a pipe table's cells are split at the pipes (the rule under the header is left out) and named
  as in csv.
* json: the two documents are walked together; a value is named by the path of its parent (the
  row, e.g. ``rows[7]``) and its key or index (the column).

A cell that reads as a number in both texts (``float()``: ``1``, ``1.0``, ``1e+00`` are one
number) agrees when ``|a - b| <= max(rtol max(|a|, |b|), atol)``; any other cell agrees when its
text is identical. A missing or extra row, column or key is a difference of its own.
"""

from __future__ import annotations

import math
from typing import Any

from bearingload.lazy_dataclass import dataclass

#: How a difference shows the side that has no such cell.
ABSENT = "(absent)"


@dataclass(frozen=True)
class Cell:
    """A cell that differs: where (``row``, ``column``), its two texts, and the relative
    difference ``|a - b| / max(|a|, |b|)`` of two numbers (``None`` for text). [-]"""

    row: str
    column: str
    committed: str
    regenerated: str
    relative: float | None = None


def numbers_agree(a: float, b: float, rtol: float, atol: float) -> tuple[bool, float]:
    """Whether two numbers agree within ``rtol`` (relative) or ``atol`` (absolute), and their
    relative difference [-] (0 for equal numbers, nan when one is nan).

    >>> numbers_agree(1.0, 1.0 + 1e-12, 1e-9, 0.0)[0], numbers_agree(0.0, 1e-15, 1e-9, 1e-12)[0]
    (True, True)
    >>> numbers_agree(2.0, 2.002, 1e-9, 0.0)
    (False, 0.000999000999)
    """
    if math.isnan(a) or math.isnan(b):
        same = math.isnan(a) and math.isnan(b)
        return same, 0.0 if same else math.nan
    if a == b:
        return True, 0.0
    if math.isinf(a) or math.isinf(b):
        return False, math.inf
    gap = abs(a - b)
    scale = max(abs(a), abs(b))
    relative = gap / scale if math.isfinite(gap) else math.inf  # the gap of two huge numbers
    return gap <= max(rtol * scale, atol), relative


def _number(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


def _compare_cell(row: str, column: str, a: str, b: str, rtol: float, atol: float) -> Cell | None:
    x, y = _number(a), _number(b)
    if x is not None and y is not None:
        same, relative = numbers_agree(x, y, rtol, atol)
        return None if same else Cell(row, column, a, b, relative)
    return None if a == b else Cell(row, column, a, b)


def compare_grid(
    a: list[list[str]], b: list[list[str]], rtol: float, atol: float, prefix: str = ""
) -> list[Cell]:
    """Two tables of text cells whose first row is the header, cell by cell."""
    out: list[Cell] = []
    header_a, header_b = (a[0] if a else []), (b[0] if b else [])
    for j in range(max(len(header_a), len(header_b))):
        ha = header_a[j] if j < len(header_a) else ABSENT
        hb = header_b[j] if j < len(header_b) else ABSENT
        if ha != hb:
            out.append(Cell(f"{prefix}header", f"column {j + 1}", ha, hb))
    for i in range(1, max(len(a), len(b))):
        row = f"{prefix}row {i}"
        if i >= len(a) or i >= len(b):
            there = a[i] if i < len(a) else b[i]
            text = ",".join(there)
            out.append(
                Cell(row, "(whole row)", *((text, ABSENT) if i < len(a) else (ABSENT, text)))
            )
            continue
        for j in range(max(len(a[i]), len(b[i]))):
            column = header_a[j] if j < len(header_a) else f"column {j + 1}"
            ca = a[i][j] if j < len(a[i]) else ABSENT
            cb = b[i][j] if j < len(b[i]) else ABSENT
            cell = _compare_cell(row, column, ca, cb, rtol, atol)
            if cell is not None:
                out.append(cell)
    return out


def _csv_rows(text: str) -> list[list[str]]:
    import csv
    import io

    return list(csv.reader(io.StringIO(text)))


def _markdown_blocks(text: str) -> list[tuple[int, Any]]:
    """The blocks of a Markdown text: ``(line, str)`` for a text line, ``(line, grid)`` for a pipe
    table (its header and body cells, the rule left out)."""
    blocks: list[tuple[int, Any]] = []
    lines = text.replace("\r\n", "\n").split("\n")  # (CR LF: a checkout's line ends)
    i = 0
    while i < len(lines):
        if not lines[i].lstrip().startswith("|"):
            blocks.append((i + 1, lines[i]))
            i += 1
            continue
        start, grid = i, []
        while i < len(lines) and lines[i].lstrip().startswith("|"):
            cells = [c.strip() for c in lines[i].strip().strip("|").split("|")]
            if not (i == start + 1 and all(set(c) <= set("-: ") and c for c in cells)):
                grid.append(cells)
            i += 1
        blocks.append((start + 1, grid))
    return blocks


def _compare_markdown(a: str, b: str, rtol: float, atol: float) -> list[Cell]:
    """Text lines aligned as a diff aligns them (a line added or removed is one difference,
    not a shift of every line after it); pipe tables paired in order and compared as grids."""
    from difflib import SequenceMatcher

    out: list[Cell] = []
    blocks_a, blocks_b = _markdown_blocks(a), _markdown_blocks(b)
    keys_a = [None if isinstance(x, list) else x for _, x in blocks_a]
    keys_b = [None if isinstance(x, list) else x for _, x in blocks_b]
    tables = sum(1 for k in keys_a if k is None)
    count = 0
    matcher = SequenceMatcher(None, keys_a, keys_b, autojunk=False)
    for _, i0, i1, j0, j1 in matcher.get_opcodes():
        for k in range(max(i1 - i0, j1 - j0)):
            la, ba = blocks_a[i0 + k] if i0 + k < i1 else (None, None)
            lb, bb = blocks_b[j0 + k] if j0 + k < j1 else (None, None)
            if isinstance(ba, list) and isinstance(bb, list):
                count += 1
                prefix = f"table {count}, " if tables > 1 else ""
                out += compare_grid(ba, bb, rtol, atol, prefix)
            elif ba != bb:
                line = f"line {la}" if la is not None else f"after line {_before(blocks_a, i0)}"
                out.append(Cell(line, "(text)", _block_text(ba), _block_text(bb)))
    return out


def _before(blocks: list[tuple[int, Any]], i: int) -> int:
    """The line of the committed text after which a block of the other text would stand."""
    return blocks[i - 1][0] if i > 0 else 0


def _block_text(block: Any) -> str:
    if block is None:
        return ABSENT
    if isinstance(block, list):
        return f"(a table of {len(block) - 1} rows)"
    return str(block)


def _walk(a: Any, b: Any, path: str, key: str, rtol: float, atol: float, out: list[Cell]) -> None:
    """Two json values at ``path``/``key`` walked together."""
    here = f"{path}[{key}]" if key.isdigit() else (f"{path}.{key}" if path else key)
    if isinstance(a, dict) and isinstance(b, dict):
        for k in list(a) + [k for k in b if k not in a]:
            if k not in a or k not in b:
                out.append(Cell(here or "(top)", k, *_sides(a.get(k, ABSENT), b.get(k, ABSENT))))
            else:
                _walk(a[k], b[k], here, k, rtol, atol, out)
        return
    if isinstance(a, list) and isinstance(b, list):
        for i in range(max(len(a), len(b))):
            if i >= len(a) or i >= len(b):
                out.append(Cell(here or "(top)", str(i), *_sides(*_pair(a, b, i))))
            else:
                _walk(a[i], b[i], here, str(i), rtol, atol, out)
        return
    numeric = all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in (a, b))
    if numeric:
        same, relative = numbers_agree(float(a), float(b), rtol, atol)
        if not same:
            out.append(Cell(path or "(top)", key or "(value)", *_sides(a, b), relative))
    elif a != b or type(a) is not type(b):
        out.append(Cell(path or "(top)", key or "(value)", *_sides(a, b)))


def _pair(a: list[Any], b: list[Any], i: int) -> tuple[Any, Any]:
    return (a[i] if i < len(a) else ABSENT), (b[i] if i < len(b) else ABSENT)


def _sides(a: Any, b: Any) -> tuple[str, str]:
    import json

    def text(v: Any) -> str:
        return v if v is ABSENT or isinstance(v, str) else json.dumps(v, ensure_ascii=False)

    return text(a), text(b)


def compare(committed: str, regenerated: str, fmt: str, rtol: float, atol: float) -> list[Cell]:
    """The cells of ``committed`` that differ from ``regenerated`` (format ``fmt``: csv,
    markdown or json), in the order of the file."""
    if fmt == "csv":
        return compare_grid(_csv_rows(committed), _csv_rows(regenerated), rtol, atol)
    if fmt == "markdown":
        return _compare_markdown(committed, regenerated, rtol, atol)
    if fmt == "json":
        import json

        try:
            a = json.loads(committed)
        except ValueError as exc:
            return [Cell("(file)", "(json)", f"not valid JSON: {exc}", "(valid)")]
        out: list[Cell] = []
        _walk(a, json.loads(regenerated), "", "", rtol, atol, out)
        return out
    raise ValueError(f"unknown format {fmt!r}")
