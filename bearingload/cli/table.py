"""``bearingload table``: the classical design tables, regenerated exactly; and `table life`, a
bearing's ISO/TS 16281 life against its clearance."""

from __future__ import annotations

from typing import Any

import click

from bearingload.bearings.mounting import MOUNTING_PARAMS
from bearingload.cli.case_options import Clearance, case_options
from bearingload.cli.options import (
    CONTEXT,
    emit,
    library_errors,
    method_option,
    option_message,
    output_options,
)
from bearingload.plan.bearing import refuse_range
from bearingload.plan.case import COMBINED_PARAMS, DYNAMICS_PARAMS, MOUNTING_REFUSAL, Case

TABLES = ("k", "kq", "life")
#: Why table k and kq refuse the options of the ball dynamics.
DYNAMICS_REFUSAL = (
    "table k and kq are the papers' static design tables (no speed); the ball dynamics at "
    "--speed are solved by 'table life', 'solve' and 'sweep' (docs/speed.md)"
)
#: Why table k and kq refuse the combined-load options.
RADIAL_ONLY = (
    "table k and kq are the papers' radial, dimensionless design tables (k = Q_max/F_r over "
    "z; no axial load, no tilt, no life); for a combined load or the life use 'table life', "
    "'solve' or 'sweep'"
)


class ClearanceList(click.ParamType):
    """Comma-separated clearance lengths (bare number: mm), each read as ``--clearance`` reads a
    length."""

    name = "G1,G2,..."

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        from bearingload.bearings.clearance import clearance_length

        if isinstance(value, list):
            return value
        out = []
        for item in str(value).split(","):
            spec = Clearance().convert(item.strip(), param, ctx)
            if spec is None or getattr(spec, "length", None) is None:
                self.fail(f"{item.strip()!r} is not a length (classes are not rows)", param, ctx)
            out.append(clearance_length(spec))
        return out


class ForceList(click.ParamType):
    """Comma-separated forces (bare number: N), each read as ``--preload`` reads a force."""

    name = "F1,F2,..."

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        from bearingload.cli.options import Quantity

        if isinstance(value, list):
            return value
        return [
            Quantity("force").convert(item.strip(), param, ctx) for item in str(value).split(",")
        ]


