"""Grid scan of the angular-contact solver at light loads (not part of the test suite).

Run: ``.venv/bin/python -m tests.scan_angular_light [base|wide|thrust] [cases]``.

* ``base``: the scan of docs/angular_contact.md: 9 balls of 7.938 mm on 38.5 mm at 15°, 25°
  and 40°, F_r on a log grid from 1e-6 N to 1e3 N (14 values), F_a/F_r on a log grid from 1e-4
  to 1 (12 values): 504 cases, the ring free to tilt.
* ``wide`` (default 3000 cases, seed 1): z 3 to 40 with D_w 0.3 to 0.95 of the largest that
  fits (d_m sin(180°/z)), d_m 14 to 102.5 mm, α0 10 to 45°, F_r 1e-6 N to 1e3 N, F_a/F_r 1e-4
  to 10 (log-uniform), the ring free to tilt, under a moment (either way, up to 0.9 of what the
  one-way balls hold) or under a misalignment (±0.001 to 0.3°), the cage at 0, half a pitch or
  anywhere.
* ``thrust`` (cases seeds 1 to n): normal loads with a small thrust: z 3 to 12, d_m 30 to 100
  mm, D_w 0.3 to 0.95 of the largest that fits, α0 10 to 45°, F_r 10 N to 10 kN, F_a/F_r 1e-5 to
  1e-1 (log-uniform), the cage anywhere, the ring free to tilt or (half the cases) under a
  moment (either way, up to 0.9 of what the one-way balls hold).

A case below the solver's least load is refused with that load in the message: it is then solved
again at that load (all loads scaled together), which must solve. Printed: cases, solved,
refused (and solved at the stated least load), ConvergenceError, other errors, NaN or negative
loads; the largest residual of each applied component as the solver measures it (over the
applied value, or over the sum of the magnitudes of its terms where those exceed 1e3 times it)
and as an independent plain sum of the returned ball loads and angles (beyond that sum's own
rounding, 4 eps of the sum of its terms' magnitudes).
"""

from __future__ import annotations

import math
import re
import sys
import time
from typing import Any

import numpy as np

from bearingload.errors import ConvergenceError, InputError
from bearingload.models import combined
from bearingload.models.combined import solve_combined


def base_cases() -> list[dict[str, Any]]:
    out = []
    for alpha in (15.0, 25.0, 40.0):
        for fr in np.logspace(-6, 3, 14):
            for ratio in np.logspace(-4, 0, 12):
                out.append({"z": 9, "dw": 7.938, "dm": 38.5, "alpha": alpha, "fr": float(fr),
                            "fa": float(fr * ratio), "cage": 0.0})  # fmt: skip
    return out


def wide_case(rng: np.random.Generator) -> dict[str, Any]:
    z = int(rng.integers(3, 41))
    dm = float(rng.uniform(14.0, 102.5))
    dw = dm * math.sin(math.pi / z) * float(rng.uniform(0.3, 0.95))
    dw = min(dw, 0.3 * dm)  # (3 balls: D_w below d_m / 3.3, a real ring)
    alpha = float(rng.uniform(10.0, 45.0))
    fr = float(10 ** rng.uniform(-6.0, 3.0))
    fa = fr * float(10 ** rng.uniform(-4.0, 1.0))
    cage = float(rng.choice([0.0, 180.0 / z, rng.uniform(0, 360)]))
    out: dict[str, Any] = {"z": z, "dw": dw, "dm": dm, "alpha": alpha, "fr": fr, "fa": fa,
                           "cage": cage}  # fmt: skip
    kind = rng.random()
    if kind < 0.25:
        r_i = dm / 2.0 + 0.02 * dw * math.cos(math.radians(alpha))
        most = 0.9 * fa * r_i * math.cos(math.pi / z)
        out["moment"] = float(rng.choice([-1, 1]) * most * 10 ** rng.uniform(-4, 0))
    elif kind < 0.5:
        out["misalignment"] = float(rng.choice([-1, 1]) * 10 ** rng.uniform(-3, math.log10(0.3)))
    return out


def thrust_case(rng: np.random.Generator) -> dict[str, Any]:
    """The ``thrust`` scan: z 3-12, α0 10-45°, F_r 10 N to 10 kN and F_a/F_r 1e-5 to 1e-1
    (log-uniform), the cage anywhere, the ring free to tilt or (half the cases) under a moment."""
    z = int(rng.integers(3, 13))
    dm = float(rng.uniform(30.0, 100.0))
    dw = min(dm * math.sin(math.pi / z) * float(rng.uniform(0.3, 0.95)), 0.3 * dm)
    alpha = float(rng.uniform(10.0, 45.0))
    fr = float(10 ** rng.uniform(1.0, 4.0))
    fa = fr * float(10 ** rng.uniform(-5.0, -1.0))
    out: dict[str, Any] = {"z": z, "dw": dw, "dm": dm, "alpha": alpha, "fr": fr, "fa": fa,
                           "cage": float(rng.uniform(0.0, 360.0))}  # fmt: skip
    if rng.random() < 0.5:
        r_i = dm / 2.0 + 0.02 * dw * math.cos(math.radians(alpha))
        most = 0.9 * fa * r_i * math.cos(math.pi / z)
        out["moment"] = float(rng.choice([-1, 1]) * most * 10 ** rng.uniform(-4, 0))
    return out


