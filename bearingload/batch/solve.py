"""Solving the rows of a block: each row by the engine ``solve`` would choose for it.

The load alone chooses a row's engine, as for ``solve``: a cell in a load column (axial_load,
moment, moment_cross, misalignment) makes it a combined-load case of a deep-groove ball bearing
(3-D ring equilibrium); otherwise it is a radial case, a ring given by z and K or a bearing.
Rows that share what a vectorised call shares are solved together, by the functions ``solve``
calls for one case, given arrays: a ring's rows of one method by
:func:`bearingload.studies.loaded_bearing.solve_ring`; a bearing's rows of one method and
rotating ring by :func:`~bearingload.studies.loaded_bearing.solve_bearing` and
:func:`~bearingload.studies.reference_life.with_reference_lives`; a bearing's combined rows of
one kind of tilt, rotating ring and C_r by
:func:`bearingload.studies.combined_bearing.solve_combined_bearing` (their loads, moments and
cage angles as arrays). The per-row checks are those of :mod:`bearingload.bearings.checks`.
Every engine solves each case on its own, so a row's answer depends on its own cells only.
Should a call fail, its rows are split in halves until the failing row stands alone, named.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from bearingload.batch.read import (
    DYNAMICS_COLUMNS,
    LOAD_COLUMNS,
    SERVICE_COLUMNS,
    SERVICE_RANGES,
    Block,
    CellParser,
    Header,
    read_column,
    row_message,
)
from bearingload.bearings.lubrication import speed_needed
from bearingload.bearings.mounting import MOUNTING_PARAMS
from bearingload.bearings.oil import OIL_INPUTS
from bearingload.errors import BearingloadError, ConvergenceError, InputError


@dataclass
class Chunk:
    """The answer for one block: the solved ``rows`` (row numbers, in input order), their
    ``values`` (quantity key -> array or list over ``rows``; None where not given, and
    ``warnings``: one tuple per row), and the skipped rows (row number, reason)."""

    rows: list[int] = field(default_factory=list)
    values: dict[str, Any] = field(default_factory=dict)
    errors: list[tuple[int, str]] = field(default_factory=list)


#: Cells that make a row a bearing (resolved) rather than a ring given by z and K.
_GEOMETRY = ("bearing", "ball_diameter", "pitch_diameter")
#: Cells of a bearing that a ring given by z and K cannot use.
_BEARING_ONLY = ("inner_conformity", "outer_conformity", "modulus", "poisson", "ball_material",
                 *MOUNTING_PARAMS, "clearance_pick",
                 "revolutions", "rotating", "dynamic_rating", "static_rating",
                 *SERVICE_COLUMNS)  # fmt: skip
_TILT_ALONE = (
    "tilt_radius: it is the lever of the inner ring's tilt, and only the combined load "
    "(axial_load, moment, moment_cross, misalignment) tilts the ring"
)
#: Rows times balls solved per combined call (about 30 MB of solver work arrays).
CALL_BALLS = 2**15

Part = tuple[list[int], dict[str, Any]]


class BatchSolver:
    """Solve the blocks of one case file; resolved bearings are kept from block to block."""

    def __init__(self, header: Header) -> None:
        self.header = header
        self.parsers = {n: CellParser(n, header.units.get(n)) for n in header.names}
        self.bearings: dict[tuple[Any, ...], Any] = {}

    def solve(self, block: Block) -> Chunk:
        """Solve one block of rows."""
        errors = dict(block.errors)
        width = len(self.header.names)
        numbers, rows = block.numbers, block.cells
        if set(map(len, rows)) - {width}:  # lines with another number of cells: bad rows
            numbers, rows = [], []
            for number, cells in zip(block.numbers, block.cells, strict=True):
                message = self._malformed(cells)
                if message is None:
                    numbers.append(number)
                    rows.append(cells[:width])
                else:
                    errors[number] = message
        cols, bad = self._columns(rows)
        return self._solved(cols, numbers, errors, bad)

    def _solved(self, cols: dict[str, list[Any]], numbers: list[int], errors: dict[int, str],
                bad: dict[int, str]) -> Chunk:  # fmt: skip
        """The block's rows, read into ``cols`` (``bad``: the rows that failed), solved."""
        groups: dict[tuple[Any, ...], list[int]] = {}
        for i, key in enumerate(self._keys(cols, len(numbers), bad)):
            if key is not None:
                groups.setdefault(key, []).append(i)
        parts: list[Part] = []
        for key, idx in groups.items():
            size = _call_size(key)
            for start in range(0, len(idx), size):
                parts += _split(_ENGINES[key[0]], key, idx[start : start + size], cols, bad)
        with_service(parts, cols, bad)
        for idx, out in parts:  # the oil's cells, written as given (the viscosity is nu's)
            out |= {c: [cols[c][i] for i in idx] for c in OIL_INPUTS if c in cols}
        for i, message in bad.items():
            errors[numbers[i]] = message
        return _merged(parts, numbers, errors)

    def _malformed(self, cells: list[str]) -> str | None:
        """Why a row's cells do not fit the header, or None: one cell per named column, and
        up to the header's empty trailing columns more, left empty."""
        width, tail = len(self.header.names), self.header.blank_tail
        if width <= len(cells) <= width + tail:
            extra = next((c for c in cells[width:] if c.strip()), None)
            if extra is None:
                return None
            return (
                f"a value ({extra!r}) in a column the header gives no name (after its last "
                f"column '{self.header.names[-1]}'); name the column or leave it empty"
            )
        named = f" (and {tail} unnamed empty one(s) after them)" if tail else ""
        return f"malformed line: {len(cells)} cells, the header names {width} columns{named}"

    def _columns(self, rows: list[list[str]]) -> tuple[dict[str, list[Any]], dict[int, str]]:
        """Every column's values (None: blank) and each failing row's first error: the exponent
        first (a stiffness unit depends on it), then in file order."""
        names = self.header.names
        texts = dict(zip(names, zip(*rows, strict=True), strict=True)) if rows else {}
        cols: dict[str, list[Any]] = {}
        bad: dict[int, str] = {}
        m = None
        if "bearing" in texts:  # m of a stiffness unit: 10/9 where the row names a roller bearing
            from bearingload.bearings.designation import contact_exponent

            kinds = {t: contact_exponent(t) for t in set(texts["bearing"])}
            m = [kinds[t] for t in texts["bearing"]]
        for name in sorted(names, key=lambda n: n != "exponent"):
            values, failed = read_column(self.parsers[name], texts.get(name, ()), m)
            for i, message in failed.items():
                bad.setdefault(i, message)
            cols[name] = values
            if name == "exponent":
                m = [
                    x if x is not None else 1.5 if m is None else m[i] for i, x in enumerate(values)
                ]
            if name in SERVICE_RANGES:
                _check_range(name, values, bad)
        with_oil_viscosity(cols, len(rows), bad)
        if "viscosity" in cols:  # nu_1 needs the speed, as solve's --viscosity needs --speed
            speed = cols.get("speed", [None] * len(rows))
            for i, nu in enumerate(cols["viscosity"]):
                if nu is not None and speed[i] is None:
                    bad.setdefault(i, "viscosity: needs the shaft speed (a speed cell) for the "
                                   "rated viscosity nu_1")  # fmt: skip
        _check_needs(cols, len(rows), bad)
        return cols, bad

    def _keys(self, cols: dict[str, list[Any]], n: int, bad: dict[int, str]) -> list[Any]:
        """Each row's group: ("ring", method), ("bearing", resolved bearing, method, rotating)
        or ("combined", ...); a row that cannot be solved goes to ``bad``."""
        keys: list[Any] = [None] * n
        rows = n
        cols["_lever"] = [None] * n  # a combined row's lever of the tilt [mm]
        loads = [cols[c] for c in LOAD_COLUMNS if c in cols]
        geometry = [cols[c] for c in _GEOMETRY if c in cols]
        tilt = cols.get("tilt_radius")
        rings = []
        if not (loads or geometry or tilt):  # rings given by z and K only
            rings = [i for i in range(n) if i not in bad]
            n = 0
        for i in range(n):
            if i in bad:
                continue
            try:
                if loads and (any(c[i] is not None for c in loads) or self._angular(cols, i)):
                    keys[i] = self._combined_key(cols, i)
                elif geometry and self._at_speed(cols, i):
                    keys[i] = self._combined_key(cols, i)
                elif tilt is not None and tilt[i] is not None:
                    bad[i] = _TILT_ALONE
                elif geometry and any(c[i] is not None for c in geometry):
                    keys[i] = self._bearing_key(cols, i)
                else:
                    rings.append(i)
            except BearingloadError as exc:
                bad[i] = row_message(exc)
        _ring_keys(cols, rings, keys, bad)
        _refuse_radial_dynamics(cols, keys, rows, bad)
        return keys

    def _angular(self, cols: dict[str, list[Any]], i: int) -> bool:
        """Whether row ``i`` names an angular-contact bearing, which solve gives the combined
        engine with F_a = 0 when no axial load is given (a blank cell takes solve's default)."""
        v = self._row(cols, i)
        return any(k in v for k in _GEOMETRY) and self._bearing(v).contact_angle is not None

    def _at_speed(self, cols: dict[str, list[Any]], i: int) -> bool:
        """Whether radial row ``i`` (no load cell) is a ball bearing at a speed (quasi_static
        not true), which solve gives the combined engine at F_a = 0 with the ball dynamics; its
        method, revolutions and exponent cells checked as solve checks the options."""
        v = self._row(cols, i)
        if "speed" not in v or v.get("quasi_static", False) or not any(k in v for k in _GEOMETRY):
            return False
        b = self._bearing(v)
        if b.kind != "ball":
            return False
        instead = ("the ball dynamics at a speed are solved by the combined engine at an axial "
                   "load of 0 (as solve --speed); set quasi_static true for the static model")  # fmt: skip
        if v.get("method", "exact") != "exact":
            _check_method(v["method"])
            raise InputError("method", f"{v['method']}: {instead}, which takes the other methods")
        if "revolutions" in v:
            raise InputError("revolutions", "sets the life of the allowable radial load, which "
                             f"only the radial engine gives: {instead}")  # fmt: skip
        if v.get("exponent", b.exponent) != b.exponent:
            raise InputError("exponent", "a ball bearing (Hertz point contact) has m = 1.5; "
                             "other exponents need balls and stiffness without a bearing")  # fmt: skip
        return True

    def _row(self, cols: dict[str, list[Any]], i: int) -> dict[str, Any]:
        return {k: v[i] for k, v in cols.items() if v[i] is not None}

    def _bearing_key(self, cols: dict[str, list[Any]], i: int) -> tuple[Any, ...]:
        """A radial row of a bearing: its resolved bearing (C_r replaced by a dynamic_rating
        cell), method and rotating ring, checked as solve checks them."""
        v = self._row(cols, i)
        method = v.get("method", "exact")
        _check_method(method)
        b = self._bearing(v)
        c_r = v.get("dynamic_rating")
        if v.get("exponent", b.exponent) != b.exponent:  # a blank cell: the bearing's m
            contact = ("a roller bearing (line contact) has m = 10/9" if b.kind == "roller"
                       else "a ball bearing (Hertz point contact) has m = 1.5")  # fmt: skip
            raise InputError("exponent", f"{contact}; other exponents need balls and stiffness "
                             "without a bearing")  # fmt: skip
        _check_rotating(v, b, c_r, method)
        _check_life_cells(v, b)
        if "load" not in v:
            raise InputError("load", "missing: every row needs a load")
        if not v.get("revolutions", 1.0) > 0:
            raise InputError(
                "revolutions", f"must be greater than 0 rev (got {v['revolutions']:g})"
            )
        if "revolutions" in v and not b.C:  # no allowable load C/L^(1/p): solve refuses it
            raise InputError("revolutions", "sets the life of the allowable load, which needs "
                             "a dynamic load rating C: give a dynamic_rating (or a bearing)")  # fmt: skip
        return ("bearing", b, method, v.get("rotating", "inner"))

    def _combined_key(self, cols: dict[str, list[Any]], i: int) -> tuple[Any, ...]:
        """A combined-load row: its resolved bearing and what its call shares (the kind of tilt,
        the rotating ring, C_r), checked as solve checks them."""
        from bearingload.bearings.tilt import tilt_lever

        v = self._row(cols, i)
        if not any(k in v for k in _GEOMETRY):
            raise InputError(
                "bearing", "missing: the combined load needs a bearing or its ball geometry"
            )
        b = self._bearing(v)
        if "contact_angle" in v:
            b = _hand_angular(v, b)
        _check_rotating(v, b, v.get("dynamic_rating"), "exact")
        _check_life_cells(v, b)
        if "load" not in v:
            raise InputError("load", "missing: every row needs a (radial) load, 0 allowed")
        if not v["load"] >= 0:
            raise InputError("load", f"must be 0 N or more (got {v['load']!r} N)")
        lever = cols["_lever"][i] = tilt_lever(v.get("tilt_radius"), b.pitch_diameter)
        tilts = (*(k in v for k in ("moment", "misalignment", "moment_cross")), lever is None)
        dynamics = dynamics_of(v, b)
        return ("combined", b, tilts, v.get("rotating", "inner"), v.get("dynamic_rating"), dynamics)

    def _bearing(self, v: dict[str, Any]) -> Any:
        """The resolved bearing of a row's cells, resolved once per distinct cells."""
        from bearingload.bearings.resolve import resolve_bearing

        args = {"balls": v.get("balls"), "ball_diameter": v.get("ball_diameter"),
                "pitch_diameter": v.get("pitch_diameter"), "f_i": v.get("inner_conformity"),
                "f_o": v.get("outer_conformity"), "modulus": v.get("modulus"),
                "poisson": v.get("poisson"), "ball_material": v.get("ball_material"),
                "stiffness": v.get("stiffness"), **{n: v.get(n) for n in MOUNTING_PARAMS},
                "clearance": v.get("clearance"), "clearance_pick": v.get("clearance_pick", "mean")}  # fmt: skip
        if args["balls"] is not None:
            args["balls"] = int(args["balls"])
        c_r, c_0 = v.get("dynamic_rating"), v.get("static_rating")
        key = (v.get("bearing"), c_r, c_0, *args.values())  # floats, text, frozen ClearanceSpec
        hit = self.bearings.get(key)
        if hit is None:
            try:
                if c_r is not None and not c_r > 0:
                    raise InputError("dynamic_rating", "must be greater than 0 N")
                if not self.header.pairs:
                    _refuse_pair(v.get("bearing"))
                hit = resolve_bearing(v.get("bearing"), **args)
                if "clearance_pick" in v and hit.clearance_class is None:  # as solve refuses it
                    raise InputError("clearance_pick", _no_class_to_pick(hit))
                hit = hit if c_r is None else hit.with_dynamic_rating(c_r)
                hit = hit if c_0 is None else hit.with_static_rating(c_0)
            except BearingloadError as exc:
                hit = exc
            if len(self.bearings) < 10_000:
                self.bearings[key] = hit
        if isinstance(hit, BearingloadError):
            raise hit
        return hit


