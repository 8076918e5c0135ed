"""Internals of the combined-load solver (:mod:`bearingload.models.combined`): the scaled problem,
the ball geometry to the last digit, the ring forces in deviation form and the Newton minimiser.

Scaled units: lengths over ``s = (F/K)^(2/3)``, forces over ``F`` (the largest applied load).
Unknowns ``v = (x, y, a, t, t_c)``, ``t = R_i theta / s``. Ball ``j`` at ``phi_j``
(``c_j, s_j`` its cosine and sine): ``rho_j = A - g + x c_j + y s_j``, ``u_j = a + (t + t_imp)
c_j + t_c s_j``, ``d_j = |(max(rho_j, 0), u_j)|``, approach ``delta_j = d_j - A``.

Why each piece keeps its digits:

* Position. The state is a pair ``(hi, lo)`` per unknown (a double-double): with a clearance of
  up to 2A, ``x`` is up to ``2e7`` elastic approaches, and one double resolves it only to
  ``eps |x|``, a force error of about 1e-9 of the load. :func:`reference` evaluates every ball
  at such a point in double-double arithmetic (Dekker's exact products), so the approach
  ``d - B`` (``B = A + p``, ``p`` the preload approach) comes out to about ``eps`` of itself
  however large the lengths it is the difference of; :func:`offset` moves from there by a small
  step (a line-search trial) with the difference formulas, which lose nothing either.
* Preload. Every ball carries ``q_0 = p^1.5`` at the centred ring, and ``sum_j q_0 (c_j, s_j)``
  is exactly 0 around a ring of ``z >= 2`` equally spaced balls. The forces are summed as
  ``sum_j (q_j - q_0) g_j + q_0 sum_j g'_j`` with ``g'`` the ball direction less its
  ring-cancelling part (``cos(alpha) - 1 = -sin^2/(1 + cos)`` instead of ``cos(alpha)``), and
  ``q_j - q_0 = q_0 ((1 + kappa_j)(1 + tau_j)^1.5 - 1)``, ``tau_j = (delta_j - p)/p``, in a form
  without cancellation; the stiffness enters as its deviation ``kappa_j = K_j/K_0 - 1``. So a
  preload 10^6 times the load leaves an axial load of 1e-9 of the radial one its own digits
  (the radial engine, :mod:`bearingload.models._ring`, does the same in 2-D).
* Stopping. Each component of the residual is measured against its own applied load or, where
  none is applied, the sum of the magnitudes of the terms it is made of (its rounding level).
* A ball whose groove centres have crossed (``rho_j <= 0``) touches no groove: the potential
  uses ``max(rho_j, 0)``, which is convex and once differentiable; such a ball is loose unless
  ``|u_j| > A``: then it would carry load at a contact angle of exactly 90°, the groove edge,
  which :mod:`bearingload.models.combined` refuses.

Every operation is row-wise (one case per row), so no case depends on the others in its batch.
"""

from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass
from typing import Any

import numpy as np

#: Relative residual of every applied component each case is driven below. [-]
TOLERANCE = 1e-12
#: Largest relative residual accepted at the end (above it the caller raises). [-]
ACCEPT = 1e-8
#: Newton iterations per stiffness update (a load near the smallest accepted with a clearance of
#: about A takes up to some hundreds). [-]
MAX_ITERATIONS = 2000
#: A case near equilibrium (residual below STALL_BELOW) whose residual has not halved in STALL
#: iterations has reached its rounding. [-]
STALL = 12
STALL_BELOW = 1e-9
#: A residual within this times the sum of the magnitudes of its terms is their rounding. [-]
#: 8 eps: the campaign (tests/campaign_combined.py, 3000 cases, seed 1) then balances every
#: component whose terms stay below 1e3 times its load to <= 9.9e-13 of that load (64 eps
#: allowed 3.2e-12 there), with the same cases solved, none failing, in the same time.
ROUNDING = 8.0 * float(np.finfo(float).eps)
#: A component without an applied load is measured against the rounding of its terms or, where
#: those vanish with it at the answer, this times the largest applied load. [-]
FLOOR = 1e-6
#: Dekker's splitting constant 2^27 + 1 (exact products of doubles). [-]
SPLITTER = 134217729.0
#: The generalised-force columns (x, y, a, t, t_c).
X, Y, AX, T, TC = range(5)


# ------------------------------------------------------------------------ double-double pieces


def _two_sum(a: Any, b: Any) -> tuple[Any, Any]:
    """a + b as an unevaluated sum s + e, exactly (Knuth)."""
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _fast(s: Any, e: Any) -> tuple[Any, Any]:
    """Renormalise s + e (|s| >= |e|) to a double-double."""
    hi = s + e
    return hi, e - (hi - s)


def _split(a: Any) -> tuple[Any, Any]:
    t = SPLITTER * a
    hi = t - (t - a)
    return hi, a - hi


