"""Solving the rows of a block: each row a :class:`~bearingload.plan.case.Case` of its cells,
planned by the plan's functions (:mod:`bearingload.plan`: the engine, the refusals, the ways
out), then solved in groups.

Rows that share what a vectorised call shares are solved together, by the functions ``solve``
calls for one case, given arrays: a ring's rows of one method by
:func:`bearingload.studies.loaded_bearing.solve_ring`; a bearing's rows of one method and
rotating ring by :func:`~bearingload.studies.loaded_bearing.solve_bearing` and
:func:`~bearingload.studies.reference_life.with_reference_lives`; a bearing's combined rows of
one kind of tilt, rotating ring and C_r by
:func:`bearingload.studies.combined_bearing.solve_combined_bearing` (their loads, moments and
cage angles as arrays). Every engine solves each case on its own, so a row's answer depends on
its own cells only. Should a call fail, its rows are split in halves until the failing row
stands alone, named.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from bearingload.batch.read import (
    LOAD_COLUMNS,
    SERVICE_COLUMNS,
    Block,
    CellParser,
    Header,
    read_column,
    row_message,
)
from bearingload.bearings.oil import OIL_INPUTS
from bearingload.errors import BearingloadError, ConvergenceError, InputError
from bearingload.plan.bearing import (
    check_rotating,
    refuse_tilt_radius,
    refuse_unused,
    resolve_bearings,
    ring_by_hand,
    with_contact_angle,
    with_ratings,
)
from bearingload.plan.case import Case
from bearingload.plan.solve import (
    QUASI_STATIC_WAY,
    check_revolutions,
    engine_of,
    refuse_radial_options,
    refuse_revolutions,
    refuse_static_dynamics,
    speed_hint,
)


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
#: Columns whose values differ from row to row and whose plan depends only on whether they
#: are given: a row's plan is kept for rows that differ from it only in their values.
_PER_ROW = (
    *("load", "axial_load", "moment", "moment_cross", "misalignment", "cage_angle"),
    *("speed", "ball_density", *SERVICE_COLUMNS[1:]),
)
#: Columns that are no input of a case: the radial engine's method and life.
_NOT_CASE = ("method", "revolutions")
#: Rows times balls solved per combined call (about 30 MB of solver work arrays).
CALL_BALLS = 2**15

Part = tuple[list[int], dict[str, Any]]


def row_case(v: dict[str, Any]) -> Case:
    """The :class:`~bearingload.plan.case.Case` of a row's cells ``v`` (blank cells left out;
    ``stiffness`` in N/mm^m, kept as its text)."""
    values = {"e_c" if k == "ec" else k: x for k, x in v.items() if k not in _NOT_CASE}
    if "stiffness" in values:
        values["stiffness"] = repr(float(values["stiffness"]))
    if "balls" in values:
        values["balls"] = int(values["balls"])
    return Case.of(values)


class BatchSolver:
    """Solve the blocks of one case file; each distinct plan of a row (its resolved bearing and
    group, or its refusal) is kept from block to block."""

    def __init__(self, header: Header) -> None:
        self.header = header
        self.parsers = {n: CellParser(n, header.units.get(n)) for n in header.names}
        self.plans: dict[tuple[Any, ...], Any] = {}
        self.bare: dict[str, list[bool]] = {}

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
        keys = self._keys(cols, len(numbers), bad)
        with_oil_viscosity(cols, [i for i, key in enumerate(keys) if key is not None], bad)
        groups: dict[tuple[Any, ...], list[int]] = {}
        for i, key in enumerate(keys):
            if key is not None and i not in bad:
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
        first (a stiffness unit depends on it), then in file order. ``self.bare``: whether each
        cell of a column judged against the bearing's size was written without a unit."""
        from bearingload.bearings.plausible import BEARING_SCALE
        from bearingload.units import is_bare

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
            if name in RANGED:
                _check_range(name, values, bad)
        self.bare = {
            n: [is_bare(t) for t in texts[n]]
            for n in BEARING_SCALE
            if n in texts and n not in self.header.units and self.header.has_bearing
        }
        return cols, bad

    def _keys(self, cols: dict[str, list[Any]], n: int, bad: dict[int, str]) -> list[Any]:
        """Each row's group: ("ring", method), ("bearing", resolved bearing, method, rotating)
        or ("combined", ...); a row that cannot be solved goes to ``bad``."""
        keys: list[Any] = [None] * n
        cols["_lever"] = [None] * n  # a combined row's lever of the tilt [mm]
        rings = [i for i in range(n) if i not in bad]
        if any(c in cols for c in (*LOAD_COLUMNS, *_GEOMETRY, "tilt_radius")):
            rings = []
            for i in range(n):
                if i in bad:
                    continue
                try:
                    keys[i] = self._key(cols, i)
                except BearingloadError as exc:
                    bad[i] = row_message(exc)
                    continue
                if keys[i] is None:
                    rings.append(i)
        _ring_keys(cols, rings, keys, bad)
        return keys

    def _key(self, cols: dict[str, list[Any]], i: int) -> tuple[Any, ...] | None:
        """Row ``i``'s group (None: a ring given by z and K), planned once for every row of the
        same cells but their values of :data:`_PER_ROW`; its load and bare numbers checked."""
        v = {k: c[i] for k, c in cols.items() if c[i] is not None and k != "_lever"}
        hit = self.planned(v, self._plan)
        key, cols["_lever"][i] = hit
        if key is None:
            return None
        check_load(v, key[0] == "combined")
        self.refuse_bare(v, i, key[1])
        return key

    def planned(self, v: dict[str, Any], plan: Callable[[dict[str, Any]], Any]) -> Any:
        """``plan(v)``, or its refusal raised, kept for the rows of the same plan."""
        marker = tuple((k, True if k in _PER_ROW else x) for k, x in v.items())
        hit = self.plans.get(marker)
        if hit is None:
            try:
                hit = plan(v)
            except BearingloadError as exc:
                hit = exc
            if len(self.plans) < 10_000:
                self.plans[marker] = hit
        if isinstance(hit, BearingloadError):
            raise hit
        return hit

    def refuse_bare(self, v: dict[str, Any], i: int, b: Any) -> None:
        """Refuse a bare number of row ``i`` implausible for its bearing ``b``
        (:func:`bearingload.bearings.plausible.refuse_implausible_bare`, solve's rule)."""
        from bearingload.bearings.plausible import refuse_implausible_bare

        bare = {n: float(v[n]) for n, flags in self.bare.items() if n in v and flags[i]}
        if bare:
            refuse_implausible_bare(b, bare)

    def _plan(self, v: dict[str, Any]) -> tuple[tuple[Any, ...] | None, float | None]:
        """(the group, the lever of the tilt [mm]) of a row of cells ``v``, by the plan's rules
        for its case: the engine, the refusals; (None, None) for a ring given by z and K."""
        case = row_case(v)
        loads = any(c in self.header.names for c in LOAD_COLUMNS)
        if case.by_hand:
            if loads and case.first_given(LOAD_COLUMNS) is not None:
                raise InputError(
                    "bearing", "missing: the combined load needs a bearing or its ball geometry"
                )
            refuse_tilt_radius(case)
            return None, None
        method, revolutions = v.get("method", "exact"), v.get("revolutions")
        if not self.header.pairs:
            _refuse_pair(case.bearing)
        case, engine, at_speed = engine_of(case, method, revolutions)
        if engine == "combined" and not loads:  # an angular designation: radial at rest
            at_speed = case.speed is not None and not case.quasi_static
            if at_speed:
                refuse_radial_options(method, revolutions)
        if at_speed or loads and engine == "combined":
            return self._combined_key(case)
        refuse_tilt_radius(case)
        return self._bearing_key(case, method, revolutions), None

    def _bearing_key(self, case: Case, method: str, revolutions: Any) -> tuple[Any, ...]:
        """A radial row of a bearing: its resolved bearing (C_r replaced by a dynamic_rating
        cell), method and rotating ring, checked as solve checks them."""
        _check_method(method)
        refuse_static_dynamics(case)
        b = self.bearing(case)
        check_revolutions(revolutions)
        if not b.C:
            refuse_revolutions(
                revolutions, "a bearing without a dynamic load rating C", "give 'dynamic_rating'"
            )
        check_rotating(case, b, [method])
        return ("bearing", b, method, case.rotating or "inner")

    def _combined_key(self, case: Case) -> tuple[tuple[Any, ...], float | None]:
        """A combined-load row: its resolved bearing and what its call shares (the kind of tilt,
        the rotating ring, C_r, the ball dynamics), checked as solve checks them; the lever."""
        from bearingload.bearings.tilt import tilt_lever

        b = self.bearing(case)
        if b.kind == "ball" and b.has_geometry:
            check_rotating(case, b, ["exact"])
        b = with_contact_angle([b], case, "'contact_angle'")[0]
        lever = tilt_lever(case.tilt_radius, b.pitch_diameter)
        given = (case.moment, case.misalignment, case.moment_cross)
        tilts = (*(x is not None for x in given), lever is None)
        dynamics = (case.dynamics_arguments()["speed"] is not None, case.ball_density is not None)
        key = ("combined", b, tilts, case.rotating or "inner", case.dynamic_rating, dynamics)
        return key, lever

    def bearing(self, case: Case) -> Any:
        """The resolved bearing of a row's case, its ratings replaced by those given."""
        stiffness = None if case.stiffness is None else float(case.stiffness)
        b = with_ratings(resolve_bearings(case, stiffness), case)[0]
        return b if case.dynamic_rating is None else b.with_dynamic_rating(case.dynamic_rating)