@click.command(context_settings=CONTEXT)
@click.argument("name", type=click.Choice(TABLES))
@case_options(
    bearing="option",
    defaults={"load": "1000"},
    hidden=["preload"],  # a pair's table life runs over --preloads
    pair=True,
)
@click.option(
    "--z-max",
    type=click.IntRange(1, 1000),
    default=30,
    show_default=True,
    help="Largest z (k, kq).",
)
@click.option(
    "--clearances",
    type=ClearanceList(),
    help="life: the rows' clearances G_r, comma-separated lengths (bare number: mm; negative = "
    "preload), e.g. '-10um,0,10um,30um'. Default: -20 to 80 µm at a 25 mm bore, scaled by the "
    "bore's ISO 5753-1 C5 maximum.",
)
@click.option(
    "--preloads",
    type=ForceList(),
    help="life of a bearing pair (--bearing 7205BDB, or --arrangement DB|DF): the rows' "
    "preloads F_p, comma-separated forces (bare number: N), e.g. '0,100N,300N,1kN'.",
)
@method_option(
    "The model the table is computed with (see 'bearingload solve --help'); all: one table "
    "comparing every method with its error against the exact answer."
)
@output_options
@library_errors
def table(
    name: str,
    case: Case,
    z_max: int,
    clearances: list[float] | None,
    preloads: list[float] | None,
    method: str,
    fmt: str,
    output: str | None,
) -> None:
    """Print a design table for z = 1..z-max balls, or a bearing's life against its clearance.

    \b
    NAME  k     Table 1 of Kuzmenko (2010): k = Q_max/F_r and loaded balls n
          kq    Table 2.2 of Kuzmenko & Sabadash (2014): K_Q = k z/2
          life  reference rating life L10r (ISO/TS 16281) against the radial clearance
                (a pair of angular-contact bearings: against the preload)

    k, kq: by default the paper's conditions: zero clearance, a ball under the load. With
    --clearance the answer depends on load and stiffness, so give those too. They are radial
    tables: the combined-load options (--axial-load ...) belong to 'table life', 'solve' and
    'sweep'.

    life: one deep-groove ball bearing (--bearing, or --balls, --ball-diameter,
    --pitch-diameter and --dynamic-rating) under --load and optionally --axial-load, --moment,
    --moment-cross or --misalignment (--tilt-radius: the lever of the tilt), the ring named by --rotating turning (default inner): per clearance G_r
    (--clearances, default from preload to large play scaled to the bearing) the free contact
    angle, loaded balls, Q_max, L10r and L10r relative to G_r = 0, and ISO 281's (C_r/P)^3
    beside it, which does not see the clearance (Oswald, Zaretsky & Poplawski, NASA
    TM-2012-217115: which clearance lives longest).
    With --speed, --viscosity and the other life options of 'solve' (docs/life.md) each row
    also gives L10rh, P_ref, a_ISO, L_nmr and the film; what is the same in every row (kappa,
    e_C, C_u, L_nm) is among the conditions. At --speed every row is solved as 'solve
    --clearance G_r --speed' solves it: with each ball's centrifugal force and gyroscopic
    moment (--ball-density; docs/speed.md), or with --quasi-static by the static model.

    life of a pair of angular-contact bearings (--bearing 7205BDB, or 7205B with --arrangement
    DB or DF; docs/angular_contact.md): per preload F_p (--preloads) each bearing's Q_max and
    loaded balls, the pair's axial and radial stiffness, lift-off load, L10r and L10, as 'solve
    7205BDB --preload F_p' gives them; at --speed with the ball dynamics of both bearings and
    L10r also in hours (--quasi-static: the static pair). A single angular-contact bearing has
    no table life: its contact angle fixes its geometry, so it has no radial clearance to run
    over.

    \b
    Examples:
      bearingload table k
      bearingload table kq --format csv -o kq.csv
      bearingload table k --clearance 20um --load 300kgf --stiffness 4700kgf/mm^1.5
      bearingload table k --cage-angle half --z-max 40
      # Table 1 for the ball and raceways of bearing 306 (exact Hertz K), 300 kgf, 20 µm
      bearingload table k --bearing 306 --load 300kgf --clearance 20um
      # exact, continuum, Stribeck and Palmgren side by side for z = 1-30
      bearingload table k --method all
      # L10r of a 6205 against clearance at 1.4 kN, then with 700 N axial
      bearingload table life --bearing 6205 --load 1.4kN
      bearingload table life -b 6205 -F 1.4kN --axial-load 700N --clearances -10um,0,10um,20um,40um
      # at 10000 rpm with the ball dynamics, ceramic balls (each row as solve --speed)
      bearingload table life -b 6205 -F 1kN --speed 10000 --ball-density 3200
      # a hand-given ball set with its C_r, outer ring rotating, 2 mrad misalignment, csv
      bearingload table life -z 7 --ball-diameter 11.5 --pitch-diameter 43.5 -C 23.4kN -F 1kN --rotating outer --misalignment 2mrad --format csv
      # a back-to-back pair of 7205B: L10r and stiffness against the preload
      bearingload table life -b 7205BDB -F 1kN -A 200N --preloads 0,100N,300N,1kN
    """
    from bearingload.reports.render import render
    from bearingload.reports.tables import design_table

    case.refuse(
        ("contact_angle",),
        f"table {name}",
        "a ring given by hand with its contact angle is solved by 'solve' only; an "
        "angular-contact designation (7205B) by 'solve', 'sweep' and 'batch' "
        "(docs/angular_contact.md)",
    )
    case.refuse(MOUNTING_PARAMS, f"table {name}", MOUNTING_REFUSAL)
    if name != "life":
        case.refuse(DYNAMICS_PARAMS, f"table {name}", DYNAMICS_REFUSAL)
    from bearingload.bearings.angular import parse_angular

    pair = case.as_pair()
    if pair is not None or preloads is not None:
        _pair_life(name, pair, preloads, clearances, fmt, output)
        return
    if case.bearing is not None and parse_angular(case.bearing) is not None:  # as --contact-angle
        raise click.UsageError(
            f"Invalid value for '--bearing': {case.bearing.strip()!r} is an angular-contact "
            f"bearing, solved by 'solve', 'sweep' and 'batch', not by 'table {name}'"
            + (
                ": its rows are radial clearances, and the contact angle fixes an "
                "angular-contact bearing's geometry (no clearance); for a pair, 'table life -b "
                f"{case.bearing.strip()}DB --preloads 0,100N,300N' gives L10r against the preload"
                if name == "life"
                else ""
            )
            + " (docs/angular_contact.md)"
        )
    k_given = case.stiffness_value()  # N/mm^m
    if name == "life":
        refused = {
            "--z-max": (_given("z_max"), "it is one bearing, not a table over z"),
            "--method": (_given("method"), "the life comes from the exact 3-D model only"),
            "--clearance": (case.clearance is not None, "its rows are clearances (--clearances)"),
            "--clearance-pick": (
                "clearance_pick" in case.given,
                "its rows are clearances (--clearances), no class to pick in",
            ),
        }
        for option, (given, why) in refused.items():
            if given:
                raise click.UsageError(f"{option} cannot be used with table life: {why}")
        if "load" not in case.given:
            raise click.UsageError("Missing option '--load' / '-F': table life needs F_r (N)")
        _life(case, clearances, fmt, output)
        return
    refuse_range(case, f"table {name}")  # table life refuses every pick (above)
    case.refuse(COMBINED_PARAMS, f"table {name}", RADIAL_ONLY)
    for option, value in (("--balls", case.balls), ("--clearances", clearances)):
        if value is not None:
            raise click.UsageError(
                f"{option} cannot be used with table {name}: it is an option of table life "
                "(table k and kq run over z = 1..--z-max at one clearance)"
            )
    if case.bearing is not None:
        cond = _bearing_conditions(case, k_given)
    elif not case.by_hand or any(getattr(case, n) is not None for n in _GEOMETRY):
        raise click.UsageError(
            "the geometry and material options (--ball-diameter ... --poisson) need --bearing"
        )
    else:
        from bearingload.bearings.clearance import clearance_length
        from bearingload.plan.bearing import refuse_unused
        from bearingload.studies.tables import Conditions

        refuse_unused(case, ("maker",), "--bearing (a class and a maker's ball set are a "
                      "catalogue bearing's); without one")  # fmt: skip
        k = 1e5 if k_given is None else k_given
        cond = Conditions(case.radial_load, k, clearance_length(case.clearance), case.cage_angle,
                          case.exponent_or(1.5))  # fmt: skip
    emit(render([design_table(name, z_max, cond, method)], fmt), output)


