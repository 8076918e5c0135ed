"""Tests of the method registry and of the discrete answer tending to the continuum one as z grows."""

from __future__ import annotations

import inspect
import math
import subprocess
import sys
from typing import Any

import mpmath as mp
import numpy as np
import pytest

from bearingload.errors import InputError
from bearingload.models.approximations import (
    PALMGREN_CONSTANT,
    STRIBECK_CONSTANT,
    palmgren,
    stribeck,
)
from bearingload.models.case import Result
from bearingload.models.continuum import solve_continuum
from bearingload.models.equilibrium import solve
from bearingload.models.registry import (
    DEFAULT_METHOD,
    METHODS,
    compute,
    compute_all,
    get_method,
    list_methods,
    relative_error,
)

KGF = 9.80665
CASE = (8, 300 * KGF, 4700 * KGF, 0.02, 0.0, 1.5)  # bearing 306 of Kuzmenko (2010), G_r = 20 um
Z_SERIES = np.array([5, 10, 20, 40, 80, 160, 320])


# --------------------------------------------------------------------------- the registry


def test_list_and_default():
    assert list_methods() == ["exact", "continuum", "stribeck", "palmgren"]
    assert DEFAULT_METHOD == "exact" == list_methods()[0]
    assert list(METHODS) == list_methods()


def test_same_signature_for_every_method():
    """Every model function names its parameters like the case inputs, in the same order (it
    leaves out what it ignores), and every model answers with one Result."""
    names = ["balls", "load", "stiffness", "clearance", "cage_angle", "exponent"]
    for name, method in METHODS.items():
        assert method.name == name
        params = [p for p in inspect.signature(method.model()).parameters if p in names]
        assert params == [p for p in names if p not in method.ignores]
        assert params[:2] == ["balls", "load"]
        r = method(*CASE)
        assert isinstance(r, Result) and r.method == name
        for value in (r.k, r.q_max, r.K_Q):
            assert isinstance(value, float)
        assert r.q_max == pytest.approx(r.k * CASE[1], rel=1e-14)
        assert r.K_Q == pytest.approx(r.k * CASE[0] / 2, rel=1e-14)


def test_titles_quote_the_constants_and_import_is_light():
    assert f"Q_max = {STRIBECK_CONSTANT:g} F_r/z" in METHODS["stribeck"].title
    assert f"Q_max = {PALMGREN_CONSTANT:g} F_r/z" in METHODS["palmgren"].title
    code = "import sys, bearingload.models.registry; print('numpy' in sys.modules)"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert r.stdout.strip() == "False", r.stderr


def test_unknown_method_names_the_valid_ones():
    with pytest.raises(
        InputError, match="unknown method 'hertz'; valid: exact, continuum, stribeck, palmgren"
    ) as exc:
        compute("hertz", *CASE)
    assert exc.value.parameter == "method"
    with pytest.raises(InputError):
        get_method(None)  # type: ignore[arg-type]


def test_each_method_is_its_library_function():
    z, f, k, g, a, m = CASE
    exact = solve(z, f, k, g, a, m)
    r = compute("exact", *CASE)
    assert (r.k, r.q_max, r.K_Q, r.load_zone) == (
        float(exact.k),
        float(exact.q_max),
        float(exact.K_Q),
        float(exact.load_zone),
    )
    cont = solve_continuum(z, f, k, g, m)
    r = compute("continuum", *CASE)
    assert (r.k, r.q_max, r.K_Q, r.load_zone) == (
        float(cont.k),
        float(cont.q_max),
        float(cont.K_Q),
        float(cont.load_zone),
    )
    assert compute("stribeck", *CASE).q_max == stribeck(z, f).q_max == 4.37 * f / 8
    assert compute("palmgren", *CASE).q_max == palmgren(z, f).q_max == 5 * f / 8


def test_one_line_estimates_have_no_load_zone_and_ignore_the_rest():
    for name in ("stribeck", "palmgren"):
        assert set(METHODS[name].ignores) == {"stiffness", "clearance", "cage_angle", "exponent"}
        a = compute(name, 9, 1000.0, 1e5)
        b = compute(name, 9, 1000.0, 3.0, -0.05, 17.0, 10 / 9)
        assert a.quantities() == b.quantities() and a.load_zone is None
        assert a.valid is True and b.valid is False  # outside the estimate's range: said so
        # ... but they reject what no method accepts
        for bad, param in (((9, 1000.0, -1.0), "stiffness"), ((9, 1000.0, 1e5, math.nan), "clearance"),
                           ((9, 1000.0, 1e5, 0.0, 0.0, 0.5), "exponent"), ((0, 1000.0, 1e5), "balls")):  # fmt: skip
            with pytest.raises(InputError) as exc:
                compute(name, *bad)
            assert exc.value.parameter == param
    # Stribeck's K_Q = 4.37/2 and Palmgren's 5/2 for every z (the paper's K_Q definition)
    assert compute("stribeck", 17, 1.0, 1.0).K_Q == pytest.approx(2.185)
    assert compute("palmgren", 17, 1.0, 1.0).K_Q == pytest.approx(2.5)


def test_continuum_ignores_the_cage_angle_but_checks_it():
    assert METHODS["continuum"].ignores == ("cage_angle",)
    assert (
        compute("continuum", *CASE[:4], 22.5).quantities()
        == compute("continuum", *CASE).quantities()
    )
    with pytest.raises(InputError) as exc:
        compute("continuum", *CASE[:4], math.inf)
    assert exc.value.parameter == "cage_angle"


