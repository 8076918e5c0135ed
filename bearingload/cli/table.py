"""``bearingload table``: the classical design tables, regenerated exactly."""

from __future__ import annotations

from typing import Any

import click

from .options import CONTEXT, CageAngle, Quantity, emit, library_errors, output_options

TABLES = ("k", "kq")


@click.command(context_settings=CONTEXT)
@click.argument("name", type=click.Choice(TABLES))
@click.option(
    "--z-max", type=click.IntRange(1, 1000), default=30, show_default=True, help="Largest z."
)
@click.option(
    "--load",
    "-F",
    type=Quantity("force"),
    default="1000",
    show_default=True,
    help="Radial load F_r (matters only with clearance). Bare number: N.",
)
@click.option(
    "--stiffness",
    "-K",
    type=Quantity("stiffness"),
    default="1e5",
    show_default=True,
    help="Ball stiffness K (matters only with clearance). Bare number: N/mm^1.5.",
)
@click.option(
    "--clearance",
    "-G",
    type=Quantity("length"),
    default="0",
    show_default=True,
    help="Radial internal clearance G_r, total play; negative = preload. Bare number: mm.",
)
@click.option(
    "--cage-angle",
    type=CageAngle(),
    default="0",
    show_default=True,
    help="Cage angle in degrees, or 'half' (the load between two balls).",
)
@click.option(
    "--exponent",
    "-m",
    type=float,
    default=1.5,
    show_default=True,
    help="Load-deflection exponent m: 1.5 balls, 1.1111 rollers.",
)
@output_options
@library_errors
def table(
    name: str,
    z_max: int,
    load: float,
    stiffness: float,
    clearance: float,
    cage_angle: Any,
    exponent: float,
    fmt: str,
    output: str | None,
) -> None:
    """Print a design table for z = 1..z-max balls.

    \b
    NAME  k   Table 1 of Kuzmenko (2010): k = Q_max/F_r and loaded balls n
          kq  Table 2.2 of Kuzmenko & Sabadash (2014): K_Q = k z/2

    By default the paper's conditions: zero clearance, a ball under the load. With --clearance the
    answer depends on load and stiffness, so give those too.

    \b
    Examples:
      bearingload table k
      bearingload table kq --format csv -o kq.csv
      bearingload table k --clearance 20um --load 300kgf --stiffness 4700kgf/mm^1.5
      bearingload table k --cage-angle half --z-max 40
    """
    from ..render import render
    from ..tables import Conditions, table_k, table_kq

    cond = Conditions(load, stiffness, clearance, cage_angle, exponent)
    builder = {"k": table_k, "kq": table_kq}[name]
    emit(render([builder(z_max, cond)], fmt), output)
