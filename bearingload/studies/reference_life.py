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

if TYPE_CHECKING:
    from bearingload.bearings.resolve import ResolvedBearing
    from bearingload.studies.loaded_bearing import LoadedCase


def ball_reference_life(b: ResolvedBearing, ball_loads: Any, rotating: str, c_r: float) -> Any:
    """L10r (ISO/TS 16281:2008, 4.3) of the ball loads Q_j [N] (last axis the z balls) of a ball
    bearing with known D_w, d_m, f_i, f_o, the contact ratings from C_r [N]. [10^6 rev]"""
    from bearingload.bearings.iso16281 import contact_ratings, reference_rating_life

    assert b.ball_diameter and b.pitch_diameter and b.f_i and b.f_o
    q_ci, q_ce = contact_ratings(c_r, b.balls, b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o)
    return reference_rating_life(ball_loads, q_ci, q_ce, rotating)


def has_reference_life(b: ResolvedBearing, dynamic_rating: float | None = None) -> bool:
    """Whether L10r can be computed for ``b``: a ball bearing with its ball geometry and a C_r
    (``dynamic_rating`` or the catalogue's)."""
    return b.kind == "ball" and b.has_geometry and bool(dynamic_rating or b.C)


def with_reference_lives(cases: Sequence[LoadedCase], rotating: str) -> list[LoadedCase]:
    """The radial path's cases (:func:`bearingload.studies.loaded_bearing.solve_bearing`) with
    the reference rating life L10r from the exact model's ball loads, every ball at the contact
    angle 0 (ISO/TS 16281:2008, 4.3; ``rotating`` the ring that turns relative to the load),
    where it can be computed (:func:`has_reference_life`, exact model); others unchanged."""
    out = []
    for c in cases:
        b = c.bearing
        if b is None or c.result.method != "exact" or not has_reference_life(b):
            out.append(c)
            continue
        assert b.C is not None
        life = float(ball_reference_life(b, c.result.model.ball_loads, rotating, b.C))
        out.append(dataclasses.replace(c, reference_rating_life=life, rotating=rotating))
    return out
