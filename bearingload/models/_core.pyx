# cython: language_level=3
"""The compiled core of the ball-bearing ring equilibrium (C-level Cython): its build, its
kernels over the structs of ``_core.pxd``, its batches and statuses, and what it solves for
each model: docs/architecture.md, "The compiled core".

One case is one C call: the scaled problem of :mod:`bearingload.models._combined_ring` (its
docstring gives the model, the scaled units and why each piece keeps its digits) solved by

1. Newton in plain double precision, the ball stiffness following the contact angles, from the
   caller's start until double precision stops resolving the forces (``fast_newton``);
2. damped Newton with an Armijo line search on the convex potential, the ball stiffness frozen,
   the ring position and the ball approaches in double-double (``minimise``);
3. the stiffness updated to the contact angles and step 2 repeated until the update leaves the
   equilibrium (``solve_case``).
"""

from libc.math cimport (asin, atan, atan2, cbrt, copysign, cos, exp, expm1, fabs, fma, fmod, hypot,
                        isfinite, isnan, log, log1p, nextafterf, pow, rint, sin, sqrt,
                        INFINITY, NAN)
from libc.stdint cimport int64_t
from libc.stdlib cimport free, malloc
from libc.string cimport memcpy, memset

from bearingload._elliptic cimport (NEWTON_STEPS, admissible, agm, agm2, contact_stiffness,
                                    ellipticity_start, in_series, log_kappa, near_circle,
                                    newton_last, p_m, solve_ellipticity)
from bearingload.models._core cimport (NODES, Balls, Case, Dual, Dyn, Limits, Loads, Point, Ring,
                                      Shaft, ShaftState, Speed, SpeedLimits)

import numpy as np

#: Relative residual of every applied component each case is driven below. [-]
TOLERANCE = 1e-12
#: A residual within this times the sum of the magnitudes of its terms is their rounding: 8 eps
#: (the campaign, tests/campaign_combined.py, balances every component whose terms stay below
#: 1e3 times its load to <= 9.9e-13 of that load; 64 eps allowed 3.2e-12 there). [-]
ROUNDING = 8.0 * 2.220446049250313e-16
#: A component without an applied load is measured against the rounding of its terms or, where
#: those vanish with it at the answer, this times the largest applied load. [-]
FLOOR = 1e-6
#: Newton iterations per stiffness update (a load near the smallest accepted with a clearance of
#: about A takes up to some hundreds). [-]
MAX_ITERATIONS = 2000
#: A case near equilibrium (residual below STALL_BELOW) whose residual has not halved in STALL
#: iterations has reached its rounding. [-]
STALL = 12
STALL_BELOW = 1e-9
#: Steps a point is carried by the difference formulas before it is recomputed afresh. [-]
REFRESH = 8
#: Stiffness updates (each followed by a minimisation) before a case is given up. [-]
MAX_STIFFNESS_UPDATES = 40
#: A stiffness update that changes no ball's stiffness factor (1 + kappa) by more than this
#: share ends the updates: a minimisation stalled above the tolerance along a nearly free
#: direction (40 balls of 2.87 mm, G_r 83 µm, F_r 0.47 N, F_a 0.00087 N, the cage 1e-12° off
#: the load line: the two loaded balls leave the ring free across, the residual a cross
#: moment of 1e-16 of the load) kept moving the ring 1e-12 of the stiffness each update, each
#: leaving the residual (1.1e-10) a hair above where the minimisation ended, until the 40
#: updates ran out. [-]
cdef double KAPPA_SETTLED = 1e-11
#: Plain-double first stage: steps at most, halvings of a step, and the residual below which a
#: case is handed on to the double-double stage (which finishes it). [-]
FIRST_STAGE_STEPS = 16
FIRST_STAGE_HALVINGS = 8
HAND_ON = 1e-9

# the limits above as C values, for the kernels (one source: the Python names)
cdef Limits LIMITS
LIMITS.tolerance = TOLERANCE
LIMITS.rounding = ROUNDING
LIMITS.floor = FLOOR
LIMITS.stall_below = STALL_BELOW
LIMITS.hand_on = HAND_ON
LIMITS.max_iterations = MAX_ITERATIONS
LIMITS.stall = STALL
LIMITS.refresh = REFRESH
LIMITS.max_updates = MAX_STIFFNESS_UPDATES
LIMITS.fast_steps = FIRST_STAGE_STEPS
LIMITS.fast_halvings = FIRST_STAGE_HALVINGS

cpdef enum Status:
    OK = 0             # solved (the caller measures the residual)
    NOT_CONVERGED = 1  # the stiffness updates ran out
    NO_MEMORY = 2      # the work space of a case could not be allocated


# the radial engine (the ring of a radial bearing: its forward problem and its equilibrium)
include "_radial.pxi"


# ------------------------------------------------------------------ double-double pieces

cdef inline void two_sum(double a, double b, double *s, double *e) noexcept nogil:
    """a + b = s + e exactly (Knuth)."""
    cdef double bb
    s[0] = a + b
    bb = s[0] - a
    e[0] = (a - (s[0] - bb)) + (b - bb)


cdef inline void quick(double s, double e, double *hi, double *lo) noexcept nogil:
    """Renormalise s + e (|s| >= |e|)."""
    hi[0] = s + e
    lo[0] = e - (hi[0] - s)


cdef inline void two_prod(double a, double b, double *p, double *e) noexcept nogil:
    """a b = p + e exactly."""
    p[0] = a * b
    e[0] = fma(a, b, -p[0])


cdef inline void dd_mul(double ah, double al, double bh, double bl,
                        double *hi, double *lo) noexcept nogil:
    cdef double p, e
    two_prod(ah, bh, &p, &e)
    quick(p, e + (ah * bl + al * bh), hi, lo)


# ------------------------------------------------------------------------- the balls

cdef inline bint same_bits(double a, double b) noexcept nogil:
    """Whether a and b are the same number, the sign of a zero included (not NaN)."""
    return a == b and copysign(1.0, a) == copysign(1.0, b)


cdef inline double norm(double a, double b) noexcept nogil:
    """|(a, b)|: the scaled lengths stay far inside the range where the squares neither overflow
    nor underflow (the solver refuses loads beyond a ratio of 2e7 to the groove geometry)."""
    return sqrt(a * a + b * b)


cdef inline double curve_kappa(const Case *cs, double ca, double cam1) noexcept nogil:
    """K(alpha)/K_0 - 1 = (c - 1) D(c), D the barycentric Chebyshev interpolant of the divided
    difference at the nodes (docs/models.md, "The stiffness curve"); 0 at a constant K.
    (Its 24 quotients are independent: faster than Clenshaw's serial recurrence.)"""
    cdef double t, term, num = 0.0, den = 0.0
    cdef int k
    if cs.curve == NULL:
        return 0.0
    t = 2.0 * min(max(ca, 0.0), 1.0) - 1.0
    for k in range(NODES):
        term = cs.node_w[k] / (t - cs.node_x[k])
        num += term * cs.curve[k]
        den += term
    return cam1 * num / den


cdef inline double curve_slope(const Case *cs, double ca, double cam1) noexcept nogil:
    """d(kappa)/d(cos alpha) of the interpolant: D + (c - 1) dD/dc, the barycentric quotient
    differentiated term by term."""
    cdef double t, inv, term, num = 0.0, den = 0.0, d_num = 0.0, d_den = 0.0
    cdef int k
    t = 2.0 * min(max(ca, 0.0), 1.0) - 1.0
    for k in range(NODES):
        inv = 1.0 / (t - cs.node_x[k])
        term = cs.node_w[k] * inv
        num += term * cs.curve[k]
        den += term
        d_num -= term * inv * cs.curve[k]
        d_den -= term * inv
    return num / den + cam1 * 2.0 * (d_num * den - num * d_den) / (den * den)


# ------------------------------------------------------- the Hertz stiffness curve's nodes
#
# K(alpha) of both contacts in series at the nodes of the curve, for one geometry: the point
# contact of bearingload/_elliptic.pyx (the one C copy of contact.hertz's: the ellipticity by
# Newton on the AGM's elliptic integrals, the contact stiffness, both in series); K_0 by its
# single-contact solve (hertz.ball_stiffness's bits), the nodes from one node to the next (each
# start within 1e-10: one AGM a contact) by its Newton steps. Inputs hertz.py refuses (a
# curvature ratio beyond 1e15, Poisson's ratio outside (-1, 0.5]) or an ellipticity not settled
# come back as a status: the caller lets hertz.py say why.

cdef double PI = 3.141592653589793


cdef inline void sums(double dw, double dm, double f, double sign, double *rho) noexcept nogil:
    """The curvature sums (rho_x, rho_y) of the inner (``sign`` -1) or outer (+1) contact."""
    rho[0], rho[1] = 2.0 * dm / (dw * (dm + sign * dw)), (2.0 * f - 1.0) / (f * dw)


ctypedef struct Track:
    # one contact's ellipticity along the nodes: t and dt/d(target) at the last three targets
    # ln(B/A) (n of them so far)
    double x[3]
    double t[3]
    double d[3]
    int n


