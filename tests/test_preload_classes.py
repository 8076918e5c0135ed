"""Preload classes of matched pairs (NSK EL, L, M, H): the table against its sources, one reading
for --preload, a designation's suffix, a batch cell and the library, and the refusals."""

from __future__ import annotations

import csv
from importlib import resources

import pytest
from click.testing import CliRunner

from bearingload.bearings.angular import split_pair
from bearingload.bearings.preload import parse_preload, resolve_preload
from bearingload.bearings.resolve import resolve_bearing
from bearingload.cli import main
from bearingload.errors import InputError
from bearingload.studies.bearing_pair import solve_bearing_pair

from .cli_helpers import besides_tilt, run_entry, solved_csv

#: NSK Rolling Bearings CAT. No. E1102e, p. A99, Table 10.2 "Preloads for duplex angular contact
#: ball bearings" (15°), as printed: bore codes 00 ... 20, (EL, L, M, H) [N]. Table 10.2.2,
#: series 70 (EL and L printed beside the numbers, M and H in a block after them):
E1102E_70C = dict(
    zip(
        [f"{k:02d}" for k in range(21)],
        zip(
            [
                12,
                12,
                14,
                14,
                24,
                29,
                39,
                60,
                60,
                75,
                75,
                100,
                100,
                125,
                145,
                145,
                195,
                195,
                245,
                270,
                270,
            ],
            [
                25,
                25,
                29,
                29,
                49,
                59,
                78,
                120,
                120,
                150,
                150,
                200,
                200,
                250,
                290,
                290,
                390,
                390,
                490,
                540,
                540,
            ],
            [
                49,
                59,
                69,
                69,
                120,
                150,
                200,
                250,
                290,
                340,
                390,
                490,
                540,
                540,
                740,
                780,
                930,
                980,
                1180,
                1180,
                1270,
            ],
            [
                100,
                120,
                150,
                150,
                250,
                290,
                390,
                490,
                590,
                690,
                780,
                980,
                1080,
                1080,
                1470,
                1570,
                1860,
                1960,
                2350,
                2350,
                2550,
            ],
            strict=True,
        ),
        strict=True,
    )
)
#: Table 10.2.3, series 72.
E1102E_72C = dict(
    zip(
        [f"{k:02d}" for k in range(21)],
        [
            (14, 29, 69, 150),
            (19, 39, 100, 200),
            (19, 39, 100, 200),
            (24, 49, 150, 290),
            (34, 69, 200, 390),
            (39, 78, 200, 390),
            (60, 120, 290, 590),
            (75, 150, 390, 780),
            (100, 200, 490, 980),
            (125, 250, 540, 1080),
            (125, 250, 590, 1180),
            (145, 290, 780, 1570),
            (195, 390, 930, 1860),
            (220, 440, 1080, 2160),
            (245, 490, 1180, 2350),
            (270, 540, 1230, 2450),
            (295, 590, 1370, 2750),
            (345, 690, 1670, 3330),
            (390, 780, 1860, 3730),
            (440, 880, 2060, 4120),
            (490, 980, 2350, 4710),
        ],
        strict=True,
    )
)


def _rows() -> list[dict[str, str]]:
    text = resources.files("bearingload.bearings").joinpath("data/preload_classes.csv")
    return list(csv.DictReader(text.read_text(encoding="utf-8").splitlines()))


def test_every_row_has_a_source_and_rising_classes():
    rows = _rows()
    assert len(rows) == 182  # 70 C and A5: 32 each; 72 C and A5: 27 each; 79 C and A5: 32 each
    for r in rows:
        assert "NSK" in r["source"] and r["maker"] == "NSK"
        forces = [float(r[c]) for c in ("EL", "L", "M", "H")]
        assert forces == sorted(forces) and forces[0] > 0


@pytest.mark.parametrize(("series", "printed"), [("70", E1102E_70C), ("72", E1102E_72C)])
def test_15_degree_rows_are_nsk_general_catalogue_table_10_2(series, printed):
    """An independent source: the super-precision catalogue's 15° rows against the general
    catalogue's Table 10.2 (21 bore codes each)."""
    rows = {r["bore_code"]: r for r in _rows() if r["series"] == series and r["angle_code"] == "C"}
    for code, forces in printed.items():
        assert tuple(float(rows[code][c]) for c in ("EL", "L", "M", "H")) == forces, code
        assert "E1102e" in rows[code]["source"]


def test_published_spot_values():
    # reference notes: 7008C 60/120/290/590 N, 7208C 100/200/490/980 N, 7205C 39/78/200/390 N
    for name, forces in (
        ("7008C", (60, 120, 290, 590)),
        ("7208C", (100, 200, 490, 980)),
        ("7205C", (39, 78, 200, 390)),
    ):
        b = resolve_bearing(name)
        assert tuple(resolve_preload(c, b).force for c in ("EL", "L", "M", "H")) == forces


def test_the_25_degree_class_is_its_own_table_row():
    b = resolve_bearing("7205AC")  # the 25° row 7205A5
    p = resolve_preload("m", b)
    assert (p.force, p.preload_class) == (340.0, "M") and "A5" in p.source
    assert resolve_preload("M", resolve_bearing("7205C")).force == 200.0  # 15°: another row


