"""Parse bearing designations: ISO ``6306-2RS1/C3``, ``608``, ``61806``, ``NU206`` and GOST ``75-313``.

Accepted forms
--------------
* ISO 15 / maker designations of single-row deep groove ball bearings: ``6`` + diameter series
  (``0``, ``2``, ``3``, ``4``, ``8``, ``9``) + two-digit bore code, e.g. ``6306``; the
  series with a width-series digit, ``618xx``, ``619xx`` and ``160xx`` (``61806``,
  ``16005``; ``68xx`` and ``69xx`` are the old names of ``618xx`` and ``619xx``, and name
  the same catalogue rows); and bores below 10 mm, whose one-digit bore code *is* the bore in
  mm (ISO 15): ``608`` (d = 8), ``623`` (d = 3), ``6x`` + digit. All with
  optional suffixes: seals and shields (``-2RS``, ``2RS1``, ``-2Z``, ``ZZ``, ``LLU`` ...), the
  clearance class (``C2``, ``CN``, ``C3``, ``C4``, ``C5``, also ``C1``), the accuracy class
  (``P6``, ``P5`` ...), or both at once as SKF writes them (``P63`` = P6 + C3) [2]_.
  Separators ``-``, ``/`` and spaces are optional: ``6306-2RS1/C3``, ``6306 ZZ C3``,
  ``6306ZZC3``.
* Russian designations of GOST 8338-75, which drop the leading 6 of the ISO name [1]_:
  a three-digit number whose first digit is the diameter series ``2``, ``3`` or ``4``
  (``306`` = 6306). A five- or six-digit number is read with the layout of Russian basic
  designations [2]_ (design variant, type ``0`` = radial ball bearing, series, bore), e.g.
  ``180306``; the design variant is kept in :attr:`Designation.design_code` and not
  interpreted.
  An optional prefix before a dash carries, read from the dash leftwards, the accuracy class,
  the radial clearance group and the friction-moment row [2]_: ``75-313`` is accuracy class 5,
  clearance group 7 (= C3), bearing 313; ``6-208`` is accuracy class 6 with the normal group;
  ``0-306`` is class 0. GOST 24810-81 groups of these bearings: 6 = C2, none (or ``M``) = CN,
  7 = C3, 8 = C4, 9 = C5 [2]_.

* Single-row cylindrical roller bearings ``NU``, ``N``, ``NJ``, ``NUP`` + diameter series
  ``2`` or ``3`` + two-digit bore code, with suffixes (``NU206``, ``N 306 ECP/C3``); the
  four designs of one size share the rollers and are one catalogue row (``NU206``).

A three-digit ``6xx`` is ISO (a bore below 10 mm): GOST 8338 has no diameter series 6, so the
old reading of ``608`` as a GOST series was never right.
A four-digit ``6xxx`` is always read as ISO (in the Russian layout the digit 6 in that
place would mean a bearing type other than the radial ball bearing; the catalogues this
package uses never need that reading).
Bore code: 00 = 10, 01 = 12, 02 = 15, 03 = 17 mm, otherwise d = 5 x code.

References
----------
.. [1] Catalogue cross-references ISO <-> GOST (NSK / GOST 8338-75 tables, KINEX catalogue):
   306 = 6306, 208 = 6208, 405 = 6405.
.. [2] aprom.by, "Зазоры в подшипниках качения" (GOST designation scheme "category, friction
   moment, clearance group, accuracy - basic designation", example 75-313ЕШ2; GOST 24810 - ISO
   clearance equivalents; SKF P63 = P6 + C3), text copy in the BearingsInfo collection,
   section 1.3.

>>> d = parse("75-313")
>>> d.iso_name, d.bore, d.clearance_class, d.accuracy_class
('6313', 65.0, 'C3', '5')
>>> parse("6306-2RS1/C3").suffixes
('2RS1', 'C3')
"""

from __future__ import annotations

import re

from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass

