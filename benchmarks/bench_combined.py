"""Benchmark: the combined-load solver against the radial engine and against scipy fsolve.

Run with ``make bench``. Two parts, each as ratios measured in the same run.

1. Against the radial engine, same cases: cases per second of
   * the radial engine (models.equilibrium.solve) on (z, F_r, K, G_r, cage angle),
   * the combined solver (models.combined.solve_combined) on the same cases with F_a = 0 and with
     an axial load, once with a constant ball stiffness and once with the Hertz stiffness at each
     ball's contact angle (the default),
   and the ratio of each to the radial engine. The combined solver takes one z per call: the
   cases are grouped by z, as a user with a batch would.

2. Against the baseline a user would write: per case, ``scipy.optimize.fsolve`` on the three
   equilibrium equations of the inner ring in (x, a, theta) of a 6205 (catalogue geometry), cage
   angle 0 (symmetric, so y = theta_c = 0), free tilt (M = 0), one constant ball stiffness K:
   ``rho_j = A - G_r/2 + x cos phi_j``, ``u_j = a + R_i theta cos phi_j``, ``delta_j =
   sqrt(rho_j^2 + u_j^2) - A``, ``Q_j = K max(delta_j, 0)^1.5`` (models/combined.py) and
   ``sum Q_j (cos alpha_j cos phi_j, sin alpha_j, R_i sin alpha_j cos phi_j) = (F_r, F_a, 0)``;
   no Jacobian (fsolve estimates it), xtol 1e-13, started at x = G_r/2 + (F_r/K)^(2/3) and the
   axial offset where z balls at sin(alpha) = 0.3 carry F_a, theta = 0. Times: one scalar
   ``solve_combined`` call (stiffness=K, the Hertz default, and the Hertz default on a pitch
   diameter new to every call: no set-up cached) over one fsolve call, and one
   vectorised call on N_VECTOR cases per case over fsolve per case; agreement of the ball loads
   with ``solve_combined(..., stiffness=K)``, and how many fsolve runs did not report success.

``--profile``: instead, cProfile of one scalar ``solve_combined`` call (the 25 functions of most
cumulative time). Single thread: BLAS threads are pinned to 1.
"""

from __future__ import annotations

import os
import sys

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")


import time  # noqa: E402
from collections.abc import Callable  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from bench_solver import best_of  # noqa: E402

from bearingload.bearings.resolve import resolve_bearing  # noqa: E402
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


def against_radial() -> None:
    """Part 1: the combined solver against the radial engine on the same cases."""
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


#: Part 2: cases timed one call each (scalar, fsolve); cases compared with fsolve; cases of one
#: vectorised call.
N_SCALAR = 100
N_CHECK = 1_000
N_VECTOR = 10_000


def bearing_6205() -> tuple[int, dict[str, float], float]:
    """z, the geometry keywords of solve_combined, and the ball stiffness K [N/mm^1.5] of a 6205."""
    b = resolve_bearing("6205")
    geometry = {"ball_diameter": b.ball_diameter, "pitch_diameter": b.pitch_diameter,
                "f_i": b.f_i, "f_o": b.f_o, "modulus": b.modulus, "poisson": b.poisson}  # fmt: skip
    return b.balls, geometry, float(b.stiffness)


