"""An array input refused at any of its limits is named by the index and value of its first
offending element (``clearance[1] = 5 mm: ...``), as the library's simple limits name it."""

from __future__ import annotations

import pytest

from bearingload import solve, solve_combined, solve_continuum, solve_high_speed, solve_pair
from bearingload.errors import InputError

GEOMETRY = {"ball_diameter": 7.938, "pitch_diameter": 38.5}
PAIR = {**GEOMETRY, "contact_angle": 40.0, "width": 15.0, "preload": 100.0}


@pytest.mark.parametrize(
    ("call", "named"),
    [
        # the groove limit: G_r below 2 (f_i + f_o - 1) D_w
        (
            lambda: solve_combined(9, 1000.0, 100.0, **GEOMETRY, clearance=[0.01, 2.0]),
            "clearance[1] = 2 mm",
        ),
        (
            lambda: solve_combined(9, 1000.0, 100.0, **GEOMETRY, clearance=[[0.01], [2.0]]),
            "clearance[1, 0] = 2 mm",
        ),
        # |G_r| below half the ball diameter, and a misalignment within 2°
        (
            lambda: solve_combined(9, 1000.0, 100.0, **GEOMETRY, clearance=[[0.01], [-5.0]]),
            "clearance[1, 0] = -5 mm",
        ),
        (
            lambda: solve_combined(9, 1000.0, 100.0, **GEOMETRY, misalignment=[0.1, -3.0]),
            "misalignment[1] = -3 °",
        ),
        (
            lambda: solve_combined(9, [1000.0, 0.0], [100.0, 0.0], **GEOMETRY),
            "radial_load[1] = 0 N",
        ),
        (
            lambda: solve_combined(9, 1000.0, [100.0, -5.0], contact_angle=25.0, **GEOMETRY),
            "axial_load[1] = -5 N",
        ),
        (
            lambda: solve_combined(9, 1000.0, 100.0, contact_angle=[10.0, 70.0], **GEOMETRY),
            "contact_angle[1] = 70 °",
        ),
        # n d_m of the ball dynamics
        (
            lambda: solve_high_speed(9, 1000.0, 100.0, **GEOMETRY, speed=[3000.0, 1e7]),
            "speed[1] = 10000000 rpm",
        ),
        (
            lambda: solve_high_speed(9, 1000.0, 100.0, **GEOMETRY, speed=[3000.0, -1.0]),
            "speed[1] = -1 rpm",
        ),
        # the range of the ring equilibrium, the same in the continuum model
        (lambda: solve(8, [1000.0, 1e-300], 1e5), "load[1] = 1e-300 N"),
        (
            lambda: solve(8, [[1000.0], [1e-300]], 1e5, clearance=[0.0, 0.01]),
            "load[1, 0] = 1e-300 N",
        ),
        (lambda: solve(8, 1000.0, 1e5, clearance=[0.01, 1e300]), "clearance[1] = 1e+300 mm"),
        (lambda: solve_continuum(8, [1000.0, 1e-300], 1e5), "load[1] = 1e-300 N"),
        # a pair's width and preload
        (
            lambda: solve_pair(12, 1000.0, 100.0, **{**PAIR, "width": [15.0, 5.0]}),
            "width[1] = 5 mm",
        ),
        (
            lambda: solve_pair(12, 1000.0, 100.0, **{**PAIR, "preload": [100.0, -1.0]}),
            "preload[1] = -1 N",
        ),
    ],
)
def test_every_limit_names_the_first_bad_element(call, named):
    with pytest.raises(InputError) as info:
        call()
    assert str(info.value).startswith(f"{named}: "), str(info.value)


def test_a_pair_without_a_load_names_its_case():
    from bearingload.models.pair import solve_pair

    geometry = {"contact_angle": 40, "ball_diameter": 7.938, "pitch_diameter": 38.5}
    with pytest.raises(InputError, match=r"^radial_load\[1\] = 0 N: give a radial load"):
        solve_pair(12, [1000, 0], [300, 0], width=15, **geometry)
