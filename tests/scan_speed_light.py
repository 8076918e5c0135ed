"""Grid scan of the ball dynamics (bearingload.models.high_speed) at small and near-symmetric
loads (not part of the test suite).

Run: ``.venv/bin/python -m tests.scan_speed_light [grid|zero]``.

* ``grid`` (default): 9 balls of 7.938 mm on 38.5 mm, deep groove (clearance 0) and angular
  contact at 15° and 40°; F_r in {1e-6, 1e-3, 1, 100} N; F_a in {0, 1e-6, 1e-4, 1e-2} N (and
  F_r 0 with F_a 1e-6 or 1 N); the cage at 0, 1e-12° and half a pitch; the speed 1000, 30 000
  and 50 000 rpm: 3 * 18 * 3 * 3 = 486 cases.
* ``zero``: the same loads, cages and bearings at speed 0, each against the static solver
  (solve_combined): a case the static solver answers must be answered, with the static answer.
* ``wide`` (cases seeds 1 to n, default 1000): the four ball sets of tests/campaign_combined.py,
  z 3 to 20 (as many as fit), deep groove (G_r 0, 10 µm or -5 µm) or angular contact (10 to
  45°); F_r 1e-6 to 100 N (log-uniform), F_a 0 or F_r 1e-6 to 1e-2; the cage at 0, 1e-12°,
  half a pitch or half a pitch plus 1e-12°; the speed in the top half of the n d_m limit.

Printed: cases, solved, refused (by reason), ConvergenceError, other errors, NaN or negative
loads; each failure with its inputs.
"""

from __future__ import annotations

import math
import sys
import time
import warnings
from typing import Any

import numpy as np

from bearingload.errors import ConvergenceError, InputError
from bearingload.models.combined import solve_combined
from bearingload.models.high_speed import MAX_SPEED_PITCH, solve_high_speed
from tests.campaign_combined import BALL_SETS

BEARING = {"ball_diameter": 7.938, "pitch_diameter": 38.5}
LOADS = [(float(fr), fa) for fr in np.logspace(-6, 3, 10) for fa in (0.0, 1e-6, 1e-4, 1e-2, 1.0)]
LOADS += [(0.0, 1e-6), (0.0, 1.0)]


def cases(speeds: tuple[float, ...]) -> list[dict[str, Any]]:
    out = []
    for alpha in (None, 15.0, 25.0, 40.0):
        for fr, fa in LOADS:
            for cage in (0.0, 1e-12, 20.0):
                for n in speeds:
                    kw: dict[str, Any] = dict(BEARING, cage_angle=cage)
                    if alpha is not None:
                        kw["contact_angle"] = alpha
                    out.append({"z": 9, "fr": fr, "fa": fa, "speed": n, "kw": kw})
    return out


def wide_case(rng: np.random.Generator) -> dict[str, Any]:
    dw, dm = BALL_SETS[int(rng.integers(len(BALL_SETS)))]
    z = int(rng.integers(3, min(20, int(0.95 * math.pi * dm / dw)) + 1))
    kw: dict[str, Any] = {"ball_diameter": dw, "pitch_diameter": dm}
    if rng.random() < 0.5:
        kw["contact_angle"] = float(rng.uniform(10.0, 45.0))
    else:
        kw["clearance"] = float(rng.choice([0.0, 0.01, -0.005]))
    fr = float(10 ** rng.uniform(-6.0, 2.0))
    fa = 0.0 if rng.random() < 0.3 else fr * float(10 ** rng.uniform(-6.0, -2.0))
    half = 180.0 / z
    kw["cage_angle"] = float(rng.choice([0.0, 1e-12, half, half + 1e-12]))
    speed = MAX_SPEED_PITCH / dm * float(rng.uniform(0.5, 1.0))
    return {"z": z, "fr": fr, "fa": fa, "speed": speed, "kw": kw}


def main(mode: str, n: int) -> None:
    if mode == "wide":
        grid = [wide_case(np.random.default_rng(1 + i)) for i in range(n)]
    else:
        grid = cases((0.0,) if mode == "zero" else (1000.0, 30000.0, 50000.0))
    counts = dict.fromkeys(
        ("solved", "refused", "ConvergenceError", "other", "NaN/negative", "static differs"), 0
    )
    started = time.perf_counter()
    for c in grid:
        static = None
        if mode == "zero":
            try:
                static = solve_combined(c["z"], c["fr"], c["fa"], **c["kw"])
            except InputError:
                pass
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                r = solve_high_speed(c["z"], c["fr"], c["fa"], speed=c["speed"], **c["kw"])
        except InputError as err:
            counts["refused"] += 1
            if static is not None:
                print("refused, static answered:", c, str(err)[:160])
            continue
        except ConvergenceError as err:
            counts["ConvergenceError"] += 1
            print("ConvergenceError:", c, str(err)[:120])
            continue
        except Exception as err:  # a scan counts every failure
            counts["other"] += 1
            print("other:", c, repr(err)[:160])
            continue
        counts["solved"] += 1
        q = np.asarray(r.ball_loads_inner)
        if not np.all(np.isfinite(q)) or np.any(q < 0):
            counts["NaN/negative"] += 1
        if static is not None and not np.allclose(
            static.ball_loads, q, rtol=0.0, atol=1e-6 * float(np.max(q))
        ):
            counts["static differs"] += 1
            print("static differs:", c)
    print(f"{mode}: {len(grid)} cases", counts, f"({time.perf_counter() - started:.0f} s)")


if __name__ == "__main__":
    main(
        sys.argv[1] if len(sys.argv) > 1 else "grid",
        int(sys.argv[2]) if len(sys.argv) > 2 else 1000,
    )