def _refuse_pair(text: str | None) -> None:
    """A matched pair (7205BDB) in a file without pair columns: its row is skipped, saying how a
    file of pairs is written (its columns are those of a pair)."""
    from bearingload.bearings.angular import split_pair

    try:
        kind = None if text is None else split_pair(text)[1]
    except InputError:
        return  # a set suffix not read: the resolver names it
    if kind is not None:
        raise InputError("bearing", f"{str(text).strip()!r} names a {kind} pair: a file of pairs has "
                         "an 'arrangement' column (or 'preload', 'width'; every row of it a "
                         "pair, written as solve writes a pair); here give the single bearing "
                         "with the load it carries")  # fmt: skip


def _no_class_to_pick(b: Any) -> str:
    """Why a row's ``clearance_pick`` is refused: bearing ``b`` has no clearance class (solve's
    reason for --clearance-pick, :func:`bearingload.plan.bearing.resolve_bearings`)."""
    why = ("an angular-contact bearing has no radial clearance" if b.contact_angle is not None
           else f"this row's clearance is one value, no class (G_r = {b.clearance * 1000:g} µm)")  # fmt: skip
    return (
        "it picks the min, mean or max of a clearance class (a clearance cell CN, C3 ... of a "
        f"catalogue bearing); {why}, so it would be ignored"
    )