def _two_prod(a: Any, b: Any, bs: tuple[Any, Any] | None = None) -> tuple[Any, Any]:
    """a b as p + e, exactly (Dekker); ``bs``: the split of ``b`` if known."""
    p = a * b
    ah, al = _split(a)
    bh, bl = _split(b) if bs is None else bs
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def _dd_mul(ah: Any, al: Any, bh: Any, bl: Any) -> tuple[Any, Any]:
    p, e = _two_prod(ah, bh)
    return _fast(p, e + (ah * bl + al * bh))


# ------------------------------------------------------------------------------- the problem


@dataclass(frozen=True)
class Problem:
    """The scaled problem of n cases (every array has the cases on its first axis)."""

    z: int
    c: np.ndarray  # cos phi_j, (n, z)
    s: np.ndarray  # sin phi_j, (n, z)
    scale: np.ndarray  # s [mm], (n,)
    a_hat: np.ndarray  # A / s
    pre: np.ndarray  # preload approach p = max(-G_r/2, 0) / s
    gap: np.ndarray  # max(G_r/2, 0) / s
    b_hi: np.ndarray  # B = A + p, double-double
    b_lo: np.ndarray
    f: np.ndarray  # generalised forces of (x, y, a, t, t_c), (n, 5)
    t_imp: np.ndarray  # imposed R_i theta / s, (n,)
    locked: np.ndarray  # (n, 5) bool: held (imposed tilt, or 0 by symmetry)
    imposed: np.ndarray  # (n, 5) bool: held by an imposed tilt (its moment is a reaction)
    f_ref: np.ndarray  # F [N]
    k_ref: np.ndarray  # K_0 [N/mm^1.5]
    one_sided: np.ndarray  # (n,) bool: angular contact, a ball with u_j < 0 is at 0° (see below)

    @staticmethod
    def make(z: int, directions: tuple[np.ndarray, np.ndarray], lengths: tuple[np.ndarray, ...],
             **rest: Any) -> Problem:  # fmt: skip
        """``directions`` = cos, sin of the ball angles (n, z); ``lengths`` = (A, G_r/2) [mm];
        ``rest``: f, t_imp [mm], locked, imposed, f_ref, k_ref, optionally one_sided (n,) bool
        (default none: deep groove; the scale s = (F/K)^(2/3) follows)."""
        big_a, g = lengths
        scale = (rest["f_ref"] / rest["k_ref"]) ** (2.0 / 3.0)
        c, s = directions
        c = np.where(np.abs(c) < 1e-15, 0.0, c)
        s = np.where(np.abs(s) < 1e-15, 0.0, s)
        a_hat = big_a / scale
        pre = np.maximum(-g, 0.0) / scale
        b_hi, b_lo = _two_sum(a_hat, pre)
        t_imp = rest.pop("t_imp") / scale
        rest.setdefault("one_sided", np.zeros(np.shape(scale), dtype=bool))
        return Problem(z, c, s, scale, a_hat, pre, np.maximum(g, 0.0) / scale, b_hi, b_lo,
                       t_imp=t_imp, **rest)  # fmt: skip

    def take(self, idx: np.ndarray) -> Problem:
        """The cases ``idx`` only."""
        out = {}
        for field in dataclasses.fields(self):
            value = getattr(self, field.name)
            if isinstance(value, np.ndarray):
                value = value[idx]
            out[field.name] = value
        return Problem(**out)

    @functools.cached_property
    def arms(self) -> np.ndarray:
        """The factors of the ball forces in the generalised ones, ``(c, s, 1, c, s)`` per ball
        (n, 5, z)."""
        return np.stack([self.c, self.s, np.ones_like(self.c), self.c, self.s], axis=1)

    @property
    def deviation(self) -> np.ndarray:
        """Cases whose forces are summed from the preloaded reference, (n,) bool."""
        return (self.pre > 0) & (self.z >= 2)


@dataclass(frozen=True)
class Balls:
    """The geometry of every ball at one ring position, (n, z) each."""

    rho: np.ndarray  # radial separation of the groove centres
    u: np.ndarray  # axial separation
    d: np.ndarray  # |(max(rho, 0), u')|
    eps: np.ndarray  # d - B, to the last digits
    up: np.ndarray  # u' = the axial separation the contact sees: u, or max(u, 0) one-sided

    def take(self, idx: np.ndarray) -> Balls:
        return Balls(*(getattr(self, k)[idx] for k in _BALL_FIELDS))

    def put(self, mask: np.ndarray, other: Balls) -> Balls:
        """These balls, with the rows ``mask`` from ``other``."""
        m = mask[:, None]
        return Balls(*(np.where(m, getattr(other, k), getattr(self, k)) for k in _BALL_FIELDS))


_BALL_FIELDS = ("rho", "u", "d", "eps", "up")


