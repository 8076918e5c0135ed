"""Tests of bearingload.bearings.catalog: row consistency, the papers' bearings, lookup and overrides."""

from __future__ import annotations

import csv
import json
import math
from importlib import resources

import pytest

from bearingload.bearings.catalog import (
    DEFAULT_F_I,
    DEFAULT_F_O,
    BearingGeometry,
    _counterpart,
    check_geometry,
    entries,
    find,
    lookup,
)
from bearingload.bearings.designation import parse
from bearingload.errors import InputError
from bearingload.units import KGF

from .cli_helpers import invoke

ROWS = entries()
WITH_GEOMETRY = [r for r in ROWS if r.has_geometry]
#: Designations of data/bearings.csv (GOST 8338 rows, NSK 60/62/63 to 6317, FBJ 64xx); the
#: other ISO rows (618, 619, 160 series, 6318-6320) come from data/ball_sets.csv alone.
TABLE_ROWS = {
    (r["standard"], r["designation"])
    for r in csv.DictReader(
        resources.files("bearingload.bearings")
        .joinpath("data/bearings.csv")
        .read_text(encoding="utf-8")
        .splitlines()
    )
}


def _id(row: BearingGeometry) -> str:
    return f"{row.standard}-{row.designation}"


def test_catalogue_size_and_standards() -> None:
    assert len([r for r in ROWS if r.standard == "GOST"]) == 26
    # 74 of bearings.csv + 40 of bores below 10 mm (NSK's miniature tables) + 65
    assert len([r for r in ROWS if r.standard == "ISO"]) == 179
    assert len(TABLE_ROWS) == 140
    assert len(WITH_GEOMETRY) >= 50
    names = [(r.standard, r.designation) for r in ROWS]
    assert len(names) == len(set(names))


@pytest.mark.parametrize("name", ["ball_sets.csv", "rollers.csv"])
def test_new_csv_files_are_plain(name: str) -> None:
    raw = resources.files("bearingload.bearings").joinpath(f"data/{name}").read_bytes()
    assert b"\r" not in raw and raw.endswith(b"\n")
    rows = list(csv.reader(raw.decode("utf-8").splitlines()))
    assert all(len(r) == len(rows[0]) for r in rows)
    assert rows[0][-2:] == ["source", "notes"]


@pytest.mark.parametrize(
    "name", ["bearings.csv", "ball_sets.csv", "angular_contact.csv", "rollers.csv"]
)
def test_reading_the_rows_of_one_designation_reads_what_the_whole_file_holds(name: str) -> None:
    """read_rows(name, first) parses only the lines that may start with ``first``: it gives the
    rows of the whole file whose first cell is ``first``, in file order, for every first cell
    there is and one there is not; that holds because no cell of the data files holds a line
    break (one row per line after the header)."""
    from bearingload.bearings._data import _DIR, read_rows

    rows = read_rows(name)
    with open(f"{_DIR}/{name}", encoding="utf-8", newline="") as handle:
        assert len(rows) + 1 == len(handle.read().splitlines())  # no line break in a cell
    column = next(iter(rows[0]))
    for first in [*dict.fromkeys(r[column] for r in rows), "9999"]:
        assert read_rows(name, first) == [r for r in rows if r[column] == first], first


def test_new_series_filters() -> None:
    # 618 and 619: 21 each of two-digit bore codes, 9 each of one-digit bores (681 ... 699)
    assert [len(entries(series=s)) for s in ("618", "68", "619", "69xx", "160")] == [
        30,
        30,
        30,
        30,
        20,
    ]
    assert entries(series="63", bore=100)[0].designation == "6320"
    with pytest.raises(InputError, match="allowed: 60, 62, 63, 64, 618, 619, 160"):
        entries(series="617")


def test_csv_is_plain() -> None:
    raw = resources.files("bearingload.bearings").joinpath("data/bearings.csv").read_bytes()
    assert b"\r" not in raw
    assert raw.endswith(b"\n")
    assert raw.splitlines()[0] == (
        b"designation,standard,d,D,B,ball_diameter,balls,pitch_diameter,C,C0,f0,f_i,f_o,"
        b"source,notes,limiting_speed_grease,limiting_speed_oil,limiting_speed_source"
    )


