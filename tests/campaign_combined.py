"""Random campaign of the combined solver (not part of the test suite; a seeded 300-case version
is tests/test_combined_seams.py::test_random_campaign).

Run: ``.venv/bin/python -m tests.campaign_combined [cases] [seed]`` (default 10 000 cases, seed
1). Each case is solved alone: z 3..40, four ball sets (D_w 3 to 23.8 mm; d_m raised where z
balls would overlap), loads from the
smallest the solver accepts to 10^6 N, axial loads down to 1e-9 of the load, clearances from
30 um of preload to the groove limit 2A (a fifth within 1e-6..1 of it), free tilt, a moment
either way, a misalignment of 0 or up to 0.2°, a moment across the load line (one in five), the
cage at 0, half a pitch or anywhere.

Printed: how many cases were solved, refused (by reason), failed to converge, gave NaN or a
loaded ball at 90° or beyond; for every applied component, the largest residual over the applied
value as the solver evaluates it at the answer (forces summed from the preloaded reference), and
as a plain independent sum of the returned ball loads and angles beyond that sum's own rounding.
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
from bearingload.models.combined import GEOMETRY_RATIO_MAX, ball_stiffness_at, solve_combined
from tests.campaign_tools import spy_forces

BALL_SETS = [(7.938, 38.5), (11.5, 43.5), (23.812, 102.5), (3.0, 14.0)]
NAMES = ("F_r", "F_y", "F_a", "M", "M_c")


def fitting_pitch(z: int, dw: float, dm: float) -> float:
    """d_m, or where z balls of D_w overlap on it the smallest pitch circle (to 0.1 %) they fit
    on, D_w <= d_m sin(180°/z) (the solver refuses overlapping balls). [mm]"""
    return max(dm, 1.001 * dw / math.sin(math.pi / z))


def random_case(rng: np.random.Generator) -> dict[str, Any]:
    dw, dm = BALL_SETS[int(rng.integers(len(BALL_SETS)))]
    z = int(rng.integers(3, 41))
    dm = fitting_pitch(z, dw, dm)
    big_a = 0.05 * dw
    f_min = float(ball_stiffness_at(0.0, dw, dm, 0.52, 0.53)) * (big_a / GEOMETRY_RATIO_MAX) ** 1.5
    scale = 10 ** rng.uniform(math.log10(f_min), 6)
    fr = float(rng.choice([0.0, scale * 10 ** rng.uniform(-3, 0)]))
    fa = float(rng.choice([0.0, 1.0, -1.0])) * scale * 10 ** rng.uniform(-9, 0)
    if fr == 0 and fa == 0:
        fa = scale
    u = rng.random()
    if u < 0.3:
        g = -rng.uniform(0, 0.03)
    elif u < 0.5:
        g = 2 * big_a * (1 - 10 ** rng.uniform(-6, 0))
    else:
        g = rng.uniform(0, 2 * big_a)
    kind = int(rng.integers(4))
    tilt: dict[str, float] = [
        {},
        {"moment": float(rng.choice([-1, 1]) * scale * dm * 10 ** rng.uniform(-6, 0))},
        {"misalignment": 0.0},
        {"misalignment": float(rng.uniform(-0.2, 0.2))},
    ][kind]
    if rng.random() < 0.2:
        tilt["moment_cross"] = float(rng.choice([-1, 1]) * scale * dm * 10 ** rng.uniform(-6, 0))
    cage = float(rng.choice([0.0, 180.0 / z, rng.uniform(0, 360)]))
    return {"z": z, "fr": fr, "fa": fa, "g": float(g), "cage": cage, "dw": dw, "dm": dm, **tilt}


def plain_excess(case: dict[str, Any], r: Any) -> list[float]:
    """|sum - applied| beyond 4 eps of the sum of the terms' magnitudes, over |applied|."""
    q, al, ph = r.ball_loads, np.radians(r.contact_angles), np.radians(r.ball_angles)
    arm = case["dm"] / 2 + 0.02 * case["dw"] * math.cos(math.radians(float(r.free_contact_angle)))
    terms = [q * np.cos(al) * np.cos(ph), q * np.cos(al) * np.sin(ph), q * np.sin(al),
             arm * q * np.sin(al) * np.cos(ph), arm * q * np.sin(al) * np.sin(ph)]  # fmt: skip
    wanted = [case["fr"], 0.0, case["fa"], case.get("moment"), case.get("moment_cross", 0.0)]
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
    counts = dict.fromkeys(("solved", "refused: 90 degrees", "refused: load too small",
                            "refused: other", "ConvergenceError", "NaN", "loaded ball at 90 deg or more"), 0)  # fmt: skip
    own = [0.0] * 5  # solver's residual over the applied value
    own_terms = [0.0] * 5  # over max(applied, sum of the terms' magnitudes)
    dominated = [0] * 5  # applied components whose terms exceed 1e3 times them
    plain = [0.0] * 5
    worst: list[Any] = [None] * 5
    worst_plain: list[Any] = [None] * 5
    started = time.perf_counter()
    for _ in range(n):
        case = random_case(rng)
        kw = {k: case[k] for k in ("moment", "misalignment", "moment_cross") if k in case}
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                r = solve_combined(case["z"], case["fr"], case["fa"], clearance=case["g"],
                                   cage_angle=case["cage"], ball_diameter=case["dw"],
                                   pitch_diameter=case["dm"], **kw)  # fmt: skip
        except InputError as exc:
            text = str(exc)
            key = ("refused: 90 degrees" if "contact angle of 90" in text else
                   "refused: load too small" if "too small" in text else "refused: other")  # fmt: skip
            counts[key] += 1
            if key == "refused: other":
                print("refused:", case, text[:160])
            continue
        except ConvergenceError as exc:
            counts["ConvergenceError"] += 1
            print("no convergence:", case, str(exc)[:160])
            continue
        counts["solved"] += 1
        if not (np.all(np.isfinite(r.ball_loads)) and np.all(np.isfinite(r.contact_angles))):
            counts["NaN"] += 1
        if np.any(np.abs(r.contact_angles[r.ball_loads > 0]) >= 90.0):
            counts["loaded ball at 90 deg or more"] += 1
        gen, f, size = seen["gen"], seen["f"], seen["size"]
        for i in range(5):
            if f[i] == 0 or seen["imposed"][i]:
                continue
            rel = abs(gen[i] - f[i]) / abs(f[i])
            if size[i] > 1e3 * abs(f[i]):
                dominated[i] += 1
            elif rel > own[i]:
                own[i], worst[i] = rel, case
            own_terms[i] = max(own_terms[i], abs(gen[i] - f[i]) / max(abs(f[i]), size[i]))
        for i, value in enumerate(plain_excess(case, r)):
            if f[i] != 0 and size[i] <= 1e3 * abs(f[i]) and value > plain[i]:
                plain[i], worst_plain[i] = value, case
    print(json.dumps(counts), f"({time.perf_counter() - started:.0f} s)")
    for i, name in enumerate(NAMES):
        if name == "F_y":
            continue
        print(
            f"{name}: over the applied value, solver's residual <= {own[i]:.2e}, plain sum "
            f"beyond its rounding <= {plain[i]:.2e} (cases whose terms are less than 1e3 times "
            f"the applied value; {dominated[i]} are not); solver's residual over max(applied, "
            f"terms) <= {own_terms[i]:.2e}"
        )
        if worst[i]:
            print("   worst:", worst[i])
        if worst_plain[i]:
            print("   worst plain:", worst_plain[i])


if __name__ == "__main__":
    main(
        int(sys.argv[1]) if len(sys.argv) > 1 else 10_000,
        int(sys.argv[2]) if len(sys.argv) > 2 else 1,
    )
