"""Rows of a batch file under a combined load: the computation behind ``bearingload batch`` when
the file has an ``axial_load``, ``moment``, ``misalignment``, ``dynamic_rating`` or ``rotating``
column.

Every row names a deep-groove ball bearing (a catalogue designation and/or its ball geometry),
as ``bearingload solve --axial-load ...`` needs. The rows of one resolved bearing that share the
kind of tilt (free, a moment, an imposed misalignment), the rotating ring and C_r are solved by
ONE vectorised call (their clearances, loads and cage angles as arrays) of :func:`bearingload.models.combined.solve_combined` (through
:func:`bearingload.studies.combined_bearing.solve_on_bearing`), their lives by the vectorised
ISO/TS 16281 and ISO 281 functions. Should a group's call fail, its rows are solved one by one so
that the failing row is named and the others kept. Each row's answer depends on its own inputs
only (the combined solver treats every case independently; a test checks batch against solve).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from bearingload.errors import BearingloadError
from bearingload.studies.batch_input import row_message

#: The output columns of a combined-load file (those of ``solve --format csv`` with an axial
#: load), after the row number.
COMBINED_KEYS = (
    "bearing", "method", "balls", "load", "axial_load", "moment", "moment_cross",
    "misalignment", "tilt_radius", "rotating", "stiffness", "clearance", "clearance_pick",
    "cage_angle", "q_max", "loaded_balls", "p_max_inner", "p_max_outer",
    "static_equivalent_load", "static_safety", "contact_angle_max", "free_contact_angle", "axial_play", "x", "y",
    "axial", "tilt", "tilt_cross", "stiffness_radial", "stiffness_axial", "stiffness_tilt",
    "reference_rating_life",
    "dynamic_rating", "equivalent_load", "rating_life",
)  # fmt: skip

Part = tuple[list[int], dict[str, Any]]

#: Rows times balls solved per vectorised call (about 30 MB of solver work arrays; larger calls
#: are no faster per case).
CALL_BALLS = 2**15


def solve_combined_rows(rows: Sequence[dict[str, Any]], errors: dict[int, str]) -> list[Part]:
    """Solve rows given as dicts (``row``, ``bearing`` (resolved), ``load``, ``axial_load``,
    ``moment``, ``misalignment``, ``rotating``, ``dynamic_rating``, ``cage_angle``); per group,
    the row numbers and the quantities over them. Failing rows go to ``errors``."""
    groups: dict[tuple[Any, ...], list[dict[str, Any]]] = {}
    for r in rows:
        key = (_same_balls(r["bearing"]), r["moment"] is None, r["misalignment"] is None,
               r["rotating"], r["dynamic_rating"], r["moment_cross"] is None,
               r["tilt_radius"] is None)  # fmt: skip
        groups.setdefault(key, []).append(r)
    out: list[Part] = []
    for group in groups.values():  # memory bounded: at most CALL_BALLS ball contacts a call
        size = max(1, CALL_BALLS // int(group[0]["bearing"].balls))
        for i in range(0, len(group), size):
            out += _solve_group(group[i : i + size], errors)
    return out


def _same_balls(b: Any) -> tuple[Any, ...]:
    """What rows must share to be solved in one call: the bearing but its clearance (which
    enters the call as an array)."""
    f0 = None if b.geometry is None else b.geometry.f0
    return (b.designation, b.kind, b.balls, b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o,
            b.modulus, b.poisson, b.stiffness, b.stiffness_given, b.C, b.C0, f0)  # fmt: skip


def _solve_group(group: list[dict[str, Any]], errors: dict[int, str]) -> list[Part]:
    """One vectorised call for the group; one call per row if that fails."""
    try:
        with np.errstate(all="ignore"):
            return [_group_values(group)]
    except (BearingloadError, ValueError, ArithmeticError) as exc:
        if len(group) == 1:
            errors[group[0]["row"]] = row_message(exc)
            return []
    out: list[Part] = []
    for r in group:
        out += _solve_group([r], errors)
    return out


def _group_values(group: list[dict[str, Any]]) -> Part:
    """Solve the rows of one bearing together: their quantities (arrays over the rows)."""
    from bearingload.bearings.checks import combined_warnings
    from bearingload.studies.combined_bearing import (
        basic_lives,
        case_columns,
        reference_lives,
        ring_tilt,
        solve_on_bearing,
    )

    first = group[0]
    b = first["bearing"]

    def given(key: str) -> Any:
        return None if first[key] is None else np.array([r[key] for r in group], dtype=float)

    load, axial = given("load"), given("axial_load")
    misalignment = given("misalignment")  # an array: solve_on_bearing checks its largest
    clearance = np.array([g["bearing"].clearance for g in group], dtype=float)
    cross, lever = given("moment_cross"), given("tilt_radius")
    r = solve_on_bearing(b, load, axial, cage_angle=given("cage_angle"), moment=given("moment"),
                         misalignment=misalignment, clearance=clearance, moment_cross=cross,
                         tilt_radius=lever)  # fmt: skip
    c_r = first["dynamic_rating"] or b.C
    l10r = p_eq = life = None
    if c_r:
        l10r = reference_lives(b, r, first["rotating"], c_r)
        p_eq, life = basic_lives(b, c_r, load, axial)
    n = len(group)
    cols = case_columns(b, r, misalignment, first["rotating"], None if not c_r else
                        np.full(n, float(c_r)), p_eq, life, l10r, moment_cross=cross,
                        tilt_radius=lever)  # fmt: skip
    cols |= {k: cols.get(k) for k in ("moment_cross", "tilt_radius")}  # None: not given
    cols = {k: _over_rows(v, n) for k, v in cols.items()}
    for key in ("equivalent_load", "rating_life"):  # a moment alone, an F_a without f0: none
        values = cols[key]
        if isinstance(values, np.ndarray) and np.isnan(values).any():
            cols[key] = [None if v != v else v for v in values.tolist()]
    cols["clearance_pick"] = [g["bearing"].clearance_pick for g in group]
    pressures = _row_pressures(b, r, n)
    cols |= _static_columns(b, pressures, [g["load"] for g in group],
                            [g["axial_load"] for g in group])  # fmt: skip
    tilts = np.broadcast_to(ring_tilt(r), (n,)).tolist()
    q, loaded = cols["q_max"].tolist(), cols["loaded_balls"].tolist()
    per_row: list[Any] = (
        [None] * n
        if pressures is None
        else list(zip(*(p.tolist() for p in pressures), strict=True))
    )
    cols["warnings"] = [
        combined_warnings(g["bearing"], g["load"], g["axial_load"], q[i], loaded[i],
                          tilts[i] if g["moment"] is not None or g["moment_cross"]
                          else g["misalignment"], per_row[i])
        for i, g in enumerate(group)
    ]  # fmt: skip
    return [g["row"] for g in group], cols


def _static_columns(
    b: Any, pressures: tuple[np.ndarray, np.ndarray] | None, load: list[float], axial: list[float]
) -> dict[str, Any]:
    """The columns ``solve`` adds to the solved case (as
    :func:`bearingload.studies.combined_bearing.solve_combined_bearing` computes them): the
    largest inner and outer contact pressure of each row (blank where the ball geometry is not
    known) [MPa], the static equivalent load P0 = max(F_r, 0.6 F_r + 0.5 |F_a|) of ISO 76:2006,
    7.1 [N] and the static safety s0 = C0/P0 (ISO 76:2006, 3.6; blank where C0 is not known or
    P0 = 0) [-], by the functions solve uses."""
    from bearingload.bearings.checks import static_equivalent_load, static_safety

    n = len(load)
    p0 = [static_equivalent_load(fr, fa) for fr, fa in zip(load, axial, strict=True)]
    inner, outer = ([None] * n, [None] * n) if pressures is None else pressures
    return {
        "p_max_inner": inner,
        "p_max_outer": outer,
        "static_equivalent_load": np.array(p0, dtype=float),
        "static_safety": [static_safety(b.C0, p) for p in p0],
    }


def _row_pressures(b: Any, r: Any, n: int) -> tuple[np.ndarray, np.ndarray] | None:
    """The largest inner and outer contact pressure of each of the ``n`` rows, every ball at its
    load and contact angle, as ``solve`` weighs them (exact Hertz,
    :func:`bearingload.bearings.checks.max_contact_pressures`, vectorised over the rows); None
    where the ball geometry is not known. [MPa]"""
    if None in (b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o):  # as max_contact_pressures
        return None
    from bearingload.bearings.checks import ball_pressures

    loads = np.asarray(r.ball_loads, dtype=float).reshape(n, -1)
    p_i, p_o = ball_pressures(b, loads, np.broadcast_to(r.contact_angles, loads.shape))
    return np.max(p_i, axis=-1), np.max(p_o, axis=-1)


def _over_rows(value: Any, n: int) -> Any:
    """A column over the ``n`` rows: an array, or a list (text; None where not given)."""
    if value is None or isinstance(value, str):
        return [value] * n
    return np.broadcast_to(value, (n,)).copy()
