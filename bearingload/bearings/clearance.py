"""Radial internal clearance of single-row deep groove ball bearings and of cylindrical roller
bearings with a cylindrical bore (ISO 5753-1 classes).

The clearance classes C2 < CN < C3 < C4 < C5 give the *radial internal clearance* G_r, the
total radial play of one ring against the other, unmounted and unloaded. The papers' gap per
side is half of it (Delta = e = G_r / 2); this module returns G_r itself.

The limits are those of ``data/clearance_deep_groove.csv``, copied from NSK's reproduction of
the ISO 5753-1 table for deep groove ball bearings [1]_ and confirmed cell by cell for 6-140 mm
by [2]_; the row over 2.5 up to 6 mm (C2, CN, C3 only) from the makers' pages its source
names. Bore ranges are "over / incl": a bore of exactly 30 mm belongs to the 24-30 row.

The limits of cylindrical roller bearings with a cylindrical bore (``kind="roller"``) are those
of ``data/clearance_cylindrical_roller.csv``, copied from the ISO 5753-1 table reproduced by [4]_
(C2, Normal, C3, C4, C5) and confirmed for C2-C4 cell by cell to 250 mm by [5]_. The number of
the table inside ISO 5753-1 was not read.

GOST 24810-81 numbers the same clearance groups of single-row radial ball bearings with a
cylindrical bore 6, normal, 7, 8, 9 (= C2, CN, C3, C4, C5) [3]_. The GOST micrometre limits
were not found, so the ISO limits are used for the GOST groups too.

References
----------
.. [1] NSK, *Rolling Bearings* catalogue, Table 9.9 "Radial Internal Clearances in Deep Groove
   Ball Bearings" (values of ISO 5753-1), micrometres.
.. [2] PTI, "Bearing inserts internal clearance", pti.eu technical information (same values).
.. [3] aprom.by, "Зазоры в подшипниках качения" (GOST 24810 groups and their ISO
   equivalents), text copy in the BearingsInfo collection, section 1.3.
.. [4] original-bearing.com, "Radial internal clearance of cylindrical roller bearings with a
   cylindrical bore", https://original-bearing.com/article/s103/ (micrometres).
.. [5] AHR International, "Bearing clearance", http://ahrinternational.com/bearing_clearance.htm
   (C2, CN, C3, C4 of cylindrical roller bearings, micrometres).

>>> clearance_range(30, "C3")
(0.013, 0.028)
>>> radial_clearance(30, "CN")
0.0125
>>> parse_class("7")
'C3'
>>> clearance_range(30, "CN", kind="roller")
(0.02, 0.045)
"""

from __future__ import annotations

import functools
import re

from bearingload.constants import CLEARANCE_PICKS
from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.units import IMPLAUSIBLE, parse_quantity

#: The ISO clearance classes the table gives, in increasing clearance.
CLASSES: tuple[str, ...] = ("C2", "CN", "C3", "C4", "C5")

#: GOST 24810-81 clearance groups of single-row radial ball bearings with a cylindrical
#: bore, and their ISO classes (aprom.by text, see the module references).
GOST_GROUPS: dict[str, str] = {"6": "C2", "7": "C3", "8": "C4", "9": "C5"}

#: How a class may be picked from its range.
PICKS: tuple[str, ...] = CLEARANCE_PICKS
#: The pick that takes a class at every one of :data:`PICKS`, side by side.
RANGE = "range"

_NORMAL = {"N", "CN", "C0", "0", "NORMAL", "NORM", "НОРМАЛЬНАЯ", "НОРМ", "M", "М"}
#: A GOST group written with its word (``G7``, ``GR. 7``), a pattern text compiled at its
#: first use by :func:`_group_word`.
_GROUP_WORD = r"^(?:G|GR|GROUP|ГР|ГРУППА)\s*\.?\s*(\S+)$"
_ALLOWED = (
    "C2, CN, C3, C4, C5 (ISO 5753-1; 'N', 'normal', '0' mean CN) or the GOST 24810 groups "
    "6, 7, 8, 9 (= C2, C3, C4, C5; normal = CN), also written 'G7'"
)


