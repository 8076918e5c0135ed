"""Shared pieces of the command line: quantity types, output options, error handling."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import click

from bearingload.errors import BearingloadError, InputError
from bearingload.units import (
    BASE_UNIT,
    UNITS,
    is_bare,
    parse_cage_angle,
    parse_quantity,
)

CONTEXT = {"help_option_names": ["-h", "--help"], "max_content_width": 100}
#: Key of click's context meta: the names of the options given a bare number (no unit).
BARE = "bearingload.bare"
#: Key of click's context meta: the text of each option given a number with a unit ("0.1kN").
TYPED = "bearingload.typed"


def note_typed(value: Any, param: click.Parameter | None, ctx: click.Context | None) -> None:
    """Keep the text of an option given a number with a unit, which a failure names it by."""
    if ctx is not None and param is not None and isinstance(value, str) and not is_bare(value):
        ctx.meta.setdefault(TYPED, {})[param.name] = value.strip()


class Quantity(click.ParamType):
    """A number with an optional unit suffix, converted to the package's internal unit."""

    def __init__(self, kind: str, *, positive: bool = False, at_zero: str = "") -> None:
        self.kind = kind
        self.positive = positive
        self.at_zero = at_zero  # what a user giving 0 means, and how to ask for it
        self.name = f"{kind} [{BASE_UNIT[kind]}]"

    def convert(
        self, value: Any, param: click.Parameter | None, ctx: click.Context | None
    ) -> float | str:
        if isinstance(value, float):
            return value
        try:
            number = parse_quantity(value, self.kind, parameter=param.name if param else None)
        except InputError as exc:
            self.fail(exc.message, param, ctx)
        if ctx is not None and param is not None and is_bare(value):
            ctx.meta.setdefault(BARE, set()).add(param.name)  # judged against the bearing later
        note_typed(value, param, ctx)
        if self.kind == "stiffness":
            return str(value)  # converted with the exponent by the command (stiffness_value)
        if self.positive and not number > 0:
            hint = f": {option_message(self.at_zero)}" if self.at_zero and number == 0 else ""
            self.fail(f"must be greater than 0 {BASE_UNIT[self.kind]} (got {value}){hint}", param,
                      ctx)  # fmt: skip
        return number

    def get_metavar(self, param: click.Parameter, ctx: click.Context | None = None) -> str:
        return f"{self.kind.upper()} [{BASE_UNIT[self.kind]}]"


class PreloadValue(click.ParamType):
    """A pair's preload: a force (bare number: N) or a preload class letter, read by
    :func:`bearingload.bearings.preload.parse_preload`, as ``batch`` reads its ``preload``
    column and the library its ``preload=``."""

    name = "FORCE|EL|L|M|H"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if isinstance(value, float):
            return value
        from bearingload.bearings.preload import parse_preload

        try:
            preload = parse_preload(value, parameter=param.name if param else "preload")
        except InputError as exc:
            self.fail(exc.message, param, ctx)
        note_typed(value, param, ctx)
        return preload


class CageAngle(click.ParamType):
    """Cage angle: degrees by default, ``deg``, ``rad``, ``mrad``, or ``half`` for half a pitch
    (the load between two balls); read by :func:`bearingload.units.parse_cage_angle`, as
    ``batch`` reads its ``cage_angle`` column."""

    name = "DEG|half"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if value == "half" or isinstance(value, float):
            return value
        try:
            angle = parse_cage_angle(value)
        except InputError as exc:
            self.fail(exc.message, param, ctx)
        note_typed(value, param, ctx)
        return angle


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


