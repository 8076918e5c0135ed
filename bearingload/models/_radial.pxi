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

from libc.math cimport M_PI, NAN, cos, exp, expm1, log1p, pow, sin

ctypedef struct RingSet:
    # the balls of one ring (arrays of k angles) and the work arrays of an evaluation
    int k
    double *c
    double *s
    double *u      # gap factor of each ball (1 in the forward problem and under preload)
    double *w      # multiplicity (or the ball stiffness in the forward problem)
    double *delta  # approach of each ball at the last evaluation
    double *q      # load and slope of each ball at the last evaluation
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
        r.q[j] = q
        r.dq[j] = dq
        wt = r.w[j] * term
        sums_add(o, wt, r.w[j] * dq, r.c[j], r.s[j])
        o.size += fabs(wt)
        o.energy += r.w[j] * pm * (p * br)


cdef inline double ring_snap(double v) noexcept nogil:
    """A cosine or sine below 1e-14 in size is the rounding of an exact zero."""
    return 0.0 if fabs(v) < 1e-14 else v


cdef void forward_case(RingSet *r, double x, double y, double k, double e, double phi1_deg,
                       double m, double *out, int *loaded) noexcept nogil:
    """The forward problem of one case: ``r`` holds the ball directions of the cage's frame
    (ball 1 on its first axis), ``r.w`` the stiffness K of every ball, ``r.q`` the ball loads'
    output; the displacement is turned into that frame and the force (fx, fy) and the tangent
    (kxx, kxy, kyy) into ``out`` turned back (F = R F', K = R K' R^T)."""
    cdef double rad = phi1_deg * (M_PI / 180.0)
    cdef double c1 = ring_snap(cos(rad)), s1 = ring_snap(sin(rad))
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
            r.c[j] = ring_snap(cos((360.0 * j / z) * (M_PI / 180.0)))
            r.s[j] = ring_snap(sin((360.0 * j / z) * (M_PI / 180.0)))
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


# ------------------------------------------------------------- the radial equilibrium
#
# The scaled ring equilibrium of bearingload.models.equilibrium (lengths over s = (F_r/K)^(1/m),
# forces over F_r): find (xi, eta) where the ball forces balance the unit load along x. A
# symmetric cage (0 or half pitch) is half a ring folded onto the other (``w`` the multiplicity),
# eta = 0: bracketed Newton on x alone (``ring_solve_sym``). Any other cage angle: damped Newton on
# the convex potential in (xi, eta) with an Armijo line search, the first contact along a step
# and the step in x alone where the line search stalls (``ring_solve_gen``).

cdef double RADIAL_EPS = 2.220446049250313e-16

# the ring sums as ``ring_eval`` leaves them: the scaled residual (gx = force - 1, gy), its
# Jacobian, the size the residual is measured against (max(1, sum |terms|)) and the potential
ctypedef Sums Eval

ctypedef struct Radial:
    # one case: its ring (the balls in the load frame), its data and its work arrays
    RingSet r
    bint folded        # a symmetric half ring: eta = 0, transverse sums cancel with the mirror
    double tol         # relative residual to reach
    double polish      # tolerances up to this get the last Newton step too
    int max_iterations
    double start, hi   # start and upper bound of xi (the one-ball bound)
    double *keep       # the approaches of the current point (the line search's trials in r.delta)
    bint turned        # a general ring: r.c, r.s in the frame of the ball nearest the load line
    double cp, sp, sign  # cos and sin of that ball's angle, -1 in a mirror image (else 1)
    double *lc         # a general ring's ball directions in the load frame (for the results)
    double *ls


cdef inline void turn_in(const Radial *rd, double a, double b, double *at) noexcept nogil:
    """(a, b) of the load frame in the frame of the ball nearest the load line (of the mirror
    image where that is ball z): one table of ball directions serves every cage angle, and the
    turn's rounding, eps |sin(tau)| of the sums, stays proportional to the loaded balls' angles."""
    cdef double mirrored = rd.sign * b
    at[0] = rd.cp * a + rd.sp * mirrored
    at[1] = rd.cp * mirrored - rd.sp * a