def test_vectorised_and_broadcast():
    z = np.arange(5, 31)
    for name in list_methods():
        r = compute(name, z, 1000.0, 1e5, 0.0, 0.0)
        assert np.shape(r.k) == np.shape(r.q_max) == np.shape(r.K_Q) == z.shape
        for i in (0, 7, 25):
            one = compute(name, int(z[i]), 1000.0, 1e5)
            assert float(r.k[i]) == pytest.approx(one.k, rel=1e-12)
    # the cage angle broadcasts against z for the continuum too
    r = compute("continuum", 9, 1000.0, 1e5, 0.0, [0.0, 10.0, 20.0])
    assert np.shape(r.k) == (3,) and np.all(r.k == r.k[0])


def test_compute_all_and_relative_error():
    results = compute_all(*CASE)
    assert list(results) == list_methods()
    assert relative_error(results["exact"], results["exact"]) == 0.0
    err = relative_error(results["stribeck"], results["exact"])
    assert err == pytest.approx(results["stribeck"].k / results["exact"].k - 1, rel=1e-12)


def test_exact_k_z9_is_table_2_2():
    # Kuzmenko & Sabadash (2014), Table 2.2, cell z/n1 = 9/5: K_Q = 2.193 (zero clearance, ball
    # under the load); checked against the Stribeck sum with mpmath.
    with mp.workdps(30):
        s = 1 + 2 * sum(mp.cos(2 * mp.pi * i / 9) ** mp.mpf(2.5) for i in (1, 2))
        ref = float(9 / (2 * s))
    r = compute("exact", 9, 1000.0, 1e5)
    assert r.K_Q == pytest.approx(ref, rel=1e-12)
    assert round(r.K_Q, 3) == 2.193


# --------------------------------------------------------------------------- discrete -> continuum


def _rel(z: np.ndarray, clearance: float, cage: str, m: float = 1.5) -> tuple[np.ndarray, Any]:
    """k_exact/k_continuum - 1 at F_r = 100 N per ball (so the continuum k z is the same for all z)."""
    load = 100.0 * z
    angle = 0.0 if cage == "ball" else 180.0 / z
    exact = compute("exact", z, load, 1e5, clearance, angle, m)
    cont = compute("continuum", z, load, 1e5, clearance, angle, m)
    return np.asarray(exact.k) / np.asarray(cont.k) - 1.0, cont


def _slope(z: np.ndarray, err: np.ndarray) -> float:
    return float(np.polyfit(np.log(z), np.log(np.abs(err)), 1)[0])


@pytest.mark.parametrize("m", [1.5, 10 / 9])
def test_discrete_tends_to_continuum_zero_clearance(m):
    """A ball under the load: |k_exact/k_continuum - 1| falls at every step, like z^-(m+2).

    The continuum limit is k z = pi/I_m (Kuzmenko 2010, eq. 4.19), I_m by mpmath quadrature.
    The summand cos^(m+1) vanishes to order m+1 at the edge of the load zone (90°), so the
    discrete sum (a trapezoid rule) differs from the integral by O(z^-(m+2)).
    """
    err, cont = _rel(Z_SERIES, 0.0, "ball", m)
    with mp.workdps(30):
        limit = float(mp.pi / mp.quad(lambda p: mp.cos(p) ** (mp.mpf(m) + 1), [0, mp.pi / 2]))
    assert np.asarray(cont.k) * Z_SERIES == pytest.approx(limit, rel=1e-13)
    assert np.all(np.diff(np.abs(err)) < 0), err
    assert _slope(Z_SERIES[-4:], err[-4:]) == pytest.approx(-(m + 2), abs=0.1)
    assert abs(err[-1]) < (2e-8 if m == 1.5 else 2e-7)
    if m == 1.5:  # the numbers quoted in the README (zero clearance, ball under the load)
        assert abs(err[0]) == pytest.approx(0.0343, abs=5e-5)  # z = 5: +3.4 %
        assert abs(err[1]) == pytest.approx(0.00206, abs=5e-6)  # z = 10: +0.21 %
        assert abs(err[6]) == pytest.approx(1.26e-8, rel=0.01)  # z = 320


@pytest.mark.parametrize("clearance", [0.0, 0.02, -0.01])
def test_discrete_tends_to_continuum_half_pitch(clearance):
    """The load between two balls: the heaviest ball sits at pi/z from the load line, so
    k_exact/k_continuum - 1 -> -(m/2) (pi/z)^2 / (2 eps), eps = (1 - e/x)/2 of the continuum."""
    err, _ = _rel(Z_SERIES, clearance, "half")
    assert np.all(err < 0) and np.all(np.diff(np.abs(err)) < 0), err
    eps = solve_continuum(Z_SERIES, 100.0 * Z_SERIES, 1e5, clearance).epsilon
    predicted = -0.75 * (np.pi / Z_SERIES) ** 2 / (2 * eps)
    assert err[-1] / predicted[-1] == pytest.approx(1.0, abs=0.01)
    assert _slope(Z_SERIES[-4:], err[-4:]) == pytest.approx(-2.0, abs=0.05)


@pytest.mark.parametrize("clearance", [0.02, -0.01])
def test_discrete_tends_to_continuum_with_clearance(clearance):
    """With clearance (or preload) and a ball under the load the error oscillates in sign, because
    the edge of the load zone moves between balls, but its envelope falls: the largest |error| at
    or beyond each z never grows, and stays below 1/z^2."""
    err, _ = _rel(Z_SERIES, clearance, "ball")
    envelope = np.maximum.accumulate(np.abs(err)[::-1])[::-1]
    assert np.all(np.diff(envelope) <= 0), err
    assert envelope[-1] < 1e-4 * envelope[0]
    assert np.all(np.abs(err) * Z_SERIES**2 < 1.0), err
    assert abs(err[-1]) < 1e-6
    assert abs(err[0]) > 1e-2  # z = 5 is far from the continuum (1.7 % / 3.2 %)
