"""Benchmark: the ball dynamics at speed (:mod:`bearingload.models.high_speed`) against a per-case
fsolve, and one case alone.

Run: ``make bench`` or ``.venv/bin/python benchmarks/bench_speed.py``.
Targets: one case at speed in <= 0.5 ms (the per-case constant-K fsolve of
bench_combined.py); the vectorised solve >= 20 times a per-case
``scipy.optimize.fsolve`` on the same equations.
The baseline: per case, fsolve on the 3 + 2 z equations of a 7205-sized angular-contact bearing
(D_w 7.938 mm, d_m 38.5 mm, f_i 0.52, f_o 0.53, 13 balls, cage angle 0, free tilt): the ring's
F_r, F_a and moment equations in (x, a, R_i theta) and every ball's two equations in (delta_o,
alpha_o), the model's equations as a user writes them in numpy (:func:`ball_equations`, K_i and
K_o the solver's Hertz interpolants), no Jacobian, xtol 1e-12, started at the
static answer (solve_combined, not timed) with every ball on its line. Cases: contact angle
10-45°, F_r and F_a 10-5000 N, n 1000-26 000 rpm (n d_m <= 1e6 mm/min). The vectorised call is
``solve_high_speed(13, F_r, F_a, speed=n, contact_angle=a0)`` on all cases at once (its static
start included). The machine is shared: the two are timed in pairs, the ratio of each pair
printed, and their median.

The one case is timed 20 times (median), and so is its static start alone (``solve_combined`` on
the same case, the floor of the one-case time: the dynamics start from its answer), and the
compiled core's solve of the dynamics within it (``_core.solve_speed``). ``--profile`` prints
cProfile's table of the one case (20 calls) instead of the batch comparison.
"""

from __future__ import annotations

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import math  # noqa: E402
import statistics  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from types import SimpleNamespace  # noqa: E402
from typing import Any  # noqa: E402

import numpy as np  # noqa: E402

from bearingload.models import high_speed as hs  # noqa: E402
from bearingload.models.combined import angular_geometry, solve_combined  # noqa: E402

Z = 13
GEO = {"ball_diameter": 7.938, "pitch_diameter": 38.5, "f_i": 0.52, "f_o": 0.53}
N_CASES, PAIRS, SEED = 100, 3, 20261124


def ball_equations(
    b: Any, rho: np.ndarray, u: np.ndarray, do: np.ndarray, ao: np.ndarray
) -> tuple[np.ndarray, ...]:
    """The two equations of every ball and its (F_a, F_r) on the ring, in numpy (the model of
    :mod:`bearingload.models.high_speed`): (g1, g2, F_a, F_r)."""
    lo, so, co = b.ro + do, np.sin(ao), np.cos(ao)
    e1, e2 = u - lo * so, np.maximum(rho - lo * co, 0.0)
    li = np.hypot(e1, e2)
    si, ci = e1 / li, e2 / li
    qi = hs.stiffness(b.ki, ci) * np.maximum(li - b.ri, 0.0) ** 1.5
    qo = hs.stiffness(b.ko, co) * np.maximum(do, 0.0) ** 1.5
    gamma = b.dw / b.dm
    tb = so / (co + gamma)
    beta = np.arctan(tb)
    c_o = (co + tb * so) / (1.0 + gamma * co)
    c_i = (ci + tb * si) / (1.0 - gamma * ci)
    wc = b.omega * c_o / (c_o + c_i)
    wr = b.omega / (gamma * np.cos(beta) * (c_o + c_i))
    fc = 0.5 * b.mass * b.dm * wc * wc * 1e-3
    fr = 2.0 * 0.1 * b.mass * b.dw * wr * wc * np.sin(beta) * 1e-3
    return (qi * si - qo * so + fr * co, qi * ci - qo * co - fr * so + fc, qi * si, qi * ci)