def check_load(v: dict[str, Any], combined: bool = True) -> None:
    """Every row has a load (a combined row's radial one 0 or more)."""
    if "load" not in v:
        what = "a (radial) load, 0 allowed" if combined else "a load"
        raise InputError("load", f"missing: every row needs {what}")
    if combined and not v["load"] >= 0:
        raise InputError("load", f"must be 0 N or more (got {v['load']!r} N)")


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


def with_oil_viscosity(cols: dict[str, list[Any]], rows: list[int], bad: dict[int, str]) -> None:
    """The operating viscosity of each of ``rows`` with an oil cell (:data:`OIL_INPUTS`) into
    its ``viscosity`` cell, by solve's one rule (:meth:`bearingload.plan.case.Case.
    oil_viscosity`, each row on its own, each distinct oil once); a row it refuses goes to
    ``bad``."""
    present = [c for c in OIL_INPUTS if c in cols]
    if not present:
        return
    n = len(cols["load"])
    nu = cols.setdefault("viscosity", [None] * n)
    speed = cols.get("speed", [None] * n)
    seen: dict[tuple[Any, ...], tuple[float | None, str | None]] = {}
    for i in rows:
        oil = {c: cols[c][i] for c in present}
        if i in bad or all(x is None for x in oil.values()):
            continue
        key = (nu[i], speed[i] is None, *oil.values())
        if key not in seen:
            try:
                case = Case(viscosity=nu[i], speed=speed[i], **oil)
                seen[key] = (case.oil_viscosity()[0], None)
            except InputError as exc:
                seen[key] = (None, row_message(exc))
        value, why = seen[key]
        if why is None:
            nu[i] = value
        else:
            bad[i] = why


