"""A thrust tiny against the radial load at speed (bearingload.models.high_speed): an
angular-contact bearing under an ordinary radial load and a thrust of 1e-10 to 1e-6 of it.

The loaded balls sit at about 0° and the thrust is carried by a touching ball whose axial
offset u barely passes 0 (one-sided contact: u' = max(u, 0)) and a ball across the ring at 90°,
the ring tilted to bring it in. The solver stopped with the loaded balls just below u = 0
(``clipped``: their forces then do not move with u, the plain tangent has no column for it) and
no ball across: a ConvergenceError (`solve 7205B -F 100N -A 1e-6N --speed 3000 --cage-angle
15`, relative residual 1e-8; 1 of 480 in a 7205B scan, 15 of the 1800 of ``python -m
tests.scan_speed_thrust``), or, below ACCEPT, an answer that leaves half the thrust unbalanced
at another tilt (54 of those 1800). The core now takes the Newton step with the clipped balls
in contact and the step to a first contact along their side's tangent, and a thrust left
uncarried is solved by continuation in it from 1e-6 of the radial load: the answer is the
limit its neighbours approach.

Checked independently: every applied component as a plain sum (math.fsum) of the returned inner
loads and angles, the thrust and both moments to 1e-3 of the thrust itself (the solver's
tolerance, 1e-12 of F_r, is 1e-2 of a thrust of 1e-10 F_r: the ratios here stop at 1e-9), and
the tilt of the tiny thrusts against that of a thrust 1000 times larger.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingload.models.high_speed import solve_high_speed
from tests.bearings_data import B7205B
from tests.campaign_speed import ball_residual

from .cli_helpers import run_entry


def carried(r, fr: float, fa: float) -> tuple[float, float]:
    """(the radial residual over F_r, the largest of the axial and both moment residuals over
    F_a) as plain sums of the returned inner contacts."""
    q, al, ph = r.ball_loads_inner, np.radians(r.contact_angles_inner), np.radians(r.ball_angles)
    radial = math.fsum((q * np.cos(al) * np.cos(ph)).tolist()) - fr
    axial = math.fsum((q * np.sin(al)).tolist()) - fa
    tilt = math.fsum((q * np.sin(al) * np.cos(ph)).tolist())
    cross = math.fsum((q * np.sin(al) * np.sin(ph)).tolist())
    return abs(radial) / fr, max(abs(axial), abs(tilt), abs(cross)) / fa


@pytest.mark.parametrize(
    "z, fr, fa, n, cage, geometry",
    [
        (12, 100.0, 1e-6, 3000.0, 15.0, B7205B),
        (12, 50.0, 1e-7, 1000.0, 0.0, B7205B),
        (
            16,
            113.0,
            4e-6,
            5600.0,
            19.0,
            dict(ball_diameter=6.35, pitch_diameter=60.0, contact_angle=15.0),
        ),
        (12, 40.916660020213875, 1e-7, 1000.0, 0.0, B7205B),
    ],
)
def test_a_tiny_thrust_at_speed_is_solved_and_carried(z, fr, fa, n, cage, geometry):
    """The cases docs/accuracy.md listed as ending in a ConvergenceError."""
    r = solve_high_speed(z, fr, fa, speed=n, cage_angle=cage, **geometry)
    radial, thrust = carried(r, fr, fa)
    assert radial < 1e-11 and thrust < 1e-3
    assert ball_residual({"kw": geometry}, r) < 1e-11


@pytest.mark.parametrize(
    "fr, cage, n",
    [(100.0, 15.0, 3000.0), (3000.0, 7.0, 2114.7425268811285), (83.70865336048837, 15.0, 1000.0)],
)
def test_the_answer_is_continuous_in_a_tiny_thrust(fr, cage, n):
    """Thrusts of 1e-9 to 1e-6 of F_r give the tilt their neighbours approach (that of 1e-6 F_r
    to 5e-4°, its own change up to 1e-5 F_r being 3e-4°), each carried; a thrust of 1e-9 F_r
    was left half unbalanced at a tilt 0.12° off (F_r 3000 N), 1e-7 ended in a
    ConvergenceError (100 N)."""
    answers = [
        solve_high_speed(12, fr, k * fr, speed=n, cage_angle=cage, **B7205B)
        for k in (1e-9, 1e-8, 1e-7, 1e-6)
    ]
    for k, r in zip((1e-9, 1e-8, 1e-7, 1e-6), answers, strict=True):
        assert carried(r, fr, k * fr)[1] < 1e-3
        assert not r.displacement_undetermined
    tilts = [float(r.tilt) for r in answers]
    assert max(tilts) - min(tilts) < 5e-4


@pytest.mark.parametrize(
    "fr, ratio, n, cage",
    [
        (40.916660020213875, 1e-8, 20000.0, 1e-6),
        (83.70865336048837, 1e-8, 20000.0, 1e-3),
        (83.70865336048837, 1e-10, 20000.0, 1e-3),
        (20.0, 1e-8, 2114.74, 1e-3),
    ],
)
def test_a_cage_just_off_symmetry_gives_the_answer_of_one_further_off(fr, ratio, n, cage):
    """The cage 1e-6° to 1e-3° off the load line: the load-line ball's F_y (F_r times the
    sine of the offset) is carried by a ball across a nearly free y; the Newton crossed y the
    wrong way and ended in a ConvergenceError (relative residual 1.75e-8 to 2.9e-6), or left
    half the thrust unbalanced (1e-10 of F_r). Solved by continuation in the offset from
    0.1°: the answer of a cage of 0.01° to 1e-4° and 0.02 µm (y changes by 0.008 µm over the
    offset), the thrust carried to 1 % (the tolerance, 1e-12 of F_r, is 1 % of 1e-10 F_r)."""
    r = solve_high_speed(12, fr, ratio * fr, speed=n, cage_angle=cage, **B7205B)
    far = solve_high_speed(12, fr, ratio * fr, speed=n, cage_angle=0.01, **B7205B)
    radial, thrust = carried(r, fr, ratio * fr)
    assert radial < 1e-11 and thrust < 1e-2
    assert abs(r.tilt - far.tilt) < 1e-4 and abs(r.tilt_cross - far.tilt_cross) < 1e-4
    assert abs(r.y - far.y) < 2e-5


def test_the_command_line_answers_a_tiny_thrust(capsys):
    code, out, err = run_entry(
        capsys,
        "solve",
        "7205B",
        "-F",
        "100N",
        "-A",
        "1e-6N",
        "--speed",
        "3000",
        "--cage-angle",
        "15",
    )
    assert code == 0 and "Error" not in err and "ring displacement" in out


def test_a_subnormal_thrust_is_stepped_down_to_like_any_tiny_one():
    """A thrust of 1e-320 N (subnormal: 1e-6 of F_r over it overflows a double, as 10**321
    does) is continued down to as a thrust of 1e-300 N is, to the same answer; it raised
    OverflowError (5 balls of 10 mm on 40 mm at 0°, F_r 2000 N, 15 000 rpm, the cage at 1°)."""
    kw = dict(speed=15000.0, cage_angle=1.0, ball_diameter=10.0, pitch_diameter=40.0)
    tiny = solve_high_speed(5, 2000.0, 1e-320, contact_angle=0.0, **kw)
    small = solve_high_speed(5, 2000.0, 1e-300, contact_angle=0.0, **kw)
    assert abs(tiny.tilt - small.tilt) < 1e-9 and abs(tiny.axial - small.axial) < 1e-9
    assert carried(tiny, 2000.0, 1.0)[0] < 1e-11
