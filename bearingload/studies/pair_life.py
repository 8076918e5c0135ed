"""A pair of angular-contact ball bearings (DB or DF) against its preload: ``table life
7205BDB --preloads ...``.

Every preload is a row, the pair ``solve 7205BDB --preload F_p`` gives at it: all rows in one
vectorised call of :func:`bearingload.studies.bearing_pair.solve_bearing_pairs` (the static
:func:`bearingload.models.pair.solve_pair`; at a ``speed`` the ball dynamics of both bearings,
:func:`bearingload.models.pair_speed.solve_pair_high_speed`, as ``solve 7205BDB --speed``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from bearingload.bearings.resolve import ResolvedBearing
from bearingload.studies.bearing_pair import PairCase


@dataclass(frozen=True)
class LifeAgainstPreload:
    """A bearing pair (DB or DF) at several preloads under one load.

    Attributes
    ----------
    bearing : ResolvedBearing
        One bearing of the pair (both alike).
    cases : tuple of PairCase
        The pair solved at every preload, as ``solve 7205BDB --preload F_p`` solves it.
    warnings : tuple of str
        The findings of every row, each once, in order.
    """

    bearing: ResolvedBearing
    cases: tuple[PairCase, ...]
    warnings: tuple[str, ...] = ()

    @property
    def preloads(self) -> np.ndarray:
        """F_p of every row. [N]"""
        return np.array([float(c.result.preload) for c in self.cases])

    @property
    def model(self) -> str | None:
        """The ball dynamics the rows were solved with (the result's ``model`` of
        :mod:`bearingload.models.pair_speed`); None: the static model."""
        return getattr(self.cases[0].result, "model", None)


def life_against_preload(
    bearing: ResolvedBearing,
    load: float,
    axial_load: float = 0.0,
    *,
    arrangement: str,
    preloads: Any,
    width: float | None = None,
    cage_angle: float = 0.0,
    moment: float | None = None,
    moment_cross: float | None = None,
    tilt_radius: Any = None,
    rotating: str = "inner",
    dynamic_rating: float | None = None,
    speed: float | None = None,
    ball_density: float | None = None,
) -> LifeAgainstPreload:
    """Solve the pair of two bearings ``bearing`` at every preload of ``preloads`` [N] in one
    vectorised call; each row the pair ``solve`` gives at that preload. ``speed`` [rpm] (not
    None): with the ball dynamics of both bearings, ``ball_density`` [kg/m^3] (None: bearing
    steel). The other arguments are those of
    :func:`bearingload.studies.bearing_pair.solve_bearing_pair`.

    >>> from bearingload.bearings.resolve import resolve_bearing
    >>> t = life_against_preload(resolve_bearing("7205B"), 1000.0, 200.0, arrangement="DB",
    ...                          preloads=[0.0, 300.0], speed=10000.0)
    >>> t.preloads.tolist(), t.model is not None
    ([0.0, 300.0], True)
    """
    from bearingload.studies.bearing_pair import solve_bearing_pairs

    fp = np.asarray(preloads, dtype=float).reshape(-1)
    cases = solve_bearing_pairs(
        bearing, np.full(fp.shape, float(load)), np.full(fp.shape, float(axial_load)),
        arrangement=arrangement, preload=fp, width=width, cage_angle=cage_angle,
        moment=moment, moment_cross=moment_cross, tilt_radius=tilt_radius, rotating=rotating,
        dynamic_rating=dynamic_rating, speed=speed, ball_density=ball_density,
    )  # fmt: skip
    found = list(dict.fromkeys(w for c in cases for w in c.warnings))
    return LifeAgainstPreload(bearing, tuple(cases), tuple(found))
