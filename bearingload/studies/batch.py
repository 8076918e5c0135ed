"""Many cases at once: the computation behind ``bearingload batch``.

A chunk of rows of a case file (:mod:`bearingload.studies.batch_input`) is read cell by cell,
each row checked on its own, and then every row of one method is solved by ONE vectorised call
of the registered model (:mod:`bearingload.models.registry`, e.g. the exact ring equilibrium
:func:`bearingload.models.equilibrium.solve`, which broadcasts over arrays). A catalogue bearing
is resolved once per distinct (designation, overrides, clearance) and its z, K, G_r enter the
same arrays. Should a vectorised call still fail, that method's rows of the chunk are solved one
by one, so the offending row is named and the others are kept. Each case's answer depends on its
own row only: the engine solves every case independently.

The quantities are those of :func:`bearingload.studies.loaded_bearing.case_values` (the keys of
:mod:`bearingload.reports.quantities`), as arrays over the rows.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from bearingload.bearings.tilt import tilt_lever
from bearingload.errors import BearingloadError, InputError
from bearingload.studies.batch_input import (
    COLUMNS,
    Block,
    CellParser,
    Header,
    row_message,
    unit_kind,
)
from bearingload.studies.loaded_bearing import DEFAULT_REVOLUTIONS


@dataclass
class Chunk:
    """The answer for one chunk of rows.

    Attributes
    ----------
    rows : list of int
        Row numbers of the solved rows, in input order (the header is row 1).
    values : dict
        Quantity key -> numpy array or list over ``rows`` (a list holds None where a
        quantity is not given for that row).
    errors : list of (int, str)
        Skipped rows: row number and the reason (``"load: must be greater than 0 N (got -5)"``).
    """

    rows: list[int] = field(default_factory=list)
    values: dict[str, Any] = field(default_factory=dict)
    errors: list[tuple[int, str]] = field(default_factory=list)


class BatchSolver:
    """Solve the chunks of one case file; parsed cells and resolved bearings are cached."""

    def __init__(self, header: Header) -> None:
        self.header = header
        self.parsers = {n: CellParser(n, header.units.get(n)) for n in header.names}
        self.bearings: dict[tuple[Any, ...], Any] = {}

    def solve(self, block: Block) -> Chunk:
        """Solve one block of rows."""
        errors: dict[int, str] = dict(block.errors)
        if self.header.combined:
            from bearingload.studies.batch_combined import solve_combined_rows

            cells = self._row_dicts(block.cells(), errors)
            found = [x for x in (self._combined_row(r, c, errors) for r, c in cells) if x]
            return _merged(solve_combined_rows(found, errors), errors)
        if self.header.has_bearing:
            rows = self._bearing_rows(block.cells(), errors)
        else:
            rows = self._numbers_only(block) or self._hand_rows(block.cells(), errors)
        return _merged(_solve_rows(rows, errors), errors)

    def _combined_row(
        self, row: int, v: dict[str, Any], errors: dict[int, str]
    ) -> dict[str, Any] | None:
        """The inputs of one combined-load row: its resolved bearing, F_r, F_a, the tilt."""
        try:
            if "tilt_radius" in v and not any(k in v for k in _COMBINED_LOADS):
                raise InputError("tilt_radius", _TILT_ALONE)
            if not any(k in v for k in ("bearing", "ball_diameter", "pitch_diameter")):
                raise InputError(
                    "bearing", "missing: the combined load needs a bearing or its ball geometry"
                )
            b = self._bearing({k: x for k, x in v.items() if k != "exponent"})
            if "load" not in v:
                raise InputError("load", "missing: every row needs a (radial) load, 0 allowed")
            if not v["load"] >= 0:
                raise InputError("load", f"must be 0 N or more (got {v['load']!r} N)")
            if v.get("dynamic_rating") is not None and not v["dynamic_rating"] > 0:
                raise InputError("dynamic_rating", "must be greater than 0 N")
            angle = v.get("cage_angle", 0.0)
            angle = 180.0 / b.balls if angle == "half" else angle
            lever = tilt_lever(v.get("tilt_radius"), b.pitch_diameter)  # None: groove
        except BearingloadError as exc:
            errors[row] = row_message(exc)
            return None
        return {"row": row, "bearing": b, "load": v["load"],
                "axial_load": v.get("axial_load", 0.0), "moment": v.get("moment"),
                "moment_cross": v.get("moment_cross"), "tilt_radius": lever,
                "misalignment": v.get("misalignment"), "rotating": v.get("rotating", "inner"),
                "dynamic_rating": v.get("dynamic_rating"), "cage_angle": angle}  # fmt: skip

    def _numbers_only(self, block: Block) -> Rows | None:
        """The rows of a block whose cells are all bare numbers (and the columns all numeric:
        balls, stiffness, load ...), read by numpy at once; None when some cell needs the cell
        parser (a unit, 'half', a fraction, a bad or implausible number), which then reads the
        block and names the bad rows."""
        names = self.header.names
        n = len(block.numbers)
        if block.lines is None or not n or not set(names) <= _NUMERIC or not _HAND <= set(names):
            return None
        try:
            table = np.loadtxt(block.lines, delimiter=",", comments=None, dtype=float, ndmin=2)
        except ValueError:
            return None
        if table.shape != (n, len(names)):
            return None
        given = dict(zip(names, table.T, strict=True))
        arrays: dict[str, np.ndarray] = {}
        for name, default in (("exponent", 1.5), ("balls", None), ("load", None),
                              ("stiffness", None), ("clearance", 0.0), ("cage_angle", 0.0)):  # fmt: skip
            if name not in given:
                arrays[name] = np.full(n, default)
                continue
            found = self._bare(name, given[name], arrays.get("exponent"))
            if found is None:
                return None
            arrays[name] = found
        return Rows(block.numbers, arrays, ["exact"] * n, [None] * n, np.full(n, 36e6), True)

    def _bare(self, name: str, values: np.ndarray, m: np.ndarray | None) -> np.ndarray | None:
        """Bare numbers of a column in package units (a unit in the header scales them), or
        None when some are not finite or implausible for their quantity without a unit."""
        parser = self.parsers[name]
        if not np.all(np.isfinite(values)):
            return None
        if parser.kind == "count" and np.any(values != np.round(values)):
            return None  # 8.5 balls: named by the cell parser, as when another cell needs it
        if not parser.unit:
            return None if _implausible(name, parser.kind, values) else values
        if name == "stiffness":
            from bearingload.units import stiffness_factor

            assert m is not None
            try:  # a unit of another exponent: the cell parser names the row
                factors = {e: stiffness_factor(parser.unit, e, parameter=name)
                           for e in set(m.tolist())}  # fmt: skip
            except InputError:
                return None
            return values * np.array([factors[e] for e in m.tolist()])
        from bearingload.units import parse_quantity

        kind = unit_kind(parser.kind)
        return values * parse_quantity("1" + parser.unit, kind, parameter=name)

    def _hand_rows(self, lines: list[tuple[int, list[str]]], errors: dict[int, str]) -> Rows:
        """The rows of a file without bearing columns (rings given by z and K), column by
        column: bare numbers are converted by numpy at once, other cells one distinct text at
        a time."""
        names = self.header.names
        good = self._well_formed(lines, errors)
        numbers = [r for r, _ in good]
        texts = dict(zip(names, zip(*[c for _, c in good], strict=True), strict=False))
        texts = {n: texts.get(n, ()) for n in names}
        bad: dict[int, str] = {}
        m = self._column("exponent", texts, bad, 1.5, None)
        arrays = {
            "exponent": m,
            "balls": self._column("balls", texts, bad, None, m),
            "load": self._column("load", texts, bad, None, m),
            "stiffness": self._column("stiffness", texts, bad, None, m),
            "clearance": self._column("clearance", texts, bad, 0.0, m),
        }
        cage = self._column("cage_angle", texts, bad, 0.0, m, half=True)
        with np.errstate(divide="ignore"):
            arrays["cage_angle"] = np.where(np.isnan(cage), 180.0 / arrays["balls"], cage)
        methods = (
            [t.strip() or "exact" for t in texts["method"]]
            if "method" in texts
            else ["exact"] * len(good)
        )
        if "method" in texts:
            from bearingload.models.registry import METHODS, get_method

            for i, name in enumerate(methods):
                if name not in METHODS:
                    try:
                        get_method(name)
                    except InputError as exc:
                        bad.setdefault(i, str(exc))
        for i, message in bad.items():
            errors[numbers[i]] = message
        return Rows(numbers, arrays, methods, [None] * len(good), np.full(len(good), 36e6), True)

    def _column(
        self,
        name: str,
        texts: dict[str, tuple[str, ...]],
        bad: dict[int, str],
        default: float | None,
        m: np.ndarray | None,
        half: bool = False,
    ) -> np.ndarray:
        """One numeric column in package units (``half``: NaN marks 'half'); a missing cell
        takes ``default`` or is an error; errors go to ``bad`` (index -> reason)."""
        n = len(next(iter(texts.values()), ()))
        if name not in texts:
            if default is None:
                for i in range(n):
                    bad.setdefault(i, f"{name}: {_missing(name)}")
                return np.ones(n)
            return np.full(n, default)
        cells = texts[name]
        parser = self.parsers[name]
        try:  # bare numbers at once; otherwise (and to name the bad ones) cell by cell
            if "_" in "".join(cells):  # numpy reads '1_000' as Python does; the cells refuse it
                raise ValueError("underscores")
            found = self._bare(name, np.array(cells, dtype=float), m)
            if found is not None:
                return found
        except (ValueError, InputError):
            pass
        out = np.ones(n)
        for i, text in enumerate(cells):
            try:
                if not text.strip():
                    if default is None:
                        raise InputError(name, _missing(name))
                    out[i] = default
                    continue
                v = parser.parse(text, 1.5 if m is None else float(m[i]))
                if v == "half" and half:
                    v = np.nan
                elif not isinstance(v, float):
                    from bearingload.bearings.clearance import clearance_length

                    v = clearance_length(v)
                out[i] = v
            except InputError as exc:
                bad.setdefault(i, str(exc))
        return out

    def _well_formed(
        self, lines: list[tuple[int, list[str]]], errors: dict[int, str]
    ) -> list[tuple[int, list[str]]]:
        """The lines with as many cells as the header names columns; the others go to
        ``errors``."""
        width = len(self.header.names)
        good = []
        for row, cells in lines:
            if len(cells) == width:
                good.append((row, cells))
            else:
                errors[row] = _malformed(len(cells), width)
        return good

    def _row_dicts(
        self, lines: list[tuple[int, list[str]]], errors: dict[int, str]
    ) -> list[tuple[int, dict[str, Any]]]:
        """Each readable row's non-blank cells by column, parsed to package units (the rows that
        fail to parse, and malformed lines, go to ``errors``)."""
        names = self.header.names
        good = self._well_formed(lines, errors)
        parsed, failed = self._parsed_columns([c for _, c in good])
        out = []
        for i, (row, _) in enumerate(good):
            if i in failed:
                errors[row] = failed[i]
                continue
            out.append((row, {n: parsed[n][i] for n in names if parsed[n][i] is not _EMPTY}))
        return out

    def _bearing_rows(self, lines: list[tuple[int, list[str]]], errors: dict[int, str]) -> Rows:
        """The rows of a file that can name bearings, column by column: each distinct cell text
        parsed once, each distinct set of a row's bearing inputs (all but its load, cage angle
        and revolutions) resolved once; a row's first error in file order is kept."""
        names = self.header.names
        good = self._well_formed(lines, errors)
        numbers = [row for row, _ in good]
        parsed, failed = self._parsed_columns([c for _, c in good])
        keyed = [n for n in names if n not in _PER_ROW]
        index: dict[tuple[Any, ...], int] = {}
        codes = np.array(
            [index.setdefault(k, len(index)) for k in zip(*(parsed[n] for n in keyed), strict=True)]
            if keyed
            else [index.setdefault((), 0)] * len(good),
            dtype=np.intp,
        )
        cases: list[Any] = []
        for key in index:  # each distinct bearing once
            v = {n: x for n, x in zip(keyed, key, strict=True) if x is not _EMPTY}
            try:
                cases.append(self._case_of(v))  # no "exponent": the cell is blank
            except BearingloadError as exc:
                cases.append(row_message(exc))
        bad = dict(failed)  # a row's first error: its cells, its bearing, its load ...
        for i, code in enumerate(codes.tolist()):
            if isinstance(cases[code], str):
                bad.setdefault(i, cases[code])
        per_row = {n: parsed.get(n, [_EMPTY] * len(good)) for n in _PER_ROW}
        for i, x in enumerate(per_row["load"]):
            if x is _EMPTY:
                bad.setdefault(i, "load: missing: every row needs a load")
        revolutions = [DEFAULT_REVOLUTIONS if x is _EMPTY else x for x in per_row["revolutions"]]
        for i, x in enumerate(revolutions):
            if not x > 0:
                bad.setdefault(i, f"revolutions: must be greater than 0 rev (got {x:g})")
        for i, message in bad.items():
            errors[numbers[i]] = message
        keep = [i for i in range(len(good)) if i not in bad]
        return self._rows_of(keep, numbers, codes, cases, per_row, revolutions)

    @staticmethod
    def _rows_of(
        keep: list[int], numbers: list[int], codes: np.ndarray, cases: list[Any],
        per_row: dict[str, list[Any]], revolutions: list[float],
    ) -> Rows:  # fmt: skip
        """The kept rows as arrays: each row's bearing case by its code, its load, cage angle
        ('half': half the pitch; blank: 0) and revolutions."""
        ok = [c if isinstance(c, dict) else None for c in cases]
        code = codes[keep]
        table = {k: np.array([0.0 if c is None else c[k] for c in ok], dtype=float)
                 for k in ("balls", "stiffness", "clearance", "exponent")}  # fmt: skip
        arrays = {k: t[code] for k, t in table.items()}
        arrays["load"] = np.array([per_row["load"][i] for i in keep], dtype=float)
        angles = [per_row["cage_angle"][i] for i in keep]
        half = np.array([a == "half" for a in angles], dtype=bool)
        given = np.array([0.0 if a is _EMPTY or a == "half" else a for a in angles], float)
        z = arrays["balls"]
        with np.errstate(divide="ignore"):
            arrays["cage_angle"] = np.where(half, np.where(z >= 1, 180.0 / z, 0.0), given)
        code_list = code.tolist()
        return Rows(
            [numbers[i] for i in keep],
            arrays,
            [ok[c]["method"] for c in code_list],
            [ok[c]["bearing"] for c in code_list],
            np.array([revolutions[i] for i in keep], dtype=float),
            all(c is None or c["bearing"] is None for c in ok),
        )

    def _numeric_column(self, name: str, texts: Any, m: list[Any]) -> list[float] | None:
        """A column of bare numbers in package units at once (as the cell parser reads each),
        or None when some cell needs the parser (a unit or word in the cell, a blank, a bad or
        implausible number, a fraction in the count of balls)."""
        kind = COLUMNS[name]
        if kind in ("text", "pick", "ring", "exponent") or not texts or "_" in "".join(texts):
            return None  # numpy reads '1_000' as Python does; the cell parser refuses it
        try:
            values = np.array(texts, dtype=float)
        except ValueError:
            return None
        if kind == "count" and not np.all(values == np.round(values)):
            return None
        if kind in ("count", "number"):
            return values.tolist() if np.all(np.isfinite(values)) else None
        try:
            found = self._bare(name, values, np.array(m, dtype=float))
        except InputError:
            return None
        return None if found is None else found.tolist()

    def _contact_exponents(self, designations: Any, n: int) -> list[float]:
        """Each row's m for reading its stiffness where its exponent cell is blank: 10/9 where
        the row names a cylindrical roller bearing (as solve reads -K with one), else 1.5."""
        if designations is None:
            return [1.5] * n
        from bearingload.bearings.designation import contact_exponent

        kinds = {text: contact_exponent(text) for text in set(designations)}
        return [kinds[t] for t in designations]

    def _parsed_columns(self, rows: list[list[str]]) -> tuple[dict[str, list[Any]], dict[int, str]]:
        """Every column's cells parsed (``_EMPTY`` for a blank cell), and each failing row's first
        error: the exponent first (other cells depend on it), then in file order."""
        names = self.header.names
        texts = dict(zip(names, zip(*rows, strict=True), strict=False)) if rows else {}
        order = (["exponent"] if "exponent" in names else []) + [
            n for n in names if n != "exponent"
        ]
        parsed: dict[str, list[Any]] = {}
        failed: dict[int, str] = {}
        contact = self._contact_exponents(texts.get("bearing"), len(rows))
        m: list[Any] = contact
        for n in order:
            fast = self._numeric_column(n, texts.get(n, ()), m)
            if fast is not None:  # every cell a bare number, read at once
                parsed[n] = fast
                continue
            parser = self.parsers[n]
            cache: dict[tuple[str, Any], Any] = {}
            column = []
            for i, (text, e) in enumerate(zip(texts.get(n, ()), m, strict=True)):
                key = (text, e)
                hit = cache.get(key)
                if hit is None:
                    t = text.strip()
                    try:
                        hit = (True, parser.parse(t, e) if t else _EMPTY)
                    except InputError as exc:
                        hit = (False, row_message(exc))
                    cache[key] = hit
                if not hit[0] and i not in failed:
                    failed[i] = hit[1]
                column.append(hit[1] if hit[0] else _EMPTY)
            parsed[n] = column
            if n == "exponent":
                m = [c if x is _EMPTY else x for x, c in zip(column, contact, strict=True)]
        return parsed, failed

    def _case_of(self, v: dict[str, Any]) -> dict[str, Any]:
        """What a row's inputs other than load, cage angle and revolutions give: the method,
        the resolved bearing (None: a ring by z and K), z, K, G_r and m."""
        from bearingload.bearings.clearance import clearance_length
        from bearingload.models.registry import get_method

        get_method(v.get("method", "exact"))
        by_hand = not any(k in v for k in ("bearing", "ball_diameter", "pitch_diameter"))
        if by_hand:
            extra = [k for k in ("inner_conformity", "outer_conformity", "modulus", "poisson",
                                 "clearance_pick") if k in v]  # fmt: skip
            if extra:
                raise InputError(extra[0], "needs a bearing or a ball geometry")
            for need in ("balls", "stiffness"):
                if need not in v:
                    raise InputError(need, "missing (give balls and stiffness, or a bearing)")
            g = v.get("clearance", 0.0)
            return {"bearing": None, "balls": v["balls"], "stiffness": v["stiffness"],
                    "clearance": g if isinstance(g, float) else clearance_length(g),
                    "exponent": v.get("exponent", 1.5), "method": v.get("method", "exact")}  # fmt: skip
        b = self._bearing(v)
        return {"bearing": b, "balls": b.balls, "stiffness": b.stiffness,
                "clearance": b.clearance, "exponent": b.exponent,
                "method": v.get("method", "exact")}  # fmt: skip

    def _bearing(self, v: dict[str, Any]) -> Any:
        """The resolved bearing of a row, resolved once per distinct inputs."""
        from bearingload.bearings.resolve import resolve_bearing

        args = {
            "balls": v.get("balls"),
            "ball_diameter": v.get("ball_diameter"),
            "pitch_diameter": v.get("pitch_diameter"),
            "f_i": v.get("inner_conformity"),
            "f_o": v.get("outer_conformity"),
            "modulus": v.get("modulus"),
            "poisson": v.get("poisson"),
            "stiffness": v.get("stiffness"),
            "clearance": v.get("clearance"),
            "clearance_pick": v.get("clearance_pick", "mean"),
        }
        if args["balls"] is not None:
            args["balls"] = int(args["balls"])
        key = (v.get("bearing"), *args.values())  # floats, text, frozen ClearanceSpec
        hit = self.bearings.get(key)
        if hit is None:
            try:
                hit = resolve_bearing(v.get("bearing"), **args)
            except BearingloadError as exc:
                hit = exc
            if len(self.bearings) < 10_000:
                self.bearings[key] = hit
        if isinstance(hit, BearingloadError):
            raise hit
        if v.get("exponent", hit.exponent) != hit.exponent:  # a blank cell: the bearing's m
            contact = (
                "a roller bearing (line contact) has m = 10/9"
                if hit.kind == "roller"
                else "a ball bearing (Hertz point contact) has m = 1.5"
            )
            raise InputError(
                "exponent", f"{contact}; other exponents need balls and stiffness without a bearing"
            )
        return hit


