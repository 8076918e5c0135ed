"""Quantities with units: parse ``"300kgf"``, ``"20um"``, ``"4700 kgf/mm^1.5"`` into SI-mm values.

Internal units of the whole package: force in newtons [N], length in millimetres [mm],
ball stiffness in [N/mm^1.5] (roller stiffness in [N/mm^(10/9)]), modulus in [MPa] = [N/mm^2].
A bare number means the internal unit of its kind.

>>> parse_quantity("300kgf", "force")
2941.995
>>> parse_quantity("20um", "length")
0.02
>>> parse_quantity("-5 µm", "length")
-0.005
"""

from __future__ import annotations

import math
import re
from typing import Any

from bearingload.constants import INCH, KGF, LBF  # noqa: F401  (re-exported: units.KGF)

#: Accepted unit suffixes per kind, as factors to the internal unit.
UNITS: dict[str, dict[str, float]] = {
    "force": {"N": 1.0, "kN": 1e3, "kgf": KGF, "kp": KGF, "lbf": LBF},
    "length": {"mm": 1.0, "um": 1e-3, "µm": 1e-3, "μm": 1e-3, "in": INCH, "m": 1e3},
    # stiffness units are read by parse_stiffness: F/L^e for any force F and length L above
    "stiffness": {"N/mm^1.5": 1.0, "kgf/mm^1.5": KGF, "N/um^1.5": 1e3**1.5, "N/mm^(10/9)": 1.0},
    "modulus": {"MPa": 1.0, "N/mm^2": 1.0, "GPa": 1e3, "kgf/mm^2": KGF, "Pa": 1e-6},
    "moment": {"Nmm": 1.0, "N*mm": 1.0, "Nm": 1e3, "N*m": 1e3, "kNm": 1e6, "kgfmm": KGF},
    # minutes and seconds of arc as well: the misalignment a bearing tolerates is quoted in
    # arcmin (SKF: 2-10'); ' and " are the usual signs, ′ and ″ the typographic primes
    "angle": {
        "deg": 1.0,
        "°": 1.0,
        "rad": 180.0 / math.pi,
        "mrad": 0.18 / math.pi,
        "arcmin": 1.0 / 60.0,
        "'": 1.0 / 60.0,
        "′": 1.0 / 60.0,
        "arcsec": 1.0 / 3600.0,
        '"': 1.0 / 3600.0,
        "″": 1.0 / 3600.0,
    },
    # shaft speed: revolutions per minute (ISO 281 writes r/min)
    "speed": {
        "rpm": 1.0,
        "r/min": 1.0,
        "1/min": 1.0,
        "rad/s": 30.0 / math.pi,
        "1/s": 60.0,
        "Hz": 60.0,
    },
    # kinematic viscosity of the lubricant (1 cSt = 1 mm^2/s)
    "viscosity": {"mm^2/s": 1.0, "mm²/s": 1.0, "cSt": 1.0, "m^2/s": 1e6, "m²/s": 1e6},
    # a life in revolutions; ISO 281 counts lives in millions of them (Mrev = 10^6 rev)
    "revolutions": {"rev": 1.0, "Mrev": 1e6},
}

#: The unit a bare number is taken in, per kind.
BASE_UNIT = {
    "force": "N",
    "length": "mm",
    "stiffness": "N/mm^1.5",
    "modulus": "MPa",
    "moment": "N mm",
    "angle": "°",
    "speed": "rpm",
    "viscosity": "mm^2/s",
    "revolutions": "rev",
}

