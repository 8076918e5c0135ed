"""One vocabulary: the JSON key of a quantity is its library field; one scalar contract."""

import json

import numpy as np
from click.testing import CliRunner

from bearingload.cli import main
from bearingload.contact.hertz import ball_stiffness
from bearingload.models.combined import CombinedDistribution, solve_combined
from bearingload.models.equilibrium import solve
from bearingload.reports.quantities import QUANTITIES

GEOMETRY = {"ball_diameter": 7.938, "pitch_diameter": 38.5}


def test_scalar_case_gives_python_floats_everywhere():
    r = solve(8, 1000.0, 4.7e4, 0.02)
    c = solve_combined(9, 1000.0, 500.0, clearance=0.01, **GEOMETRY)
    k = ball_stiffness(7.938, 38.5, 0.52, 0.53)
    for value in (
        r.q_max,
        r.stiffness_radial,
        c.q_max,
        c.x,
        c.axial,
        c.tilt,
        c.load,
        k.ball,
        k.inner,
    ):
        assert type(value) is float, type(value)
    assert type(c.iterations) is int
    # ball-level quantities stay arrays, of one case (z,)
    assert r.ball_loads.shape == (8,) and c.ball_loads.shape == (9,)
    assert r.ball_angles.shape == (8,) and c.contact_angles.shape == (9,)


def test_array_case_gives_arrays():
    c = solve_combined(9, [1000.0, 2000.0], 500.0, clearance=0.01, **GEOMETRY)
    assert isinstance(c.axial, np.ndarray) and c.axial.shape == (2,)
    assert c.ball_loads.shape == (2, 9)


def test_json_keys_are_the_library_field_names():
    fields = set(CombinedDistribution.__dataclass_fields__)
    for key in ("load", "axial", "tilt", "tilt_cross", "cage_angle", "free_contact_angle"):
        assert key in fields and key in QUANTITIES
    assert not [k for k in QUANTITIES if k.endswith("_deg")]
    out = CliRunner().invoke(
        main,
        ["solve", "6205", "--load", "1kN", "--axial-load", "500N", "--format", "json"],
    )
    assert out.exit_code == 0, out.output
    text = out.stdout
    assert '"axial"' in text and '"deflection_axial"' not in text and "_deg" not in text
    json.loads(text)
