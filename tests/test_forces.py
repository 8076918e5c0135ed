"""ring_forces, the forward problem: against direct sums in mpmath, against solve, against finite
differences, at the edges of contact, under preload, with 1 and 1000 balls."""

from __future__ import annotations

import warnings

import mpmath as mp
import numpy as np
import pytest

from bearingload import ring_forces
from bearingload.errors import InputError
from bearingload.models.equilibrium import solve

mp.mp.dps = 40


def mp_direct(z, x, y, k, g, phi1_deg, m):
    """Direct sums over the balls at 40 digits (Kurochkin 1973, eqs. 1.1-1.5), from the equations.

    Returns (F_x, F_y, [[K_xx, K_xy], [K_xy, K_yy]], [Q_1 .. Q_z]).
    """
    x, y, k, e, m = (mp.mpf(v) for v in (x, y, k, g / 2, m))
    fx = fy = kxx = kxy = kyy = mp.mpf(0)
    loads = []
    for i in range(z):
        phi = mp.radians(mp.mpf(phi1_deg)) + 2 * mp.pi * i / z
        c, s = mp.cos(phi), mp.sin(phi)
        d = x * c + y * s - e
        q = k * d**m if d > 0 else mp.mpf(0)
        dq = k * m * d ** (m - 1) if d > 0 else mp.mpf(0)
        loads.append(q)
        fx += q * c
        fy += q * s
        kxx += dq * c * c
        kxy += dq * c * s
        kyy += dq * s * s
    return fx, fy, [[kxx, kxy], [kxy, kyy]], loads


CASES = [
    # z, x [mm], y [mm], K [N/mm^m], G_r [mm], cage angle [°], m
    (8, 0.060, 0.0, 46091.0, 0.020, 0.0, 1.5),
    (9, 0.012, 0.003, 1e5, 0.01, 13.7, 1.5),
    (9, 0.012, -0.003, 1e5, 0.01, -13.7, 1.5),
    (13, 2e-4, 1e-4, 3.8e5, -0.05, 101.3, 1.5),
    (20, 0.004, 0.001, 2e6, 0.002, 7.25, 10 / 9),
    (5, 1.2e-3, 4e-4, 5e4, 0.0, 359.9, 1.0),
    (7, 3e-3, -2e-3, 4.4e5, 4e-3, 1e6 + 0.3, 2.7),
    (1, 0.02, 0.01, 1e5, 0.001, 0.0, 1.5),
    (2, 0.02, 0.01, 1e5, 0.001, 30.0, 1.5),
]


@pytest.mark.parametrize("case", CASES)
def test_against_direct_sums_in_mpmath(case):
    z, x, y, k, g, phi1, m = case
    f = ring_forces(z, x, y, k, g, phi1, m)
    fx, fy, kk, loads = mp_direct(z, x, y, k, g, phi1, m)
    scale = float(sum(loads)) + 1e-300  # force sums cancel: measure against the ball loads
    assert abs(f.force_x - float(fx)) <= 1e-13 * scale
    assert abs(f.force_y - float(fy)) <= 1e-13 * scale
    kscale = float(kk[0][0] + kk[1][1]) + 1e-300
    for i in range(2):
        for j in range(2):
            assert abs(f.stiffness_matrix[i, j] - float(kk[i][j])) <= 1e-13 * kscale
    np.testing.assert_allclose(f.ball_loads, [float(q) for q in loads], rtol=1e-13, atol=0)
    assert f.loaded_balls == sum(1 for q in loads if q > 0)


def test_scalar_in_python_numbers_out():
    f = ring_forces(9, 0.01, 0.0, 1e5)
    assert type(f.force_x) is float and type(f.force_y) is float
    assert type(f.loaded_balls) is int
    assert f.stiffness_matrix.shape == (2, 2) and f.ball_loads.shape == (9,)


