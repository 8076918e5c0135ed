"""A ring position the loads do not determine at speed (bearingload.models.high_speed): one ball
loaded on the load line (the cage 1e-12° off symmetry) leaves y free, its stiffness k_yy about 0;
the solver stops somewhere in the range (y = -3.609 µm for 9 balls of 7.938 mm on 38.5 mm at 15°,
F_r 10 N, 20 000 rpm, against -4.383 µm with two balls loaded at a cage of 1e-9°), so the answer
says so (``displacement_undetermined`` and a warning). Checked independently: the returned
tangent's k_yy over its k_xx, from the stiffness matrix itself."""

from __future__ import annotations

import numpy as np
import pytest

from bearingload.models.high_speed import SINGULAR, solve_high_speed
from bearingload.studies.combined_bearing import POSITION_UNDETERMINED

from .cli_helpers import run_entry

#: 9 balls of 7.938 mm on a 38.5 mm pitch, 15° (the ball set of a 7205B), F_r 10 N, 20 000 rpm.
ANGULAR = dict(
    balls=9,
    radial_load=10.0,
    speed=20000.0,
    ball_diameter=7.938,
    pitch_diameter=38.5,
    contact_angle=15.0,
)


@pytest.mark.parametrize("cage, free", [(1e-12, True), (1e-9, False), (0.0, False), (7.0, False)])
def test_one_ball_on_the_load_line_at_speed_leaves_y_undetermined(cage, free):
    r = solve_high_speed(**ANGULAR, cage_angle=cage)
    k = np.asarray(r.stiffness_matrix)
    assert bool(r.displacement_undetermined) is free
    # independent: the matrix's own k_yy against its k_xx (no tilt in this case's free set)
    assert bool(abs(k[1, 1]) <= SINGULAR * abs(k[0, 0])) is free or cage == 0.0  # y held at 0


@pytest.mark.parametrize(
    "args",
    [
        (
            "-z",
            "9",
            "--ball-diameter",
            "7.938",
            "--pitch-diameter",
            "38.5",
            "--contact-angle",
            "15",
            "-F",
            "10N",
            "--speed",
            "20000",
        ),
        ("6205", "-F", "0.1N", "-G", "10um", "--speed", "6772"),
    ],
)
def test_the_command_line_warns_where_the_loads_leave_a_direction_free(capsys, args):
    code, _, err = run_entry(capsys, "solve", *args, "--cage-angle", "1e-12")
    assert code == 0 and f"Warning: {POSITION_UNDETERMINED}" in err
    code, _, err = run_entry(capsys, "solve", *args, "--cage-angle", "1e-9")
    assert code == 0 and POSITION_UNDETERMINED not in err


def test_table_life_warns_as_solve_where_a_direction_is_free(capsys):
    """table life's rows at speed carry the solver's free-direction flag, as solve's case does."""
    ring = ("-z", "9", "--ball-diameter", "7.938", "--pitch-diameter", "38.5")
    load = ("-F", "20N", "-A", "0", "--speed", "15000", "--cage-angle", "1e-12")
    args = ("table", "life", *ring, "--dynamic-rating", "14kN", *load, "--clearances", "50um")
    code, _, err = run_entry(capsys, *args)
    assert code == 0 and f"Warning: {POSITION_UNDETERMINED}" in err