def reference(p: Problem, vh: np.ndarray, vl: np.ndarray) -> Balls:
    """Every ball at the position ``vh + vl`` (n, 5), in double-double arithmetic.

    ``d^2 - B^2 = m (m + 2B) + u^2`` with ``m = rho - B = x c + y s - max(G_r/2, 0)``: with the
    products exact and the sums carried, the approach keeps its digits when ``x`` and ``a`` are
    millions of times the approach (a clearance near 2A), and the result is a function of the
    position alone.
    """
    c_hi, c_lo = _split(p.c)
    s_hi, s_lo = _split(p.s)
    col = [(vh[:, i, None], vl[:, i, None]) for i in range(5)]
    r1 = _two_prod(col[X][0], p.c, (c_hi, c_lo))
    r2 = _two_prod(col[Y][0], p.s, (s_hi, s_lo))
    r, e = _two_sum(r1[0], r2[0])
    m, e2 = _two_sum(r, -p.gap[:, None])
    m_hi, m_lo = _fast(m, e2 + e + r1[1] + r2[1] + col[X][1] * p.c + col[Y][1] * p.s)
    n_hi, e = _two_sum(m_hi, 2.0 * p.b_hi[:, None])
    n_hi, n_lo = _fast(n_hi, e + m_lo + 2.0 * p.b_lo[:, None])
    t_hi, t_lo = _two_sum(col[T][0], p.t_imp[:, None])
    u1 = _two_prod(t_hi, p.c, (c_hi, c_lo))
    u2 = _two_prod(col[TC][0], p.s, (s_hi, s_lo))
    u, e = _two_sum(col[AX][0], u1[0])
    u, e2 = _two_sum(u, u2[0])
    tail = e + e2 + u1[1] + u2[1] + col[AX][1] + (t_lo + col[T][1]) * p.c + col[TC][1] * p.s
    u_hi, u_lo = _fast(u, tail)
    ud = u_hi + u_lo
    if p.one_sided.any():  # angular contact: the ball sees max(u, 0) (module notes)
        cut = p.one_sided[:, None] & (u_hi < 0)
        u_hi, u_lo = np.where(cut, 0.0, u_hi), np.where(cut, 0.0, u_lo)
    mn = _dd_mul(m_hi, m_lo, n_hi, n_lo)
    uu = _dd_mul(u_hi, u_lo, u_hi, u_lo)
    d2, e = _two_sum(mn[0], uu[0])
    d2 = d2 + (e + mn[1] + uu[1])
    rho, e = _two_sum(p.b_hi[:, None], m_hi)
    rho = rho + (e + p.b_lo[:, None] + m_lo)
    up = u_hi + u_lo
    d = np.hypot(np.maximum(rho, 0.0), up)
    b = p.b_hi[:, None]
    # at the groove edge (rho <= 0) d = |u|: |u| - B from the double-double u, not from ud
    sign = np.where(u_hi < 0, -1.0, 1.0)
    edge, e = _two_sum(sign * u_hi, -b)
    edge = edge + (e + sign * u_lo - p.b_lo[:, None])
    eps = np.where(rho > 0, d2 / (d + b), edge)
    return Balls(rho, ud, d, eps, up)


def offset(p: Problem, ref: Balls, w: np.ndarray) -> tuple[Balls, np.ndarray, np.ndarray]:
    """The balls after a (small) move ``w`` (n, 5) from ``ref``; also ``d - d_ref`` and
    ``(d - d_ref) - (rho - rho_ref)``, both from the move itself (``d^2 - d_ref^2 = dr (rho_ref
    + rho) + du (u_ref + u)``), so that a step far below the rounding of ``u_ref`` still counts.
    """
    dr = w[:, X, None] * p.c + w[:, Y, None] * p.s
    du = w[:, AX, None] + w[:, T, None] * p.c + w[:, TC, None] * p.s
    rho, u = ref.rho + dr, ref.u + du
    rp, rp_ref = np.maximum(rho, 0.0), np.maximum(ref.rho, 0.0)
    up, up_ref = u, ref.up
    uu = du * (ref.u + u)
    if p.one_sided.any():  # max(u, 0) where one-sided; the difference formula where both > 0
        cut = p.one_sided[:, None]
        up = np.where(cut, np.maximum(u, 0.0), u)
        uu = np.where(cut & ~((u > 0) & (ref.u > 0)), up * up - up_ref * up_ref, uu)
    d = np.hypot(rp, up)
    both = (rho > 0) & (ref.rho > 0)
    den = d + ref.d
    den = np.where(den > 0, den, 1.0)
    dd = (np.where(both, dr * (ref.rho + rho), rp * rp - rp_ref * rp_ref) + uu) / den
    # d - rho = u^2 / (d + rho): the change of that is the part of dd not in dr
    w_new = up * up / np.where(both, d + rho, 1.0)
    w_ref = up_ref * up_ref / np.where(both, ref.d + ref.rho, 1.0)
    ddr = np.where(both, (uu - dr * (w_ref + w_new)) / den, dd - dr)
    return Balls(rho, u, d, ref.eps + dd, up), dd, ddr


# ----------------------------------------------------------------------------------- forces


@dataclass(frozen=True)
class Loads:
    """Ball loads and directions at one position, (n, z) each; ``q0`` (n,)."""

    ca: np.ndarray  # cos(alpha)
    sa: np.ndarray  # sin(alpha)
    cam1: np.ndarray  # cos(alpha) - 1, without cancellation
    q: np.ndarray  # (1 + kappa) delta^1.5
    dq: np.ndarray  # q - q0
    root: np.ndarray  # sqrt(max(delta, 0))
    tau: np.ndarray  # (delta - p)/p on the deviation cases, else 0
    sig: np.ndarray  # sqrt(1 + tau) - 1
    q0: np.ndarray  # p^1.5 on the deviation cases, else 0


