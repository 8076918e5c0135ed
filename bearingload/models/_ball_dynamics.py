"""One ball at speed, outer-raceway control: its two equations and their robust solution (a
private helper of :mod:`bearingload.models.high_speed`, whose docstring states the model and its
sources: Jones 1960; Harris & Kotzalas, *Rolling Bearing Analysis*, 5th ed., vol. 2, ch. 2-3).

Units: N, mm, kg, s. Every function takes the balls of n cases at once, arrays (n, z) (or one
ball per row, (m, 1)); the constants of :class:`_Set` are per case, (n, 1).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

import numpy as np

from bearingload.models import _core
from bearingload.models import combined as _combined

#: Relative residual of each ball's equations (of the sum of its force magnitudes). [-]
BALL_TOLERANCE = 1e-13
#: Newton steps of a ball from its warm start, and from the loose / touching starts. [-]
BALL_ITERATIONS = 12
FALLBACK_ITERATIONS = 60
#: Halvings of a ball's Newton step. [-]
HALVINGS = 30
#: Rounding of an approach over its length's (of the ball tolerance). [-]
_ROUND = 16.0 * float(np.finfo(float).eps) / BALL_TOLERANCE
#: N mm per kg mm^2/s^2 (forces from kg, mm, s). [-]
_KG_MM = 1e-3
_NODE_X = _combined._NODE_X
_NODE_W = _combined._NODE_W
_ONES = np.ones(_NODE_X.size)


@dataclass
class _Set:
    """Constants of every ball (n, z) or per case (n, 1), physical units."""

    ri: np.ndarray  # r'_i = (f_i - 1/2) D_w [mm]
    ro: np.ndarray  # r'_o
    dw: np.ndarray
    dm: np.ndarray
    omega: np.ndarray  # [rad/s]
    mass: np.ndarray  # [kg]
    ki: np.ndarray  # K_i at the Chebyshev nodes of cos(alpha) (n, 1, NODES) [N/mm^1.5]
    ko: np.ndarray

    def take(self, idx: np.ndarray) -> _Set:
        return _Set(self.ri[idx], self.ro[idx], self.dw[idx], self.dm[idx], self.omega[idx],
                    self.mass[idx], self.ki[idx], self.ko[idx])  # fmt: skip


def _packed(b: _Set) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The constants of ``b`` as the core takes them: (rows, 6) r'_i, r'_o, D_w, d_m, omega,
    mass; K_i, K_o at the nodes (rows, NODES)."""
    rows = b.ki.shape[0]
    cols = [np.broadcast_to(a, (rows, 1))[:, 0] for a in (b.ri, b.ro, b.dw, b.dm, b.omega, b.mass)]
    return (
        np.ascontiguousarray(np.stack(cols, axis=1), dtype=float),
        np.ascontiguousarray(b.ki.reshape(rows, -1), dtype=float),
        np.ascontiguousarray(b.ko.reshape(rows, -1), dtype=float),
    )


def _core_balls(b: _Set, rho: Any, u: Any, do: Any, ao: Any, partials: bool) -> tuple[Any, ...]:
    """The compiled ball evaluator (:func:`bearingload.models._core.speed_balls`) on the balls
    (rows, z) (or one ball a row, (rows, 1)) of ``b``'s rows: (terms (14, rows, z), partials
    (4, 4, rows, z) or None)."""
    shape = np.broadcast_shapes(np.shape(rho), np.shape(u), np.shape(do), np.shape(ao))
    flat = [
        np.ascontiguousarray(np.broadcast_to(a, shape), dtype=float).reshape(-1)
        for a in (rho, u, do, ao)
    ]
    rows = b.ki.shape[0]
    row = np.broadcast_to(
        np.arange(rows, dtype=np.int64).reshape((rows,) + (1,) * (len(shape) - 1)), shape
    ).reshape(-1)
    consts, ki, ko = _packed(b)
    m = flat[0].size
    terms = np.empty((14, m))
    part = np.empty((16 if partials else 0, m))
    _core.speed_balls(
        *flat, np.ascontiguousarray(row), consts, ki, ko, _NODE_X, _NODE_W, terms, part
    )
    return terms.reshape((14,) + shape), part.reshape((4, 4) + shape) if partials else None


