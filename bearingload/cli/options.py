"""Shared pieces of the command line: quantity types, output options, error handling."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import click

from bearingload.errors import BearingloadError, InputError
from bearingload.units import BASE_UNIT, UNITS, parse_cage_angle, parse_quantity

CONTEXT = {"help_option_names": ["-h", "--help"], "max_content_width": 100}


class Quantity(click.ParamType):
    """A number with an optional unit suffix, converted to the package's internal unit."""

    def __init__(self, kind: str, *, positive: bool = False) -> None:
        self.kind = kind
        self.positive = positive
        self.name = f"{kind} [{BASE_UNIT[kind]}]"

    def convert(
        self, value: Any, param: click.Parameter | None, ctx: click.Context | None
    ) -> float | str:
        if isinstance(value, float):
            return value
        try:
            number = parse_quantity(value, self.kind, parameter=param.name if param else None)
        except InputError as exc:
            self.fail(str(exc).split(": ", 1)[-1], param, ctx)
        if self.kind == "stiffness":
            return str(value)  # converted with the exponent by the command (stiffness_value)
        if self.positive and not number > 0:
            self.fail(f"must be greater than 0 {BASE_UNIT[self.kind]} (got {value})", param, ctx)
        return number

    def get_metavar(self, param: click.Parameter, ctx: click.Context | None = None) -> str:
        return f"{self.kind.upper()} [{BASE_UNIT[self.kind]}]"


class CageAngle(click.ParamType):
    """Cage angle: degrees by default, ``deg``, ``rad``, ``mrad``, or ``half`` for half a pitch
    (the load between two balls); read by :func:`bearingload.units.parse_cage_angle`, as
    ``batch`` reads its ``cage_angle`` column."""

    name = "DEG|half"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if value == "half" or isinstance(value, float):
            return value
        try:
            return parse_cage_angle(value)
        except InputError as exc:
            self.fail(str(exc).split(": ", 1)[-1], param, ctx)


def stiffness_value(text: str | None, exponent: float, bearing: str | None = None) -> float | None:
    """The --stiffness text in N/mm^m, its unit checked against the exponent m: the --exponent
    given, else that of the BEARING's contact (10/9 for a cylindrical roller bearing)."""
    if text is None:
        return None
    exponent = _contact_exponent(bearing, exponent)
    from bearingload.units import parse_stiffness
    from bearingload.validate import exponent as valid_exponent

    try:
        valid_exponent(exponent)  # the exponent's own error comes first
    except InputError as exc:
        raise click.UsageError(
            f"Invalid value for '--exponent': {str(exc).split(': ', 1)[-1]}"
        ) from exc
    try:
        return parse_stiffness(text, exponent)
    except InputError as exc:
        raise click.UsageError(
            f"Invalid value for '--stiffness': {str(exc).split(': ', 1)[-1]}"
        ) from exc


def exponent_given() -> bool:
    """Whether the command line gave --exponent (not its default 1.5)."""
    ctx = click.get_current_context(silent=True)
    source = ctx.get_parameter_source("exponent") if ctx is not None else None
    return source not in (None, click.core.ParameterSource.DEFAULT)


def _contact_exponent(bearing: str | None, exponent: float) -> float:
    """``exponent`` if --exponent was given or no roller bearing is named, else 10/9."""
    if exponent_given():
        return exponent
    from bearingload.bearings.designation import contact_exponent

    return contact_exponent(bearing, exponent)


def units_help(kind: str) -> str:
    return ", ".join(UNITS[kind])


def output_options(func: Callable[..., Any]) -> Callable[..., Any]:
    """``--format`` and ``-o/--output``, shared by every command that prints results."""
    func = click.option(
        "-o",
        "--output",
        type=click.Path(dir_okay=False, writable=True),
        help="Write to FILE (whole or not at all; '-' is standard output) instead of "
        "standard output.",
    )(func)
    func = click.option(
        "--format",
        "fmt",
        type=click.Choice(["table", "csv", "markdown", "json"]),
        default="table",
        show_default=True,
        help="Output format; csv and json carry 10 significant digits.",
    )(func)
    return func


