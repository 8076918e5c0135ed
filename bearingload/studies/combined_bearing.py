"""A deep-groove ball bearing under a combined load: the 3-D ring equilibrium and the lives.

The computation behind ``bearingload solve`` with ``--axial-load``, ``--moment``,
``--misalignment``, ``--dynamic-rating`` or ``--rotating``: one :class:`CombinedCase` per clearance
(a class at its min, mean and max gives three). The report only prints it.

Lives: ISO/TS 16281:2008 reference rating life L10r from the ball loads
(:mod:`bearingload.bearings.iso16281`), and ISO 281:2007's basic rating life (C_r/P)^3 with
P = X F_r + Y F_a (clause 5.2, Table 3; needs C0r and f0, i.e. a catalogue bearing; P = F_r
without an axial load).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from bearingload.bearings.resolve import ResolvedBearing
from bearingload.errors import InputError
from bearingload.models.combined import CombinedDistribution

#: The largest imposed misalignment accepted: a tilt of a few degrees would push the balls over
#: the groove shoulders of a deep-groove bearing (which tolerates 2-10 arcmin). [°]
MISALIGNMENT_MAX = 2.0


@dataclass(frozen=True)
class CombinedCase:
    """One solved combined-load case of a bearing and the lives derived from it."""

    bearing: ResolvedBearing
    result: CombinedDistribution
    misalignment: float | None  # [°]
    rotating: str
    dynamic_rating: float | None  # [N]
    equivalent_load: float | None  # [N]
    rating_life: float | None  # [10^6 rev]
    reference_rating_life: float | None  # [10^6 rev]
    warnings: tuple[str, ...] = ()


def solve_combined_bearing(
    bearings: Sequence[ResolvedBearing],
    load: float,
    axial_load: float = 0.0,
    *,
    cage_angle: float = 0.0,
    moment: float | None = None,
    misalignment: float | None = None,
    rotating: str = "inner",
    dynamic_rating: float | None = None,
) -> list[CombinedCase]:
    """Solve each resolved bearing (one per clearance) under F_r, F_a and a moment.

    Parameters
    ----------
    bearings : sequence of ResolvedBearing
        With known ball geometry (D_w, d_m, f_i, f_o).
    load, axial_load : float
        F_r >= 0 and F_a. [N]
    cage_angle : float
        Angle of ball 1 from the load line. [°]
    moment : float, optional
        Moment in the plane of the load; default free tilt. [N mm]
    misalignment : float, optional
        Imposed tilt in the plane of the load. [°]
    rotating : {"inner", "outer"}
        Ring rotating relative to the load (for L10r).
    dynamic_rating : float, optional
        C_r replacing the catalogue's. [N]

    Raises
    ------
    InputError
        ``ball_diameter`` when the geometry is unknown; the solver's own errors.
    """
    from bearingload.bearings.checks import combined_warnings
    from bearingload.models.combined import solve_combined

    if misalignment is not None and abs(misalignment) > MISALIGNMENT_MAX:
        raise InputError(
            "misalignment",
            f"must be within ±{MISALIGNMENT_MAX:g}° (got {misalignment:g}°): a deep-groove ball "
            "bearing tolerates 2-10 arcmin, and a tilt of degrees would push the balls over the "
            "groove shoulders, which the model does not describe",
        )
    out = []
    for b in bearings:
        if not b.has_geometry:
            raise InputError(
                "ball_diameter",
                "the combined load needs the ball geometry: give a bearing designation, or "
                "the ball and pitch diameters",
            )
        r = solve_combined(
            b.balls,
            load,
            axial_load,
            ball_diameter=b.ball_diameter,
            pitch_diameter=b.pitch_diameter,
            f_i=b.f_i,
            f_o=b.f_o,
            clearance=b.clearance,
            cage_angle=cage_angle,
            moment=moment,
            misalignment=misalignment,
            modulus=b.modulus,
            poisson=b.poisson,
            stiffness=b.stiffness if b.stiffness_given else None,
        )
        tilt = math.degrees(
            math.hypot(math.radians(float(r.tilt)), math.radians(float(r.tilt_cross)))
        )
        if moment is not None and misalignment is None and tilt > MISALIGNMENT_MAX:
            raise InputError(
                "moment",
                f"tilts the inner ring by {tilt:.3g}°, beyond ±{MISALIGNMENT_MAX:g}°: the balls "
                "would ride over the groove shoulders, which the model does not describe",
            )
        case = _lives(b, r, misalignment, rotating, dynamic_rating or b.C)
        found = combined_warnings(b, load, axial_load, float(r.q_max), int(r.loaded_balls),
                                  tilt if moment is not None else misalignment)  # fmt: skip
        out.append(dataclasses.replace(case, warnings=tuple(found)))
    return out


def _lives(
    b: ResolvedBearing,
    r: CombinedDistribution,
    misalignment: float | None,
    rotating: str,
    c_r: float | None,
) -> CombinedCase:
    from bearingload.bearings.iso16281 import contact_ratings, reference_rating_life
    from bearingload.bearings.life import equivalent_load_deep_groove, rating_life

    l10r = p_eq = life = None
    if c_r:
        assert b.ball_diameter and b.pitch_diameter and b.f_i and b.f_o
        q_ci, q_ce = contact_ratings(c_r, b.balls, b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o)
        l10r = float(reference_rating_life(r.ball_loads, q_ci, q_ce, rotating))
        fr, fa = float(r.radial_load), float(r.axial_load)
        f0 = None if b.geometry is None else b.geometry.f0
        if fa == 0:
            p_eq = fr
        elif b.C0 is not None and f0 is not None:
            p_eq = float(equivalent_load_deep_groove(fr, fa, b.C0, f0))
        if p_eq:
            life = float(rating_life(c_r, p_eq))
    return CombinedCase(b, r, misalignment, rotating, c_r, p_eq, life, l10r)


def combined_values(c: CombinedCase) -> dict[str, Any]:
    """Every quantity of one case under its key of :mod:`bearingload.reports.quantities`."""
    r, b = c.result, c.bearing
    return {
        "bearing": b.designation or "given by hand",
        "method": "combined",
        "balls": int(r.balls),
        "load": float(r.radial_load),
        "axial_load": float(r.axial_load),
        "moment": float(r.moment),
        "misalignment_deg": c.misalignment,
        "rotating": c.rotating,
        "stiffness": float(b.stiffness),
        "clearance": float(r.clearance),
        "clearance_pick": b.clearance_pick,
        "cage_angle_deg": float(r.cage_angle),
        "free_contact_angle_deg": float(r.free_contact_angle),
        "axial_play": float(r.axial_play),
        "q_max": float(r.q_max),
        "loaded_balls": int(r.loaded_balls),
        "x": float(r.x),
        "y": float(r.y),
        "deflection_axial": float(r.axial),
        "tilt_deg": float(r.tilt),
        "tilt_cross_deg": float(r.tilt_cross),
        "contact_angle_max_deg": _largest_loaded_angle(r),
        "dynamic_rating": c.dynamic_rating,
        "equivalent_load": c.equivalent_load,
        "rating_life": c.rating_life,
        "reference_rating_life": c.reference_rating_life,
    }


def _largest_loaded_angle(r: CombinedDistribution) -> float:
    """The contact angle of largest size among the balls that carry load, with its sign. [°]"""
    import numpy as np

    angles = np.asarray(r.contact_angles, dtype=float).ravel()
    loaded = np.asarray(r.ball_loads, dtype=float).ravel() > 0
    pool = angles[loaded] if loaded.any() else angles
    return float(pool[np.argmax(np.abs(pool))])
