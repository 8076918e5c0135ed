# ==================================================================== the radial engine
#
# Included by _core.pyx (one extension): the ring equations of the radial bearing (Kurochkin
# 1973, eqs. 1.1-1.8; bearingload.models.equilibrium gives the model and the scaled units).
# The inner ring moves by (a, b); ball j at (c[j], s[j]) = (cos, sin) of its angle from the load
# line, multiplicity w[j], is compressed by delta_j = a c_j + b s_j - e u_j and carries
# w_j max(delta_j, 0)^m (``ring_sums``); under a preload p = -e the forces are summed as
# p^m ((1 + t)^m - 1), t = (a c + b s)/p, whose p^m cancel around the ring (``ring_sums_pre``).
# ``ring_forces`` (the forward problem of bearingload.models.forces) evaluates these sums at
# given positions.

from libc.math cimport M_PI, cos, exp, expm1, log1p, pow, sin

ctypedef struct RingSet:
    # the balls of one ring (arrays of k angles) and the work arrays of an evaluation
    int k
    double *c
    double *s
    double *u      # gap factor of each ball (1 in the forward problem and under preload)
    double *w      # multiplicity (or the ball stiffness in the forward problem)
    double *delta  # approach of each ball at the last evaluation
    double *q      # load and slope of each ball at the last evaluation, or NULL
    double *dq
    double e       # gap per side (scaled: e_hat); under preload -p
    double m       # load-deflection exponent
    bint pre       # preload: the centred formulation (p = -e > 0)

ctypedef struct Sums:
    # the sums of one evaluation: sum w q (c, s); sum w dq (cc, cs, ss); sum |w q| (or of the
    # preload terms); the potential sum w q delta/(m + 1) (or its preload form)
    double gx, gy, hxx, hxy, hyy, size, energy


cdef inline void sums_zero(Sums *o) noexcept nogil:
    o.gx = 0.0
    o.gy = 0.0
    o.hxx = 0.0
    o.hxy = 0.0
    o.hyy = 0.0
    o.size = 0.0
    o.energy = 0.0


cdef inline void sums_add(Sums *o, double wq, double wdq, double c, double s) noexcept nogil:
    cdef double dc = wdq * c
    o.gx += wq * c
    o.gy += wq * s
    o.hxx += dc * c
    o.hxy += dc * s
    o.hyy += wdq * s * s


cdef void ring_sums(const RingSet *r, double a, double b, Sums *o) noexcept nogil:
    """The ball sums at (a, b), a clearance (or none): one-sided loads q = max(delta, 0)^m,
    slopes m delta^(m-1) (0 where unloaded), the energy sum w q delta (not yet over m + 1)."""
    cdef int j
    cdef double d, root, q, dq, wq
    sums_zero(o)
    for j in range(r.k):
        d = a * r.c[j] + b * r.s[j] - r.e * r.u[j]
        r.delta[j] = d
        q = 0.0
        dq = 0.0
        if d > 0.0:
            root = sqrt(d) if r.m == 1.5 else pow(d, r.m - 1.0)
            q = d * root
            dq = r.m * root
        if r.q != NULL:
            r.q[j] = q
            r.dq[j] = dq
        if d > 0.0:
            wq = r.w[j] * q
            sums_add(o, wq, r.w[j] * dq, r.c[j], r.s[j])
            o.size += wq
            o.energy += wq * d


cdef void ring_sums_pre(const RingSet *r, double a, double b, Sums *o) noexcept nogil:
    """The ball sums at (a, b) from the centred ring under a preload p = -e: the force terms
    p^m ((1 + t)^m - 1) (-p^m where a ball has lifted off), the energy terms p^(m+1)
    ((1 + t)^(m+1) - 1 - (m + 1) t) (not yet over m + 1); ``size`` sums |terms|."""
    cdef int j
    cdef double p = -r.e, m = r.m, t, lg, term, q, dq, br, move, wt
    cdef double pm = pow(p, m), pm1 = pow(p, m - 1.0)
    sums_zero(o)
    for j in range(r.k):
        move = a * r.c[j] + b * r.s[j]
        t = move / p
        if t > -1.0:
            lg = log1p(t)
            term = pm * expm1(m * lg)
            q = pm * exp(m * lg)
            dq = m * pm1 * exp((m - 1.0) * lg)
            br = expm1((m + 1.0) * lg) - (m + 1.0) * t
        else:
            term = -pm
            q = 0.0
            dq = 0.0
            br = -1.0 - (m + 1.0) * t
        r.delta[j] = p + move
        if r.q != NULL:
            r.q[j] = q
            r.dq[j] = dq
        wt = r.w[j] * term
        sums_add(o, wt, r.w[j] * dq, r.c[j], r.s[j])
        o.size += fabs(wt)
        o.energy += r.w[j] * pm * (p * br)


