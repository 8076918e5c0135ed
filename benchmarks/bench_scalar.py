"""Benchmark: one call from Python, against a per-case scipy baseline, as ratios in one run.

Run with ``make bench``. Python users call ``solve`` in loops (optimisers, time-stepping rotor
models); what counts there is the cost of one call.

Engine: ``solve(9, 1000.0, 1e5, 0.01, cage_angle=17.0)`` (a general cage angle, 2-D).
Baseline: ``scipy.optimize.root(method='hybr')`` on the same ring: the two force equations
``sum K (x cos phi_i + y sin phi_i - e)_+^1.5 (cos, sin) = (F_r, 0)`` written with numpy, started
at the one-ball approach plus the gap, ``xtol`` 1e-13 (the engine's tolerance), no Jacobian
(hybr estimates it, as a user of ``root`` would leave it).

Hertz: ``ball_stiffness(12.3, 51.0, 0.515, 0.515)`` (both raceway contacts of a 6308-size ball and
the two in series). Baseline: per contact, ``scipy.optimize.brentq`` on the ellipticity equation
``((kappa^2 + 1) E - 2 K)/((kappa^2 - 1) E) = F(rho)`` with ``scipy.special.ellipk``/``ellipe``
(parameter ``m = 1 - 1/kappa^2``), bracket [1 + 1e-12, B/A], xtol 1e-15, rtol 8.9e-16 (the
smallest brentq takes), then delta* and the stiffness from K, E as in the module, and the series.

The core's own time for one case: the same case 10 000 times in one call, per case (each case
is solved in the core's C loop from its own data; the set-up of the call is included).

Timing: the best of 7 rounds of many calls each, engine and baseline interleaved, so that a
busy machine slows both alike. Single thread: BLAS threads are pinned to 1.
"""

from __future__ import annotations

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")

import time  # noqa: E402
from collections.abc import Callable  # noqa: E402

import numpy as np  # noqa: E402

from bearingload.contact.hertz import ball_stiffness, reduced_modulus  # noqa: E402
from bearingload.models.equilibrium import solve  # noqa: E402

CASE = (9, 1000.0, 1e5, 0.01)
CAGE = 17.0
#: The same case 10 000 times in one call: its time per case is the core's C loop (each case
#: solved from its own data) plus the vectorised set-up, an upper bound of the core's own time.
COPIES = np.full(10_000, CAGE)
BALL = (12.3, 51.0, 0.515, 0.515)


def hybr_case(z: int, load: float, k: float, g: float, cage_deg: float) -> np.ndarray:
    """(x, y) of one case by scipy.optimize.root(method='hybr'); the per-case baseline."""
    from scipy.optimize import root

    phi = np.deg2rad(cage_deg) + 2 * np.pi * np.arange(z) / z
    c, s = np.cos(phi), np.sin(phi)
    e = g / 2

    def residual(v: np.ndarray) -> list[float]:
        d = np.maximum(v[0] * c + v[1] * s - e, 0.0)
        q = k * d**1.5
        return [float(q @ c) - load, float(q @ s)]

    start = [(load / k) ** (2 / 3) + e, 0.0]
    sol = root(residual, start, method="hybr", options={"xtol": 1e-13})
    return sol.x


def brentq_contact_stiffness(rho_x: float, rho_y: float, e_star: float) -> float:
    """Stiffness of one point contact: brentq on the ellipticity equation, scipy K and E."""
    from scipy.optimize import brentq
    from scipy.special import ellipe, ellipk

    small, large = min(rho_x, rho_y), max(rho_x, rho_y)
    f_rho = (large - small) / (large + small)

    def residual(kappa: float) -> float:
        m = 1.0 - 1.0 / kappa**2
        k_int, e_int = ellipk(m), ellipe(m)
        return ((kappa**2 + 1) * e_int - 2 * k_int) / ((kappa**2 - 1) * e_int) - f_rho

    kappa = brentq(residual, 1 + 1e-12, large / small, xtol=1e-15, rtol=8.9e-16)
    m = 1.0 - 1.0 / kappa**2
    k_int, e_int = ellipk(m), ellipe(m)
    d_star = 2.0 * k_int / np.pi * (np.pi / (2.0 * kappa**2 * e_int)) ** (1.0 / 3.0)
    return float(4.0 * np.sqrt(2.0) / 3.0 * e_star / (d_star**1.5 * np.sqrt(rho_x + rho_y)))


