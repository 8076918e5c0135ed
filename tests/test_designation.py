"""Tests of bearingload.bearings.designation: ISO and GOST designations, prefixes, suffixes, errors."""

from __future__ import annotations

import dataclasses

import pytest

from bearingload.bearings.designation import Designation, bore_from_code, parse
from bearingload.errors import InputError

# text -> (standard, base, iso_name, gost_name, bore [mm], suffixes, clearance, group, accuracy)
CASES = {
    "306": ("GOST", "306", "6306", "306", 30.0, (), None, None, None),
    "6306": ("ISO", "6306", "6306", "306", 30.0, (), None, None, None),
    "208": ("GOST", "208", "6208", "208", 40.0, (), None, None, None),
    "6306-2RS": ("ISO", "6306", "6306", "306", 30.0, ("2RS",), None, None, None),
    "6306 2rs": ("ISO", "6306", "6306", "306", 30.0, ("2RS",), None, None, None),
    "6306-2Z": ("ISO", "6306", "6306", "306", 30.0, ("2Z",), None, None, None),
    "6306ZZ": ("ISO", "6306", "6306", "306", 30.0, ("ZZ",), None, None, None),
    "6306C3": ("ISO", "6306", "6306", "306", 30.0, ("C3",), "C3", None, None),
    "6306-C3": ("ISO", "6306", "6306", "306", 30.0, ("C3",), "C3", None, None),
    "6306-2RS1/C3": ("ISO", "6306", "6306", "306", 30.0, ("2RS1", "C3"), "C3", None, None),
    "6306 ZZ C4": ("ISO", "6306", "6306", "306", 30.0, ("ZZ", "C4"), "C4", None, None),
    "6208ZZC2": ("ISO", "6208", "6208", "208", 40.0, ("ZZ", "C2"), "C2", None, None),
    "6205-2RSH/C5": ("ISO", "6205", "6205", "205", 25.0, ("2RSH", "C5"), "C5", None, None),
    "6205/CN": ("ISO", "6205", "6205", "205", 25.0, ("CN",), "CN", None, None),
    "6306/P63": ("ISO", "6306", "6306", "306", 30.0, ("P63",), "C3", None, "P6"),
    "6306-TN9C3": ("ISO", "6306", "6306", "306", 30.0, ("TN9", "C3"), "C3", None, None),
    "6000": ("ISO", "6000", "6000", None, 10.0, (), None, None, None),
    "6001": ("ISO", "6001", "6001", None, 12.0, (), None, None, None),
    "6202": ("ISO", "6202", "6202", "202", 15.0, (), None, None, None),
    "6303": ("ISO", "6303", "6303", "303", 17.0, (), None, None, None),
    "6416": ("ISO", "6416", "6416", "416", 80.0, (), None, None, None),
    "6807": ("ISO", "6807", "6807", None, 35.0, (), None, None, None),
    # GOST prefixes: read leftwards from the dash, accuracy class then clearance group
    # (aprom.by text, example 75-313ЕШ2: group 7, class 5, bearing 313).
    "75-313": ("GOST", "313", "6313", "313", 65.0, (), "C3", "7", "5"),
    "75-313ЕШ2": ("GOST", "313", "6313", "313", 65.0, ("EШ2",), "C3", "7", "5"),
    "6-208": ("GOST", "208", "6208", "208", 40.0, (), None, None, "6"),
    "60-208": ("GOST", "208", "6208", "208", 40.0, (), "C2", "6", "0"),
    "0-306": ("GOST", "306", "6306", "306", 30.0, (), None, None, "0"),
    "80-306": ("GOST", "306", "6306", "306", 30.0, (), "C4", "8", "0"),
    "96-310": ("GOST", "310", "6310", "310", 50.0, (), "C5", "9", "6"),
    "2М5-208": ("GOST", "208", "6208", "208", 40.0, (), "CN", "M", "5"),
    "Н0-306": ("GOST", "306", "6306", "306", 30.0, (), None, "H", "0"),
    "306-C3": ("GOST", "306", "6306", "306", 30.0, ("C3",), "C3", None, None),
    "405": ("GOST", "405", "6405", "405", 25.0, (), None, None, None),
    # ISO 15: bores below 10 mm carry the bore itself as a one-digit code (608: d = 8 mm)
    "608": ("ISO", "608", "608", None, 8.0, (), None, None, None),
    "608-2RS": ("ISO", "608", "608", None, 8.0, ("2RS",), None, None, None),
    "623ZZ/C3": ("ISO", "623", "623", None, 3.0, ("ZZ", "C3"), "C3", None, None),
    "629": ("ISO", "629", "629", None, 9.0, (), None, None, None),
    "61806": ("ISO", "61806", "61806", None, 30.0, (), None, None, None),
    "61900-2RS": ("ISO", "61900", "61900", None, 10.0, ("2RS",), None, None, None),
    "16005": ("ISO", "16005", "16005", None, 25.0, (), None, None, None),
    "NU206": ("ISO", "NU206", "NU206", None, 30.0, (), None, None, None),
    "N 306 ECP/C3": ("ISO", "N306", "N306", None, 30.0, ("ECP", "C3"), "C3", None, None),
}


