"""A pair left unbalanced with its cage within 1e-9° of a symmetric position is solved at that
position, as one bearing is (``solve 7205BDT -F 1kN -A 10N --cage-angle 1e-12`` ended in a
ConvergenceError of the shaft equilibrium, residual 2.8e-5 after 420 iterations)."""

import numpy as np

from bearingload.models.pair import solve_pair
from tests.bearings_data import B7205B

#: A tandem pair of 7205B (B = 15 mm).
GEOMETRY = dict(arrangement="DT", width=15.0, **B7205B)


def test_a_tandem_pair_just_off_symmetry_is_solved_at_the_symmetric_position():
    near = solve_pair(12, 1000.0, 10.0, cage_angle=1e-12, **GEOMETRY)
    at = solve_pair(12, 1000.0, 10.0, cage_angle=0.0, **GEOMETRY)
    assert np.array_equal(np.asarray(near.x), np.asarray(at.x))
    assert float(near.bearings[0].cage_angle) == 0.0  # the position it was solved at


def test_a_converged_case_near_symmetry_keeps_its_own_cage():
    """Only a case the Newton leaves unbalanced moves: a balanced one keeps its cage angle."""
    near = solve_pair(12, 1000.0, 10.0, cage_angle=1e-12, **GEOMETRY | {"arrangement": "DB"})
    assert float(near.bearings[0].cage_angle) == 1e-12
