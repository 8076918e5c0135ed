"""From what an engineer types to what the engine needs: geometry, stiffness, clearance, sources.

:func:`resolve_bearing` turns a designation (``306``, ``6306-2RS/C3``) or a hand-given ball
set, optional overrides of every geometry value, a modulus and a clearance (a length or an
ISO 5753-1 class) into a :class:`ResolvedBearing`: the number of balls, the ball stiffness
K [N/mm^1.5] with its inner and outer contact parts, the radial internal clearance G_r [mm], the
load ratings, and for every value the place it came from.

Rules
-----
* Geometry: catalogue row (:func:`bearingload.bearings.catalog.lookup`), each value replaceable;
  ``maker`` picks another maker's ball set (default NSK, see :mod:`bearingload.bearings.catalog`).
  A cylindrical roller designation (``NU206``) resolves through
  :mod:`bearingload.bearings.rollers`: Palmgren line-contact stiffness [N/mm^(10/9)], exponent
  10/9, and a clearance given as a length or an ISO 5753-1 class of cylindrical roller bearings
  (default: the class the designation marks, else CN, as for ball bearings).
  Without a designation, ``balls`` is needed and either ``stiffness`` or the ball geometry
  (``ball_diameter`` and ``pitch_diameter``; conformities default to 0.52 / 0.53).
* Stiffness: exact Hertz (:func:`bearingload.contact.hertz.ball_stiffness`) from the geometry, E and nu
  (default bearing steel, 208 000 MPa and 0.3), unless ``stiffness`` is given.
* Clearance: a length is G_r itself (total radial play; the gap per side is G_r/2). A class
  (``C2 CN C3 C4 C5``, GOST groups written ``G6 G7 G8 G9``; a bare number is always a length)
  is resolved by the bore from the ISO 5753-1 table and picked at ``min``, ``mean`` or ``max``.
  With a designation and no clearance, the class the designation marks is used, else CN
  (by ISO and GOST an unmarked designation means the normal group). Without a designation
  and no clearance: zero.

>>> b = resolve_bearing("306", clearance="20um")
>>> b.balls, round(b.clearance, 6), round(float(b.stiffness), -2)
(8, 0.02, 404600.0)
"""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING, Any

from bearingload.bearings.catalog import (
    DEFAULT_F_I,
    DEFAULT_F_O,
    DEFAULT_MAKER,
    BearingGeometry,
    lookup,
)
from bearingload.bearings.clearance import (
    PICKS,
    RANGE,
    ClearanceSpec,
    parse_clearance,
    picks_of,
)
from bearingload.bearings.mounting import Mounting, check_mounting, mount
from bearingload.bearings.resolved import (
    DEFAULT_MODULUS,
    DEFAULT_POISSON,
    Provenance,
    ResolvedBearing,
    clearance_row_source,
    resolve_clearance,
)
from bearingload.errors import InputError, MissingError
from bearingload.validate import (
    ball_size_fits,
    ball_spacing,
    ball_too_small,
    clearance_beyond_ball,
    clearance_fits,
    conformity,
    finite_positive,
)

if TYPE_CHECKING:
    from bearingload.bearings.materials import BallMaterial