cdef void turn_back(const Radial *rd, Sums *o) noexcept nogil:
    """Force g and Jacobian H of the turned frame in the load frame: R g, R H R^T."""
    cdef double cp = rd.cp, sp = rd.sp, gx = o.gx, gy = o.gy, hxx = o.hxx, hyy = o.hyy
    cdef double cc = cp * cp, ss = sp * sp, cs = cp * sp, two_cs_hxy = 2.0 * cs * o.hxy
    o.gx = cp * gx - sp * gy
    o.gy = rd.sign * (sp * gx + cp * gy)
    o.hxx = cc * hxx - two_cs_hxy + ss * hyy
    o.hxy = rd.sign * (cs * (hxx - hyy) + (cc - ss) * o.hxy)
    o.hyy = ss * hxx + two_cs_hxy + cc * hyy


cdef void ring_eval(Radial *rd, double a, double b, Eval *ev) noexcept nogil:
    """The scaled residual, Jacobian, size and potential at (a, b) of the load frame."""
    cdef double at[2]
    at[0] = a
    at[1] = b
    if rd.turned:
        turn_in(rd, a, b, at)
    if rd.r.pre:
        ring_sums_pre(&rd.r, at[0], at[1], ev)
    else:
        ring_sums(&rd.r, at[0], at[1], ev)
    if rd.turned:
        turn_back(rd, ev)
    ev.gx = ev.gx - 1.0
    if rd.folded:
        ev.gy = ev.hxy = 0.0
    ev.size = max(1.0, ev.size)
    ev.energy = ev.energy / (rd.r.m + 1.0) - a


cdef void ring_start_sums(const double *c, const double *u, const double *w, int k, double m,
                     double *out) noexcept nogil:
    """(xi0, slope, sum w c^2) of a symmetric ring's start: ``xi0 = (sum w c^(m+1))^(-1/m)``
    over the balls ahead of 90°, the slope of the start in the clearance ``sum w c^m u /
    sum w c^(m+1)``, and the sum over every ball of ``w c^2`` (the preload's linear start)."""
    cdef double sum_c = 0.0, sum_u = 0.0, sum_c2 = 0.0
    cdef int j
    for j in range(k):
        if c[j] > 0.0:
            sum_c += w[j] * pow(c[j], m + 1.0)
            sum_u += w[j] * pow(c[j], m) * u[j]
        sum_c2 += w[j] * c[j] * c[j]
    out[0] = pow(sum_c, -1.0 / m)
    out[1] = sum_u / sum_c
    out[2] = sum_c2


cdef double ring_start(const double *sums, double e_hat, double m, bint pre,
                     double hi) noexcept nogil:
    """The start of xi from the ring sums of ``ring_start_sums``: the zero-clearance tangent moved
    by the clearance, or the linear response of a preloaded ring; at most ``hi``."""
    if pre:
        return min(1.0 / (m * pow(-e_hat, m - 1.0) * sums[2]), hi)
    return min(sums[0] + sums[1] * e_hat, hi)


cdef int ring_solve_sym(Radial *rd, double *xi, int *its, double *res) noexcept nogil:
    """Bracketed Newton on gx(xi, 0) = 0 (it rises with xi; gx(0) = -1; ``rd.hi`` bounds the
    root, widened under preload). Returns OK or NOT_CONVERGED (``res``: the last residual)."""
    cdef double lo = 0.0, hi = rd.hi, x = rd.start, new, rel
    cdef bint met, outside
    cdef Eval ev
    cdef int it, k
    if rd.r.pre:
        for k in range(2100):
            ring_eval(rd, hi, 0.0, &ev)
            if not ev.gx < 0.0:
                break
            hi = 2.0 * hi
    for it in range(1, rd.max_iterations + 1):
        ring_eval(rd, x, 0.0, &ev)
        if ev.gx < 0.0:
            lo = x
        elif ev.gx > 0.0:
            hi = x
        new = x - ev.gx / ev.hxx
        outside = not (new > lo and new < hi)
        if outside:
            new = 0.5 * (lo + hi)
        rel = ev.gx / ev.size
        met = fabs(rel) <= rd.tol
        its[0] = it
        res[0] = fabs(rel)
        if met or fabs(new - x) <= 4.0 * RADIAL_EPS * fabs(x):
            # at full-precision tolerances the last Newton step is taken too
            xi[0] = new if (met and rd.tol <= rd.polish and not outside) else x
            return OK
        x = new
    xi[0] = x
    return NOT_CONVERGED


