"""The combined solver just off a symmetric cage at tiny loads: within 1e-9° of a ball on the
load line (or the load between two balls) a case the Newton cannot balance is answered with the
balls at the symmetric position, as the radial engine answers it."""

from __future__ import annotations

import pytest

from bearingload import solve, solve_combined
from bearingload.models.combined import NEAR_SYMMETRIC_DEG

#: A 6205's ball set, G_r = 20 µm: F_r = 0.01 N and a cage 1e-12° off the load line ended in a
#: ConvergenceError after 2016 iterations (relative residual 1.75e-8).
RING = {"ball_diameter": 7.938, "pitch_diameter": 38.5, "clearance": 0.02}


@pytest.mark.parametrize("load", [1e-3, 1e-2, 3e-2])
@pytest.mark.parametrize("cage", [1e-12, -1e-12, 40.0 - 1e-12])
def test_a_tiny_load_just_off_symmetry_is_solved(load, cage):
    r = solve_combined(9, load, 0.0, cage_angle=cage, **RING)
    symmetric = solve_combined(9, load, 0.0, cage_angle=round(cage / 40.0) * 40.0, **RING)
    assert r.q_max == pytest.approx(symmetric.q_max, rel=1e-9)
    assert r.x == pytest.approx(symmetric.x, rel=1e-9)
    radial = solve(9, load, float(symmetric.ball_stiffnesses[0]), 0.02, cage_angle=0.0)
    assert r.q_max == pytest.approx(radial.q_max, rel=1e-6)


def test_only_cages_within_the_band_are_snapped():
    assert NEAR_SYMMETRIC_DEG == 1e-9
    r = solve_combined(9, 1.0, 0.0, cage_angle=1e-12, **RING)  # balanced as it is: not moved
    assert r.iterations < 2016