def test_broadcasting_shapes_and_independence():
    x = np.linspace(0.001, 0.02, 4)[:, None]
    angles = np.array([0.0, 5.0, 20.0])
    f = ring_forces(9, x, 0.001, 1e5, np.array([0.0, 0.01, -0.01]), angles)
    assert f.force_x.shape == (4, 3) and f.stiffness_matrix.shape == (4, 3, 2, 2)
    assert f.ball_loads.shape == (4, 3, 9) and f.loaded_balls.shape == (4, 3)
    for i in range(4):
        for j in range(3):  # each case alone gives the same, bit for bit
            one = ring_forces(9, float(x[i, 0]), 0.001, 1e5, [0.0, 0.01, -0.01][j], angles[j])
            assert one.force_x == f.force_x[i, j] or abs(one.force_x / f.force_x[i, j] - 1) < 1e-15
            np.testing.assert_allclose(one.ball_loads, f.ball_loads[i, j], rtol=1e-15)


@pytest.mark.parametrize(
    "z, g, phi1, m",
    [(9, 0.01, 0.0, 1.5), (9, 0.01, 11.0, 1.5), (12, -0.02, 7.0, 1.5), (8, 0.004, 22.5, 10 / 9),
     (31, 0.0, 3.3, 1.5), (4, 0.002, 17.0, 1.5)],
)  # fmt: skip
def test_solved_displacement_gives_back_the_load(z, g, phi1, m):
    load, k = 2500.0, 2e5
    r = solve(z, load, k, g, phi1, m)
    f = ring_forces(z, r.x, r.y, k, g, phi1, m)
    # x ~ e + elastic approach: the force is as exact as x can be given in doubles
    assert abs(f.force_x - load) <= 1e-9 * load
    assert abs(f.force_y) <= 1e-9 * load
    np.testing.assert_allclose(f.stiffness_matrix, r.stiffness_matrix, rtol=1e-8, atol=1e-8 * load)
    assert f.loaded_balls == int(r.loaded_balls)
    np.testing.assert_allclose(f.ball_loads, r.ball_loads, rtol=1e-8, atol=1e-9 * load)


def test_sweep_of_solved_positions_in_one_call():
    angles = np.linspace(0.0, 40.0, 101)
    r = solve(9, 1000.0, 1e5, 0.01, angles)
    f = ring_forces(9, r.x, r.y, 1e5, 0.01, angles)
    np.testing.assert_allclose(f.force_x, 1000.0, rtol=1e-10)
    np.testing.assert_allclose(f.force_y, 0.0, atol=1e-9)


@pytest.mark.parametrize(
    "x, y, g, phi1, m",
    [(0.012, 0.004, 0.01, 8.0, 1.5), (0.001, -0.0005, -0.004, 3.0, 1.5),
     (0.02, 0.007, 0.0, 29.0, 10 / 9), (0.015, 0.0, 0.02, 0.0, 1.5)],
)  # fmt: skip
def test_stiffness_matrix_against_finite_differences(x, y, g, phi1, m):
    z, k = 9, 1e5
    f = ring_forces(z, x, y, k, g, phi1, m)
    h = 1e-7
    for j, (dx, dy) in enumerate([(h, 0.0), (0.0, h)]):
        plus = ring_forces(z, x + dx, y + dy, k, g, phi1, m)
        minus = ring_forces(z, x - dx, y - dy, k, g, phi1, m)
        col = [(plus.force_x - minus.force_x) / (2 * h), (plus.force_y - minus.force_y) / (2 * h)]
        scale = np.trace(f.stiffness_matrix)
        np.testing.assert_allclose(f.stiffness_matrix[:, j], col, rtol=1e-6, atol=1e-6 * scale)


@pytest.mark.parametrize("m", [1.0, 10 / 9, 1.5, 3.0])
def test_exact_contact_boundaries_give_no_nan_and_no_warning(m):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        # ball 1 exactly at the edge (delta = 0), balls at 90° exactly unloaded
        edge = ring_forces(4, 0.005, 0.0, 1e5, 0.01, 0.0, m)
        assert edge.force_x == 0.0 and edge.force_y == 0.0 and edge.loaded_balls == 0
        assert np.all(edge.stiffness_matrix == 0.0) and np.all(edge.ball_loads == 0.0)
        # the centred ring without clearance: every ball at delta = 0
        zero = ring_forces(np.array(8), np.zeros(3), 0.0, 1e5, 0.0, [0.0, 22.5, 10.0], m)
        assert np.all(zero.force_x == 0) and np.all(zero.stiffness_matrix == 0)
        # balls at 90°: cos snaps to 0 exactly, no stray load from cos(pi/2) = 6e-17
        side = ring_forces(4, 1.0, 0.0, 1e5, 0.0, 90.0, m)
        assert side.force_x == 1e5 and side.loaded_balls == 1
        assert not np.any(np.isnan(edge.stiffness_matrix))