#: Plausible ranges of a BARE number (no unit) per (kind, parameter); outside, the number is
#: refused with the unit the user most likely meant, instead of being used. [base unit]
PLAUSIBLE_BARE: dict[tuple[str, str | None], tuple[float, float, str]] = {
    # Young's modulus: bare numbers are MPa; steel 2.1e5, ceramics 3.1e5; "210" is 210 GPa meant
    ("modulus", None): (1e3, 1e7, "a Young's modulus"),
    # a radial clearance of 1 mm or more is beyond every ISO 5753-1 class up to 1000 mm bore
    ("length", "clearance"): (-1.0, 1.0, "a radial clearance"),
    # a composite rms roughness of ground raceways and balls: 0.01 to 1 µm; a bare 0.2 is µm meant
    ("length", "roughness"): (0.0, 0.01, "a composite surface roughness"),
    # shaft speeds: dental turbines reach 4e5 rpm; a bare 1e9 is no shaft speed in rpm
    ("speed", None): (0.0, 1e6, "a shaft speed"),
    # operating viscosities of oils and greases' base oils: 1 (water-like) to 1e5 mm^2/s (a cold
    # gear oil); a bare 6.8e-5 is m^2/s meant
    ("viscosity", None): (0.1, 1e6, "an operating kinematic viscosity"),
    # the datasheet's viscosities of an oil at 40 and 100 °C: the same range (ISO VG 2 is 2.2 at
    # 40 °C, VG 3200 3200), named for what they are: not the operating viscosity nu
    ("viscosity", "viscosity_40"): (0.1, 1e6, "an oil's kinematic viscosity at 40 °C"),
    ("viscosity", "viscosity_100"): (0.1, 1e6, "an oil's kinematic viscosity at 100 °C"),
    # the life of an allowable load C/(L/10^6)^(1/p): below 1e5 rev (half an hour at 3000 rpm)
    # it exceeds 2 C, far beyond the static rating C0 < C; 1e15 rev is 1e9 x 10^6 rev, beyond
    # any bearing (1e5 rpm for 1e6 h is 6e12 rev). A bare 36 is Kuzmenko's N = 36 x 10^6 meant
    ("revolutions", None): (1e5, 1e15, "the life of an allowable load"),
}


def plausible_ranges_help(kind: str, parameter: str | None = None) -> str:
    """The bare numbers refused as implausible, for --help, in the words of the refusal: the
    lower bound is accepted, the upper one refused.

    >>> plausible_ranges_help("length", "clearance")
    'a bare number below -1 mm or of 1 mm or more is refused'
    """
    low, high, _ = PLAUSIBLE_BARE[(kind, parameter)]
    unit = BASE_UNIT[kind]
    return f"a bare number below {low:g} {unit} or of {high:g} {unit} or more is refused"


#: The units a bare, implausible number may have been meant in, most likely first, per kind
#: (spellings of one factor once; the base unit's synonyms, cSt for mm^2/s, never help).
HINT_UNITS = {
    "modulus": ("GPa", "Pa"),
    "length": ("um", "in", "m"),
    "viscosity": ("m^2/s",),
    "revolutions": ("Mrev",),
}


#: Where a hinted reading must fall, per kind, where narrower than :data:`PLAUSIBLE_BARE`: a unit
#: is suggested only where it makes the number a usual value, not a merely possible one. [base]
HINT_RANGE = {
    # oils in service and their datasheet viscosities at 40 and 100 °C (ISO VG 2 to 3200): 1 to
    # 1e4 mm^2/s, written 1e-6 to 1e-2 in m^2/s; a bare 0.05 read as m^2/s would be 5e4 mm^2/s,
    # an oil near its pour point, so no unit is suggested for it
    "viscosity": (1.0, 1e4),
}


def likely_unit(value: float, kind: str, name: str) -> str | None:
    """``value`` written with the first unit of :data:`HINT_UNITS` that makes it plausible for
    the parameter ``name`` (``210GPa``) and, for the kinds of :data:`HINT_RANGE`, a usual value,
    or None where no unit does (a bare speed of 1e9: every speed unit is larger than rpm)."""
    low, high, _ = PLAUSIBLE_BARE.get((kind, name)) or PLAUSIBLE_BARE[(kind, None)]
    low, high = HINT_RANGE.get(kind, (low, high))
    for unit in HINT_UNITS.get(kind, ()):
        if low <= value * UNITS[kind][unit] < high:
            return f"{value:g}{unit}"
    return None


#: Kinds whose bare numbers <= 0 are left to the option's own positivity check.
_SIGNED = ("modulus", "speed", "viscosity", "revolutions")