def resolve_bearing(
    designation: str | None = None,
    *,
    balls: int | None = None,
    ball_diameter: float | None = None,
    pitch_diameter: float | None = None,
    f_i: float | None = None,
    f_o: float | None = None,
    modulus: float | None = None,
    poisson: float | None = None,
    stiffness: float | None = None,
    clearance: str | float | ClearanceSpec | None = None,
    clearance_pick: str = "mean",
    maker: str | None = None,
    ball_material: str | None = None,
    shaft_fit: str | None = None,
    housing_fit: str | None = None,
    shaft_bore: float | None = None,
    housing_diameter: float | None = None,
    inner_ring_temperature: float | None = None,
    outer_ring_temperature: float | None = None,
) -> ResolvedBearing:
    """Resolve a bearing for a calculation: geometry, K, G_r and the source of each.

    Parameters
    ----------
    designation : str, optional
        Catalogue designation (``306``, ``6306-2RS/C3``, ``75-313``); a number is read as its
        text (``6205``), as :func:`bearingload.bearings.catalog.lookup` reads it.
    balls : int, optional
        Number of balls z (required without a designation).
    ball_diameter, pitch_diameter : float, optional
        D_w and d_m, replacing the catalogue's. [mm]
    f_i, f_o : float, optional
        Inner and outer groove conformity r / D_w. [-]
    modulus : float, optional
        Young's modulus E of the rings (and of the balls without ``ball_material``); default
        208 000. [MPa]
    poisson : float, optional
        Poisson's ratio nu of the rings (and balls, as ``modulus``); default 0.3. [-]
    stiffness : float, optional
        Ball stiffness K replacing the Hertz value. [N/mm^1.5]
    clearance : str, float or ClearanceSpec, optional
        G_r as a length (float: [mm]; text with a unit) or a class, see :func:`parse_clearance`.
    clearance_pick : {"mean", "min", "max"}
        Where in a class range to take G_r.
    maker : str, optional
        Whose ball set (``NSK`` default, ``NTN``, ``SKF``, ``GMN``, ``GOST`` ...), see
        :func:`bearingload.bearings.catalog.variant`.
    ball_material : {"steel", "si3n4"}, optional
        The balls' material (:mod:`bearingload.bearings.materials`): their modulus and
        Poisson's ratio enter the Hertz contact with the rings' (the bearing's ``modulus`` and
        ``poisson`` become the equivalent pair of :func:`bearingload.contact.hertz.
        equivalent_material`), their density the ball dynamics at speed. None: the balls are
        of the rings' material (steel unless ``modulus``/``poisson`` say otherwise).
    shaft_fit, housing_fit : str, optional
        ISO 286 classes of the seats (``k5``, ``m6`` ...; ``H7``, ``N7`` ...): the bearing is
        solved at its operating clearance (:mod:`bearingload.bearings.mounting`); its
        ``clearance`` becomes that, ``mounting`` holds the unmounted one and the reductions.
    shaft_bore, housing_diameter : float, optional
        Bore d_0 of a hollow shaft and outside diameter D_h of the housing (none: solid shaft,
        thick housing). [mm]
    inner_ring_temperature, outer_ring_temperature : float, optional
        The rings' temperatures in operation, both or neither (-60 to 250). [°C]

    Returns
    -------
    ResolvedBearing

    Raises
    ------
    InputError
        Unknown designation (``bearing``), impossible geometry (``balls``, ``ball_diameter``,
        ``pitch_diameter``, ``f_i``, ``f_o``), missing inputs, a clearance class without a bore
        (``clearance``), bad modulus or Poisson's ratio.
    """
    if designation is not None and not isinstance(designation, str):
        designation = str(designation)  # 6205 read as "6205", as catalog.lookup reads it
    _check_inputs(modulus, stiffness, ball_diameter, pitch_diameter, poisson, clearance_pick)
    fits, temperatures = (shaft_fit, housing_fit), (inner_ring_temperature, outer_ring_temperature)
    seats = (*fits, shaft_bore, housing_diameter, *temperatures)
    # a bearing as bought (nothing of the mounting given): no Mounting to check or build
    mounting = None if all(v is None for v in seats) else check_mounting(Mounting(*seats))
    spec = clearance if isinstance(clearance, ClearanceSpec) else parse_clearance(clearance)
    if designation is not None and _is_roller(designation):
        if ball_material is not None and str(ball_material).strip().lower() != "steel":
            raise InputError("ball_material", "a hybrid bearing is modelled for ball bearings "
                             "only: the roller contact is Palmgren's steel-on-steel law")  # fmt: skip
        return mount(_roller(designation, maker, balls, ball_diameter, pitch_diameter, modulus,
                             poisson, stiffness, spec, clearance_pick), mounting)  # fmt: skip
    given = {"balls": balls, "ball_diameter": ball_diameter, "pitch_diameter": pitch_diameter,
             "f_i": f_i, "f_o": f_o}  # fmt: skip
    if designation is not None:
        from bearingload.bearings.angular import parse_angular, refuse_gost_suffix

        angular = parse_angular(designation)
        if angular is None:
            refuse_gost_suffix(designation)
        if angular is not None:
            if spec is not None:
                raise InputError(
                    "clearance",
                    "an angular-contact bearing takes no clearance: the design contact angle "
                    "fixes its geometry",
                )
            b = _angular(angular, given, modulus, poisson, stiffness, maker, ball_material)
            return mount(b, mounting)
    g = _ball_set(designation, maker, given, stiffness)
    prov = g.provenance + _ball_set_provenance(g, given)
    e = DEFAULT_MODULUS if modulus is None else float(modulus)
    nu = DEFAULT_POISSON if poisson is None else float(poisson)
    material = None
    if ball_material is not None:
        from bearingload.bearings.materials import ball_material as find_ball_material

        material = find_ball_material(ball_material)
    k_i = k_o = k_hertz = None
    if g.dw is not None and g.dm is not None and g.fi is not None and g.fo is not None:
        from bearingload.contact.hertz import ball_stiffness

        prov += _material_provenance(e, nu, modulus, poisson, material)
        e, nu = contact_pair(e, nu, material)
        ks = ball_stiffness(g.dw, g.dm, g.fi, g.fo, e, nu)
        k_i, k_o, k_hertz = float(ks.inner), float(ks.outer), float(ks.ball)
        prov += [
            Provenance("stiffness_inner", "inner contact K_i", k_i, "N/mm^1.5", "Hertz, exact"),
            Provenance("stiffness_outer", "outer contact K_o", k_o, "N/mm^1.5", "Hertz, exact"),
        ]
    k = float(stiffness) if stiffness is not None else float(k_hertz or 0.0)
    k_src = "given" if stiffness is not None else "Hertz, exact: (K_i^-2/3 + K_o^-2/3)^-3/2"
    prov.append(Provenance("stiffness", "ball stiffness K (series)", k, "N/mm^1.5", k_src))
    g_r, cls, rng, pick, g_src = resolve_clearance(spec, g.geom, g.bore, clearance_pick)
    if g.dw is not None and not clearance_fits(g_r, g.dw):
        raise _clearance_beyond_ball(spec, g_r, g.dw)
    sources = g.sources + ([clearance_row_source(g.bore)] if rng is not None else [])
    prov.append(Provenance("clearance", "radial clearance G_r (total)", g_r * 1e3, "µm", g_src))
    geom = g.geom
    c = geom.C if geom is not None else None
    c0 = geom.C0 if geom is not None else None
    if geom is not None:
        prov += [
            Provenance("C", "dynamic load rating C", c, "N", _rating_source(geom, c)),
            Provenance("C0", "static load rating C0", c0, "N", _rating_source(geom, c0)),
        ]
    return mount(ResolvedBearing(
        designation=designation, geometry=geom, balls=g.z, ball_diameter=g.dw,
        pitch_diameter=g.dm, f_i=g.fi, f_o=g.fo, modulus=e, poisson=nu, stiffness=k,
        stiffness_inner=k_i, stiffness_outer=k_o, stiffness_given=stiffness is not None,
        clearance=g_r, clearance_class=cls, clearance_range=rng, clearance_pick=pick,
        C=c, C0=c0, provenance=tuple(prov), sources=tuple(sources),
        ball_material=None if material is None else material.name,
        ball_density=None if material is None else material.density,
    ), mounting)  # fmt: skip


