"""Benchmark: the combined solver on angular-contact ball bearings against a per-case fsolve.

Run: ``make bench`` or ``.venv/bin/python benchmarks/bench_angular.py``.
The target: the vectorised solve at least 50 times a per-case ``scipy.optimize.fsolve``
on the same equations. The baseline: per case, fsolve on the three equilibrium equations of the
inner ring in (x, a, theta) of a 7205-sized bearing (D_w 7.938 mm, d_m 38.5 mm, f_i 0.52, f_o
0.53, 13 balls), cage angle 0, free tilt, one constant ball stiffness K, the angular-contact
geometry of :mod:`bearingload.models.combined` (groove centres ``A cos a0`` and ``A sin a0``
apart at zero load, one-sided contact ``max(u, 0)``); no Jacobian, xtol 1e-13, started where
every ball carries F_a at the design angle. Cases: a0 10-45°, F_r and F_a 10 N-C_0r. The
vectorised call is ``solve_combined(13, F_r, F_a, contact_angle=a0, stiffness=K)`` on all
cases at once. The machine is shared: the two are timed in pairs (fsolve on the cases, then the
vectorised call on the same cases), the ratio of each pair printed, and their median.
"""

from __future__ import annotations

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import math  # noqa: E402
import statistics  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from bench_combined import baseline_per_case, interleaved  # noqa: E402

from bearingload.models.combined import solve_combined  # noqa: E402

Z, K = 13, 7.0e5
GEO = {"ball_diameter": 7.938, "pitch_diameter": 38.5, "f_i": 0.52, "f_o": 0.53}
N_CASES, PAIRS, SEED = 300, 5, 20261124
N_ONE = 100


def fsolve_case(fr: float, fa: float, alpha: float) -> tuple[np.ndarray, bool]:
    """Ball loads [N] of one case by fsolve on (x, a, theta), and whether the residual is 1e-8."""
    from scipy.optimize import fsolve

    dw, dm, fi = GEO["ball_diameter"], GEO["pitch_diameter"], GEO["f_i"]
    big_a = (fi + GEO["f_o"] - 1.0) * dw
    a0 = math.radians(alpha)
    r_i = dm / 2.0 + (fi - 0.5) * dw * math.cos(a0)
    c = np.cos(2.0 * np.pi * np.arange(Z) / Z)

    def loads(v: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        rho = big_a * math.cos(a0) + v[0] * c
        u = np.maximum(big_a * math.sin(a0) + v[1] + r_i * v[2] * c, 0.0)
        d = np.hypot(np.maximum(rho, 0.0), u)
        d = np.where(d > 0, d, 1.0)
        return K * np.maximum(d - big_a, 0.0) ** 1.5, np.maximum(rho, 0.0) / d, u / d

    def residual(v: np.ndarray) -> list[float]:
        q, cos_a, sin_a = loads(v)
        return [q @ (cos_a * c) - fr, q @ sin_a - fa, r_i * (q @ (sin_a * c))]

    approach = (fa / (Z * K * math.sin(a0))) ** (2.0 / 3.0)
    v = fsolve(residual, [0.0, approach / math.sin(a0), 0.0], xtol=1e-13)
    return loads(v)[0], bool(np.max(np.abs(residual(v))) <= 1e-8 * max(fr, fa))


def cases(rng: np.random.Generator) -> tuple[np.ndarray, ...]:
    alpha = rng.uniform(10.0, 45.0, N_CASES)
    c0 = 12.3 * Z * GEO["ball_diameter"] ** 2 * np.cos(np.radians(alpha))
    fr = 10 ** rng.uniform(1.0, np.log10(c0))
    fa = 10 ** rng.uniform(1.0, np.log10(c0))
    return fr, fa, alpha


def one_call(fr: np.ndarray, fa: np.ndarray, alpha: np.ndarray) -> None:
    """One case per call (Hertz default) against the per-case baseline of bench_combined."""
    few = [(float(fr[i]), float(fa[i]), float(alpha[i])) for i in range(N_ONE)]
    base = baseline_per_case()

    def calls() -> None:
        for a, b, angle in few:
            solve_combined(Z, a, b, contact_angle=angle, **GEO)

    per = interleaved({"one": calls})["one"] / N_ONE
    print(
        f"one call, angular contact, Hertz K(alpha): {per * 1e6:.1f} us ({per / base:.2f} x the "
        f"bench_combined fsolve time per case, {base * 1e6:.1f} us; target <= 0.1)"
    )


def main() -> None:
    fr, fa, alpha = cases(np.random.default_rng(SEED))
    one_call(fr, fa, alpha)
    ref = [fsolve_case(fr[i], fa[i], alpha[i]) for i in range(N_CASES)]  # imports scipy
    vec = solve_combined(Z, fr, fa, contact_angle=alpha, stiffness=K, **GEO)
    ok = np.array([good for _, good in ref])
    q_ref = np.array([q for q, _ in ref])
    diff = np.max(np.abs(vec.ball_loads - q_ref)[ok], axis=1) / np.max(q_ref[ok], axis=1)
    print(f"{N_CASES} cases (a0 10-45°, F_r, F_a 10 N-C_0r, z = {Z}, constant K): fsolve "
          f"reached a residual of 1e-8 in {int(ok.sum())}; ball loads agree with the vectorised "
          f"solve to {float(diff.max()):.1e} of Q_max there")  # fmt: skip
    ratios = []
    for _ in range(PAIRS):
        t0 = time.perf_counter()
        for i in range(N_CASES):
            fsolve_case(fr[i], fa[i], alpha[i])
        t_fsolve = time.perf_counter() - t0
        t0 = time.perf_counter()
        solve_combined(Z, fr, fa, contact_angle=alpha, stiffness=K, **GEO)
        t_vec = time.perf_counter() - t0
        ratios.append(t_fsolve / t_vec)
        print(f"  pair: fsolve {t_fsolve / N_CASES * 1e6:.0f} us/case, vectorised "
              f"{t_vec / N_CASES * 1e6:.1f} us/case, ratio {t_fsolve / t_vec:.1f}")  # fmt: skip
    print(f"vectorised / per-case fsolve speed ratio: median {statistics.median(ratios):.1f} "
          f"(min {min(ratios):.1f}, max {max(ratios):.1f}) over {PAIRS} pairs")  # fmt: skip


if __name__ == "__main__":
    main()
