"""``bearingload sweep``: exact output of every format, errors, help, start-up."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import numpy as np
import pytest

from bearingload.studies.sweep import sweep

from .cli_helpers import invoke, run_entry

CASE = ("sweep", "-z", "9", "-F", "1kN", "-K", "1e5", "-G", "10um")

CSV_3 = """\
balls,load [N],stiffness [N/mm^1.5],clearance [mm],exponent,cage_angle [°],x [mm],y [mm],q_max [N],q_max_ball,loaded_balls,stiffness_matrix_11 [N/mm],stiffness_matrix_12 [N/mm],stiffness_matrix_21 [N/mm],stiffness_matrix_22 [N/mm],stiffness_radial [N/mm]
9,1000.0,100000.0,0.01,1.5,0.0,0.03472437386,0.0,512.4707383,1,5,52025.23487,0.0,0.0,27554.40218,52025.23487
9,1000.0,100000.0,0.01,1.5,20.0,0.03471268143,0.0,459.005443,1,4,52361.87697,0.0,0.0,30842.96794,52361.87697
9,1000.0,100000.0,0.01,1.5,40.0,0.03472437386,0.0,512.4707383,9,5,52025.23487,0.0,0.0,27554.40218,52025.23487
"""


def test_csv_exact_and_rectangular():
    out = invoke(*CASE, "--steps", "3", "--format", "csv")
    assert out.exit_code == 0
    assert out.output == CSV_3
    lines = out.output.splitlines()
    assert len({line.count(",") for line in lines}) == 1  # one rectangular block


def test_csv_is_byte_identical_run_to_run_and_written_atomically(tmp_path):
    target = tmp_path / "s.csv"
    first = invoke(*CASE, "--steps", "5", "--format", "csv", "-o", str(target))
    assert first.exit_code == 0 and first.output == ""
    once = target.read_bytes()
    invoke(*CASE, "--steps", "5", "--format", "csv", "-o", str(target))
    assert target.read_bytes() == once and b"\r" not in once
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.csv"]


def test_json_rows_summary_units_match_the_library():
    out = invoke(*CASE, "--steps", "7", "--format", "json")
    doc = json.loads(out.output)
    s = sweep(9, 1000.0, 1e5, 0.01, steps=7)
    assert [r["cage_angle"] for r in doc["rows"]] == pytest.approx(s.cage_angle.tolist())
    for i, row in enumerate(doc["rows"]):
        assert set(row) >= {"cage_angle", "x", "y", "q_max", "loaded_balls", "stiffness_matrix"}
        assert row["x"] == pytest.approx(s.x[i], rel=1e-9)
        assert row["y"] == pytest.approx(s.y[i], rel=1e-9, abs=1e-15)
        assert row["q_max"] == pytest.approx(s.q_max[i], rel=1e-9)
        assert row["q_max_ball"] == s.q_max_ball[i]
        assert row["loaded_balls"] == s.loaded_balls[i]
        block = [r[:2] for r in row["stiffness_matrix"][:2]]  # the 5x5's x, y block
        assert np.allclose(block, s.stiffness_matrix[i], rtol=1e-9, atol=1e-6)
    summary = doc["summary"]
    for key in ("x", "y", "q_max", "stiffness_radial"):
        sp = s.spread(key)
        assert summary[key]["min"] == pytest.approx(sp.min, rel=1e-9)
        assert summary[key]["max"] == pytest.approx(sp.max, rel=1e-9)
        assert summary[key]["peak_to_peak"] == pytest.approx(sp.peak_to_peak, rel=1e-9)
        assert summary[key]["mean"] == pytest.approx(sp.mean, rel=1e-9, abs=1e-15)
    assert summary["ripple_per_cage_revolution"] == 9
    assert summary["compensating_clearance"] == pytest.approx(s.compensating_clearance, rel=1e-9)
    assert doc["units"]["x"] == "mm" and doc["units"]["stiffness_matrix"].startswith("rows F_x")
    assert doc["units"]["compensating_clearance"].startswith("mm")
    assert (doc["balls"], doc["load"], doc["clearance"], doc["steps"]) == (9, 1000.0, 0.01, 7)


def test_table_shows_every_block_with_units():
    out = invoke(*CASE, "--steps", "9")
    text = out.output
    assert text.startswith(
        "Over one ball pitch (z = 9, F_r = 1000 N (101.972 kgf), K = 100000 N/mm^1.5, "
        "G_r = 10 µm (gap per side 5 µm), m = 1.5; cage angle 0 to 40° in 9 positions)\n"
    )
    lines = {ln[:35].strip(): ln.split() for ln in text.splitlines()}
    assert lines["ring displacement along the load x"][-5:] == [
        "34.7008", "34.7075", "34.7244", "0.02353", "µm",
    ]  # fmt: skip
    assert lines["radial stiffness dF_r/dx"][-5:] == ["52025.2", "52228.2", "52361.9", "336.6", "N/mm"]  # fmt: skip
    assert lines["ring displacement across the load y"][-5:] == [
        "-0.312488", "0", "0.312488", "0.6250", "µm",
    ]  # fmt: skip
    assert "ripple frequency (periods per cage revolution)         9  1/rev" in text
    assert "compensating clearance G_r                       10.6478  µm" in text
    assert "cage angle [°]   x [µm]     y [µm]  Q_max [N]  ball  loaded" in text
    # the whole output of every format: tests/golden/sweep_*.txt (test_golden.py)


def test_markdown():
    out = invoke(*CASE, "--steps", "3", "--format", "markdown")
    assert out.exit_code == 0
    assert out.output.startswith("### Over one ball pitch (z = 9")
    assert "| cage angle [°] |" in out.output


def test_catalogue_bearing_names_its_sources():
    out = invoke("sweep", "306", "--load", "300kgf", "--clearance", "C3", "--steps", "3")
    assert out.exit_code == 0
    assert "z and K (exact Hertz) of bearing 306; G_r: " in out.output
    assert "z = 8, F_r = 2941.99 N (300 kgf)" in out.output


def test_rollers_by_stiffness_and_exponent():
    out = invoke("sweep", "-z", "14", "-F", "10kN", "-K", "8e5", "-m", "10/9", "--steps", "3")
    assert out.exit_code == 0 and "K = 800000 N/mm^1.11111" in out.output


@pytest.mark.parametrize(
    "args, message",
    [
        (("sweep", "-F", "1kN", "-K", "1e5"), "Error: Missing option '--balls' / '-z'"),
        (("sweep", "-z", "9", "-F", "1kN"), "Error: Missing option '--stiffness' / '-K'"),
        ((*CASE, "--steps", "1"), "Error: Invalid value for '--steps': must be between 2 "),
        # said 'must be between 1 and 1000000 (got 0)', and 1 is refused
        ((*CASE, "--steps", "0"), "Error: Invalid value for '--steps': must be between 2 "),
        (
            ("sweep", "-z", "2", "-F", "1kN", "-K", "1e5"),
            "Error: Invalid value for '--balls': a sweep needs at least 3 balls",
        ),  # fmt: skip
        (("sweep", "-z", "9", "-F", "-1", "-K", "1e5"), "Error: Invalid value for '--load'"),
        (
            ("sweep", "306", "-F", "1kN", "-m", "10/9"),
            "Error: Invalid value for '--exponent': a ball bearing",
        ),  # fmt: skip
    ],
)
def test_errors_are_one_line_exit_2(capsys, args, message):
    code, out, err = run_entry(capsys, *args)
    assert code == 2 and out == ""
    assert err.startswith(message) and err.count("\n") == 1


@pytest.mark.parametrize(
    ("args", "kurochkin"),
    [(("6205", "-A", "100N"), False), (("-z", "9", "-K", "1e5"), False), (("-z", "7"), True)],
)
def test_a_sweep_without_a_load_says_the_radial_load_is_missing(capsys, args, kurochkin):
    """What is missing is the radial load (0 beside a thrust); Kurochkin's dimensionless mode,
    which takes no load, is offered only to a ring given by its balls alone."""
    code, out, err = run_entry(capsys, "sweep", *args)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith(
        "Error: Missing option '--load' / '-F' (the radial load F_r; 0 with an axial load or a "
        "moment"
    )
    assert ("--kurochkin-T" in err) is kurochkin


def test_error_leaves_no_output_file(capsys, tmp_path):
    target = tmp_path / "s.csv"
    code, _, err = run_entry(capsys, *CASE, "--steps", "0", "-o", str(target))
    assert code == 2 and not target.exists()


def test_help_has_examples_and_is_listed():
    out = invoke("sweep", "--help")
    assert out.exit_code == 0
    assert "Examples:" in out.output and "bearingload sweep -z 9" in out.output
    for option in ("--steps", "--plot", "--clearance-pick", "--format", "--ball-diameter"):
        assert option in out.output
    assert "sweep" in invoke("--help").output


def test_sweep_help_and_solve_import_no_matplotlib():
    code = (
        "import sys\n"
        "from bearingload.cli import main\n"
        "main.main(args=['solve', '-z', '8', '-F', '1', '-K', '1'], standalone_mode=False)\n"
        "print('matplotlib' in sys.modules)\n"
        "import bearingload.cli.sweep\n"
        "print('numpy' in sys.modules or 'matplotlib' in sys.modules)\n"
    )
    env = dict(os.environ)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip().splitlines()[-2:] == ["False", "True"]  # solve itself uses numpy
    fresh = subprocess.run(
        [sys.executable, "-c", "import sys, bearingload.cli.sweep; print('numpy' in sys.modules)"],
        capture_output=True,
        text=True,
        env=env,
    )
    assert fresh.stdout.strip() == "False"


def _sweep_json(*args: str) -> dict:
    out = invoke("sweep", *args, "--format", "json")
    assert out.exit_code == 0, out.output
    return json.loads(out.output)


def test_life_inputs_alone_keep_the_radial_engine_and_give_its_lives():
    """--rotating, --dynamic-rating or --speed without a load option switched sweep to the
    combined engine (another report; NU205 -C refused as 'a roller bearing'): input that only
    feeds the lives must not change the engine. The radial sweep now carries them: L10r at each
    cage position equal to solve's radial L10r there and to the combined sweep's (F_a = 0);
    L10 and L10h the same at every position; the ball loads those of the plain sweep. (The
    speed with --quasi-static: without it a ball bearing at speed is swept with the ball
    dynamics, as solve solves it; tests/test_sweep_speed.py.)"""
    base = ["6205", "-F", "1.4kN", "--steps", "5"]
    plain = _sweep_json(*base)
    lives = _sweep_json(*base, "--rotating", "outer", "--speed", "3000", "--quasi-static")
    assert "stiffness_matrix" in lives["rows"][0] and "axial" not in lives["rows"][0]
    for key in ("x", "y", "q_max", "stiffness_radial"):
        assert [r[key] for r in lives["rows"]] == [r[key] for r in plain["rows"]]
    assert lives["summary"]["rating_life"] == pytest.approx(1000.0)  # (14 kN / 1.4 kN)^3
    assert lives["summary"]["rating_life_hours"] == pytest.approx(1000.0e6 / (60 * 3000))
    assert lives["units"]["reference_rating_life"] == "10^6 rev"
    assert lives["units"]["reference_rating_life_hours"] == "h"
    combined = _sweep_json(*base, "-A", "0", "--rotating", "outer", "--speed", "3000",
                           "--quasi-static")  # fmt: skip
    for row, other in zip(lives["rows"], combined["rows"], strict=True):
        assert row["reference_rating_life"] == pytest.approx(
            other["reference_rating_life"], rel=1e-9
        )
        alone = json.loads(invoke("solve", "6205", "-F", "1.4kN", "--rotating", "outer",
                                  "--cage-angle", repr(row["cage_angle"]),
                                  "--format", "json").output)["cases"][0]  # fmt: skip
        assert row["reference_rating_life"] == pytest.approx(
            alone["reference_rating_life"], rel=1e-9
        )
        assert row["reference_rating_life_hours"] == pytest.approx(
            row["reference_rating_life"] * 1e6 / (60 * 3000), rel=1e-9
        )
    rated = _sweep_json("NU205", "-F", "1kN", "--steps", "3", "-C", "20kN")
    assert rated["summary"]["rating_life"] == pytest.approx(20.0 ** (10 / 3))
    assert [r["q_max"] for r in rated["rows"]] == [
        r["q_max"] for r in _sweep_json("NU205", "-F", "1kN", "--steps", "3")["rows"]
    ]


def test_rotating_is_refused_where_solve_refuses_it(capsys):
    """A roller bearing has no L10r for --rotating to select the ring of: the radial sweep
    refuses it with solve's message (it was refused as a roller under the combined engine)."""
    code, _, err = run_entry(capsys, "sweep", "NU205", "-F", "1kN", "--rotating", "inner")
    code_solve, _, err_solve = run_entry(capsys, "solve", "NU205", "-F", "1kN", "--rotating",
                                         "inner")  # fmt: skip
    assert code == code_solve == 2 and err == err_solve and err.count("\n") == 1
    assert "L10r is computed for ball bearings only" in err