@pytest.mark.parametrize("row", ROWS, ids=_id)
def test_row_consistency(row: BearingGeometry) -> None:
    parsed = parse(row.designation)
    assert parsed.standard == row.standard
    assert parsed.base == row.designation
    assert parsed.bore == row.d  # bore code agrees with the tabulated bore
    assert 0 < row.d < row.D
    if (row.standard, row.designation) in TABLE_ROWS:
        assert row.B is not None and 0 < row.B < row.D - row.d
    else:
        assert row.B is None  # the sources of ball_sets.csv give no width
    if row.has_geometry or (row.standard, row.designation) in TABLE_ROWS:
        assert row.C is not None and row.C0 is not None
    if (row.standard, row.designation) in TABLE_ROWS:
        assert row.C is not None and row.C0 is not None
        assert 0 < row.C0 < row.C  # ball bearings of bearings.csv: C0 below C in every source
    else:  # NSK 618xx: C0 reaches 1.18 C (61820: 23.0 vs 19.6 kN)
        assert row.C is not None and row.C0 is not None and 0 < row.C0 < 1.2 * row.C
    assert row.source.strip()
    assert row.notes.strip()
    assert 0.5 < row.f_i <= row.f_o < 0.6


@pytest.mark.parametrize("row", WITH_GEOMETRY, ids=_id)
def test_ball_set_fits(row: BearingGeometry) -> None:
    z, dw, dm = row.balls, row.ball_diameter, row.pitch_diameter
    assert z is not None and dw is not None and dm is not None
    assert row.d < dm < row.D
    assert dm == pytest.approx((row.d + row.D) / 2)  # every source used: d_m = (d + D)/2
    assert dw < (row.D - row.d) / 2
    assert z * dw < math.pi * dm
    assert dw < dm * math.sin(math.pi / z)  # neighbouring balls do not overlap
    check_geometry(row.d, row.D, z, dw, dm, row.f_i, row.f_o)


GOST_AMBIGUOUS = {"209", "307"}


@pytest.mark.parametrize("row", [r for r in WITH_GEOMETRY if r.standard == "GOST"], ids=_id)
def test_gost_static_rating_rule(row: BearingGeometry) -> None:
    # Old GOST / Palmgren rule C0 = 1.25 z Dw^2 [kgf, mm], used to derive z.
    assert row.balls is not None and row.ball_diameter is not None and row.C0 is not None
    ratio = row.C0 / (1.25 * KGF * row.balls * row.ball_diameter**2)
    if row.designation in GOST_AMBIGUOUS:
        assert "ambiguous" in row.notes
        assert 0.95 < ratio < 1.05
    else:
        assert ratio == pytest.approx(1.0, abs=0.02)
        if row.designation in ("208", "306"):  # z given by the papers
            assert "Kuzmenko" in row.source
        else:
            assert "z derived" in row.source and "z derived" in row.notes


@pytest.mark.parametrize(
    "row",
    [
        r
        for r in WITH_GEOMETRY
        if r.standard == "ISO" and r.series in ("60", "62", "63") and r.d >= 10
    ],
    ids=_id,
)
def test_iso_ball_set_matches_nsk_fingerprint(row: BearingGeometry) -> None:
    # C0r = f0 z Dw^2 (NSK catalogue); the accepted ball sets agree within 1 %.
    assert row.f0 is not None and row.C0 is not None
    assert row.balls is not None and row.ball_diameter is not None
    assert row.f0 * row.balls * row.ball_diameter**2 == pytest.approx(row.C0, rel=0.01)


def test_rows_without_ball_set_say_so() -> None:
    for row in ROWS:
        if not row.has_geometry:
            assert row.balls is None and row.ball_diameter is None and row.pitch_diameter is None
            assert "--balls" in row.notes


def test_gost_and_iso_pairs_share_boundary_dimensions() -> None:
    iso = {r.designation: r for r in ROWS if r.standard == "ISO"}
    for row in (r for r in ROWS if r.standard == "GOST"):
        other = iso[parse(row.designation).iso_name]
        assert (row.d, row.D, row.B) == (other.d, other.D, other.B)


def test_kuzmenko2010_bearing_306() -> None:
    # Kuzmenko 2010, Table 2 "Данные по ГОСТ 8338-75":
    # 306: d 30, D 72, Dw 12.3, z 8, C 2200 kgf, C0 1510 kgf; groove radius R2 = 1.03 R1
    # (section 3.4: R1 = 6.15, R2 = 6.33 mm) -> f = 0.515.
    b = lookup("306")
    assert (b.standard, b.d, b.D, b.ball_diameter, b.balls) == ("GOST", 30.0, 72.0, 12.3, 8)
    assert b.C == pytest.approx(2200 * KGF, rel=1e-12)
    assert b.C0 == pytest.approx(1510 * KGF, rel=1e-12)
    assert (b.f_i, b.f_o) == (0.515, 0.515)
    assert b.pitch_diameter == 51.0
    assert "Kuzmenko 2010 Table 2" in b.source