def with_oil_viscosity(cols: dict[str, list[Any]], n: int, bad: dict[int, str]) -> None:
    """The operating viscosity of each row with an oil cell (:data:`OIL_INPUTS`) into its
    ``viscosity`` cell, by solve's one rule (:func:`bearingload.bearings.oil.operating_viscosity`,
    each row on its own, each distinct oil once); a row it refuses, or whose viscosity would
    have no speed for nu_1, goes to ``bad`` naming the column."""
    from bearingload.bearings.oil import operating_viscosity

    present = [c for c in OIL_INPUTS if c in cols]
    if not present:
        return
    nu = cols.setdefault("viscosity", [None] * n)
    speed = cols.get("speed", [None] * n)
    seen: dict[tuple[Any, ...], tuple[float | None, str | None]] = {}
    for i in range(n):
        oil = {c: cols[c][i] for c in present}
        first = next((c for c in present if oil[c] is not None), None)
        if i in bad or first is None:
            continue
        key = (nu[i], *oil.values())
        if key not in seen:
            try:
                seen[key] = (operating_viscosity(nu[i], **oil)[0], None)
            except InputError as exc:
                seen[key] = (None, row_message(exc))
        value, why = seen[key]
        if why is None and speed[i] is None:
            why = row_message(speed_needed(first))
        if why is None:
            nu[i] = value
        else:
            bad[i] = why


