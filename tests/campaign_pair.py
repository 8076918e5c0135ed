"""Random campaign of the bearing-pair solver (a sibling of tests/campaign_angular.py, not part
of the test suite).

Run: ``.venv/bin/python -m tests.campaign_pair [cases] [seed]`` (default 10 000 cases, seed 1).
Each case alone: z 3..40, the four ball sets of the deep-groove campaign (the pitch circle widened
where z balls would overlap, as there), a design contact angle
10 to 45°, DB, DF or DT; F_r 0 or 10 N to C_0r, F_a 10 N to C_0r either way (DT: > 0), a preload
(DB, DF; one in five none) from 1e-3 to 1 times C_0r/10 (light preload to lift-off), one in
three a moment and one in six a moment across, up to F_a d_m/10; the cage at 0, half a pitch or
anywhere; Hertz K (one in four a constant K); the width 0.3 to 0.6 d_m.

Printed: solved, refused (by parameter), ConvergenceError, NaN, negative loads, unloaded
bearings, the largest residual of the pair's equilibrium (the solver's measure: over the applied
load or the rounding of its terms) and of an independent plain sum of the returned ball loads
and angles of the axial force, over max(|F_a|, F_p).
"""

from __future__ import annotations

import math
import sys
import time
from typing import Any

import numpy as np

from bearingload.models.pair import solve_pair
from tests.campaign_angular import static_rating
from tests.campaign_combined import BALL_SETS, fitting_pitch
from tests.campaign_tools import attempt


def random_case(rng: np.random.Generator) -> dict[str, Any]:
    dw, dm = BALL_SETS[int(rng.integers(len(BALL_SETS)))]
    z = int(rng.integers(3, 41))
    dm = fitting_pitch(z, dw, dm)
    alpha = float(rng.uniform(10.0, 45.0))
    kind = str(rng.choice(["DB", "DF", "DT"]))
    c0 = static_rating(z, dw, dm, alpha)
    fr = 0.0 if rng.random() < 0.2 else float(10 ** rng.uniform(1.0, math.log10(c0)))
    fa = float(10 ** rng.uniform(1.0, math.log10(c0)))
    if kind != "DT" and rng.random() < 0.5:
        fa = -fa
    fp = 0.0
    if kind != "DT" and rng.random() < 0.8:
        fp = float(c0 / 10 * 10 ** rng.uniform(-3, 0))
    kw: dict[str, Any] = dict(arrangement=kind, preload=fp, contact_angle=alpha,
                              ball_diameter=dw, pitch_diameter=dm,
                              width=float(dm * rng.uniform(0.3, 0.6)))  # fmt: skip
    if rng.random() < 1 / 3:
        kw["moment"] = float(rng.choice([-1, 1]) * abs(fa) * dm * 10 ** rng.uniform(-4, -1))
    if rng.random() < 1 / 6:
        kw["moment_cross"] = float(rng.choice([-1, 1]) * abs(fa) * dm * 10 ** rng.uniform(-4, -1))
    kw["cage_angle"] = float(rng.choice([0.0, 180.0 / z, rng.uniform(0, 360)]))
    if rng.random() < 0.25:
        kw["stiffness"] = float(10 ** rng.uniform(5, 6))
    return {"z": z, "fr": fr, "fa": fa, "kw": kw}


def plain_axial(case: dict[str, Any], r: Any) -> float:
    """|sum of the bearings' thrusts - F_a| beyond its rounding, over max(|F_a|, F_p)."""
    sign = (1.0, -1.0 if case["kw"]["arrangement"] != "DT" else 1.0)
    terms: list[float] = []
    for s, b in zip(sign, r.bearings, strict=True):
        terms += (s * b.ball_loads * np.sin(np.radians(b.contact_angles))).tolist()
    err = abs(math.fsum(terms) - case["fa"]) - 4.4e-16 * sum(abs(t) for t in terms)
    return max(err, 0.0) / max(abs(case["fa"]), case["kw"]["preload"])


def main(n: int, seed: int) -> None:
    rng = np.random.default_rng(seed)
    counts = dict.fromkeys(("solved", "refused", "ConvergenceError", "NaN", "negative load",
                            "one bearing unloaded"), 0)  # fmt: skip
    refused: dict[str, int] = {}
    worst_res, worst_plain, worst_case = 0.0, 0.0, None
    start = time.perf_counter()
    for _ in range(n):
        case = random_case(rng)
        r = attempt(solve_pair, case, counts, refused)
        if r is None:
            continue
        arrays = [r.x, r.axial, r.tilt, r.residual, r.stiffness_matrix]
        arrays += [b.ball_loads for b in r.bearings] + [b.contact_angles for b in r.bearings]
        if not all(np.all(np.isfinite(a)) for a in arrays):
            counts["NaN"] += 1
            print("NaN:", case)
            continue
        counts["solved"] += 1
        counts["negative load"] += int(any((b.ball_loads < 0).any() for b in r.bearings))
        counts["one bearing unloaded"] += int(r.unloaded.any())
        if r.residual > worst_res:
            worst_res, worst_case = float(r.residual), case
        worst_plain = max(worst_plain, plain_axial(case, r))
    took = time.perf_counter() - start
    print(f"{n} cases, seed {seed}, {took:.1f} s: {counts}; refused by parameter {refused}")
    print(f"largest residual (solver's measure) {worst_res:.3g}; plain sum of the thrusts "
          f"{worst_plain:.3g}; worst case {worst_case}")  # fmt: skip


if __name__ == "__main__":
    main(
        int(sys.argv[1]) if len(sys.argv) > 1 else 10_000,
        int(sys.argv[2]) if len(sys.argv) > 2 else 1,
    )
