"""Units that catch mistakes: an implausible bare number is refused with the likely unit, and the
usual slips (a space before the unit, a decimal comma) get a hint instead of an unrelated error."""

from __future__ import annotations

import json
import math

import pytest

from bearingload.errors import InputError
from bearingload.units import HINT_RANGE, UNITS, parse_cage_angle, parse_quantity

from .cli_helpers import invoke, run_entry

HAND = ["solve", "-z", "8", "-F", "300kgf", "-K", "4700kgf/mm^1.5"]


@pytest.mark.parametrize(
    "args, message",
    [
        (["solve", "306", "-F", "300kgf", "--modulus", "210"],
         "Error: Invalid value for '--modulus': a bare 210 is 210 MPa, implausible for a Young's "
         "modulus (bare numbers are MPa; plausible at least 1000 and below 1e+07 MPa): did you mean "
         "210GPa?"),
        (["solve", "306", "-F", "300kgf", "--modulus", "2.1e11"], "did you mean 2.1e+11Pa?"),
        ([*HAND, "-G", "20"],
         "Error: Invalid value for '--clearance' / '-G': a bare 20 is 20 mm, implausible for a "
         "radial clearance (bare numbers are mm; plausible at least -1 and below 1 mm): did you mean "
         "20um?"),
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


#: (option, bare number) of implausible bare numbers on every option with a plausibility rule.
IMPLAUSIBLE = [
    ("--clearance", "5"), ("--clearance", "20"), ("--clearance", "5000"), ("--clearance", "-3"),
    ("--modulus", "210"), ("--modulus", "2.1e11"), ("--modulus", "1e20"), ("--modulus", "10"),
    ("--speed", "1e6"), ("--speed", "1e9"),
    ("--viscosity", "1e6"), ("--viscosity", "1e7"), ("--viscosity", "1e-5"),
    ("--viscosity", "1e-9"), ("--viscosity", "0.05"), ("--viscosity", "0.009"),
    ("--roughness", "0.2"), ("--roughness", "50"),
    ("--revolutions", "1e-308"), ("--revolutions", "36"), ("--revolutions", "1e20"),
]  # fmt: skip
KIND = {"--clearance": ("length", "clearance"), "--modulus": ("modulus", "modulus"),
        "--speed": ("speed", "speed"), "--viscosity": ("viscosity", "viscosity"),
        "--roughness": ("length", "roughness"),
        "--revolutions": ("revolutions", "revolutions")}  # fmt: skip


@pytest.mark.parametrize(("option", "bare"), IMPLAUSIBLE)
def test_a_unit_hint_names_a_unit_that_makes_the_number_plausible_or_none(capsys, option, bare):
    """The hints offered units that did not help: 'did you mean 1e+09 in another unit (e.g.
    1e+09rad/s)' for a bare 1e9 rpm (1e9 rad/s is a larger speed still), '1e+06cSt' for a bare
    1e6 mm^2/s (cSt is mm^2/s), under 'plausible 0.1 to 1e+06' that 1e6 itself seemed to meet.
    Now a hint's number and unit pass the same plausibility rule, or there is no hint; the range
    printed excludes the number refused."""
    import re

    # the static radial engine (--quasi-static), which takes --revolutions at a speed
    base = ["solve", "6205", "-F", "1kN", "--speed", "3000", "--viscosity", "20", "--quasi-static"]
    code, out, err = run_entry(capsys, *base, option, bare)
    assert code == 2 and out == "" and err.count("\n") == 1, err
    low, high = map(
        float, re.search(r"plausible (?:at least|above) (\S+) and below (\S+) ", err).groups()
    )
    assert not low <= float(bare) < high  # the range printed excludes what was refused
    kind, name = KIND[option]
    hint = re.search(r"did you mean (\S+)\?", err)
    usual = HINT_RANGE.get(kind, (low, high))  # where a hinted reading must fall
    if hint is None:
        assert all(
            not usual[0] <= float(bare) * factor < usual[1] for factor in UNITS[kind].values()
        ), err  # no unit of the kind makes it plausible (a usual value, for a viscosity)
        return
    value = parse_quantity(hint.group(1), kind, parameter=name)
    assert low <= value < high and usual[0] <= value < usual[1], err
    code, _, err = run_entry(capsys, *base, option, hint.group(1))
    assert code == 0, err  # what the hint says is a case solve solves


@pytest.mark.parametrize(
    ("text", "hint"),
    [("400", "did you mean 400K (126.85 °C)?"), ("300", "did you mean 300K"), ("1000", None),
     ("-300", None), ("300C", None), ("600K", None)],
)  # fmt: skip
def test_a_bare_temperature_out_of_range_offers_kelvin_where_it_fits(capsys, text, hint):
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--speed", "3000", "--oil",
                               "VG68", "--temperature", text)  # fmt: skip
    assert code == 2 and err.count("\n") == 1 and "-60 to 250 °C" in err, err
    assert (hint in err) if hint else ("did you mean" not in err)


def test_a_ball_diameter_too_small_for_the_class_clearance_names_the_ball_diameter(capsys):
    """A 6205 with --ball-diameter 0.01 (the class CN clearance, 12.5 um, exceeds half of it)
    was refused as a bad '--clearance' the user never gave, with 'did you mean 0.0125um?'."""
    code, _, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--ball-diameter", "0.01")
    assert code == 2 and err.count("\n") == 1
    assert err.startswith("Error: Invalid value for '--ball-diameter': 0.01 mm is too small"), err
    assert "did you mean" not in err
    hand = ["solve", "-z", "8", "--ball-diameter", "1", "--pitch-diameter", "10", "-F", "10"]
    assert "did you mean 0.6um?" in run_entry(capsys, *hand, "-G", "0.6")[2]
    assert "did you mean" not in run_entry(capsys, *hand, "-G", "0.6mm")[2]


def test_the_lower_bound_printed_for_a_roughness_is_one_it_accepts(capsys):
    """A bare -0.2 --roughness said 'plausible at least 0 and below 0.01 mm', yet a roughness of
    0 is refused ('must be greater than 0 mm'): the range printed contradicted the refusal."""
    base = ["solve", "6205", "-F", "1kN", "--speed", "3000", "--viscosity", "20", "--roughness"]
    code, out, err = run_entry(capsys, *base, "-0.2")
    assert code == 2 and "plausible above 0 and below 0.01 mm" in err, err
    code, out, err = run_entry(capsys, *base, "0")
    assert code == 2 and "greater than 0" in err, err


@pytest.mark.parametrize(
    ("option", "what"),
    [("--viscosity", "an operating kinematic viscosity"),
     ("--viscosity-40", "an oil's kinematic viscosity at 40 °C"),
     ("--viscosity-100", "an oil's kinematic viscosity at 100 °C")],
)  # fmt: skip
def test_each_viscosity_is_named_for_what_it_is(capsys, option, what):
    """A bare 1e7 --viscosity-40 was 'implausible for an operating kinematic viscosity': nu_40 is
    the oil's viscosity at 40 °C (its datasheet's), nu at the operating temperature is another."""
    oil = ["--oil", "VG68"] if option == "--viscosity-100" else []
    args = ["solve", "6205", "-F", "1kN", "--speed", "3000", *oil, option, "1e7"]
    code, out, err = run_entry(capsys, *args, "--temperature", "60")
    assert code == 2 and out == "" and err.count("\n") == 1, err
    assert f"implausible for {what} (" in err, err
    assert ("operating" in err) == (option == "--viscosity"), err


@pytest.mark.parametrize(
    ("option", "bare", "hint"),
    [("--viscosity", "0.05", None), ("--viscosity", "0.02", None),
     ("--viscosity", "6.8e-5", "6.8e-05m^2/s"), ("--viscosity", "0.009", "0.009m^2/s"),
     ("--viscosity-40", "0.05", None), ("--viscosity-40", "6.8e-5", "6.8e-05m^2/s")],
)  # fmt: skip
def test_a_viscosity_hint_is_a_usual_viscosity(capsys, option, bare, hint):
    """A bare --viscosity 0.05 got 'did you mean 0.05m^2/s?': 5e4 mm^2/s, an oil near its pour
    point, no likely reading of 0.05 (the plausible range goes to 1e6 mm^2/s only to refuse no
    real oil). A hint now reads the number as a usual viscosity, 1 to 1e4 mm^2/s, or there is
    none; the bare unit is mm^2/s (= cSt), never suggested."""
    temperature = ["--temperature", "60"] if option == "--viscosity-40" else []
    args = ["solve", "6205", "-F", "1kN", "--speed", "3000", option, bare, *temperature]
    code, out, err = run_entry(capsys, *args)
    assert code == 2 and out == "" and err.count("\n") == 1, err
    assert (f"did you mean {hint}?" in err) if hint else ("did you mean" not in err), err


@pytest.mark.parametrize(
    ("option", "kind", "parameter"),
    [("--clearance", "length", "clearance"), ("--modulus", "modulus", "modulus")],
)
def test_the_help_states_exactly_the_bare_numbers_refused(option, kind, parameter):
    """--clearance's help said 'a bare number of 1 mm or more is refused', yet -3 is refused
    too; --modulus's said 'outside 1000 to 1e7 MPa', yet 1e7 itself is refused. The help now
    names both bounds as the refusal applies them: the lower one accepted, the upper refused."""
    import re

    text = " ".join(invoke("solve", "--help").output.split())
    unit = {"length": "mm", "modulus": "MPa"}[kind]
    bounds = re.search(
        rf"{option}.*?a bare number below (\S+) {unit} or of (\S+) {unit} or more is refused",
        text,
        flags=re.IGNORECASE,
    )
    assert bounds is not None, text
    low, high = map(float, bounds.groups())
    assert parse_quantity(repr(low), kind, parameter=parameter) == low
    assert parse_quantity(repr(high * (1 - 1e-9)), kind, parameter=parameter) < high
    for refused in (low - abs(low) * 1e-9 - 1e-12, high):
        with pytest.raises(InputError, match="implausible"):
            parse_quantity(repr(refused), kind, parameter=parameter)


def test_implausible_revolutions_are_refused_with_the_likely_unit(capsys):
    """--revolutions 1e-308 was taken (1e-314 x 10^6 rev) and gave an allowable load of
    6.5e108 N; a bare 36 (Kuzmenko's N = 36 x 10^6 rev) gave 30 C. A bare life outside 1e5 to
    1e15 rev is refused in one line, with the unit that makes it plausible (Mrev = 10^6 rev),
    and the number with its unit is the case solve solves."""
    import re

    base = ["solve", "6205", "-F", "1kN", "--format", "json"]
    for bare, hint in (("1e-308", None), ("36", "36Mrev"), ("1e20", None), ("99999", "99999Mrev")):
        code, out, err = run_entry(capsys, *base, "--revolutions", bare)
        assert code == 2 and out == "" and err.count("\n") == 1, err
        assert err.startswith("Error: Invalid value for '--revolutions': a bare ") and (
            "plausible at least 100000 and below 1e+15 rev" in err
        ), err
        assert (f"did you mean {hint}?" in err) if hint else ("did you mean" not in err), err
    allowable = []
    for given in ("36Mrev", "36e6", "3.6e7rev", "1e5"):
        code, out, err = run_entry(capsys, *base, "--revolutions", given)
        assert code == 0, err
        allowable.append(json.loads(out)["cases"][0]["allowable_load"])
    assert allowable[0] == allowable[1] == allowable[2] == pytest.approx(14000 / 36 ** (1 / 3))
    assert allowable[3] == pytest.approx(14000 / 0.1 ** (1 / 3))
    code, _, err = run_entry(capsys, *base, "--revolutions", "1e303Mrev")
    assert code == 2 and re.search(r"'1e303Mrev' overflows", err), err


@pytest.mark.parametrize(
    ("text", "rpm"),
    [
        ("3000RPM", 3000.0),
        ("3000Rpm", 3000.0),
        ("3000 R/MIN", 3000.0),
        ("3000 1/MIN", 3000.0),
        ("50hz", 3000.0),
        ("50HZ", 3000.0),
        ("100RAD/S", 3000.0 / math.pi),
        ("50 1/S", 3000.0),
    ],
)
def test_speed_units_are_read_in_any_case(text, rpm):
    """--speed 3000RPM was refused (only lowercase rpm): speed unit names are read whatever
    their case (none differs from another only in case)."""
    from bearingload.units import parse_quantity

    assert parse_quantity(text, "speed", parameter="speed") == pytest.approx(rpm, rel=1e-15)


def test_speed_in_capitals_on_the_command_line_other_units_keep_their_case(capsys):
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--speed", "3000RPM")
    assert code == 0 and "shaft speed n" in out, err
    from bearingload.units import parse_quantity

    # lengths and forces stay case-sensitive: mm vs Mm, mN vs MN must not become one unit
    for text, kind in (("20UM", "length"), ("1KN", "force"), ("1MM", "length")):
        with pytest.raises(InputError):
            parse_quantity(text, kind)
    assert parse_quantity("1kN", "force") == 1000.0


@pytest.mark.parametrize(
    ("option", "given", "meant"),
    [
        ("-F", "3KN", "3kN"),
        ("-F", "3kn", "3kN"),
        ("-F", "300kg", "300kgf"),
        ("-F", "3000lb", "3000lbf"),
        ("--moment", "5N.m", "5N*m"),
        ("--clearance", "20UM", "20um"),
    ],
)
def test_a_misspelt_unit_is_refused_with_the_unit_meant(capsys, option, given, meant):
    """3KN, 3kn, 300kg, 3000lb, 5N.m were refused with the list of units alone: the one Error
    line names the unit meant (never reads it: a kilogram is no force, and mm and Mm differ),
    and the spelling suggested is accepted."""
    base = ["solve", "6205", "-F", "3kN"]
    code, out, err = run_entry(capsys, *base, option, given)
    assert code == 2 and out == "" and err.count("\n") == 1, err
    assert f"did you mean {meant}?" in err, err
    assert run_entry(capsys, *base, option, meant)[0] == 0


def test_a_temperature_in_fahrenheit_is_refused_with_its_celsius(capsys):
    """--temperature 160F said only what is allowed: it names 71.11C, (160 - 32)/1.8 °C."""
    oil = ("solve", "6205", "-F", "3kN", "--speed", "3000", "--oil", "VG68", "--temperature")
    code, _, err = run_entry(capsys, *oil, "160F")
    assert code == 2 and "did you mean 71.11C (160 °F)?" in err, err
    assert run_entry(capsys, *oil, "71.11C")[0] == 0


def test_a_unit_of_no_likeness_gets_no_suggestion():
    with pytest.raises(InputError) as exc:
        parse_quantity("3parsec", "force", parameter="load")
    assert "did you mean" not in exc.value.message and "allowed: N, kN" in exc.value.message


@pytest.mark.parametrize(
    ("args", "option", "meant"),
    [
        (("-F", "3000", "--moment", "5"), "--moment", "5Nm"),
        (("-F", "3"), "--load", "3kN"),
        (("-F", "3000", "-K", "4700"), "--stiffness", "4700kgf/mm^1.5"),
    ],
)
def test_a_bare_number_implausible_for_the_bearing_names_its_unit(capsys, args, option, meant):
    """Bare numbers that pass every fixed range were used as typed: solve 6205 -F 3000 --moment
    5 as 5 N mm, -F 3 as 3 N (a hint about the clearance followed), -K 4700 replaced the 6205's
    Hertz stiffness 274 869 N/mm^1.5 without a word. Judged against the bearing (C0 = 7850 N,
    C0 d_m/2, its Hertz stiffness: bearings.plausible) they are refused naming the unit meant;
    the number with its unit written is used as it is, and the unit suggested is accepted."""
    from .cli_helpers import error_line

    line = error_line(capsys, "solve", "6205", *args)
    assert line.startswith(f"Error: Invalid value for '{option}': a bare "), line
    assert f"did you mean {meant}?" in line, line
    bare = args[-1]
    base = {"--moment": "Nmm", "--load": "N", "--stiffness": "N/mm^1.5"}[option]
    for written in (f"{bare}{base}", meant):
        fixed = [*args[:-1], written]
        assert run_entry(capsys, "solve", "6205", *fixed)[0] == 0, written
    assert "274869" in line or option != "--stiffness"


def test_bare_numbers_in_the_bearing_range_and_rings_by_hand_are_used():
    """Plausible bare numbers pass, a ring by hand has no scale to judge by, and 0 is no load."""
    for args in (
        ["6205", "-F", "3000", "--moment", "5000"],
        ["6205", "-F", "8", "-A", "0"],
        ["6205", "-F", "3000", "-K", "274869"],
        ["-z", "8", "-F", "3", "-K", "4700"],
    ):
        assert invoke("solve", *args).exit_code == 0, args


@pytest.mark.parametrize(
    ("bearing", "option", "bare", "meant", "catalogue"),
    [
        ("6205", "--dynamic-rating", "14", "14kN", "C = 14000 N"),
        ("6205", "--static-rating", "7.85", "7.85kN", "C0 = 7850 N"),
        ("7205BDB", "--dynamic-rating", "16.7", "16.7kN", "C = 16700 N"),
    ],
)
def test_a_bare_load_rating_implausible_for_the_bearing_names_its_unit(
    capsys, bearing, option, bare, meant, catalogue
):
    """solve 6205 --dynamic-rating 14 (14 kN meant) took 14 N and printed L10 = 2.7e-6 x 10^6
    rev; --dynamic-rating 1e-300 an L10 of 0. A bare rating is judged against the catalogue's
    (a tenth to ten times it); the number with its unit is used as it is."""
    from .cli_helpers import error_line

    args = ("solve", bearing, "-F", "1kN", *(("--preload", "300N") if "DB" in bearing else ()))
    line = error_line(capsys, *args, option, bare)
    assert line.startswith(f"Error: Invalid value for '{option}': a bare {bare} is "), line
    assert f"({catalogue}; plausible" in line and f"did you mean {meant}?" in line, line
    assert "did you mean" not in error_line(capsys, *args, option, "1e-300")
    for written in (f"{bare}N", meant):
        assert run_entry(capsys, *args, option, written)[0] == 0, written


def test_a_bare_rating_is_judged_alike_by_solve_analyse_many_and_batch(capsys, tmp_path):
    """A case of analyse_many and a row of batch judge a bare rating against the catalogue's,
    as solve does, and a bare load against the catalogue's C0 where the case gives its own
    static rating (C0 = 785 N made a bare load of 3 N plausible there)."""
    from bearingload import analyse_many

    cases = [
        {"bearing": "6205", "load": 1000, "dynamic_rating": 14},
        {"bearing": "6205", "load": 1000, "dynamic_rating": "14N"},
        {"bearing": "6205", "load": 1000, "axial_load": 100, "static_rating": 7.85},
        {"bearing": "6205", "load": 3, "static_rating": 785},
        {"bearing": "7205BDB", "load": 1000, "preload": 300, "dynamic_rating": 16.7},
        {"bearing": "7205BDB", "load": 1000, "preload": 300, "dynamic_rating": 16700},
    ]
    many = analyse_many(cases)
    assert many.rows == [1, 5]
    for i, name in (
        (0, "dynamic_rating"),
        (2, "static_rating"),
        (3, "load"),
        (4, "dynamic_rating"),
    ):
        assert many.errors[i].parameter == name and "implausible" in many.errors[i].message
    path = tmp_path / "ratings.csv"
    path.write_text("bearing,load,dynamic_rating\n6205,1000,14\n6205,1000,14000\n")
    code, out, err = run_entry(capsys, "batch", str(path), "--format", "csv")
    assert code == 1 and "row 2: dynamic_rating: a bare 14 is 14 N" in err
    assert [line.split(",", 1)[0] for line in out.splitlines()[1:]] == ["2", "3"]
