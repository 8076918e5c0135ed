"""Limiting speeds of the catalogue rows and the warning on a speed above them.

The values are Koyo's, as printed in CAT. No. B2001RUS (2008) and copied with their pages into
tests/fixtures/limiting_speeds.py: the 183 Koyo angular-contact rows (pp. 56-74) and the 74 ISO
deep-groove rows (pp. 8-13). ``solve``, ``sweep`` and ``batch`` warn once when the speed is above
the grease figure (saying whether above the oil figure too), never at or below it, and never for
a bearing the catalogue gives no limiting speed for (docs/speed.md).
"""

from __future__ import annotations

import csv
import io
import json
import re

import pytest

from bearingload.bearings._data import read_rows
from bearingload.bearings.resolve import resolve_bearing
from tests.cli_helpers import invoke, run_entry
from tests.fixtures.angular_factors import KOYO_B2001
from tests.fixtures.limiting_speeds import KOYO_ANGULAR_SPEEDS, KOYO_DEEP_GROOVE_SPEEDS

from .cli_helpers import besides_tilt, warnings_of


def speed_findings(speed, bearing):
    """:func:`bearingload.bearings.checks.speed_findings`, imported here so that each test
    fails alone on a tree without it."""
    from bearingload.bearings.checks import speed_findings as findings

    return findings(speed, bearing)


def _koyo_name(designation: str) -> str:
    """Koyo's name of a stored Koyo row (Koyo's plain 7205 is stored as 7205A)."""
    return designation[:-1] if designation.endswith("A") else designation


def test_the_printed_row_of_each_angular_speed_is_that_of_its_designation():
    """Each fixture row's printed d, D, B and first C_r/C_0r pair are those of the row paired
    with the same designation by its load centre (tests/fixtures/angular_factors.py)."""
    assert set(KOYO_ANGULAR_SPEEDS) == set(KOYO_B2001)
    for name, (d, D, B, cr, c0r, grease, oil, page) in KOYO_ANGULAR_SPEEDS.items():
        assert (d, D, B, cr, c0r) == KOYO_B2001[name][:5], name
        assert 0 < grease < oil, name
        assert 56 <= page <= 74 and page % 2 == 0, name


@pytest.mark.parametrize("path", ["angular_contact.csv", "bearings.csv"])
def test_every_limiting_speed_is_the_printed_one_and_none_is_invented(path):
    rows = read_rows(path)
    have = [r for r in rows if r["limiting_speed_grease"] or r["limiting_speed_oil"]]
    for r in rows:
        koyo = (
            (r.get("maker") == "KOYO") if path == "angular_contact.csv" else r["standard"] == "ISO"
        )
        if not koyo:  # NSK's 40° leaflet rows and the GOST rows: none printed by their sources
            assert r["limiting_speed_grease"] == r["limiting_speed_oil"] == ""
            assert r["limiting_speed_source"] == ""
            continue
        if path == "bearings.csv" and float(r["d"]) < 10:  # NSK's miniature tables, printed
            assert r["limiting_speed_source"].startswith("NSK Rolling Bearings CAT. No. E1102e")
            continue  # with the row (test_catalog_miniature.py checks them against the print)
        if path == "angular_contact.csv":
            _, _, _, _, _, grease, oil, page = KOYO_ANGULAR_SPEEDS[_koyo_name(r["designation"])]
        else:
            d, D, B, grease, oil, page = KOYO_DEEP_GROOVE_SPEEDS[r["designation"]]
            assert (float(r["d"]), float(r["D"]), float(r["B"])) == (d, D, B)
        assert (float(r["limiting_speed_grease"]), float(r["limiting_speed_oil"])) == (grease, oil)
        assert r["limiting_speed_source"].startswith(f"Koyo CAT. No. B2001RUS, 2008, p. {page} (")
        assert f"pdf page {page + 3})" in r["limiting_speed_source"]
    assert len(have) == (183 if path == "angular_contact.csv" else 74 + 40)


