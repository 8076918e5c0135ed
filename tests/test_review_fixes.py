"""Findings of an independent review, each kept fixed: API input errors, one unit per JSON key,
the one-line estimates' range, a zero dynamic rating."""

from __future__ import annotations

import json

import numpy as np
import pytest

from bearingload import InputError, compute, ring_forces, solve
from bearingload.models.combined import solve_combined

from .cli_helpers import invoke, run_entry

GEOMETRY = {"ball_diameter": 7.938, "pitch_diameter": 38.5}


@pytest.mark.parametrize(
    "call, parameter",
    [
        (lambda: ring_forces(9, [0.01, 0.02], [0.0, 0.0, 0.0], 1e5), "x, y"),
        (lambda: ring_forces(9, np.array([]), np.array([]), 1e5), "x, y"),
        (lambda: solve(8, "1kN", 1e5), "load"),
        (lambda: solve(True, 1000.0, 1e5), "balls"),
        (lambda: solve_combined(9, [1000.0, 2000.0], [500.0, 1, 2], **GEOMETRY), "radial_load, axial_load"),
        (lambda: solve_combined(9, np.array([]), 500.0, **GEOMETRY), "radial_load"),
    ],
)  # fmt: skip
def test_bad_arrays_and_types_are_input_errors(call, parameter):
    with pytest.raises(InputError) as exc:
        call()
    assert exc.value.parameter == parameter


def test_the_dynamic_rating_is_always_in_newtons():
    listed = json.loads(invoke("catalog", "--bore", "25", "--format", "json").output)
    row = next(r for r in listed["rows"] if r["designation"] == "6205")
    shown = json.loads(invoke("catalog", "show", "6205", "--format", "json").output)
    assert listed["units"]["C"] == "N" and row["C"] == 14000.0
    assert json.dumps(shown).count("14000.0") >= 1


def test_one_line_estimates_are_outside_their_range_below_five_balls():
    """k = 4.37/z (5/z) above 1 for z < 5: one ball would carry more than the whole load."""
    for z in (1, 2, 3, 4):
        assert compute("stribeck", z, 1000.0, 1e5).valid is False
        assert compute("palmgren", z, 1000.0, 1e5).valid is False
    assert compute("stribeck", 5, 1000.0, 1e5).valid is True


def test_a_zero_dynamic_rating_is_refused(capsys):
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "-C", "0")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "--dynamic-rating" in err and "must be greater than 0 N" in err
