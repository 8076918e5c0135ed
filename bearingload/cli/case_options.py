"""The case options of ``solve``, ``sweep`` and ``table``: declared once, read once.

:func:`case_options` declares every option that describes the case (the bearing, its balls, the
load, stiffness, clearance, geometry, material, cage angle, exponent and the combined load), each
with its one help text; a command lists the few it does not take (``omit``). Click's values are
converted once into a :class:`CaseOptions`, which the command receives as its ``case`` argument
and which converts itself into the library's arguments (:meth:`CaseOptions.bearing_arguments`,
:meth:`CaseOptions.combined_arguments`). Every option answers for the library's names of its
parameter (:class:`bearingload.cli.options.LibraryOption`), so a library error names the option
the user typed.

The LOAD options (:data:`LOAD_PARAMS`: axial load, moment, cross moment, misalignment) choose the
3-D combined engine; ``--tilt-radius`` only sets its lever; ``--dynamic-rating`` and
``--rotating`` (:data:`LIFE_PARAMS`) feed only the lives and never change a ball load.

Imports nothing heavy: the command line reads it at start-up.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass, fields
from typing import Any

import click

from bearingload.bearings.mounting import MOUNTING_PARAMS
from bearingload.cli.options import (
    BARE,
    CageAngle,
    Exponent,
    LibraryArgument,
    LibraryOption,
    PreloadValue,
    Quantity,
    option_message,
    option_name,
    units_help,
    usage_error,
)
from bearingload.constants import CONTAMINATION_LEVELS
from bearingload.errors import InputError
from bearingload.units import plausible_ranges_help

#: The load options: any of them given, the combined engine solves the case.
LOAD_PARAMS = ("axial_load", "moment", "moment_cross", "misalignment", "contact_angle")
#: The options of the combined engine that are not loads: the lever of the tilt.
TILT_PARAMS = ("tilt_radius",)
#: The operating conditions of the lives in hours, the modified life and the film
#: (:class:`bearingload.bearings.service_life.Operating`); they change no load.
SERVICE_PARAMS = ("static_rating", "speed", "reliability", "viscosity", "oil", "viscosity_40",
                  "viscosity_100", "viscosity_index", "temperature", "contamination", "e_c",
                  "fatigue_load_limit", "roughness", "pressure_viscosity")  # fmt: skip
#: What --speed 0 means (a shaft at rest) and how to ask for it.
AT_REST = ("a shaft at rest is the case without --speed: the static model (the answer of the "
           "ball dynamics at 0 rpm), its lives in 10^6 revolutions, none in hours")  # fmt: skip
#: The options of the ball dynamics at --speed (solve's ball bearings: the combined engine).
DYNAMICS_PARAMS = ("ball_density", "quasi_static")
#: The options that give the operating viscosity from the oil (instead of --viscosity).
OIL_PARAMS = ("oil", "viscosity_40", "viscosity_100", "viscosity_index", "temperature")
#: The options that feed only the lives.
LIFE_PARAMS = ("dynamic_rating", "rotating", *SERVICE_PARAMS)
#: The combined-load options, in the order a refusal names the first one given.
COMBINED_PARAMS = LOAD_PARAMS + TILT_PARAMS + LIFE_PARAMS
#: Why sweep and table refuse the mounting options (solve and batch take them).
MOUNTING_REFUSAL = (
    "the operating clearance of a mounted bearing is solve's and batch's (docs/mounting.md); "
    "'bearingload solve' prints it: give it here with -G"
)
#: The options only a bearing or its ball geometry uses, refused for a ring given by z and K.
BEARING_ONLY = ("inner_conformity", "outer_conformity", "modulus", "poisson", "ball_material",
                *MOUNTING_PARAMS, "maker",
                "dynamic_rating", "rotating", *SERVICE_PARAMS)  # fmt: skip

CLEARANCE_HELP = (
    "Radial internal clearance G_r, total play (gap per side G_r/2; negative = preload): a length "
    "(bare number: mm; units um, mm, in) or an ISO 5753-1 class C2, CN, C3, C4, C5, resolved by "
    "the bearing's bore (deep groove ball or cylindrical roller bearing table); GOST 24810 groups "
    f"are written G6, G7, G8, G9. A{plausible_ranges_help('length', 'clearance')[1:]} as "
    "implausible (20 -> did you mean 20um?); write 1.5mm to mean it. Default: 0 without a "
    "bearing; with one, the class its designation marks, else CN (an unmarked designation "
    "means the normal group); table k and kq: 0, the papers' condition."
)


class Clearance(click.ParamType):
    """A clearance length or class, read by :func:`bearingload.bearings.clearance.parse_clearance`."""

    name = "LENGTH|CLASS"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        from bearingload.bearings.clearance import ClearanceSpec, parse_clearance

        if isinstance(value, ClearanceSpec):
            return value
        try:
            return parse_clearance(value)
        except InputError as exc:
            self.fail(exc.message, param, ctx)


class Temperature(click.ParamType):
    """A temperature, read by :func:`bearingload.units.parse_temperature` (°C; ``K`` kelvin)."""

    name = "TEMPERATURE [°C]"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        from bearingload.units import parse_temperature

        if isinstance(value, float):
            return value
        try:
            return parse_temperature(value)
        except InputError as exc:
            self.fail(exc.message, param, ctx)


class TiltRadius(click.ParamType):
    """``groove``, ``pitch`` or a length, read by :func:`bearingload.bearings.tilt.parse_tilt_radius`."""

    name = "groove|pitch|LENGTH"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        from bearingload.bearings.tilt import parse_tilt_radius

        try:
            return parse_tilt_radius(value)
        except InputError as exc:
            self.fail(exc.message, param, ctx)


class Arrangement(click.ParamType):
    """DB, DF or DT, in either case."""

    name = "DB|DF|DT"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        text = str(value).strip().upper()
        if text not in ("DB", "DF", "DT"):
            self.fail(
                f"{value!r}: give DB (back-to-back), DF (face-to-face) or DT (tandem)", param, ctx
            )
        return text


def _option(*decls: str, **attrs: Any) -> tuple[tuple[str, ...], dict[str, Any]]:
    return decls, attrs


_FORCE, _MOMENT, _ANGLE = (units_help(k) for k in ("force", "moment", "angle"))
MAKER_HELP = (
    "Whose ball set the designation uses where makers differ: NSK (default), NTN, SKF, GMN, "
    "GOST, KOYO, EPK (angular-contact rows; the default where NSK has none), or a published "
    "test-rig set (CWRU, PRONOSTIA, PADERBORN); 'bearingload catalog show X' lists the makers "
    "of X."
)

#: Every case option: click parameter name -> (declarations, attributes), in help order;
#: ``library``: the library's other names of the parameter (:class:`LibraryOption`).
DECLARATIONS: dict[str, tuple[tuple[str, ...], dict[str, Any]]] = {
    "balls": _option(
        "--balls",
        "-z",
        type=int,
        library=("rollers",),
        help="Number of balls z (1 to 100000; a sweep: 3 or more): required for a ring given "
        "by hand, else it replaces the designation's.",
    ),
    "load": _option(
        "--load",
        "-F",
        type=Quantity("force"),
        library=("radial_load",),
        help=f"Radial load F_r > 0 (>= 0 with an axial load or a moment). Units: {_FORCE} "
        "(bare number: N).",
    ),
    "axial_load": _option(
        "--axial-load",
        "-A",
        type=Quantity("force"),
        help="Axial load F_a on the inner ring (ball bearings; needs the ball "
        f"geometry). Units: {_FORCE} (bare number: N).",
    ),
    "moment": _option(
        "--moment",
        type=Quantity("moment"),
        help="Moment M tilting the inner ring in the plane of the radial load (about the "
        "axis across the load line); default: the ring is free to tilt (M = 0). Units: "
        f"{_MOMENT} (bare number: N mm).",
    ),
    "moment_cross": _option(
        "--moment-cross",
        type=Quantity("moment"),
        help="Moment M_cross tilting the inner ring about the load line (MASTA's M_x); "
        f"default 0. Units: {_MOMENT} (bare number: N mm).",
    ),
    "misalignment": _option(
        "--misalignment",
        type=Quantity("angle"),
        help="Imposed tilt of the inner ring in the plane of the radial load, instead of "
        f"--moment. Units: {_ANGLE} (bare number: degrees).",
    ),
    "contact_angle": _option(
        "--contact-angle",
        type=Quantity("angle"),
        help="Design contact angle of a single-row angular-contact ball bearing given by hand "
        "(0 to 60°; with --ball-diameter and --pitch-diameter): the balls take thrust one way, "
        "F_a >= 0, and leave their grooves when pushed the other way; no clearance. See "
        f"docs/angular_contact.md. Units: {_ANGLE} (bare number: degrees).",
    ),
    "tilt_radius": _option(
        "--tilt-radius",
        type=TiltRadius(),
        help="Lever of the tilt: the radius at which a tilt moves the inner groove centres "
        "axially, and the arm of the moments. 'groove' (default): R_i of the inner groove "
        "curvature centres (ISO/TS 16281); 'pitch': d_m/2, the lever of MASTA's tilts; or a "
        "length (bare number: mm).",
    ),
    "stiffness": _option(
        "--stiffness",
        "-K",
        type=Quantity("stiffness"),
        help="Ball stiffness K of both contacts in series, Q = K delta^m; required without a "
        "bearing or the ball geometry (table k and kq: default 1e5 N/mm^1.5), else it "
        f"replaces the Hertz value. Units: {units_help('stiffness')} (bare number: "
        "N/mm^1.5, N/mm^(10/9) for a cylindrical roller bearing unless --exponent says "
        "otherwise).",
    ),
    "clearance": _option(
        "--clearance", "-G", type=Clearance(), library=("bore",), help=CLEARANCE_HELP
    ),
    "clearance_pick": _option(
        "--clearance-pick",
        type=click.Choice(["min", "mean", "max", "range"]),
        default="mean",
        show_default=True,
        library=("pick",),
        help="Where in a clearance class to take G_r; 'range' (solve): at min, mean and max, "
        "side by side.",
    ),
    "shaft_fit": _option(
        "--shaft-fit",
        help="ISO 286 class of the shaft seat (j5 j6 k5 k6 m5 m6 n5 n6 p5 p6): with the bearing's "
        "ISO 492 Normal bore tolerance it gives the inner ring's interference, which takes "
        "clearance; the case is solved at the operating clearance (docs/mounting.md). Example: "
        "solve 6205 -F 2kN -G C3 --shaft-fit k5 --inner-ring-temperature 50 "
        "--outer-ring-temperature 40.",
    ),
    "housing_fit": _option(
        "--housing-fit",
        help="ISO 286 class of the housing bore (H6 H7 J7 K6 K7 M6 M7 N6 N7 P6 P7), against the "
        "bearing's ISO 492 Normal outside diameter: an interference shrinks the outer raceway.",
    ),
    "shaft_bore": _option(
        "--shaft-bore",
        type=Quantity("length", positive=True),
        help="Bore d_0 of a hollow shaft under --shaft-fit (default a solid shaft): a thinner "
        "shaft lets the inner ring grow less. Bare number: mm.",
    ),
    "housing_diameter": _option(
        "--housing-diameter",
        type=Quantity("length", positive=True),
        help="Outside diameter D_h of the housing wall under --housing-fit (default a housing "
        "thick enough to count as infinite). Bare number: mm.",
    ),
    "inner_ring_temperature": _option(
        "--inner-ring-temperature",
        type=Temperature(),
        help="Temperature of the inner ring (and balls) in operation, with "
        "--outer-ring-temperature: a warmer inner ring takes clearance, alpha (t_i - t_o) E "
        "(-60 to 250 °C; bare number: °C, K kelvin).",
    ),
    "outer_ring_temperature": _option(
        "--outer-ring-temperature",
        type=Temperature(),
        help="Temperature of the outer ring in operation, with --inner-ring-temperature.",
    ),
    "ball_diameter": _option(
        "--ball-diameter",
        type=Quantity("length"),
        library=("D_w", "roller_diameter"),
        help="Ball diameter D_w, replacing the catalogue's. Bare number: mm.",
    ),
    "pitch_diameter": _option(
        "--pitch-diameter",
        type=Quantity("length"),
        library=("d_m",),
        help="Pitch diameter d_m; default the catalogue's, else (d + D)/2. Bare number: mm.",
    ),
    "inner_conformity": _option(
        "--inner-conformity",
        type=float,
        library=("f_i",),
        help="Inner groove conformity f_i = r_i/D_w, in (0.5, 1); default the catalogue's "
        "(0.52 when unknown).",
    ),
    "outer_conformity": _option(
        "--outer-conformity",
        type=float,
        library=("f_o",),
        help="Outer groove conformity f_o = r_o/D_w; default the catalogue's (0.53 when unknown).",
    ),
    "modulus": _option(
        "--modulus",
        type=Quantity("modulus"),
        library=("E1",),
        help="Young's modulus E of the rings (and of the balls unless --ball-material); default "
        "208000 MPa (bearing steel). "
        f"Units: {units_help('modulus')} (bare number: MPa; "
        f"{plausible_ranges_help('modulus')}: 210 -> did you mean 210GPa?).",
    ),
    "poisson": _option(
        "--poisson",
        type=float,
        library=("nu1",),
        help="Poisson's ratio nu of the rings (and balls unless --ball-material); default 0.3.",
    ),
    "ball_material": _option(
        "--ball-material",
        help="Material of the balls: steel or si3n4 (silicon nitride, a hybrid bearing: E 310 "
        "GPa, nu 0.26, 3200 kg/m^3, SKF). Its modulus and Poisson's ratio enter the Hertz "
        "contact with the rings' (--modulus, --poisson stay the rings'), its density the ball "
        "dynamics at --speed (--ball-density overrides it). Default: balls of the rings' "
        "material. Example: solve 6205 -F 2kN --ball-material si3n4.",
    ),
    "maker": _option("--maker", help=MAKER_HELP),
    "cage_angle": _option(
        "--cage-angle",
        type=CageAngle(),
        default="0",
        show_default=True,
        help="Angle of ball 1 from the load line, degrees unless a unit follows (12, 12deg, "
        "0.2rad, 3mrad); 0 = a ball under the load, 'half' = the load between two balls.",
    ),
    "exponent": _option(
        "--exponent",
        "-m",
        type=Exponent(),
        default=1.5,
        show_default=True,
        help="Load-deflection exponent m: 1.5 (or 3/2) for balls, 10/9 for rollers.",
    ),
    "dynamic_rating": _option(
        "--dynamic-rating",
        "-C",
        type=Quantity("force", positive=True),
        help="Basic dynamic load rating C_r for the lives L10 and L10r, replacing the "
        f"catalogue's (needed for a bearing given by hand); changes no load. Units: {_FORCE} "
        "(bare number: N).",
    ),
    "rotating": _option(
        "--rotating",
        type=click.Choice(["inner", "outer"]),
        help="The ring that rotates relative to the load, for the reference rating life "
        "L10r and, with --speed, the defect frequencies (default inner); changes no load.",
    ),
    "static_rating": _option(
        "--static-rating",
        type=Quantity("force", positive=True),
        library=("C0",),
        help="Basic static load rating C_0 for the static safety s0 = C0/P0 and ISO 281's "
        "estimate of C_u, replacing the catalogue's; changes no load. Units: "
        f"{_FORCE} (bare number: N).",
    ),
    "speed": _option(
        "--speed",
        type=Quantity("speed", positive=True, at_zero=AT_REST),
        help="Shaft speed n of the rotating ring: every life also in hours, L 10^6/(60 n); "
        "needed for the rated viscosity. In 'solve', 'sweep' and 'table life' a ball bearing "
        "includes each ball's centrifugal force and gyroscopic moment (outer-raceway control, "
        "the inner ring turning; the combined engine, F_a = 0 without a load option; "
        "docs/speed.md) unless --quasi-static (a pair: both bearings); a roller bearing keeps "
        "the static model. Units: rpm, r/min, rad/s, 1/s, Hz (bare number: rpm; a bare number of 1e6 or more is refused).",
    ),
    "ball_density": _option(
        "--ball-density",
        type=click.FloatRange(min=0.0, min_open=True, max=1e5),
        help="Density of the balls in kg/m^3 for their centrifugal force and gyroscopic moment "
        "at --speed (default that of --ball-material, else bearing steel 7850; silicon "
        "nitride about 3200).",
    ),
    "quasi_static": _option(
        "--quasi-static",
        is_flag=True,
        default=None,  # None when not given, as every case option
        help="With --speed, solve the static model (no ball dynamics): the speed then gives "
        "the lives in hours only.",
    ),
    "reliability": _option(
        "--reliability",
        type=click.FloatRange(90.0, 99.95),
        help="Reliability R in % (90 to 99.95) for a_1 of ISO 281 Table 12 in the modified "
        "lives; default 90 (a_1 = 1).",
    ),
    "viscosity": _option(
        "--viscosity",
        type=Quantity("viscosity", positive=True),
        help="Operating kinematic viscosity nu of the lubricant (at the operating "
        "temperature): kappa = nu/nu_1, a_ISO and the modified lives of ISO 281 (needs "
        "--speed). Units: mm^2/s, cSt, m^2/s (bare number: mm^2/s).",
    ),
    "oil": _option(
        "--oil",
        help="ISO 3448 grade of the oil (VG2 ... VG3200; VG68 = 68 mm^2/s at 40 °C, +-10 %) "
        "instead of --viscosity: with --temperature, nu at the operating temperature by ASTM "
        "D341 (Walther) through nu_40 and nu_100 (--viscosity-100, else from the viscosity "
        "index by ASTM D2270).",
    ),
    "viscosity_40": _option(
        "--viscosity-40",
        type=Quantity("viscosity", positive=True),
        help="Kinematic viscosity of the oil at 40 °C (its datasheet's), instead of --oil. "
        "Units: mm^2/s, cSt, m^2/s (bare number: mm^2/s).",
    ),
    "viscosity_100": _option(
        "--viscosity-100",
        type=Quantity("viscosity", positive=True),
        help="Kinematic viscosity of the oil at 100 °C (its datasheet's), with --oil or "
        "--viscosity-40: ASTM D341 through the two points gives nu at --temperature. Units: "
        "mm^2/s, cSt, m^2/s (bare number: mm^2/s).",
    ),
    "viscosity_index": _option(
        "--viscosity-index",
        type=float,
        help="Viscosity index VI of the oil (its datasheet's), with --oil or --viscosity-40 "
        "instead of --viscosity-100: nu_100 follows by ASTM D2270. Default 95 (a mineral oil; "
        "the VI of SKF's viscosity-temperature diagram).",
    ),
    "temperature": _option(
        "--temperature",
        type=Temperature(),
        help="Operating temperature of the oil for --oil or --viscosity-40 (bare number or C: "
        "°C; K: kelvin; -60 to 250 °C).",
    ),
    "contamination": _option(
        "--contamination",
        type=click.Choice(CONTAMINATION_LEVELS),
        help="Contamination level of ISO 281 Table 13 (extreme ... very-severe; e_C the "
        "middle of its range for the pitch diameter); default normal.",
    ),
    "e_c": _option(
        "--eC",
        type=click.FloatRange(0.0, 1.0),
        library=("eC",),
        help="Contamination factor e_C (0 to 1) instead of --contamination.",
    ),
    "fatigue_load_limit": _option(
        "--fatigue-load-limit",
        type=Quantity("force", positive=True),
        library=("C_u",),
        help="Fatigue load limit C_u (the maker's); default ISO 281 Annex B's estimate from "
        f"C_0. Units: {_FORCE} (bare number: N).",
    ),
    "roughness": _option(
        "--roughness",
        type=Quantity("length", positive=True),
        help="Composite rms roughness sigma = sqrt(sigma_1^2 + sigma_2^2) of the raceway and "
        "ball, for the film ratio h_min/sigma (e.g. 0.2um; a bare number is mm, 0.01 or more "
        "refused).",
    ),
    "pressure_viscosity": _option(
        "--pressure-viscosity",
        type=click.FloatRange(1.0, 100.0),
        help="Pressure-viscosity coefficient alpha of the oil in 1/GPa (1 to 100) for the film "
        "thickness; default 22 (2.2e-8 1/Pa, a mineral oil).",
    ),
}
#: The options of a bearing pair, declared on ``solve`` only (:func:`case_options` ``pair``).
PAIR_DECLARATIONS: dict[str, tuple[tuple[str, ...], dict[str, Any]]] = {
    "arrangement": _option(
        "--arrangement",
        type=Arrangement(),
        help="Solve a pair of two identical angular-contact ball bearings on one shaft: DB "
        "back-to-back, DF face-to-face, DT tandem (or the designation's suffix: 7205BDB); the "
        "loads act on the shaft at the pair's centre. See docs/angular_contact.md.",
    ),
    "preload": _option(
        "--preload",
        type=PreloadValue(),
        help="Axial preload F_p of a DB or DF pair: the axial force each bearing carries with "
        f"no external load (>= 0; default 0). Units: {_FORCE} (bare number: N). Or a preload "
        "class as the pair is sold, EL | L | M | H (NSK's extra light ... heavy; the force of "
        "the table of 70xx and 72xx at 15° and 25°, printed with its source), also as the "
        "designation's suffix (7205CDBL). E.g. --preload 300N, --preload M.",
    ),
    "width": _option(
        "--width",
        type=Quantity("length", positive=True),
        help="Width B of one bearing of a pair (the bearings' centres lie B apart); default "
        "the catalogue's. Bare number: mm.",
    ),
}


BEARING_HELP = (
    "Catalogue designation (306, 6306-2RS/C3, NU206; see 'bearingload catalog'): its ball set "
    "gives the exact Hertz ball stiffness, its bore resolves a clearance class."
)


def maker_option(func: Callable[..., Any]) -> Callable[..., Any]:
    """``--maker`` alone, for a command that shows a designation (``catalog show``)."""
    return click.option("--maker", cls=LibraryOption, help=MAKER_HELP)(func)


def case_options(
    *,
    bearing: str = "argument",
    omit: Collection[str] = (),
    required: Collection[str] = (),
    defaults: Mapping[str, Any] | None = None,
    hidden: Collection[str] = (),
    pair: bool = False,
) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Declare the case options on a command and hand it one :class:`CaseOptions` as ``case``.

    Parameters
    ----------
    bearing : {"argument", "option"}
        The designation as the optional argument BEARING, or as ``--bearing/-b``.
    omit : collection of str
        Options (parameter names) the command does not declare at all.
    required : collection of str
        Options click requires.
    defaults : mapping, optional
        Defaults other than none (shown in the help), e.g. ``{"load": "1000"}``.
    hidden : collection of str
        Options declared but not in the help: the command refuses them, saying why.
    pair : bool
        Declare the options of a bearing pair (:data:`PAIR_DECLARATIONS`) too.
    """
    declared = {n: d for n, d in DECLARATIONS.items() if n not in omit}
    if pair:  # after --contact-angle, in help order
        at = list(declared).index("contact_angle") + 1 if "contact_angle" in declared else 0
        items = list(declared.items())
        declared = dict(items[:at] + list(PAIR_DECLARATIONS.items()) + items[at:])

    def decorate(func: Callable[..., Any]) -> Callable[..., Any]:
        @functools.wraps(func)
        def command(**kwargs: Any) -> Any:
            values = {name: kwargs.pop(name, None) for name in CASE_FIELDS}
            try:
                case = CaseOptions.of(values)
            except InputError as exc:
                raise usage_error(exc) from exc
            return func(case=case, **kwargs)

        for name, (decls, attrs) in reversed(declared.items()):
            if name in (defaults or {}):
                attrs = attrs | {"default": (defaults or {})[name], "show_default": True}
            if name in hidden:
                attrs = attrs | {"hidden": True}
            option = click.option(
                *decls, name, cls=LibraryOption, required=name in required, **attrs
            )
            command = option(command)
        if bearing == "option":
            return click.option("--bearing", "-b", cls=LibraryOption, help=BEARING_HELP)(command)
        designation = click.argument(
            "bearing", cls=LibraryArgument, required=False, metavar="[BEARING]"
        )
        return designation(command)

    return decorate


