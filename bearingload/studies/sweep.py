"""The turning cage: the ring equilibrium over one ball pitch of cage positions.

As the cage turns one pitch ``360/z`` the load passes from "a ball under the load" (cage angle 0)
to "the load between two balls" (``180/z``) and back; the inner-ring position, the heaviest ball
load and the stiffness change periodically, z times per cage revolution: the varying compliance
that excites bearing vibration (Kurochkin 1973; the varying-compliance abstract;
Sunnersjö 1978). All cage positions are solved in one vectorised call of the exact engine
(:func:`bearingload.models.equilibrium.solve`). Conventions are the engine's: outer ring fixed,
radial load on the inner ring along +x, angles from the load line, ball 1 at the cage angle.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from bearingload import validate
from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.models.equilibrium import solve

#: Cage positions over one pitch when none are asked for (both ends included). [-]
DEFAULT_STEPS = 37
#: Most cage positions one sweep solves. [-]
MAX_STEPS = 1_000_000


@dataclass(frozen=True)
class Spread:
    """Minimum, mean, maximum and peak-to-peak of a quantity over the cage positions.

    The mean is over one period: the two ends of the sweep are the same cage position, so the
    last one is left out (the trapezoidal mean over the pitch). A mean below 1e-12 of the largest
    value in size is rounding noise (the engine resolves each value to about 1e-13) and is 0.
    """

    min: float
    mean: float
    max: float
    peak_to_peak: float


@dataclass(frozen=True)
class CageSweep:
    """The ring equilibrium at cage positions over one ball pitch, both ends included.

    Attributes
    ----------
    balls : int
        Number of balls ``z``. [-]
    load, stiffness, clearance, exponent : float
        Radial load [N], ball stiffness [N/mm^m], radial internal clearance G_r [mm], ``m`` [-].
    cage_angle : ndarray, shape (steps,)
        Angle of ball 1 from the load line, 0 to ``360/z``. [°]
    x, y : ndarray
        Inner-ring displacement along and across the load. [mm]
    q_max : ndarray
        Heaviest ball load. [N]
    q_max_ball : ndarray of int
        The ball (1..z, ball 1 at the cage angle) carrying ``q_max``; of two equal, the lower. [-]
    loaded_balls : ndarray of int
        Number of balls carrying load. [-]
    stiffness_matrix : ndarray, shape (steps, 2, 2)
        Tangent stiffness ``dF/d(x, y)`` in the (along, across) axes, analytic. [N/mm]
    stiffness_radial : ndarray
        Tangent radial stiffness ``dF_r/dx`` with the transverse force held at zero. [N/mm]
    compensating_clearance : list of float
        Every clearance ``G_r`` at which ``x`` is the same with a ball under the load and with
        the load between two balls, in increasing order (negative = preload); the
        varying-compliance paper's delta_alpha = delta_S is the smallest positive one. From
        :func:`bearingload.studies.compensation.compensating_clearances`. [mm]
    reference_rating_life : ndarray or None
        L10r at each cage position from its ball loads (``life`` of :func:`sweep`). [10^6 rev]
    dynamic_rating : float or None
        C_r of a bearing whose lives are asked for (ISO 281's L10 = (C_r/F_r)^p). [N]
    life_exponent : float
        p of ISO 281's L10: 3 for balls, 10/3 for rollers. [-]
    rotating : str or None
        The ring rotating relative to the load, of ``reference_rating_life``.
    speed : float or None
        Shaft speed for the lives in hours. [rpm]
    warnings : tuple of str
        solve's finding of one loaded ball, with the cage angles where it holds
        (:func:`one_ball_findings`); the plan puts the checks on a bearing before it.
    """

    balls: int
    load: float
    stiffness: float
    clearance: float
    exponent: float
    cage_angle: np.ndarray
    x: np.ndarray
    y: np.ndarray
    q_max: np.ndarray
    q_max_ball: np.ndarray
    loaded_balls: np.ndarray
    stiffness_matrix: np.ndarray
    stiffness_radial: np.ndarray
    compensating_clearance: list[float]
    reference_rating_life: np.ndarray | None = None
    dynamic_rating: float | None = None
    life_exponent: float = 3.0
    rotating: str | None = None
    speed: float | None = None
    warnings: tuple[str, ...] = ()

    @property
    def rating_life(self) -> float | None:
        """ISO 281's basic rating life (C_r/F_r)^p (P = F_r), None without C_r. [10^6 rev]"""
        if self.dynamic_rating is None:
            return None
        from bearingload.bearings.life import rating_life

        return float(rating_life(self.dynamic_rating, self.load, self.life_exponent))

    def hours(self, life: Any) -> Any:
        """``life`` [10^6 rev] in hours at :attr:`speed` (None without a speed or a life). [h]"""
        return hours_at(life, self.speed)

    def values(self, name: str) -> Any:
        """The per-position values of ``name``: the spread quantities, ``reference_rating_life``
        and ``reference_rating_life_hours`` (None where not computed)."""
        if name == "reference_rating_life":
            return self.reference_rating_life
        if name == "reference_rating_life_hours":
            return self.hours(self.reference_rating_life)
        return getattr(self, name)

    @property
    def ripple_order(self) -> int:
        """Ripple frequency: periods of x, y, Q_max and stiffness per cage revolution, ``z``. [-]"""
        return self.balls

    def spread(self, name: str) -> Spread:
        """Min, mean, max and peak-to-peak of ``x``, ``y``, ``q_max``, ``stiffness_radial`` or
        (where computed) ``reference_rating_life`` and ``reference_rating_life_hours``."""
        allowed = ("x", "y", "q_max", "stiffness_radial", "reference_rating_life",
                   "reference_rating_life_hours")  # fmt: skip
        values = self.values(name) if name in allowed else None
        if values is None:
            raise InputError("name", f"must be one of {', '.join(allowed)} (where computed)")
        return spread_of(values)


def bearing_checks(bearing: Any, s: CageSweep) -> tuple[str, ...]:
    """The checks ``solve`` makes on a bearing's case
    (:func:`bearingload.bearings.checks.case_warnings`: static safety s0 = C0/F_r and F_r above
    C0, the contact pressure, the clearance beyond ISO 5753-1's classes or the preload beyond
    this package's bound), over the pitch: the pressure at its heaviest ball load. The finding
    of one loaded ball is the sweep's own (:func:`one_ball_findings`, with the cage angles).

    Parameters
    ----------
    bearing : ResolvedBearing
        The bearing swept (its C0, geometry and clearance).
    s : CageSweep
        The sweep of that bearing under its radial load.
    """
    from types import SimpleNamespace

    from bearingload.bearings.checks import case_warnings

    heaviest = SimpleNamespace(q_max=float(np.max(s.q_max)), loaded_balls=None)
    return tuple(case_warnings(bearing, s.load, heaviest))


def hours_at(life: Any, speed: float | None) -> Any:
    """``life`` [10^6 rev] in hours at the shaft ``speed`` [r/min], L 10^6/(60 n), as
    :func:`bearingload.bearings.modified_life.life_hours` gives it; None without a speed or a
    life (the one conversion of the cage sweeps, radial and combined). [h]

    >>> float(hours_at(60.0, 1000.0)), hours_at(None, 1000.0), hours_at(60.0, None)
    (1000.0, None, None)
    """
    if speed is None or life is None:
        return None
    from bearingload.bearings.modified_life import life_hours

    return life_hours(life, speed)


#: Quantities whose rounding noise is measured against the largest of their family.
FAMILIES = (("x", "y", "axial"), ("tilt", "tilt_cross"))


def family_spread(values: Callable[[str], Any], key: str) -> Spread | None:
    """Min, mean, max and peak-to-peak of ``values(key)`` over the pitch (None if not given).

    A mean of a displacement (tilt) below 1e-12 of the largest displacement (tilt) of any axis
    (``values`` of the others of its family in :data:`FAMILIES`) is the solver's rounding noise
    and is 0 (y and the cross tilt are odd in the cage angle)."""
    v = values(key)
    if v is None:
        return None
    family = next((f for f in FAMILIES if key in f), (key,))
    scale = max(float(np.max(np.abs(np.asarray(values(k))))) for k in family)
    return spread_of(v, scale)


def cage_chunks(angles: np.ndarray, balls: int, contacts: int) -> list[np.ndarray]:
    """``angles`` in consecutive chunks of at most ``contacts`` ball contacts (at least one cage
    position each): a long sweep solved one call per chunk, which changes no answer."""
    n = max(1, contacts // balls)
    return [angles[i : i + n] for i in range(0, angles.size, n)]


def at_cage_angles(where: Any, steps: int) -> str:
    """Where a finding of a sweep holds: ``at 3 of 37 cage angles (10° to 30°)``, ``where`` the
    cage angles [°] of ``steps`` positions."""
    a = np.asarray(where, dtype=float)
    return f"at {a.size} of {steps} cage angles ({a.min():.6g}° to {a.max():.6g}°)"


def one_ball_findings(loaded_balls: Any, angles: np.ndarray) -> list[str]:
    """solve's finding of one loaded ball, once, with the cage ``angles`` [°] where it holds
    (none where more balls carry the load everywhere)."""
    one = np.asarray(loaded_balls) == 1
    if not one.any():
        return []
    return [
        f"only one ball carries the load {at_cage_angles(angles[one], one.size)}: the result "
        "hangs on a single contact (large clearance or few elements); check the clearance"
    ]


def spread_of(values: Any, scale: float | None = None) -> Spread:
    """Min, mean, max and peak-to-peak of ``values`` over the cage positions of one pitch, both
    ends included (see :class:`Spread`); a mean below 1e-12 of ``scale`` (default the largest
    value in size) is rounding noise and is 0."""
    v = np.asarray(values, dtype=float)
    lo, hi = float(v.min()), float(v.max())
    period = v[:-1] if v.size > 1 else v
    with np.errstate(over="ignore"):
        mean = float(period.mean())
    if not np.isfinite(mean):  # the sum of values near the largest double overflows
        big = float(np.abs(period).max())
        mean = big * float((period / big).mean())
    if abs(mean) <= 1e-12 * (float(np.abs(v).max()) if scale is None else scale):
        mean = 0.0  # rounding noise of a quantity that averages out (y: odd in the cage angle)
    return Spread(lo, mean, hi, hi - lo)


def sweep(
    balls: Any,
    load: Any,
    stiffness: Any,
    clearance: Any = 0.0,
    exponent: Any = 1.5,
    steps: Any = DEFAULT_STEPS,
    life: Callable[[np.ndarray], Any] | None = None,
) -> CageSweep:
    """Solve the ring equilibrium at ``steps`` cage positions over one ball pitch.

    Cage angles ``0, p/(steps - 1), ..., p`` with the pitch ``p = 360/z`` degrees (both ends: the
    same position, a ball under the load), solved in one vectorised call of the exact 2-D
    equilibrium (Kurochkin 1973, eqs. 1.6-1.8).

    Parameters
    ----------
    balls : int
        Number of balls ``z``, 3 to 100 000 (with fewer no equilibrium exists off the load
        line). [-]
    load : float
        Radial load ``F_r``, > 0. [N]
    stiffness : float
        Ball stiffness ``K`` of both contacts in series, ``Q = K delta^m``, > 0. [N/mm^m]
    clearance : float, default 0
        Radial internal clearance ``G_r`` (total play; gap per side ``G_r/2``; negative = preload). [mm]
    exponent : float, default 1.5
        Load-deflection exponent ``m``: 3/2 for balls, 10/9 for rollers. [-]
    steps : int, default 37
        Cage positions over the pitch, both ends included, 2 to 1 000 000. [-]
    life : callable, optional
        L10r of ball loads [N] of shape (steps, z) (e.g. a partial of
        :func:`bearingload.studies.reference_life.ball_reference_life`): its values at every
        cage position become ``reference_rating_life``. [10^6 rev]

    Returns
    -------
    CageSweep

    Examples
    --------
    Nine balls, 1 kN, K = 1e5 N/mm^1.5, G_r = 10 µm: the ring moves across the load by up to a
    few tenths of a micrometre as the cage turns.

    >>> s = sweep(9, 1000.0, 1e5, 0.01, steps=9)
    >>> s.cage_angle[[0, 4, 8]].tolist(), s.q_max_ball[[0, 8]].tolist()
    ([0.0, 20.0, 40.0], [1, 9])
    >>> round(s.spread("y").max * 1e3, 4)
    0.3125
    """
    from bearingload.studies.compensation import compensating_clearances
    from bearingload.studies.reference_life import all_ball_approaches

    z = _one_int("balls", validate.ball_count(balls))
    angles = cage_angles(z, steps)
    f, k, g, m = (
        float(_one("load", validate.positive("load", load, "N"))),
        float(_one("stiffness", validate.positive("stiffness", stiffness, "N/mm^m"))),
        float(_one("clearance", validate.finite("clearance", clearance))),
        float(_one("exponent", validate.exponent(exponent))),
    )
    r = solve(z, f, k, g, angles, m)
    delta = all_ball_approaches(r)
    top = delta.max(axis=1, keepdims=True)
    ties = delta >= top - 1e-12 * np.abs(top)
    return CageSweep(
        balls=z,
        load=f,
        stiffness=k,
        clearance=g,
        exponent=m,
        cage_angle=angles,
        x=r.x,
        y=r.y,
        q_max=r.q_max,
        q_max_ball=np.argmax(ties, axis=1) + 1,
        loaded_balls=r.loaded_balls,
        stiffness_matrix=r.stiffness_matrix,
        stiffness_radial=r.stiffness_radial,
        compensating_clearance=[float(g) for g in compensating_clearances(z, f, k, m)],
        reference_rating_life=(
            None if life is None else np.asarray(life(k * np.maximum(delta, 0.0) ** m))
        ),
        warnings=tuple(one_ball_findings(r.loaded_balls, angles)),
    )


def cage_angles(balls: int, steps: Any = DEFAULT_STEPS) -> np.ndarray:
    """The ``steps`` cage angles ``0, p/(steps - 1), ..., p`` over one pitch ``p = 360/z``. [°]

    Raises
    ------
    InputError
        ``balls`` below 3 (no equilibrium off the load line), ``steps`` not 2 to 1 000 000.
    """
    if balls < 3:
        raise InputError(
            "balls",
            "a sweep needs at least 3 balls: with 1 or 2 the ring has no equilibrium unless a "
            "ball sits on the load line",
        )
    arr = validate.finite("steps", steps)
    if np.any((arr < 2) | (arr > MAX_STEPS)):  # ball_count's range starts at 1: refused here
        raise InputError(
            "steps", f"must be between 2 (both ends of the pitch) and {MAX_STEPS} (got {steps})"
        )
    n = _one_int("steps", validate.ball_count(steps, name="steps", maximum=MAX_STEPS))
    return np.linspace(0.0, 360.0 / balls, n)


def _one(name: str, value: np.ndarray) -> np.ndarray:
    if value.ndim != 0:
        raise InputError(name, "must be one number (a sweep is one bearing under one load)")
    return value


def _one_int(name: str, value: np.ndarray) -> int:
    return int(_one(name, value))
