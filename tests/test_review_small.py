"""Small findings of an independent review (overlapping balls, hints and labels at speed, speed
units): each test fails on the code before its fix."""

from __future__ import annotations

import math
from typing import Any

import pytest

from bearingload.bearings.resolve import resolve_bearing
from bearingload.errors import InputError

from .cli_helpers import run_entry


def _error(capsys: Any, *args: str) -> str:
    """The one ``Error:`` line of a refused command line (exit 2, nothing on stdout)."""
    code, out, err = run_entry(capsys, *args)
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and lines[0].startswith("Error:"), err
    return lines[0]


_OVERLAP = ("-z", "9", "--ball-diameter", "30", "--pitch-diameter", "38.5")


@pytest.mark.parametrize(
    "command",
    [
        ("solve", *_OVERLAP, "-F", "1kN"),
        ("solve", *_OVERLAP, "-F", "1kN", "--speed", "3000"),
        ("solve", *_OVERLAP, "-F", "1kN", "--speed", "3000", "--quasi-static"),
        ("solve", *_OVERLAP, "-F", "1kN", "-A", "100N"),
        ("solve", *_OVERLAP, "-F", "1kN", "--contact-angle", "25"),
        ("sweep", *_OVERLAP, "-F", "1kN"),
        ("table", "life", *_OVERLAP, "-F", "1kN"),
    ],
)
def test_overlapping_balls_are_refused(capsys, command):
    """9 balls of 30 mm on a 38.5 mm pitch circle overlap (adjacent centres are
    d_m sin(pi/9) = 13.17 mm apart); every engine solved it. One Error line naming
    --ball-diameter and the largest diameter allowed."""
    line = _error(capsys, *command)
    chord = 38.5 * math.sin(math.pi / 9)
    assert "'--ball-diameter'" in line and f"{chord:.6g} mm" in line, line
    assert "d_m sin(pi/z)" in line


def test_overlapping_balls_refused_by_the_library_and_batch(capsys, tmp_path):
    with pytest.raises(InputError) as exc:
        resolve_bearing(balls=9, ball_diameter=30.0, pitch_diameter=38.5)
    assert exc.value.parameter == "ball_diameter"
    # the limit itself: touching balls (a full complement) are accepted, a hair more is not
    chord = 38.5 * math.sin(math.pi / 9)
    assert resolve_bearing(balls=9, ball_diameter=chord, pitch_diameter=38.5).balls == 9
    with pytest.raises(InputError):
        resolve_bearing(balls=9, ball_diameter=chord * (1 + 1e-9), pitch_diameter=38.5)
    # one ball, and two balls below d_m, have no spacing rule to break
    assert resolve_bearing(balls=1, ball_diameter=30.0, pitch_diameter=38.5).balls == 1
    assert resolve_bearing(balls=2, ball_diameter=30.0, pitch_diameter=38.5).balls == 2
    path = tmp_path / "cases.csv"
    path.write_text("balls,ball_diameter,pitch_diameter,load\n9,30,38.5,1000\n9,12,38.5,1000\n")
    code, out, err = run_entry(capsys, "batch", str(path), "--format", "csv")
    assert "row 2: ball_diameter: 9 balls of 30 mm overlap" in err and code == 1, err
    assert len(out.strip().splitlines()) == 2  # header and the good row


@pytest.mark.parametrize("extra", [(), ("--speed", "3000"), ("--speed", "3000", "--quasi-static")])
def test_too_small_load_on_an_angular_bearing_names_no_radial_solver(capsys, extra):
    """solve 7205B -F 1e-9N (at speed or not) advised 'the radial solver, without an axial
    load, takes any load', which cannot solve an angular-contact bearing. The hint now says
    the combined solver is the only one and gives the smallest load; that load (printed rounded
    up) is solved statically."""
    line = _error(capsys, "solve", "7205B", "-F", "1e-9N", *extra)
    assert "radial solver" not in line and "radial engine" not in line, line
    assert "angular-contact bearing is solved by this solver only" in line, line
    smallest = line.split("it takes at least ")[1].split(" N")[0]
    code, out, err = run_entry(capsys, "solve", "7205B", "-F", f"{smallest}N")
    assert code == 0 and "Error" not in err, err


