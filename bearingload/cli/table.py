"""``bearingload table``: the classical design tables, regenerated exactly; and `table life`, a
bearing's ISO/TS 16281 life against its clearance."""

from __future__ import annotations

from typing import Any

import click

from bearingload.cli.bearing_options import (
    CLEARANCE_HELP,
    Clearance,
    ClearanceList,
    geometry_options,
)
from bearingload.cli.combined_options import combined_options, refuse_combined
from bearingload.cli.options import (
    CONTEXT,
    Quantity,
    cage_angle_option,
    emit,
    exponent_option,
    library_errors,
    maker_option,
    method_option,
    output_options,
    stiffness_value,
    units_help,
)
from bearingload.errors import InputError

TABLES = ("k", "kq", "life")
#: Why table k and kq refuse the combined-load options.
RADIAL_ONLY = (
    "table k and kq are the papers' radial, dimensionless design tables (k = Q_max/F_r over "
    "z; no axial load, no tilt, no life); for a combined load or the life use 'table life', "
    "'solve' or 'sweep'"
)


@click.command(context_settings=CONTEXT)
@click.argument("name", type=click.Choice(TABLES))
@click.option(
    "--z-max",
    type=click.IntRange(1, 1000),
    default=30,
    show_default=True,
    help="Largest z (k, kq).",
)
@click.option(
    "--load",
    "-F",
    type=Quantity("force"),
    default="1000",
    show_default=True,
    help="Radial load F_r (k, kq: matters only with clearance; life: required, >= 0 with an "
    f"axial load or a moment). Units: {units_help('force')} (bare number: N).",
)
@click.option(
    "--bearing",
    "-b",
    help="Catalogue designation (306, 6306): K is the exact Hertz stiffness of its ball and "
    "raceways, a clearance class is resolved by its bore.",
)
@click.option(
    "--stiffness",
    "-K",
    type=Quantity("stiffness"),
    help="Ball stiffness K (matters only with clearance); default 1e5 N/mm^1.5, or the Hertz "
    "value of --bearing. Bare number: N/mm^1.5.",
)
@click.option("--clearance", "-G", type=Clearance(), help=CLEARANCE_HELP + " Default: 0.")
@click.option(
    "--clearance-pick",
    type=click.Choice(["min", "mean", "max"]),
    default="mean",
    show_default=True,
    help="Where in a clearance class to take G_r.",
)
@click.option(
    "--balls",
    "-z",
    type=int,
    help="life: number of balls z of a ball set given by hand (with --ball-diameter, "
    "--pitch-diameter and --dynamic-rating), or an override of --bearing's.",
)
@click.option(
    "--clearances",
    type=ClearanceList(),
    help="life: the rows' clearances G_r, comma-separated lengths (bare number: mm; negative = "
    "preload), e.g. '-10um,0,10um,30um'. Default: -20 to 80 µm at a 25 mm bore, scaled by the "
    "bore's ISO 5753-1 C5 maximum.",
)
@geometry_options
@combined_options
@cage_angle_option
@exponent_option
@method_option(
    "The model the table is computed with (see 'bearingload solve --help'); all: one table "
    "comparing every method with its error against the exact answer."
)
@maker_option
@output_options
@library_errors
def table(
    name: str,
    z_max: int,
    load: float,
    bearing: str | None,
    stiffness: str | None,
    clearance: Any,
    clearance_pick: str,
    ball_diameter: float | None,
    pitch_diameter: float | None,
    inner_conformity: float | None,
    outer_conformity: float | None,
    modulus: float | None,
    poisson: float | None,
    cage_angle: Any,
    exponent: float,
    method: str,
    maker: str | None,
    fmt: str,
    output: str | None,
    balls: int | None,
    clearances: list[float] | None,
    **combined: Any,
) -> None:
    """Print a design table for z = 1..z-max balls, or a bearing's life against its clearance.

    \b
    NAME  k     Table 1 of Kuzmenko (2010): k = Q_max/F_r and loaded balls n
          kq    Table 2.2 of Kuzmenko & Sabadash (2014): K_Q = k z/2
          life  reference rating life L10r (ISO/TS 16281) against the radial clearance

    k, kq: by default the paper's conditions: zero clearance, a ball under the load. With
    --clearance the answer depends on load and stiffness, so give those too. They are radial
    tables: the combined-load options (--axial-load ...) belong to 'table life', 'solve' and
    'sweep'.

    life: one deep-groove ball bearing (--bearing, or --balls, --ball-diameter,
    --pitch-diameter and --dynamic-rating) under --load and optionally --axial-load, --moment or
    --misalignment, the ring named by --rotating turning (default inner): per clearance G_r
    (--clearances, default from preload to large play scaled to the bearing) the free contact
    angle, loaded balls, Q_max, L10r and L10r relative to G_r = 0, and ISO 281's (C_r/P)^3
    beside it, which does not see the clearance (Oswald, Zaretsky & Poplawski, NASA
    TM-2012-217115: which clearance lives longest).

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
      # a hand-given ball set with its C_r, outer ring rotating, 2 mrad misalignment, csv
      bearingload table life -z 7 --ball-diameter 11.5 --pitch-diameter 43.5 -C 23.4kN -F 1kN --rotating outer --misalignment 2mrad --format csv
    """
    from bearingload.reports.render import render
    from bearingload.reports.tables import design_table

    k_given = stiffness_value(stiffness, exponent, bearing)  # N/mm^m
    geometry: dict[str, Any] = dict(ball_diameter=ball_diameter, pitch_diameter=pitch_diameter,
                    f_i=inner_conformity, f_o=outer_conformity, modulus=modulus, poisson=poisson)  # fmt: skip
    if name == "life":
        refused = {
            "--z-max": (_given("z_max"), "it is one bearing, not a table over z"),
            "--method": (_given("method"), "the life comes from the exact 3-D model only"),
            "--clearance": (clearance is not None, "its rows are clearances (--clearances)"),
        }
        for option, (given, why) in refused.items():
            if given:
                raise click.UsageError(f"{option} cannot be used with table life: {why}")
        if not _given("load"):
            raise click.UsageError("Missing option '--load' / '-F': table life needs F_r (N)")
        geometry |= {"balls": balls, "maker": maker}
        _life(bearing, load, k_given, clearance_pick, exponent, geometry, clearances,
              cage_angle, combined, fmt, output)  # fmt: skip
        return
    refuse_combined(combined, f"table {name}", RADIAL_ONLY)
    for option, value in (("--balls", balls), ("--clearances", clearances)):
        if value is not None:
            raise click.UsageError(
                f"{option} cannot be used with table {name}: it is an option of table life "
                "(table k and kq run over z = 1..--z-max at one clearance)"
            )
    if bearing is not None:
        cond = _bearing_conditions(bearing, load, k_given, clearance, clearance_pick, cage_angle,
                                   exponent, dict(geometry, maker=maker))  # fmt: skip
    elif any(v is not None for v in geometry.values()):
        raise click.UsageError(
            "the geometry and material options (--ball-diameter ... --poisson) need --bearing"
        )
    else:
        from bearingload.bearings.clearance import clearance_length
        from bearingload.cli.cases import refuse_unused
        from bearingload.studies.tables import Conditions

        refuse_unused({}, "--bearing (a class is a catalogue bearing's); without one")
        k = 1e5 if k_given is None else k_given
        cond = Conditions(load, k, clearance_length(clearance), cage_angle, exponent)
    emit(render([design_table(name, z_max, cond, method)], fmt), output)


