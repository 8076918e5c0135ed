"""Benchmark: a combined-load cage sweep in one vectorised call against one call per cage angle.

Run with ``make bench``. Bearing 6205 (C3 mean clearance), F_r = 1.4 kN, F_a = 700 N, 36 cage
positions over one pitch. Times, in the same run:
* ``combined_sweep`` (studies.combined_sweep): one ``solve_combined`` call with the 36 cage
  angles as an array, the lives and checks included;
* ``solve_combined`` alone on the 36 angles in one call;
* a loop of 36 ``solve_combined`` calls, one cage angle each, with the ISO/TS 16281 life of each,
as a user without the sweep would write it; and the largest difference between the two answers.
Single thread: BLAS threads are pinned to 1.
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

from bearingload.bearings.iso16281 import contact_ratings, reference_rating_life  # noqa: E402
from bearingload.bearings.resolve import resolve_bearing  # noqa: E402
from bearingload.models.combined import solve_combined  # noqa: E402
from bearingload.studies.combined_sweep import combined_sweep  # noqa: E402
from bearingload.studies.sweep import cage_angles  # noqa: E402

STEPS = 36
F_R, F_A = 1400.0, 700.0


def main() -> None:
    b = resolve_bearing("6205", clearance="C3")
    geometry = dict(ball_diameter=b.ball_diameter, pitch_diameter=b.pitch_diameter, f_i=b.f_i,
                    f_o=b.f_o, clearance=b.clearance, modulus=b.modulus, poisson=b.poisson)  # fmt: skip
    angles = cage_angles(b.balls, STEPS)
    assert b.C is not None
    q_ci, q_ce = contact_ratings(b.C, b.balls, b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o)

    def sweep() -> object:
        return combined_sweep(b, F_R, F_A, steps=STEPS)

    def vectorised() -> object:
        return solve_combined(b.balls, F_R, F_A, cage_angle=angles, **geometry)

    def loop() -> tuple[list[float], list[float]]:
        q, life = [], []
        for a in angles:
            r = solve_combined(b.balls, F_R, F_A, cage_angle=float(a), **geometry)
            q.append(float(r.q_max))
            life.append(float(reference_rating_life(r.ball_loads, q_ci, q_ce)))
        return q, life

    s = sweep()
    q_loop, life_loop = loop()
    t_sweep = best_of(sweep, 5)
    t_vec = best_of(vectorised, 5)
    t_loop = best_of(loop, 3)
    q_diff = np.max(np.abs(np.asarray(s.result.q_max) / np.asarray(q_loop) - 1.0))
    l_diff = np.max(np.abs(np.asarray(s.reference_rating_life) / np.asarray(life_loop) - 1.0))
    print("bearingload combined sweep benchmark (one core; BLAS threads pinned to 1)")
    print(f"  6205 C3, F_r = {F_R:g} N, F_a = {F_A:g} N, {STEPS} cage positions over one pitch")
    print(f"  combined_sweep (one call, lives)  : {t_sweep * 1e3:8.1f} ms  (best of 5)")
    print(f"  solve_combined, 36 angles at once : {t_vec * 1e3:8.1f} ms  (best of 5)")
    print(f"  36 solve_combined calls + L10r    : {t_loop * 1e3:8.1f} ms  (best of 3)")
    print(f"  ratio loop / combined_sweep       : {t_loop / t_sweep:8.1f} x")
    print(f"  agreement                         : max |Q_max/Q_max,loop - 1| = {q_diff:.1e}, "
          f"max |L10r/L10r,loop - 1| = {l_diff:.1e}")  # fmt: skip


if __name__ == "__main__":
    main()