def test_ball_density_is_reported_at_speed(capsys):
    """--ball-density changed the answer but appeared nowhere in it: a ceramic-ball run could
    not be told from a steel one. json has ball_density [kg/m^3] (the batch column's key and
    unit), the terminal a row; a static solve has neither."""
    import json

    args = ("solve", "6205", "-F", "1kN", "--speed", "3000")
    for extra, rho in (((), 7850.0), (("--ball-density", "3200"), 3200.0)):
        code, out, err = run_entry(capsys, *args, *extra, "--format", "json")
        assert code == 0, err
        doc = json.loads(out)
        assert doc["cases"][0]["ball_density"] == pytest.approx(rho, rel=1e-12)
        assert doc["units"]["ball_density"] == "kg/m^3"
        code, out, err = run_entry(capsys, *args, *extra)
        row = [line for line in out.splitlines() if line.startswith("ball density")]
        assert len(row) == 1 and row[0].split()[-2:] == [f"{rho:.2f}", "kg/m^3"], row
    code, out, _ = run_entry(capsys, "solve", "6205", "-F", "1kN", "--format", "json")
    assert "ball_density" not in out
    code, out, _ = run_entry(capsys, *args, "--quasi-static")
    assert code == 0 and "ball density" not in out


def test_unloaded_ball_note_at_speed_names_the_inner_contact(capsys):
    """At speed a '-' ball's outer contact carries its centrifugal force (json: ball_loads_outer
    > 0 where ball_loads_inner is 0); the note said 'the ball carries no load'. It now says the
    inner contact carries none; the static note is unchanged."""
    import json

    args = ("solve", "6205", "-F", "1kN")
    code, out, _ = run_entry(capsys, *args, "--speed", "3000", "--format", "json")
    case = json.loads(out)["cases"][0]
    loose = [i for i, q in enumerate(case["ball_loads_inner"]) if q == 0.0]
    assert loose and all(case["ball_loads_outer"][i] > 0.0 for i in loose)
    code, out, _ = run_entry(capsys, *args, "--speed", "3000")
    assert code == 0 and "the ball carries no load" not in out
    assert "Contact angle '-': the ball's inner contact carries no load" in out
    assert "outer contact still carries the centrifugal force" in out
    code, out, _ = run_entry(capsys, *args, "-A", "0")
    assert code == 0 and "Contact angle '-': the ball carries no load" in out
    assert "inner contact" not in out


@pytest.mark.parametrize(
    ("text", "rpm"),
    [("3000RPM", 3000.0), ("3000Rpm", 3000.0), ("3000 R/MIN", 3000.0), ("3000 1/MIN", 3000.0),
     ("50hz", 3000.0), ("50HZ", 3000.0), ("100RAD/S", 3000.0 / math.pi), ("50 1/S", 3000.0)],
)  # fmt: skip
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


def test_batch_writes_the_ball_density_of_its_rows_at_speed(capsys, tmp_path):
    """solve's csv at speed has ball_density [kg/m^3]: a combined-load file with a speed column
    writes it too (the value used: the cell, else steel; blank where quasi_static is true), and
    a file without a speed column has no such column."""
    import csv
    import io

    path = tmp_path / "rows.csv"
    path.write_text(
        "bearing,load,axial_load,speed,ball_density,quasi_static\n"
        "6205,1000,0,3000,3200,\n6205,1000,0,3000,,\n6205,1000,0,3000,,true\n",
        encoding="utf-8",
    )
    code, out, err = run_entry(capsys, "batch", str(path), "--format", "csv")
    assert code == 0, err
    rows = list(csv.DictReader(io.StringIO(out)))
    assert [float(r["ball_density [kg/m^3]"] or "nan") for r in rows[:2]] == [3200.0, 7850.0]
    assert rows[2]["ball_density [kg/m^3]"] == ""
    path.write_text("bearing,load,axial_load\n6205,1000,0\n", encoding="utf-8")
    code, out, err = run_entry(capsys, "batch", str(path), "--format", "csv")
    assert code == 0 and "ball_density" not in out, err
