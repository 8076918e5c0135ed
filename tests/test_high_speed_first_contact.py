"""The ring Newton of the ball dynamics (bearingload.models.high_speed) bringing balls held off
the inner ring by their centrifugal forces into contact (the core's ``contact_step``).

At speed a light load leaves few balls touching the inner ring: none at the static answer (9
balls of 7.938 mm on 38.5 mm at 15°, F_r 1e-6 N, 30 000 rpm, the cage 1e-12° off symmetry,
y free), or one (F_r 100 N, F_a 1e-4 N at 40°, 50 000 rpm), whose F_a and M/R_i are equal, so
that a thrust without moment needs a ball across the ring. The tangent of the ring forces is
then singular along the residual: the Newton and Levenberg-Marquardt steps have no part along
it, and each such case ended on a ConvergenceError (relative residual 1, 5e-7; 18 of the 1872
cases of ``python -m tests.scan_speed_light``, 139 of its 1000 ``wide`` cases; 0 and 15
since). Checked independently: each applied component as a plain sum of the returned inner
loads and angles (tests/campaign_speed.py's measure, over the largest applied load) to 1e-8
(a light load is balanced to the rounding of the ball forces, up to NOISE_MAX of it: 3e-9
here), every ball's two equations to 1e-11.
"""

from __future__ import annotations

import numpy as np
import pytest

from bearingload.models.combined import solve_combined
from bearingload.models.high_speed import solve_high_speed
from tests.campaign_speed import ball_residual, ring_residual

#: 6205/7205-sized ball set (NSK: 7.938 mm balls on 38.5 mm).
BALLS = dict(ball_diameter=7.938, pitch_diameter=38.5)

#: (F_r [N], F_a [N], n [rpm], alpha_0 [°], cage [°]): failures of tests/scan_speed_light.py.
CASES = [
    (1e-6, 0.0, 30000.0, 15.0, 1e-12),
    (100.0, 1e-4, 50000.0, 40.0, 0.0),
    (1e-6, 0.0, 30000.0, 25.0, 1e-12),
    (100.0, 1e-6, 50000.0, 40.0, 1e-12),
    (1e-3, 1e-6, 50000.0, 40.0, 1e-12),
    (1e-5, 1e-6, 30000.0, 40.0, 20.0),
    (1e3, 1e-4, 30000.0, 40.0, 20.0),
]


@pytest.mark.parametrize("fr, fa, speed, alpha, cage", CASES)
def test_balls_held_off_by_their_centrifugal_force_are_brought_into_contact(
    fr, fa, speed, alpha, cage
):
    kw = dict(BALLS, contact_angle=alpha, cage_angle=cage, speed=speed)
    r = solve_high_speed(9, fr, fa, **kw)
    case = {"z": 9, "fr": fr, "fa": fa, "kw": kw}
    assert ring_residual(case, r) <= 1e-8
    assert ball_residual(case, r) <= 1e-11
    assert np.all(r.ball_loads_inner >= 0) and np.any(r.ball_loads_inner > 0)
    if fa > 0:  # the thrust without moment: a second ball across the ring touches
        assert np.count_nonzero(r.ball_loads_inner) >= 2


#: Deep-groove cases of ``python -m tests.scan_speed_light wide`` (G_r 0, the cage at 0): a
#: thrust of 2e-4 and 1e-5 of F_r on one loaded ball; the balls across the ring touch only
#: by a move across their contact lines, along which their approach grows with its square.
WIDE = [
    (12, 2.4481682580729187e-05, 4.563355170685561e-09, 12473.215503671898),
    (5, 2.7185121812098905e-05, 2.2724601162934224e-10, 16297.031636807655),
]


@pytest.mark.parametrize("z, fr, fa, speed", WIDE)
def test_a_light_thrust_on_a_deep_groove_bearing_at_speed_is_balanced(z, fr, fa, speed):
    kw = dict(ball_diameter=23.812, pitch_diameter=102.5, clearance=0.0, speed=speed)
    r = solve_high_speed(z, fr, fa, **kw)
    case = {"z": z, "fr": fr, "fa": fa, "kw": kw}
    assert ring_residual(case, r) <= 1e-8
    assert ball_residual(case, r) <= 1e-11
    assert np.count_nonzero(r.ball_loads_inner) >= 2


def test_a_cage_just_off_symmetry_gives_the_symmetric_answer():
    """The cage at 1e-12° (y free) and at 0 (y held by the mirror symmetry): the same x to 1e-9
    of it. The one ball touching leaves y free (within the gaps of the others): the ring keeps
    the static answer's y there, to 1e-12 mm."""
    kw = dict(BALLS, contact_angle=15.0)
    off = solve_high_speed(9, 1e-6, 0.0, cage_angle=1e-12, speed=30000.0, **kw)
    on = solve_high_speed(9, 1e-6, 0.0, cage_angle=0.0, speed=30000.0, **kw)
    static = solve_combined(9, 1e-6, 0.0, cage_angle=1e-12, **kw)
    assert abs(off.x - on.x) <= 1e-9 * abs(on.x)
    assert abs(off.y - static.y) <= 1e-12


@pytest.mark.parametrize("fr, clearance", [(1e-6, -0.010), (1e-6, -0.030), (2e-6, -0.050)])
def test_a_tiny_load_the_static_solver_answers_is_answered_at_speed_0(fr, clearance):
    """At speed 0 under a preload, 1e-6 N was refused as below the rounding of the ball forces
    (1e-5 of the load, a rule for the balls' forces at speed), though the static solver (in
    double-double) answers it: now the static answer, its ball loads to 1e-11 of the largest."""
    static = solve_combined(9, fr, 0.0, clearance=clearance, **BALLS)
    r = solve_high_speed(9, fr, 0.0, speed=0.0, clearance=clearance, **BALLS)
    top = float(np.max(static.ball_loads))
    assert np.max(np.abs(r.ball_loads - static.ball_loads)) <= 1e-11 * top
    case = {"z": 9, "fr": fr, "fa": 0.0, "kw": dict(BALLS, clearance=clearance, speed=0.0)}
    assert ball_residual(case, r) <= 1e-11
