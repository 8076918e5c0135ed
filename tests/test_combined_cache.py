"""The Hertz set-up of the combined solver (K_0 and the stiffness curve's nodes, in the compiled
core for every case): the scalar Hertz stiffness's bits at every node, each case's own whatever
else its call holds, and the geometries the Hertz functions refuse refused alike."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from bearingload.contact.hertz import ball_stiffness
from bearingload.errors import InputError
from bearingload.models import _core, combined
from bearingload.models.combined import solve_combined

GEOMETRY = {"ball_diameter": 7.938, "f_i": 0.52, "f_o": 0.53}


def _fields(r: combined.CombinedDistribution) -> dict:
    return {f.name: np.asarray(getattr(r, f.name)) for f in dataclasses.fields(r)}


def _case(pitch: object, load: object = 1500.0) -> combined.CombinedDistribution:
    return solve_combined(9, load, 700.0, pitch_diameter=pitch, clearance=0.012, **GEOMETRY)


def test_a_case_is_the_same_bits_alone_or_among_other_geometries() -> None:
    pitches = np.array([40.0, 38.5, 38.5, 52.0, 40.0])
    loads = np.array([200.0, 1500.0, 800.0, 3000.0, 900.0])
    mixed = _case(pitches, loads)
    for i in range(pitches.size):
        alone = _case(float(pitches[i]), float(loads[i]))
        for name, value in _fields(mixed).items():
            if name != "balls":
                assert value[i].tobytes() == _fields(alone)[name].tobytes(), (i, name)


@pytest.mark.parametrize(
    "geometry",
    [
        (7.938, 38.5, 0.52, 0.53, 208000.0, 0.3),
        (25.4, 260.0, 0.5005, 0.58, 1e5, -0.5),
        (1.0, 1.6, 0.57, 0.501, 3.1e5, 0.5),
    ],
)
def test_the_nodes_are_the_scalar_hertz_stiffness(geometry) -> None:
    """K_0 and every node's divided difference from ``ball_stiffness`` of plain floats (its
    scalar path), to the bit."""
    x = np.cos((2.0 * np.arange(24) + 1.0) * np.pi / 48.0)
    k0, values, bad = _core.hertz_curves(np.array([geometry]), x)
    dw, dm, fi, fo, e, nu = geometry
    k1 = ball_stiffness(dw, dm, fi, fo, e, nu).ball
    assert not bad[0] and k0[0] == k1
    for c, value in zip((x + 1.0) / 2.0, values[0], strict=True):
        k = ball_stiffness(dw, float(dm / c), fi, fo, e, nu).ball
        assert value == (k / k1 - 1.0) / (c - 1.0)


def test_a_geometry_the_hertz_functions_refuse_is_refused() -> None:
    """Poisson's ratio outside (-1, 0.5] comes back from the core as a status; the Hertz
    functions name it."""
    assert _core.hertz_curves(np.array([[7.938, 38.5, 0.52, 0.53, 2e5, 0.6]]), np.zeros(24))[2][0]
    with pytest.raises(InputError, match="poisson"):
        solve_combined(9, 1000.0, 300.0, pitch_diameter=38.5, poisson=0.6, **GEOMETRY)


def test_setup_matches_the_exact_stiffness() -> None:
    """K at every ball is the exact Hertz stiffness at its contact angle."""
    for load in (1e-3, 1500.0):
        r = _case(38.5, load)
        exact = combined.ball_stiffness_at(r.contact_angles, 7.938, 38.5, 0.52, 0.53)
        assert np.allclose(r.ball_stiffnesses, exact, rtol=1e-12, atol=0)
