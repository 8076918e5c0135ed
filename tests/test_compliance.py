"""The compliance abstract: compensating clearances and the paper's fits, against an mpmath reference."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from bearingload.studies import compliance as co

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


def test_issue_example_has_six_roots_three_under_preload():
    roots = co.compensating_clearances(9, 1000.0, 1.0e5, lower=-0.03, upper=0.5)
    assert len(roots) == 6
    assert sum(g < 0 for g in roots) == 3
    assert roots == sorted(roots)
    assert co.compensating_clearances(9, 1000.0, 1.0e5) == pytest.approx(roots, rel=1e-9)


@pytest.mark.parametrize(
    "z,load,stiffness", [(9, 1000.0, 1.0e5), (12, 250.0, 3.0e5), (7, 1.0, 1.0)]
)
def test_roots_solved_back_against_reference(z, load, stiffness):
    s = (load / stiffness) ** (2 / 3)
    roots = co.compensating_clearances(z, load, stiffness)
    assert roots
    for g in roots:
        # the exact positions coincide at the root and the difference changes sign across it
        assert abs(ref_difference(z, load, stiffness, g)) < 1e-10 * s
        h = 1e-6 * s
        left = ref_difference(z, load, stiffness, g - h)
        right = ref_difference(z, load, stiffness, g + h)
        assert left * right < 0


def test_no_root_with_three_balls_and_roller_exponent():
    assert co.compensating_clearances(3, 1000.0, 1.0e5) == []
    roots = co.compensating_clearances(9, 1000.0, 1.0e5, exponent=10 / 9)
    assert all(abs(co.position_difference(9, 1000.0, 1.0e5, g, 10 / 9)) < 1e-12 for g in roots)


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
