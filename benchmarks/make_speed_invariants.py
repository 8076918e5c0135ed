"""Write tests/fixtures/high_speed_invariants.json: the ball dynamics' answers on a random set of
well-conditioned cases (:mod:`bearingload.models.high_speed`), stored so that a change meant to
leave the numbers alone (a speed-up) is checked against them (tests/test_high_speed_invariants.py,
1e-12 relative) rather than against the old code.

Run: ``.venv/bin/python benchmarks/make_speed_invariants.py`` (seed 20261128). The cases: 7205-
sized angular contact (13 balls, 10-45°) and 6205-sized deep groove (9 balls, clearance 0-20 µm),
F_r and F_a 50-5000 N, 1000-40 000 rpm (n d_m <= 1.5e6 mm/min), cage at 0 or anywhere; each
solved alone, and the set solved again as one array (the same numbers: no case depends on the
others). Stored: x, axial, tilt [mm, °] and every ball's Q_i, Q_o [N], alpha_i, alpha_o [°].
"""

from __future__ import annotations

import json
import pathlib
import sys

import numpy as np

from bearingload.models.high_speed import solve_high_speed

SEED, N = 20261128, 24
OUT = (
    pathlib.Path(__file__).resolve().parents[1]
    / "tests"
    / "fixtures"
    / "high_speed_invariants.json"
)
KEYS = ("x", "axial", "tilt", "ball_loads_inner", "ball_loads_outer", "contact_angles_inner",
        "contact_angles_outer")  # fmt: skip


def cases() -> list[dict]:
    rng = np.random.default_rng(SEED)
    out = []
    for k in range(N):
        angular = k % 2 == 0
        z, dw, dm = (13, 7.938, 38.5) if angular else (9, 7.938, 38.5)
        kw: dict = dict(ball_diameter=dw, pitch_diameter=dm)
        if angular:
            kw["contact_angle"] = float(rng.uniform(10.0, 45.0))
        else:
            kw["clearance"] = float(rng.uniform(0.0, 0.02))
        kw["speed"] = float(rng.uniform(1000.0, 1.5e6 / dm))
        kw["cage_angle"] = float(rng.choice([0.0, rng.uniform(0.0, 360.0)]))
        out.append({"z": z, "fr": float(rng.uniform(50.0, 5000.0)),
                    "fa": float(rng.uniform(50.0, 5000.0)), "kw": kw})  # fmt: skip
    return out


def main() -> None:
    rows = []
    for case in cases():
        r = solve_high_speed(case["z"], case["fr"], case["fa"], **case["kw"])
        rows.append(dict(case, **{k: np.ravel(getattr(r, k)).tolist() for k in KEYS}))
    OUT.write_text(json.dumps({"seed": SEED, "cases": rows}, indent=1) + "\n")
    print(f"wrote {len(rows)} cases to {OUT}", file=sys.stderr)


if __name__ == "__main__":
    main()
