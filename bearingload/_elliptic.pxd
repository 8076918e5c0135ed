# One Hertz point contact in C (bearingload/_elliptic.pyx): the complete elliptic integrals by
# the AGM (the one copy, which bearingload.numerics.elliptic_integrals calls too), the
# ellipticity's Newton steps, the coefficients and the stiffness, for contact.hertz and for the
# compiled core's Hertz stiffness curve.

cdef enum:
    NEWTON_STEPS = 30  # Newton steps of the ellipticity at the most

cdef void agm(double p, double m, double *ell) noexcept nogil
cdef void agm2(const double *p, const double *m, double *ell) noexcept nogil
cdef void elliptic(double t, double *ell) noexcept nogil
cdef double ellipticity_start(double target) noexcept nogil
cdef void p_m(double t, bint node, double *p, double *m) noexcept nogil
cdef bint newton_last(double target, double *t, double *previous, const double *ell, bint node,
                      double *out) noexcept nogil
cdef int log_kappa(double target, double t, double previous, double *out, bint node,
                   int steps) noexcept nogil
cdef bint near_circle(double target, double *got) noexcept nogil
cdef bint admissible(double small, double large) noexcept nogil
cdef int ellipticity(double small, double large, int steps, double *got) noexcept nogil
cdef void coefficients(const double *got, double *out) noexcept nogil
cdef double contact_stiffness(const double *rho, double e_star, const double *got) noexcept nogil
cdef double in_series(double k_inner, double k_outer) noexcept nogil
