"""``bearingload table life`` at --speed solves every row as ``solve --speed`` solves it: a
ball bearing's clearances (a pair's preloads) with each ball's centrifugal force and gyroscopic
moment, in one vectorised call; --quasi-static the static model. Every row equals solve's
answer at that clearance (preload) to the printed digits, csv and json; the model is named
(solve's json key ``model``; the static model at a speed: ``ball_dynamics``); what the ball
dynamics refuse or leave unbalanced is one Error line naming --quasi-static."""

from __future__ import annotations

import csv
import io
import json

import pytest
from click.testing import CliRunner

from bearingload.cli import main

CLEARANCES = ["-10um", "0", "10um", "40um"]
#: The keys of a table row solve's json case has (relative_life is the table's own).
ROW_KEYS = ("free_contact_angle", "loaded_balls", "contact_angle_max", "q_max",
            "reference_rating_life", "rating_life", "reference_rating_life_hours")  # fmt: skip
#: The table's conditions solve's json case has.
CONDITION_KEYS = ("load", "axial_load", "rotating", "cage_angle", "dynamic_rating",
                  "equivalent_load", "static_rating", "rating_life_hours", "speed",
                  "ball_density")  # fmt: skip
PAIR = ["7205BDB", "-F", "1kN", "-A", "200N"]
PRELOADS = ["0", "100N", "300N", "1kN"]


def _run(*args: str):
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


def _ok(*args: str) -> str:
    out = _run(*args)
    assert out.exit_code == 0, out.output
    return out.stdout


def _case(*args: str) -> dict:
    (case,) = json.loads(_ok("solve", *args, "--format", "json"))["cases"]
    return case


@pytest.mark.parametrize(
    ("load", "speed", "solve_extra"),
    [
        (["-F", "1kN"], ["--speed", "10000"], []),
        (["-F", "1kN"], ["--speed", "8000", "--ball-density", "3200"], []),
        (["-F", "2kN", "-A", "500N"], ["--speed", "12000"], []),
        # the static rows are the combined engine's at F_a = 0 (solve -A 0): solve's radial
        # engine, which solve 6205 --quasi-static takes, is not the table's
        (["-F", "1kN"], ["--speed", "10000", "--quasi-static"], ["-A", "0"]),
    ],
)
def test_every_row_is_solves_case_at_that_clearance(load, speed, solve_extra):
    table = ["table", "life", "-b", "6205", *load, *speed, "--clearances", ",".join(CLEARANCES)]
    doc = json.loads(_ok(*table, "--format", "json"))
    sheet = list(csv.DictReader(io.StringIO(_ok(*table, "--format", "csv"))))
    heads = {h.split(" [")[0]: h for h in sheet[0]}
    zero = None
    for g, row, line in zip(CLEARANCES, doc["rows"], sheet, strict=True):
        case = _case("6205", *load, *speed, *solve_extra, "--clearance", g)
        assert row["clearance"] == case["clearance"]
        keys = [k for k in ROW_KEYS if k in row]
        assert len(keys) >= 6 and ("contact_angle_max" in keys) == ("-A" in load)
        assert {k: row[k] for k in keys} == {k: case[k] for k in keys}, g
        assert {k: float(line[heads[k]]) for k in keys} == {k: case[k] for k in keys}, g
        if g == "0":
            zero = case["reference_rating_life"]
    assert zero is not None
    for row in doc["rows"]:
        assert row["relative_life"] == pytest.approx(row["reference_rating_life"] / zero, 1e-9)
    conds = [k for k in CONDITION_KEYS if k in doc]
    assert {k: doc[k] for k in conds} == {k: case[k] for k in conds}
    dynamics = "--quasi-static" not in speed
    assert ("ball_density" in conds) == dynamics and "speed" in conds
    if dynamics:
        assert doc["model"] == case["model"] and "ball dynamics" in doc["model"]
        assert "ball_dynamics" not in doc
    else:
        assert "model" not in doc and doc["ball_dynamics"].startswith("Ball dynamics left out")


@pytest.mark.parametrize(
    "speed", [["--speed", "10000"], ["--speed", "30000"], ["--speed", "3000", "--quasi-static"]]
)
def test_the_film_is_solves_at_every_clearance(speed):
    """The film took each row's free contact angle alpha_0; solve takes the heaviest ball's
    (0.383450 against 0.381873 µm at 10 000 rpm, about 1 % apart at 30 000 rpm): now equal."""
    load, extra = ["-F", "1kN", "-A", "300N"], ["--viscosity", "20", "--roughness", "0.2um"]
    table = ["table", "life", "-b", "6205", *load, *speed, *extra, "--clearances", "20um,40um"]
    rows = json.loads(_ok(*table, "--format", "json"))["rows"]
    for g, row in zip(("20um", "40um"), rows, strict=True):
        case = _case("6205", *load, *speed, *extra, "--clearance", g)
        for key in ("film_thickness", "film_ratio", "modified_reference_rating_life"):
            assert row[key] == case[key], (g, key)


