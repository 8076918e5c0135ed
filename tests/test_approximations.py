"""Tests of the Stribeck and Palmgren one-line estimates."""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearingload import compute
from bearingload.errors import InputError
from bearingload.models.approximations import (
    PALMGREN_CONSTANT,
    STRIBECK_CONSTANT,
    Approximation,
    palmgren,
    stribeck,
)


def test_published_constants():
    # Stribeck 1901 (Kuzmenko 2010, ref. [2]): Q_max = 4.37 F_r / z.
    assert STRIBECK_CONSTANT == 4.37
    # The crane paper (2009), eq. (2): Q = 5 F_r / (i z cos alpha).
    assert PALMGREN_CONSTANT == 5.0


def test_stribeck_constant_is_the_continuum_value_rounded():
    """4.37 = pi / int_0^{pi/2} cos^{5/2} (mpmath), rounded to three figures."""
    with mp.workdps(30):
        exact = mp.pi / mp.quad(lambda p: mp.cos(p) ** 2.5, [0, mp.pi / 2])
    assert round(float(exact), 2) == STRIBECK_CONSTANT
    assert abs(float(exact) - STRIBECK_CONSTANT) < 1e-4


def test_stribeck_values():
    r = stribeck(8, 300 * 9.80665)
    assert isinstance(r, Approximation)
    assert isinstance(r.k, float) and isinstance(r.q_max, float)
    assert r.k == pytest.approx(4.37 / 8, rel=1e-15)
    assert r.q_max == pytest.approx(4.37 / 8 * 300 * 9.80665, rel=1e-15)
    # Bearing 306 (Kuzmenko 2010, §3.3): Stribeck gives 163.9 kgf against the discrete 163 kgf.
    assert stribeck(8, 300.0).q_max == pytest.approx(163.875, rel=1e-12)


def test_palmgren_values_rows_and_angle():
    r = palmgren(8, 1000.0)
    assert r.k == 5 / 8 and r.q_max == pytest.approx(625.0)
    r = palmgren(12, 1000.0, rows=2, contact_angle=30.0)  # degrees
    with mp.workdps(30):
        ref = 5 * 1000 / (2 * 12 * mp.cos(mp.radians(30)))
    assert r.q_max == pytest.approx(float(ref), rel=1e-14)


def test_vectorised_and_broadcast():
    z = np.array([8, 9, 12])
    loads = np.array([[100.0], [1000.0]])
    r = stribeck(z, loads)
    assert r.q_max.shape == (2, 3) and r.k.shape == (2, 3)
    assert np.allclose(r.k[0], 4.37 / z)
    assert np.allclose(r.q_max, 4.37 / z * loads)
    p = palmgren(z, 1000.0)
    assert np.allclose(p.k, 5 / z)


@given(z=st.integers(1, 200), load=st.floats(1e-6, 1e9))
def test_palmgren_exceeds_stribeck(z, load):
    assert palmgren(z, load).q_max > stribeck(z, load).q_max


def test_errors():
    with pytest.raises(InputError, match="balls"):
        stribeck(0, 100.0)
    with pytest.raises(InputError, match="balls"):
        palmgren(np.array([8, 0]), 100.0)
    with pytest.raises(InputError, match="load"):
        stribeck(8, -1.0)
    with pytest.raises(InputError, match="load"):
        stribeck(8, np.nan)
    with pytest.raises(InputError, match="rows"):
        palmgren(8, 100.0, rows=0)
    with pytest.raises(InputError, match="contact_angle"):
        palmgren(8, 100.0, contact_angle=90.0)
    with pytest.raises(InputError, match="constant"):
        stribeck(8, 100.0, constant=0.0)


def test_one_line_estimates_are_outside_their_range_below_five_balls():
    """k = 4.37/z (5/z) above 1 for z < 5: one ball would carry more than the whole load."""
    for z in (1, 2, 3, 4):
        assert compute("stribeck", z, 1000.0, 1e5).valid is False
        assert compute("palmgren", z, 1000.0, 1e5).valid is False
    assert compute("stribeck", 5, 1000.0, 1e5).valid is True
