"""Designations and catalogue rows of single-row angular-contact ball bearings.

Designations read (the contact angle from the suffix or the GOST type):

* ISO/maker form ``79xx``, ``70xx``, ``72xx``, ``73xx`` with a contact-angle suffix: ``C``
  15°, ``A5`` and ``AC`` 25°, ``A`` 30°, ``B`` 40° (NSK's angular-contact section: "a contact
  angle of 30° (Symbol A) or 40° (Symbol B)", C 15°, A5 25°; SKF's AC 25° and B 40°, SKF's older
  A 30° as a maker's page restates SKF's text). Maker suffixes after the letter (``7205 BEP``,
  ``7205BECBP``, ``7205-B-TVP``, ``7205ACD``) are read past, but a matched pair or set
  (``7205BDB``, ``7205B/DF``, ``7205BDT``) is refused. A plain ``7205`` is not read:
  Nachi's plain 72xx is 30°, while GOST 3189 reads 7205 as a tapered roller bearing.
* GOST 831-75 types ``36xxx`` (12°), ``46xxx`` (26°), ``66xxx`` (36°), e.g. ``46205``
  (GOST 831-75, clause 2, as restated at ajdocs.ru/gsp/49821/2; the K, K6, K7 variants are not
  read).

Rows: ``data/angular_contact.csv``, each with its source (NSK's and Koyo's ISO-form rows, the
79 series NSK's only; EPK's GOST 36xxx/46xxx/66xxx rows, General Catalogue 2011); a designation
of one of these types without a row is refused, naming the rows there are (:func:`find_angular`).
"""

from __future__ import annotations

import re
from functools import lru_cache

from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass

#: ISO/maker contact-angle suffixes and the nominal angle each stands for. [°]
ISO_SUFFIX_ANGLES: dict[str, float] = {"C": 15.0, "A5": 25.0, "AC": 25.0, "A": 30.0, "B": 40.0}
#: The letter of a catalogue row's name where two letters name one angle: SKF's AC and NSK's A5
#: are both 25°, and the 25° rows (NSK's) are named with A5 (``7205AC`` finds ``7205A5``).
ROW_LETTERS: dict[str, str] = {"AC": "A5"}
#: GOST 831-75 design digit (before the type digit 6) and the nominal angle. [°]
GOST_TYPE_ANGLES: dict[str, float] = {"3": 12.0, "4": 26.0, "6": 36.0}

#: The forms read, as pattern texts compiled at their first use by :func:`_match`, which a text
#: that cannot match (a deep-groove ``306``) does not reach: ISO ``7205B``, its series first.
_ISO = (
    r"^(?P<series>7[0239])(?P<bore>\d{2})\s*[-/]?\s*(?P<letter>A5|AC|A|B|C)(?P<rest>(?:[^0-9].*)?)$"
)
#: A matched pair or set after the contact-angle letter (NSK's 7205BDB, 7205BDF, 7205BDT; the
#: /DB form), with the preload class the pair is sold at where one follows: NSK's EL, L, M, H
#: (7205CDBL), SKF's A ... D (7205ACDBA), FAG's UL; an accuracy class may follow (DBLP4).
#: (These two are pattern texts, compiled by re at their first use: a plain bearing needs neither.)
_PAIR = r"D[BFT](?:[\s/-]?(?P<cls>EL|UL|[LMHA-D])(?=$|[^A-Z]|P\d))?(?=$|[^A-Z]|P\d)"
#: DB, DF, DT followed by letters not read: a set, not one bearing.
_PAIR_LIKE = r"D[BFT][A-Z]+"
#: GOST 831 ``46205``: the type digit 6 fourth from the end.
_GOST = r"^(?:[^-\s]{1,6}\s*-\s*)?(?P<design>[346])6(?P<series>[1-4])(?P<bore>\d{2})$"