def contact_pair(e: float, nu: float, balls: BallMaterial | None) -> tuple[float, float]:
    """The (modulus, poisson) the contacts use: the rings' (E, nu) where the balls are of
    the rings' material (``balls`` None), else the equivalent pair of the hybrid contact
    (:func:`bearingload.contact.hertz.equivalent_material`). [MPa], [-]"""
    from bearingload.contact.hertz import equivalent_material

    if balls is None:
        return e, nu
    return equivalent_material(e, nu, balls.modulus, balls.poisson)


#: The contact of each kind of bearing, which gives its load-deflection exponent m of
#: Q = K delta^m: Hertz point contact 1.5, line contact 10/9 (Palmgren).
CONTACTS = {
    "ball": "a ball bearing (Hertz point contact) has m = 1.5",
    "roller": "a roller bearing (line contact) has m = 10/9",
}


def check_exponent(bearing: ResolvedBearing, exponent: float | None) -> None:
    """Refuse a load-deflection exponent m other than the one the bearing's contact gives
    (:data:`CONTACTS`); None: the bearing's own.

    Raises
    ------
    InputError
        (parameter ``exponent``) naming the contact and its m.
    """
    if exponent is not None and exponent != bearing.exponent:
        given = "a bearing designation" if bearing.designation is not None else "its ball geometry"
        raise InputError(
            "exponent",
            f"{CONTACTS[bearing.kind]}; another exponent needs a ring given by its stiffness, "
            f"not {given}",
        )