def _merged(parts: list[Part], errors: dict[int, str]) -> Chunk:
    """The chunk's answer: the solved parts merged in row order, and the skipped rows."""
    out = Chunk(errors=sorted(errors.items()))
    if len(parts) == 1:
        out.rows, out.values = parts[0]
    elif parts:
        numbers = [n for p, _ in parts for n in p]
        order = sorted(range(len(numbers)), key=numbers.__getitem__)
        out.rows = [numbers[i] for i in order]
        for k in parts[0][1]:
            pieces = [c[k] for _, c in parts]
            if all(isinstance(p, np.ndarray) for p in pieces):
                out.values[k] = np.concatenate(pieces)[order]
            else:
                merged = [v for p in pieces for v in _items(p)]
                out.values[k] = [merged[i] for i in order]
    return out


def _items(values: Any) -> list[Any]:
    """A column as a list of Python values (None where not given)."""
    return values.tolist() if isinstance(values, np.ndarray) else list(values)


#: A blank cell (the column's default applies).
_EMPTY: Any = object()
#: Columns that differ from row to row without changing the bearing.
_PER_ROW = ("load", "cage_angle", "revolutions")

#: The cells that load a combined-load row (as solve's load options choose its engine).
_COMBINED_LOADS = ("axial_load", "moment", "moment_cross", "misalignment")
#: A tilt_radius without a load that tilts the ring: solve's refusal of --tilt-radius
#: (bearingload.cli.cases.refuse_tilt_radius), in column names.
_TILT_ALONE = (
    "it is the lever of the inner ring's tilt, and only the combined load (axial_load, moment, "
    "moment_cross, misalignment) tilts the ring"
)