def _match(pattern: str, norm: str) -> re.Match[str] | None:
    """``re.match(pattern, norm)`` for the patterns above, skipped (None) where the text cannot
    match: an ISO form starts with 7, a GOST form has the type digit 6 fourth from its end."""
    if pattern is _ISO and not norm.startswith("7"):
        return None
    if pattern is _GOST and norm[-4:-3] != "6":
        return None
    return re.match(pattern, norm)


@dataclass(frozen=True)
class AngularDesignation:
    """A parsed angular-contact designation.

    Attributes
    ----------
    text : str
        As given (stripped).
    name : str
        The catalogue name: ``7205B`` (series, bore code, contact-angle letter), ``46205``.
    standard : str
        ``"ISO"`` or ``"GOST"``.
    series : str
        ``"79"``, ``"70"``, ``"72"``, ``"73"``; GOST: the series digit.
    bore_code : str
        Two digits.
    bore : float
        d. [mm]
    contact_angle : float
        Nominal contact angle. [°]
    what : str
        The type in words, for messages.
    """

    text: str
    name: str
    standard: str
    series: str
    bore_code: str
    bore: float
    contact_angle: float
    what: str


def parse_angular(text: str) -> AngularDesignation | None:
    """The angular-contact designation ``text``, or None when it is not one of the forms read.

    >>> d = parse_angular("7205 BEP")
    >>> d.name, d.contact_angle, d.bore
    ('7205B', 40.0, 25.0)
    >>> parse_angular("46205").contact_angle, parse_angular("6205") is None
    (26.0, True)
    """
    from bearingload.bearings.designation import bore_from_code

    raw = text.strip()
    norm = " ".join(raw.upper().split())  # whitespace runs as one space, as re's \s+
    m = _match(_ISO, norm)
    if m:
        letter = m.group("letter")
        alpha = ISO_SUFFIX_ANGLES[letter]
        what = (f"a single-row angular contact ball bearing (series {m.group('series')}, "
                f"suffix {letter}: {alpha:g}°)")  # fmt: skip
        bore, row_letter = m.group("bore"), ROW_LETTERS.get(letter, letter)
        return AngularDesignation(raw, f"{m.group('series')}{bore}{row_letter}", "ISO",
                                  m.group("series"), bore, bore_from_code(bore), alpha, what)  # fmt: skip
    m = _match(_GOST, norm)
    if m:
        design, series, bore = m.group("design"), m.group("series"), m.group("bore")
        alpha = GOST_TYPE_ANGLES[design]
        name = f"{design}6{series}{bore}"
        what = f"a single-row angular contact ball bearing (GOST 831 type {design}6000: {alpha:g}°)"
        return AngularDesignation(raw, name, "GOST", series, bore, bore_from_code(bore), alpha,
                                  what)  # fmt: skip
    return None


#: A GOST 831 angular-contact designation followed by a suffix that is not read (EPK's K, K6,
#: K7 variants, a pair suffix DB/DF/DT, a seal): the type is modelled, the suffix is not.
_GOST_SUFFIXED = (
    r"^(?P<body>(?:[^-\s]{1,6}\s*-\s*)?(?P<name>[346]6[1-4]\d{2}))\s*[-/]?\s*(?P<rest>[A-Z].*)$"
)


