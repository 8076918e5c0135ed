"""``bearingload sweep``: the ring equilibrium over one ball pitch of cage positions."""

from __future__ import annotations

import click

from bearingload.bearings.mounting import MOUNTING_PARAMS
from bearingload.cli.case_options import case_options
from bearingload.cli.options import (
    CONTEXT,
    LibraryOption,
    emit,
    library_errors,
    output_options,
    usage_error,
)
from bearingload.cli.plot import check_plot, save_plot
from bearingload.plan.bearing import refuse_range
from bearingload.plan.case import (
    COMBINED_PARAMS,
    LOAD_NEEDED,
    MOUNTING_REFUSAL,
    SERVICE_PARAMS,
    Case,
)
from bearingload.plan.sweep import Swept, sweep_case

#: The case options the dimensionless mode refuses (P = K = 1, the gap from T).
KUROCHKIN_REFUSES = ("bearing", "load", "stiffness", "clearance", "plot", "ball_diameter",
                     "pitch_diameter", "inner_conformity", "outer_conformity", "modulus",
                     "poisson", "ball_material", "maker", *COMBINED_PARAMS)  # fmt: skip

#: Why sweep refuses the operating conditions of the modified lives (:data:`SERVICE_PARAMS`
#: but --speed, which gives L10h and L10rh at every cage position).
SERVICE_REFUSAL = (
    "the sweep shows how the ring position, Q_max and L10r (in hours with --speed) ripple over "
    "one ball pitch; C_0, a_1, a_ISO, the modified lives and the film are those of the case: "
    "give the same options to 'bearingload solve' (or 'table life' against the clearance)"
)


@click.command(context_settings=CONTEXT)
@case_options(
    omit=("cage_angle",),
    hidden=[n for n in SERVICE_PARAMS if n != "speed"],
    pair=True,
)
@click.option(
    "--steps",
    "-n",
    type=int,
    default=37,
    show_default=True,
    help="Cage positions over one ball pitch, both ends included (2 to 1000000).",
)
@click.option(
    "--plot",
    type=click.Path(dir_okay=False),
    help="Also draw x, y, Q_max and stiffness over the cage angle into FILE; its extension "
    "gives the format (.png, .pdf, .svg ...). Needs matplotlib: pip install matplotlib.",
)
@click.option(
    "--kurochkin-T",
    "kurochkin_t",
    type=float,
    cls=LibraryOption,
    library=("T",),
    help="Kurochkin's dimensionless mode (1973): P = K = 1 and the gap from his parameter T, "
    "eq. (1.13); rows give F0 = x0 and F0' = -y0, the summary the contact sequence, exit angle "
    "and Fourier coefficients F0j'. Needs --balls (>= 5) only.",
)
@output_options
@library_errors
def sweep(
    case: Case,
    steps: int,
    plot: str | None,
    kurochkin_t: float | None,
    fmt: str,
    output: str | None,
) -> None:
    """Turn the cage one ball pitch: ring position, Q_max and stiffness at every cage angle.

    As the cage turns one pitch 360/z the load passes from a ball under the load (cage angle 0)
    to the load between two balls (180/z) and back: the inner ring moves along and across the
    load, the heaviest ball load and the stiffness ripple z times per cage revolution (the
    varying compliance that excites vibration; Kurochkin 1973). Every cage position is solved
    exactly, in one vectorised call. The summary gives min, mean, max and peak-to-peak over the
    pitch, and every compensating clearance: the G_r at which the ring sits at the same x with a
    ball under the load and with the load between two balls.

    The bearing and condition options are those of 'bearingload solve' (the cage angle is what
    turns). csv: one row per cage angle with the inputs as columns; json: rows, a summary and
    units.

    With --axial-load, --moment, --moment-cross or --misalignment (a deep-groove ball bearing: a
    catalogue designation, or --balls with --ball-diameter and --pitch-diameter) every cage
    position is solved by the 3-D ring equilibrium of 'solve' (ISO/TS 16281), all in one
    vectorised call: per position x, y, the axial displacement (from the centred rings, half the
    axial play included), the tilts about both axes (the ring is free to tilt unless a moment or
    a misalignment is given; --tilt-radius sets the lever), Q_max and its ball, the loaded balls,
    the largest contact angle and the reference rating life L10r of the rotating ring (default
    inner); beside them ISO 281's (C_r/P)^3, the same at every position. Not for roller bearings
    or --kurochkin-T. The life options alone (--dynamic-rating, --rotating) never change the
    engine: the radial sweep adds L10r at each position (ball bearings) and L10.

    With --speed a ball bearing is swept as 'solve --speed' solves it: every position with the
    ball dynamics (each ball's centrifugal force and gyroscopic moment, outer-raceway control;
    a radial load on the 3-D engine at F_a = 0; --ball-density for ceramic balls), the lives
    also in hours; a pair (7205BDB): both bearings' ball dynamics. --quasi-static keeps the
    static model (the speed then gives the hours only), as do roller bearings.

    \b
    Examples:
      # nine balls, 1 kN, K = 1e5 N/mm^1.5, G_r = 10 µm, 19 cage positions
      bearingload sweep -z 9 -F 1kN -K 1e5 -G 10um --steps 19
      # catalogue bearing 306 at 300 kgf, clearance class C3, a plot of the ripple
      bearingload sweep 306 --load 300kgf --clearance C3 --plot sweep306.png
      # one csv row per cage angle for a spreadsheet
      bearingload sweep -z 12 -F 5kN -K 3.8e5 -G -20um --format csv -o sweep.csv
      # Kurochkin's dimensionless statics: 7 balls, T = 0.567 (his Table 3)
      bearingload sweep --balls 7 --kurochkin-T 0.567 --steps 21
      # combined load on a 6205 (C3): F_r 1.4 kN, F_a 700 N, L10r at every cage position
      bearingload sweep 6205 -F 1.4kN --axial-load 700N -G C3 --steps 9
      # a hand-given ball set, C_r 23.4 kN, outer ring rotating, imposed 2 mrad tilt, as csv
      bearingload sweep -z 7 --ball-diameter 11.5 --pitch-diameter 43.5 -F 1kN -G 10um -C 23.4kN --rotating outer --misalignment 2mrad --format csv
      # a moment of 5 N m in the load plane, json for a script
      bearingload sweep 6205 -F 1kN -A 300N --moment 5Nm --format json
      # a moment of 2 N m about the load line, the tilt at the pitch radius as MASTA
      bearingload sweep 6205 -F 1kN -A 300N --moment-cross 2Nm --tilt-radius pitch --steps 9
      # a 6205 at 10000 rpm: the ball dynamics at every cage position, L10r also in hours
      bearingload sweep 6205 -F 1kN -A 300N --speed 10000 --steps 9
      # a back-to-back pair of 7205B, 300 N preload: the shaft, each bearing's Q_max, stiffness
      bearingload sweep 7205BDB --preload 300N -F 1kN -A 200N --steps 7
    """
    case.refuse(
        ("contact_angle",),
        "sweep",
        "a ring given by hand with its contact angle is solved by 'solve' only; sweep takes "
        "an angular-contact designation (7205B; docs/angular_contact.md)",
    )
    case.refuse([n for n in SERVICE_PARAMS if n != "speed"], "sweep", SERVICE_REFUSAL)
    case.refuse(MOUNTING_PARAMS, "sweep", MOUNTING_REFUSAL)
    if kurochkin_t is not None:
        _kurochkin(case, kurochkin_t, steps, plot, fmt, output)
        return
    if case.load is None:
        _missing_load(case)
    refuse_range(case, "sweep")
    if plot is not None and case.as_pair() is not None:
        raise click.UsageError(
            "Invalid value for '--plot': it draws one bearing's ripple, not a pair's; "
            "--format csv gives the pair at every cage position"
        )
    if plot is not None:
        check_plot(plot)
    swept = sweep_case(case, steps)
    _emit(swept, plot, fmt, output)