#: The reason of the refusal of a bare number implausible for its quantity.
IMPLAUSIBLE = "implausible"


def _check_plausible(value: float, kind: str, name: str, text: object) -> None:
    rule = PLAUSIBLE_BARE.get((kind, name)) or PLAUSIBLE_BARE.get((kind, None))
    if rule is None or rule[0] <= value < rule[1] or (kind in _SIGNED and value <= 0):
        return  # a modulus <= 0 is refused by the model's own check, not guessed at
    from bearingload.errors import InputError

    low, high, what = rule
    base = BASE_UNIT[kind]
    meant = likely_unit(value, kind, name)
    hint = f": did you mean {meant}?" if meant is not None else "."
    # a lower bound of 0 is never a value: the signed kinds and the roughness refuse it
    lowest = f"above {low:g}" if low == 0 else f"at least {low:g}"
    raise InputError(
        name,
        f"a bare {text} is {value:g} {base}, implausible for {what} (bare numbers are {base}; "
        f"plausible {lowest} and below {high:g} {base}){hint} Write the unit to use the number "
        "as it is.",
        reason=IMPLAUSIBLE,
    )


#: Kinds whose unit names are read case-insensitively (RPM, R/MIN, Rad/s, hz): none of their
#: names differ only in case. Not the others: mm and Mm, mN and MN would be one unit.
CASE_FREE_KINDS = frozenset({"speed"})

_NUMBER = re.compile(r"^\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(.*?)\s*$")


def is_bare(text: object) -> bool:
    """True when ``text`` is a number written without a unit (``3``, ``3e3``), which is read in
    the package's unit of its kind (:data:`BASE_UNIT`)."""
    match = _NUMBER.match(str(text))
    return match is not None and match.group(2) == ""


def as_written(text: object, kind: str | None = None) -> str:
    """A quantity as the user wrote it, for a message: its number and unit one space apart
    (``-1kN`` and a ``-1`` in a ``[kN]`` column of a batch file: ``-1 kN``); a bare number with
    the unit it is read in (``-1``: ``-1 N``); a text that is no number as it is.

    >>> as_written("-1kN", "force"), as_written(" -1 ", "force"), as_written(2.5, "length")
    ('-1 kN', '-1 N', '2.5 mm')
    """
    match = _NUMBER.match(str(text))
    if match is None:
        return str(text).strip()
    unit = match.group(2) or (BASE_UNIT[kind] if kind else "")
    return f"{match.group(1)} {unit}".rstrip()


def _canonical(unit: str) -> str:
    return unit.replace(" ", "").replace("**", "^").replace("(3/2)", "3/2")


#: Spellings that name no unit but whose unit is plain, per kind: a mass for its weight, the
#: pound for the pound-force. Suggested in the refusal, never read: 300kg is refused, naming
#: 300kgf (a kilogram is no force; 1 kgf = 9.80665 N).
UNIT_SLIPS: dict[str, dict[str, str]] = {
    "force": {"kg": "kgf", "kgs": "kgf", "lb": "lbf", "lbs": "lbf"},
    "moment": {"kgmm": "kgfmm", "kgf*mm": "kgfmm"},
}


def meant_unit(unit: str, kind: str) -> str | None:
    """The unit of ``kind`` an unknown spelling most likely means, or None: a unit written in
    another case (``KN``, ``kn``: kN), with a dot or a middle dot for the product (``N.m``:
    N*m) or one of :data:`UNIT_SLIPS` (``kg``: kgf, ``lb``: lbf)."""
    known = {_canonical(u): u for u in UNITS[kind]}
    key = re.sub(r"[.·⋅]", "*", unit)
    if key in known:
        return known[key]
    slips = UNIT_SLIPS.get(kind, {})
    folded = [u for c, u in known.items() if c.casefold() == key.casefold()]
    if len(set(folded)) == 1:
        return folded[0]
    return slips.get(key.casefold())


