"""How each input of a case is read from a library argument: a number in the command line's
default unit, or a string with a unit (``"1kN"``), checked for its range.

One reader per input name (:data:`READERS`); ``bearingload solve``'s options read the same
quantities through the same parsers (:mod:`bearingload.units`), and ``tests`` check that each
option's type and range agree with the reader of its name.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from bearingload.constants import CONTAMINATION_LEVELS
from bearingload.errors import InputError
from bearingload.plan.case import AT_REST

Reader = Callable[[Any, str], Any]


def quantity(kind: str, *, positive: bool = False, at_zero: str = "") -> Reader:
    """A number with an optional unit of ``kind`` (:func:`bearingload.units.parse_quantity`); a
    number given without a unit is read as the command line reads a bare number, its
    plausibility for the quantity checked the same way; ``at_zero``: what a 0 given means and
    how to ask for it (the command line's words). (A radial load's sign depends on the bearing
    and the command: :meth:`bearingload.plan.case.Case.check_load`.)"""

    def read(value: Any, name: str) -> float:
        from bearingload.units import BASE_UNIT, parse_quantity

        number = parse_quantity(_as_text(value, name), kind, parameter=name)
        if positive and not number > 0:
            hint = f": {at_zero}" if at_zero and number == 0 else ""
            raise InputError(name, f"must be greater than 0 {BASE_UNIT[kind]} (got {value}){hint}")
        return number

    read.kind, read.positive = kind, positive  # type: ignore[attr-defined]
    return read


def number_in(low: float, high: float, *, low_open: bool = False) -> Reader:
    """A plain number in [low, high] ((low, high] with ``low_open``)."""

    def read(value: Any, name: str) -> float:
        number = _float(value, name)
        inside = (number > low if low_open else number >= low) and number <= high
        if not inside:
            left = "(" if low_open else "["
            raise InputError(name, f"must be in {left}{low:g}, {high:g}] (got {number:g})")
        return number

    read.range = (low, high, low_open)  # type: ignore[attr-defined]
    return read


def choice(*allowed: str, case: str | None = None) -> Reader:
    """One of ``allowed`` (``case``: "upper" or "lower" to fold the case first)."""

    def read(value: Any, name: str) -> str:
        text = str(value).strip()
        text = text.upper() if case == "upper" else text.lower() if case == "lower" else text
        if text not in allowed:
            raise InputError(name, f"{value!r} is not one of {', '.join(allowed)}")
        return text

    read.choices = allowed  # type: ignore[attr-defined]
    return read


def text(value: Any, name: str) -> str:
    """A text as given (a designation, a fit class, an oil grade, a maker), not empty."""
    if not isinstance(value, str):
        raise InputError(name, f"must be a text, got {value!r}")
    if not value.strip():
        raise InputError(name, "must not be empty")
    return value


def count(value: Any, name: str) -> int:
    """A whole number (the balls)."""
    number = _float(value, name)
    if not number.is_integer():
        raise InputError(name, f"must be a whole number, got {value!r}")
    return int(number)


def flag(value: Any, name: str) -> bool:
    """True or False."""
    if not isinstance(value, bool):
        raise InputError(name, f"must be True or False, got {value!r}")
    return value


def stiffness(value: Any, name: str) -> str:
    """The stiffness as written: its unit is checked against the exponent later."""
    return _as_text(value, name)


stiffness.kind = "stiffness"  # type: ignore[attr-defined]


def _reader(module: str, function: str, kind: str | None = None) -> Reader:
    """``module.function`` of the text; ``kind``: the kind of unit of its numbers."""

    def read(value: Any, name: str) -> Any:
        import importlib

        return getattr(importlib.import_module(module), function)(_as_text(value, name))

    read.kind = kind  # type: ignore[attr-defined]
    return read


def _named(module: str, function: str, kind: str | None = None) -> Reader:
    """:func:`_reader` of a parser that names its parameter."""

    def read(value: Any, name: str) -> Any:
        import importlib

        parse = getattr(importlib.import_module(module), function)
        return parse(_as_text(value, name), parameter=name)

    read.kind = kind  # type: ignore[attr-defined]
    return read


def exponent(value: Any, name: str) -> float:
    """A load-deflection exponent as a number or a fraction (``"10/9"``)."""
    if isinstance(value, str):
        num, slash, den = value.strip().partition("/")
        try:
            return float(num) / float(den) if slash else float(value)
        except (ValueError, ZeroDivisionError):
            raise InputError(
                name, f"{value!r} is neither a number nor a fraction like 10/9"
            ) from None
    return _float(value, name)


def _float(value: Any, name: str) -> float:
    """A real number given as a Python or numpy scalar (or its text), finite."""
    import math
    import numbers

    from bearingload.validate import not_real

    if isinstance(value, str):
        try:
            number = float(value)
        except ValueError:
            raise InputError(name, f"must be a number, got {value!r}") from None
    elif not_real(value) or not (isinstance(value, numbers.Real) or hasattr(value, "shape")):
        raise InputError(name, f"must be a number, got {value!r}")  # (True, a date: not_real)
    elif isinstance(value, numbers.Real):
        try:
            number = float(value)
        except OverflowError:
            raise InputError(name, "is too large for a number of this package") from None
    else:
        raise InputError(name, "analyse takes one case: give a number, not an array")
    if not math.isfinite(number):
        raise InputError(name, f"must be a finite number, got {number}")
    return number


def _as_text(value: Any, name: str) -> str:
    """The text the command line would read for ``value``: a string as it is, a number (a
    Python or numpy scalar) as the bare number it is."""
    if isinstance(value, str):
        return value
    number = _float(value, name)
    return str(int(number)) if number.is_integer() and abs(number) < 1e16 else repr(number)


#: Every input of a case by its library name -> its reader.
READERS: dict[str, Reader] = {
    "balls": count,
    "load": quantity("force"),
    "axial_load": quantity("force"),
    "moment": quantity("moment"),
    "moment_cross": quantity("moment"),
    "misalignment": quantity("angle"),
    "contact_angle": quantity("angle"),
    "arrangement": choice("DB", "DF", "DT", case="upper"),
    "preload": _named("bearingload.bearings.preload", "parse_preload", "force"),
    "width": quantity("length", positive=True),
    "tilt_radius": _reader("bearingload.bearings.tilt", "parse_tilt_radius", "length"),
    "stiffness": stiffness,
    "clearance": _reader("bearingload.bearings.clearance", "parse_clearance", "length"),
    "clearance_pick": choice("min", "mean", "max", "range"),
    "shaft_fit": text,
    "housing_fit": text,
    "shaft_bore": quantity("length", positive=True),
    "housing_diameter": quantity("length", positive=True),
    "inner_ring_temperature": _named("bearingload.units", "parse_temperature", "temperature"),
    "outer_ring_temperature": _named("bearingload.units", "parse_temperature", "temperature"),
    "ball_diameter": quantity("length"),
    "pitch_diameter": quantity("length"),
    "inner_conformity": lambda v, n: _float(v, n),
    "outer_conformity": lambda v, n: _float(v, n),
    "modulus": quantity("modulus"),
    "poisson": lambda v, n: _float(v, n),
    "ball_material": text,
    "maker": text,
    "cage_angle": _named("bearingload.units", "parse_cage_angle", "angle"),
    "exponent": exponent,
    "dynamic_rating": quantity("force", positive=True),
    "rotating": choice("inner", "outer"),
    "static_rating": quantity("force", positive=True),
    "speed": quantity("speed", positive=True, at_zero=AT_REST),
    "ball_density": number_in(0.0, 1e5, low_open=True),
    "quasi_static": flag,
    "reliability": number_in(90.0, 99.95),
    "viscosity": quantity("viscosity", positive=True),
    "oil": text,
    "viscosity_40": quantity("viscosity", positive=True),
    "viscosity_100": quantity("viscosity", positive=True),
    "viscosity_index": lambda v, n: _float(v, n),
    "temperature": _named("bearingload.units", "parse_temperature", "temperature"),
    "contamination": choice(*CONTAMINATION_LEVELS),
    "e_c": number_in(0.0, 1.0),
    "fatigue_load_limit": quantity("force", positive=True),
    "roughness": quantity("length", positive=True),
    "pressure_viscosity": number_in(1.0, 100.0),
}


#: The other names the models below give an input (``f_i`` for ``inner_conformity``): a
#: refusal naming one of them names the input (:func:`argument_of`), and the command line's
#: option answers for them.
LIBRARY_NAMES: dict[str, tuple[str, ...]] = {
    "balls": ("rollers",),
    "load": ("radial_load",),
    "clearance": ("bore",),
    "clearance_pick": ("pick",),
    "ball_diameter": ("D_w", "roller_diameter"),
    "pitch_diameter": ("d_m",),
    "inner_conformity": ("f_i",),
    "outer_conformity": ("f_o",),
    "modulus": ("E1",),
    "poisson": ("nu1",),
    "static_rating": ("C0",),
    "e_c": ("eC",),
    "fatigue_load_limit": ("C_u",),
}


def argument_of(parameter: str) -> str:
    """The input a model's parameter name stands for (``f_i`` -> ``inner_conformity``)."""
    return next((n for n, other in LIBRARY_NAMES.items() if parameter in other), parameter)


def read_inputs(options: dict[str, Any]) -> dict[str, Any]:
    """The inputs of a case read from library arguments (None: not given); an unknown name is
    refused naming the inputs there are."""
    unknown = sorted(set(options) - set(READERS))
    if unknown:
        import difflib

        near = difflib.get_close_matches(unknown[0], list(READERS), n=1)
        hint = f" (did you mean {near[0]!r}?)" if near else ""
        raise InputError(
            unknown[0],
            f"is not an input of a case{hint}; the inputs are {', '.join(READERS)}",
        )
    return {n: None if v is None else READERS[n](v, n) for n, v in options.items()}