def loads(p: Problem, b: Balls, kappa: np.ndarray) -> Loads:
    """Ball loads (scaled, frozen stiffness ``1 + kappa``) and their directions."""
    rp = np.maximum(b.rho, 0.0)
    pos_d = b.d > 0
    safe = np.where(pos_d, b.d, 1.0)
    ca = np.where(pos_d, rp / safe, 1.0)
    sa = np.where(pos_d, b.up / safe, 0.0)
    cam1 = np.where(b.rho > 0, -sa * sa / (1.0 + ca), ca - 1.0)
    pre = p.pre[:, None]
    delta = pre + b.eps
    touch = delta > 0
    pos = np.where(touch, delta, 0.0)
    root = np.sqrt(pos)
    k = 1.0 + kappa
    q = k * pos * root
    dev = p.deviation
    q0 = np.where(dev, p.pre * np.sqrt(p.pre), 0.0)
    if not dev.any():  # no preload in this call: the deviations are the loads
        zero = np.zeros_like(q)
        return Loads(ca, sa, cam1, q, q, root, zero, zero, q0)
    tau = np.where(dev[:, None], b.eps / np.where(pre > 0, pre, 1.0), 0.0)
    sig = tau / (1.0 + np.sqrt(np.maximum(1.0 + tau, 0.0)))
    change = q0[:, None] * np.where(touch, k * (tau + sig + tau * sig) + kappa, -1.0)
    return Loads(ca, sa, cam1, q, np.where(dev[:, None], change, q), root, tau, sig, q0)


def forces(p: Problem, lo: Loads) -> tuple[np.ndarray, np.ndarray]:
    """The generalised ball forces on the ring, ``sum_j (q_j - q_0) g_j + q_0 sum_j g'_j`` (see
    the module notes), and the sum of the magnitudes of the terms of each (its rounding level
    over eps), (n, 5) each."""
    q0 = lo.q0[:, None]
    radial = lo.dq * lo.ca + q0 * lo.cam1
    axial = (lo.dq + q0) * lo.sa
    gen = sum_arms(radial, axial, p.arms)
    w_r = np.abs(lo.dq * lo.ca) + q0 * np.abs(lo.cam1)
    w_a = (np.abs(lo.dq) + q0) * np.abs(lo.sa)
    return gen, sum_arms(w_r, w_a, np.abs(p.arms))


def _times_arms(radial: np.ndarray, axial: np.ndarray, arms: np.ndarray) -> np.ndarray:
    """``(radial c, radial s, axial, axial c, axial s)`` per ball, (n, z, 5) contiguous."""
    terms = np.empty(arms.shape)
    terms[:, :2] = radial[:, None]
    terms[:, 2:] = axial[:, None]
    terms *= arms
    return np.ascontiguousarray(terms.transpose(0, 2, 1))


def sum_arms(radial: np.ndarray, axial: np.ndarray, arms: np.ndarray) -> np.ndarray:
    """``sum_j (radial_j c_j, radial_j s_j, axial_j, axial_j c_j, axial_j s_j)`` (n, 5), the
    products formed in one array (the same sums, term by term, as five apart)."""
    terms = np.empty(arms.shape)
    terms[:, :2] = radial[:, None]
    terms[:, 2:] = axial[:, None]
    terms *= arms
    return np.add.reduce(terms, axis=2)


def residual(p: Problem, gen: np.ndarray, size: np.ndarray, held: np.ndarray) -> np.ndarray:
    """Per case, the largest residual of a component not ``held`` (n, 5), each over its applied
    load or, where larger, the rounding level of its terms (ROUNDING times the sum of their
    magnitudes) over TOLERANCE: so at most TOLERANCE means each component balanced to 1e-12 of
    its load, or to the rounding of the sum it is (its terms 100 times the load, say, under an
    imposed tilt). A component without an applied load is also measured against FLOOR times
    the largest load (1 scaled): its terms may vanish at the answer with its residual. [-]"""
    return residual_of(p.f, gen, size, held)


def residual_of(f: np.ndarray, gen: np.ndarray, size: np.ndarray, held: np.ndarray) -> np.ndarray:
    """:func:`residual` of the applied forces ``f`` (n, 5) (the cases of a problem, taken or
    not)."""
    grad = np.where(held, 0.0, gen - f)
    ref = np.maximum(np.abs(f), (ROUNDING / TOLERANCE) * size)
    ref = np.where(f == 0, np.maximum(ref, FLOOR), ref)
    return np.max(np.abs(grad) / ref, axis=1)


def hessian(p: Problem, b: Balls, lo: Loads, kappa: np.ndarray) -> np.ndarray:
    """d(forces)/dv (n, 5, 5) with the held components decoupled (unit rows)."""
    w1 = 1.5 * (1.0 + kappa) * lo.root
    w2 = np.where(turns(b.rho, b.u, p.one_sided), lo.q / np.where(b.d > 0, b.d, 1.0), 0.0)
    return hold(ball_tangent(p.arms, lo.ca, lo.sa, w1, w2), p.locked)