def test_kuzmenko_sabadash2014_bearing_208() -> None:
    # Kuzmenko & Sabadash 2014, section 2.1 item 2: bearing 208 with d 40, D 80,
    # B 18 mm, C 2500 kgf, C_k 1810 kgf, ball diameter 12.7 mm, z 9.
    b = lookup("208")
    assert (b.d, b.D, b.B, b.ball_diameter, b.balls) == (40.0, 80.0, 18.0, 12.7, 9)
    assert b.C == pytest.approx(2500 * KGF, rel=1e-12)
    assert b.C0 == pytest.approx(1810 * KGF, rel=1e-12)
    assert (b.f_i, b.f_o) == (DEFAULT_F_I, DEFAULT_F_O) == (0.52, 0.53)
    assert "Kuzmenko & Sabadash 2014" in b.source


def test_one_row_lookup_equals_the_whole_catalogue() -> None:
    """find() builds only the row asked for (start-up); it is the row the whole catalogue has,
    for every designation, and none where the catalogue has none."""
    from bearingload.bearings import catalog

    catalog._row.cache_clear()
    for row in catalog._rows():
        first = next(
            r
            for r in catalog._rows()
            if (r.standard, r.designation) == (row.standard, row.designation)
        )
        assert catalog._row(row.standard, row.designation) == first
        assert find(row.designation) == first
    assert catalog._row("ISO", "6999") is None and catalog._row("GOST", "999") is None


def test_gost_and_iso_resolve_to_their_own_rows() -> None:
    gost, iso = lookup("306"), lookup("6306")
    assert (gost.standard, iso.standard) == ("GOST", "ISO")
    # NSK-consistent ISO ball set 8 x 11.906 (z Dw^2 f0 = 15 kN = C0r) vs the paper's 12.3.
    assert (iso.balls, iso.ball_diameter) == (8, 11.906)
    assert iso.C == 26700.0 and iso.C0 == 15000.0  # NSK 6306: Cr 26.7 kN, C0r 15.0 kN
    assert (iso.f_i, iso.f_o) == (0.52, 0.53)


def test_default_conformity_everywhere_but_306() -> None:
    odd = [r.designation for r in ROWS if (r.f_i, r.f_o) != (DEFAULT_F_I, DEFAULT_F_O)]
    assert odd == ["306"]


def test_lookup_keeps_the_parsed_designation() -> None:
    b = lookup("6306-2RS1/C3")
    assert b.designation == "6306"
    assert b.parsed.clearance_class == "C3"
    assert b.parsed.suffixes == ("2RS1", "C3")
    g = lookup("75-313")
    assert (g.designation, g.standard, g.parsed.clearance_class) == ("313", "GOST", "C3")
    assert lookup("180306").designation == "306"


def test_unknown_designation_explains_manual_geometry() -> None:
    with pytest.raises(InputError) as info:
        lookup("6417")
    msg = str(info.value)
    assert info.value.parameter == "bearing"
    assert "not in the catalogue" in msg
    assert "'balls', 'ball_diameter' and 'pitch_diameter'" in msg  # the CLI: --ball-diameter
    assert "bearingload catalog" in msg


def test_unknown_gost_points_to_iso_counterpart() -> None:
    with pytest.raises(InputError, match="'6203' is in the catalogue"):
        lookup("203")


def test_unreadable_designation_explains_manual_geometry() -> None:
    with pytest.raises(InputError, match="'balls', 'ball_diameter'") as info:
        find("bearing-x")
    assert info.value.parameter == "bearing"
    assert "accepted: ISO" in str(info.value)


def test_row_without_ball_set() -> None:
    row = find("6302")  # listed, no default (NSK) ball set: NSK's inversion is inconclusive
    assert not row.has_geometry and row.C0 == 5450.0
    with pytest.raises(InputError, match="give 'balls' and 'ball_diameter'"):
        lookup("6302")
    with pytest.raises(InputError, match="give 'ball_diameter'$"):
        lookup("6302", balls=7)
    with pytest.raises(InputError, match=r"with 'maker': NTN \| SKF"):
        lookup("6404")
    # the GOST counterpart of an ISO row (the hint of a row without a ball set)
    other = _counterpart(parse("6304"))
    assert other is not None and (other.standard, other.designation) == ("GOST", "304")


def test_overrides() -> None:
    b = lookup("6002", balls=9, ball_diameter=4.762)
    assert (b.balls, b.ball_diameter, b.pitch_diameter) == (9, 4.762, 23.5)
    assert b.overrides == ("balls", "ball_diameter")
    c = lookup("306", balls=9, pitch_diameter=50.5, f_i=0.52, f_o=0.53)
    assert (c.balls, c.ball_diameter, c.pitch_diameter, c.f_i, c.f_o) == (
        9,
        12.3,
        50.5,
        0.52,
        0.53,
    )
    assert set(c.overrides) == {"balls", "pitch_diameter", "f_i", "f_o"}
    assert lookup("306").overrides == ()