cdef double track_start(const Track *tr, double target) noexcept nogil:
    """Newton's start at ``target``: hertz.py's fitted start at the first node, then the Hermite
    interpolant (t and its slope) of the last three nodes, extrapolated (within 1e-10 of the
    root from the fourth: Newton's first step its last)."""
    cdef double z[6]
    cdef double q[6]
    cdef double t
    cdef int i, j, n = 2 * tr.n
    for i in range(n):
        z[i], q[i] = tr.x[i // 2], tr.t[i // 2]
    for j in range(1, n):  # the divided differences over x_0, x_0, x_1, x_1, ... in place
        for i in range(n - 1, j - 1, -1):
            q[i] = tr.d[i // 2] if j == 1 and i % 2 else (q[i] - q[i - 1]) / (z[i] - z[i - j])
    t = q[n - 1] if n else 0.0
    for i in range(n - 2, -1, -1):
        t = t * (target - z[i]) + q[i]
    return t if 0 < t <= target else min(ellipticity_start(target), target)


cdef inline void track_push(Track *tr, double target, const double *got) noexcept nogil:
    tr.x[2], tr.x[1], tr.x[0] = tr.x[1], tr.x[0], target
    tr.t[2], tr.t[1], tr.t[0] = tr.t[1], tr.t[0], got[0]
    tr.d[2], tr.d[1], tr.d[0] = tr.d[1], tr.d[0], got[3]
    tr.n = min(tr.n + 1, 3)


cdef int contacts(const double *rho, Track *tr, double *got) noexcept nogil:
    """``got[5k:]`` = t, K, E, dt/d(target), p of contact k (curvature sums ``rho[2k:]``) of a
    ball (the circle: 0, pi/2, pi/2, -, 1): before the tracks begin, ``ellipticity``'s solve
    (from the fitted start), then Newton from ``track_start``, the first steps of the two
    contacts at once (in one loop: ``agm2``), near the circle its series; each kept in
    ``tr[k]``. 0 where hertz.py would refuse or Newton did not settle."""
    cdef double target[2]
    cdef double t[2]
    cdef double p[2]
    cdef double m[2]
    cdef double ell[12]
    cdef double small, large, previous
    cdef bint node = tr[0].n > 0 or tr[1].n > 0, live[2]  # live: Newton from the track next
    cdef int k
    for k in range(2):
        small, large = min(rho[2 * k], rho[2 * k + 1]), max(rho[2 * k], rho[2 * k + 1])
        got[5 * k], got[5 * k + 1], got[5 * k + 2], got[5 * k + 4] = 0.0, PI / 2, PI / 2, 1.0
        if not admissible(small, large):
            return 0
        live[k], p[k], m[k] = small != large, 0.5, 0.5
        if not live[k]:
            continue
        target[k] = log(large / small) if node else log(large) - log(small)
        if node and not near_circle(target[k], &got[5 * k]):
            t[k] = track_start(&tr[k], target[k])
            p_m(t[k], True, &p[k], &m[k])
            continue
        # K_0's contact (``ellipticity``'s solve, its bits) or a node's next to the circle
        if not (node or solve_ellipticity(target[k], NEWTON_STEPS, &got[5 * k])):
            return 0
        track_push(&tr[k], target[k], &got[5 * k])
        live[k] = False
    if not node:
        return 1
    agm2(p, m, ell)
    for k in range(2):
        previous = INFINITY
        if live[k] and not (newton_last(target[k], &t[k], &previous, &ell[6 * k], True,
                                        &got[5 * k]) or
                            log_kappa(target[k], t[k], previous, &got[5 * k], True, NEWTON_STEPS)):
            return 0
        if live[k]:
            track_push(&tr[k], target[k], &got[5 * k])
    return 1


cdef inline double node_term(const double *rho, const double *got) noexcept nogil:
    """``K (p (rho_x + rho_y)/E)^(1/3)`` of one contact (``contact``'s ``got``): a ball's stiffness
    is (2 sqrt 2 pi/3) E* y^-1.5, y the sum of its two contacts' (their K^(-2/3) in series:
    delta* (sum rho)^(1/3), delta* = (2K/pi) (pi p/(2E))^(1/3), over (2/pi)^(2/3))."""
    return got[1] * cbrt(got[4] * (rho[0] + rho[1]) / got[2])


cdef int hertz_curve(const double *geo, const double *node_x, double *k0,
                     double *values) noexcept nogil:
    """K_0 = K(alpha = 0) (hertz.ball_stiffness's bits: both contacts in series) and the
    divided differences ``(K(c)/K_0 - 1)/(c - 1) = ((y_0/y)^1.5 - 1)/(c - 1)`` at the nodes
    ``c = (x + 1)/2`` (``node_term``'s y, each contact's ellipticity continued from the nodes
    before) of one geometry ``geo`` = (D_w, d_m, f_i, f_o, E, nu) (combined.hertz_setup); 0
    where hertz.py would refuse or not converge."""
    cdef double nu = geo[5], e_star, c, y0, y, r
    cdef double rho[4]
    cdef double got[10]
    cdef Track tr[2]
    cdef int i
    if not (nu > -1.0 and nu <= 0.5):
        return 0
    e_star = 1.0 / ((1.0 - nu * nu) / geo[4] + (1.0 - nu * nu) / geo[4])
    tr[0].n = tr[1].n = 0
    for i in range(-1, NODES):
        c = (node_x[i] + 1.0) / 2.0 if i >= 0 else 1.0
        sums(geo[0], geo[1] / c, geo[2], -1.0, rho)
        sums(geo[0], geo[1] / c, geo[3], 1.0, rho + 2)
        if not contacts(rho, tr, got):
            return 0
        y = node_term(rho, got) + node_term(rho + 2, got + 5)
        if i < 0:
            y0 = y
            k0[0] = in_series(contact_stiffness(rho, e_star, got),
                              contact_stiffness(rho + 2, e_star, got + 5))
        else:
            r = y0 / y
            values[i] = (r * sqrt(r) - 1.0) / (c - 1.0)
    return 1


cdef int curve_of(const double *geo, const double *before, bint reuse, const double *node_x,
                  double *k0, double *values) noexcept nogil:
    """``hertz_curve`` of one case's geometry ``geo`` (6), or where ``reuse`` (the case before
    it set up, its geometry ``before``, its K_0 and values just before ``k0`` and ``values``)
    and the six are the same, that case's values (the same bits)."""
    cdef int i
    cdef bint same = reuse
    for i in range(6):
        same = same and geo[i] == before[i]
    if not same:
        return hertz_curve(geo, node_x, k0, values)
    k0[0] = k0[-1]
    for i in range(NODES):
        values[i] = values[i - NODES]
    return 1


def hertz_curves(const double[:, ::1] geometry, const double[::1] node_x):
    """K_0 (n,) and the stiffness curve's values (n, NODES) of every case's geometry (n, 6):
    D_w, d_m, f_i, f_o, E, nu (``hertz_curve``), and which cases hertz.py would refuse (n,)
    uint8. A case of the same geometry as the one before it takes its values (the same bits)."""
    cdef Py_ssize_t n = geometry.shape[0], k
    k0_a = np.empty(n)
    values_a = np.empty((n, NODES))
    bad_a = np.zeros(n, dtype=np.uint8)
    cdef double[::1] k0 = k0_a
    cdef double[:, ::1] values = values_a
    cdef unsigned char[::1] bad = bad_a
    with nogil:
        for k in range(n):
            bad[k] = not curve_of(&geometry[k, 0], &geometry[k - 1 if k else 0, 0],
                                  k > 0 and not bad[k - 1 if k else 0], &node_x[0], &k0[k],
                                  &values[k, 0])
    return k0_a, values_a, bad_a


cdef void reference(const Case *cs, const double *vh, const double *vl, Balls b) noexcept nogil:
    """Every ball at the position vh + vl in double-double arithmetic (_combined_ring's notes:
    d^2 - B^2 = m (m + 2B) + u^2, m = rho - B)."""
    cdef int j
    cdef double c, s, p1, e1, p2, e2, r, e, m, e3, m_hi, m_lo, n_hi, n_lo
    cdef double t_hi, t_lo, u1, f1, u2, f2, u, e4, u_hi, u_lo, ud
    cdef double mn_hi, mn_lo, uu_hi, uu_lo, d2, rho, up, d, sign, edge
    two_sum(vh[3], cs.t_imp, &t_hi, &t_lo)
    for j in range(cs.z):
        c = cs.c[j]
        s = cs.s[j]
        two_prod(vh[0], c, &p1, &e1)
        two_prod(vh[1], s, &p2, &e2)
        two_sum(p1, p2, &r, &e)
        two_sum(r, -cs.gap, &m, &e3)
        quick(m, e3 + e + e1 + e2 + vl[0] * c + vl[1] * s, &m_hi, &m_lo)
        two_sum(m_hi, 2.0 * cs.b_hi, &n_hi, &e)
        quick(n_hi, e + m_lo + 2.0 * cs.b_lo, &n_hi, &n_lo)
        two_prod(t_hi, c, &u1, &f1)
        two_prod(vh[4], s, &u2, &f2)
        two_sum(vh[2], u1, &u, &e)
        two_sum(u, u2, &u, &e4)
        quick(u, e + e4 + f1 + f2 + vl[2] + (t_lo + vl[3]) * c + vl[4] * s, &u_hi, &u_lo)
        ud = u_hi + u_lo
        if cs.one_sided and u_hi < 0:
            u_hi = 0.0
            u_lo = 0.0
        dd_mul(m_hi, m_lo, n_hi, n_lo, &mn_hi, &mn_lo)
        dd_mul(u_hi, u_lo, u_hi, u_lo, &uu_hi, &uu_lo)
        two_sum(mn_hi, uu_hi, &d2, &e)
        d2 = d2 + (e + mn_lo + uu_lo)
        two_sum(cs.b_hi, m_hi, &rho, &e)
        rho = rho + (e + cs.b_lo + m_lo)
        up = u_hi + u_lo
        d = norm(max(rho, 0.0), up)
        sign = -1.0 if u_hi < 0 else 1.0
        two_sum(sign * u_hi, -cs.b_hi, &edge, &e)
        edge = edge + (e + sign * u_lo - cs.b_lo)
        b.rho[j] = rho
        b.u[j] = ud
        b.d[j] = d
        b.eps[j] = d2 / (d + cs.b_hi) if rho > 0 else edge
        b.up[j] = up


cdef void offset(const Case *cs, Balls ref, const double *w, Balls b,
                 double *dd, double *ddr) noexcept nogil:
    """The balls after a small move w from ref, with d - d_ref and (d - d_ref) - (rho - rho_ref)
    from the move itself (_combined_ring's notes)."""
    cdef int j
    cdef double dr, du, rho, u, rp, rp_ref, up, uu, d, den, w_new, w_ref, change
    cdef bint both
    for j in range(cs.z):
        dr = w[0] * cs.c[j] + w[1] * cs.s[j]
        du = w[2] + w[3] * cs.c[j] + w[4] * cs.s[j]
        rho = ref.rho[j] + dr
        u = ref.u[j] + du
        rp = max(rho, 0.0)
        rp_ref = max(ref.rho[j], 0.0)
        up = u
        uu = du * (ref.u[j] + u)
        if cs.one_sided:
            up = max(u, 0.0)
            if not (u > 0 and ref.u[j] > 0):
                uu = up * up - ref.up[j] * ref.up[j]
        d = norm(rp, up)
        both = rho > 0 and ref.rho[j] > 0
        den = d + ref.d[j]
        if not den > 0:
            den = 1.0
        change = ((dr * (ref.rho[j] + rho) if both else rp * rp - rp_ref * rp_ref) + uu) / den
        if both:
            w_new = up * up / (d + rho)
            w_ref = ref.up[j] * ref.up[j] / (ref.d[j] + ref.rho[j])
            ddr[j] = (uu - dr * (w_ref + w_new)) / den
        else:
            ddr[j] = change - dr
        dd[j] = change
        b.rho[j] = rho
        b.u[j] = u
        b.d[j] = d
        b.eps[j] = ref.eps[j] + change
        b.up[j] = up


cdef void loads(const Case *cs, Balls b, const double *kappa, Loads lo) noexcept nogil:
    """Ball loads (scaled, stiffness 1 + kappa) and directions (_combined_ring's notes)."""
    cdef int j
    cdef double rp, ca, sa, delta, tau
    for j in range(cs.z):
        rp = max(b.rho[j], 0.0)
        if b.d[j] > 0:
            ca = rp / b.d[j]
            sa = b.up[j] / b.d[j]
        else:
            ca = 1.0
            sa = 0.0
        lo.ca[j] = ca
        lo.sa[j] = sa
        lo.cam1[j] = -sa * sa / (1.0 + ca) if b.rho[j] > 0 else ca - 1.0
        delta = cs.pre + b.eps[j]
        lo.root[j] = sqrt(delta if delta > 0 else 0.0)
        if cs.deviation:
            tau = b.eps[j] / cs.pre
            lo.tau[j] = tau
            lo.sig[j] = tau / (1.0 + sqrt(max(1.0 + tau, 0.0)))
        else:
            lo.tau[j] = 0.0
            lo.sig[j] = 0.0
    stiff_loads(cs, b, kappa, lo)


cdef void stiff_loads(const Case *cs, Balls b, const double *kappa, Loads lo) noexcept nogil:
    """The loads of ``loads`` with the stiffness 1 + kappa, its directions, roots and
    deviations (lo.ca ... lo.sig) given: alone where only the stiffness changed."""
    cdef int j
    cdef double delta, pos, k, tau, sig
    for j in range(cs.z):
        delta = cs.pre + b.eps[j]
        pos = delta if delta > 0 else 0.0
        k = 1.0 + kappa[j]
        lo.q[j] = k * pos * lo.root[j]
        if cs.deviation:
            tau = lo.tau[j]
            sig = lo.sig[j]
            lo.dq[j] = cs.q0 * ((k * (tau + sig + tau * sig) + kappa[j]) if delta > 0 else -1.0)
        else:
            lo.dq[j] = lo.q[j]


cdef inline void add(double *sum, double *err, double x) noexcept nogil:
    """A compensated running sum (Neumaier): sum + err."""
    cdef double s, e
    two_sum(sum[0], x, &s, &e)
    sum[0] = s
    err[0] += e


cdef inline void add_ball(const Case *cs, int j, double radial, double axial, double w_r,
                          double w_a, double *gen, double *err, double *size) noexcept nogil:
    """Ball j's radial and axial forces into the generalised forces (compensated: gen + err),
    and the magnitudes w_r, w_a of its terms into their sizes."""
    cdef double c = cs.c[j], s = cs.s[j]
    add(&gen[0], &err[0], radial * c)
    add(&gen[1], &err[1], radial * s)
    add(&gen[2], &err[2], axial)
    add(&gen[3], &err[3], axial * c)
    add(&gen[4], &err[4], axial * s)
    size[0] += w_r * fabs(c)
    size[1] += w_r * fabs(s)
    size[2] += w_a
    size[3] += w_a * fabs(c)
    size[4] += w_a * fabs(s)


cdef inline void sums_open(double *gen, double *err, double *size) noexcept nogil:
    cdef int i
    for i in range(5):
        gen[i] = 0.0
        err[i] = 0.0
        size[i] = 0.0


cdef inline void sums_close(double *gen, const double *err) noexcept nogil:
    cdef int i
    for i in range(5):
        gen[i] += err[i]


cdef void forces(const Case *cs, Loads lo, double *gen, double *size) noexcept nogil:
    """The generalised ball forces sum_j (q_j - q_0) g_j + q_0 sum_j g'_j, compensated, and the
    sums of the magnitudes of their terms (_combined_ring's notes)."""
    cdef int j
    cdef double radial, axial
    cdef double err[5]
    sums_open(gen, err, size)
    for j in range(cs.z):
        radial = lo.dq[j] * lo.ca[j] + cs.q0 * lo.cam1[j]
        axial = (lo.dq[j] + cs.q0) * lo.sa[j]
        add_ball(cs, j, radial, axial, fabs(lo.dq[j] * lo.ca[j]) + cs.q0 * fabs(lo.cam1[j]),
                 (fabs(lo.dq[j]) + cs.q0) * fabs(lo.sa[j]), gen, err, size)
    sums_close(gen, err)


cdef double residual(const Case *cs, const double *gen, const double *size) noexcept nogil:
    """The largest residual of a free component over its applied load or, where larger, the
    rounding level of its terms over TOLERANCE (a component without a load: at least FLOOR);
    NaN if any is (_combined_ring.residual_of)."""
    cdef int i
    cdef double grad, ref, r, worst = 0.0
    for i in range(5):
        grad = 0.0 if cs.locked[i] else gen[i] - cs.f[i]
        ref = max(fabs(cs.f[i]), (cs.lim.rounding / cs.lim.tolerance) * size[i])
        if cs.f[i] == 0:
            ref = max(ref, cs.lim.floor)
        r = fabs(grad) / ref
        if r != r:
            return r
        worst = max(worst, r)
    return worst


cdef void evaluate(const Case *cs, const double *kappa, Point *pt) noexcept nogil:
    """Loads, forces and residual of the point's balls."""
    loads(cs, pt.b, kappa, pt.lo)
    forces(cs, pt.lo, pt.gen, pt.size)
    pt.res = residual(cs, pt.gen, pt.size)


cdef void fresh(const Case *cs, const double *vh, const double *vl, const double *kappa,
                Point *pt) noexcept nogil:
    """The point at vh + vl computed afresh in double-double."""
    reference(cs, vh, vl, pt.b)
    evaluate(cs, kappa, pt)
    pt.age = 0


# ----------------------------------------------------------------------- linear algebra

cdef inline bint turns(const Case *cs, double rho, double u) noexcept nogil:
    """Whether a ball's contact normal turns with the ring: groove centres not crossed and,
    one-sided, u > 0."""
    return rho > 0 and (not cs.one_sided or u > 0)


cdef inline void normal_directions(const Case *cs, const double *ca, const double *sa, int j,
                                   double *g, double *h) noexcept nogil:
    """g = (ca c, ca s, sa, sa c, sa s), the generalised direction of ball j's contact normal,
    and h, that of the direction in which it turns ((ca, sa) turned to (-sa, ca))."""
    g[0] = ca[j] * cs.c[j]
    g[1] = ca[j] * cs.s[j]
    g[2] = sa[j]
    g[3] = sa[j] * cs.c[j]
    g[4] = sa[j] * cs.s[j]
    h[0] = -sa[j] * cs.c[j]
    h[1] = -sa[j] * cs.s[j]
    h[2] = ca[j]
    h[3] = ca[j] * cs.c[j]
    h[4] = ca[j] * cs.s[j]


cdef void add_turn(const Case *cs, const double *ca, const double *sa, const double *w3,
                   double *hess) noexcept nogil:
    """hess += sum_j w3 g h^T (``tangent``), summed on its own first: row by row, each row's
    five sums ball by ball in local accumulators."""
    cdef int i, j
    cdef double g[5]
    cdef double h[5]
    cdef double gw, r0, r1, r2, r3, r4
    for i in range(5):
        r0 = r1 = r2 = r3 = r4 = 0.0
        for j in range(cs.z):
            normal_directions(cs, ca, sa, j, g, h)
            gw = w3[j] * g[i]
            r0 += gw * h[0]
            r1 += gw * h[1]
            r2 += gw * h[2]
            r3 += gw * h[3]
            r4 += gw * h[4]
        hess[5 * i] += r0
        hess[5 * i + 1] += r1
        hess[5 * i + 2] += r2
        hess[5 * i + 3] += r3
        hess[5 * i + 4] += r4


cdef void tangent_sums(const Case *cs, const double *ca, const double *sa, const double *w1,
                       const double *w2, double *u) noexcept nogil:
    """The upper triangle u (15 entries, row by row) of sum_j w1 g g^T + w2 h h^T
    (``tangent``), each entry summed ball by ball in a local accumulator (kept in registers:
    none can alias the inputs)."""
    cdef int j
    cdef double g0, g1, g2, g3, g4, h0, h1, h2, h3, h4, a, b
    cdef double s00 = 0.0, s01 = 0.0, s02 = 0.0, s03 = 0.0, s04 = 0.0, s11 = 0.0, s12 = 0.0
    cdef double s13 = 0.0, s14 = 0.0, s22 = 0.0, s23 = 0.0, s24 = 0.0, s33 = 0.0, s34 = 0.0
    cdef double s44 = 0.0
    for j in range(cs.z):
        g0, g1, g2 = ca[j] * cs.c[j], ca[j] * cs.s[j], sa[j]  # (``normal_directions``)
        g3, g4 = sa[j] * cs.c[j], sa[j] * cs.s[j]
        h0, h1, h2 = -sa[j] * cs.c[j], -sa[j] * cs.s[j], ca[j]
        h3, h4 = ca[j] * cs.c[j], ca[j] * cs.s[j]
        a, b = w1[j] * g0, w2[j] * h0
        s00 += a * g0 + b * h0
        s01 += a * g1 + b * h1
        s02 += a * g2 + b * h2
        s03 += a * g3 + b * h3
        s04 += a * g4 + b * h4
        a, b = w1[j] * g1, w2[j] * h1
        s11 += a * g1 + b * h1
        s12 += a * g2 + b * h2
        s13 += a * g3 + b * h3
        s14 += a * g4 + b * h4
        a, b = w1[j] * g2, w2[j] * h2
        s22 += a * g2 + b * h2
        s23 += a * g3 + b * h3
        s24 += a * g4 + b * h4
        a, b = w1[j] * g3, w2[j] * h3
        s33 += a * g3 + b * h3
        s34 += a * g4 + b * h4
        a, b = w1[j] * g4, w2[j] * h4
        s44 += a * g4 + b * h4
    u[0], u[1], u[2], u[3], u[4] = s00, s01, s02, s03, s04
    u[5], u[6], u[7], u[8], u[9] = s11, s12, s13, s14, s22
    u[10], u[11], u[12], u[13], u[14] = s23, s24, s33, s34, s44


cdef inline void direction_of(const Case *cs, const double *ca, const double *sa, int j,
                                int i, double *g, double *h) noexcept nogil:
    """Component i of ``normal_directions``'s g and h of ball j (the same products)."""
    if i == 0:
        g[0], h[0] = ca[j] * cs.c[j], -sa[j] * cs.c[j]
    elif i == 1:
        g[0], h[0] = ca[j] * cs.s[j], -sa[j] * cs.s[j]
    elif i == 2:
        g[0], h[0] = sa[j], ca[j]
    elif i == 3:
        g[0], h[0] = sa[j] * cs.c[j], ca[j] * cs.c[j]
    else:
        g[0], h[0] = sa[j] * cs.s[j], ca[j] * cs.s[j]


cdef void tangent_sums3(const Case *cs, const double *ca, const double *sa, const double *w1,
                        const double *w2, const int *free_, double *hess) noexcept nogil:
    """``tangent_sums`` where only the three components free_[:3] are free (a mirrored case:
    y and the cross tilt held): their six entries of the upper triangle into hess (the
    others left), each summed ball by ball in a local accumulator, as tangent_sums does."""
    cdef int j, i0 = free_[0], i1 = free_[1], i2 = free_[2]
    cdef double g0, g1, g2, h0, h1, h2, a, b
    cdef double s00 = 0.0, s01 = 0.0, s02 = 0.0, s11 = 0.0, s12 = 0.0, s22 = 0.0
    for j in range(cs.z):
        direction_of(cs, ca, sa, j, i0, &g0, &h0)
        direction_of(cs, ca, sa, j, i1, &g1, &h1)
        direction_of(cs, ca, sa, j, i2, &g2, &h2)
        a, b = w1[j] * g0, w2[j] * h0
        s00 += a * g0 + b * h0
        s01 += a * g1 + b * h1
        s02 += a * g2 + b * h2
        a, b = w1[j] * g1, w2[j] * h1
        s11 += a * g1 + b * h1
        s12 += a * g2 + b * h2
        a, b = w1[j] * g2, w2[j] * h2
        s22 += a * g2 + b * h2
    hess[6 * i0], hess[5 * i0 + i1], hess[5 * i0 + i2] = s00, s01, s02
    hess[6 * i1], hess[5 * i1 + i2], hess[6 * i2] = s11, s12, s22


cdef void tangent(const Case *cs, const double *ca, const double *sa, const double *w1,
                  const double *w2, const double *w3, bint hold, double *hess) noexcept nogil:
    """sum_j w1 g g^T + w2 h h^T (+ w3 g h^T where w3 is given), g and h the generalised
    directions of ball j's contact normal and of its turn (``normal_directions``): with w1 =
    dQ/d(delta), w2 = Q/d and w3 = dQ/d(alpha)/d the tangent of the ring forces. ``hold``: the
    locked components decoupled (unit rows and columns), as the Newton matrix has them: with
    three free components (a mirrored case) only their entries are summed
    (``tangent_sums3``), otherwise every entry, those of a locked component then replaced;
    each free entry is the same sum, ball by ball."""
    cdef int i, k, n = 0
    cdef int free_[5]
    cdef double upper[15]
    for i in range(5):
        if not (hold and cs.locked[i]):
            free_[n] = i
            n += 1
    if n == 3:  # (free_ ascending: its entries are upper-triangle ones)
        for i in range(25):
            hess[i] = 0.0
        tangent_sums3(cs, ca, sa, w1, w2, free_, hess)
        for i in range(5):
            for k in range(i):
                hess[5 * i + k] = hess[5 * k + i]
    else:
        n = 0
        tangent_sums(cs, ca, sa, w1, w2, upper)
        for i in range(5):
            for k in range(i, 5):
                hess[5 * i + k] = upper[n]
                hess[5 * k + i] = upper[n]
                n += 1
    if w3 != NULL:  # (a sum of the symmetric part is never -0: adding 0 would not change it)
        add_turn(cs, ca, sa, w3, hess)
    if hold:
        for i in range(5):
            if cs.locked[i]:
                for k in range(5):
                    hess[5 * i + k] = 0.0
                    hess[5 * k + i] = 0.0
                hess[6 * i] = 1.0


cdef inline void swap_rows(double *m, double *r, int a, int b) noexcept nogil:
    """Rows ``a`` and ``b`` of the 5×5 matrix ``m`` (row-major) and of ``r`` exchanged."""
    cdef int k
    cdef double t
    for k in range(5):
        t = m[5 * a + k]
        m[5 * a + k] = m[5 * b + k]
        m[5 * b + k] = t
    t = r[a]
    r[a] = r[b]
    r[b] = t


cdef void solve5(const double *a, const double *b, double *x) noexcept nogil:
    """x = a^-1 b for a 5x5 a (row-major), Gaussian elimination with partial pivoting; a
    singular a gives non-finite x (the caller's residual then stops the case)."""
    cdef double m[25]
    cdef double r[5]
    cdef int i, k, col, piv
    cdef double t
    for i in range(25):
        m[i] = a[i]
    for i in range(5):
        r[i] = b[i]
    for col in range(5):
        piv = col
        for i in range(col + 1, 5):
            if fabs(m[5 * i + col]) > fabs(m[5 * piv + col]):
                piv = i
        if piv != col:
            swap_rows(m, r, col, piv)
        for i in range(col + 1, 5):
            t = m[5 * i + col] / m[5 * col + col]
            for k in range(col, 5):
                m[5 * i + k] -= t * m[5 * col + k]
            r[i] -= t * r[col]
    for i in range(4, -1, -1):
        t = r[i]
        for k in range(i + 1, 5):
            t -= m[5 * i + k] * x[k]
        x[i] = t / m[6 * i]


cdef inline bint minus_zero(double v) noexcept nogil:
    return v == 0 and copysign(1.0, v) < 0


cdef bint held_form(const Case *cs, const double *a, const double *b) noexcept nogil:
    """Whether every held row and column of the 5x5 ``a`` is +0 but its diagonal (positive,
    finite) and ``b`` is 0 there: ``tangent``'s Newton matrix (``solve_held``)."""
    cdef int i, k
    for i in range(5):
        if not cs.locked[i]:
            continue
        if not (b[i] == 0 and a[6 * i] > 0 and isfinite(a[6 * i])):
            return False
        for k in range(5):
            if k != i and not (a[5 * i + k] == 0 and a[5 * k + i] == 0
                               and copysign(1.0, a[5 * i + k]) > 0
                               and copysign(1.0, a[5 * k + i]) > 0):
                return False
    return True


cdef void solve_held(const Case *cs, const double *a, const double *b, double *x) noexcept nogil:
    """``solve5`` of a Newton matrix whose held components are unit rows and columns
    (``held_form``), to the bit, with the arithmetic of the free rows and columns alone.
    There, solve5's operations on a held row or column are +-0 (a +0 over a finite nonzero
    pivot, times finite numbers): they change no free number but the sign of a zero of the
    right-hand side or of a back substitution's sum (x - (-0) turns -0 into +0); those signs
    are followed here. Where a pivot is 0 or not finite, or an x not finite (those +-0 would
    be NaN there), solve5 itself."""
    cdef double m[25]
    cdef double r[5]
    cdef double t
    cdef int i, k, col, piv
    if not held_form(cs, a, b):
        solve5(a, b, x)
        return
    memcpy(m, a, 25 * sizeof(double))
    memcpy(r, b, 5 * sizeof(double))
    for col in range(5):
        if cs.locked[col]:  # r[i] -= (+0 / its diagonal) r[col], each row below
            if minus_zero(r[col]):
                for i in range(col + 1, 5):
                    if minus_zero(r[i]):
                        r[i] = 0.0
            continue
        piv = col
        for i in range(col + 1, 5):
            if not cs.locked[i] and fabs(m[5 * i + col]) > fabs(m[5 * piv + col]):
                piv = i
        if piv != col:
            swap_rows(m, r, col, piv)
        if not (m[6 * col] != 0 and isfinite(m[6 * col])):
            solve5(a, b, x)
            return
        for i in range(col + 1, 5):
            if cs.locked[i]:  # r[i] -= (+0 / pivot: its sign) r[col]
                if minus_zero(r[i]) and (m[6 * col] < 0) != (copysign(1.0, r[col]) < 0):
                    r[i] = 0.0
                continue
            t = m[5 * i + col] / m[5 * col + col]
            for k in range(col, 5):
                if not cs.locked[k]:
                    m[5 * i + k] -= t * m[5 * col + k]
            r[i] -= t * r[col]
    if not back_held(cs, m, r, x):
        solve5(a, b, x)


cdef bint back_held(const Case *cs, const double *m, const double *r, double *x) noexcept nogil:
    """The back substitution of ``solve_held`` (a held row's or column's term +0 x_k, its
    sign followed); whether every x is finite."""
    cdef int i, k
    cdef double t
    for i in range(4, -1, -1):
        t = r[i]
        for k in range(i + 1, 5):
            if cs.locked[i] or cs.locked[k]:  # t -= +0 x[k]: -0 turns +0 where x[k] < 0
                if minus_zero(t) and copysign(1.0, x[k]) < 0:
                    t = 0.0
            else:
                t -= m[5 * i + k] * x[k]
        x[i] = t / m[6 * i]
        if not isfinite(x[i]):
            return False
    return True


cdef void cap_step(const Case *cs, double *step) noexcept nogil:
    """One-sided cases: the step shortened so that no axial part (a, t, t_c) exceeds A (a ball
    at u < 0 has no stiffness along its groove; _combined_ring.cap_step)."""
    cdef double longest = 0.0, shrink
    cdef int i
    if not cs.one_sided:
        return
    for i in range(2, 5):
        longest = max(longest, fabs(step[i]))
    if longest > cs.a_hat:
        shrink = cs.a_hat / longest
        for i in range(5):
            step[i] *= shrink


# ------------------------------------------------------------------- work space of a case

cdef enum:
    BALL_ARRAYS = 13  # the arrays of one Point: 5 of Balls, 8 of Loads
    FAST_ARRAYS = 8   # the ball arrays of one state of the first stage (Fast)

cdef void point_on(double *block, int z, Point *pt) noexcept nogil:
    """A Point whose ball arrays are the 13 z-blocks from block."""
    pt.b.rho = block
    pt.b.u = block + z
    pt.b.d = block + 2 * z
    pt.b.eps = block + 3 * z
    pt.b.up = block + 4 * z
    pt.lo.ca = block + 5 * z
    pt.lo.sa = block + 6 * z
    pt.lo.cam1 = block + 7 * z
    pt.lo.q = block + 8 * z
    pt.lo.dq = block + 9 * z
    pt.lo.root = block + 10 * z
    pt.lo.tau = block + 11 * z
    pt.lo.sig = block + 12 * z


ctypedef struct Work:
    Point pt       # the current point
    Point trial    # a line-search trial
    Point trial2   # its second-order correction
    double *dd     # d - d_ref of a move, (z)
    double *ddr    # (d - d_ref) - (rho - rho_ref)
    double *dd2
    double *ddr2
    double *kappa  # the frozen stiffness deviations K_j/K_0 - 1
    double *w1     # tangent weights
    double *w2
    double *fast   # the first stage's two states (2 FAST_ARRAYS z)
    int *twin      # each ball's mirror twin (``mirror_twins``)
    double *block  # the memory of all of these
    double sym[25] # the symmetric part of the tangent at pt (``stiffness``), its weights w1, w2
    bint sym_at    # whether sym and w1, w2 are those of the current point


cdef int work_open(int z, Work *wk) noexcept nogil:
    """The work space of a case of z balls, one block (its first stage's too: ``fast``, the
    two states of ``solve_case`` and the balls' mirror twins)."""
    cdef double *m = <double *> malloc(
        (3 * BALL_ARRAYS + 9 + 2 * FAST_ARRAYS) * z * sizeof(double) + 3 * z * sizeof(int))
    if m == NULL:
        return 0
    wk.block = m
    point_on(m, z, &wk.pt)
    point_on(m + BALL_ARRAYS * z, z, &wk.trial)
    point_on(m + 2 * BALL_ARRAYS * z, z, &wk.trial2)
    m += 3 * BALL_ARRAYS * z
    wk.dd = m
    wk.ddr = m + z
    wk.dd2 = m + 2 * z
    wk.ddr2 = m + 3 * z
    wk.kappa = m + 4 * z
    wk.w1 = m + 5 * z
    wk.w2 = m + 6 * z
    wk.fast = m + 9 * z
    wk.twin = <int *> (wk.fast + 2 * FAST_ARRAYS * z)
    wk.sym_at = False
    return 1


# ---------------------------------------------------------------- the double-double Newton

cdef inline double excess(double tau, double sig) noexcept nogil:
    """(1 + tau)_+^2.5 - 1 - 2.5 tau without cancellation (sig = sqrt(1 + tau) - 1)."""
    if tau > -1.0:
        return -0.5 * sig * sig + 2.0 * tau * sig + tau * tau * (1.0 + sig)
    return -1.0 - 2.5 * tau


cdef double energy_change(const Case *cs, const double *kappa, const Point *ref,
                          const Point *at, const double *w, const double *dd,
                          const double *ddr) noexcept nogil:
    """The potential at ``at`` less that at ``ref`` (_combined_ring.energy_change)."""
    cdef int j, i
    cdef double work = 0.0, linear = 0.0, bend = 0.0, total = 0.0, pre
    cdef double pos_ref, r, sig, kd
    for i in range(5):
        work += cs.f[i] * w[i]
    if cs.deviation:
        pre = cs.pre
        for j in range(cs.z):
            linear += ddr[j] + kappa[j] * dd[j]
            bend += (1.0 + kappa[j]) * (excess(at.lo.tau[j], at.lo.sig[j])
                                        - excess(ref.lo.tau[j], ref.lo.sig[j]))
        return cs.q0 * linear + pre * pre * sqrt(pre) / 2.5 * bend - work
    for j in range(cs.z):
        pos_ref = ref.lo.root[j] * ref.lo.root[j]
        kd = ref.lo.q[j] * pos_ref
        if ref.lo.root[j] > 0 and at.lo.root[j] > 0:
            r = dd[j] / pos_ref
            sig = r / (1.0 + sqrt(max(1.0 + r, 0.0)))
            total += kd * (r + excess(r, sig) / 2.5)
        else:
            total += (at.lo.q[j] * at.lo.root[j] * at.lo.root[j] - kd) / 2.5
    return total - work


cdef double first_contact(const Case *cs, const Point *pt, const double *step) noexcept nogil:
    """The step fraction (1.001 times, to first order) at which the first ball not in contact
    would touch moving along step; 1 where none would before the full step."""
    cdef int j
    cdef double delta, dr, du, rate, reach = INFINITY
    for j in range(cs.z):
        delta = cs.pre + pt.b.eps[j]
        dr = step[0] * cs.c[j] + step[1] * cs.s[j]
        du = step[2] + step[3] * cs.c[j] + step[4] * cs.s[j]
        rate = pt.lo.ca[j] * dr + pt.lo.sa[j] * du
        if rate > 0 and delta < 0:
            reach = min(reach, -delta / rate)
    return min(1.001 * reach, 1.0)


cdef void to_contact(const Case *cs, const Point *pt, double *step) noexcept nogil:
    """For a ring that touches no ball: the step along the generalised load that brings the
    nearest ball (to first order) a little into contact; 0 where none comes nearer."""
    cdef int i, j
    cdef double norm = 0.0, rate, delta, reach = INFINITY, t
    cdef double direction[5]
    for i in range(5):
        direction[i] = 0.0 if cs.locked[i] else cs.f[i]
        norm += direction[i] * direction[i]
    norm = max(sqrt(norm), 1e-300)
    for i in range(5):
        direction[i] /= norm
    for j in range(cs.z):
        delta = cs.pre + pt.b.eps[j]
        rate = (pt.lo.ca[j] * cs.c[j] * direction[0] + pt.lo.ca[j] * cs.s[j] * direction[1]
                + pt.lo.sa[j] * direction[2] + pt.lo.sa[j] * cs.c[j] * direction[3]
                + pt.lo.sa[j] * cs.s[j] * direction[4])
        if rate > 0:
            reach = min(reach, -delta / rate)
    t = 1.001 * reach + 1e-9 if isfinite(reach) else 0.0
    for i in range(5):
        step[i] = direction[i] * t


cdef void newton_step(const Case *cs, Work *wk, const double *grad, double *step,
                      double *hess) noexcept nogil:
    """The regularised Newton step and its matrix; for a ring touching no ball, the step to the
    first contact."""
    cdef int j, i, held = 0
    cdef double trace = 0.0, reg
    cdef double minus[5]
    cdef Point *pt = &wk.pt
    for j in range(cs.z):
        wk.w1[j] = 1.5 * (1.0 + wk.kappa[j]) * pt.lo.root[j]
        wk.w2[j] = 0.0
        if turns(cs, pt.b.rho[j], pt.b.u[j]):
            wk.w2[j] = pt.lo.q[j] / (pt.b.d[j] if pt.b.d[j] > 0 else 1.0)
    tangent(cs, pt.lo.ca, pt.lo.sa, wk.w1, wk.w2, NULL, True, hess)
    for i in range(5):
        trace += hess[6 * i]
        held += cs.locked[i]
        minus[i] = -grad[i]
    reg = 1e-13 * trace + 1e-300
    for i in range(5):
        hess[6 * i] += reg
    solve_held(cs, hess, minus, step)
    cap_step(cs, step)
    if not trace > held:  # no ball in contact: move along the load to the first contact
        to_contact(cs, pt, step)
        cap_step(cs, step)


cdef bint accept(const Case *cs, Work *wk, const double *w, double drop_min, double res,
                 bint need_drop, Point *trial, double *dd, double *ddr) noexcept nogil:
    """Whether the move w from the current point is taken (the residual halves, or the potential
    falls by 1e-4 of drop_min); ``trial`` gets the point there. A move that loses a ball's
    approach (overflow: a correction step of a ring touching no ball, 1e300 long) is not taken,
    though the potential, -F.w there, falls."""
    cdef bint ok, moves = False
    cdef int i
    offset(cs, wk.pt.b, w, trial.b, dd, ddr)
    for i in range(cs.z):
        if not isfinite(trial.b.eps[i]):
            return False
    evaluate(cs, wk.kappa, trial)
    trial.age = wk.pt.age + 1
    trial.drop = 0.0
    ok = trial.res < 0.5 * res
    if need_drop or not ok:
        trial.drop = energy_change(cs, wk.kappa, &wk.pt, trial, w, dd, ddr)
        if not isfinite(trial.drop):
            trial.drop = INFINITY
        ok = ok or trial.drop <= 1e-4 * drop_min
    for i in range(5):
        moves = moves or w[i] != 0.0
    return ok and moves


cdef void swap(Point *a, Point *b) noexcept nogil:
    cdef Point t = a[0]
    a[0] = b[0]
    b[0] = t


cdef void line_search(const Case *cs, Work *wk, const double *step, const double *hess,
                      const double *grad, bint slow, double *moved) noexcept nogil:
    """The move along step that the Armijo search takes (t = 1; then just past the first
    contact along the step, or half; then halved), tried once more with a second-order
    correction where the case is slow (_combined_ring._line_search); 0 where none is
    taken. The current point becomes the point reached."""
    cdef double slope = 0.0, t = 1.0, res = wk.pt.res, drop_min
    cdef double w[5]
    cdef double w2[5]
    cdef double left[5]
    cdef double fix[5]
    cdef bint ok, ok2, any_step = False
    cdef int i, k
    for i in range(5):
        slope += grad[i] * step[i]
        moved[i] = 0.0
        any_step = any_step or step[i] != 0.0
    if not any_step:
        return
    for k in range(60):
        for i in range(5):
            w[i] = t * step[i]
        drop_min = t * slope
        ok = accept(cs, wk, w, drop_min, res, False, &wk.trial, wk.dd, wk.ddr)
        if slow and (not ok or wk.trial.res > 0.9 * res):
            for i in range(5):
                left[i] = 0.0 if cs.locked[i] else cs.f[i] - wk.trial.gen[i]
            solve_held(cs, hess, left, fix)
            cap_step(cs, fix)
            for i in range(5):
                w2[i] = w[i] + fix[i]
            ok2 = accept(cs, wk, w2, drop_min, res, True, &wk.trial2, wk.dd2, wk.ddr2)
            if ok2 and (not ok or wk.trial2.drop < wk.trial.drop):
                for i in range(5):
                    w[i] = w2[i]
                ok = True
                swap(&wk.trial, &wk.trial2)
        if ok:
            for i in range(5):
                moved[i] = w[i]
            swap(&wk.pt, &wk.trial)
            return
        if k == 0:
            t = min(0.5, first_contact(cs, &wk.pt, step))
        else:
            t *= 0.5


cdef int minimise(const Case *cs, Work *wk, double *vh, double *vl, bint have_start,
                  bint polish) noexcept nogil:
    """Damped Newton on the convex potential, the stiffness wk.kappa frozen, until every free
    component is within TOLERANCE or the residual stops falling (rounding); the point is
    recomputed afresh every REFRESH steps and at the end (_combined_ring.minimise). Returns
    the steps taken; wk.pt is the point at the final position, fresh."""
    cdef double best = INFINITY, before, hi, lo
    cdef double grad[5]
    cdef double step[5]
    cdef double hess[25]
    cdef double moved[5]
    cdef int k, i, stall = 0, its = 0
    cdef bint slow = False, still
    cdef Point *pt = &wk.pt
    if not have_start:
        fresh(cs, vh, vl, wk.kappa, pt)
    for k in range(cs.lim.max_iterations):
        if (pt.res <= cs.lim.tolerance and pt.age > 0) or pt.age >= cs.lim.refresh:
            fresh(cs, vh, vl, wk.kappa, pt)
        if pt.res < 0.5 * best or pt.res > cs.lim.stall_below:
            best = pt.res
            stall = 0
        else:
            stall += 1
        if ((pt.res <= cs.lim.tolerance and (k > 0 or not polish)) or stall >= cs.lim.stall
                or not isfinite(pt.res)):
            break
        for i in range(5):
            grad[i] = 0.0 if cs.locked[i] else pt.gen[i] - cs.f[i]
        newton_step(cs, wk, grad, step, hess)
        before = pt.res
        line_search(cs, wk, step, hess, grad, slow, moved)
        slow = pt.res > 0.9 * before
        still = True
        for i in range(5):
            still = still and moved[i] == 0.0
        if still and pt.age == 0:
            break
        if still:
            pt.age = cs.lim.refresh
        for i in range(5):
            two_sum(vh[i], moved[i], &hi, &lo)
            quick(hi, lo + vl[i], &vh[i], &vl[i])
        its += 1
    if pt.age != 0:
        fresh(cs, vh, vl, wk.kappa, pt)
    return its


# ------------------------------------------------------------- the plain-double first stage

ctypedef struct Fast:
    # the balls at one position of the first stage (arrays of z) and what follows from them
    double *ca
    double *sa
    double *rho
    double *d
    double *q
    double *root
    double *kappa
    double *u
    const int *twin  # an earlier ball to compare with (``mirror_twins``), or -1
    int *todo        # work space (z): the balls whose stiffness is interpolated
    int *src         # work space (z): the ball whose values a ball takes (itself or its twin)
    double grad[5]
    double res
    double energy


cdef void fast_on(double *block, int z, const int *twin, int *scratch, Fast *st) noexcept nogil:
    st.ca = block
    st.sa = block + z
    st.rho = block + 2 * z
    st.d = block + 3 * z
    st.q = block + 4 * z
    st.root = block + 5 * z
    st.kappa = block + 6 * z
    st.u = block + 7 * z
    st.twin = twin
    st.todo = scratch
    st.src = scratch + z


cdef void mirror_twins(const Case *cs, int *twin) noexcept nogil:
    """twin[j]: the earlier ball at the mirror image of ball j about the load line (the same
    cosine, the opposite sine), or -1. Where the ring stays on the load line, the two are at
    the same (rho, u): ``fast_state`` takes the one's values for the other (where equal). The
    balls' angles are ``cage + 360° j/z``: the mirror of ball j is ball m - j (mod z), m that
    of ball 0."""
    cdef int j, p, m = -1
    for j in range(cs.z):
        if cs.c[j] == cs.c[0] and cs.s[j] == -cs.s[0]:
            m = j
            break
    for j in range(cs.z):
        p = (m - j + cs.z) % cs.z if m >= 0 else -1
        twin[j] = p if 0 <= p < j and cs.c[p] == cs.c[j] and cs.s[p] == -cs.s[j] else -1


cdef inline bint fast_ball(const Case *cs, Fast *st, int j, double rho, double u) noexcept nogil:
    """Ball j of ``fast_state`` at the groove-centre separations (rho, u): its contact
    direction, approach, stiffness (following the contact angle) and load."""
    cdef double rp = max(rho, 0.0), d, safe, delta
    d = norm(rp, u)
    safe = d if d > 0 else 1.0
    st.ca[j] = rp / safe
    st.sa[j] = u / safe
    st.rho[j] = rho
    st.u[j] = u
    st.d[j] = d
    delta = max(d - cs.a_hat, 0.0)
    st.root[j] = sqrt(delta)
    st.kappa[j] = 0.0
    return delta > 0 and cs.curve != NULL


cdef inline void fast_copy(Fast *st, int p, int j) noexcept nogil:
    """Ball j of ``fast_state`` as ball p, at the same (rho, u)."""
    st.ca[j] = st.ca[p]
    st.sa[j] = st.sa[p]
    st.rho[j] = st.rho[p]
    st.u[j] = st.u[p]
    st.d[j] = st.d[p]
    st.root[j] = st.root[p]


cdef inline void curve_two(const Case *cs, double ca0, double cam0, double ca1, double cam1,
                           double *k0, double *k1) noexcept nogil:
    """``curve_kappa`` of two balls, each ball's sums in the order of the nodes (the same
    bits), the two chains of additions interleaved."""
    cdef int k
    cdef double t0, t1, a0, a1, n0 = 0.0, n1 = 0.0, d0 = 0.0, d1 = 0.0
    t0 = 2.0 * min(max(ca0, 0.0), 1.0) - 1.0
    t1 = 2.0 * min(max(ca1, 0.0), 1.0) - 1.0
    for k in range(NODES):
        a0 = cs.node_w[k] / (t0 - cs.node_x[k])
        a1 = cs.node_w[k] / (t1 - cs.node_x[k])
        n0 += a0 * cs.curve[k]
        d0 += a0
        n1 += a1 * cs.curve[k]
        d1 += a1
    k0[0] = cam0 * n0 / d0
    k1[0] = cam1 * n1 / d1


cdef void curve_pairs(const Case *cs, Fast *st, int n) noexcept nogil:
    """``curve_kappa`` of the balls st.todo[:n] into st.kappa, two balls at a time
    (``curve_two``), an odd last one alone."""
    cdef int i, j0, j1
    for i in range(0, n - 1, 2):
        j0, j1 = st.todo[i], st.todo[i + 1]
        curve_two(cs, st.ca[j0], -st.sa[j0] * st.sa[j0] / (1.0 + st.ca[j0]),
                  st.ca[j1], -st.sa[j1] * st.sa[j1] / (1.0 + st.ca[j1]),
                  &st.kappa[j0], &st.kappa[j1])
    if n % 2:
        j0 = st.todo[n - 1]
        st.kappa[j0] = curve_kappa(cs, st.ca[j0], -st.sa[j0] * st.sa[j0] / (1.0 + st.ca[j0]))


cdef void fast_state(const Case *cs, const double *v, Fast *st) noexcept nogil:
    """The balls, forces, residual and potential at v in plain double precision, the stiffness
    following the contact angles."""
    cdef int j, i, p, n = 0
    cdef double rho, u, delta, gen[5], size[5], err[5], work = 0.0, energy = 0.0
    cdef double qc, qs
    for i in range(5):
        gen[i] = 0.0
        size[i] = 0.0
        err[i] = 0.0
    for j in range(cs.z):
        rho = (cs.a_hat + cs.pre - cs.gap) + v[0] * cs.c[j]
        rho += v[1] * cs.s[j]
        u = (v[2] + (v[3] + cs.t_imp) * cs.c[j]) + v[4] * cs.s[j]
        if cs.one_sided:
            u = max(u, 0.0)
        p = st.twin[j]
        st.src[j] = j
        if p >= 0 and same_bits(st.rho[p], rho) and same_bits(st.u[p], u):
            fast_copy(st, p, j)  # (every value here a function of (rho, u) alone)
            st.src[j] = p
        elif fast_ball(cs, st, j, rho, u):
            st.todo[n] = j
            n += 1
    curve_pairs(cs, st, n)
    for j in range(cs.z):
        st.kappa[j] = st.kappa[st.src[j]]
        delta = max(st.d[j] - cs.a_hat, 0.0)
        st.q[j] = (1.0 + st.kappa[j]) * delta * st.root[j]
        energy += st.q[j] * delta
        qc = st.q[j] * st.ca[j]
        qs = st.q[j] * st.sa[j]
        add_ball(cs, j, qc, qs, fabs(qc), fabs(qs), gen, err, size)
    for i in range(5):
        gen[i] += err[i]
        st.grad[i] = 0.0 if cs.locked[i] else gen[i] - cs.f[i]
        if not cs.locked[i]:
            work += cs.f[i] * v[i]
    st.res = residual(cs, gen, size)
    st.energy = energy / 2.5 - work


cdef int fast_newton(const Case *cs, Work *wk, Fast *cur, Fast *trial, double *v) noexcept nogil:
    """From the start v: Newton steps (the stiffness frozen in the matrix), halved until the
    residual or the potential falls, until the residual is below HAND_ON or stops falling; v
    and wk.kappa become the last position's. Returns the steps taken."""
    cdef int steps = 0, n, h, i, j
    cdef double slope, t, hess[25], step[5], minus[5], tv[5], trace
    cdef bint loaded, took
    cdef Fast swap_st
    fast_state(cs, v, cur)
    for n in range(cs.lim.fast_steps):
        loaded = False
        for j in range(cs.z):
            loaded = loaded or cur.root[j] > 0
        if not (cur.res > cs.lim.hand_on and isfinite(cur.res) and loaded):
            break
        for j in range(cs.z):
            wk.w1[j] = 1.5 * (1.0 + cur.kappa[j]) * cur.root[j]
            wk.w2[j] = cur.q[j] / (cur.d[j] if cur.d[j] > 0 else 1.0) if turns(
                cs, cur.rho[j], cur.sa[j]) else 0.0
        tangent(cs, cur.ca, cur.sa, wk.w1, wk.w2, NULL, True, hess)
        trace = 0.0
        for i in range(5):
            trace += hess[6 * i]
            minus[i] = -cur.grad[i]
        for i in range(5):
            hess[6 * i] += 1e-13 * trace
        solve_held(cs, hess, minus, step)
        cap_step(cs, step)
        slope = 0.0
        for i in range(5):
            slope += cur.grad[i] * step[i]
        t = 1.0
        took = False
        for h in range(cs.lim.fast_halvings):
            for i in range(5):
                tv[i] = v[i] + t * step[i]
            fast_state(cs, tv, trial)
            if trial.res < cur.res or trial.energy <= cur.energy + 1e-4 * t * slope:
                took = True
                break
            t *= 0.5
        if not took:
            break
        for i in range(5):
            v[i] = tv[i]
        steps += 1
        swap_st = cur[0]
        cur[0] = trial[0]
        trial[0] = swap_st
    for j in range(cs.z):
        wk.kappa[j] = cur.kappa[j]
    return steps


cdef inline double turn_weight(const Case *cs, const Point *pt, int j, double d,
                               const int *twin, double *slope, const double *w3) noexcept nogil:
    """``true_tangent``'s w3 of ball j (turning, loaded; d its safe centre distance): its
    twin's slope where its cos(alpha) and cos(alpha) - 1 are the twin's to the bit, and the
    twin's whole w3 where its sin(alpha), root and centre distance are too (the same
    operations on the same numbers)."""
    cdef int p = twin[j] if twin != NULL else -1
    cdef bint same = (p >= 0 and slope[p] == slope[p] and same_bits(pt.lo.ca[p], pt.lo.ca[j])
                      and same_bits(pt.lo.cam1[p], pt.lo.cam1[j]))
    cdef double s
    if (same and same_bits(pt.lo.sa[p], pt.lo.sa[j]) and same_bits(pt.lo.root[p], pt.lo.root[j])
            and same_bits(pt.b.d[p], pt.b.d[j])):
        slope[j] = slope[p]
        return w3[p]
    s = slope[p] if same else curve_slope(cs, pt.lo.ca[j], pt.lo.cam1[j])
    if twin != NULL:
        slope[j] = s
    return s * -pt.lo.sa[j] * pt.lo.root[j] ** 3 / d


cdef void true_tangent(const Case *cs, Point *pt, const double *kappa, double *w1, double *w2,
                       double *w3, double *out, double *sym, const int *twin,
                       double *slope) noexcept nogil:
    """The tangent of the ring forces at the point ``pt`` with the stiffness deviations
    ``kappa`` (scaled, every component free): d(generalised force)/d(displacement), with the
    stiffness's change with the contact angle (w3) where K follows it; ``w1``, ``w2``, ``w3``
    work arrays of z (``physical_case`` puts it in physical units). ``sym``: where given, gets the
    symmetric part (the tangent without the w3 term: ``tangent``'s sum before it adds that).
    ``twin``, ``slope``: where given, the balls' mirror twins and a work array of z: a ball
    whose cos(alpha) and cos(alpha) - 1 are its twin's to the bit takes the twin's slope
    (``turn_weight``)."""
    cdef int j
    cdef double d
    for j in range(cs.z):
        d = pt.b.d[j] if pt.b.d[j] > 0 else 1.0
        w1[j] = 1.5 * (1.0 + kappa[j]) * pt.lo.root[j]
        w2[j] = 0.0
        w3[j] = 0.0
        if twin != NULL:
            slope[j] = NAN
        if turns(cs, pt.b.rho[j], pt.b.u[j]):
            w2[j] = pt.lo.q[j] / d
            if cs.curve != NULL and pt.lo.root[j] > 0:
                w3[j] = turn_weight(cs, pt, j, d, twin, slope, w3)
    if sym == NULL:
        tangent(cs, pt.lo.ca, pt.lo.sa, w1, w2, w3 if cs.curve != NULL else NULL, False, out)
        return
    tangent(cs, pt.lo.ca, pt.lo.sa, w1, w2, NULL, False, sym)
    memcpy(out, sym, 25 * sizeof(double))
    if cs.curve != NULL:
        add_turn(cs, pt.lo.ca, pt.lo.sa, w3, out)


cdef void stiffness(const Case *cs, Work *wk, double *out) noexcept nogil:
    """The true tangent at the current point of a solve (``true_tangent``)."""
    true_tangent(cs, &wk.pt, wk.kappa, wk.w1, wk.w2, wk.dd, out, wk.sym, wk.twin,
                 wk.ddr)  # (wk.dd, wk.ddr: free at the answer)
    wk.sym_at = True


cdef bint physical_case(double *t, double factor, double radius, bint mirrored,
                        int z) noexcept nogil:
    """One case's scaled tangent ``t`` (5 x 5, in place) in physical units: times ``factor``
    = F/s and the tilt lever ``radius`` on the tilt rows and columns; the couplings of
    (x, axial, tilt) with (y, tilt_cross) 0 where the case is ``mirrored``; an entry within
    the rounding of its sum over the z balls (``|K_ab| <= 4 z eps sqrt(K_aa K_bb)``) 0. False
    (the rounding left alone) where an entry overflows."""
    cdef double lever[5]
    cdef double diag[5]
    cdef double small = 4.0 * z * 2.220446049250313e-16
    cdef int i, k
    for i in range(5):
        lever[i] = radius if i >= 3 else 1.0
    for i in range(5):
        for k in range(5):
            t[5 * i + k] *= factor * lever[i] * lever[k]
            if mirrored and (i == 1 or i == 4) != (k == 1 or k == 4):
                t[5 * i + k] = 0.0
    for i in range(25):
        if not isfinite(t[i]):
            return False
    for i in range(5):
        diag[i] = sqrt(fabs(t[6 * i]))
    for i in range(25):
        if fabs(t[i]) <= small * diag[i // 5] * diag[i % 5]:
            t[i] = 0.0
    return True


cdef bint same_weights(const Case *cs, const Work *wk) noexcept nogil:
    """Whether ``holding`` would weigh every ball as ``stiffness`` did (wk.w1, wk.w2): a ball
    whose load exceeds the tolerance alike (its distance positive where it turns), any other
    with weights 0 there too (at a finite direction: a term of +-0 leaves a sum that began at
    +0 as it is, bit for bit)."""
    cdef int j
    cdef const Point *pt = &wk.pt
    for j in range(cs.z):
        if not (isfinite(pt.lo.ca[j]) and isfinite(pt.lo.sa[j])):
            return False
        if pt.lo.q[j] > cs.lim.tolerance:
            if turns(cs, pt.b.rho[j], pt.b.u[j]) and not pt.b.d[j] > 0:
                return False
        elif not (wk.w1[j] == 0 and wk.w2[j] == 0):
            return False
    return True


cdef void holding(const Case *cs, Work *wk, double *out) noexcept nogil:
    """The potential's Hessian at the current point (the stiffness frozen) from the balls whose
    load exceeds the tolerance (1e-12 of the largest applied load): the stiffness of the balls
    that determine the equilibrium, every component free. A null direction of it is one the
    loads do not determine (combined._least_norm_tilt). Where every ball's weights are those
    of ``stiffness`` just before (``same_weights``), the symmetric part it summed."""
    cdef int j
    cdef Point *pt = &wk.pt
    if wk.sym_at and same_weights(cs, wk):
        memcpy(out, wk.sym, 25 * sizeof(double))
        return
    wk.sym_at = False
    for j in range(cs.z):
        wk.w1[j] = 0.0
        wk.w2[j] = 0.0
        if pt.lo.q[j] > cs.lim.tolerance:
            wk.w1[j] = 1.5 * (1.0 + wk.kappa[j]) * pt.lo.root[j]
            if turns(cs, pt.b.rho[j], pt.b.u[j]):
                wk.w2[j] = pt.lo.q[j] / pt.b.d[j]
    tangent(cs, pt.lo.ca, pt.lo.sa, wk.w1, wk.w2, NULL, False, out)


cdef bint maybe_flat(const Case *cs, const double *h) noexcept nogil:
    """Whether the free block of the Hessian h may have a null direction (an eigenvalue below
    1e-12 of the largest): a pivot of its Cholesky factorisation with diagonal pivoting below
    1e-8 of its largest diagonal entry (the last pivot is at most 4^4 times the smallest
    eigenvalue, the largest diagonal at least a fifth of the largest: every such matrix is
    caught; the caller decides on the eigenvalues)."""
    cdef double m[25]
    cdef int idx[5]
    cdef int n = 0, i, k, step, best
    cdef double dmax = 0.0, piv
    for i in range(5):
        if not cs.locked[i]:
            idx[n] = i
            n += 1
    for i in range(n):
        for k in range(n):
            m[5 * i + k] = h[5 * idx[i] + idx[k]]
        dmax = max(dmax, m[6 * i])
    if n == 0 or not dmax > 0:
        return n > 0
    for step in range(n):
        best = step
        for i in range(step + 1, n):
            if m[6 * i] > m[6 * best]:
                best = i
        if not m[6 * best] > 1e-8 * dmax:
            return True
        if best != step:  # swap rows and columns step <-> best
            for k in range(n):
                piv = m[5 * step + k]
                m[5 * step + k] = m[5 * best + k]
                m[5 * best + k] = piv
            for k in range(n):
                piv = m[5 * k + step]
                m[5 * k + step] = m[5 * k + best]
                m[5 * k + best] = piv
        piv = m[6 * step]
        for i in range(step + 1, n):
            for k in range(step + 1, n):
                m[5 * i + k] -= m[5 * i + step] * m[5 * step + k] / piv
    return False


# ------------------------------------------------------------------------------ the start

cdef void radial_gradient(const Case *cs, double x, double y, double g, double f0,
                          double *out) noexcept nogil:
    """The ring of constant stiffness under F_r alone (the radial model, contact angle 0):
    out = (potential, dPhi/dx, dPhi/dy, d2/dx2, d2/dxdy, d2/dy2, balls loaded)."""
    cdef int j
    cdef double delta, root, q, h
    for j in range(7):
        out[j] = 0.0
    for j in range(cs.z):
        delta = x * cs.c[j] + y * cs.s[j] - g
        if delta <= 0:
            continue
        root = sqrt(delta)
        q = delta * root
        h = 1.5 * root
        out[0] += q * delta / 2.5
        out[1] += q * cs.c[j]
        out[2] += q * cs.s[j]
        out[3] += h * cs.c[j] * cs.c[j]
        out[4] += h * cs.c[j] * cs.s[j]
        out[5] += h * cs.s[j] * cs.s[j]
        out[6] += 1.0
    out[0] -= f0 * x
    out[1] -= f0


cdef void radial_start(const Case *cs, double f0, double *v) noexcept nogil:
    """(x, y) of the ring under the radial load f0 alone with the stiffness K_0 (scaled: K = 1)
    and the gap per side g = gap - pre: damped Newton on the convex potential (regularised as
    the radial engine's, so that a ring on one ball moves across the load line to the next),
    from where the ball nearest the load line alone carries f0; y held where the case holds
    it; until the forces balance to 1e-13 of f0 or the step stops moving the ring."""
    cdef double g = cs.gap - cs.pre, cmax = -1.0, x, y = 0.0, dx, dy, det, t, slope, reg
    cdef double a, d
    cdef double now[7]
    cdef double trial[7]
    cdef int j, k, h
    for j in range(cs.z):
        cmax = max(cmax, cs.c[j])
    x = (g + f0 ** (2.0 / 3.0)) / cmax
    radial_gradient(cs, x, y, g, f0, now)
    for k in range(200):
        if now[6] == 0:  # (no ball loaded: back to the first contact plus one approach)
            x = (g + f0 ** (2.0 / 3.0)) / cmax
            radial_gradient(cs, x, y, g, f0, now)
        if fabs(now[1]) <= 1e-13 * f0 and (cs.locked[1] or fabs(now[2]) <= 1e-13 * f0):
            break
        reg = 1e-12 * (now[3] + now[5]) + 1e-300
        a = now[3] + reg
        d = now[5] + reg
        if cs.locked[1]:
            dx = -now[1] / a
            dy = 0.0
        else:
            det = a * d - now[4] * now[4]
            dx = -(d * now[1] - now[4] * now[2]) / det
            dy = -(a * now[2] - now[4] * now[1]) / det
        if not (fabs(dx) > 1e-15 * (fabs(x) + fabs(y)) or fabs(dy) > 1e-15 * (fabs(x) + fabs(y))):
            break
        slope = now[1] * dx + now[2] * dy
        t = 1.0
        for h in range(100):
            radial_gradient(cs, x + t * dx, y + t * dy, g, f0, trial)
            if trial[0] <= now[0] + 1e-4 * t * slope:
                break
            t *= 0.5
        x += t * dx
        y += t * dy
        for j in range(7):
            now[j] = trial[j]
    v[0] = x
    v[1] = y


cdef double axial_offset(const Case *cs, double target, bint single) noexcept nogil:
    """The axial offset u at which z balls alike, each carrying Q = (u/d) delta^1.5 axially,
    carry ``target`` z in all (scaled: K = 1), by bisection: to 4e-16 of u or, ``single``,
    until both ends round to the same single-precision number (the start needs no more; the
    bisection of bearingload.models.combined.axial_only). Two halvings a round: the middle
    and both midpoints it may lead to are evaluated together (independent, they overlap),
    the halvings, their order and their stops those of one at a time."""
    cdef double g = cs.gap - cs.pre, c = cs.a_hat - g, gap2 = g * (2.0 * cs.a_hat - g)
    cdef double lo = sqrt(max(gap2, 0.0)), hi, mid, left, right, r = target ** (1.0 / 3.0)
    cdef double f_mid, f_left, f_right, f_next
    cdef int k, halvings = 0
    hi = lo + r * r + sqrt(r * cs.a_hat) + 1e-300
    for k in range(2000):
        f_mid = axial_excess(c, gap2, cs.a_hat, hi, target)
        if not f_mid < 0:
            break
        hi *= 2.0
    if single:  # (its answer found faster where it can be told)
        mid = axial_single(c, gap2, cs.a_hat, lo, hi, f_mid, target)
        if mid == mid:
            return mid
    while halvings < 200 and not bisected(lo, hi, single):
        mid = 0.5 * (lo + hi)
        left = 0.5 * (lo + mid)  # (the next middle where the root is below mid)
        right = 0.5 * (mid + hi)
        f_mid = axial_excess(c, gap2, cs.a_hat, mid, target)
        f_left = axial_excess(c, gap2, cs.a_hat, left, target)
        f_right = axial_excess(c, gap2, cs.a_hat, right, target)
        if f_mid < 0:
            lo, f_next = mid, f_right
        else:
            hi, f_next = mid, f_left
        halvings += 1
        if halvings >= 200 or bisected(lo, hi, single):
            break
        if f_next < 0:  # (0.5 (lo + hi) is now right or left, as computed)
            lo = 0.5 * (lo + hi)
        else:
            hi = 0.5 * (lo + hi)
        halvings += 1
    return 0.5 * (lo + hi)


cdef double axial_single(double c, double gap2, double a, double lo, double hi, double f_hi,
                         double target) noexcept nogil:
    """``axial_offset``'s single-precision answer in fewer evaluations: the root by regula
    falsi (Illinois) in [lo, hi] to 2^-30 of it, then the float F it rounds to where the
    excess is below 0 at 64 doubles above the lower end of F's rounding interval and not
    below 0 at 64 doubles under its upper end: the excess rising with u, its bisection ends
    inside those two points (both ends rounding to F, within its 200 halvings of [lo, hi])
    and returns F's number. NAN where not so told (the bisection then decides)."""
    cdef double f_lo = -target, u, f_u, below, above, spare, width = hi - lo
    cdef float f
    cdef int k, side = 0
    for k in range(100):
        if not hi - lo > 9.313225746154785e-10 * hi:  # (2^-30)
            break
        u = hi - f_hi * (hi - lo) / (f_hi - f_lo)
        if not lo < u < hi:
            u = 0.5 * (lo + hi)
        f_u = axial_excess(c, gap2, a, u, target)
        if f_u < 0:
            lo, f_lo = u, f_u
            f_hi = 0.5 * f_hi if side < 0 else f_hi
            side = -1
        else:
            hi, f_hi = u, f_u
            f_lo = 0.5 * f_lo if side > 0 else f_lo
            side = 1
    f = <float> (0.5 * (lo + hi))
    if not (hi - lo <= 9.313225746154785e-10 * hi and 1e-30 < f < 1e29):
        return NAN
    below = 0.5 * (<double> f + <double> nextafterf(f, 0.0))
    above = 0.5 * (<double> f + <double> nextafterf(f, INFINITY))
    spare = 64.0 * 2.220446049250313e-16 * below
    if width < 1e50 * spare and (axial_excess(c, gap2, a, below + spare, target) < 0
            and not axial_excess(c, gap2, a, above - spare, target) < 0):
        return f
    return NAN


cdef inline bint bisected(double lo, double hi, bint single) noexcept nogil:
    """Whether ``axial_offset``'s bisection stops at [lo, hi]."""
    return not hi - lo > 4e-16 * hi or (single and <float> lo == <float> hi and hi < 1e30)


cdef inline double axial_excess(double c, double gap2, double a, double u,
                                double target) noexcept nogil:
    """One ball's axial force at the offset u less its share of the thrust."""
    cdef double d = hypot(c, u), approach = max((u * u - gap2) / (d + a), 0.0)
    return approach * sqrt(approach) * (u / d) - target


cdef void standard_start(const Case *cs, double *v) noexcept nogil:
    """The radial model's (x, y) for F_r, the axial closed form's offset for F_a (a load
    component below 1e-3 of the largest picks no start), for a moment alone the tilt the closed
    form gives twice it; rounded to single precision (a start needs no more, and then does not
    depend on the last bits of these solutions), the held components 0."""
    cdef int i
    cdef bint radial = cs.f[0] > 1e-3, axial = fabs(cs.f[2]) > 1e-3
    cdef double size, u
    for i in range(5):
        v[i] = 0.0
    if radial:
        radial_start(cs, cs.f[0], v)
    if axial:
        v[2] = axial_offset(cs, fabs(cs.f[2]) / cs.z, True)
        if cs.f[2] < 0:
            v[2] = -v[2]
    size = hypot(0.0 if cs.locked[3] else cs.f[3], cs.f[4])
    if not radial and not axial and size > 0 and cs.t_imp == 0:
        u = axial_offset(cs, 2.0 * size / cs.z, False)
        v[3] = u * cs.f[3] / size
        v[4] = u * cs.f[4] / size
    for i in range(5):
        if cs.locked[i]:
            v[i] = 0.0
        elif fabs(v[i]) < 1e30:
            v[i] = <double> <float> v[i]


# ---------------------------------------------------------------------------- one case

cdef double stiffness_update(const Case *cs, Work *wk, Fast *st) noexcept nogil:
    """wk.kappa of the loaded balls at wk.pt's contact angles (a ball whose angle is its
    twin's to the bit takes the twin's; the others two at a time, ``curve_two``, into the
    free first-stage arrays ``st``); returns the largest change |new - old| / (1 + |new|)."""
    cdef const Point *pt = &wk.pt
    cdef int j, p, i, n = 0
    cdef double change = 0.0, k_new
    for j in range(cs.z):
        p = wk.twin[j]
        st.src[j] = j
        if pt.lo.root[j] > 0:
            if (p >= 0 and pt.lo.root[p] > 0 and same_bits(pt.lo.ca[p], pt.lo.ca[j])
                    and same_bits(pt.lo.cam1[p], pt.lo.cam1[j])):
                st.src[j] = p
            else:
                st.todo[n] = j
                n += 1
    for i in range(0, n - 1, 2):
        j, p = st.todo[i], st.todo[i + 1]
        curve_two(cs, pt.lo.ca[j], pt.lo.cam1[j], pt.lo.ca[p], pt.lo.cam1[p], &st.kappa[j],
                  &st.kappa[p])
    if n % 2:
        j = st.todo[n - 1]
        st.kappa[j] = curve_kappa(cs, pt.lo.ca[j], pt.lo.cam1[j])
    for j in range(cs.z):
        if pt.lo.root[j] > 0:
            k_new = st.kappa[st.src[j]]
            change = max(change, fabs(k_new - wk.kappa[j]) / (1.0 + fabs(k_new)))
            wk.kappa[j] = k_new
    return change


cdef int solve_case(const Case *cs, const double *v0, bint given, double *vh, double *vl,
                    int64_t *iterations, Work *wk) noexcept nogil:
    """The first stage, then minimisations with the stiffness updated to the contact angles
    until the update leaves the equilibrium (to the tolerance), or, where the minimisation
    stalled above the tolerance, until the update changes no stiffness by more than
    KAPPA_SETTLED nor the residual by more than 1 % (the caller's residual test judges it).
    Returns OK or NOT_CONVERGED (the updates ran out); wk.pt is the point at the answer with
    wk.kappa."""
    cdef Fast cur, trial
    cdef int i, update
    cdef double end_res, change
    cdef Point *pt = &wk.pt
    mirror_twins(cs, wk.twin)
    fast_on(wk.fast, cs.z, wk.twin, wk.twin + cs.z, &cur)  # (one scratch: a state at a time)
    fast_on(wk.fast + FAST_ARRAYS * cs.z, cs.z, wk.twin, wk.twin + cs.z, &trial)
    for i in range(5):
        vh[i] = v0[i]
        vl[i] = 0.0
    if not given:
        standard_start(cs, vh)
    iterations[0] = fast_newton(cs, wk, &cur, &trial, vh)
    for update in range(cs.lim.max_updates):
        iterations[0] += minimise(cs, wk, vh, vl, update > 0, update == 0)
        if cs.curve == NULL:
            return OK
        end_res = pt.res
        change = stiffness_update(cs, wk, &cur)
        stiff_loads(cs, pt.b, wk.kappa, pt.lo)  # (only the stiffness changed)
        forces(cs, pt.lo, pt.gen, pt.size)
        pt.res = residual(cs, pt.gen, pt.size)
        if not pt.res > max(cs.lim.tolerance, end_res):
            return OK
        if end_res > cs.lim.tolerance and change <= KAPPA_SETTLED and pt.res <= 1.01 * end_res:
            return OK  # stalled, the stiffness settled: the caller's residual test judges it
    return NOT_CONVERGED


# ------------------------------------------------------------------------ Python boundary

cdef inline double floor_mod(double a, double b) noexcept nogil:
    """a mod b with the sign of b, numpy's ``mod`` of doubles."""
    cdef double m = fmod(a, b)
    if m == 0:
        return copysign(0.0, b)
    if (b < 0) != (m < 0):
        m += b
    return m


cdef bint ball_directions(int z, double cage, double snap, double *c, double *s) noexcept nogil:
    """cos and sin of every ball's angle (ball j at ``cage + 360° j/z``), and whether the case
    is symmetric about the load line (the cage within ``snap`` of 0 or half a pitch): then the
    directions exactly mirrored, ball j at (k_j / z) turns, k_j = j + first + (0 or 1/2), the
    angle folded onto [0, 180°] before its cosine is taken (combined.ball_directions says why)."""
    cdef double pitch = 360.0 / z, frac, first, k, folded, rad = cage * (PI / 180.0)
    cdef bint half, mirror
    cdef int j
    frac = floor_mod(fmod(fabs(cage), 360.0), pitch)
    half = fabs(frac - pitch / 2.0) <= snap
    mirror = frac <= snap or frac >= pitch - snap or half
    first = rint((cage - 0.5 * pitch * half) / pitch)
    for j in range(z):
        if mirror:
            k = floor_mod(j + first + 0.5 * half, z)
            folded = 2.0 * PI * min(k, z - k) / z
            c[j] = cos(folded)
            s[j] = (1.0 if k <= z / 2.0 else -1.0) * sin(folded)
        else:
            c[j] = cos(rad + 2.0 * PI * j / z)
            s[j] = sin(rad + 2.0 * PI * j / z)
    return mirror


def held_solves(const double[:, ::1] a, const double[:, ::1] b,
                const unsigned char[:, ::1] held):
    """``solve5`` and ``solve_held`` of n 5x5 systems ``a`` (n, 25, row-major), ``b`` (n, 5)
    with the components ``held`` (n, 5) uint8: their x (2, n, 5), which are to be the same
    bits (tests/test_core_held_solve.py)."""
    cdef Py_ssize_t n = a.shape[0], k
    cdef Case cs
    cdef int i
    out_a = np.empty((2, n, 5))
    cdef double[:, :, ::1] out = out_a
    with nogil:
        for k in range(n):
            for i in range(5):
                cs.locked[i] = held[k, i]
            solve5(&a[k, 0], &b[k, 0], &out[0, k, 0])
            solve_held(&cs, &a[k, 0], &b[k, 0], &out[1, k, 0])
    return out_a


def directions(int z, const double[::1] cage, double snap):
    """cos and sin of every ball's angle (n, z) each and which cases are symmetric about the
    load line (n,) bool, for the cage angles ``cage`` (n,) [°] (``ball_directions``)."""
    cdef Py_ssize_t n = cage.shape[0], k
    c_a = np.empty((n, z))
    s_a = np.empty((n, z))
    mirror_a = np.empty(n, dtype=bool)
    cdef double[:, ::1] c = c_a, s = s_a
    cdef unsigned char[::1] mirror = mirror_a.view(np.uint8)
    with nogil:
        for k in range(n):
            mirror[k] = ball_directions(z, cage[k], snap, &c[k, 0], &s[k, 0])
    return c_a, s_a, mirror_a


cdef void scaled_case(int z, const double *c, const double *s, double big_a, double g,
                      double scale, double t_imp, double *c2, double *s2, double *out,
                      Py_ssize_t m) noexcept nogil:
    """One case of ``scaled_problem`` (``c2``, ``s2`` may be ``c``, ``s``; ``out`` its column
    of the six, ``m`` apart)."""
    cdef int j
    cdef double a = big_a / scale, p = (-g if -g > 0.0 else 0.0) / scale
    for j in range(z):
        c2[j] = 0.0 if fabs(c[j]) < 1e-15 else c[j]
        s2[j] = 0.0 if fabs(s[j]) < 1e-15 else s[j]
    out[0], out[m], out[2 * m] = a, p, (g if g > 0.0 else 0.0) / scale
    two_sum(a, p, &out[3 * m], &out[4 * m])
    out[5 * m] = t_imp / scale


def scaled_problem(const double[:, ::1] c, const double[:, ::1] s, const double[::1] big_a,
                   const double[::1] g, const double[::1] scale, const double[::1] t_imp):
    """The scaled problem of n cases (_combined_ring.Problem.make): the ball directions ``c``,
    ``s`` (n, z) with those below 1e-15 made 0, and A, p = max(-g, 0), max(g, 0), B = A + p in
    double-double (Knuth's two-sum) and the imposed tilt ``t_imp``, each over ``scale`` (n,)."""
    cdef Py_ssize_t n = c.shape[0], z = c.shape[1], k
    c_a, s_a = np.empty((n, z)), np.empty((n, z))
    out_a = np.empty((6, n))
    cdef double[:, ::1] c2 = c_a, s2 = s_a, out = out_a
    with nogil:
        for k in range(n):
            scaled_case(<int> z, &c[k, 0], &s[k, 0], big_a[k], g[k], scale[k], t_imp[k],
                        &c2[k, 0], &s2[k, 0], &out[0, k], n)
    return c_a, s_a, out_a


def residuals(const double[:, ::1] f, const double[:, ::1] gen, const double[:, ::1] size,
              const unsigned char[:, ::1] held):
    """Per case (n,), the largest residual of the forces ``gen`` against the applied ``f`` of
    a component not ``held``, over its load or its terms' rounding level (``size``), at least
    FLOOR without a load; NaN if any is (``residual``; _combined_ring.residual_of)."""
    cdef Py_ssize_t n = f.shape[0], k
    cdef int i
    out_a = np.empty(n)
    cdef double[::1] out = out_a
    cdef Case cs
    cs.lim = LIMITS
    with nogil:
        for k in range(n):
            for i in range(5):
                cs.f[i] = f[k, i]
                cs.locked[i] = held[k, i]
            out[k] = residual(&cs, &gen[k, 0], &size[k, 0])
    return out_a


cdef void store(const Work *wk, int z, double *kappa, double *balls, Py_ssize_t stride,
                double *gen, double *size, double *res) noexcept nogil:
    """A case's answer into the outputs: its stiffness deviations, the 13 ball arrays of its
    point (``stride`` apart), the forces, their terms' sizes and the residual."""
    cdef int i, j
    for i in range(z):
        kappa[i] = wk.kappa[i]
    for j in range(BALL_ARRAYS):
        for i in range(z):
            balls[j * stride + i] = wk.pt.b.rho[j * z + i]
    for i in range(5):
        gen[i] = wk.pt.gen[i]
        size[i] = wk.pt.size[i]
    res[0] = wk.pt.res



cdef void answer_flags(Case *cs, const int *imposed, const Point *pt, double *res,
                       unsigned char *edge) noexcept nogil:
    """A case's residual with the components ``imposed`` held instead of its locked ones (the
    acceptance test of combined._checked: a component 0 by a symmetry measured too) and
    whether a loaded ball may sit at the groove edge (its groove centres crossed, or a contact
    angle within 1e-8 of 90°: combined._checked looks closer)."""
    cdef int locked[5]
    cdef int i, j
    for i in range(5):
        locked[i] = cs.locked[i]
        cs.locked[i] = imposed[i]
    res[0] = residual(cs, pt.gen, pt.size)
    for i in range(5):
        cs.locked[i] = locked[i]
    edge[0] = False
    for j in range(cs.z):
        if pt.lo.root[j] > 0 and (pt.b.rho[j] <= 0 or pt.lo.ca[j] < 1e-8):
            edge[0] = True


ctypedef struct Answers:
    # the outputs of ``solve`` for n cases of z balls (as its docstring lays them out)
    Py_ssize_t n
    double *v         # (2, n, 5): vh, vl
    double *forces    # (2, n, 5): the forces, their terms' sizes
    double *mats      # (2, n, 5, 5): the tangent, the holding Hessian
    double *kappa     # (n, z)
    double *balls     # (BALL_ARRAYS, n, z)
    double *res       # (2, n): the residual, that with the imposed components held
    int64_t *its      # (n,)
    int *status       # (n,)
    unsigned char *flags  # (2, n): maybe flat, maybe at the groove edge


def answers_arrays(Py_ssize_t n, int z, list doubles=None, mats=None):
    """The output arrays of ``solve`` for n cases of z balls: vh and vl (2, n, 5), the forces
    and their terms' sizes (2, n, 5), the tangent and the holding Hessian (2, n, 5, 5), kappa
    (n, z), the ball arrays (BALL_ARRAYS, n, z), the residuals (2, n), the iterations (n,),
    the status (n,), the flags (2, n) (``answers_at`` points into them). ``doubles``, ``mats``:
    the caller's arrays of ``answer_shapes`` and its tangent and Hessian array, else its own."""
    v, forces, kappa, balls, res = carve(n, answer_shapes(n, z)) if doubles is None else doubles
    return (v, forces, np.empty((2, n, 5, 5)) if mats is None else mats, kappa, balls, res,
            np.empty(n, dtype=np.int64), np.empty(n, dtype=np.int32), np.zeros((2, n), np.uint8))


def answer_shapes(Py_ssize_t n, int z):
    """The shapes of ``answers_arrays``' vh and vl, forces, kappa, balls and residuals."""
    return ((2, n, 5), (2, n, 5), (n, z), (BALL_ARRAYS, n, z), (2, n))


#: Cases below which ``carve`` allocates each array on its own (a few pages: no faults to save,
#: and the views would cost more than the allocations). [-]
CARVED = 64


def carve(Py_ssize_t n, tuple shapes):
    """Arrays of doubles of ``shapes`` (of n cases) as views of one block. One allocation, not
    one each: freed, a block this large raises glibc's trim threshold with it, and the next
    call's arrays take its pages again instead of faulting in fresh ones (0.3-0.5 page faults
    a case in the batches of combined_call, ~0.8 us a case of 10 000 on a 6205)."""
    cdef Py_ssize_t total = 0, size, at = 0
    if n < CARVED:
        return [np.empty(shape) for shape in shapes]
    sizes = []
    for shape in shapes:
        size = 1
        for m in shape:
            size *= m
        sizes.append(size)
        total += size
    block, out = np.empty(total), []
    for shape, size in zip(shapes, sizes):
        out.append(block[at:at + size].reshape(shape))
        at += size
    return out


def answers_of(arrays):
    """``solve``'s return of its ``answers_arrays``."""
    v, forces, mats, kappa, balls, res, its, status, flags = arrays
    return (v[0], v[1], kappa, its, status, (balls, forces[0], forces[1], res[0]), mats[0],
            (mats[1], flags[0]), (res[1], flags[1]))


cdef void answers_at(Answers *a, Py_ssize_t n, double[:, :, ::1] v, double[:, :, ::1] forces,
                     double[:, :, :, ::1] mats, double[:, ::1] kappa, double[:, :, ::1] balls,
                     double[:, ::1] res, int64_t[::1] its, int[::1] status,
                     unsigned char[:, ::1] flags) noexcept nogil:
    """``a`` pointing into the arrays of ``answers_arrays`` (none where n is 0)."""
    a.n = n
    if n > 0 and kappa.shape[1] > 0:
        a.v, a.forces, a.mats = &v[0, 0, 0], &forces[0, 0, 0], &mats[0, 0, 0, 0]
        a.kappa, a.balls, a.res = &kappa[0, 0], &balls[0, 0, 0], &res[0, 0]
        a.its, a.status, a.flags = &its[0], &status[0], &flags[0, 0]


cdef void case_at(Case *cs, int z, const double *c, const double *s, const double *scalars,
                  Py_ssize_t n, const double *f, const unsigned char *locked, int one_sided,
                  const double *curve) noexcept nogil:
    """``cs`` the case of the ball directions ``c``, ``s`` (z), ``scalars`` = (a_hat, pre, gap,
    b_hi, b_lo, t_imp) ``n`` apart, the forces ``f`` and held components ``locked`` (5), the
    stiffness curve's values ``curve`` (NULL: constant K); its limits and nodes the caller's."""
    cdef int i
    cs.z, cs.c, cs.s, cs.one_sided = z, c, s, one_sided
    cs.a_hat, cs.pre, cs.gap = scalars[0], scalars[n], scalars[2 * n]
    cs.b_hi, cs.b_lo, cs.t_imp = scalars[3 * n], scalars[4 * n], scalars[5 * n]
    for i in range(5):
        cs.f[i] = f[i]
        cs.locked[i] = locked[i]
    cs.deviation = cs.pre > 0 and z >= 2
    cs.q0 = cs.pre * sqrt(cs.pre) if cs.deviation else 0.0
    cs.curve = curve


cdef void solve_into(Case *cs, const int *held, const double *v0, bint given, Py_ssize_t k,
                     Answers *a) noexcept nogil:
    """Case ``k`` solved (``solve_case``) from ``v0`` where ``given``, its answer, tangent,
    holding Hessian and checks (the components ``held`` as imposed) stored into ``a``."""
    cdef Py_ssize_t n = a.n
    cdef int z = cs.z
    cdef Work wk
    if not work_open(z, &wk):
        a.status[k] = NO_MEMORY
        return
    a.status[k] = solve_case(cs, v0, given, &a.v[5 * k], &a.v[5 * (n + k)], &a.its[k], &wk)
    if a.status[k] == NO_MEMORY:  # no point to store: the status fails the case
        a.res[k] = NAN
        free(wk.block)
        return
    stiffness(cs, &wk, &a.mats[25 * k])
    holding(cs, &wk, &a.mats[25 * (n + k)])
    a.flags[k] = maybe_flat(cs, &a.mats[25 * (n + k)])
    store(&wk, z, &a.kappa[z * k], &a.balls[z * k], n * z, &a.forces[5 * k],
          &a.forces[5 * (n + k)], &a.res[k])
    answer_flags(cs, held, &wk.pt, &a.res[n + k], &a.flags[n + k])
    free(wk.block)


def solve(const double[:, ::1] c, const double[:, ::1] s, const double[:, ::1] lengths,
          const double[:, ::1] f, const unsigned char[:, ::1] locked,
          const unsigned char[:, ::1] imposed, const unsigned char[::1] one_sided,
          const double[:, ::1] curve, const double[::1] node_x, const double[::1] node_w,
          const double[:, ::1] v0, const unsigned char[::1] given, *,
          int max_iterations=MAX_ITERATIONS,
          int first_stage_steps=FIRST_STAGE_STEPS):
    """Solve n cases of the scaled ring equilibrium (see the module docstring).

    Arrays over the n cases (the scaled :class:`bearingload.models._combined_ring.Problem`):
    ``c``, ``s`` (n, z); ``lengths`` (6, n) = a_hat, pre, gap, b_hi, b_lo, t_imp; ``f``,
    ``locked``, ``imposed`` (uint8), ``v0`` (n, 5) the start where ``given`` (n,) uint8 is 1,
    else the standard one (``standard_start``); ``one_sided`` (n,) uint8; ``curve`` (n, NODES)
    the stiffness curve's values, or (n, 0) for a constant K; ``node_x``, ``node_w`` its nodes
    and weights (NODES,). ``max_iterations`` (per stiffness update) and ``first_stage_steps``
    default to the module's limits (lower ones make a test's case fail on purpose).

    Returns (vh, vl, kappa, iterations, status, point, tangent, holding, checks): the position
    in double-double (n, 5) each, the stiffness deviations (n, z), the Newton steps (n,), the
    status per case (n,), the point at the answer (the balls and their loads, a (13, n, z)
    array of rho, u, d, eps, up, ca, sa, cam1, q, dq, root, tau, sig; the generalised forces
    and the sums of their terms' magnitudes (n, 5) each; the residual (n,)), the tangent of the
    ring forces there (n, 5, 5), scaled, every component free (``stiffness``), the Hessian
    of the balls that determine the equilibrium (``holding``) with whether it may have a null
    direction among the free components (``maybe_flat``, (n,) uint8), and the answer's checks
    (``answer_flags``): the residual with the ``imposed`` components held (n,) and whether a
    loaded ball may sit at the groove edge (n,) uint8.
    """
    cdef Py_ssize_t n = c.shape[0], k
    cdef int z = <int> c.shape[1], i
    cdef bint has_curve = curve.shape[1] == NODES
    cdef int held[5]
    cdef Case cs
    cdef Answers a
    arrays = answers_arrays(n, z)
    answers_at(&a, n, arrays[0], arrays[1], arrays[2], arrays[3], arrays[4], arrays[5],
               arrays[6], arrays[7], arrays[8])
    cs.lim = LIMITS
    cs.lim.max_iterations = max_iterations
    cs.lim.fast_steps = first_stage_steps
    cs.node_x, cs.node_w = &node_x[0], &node_w[0]
    with nogil:
        for k in range(n):
            case_at(&cs, z, &c[k, 0], &s[k, 0], &lengths[0, k], n, &f[k, 0], &locked[k, 0],
                    one_sided[k], &curve[k, 0] if has_curve else NULL)
            for i in range(5):
                held[i] = imposed[k, i]
            solve_into(&cs, held, &v0[k, 0], given[k], k, &a)
    return answers_of(arrays)


# ----------------------------------------------------------------------- the preloaded pair
#
# Two bearings of the same balls on one rigid shaft (bearingload.models.pair; its model and two
# stages: docs/architecture.md, "The compiled core"): the shaft at v = (x, y, a, t, t_c) (scaled,
# t = R_i theta / s) about the pair's centre, bearing k at L_k v plus its offset (``pair_local``);
# in the double-double stage K at each ball's angle, frozen in the line search's potential.

#: Newton steps of a case in the pair's double-double stage, and halvings of a step. [-]
PAIR_MAX_STEPS = 400
PAIR_HALVINGS = 50
#: The plain-double first stage hands a case on at this residual, or after PAIR_FIRST_STEPS
#: steps, or where its line search (PAIR_FIRST_HALVINGS halvings) finds no step. [-]
PAIR_FIRST_STAGE = 1e-9
PAIR_FIRST_STEPS = 60
PAIR_FIRST_HALVINGS = 30

ctypedef struct Pair:
    Case bear         # the balls of either bearing (its f and locked unused)
    Case whole        # the pair's applied forces and held components (its residual)
    double sigma[2]   # +1, or -1 where the bearing is mirrored
    double arm[2]     # -z_k / R_i: bearing k's radial move per unit of scaled tilt
    double off_hi[2]  # bearing k's axial preload offset, double-double
    double off_lo[2]
    int max_steps       # the double-double stage: steps, halvings of a step
    int halvings
    double first_stage  # the plain-double stage: hand-on residual, steps, halvings
    int first_steps
    int first_halvings

ctypedef struct Side:
    Point pt        # the balls and loads of one bearing (gen, size: its local forces)
    double *kappa   # their stiffness deviations at their contact angles

ctypedef struct PairState:
    Side side[2]
    double gen[5]   # the pair's generalised forces, scaled
    double size[5]  # the magnitudes of their terms
    double res      # residual of the pair's equilibrium
    double energy   # the balls' potential, the stiffness of ``kappa``

cdef enum:
    LEAN_ARRAYS = 8  # the arrays of one Lean


ctypedef struct Lean:
    # one bearing's balls at a position of the plain-double first stage (arrays of z)
    double *ca
    double *sa
    double *rho
    double *up
    double *d
    double *root
    double *kappa
    double *q

ctypedef struct LeanState:
    Lean side[2]
    double gen[5]
    double size[5]
    double res
    double energy   # the potential, the work of the applied forces included

ctypedef struct PairWork:
    PairState cur
    PairState trial
    LeanState lean
    LeanState lean_trial
    double *w1      # tangent weights (z)
    double *w2
    double *w3
    double *block


cdef int pair_open(int z, PairWork *wk) noexcept nogil:
    """The work space of one pair case (one block)."""
    cdef double *m = <double *> malloc((4 * (BALL_ARRAYS + 1) + 4 * LEAN_ARRAYS + 3) * z
                                       * sizeof(double))
    cdef int k
    cdef PairState *st
    if m == NULL:
        return 0
    wk.block = m
    for k in range(2):
        st = &wk.cur if k == 0 else &wk.trial
        point_on(m, z, &st.side[0].pt)
        point_on(m + BALL_ARRAYS * z, z, &st.side[1].pt)
        st.side[0].kappa = m + 2 * BALL_ARRAYS * z
        st.side[1].kappa = m + (2 * BALL_ARRAYS + 1) * z
        m += 2 * (BALL_ARRAYS + 1) * z
    for k in range(2):
        lean_on(m, z, &wk.lean.side[k])
        lean_on(m + LEAN_ARRAYS * z, z, &wk.lean_trial.side[k])
        m += 2 * LEAN_ARRAYS * z
    wk.w1 = m
    wk.w2 = m + z
    wk.w3 = m + 2 * z
    return 1


cdef void lean_on(double *block, int z, Lean *ln) noexcept nogil:
    ln.ca = block
    ln.sa = block + z
    ln.rho = block + 2 * z
    ln.up = block + 3 * z
    ln.d = block + 4 * z
    ln.root = block + 5 * z
    ln.kappa = block + 6 * z
    ln.q = block + 7 * z


cdef void pair_local(const Pair *pr, int k, const double *vh, const double *vl, double *wh,
                     double *wl) noexcept nogil:
    """Bearing k's local position L_k v + its axial offset, double-double (the lever's
    product exact, the sums carried)."""
    cdef double s = pr.sigma[k], r = pr.arm[k], p, e, hi, e2
    cdef int i, t
    for i in range(2):
        t = i + 3
        two_prod(vh[t], r, &p, &e)
        two_sum(vh[i], p, &hi, &e2)
        quick(hi, e2 + e + vl[i] + r * vl[t], &wh[i], &wl[i])
    two_sum(s * vh[2], pr.off_hi[k], &hi, &e2)
    quick(hi, e2 + s * vl[2] + pr.off_lo[k], &wh[2], &wl[2])
    for i in range(3, 5):
        wh[i] = s * vh[i]
        wl[i] = s * vl[i]


cdef inline void lift(double s, double r, const double *f, double *out) noexcept nogil:
    """out += L_k^T f: a bearing's generalised forces f as the shaft's (its axial ones times
    sigma_k = s, its radial ones also times the lever r in the tilts)."""
    out[0] += f[0]
    out[1] += f[1]
    out[2] += s * f[2]
    out[3] += s * f[3] + r * f[0]
    out[4] += s * f[4] + r * f[1]


cdef double side_energy(const Case *cs, const Point *pt, const double *kappa) noexcept nogil:
    """sum_j Q_j delta_j of one bearing with the stiffness deviations ``kappa``."""
    cdef double total = 0.0, delta, pos, root
    cdef int j
    for j in range(cs.z):
        delta = cs.pre + pt.b.eps[j]
        pos = delta if delta > 0 else 0.0
        root = pt.lo.root[j]
        total += (1.0 + kappa[j]) * pos * root * root * root
    return total


cdef void pair_state(const Pair *pr, const double *vh, const double *vl,
                     const PairState *frozen, PairState *st, double *held_energy) noexcept nogil:
    """Both bearings at v = vh + vl, K at each ball's angle: the pair's forces, residual and
    potential; with ``frozen``, also the potential with its stiffness in
    ``held_energy``."""
    cdef const Case *cs = &pr.bear
    cdef double wh[5]
    cdef double wl[5]
    cdef int k, j, i
    cdef Point *pt
    cdef double *kappa
    for i in range(5):
        st.gen[i] = 0.0
        st.size[i] = 0.0
    st.energy = 0.0
    held_energy[0] = 0.0
    for k in range(2):
        pt = &st.side[k].pt
        kappa = st.side[k].kappa
        pair_local(pr, k, vh, vl, wh, wl)
        reference(cs, wh, wl, pt.b)
        for j in range(cs.z):
            kappa[j] = 0.0
        if cs.curve != NULL:
            loads(cs, pt.b, kappa, pt.lo)
            for j in range(cs.z):
                kappa[j] = curve_kappa(cs, pt.lo.ca[j], pt.lo.cam1[j])
        loads(cs, pt.b, kappa, pt.lo)
        forces(cs, pt.lo, pt.gen, pt.size)
        lift(pr.sigma[k], pr.arm[k], pt.gen, st.gen)
        lift(fabs(pr.sigma[k]), fabs(pr.arm[k]), pt.size, st.size)
        st.energy += side_energy(cs, pt, kappa) / 2.5
        if frozen != NULL:
            held_energy[0] += side_energy(cs, pt, frozen.side[k].kappa) / 2.5
    st.res = residual(&pr.whole, st.gen, st.size)


cdef void add_mapped(double sigma, double arm, const double *t, bint left,
                     double *out) noexcept nogil:
    """out += L^T t L: a bearing's local tangent t as the shaft's, L the map of its sign
    ``sigma`` and its radial move ``arm`` per unit of tilt; summed as L^T (t L), or where
    ``left`` as (L^T t) L (numpy's order, the pair's stiffness in physical units)."""
    cdef double tl[25]
    cdef double lk[25]
    cdef double acc
    cdef int i, m, n
    for i in range(25):
        lk[i] = 0.0
    lk[0] = 1.0
    lk[6] = 1.0
    lk[3] = arm
    lk[9] = arm
    for i in range(2, 5):
        lk[6 * i] = sigma
    for i in range(5):  # t L_k, or L_k^T t
        for n in range(5):
            acc = 0.0
            for m in range(5):
                acc += lk[5 * m + i] * t[5 * m + n] if left else t[5 * i + m] * lk[5 * m + n]
            tl[5 * i + n] = acc
    for i in range(5):  # L_k^T (t L_k), or (L_k^T t) L_k
        for n in range(5):
            acc = 0.0
            for m in range(5):
                acc += tl[5 * i + m] * lk[5 * m + n] if left else lk[5 * m + i] * tl[5 * m + n]
            out[5 * i + n] += acc


cdef void side_tangent(const Pair *pr, PairWork *wk, int k, double *t) noexcept nogil:
    """Bearing k's true tangent at the current state, local and scaled (``true_tangent``)."""
    true_tangent(&pr.bear, &wk.cur.side[k].pt, wk.cur.side[k].kappa, wk.w1, wk.w2, wk.w3, t,
                 NULL, NULL, NULL)


cdef void pair_tangent(const Pair *pr, PairWork *wk, double *out) noexcept nogil:
    """The pair's tangent d(forces)/dv at the current state, sum_k L_k^T K_k L_k with each
    bearing's true tangent K_k (``side_tangent``)."""
    cdef double t[25]
    cdef int k, i
    for i in range(25):
        out[i] = 0.0
    for k in range(2):
        side_tangent(pr, wk, k, t)
        add_mapped(pr.sigma[k], pr.arm[k], t, False, out)


cdef void pair_move(const Pair *pr, double *jac, const double *grad,
                    double *step) noexcept nogil:
    """The Newton step on the pair's tangent ``jac`` (changed: the held components decoupled,
    regularised); where it is not finite or no ball is in contact, a move of length A against
    the gradient; its axial parts (a, t, t_c) within max(A, 0.1) of the scaled approach (the
    single bearing's ``cap_step`` takes A: capped at A, a heavy pair's steps ran out short of
    the groove edge), its radial parts free (capped too, they took 10^3 steps where the
    approach is 10^3 A)."""
    cdef double minus[5]
    cdef double trace = 0.0, norm = 0.0, longest = 0.0, a_hat = pr.bear.a_hat
    cdef bint bad = False
    cdef int i, k
    for i in range(5):
        minus[i] = -grad[i]
        if pr.whole.locked[i]:
            for k in range(5):
                jac[5 * i + k] = 0.0
                jac[5 * k + i] = 0.0
            jac[6 * i] = 1.0
    for i in range(5):
        trace += jac[6 * i]
    for i in range(5):
        jac[6 * i] += 1e-13 * fabs(trace) + 1e-300
    solve5(jac, minus, step)
    for i in range(5):
        bad = bad or not isfinite(step[i])
    if bad or not trace > 1e-200:
        for i in range(5):
            norm += grad[i] * grad[i]
        norm = max(sqrt(norm), 1e-300)
        for i in range(5):
            step[i] = -grad[i] / norm * a_hat
    for i in range(2, 5):
        longest = max(longest, fabs(step[i]))
    reach = max(a_hat, 0.1)
    if longest > reach:
        for i in range(5):
            step[i] *= reach / longest


cdef void pair_step(const Pair *pr, PairWork *wk, double *step) noexcept nogil:
    """The Newton step of the double-double stage at the current state."""
    cdef double jac[25]
    cdef double grad[5]
    cdef int i
    for i in range(5):
        grad[i] = 0.0 if pr.whole.locked[i] else wk.cur.gen[i] - pr.whole.f[i]
    pair_tangent(pr, wk, jac)
    pair_move(pr, jac, grad, step)


cdef void swap_states(PairState *a, PairState *b) noexcept nogil:
    cdef PairState t = a[0]
    a[0] = b[0]
    b[0] = t


cdef void pair_search(const Pair *pr, PairWork *wk, const double *vh, const double *vl,
                      const double *step, double *moved) noexcept nogil:
    """The move t step, t = 1, 1/2, ..., the first where the potential with the stiffness
    frozen falls by 1e-4 of its slope (Armijo) or the residual halves; 0 where none does. The
    current state becomes the one reached."""
    cdef double slope = 0.0, t = 1.0, work, drop, held_energy
    cdef double w[5]
    cdef double th[5]
    cdef double tl[5]
    cdef bint finite
    cdef int k, i
    for i in range(5):
        moved[i] = 0.0
        if not pr.whole.locked[i]:
            slope += (wk.cur.gen[i] - pr.whole.f[i]) * step[i]
    for k in range(pr.halvings):
        work = 0.0
        finite = True
        for i in range(5):
            w[i] = t * step[i]
            work += pr.whole.f[i] * w[i]
            finite = finite and isfinite(w[i])
            two_sum(vh[i], w[i], &th[i], &tl[i])
            quick(th[i], tl[i] + vl[i], &th[i], &tl[i])
        pair_state(pr, th, tl, &wk.cur, &wk.trial, &held_energy)
        drop = held_energy - wk.cur.energy - work
        if finite and (drop <= 1e-4 * t * slope or wk.trial.res < 0.5 * wk.cur.res):
            for i in range(5):
                moved[i] = w[i]
            swap_states(&wk.cur, &wk.trial)
            return
        t *= 0.5


cdef int pair_newton(const Pair *pr, PairWork *wk, double *vh, double *vl,
                     double *res) noexcept nogil:
    """Damped Newton of one case from vh + vl until its residual is within TOLERANCE, it
    stalls (rounding), or max_steps: vh, vl the position, res its residual.
    Returns the steps taken."""
    cdef double best = INFINITY, held_energy, hi, lo
    cdef double step[5]
    cdef double moved[5]
    cdef int n, i, stall = 0, its = 0
    cdef bint still
    pair_state(pr, vh, vl, NULL, &wk.cur, &held_energy)
    res[0] = INFINITY
    for n in range(pr.max_steps):
        res[0] = wk.cur.res
        if wk.cur.res < 0.5 * best or wk.cur.res > pr.bear.lim.stall_below:
            best = wk.cur.res
            stall = 0
        else:
            stall += 1
        if (wk.cur.res <= pr.bear.lim.tolerance or stall >= pr.bear.lim.stall
                or not isfinite(wk.cur.res)):
            break
        pair_step(pr, wk, step)
        pair_search(pr, wk, vh, vl, step, moved)
        still = True
        for i in range(5):
            still = still and moved[i] == 0.0
        if still:
            stall = pr.bear.lim.stall  # no step taken: rounding (or a failed search)
        for i in range(5):
            two_sum(vh[i], moved[i], &hi, &lo)
            quick(hi, lo + vl[i], &vh[i], &vl[i])
        its += 1
    return its


cdef double preload_thrust(const Case *cs, double delta) noexcept nogil:
    """The thrust (scaled) of the one-sided bearing ``cs`` with every ball at the approach
    ``delta`` and no radial move: ``z K(alpha) delta^1.5 sin(alpha)``, ``cos(alpha) =
    A cos(alpha_0)/(A + delta)``."""
    cdef double d = cs.a_hat + delta, sa, ca, kappa = 0.0
    # sin^2 = (d^2 - cc^2)/d^2, with d^2 - cc^2 = gap (2A - gap) + delta (2A + delta)
    sa = sqrt(cs.gap * (2.0 * cs.a_hat - cs.gap) + delta * (2.0 * cs.a_hat + delta)) / d
    if cs.curve != NULL:
        ca = (cs.a_hat - cs.gap) / d
        kappa = curve_kappa(cs, ca, -sa * sa / (1.0 + ca))
    return cs.z * (1.0 + kappa) * pow(delta, 1.5) * sa


cdef double preload_delta(const Case *cs, double target) noexcept nogil:
    """The approach of every ball of the bearing ``cs`` carrying the thrust ``target > 0``
    (scaled) alone, by secant steps in log-log to the last digit (Harris & Kotzalas §8.3): from
    the approach at the free angle (an upper bound), the slope 1.5 of a fixed angle first and
    within [1, 4] after; stopped at the first step below the last digit."""
    cdef double goal = log(target), sin0, x0, x1, x2, f0, f1, step, slope, root
    cdef int i
    sin0 = sqrt(cs.gap * (2.0 * cs.a_hat - cs.gap)) / cs.a_hat
    root = cbrt(target / (cs.z * sin0))
    x0 = root * root
    f0 = log(preload_thrust(cs, x0)) - goal
    x1 = x0 * exp(-f0 / 1.5)
    for i in range(60):
        f1 = log(preload_thrust(cs, x1)) - goal
        step = log(x1) - log(x0)
        slope = (f1 - f0) / step if step != 0 else 1.5
        x2 = x1 * exp(-f1 / min(max(slope, 1.0), 4.0))
        x0, f0 = x1, f1
        if not fabs(x2 - x1) > 2e-16 * x1:
            break
        x1 = x2
    return x1


cdef void axial_position(Case *cs, double delta, double *hi, double *lo) noexcept nogil:
    """The axial position (double-double) at which every ball of the one-sided bearing ``cs``
    is at the approach ``delta`` with no radial move: the closed form, then 4 Newton steps on
    the double-double approach of ``reference`` (every ball alike: one ball on the load line)."""
    cdef double vh[5]
    cdef double vl[5]
    cdef double rho, u, d, eps, up, sa, sum_, err
    cdef double one = 1.0, zero = 0.0
    cdef Balls b
    cdef int i
    b.rho, b.u, b.d, b.eps, b.up = &rho, &u, &d, &eps, &up
    cs.z, cs.c, cs.s, cs.t_imp, cs.one_sided = 1, &one, &zero, 0.0, 1
    for i in range(5):
        vh[i] = 0.0
        vl[i] = 0.0
    hi[0] = sqrt(cs.gap * (2.0 * cs.a_hat - cs.gap) + delta * (2.0 * cs.a_hat + delta))
    lo[0] = 0.0
    for i in range(4):
        vh[2] = hi[0]
        vl[2] = lo[0]
        reference(cs, vh, vl, b)
        sa = up / (d if d > 0 else 1.0)
        two_sum(hi[0], (delta - eps) / (sa if sa > 0 else 1.0), &sum_, &err)
        quick(sum_, err + lo[0], hi, lo)


cdef void preload_offset(const Case *bear, double target, double *delta, double *hi,
                         double *lo) noexcept nogil:
    """The approach ``delta`` of every ball of the bearing ``bear`` carrying the thrust ``target``
    (scaled; 0 where not positive: ``preload_delta``) and the axial position (hi, lo) there
    (``axial_position``)."""
    cdef Case one
    memset(&one, 0, sizeof(Case))
    one.z = bear.z
    one.node_x = bear.node_x
    one.node_w = bear.node_w
    one.a_hat, one.gap, one.b_hi, one.b_lo = bear.a_hat, bear.gap, bear.b_hi, bear.b_lo
    one.curve = bear.curve
    delta[0] = preload_delta(&one, target) if target > 0 else 0.0
    axial_position(&one, delta[0], hi, lo)


cdef void pair_case(Pair *pr, Py_ssize_t k, int z, const double *c, const double *s,
                    double a_hat, double pre, double gap, double b_hi,
                    double b_lo) noexcept nogil:
    """The balls of case k's bearings (one-sided contacts, no imposed tilt)."""
    cdef int i
    pr.bear.z = z
    pr.bear.c = c
    pr.bear.s = s
    pr.bear.a_hat = a_hat
    pr.bear.pre = pre
    pr.bear.gap = gap
    pr.bear.b_hi = b_hi
    pr.bear.b_lo = b_lo
    pr.bear.t_imp = 0.0
    pr.bear.one_sided = 1
    pr.bear.deviation = pre > 0 and z >= 2
    pr.bear.q0 = pre * sqrt(pre) if pr.bear.deviation else 0.0
    for i in range(5):
        pr.bear.f[i] = 0.0
        pr.bear.locked[i] = 0
    pr.whole.z = z


# ------------------------------------------------------------ the pair's plain-double stage

cdef void lean_side(const Case *cs, const double *w, Lean *ln, double *gen, double *size,
                    double *energy) noexcept nogil:
    """One bearing at the local position w in plain doubles, K at each ball's angle (pair.
    _lean_state): its balls, its generalised forces (compensated), their terms' magnitudes and
    sum_j Q_j delta_j."""
    cdef int j, i
    cdef double rho, u, up, rp, d, m, eps, safe, pos, cam1, qc, qs
    cdef double err[5]
    for i in range(5):
        gen[i] = 0.0
        size[i] = 0.0
        err[i] = 0.0
    energy[0] = 0.0
    for j in range(cs.z):
        rho = (cs.a_hat - cs.gap) + (w[0] * cs.c[j] + w[1] * cs.s[j])
        u = w[2] + w[3] * cs.c[j] + w[4] * cs.s[j]
        up = max(u, 0.0)
        rp = max(rho, 0.0)
        d = hypot(rp, up)
        m = rho - cs.a_hat
        eps = (m * (m + 2.0 * cs.a_hat) + up * up) / (d + cs.a_hat) if rho > 0 else up - cs.a_hat
        safe = d if d > 0 else 1.0
        ln.ca[j] = rp / safe if d > 0 else 1.0
        ln.sa[j] = up / safe
        ln.rho[j] = rho
        ln.up[j] = up
        ln.d[j] = d
        pos = max(eps, 0.0)
        ln.root[j] = sqrt(pos)
        ln.kappa[j] = 0.0
        if cs.curve != NULL:
            cam1 = -ln.sa[j] * ln.sa[j] / (1.0 + ln.ca[j]) if rho > 0 else ln.ca[j] - 1.0
            ln.kappa[j] = curve_kappa(cs, ln.ca[j], cam1)
        ln.q[j] = (1.0 + ln.kappa[j]) * pos * ln.root[j]
        energy[0] += ln.q[j] * pos
        qc = ln.q[j] * ln.ca[j]
        qs = ln.q[j] * ln.sa[j]
        add_ball(cs, j, qc, qs, fabs(qc), fabs(qs), gen, err, size)
    for i in range(5):
        gen[i] += err[i]


cdef void lean_state(const Pair *pr, const double *v, LeanState *st) noexcept nogil:
    """The pair at v in plain doubles: each bearing at L_k v plus its offset, the pair's forces,
    residual and potential."""
    cdef double w[5]
    cdef double gen[5]
    cdef double size[5]
    cdef double energy, total = 0.0, work = 0.0
    cdef int k, i
    for i in range(5):
        st.gen[i] = 0.0
        st.size[i] = 0.0
    for k in range(2):
        w[0] = v[0] + pr.arm[k] * v[3]
        w[1] = v[1] + pr.arm[k] * v[4]
        w[2] = (pr.off_hi[k] + pr.off_lo[k]) + pr.sigma[k] * v[2]
        w[3] = pr.sigma[k] * v[3]
        w[4] = pr.sigma[k] * v[4]
        lean_side(&pr.bear, w, &st.side[k], gen, size, &energy)
        lift(pr.sigma[k], pr.arm[k], gen, st.gen)
        lift(fabs(pr.sigma[k]), fabs(pr.arm[k]), size, st.size)
        total += energy
    for i in range(5):
        work += pr.whole.f[i] * v[i]
    st.res = residual(&pr.whole, st.gen, st.size)
    st.energy = total / 2.5 - work


cdef void lean_step(const Pair *pr, PairWork *wk, double *step) noexcept nogil:
    """The Newton step of the first stage: the pair's tangent at the lean state (with the
    change of K with the angle), as pair_move takes it."""
    cdef const Case *cs = &pr.bear
    cdef Lean *ln
    cdef double jac[25]
    cdef double t[25]
    cdef double grad[5]
    cdef double safe
    cdef bint turning
    cdef int k, j, i
    for i in range(25):
        jac[i] = 0.0
    for k in range(2):
        ln = &wk.lean.side[k]
        for j in range(cs.z):
            safe = ln.d[j] if ln.d[j] > 0 else 1.0
            turning = ln.rho[j] > 0 and ln.up[j] > 0
            wk.w1[j] = 1.5 * (1.0 + ln.kappa[j]) * ln.root[j]
            wk.w2[j] = ln.q[j] / safe if turning else 0.0
            wk.w3[j] = 0.0
            if cs.curve != NULL and turning and ln.root[j] > 0:
                wk.w3[j] = (curve_slope(cs, ln.ca[j], -ln.sa[j] * ln.sa[j] / (1.0 + ln.ca[j]))
                            * -ln.sa[j] * ln.root[j] ** 3 / safe)
        tangent(cs, ln.ca, ln.sa, wk.w1, wk.w2, wk.w3 if cs.curve != NULL else NULL, False, t)
        add_mapped(pr.sigma[k], pr.arm[k], t, False, jac)
    for i in range(5):
        grad[i] = 0.0 if pr.whole.locked[i] else wk.lean.gen[i] - pr.whole.f[i]
    pair_move(pr, jac, grad, step)


cdef void swap_lean(LeanState *a, LeanState *b) noexcept nogil:
    cdef LeanState t = a[0]
    a[0] = b[0]
    b[0] = t


cdef int lean_newton(const Pair *pr, PairWork *wk, double *v) noexcept nogil:
    """The first stage from v: damped Newton in plain doubles until the residual is below
    first_stage or first_steps steps; a step t = 1, 1/2, ... where the potential falls
    (Armijo, 1e-4 of the slope) or the residual halves; a case whose search finds none is
    handed on. Returns the steps taken (the failed search counted)."""
    cdef double step[5]
    cdef double trial[5]
    cdef double slope, t
    cdef int n, h, i, its = 0
    cdef bint taken
    lean_state(pr, v, &wk.lean)
    for n in range(pr.first_steps):
        if not wk.lean.res > pr.first_stage:
            break
        lean_step(pr, wk, step)
        slope = 0.0
        for i in range(5):
            slope += (0.0 if pr.whole.locked[i] else wk.lean.gen[i] - pr.whole.f[i]) * step[i]
        t = 1.0
        taken = False
        for h in range(pr.first_halvings):
            for i in range(5):
                trial[i] = v[i] + t * step[i]
            lean_state(pr, trial, &wk.lean_trial)
            if (wk.lean_trial.energy - wk.lean.energy <= 1e-4 * t * slope
                    or wk.lean_trial.res < 0.5 * wk.lean.res):
                taken = True
                break
            t *= 0.5
        its += 1
        if not taken:
            break
        for i in range(5):
            v[i] = trial[i]
        swap_lean(&wk.lean, &wk.lean_trial)
    return its


# ------------------------------------------------------------- one call of the pair

cpdef enum PairFlag:
    UNBALANCED = 1     # the residual above the acceptance (or not finite)
    EDGE_FIRST = 2     # a loaded ball of bearing 1 at a contact angle of 90°
    EDGE_SECOND = 4    # the same in bearing 2
    STIFF_OVERFLOW = 8 # a bearing's physical stiffness overflows
    NO_CURVE = 16      # a Hertz curve the core cannot set up (the case not solved)
    NO_GROOVE = 32     # a geometry ``groove`` refuses, or balls that overlap (the case not solved)
    BAD_WIDTH = 64     # a width below D_w or beyond its largest times d_m (the case not solved)


cdef int NOT_SET_UP = BAD_WIDTH | NO_GROOVE | NO_CURVE


ctypedef struct PairCase:
    # one case of ``pair_call``: the Pair, its set-up and its answer
    Pair pr
    double geo[4]     # A, g, R_i (the tilt lever: the tilt radius where given), alpha_0 [mm, rad]
    double out[8]     # problem_case's s, A/s, p, gap, b_hi, b_lo, t_imp, F
    double v[5]       # the start, then the answer (double-double with ``vl``)
    double vl[5]
    double delta      # the preload approach, scaled
    double res
    double k0         # K_0, or the constant K
    int status        # problem_case's SetupStatus
    unsigned char mirror


cdef double cube_root(double x) noexcept nogil:
    """The cube root of ``x`` rounded to nearest: libm's cbrt (within an ulp) and one Newton
    step on its residual y^3 - x in double-double (y^3 within a few ulps of x: their difference
    exact), the bits numpy's cbrt gives (but for rare hard cases)."""
    cdef double y = cbrt(x), p, e, q, f
    if not (isfinite(y) and y != 0):
        return y
    two_prod(y, y, &p, &e)
    two_prod(p, y, &q, &f)
    return y - ((q - x) + (f + e * y)) / (3.0 * (y * y))


cdef void pair_start(int z, double alpha0, double sigma2, double pre, const double *f,
                     double *v) noexcept nogil:
    """The standard start of a pair's case: the shares of the loads a rigid ring would give
    (Stribeck's 5 for the radial load, the thrust on one bearing, or on both of a tandem
    pair: ``sigma2`` > 0), or the preloaded position where the preload ``pre`` is the largest
    load (scaled forces ``f``)."""
    cdef double ca = cos(alpha0), sa = sin(alpha0), top = 0.0, share, root
    cdef int i
    share = (0.5 if sigma2 > 0 else 1.0) * fabs(f[2])
    root = cube_root(share / (z * sa))
    v[2] = ((f[2] > 0) - (f[2] < 0)) * (root * root) / sa
    root = cube_root(2.5 * f[0] / (z * ca))
    v[0] = (root * root) / ca
    v[1] = v[3] = v[4] = 0.0
    for i in range(5):
        top = max(top, fabs(f[i]))
    if pre >= top:
        for i in range(5):
            v[i] = 0.0


cdef void pair_defaults(Pair *pr, int max_steps, int halvings, double first_stage,
                        int first_steps, int first_halvings) noexcept nogil:
    """The limits of every case of a pair's solve (the module's)."""
    memset(pr, 0, sizeof(Pair))
    pr.bear.lim = LIMITS
    pr.whole = pr.bear
    pr.max_steps, pr.halvings = max_steps, halvings
    pr.first_stage, pr.first_steps, pr.first_halvings = first_stage, first_steps, first_halvings


ctypedef struct PairCall:
    # the inputs, work space and outputs of one ``pair_call`` (its docstring)
    int z
    Py_ssize_t n
    bint hertz
    const double *limits
    const double *known    # K_0 and the curve's values of each case (1 + NODES), or NULL
    const double *node_x
    double *geo6           # (n, 6): each case's D_w, d_m, f_i, f_o, E, nu
    double *c              # (z): the case's ball directions
    double *s
    double *k0             # (n)
    double *values         # (n, NODES)
    double *rows           # (10, 2n)
    double *per_ball       # (5, 2n, z)
    double *tangents       # (2, n, 25)
    double *stiff          # (n, 25)
    unsigned char *unloaded  # (n, 2)
    int64_t *its           # (n)


cdef int stiffness_of(const double *col, Py_ssize_t n, int row, const double *known,
                      bint reuse, const double *node_x, double *geo6, double *k0,
                      double *values) noexcept nogil:
    """A case's stiffness (``col`` its column of the input rows, ``n`` apart): with ``values``
    NULL the constant K of its row ``row``; else K_0 and the Hertz curve's values from
    ``known`` (K_0 and the values) where not NULL, else by ``curve_of`` of its six ``geo6``
    (the case before's, just before, where ``reuse``). Returns 0 where the core cannot."""
    cdef int i
    if values == NULL:
        k0[0] = col[row * n]
    elif known != NULL:
        k0[0] = known[0]
        for i in range(NODES):
            values[i] = known[1 + i]
    else:
        geo6[0], geo6[1], geo6[2], geo6[3] = col[9 * n], col[10 * n], col[11 * n], col[12 * n]
        geo6[4], geo6[5] = col[7 * n], col[8 * n]
        return curve_of(geo6, geo6 - 6 if reuse else geo6, reuse, node_x, k0, values)
    return 1


cdef int pair_set_up(const PairCall *call, Py_ssize_t k, const double *col, bint reuse,
                     PairCase *pc) noexcept nogil:
    """Case k of ``pair_call`` set up (``col`` its column of the input rows, n apart): the
    groove (``groove_case``; the tilt radius where given), the stiffness (``stiffness_of``), the
    scaled problem (``problem_case``), the held components, the preload offset
    (``preload_offset``) and the start. Returns BAD_WIDTH, NO_GROOVE (also balls that overlap)
    or NO_CURVE where it cannot, else 0."""
    cdef const double *limits = call.limits
    cdef double load[6]
    cdef unsigned char held[5]
    cdef Pair *pr = &pc.pr
    cdef Py_ssize_t n = call.n
    cdef int i
    if col[14 * n] < col[9 * n] or col[14 * n] > limits[10] * col[10 * n]:
        return BAD_WIDTH
    if not groove_case(&col[9 * n], n, True, limits[3], limits[4], pc.geo, 1, True):
        return NO_GROOVE
    if not col[9 * n] <= col[10 * n] * limits[11] * (1.0 + 1e-12):  # (as ``set_up``)
        return NO_GROOVE
    if not stiffness_of(col, n, 15, &call.known[(1 + NODES) * k] if call.known != NULL else NULL,
                        reuse, call.node_x, &call.geo6[6 * k], &call.k0[k],
                        &call.values[NODES * k] if call.hertz else NULL):
        return NO_CURVE
    pc.k0 = call.k0[k]
    if col[16 * n] > 0:
        pc.geo[2] = col[16 * n]
    for i in range(6):
        load[i] = col[i * n]
    pc.status = problem_case(call.z, load, col[6 * n], pc.geo, pc.k0, True, False, limits, 1,
                             call.c, call.s, &pc.mirror, held, pr.whole.f, pc.out)
    symmetry_locks(call.z, pc.mirror, load[0], load[1], load[2], load[3], 0.0, False,
                   limits[7] > 0, held)
    pair_case(pr, k, call.z, call.c, call.s, pc.out[1], pc.out[2], pc.out[3], pc.out[4],
              pc.out[5])
    pr.bear.curve = &call.values[NODES * k] if call.hertz else NULL
    for i in range(5):
        pr.whole.locked[i] = held[i]
    preload_offset(&pr.bear, load[5] / pc.out[7], &pc.delta, &pr.off_hi[0], &pr.off_lo[0])
    for i in range(2):
        pr.sigma[i] = limits[6 + i]
        pr.arm[i] = -(limits[8 + i] * col[14 * n] / pc.geo[2])
        pr.off_hi[i], pr.off_lo[i] = pr.off_hi[0], pr.off_lo[0]
    pair_start(call.z, pc.geo[3], limits[7], load[5] / pc.out[7], pr.whole.f, pc.v)
    return 0


cdef void lift_off(const Case *cs, double delta, double f_ref, double *offset,
                   double *thrust) noexcept nogil:
    """A preloaded bearing's offset and the pair's lift-off thrust: from its scaled A/s and
    max(g, 0)/s and its preload approach ``delta``, the axial approach from the zero-load
    position to every ball at it, ``u_p - u_0 = delta (2A + delta)/(u_p + u_0)`` (without
    cancellation; u_0^2 = g (2A - g)), and the external thrust at which the other bearing
    carries nothing, this one at twice that offset: z (1 + kappa) delta^1.5 sin(alpha) F [N]."""
    cdef double big_a = cs.a_hat, u0, up, cc, w, u, d, dd, ca, sa, kappa
    u0 = sqrt(cs.gap * (2.0 * big_a - cs.gap))
    up = sqrt(u0 * u0 + delta * (2.0 * big_a + delta))
    offset[0] = delta * (2.0 * big_a + delta) / (up + u0)
    cc = big_a - cs.gap
    w = 2.0 * offset[0]
    u = u0 + w
    d = hypot(cc, u)
    dd = w * (2.0 * u0 + w) / (d + big_a)
    ca, sa = cc / d, u / d
    kappa = curve_kappa(cs, ca, -sa * sa / (1.0 + ca))
    thrust[0] = cs.z * (1.0 + kappa) * pow(dd, 1.5) * sa * f_ref


cdef int side_edge(const Case *cs, const Point *pt) noexcept nogil:
    """Whether a loaded ball of a bearing sits at the groove edge (contact angle 90°)."""
    cdef int j
    for j in range(cs.z):
        if pt.lo.root[j] > 0 and (pt.b.rho[j] <= 0 or (
                pt.lo.ca[j] < 1e-8 and atan2(fabs(pt.lo.sa[j]), pt.lo.ca[j]) * (180.0 / PI)
                >= 90.0)):
            return 1
    return 0


cdef int side_result(const PairCase *pc, PairWork *wk, int b, const double *col,
                     Py_ssize_t n, double *row, double *ball, double *tangent, double *stiff,
                     unsigned char *unloaded) noexcept nogil:
    """Bearing b's results (``col`` the case's column of the input rows, ``n`` apart; ``row``
    its column of the bearing rows, ``ball`` of the ball rows, 2n apart): its loads (the size
    of its radial force, its thrust [N] in rows 8, 9, its moment [N mm]; the radial force and
    the moment exactly 0 where the shaft takes no radial load nor moment), ``result_case``
    with its tangent made physical (``tangent``) and added to the pair's (``stiff``), whether
    it carries no load. Returns its flags (STIFF_OVERFLOW, its EDGE_)."""
    cdef const Pair *pr = &pc.pr
    cdef const Point *pt = &wk.cur.side[b].pt
    cdef double f_ref = pc.out[7], radius = pc.geo[2]
    cdef double wh[5]
    cdef double wl[5]
    cdef double case_in[11]
    cdef const double *bl[4]
    cdef int i, flags = 0
    cdef bint axisymmetric = pr.whole.locked[0]
    pair_local(pr, b, pc.v, pc.vl, wh, wl)
    for i in range(5):
        wh[i] += wl[i]
    row[8 * 2 * n] = 0.0 if axisymmetric else hypot(pt.gen[0], pt.gen[1]) * f_ref
    row[9 * 2 * n] = pt.gen[2] * f_ref
    case_in[0], case_in[1], case_in[2], case_in[3] = pc.out[6], pc.out[0], radius, pc.geo[3]
    case_in[4], case_in[5], case_in[6] = pc.geo[0], 1.0, f_ref
    case_in[7] = 0.0 if axisymmetric else pt.gen[3] * f_ref * radius
    case_in[8], case_in[9], case_in[10] = col[6 * n], pc.out[2], pc.k0
    bl[0], bl[1], bl[2], bl[3] = pt.b.eps, pt.lo.ca, pt.lo.sa, pt.lo.q
    side_tangent(pr, wk, b, tangent)
    if not result_case(wh, case_in, 1, pt.gen, bl, 1, wk.cur.side[b].kappa, pr.bear.z, False,
                       tangent, pc.mirror and col[3 * n] == 0, row, ball, 2 * n):
        flags |= STIFF_OVERFLOW
    add_mapped(pr.sigma[b], pr.arm[b] * radius, tangent, True, stiff)
    unloaded[0] = True
    for i in range(pr.bear.z):
        unloaded[0] = unloaded[0] and pt.lo.q[i] == 0
    if side_edge(&pr.bear, pt):
        flags |= EDGE_FIRST if b == 0 else EDGE_SECOND
    return flags


cdef void pair_rows(const PairCase *pc, const double *col, Py_ssize_t n,
                    double *row) noexcept nogil:
    """A case's column of the pair's rows (``n`` apart): F_r, F_a, M, M_c, F_p [N, N mm], the
    preload offset [mm], B [mm], the shaft's x, y, axial [mm], tilt, tilt_cross [°], the
    residual, the lift-off thrust (the sign of F_a, + if 0) [N], R_i [mm]."""
    cdef double sc = pc.out[0], radius = pc.geo[2], offset, thrust, moved
    cdef int i
    for i in range(5):
        row[i * n] = col[i * n] if i < 4 else col[5 * n]
        moved = (pc.v[i] + pc.vl[i]) * sc
        row[(7 + i) * n] = moved if i < 3 else (moved / radius) * (180.0 / PI)
    lift_off(&pc.pr.bear, pc.delta, pc.out[7], &offset, &thrust)
    row[5 * n], row[6 * n], row[12 * n] = offset * sc, col[14 * n], pc.res
    row[13 * n], row[14 * n] = -thrust if col[n] < 0 else thrust, radius


cdef int pair_one(const PairCall *call, Py_ssize_t k, const double *col, bint reuse,
                  PairCase *pc, PairWork *wk) noexcept nogil:
    """Case k of ``pair_call`` set up, solved from the standard start and its results
    written (``side_result``; the pair's stiffness, its couplings of (x, axial, tilt) with (y,
    tilt_cross) 0 where the case is mirrored). Returns its PairFlags."""
    cdef Py_ssize_t n = call.n, col_b
    cdef double *stiff = &call.stiff[25 * k]
    cdef int i, b, flags = pair_set_up(call, k, col, reuse, pc)
    if flags:
        return flags
    for i in range(5):
        pc.vl[i] = 0.0
    call.its[k] = lean_newton(&pc.pr, wk, pc.v)
    call.its[k] += pair_newton(&pc.pr, wk, pc.v, pc.vl, &pc.res)
    if not pc.res <= call.limits[5]:
        flags |= UNBALANCED
    for i in range(25):
        stiff[i] = 0.0
    for b in range(2):
        col_b = b * n + k
        flags |= side_result(pc, wk, b, col, n, &call.rows[col_b],
                             &call.per_ball[call.z * col_b], &call.tangents[25 * col_b], stiff,
                             &call.unloaded[2 * k + b])
    if pc.mirror and col[3 * n] == 0:
        for i in range(25):
            if (i // 5 == 1 or i // 5 == 4) != (i % 5 == 1 or i % 5 == 4):
                stiff[i] = 0.0
    return flags


def pair_call(int z, const double[:, ::1] cols, bint hertz, const double[::1] known,
              const double[::1] limits, const double[::1] node_x, const double[::1] node_w):
    """One call of the pair solver (bearingload.models.pair) on n cases: per case the set-up
    (``groove``, the Hertz curve, ``combined_problem``, the held components, the preload
    offset, the start), the solve (a damped Newton over the shaft's position, first in plain
    doubles (``lean_newton``), then with the balls in double-double (``pair_newton``)) and the
    results; the caller refuses what it flags.

    ``cols`` (17, n): the input rows of pair.INPUT_ROWS; ``hertz``: the Hertz stiffness (else
    the constant K of the stiffness row), with ``known`` = K_0 and the curve's values (1 +
    NODES) of every case where known, else empty; ``limits`` = the symmetry snap [°], the
    largest and the smallest A/s (angular contact: TOO_HEAVY below it), the conformity range
    (2), the residual accepted, sigma_k (2: +1, or -1 for a mirrored bearing), z_k/B (2), the
    largest width over d_m, sin(180°/z) (balls of D_w above d_m times it overlap: flagged
    NO_GROOVE); the nodes and weights of the curve; the iteration limits are the module's.

    Returns (whether no case is flagged, then (n cases): the PairFlags (uint8), problem_case's
    SetupStatus (int8), the steps, K_0 or the constant K, the curve's values (n, NODES), the
    bearings' rows (10, 2n, bearing-major) = ``combined_result``'s 8 (the tangent made
    physical), the size of the radial force and the thrust [N]; the ball rows (5, 2n, z); the
    bearings' physical tangents (2, n, 5, 5); the pair's rows (15, n: ``pair_rows``); the
    pair's stiffness sum_k L_k^T K_k L_k at its centre (n, 5, 5); whether each bearing carries
    no load (n, 2) bool). A case flagged BAD_WIDTH, NO_GROOVE or NO_CURVE is not solved: its
    outputs but the flags are not set."""
    cdef Py_ssize_t n = cols.shape[1], k
    out = (np.zeros(n, dtype=np.uint8), np.zeros(n, dtype=np.int8), np.zeros(n, dtype=np.int64),
           np.empty(n), np.empty((n, NODES)), np.empty((10, 2 * n)), np.empty((5, 2 * n, z)),
           np.empty((2, n, 5, 5)), np.empty((15, n)), np.empty((n, 5, 5)),
           np.empty((n, 2), dtype=bool))
    cdef unsigned char[::1] flags = out[0]
    cdef signed char[::1] status = out[1]
    cdef int64_t[::1] its = out[2]
    cdef double[::1] k0 = out[3]
    cdef double[:, ::1] values = out[4], rows = out[5], prow = out[8]
    cdef double[:, :, ::1] per_ball = out[6], stiff = out[9]
    cdef double[:, :, :, ::1] tangents = out[7]
    cdef unsigned char[:, ::1] unloaded = out[10].view(np.uint8)
    cdef PairCall call
    cdef PairCase pc
    cdef PairWork wk
    cdef bint clean = True, reuse
    cdef double *buf = NULL
    if n == 0:
        return (clean,) + out
    buf = <double *> malloc((2 * z + 6 * n) * sizeof(double))
    if buf == NULL or not pair_open(z, &wk):
        free(buf)
        raise MemoryError()
    call.z, call.n, call.hertz, call.limits = z, n, hertz, &limits[0]
    call.known = &known[0] if known.shape[0] else NULL
    call.node_x, call.c, call.s, call.geo6 = &node_x[0], buf, buf + z, buf + 2 * z
    call.k0, call.values, call.rows = &k0[0], &values[0, 0], &rows[0, 0]
    call.per_ball, call.tangents = &per_ball[0, 0, 0], &tangents[0, 0, 0, 0]
    call.stiff, call.unloaded, call.its = &stiff[0, 0, 0], &unloaded[0, 0], &its[0]
    pair_defaults(&pc.pr, PAIR_MAX_STEPS, PAIR_HALVINGS, PAIR_FIRST_STAGE, PAIR_FIRST_STEPS,
                  PAIR_FIRST_HALVINGS)
    pc.pr.bear.node_x, pc.pr.bear.node_w = &node_x[0], &node_w[0]
    with nogil:
        for k in range(n):
            reuse = k > 0 and not flags[k - 1] & NOT_SET_UP
            flags[k] = pair_one(&call, k, &cols[0, k], reuse, &pc, &wk)
            if not flags[k] & NOT_SET_UP:
                status[k] = pc.status
                pair_rows(&pc, &cols[0, k], n, &prow[0, k])
            clean = clean and flags[k] == 0 and status[k] == SET_UP
    free(buf)
    free(wk.block)
    return (clean,) + out


# ------------------------------------------------------------------------ the balls at speed
#
# One ball of bearingload.models.high_speed (Jones's outer-raceway control; the model is stated
# there): its two equations (g1, g2), the forces it puts on the inner ring (F_a = Q_i sin a_i,
# F_r = Q_i cos a_i) and their derivatives by (delta_o, alpha_o, rho, u'), in forward-mode dual
# arithmetic: the chain rule applied term by term, exact to rounding.

cdef enum:
    # g1, g2, Q_i, Q_o, sin a_i, cos a_i, F_c, M_g, omega_c, omega_R, beta, delta_i, F_a, F_r
    BALL_TERMS = 14
    # rows g1, g2, F_a, F_r; columns delta_o, alpha_o, rho, u'
    BALL_PARTIALS = 16

#: N mm per kg mm^2/s^2 (forces from kg, mm, s). [-]
cdef double KG_MM = 1e-3
cdef double EPS = 2.220446049250313e-16


cdef inline Dual dual(double v) noexcept nogil:
    cdef Dual r
    r.v = v
    r.d[0] = 0.0
    r.d[1] = 0.0
    r.d[2] = 0.0
    r.d[3] = 0.0
    return r


cdef inline Dual variable(double v, int k) noexcept nogil:
    cdef Dual r = dual(v)
    r.d[k] = 1.0
    return r


cdef inline Dual d_add(Dual a, Dual b) noexcept nogil:
    cdef int k
    a.v = a.v + b.v
    for k in range(4):
        a.d[k] = a.d[k] + b.d[k]
    return a


cdef inline Dual d_sub(Dual a, Dual b) noexcept nogil:
    cdef int k
    a.v = a.v - b.v
    for k in range(4):
        a.d[k] = a.d[k] - b.d[k]
    return a


cdef inline Dual d_mul(Dual a, Dual b) noexcept nogil:
    cdef Dual r
    cdef int k
    r.v = a.v * b.v
    for k in range(4):
        r.d[k] = a.d[k] * b.v + a.v * b.d[k]
    return r


cdef inline Dual d_div(Dual a, Dual b) noexcept nogil:
    cdef Dual r
    cdef int k
    r.v = a.v / b.v
    for k in range(4):
        r.d[k] = (a.d[k] - r.v * b.d[k]) / b.v
    return r


cdef inline Dual d_scale(Dual a, double s) noexcept nogil:
    """s a, the constant on the left (as the numpy expressions it replaces round)."""
    cdef int k
    a.v = s * a.v
    for k in range(4):
        a.d[k] = s * a.d[k]
    return a


cdef inline Dual d_chain(double v, double slope, Dual a) noexcept nogil:
    """f(a) from its value v = f(a.v) and slope f'(a.v)."""
    cdef Dual r
    cdef int k
    r.v = v
    for k in range(4):
        r.d[k] = slope * a.d[k]
    return r


cdef inline Dual d_sqrt(Dual a) noexcept nogil:
    cdef double v = sqrt(a.v)
    return d_chain(v, 0.5 / v if v > 0.0 else 0.0, a)


cdef inline Dual d_pow(Dual a, double p) noexcept nogil:
    """max(a, 0)^p."""
    if a.v <= 0.0:
        return dual(0.0)
    return d_chain(pow(a.v, p), p * pow(a.v, p - 1.0), a)


cdef Dual d_stiffness(const Speed *sp, const double *nodes, Dual c) noexcept nogil:
    """K(cos alpha) from its values at the Chebyshev nodes (barycentric interpolation in x = 2c -
    1); below c = 0.05 (a loose ball pointing across the groove: no load) the value at 0.05 and
    no slope. [N/mm^1.5]"""
    cdef double x = 2.0 * max(c.v, 0.05) - 1.0, t, num = 0.0, den = 0.0, d_num = 0.0, d_den = 0.0
    cdef double k
    cdef int i
    for i in range(NODES):
        t = sp.node_w[i] / (x - sp.node_x[i])
        num += t * nodes[i]
        den += t
        d_num += t * t / sp.node_w[i] * nodes[i]
        d_den += t * t / sp.node_w[i]
    k = num / den
    return d_chain(k, 2.0 * (k * d_den - d_num) / den if c.v >= 0.05 else 0.0, c)


cdef void inner_contact(const Speed *sp, Dual rho, Dual u, Dual lo, Dual so, Dual co,
                        Dual *si, Dual *ci, Dual *di) noexcept nogil:
    """The inner contact of a ball whose centre is lo (sin, cos) alpha_o from the outer groove
    centre: its angle (sin, cos) and approach. The inner raceway is the half of the groove
    facing the ball (cos a_i >= 0: the radial offset taken at least 0)."""
    cdef Dual e1 = d_sub(u, d_mul(lo, so)), e2 = d_sub(rho, d_mul(lo, co)), li
    if not e2.v > 0.0:
        e2 = dual(0.0)
    li = d_sqrt(d_add(d_mul(e1, e1), d_mul(e2, e2)))
    di[0] = d_sub(li, dual(sp.ri))
    if li.v > 0.0:
        si[0] = d_div(e1, li)
        ci[0] = d_div(e2, li)
    else:
        si[0] = e1
        ci[0] = e2


cdef void ball_speeds(const Speed *sp, Dual so, Dual co, Dual si, Dual ci, Dual *wc, Dual *wr,
                      Dual *beta) noexcept nogil:
    """Outer-raceway control: the orbit speed omega_c, the ball's spin omega_R and its attitude
    angle beta from the two contact angles. [rad/s, rad]"""
    cdef double gamma = sp.dw / sp.dm
    cdef Dual tb = d_div(so, d_add(co, dual(gamma))), c_o, c_i, total
    beta[0] = d_chain(atan(tb.v), 1.0 / (1.0 + tb.v * tb.v), tb)
    c_o = d_div(d_add(co, d_mul(tb, so)), d_add(dual(1.0), d_scale(co, gamma)))
    c_i = d_div(d_add(ci, d_mul(tb, si)), d_sub(dual(1.0), d_scale(ci, gamma)))
    total = d_add(c_o, c_i)
    wc[0] = d_div(d_scale(c_o, sp.omega), total)
    wr[0] = d_div(dual(sp.omega), d_mul(d_scale(d_chain(cos(beta.v), -sin(beta.v), beta[0]),
                                                gamma), total))


cdef void ball_eval(const Speed *sp, double rho_, double u_, double do_, double ao_, double *t,
                    double *jac) noexcept nogil:
    """One ball at the groove-centre offsets (rho, u') with its unknowns (delta_o, alpha_o):
    the BALL_TERMS values ``t`` and, if ``jac`` is not NULL, the BALL_PARTIALS derivatives of
    (g1, g2, F_a, F_r) by (delta_o, alpha_o, rho, u') (row-major)."""
    cdef Dual do = variable(do_, 0), ao = variable(ao_, 1)
    cdef Dual rho = variable(rho_, 2), u = variable(u_, 3)
    cdef Dual lo = d_add(dual(sp.ro), do), so, co, si, ci, di, qi, qo, wc, wr, beta, sb
    cdef Dual fc, mg, fr
    cdef Dual g[4]
    cdef int r, k
    so = d_chain(sin(ao.v), cos(ao.v), ao)
    co = d_chain(cos(ao.v), -sin(ao.v), ao)
    inner_contact(sp, rho, u, lo, so, co, &si, &ci, &di)
    qi = d_mul(d_stiffness(sp, sp.ki, ci), d_pow(di, 1.5))
    qo = d_mul(d_stiffness(sp, sp.ko, co), d_pow(do, 1.5))
    ball_speeds(sp, so, co, si, ci, &wc, &wr, &beta)
    fc = d_scale(d_mul(d_scale(wc, 0.5 * sp.mass * sp.dm), wc), KG_MM)
    sb = d_chain(sin(beta.v), cos(beta.v), beta)
    mg = d_scale(d_mul(d_mul(d_scale(wr, 0.1 * sp.mass * sp.dw * sp.dw), wc), sb), KG_MM)
    fr = d_scale(mg, 2.0 / sp.dw)
    g[0] = d_add(d_sub(d_mul(qi, si), d_mul(qo, so)), d_mul(fr, co))
    g[1] = d_add(d_sub(d_sub(d_mul(qi, ci), d_mul(qo, co)), d_mul(fr, so)), fc)
    g[2] = d_mul(qi, si)
    g[3] = d_mul(qi, ci)
    t[0] = g[0].v
    t[1] = g[1].v
    t[2] = qi.v
    t[3] = qo.v
    t[4] = si.v
    t[5] = ci.v
    t[6] = fc.v
    t[7] = mg.v
    t[8] = wc.v
    t[9] = wr.v
    t[10] = beta.v
    t[11] = di.v
    t[12] = g[2].v
    t[13] = g[3].v
    if jac != NULL:
        for r in range(4):
            for k in range(4):
                jac[4 * r + k] = g[r].d[k]


cdef void static_eval(const Speed *sp, double rho_, double u_, double *f, double *jac) noexcept nogil:
    """A ball at speed 0, on the line of its groove centres, K_i and K_o in series: its forces
    on the ring (F_a, F_r) and their derivatives by (rho, u') (row-major 2 x 2)."""
    cdef Dual rho = variable(rho_, 2), u = variable(u_, 3), rp, d, ca, k, q, fa, fr
    cdef int r
    rp = rho if rho.v > 0.0 else dual(0.0)
    d = d_sqrt(d_add(d_mul(rp, rp), d_mul(u, u)))
    ca = d_div(rp, d) if d.v > 0.0 else rp
    k = d_pow(d_add(d_pow(d_stiffness(sp, sp.ki, ca), -2.0 / 3.0),
                    d_pow(d_stiffness(sp, sp.ko, ca), -2.0 / 3.0)), -1.5)
    q = d_mul(k, d_pow(d_sub(d, dual(sp.ri + sp.ro)), 1.5))
    fa = d_div(d_mul(q, u), d)
    fr = d_div(d_mul(q, rp), d)
    f[0] = fa.v
    f[1] = fr.v
    for r in range(2):
        jac[r] = fa.d[2 + r] if isfinite(fa.d[2 + r]) else 0.0
        jac[2 + r] = fr.d[2 + r] if isfinite(fr.d[2 + r]) else 0.0


cdef inline void speed_on(Speed *sp, const double *consts, const double *ki, const double *ko,
                          const double *node_x, const double *node_w) noexcept nogil:
    sp.ri = consts[0]
    sp.ro = consts[1]
    sp.dw = consts[2]
    sp.dm = consts[3]
    sp.omega = consts[4]
    sp.mass = consts[5]
    sp.ki = ki
    sp.ko = ko
    sp.node_x = node_x
    sp.node_w = node_w


def speed_balls(const double[::1] rho, const double[::1] u, const double[::1] do,
                const double[::1] ao, const int64_t[::1] row, const double[:, ::1] consts,
                const double[:, ::1] ki, const double[:, ::1] ko, const double[::1] node_x,
                const double[::1] node_w, double[:, ::1] terms, double[:, ::1] partials):
    """m balls at speed (``ball_eval``): ball i at (rho[i], u[i]) with (do[i], ao[i]), its case
    ``row[i]`` (consts (cases, 6): r'_i, r'_o, D_w, d_m, omega, mass; ki, ko (cases, NODES)).
    Writes terms (BALL_TERMS, m) and, if partials has BALL_PARTIALS rows, the derivatives."""
    cdef Py_ssize_t m = rho.shape[0], i
    cdef int k
    cdef bint want = partials.shape[0] == BALL_PARTIALS
    cdef double t[BALL_TERMS]
    cdef double jac[BALL_PARTIALS]
    cdef Speed sp
    with nogil:
        for i in range(m):
            speed_on(&sp, &consts[row[i], 0], &ki[row[i], 0], &ko[row[i], 0], &node_x[0],
                     &node_w[0])
            ball_eval(&sp, rho[i], u[i], do[i], ao[i], t, jac if want else NULL)
            for k in range(BALL_TERMS):
                terms[k, i] = t[k]
            if want:
                for k in range(BALL_PARTIALS):
                    partials[k, i] = jac[k]


# --------------------------------------------------------------------- one ball's equilibrium
#
# Each ball's two equations at a given ring position (bearingload.models.high_speed): Newton on
# its centre (X_1, X_2) = (r'_o + delta_o)(sin, cos) alpha_o from the outer groove centre, the
# step halved until the residual falls; a ball left unbalanced is solved from its loose state.

cdef double ZERO_NODES[NODES]  # K_i of a ball without inner contact


cdef double stiffness_at(const Speed *sp, const double *nodes, double c) noexcept nogil:
    """K(cos alpha), the value of ``d_stiffness``. [N/mm^1.5]"""
    cdef double x = 2.0 * max(c, 0.05) - 1.0, t, num = 0.0, den = 0.0
    cdef int i
    for i in range(NODES):
        t = sp.node_w[i] / (x - sp.node_x[i])
        num += t * nodes[i]
        den += t
    return num / den


cdef double ball_norm(const Speed *sp, const double *t, double do, double round_) noexcept nogil:
    """The ball's residual over the sum of its force magnitudes plus the rounding of its
    approaches (differences of lengths up to r' + delta; ``round_`` times each contact's load
    times its length over its approach); inf where not finite."""
    cdef double di = fabs(t[11]), size, extra, out
    size = fabs(t[2]) + fabs(t[3]) + fabs(t[6]) + 2.0 * fabs(t[7]) / sp.dw
    extra = t[2] * (di + sp.ri) / di + t[3] * (do + sp.ro) / do
    if isnan(extra):
        extra = 0.0  # no contact: 0/0
    out = hypot(t[0], t[1]) / (size + round_ * extra)
    return out if isfinite(out) else INFINITY


cdef void line_start(const Speed *sp, double rho, double u, double *do, double *ao) noexcept nogil:
    """The static position: the ball on the line of its groove centres, the approach shared by
    the contacts as their compliances."""
    cdef double r = max(rho, 0.0), d, ca, ci, co
    d = hypot(r, u)
    ca = r / (d if d > 0.0 else 1.0)
    ci = pow(stiffness_at(sp, sp.ki, ca), -2.0 / 3.0)
    co = pow(stiffness_at(sp, sp.ko, ca), -2.0 / 3.0)
    do[0] = co / (ci + co) * (d - sp.ri - sp.ro)
    ao[0] = atan2(u, r)


cdef bint ball_step(const Speed *sp, double rho, double u, double *x, double *t, bint touching,
                    const SpeedLimits *lim) noexcept nogil:
    """One Newton step of an unbalanced ball at x = (delta_o, alpha_o) whose terms are t (the
    Jacobian in its centre's Cartesian coordinates), no longer than r'_o/4, halved until the
    residual falls (a touching ball kept in inner contact). Updates x and t; whether it
    moved. Sets t's balance in x[2] (1: balanced)."""
    cdef double jac[BALL_PARTIALS]
    cdef double t2[BALL_TERMS]
    cdef double a11, a12, a21, a22, det, s1, s2, lo, so, co, cut, y1, y2, d2, a2, size
    cdef double lam = 1.0
    cdef bint ok2
    cdef int h, k
    ball_eval(sp, rho, u, x[0], x[1], t2, jac)
    lo = sp.ro + x[0]
    so = sin(x[1])
    co = cos(x[1])
    a11 = jac[0] * so + jac[1] * co / lo
    a12 = jac[0] * co - jac[1] * so / lo
    a21 = jac[4] * so + jac[5] * co / lo
    a22 = jac[4] * co - jac[5] * so / lo
    det = a11 * a22 - a12 * a21
    s1 = -(a22 * t[0] - a12 * t[1]) / det
    s2 = -(-a21 * t[0] + a11 * t[1]) / det
    if not (isfinite(s1) and isfinite(s2)):
        return False
    cut = min(1.0, 0.25 * sp.ro / max(hypot(s1, s2), 1e-300))
    size = hypot(t[0], t[1])
    for h in range(lim.ball_halvings):
        y1 = lo * so + lam * (s1 * cut)
        y2 = lo * co + lam * (s2 * cut)
        d2 = hypot(y1, y2) - sp.ro
        a2 = atan2(y1, y2)
        ball_eval(sp, rho, u, d2, a2, t2, NULL)
        ok2 = ball_norm(sp, t2, d2, lim.ball_round) <= lim.ball_tolerance
        if (hypot(t2[0], t2[1]) < (1.0 - 1e-4 * lam) * size or ok2) and (
                not touching or t2[11] > 0.0):
            x[0] = d2
            x[1] = a2
            x[2] = 1.0 if ok2 else 0.0
            for k in range(BALL_TERMS):
                t[k] = t2[k]
            return True
        lam *= 0.5
    return False


cdef bint ball_newton(const Speed *sp, double rho, double u, double *x, bint moving,
                      int iterations, bint keep_contact, const SpeedLimits *lim) noexcept nogil:
    """Newton on one ball from x = (delta_o, alpha_o) (``ball_step``); whether it is balanced
    (a ball not moving is)."""
    cdef double t[BALL_TERMS]
    cdef bint touching
    cdef int it
    ball_eval(sp, rho, u, x[0], x[1], t, NULL)
    x[2] = 1.0 if (not moving or ball_norm(sp, t, x[0], lim.ball_round) <= lim.ball_tolerance) else 0.0
    touching = keep_contact and t[11] > 0.0
    for it in range(iterations):
        if x[2] != 0.0 or not ball_step(sp, rho, u, x, t, touching, lim):
            break
    return x[2] != 0.0


cdef bint loose(const Speed *sp, double rho, double u, double *do, const SpeedLimits *lim) noexcept nogil:
    """The ball without inner contact: alpha_o = 0 (no friction: beta = 0) and K_o
    delta_o^1.5 = F_c, by Newton in delta_o from the rigid-rolling F_c; whether solved."""
    cdef Speed bare = sp[0]
    cdef double t[BALL_TERMS]
    cdef double jac[BALL_PARTIALS]
    cdef double fc = 0.125 * sp.mass * sp.dm * sp.omega * sp.omega * KG_MM, step
    cdef bint ok = False
    cdef int it
    bare.ki = ZERO_NODES
    do[0] = pow(fc / stiffness_at(sp, sp.ko, 1.0), 2.0 / 3.0)
    for it in range(lim.fallback_iterations):
        ball_eval(&bare, rho, u, do[0], 0.0, t, jac)
        ok = ball_norm(&bare, t, do[0], lim.ball_round) <= lim.ball_tolerance
        if ok:
            break
        step = -t[1] / jac[4]
        if not isfinite(step):
            step = 0.0
        do[0] = do[0] + step if do[0] + step > 0.0 else 0.5 * do[0]
    return ok and isfinite(do[0])


cdef bint solve_ball(const Speed *sp, double rho, double u, double *x,
                     const SpeedLimits *lim) noexcept nogil:
    """One ball's equations at (rho, u') from x = (delta_o, alpha_o): Newton from x; if left
    unbalanced, its loose state where its inner approach is a gap there, else Newton from that
    state (or its line) kept in inner contact. Whether it is balanced."""
    cdef double t[BALL_TERMS]
    cdef double ld, line_d, line_a
    cdef bint moving = sp.omega > 0.0, loose_ok
    if ball_newton(sp, rho, u, x, moving, lim.ball_iterations, False, lim):
        return True
    loose_ok = loose(sp, rho, u, &ld, lim)
    line_start(sp, rho, u, &line_d, &line_a)
    ball_eval(sp, rho, u, ld, 0.0, t, NULL)
    if loose_ok and t[11] <= 0.0:
        x[0] = ld
        x[1] = 0.0
        x[2] = 1.0
        return True
    x[0] = ld if loose_ok else max(line_d, 1e-6 * sp.ro)
    x[1] = 0.0 if loose_ok else line_a
    return ball_newton(sp, rho, u, x, True, lim.fallback_iterations, True, lim)


# ------------------------------------------------------------ the ring of one bearing at speed
#
# The inner ring's forces and tangent at a ring position v = (x, y, a, R_i theta, R_i theta_c)
# with every ball solved (``speed_state``), each ball's equations eliminated from the tangent by
# the implicit function theorem; the rounding level of each force and its change over the
# balls' own residuals (bearingload.models.high_speed: the acceptance rules).

cdef enum:
    DYN_PER_BALL = 29  # doubles a ball in a Dyn


cdef void dyn_on(double *block, int z, Dyn *st) noexcept nogil:
    st.do = block
    st.ao = block + z
    st.ok = block + 2 * z
    st.terms = block + 3 * z
    st.sens = block + (3 + BALL_TERMS) * z
    st.tot = block + (9 + BALL_TERMS) * z
    st.gain = block + (13 + BALL_TERMS) * z


cdef void copy_dyn(int z, const Dyn *src, Dyn *dst) noexcept nogil:
    """dst = src, each on its own block (``dyn_on``): the block's balls copied whole, the struct
    assigned, and dst's pointers put back on its block."""
    cdef double *block = dst.do
    memcpy(block, src.do, DYN_PER_BALL * z * sizeof(double))
    dst[0] = src[0]
    dyn_on(block, z, dst)


cdef inline void centre(const Ring *rg, const double *v, int j, double *rho, double *u) noexcept nogil:
    """Ball j's inner groove centre from its outer one: radial rho and axial u. [mm]"""
    rho[0] = rg.base + v[0] * rg.c[j] + v[1] * rg.s[j]
    u[0] = v[2] + v[3] * rg.c[j] + v[4] * rg.s[j]


cdef void eliminate(const Ring *rg, double rho, double up, double dup, const double *d,
                    double *sens, double *tot, double *gain) noexcept nogil:
    """A ball's sensitivity dX/d(rho, u') = -(dg/dX)^-1 dg/dp, the total derivatives of its
    ring forces (F_a, F_r) by (rho, u) with its equations eliminated (at speed 0 those of the
    ball on its line, ``static_eval``), and the gain |dF/dX (dg/dX)^-1| of each."""
    cdef double det = d[0] * d[5] - d[1] * d[4], inv[4]
    cdef double f[2]
    cdef double stat[4]
    cdef double dx0, dx1, total
    cdef bint moving = rg.sp.omega > 0.0
    cdef int r, c, k
    inv[0] = d[5] / det
    inv[1] = -d[1] / det
    inv[2] = -d[4] / det
    inv[3] = d[0] / det
    sens[0] = rho
    sens[1] = up
    for c in range(2):
        for k in range(2):
            total = -(inv[2 * k] * d[2 + c] + inv[2 * k + 1] * d[6 + c])
            sens[2 + 2 * c + k] = total if isfinite(total) else 0.0
    if not moving:
        static_eval(&rg.sp, rho, up, f, stat)
    for r in range(2):
        for c in range(2):
            dx0 = inv[0] * d[2 + c] + inv[1] * d[6 + c]
            dx1 = inv[2] * d[2 + c] + inv[3] * d[6 + c]
            total = d[4 * (2 + r) + 2 + c] - (d[4 * (2 + r)] * dx0 + d[4 * (2 + r) + 1] * dx1)
            tot[2 * r + c] = (total if moving else stat[2 * r + c]) * (dup if c == 1 else 1.0)
        total = (fabs(d[4 * (2 + r)] * inv[0] + d[4 * (2 + r) + 1] * inv[2])
                 + fabs(d[4 * (2 + r)] * inv[1] + d[4 * (2 + r) + 1] * inv[3]))
        gain[r] = total if moving and isfinite(total) else 0.0


cdef void start_ball(const Ring *rg, double rho, double up, const double *prev,
                     const double *sens, double *x) noexcept nogil:
    """A ball's start at (rho, u'): its previous (delta_o, alpha_o) moved to first order by its
    sensitivity (if any), else (or at speed 0) its line; at speed pressed by about F_c."""
    cdef const Speed *sp = &rg.sp
    cdef bint moving = sp.omega > 0.0, fresh
    cdef double fc = 0.125 * sp.mass * sp.dm * sp.omega * sp.omega * KG_MM, dr, du
    x[0] = prev[0]
    x[1] = prev[1]
    if sens != NULL:
        dr = rho - sens[0]
        du = up - sens[1]
        x[0] = x[0] + sens[2] * dr + sens[4] * du
        x[1] = x[1] + sens[3] * dr + sens[5] * du
    fresh = not moving or not isfinite(x[0])
    if fresh:
        line_start(sp, rho, up, &x[0], &x[1])
    if moving and fresh and x[0] <= 0.0:
        x[1] = 0.0
    if moving:
        x[0] = max(x[0], pow(fc / sp.ko[NODES - 1], 2.0 / 3.0))


cdef inline void ball_arms(const Ring *rg, int j, double *arm_r, double *arm_a) noexcept nogil:
    """How ball j's radial and axial ring forces (F_r, F_a) enter the generalised forces (x, y,
    a, R_i theta, R_i theta_c)."""
    arm_r[0] = rg.c[j]
    arm_r[1] = rg.s[j]
    arm_a[3] = rg.c[j]
    arm_a[4] = rg.s[j]
    arm_r[2] = arm_r[3] = arm_r[4] = arm_a[0] = arm_a[1] = 0.0
    arm_a[2] = 1.0


cdef void add_ball_tangent(const Ring *rg, int j, const double *tot, double *jac) noexcept nogil:
    """Ball j's part of the ring tangent from the total derivatives ``tot`` of its ring forces
    (``eliminate``) into jac (25)."""
    cdef double arm_r[5]
    cdef double arm_a[5]
    cdef int k, l
    ball_arms(rg, j, arm_r, arm_a)
    for k in range(5):
        for l in range(5):
            jac[5 * k + l] += (arm_r[k] * (tot[2] * arm_r[l] + tot[3] * arm_a[l])
                               + arm_a[k] * (tot[0] * arm_r[l] + tot[1] * arm_a[l]))


cdef void add_ball_forces(const Ring *rg, int j, const double *t, const double *tot,
                          Dyn *st) noexcept nogil:
    """Ball j's ring forces (F_a, F_r) = (t[12], t[13]) into the generalised forces and their
    tangent."""
    cdef double arm_r[5]
    cdef double arm_a[5]
    cdef int k
    ball_arms(rg, j, arm_r, arm_a)
    for k in range(5):
        st.gen[k] += arm_r[k] * t[13] + arm_a[k] * t[12]
    add_ball_tangent(rg, j, tot, st.jac)


cdef void add_levels(const Ring *rg, int j, const double *t, const double *tot,
                     const double *gain, double length, double *moved, Dyn *st) noexcept nogil:
    """Ball j's part of each component's rounding level: its terms' magnitudes (``floor``, the
    ROUNDING factor applied in ``score``) and the force change over one rounding eps (|rho| +
    |u'|) of its groove-centre position (``moved``); and of the change of the forces over the
    ball's own residual (``noise``)."""
    cdef double arm_r[5]
    cdef double arm_a[5]
    cdef double g = hypot(t[0], t[1]), own
    cdef int k
    ball_arms(rg, j, arm_r, arm_a)
    for k in range(5):
        arm_r[k] = fabs(arm_r[k])
        arm_a[k] = fabs(arm_a[k])
        st.floor[k] += arm_r[k] * fabs(t[13]) + arm_a[k] * fabs(t[12])
        moved[k] += ((fabs(tot[2]) + fabs(tot[3])) * arm_r[k]
                     + (fabs(tot[0]) + fabs(tot[1])) * arm_a[k]) * (EPS * length)
        own = arm_a[k] * (gain[0] * g) + arm_r[k] * (gain[1] * g)
        if isfinite(own):
            st.noise[k] += own


cdef void speed_state(const Ring *rg, const double *v, const Dyn *prev, bint warm,
                      Dyn *st) noexcept nogil:
    """Every ball solved at the ring position v (from ``prev``'s balls, moved by their
    sensitivities where ``warm``; NaN balls start on their lines), the ring's forces, tangent,
    rounding level (ROUNDING times the terms' magnitudes plus ``moved``) and noise into ``st``
    (which may be ``prev``)."""
    cdef double t[BALL_TERMS]
    cdef double d[BALL_PARTIALS]
    cdef double moved[5]
    cdef double x[3]
    cdef double rho, u, up, dup
    cdef int j, k
    for k in range(5):
        st.gen[k] = st.floor[k] = st.noise[k] = moved[k] = 0.0
    for k in range(25):
        st.jac[k] = 0.0
    st.balls_ok = True
    st.touching = False
    for j in range(rg.z):
        centre(rg, v, j, &rho, &u)
        up = max(u, 0.0) if rg.one_sided else u
        dup = (1.0 if u > 0.0 else 0.0) if rg.one_sided else 1.0
        x[0] = prev.do[j]
        x[1] = prev.ao[j]
        start_ball(rg, rho, up, x, &prev.sens[6 * j] if warm else NULL, x)
        st.ok[j] = 1.0 if solve_ball(&rg.sp, rho, up, x, &rg.lim) else 0.0
        st.balls_ok = st.balls_ok and st.ok[j] != 0.0
        st.do[j] = x[0]
        st.ao[j] = x[1]
        ball_eval(&rg.sp, rho, up, x[0], x[1], t, d)
        for k in range(BALL_TERMS):
            st.terms[BALL_TERMS * j + k] = t[k]
        st.touching = st.touching or t[2] > 0.0
        eliminate(rg, rho, up, dup, d, &st.sens[6 * j], &st.tot[4 * j], &st.gain[2 * j])
        add_ball_forces(rg, j, t, &st.tot[4 * j], st)
        add_levels(rg, j, t, &st.tot[4 * j], &st.gain[2 * j], fabs(rho) + fabs(up), moved, st)
    for k in range(5):
        st.floor[k] = rg.lim.rounding * st.floor[k] + moved[k]
        if not isfinite(st.floor[k]):
            st.floor[k] = 0.0


# A touching ball of a one-sided (angular-contact) bearing at u <= 0 is held at u' = max(u, 0) =
# 0 (clipped): its ring forces do not move with u and the plain tangent has no u' column for it.
# Where a thrust needs such a ball past u = 0 (a radial load with a thrust of 1e-8 of it: the
# loaded balls at about 0° stopped at u < 0, the ring tilted to bring a ball across the ring in),
# no step along the plain tangent lowers the residual; the shaft's Newton takes the tangent of
# their side u > 0 there (``lifted_system``, ``shaft_newton``).

cdef bint clipped(const Ring *rg, const Dyn *st, const double *v, int j, double *rho,
                  double *u) noexcept nogil:
    """Whether ball j, at the ring position v, touches the inner ring of a one-sided bearing at
    u <= 0 (its rho and u into rho, u). [mm]"""
    centre(rg, v, j, rho, u)
    return rg.one_sided and u[0] <= 0.0 and st.terms[BALL_TERMS * j + 11] > 0.0


cdef double lifted_ball(const Ring *rg, const Dyn *st, int j, double rho,
                        double *tot) noexcept nogil:
    """The total derivatives (``eliminate``) of a clipped ball j's ring forces at u' = 0 taken on
    its side u > 0, into tot (4); returns dF_a/du' there. [N/mm]"""
    cdef double t[BALL_TERMS]
    cdef double d[BALL_PARTIALS]
    cdef double sens[6]
    cdef double gain[2]
    ball_eval(&rg.sp, rho, 0.0, st.do[j], st.ao[j], t, d)
    eliminate(rg, rho, 0.0, 1.0, d, sens, tot, gain)
    return tot[1]


cdef int lift_tangent(const Ring *rg, const Dyn *st, const double *v, int which, int *counter,
                      double *jac, double *virt) noexcept nogil:
    """jac (25) += the u' columns of the clipped balls (``clipped``) on their side u > 0, and
    virt (5) += the ring forces they would have there at their u (< 0) to first order: all of
    them where ``which`` < 0, else the one numbered ``which`` (counted on from ``counter``
    over the bearings). How many there are."""
    cdef double tot[4]
    cdef double arm_r[5]
    cdef double arm_a[5]
    cdef double rho, u
    cdef int j, k, n = 0
    for j in range(rg.z):
        if not clipped(rg, st, v, j, &rho, &u):
            continue
        n += 1
        counter[0] += 1
        if which >= 0 and counter[0] - 1 != which:
            continue
        lifted_ball(rg, st, j, rho, tot)
        tot[0] = 0.0
        tot[2] = 0.0
        add_ball_tangent(rg, j, tot, jac)
        ball_arms(rg, j, arm_r, arm_a)
        for k in range(5):
            virt[k] += (arm_r[k] * tot[3] + arm_a[k] * tot[1]) * u
    return n


cdef double kink_reach(const Ring *rg, const Dyn *st, const double *v, const double *d,
                       double load) noexcept nogil:
    """How far along the direction d (a bearing's own frame) the nearest clipped ball passes u =
    0, pressed to carry about ``load`` axially (u = load over dF_a/du' on that side); inf where
    none does. [-]"""
    cdef double tot[4]
    cdef double reach = INFINITY, rho, u, du, move
    cdef int j
    for j in range(rg.z):
        if not clipped(rg, st, v, j, &rho, &u):
            continue
        du = d[2] + d[3] * rg.c[j] + d[4] * rg.s[j]
        move = (load / lifted_ball(rg, st, j, rho, tot) - u) / du
        if du > 0.0 and move > 0.0 and isfinite(move):
            reach = min(reach, move)
    return reach


# ------------------------------------------------------------------- the shaft's damped Newton
#
# One bearing, or the rigid shaft of a pair (bearingload.models.pair_speed): the position v
# (x, y, a, R_i theta, R_i theta_c) gives bearing k the local position L_k v + offset_k (one
# bearing: L = I, offset 0), where ``speed_state`` solves its balls; the forces sum_k L_k^T f_k,
# the tangent sum_k L_k^T J_k L_k, each bearing's rounding level and noise carried through
# |L_k^T|. One damped Newton (``shaft_newton``) and one continuation in speed for both.

#: Steps to a first contact (``contact_step``) in a row, without a Newton step between; the
#: most the residual's 2-norm may grow over one (the ball brought in is pressed to carry about
#: the residual, an estimate from its stiffness at its present angle). Of the 1000 light
#: cases of tests/scan_speed_light.py wide, 4 left 23 unbalanced, 30 left 15, 1e3 left 13 but
#: one of them F_r = 15.5 N (F_a/F_r 3e-5), which 4 and 30 balance. [-]
cdef int CONTACT_STEPS = 8
cdef double CONTACT_GROWTH = 30.0
#: Where the Newton goes on past its end (``shaft_newton``, its answer kept only where better),
#: a step to a first contact is taken where the residual (over the largest applied load) grows
#: to at most CONTACT_GROWTH times the larger of its size and this: a ball brought in across a
#: nearly free direction, its reach a difference of lengths (47 µm across, the cage 1e-6° off
#: the load line of a 7205B at F_r 41 N, 20 000 rpm), carries many times the residual it was
#: pressed for (1.6e-3 N for 7e-7 N). [-]
cdef double LIFTED_GROWTH = 1e-3


cdef void lm_step(const double *jac, const double *res, double mu, double *step) noexcept nogil:
    """The Newton step (mu = 0) or the Levenberg-Marquardt step (J^T J + mu diag) s = J^T r; a
    singular tangent (no ball touching along a direction) gives the damped least-squares step;
    non-finite parts 0. [mm]"""
    cdef double a[25]
    cdef double b[5]
    cdef double top = 0.0
    cdef int i, k, l
    if mu == 0.0:
        solve5(jac, res, step)
        for i in range(5):
            if not isfinite(step[i]):
                lm_step(jac, res, 1e-14, step)
                return
        return
    for k in range(5):
        b[k] = 0.0
        for i in range(5):
            b[k] += jac[5 * i + k] * res[i]
        for l in range(5):
            a[5 * k + l] = 0.0
            for i in range(5):
                a[5 * k + l] += jac[5 * i + k] * jac[5 * i + l]
        top = max(top, a[6 * k])
    for k in range(5):
        a[6 * k] += mu * max(a[6 * k], 1e-12 * top)
    solve5(a, b, step)
    for i in range(5):
        if not isfinite(step[i]):
            step[i] = 0.0


cdef void trial_step(const double *jac, const double *res, const int *held, double length,
                     int k, int halvings, double *step) noexcept nogil:
    """Trial k of the safeguarded Newton (of the ring, or of a pair's shaft): the Newton step
    halved k times up to ``halvings``, then Levenberg-Marquardt steps with mu growing 100-fold
    from 1e-6; held components not moved; no longer than a tenth of ``length`` (A). [mm]"""
    cdef double lam = 1.0, mu = 0.0, longest = 0.0, shrink
    cdef int i
    if k < halvings:
        lam = pow(0.5, k)
    else:
        mu = 1e-6 * pow(100.0, k - halvings)
    lm_step(jac, res, mu, step)
    for i in range(5):
        step[i] = 0.0 if held[i] else lam * step[i]
        longest = max(longest, fabs(step[i]))
    shrink = min(1.0, 0.1 * length / max(longest, 1e-300))
    for i in range(5):
        step[i] = step[i] * shrink


cdef double contact_reach(const Ring *rg, const Dyn *st, const double *d,
                          double load) noexcept nogil:
    """How far along the direction d (a bearing's own frame) its nearest ball without inner
    contact comes into it, pressed to carry about ``load``: the ring's move t where the inner
    groove centre, moved by t (d_rho, d_u') from the ball's centre (held), lies r'_i + the
    pressed approach from it (a quadratic in t: a loose ball's approach grows with the square
    of a move across its contact line, as a thrust on a ball loose at 0°); inf where none comes
    nearer. [-]"""
    cdef const double *t
    cdef double reach = INFINITY, dr, du, press, li, e1, e2, a, b, gap, q, move
    cdef int j
    for j in range(rg.z):
        t = &st.terms[BALL_TERMS * j]
        if not t[11] < 0.0:
            continue
        dr = d[0] * rg.c[j] + d[1] * rg.s[j]
        du = d[2] + d[3] * rg.c[j] + d[4] * rg.s[j]
        if rg.one_sided and st.sens[6 * j + 1] <= 0.0:
            du = max(du, 0.0)  # u' = max(u, 0): the ball at u <= 0 moves once u turns positive
        li = t[11] + rg.sp.ri
        e1 = li * t[4]
        e2 = li * t[5]
        press = pow(load / stiffness_at(&rg.sp, rg.sp.ki, t[5]), 2.0 / 3.0)
        a = du * du + dr * dr
        b = e1 * du + e2 * dr
        gap = (rg.sp.ri + press) * (rg.sp.ri + press) - li * li
        q = sqrt(b * b + a * gap)
        move = gap / (b + q) if b >= 0.0 else (q - b) / a
        if move > 0.0 and isfinite(move):
            reach = min(reach, move)
    return reach


cdef bint contact_step(const Shaft *sh, const ShaftState *cur, const double *jac,
                       const double *res, const double *v, double *step) noexcept nogil:
    """The step that brings the nearest ball without inner contact into it (to first order,
    pressed to carry about the residual): along the regularised Newton step (J + 1e-13 tr|J|)
    s = r of the held system. Where the tangent is singular along the residual (no ball
    touching the inner ring; or the balls touching cannot balance it, as one ball under a light
    thrust, whose F_a and M/R_i are equal, the others held off by their centrifugal forces) the
    plain Newton and Levenberg-Marquardt steps have no part along it, and this one mostly that
    part. No longer than A. Where v (the position) is given, a clipped ball passing u = 0
    (``kink_reach``) counts as a contact too. Whether there is such a step. [mm]"""
    cdef double a[25]
    cdef double d[5]
    cdef double local[5]
    cdef double here[5]
    cdef double trace = 0.0, size = 0.0, load = 0.0, reach = INFINITY
    cdef const double *m
    cdef int i, k, l
    for i in range(25):
        a[i] = jac[i]
    for i in range(5):
        if not sh.held[i]:
            trace += fabs(jac[6 * i])
        load += res[i] * res[i]
    for i in range(5):
        if not sh.held[i]:
            a[6 * i] += 1e-13 * trace + 1e-300
    solve5(a, res, d)
    for i in range(5):
        if sh.held[i] or not isfinite(d[i]):
            d[i] = 0.0
        size = max(size, fabs(d[i]))
    if not size > 0.0:
        return False
    for i in range(5):
        d[i] /= size  # (the largest part 1, against overflow)
    size = 0.0
    for i in range(5):
        size += d[i] * d[i]
    size = sqrt(size)
    for i in range(5):
        d[i] /= size
    for k in range(sh.parts):
        m = &sh.maps[25 * k]
        for i in range(5):
            local[i] = 0.0
            for l in range(5):
                local[i] += m[5 * i + l] * d[l]
        reach = min(reach, contact_reach(&sh.ring, &cur.part[k], local, sqrt(load)))
        if v != NULL:
            local_position(sh, k, v, here)
            reach = min(reach, kink_reach(&sh.ring, &cur.part[k], here, local, sqrt(load)))
    if not isfinite(reach):
        return False
    reach = min(reach, sh.ring.length)
    for i in range(5):
        step[i] = reach * d[i]
    return True


cdef void shaft_measures(const Shaft *sh, ShaftState *st) noexcept nogil:
    """``merit`` (the largest free residual over f_ref), ``score`` (each free residual against
    the largest of ACCEPT f_ref, its rounding level and, up to NOISE_MAX f_ref, its change over
    the balls' own residuals, over ACCEPT) and ``level`` (the largest rounding level over
    f_ref); inf where a ball is unsolved or a measure not finite."""
    cdef double res, worst = 0.0, merit = 0.0, level = 0.0, noise
    cdef bint ok = True
    cdef int i
    for i in range(sh.parts):
        ok = ok and st.part[i].balls_ok
    for i in range(5):
        res = 0.0 if sh.held[i] else fabs(sh.f[i] - st.gen[i])
        noise = min(st.noise[i], sh.ring.lim.noise_max * sh.f_ref)
        merit = max(merit, res)
        worst = max(worst, res / max(sh.f_ref, max(st.floor[i], noise) / sh.ring.lim.accept))
        level = max(level, st.floor[i])
    st.merit = merit / sh.f_ref
    if not (ok and isfinite(st.merit)):
        st.merit = INFINITY
    st.score = worst if isfinite(st.merit) and isfinite(worst) else INFINITY
    st.level = level / sh.f_ref


cdef inline void local_position(const Shaft *sh, int k, const double *v,
                                double *local) noexcept nogil:
    """Bearing k's own position L_k v + offset_k at the shaft's position v. [mm]"""
    cdef const double *m = &sh.maps[25 * k]
    cdef int i, l
    for i in range(5):
        local[i] = sh.offset[5 * k + i]
        for l in range(5):
            local[i] += m[5 * i + l] * v[l]


cdef void shaft_state(const Shaft *sh, const double *v, ShaftState *prev, bint warm,
                      ShaftState *st) noexcept nogil:
    """Every bearing at the position v (their balls from ``prev``'s, which may be st), the
    forces, tangent and measures into st."""
    cdef double local[5]
    cdef const double *m
    cdef Dyn *p
    cdef int k, i, j, l, q
    for i in range(5):
        st.gen[i] = st.floor[i] = st.noise[i] = 0.0
    for i in range(25):
        st.jac[i] = 0.0
    st.touching = False
    for k in range(sh.parts):
        m = &sh.maps[25 * k]
        local_position(sh, k, v, local)
        p = &st.part[k]
        speed_state(&sh.ring, local, &prev.part[k], warm, p)
        st.touching = st.touching or p.touching
        for i in range(5):
            for j in range(5):
                st.gen[i] += m[5 * j + i] * p.gen[j]
                st.floor[i] += fabs(m[5 * j + i]) * p.floor[j]
                st.noise[i] += fabs(m[5 * j + i]) * p.noise[j]
                for l in range(5):
                    for q in range(5):
                        st.jac[5 * i + l] += m[5 * j + i] * p.jac[5 * j + q] * m[5 * q + l]
    shaft_measures(sh, st)


cdef inline double shaft_norm2(const Shaft *sh, const ShaftState *st) noexcept nogil:
    """The 2-norm of the free residual over f_ref (inf: a ball unsolved)."""
    cdef double sum = 0.0, res
    cdef int k
    if not isfinite(st.merit):
        return INFINITY
    for k in range(5):
        res = 0.0 if sh.held[k] else sh.f[k] - st.gen[k]
        sum += res * res
    return sqrt(sum) / sh.f_ref


cdef void swap_shaft(ShaftState *a, ShaftState *b) noexcept nogil:
    cdef ShaftState t = a[0]
    a[0] = b[0]
    b[0] = t


cdef void copy_shaft(const Shaft *sh, const ShaftState *src, ShaftState *dst) noexcept nogil:
    """dst = src: the struct assigned with dst's own bearings kept, then each bearing of the
    shaft by ``copy_dyn``."""
    cdef Dyn part[2]
    cdef int i
    part[0], part[1] = dst.part[0], dst.part[1]
    dst[0] = src[0]
    dst.part[0], dst.part[1] = part[0], part[1]
    for i in range(sh.parts):
        copy_dyn(sh.ring.z, &src.part[i], &dst.part[i])


cdef void held_matrix(const Shaft *sh, const double *tangent, double *jac) noexcept nogil:
    """The Newton matrix of a tangent (25): held rows and columns replaced by the identity's."""
    cdef int k, l
    for k in range(5):
        for l in range(5):
            jac[5 * k + l] = 0.0 if (sh.held[k] or sh.held[l]) else tangent[5 * k + l]
        if sh.held[k]:
            jac[6 * k] = 1.0


cdef void held_system(const Shaft *sh, const ShaftState *st, double *jac,
                      double *res) noexcept nogil:
    """The Newton system at st: the tangent with held rows and columns replaced by the
    identity's, the free residual f - gen (0 where held)."""
    cdef int k
    for k in range(5):
        res[k] = 0.0 if sh.held[k] else sh.f[k] - st.gen[k]
    held_matrix(sh, st.jac, jac)


cdef int lifted_system(const Shaft *sh, const ShaftState *st, const double *v, int which,
                       double *jac, double *res) noexcept nogil:
    """The Newton system at st (position v) with the clipped balls (all where ``which`` < 0,
    else the one numbered ``which``) taken on their side u > 0 (``lift_tangent``, carried
    through L_k): the tangent with their u' columns, the residual less the forces they would
    have at their u to first order (the Newton step of the active set with them in contact).
    How many clipped balls there are."""
    cdef double tangent[25]
    cdef double part[25]
    cdef double virt[5]
    cdef double local[5]
    cdef const double *m
    cdef int k, i, j, l, q, n = 0, counter = 0
    for i in range(25):
        tangent[i] = st.jac[i]
    held_system(sh, st, jac, res)
    for k in range(sh.parts):
        m = &sh.maps[25 * k]
        local_position(sh, k, v, local)
        for i in range(25):
            part[i] = 0.0
        for i in range(5):
            virt[i] = 0.0
        n += lift_tangent(&sh.ring, &st.part[k], local, which, &counter, part, virt)
        for i in range(5):
            for j in range(5):
                if not sh.held[i]:
                    res[i] -= m[5 * j + i] * virt[j]
                for l in range(5):
                    for q in range(5):
                        tangent[5 * i + l] += m[5 * j + i] * part[5 * j + q] * m[5 * q + l]
    held_matrix(sh, tangent, jac)
    return n


cdef bint take_contact(const Shaft *sh, double *v, ShaftState *cur, ShaftState *trial,
                       const double *step, double size, bint lifted) noexcept nogil:
    """The step to a first contact taken from v where some ball touches an inner ring there and
    the residual's 2-norm (``size`` at cur) grows at most CONTACT_GROWTH-fold or, where
    ``lifted``, to that many times LIFTED_GROWTH (a residual near the tolerance, a direction
    the loads barely determine: the ball brought in to carry it, its reach a difference of
    lengths, can carry many times more); whether."""
    cdef double vt[5]
    cdef int i
    for i in range(5):
        vt[i] = v[i] + step[i]
    shaft_state(sh, vt, cur, True, trial)
    if lifted:
        size = max(size, LIFTED_GROWTH)
    if trial.touching and shaft_norm2(sh, trial) < CONTACT_GROWTH * size:
        for i in range(5):
            v[i] = vt[i]
        swap_shaft(cur, trial)
        return True
    return False


cdef bint singular(const Shaft *sh, const ShaftState *st) noexcept nogil:
    """Whether a free component's stiffness (the tangent's diagonal) is at most SINGULAR of the
    largest: a direction the loads do not determine (bearingload.models.high_speed's
    ``undetermined``)."""
    cdef double top = 0.0
    cdef int i
    for i in range(5):
        top = max(top, fabs(st.jac[6 * i]))
    for i in range(5):
        if not sh.held[i] and fabs(st.jac[6 * i]) <= sh.ring.lim.singular * top and top > 0.0:
            return True
    return False


cdef inline bint settled(const Shaft *sh, const ShaftState *st, bint lifted) noexcept nogil:
    """Balanced to the tolerance and, where ``lifted``, determined (not ``singular``)."""
    return st.merit <= sh.ring.lim.tolerance and not (lifted and singular(sh, st))


cdef bint take_step(const Shaft *sh, double *v, ShaftState *cur, ShaftState *trial,
                    const double *step, double size, bint lifted) noexcept nogil:
    """A Newton trial taken from v where it lowers the residual's 2-norm (``size`` at cur) or
    leaves it ``settled``, with some ball touching an inner ring; whether."""
    cdef double vt[5]
    cdef int i
    for i in range(5):
        vt[i] = v[i] + step[i]
    shaft_state(sh, vt, cur, True, trial)
    if ((shaft_norm2(sh, trial) < (1.0 - 1e-4) * size or settled(sh, trial, lifted))
            and trial.touching):
        for i in range(5):
            v[i] = vt[i]
        swap_shaft(cur, trial)
        return True
    return False


cdef bint lifted_trials(const Shaft *sh, double *v, ShaftState *cur, ShaftState *trial,
                        double size, int *contacts) noexcept nogil:
    """Where the plain trials take no step and balls are clipped: the Newton step of the active
    set with the clipped balls in contact (``lifted_system``), all of them, then each alone
    (the step halved as ``trial_step``); then the step to a first contact along the tangent
    with all of them on their side u > 0, a clipped ball passing u = 0 counting as a contact.
    Whether a step was taken."""
    cdef double jac[25]
    cdef double res[5]
    cdef double plain[5]
    cdef double step[5]
    cdef int n, w, k
    n = lifted_system(sh, cur, v, -1, jac, res)
    if n == 0:
        return False
    for w in range(-1, n if n > 1 else 0):
        lifted_system(sh, cur, v, w, jac, res)
        for k in range(sh.ring.lim.halvings):
            trial_step(jac, res, sh.held, sh.ring.length, k, sh.ring.lim.halvings, step)
            if take_step(sh, v, cur, trial, step, size, True):
                contacts[0] = 0
                return True
    if contacts[0] >= CONTACT_STEPS:
        return False
    held_system(sh, cur, jac, plain)
    lifted_system(sh, cur, v, -1, jac, res)
    if contact_step(sh, cur, jac, plain, v, step) and take_contact(sh, v, cur, trial, step,
                                                                   size, True):
        contacts[0] += 1
        return True
    return False


cdef bint newton_iteration(const Shaft *sh, double *v, ShaftState *cur, ShaftState *trial,
                           int *contacts, bint lifted) noexcept nogil:
    """One iteration of the damped Newton: the first of its trials (``trial_step``) that lowers
    the residual's 2-norm (or balances it) with some ball touching an inner ring; after the
    Newton steps halved, the step to a first contact (``contact_step``); where ``lifted`` and
    none is taken, the trials with the clipped balls in contact (``lifted_trials``). Whether a
    step was taken (v, cur moved)."""
    cdef double jac[25]
    cdef double res[5]
    cdef double step[5]
    cdef double size
    cdef int k
    held_system(sh, cur, jac, res)
    size = shaft_norm2(sh, cur)
    for k in range(sh.ring.lim.trials):
        trial_step(jac, res, sh.held, sh.ring.length, k, sh.ring.lim.halvings, step)
        if take_step(sh, v, cur, trial, step, size, lifted):
            contacts[0] = 0
            return True
        if k + 1 == sh.ring.lim.halvings and contacts[0] < CONTACT_STEPS and contact_step(
                sh, cur, jac, res, NULL, step):
            # the Newton step halved finds nothing: a ball to bring into contact first
            if take_contact(sh, v, cur, trial, step, size, lifted):
                contacts[0] += 1
                return True
    return lifted and lifted_trials(sh, v, cur, trial, size, contacts)


cdef int newton_run(const Shaft *sh, double *v, ShaftState *cur, ShaftState *trial,
                    bint lifted) noexcept nogil:
    """Newton iterations (``newton_iteration``) until balanced to the tolerance or no step is
    taken; how many."""
    cdef int its = 0, it, contacts = 0
    cdef bint found
    for it in range(sh.iterations):
        found = newton_iteration(sh, v, cur, trial, &contacts, lifted)
        its += 1
        if not found or settled(sh, cur, lifted):
            break
    return its


cdef int shaft_newton(const Shaft *sh, double *v, ShaftState *cur, ShaftState *trial,
                      ShaftState *spare, bint warm) noexcept nogil:
    """Damped Newton on v from the balls in ``cur`` (moved by their sensitivities where
    ``warm``; NaN balls start on their lines) (``newton_run``). Where it ends unbalanced with a
    clipped ball, or with a direction left undetermined (``singular``), it goes on,
    the steps to a first contact along the tangent of the clipped balls' side u > 0 too, until
    balanced and determined; that answer kept where it is accepted wherever the first was and
    has a lower residual or, the first balanced, is balanced and determined (``spare`` holds
    the first). The answer in cur; the iterations."""
    cdef double saved[5]
    cdef double jac[25]
    cdef double res[5]
    cdef double tol = sh.ring.lim.tolerance
    cdef int its, i
    cdef bint keep
    shaft_state(sh, v, cur, warm, cur)
    if cur.merit <= tol:
        return 0
    its = newton_run(sh, v, cur, trial, False)
    if spare == NULL:
        return its
    if not singular(sh, cur) and (cur.merit <= tol or lifted_system(sh, cur, v, -1, jac,
                                                                    res) == 0):
        return its
    copy_shaft(sh, cur, spare)
    for i in range(5):
        saved[i] = v[i]
    its += newton_run(sh, v, cur, trial, True)
    keep = cur.score <= max(spare.score, sh.ring.lim.accept)
    if spare.merit > tol:
        keep = keep and cur.merit < spare.merit
    else:
        keep = keep and cur.merit <= tol and not singular(sh, cur)
    if not keep:
        copy_shaft(sh, spare, cur)
        for i in range(5):
            v[i] = saved[i]
    return its


cdef bint shaft_continuation(const Shaft *sh, const double *v_static, double *v,
                             ShaftState *cur, ShaftState *trial, ShaftState *keep,
                             ShaftState *spare, int *its) noexcept nogil:
    """The case by continuation in omega^2 (the centrifugal and gyroscopic terms) from the
    static answer: stages of a quarter, halved on a stage not accepted (ACCEPT), doubled after
    one that is, each from the last stage's balls (warm where ``sh.warm_stages``) and its
    position extrapolated from the last two. Whether it reached the full speed (the answer in
    v, cur)."""
    cdef Shaft stage = sh[0]
    cdef double x[5]
    cdef double x1[5]
    cdef double rate[5]
    cdef double done = 0.0, step = 0.25, frac
    cdef int i, n
    for i in range(5):
        x[i] = v_static[i]
        rate[i] = 0.0
    for n in range(sh.stages):
        frac = min(1.0, done + step)
        stage.ring.sp.omega = sh.ring.sp.omega * sqrt(frac)
        for i in range(5):
            x1[i] = x[i] + rate[i] * (frac - done)
        if done > 0.0:
            copy_shaft(sh, keep, cur)
        else:
            for i in range(sh.parts * sh.ring.z):
                cur.part[i // sh.ring.z].do[i % sh.ring.z] = NAN
                cur.part[i // sh.ring.z].ao[i % sh.ring.z] = NAN
        its[0] += shaft_newton(&stage, x1, cur, trial, NULL, done > 0.0 and sh.warm_stages)
        if cur.score <= sh.ring.lim.accept:
            for i in range(5):
                if done > 0.0:
                    rate[i] = (x1[i] - x[i]) / (frac - done)
                x[i] = x1[i]
            done = frac
            copy_shaft(sh, cur, keep)
            if done == 1.0:
                for i in range(5):
                    v[i] = x[i]
                return True
            step = min(2.0 * step, 1.0 - done)
        else:
            step *= 0.5
            if step < 1e-6:
                return False
    return False


# ----------------------------------------------------------------------------- Python boundary

cdef void ring_on(Ring *rg, int z, const double *consts, const double *ki, const double *ko,
                  const double *node_x, const double *node_w, const double *c, const double *s,
                  const double *geo, const double *lim) noexcept nogil:
    """One case's Ring from the rows of the boundary's arrays (see ``solve_speed``)."""
    speed_on(&rg.sp, consts, ki, ko, node_x, node_w)
    rg.z = z
    rg.c = c
    rg.s = s
    rg.base = geo[0]
    rg.length = geo[2]
    rg.one_sided = geo[3] != 0.0
    rg.lim.tolerance = lim[0]
    rg.lim.accept = lim[1]
    rg.lim.rounding = lim[2]
    rg.lim.noise_max = lim[3]
    rg.lim.ball_tolerance = lim[4]
    rg.lim.ball_round = lim[5]
    rg.lim.trials = <int> lim[6]
    rg.lim.halvings = <int> lim[7]
    rg.lim.ball_iterations = <int> lim[8]
    rg.lim.fallback_iterations = <int> lim[9]
    rg.lim.ball_halvings = <int> lim[10]
    rg.lim.singular = lim[11]


cdef void shaft_on(Shaft *sh, int parts, const double *maps, const double *offset,
                   const double *f, const unsigned char *held, double f_ref,
                   const double *shaft_limits) noexcept nogil:
    """The shaft of one case (its Ring set apart by ``ring_on``)."""
    cdef int i
    sh.parts = parts
    for i in range(25 * parts):
        sh.maps[i] = maps[i]
    for i in range(5 * parts):
        sh.offset[i] = offset[i]
    for i in range(5):
        sh.f[i] = f[i]
        sh.held[i] = held[i]
    sh.f_ref = f_ref
    sh.iterations = <int> shaft_limits[0]
    sh.stages = <int> shaft_limits[1]
    sh.warm_stages = shaft_limits[2] != 0.0


cdef void store_dyn(const Dyn *st, int z, Py_ssize_t n, Py_ssize_t k, double *balls,
                    double *terms, double *ring) noexcept nogil:
    """Case k's bearing into the outputs: balls (2, n, z) delta_o, alpha_o; terms
    (BALL_TERMS, n, z); ring (n, 30): gen (5), jac (25)."""
    cdef Py_ssize_t j, i
    for j in range(z):
        balls[k * z + j] = st.do[j]
        balls[(n + k) * z + j] = st.ao[j]
        for i in range(BALL_TERMS):
            terms[(i * n + k) * z + j] = st.terms[BALL_TERMS * j + i]
    for i in range(5):
        ring[30 * k + i] = st.gen[i]
    for i in range(25):
        ring[30 * k + 5 + i] = st.jac[i]


cdef double *shafts_open(int z, ShaftState *states) noexcept nogil:
    """Five shaft states of two bearings of z balls in one block (to free); NULL if out of
    memory."""
    cdef double *block = <double *> malloc(10 * DYN_PER_BALL * z * sizeof(double) + 8)
    cdef int i
    if block != NULL:
        for i in range(10):
            dyn_on(block + i * DYN_PER_BALL * z, z, &states[i // 2].part[i % 2])
    return block


cdef int shaft_case(Shaft *sh, double *v, const double *v_static, bint continued,
                    ShaftState *st) noexcept nogil:
    """One case: the Newton from v, the balls on their lines; where left unbalanced and
    ``continued``, the continuation from v_static, its answer taken where it reaches the full
    speed. The answer in v and st[0] (st[1] to st[4] work space); the iterations."""
    cdef double saved[5]
    cdef int its, i
    for i in range(sh.parts * sh.ring.z):
        st[0].part[i // sh.ring.z].do[i % sh.ring.z] = NAN
        st[0].part[i // sh.ring.z].ao[i % sh.ring.z] = NAN
    its = shaft_newton(sh, v, &st[0], &st[1], &st[4], False)
    if st[0].score <= sh.ring.lim.accept or not continued:
        return its
    copy_shaft(sh, &st[0], &st[3])
    for i in range(5):
        saved[i] = v[i]
    if not shaft_continuation(sh, v_static, v, &st[0], &st[1], &st[2], &st[4], &its):
        copy_shaft(sh, &st[3], &st[0])
        for i in range(5):
            v[i] = saved[i]
    return its


cdef void store_case(const Shaft *sh, const ShaftState *st, Py_ssize_t n, Py_ssize_t k,
                     double **outs, double *out) noexcept nogil:
    """Case k's answer: each bearing's by ``store_dyn`` into outs (balls, terms, ring of
    bearing 1, then of bearing 2); out (n, 45): gen (5), jac (25), floor (5), merit, score,
    level (35-37); 38-39 left to the caller."""
    cdef int i
    for i in range(sh.parts):
        store_dyn(&st.part[i], sh.ring.z, n, k, outs[3 * i], outs[3 * i + 1], outs[3 * i + 2])
    for i in range(5):
        out[45 * k + i] = st.gen[i]
        out[45 * k + 30 + i] = st.floor[i]
    for i in range(25):
        out[45 * k + 5 + i] = st.jac[i]
    out[45 * k + 35] = st.merit
    out[45 * k + 36] = st.score
    out[45 * k + 37] = st.level


cdef void at_rest(Shaft *sh, ShaftState *st, double *out) noexcept nogil:
    """The shaft centred (v = 0), every ball solved from its line: bearing 1's thrust, and 1
    where every ball of both is balanced (out[0], out[1])."""
    cdef double zero[5]
    cdef int i
    for i in range(5):
        zero[i] = 0.0
    for i in range(sh.parts * sh.ring.z):
        st.part[i // sh.ring.z].do[i % sh.ring.z] = NAN
        st.part[i // sh.ring.z].ao[i % sh.ring.z] = NAN
    shaft_state(sh, zero, st, False, st)
    out[0] = st.part[0].gen[2]
    out[1] = 1.0 if st.part[0].balls_ok and st.part[sh.parts - 1].balls_ok else 0.0


def solve_speed(const double[:, ::1] consts, const double[:, ::1] ki, const double[:, ::1] ko,
                const double[::1] node_x, const double[::1] node_w, const double[:, ::1] c,
                const double[:, ::1] s, const double[:, ::1] geo, const double[::1] limits,
                const double[:, :, :, ::1] maps, const double[:, :, ::1] offset,
                const double[:, ::1] f, const unsigned char[:, ::1] held,
                const double[::1] shaft_limits, const double[:, ::1] v0,
                const double[:, ::1] v_static, const unsigned char[::1] continued):
    """n cases at speed, one bearing (maps (n, 1, 5, 5) the identity, offset 0) or a pair's
    shaft (maps (n, 2, 5, 5), offset (n, 2, 5)): ``shaft_case`` from v0 (n, 5), the continuation
    from v_static where ``continued``. Per case: consts (6), ki, ko (NODES) as ``speed_balls``;
    c, s (z); geo (4): A - G_r/2, the largest applied load (and preload), A, one-sided; f (5),
    held (5, uint8); limits (12): TOLERANCE, ACCEPT, ROUNDING, NOISE_MAX, BALL_TOLERANCE, the
    ball rounding factor, LM_TRIALS, HALVINGS, BALL_ITERATIONS, FALLBACK_ITERATIONS, the ball
    halvings, SINGULAR; shaft_limits (4): Newton iterations, continuation stages, 1: each stage's balls
    warm, 1: the state at rest too (``at_rest``). Returns (v, bearings: (balls, terms, ring)
    of each as ``store_dyn``, out (n, 45) as ``store_case`` with out[:, 38] the
    iterations, 39 accepted, 40-41 ``at_rest``, 42 out of memory)."""
    cdef Py_ssize_t n = c.shape[0], k
    cdef int z = <int> c.shape[1], parts = <int> maps.shape[1], i
    v_a = np.array(v0, dtype=float, copy=True)
    bearings = [(np.empty((2, n, z)), np.empty((BALL_TERMS, n, z)), np.zeros((n, 30)))
                for i in range(parts)]
    out_a = np.zeros((n, 45))
    cdef double[:, ::1] v = v_a, out = out_a
    cdef double *outs[6]
    cdef double[:, :, ::1] arr3
    cdef double[:, ::1] arr2
    for i in range(parts):
        for k in range(2):
            arr3 = bearings[i][k]
            outs[3 * i + k] = &arr3[0, 0, 0]
        arr2 = bearings[i][2]
        outs[3 * i + 2] = &arr2[0, 0]
    cdef Shaft sh
    cdef ShaftState st[5]
    cdef double *block
    with nogil:
        for k in range(n):
            ring_on(&sh.ring, z, &consts[k, 0], &ki[k, 0], &ko[k, 0], &node_x[0], &node_w[0],
                    &c[k, 0], &s[k, 0], &geo[k, 0], &limits[0])
            shaft_on(&sh, parts, &maps[k, 0, 0, 0], &offset[k, 0, 0], &f[k, 0], &held[k, 0],
                     geo[k, 1], &shaft_limits[0])
            block = shafts_open(z, st)
            if block == NULL:
                out[k, 42] = 1.0
                continue
            out[k, 38] = shaft_case(&sh, &v[k, 0], &v_static[k, 0], continued[k], st)
            out[k, 39] = 1.0 if st[0].score <= sh.ring.lim.accept else 0.0
            store_case(&sh, &st[0], n, k, outs, &out[0, 0])
            if shaft_limits[3] != 0.0:
                at_rest(&sh, &st[1], &out[k, 40])
            free(block)
    return v_a, bearings, out_a


# ------------------------------------------------- the combined solver's set-up and results
# (bearingload.models.combined checks and refuses; docs/architecture.md, "The compiled core")

def points(const double[:, ::1] c, const double[:, ::1] s, const double[:, ::1] scalars,
           const double[:, ::1] f, const unsigned char[:, ::1] locked,
           const unsigned char[::1] one_sided, const double[:, ::1] vh, const double[:, ::1] vl,
           const double[:, ::1] kappa):
    """Every ball of n cases at the positions ``vh + vl`` (n, 5) in double-double, their loads
    with the stiffness deviations ``kappa`` (n, z), the forces and the residual (``fresh``):
    ``scalars`` (6, n) = a_hat, pre, gap, b_hi, b_lo, t_imp; returns the (13, n, z) ball arrays
    (as ``solve``'s point), the forces and their terms' sizes (n, 5) each, the residual (n,)."""
    cdef Py_ssize_t n = c.shape[0], k
    cdef int z = <int> c.shape[1], i, j
    balls_a, gen_a, size_a, res_a = np.empty((BALL_ARRAYS, n, z)), np.empty((n, 5)), \
        np.empty((n, 5)), np.empty(n)
    cdef double[:, :, ::1] balls = balls_a
    cdef double[:, ::1] gen = gen_a, size = size_a
    cdef double[::1] res = res_a
    cdef Case cs
    cdef Point pt
    cdef double *block = <double *> malloc(BALL_ARRAYS * z * sizeof(double))
    if block == NULL:
        raise MemoryError()
    point_on(block, z, &pt)
    cs.lim = LIMITS
    with nogil:
        for k in range(n):
            case_at(&cs, z, &c[k, 0], &s[k, 0], &scalars[0, k], n, &f[k, 0], &locked[k, 0],
                    one_sided[k], NULL)
            fresh(&cs, &vh[k, 0], &vl[k, 0], &kappa[k, 0], &pt)
            for i in range(BALL_ARRAYS):
                for j in range(z):
                    balls[i, k, j] = block[i * z + j]
            for i in range(5):
                gen[k, i], size[k, i] = pt.gen[i], pt.size[i]
            res[k] = pt.res
    free(block)
    return balls_a, gen_a, size_a, res_a


cpdef enum SetupStatus:
    SET_UP = 0        # the case's scaled problem is set up
    NO_SCALE = 1      # no load, or the load or the one-ball approach (F/K)^(2/3) beyond range
    TOO_LIGHT = 2     # A over the approach beyond the combined solver's ratio
    TOO_HEAVY = 3     # an angular-contact case's A over the approach below its ratio


cdef void symmetry_locks(int z, bint mirror, double fr, double fa, double mm, double mc,
                         double t_imp, bint imposed, bint tandem,
                         unsigned char *held) noexcept nogil:
    """Which of (x, y, a, t, t_c) a case holds (``held``, 5): the tilt where imposed, and the
    components 0 by a symmetry of the case (combined.symmetry_locks states them; a pair's,
    pair.held_components: its mirror across the mid-plane, not a ``tandem`` pair's)."""
    cdef bint no_tilt = mm == 0 and mc == 0 and t_imp == 0
    cdef bint across = mirror and mc == 0
    cdef bint axial = not tandem and fa == 0 and no_tilt
    cdef bint radial = fr == 0 and no_tilt and z >= 2
    held[0], held[1], held[2] = radial, across or radial, axial
    held[3], held[4] = axial or radial or imposed, across or axial or radial


def locks(int z, const unsigned char[::1] mirror, const double[:, ::1] loads, bint imposed,
          bint tandem=False):
    """``symmetry_locks`` of n cases: ``mirror`` (n,) uint8, ``loads`` (5, n) = F_r, F_a, M,
    M_c, the imposed tilt (a pair's: (4, n), no tilt; ``tandem``: a DT pair's, without the
    mirror across the mid-plane); returns held (n, 5) bool."""
    cdef Py_ssize_t n = mirror.shape[0], k
    cdef bint tilted = loads.shape[0] > 4
    held_a = np.empty((n, 5), dtype=bool)
    cdef unsigned char[:, ::1] held = held_a.view(np.uint8)
    with nogil:
        for k in range(n):
            symmetry_locks(z, mirror[k], loads[0, k], loads[1, k], loads[2, k], loads[3, k],
                           loads[4, k] if tilted else 0.0, imposed, tandem, &held[k, 0])
    return held_a


cdef int problem_case(int z, const double *load, double cage, const double *length,
                      double k_ref, bint angular, bint imposed, const double *limits,
                      Py_ssize_t n, double *c, double *s, unsigned char *mirror,
                      unsigned char *held, double *f, double *out) noexcept nogil:
    """One case of ``combined_problem``: ``load`` and ``length`` its columns (``n`` apart),
    ``out`` its column of the 8 rows; returns its SetupStatus (every output set all the
    same)."""
    cdef double fr = load[0], fa = load[n], mm = load[2 * n], mc = load[3 * n]
    cdef double big_a = length[0], g = length[n], radius = length[2 * n]
    cdef double f_ref, scale, t_imp
    cdef int status = SET_UP
    f_ref = max(max(max(fr, fabs(fa)), hypot(mm, mc) / radius), load[5 * n])
    scale = pow(f_ref / k_ref, 2.0 / 3.0)
    if not (isfinite(f_ref) and f_ref > 0 and scale <= 1e100):
        status = NO_SCALE
    elif big_a / scale > limits[1]:
        status = TOO_LIGHT
    elif angular and big_a / scale < limits[2]:
        status = TOO_HEAVY
    t_imp = radius * (load[4 * n] * (PI / 180.0))
    mirror[0] = ball_directions(z, cage, limits[0], c, s)
    scaled_case(z, c, s, big_a, g, scale, t_imp, c, s, &out[n], n)
    symmetry_locks(z, mirror[0], fr, fa, mm, mc, t_imp, imposed, False, held)
    f[0], f[1], f[2] = fr / f_ref, 0.0 / f_ref, fa / f_ref
    f[3], f[4] = (mm / radius) / f_ref, (mc / radius) / f_ref
    out[0], out[7 * n] = scale, f_ref
    return status


def combined_problem(int z, const double[:, ::1] loads, const double[::1] cage,
                     const double[:, ::1] lengths, const double[::1] k_ref, bint angular,
                     bint imposed, const double[::1] limits):
    """The scaled problem of n cases of the combined solver from their loads (6, n) = F_r,
    F_a, M, M_c [N, N mm], the imposed tilt [°] and a force F is at least (a pair's preload,
    else 0) [N]; the cage angles (n,) [°]; the lengths (3, n)
    = A, G_r/2, the tilt lever R_i [mm]; K_0 (n,) [N/mm^1.5]; ``angular`` (one-sided contact),
    ``imposed`` (the tilt held at the given one); ``limits`` = the symmetry snap [°], the
    largest and (angular contact) smallest A over (F/K_0)^(2/3).

    Per case: F = max(F_r, |F_a|, |(M, M_c)|/R_i, that force), s = (F/K_0)^(2/3), the ball directions
    (``ball_directions``, below 1e-15 made 0) and whether the case is mirrored, the components
    held (combined.symmetry_locks states the symmetries), the applied forces over F, and s,
    A/s, p, max(g, 0)/s, B = A + p in double-double, the imposed tilt R_i theta/s, F (8, n).
    Returns (status (n,) int8 (SetupStatus: the caller refuses), c, s, mirror, held, f, those
    8 rows)."""
    cdef Py_ssize_t n = loads.shape[1], k
    status_a, mirror_a = np.empty(n, dtype=np.int8), np.empty(n, dtype=bool)
    c_a, s_a, held_a = np.empty((n, z)), np.empty((n, z)), np.empty((n, 5), dtype=bool)
    f_a, out_a = np.empty((n, 5)), np.empty((8, n))
    cdef signed char[::1] status = status_a
    cdef unsigned char[::1] mirror = mirror_a.view(np.uint8)
    cdef unsigned char[:, ::1] held = held_a.view(np.uint8)
    cdef double[:, ::1] c = c_a, s = s_a, f = f_a, out = out_a
    with nogil:
        for k in range(n):
            status[k] = problem_case(z, &loads[0, k], cage[k], &lengths[0, k], k_ref[k],
                                     angular, imposed, &limits[0], n, &c[k, 0], &s[k, 0],
                                     &mirror[k], &held[k, 0], &f[k, 0], &out[0, k])
    return status_a, c_a, s_a, mirror_a, held_a, f_a, out_a


cpdef enum CallState:
    ANSWERED = 0   # every case set up, solved, checked: the results are set
    SET_UP_APART = 1  # a case the set-up refuses or treats apart: the caller starts over
    SOLVED = 2     # every case set up and solved, a case flagged (not converged, its residual
                   # above the acceptance, a tilt that may be undetermined, a ball that may
                   # sit at the groove edge): the caller goes on from the solve


cdef bint set_up(int z, const double *col, Py_ssize_t n, bint angular, bint imposed,
                 const double *limits, const double *known, bint reuse, const double *node_x,
                 double *geo, double *geo6, double *k0, double *values, double *c, double *s,
                 unsigned char *mirror, unsigned char *held, double *f, double *out) noexcept nogil:
    """One case of ``combined_call`` set up: ``col`` its column of the 17 input rows (``n``
    apart); ``geo`` its column of A, g, R_i, alpha_0 (``n`` apart); ``k0`` its K_0 or
    constant K and ``values`` its curve's (``stiffness_of``, row 16: the stiffness); the rest
    as ``problem_case``. Returns 0 where the caller's general path must take the call: a geometry ``groove`` refuses, balls that overlap (``limits[5]`` = sin(180°/z)),
    fewer than 3 balls, an angular-contact moment to check, a Hertz set-up the core cannot
    make, a load ``problem_case`` refuses, or a light angular-contact case (A/s above
    ``limits[6]``)."""
    if not groove_case(&col[9 * n], n, angular, limits[3], limits[4], geo, n, True):
        return 0
    if z < 3 or not col[9 * n] <= col[10 * n] * limits[5] * (1.0 + 1e-12):
        return 0
    if angular and (col[3 * n] != 0 or (col[2 * n] != 0 and not imposed)):
        return 0
    if not stiffness_of(col, n, 16, known, reuse, node_x, geo6, k0, values):
        return 0
    if problem_case(z, col, col[6 * n], geo, k0[0], angular, imposed, limits, n, c, s,
                    mirror, held, f, out) != SET_UP:
        return 0
    return not (angular and out[n] > limits[6])


ctypedef struct Setup:
    # the scaled problem of n cases of z balls (``problem_case``'s outputs), C buffers
    double *c          # (n, z)
    double *s          # (n, z)
    double *geo6       # (n, 6): D_w, d_m, f_i, f_o, E, nu
    double *f          # (n, 5)
    double *out        # (8, n): s, A/s, p, gap, b_hi, b_lo, t_imp, F
    unsigned char *mirror  # (n,)
    unsigned char *held    # (n, 5)


cdef int setup_open(Py_ssize_t n, int z, double *f, Setup *st) noexcept nogil:
    """``st``'s buffers (freed by ``free(st.c)`` and ``free(st.mirror)``), its forces ``f``
    the caller's; 0 without memory."""
    st.c = <double *> malloc((2 * n * z + 14 * n) * sizeof(double))
    st.mirror = <unsigned char *> malloc(6 * n)
    if st.c == NULL or st.mirror == NULL:
        free(st.c)
        free(st.mirror)
        return 0
    st.s, st.geo6 = st.c + n * z, st.c + 2 * n * z
    st.f, st.out = f, st.geo6 + 6 * n
    st.held = st.mirror + n
    return 1


cdef bint set_up_all(int z, const double[:, ::1] cols, bint angular, bint imposed,
                     const double *limits, const double *known, const double *node_x,
                     double[:, ::1] geo, double[::1] k0, double *values,
                     Setup *st) noexcept nogil:
    """Every case of ``combined_call`` set up (``set_up``); False at the first the caller's
    general path must take."""
    cdef Py_ssize_t n = cols.shape[1], k
    for k in range(n):
        if not set_up(z, &cols[0, k], n, angular, imposed, limits, known, k > 0, node_x,
                      &geo[0, k], &st.geo6[6 * k], &k0[k],
                      &values[NODES * k] if values != NULL else NULL, &st.c[z * k],
                      &st.s[z * k], &st.mirror[k], &st.held[5 * k], &st.f[5 * k], &st.out[k]):
            return False
    return True


cdef bint solve_all(int z, Py_ssize_t n, const Setup *st, bint angular, bint imposed,
                    const double *values, const double *node_x, const double *node_w,
                    const Limits *lim, double accept, Answers *a) noexcept nogil:
    """Every case of ``combined_call`` solved from the standard start (as ``solve``); False
    where a case is flagged (not converged, its residual with the imposed components held
    above ``accept``, a tilt that may be undetermined, a ball that may sit at the groove
    edge)."""
    cdef Py_ssize_t k
    cdef int i
    cdef int held[5]
    cdef double v0[5]
    cdef Case cs
    cdef bint clean = True
    cs.lim = lim[0]
    for i in range(5):
        v0[i] = 0.0
        held[i] = imposed and i == 3
    cs.node_x, cs.node_w = node_x, node_w
    for k in range(n):
        case_at(&cs, z, &st.c[z * k], &st.s[z * k], &st.out[n + k], n, &st.f[5 * k],
                &st.held[5 * k], angular, &values[NODES * k] if values != NULL else NULL)
        solve_into(&cs, held, v0, False, k, a)
        clean = clean and a.status[k] == OK and a.res[n + k] <= accept
        clean = clean and not a.flags[k] and not a.flags[n + k]
    return clean


cdef void result_all(int z, const double[:, ::1] cols, bint angular, bint imposed,
                     const double[:, ::1] geo, const double[::1] k0, const Setup *st,
                     Answers *a, double[:, ::1] rows, double[:, :, ::1] per_ball,
                     unsigned char[::1] bad) noexcept nogil:
    """Every case's results (``result_case``, as ``combined_result`` with the tangent scaled,
    a case mirrored where its balls are and no cross moment acts)."""
    cdef Py_ssize_t n = cols.shape[1], k, nz = n * z
    cdef double v[5]
    cdef double case_in[11]
    cdef const double *bl[4]
    cdef int j
    for k in range(n):
        for j in range(5):
            v[j] = a.v[5 * k + j] + a.v[5 * (n + k) + j]
        case_in[0], case_in[1], case_in[2] = st.out[6 * n + k], st.out[k], geo[2, k]
        case_in[3], case_in[4], case_in[5] = geo[3, k], geo[0, k], angular
        case_in[6], case_in[7], case_in[8] = st.out[7 * n + k], cols[2, k], cols[6, k]
        case_in[9], case_in[10] = st.out[2 * n + k], k0[k]
        bl[0], bl[1], bl[2], bl[3] = &a.balls[3 * nz + z * k], &a.balls[5 * nz + z * k], \
            &a.balls[6 * nz + z * k], &a.balls[8 * nz + z * k]
        bad[k] = not result_case(v, case_in, 1, &a.forces[5 * k], bl, 1, &a.kappa[z * k], z,
                                 imposed, &a.mats[25 * k], st.mirror[k] and cols[3, k] == 0,
                                 &rows[0, k], &per_ball[0, k, 0], n)


def combined_call(int z, const double[:, ::1] cols, bint angular, bint imposed,
                  const double[::1] known, bint hertz, const double[::1] limits,
                  const double[::1] node_x, const double[::1] node_w, int max_iterations,
                  int first_stage_steps):
    """One call of the combined solver on n cases in one: the set-up (``groove``, the Hertz
    curve, ``combined_problem``), the solve (``solve``, every case from the standard start)
    and the results (``combined_result``), for the common path; the caller's general path
    takes what this leaves (the CallState says where it stopped).

    ``cols`` (17, n): the input rows of combined.INPUT_ROWS; ``hertz``: the Hertz stiffness
    (else the constant K of the stiffness row), with ``known`` = K_0 and the curve's values
    (1 + NODES) of the one case where known, else empty; ``limits`` = the symmetry snap [°],
    the largest and the smallest (angular contact) A/s, the conformity range (2), sin(180°/z),
    the light ratio of angular contact, the residual accepted; the nodes and weights of the
    curve; the iteration limits of ``solve``.

    Returns (state, the solve's output arrays (``answers_arrays``; as ``solve`` returns
    them: ``answers_of``; set where SOLVED or ANSWERED), (the case rows (8, n), the ball rows (5, n, z), the cases whose stiffness
    overflows (n,) uint8: ``combined_result``'s, the tangent made physical; set where
    ANSWERED), the geometry (4, n) = A, g, R_i, alpha_0, K_0 or the constant K (n,), the
    curve's values (n, NODES), the scaled applied forces (n, 5): set where the set-up
    passed; and the one array of which K_0 and the values are views (n (1 + NODES): for one
    case the layout of ``known``, to keep without a copy))."""
    cdef Py_ssize_t n = cols.shape[1]
    cdef Answers a
    cdef Setup st
    cdef Limits lim = LIMITS
    cdef int state = SET_UP_APART
    # (what the result keeps in one block, the rest in another: ``carve``)
    geo_a, rows_a, per_ball_a, mats_a = carve(n, ((4, n), (8, n), (5, n, z), (2, n, 5, 5)))
    kv_a, f_a, *doubles = carve(n, ((n * (1 + NODES),), (n, 5)) + answer_shapes(n, z))
    arrays = answers_arrays(n, z, doubles, mats_a)
    k0_a, values_a = kv_a[:n], kv_a[n:].reshape(n, NODES)
    result_a = (rows_a, per_ball_a, np.zeros(n, dtype=np.uint8))
    answers_at(&a, n, arrays[0], arrays[1], arrays[2], arrays[3], arrays[4], arrays[5],
               arrays[6], arrays[7], arrays[8])
    cdef double[:, ::1] geo = geo_a, values = values_a, rows = result_a[0], f = f_a
    cdef double[::1] k0 = k0_a
    cdef double[:, :, ::1] per_ball = result_a[1]
    cdef unsigned char[::1] bad = result_a[2]
    cdef double *vals = &values[0, 0] if hertz and n > 0 else NULL
    lim.max_iterations, lim.fast_steps = max_iterations, first_stage_steps
    if n == 0 or not setup_open(n, z, &f[0, 0], &st):
        return (state, arrays, result_a, geo_a, k0_a, values_a, f_a, kv_a)
    with nogil:
        if set_up_all(z, cols, angular, imposed, &limits[0],
                      &known[0] if known.shape[0] else NULL, &node_x[0], geo, k0, vals, &st):
            state = SOLVED
            if solve_all(z, n, &st, angular, imposed, vals, &node_x[0], &node_w[0], &lim,
                         limits[7], &a):
                state = ANSWERED
                result_all(z, cols, angular, imposed, geo, k0, &st, &a, rows, per_ball, bad)
        free(st.c)
        free(st.mirror)
    return (state, arrays, result_a, geo_a, k0_a, values_a, f_a, kv_a)


#: Below it a ball's angle [°] is kept, at or above it it is a whole turn, 0: the rule of
#: validate.reduced_angle (360 less validate.TURN_ROUNDING, 4 eps 360°, computed alike).
cdef double TURN_BELOW = 360.0 - 4.0 * 2.220446049250313e-16 * 360.0


cdef bint result_case(const double *v, const double *case_in, Py_ssize_t m, const double *gen,
                      const double **bl, Py_ssize_t step, const double *kappa, int z,
                      bint imposed, double *tangent, bint mirrored, double *out, double *ball,
                      Py_ssize_t n) noexcept nogil:
    """One case of ``combined_result``: its position ``v`` (5), its column of ``case_in``
    (``m`` apart), forces ``gen`` (5), the ball arrays it reads (``bl``: the approach less p,
    cos and sin of the contact angle, the scaled load, ``step`` apart along the balls), its
    stiffness deviations ``kappa`` (z); its tangent made physical in place (``mirrored``: as
    ``physical_case``); writes its column of the case rows (``n`` apart) and its ball rows
    (``n z`` apart), the ball angles reduced to [0, 360) as validate.reduced_angle reduces
    them (``TURN_BELOW``). Returns 0 where the physical stiffness overflows."""
    cdef double w[5]
    cdef double sc = case_in[m], lever = case_in[2 * m], sin0, deg = 180.0 / PI, phi
    cdef Py_ssize_t nz = n * z
    cdef int j
    for j in range(5):
        w[j] = v[j] * sc
    w[3] = (v[3] + case_in[0]) * sc
    sin0 = sin(case_in[3 * m])
    out[0], out[n] = w[0], w[1]
    out[2 * n] = w[2] - (case_in[4 * m] * sin0 if case_in[5 * m] else 0.0)
    out[3 * n], out[4 * n] = (w[3] / lever) * deg, (w[4] / lever) * deg
    out[5 * n] = case_in[3 * m] * deg
    out[6 * n] = 0.0 if case_in[5 * m] else 2.0 * case_in[4 * m] * sin0
    out[7 * n] = lever * case_in[6 * m] * gen[3] if imposed else case_in[7 * m]
    for j in range(z):
        phi = floor_mod(case_in[8 * m] + 360.0 * j / z, 360.0)  # (never -0)
        ball[j] = phi if phi < TURN_BELOW else 0.0  # (just below a whole turn: 0, as the cage)
        ball[nz + j] = atan2(bl[2][j * step], bl[1][j * step]) * deg
        ball[2 * nz + j] = (case_in[9 * m] + bl[0][j * step]) * sc
        ball[3 * nz + j] = (1.0 + kappa[j]) * case_in[10 * m]
        ball[4 * nz + j] = case_in[6 * m] * bl[3][j * step]
    return physical_case(tangent, case_in[6 * m] / sc, lever, mirrored, z)


def combined_result(const double[:, ::1] v, const double[:, ::1] case_in,
                    const double[:, ::1] gen, const double[:, :, :] balls,
                    const double[:, ::1] kappa, bint imposed, double[:, :, ::1] tangent,
                    const unsigned char[::1] mirrored):
    """The answers of n cases of the combined solver in physical units: the scaled position
    ``v`` (n, 5) and ``case_in`` (11, n) = the imposed tilt t_imp, the scale s, the tilt lever
    R_i, the free contact angle [rad], A, one-sided (1/0), F, the moment given [N mm], the cage
    angle [°], the preload approach p, K_0; the scaled forces ``gen`` (n, 5); the balls at the
    answer (13, n, z), as ``solve``'s point (of them the approach less p, the cos and sin of
    the contact angle and the scaled load are read); the stiffness deviations (n, z);
    ``imposed``: the tilt imposed, the moment is the tilt's reaction R_i F gen_t; the stiffness
    ``tangent`` (n, 5, 5), scaled, made physical in place (``physical_case`` with F/s and R_i;
    ``mirrored`` (n,) uint8: the cases mirrored about the load line).

    Returns the case rows (8, n) = x, y, axial (from the centred rings, or for one-sided
    contact from the zero-load position), tilt, tilt_cross [°], free contact angle [°], axial
    play (0 one-sided), moment; the ball rows (5, n, z) = phi_j [°], contact angle [°],
    approach [mm], stiffness [N/mm^1.5], load [N]; and the cases whose physical stiffness
    overflows (n,) uint8."""
    cdef Py_ssize_t n = v.shape[0], k
    cdef int z = <int> kappa.shape[1]
    cases_a, balls_a, bad_a = np.empty((8, n)), np.empty((5, n, z)), np.zeros(n, dtype=np.uint8)
    cdef unsigned char[::1] bad = bad_a
    cdef double[:, ::1] out = cases_a
    cdef double[:, :, ::1] ball = balls_a
    cdef const double *bl[4]
    cdef Py_ssize_t step = balls.strides[2] // sizeof(double)
    with nogil:
        for k in range(n):
            bl[0], bl[1], bl[2], bl[3] = &balls[3, k, 0], &balls[5, k, 0], &balls[6, k, 0], \
                &balls[8, k, 0]
            bad[k] = not result_case(&v[k, 0], &case_in[0, k], n, &gen[k, 0], bl, step,
                                     &kappa[k, 0], z, imposed, &tangent[k, 0, 0],
                                     mirrored[k], &out[0, k], &ball[0, k, 0], n)
    return cases_a, balls_a, bad_a


cdef bint groove_case(const double *given, Py_ssize_t n, bint angular, double low, double high,
                      double *out, Py_ssize_t m, bint lever_third) noexcept nogil:
    """One case of ``groove``: ``given`` its column of the five (``n`` apart), ``out`` its
    column of A, g, alpha0, R_i (``m`` apart; ``lever_third``: A, g, R_i, alpha0); returns
    whether it fits."""
    cdef double dw = given[0], dm = given[n], fi = given[2 * n], fo = given[3 * n]
    cdef double big_a, g, alpha0, half
    big_a = (fi + fo - 1.0) * dw
    if angular:
        alpha0 = given[4 * n] * (PI / 180.0)
        half = sin(alpha0 / 2.0)
        g = 4.0 * big_a * (half * half) / 2.0
    else:
        g = given[4 * n] / 2.0
        alpha0 = 2.0 * asin(sqrt(g / (2.0 * big_a))) if g > 0 else 0.0
    out[0], out[m], out[(3 if lever_third else 2) * m] = big_a, g, alpha0
    out[(2 if lever_third else 3) * m] = dm / 2.0 + (fi - 0.5) * dw * cos(alpha0)
    return (dw > 0 and dm > 0 and dw < dm and fi > low and fi < high and
            fo > low and fo < high and g < big_a)


def groove(const double[:, ::1] given, bint angular, double low, double high):
    """The ring geometry of n deep-groove (or, ``angular``, angular-contact) cases from
    ``given`` (5, n) = D_w, d_m, f_i, f_o [mm, -], and G_r [mm] or (``angular``) the design
    contact angle [°]: returns (5, n) = A = (f_i + f_o - 1) D_w, g = G_r/2 (angular contact:
    G_r = 4 A sin^2(alpha_0/2)), the free contact angle alpha_0 [rad] (deep groove: cos(alpha_0)
    = 1 - g/A as 2 asin(sqrt(g/(2A))), which keeps a small g's digits, 0 without clearance;
    angular contact: as given, not through the arcsine), R_i = d_m/2 + (f_i -
    1/2) D_w cos(alpha_0), and 1 where the case fits (D_w, d_m > 0, D_w < d_m, the
    conformities inside (low, high), g < A), else 0 (combined.ring_geometry refuses it)."""
    cdef Py_ssize_t n = given.shape[1], k
    out_a = np.empty((5, n))
    cdef double[:, ::1] out = out_a
    with nogil:
        for k in range(n):
            out[4, k] = groove_case(&given[0, k], n, angular, low, high, &out[0, k], n, False)
    return out_a
