"""A pair left unbalanced with its cage within 1e-9° of a symmetric position is solved at that
position, as one bearing is (``solve 7205BDT -F 1kN -A 10N --cage-angle 1e-12`` ended in a
ConvergenceError of the shaft equilibrium, residual 2.8e-5 after 420 iterations)."""

import numpy as np

from bearingload.models.pair import solve_pair

#: 7205B as the catalogue resolves it (NSK 40°, 12 balls of 8.7312 mm on 38.5 mm, 0.52/0.53).
GEOMETRY = dict(
    arrangement="DT",
    contact_angle=40.0,
    ball_diameter=8.7312,
    pitch_diameter=38.5,
    width=15.0,
    f_i=0.52,
    f_o=0.53,
    modulus=208000.0,
)


def test_a_tandem_pair_just_off_symmetry_is_solved_at_the_symmetric_position():
    near = solve_pair(12, 1000.0, 10.0, cage_angle=1e-12, **GEOMETRY)
    at = solve_pair(12, 1000.0, 10.0, cage_angle=0.0, **GEOMETRY)
    assert np.array_equal(np.asarray(near.x), np.asarray(at.x))
    assert float(near.bearings[0].cage_angle) == 0.0  # the position it was solved at


def test_a_converged_case_near_symmetry_keeps_its_own_cage():
    """Only a case the Newton leaves unbalanced moves: a balanced one keeps its cage angle."""
    near = solve_pair(12, 1000.0, 10.0, cage_angle=1e-12, **GEOMETRY | {"arrangement": "DB"})
    assert float(near.bearings[0].cage_angle) == 1e-12
