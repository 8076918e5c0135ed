"""The preload of a matched pair: a force, or a maker's preload class resolved against its table.

Matched pairs of angular-contact ball bearings are sold by preload class, not in newtons: NSK
extra light ``EL``, light ``L``, medium ``M``, heavy ``H``; SKF ``A`` ... ``D``; FAG ``UL``, ``L``,
``M``, ``H``. The force of a class differs from maker to maker and from size to size. The one
reading of a preload, for ``--preload``, a batch file's ``preload`` cell and the library's
``preload=``, is :func:`parse_preload` (a force with units, or a class letter); a class becomes the
force of its table by :func:`resolve_preload`.

Tables (``data/preload_classes.csv``, a source on every row): NSK's preloads of DB and DF pairs of
the 79, 70 and 72 series at 15° (``C``) and 25° (``A5``), by bore code. The 15° rows of bore codes 00
to 20 are also in NSK's general catalogue (CAT. No. E1102e, Table 10.2), with the same values.
The table of the bearing's series, bore and contact angle is used whichever maker's row gives the
ratings (Koyo's 7205C takes NSK's class forces of a 7205C pair), and said so. A class of a
bearing without a table (40° and 30° rows, the GOST types, the 73 series, a ring given by hand)
is refused, naming the series that have one; so are the letters of a maker without a table
(SKF's A ... D, FAG's UL).

>>> parse_preload("m"), parse_preload("300N"), parse_preload("0.5kN")
('M', 300.0, 500.0)
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Any

from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass

#: The classes with a table, in order of force, and the maker whose letters they are.
CLASSES: tuple[str, ...] = ("EL", "L", "M", "H")
TABLE_MAKER = "NSK"
#: Every maker's class letters (those of :data:`TABLE_MAKER` have a table, the others not).
MAKER_LETTERS: dict[str, tuple[str, ...]] = {
    "NSK": CLASSES,
    "SKF": ("A", "B", "C", "D"),
    "FAG": ("UL", "L", "M", "H"),
}
_LETTER = re.compile(r"^(EL|UL|[LMHABCD])$")


@dataclass(frozen=True)
class Preload:
    """A pair's preload: ``force`` F_p [N] (the axial force each bearing of a DB or DF pair
    carries with no external load); the ``preload_class`` it was read from (None: a force
    given); ``source``: where the force comes from (``given`` or the table row's source)."""

    force: float
    preload_class: str | None = None
    source: str = "given"

    @property
    def text(self) -> str:
        """The preload in words, for a report's title: ``200 N`` or ``200 N (NSK class M)``."""
        if self.preload_class is None:
            return f"{self.force:.6g} N"
        return f"{self.force:.6g} N ({TABLE_MAKER} class {self.preload_class})"


def parse_preload(value: Any, *, parameter: str = "preload") -> float | str:
    """A preload as typed: a class letter (``EL``, ``L``, ``M``, ``H``, or another maker's:
    ``A`` ... ``D``, ``UL``; any case), returned upper-case, or a force (a bare number is N,
    units as every force) in N, 0 or more.

    Raises
    ------
    InputError
        (``parameter``) neither a class letter nor a force of 0 N or more.
    """
    from bearingload.units import as_written, parse_quantity

    if isinstance(value, str) and _LETTER.match(value.strip().upper()):
        return value.strip().upper()
    try:
        force = parse_quantity(value, "force", parameter=parameter)
    except InputError as exc:
        way = f"or a preload class: {' | '.join(CLASSES)}"
        raise InputError(parameter, exc.problem, way_out=way, reason=exc.reason) from None
    if not force >= 0:
        raise InputError(parameter, f"must be 0 N or more (got {as_written(value, 'force')})")
    return force


@dataclass(frozen=True)
class _Row:
    series: str
    contact_angle: float
    bore_code: str
    forces: dict[str, float]
    source: str


@lru_cache(maxsize=1)
def _table() -> dict[tuple[str, float, str], _Row]:
    from bearingload.bearings._data import read_rows

    rows = {}
    for r in read_rows("preload_classes.csv"):
        forces = {c: float(r[c]) for c in CLASSES}
        row = _Row(r["series"], float(r["contact_angle"]), r["bore_code"], forces, r["source"])
        rows[(row.series, row.contact_angle, row.bore_code)] = row
    return rows


def tabulated() -> str:
    """The series, angles and bore codes that have a class table, in words (for messages)."""
    angles: dict[str, set[float]] = {}
    codes: dict[str, set[str]] = {}
    for r in _table().values():
        angles.setdefault(r.series, set()).add(r.contact_angle)
        codes.setdefault(r.series, set()).add(r.bore_code)
    return ", ".join(
        f"{s}xx at {' and '.join(f'{a:g}°' for a in sorted(angles[s]))} "
        f"(bore codes {min(codes[s])}-{max(codes[s])})"
        for s in sorted(angles)
    )


def _refuse(why: str) -> InputError:
    return InputError(
        "preload",
        f"{why}; the preload classes {', '.join(CLASSES)} ({TABLE_MAKER}'s) are tabulated for "
        f"{tabulated()} (7205C, 7008A5, 7205AC ...); give the preload as a force (e.g. 300N)",
    )


def resolve_preload(value: Any, bearing: Any = None, maker: str | None = None) -> Preload:
    """The preload ``value`` (as :func:`parse_preload` reads it) of a pair of ``bearing`` (a
    :class:`~bearingload.bearings.resolved.ResolvedBearing`; None: a ring given by hand) as a
    force: a force as given, a class from the table of the bearing's series, bore and angle.

    ``maker``: the maker named for the bearing; a class letter is read as that maker's (only
    NSK's have a table); without one, as NSK's.

    Raises
    ------
    InputError
        (``preload``) an unreadable value, a class of a bearing or a maker without a table.
    """
    parsed = parse_preload(value)
    if isinstance(parsed, float):
        return Preload(parsed)
    named = (maker or TABLE_MAKER).strip().upper()
    own = MAKER_LETTERS.get(named)
    if named != TABLE_MAKER and own is not None and parsed in own:
        raise _refuse(f"{named}'s preload class {parsed} has no table in the catalogue")
    if parsed not in CLASSES:
        owners = [m for m, letters in MAKER_LETTERS.items() if parsed in letters]
        raise _refuse(f"{parsed} is {' or '.join(owners)}'s preload class, which has no table")
    geometry = getattr(bearing, "geometry", None)
    alpha = getattr(bearing, "contact_angle", None)
    name = "" if geometry is None else str(geometry.designation)
    m = re.match(r"^(7[0-9])(\d{2})", name)
    if m is None or alpha is None:
        what = f"the bearing {name}" if name else "a ring given by hand"
        raise _refuse(f"the class {parsed} needs a bearing of a table; {what} has none")
    row = _table().get((m.group(1), float(alpha), m.group(2)))
    if row is None:
        raise _refuse(f"the bearing {name} ({alpha:g}°) has no preload-class table")
    source = (
        f"preload class {parsed} of a {name} pair ({alpha:g}°), "
        f"{row.forces[parsed]:g} N as ground ({TABLE_MAKER}'s table, whichever maker's row "
        f"gives the ratings): {row.source}"
    )
    return Preload(row.forces[parsed], parsed, source)
