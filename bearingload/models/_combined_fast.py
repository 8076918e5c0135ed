"""The first stage of the combined-load solver (:mod:`bearingload.models.combined`): Newton in
plain double precision, with the ball stiffness following the contact angles as it goes.

It carries each case from the start (the radial engine's solution and the axial closed form)
to where double precision stops resolving the ring forces, typically in 4 to 8 steps of a few
small array operations each. It decides nothing: the double-double stage
(:mod:`bearingload.models._combined_ring`) starts from where it ends, measures the residual of
every component to its own digits and goes on until each is within the tolerance, so the
accuracy of an answer is that stage's (and a case this stage cannot help, a ring that touches
no ball or a step that does not lower the residual, goes on from the original start).

Scaled units and unknowns as in :mod:`bearingload.models._combined_ring`: ``v = (x, y, a, t,
t_c)``, lengths over ``(F/K_0)^(2/3)``, forces over ``F``. Ball ``j``: ``rho_j = A + p - g +
x c_j + y s_j``, ``u_j = a + (t + t_imp) c_j + t_c s_j``, approach ``delta_j = |(max(rho_j, 0),
u_j)| - A``, load ``(1 + kappa_j) max(delta_j, 0)^1.5`` with ``kappa_j = K(alpha_j)/K_0 - 1``
evaluated at the current contact angle (its change with the angle is left out of the Newton
matrix: K changes by a few 1e-4 over the angles a deep groove allows, so the steps still
shrink fast). Every operation is row-wise, and a case stops on its own: no case depends on the
others of its call.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from bearingload.models._combined_ring import (
    Problem,
    ball_tangent,
    cap_step,
    hold,
    residual_of,
    sum_arms,
    turns,
)

#: Newton steps at most; a case still going then is handed on as it is. [-]
STEPS = 16
#: Halvings of a step that does not lower the residual before the case is handed on. [-]
HALVINGS = 8
#: A case whose residual is below this is handed on (the double-double stage finishes it). [-]
HAND_ON = 1e-9

Curve = Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray]


def _state(p: Problem, v: np.ndarray, rows: np.ndarray, curve: Curve | None) -> tuple:
    """The balls (directions, loads, stiffness deviations, potential), generalised forces and
    residual (as :func:`bearingload.models._combined_ring.residual` measures it) at ``v`` of the
    cases ``rows`` of ``p`` (``v`` holds those rows only)."""
    c, s, f, locked = p.c[rows], p.s[rows], p.f[rows], p.locked[rows]
    rho = (p.a_hat[rows] + p.pre[rows] - p.gap[rows])[:, None] + v[:, 0, None] * c
    rho += v[:, 1, None] * s
    u = (v[:, 2, None] + (v[:, 3] + p.t_imp[rows])[:, None] * c) + v[:, 4, None] * s
    rp = np.maximum(rho, 0.0)
    one_sided = p.one_sided[rows]
    if one_sided.any():  # angular contact: the ball sees max(u, 0)
        u = np.where(one_sided[:, None], np.maximum(u, 0.0), u)
    d = np.hypot(rp, u)
    safe = np.where(d > 0, d, 1.0)
    ca, sa = rp / safe, u / safe
    delta = np.maximum(d - p.a_hat[rows, None], 0.0)
    root = np.sqrt(delta)
    if curve is None:
        kappa = np.zeros_like(delta)
    else:
        kappa = np.where(delta > 0, curve(rows, ca, -sa * sa / (1.0 + ca)), 0.0)
    q = (1.0 + kappa) * delta * root
    arms = p.arms[rows]
    gen = sum_arms(q * ca, q * sa, arms)
    size = sum_arms(np.abs(q * ca), np.abs(q * sa), np.abs(arms))
    res = residual_of(f, gen, size, locked)
    grad = np.where(locked, 0.0, gen - f)
    energy = (q * delta).sum(1) / 2.5 - (np.where(locked, 0.0, f) * v).sum(1)
    return (ca, sa, rho, d, q, root, kappa, energy), grad, res


def _step(p: Problem, rows: np.ndarray, balls: tuple, grad: np.ndarray) -> np.ndarray:
    """The Newton step of the cases ``rows`` (the stiffness frozen), 0 on the held components."""
    ca, sa, rho, d, q, root, kappa, _ = balls
    w1 = 1.5 * (1.0 + kappa) * root
    inside = turns(rho, sa, p.one_sided[rows])  # (sa has the sign of u)
    w2 = np.where(inside, q / np.where(d > 0, d, 1.0), 0.0)
    hess = hold(ball_tangent(p.arms[rows], ca, sa, w1, w2), p.locked[rows])
    hess += (1e-13 * np.trace(hess, axis1=1, axis2=2))[:, None, None] * np.eye(5)
    return cap_step(p, -np.linalg.solve(hess, grad[:, :, None])[:, :, 0], rows)


def newton(p: Problem, v0: np.ndarray, curve: Curve | None) -> tuple[np.ndarray, ...]:
    """Each case from ``v0`` (n, 5) by Newton steps, halved until the residual falls, until its
    residual is below HAND_ON or stops falling. Returns the positions (n, 5), the stiffness
    deviations kappa there (n, z) and the steps each case took (n,) (one without any ball in
    contact at ``v0``, or whose first step fails, stays at ``v0``)."""
    v = v0.copy()
    steps = np.zeros(v.shape[0], dtype=np.int64)
    rows = np.arange(v.shape[0])  # the cases still going
    balls, grad, res = _state(p, v, rows, curve)
    kappa = balls[6].copy()
    for _ in range(STEPS):
        going = np.flatnonzero((res > HAND_ON) & np.isfinite(res) & (balls[5] > 0).any(1))
        if not going.size:
            break
        rows, grad, res = rows[going], grad[going], res[going]
        balls = tuple(b[going] for b in balls)
        step = _step(p, rows, balls, grad)
        slope = (grad * step).sum(1)
        t = np.ones(rows.size)
        todo = np.arange(rows.size)
        took_res = np.full(rows.size, np.inf)
        took_grad = np.empty_like(grad)
        took_balls = [np.empty_like(b) for b in balls]
        for _ in range(HALVINGS):
            trial = v[rows[todo]] + t[todo, None] * step[todo]
            b_t, g_t, r_t = _state(p, trial, rows[todo], curve)
            # the residual falls, or the potential (Armijo, the stiffness as it is) does
            ok = (r_t < res[todo]) | (b_t[7] <= balls[7][todo] + 1e-4 * t[todo] * slope[todo])
            took = todo[ok]
            v[rows[took]], took_res[took], took_grad[took] = trial[ok], r_t[ok], g_t[ok]
            for dst, src in zip(took_balls, b_t, strict=True):
                dst[took] = src[ok]
            todo = todo[~ok]
            if not todo.size:
                break
            t[todo] *= 0.5
        keep = np.flatnonzero(np.isfinite(took_res))  # a step failing every halving: stop
        steps[rows[keep]] += 1
        kappa[rows[keep]] = took_balls[6][keep]
        rows, grad, res = rows[keep], took_grad[keep], took_res[keep]
        balls = tuple(b[keep] for b in took_balls)
    return v, kappa, steps
