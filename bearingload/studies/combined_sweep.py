"""The turning cage under a combined load: the 3-D ring equilibrium over one ball pitch.

The combined-load counterpart of :mod:`bearingload.studies.sweep`: a deep-groove ball bearing
under F_r, F_a and a moment (or a misalignment), solved at ``steps`` cage positions over one
pitch ``360/z`` in ONE vectorised call of :func:`bearingload.models.combined.solve_combined` (the
cage angle is an array of cases). Per position: the ring's radial, axial and tilt displacement,
the heaviest ball load and its ball, the loaded balls, the largest contact angle of a loaded ball
and the ISO/TS 16281:2008 reference rating life L10r (clause 4.3) from that position's ball
loads; ISO 281's basic life, blind to the cage, is one number beside. Conventions are those of
``bearingload solve`` with a combined load (outer ring fixed, angles from the load line, ball 1
at the cage angle, axial displacement from the centred rings).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from typing import Any

import numpy as np

from bearingload.bearings.resolve import ResolvedBearing
from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.models.combined import CombinedDistribution
from bearingload.studies.sweep import (
    DEFAULT_STEPS,
    Spread,
    at_cage_angles,
    cage_angles,
    cage_chunks,
    family_spread,
    hours_at,
    one_ball_findings,
)

#: Per-position quantities a combined sweep summarises, keys of reports.quantities.
SPREAD_KEYS = (
    "x",
    "y",
    "axial",
    "tilt",
    "tilt_cross",
    "moment",
    "q_max",
    "loaded_balls",
    "contact_angle_max",
    "reference_rating_life",
    "reference_rating_life_hours",
)
#: Two ball loads within this relative difference are equal when naming the heaviest ball. [-]
TIE = 1e-9
#: Cage positions times balls solved per call: a longer sweep runs in chunks of this many ball
#: contacts (about 100 MB each), which changes no answer (no case depends on its batch). [-]
CHUNK_BALLS = 2**17


@dataclass(frozen=True)
class CombinedSweep:
    """A combined-load bearing at cage positions over one ball pitch, both ends included.

    Attributes
    ----------
    bearing : ResolvedBearing
        The bearing (its geometry, clearance and ratings).
    result : CombinedDistribution
        The 3-D equilibrium at every cage position (arrays of shape (steps,), balls last).
    misalignment : float or None
        Imposed tilt, None for a moment or a free ring. [°]
    rotating : str
        ``inner`` or ``outer``: the ring rotating relative to the load (for L10r).
    dynamic_rating, equivalent_load : float or None
        C_r and ISO 281's P = X F_r + Y F_a. [N]
    rating_life : float or None
        ISO 281's basic life (C_r/P)^3, the same at every cage position. [10^6 rev]
    reference_rating_life : ndarray or None
        ISO/TS 16281 L10r at every cage position. [10^6 rev]
    q_max_ball : ndarray of int
        The ball (1..z, ball 1 at the cage angle) carrying Q_max; of two equal (within 1e-9),
        the lower number. [-]
    contact_angle_max : ndarray
        Contact angle of largest size among the loaded balls, with its sign. [°]
    warnings : tuple of str
        The checks of ``solve`` over the pitch (heaviest load, fewest loaded balls).
    moment_cross : float or None
        The moment applied about the load line; None: not given. [N mm]
    tilt_radius : float or None
        The lever of the tilt given; None: the solver's R_i (``groove``). [mm]
    speed : float or None
        Shaft speed n for the lives in hours, L 10^6/(60 n); None: not given. [r/min]
    """

    bearing: ResolvedBearing
    result: CombinedDistribution
    misalignment: float | None
    rotating: str
    dynamic_rating: float | None
    equivalent_load: float | None
    rating_life: float | None
    reference_rating_life: np.ndarray | None
    q_max_ball: np.ndarray
    contact_angle_max: np.ndarray
    warnings: tuple[str, ...] = ()
    moment_cross: float | None = None
    tilt_radius: float | None = None
    speed: float | None = None

    @property
    def balls(self) -> int:
        """Number of balls z. [-]"""
        return int(self.result.balls)

    @property
    def cage_angle(self) -> np.ndarray:
        """Angle of ball 1 from the load line at every position, 0 to 360/z. [°]"""
        return np.asarray(self.result.cage_angle)

    @property
    def ripple_order(self) -> int:
        """Periods of every quantity per cage revolution, ``z``. [-]"""
        return self.balls

    def values(self, key: str) -> np.ndarray | None:
        """The per-position values of ``key`` (one of :data:`SPREAD_KEYS`), None if not given."""
        if key not in SPREAD_KEYS:
            raise InputError("name", f"must be one of {', '.join(SPREAD_KEYS)}")
        if key == "reference_rating_life_hours":
            v = self.hours(self.reference_rating_life)
        elif key in ("contact_angle_max", "reference_rating_life"):
            v = getattr(self, key)
        else:  # the solver's
            v = getattr(self.result, key)
        return None if v is None else np.asarray(v)

    def hours(self, life: Any) -> Any:
        """``life`` [10^6 rev] in hours at :attr:`speed` (None without a speed or a life). [h]"""
        return hours_at(life, self.speed)

    def spread(self, key: str) -> Spread | None:
        """Min, mean, max and peak-to-peak of ``key`` over the pitch (None if not given).

        A mean of a displacement (tilt) below 1e-12 of the largest displacement (tilt) of any
        axis is the solver's rounding noise and is 0 (y and the cross tilt are odd in the cage
        angle)."""
        return family_spread(self.values, key)


def combined_sweep(
    bearing: ResolvedBearing,
    load: float,
    axial_load: float = 0.0,
    *,
    moment: float | None = None,
    misalignment: float | None = None,
    rotating: str = "inner",
    dynamic_rating: float | None = None,
    steps: Any = DEFAULT_STEPS,
    moment_cross: float | None = None,
    tilt_radius: str | float | None = None,
    speed: float | None = None,
    ball_density: float | None = None,
) -> CombinedSweep:
    """Solve a deep-groove ball bearing under a combined load at ``steps`` cage positions.

    Cage angles ``0, p/(steps - 1), ..., p`` with the pitch ``p = 360/z`` degrees, all solved in
    one vectorised call of :func:`bearingload.models.combined.solve_combined` (each position's
    answer is the one a single call at that angle gives: no case depends on its batch); beyond
    :data:`CHUNK_BALLS` ball contacts, in one call per chunk of that size.

    Parameters
    ----------
    bearing : ResolvedBearing
        With known ball geometry (a catalogue designation or D_w, d_m given).
    load, axial_load : float
        F_r >= 0 and F_a (either sign). [N]
    moment : float, optional
        Moment in the plane of the load; default the ring is free to tilt. [N mm]
    misalignment : float, optional
        Imposed tilt in the plane of the load, instead of a moment. [°]
    rotating : {"inner", "outer"}
        Ring rotating relative to the load, for L10r (ISO/TS 16281, 4.3).
    dynamic_rating : float, optional
        C_r replacing the catalogue's (needed for the lives of a hand-given ball set). [N]
    steps : int, default 37
        Cage positions over the pitch, both ends included, 2 to 1 000 000. [-]
    moment_cross : float, optional
        Moment about the load line (MASTA's M_x); None: not given (0). [N mm]
    tilt_radius : {"groove", "pitch"} or float, optional
        Lever of the tilt, see :mod:`bearingload.bearings.tilt`; None: groove. [mm]
    speed, ball_density : float, optional
        Inner ring speed [rpm]: every position solved with the ball dynamics of
        :mod:`bearingload.models.high_speed` (each ball's centrifugal force and gyroscopic
        moment, outer-raceway control), as ``solve --speed`` solves one; the lives also in
        hours at it. Ball density [kg/m^3], default steel. None: the static model.

    Returns
    -------
    CombinedSweep

    Raises
    ------
    InputError
        Fewer than 3 balls, ``steps`` out of range, no ball geometry, a misalignment or a
        moment's tilt beyond 2°; the solver's own errors.

    Examples
    --------
    >>> from bearingload.bearings.resolve import resolve_bearing
    >>> s = combined_sweep(resolve_bearing("6205", clearance=0.0205), 1400.0, 700.0, steps=5)
    >>> s.cage_angle.tolist(), s.q_max_ball.tolist()
    ([0.0, 10.0, 20.0, 30.0, 40.0], [1, 1, 1, 9, 9])
    >>> round(s.spread("reference_rating_life").min, 1) > 0
    True
    """
    from bearingload.bearings.checks import combined_warnings
    from bearingload.bearings.tilt import tilt_lever
    from bearingload.studies.combined_bearing import (
        largest_loaded_angle,
        life_figures,
        solve_on_bearing,
        warned_tilt,
    )

    angles = cage_angles(int(bearing.balls), steps)
    lever = tilt_lever(tilt_radius, bearing.pitch_diameter)
    r = _joined(
        [
            solve_on_bearing(
                bearing,
                load,
                axial_load,
                cage_angle=part,
                moment=moment,
                misalignment=misalignment,
                moment_cross=moment_cross,
                tilt_radius=lever,
                speed=speed,
                ball_density=ball_density,
            )  # fmt: skip
            for part in cage_chunks(angles, int(bearing.balls), CHUNK_BALLS)
        ]
    )
    l10r, p_eq, life, c_r = life_figures(bearing, r, rotating, dynamic_rating)
    loads = np.asarray(r.ball_loads)
    top = loads.max(axis=1, keepdims=True)
    heaviest = np.argmax(loads >= top * (1.0 - TIE), axis=1) + 1
    tilt = float(np.max(warned_tilt(r)))
    found = combined_warnings(bearing, load, axial_load, float(np.max(r.q_max)), 2, tilt)
    found += _groove_side(r, angles) + one_ball_findings(r.loaded_balls, angles)
    return CombinedSweep(
        bearing=bearing,
        result=r,
        misalignment=misalignment,
        rotating=rotating,
        dynamic_rating=c_r,
        equivalent_load=p_eq,
        rating_life=life,
        reference_rating_life=None if l10r is None else np.asarray(l10r, dtype=float),
        q_max_ball=heaviest,
        contact_angle_max=np.asarray(largest_loaded_angle(r), dtype=float),
        warnings=tuple(found),
        moment_cross=moment_cross,
        tilt_radius=lever,
        speed=speed,
    )


def _groove_side(r: CombinedDistribution, angles: np.ndarray) -> list[str]:
    """At a speed, solve's warning on balls whose loaded inner contact sits at 90° (the
    groove's side: :func:`bearingload.studies.combined_bearing.groove_side_warnings`), once,
    with the cage angles where it holds. [°]"""
    from bearingload.studies.combined_bearing import groove_side_warnings

    at = [i for i, w in enumerate(groove_side_warnings(r, angles.size)) if w is not None]
    if not at:
        return []
    return [groove_side_finding(angles[at], angles.size)]


def groove_side_finding(where: Any, steps: int) -> str:
    """solve's warning on balls whose loaded inner contact sits at 90° over a sweep, once:
    ``where`` the cage angles [°] of ``steps`` where it holds."""
    from bearingload.studies.combined_bearing import GROOVE_SIDE_WHY

    where_text = at_cage_angles(where, steps)
    return f"{where_text} the loaded inner contact of a ball sits at 90°{GROOVE_SIDE_WHY}"


def _joined(parts: Sequence[CombinedDistribution]) -> CombinedDistribution:
    """The solutions of consecutive chunks of cage positions as one (the one part as it is;
    at a speed, :class:`bearingload.models.high_speed.HighSpeedDistribution`'s fields too)."""
    if len(parts) == 1:
        return parts[0]
    kind = type(parts[0])
    fixed = {"balls", "model"}
    joined: dict[str, Any] = {
        f.name: getattr(parts[0], f.name)
        if f.name in fixed
        else np.concatenate([getattr(p, f.name) for p in parts])
        for f in dataclasses.fields(kind)
    }
    return kind(**joined)
