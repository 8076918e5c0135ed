"""Hand-calculation procedures for Q_max, reproduced so that their error can be measured.

Two ways an engineer gets the maximum ball load without a computer solver:

* :func:`kuzmenko2010_trial`: the trial-and-error solution of the resolving equation with the
  load-zone angle ``phi0`` tried at a fixed resolution (1°, 0.1°, 0.01°), as Kuzmenko (2010, §3.4,
  eqs. 2.12-2.13 and 3.4) does for bearing 306: ``phi0 = 80°, 85°, 85.2°`` and then
  ``Q0 = K Delta^(3/2) (1/cos(phi0) - 1)^(3/2)`` at the angle found.
* :func:`load_zone_table_k`: the continuum model with the load-zone integral ``J_r(eps)`` read by
  linear interpolation from a table printed at steps of 0.1 with 4 decimals, in the form of
  Harris & Kotzalas (2007, vol. 1, Table 7.1) for point contact.

Conventions as in :mod:`bearingload.models.equilibrium`: ``clearance`` is the radial internal
clearance ``G_r`` (total play), the papers' ``Delta`` is the gap per side ``e = G_r/2``.

References
----------
.. [1] Kuzmenko A.G. Load distribution between balls in a radial ball bearing (in Russian).
   Problems of Tribology, 2010, no. 1, pp. 29-41, §2-3.
.. [2] Harris T.A., Kotzalas M.N. Rolling Bearing Analysis, 5th ed., vol. 1. CRC Press, 2007,
   §7.2, eqs. 7.20-7.23 and Table 7.1.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from bearingload import validate
from bearingload.errors import InputError
from bearingload.models.case import checked
from bearingload.numerics import scalar_out

#: Load-zone parameters of the printed table, steps of 0.1. [-]
TABLE_EPSILON = (0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0)
#: ``J_r(eps)`` for point contact (m = 3/2) at :data:`TABLE_EPSILON`, 4 decimals as printed;
#: each value is the exact integral rounded (checked by the tests). [-]
TABLE_JR = (0.0, 0.1156, 0.1590, 0.1892, 0.2117, 0.2288, 0.2416, 0.2505, 0.2559, 0.2576, 0.2546)


class TrialResult(NamedTuple):
    """Result of :func:`kuzmenko2010_trial` (arrays of the input shape, floats for scalars).

    Attributes
    ----------
    k : float or ndarray
        Load factor ``Q_max/F_r``. [-]
    q_max : float or ndarray
        ``Q0`` at the accepted trial angle. [N]
    angle : float or ndarray
        The accepted trial angle ``phi0``, a multiple of ``step``. [°]
    evaluations : int or ndarray
        Evaluations of the resolving equation spent. [-]
    """

    k: Any
    q_max: Any
    angle: Any
    evaluations: Any


def kuzmenko2010_trial(
    balls: Any,
    load: Any,
    stiffness: Any,
    clearance: Any,
    cage_angle: Any = 0.0,
    step: float = 0.1,
    exponent: Any = 1.5,
    rounding: str = "nearest",
) -> TrialResult:
    """Q_max by trying load-zone angles ``phi0`` at a fixed resolution (Kuzmenko 2010, §3.4).

    The resolving equation (Kuzmenko 2010, eq. 2.12, the sum over all balls written for any
    symmetric cage) is ``F_r/(K Delta^m) = sum_i max(cos(phi_i)/cos(phi0) - 1, 0)^m cos(phi_i)``;
    its right side grows with ``phi0``. The angles tried are the multiples of ``step``; the two that
    bracket the root are found by bisection over them, and the root is rounded to the nearer one
    (one more evaluation, at the half step between them); with ``rounding="up"`` the first angle
    whose right side reaches the left side is accepted, as the paper accepts 85.2° (64.98 against
    63.82) for a root at 85.149°. Then (eq. 2.13)
    ``Q_max = K Delta^m (cos(phi_1)/cos(phi0) - 1)^m`` with ``phi_1`` the ball nearest the load line.

    Parameters
    ----------
    balls : int or array_like
        Number of balls ``z`` (>= 1). [-]
    load : float or array_like
        Radial load ``F_r > 0``. [N]
    stiffness : float or array_like
        Ball stiffness ``K`` of both contacts in series, ``Q = K delta^m``. [N/mm^m]
    clearance : float or array_like
        Radial internal clearance ``G_r > 0`` (``Delta = G_r/2``; the procedure needs a gap). [mm]
    cage_angle : float or array_like, default 0
        0 (a ball under the load) or ``180/z`` (half pitch): the equation assumes a symmetric ring. [°]
    step : float, default 0.1
        Resolution of the trial angles, 0 < step <= 10. [°]
    exponent : float or array_like, default 1.5
        Load-deflection exponent ``m``. [-]
    rounding : {"nearest", "up"}, default "nearest"
        Accept the trial angle nearest the root, or the first one at or beyond it (the paper's). [-]

    Returns
    -------
    TrialResult

    Examples
    --------
    Bearing 306 (Kuzmenko 2010, §3.4): 300 kgf, K = 4700 kgf/mm^1.5, Delta = 0.01 mm; the paper
    accepts 85.2° and Q0 = 170.3 kgf (k = 0.5677); the exact answer is 167.3 kgf:

    >>> r = kuzmenko2010_trial(8, 300.0, 4700.0, 0.02, step=0.1, rounding="up")
    >>> round(r.angle, 1), round(r.q_max, 1), round(r.k, 4)
    (85.2, 170.3, 0.5677)
    >>> r = kuzmenko2010_trial(8, 300.0, 4700.0, 0.02, step=0.1)
    >>> round(r.angle, 1), round(r.q_max, 1)
    (85.1, 164.7)
    """
    z, f, kk = checked(balls=balls, load=load, stiffness=stiffness)
    g = validate.positive("clearance", clearance, "mm")  # the procedure needs a gap
    cage, m = checked(cage_angle=cage_angle, exponent=exponent)
    if not (isinstance(step, (int, float)) and 0 < step <= 10):
        raise InputError("step", f"must be a number of degrees in (0, 10], got {step!r}")
    if rounding not in ("nearest", "up"):
        raise InputError("rounding", f"must be 'nearest' or 'up', got {rounding!r}")
    z, f, kk, g, cage, m = np.broadcast_arrays(z, f, kk, g, cage, m)
    shape = z.shape
    z, f, kk, g, cage, m = (a.ravel() for a in (z, f, kk, g, cage, m))
    pitch = 360.0 / z
    frac = np.mod(cage, pitch) / pitch
    if np.any((np.abs(frac) > 1e-12) & (np.abs(frac - 0.5) > 1e-12) & (np.abs(frac - 1) > 1e-12)):
        raise InputError("cage_angle", "must be 0 or half a pitch (180/z): a symmetric ring")
    e = g / 2.0
    target = f / (kk * e**m)
    zmax = int(z.max())
    i = np.arange(zmax)
    phi = np.deg2rad(cage[:, None] + i[None, :] * pitch[:, None])
    c = np.where(i[None, :] < z[:, None], np.cos(phi), 0.0)  # absent balls: never loaded

    def side(j: np.ndarray, rows: np.ndarray) -> np.ndarray:
        cos0 = np.cos(np.deg2rad(j * step))
        d = np.maximum(c[rows] / cos0[:, None] - 1.0, 0.0)
        return np.sum(d ** m[rows, None] * c[rows], axis=1)

    n = z.size
    every = np.arange(n)
    last = int(np.ceil(90.0 / step)) - 1  # the last multiple of step below 90°
    lo, hi = np.zeros(n, dtype=np.int64), np.full(n, last, dtype=np.int64)
    f_lo, f_hi = np.zeros(n), side(hi, every)
    evaluations = np.ones(n, dtype=np.int64)
    active = every[hi - lo > 1]
    while active.size:
        mid = (lo[active] + hi[active]) // 2
        value = side(mid, active)
        up = value < target[active]
        lo[active] = np.where(up, mid, lo[active])
        f_lo[active] = np.where(up, value, f_lo[active])
        hi[active] = np.where(up, hi[active], mid)
        f_hi[active] = np.where(up, f_hi[active], value)
        evaluations[active] += 1
        active = active[hi[active] - lo[active] > 1]
    # round to the nearer multiple: the root lies below the half step iff the side there exceeds
    if rounding == "nearest":
        take_lo = (lo > 0) & (side(lo + 0.5, every) >= target)
        evaluations += 1
    else:
        take_lo = np.zeros(n, dtype=bool)
    j = np.where(take_lo, lo, hi)
    cos0 = np.cos(np.deg2rad(j * step))
    q = kk * e**m * np.maximum(c.max(axis=1) / cos0 - 1.0, 0.0) ** m
    return TrialResult(*(scalar_out(a.reshape(shape)) for a in (q / f, q, j * step, evaluations)))


def table_jr(epsilon: Any) -> np.ndarray:
    """``J_r(eps)`` by linear interpolation in the printed table :data:`TABLE_JR` (m = 3/2). [-]"""
    return np.interp(epsilon, TABLE_EPSILON, TABLE_JR)


class TableResult(NamedTuple):
    """Result of :func:`load_zone_table_k`: ``k`` [-], ``q_max`` [N], ``epsilon`` [-], ``iterations`` [-]."""

    k: Any
    q_max: Any
    epsilon: Any
    iterations: Any


def load_zone_table_k(balls: Any, load: Any, stiffness: Any, clearance: Any = 0.0) -> TableResult:
    """Q_max of the continuum model with ``J_r`` interpolated linearly in a printed table.

    Solves ``F_r = z K delta_max^(3/2) J_r(eps)`` with ``delta_max = 2 eps e/(1 - 2 eps)``
    (``e = G_r/2``; Harris & Kotzalas 2007, eqs. 7.20-7.23) for ``eps`` by bisection, ``J_r`` read
    from :data:`TABLE_JR` (steps of 0.1, 4 decimals); then ``Q_max = F_r/(z J_r(eps))``. Zero
    clearance is ``eps = 1/2`` at once. Point contact (m = 3/2) only, as the table.

    Parameters
    ----------
    balls : int or array_like
        Number of balls ``z`` (>= 1). [-]
    load : float or array_like
        Radial load ``F_r > 0``. [N]
    stiffness : float or array_like
        Ball stiffness ``K`` of both contacts in series. [N/mm^1.5]
    clearance : float or array_like, default 0
        Radial internal clearance ``G_r`` (negative = preload, within the table: ``eps <= 1``). [mm]

    Returns
    -------
    TableResult

    Raises
    ------
    InputError
        A preload so heavy that ``eps`` leaves the table (``eps > 1``).

    Examples
    --------
    >>> round(load_zone_table_k(8, 1000.0, 1e5).k * 8, 4)  # 1/0.2288
    4.3706
    """
    z, f, kk, g = checked(balls=balls, load=load, stiffness=stiffness, clearance=clearance)
    z, f, kk, g = np.broadcast_arrays(z.astype(float), f, kk, g)
    e = g / 2.0
    with np.errstate(divide="ignore", over="ignore"):
        target = f / (z * kk * np.abs(e) ** 1.5)
    preload = e < 0
    if np.any(preload & (target < 2.0**1.5 * TABLE_JR[-1])):
        raise InputError("clearance", "the preload puts eps beyond the table's 1.0")
    lo = np.where(preload, 0.5, 0.0)
    hi = np.where(preload, 1.0, 0.5)
    iterations = 0
    while np.any(hi - lo > 1e-15) and iterations < 100:
        mid = 0.5 * (lo + hi)
        with np.errstate(divide="ignore"):
            value = (2.0 * mid / np.abs(1.0 - 2.0 * mid)) ** 1.5 * table_jr(mid)
        # the right side rises with eps under clearance and falls with it under preload
        below = (value < target) != preload
        lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
        iterations += 1
    eps = np.where(e == 0, 0.5, 0.5 * (lo + hi))
    k = 1.0 / (z * table_jr(eps))
    its = np.where(e == 0, 0, iterations)
    return TableResult(*(scalar_out(np.asarray(a)) for a in (k, k * f, eps, its)))