def parse_quantity(text: str | float, kind: str, *, parameter: str | None = None) -> float:
    """Parse a number with an optional unit into the internal unit of ``kind``.

    Parameters
    ----------
    text : str or float
        ``"300kgf"``, ``"0.02 mm"``, ``"20um"``, or a bare number. [unit as written]
    kind : str
        One of ``force``, ``length``, ``stiffness``, ``modulus``, ``moment``, ``angle``,
        ``speed``, ``viscosity``, ``revolutions``.
    parameter : str, optional
        Name used in the error message (defaults to ``kind``).

    Returns
    -------
    float
        The value in N, mm, N/mm^1.5, MPa, N mm, degrees, rpm, mm^2/s or revolutions.

    Raises
    ------
    InputError
        When the text is not a finite number followed by an accepted unit of that kind.
    """
    from bearingload.errors import InputError

    name = parameter or kind
    units = UNITS[kind]
    if isinstance(text, (int, float)):
        value, unit, written = float(text), "", ""
    else:
        match = _NUMBER.match(str(text))
        if match is None or ("," in str(text) and re.match(r"^\s*[+-]?\d*,\d", str(text))):
            raise InputError(name, _unreadable(str(text), kind))
        written = match.group(1)
        value, unit = float(written), _canonical(match.group(2))
    if not math.isfinite(value):
        raise InputError(name, f"{text!r} is not a finite number")
    if unit == "":
        if not isinstance(text, (int, float)):
            _check_plausible(value, kind, name, text)
        return value
    if kind == "stiffness":
        return value * stiffness_factor(unit, None, parameter=name)
    lookup = {_canonical(u): f for u, f in units.items()}
    if kind in CASE_FREE_KINDS:  # 3000RPM, 50hz: no two speed units differ only in case
        lookup = {u.lower(): f for u, f in lookup.items()}
        unit = unit.lower()
    if unit not in lookup:
        meant = meant_unit(unit, kind)
        hint = f"did you mean {written}{meant}? " if meant else ""
        raise InputError(
            name,
            f"unknown unit {unit!r} in {text!r}; {hint}allowed: {', '.join(units)} "
            f"(a bare number is {BASE_UNIT[kind]})",
        )
    converted, base = value * lookup[unit], BASE_UNIT[kind]
    if not math.isfinite(converted):
        raise InputError(name, f"{text!r} overflows: it is beyond every finite number of {base}")
    return converted


def parse_cage_angle(text: str | float, *, parameter: str = "cage_angle") -> float | str:
    """Parse a cage angle: ``"half"`` (half a pitch, the load between two balls) or an angle.

    The one reading of a cage angle for every command and for ``batch`` files: a bare number is
    degrees; ``deg``, ``°``, ``rad``, ``mrad``, ``arcmin`` (or ``'``) and ``arcsec`` (or ``"``)
    may follow it (any case: ``5DEG``, ``0.1rad``, ``30arcmin``).

    Parameters
    ----------
    text : str or float
        ``"12"``, ``"12deg"``, ``"0.1rad"``, ``"half"``, or a number. [° unless a unit is written]
    parameter : str, optional
        Name used in the error message.

    Returns
    -------
    float or str
        The angle in [°], or ``"half"``.

    Raises
    ------
    InputError
        When the text is neither ``half`` nor a finite angle with an angle unit.

    Examples
    --------
    >>> parse_cage_angle("HALF"), parse_cage_angle("20"), parse_cage_angle("90°")
    ('half', 20.0, 90.0)
    >>> round(parse_cage_angle("0.1rad"), 9)
    5.729577951
    >>> parse_cage_angle("30arcmin"), parse_cage_angle("90'"), parse_cage_angle('5400"')
    (0.5, 1.5, 1.5)
    """
    if isinstance(text, (int, float)):
        return parse_quantity(float(text), "angle", parameter=parameter)
    folded = str(text).strip().lower()
    if folded == "half":
        return "half"
    from bearingload.errors import InputError

    try:
        return parse_quantity(folded, "angle", parameter=parameter)
    except InputError as exc:
        way = "or 'half' (half a pitch: the load between two balls)"
        raise InputError(parameter, exc.problem, way_out=way, reason=exc.reason) from None