cdef inline void ring_newton(const Eval *ev, double *dx, double *dy) noexcept nogil:
    """The Newton step of (gx, gy), the Jacobian regularised by 1e-12 of its trace."""
    cdef double reg = 1e-12 * (ev.hxx + ev.hyy) + 1e-300
    cdef double hxx = ev.hxx + reg, hyy = ev.hyy + reg
    cdef double det = hxx * hyy - ev.hxy * ev.hxy
    dx[0] = -(hyy * ev.gx - ev.hxy * ev.gy) / det
    dy[0] = -(hxx * ev.gy - ev.hxy * ev.gx) / det


cdef inline bint ring_armijo(const Eval *new, const Eval *cur, double t, double slope,
                        double gnorm) noexcept nogil:
    """Armijo decrease of the potential, or the residual at least halved (a potential at the
    rounding level)."""
    return new.energy <= cur.energy + 1e-4 * t * slope or hypot(new.gx, new.gy) < 0.5 * gnorm


cdef double ring_first_contact(const Radial *rd, double dx, double dy) noexcept nogil:
    """The step fraction (1.001 times it) at which the first ball out of contact (approach below
    -1e-12, so a ball a rounding short of contact counts as touching) would touch moving by
    (dx, dy); 1 where none would before the full step. Where only the balls near the load line
    carry (3 or 4 balls under preload, the cage 1e-9° off the load line) the Newton step across
    it is huge, and halving it from 1 takes x's part down with it: the iteration stalled."""
    cdef double reach = INFINITY, rate
    cdef int j
    cdef double at[2]
    at[0] = dx
    at[1] = dy
    if rd.turned:
        turn_in(rd, dx, dy, at)
    for j in range(rd.r.k):
        rate = at[0] * rd.r.c[j] + at[1] * rd.r.s[j]
        if rate > 0.0 and rd.keep[j] < -1e-12:
            reach = min(reach, -rd.keep[j] / rate)
    return min(1.001 * reach, 1.0)


cdef bint ring_line_search(Radial *rd, double a, double b, const Eval *cur, double *step,
                      Eval *trial) noexcept nogil:
    """Damped step from (a, b) along ``step`` (dx, dy, t in, the accepted t out): the full
    step, then just past the first contact along it (or half), then halvings; after DECOUPLE
    trials the Newton step in x alone where x is out of balance, more than y (a huge y part held
    it back; where y is the more out of balance, the halvings go on: 3 balls, m = 3, the cage
    2.1° off the load line stalled in x steps with a tenth of the load unbalanced across).
    ``trial`` is the state at the accepted point; False: none accepted in 80 trials."""
    cdef double gnorm = hypot(cur.gx, cur.gy), slope = cur.gx * step[0] + cur.gy * step[1]
    cdef double t = 1.0
    cdef int k
    ring_eval(rd, a + step[0], b + step[1], trial)
    if ring_armijo(trial, cur, t, slope, gnorm):
        step[2] = t
        return True
    for k in range(80):
        if k == 0:
            t = min(0.5, ring_first_contact(rd, step[0], step[1]))
        elif k == RADIAL_DECOUPLE and fabs(cur.gx) > max(rd.polish * cur.size, fabs(cur.gy)):
            step[0] = -cur.gx / (cur.hxx + 1e-12 * (cur.hxx + cur.hyy) + 1e-300)
            step[1] = 0.0
            t = 1.0
            slope = cur.gx * step[0]
        else:
            t = 0.5 * t
        ring_eval(rd, a + t * step[0], b + t * step[1], trial)
        if ring_armijo(trial, cur, t, slope, gnorm):
            step[2] = t
            return True
    step[2] = t
    return False