#: Bore codes with a special bore diameter; every other code means d = 5 x code. [mm]
SPECIAL_BORES: dict[str, float] = {"00": 10.0, "01": 12.0, "02": 15.0, "03": 17.0}

#: GOST 24810-81 radial clearance groups of single-row radial ball bearings with a
#: cylindrical bore, as ISO classes ("M" marks the normal group when a friction row is given).
GOST_CLEARANCE_GROUPS: dict[str, str | None] = {
    "6": "C2",
    "7": "C3",
    "8": "C4",
    "9": "C5",
    "M": "CN",
    "H": None,  # non-standard clearance agreed with the customer
}

ACCEPTED_FORMS = (
    "ISO '6306', '6306-2RS', '6306-2Z/C3', '6306ZZC3' (series 60, 62, 63, 64, 68, 69), "
    "'61806', '61906', '16005', small bores '608', '623'; cylindrical roller 'NU206', 'N 306'; "
    "or GOST '306', '180306', '75-313', '6-208' (series 2xx, 3xx, 4xx)"
)

#: What bearingload models, named when it refuses a designation of another bearing type.
MODELLED = (
    "single-row deep groove ball bearings (ISO series 60, 62, 63, 64, 618, 619, 160 and bores "
    "below 10 mm; GOST 8338 2xx, 3xx, 4xx) and single-row cylindrical roller bearings (NU, N, "
    "NJ, NUP of the 2 and 3 series)"
)

#: Designations of bearing types that bearingload does not model, as the makers' catalogues
#: name them: (the characters such a designation can start with; pattern of the upper-case
#: designation, whose group ``series`` is the series; what the designation is, with
#: ``{series}``). Checked before the deep-groove and GOST forms: a tapered roller bearing 30205
#: would otherwise read as a GOST ball bearing 205 of design variant 3. The type digit of GOST
#: 3189 (the fourth from the right) is 2 for cylindrical, 7 for tapered roller bearings, 6 for
#: angular contact and 8 for thrust ball bearings. The patterns are texts compiled by re at
#: their first use, which a designation starting otherwise (a deep-groove 6306) does not reach.
_UNMODELLED: tuple[tuple[str, str, str], ...] = (
    (
        "3",
        r"^(?P<series>3(?:0[23]|13|2[0239]|3[012]))\d{2}(?!\d)",
        "a tapered roller bearing (series {series})",
    ),
    (
        "2",
        r"^(?P<series>2(?:2[23]|3[01289]|4[01]))\d{2}(?!\d)",
        "a spherical roller bearing (series {series})",
    ),
    ("1", r"^(?P<series>1[23])\d{2}(?!\d)", "a self-aligning ball bearing (series {series})"),
    (
        "2",
        r"^(?P<series>2[23])\d{2}(?!\d)",
        "a self-aligning ball bearing (series {series}; read as GOST 3189, type digit 2, a "
        "cylindrical roller bearing: give its ISO name, NU, N, NJ or NUP and the last three "
        "digits)",
    ),
    (
        "5",
        r"^(?P<series>5(?:1[1-4]|[234][2-4]))\d{2}(?!\d)",
        "a thrust ball bearing (series {series})",
    ),
    ("8", r"^(?P<series>8[1-5])\d{2}(?!\d)", "a thrust ball bearing (GOST 3189 type digit 8)"),
    (
        "28",
        r"^(?P<series>29[234]|81[12]|89[34])\d{2}(?!\d)",
        "a thrust roller bearing (series {series})",
    ),
    (
        "7",
        r"^(?P<series>7[0-4]|71[89])\d{2}\s*[-/]?\s*(?:AC|A|B|C|E)",
        "a single-row angular contact ball bearing (series {series})",
    ),
    (
        "7",
        r"^(?P<series>71[89])\d{2}(?!\d)",
        "a single-row angular contact ball bearing (series {series})",
    ),
    (
        "7",
        r"^(?P<series>7[0-5])\d{2}(?!\d)",
        "a single-row angular contact ball bearing (series {series}; read as GOST 3189, "
        "type digit 7, a tapered roller bearing)",
    ),
    (
        "34",
        r"^(?P<series>[34]6[1-4])\d{2}(?!\d)",
        "an angular contact ball bearing (GOST 3189 type digit 6)",
    ),
    (
        "RNHB",
        r"^(?P<series>RNA|NA|NKI[AB]?|NKS|NKX|NK|NX|HK|BK)\s*\d",
        "a needle roller bearing ({series})",
    ),
    ("Q", r"^(?P<series>QJF?)\s*\d", "a four-point contact ball bearing ({series})"),
    ("N", r"^(?P<series>NNU?)\s*\d", "a double-row cylindrical roller bearing ({series})"),
)

