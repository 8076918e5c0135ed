"""The life basis of a solved case (:class:`bearingload.bearings.service_life.LifeBasis`): what
its service lives (hours, a_1, a_ISO, the modified lives, the film) take from the case, for
``solve``, ``table life`` and ``batch``'s pairs alike."""

from __future__ import annotations

from typing import Any

__all__ = ["combined_basis", "life_geometry", "radial_basis"]


def life_geometry(b: Any) -> dict[str, Any]:
    """The bearing's part of a :class:`bearingload.bearings.service_life.LifeBasis`."""
    return {
        "kind": b.kind,
        "C0": b.C0,
        "pitch_diameter": b.pitch_diameter,
        "ball_diameter": b.ball_diameter,
        "f_i": b.f_i,
        "f_o": b.f_o,
        "modulus": b.modulus,
        "poisson": b.poisson,
        "roller_length": b.roller_length,
    }


def radial_basis(c: Any, rotating: str | None = None) -> Any:
    """The life basis of a radial case (:class:`bearingload.studies.loaded_bearing.LoadedCase`):
    P = F_r, contact angle 0; ``rotating`` the ring turning (None: the case's, else inner)."""
    from bearingload.bearings.service_life import LifeBasis

    b = c.bearing
    return LifeBasis(
        C=b.C,
        equivalent_load=float(c.result.case.load),
        rating_life=c.rating_life,
        reference_rating_life=c.reference_rating_life,
        q_max=None if c.result.q_max is None else float(c.result.q_max),
        balls=b.balls,
        rotating=rotating or c.rotating or "inner",
        **life_geometry(b),
    )


def combined_basis(c: Any) -> Any:
    """The life basis of a combined-load case: P = X F_r + Y F_a, the heaviest ball at its
    contact angle (its inner and outer ones with the ball dynamics at speed)."""
    import numpy as np

    from bearingload.bearings.service_life import LifeBasis

    res = c.result
    heaviest = int(np.argmax(res.ball_loads))
    outer = getattr(res, "contact_angles_outer", None)  # the ball dynamics at speed
    return LifeBasis(
        C=c.dynamic_rating or c.bearing.C,
        equivalent_load=c.equivalent_load,
        rating_life=c.rating_life,
        reference_rating_life=c.reference_rating_life,
        q_max=float(res.ball_loads[heaviest]),
        contact_angle=float(res.contact_angles[heaviest]),
        contact_angle_outer=None if outer is None else float(outer[heaviest]),
        balls=c.bearing.balls,
        rotating=c.rotating,
        **life_geometry(c.bearing),
    )
