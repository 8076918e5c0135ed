"""Internals of the combined-load solver (:mod:`bearingload.models.combined`): the scaled problem
and the balls at a ring position as the compiled core (:mod:`bearingload.models._core`, one C
call per case) computes them, for the set-up and the results of a solve and for the pair's
solver; the core's kernels evaluate the ball geometry to the last digit and the ring forces in
deviation form, with the formulas this docstring states.

Scaled units: lengths over ``s = (F/K)^(2/3)``, forces over ``F`` (the largest applied load).
Unknowns ``v = (x, y, a, t, t_c)``, ``t = R_i theta / s``. Ball ``j`` at ``phi_j``
(``c_j, s_j`` its cosine and sine): ``rho_j = A - g + x c_j + y s_j``, ``u_j = a + (t + t_imp)
c_j + t_c s_j``, ``d_j = |(max(rho_j, 0), u_j)|``, approach ``delta_j = d_j - A``.

Why each piece keeps its digits:

* Position. The state is a pair ``(hi, lo)`` per unknown (a double-double): with a clearance of
  up to 2A, ``x`` is up to ``2e7`` elastic approaches, and one double resolves it only to
  ``eps |x|``, a force error of about 1e-9 of the load. The core's ``reference`` evaluates every ball
  at such a point in double-double arithmetic (Dekker's exact products), so the approach
  ``d - B`` (``B = A + p``, ``p`` the preload approach) comes out to about ``eps`` of itself
  however large the lengths it is the difference of; its ``offset`` moves from there by a small
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
from dataclasses import dataclass
from typing import Any

import numpy as np

# the tolerances are the compiled core's (one copy; its module says why each)
from bearingload.models import _core
from bearingload.models._core import (  # noqa: F401
    FIRST_STAGE_STEPS,
    FLOOR,
    MAX_ITERATIONS,
    ROUNDING,
    TOLERANCE,
    Status,
)

#: The status of a case the core solved. [-]
OK = int(Status.OK)
#: Largest relative residual accepted at the end (above it the caller raises). [-]
ACCEPT = 1e-8


# ------------------------------------------------------------------------ double-double pieces


def two_sum(a: Any, b: Any) -> tuple[Any, Any]:
    """a + b as an unevaluated sum s + e, exactly (Knuth)."""
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def fast_two_sum(s: Any, e: Any) -> tuple[Any, Any]:
    """Renormalise s + e (|s| >= |e|) to a double-double."""
    hi = s + e
    return hi, e - (hi - s)


# ------------------------------------------------------------------------------- the problem


@dataclass
class Problem:
    """The scaled problem of n cases (every array has the cases on its first axis, but
    ``lengths``, which has them on its second: a row each, as the compiled core takes them)."""

    z: int
    c: np.ndarray  # cos phi_j, (n, z)
    s: np.ndarray  # sin phi_j, (n, z)
    scale: np.ndarray  # s [mm], (n,)
    lengths: np.ndarray  # (6, n): a_hat, pre, gap, B = A + p (double-double: hi, lo), t_imp
    f: np.ndarray  # generalised forces of (x, y, a, t, t_c), (n, 5)
    locked: np.ndarray  # (n, 5) bool: held (imposed tilt, or 0 by symmetry)
    imposed: np.ndarray  # (n, 5) bool: held by an imposed tilt (its moment is a reaction)
    f_ref: np.ndarray  # F [N]
    k_ref: np.ndarray  # K_0 [N/mm^1.5]
    one_sided: np.ndarray  # (n,) bool: angular contact, a ball with u_j < 0 is at 0° (see below)

    @property
    def a_hat(self) -> np.ndarray:
        """A / s."""
        return self.lengths[0]

    @property
    def pre(self) -> np.ndarray:
        """The preload approach p = max(-G_r/2, 0) / s."""
        return self.lengths[1]

    @property
    def gap(self) -> np.ndarray:
        """max(G_r/2, 0) / s."""
        return self.lengths[2]

    @property
    def t_imp(self) -> np.ndarray:
        """The imposed R_i theta / s."""
        return self.lengths[5]

    @staticmethod
    def make(z: int, directions: tuple[np.ndarray, np.ndarray], lengths: tuple[np.ndarray, ...],
             **rest: Any) -> Problem:  # fmt: skip
        """``directions`` = cos, sin of the ball angles (n, z); ``lengths`` = (A, G_r/2) [mm];
        ``rest``: f, t_imp [mm], locked, imposed, f_ref, k_ref, optionally one_sided (n,) bool
        (default none: deep groove; the scale s = (F/K)^(2/3) follows)."""
        scale = (rest["f_ref"] / rest["k_ref"]) ** (2.0 / 3.0)
        c, s, scaled = _core.scaled_problem(
            *(np.ascontiguousarray(v, dtype=float) for v in directions),
            *(np.ascontiguousarray(v, dtype=float) for v in (*lengths, scale, rest.pop("t_imp"))),
        )
        rest.setdefault("one_sided", np.zeros(np.shape(scale), dtype=bool))
        return Problem(z, c, s, scale, scaled, **rest)

    def take(self, idx: np.ndarray) -> Problem:
        """The cases ``idx`` only."""
        items = ((f.name, getattr(self, f.name)) for f in dataclasses.fields(self))
        out = {k: v[idx] if isinstance(v, np.ndarray) and k != "lengths" else v for k, v in items}
        out["lengths"] = np.ascontiguousarray(self.lengths[:, idx])  # (the cases its 2nd axis)
        return Problem(**out)


@dataclass
class Balls:
    """The geometry of every ball at one ring position, (n, z) each."""

    rho: np.ndarray  # radial separation of the groove centres
    u: np.ndarray  # axial separation
    d: np.ndarray  # |(max(rho, 0), u')|
    eps: np.ndarray  # d - B, to the last digits
    up: np.ndarray  # u' = the axial separation the contact sees: u, or max(u, 0) one-sided


# ----------------------------------------------------------------------------------- forces


@dataclass
class Loads:
    """Ball loads and directions at one position, (n, z) each."""

    ca: np.ndarray  # cos(alpha)
    sa: np.ndarray  # sin(alpha)
    cam1: np.ndarray  # cos(alpha) - 1, without cancellation
    q: np.ndarray  # (1 + kappa) delta^1.5
    dq: np.ndarray  # q - q0 (q0 = p^1.5 on the deviation cases, else 0)
    root: np.ndarray  # sqrt(max(delta, 0))
    tau: np.ndarray  # (delta - p)/p on the deviation cases, else 0
    sig: np.ndarray  # sqrt(1 + tau) - 1


def residual_of(f: np.ndarray, gen: np.ndarray, size: np.ndarray, held: np.ndarray) -> np.ndarray:
    """Per case, the largest residual of the forces ``gen`` against the applied ``f`` (n, 5)
    of a component not ``held``, each over its applied load or, where larger, the rounding
    level of its terms (ROUNDING times the sum of their magnitudes ``size``) over TOLERANCE: so
    at most TOLERANCE means each component balanced to 1e-12 of its load, or to the rounding of
    the sum it is (its terms 100 times the load, say, under an imposed tilt). A component
    without an applied load is also measured against FLOOR times the largest load (1 scaled):
    its terms may vanish at the answer with its residual. [-]"""
    return _core.residuals(
        *(np.ascontiguousarray(v, dtype=float) for v in (f, gen, size)),
        np.ascontiguousarray(held, dtype=np.uint8),
    )


# ----------------------------------------------------------------------------------- points


@dataclass
class Point:
    """The balls and their loads (``block``, (13, n, z): the arrays of :class:`Balls`, then of
    :class:`Loads`, as the compiled core gives them), the generalised forces, term sizes and
    residual at the positions of some cases (the rows of every array); ``checks``: the core's
    checks of a solve's answer (``solve``: the residual with the imposed components held (n,),
    whether a loaded ball may sit at the groove edge (n,)), None where not known (a point
    some of whose rows were replaced since: :meth:`put`)."""

    block: np.ndarray
    gen: np.ndarray
    size: np.ndarray
    res: np.ndarray
    checks: tuple[np.ndarray, np.ndarray] | None = None

    @property
    def b(self) -> Balls:
        """The balls (views of ``block``)."""
        return Balls(*self.block[:5])

    @property
    def lo(self) -> Loads:
        """Their loads (views of ``block``)."""
        return Loads(*self.block[5:])

    @staticmethod
    def at(q: Problem, kappa: np.ndarray, vh: np.ndarray, vl: np.ndarray) -> Point:
        """The point of the cases of ``q`` at ``vh + vl`` (n, 5), the stiffness deviations
        ``kappa`` (n, z): the compiled core's ``points`` (its ``reference``, ``loads`` and
        ``forces``, the same kernels as the solve's)."""
        balls, gen, size, res = _core.points(
            *(np.ascontiguousarray(v, dtype=float) for v in (q.c, q.s, q.lengths, q.f)),
            np.ascontiguousarray(q.locked, dtype=np.uint8),
            np.ascontiguousarray(q.one_sided, dtype=np.uint8),
            *(np.ascontiguousarray(v, dtype=float) for v in (vh, vl, kappa)),
        )
        return Point(balls, gen, size, res)

    def put(self, rows: np.ndarray, other: Point) -> None:
        """Overwrite the rows ``rows`` with ``other`` (in place); the checks are then not known."""
        self.block[:, rows] = other.block
        self.checks = None
        for name in ("gen", "size", "res"):
            getattr(self, name)[rows] = getattr(other, name)
