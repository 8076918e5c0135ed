"""The crane paper (2009): bearing radial stiffness, exact (against mpmath) and by the paper's procedure."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from bearingload.contact.hertz import roller_stiffness
from bearingload.errors import InputError
from bearingload.papers import crane_stiffness as st

mp.mp.dps = 30


def ref_row(z, load, k, m, rows, alpha_deg):
    """Zero clearance, element under the load: x, tangent and secant [mm, N/mm], 30 digits."""
    a = mp.radians(alpha_deg)
    kr = mp.mpf(k) * mp.cos(a) ** (mp.mpf(m) + 1)
    phis = [2 * mp.pi * i / z for i in range(z)]
    s = sum(max(mp.cos(p), 0) ** (mp.mpf(m) + 1) for p in phis)
    # row force kr x^m s = F/i  (every element with cos > 0 is loaded at zero clearance)
    x = (mp.mpf(load) / rows / (kr * s)) ** (1 / mp.mpf(m))
    tangent = rows * mp.mpf(m) * kr * x ** (mp.mpf(m) - 1) * s
    return x, tangent, mp.mpf(load) / x


@pytest.mark.parametrize(
    "z,load,k,m,rows,alpha",
    [
        (8, 2942.0, 46091.0, 1.5, 1, 0.0),
        (9, 5000.0, 3e5, 10 / 9, 2, 15.0),
        (13, 1.0, 1.0, 1.5, 2, 40.0),
    ],
)
def test_radial_stiffness_against_reference(z, load, k, m, rows, alpha):
    r = st.radial_stiffness(z, load, k, 0.0, 0.0, m, rows, alpha)
    x, tangent, secant = ref_row(z, load, k, m, rows, alpha)
    assert r.displacement == pytest.approx(float(x), rel=1e-12)
    assert r.tangent == pytest.approx(float(tangent), rel=1e-10)
    assert r.secant == pytest.approx(float(secant), rel=1e-12)


def test_tangent_against_finite_difference_and_vectorised():
    loads = np.array([500.0, 1000.0, 2000.0])
    r = st.radial_stiffness(9, loads, 1e5, 0.02, 7.0, 1.5, 2, 10.0)
    h = 1e-4
    up = st.radial_stiffness(9, loads * (1 + h), 1e5, 0.02, 7.0, 1.5, 2, 10.0)
    dn = st.radial_stiffness(9, loads * (1 - h), 1e5, 0.02, 7.0, 1.5, 2, 10.0)
    fd = 2 * h * loads / (up.displacement - dn.displacement)
    # the cage is off-symmetric, so dF/dx at fixed F_y = 0 is the Schur complement (engine's)
    np.testing.assert_allclose(r.tangent, fd, rtol=1e-6)
    assert r.tangent.shape == (3,)


def test_crane2009_procedure_by_hand():
    z, load, k, m = 8, 2942.0, 46091.0, 1.5
    res = st.crane2009_stiffness(z, load, k, m, rows=2, contact_angle=20.0)
    a = math.radians(20.0)
    q0 = 5 * load / (2 * z * math.cos(a))
    g = 2 * math.pi / z
    loads = [q0 * math.cos(j * g) ** m for j in (0, 1)]  # 0° and 45° (90° carries nothing)
    c = [q / (q / k) ** (1 / m) for q in loads]
    assert res.q0 == pytest.approx(q0)
    np.testing.assert_allclose(res.loads, loads)
    assert res.stiffness == pytest.approx(2 * math.cos(a) * (c[0] + 2 * c[1] * math.cos(g)))


def test_rollers_from_geometry():
    assert st.roller_element_stiffness(10.0, 12.0) == pytest.approx(roller_stiffness(12.0))
    with pytest.raises(InputError, match="roller_diameter"):
        st.roller_element_stiffness(0.0, 12.0)
    with pytest.raises(InputError, match="contact_angle"):
        st.radial_stiffness(8, 1.0, 1.0, contact_angle=90.0)


def test_comparison_rows_and_ratios():
    rows = st.comparison_rows()
    assert len(rows) == 8
    balls0 = [r for r in rows if r["case"].startswith("306,")]
    for r in balls0:  # tangent/secant = m at zero clearance; (21) between them for α = 0 balls
        assert r["tangent"] / r["secant"] == pytest.approx(1.5, rel=1e-9)
        assert r["secant"] < r["c_paper"] < r["tangent"]
    rollers = [r for r in rows if r["case"].startswith("rollers")]
    assert all(r["c_paper"] > r["tangent"] for r in rollers)


def test_crane2009_rows():
    rows = st.crane2009_rows()
    five = [r for r in rows if "factor 5" in r["cell"]]
    assert all(r["verdict"] == "differs" for r in five)
    assert five[2]["computed"] == pytest.approx(4.37, abs=0.005)  # 1/J_r(0.5), many balls
    assert five[-1]["computed"] == pytest.approx(4.08, abs=0.01)  # line contact
    assert rows[-1]["verdict"] == "agrees within printed rounding"
