# cython: language_level=3
"""The complete elliptic integrals of a Hertz contact by the arithmetic-geometric mean, in C.

The one implementation of :func:`bearingload.numerics.elliptic_integrals` (which documents the
method: Abramowitz & Stegun 17.6, sums of positive terms) and of the compiled core's Hertz
stiffness curve (``bearingload.models._core`` cimports :func:`elliptic`), so that the scalar
Hertz path in Python and its copy in the core share the AGM's every bit. A module of its own, a
layer below the models: numerics cannot import the models' core. Built with the core's flags
(setup.py: no contracted multiply-add, no fast-math), so each value is that of the operations
in their written order.
"""

from libc.math cimport NAN, exp, expm1, sqrt

import numpy as np

#: Steps of the AGM at the most (it converges quadratically: 6 steps reach m = 1 - 1e-300). [-]
AGM_STEPS = 60
cdef int STEPS = AGM_STEPS
cdef double PI = 3.141592653589793


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