def ball_tangent(
    arms: np.ndarray, ca: np.ndarray, sa: np.ndarray, w1: np.ndarray, w2: np.ndarray,
    w3: np.ndarray | None = None,
) -> np.ndarray:  # fmt: skip
    """``sum_j w1 g g^T + w2 h h^T (+ w3 g h^T)`` (n, 5, 5): ``g_j`` the generalised direction of
    ball j's contact normal ``(ca c, ca s, sa, sa c, sa s)``, ``h_j`` the direction in which it
    turns (``ca``, ``sa`` replaced by ``-sa``, ``ca``); ``arms`` (n, 5, z) of :class:`Problem`.
    With ``w1 = dQ/d(delta)``, ``w2 = Q/d`` and ``w3 = dQ/d(alpha)/d`` the tangent of the ring
    forces."""
    g = _times_arms(ca, sa, arms)
    h = _times_arms(-sa, ca, arms)
    # one stacked product (n, 5, 2z) @ (n, 2z, 5): a three-operand einsum is 4-5 times slower
    both = np.concatenate((g, h), axis=1)
    weighted = np.concatenate((g * w1[:, :, None], h * w2[:, :, None]), axis=1)
    t = weighted.transpose(0, 2, 1) @ both
    if w3 is not None:
        t += (g * w3[:, :, None]).transpose(0, 2, 1) @ h
    return t


def hold(hess: np.ndarray, locked: np.ndarray) -> np.ndarray:
    """``hess`` (n, 5, 5) with the ``locked`` components (n, 5) decoupled: unit rows and
    columns (in place)."""
    free = ~locked
    hess *= free[:, :, None] & free[:, None, :]
    hess += np.eye(5) * locked[:, None, :]
    return hess


def turns(rho: np.ndarray, u: np.ndarray, one_sided: np.ndarray) -> np.ndarray:
    """Balls whose contact normal turns with the ring (n, z): groove centres not crossed and,
    one-sided (``one_sided`` (n,)), ``u_j > 0`` (at ``u_j <= 0`` the ball sits at 0° whatever
    ``u_j``: no curvature across the groove)."""
    inside = rho > 0
    if one_sided.any():
        inside &= ~one_sided[:, None] | (u > 0)
    return inside


def _excess(tau: np.ndarray, sig: np.ndarray) -> np.ndarray:
    """(1 + tau)_+^2.5 - 1 - 2.5 tau without cancellation (sig = sqrt(1 + tau) - 1)."""
    inside = -0.5 * sig * sig + 2.0 * tau * sig + tau * tau * (1.0 + sig)
    return np.where(tau > -1.0, inside, -1.0 - 2.5 * tau)


def energy_change(
    p: Problem, kappa: np.ndarray, lr: Loads, lo: Loads, steps: tuple[np.ndarray, ...]
) -> np.ndarray:
    """Potential at a trial position less that at the reference, (n,); ``steps`` = (w,
    d - d_ref, (d - d_ref) - (rho - rho_ref)) of the move (:func:`offset`). On the deviation
    cases ``q_0 sum_j (rho_j - rho_ref,j)``, 0 around the ring, is left out of the sum, and the
    rest is ``sum_j (1 + kappa_j) [q_0 (d_j - d_ref,j) + p^2.5/2.5 (X(tau_j) - X(tau_ref,j))]``
    with ``X(tau) = (1 + tau)^2.5 - 1 - 2.5 tau``."""
    w, dd, ddr = steps
    dev = p.deviation
    work = (p.f * w).sum(1)
    deviation = np.zeros_like(work)
    if dev.any():
        pre = np.where(dev, p.pre, 1.0)
        linear = lo.q0 * (ddr + kappa * dd).sum(1)
        bend = ((1.0 + kappa) * (_excess(lo.tau, lo.sig) - _excess(lr.tau, lr.sig))).sum(1)
        deviation = linear + pre * pre * np.sqrt(pre) / 2.5 * bend
        if dev.all():
            return deviation - work
    # without preload: K/2.5 (delta^2.5 - delta_ref^2.5) = K delta_ref^2.5 (2.5 r + X(r))/2.5,
    # r = dd/delta_ref, for a ball in contact at both positions (a difference otherwise)
    pos_ref = lr.root * lr.root
    both = (lr.root > 0) & (lo.root > 0)
    r = dd / np.where(both, pos_ref, 1.0)
    sig = r / (1.0 + np.sqrt(np.maximum(1.0 + r, 0.0)))
    kd = lr.q * pos_ref  # K delta_ref^2.5
    change = np.where(both, kd * (r + _excess(r, sig) / 2.5), (lo.q * lo.root**2 - kd) / 2.5)
    return np.where(dev, deviation, change.sum(1)) - work


# ------------------------------------------------------------------------------- the Newton