cdef inline double snap(double v) noexcept nogil:
    """A cosine or sine below 1e-14 in size is the rounding of an exact zero."""
    return 0.0 if fabs(v) < 1e-14 else v


cdef void forward_case(RingSet *r, double x, double y, double k, double e, double phi1_deg,
                       double m, double *out, int *loaded) noexcept nogil:
    """The forward problem of one case: ``r`` holds the ball directions of the cage's frame
    (ball 1 on its first axis), ``r.w`` the stiffness K of every ball, ``r.q`` the ball loads'
    output; the displacement is turned into that frame and the force (fx, fy) and the tangent
    (kxx, kxy, kyy) into ``out`` turned back (F = R F', K = R K' R^T)."""
    cdef double rad = phi1_deg * (M_PI / 180.0)
    cdef double c1 = snap(cos(rad)), s1 = snap(sin(rad))
    cdef double cc = c1 * c1, cs = c1 * s1, ss = s1 * s1
    cdef Sums o
    cdef int j
    r.e = e
    r.m = m
    ring_sums(r, x * c1 + y * s1, y * c1 - x * s1, &o)
    loaded[0] = 0
    for j in range(r.k):
        if r.delta[j] > 0.0:
            loaded[0] += 1
    out[0] = c1 * o.gx - s1 * o.gy
    out[1] = s1 * o.gx + c1 * o.gy
    out[2] = cc * o.hxx - 2.0 * cs * o.hxy + ss * o.hyy
    out[3] = cs * (o.hxx - o.hyy) + (cc - ss) * o.hxy
    out[4] = ss * o.hxx + 2.0 * cs * o.hxy + cc * o.hyy


def ring_forces(int z, const double[:] x, const double[:] y, const double[:] k,
                const double[:] e, const double[:] phi1, const double[:] m):
    """The forward problem over n cases (bearingload.models.forces.ring_forces): ``x``, ``y``,
    ``k`` (the ball stiffness), ``e`` (the gap per side), ``phi1`` (the cage angle in [0, 360)
    degrees), ``m``, each of n (broadcast views welcome). Returns (out (n, 5): fx, fy, kxx, kxy,
    kyy; loads (n, z); loaded (n,) int64)."""
    cdef Py_ssize_t n = x.shape[0], i
    cdef int j
    out_a = np.empty((n, 5))
    loads_a = np.empty((n, z))
    loaded_a = np.empty(n, dtype=np.int64)
    cdef double[:, ::1] out = out_a, loads = loads_a
    cdef int64_t[::1] loaded = loaded_a
    cdef double *block = <double *> malloc(6 * max(z, 1) * sizeof(double))
    cdef RingSet r
    cdef int count
    if block == NULL:
        raise MemoryError("ring_forces: no memory for the balls of one case")
    r.k = z
    r.c = block
    r.s = block + z
    r.u = block + 2 * z
    r.w = block + 3 * z
    r.delta = block + 4 * z
    r.dq = block + 5 * z
    r.pre = False
    with nogil:
        for j in range(z):
            r.c[j] = snap(cos((360.0 * j / z) * (M_PI / 180.0)))
            r.s[j] = snap(sin((360.0 * j / z) * (M_PI / 180.0)))
            r.u[j] = 1.0
        for i in range(n):
            for j in range(z):
                r.w[j] = k[i]
            r.q = &loads[i, 0]
            forward_case(&r, x[i], y[i], k[i], e[i], phi1[i], m[i], &out[i, 0], &count)
            loaded[i] = count
            for j in range(z):
                loads[i, j] *= k[i]
    free(block)
    return out_a, loads_a, loaded_a