def resolve_bearings(
    designation: str | None = None,
    *,
    clearance_pick: str = "mean",
    exponent: float | None = None,
    **options: Any,
) -> list[ResolvedBearing]:
    """The bearing of :func:`resolve_bearing` at every pick of ``clearance_pick``: one, or the
    min, mean and max of its clearance class for ``"range"`` (:func:`picks_of`).

    Parameters
    ----------
    designation, **options
        As :func:`resolve_bearing`.
    clearance_pick : {"mean", "min", "max", "range"}
        Where in a class range to take G_r; ``range``: at each of min, mean and max.
    exponent : float, optional
        A load-deflection exponent m to check against the bearing's (:func:`check_exponent`). [-]

    Raises
    ------
    InputError
        Those of :func:`resolve_bearing` and :func:`check_exponent`; ``pick`` for ``range`` with a
        clearance given as a length.

    >>> [round(b.clearance, 4) for b in resolve_bearings("306", clearance="C3",
    ...                                                   clearance_pick="range")]
    [0.013, 0.0205, 0.028]
    """
    picks = picks_of(clearance_pick)
    resolved = resolve_bearing(
        designation, clearance_pick="mean" if clearance_pick == RANGE else clearance_pick, **options
    )
    check_exponent(resolved, exponent)
    if clearance_pick != RANGE:
        return [resolved]
    if resolved.clearance_range is None:
        raise InputError(
            "pick",
            f"{RANGE!r} needs a clearance class (C2 CN C3 C4 C5), not a clearance length",
        )
    return [resolved.with_clearance(p) for p in picks]


def _check_inputs(
    modulus: float | None,
    stiffness: float | None,
    ball_diameter: float | None,
    pitch_diameter: float | None,
    poisson: float | None,
    clearance_pick: str,
) -> None:
    for name, value in (
        ("modulus", modulus),
        ("stiffness", stiffness),
        ("ball_diameter", ball_diameter),
        ("pitch_diameter", pitch_diameter),
    ):
        if value is not None:
            finite_positive(name, value)
    if poisson is not None and not (math.isfinite(poisson) and -1.0 < poisson <= 0.5):
        raise InputError("poisson", f"must lie in (-1, 0.5]; got {poisson!r}")
    if clearance_pick not in PICKS:
        raise InputError("pick", f"unknown pick {clearance_pick!r}; allowed: {', '.join(PICKS)}")


class _BallSet:
    """The ball set in use and where it came from (internal to :func:`resolve_bearing`; a
    plain class, read by attribute only: no dataclass to build on every solve)."""

    __slots__ = ("geom", "z", "dw", "dm", "fi", "fo", "bore", "sources", "provenance")

    def __init__(
        self,
        geom: BearingGeometry | None,
        z: int,
        dw: float | None,
        dm: float | None,
        fi: float | None,
        fo: float | None,
        bore: float | None,
        sources: list[str],
        provenance: list[Provenance],
    ) -> None:
        self.geom = geom
        self.z = z
        self.dw = dw
        self.dm = dm
        self.fi = fi
        self.fo = fo
        self.bore = bore
        self.sources = sources
        self.provenance = provenance