@dataclass
class Point:
    """The balls, loads, generalised forces, term sizes and residual at the positions of some
    cases (the rows of every array), and how many steps they were carried along by
    :func:`offset` since :func:`reference` computed them."""

    b: Balls
    lo: Loads
    gen: np.ndarray
    size: np.ndarray
    res: np.ndarray
    age: np.ndarray

    @staticmethod
    def at(q: Problem, kappa: np.ndarray, b: Balls, age: int = 0) -> Point:
        lo = loads(q, b, kappa)
        gen, size = forces(q, lo)
        res = residual(q, gen, size, q.locked)
        return Point(b, lo, gen, size, res, np.full(res.shape, age, dtype=np.int64))

    def take(self, rows: np.ndarray) -> Point:
        return Point(self.b.take(rows), _take_loads(self.lo, rows), self.gen[rows],
                     self.size[rows], self.res[rows], self.age[rows])  # fmt: skip

    def put(self, rows: np.ndarray, other: Point) -> None:
        """Overwrite the rows ``rows`` with ``other`` (in place)."""
        for name in _BALL_FIELDS:
            getattr(self.b, name)[rows] = getattr(other.b, name)
        for name in _LOAD_FIELDS:
            getattr(self.lo, name)[rows] = getattr(other.lo, name)
        for name in ("gen", "size", "res", "age"):
            getattr(self, name)[rows] = getattr(other, name)


#: Steps a point is carried by the difference formulas before it is recomputed afresh. [-]
REFRESH = 8


def minimise(
    p: Problem,
    vh: np.ndarray,
    vl: np.ndarray,
    kappa: np.ndarray,
    start: Point | None = None,
    polish: bool = False,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, Point]:
    """Damped Newton with an Armijo line search on the convex potential (stiffness ``1 +
    kappa`` frozen): each case until every free component is within TOLERANCE (see
    :func:`residual`) or its residual stops falling (rounding). The point a step reaches is
    the line search's trial (:func:`offset` from the last); a case is recomputed afresh in
    double-double (:func:`reference`) every REFRESH steps and before it counts as converged.
    ``start``: the point at ``(vh, vl)`` if the caller has it (``Point.at`` of
    :func:`reference` there, as computed here otherwise). Returns the position (hi, lo), the
    iterations per case and the point there (fresh); the caller checks the residual."""
    vh, vl = vh.copy(), vl.copy()
    iterations = np.zeros(vh.shape[0], dtype=np.int64)
    active = np.arange(vh.shape[0])
    q, ka = p, kappa
    pt = Point.at(q, ka, reference(q, vh, vl)) if start is None else start
    best = np.full(active.size, np.inf)
    stall = np.zeros(active.size, dtype=np.int64)
    slow = np.zeros(active.size, dtype=bool)
    ends: list[tuple[np.ndarray, Point, np.ndarray]] = []
    for k in range(MAX_ITERATIONS):
        old = np.flatnonzero(((pt.res <= TOLERANCE) & (pt.age > 0)) | (pt.age >= REFRESH))
        if old.size == active.size:  # all of them: no copies
            pt = Point.at(q, ka, reference(q, vh[active], vl[active]))
        elif old.size:
            sub = q.take(old)
            pt.put(old, Point.at(sub, ka[old], reference(sub, vh[active[old]], vl[active[old]])))
        better = (pt.res < 0.5 * best) | (pt.res > STALL_BELOW)
        best = np.where(better, pt.res, best)
        stall = np.where(better, 0, stall + 1)
        stop = ((pt.res <= TOLERANCE) & (k > 0 or not polish)) | (stall >= STALL)
        stop |= ~np.isfinite(pt.res)
        if stop.all():  # (no step: the position and the point stay)
            ends.append((active, pt, pt.age == 0))
            break
        grad = np.where(q.locked, 0.0, pt.gen - q.f)
        step, hess = _newton_step(q, pt.b, pt.lo, ka, grad, stop)
        before = pt.res.copy()  # the line search may change pt in place
        moved, pt = _line_search(q, ka, pt, (step, hess), grad, slow)
        slow = pt.res > 0.9 * before
        still = ~np.any(moved != 0.0, axis=1)
        stop |= still & (pt.age == 0)  # no step from a fresh point: rounding
        if stop.any():
            ends.append((active[stop], pt.take(np.flatnonzero(stop)), pt.age[stop] == 0))
        pt.age[still] = REFRESH  # no step from a carried point: recompute it first
        hi, lo_ = _two_sum(vh[active], moved)
        vh[active], vl[active] = _fast(hi, lo_ + vl[active])
        iterations[active[~stop]] += 1
        keep = np.flatnonzero(~stop)
        if not keep.size:
            break
        if keep.size < active.size:
            active, q, ka, pt = active[keep], q.take(keep), ka[keep], pt.take(keep)
            best, stall, slow = best[keep], stall[keep], slow[keep]
    return vh, vl, iterations, _ended(p, kappa, vh, vl, ends)