@pytest.mark.parametrize(
    ("designation", "maker", "grease", "oil"),
    [
        ("7205C", None, 21000, 28000),  # p. 58
        ("7205B", "KOYO", 12000, 15000),  # p. 58
        ("7000A", None, 34000, 42000),  # p. 56, Koyo's plain 7000
        ("7320C", None, 5000, 6700),  # p. 74
        ("7012B", None, 5800, 7700),  # p. 66
        ("6205", None, 13000, 15000),  # p. 9
        ("6208", "SKF", 8300, 10000),  # the designation's limits, whoever's ball set
        ("6208", "GOST", 8300, 10000),  # p. 10
        ("6416", None, 3400, 4100),  # p. 12
        ("6220-ZZ/C3", None, 3500, 4200),  # p. 13; shields are no seals
    ],
)
def test_the_resolved_bearing_carries_them(designation, maker, grease, oil):
    limits = resolve_bearing(designation, maker=maker).limiting_speeds
    assert limits is not None
    assert (limits.grease, limits.oil) == (grease, oil)
    assert limits.source.startswith("Koyo CAT. No. B2001RUS, 2008, p. ")


@pytest.mark.parametrize("designation", ["7205B", "205", "6205-2RS1", "6205 LLU", "NU205"])
def test_no_limit_where_the_catalogue_gives_none(designation):
    """NSK's 40° rows and the GOST rows print none; a seal lowers the open bearing's limits;
    the roller rows have none; nor has a ring given by hand."""
    assert resolve_bearing(designation).limiting_speeds is None
    sealed = designation in ("6205-2RS1", "6205 LLU")  # warned above the open 6205's limit
    assert len(speed_findings(1e6, resolve_bearing(designation))) == sealed
    assert speed_findings(13000.0, resolve_bearing(designation)) == []
    assert (
        resolve_bearing(balls=9, ball_diameter=7.9375, pitch_diameter=38.5).limiting_speeds is None
    )


def test_the_rule_at_both_limits():
    b = resolve_bearing("7205C")  # grease 21 000, oil 28 000 rpm
    assert speed_findings(None, b) == []
    assert speed_findings(21000.0, b) == []
    (grease,) = speed_findings(21000.5, b)
    assert "above the limiting speed of 7205C with grease lubrication, 21000 rpm" in grease
    assert "with oil lubrication 28000 rpm, which it does not exceed" in grease
    assert grease.endswith("; Koyo CAT. No. B2001RUS, 2008, p. 58)")
    assert speed_findings(28000.0, b) == [grease.replace("21000.5", "28000")]
    (oil,) = speed_findings(28000.5, b)
    assert "above the limiting speeds of 7205C with oil lubrication, 28000 rpm, and with " in oil
    assert oil.endswith("grease, 21000 rpm (Koyo CAT. No. B2001RUS, 2008, p. 58)")


def test_the_warning_shows_the_speed_above_the_limit_and_unit_rounding_is_at_it(capsys):
    """A speed just above a limit is printed with the digits that show it above (13000.001 rpm
    printed as 13000 read 'the speed n = 13000 rpm is above ... 13000 rpm'); a speed given in
    another unit that is the limit to rounding (1361.356816555577 rad/s, 250 Hz, 500 pi rad/s) is
    at it, not above."""
    b = resolve_bearing("6205")  # grease 13 000, oil 15 000 rpm
    (grease,) = speed_findings(13000.001, b)
    assert grease.startswith("the speed n = 13000.001 rpm is above the limiting speed of 6205")
    (oil,) = speed_findings(15000.00004, b)
    assert oil.startswith("the speed n = 15000.00004 rpm is above the limiting speeds of 6205")
    assert speed_findings(14000.0, b)[0].startswith("the speed n = 14000 rpm is above")
    assert speed_findings(13000.0 * (1.0 + 2.0**-52), b) == []
    assert "which it does not exceed" in speed_findings(15000.0 * (1.0 + 2.0**-52), b)[0]
    for speed in ("1361.356816555577rad/s", "216.6666666666667Hz"):
        code, _, err = run_entry(capsys, "solve", "6205", "-F", "2kN", "--speed", speed)
        assert code == 0 and _warned(err) == [], speed
    code, _, err = run_entry(
        capsys, "solve", "6205", "-F", "2kN", "--speed", "1570.796326794897rad/s"
    )
    assert code == 0 and "which it does not exceed" in _warned(err)[0]


def _warned(err: str) -> list[str]:
    return [line for line in err.splitlines() if "limiting speed" in line]


