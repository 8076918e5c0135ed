"""The numerics every model shares: a bracketed root, the complete elliptic integrals by the
arithmetic-geometric mean, and the scalar contract of the public functions.

* :func:`bracketed_root`: one root of a scalar function inside a sign-changing bracket, without
  scipy. The studies that refine a bracketed root (the compensating clearances of the sweep, the
  contact changes and the zero of a Fourier coefficient in Kurochkin's statics) need only a
  bracketed solver; importing ``scipy.optimize`` for it cost a terminal ``bearingload sweep``
  about 0.4 s of its start-up. It is regula falsi through the bracket ends with a bisection on
  every third step (so the bracket at least halves every three evaluations and the search ends
  however the function bends), stopping when the bracket is within ``2 (xtol + rtol |x|)``.
  Tests check it against ``scipy.optimize.brentq`` on the project's own functions.
* :func:`elliptic_integrals`: K, E, ``(E - pK)/m`` and ``(K - E)/m`` at the ellipticity
  ``kappa = e^t`` of a Hertz contact, by the AGM (Abramowitz & Stegun 17.6), for one contact (a
  float) or many (an array, element by element). The AGM is one C function
  (``bearingload/_elliptic.pyx``, a compiled module of this layer), which the models' compiled
  core uses too for the Hertz stiffness curve. Only ``p = e^(-2t)`` and ``m = 1 - p`` differ
  between a float and an array: numpy's ``exp`` and ``expm1`` may round the last bit otherwise
  than the C library's (7 % and 1.6 % of t from 1e-9 to 40, numpy 2.4), so an element may differ
  from the float path by an ulp.
* :func:`scalar_out`: a case given as scalars gives Python numbers, as arrays gives arrays.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from bearingload import _elliptic
from bearingload.errors import ConvergenceError

#: Evaluations at the most: enough to halve any double-precision bracket to its last bit.
MAX_EVALUATIONS = 400


def bracketed_root(
    f: Callable[[float], float],
    a: float,
    b: float,
    *,
    xtol: float = 1e-12,
    rtol: float = 4.5e-16,
) -> float:
    """The root of ``f`` in [a, b] where ``f(a)`` and ``f(b)`` differ in sign.

    Parameters
    ----------
    f : callable
        Continuous on [a, b]. [any unit]
    a, b : float
        The bracket. [unit of x]
    xtol, rtol : float
        Absolute [unit of x] and relative [-] tolerance of the root.

    Returns
    -------
    float
        A point within ``2 (xtol + rtol |x|)`` of a sign change of ``f`` (of the two last
        bracket ends, the one where ``|f|`` is smaller). [unit of x]

    Raises
    ------
    ValueError
        ``f(a)`` and ``f(b)`` have the same sign, or a value is not finite.
    ConvergenceError
        The bracket is still wider than the tolerance after :data:`MAX_EVALUATIONS` steps
        (a bracket over 2^133 times the tolerance), instead of a bracket end far from the root.

    >>> round(bracketed_root(lambda x: x * x - 2.0, 0.0, 2.0, xtol=1e-15), 14)
    1.41421356237309
    """
    a, b = float(a), float(b)
    fa, fb = float(f(a)), float(f(b))
    for x, fx in ((a, fa), (b, fb)):
        if fx != fx or fx in (float("inf"), float("-inf")):
            raise ValueError(f"f({x!r}) is not finite")
        if fx == 0.0:
            return x
    if (fa > 0) == (fb > 0):
        raise ValueError(f"f(a) and f(b) have the same sign (f({a!r}) = {fa}, f({b!r}) = {fb})")
    for step in range(MAX_EVALUATIONS):
        tol = xtol + rtol * max(abs(a), abs(b))
        if abs(b - a) <= 2.0 * tol:
            break
        c = b - fb * (b - a) / (fb - fa)  # the secant through the bracket ends
        low, high = min(a, b), max(a, b)
        if step % 3 == 2 or not (low + tol < c < high - tol):
            c = 0.5 * (a + b)
        fc = float(f(c))
        if fc != fc:
            raise ValueError(f"f({c!r}) is not finite")
        if fc == 0.0:
            return c
        if (fc > 0) == (fa > 0):
            a, fa = c, fc
        else:
            b, fb = c, fc
    else:
        if abs(b - a) > 2.0 * (xtol + rtol * max(abs(a), abs(b))):
            raise ConvergenceError("bracketed root", MAX_EVALUATIONS, abs(b - a), {"a": a, "b": b})
    return a if abs(fa) < abs(fb) else b


def elliptic_integrals(t: Any) -> tuple[Any, Any, Any, Any, Any, Any]:
    """``(K, E, (E - pK)/m, (K - E)/m, m, p)`` at ``kappa = e^t`` (``p = 1/kappa^2``, ``m = 1 - p``).

    Parameters
    ----------
    t : float or ndarray
        ``ln kappa >= 0`` of one contact (a Python float, > 0) or of many (an array; 0 gives the
        circle's limits ``K = E = pi/2``, ``(K - E)/m = (E - pK)/m = pi/4``). [-]

    Returns
    -------
    tuple
        Floats for a float, arrays of the shape of ``t`` for an array. [-]

    ``K = pi / (2 AGM(1, sqrt p))`` and ``(K - E)/m = K (1/2 + sum_(n>=1) 2^(n-1) c_n^2 / m)``
    with ``c_(n+1) = c_n^2 / (4 a_(n+1))`` (Abramowitz & Stegun 17.6), summed from positive terms
    so that neither the circle (``m -> 0``, where ``K - E`` cancels) nor a long ellipse
    (``m -> 1``) loses precision; ``(E - pK)/m`` near the circle as ``K (1/2 - sum ...)``. The
    AGM runs in C (``bearingload._elliptic``, the compiled core's too), each element stopping at
    its own step, so its value does not depend on the others; ``p`` and ``m`` of an array come
    from numpy's ``exp`` and ``expm1``, those of a float from the C library's.

    >>> k_int, e_int, *_ = elliptic_integrals(0.5)
    >>> round(k_int, 12), round(e_int, 12)
    (1.985871804956, 1.280760067829)
    """
    if isinstance(t, float):
        return _elliptic.at(t)
    t = np.asarray(t, dtype=float)
    p, m = np.exp(-2.0 * t), -np.expm1(-2.0 * t)
    k_int, e_int, n, d = (v[()] for v in _elliptic.of_arrays(p, m))
    return k_int, e_int, n, d, m, p


def scalar_out(value: Any) -> Any:
    """The scalar contract of every public function: a case given as scalars gives Python
    ``float``/``int``/``bool`` (a 0-d array or numpy scalar is unwrapped with ``.item()``), a case
    given as arrays gives numpy arrays; ``None`` stays ``None``. Ball-level quantities are
    arrays in either case (their callers do not pass them here).

    >>> scalar_out(np.float64(2.5)), type(scalar_out(np.asarray(3)))
    (2.5, <class 'int'>)
    >>> scalar_out(np.zeros(2))
    array([0., 0.])
    """
    if value is None or isinstance(value, (bool, int, float)) and not isinstance(value, np.generic):
        return value
    arr = np.asarray(value)
    return arr.item() if arr.ndim == 0 else arr


#: A transverse stiffness K_yy at most this fraction of K_xx leaves y free: the loads do not
#: determine it, and :func:`radial_stiffness` gives K_xx (as the speed model's free-direction
#: test, :data:`bearingload.models.high_speed.SINGULAR`). [-]
FREE_TRANSVERSE = 1e-9


def radial_stiffness(kxx: Any, kxy: Any, kyx: Any, kyy: Any) -> Any:
    """The radial stiffness dF_x/dx with the transverse force F_y held at zero, the Schur
    complement ``K_xx - K_xy K_yx / K_yy`` of a ring's tangent, elementwise; ``K_xx`` where
    nothing stiffens y (``K_yy`` at most :data:`FREE_TRANSVERSE` of ``|K_xx|``, one ball on the
    load line: y is free, and the complement of a rounding-level K_yy would cancel K_xx). [N/mm]
    """
    kxx, kxy, kyx, kyy = (np.asarray(v, dtype=float) for v in (kxx, kxy, kyx, kyy))
    stiff = kyy > FREE_TRANSVERSE * np.abs(kxx)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(stiff, kyx / np.where(stiff, kyy, 1.0), 0.0)
    return scalar_out(kxx - kxy * ratio)
