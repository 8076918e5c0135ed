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
    # 2200 / 360^(1/3) = 309.3 kgf
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


# ISO 281:2007, 5.2, Table 3, single-row radial ball bearings, normal clearance: rows
# (f0 F_a/C0r, e, Y) and X = 0.56 for F_a/F_r > e, copied from the standard's table.
ISO281_TABLE3 = [
    (0.172, 0.19, 2.30),
    (0.345, 0.22, 1.99),
    (0.689, 0.26, 1.71),
    (1.03, 0.28, 1.55),
    (1.38, 0.30, 1.45),
    (2.07, 0.34, 1.31),
    (3.45, 0.38, 1.15),
    (5.17, 0.42, 1.04),
    (6.89, 0.44, 1.00),
]


@pytest.mark.parametrize(("ratio", "e", "y"), ISO281_TABLE3)
def test_iso281_table3_rows(ratio, e, y):
    from bearingload.bearings.life import equivalent_load_deep_groove

    c0, f0 = 10000.0, 10.0
    fa = ratio * c0 / f0
    # just above e: P = 0.56 F_r + Y F_a; just below: P = F_r
    fr_above = fa / (e * 1.001)
    p = float(equivalent_load_deep_groove(fr_above, fa, c0, f0))
    assert p == pytest.approx(0.56 * fr_above + y * fa, rel=1e-12)
    fr_below = fa / (e * 0.999)
    assert float(equivalent_load_deep_groove(fr_below, fa, c0, f0)) == fr_below


def test_iso281_interpolates_and_clamps():
    from bearingload.bearings.life import equivalent_load_deep_groove

    # halfway between the rows 1.03 and 1.38: Y = 1.50
    p = float(equivalent_load_deep_groove(100.0, 1205.0, 10000.0, 10.0))
    assert p == pytest.approx(56.0 + 1.50 * 1205.0, rel=1e-12)
    # beyond the last row the last Y (1.00), below the first the first (2.30)
    assert float(equivalent_load_deep_groove(1.0, 1e5, 1e4, 1.0)) == pytest.approx(0.56 + 1e5)
    assert float(equivalent_load_deep_groove(1.0, 10.0, 1e6, 1.0)) == pytest.approx(0.56 + 23.0)
    # pure axial load, f0 F_a/C0r = 1.0 (between the rows 0.689 and 1.03): P = Y F_a
    y = 1.71 + (1.0 - 0.689) / (1.03 - 0.689) * (1.55 - 1.71)
    assert float(equivalent_load_deep_groove(0.0, 1000.0, 1e4, 10.0)) == pytest.approx(y * 1000)