#: Old four-digit names of the 618 and 619 series (``6806`` = ``61806``).
OLD_SERIES_NAMES: dict[str, str] = {"68": "618", "69": "619"}

#: Cylindrical roller bearing types; all four share the rollers of one size.
ROLLER_TYPES: tuple[str, ...] = ("NUP", "NU", "NJ", "N")

# Cyrillic letters that look like Latin ones, folded so that both spellings parse.
_FOLD = str.maketrans("АВСЕНКМОРТХ", "ABCEHKMOPTX")

#: The forms read: (the characters such a designation can start with, "" any; pattern text),
#: compiled by re at their first use by :func:`_match`, which a designation that cannot match
#: does not reach (a GOST 306 compiles only :data:`_GOST`).
_ISO = ("6", r"^6(?P<series>[023489])(?P<bore>\d{2})(?P<rest>(?:[^0-9].*)?)$")
_ISO_WIDE = ("16", r"^(?P<series>61[89]|160)(?P<bore>\d{2})(?P<rest>(?:[^0-9].*)?)$")
_ISO_SMALL = ("6", r"^6(?P<series>[023489])(?P<bore>[1-9])(?P<rest>(?:[^0-9].*)?)$")
_ROLLER = (
    "N",
    r"^(?P<type>NUP|NU|NJ|N)\s*(?P<series>[23])(?P<bore>\d{2})(?P<rest>(?:[^0-9].*)?)$",
)
_GOST = (
    "",
    r"^(?:(?P<prefix>[^-\s]{1,6})\s*-\s*)?"
    r"(?:(?P<design>[1-9]\d?)0)?(?P<series>\d)(?P<bore>\d{2})"
    r"(?P<rest>(?:[^0-9].*)?)$",
)
#: Prefix and suffix patterns: texts compiled by re at their first use (a plain 306 has neither).
_PREFIX = (
    r"^(?P<category>\d?[ABC])?"
    r"(?:(?P<friction>\d)?(?P<clearance>[0-9MH]))?"
    r"(?P<accuracy>[0245678T])$"
)
_SUFFIX_TOKENS = (
    r"(?P<clearance>C[1-5N])(?![0-9])"
    r"|(?P<precision>P(?:6X|[0245-6]))(?P<pclr>[1-5])?(?![0-9])"
    r"|(?P<seal>2RS[1HR]?|RS[1HR]?|2RZ|RZ|2Z|ZZ|Z|2NSE|NSE|DDU|DD|LLU|LLB|LLH|LU|LB|VV|NR|N)"
)


def _match(form: tuple[str, str], text: str) -> re.Match[str] | None:
    """``re.match`` of a form's pattern (:data:`_ISO` ...; an entry of :data:`_UNMODELLED`)
    on ``text``, skipped (None) where ``text`` starts with none of the form's characters."""
    first, pattern = form
    if first and text[:1] not in first:
        return None
    return re.match(pattern, text)