def _check_method(name: str) -> None:
    from bearingload.models.registry import METHODS, get_method

    if name != "exact" and name not in METHODS:
        get_method(name)  # raises, naming the methods there are


#: Columns a ring given by z and K may have beside its inputs; any other refuses its row.
_RING_COLUMNS = ("balls", "load", "stiffness", "clearance", "cage_angle", "exponent", "method")


def _ring_keys(
    cols: dict[str, list[Any]], idx: list[int], keys: list[Any], bad: dict[int, str]
) -> None:
    """The group of each radial row of a ring given by z and K, ("ring", method); a row the
    plan refuses (:func:`_ring_checks`) goes to ``bad``, checked only where some row has a cell
    a ring does not take or lacks one it needs."""
    methods = ["exact" if m is None else m for m in cols["method"]] if "method" in cols else None
    given = [c for c in cols if c not in _RING_COLUMNS and c[0] != "_"]
    odd = any(cols[c].count(None) < len(cols[c]) for c in given)
    odd = odd or any(c not in cols or None in cols[c] for c in ("balls", "load", "stiffness"))
    for i in idx:
        try:
            if methods is not None:
                _check_method(methods[i])
            if odd:
                _ring_checks({k: c[i] for k, c in cols.items() if c[i] is not None})
        except BearingloadError as exc:
            bad[i] = row_message(exc)
            continue
        keys[i] = ("ring", "exact" if methods is None else methods[i])


def _ring_checks(v: dict[str, Any]) -> None:
    """A ring given by z and K as solve checks it: no ball dynamics, no input of a bearing, no
    life of an allowable load, both z and K, a load."""
    case = row_case({k: x for k, x in v.items() if k[0] != "_"})
    refuse_static_dynamics(case)
    refuse_unused(case)
    refuse_revolutions(
        v.get("revolutions"), "a ring given by its balls and stiffness", "it has no C"
    )
    ring_by_hand(case, None if case.stiffness is None else float(case.stiffness))
    if "load" not in v:
        raise InputError("load", "missing: every row needs a load")


def taken(cols: dict[str, list[Any]], name: str, idx: list[int], default: Any = None) -> list[Any]:
    column = cols.get(name)
    if column is None:
        return [default] * len(idx)
    return [default if column[i] is None else column[i] for i in idx]


def cage_angles(given: list[Any], balls: Any) -> np.ndarray:
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

    def floats(name: str, default: Any = None) -> np.ndarray:
        return np.array(taken(cols, name, idx, default), dtype=float)

    balls = floats("balls")
    given = taken(cols, "clearance", idx, 0.0)
    clearance = [g if isinstance(g, float) else clearance_length(g) for g in given]
    angles = cage_angles(taken(cols, "cage_angle", idx, 0.0), balls)
    (lc,) = solve_ring(
        [key[1]],
        balls,
        floats("load"),
        floats("stiffness"),
        np.array(clearance, dtype=float),
        angles,
        floats("exponent", 1.5),
    )
    return case_columns(lc) | {"warnings": list(lc.warnings)}


