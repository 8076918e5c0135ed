"""Kurochkin (1973), statics of a radial ball bearing, in his dimensionless form.

V. A. Kurochkin, "Statics of a radial ball bearing" (Izv. AN SSSR, MTT, 1973). He solves the
ring equilibrium at any cage angle ``phi_1`` with ``P = K = 1`` and one generalised parameter
(his eq. 1.13, ``n`` = number of balls, ``e`` = gap per side = ``G_r/2``):

    T = 2 e (K/P)^(2/3) / (cot^2(pi/n) - 1)

and tabulates (Tables 1-4, n = 5-8) the ring displacement across the load
``y0 = -(P/K)^(2/3) F0'`` (eq. 2.1), the exit angle ``psi`` and the Fourier sine coefficients
``F0j'`` of ``F0'`` over the cage angle (eq. 2.3). Here every quantity comes from the exact engine
:func:`bearingload.models.equilibrium.solve` (``load = stiffness = 1``, clearance ``G_r = 2e``):
``F0 = x``, ``F0' = -y``.

Definitions used here (Kurochkin 1973, §1):

* exit angle ``psi``: the angle from the load line at which a ball leaves contact (its load falls
  to zero) as the cage turns forward; by symmetry balls enter contact at ``-psi``. In the
  sequence 1-2-1 (``T >= 1``) ``psi = 360/n`` (his eq. 1.15).
* contact sequence: the numbers of loaded balls at ``phi_1 = 0``, on each stretch between the cage
  angles where a ball enters or leaves contact, and at ``phi_1 = 360/n``, repeats merged:
  "1-2-1" (``T > 1``), "3-2-3" (his second sequence, ``T_min <= T <= 1``), "3-4-3" ...
* Fourier coefficients: ``F0j' = (n/pi) int_0^(2pi/n) F0' sin(j n phi_1) dphi_1`` (his eq. 2.3).
  ``F0'`` is odd about 0 and about half pitch, so the integral is twice that over half a pitch.
  That half pitch is split at the cage angles where a ball enters or leaves contact (there ``F0'``
  has a ``t^(3/2)`` kink, found by root finding on the engine's ball approach); on each piece the
  map ``phi = a + (b - a) s^2 (3 - 2 s)`` removes the kink (``t^(3/2) -> s^3``) and Gauss-Legendre
  quadrature in ``s`` converges spectrally (error < 1e-12 with 48 nodes per piece; see tests).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from bearingload import validate
from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.models.equilibrium import solve

#: Gauss-Legendre nodes per smooth piece of the half pitch (see the module docstring). [-]
QUADRATURE_NODES = 48
#: Cage positions per pitch used to bracket the contact events before root finding. [-]
BRACKET_STEPS = 240


def _balls(balls: Any) -> int:
    z = int(balls)
    if z != balls or z < 5:
        raise InputError(
            "balls", f"must be an integer >= 5: T needs cot^2(pi/n) > 1 (got {balls!r})"
        )
    return z


def _cot2_minus_1(z: int) -> float:
    return 1.0 / math.tan(math.pi / z) ** 2 - 1.0


def generalised_parameter(clearance: Any, load: Any, stiffness: Any, balls: int) -> Any:
    """Kurochkin's generalised parameter T (1973, eq. 1.13), balls only (m = 3/2). [-]

    ``T = 2 e (K/P)^(2/3) / (cot^2(pi/n) - 1)`` with ``e = G_r/2``.

    Parameters
    ----------
    clearance : array_like
        Radial internal clearance ``G_r`` = 2 e (negative = preload). [mm]
    load : array_like
        Radial load ``P``, > 0. [N]
    stiffness : array_like
        Ball stiffness ``K`` of both contacts, ``Q = K delta^(3/2)``. [N/mm^1.5]
    balls : int
        Number of balls ``n`` >= 5. [-]

    >>> round(generalised_parameter(0.006, 2.5, 0.45 * 1e3**1.5, 7), 4)  # Example 1, e = 3 µm
    0.5776
    """
    z = _balls(balls)
    e = np.asarray(clearance, dtype=float) / 2.0
    t = 2.0 * e * (np.asarray(stiffness, float) / np.asarray(load, float)) ** (2.0 / 3.0)
    out = t / _cot2_minus_1(z)
    return float(out) if np.ndim(out) == 0 else out


def clearance_from_parameter(T: Any, balls: int, load: Any = 1.0, stiffness: Any = 1.0) -> Any:
    """The clearance ``G_r = 2e`` giving Kurochkin's parameter T (eq. 1.13 solved for e). [mm]

    Parameters
    ----------
    T : array_like
        Generalised parameter. [-]
    balls : int
        Number of balls ``n`` >= 5. [-]
    load, stiffness : array_like
        ``P`` [N] and ``K`` [N/mm^1.5]; 1 and 1 give his dimensionless mode.

    >>> round(clearance_from_parameter(1.0, 6), 12)  # n = 6: cot^2(30°) - 1 = 2
    2.0
    """
    z = _balls(balls)
    ratio = (np.asarray(load, float) / np.asarray(stiffness, float)) ** (2.0 / 3.0)
    out = np.asarray(T, float) * _cot2_minus_1(z) * ratio
    return float(out) if np.ndim(out) == 0 else out


def lower_parameter(balls: int) -> float:
    """Lowest T of the second contact sequence 3-2-3 (Kurochkin 1973, eq. 1.17). [-]

    ``T_min = (1/(2 cos(pi/n)))^(2/3) (1 - 1/(2 cos(2 pi/n)))``; at it ``psi = 3 pi/n``.
    """
    z = _balls(balls)
    return (0.5 / math.cos(math.pi / z)) ** (2.0 / 3.0) * (1.0 - 0.5 / math.cos(2 * math.pi / z))


def displacement(balls: int, T: Any, cage_angle: Any) -> tuple[Any, Any]:
    """``F0 = x0`` and ``F0' = -y0`` with P = K = 1 (Kurochkin 1973, eq. 2.1), vectorised.

    Parameters
    ----------
    balls : int
        Number of balls ``n`` >= 5. [-]
    T : array_like
        Generalised parameter (eq. 1.13). [-]
    cage_angle : array_like
        Cage angle ``phi_1`` (ball 1 from the load line). [°]

    Returns
    -------
    F0, F0_prime : float or ndarray
        Ring displacement along the load and minus that across it, in units of (P/K)^(2/3). [-]
    """
    r = solve(balls, 1.0, 1.0, clearance_from_parameter(T, balls), cage_angle)
    f0, f0p = r.x, 0.0 - r.y  # 0.0 - y: no negative zero at the symmetric positions
    if np.ndim(f0) == 0:
        return float(f0), float(f0p)
    return f0, f0p


def _approach(cage_angle: float, balls: int, T: float, ball: int) -> float:
    r = solve(balls, 1.0, 1.0, clearance_from_parameter(T, balls), cage_angle)
    return float(r.ball_approaches[ball])


def exit_angle(balls: int, T: float) -> float | None:
    """Exit angle ``psi``: where a ball leaves contact as the cage turns forward. [°]

    Found by bracketing the sign change of each ball's approach over one pitch of cage angles
    and solving ``delta_i(phi_1) = 0`` in its bracket (:func:`bearingload.numerics.bracketed_root`, xtol 1e-13°) on the engine's solution.
    ``psi = 360/n`` in the sequence 1-2-1 (Kurochkin 1973, eq. 1.15); ``None`` when every ball
    stays loaded at every cage angle (heavy preload).

    Parameters
    ----------
    balls : int
        Number of balls ``n`` >= 5. [-]
    T : float
        Generalised parameter (eq. 1.13). [-]
    """
    return _events(balls, float(T))[0]


def _events(balls: int, T: float) -> tuple[float | None, list[float]]:
    """(psi, sorted cage angles in [0, pitch] where a ball enters or leaves contact) [°]."""
    from functools import partial

    from bearingload.numerics import bracketed_root

    z = _balls(balls)
    pitch = 360.0 / z
    grid = np.linspace(0.0, pitch, BRACKET_STEPS + 1)
    r = solve(z, 1.0, 1.0, clearance_from_parameter(T, z), grid)
    delta = np.array([r[k].ball_approaches for k in range(grid.size)])  # (steps, balls)
    leaving = (delta[:-1] > 0) & (delta[1:] <= 0)
    candidates = []
    for k, ball in zip(*np.nonzero(leaving), strict=True):
        a, b = grid[k], grid[k + 1]
        approach = partial(_approach, balls=z, T=T, ball=int(ball))
        root = bracketed_root(approach, a, b, xtol=1e-13, rtol=1e-15)
        psi = (root + ball * pitch + 180.0) % 360.0 - 180.0
        if psi > 0:
            candidates.append(psi)
    if not candidates:  # every ball stays loaded over the whole pitch
        return None, []
    psi = min(candidates)
    first = psi % pitch
    events = sorted({round(first, 12), round(pitch - first, 12)} - {0.0, round(pitch, 12)})
    return psi, events


def contact_sequence(balls: int, T: float) -> str:
    """Numbers of loaded balls over one pitch, e.g. "1-2-1", "3-2-3" (Kurochkin 1973, §1).

    Counted at cage angle 0, on each stretch between contact events, and at one pitch.
    """
    z = _balls(balls)
    _, events = _events(z, float(T))
    pitch = 360.0 / z
    edges = [0.0, *events, pitch]
    probes = [0.0] + [(a + b) / 2 for a, b in zip(edges[:-1], edges[1:], strict=True)] + [pitch]
    r = solve(z, 1.0, 1.0, clearance_from_parameter(T, z), np.array(probes))
    counts = [int(c) for c in r.loaded_balls]
    merged = [counts[0]] + [c for p, c in zip(counts[:-1], counts[1:], strict=True) if c != p]
    return "-".join(str(c) for c in merged)


def _nodes(balls: int, T: float, nodes: int) -> tuple[np.ndarray, np.ndarray]:
    """Cage angles [°] and weights [rad] of the quadrature over half a pitch, kinks removed."""
    z = _balls(balls)
    half = 180.0 / z
    _, events = _events(z, T)
    edges = [0.0, *[a for a in events if 0.0 < a < half], half]
    s, w = np.polynomial.legendre.leggauss(nodes)
    s, w = (s + 1.0) / 2.0, w / 2.0
    g, dg = s * s * (3.0 - 2.0 * s), 6.0 * s * (1.0 - s)
    angles, weights = [], []
    for a, b in zip(edges[:-1], edges[1:], strict=True):
        angles.append(a + (b - a) * g)
        weights.append(np.deg2rad(b - a) * dg * w)
    return np.concatenate(angles), np.concatenate(weights)


def fourier_sine(balls: int, T: float, harmonics: int = 5, nodes: int = QUADRATURE_NODES) -> Any:
    """Fourier sine coefficients ``F0j'`` (j = 1..harmonics) of ``F0'`` over the cage angle. [-]

    ``F0j' = (n/pi) int_0^(2 pi/n) F0' sin(j n phi_1) dphi_1`` (Kurochkin 1973, eq. 2.3), by
    Gauss-Legendre quadrature over each smooth piece of half a pitch (module docstring).

    Parameters
    ----------
    balls : int
        Number of balls ``n`` >= 5. [-]
    T : float
        Generalised parameter (eq. 1.13). [-]
    harmonics : int
        Number of coefficients. [-]
    nodes : int
        Gauss-Legendre nodes per piece. [-]

    Returns
    -------
    ndarray, shape (harmonics,)
        ``F0j'`` in units of (P/K)^(2/3). [-]
    """
    z = _balls(balls)
    angles, weights = _nodes(z, float(T), nodes)
    _, f0p = displacement(z, T, angles)
    j = np.arange(1, harmonics + 1)[:, None]
    phi = np.deg2rad(angles)[None, :]
    return 2.0 * z / math.pi * np.sum(weights * f0p * np.sin(j * z * phi), axis=1)


def moment_arm(inner_diameter: float, ball_diameter: float, rotating: str = "inner") -> float:
    """Kurochkin's ratio ``w`` of cage to ring rotation (1973, eq. 1.3). [-]

    ``w = D/(2(D + d))`` for a rotating inner ring, ``(D + 2d)/(2(D + d))`` for a rotating outer
    ring; ``D`` inner-ring raceway diameter [mm], ``d`` ball diameter [mm].
    """
    d_in, d_b = float(inner_diameter), float(ball_diameter)
    if rotating == "inner":
        return d_in / (2.0 * (d_in + d_b))
    if rotating == "outer":
        return (d_in + 2.0 * d_b) / (2.0 * (d_in + d_b))
    raise InputError("rotating", f"must be 'inner' or 'outer' (got {rotating!r})")


def conservative_moment(
    balls: int,
    load: float,
    stiffness: float,
    clearance: float,
    cage_angle: Any,
    inner_diameter: float,
    ball_diameter: float,
    rotating: str = "inner",
) -> Any:
    """Conservative moment ``M = w P y0`` on the rotating ring (Kurochkin 1973, eq. 1.9). [N mm]

    Parameters
    ----------
    balls : int
        Number of balls. [-]
    load : float
        Radial load ``P``. [N]
    stiffness : float
        Ball stiffness ``K``. [N/mm^1.5]
    clearance : float
        Radial internal clearance ``G_r = 2e``. [mm]
    cage_angle : array_like
        Cage angle ``phi_1``. [°]
    inner_diameter, ball_diameter : float
        ``D`` (inner-ring raceway) and ``d`` (ball). [mm]
    rotating : {"inner", "outer"}
        Which ring turns (sets ``w``).
    """
    w = moment_arm(inner_diameter, ball_diameter, rotating)
    r = solve(balls, load, stiffness, clearance, cage_angle)
    out = w * load * r.y
    return float(out) if np.ndim(out) == 0 else out


def harmonic_null_parameter(balls: int, harmonic: int, lower: float, upper: float) -> float:
    """The T in [lower, upper] at which ``F0j'(T) = 0`` for j = ``harmonic``. [-]

    The conservative moment ``M = w P y0`` then has no j-th harmonic (Kurochkin 1973, Example 1,
    part 2).
    """
    from bearingload.numerics import bracketed_root

    def f(t: float) -> float:
        return float(fourier_sine(balls, t, harmonic)[harmonic - 1])

    return bracketed_root(f, lower, upper, xtol=1e-13)


@dataclass(frozen=True)
class KurochkinSweep:
    """Kurochkin's dimensionless statics over one ball pitch (P = K = 1)."""

    balls: int
    T: float
    clearance: float
    """``G_r = 2e`` in units of (P/K)^(2/3). [-]"""
    cage_angle: np.ndarray
    """[°]"""
    F0: np.ndarray
    F0_prime: np.ndarray
    contact_sequence: str
    exit_angle: float | None
    """[°]; None when every ball stays loaded"""
    fourier: np.ndarray
    """F0j', j = 1..5. [-]"""


def kurochkin_sweep(balls: int, T: float, steps: int = 37) -> KurochkinSweep:
    """F0, F0' at ``steps`` cage angles over one pitch (both ends), with ψ, sequence and F0j'.

    Parameters
    ----------
    balls : int
        Number of balls ``n`` >= 5. [-]
    T : float
        Generalised parameter (Kurochkin 1973, eq. 1.13). [-]
    steps : int
        Cage positions from 0 to 360/n, both included, >= 2. [-]
    """
    z = _balls(balls)
    t = float(validate.finite("T", T))
    n = int(steps)
    if n != steps or n < 2 or n > 1_000_000:
        raise InputError("steps", f"must be an integer from 2 to 1000000 (got {steps!r})")
    angles = np.linspace(0.0, 360.0 / z, n)
    f0, f0p = displacement(z, t, angles)
    return KurochkinSweep(
        balls=z,
        T=t,
        clearance=float(clearance_from_parameter(t, z)),
        cage_angle=angles,
        F0=np.asarray(f0),
        F0_prime=np.asarray(f0p),
        contact_sequence=contact_sequence(z, t),
        exit_angle=exit_angle(z, t),
        fourier=np.asarray(fourier_sine(z, t, 5)),
    )
