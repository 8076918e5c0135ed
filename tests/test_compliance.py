"""The compliance abstract: compensating clearances and the paper's fits, against an mpmath reference."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from bearingload.papers import compliance as co
from bearingload.studies import compensation as comp

mp.mp.dps = 30


def ref_x(z: int, load: float, stiffness: float, clearance, cage: str) -> mp.mpf:
    """Symmetric ring displacement x [mm] at cage angle 0 ("ball") or 180/z ("half"), 30 digits."""
    e = mp.mpf(clearance) / 2
    start = 0 if cage == "ball" else mp.pi / z
    phis = [start + 2 * mp.pi * i / z for i in range(z)]

    def force(x):
        return (
            sum(stiffness * max(x * mp.cos(p) - e, 0) ** mp.mpf(1.5) * mp.cos(p) for p in phis)
            - load
        )

    lo, hi = -abs(e) - 1, abs(e) + 10 * (load / stiffness) ** (mp.mpf(2) / 3) + 1
    return mp.findroot(force, (lo, hi), solver="illinois")


def ref_difference(z, load, stiffness, clearance):
    return ref_x(z, load, stiffness, clearance, "ball") - ref_x(
        z, load, stiffness, clearance, "half"
    )


def test_nine_balls_have_six_compensating_clearances_three_under_preload():
    roots = comp.compensating_clearances(9, 1000.0, 1.0e5, lower=-0.03, upper=0.5)
    assert len(roots) == 6
    assert sum(g < 0 for g in roots) == 3
    assert roots == sorted(roots)
    assert comp.compensating_clearances(9, 1000.0, 1.0e5) == pytest.approx(roots, rel=1e-9)


@pytest.mark.parametrize(
    "z,load,stiffness", [(9, 1000.0, 1.0e5), (12, 250.0, 3.0e5), (7, 1.0, 1.0)]
)
def test_roots_solved_back_against_reference(z, load, stiffness):
    s = (load / stiffness) ** (2 / 3)
    roots = comp.compensating_clearances(z, load, stiffness)
    assert roots
    for g in roots:
        # the exact positions coincide at the root and the difference changes sign across it
        assert abs(ref_difference(z, load, stiffness, g)) < 1e-10 * s
        h = 1e-6 * s
        left = ref_difference(z, load, stiffness, g - h)
        right = ref_difference(z, load, stiffness, g + h)
        assert left * right < 0


def test_close_pair_of_roots_z33():
    """Two roots 0.018 µm apart under preload (z = 33, 3.28 N, K = 4490 N/mm^1.5) that a scan of
    the difference at fixed steps (1/400 in asinh(e/s), 0.04 µm here) stepped over: both are
    listed and each is the mpmath root of the exact x(0) - x(180/z) in its own bracket."""
    z, load, stiffness = 33, 3.28, 4490.0
    roots = comp.compensating_clearances(z, load, stiffness)
    close = [g for g in roots if -1.96e-3 < g < -1.93e-3]
    assert [round(g * 1e3, 5) for g in close] == [-1.95644, -1.93865]
    half = 5e-6  # [mm] each bracket holds one root: the two are 1.78e-5 mm apart
    for g in close:
        left = ref_difference(z, load, stiffness, g - half)
        right = ref_difference(z, load, stiffness, g + half)
        assert left * right < 0
        exact = mp.findroot(
            lambda c: ref_difference(z, load, stiffness, c),
            (mp.mpf(g) - half, mp.mpf(g) + half),
            solver="anderson",
        )
        assert abs(float(exact) - g) < 1e-15
    assert len(roots) == 30


def ref_balance(z: int, m, t) -> mp.mpf:
    """h(t) of the compliance module at 30 digits."""
    m, t = mp.mpf(m), mp.mpf(t)
    total = mp.mpf(0)
    for j in range(z):
        for cos, sign in ((mp.cos(2 * mp.pi * j / z), 1), (mp.cos(mp.pi * (2 * j + 1) / z), -1)):
            total += sign * max(cos - t, 0) ** m * cos
    return total


@pytest.mark.parametrize("z,m", [(3, 1.5), (4, 1.5), (5, 10 / 9), (6, 2.5), (7, 1.5), (9, 2.0)])
def test_balance_difference_and_its_sign_under_full_preload(z, m):
    """h(t) against mpmath, and below t = -1 (every ball loaded) the sign the binomial series
    predicts (0: the difference vanishes identically for an integer m < z - 1)."""
    for t in (-0.9, -0.3, 0.2, 0.8):
        assert comp.balance_difference(t, z, m) == pytest.approx(
            float(ref_balance(z, m, t)), abs=1e-14
        )
    sign = comp._preload_sign(z, m)
    for t in (-1.0, -1.5, -4.0, -30.0):
        ref = ref_balance(z, m, t)
        assert (abs(ref) < mp.mpf(10) ** -25) if sign == 0 else (mp.sign(ref) == sign)


def test_root_condition_is_the_balance_difference():
    """At a root t of h the exact ring displacement is the same at both cage angles, with the
    clearance G_r = 2 t (F/(K g_0(t)))^(1/m) the function returns."""
    z, load, stiffness = 12, 250.0, 3.0e5
    for g in comp.compensating_clearances(z, load, stiffness):
        x_ball = ref_x(z, load, stiffness, g, "ball")
        t = mp.mpf(g) / 2 / x_ball
        assert abs(ref_balance(z, 1.5, t)) < 1e-12
        assert abs(x_ball - ref_x(z, load, stiffness, g, "half")) < 1e-14


@pytest.mark.parametrize("z,m", [(8, 1.0), (9, 2.0), (10, 1.5), (17, 10 / 9), (24, 2.5), (41, 1.5)])
def test_every_sign_change_of_a_fine_scan_is_bracketed(z, m):
    """Each sign change of h on a 100001-point scan of -1 <= t <= cos(π/z) (points within the
    rounding margin carry no sign) lies in one bracket, and each bracket holds one."""
    brackets = comp._sign_brackets(z, m)
    t = np.linspace(-1.0, math.cos(math.pi / z), 100_001)
    signs = comp._signs(t, z, m)
    keep = signs != 0
    ts, ss = t[keep], signs[keep]
    changes = [(ts[i], ts[i + 1]) for i in np.nonzero(ss[:-1] != ss[1:])[0]]
    first = comp._preload_sign(z, m)
    if first and ss[0] != first:
        changes.insert(0, (-1.0, ts[0]))
    assert len(changes) == len(brackets)
    for (lo, hi), (a, b) in zip(changes, brackets, strict=True):
        assert a <= hi and lo <= b


def test_roots_in_a_range():
    every = comp.compensating_clearances(9, 1000.0, 1.0e5)
    inside = comp.compensating_clearances(9, 1000.0, 1.0e5, lower=0.0, upper=0.1)
    assert inside == [g for g in every if 0.0 <= g <= 0.1]
    assert len(inside) == 2


def test_no_root_with_three_balls_and_roller_exponent():
    assert comp.compensating_clearances(3, 1000.0, 1.0e5) == []
    roots = comp.compensating_clearances(9, 1000.0, 1.0e5, exponent=10 / 9)
    assert all(abs(comp.position_difference(9, 1000.0, 1.0e5, g, 10 / 9)) < 1e-12 for g in roots)


def test_paper_groups_against_reference():
    z, pz = 9, 0.5
    g = co.paper_groups(z, pz * z, 1.0, 2.0)
    x0 = ref_x(z, pz * z, 1.0, 2, "ball")
    xh = ref_x(z, pz * z, 1.0, 2, "half")
    assert g["alpha_ball"] == pytest.approx(float(x0 - 1), rel=1e-11)
    assert g["alpha_half"] == pytest.approx(float(xh * mp.cos(mp.pi / z) - 1), rel=1e-11)
    assert g["pbar_z"] == pytest.approx(pz, rel=1e-14)


def test_fit_rows_and_where_fit_7_holds():
    rows = co.fit_rows()
    assert len(rows) == len(co.FIT_BALLS) * len(co.FIT_PBAR_Z)
    inside = [r for r in rows if 0.1 <= r["pbar_z"] <= 3.0]
    assert max(abs(r["alpha_ball_error"]) for r in inside) < 5.0
    assert max(abs(r["alpha_ball_error"]) for r in rows if r["pbar_z"] == 100.0) > 20.0
    for r in rows:
        assert r["alpha_ball_fit"] == pytest.approx(2.855 * r["pbar_z"] ** 0.6)


def test_compliance_rows():
    rows = co.compliance_rows()
    assert [r["verdict"] for r in rows] == ["differs"] * len(rows)
    by = {r["cell"]: r for r in rows}
    assert by["eq. (8) against eq. (7): 0.076 should be 2.855 - 2.773"][
        "computed"
    ] == pytest.approx(0.082)
    nine = by["eq. (9), coefficient 0.152 (z = 9, F = 1000 N, K = 1e5 N/mm^1.5)"]
    assert nine["computed"] == pytest.approx(
        math.sin(2 * math.pi / 9) / (1000 / (9e5 * (0.010647795317734743 / 2) ** 1.5)) ** 0.6,
        rel=1e-8,
    )
    assert np.isfinite([r["computed"] for r in rows]).all()