def _hand_angular(v: dict[str, Any], b: Any) -> Any:
    """The angular-contact ring of a row's ball set and ``contact_angle`` cell, checked as
    solve's --contact-angle is: 0 to 60°, no designation, no clearance."""
    import dataclasses

    alpha = v["contact_angle"]
    if not 0.0 <= alpha <= 60.0:
        raise InputError("contact_angle", f"must be from 0 to 60° (got {alpha:.10g}°)")
    if "bearing" in v:
        raise InputError(
            "contact_angle",
            "cannot be used with a bearing designation (the designation gives the angle): give "
            "the angular-contact ring by its ball set (ball_diameter, pitch_diameter, balls)",
        )
    if v.get("clearance") is not None:
        raise InputError(
            "clearance",
            "must be blank with a contact_angle: the design contact angle fixes the geometry "
            "of an angular-contact bearing",
        )
    return dataclasses.replace(b, contact_angle=float(alpha), clearance=0.0)


def dynamics_of(v: dict[str, Any], b: Any) -> tuple[bool, bool]:
    """:func:`_dynamics` of a row of bearing ``b`` (one bearing or a pair's), refused where the
    ball dynamics cannot solve it, as solve refuses --rotating outer and a given stiffness at
    --speed."""
    dynamics = _dynamics(v)
    if dynamics[0] and v.get("rotating") == "outer":  # as solve refuses --rotating outer
        raise InputError("rotating", "the ball dynamics at a speed are coded for the inner "
                         "ring turning (docs/speed.md); set quasi_static true for the "
                         "static model with the outer ring's lives")  # fmt: skip
    if dynamics[0] and b.stiffness_given:  # as the library refuses it, in the batch's words
        raise InputError("speed", "the ball dynamics need each contact's Hertz stiffness "
                         "from the ball geometry, not a given ball stiffness: leave the "
                         "stiffness cell blank, or set quasi_static true (the static "
                         "model)")  # fmt: skip
    return dynamics


def _dynamics(v: dict[str, Any]) -> tuple[bool, bool]:
    """(solved with the ball dynamics, with a ball_density cell) of a combined row, its
    ball_density and quasi_static cells checked as solve checks --ball-density and
    --quasi-static: the dynamics need a speed, and quasi_static true leaves them out."""
    quasi = v.get("quasi_static", False)
    if "ball_density" in v and ("speed" not in v or quasi):
        raise InputError("ball_density", "it enters the ball dynamics at a speed, which "
                         "quasi_static true or a missing speed leave out")  # fmt: skip
    if quasi and "speed" not in v:
        raise InputError("quasi_static", "it needs a speed (true: the static model at that "
                         "speed, which then gives the lives in hours only)")  # fmt: skip
    return "speed" in v and not quasi, "ball_density" in v


def _refuse_radial_dynamics(
    cols: dict[str, list[Any]], keys: list[Any], n: int, bad: dict[int, str]
) -> None:
    """A radial row (ring or bearing) with a ball_density cell or a quasi_static true cell
    without a speed is refused, as solve refuses them on the radial engine: a ball bearing
    at a speed is the combined engine's, unless quasi_static true; a roller has no ball
    dynamics."""
    given = [(c, cols[c]) for c in DYNAMICS_COLUMNS if c in cols]
    for i in range(n) if given else ():
        name = next((c for c, x in given if x[i] not in (None, False)), None)
        if name is None or i in bad or keys[i] is None or keys[i][0] == "combined":
            continue
        v = {c: cols[c][i] for c in ("speed", *DYNAMICS_COLUMNS) if c in cols}
        roller = keys[i][0] == "bearing" and keys[i][1].kind == "roller"
        try:
            if roller and v.get("ball_density") is not None:  # a blank cell is None
                raise InputError("ball_density", "a roller bearing is solved by the static "
                                 "model at any speed: the ball dynamics are coded for ball "
                                 "bearings")  # fmt: skip
            _dynamics({k: x for k, x in v.items() if x is not None})
        except InputError as exc:
            keys[i] = None
            bad[i] = row_message(exc)


def _check_life_cells(v: dict[str, Any], b: Any) -> None:
    """A viscosity needs the pitch diameter for nu_1, as solve's --viscosity does."""
    if "viscosity" in v and b.pitch_diameter is None:
        raise InputError(
            "viscosity", "needs the pitch diameter (a bearing with its ball set or pitch_diameter)"
        )