@pytest.mark.parametrize(
    ("text", "want"),
    [("M", "M"), (" el ", "EL"), ("300", 300.0), ("0.3kN", 300.0), ("0", 0.0), ("ul", "UL")],
)
def test_a_preload_is_a_force_or_a_class_letter(text, want):
    assert parse_preload(text) == want


@pytest.mark.parametrize("text", ["X", "-5N", "MM", "300 mm"])
def test_an_unreadable_preload_is_refused_naming_the_classes(text):
    with pytest.raises(InputError) as info:
        parse_preload(text)
    assert info.value.parameter == "preload"


@pytest.mark.parametrize(
    ("name", "value", "words"),
    [
        ("7205B", "M", "7205B (40°) has no preload-class table"),
        ("7305C", "L", "7305C (15°) has no preload-class table"),
        ("36205", "L", "the bearing 36205 has none"),
        ("7205C", "A", "SKF's preload class"),
        ("7205C", "UL", "FAG's preload class"),
    ],
)
def test_a_class_without_a_table_is_refused_naming_the_series_with_one(name, value, words):
    tables = (
        r"tabulated for 70xx at 15° and 25° \(bore codes 00-40\), 72xx at 15° and 25° "
        r"\(bore codes 00-30\), 79xx at 15° and 25° \(bore codes 00-40\) "
    )
    with pytest.raises(InputError, match=tables) as info:
        resolve_preload(value, resolve_bearing(name))
    assert words in info.value.message and info.value.parameter == "preload"


def test_a_maker_named_reads_its_own_letters():
    b = resolve_bearing("7205C")
    assert resolve_preload("L", b, maker="nsk").force == 78.0
    with pytest.raises(InputError, match="FAG's preload class L has no table"):
        resolve_preload("L", b, maker="FAG")


def test_the_designation_carries_the_class():
    assert split_pair("7205CDBL") == ("7205C", "DB", "L")
    assert split_pair("7008A5 DFEL") == ("7008A5", "DF", "EL")


def test_library_class_is_the_tables_force_and_says_so():
    b = resolve_bearing("7205C")
    by_class = solve_bearing_pair(b, 1000.0, 200.0, arrangement="DB", preload="M")
    by_force = solve_bearing_pair(b, 1000.0, 200.0, arrangement="DB", preload=200.0)
    assert by_class.result.x == by_force.result.x and by_class.result.preload == 200.0
    assert by_class.preload_class is not None and by_class.preload_class.preload_class == "M"
    assert any("preload class M" in s for s in by_class.bearing.sources)
    assert by_force.preload_class is None


def test_solve_with_a_class_is_solve_with_its_force_and_prints_both(capsys):
    code, out, err = run_entry(capsys, "solve", "7205CDBL", "-F", "1kN", "-A", "200N")
    assert code == 0 and besides_tilt(err) == []
    assert "preload 78 N (NSK class L)" in out.splitlines()[0]
    assert "Preload: preload class L of a 7205C pair (15°), 78 N as ground" in out
    _, by_force, _ = run_entry(
        capsys, "solve", "7205CDB", "--preload", "78N", "-F", "1kN", "-A", "200N"
    )
    body = out.splitlines()[1:]
    assert [line for line in body if not line.startswith("Preload:")] == by_force.splitlines()[1:]
    code, same, _ = run_entry(
        capsys, "solve", "7205C", "--arrangement", "DB", "--preload", "l", "-F", "1kN", "-A", "200N"
    )
    assert code == 0 and same == out


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["7205BDB", "--preload", "M"], "7205B (40°) has no preload-class table"),
        (["7205CDBL", "--preload", "M"], "M contradicts the designation '7205CDBL'"),
        (
            [
                "-z",
                "12",
                "--ball-diameter",
                "7.9375",
                "--pitch-diameter",
                "38.5",
                "--contact-angle",
                "15",
                "--arrangement",
                "DB",
                "--width",
                "15",
                "--preload",
                "M",
            ],
            "a ring given by hand",
        ),
        (["7205CDB", "--preload", "Q"], "or a preload class: EL | L | M | H"),
    ],
)
def test_solve_refuses_with_one_error_line_naming_preload(capsys, args, words):
    code, out, err = run_entry(capsys, "solve", *args, "-F", "1kN")
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and lines[0].startswith("Error:")
    assert "--preload" in err and words in err


def test_sweep_takes_a_class(capsys):
    code, out, err = run_entry(
        capsys, "sweep", "7205CDBM", "-F", "1kN", "-A", "200N", "--steps", "3"
    )
    assert code == 0 and besides_tilt(err) == [] and "preload 200 N (NSK class M)" in out
    assert "Preload: preload class M of a 7205C pair (15°), 200 N as ground" in out


def test_batch_reads_a_class_cell_and_the_designations_class():
    text = (
        "bearing,arrangement,preload,load,axial_load\n"
        "7205C,DB,M,1kN,200N\n7205CDBM,,,1kN,200N\n7205C,DB,200N,1kN,200N\n"
        "7205B,DB,M,1kN,200N\n"
    )
    out = CliRunner().invoke(
        main, ["batch", "-", "--format", "csv"], input=text, catch_exceptions=False
    )
    lines = solved_csv(out.stdout).splitlines()
    rows = [line.split(",", 1)[1] for line in lines[1:]]
    assert len(rows) == 6 and rows[0:2] == rows[2:4] == rows[4:6]
    assert "row 5: preload: the bearing 7205B (40°) has no preload-class table" in out.stderr
