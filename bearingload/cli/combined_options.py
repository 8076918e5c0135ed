"""The combined-load options of ``bearingload solve`` and the path that serves them.

``--axial-load``, ``--moment``, ``--misalignment``, ``--dynamic-rating``, ``--rotating``: with
any of them given, ``solve`` runs the 3-D ring equilibrium of a deep-groove ball bearing
(:func:`bearingload.models.combined.solve_combined`) instead of the radial engine, and reports
the ISO/TS 16281 reference rating life beside ISO 281's basic life.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import click

from bearingload.cli.options import Quantity, units_help

#: The parameters of the combined path, as the command receives them.
COMBINED_PARAMS = ("axial_load", "moment", "misalignment", "dynamic_rating", "rotating")


def combined_options(func: Callable[..., Any]) -> Callable[..., Any]:
    """Add the five combined-load options to a command."""
    options = [
        click.option(
            "--axial-load",
            "-A",
            type=Quantity("force"),
            help="Axial load F_a on the inner ring (deep-groove ball bearings; needs the ball "
            f"geometry). Units: {units_help('force')} (bare number: N).",
        ),
        click.option(
            "--moment",
            type=Quantity("moment"),
            help="Moment tilting the inner ring in the plane of the radial load; default: the "
            f"ring is free to tilt (M = 0). Units: {units_help('moment')} (bare number: N mm).",
        ),
        click.option(
            "--misalignment",
            type=Quantity("angle"),
            help="Imposed tilt of the inner ring in the plane of the radial load, instead of "
            f"a moment. Units: {units_help('angle')} (bare number: degrees).",
        ),
        click.option(
            "--dynamic-rating",
            "-C",
            type=Quantity("force", positive=True),
            help="Basic dynamic load rating C_r for the lives, replacing the catalogue's (needed "
            "for a bearing given by hand). Units: N, kN, kgf (bare number: N).",
        ),
        click.option(
            "--rotating",
            type=click.Choice(["inner", "outer"]),
            help="The ring that rotates relative to the load, for the reference rating life "
            "(default inner).",
        ),
    ]
    for option in reversed(options):
        func = option(func)
    return func


def wants_combined(values: dict[str, Any]) -> bool:
    """True when any combined-load option was given."""
    return any(values.get(k) is not None for k in COMBINED_PARAMS)


def combined_inputs(values: dict[str, Any]) -> dict[str, Any]:
    """The combined-load options as the keyword arguments of the library (F_a 0 when not given,
    the inner ring rotating by default): the one conversion ``solve``, ``sweep`` and ``table``
    share."""
    return {
        "axial_load": values.get("axial_load") or 0.0,
        "moment": values.get("moment"),
        "misalignment": values.get("misalignment"),
        "rotating": values.get("rotating") or "inner",
        "dynamic_rating": values.get("dynamic_rating"),
    }


def refuse_combined(values: dict[str, Any], where: str, why: str) -> None:
    """One usage error naming the first combined-load option given, ``where`` it was given and
    ``why`` it is refused there."""
    given = [k for k in COMBINED_PARAMS if values.get(k) is not None]
    if given:
        option = "--" + given[0].replace("_", "-")
        raise click.UsageError(f"{option} cannot be used with {where}: {why}")


def combined_text(
    bearings: list[Any],
    load: float,
    cage_angle: Any,
    values: dict[str, Any],
    fmt: str,
    per_ball: bool = False,
    show_geometry: bool = False,
) -> tuple[str, list[str]]:
    """Solve the resolved ``bearings`` (one per clearance) under the combined load: the report
    and the warnings of every case."""
    from bearingload.cli.options import cage_angle_deg
    from bearingload.reports.combined import combined_report
    from bearingload.studies.combined_bearing import solve_combined_bearing

    cases = solve_combined_bearing(
        bearings,
        load,
        cage_angle=cage_angle_deg(cage_angle, bearings[0].balls),
        **combined_inputs(values),
    )
    text = combined_report(cases, fmt, per_ball=per_ball, show_geometry=show_geometry)
    return text, list(dict.fromkeys(w for c in cases for w in c.warnings))
