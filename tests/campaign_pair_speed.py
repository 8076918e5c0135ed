"""Random campaign of the bearing pair at speed (bearingload.models.pair_speed; a sibling of
tests/campaign_pair.py and tests/campaign_speed.py, not part of the test suite).

Run: ``.venv/bin/python -m tests.campaign_pair_speed [cases] [seed]`` (default 300, seed 1).
The cases of tests/campaign_pair.py (z 3..40, four ball sets, 10-45°, DB/DF/DT, loads 10 N to
C_0r, preloads, moments, any cage angle; Hertz K only: the dynamics take no constant K), each at
a speed with n d_m from 0 to 1e6 mm/min (a third in the top fifth), one in five with silicon
nitride balls.

Printed: solved, refused (by parameter), ConvergenceError, NaN, negative loads; the largest
shaft residual (the solver's measure, over the largest of the applied loads and the preload),
how many are above 1e-12 (accepted at the rounding of the ball forces); an independent plain
sum of the returned inner loads and angles of the shaft's five forces over that load; each
ball's two equations from the returned forces and angles over the largest of their terms.
"""

from __future__ import annotations

import math
import sys
import time
from typing import Any

import numpy as np

from bearingload.models.pair_speed import solve_pair_high_speed
from tests.campaign_pair import random_case as pair_case
from tests.campaign_tools import attempt


def random_case(rng: np.random.Generator) -> dict[str, Any]:
    case = pair_case(rng)
    case["kw"].pop("stiffness", None)
    dm = case["kw"]["pitch_diameter"]
    top = 1e6 / dm
    case["kw"]["speed"] = float(top * (rng.uniform(0.8, 1.0) if rng.random() < 1 / 3
                                       else rng.uniform(0.0, 1.0)))  # fmt: skip
    if rng.random() < 0.2:
        case["kw"]["ball_density"] = 3200.0
    return case


def plain_shaft(case: dict[str, Any], r: Any) -> float:
    """The shaft's five forces summed from the returned inner contacts (math.fsum), against
    the applied ones, over the largest of the applied loads and the preload."""
    kw = case["kw"]
    kind, width = kw["arrangement"], kw["width"]
    first = -0.5 if kind in ("DB", "DT") else 0.5
    f = [0.0] * 5
    terms: list[list[float]] = [[] for _ in range(5)]
    for k, b in enumerate(r.bearings):
        zk, sigma = (first, 1.0) if k == 0 else (-first, 1.0 if kind == "DT" else -1.0)
        phi = np.radians(b.ball_angles)
        ai = np.radians(b.contact_angles_inner)
        fr = b.ball_loads_inner * np.cos(ai)
        fa = b.ball_loads_inner * np.sin(ai)
        lever = float(b.tilt_radius)
        terms[0] += (fr * np.cos(phi)).tolist()
        terms[1] += (fr * np.sin(phi)).tolist()
        terms[2] += (sigma * fa).tolist()
        terms[3] += (sigma * lever * fa * np.cos(phi) - zk * width * fr * np.cos(phi)).tolist()
        terms[4] += (sigma * lever * fa * np.sin(phi) - zk * width * fr * np.sin(phi)).tolist()
    applied = [case["fr"], 0.0, case["fa"], kw.get("moment", 0.0), kw.get("moment_cross", 0.0)]
    lever = float(r.bearings[0].tilt_radius)
    ref = max(case["fr"], abs(case["fa"]), math.hypot(applied[3], applied[4]) / lever,
              kw["preload"])  # fmt: skip
    for i in range(5):
        scale = lever if i >= 3 else 1.0
        f[i] = abs(math.fsum(terms[i]) - applied[i]) / scale
    return max(f) / ref


