# The compiled core's C structures (bearingload/models/_core.pyx): one case of the scaled
# ball-bearing ring equilibrium, the state of its balls at one ring position, and a point of the
# Newton iteration. Nothing here holds a Python object.

cdef enum:
    NODES = 24  # Chebyshev nodes of the Hertz stiffness curve K(alpha)/K_0 - 1

ctypedef struct Limits:
    # the tolerances and iteration limits of a call (the module constants of _core.pyx)
    double tolerance, rounding, floor, stall_below, hand_on
    int max_iterations, stall, refresh, max_updates, fast_steps, fast_halvings

ctypedef struct Case:
    # one case of the scaled problem (lengths over (F/K_0)^(2/3), forces over F); ball j at
    # (c[j], s[j]) = (cos, sin) of its angle from the load line
    int z
    const double *c
    const double *s
    double a_hat        # A / scale, the groove-centre distance at contact
    double pre          # preload approach p = max(-G_r/2, 0) / scale
    double gap          # max(G_r/2, 0) / scale
    double b_hi, b_lo   # B = A + p, double-double
    double t_imp        # imposed tilt R_i theta / scale
    double f[5]         # applied generalised forces (x, y, axial, tilt, tilt_cross)
    int locked[5]       # components held (imposed tilt, or 0 by a symmetry)
    int one_sided       # angular contact: a ball sees max(u, 0)
    int deviation       # preloaded ring of z >= 2: forces summed from the preloaded reference
    double q0           # p^1.5 on the deviation cases, else 0
    const double *curve # K(alpha)/K_0 - 1 divided differences at the nodes, or NULL: constant K
    const double *node_x
    const double *node_w
    Limits lim

ctypedef struct Balls:
    # every ball at one ring position (arrays of z)
    double *rho   # radial separation of the groove centres
    double *u     # axial separation
    double *d     # |(max(rho, 0), u')|
    double *eps   # d - B, to the last digits
    double *up    # the axial separation the contact sees: u, or max(u, 0) one-sided

ctypedef struct Loads:
    double *ca
    double *sa
    double *cam1  # cos(alpha) - 1 without cancellation
    double *q     # (1 + kappa) delta^1.5
    double *dq    # q - q0
    double *root  # sqrt(max(delta, 0))
    double *tau   # (delta - p)/p on the deviation cases, else 0
    double *sig   # sqrt(1 + tau) - 1

ctypedef struct Point:
    Balls b
    Loads lo
    double gen[5]   # generalised ball forces on the ring
    double size[5]  # sum of the magnitudes of their terms
    double res      # relative residual (see residual)
    int age         # steps carried by the difference formulas since a fresh evaluation
    double drop     # change of the potential from the point it was reached from

# ------------------------------------------------------------------------ the balls at speed

ctypedef struct Speed:
    # the balls of one case at speed (bearingload.models.high_speed; N, mm, kg, s): r'_i, r'_o,
    # D_w, d_m, the shaft speed [rad/s], the ball mass [kg], and K_i, K_o at the NODES Chebyshev
    # nodes of cos(alpha) [N/mm^1.5] with the nodes' abscissae and barycentric weights
    double ri, ro, dw, dm, omega, mass
    const double *ki
    const double *ko
    const double *node_x
    const double *node_w

ctypedef struct Dual:
    # a value and its derivatives by (delta_o, alpha_o, rho, u') of one ball
    double v
    double d[4]

ctypedef struct SpeedLimits:
    # the tolerances and limits of bearingload.models.high_speed (its module constants)
    double tolerance, accept, rounding, noise_max, ball_tolerance, ball_round
    int trials, halvings, ball_iterations, fallback_iterations, ball_halvings
    double singular

ctypedef struct Ring:
    # one bearing at speed in its own frame (physical units; tilts as R_i theta [mm]): ball j at
    # (c[j], s[j]) = (cos, sin) of its angle; base = A - G_r/2; A (length)
    Speed sp
    int z
    const double *c
    const double *s
    double base, length
    int one_sided
    SpeedLimits lim

ctypedef struct Dyn:
    # every ball of a bearing at speed and the ring's forces at one ring position
    double *do      # delta_o (z)
    double *ao      # alpha_o (z)
    double *ok      # 1 where the ball is balanced (z)
    double *terms   # BALL_TERMS a ball (ball-major)
    double *sens    # 6 a ball: rho, u', d(delta_o, alpha_o)/drho, d(delta_o, alpha_o)/du'
    double *tot     # 4 a ball: dF_a/drho, dF_a/du', dF_r/drho, dF_r/du' (its equations eliminated)
    double *gain    # 2 a ball: |dF/dX (dg/dX)^-1| of F_a, F_r
    double gen[5]   # generalised ring forces [N]
    double jac[25]  # their tangent (row-major) [N/mm]
    double floor[5] # rounding level of each [N]
    double noise[5] # their change over the balls' own residuals [N]
    int balls_ok, touching

ctypedef struct Shaft:
    # one bearing (parts 1: L = I, offset 0) or a pair on one rigid shaft (parts 2,
    # bearingload.models.pair_speed): bearing k the Ring ``ring`` at L_k v + offset_k
    Ring ring
    int parts
    double maps[50]    # L_1, L_2 (5 x 5 each, row-major)
    double offset[10]
    double f[5]        # applied generalised forces [N]
    double f_ref       # the largest applied load (and preload) [N]
    int held[5]        # components held by a symmetry or an imposed tilt
    int iterations, stages, warm_stages

ctypedef struct ShaftState:
    Dyn part[2]
    double gen[5]
    double jac[25]
    double floor[5]
    double noise[5]
    double merit, score, level
    int touching