def ball_terms(b: _Set, rho: Any, u: Any, do: Any, ao: Any) -> tuple[Any, ...]:
    """Every quantity of the balls at (rho, u) with the unknowns (delta_o, alpha_o).

    Returns (g1, g2, Q_i, Q_o, sin a_i, cos a_i, F_c, M_g, omega_c, omega_R, beta, delta_i,
    ring axial force, ring radial force) [N, mm, rad/s]; the ring forces are those the ball
    puts on the inner ring's equilibrium (``Q_i sin a_i``, ``Q_i cos a_i``). The compiled
    evaluator (``ball_eval`` of :mod:`bearingload.models._core`).

    The inner raceway is the half of the inner groove facing the ball set (``cos a_i >= 0``):
    the radial offset of the inner groove centre from the ball centre is taken at least 0, as
    the static model takes the groove centres' radial offset (``max(rho, 0)``). Without it a
    ball whose centre lies radially outward of its inner groove centre would touch the far side
    of the groove circle, where the ring has no surface, and Jones's relations with ``cos a_i =
    -1`` give ``c_o + c_i = 0``, an infinite orbit speed."""
    return tuple(_core_balls(b, rho, u, do, ao, False)[0])


def ball_partials(b: _Set, rho: Any, u: Any, do: Any, ao: Any) -> tuple[tuple[Any, ...], Any]:
    """:func:`ball_terms` and the derivatives of (g1, g2, F_a, F_r) (rows) by (delta_o, alpha_o,
    rho, u') (columns), analytic (the chain rule in the core), (4, 4) + the balls' shape."""
    terms, part = _core_balls(b, rho, u, do, ao, True)
    return tuple(terms), part


def static_partials(b: _Set, rho: Any, up: Any) -> np.ndarray:
    """Balls at speed 0 (on their lines, K_i and K_o in series): (F_a, F_r, dF_a/drho, dF_a/du',
    dF_r/drho, dF_r/du') (6,) + the balls' shape. [N, N/mm]"""
    shape = np.broadcast_shapes(np.shape(rho), np.shape(up))
    flat = [
        np.ascontiguousarray(np.broadcast_to(a, shape), dtype=float).reshape(-1) for a in (rho, up)
    ]
    rows = b.ki.shape[0]
    row = np.broadcast_to(
        np.arange(rows, dtype=np.int64).reshape((rows,) + (1,) * (len(shape) - 1)), shape
    ).reshape(-1)
    out = np.empty((6, flat[0].size))
    _core.static_balls(*flat, np.ascontiguousarray(row), *_packed(b), _NODE_X, _NODE_W, out)
    return out.reshape((6,) + shape)


def _stiffness(nodes: np.ndarray, cos_alpha: np.ndarray) -> np.ndarray:
    """K(cos alpha) from its values ``nodes`` (n, 1, NODES) at the Chebyshev nodes (barycentric
    interpolation); below cos = 0.05 (a loose ball pointing across the groove: no load) the
    value at 0.05. [N/mm^1.5]"""
    terms = (2.0 * np.maximum(cos_alpha, 0.05) - 1.0)[..., None] - _NODE_X  # x - x_k
    np.divide(_NODE_W, terms, out=terms)  # w_k / (x - x_k)
    return (terms @ np.swapaxes(nodes, -1, -2))[..., 0] / (terms @ _ONES)