def refuse_gost_suffix(text: str) -> None:
    """Refuse a GOST 831 angular-contact designation with a suffix that is not read
    (``36205K``, ``46305DF``, ``66211K``), naming the plain designation: the type is modelled,
    so the deep-groove parser's 'a type bearingload does not model' would be false.

    >>> refuse_gost_suffix("36205")  # no suffix: nothing to refuse
    """
    norm = " ".join(text.upper().split())
    m = re.match(_GOST_SUFFIXED, norm) if len(norm) > 5 else None  # 5 digits and a suffix
    if m is None:
        return
    rest, name = m.group("rest").strip(), m.group("name")
    if re.match(_PAIR, rest) or re.match(_PAIR_LIKE, rest):
        why = (
            f"the matched-pair suffix {rest} is read on the ISO form only (7205BDB); give "
            f"{name} with the arrangement {rest[:2]} and its preload force"
        )
    else:
        why = (
            f"the suffix {rest} is not read (GOST 831's K, K6 and K7 variants print other "
            f"ratings); give {name} for the plain type's row, or the ring by hand with its "
            "contact angle"
        )
    raise InputError(
        "bearing",
        f"{text.strip()!r} is a single-row angular contact ball bearing (GOST 831 type "
        f"{name[0]}6000: {GOST_TYPE_ANGLES[name[0]]:g}°): {why}",
    )


def split_pair(text: str) -> tuple[str, str | None, str | None]:
    """``text`` without the suffix of a matched pair (``7205BDB`` -> ``7205B``, "DB"), the
    arrangement (None: no such suffix) and the preload class written after it (``7205CDBL``:
    "L"; None: none), which :func:`bearingload.bearings.preload.resolve_preload` reads.

    >>> split_pair("7205BDB"), split_pair("7205B/DF"), split_pair("7205 BEP")
    (('7205B', 'DB', None), ('7205B', 'DF', None), ('7205 BEP', None, None))
    >>> split_pair("7205CDBL"), split_pair("7008A5 DBEL P4")
    (('7205C', 'DB', 'L'), ('7008A5P4', 'DB', 'EL'))
    """
    norm = " ".join(text.upper().split())
    m = _match(_ISO, norm)
    found = re.search(_PAIR, m.group("rest")) if m else None
    if m is not None and found is None:
        _refuse_unread_set(text, m)
    if m is None or found is None:
        return text, None, None
    rest = m.group("rest")
    single = rest[: found.start()] + rest[found.end() :]
    name = f"{m.group('series')}{m.group('bore')}{m.group('letter')}{single.strip(' /-')}"
    return name, found.group(0)[:2], found.group("cls")


def _refuse_unread_set(text: str, m: re.Match[str]) -> None:
    """Refuse DB, DF or DT followed by letters that are not a preload class (NSK's ``DBL``, a
    light preload): a set, which read past as a maker's suffix would be solved as one bearing;
    and a radial clearance class (``7205B/C3``), which an angular-contact bearing has not."""
    clearance = re.search(r"C[2-5N](?![0-9])", m.group("rest"))
    if clearance is not None:  # a radial clearance class: a deep-groove bearing's suffix
        raise InputError(
            "bearing",
            f"{text.strip()!r}: the suffix {clearance.group(0)} is a radial clearance class, which "
            "a single-row angular-contact bearing does not have (it is solved at its contact "
            f"angle, without clearance): give {m.group('series')}{m.group('bore')}"
            f"{m.group('letter')}",
        )
    unread = re.search(_PAIR_LIKE, m.group("rest"))
    if unread is not None:
        raise InputError(
            "bearing",
            f"{text.strip()!r}: the suffix {unread.group(0)} is not read (a matched set is DB, "
            "DF or DT, with a preload class EL, L, M, H (A ... D, UL) at most): give the pair as "
            f"{m.group('series')}{m.group('bore')}{m.group('letter')}{unread.group(0)[:2]} "
            "with its preload force, or the single bearing without the suffix",
        )


@dataclass(frozen=True)
class AngularRow:
    """One row of ``data/angular_contact.csv`` (units: mm, N, °; ``f0`` the factor of
    C_0r = f0 z D_w^2 cos(alpha) where the maker prints it: Koyo's 15° rows)."""

    designation: str
    maker: str
    contact_angle: float
    d: float
    D: float
    B: float
    balls: int
    ball_diameter: float
    pitch_diameter: float
    C: float
    C0: float
    f0: float | None
    method: str
    confidence: str
    source: str
    notes: str
    #: Limiting speeds with grease and oil lubrication as the maker prints them (None: not
    #: read), and their source. [r/min]
    limiting_speed_grease: float | None = None
    limiting_speed_oil: float | None = None
    limiting_speed_source: str = ""