def _ball_set(
    designation: str | None, maker: str | None, given: dict[str, Any], stiffness: float | None
) -> _BallSet:
    """The catalogue row with the overrides applied, or the ball set given by hand."""
    sources: list[str] = []
    hand_bore: float | None = None
    geom: BearingGeometry | None = None
    if designation is not None:
        try:
            geom = lookup(designation, maker=maker, **given)
        except InputError as exc:
            if exc.parameter == "maker":
                raise
            # not in the catalogue (or no ball set there): with the ball set given by hand, the
            # designation still gives the bore, which resolves a clearance class
            if None in (given["balls"], given["ball_diameter"], given["pitch_diameter"]):
                raise
            from bearingload.bearings.designation import parse

            hand_bore = parse(designation).bore
            sources.append(
                f"{designation}: not used from the catalogue; bore d = {hand_bore:g} mm read from "
                "the designation, ball set given by hand"
            )
    if geom is not None:
        sources.append(f"catalogue row {geom.designation} ({geom.standard}): {geom.source}")
        if geom.only_maker:
            sources.append(only_maker_text(geom))
        if geom.notes:
            sources.append(f"catalogue notes: {geom.notes}")
        prov = [
            Provenance("d", "bore d", geom.d, "mm", "catalogue"),
            Provenance("D", "outside diameter D", geom.D, "mm", "catalogue"),
        ]
        return _BallSet(geom, int(geom.balls or 0), geom.ball_diameter, geom.pitch_diameter,
                        geom.f_i, geom.f_o, geom.d, sources, prov)  # fmt: skip
    balls, dw, dm = given["balls"], given["ball_diameter"], given["pitch_diameter"]
    if balls is None:
        raise MissingError("balls", "the number of balls z; or give a 'bearing' designation")
    if isinstance(balls, bool) or int(balls) != balls or balls < 1:
        raise InputError("balls", f"the number of balls must be a whole number >= 1, not {balls!r}")
    if dw is not None and dm is not None:
        ball_spacing(balls, dw, dm)
        if not ball_size_fits(dw, dm):
            raise ball_too_small(dw, dm)
    for name in ("f_i", "f_o"):  # the ring's rule, whether or not a Hertz stiffness follows
        if given[name] is not None:
            conformity(name, given[name])
    fi = given["f_i"] if given["f_i"] is not None or dw is None else DEFAULT_F_I
    fo = given["f_o"] if given["f_o"] is not None or dw is None else DEFAULT_F_O
    if stiffness is None and (dw is None or dm is None):
        raise _missing_stiffness(dw, dm)
    return _BallSet(None, int(balls), dw, dm, fi, fo, hand_bore, sources, [])


def _missing_stiffness(dw: float | None, dm: float | None) -> MissingError:
    """The ball stiffness is needed, or the ball geometry: the refusal names the half of the
    geometry not given, else the stiffness."""
    if dw is None and dm is None:
        return MissingError(
            "stiffness",
            "the ball stiffness; or give the ball geometry ('ball_diameter' and "
            "'pitch_diameter'), or a 'bearing' designation",
        )
    given, missing = (
        ("ball_diameter", "pitch_diameter") if dm is None else ("pitch_diameter", "ball_diameter")
    )
    return MissingError(
        missing,
        f"the ball geometry needs it beside '{given}'; or give the "
        "ball stiffness 'stiffness' instead",
    )


def only_maker_text(geom: BearingGeometry) -> str:
    """Why a ball set was used without a maker being named: its maker is the only one."""
    return (
        f"ball set: {geom.maker}'s, the only maker with a ball set for {geom.designation} in the "
        f"catalogue (no {DEFAULT_MAKER} set), used without a maker being named"
    )


def _ball_set_provenance(g: _BallSet, given: dict[str, Any]) -> list[Provenance]:
    """z, D_w, d_m, f_i, f_o with the source of each: catalogue, override or given."""
    geom = g.geom
    overridden = set(geom.overrides) if geom is not None else set(given)

    def src(field: str, default: str) -> str:
        if geom is None:
            return "given" if given.get(field) is not None else default
        return "given (override)" if field in overridden else default

    set_src = "catalogue"
    if geom is not None and geom.standard == "ISO" and geom.maker is not None:
        set_src = f"catalogue: {geom.maker} ball set, {geom.method}"
        if geom.only_maker:
            set_src += f" (the only maker with a set for {geom.designation})"
    pitch_src = set_src
    if geom is not None and "pitch_diameter" not in overridden:
        pitch_src = "(d + D)/2" if math.isclose(g.dm or 0.0, (geom.d + geom.D) / 2) else pitch_src
    return [
        Provenance("balls", "balls z", g.z, "", src("balls", set_src)),
        Provenance("ball_diameter", "ball diameter D_w", g.dw, "mm", src("ball_diameter", set_src)),
        Provenance(
            "pitch_diameter", "pitch diameter d_m", g.dm, "mm", src("pitch_diameter", pitch_src)
        ),
        Provenance(
            "f_i", "inner conformity f_i = r_i/D_w", g.fi, "", src("f_i", _f_source(geom, "f_i"))
        ),
        Provenance(
            "f_o", "outer conformity f_o = r_o/D_w", g.fo, "", src("f_o", _f_source(geom, "f_o"))
        ),
    ]