def _check_rotating(v: dict[str, Any], b: Any, c_r: Any, method: str) -> None:
    """A rotating cell where no L10r is computed is refused, as solve refuses --rotating."""
    from bearingload.studies.reference_life import rotating_refusal

    if "rotating" in v and (why := rotating_refusal(b, c_r, method)) is not None:
        why = re.sub(r"--([a-z-]+)", lambda m: m.group(1).replace("-", "_"), why)
        raise InputError("rotating", "it names the rotating ring for the reference rating "
                         f"life L10r (ISO/TS 16281), and {why.replace('a BEARING', 'a bearing')}")  # fmt: skip


def _check_method(name: str) -> None:
    from bearingload.models.registry import METHODS, get_method

    if name not in METHODS:
        get_method(name)  # raises, naming the methods there are


def _ring_keys(
    cols: dict[str, list[Any]], idx: list[int], keys: list[Any], bad: dict[int, str]
) -> None:
    """The group of each radial row of a ring given by z and K, ("ring", method): it has both, a
    load, a known method and no cell of a bearing (a row's first error goes to ``bad``)."""
    from bearingload.models.registry import METHODS, get_method

    methods = ["exact" if m is None else m for m in cols["method"]] if "method" in cols else None
    for name in {} if methods is None else set(methods) - set(METHODS):
        try:
            get_method(name)
        except InputError as exc:
            for i in idx:
                if methods is not None and methods[i] == name:
                    bad.setdefault(i, row_message(exc))
    found = [(k, "needs a bearing or a ball geometry") for k in _BEARING_ONLY if k in cols]
    found += [
        (k, "missing (give balls and stiffness, or a bearing)") for k in ("balls", "stiffness")
    ]
    found += [("load", "missing: every row needs a load")]
    for name, why in found:
        column = cols.get(name, [None] * len(keys))
        blank = name not in _BEARING_ONLY
        if (None in column) if blank else (column.count(None) < len(column)):  # some row fails
            for i in idx:
                if (column[i] is None) == blank:
                    bad.setdefault(i, f"{name}: {why}")
    for i in idx:
        keys[i] = None if i in bad else ("ring", "exact" if methods is None else methods[i])


def _take(cols: dict[str, list[Any]], name: str, idx: list[int], default: Any = None) -> list[Any]:
    column = cols.get(name)
    if column is None:
        return [default] * len(idx)
    return [default if column[i] is None else column[i] for i in idx]


def _angles(given: list[Any], balls: Any) -> np.ndarray:
    """Cage angles [°]: 'half' is half the pitch 180/z."""
    z = np.broadcast_to(np.asarray(balls, dtype=float), (len(given),))
    half = np.array([a == "half" for a in given], dtype=bool)
    angles = np.array([0.0 if a == "half" else a for a in given], dtype=float)
    return np.where(half, 180.0 / np.maximum(z, 1.0), angles)


def _solve_rings(
    key: tuple[Any, ...], idx: list[int], cols: dict[str, list[Any]]
) -> dict[str, Any]:
    from bearingload.bearings.clearance import clearance_length
    from bearingload.studies.loaded_bearing import case_columns, solve_ring

    balls = np.array(_take(cols, "balls", idx), dtype=float)
    clearance = [g if isinstance(g, float) else clearance_length(g)
                 for g in _take(cols, "clearance", idx, 0.0)]  # fmt: skip
    (lc,) = solve_ring([key[1]], balls, np.array(_take(cols, "load", idx), dtype=float),
                       np.array(_take(cols, "stiffness", idx), dtype=float),
                       np.array(clearance, dtype=float),
                       _angles(_take(cols, "cage_angle", idx, 0.0), balls),
                       np.array(_take(cols, "exponent", idx, 1.5), dtype=float))  # fmt: skip
    return case_columns(lc) | {"warnings": list(lc.warnings)}


def _solve_bearing(
    key: tuple[Any, ...], idx: list[int], cols: dict[str, list[Any]]
) -> dict[str, Any]:
    from bearingload.models.registry import METHODS
    from bearingload.studies.loaded_bearing import DEFAULT_REVOLUTIONS, case_columns, solve_bearing
    from bearingload.studies.reference_life import with_reference_lives

    _, b, method, rotating = key
    load = np.array(_take(cols, "load", idx), dtype=float)
    cage = _angles(_take(cols, "cage_angle", idx, 0.0), b.balls)
    revolutions = np.array(_take(cols, "revolutions", idx, DEFAULT_REVOLUTIONS), dtype=float)
    cases = solve_bearing([b], load, cage, [method], revolutions)
    (lc,) = with_reference_lives(cases, rotating)
    out = case_columns(lc) | {"warnings": list(lc.warnings), "model": METHODS[method].title}
    n = len(idx)
    return out | {
        "_bearing": b,
        "_load": out["load"],
        "_angle": np.zeros(n),
        "_angle_outer": np.full(n, np.nan),
        "_rotating": rotating,
    }