#: Columns whose cells may all be bare numbers (then a block is read by numpy at once).
_NUMERIC = frozenset(("balls", "load", "stiffness", "clearance", "cage_angle", "exponent"))
_HAND = frozenset(("balls", "load", "stiffness"))


def _implausible(name: str, kind: str, values: np.ndarray) -> bool:
    """Whether some bare number lies outside the plausible range of its quantity
    (:data:`bearingload.units.PLAUSIBLE_BARE`)."""
    from bearingload.units import PLAUSIBLE_BARE

    kind = unit_kind(kind)
    rule = PLAUSIBLE_BARE.get((kind, name)) or PLAUSIBLE_BARE.get((kind, None))
    if rule is None:
        return False
    low, high, _ = rule
    return bool(np.any((values < low) | (values >= high)))


def _missing(name: str) -> str:
    """Why an empty cell of a column without a default is a bad row."""
    if name == "load":
        return "missing: every row needs a load"  # as for rows of bearings
    return "missing (give balls and stiffness, or a bearing)"


def _malformed(cells: int, columns: int) -> str:
    return f"malformed line: {cells} cells, the header names {columns} columns"


_CHECKS = (
    ("balls", lambda a: (a < 1) | (a > 100_000) | (a != np.round(a))),
    ("load", lambda a: ~(a > 0) | ~np.isfinite(a)),
    ("stiffness", lambda a: ~(a > 0) | ~np.isfinite(a)),
    ("clearance", lambda a: ~np.isfinite(a)),
    ("cage_angle", lambda a: ~np.isfinite(a)),
    ("exponent", lambda a: ~((a >= 1) & (a <= 3))),
)


