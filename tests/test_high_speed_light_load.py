"""Light applied loads at speed (bearingload.models.high_speed): a load tiny against the balls'
centrifugal forces or against a preload. The static engine answers these; the ball dynamics
raised a ConvergenceError (relative residual 1, or 1.4e-9 to 2e-7 of the applied load) because
its ring test was relative to the applied load alone, below the rounding of the ball forces and
positions (docs/speed.md, "Numerics").

Checked independently from the returned state: the ring equilibrium as an exact sum
(math.fsum) of the returned inner loads and angles against the applied load, within 1e-12 of
that load or the rounding level of the terms, computed here from the returned balls: 64 eps
(the static model's rounding) times the sum of the terms' magnitudes plus 4 eps times A times
the balls' inner contact stiffnesses ``1.5 Q_i / delta_i`` (the force change over a rounding of
the lengths near A that give the inner approach); each ball's two equations from its returned
forces and angles (tests/campaign_speed.py's measure) to 1e-11 (the campaign's worst: 4e-12).
A load whose rounding level is above 1e-5 of it is refused, naming the smallest load accepted.
"""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest
from click.testing import CliRunner

from bearingload.cli import main
from bearingload.errors import InputError
from bearingload.models.high_speed import NOISE_MAX, solve_high_speed
from tests.bearings_data import B7205B
from tests.campaign_speed import ball_residual

EPS = float(np.finfo(float).eps)
#: 6205 and 6320 as the catalogue gives them (NSK ball sets; f_i 0.52, f_o 0.53, E 208 GPa;
#: the 6205's CN clearance mean 12.5 µm).
B6205 = dict(ball_diameter=7.938, pitch_diameter=38.5, f_i=0.52, f_o=0.53, modulus=208000.0)
B6320 = dict(ball_diameter=36.512, pitch_diameter=157.5, f_i=0.52, f_o=0.53, modulus=208000.0)

#: (z, F_r [N], G_r [mm], n [rpm], geometry): the reviewer's reproductions.
CASES = [
    (9, 1e-6, 0.0125, 3000.0, B6205),
    (9, 1e-6, 0.0125, 10000.0, B6205),
    (9, 1e-4, -0.002, 3000.0, B6205),
    (9, 1e-4, -0.010, 3000.0, B6205),
    (9, 1e-4, -0.050, 3000.0, B6205),
    (9, 1e-5, -0.010, 10000.0, B6205),
    (9, 1e-5, -0.010, 30000.0, B6205),
    (9, 1e-5, -0.010, 50000.0, B6205),
    (8, 0.01, -0.010, 3809.52, B6320),
]


def ring_check(r, fr, geometry):
    """(|exact sum - F_r|, the rounding level) of the radial component, and the exact sum of the
    component across the load (held by symmetry). [N]"""
    q, ai = r.ball_loads_inner, np.radians(r.contact_angles_inner)
    phi = np.radians(r.ball_angles)
    along = q * np.cos(ai) * np.cos(phi)
    across = q * np.cos(ai) * np.sin(phi)
    big_a = (geometry["f_i"] + geometry["f_o"] - 1.0) * geometry["ball_diameter"]
    loaded = q > 0
    stiff = np.sum(1.5 * q[loaded] / r.approaches_inner[loaded])
    level = 64.0 * EPS * np.abs(along).sum() + 4.0 * EPS * big_a * stiff
    return abs(math.fsum(along.tolist()) - fr), level, abs(math.fsum(across.tolist()))


@pytest.mark.parametrize("z, fr, clearance, speed, geometry", CASES)
def test_a_light_load_at_speed_is_balanced_to_its_rounding(z, fr, clearance, speed, geometry):
    r = solve_high_speed(z, fr, 0.0, speed=speed, clearance=clearance, **geometry)
    off, level, across = ring_check(r, fr, geometry)
    assert off <= max(1e-12 * fr, level), (off / fr, level / fr)
    assert across <= max(1e-12 * fr, level), (across / fr, level / fr)
    # the rounding is far below the load: the answer resolves it
    assert level <= 1e-4 * fr
    case = {"kw": {"ball_diameter": geometry["ball_diameter"]}}
    assert ball_residual(case, r) <= 1e-11
    assert np.all(r.ball_loads_inner >= 0) and np.any(r.ball_loads_inner > 0)
    # the balls carry their centrifugal force at the outer contacts
    assert np.all(r.ball_loads_outer >= r.centrifugal_forces * (1 - 1e-12))


def test_the_terminal_calls_answer():
    """``solve 6205 -F 1e-6N --speed 3000``, ``solve 6205 -G -10um -F 1e-4N --speed 3000`` and
    ``solve 6320 -F 0.01N -G -10um --speed 3809.52`` answer (exit 0), as --quasi-static does,
    with the ball dynamics: the library's answer (the json keeps 10 digits)."""
    calls = [(["6205", "-F", "1e-6N", "--speed", "3000"], CASES[0]),
             (["6205", "-G", "-10um", "-F", "1e-4N", "--speed", "3000"], CASES[3]),
             (["6320", "-F", "0.01N", "-G", "-10um", "--speed", "3809.52"], CASES[8])]  # fmt: skip
    for args, (z, fr, clearance, speed, geometry) in calls:
        out = CliRunner().invoke(main, ["solve", *args, "--format", "json"])
        assert out.exit_code == 0, out.output
        case = json.loads(out.stdout)["cases"][0]
        assert "ball dynamics" in case["model"]
        r = solve_high_speed(z, fr, 0.0, speed=speed, clearance=clearance, **geometry)
        assert np.allclose(case["ball_loads_inner"], r.ball_loads_inner, rtol=1e-9, atol=0)
        assert np.allclose(case["ball_loads_outer"], r.ball_loads_outer, rtol=1e-9, atol=0)


