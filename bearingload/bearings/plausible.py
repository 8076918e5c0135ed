"""Bare numbers judged against the bearing they are given for.

A bare number is taken in the package's unit (N, N mm, N/mm^1.5: :mod:`bearingload.units`). The
fixed ranges of :data:`bearingload.units.PLAUSIBLE_BARE` catch what no bearing takes; a load, a
moment or a ball stiffness shows its slip only against the bearing's own size: 3 (N) on a 6205
whose C0 is 7850 N, a moment of 5 (N mm), a stiffness of 4700 (N/mm^1.5, 4700 kgf/mm^1.5 meant)
where the 6205's Hertz stiffness is 274 869 N/mm^1.5. Each quantity's rule is one row of
:data:`BEARING_SCALE`; the refusal names the unit that makes the number plausible, and the same
number written with its unit is used as it is.

>>> from bearingload.bearings.resolve import resolve_bearing
>>> refuse_implausible_bare(resolve_bearing("6205"), {"load": 3.0})
Traceback (most recent call last):
...
bearingload.errors.InputError: load: a bare 3 is 3 N, implausible for a load on 6205 (C0 = 7850 N; plausible from 7.85 N): did you mean 3kN? Write the unit to use the number as it is.
"""

from __future__ import annotations

from typing import Any

from bearingload.errors import InputError
from bearingload.units import BASE_UNIT, UNITS

#: parameter -> (kind, what it is, the units a slip most likely meant, the plausible range of a
#: bare number as multiples of the bearing's scale (:func:`bearing_scale`)). A load below a
#: thousandth of C0, a moment below 1e-4 of C0 d_m/2 (the moment of C0 at the pitch radius), a
#: ball stiffness beyond ten times either side of the Hertz value of the ball set, a load rating
#: beyond ten times either side of the catalogue's (14 on a 6205 is 14 kN meant: C = 14 kN).
BEARING_SCALE: dict[str, tuple[str, str, tuple[str, ...], tuple[float, float]]] = {
    "load": ("force", "a load", ("kN", "kgf"), (1e-3, float("inf"))),
    "axial_load": ("force", "an axial load", ("kN", "kgf"), (1e-3, float("inf"))),
    "moment": ("moment", "a moment", ("Nm", "kNm"), (1e-4, float("inf"))),
    "moment_cross": ("moment", "a moment", ("Nm", "kNm"), (1e-4, float("inf"))),
    "stiffness": ("stiffness", "a ball stiffness", ("kgf/mm^1.5", "N/um^1.5"), (0.1, 10.0)),
    "dynamic_rating": ("force", "a dynamic load rating", ("kN", "kgf"), (0.1, 10.0)),
    "static_rating": ("force", "a static load rating", ("kN", "kgf"), (0.1, 10.0)),
}


def bearing_scale(bearing: Any, parameter: str) -> tuple[float, str] | None:
    """The bearing's own size for ``parameter`` and its words: C0 [N] for a load and a static
    rating, C [N] for a dynamic rating, C0 d_m/2 [N mm] for a moment, the Hertz stiffness of
    its ball set [N/mm^1.5] (series of the inner and outer contacts); None where the bearing
    does not give it (a ring by hand, a roller's stiffness, a rating not in the catalogue)."""
    c0, dm = getattr(bearing, "C0", None), getattr(bearing, "pitch_diameter", None)
    if parameter in ("load", "axial_load", "static_rating") and c0:
        return float(c0), f"C0 = {c0:g} N"
    c = getattr(bearing, "C", None)
    if parameter == "dynamic_rating" and c:
        return float(c), f"C = {c:g} N"
    if parameter in ("moment", "moment_cross") and c0 and dm:
        return float(c0) * float(dm) / 2.0, f"C0 d_m/2 = {c0 * dm / 2.0:.4g} N mm"
    k_i, k_o = getattr(bearing, "stiffness_inner", None), getattr(bearing, "stiffness_outer", None)
    if parameter == "stiffness" and k_i and k_o and getattr(bearing, "kind", "ball") == "ball":
        hertz = (k_i ** (-2.0 / 3.0) + k_o ** (-2.0 / 3.0)) ** -1.5
        return float(hertz), f"its Hertz stiffness {hertz:.6g} N/mm^1.5"
    return None


def refuse_implausible_bare(bearing: Any, bare: dict[str, float]) -> None:
    """Refuse a bare number of :data:`BEARING_SCALE` (parameter -> the value typed without a
    unit, in the package's unit) outside its plausible range for ``bearing``, naming the unit
    that brings it into the range. 0 is left alone (no load, no moment). Raises InputError."""
    for name, value in bare.items():
        rule, scale = BEARING_SCALE.get(name), bearing_scale(bearing, name)
        if rule is None or scale is None or value == 0:
            continue
        kind, what, likely, (low, high) = rule
        size, words = scale
        if low * size <= abs(value) <= high * size:
            continue
        base = BASE_UNIT[kind]
        meant = [u for u in likely if low * size <= abs(value) * _factor(kind, u) <= high * size]
        hint = f": did you mean {value:g}{meant[0]}?" if meant else "."
        name_of = getattr(bearing, "designation", None) or "this bearing"
        if high == float("inf"):
            bound = f"from {low * size:.3g} {base}"
        else:
            bound = f"{low * size:.3g} to {high * size:.3g} {base}"
        raise InputError(
            name,
            f"a bare {value:g} is {value:g} {base}, implausible for {what} on {name_of} ({words}; "
            f"plausible {bound}){hint} Write the unit to use the number as it is.",
        )


def _factor(kind: str, unit: str) -> float:
    if kind != "stiffness":
        return UNITS[kind][unit]
    from bearingload.units import stiffness_factor

    return stiffness_factor(unit, 1.5)
