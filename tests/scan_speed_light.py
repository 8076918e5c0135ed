"""Grid scan of the ball dynamics (bearingload.models.high_speed) at small and near-symmetric
loads (not part of the test suite).

Run: ``.venv/bin/python -m tests.scan_speed_light [grid|zero]``.

* ``grid`` (default): 9 balls of 7.938 mm on 38.5 mm, deep groove (clearance 0) and angular
  contact at 15° and 40°; F_r in {1e-6, 1e-3, 1, 100} N; F_a in {0, 1e-6, 1e-4, 1e-2} N (and
  F_r 0 with F_a 1e-6 or 1 N); the cage at 0, 1e-12° and half a pitch; the speed 1000, 30 000
  and 50 000 rpm: 3 * 18 * 3 * 3 = 486 cases.
* ``zero``: the same loads, cages and bearings at speed 0, each against the static solver
  (solve_combined): a case the static solver answers must be answered, with the static answer.

Printed: cases, solved, refused (by reason), ConvergenceError, other errors, NaN or negative
loads; each failure with its inputs.
"""

from __future__ import annotations

import sys
import time
import warnings
from typing import Any

import numpy as np

from bearingload.errors import ConvergenceError, InputError
from bearingload.models.combined import solve_combined
from bearingload.models.high_speed import solve_high_speed

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


def main(mode: str) -> None:
    grid = cases((0.0,) if mode == "zero" else (1000.0, 30000.0, 50000.0))
    counts = dict.fromkeys(("solved", "refused", "ConvergenceError", "other", "NaN/negative",
                            "static differs"), 0)  # fmt: skip
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
    main(sys.argv[1] if len(sys.argv) > 1 else "grid")