def _solve_bearing(
    key: tuple[Any, ...], idx: list[int], cols: dict[str, list[Any]]
) -> dict[str, Any]:
    from bearingload.models.registry import METHODS
    from bearingload.studies.loaded_bearing import DEFAULT_REVOLUTIONS, case_columns, solve_bearing
    from bearingload.studies.reference_life import with_reference_lives

    _, b, method, rotating = key
    load = np.array(taken(cols, "load", idx), dtype=float)
    cage = cage_angles(taken(cols, "cage_angle", idx, 0.0), b.balls)
    revolutions = np.array(taken(cols, "revolutions", idx, DEFAULT_REVOLUTIONS), dtype=float)
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
        return np.array(taken(cols, name, idx, default), dtype=float) if on else None

    rho = given("ball_density", density)  # [kg/m^3], as solve's --ball-density
    try:
        (case,) = solve_combined_bearing(
            [b], given("load"), given("axial_load", default=0.0),
            cage_angle=cage_angles(taken(cols, "cage_angle", idx, 0.0), b.balls),
            moment=given("moment", moment), misalignment=given("misalignment", misaligned),
            rotating=rotating, dynamic_rating=c_r, moment_cross=given("moment_cross", cross),
            tilt_radius=None if groove else given("_lever"), speed=given("speed", at_speed),
            ball_density=rho,
        )  # fmt: skip
    except (InputError, ConvergenceError) as exc:  # a radial row at speed: no load cell
        cells = [cols[c][i] for c in LOAD_COLUMNS if c in cols for i in idx]
        radial = b.contact_angle is None and all(x is None for x in cells)
        hinted: BearingloadError | None = None
        deep_groove = b.contact_angle is None  # an angular-contact row: the solver's words
        if at_speed and isinstance(exc, InputError) and (deep_groove or too_fast(exc)):
            hinted = speed_hint(exc, radial)
        elif at_speed and radial:
            hinted = exc.with_way_out(QUASI_STATIC_WAY)
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
    """The operating conditions of ``rows`` (which give the same life cells) as arrays, as
    solve's case gives them (:meth:`bearingload.plan.case.Case.operating`; the viscosity is the
    oil's where an oil is given)."""

    def given(c: str) -> Any:
        if c not in cols or cols[c][rows[0]] is None:
            return None
        if c == "contamination":
            return cols[c][rows[0]]
        return np.array([cols[c][i] for i in rows], dtype=float)

    names = [c for c in SERVICE_COLUMNS if c not in OIL_INPUTS]
    return Case(**{"e_c" if c == "ec" else c: given(c) for c in names}).operating()


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
    speed the catalogue gives for bearing ``b`` (:func:`bearingload.plan.solve.speed_warnings`,
    each distinct speed once)."""
    from bearingload.plan.solve import speed_warnings

    if speeds is None:
        return
    warnings = out["warnings"]
    found: dict[Any, Any] = {}
    for j, i in enumerate(idx):
        if speeds[i] not in found:
            found[speeds[i]] = speed_warnings((), speeds[i], b)
        if found[speeds[i]]:
            warnings[j] = speed_warnings(tuple(warnings[j]), speeds[i], b)


def _floats(value: Any, n: int) -> np.ndarray:
    """A column over ``n`` rows as floats, None as NaN."""
    if value is None:
        return np.full(n, np.nan)
    if isinstance(value, list):
        return np.array([np.nan if x is None else x for x in value], dtype=float)
    return np.broadcast_to(np.asarray(value, dtype=float), (n,))


#: The columns whose values are checked against their input's range when read.
RANGED = (
    *("static_rating", "fatigue_load_limit", "speed", "viscosity", "viscosity_40"),
    *("viscosity_100", "roughness", "reliability", "ec", "pressure_viscosity", "ball_density"),
)


def _check_range(name: str, values: list[Any], bad: dict[int, str]) -> None:
    """Rows whose cell lies outside its input's range, refused by the input's reader
    (:data:`bearingload.plan.inputs.READERS`, the library's and solve's range and words)."""
    from bearingload.plan.inputs import READERS

    name = "e_c" if name == "ec" else name
    read = READERS[name]
    low, high, low_open = getattr(read, "range", (0.0, float("inf"), True))
    v = np.array([np.nan if x is None else x for x in values], dtype=float)
    inside = ((v > low) if low_open else (v >= low)) & (v <= high)
    for i in np.flatnonzero(~inside & ~np.isnan(v)).tolist():
        x = values[i]
        try:
            read(format(x, "g") if float(format(x, "g")) == x else repr(x), name)
        except InputError as exc:
            bad.setdefault(i, row_message(exc))


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