def brentq_ball_stiffness(dw: float, dm: float, fi: float, fo: float) -> float:
    """Ball stiffness (both contacts in series) from the brentq contacts; the baseline."""
    e_star = float(reduced_modulus())
    k_i = brentq_contact_stiffness(2 * dm / (dw * (dm - dw)), (2 * fi - 1) / (fi * dw), e_star)
    k_o = brentq_contact_stiffness(2 * dm / (dw * (dm + dw)), (2 * fo - 1) / (fo * dw), e_star)
    return (k_i ** (-2 / 3) + k_o ** (-2 / 3)) ** -1.5


def interleaved(fns: dict[str, Callable[[], object]], calls: dict[str, int], rounds: int = 7):
    """Best seconds per call of each function, rounds interleaved."""
    best = dict.fromkeys(fns, float("inf"))
    for _ in range(rounds):
        for name, fn in fns.items():
            t0 = time.perf_counter()
            for _ in range(calls[name]):
                fn()
            best[name] = min(best[name], (time.perf_counter() - t0) / calls[name])
    return best


def main() -> None:
    engine = solve(*CASE, cage_angle=CAGE)
    ref = hybr_case(*CASE, CAGE)  # also imports scipy outside the timing
    agreement = max(abs(float(engine.x) / ref[0] - 1), abs(float(engine.y) / ref[1] - 1))
    k_ball = float(ball_stiffness(*BALL).ball)
    k_agreement = abs(k_ball / brentq_ball_stiffness(*BALL) - 1)
    t = interleaved(
        {
            "solve": lambda: solve(*CASE, cage_angle=CAGE),
            "batch": lambda: solve(*CASE, cage_angle=COPIES),
            "solve_sym": lambda: solve(*CASE),
            "hybr": lambda: hybr_case(*CASE, CAGE),
            "hertz": lambda: ball_stiffness(*BALL),
            "brentq": lambda: brentq_ball_stiffness(*BALL),
        },
        {"solve": 2000, "batch": 5, "solve_sym": 2000, "hybr": 300, "hertz": 2000, "brentq": 300},
    )
    print("one call from Python (best of 7 interleaved rounds; one core)")
    print(f"  solve(9, 1000.0, 1e5, 0.01, cage_angle=17.0): {t['solve'] * 1e6:8.1f} us")
    print(f"  solve(9, 1000.0, 1e5, 0.01) (symmetric)     : {t['solve_sym'] * 1e6:8.1f} us")
    print(f"  scipy.optimize.root(hybr), same ring        : {t['hybr'] * 1e6:8.1f} us")
    print(f"  ratio solve / hybr                          : {t['solve'] / t['hybr']:8.3f}")
    print(f"  agreement (x, y)                            : {agreement:8.1e}")
    per_case = t["batch"] / COPIES.size
    print(f"  the core's time for one case (one call of {COPIES.size} copies, per case)")
    print(f"                                              : {per_case * 1e6:8.2f} us")
    print(f"  ratio core / hybr                           : {per_case / t['hybr']:8.3f}")
    print(f"  ball_stiffness(12.3, 51.0, 0.515, 0.515)    : {t['hertz'] * 1e6:8.1f} us")
    print(f"  brentq + scipy ellipk/ellipe, both contacts : {t['brentq'] * 1e6:8.1f} us")
    print(f"  ratio ball_stiffness / brentq               : {t['hertz'] / t['brentq']:8.3f}")
    print(f"  agreement (ball stiffness)                  : {k_agreement:8.1e}")


if __name__ == "__main__":
    main()
