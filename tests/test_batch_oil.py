"""``bearingload batch`` with the oil columns (oil, viscosity_40, viscosity_100, viscosity_index,
temperature): the operating viscosity of each row by solve's one rule
(:func:`bearingload.bearings.oil.operating_viscosity`), every row equal to ``solve --format json``
of the same case, rows with and without oil cells in one file, each row independent of the
others, refused rows skipped with solve's reason naming the column."""

from __future__ import annotations

import csv
import io
import json
import re

import mpmath
import pytest
from click.testing import CliRunner

from bearingload.batch.read import Block, read_header
from bearingload.batch.solve import BatchSolver
from bearingload.bearings.oil import OIL_INPUTS, operating_viscosity, viscosity_100_of_index
from bearingload.cli import main
from bearingload.errors import InputError
from bearingload.plan.case import OIL_PARAMS
from bearingload.units import parse_temperature

from .cli_helpers import SolvedRows, run_entry

#: (batch cells, solve options) of one case each: the oil by grade or nu_40, nu_100 given or
#: from the VI (given or the default 95), temperatures in °C and K, units in the cells, a
#: roller bearing, and rows without oil cells (a viscosity, no lubricant at all).
RADIAL = [
    ({"bearing": "6205", "load": "2kN", "speed": "3000", "oil": "VG68", "temperature": "70"},
     ["6205", "-F", "2kN", "--speed", "3000", "--oil", "VG68", "--temperature", "70"]),
    ({"bearing": "6205", "load": "1.4kN", "speed": "3000", "oil": "VG68",
      "viscosity_100": "8.6cSt", "temperature": "70C"},
     ["6205", "-F", "1.4kN", "--speed", "3000", "--oil", "VG68", "--viscosity-100", "8.6cSt",
      "--temperature", "70C"]),
    ({"bearing": "6205", "load": "1.4kN", "speed": "3000", "viscosity_40": "6.8e-5m^2/s",
      "viscosity_100": "8.6", "temperature": "343.15K", "reliability": "99"},
     ["6205", "-F", "1.4kN", "--speed", "3000", "--viscosity-40", "6.8e-5m^2/s",
      "--viscosity-100", "8.6", "--temperature", "343.15K", "--reliability", "99"]),
    ({"bearing": "6306", "load": "3kN", "clearance": "C3", "speed": "1500",
      "oil": "ISO VG 100", "viscosity_index": "140", "temperature": "85"},
     ["6306", "-F", "3kN", "-G", "C3", "--speed", "1500", "--oil", "ISO VG 100",
      "--viscosity-index", "140", "--temperature", "85"]),
    ({"bearing": "NU206", "load": "5kN", "speed": "2000", "viscosity_40": "46",
      "temperature": "-20", "contamination": "typical", "roughness": "0.1um"},
     ["NU206", "-F", "5kN", "--speed", "2000", "--viscosity-40", "46", "--temperature", "-20",
      "--contamination", "typical", "--roughness", "0.1um"]),
    ({"bearing": "6205", "load": "1kN", "speed": "3000", "viscosity": "20"},
     ["6205", "-F", "1kN", "--speed", "3000", "--viscosity", "20"]),
    ({"bearing": "6205", "load": "1kN", "speed": "3000"},
     ["6205", "-F", "1kN", "--speed", "3000"]),
    ({"bearing": "6205", "load": "1kN"}, ["6205", "-F", "1kN"]),
]  # fmt: skip
#: Combined rows: at a speed both solve the ball dynamics (docs/speed.md).
COMBINED = [
    ({"bearing": "6205", "load": "2kN", "axial_load": "1kN", "speed": "3000", "oil": "VG46",
      "temperature": "50"},
     ["6205", "-F", "2kN", "-A", "1kN", "--speed", "3000", "--oil", "VG46",
      "--temperature", "50"]),
    ({"bearing": "6205", "load": "2kN", "axial_load": "500N", "speed": "1500", "viscosity": "30"},
     ["6205", "-F", "2kN", "-A", "500N", "--speed", "1500", "--viscosity",
      "30"]),
    ({"bearing": "6205", "load": "1kN", "axial_load": "0", "speed": "1500", "viscosity_40": "32",
      "viscosity_index": "110", "temperature": "313.15K"},
     ["6205", "-F", "1kN", "-A", "0", "--speed", "1500", "--viscosity-40",
      "32", "--viscosity-index", "110", "--temperature", "313.15K"]),
]  # fmt: skip
HEAD = ("bearing", "load", "axial_load", "clearance", "speed", "reliability", "viscosity", "oil",
        "viscosity_40", "viscosity_100", "viscosity_index", "temperature", "contamination",
        "roughness")  # fmt: skip


