"""Random campaign of the ball dynamics at speed (bearingload.models.high_speed), a sibling of
tests/campaign_pair.py, run by hand, not part of the test suite.

Run: ``.venv/bin/python -m tests.campaign_speed [cases] [seed]`` (default 1000 cases, seed 1).
Each case alone: half deep groove, half angular contact (design angle 10 to 45°); the four ball
sets of the combined campaign with z from 3 to as many as fit (z D_w <= 0.95 pi d_m, at most
40); F_r 0 (one in five) or 1 N to C_0r, F_a 0 (deep groove, one in five) or 1 N to C_0r
(either way on a deep-groove bearing); deep groove: a clearance from 30 µm of preload to 2A (a
fifth of them preloaded, a fifth at 0); one in four a moment up to F d_m/10, one in eight a
misalignment up to 0.1°; the cage at 0, half a pitch or anywhere; the speed 0 (one in ten) or
up to the n d_m limit (a third of the cases in its top fifth); one in five silicon nitride balls.

Printed: solved, refused (by parameter), ConvergenceError, NaN, negative loads, balls touching
the inner ring at 90° or beyond; the worst ring residual (an independent plain sum of the
returned inner loads and angles against each applied component, over the largest applied load:
the solver's own measure), the same over the components whose terms stay under 10^3 times the
load (tests/campaign_combined.py's criterion) and how many components lie above 1e-12 with the
least ratio of their terms to the load and the worst ball residual (each ball's two equations from the
returned Q_i, Q_o, angles, F_c and M_g over the sum of their magnitudes); the total time, the
slowest case and the most ring iterations.
"""

from __future__ import annotations

import math
import sys
import time
from typing import Any

import numpy as np

from bearingload.models.high_speed import MAX_SPEED_PITCH, solve_high_speed
from tests.campaign_angular import static_rating
from tests.campaign_combined import BALL_SETS
from tests.campaign_tools import attempt


def random_case(rng: np.random.Generator) -> dict[str, Any]:
    dw, dm = BALL_SETS[int(rng.integers(len(BALL_SETS)))]
    z = int(rng.integers(3, min(40, int(0.95 * math.pi * dm / dw)) + 1))
    angular = bool(rng.random() < 0.5)
    alpha = float(rng.uniform(10.0, 45.0)) if angular else 0.0
    c0 = static_rating(z, dw, dm, alpha)
    fr = 0.0 if rng.random() < 0.2 else float(10 ** rng.uniform(0.0, math.log10(c0)))
    fa = float(10 ** rng.uniform(0.0, math.log10(c0)))
    kw: dict[str, Any] = dict(ball_diameter=dw, pitch_diameter=dm)
    if angular:
        kw["contact_angle"] = alpha
    else:
        fa *= 0.0 if rng.random() < 0.2 else float(rng.choice([-1.0, 1.0]))
        u = rng.random()
        big_a = 0.05 * dw
        kw["clearance"] = (-rng.uniform(0.0, 0.03) if u < 0.2 else 0.0 if u < 0.4
                           else float(rng.uniform(0.0, 2.0 * big_a)))  # fmt: skip
    if fr == 0.0 and fa == 0.0:
        fr = float(10 ** rng.uniform(0.0, math.log10(c0)))
    if rng.random() < 0.25:
        load = max(fr, abs(fa))
        kw["moment"] = float(rng.choice([-1, 1]) * load * dm * 10 ** rng.uniform(-4, -1))
    elif rng.random() < 1 / 7:
        kw["misalignment"] = float(rng.uniform(-0.1, 0.1))
    kw["cage_angle"] = float(rng.choice([0.0, 180.0 / z, rng.uniform(0, 360)]))
    top = MAX_SPEED_PITCH / dm
    v = rng.random()
    kw["speed"] = (
        0.0 if v < 0.1 else float(top * (rng.uniform(0.8, 1.0) if v < 0.4 else rng.random()))
    )
    if rng.random() < 0.2:
        kw["ball_density"] = 3200.0
    return {"z": z, "fr": fr, "fa": fa, "kw": kw}