def _bearing_conditions(
    bearing: str,
    load: float,
    k_given: float | None,
    clearance: Any,
    clearance_pick: str,
    cage_angle: Any,
    exponent: float,
    geometry: dict[str, Any],
) -> Any:
    """The conditions of a catalogue bearing's ball and raceways (Hertz K, its clearance)."""
    from bearingload.bearings.resolve import resolve_bearing
    from bearingload.studies.tables import for_bearing

    if exponent != 1.5:
        raise click.UsageError(
            "Invalid value for '--exponent': a ball bearing (Hertz point contact) has m = 1.5"
        )
    resolved = resolve_bearing(
        bearing,
        stiffness=k_given,
        clearance=clearance if clearance is not None else 0.0,
        clearance_pick=clearance_pick,
        **geometry,
    )
    if resolved.kind != "ball":
        raise click.UsageError(
            "Invalid value for '--bearing': the tables take ball bearings; for a roller "
            "bearing use 'bearingload solve' or --exponent 10/9 with --stiffness"
        )
    return for_bearing(resolved, load, cage_angle)


def _given(param: str) -> bool:
    """True when the option of ``param`` was given, not left at its default."""
    source = click.get_current_context().get_parameter_source(param)
    return source is not None and source.name != "DEFAULT"


def _life(
    bearing: str | None,
    load: float,
    k_given: float | None,
    clearance_pick: str,
    exponent: float,
    geometry: dict[str, Any],
    clearances: list[float] | None,
    cage_angle: Any,
    combined: dict[str, Any],
    fmt: str,
    output: str | None,
) -> None:
    """``table life``: resolve the bearing as solve does, solve every clearance, emit."""
    from bearingload.cli.cases import resolve_bearings
    from bearingload.cli.combined_options import combined_inputs
    from bearingload.cli.options import cage_angle_deg, print_warnings
    from bearingload.reports.life_clearance import life_report
    from bearingload.studies.life_clearance import life_against_clearance

    if bearing is None and geometry["ball_diameter"] is None:
        raise click.UsageError(
            "table life needs a bearing: --bearing, or --balls, --ball-diameter, "
            "--pitch-diameter and --dynamic-rating"
        )
    b = resolve_bearings(bearing, k_given, None, clearance_pick, exponent, **geometry)[0]
    try:
        result = life_against_clearance(
            b,
            load,
            clearances=clearances,
            cage_angle=cage_angle_deg(cage_angle, b.balls),
            **combined_inputs(combined),
        )
    except InputError as exc:
        if exc.parameter != "clearance":
            raise
        message = str(exc).split(": ", 1)[-1]
        raise click.UsageError(f"Invalid value for '--clearances': {message}") from exc
    text = life_report(result, fmt)
    print_warnings(list(result.warnings), False)
    emit(text, output)