def _material_provenance(
    e: float, nu: float, modulus: float | None, poisson: float | None,
    balls: BallMaterial | None = None,
) -> list[Provenance]:  # fmt: skip
    e_src = "given" if modulus is not None else "default: bearing steel (NSK 208 000 MPa)"
    nu_src = "given" if poisson is not None else "default: steel"
    if balls is None:
        return [
            Provenance("modulus", "Young's modulus E", e, "MPa", e_src),
            Provenance("poisson", "Poisson's ratio nu", nu, "", nu_src),
        ]
    from bearingload.contact.hertz import reduced_modulus

    e_star = float(reduced_modulus(e, nu, balls.modulus, balls.poisson))
    return [
        Provenance("modulus", "Young's modulus E of the rings", e, "MPa", e_src),
        Provenance("poisson", "Poisson's ratio nu of the rings", nu, "", nu_src),
        Provenance("ball_material", "ball material", balls.title, "", "given (--ball-material)"),
        Provenance("ball_modulus", "Young's modulus E of the balls", balls.modulus, "MPa",
                   balls.source),
        Provenance("ball_poisson", "Poisson's ratio nu of the balls", balls.poisson, "",
                   balls.source),
        Provenance("ball_material_density", "density of the balls", balls.density, "kg/m^3",
                   balls.source),
        Provenance("contact_modulus", "contact modulus E* (balls on rings)", e_star, "MPa",
                   "1/E* = (1 - nu_r^2)/E_r + (1 - nu_b^2)/E_b"),
    ]  # fmt: skip


def _f_source(geom: BearingGeometry | None, field: str) -> str:
    if geom is None:
        return f"default {DEFAULT_F_I if field == 'f_i' else DEFAULT_F_O} (ISO/TS 16281 convention)"
    value = getattr(geom, field)
    default = DEFAULT_F_I if field == "f_i" else DEFAULT_F_O
    if value == default:
        return "default (ISO/TS 16281 convention)"
    return "catalogue"


def _roller(
    designation: str,
    maker: str | None,
    rollers: int | None,
    roller_diameter: float | None,
    pitch_diameter: float | None,
    modulus: float | None,
    poisson: float | None,
    stiffness: float | None,
    spec: ClearanceSpec | None,
    clearance_pick: str = "mean",
) -> ResolvedBearing:
    """A cylindrical roller bearing, see :func:`bearingload.bearings.resolve_roller.resolve_roller`."""
    from bearingload.bearings.resolve_roller import resolve_roller

    if maker is not None:
        raise InputError("maker", "the roller bearings have one design each (SKF ECP)")
    return resolve_roller(
        designation,
        rollers=rollers,
        roller_diameter=roller_diameter,
        pitch_diameter=pitch_diameter,
        modulus=modulus,
        poisson=poisson,
        stiffness=stiffness,
        clearance=spec,
        clearance_pick=clearance_pick,
    )


def _is_roller(designation: str) -> bool:
    """True for a cylindrical roller designation (NU206 ...); unreadable text counts as not."""
    from bearingload.bearings.designation import parse

    try:
        return parse(designation).kind == "roller"
    except InputError:
        return False


def _rating_source(geom: BearingGeometry, value: float | None) -> str:
    if not value:
        return "unknown"
    if geom.standard == "ISO" and geom.maker is not None:
        return f"catalogue: {geom.maker}"
    return "catalogue"


