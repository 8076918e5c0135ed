"""A refusal of an array input names its first bad element by index and value, as the range
checks do (``clearance[1] = 5 mm``): the loads too small (or, angular contact, too large) for
the combined solver, and the ring geometry of :func:`groove_geometry` as of
:func:`solve_combined`."""

import numpy as np
import pytest

from bearingload.errors import InputError
from bearingload.models.combined import groove_geometry, solve_combined

GEOMETRY = {"ball_diameter": 7.938, "pitch_diameter": 38.5}


def _refusal(*args, **kwargs) -> InputError:
    with pytest.raises(InputError) as info:
        solve_combined(*args, **kwargs)
    return info.value


def test_loads_too_small_name_the_first_case_refused():
    """The message's load is that case's (2e-9 N), not the smallest of the call (1e-9 N)."""
    exc = _refusal(9, np.array([1e3, 2e-9, 1e-9]), 0.0, **GEOMETRY, clearance=0.01)
    assert exc.reason == "too_light" and exc.element == "[1] = 2e-09 N"
    assert str(exc).startswith("radial_load[1] = 2e-09 N: the loads are too small")
    assert "M/R_i is 2e-09 N" in str(exc)


def test_loads_too_small_name_the_largest_load_of_the_case():
    """The case's largest load names the input: the thrust of case 2 under 1e-10 N radial."""
    exc = _refusal(9, 1e-10, np.array([100.0, 50.0, 3e-9]), **GEOMETRY)
    assert str(exc).startswith("axial_load[2] = 3e-09 N: the loads are too small")


def test_one_load_beside_arrays_names_no_element():
    """A load given as one number has no element to name (its cases come from other arrays)."""
    exc = _refusal(9, 1e-9, 0.0, **GEOMETRY, clearance=np.array([0.01, 0.02]))
    assert exc.reason == "too_light" and exc.element == ""


def test_angular_loads_too_large_name_the_case():
    exc = _refusal(12, np.array([1.0, 1e30]), 100.0, **GEOMETRY, contact_angle=25.0)
    assert str(exc).startswith("radial_load[1] = 1e+30 N: too large for the angular-contact")


BAD_GEOMETRIES = [
    {"clearance": np.array([0.01, 0.02, 2.0])},
    {"clearance": np.array([0.01, -0.02, -5.0])},
    {"clearance": np.array([0.01, 2.0]), "ball_diameter": np.array([7.938, 50.0])},
    {"clearance": np.array([0.01, 2.0]), "f_i": np.array([0.52, 0.4])},
    {"clearance": np.nan, "ball_diameter": np.array([7.938, -1.0])},
    {"ball_diameter": np.array([7.938, 50.0]), "f_i": 0.3},
    {"ball_diameter": -1.0, "clearance": np.array([0.01, 0.02])},
    {"pitch_diameter": np.array([[38.5], [-1.0]]), "clearance": np.array([0.01, 0.1])},
]


@pytest.mark.parametrize("bad", BAD_GEOMETRIES)
def test_groove_geometry_refuses_as_solve_combined(bad):
    """groove_geometry refuses the input solve_combined refuses, in the same order of checks,
    naming the same element (none for one number beside arrays)."""
    given = {**GEOMETRY, "f_i": 0.52, "f_o": 0.53, "clearance": 0.01} | bad
    with pytest.raises(InputError) as groove:
        groove_geometry(*given.values())
    assert str(groove.value) == str(_refusal(9, 1000.0, 0.0, **given))


def test_groove_geometry_names_the_clearance_element():
    with pytest.raises(InputError) as info:
        groove_geometry(7.938, 38.5, 0.52, 0.53, np.array([0.01, 2.0]))
    assert str(info.value).startswith("clearance[1] = 2 mm: must be smaller than 2 (f_i")


def test_a_case_among_many_is_refused_as_alone():
    """analyse_many (and batch, by the same plan) names a case by its index: its refusal is the
    one analyse gives the case alone, with no element of the call that held it."""
    from bearingload import analyse, analyse_many

    light = {"bearing": "6205", "load": "1e-9N", "axial_load": "1e-10N"}
    many = analyse_many([{"bearing": "6205", "load": "1kN", "axial_load": "10N"}, light])
    with pytest.raises(InputError) as alone:
        analyse(**light)
    assert str(many.errors[1]) == str(alone.value) and many.errors[1].element == ""