#: The ball geometry and material options, which only a catalogue bearing's table takes.
_GEOMETRY = ("inner_conformity", "outer_conformity", "modulus", "poisson", "ball_material")


def _bearing_conditions(case: Case, k_given: float | None) -> Any:
    """The conditions of a catalogue bearing's ball and raceways (Hertz K, its clearance)."""
    from bearingload.bearings.resolve import check_exponent
    from bearingload.plan.bearing import resolve_bearings
    from bearingload.studies.tables import for_bearing

    clearance = case.clearance if case.clearance is not None else 0.0
    resolved = resolve_bearings(case, k_given, clearance=clearance, exponent=None)[0]
    if resolved.kind != "ball":
        raise click.UsageError(
            "Invalid value for '--bearing': the tables take ball bearings; for a roller "
            "bearing use 'bearingload solve' or --exponent 10/9 with --stiffness"
        )
    check_exponent(resolved, case.exponent)
    return for_bearing(resolved, case.radial_load, case.cage_angle)


def _given(param: str) -> bool:
    """True when the option of ``param`` was given, not left at its default."""
    source = click.get_current_context().get_parameter_source(param)
    return source is not None and source.name != "DEFAULT"


def _life(
    case: Case,
    clearances: list[float] | None,
    fmt: str,
    output: str | None,
) -> None:
    """``table life``: resolve the bearing as solve does, solve every clearance, emit; a speed
    above the catalogue's limiting speed warns, as in solve."""
    from bearingload.cli.options import print_warnings
    from bearingload.reports.life_clearance import life_report
    from bearingload.reports.solve import printed_warnings

    if case.bearing is None and case.ball_diameter is None:
        raise click.UsageError(
            "table life needs a bearing: --bearing, or --balls, --ball-diameter, "
            "--pitch-diameter and --dynamic-rating"
        )
    from bearingload.plan.life_table import life_against_clearance_case

    result, service = life_against_clearance_case(case, clearances, option_message)
    text = life_report(result, fmt, service)
    print_warnings(printed_warnings(result.warnings, service), False)
    emit(text, output)


def _pair_life(
    name: str,
    case: Case | None,
    preloads: list[float] | None,
    clearances: list[float] | None,
    fmt: str,
    output: str | None,
) -> None:
    """``table life`` of a bearing pair: L10r against the preload (``--preloads``), emit."""
    from bearingload.cli.options import print_warnings
    from bearingload.plan.life_table import life_against_preload_case
    from bearingload.reports.pair_life import preload_life_report

    if case is None:
        raise click.UsageError(
            "--preloads cannot be used without a bearing pair: it gives the rows of table life "
            "of a pair (--bearing 7205BDB, or --arrangement DB or DF)"
        )
    if name != "life":
        raise click.UsageError(
            f"a bearing pair (--arrangement, or a designation such as 7205BDB) cannot be used "
            f"with table {name}: {RADIAL_ONLY}"
        )
    for option, given, why in (
        ("--preload", "preload" in case.given, "its rows are preloads (--preloads)"),
        (
            f"the designation's preload class {case.preload}",
            "preload" not in case.given and case.preload is not None,
            "its rows are preloads (--preloads); give the designation without the class",
        ),
        ("--clearances", clearances is not None, "a pair's rows are preloads (--preloads)"),
        ("--z-max", _given("z_max"), "it is one pair, not a table over z"),
        ("--method", _given("method"), "the life comes from the exact model only"),
    ):
        if given:
            raise click.UsageError(f"{option} cannot be used with table life of a pair: {why}")
    if preloads is None:
        raise click.UsageError(
            "Missing option '--preloads': table life of a pair runs over the preload; give the "
            "rows, e.g. --preloads 0,100N,300N,1kN"
        )
    if "load" not in case.given:
        raise click.UsageError("Missing option '--load' / '-F': table life needs F_r (N)")
    result = life_against_preload_case(case, preloads)
    text = preload_life_report(result, fmt, case.speed)
    print_warnings(list(result.warnings), False)
    emit(text, output)