cdef inline double ring_residual(const Eval *ev) noexcept nogil:
    return hypot(ev.gx, ev.gy) / ev.size


cdef void ring_polish(Radial *rd, const Eval *st, double *xi, double *eta) noexcept nogil:
    """One more Newton step from the converged state, taken where it does not raise the
    residual: on a flat valley (3 balls under preload, the cage 5e-12° off the load line) a
    full step may jump so far that a lifted ball touches again."""
    cdef double px, py
    cdef Eval new
    ring_newton(st, &px, &py)
    ring_eval(rd, xi[0] + px, eta[0] + py, &new)
    if ring_residual(&new) <= ring_residual(st):
        xi[0] += px
        eta[0] += py


cdef int ring_solve_gen(Radial *rd, double *xi, double *eta, int *its, double *res) noexcept nogil:
    """Damped Newton on the potential in (xi, eta) from (rd.start, 0). Returns OK or
    NOT_CONVERGED (``res``: the residual where it stopped)."""
    cdef double a, b, na, nb, step[3]
    cdef Eval cur, trial
    cdef double *swap_delta
    cdef int it
    cdef bint conv, small
    xi[0] = rd.start
    eta[0] = 0.0
    its[0] = 0
    ring_eval(rd, xi[0], eta[0], &cur)
    if ring_residual(&cur) <= rd.tol:
        return OK
    for it in range(rd.max_iterations):
        swap_delta = rd.keep  # the approaches at the current point, for the first contact
        rd.keep = rd.r.delta
        rd.r.delta = swap_delta
        a = xi[0]
        b = eta[0]
        ring_newton(&cur, &step[0], &step[1])
        if not ring_line_search(rd, a, b, &cur, step, &trial):
            ring_eval(rd, a + step[2] * step[0], b + step[2] * step[1], &trial)
        na = a + step[2] * step[0]
        nb = b + step[2] * step[1]
        small = hypot(na - a, nb - b) <= 4.0 * RADIAL_EPS * hypot(na, nb) + 1e-300
        xi[0] = na
        eta[0] = nb
        its[0] += 1
        conv = hypot(trial.gx, trial.gy) <= rd.tol * trial.size
        if conv and rd.tol <= rd.polish:
            ring_polish(rd, &trial, xi, eta)
        if conv or small:
            return OK
        cur = trial
    res[0] = ring_residual(&cur)
    return NOT_CONVERGED


cdef void ring_derived(Radial *rd, double xi, double eta, double *out) noexcept nogil:
    """(q_hat, loaded, hxx, hxy, hyy, residual) at the solution, scaled. A ball counts as loaded
    when its approach exceeds the rounding of its own computation (8 eps of the terms summed):
    one decision per case, not a rounding accident; an unloaded ball adds no stiffness."""
    cdef RingSet *r = &rd.r
    cdef double noise, q_hat = 0.0, loaded = 0.0, hxx = 0.0, hxy = 0.0, hyy = 0.0, wdq
    cdef Eval ev
    cdef int j
    ring_eval(rd, xi, eta, &ev)
    for j in range(r.k):
        noise = fabs(xi * r.c[j]) + fabs(eta * r.s[j]) + fabs(r.e * r.u[j])
        if r.delta[j] > 8.0 * RADIAL_EPS * noise:
            q_hat = max(q_hat, r.q[j])
            loaded += r.w[j]
            wdq = r.w[j] * r.dq[j]
            hxx += wdq * r.c[j] * r.c[j]
            hxy += wdq * r.c[j] * r.s[j]
            hyy += wdq * r.s[j] * r.s[j]
    out[0] = q_hat
    out[1] = loaded
    out[2] = hxx
    out[3] = 0.0 if rd.folded else hxy
    out[4] = hyy
    out[5] = ring_residual(&ev)


cdef enum:
    RADIAL_DECOUPLE = 12  # line-search trials after which the step becomes the x part alone
    RADIAL_OUT = 11       # columns of a case's result row (see ``radial``)

