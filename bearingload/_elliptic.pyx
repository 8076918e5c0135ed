# cython: language_level=3
"""One Hertz point contact in C: the complete elliptic integrals by the arithmetic-geometric mean,
the ellipticity's root, the dimensionless coefficients and the contact stiffness.

The one implementation of :func:`bearingload.numerics.elliptic_integrals` (which documents the
AGM: Abramowitz & Stegun 17.6, sums of positive terms), of the Hertz point contact of
:mod:`bearingload.contact.hertz` (one contact or an array of them, each element by the same C
function) and of the single-contact pieces of the compiled core's Hertz stiffness curve
(``bearingload.models._core`` cimports them, ``_elliptic.pxd``), so that Python and the core
share every bit. A module of its own, a layer below contact/ and the models (numerics and
contact cannot import the models' core). Built with the core's flags (setup.py: no contracted
multiply-add, no fast-math), so each value is that of the operations in their written order.

The ellipticity (Johnson 1985, §4.2; Harris & Kotzalas, ch. 6): ``kappa = e^t`` solves
``ln((E - pK)/(K - E)) + 2t = ln(B/A)`` with ``p = 1/kappa^2 = 1 - m``, by Newton with the
analytic derivative (``dK/dm``, ``dE/dm`` in closed form) from a fitted start
(``START_CHEBYSHEV``, tools/fit_hertz_start.py) until the step is at rounding level.
"""

from libc.math cimport INFINITY, NAN, exp, expm1, fabs, log, log1p, pow, sqrt

import numpy as np

#: Steps of the AGM at the most (it converges quadratically: 6 steps reach m = 1 - 1e-300). [-]
AGM_STEPS = 60
cdef int STEPS = AGM_STEPS
cdef double PI = 3.141592653589793
#: Newton steps of the ellipticity at the most (it settles in 2 to 5; _elliptic.pxd). [-]
HERTZ_STEPS = NEWTON_STEPS
#: The largest ratio of curvature sums of a point contact (contact.hertz.MAX_CURVATURE_RATIO;
#: ``admissible``, _elliptic.pxd). [-]
MAX_RATIO = max_ratio()

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
cdef enum:
    START_TERMS = 17
cdef double START[START_TERMS]
START[:] = START_CHEBYSHEV
cdef double START_LOG_MAX = log1p(log(max_ratio()))


cdef inline void agm_end(double a, double rest, double p, double m, double *ell) noexcept nogil:
    """``agm``'s values from its last ``a`` and its sum ``rest`` (m > 0; m = 0: rest = 0)."""
    cdef double total = 0.5 + rest / m if m > 0 else 0.5, k_int = PI / (2.0 * a)
    ell[0] = k_int
    ell[3] = k_int * total  # (K - E)/m
    ell[1] = k_int - m * ell[3]
    # (E - pK)/m: near the circle as K (1/2 - sum_{n>=1} 2^(n-1) c_n^2/m), else directly
    ell[2] = k_int * (1.0 - total) if p > 0.5 else (ell[1] - p * k_int) / m
    ell[4] = m
    ell[5] = p


cdef void agm(double p, double m, double *ell) noexcept nogil:
    """``ell`` = K, E, (E - pK)/m, (K - E)/m, m, p from ``p = 1/kappa^2`` and ``m = 1 - p`` (each
    given rounded once). The AGM from ``a_0 = 1``, ``b_0 = sqrt p``, ``c_0^2 = m``, with
    ``c_(n+1) = c_n^2 / (4 a_(n+1))`` (no cancellation), stops where the term ``2^(n-1) c_n^2``
    is below ``1e-17 m``; ``m = 0`` (the circle) takes no step and gives its limits
    ``K = E = pi/2``, ``(K - E)/m = (E - pK)/m = pi/4``; outside the domain (``m < 0``: an
    ellipticity ``kappa < 1``, or NaN) every value is NaN."""
    cdef double a = 1.0, b = sqrt(p), c2 = m, rest = 0.0, weight = 0.5, small = 1e-17 * m
    cdef double a_next, c, term
    cdef int i
    if not m >= 0:
        for i in range(6):
            ell[i] = NAN
        return
    if m > 0:
        for i in range(STEPS):
            a_next = 0.5 * (a + b)
            c = c2 / (4.0 * a_next)
            b = sqrt(a * b)
            a = a_next
            c2 = c * c
            weight += weight
            term = weight * c2
            rest = rest + term
            if term <= small:
                break
    agm_end(a, rest, p, m, ell)


