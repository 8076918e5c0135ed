"""The Hertz set-up of the combined solver is cached per geometry across calls
(bearingload.models.combined._hertz_setup): a cached set-up gives the bit-identical answer to a
computed one, whatever else the cache holds or the call contains."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from bearingload.models import combined
from bearingload.models.combined import solve_combined

GEOMETRY = {"ball_diameter": 7.938, "f_i": 0.52, "f_o": 0.53}


def _fields(r: combined.CombinedDistribution) -> dict:
    return {f.name: np.asarray(getattr(r, f.name)) for f in dataclasses.fields(r)}


def _same(a: combined.CombinedDistribution, b: combined.CombinedDistribution) -> None:
    fa, fb = _fields(a), _fields(b)
    for name, value in fa.items():
        assert value.tobytes() == fb[name].tobytes(), name


def _case(pitch: object, load: object = 1500.0) -> combined.CombinedDistribution:
    return solve_combined(9, load, 700.0, pitch_diameter=pitch, clearance=0.012, **GEOMETRY)


@pytest.fixture
def empty_cache() -> None:
    combined._SETUP.clear()
    yield
    combined._SETUP.clear()


def test_cached_setup_is_bit_identical(empty_cache: None) -> None:
    cold = _case(38.5)
    assert len(combined._SETUP) == 1
    _same(cold, _case(38.5))  # from the cache
    pitches = np.array([40.0, 38.5, 52.0, 40.0])
    loads = np.array([200.0, 1500.0, 3000.0, 900.0])
    mixed = _case(pitches, loads)  # one geometry cached, two not
    for i in range(4):
        combined._SETUP.clear()
        alone = _case(float(pitches[i]), float(loads[i]))
        for name, value in _fields(mixed).items():
            if name != "balls":
                assert value[i].tobytes() == _fields(alone)[name].tobytes(), (i, name)


def test_cache_is_bounded_and_evicted_setups_recomputed_alike(empty_cache: None) -> None:
    first = _case(38.5)
    size = combined.SETUP_CACHE_SIZE
    pitches = 40.0 + np.arange(size + 3) * 0.01
    solve_combined(9, 1000.0, 300.0, pitch_diameter=pitches, **GEOMETRY)
    assert len(combined._SETUP) == size
    assert (7.938, 38.5, 0.52, 0.53, combined.STEEL_MODULUS, 0.3) not in combined._SETUP
    _same(first, _case(38.5))


def test_setup_matches_the_exact_stiffness(empty_cache: None) -> None:
    """K_0 is the exact Hertz stiffness at alpha = 0, cached or not."""
    for _ in range(2):
        r = _case(38.5, 1e-3)  # a tiny load: contact angles near alpha_0, K near K_0
        exact = combined.ball_stiffness_at(r.contact_angles, 7.938, 38.5, 0.52, 0.53)
        assert np.allclose(r.ball_stiffnesses, exact, rtol=1e-12, atol=0)