ctypedef struct RadialSet:
    # what the cases of one call share: the ring's tables (a symmetric ring's half, or a
    # general ring's pitch table in the frame of ball 1) and the half ring the start is from
    int z
    bint folded
    const double *c
    const double *s
    const double *u
    const double *w
    const double *hc
    const double *hu
    const double *hw
    int hk
    double h_top, h_cw  # the start ring's largest cosine and its weight times it
    double last_m       # the exponent of the sums below (NaN: none yet)
    double sums[3]


cdef void turned_ring(const RadialSet *rs, Radial *rd, double frac, double *geo) noexcept nogil:
    """A general ring's ball directions in the load frame, ball 1 at ``frac`` of a pitch: turned
    from the pitch table by the angle of the ball nearest the load line (of the mirror image
    where that is ball z: its angle keeps its digits however near the load line) into ``rd.lc,
    rd.ls``, the turn into ``rd`` (the Newton iterations run in the turned frame); ``geo``: the
    reference position over e (x0, y0), the reference angle mu and the largest cosine."""
    cdef int z = rs.z, j
    cdef bint last = frac > 0.5
    cdef double h = M_PI / z
    cdef double tau = ((1.0 - frac if last else frac) * 2.0 * M_PI) / z
    cdef double ct = cos(tau), st = sin(tau), sign = -1.0 if last else 1.0
    rd.cp, rd.sp, rd.sign = ct, st, sign
    for j in range(z):
        rd.lc[j] = ring_snap(ct * rs.c[j] - st * rs.s[j])
        rd.ls[j] = sign * ring_snap(st * rs.c[j] + ct * rs.s[j])
    geo[2] = (frac * 2.0 * M_PI) / z - h
    geo[0] = cos(geo[2]) / cos(h)
    geo[1] = sin(geo[2]) / cos(h)
    geo[3] = ring_snap(ct)


cdef int radial_case(RadialSet *rs, Radial *rd, double frac, double ratio, double g, double m,
                     double *out, double *geo) noexcept nogil:
    """Solve one case (``ratio`` = F_r/K, ``g`` = G_r) into its row ``out`` (xi, eta,
    iterations, q_hat, loaded, hxx, hxy, hyy, residual, status, the scale s = (F_r/K)^(1/m))
    and, for a general ring, ``geo`` (``turned_ring``)."""
    cdef double xi, eta = 0.0, res = 0.0, top
    cdef double scale = pow(ratio, 1.0 / m), e_hat = (g / 2.0) / scale
    cdef int its = 0, status
    rd.r.e = e_hat
    rd.r.m = m
    if not m == rs.last_m:  # the start ring's sums, once per exponent (the same numbers)
        ring_start_sums(rs.hc, rs.hu, rs.hw, rs.hk, m, rs.sums)
        rs.last_m = m
    rd.hi = pow(1.0 / rs.h_cw, 1.0 / m) / rs.h_top
    rd.start = ring_start(rs.sums, e_hat, m, rd.r.pre, rd.hi)
    if rs.folded:
        status = ring_solve_sym(rd, &xi, &its, &res)
    else:
        turned_ring(rs, rd, frac, geo)
        top = geo[3]
        rd.start = min(rd.start, pow(1.0 / top, 1.0 / m) / top)
        rd.turned, rd.r.c, rd.r.s = True, <double *> rs.c, <double *> rs.s
        status = ring_solve_gen(rd, &xi, &eta, &its, &res)
        rd.turned, rd.r.c, rd.r.s = False, rd.lc, rd.ls  # the results in the load frame
    out[0] = xi
    out[1] = eta
    out[2] = its
    ring_derived(rd, xi, eta, &out[3])
    if status != OK:
        out[8] = res
    out[9] = status
    out[10] = scale
    return status


