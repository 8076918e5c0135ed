"""Set-up of the ring-equilibrium engine: the tables of ball angles its core solver runs on.

Everything is in scaled units (lengths over the one-ball approach ``s = (F_r/K)^(1/m)``, forces
over ``F_r``; see :mod:`bearingload.models.equilibrium`). Two formulations keep the digits:

* clearance >= 0: the unknown ``(xi, eta)`` is the displacement from the reference position
  where the balls nearest the load line just touch; ball approach ``xi c + eta s - e_hat u``,
  ``u`` the ball's gap factor.
* preload (clearance < 0, z >= 2): the unknown is the displacement from the centred ring; ball
  approach ``p + xi c + eta s`` with ``p = -e_hat``, the ball forces summed as
  ``p^m ((1 + t)^m - 1)`` (the ``p^m`` terms cancel exactly around a full ring).

A symmetric cage (0 or half pitch) is half a ring, each angle with its multiplicity; a general
cage angle is the whole ring, given to the core as the table of ``cos``, ``sin`` of ``k pitch``
and turned there per case by the angle of the ball nearest the load line. The Newton solvers
are kernels of the compiled core (``_core.radial``; ``models/_radial.pxi``).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from bearingload import validate

EPS = float(np.finfo(float).eps)
#: Iteration cap of every Newton loop; reaching it raises ConvergenceError.
MAX_ITERATIONS = 200
#: At tolerances up to this the converged point gets one more Newton step (rounding level). [-]
POLISH = 1e-13
#: Preloads |e|/s above this are solved from the centred ring (below, from the touching one). [-]
PRELOAD_CENTRED = 1e-50
#: A cage angle within this of 0 or half pitch is symmetric: 4 ulps of 360°, the rounding of
#: reducing an angle to one turn and one pitch (validate.TURN_ROUNDING). [°]
SYMMETRY_SNAP_DEG = validate.TURN_ROUNDING
#: Cosines and sines below this are rounding of an exact zero. [-]
SNAP = 1e-14
#: Range of the one-ball approach (F_r/K)^(1/m) the solver accepts, and of the clearance in
#: units of it: inside it every intermediate value is a normal double. [mm], [-]
APPROACH_RANGE = (1e-100, 1e100)
CLEARANCE_RATIO_MAX = 1e100
#: Largest and smallest magnitude of a result (ball load [N], stiffness [N/mm]) accepted. [-]
RESULT_RANGE = (1e-300, 1e300)
#: The refusal of a radial load on 1 or 2 balls none of which sits on the load line (the radial
#: and the combined engines').
CAGE_OFF_LINE = (
    "with 1 or 2 balls a ball must sit on the load line (cage angle 0), otherwise no "
    "equilibrium exists"
)


def snapped_cos(phi: np.ndarray) -> np.ndarray:
    c = np.cos(phi)
    return np.where(np.abs(c) < SNAP, 0.0, c)


def snapped_sin(phi: np.ndarray) -> np.ndarray:
    s = np.sin(phi)
    return np.where(np.abs(s) < SNAP, 0.0, s)


def gap_factor(theta: np.ndarray, h: float) -> np.ndarray:
    """``u = 1 - cos(theta)/cos(h)`` without cancellation; rounding of an exact 0 is 0."""
    u = 2.0 * np.sin((theta + h) / 2.0) * np.sin((theta - h) / 2.0) / np.cos(h)
    return np.where(u < 1e-13, 0.0, u)


@functools.lru_cache(maxsize=4096)
def symmetric(z: int, half_pitch: bool, preload: bool) -> tuple[np.ndarray, ...]:
    """Half of a ring symmetric about the load line: (c, s, u, w) of each angle, ``w`` its
    multiplicity; with a clearance only the balls ahead of 90° (the others never carry)."""
    j = np.arange(z)
    phi = (j + (0.5 if half_pitch else 0.0)) * 2.0 * np.pi / z
    phi = np.minimum(phi, 2.0 * np.pi - phi)  # fold the lower half onto the upper half
    uniq, counts = np.unique(np.round(phi / np.pi * 2 * z) / (2 * z), return_counts=True)
    phi, w = uniq * np.pi, counts.astype(float)
    if not preload:
        keep = np.cos(phi) > SNAP
        phi, w = phi[keep], w[keep]
    u = np.ones_like(phi) if preload else gap_factor(phi, np.pi / z if half_pitch else 0.0)
    return _frozen(snapped_cos(phi), snapped_sin(phi), u, w)


@functools.lru_cache(maxsize=1024)
def pitch_table(z: int, preload: bool) -> tuple[np.ndarray, ...]:
    """cos and sin of ``k pitch``, the gap factors and the multiplicities (ones) of a general
    ring, k = 0..z-1. Entry ``k`` is ball ``k + 1``, at ``theta = (k + 1/2) pitch`` from the
    reference angle ``mu`` whatever the cage angle."""
    pitch = 2.0 * math.pi / z
    h = pitch / 2.0
    theta = [(j + 0.5) * pitch for j in range(z)]
    u = [2.0 * math.sin((t + h) / 2.0) * math.sin((t - h) / 2.0) / math.cos(h) for t in theta]
    u = [1.0 if preload else (0.0 if v < 1e-13 else v) for v in u]
    return _frozen(
        np.array([math.cos(j * pitch) for j in range(z)]),
        np.array([math.sin(j * pitch) for j in range(z)]),
        np.array(u),
        np.ones(z),
    )


def _frozen(*arrays: np.ndarray) -> tuple[np.ndarray, ...]:
    out = tuple(np.ascontiguousarray(a, dtype=float) for a in arrays)
    for a in out:
        a.flags.writeable = False
    return out


@functools.lru_cache(maxsize=4096)
def tables(z: int, kind: int, preload: bool) -> tuple:
    """The leading arguments of ``_core.radial`` for a ring of ``z`` balls, cage ``kind`` (0: a
    ball under the load, 1: half pitch, 2: general) and formulation: (folded, preload, the
    (7, k) table of c, s, u, w of the ring and c, u, w of the start ring, the start ring's
    length, its largest cosine and that times its weight)."""
    ring = pitch_table(z, preload) if kind == 2 else symmetric(z, kind == 1, preload)
    c, _, u, w = symmetric(z, kind != 0, preload)  # the ring the start is taken from
    tab = np.zeros((7, ring[0].size))  # (the start ring is never longer than the ring)
    for row, a in enumerate((*ring, c, u, w)):
        tab[row, : a.size] = a
    top = int(np.argmax(c))
    (tab,) = _frozen(tab)
    return (kind != 2, preload, tab, c.size, float(c[top]), float(w[top] * c[top]))