@pytest.mark.parametrize("fr, clearance, speed", [(1e-6, -0.010, 100.0), (8e-7, -0.050, 30000.0)])
def test_a_load_below_the_rounding_of_the_ball_forces_is_refused(fr, clearance, speed):
    """1e-6 N against 10 µm of preload (ball loads of 96 N), 8e-7 N against 50 µm (1100 N): the
    rounding of the ball forces is more than 1e-5 of the load; refused, naming the load and the
    smallest accepted, which is answered and balanced to its rounding."""
    with pytest.raises(InputError, match="too small against the ball forces") as err:
        solve_high_speed(9, fr, 0.0, speed=speed, clearance=clearance, **B6205)
    assert err.value.parameter == "radial_load"
    smallest = float(re.search(r"at least ([0-9.e+-]+) N", str(err.value)).group(1))
    assert fr < smallest < 1e3 * fr
    r = solve_high_speed(9, smallest, 0.0, speed=speed, clearance=clearance, **B6205)
    off, level, across = ring_check(r, smallest, B6205)
    assert off <= max(1e-12 * smallest, level) and across <= max(1e-12 * smallest, level)


def test_a_case_refused_among_mixed_speeds_is_named_by_its_speed_element():
    """Speeds [0, 3000, 50000] rpm with 1e-6 N against 5 µm of preload: the case at 3000 rpm is
    refused first (the largest rounding at the lowest speed but 0); the refusal named only
    'radial_load', which is one number for all three; it names the speed that tells the case
    apart, by its index, as the other array refusals name their element."""
    speeds = np.array([0.0, 3000.0, 50000.0])
    with pytest.raises(InputError, match="too small against the ball forces") as err:
        solve_high_speed(9, 1e-6, 0.0, speed=speeds, clearance=-0.005, **B6205)
    assert err.value.parameter == "speed" and err.value.element == "[1] = 3000 rpm"
    assert str(err.value).startswith("speed[1] = 3000 rpm: the loads are too small")
    # one speed for every case: the load names the case, by its own element where an array
    with pytest.raises(InputError) as err:
        solve_high_speed(9, np.array([1.0, 1e-6]), 0.0, speed=3000.0, clearance=-0.005, **B6205)
    assert err.value.parameter == "radial_load" and err.value.element == "[1] = 1e-06 N"


def test_a_pair_refused_among_mixed_speeds_is_named_by_its_speed_element():
    from bearingload.models.pair_speed import solve_pair_high_speed

    kw = dict(preload=0.0, contact_angle=40.0, width=15.0, **B6205)
    with pytest.raises(InputError, match="too small against the ball forces") as err:
        solve_pair_high_speed(12, 1e-6, 1e-6, speed=np.array([3000.0, 40000.0]), **kw)
    assert err.value.parameter == "speed" and err.value.element == "[1] = 40000 rpm"


@pytest.mark.parametrize("fa", [5e-6, 1e-5, 2e-5])
def test_light_axial_load_of_an_angular_contact_bearing_at_speed_is_answered(fa):
    """``solve 7205B -F 0 -A 1e-5N --speed 3000`` (also 5e-6 N, 2e-5 N) ended on a
    ConvergenceError (ring residual 1.6e-9, 2.4e-9, 1.2e-9 of the load: above ACCEPT), while
    1e-6 N and 3e-5 N answered: the balls are balanced to BALL_TOLERANCE of their forces (about
    1.2 N with the centrifugal force, 1e5 times the load), and their residuals move the inner
    ring forces by up to 2e-6 of the load (measured), so the ring Newton stalls there. Checked
    from the returned balls: the axial sum of Q_i sin alpha_i (math.fsum) is the load to
    NOISE_MAX of it, the sums across it vanish to that, every ball's equations hold to 1e-11."""
    r = solve_high_speed(12, 0.0, fa, speed=3000.0, **B7205B)
    q, ai = r.ball_loads_inner, np.radians(r.contact_angles_inner)
    phi = np.radians(r.ball_angles)
    axial = math.fsum((q * np.sin(ai)).tolist())
    assert abs(axial - fa) <= NOISE_MAX * fa, (axial - fa) / fa
    for w in (np.cos(phi), np.sin(phi)):
        assert abs(math.fsum((q * np.cos(ai) * w).tolist())) <= NOISE_MAX * fa
    assert ball_residual({"kw": {"ball_diameter": B7205B["ball_diameter"]}}, r) <= 1e-11
    assert np.all(r.ball_loads_outer >= r.centrifugal_forces * (1 - 1e-12))
    out = CliRunner().invoke(
        main, ["solve", "7205B", "-F", "0", "-A", f"{fa}N", "--speed", "3000", "--format", "json"]
    )
    assert out.exit_code == 0, out.output
