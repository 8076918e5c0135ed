"""Grid scan of the ball dynamics (bearingload.models.high_speed) of a 7205B under a radial load
with a thrust tiny against it (not part of the test suite).

Run: ``.venv/bin/python -m tests.scan_speed_thrust [-v]`` (-v: each undetermined case too).

The 7205B as the catalogue gives it (12 balls of 8.7312 mm on 38.5 mm, 40°; f_i 0.52, f_o 0.53,
E 208 GPa); F_r 20 to 3000 N (8 values, geometrically); F_a/F_r 1e-10 to 1e-3 (a decade apart)
and 0; the cage at 0, 1e-9°, 7°, 15° (half a pitch) and 22°; 1000 to 20 000 rpm (5 values,
geometrically): 8 * 9 * 5 * 5 = 1800 cases.

Printed: cases, solved, ConvergenceError, other errors, NaN, answers flagged undetermined; each
failure with its inputs; and the continuity in the thrust: over each (F_r, cage, speed), the
spread of the tilt [°] and of the axial displacement [µm] over the thrusts 1e-10 to 1e-6 of
F_r (the limit of a vanishing thrust: F_a 0 apart, where the ring is free to tilt).
"""

from __future__ import annotations

import sys
import time
import warnings
from typing import Any

import numpy as np

from bearingload.errors import ConvergenceError
from bearingload.models.high_speed import solve_high_speed
from tests.bearings_data import B7205B

RADIAL = [float(f) for f in np.geomspace(20.0, 3000.0, 8)]
RATIOS = [0.0] + [10.0**k for k in range(-10, -2)]
CAGES = [0.0, 1e-9, 1e-6, 1e-3, 7.0, 15.0, 22.0]
SPEEDS = [float(n) for n in np.geomspace(1000.0, 20000.0, 5)]
#: The thrusts (over F_r) whose answers should agree: the limit of a vanishing thrust. [-]
TINY = 1e-6


def solve_row(fr: float, cage: float, n: float, counts: dict[str, int]) -> list[Any]:
    """The (tilt [°], axial [µm]) of each thrust of RATIOS (None: failed), counted."""
    row: list[Any] = []
    for ratio in RATIOS:
        counts["cases"] += 1
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                r = solve_high_speed(12, fr, ratio * fr, speed=n, cage_angle=cage, **B7205B)
        except ConvergenceError as err:
            counts["ConvergenceError"] += 1
            print("ConvergenceError:", fr, ratio * fr, cage, n, err)
            row.append(None)
            continue
        except Exception as err:  # the scan counts every failure
            counts["other"] += 1
            print("error:", fr, ratio * fr, cage, n, repr(err))
            row.append(None)
            continue
        if not all(np.isfinite(a).all() for a in (r.x, r.axial, r.tilt, r.ball_loads)):
            counts["NaN"] += 1
        counts["solved"] += 1
        if r.displacement_undetermined:
            counts["undetermined"] += 1
            if "-v" in sys.argv:
                print("undetermined:", fr, ratio * fr, cage, n)
        row.append((float(r.tilt), float(r.axial) * 1e3))
    return row


def main() -> None:
    counts = dict.fromkeys(("cases", "solved", "ConvergenceError", "other", "NaN"), 0)
    counts["undetermined"] = 0
    spread, where = [0.0, 0.0], None
    start = time.perf_counter()
    for fr in RADIAL:
        for cage in CAGES:
            for n in SPEEDS:
                row = solve_row(fr, cage, n, counts)
                tiny = [x for x, ratio in zip(row, RATIOS, strict=True) if 0 < ratio <= TINY]
                if any(x is None for x in tiny):
                    continue
                tilts, axials = np.array(tiny).T
                if np.ptp(tilts) > spread[0]:
                    spread[0], where = float(np.ptp(tilts)), (fr, cage, n)
                spread[1] = max(spread[1], float(np.ptp(axials)))
    took = time.perf_counter() - start
    print(f"{counts} in {took:.1f} s")
    print(
        f"thrusts of 1e-10 to {TINY:.0e} of F_r, the largest spread over one (F_r, cage, n): "
        f"tilt {spread[0]:.3g}° (at F_r, cage, n = {where}), axial {spread[1]:.3g} µm"
    )


if __name__ == "__main__":
    main()