def test_the_notes_name_the_model():
    args = ("table", "life", "-b", "6205", "-F", "1kN", "--clearances", "0,10um")
    for fmt in ("table", "markdown"):
        fast = _ok(*args, "--speed", "10000", "--format", fmt)
        assert "Speed: ball dynamics: centrifugal force and gyroscopic moment" in fast
        assert "balls of 7850 kg/m^3" in fast and "left out" not in fast
        static = _ok(*args, "--speed", "10000", "--quasi-static", "--format", fmt)
        assert "Ball dynamics left out: the static model (--quasi-static" in static
        assert "Speed:" not in static
        assert "Ball dynamics" not in _ok(*args, "--format", fmt)
    assert "balls of 3200 kg/m^3" in _ok(*args, "--speed", "1e4", "--ball-density", "3200")


@pytest.mark.parametrize(
    "speed",
    [["--speed", "10000"], ["--speed", "10000", "--quasi-static"],
     ["--speed", "8000", "--ball-density", "3200"]],
)  # fmt: skip
def test_every_pair_row_is_solves_pair_at_that_preload(speed):
    table = ["table", "life", "-b", *PAIR, *speed, "--preloads", ",".join(PRELOADS)]
    lines = _ok(*table, "--format", "csv").splitlines()
    assert len(lines) == 1 + 2 * len(PRELOADS)
    doc = json.loads(_ok(*table, "--format", "json"))
    for k, fp in enumerate(PRELOADS):
        solved = _ok("solve", *PAIR, *speed, "--preload", fp, "--format", "csv")
        assert solved.splitlines() == [lines[0], *lines[1 + 2 * k : 3 + 2 * k]], fp
        case = _case(*PAIR, *speed, "--preload", fp)
        row = doc["rows"][k]
        assert {k: v for k, v in row.items() if k != "bearings"} == {
            k: case[k] for k in row if k != "bearings"
        }
        assert "reference_rating_life_hours" in row and row["speed"] == case["speed"]
        for mine, theirs in zip(row["bearings"], case["bearings"], strict=True):
            assert mine == {k: theirs[k] for k in mine}
        assert doc["model"] == case["model"]
    text = _ok(*table)
    assert "L10rh [h]" in text
    if "--quasi-static" in speed:
        assert "Speed: --quasi-static: the pair is solved by the static model" in text
    else:
        assert "ball dynamics" in doc["model"]
        assert "outer-raceway control in both bearings (Jones 1960" in text


@pytest.mark.parametrize(
    ("args", "code", "words"),
    [
        (["-b", "6205", "-F", "1kN", "--speed", "60000"], 2,
         "Invalid value for '--speed': n d_m must be at most 2e+06 mm/min"),
        (["-b", "6205", "-F", "1kN", "--speed", "10000", "--rotating", "outer"], 2,
         "Invalid value for '--rotating': the ball dynamics at '--speed' are coded"),
        (["-b", "6205", "-F", "1kN", "--speed", "1000", "-K", "3e5"], 2,
         "Invalid value for '--stiffness': the ball dynamics at '--speed' need"),
        (["-b", *PAIR, "--preloads", "0,100N", "--speed", "60000"], 2,
         "Invalid value for '--speed': n d_m must be at most 2e+06 mm/min"),
        (["-b", "7205BDB", "-F", "1e-6N", "--preloads", "0,1e-6N", "--speed", "6000"], 2,
         "Invalid value for '--load': the loads are too small against the ball forces"),
    ],
)  # fmt: skip
def test_what_the_dynamics_refuse_names_quasi_static(args, code, words):
    out = _run("table", "life", *args)
    assert out.exit_code == code and out.stdout == ""
    line = out.stderr.splitlines()[-1]  # after click's usage lines
    assert line.startswith(f"Error: {words}") and "Traceback" not in out.stderr
    assert "--quasi-static" in line
    assert _run("table", "life", *args, "--quasi-static").exit_code == 0