def solve(case: dict[str, Any], factor: float = 1.0) -> Any:
    kw = {k: case[k] for k in ("moment", "misalignment") if k in case}
    if "moment" in kw:
        kw["moment"] *= factor
    return solve_combined(case["z"], case["fr"] * factor, case["fa"] * factor,
                          contact_angle=case["alpha"], cage_angle=case["cage"],
                          ball_diameter=case["dw"], pitch_diameter=case["dm"], **kw)  # fmt: skip


def plain_excess(case: dict[str, Any], r: Any, factor: float) -> list[float]:
    """F_r, F_a (and M where applied): |plain sum - applied| beyond 4 eps of the sum of its
    terms' magnitudes, over |applied| (0 where the terms exceed 1e3 times it)."""
    q, al, ph = r.ball_loads, np.radians(r.contact_angles), np.radians(r.ball_angles)
    arm = float(r.tilt_radius)
    terms = [q * np.cos(al) * np.cos(ph), q * np.sin(al), arm * q * np.sin(al) * np.cos(ph)]
    wanted = [case["fr"] * factor, case["fa"] * factor, case.get("moment", 0.0) * factor]
    out = []
    for i, (t, w) in enumerate(zip(terms, wanted, strict=True)):
        size = float(np.abs(t).sum())
        if not w or size > 1e3 * abs(w) or (i == 2 and "misalignment" in case):
            out.append(0.0)
            continue
        err = abs(math.fsum(t.tolist()) - w) - 4.4e-16 * size
        out.append(max(err, 0.0) / abs(w))
    return out


def main(mode: str, n: int) -> None:
    maker = thrust_case if mode == "thrust" else wide_case
    cases = base_cases() if mode == "base" else [maker(np.random.default_rng(1 + i))
                                                 for i in range(n)]  # fmt: skip
    seen: dict[str, Any] = {}
    original = combined._checked

    def spy(p: Any, end: Any, its: Any, given: Any) -> Any:
        out = original(p, end, its, given)
        seen["gen"], seen["f"], seen["size"] = out[2][0], p.f[0], end.size[0]
        return out

    combined._checked = spy
    counts = dict.fromkeys(("solved", "refused, least load solved", "refused, least load "
                            "failed", "refused otherwise", "ConvergenceError", "NaN/negative"), 0)  # fmt: skip
    own, own_terms, plain = [0.0] * 5, [0.0] * 5, [0.0] * 3
    started = time.perf_counter()
    for case in cases:
        factor = 1.0
        try:
            r = solve(case)
        except InputError as exc:
            found = re.search(r"at least ([0-9.e+-]+) N", str(exc))
            if not found:
                counts["refused otherwise"] += 1
                print("refused:", case, str(exc)[:200])
                continue
            factor = float(found.group(1)) / max(case["fr"], case["fa"])
            try:
                r = solve(case, factor)
                counts["refused, least load solved"] += 1
            except (InputError, ConvergenceError) as exc2:
                counts["refused, least load failed"] += 1
                print("least load failed:", case, factor, str(exc2)[:200])
                continue
        except ConvergenceError as exc:
            counts["ConvergenceError"] += 1
            print("no convergence:", case, str(exc)[:200])
            continue
        else:
            counts["solved"] += 1
        bad = not (np.all(np.isfinite(r.ball_loads)) and np.all(np.isfinite(r.contact_angles)))
        bad |= bool(np.any(r.ball_loads < 0) or np.any(r.contact_angles < 0))
        counts["NaN/negative"] += int(bad)
        gen, f, size = seen["gen"], seen["f"], seen["size"]
        for i in range(5):
            if f[i] == 0 or (i == 3 and "misalignment" in case):
                continue
            err = abs(gen[i] - f[i])
            own_terms[i] = max(own_terms[i], err / max(abs(f[i]), size[i]))
            if size[i] <= 1e3 * abs(f[i]):
                own[i] = max(own[i], err / abs(f[i]))
        plain = [max(a, b) for a, b in zip(plain, plain_excess(case, r, factor), strict=True)]
    print(f"{mode}: {len(cases)} cases", counts, f"({time.perf_counter() - started:.0f} s)")
    print(f"solver's residual over the applied value (terms <= 1e3 times it): F_r {own[0]:.2e}, "
          f"F_a {own[2]:.2e}, M {own[3]:.2e}; over max(applied, terms): F_r {own_terms[0]:.2e}, "
          f"F_a {own_terms[2]:.2e}, M {own_terms[3]:.2e}")  # fmt: skip
    print(
        f"plain sums beyond their rounding, over the applied value: F_r {plain[0]:.2e}, "
        f"F_a {plain[1]:.2e}, M {plain[2]:.2e}"
    )


if __name__ == "__main__":
    main(
        sys.argv[1] if len(sys.argv) > 1 else "wide",
        int(sys.argv[2]) if len(sys.argv) > 2 else 3000,
    )
