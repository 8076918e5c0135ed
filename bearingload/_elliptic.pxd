# The complete elliptic integrals by the AGM (bearingload/_elliptic.pyx), for the compiled core's
# Hertz stiffness curve: the one copy, which bearingload.numerics.elliptic_integrals calls too.

cdef void agm(double p, double m, double *ell) noexcept nogil
cdef void agm2(const double *p, const double *m, double *ell) noexcept nogil
cdef void elliptic(double t, double *ell) noexcept nogil
