"""bearingload.numerics: bracketed_root (the studies' root refinement without scipy) against
scipy.optimize.brentq on the project's own functions and on awkward ones; the AGM elliptic integrals
against mpmath, one contact and many."""

from __future__ import annotations

import math

import pytest
from scipy.optimize import brentq

from bearingload.errors import ConvergenceError
from bearingload.numerics import bracketed_root
from bearingload.studies.compensation import compensating_clearances, position_difference

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
        reference = brentq(
            lambda c: position_difference(z, f, k, c, m), g - h, g + h, xtol=1e-12 * s
        )
        assert abs(g - reference) <= 4e-12 * s


def test_bad_brackets_are_refused():
    with pytest.raises(ValueError, match="same sign"):
        bracketed_root(lambda x: x * x + 1.0, -1.0, 1.0)
    with pytest.raises(ValueError, match="not finite"):
        bracketed_root(lambda x: math.nan, -1.0, 1.0)
    assert bracketed_root(lambda x: x, 0.0, 1.0) == 0.0


# ---------------------------------------------------------------------------------------------
# The complete elliptic integrals by the AGM: one implementation for one contact and for many
# ---------------------------------------------------------------------------------------------


def _mp_elliptic(t: float) -> tuple[float, float, float, float]:
    """K, E, K - E and E - pK at kappa = e^t by mpmath at 200 digits (parameter m = 1 - p,
    p = 1/kappa^2 = e^(-2t); the differences taken before rounding to a double)."""
    import mpmath as mp

    with mp.workdps(200):
        p = mp.exp(-2 * mp.mpf(t))
        k, e = mp.ellipk(1 - p), mp.ellipe(1 - p)
        return float(k), float(e), float(k - e), float(e - p * k)


@pytest.mark.parametrize("t", [1e-9, 1e-4, 0.01, 0.3, 1.0, 3.0, 10.0, 40.0])
def test_elliptic_integrals_against_mpmath(t):
    import numpy as np

    from bearingload.numerics import elliptic_integrals

    k_ref, e_ref, k_minus_e, e_minus_pk = _mp_elliptic(t)
    k_int, e_int, n, d, m, p = elliptic_integrals(t)
    assert k_int == pytest.approx(k_ref, rel=4e-15)
    assert e_int == pytest.approx(e_ref, rel=4e-15)
    assert d * m == pytest.approx(k_minus_e, rel=1e-14)  # no cancellation near the circle
    assert n * m == pytest.approx(e_minus_pk, rel=1e-14)
    vector = elliptic_integrals(np.array([t]))
    assert all(isinstance(v, float) for v in (k_int, e_int, n, d))
    assert all(
        float(v[0]) == pytest.approx(s, rel=1e-15)
        for v, s in zip(vector, (k_int, e_int, n, d), strict=False)
    )


def test_elliptic_integrals_elements_do_not_depend_on_each_other():
    """Each element of an array stops at its own AGM step: alone or among others it is the same
    bit for bit, and the circle (t = 0) gives the limits K = E = pi/2, (K - E)/m = pi/4."""
    import numpy as np

    from bearingload.numerics import elliptic_integrals

    ts = np.array([0.0, 1e-12, 1e-3, 0.5, 2.0, 30.0, 300.0])
    together = elliptic_integrals(ts)
    for i, t in enumerate(ts):
        alone = elliptic_integrals(np.array([t]))
        for a, b in zip(together[:4], alone[:4], strict=True):
            assert a[i] == b[0]
    k_int, e_int, n, d = (v[0] for v in together[:4])
    assert (k_int, e_int) == (math.pi / 2, math.pi / 2)
    assert (n, d) == (math.pi / 4, math.pi / 4)


def test_bracketed_root_does_not_return_a_far_bracket_end_silently():
    # a bracket of 1e300 around a root at 1 cannot be halved to 1e-12 in 400 evaluations: it
    # returned 0.0 (where f = -0.785) as the root; it must raise instead
    with pytest.raises(ConvergenceError):
        bracketed_root(lambda x: math.atan(x - 1.0), 0.0, 1e300)
    # a wide bracket that can be halved in time still gives the root
    assert abs(bracketed_root(lambda x: math.atan(x - 1.0), 0.0, 1e6) - 1.0) <= 4e-12


def test_a_float_and_an_array_take_the_one_agm():
    """The AGM is one C function (``bearingload/_elliptic.pyx``, the compiled core's Hertz
    stiffness curve's too): given the float path's p and m (the C library's ``exp`` and
    ``expm1``), the array path's values are the float path's to the bit, at 20 000 t from 1e-9
    to 40 (log-uniform) and at the ends."""
    import numpy as np

    from bearingload import _elliptic
    from bearingload.numerics import elliptic_integrals

    rng = np.random.default_rng(1)
    ts = np.concatenate([10 ** rng.uniform(-9.0, 1.6, 20000), [1e-300, 1e-20, 1e-12, 40.0]])
    p = np.array([math.exp(-2.0 * t) for t in ts.tolist()])
    m = np.array([-math.expm1(-2.0 * t) for t in ts.tolist()])
    rows = zip(
        ts.tolist(),
        *(v.tolist() for v in _elliptic.of_arrays(p, m)),
        m.tolist(),
        p.tolist(),
        strict=True,
    )
    for t, *values in rows:
        assert tuple(values) == elliptic_integrals(t), t


@pytest.mark.parametrize("t", [-1e-12, -0.5, -40.0, math.nan])
def test_elliptic_integrals_outside_their_domain_are_nan(t):
    import numpy as np

    from bearingload.numerics import elliptic_integrals

    # kappa = e^t < 1 (m < 0) or NaN: no value, not the circle's limits
    for values in (elliptic_integrals(t), elliptic_integrals(np.array([t, 0.5]))):
        first = [float(np.ravel(v)[0]) for v in values[:4]]
        assert all(math.isnan(v) for v in first), first
    k_int, e_int, *_ = elliptic_integrals(0.0)  # the circle itself keeps its limits
    assert k_int == e_int == math.pi / 2