def emit(text: str, output: str | None) -> None:
    """Print ``text`` (also for ``-o -``) or write it whole to the file ``output``."""
    if output == "":
        raise click.UsageError("Invalid value for '-o' / '--output': the file name is empty")
    if output is not None and output != "-":
        from bearingload.reports.render import write_atomic

        try:
            write_atomic(text, output)
        except OSError as exc:
            raise click.UsageError(
                f"Invalid value for '-o' / '--output': cannot write {output!r}: {exc.strerror}"
            ) from exc
    else:
        click.echo(text, nl=False)


#: Library parameter names -> the option the user typed.
OPTION_NAMES = {
    "balls": "--balls",
    "load": "--load",
    "stiffness": "--stiffness",
    "clearance": "--clearance",
    "cage_angle": "--cage-angle",
    "exponent": "--exponent",
    "steps": "--steps",
    "T": "--kurochkin-T",
    # bearing, geometry and life options (bearingload.bearings.resolve, bearingload.bearings.life)
    "bearing": "BEARING",
    "ball-diameter": "--ball-diameter",
    "D_w": "--ball-diameter",
    "pitch-diameter": "--pitch-diameter",
    "d_m": "--pitch-diameter",
    "f_i": "--inner-conformity",
    "f_o": "--outer-conformity",
    "modulus": "--modulus",
    "E1": "--modulus",
    "poisson": "--poisson",
    "nu1": "--poisson",
    "pick": "--clearance-pick",
    "bore": "--clearance",
    "revolutions": "--revolutions",
    "series": "--series",
    # combined load (bearingload.models.combined, bearingload.bearings.iso16281)
    "radial_load": "--load",
    "axial_load": "--axial-load",
    "moment": "--moment",
    "misalignment": "--misalignment",
    "dynamic_rating": "--dynamic-rating",
    "ball_diameter": "--ball-diameter",
    "pitch_diameter": "--pitch-diameter",
    "standard": "--standard",
    "paper": "--paper",
    "maker": "--maker",
    "roller-length": "--roller-length",
    "plot": "--plot",
    "family": "--family",
    "size": "--size",
}


#: Where a command calls a library parameter by another option name.
COMMAND_OPTION_NAMES = {
    "table": {"bearing": "--bearing"},
    "catalog show": {"bearing": "DESIGNATION"},
    "fit": {
        "base": "--base",
        "base_points": "--base",
        "balls": "--balls",
        "load_unit": "--load-unit",
        "displacement_unit": "--displacement-unit",
    },
}


def option_name(parameter: str) -> str:
    """The option the user typed for a library parameter: the one map from the library's
    parameter names to the command line's option names."""
    ctx = click.get_current_context(silent=True)
    command = " ".join(ctx.command_path.split()[1:]) if ctx is not None else ""
    return COMMAND_OPTION_NAMES.get(command, {}).get(parameter) or OPTION_NAMES.get(
        parameter, parameter
    )


def option_message(message: str) -> str:
    """A library message with every quoted parameter name ('ball_diameter') written as the
    option the user types ('--ball-diameter')."""
    import re

    def swap(match: re.Match[str]) -> str:
        name = match.group(1)
        return (
            f"'{option_name(name)}'"
            if name in OPTION_NAMES or name in _COMMAND_NAMES
            else match.group(0)
        )

    return re.sub(r"'([a-z_]+)'", swap, message)


_COMMAND_NAMES = {p for names in COMMAND_OPTION_NAMES.values() for p in names}


def usage_error(exc: InputError) -> click.UsageError:
    """The one ``Invalid value for '<option>': <message>`` of a library InputError."""
    message = option_message(str(exc).split(": ", 1)[-1])
    return click.UsageError(f"Invalid value for '{option_name(exc.parameter)}': {message}")