def _solve_combined(
    key: tuple[Any, ...], idx: list[int], cols: dict[str, list[Any]]
) -> dict[str, Any]:
    from bearingload.models.high_speed import too_fast
    from bearingload.studies.combined_bearing import combined_columns, solve_combined_bearing

    _, b, (moment, misaligned, cross, groove), rotating, c_r, (at_speed, density) = key

    def given(name: str, on: bool = True, default: Any = None) -> Any:
        return np.array(_take(cols, name, idx, default), dtype=float) if on else None

    rho = given("ball_density", density)  # [kg/m^3], as solve's --ball-density
    try:
        (case,) = solve_combined_bearing(
            [b], given("load"), given("axial_load", default=0.0),
            cage_angle=_angles(_take(cols, "cage_angle", idx, 0.0), b.balls),
            moment=given("moment", moment), misalignment=given("misalignment", misaligned),
            rotating=rotating, dynamic_rating=c_r, moment_cross=given("moment_cross", cross),
            tilt_radius=None if groove else given("_lever"), speed=given("speed", at_speed),
            ball_density=rho,
        )  # fmt: skip
    except (InputError, ConvergenceError) as exc:
        cells = [cols[c][i] for c in LOAD_COLUMNS if c in cols for i in idx]
        deep_groove = at_speed and b.contact_angle is None
        radial = deep_groove and all(x is None for x in cells)
        hinted = _quasi_static_hint(exc, radial) if deep_groove else None
        if at_speed and isinstance(exc, InputError) and too_fast(exc):
            hinted = exc.with_way_out(FAST_WAY)
        if hinted is None:
            raise
        raise hinted from exc
    out = combined_columns(case) | _contacts(case.result, len(idx), b.contact_angle)
    loads = np.asarray(case.result.ball_loads, dtype=float).reshape(len(idx), -1)
    heaviest = np.argmax(loads, axis=-1)[:, None]
    angles = np.asarray(case.result.contact_angles, dtype=float).reshape(len(idx), -1)
    angle = np.take_along_axis(angles, heaviest, axis=-1)[:, 0]
    outer = getattr(case.result, "contact_angles_outer", None)  # the ball dynamics at speed
    outer = (
        np.full(len(idx), np.nan)
        if outer is None
        else np.take_along_axis(
            np.asarray(outer, dtype=float).reshape(len(idx), -1), heaviest, axis=-1
        )[:, 0]
    )
    return out | {
        "_bearing": b,
        "_load": out["equivalent_load"],
        "_angle": angle,
        "_angle_outer": outer,
        "_rotating": rotating,
    }


#: The way out of a speed beyond the ball dynamics' limit (n d_m), in the batch's words.
FAST_WAY = "quasi_static true gives the static model at any speed (the lives in hours)"


def _quasi_static_hint(
    exc: InputError | ConvergenceError, radial: bool = True
) -> BearingloadError | None:
    """The combined solver's refusal of loads too small for it on deep-groove rows at a speed
    (the ball dynamics): it named 'the radial solver, without an axial load', which at a speed
    is the ball dynamics too; quasi_static true is the way to it (as solve's --quasi-static), on
    a row with load cells beside the radial load (not ``radial``) with those cells left blank.
    The dynamics' non-convergence on radial rows names the same way."""
    from bearingload.models.combined import TOO_LIGHT

    if isinstance(exc, ConvergenceError):
        if not radial:
            return None
        return exc.with_way_out(
            "quasi_static true gives the static radial engine (the ball dynamics left out)"
        )
    if exc.reason != TOO_LIGHT:
        return None
    way = ("quasi_static true gives the static radial engine, which takes any load" if radial
           else "quasi_static true with the axial_load and moment cells blank gives the static "
           "radial engine, which takes any load")  # fmt: skip
    hint = f"at a speed a ball bearing is solved by the combined engine (the ball dynamics); {way}"
    return exc.with_way_out(hint)


def _contacts(res: Any, n: int, contact_angle: float | None) -> dict[str, Any]:
    """The json-only quantities of the ``n`` combined rows of ``res``, as solve's json names
    them (:func:`bearingload.reports.combined.contact_values`): ``model`` and each row's
    per-ball contact angles and loads, inner and outer."""
    from bearingload.reports.combined import contact_values

    found = contact_values(res, contact_angle)
    out: dict[str, Any] = {"model": found.pop("model")}
    for key, value in found.items():
        out[key] = list(np.asarray(value, dtype=float).reshape(n, -1))
    return out


def with_service(parts: list[Part], cols: dict[str, list[Any]], bad: dict[int, str]) -> None:
    """Add to the bearing rows of ``parts`` the lives of
    :func:`bearingload.bearings.service_life.service_columns`: C_0 for every row, the others by
    the life cells each row gives (a value a row has not is None), and their warnings.

    The rows of the block whose bearings share what the lives use (kind, C, C_0, the ball
    geometry; not the clearance) and that give the same life cells (and contamination level)
    are one call on arrays. Each part's hidden ``_bearing``, ``_load`` (P of L10 [N]) and
    ``_angle`` (the contact angle of the heaviest ball [°]) are used and removed. A row whose
    lives solve would refuse (a speed so small that its life in hours overflows) is taken out of
    its part, its reason in ``bad``."""
    from bearingload.bearings.service_life import service_columns

    present = [c for c in SERVICE_COLUMNS if c in cols]
    groups: dict[tuple[Any, ...], list[tuple[int, int]]] = {}
    bases: dict[tuple[Any, ...], Any] = {}
    for p, (idx, out) in enumerate(parts):
        b = out.pop("_bearing", None)
        rotating = out.pop("_rotating", "inner")
        if b is None:
            continue
        _speed_warnings(b, idx, out, cols.get("speed"))
        same = (b.kind, b.C, b.C0, b.pitch_diameter, b.ball_diameter, b.f_i, b.f_o, b.modulus,
                b.poisson, b.roller_length)  # fmt: skip
        bases[same] = b
        for j, i in enumerate(idx):
            given = tuple((c, cols[c][i] if c == "contamination" else True)
                          for c in present if cols[c][i] is not None)  # fmt: skip
            groups.setdefault((same, rotating, given), []).append((p, j))
    floats: dict[tuple[int, str], np.ndarray] = {}

    def gathered(key: str, members: list[tuple[int, int]]) -> np.ndarray:
        for p in {p for p, _ in members}:
            if (p, key) not in floats:
                floats[p, key] = _floats(parts[p][1].get(key), len(parts[p][0]))
        return np.array([floats[p, key][j] for p, j in members], dtype=float)

    failed: dict[tuple[int, int], str] = {}
    for (same, rotating, _), group in groups.items():

        def call(
            members: list[tuple[int, int]], b: Any = bases[same], turning: str = rotating
        ) -> dict[str, Any]:
            rows = [parts[p][0][j] for p, j in members]
            return service_columns(_operating(cols, rows), _basis(b, members, gathered, turning))

        for members, found in _bisected(group, call, failed):
            rows = [parts[p][0][j] for p, j in members]
            for key, value in found.items():
                values = np.broadcast_to(value, (len(members),)).tolist()
                for (p, j), x in zip(members, values, strict=True):
                    column = parts[p][1].setdefault(key, [None] * len(parts[p][0]))
                    column[j] = None if x != x else x
            _service_warnings(found.get("kappa"), _operating(cols, rows[:1]), bases[same],
                              members, parts)  # fmt: skip
    for _, out in parts:
        out.pop("_load", None)
        out.pop("_angle", None)
        out.pop("_angle_outer", None)
    for p in sorted({p for p, _ in failed}, reverse=True):
        idx, out = parts[p]
        for j in (j for q, j in failed if q == p):
            bad[idx[j]] = failed[p, j]
        keep = [j for j in range(len(idx)) if (p, j) not in failed]
        if not keep:
            del parts[p]
            continue
        columns = {k: _over(v, len(idx)) for k, v in out.items()}
        parts[p] = ([idx[j] for j in keep], {k: [v[j] for j in keep] if isinstance(v, list)
                                             else np.asarray(v)[keep] for k, v in columns.items()})  # fmt: skip


