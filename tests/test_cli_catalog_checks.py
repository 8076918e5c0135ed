"""The command line with the new catalogue: small and wide series, makers, rollers, warnings."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from bearingload.cli import main
from tests.test_cli_bearing import error_of

OVERLOAD_WARNINGS = (
    "Warning: static safety factor s0 = C0/P0 = 0.0157 is below 1 (ISO 76: P0 = F_r = 500000 N, "
    "C0 = 7850 N): the raceways deform permanently\n"
    "Warning: the load F_r = 500000 N is above the basic static rating C0 = 7850 N\n"
    "Warning: maximum contact pressure 16133 MPa (inner contact, heaviest ball 244144 N) is above "
    "4200 MPa, the pressure of the static rating of ball bearings (ISO 76)\n"
)


def run(*args: str):
    result = CliRunner().invoke(main, list(args), catch_exceptions=False)
    assert result.exit_code == 0, result.output
    return result


def test_overload_warns_on_stderr_and_still_prints() -> None:
    r = run("solve", "6205", "-F", "500kN")
    assert r.stderr == OVERLOAD_WARNINGS
    assert r.stdout.startswith("Bearing 6205, z = 9, F_r = 500000 N (50985.8 kgf), K = 274869")
    assert "basic rating life L10 = (C/P)^p" in r.stdout


def test_sane_case_is_silent() -> None:
    r = run("solve", "6205", "-F", "5kN", "-G", "C3")
    assert r.stderr == ""
    doc = json.loads(run("solve", "6205", "-F", "5kN", "-G", "C3", "--format", "json").stdout)
    assert doc["warnings"] == []


def test_quiet_silences_the_terminal_not_json() -> None:
    assert run("solve", "6205", "-F", "500kN", "--quiet").stderr == ""
    r = run("solve", "6205", "-F", "500kN", "-q", "--format", "json")
    assert r.stderr == ""
    doc = json.loads(r.stdout)
    assert doc["warnings"] == [
        line.removeprefix("Warning: ") for line in OVERLOAD_WARNINGS.splitlines()
    ]
    r = run("solve", "6205", "-F", "500kN", "--format", "json")
    assert r.stderr == OVERLOAD_WARNINGS


def test_range_collects_warnings_once() -> None:
    r = run(
        "solve", "6205", "-F", "500kN", "-G", "C3", "--clearance-pick", "range", "--format", "json"
    )
    doc = json.loads(r.stdout)
    assert len(doc["cases"]) == 3 and all(len(c["warnings"]) == 3 for c in doc["cases"])
    assert len(doc["warnings"]) == len(set(doc["warnings"])) == len(r.stderr.splitlines())


def test_hand_given_single_ball() -> None:
    r = run("solve", "-z", "9", "-F", "10N", "-K", "3e5", "-G", "50um")
    assert r.stderr == (
        "Warning: only one ball carries the load: the result hangs on a single contact (large "
        "clearance or few elements); check the clearance\n"
    )
    doc = json.loads(run("solve", "-z", "9", "-F", "1kN", "-K", "3e5", "--format", "json").stdout)
    assert doc["warnings"] == []


@pytest.mark.parametrize(
    ("args", "geometry"),
    [
        (("solve", "6004", "-F", "1kN"), ("balls z", "9", "catalogue: NSK ball set, derived")),
        (("solve", "61806", "-F", "500N"), ("balls z", "18", "catalogue: NSK ball set, derived")),
        (("solve", "16005", "-F", "1kN"), ("balls z", "12", "catalogue: NSK ball set, derived")),
        (("solve", "6806", "-F", "500N"), ("balls z", "18", "catalogue: NSK ball set, derived")),
        (("solve", "6208", "-F", "5kN", "--maker", "SKF"), ("balls z", "9", "catalogue: SKF ball set, derived")),
        (("solve", "6205", "-F", "5kN", "--maker", "cwru"), ("balls z", "9", "catalogue: CWRU ball set, read")),
    ],
)  # fmt: skip
def test_new_designations_say_where_geometry_comes_from(args, geometry) -> None:
    r = run(*args, "--show-geometry")
    assert r.stderr == ""
    row = next(line for line in r.stdout.splitlines() if line.startswith("balls z"))
    assert row.split()[:3] == ["balls", "z", geometry[1]]
    assert row.endswith(geometry[2])
    assert f"ball set ({geometry[2].rsplit(', ', 1)[1]}): " in r.stdout  # the source text


def test_maker_json_and_ratings() -> None:
    doc = json.loads(run("solve", "6208", "-F", "5kN", "--maker", "SKF", "--format", "json").stdout)
    b = doc["bearing"]
    assert b["maker"] == "SKF" and b["C0"] == 19000.0
    assert b["geometry"]["ball_diameter"]["value"] == 12.303
    assert "derived" in b["geometry"]["ball_diameter"]["source"]


def test_roller_bearing_nu206() -> None:
    r = run("solve", "NU206", "--load", "5kN", "--show-geometry")
    assert r.stderr == ""
    assert r.stdout.startswith("Bearing NU206: geometry and stiffness used\n")
    assert (
        "rollers z                          13               catalogue: read (dataset)" in r.stdout
    )
    assert "life L10 = (C/F_r)^(10/3)" in r.stdout
    assert "m = 1.11111" in r.stdout
    doc = json.loads(run("solve", "NU206", "-F", "5kN", "--format", "json").stdout)
    case = doc["cases"][0]
    assert doc["bearing"]["kind"] == "roller" and case["exponent"] == pytest.approx(10 / 9)
    assert doc["bearing"]["units"]["stiffness_inner"] == "N/mm^(10/9)"
    assert doc["warnings"] == [] and case["warnings"] == []
    # life with p = 10/3: (C/F_r)^(10/3), SKF C = 44 kN
    assert case["rating_life"] == pytest.approx((44000 / 5000) ** (10 / 3), rel=1e-9)  # 10 digits
    over = run("solve", "N 206", "-F", "60kN")
    assert "above 4000 MPa" in over.stderr and over.stderr.count("Warning: ") == 3


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (
            ["solve", "6208", "-F", "1kN", "--maker", "FAG"],
            "Error: Invalid value for '--maker': no FAG ball set for 6208 in the catalogue; makers "
            "with one: NSK, NTN, SKF, GMN, GOST",
        ),
        (["solve", "NU206", "-F", "1kN", "-m", "1.1"], "a roller bearing (line contact) has m = 10/9"),
        (["solve", "NU206", "-F", "1kN", "-G", "4.5mm"], "Invalid value for '--clearance': G_r = 4.5 mm is at least half the roller diameter"),
        (["solve", "6404", "-F", "1kN"], "choose a maker's set with '--maker': NTN | SKF"),
        (["table", "k", "-b", "NU206"], "the tables take ball bearings"),
        (["catalog", "show", "6208", "--maker", "X"], "Invalid value for '--maker': no X ball set"),
    ],
)  # fmt: skip
def test_errors(capsys, args, message) -> None:
    assert message in error_of(capsys, *args)


def test_catalog_show_and_list() -> None:
    text = run("catalog", "show", "6208", "--maker", "GOST").stdout
    assert "ball diameter D_w            12.7000" in text
    assert "makers (--maker)             NSK, NTN, SKF, GMN, GOST" in text
    lines = run("catalog", "--series", "68").stdout.splitlines()
    assert lines[0] == "Deep groove ball bearings in the catalogue (series 68)"
    assert "30 bearings" in lines[-1]  # 21 of 618xx, 9 of one-digit bores (681 ... 689)
    assert run("table", "k", "-b", "6208", "--maker", "gost", "--z-max", "3").stdout.startswith(
        "Bearing 6208: Load factor"
    )


def test_catalog_roller_entry_and_maker_column() -> None:
    text = run("catalog", "show", "N 206").stdout
    assert text.startswith("Cylindrical roller bearing NU206 (ISO)\n")
    assert (
        "rollers z                  13\n" in text
        and "effective length L_we      8.79180  mm\n" in text
    )
    doc = json.loads(run("catalog", "show", "NU312", "--format", "json").stdout)
    assert (doc["rollers"], doc["roller_diameter"], doc["method"]) == (12, 19.0, "derived z")
    lines = run("catalog", "--bore", "30").stdout.splitlines()
    assert lines[2].split()[-2:] == ["ball", "set"]
    assert lines[4].endswith("  GOST (D_w read, z derived)")
    assert lines[9].startswith("6406 ") and lines[9].endswith("  -")  # 64xx: no default maker
    assert lines[10].startswith("61806 ") and lines[10].endswith("  NSK (derived)")


def test_warnings_of_several_cases_name_their_case() -> None:
    r = run("solve", "6205", "-F", "500kN", "--method", "all")
    lines = r.stderr.splitlines()
    assert lines[:2] == OVERLOAD_WARNINGS.splitlines()[:2]  # shared: given once, as they are
    assert [x.split(":")[1].strip() for x in lines[2:]] == [
        "exact",
        "continuum",
        "stribeck",
        "palmgren",
    ]
    assert all("above 4200 MPa" in x for x in lines[2:])
    # near C0 only the largest C5 clearance crosses 4200 MPa: that warning names its case
    r = run("solve", "6205", "-F", "8000N", "-G", "C5", "--clearance-pick", "range")
    assert r.stderr == (
        "Warning: static safety factor s0 = C0/P0 = 0.981 is below 1 (ISO 76: P0 = F_r = 8000 N, "
        "C0 = 7850 N): the raceways deform permanently\n"
        "Warning: the load F_r = 8000 N is above the basic static rating C0 = 7850 N\n"
        "Warning: G_r max: maximum contact pressure 4215.9 MPa (inner contact, heaviest ball "
        "4357.11 N) is above 4200 MPa, the pressure of the static rating of ball bearings (ISO 76)\n"
    )