def _file(cases: list[dict[str, str]], combined: bool) -> str:
    head = [k for k in HEAD if k != "axial_load" or combined]
    lines = [",".join(head)] + [",".join(c.get(k, "") for k in head) for c in cases]
    return "\n".join(lines) + "\n"


def _run(*args: str, text: str | None = None):
    return SolvedRows(CliRunner().invoke(main, list(args), input=text, catch_exceptions=False))


def _json(text: str) -> dict:
    out = _run("batch", "-", "--format", "json", text=text)
    assert out.exit_code in (0, 1), out.output
    return json.loads(out.stdout)


@pytest.mark.parametrize("cases", [RADIAL, COMBINED], ids=["radial", "combined"])
def test_every_row_equals_solve(cases):
    """Each row, in a file of rows with and without oil cells, gives solve's numbers (every key
    solve writes: nu, nu_1, kappa, a_ISO, the modified lives, the film ...) to 1e-12, and its
    oil cells as given."""
    doc = _json(_file([c for c, _ in cases], cases is COMBINED))
    assert doc["skipped"] == [] and len(doc["cases"]) == len(cases)
    for row, (cells, args) in zip(doc["cases"], cases, strict=True):
        solved = _run("solve", *args, "--format", "json")
        assert solved.exit_code == 0, solved.output
        expected = json.loads(solved.stdout)["cases"][0]
        shared = [k for k in expected if k in row and k != "warnings"]
        assert {"viscosity", "kappa", "a_iso", "modified_rating_life"} <= set(shared) or (
            "viscosity" not in expected
        )
        for key in shared:
            want, got = expected[key], row[key]
            if isinstance(want, float) and isinstance(got, float):
                assert got == pytest.approx(want, rel=1e-12, abs=0.0), (args, key)
            else:
                assert got == want, (args, key)
        assert row["warnings"] == [w.removeprefix("Warning: ") for w in solved.stderr.splitlines()]
        for name in ("oil", "viscosity_40", "viscosity_100", "viscosity_index", "temperature"):
            assert (row[name] is None) == (name not in cells), (args, name)
        if "oil" in cells:
            assert row["oil"] == cells["oil"]
        if "temperature" in cells:
            assert row["temperature"] == pytest.approx(parse_temperature(cells["temperature"]))


def test_a_row_does_not_depend_on_the_others():
    """Each row alone gives the line it gives among the others (csv, every column)."""
    for cases, combined in ((RADIAL, False), (COMBINED, True)):
        lines = _run("batch", "-", "--format", "csv",
                     text=_file([c for c, _ in cases], combined)).stdout.splitlines()  # fmt: skip
        for i, (cells, _) in enumerate(cases):
            alone = _run("batch", "-", "--format", "csv", text=_file([cells], combined))
            head, line = alone.stdout.splitlines()
            assert head == lines[0]
            assert line.split(",", 1)[1] == lines[i + 1].split(",", 1)[1], i


def test_the_viscosity_against_an_independent_walther():
    """The viscosity column of the rows with nu_40 and nu_100 (grade or value, °C or K) equals
    ASTM D341 through the two points, computed with mpmath at 50 digits, to 1e-12; one with the
    VI equals D341 through nu_100 of that VI."""
    mpmath.mp.dps = 50

    def walther(nu40: float, nu100: float, celsius: float) -> float:
        y = [mpmath.log10(mpmath.log10(mpmath.mpf(v) + mpmath.mpf("0.7"))) for v in (nu40, nu100)]
        t = [mpmath.mpf(c) + mpmath.mpf("273.15") for c in (40, 100, celsius)]
        b = (y[0] - y[1]) / (mpmath.log10(t[1]) - mpmath.log10(t[0]))
        a = y[0] + b * mpmath.log10(t[0])
        return float(mpmath.power(10, mpmath.power(10, a - b * mpmath.log10(t[2]))) - 0.7)

    text = (
        "bearing,load,speed,oil,viscosity_40,viscosity_100,viscosity_index,temperature\n"
        "6205,1kN,3000,VG68,,8.6,,70\n"
        "6205,1kN,3000,,68,8.6,,343.15K\n"
        "6205,1kN,3000,VG220,,19,,25C\n"
        "6205,1kN,3000,,32,,110,-10\n"
    )
    header = read_header(text.splitlines()[0].split(","))
    lines = [line.split(",") for line in text.splitlines()[1:]]
    chunk = BatchSolver(header).solve(Block(list(range(2, 6)), lines))
    assert chunk.errors == [] and chunk.rows == [2, 3, 4, 5]
    nu = [float(v) for v in chunk.values["viscosity"]]
    wanted = [walther(68, 8.6, 70), walther(68, 8.6, 70), walther(220, 19, 25),
              walther(32, float(viscosity_100_of_index(32.0, 110.0)), -10)]  # fmt: skip
    assert nu == pytest.approx(wanted, rel=1e-12, abs=0.0)
    assert nu[0] == operating_viscosity(oil="VG68", viscosity_100=8.6, temperature=70.0)[0]


