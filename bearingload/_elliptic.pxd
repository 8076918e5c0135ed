# One Hertz point contact in C (bearingload/_elliptic.pyx): the complete elliptic integrals by
# the AGM (the one copy, which bearingload.numerics.elliptic_integrals calls too), the
# ellipticity's Newton steps, the coefficients and the stiffness, for contact.hertz and for the
# compiled core's Hertz stiffness curve. The Newton step and the tests of a contact (its
# curvature ratio, the circle's series) are defined here, inline: the core's curve takes them at
# each node of each contact (a call through the module's table cost it 5 %).

from libc.float cimport DBL_EPSILON
from libc.math cimport exp, expm1, fabs, log

cdef enum:
    NEWTON_STEPS = 30  # Newton steps of the ellipticity at the most

cdef void agm(double p, double m, double *ell) noexcept nogil
cdef void agm2(const double *p, const double *m, double *ell) noexcept nogil
cdef void elliptic(double t, double *ell) noexcept nogil
cdef double ellipticity_start(double target) noexcept nogil
cdef int log_kappa(double target, double t, double previous, double *out, bint node,
                   int steps) noexcept nogil
cdef int solve_ellipticity(double target, int steps, double *got) noexcept nogil
cdef int ellipticity(double small, double large, int steps, double *got) noexcept nogil
cdef void coefficients(const double *got, double *out) noexcept nogil
cdef double contact_stiffness(const double *rho, double e_star, const double *got) noexcept nogil
cdef double in_series(double k_inner, double k_outer) noexcept nogil


cdef inline void p_m(double t, bint node, double *p, double *m) noexcept nogil:
    """p = e^-2t and m = -expm1(-2t) (``elliptic``'s bits); at a ``node`` of the core's curve
    beyond t = 0.35, m = 1 - p (rounded once, p < 1/2: as close)."""
    p[0] = exp(-2.0 * t)
    m[0] = 1.0 - p[0] if node and t > 0.35 else -expm1(-2.0 * t)


cdef inline bint newton_last(double target, double *t, double *previous, const double *ell,
                             bint node, double *out) noexcept nogil:
    """One Newton step at ``t`` on the residual ln((E - pK)/(K - E)) + 2t - ln(B/A), the
    integrals there ``ell`` (``agm``): True where it was the last (``out`` set: t, K, E,
    dt/d(target), p), else t and the step before, ``previous``, moved on.

    The slope: dK/dm = n/(2p), dE/dm = -d/2, dm/dt = 2p (n m = E - pK, d m = K - E); at a
    ``node`` of the core's curve the same in one quotient (only a step's). Near the circle
    (``t < 0.01``) it cancels; there it is ``3/2 + 3 t^2/64`` (the series), good to ``t^4``.
    Once a step is below 1e-9 and 1e-3 of the one before (quadratic convergence seen), it is
    the last: the next error is below ``step^2``, and K, E, p follow it to first order
    (``dK/dt = (E - pK)/m``, ``dE/dt = -p (K - E)/m``), exact to ``step^2``. A step that
    no longer moves t, or grows, ends at t."""
    cdef double k_int = ell[0], n = ell[2], d = ell[3], m = ell[4], p = ell[5], dk, de, df, step
    if node:
        df = (p * (2.0 * k_int - d - 3.0 * n) * d - (n - p * d) * n) / (m * n * d) + 2.0
    else:
        dk = n / (2.0 * p) * 2.0 * p
        de = -d / 2.0 * 2.0 * p
        df = ((((de + 2.0 * p * k_int - p * dk) - n * 2.0 * p) / m) / n
              - (((dk - de) - d * 2.0 * p) / m) / d + 2.0)
    if t[0] < 0.01:
        df = 1.5 + 0.046875 * t[0] * t[0]
    step = (log(n / d) + 2.0 * t[0] - target) / df
    out[3], out[4] = 1.0 / df, p
    if fabs(step) <= 1e-9 * t[0] and fabs(step) <= 1e-3 * previous[0]:
        out[0], out[1], out[2] = t[0] - step, ell[0] - ell[2] * step, ell[1] + ell[5] * ell[3] * step
        out[4] += p * (2.0 * step)
        return True
    if fabs(min(max(t[0] - step, 0.5 * t[0]), target) - t[0]) <= 4 * DBL_EPSILON * t[0] or fabs(
            step) >= previous[0]:
        out[0], out[1], out[2] = t[0], ell[0], ell[1]
        return True
    previous[0] = fabs(step)
    t[0] = min(max(t[0] - step, 0.5 * t[0]), target)
    return False


cdef inline bint near_circle(double target, double *got) noexcept nogil:
    """True and ``got`` of ``ellipticity`` where ``target = ln(B/A) < 1e-6``, by the series of the
    residual, ``ln(B/A) = 3t/2 + t^3/64 + O(t^5)``: ``t = t0 - t0^3/96``, ``t0 = 2 target/3``
    (its next term ~t^5, far below t's rounding). There the residual's rounding (~eps, not
    relative to t) is above Newton's stopping test (a step below 1e-9 t): below ln(B/A) ~ 4e-15
    Newton did not settle."""
    cdef double t0, t, p, m
    cdef double ell[6]
    if not target < 1e-6:
        return False
    t0 = target / 1.5
    t = t0 - t0 * t0 * t0 / 96.0
    p_m(t, False, &p, &m)
    agm(p, m, ell)
    got[0], got[1], got[2], got[3], got[4] = t, ell[0], ell[1], 1.0 / (1.5 + 0.046875 * t * t), p
    return True


cdef inline double max_ratio() noexcept nogil:
    """The largest ratio of curvature sums of a point contact (kappa ~ 1e7, a line contact for
    every practical purpose; contact.hertz refuses beyond it). [-]"""
    return 1e15


cdef inline bint admissible(double small, double large) noexcept nogil:
    """A point contact of curvature sums ``small <= large``: ``small > 0``, ``large <=
    max_ratio() small`` (contact.hertz refuses the rest)."""
    return small > 0 and large <= max_ratio() * small