#: The units of a temperature: a bare number and these three are degrees Celsius, ``K`` kelvin.
TEMPERATURE_UNITS = ("°C", "C", "degC", "K")
#: The operating temperatures of an oil accepted, as the command line accepts them. [°C]
TEMPERATURE_RANGE = (-60.0, 250.0)


def parse_temperature(text: str | float, *, parameter: str = "temperature") -> float:
    """An operating temperature in °C: a bare number, ``C``, ``°C`` or ``degC`` is degrees
    Celsius, ``K`` kelvin (T - 273.15); -60 to 250 °C (:data:`TEMPERATURE_RANGE`). The one
    reading of ``--temperature`` and of the ``temperature`` column of ``batch``. [°C]

    >>> parse_temperature("70"), parse_temperature("70C"), round(parse_temperature("343.15K"), 9)
    (70.0, 70.0, 70.0)

    Raises
    ------
    InputError
        Naming ``parameter``: an unreadable text or a temperature outside the range (a bare
        number that fits the range as kelvin is offered as such: 300 -> 300K).
    """
    from bearingload.errors import InputError

    if isinstance(text, (int, float)):
        match, number = None, float(text)
    else:
        units = "|".join(TEMPERATURE_UNITS)
        match = re.fullmatch(rf"\s*([-+]?[0-9.]+(?:e[-+]?\d+)?)\s*({units})?\s*", str(text))
        try:
            number = float(match.group(1)) if match else float("nan")
        except ValueError:
            number = float("nan")
    celsius = number - 273.15 if match and match.group(2) == "K" else number
    low, high = TEMPERATURE_RANGE
    if not low <= celsius <= high:
        as_kelvin = number - 273.15  # a bare number meant in kelvin, where that fits
        hint = (
            f"; did you mean {number:g}K ({as_kelvin:g} °C)?"
            if match and match.group(2) is None and low <= as_kelvin <= high
            else ""
        )
        fahrenheit = re.fullmatch(r"\s*([-+]?[0-9.]+)\s*(°F|F|degF)\s*", str(text))
        if fahrenheit and re.fullmatch(r"[-+]?\d+\.?\d*|[-+]?\.\d+", fahrenheit.group(1)):
            degrees = (float(fahrenheit.group(1)) - 32.0) / 1.8
            hint = f"; did you mean {degrees:.4g}C ({fahrenheit.group(1)} °F)?"
        raise InputError(
            parameter,
            f"{text!r}: give the operating temperature in °C (70, 70C) or K (343.15K), "
            f"{low:g} to {high:g} °C{hint}",
        )
    return celsius


def _unreadable(text: str, kind: str) -> str:
    """Why ``text`` is no number with a unit, with a hint for the usual slips."""
    if re.match(r"^\s*[+-]?\d*,\d+", text):
        fixed = text.strip().replace(",", ".", 1)
        if re.match(r"^\s*[+-]?\d{1,3}(,\d{3})+\b", text):  # 3,000: a thousands separator?
            whole = re.sub(r"(?<=\d),(?=\d{3}\b)", "", text.strip())
            return (
                f"cannot read {text!r}: write no thousands separator ({whole}) or a decimal "
                f"point ({fixed})"
            )
        return f"cannot read {text!r}: write the decimal point, not a comma: {fixed}"
    return (
        f"cannot read {text!r} as a number with a unit; "
        f"write e.g. '{_example(kind)}' (units: {', '.join(UNITS[kind])})"
    )


def unit_names() -> set[str]:
    """Every unit the parser knows, as written (for the hint on a unit typed after a space)."""
    return {u for units in UNITS.values() for u in units} | {"kgf/mm^1.5", "N/mm^1.5"}


def _example(kind: str) -> str:
    examples = {"force": "300kgf", "length": "20um", "stiffness": "4700kgf/mm^1.5"}
    more = {"moment": "1.5Nm", "angle": "2.7mrad", "speed": "3000rpm", "viscosity": "20cSt",
            "revolutions": "36Mrev"}  # fmt: skip
    return (examples | more).get(kind, "208GPa")


