"""Checks of a solved case against what the bearing and the model support: warnings, not errors.

:func:`case_warnings` returns one sentence per finding (an empty list when all is well):

* **static safety factor** s0 = C0/P0 below :data:`S0_MIN` = 1. ISO 76:2006 defines s0 as the
  ratio of the basic static load rating to the static equivalent load (3.6); the static
  equivalent radial load of a radial bearing under a purely radial load is P0r = F_r (3.4 and
  the P0r formula, X0 = 1 when F_a = 0). Below 1 the permanent deformation of rolling element
  and raceway exceeds the 0.0001 D_w the rating stands for (3.2, note 2).
* **load above C0**: F_r > C0, the load exceeds the basic static radial load rating itself.
* **maximum contact pressure** above the pressure that defines C0r in ISO 76:2006 3.2:
  :data:`P_MAX_BALL` = 4200 MPa for ball bearings (other than self-aligning) and
  :data:`P_MAX_ROLLER` = 4000 MPa for roller bearings, at the centre of the most heavily loaded
  contact (computed here by exact Hertz theory for balls and Johnson's line contact for rollers).
* **one rolling element carries the load**: the solution then rests on a single contact, the
  model's distribution over the ring means little and a small change of clearance or cage angle
  changes the answer a lot.
* **clearance outside the plausible range** of a deep groove ball bearing of this bore: above the
  C5 maximum of ISO 5753-1 (the largest class there is), or a preload (negative G_r) deeper than
  :data:`PRELOAD_BOUND_FACTOR` times that C5 maximum (a bound of this project, not of a standard:
  interference fits and preloading springs take away a few tens of micrometres at these bores,
  not more than the widest clearance class spans). Positive clearances below C2 min (0 to 3 µm
  at these bores) are not flagged.

:func:`speed_findings` (solve, sweep and batch with a speed) adds one more: the **speed above
the limiting speed** the catalogue gives for the bearing (a maker's printed figures, with grease
and with oil lubrication; oil the higher): above the oil figure it is above both; between the
two, above the grease figure only (no warning for oil lubrication then, which the sentence
says). No warning where the catalogue gives no limiting speed (a ring given by hand, a row
without them). A sealed bearing (a seal lowers the open bearing's limits; its own are not read)
is warned above the open bearing's grease figure, where it is above its own limit too.

Every threshold is a module constant; the CLI prints each finding as a ``Warning: ...`` line on
stderr and JSON carries them as ``warnings``.

>>> from bearingload.bearings.resolve import resolve_bearing
>>> from bearingload.models.equilibrium import solve
>>> b = resolve_bearing("6205", clearance="C3")
>>> case_warnings(b, 5000.0, solve(b.balls, 5000.0, b.stiffness, b.clearance))
[]
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload.errors import InputError

if TYPE_CHECKING:  # the catalogue is imported only where a bearing is resolved
    from bearingload.bearings.resolve import ResolvedBearing

#: Smallest acceptable static safety factor s0 = C0/P0 (ISO 76:2006 3.6). [-]
S0_MIN = 1.0
#: Contact pressure defining C0r of ball bearings other than self-aligning (ISO 76:2006 3.2). [MPa]
P_MAX_BALL = 4200.0
#: Contact pressure defining C0r of roller bearings (ISO 76:2006 3.2). [MPa]
P_MAX_ROLLER = 4000.0
#: Deepest preload accepted without a warning, as a multiple of the bore's C5 maximum. [-]
PRELOAD_BOUND_FACTOR = 1.0
#: ISO 76:2006, 7.1: static equivalent radial load of radial ball bearings,
#: P0r = X0 F_r + Y0 F_a with X0 = 0.6, Y0 = 0.5, and P0r = F_r where that is larger. [-]
X0_BALL, Y0_BALL = 0.6, 0.5


def max_contact_pressures(
    bearing: ResolvedBearing, load: Any, contact_angle: Any = 0.0
) -> tuple[float, float] | None:
    """Maximum pressures of the inner and outer contact of a rolling element under ``load``,
    or the largest of each contact over several balls (see :func:`contact_pressures`). [MPa]

    Returns
    -------
    (float, float) or None
        (p_inner, p_outer), each the largest over the balls given [MPa]; None when the geometry
        is not known (stiffness given by hand).
    """
    found = contact_pressures(bearing, load, contact_angle)
    if found is None:
        return None
    return float(np.max(found[0])), float(np.max(found[1]))


def contact_pressures(bearing: ResolvedBearing, load: Any, contact_angle: Any = 0.0) -> Any:
    """Maximum pressures of the inner and outer contact of each rolling element load given.

    A ball at the contact angle alpha touches raceways whose curvature in the rolling direction
    is 2 cos(alpha)/(d_m -+ D_w cos(alpha)) (inner, outer; Harris & Kotzalas, ISO/TS 16281),
    that of a zero-angle bearing of pitch diameter d_m/cos(alpha): exact Hertz theory
    (:func:`bearingload.contact.hertz.ball_contacts`) at that pitch diameter, the curvatures
    the combined-load solver gives the ball stiffness with. Rollers: Johnson's line contact
    (:func:`bearingload.bearings.rollers.line_contact_pressure`).

    Parameters
    ----------
    bearing : ResolvedBearing
        Balls need D_w, d_m, f_i, f_o; rollers D_w, d_m, L_we.
    load : float or array_like
        Rolling-element loads Q >= 0 (one case's balls, or the heaviest ball of many cases). [N]
    contact_angle : float or array_like
        Contact angle of each ball (balls only; rollers: 0). [°]

    Returns
    -------
    (p_inner, p_outer) or None
        Floats for one load, arrays of the shape of ``load`` otherwise [MPa]; None when the
        geometry is not known (stiffness given by hand).
    """
    if bearing.kind == "roller":
        if bearing.roller_length is None or bearing.ball_diameter is None:
            return None
        from bearingload.bearings.rollers import line_contact_pressure

        return line_contact_pressure(
            load,
            bearing.roller_length,
            bearing.ball_diameter,
            bearing.pitch_diameter or 0.0,
            bearing.modulus,
            bearing.poisson,
        )
    dw, dm, fi, fo = bearing.ball_diameter, bearing.pitch_diameter, bearing.f_i, bearing.f_o
    if dw is None or dm is None or fi is None or fo is None:
        return None
    if np.ndim(contact_angle) == 0 and float(contact_angle) == 0.0:
        from bearingload.contact.hertz import ball_contacts

        one = np.ndim(load) == 0
        c = ball_contacts(float(load) if one else np.asarray(load, dtype=float), dw, dm, fi, fo,
                          bearing.modulus, bearing.poisson)  # fmt: skip
        if one:
            return float(c.inner.p_max), float(c.outer.p_max)
        return np.asarray(c.inner.p_max), np.asarray(c.outer.p_max)
    return ball_pressures(bearing, load, contact_angle)


def ball_pressures(
    bearing: ResolvedBearing, load: Any, contact_angle: Any
) -> tuple[np.ndarray, np.ndarray]:
    """Maximum pressures of the inner and outer contact of every ball given (the arrays of
    ``load`` and ``contact_angle`` broadcast), each ball at its own contact angle (see
    :func:`max_contact_pressures`; the bearing's D_w, d_m, f_i, f_o must be known). [MPa]"""
    from bearingload.contact.hertz import ball_contacts

    dw, dm, fi, fo = bearing.ball_diameter, bearing.pitch_diameter, bearing.f_i, bearing.f_o
    assert dw is not None and dm is not None and fi is not None and fo is not None
    # |cos|: a contact angle past 90° (which the combined solver can report far beyond C0) has
    # the raceway curvatures of its mirror angle; at 90° the rolling curvature is that of d_m = inf
    cos_a = np.clip(np.abs(np.cos(np.deg2rad(np.asarray(contact_angle, dtype=float)))), 1e-9, 1.0)
    c = ball_contacts(np.asarray(load, dtype=float), dw, dm / cos_a, fi, fo, bearing.modulus,
                      bearing.poisson)  # fmt: skip
    return np.asarray(c.inner.p_max), np.asarray(c.outer.p_max)


def static_equivalent_load(radial_load: float, axial_load: float = 0.0) -> float:
    """Static equivalent radial load P0 of a radial ball bearing (ISO 76:2006, 7.1). [N]

    ``P0 = max(X0 F_r + Y0 |F_a|, F_r)`` with X0 = :data:`X0_BALL` = 0.6, Y0 = :data:`Y0_BALL`
    = 0.5 (single-row radial ball bearings); P0 = F_r without an axial load, as for a
    cylindrical roller bearing under its radial load (ISO 76, 7.2).

    >>> static_equivalent_load(1000.0), static_equivalent_load(1000.0, 2000.0)
    (1000.0, 1600.0)
    """
    return max(radial_load, X0_BALL * radial_load + Y0_BALL * abs(axial_load))


def static_equivalent_load_angular(
    radial_load: float, axial_load: float, contact_angle: float
) -> float | None:
    """Static equivalent load P0 = max(X0 F_r + Y0 F_a, F_r) of a single-row angular-contact
    ball bearing, single or tandem (ISO 76:2006, 7.1: X0 = 0.5, Y0 by the contact angle, the
    table with its sources in :mod:`bearingload.bearings.angular_factors`); None for a contact
    angle without a coded Y0. [N]

    >>> static_equivalent_load_angular(1000.0, 2000.0, 40.0)
    1020.0
    >>> static_equivalent_load_angular(1000.0, 2000.0, 20.0)
    1340.0
    >>> static_equivalent_load_angular(1000.0, 2000.0, 26.0) is None
    True
    """
    from bearingload.bearings.angular_factors import X0_SINGLE, static_y0

    y0 = static_y0(contact_angle)
    if y0 is None:
        return None
    return max(radial_load, X0_SINGLE * radial_load + y0 * abs(axial_load))


def static_equivalent_load_angular_pair(
    radial_load: float, axial_load: float, contact_angle: float
) -> float | None:
    """Static equivalent load P0 = F_r + Y0 F_a of a back-to-back or face-to-face pair taken as
    one bearing (ISO 76:2006, 7.1: X0 = 1, the pair's Y0, twice one bearing's); None for a
    contact angle without a coded Y0. [N]

    >>> static_equivalent_load_angular_pair(1000.0, 2000.0, 40.0)
    2040.0
    """
    from bearingload.bearings.angular_factors import X0_PAIR, static_y0

    y0 = static_y0(contact_angle, pair=True)
    if y0 is None:
        return None
    return X0_PAIR * radial_load + y0 * abs(axial_load)


def static_safety(c0: float | None, p0: float) -> float | None:
    """Static safety factor s0 = C0/P0 (ISO 76:2006, 3.6); None where C0 is not known or
    P0 = 0 (nothing loads the bearing statically: no finite factor). [-]

    >>> static_safety(10000.0, 2500.0), static_safety(None, 1.0), static_safety(1.0, 0.0)
    (4.0, None, None)
    """
    return c0 / p0 if c0 and p0 > 0 else None


def speed_findings(speed: float | None, bearing: ResolvedBearing) -> list[str]:
    """The warning on a shaft speed above the bearing's limiting speed; empty when the speed
    is not above the grease figure, or none is given or known.

    Parameters
    ----------
    speed : float or None
        Shaft speed n of the rotating ring. [r/min]
    bearing : ResolvedBearing
        Its :attr:`~bearingload.bearings.resolved.ResolvedBearing.limiting_speeds` (grease,
        oil [r/min] and their source) are read.

    Returns
    -------
    list of str
        Empty, or one sentence naming the speed, the limit passed and the source.
    """
    limits = bearing.limiting_speeds
    if speed is not None and limits is None:
        return _sealed_findings(speed, bearing)
    if speed is None or limits is None or not _above(speed, limits.grease):
        return []
    name = bearing.geometry.designation if bearing.geometry is not None else "the bearing"
    cite = limits.source.split(" (", 1)[0]
    if _above(speed, limits.oil):
        return [
            f"the speed n = {_speed_text(speed, limits.oil)} rpm is above the limiting speeds of "
            f"{name} with oil lubrication, {limits.oil:.6g} rpm, and with grease, "
            f"{limits.grease:.6g} rpm ({cite})"
        ]
    return [
        f"the speed n = {_speed_text(speed, limits.grease)} rpm is above the limiting speed of "
        f"{name} with grease lubrication, {limits.grease:.6g} rpm (with oil lubrication "
        f"{limits.oil:.6g} rpm, which it does not exceed; {cite})"
    ]


def _sealed_findings(speed: float, bearing: ResolvedBearing) -> list[str]:
    """A sealed bearing (its limits not read; a seal lowers the open bearing's, Koyo CAT. No.
    B2001RUS p. 20) above the open bearing's grease figure: above its own limit too."""
    from bearingload.bearings.catalog import sealed

    geo = bearing.geometry
    limits = getattr(geo, "open_limiting_speeds", None)
    if geo is None or limits is None or not sealed(geo.parsed.suffixes):
        return []
    if not _above(speed, limits.grease):
        return []
    cite = limits.source.split(" (", 1)[0]
    return [
        f"the speed n = {_speed_text(speed, limits.grease)} rpm is above the limiting speed of "
        f"{geo.parsed.text}: the open {geo.designation}'s with grease lubrication is "
        f"{limits.grease:.6g} rpm (with oil {limits.oil:.6g} rpm), and its seal lowers it "
        f"({cite}; sealed bearings p. 20)"
    ]


def _above(speed: float, limit: float) -> bool:
    """``speed`` above ``limit`` [r/min] by more than the rounding of a unit conversion (a limit
    given in rad/s or Hz reads a few ulp off the printed figure: it is at the limit)."""
    return speed > limit and not math.isclose(speed, limit, rel_tol=1e-12)


def _speed_text(speed: float, limit: float) -> str:
    """The speed [r/min] with 6 significant digits, more where 6 print it as the limit it
    exceeds (13000.001 rpm above 13000 rpm)."""
    for digits in range(6, 13):
        text = f"{speed:.{digits}g}"
        if float(text) > limit:
            return text
    return f"{speed:.12g}"


def clearance_findings(bearing: ResolvedBearing) -> list[str]:
    mounted = bearing.mounting.warning() if bearing.mounting is not None else None
    if mounted is not None:  # the preload of the mounting, named with its causes
        return [mounted]
    if bearing.kind != "ball" or bearing.geometry is None:
        return []
    from bearingload.bearings.clearance import largest_class, table_name

    bore = bearing.geometry.d
    try:
        name, c5_max = largest_class(bore)
    except InputError:  # bore outside the clearance table
        return []
    g_r = bearing.clearance
    um = 1e3
    where = table_name(bore)
    if g_r > c5_max:
        return [
            f"radial clearance G_r = {g_r * um:.4g} µm is above the largest class of {where} "
            f"({name} max {c5_max * um:.4g} µm at d = {bore:g} mm): no deep groove ball bearing "
            "of this bore has so much play"
        ]
    bound = PRELOAD_BOUND_FACTOR * c5_max
    if g_r < -bound:
        return [
            f"preload G_r = {g_r * um:.4g} µm is deeper than {bound * um:.4g} µm (the {name} "
            f"maximum of {where} at d = {bore:g} mm, this package's bound): check the fits"
        ]
    return []


def case_warnings(
    bearing: ResolvedBearing, load: float, result: Any, pressures: Any = "compute"
) -> list[str]:
    """Findings on one solved case, one sentence each; empty when all is well.

    Parameters
    ----------
    bearing : ResolvedBearing
        The bearing as solved (from :func:`bearingload.bearings.resolve.resolve_bearing`).
    load : float
        Radial load F_r. [N]
    result : LoadDistribution or Result
        One case of :func:`bearingload.models.equilibrium.solve` or a registered model's
        :class:`bearingload.models.case.Result` (``q_max`` [N] and ``loaded_balls`` are read).
    pressures : (float, float) or None, optional
        The maximum contact pressures (inner, outer) at Q_max [MPa] where already known (None:
        not known for this bearing); by default computed here.

    Returns
    -------
    list of str
        Thresholds and their sources in the module text.
    """
    out: list[str] = []
    element = "roller" if bearing.kind == "roller" else "ball"
    c0 = bearing.C0
    s0 = static_safety(c0, load)
    if c0 and s0 is not None:
        if s0 < S0_MIN:
            out.append(
                f"static safety factor s0 = C0/P0 = {s0:.3g} is below {S0_MIN:g} (ISO 76: "
                f"P0 = F_r = {load:.6g} N, C0 = {c0:.6g} N): the raceways deform permanently"
            )
        if load > c0:
            out.append(
                f"the load F_r = {load:.6g} N is above the basic static rating C0 = {c0:.6g} N"
            )
    q_max = float(result.q_max)
    if isinstance(pressures, str):
        pressures = max_contact_pressures(bearing, q_max)
    if pressures is not None:
        limit = P_MAX_ROLLER if bearing.kind == "roller" else P_MAX_BALL
        p, where = max(zip(pressures, ("inner", "outer"), strict=True))
        if p > limit:
            out.append(
                f"maximum contact pressure {p:.5g} MPa ({where} contact, heaviest {element} "
                f"{q_max:.6g} N) is above {limit:g} MPa, the pressure of the static rating of "
                f"{element} bearings (ISO 76)"
            )
    out += element_warnings(result, bearing.balls, element)
    out += clearance_findings(bearing)
    return out


def element_warnings(result: Any, balls: int, element: str = "ball") -> list[str]:
    """The finding that needs no bearing data: only one of several elements carries the load.

    Parameters
    ----------
    result : LoadDistribution or Result
        One solved case (``loaded_balls`` is read; None, as the closed-form methods give,
        means no finding).
    balls : int
        Number of rolling elements z.
    element : str
        ``"ball"`` or ``"roller"``, for the wording.

    Returns
    -------
    list of str
        Empty, or the one sentence.
    """
    loaded = getattr(result, "loaded_balls", None)
    if loaded is not None and int(loaded) == 1 and balls > 1:
        return [
            f"only one {element} carries the load: the result hangs on a single contact "
            "(large clearance or few elements); check the clearance"
        ]
    return []


#: Misalignment a deep-groove ball bearing tolerates: 2 to 10 arcmin (SKF rolling bearings
#: catalogue, deep groove ball bearings, "Misalignment"); above 10 arcmin a warning. [°]
MISALIGNMENT_TOLERATED = 10.0 / 60.0


def misalignment_findings(misalignment: float, angular: bool) -> list[str]:
    """The warning on a tilt of the inner ring [°]: above :data:`MISALIGNMENT_TOLERATED` for a
    deep-groove bearing; any tilt for a single-row angular-contact bearing, whose tolerable
    misalignment SKF does not give as a number ("limited ability to compensate misalignment
    ... exact permissible values cannot be given": SKF General Catalogue 6000, Russian edition
    2006, single row angular contact ball bearings, "Misalignment", p. 413)."""
    if angular and abs(misalignment) > 0:
        return [
            f"the inner ring tilts by {misalignment:.4g}° ({abs(misalignment) * 60:.3g} arcmin): "
            "a single-row angular-contact ball bearing takes little misalignment, and SKF gives "
            "no tolerable value for it (it depends on the clearance or preload, the size, the "
            "internal design and the loads); the 2-10 arcmin of a deep-groove bearing do not "
            "apply: check the tilt with the maker"
        ]
    if not angular and abs(misalignment) > MISALIGNMENT_TOLERATED:
        return [
            f"a tilt of the inner ring of {misalignment:.4g}° is more than the 10 arcmin "
            "(0.167°) a deep-groove ball bearing tolerates (SKF catalogue)"
        ]
    return []


def combined_warnings(
    bearing: ResolvedBearing,
    radial_load: float,
    axial_load: float,
    q_max: float,
    loaded_balls: int,
    misalignment: float | None = None,
    pressures: tuple[float, float] | None | str = "compute",
) -> list[str]:
    """Findings on one combined-load case (ball bearing), one sentence each; empty when all is well.

    The static checks use the static equivalent load of ISO 76:2006, 7.1
    (:func:`static_equivalent_load`, ``P0 = max(F_r, 0.6 F_r + 0.5 |F_a|)``). The contact
    pressure: ``pressures`` (inner, outer) [MPa] where known (the largest of every ball at its
    contact angle, as ``solve`` reports them; None: not known for this bearing), by default that
    of the heaviest ball at the groove's radial section (:func:`max_contact_pressures`).
    """
    out: list[str] = []
    alpha = bearing.contact_angle
    p0 = (static_equivalent_load(radial_load, axial_load) if alpha is None
          else static_equivalent_load_angular(radial_load, axial_load, alpha))  # fmt: skip
    c0 = bearing.C0
    s0 = None if p0 is None else static_safety(c0, p0)
    if c0 and s0 is not None and p0 is not None:
        rule = "0.6 F_r + 0.5 F_a" if alpha is None else f"0.5 F_r + Y0 F_a at {alpha:g}°"
        if s0 < S0_MIN:
            out.append(
                f"static safety factor s0 = C0/P0 = {s0:.3g} is below {S0_MIN:g} (ISO 76: "
                f"P0 = max(F_r, {rule}) = {p0:.6g} N, C0 = {c0:.6g} N): the raceways "
                "deform permanently"
            )
        if p0 > c0:
            out.append(
                f"the static equivalent load P0 = {p0:.6g} N is above the basic static rating "
                f"C0 = {c0:.6g} N"
            )
    if isinstance(pressures, str):
        pressures = max_contact_pressures(bearing, q_max)
    if pressures is not None:
        p, where = max(zip(pressures, ("inner", "outer"), strict=True))
        if p > P_MAX_BALL:
            out.append(
                f"maximum contact pressure {p:.5g} MPa ({where} contact, heaviest ball "
                f"{q_max:.6g} N) is above {P_MAX_BALL:g} MPa, the pressure of the static rating "
                "of ball bearings (ISO 76)"
            )
    if loaded_balls == 1 and bearing.balls > 1:
        out.append(
            "only one ball carries the load: the result hangs on a single contact (large "
            "clearance or few elements); check the clearance"
            if alpha is None  # an angular-contact bearing has no clearance to check
            else "only one ball carries the load: the result hangs on a single contact (a light "
            "thrust, or few balls); more thrust (a preload "
            "against another bearing) loads more balls"
        )
    if misalignment is not None:
        out.extend(misalignment_findings(misalignment, alpha is not None))
    group = bearing.clearance_class
    f0 = None if bearing.geometry is None else bearing.geometry.f0  # P needs C0r and f0
    if axial_load != 0 and c0 and f0 is not None and group in ("C3", "C4", "C5"):
        out.append(
            f"ISO 281's P = X F_r + Y F_a here uses the factors of Table 3 for normal clearance "
            f"(the standard's e, X, Y for {group} clearance are not in this package): P and L10 "
            "are those of a bearing with normal clearance; L10r, from the load distribution, "
            "sees the clearance"
        )
    return out + clearance_findings(bearing)
