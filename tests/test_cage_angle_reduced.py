"""A cage angle is reduced to [0, 360°) and echoed so: a negative angle within rounding of 0
(-1e-320°, which ``np.mod`` takes to 360; -1e-13°, which it takes to 359.9999999999999, printed
360) is 0°, in every engine and front door."""

import json

import numpy as np
import pytest

from bearingload.validate import reduced_angle

from .cli_helpers import invoke


@pytest.mark.parametrize(
    ("angle", "reduced"),
    [
        (-1e-320, 0.0),
        (-1e-17, 0.0),
        (-1e-13, 0.0),
        (-3e-13, 0.0),
        (-1e-12, 359.999999999999),
        (-0.0, 0.0),
        (-1e-6, 359.999999),
        (-10.0, 350.0),
        (725.0, 5.0),
        (360.0, 0.0),
    ],
)
def test_an_angle_is_reduced_to_one_turn(angle, reduced):
    for got in (reduced_angle(angle), reduced_angle(np.array([angle]))[0]):
        assert got == reduced and np.copysign(1.0, got) == 1.0  # no 360, no -0


@pytest.mark.parametrize(
    "args",
    [
        ("6205", "-F", "1kN"),
        ("6205", "-F", "1kN", "-A", "10N"),
        ("6205", "-F", "1kN", "--speed", "3000"),
        ("7205BDB", "-F", "1kN", "-A", "10N", "--preload", "100N"),
        ("7205BDB", "-F", "1kN", "-A", "10N", "--preload", "100N", "--speed", "3000"),
    ],
)
@pytest.mark.parametrize("angle", ["-1e-320", "-1e-13"])
def test_solve_echoes_a_cage_angle_just_below_0_as_0(args, angle):
    text = invoke("solve", *args, f"--cage-angle={angle}").output
    assert "cage angle 0°" in text and "360" not in text
    doc = json.loads(invoke("solve", *args, f"--cage-angle={angle}", "--format", "json").stdout)
    angles = [c["cage_angle"] for c in doc["cases"]]
    angles += [b["cage_angle"] for c in doc["cases"] for b in c.get("bearings", [])]
    assert angles and all(a == 0.0 for a in angles)
    docs = doc["cases"] + [b for c in doc["cases"] for b in c.get("bearings", [])]
    balls = [d["ball_angles"][0] for d in docs if "ball_angles" in d]
    assert balls and all(a == 0.0 for a in balls)


def test_batch_echoes_a_cage_angle_just_below_0_as_0(tmp_path):
    path = tmp_path / "cases.csv"
    path.write_text(
        "bearing,load,axial_load,cage_angle\n6205,1000N,10N,-1e-320\n6205,1000N,,-1e-17\n"
        "6205,1000N,10N,-1e-13\n6205,1000N,,-1e-13\n",
        encoding="utf-8",
    )
    rows = invoke("batch", str(path), "--format", "json").stdout
    assert [r["cage_angle"] for r in json.loads(rows)["cases"]] == [0.0, 0.0, 0.0, 0.0]


def test_the_library_solvers_reduce_the_cage_angle():
    from bearingload import solve
    from bearingload.models.combined import solve_combined

    assert solve(9, 1000.0, 1e5, cage_angle=-1e-320).cage_angle == 0.0
    assert list(solve(9, np.array([1e3, 2e3]), 1e5, cage_angle=-1e-320).cage_angle) == [0, 0]
    combined = solve_combined(
        9, 1000.0, 10.0, ball_diameter=7.938, pitch_diameter=38.5, cage_angle=-1e-320
    )
    assert combined.cage_angle == 0.0
    assert solve(9, 1000.0, 1e5, cage_angle=-1e-13).cage_angle == 0.0


def test_the_tables_take_the_cage_angle_within_one_turn():
    """table k's header and json: -1e-320 and -0 are a ball under the load (0°, z = 1 kept,
    which needs its ball on the load line), -10 is 350° as solve gives it."""
    for angle in ("-1e-320", "-0"):
        text = invoke("table", "k", f"--cage-angle={angle}", "--z-max", "3").stdout
        assert "a ball under the load" in text.splitlines()[0]
        assert [line.split()[0] for line in text.splitlines()[4:7]] == ["1", "2", "3"]
        doc = invoke("table", "k", f"--cage-angle={angle}", "--z-max", "3", "--format", "json")
        assert '"cage_angle": -0.0' not in doc.stdout and '"cage_angle": 0.0' in doc.stdout
    head = invoke("table", "k", "--cage-angle=-10", "--z-max", "3").stdout.splitlines()[0]
    assert "cage angle 350°" in head


@pytest.mark.parametrize(
    "args",
    [
        ("6205", "-F", "1kN"),
        ("6205", "-F", "1kN", "-A", "10N"),
        ("6205", "-F", "1kN", "--speed", "3000"),
    ],
)
def test_a_ball_just_below_a_whole_turn_is_at_0(args):
    # a cage 1e-13° below a pitch (z = 9: 40°) puts ball 9 at 360° - 1e-13°, which was printed
    # at 360.000 (json 359.9999999999999): it is reduced as the cage angle is, to 0
    cage = f"--cage-angle={40.0 - 1e-13!r}"
    doc = json.loads(invoke("solve", *args, cage, "--format", "json").stdout)
    angles = doc["cases"][0]["ball_angles"]
    assert angles[-1] == 0.0 and angles[0] == pytest.approx(40.0, abs=1e-12)
    assert "360" not in invoke("solve", *args, cage).output
