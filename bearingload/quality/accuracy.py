"""Work-precision study: every way the package computes Q_max, its error and its cost.

The cases (fixed; ``data/accuracy_reference.csv``): bearing 306 of Kuzmenko (2010, §3.4:
``F_r = 300 kgf``, ``K = 4700 kgf/mm^1.5``) with z = 6, 8, 12, 20, 40 balls, radial clearance
``G_r`` = -20 (preload), 0, 20 (the paper's Delta = 0.01 mm), 100 and 400 um, a ball under the load
(cage angle 0) and the load between two balls (180/z), m = 3/2: 50 cases.

The reference is ``k = Q_max/F_r`` of the exact ring equilibrium at 50 digits (mpmath), written by
``benchmarks/make_reference.py``, which shares no code with the package (a test re-computes a
sample of it). The methods measured:

* ``exact``: the ring-equilibrium engine (:func:`bearingload.models.equilibrium.solve`) at
  relative residual tolerances 1e-2 ... 1e-14;
* ``trial``: Kuzmenko's trial angles at 1°, 0.1°, 0.01° (:func:`bearingload.models.hand.kuzmenko2010_trial`;
  the cases with clearance only, the procedure needs a gap);
* ``continuum``: the continuum model at Gauss-Legendre orders 2 ... 128 and its default
  (:func:`bearingload.models.continuum.solve_continuum`); it ignores the cage angle;
* ``jr_table``: the continuum model with ``J_r`` interpolated in a table at steps of 0.1
  (:func:`bearingload.models.hand.load_zone_table_k`);
* ``stribeck`` (4.37/z) and ``palmgren`` (5/z).

The combined-load solver (:func:`bearingload.models.combined.solve_combined`, the 3-D ring
equilibrium of ISO/TS 16281 with Hertz ``K(alpha)``) is measured on its own cases
(``data/accuracy_combined_reference.csv``): a deep-groove bearing of the 6305 size (z = 7,
``D_w = 11.5``, ``d_m = 43.5`` mm, ``f_i = 0.52``, ``f_o = 0.53``), radial, axial and combined
loads, a moment, preload down to -30 µm, an imposed misalignment of 0.05° and of exactly 0. The
reference is ``Q_max`` of that model at 40 digits (mpmath), written by
``benchmarks/make_combined_reference.py``, which shares no code with the package (a test checks
the stored states against the model's equations). Rows ``combined``: one per group of cases
(with clearance, under preload, with an imposed misalignment).

Errors and iteration counts are deterministic and committed (``tables/accuracy.*``); run times
vary from run to run and are only printed.
"""

from __future__ import annotations

import csv
import os
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from bearingload.lazy_dataclass import dataclass

REFERENCE_FILE = os.path.join(os.path.dirname(__file__), "data", "accuracy_reference.csv")
COMBINED_REFERENCE_FILE = os.path.join(
    os.path.dirname(__file__), "data", "accuracy_combined_reference.csv"
)
#: Tolerances of the exact solver measured (relative equilibrium residual). [-]
TOLERANCES = (1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-13, 1e-14)
#: Resolutions of the trial angle. [°]
TRIAL_STEPS = (1.0, 0.1, 0.01)
#: Gauss-Legendre orders of the continuum model. [-]
QUADRATURE_ORDERS = (2, 4, 8, 16, 32, 128)


@dataclass(frozen=True)
class Cases:
    """The accuracy cases as arrays, with the reference load factor."""

    balls: np.ndarray
    load: np.ndarray
    stiffness: np.ndarray
    clearance: np.ndarray
    cage_angle: np.ndarray
    k_reference: np.ndarray

    def take(self, mask: np.ndarray) -> Cases:
        return Cases(*(getattr(self, f)[mask] for f in self.__dataclass_fields__))

    def one(self, i: int) -> Cases:
        """Case ``i`` as Python numbers, the way a caller passes one case."""
        values = [getattr(self, f)[i].item() for f in self.__dataclass_fields__]
        return Cases(*values)

    def tile(self, copies: int) -> Cases:
        return Cases(*(np.tile(getattr(self, f), copies) for f in self.__dataclass_fields__))

    def __len__(self) -> int:
        return int(self.balls.size)


def reference_cases() -> Cases:
    """Read the cases and their 50-digit reference ``k`` (as doubles) from the package data."""
    with open(REFERENCE_FILE, encoding="utf-8", newline="") as fh:
        rows = list(csv.reader(fh))[1:]
    cols = list(zip(*rows, strict=True))
    return Cases(
        np.array(cols[1], dtype=np.int64),
        *(np.array(cols[i], dtype=float) for i in range(2, 7)),
    )