@pytest.mark.parametrize(
    ("kwargs", "parameter"),
    [
        ({"balls": 0}, "balls"),
        ({"balls": 2.5}, "balls"),
        ({"balls": 20}, "balls"),  # 20 x 12.3 mm balls overlap on d_m 51
        ({"ball_diameter": 0.0}, "ball_diameter"),
        ({"ball_diameter": 21.0}, "ball_diameter"),  # (D - d)/2 = 21
        ({"pitch_diameter": 40.0}, "pitch_diameter"),  # below d + Dw = 42.3
        ({"pitch_diameter": 60.0}, "pitch_diameter"),  # above D - Dw = 59.7
        ({"f_i": 0.5}, "f_i"),
        ({"f_o": 1.2}, "f_o"),
    ],
)
def test_bad_overrides(kwargs: dict[str, float], parameter: str) -> None:
    with pytest.raises(InputError) as info:
        lookup("306", **kwargs)  # type: ignore[arg-type]
    assert info.value.parameter == parameter


def test_entries_filters() -> None:
    assert [b.designation for b in entries(bore=30)] == [
        "206",
        "306",
        "6006",
        "6206",
        "6306",
        "6406",
        "61806",
        "61906",
        "16006",
    ]
    s63 = entries(series="63")
    assert s63 and all(b.series == "63" for b in s63)
    assert entries(series="3") == s63 == entries(series="63xx")
    gost = entries(standard="gost")
    assert len(gost) == 26 and all(b.standard == "GOST" for b in gost)
    assert [b.designation for b in entries(series="2", standard="ISO", bore=40)] == ["6208"]
    assert entries(bore=31) == []


@pytest.mark.parametrize(
    ("kwargs", "parameter"), [({"series": "65"}, "series"), ({"standard": "DIN"}, "standard")]
)
def test_entries_errors(kwargs: dict[str, str], parameter: str) -> None:
    with pytest.raises(InputError) as info:
        entries(**kwargs)  # type: ignore[arg-type]
    assert info.value.parameter == parameter


def test_a_lone_makers_set_is_the_rows_set() -> None:
    """6405 and 6407-6416: NTN alone gives a ball set; it is used without maker= and marked
    (only_maker), its ratings with it. Where two makers give one (6302, 6403, 6404, 6406) the
    row stays without a set and a maker must be named."""
    from bearingload.bearings.catalog import ball_sets, variant

    lone = {bs.designation for bs in ball_sets()} - {
        bs.designation for bs in ball_sets() if bs.maker == "NSK"
    }
    for name in sorted(lone):
        row = find(name)
        if len(row.makers) == 1:
            assert row.only_maker and row.has_geometry and row.maker == row.makers[0] == "NTN"
            ntn = variant(name, "NTN")
            assert (row.balls, row.ball_diameter, row.C, row.C0) == (
                ntn.balls, ntn.ball_diameter, ntn.C, ntn.C0
            )  # fmt: skip
            assert not ntn.only_maker  # named: nothing to say
        else:
            assert not row.only_maker and not row.has_geometry
    assert sorted(n for n in lone if find(n).only_maker) == [
        "6405", "6407", "6408", "6409", "6410", "6411", "6412", "6413", "6414", "6415", "6416"
    ]  # fmt: skip


def test_the_dynamic_rating_is_always_in_newtons():
    listed = json.loads(invoke("catalog", "--bore", "25", "--format", "json").output)
    row = next(r for r in listed["rows"] if r["designation"] == "6205")
    shown = json.loads(invoke("catalog", "show", "6205", "--format", "json").output)
    assert listed["units"]["C"] == "N" and row["C"] == 14000.0
    assert json.dumps(shown).count("14000.0") >= 1


@pytest.mark.parametrize("bore", ["-5", "0", "-3in"])
@pytest.mark.parametrize("kind", ["deep-groove", "angular"])
def test_a_bore_of_zero_or_less_is_refused_not_listed_as_empty(capsys, kind, bore):
    """catalog --bore -5 printed an empty list (0 bearings), exit 0, as if no bearing had that
    bore; the library's entries(bore=nan) returned [] alike. A bore must be a number > 0."""
    from .cli_helpers import error_line

    line = error_line(capsys, "catalog", "--type", kind, f"--bore={bore}")
    assert line.startswith("Error: Invalid value for '--bore': must be greater than 0 mm"), line
    for bad in (-5.0, float("nan"), "30", [30, 40]):
        with pytest.raises(InputError) as info:
            entries(bore=bad)
        assert info.value.parameter == "bore"
    assert entries(bore=31) == [] and len(entries(bore=30.0)) == 9