def _angular(
    parsed: Any, given: dict[str, Any], modulus: float | None, poisson: float | None,
    stiffness: float | None, maker: str | None = None, ball_material: str | None = None,
) -> ResolvedBearing:  # fmt: skip
    """An angular-contact bearing of the catalogue (:mod:`bearingload.bearings.angular`): its
    row, with the values given by hand replacing the row's, at its nominal contact angle, no
    clearance."""
    import dataclasses

    from bearingload.bearings.angular import find_angular
    from bearingload.bearings.designation import Designation

    row = find_angular(parsed, maker)
    fi = DEFAULT_F_I if given["f_i"] is None else given["f_i"]
    fo = DEFAULT_F_O if given["f_o"] is None else given["f_o"]
    set_ = {"balls": row.balls, "ball_diameter": row.ball_diameter,
            "pitch_diameter": row.pitch_diameter, "f_i": fi, "f_o": fo}  # fmt: skip
    hand = {k: v if given[k] is None else given[k] for k, v in set_.items()}
    z, dw, dm = int(hand["balls"]), float(hand["ball_diameter"]), float(hand["pitch_diameter"])
    from bearingload.bearings.catalog import check_geometry

    check_geometry(row.d, row.D, z, dw, dm, fi, fo)  # values given by hand must fit the rings
    b = resolve_bearing(balls=z, ball_diameter=dw, pitch_diameter=dm, f_i=fi, f_o=fo,
                        modulus=modulus, poisson=poisson, stiffness=stiffness,
                        ball_material=ball_material)  # fmt: skip
    name = Designation(parsed.text, parsed.standard, parsed.series, parsed.bore_code, parsed.bore,
                       row.designation, row.designation if parsed.standard == "GOST" else None)  # fmt: skip
    overrides = tuple(k for k in set_ if given[k] is not None)
    geom = BearingGeometry(
        row.designation, parsed.standard, row.d, row.D, row.B, dw, z, dm, row.C, row.C0, fi, fo,
        row.source, row.notes,
        name, f0=row.f0, overrides=overrides, maker=row.maker, method=row.method, confidence=row.confidence,
        limiting_speed_grease=row.limiting_speed_grease, limiting_speed_oil=row.limiting_speed_oil,
        limiting_speed_source=row.limiting_speed_source,
    )  # fmt: skip
    src = f"catalogue row {row.designation} ({row.maker}, {row.contact_angle:g}°): {row.source}"
    what = {k: "given" if k in overrides else f"catalogue ({row.method})" for k in set_}
    for k in ("f_i", "f_o"):
        what[k] = "given" if k in overrides else "not printed by the source: the default, assumed"
    prov = [
        Provenance("d", "bore d", row.d, "mm", "catalogue"),
        Provenance("D", "outside diameter D", row.D, "mm", "catalogue"),
        Provenance("contact_angle", "nominal contact angle alpha_0", row.contact_angle, "°",
                   f"designation {parsed.text} ({parsed.what})"),
        Provenance("balls", "number of balls z", hand["balls"], "", what["balls"]),
        Provenance("ball_diameter", "ball diameter D_w", hand["ball_diameter"], "mm",
                   what["ball_diameter"]),
        Provenance("pitch_diameter", "pitch diameter d_m", hand["pitch_diameter"], "mm",
                   what["pitch_diameter"]),
        Provenance("f_i", "inner conformity f_i = r_i/D_w", fi, "", what["f_i"]),
        Provenance("f_o", "outer conformity f_o = r_o/D_w", fo, "", what["f_o"]),
        *[p for p in b.provenance if p.key not in ("balls", "ball_diameter", "pitch_diameter",
                                                    "clearance", "f_i", "f_o")],
        Provenance("clearance", "radial clearance G_r (total)", 0.0, "µm",
                   "none: the design contact angle fixes the geometry"),
        Provenance("C", "dynamic load rating C", row.C, "N", f"catalogue ({row.maker})"),
        Provenance("C0", "static load rating C0", row.C0, "N", f"catalogue ({row.maker})"),
    ]  # fmt: skip
    return dataclasses.replace(
        b, designation=parsed.text, geometry=geom, C=row.C, C0=row.C0, clearance=0.0,
        contact_angle=row.contact_angle, provenance=tuple(prov),
        sources=(src, f"catalogue notes: {row.notes}"),
    )  # fmt: skip


def _clearance_beyond_ball(spec: ClearanceSpec | None, g_r: float, dw: float) -> InputError:
    """The models' refusal of G_r [mm] with balls of D_w [mm]
    (:func:`bearingload.validate.clearance_beyond_ball`) as given: a clearance of its class
    names the ball diameter as the slip; a bare number (mm) the micrometres it likely meant,
    where that would fit."""
    refused = clearance_beyond_ball(g_r, dw)
    what = refused.problem
    if spec is None or spec.length is None:
        return InputError(
            "ball_diameter",
            f"{dw:g} mm is too small for this bearing's clearance: {what} (bare numbers are mm)",
        )
    bare = re.fullmatch(r"\s*[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?\s*", spec.text)
    if bare and clearance_fits(g_r * 1e-3, dw):
        return refused.with_way_out(f"a bare number is mm (did you mean {g_r:g}um?)")
    return refused