def _ended(
    p: Problem, kappa: np.ndarray, vh: np.ndarray, vl: np.ndarray, ends: list[tuple[Any, ...]]
) -> Point:
    """The point of every case at its final position: where the minimisation stopped at a fresh
    point (:func:`reference` there), that one; the others recomputed afresh."""
    n = vh.shape[0]
    fresh = np.zeros(n, dtype=bool)
    if len(ends) == 1 and ends[0][0].size == n and ends[0][2].all():
        rows, pt, _ = ends[0]
        if np.array_equal(rows, np.arange(n)):
            return pt
    for rows, _, is_fresh in ends:
        fresh[rows[is_fresh]] = True
    redo = np.flatnonzero(~fresh)
    if redo.size == n:
        return Point.at(p, kappa, reference(p, vh, vl))
    first = ends[0][1]
    out = Point(
        Balls(*(np.empty((n,) + getattr(first.b, k).shape[1:]) for k in _BALL_FIELDS)),
        Loads(*(np.empty((n,) + getattr(first.lo, k).shape[1:]) for k in _LOAD_FIELDS)),
        np.empty((n, 5)), np.empty((n, 5)), np.empty(n), np.zeros(n, dtype=np.int64),
    )  # fmt: skip
    for rows, pt, is_fresh in ends:
        keep = np.flatnonzero(is_fresh)
        out.put(rows[keep], pt.take(keep))
    if redo.size:
        sub = p.take(redo)
        out.put(redo, Point.at(sub, kappa[redo], reference(sub, vh[redo], vl[redo])))
    return out