def ring_residual(case: dict[str, Any], r: Any, light: list[float] | None = None) -> float:
    """The largest |applied - plain sum of the inner contacts| over the largest applied load (the
    moment over the tilt lever; the moment not checked under a misalignment). ``light``: the
    campaign's tally of the static campaign's criterion (its worst residual over the components
    whose terms stay under 10^3 times the largest applied load, the count of components above
    1e-12 and the smallest ratio of terms to load among them)."""
    q, al, ph = r.ball_loads_inner, np.radians(r.contact_angles_inner), np.radians(r.ball_angles)
    lever = float(r.tilt_radius)
    terms = [q * np.cos(al) * np.cos(ph), q * np.cos(al) * np.sin(ph), q * np.sin(al),
             lever * q * np.sin(al) * np.cos(ph), lever * q * np.sin(al) * np.sin(ph)]  # fmt: skip
    kw = case["kw"]
    wanted = [case["fr"], 0.0, case["fa"], kw.get("moment", 0.0), kw.get("moment_cross", 0.0)]
    f_ref = max(case["fr"], abs(case["fa"]), abs(kw.get("moment", 0.0)) / lever)
    worst = 0.0
    for i, (t, w) in enumerate(zip(terms, wanted, strict=True)):
        if i >= 3 and "misalignment" in kw:
            continue
        scale = 1.0 if i < 3 else lever
        res = abs(math.fsum(t.tolist()) - w) / scale / f_ref
        worst = max(worst, res)
        ratio = float(np.sum(np.abs(t))) / scale / f_ref  # the terms' size over the load
        if light is not None and ratio <= 1e3:
            light[0] = max(light[0], res)
        if light is not None and res > 1e-12:
            light[1] += 1
            light[2] = min(light[2], ratio)
    return worst


def ball_residual(case: dict[str, Any], r: Any) -> float:
    """Each ball's two equations from the returned forces and angles, over their magnitudes."""
    qi, qo, fc = r.ball_loads_inner, r.ball_loads_outer, r.centrifugal_forces
    fr = 2.0 * r.gyroscopic_moments / case["kw"]["ball_diameter"]
    ai, ao = np.radians(r.contact_angles_inner), np.radians(r.contact_angles_outer)
    g1 = qi * np.sin(ai) - qo * np.sin(ao) + fr * np.cos(ao)
    g2 = qi * np.cos(ai) - qo * np.cos(ao) - fr * np.sin(ao) + fc
    size = qi + qo + np.abs(fc) + np.abs(fr)
    return float(np.max(np.hypot(g1, g2) / np.where(size > 0, size, 1.0)))


def main(n: int, seed: int) -> None:
    rng = np.random.default_rng(seed)
    counts = dict.fromkeys(("solved", "refused", "ConvergenceError", "crash", "NaN", "negative load",
                            "inner contact at 90 deg or beyond"), 0)  # fmt: skip
    refused: dict[str, int] = {}
    worst_ring, worst_ball, slowest, most = 0.0, 0.0, (0.0, None), (0, None)
    worst_case: Any = None
    worst_ball_case: Any = None
    light = [0.0, 0, math.inf]  # (worst under 10^3, count above 1e-12, their least ratio)
    start = time.perf_counter()
    for _ in range(n):
        case = random_case(rng)
        t0 = time.perf_counter()
        r = attempt(solve_high_speed, case, counts, refused)
        if r is None:
            continue
        took = time.perf_counter() - t0
        arrays = [r.x, r.axial, r.tilt, r.ball_loads_inner, r.ball_loads_outer,
                  r.contact_angles_inner, r.contact_angles_outer, r.stiffness_matrix]  # fmt: skip
        if not all(np.all(np.isfinite(a)) for a in arrays):
            counts["NaN"] += 1
            print("NaN:", case)
            continue
        counts["solved"] += 1
        counts["negative load"] += int(
            (r.ball_loads_inner < 0).any() or (r.ball_loads_outer < 0).any()
        )
        touching = r.ball_loads_inner > 0
        counts["inner contact at 90 deg or beyond"] += int(
            np.any(np.abs(r.contact_angles_inner[touching]) >= 90.0)
        )
        ring = ring_residual(case, r, light)
        if ring > worst_ring:
            worst_ring, worst_case = ring, case
        if ball_residual(case, r) > worst_ball:
            worst_ball, worst_ball_case = ball_residual(case, r), case
        if took > slowest[0]:
            slowest = (took, case)
        its = int(r.iterations)
        if its > most[0]:
            most = (its, case)
    total = time.perf_counter() - start
    print(f"{n} cases, seed {seed}, {total:.1f} s ({total / n * 1e3:.1f} ms a case): {counts}; "
          f"refused by parameter {refused}")  # fmt: skip
    print(f"worst ring residual (plain sum, over the largest applied load) {worst_ring:.3g}: "
          f"{worst_case}")  # fmt: skip
    print(f"components whose terms stay under 10^3 times the load: worst residual "
          f"{light[0]:.3g}; components above 1e-12: {light[1]}, their terms at least "
          f"{light[2]:.3g} times the load")  # fmt: skip
    print(f"worst ball residual (over its force magnitudes) {worst_ball:.3g}: {worst_ball_case}")
    print(f"slowest case {slowest[0] * 1e3:.0f} ms: {slowest[1]}")
    print(f"most iterations (static + ring) {most[0]}: {most[1]}")


if __name__ == "__main__":
    main(
        int(sys.argv[1]) if len(sys.argv) > 1 else 1000,
        int(sys.argv[2]) if len(sys.argv) > 2 else 1,
    )
