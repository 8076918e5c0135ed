"""Benchmark: ``bearingload batch`` end to end on a csv file of 10^5 cases, in one run.

Run with ``make bench``. Times, each as the best of a few runs of a fresh ``bearingload batch``
process (start-up, reading, checking, solving and writing the csv included):

* 10 cases and 10^5 cases: their ratio (the aim: at most 10x with plain code: one
  thread; the csv module reads, every number is written by ``render.number_text``);
* the per-case scipy ``brentq`` baseline of ``bench_solver.py`` on 2000 of the same cases, as
  cases per second, against the batch's cases per second end to end;
* agreement of the batch's Q_max (10 significant digits in the csv) with the baseline.

The cases are those of ``bench_solver.py``: z 3-40, loads 1 N-10 kN, K 10^4.5-10^6 N/mm^1.5,
clearance 0 or 0.1 um-0.5 mm, cage angle 0 or half a pitch. Single thread: BLAS pinned to 1.
"""

from __future__ import annotations

import csv
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_solver import SEED, brentq_case, random_cases  # noqa: E402

N_CASES = 100_000
N_SMALL = 10
N_BASELINE = 2_000
BIN = os.path.join(os.path.dirname(sys.executable), "bearingload")


def write_cases(path: str, cases: dict[str, np.ndarray], n: int) -> None:
    columns = [cases[k][:n].tolist() for k in ("z", "load", "stiffness", "clearance", "cage")]
    with open(path, "w", encoding="utf-8", newline="\n") as fh:
        fh.write("balls,load [N],stiffness,clearance [mm],cage_angle\n")
        for row in zip(*columns, strict=True):
            fh.write(",".join(repr(v) for v in row) + "\n")


def run_batch(src: str, out: str, repeats: int) -> float:
    """Best wall time of ``bearingload batch SRC --format csv -o OUT`` in a fresh process."""
    best = float("inf")
    for _ in range(repeats):
        t0 = time.perf_counter()
        done = subprocess.run(
            [BIN, "batch", src, "--format", "csv", "-o", out], capture_output=True, text=True
        )
        best = min(best, time.perf_counter() - t0)
        if done.returncode != 0:
            raise SystemExit(f"bearingload batch failed: {done.stderr}")
    return best


def main() -> None:
    rng = np.random.default_rng(SEED)
    cases = random_cases(N_CASES, rng)
    with tempfile.TemporaryDirectory() as tmp:
        small, large = os.path.join(tmp, "small.csv"), os.path.join(tmp, "large.csv")
        out_small, out_large = os.path.join(tmp, "o10.csv"), os.path.join(tmp, "o1e5.csv")
        write_cases(small, cases, N_SMALL)
        write_cases(large, cases, N_CASES)
        t_small = run_batch(small, out_small, 5)
        t_large = run_batch(large, out_large, 3)
        with open(out_large, encoding="utf-8") as fh:
            q_batch = np.array([float(r["q_max [N]"]) for r in csv.DictReader(fh)])
    t0 = time.perf_counter()
    q_ref = np.array(
        [
            brentq_case(int(cases["z"][i]), cases["load"][i], cases["stiffness"][i],
                        cases["clearance"][i], cases["cage"][i])
            for i in range(N_BASELINE)
        ]
    )  # fmt: skip
    t_base = time.perf_counter() - t0
    agree = float(np.max(np.abs(q_batch[:N_BASELINE] / q_ref - 1.0)))
    rate_batch, rate_base = N_CASES / t_large, N_BASELINE / t_base
    print("bearingload batch benchmark (fresh process, csv in and out, best of runs)")
    print(f"  {N_SMALL} cases end to end      : {t_small:8.3f} s (best of 5)")
    print(f"  {N_CASES:,} cases end to end : {t_large:8.3f} s (best of 3)")
    print(f"  ratio 10^5 / 10 cases     : {t_large / t_small:8.1f} x  (aim: <= 10 x)")
    print(f"  batch, end to end         : {rate_batch:12,.0f} cases/s")
    print(f"  per-case brentq loop      : {rate_base:12,.0f} cases/s ({N_BASELINE:,} cases)")
    print(f"  ratio batch / brentq loop : {rate_batch / rate_base:8.1f} x")
    print(f"  agreement                 : max |Q_max/Q_max,brentq - 1| = {agree:.1e}")


if __name__ == "__main__":
    main()
