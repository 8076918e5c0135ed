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


def test_the_combined_path_warns_like_the_radial_one(capsys):
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "500kN", "-A", "1N")
    assert code == 0 and "Bearing 6205" in out
    assert "Warning: static safety factor s0 = C0/P0" in err
    assert "is above the basic static rating C0 = 7850 N" in err
    assert "maximum contact pressure" in err
    doc = json.loads(invoke("solve", "6205", "-F", "1kN", "-A", "100N", "--format", "json").output)
    assert doc["warnings"] == [] and doc["cases"][0]["warnings"] == []
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--misalignment", "0.5")
    assert code == 0 and "more than the 10 arcmin" in err


def test_a_tilt_of_degrees_is_refused(capsys):
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--misalignment", "90")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "Invalid value for '--misalignment': must be within ±2°" in err


@pytest.mark.parametrize("radial", [1e-12, 1e-9, 1e-6, 1e-3])
def test_a_vanishing_radial_load_beside_a_moment_is_solved(radial):
    """The start follows the load that dominates: the tilt is the moment-alone tilt."""
    alone = solve_combined(9, 0.0, 0.0, moment=1e3, **GEOMETRY)
    r = solve_combined(9, radial, 0.0, moment=1e3, **GEOMETRY)
    assert float(r.tilt) == pytest.approx(float(alone.tilt), rel=1e-6)


def test_loads_too_small_for_the_combined_solver_are_refused(capsys):
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1e-9N", "-A", "1e-9N")
    assert code == 2 and err.count("\n") == 1 and "RuntimeWarning" not in err
    assert "the loads are too small for the combined solver" in err


@pytest.mark.parametrize(
    "extra, message",
    [
        (["--modulus", "210GPa"], "Error: --modulus needs a BEARING or the ball geometry"),
        (["--clearance-pick", "range"], "Error: --clearance-pick needs a BEARING"),
        (["--poisson", "0.3", "--maker", "SKF"], "Error: --poisson, --maker need a BEARING"),
    ],
)
def test_options_a_hand_given_ring_would_ignore_are_refused(capsys, extra, message):
    code, out, err = run_entry(capsys, "solve", "-z", "8", "-F", "1kN", "-K", "1e5", *extra)
    assert code == 2 and out == "" and err.count("\n") == 1 and err.startswith(message), err


@pytest.mark.parametrize(
    "args, message",
    [
        (["solve", "-z", "8", "-F", "1kN", "-K", "1e5", "--clearance-pick", "mean"],
         "Error: --clearance-pick needs a BEARING"),
        (["sweep", "-z", "8", "-F", "1kN", "-K", "1e5", "--modulus", "210GPa"],
         "Error: --modulus needs a BEARING or the ball geometry"),
        (["sweep", "-z", "8", "-F", "1kN", "-K", "1e5", "--clearance-pick", "max"],
         "Error: --clearance-pick needs a BEARING"),
        (["table", "k", "--clearance-pick", "min"], "Error: --clearance-pick needs --bearing"),
    ],
)  # fmt: skip
def test_sweep_and_table_refuse_what_a_hand_given_ring_would_ignore(capsys, args, message):
    """sweep and table k took --modulus or --clearance-pick without a bearing and ignored them;
    solve let an explicit --clearance-pick mean pass (a batch file's clearance_pick cell is
    refused): all refuse them now, as solve refused the others."""
    code, out, err = run_entry(capsys, *args)
    assert code == 2 and out == "" and err.count("\n") == 1 and err.startswith(message), err


def test_the_largest_contact_angle_is_that_of_a_loaded_ball():
    doc = json.loads(
        invoke("solve", "6205", "-F", "1kN", "--misalignment", "0.1", "--format", "json").output
    )
    case = doc["cases"][0]
    loaded = [a for a, q in zip(case["contact_angles"], case["ball_loads"], strict=True) if q > 0]
    assert case["contact_angle_max"] == max(loaded, key=abs)


def test_second_review_sweep_moment_and_separators(capsys):
    code, out, err = run_entry(
        capsys, "sweep", "-z", "9", "-F", "1kN", "-K", "1e5", "-G", "0.9mm", "-n", "3"
    )
    assert code == 0 and "Warning: only one ball carries the load at 2 of 3 cage angles" in err
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--moment", "1e9Nmm")
    assert code == 2 and "Invalid value for '--moment': tilts the inner ring by 39" in err
    code, out, err = run_entry(capsys, "solve", "-z", "8", "-F", "3,000", "-K", "1e5")
    assert code == 2 and "write no thousands separator (3000) or a decimal point (3.000)" in err