def _emit(swept: Swept, plot: str | None, fmt: str, output: str | None) -> None:
    """Render a solved sweep, print its warnings, draw its plot, write it."""
    from bearingload.cli.options import print_warnings

    result = swept.result
    if swept.engine == "pair":
        from bearingload.reports.pair_sweep import pair_sweep_report

        text = pair_sweep_report(result, fmt, swept.lives, swept.context)
    elif swept.engine == "combined":
        from bearingload.reports.combined_sweep import combined_sweep_report

        text = combined_sweep_report(result, fmt, swept.context)
    else:
        from bearingload.reports.sweep import sweep_report

        text = sweep_report(result, fmt, swept.context)
    print_warnings(list(result.warnings), False)
    if plot is not None:
        from bearingload.reports import plots

        draw = plots.combined_sweep_figure if swept.engine == "combined" else plots.sweep_figure
        save_plot(lambda: draw(result, swept.designation), plot)
    emit(text, output)


def _missing_load(case: Case) -> None:
    """Refuse a sweep without a load, saying what is missing; a ring given by its balls alone
    may mean Kurochkin's dimensionless mode, which takes no load."""
    from bearingload.errors import MissingError

    balls_only = case.given <= {"balls"}
    mode = "; or 'kurochkin_t' for Kurochkin's dimensionless mode" if balls_only else ""
    raise usage_error(MissingError("load", LOAD_NEEDED + mode))


def _kurochkin(
    case: Case, t: float, steps: int, plot: str | None, fmt: str, output: str | None
) -> None:
    """The dimensionless mode: refuse the options it does not use, then sweep and emit."""
    extra = [
        n for n in KUROCHKIN_REFUSES if (plot if n == "plot" else getattr(case, n)) is not None
    ]
    if extra:
        name = extra[0].replace("_", "-")
        option = "BEARING" if name == "bearing" else f"--{name}"
        raise click.UsageError(f"{option} cannot be used with --kurochkin-T (P = K = 1).")
    if case.balls is None:
        raise click.UsageError("--kurochkin-T needs --balls.")
    if case.exponent_or(1.5) != 1.5:
        raise click.UsageError("--kurochkin-T is for balls: --exponent must be 3/2.")
    from bearingload.papers.kurochkin import kurochkin_sweep
    from bearingload.reports.kurochkin import kurochkin_report

    emit(kurochkin_report(kurochkin_sweep(case.balls, t, steps), fmt), output)
