"""The plan of many cases at once: each case planned by the rules of one
(:func:`~bearingload.plan.solve.engine_of` and the refusals of :mod:`bearingload.plan`), then
the cases that share what a vectorised call shares solved together, as arrays.

The cases are columns (input name -> one value per case, None: not given), as batch reads a
csv file and as :func:`analyse_many` gathers a list of cases. Groups: a ring's cases of one
method by :func:`bearingload.studies.loaded_bearing.solve_ring`; a bearing's cases of one method
and rotating ring by :func:`~bearingload.studies.loaded_bearing.solve_bearing` and
:func:`~bearingload.studies.reference_life.with_reference_lives`; a bearing's combined cases of
one kind of tilt, rotating ring, C_r and ball dynamics by
:func:`bearingload.studies.combined_bearing.solve_combined_bearing`; the lives of the cases
whose bearings share what the lives use by
:func:`bearingload.bearings.service_life.service_columns`. Every engine solves each case on its
own, so a case's answer depends on its own inputs only. Should a call fail, its cases are split
in halves until the failing case stands alone; its error is kept, the others are solved.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

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
from bearingload.plan.case import LOAD_PARAMS, Case
from bearingload.plan.many_lives import SERVICE, service_groups
from bearingload.plan.solve import (
    QUASI_STATIC_WAY,
    check_revolutions,
    engine_of,
    in_case_terms,
    refuse_radial_options,
    refuse_revolutions,
    refuse_static_dynamics,
    speed_hint,
)

#: The inputs of a bearing pair: a column of one, every row of a file is a pair (a case of
#: the library given one is a pair).
PAIR_PARAMS = ("arrangement", "preload", "width")
#: Inputs that make a case a bearing (resolved) rather than a ring given by z and K.
GEOMETRY = ("bearing", "ball_diameter", "pitch_diameter")
#: Inputs whose plan depends only on whether they are given: a case's plan is kept for the
#: cases that differ from it only in their values.
_PER_CASE = (*LOAD_PARAMS[:-1], "load", "cage_angle", "ball_density", *SERVICE)
#: The load ratings a case may give in place of the catalogue's.
_RATINGS = ("dynamic_rating", "static_rating")
#: Inputs of no case but of the radial engine: its method and life.
_NOT_CASE = ("method", "revolutions")
#: Inputs a ring given by z and K may have; any other refuses its case.
_RING = ("balls", "load", "stiffness", "clearance", "cage_angle", "exponent", "method")
#: Cases times balls solved per combined call (about 30 MB of solver work arrays).
CALL_BALLS = 2**15

Part = tuple[list[int], dict[str, Any]]


@dataclass
class Many:
    """Solved cases: the ``rows`` solved (indices of the cases, in input order), their
    ``values`` (key -> array or list aligned with ``rows``, None where not given or where a
    quantity does not apply to a row's kind, a pair's or a single bearing's; ``warnings``: one
    tuple per case) and the ``errors`` of the cases not solved (index -> the refusal)."""

    rows: list[int] = field(default_factory=list)
    values: dict[str, Any] = field(default_factory=dict)
    errors: dict[int, Exception] = field(default_factory=dict)


def case_of(v: Mapping[str, Any], typed: dict[str, str] | None = None) -> Case:
    """The :class:`~bearingload.plan.case.Case` of one case's inputs ``v`` (not given left out;
    ``stiffness`` in N/mm^m, kept as its text), ``typed`` the texts of those given with a unit."""
    values = {k: x for k, x in v.items() if k not in _NOT_CASE and k[0] != "_"}
    if "stiffness" in values:
        values["stiffness"] = repr(float(values["stiffness"]))
    if "balls" in values:
        values["balls"] = int(values["balls"])
    return Case.of(values, typed=typed)


class Planner:
    """Plans and solves many cases whose inputs are among ``names``; each distinct plan of a
    case (its resolved bearing and group, or its refusal) is kept from call to call. Cases of
    pairs (``pairs``) are solved by :func:`bearingload.plan.many_pairs.solve_pair_cases`.

    A file's cases (batch) are planned by its columns: with a column of a load beyond the
    radial one (``loads``) an angular-contact designation's rows take the combined engine,
    without one the radial engine at rest; each row's load is checked by :func:`check_load`.
    ``per_case`` cases (the library's) are planned by their own inputs only, as
    :func:`~bearingload.plan.solve.engine_of` plans one: an angular-contact designation always
    takes the combined engine, as does a ring given by hand with a load beyond the radial one
    (which the combined engine refuses), and the load is left to the reader of the arguments
    (:func:`bearingload.plan.analyse.read_arguments`) and the solvers, as for one case."""

    def __init__(self, names: Collection[str], *, per_case: bool = False) -> None:
        self.names = frozenset(names)
        self.per_case = per_case
        self.loads = per_case or any(n in LOAD_PARAMS for n in self.names)
        self.pairs = any(n in PAIR_PARAMS for n in self.names)
        self.plans: dict[tuple[Any, ...], Any] = {}
        self.bare: dict[str, list[bool]] = {}
        self.typed: Sequence[dict[str, str]] = ()

    def solve(
        self,
        cols: dict[str, list[Any]],
        n: int,
        bad: dict[int, Any],
        bare: dict[str, list[bool]] | None = None,
        typed: Sequence[dict[str, str]] = (),
    ) -> Many:
        """Solve the ``n`` cases of ``cols`` but those in ``bad`` (index -> why not), whose
        inputs in ``bare`` (name -> per case) were bare numbers, judged by the bearing's size;
        ``typed`` each case's inputs typed with a unit (name -> ``"0kN"``; none: numbers in the
        package's units), which the refusal of a load of 0 and a failure name as typed."""
        self.bare = bare or {}
        self.typed = typed
        keys = self._keys(cols, n, bad)
        with_oil_viscosity(cols, [i for i, key in enumerate(keys) if key is not None], bad)
        groups: dict[tuple[Any, ...], list[int]] = {}
        for i, key in enumerate(keys):
            if key is not None and i not in bad:
                groups.setdefault(key, []).append(i)
        parts: list[Part] = []
        for key, idx in groups.items():
            size = _call_size(key)
            for start in range(0, len(idx), size):
                parts += split(_ENGINES[key[0]], key, idx[start : start + size], cols, bad)
        with_service(parts, cols, bad)
        for idx, out in parts:  # the oil's inputs, as given (the viscosity is nu's)
            out |= {c: [cols[c][i] for i in idx] for c in OIL_INPUTS if c in cols}
        many = merged(parts)
        many.errors = {i: self.in_case_terms(exc, cols, i) for i, exc in bad.items()}
        return many

    def in_case_terms(self, exc: Any, cols: dict[str, list[Any]], i: int) -> Any:
        """A failure of case ``i`` named by its inputs as given (:func:`~.solve.in_case_terms`:
        those given, as typed), not the solver's; ``per_case`` cases are named by their
        caller, which knows them (:func:`bearingload.plan.analyse.as_called`)."""
        if self.per_case or not isinstance(exc, ConvergenceError):
            return exc
        v = {k: c[i] for k, c in cols.items() if c[i] is not None}
        return in_case_terms(exc, case_of(v, self.typed[i] if i < len(self.typed) else None))

    def _keys(self, cols: dict[str, list[Any]], n: int, bad: dict[int, Any]) -> list[Any]:
        """Each case's group: ("ring", method), ("bearing", resolved bearing, method, rotating)
        or ("combined", ...); a case that cannot be solved goes to ``bad``."""
        keys: list[Any] = [None] * n
        cols["_lever"] = [None] * n  # a combined case's lever of the tilt [mm]
        rings = [i for i in range(n) if i not in bad]
        if any(c in cols for c in (*LOAD_PARAMS, *GEOMETRY, "tilt_radius")):
            rings = []
            for i in range(n):
                if i in bad:
                    continue
                try:
                    keys[i] = self._key(cols, i)
                except BearingloadError as exc:
                    bad[i] = exc
                    continue
                if keys[i] is None:
                    rings.append(i)
        _ring_keys(cols, rings, keys, bad)
        for i in [i for i, f in enumerate(cols.get("load", ())) if f == 0 and keys[i]]:
            if keys[i][0] != "combined":  # the radial engine: as solve refuses it
                try:
                    self.refuse_zero_load({k: c[i] for k, c in cols.items() if c[i] is not None}, i)
                except InputError as exc:
                    bad[i], keys[i] = exc, None
        return keys

    def refuse_zero_load(self, v: dict[str, Any], i: int) -> None:
        """Refuse case ``i``'s load of 0 (inputs ``v``) on the radial engine by the plan's check
        (:meth:`~bearingload.plan.case.Case.check_load`), named as typed (:attr:`typed`);
        an angular-contact designation's own refusal (the combined engine only) left to it."""
        case = case_of(v, self.typed[i] if i < len(self.typed) else None)
        case.check_load(radial=not case.wants_combined, combined=case.takes_combined)

    def _key(self, cols: dict[str, list[Any]], i: int) -> tuple[Any, ...] | None:
        """Case ``i``'s group (None: a ring given by z and K), planned once for every case of
        the same inputs but their values of :data:`_PER_CASE`; its load and bare numbers
        checked."""
        v = {k: c[i] for k, c in cols.items() if c[i] is not None and k != "_lever"}
        key, cols["_lever"][i] = self.planned(v, self._plan)
        if key is None:
            return None
        if not self.per_case:
            check_load(v, key[0] == "combined")
        self.refuse_bare(v, i, key[1])
        return key

    def planned(self, v: dict[str, Any], plan: Callable[[dict[str, Any]], Any]) -> Any:
        """``plan(v)``, or its refusal raised, kept for the cases of the same plan."""
        marker = tuple((k, True if k in _PER_CASE else x) for k, x in v.items())
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
        """Refuse a bare number of case ``i`` implausible for its bearing ``b``
        (:func:`bearingload.bearings.plausible.refuse_implausible_bare`, solve's rule): judged
        against the catalogue's ratings, as solve judges them, where the case replaces them."""
        from bearingload.bearings.plausible import refuse_implausible_bare

        bare = {n: float(v[n]) for n, flags in self.bare.items() if n in v and flags[i]}
        if bare and any(n in v for n in _RATINGS):
            rest = {k: x for k, x in v.items() if k not in _RATINGS}
            b = self.planned({**rest, "_catalogue": True}, _catalogue_bearing)
        if bare:
            refuse_implausible_bare(b, bare)

    def _plan(self, v: dict[str, Any]) -> tuple[tuple[Any, ...] | None, float | None]:
        """(the group, the lever of the tilt [mm]) of a case of inputs ``v``, by the plan's
        rules: the engine, the refusals; (None, None) for a ring given by z and K."""
        case = case_of(v)
        combined = self.loads and case.first_given(LOAD_PARAMS) is not None
        if case.by_hand and not (combined and self.per_case):
            if combined:
                raise InputError(
                    "bearing", "missing: the combined load needs a bearing or its ball geometry"
                )
            refuse_tilt_radius(case)
            return None, None
        method, revolutions = v.get("method", "exact"), v.get("revolutions")
        _refuse_pair(case.bearing)
        case, engine, at_speed = engine_of(case, method, revolutions)
        if engine == "combined" and not self.loads:  # an angular designation: radial at rest
            at_speed = case.speed is not None and not case.quasi_static
            if at_speed:
                refuse_radial_options(method, revolutions)
        if at_speed or self.loads and engine == "combined":
            return _combined_key(case)
        refuse_tilt_radius(case)
        return _bearing_key(case, method, revolutions), None


def _bearing_key(case: Case, method: str, revolutions: Any) -> tuple[Any, ...]:
    """A radial case of a bearing: its resolved bearing (C_r replaced by a dynamic_rating),
    method and rotating ring, checked as solve checks them."""
    _check_method(method)
    refuse_static_dynamics(case)
    b = bearing_of(case)
    check_revolutions(revolutions)
    if not b.C:
        refuse_revolutions(
            revolutions, "a bearing without a dynamic load rating C", "give 'dynamic_rating'"
        )
    check_rotating(case, b, [method])
    return ("bearing", b, method, case.rotating or "inner")


def _combined_key(case: Case) -> tuple[tuple[Any, ...], float | None]:
    """A combined-load case: its resolved bearing and what its call shares (the kind of tilt,
    the rotating ring, C_r, the ball dynamics), checked as solve checks them; the lever."""
    from bearingload.bearings.tilt import tilt_lever

    b = bearing_of(case)
    if b.kind == "ball" and b.has_geometry:
        check_rotating(case, b, ["exact"])
    b = with_contact_angle([b], case, "'contact_angle'")[0]
    lever = tilt_lever(case.tilt_radius, b.pitch_diameter)
    given = (case.moment, case.misalignment, case.moment_cross)
    tilts = (*(x is not None for x in given), lever is None)
    dynamics = (case.dynamics_arguments()["speed"] is not None, case.ball_density is not None)
    key = ("combined", b, tilts, case.rotating or "inner", case.dynamic_rating, dynamics)
    return key, lever


def _catalogue_bearing(v: dict[str, Any]) -> Any:
    """The resolved bearing (one of a pair) of a case's inputs ``v`` given without ratings:
    the catalogue's ratings."""
    case = engine_of(case_of(v), v.get("method", "exact"), v.get("revolutions"))[0]
    return resolve_bearings(case, case.stiffness_value())[0]


def bearing_of(case: Case) -> Any:
    """The resolved bearing of a case, its ratings replaced by those given."""
    stiffness = None if case.stiffness is None else float(case.stiffness)
    b = with_ratings(resolve_bearings(case, stiffness), case)[0]
    return b if case.dynamic_rating is None else b.with_dynamic_rating(case.dynamic_rating)


def check_load(v: dict[str, Any], combined: bool = True) -> None:
    """Every case has a load (a combined case's radial one 0 or more)."""
    if "load" not in v:
        what = "a (radial) load, 0 allowed" if combined else "a load"
        raise InputError("load", f"missing: every row needs {what}")
    if combined and not v["load"] >= 0:
        raise InputError("load", f"must be 0 N or more (got {v['load']!r} N)")


def _refuse_pair(text: str | None) -> None:
    """A matched pair (7205BDB) among cases without a pair's inputs: refused, saying how a
    file of pairs is written (its columns are those of a pair)."""
    from bearingload.bearings.angular import split_pair

    try:
        kind = None if text is None else split_pair(text)[1]
    except InputError:
        return  # a set suffix not read: the resolver names it
    if kind is not None:
        raise InputError(
            "bearing",
            f"{str(text).strip()!r} names a {kind} pair: a file of pairs has an 'arrangement' "
            "column (or 'preload', 'width'; every row of it a pair, written as solve writes a "
            "pair); here give the single bearing with the load it carries",
        )


def with_oil_viscosity(cols: dict[str, list[Any]], rows: list[int], bad: dict[int, Any]) -> None:
    """The operating viscosity of each of ``rows`` with an oil input (:data:`OIL_INPUTS`) into
    its ``viscosity``, by solve's one rule (:meth:`bearingload.plan.case.Case.oil_viscosity`,
    each case on its own, each distinct oil once); a case it refuses goes to ``bad``."""
    present = [c for c in OIL_INPUTS if c in cols]
    if not present:
        return
    n = len(cols["load"])
    nu = cols.setdefault("viscosity", [None] * n)
    speed = cols.get("speed", [None] * n)
    seen: dict[tuple[Any, ...], tuple[float | None, Exception | None]] = {}
    for i in rows:
        oil = {c: cols[c][i] for c in present}
        if i in bad or all(x is None for x in oil.values()):
            continue
        key = (nu[i], speed[i] is None, *oil.values())
        if key not in seen:
            try:
                seen[key] = (Case(viscosity=nu[i], speed=speed[i], **oil).oil_viscosity()[0], None)
            except InputError as exc:
                seen[key] = (None, exc)
        value, why = seen[key]
        if why is None:
            nu[i] = value
        else:
            bad[i] = why


def _check_method(name: str) -> None:
    from bearingload.models.registry import METHODS, get_method

    if name != "exact" and name not in METHODS:
        get_method(name)  # raises, naming the methods there are


def _ring_keys(
    cols: dict[str, list[Any]], idx: list[int], keys: list[Any], bad: dict[int, Any]
) -> None:
    """The group of each radial case of a ring given by z and K, ("ring", method); a case the
    plan refuses (:func:`_ring_checks`) goes to ``bad``, checked only where some case has an
    input a ring does not take or lacks one it needs."""
    methods = ["exact" if m is None else m for m in cols["method"]] if "method" in cols else None
    given = [c for c in cols if c not in _RING and c[0] != "_"]
    odd = any(cols[c].count(None) < len(cols[c]) for c in given)
    odd = odd or any(c not in cols or None in cols[c] for c in ("balls", "load", "stiffness"))
    for i in idx:
        try:
            if methods is not None:
                _check_method(methods[i])
            if odd:
                _ring_checks({k: c[i] for k, c in cols.items() if c[i] is not None})
        except BearingloadError as exc:
            bad[i] = exc
            continue
        keys[i] = ("ring", "exact" if methods is None else methods[i])


def _ring_checks(v: dict[str, Any]) -> None:
    """A ring given by z and K as solve checks it: no ball dynamics, no input of a bearing, no
    life of an allowable load, both z and K, a load."""
    case = case_of(v)
    refuse_static_dynamics(case)
    refuse_unused(case)
    refuse_revolutions(
        v.get("revolutions"), "a ring given by its balls and stiffness", "it has no C"
    )
    ring_by_hand(case, None if case.stiffness is None else float(case.stiffness))
    if "load" not in v:
        raise InputError("load", "missing: every row needs a load")


def taken(cols: dict[str, list[Any]], name: str, idx: list[int], default: Any = None) -> list[Any]:
    """The values of ``name`` of the cases ``idx``, ``default`` where not given."""
    column = cols.get(name)
    if column is None:
        return [default] * len(idx)
    return [default if column[i] is None else column[i] for i in idx]


def floats(cols: dict[str, list[Any]], name: str, idx: list[int], default: Any = None) -> Any:
    """:func:`taken` as an array of floats."""
    return np.array(taken(cols, name, idx, default), dtype=float)


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

    balls = floats(cols, "balls", idx)
    given = taken(cols, "clearance", idx, 0.0)
    clearance = np.array([g if isinstance(g, float) else clearance_length(g) for g in given])
    angles = cage_angles(taken(cols, "cage_angle", idx, 0.0), balls)
    load, k = floats(cols, "load", idx), floats(cols, "stiffness", idx)
    m = floats(cols, "exponent", idx, 1.5)
    (lc,) = solve_ring([key[1]], balls, load, k, clearance, angles, m)
    return case_columns(lc) | {"warnings": list(lc.warnings)}


def _solve_bearing(
    key: tuple[Any, ...], idx: list[int], cols: dict[str, list[Any]]
) -> dict[str, Any]:
    from bearingload.models.registry import METHODS
    from bearingload.studies.loaded_bearing import DEFAULT_REVOLUTIONS, case_columns, solve_bearing
    from bearingload.studies.reference_life import with_reference_lives

    _, b, method, rotating = key
    cage = cage_angles(taken(cols, "cage_angle", idx, 0.0), b.balls)
    revolutions = floats(cols, "revolutions", idx, DEFAULT_REVOLUTIONS)
    cases = solve_bearing([b], floats(cols, "load", idx), cage, [method], revolutions)
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
    from bearingload.studies.combined_bearing import combined_columns, solve_combined_bearing

    _, b, (moment, misaligned, cross, groove), rotating, c_r, (at_speed, density) = key

    def given(name: str, on: bool = True, default: Any = None) -> Any:
        return floats(cols, name, idx, default) if on else None

    try:
        (case,) = solve_combined_bearing(
            [b],
            given("load"),
            given("axial_load", default=0.0),
            cage_angle=cage_angles(taken(cols, "cage_angle", idx, 0.0), b.balls),
            moment=given("moment", moment),
            misalignment=given("misalignment", misaligned),
            rotating=rotating,
            dynamic_rating=c_r,
            moment_cross=given("moment_cross", cross),
            tilt_radius=None if groove else given("_lever"),
            speed=given("speed", at_speed),
            ball_density=given("ball_density", density),  # [kg/m^3], as solve's
        )
    except (InputError, ConvergenceError) as exc:
        raise _speed_way(exc, b, idx, cols) if at_speed else exc from exc
    out = combined_columns(case) | _contacts(case.result, len(idx), b.contact_angle)
    hidden = {"_bearing": b, "_load": out["equivalent_load"], "_rotating": rotating}
    return out | _heaviest(case.result, len(idx)) | hidden


def _speed_way(exc: Any, b: Any, idx: list[int], cols: dict[str, list[Any]]) -> Any:
    """A refusal of the ball dynamics with the way to the static engine, as solve gives it
    (:func:`~bearingload.plan.solve.speed_hint`); ``exc`` itself where solve gives none."""
    from bearingload.models.high_speed import too_fast

    cells = [cols[c][i] for c in LOAD_PARAMS if c in cols for i in idx]
    radial = b.contact_angle is None and all(x is None for x in cells)
    deep_groove = b.contact_angle is None  # an angular-contact case: the solver's words
    hinted = None
    if isinstance(exc, InputError) and (deep_groove or too_fast(exc)):
        hinted = speed_hint(exc, radial)
    elif radial:
        hinted = exc.with_way_out(QUASI_STATIC_WAY)
    return exc if hinted is None else hinted


def _heaviest(res: Any, n: int) -> dict[str, Any]:
    """The contact angles of each case's heaviest ball, inner and outer (NaN without the ball
    dynamics) [°], and P of L10, for the lives."""
    loads = np.asarray(res.ball_loads, dtype=float).reshape(n, -1)
    heaviest = np.argmax(loads, axis=-1)[:, None]

    def at_heaviest(values: Any) -> Any:
        if values is None:
            return np.full(n, np.nan)
        angles = np.asarray(values, dtype=float).reshape(n, -1)
        return np.take_along_axis(angles, heaviest, axis=-1)[:, 0]

    outer = getattr(res, "contact_angles_outer", None)  # the ball dynamics at speed
    return {"_angle": at_heaviest(res.contact_angles), "_angle_outer": at_heaviest(outer)}


def _contacts(res: Any, n: int, contact_angle: float | None) -> dict[str, Any]:
    """The json-only quantities of the ``n`` combined cases of ``res``, as solve's json names
    them (:func:`bearingload.reports.combined.contact_values`): ``model`` and each case's
    per-ball contact angles and loads, inner and outer."""
    from bearingload.reports.combined import contact_values

    found = contact_values(res, contact_angle)
    out: dict[str, Any] = {"model": found.pop("model")}
    for key, value in found.items():
        out[key] = list(np.asarray(value, dtype=float).reshape(n, -1))
    return out


def with_service(parts: list[Part], cols: dict[str, list[Any]], bad: dict[int, Any]) -> None:
    """Add to the bearing cases of ``parts`` the lives of
    :func:`bearingload.bearings.service_life.service_columns` (C_0 for every case, the others by
    the inputs each case gives; a value a case has not is None) and their warnings.

    The cases whose bearings share what the lives use (kind, C, C_0, the ball geometry; not the
    clearance) and that give the same life inputs (and contamination level) are one call on
    arrays. A case whose lives solve would refuse (a speed so small that its life in hours
    overflows) is taken out of its part, its reason in ``bad``."""
    failed = service_groups(parts, cols)
    for p in sorted({p for p, _ in failed}, reverse=True):
        idx, out = parts[p]
        for j in (j for q, j in failed if q == p):
            bad[idx[j]] = failed[p, j]
        keep = [j for j in range(len(idx)) if (p, j) not in failed]
        if not keep:
            del parts[p]
            continue
        columns = {k: _over(v, len(idx)) for k, v in out.items()}
        parts[p] = (
            [idx[j] for j in keep],
            {
                k: [v[j] for j in keep] if isinstance(v, list) else np.asarray(v)[keep]
                for k, v in columns.items()
            },
        )


Engine = Callable[[tuple[Any, ...], list[int], dict[str, list[Any]]], dict[str, Any]]
_ENGINES: dict[str, Engine] = {
    "ring": _solve_rings,
    "bearing": _solve_bearing,
    "combined": _solve_combined,
}


def _call_size(key: tuple[Any, ...]) -> int:
    """Cases per call: a combined call holds at most :data:`CALL_BALLS` ball contacts."""
    return max(1, CALL_BALLS // int(key[1].balls)) if key[0] == "combined" else 1 << 62


def split(
    call: Callable[..., Any], key: Any, idx: list[int], cols: Any, bad: dict[int, Any]
) -> list[Any]:
    """``[(idx, call(key, idx, cols))]``: the cases ``idx`` of one group in one call; if that
    fails, each half on its own, down to the failing case, whose error goes to ``bad``."""
    try:
        with np.errstate(all="ignore"):
            return [(idx, call(key, idx, cols))]
    except (BearingloadError, ValueError, ArithmeticError) as exc:
        if len(idx) == 1:
            bad[idx[0]] = exc
            return []
    half = len(idx) // 2
    return split(call, key, idx[:half], cols, bad) + split(call, key, idx[half:], cols, bad)


def merged(parts: Sequence[Part]) -> Many:
    """The cases of ``parts`` (``(indices, values over them)``, the parts' indices disjoint)
    in input order, each value over them (an array where every part gives one of one kind,
    else a list with None where a part has none)."""
    out = Many()
    if not parts:
        return out
    idx = [i for p, _ in parts for i in p]
    order: Any = np.argsort(idx, kind="stable")
    if bool(np.all(np.diff(idx) > 0)):
        order = slice(None)  # in input order already
    out.rows = np.asarray(idx)[order].tolist()
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
    """A value over ``n`` cases: an array, or a list (text; None where not given)."""
    if value is None or isinstance(value, str):
        return [value] * n
    if isinstance(value, list):
        return value
    return np.broadcast_to(value, (n,))