Part = tuple[list[int], dict[str, list[Any]]]


@dataclass
class Rows:
    """Rows ready to solve: row ``numbers``, the case inputs as ``arrays`` (the names of
    :data:`bearingload.models.case.INPUTS`), each row's ``methods``, ``bearings`` (None: a ring
    given by z and K) and ``revolutions`` [rev]."""

    numbers: list[int]
    arrays: dict[str, np.ndarray]
    methods: list[str]
    bearings: list[Any]
    revolutions: np.ndarray
    by_hand: bool = False  # True: every ring given by z and K (no bearing)

    @classmethod
    def of(cls, rows: list[dict[str, Any]]) -> Rows:
        from bearingload.models.case import INPUTS

        return cls(
            [r["row"] for r in rows],
            {k: np.array([r[k] for r in rows], dtype=float) for k in INPUTS},
            [r["method"] for r in rows],
            [r["bearing"] for r in rows],
            np.array([r["revolutions"] for r in rows], dtype=float),
            all(r["bearing"] is None for r in rows),
        )

    def take(self, idx: list[int]) -> Rows:
        return Rows(
            [self.numbers[i] for i in idx],
            {k: a[idx] for k, a in self.arrays.items()},
            [self.methods[i] for i in idx],
            [self.bearings[i] for i in idx],
            self.revolutions[idx],
            self.by_hand,
        )