#: A stiffness unit F/L^e (a pattern text, compiled at its first use: most runs type none).
_STIFFNESS_UNIT = r"^(?P<force>[A-Za-z]+)/(?P<length>[A-Za-zµμ]+)\^\(?(?P<num>\d+(?:\.\d*)?)(?:/(?P<den>\d+))?\)?$"


def stiffness_factor(unit: str, exponent: float | None, *, parameter: str = "stiffness") -> float:
    """Factor from a stiffness unit ``F/L^e`` to N/mm^e, checking ``e`` against ``exponent``.

    ``Q = K delta^m``: a stiffness in force ``F`` per length ``L`` to the power ``e`` converts
    as ``K [N/mm^e] = K' f_F / f_L^e`` (``f``: the factor of each unit to N or mm), so the
    exponent of the unit must be the load-deflection exponent ``m`` of the calculation.

    >>> stiffness_factor("kgf/mm^1.5", 1.5)
    9.80665
    >>> round(stiffness_factor("N/um^(10/9)", 10 / 9), 3)
    2154.435
    """
    from bearingload.errors import InputError

    match = re.match(_STIFFNESS_UNIT, _canonical(unit))
    forces, lengths = UNITS["force"], UNITS["length"]
    if match is None or match["force"] not in forces or match["length"] not in lengths:
        raise InputError(
            parameter,
            f"unknown unit {unit!r}; write force/length^m with a force in "
            f"{', '.join(forces)} and a length in {', '.join(lengths)}, e.g. N/mm^1.5, "
            "kgf/mm^1.5, N/um^1.5, N/mm^(10/9) (a bare number is N/mm^m)",
        )
    e = float(match["num"]) / (float(match["den"]) if match["den"] else 1.0)
    if exponent is not None and abs(e - exponent) > 1e-3 * exponent:
        raise InputError(
            parameter,
            f"the unit {unit!r} is for the exponent {e:g}, but the load-deflection exponent is "
            f"{exponent:g}; write the stiffness in N/mm^{exponent:g} (or force/length^{exponent:g})",
        )
    return forces[match["force"]] / lengths[match["length"]] ** (exponent or e)


def parse_stiffness(text: str | float, exponent: float, *, parameter: str = "stiffness") -> float:
    """A ball or roller stiffness with its unit, in N/mm^m for the exponent ``m``.

    A bare number is N/mm^m; ``4700kgf/mm^1.5``, ``3e5 N/mm^(10/9)``, ``12 N/um^1.5`` are read with
    their own units, whose length exponent must equal ``m``.

    >>> parse_stiffness("4700kgf/mm^1.5", 1.5)
    46091.255
    """
    from bearingload.errors import InputError

    if isinstance(text, (int, float)):
        return float(text)
    match = _NUMBER.match(str(text))
    if match is None:
        raise InputError(
            parameter, f"cannot read {text!r} as a number with a unit; write e.g. '4700kgf/mm^1.5'"
        )
    value = float(match.group(1))
    unit = _canonical(match.group(2))
    return value if unit == "" else value * stiffness_factor(unit, exponent, parameter=parameter)


def turn_angle(value: Any, digits: int) -> Any:
    """A turn angle [°] as a report rounds it to ``digits`` significant digits: 0 where that
    gives 360 (an angle just below a turn, -1e-12° reduced to 359.999999999999°, is printed at
    the turn's start, never as 360), else ``value``. The one rule of every format: json, csv, table
    and markdown (:data:`bearingload.reports.render.TURN_KEYS`) and a title's cage angle.

    >>> turn_angle(359.999999999999, 10), turn_angle(359.99, 6), turn_angle(359.9999999, 6)
    (0.0, 359.99, 0.0)
    """
    if value is None or isinstance(value, (bool, str)) or not 355.0 <= value <= 365.0:
        return value  # (nothing outside rounds to 360 at any digits)
    return 0.0 if float(f"{float(value):.{digits}g}") == 360.0 else value
