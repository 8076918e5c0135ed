"""Tolerances of the seats and of the bearing: ISO 286 fit classes and ISO 492's Normal class.

* ISO 286 (limits and fits): the shaft classes j5 j6 k5 k6 m5 m6 n5 n6 p5 p6 and the housing
  classes H6 H7 J7 K6 K7 M6 M7 N6 N7 P6 P7, for sizes up to 500 mm
  (``data/iso286_deviations.csv``: the standard tolerance grades IT5-IT7 of ISO 286-1:2010
  Table 1, the shafts' fundamental deviations ei of Table 2, J7's upper deviation of ISO
  286-2:2010). A shaft's limits are ei and ei + IT; a hole's H: EI = 0, ES = IT; K, M, N (grades
  up to IT8) and P (up to IT7): ES = -ei + Delta with ei that of the shaft of the same letter and
  Delta = IT_n - IT_(n-1) (ISO 286-1:2010, the rule of the holes K to ZC; Delta = 0 up to 3 mm),
  EI = ES - IT.
* ISO 492 Normal tolerance class: the mean bore diameter deviation t_Δdmp of the inner ring and
  the mean outside diameter deviation t_ΔDmp of the outer ring (``data/iso492_normal.csv``).

Deviations in µm from the nominal size; positive = larger.
"""

from __future__ import annotations

import functools

from bearingload.bearings._data import read_rows
from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass

__all__ = ["SHAFT_CLASSES", "HOUSING_CLASSES", "Limits", "fit_limits", "ring_limits"]

#: The shaft classes: letter -> the grades taken.
SHAFT_CLASSES = ("j5", "j6", "k5", "k6", "m5", "m6", "n5", "n6", "p5", "p6")
#: The housing (hole) classes.
HOUSING_CLASSES = ("H6", "H7", "J7", "K6", "K7", "M6", "M7", "N6", "N7", "P6", "P7")


@dataclass(frozen=True)
class Limits:
    """The upper and lower deviation of a size from its nominal value, and their source. [µm]"""

    upper: float
    lower: float
    source: str


@functools.cache
def _iso286() -> tuple[dict[str, str], ...]:
    return tuple(read_rows("iso286_deviations.csv"))


@functools.cache
def _iso492() -> tuple[dict[str, str], ...]:
    return tuple(read_rows("iso492_normal.csv"))


def _row(rows: tuple[dict[str, str], ...], size: float, parameter: str, what: str) -> dict:
    for row in rows:
        if float(row["size_over"]) < size <= float(row["size_incl"]):
            return row
    low, high = float(rows[0]["size_over"]), float(rows[-1]["size_incl"])
    raise InputError(parameter, f"{what} has a table for diameters over {low:g} up to {high:g} "
                     f"mm, not {size:g} mm")  # fmt: skip


def fit_limits(fit: str, size: float, parameter: str) -> Limits:
    """The limits of the ISO 286 class ``fit`` (``k5``: a shaft; ``H7``: a hole, by the case of
    its letter) at the nominal ``size`` [mm].

    >>> l = fit_limits("k5", 25.0, "shaft_fit"); (l.upper, l.lower)
    (11.0, 2.0)
    >>> l = fit_limits("P7", 52.0, "housing_fit"); (l.upper, l.lower)
    (-21.0, -51.0)

    Raises
    ------
    InputError
        (``parameter``) for a class not taken, naming those taken; a size outside the table.
    """
    text = str(fit).strip()
    allowed = SHAFT_CLASSES if parameter == "shaft_fit" else HOUSING_CLASSES
    if text not in allowed:
        raise InputError(parameter, f"unknown ISO 286 class {fit!r}; allowed: {' '.join(allowed)}")
    row = _row(_iso286(), size, parameter, f"ISO 286 class {text}")
    letter, grade = text[0], int(text[1:])
    it = float(row[f"IT{grade}"])
    source = f"ISO 286 {text} at {size:g} mm (over {row['size_over']} incl {row['size_incl']}): {row['source']}"
    if letter.islower():
        ei = float(row[f"{letter}_ei"])
        return Limits(ei + it, ei, source)
    if letter == "H":
        return Limits(it, 0.0, source)
    if letter == "J":
        es = float(row["J7_ES"])
        return Limits(es, es - it, source)
    delta = 0.0 if float(row["size_incl"]) <= 3.0 else it - float(row[f"IT{grade - 1}"])
    es = -float(row[f"{letter.lower()}_ei"]) + delta
    return Limits(es, es - it, source)


def ring_limits(ring: str, size: float) -> Limits:
    """ISO 492 Normal class: the mean bore (``ring`` inner) or outside diameter (outer)
    deviation of a radial bearing at the nominal ``size`` [mm].

    >>> l = ring_limits("inner", 25.0); (l.upper, l.lower)
    (0.0, -10.0)
    """
    rows = tuple(
        {"size_over": r["over"], "size_incl": r["incl"], **r}
        for r in _iso492()
        if r["ring"] == ring
    )
    what = "ISO 492 Normal class " + ("bore" if ring == "inner" else "outside diameter")
    row = _row(rows, size, "bearing", what)
    return Limits(float(row["upper"]), float(row["lower"]), row["source"])