def _solve_rows(rows: Rows, errors: dict[int, str]) -> list[Part]:
    """Check the rows (vectorised; the library names a failing row's reason), then solve each
    method's rows in one call: per method, the row numbers and the quantities over them."""
    from bearingload.models.case import INPUTS, Case

    if not rows.numbers:
        return []
    arrays = rows.arrays
    suspect = np.zeros(len(rows.numbers), bool)
    for name, bad in _CHECKS:
        suspect |= bad(arrays[name])
    for i in np.flatnonzero(suspect):
        try:
            Case.of(*(arrays[k][i] for k in INPUTS))
        except InputError as exc:
            errors.setdefault(rows.numbers[i], row_message(exc))  # a row's first error kept
    out = []
    methods = dict.fromkeys(rows.methods)
    if len(methods) == 1 and (not errors or not any(n in errors for n in rows.numbers)):
        return _solve_method(rows.methods[0], rows, errors)  # every row, one call
    for method in methods:
        idx = [i for i, (n, m) in enumerate(zip(rows.numbers, rows.methods, strict=True))
               if m == method and n not in errors]  # fmt: skip
        if idx:
            out += _solve_method(method, rows.take(idx), errors)
    return out


def _solve_method(method: str, rows: Rows, errors: dict[int, str]) -> list[Part]:
    """One vectorised call for all ``rows`` of one method; one call per row if that fails (a
    row that fails alone is named in ``errors``, also when it is the only row of its method or
    of its chunk)."""
    from bearingload.models.case import INPUTS, Case
    from bearingload.models.registry import get_method

    model = get_method(method)
    try:
        with np.errstate(all="ignore"):
            result = model.run(Case.of(*(rows.arrays[k] for k in INPUTS)))
        return [_values(result, rows)]
    except (BearingloadError, ValueError, ArithmeticError) as exc:
        if len(rows.numbers) == 1:
            errors[rows.numbers[0]] = row_message(exc)
            return []
    out: list[Part] = []
    for i in range(len(rows.numbers)):
        out += _solve_method(method, rows.take([i]), errors)
    return out


