"""Units that catch mistakes: an implausible bare number is refused with the likely unit, and the
usual slips (a space before the unit, a decimal comma) get a hint instead of an unrelated error."""

from __future__ import annotations

import json
import math

import pytest

from bearingload.errors import InputError
from bearingload.units import parse_cage_angle, parse_quantity

from .cli_helpers import invoke, run_entry

HAND = ["solve", "-z", "8", "-F", "300kgf", "-K", "4700kgf/mm^1.5"]


@pytest.mark.parametrize(
    "args, message",
    [
        (["solve", "306", "-F", "300kgf", "--modulus", "210"],
         "Error: Invalid value for '--modulus': a bare 210 is 210 MPa, implausible for a Young's "
         "modulus (bare numbers are MPa; plausible 1000 to 1e+07 MPa): did you mean 210GPa?"),
        (["solve", "306", "-F", "300kgf", "--modulus", "2.1e11"], "did you mean 2.1e+11Pa?"),
        ([*HAND, "-G", "20"],
         "Error: Invalid value for '--clearance' / '-G': a bare 20 is 20 mm, implausible for a "
         "radial clearance (bare numbers are mm; plausible -1 to 1 mm): did you mean 20um?"),
        (["solve", "306", "-F", "300kgf", "-G", "7"], "(the GOST clearance group 7 is written G7)"),
        ([*HAND, "-G", "0,02"], "write the decimal point, not a comma: 0.02"),
        (["solve", "-z", "8", "-F", "300", "kgf", "-K", "4700kgf/mm^1.5"],
         "Error: Invalid value for '-F': '300 kgf': write a number and its unit without a space, e.g. 300kgf"),
        (["table", "k", "-G", "20", "um"], "Error: Invalid value for '-G': '20 um': write a number and its unit without a space"),
    ],
)  # fmt: skip
def test_slips_get_one_line_with_the_likely_meaning(capsys, args, message):
    code, out, err = run_entry(capsys, *args)
    assert code == 2 and out == "" and err.count("\n") == 1 and "Traceback" not in err
    assert message in err, err


def test_written_units_are_used_as_they_are(capsys):
    """The refusal is for bare numbers only: with its unit a number means what it says."""
    code, out, _ = run_entry(capsys, *HAND, "-G", "1.5mm")
    assert code == 0 and "G_r = 1500 µm" in out
    code, out, _ = run_entry(capsys, "solve", "306", "-F", "300kgf", "--modulus", "210GPa")
    assert code == 0
    assert parse_quantity("210000", "modulus") == 210000.0
    assert parse_quantity("0.99", "length", parameter="clearance") == 0.99
    with pytest.raises(InputError, match="did you mean 1um"):
        parse_quantity("1", "length", parameter="clearance")
    assert parse_quantity("20", "length", parameter="ball_diameter") == 20.0  # no rule there


@pytest.mark.parametrize(
    "spelling, degrees",
    [("0.1rad", 0.1 * 180.0 / math.pi), ("5.5", 5.5), ("5.5deg", 5.5), ("5.5°", 5.5),
     ("5.5DEG", 5.5), ("30mrad", 0.03 * 180.0 / math.pi), ("0.1 rad", 0.1 * 180.0 / math.pi),
     ("330arcmin", 5.5), ("330'", 5.5), ("19800arcsec", 5.5), ('19800"', 5.5), ("330′", 5.5)],
)  # fmt: skip
def test_cage_angle_spellings_are_those_of_batch(tmp_path, spelling, degrees):
    """solve and table read --cage-angle as batch reads its cage_angle column: degrees by
    default, deg, rad, mrad, arcmin (or '), arcsec (or ") (solve used to refuse '0.1rad')."""
    solve = [*HAND, "-G", "20um", "--format", "json"]
    got = json.loads(invoke(*solve, "--cage-angle", spelling).output)["cases"][0]
    want = json.loads(invoke(*solve, "--cage-angle", repr(degrees)).output)["cases"][0]
    assert got["cage_angle"] == pytest.approx(degrees, rel=1e-9)  # json: 10 digits
    assert got["q_max"] == want["q_max"]
    cases = tmp_path / "c.csv"
    cell = spelling if spelling != "5.5DEG" else "5.5deg"  # batch's units are case-sensitive
    cases.write_text(f"balls,load,stiffness,clearance,cage_angle\n8,300kgf,4700kgf/mm^1.5,20um,"
                     f"{cell}\n", encoding="utf-8")  # fmt: skip
    row = json.loads(invoke("batch", str(cases), "--format", "json").output)["cases"][0]
    assert row["q_max"] == pytest.approx(got["q_max"], rel=1e-9)
    table = invoke("table", "k", "--z-max", "9", "--cage-angle", spelling, "--format", "json")
    assert table.exit_code == 0


def test_cage_angle_parser_half_and_refusals():
    assert parse_cage_angle("Half") == "half" and parse_cage_angle(12) == 12.0
    with pytest.raises(InputError, match="'half'"):
        parse_cage_angle("12 kgf")
    with pytest.raises(InputError, match="cage_angle"):
        parse_cage_angle("nan")


def test_bad_cage_angle_is_one_error_line(capsys):
    code, out, err = run_entry(capsys, *HAND, "--cage-angle", "0.1radian")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith("Error: Invalid value for '--cage-angle': unknown unit 'radian'"), err


@pytest.mark.parametrize(
    ("text", "degrees"),
    [("10arcmin", 10 / 60), ("10 arcmin", 10 / 60), ("10'", 10 / 60), ("10′", 10 / 60),
     ("36arcsec", 0.01), ('36"', 0.01), ("36″", 0.01), ("-3ARCMIN", None)],
)  # fmt: skip
def test_minutes_and_seconds_of_arc(text, degrees):
    """The misalignment a deep-groove bearing tolerates is quoted in arcmin (2-10'); the
    warnings speak in arcmin: the options read it (units are case-sensitive, as for forces)."""
    if degrees is None:
        with pytest.raises(InputError, match="unknown unit 'ARCMIN'.*arcmin"):
            parse_quantity(text, "angle")
        return
    assert parse_quantity(text, "angle") == pytest.approx(degrees, rel=1e-15)