cdef void agm2(const double *p, const double *m, double *ell) noexcept nogil:
    """``agm`` of two (p, m), m > 0, into ell[:6] and ell[6:], in one loop of steps (the two
    chains of square roots and quotients side by side), until both terms are below 1e-17 m:
    a lane done first takes the other's further steps, which leave its a within an ulp."""
    cdef double a[2]
    cdef double b[2]
    cdef double c2[2]
    cdef double rest[2]
    cdef double term[2]
    cdef double weight = 0.5, a_next, c
    cdef int i, k
    for k in range(2):
        a[k], b[k], c2[k], rest[k] = 1.0, sqrt(p[k]), m[k], 0.0
    for i in range(STEPS):
        weight += weight
        for k in range(2):
            a_next = 0.5 * (a[k] + b[k])
            c = c2[k] / (4.0 * a_next)
            b[k] = sqrt(a[k] * b[k])
            a[k] = a_next
            c2[k] = c * c
            term[k] = weight * c2[k]
            rest[k] = rest[k] + term[k]
        if term[0] <= 1e-17 * m[0] and term[1] <= 1e-17 * m[1]:
            break
    agm_end(a[0], rest[0], p[0], m[0], ell)
    agm_end(a[1], rest[1], p[1], m[1], ell + 6)


cdef void elliptic(double t, double *ell) noexcept nogil:
    """``agm`` at ``kappa = e^t``: ``p = exp(-2t)``, ``m = -expm1(-2t)`` by the C library."""
    agm(exp(-2.0 * t), -expm1(-2.0 * t), ell)


# ----------------------------------------------------------------- one Hertz point contact


cdef double ellipticity_start(double target) noexcept nogil:
    """The fitted start ``t ~ L g(u)`` at ``L = ln(B/A) = target`` (Clenshaw's recurrence)."""
    cdef double u = 2.0 * log1p(target) / START_LOG_MAX - 1.0, u2, b1 = 0.0, b2 = 0.0, b0
    cdef int i
    u2 = u + u
    for i in range(START_TERMS - 1, 0, -1):
        b0 = u2 * b1 - b2 + START[i]
        b2 = b1
        b1 = b0
    return target * (u * b1 - b2 + START[0])


cdef int log_kappa(double target, double t, double previous, double *out, bint node,
                   int steps) noexcept nogil:
    """``out`` = t = ln kappa for ``ln(B/A) = target > 0``, K and E there, dt/d(target) (at the
    last step) and p = e^-2t, by at most ``steps`` Newton steps (``newton_last``) from ``t``
    (``previous`` the step before it, at first infinite); 0 where it did not settle (``out[0]``
    its last t)."""
    cdef double ell[6]
    cdef double p, m
    cdef int i
    for i in range(steps):
        p_m(t, node, &p, &m)
        agm(p, m, ell)
        if newton_last(target, &t, &previous, ell, node, out):
            return 1
    out[0] = t
    return 0


cdef int solve_ellipticity(double target, int steps, double *got) noexcept nogil:
    """``got`` = t, K, E, dt/d(target), p for ``target = ln(B/A) > 0``: ``near_circle``, else at
    most ``steps`` of Newton (``log_kappa``) from the fitted start; 0 where it did not settle."""
    if near_circle(target, got):
        return 1
    return log_kappa(target, min(ellipticity_start(target), target), INFINITY, got, False, steps)


cdef int ellipticity(double small, double large, int steps, double *got) noexcept nogil:
    """``got`` = t, K, E, dt/d(target), p of one contact of curvature sums ``small <= large``
    (the circle: 0, pi/2, pi/2, -, 1; else ``solve_ellipticity`` at ln(B/A) = ln large - ln
    small); 0 outside a point contact (``admissible``) or where Newton did not settle."""
    got[0], got[1], got[2], got[4] = 0.0, PI / 2, PI / 2, 1.0
    if not admissible(small, large):
        return 0
    if small == large:
        return 1
    return solve_ellipticity(log(large) - log(small), steps, got)


cdef void coefficients(const double *got, double *out) noexcept nogil:
    """``out`` = kappa, a*, b*, delta*, K, E from ``ellipticity``'s ``got`` (Harris's a*, b*,
    delta*: contact.hertz's module notes); the circle (t = 0) exactly 1, 1, 1, 1, pi/2, pi/2."""
    cdef double kappa = exp(got[0]), k_int = got[1], e_int = got[2]
    out[4], out[5] = k_int, e_int
    if got[0] == 0:
        out[0] = out[1] = out[2] = out[3] = 1.0
        return
    out[0] = kappa
    out[1] = pow(2.0 * pow(kappa, 2.0) * e_int / PI, 1.0 / 3.0)
    out[2] = pow(2.0 * e_int / (PI * kappa), 1.0 / 3.0)
    out[3] = 2.0 * k_int / PI * pow(PI / (2.0 * pow(kappa, 2.0) * e_int), 1.0 / 3.0)