def _values(result: Any, rows: Rows) -> Part:
    """The quantities of every row (the keys of ``case_values``), lists over the rows."""
    n = len(rows.numbers)
    arrays = rows.arrays

    def col(value: Any) -> Any:
        return [None] * n if value is None else np.broadcast_to(value, (n,)).copy()

    q = np.broadcast_to(result.q_max, (n,))
    approach = None if result.x is None else (q / arrays["stiffness"]) ** (1.0 / arrays["exponent"])
    bearings = rows.bearings
    by_hand = rows.by_hand
    cols = {
        "bearing": [None] * n
        if by_hand
        else [None if b is None else (b.designation or "given by hand") for b in bearings],
        "method": rows.methods,
        "balls": arrays["balls"].astype(np.int64),
        "load": arrays["load"],
        "stiffness": arrays["stiffness"],
        "clearance": arrays["clearance"],
        "clearance_pick": [None] * n
        if by_hand
        else [None if b is None else b.clearance_pick for b in bearings],
        "cage_angle": np.mod(arrays["cage_angle"], 360.0),
        "exponent": arrays["exponent"],
        "q_max": col(result.q_max),
        "k": col(result.k),
        "K_Q": col(result.K_Q),
        "loaded_balls": col(result.loaded_balls),
        "load_zone": col(result.load_zone),
        "x": col(result.x),
        "y": col(result.y),
        "stiffness_radial": col(result.stiffness_radial),
        "approach_max": col(approach),
        "epsilon": col(getattr(result.model, "epsilon", None)),
        "valid": col(result.valid),
    }
    cols |= _bearing_values(rows, q)
    cols |= _solve_lives(result, rows)
    cols["warnings"] = _warnings(rows, cols)
    return rows.numbers, cols


