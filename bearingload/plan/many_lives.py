"""The lives of many solved cases on arrays: the cases whose bearings share what the lives use
and that give the same operating inputs are one call of
:func:`bearingload.bearings.service_life.service_columns`, as
:func:`bearingload.plan.solve.service_lives` computes them for one case, with the same
warnings (solve's limiting speed, kappa outside its range, a missing fatigue load limit)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from bearingload.bearings.oil import OIL_INPUTS
from bearingload.errors import BearingloadError
from bearingload.plan.case import SERVICE_PARAMS, Case

#: The operating conditions of the lives that vary from case to case (C_0 changes the bearing).
SERVICE = tuple(n for n in SERVICE_PARAMS if n != "static_rating")
Member = tuple[int, int]  # (part, case within the part)


def service_groups(parts: list[Any], cols: dict[str, list[Any]]) -> dict[Member, Exception]:
    """Add to the bearing cases of ``parts`` (``(indices, values)``) their lives and warnings;
    each part's hidden ``_bearing``, ``_rotating``, ``_load`` (P of L10 [N]) and ``_angle``,
    ``_angle_outer`` (the heaviest ball's contact angles [°]) are used and removed. Returns the
    cases whose lives are refused (a speed so small that the life in hours overflows)."""
    present = [c for c in SERVICE if c in cols]
    groups: dict[tuple[Any, ...], list[Member]] = {}
    bases: dict[tuple[Any, ...], Any] = {}
    for p, (idx, out) in enumerate(parts):
        b = out.pop("_bearing", None)
        rotating = out.pop("_rotating", "inner")
        if b is None:
            continue
        _speed_warnings(b, idx, out, cols.get("speed"))
        same = _life_bearing(b)
        bases[same] = b
        for j, i in enumerate(idx):
            given = tuple(
                (c, cols[c][i] if c == "contamination" else True)
                for c in present
                if cols[c][i] is not None
            )
            groups.setdefault((same, rotating, given), []).append((p, j))
    failed: dict[Member, Exception] = {}
    gathered = _Gathered(parts)
    for (same, rotating, _), group in groups.items():
        b = bases[same]
        for members, found in _bisected(group, _call(parts, cols, b, rotating, gathered), failed):
            _write(parts, members, found)
            rows = [parts[p][0][j] for p, j in members[:1]]
            _life_warnings(found.get("kappa"), operating(cols, rows), b, members, parts)
    for _, out in parts:
        for key in ("_load", "_angle", "_angle_outer"):
            out.pop(key, None)
    return failed


def _life_bearing(b: Any) -> tuple[Any, ...]:
    """What of bearing ``b`` the lives use (not its clearance): bearings alike share a call."""
    geometry = (b.pitch_diameter, b.ball_diameter, b.f_i, b.f_o, b.modulus, b.poisson)
    return (b.kind, b.C, b.C0, *geometry, b.roller_length)


class _Gathered:
    """A value of the members' parts as one array of floats (None as NaN)."""

    def __init__(self, parts: list[Any]) -> None:
        self.parts = parts
        self.floats: dict[tuple[int, str], np.ndarray] = {}

    def __call__(self, key: str, members: list[Member]) -> np.ndarray:
        for p in {p for p, _ in members}:
            if (p, key) not in self.floats:
                self.floats[p, key] = _floats(self.parts[p][1].get(key), len(self.parts[p][0]))
        return np.array([self.floats[p, key][j] for p, j in members], dtype=float)


def _call(
    parts: list[Any], cols: dict[str, list[Any]], b: Any, rotating: str, gathered: _Gathered
) -> Callable[[list[Member]], dict[str, Any]]:
    from bearingload.bearings.service_life import service_columns

    def call(members: list[Member]) -> dict[str, Any]:
        rows = [parts[p][0][j] for p, j in members]
        return service_columns(operating(cols, rows), _basis(b, members, gathered, rotating))

    return call


def _write(parts: list[Any], members: list[Member], found: dict[str, Any]) -> None:
    """The values ``found`` over ``members`` into their parts (NaN: None)."""
    for key, value in found.items():
        values = np.broadcast_to(value, (len(members),)).tolist()
        for (p, j), x in zip(members, values, strict=True):
            column = parts[p][1].setdefault(key, [None] * len(parts[p][0]))
            column[j] = None if x != x else x


def _bisected(
    members: list[Member],
    call: Callable[[list[Member]], dict[str, Any]],
    failed: dict[Member, Exception],
) -> list[tuple[list[Member], dict[str, Any]]]:
    """``call`` on ``members`` at once; if that is refused, each half on its own, down to the
    refused case, whose error goes to ``failed``."""
    try:
        with np.errstate(all="ignore"):
            return [(members, call(members))]
    except BearingloadError as exc:
        if len(members) == 1:
            failed[members[0]] = exc
            return []
    half = len(members) // 2
    return _bisected(members[:half], call, failed) + _bisected(members[half:], call, failed)


def operating(cols: dict[str, list[Any]], rows: list[int]) -> Any:
    """The operating conditions of ``rows`` (which give the same life inputs) as arrays, as a
    case gives them (:meth:`bearingload.plan.case.Case.operating`; the viscosity is the oil's
    where an oil is given)."""

    def given(c: str) -> Any:
        if c not in cols or cols[c][rows[0]] is None:
            return None
        if c == "contamination":
            return cols[c][rows[0]]
        return np.array([cols[c][i] for i in rows], dtype=float)

    return Case(**{c: given(c) for c in SERVICE if c not in OIL_INPUTS}).operating()


def _basis(b: Any, members: list[Member], gathered: _Gathered, rotating: str) -> Any:
    """The life basis of the cases ``members`` of bearing ``b`` (P, lives, Q_max, the heaviest
    ball's angles, the rotating ring)."""
    from bearingload.bearings.service_life import LifeBasis
    from bearingload.studies.life_basis import life_geometry

    return LifeBasis(
        C=b.C,
        equivalent_load=gathered("_load", members),
        rating_life=gathered("rating_life", members),
        reference_rating_life=gathered("reference_rating_life", members),
        q_max=gathered("q_max", members),
        contact_angle=gathered("_angle", members),
        contact_angle_outer=gathered("_angle_outer", members),
        balls=b.balls,
        rotating=rotating,
        **life_geometry(b),
    )


def _life_warnings(
    kappa: Any, op: Any, basis: Any, members: list[Member], parts: list[Any]
) -> None:
    """Each case's warnings of its lives, as solve gives them for one case
    (:func:`bearingload.bearings.service_life.life_warnings`)."""
    from bearingload.bearings.service_life import life_warnings

    kappas = np.broadcast_to(np.nan if kappa is None else kappa, (len(members),))
    for (p, j), found in zip(members, life_warnings(op, basis, kappas), strict=True):
        if found:
            warnings = parts[p][1]["warnings"]
            row = list(warnings[j])
            warnings[j] = tuple(row + [w for w in found if w not in row])


def _speed_warnings(b: Any, idx: list[int], out: dict[str, Any], speeds: Any) -> None:
    """Add to each case of a part the warning solve gives on its speed [r/min] above the
    limiting speed the catalogue gives for bearing ``b`` (:func:`bearingload.plan.solve.
    speed_warnings`, each distinct speed once)."""
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
    """A value over ``n`` cases as floats, None as NaN."""
    if value is None:
        return np.full(n, np.nan)
    if isinstance(value, list):
        return np.array([np.nan if x is None else x for x in value], dtype=float)
    return np.broadcast_to(np.asarray(value, dtype=float), (n,))