def _bisected(
    members: list[tuple[int, int]],
    call: Callable[[list[tuple[int, int]]], dict[str, Any]],
    failed: dict[tuple[int, int], str],
) -> list[tuple[list[tuple[int, int]], dict[str, Any]]]:
    """``call`` on ``members`` at once; if that is refused, each half on its own, down to the
    refused row, whose reason goes to ``failed`` (as :func:`_split` does for the engines)."""
    try:
        with np.errstate(all="ignore"):
            return [(members, call(members))]
    except BearingloadError as exc:
        if len(members) == 1:
            failed[members[0]] = row_message(exc)
            return []
    half = len(members) // 2
    return _bisected(members[:half], call, failed) + _bisected(members[half:], call, failed)


def _operating(cols: dict[str, list[Any]], rows: list[int]) -> Any:
    """The operating conditions of ``rows`` (which give the same life cells) as arrays."""
    from bearingload.bearings.service_life import Operating

    def given(c: str, scale: float = 1.0) -> Any:
        if c not in cols or cols[c][rows[0]] is None:
            return None
        return np.array([cols[c][i] for i in rows], dtype=float) * scale

    alpha = given("pressure_viscosity", 1e-9)
    return Operating(
        speed=given("speed"), reliability=given("reliability"), viscosity=given("viscosity"),
        contamination=cols["contamination"][rows[0]] if "contamination" in cols else None,
        e_c=given("ec"), fatigue_load_limit=given("fatigue_load_limit"),
        roughness=given("roughness"), pressure_viscosity=alpha,
    )  # fmt: skip


def _basis(
    b: Any, members: list[tuple[int, int]], gathered: Callable[..., np.ndarray], rotating: str
) -> Any:
    """The life basis of the rows ``members`` of bearing ``b`` (P, lives, Q_max, the heaviest
    ball's angles, the rotating ring)."""
    from bearingload.bearings.service_life import LifeBasis
    from bearingload.studies.life_basis import life_geometry

    return LifeBasis(
        C=b.C, equivalent_load=gathered("_load", members),
        rating_life=gathered("rating_life", members),
        reference_rating_life=gathered("reference_rating_life", members),
        q_max=gathered("q_max", members), contact_angle=gathered("_angle", members),
        contact_angle_outer=gathered("_angle_outer", members), balls=b.balls, rotating=rotating,
        **life_geometry(b),
    )  # fmt: skip


def _service_warnings(
    kappa: Any, op: Any, basis: Any, members: list[tuple[int, int]], parts: list[Part]
) -> None:
    """Each row's warnings of its lives, as solve prints them for the case."""
    from bearingload.bearings.modified_life import KAPPA_RANGE, clamp_kappa
    from bearingload.bearings.service_life import missing_fatigue_limit

    common = missing_fatigue_limit(op, basis)
    if kappa is None and not common:
        return
    ks = np.broadcast_to(np.nan if kappa is None else kappa, (len(members),))
    low, high = KAPPA_RANGE
    for (p, j), k in zip(members, ks.tolist(), strict=True):
        found = (clamp_kappa(k)[1] if k == k and not low <= k <= high else []) + common
        if found:
            warnings = parts[p][1]["warnings"]
            row = list(warnings[j])
            warnings[j] = tuple(row + [w for w in found if w not in row])


def _speed_warnings(b: Any, idx: list[int], out: dict[str, Any], speeds: Any) -> None:
    """Add to each row of a part the warning solve gives on its speed [r/min] above the limiting
    speed the catalogue gives for bearing ``b`` (:func:`bearingload.bearings.checks.speed_findings`)."""
    from bearingload.bearings.checks import speed_findings

    if speeds is None or getattr(b.geometry, "open_limiting_speeds", None) is None:
        return  # (a sealed bearing is warned above its open bearing's limits)
    warnings = out["warnings"]
    for j, i in enumerate(idx):
        found = speed_findings(speeds[i], b)
        if found:
            row = list(warnings[j])
            warnings[j] = tuple(row + [w for w in found if w not in row])