class LibraryOption(click.Option):
    """An option that answers for the library's names of its parameter (``library``), so that a
    library error names the option the user typed (:func:`option_name`)."""

    def __init__(self, *args: Any, library: tuple[str, ...] = (), **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.library = library


class LibraryArgument(click.Argument):
    """An argument that answers for the library's names of its parameter (``library``)."""

    def __init__(self, *args: Any, library: tuple[str, ...] = (), **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.library = library


def _shown(param: click.Parameter) -> str:
    """How the user writes ``param``: its long option, or the argument's name."""
    if isinstance(param, click.Option):
        return next((o for o in param.opts if o.startswith("--")), param.opts[0])
    return (param.metavar or (param.name or "").upper()).strip("[]. ")


def _parameter(name: str) -> click.Parameter | None:
    """The parameter of the running command that the library calls ``name``: its own name, or
    one of the ``library`` names it answers for."""
    ctx = click.get_current_context(silent=True)
    params = ctx.command.params if ctx is not None else []
    return next((p for p in params if p.name == name), None) or next(
        (p for p in params if name in getattr(p, "library", ())), None
    )


def option_name(parameter: str) -> str:
    """The option the user typed for a library parameter (``ball_diameter``, ``D_w`` ->
    ``--ball-diameter``); a name no parameter of the running command answers for, as it is."""
    param = _parameter(parameter)
    return parameter if param is None else _shown(param)


def option_message(message: str, keep: str | None = None) -> str:
    """A library message with every quoted parameter name ('ball_diameter') of the running
    command written as the option the user types ('--ball-diameter'); a quoted ``keep`` (the
    value the user gave, 'load' as a designation) stays as it is."""
    import re

    def swap(match: re.Match[str]) -> str:
        param = None if match.group(1) == keep else _parameter(match.group(1))
        return match.group(0) if param is None else f"'{_shown(param)}'"

    return re.sub(r"'([a-z_][a-z0-9_]*)'", swap, message)


def _all_names(parameter: str) -> str:
    """Every spelling of an option (``'--balls' / '-z'``), or the argument's name."""
    param = _parameter(parameter)
    if isinstance(param, click.Option):
        return " / ".join(f"'{o}'" for o in param.opts)
    return f"'{option_name(parameter)}'"


def usage_error(exc: InputError) -> click.UsageError:
    """The one usage error of a library InputError, from its fields: ``Invalid value for
    '<option>': <message>``; ``<option> cannot be used with <where>: <why>`` for a conflict;
    ``Missing option '<option>' (<instead>)``; the options a case would ignore."""
    from bearingload.bearings.oil import OilInputError
    from bearingload.errors import ConflictError, MissingError, UnusedError

    option = option_name(exc.parameter)
    spell = functools.partial(option_message, keep=_typed(exc.parameter))  # its value as typed
    if isinstance(exc, ConflictError):
        where, why = spell(exc.where), spell(exc.why)
        return click.UsageError(f"{option} cannot be used with {where}: {why}")
    if isinstance(exc, MissingError):
        return click.UsageError(
            f"Missing option {_all_names(exc.parameter)} ({spell(exc.instead)})"
        )
    if isinstance(exc, UnusedError):
        names = ", ".join(option_name(n) for n in exc.parameters)
        one = len(exc.parameters) == 1
        verb, it = ("needs", "it") if one else ("need", "they")
        return click.UsageError(f"{names} {verb} {spell(exc.need)} {it} would be ignored")
    if isinstance(exc, OilInputError):
        why = spell(exc.why)
        if exc.kind == "conflict":
            assert exc.other is not None
            return click.UsageError(f"{option} cannot be used with {option_name(exc.other)}: {why}")
        names = " / ".join(f"'{option_name(p)}'" for p in exc.parameters)
        head = "Missing option" if exc.kind == "missing" else "Invalid value for"
        return click.UsageError(f"{head} {names}: {why}")
    message = spell(exc.problem)  # the value refused; the way out names only inputs
    if exc.way_out is not None:
        message += f"; {option_message(exc.way_out)}"
    return click.UsageError(f"Invalid value for '{option}': {message}")


def _typed(parameter: str) -> str | None:
    """The text the user gave the parameter the library calls ``parameter`` (a designation, an
    oil grade), which a refusal of it quotes; None for a number or nothing given."""
    param = _parameter(parameter)
    ctx = click.get_current_context(silent=True)
    value = None if param is None or ctx is None else ctx.params.get(param.name or "")
    return value.strip() if isinstance(value, str) else None


def library_errors(func: Callable[..., Any]) -> Callable[..., Any]:
    """Turn library exceptions into one ``Error:`` line with exit status 2 (bad input) or 1."""

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return func(*args, **kwargs)
        except InputError as exc:
            raise usage_error(exc) from exc
        except BearingloadError as exc:
            raise click.ClickException(_failure(exc)) from exc

    return wrapper


def _failure(exc: BearingloadError) -> str:
    """The line of a failure of the computation: a ConvergenceError names its cases' inputs by
    the options the user types, each value as typed (``--load = 1 kN``, ``--speed = 3000 rpm``)."""
    from bearingload.errors import ConvergenceError

    if not isinstance(exc, ConvergenceError):
        return option_message(str(exc))
    cases = {option_name(k): v for k, v in exc.cases.items()}
    units = {option_name(k): u for k, u in (exc.units or {}).items()}
    typed = {option_name(k): t for k, t in (exc.typed or {}).items()}
    way = None if exc.way_out is None else option_message(exc.way_out)
    failure = ConvergenceError(exc.solver, exc.iterations, exc.residual, cases, units, way, typed)
    return str(failure)


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