@pytest.mark.parametrize(
    "args",
    [
        ["solve", "6205", "-F", "2kN"],  # radial engine
        ["solve", "6205", "-F", "2kN", "-A", "500N", "--quasi-static"],  # combined engine
        ["sweep", "6205", "-F", "2kN", "--steps", "3"],
        ["sweep", "6205", "-F", "2kN", "-A", "500N", "--steps", "3"],
    ],
)
def test_solve_and_sweep_warn_just_above_and_not_just_below(capsys, args):
    code, _, err = run_entry(capsys, *args, "--speed", "12999")  # grease limit 13 000 rpm
    assert code == 0 and _warned(err) == []
    code, _, err = run_entry(capsys, *args, "--speed", "13001")
    assert code == 0
    assert _warned(err) == [
        "Warning: the speed n = 13001 rpm is above the limiting speed of 6205 with grease "
        "lubrication, 13000 rpm (with oil lubrication 15000 rpm, which it does not exceed; Koyo "
        "CAT. No. B2001RUS, 2008, p. 9)"
    ]
    code, out, err = run_entry(capsys, *args, "--speed", "15001", "--format", "json")
    assert code == 0
    (line,) = _warned(err)
    assert "15001 rpm is above the limiting speeds of 6205 with oil lubrication, 15000 rpm" in line
    assert line.removeprefix("Warning: ") in json.loads(out)["warnings"]


def test_solve_warns_for_an_angular_contact_bearing_and_not_for_one_without_data(capsys):
    code, out, err = run_entry(capsys, "solve", "7205C", "-F", "2kN", "-A", "1kN", "--speed",
                               "21001", "--quasi-static", "--format", "json")  # fmt: skip
    assert code == 0
    (line,) = _warned(err)
    assert "limiting speed of 7205C with grease lubrication, 21000 rpm" in line
    assert besides_tilt(json.loads(out)["cases"][0]["warnings"]) == [line.removeprefix("Warning: ")]
    for args in (["7205B", "-A", "1kN"], ["205"],
                 ["-z", "9", "--ball-diameter", "7.9375", "--pitch-diameter", "38.5"]):  # fmt: skip
        code, _, err = run_entry(capsys, "solve", *args, "-F", "2kN", "--speed", "1e5",
                                 "--quasi-static")  # fmt: skip
        assert code == 0, err
        assert _warned(err) == [], args


def test_a_sealed_bearing_above_its_open_bearing_s_limit_is_warned(capsys):
    """A seal lowers the open bearing's limits (Koyo p. 20), so a sealed 6205-2RS above the open
    6205's grease figure (13 000 rpm) is above its own limit too: one warning, which says so
    (there was none, even at 1e5 rpm); at or below it, where the sealed limit is not known, none.
    Shields keep the open bearing's limits and warning."""
    for args in (["6205-2RS", "-F", "2kN"], ["6205-2RS1/C3", "-F", "2kN", "-A", "500N",
                 "--quasi-static"], ["6205 LLU", "-F", "2kN"]):  # fmt: skip
        code, out, err = run_entry(capsys, "solve", *args, "--speed", "13001", "--format", "json")
        assert code == 0, err
        (line,) = _warned(err)
        name = args[0]
        assert line == (
            f"Warning: the speed n = 13001 rpm is above the limiting speed of {name}: the open "
            "6205's with grease lubrication is 13000 rpm (with oil 15000 rpm), and its seal "
            "lowers it (Koyo CAT. No. B2001RUS, 2008, p. 9; sealed bearings p. 20)"
        ), args
        assert line.removeprefix("Warning: ") in json.loads(out)["cases"][0]["warnings"]
        code, _, err = run_entry(capsys, "solve", *args, "--speed", "13000")
        assert code == 0 and _warned(err) == [], args
    code, _, err = run_entry(capsys, "sweep", "6205-2RS", "-F", "2kN", "--speed", "1e5",
                             "--quasi-static", "--steps", "3")  # fmt: skip
    assert code == 0 and len(_warned(err)) == 1
    rows = "bearing,load,speed\n6205-2RS,2kN,13001\n6205-2RS,2kN,13000\n"
    from click.testing import CliRunner

    from bearingload.cli import main

    found = CliRunner().invoke(main, ["batch", "-", "--format", "json"], input=rows)
    doc = json.loads(found.stdout)
    assert [len(c["warnings"]) for c in doc["cases"]] == [1, 0]
    assert "above the limiting speed of 6205-2RS: the open 6205's" in doc["cases"][0]["warnings"][0]
    code, _, err = run_entry(capsys, "solve", "6205ZZ", "-F", "2kN", "--speed", "13001")
    assert "above the limiting speed of 6205 with grease lubrication" in _warned(err)[0]