def _line_start(b: _Set, rho: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The static position: the ball on the line of its groove centres, the approach shared by
    the contacts as their compliances, delta_o = w delta, w = K_o^-2/3 / (K_i^-2/3 + K_o^-2/3)."""
    r = np.maximum(rho, 0.0)
    d = np.hypot(r, u)
    cos_a = r / np.where(d > 0, d, 1.0)
    ci, co = _stiffness(b.ki, cos_a) ** (-2.0 / 3.0), _stiffness(b.ko, cos_a) ** (-2.0 / 3.0)
    w = co / (ci + co)
    return w * (d - b.ri - b.ro), np.arctan2(u, r)


def _ball_norm(
    b: _Set, t: tuple[Any, ...], do: np.ndarray, moving: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The balls' residual over their force size, and which balls are balanced (those at
    speed 0 are, on their line)."""
    g1, g2, qi, qo, fc, mg = t[0], t[1], t[2], t[3], t[6], t[7]
    size = np.abs(qi) + np.abs(qo) + np.abs(fc) + 2.0 * np.abs(mg) / b.dw
    # the rounding of the approaches, differences of lengths up to r' + delta
    di = np.abs(t[11])
    with np.errstate(all="ignore"):
        extra = qi * (di + b.ri) / di + qo * (do + b.ro) / do  # NaN at 0/0 (no contact)
        size = size + _ROUND * np.where(np.isnan(extra), 0.0, extra)
        norm = np.hypot(g1, g2) / size
    norm = np.where(np.isfinite(norm), norm, np.inf)
    return norm, ~moving | (norm <= BALL_TOLERANCE)


def solve_balls(
    b: _Set, rho: np.ndarray, u: np.ndarray, do: np.ndarray, ao: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Every ball's two equations at the ring position (rho, u) (n, z), from (do, ao). Cases
    at speed 0 keep the given (line) position. Returns (do, ao, converged (n, z)).

    Newton from the given (warm) start, each ball until it is balanced; a ball it leaves
    unbalanced is solved alone: its loose state (no inner contact; ``alpha_o = 0``, ``Q_o =
    F_c``: the friction ``2 M_g/D_w`` vanishes with ``beta``), the answer when its inner
    approach is a gap there; otherwise Newton from that state kept in inner contact
    (``delta_i > 0``), where the equations are smooth."""
    shape = do.shape
    one = b.take(np.repeat(np.arange(shape[0]), shape[1]))  # one ball a row (m, 1)
    r1, u1 = rho.reshape(-1, 1), u.reshape(-1, 1)
    moving = np.broadcast_to(b.omega > 0, shape).reshape(-1, 1)
    do, ao, ok = _ball_newton(one, r1, u1, do.reshape(-1, 1), ao.reshape(-1, 1), moving,
                              BALL_ITERATIONS, False)  # fmt: skip
    if not ok.all():
        bad = np.flatnonzero(~ok[:, 0])
        one, r1, u1 = one.take(bad), r1[bad], u1[bad]
        live = np.ones((bad.size, 1), dtype=bool)
        ld, loose_ok = _loose(one, r1, u1, live)
        line = _line_start(one, r1, u1)
        gap = np.real(ball_terms(one, r1, u1, ld, np.zeros_like(ld))[11]) <= 0.0
        take = loose_ok & gap
        start_d = np.where(loose_ok, ld, np.maximum(line[0], 1e-6 * one.ro))
        start_a = np.where(loose_ok, 0.0, line[1])
        d2, a2, ok2 = _ball_newton(one, r1, u1, start_d, start_a, live & ~take,
                                   FALLBACK_ITERATIONS, True)  # fmt: skip
        do[bad], ao[bad] = np.where(take, ld, d2), np.where(take, 0.0, a2)
        ok[bad] = take | ok2
    return do.reshape(shape), ao.reshape(shape), ok.reshape(shape)


def _ball_jacobian(
    b: _Set, rho: np.ndarray, u: np.ndarray, do: np.ndarray, ao: np.ndarray
) -> tuple[np.ndarray, ...]:
    """d(g1, g2)/d(X_1, X_2) (the ball centre, Cartesian) from the analytic derivatives by
    (do, ao)."""
    d = ball_partials(b, rho, u, do, ao)[1]
    j11, j12, j21, j22 = d[0, 0], d[0, 1], d[1, 0], d[1, 1]
    lo, so, co = b.ro + do, np.sin(ao), np.cos(ao)
    # d do/dX = (so, co), d ao/dX = (co, -so)/lo
    return (j11 * so + j12 * co / lo, j11 * co - j12 * so / lo,
            j21 * so + j22 * co / lo, j21 * co - j22 * so / lo)  # fmt: skip


def _ball_newton(
    b: _Set, rho: np.ndarray, u: np.ndarray, do: np.ndarray, ao: np.ndarray,
    moving: np.ndarray, iterations: int, keep_contact: bool,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:  # fmt: skip
    """Newton on the ball centre (X_1, X_2) of one ball a row (m, 1), each step on the balls
    still unbalanced only, halved until the residual falls (and, with ``keep_contact``, the
    inner approach of a ball touching stays positive)."""
    do, ao = do.copy(), ao.copy()
    t = ball_terms(b, rho, u, do, ao)
    ok = _ball_norm(b, t, do, moving)[1]
    touching = keep_contact & (t[11] > 0)
    g1, g2 = t[0].copy(), t[1].copy()
    for _ in range(iterations):
        act: Any = np.flatnonzero(~ok[:, 0])
        if act.size == 0:
            break
        if act.size == do.shape[0]:  # every ball: no copies
            act = slice(None)
        d, a, ok_a, moved, h1, h2 = _ball_step(
            b if isinstance(act, slice) else b.take(act), rho[act], u[act], do[act], ao[act],
            moving[act], touching[act], (g1[act], g2[act]),
        )  # fmt: skip
        do[act], ao[act], ok[act], g1[act], g2[act] = d, a, ok_a, h1, h2
        if not moved.any():
            break
    return do, ao, ok


def _ball_step(
    b: _Set, rho: np.ndarray, u: np.ndarray, do: np.ndarray, ao: np.ndarray,
    moving: np.ndarray, touching: np.ndarray, g: tuple[np.ndarray, np.ndarray],
) -> tuple[np.ndarray, ...]:  # fmt: skip
    """One Newton step of unbalanced balls whose residual is g, halved until the residual
    falls. Returns (do, ao, balanced, moved, g1, g2)."""
    t = g
    a11, a12, a21, a22 = _ball_jacobian(b, rho, u, do, ao)
    det = a11 * a22 - a12 * a21
    with np.errstate(all="ignore"):
        s1 = -(a22 * t[0] - a12 * t[1]) / det
        s2 = -(-a21 * t[0] + a11 * t[1]) / det
    go = np.isfinite(s1) & np.isfinite(s2)
    s1, s2 = np.where(go, s1, 0.0), np.where(go, s2, 0.0)
    cut = np.minimum(1.0, 0.25 * b.ro / np.maximum(np.hypot(s1, s2), 1e-300))
    lo = b.ro + do
    y0 = (lo * np.sin(ao), lo * np.cos(ao))
    return _ball_search(b, rho, u, (do, ao), y0, (s1 * cut, s2 * cut), moving, touching, t, go)


def _ball_search(
    b: _Set, rho: np.ndarray, u: np.ndarray, x: tuple[np.ndarray, np.ndarray],
    y0: tuple[np.ndarray, np.ndarray], s: tuple[np.ndarray, np.ndarray], moving: np.ndarray,
    touching: np.ndarray, g: tuple[np.ndarray, np.ndarray], go: np.ndarray,
) -> tuple[np.ndarray, ...]:  # fmt: skip
    """The step s from the ball centres y0 (X_1, X_2), halved for each ball until its
    residual falls below its size |g|, each trial on the balls still pending only (a ball's
    trials depend on it alone). Returns (do, ao, balanced, moved, g1, g2)."""
    do, ao = x[0].copy(), x[1].copy()
    g1, g2 = g[0].copy(), g[1].copy()
    size = np.hypot(g1, g2)
    ok = np.zeros(do.shape, dtype=bool)
    rows = np.flatnonzero(go)
    lam = 1.0
    for _ in range(HALVINGS):
        if rows.size == 0:
            break
        every = rows.size == do.shape[0]  # no copies on the first trial of every ball
        r, br = (slice(None), b) if every else (rows, b.take(rows))
        y1, y2 = y0[0][r] + lam * s[0][r], y0[1][r] + lam * s[1][r]
        d2, a2 = np.hypot(y1, y2) - br.ro, np.arctan2(y1, y2)
        t2 = ball_terms(br, rho[r], u[r], d2, a2)
        ok2 = _ball_norm(br, t2, d2, moving[r])[1]
        better = (np.hypot(t2[0], t2[1]) < (1.0 - 1e-4 * lam) * size[r]) | ok2
        better = (better & (~touching[r] | (t2[11] > 0)))[:, 0]
        won = rows[better]
        do[won], ao[won], ok[won] = d2[better], a2[better], ok2[better]
        g1[won], g2[won] = t2[0][better], t2[1][better]
        rows = rows[~better]
        lam *= 0.5
    moved = go.copy()
    moved[rows] = False
    return do, ao, ok, moved, g1, g2


def _loose(
    b: _Set, rho: np.ndarray, u: np.ndarray, live: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The ball without inner contact: ``alpha_o = 0`` (no friction: beta = 0) and
    ``K_o delta_o^1.5 = F_c`` (F_c at this position), by Newton in delta_o from the rigid
    rolling F_c. Returns (delta_o, solved)."""
    b = dataclasses.replace(b, ki=np.zeros_like(b.ki))  # no inner contact
    k = _stiffness(b.ko, np.ones_like(b.ro))
    fc = 0.125 * b.mass * b.dm * b.omega**2 * _KG_MM
    do = np.broadcast_to((fc / k) ** (2.0 / 3.0), rho.shape).copy()
    zero = np.zeros_like(do)
    ok = np.zeros(do.shape, dtype=bool)
    for _ in range(FALLBACK_ITERATIONS):
        t, d = ball_partials(b, rho, u, do, zero)
        ok = _ball_norm(b, t, do, live)[1]
        if ok.all():
            break
        slope = d[1, 0]
        with np.errstate(all="ignore"):
            step = np.where(ok, 0.0, -t[1] / slope)
        step = np.where(np.isfinite(step), step, 0.0)
        do = np.where(do + step > 0.0, do + step, 0.5 * do)
    return do, ok & np.isfinite(do)
