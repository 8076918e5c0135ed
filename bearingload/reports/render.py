"""The one place that turns rows into text: aligned table, CSV, Markdown or JSON.

Numbers are formatted and columns aligned here (no tabulate: its import alone costs more
than the whole terminal calculation), never by the callers, so every output is identical from run to run
(``\\n`` line ends, fixed column order) and CI can diff the committed tables against the code.
Machine formats (csv, json) carry 10 significant digits; the human ``table`` and ``markdown``
formats carry each column's display precision.
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence
from typing import Any

from bearingload.lazy_dataclass import dataclass
from bearingload.units import turn_angle

FORMATS = ("table", "csv", "markdown", "json")
MACHINE_DIGITS = 10


@dataclass(frozen=True)
class Column:
    """One column: ``key`` in the row dicts, ``header`` shown to people, ``unit``, display ``digits``.

    ``digits`` is the number of significant digits in the human formats (``None``: integers and text).
    ``display`` (unit, factor): the human formats show a number times ``factor`` in that unit (a
    relative error as ``%``); csv and json keep the number and ``unit`` as they are.
    """

    key: str
    header: str
    unit: str = ""
    digits: int | None = None
    align: str = "right"
    display: tuple[str, float] | None = None

    def label(self) -> str:
        unit = self.display[0] if self.display else self.unit
        return f"{self.header} [{unit}]" if unit else self.header

    def shown(self, value: Any) -> Any:
        """A cell as the human formats show it: a number in the display unit."""
        if self.display is None or isinstance(value, (str, bool)) or value is None:
            return value
        return value * self.display[1]


@dataclass(frozen=True)
class Table:
    """A titled block of rows with its columns and optional notes (shown under human formats).

    ``conditions`` are values shared by every row (the load, clearance ... a table was computed
    under): the human formats say them in the title, csv repeats them as leading columns (so the
    file stays one self-describing rectangular table), json carries them as fields.
    """

    title: str
    columns: Sequence[Column]
    rows: Sequence[dict[str, Any]]
    notes: Sequence[str] = ()
    conditions: Sequence[tuple[Column, Any]] = ()


#: The keys of turn angles [°], each reduced to one turn [0, 360): the cage angle and each
#: ball's angle from the load line (not a contact angle or the load zone's half-angle), which
#: every format prints by :func:`bearingload.units.turn_angle`.
TURN_KEYS = frozenset({"cage_angle", "ball_angles"})


def machine_number(value: Any) -> Any:
    """A value as written to csv/json: floats at 10 significant digits, ints and text as they are."""
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, int) or (hasattr(value, "dtype") and value.dtype.kind in "iu"):
        return int(value)
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"refusing to write a non-finite number ({v})")
    return float(f"{v:.{MACHINE_DIGITS}g}")


def _human(value: Any, digits: int | None) -> str:
    if isinstance(value, str):
        return value
    if digits is None or isinstance(value, int) or getattr(value, "dtype", None) == "int64":
        return str(int(value))
    v = float(value)
    if v == 0:
        return "0"
    if not math.isfinite(v):  # (an overflow of extreme inputs; the checks warn of those)
        return str(v)
    text = f"{v:.{digits}g}"
    if "e" in text:
        return text
    # keep trailing zeros of the significant digits, e.g. 0.5430 not 0.543
    decimals = max(digits - 1 - int(math.floor(math.log10(abs(float(text))))), 0)
    return f"{v:.{decimals}f}"


def _machine_text(value: Any) -> str:
    v = machine_number(value)
    return (
        v if isinstance(v, str) else number_text(float(value)) if isinstance(v, float) else str(v)
    )


def render(tables: Sequence[Table], fmt: str, *, document: dict[str, Any] | None = None) -> str:
    """Render tables in ``fmt`` (one of :data:`FORMATS`).

    For ``json``, ``document`` (a dict) is written if given, else ``{title: [rows...]}``.
    """
    if fmt not in FORMATS:
        raise ValueError(f"unknown format {fmt!r}; allowed: {', '.join(FORMATS)}")
    if fmt == "json":
        doc = document if document is not None else _table_documents(tables)
        import json

        return json.dumps(_machine_tree(doc), indent=2, ensure_ascii=False) + "\n"
    if fmt == "csv" and len(tables) != 1:
        raise ValueError("csv is one rectangular table: render one table at a time")
    blocks = []
    for t in tables:
        if fmt == "csv":
            blocks.append(_csv(t))
            continue
        cells = [[_human(_shown(c, r[c.key]), c.digits) for c in t.columns] for r in t.rows]
        headers = [c.label() for c in t.columns]
        align = [c.align for c in t.columns]
        if fmt == "markdown":
            text = f"### {t.title}\n\n{_grid(cells, headers, align, markdown=True)}"
            if t.notes:
                text += "\n\n" + "\n".join(f"- {n}" for n in t.notes)
        else:
            text = f"{t.title}\n\n{_grid(cells, headers, align, markdown=False)}"
            if t.notes:
                text += "\n\n" + "\n".join(t.notes)
        blocks.append(text)
    return "\n\n".join(blocks) + "\n"


def _shown(column: Column, value: Any) -> Any:
    """A cell as the human formats show it (:meth:`Column.shown`), a turn angle by
    :func:`turn_angle` at the column's digits."""
    value = column.shown(value)
    if column.key in TURN_KEYS and column.digits is not None:
        return turn_angle(value, column.digits)
    return value


