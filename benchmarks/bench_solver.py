"""Benchmark: the vectorised equilibrium engine against a per-case scipy brentq loop, same run.

Run with ``make bench``. Prints cases per second of both, their ratio, their agreement, and the
start-up time of a terminal calculation against ``python -c "import numpy"``.

Baseline: for each case, ``scipy.optimize.brentq`` on the x-equilibrium of the same symmetric
ring (sum K (x cos phi_i - e)_+^m cos phi_i = F_r), bracketed by the one-ball bound, at the same
accuracy (xtol 1e-15 of the scale, rtol 4 eps). Single thread: BLAS threads are pinned to 1.
"""

from __future__ import annotations

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")

import statistics  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

from bearingload.models.equilibrium import solve  # noqa: E402

N_CASES = 100_000
N_BASELINE = 2_000
SEED = 20261121


def random_cases(n: int, rng: np.random.Generator) -> dict[str, np.ndarray]:
    """z 3-40; loads 1 N to 10 kN (4 decades); clearance 0 (1 in 5) or 0.1 um to 0.5 mm."""
    z = rng.integers(3, 41, n)
    load = 10 ** rng.uniform(0, 4, n)
    stiffness = 10 ** rng.uniform(4.5, 6, n)
    clearance = np.where(rng.random(n) < 0.2, 0.0, 10 ** rng.uniform(-4, np.log10(0.5), n))
    cage = np.where(rng.random(n) < 0.5, 0.0, 180.0 / z)
    return {"z": z, "load": load, "stiffness": stiffness, "clearance": clearance, "cage": cage}


def brentq_case(z: int, load: float, k: float, g: float, cage_deg: float) -> float:
    """Q_max of one symmetric case by scipy brentq on x; the per-case baseline."""
    from scipy.optimize import brentq

    phi = np.deg2rad(cage_deg) + 2 * np.pi * np.arange(z) / z
    c = np.cos(phi)
    e = g / 2

    def residual(x: float) -> float:
        d = np.maximum(x * c - e, 0.0)
        return float(k * np.sum(d**1.5 * c) - load)

    c_max = c.max()
    hi = (1.01 * (load / (k * c_max)) ** (2 / 3) + e) / c_max  # one ball alone, plus 1 %
    lo = e / c_max
    scale = (load / k) ** (2 / 3)
    x = brentq(residual, lo, hi, xtol=1e-15 * scale, rtol=4 * np.finfo(float).eps, maxiter=500)
    return float(k * np.max(np.maximum(x * c - e, 0.0)) ** 1.5)


def best_of(fn, repeat: int = 3) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def startup(cmd: list[str], repeat: int = 7) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run(cmd, check=True, capture_output=True)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main() -> None:
    rng = np.random.default_rng(SEED)
    cases = random_cases(N_CASES, rng)
    args = (cases["z"], cases["load"], cases["stiffness"], cases["clearance"], cases["cage"])

    result = solve(*args)  # warm-up, and the answers the baseline is compared with
    t_vec = best_of(lambda: solve(*args), repeat=7)
    rate_vec = N_CASES / t_vec

    idx = rng.choice(N_CASES, N_BASELINE, replace=False)
    brentq_case(8, 1.0, 1.0, 0.0, 0.0)  # import scipy outside the timing
    q_ref = np.array([brentq_case(*(a[i] for a in args)) for i in idx])
    # the baseline gets the same treatment as the engine: best of repeated runs
    t_loop = best_of(lambda: [brentq_case(*(a[i] for a in args)) for i in idx], repeat=3)
    rate_loop = N_BASELINE / t_loop
    agreement = np.max(np.abs(result.q_max[idx] / q_ref - 1))

    angles = rng.uniform(0, 360, N_CASES)
    sym = np.where(rng.random(N_CASES) < 0.5, 0.0, 180.0 / args[0])
    general = {}  # cases -> (time any cage angle, time symmetric), same cases otherwise
    for n in (N_CASES // 10, N_CASES):
        sub = tuple(a[:n] for a in args[:4])
        t_gen = best_of(lambda sub=sub, n=n: solve(*sub, angles[:n]), repeat=3)
        general[n] = (t_gen, best_of(lambda sub=sub, n=n: solve(*sub, sym[:n]), repeat=3))
    rate_gen = (N_CASES // 10) / general[N_CASES // 10][0]

    print("bearingload benchmark (one core; BLAS threads pinned to 1)")
    print("  cases: z 3-40, loads 1 N-10 kN, clearance 0 or 0.1 um-0.5 mm, cage 0 or half pitch")
    print(
        f"  vectorised engine   : {rate_vec:12,.0f} cases/s  ({N_CASES:,} cases in {t_vec:.3f} s, best of 7)"
    )
    print(
        f"  per-case brentq loop: {rate_loop:12,.0f} cases/s  ({N_BASELINE:,} cases in {t_loop:.3f} s, best of 3)"
    )
    print(f"  ratio               : {rate_vec / rate_loop:12,.0f} x")
    print(f"  agreement           : max |Q_max/Q_max,brentq - 1| = {agreement:.1e}")
    print(
        f"  any cage angle (2-D): {rate_gen:12,.0f} cases/s  ({N_CASES // 10:,} cases, best of 3)"
    )
    for n, (t_gen, t_sym) in general.items():
        print(f"  2-D / symmetric     : {t_gen / t_sym:12.2f} x  time per case, {n:,} cases, "
              "same cases otherwise")  # fmt: skip
    print(
        f"  Newton iterations   : mean {result.iterations.mean():.2f}, max {result.iterations.max()}"
    )

    t_numpy = startup([sys.executable, "-c", "import numpy"])
    t_table = startup([sys.executable, "-m", "bearingload", "table", "k"])
    print("start-up (median of 7 runs)")
    print(f"  python -c 'import numpy'      : {t_numpy * 1e3:7.1f} ms")
    print(f"  python -m bearingload table k : {t_table * 1e3:7.1f} ms")
    print(f"  ratio                         : {t_table / t_numpy:7.2f} x")


if __name__ == "__main__":
    main()
