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

#: Standard gravity, exact by definition (CGPM 1901): 1 kgf = 9.80665 N.
KGF = 9.80665
#: 1 lbf = 0.45359237 kg x g_n (international avoirdupois pound, 1959). [N]
LBF = 0.45359237 * KGF
#: 1 in = 25.4 mm exactly (international inch, 1959).
INCH = 25.4

#: Accepted unit suffixes per kind, as factors to the internal unit.
UNITS: dict[str, dict[str, float]] = {
    "force": {"N": 1.0, "kN": 1e3, "kgf": KGF, "kp": KGF, "lbf": LBF},
    "length": {"mm": 1.0, "um": 1e-3, "µm": 1e-3, "μm": 1e-3, "in": INCH, "m": 1e3},
    "stiffness": {
        "N/mm^1.5": 1.0,
        "N/mm^3/2": 1.0,
        "kgf/mm^1.5": KGF,
        "kgf/mm^3/2": KGF,
    },
    "modulus": {"MPa": 1.0, "N/mm^2": 1.0, "GPa": 1e3, "kgf/mm^2": KGF, "Pa": 1e-6},
}
# Q = K' * (delta[um])^1.5 = K' * (1000 delta[mm])^1.5 -> K[N/mm^1.5] = K' * 1000^1.5
UNITS["stiffness"]["N/um^1.5"] = 1e3**1.5
UNITS["stiffness"]["kgf/um^1.5"] = KGF * 1e3**1.5

#: The unit a bare number is taken in, per kind.
BASE_UNIT = {"force": "N", "length": "mm", "stiffness": "N/mm^1.5", "modulus": "MPa"}

_NUMBER = re.compile(r"^\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(.*?)\s*$")


def _canonical(unit: str) -> str:
    return unit.replace(" ", "").replace("**", "^").replace("(3/2)", "3/2")


def parse_quantity(text: str | float, kind: str, *, parameter: str | None = None) -> float:
    """Parse a number with an optional unit into the internal unit of ``kind``.

    Parameters
    ----------
    text : str or float
        ``"300kgf"``, ``"0.02 mm"``, ``"20um"``, or a bare number. [unit as written]
    kind : str
        One of ``force``, ``length``, ``stiffness``, ``modulus``.
    parameter : str, optional
        Name used in the error message (defaults to ``kind``).

    Returns
    -------
    float
        The value in N, mm, N/mm^1.5 or MPa.

    Raises
    ------
    InputError
        When the text is not a finite number followed by an accepted unit of that kind.
    """
    from .errors import InputError

    name = parameter or kind
    units = UNITS[kind]
    if isinstance(text, (int, float)):
        value, unit = float(text), ""
    else:
        match = _NUMBER.match(str(text))
        if match is None:
            raise InputError(
                name,
                f"cannot read {text!r} as a number with a unit; "
                f"write e.g. '{_example(kind)}' (units: {', '.join(units)})",
            )
        value, unit = float(match.group(1)), _canonical(match.group(2))
    if not math.isfinite(value):
        raise InputError(name, f"{text!r} is not a finite number")
    if unit == "":
        return value
    lookup = {_canonical(u): f for u, f in units.items()}
    if unit not in lookup:
        raise InputError(
            name,
            f"unknown unit {unit!r} in {text!r}; allowed: {', '.join(units)} "
            f"(a bare number is {BASE_UNIT[kind]})",
        )
    return value * lookup[unit]


def _example(kind: str) -> str:
    return {"force": "300kgf", "length": "20um", "stiffness": "4700kgf/mm^1.5"}.get(kind, "208GPa")
