"""The case options of ``solve``, ``sweep`` and ``table``: declared once, read once.

:func:`case_options` declares every option that describes the case (the bearing, its balls, the
load, stiffness, clearance, geometry, material, cage angle, exponent and the combined load), each
with its one help text; a command lists the few it does not take (``omit``). Click's values are
converted once into the plan's :class:`~bearingload.plan.case.Case`, which the command receives
as its ``case`` argument. Every option answers for the library's names of its parameter
(:class:`bearingload.cli.options.LibraryOption`), so a library error names the option the user
typed.

Imports nothing heavy: the command line reads it at start-up.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Collection, Mapping
from typing import Any

import click

from bearingload.cli.options import (
    BARE,
    TYPED,
    CageAngle,
    Exponent,
    LibraryArgument,
    LibraryOption,
    PreloadValue,
    Quantity,
    note_typed,
    units_help,
    usage_error,
)
from bearingload.constants import CONTAMINATION_LEVELS
from bearingload.errors import InputError
from bearingload.plan.case import AT_REST, CASE_FIELDS, Case
from bearingload.plan.inputs import LIBRARY_NAMES
from bearingload.units import plausible_ranges_help

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
            spec = parse_clearance(value)
        except InputError as exc:
            self.fail(exc.message, param, ctx)
        note_typed(value, param, ctx)  # (a class: a failure names its length in mm)
        return spec


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
        help="Number of balls z (1 to 100000; a sweep: 3 or more): required for a ring given "
        "by hand, else it replaces the designation's.",
    ),
    "load": _option(
        "--load",
        "-F",
        type=Quantity("force"),
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
    "clearance": _option("--clearance", "-G", type=Clearance(), help=CLEARANCE_HELP),
    "clearance_pick": _option(
        "--clearance-pick",
        type=click.Choice(["min", "mean", "max", "range"]),
        default="mean",
        show_default=True,
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
        help="Ball diameter D_w, replacing the catalogue's. Bare number: mm.",
    ),
    "pitch_diameter": _option(
        "--pitch-diameter",
        type=Quantity("length"),
        help="Pitch diameter d_m; default the catalogue's, else (d + D)/2. Bare number: mm.",
    ),
    "inner_conformity": _option(
        "--inner-conformity",
        type=float,
        help="Inner groove conformity f_i = r_i/D_w, in (0.5, 1); default the catalogue's "
        "(0.52 when unknown).",
    ),
    "outer_conformity": _option(
        "--outer-conformity",
        type=float,
        help="Outer groove conformity f_o = r_o/D_w; default the catalogue's (0.53 when unknown).",
    ),
    "modulus": _option(
        "--modulus",
        type=Quantity("modulus"),
        help="Young's modulus E of the rings (and of the balls unless --ball-material); default "
        "208000 MPa (bearing steel). "
        f"Units: {units_help('modulus')} (bare number: MPa; "
        f"{plausible_ranges_help('modulus')}: 210 -> did you mean 210GPa?).",
    ),
    "poisson": _option(
        "--poisson",
        type=float,
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
        help="Contamination factor e_C (0 to 1) instead of --contamination.",
    ),
    "fatigue_load_limit": _option(
        "--fatigue-load-limit",
        type=Quantity("force", positive=True),
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
        "the table of 79xx, 70xx and 72xx at 15° and 25°, printed with its source), also as "
        "the designation's suffix (7205CDBL). E.g. --preload 300N, --preload M.",
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
    """Declare the case options on a command and hand it one plan
    :class:`~bearingload.plan.case.Case` as ``case``.

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
                case = read_case(values)
            except InputError as exc:
                raise usage_error(exc) from exc
            return func(case=case, **kwargs)

        for name, (decls, attrs) in reversed(declared.items()):
            if name in (defaults or {}):
                attrs = attrs | {"default": (defaults or {})[name], "show_default": True}
            if name in hidden:
                attrs = attrs | {"hidden": True}
            attrs = attrs | {"library": LIBRARY_NAMES.get(name, ())}
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


def read_case(values: dict[str, Any]) -> Case:
    """The case of click's converted ``values`` (parameter name -> value; an omitted option
    None), with the options given on the command line (not left at a default) and those typed
    as a bare number or with a unit (its text)."""
    ctx = click.get_current_context(silent=True)
    default = (None, click.core.ParameterSource.DEFAULT)
    given = frozenset(
        name for name in values if ctx is not None and ctx.get_parameter_source(name) not in default
    )
    bare = frozenset(ctx.meta.get(BARE, ())) if ctx is not None else frozenset()
    typed = dict(ctx.meta.get(TYPED, {})) if ctx is not None else {}
    return Case.of(values, given=given, bare=bare, typed=typed)
