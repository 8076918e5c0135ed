"""Options shared by the commands that take a bearing: geometry overrides, material, clearance."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import click

from bearingload.cli.options import Quantity, units_help
from bearingload.errors import InputError

CLEARANCE_HELP = (
    "Radial internal clearance G_r, total play (gap per side G_r/2; negative = preload): a length "
    "(bare number: mm; units um, mm, in) or an ISO 5753-1 class C2, CN, C3, C4, C5, resolved by the "
    "bearing's bore (deep groove ball or cylindrical roller bearing table). GOST 24810 groups are written G6, G7, G8, G9. A bare number of 1 mm or more "
    "is refused as implausible (20 -> did you mean 20um?); write 1.5mm to mean it."
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
            self.fail(str(exc).split(": ", 1)[-1], param, ctx)


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


def geometry_options(func: Callable[..., Any]) -> Callable[..., Any]:
    """``--ball-diameter --pitch-diameter --inner-conformity --outer-conformity --modulus --poisson``."""
    options = [
        click.option(
            "--ball-diameter",
            type=Quantity("length"),
            help="Ball diameter D_w, replacing the catalogue's. Bare number: mm.",
        ),
        click.option(
            "--pitch-diameter",
            type=Quantity("length"),
            help="Pitch diameter d_m; default the catalogue's, else (d + D)/2. Bare number: mm.",
        ),
        click.option(
            "--inner-conformity",
            type=float,
            help="Inner groove conformity f_i = r_i/D_w, in (0.5, 1); default the catalogue's "
            "(0.52 when unknown).",
        ),
        click.option(
            "--outer-conformity",
            type=float,
            help="Outer groove conformity f_o = r_o/D_w; default the catalogue's (0.53 when "
            "unknown).",
        ),
        click.option(
            "--modulus",
            type=Quantity("modulus"),
            help="Young's modulus E of balls and rings; default 208000 MPa (bearing steel). "
            f"Units: {units_help('modulus')} (bare number: MPa; a bare number outside 1000 to "
            "1e7 MPa is refused: 210 -> did you mean 210GPa?).",
        ),
        click.option("--poisson", type=float, help="Poisson's ratio nu; default 0.3."),
    ]
    for option in reversed(options):
        func = option(func)
    return func
