"""The forward problem: the force and tangent stiffness of the balls for a given ring position.

Rotor-dynamics and vibration codes integrate the motion of the inner ring and need, at every time
step, the force the bearing puts on it for the displacement they have, not the displacement for a
load (that is :func:`bearingload.models.equilibrium.solve`). Conventions are the engine's
(Kurochkin 1973, eqs. 1.1-1.5; Kuzmenko 2010, §1-2):

* Outer ring fixed; the inner ring is displaced by ``(x, y)`` [mm], ``x`` along the load line,
  ``y`` across it; angles from the load line, ball 1 at the cage angle ``phi_1``, ball ``i`` at
  ``phi_i = phi_1 + 360 (i - 1)/z`` degrees.
* Ball ``i`` is compressed by ``delta_i = x cos(phi_i) + y sin(phi_i) - G_r/2`` and carries
  ``Q_i = K max(delta_i, 0)^m``.
* The returned force is ``F = sum Q_i (cos phi_i, sin phi_i)``: the load the balls carry, i.e. the
  external load that holds the ring in this position. The balls act on the inner ring with
  ``-F`` (they push back against the displacement), so a dynamics code writes
  ``m_r x'' = F_applied - F`` and the ring is in equilibrium where ``F`` equals the applied load;
  ``solve`` gives the position where ``F = (F_r, 0)``.
* The tangent stiffness is ``dF/d(x, y) = sum K m delta_i^(m-1) n_i n_i^T`` (symmetric, positive
  semi-definite): the same matrix :attr:`LoadDistribution.stiffness_matrix` gives at a solution.

A ball exactly at the edge of contact (``delta_i = 0``) carries nothing and adds nothing to the
stiffness (the one-sided derivative from the unloaded side; for ``m > 1`` both sides agree).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

import bearingload.models._core as _core
from bearingload import validate
from bearingload.errors import InputError
from bearingload.models.case import checked


@dataclass(frozen=True)
class RingForces:
    """Force, tangent stiffness and ball loads of the inner ring at given displacements.

    Attributes
    ----------
    force_x, force_y : float or ndarray
        Load carried by the balls along and across the load line, ``sum Q_i cos phi_i`` and
        ``sum Q_i sin phi_i``; the balls push the inner ring with the opposite force. [N]
    stiffness_matrix : ndarray, shape (..., 2, 2)
        Tangent stiffness ``dF/d(x, y)`` in the (along, across) axes. [N/mm]
    ball_loads : ndarray, shape (..., z)
        Load ``Q_i`` of balls 1..z (ball 1 at the cage angle). [N]
    loaded_balls : int or ndarray of int
        Number of balls carrying load (``delta_i > 0``). [-]
    """

    force_x: Any
    force_y: Any
    stiffness_matrix: np.ndarray
    ball_loads: np.ndarray
    loaded_balls: Any


def ring_forces(
    balls: Any,
    x: Any,
    y: Any,
    stiffness: Any,
    clearance: Any = 0.0,
    cage_angle: Any = 0.0,
    exponent: Any = 1.5,
) -> RingForces:
    """The force and tangent stiffness of the balls for given inner-ring displacements.

    Direct sums over the balls (Kurochkin 1973, eqs. 1.1-1.5), vectorised: ``x``, ``y``,
    ``stiffness``, ``clearance``, ``cage_angle`` and ``exponent`` broadcast against each other.

    Parameters
    ----------
    balls : int
        Number of rolling elements ``z`` of the bearing, 1 to 100 000 (one value). [-]
    x : float or array_like
        Inner-ring displacement along the load line. [mm]
    y : float or array_like
        Inner-ring displacement across the load line (towards ``phi = +90°``). [mm]
    stiffness : float or array_like
        Rolling-element stiffness ``K`` of both contacts in series, ``Q = K delta^m``, > 0. [N/mm^m]
    clearance : float or array_like, default 0
        Radial internal clearance ``G_r`` (total play; gap per side ``G_r/2``; negative = preload). [mm]
    cage_angle : float or array_like, default 0
        Angle of ball 1 from the load line. [°]
    exponent : float or array_like, default 1.5
        Load-deflection exponent ``m``, 1 to 3: 3/2 for balls, 10/9 for rollers. [-]

    Returns
    -------
    RingForces
        ``force_x``, ``force_y`` [N] (Python floats for scalar input), ``stiffness_matrix``
        [N/mm] of shape (..., 2, 2), ``ball_loads`` [N] of shape (..., z), ``loaded_balls``.

    Raises
    ------
    InputError
        A parameter outside its domain, or a displacement so large that a ball load overflows.

    Examples
    --------
    Bearing 306 of Kuzmenko (2010) with his ball stiffness 4700 kgf/mm^1.5 = 46 091 N/mm^1.5:
    the ring moved 60 µm towards a ball, 20 µm clearance.

    >>> f = ring_forces(8, 0.060, 0.0, 46091.0, clearance=0.020)
    >>> round(f.force_x, 1), round(f.force_y, 9), f.loaded_balls
    (895.9, 0.0, 3)
    """
    z = validate.ball_count(balls)
    if z.ndim != 0:
        if z.size == 0 or np.any(z != z.flat[0]):
            raise InputError(
                "balls", "must be one number of balls (ring_forces evaluates one bearing)"
            )
        z = z.flat[0]
    nz = int(z)
    xs, ys = validate.finite("x", x), validate.finite("y", y)
    kk, g, cage, m = checked(
        stiffness=stiffness, clearance=clearance, cage_angle=cage_angle, exponent=exponent
    )
    e, phi1 = g / 2.0, validate.cage_angle(cage)
    shape = validate.broadcast_shape(
        {"x": xs, "y": ys, "stiffness": kk, "clearance": e, "cage_angle": phi1, "exponent": m}
    )
    # broadcast views (a parameter shared by every case is one value read again, no copy)
    flat = [np.broadcast_to(a, shape).reshape(-1) for a in (xs, ys, kk, e, phi1, m)]
    out, loads, loaded = _core.ring_forces(nz, *flat)
    fx, fy = out[:, 0], out[:, 1]
    matrix = out[:, [2, 3, 3, 4]].reshape(-1, 2, 2)
    if not (np.all(np.isfinite(fx)) and np.all(np.isfinite(matrix))):
        raise InputError(
            "x",
            "the displacement is so large against the clearance that a ball load overflows "
            "double precision; check its unit (mm)",
        )
    if shape == ():
        return RingForces(float(fx[0]), float(fy[0]), matrix[0], loads[0], int(loaded[0]))
    return RingForces(
        fx.reshape(shape),
        fy.reshape(shape),
        matrix.reshape(shape + (2, 2)),
        loads.reshape(shape + (nz,)),
        loaded.reshape(shape),
    )