@dataclass(frozen=True)
class Designation:
    """A parsed bearing designation.

    Attributes
    ----------
    text : str
        The designation as given (stripped).
    standard : str
        ``"ISO"`` or ``"GOST"``: the system the designation was written in.
    series : str
        ISO dimension-series code: ``"60"``, ``"62"``, ``"63"``, ``"64"``, ``"68"``, ``"69"``,
        ``"618"``, ``"619"``, ``"160"``; ``"NU2"``, ``"NU3"`` for cylindrical roller bearings.
    bore_code : str
        The two-digit bore code, e.g. ``"06"`` (one digit, the bore in mm, below 10 mm).
    bore : float
        Bore diameter d. [mm]
    iso_name : str
        Basic ISO designation, e.g. ``"6306"``.
    gost_name : str or None
        Basic GOST 8338 designation, e.g. ``"306"``; None for the 60, 68 and 69 series
        (their GOST names follow other rules, not implemented).
    suffixes : tuple of str
        Suffix tokens in order, normalised to upper case (``("2RS1", "C3")``).
    clearance_class : str or None
        ISO clearance class from a suffix or a GOST group (``"C3"``); None when the
        designation marks none, which by both standards means the normal class CN.
    clearance_group : str or None
        The GOST clearance group as marked in the prefix (``"7"``, ``"M"``, ``"H"``).
    accuracy_class : str or None
        Accuracy class as marked: GOST prefix digit (``"5"``) or ISO suffix (``"P5"``).
    design_code : str or None
        GOST design-variant digits of a five- or six-digit designation (``"18"`` in 180306).
    kind : str
        ``"ball"`` (deep groove ball bearing) or ``"roller"`` (cylindrical roller bearing).
    """

    text: str
    standard: str
    series: str
    bore_code: str
    bore: float
    iso_name: str
    gost_name: str | None
    suffixes: tuple[str, ...] = ()
    clearance_class: str | None = None
    clearance_group: str | None = None
    accuracy_class: str | None = None
    design_code: str | None = None
    kind: str = "ball"

    @property
    def base(self) -> str:
        """Basic designation in the system it was written in (``"306"`` or ``"6306"``)."""
        if self.standard == "GOST" and self.gost_name is not None:
            return self.gost_name
        return self.iso_name

    @property
    def catalogue_name(self) -> str:
        """Name of the catalogue row: :attr:`base`, with ``68xx``/``69xx`` read as
        ``618xx``/``619xx`` and every cylindrical roller type as ``NU`` (``N206`` -> ``NU206``).

        >>> parse("6806").catalogue_name, parse("NJ 206 ECP").catalogue_name
        ('61806', 'NU206')
        """
        if self.kind == "roller":
            return f"NU{self.series[-1]}{self.bore_code}"
        if self.standard == "ISO" and self.series in OLD_SERIES_NAMES and len(self.bore_code) == 2:
            return OLD_SERIES_NAMES[self.series] + self.bore_code  # 688 (one-digit bore) stays
        return self.base


def bore_from_code(code: str) -> float:
    """Bore diameter of a two-digit bore code.

    Parameters
    ----------
    code : str
        ``"00"`` ... ``"99"``.

    Returns
    -------
    float
        d [mm]: 00 = 10, 01 = 12, 02 = 15, 03 = 17, otherwise 5 x code.

    Examples
    --------
    >>> bore_from_code("03"), bore_from_code("06")
    (17.0, 30.0)
    """
    if not (len(code) == 2 and code.isdecimal()):  # what re's \d{2} matches
        raise InputError("bore_code", f"{code!r} is not a two-digit bore code")
    return SPECIAL_BORES.get(code, 5.0 * int(code))


class UnmodelledBearing(InputError):
    """A designation of a bearing type bearingload does not model (tapered or spherical roller,
    self-aligning, angular contact, thrust, needle ...): no geometry given by hand helps."""


