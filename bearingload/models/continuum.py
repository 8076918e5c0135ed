"""The continuum model: the balls' loads smeared over the raceway (Sjövall/Harris load-zone integral).

Conventions (the same as the discrete engine, :mod:`bearingload.models.equilibrium`): outer ring fixed, radial load ``F_r``
on the inner ring, angles ``psi`` from the load line; ``clearance`` is the radial internal
clearance ``G_r`` (total radial play), the gap per side is ``e = G_r/2``, negative = preload;
ball stiffness ``K`` of both contacts in series, ``Q = K delta^m`` with ``m = 3/2`` for balls and
``10/9`` for rollers. ``F_r = z Q_max J_r(eps)``, ``eps = (1 - e/x)/2``, with the load-zone
integral ``J_r`` computed by Gauss-Legendre quadrature after substitutions that remove its
endpoint singularity (within 1e-13 of mpmath for 1 <= m <= 3 and every ``eps``); the unknown is
``ln(eps)``. The model, the substitutions and the solver: docs/models.md, "Continuum model and
the classical approximations" (Kuzmenko 2010, §4-5; Harris & Kotzalas, 5th ed., vol. 1, §7.2;
Sjövall 1933, its Sources).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from bearingload import validate
from bearingload.errors import ConvergenceError, InputError
from bearingload.models.case import checked
from bearingload.numerics import scalar_out

#: Gauss-Legendre order used inside the solver iterations (J_r to ~3e-14). [-]
NODES_SOLVER = 48
#: Gauss-Legendre order of the published results (J_r and dJ_r/deps to ~1e-13). [-]
NODES_FINAL = 128
#: Convergence tolerance on asinh(e/x_0) (the dimensionless clearance). [-]
TOLERANCE = 1e-13
#: Iteration cap of the Newton loop; reaching it raises ConvergenceError.
MAX_ITERATIONS = 100
#: Largest residual accepted after the loop (else ConvergenceError). [-]
ACCEPT = 1e-10
_Y_MIN, _Y_MAX = -700.0, 700.0  # bracket of ln(eps)


@dataclass(frozen=True)
class ContinuumResult:
    """Solution of the continuum model for one case or an array of cases.

    Every attribute is a numpy array of the broadcast input shape; for one case given as
    scalars, a Python ``int`` or ``float``.

    Attributes
    ----------
    k : ndarray
        Load factor ``Q_max/F_r = 1/(z J_r(eps))``. [-]
    q_max : ndarray
        Load on the most loaded element (on the load line). [N]
    K_Q : ndarray
        Load-concentration factor ``K_Q = Q_max/(F_r/(z/2)) = k z/2`` (Kuzmenko & Sabadash 2014). [-]
    load_zone : ndarray
        Half-angle of the load zone ``psi_l`` (180 when every element is loaded). [°]
    epsilon : ndarray
        Load-zone parameter ``eps = (1 - e/x)/2``. [-]
    x : ndarray
        Displacement of the inner ring along the load. [mm]
    approach_max : ndarray
        Elastic approach of the most loaded element ``delta_max = x - e``. [mm]
    stiffness_radial : ndarray
        Tangent radial stiffness of the bearing ``dF_r/dx``. [N/mm]
    iterations : ndarray
        Newton iterations spent (0 at zero clearance). [-]
    """

    k: np.ndarray
    q_max: np.ndarray
    K_Q: np.ndarray
    load_zone: np.ndarray
    epsilon: np.ndarray
    x: np.ndarray
    approach_max: np.ndarray
    stiffness_radial: np.ndarray
    iterations: np.ndarray


def zero_clearance_integral(exponent: Any = 1.5) -> Any:
    r"""Exact ``I_m = int_0^{pi/2} cos^(m+1)(phi) dphi`` of the zero-clearance continuum model.

    .. math:: I_m = \frac{\sqrt{\pi}\,\Gamma((m+2)/2)}{2\,\Gamma((m+3)/2)}

    (Dwight, *Tables of Integrals*, no. 858.45, in the form of the duplication formula). For balls
    ``I_{3/2} = 0.718884...``; Kuzmenko (2010, §4, step 4, eq. (d)) prints 0.7181.

    Parameters
    ----------
    exponent : float or array_like
        Load-deflection exponent ``m`` (1 <= m <= 3). [-]

    Returns
    -------
    float or ndarray
        ``I_m``. [-]

    Examples
    --------
    >>> round(zero_clearance_integral(1.5), 6)
    0.718884
    """
    m = validate.exponent(exponent)
    return scalar_out(_integral_i(m))


def zero_clearance_k(balls: Any, exponent: Any = 1.5) -> Any:
    r"""Load factor ``k = Q_max/F_r`` of the continuum model at zero clearance.

    .. math:: k = \frac{\Delta\varphi}{2 I_m} = \frac{\pi}{z\,I_m} = \frac{1}{z\,J_r(1/2)}

    (Kuzmenko 2010, eqs. 4.17-4.19; Stribeck's 4.37 for balls). ``k z = 4.370096...`` for balls
    and ``4.084991...`` for rollers; the paper prints 4.3749/z (eq. 4.20) from its 0.7181.

    Parameters
    ----------
    balls : int or array_like
        Number of rolling elements ``z`` (whole number >= 1). [-]
    exponent : float or array_like
        Load-deflection exponent ``m``. [-]

    Returns
    -------
    float or ndarray
        ``k``. [-]

    Examples
    --------
    >>> round(zero_clearance_k(8), 6)
    0.546262
    """
    z = validate.ball_count(balls)
    m = validate.exponent(exponent)
    z, m = np.broadcast_arrays(z, m)
    return scalar_out(np.pi / (z * _integral_i(m)))


def load_zone_integral(epsilon: Any, exponent: Any = 1.5) -> Any:
    """Sjövall/Harris radial load-zone integral ``J_r(eps)``.

    ``J_r(eps) = 1/(2 pi) int_{-psi_l}^{psi_l} [1 - (1 - cos psi)/(2 eps)]^m cos(psi) dpsi`` with
    ``psi_l = arccos(1 - 2 eps)`` for ``eps <= 1`` and ``pi`` beyond (Harris & Kotzalas 2007,
    eq. 7.22; Sjövall 1933). Limits: ``J_r(0) = 0``, ``J_r -> m/(4 eps)`` as ``eps -> inf``
    (returned as 0 at ``eps = inf``); ``1/J_r(1/2) = 4.3701`` (balls), ``4.0850`` (rollers).

    Parameters
    ----------
    epsilon : float or array_like
        Load-zone parameter ``eps >= 0`` (``(1 - e/x)/2``). [-]
    exponent : float or array_like
        Load-deflection exponent ``m`` (1 <= m <= 3). [-]

    Returns
    -------
    float or ndarray
        ``J_r``. [-]

    Examples
    --------
    >>> round(1 / load_zone_integral(0.5), 4)
    4.3701
    >>> round(1 / load_zone_integral(0.5, 10 / 9), 4)
    4.085
    """
    eps = np.asarray(epsilon, dtype=float)
    if np.any(np.isnan(eps)) or np.any(eps < 0):
        raise InputError("epsilon", "must be a number >= 0 (0 = no load zone, inf = all loaded)")
    m = validate.exponent(exponent)
    eps_b, m_b = np.broadcast_arrays(eps, m)
    j, _ = _jr(eps_b, m_b, NODES_FINAL, derivative=False)
    return scalar_out(j)


def continuum_load(
    balls: Any, deflection: Any, stiffness: Any, clearance: Any = 0.0, exponent: Any = 1.5
) -> Any:
    """Radial load of the continuum model at a given ring displacement (the forward problem).

    ``F_r = z K delta_max^m J_r(eps)``, ``delta_max = x - e``, ``eps = (1 - e/x)/2``, ``e = G_r/2``;
    zero when ``x <= e``.

    Parameters
    ----------
    balls : int or array_like
        Number of rolling elements ``z``. [-]
    deflection : float or array_like
        Displacement ``x > 0`` of the inner ring along the load. [mm]
    stiffness : float or array_like
        Element stiffness ``K`` (both contacts in series). [N/mm^m]
    clearance : float or array_like
        Radial internal clearance ``G_r`` (total play, negative = preload). [mm]
    exponent : float or array_like
        Load-deflection exponent ``m``. [-]

    Returns
    -------
    float or ndarray
        ``F_r``. [N]
    """
    z = validate.ball_count(balls).astype(float)
    x = validate.positive("deflection", deflection, "mm")
    k_ball = validate.positive("stiffness", stiffness, "N/mm^m")
    e = validate.finite("clearance", clearance) / 2.0
    m = validate.exponent(exponent)
    z, x, k_ball, e, m = np.broadcast_arrays(z, x, k_ball, e, m)
    d_max = x - e
    loaded = d_max > 0
    eps = np.where(loaded, d_max / (2.0 * x), 0.5)
    j, _ = _jr(eps, m, NODES_FINAL, derivative=False)
    force = np.where(loaded, z * k_ball * np.power(np.where(loaded, d_max, 1.0), m) * j, 0.0)
    return scalar_out(force)


def solve_continuum(
    balls: Any,
    load: Any,
    stiffness: Any,
    clearance: Any = 0.0,
    exponent: Any = 1.5,
    *,
    nodes: int | None = None,
) -> ContinuumResult:
    """Solve the continuum model for the load zone, the maximum element load and the stiffness.

    Solves ``F_r = z K (x - e)^m J_r((1 - e/x)/2)`` for the ring displacement ``x`` (Kuzmenko 2010,
    resolving equation 5.12, in the Harris/Sjövall form), for any clearance including preload.
    Vectorised: all inputs broadcast against each other.

    Parameters
    ----------
    balls : int or array_like
        Number of rolling elements ``z`` (whole number >= 1). [-]
    load : float or array_like
        Radial load ``F_r > 0``. [N]
    stiffness : float or array_like
        Element stiffness ``K`` of both contacts in series, ``Q = K delta^m``. [N/mm^m]
    clearance : float or array_like
        Radial internal clearance ``G_r`` (total play; gap per side ``e = G_r/2``; negative =
        preload). [mm]
    exponent : float or array_like
        Load-deflection exponent ``m``: 3/2 balls (point contact), 10/9 rollers (line contact);
        1 <= m <= 3. [-]
    nodes : int, optional
        Gauss-Legendre order of the load-zone integral, in the iterations and in the result;
        default: :data:`NODES_SOLVER` in the iterations, :data:`NODES_FINAL` in the result.
        A lower order trades accuracy for time (``bearingload accuracy`` measures it). [-]

    Returns
    -------
    ContinuumResult
        ``k``, ``q_max``, ``K_Q``, ``load_zone``, ``epsilon``, ``x``, ``approach_max``,
        ``stiffness`` (``dF_r/dx``) and ``iterations``.

    Raises
    ------
    InputError
        For a non-finite or out-of-domain input.
    ConvergenceError
        If some case does not converge (carries those cases).

    Examples
    --------
    Bearing 306 of Kuzmenko (2010, §3): z = 8, K = 4700 kgf/mm^1.5, F_r = 300 kgf, G_r = 20 um.

    >>> r = solve_continuum(8, 300 * 9.80665, 4700 * 9.80665, clearance=0.02)
    >>> round(float(r.k), 4), round(float(r.q_max / 9.80665), 1)
    (0.5625, 168.8)
    """
    z, force, k_ball, g, m = checked(
        balls=balls, load=load, stiffness=stiffness, clearance=clearance, exponent=exponent
    )
    z, e = z.astype(float), g / 2.0
    if nodes is not None and not (isinstance(nodes, int) and 1 <= nodes <= 1000):
        raise InputError("nodes", f"must be a whole number from 1 to 1000, got {nodes!r}")
    shape = validate.broadcast_shape(
        {"balls": z, "load": force, "stiffness": k_ball, "clearance": e, "exponent": m}
    )
    z, force, k_ball, e, m = (
        np.array(np.broadcast_to(a, shape), dtype=float).ravel() for a in (z, force, k_ball, e, m)
    )

    from bearingload.models.equilibrium import check_range

    with np.errstate(all="ignore"):  # the exact model's range: the same inputs refused alike
        scale = np.power(force / k_ball, 1.0 / m)
        check_range(force, scale, e / scale, m, z, ({"load": load, "clearance": clearance}, shape))
    j0 = _integral_i(m) / np.pi
    x0 = np.power(force / (z * k_ball * j0), 1.0 / m)
    eta = e / x0
    if not np.all(np.isfinite(eta)) or not np.all(np.isfinite(x0)) or np.any(x0 <= 0):
        bad = ~(np.isfinite(eta) & np.isfinite(x0) & (x0 > 0))
        raise InputError(
            "load",
            "load, stiffness and clearance give a displacement scale outside floating point "
            f"(first such case: load={force[bad].flat[0]:g} N, "
            f"stiffness={k_ball[bad].flat[0]:g} N/mm^m, clearance={2 * e[bad].flat[0]:g} mm)",
        )

    y, iterations = _solve_log_epsilon(
        eta,
        m,
        j0,
        nodes or NODES_SOLVER,
        balls=z,
        load=force,
        stiffness=k_ball,
        clearance=2.0 * e,
        exponent=m,
    )
    eps = np.exp(y)
    j, dj = _jr(eps, m, nodes or NODES_FINAL, derivative=True)
    d_rel = np.power(j0 / j, 1.0 / m)  # delta_max / x0
    d_max = x0 * d_rel
    x = d_max / (2.0 * eps)
    k = 1.0 / (z * j)
    # under preload (e < 0) the geometry delta_max = x - e adds two positive terms: exact to
    # rounding, while the force equation fixes x well but delta_max only to the solver's tolerance
    # on log(eps) once eps is huge (a tiny load under heavy preload); Q_max = K delta_max^m follows
    preload = e < 0
    ratio = np.where(preload, (x - e) / d_max, 1.0)
    d_max = np.where(preload, x - e, d_max)
    k = k * np.power(ratio, m)
    # dF/dx = z K delta_max^(m-1) [m J + eps (1 - 2 eps) J'] = F/delta_max [m + eps (1-2eps) J'/J]
    stiff = force / d_max * (m + eps * (1.0 - 2.0 * eps) * dj / j)
    zone = np.where(eps <= 1.0, 2.0 * np.arcsin(np.sqrt(np.minimum(eps, 1.0))), np.pi)
    return ContinuumResult(
        k=_shaped(k, shape),
        q_max=_shaped((k * force), shape),
        K_Q=_shaped((k * z / 2.0), shape),
        load_zone=_shaped(np.rad2deg(zone), shape),
        epsilon=_shaped(eps, shape),
        x=_shaped(x, shape),
        approach_max=_shaped(d_max, shape),
        stiffness_radial=_shaped(stiff, shape),
        iterations=_shaped(iterations, shape),
    )


# --------------------------------------------------------------------------- internals


def _shaped(values: Any, shape: tuple[int, ...]) -> Any:
    """``values`` in the case shape; a Python scalar for one scalar case."""
    return scalar_out(np.asarray(values).reshape(shape))


#: ln Gamma elementwise (math.lgamma, as numpy has none). [-]
_lgamma = np.vectorize(math.lgamma, otypes=[float])


def _integral_i(m: np.ndarray) -> np.ndarray:
    """I_m = sqrt(pi) Gamma((m+2)/2) / (2 Gamma((m+3)/2)), elementwise."""
    m = np.asarray(m, dtype=float)
    return 0.5 * math.sqrt(math.pi) * np.exp(_lgamma((m + 2.0) / 2.0) - _lgamma((m + 3.0) / 2.0))


@lru_cache(maxsize=8)
def _nodes(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """sin^2, cos and weights of theta = pi/2 (1 - v^4), v Gauss-Legendre on (0, 1)."""
    x, w = np.polynomial.legendre.leggauss(n)
    v = 0.5 * (x + 1.0)
    theta = 0.5 * np.pi * (1.0 - v**4)
    weight = 0.5 * w * 0.5 * np.pi * 4.0 * v**3
    s = np.sin(theta)
    c = np.cos(theta)
    return s * s, c, weight, theta


def _power(base: np.ndarray, exponent: np.ndarray) -> np.ndarray:
    """``base ** exponent`` over the broadcast (cases, nodes) grid, both operands laid out whole.

    numpy picks a different ``pow`` loop (vectorised or per element, rounding differently in the
    last bit) by the memory layout of its operands; a broadcast exponent column gives one layout
    for one case and another for many, so a case's bits would depend on the other cases of the
    call. Both operands as contiguous arrays of the full shape take one loop for every case.
    """
    shape = np.broadcast_shapes(base.shape, exponent.shape)
    return np.power(
        np.ascontiguousarray(np.broadcast_to(base, shape)),
        np.ascontiguousarray(np.broadcast_to(exponent, shape)),
    )


def _weighted_sum(values: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Each row of ``values`` times the weights ``w``, summed along the row.

    Not ``values @ w``: a BLAS matrix-vector product blocks the rows differently for different
    row counts, so one case's last bits would depend on the other cases of the call; an
    elementwise product summed along each contiguous row rounds every row alike.
    """
    return np.sum(values * w, axis=-1)


def _jr(
    eps: np.ndarray, m: np.ndarray, n: int, *, derivative: bool
) -> tuple[np.ndarray, np.ndarray]:
    """J_r(eps, m) and (optionally) dJ_r/deps by Gauss-Legendre quadrature (see module notes)."""
    s2, c, w, _ = _nodes(n)
    eps = np.asarray(eps, dtype=float)
    m = np.asarray(m, dtype=float)
    shape = np.broadcast(eps, m).shape
    e = np.broadcast_to(eps, shape).reshape(-1, 1)
    mm = np.broadcast_to(m, shape).reshape(-1, 1)
    inner = (e <= 1.0).ravel()
    j = np.zeros(e.shape[0])
    dj = np.zeros(e.shape[0])
    with np.errstate(divide="ignore", invalid="ignore", over="ignore", under="ignore"):
        if np.any(inner):
            ei, mi = e[inner], mm[inner]
            root = np.sqrt(c * c + (1.0 - ei) * s2)  # sqrt(1 - eps sin^2)
            common = (1.0 - 2.0 * ei * s2) / root
            j[inner] = (
                2.0
                * np.sqrt(ei[:, 0])
                / np.pi
                * _weighted_sum(_power(c, 2.0 * mi + 1.0) * common, w)
            )
            if derivative:
                val = _weighted_sum(_power(c, 2.0 * mi - 1.0) * s2 * common, w)
                dj[inner] = np.where(
                    ei[:, 0] > 0, 2.0 * mi[:, 0] / (np.pi * np.sqrt(ei[:, 0])) * val, np.inf
                )
        outer = ~inner
        if np.any(outer):
            eo, mo = e[outer], mm[outer]
            a = s2 / eo
            log_base = np.log1p(-a)
            f = np.expm1(mo * log_base) * (1.0 - 2.0 * s2)
            j[outer] = 2.0 / np.pi * _weighted_sum(f, w)
            if derivative:
                g = np.exp((mo - 1.0) * log_base) * s2 * (1.0 - 2.0 * s2)
                dj[outer] = 2.0 * mo[:, 0] / (np.pi * eo[:, 0] ** 2) * _weighted_sum(g, w)
    return j.reshape(shape), dj.reshape(shape)


def _asinh_from_parts(log_abs: np.ndarray, sign: np.ndarray) -> np.ndarray:
    """asinh(sign * exp(log_abs)) without overflow."""
    with np.errstate(over="ignore"):
        small = log_abs < 0
        out = np.where(
            small,
            np.arcsinh(np.exp(np.minimum(log_abs, 0.0))),
            log_abs + np.log1p(np.sqrt(1.0 + np.exp(-2.0 * np.maximum(log_abs, 0.0)))),
        )
    return sign * out


def _residual(
    y: np.ndarray, target: np.ndarray, m: np.ndarray, j0: np.ndarray, nodes: int
) -> tuple[np.ndarray, np.ndarray]:
    """h(y) = asinh(eta(e^y)) - target and dh/dy, J_r by ``nodes``-point quadrature."""
    eps = np.exp(y)
    j, dj = _jr(eps, m, nodes, derivative=True)
    log_d = (np.log(j0) - np.log(j)) / m  # ln D, D = (J0/J)^(1/m)
    g = (1.0 - 2.0 * eps) / (2.0 * eps)  # eta = D g
    with np.errstate(divide="ignore"):
        log_abs = log_d + np.log(np.abs(g))
    t = _asinh_from_parts(log_abs, np.sign(g))
    inv_d = np.exp(-log_d)
    hyp = np.hypot(inv_d, g)  # sqrt(1 + eta^2) / D
    # d eta/dy = -eta (eps J'/(m J) + 1) - D ; divide by sqrt(1 + eta^2)
    slope = -(g / hyp) * (eps * dj / (m * j) + 1.0) - 1.0 / hyp
    return t - target, slope


def _initial_guess(eta: np.ndarray, m: np.ndarray, j0: np.ndarray) -> np.ndarray:
    """ln(eps) from the asymptotes eps -> 0 (large clearance) and eps -> inf (large preload)."""
    # eps -> 0: J ~ c1 sqrt(eps), c1 = Gamma(m+1)/(sqrt(pi) Gamma(m+3/2))
    log_c1 = _lgamma(m + 1.0) - _lgamma(m + 1.5) - 0.5 * math.log(math.pi)
    with np.errstate(divide="ignore"):
        log_eta = np.log(np.abs(eta))
    y_clear = ((np.log(j0) - log_c1) / m - math.log(2.0) - log_eta) / (1.0 + 0.5 / m)
    # eps -> inf: J ~ m/(4 eps), |eta| ~ (4 J0 eps/m)^(1/m)
    y_pre = m * log_eta - np.log(4.0 * j0 / m)
    half = math.log(0.5)
    y = np.where(eta > 0, np.minimum(half, y_clear), np.maximum(half, y_pre))
    y = np.where(eta == 0, half, y)
    return np.clip(y, _Y_MIN + 1.0, _Y_MAX - 1.0)


def _solve_log_epsilon(
    eta: np.ndarray, m: np.ndarray, j0: np.ndarray, nodes: int, **cases: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Bracketed Newton iteration for y = ln(eps), vectorised; returns (y, iterations)."""
    target = np.arcsinh(eta)
    y = _initial_guess(eta, m, j0)
    lo = np.full_like(y, _Y_MIN)
    hi = np.full_like(y, _Y_MAX)
    iterations = np.zeros(y.shape, dtype=np.int64)
    active = eta != 0
    y = np.where(active, y, math.log(0.5))
    residual = np.zeros_like(y)
    for _ in range(MAX_ITERATIONS):
        idx = np.nonzero(active)
        if idx[0].size == 0:
            break
        ya = y[idx]
        h, slope = _residual(ya, target[idx], m[idx], j0[idx], nodes)
        residual[idx] = np.abs(h)
        iterations[idx] += 1
        # h is decreasing in y: h > 0 means the root lies above.
        lo_a = np.where(h > 0, ya, lo[idx])
        hi_a = np.where(h < 0, ya, hi[idx])
        with np.errstate(divide="ignore", invalid="ignore"):
            step = -h / slope
        y_new = ya + step
        bad = ~np.isfinite(y_new) | (y_new <= lo_a) | (y_new >= hi_a)
        y_new = np.where(bad, 0.5 * (lo_a + hi_a), y_new)
        done = (np.abs(h) <= TOLERANCE * np.maximum(1.0, np.abs(target[idx]))) | (
            hi_a - lo_a <= 4e-16 * np.maximum(1.0, np.abs(ya))
        )
        lo[idx], hi[idx] = lo_a, hi_a
        y[idx] = np.where(done, ya, y_new)
        sub = np.zeros_like(active)
        sub[idx] = ~done
        active = sub
    failed = active | (residual > ACCEPT * np.maximum(1.0, np.abs(target)))
    if np.any(failed):
        raise ConvergenceError(
            "continuum load-zone solver",
            int(iterations.max()),
            float(residual[failed].max()),
            {name: np.asarray(arr)[failed] for name, arr in cases.items()},
        )
    return y, iterations