@pytest.mark.parametrize("text", sorted(CASES))
def test_parse_table(text: str) -> None:
    std, base, iso, gost, bore, suffixes, clr, group, acc = CASES[text]
    d = parse(text)
    assert isinstance(d, Designation)
    assert d.text == text
    assert (d.standard, d.base, d.iso_name, d.gost_name) == (std, base, iso, gost)
    assert d.bore == bore
    assert d.suffixes == suffixes
    assert (d.clearance_class, d.clearance_group, d.accuracy_class) == (clr, group, acc)


def test_series_and_bore_code() -> None:
    d = parse("6313-2Z")
    assert (d.series, d.bore_code) == ("63", "13")
    assert parse("213").series == "62"
    assert parse("6004").series == "60"


def test_gost_long_form_keeps_design_code() -> None:
    # GOST 3189 layout: design variant, type 0 (radial ball), series, bore.
    d = parse("180306")
    assert (d.standard, d.base, d.iso_name, d.design_code) == ("GOST", "306", "6306", "18")
    assert parse("80306").design_code == "8"
    assert parse("306").design_code is None


@pytest.mark.parametrize(("cyrillic", "latin"), [("2М5-208", "2M5-208"), ("Н0-306", "H0-306")])
def test_cyrillic_and_latin_prefix_letters_are_equal(cyrillic: str, latin: str) -> None:
    assert "М" in cyrillic or "Н" in cyrillic  # really Cyrillic
    assert dataclasses.replace(parse(cyrillic), text="") == dataclasses.replace(
        parse(latin), text=""
    )


@pytest.mark.parametrize(
    ("code", "bore"),
    [("00", 10.0), ("01", 12.0), ("02", 15.0), ("03", 17.0), ("04", 20.0), ("06", 30.0)]
    + [("20", 100.0), ("96", 480.0)],
)
def test_bore_code(code: str, bore: float) -> None:
    assert bore_from_code(code) == bore


@pytest.mark.parametrize("code", ["6", "abc", "123", "", "6²", " 06"])
def test_bore_code_rejects(code: str) -> None:
    with pytest.raises(InputError, match="bore_code"):
        bore_from_code(code)


@pytest.mark.parametrize(
    ("text", "why"),
    [
        ("", "empty"),
        ("   ", "empty"),
        ("abc", "accepted: ISO"),
        ("30", "accepted: ISO"),
        ("63060", "accepted: ISO"),
        ("6506", "accepted: ISO"),
        ("106", "series 1 is not supported"),
        ("6306.2RS", "unexpected character"),
        ("6306_2RS", "unexpected character"),
        ("6306-C3C4", "two clearance classes"),
        ("6306/P6P5", "two accuracy classes"),
        ("75-313/C4", "contradicts suffix C4"),
        ("3-313", "prefix '3'"),
        ("25-313", "clearance group 2 is not a group"),
        ("5-313/P5", "accuracy class given twice"),
        ("6-6306", "accepted: ISO"),
    ],
)
def test_parse_errors(text: str, why: str) -> None:
    with pytest.raises(InputError, match="bearing") as info:
        parse(text)
    assert info.value.parameter == "bearing"
    assert why in str(info.value)
    assert "accepted: ISO '6306'" in str(info.value)


def test_error_is_a_value_error() -> None:
    with pytest.raises(ValueError):
        parse("not a bearing")


def test_consistent_suffix_and_group_is_accepted() -> None:
    assert parse("75-313/C3").clearance_class == "C3"


@pytest.mark.parametrize(
    ("text", "series", "kind", "catalogue_name"),
    [
        ("608", "60", "ball", "608"),
        ("623", "62", "ball", "623"),
        ("61806", "618", "ball", "61806"),
        ("6806", "68", "ball", "61806"),
        ("6906-2RS", "69", "ball", "61906"),
        ("16005", "160", "ball", "16005"),
        ("6306", "63", "ball", "6306"),
        ("306", "63", "ball", "306"),
        ("NU206", "NU2", "roller", "NU206"),
        ("NJ 312 ECP", "NU3", "roller", "NU312"),
        ("NUP206", "NU2", "roller", "NU206"),
    ],
)
def test_kind_series_and_catalogue_name(
    text: str, series: str, kind: str, catalogue_name: str
) -> None:
    d = parse(text)
    assert (d.series, d.kind, d.catalogue_name) == (series, kind, catalogue_name)


@pytest.mark.parametrize("text", ["610", "NU406", "NU2205", "N2", "1600", "6180"])
def test_new_forms_reject(text: str) -> None:
    with pytest.raises(InputError, match="accepted: ISO"):
        parse(text)