@dataclass(frozen=True)
class CaseOptions:
    """The case as the command line gave it, in the package's units (N, mm, N mm, °, MPa).

    ``stiffness`` stays the text typed (its unit is checked against the exponent by
    :meth:`stiffness_value`); ``exponent`` is None unless given (the bearing's own m: 10/9 for a
    cylindrical roller bearing, else 1.5); ``given`` names the options given on the command
    line (not left at a default).
    """

    bearing: str | None = None
    balls: int | None = None
    load: float | None = None
    axial_load: float | None = None
    moment: float | None = None
    moment_cross: float | None = None
    misalignment: float | None = None
    contact_angle: float | None = None
    arrangement: str | None = None
    preload: float | str | None = None
    width: float | None = None
    tilt_radius: str | float | None = None
    stiffness: str | None = None
    clearance: Any = None
    clearance_pick: str = "mean"
    shaft_fit: str | None = None
    housing_fit: str | None = None
    shaft_bore: float | None = None
    housing_diameter: float | None = None
    inner_ring_temperature: float | None = None
    outer_ring_temperature: float | None = None
    ball_diameter: float | None = None
    pitch_diameter: float | None = None
    inner_conformity: float | None = None
    outer_conformity: float | None = None
    modulus: float | None = None
    poisson: float | None = None
    ball_material: str | None = None
    maker: str | None = None
    cage_angle: float | str = 0.0
    exponent: float | None = None
    dynamic_rating: float | None = None
    rotating: str | None = None
    static_rating: float | None = None
    speed: float | None = None
    ball_density: float | None = None
    quasi_static: bool | None = None
    reliability: float | None = None
    viscosity: float | None = None
    oil: str | None = None
    viscosity_40: float | None = None
    viscosity_100: float | None = None
    viscosity_index: float | None = None
    temperature: float | None = None
    contamination: str | None = None
    e_c: float | None = None
    fatigue_load_limit: float | None = None
    roughness: float | None = None
    pressure_viscosity: float | None = None
    given: frozenset[str] = frozenset()
    bare: frozenset[str] = frozenset()  # options typed as a bare number (no unit)

    @classmethod
    def of(cls, values: dict[str, Any]) -> CaseOptions:
        """The case of click's converted ``values`` (parameter name -> value; an omitted option
        None), with the sources of the running command's parameters."""
        ctx = click.get_current_context(silent=True)
        default = (None, click.core.ParameterSource.DEFAULT)
        given = frozenset(
            name
            for name in values
            if ctx is not None and ctx.get_parameter_source(name) not in default
        )
        values = {k: v for k, v in values.items() if v is not None}
        if "exponent" not in given:
            values.pop("exponent", None)
        bare = frozenset(ctx.meta.get(BARE, ())) if ctx is not None else frozenset()
        return cls(**values, given=given, bare=bare)

    @property
    def radial_load(self) -> float:
        """F_r, 0 where none is given (sweep --kurochkin-T; solve and table always have one). [N]"""
        return 0.0 if self.load is None else self.load

    @property
    def by_hand(self) -> bool:
        """True for a ring given by its balls and stiffness: no designation, no ball geometry."""
        return self.bearing is None and self.ball_diameter is None and self.pitch_diameter is None

    @property
    def wants_combined(self) -> bool:
        """True when a load option (:data:`LOAD_PARAMS`) was given: the load alone chooses the
        engine; an angular-contact designation (``7205B``) always takes the combined engine,
        its balls at the contact angle."""
        if any(getattr(self, k) is not None for k in LOAD_PARAMS):
            return True
        from bearingload.bearings.angular import parse_angular

        return self.bearing is not None and parse_angular(self.bearing) is not None

    @property
    def lives_given(self) -> bool:
        """True when an option that feeds only the lives (:data:`LIFE_PARAMS`) was given."""
        return any(getattr(self, k) is not None for k in LIFE_PARAMS)

    def first_given(self, names: Collection[str]) -> str | None:
        """The option (``--axial-load``) of the first of ``names`` with a value, else None."""
        name = next((n for n in names if getattr(self, n) is not None), None)
        return None if name is None else DECLARATIONS[name][0][0]

    def refuse(self, names: Collection[str], where: str, why: str) -> None:
        """One usage error naming the first of the options ``names`` given, ``where`` it was
        given and ``why`` it is refused there."""
        option = self.first_given(names)
        if option is not None:
            raise click.UsageError(f"{option} cannot be used with {where}: {why}")

    def exponent_or(self, default: float = 1.5) -> float:
        """The exponent given, else ``default``. [-]"""
        return default if self.exponent is None else self.exponent

    def stiffness_value(self) -> float | None:
        """--stiffness in N/mm^m, its unit checked against the exponent m: the --exponent given,
        else that of the designation's contact (:func:`bearingload.bearings.designation.
        contact_exponent`: 10/9 for a cylindrical roller bearing, else 1.5)."""
        from bearingload.bearings.designation import contact_exponent
        from bearingload.units import parse_stiffness
        from bearingload.validate import exponent as valid_exponent

        m = self.exponent if self.exponent is not None else contact_exponent(self.bearing)
        valid_exponent(m)  # the exponent's own error comes first, also without a stiffness
        return None if self.stiffness is None else parse_stiffness(self.stiffness, m)

    def cage_angle_deg(self, balls: int) -> float:
        """The cage angle in degrees; ``"half"`` is half a pitch, 180/z. [°]"""
        return 180.0 / balls if self.cage_angle == "half" else float(self.cage_angle)

    def bearing_arguments(self, stiffness: float | None = None) -> dict[str, Any]:
        """The keyword arguments of :func:`bearingload.bearings.resolve.resolve_bearings` (the
        designation first), ``stiffness`` the converted --stiffness [N/mm^m]."""
        return {
            "designation": self.bearing,
            "balls": self.balls,
            "ball_diameter": self.ball_diameter,
            "pitch_diameter": self.pitch_diameter,
            "f_i": self.inner_conformity,
            "f_o": self.outer_conformity,
            "modulus": self.modulus,
            "poisson": self.poisson,
            "ball_material": self.ball_material,
            "maker": self.maker,
            "stiffness": stiffness,
            "clearance": self.clearance,
            "clearance_pick": self.clearance_pick,
            "exponent": self.exponent,
            **{name: getattr(self, name) for name in MOUNTING_PARAMS},
        }

    def operating(self) -> Any:
        """The operating conditions of the lives
        (:class:`bearingload.bearings.service_life.Operating`; alpha in 1/Pa)."""
        from bearingload.bearings.service_life import Operating

        alpha = None if self.pressure_viscosity is None else self.pressure_viscosity * 1e-9
        viscosity, note = self.oil_viscosity()
        return Operating(
            speed=self.speed,
            reliability=self.reliability,
            viscosity=viscosity,
            viscosity_note=note,
            contamination=self.contamination,
            e_c=self.e_c,
            fatigue_load_limit=self.fatigue_load_limit,
            roughness=self.roughness,
            pressure_viscosity=alpha,
        )

    def oil_viscosity(self) -> tuple[float | None, str | None]:
        """The operating viscosity [mm^2/s] and a note saying how, by the one rule of the oil
        options and batch's columns (:func:`bearingload.bearings.oil.operating_viscosity`):
        --viscosity, or that of the oil (--oil or --viscosity-40, --viscosity-100 or
        --viscosity-index) at --temperature by ASTM D341."""
        from bearingload.bearings.oil import OilInputError, operating_viscosity

        oil = {n: getattr(self, n) for n in OIL_PARAMS}
        try:
            nu, note = operating_viscosity(self.viscosity, **oil)
        except OilInputError as exc:
            why = option_message(exc.why)
            names = " / ".join(f"'{option_name(p)}'" for p in exc.parameters)
            if exc.kind == "conflict":
                assert exc.other is not None
                first = option_name(exc.parameter)
                raise click.UsageError(f"{first} cannot be used with {option_name(exc.other)}: "
                                       f"{why}") from exc  # fmt: skip
            head = "Missing option" if exc.kind == "missing" else "Invalid value for"
            raise click.UsageError(f"{head} {names}: {why}") from exc
        except InputError as exc:
            raise usage_error(exc) from exc
        given = next((n for n in OIL_PARAMS if oil[n] is not None), None)
        if given is not None and self.speed is None:  # name the option typed, not --viscosity
            from bearingload.bearings.lubrication import speed_needed

            raise usage_error(speed_needed(given))
        return nu, None if note is None else option_message(note)

    def dynamics_arguments(self) -> dict[str, Any]:
        """The ball dynamics of :func:`bearingload.studies.combined_bearing.solve_combined_bearing`:
        the speed [rpm] (None: the static model, also under --quasi-static) and the ball density
        [kg/m^3] (None: steel)."""
        self.check_dynamics_flags()
        if self.rotating == "outer" and self.speed is not None and not self.quasi_static:
            raise click.UsageError(
                "Invalid value for '--rotating': the ball dynamics at --speed are coded for the "
                "inner ring turning (docs/speed.md); give --quasi-static for the static model "
                "with the outer ring's lives"
            )
        if self.stiffness is not None and self.speed is not None and not self.quasi_static:
            raise click.UsageError(
                "Invalid value for '--stiffness': the ball dynamics at --speed need each "
                "contact's Hertz stiffness from the ball geometry; leave out --stiffness, or "
                "give --quasi-static for the static model"
            )
        return {
            "speed": None if self.quasi_static else self.speed,
            "ball_density": self.ball_density,
        }

    def check_dynamics_flags(self) -> None:
        """Refuse --ball-density without the ball dynamics (no --speed, or --quasi-static) and
        --quasi-static without --speed."""
        if self.ball_density is not None and (self.speed is None or self.quasi_static):
            raise click.UsageError(
                "Invalid value for '--ball-density': it enters the ball dynamics at --speed, "
                "which --quasi-static or a missing --speed leave out"
            )
        if self.quasi_static and self.speed is None:
            raise click.UsageError("Invalid value for '--quasi-static': it needs --speed")

    def combined_arguments(self) -> dict[str, Any]:
        """The combined load as the keyword arguments of the combined studies
        (:func:`bearingload.studies.combined_bearing.solve_combined_bearing`,
        :func:`bearingload.studies.combined_sweep.combined_sweep`,
        :func:`bearingload.studies.life_clearance.life_against_clearance`): F_a 0 when not
        given, the inner ring rotating by default, the lever as given (None: groove)."""
        return {
            "axial_load": self.axial_load or 0.0,
            "moment": self.moment,
            "moment_cross": self.moment_cross,
            "misalignment": self.misalignment,
            "tilt_radius": self.tilt_radius,
            "rotating": self.rotating or "inner",
            "dynamic_rating": self.dynamic_rating,
        }

    def as_pair(self) -> CaseOptions | None:
        """The case of a bearing pair (a designation's suffix, ``7205BDB``, read as the
        arrangement and taken off the designation), or None for one bearing; a preload or a
        width without a pair is refused."""
        import dataclasses

        from bearingload.bearings.angular import split_pair

        case = self
        if self.bearing is not None:
            single, kind, cls = split_pair(self.bearing)
            if kind is not None:
                if self.arrangement is not None and self.arrangement.upper() != kind:
                    raise click.UsageError(
                        f"Invalid value for '--arrangement': {self.arrangement} contradicts the "
                        f"designation {self.bearing.strip()!r} (a {kind} pair)"
                    )
                if cls is not None and self.preload not in (None, cls):
                    raise click.UsageError(
                        f"Invalid value for '--preload': {self.preload} contradicts the "
                        f"designation {self.bearing.strip()!r} (preload class {cls})"
                    )
                preload = cls or self.preload
                case = dataclasses.replace(self, bearing=single, arrangement=kind, preload=preload)
        if case.arrangement is None:
            for name in ("preload", "width"):
                if getattr(case, name) is not None:
                    raise click.UsageError(
                        f"Invalid value for '--{name}': it belongs to a bearing pair; give "
                        "--arrangement DB, DF or DT (or a designation with the suffix, "
                        "7205BDB); a single bearing is preloaded against another one"
                    )
            return None
        return case

    def pair_arguments(self, balls: int) -> dict[str, Any]:
        """The pair as the keyword arguments of
        :func:`bearingload.studies.bearing_pair.solve_bearing_pair` (``balls``: z, for the cage
        angle 'half'): the arrangement upper-cased, no preload 0."""
        return {
            "arrangement": (self.arrangement or "").upper(),
            "preload": self.preload or 0.0,
            "width": self.width,
            "cage_angle": self.cage_angle_deg(balls),
            "moment": self.moment,
            "moment_cross": self.moment_cross,
            "tilt_radius": self.tilt_radius,
            "rotating": self.rotating or "inner",
            "dynamic_rating": self.dynamic_rating,
        }


#: The parameters of :class:`CaseOptions` that come from the command line.
CASE_FIELDS = tuple(f.name for f in fields(CaseOptions) if f.name != "given")