@pytest.mark.parametrize(
    "case",
    [["6205", "-F", "1kN", "-G", "-0.9", "--speed", "3000"],  # deep preload, 11 GPa
     ["6205", "-F", "1kN", "-G", "0.9999"],  # play beyond C5, one ball at some angles
     ["6205", "-F", "20kN"],  # s0 < 1, F_r > C0, pressure
     ["NU206", "-F", "60kN"],
     ["-z", "7", "--ball-diameter", "11.5", "--pitch-diameter", "43.5", "-F", "30kN", "-G",
      "-100um"]],
)  # fmt: skip
def test_sweep_warns_as_solve_warns_on_the_same_case(capsys, case):
    """sweep 6205 -F 1kN -G -0.9 printed no warning where solve of the same case warns of an
    11 GPa contact pressure and a preload beyond the bound: sweep now gives solve's checks on
    the bearing (at the heaviest ball load of the pitch: at cage angle 0 in these cases, solve's)
    on stderr and in its JSON; only the one-loaded-ball finding names its cage angles. At a
    speed both solve the ball dynamics."""
    code, _, solve_err = run_entry(capsys, "solve", *case)
    assert code == 0
    code, out, sweep_err = run_entry(capsys, "sweep", *case, "--format", "json")
    assert code == 0
    one_ball = "only one ball carries the load"
    want = [w for w in solve_err.splitlines() if one_ball not in w]
    got = [w for w in sweep_err.splitlines() if one_ball not in w]
    assert want and got == want, (got, want)
    assert (one_ball in solve_err) <= (one_ball in sweep_err)  # solve's angle is in the pitch
    assert json.loads(out)["warnings"] == [w.removeprefix("Warning: ") for w in
                                           sweep_err.splitlines()]  # fmt: skip