#: A method: cases -> (k, iterations per case)
Runner = Callable[[Cases], tuple[np.ndarray, np.ndarray]]


@dataclass(frozen=True)
class Method:
    """One way of computing k: its name, its setting, which cases it applies to, and how."""

    method: str
    setting: str
    run: Runner
    applies: Callable[[Cases], np.ndarray] = lambda c: np.ones(len(c), dtype=bool)


def _exact(tolerance: float) -> Runner:
    def run(c: Cases) -> tuple[np.ndarray, np.ndarray]:
        from bearingload.models.equilibrium import solve

        r = solve(c.balls, c.load, c.stiffness, c.clearance, c.cage_angle, tolerance=tolerance)
        return np.asarray(r.k), np.asarray(r.iterations)

    return run


def _trial(step: float) -> Runner:
    def run(c: Cases) -> tuple[np.ndarray, np.ndarray]:
        from bearingload.models.hand import kuzmenko2010_trial

        r = kuzmenko2010_trial(c.balls, c.load, c.stiffness, c.clearance, c.cage_angle, step)
        return np.asarray(r.k), np.asarray(r.evaluations)

    return run


def _continuum(nodes: int | None) -> Runner:
    def run(c: Cases) -> tuple[np.ndarray, np.ndarray]:
        from bearingload.models.continuum import solve_continuum

        r = solve_continuum(c.balls, c.load, c.stiffness, c.clearance, nodes=nodes)
        return np.asarray(r.k), np.asarray(r.iterations)

    return run


def _table(c: Cases) -> tuple[np.ndarray, np.ndarray]:
    from bearingload.models.hand import load_zone_table_k

    r = load_zone_table_k(c.balls, c.load, c.stiffness, c.clearance)
    return np.asarray(r.k), np.asarray(r.iterations)


def _constant(value: float) -> Runner:
    def run(c: Cases) -> tuple[np.ndarray, np.ndarray]:
        from bearingload.models.approximations import palmgren, stribeck

        r = (stribeck if value == 4.37 else palmgren)(c.balls, c.load)
        return np.asarray(r.k), np.zeros(np.shape(r.k), dtype=np.int64)

    return run


def methods() -> list[Method]:
    """Every method measured, in the order of the report."""
    out = [Method("exact", f"tolerance {t:.0e}", _exact(t)) for t in TOLERANCES]
    out += [
        Method("trial", f"phi0 step {s:g} deg", _trial(s), lambda c: c.clearance > 0)
        for s in TRIAL_STEPS
    ]
    out += [Method("continuum", f"{n} nodes", _continuum(n)) for n in QUADRATURE_ORDERS]
    out.append(Method("continuum", "default (48/128 nodes)", _continuum(None)))
    out.append(Method("jr_table", "J_r step 0.1, 4 decimals", _table))
    out.append(Method("stribeck", "4.37/z", _constant(4.37)))
    out.append(Method("palmgren", "5/z", _constant(5.0)))
    return out


def _best_time(call: Callable[[], Any], repeats: int) -> float:
    best = float("inf")
    for _ in range(repeats):
        t0 = time.perf_counter()
        call()
        best = min(best, time.perf_counter() - t0)
    return best


def _time_loop(method: Method, cases: Cases, repeats: int) -> float:
    """Best time of running the cases one per call."""
    singles = [cases.one(i) for i in range(len(cases))]

    def loop() -> None:
        for one in singles:
            method.run(one)

    return _best_time(loop, repeats)


def _time_call(method: Method, cases: Cases, repeats: int) -> float:
    """Best time of one vectorised call on all the cases."""
    return _best_time(lambda: method.run(cases), repeats)


def measure(*, timing: bool = False, repeats: int = 5, copies: int = 200) -> list[dict[str, Any]]:
    """One row per method and setting: cases, relative error of Q_max (median, largest), iterations.

    With ``timing``: the run time per case one case at a time (best of ``repeats`` loops over the
    cases) and vectorised (one call on the cases repeated ``copies`` times, best of ``repeats``). [s]
    """
    all_cases = reference_cases()
    rows = []
    for method in methods():
        cases = all_cases.take(method.applies(all_cases))
        k, iterations = method.run(cases)
        error = np.abs(k / cases.k_reference - 1.0)
        row: dict[str, Any] = {
            "method": method.method,
            "setting": method.setting,
            "cases": len(cases),
            # 3 digits: an error is a magnitude, and its last digits change with the platform's
            # rounding where it is near 1e-16
            "error_median": float(f"{np.median(error):.3g}"),
            "error_max": float(f"{np.max(error):.3g}"),
            "iterations": int(np.max(iterations)),
        }
        if timing:
            many = cases.tile(copies)
            row["seconds_per_case"] = _time_loop(method, cases, repeats) / len(cases)
            row["seconds_per_case_vectorised"] = _time_call(method, many, repeats) / len(many)
        rows.append(row)
    return rows + measure_combined(timing=timing, repeats=repeats, copies=copies)