def _grid(cells: list[list[str]], headers: list[str], align: list[str], *, markdown: bool) -> str:
    """Aligned columns: a plain table with a dashed rule, or a Markdown pipe table."""
    widths = [max([len(h)] + [len(row[i]) for row in cells]) for i, h in enumerate(headers)]
    if markdown:
        widths = [max(w, 3) for w in widths]

    def line(values: list[str]) -> str:
        parts = [
            v.rjust(w) if a == "right" else v.ljust(w)
            for v, w, a in zip(values, widths, align, strict=True)
        ]
        return ("| " + " | ".join(parts) + " |") if markdown else "  ".join(parts).rstrip()

    if markdown:
        rule = (
            "|"
            + "|".join(
                ("-" * (w + 1) + ":") if a == "right" else (":" + "-" * (w + 1))
                for w, a in zip(widths, align, strict=True)
            )
            + "|"
        )
    else:
        rule = "  ".join("-" * w for w in widths)
    return "\n".join([line(headers), rule] + [line(row) for row in cells])


def _csv(t: Table) -> str:
    """One rectangular csv table: the conditions as leading columns, then the row columns."""
    columns = [c for c, _ in t.conditions] + list(t.columns)
    if len({c.key for c in columns}) != len(columns):
        raise ValueError(f"csv columns named twice in table {t.title!r}")
    values = {c.key: [v] * len(t.rows) for c, v in t.conditions}
    values |= {c.key: [r[c.key] for r in t.rows] for c in t.columns}
    return (csv_header(columns) + csv_block(columns, values)).removesuffix("\n")


def _table_documents(tables: Sequence[Table]) -> Any:
    docs = [table_document(t) for t in tables]
    return docs[0] if len(docs) == 1 else docs


def table_document(t: Table) -> dict[str, Any]:
    """The JSON object of one table: ``title``, ``conditions`` (where it has them), ``units``
    (of the columns that have one) and ``rows``."""
    doc: dict[str, Any] = {"title": t.title}
    if t.conditions:
        doc["conditions"] = {c.key: v for c, v in t.conditions}
    units = {c.key: c.unit for c, _ in t.conditions if c.unit} | {
        c.key: c.unit for c in t.columns if c.unit
    }
    return doc | {"units": units, "rows": list(t.rows)}


def _csv_header(column: Column) -> str:
    """A csv column name: the key, with its unit where it has one (``load [N]``)."""
    unit = column.unit if column.unit not in ("", "-") else ""
    return _csv_cell(f"{column.key} [{unit}]" if unit else column.key)


def _csv_cell(text: str) -> str:
    """A cell quoted where a csv reader needs it: a comma, a quote or a line end (CR or LF, as
    the csv module quotes them)."""
    if any(ch in text for ch in ',"\n\r'):
        return '"' + text.replace('"', '""') + '"'
    return text


