"""The ISO/TS 16281 reference rating life L10r of a solved ball bearing, from its ball loads.

:func:`with_reference_lives` gives the radial path of ``bearingload solve`` (the radial engine,
every ball at the contact angle 0) the L10r the combined path gives
(:mod:`bearingload.studies.combined_bearing`); both call :func:`ball_reference_life`. Kept
apart from the combined-load module so that a radial calculation imports none of it.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from bearingload.bearings.resolve import ResolvedBearing
    from bearingload.studies.loaded_bearing import LoadedCase


def ball_reference_life(
    b: ResolvedBearing, ball_loads: Any, rotating: str, c_r: float, outer_loads: Any = None
) -> Any:
    """L10r (ISO/TS 16281:2008, 4.3) of the ball loads Q_j [N] (last axis the z balls) of a ball
    bearing with known D_w, d_m, f_i, f_o, the contact ratings from C_r [N]; ``outer_loads``:
    the outer contacts' loads where they differ (ball dynamics at speed). [10^6 rev]"""
    from bearingload.bearings.iso16281 import contact_ratings, reference_rating_life

    assert b.ball_diameter and b.pitch_diameter and b.f_i and b.f_o
    q_ci, q_ce = contact_ratings(c_r, b.balls, b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o,
                                 contact_angle=b.contact_angle or 0.0)  # fmt: skip
    return reference_rating_life(ball_loads, q_ci, q_ce, rotating, outer_loads=outer_loads)


def has_reference_life(b: ResolvedBearing, dynamic_rating: float | None = None) -> bool:
    """Whether L10r can be computed for ``b``: a ball bearing with its ball geometry and a C_r
    (``dynamic_rating`` or the catalogue's)."""
    return b.kind == "ball" and b.has_geometry and bool(dynamic_rating or b.C)


def with_reference_lives(cases: Sequence[LoadedCase], rotating: str) -> list[LoadedCase]:
    """The radial path's cases (:func:`bearingload.studies.loaded_bearing.solve_bearing`) with
    the reference rating life L10r from the exact model's ball loads, every ball at the contact
    angle 0 (ISO/TS 16281:2008, 4.3; ``rotating`` the ring that turns relative to the load),
    where it can be computed (:func:`has_reference_life`, exact model); others unchanged. A
    case holding many cases gets an array of lives."""
    out = []
    for c in cases:
        b = c.bearing
        if b is None or c.result.method != "exact" or not has_reference_life(b):
            out.append(c)
            continue
        assert b.C is not None
        many = c.result.case.shape != ()
        loads = all_ball_loads(c.result.model) if many else c.result.model.ball_loads
        life = ball_reference_life(b, loads, rotating, b.C)
        life = np.asarray(life).reshape(-1) if many else float(life)
        out.append(dataclasses.replace(c, reference_rating_life=life, rotating=rotating))
    return out


def all_ball_loads(model: Any) -> np.ndarray:
    """Loads Q_i [N] of balls 1..z (ball 1 at the cage angle) of every case of the exact
    model's result (one z), one row per case, as
    :attr:`bearingload.models.equilibrium.LoadDistribution.ball_loads` gives them one by one."""
    delta = all_ball_approaches(model)
    return _per_case(model, "stiffness") * np.maximum(delta, 0.0) ** _per_case(model, "exponent")


def all_ball_approaches(model: Any) -> np.ndarray:
    """Approach [mm] of balls 1..z of every case of the exact model's result, one row per case:
    the engine's own :func:`bearingload.models.equilibrium.ball_approaches` (from the reference
    position, so that a clearance much larger than the elastic approach costs no digits; under
    preload from the centred ring, every ball pressed by -G_r/2 plus the ring's displacement)."""
    from bearingload.models.equilibrium import ball_approaches

    n = int(np.size(model.x))
    z = int(np.asarray(model.balls).reshape(-1)[0])
    reference, offset = (
        np.broadcast_to(a, (*np.shape(model.x), 2)).reshape(n, 2)
        for a in (model.reference, model.offset)
    )
    angle, clearance, x, y = (_per_case(model, k) for k in ("cage_angle", "clearance", "x", "y"))
    return ball_approaches(z, angle, clearance, x, y, reference, offset)


def _per_case(model: Any, name: str) -> np.ndarray:
    """``name`` of every case of ``model`` as a column, one row per case."""
    return np.broadcast_to(getattr(model, name), np.shape(model.x)).reshape(-1, 1)
