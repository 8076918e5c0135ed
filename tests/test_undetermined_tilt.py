"""A ring whose tilt the loads do not determine: one defined answer (the least tilt), said.

Four balls of an angular-contact bearing under a thrust of 1e-3 F_r: two loaded balls opposite
each other, a third at 0° (its one-sided contact takes no axial part), the fourth loose. Every
tilt about the line through the two loaded balls balances the loads, up to where the loose ball
touches or the one at 0° leaves the groove bottom. The solver returned whichever its start led
to, without a word: -0.632° at F_a = 3.4753 N and -0.683° at 3.47531 N (42 of 300 random such
cases jumped between neighbouring loads).
"""

from __future__ import annotations

import numpy as np
import pytest

from bearingload.models.combined import solve_combined
from tests.bearings_data import B7205B

#: The reported bearing (an angular-contact ball set, 24.06°).
FOUR = dict(ball_diameter=9.184, pitch_diameter=34.69, contact_angle=24.06)


def _balanced(r, fr: float, fa: float) -> None:
    q = np.asarray(r.ball_loads)
    al, ph = np.radians(r.contact_angles), np.radians(r.ball_angles)
    fx = float(np.sum(q * np.cos(al) * np.cos(ph)))
    fz = float(np.sum(q * np.sin(al)))
    assert abs(fx - fr) <= 1e-11 * fr and abs(fz - fa) <= 1e-9 * fr


def test_the_reported_loads_give_one_tilt_and_say_it_is_undetermined():
    a = solve_combined(4, 3475.3, 3.4753, cage_angle=106.28, **FOUR)
    b = solve_combined(4, 3475.3, 3.47531, cage_angle=106.28, **FOUR)
    assert bool(a.tilt_undetermined) and bool(b.tilt_undetermined)
    assert abs(a.tilt - b.tilt) <= 1e-5 and abs(a.tilt_cross - b.tilt_cross) <= 1e-5
    assert np.allclose(a.ball_loads, b.ball_loads, rtol=1e-4, atol=1e-9)
    _balanced(a, 3475.3, 3.4753)
    _balanced(b, 3475.3, 3.47531)


def test_the_tilt_returned_is_the_least_of_those_that_balance():
    """The tilts that balance run from where the loose ball (2) touches to where ball 4 leaves
    the groove bottom: the answer is at the end of the smaller tilt (within 1e-6 of the range),
    below the -0.632° and -0.683° the solver gave before."""
    r = solve_combined(4, 3475.3, 3.4753, cage_angle=106.28, **FOUR)
    size = float(np.hypot(r.tilt, r.tilt_cross))
    assert size < float(np.hypot(-0.632, 0.307)) and size < float(np.hypot(-0.683, 0.292))
    assert r.ball_loads[1] == 0.0 and r.contact_angles[3] == 0.0  # still inside the range


@pytest.mark.parametrize("seed", [1, 2])
def test_neighbouring_thrusts_give_neighbouring_tilts(seed):
    """Random 4-ball bearings at 10-40° under a thrust of 1e-3 F_r: the tilt at F_a and at
    F_a (1 + 1e-6) agree to 1e-4° (they jumped by up to 0.1°); every answer balanced. (Whether
    a case is flagged may differ between the two: at the valley's end a ball carries a load just
    above or below the tolerance, 1e-12 of F_r, at the same tilt.)"""
    rng = np.random.default_rng(seed)
    flagged = 0
    for _ in range(40):
        alpha, cage = rng.uniform(10.0, 40.0), rng.uniform(0.0, 360.0)
        fr = rng.uniform(500.0, 5000.0)
        fa = 1e-3 * fr
        kw = dict(ball_diameter=9.184, pitch_diameter=34.69, contact_angle=alpha, cage_angle=cage)
        a = solve_combined(4, fr, fa, **kw)
        b = solve_combined(4, fr, fa * (1 + 1e-6), **kw)
        assert abs(a.tilt - b.tilt) <= 1e-4 and abs(a.tilt_cross - b.tilt_cross) <= 1e-4
        _balanced(a, fr, fa)
        _balanced(b, fr, fa * (1 + 1e-6))
        flagged += bool(a.tilt_undetermined)
    assert flagged > 0  # (the family has such cases: the test sees them)


def test_a_ring_held_every_way_is_not_flagged():
    r = solve_combined(9, 3000.0, 500.0, ball_diameter=7.938, pitch_diameter=38.5, clearance=0.01)
    assert not bool(r.tilt_undetermined)
    r = solve_combined(
        12,
        3000.0,
        1000.0,
        cage_angle=7.0,
        contact_angle=40.0,
        ball_diameter=7.938,
        pitch_diameter=38.5,
    )
    assert not bool(r.tilt_undetermined)


