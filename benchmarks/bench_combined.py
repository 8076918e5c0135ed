"""Benchmark: the combined-load solver against the radial engine on the same cases, same run.

Run with ``make bench``. Prints cases per second of
* the radial engine (models.equilibrium.solve) on (z, F_r, K, G_r, cage angle),
* the combined solver (models.combined.solve_combined) on the same cases with F_a = 0 and with an
  axial load, once with a constant ball stiffness and once with the Hertz stiffness at each
  ball's contact angle (the default),
and the ratio of each to the radial engine. The combined solver takes one z per call: the cases
are grouped by z, as a user with a batch would. Single thread: BLAS threads are pinned to 1.
"""

from __future__ import annotations

import os
import sys

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")


import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from bench_solver import best_of  # noqa: E402

from bearingload.contact.hertz import ball_stiffness  # noqa: E402
from bearingload.models.combined import solve_combined  # noqa: E402
from bearingload.models.equilibrium import solve  # noqa: E402

N_CASES = 2_000
SEED = 20261122
GEOMETRY = {"ball_diameter": 7.938, "pitch_diameter": 38.5, "f_i": 0.52, "f_o": 0.53}


def random_cases(n: int, rng: np.random.Generator) -> dict[str, np.ndarray]:
    """z 7-12; F_r 10 N-10 kN; F_a 0.1-1 F_r; G_r 0 (1 in 5) or 1-100 um; cage angle any."""
    z = rng.integers(7, 13, n)
    fr = 10 ** rng.uniform(1, 4, n)
    fa = fr * rng.uniform(0.1, 1.0, n)
    g = np.where(rng.random(n) < 0.2, 0.0, 10 ** rng.uniform(-3, -1, n))
    cage = rng.uniform(0, 360, n)
    return {"z": z, "fr": fr, "fa": fa, "g": g, "cage": cage}


def main() -> None:
    rng = np.random.default_rng(SEED)
    c = random_cases(N_CASES, rng)
    k0 = float(ball_stiffness(*GEOMETRY.values()).ball)
    groups = [np.nonzero(c["z"] == z)[0] for z in np.unique(c["z"])]

    def radial() -> None:
        solve(c["z"], c["fr"], k0, c["g"], c["cage"])

    def combined(axial: bool, hertz: bool) -> None:
        extra = {} if hertz else {"stiffness": k0}
        for idx in groups:
            fa = c["fa"][idx] if axial else 0.0
            solve_combined(int(c["z"][idx[0]]), c["fr"][idx], fa, clearance=c["g"][idx],
                           cage_angle=c["cage"][idx], **GEOMETRY, **extra)  # fmt: skip

    radial()
    t_radial = best_of(radial, repeat=5)
    runs = {
        "combined, F_a = 0, constant K": lambda: combined(False, False),
        "combined, F_a > 0, constant K": lambda: combined(True, False),
        "combined, F_a > 0, Hertz K(alpha)": lambda: combined(True, True),
    }
    print("bearingload combined-load benchmark (one core; BLAS threads pinned to 1)")
    print("  cases: z 7-12, F_r 10 N-10 kN, F_a 0.1-1 F_r, G_r 0 or 1-100 um, any cage angle")
    print(f"  radial engine (F_a = 0)          : {N_CASES / t_radial:10,.0f} cases/s  (best of 5)")
    for label, fn in runs.items():
        t = best_of(fn, repeat=3)
        ratio = t / t_radial
        print(f"  {label:33s}: {N_CASES / t:10,.0f} cases/s  ({ratio:6.1f} x the radial time)")


if __name__ == "__main__":
    main()