def _warnings(rows: Rows, cols: dict[str, Any]) -> list[Sequence[str]]:
    """The checks of ``solve`` on every row (bearings.checks): the static rating, the contact
    pressure and a single loaded ball for a catalogue bearing; a single loaded ball otherwise."""
    from types import SimpleNamespace

    from bearingload.bearings.checks import case_warnings, element_warnings

    out: list[Sequence[str]] = [()] * len(rows.bearings)
    if rows.by_hand:  # rings by z and K: only a single loaded ball
        found = cols["loaded_balls"]
        loaded = (
            found
            if isinstance(found, np.ndarray)
            else np.array([-1 if v is None else v for v in found])
        )
        single = tuple(element_warnings(SimpleNamespace(loaded_balls=1), 2))  # one sentence
        for i in np.flatnonzero((loaded == 1) & (np.asarray(cols["balls"]) > 1)).tolist():
            out[i] = single
        return out
    for i in np.flatnonzero(_may_warn(rows, cols)).tolist():  # the others: nothing to say
        b = rows.bearings[i]
        one = SimpleNamespace(q_max=cols["q_max"][i], loaded_balls=cols["loaded_balls"][i])
        if b is not None:
            inner, outer = cols["p_max_inner"][i], cols["p_max_outer"][i]
            known = None if inner is None else (inner, outer)  # computed over the rows above
            out[i] = case_warnings(b, cols["load"][i], one, known)
        else:
            out[i] = element_warnings(one, cols["balls"][i])
    return out


