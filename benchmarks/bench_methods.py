"""Benchmark: every registered method of :mod:`bearingload.models.registry`, timed side by side.

Run with ``python benchmarks/bench_methods.py``. For each method: the time of one scalar call
(median of repeats), the throughput of one vectorised call over random cases, and the relative
error of Q_max against the exact discrete answer over the same cases (median and largest).
Single thread: BLAS threads are pinned to 1.
"""

from __future__ import annotations

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")

import statistics  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

from bearingload.models.registry import METHODS, compute  # noqa: E402

N_CASES = 100_000
REPEATS = 200
SEED = 20261122


def random_cases(n: int, rng: np.random.Generator) -> tuple[np.ndarray, ...]:
    """z 5-40; loads 10 N to 10 kN; stiffness 10^4.5-10^6 N/mm^1.5; clearance 0 (1 in 3) to 50 um."""
    z = rng.integers(5, 41, n)
    load = 10 ** rng.uniform(1, 4, n)
    stiffness = 10 ** rng.uniform(4.5, 6, n)
    clearance = np.where(rng.random(n) < 1 / 3, 0.0, rng.uniform(0.0, 0.05, n))
    cage = np.where(rng.random(n) < 0.5, 0.0, 180.0 / z)
    return z, load, stiffness, clearance, cage, np.full(n, 1.5)


def main() -> None:
    rng = np.random.default_rng(SEED)
    cases = random_cases(N_CASES, rng)
    one = (8, 2941.995, 46091.255, 0.02, 0.0, 1.5)  # bearing 306, Kuzmenko 2010
    exact = compute("exact", *cases)
    print(
        f"{'method':<10} {'scalar call':>12} {'vectorised':>16} {'|err| median':>13} {'|err| max':>10}"
    )
    for name in METHODS:
        compute(name, *one)
        times = []
        for _ in range(REPEATS):
            t0 = time.perf_counter()
            compute(name, *one)
            times.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        r = compute(name, *cases)
        elapsed = time.perf_counter() - t0
        err = np.abs(np.asarray(r.q_max) / np.asarray(exact.q_max) - 1.0)
        print(
            f"{name:<10} {statistics.median(times) * 1e6:>9.0f} µs "
            f"{N_CASES / elapsed:>10.3g} case/s {np.median(err):>12.2%} {err.max():>10.2%}"
        )


if __name__ == "__main__":
    main()