def _newton_step(
    q: Problem, cur: Balls, lo: Loads, kappa: np.ndarray, grad: np.ndarray, stop: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The Newton step (regularised) and the Hessian it solved; for a ring that touches no
    ball, the step to the first contact (:func:`_to_contact`); 0 where the case has stopped."""
    hess = hessian(q, cur, lo, kappa)
    trace = np.trace(hess, axis1=1, axis2=2)
    hess += (1e-13 * trace + 1e-300)[:, None, None] * np.eye(5)
    step = cap_step(q, -np.linalg.solve(hess, grad[:, :, None])[:, :, 0])
    loose = np.flatnonzero(~(trace > q.locked.sum(1)) & ~stop)  # no ball in contact
    if loose.size:  # Newton has no curvature there: move along the load to the first contact
        step[loose] = cap_step(
            q, _to_contact(q.take(loose), cur.take(loose), _take_loads(lo, loose)), loose
        )
    return np.where(stop[:, None], 0.0, step), hess


def cap_step(p: Problem, step: np.ndarray, rows: Any = slice(None)) -> np.ndarray:
    """One-sided cases: the step shortened so that no axial part (a, t, t_c) exceeds A. A ball
    at u_j < 0 has no stiffness along the groove, so with few balls in contact the Newton matrix
    may be singular along a move that lifts the others further off (its regularised step then
    goes 1e13 times the force out and takes thousands of steps to come back); an equilibrium
    lies within a few A of any start (a loaded ball has |u_j| < A). Deep-groove cases: as is."""
    one = p.one_sided[rows]
    if not one.any():
        return step
    longest = np.max(np.abs(step[:, 2:]), axis=1)
    a_hat = p.a_hat[rows]
    shrink = np.where(one & (longest > a_hat), a_hat / np.where(longest > 0, longest, 1.0), 1.0)
    return step * shrink[:, None]


def _take_loads(lo: Loads, idx: np.ndarray) -> Loads:
    return Loads(*(getattr(lo, name)[idx] for name in _LOAD_FIELDS))


_LOAD_FIELDS = ("ca", "sa", "cam1", "q", "dq", "root", "tau", "sig", "q0")


def _line_search(
    q: Problem,
    kappa: np.ndarray,
    pt: Point,
    newton: tuple[np.ndarray, np.ndarray],
    grad: np.ndarray,
    slow: np.ndarray,
) -> tuple[np.ndarray, Point]:
    """The move (n, 5) and the point it reaches: ``t`` times the step, t = 1, then (if that fails and a ball not in
    contact would be reached before) just past the first contact along the step, then halved,
    until the potential falls (Armijo) or the residual halves. On the ``slow`` cases (the last
    step took off less than a tenth of the residual), a trial that fails or does the same is
    tried once more with a second-order correction (``-H^-1`` times the forces left at the
    trial). ``pt`` may be changed in place.

    The first contact matters along a direction the balls in contact do not resist (a ring
    sliding in its clearance): the regularised Newton step there is a fixed length, and halving
    it only would approach the next contact geometrically. The correction matters where the
    path is an arc (a ring rolling a ball along its groove, radius A, about millions of elastic
    approaches): a straight step leaves the arc by s^2/(2A), into the stiff direction.
    """
    step, hess = newton
    slope = (grad * step).sum(1)
    t = np.ones(step.shape[0])
    moved = np.zeros_like(step)
    res = pt.res.copy()
    pending = np.flatnonzero(np.any(step != 0.0, axis=1))
    for k in range(60):
        if not pending.size:
            break
        part = _part(q, kappa, pt, pending)
        w = t[pending, None] * step[pending]
        drop_min = t[pending] * slope[pending]
        ok, trial = _accept(part, w, drop_min, res[pending])
        # corrected where the trial fails or leaves more than 90 % of the residual, again
        retry = np.flatnonzero(slow[pending] & (~ok | (trial.res > 0.9 * res[pending])))
        if retry.size:
            sub = _part(*part, retry)
            left = np.where(sub[0].locked, 0.0, trial.gen[retry] - sub[0].f)
            fix = -np.linalg.solve(hess[pending[retry]], left[:, :, None])[:, :, 0]
            fix = cap_step(sub[0], fix)
            ok2, trial2 = _accept(sub, w[retry] + fix, drop_min[retry], res[pending[retry]], True)
            better = ok2 & (~ok[retry] | (trial2.drop < trial.drop[retry]))
            w[retry[better]] += fix[better]
            ok[retry[better]] = True
            trial.put(retry[better], trial2.take(np.flatnonzero(better)))
        moved[pending[ok]] = w[ok]
        if ok.all() and pending.size == step.shape[0]:
            return moved, trial  # every case took its first trial: that is the new point
        pt.put(pending[ok], trial.take(np.flatnonzero(ok)))
        pending = pending[~ok]
        if k == 0 and pending.size:  # just past the first contact along the step, or half
            sub = _part(q, kappa, pt, pending)
            t[pending] = np.minimum(0.5, _first_contact(sub[0], sub[2].b, sub[2].lo, step[pending]))
        else:
            t[pending] *= 0.5
    return moved, pt


Part = tuple[Problem, np.ndarray, Point]


def _part(q: Problem, kappa: np.ndarray, pt: Point, rows: np.ndarray) -> Part:
    """The cases ``rows`` of a problem, its stiffness and its point (all of them as they are)."""
    if rows.size == q.f.shape[0]:
        return q, kappa, pt
    return q.take(rows), kappa[rows], pt.take(rows)


@dataclass
class _Trial(Point):
    drop: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros(0))

    def take(self, rows: np.ndarray) -> _Trial:
        p = Point.take(self, rows)
        return _Trial(p.b, p.lo, p.gen, p.size, p.res, p.age, self.drop[rows])

    def put(self, rows: np.ndarray, other: Point) -> None:
        Point.put(self, rows, other)
        if isinstance(other, _Trial):
            self.drop[rows] = other.drop


def _accept(
    part: Part, w: np.ndarray, drop_min: np.ndarray, res: np.ndarray, need_drop: bool = False
) -> tuple[Any, ...]:
    """Whether the move ``w`` is taken (the residual halves, or the potential falls by 1e-4 of
    ``drop_min``), and the point there with the change of the potential, ``drop`` (0 where not
    needed: every residual halves, unless ``need_drop``)."""
    q, kappa, pt = part
    b, dd, ddr = offset(q, pt.b, w)
    lt = loads(q, b, kappa)
    gen, size = forces(q, lt)
    left = residual(q, gen, size, q.locked)
    ok = left < 0.5 * res
    drop = np.zeros_like(left)  # (not needed where the residual halves)
    if need_drop or not ok.all():
        drop = energy_change(q, kappa, pt.lo, lt, (w, dd, ddr))
        drop = np.where(np.isfinite(drop), drop, np.inf)
        ok |= drop <= 1e-4 * drop_min
    ok &= np.any(w != 0.0, axis=1)
    return ok, _Trial(b, lt, gen, size, left, pt.age + 1, drop)


def _first_contact(q: Problem, cur: Balls, lo: Loads, step: np.ndarray) -> np.ndarray:
    """Per case, the step fraction (to first order, 1.001 times it) at which the first ball not
    in contact would touch when moving along ``step``; 1 where none would before the full step."""
    delta = q.pre[:, None] + cur.eps
    dr = step[:, X, None] * q.c + step[:, Y, None] * q.s
    du = step[:, AX, None] + step[:, T, None] * q.c + step[:, TC, None] * q.s
    rate = lo.ca * dr + lo.sa * du  # d(delta_j)/dt
    with np.errstate(divide="ignore", invalid="ignore"):
        reach = np.where((rate > 0) & (delta < 0), -delta / rate, np.inf)
    return np.minimum(1.001 * np.min(reach, axis=1), 1.0)


def _to_contact(p: Problem, b: Balls, lo: Loads) -> np.ndarray:
    """For rings that touch no ball: the step along the generalised load (the potential falls
    along it while no ball is loaded) that brings the nearest ball, to first order, a little
    into contact; zero where no ball comes nearer that way."""
    delta = p.pre[:, None] + b.eps
    direction = np.where(p.locked, 0.0, p.f)
    direction /= np.maximum(np.linalg.norm(direction, axis=1, keepdims=True), 1e-300)
    c, s, ca, sa = p.c, p.s, lo.ca, lo.sa
    rate = (ca * c * direction[:, X, None] + ca * s * direction[:, Y, None]
            + sa * direction[:, AX, None] + sa * c * direction[:, T, None]
            + sa * s * direction[:, TC, None])  # fmt: skip
    with np.errstate(divide="ignore", invalid="ignore"):
        reach = np.where(rate > 0, -delta / rate, np.inf)
    t = np.min(reach, axis=1)
    t = np.where(np.isfinite(t), 1.001 * t + 1e-9, 0.0)
    return direction * t[:, None]