def _floats(value: Any, n: int) -> np.ndarray:
    """A column over ``n`` rows as floats, None as NaN."""
    if value is None:
        return np.full(n, np.nan)
    if isinstance(value, list):
        return np.array([np.nan if x is None else x for x in value], dtype=float)
    return np.broadcast_to(np.asarray(value, dtype=float), (n,))


#: The batch column of a library parameter, where the two are spelled apart. [-]
_CELL_OF = {"e_c": "ec"}


def _check_needs(cols: dict[str, list[Any]], n: int, bad: dict[int, str]) -> None:
    """Rows that solve would refuse by :func:`bearingload.bearings.service_life._check_needs`,
    refused row by row (that check is for a whole call: it ended the batch): a cell of
    :data:`~bearingload.bearings.service_life.NEED_VISCOSITY` without a viscosity, a contamination level with eC, a roughness
    outside :data:`bearingload.bearings.service_life.ROUGHNESS`."""
    from bearingload.bearings.service_life import NEED_VISCOSITY, ROUGHNESS

    need = [_CELL_OF.get(name, name) for name in NEED_VISCOSITY]
    none: list[Any] = [None] * n
    nu, level, ec, rough = (cols.get(c, none) for c in ("viscosity", "contamination", "ec",
                                                         "roughness"))  # fmt: skip
    for i in range(n):
        given = [c for c in need if cols.get(c, none)[i] is not None]
        if given and nu[i] is None:
            bad.setdefault(i, f"{'eC' if given[0] == 'ec' else given[0]}: feeds the modified "
                           "life (a_ISO) or the film, which need the operating viscosity (a "
                           "viscosity cell, with a speed): without it, it would be ignored")  # fmt: skip
        elif level[i] is not None and ec[i] is not None:
            bad.setdefault(i, "eC: give a contamination level or eC, not both (each gives e_C)")
        elif rough[i] is not None and not ROUGHNESS[0] <= rough[i] <= ROUGHNESS[1]:
            bad.setdefault(i, f"roughness: must lie between {ROUGHNESS[0]:g} and "
                           f"{ROUGHNESS[1]:g} mm (0.1 nm to 100 um; got {rough[i]:g} mm)")  # fmt: skip


def _check_range(name: str, values: list[Any], bad: dict[int, str]) -> None:
    """Rows whose cell of a service column lies outside its range (:data:`SERVICE_RANGES`)."""
    low, high, closed, why = SERVICE_RANGES[name]
    for i, x in enumerate(values):
        if (
            x is not None
            and not ((low <= x) if closed else (low < x))
            or (x is not None and x > high)
        ):
            bad.setdefault(i, f"{'eC' if name == 'ec' else name}: {why} (got {x:g})")


Engine = Callable[[tuple[Any, ...], list[int], dict[str, list[Any]]], dict[str, Any]]
_ENGINES: dict[str, Engine] = {
    "ring": _solve_rings,
    "bearing": _solve_bearing,
    "combined": _solve_combined,
}


def _call_size(key: tuple[Any, ...]) -> int:
    """Rows per call: a combined call holds at most :data:`CALL_BALLS` ball contacts."""
    return max(1, CALL_BALLS // int(key[1].balls)) if key[0] == "combined" else 1 << 62


def _split(engine: Engine, key: tuple[Any, ...], idx: list[int], cols: dict[str, list[Any]],
           bad: dict[int, str]) -> list[Part]:  # fmt: skip
    """The rows ``idx`` of one group in one call; if that fails, each half on its own, down to
    the failing row, whose reason goes to ``bad``."""
    try:
        with np.errstate(all="ignore"):
            return [(idx, engine(key, idx, cols))]
    except (BearingloadError, ValueError, ArithmeticError) as exc:
        if len(idx) == 1:
            bad[idx[0]] = row_message(exc)
            return []
    half = len(idx) // 2
    return _split(engine, key, idx[:half], cols, bad) + _split(engine, key, idx[half:], cols, bad)


def _merged(parts: Sequence[Part], numbers: list[int], errors: dict[int, str]) -> Chunk:
    """The block's answer: the parts' rows in input order, each column over them (an array
    where every part gives one of one kind, else a list with None where a part has none)."""
    out = Chunk(errors=sorted(errors.items()))
    if not parts:
        return out
    idx = [i for p, _ in parts for i in p]
    order = np.argsort(idx, kind="stable")
    if bool(np.all(np.diff(idx) > 0)):
        order = slice(None)  # type: ignore[assignment]  # in input order already
    out.rows = [numbers[i] for i in np.asarray(idx)[order].tolist()]
    keys = list(dict.fromkeys(k for _, v in parts for k in v))
    for k in keys:
        pieces = [_over(v.get(k), len(p)) for p, v in parts]
        kinds = {p.dtype.kind if isinstance(p, np.ndarray) else None for p in pieces}
        if len(kinds) == 1 and None not in kinds:
            out.values[k] = np.concatenate(pieces)[order]
        else:
            merged = [x for p in pieces for x in (p.tolist() if isinstance(p, np.ndarray) else p)]
            out.values[k] = merged if isinstance(order, slice) else [merged[j] for j in order]
    return out


def _over(value: Any, n: int) -> Any:
    """A column over ``n`` rows: an array, or a list (text; None where not given)."""
    if value is None or isinstance(value, str):
        return [value] * n
    if isinstance(value, list):
        return value
    return np.broadcast_to(value, (n,))