#: Designations of bearing types the package does not model (makers' catalogue names), and the
#: type the refusal must name; 30205 and 30305 used to read as GOST ball bearings 205 and 305.
UNMODELLED = {
    "30205": "tapered roller bearing (series 302)",
    "30305": "tapered roller bearing (series 303)",
    "31305 J2": "tapered roller bearing (series 313)",
    "32005 X": "tapered roller bearing (series 320)",
    "32205": "tapered roller bearing (series 322)",
    "32305": "tapered roller bearing (series 323)",
    "32905": "tapered roller bearing (series 329)",
    "33005": "tapered roller bearing (series 330)",
    "33105": "tapered roller bearing (series 331)",
    "33205": "tapered roller bearing (series 332)",
    "22205 E": "spherical roller bearing (series 222)",
    "22308 EK": "spherical roller bearing (series 223)",
    "23005": "spherical roller bearing (series 230)",
    "23105": "spherical roller bearing (series 231)",
    "23205": "spherical roller bearing (series 232)",
    "23905": "spherical roller bearing (series 239)",
    "24005": "spherical roller bearing (series 240)",
    "24105": "spherical roller bearing (series 241)",
    "1205": "self-aligning ball bearing (series 12)",
    "1305 ETN9": "self-aligning ball bearing (series 13)",
    "2205": "self-aligning ball bearing (series 22",
    "2305-2RS": "self-aligning ball bearing (series 23",
    "51105": "thrust ball bearing (series 511)",
    "51205": "thrust ball bearing (series 512)",
    "51305": "thrust ball bearing (series 513)",
    "51405": "thrust ball bearing (series 514)",
    "52205": "thrust ball bearing (series 522)",
    "53205": "thrust ball bearing (series 532)",
    "29412 E": "thrust roller bearing (series 294)",
    "81212": "thrust roller bearing (series 812)",
    "NA4905": "needle roller bearing (NA)",
    "NK20/16": "needle roller bearing (NK)",
    "HK1516": "needle roller bearing (HK)",
    "NKI 20/16": "needle roller bearing (NKI)",
    "7205B": "angular contact ball bearing (series 72)",
    "7305 BEP": "angular contact ball bearing (series 73)",
    "7005C": "angular contact ball bearing (series 70)",
    "7206AC": "angular contact ball bearing (series 72)",
    "71905 CD/P4A": "angular contact ball bearing (series 719)",
    "7205": "angular contact ball bearing (series 72; read as GOST 3189, type digit 7, a tapered",
    "36205": "angular contact ball bearing (GOST 3189 type digit 6)",
    "8205": "thrust ball bearing (GOST 3189 type digit 8)",
    "QJ 206": "four-point contact ball bearing (QJ)",
    "NN3006": "double-row cylindrical roller bearing (NN)",
    "6-30205": "tapered roller bearing (series 302)",
}


@pytest.mark.parametrize("text", sorted(UNMODELLED))
def test_unmodelled_types_are_named_and_refused(text: str) -> None:
    from bearingload.bearings.designation import MODELLED, UnmodelledBearing

    with pytest.raises(UnmodelledBearing) as info:
        parse(text)
    assert info.value.parameter == "bearing"
    message = str(info.value)
    assert f"{text!r} is " in message and UNMODELLED[text] in message
    assert message.endswith(f"which bearingload does not model; it models {MODELLED}")


def test_a_pattern_is_skipped_only_for_a_designation_it_cannot_match() -> None:
    """Each form (and unmodelled type) lists the characters a designation it matches starts
    with; a designation starting otherwise skips its pattern. No designation of these tests,
    nor any with its first character replaced by another digit or letter, is matched by a
    pattern beside characters that do not include its first one."""
    import re

    from bearingload.bearings import designation as d

    forms = [d._ISO, d._ISO_WIDE, d._ISO_SMALL, d._ROLLER, d._GOST]
    forms += [(first, pattern) for first, pattern, _ in d._UNMODELLED]
    texts = {t.upper() for t in [*CASES, *UNMODELLED, "608", "61806", "16005", "NUP 306"]}
    tried = {c + t[1:] for t in texts for c in "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ"}
    for first, pattern in forms:
        hits = [t for t in tried if re.match(pattern, t)]
        assert hits, pattern  # every pattern is tried on designations it matches
        assert [t for t in hits if first and t[0] not in first] == [], pattern


def test_the_refusal_keeps_every_form_the_catalogue_accepts() -> None:
    """Every catalogue and roller row still parses (the refusal runs before every form), and
    the GOST long forms with a design variant stay ball bearings."""
    from bearingload.bearings.catalog import entries
    from bearingload.bearings.rollers import entries as roller_entries

    for name in [r.designation for r in entries()] + [r.designation for r in roller_entries()]:
        assert parse(name).base == name
    for text in ("180306", "80306", "60205", "50205", "160306", "6-208", "75-313", "306"):
        assert parse(text).kind == "ball" and parse(text).standard == "GOST"
