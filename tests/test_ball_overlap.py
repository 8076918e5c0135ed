"""Balls that overlap on their pitch circle (d_m sin(pi/z) below D_w) are refused by every
engine, the library and batch, naming --ball-diameter and the largest diameter allowed."""

from __future__ import annotations

import math

import pytest

from bearingload.bearings.resolve import resolve_bearing
from bearingload.errors import InputError

from .cli_helpers import error_line, run_entry


def test_overlap_refusal_shows_the_digits_that_differ_and_an_accepted_maximum(capsys):
    """``solve -z 20 --ball-diameter 6.022728 --pitch-diameter 38.5 -F 1kN`` said '20 balls of
    6.02273 mm overlap ... the ball diameter D_w must be at most 6.02273 mm': the given and the
    largest diameter printed alike (6 digits), the largest rounded up (d_m sin(pi/20) =
    6.0227269...). The digits now go as far as they differ, the largest rounded down: it is
    accepted, and the given diameter is above it."""
    import re

    from tests.cli_helpers import run_entry

    args = ["solve", "-z", "20", "--pitch-diameter", "38.5", "-F", "1kN"]
    code, _, err = run_entry(capsys, *args, "--ball-diameter", "6.022728")
    assert code != 0 and len(err.strip().splitlines()) == 1, err
    given = re.search(r"20 balls of ([0-9.]+) mm overlap", err).group(1)
    most = re.search(r"must be at most ([0-9.]+) mm", err).group(1)
    assert float(given) == 6.022728 and float(most) < float(given), err
    assert float(most) <= 38.5 * math.sin(math.pi / 20)
    code, _, err = run_entry(capsys, *args, "--ball-diameter", most)
    assert code == 0, err


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
    line = error_line(capsys, *command)
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
    lines = out.strip().splitlines()  # header, the skipped row with its reason, the good row
    assert len(lines) == 3 and lines[1].startswith("2,") and "overlap" in lines[1]
    assert lines[2].startswith("3,") and lines[2].endswith(",")