class ClearanceRow:
    """One bore range of the clearance table (a plain class, read by attribute only: no
    dataclass to build on every solve of a bearing).

    Attributes
    ----------
    bore_over, bore_incl : float
        The row holds bores ``bore_over < d <= bore_incl``. [mm]
    limits : dict
        ``{class: (min, max)}`` radial internal clearance. [mm]
    source : str
        Where the row was copied from.
    """

    __slots__ = ("bore_over", "bore_incl", "limits", "source")

    def __init__(
        self,
        bore_over: float,
        bore_incl: float,
        limits: dict[str, tuple[float, float]],
        source: str,
    ) -> None:
        self.bore_over = bore_over
        self.bore_incl = bore_incl
        self.limits = limits
        self.source = source


#: Bearing kind -> (file of its clearance table, what the table covers).
TABLES: dict[str, tuple[str, str]] = {
    "ball": ("clearance_deep_groove.csv", "deep groove ball bearings"),
    "roller": (
        "clearance_cylindrical_roller.csv",
        "cylindrical roller bearings (cylindrical bore)",
    ),
}


@functools.lru_cache(maxsize=2)
def table(kind: str = "ball") -> tuple[ClearanceRow, ...]:
    """The clearance table of one bearing kind, rows in increasing bore.

    Parameters
    ----------
    kind : {"ball", "roller"}
        Deep groove ball bearings, or cylindrical roller bearings with a cylindrical bore.

    Returns
    -------
    tuple of ClearanceRow
        Limits converted from the file's micrometres to [mm].
    """
    from bearingload.bearings._data import read_rows  # the table is read on first use only

    if kind not in TABLES:
        raise InputError("kind", f"unknown bearing kind {kind!r}; allowed: {', '.join(TABLES)}")
    rows = []
    for rec in read_rows(TABLES[kind][0]):
        limits = {  # a class the source does not give for the row is left out
            cls: (float(rec[f"{cls}_min"]) / 1000.0, float(rec[f"{cls}_max"]) / 1000.0)
            for cls in CLASSES
            if rec[f"{cls}_min"] != ""
        }
        rows.append(
            ClearanceRow(float(rec["bore_over"]), float(rec["bore_incl"]), limits, rec["source"])
        )
    return tuple(rows)


def parse_class(text: str) -> str:
    """Read a clearance class or GOST clearance group.

    Parameters
    ----------
    text : str
        ``C2``, ``CN``, ``C3``, ``C4``, ``C5`` (any case; ``N``, ``normal``, ``0`` and ``M``
        mean CN), or a GOST 24810 group ``6``, ``7``, ``8``, ``9``, optionally written
        ``G7`` / ``group 7``.

    Returns
    -------
    str
        One of :data:`CLASSES`.

    Raises
    ------
    InputError
        For anything else (parameter ``clearance``), listing the allowed classes.

    Examples
    --------
    >>> parse_class("c3"), parse_class("normal"), parse_class("G9")
    ('C3', 'CN', 'C5')
    """
    raw = str(text).strip().upper()
    group = _group_word(raw)
    key = group.group(1) if group else raw
    if key in CLASSES:
        return key
    if key in _NORMAL:
        return "CN"
    if key in GOST_GROUPS:
        return GOST_GROUPS[key]
    hint = ""
    if key == "C1":
        hint = " (C1 is not tabulated for deep groove ball bearings)"
    raise InputError("clearance", f"unknown clearance class {text!r}{hint}; allowed: {_ALLOWED}")


def _group_word(raw: str) -> re.Match[str] | None:
    """:data:`_GROUP_WORD` matched on ``raw``, skipped (None) unless it starts with G or Г."""
    return re.match(_GROUP_WORD, raw) if raw[:1] in "GГ" else None