#: Keyword arguments of ``solve_combined`` read from the combined reference, with their column.
_COMBINED_INPUTS = (
    ("ball_diameter", "ball_diameter [mm]"),
    ("pitch_diameter", "pitch_diameter [mm]"),
    ("f_i", "f_i"),
    ("f_o", "f_o"),
    ("modulus", "modulus [MPa]"),
    ("poisson", "poisson"),
    ("radial_load", "load [N]"),
    ("axial_load", "axial_load [N]"),
    ("clearance", "clearance [mm]"),
    ("cage_angle", "cage_angle [°]"),
)
#: The groups of combined-load cases reported, in order.
COMBINED_GROUPS = (
    "Hertz K(alpha), with clearance",
    "Hertz K(alpha), preload",
    "Hertz K(alpha), imposed misalignment",
)


def _group(case: dict[str, Any]) -> str:
    """The group of :data:`COMBINED_GROUPS` a combined case belongs to."""
    if case["misalignment"] is not None:
        return COMBINED_GROUPS[2]
    return COMBINED_GROUPS[1] if case["clearance"] < 0 else COMBINED_GROUPS[0]


def combined_cases() -> list[dict[str, Any]]:
    """The combined-load cases: ``label``, ``balls``, the inputs of ``solve_combined`` (``moment``
    or, where imposed, ``misalignment`` [°]) and the reference ``q_max`` [N] (as a double)."""
    with open(COMBINED_REFERENCE_FILE, encoding="utf-8", newline="") as fh:
        rows = list(csv.DictReader(fh))
    out = []
    for r in rows:
        case: dict[str, Any] = {"label": r["label"], "balls": int(r["balls"])}
        case |= {key: float(r[column]) for key, column in _COMBINED_INPUTS}
        tilt = r["misalignment [°]"]
        case["misalignment"] = float(tilt) if tilt else None
        case["moment"] = float(r["moment [N mm]"])
        case["q_max"] = float(r["q_max [N]"])
        out.append(case)
    return out


def _run_combined(cases: list[dict[str, Any]], copies: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Q_max [N] and iterations of the cases (one z and one kind of tilt), in one call."""
    from bearingload.models.combined import solve_combined

    keys = [k for k, _ in _COMBINED_INPUTS]
    keys.append("moment" if cases[0]["misalignment"] is None else "misalignment")
    kw = {k: np.tile([float(c[k]) for c in cases], copies) for k in keys}
    r = solve_combined(cases[0]["balls"], **kw)
    return np.asarray(r.q_max), np.asarray(r.iterations)


def measure_combined(
    *, timing: bool = False, repeats: int = 5, copies: int = 200
) -> list[dict[str, Any]]:
    """The combined-load rows of :func:`measure`: per group of :data:`COMBINED_GROUPS` the
    relative error of Q_max against the 40-digit reference, per case the larger of one case per
    call and the group in one call (so that an answer depending on the batch shows), and the
    iterations; with ``timing`` the time per case one per call and vectorised (``copies`` of the
    group in one call). [s]"""
    everything = combined_cases()
    rows = []
    for setting in COMBINED_GROUPS:
        cases = [c for c in everything if _group(c) == setting]
        ref = np.array([c["q_max"] for c in cases])
        together, iterations = _run_combined(cases)
        alone = np.concatenate([_run_combined([c])[0] for c in cases])
        error = np.maximum(np.abs(together / ref - 1.0), np.abs(alone / ref - 1.0))
        row: dict[str, Any] = {
            "method": "combined",
            "setting": setting,
            "cases": len(cases),
            "error_median": float(f"{np.median(error):.3g}"),
            "error_max": float(f"{np.max(error):.3g}"),
            "iterations": int(np.max(iterations)),
        }
        if timing:

            def loop(cs: list[dict[str, Any]] = cases) -> None:
                for c in cs:
                    _run_combined([c])

            row["seconds_per_case"] = _best_time(loop, repeats) / len(cases)

            def call(cs: list[dict[str, Any]] = cases) -> None:
                _run_combined(cs, copies)

            many = _best_time(call, repeats)
            row["seconds_per_case_vectorised"] = many / (len(cases) * copies)
        rows.append(row)
    return rows
