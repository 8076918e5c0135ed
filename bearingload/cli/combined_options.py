"""The combined-load options of ``bearingload solve`` and the path that serves them.

``--axial-load``, ``--moment``, ``--misalignment`` (the LOAD options, :data:`LOAD_PARAMS`): with
any of them given, ``solve`` runs the 3-D ring equilibrium of a deep-groove ball bearing
(:func:`bearingload.models.combined.solve_combined`) instead of the radial engine.
``--dynamic-rating`` and ``--rotating`` (:data:`LIFE_PARAMS`) feed only the lives (ISO 281's L10,
ISO/TS 16281's L10r): they never choose the engine, so they never change a ball load.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import click

from bearingload.cli.options import Quantity, units_help

#: The load options: any of them given, ``solve`` solves the combined load.
LOAD_PARAMS = ("axial_load", "moment", "misalignment")
#: The options that feed only the lives.
LIFE_PARAMS = ("dynamic_rating", "rotating")
#: The parameters of the combined path, as the command receives them.
COMBINED_PARAMS = LOAD_PARAMS + LIFE_PARAMS


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
            help="Basic dynamic load rating C_r for the lives L10 and L10r, replacing the "
            "catalogue's (needed for a bearing given by hand); changes no load. Units: N, kN, "
            "kgf (bare number: N).",
        ),
        click.option(
            "--rotating",
            type=click.Choice(["inner", "outer"]),
            help="The ring that rotates relative to the load, for the reference rating life "
            "L10r (default inner); changes no load.",
        ),
    ]
    for option in reversed(options):
        func = option(func)
    return func


def wants_combined(values: dict[str, Any]) -> bool:
    """True when a load option (:data:`LOAD_PARAMS`: axial load, moment, misalignment) was
    given: the load alone chooses the engine."""
    return any(values.get(k) is not None for k in LOAD_PARAMS)


def lives_given(values: dict[str, Any]) -> bool:
    """True when an option that feeds only the lives (:data:`LIFE_PARAMS`) was given."""
    return any(values.get(k) is not None for k in LIFE_PARAMS)


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


def combined_cases(
    bearings: list[Any], load: float, cage_angle: Any, values: dict[str, Any]
) -> list[Any]:
    """Solve the resolved ``bearings`` (one per clearance) under the combined load: one
    :class:`bearingload.studies.combined_bearing.CombinedCase` each."""
    from bearingload.cli.options import cage_angle_deg
    from bearingload.studies.combined_bearing import solve_combined_bearing

    return solve_combined_bearing(
        bearings,
        load,
        cage_angle=cage_angle_deg(cage_angle, bearings[0].balls),
        **combined_inputs(values),
    )