def test_solve_warns_that_the_loads_do_not_determine_the_tilt():
    from click.testing import CliRunner

    from bearingload.cli import main

    args = "solve --balls 4 --ball-diameter 9.184 --pitch-diameter 34.69 --contact-angle 24.06"
    args += " --cage-angle 106.28 -F 3475.3N -A 3.4753N"
    result = CliRunner().invoke(main, args.split())
    assert result.exit_code == 0, result.output
    assert "Warning: the loads do not determine the ring's tilt" in result.output
    result = CliRunner().invoke(main, ["solve", "6205", "-F", "3kN", "-A", "1kN"])
    assert "do not determine" not in result.output


def test_a_symmetric_cage_is_flagged_too():
    """A cage at 0 holds the cross tilt by symmetry; the tilt in the plane of the load can
    still be free (4 balls at 15°: -0.398973° or -0.398486° for thrusts 1e-6 apart, no word)."""
    kw = dict(ball_diameter=9.184, pitch_diameter=34.69, contact_angle=15.0)
    a = solve_combined(4, 3475.3, 3.4753, **kw)
    b = solve_combined(4, 3475.3, 3.4753035, **kw)
    assert bool(a.tilt_undetermined)
    assert abs(a.tilt - b.tilt) <= 1e-5


def test_a_curved_valley_is_followed_to_its_least_tilt():
    """``solve 7205B -F 1kN -A 1N --cage-angle 7`` gave a tilt of -0.5715°, with ``-A
    1.000001N`` -0.5758°: the least tilt lies at the valley's end where a loose ball touches,
    the move to its first-order estimate pressed that ball, and the halves tried then left the
    ring mid-valley. The end found by bisection: the two agree to 1e-6°, both balanced, and the
    tilt is no larger than either answer of before."""
    a = solve_combined(12, 1000.0, 1.0, cage_angle=7.0, **B7205B)
    b = solve_combined(12, 1000.0, 1.000001, cage_angle=7.0, **B7205B)
    assert bool(a.tilt_undetermined) and bool(b.tilt_undetermined)
    assert abs(a.tilt - b.tilt) <= 1e-6 and abs(a.tilt_cross - b.tilt_cross) <= 1e-6
    _balanced(a, 1000.0, 1.0)
    _balanced(b, 1000.0, 1.000001)
    size = float(np.hypot(b.tilt, b.tilt_cross))
    assert size <= float(np.hypot(-0.5715, 0.0697)) * (1 + 1e-5)


def test_neighbouring_thrusts_on_a_12_ball_bearing_give_neighbouring_tilts():
    """7205B under F_r = 1 kN, F_a 0.3, 1 and 3 N, the cage 1° to 29° in steps of 0.5°: the
    tilt at F_a and at F_a (1 + 1e-6) agree to 1e-4° (two pairs jumped by 0.01° before)."""
    for cage in np.linspace(1.0, 29.0, 57):
        for fa in (0.3, 1.0, 3.0):
            a = solve_combined(12, 1000.0, fa, cage_angle=cage, **B7205B)
            b = solve_combined(12, 1000.0, fa * (1 + 1e-6), cage_angle=cage, **B7205B)
            assert abs(a.tilt - b.tilt) <= 1e-4, (cage, fa, a.tilt, b.tilt)
            assert abs(a.tilt_cross - b.tilt_cross) <= 1e-4, (cage, fa)


def test_a_thrust_at_the_tolerance_gives_the_least_tilt_of_its_neighbours():
    """``solve 7205B -F 1kN -A X --cage-angle 7`` gave -0.57158°/0.07226° for X = 1e-10, 1e-8,
    1e-7 and 1e-6 N but -0.58161°/0.04862° for X = 1e-9 N, a larger tilt: at 1e-12 of F_r (the
    tolerance) the ball across the ring that carries the thrust, of 5e-10 N, counted as loose,
    and the balls above it left a plane of tilts, one direction of which was taken, without an
    end. Where the balls above the tolerance leave more than one direction free, every
    touching ball holds the ring: one line, as at 1e-8 N. Every thrust from 1e-12 to 1e-6 N
    now gives the answer of 1e-8 N to 1e-6°, each balanced, the tilt the least of before."""
    ref = solve_combined(12, 1000.0, 1e-8, cage_angle=7.0, **B7205B)
    for fa in (1e-12, 1e-11, 1e-10, 3e-10, 1e-9, 3e-9, 1e-7, 1e-6):
        r = solve_combined(12, 1000.0, fa, cage_angle=7.0, **B7205B)
        assert bool(r.tilt_undetermined)
        assert abs(r.tilt - ref.tilt) <= 1e-6 and abs(r.tilt_cross - ref.tilt_cross) <= 1e-6
        _balanced(r, 1000.0, fa)
    assert float(np.hypot(ref.tilt, ref.tilt_cross)) < float(np.hypot(-0.58161, 0.04862))
