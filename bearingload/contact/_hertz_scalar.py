"""One Hertz point contact in pure Python: the fast path of the contact functions for scalars.

Same equation as :mod:`bearingload.contact.hertz` (Johnson 1985, §4.2; Harris & Kotzalas,
ch. 6): the ellipticity ``kappa = e^t`` solves ``ln((E - pK)/(K - E)) + 2t = ln(B/A)`` with
``p = 1/kappa^2 = 1 - m``. Here for one contact:

* K and E by the arithmetic-geometric mean (:func:`bearingload.numerics.elliptic_integrals`,
  the one the vectorised path uses; Abramowitz & Stegun 17.6);
* a start from Hamrock & Brewe's fit, then Newton with the analytic derivative (``dK/dm``,
  ``dE/dm`` in closed form) until the step is at rounding level.
"""

from __future__ import annotations

import math

from bearingload.numerics import elliptic_integrals

EPS = 2.220446049250313e-16


def _residual(t: float, target: float) -> tuple[float, float, tuple]:
    """Residual ln(n/d) + 2t - ln(B/A) and its derivative in t."""
    ell = elliptic_integrals(t)
    k_int, e_int, n, d, m, p = ell
    # dK/dm = n/(2p), dE/dm = -d/2, dm/dt = 2p; n m = E - pK, d m = K - E
    dk, de = n / (2.0 * p) * 2.0 * p, -d / 2.0 * 2.0 * p
    dn = ((de + 2.0 * p * k_int - p * dk) - n * 2.0 * p) / m  # d(n m)/dt = dE - dp K - p dK
    dd = ((dk - de) - d * 2.0 * p) / m
    return math.log(n / d) + 2.0 * t - target, dn / n - dd / d + 2.0, ell


#: ln(kappa)/ln(B/A) as a Chebyshev series in u = 2 ln(1 + L)/ln(1 + ln 1e15) - 1, fitted to
#: the exact solution by tools/fit_hertz_start.py (start within 2.6e-7; only a start).
START_CHEBYSHEV = (
    0.6144372356545134,
    -0.06798402157265024,
    -0.010881362205892586,
    0.00708062477521872,
    0.001210129551538224,
    -0.0012803796185209733,
    -5.376346780306019e-05,
    0.0002544273868212515,
    -2.5664711624450478e-05,
    -4.918005091410309e-05,
    1.213984744991505e-05,
    8.7537043377246e-06,
    -3.662694307887396e-06,
    -1.3656992476512864e-06,
    9.181196676884904e-07,
    1.4033102846808042e-07,
    -1.9665715343740822e-07,
)
_START_LOG_MAX = math.log1p(math.log(1e15))
_START_REVERSED = tuple(reversed(START_CHEBYSHEV[1:]))


def start(target: float) -> float:
    """The fitted start ``t ~ L g(u)`` (Clenshaw's recurrence)."""
    u = 2.0 * math.log1p(target) / _START_LOG_MAX - 1.0
    u2 = u + u
    b1 = b2 = 0.0
    for c in _START_REVERSED:
        b1, b2 = u2 * b1 - b2 + c, b1
    return target * (u * b1 - b2 + START_CHEBYSHEV[0])


def log_kappa(target: float) -> tuple[float, float, float]:
    """``(t, K, E)``: ``t = ln kappa`` for ``ln(B/A) = target > 0`` and K, E there.

    Newton from the fitted start. Near the circle (``t < 0.01``) the analytic derivative
    cancels; there it is ``3/2 + 3 t^2/64`` (the series), good to ``t^4``. Once a step is below
    1e-9 and 1e-3 of the one before (quadratic convergence seen), it is the last: the next
    error is below ``step^2``, and K, E follow it to first order (``dK/dt = (E - pK)/m``,
    ``dE/dt = -p (K - E)/m``), exact to ``step^2``.
    """
    t = min(start(target), target)
    previous = math.inf
    for _ in range(30):
        f, df, (k_int, e_int, n, d, _, p) = _residual(t, target)
        if t < 0.01:
            df = 1.5 + 0.046875 * t * t
        step = f / df
        if abs(step) <= 1e-9 * t and abs(step) <= 1e-3 * previous:
            return t - step, k_int - n * step, e_int + p * d * step
        new = min(max(t - step, 0.5 * t), target)
        if abs(new - t) <= 4 * EPS * t or abs(step) >= previous:
            return t, k_int, e_int
        previous = abs(step)
        t = new
    raise ArithmeticError("Hertz ellipticity: Newton did not settle")  # caller falls back


def coefficients(rho_small: float, rho_large: float) -> tuple[float, ...]:
    """(kappa, a*, b*, delta*, K, E) of one contact with curvature sums small <= large."""
    if rho_large == rho_small:
        return 1.0, 1.0, 1.0, 1.0, 0.5 * math.pi, 0.5 * math.pi
    t, k_int, e_int = log_kappa(math.log(rho_large) - math.log(rho_small))
    kappa = math.exp(t)
    a_star = (2.0 * kappa**2 * e_int / math.pi) ** (1.0 / 3.0)
    b_star = (2.0 * e_int / (math.pi * kappa)) ** (1.0 / 3.0)
    d_star = 2.0 * k_int / math.pi * (math.pi / (2.0 * kappa**2 * e_int)) ** (1.0 / 3.0)
    return kappa, a_star, b_star, d_star, k_int, e_int


def stiffness(rho_x: float, rho_y: float, e_star: float) -> float:
    """K of one point contact, (4 sqrt 2 / 3) E* / (delta*^1.5 sqrt(sum rho)). [N/mm^1.5]"""
    if rho_x == rho_y:
        d_star = 1.0
    else:
        small, large = (rho_x, rho_y) if rho_x < rho_y else (rho_y, rho_x)
        t, k_int, e_int = log_kappa(math.log(large) - math.log(small))
        d_star = (
            2.0 * k_int / math.pi * (math.pi / (2.0 * math.exp(2.0 * t) * e_int)) ** (1.0 / 3.0)
        )
    return 4.0 * math.sqrt(2.0) / 3.0 * e_star / (d_star**1.5 * math.sqrt(rho_x + rho_y))