def test_batch_warns_on_each_row_above_its_limit(tmp_path):
    rows = [("6205", "2kN", "", "12999"), ("6205", "2kN", "", "13001"),
            ("7205C", "2kN", "1kN", "28001"), ("205", "2kN", "", "50000"),
            ("6205", "2kN", "500N", "16000")]  # fmt: skip
    text = io.StringIO()
    csv.writer(text).writerows([("bearing", "load", "axial_load", "speed"), *rows])
    path = tmp_path / "cases.csv"
    path.write_text(text.getvalue(), encoding="utf-8")
    result = invoke("batch", str(path), "--format", "json")
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    found = [[w for w in c["warnings"] if "limiting speed" in w] for c in doc["cases"]]
    assert [len(f) for f in found] == [0, 1, 1, 0, 1]
    assert "13001 rpm is above the limiting speed of 6205 with grease" in found[1][0]
    assert (
        "28001 rpm is above the limiting speeds of 7205C with oil lubrication, 28000" in found[2][0]
    )
    assert "16000 rpm is above the limiting speeds of 6205 with oil" in found[4][0]


def test_catalog_show_prints_them_with_units():
    text = invoke("catalog", "show", "7205C").output
    assert re.search(r"\nlimiting speed, grease +21000\.0 +rpm\n", text)
    assert re.search(r"\nlimiting speed, oil +28000\.0 +rpm\n", text)
    assert "limiting speeds: Koyo CAT. No. B2001RUS, 2008, p. 58 (" in text
    doc = json.loads(invoke("catalog", "show", "6205", "--format", "json").output)
    assert (doc["limiting_speed_grease"], doc["limiting_speed_oil"]) == (13000, 15000)
    assert doc["units"]["limiting_speed_oil"] == "rpm"
    assert doc["limiting_speed_source"].startswith("Koyo CAT. No. B2001RUS, 2008, p. 9 (")
    doc = json.loads(invoke("catalog", "show", "7205B", "--format", "json").output)
    assert doc["limiting_speed_grease"] == doc["limiting_speed_oil"] == "-"
    assert "none read" in doc["limiting_speed_source"]


def test_table_life_warns_above_the_limit_as_solve_does(capsys):
    """table life --speed above the catalogue's limit: the line solve prints, on stderr and in the
    json's warnings (there was none); at the limit, none."""
    code, out, err = run_entry(capsys, "table", "life", "-b", "6205", "-F", "1kN", "--speed",
                               "20000", "--format", "json")  # fmt: skip
    assert code == 0, err
    (line,) = _warned(err)
    assert "20000 rpm is above the limiting speeds of 6205 with oil lubrication, 15000" in line
    assert json.loads(out)["warnings"] == [line.removeprefix("Warning: ")]
    _, _, solved = run_entry(capsys, "solve", "6205", "-F", "1kN", "--speed", "20000")
    assert _warned(solved) == [line]
    code, _, err = run_entry(capsys, "table", "life", "-b", "6205", "-F", "1kN", "--speed", "13000")
    assert code == 0 and _warned(err) == []


def test_table_life_warns_above_the_limiting_speed(capsys):
    """table life -b 6205 --speed 1e5 printed no limiting-speed warning (solve, sweep and
    batch do): it prints solve's line, json lists it, none at or below the limit (1e5 rpm with
    --quasi-static: the ball dynamics refuse n d_m beyond 2e6 mm/min)."""
    args = ("table", "life", "-b", "6205", "-F", "1kN")
    for speed, bearing in (("1e5", "6205"), ("1400rad/s", "6205"), ("1e5", "6205-2RS")):
        case = ("table", "life", "-b", bearing, "-F", "1kN", "--speed", speed, "--quasi-static")
        code, _, err = run_entry(capsys, *case)
        _, _, solved = run_entry(
            capsys, "solve", bearing, "-F", "1kN", "--speed", speed, "--quasi-static"
        )
        assert code == 0 and warnings_of(err) == warnings_of(solved) and len(warnings_of(err)) == 1
        assert "limiting speed" in warnings_of(err)[0]
        code, out, err = run_entry(capsys, *case, "--format", "json")
        assert json.loads(out)["warnings"] == warnings_of(err)
    for speed in ("13000", "1361.356816555577rad/s"):  # at the grease limit: no warning
        code, _, err = run_entry(capsys, *args, "--speed", speed)
        assert code == 0 and warnings_of(err) == [], err