def _as_columns(line: str) -> str:
    """Solve's Error line in batch's words: options as columns, ``column: reason``."""
    text = line.removeprefix("Error: ")
    text = re.sub(r"--([a-z0-9-]+)", lambda m: m.group(1).replace("-", "_"), text)
    text = re.sub(r"^Missing option '([a-z0-9_]+)': ", r"\1: missing: ", text)
    text = re.sub(r"^Missing option '([a-z0-9_]+)' / '([a-z0-9_]+)': ", r"\1 / \2: missing: ", text)
    text = re.sub(r"^Invalid value for '([a-z0-9_]+)' / '([a-z0-9_]+)': ", r"\1 / \2: ", text)
    text = re.sub(r"^Invalid value for '([a-z0-9_]+)': ", r"\1: ", text)
    return re.sub(r"^([a-z0-9_]+) cannot be used with ([a-z0-9_]+): ",
                  r"\1: cannot be used with '\2': ", text)  # fmt: skip


#: Rows solve refuses (cells, solve's oil options), each with the column its reason names.
REFUSED = [
    ({"oil": "VG68"}, ["--oil", "VG68"], "temperature"),
    ({"viscosity": "20", "oil": "VG68", "temperature": "70"},
     ["--viscosity", "20", "--oil", "VG68", "--temperature", "70"], "oil"),
    ({"viscosity": "20", "viscosity_index": "95"}, ["--viscosity", "20", "--viscosity-index", "95"],
     "viscosity_index"),
    ({"oil": "VG68", "viscosity_40": "60", "temperature": "70"},
     ["--oil", "VG68", "--viscosity-40", "60", "--temperature", "70"], "oil / viscosity_40"),
    ({"temperature": "70"}, ["--temperature", "70"], "oil / viscosity_40"),
    ({"oil": "VG68", "viscosity_100": "8", "viscosity_index": "95", "temperature": "70"},
     ["--oil", "VG68", "--viscosity-100", "8", "--viscosity-index", "95", "--temperature", "70"],
     "viscosity_index"),
    ({"oil": "VG67", "temperature": "70"}, ["--oil", "VG67", "--temperature", "70"], "oil"),
    ({"oil": "VG5", "temperature": "70"}, ["--oil", "VG5", "--temperature", "70"],
     "viscosity_index"),
    ({"viscosity_40": "5", "viscosity_index": "200", "temperature": "70"},
     ["--viscosity-40", "5", "--viscosity-index", "200", "--temperature", "70"],
     "viscosity_index"),
    ({"oil": "VG68", "viscosity_100": "80", "temperature": "70"},
     ["--oil", "VG68", "--viscosity-100", "80", "--temperature", "70"], "viscosity_100"),
    ({"viscosity_40": "0", "temperature": "70"}, ["--viscosity-40", "0", "--temperature", "70"],
     "viscosity_40"),
    ({"oil": "VG68", "temperature": "300"}, ["--oil", "VG68", "--temperature", "300"],
     "temperature"),
    ({"oil": "VG68", "temperature": "500K"}, ["--oil", "VG68", "--temperature", "500K"],
     "temperature"),
]  # fmt: skip