def _may_warn(rows: Rows, cols: dict[str, Any]) -> np.ndarray:
    """The rows on which a check of ``case_warnings`` can fire (a superset, vectorised): s0 or
    C0 exceeded, contact pressure above its limit, one loaded ball, a clearance finding of the
    bearing (each distinct bearing asked once)."""
    from bearingload.bearings.checks import P_MAX_BALL, P_MAX_ROLLER, S0_MIN, clearance_findings

    n = len(rows.bearings)
    c0, limit = np.full(n, np.nan), np.full(n, np.inf)
    own = np.zeros(n, bool)
    seen: dict[int, tuple[float, float, bool]] = {}
    for i, b in enumerate(rows.bearings):
        if b is not None:
            if id(b) not in seen:
                seen[id(b)] = (b.C0 or np.nan, P_MAX_ROLLER if b.kind == "roller" else P_MAX_BALL,
                               bool(clearance_findings(b)))  # fmt: skip
            c0[i], limit[i], own[i] = seen[id(b)]

    def numbers(key: str, missing: float) -> np.ndarray:
        v = cols[key]
        return (
            v
            if isinstance(v, np.ndarray)
            else np.array([missing if x is None else x for x in v], float)
        )

    load = np.asarray(cols["load"], dtype=float)
    pressure = np.maximum(numbers("p_max_inner", 0.0), numbers("p_max_outer", 0.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        static = (c0 / load < S0_MIN) | (load > c0)
    single = (numbers("loaded_balls", -1.0) == 1) & (np.asarray(cols["balls"]) > 1)
    return static | (pressure > limit) | own | single


def _bearing_values(rows: Rows, q: np.ndarray) -> dict[str, list[Any]]:
    """Hertz pressures at Q_max (known geometry) and life and allowable load (known C)."""
    from bearingload.bearings.life import allowable_load, rating_life

    n = len(rows.numbers)
    out: dict[str, list[Any]] = {
        k: [None] * n
        for k in ("p_max_inner", "p_max_outer", "rating_life", "revolutions", "allowable_load")
    }
    bearings = rows.bearings
    if rows.by_hand:  # rings given by z and K
        return out
    groups: dict[int, list[int]] = {}  # one Hertz solution per bearing, over its rows' loads
    for i, b in enumerate(bearings):
        if b is not None and b.has_geometry:
            groups.setdefault(id(b), []).append(i)
    if any(b is not None and b.kind == "roller" for b in bearings):
        groups.update(
            {id(b): [i for i, x in enumerate(bearings) if x is b] for b in bearings
             if b is not None and b.kind == "roller"}
        )  # fmt: skip
    if groups:
        from bearingload.bearings.checks import max_contact_pressures
        from bearingload.contact.hertz import ball_contacts

        for idx in groups.values():
            b = bearings[idx[0]]
            if b.kind == "roller":  # line contact, one row at a time
                for i in idx:
                    found = max_contact_pressures(b, float(q[i]))
                    if found is not None:
                        out["p_max_inner"][i], out["p_max_outer"][i] = found
                continue
            c = ball_contacts(
                q[idx], b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o, b.modulus, b.poisson
            )
            inner = np.broadcast_to(c.inner.p_max, (len(idx),)).tolist()
            outer = np.broadcast_to(c.outer.p_max, (len(idx),)).tolist()
            for j, i in enumerate(idx):
                out["p_max_inner"][i] = inner[j]
                out["p_max_outer"][i] = outer[j]
    rated = [i for i, b in enumerate(bearings) if b is not None and b.C]
    if rated:
        from bearingload.constants import BALL_LIFE_EXPONENT, ROLLER_LIFE_EXPONENT

        C = np.array([bearings[i].C for i in rated])
        rev = rows.revolutions[rated]
        load = rows.arrays["load"][rated]
        p = np.array([ROLLER_LIFE_EXPONENT if bearings[i].kind == "roller" else BALL_LIFE_EXPONENT
                      for i in rated])  # fmt: skip
        life = np.ravel(rating_life(C, load, p))
        allow = np.ravel(allowable_load(C, rev / 1e6, p))
        for j, i in enumerate(rated):
            out["rating_life"][i] = float(life[j])
            out["allowable_load"][i] = float(allow[j])
            out["revolutions"][i] = float(rev[j] / 1e6)
    return out


def _solve_lives(result: Any, rows: Rows) -> dict[str, list[Any]]:
    """What solve's radial path adds for a bearing: the static safety s0 = C0/P0 with P0 = F_r
    (ISO 76:2006, 3.6) where C0 is known, and the reference rating life L10r (ISO/TS 16281:2008,
    4.3) of the exact model's ball loads, the inner ring rotating (solve's default), where
    :func:`bearingload.studies.reference_life.has_reference_life`; one call per bearing."""
    from bearingload.studies.reference_life import ball_reference_life, has_reference_life

    n = len(rows.numbers)
    out: dict[str, list[Any]] = {
        k: [None] * n for k in ("static_safety", "reference_rating_life", "rotating")
    }
    if rows.by_hand:
        return out
    c0 = np.array([np.nan if b is None or not b.C0 else b.C0 for b in rows.bearings])
    with np.errstate(divide="ignore", invalid="ignore"):
        s0 = c0 / rows.arrays["load"]  # every load > 0 (checked)
    out["static_safety"] = [None if np.isnan(v) else v for v in s0.tolist()]
    groups: dict[int, list[int]] = {}
    for i, (b, m) in enumerate(zip(rows.bearings, rows.methods, strict=True)):
        if b is not None and m == "exact" and has_reference_life(b):
            groups.setdefault(id(b), []).append(i)
    for idx in groups.values():
        b = rows.bearings[idx[0]]
        loads = _ball_loads(result.model, n, np.array(idx), b.balls)
        life = np.broadcast_to(ball_reference_life(b, loads, "inner", b.C), (len(idx),))
        for j, i in enumerate(idx):
            out["reference_rating_life"][i] = float(life[j])
            out["rotating"][i] = "inner"
    return out


def _ball_loads(model: Any, n: int, idx: np.ndarray, z: int) -> np.ndarray:
    """Loads Q_i [N] of balls 1..z (ball 1 at the cage angle) of the cases ``idx`` of the
    exact model's ``n`` cases, each of z balls, as
    :attr:`bearingload.models.equilibrium.LoadDistribution.ball_loads` gives them one by one."""
    from bearingload.models.equilibrium import ball_approaches

    def at(name: str) -> np.ndarray:
        return np.reshape(getattr(model, name), (n,))[idx][:, None]

    reference = np.reshape(model.reference, (n, 2))[idx]
    offset = np.reshape(model.offset, (n, 2))[idx]
    delta = ball_approaches(
        z, at("cage_angle"), at("clearance"), at("x"), at("y"), reference, offset
    )
    return at("stiffness") * np.maximum(delta, 0.0) ** at("exponent")
