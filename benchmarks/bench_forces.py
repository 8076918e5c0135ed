"""Benchmark: ring_forces (the forward problem) against a per-evaluation Python loop, same run.

Run with ``make bench``. A dynamics code evaluates the bearing force at every time step; the
baseline is what such a code writes without the library: for each evaluation, a Python loop over
the balls with ``math`` (force, stiffness matrix and ball loads, as ring_forces returns them).
Cases: z = 9, displacements around an operating point, cage angles over a full turn (every case
its own cage angle), 10 µm clearance. Single thread: BLAS threads are pinned to 1.
"""

from __future__ import annotations

import os
import sys

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")

import math  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from bench_solver import best_of  # noqa: E402

from bearingload.models.forces import ring_forces  # noqa: E402

Z = 9
K = 1e5  # N/mm^1.5
G_R = 0.01  # mm
N_VEC = 1_000_000
N_LOOP = 20_000
SEED = 20261122


def loop_case(x: float, y: float, cage_deg: float) -> tuple[float, float, float, float, float]:
    """One evaluation by a Python loop over the balls: F_x, F_y, K_xx, K_xy, K_yy."""
    e = G_R / 2
    fx = fy = kxx = kxy = kyy = 0.0
    for i in range(Z):
        phi = math.radians(cage_deg + 360.0 * i / Z)
        c, s = math.cos(phi), math.sin(phi)
        d = x * c + y * s - e
        if d > 0:
            root = math.sqrt(d)
            q, dq = K * d * root, 1.5 * K * root
            fx += q * c
            fy += q * s
            kxx += dq * c * c
            kxy += dq * c * s
            kyy += dq * s * s
    return fx, fy, kxx, kxy, kyy


def main() -> None:
    rng = np.random.default_rng(SEED)
    x = 0.005 + 0.01 * rng.random(N_VEC)  # mm
    y = 0.002 * (rng.random(N_VEC) - 0.5)  # mm
    cage = 360.0 * rng.random(N_VEC)  # deg
    f = ring_forces(Z, x, y, K, G_R, cage)  # warm-up, and the answers the loop is checked with
    t_vec = best_of(lambda: ring_forces(Z, x, y, K, G_R, cage), repeat=3)
    t_one = best_of(lambda: ring_forces(Z, x, y, K, G_R, 17.0), repeat=3)
    idx = rng.choice(N_VEC, N_LOOP, replace=False)
    xs, ys, cs = x[idx].tolist(), y[idx].tolist(), cage[idx].tolist()
    ref = np.array([loop_case(a, b, c) for a, b, c in zip(xs, ys, cs, strict=True)])
    t_loop = best_of(lambda: [loop_case(a, b, c) for a, b, c in zip(xs, ys, cs, strict=True)], 3)
    got = np.column_stack(
        [f.force_x[idx], f.force_y[idx], f.stiffness_matrix[idx, 0, 0],
         f.stiffness_matrix[idx, 0, 1], f.stiffness_matrix[idx, 1, 1]]
    )  # fmt: skip
    agreement = np.max(np.abs(got - ref) / np.abs(ref).max(axis=0))
    rate_vec, rate_one, rate_loop = N_VEC / t_vec, N_VEC / t_one, N_LOOP / t_loop
    print("ring_forces benchmark (one core; BLAS threads pinned to 1; z = 9)")
    print(
        f"  ring_forces, a cage angle per case: {rate_vec:12,.0f} evaluations/s "
        f"({N_VEC:,} in {t_vec:.3f} s, best of 3)"
    )
    print(
        f"  ring_forces, one cage angle       : {rate_one:12,.0f} evaluations/s "
        f"({N_VEC:,} in {t_one:.3f} s, best of 3)"
    )
    print(
        f"  per-evaluation Python loop        : {rate_loop:12,.0f} evaluations/s "
        f"({N_LOOP:,} in {t_loop:.3f} s, best of 3)"
    )
    print(f"  ratio (a cage angle per case)     : {rate_vec / rate_loop:12,.0f} x")
    print(f"  agreement                         : max relative difference {agreement:.1e}")


if __name__ == "__main__":
    main()