@pytest.mark.parametrize("pair", [False, True])
def test_rows_the_dynamics_leave_unbalanced_name_quasi_static(monkeypatch, pair):
    """A ConvergenceError of the ball dynamics: one Error line naming --quasi-static, exit 1."""
    from bearingload.errors import ConvergenceError

    def unbalanced(*_args, **_kwargs):
        raise ConvergenceError("ball-dynamics ring and ball equilibrium", 7, 1e-3,
                               {"speed": 10000.0}, {"speed": "rpm"})  # fmt: skip

    where = "pair_speed.solve_pair_high_speed" if pair else "high_speed.solve_high_speed"
    module, name = where.split(".")
    monkeypatch.setattr(f"bearingload.models.{module}.{name}", unbalanced)
    args = ["-b", *PAIR, "--preloads", "0,100N"] if pair else ["-b", "6205", "-F", "1kN"]
    out = _run("table", "life", *args, "--speed", "10000")
    assert out.exit_code == 1 and out.stdout == ""
    (line,) = out.stderr.splitlines()
    assert line.startswith("Error: ball-dynamics ring and ball equilibrium did not converge")
    way = "" if pair else " (the ball dynamics left out)"  # a pair: solve's words
    assert line.endswith(f"; '--quasi-static' gives the static model{way}")


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["-b", "6205", "-F", "1kN", "--quasi-static"],
         "Invalid value for '--quasi-static': it needs '--speed'"),
        (["-b", "6205", "-F", "1kN", "--speed", "1000", "--quasi-static", "--ball-density", "3e3"],
         "Invalid value for '--ball-density': it enters the ball dynamics at '--speed'"),
        (["-b", *PAIR, "--preloads", "0,1kN", "--ball-density", "3e3"],
         "Invalid value for '--ball-density': it enters the ball dynamics at '--speed'"),
        (["-b", "6205", "-F", "1e-7N", "--speed", "1000"],
         "Invalid value for '--load': the loads are too small for the combined solver"),
    ],
)  # fmt: skip
def test_the_options_of_the_dynamics_are_checked(args, words):
    out = _run("table", "life", *args)
    assert out.exit_code == 2 and out.stdout == ""
    line = out.stderr.splitlines()[-1]  # after click's usage lines
    assert line.startswith(f"Error: {words}") and "Traceback" not in out.stderr
    assert "radial solver" not in line  # table life has none: every row is the combined one's


def test_table_k_refuses_the_dynamics():
    out = _run("table", "k", "--quasi-static")
    assert out.exit_code == 2
    assert out.stderr.splitlines()[-1] == (
        "Error: --quasi-static cannot be used with table k: table k and kq are the papers' "
        "static design tables (no speed); the ball dynamics at '--speed' are solved by 'table "
        "life', 'solve' and 'sweep' (docs/speed.md)"
    )


def test_rows_on_the_side_of_the_inner_groove_are_named():
    """The ball dynamics' known limit (a loaded inner contact at 90°), which solve warns of ball
    by ball, is named once by its rows, as solve warns at each of them."""
    args = ("6205", "-F", "1kN", "-A", "300N", "--speed", "50000")
    out = _run("table", "life", "-b", *args, "--clearances", "0,150um,200um", "--format", "json")
    assert out.exit_code == 0
    side = [w for w in json.loads(out.stdout)["warnings"] if "sits at 90°" in w]
    assert side == [
        "at G_r = 150, 200 µm a loaded inner contact sits at 90°, on the side of the inner "
        "groove, where the ball dynamics hold the ball (a real ball rides onto the groove "
        "shoulder) and overstate its orbit speed and centrifugal force: those rows are outside "
        "what the model describes"
    ]
    for g, warned in (("0", False), ("150um", True), ("200um", True)):
        solved = _run("solve", *args, "--clearance", g)
        assert ("the loaded inner contact sits at 90°" in solved.stderr) == warned, g


def test_table_life_conditions_give_the_speed_as_given(capsys):
    """``table life --bearing 6205 -F 1kN --speed 12345`` printed 'shaft speed n = 1.234e+04
    rpm' (4 digits: 12340, not the 12345 given; solve prints 12345); the conditions line now
    keeps 6 digits, as solve's tables."""
    from tests.cli_helpers import run_entry

    code, out, err = run_entry(
        capsys,
        "table",
        "life",
        "--bearing",
        "6205",
        "-F",
        "1kN",
        "--speed",
        "12345",
        "--viscosity",
        "20.25",
    )
    assert code == 0, err
    assert "shaft speed n = 12345 rpm" in out, out
    assert "operating viscosity nu = 20.25 mm^2/s" in out, out