cdef double contact_stiffness(const double *rho, double e_star, const double *got) noexcept nogil:
    """K of one point contact of curvature sums ``rho`` (2) from ``ellipticity``'s ``got``:
    (4 sqrt 2 / 3) E* / (delta*^1.5 sqrt(sum rho)). [N/mm^1.5]"""
    cdef double d_star = 1.0
    if rho[0] != rho[1]:
        d_star = 2.0 * got[1] / PI * pow(PI / (2.0 * exp(2.0 * got[0]) * got[2]), 1.0 / 3.0)
    return 4.0 * sqrt(2.0) / 3.0 * e_star / (pow(d_star, 1.5) * sqrt(rho[0] + rho[1]))


cdef double in_series(double k_inner, double k_outer) noexcept nogil:
    """Two point contacts under one load in series: (k_i^(-2/3) + k_o^(-2/3))^(-3/2)."""
    return pow(pow(k_inner, -1.0 / 1.5) + pow(k_outer, -1.0 / 1.5), -1.5)


def at(double t):
    """(K, E, (E - pK)/m, (K - E)/m, m, p) at ``kappa = e^t``, Python floats."""
    cdef double ell[6]
    elliptic(t, ell)
    return ell[0], ell[1], ell[2], ell[3], ell[4], ell[5]


def of_arrays(p_in, m_in):
    """K, E, (E - pK)/m, (K - E)/m of ``agm`` at each element of the arrays ``p`` and ``m`` (one
    shape): four contiguous arrays of that shape (numpy's loops round by the layout too)."""
    p_a = np.ascontiguousarray(p_in, dtype=float).reshape(-1)
    m_a = np.ascontiguousarray(m_in, dtype=float).reshape(-1)
    cdef const double[::1] p = p_a
    cdef const double[::1] m = m_a
    cdef Py_ssize_t n = p.shape[0], i
    cdef double ell[6]
    out_a = np.empty((4, n))
    cdef double[:, ::1] out = out_a
    with nogil:
        for i in range(n):
            agm(p[i], m[i], ell)
            out[0, i], out[1, i], out[2, i], out[3, i] = ell[0], ell[1], ell[2], ell[3]
    return tuple(row.reshape(np.shape(p_in)) for row in out_a)


def start(double target):
    """The fitted start of Newton, ln kappa ~ ``ellipticity_start(ln(B/A))``, a Python float."""
    return ellipticity_start(target)


def point(double small, double large):
    """(kappa, a*, b*, delta*, K, E) of one point contact of curvature sums ``small <= large``
    (``ellipticity``, ``coefficients``), or None where ``ellipticity`` gives 0."""
    cdef double got[5]
    cdef double out[6]
    if not ellipticity(small, large, NEWTON_STEPS, got):
        return None
    coefficients(got, out)
    return out[0], out[1], out[2], out[3], out[4], out[5]


def ball(double inner_x, double inner_y, double outer_x, double outer_y, double e_star):
    """(K_i, K_o, K) of a ball: its inner and outer contacts' ``contact_stiffness`` (curvature
    sums of each) and the two ``in_series``, or None where ``ellipticity`` gives 0. [N/mm^1.5]"""
    cdef double rho[4]
    cdef double got[10]
    cdef double k[2]
    cdef int c
    rho[0], rho[1], rho[2], rho[3] = inner_x, inner_y, outer_x, outer_y
    for c in range(2):
        if not ellipticity(min(rho[2 * c], rho[2 * c + 1]), max(rho[2 * c], rho[2 * c + 1]),
                           NEWTON_STEPS, &got[5 * c]):
            return None
        k[c] = contact_stiffness(&rho[2 * c], e_star, &got[5 * c])
    return k[0], k[1], in_series(k[0], k[1])


def points(small_in, large_in, int steps=NEWTON_STEPS):
    """``point`` of each element of the arrays ``small`` and ``large`` (one shape), by at most
    ``steps`` Newton steps each: the six arrays (kappa, a*, b*, delta*, K, E) of that shape and
    a bool array, True where the element did not settle (its kappa ln kappa's last iterate, the
    other five NaN)."""
    small_a = np.ascontiguousarray(small_in, dtype=float).reshape(-1)
    large_a = np.ascontiguousarray(large_in, dtype=float).reshape(-1)
    cdef const double[::1] small = small_a
    cdef const double[::1] large = large_a
    cdef Py_ssize_t n = small.shape[0], i
    cdef double got[5]
    out_a = np.empty((n, 6))
    failed_a = np.zeros(n, dtype=bool)
    cdef double[:, ::1] out = out_a
    cdef unsigned char[::1] failed = failed_a.view(np.uint8)
    with nogil:
        for i in range(n):
            if ellipticity(small[i], large[i], steps, got):
                coefficients(got, &out[i, 0])
            else:
                failed[i] = 1
                out[i, 0] = got[0]
                out[i, 1] = out[i, 2] = out[i, 3] = out[i, 4] = out[i, 5] = NAN
    shape = np.shape(small_in)
    return tuple(col.reshape(shape) for col in out_a.T), failed_a.reshape(shape)
