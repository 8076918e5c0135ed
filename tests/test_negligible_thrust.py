"""A thrust too small to matter: the combined solver answers continuously as F_a goes to 0,
solving a case it cannot balance with a thrust below 1e-12 of the largest load as its neighbour
at that share of the load (the limit of a thrust going to 0: any thrust pushes the ring across
its axial play), and saying so."""

from __future__ import annotations

import numpy as np
import pytest

from bearingload import solve_combined
from bearingload.models.combined import NEGLIGIBLE_THRUST

#: A 6205 with a huge clearance: one ball carries F_r = 1 kN; its axial position resolved
#: 1e-11 N of thrust, not 1e-12 N (a ConvergenceError before).
ONE_BALL = {"ball_diameter": 7.938, "pitch_diameter": 38.5, "clearance": 0.2}
#: The 6205's ball set alone.
GEOMETRY = {"ball_diameter": 7.938, "pitch_diameter": 38.5}


def test_a_sweep_of_the_thrust_down_to_zero_has_no_hole():
    thrusts = np.array([0.0, 1e-15, 1e-14, 1e-13, 1e-12, 1e-11, 1e-10, 1e-6, 1.0])
    r = solve_combined(9, 1000.0, thrusts, **ONE_BALL)
    assert np.all(np.isfinite(r.q_max)) and np.allclose(r.q_max[:-1], 1000.0, rtol=1e-9)
    neglected = np.asarray(r.thrust_neglected)
    assert not neglected[0] and not neglected[5:].any()  # 0 is no thrust; 1e-11 N balances
    assert neglected[1:5].all()
    # the limit of a thrust going to 0: the ring pushed across its axial play, as at 1e-11 N
    assert np.allclose(r.axial[1:7], r.axial[5], rtol=1e-9) and r.axial[5] > 0.1
    assert np.allclose(r.tilt[1:7], r.tilt[5], rtol=1e-9)


def test_only_a_thrust_below_the_tolerance_of_the_largest_load_is_left_out():
    assert NEGLIGIBLE_THRUST == 1e-12
    r = solve_combined(9, 1000.0, 1e-12, **ONE_BALL)
    assert bool(r.thrust_neglected)
    assert not solve_combined(9, 1000.0, 1e-11, **ONE_BALL).thrust_neglected
    assert not solve_combined(9, 1000.0, 300.0, **ONE_BALL).thrust_neglected


def test_the_thrust_left_out_is_said_with_its_size(capsys):
    from .cli_helpers import run_entry

    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "-A", "1e-12N", "-G", "0.2")
    assert code == 0 and "heaviest ball load" in out
    assert "the thrust F_a = 1e-12 N is below 1e-12 of the largest load" in err
    assert "solved with a thrust of 1e-12 of that load" in err


@pytest.mark.parametrize(
    "args",
    [
        ("sweep", "6205", "-F", "1kN", "-A", "1e-12N", "-G", "0.2", "--steps", "3"),
        ("table", "life", "-b", "6205", "-F", "1kN", "-A", "1e-12N", "--clearances", "0.2"),
    ],
)
def test_sweep_and_table_life_say_the_thrust_left_out_as_solve_does(capsys, args):
    from .cli_helpers import run_entry

    code, out, err = run_entry(capsys, *args)
    assert code == 0 and out
    said = [w for w in err.splitlines() if "the thrust F_a = 1e-12 N is below" in w]
    assert len(said) == 1, err
    assert "the loads do not determine the ring's tilt" in err


@pytest.mark.parametrize("thrust", [1e-13, 1e-12])
def test_a_case_alone_and_in_a_batch_agree(thrust):
    alone = solve_combined(9, 1000.0, thrust, **ONE_BALL)
    batch = solve_combined(9, 1000.0, np.array([300.0, thrust, 1e-14]), **ONE_BALL)
    assert alone.q_max == batch.q_max[1] and alone.x == batch.x[1]


def test_the_flags_and_counts_of_a_result_at_speed_keep_their_types():
    """A result at speed keeps the static answer's flags as bools and its counts as integers,
    so that they index and count as the static result's do."""
    from bearingload import solve_high_speed

    loads = np.array([1000.0, 2000.0])
    r = solve_high_speed(9, loads, 0.0, speed=3000, clearance=0.01, **GEOMETRY)
    assert r.tilt_undetermined.dtype == bool and r.thrust_neglected.dtype == bool
    assert r.iterations.dtype.kind == "i" and r.tilt[r.thrust_neglected].size == 0