def test_refused_rows_are_skipped_with_solves_reason(capsys):
    """Each refused row is skipped (never the file) with the reason of solve's Error line for
    the same case, naming the column; the good rows around them are written as alone."""
    good = {"bearing": "6205", "load": "1kN", "speed": "3000", "oil": "VG46", "temperature": "60"}
    cases = [good] + [
        {"bearing": "6205", "load": "1kN", "speed": "3000", **c} for c, _, _ in REFUSED
    ]
    doc = _json(_file([*cases, good], False))
    assert [c["row"] for c in doc["cases"]] == [2, len(cases) + 2]
    reasons = {s["row"]: s["reason"] for s in doc["skipped"]}
    assert sorted(reasons) == list(range(3, len(cases) + 2))
    for row, (_, options, column) in enumerate(REFUSED, 3):
        code, out, err = run_entry(
            capsys, "solve", "6205", "-F", "1kN", "--speed", "3000", *options
        )
        assert code == 2 and out == "", options
        (line,) = err.strip().splitlines()
        assert reasons[row] == _as_columns(line), options
        assert reasons[row].startswith(f"{column}: "), (options, reasons[row])
    alone = _json(_file([good], False))["cases"][0]
    for case in doc["cases"]:
        assert {k: v for k, v in case.items() if k != "row"} == {
            k: v for k, v in alone.items() if k != "row"
        }


def test_an_oil_without_speed_or_bearing_is_refused_naming_its_column():
    """nu_1 needs the speed (solve: --viscosity needs --speed, here the viscosity is the
    oil's): the row names its first oil column; a ring by hand takes no oil (as no viscosity)."""
    text = ("bearing,balls,stiffness,load,speed,viscosity_40,temperature\n"
            "6205,,,1kN,,68,70\n,8,1e5,1kN,3000,68,70\n6205,,,1kN,3000,68,70\n")  # fmt: skip
    out = _run("batch", "-", "--format", "csv", text=text)
    assert out.exit_code == 1
    errors = out.stderr.splitlines()
    assert errors[0] == (
        "Skipped: row 2: viscosity_40: needs the shaft speed ('speed') for the rated viscosity nu_1"
    )
    assert errors[1] == (
        "Skipped: row 3: speed, viscosity_40, temperature: need a bearing designation or the "
        "ball geometry ('ball_diameter' and 'pitch_diameter'): with 'balls' and 'stiffness' "
        "alone they would be ignored"
    )
    assert [r["row"] for r in csv.DictReader(io.StringIO(out.stdout))] == ["4"]
    assert _run("solve", "6205", "-F", "1kN", "--viscosity-40", "68", "--temperature",
                "70").exit_code == 2  # fmt: skip


def test_units_of_the_oil_columns_as_the_options_read_them():
    """temperature: bare °C, C, °C, degC, K in a cell, a header unit for its bare numbers;
    viscosities: bare mm^2/s, cSt, m^2/s. Equal temperatures give equal rows."""
    same = ["70", "70C", "70°C", "70degC", "343.15K"]
    text = "bearing,load,speed,oil,temperature\n" + "".join(
        f"6205,1kN,3000,VG68,{t}\n" for t in same
    )
    rows = _json(text)["cases"]
    assert len(rows) == len(same)
    assert all(r["temperature"] == pytest.approx(70.0, rel=1e-12) for r in rows)
    assert len({r["viscosity"] for r in rows}) == 1
    kelvin = _json("bearing,load,speed,oil,temperature [K]\n6205,1kN,3000,VG68,343.15\n")
    assert kelvin["cases"][0]["viscosity"] == rows[0]["viscosity"]
    nu = _json("bearing,load,speed,viscosity_40,viscosity_100,temperature\n"
               "6205,1kN,3000,68,8.6,70\n6205,1kN,3000,68cSt,8.6e-6m^2/s,70\n")["cases"]  # fmt: skip
    assert nu[0]["viscosity"] == nu[1]["viscosity"]
    bad = _run("batch", "-", text="bearing,load,temperature [F]\n6205,1kN,70\n")
    assert bad.exit_code == 2 and "temperature [F]: allowed units: °C, C, degC, K" in bad.stderr


def test_the_output_columns():
    """The oil columns the file has, as given, just before the operating viscosity they give;
    with an oil column but no viscosity column, every column the viscosity feeds."""
    out = _run("batch", "-", "--format", "csv",
               text="bearing,load,speed,temperature,oil\n6205,1kN,3000,70,VG68\n")  # fmt: skip
    head = out.stdout.splitlines()[0].split(",")
    at = head.index("viscosity [mm^2/s]")
    assert head[at - 2 : at] == ["oil", "temperature [°C]"]
    for key in ("kappa", "a_iso", "modified_rating_life [10^6 rev]", "film_thickness [mm]"):
        assert key in head
    plain = _run("batch", "-", "--format", "csv", text="bearing,load,speed\n6205,1kN,3000\n")
    assert not {"oil", "temperature [°C]", "viscosity [mm^2/s]"} & set(plain.stdout.split(","))