def looks_like_class(text: str) -> bool:
    """Tell whether ``text`` names a clearance class rather than a length.

    A bare number is always a length (the package's rule: a bare number is in mm), so
    ``"0"`` means zero clearance here and ``"7"`` means 7 mm; write ``"G7"`` or ``"C3"`` for
    the GOST group 7. Use it to route a ``--clearance`` option to :func:`parse_class` or to
    :func:`bearingload.units.parse_quantity`.

    Parameters
    ----------
    text : str
        The option value as typed.

    Returns
    -------
    bool

    Examples
    --------
    >>> looks_like_class("C3"), looks_like_class("cn"), looks_like_class("20um")
    (True, True, False)
    """
    raw = str(text).strip().upper()
    if re.fullmatch(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:E[+-]?\d+)?", raw):
        return False
    group = _group_word(raw)
    key = group.group(1) if group else raw
    if group and key in GOST_GROUPS:
        return True
    return key in CLASSES or (key in _NORMAL and not key[0].isdigit()) or key == "C1"


def _row(bore: float, kind: str = "ball") -> ClearanceRow:
    rows = table(kind)
    try:
        d = float(bore)
    except (TypeError, ValueError):
        raise InputError("bore", f"{bore!r} is not a number") from None
    for row in rows:
        if row.bore_over < d <= row.bore_incl:
            return row
    raise InputError(
        "bore",
        f"{d:g} mm is outside the clearance table of {TABLES[kind][1]} "
        f"(over {rows[0].bore_over:g} up to {rows[-1].bore_incl:g} mm); "
        "give 'clearance' as a length instead, e.g. 20um",
    )


def clearance_range(bore: float, cls: str, kind: str = "ball") -> tuple[float, float]:
    """Smallest and largest radial internal clearance G_r of a class.

    Parameters
    ----------
    bore : float
        Nominal bore diameter d. [mm]
    cls : str
        Clearance class or GOST group, as accepted by :func:`parse_class`.
    kind : {"ball", "roller"}, default "ball"
        Deep groove ball bearing, or cylindrical roller bearing with a cylindrical bore.

    Returns
    -------
    (float, float)
        (min, max) radial internal clearance G_r. [mm]

    Raises
    ------
    InputError
        Bore outside the table, or unknown class.
    """
    row, name = _row(bore, kind), parse_class(cls)
    if name not in row.limits:
        raise InputError(
            "clearance",
            f"class {name} is not tabulated for a bore of {float(bore):g} mm (over "
            f"{row.bore_over:g} up to {row.bore_incl:g} mm: {', '.join(row.limits)}); give "
            "another class, or 'clearance' as a length",
        )
    return row.limits[name]


def largest_class(bore: float, kind: str = "ball") -> tuple[str, float]:
    """The largest class tabulated at ``bore`` [mm] and its upper limit G_r [mm] (C5, or C3
    where the row over 2.5 up to 6 mm stops)."""
    row = _row(bore, kind)
    name = [c for c in CLASSES if c in row.limits][-1]
    return name, row.limits[name][1]


def table_name(bore: float, kind: str = "ball") -> str:
    """What the row of ``bore`` reproduces: ``ISO 5753-1`` for the rows copied from a maker's
    reproduction of the standard, ``makers' tables`` for the row over 2.5 up to 6 mm, read from
    makers' pages only (its source in the data file)."""
    return "ISO 5753-1" if "ISO 5753-1 values" in _row(bore, kind).source else "makers' tables"


