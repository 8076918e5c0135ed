"""Reference rating life L10r against the radial internal clearance, from preload to large play.

The question of Oswald, Zaretsky & Poplawski (*Effect of Internal Clearance on Load Distribution
and Life of Radially Loaded Ball and Roller Bearings*, NASA TM-2012-217115, 2012): which
clearance gives the longest life, and how a slight preload compares with a clearance.
:func:`life_against_clearance` answers it for any deep-groove ball bearing (a catalogue
designation, or a hand-given ball set with its C_r) under a radial load, an axial load and a
moment or misalignment: the ISO/TS 16281:2008 life (clause 4.3) from the load distribution of
:func:`bearingload.models.combined.solve_combined` (exact Hertz stiffness at each contact angle,
ring free to tilt unless a moment or misalignment is given), every clearance in one vectorised
call. ISO 281's basic life (C_r/P)^3 with P = X F_r + Y F_a (normal clearance) does not see the
clearance; it is given beside. At a ``speed`` every row is solved with the ball dynamics of
:func:`bearingload.models.high_speed.solve_high_speed` instead (each ball's centrifugal force and
gyroscopic moment, as ``solve --speed`` solves a ball bearing). ``bearingload table life``
prints it.

The committed table ``tables/life_vs_clearance_6205`` is :func:`life_vs_clearance`: the same
computation for the catalogue bearing 6205 (docs/guide.md).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass

if TYPE_CHECKING:
    from bearingload.bearings.resolve import ResolvedBearing

#: The committed study's bearing and loads. [N]
DESIGNATION = "6205"
RADIAL_LOAD = 1400.0  # C_r / 10
AXIAL_LOAD = 700.0
#: Radial internal clearances G_r of the rows at a bore of 25 mm, from preload to large play
#: (C5 ends at 53 um there); other bores scale them by their C5 maximum (ISO 5753-1). [um]
CLEARANCES_UM = (-20, -15, -10, -8, -6, -4, -2, 0, 2, 4, 6, 8, 10, 15, 20, 30, 40, 60, 80)
#: C5 maximum of ISO 5753-1 at the bore of :data:`CLEARANCES_UM` (24 < d <= 30 mm). [mm]
REFERENCE_C5_MAX = 0.053


@dataclass(frozen=True)
class LifeAgainstClearance:
    """L10r of one bearing under one load at a list of clearances.

    Attributes
    ----------
    bearing : ResolvedBearing
        The bearing (its geometry and ratings).
    load, axial_load : float
        F_r and F_a. [N]
    moment, misalignment : float or None
        Applied moment [N mm] or imposed tilt [°]; both None: the ring is free to tilt.
    cage_angle : float
        Angle of ball 1 from the load line. [°]
    rotating : str
        The ring rotating relative to the load.
    dynamic_rating : float
        C_r. [N]
    clearance : ndarray
        G_r of the rows (negative = preload). [mm]
    free_contact_angle, contact_angle_max : ndarray
        alpha_0 and the largest contact angle of a loaded ball, with its sign. [°]
    loaded_balls : ndarray of int
        Balls carrying load. [-]
    q_max : ndarray
        Heaviest ball load. [N]
    reference_rating_life : ndarray
        ISO/TS 16281 L10r. [10^6 rev]
    relative_life : ndarray
        L10r over L10r at G_r = 0 (solved in the same call when not among the rows). [-]
    equivalent_load, rating_life : float or None
        ISO 281's P = X F_r + Y F_a [N] and (C_r/P)^3 [10^6 rev]; None where P needs C0r and
        f0 that a hand-given ball set does not have.
    warnings : tuple of str
        The checks of ``solve`` (static safety, contact pressure, one loaded ball) over the rows.
    moment_cross, tilt_radius : float or None
        Moment applied about the load line [N mm] and the lever of the tilt [mm]; None: not
        given (0, and the solver's R_i).
    model : str or None
        The ball dynamics the rows were solved with at a speed (the result's ``model`` of
        :mod:`bearingload.models.high_speed`); None: the static model.
    speed, ball_density : float or None
        Shaft speed [rpm] and ball density [kg/m^3] of the ball dynamics; None: the static
        model.
    heaviest_contact_angle : ndarray or None
        Each row's contact angle of its heaviest ball (the film's, as solve's). [°]
    thrust_neglected, tilt_undetermined, displacement_undetermined : ndarray of bool or None
        The solver's flags of each row (:class:`~bearingload.models.combined.
        CombinedDistribution`): a thrust it left out, a tilt the loads do not determine, at
        speed a position they do not determine.
    """

    bearing: ResolvedBearing
    load: float
    axial_load: float
    moment: float | None
    misalignment: float | None
    cage_angle: float
    rotating: str
    dynamic_rating: float
    clearance: np.ndarray
    free_contact_angle: np.ndarray
    contact_angle_max: np.ndarray
    loaded_balls: np.ndarray
    q_max: np.ndarray
    reference_rating_life: np.ndarray
    relative_life: np.ndarray
    equivalent_load: float | None
    rating_life: float | None
    warnings: tuple[str, ...] = ()
    moment_cross: float | None = None
    tilt_radius: float | None = None
    model: str | None = None
    heaviest_contact_angle: np.ndarray | None = None
    speed: float | None = None
    ball_density: float | None = None
    thrust_neglected: np.ndarray | None = None
    tilt_undetermined: np.ndarray | None = None
    displacement_undetermined: np.ndarray | None = None


def _rows(flags: Any, n: int) -> np.ndarray | None:
    """The solver's flags of the first ``n`` rows (bools), None where it gives none."""
    return None if flags is None else np.asarray(flags, dtype=bool).reshape(-1)[:n]


def default_clearances(bearing: ResolvedBearing) -> np.ndarray:
    """The rows' clearances for ``bearing``: :data:`CLEARANCES_UM` scaled by the largest class's
    maximum of ISO 5753-1 at its bore (C5; C3 up to a 6 mm bore) over the C5 maximum at 25 mm,
    to 0.1 um. [mm]

    A hand-given ball set has no bore: it is taken as d_m - 1.5 D_w (6205: 26.6 mm for 25 mm;
    6305 and 306 within 3 mm), clamped to the bores of the clearance table (6 to 400 mm).
    """
    from bearingload.bearings.clearance import largest_class, table

    rows = table()
    if bearing.geometry is not None:
        bore = float(bearing.geometry.d)
    else:
        assert bearing.pitch_diameter is not None and bearing.ball_diameter is not None
        bore = bearing.pitch_diameter - 1.5 * bearing.ball_diameter
    bore = min(max(bore, rows[0].bore_over + 1e-9), rows[-1].bore_incl)
    scale = largest_class(bore)[1] / REFERENCE_C5_MAX
    values = np.round(np.asarray(CLEARANCES_UM, dtype=float) * scale, 1)
    return np.unique(values) * 1e-3


def life_against_clearance(
    bearing: ResolvedBearing,
    load: float,
    axial_load: float = 0.0,
    *,
    clearances: Any = None,
    cage_angle: float = 0.0,
    moment: float | None = None,
    misalignment: float | None = None,
    rotating: str = "inner",
    dynamic_rating: float | None = None,
    moment_cross: float | None = None,
    tilt_radius: str | float | None = None,
    speed: float | None = None,
    ball_density: float | None = None,
) -> LifeAgainstClearance:
    """The ISO/TS 16281 life of ``bearing`` at a list of clearances, in one vectorised solve.

    Parameters
    ----------
    bearing : ResolvedBearing
        A deep-groove ball bearing with its ball geometry (its own clearance is not used).
    load, axial_load : float
        F_r >= 0 and F_a. [N]
    clearances : array_like, optional
        G_r of the rows, each below 2 (f_i + f_o - 1) D_w; default :func:`default_clearances`. [mm]
    cage_angle : float, default 0
        Angle of ball 1 from the load line. [°]
    moment, misalignment : float, optional
        Moment in the load plane [N mm] or imposed tilt [°]; default the ring is free to tilt.
    rotating : {"inner", "outer"}
        Ring rotating relative to the load (ISO/TS 16281, 4.3).
    dynamic_rating : float, optional
        C_r replacing the catalogue's; needed for a hand-given ball set. [N]
    moment_cross, tilt_radius : optional
        Moment about the load line [N mm] and the lever of the tilt
        (:mod:`bearingload.bearings.tilt`), as :func:`bearingload.studies.combined_bearing.
        solve_combined_bearing` takes them.
    speed, ball_density : float, optional
        Inner ring speed [rpm]: every row with the ball dynamics (centrifugal force, gyroscopic
        moment; :mod:`bearingload.models.high_speed`), as ``solve --speed``; ball density
        [kg/m^3], default bearing steel. None: the static model.

    Returns
    -------
    LifeAgainstClearance

    Raises
    ------
    InputError
        ``dynamic_rating`` when C_r is unknown, ``clearance`` for an empty or non-finite list,
        ``rotating`` "outer" with a speed; those of
        :func:`bearingload.studies.combined_bearing.solve_on_bearing`.
    ConvergenceError
        Where the ball dynamics leave a row unbalanced.

    Examples
    --------
    NASA TM-2012-217115's finding for a radially loaded ball bearing: a slight preload lives
    longer than zero clearance.

    >>> from bearingload.bearings.resolve import resolve_bearing
    >>> t = life_against_clearance(resolve_bearing("6205"), 1400.0, clearances=[-0.01, 0.0, 0.03])
    >>> t.relative_life.round(3).tolist()
    [1.116, 1.0, 0.766]
    """
    from bearingload.bearings.checks import combined_warnings
    from bearingload.bearings.tilt import tilt_lever
    from bearingload.studies.combined_bearing import (
        largest_loaded_angle,
        life_figures,
        refuse_outer_at_speed,
        solve_on_bearing,
        warned_tilt,
    )

    refuse_outer_at_speed(speed, rotating)
    if not (dynamic_rating or bearing.C):
        raise InputError(
            "dynamic_rating",
            "the life needs the basic dynamic load rating C_r: a ball set given by hand has "
            "none; give it",
        )
    g = default_clearances(bearing) if clearances is None else np.asarray(clearances, float)
    if g.ndim != 1 or g.size == 0 or not np.all(np.isfinite(g)):
        raise InputError("clearance", "must be a non-empty list of finite lengths")
    with_zero = g if np.any(g == 0) else np.append(g, 0.0)
    lever = tilt_lever(tilt_radius, bearing.pitch_diameter)
    r = solve_on_bearing(bearing, load, axial_load, cage_angle=cage_angle, moment=moment,
                         misalignment=misalignment, clearance=with_zero,
                         moment_cross=moment_cross, tilt_radius=lever, speed=speed,
                         ball_density=ball_density)  # fmt: skip
    l10r, p_eq, life, c_r = life_figures(bearing, r, rotating, dynamic_rating)
    assert l10r is not None and c_r is not None
    zero = float(l10r[int(np.flatnonzero(with_zero == 0)[0])])
    n = g.size
    tilt = float(np.max(warned_tilt(r)[:n]))
    found = combined_warnings(bearing, load, axial_load, float(np.max(r.q_max[:n])), 2, tilt)
    one = np.asarray(r.loaded_balls)[:n] == 1
    if one.any() and bearing.balls > 1:
        at = ", ".join(f"{v * 1e3:.6g}" for v in g[one])
        found.append(
            f"only one ball carries the load at G_r = {at} µm: those rows hang on a single "
            "contact (large clearance or few elements)"
        )
    found += _groove_side(r, g)
    return LifeAgainstClearance(
        bearing=bearing,
        load=float(load),
        axial_load=float(axial_load),
        moment=moment,
        misalignment=misalignment,
        cage_angle=float(cage_angle),
        rotating=rotating,
        dynamic_rating=float(c_r),
        clearance=g,
        free_contact_angle=np.asarray(r.free_contact_angle)[:n],
        contact_angle_max=np.asarray(largest_loaded_angle(r))[:n],
        loaded_balls=np.asarray(r.loaded_balls)[:n],
        q_max=np.asarray(r.q_max)[:n],
        reference_rating_life=np.asarray(l10r)[:n],
        relative_life=np.asarray(l10r)[:n] / zero,
        equivalent_load=p_eq,
        rating_life=life,
        warnings=tuple(found),
        moment_cross=moment_cross,
        tilt_radius=lever,
        model=getattr(r, "model", None),
        speed=None if speed is None else float(speed),
        ball_density=_density(r),
        heaviest_contact_angle=_heaviest_angle(r)[:n],
        thrust_neglected=_rows(getattr(r, "thrust_neglected", None), n),
        tilt_undetermined=_rows(getattr(r, "tilt_undetermined", None), n),
        displacement_undetermined=_rows(getattr(r, "displacement_undetermined", None), n),
    )


def _heaviest_angle(r: Any) -> np.ndarray:
    """Each row's contact angle of its heaviest ball (of two equal, the first), the angle the
    film takes, as solve takes it (:func:`bearingload.studies.life_basis.combined_basis`). [°]"""
    loads = np.asarray(r.ball_loads, dtype=float)
    heaviest = np.argmax(loads, axis=-1)[..., None]
    return np.take_along_axis(np.asarray(r.contact_angles, dtype=float), heaviest, -1)[..., 0]


def _density(r: Any) -> float | None:
    """The ball density of the ball dynamics solved in ``r`` [kg/m^3]; None: static."""
    density = getattr(r, "ball_density", None)
    return None if density is None else float(np.asarray(density).flat[0])


def _groove_side(r: Any, g: np.ndarray) -> list[str]:
    """At a speed, the rows of ``r`` (clearances ``g`` [mm] first) where a loaded inner contact
    sits at 90° on the side of the inner groove (the ball dynamics' limit, as ``solve`` warns
    it), one finding naming them; none for the static model."""
    from bearingload.studies.combined_bearing import groove_side_warnings

    sides = groove_side_warnings(r, np.size(r.q_max))[: g.size]
    rows = [g[i] for i, w in enumerate(sides) if w is not None]
    if not rows:
        return []
    at = ", ".join(f"{v * 1e3:.6g}" for v in rows)
    return [
        f"at G_r = {at} µm a loaded inner contact sits at 90°, on the side of the inner groove, "
        "where the ball dynamics hold the ball (a real ball rides onto the groove shoulder) and "
        "overstate its orbit speed and centrifugal force: those rows are outside what the "
        "model describes"
    ]


def life_vs_clearance(
    clearances_um: tuple[float, ...] = CLEARANCES_UM,
) -> tuple[list[dict[str, float]], LifeAgainstClearance, LifeAgainstClearance]:
    """Rows of G_r [um], alpha_0 [°], loaded balls, Q_max [N], L10r [10^6 rev] for F_r alone and
    for F_r with F_a, and L10r relative to zero clearance: two :func:`life_against_clearance`
    side by side (inner ring rotating, a ball under the load); and those two, whose ISO 281 P
    and (C_r/P)^3, blind to the clearance, the committed table states beside its rows."""
    from bearingload.bearings.resolve import resolve_bearing

    b = resolve_bearing(DESIGNATION, clearance=0.0)
    g = np.asarray(clearances_um, dtype=float) * 1e-3
    radial = life_against_clearance(b, RADIAL_LOAD, 0.0, clearances=g)
    combined = life_against_clearance(b, RADIAL_LOAD, AXIAL_LOAD, clearances=g)
    rows = []
    for i, gr in enumerate(clearances_um):
        rows.append(
            {
                "clearance_um": float(gr),
                "free_contact_angle": float(radial.free_contact_angle[i]),
                "loaded_r": int(radial.loaded_balls[i]),
                "q_max_r": float(radial.q_max[i]),
                "life_r": float(radial.reference_rating_life[i]),
                "ratio_r": float(radial.relative_life[i]),
                "loaded_c": int(combined.loaded_balls[i]),
                "alpha_max_c": float(combined.contact_angle_max[i]),
                "q_max_c": float(combined.q_max[i]),
                "life_c": float(combined.reference_rating_life[i]),
                "ratio_c": float(combined.relative_life[i]),
            }
        )
    return rows, radial, combined