def ball_residual(r: Any, kw: dict[str, Any]) -> tuple[float, float]:
    """Each ball's axial and radial equations from the returned forces and angles: the largest
    over the sum of their terms' magnitudes, and the largest over the ball solver's tolerance
    (the core's ball_norm, bearingload/models/_core.pyx: 1e-13 of those magnitudes plus the rounding
    of its approaches, 16 eps times each contact's load times its length r' + delta over its
    approach delta: a light ball's approach is a difference of lengths near r')."""
    dw = kw["ball_diameter"]
    ri, ro = (kw.get("f_i", 0.52) - 0.5) * dw, (kw.get("f_o", 0.53) - 0.5) * dw
    plain = ratio = 0.0
    for b in r.bearings:
        ai, ao = np.radians(b.contact_angles_inner), np.radians(b.contact_angles_outer)
        qi, qo, fc = b.ball_loads_inner, b.ball_loads_outer, b.centrifugal_forces
        friction = 2.0 * b.gyroscopic_moments / dw
        g = np.hypot(
            qi * np.sin(ai) - qo * np.sin(ao) + friction * np.cos(ao),
            qi * np.cos(ai) - qo * np.cos(ao) - friction * np.sin(ao) + fc,
        )
        di, do = np.abs(b.approaches_inner), np.abs(b.approaches_outer)
        with np.errstate(all="ignore"):
            extra = np.nan_to_num(qi * (di + ri) / di) + np.nan_to_num(qo * (do + ro) / do)
        size = qi + qo + np.abs(fc) + np.abs(friction)
        plain = max(plain, float(np.max(g / np.where(size > 0, size, 1.0))))
        tol = 1e-13 * size + 16 * 2.220446e-16 * extra
        ratio = max(ratio, float(np.max(g / np.where(tol > 0, tol, 1.0))))
    return plain, ratio


def main(n: int, seed: int) -> None:
    rng = np.random.default_rng(seed)
    counts = dict.fromkeys(("solved", "refused", "ConvergenceError", "NaN", "negative load",
                            "above 1e-12"), 0)  # fmt: skip
    refused: dict[str, int] = {}
    worst = {"residual": 0.0, "plain": 0.0, "ball": 0.0, "ball tolerance": 0.0}
    worst_case, slowest = None, (0.0, None)
    start = time.perf_counter()
    for _ in range(n):
        case = random_case(rng)
        t0 = time.perf_counter()
        r = attempt(solve_pair_high_speed, case, counts, refused)
        if r is None:
            continue
        took = time.perf_counter() - t0
        if took > slowest[0]:
            slowest = (took, case)
        arrays = [r.x, r.axial, r.tilt, r.residual, r.stiffness_matrix]
        for b in r.bearings:
            arrays += [b.ball_loads_inner, b.ball_loads_outer, b.contact_angles_inner,
                       b.contact_angles_outer]  # fmt: skip
        if not all(np.all(np.isfinite(a)) for a in arrays):
            counts["NaN"] += 1
            print("NaN:", case)
            continue
        counts["solved"] += 1
        counts["negative load"] += int(any((b.ball_loads_inner < 0).any() for b in r.bearings))
        counts["above 1e-12"] += int(r.residual > 1e-12)
        if r.residual > worst["residual"]:
            worst["residual"], worst_case = float(r.residual), case
        worst["plain"] = max(worst["plain"], plain_shaft(case, r))
        plain, ratio = ball_residual(r, case["kw"])
        worst["ball"] = max(worst["ball"], plain)
        worst["ball tolerance"] = max(worst["ball tolerance"], ratio)
    took = time.perf_counter() - start
    print(f"{n} cases, seed {seed}, {took:.1f} s: {counts}; refused by parameter {refused}")
    print(f"largest shaft residual (solver's measure) {worst['residual']:.3g}; plain sum "
          f"{worst['plain']:.3g}; ball equations {worst['ball']:.3g} of their forces, "
          f"{worst['ball tolerance']:.3g} times the ball solver's tolerance")  # fmt: skip
    print(f"worst case {worst_case}; slowest {slowest[0]:.2f} s: {slowest[1]}")


if __name__ == "__main__":
    main(
        int(sys.argv[1]) if len(sys.argv) > 1 else 300,
        int(sys.argv[2]) if len(sys.argv) > 2 else 1,
    )