cdef void radial_open(bint folded, bint pre, const double[:, ::1] tab, int hk, double h_top,
                      double h_cw, double *block, RadialSet *rs, Radial *rd) noexcept nogil:
    """The shared tables of a call (rows of ``tab``: c, s, u, w of the ring, c, u, w of the
    start ring, the first ``hk`` of them) and a case's work arrays (6 rows of ``block``)."""
    cdef int k = <int> tab.shape[1]
    rs.z, rs.folded, rs.hk = k, folded, hk
    rs.c, rs.s, rs.u, rs.w = &tab[0, 0], &tab[1, 0], &tab[2, 0], &tab[3, 0]
    rs.hc, rs.hu, rs.hw = &tab[4, 0], &tab[5, 0], &tab[6, 0]
    rs.h_top, rs.h_cw, rs.last_m = h_top, h_cw, NAN
    rd.r.k, rd.r.pre, rd.folded = k, pre, folded
    rd.r.c, rd.r.s, rd.lc, rd.ls, rd.turned = <double *> rs.c, <double *> rs.s, block, block + k, False
    rd.r.u, rd.r.w = <double *> rs.u, <double *> rs.w
    rd.r.delta, rd.keep, rd.r.q, rd.r.dq = block + 2 * k, block + 3 * k, block + 4 * k, block + 5 * k


def radial(bint folded, bint pre, const double[:, ::1] tab, int hk, double h_top, double h_cw,
           const double[::1] frac, const double[::1] ratio, const double[::1] g,
           const double[::1] m, double tol,
           int max_iterations, double polish):
    """Solve n cases of one ring kind (bearingload.models.equilibrium groups them): ``folded``
    (a symmetric half ring) or a general ring (its pitch table in the frame of ball 1, ball 1
    at ``frac`` of a pitch per case); ``pre``: the centred formulation; ``tab`` (7, k): c, s, u,
    w of the ring, then c, u, w of the half ring the start is taken from (its first ``hk``),
    ``h_top`` its largest cosine and ``h_cw`` that times its weight; per case ``ratio`` =
    F_r/K, ``g`` = G_r and ``m`` (the core scales them: the same bits for one case or many).
    Returns (rows (n, 11): xi, eta, iterations, q_hat, loaded, hxx, hxy, hyy, residual, status,
    scale; geo (n, 4): x0, y0, mu, largest cosine of a general ring)."""
    cdef Py_ssize_t n = g.shape[0], i
    rows_a = np.empty((n, RADIAL_OUT))
    geo_a = np.zeros((n, 4))
    cdef double[:, ::1] rows = rows_a, geo = geo_a
    cdef RadialSet rs
    cdef Radial rd
    cdef double *block = <double *> malloc(6 * max(tab.shape[1], 1) * sizeof(double))
    if block == NULL:
        raise MemoryError("radial: no memory for the balls of one case")
    radial_open(folded, pre, tab, hk, h_top, h_cw, block, &rs, &rd)
    rd.tol, rd.polish, rd.max_iterations = tol, polish, max_iterations
    with nogil:
        for i in range(n):
            radial_case(&rs, &rd, frac[i], ratio[i], g[i], m[i], &rows[i, 0], &geo[i, 0])
    free(block)
    return rows_a, geo_a


def radial_one(bint folded, bint pre, const double[:, ::1] tab, int hk, double h_top,
               double h_cw, double frac, double ratio, double g, double m, double tol,
               int max_iterations,
               double polish):
    """One case of ``radial`` (the same kernel, a batch of one) for a call from Python with
    numbers: its row and geo as one tuple of 15 floats."""
    cdef RadialSet rs
    cdef Radial rd
    cdef double row[RADIAL_OUT]
    cdef double geo[4]
    cdef double *block = <double *> malloc(6 * max(tab.shape[1], 1) * sizeof(double))
    if block == NULL:
        raise MemoryError("radial: no memory for the balls of one case")
    radial_open(folded, pre, tab, hk, h_top, h_cw, block, &rs, &rd)
    rd.tol, rd.polish, rd.max_iterations = tol, polish, max_iterations
    geo[0] = geo[1] = geo[2] = geo[3] = 0.0
    radial_case(&rs, &rd, frac, ratio, g, m, row, geo)
    free(block)
    return (row[0], row[1], row[2], row[3], row[4], row[5], row[6], row[7], row[8], row[9],
            row[10], geo[0], geo[1], geo[2], geo[3])