def library_errors(func: Callable[..., Any]) -> Callable[..., Any]:
    """Turn library exceptions into one ``Error:`` line with exit status 2 (bad input) or 1."""

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return func(*args, **kwargs)
        except InputError as exc:
            raise usage_error(exc) from exc
        except BearingloadError as exc:
            raise click.ClickException(str(exc)) from exc

    return wrapper


def cage_angle_deg(cage_angle: float | str, balls: int) -> float:
    """The ``--cage-angle`` value in degrees; ``"half"`` is half a pitch, 180/z."""
    return 180.0 / balls if cage_angle == "half" else float(cage_angle)


def cage_angle_option(func: Callable[..., Any]) -> Callable[..., Any]:
    """``--cage-angle DEG|half``, shared by ``solve`` and ``table``."""
    return click.option(
        "--cage-angle",
        type=CageAngle(),
        default="0",
        show_default=True,
        help="Angle of ball 1 from the load line, degrees unless a unit follows (12, 12deg, "
        "0.2rad, 3mrad); 0 = a ball under the load, 'half' = the load between two balls.",
    )(func)


class Exponent(click.ParamType):
    """A load-deflection exponent as a number or a fraction: ``1.5``, ``3/2``, ``10/9``."""

    name = "M"

    def convert(
        self, value: Any, param: click.Parameter | None, ctx: click.Context | None
    ) -> float | str:
        if isinstance(value, float):
            return value
        text = str(value).strip()
        num, slash, den = text.partition("/")
        try:
            m = float(num) / float(den) if slash else float(text)
        except (ValueError, ZeroDivisionError):
            self.fail(f"{value!r} is neither a number nor a fraction like 10/9", param, ctx)
        return m


def exponent_option(func: Callable[..., Any]) -> Callable[..., Any]:
    """``--exponent/-m``, shared by ``solve`` and ``table``."""
    return click.option(
        "--exponent",
        "-m",
        type=Exponent(),
        default=1.5,
        show_default=True,
        help="Load-deflection exponent m: 1.5 (or 3/2) for balls, 10/9 for rollers.",
    )(func)


def stiffness_option(func: Callable[..., Any]) -> Callable[..., Any]:
    """``--stiffness/-K`` of one ring, shared by ``solve`` and ``sweep``."""
    return click.option(
        "--stiffness",
        "-K",
        type=Quantity("stiffness"),
        help="Ball stiffness K of both contacts in series, Q = K delta^m; required without a "
        "BEARING or ball geometry, else it replaces the Hertz value. "
        f"Units: {units_help('stiffness')} (bare number: N/mm^1.5, N/mm^(10/9) for a "
        "cylindrical roller bearing unless --exponent says otherwise).",
    )(func)


def method_option(help_text: str) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """``--method`` over the registered methods and ``all``; imports no numpy."""
    from bearingload.models.registry import DEFAULT_METHOD, list_methods

    return click.option(
        "--method",
        type=click.Choice([*list_methods(), "all"]),
        default=DEFAULT_METHOD,
        show_default=True,
        help=help_text,
    )


def maker_option(func: Callable[..., Any]) -> Callable[..., Any]:
    """``--maker``: whose ball set a catalogue designation uses."""
    return click.option(
        "--maker",
        help="Whose ball set the designation uses where makers differ: NSK (default), NTN, SKF, "
        "GMN, GOST, or a published test-rig set (CWRU, PRONOSTIA, PADERBORN); "
        "'bearingload catalog show X' lists the makers of X.",
    )(func)


def quiet_option(func: Callable[..., Any]) -> Callable[..., Any]:
    """``--quiet``: no ``Warning:`` lines on the terminal (JSON keeps its ``warnings``)."""
    return click.option(
        "--quiet",
        "-q",
        is_flag=True,
        help="Do not print warnings (static safety, contact pressure, ...) on stderr; "
        "JSON output keeps them under 'warnings'.",
    )(func)


def print_warnings(warnings: list[str], quiet: bool) -> None:
    """Print each warning as one ``Warning: ...`` line on stderr, unless ``quiet``."""
    if quiet:
        return
    for text in warnings:
        click.echo(f"Warning: {text}", err=True)
