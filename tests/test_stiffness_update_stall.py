"""The stiffness updates of the combined solver (the core's ``solve_case``) end where the
minimisation stalls above the tolerance and the update settles: no ball stiffness changed by
more than 1e-11 of it, the residual by at most 1 %; the caller's residual test judges the
answer.

``solve -z 40 --ball-diameter 2.87 --pitch-diameter 38.5 -F 0.47N -A 0.00087N -G 83um
--cage-angle 1e-12`` ended on a ConvergenceError (the 40 stiffness updates ran out, relative
residual 1.12e-10): two loaded balls (0° and 180°) leave the ring free across the load, the
cage 1e-12° off the load line leaves a cross moment of 1e-16 of the load, and each
minimisation crawled along that free direction (the stiffness moving 1e-12 each update, the
residual a hair above where the minimisation ended). Checked independently: the ball loads are
those of the cage on the load line (the loads do not depend on the free direction) to 1e-9,
each applied component balanced as a plain sum of the returned loads and angles.
"""

from __future__ import annotations

import math

import numpy as np
from click.testing import CliRunner

from bearingload.cli import main
from bearingload.models.combined import solve_combined

CASE = dict(ball_diameter=2.87, pitch_diameter=38.5, clearance=0.083)
FR, FA = 0.47, 0.00087


def test_a_stall_along_a_free_direction_ends_the_stiffness_updates():
    r = solve_combined(40, FR, FA, cage_angle=1e-12, **CASE)
    on_line = solve_combined(40, FR, FA, cage_angle=0.0, **CASE)
    assert np.allclose(r.ball_loads, on_line.ball_loads, rtol=0.0, atol=1e-9 * FR)
    assert math.isclose(r.x, on_line.x, rel_tol=1e-9)
    q, a = r.ball_loads, np.radians(r.contact_angles)
    phi = np.radians(r.ball_angles)
    radial = math.fsum((q * np.cos(a) * np.cos(phi)).tolist())
    across = math.fsum((q * np.cos(a) * np.sin(phi)).tolist())
    axial = math.fsum((q * np.sin(a)).tolist())
    assert abs(radial - FR) <= 1e-10 * FR
    assert abs(across) <= 1e-10 * FR
    assert abs(axial - FA) <= 1e-9 * FA


def test_the_terminal_call_answers():
    args = [
        "solve",
        "-z",
        "40",
        "--ball-diameter",
        "2.87",
        "--pitch-diameter",
        "38.5",
        "-F",
        "0.47N",
        "-A",
        "0.00087N",
        "-G",
        "83um",
        "--cage-angle",
        "1e-12",
    ]
    out = CliRunner().invoke(main, args)
    assert out.exit_code == 0, out.output
    assert "balls carrying load" in out.output
