"""Basic rating life and allowable load (bearingload.bearings.life) against Kuzmenko (2010) §3.2."""

from __future__ import annotations

import numpy as np
import pytest

from bearingload.bearings.life import ROLLER_LIFE_EXPONENT, allowable_load, rating_life
from bearingload.errors import InputError

# Kuzmenko (2010), §3.2: allowable load Q = C / N^(1/3) for bearing 306, C = 2200 kgf:
# "666 kgf" for N = 36 x 10^6 revolutions (printed to whole kgf); from the shipped data.
from .fixtures.published import KUZMENKO2010_ALLOWABLE_36_KGF, KUZMENKO2010_C_KGF


def test_allowable_load_of_the_paper():
    q = float(allowable_load(KUZMENKO2010_C_KGF, 36.0))
    assert q == pytest.approx(2200.0 / 36.0 ** (1.0 / 3.0), rel=1e-15)
    assert round(q) == KUZMENKO2010_ALLOWABLE_36_KGF  # 666.28


def test_allowable_load_for_360_million_revolutions():
    # the second check: 2200 / 360^(1/3) = 309.3 kgf
    assert float(allowable_load(2200.0, 360.0)) == pytest.approx(309.26, abs=0.005)


def test_life_and_allowable_load_are_inverse():
    c = np.array([2200.0, 21574.63, 5e4])
    life = np.array([1.0, 36.0, 1e4])
    p = allowable_load(c, life)
    np.testing.assert_allclose(rating_life(c, p), life, rtol=1e-13)
    np.testing.assert_allclose(rating_life(c, p, ROLLER_LIFE_EXPONENT) ** 0.3, (c / p))


def test_scalar_in_scalar_out_and_array_broadcast():
    assert np.ndim(rating_life(2200.0, 300.0)) == 0
    assert float(rating_life(2200.0, 300.0)) == pytest.approx((2200 / 300) ** 3, rel=1e-15)
    out = rating_life(2200.0, np.array([[100.0], [200.0]]))
    assert out.shape == (2, 1)
    assert float(rating_life(3000.0, 300.0, ROLLER_LIFE_EXPONENT)) == pytest.approx(10 ** (10 / 3))


@pytest.mark.parametrize(
    ("call", "parameter"),
    [
        (lambda: rating_life(0.0, 1.0), "C"),
        (lambda: rating_life(1.0, -1.0), "load"),
        (lambda: rating_life(1.0, np.nan), "load"),
        (lambda: allowable_load(1.0, 0.0), "revolutions"),
        (lambda: allowable_load(1.0, 1.0, exponent=0.0), "exponent"),
    ],
)
def test_bad_input(call, parameter):
    with pytest.raises(InputError, match="greater than 0") as info:
        call()
    assert info.value.parameter == parameter
