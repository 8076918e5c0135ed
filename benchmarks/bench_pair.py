"""Benchmark: the bearing-pair solver (DB, DF, DT) against a per-case fsolve.

Run: ``make bench`` or ``.venv/bin/python benchmarks/bench_pair.py``.
The target: the vectorised solve at least 50 times a per-case ``scipy.optimize.fsolve`` on the
same equations. The baseline: per case, the preload offset by ``scipy.optimize.brentq`` on the
single bearing's pure-thrust equation, then fsolve on the three equilibrium equations of the
shaft in (x, a, theta) (the case is symmetric about the load line: y = theta_c = 0) of a pair
of 7205-sized bearings (D_w 8.7312 mm, d_m 38.5 mm, f_i 0.52, f_o 0.53, 12 balls, B 15 mm),
cage angle 0, one constant ball stiffness K, the geometry of :mod:`bearingload.models.pair`
(each bearing's groove centres moved by the shaft's translation and tilt about the pair's
centre, bearing 2 of DB/DF facing the other way, one-sided contact ``max(u, 0)``); no
Jacobian, xtol 1e-13, started at the rigid-ring estimate. Cases: DB, DF, DT in turn, a0 10-45°,
F_r 10 N-C_0r, F_a 10 N-C_0r (DB/DF either sign), a preload (DB/DF) 0.1 % to 10 % of C_0r. The
vectorised call is ``solve_pair`` on all the cases of one arrangement at once (1000 each). The machine is
shared: the two are timed in pairs, the ratio of each pair printed, and their median.

One call: ``solve_pair`` on one preloaded DB case at a time (Hertz default, the first N_ONE
cases), per call, over the per-case baseline of ``bench_combined.py`` (fsolve on a 6205
deep-groove bearing, constant K) measured in the same run; target at most 0.2.
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

from bearingload.models.pair import solve_pair  # noqa: E402

Z, K, WIDTH = 12, 7.0e5, 15.0
GEO = {"ball_diameter": 8.7312, "pitch_diameter": 38.5, "f_i": 0.52, "f_o": 0.53}
N_CASES, PAIRS, SEED = 1000, 3, 20261124
KINDS = ("DB", "DF", "DT")
N_ONE = 100


def fsolve_case(
    kind: str, fr: float, fa: float, fp: float, alpha: float
) -> tuple[np.ndarray, bool]:
    """Ball loads [N] of both bearings (2, z) of one case, and whether fsolve reached 1e-8."""
    from scipy.optimize import brentq, fsolve

    dw, dm, fi = GEO["ball_diameter"], GEO["pitch_diameter"], GEO["f_i"]
    big_a = (fi + GEO["f_o"] - 1.0) * dw
    a0 = math.radians(alpha)
    r_i = dm / 2.0 + (fi - 0.5) * dw * math.cos(a0)
    c = np.cos(2.0 * np.pi * np.arange(Z) / Z)
    ca0, sa0 = big_a * math.cos(a0), big_a * math.sin(a0)
    rows = {"DB": ((-0.5, 1.0), (0.5, -1.0)), "DF": ((0.5, 1.0), (-0.5, -1.0)),
            "DT": ((-0.5, 1.0), (0.5, 1.0))}[kind]  # fmt: skip

    def thrust(u: float) -> float:  # one bearing under thrust alone, axial offset u
        d = math.hypot(ca0, sa0 + u)
        return Z * K * max(d - big_a, 0.0) ** 1.5 * (sa0 + u) / d - fp

    off = brentq(thrust, 0.0, big_a, xtol=1e-16) if fp > 0 else 0.0

    def loads(v: np.ndarray) -> list[tuple[np.ndarray, ...]]:
        out = []
        for half, sign in rows:
            zk = half * WIDTH
            rho = ca0 + (v[0] - zk * v[2]) * c
            u = np.maximum(sa0 + off + sign * (v[1] + r_i * v[2] * c), 0.0)
            d = np.hypot(np.maximum(rho, 0.0), u)
            d = np.where(d > 0, d, 1.0)
            q = K * np.maximum(d - big_a, 0.0) ** 1.5
            out.append((q, np.maximum(rho, 0.0) / d, u / d, zk, sign))
        return out

    def residual(v: np.ndarray) -> list[float]:
        f = [-fr, -fa, 0.0]
        for q, cos_a, sin_a, zk, sign in loads(v):
            f[0] += q @ (cos_a * c)
            f[1] += sign * (q @ sin_a)
            f[2] += sign * r_i * (q @ (sin_a * c)) - zk * (q @ (cos_a * c))
        return f

    share = abs(fa) / (2.0 if kind == "DT" else 1.0)
    approach = (share / (Z * K * math.sin(a0))) ** (2.0 / 3.0)
    x0 = (2.5 * fr / (Z * K * math.cos(a0))) ** (2.0 / 3.0) / math.cos(a0)
    start = (
        [0.0, 0.0, 0.0]
        if fp >= max(fr, abs(fa))
        else [x0, math.copysign(approach / math.sin(a0), fa), 0.0]
    )
    v = fsolve(residual, start, xtol=1e-13)
    good = max(abs(x) for x in residual(v)) <= 1e-8 * max(fr, abs(fa), fp)
    return np.array([b[0] for b in loads(v)]), bool(good)


def cases(rng: np.random.Generator, kind: str) -> tuple[np.ndarray, ...]:
    alpha = rng.uniform(10.0, 45.0, N_CASES)
    c0 = 12.3 * Z * GEO["ball_diameter"] ** 2 * np.cos(np.radians(alpha))
    fr = 10 ** rng.uniform(1.0, np.log10(c0))
    fa = 10 ** rng.uniform(1.0, np.log10(c0))
    fp = np.zeros(N_CASES)
    if kind != "DT":
        fa *= rng.choice([-1.0, 1.0], N_CASES)
        fp = c0 * 10 ** rng.uniform(-3.0, -1.0, N_CASES)
    return fr, fa, fp, alpha


def vectorised(
    kind: str, fr: np.ndarray, fa: np.ndarray, fp: np.ndarray, alpha: np.ndarray
) -> object:
    return solve_pair(Z, fr, fa, arrangement=kind, preload=fp, contact_angle=alpha, width=WIDTH,
                      stiffness=K, **GEO)  # fmt: skip


def one_call(fr: np.ndarray, fa: np.ndarray, fp: np.ndarray, alpha: np.ndarray) -> None:
    """One preloaded DB case per call (Hertz default) against the baseline of bench_combined."""
    few = [(float(fr[i]), float(fa[i]), float(fp[i]), float(alpha[i])) for i in range(N_ONE)]
    base = baseline_per_case()

    def calls() -> None:
        for a, b, p, angle in few:
            solve_pair(
                Z, a, b, arrangement="DB", preload=p, contact_angle=angle, width=WIDTH, **GEO
            )

    per = interleaved({"one": calls})["one"] / N_ONE
    print(
        f"one call, DB pair, Hertz K(alpha): {per * 1e6:.1f} us ({per / base:.2f} x the "
        f"bench_combined fsolve time per case, {base * 1e6:.1f} us; target <= 0.2)"
    )


def main() -> None:
    rng = np.random.default_rng(SEED)
    sets = {kind: cases(rng, kind) for kind in KINDS}
    one_call(*sets["DB"])
    for kind, (fr, fa, fp, alpha) in sets.items():
        ref = [fsolve_case(kind, fr[i], fa[i], fp[i], alpha[i]) for i in range(N_CASES)]
        vec = vectorised(kind, fr, fa, fp, alpha)
        ok = np.array([good for _, good in ref])
        q_ref = np.array([q for q, _ in ref])  # (n, 2, z)
        q_vec = np.stack([b.ball_loads for b in vec.bearings], axis=1)  # type: ignore[attr-defined]
        diff = np.max(np.abs(q_vec - q_ref)[ok], axis=(1, 2)) / np.max(q_ref[ok], axis=(1, 2))
        print(f"{kind}: {N_CASES} cases (a0 10-45°, F_r, |F_a| 10 N-C_0r, z = {Z}, constant K): "
              f"fsolve reached a residual of 1e-8 in {int(ok.sum())}; ball loads agree with the "
              f"vectorised solve to {float(diff.max()):.1e} of Q_max there")  # fmt: skip
    ratios = []
    for _ in range(PAIRS):
        t_fsolve = t_vec = 0.0
        for kind, (fr, fa, fp, alpha) in sets.items():
            t0 = time.perf_counter()
            for i in range(N_CASES):
                fsolve_case(kind, fr[i], fa[i], fp[i], alpha[i])
            t_fsolve += time.perf_counter() - t0
            t0 = time.perf_counter()
            vectorised(kind, fr, fa, fp, alpha)
            t_vec += time.perf_counter() - t0
        n = N_CASES * len(KINDS)
        ratios.append(t_fsolve / t_vec)
        print(f"  pair: fsolve {t_fsolve / n * 1e6:.0f} us/case, vectorised {t_vec / n * 1e6:.1f} "
              f"us/case, ratio {t_fsolve / t_vec:.1f}")  # fmt: skip
    print(f"vectorised / per-case fsolve speed ratio: median {statistics.median(ratios):.1f} "
          f"(min {min(ratios):.1f}, max {max(ratios):.1f}) over {PAIRS} pairs")  # fmt: skip


if __name__ == "__main__":
    main()
