"""The turning cage in a pair of angular-contact ball bearings (DB, DF, DT): the pair's
equilibrium over one ball pitch.

The pair counterpart of :mod:`bearingload.studies.combined_sweep`: both bearings' cages turn
together (ball 1 of each at the same cage angle, as ``solve 7205BDB --cage-angle``), and the
``steps`` positions over one pitch ``360/z`` are solved by one vectorised call of
:func:`bearingload.models.pair.solve_pair` per chunk
(:func:`bearingload.studies.bearing_pair.solve_bearing_pairs`; each position's answer is the one
``solve`` gives at that cage angle). Per position: the shaft's displacement, the pair's
stiffness, each bearing's Q_max and loaded balls, and the pair's L10r.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from bearingload.bearings.resolve import ResolvedBearing
from bearingload.lazy_dataclass import dataclass
from bearingload.studies.bearing_pair import PairCase
from bearingload.studies.sweep import (
    DEFAULT_STEPS,
    Spread,
    cage_angles,
    cage_chunks,
    family_spread,
    hours_at,
)

#: The pair's per-position quantities a pair sweep summarises (keys of reports.quantities).
PAIR_KEYS = ("x", "y", "axial", "tilt", "tilt_cross", "stiffness_radial", "stiffness_axial",
             "stiffness_tilt", "reference_rating_life", "reference_rating_life_hours")  # fmt: skip
#: Each bearing's per-position quantities a pair sweep summarises.
BEARING_KEYS = ("q_max", "loaded_balls")
#: Cage positions times balls solved per call (as a batch of pairs). [-]
CHUNK_BALLS = 2**14


@dataclass(frozen=True)
class PairSweep:
    """A bearing pair at cage positions over one ball pitch, both ends included.

    Attributes
    ----------
    bearing : ResolvedBearing
        One bearing of the pair (both alike).
    cases : tuple of PairCase
        The pair solved at every cage position, as ``solve`` solves it at that cage angle.
    warnings : tuple of str
        The findings of every position, each once, in order.
    speed : float or None
        Shaft speed n for the pair's L10r in hours, L 10^6/(60 n) (the loads are the ball
        dynamics' where the cases carry them, :attr:`model`, else the static model's); None:
        not given. [r/min]
    """

    bearing: ResolvedBearing
    cases: tuple[PairCase, ...]
    warnings: tuple[str, ...] = ()
    speed: float | None = None

    @property
    def balls(self) -> int:
        """Balls per bearing z. [-]"""
        return int(self.bearing.balls)

    @property
    def cage_angle(self) -> np.ndarray:
        """Angle of ball 1 from the load line at every position, 0 to 360/z. [°]"""
        return np.array([float(c.bearings[0].result.cage_angle) for c in self.cases])

    @property
    def model(self) -> str | None:
        """The ball dynamics the positions were solved with (the result's ``model`` of
        :mod:`bearingload.models.pair_speed`), as a pair's table life names it; None: the static
        model."""
        return getattr(self.cases[0].result, "model", None)

    def values(self, key: str, bearing: int | None = None) -> np.ndarray | None:
        """The per-position values of the pair's ``key`` (:data:`PAIR_KEYS`), or of bearing
        ``bearing`` (1 or 2; :data:`BEARING_KEYS`); None where a position has none (L10r
        without C_r)."""
        if key == "reference_rating_life_hours":
            life = self.values("reference_rating_life")
            return None if life is None else hours_at(life, self.speed)
        if bearing is None:
            got = [getattr(c, key) if key == "reference_rating_life" else getattr(c.result, key)
                   for c in self.cases]  # fmt: skip
        else:
            got = [getattr(c.bearings[bearing - 1].result, key) for c in self.cases]
        if any(v is None for v in got):
            return None
        return np.asarray(got, dtype=float)

    def spread(self, key: str, bearing: int | None = None) -> Spread | None:
        """Min, mean, max and peak-to-peak of ``key`` over the pitch (None if not given); a
        mean of a displacement (tilt) below 1e-12 of the largest of any axis is 0, as for one
        bearing's sweep."""
        return family_spread(lambda k: self.values(k, bearing), key)


def pair_sweep(
    bearing: ResolvedBearing,
    load: float,
    axial_load: float = 0.0,
    *,
    arrangement: str,
    preload: float = 0.0,
    width: float | None = None,
    moment: float | None = None,
    moment_cross: float | None = None,
    tilt_radius: Any = None,
    rotating: str = "inner",
    dynamic_rating: float | None = None,
    steps: Any = DEFAULT_STEPS,
    speed: float | None = None,
    ball_density: float | None = None,
) -> PairSweep:
    """Solve the pair of two bearings ``bearing`` at ``steps`` cage positions over one pitch.

    The arguments are those of :func:`bearingload.studies.bearing_pair.solve_bearing_pair`
    (the cage angle is what turns; ``speed`` [rpm]: every position with the ball dynamics of
    both bearings, and the pair's L10r in hours at it; ``ball_density`` [kg/m^3]) and
    ``steps`` (2 to 1 000 000, both ends included).

    >>> from bearingload.bearings.resolve import resolve_bearing
    >>> s = pair_sweep(resolve_bearing("7205B"), 1000.0, 200.0, arrangement="DB",
    ...                preload=300.0, steps=3)
    >>> s.cage_angle.tolist()
    [0.0, 15.0, 30.0]
    """
    from bearingload.studies.bearing_pair import solve_bearing_pairs

    angles = cage_angles(int(bearing.balls), steps)
    cases: list[PairCase] = []
    for part in cage_chunks(angles, int(bearing.balls), CHUNK_BALLS):
        cases += solve_bearing_pairs(
            bearing, np.full(part.shape, float(load)), np.full(part.shape, float(axial_load)),
            arrangement=arrangement, preload=preload, width=width, cage_angle=part,
            moment=moment, moment_cross=moment_cross, tilt_radius=tilt_radius,
            rotating=rotating, dynamic_rating=dynamic_rating, speed=speed,
            ball_density=ball_density,
        )  # fmt: skip
    return PairSweep(bearing, tuple(cases), tuple(_findings(cases, angles)), speed)


def _findings(cases: list[PairCase], angles: np.ndarray) -> list[str]:
    """The findings of every position, each once, in order; the warning on balls whose loaded
    inner contact sits at 90° (it names the balls of one position) once per bearing, with the
    cage angles where it holds, as one bearing's sweep gives it. [°]"""
    from bearingload.studies.combined_bearing import GROOVE_SIDE
    from bearingload.studies.combined_sweep import groove_side_finding

    found: list[str] = []
    at: dict[str, list[float]] = {}
    for c, angle in zip(cases, angles.tolist(), strict=True):
        for w in c.warnings:
            if GROOVE_SIDE in w and w.startswith("bearing "):
                at.setdefault(w.split(":", 1)[0], []).append(angle)
            elif w not in found:
                found.append(w)
    for who, where in sorted(at.items()):
        found.append(f"{who}: {groove_side_finding(where, len(cases))}")
    return found