def _refuse_unmodelled(raw: str, norm: str) -> None:
    """Raise :class:`UnmodelledBearing` when ``norm`` (with or without a GOST prefix such as
    ``6-``) names a bearing type of :data:`_UNMODELLED`."""
    bodies = [norm]
    m = re.match(r"^([^-\s]{1,6})\s*-\s*(\S.*)$", norm) if "-" in norm else None
    if m and re.match(_PREFIX, m.group(1)):
        bodies.append(m.group(2))
    for body in bodies:
        for first, pattern, what in _UNMODELLED:
            hit = _match((first, pattern), body)
            if hit:
                raise UnmodelledBearing(
                    "bearing",
                    f"{raw!r} is {what.format(series=hit.group('series'))}, which bearingload "
                    f"does not model; it models {MODELLED}",
                )


def _error(text: str, why: str = "") -> InputError:
    reason = f" ({why})" if why else ""
    return InputError(
        "bearing",
        f"cannot read {text!r} as a bearing designation{reason}",
        way_out=f"accepted: {ACCEPTED_FORMS}",
    )


def _parse_suffixes(text: str, rest: str) -> tuple[tuple[str, ...], str | None, str | None]:
    """Split the suffix part into tokens; return (tokens, clearance class, accuracy class)."""
    if not rest:
        return (), None, None
    if re.search(r"[^\w\s/-]|_", rest):
        raise _error(text, f"unexpected character in the suffix {rest.strip()!r}")
    tokens: list[str] = []
    clearances: list[str] = []
    accuracies: list[str] = []
    for chunk in re.split(r"[-/\s]+", rest.strip(" -/")):
        pos = 0
        while pos < len(chunk):
            m = re.compile(_SUFFIX_TOKENS).match(chunk, pos)
            if m is None:
                # An unknown token runs to the end of the chunk, except a trailing clearance
                # code glued to it ("TN9C3").
                tail = re.search(r"C[1-5N]$", chunk[pos:])
                end = len(chunk) - (2 if tail and len(chunk) - pos > 2 else 0)
                tokens.append(chunk[pos:end])
                pos = end
                continue
            tokens.append(m.group(0))
            if m.group("clearance"):
                clearances.append(m.group("clearance"))
            if m.group("precision"):
                accuracies.append(m.group("precision"))
                if m.group("pclr"):
                    clearances.append("C" + m.group("pclr"))
            pos = m.end()
    if len(set(clearances)) > 1:
        raise _error(text, f"two clearance classes {', '.join(clearances)}")
    if len(set(accuracies)) > 1:
        raise _error(text, f"two accuracy classes {', '.join(accuracies)}")
    return (
        tuple(t for t in tokens if t),
        clearances[0] if clearances else None,
        accuracies[0] if accuracies else None,
    )


