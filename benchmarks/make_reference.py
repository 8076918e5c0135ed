"""Write the high-precision reference of ``bearingload accuracy``: Q_max of the exact ring equilibrium.

Run ``python benchmarks/make_reference.py`` (needs mpmath, a test dependency) to regenerate
``bearingload/quality/data/accuracy_reference.csv``. It shares no code with the package: the ring
equilibrium is written out here again in mpmath at 50 significant digits and solved by bisection.

The cases (the fixed set of the accuracy report): bearing 306 of Kuzmenko (2010, §3.4: F_r =
300 kgf, K = 4700 kgf/mm^1.5) with z = 6, 8, 12, 20, 40 balls, radial clearance G_r = -20 (preload),
0, 20 (the paper's Delta = 0.01 mm), 100 and 400 um, a ball under the load (cage angle 0) and the
load between two balls (cage angle 180/z), m = 3/2: 50 cases.

Both cage angles are symmetric about the load line, so y = 0 and the one unknown x solves
``sum_i K max(x cos(phi_i) - e, 0)^m cos(phi_i) = F_r`` (e = G_r/2), which increases in x; the
root is bracketed by x = max(e, 0) (residual -F_r) and a doubled upper bound, then bisected to
1e-45 relative. Q_max is the load of the ball nearest the load line.
"""

from __future__ import annotations

import os
import sys

import mpmath as mp

KGF = 9.80665  # N, exact by definition
LOAD = 300 * KGF  # N
STIFFNESS = 4700 * KGF  # N/mm^1.5
BALLS = (6, 8, 12, 20, 40)
CLEARANCES = (-0.020, 0.0, 0.020, 0.100, 0.400)  # mm
EXPONENT = 1.5
DIGITS = 50
OUT = os.path.join(
    os.path.dirname(__file__), "..", "bearingload", "quality", "data", "accuracy_reference.csv"
)


def reference_k(z: int, load: float, stiffness: float, clearance: float, half: bool) -> mp.mpf:
    """k = Q_max/F_r of the symmetric ring, at DIGITS digits."""
    with mp.workdps(DIGITS + 10):
        f, kk, e, m = mp.mpf(load), mp.mpf(stiffness), mp.mpf(clearance) / 2, mp.mpf(EXPONENT)
        shift = mp.mpf(1) / 2 if half else 0
        cosines = [mp.cos(2 * mp.pi * (i + shift) / z) for i in range(z)]

        def residual(x: mp.mpf) -> mp.mpf:
            total = mp.mpf(0)
            for c in cosines:
                d = x * c - e
                if d > 0:
                    total += kk * d**m * c
            return total - f

        lo = max(e, mp.mpf(0))
        hi = lo + (f / kk) ** (1 / m) + abs(e) + 1
        while residual(hi) <= 0:
            hi *= 2
        while hi - lo > mp.mpf(10) ** (-DIGITS + 5) * hi:
            mid = (lo + hi) / 2
            if residual(mid) > 0:
                hi = mid
            else:
                lo = mid
        x = (lo + hi) / 2
        c_max = max(cosines)
        return kk * (x * c_max - e) ** m / f


def main() -> None:
    lines = ["case,balls,load [N],stiffness [N/mm^1.5],clearance [mm],cage_angle [deg],k_reference"]
    n = 0
    for z in BALLS:
        for g in CLEARANCES:
            for half in (False, True):
                n += 1
                k = reference_k(z, LOAD, STIFFNESS, g, half)
                cage = repr(180.0 / z) if half else "0.0"
                lines.append(
                    f"{n},{z},{LOAD!r},{STIFFNESS!r},{g!r},{cage},{mp.nstr(k, 30, strip_zeros=False)}"
                )
                print(lines[-1], file=sys.stderr)
    with open(OUT, "w", encoding="utf-8", newline="\n") as fh:
        fh.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
