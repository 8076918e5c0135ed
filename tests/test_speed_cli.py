"""``bearingload solve --speed`` with the ball dynamics: options that the dynamics cannot honour
are refused with one ``Error:`` line naming them, never silently ignored."""

from __future__ import annotations

import json

from .cli_helpers import run_entry

BASE = ("solve", "7205B", "-F", "500N", "-A", "1kN", "--speed", "20000")


def _error_line(capsys, *args: str) -> str:
    code, out, err = run_entry(capsys, *args)
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and lines[0].startswith("Error:"), err
    return lines[0]


def test_outer_ring_rotating_is_refused_with_the_ball_dynamics(capsys):
    # the dynamics are coded for the inner ring turning; --rotating outer was accepted and the
    # cage speed and centrifugal forces of the inner ring turning silently used
    line = _error_line(capsys, *BASE, "--rotating", "outer")
    assert "--rotating" in line and "--quasi-static" in line
    code, out, _ = run_entry(capsys, *BASE, "--rotating", "outer", "--quasi-static",
                             "--format", "json")  # fmt: skip
    assert code == 0 and json.loads(out)["cases"][0]["rotating"] == "outer"


def test_given_stiffness_is_refused_in_the_words_of_the_command_line(capsys):
    # the refusal named the library's argument: 'ask for the static model (speed None)'
    line = _error_line(capsys, *BASE, "--stiffness", "3e5")
    assert "--stiffness" in line and "--quasi-static" in line and "None" not in line
    code, _, _ = run_entry(capsys, *BASE, "--stiffness", "3e5", "--quasi-static")
    assert code == 0
