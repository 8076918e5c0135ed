"""bearingload.roots.bracketed_root (the studies' root refinement without scipy) against
scipy.optimize.brentq on the project's own functions and on awkward ones."""

from __future__ import annotations

import math

import pytest
from scipy.optimize import brentq

from bearingload.roots import bracketed_root
from bearingload.studies.compliance import _difference, compensating_clearances

AWKWARD = [  # (f, a, b, the root)
    (lambda x: x**3 - 2 * x - 5, 2.0, 3.0, None),  # None: brentq's
    (lambda x: math.exp(x) - 1e6, 0.0, 30.0, math.log(1e6)),  # steep
    (lambda x: (x - 1.0) ** 9, -3.0, 4.0, 1.0),  # flat: brentq gives up after 100 steps here
    (lambda x: math.atan(1e6 * (x - 0.3)), -1.0, 1.0, 0.3),  # a step
    (lambda x: -1.0 if x < 0.7 else 2.0, 0.0, 1.0, 0.7),  # a jump: the sign change is found
    (lambda x: math.sin(x), 3.0, 4.0, math.pi),
]


@pytest.mark.parametrize(("f", "a", "b", "root"), AWKWARD)
def test_awkward_functions(f, a, b, root):
    got = bracketed_root(f, a, b, xtol=1e-13)
    expected = brentq(f, a, b, xtol=1e-13) if root is None else root
    assert abs(got - expected) <= 4e-13 + 4 * 4.5e-16 * abs(got)


def test_compensating_clearances_agree_with_brentq():
    z, f, k, m = 9, 1000.0, 1e5, 1.5
    s = (f / k) ** (1 / m)
    for g in compensating_clearances(z, f, k, m):
        h = 1e-6 * s
        reference = brentq(_difference, g - h, g + h, args=(z, f, k, m), xtol=1e-12 * s)
        assert abs(g - reference) <= 4e-12 * s


def test_bad_brackets_are_refused():
    with pytest.raises(ValueError, match="same sign"):
        bracketed_root(lambda x: x * x + 1.0, -1.0, 1.0)
    with pytest.raises(ValueError, match="not finite"):
        bracketed_root(lambda x: math.nan, -1.0, 1.0)
    assert bracketed_root(lambda x: x, 0.0, 1.0) == 0.0