def plain_tree(obj: Any) -> Any:
    """A document of dicts, lists, numpy arrays and scalars as plain Python values at full
    precision (what :func:`render` writes as json, before its rounding to 10 digits)."""
    if isinstance(obj, dict):
        return {k: plain_tree(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [plain_tree(v) for v in obj]
    if hasattr(obj, "tolist"):
        return plain_tree(obj.tolist()) if getattr(obj, "ndim", 0) > 0 else obj.item()
    return obj


def _machine_tree(obj: Any, turn: bool = False) -> Any:
    """A document as json writes it, the numbers by :func:`machine_number`; ``turn``: the
    numbers of a key of :data:`TURN_KEYS` (and of its lists), by :func:`turn_angle` too."""
    if isinstance(obj, dict):
        return {k: _machine_tree(v, k in TURN_KEYS) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_machine_tree(v, turn) for v in obj]
    if hasattr(obj, "tolist") and getattr(obj, "ndim", 0) > 0:
        return [_machine_tree(v, turn) for v in obj.tolist()]
    return machine_number(turn_angle(obj, MACHINE_DIGITS) if turn else obj)


def csv_header(columns: Sequence[Column]) -> str:
    """The csv header line of ``columns`` (with its line end), as :func:`render` writes it."""
    return ",".join(_csv_header(c) for c in columns) + "\n"


def csv_block(columns: Sequence[Column], values: dict[str, Any]) -> str:
    """csv lines (each with its line end) of column-wise ``values`` (key -> list or numpy
    array over the rows; None in a list: a blank cell): the cells :func:`render` writes for the
    same rows, so that a long table can be written in chunks."""
    if not columns or not len(values[columns[0].key]):
        return ""
    cells = [_column_cells(c.key, values[c.key]) for c in columns]
    return "\n".join(map(",".join, zip(*cells, strict=True))) + "\n"


def number_text(value: float) -> str:
    """The csv text of a float: ``repr(float(f"{value:.10g}"))`` (:func:`machine_number`),
    the one formatting of every number in every csv. Where ``%.10g`` writes a point and no
    exponent, that is already its text (the same digits in the same notation)."""
    text = f"{value:.10g}"
    if "." in text and "e" not in text:
        return text
    if not math.isfinite(value):
        raise ValueError(f"refusing to write a non-finite number ({value})")
    return repr(float(text))


def _column_cells(key: str, vals: Any) -> list[str]:
    """The cells of one column: floats by :func:`number_text`, each distinct other value once."""
    items = vals.tolist() if hasattr(vals, "tolist") else vals
    kind = getattr(getattr(vals, "dtype", None), "kind", "")
    if key in TURN_KEYS and (kind != "f" or bool((vals >= 355.0).any())):
        import numpy as np  # (no angle below 355° rounds to 360: turn_angle)

        items = [turn_angle(v, MACHINE_DIGITS) for v in items]
        vals = np.asarray(items, dtype=float) if kind == "f" else items
    if not kind and items and items[0] is None and items.count(None) == len(items):
        return [""] * len(items)  # (a column no row gives: the radial engine's matrix entries)
    try:
        if kind == "f":
            import numpy as np

            same = np.all(vals == vals[0]) and np.all(np.signbit(vals) == np.signbit(vals[0]))
            if same:  # one text for a constant column (y = 0, m = 1.5)
                return [number_text(items[0])] * len(items)
            return list(map(number_text, items))
        if kind in ("i", "u") or (
            items and type(items[0]) is int and set(map(type, items)) == {int}
        ):
            return list(map(str, items))
        if kind == "b":
            return list(map({True: "True", False: "False"}.__getitem__, items))
        if items and type(items[0]) is str and items.count(items[0]) == len(items):
            return [_cell(items[0])] * len(items)  # one text in every row (method exact)
        seen: dict[Any, str] = {}
        out = []
        for v in items:
            k = (type(v), v if type(v) is not float else repr(v))  # 0.0 and -0.0 differ
            text = seen.get(k)
            if text is None:
                text = seen[k] = _cell(v)
            out.append(text)
        return out
    except ValueError as exc:  # a NaN or infinity: name its column
        raise ValueError(f"refusing to write a non-finite number in column {key!r}") from exc


def _cell(value: Any) -> str:
    return "" if value is None else _csv_cell(_machine_text(value))


class atomic_file:
    """``with atomic_file(path) as fh:`` write ``fh``; the file appears whole when the block ends
    without an exception, and is left as it was when it raises (see :func:`write_atomic`)."""

    def __init__(self, path: str) -> None:
        self.path = path
        self.tmp: str | None = None
        self.fh: Any = None

    def __enter__(self) -> Any:
        real = os.path.realpath(self.path)
        if os.path.isdir(real):
            raise IsADirectoryError(21, "is a directory", self.path)
        self.real = real
        if os.path.exists(real) and not os.path.isfile(real):
            self.fh = open(real, "w", encoding="utf-8", newline="\n")  # noqa: SIM115
            return self.fh
        if os.path.exists(real):
            self.mode = os.stat(real).st_mode & 0o7777
        else:
            umask = os.umask(0)
            os.umask(umask)
            self.mode = 0o666 & ~umask
        import tempfile  # imported here: it costs more than the rest of a terminal run's rendering

        fd, self.tmp = tempfile.mkstemp(prefix=".bearingload-", dir=os.path.dirname(real))
        self.fh = os.fdopen(fd, "w", encoding="utf-8", newline="\n")
        return self.fh

    def __exit__(self, kind: Any, exc: Any, tb: Any) -> None:
        try:
            if self.tmp is not None and kind is None:
                self.fh.flush()
                os.fchmod(self.fh.fileno(), self.mode)
            self.fh.close()
            if self.tmp is not None and kind is None:
                os.replace(self.tmp, self.real)
        finally:
            if self.tmp is not None and os.path.exists(self.tmp):
                os.unlink(self.tmp)


def write_atomic(text: str, path: str) -> None:
    """Write ``text`` to ``path`` whole or not at all.

    A regular file (new or existing) is written to a temporary file in the same directory and
    renamed over the target, so a reader never sees half a file and a failure leaves the old
    file as it was. The result has the permissions of the file it replaces, or 0666 less the
    umask for a new file. A symbolic link is followed (the file it points to is replaced, the
    link stays). Something that exists but cannot be replaced (a device, a FIFO) is written to
    directly. Raises OSError (e.g. IsADirectoryError) when the path cannot be written.
    """
    with atomic_file(path) as fh:
        fh.write(text)