def parse(text: str) -> Designation:
    """Parse a deep groove ball bearing designation.

    Parameters
    ----------
    text : str
        ISO (``6306``, ``6306-2RS1/C3``) or GOST (``306``, ``75-313``, ``180306``)
        designation; case does not matter, Cyrillic and Latin look-alike letters are equal.

    Returns
    -------
    Designation

    Raises
    ------
    InputError
        (parameter ``bearing``) when the text is not one of the accepted forms, names an
        unsupported series, or marks two different clearance or accuracy classes;
        :class:`UnmodelledBearing` when it names a bearing type the package does not model
        (``30205`` tapered roller, ``22205`` spherical roller, ``1205`` self-aligning ball,
        ``51205`` thrust, ``7205B`` angular contact, ``NA4905`` needle ...).

    Examples
    --------
    >>> d = parse("306")
    >>> d.standard, d.iso_name, d.gost_name, d.bore, d.clearance_class
    ('GOST', '6306', '306', 30.0, None)
    >>> parse("6208 ZZ C3").clearance_class
    'C3'
    """
    raw = str(text).strip()
    norm = raw.upper().translate(_FOLD)
    if not norm:
        raise _error(raw, "empty")
    _refuse_unmodelled(raw, norm)
    other = _parse_other_iso(raw, norm)
    if other is not None:
        return other
    m = _match(_ISO, norm)
    if m:
        suffixes, clr, acc = _parse_suffixes(raw, m.group("rest"))
        series, code = m.group("series"), m.group("bore")
        return Designation(
            text=raw,
            standard="ISO",
            series="6" + series,
            bore_code=code,
            bore=bore_from_code(code),
            iso_name=f"6{series}{code}",
            gost_name=f"{series}{code}" if series in "234" else None,
            suffixes=suffixes,
            clearance_class=clr,
            accuracy_class=acc,
        )
    m = _match(_GOST, norm)
    if m is None:
        raise _error(raw)
    series, code = m.group("series"), m.group("bore")
    if series not in "234":
        raise _error(raw, f"GOST diameter series {series} is not supported, only 2, 3, 4")
    suffixes, clr, acc = _parse_suffixes(raw, m.group("rest"))
    group = None
    prefix = m.group("prefix")
    if prefix is not None:
        p = re.match(_PREFIX, prefix)
        if p is None:
            raise _error(raw, f"prefix {prefix!r} is not '[friction][clearance group]accuracy'")
        group = p.group("clearance")
        if group is not None:
            if group not in GOST_CLEARANCE_GROUPS:
                raise _error(
                    raw,
                    f"clearance group {group} is not a group of single-row radial ball "
                    "bearings with cylindrical bore (6, 7, 8, 9; M or none = normal; H)",
                )
            from_group = GOST_CLEARANCE_GROUPS[group]
            if clr is not None and from_group is not None and clr != from_group:
                raise _error(raw, f"group {group} (= {from_group}) contradicts suffix {clr}")
            clr = clr or from_group
        if acc is not None:
            raise _error(raw, f"accuracy class given twice ({p.group('accuracy')} and {acc})")
        acc = p.group("accuracy")
    return Designation(
        text=raw,
        standard="GOST",
        series="6" + series,
        bore_code=code,
        bore=bore_from_code(code),
        iso_name=f"6{series}{code}",
        gost_name=f"{series}{code}",
        suffixes=suffixes,
        clearance_class=clr,
        clearance_group=group,
        accuracy_class=acc,
        design_code=m.group("design"),
    )


def _parse_other_iso(raw: str, norm: str) -> Designation | None:
    """The 618/619/160 series, bores below 10 mm and cylindrical roller bearings; else None."""
    m = _match(_ROLLER, norm)
    if m:
        series, code = m.group("series"), m.group("bore")
        name = f"{m.group('type')}{series}{code}"
        suffixes, clr, acc = _parse_suffixes(raw, m.group("rest"))
        return Designation(
            text=raw,
            standard="ISO",
            series=f"NU{series}",
            bore_code=code,
            bore=bore_from_code(code),
            iso_name=name,
            gost_name=None,
            suffixes=suffixes,
            clearance_class=clr,
            accuracy_class=acc,
            kind="roller",
        )
    for pattern, small in ((_ISO_WIDE, False), (_ISO_SMALL, True)):
        m = _match(pattern, norm)
        if m:
            series, code = m.group("series"), m.group("bore")
            suffixes, clr, acc = _parse_suffixes(raw, m.group("rest"))
            return Designation(
                text=raw,
                standard="ISO",
                series="6" + series if small else series,
                bore_code=code,
                bore=float(code) if small else bore_from_code(code),
                iso_name=f"6{series}{code}" if small else f"{series}{code}",
                gost_name=None,
                suffixes=suffixes,
                clearance_class=clr,
                accuracy_class=acc,
            )
    return None


def contact_exponent(text: str | None, default: float = 1.5) -> float:
    """The load-deflection exponent m a designation implies: 10/9 for a cylindrical roller
    bearing (line contact), else ``default`` (also for no or an unreadable designation, whose
    own error comes where it is resolved). [-]

    >>> round(contact_exponent("NU206"), 4), contact_exponent("6306"), contact_exponent(None)
    (1.1111, 1.5, 1.5)
    """
    if text is None or not text.strip():
        return default
    try:
        kind = parse(text.strip()).kind
    except InputError:
        return default
    from bearingload.constants import ROLLER_EXPONENT

    return ROLLER_EXPONENT if kind == "roller" else default
