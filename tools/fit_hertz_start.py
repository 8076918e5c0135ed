"""Fit the start of the scalar Hertz solver: ln(kappa)/ln(B/A) as a Chebyshev series.

The Hertz point contact in C (bearingload/_elliptic.pyx: contact.hertz and the compiled core's
K_0) starts Newton from this fit and refines to rounding level; the fit only saves iterations.
Regenerate with ``python tools/fit_hertz_start.py`` and paste the printed tuple into
``START_CHEBYSHEV`` of bearingload/_elliptic.pyx (the one copy; the build turns it into the C
table the start sums), then rebuild; tests/test_hertz.py checks the pasted coefficients start
within 3e-7 of the exact solution.

Variable: u = 2 ln(1 + L)/ln(1 + L_max) - 1, L = ln(B/A) in (0, ln 1e15]; fitted: t/L.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.polynomial import chebyshev

from bearingload.contact import hertz

DEGREE = 16
L_MAX = math.log(hertz.MAX_CURVATURE_RATIO)


def main() -> None:
    ell = np.linspace(1e-9, L_MAX, 4000)
    t = np.log(np.asarray(hertz.hertz_coefficients(1.0, np.exp(ell)).kappa, dtype=float))
    u = 2.0 * np.log1p(ell) / math.log1p(L_MAX) - 1.0
    coef = chebyshev.chebfit(u, t / ell, DEGREE)
    err = np.max(np.abs(chebyshev.chebval(u, coef) * ell - t) / t)
    print(f"# max relative error of the start: {err:.2e}")
    print("START_CHEBYSHEV = (")
    for c in coef:
        print(f"    {float(c)!r},")
    print(")")


if __name__ == "__main__":
    main()