def test_preload_centred_ring():
    """Centred ring under preload: every ball carries K |e|^m, no net force, isotropic stiffness
    z/2 K m |e|^(m-1) (sum of cos^2 over z >= 3 equally spaced balls is z/2)."""
    z, k, g, m = 11, 3e5, -0.004, 1.5
    f = ring_forces(z, 0.0, 0.0, k, g, 7.0, m)
    np.testing.assert_allclose(f.ball_loads, k * 0.002**1.5, rtol=1e-14)
    assert (
        abs(f.force_x) < 1e-12 * z * k * 0.002**1.5 and abs(f.force_y) < 1e-12 * z * k * 0.002**1.5
    )
    kk = z / 2 * k * m * 0.002**0.5
    np.testing.assert_allclose(f.stiffness_matrix, [[kk, 0], [0, kk]], rtol=1e-13, atol=1e-9 * kk)
    assert f.loaded_balls == z


def test_one_ball():
    f = ring_forces(1, 0.03, 0.02, 1e5, 0.02, 0.0)
    assert f.force_x == pytest.approx(1e5 * 0.02**1.5, rel=1e-14)
    assert f.force_y == 0.0  # one ball on the load line carries no transverse load
    assert f.stiffness_matrix[1, 1] == 0.0
    assert f.loaded_balls == 1


def test_thousand_balls_against_mpmath():
    z, x, y, k, g, phi1 = 1000, 0.004, 0.001, 2e5, 0.003, 0.17
    f = ring_forces(z, x, y, k, g, phi1)
    fx, fy, kk, loads = mp_direct(z, x, y, k, g, phi1, 1.5)
    assert f.force_x == pytest.approx(float(fx), rel=1e-12)
    assert f.force_y == pytest.approx(float(fy), rel=1e-12)
    np.testing.assert_allclose(f.stiffness_matrix, np.array(kk, dtype=float), rtol=1e-12)
    assert f.loaded_balls == sum(1 for q in loads if q > 0)
    r = solve(z, 1e4, k, g, phi1)
    back = ring_forces(z, r.x, r.y, k, g, phi1)
    assert back.force_x == pytest.approx(1e4, rel=1e-9) and abs(back.force_y) < 1e-9 * 1e4


def test_a_case_gives_the_same_bits_alone_or_in_a_batch():
    """A batch is a C loop over its cases: a case's forces, stiffness and ball loads are the
    same bits alone as anywhere in a batch of 12 305 (the numpy blocks of 4096 cases are gone)."""
    n = 12_305
    x = np.linspace(0.0, 0.02, n)
    angles = np.linspace(0.0, 360.0, n)
    f = ring_forces(9, x, 0.001, 1e5, 0.004, angles, exponent=np.where(x > 0.01, 1.5, 10 / 9))
    for i in [0, 4095, 4096, 8197, n - 1]:
        one = ring_forces(9, x[i], 0.001, 1e5, 0.004, angles[i], 1.5 if x[i] > 0.01 else 10 / 9)
        np.testing.assert_array_equal(f.ball_loads[i], one.ball_loads)
        np.testing.assert_array_equal(f.stiffness_matrix[i], one.stiffness_matrix)
        assert (f.force_x[i], f.force_y[i]) == (one.force_x, one.force_y)


def test_errors_name_the_parameter():
    with pytest.raises(InputError, match="balls"):
        ring_forces([8, 9], 0.01, 0.0, 1e5)
    with pytest.raises(InputError, match="balls"):
        ring_forces(0, 0.01, 0.0, 1e5)
    with pytest.raises(InputError, match="^x:"):
        ring_forces(8, float("nan"), 0.0, 1e5)
    with pytest.raises(InputError, match="^y:"):
        ring_forces(8, 0.0, float("inf"), 1e5)
    with pytest.raises(InputError, match="stiffness"):
        ring_forces(8, 0.01, 0.0, -1.0)
    with pytest.raises(InputError, match="exponent"):
        ring_forces(8, 0.01, 0.0, 1e5, exponent=0.5)
    with pytest.raises(InputError, match="overflows"):
        ring_forces(8, 1e300, 0.0, 1e5)
