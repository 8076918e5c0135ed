"""``bearingload table``: the classical design tables, regenerated exactly; and `table life`, a
bearing's ISO/TS 16281 life against its clearance."""

from __future__ import annotations

from typing import Any

import click

from bearingload.cli.case_options import Clearance, case_options
from bearingload.cli.options import (
    CONTEXT,
    emit,
    library_errors,
    method_option,
    option_message,
    output_options,
)
from bearingload.plan.case import Case
from bearingload.plan.table import TABLES


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
    from bearingload.plan.table import table_case

    tabled = table_case(
        name,
        case,
        z_max=z_max if _given("z_max") else None,
        method=method if _given("method") else None,
        clearances=clearances,
        preloads=preloads,
        spell=option_message,
    )
    emit(_report(name, tabled, fmt, case.speed, z_max, method), output)


def _given(param: str) -> bool:
    """True when the option of ``param`` was given, not left at its default."""
    source = click.get_current_context().get_parameter_source(param)
    return source is not None and source.name != "DEFAULT"


def _report(name: str, tabled: Any, fmt: str, speed: float | None, z_max: int, method: str) -> str:
    """The text of a planned table; the warnings of a table life printed on stderr."""
    from bearingload.cli.options import print_warnings

    if tabled.kind == "design":
        from bearingload.reports.render import render
        from bearingload.reports.tables import design_table

        return render([design_table(name, z_max, tabled.result, method)], fmt)
    if tabled.kind == "pair":
        from bearingload.reports.pair_life import preload_life_report

        text = preload_life_report(tabled.result, fmt, tabled.service, speed)
        print_warnings(list(tabled.result.warnings), False)
        return text
    from bearingload.reports.life_clearance import life_report
    from bearingload.reports.solve import printed_warnings

    text = life_report(tabled.result, fmt, tabled.service)
    print_warnings(printed_warnings(tabled.result.warnings, tabled.service), False)
    return text