def fsolve_case(fr: float, fa: float, n: float, alpha: float) -> bool:
    """One case by fsolve on its 3 + 2z equations; whether the ring residual is 1e-8."""
    from scipy.optimize import fsolve

    dw, dm, fi, fo = (np.array([GEO[k]]) for k in ("ball_diameter", "pitch_diameter", "f_i",
                                                    "f_o"))  # fmt: skip
    geo = angular_geometry(dw, dm, fi, fo, np.array([alpha]))
    balls = hs.ball_set(
        geo, np.array([208000.0]), np.array([0.3]), np.array([n]), np.array([7850.0])
    )
    names = ("ri", "ro", "dw", "dm", "omega", "mass")
    b = SimpleNamespace(
        ki=balls.ki, ko=balls.ko, **{k: balls.consts[:, i : i + 1] for i, k in enumerate(names)}
    )
    c = np.cos(2.0 * np.pi * np.arange(Z) / Z)[None, :]
    big_a, g, r_i = geo.A[0], geo.g[0], geo.R_i[0]
    s = solve_combined(Z, fr, fa, contact_angle=alpha, modulus=208000.0, **GEO)
    shift = big_a * math.sin(geo.alpha0[0])
    v0 = [s.x, s.axial + shift, r_i * math.radians(s.tilt)]

    def geometry(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        rho = big_a - g + v[0] * c
        return rho, np.maximum(v[1] + v[2] * c, 0.0)

    rho0, u0 = geometry(np.array(v0))
    # each ball on its line, the approach shared by the contacts as their compliances
    d0 = np.hypot(np.maximum(rho0, 0.0), u0)
    cos0 = np.maximum(rho0, 0.0) / d0
    ci, co = (hs.stiffness(k, cos0) ** (-2.0 / 3.0) for k in (b.ki, b.ko))
    do0 = np.maximum(co / (ci + co) * (d0 - b.ri - b.ro), 1e-6)
    ao0 = np.arctan2(u0, np.maximum(rho0, 0.0))

    def residual(w: np.ndarray) -> np.ndarray:
        rho, u = geometry(w[:3])
        t = ball_equations(b, rho, u, w[3 : 3 + Z][None, :], w[3 + Z :][None, :])
        fa_j, fr_j = t[2][0], t[3][0]
        ring = [fr_j @ c[0] - fr, fa_j.sum() - fa, (fa_j * c[0]).sum()]
        return np.concatenate([ring, t[0][0], t[1][0]])

    w = fsolve(residual, np.concatenate([v0, do0[0], ao0[0]]), xtol=1e-12)
    return bool(np.max(np.abs(residual(w)[:3])) <= 1e-8 * max(fr, fa))


def one_case() -> None:
    hs.solve_high_speed(Z, 800.0, 1500.0, speed=20000.0, contact_angle=40.0, modulus=208000.0,
                        **GEO)  # fmt: skip


def one_case_report() -> None:
    """The one case: its median time, its static start's, and the core's solve within it."""
    from bearingload.models import _core

    def median_ms(f: object, runs: int = 20) -> float:
        times = []
        for _ in range(runs):
            t0 = time.perf_counter()
            f()  # type: ignore[operator]
            times.append(time.perf_counter() - t0)
        return statistics.median(times) * 1e3

    static = median_ms(lambda: solve_combined(Z, 800.0, 1500.0, contact_angle=40.0,
                                              modulus=208000.0, **GEO))  # fmt: skip
    total = median_ms(one_case)
    core, solve = [], _core.solve_speed

    def timed(*args: Any) -> Any:
        t0 = time.perf_counter()
        out = solve(*args)
        core.append(time.perf_counter() - t0)
        return out

    _core.solve_speed = timed
    try:
        for _ in range(20):
            one_case()
    finally:
        _core.solve_speed = solve
    print(
        f"one case at speed (7205-sized, 20 000 rpm): median {total:.2f} ms (target <= 0.5 ms); "
        f"its static start alone {static:.2f} ms, the core's solve of the dynamics "
        f"{statistics.median(core) * 1e3:.3f} ms"
    )


def main() -> None:
    one_case()
    if "--profile" in sys.argv:
        import cProfile
        import pstats

        prof = cProfile.Profile()
        prof.runcall(lambda: [one_case() for _ in range(20)])
        pstats.Stats(prof).sort_stats("tottime").print_stats(25)
        return
    rng = np.random.default_rng(SEED)
    fr = rng.uniform(10.0, 5000.0, N_CASES)
    fa = rng.uniform(10.0, 5000.0, N_CASES)
    n = rng.uniform(1000.0, 26000.0, N_CASES)
    alpha = rng.uniform(10.0, 45.0, N_CASES)
    kw = dict(contact_angle=alpha, modulus=208000.0, **GEO)
    hs.solve_high_speed(Z, fr[:2], fa[:2], speed=n[:2], **dict(kw, contact_angle=alpha[:2]))
    one_case_report()
    t0 = time.perf_counter()
    for i in range(N_CASES):
        hs.solve_high_speed(Z, fr[i], fa[i], speed=n[i], **dict(kw, contact_angle=alpha[i]))
    print(f"the {N_CASES} cases one by one: {(time.perf_counter() - t0) / N_CASES * 1e3:.1f} ms a "
          "case")  # fmt: skip
    ratios = []
    for _ in range(PAIRS):
        t0 = time.perf_counter()
        ok = sum(fsolve_case(fr[i], fa[i], n[i], alpha[i]) for i in range(N_CASES))
        t_fsolve = time.perf_counter() - t0
        t0 = time.perf_counter()
        hs.solve_high_speed(Z, fr, fa, speed=n, **kw)
        t_vec = time.perf_counter() - t0
        ratios.append(t_fsolve / t_vec)
        print(f"  fsolve {t_fsolve * 1e3:.0f} ms ({ok}/{N_CASES} converged), vectorised "
              f"{t_vec * 1e3:.0f} ms: {ratios[-1]:.1f}x")  # fmt: skip
    print(f"vectorised vs per-case fsolve, {N_CASES} cases: median {statistics.median(ratios):.1f}x"
          " (target >= 20x)")  # fmt: skip


if __name__ == "__main__":
    main()
