"""Benchmark: one call from Python, against a per-case scipy baseline, as ratios in one run.

Run with ``make bench``. Python users call ``solve`` in loops (optimisers, time-stepping rotor
models); what counts there is the cost of one call.

Engine: ``solve(9, 1000.0, 1e5, 0.01, cage_angle=17.0)`` (a general cage angle, 2-D).
Baseline: ``scipy.optimize.root(method='hybr')`` on the same ring: the two force equations
``sum K (x cos phi_i + y sin phi_i - e)_+^1.5 (cos, sin) = (F_r, 0)`` written with numpy, started
at the one-ball approach plus the gap, ``xtol`` 1e-13 (the engine's tolerance), no Jacobian
(hybr estimates it, as a user of ``root`` would leave it).

Timing: the best of 7 rounds of many calls each, engine and baseline interleaved, so that a
busy machine slows both alike. Single thread: BLAS threads are pinned to 1.
"""

from __future__ import annotations

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")

import time  # noqa: E402
from collections.abc import Callable  # noqa: E402

import numpy as np  # noqa: E402

from bearingload.models.equilibrium import solve  # noqa: E402

CASE = (9, 1000.0, 1e5, 0.01)
CAGE = 17.0


def hybr_case(z: int, load: float, k: float, g: float, cage_deg: float) -> np.ndarray:
    """(x, y) of one case by scipy.optimize.root(method='hybr'); the per-case baseline."""
    from scipy.optimize import root

    phi = np.deg2rad(cage_deg) + 2 * np.pi * np.arange(z) / z
    c, s = np.cos(phi), np.sin(phi)
    e = g / 2

    def residual(v: np.ndarray) -> list[float]:
        d = np.maximum(v[0] * c + v[1] * s - e, 0.0)
        q = k * d**1.5
        return [float(q @ c) - load, float(q @ s)]

    start = [(load / k) ** (2 / 3) + e, 0.0]
    sol = root(residual, start, method="hybr", options={"xtol": 1e-13})
    return sol.x


def interleaved(fns: dict[str, Callable[[], object]], calls: dict[str, int], rounds: int = 7):
    """Best seconds per call of each function, rounds interleaved."""
    best = dict.fromkeys(fns, float("inf"))
    for _ in range(rounds):
        for name, fn in fns.items():
            t0 = time.perf_counter()
            for _ in range(calls[name]):
                fn()
            best[name] = min(best[name], (time.perf_counter() - t0) / calls[name])
    return best


def main() -> None:
    engine = solve(*CASE, cage_angle=CAGE)
    ref = hybr_case(*CASE, CAGE)  # also imports scipy outside the timing
    agreement = max(abs(float(engine.x) / ref[0] - 1), abs(float(engine.y) / ref[1] - 1))
    t = interleaved(
        {
            "solve": lambda: solve(*CASE, cage_angle=CAGE),
            "solve_sym": lambda: solve(*CASE),
            "hybr": lambda: hybr_case(*CASE, CAGE),
        },
        {"solve": 2000, "solve_sym": 2000, "hybr": 300},
    )
    print("one call from Python (best of 7 interleaved rounds; one core)")
    print(f"  solve(9, 1000.0, 1e5, 0.01, cage_angle=17.0): {t['solve'] * 1e6:8.1f} us")
    print(f"  solve(9, 1000.0, 1e5, 0.01) (symmetric)     : {t['solve_sym'] * 1e6:8.1f} us")
    print(f"  scipy.optimize.root(hybr), same ring        : {t['hybr'] * 1e6:8.1f} us")
    print(f"  ratio solve / hybr                          : {t['solve'] / t['hybr']:8.3f}")
    print(f"  agreement (x, y)                            : {agreement:8.1e}")


if __name__ == "__main__":
    main()
