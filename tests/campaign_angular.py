"""Random campaign of the combined solver on angular-contact ball bearings (a sibling
of tests/campaign_combined.py, not part of the test suite).

Run: ``.venv/bin/python -m tests.campaign_angular [cases] [seed]`` (default 10 000 cases, seed
1). Each case alone: z 3..40, the four ball sets of the deep-groove campaign (d_m raised where
z balls would overlap: the solver refuses them), a design contact angle 10 to 45°, F_r and F_a
each 10 N to C_0r (log-uniform; C_0r of ISO 76 for the ball set at that angle), the ring free to
tilt or (one in four) a moment either way up to 1e-2 F_a d_m, the cage at 0, half a pitch or
anywhere.

Printed: solved, refused (by reason), ConvergenceError, NaN; for F_r, F_a and M the largest
residual over the applied value as the solver evaluates it and as a plain independent sum of
the returned ball loads and angles (beyond that sum's own rounding); negative ball loads.
"""

from __future__ import annotations

import json
import math
import sys
import time
import warnings
from typing import Any

import numpy as np

from bearingload.errors import ConvergenceError, InputError
from bearingload.models.combined import solve_combined
from tests.campaign_combined import BALL_SETS, NAMES, fitting_pitch
from tests.campaign_tools import spy_forces


def static_rating(z: int, dw: float, dm: float, alpha: float) -> float:
    """ISO 76 C_0r = f_0 i z D_w^2 cos(alpha) with f_0 ~ 12.3 (a value for these sizes). [N]"""
    return 12.3 * z * dw * dw * math.cos(math.radians(alpha))


def random_case(rng: np.random.Generator) -> dict[str, Any]:
    dw, dm = BALL_SETS[int(rng.integers(len(BALL_SETS)))]
    z = int(rng.integers(3, 41))
    dm = fitting_pitch(z, dw, dm)
    alpha = float(rng.uniform(10.0, 45.0))
    c0 = static_rating(z, dw, dm, alpha)
    fr = float(10 ** rng.uniform(1.0, math.log10(c0)))
    fa = float(10 ** rng.uniform(1.0, math.log10(c0)))
    out: dict[str, Any] = {"z": z, "fr": fr, "fa": fa, "alpha": alpha, "dw": dw, "dm": dm}
    if rng.random() < 0.25:
        out["moment"] = float(rng.choice([-1, 1]) * fa * dm * 10 ** rng.uniform(-6, -2))
    out["cage"] = float(rng.choice([0.0, 180.0 / z, rng.uniform(0, 360)]))
    return out


def plain_excess(case: dict[str, Any], r: Any) -> list[float]:
    """|sum - applied| beyond 4 eps of the sum of the terms' magnitudes, over |applied|."""
    q, al, ph = r.ball_loads, np.radians(r.contact_angles), np.radians(r.ball_angles)
    arm = float(r.tilt_radius)
    terms = [q * np.cos(al) * np.cos(ph), q * np.sin(al), arm * q * np.sin(al) * np.cos(ph)]
    wanted = [case["fr"], case["fa"], case.get("moment", 0.0)]
    out = []
    for t, w in zip(terms, wanted, strict=True):
        if not w:
            out.append(0.0)
            continue
        err = abs(math.fsum(t.tolist()) - w) - 4.4e-16 * float(np.abs(t).sum())
        out.append(max(err, 0.0) / abs(w))
    return out


def main(n: int, seed: int) -> None:
    rng = np.random.default_rng(seed)
    seen: dict[str, Any] = {}
    spy_forces(seen)
    counts = dict.fromkeys(("solved", "refused", "ConvergenceError", "NaN", "negative load"), 0)
    own, plain, own_terms, dominated = [0.0] * 5, [0.0] * 3, [0.0] * 5, [0] * 5
    worst: list[Any] = [None] * 5
    started = time.perf_counter()
    for _ in range(n):
        case = random_case(rng)
        kw = {"moment": case["moment"]} if "moment" in case else {}
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                r = solve_combined(case["z"], case["fr"], case["fa"], contact_angle=case["alpha"],
                                   cage_angle=case["cage"], ball_diameter=case["dw"],
                                   pitch_diameter=case["dm"], **kw)  # fmt: skip
        except InputError as exc:
            counts["refused"] += 1
            print("refused:", case, str(exc)[:160])
            continue
        except ConvergenceError as exc:
            counts["ConvergenceError"] += 1
            print("no convergence:", case, str(exc)[:160])
            continue
        counts["solved"] += 1
        if not (np.all(np.isfinite(r.ball_loads)) and np.all(np.isfinite(r.contact_angles))):
            counts["NaN"] += 1
        counts["negative load"] += int(np.any(r.ball_loads < 0) or np.any(r.contact_angles < 0))
        gen, f, size = seen["gen"], seen["f"], seen["size"]
        for i in range(5):
            if f[i] == 0:
                continue
            rel = abs(gen[i] - f[i]) / abs(f[i])
            own_terms[i] = max(own_terms[i], abs(gen[i] - f[i]) / max(abs(f[i]), size[i]))
            if size[i] > 1e3 * abs(f[i]):  # its terms 1e3 times it: rounding of their sum
                dominated[i] += 1
            elif rel > own[i]:
                own[i], worst[i] = rel, case
        for i, value in zip((0, 2, 3), plain_excess(case, r), strict=True):
            if f[i] != 0 and size[i] <= 1e3 * abs(f[i]):
                plain[(0, 2, 3).index(i)] = max(plain[(0, 2, 3).index(i)], value)
    print(json.dumps(counts), f"({time.perf_counter() - started:.0f} s)")
    for i, name in enumerate(NAMES):
        if name in ("F_y", "M_c"):
            continue
        j = {"F_r": 0, "F_a": 1, "M": 2}[name]
        print(f"{name}: over the applied value, solver's residual <= {own[i]:.2e}, plain sum "
              f"beyond its rounding <= {plain[j]:.2e} (cases whose terms are less than 1e3 "
              f"times the applied value; {dominated[i]} are not); solver's residual over "
              f"max(applied, terms) <= {own_terms[i]:.2e}; worst: {worst[i]}")  # fmt: skip


if __name__ == "__main__":
    main(
        int(sys.argv[1]) if len(sys.argv) > 1 else 10_000,
        int(sys.argv[2]) if len(sys.argv) > 2 else 1,
    )