def test_one_rule_one_vocabulary():
    """The command line's oil options are the library's inputs, in one order."""
    assert OIL_PARAMS == OIL_INPUTS
    with pytest.raises(InputError, match="temperature: missing"):
        operating_viscosity(oil="VG68")
    assert operating_viscosity() == (None, None)
    assert operating_viscosity(12.5) == (12.5, None)


def test_parse_temperature():
    assert parse_temperature("-60") == -60.0 and parse_temperature(" 250 C ") == 250.0
    assert parse_temperature("373.15K") == pytest.approx(100.0, rel=1e-15)
    for text, hint in (("300", "did you mean 300K"), ("-61", ""), ("warm", ""), ("70F", "")):
        with pytest.raises(InputError, match="give the operating temperature") as exc:
            parse_temperature(text)
        assert hint in str(exc.value)


@pytest.mark.parametrize(
    "cells, args",
    [
        ({"bearing": "6205", "load": "1kN", "speed": "5000", "viscosity": "68"},
         ["6205", "-F", "1kN", "--speed", "5000", "--viscosity", "68"]),
        ({"bearing": "6205", "load": "1kN", "axial_load": "200N", "speed": "5000",
          "viscosity_40": "68", "viscosity_index": "120", "temperature": "40"},
         ["6205", "-F", "1kN", "-A", "200N", "--speed", "5000", "--viscosity-40", "68",
          "--viscosity-index", "120", "--temperature", "40"]),
    ],
)  # fmt: skip
def test_solve_json_lists_the_warnings_of_the_lives(cells, args):
    """A warning of the lives (kappa above 4) is printed by solve on stderr, listed under the
    case's and the document's ``warnings`` of solve's json, and under the batch row's: the
    json of solve carried only the warnings of the load distribution."""
    solved = _run("solve", *args, "--format", "json")
    assert solved.exit_code == 0, solved.output
    printed = [w.removeprefix("Warning: ") for w in solved.stderr.splitlines()]
    assert any("kappa" in w for w in printed)
    doc = json.loads(solved.stdout)
    assert doc["cases"][0]["warnings"] == printed and doc["warnings"] == printed
    row = _json(_file([cells], "axial_load" in cells))["cases"][0]
    assert row["warnings"] == printed


def test_table_life_json_lists_the_warnings_of_the_lives():
    """table life's json lists the warning of the lives (kappa above 4) it prints on stderr
    (its warnings were those of the load distribution only)."""
    out = _run("table", "life", "-b", "6205", "-F", "1kN", "--speed", "5000", "--viscosity", "68",
               "--format", "json")  # fmt: skip
    assert out.exit_code == 0, out.output
    printed = [w.removeprefix("Warning: ") for w in out.stderr.splitlines()]
    assert any("kappa" in w for w in printed)
    assert json.loads(out.stdout)["warnings"] == printed


@pytest.mark.parametrize("name", ['"ISO VG\n68"', "ISO VG\u202868", "ISO VG\x0c68"])
def test_an_oil_name_with_a_line_break_is_written_as_one_record(name):
    """The oil's cell is echoed as given: a line break inside it (quoted in the input, so
    quoted in the output) or a character where str.splitlines breaks a line split the csv
    output of its row in two, and the rows no longer matched their lines: an internal error,
    exit 3. Each row is one csv record, beside a skipped row, whatever the chunk size."""
    text = f"bearing,load,oil,temperature,speed\n6205,1kN,{name},60,3000\n6205,-1,VG68,60,3000\n"
    for chunk in ("1", "10"):
        out = CliRunner().invoke(
            main, ["batch", "-", "--format", "csv", "--chunk-size", chunk], input=text
        )
        assert out.exit_code == 1, out.output
        rows = list(csv.DictReader(io.StringIO(out.stdout, newline="")))
        after = "4" if "\n" in name else "3"  # a record is numbered by its first line
        assert [(r["row"], r["skipped"] == "") for r in rows] == [("2", True), (after, False)]
        assert rows[0]["oil"] == name.strip('"') and rows[0]["q_max [N]"]