def fsolve_case(
    z: int, fr: float, fa: float, gr: float, k: float, geometry: dict[str, float]
) -> tuple[np.ndarray, bool]:
    """Ball loads [N] of one case by scipy fsolve on (x, a, theta), and whether it converged."""
    from scipy.optimize import fsolve

    dw, dm, fi = geometry["ball_diameter"], geometry["pitch_diameter"], geometry["f_i"]
    big_a = (fi + geometry["f_o"] - 1.0) * dw
    e = gr / 2.0
    r_i = dm / 2.0 + (fi - 0.5) * dw * (1.0 - e / big_a)  # cos(alpha_0) = 1 - G_r/(2A)
    c = np.cos(2.0 * np.pi * np.arange(z) / z)

    def loads(v: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        rho, u = big_a - e + v[0] * c, v[1] + r_i * v[2] * c
        d = np.hypot(rho, u)
        return k * np.maximum(d - big_a, 0.0) ** 1.5, rho / d, u / d

    def residual(v: np.ndarray) -> list[float]:
        q, cos_a, sin_a = loads(v)
        return [q @ (cos_a * c) - fr, q @ sin_a - fa, r_i * (q @ (sin_a * c))]

    axial = big_a * big_a - (big_a - e) ** 2 + 2.0 * big_a * (fa / (z * k * 0.3)) ** (2.0 / 3.0)
    start = [e + (fr / k) ** (2.0 / 3.0), np.sqrt(axial), 0.0]
    v = fsolve(residual, start, xtol=1e-13)
    # converged: the force residual, not fsolve's flag (which reports xtol 1e-13 as not reached)
    return loads(v)[0], bool(np.max(np.abs(residual(v))) <= 1e-8 * max(fr, fa))


def interleaved(fns: dict[str, Callable[[], object]], rounds: int = 5) -> dict[str, float]:
    """Best seconds of each function over ``rounds`` rounds, the functions interleaved."""
    best = dict.fromkeys(fns, float("inf"))
    for _ in range(rounds):
        for name, fn in fns.items():
            t0 = time.perf_counter()
            fn()
            best[name] = min(best[name], time.perf_counter() - t0)
    return best


_CALLS = [0]


def new_geometry(geo: dict[str, float]) -> dict[str, float]:
    """``geo`` with a pitch diameter never given before in this run (1e-9 of it apart per
    call): a bearing whose Hertz set-up no cache holds."""
    _CALLS[0] += 1
    return geo | {"pitch_diameter": geo["pitch_diameter"] * (1.0 + 1e-9 * _CALLS[0])}


def baseline_per_case(rounds: int = 5) -> float:
    """Seconds per case of the fsolve baseline (:func:`fsolve_case` on N_SCALAR cases drawn as
    those of part 2), best of ``rounds``: the reference of the one-call ratios of bench_angular
    and bench_pair, measured in their run."""
    z, geo, k = bearing_6205()
    fr, fa, gr = fsolve_cases(N_SCALAR, np.random.default_rng(SEED + 1))
    few = [(float(fr[i]), float(fa[i]), float(gr[i])) for i in range(N_SCALAR)]
    fsolve_case(z, *few[0], k, geo)  # imports scipy
    best = interleaved({"fsolve": lambda: [fsolve_case(z, *c, k, geo) for c in few]}, rounds)
    return best["fsolve"] / N_SCALAR


def fsolve_cases(n: int, rng: np.random.Generator) -> tuple[np.ndarray, ...]:
    """F_r 10 N-5 kN, F_a 0.1-1 F_r, G_r 0 (1 in 5) or 1-50 um; cage angle 0."""
    fr = 10 ** rng.uniform(1, np.log10(5000.0), n)
    fa = fr * rng.uniform(0.1, 1.0, n)
    gr = np.where(rng.random(n) < 0.2, 0.0, 10 ** rng.uniform(-3, np.log10(0.05), n))
    return fr, fa, gr


def against_fsolve() -> None:
    """Part 2: scalar and vectorised solve_combined against a per-case fsolve, same run."""
    z, geo, k = bearing_6205()
    fr, fa, gr = fsolve_cases(N_VECTOR, np.random.default_rng(SEED + 1))
    cases = [(float(fr[i]), float(fa[i]), float(gr[i])) for i in range(N_CHECK)]
    few = cases[:N_SCALAR]
    ref = [fsolve_case(z, *case, k, geo) for case in cases]  # also imports scipy before timing
    failed = sum(not ok for _, ok in ref)
    vec = solve_combined(z, fr, fa, clearance=gr, stiffness=k, **geo)
    q = np.asarray(vec.ball_loads)[:N_CHECK]
    q_ref = np.array([loads for loads, ok in ref])
    ok = np.array([ok for _, ok in ref])
    diff = np.max(np.abs(q - q_ref)[ok], axis=1) / np.max(q_ref[ok], axis=1)

    def scalar(**extra: float) -> Callable[[], object]:
        return lambda: [solve_combined(z, a, b, clearance=g, **geo, **extra) for a, b, g in few]

    t = interleaved({
        "fsolve": lambda: [fsolve_case(z, *case, k, geo) for case in few],
        "scalar K": scalar(stiffness=k),
        "scalar Hertz": scalar(),
        "scalar new geometry": lambda: [
            solve_combined(z, a, b, clearance=g, **new_geometry(geo)) for a, b, g in few
        ],
        "vector K": lambda: solve_combined(z, fr, fa, clearance=gr, stiffness=k, **geo),
        "vector Hertz": lambda: solve_combined(z, fr, fa, clearance=gr, **geo),
    })  # fmt: skip
    per = {name: t[name] / (N_VECTOR if name.startswith("vector") else N_SCALAR) for name in t}
    print("combined solver against a per-case scipy fsolve on (x, a, theta) (one core)")
    print(f"  6205 (z = {z}, K = {k:.4g} N/mm^1.5), F_r 10 N-5 kN, F_a 0.1-1 F_r, cage 0, M = 0,")
    print("  G_r 0 (1 in 5) or 1-50 um; best of 5 interleaved rounds")
    kinds = {"K": "constant K", "Hertz": "Hertz K(alpha)"}
    print(f"  fsolve, one case                          : {per['fsolve'] * 1e6:9.1f} us")
    for kind, label in [*kinds.items(), ("new geometry", "Hertz, new geom.")]:
        ratio = per[f"scalar {kind}"] / per["fsolve"]
        print(
            f"  solve_combined, one case, {label:16s}: {per[f'scalar {kind}'] * 1e6:9.1f} us"
            f"  ({ratio:5.2f} x the fsolve time; target <= 0.1)"
        )
    for kind, label in kinds.items():
        speed = per["fsolve"] / per[f"vector {kind}"]
        print(f"  {N_VECTOR:,} cases in one call, {label:16s}: {per[f'vector {kind}'] * 1e6:9.1f}"
              f" us/case  ({speed:5.1f} x faster than fsolve; target >= 50)")  # fmt: skip
    print(f"  agreement, {N_CHECK:,} cases, constant K     : max_j |Q_j - Q_j,fsolve| / "
          f"Q_max,fsolve = {diff.max():.1e}; fsolve failed on {failed} (left out)")  # fmt: skip


def profile() -> None:
    """cProfile of one scalar solve_combined call (6205, F_r 1 kN, F_a 500 N, G_r 12.5 um),
    with the constant K and with the Hertz default."""
    import cProfile
    import pstats

    z, geo, k = bearing_6205()
    for label, extra in (("constant K", {"stiffness": k}), ("Hertz default", {})):
        solve_combined(z, 1000.0, 500.0, clearance=0.0125, **geo, **extra)  # warm-up
        prof = cProfile.Profile()
        prof.enable()
        for _ in range(100):
            solve_combined(z, 1000.0, 500.0, clearance=0.0125, **geo, **extra)
        prof.disable()
        print(f"cProfile of 100 scalar solve_combined calls ({label}), by cumulative time")
        pstats.Stats(prof).sort_stats("cumulative").print_stats(25)


def main() -> None:
    if "--profile" in sys.argv[1:]:
        profile()
        return
    against_radial()
    against_fsolve()


if __name__ == "__main__":
    main()