def radial_clearance(bore: float, cls: str, pick: str = "mean", kind: str = "ball") -> float:
    """Radial internal clearance G_r of a class, at its lower limit, middle or upper limit.

    Parameters
    ----------
    bore : float
        Nominal bore diameter d. [mm]
    cls : str
        Clearance class or GOST group, as accepted by :func:`parse_class`.
    pick : str, default "mean"
        ``min``, ``mean`` (middle of the range) or ``max``.
    kind : {"ball", "roller"}, default "ball"
        Deep groove ball bearing, or cylindrical roller bearing with a cylindrical bore.

    Returns
    -------
    float
        Radial internal clearance G_r (total play; the gap per side is G_r / 2). [mm]

    Raises
    ------
    InputError
        Bore outside the table, unknown class, or unknown pick.

    Examples
    --------
    >>> radial_clearance(40, "C3", pick="max")
    0.033
    """
    if pick not in PICKS:
        raise InputError("pick", f"unknown pick {pick!r}; allowed: {', '.join(PICKS)}")
    low, high = clearance_range(bore, cls, kind)
    if pick == "min":
        return low
    if pick == "max":
        return high
    return (low + high) / 2.0


def picks_of(pick: str) -> tuple[str, ...]:
    """The picks a clearance pick stands for: :data:`PICKS` (min, mean, max) for
    :data:`RANGE`, else the pick itself (checked where it is used).

    >>> picks_of("range"), picks_of("max")
    (('min', 'mean', 'max'), ('max',))
    """
    return PICKS if pick == RANGE else (pick,)


@dataclass(frozen=True)
class ClearanceSpec:
    """A clearance as typed: a length G_r [mm] or a clearance class.

    Raises
    ------
    InputError
        (parameter ``clearance``) a length that is not a finite number (NaN, infinity, text).
    """

    length: float | None = None
    cls: str | None = None
    text: str = ""

    def __post_init__(self) -> None:
        if self.length is not None:
            from bearingload.validate import finite

            finite("clearance", self.length)


def parse_clearance(text: str | float | None) -> ClearanceSpec | None:
    """Read a clearance option: a length (bare number = mm) or a class.

    ``C2 CN C3 C4 C5`` (also ``N``, ``normal``), GOST 24810 groups written ``G6 G7 G8 G9``; a
    bare number is always a length, so ``7`` means 7 mm, not group 7.

    Returns
    -------
    ClearanceSpec or None
        None when ``text`` is None.

    Raises
    ------
    InputError
        (parameter ``clearance``) neither a length nor a class.

    >>> parse_clearance("C3").cls, parse_clearance("g7").cls, parse_clearance("20um").length
    ('C3', 'C3', 0.02)
    """
    if text is None:
        return None
    if isinstance(text, (int, float)):
        return ClearanceSpec(length=float(text), text=repr(text))
    if looks_like_class(text):
        return ClearanceSpec(cls=parse_class(text), text=str(text))
    try:
        return ClearanceSpec(
            length=parse_quantity(text, "length", parameter="clearance"), text=text
        )
    except InputError as exc:
        if exc.reason == IMPLAUSIBLE:
            group = f"the GOST clearance group {text} is written G{text}"
            if text not in ("6", "7", "8", "9"):
                raise
            raise InputError("clearance", f"{exc.problem} ({group})", reason=IMPLAUSIBLE) from None
        way = "or a clearance class C2, CN, C3, C4, C5 (GOST groups G6, G7, G8, G9)"
        raise InputError("clearance", exc.problem, way_out=way, reason=exc.reason) from None


def clearance_length(spec: ClearanceSpec | None) -> float:
    """G_r [mm] of a clearance given as a length (0 for None); a class needs a bearing's bore.

    Raises
    ------
    InputError
        (parameter ``clearance``) for a class.
    """
    if spec is None:
        return 0.0
    if spec.length is None:
        raise InputError("clearance", NEEDS_BORE.format(spec.text))
    return spec.length


#: The refusal of a clearance class where no bore resolves it ({}: the class as typed).
NEEDS_BORE = (
    "a clearance class ({}) is resolved by the bore; give a bearing designation, or "
    "'clearance' as a length, e.g. 20um"
)