@lru_cache(maxsize=1)
def angular_rows() -> tuple[AngularRow, ...]:
    """Every angular-contact catalogue row, in file order."""
    from bearingload.bearings._data import read_rows

    return tuple(
        AngularRow(
            r["designation"],
            r["maker"],
            float(r["contact_angle"]),
            float(r["d"]),
            float(r["D"]),
            float(r["B"]),
            int(r["balls"]),
            float(r["ball_diameter"]),
            float(r["pitch_diameter"]),
            float(r["C"]),
            float(r["C0"]),
            float(r["f0"]) if r["f0"] else None,
            r["method"],
            r["confidence"],
            r["source"],
            r["notes"],
            float(r["limiting_speed_grease"]) if r["limiting_speed_grease"] else None,
            float(r["limiting_speed_oil"]) if r["limiting_speed_oil"] else None,
            r["limiting_speed_source"],
        )  # fmt: skip
        for r in read_rows("angular_contact.csv")
    )


#: The maker whose row is used when a designation has rows of several makers and none is named.
DEFAULT_ANGULAR_MAKER = "NSK"


def find_angular(parsed: AngularDesignation, maker: str | None = None) -> AngularRow:
    """The catalogue row of ``parsed``: ``maker``'s, else NSK's where NSK has one, else the
    one maker's with a row (Koyo's 15°, 30° and 40° rows, NSK's 40° BEA rows, EPK's GOST rows).

    Raises
    ------
    InputError
        (``bearing``) when there is no row: names the type and the rows of that contact angle
        and series there are; (``maker``) when ``maker`` has no row for it.
    """
    m = _match(_ISO, " ".join(parsed.text.upper().split()))
    if m and not re.search(_PAIR, m.group("rest")):
        _refuse_unread_set(parsed.text, m)
    if m and re.search(_PAIR, m.group("rest")):
        raise InputError(
            "bearing",
            f"{parsed.text!r} names a matched pair or set of {parsed.name} (suffix DB "
            f"back-to-back, DF face-to-face or DT tandem): 'solve {parsed.name}DB' solves the "
            f"pair; here give {parsed.name} with the load one bearing of the set carries",
        )
    rows = [r for r in angular_rows() if r.designation == parsed.name]
    if not rows:
        raise InputError("bearing", _no_row_message(parsed))
    if maker is not None:
        for row in rows:
            if row.maker == maker.strip().upper():
                return row
        makers = ", ".join(r.maker for r in rows)
        raise InputError(
            "maker", f"the angular-contact bearing {parsed.name} has rows of {makers} only"
        )
    return next((r for r in rows if r.maker == DEFAULT_ANGULAR_MAKER), rows[0])


def _no_row_message(parsed: AngularDesignation) -> str:
    """Why ``parsed`` has no row, with the rows of its contact angle and series there are."""
    # ISO: the rows of the series (79, 70, 72, 73) at the angle; GOST: of the type and series digit
    # (46205: the 462xx rows)
    width = 3 if parsed.standard == "GOST" else 2
    kin = sorted(
        {r.designation for r in angular_rows()
         if r.contact_angle == parsed.contact_angle and r.designation[:width] == parsed.name[:width]}
    )  # fmt: skip
    if not kin:
        near = f"there is no {parsed.contact_angle:g}° row of series {parsed.series}"
    else:
        near = f"the {parsed.contact_angle:g}° rows of series {parsed.series} are {', '.join(kin)}"
    return (
        f"{parsed.text!r} is {parsed.what}, which has no catalogue row (no public source read "
        f"for it, or its printed ratings fit no ball set); {near} (bearingload catalog --type "
        "angular lists every row), or give the ring by hand with its contact angle"
    )
