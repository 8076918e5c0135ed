"""A deep-groove ball bearing under a combined load: the 3-D ring equilibrium and the lives.

The computation behind ``bearingload solve`` with ``--axial-load``, ``--moment``,
``--moment-cross``, ``--misalignment``, ``--dynamic-rating`` or ``--rotating``: one
:class:`CombinedCase` per clearance (a class at its min, mean and max gives three). The report
only prints it. The lever of the tilt (``groove``, ``pitch`` or a length) is read by
:mod:`bearingload.bearings.tilt`.

Lives: ISO/TS 16281:2008 reference rating life L10r from the ball loads
(:mod:`bearingload.bearings.iso16281`), and ISO 281:2007's basic rating life (C_r/P)^3 with
P = X F_r + Y F_a (clause 5.2, Table 3; needs C0r and f0, i.e. a catalogue bearing; P = F_r
without an axial load).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload import validate
from bearingload.bearings.mounting import result_fields
from bearingload.bearings.resolve import ResolvedBearing
from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.studies.matrix import matrix_columns

if TYPE_CHECKING:  # the solver is imported where a case is solved
    from bearingload.models.combined import CombinedDistribution


@dataclass(frozen=True)
class CombinedCase:
    """One solved combined-load case of a bearing and what derives from it: lives, the largest
    contact pressures and the static safety."""

    bearing: ResolvedBearing
    result: CombinedDistribution
    misalignment: float | None  # [°]
    rotating: str
    dynamic_rating: float | None  # [N]
    equivalent_load: float | None  # [N]
    rating_life: float | None  # [10^6 rev]
    reference_rating_life: float | None  # [10^6 rev]
    warnings: tuple[Any, ...] = ()  # one case: its sentences; many: a tuple per case
    p_max_inner: float | None = None  # largest over the balls, each at its contact angle [MPa]
    p_max_outer: float | None = None  # [MPa]
    static_equivalent_load: float | None = None  # P0, ISO 76 [N]
    static_safety: float | None = None  # s0 = C0/P0 [-]
    moment_cross: float | None = None  # applied, about the load line; None: not given [N mm]


def solve_combined_bearing(
    bearings: Sequence[ResolvedBearing],
    load: Any,
    axial_load: Any = 0.0,
    *,
    cage_angle: Any = 0.0,
    moment: Any = None,
    misalignment: Any = None,
    rotating: str = "inner",
    dynamic_rating: float | None = None,
    moment_cross: Any = None,
    tilt_radius: Any = None,
    speed: Any = None,
    ball_density: Any = None,
) -> list[CombinedCase]:
    """Solve each resolved bearing (one per clearance) under F_r, F_a and the moments; arrays of
    loads, cage angles and moments solve many cases in one call (each
    :class:`CombinedCase` then holds arrays or lists over them, ``warnings`` a tuple per case).

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
    moment_cross : float, optional
        Moment about the load line (MASTA's M_x); None: not given (0). [N mm]
    tilt_radius : {"groove", "pitch"}, float or ndarray, optional
        Lever of the tilt, see :mod:`bearingload.bearings.tilt`; None: groove; an array: the
        lever of each case. [mm]
    speed, ball_density : float, optional
        Shaft speed [rpm] of the inner ring: the balls' centrifugal force and gyroscopic
        moment are included (:mod:`bearingload.models.high_speed`); None: the static model.
        Ball density [kg/m^3], default bearing steel.

    Raises
    ------
    InputError
        ``ball_diameter`` when the geometry is unknown; ``rotating`` "outer" with a speed (the
        ball dynamics are those of the inner ring turning); the solver's own errors.
    """
    from bearingload.bearings.tilt import tilt_lever

    refuse_outer_at_speed(speed, rotating)
    out = []
    for b in bearings:
        lever = (tilt_radius if isinstance(tilt_radius, np.ndarray)
                 else tilt_lever(tilt_radius, b.pitch_diameter))  # fmt: skip
        r = solve_on_bearing(b, load, axial_load, cage_angle=cage_angle, moment=moment,
                             misalignment=misalignment, moment_cross=moment_cross,
                             tilt_radius=lever, speed=speed, ball_density=ball_density)  # fmt: skip
        out.append(combined_case(b, r, load, axial_load, misalignment, moment_cross, lever,
                                  rotating, dynamic_rating))  # fmt: skip
    return out


def combined_case(
    b: ResolvedBearing, r: CombinedDistribution, load: Any, axial_load: Any, misalignment: Any,
    moment_cross: Any, lever: Any, rotating: str, dynamic_rating: Any,
) -> CombinedCase:  # fmt: skip
    """What derives from the solved case(s) ``r``: lives, the largest contact pressures, P0,
    s0 and the checks of every case (one case: numbers; many: arrays or lists)."""
    from bearingload.bearings.checks import (
        combined_warnings,
        contact_pressures,
        static_equivalent_load,
        static_equivalent_load_angular,
        static_safety,
    )
    from bearingload.bearings.tilt import lever_warning

    shape = np.shape(r.q_max)

    def each(value: Any) -> list[Any]:
        return np.broadcast_to(np.asarray(value, dtype=float), shape).ravel().tolist()

    c_r = dynamic_rating or b.C
    l10r = p_eq = life = None
    if c_r:
        l10r = reference_lives(b, r, rotating, c_r)
        p_eq, life = basic_lives(b, c_r, load, axial_load)
    found = contact_pressures(b, r.ball_loads, r.contact_angles)
    outer = getattr(r, "ball_loads_outer", None)  # at speed: each ball's outer contact apart
    if found is not None and outer is not None:
        angles = getattr(r, "contact_angles_outer", None)
        found = (found[0], contact_pressures(b, outer, angles)[1])
    p_i = p_o = None
    if found is not None:
        p_i, p_o = np.max(found[0], axis=-1), np.max(found[1], axis=-1)
    fr, fa, q = each(load), each(axial_load), each(r.q_max)
    loaded = np.broadcast_to(r.loaded_balls, shape).ravel().tolist()
    warned = each(warned_tilt(r))  # the ring's tilt, whatever gives it
    inner = (
        [None] * len(q)
        if p_i is None or p_o is None
        else list(zip(each(p_i), each(p_o), strict=True))
    )
    p0 = [static_equivalent_load(f, a) if b.contact_angle is None
          else static_equivalent_load_angular(f, a, b.contact_angle)
          for f, a in zip(fr, fa, strict=True)]  # fmt: skip
    s0 = [None if p is None else static_safety(b.C0, p) for p in p0]
    # each case's own lever (a batch gives one per row; None for groove and pitch)
    levers = [None] * len(q) if lever is None else each(lever)
    said = [lever_warning(x, b.pitch_diameter) for x in levers]
    sides = groove_side_warnings(r, len(q))

    def flags(name: str) -> list[bool]:  # the solver's flag of each case (none: all False)
        given = getattr(r, name, None)
        return [False] * len(q) if given is None else np.reshape(given, -1).tolist()

    undetermined = ("tilt_undetermined", "displacement_undetermined", "thrust_neglected")
    tilt_free, loose, left = (flags(name) for name in undetermined)
    per_case = []
    for i in range(len(q)):
        got = combined_warnings(b, fr[i], fa[i], q[i], int(loaded[i]), warned[i], inner[i])
        got += [w for w in (said[i], sides[i]) if w]
        got += [TILT_UNDETERMINED] if tilt_free[i] else []
        got += [POSITION_UNDETERMINED] if loose[i] else []
        got += [thrust_neglected_warning(fa[i], fr[i])] if left[i] else []
        per_case.append(tuple(got))
    checks = tuple(per_case)
    if shape == ():
        p_eq = None if p_eq is None else float(p_eq)
        life = None if life is None or np.isnan(life) else float(life)
        return CombinedCase(b, r, misalignment, rotating, c_r, p_eq, life,
                            None if l10r is None else float(l10r), checks[0],
                            None if p_i is None else float(p_i), None if p_o is None else float(p_o),
                            p0[0], s0[0], moment_cross)  # fmt: skip
    return CombinedCase(b, r, misalignment, rotating, c_r, p_eq, life, l10r, checks, p_i, p_o,
                        p0, s0, moment_cross)  # type: ignore[arg-type]  # fmt: skip


#: The warning on a ring whose tilt the loads do not determine (the solver's ``tilt_undetermined``).
TILT_UNDETERMINED = (
    "the loads do not determine the ring's tilt: a range of tilts balances them (the balls that "
    "carry load leave one tilt free, as with a few balls of an angular-contact bearing under a "
    "light thrust); the tilt given is the least of the range (where the solver could not reach "
    "it, one tilt of the range), and the ball loads are the same at every tilt of it"
)


#: The warning on a ring at speed with a free direction of no stiffness (the solver's
#: ``displacement_undetermined``).
POSITION_UNDETERMINED = (
    "the loads do not determine the ring's position in one direction: its stiffness there is "
    "about 0 (at most 1e-9 of the largest in the stiffness matrix), so a range of positions "
    "balances them (as one loaded ball on the load line leaves y free); the displacement given "
    "is one of the range, where the solver stopped, and a cage angle a little off may give "
    "another"
)


def thrust_neglected_warning(axial_load: float, radial_load: float) -> str:
    """The warning on a thrust the solver left out (the solver's ``thrust_neglected``)."""
    return (
        f"the thrust F_a = {abs(axial_load):.3g} N is below 1e-12 of the largest load "
        f"({radial_load:.6g} N) and beyond what the ring's axial position resolves here: the "
        "case is solved with a thrust of 1e-12 of that load (the limit of a thrust going to 0; "
        "a thrust, however small, pushes the ring across its axial play), the difference its "
        "balance error"
    )


#: The warning on a ball whose loaded inner contact sits on the groove's side at speed: what
#: happens, and (after it) why the result is outside the model.
GROOVE_SIDE = "the loaded inner contact sits at 90°"
GROOVE_SIDE_WHY = (
    ", on the side of the inner groove, where the model holds the ball (a real ball rides onto "
    "the groove shoulder) and takes its orbit speed and centrifugal force from Jones's relations "
    "at that angle, which overstate them: the result is outside what the model describes"
)


def groove_side_warnings(r: Any, n: int) -> list[str | None]:
    """Per case of ``r`` (``n`` cases): at a speed (the ball dynamics), the balls whose loaded
    inner contact sits at 90°, on the side of the inner groove, which the model holds them on
    (docs/speed.md, known limits); None where there is none, and always without a speed."""
    if getattr(r, "speed", None) is None:
        return [None] * n
    angles = np.asarray(r.contact_angles_inner, dtype=float).reshape(n, -1)
    loads = np.asarray(r.ball_loads_inner, dtype=float).reshape(n, -1)
    out: list[str | None] = []
    for side in (loads > 0) & (angles >= 90.0 - 1e-9):
        balls = ", ".join(str(j + 1) for j in np.flatnonzero(side))
        out.append(f"ball(s) {balls}: {GROOVE_SIDE}{GROOVE_SIDE_WHY}" if balls else None)
    return out


#: The share of the largest ball approach below which the balls do not feel a tilt: a tilt moving
#: the groove centres at the tilt's lever by at most this share (R_i theta <= 1e-7 delta_max)
#: changes no ball load by more than 1.5e-7 of the heaviest (Q ~ delta^1.5), under the six digits
#: the results print: the ring is aligned as far as its balls tell, and the tilt is no finding
#: (a pair's shaft takes 1e-10° from a thrust of 1e-6 N beside 1.4 kN; 0.01° from 100 N). [-]
TILT_UNFELT = 1e-7


def warned_tilt(r: CombinedDistribution) -> Any:
    """The tilt the checks weigh (:func:`bearingload.bearings.checks.combined_warnings`), the
    one rule of every command: the inner ring's tilt, both axes together, whatever gives it
    (a moment, an imposed misalignment, or a ring free to tilt under an eccentric load: the
    tilt is the same with --moment 0 as without a moment): its size, both axes together, of
    each case (an array of cases: an array); 0 where no ball feels it (:data:`TILT_UNFELT`;
    a ring whose balls carry nothing feels any tilt). [°]"""
    tilt = np.hypot(np.radians(r.tilt), np.radians(r.tilt_cross))
    approach = np.max(np.maximum(r.ball_approaches, 0.0), axis=-1)
    felt = np.asarray(r.tilt_radius) * tilt > TILT_UNFELT * approach
    return np.degrees(np.where(felt, tilt, 0.0))


def solve_on_bearing(
    b: ResolvedBearing,
    load: float,
    axial_load: float = 0.0,
    *,
    cage_angle: Any = 0.0,
    moment: float | None = None,
    misalignment: Any = None,
    clearance: Any = None,
    moment_cross: Any = None,
    tilt_radius: Any = None,
    speed: Any = None,
    ball_density: Any = None,
) -> CombinedDistribution:
    """The 3-D ring equilibrium of one resolved ball bearing, at one or many cage angles (or
    clearances).

    Parameters
    ----------
    b : ResolvedBearing
        With known ball geometry (D_w, d_m, f_i, f_o).
    load, axial_load : float
        F_r >= 0 and F_a. [N]
    cage_angle : float or array_like
        Angle of ball 1 from the load line; an array solves every angle in one vectorised
        call of :func:`bearingload.models.combined.solve_combined`. [°]
    moment : float, optional
        Moment in the plane of the load; default free tilt. [N mm]
    misalignment : float or array_like, optional
        Imposed tilt in the plane of the load, within the models' limit
        (:func:`bearingload.validate.misalignment`; an array: one per case, as a batch group
        of rows gives it). [°]
    clearance : float or array_like, optional
        Radial internal clearance G_r instead of the bearing's (an array solves every one in
        the same vectorised call). [mm]
    moment_cross : float or array_like, optional
        Moment about the load line (MASTA's M_x); None: 0. [N mm]
    tilt_radius : float, optional
        Lever of the tilt (:func:`bearingload.bearings.tilt.tilt_lever`); None: the solver's
        R_i. [mm]
    speed, ball_density : float, optional
        Inner ring speed [rpm]: the ball dynamics of :mod:`bearingload.models.high_speed`
        (outer-raceway control) are included; ball density [kg/m^3], default steel.

    Raises
    ------
    InputError
        ``misalignment`` beyond the limit, ``ball_diameter`` when the geometry is unknown (a
        roller bearing, or a ball set given by its stiffness), ``moment``, ``moment_cross`` or
        (a free ring) ``tilt_radius`` when it tilts the ring beyond the limit at any cage angle;
        the solver's own errors.
    """
    from bearingload.models.combined import solve_combined

    if misalignment is not None:  # (refused before the bearing's kind, as the model refuses it)
        validate.misalignment(misalignment)
    if b.kind != "ball":
        raise InputError(
            "bearing",
            f"{b.designation} is a {b.kind} bearing: the combined load (axial load, moment, "
            "misalignment, ISO/TS 16281 life) is solved for ball bearings only (deep-groove and "
            "angular-contact)",
        )
    if not b.has_geometry:
        raise InputError(
            "ball_diameter",
            "the combined load needs the ball geometry: give a bearing designation, or "
            "the ball and pitch diameters",
        )
    common = dict(
        ball_diameter=b.ball_diameter,
        pitch_diameter=b.pitch_diameter,
        f_i=b.f_i,
        f_o=b.f_o,
        clearance=b.clearance if clearance is None else clearance,
        cage_angle=cage_angle,
        moment=moment,
        misalignment=misalignment,
        modulus=b.modulus,
        poisson=b.poisson,
        tilt_radius=tilt_radius,
        moment_cross=0.0 if moment_cross is None else moment_cross,
        contact_angle=b.contact_angle,
    )
    if speed is None:
        stiffness = b.stiffness if b.stiffness_given else None
        r = solve_combined(b.balls, load, axial_load, stiffness=stiffness, **common)
    else:
        r = _at_speed(b, load, axial_load, speed, ball_density, common)
    tilt = float(np.max(warned_tilt(r)))
    cross = moment_cross is not None and bool(np.any(np.asarray(moment_cross) != 0))
    tilted = "moment" if moment is not None and misalignment is None else None
    if tilted is None and cross:
        tilted = "moment_cross"
    if tilted is None and tilt_radius is not None and misalignment is None:
        tilted = "tilt_radius"  # a free ring: a short lever alone can tilt it beyond the model
    if tilted is not None and tilt > validate.MISALIGNMENT_MAX:
        raise InputError(
            tilted,
            f"tilts the inner ring by {tilt:.3g}°, beyond ±{validate.MISALIGNMENT_MAX:g}°: the "
            "balls would ride over the groove shoulders, which the model does not describe",
        )
    return r


def _at_speed(
    b: ResolvedBearing, load: Any, axial_load: Any, speed: Any, density: Any, common: dict
) -> CombinedDistribution:
    """solve_on_bearing with the ball dynamics (:func:`bearingload.models.high_speed.
    solve_high_speed`): the two contacts need the Hertz stiffness of the ball geometry."""
    from bearingload.models.high_speed import solve_high_speed

    density = dynamics_density(b, density)
    return solve_high_speed(b.balls, load, axial_load, speed=speed, ball_density=density, **common)


def refuse_outer_at_speed(speed: Any, rotating: str) -> None:
    """Refuse the outer ring turning at a ``speed``: the ball dynamics are coded for the inner
    ring turning (the outer ring's lives are those of the static model)."""
    if speed is not None and rotating == "outer":
        raise InputError(
            "rotating",
            "the ball dynamics at a speed are coded for the inner ring "
            "turning (docs/speed.md); the outer ring's lives are those of the "
            "static model (speed None)",
        )


def dynamics_density(b: ResolvedBearing, density: Any) -> Any:
    """The ball density [kg/m^3] of the ball dynamics of ``b``: ``density`` if given, else that
    of the balls' material (a hybrid's silicon nitride), else steel; refused for a given ball
    stiffness (the dynamics need each contact's Hertz stiffness from the ball geometry)."""
    from bearingload.models.high_speed import STEEL_DENSITY

    if b.stiffness_given:
        raise InputError(
            "speed",
            "the ball dynamics need each contact's Hertz stiffness from the ball geometry, not a "
            "given ball stiffness: leave out the stiffness, or ask for the static model "
            "(speed None)",
        )
    if density is not None:
        return density
    return STEEL_DENSITY if b.ball_density is None else b.ball_density


def life_figures(
    b: ResolvedBearing, r: CombinedDistribution, rotating: str, dynamic_rating: float | None
) -> tuple[Any, float | None, float | None, float | None]:
    """(L10r [10^6 rev] of every case of ``r`` or None, P [N], L10 [10^6 rev], C_r [N]).

    L10r: ISO/TS 16281:2008, 4.3, from the ball loads (an array over the cases of ``r``). P and
    L10: ISO 281:2007, 5.2 and Table 3 (P = X F_r + Y F_a, needs C0r and f0 of a catalogue
    bearing; P = F_r without an axial load); one value, the same for every cage angle. None
    where C_r (``dynamic_rating`` or the catalogue's) is unknown.
    """
    c_r = dynamic_rating or b.C
    l10r = p_eq = life = None
    if c_r:
        l10r = reference_lives(b, r, rotating, c_r)
        fr = float(np.asarray(r.load).reshape(-1)[0])
        fa = float(np.asarray(r.axial_load).reshape(-1)[0])
        p, l10 = basic_lives(b, c_r, fr, fa)
        p_eq = None if p is None else float(p)
        life = None if l10 is None or np.isnan(l10) else float(l10)
    return l10r, p_eq, life, c_r


def reference_lives(b: ResolvedBearing, r: CombinedDistribution, rotating: str, c_r: float) -> Any:
    """L10r of every case of ``r`` (ISO/TS 16281:2008, 4.3), the contact ratings from C_r; at
    speed the inner ring's equivalent load from each ball's inner contact load, the outer
    ring's from its outer one. [10^6 rev]"""
    from bearingload.studies.reference_life import ball_reference_life

    outer = getattr(r, "ball_loads_outer", None)  # at speed: each ball's outer contact load
    return ball_reference_life(b, r.ball_loads, rotating, c_r, outer_loads=outer)


def basic_lives(b: ResolvedBearing, c_r: float, fr: Any, fa: Any) -> tuple[Any, Any]:
    """ISO 281:2007's P = X F_r + Y F_a (5.2, Table 3) and L10 = (C_r/P)^3 (5.3) of every
    (F_r, F_a) [N]: P = F_r without an axial load; (None, None) with one where C0r or f0 is
    unknown (not a catalogue bearing): NaN for those cases, each case on its own inputs, and
    (None, None) when no case has a P. Under a moment alone (F_r = F_a = 0) P = 0 and L10 is
    NaN: ISO 281 has no life for it (L10r, ISO/TS 16281, has). [N], [10^6 rev]"""
    from bearingload.bearings.life import equivalent_load_deep_groove, rating_life

    fr, fa = np.asarray(fr, dtype=float), np.asarray(fa, dtype=float)
    f0 = None if b.geometry is None else b.geometry.f0
    if b.contact_angle is not None:
        p = angular_equivalent_load(b, fr, fa, f0)
        if p is None:
            return None, None
    elif b.C0 is not None and f0 is not None:
        p = np.where(fa == 0, fr, equivalent_load_deep_groove(fr, fa, b.C0, f0))
    else:
        p = np.where(fa == 0, fr, np.nan)
        if np.isnan(p).all():
            return None, None
    loaded = p > 0
    life = np.full(p.shape, np.nan)
    life[loaded] = rating_life(c_r, p[loaded])
    return p, life


def angular_equivalent_load(b: ResolvedBearing, fr: Any, fa: Any, f0: float | None) -> Any:
    """ISO 281's P = X F_r + Y F_a of an angular-contact bearing at its nominal contact angle
    (:func:`bearingload.bearings.life.equivalent_load_angular_contact`); None where the
    angle has no coded factors, or at 15° without C0r (e, Y there depend on F_a/C0r). [N]"""
    from bearingload.bearings.life import (
        angular_contact_tabulated,
        equivalent_load_angular_contact,
    )

    alpha = float(b.contact_angle or 0.0)
    if not angular_contact_tabulated(alpha) or (abs(alpha - 15.0) < 1e-9 and b.C0 is None):
        return None
    return np.asarray(equivalent_load_angular_contact(fr, fa, alpha, b.C0, f0), dtype=float)


def combined_values(c: CombinedCase) -> dict[str, Any]:
    """Every quantity of one case under its key of :mod:`bearingload.reports.quantities`."""
    return {k: v if v is None or isinstance(v, str) else
            v[0] if isinstance(v, list) else v.reshape(-1)[0].item()
            for k, v in combined_columns(c).items() if k != "warnings"}  # fmt: skip


def combined_columns(c: CombinedCase) -> dict[str, Any]:
    """The quantities of :func:`combined_values` of every case of ``c`` (one or many): arrays,
    lists (None where a case has no value), or text; and ``warnings``, one tuple per case."""
    n = int(np.size(c.result.q_max))

    def listed(value: Any) -> Any:
        if value is None or isinstance(value, list):
            return [value] * n if value is None else value
        values = np.broadcast_to(np.asarray(value, dtype=float), (n,))
        return [None if v != v else v for v in values.tolist()]  # NaN: no value

    columns = case_columns(
        c.bearing, c.result, c.misalignment, c.rotating, c.dynamic_rating,
        c.equivalent_load, c.rating_life, c.reference_rating_life,
        moment_cross=c.moment_cross,
    )  # fmt: skip
    sel = c.static_equivalent_load  # (None: an angular contact angle without a coded Y0)
    for key in ("equivalent_load", "rating_life"):  # a moment alone, an F_a without f0: none
        values = columns[key]
        if values is not None and np.isnan(values).any():
            columns[key] = listed(values)
    return (
        columns
        | matrix_columns(c.result)
        | {
            "p_max_inner": listed(c.p_max_inner),
            "p_max_outer": listed(c.p_max_outer),
            "static_equivalent_load": listed(sel)
            if sel is None or (isinstance(sel, list) and None in sel)
            else np.broadcast_to(np.asarray(sel, float), (n,)),
            "static_safety": listed(c.static_safety),
            **_density(c.result, n),
            "warnings": [c.warnings]
            if n == 1 and np.ndim(c.result.q_max) == 0
            else list(c.warnings),
        }
    )


def _density(r: CombinedDistribution, n: int) -> dict[str, Any]:
    """``ball_density`` [kg/m^3] of the ball dynamics at speed (the result's, as solve's
    --ball-density and batch's ball_density take it); nothing for a static solve."""
    density = getattr(r, "ball_density", None)
    if density is None:
        return {}
    return {"ball_density": np.broadcast_to(np.asarray(density, dtype=float), (n,))}


def case_columns(
    b: ResolvedBearing,
    r: CombinedDistribution,
    misalignment: Any,
    rotating: Any,
    dynamic_rating: Any,
    equivalent_load: Any,
    rating_life: Any,
    reference_rating_life: Any,
    *,
    moment_cross: Any = None,
) -> dict[str, Any]:
    """Every quantity of the cases of ``r`` (one bearing) under its key of
    :mod:`bearingload.reports.quantities`: a numpy array over the cases, text, or None where a
    quantity is not given (no misalignment imposed, C_r unknown, no catalogue C0r and f0); the
    applied ``moment_cross`` [N mm] only where given; the lever ``tilt_radius`` [mm] the solve
    used (the one given, else R_i: :attr:`CombinedDistribution.tilt_radius`)."""

    def arr(value: Any, dtype: Any = float) -> Any:
        return None if value is None else np.atleast_1d(np.asarray(value, dtype=dtype))

    cross = {} if moment_cross is None else {"moment_cross": arr(moment_cross)}
    lever = {"tilt_radius": arr(r.tilt_radius)}
    return {
        "bearing": b.designation or "given by hand",
        "method": "combined",
        "balls": arr(r.balls, np.int64),
        "load": arr(r.load),
        "axial_load": arr(r.axial_load),
        "moment": arr(r.moment),
        **cross,
        "misalignment": arr(misalignment),
        **lever,
        "rotating": rotating,
        "stiffness": arr(b.stiffness),
        "clearance": arr(r.clearance),
        **{k: arr(v) for k, v in result_fields(b).items()},
        "clearance_pick": b.clearance_pick,
        "cage_angle": arr(r.cage_angle),
        **({} if b.contact_angle is None else {"contact_angle": arr(b.contact_angle)}),
        "free_contact_angle": arr(r.free_contact_angle),
        "axial_play": arr(r.axial_play),
        "q_max": arr(r.q_max),
        **radial_factors(r, misalignment, moment_cross, b.contact_angle is None),
        "loaded_balls": arr(r.loaded_balls, np.int64),
        "load_zone": _zone(b, r),
        "x": arr(r.x),
        "y": arr(r.y),
        "axial": arr(r.axial),
        "tilt": arr(r.tilt),
        "tilt_cross": arr(r.tilt_cross),
        "stiffness_radial": arr(r.stiffness_radial),
        "stiffness_axial": arr(r.stiffness_axial),
        "stiffness_tilt": arr(r.stiffness_tilt),
        "contact_angle_max": arr(largest_loaded_angle(r)),
        "dynamic_rating": arr(dynamic_rating),
        "equivalent_load": arr(equivalent_load),
        "rating_life": arr(rating_life),
        "reference_rating_life": arr(reference_rating_life),
    }


def radial_factors(
    r: CombinedDistribution, misalignment: Any, moment_cross: Any, deep_groove: bool = True
) -> dict[str, Any]:
    """The radial engine's load factor k = Q_max/F_r and load concentration K_Q = k z/2 of a
    deep-groove bearing under a radial load alone (no thrust, moment or misalignment; at a speed
    Q_max is the heaviest inner contact's, which carries the shaft's load), so that a radial case
    keeps them on the combined engine (the ball dynamics at a speed, or a thrust of 0 given):
    arrays over the cases, or lists with None for a case under another load (every key of a
    combined case is there, its value None where it has none: csv and batch keep one header)."""
    f_r = np.atleast_1d(np.asarray(r.load, dtype=float))
    alone = (f_r > 0) & deep_groove
    for value in (r.axial_load, r.moment, moment_cross, misalignment):
        if value is not None:  # (a batch's group: NaN where a row does not give it)
            given = np.broadcast_to(np.asarray(value, dtype=float), f_r.shape)
            alone = alone & ((given == 0) | np.isnan(given))
    with np.errstate(divide="ignore", invalid="ignore"):
        k = np.atleast_1d(np.asarray(r.q_max, dtype=float)) / f_r
    k_q = k * float(r.balls) / 2.0
    if alone.all():
        return {"k": k, "K_Q": k_q}
    return {
        "k": [float(v) if a else None for v, a in zip(k, alone, strict=True)],
        "K_Q": [float(v) if a else None for v, a in zip(k_q, alone, strict=True)],
    }


def _zone(b: ResolvedBearing, r: CombinedDistribution) -> Any:
    """The load zone half-angle of every case (:func:`bearingload.models.combined.load_zone`),
    as the radial engine gives it; a list of None at a speed, where the ball dynamics move the
    contacts off the groove-centre line the zone is drawn from. [°]"""
    from bearingload.models.combined import load_zone
    from bearingload.models.high_speed import HighSpeedDistribution

    if isinstance(r, HighSpeedDistribution) or None in (b.f_i, b.f_o, b.ball_diameter):
        return [None] * int(np.size(r.q_max))
    big_a = (float(b.f_i) + float(b.f_o) - 1.0) * float(b.ball_diameter)  # type: ignore[arg-type]
    return np.atleast_1d(load_zone(r, big_a, one_sided=b.contact_angle is not None))


def largest_loaded_angle(r: CombinedDistribution) -> Any:
    """The contact angle of largest size among the balls that carry load, with its sign, of
    every case of ``r`` (of all balls where none carries). [°]"""
    angles = np.asarray(r.contact_angles, dtype=float)
    loaded = np.asarray(r.ball_loads, dtype=float) > 0
    pool = loaded | ~loaded.any(axis=-1, keepdims=True)
    idx = np.argmax(np.where(pool, np.abs(angles), -1.0), axis=-1)
    out = np.take_along_axis(angles, idx[..., None], axis=-1)[..., 0]
    return out[()] if out.ndim == 0 else out
