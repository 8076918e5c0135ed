"""The cage sweep: symmetries, periodicity, stiffness against finite differences of solved
displacements, and an independent mpmath reference of the 2-D equilibrium at any cage angle."""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest

from bearingload.errors import InputError
from bearingload.models.equilibrium import solve
from bearingload.studies.sweep import sweep

mp.mp.dps = 40


# ---------------------------------------------------------------------------------------------
# Independent reference: the 2-D ring equilibrium in mpmath (Kurochkin 1973, eqs. 1.1-1.5),
# written from the equations: sum Q_i cos phi_i = F_r, sum Q_i sin phi_i = 0, Q = K (delta)_+^m.
# ---------------------------------------------------------------------------------------------
def mp_ball_forces(z, k, e, m, phi1, x, y):
    fx = fy = mp.mpf(0)
    loads = []
    for i in range(z):
        phi = phi1 + 2 * mp.pi * i / z
        d = x * mp.cos(phi) + y * mp.sin(phi) - e
        q = k * d**m if d > 0 else mp.mpf(0)
        loads.append(q)
        fx += q * mp.cos(phi)
        fy += q * mp.sin(phi)
    return fx, fy, loads


def mp_equilibrium(z, load, k, g, m, phi1_deg):
    """(x, y, loads) by bisection on x with y = 0, then mpmath's 2-D Newton from there."""
    f, k, e, m = mp.mpf(load), mp.mpf(k), mp.mpf(g) / 2, mp.mpf(m)
    phi1 = mp.radians(mp.mpf(phi1_deg))
    lo, hi = -abs(e) * 10, abs(e) * 10 + 10
    for _ in range(300):
        mid = (lo + hi) / 2
        if mp_ball_forces(z, k, e, m, phi1, mid, 0)[0] < f:
            lo = mid
        else:
            hi = mid

    def residual(a, b):
        fx, fy, _ = mp_ball_forces(z, k, e, m, phi1, a, b)
        return [fx - f, fy]

    x, y = mp.findroot(
        residual,
        ((lo + hi) / 2, mp.mpf(0)),
        tol=mp.mpf(10) ** -60,
        maxsteps=200,
    )
    fx, fy, loads = mp_ball_forces(z, k, e, m, phi1, x, y)
    assert abs(fx - f) < mp.mpf(10) ** -25 * f and abs(fy) < mp.mpf(10) ** -25 * f
    return x, y, loads


@pytest.mark.parametrize(
    "z, load, k, g, m",
    [(9, 1000.0, 1e5, 0.01, 1.5), (8, 2941.995, 46091.0, 0.02, 1.5), (12, 5000.0, 3.8e5, -0.01, 1.5),
     (7, 24.5166, 1.423e5, 0.01, 1.5), (15, 800.0, 6e5, 0.004, 10 / 9)],
)  # fmt: skip
def test_sweep_against_mpmath(z, load, k, g, m):
    s = sweep(z, load, k, g, m, steps=7)
    for i in (1, 2, 4, 5):  # away from the symmetric positions, where y is unknown too
        x, y, loads = mp_equilibrium(z, load, k, g, m, s.cage_angle[i])
        scale = abs(float(x)) + (load / k) ** (1 / m)
        assert abs(s.x[i] - float(x)) <= 1e-12 * scale
        assert abs(s.y[i] - float(y)) <= 1e-12 * scale
        q = [float(v) for v in loads]
        assert s.q_max[i] == pytest.approx(max(q), rel=1e-10)
        assert s.q_max_ball[i] == 1 + int(np.argmax(q))
        assert s.loaded_balls[i] == sum(v > 0 for v in q)


def test_cage_positions_cover_one_pitch_both_ends():
    s = sweep(9, 1000.0, 1e5, 0.01, steps=9)
    np.testing.assert_array_equal(s.cage_angle, np.linspace(0.0, 40.0, 9))
    assert s.ripple_order == 9
    # both ends are the same position: a ball under the load (ball 1 at the start, ball z at the end)
    assert s.x[0] == pytest.approx(s.x[-1], rel=1e-15) and s.y[0] == 0.0 == s.y[-1]
    assert s.q_max_ball[0] == 1 and s.q_max_ball[-1] == 9
    assert s.q_max_ball[4] == 1  # half pitch: balls 1 and 9 tie, the lower is named


@pytest.mark.parametrize("z, g", [(9, 0.01), (8, 0.0), (12, -0.01), (5, 0.03), (30, 0.002)])
def test_symmetries_and_periodicity(z, g):
    """x(phi1) = x(-phi1), y(phi1) = -y(-phi1), and a period of one pitch 360/z."""
    load, k = 1500.0, 2e5
    s = sweep(z, load, k, g, steps=21)
    mirror = solve(z, load, k, g, -s.cage_angle)
    shifted = solve(z, load, k, g, s.cage_angle + 360.0 / z * 3)
    scale = np.abs(s.x).max()
    np.testing.assert_allclose(mirror.x, s.x, rtol=0, atol=1e-13 * scale)
    np.testing.assert_allclose(mirror.y, -s.y, rtol=0, atol=1e-13 * scale)
    np.testing.assert_allclose(shifted.x, s.x, rtol=0, atol=1e-13 * scale)
    np.testing.assert_allclose(shifted.y, s.y, rtol=0, atol=1e-13 * scale)
    # inside the sweep: phi1 -> pitch - phi1 is the mirror image
    np.testing.assert_allclose(s.x[::-1], s.x, rtol=0, atol=1e-13 * scale)
    np.testing.assert_allclose(s.y[::-1], -s.y, rtol=0, atol=1e-13 * scale)
    np.testing.assert_allclose(s.q_max[::-1], s.q_max, rtol=1e-12)


@pytest.mark.parametrize("z, g, i", [(9, 0.01, 3), (9, 0.01, 0), (12, -0.01, 2), (7, 0.0, 5)])
def test_stiffness_matrix_against_finite_differences_of_solved_displacements(z, g, i):
    """Compliance columns from solves: d(x, y)/dF_r by changing the load, d(x, y)/dF_y by turning
    the load by a small angle beta (the same as turning the cage by -beta), rotated back."""
    load, k = 2000.0, 1.5e5
    s = sweep(z, load, k, g, steps=7)
    phi = s.cage_angle[i]
    h = 1e-5
    up, down = solve(z, load * (1 + h), k, g, phi), solve(z, load * (1 - h), k, g, phi)
    col_x = [(up.x - down.x) / (2 * h * load), (up.y - down.y) / (2 * h * load)]
    beta = 1e-5  # rad
    cols = []
    for b in (beta, -beta):
        r = solve(z, load, k, g, phi - np.rad2deg(b))
        cols.append([r.x * np.cos(b) - r.y * np.sin(b), r.x * np.sin(b) + r.y * np.cos(b)])
    col_y = [(cols[0][j] - cols[1][j]) / (2 * beta * load) for j in range(2)]
    compliance = np.array([[col_x[0], col_y[0]], [col_x[1], col_y[1]]], dtype=float)
    scale = np.trace(s.stiffness_matrix[i])
    np.testing.assert_allclose(
        np.linalg.inv(compliance), s.stiffness_matrix[i], rtol=1e-5, atol=1e-6 * scale
    )
    kk = s.stiffness_matrix[i]
    assert s.stiffness_radial[i] == pytest.approx(kk[0, 0] - kk[0, 1] ** 2 / kk[1, 1], rel=1e-12)


def test_spread_over_one_period():
    s = sweep(9, 1000.0, 1e5, 0.01, steps=9)
    sp = s.spread("stiffness_radial")
    assert sp.min == s.stiffness_radial.min() and sp.max == s.stiffness_radial.max()
    assert sp.mean == pytest.approx(s.stiffness_radial[:-1].mean(), rel=1e-15)
    assert sp.peak_to_peak == sp.max - sp.min > 0
    # the mean over one period does not depend on the sampling once it resolves the ripple
    fine = sweep(9, 1000.0, 1e5, 0.01, steps=721).spread("x")
    coarse = sweep(9, 1000.0, 1e5, 0.01, steps=37).spread("x")
    assert coarse.mean == pytest.approx(fine.mean, rel=1e-6)
    with pytest.raises(InputError, match="name"):
        s.spread("z")


def test_one_vectorised_solve(monkeypatch):
    import bearingload.studies.sweep as module

    calls = []
    real = module.solve

    def counting(*args, **kwargs):
        calls.append(np.size(args[4]))
        return real(*args, **kwargs)

    monkeypatch.setattr(module, "solve", counting)
    s = sweep(9, 1000.0, 1e5, 0.01, steps=1000)
    assert calls == [1000] and s.x.shape == (1000,)


def test_huge_clearance_and_tiny_load_name_the_right_ball():
    s = sweep(9, 1e-6, 1e5, 10.0, steps=9)
    for i in range(9):
        q = solve(9, 1e-6, 1e5, 10.0, s.cage_angle[i]).ball_loads
        assert s.q_max_ball[i] == 1 + int(np.argmax(q >= q.max() * (1 - 1e-9)))
    assert np.all(np.isfinite(s.stiffness_radial))


def test_errors():
    with pytest.raises(InputError, match="balls"):
        sweep(2, 1000.0, 1e5)
    with pytest.raises(InputError, match="steps"):
        sweep(9, 1000.0, 1e5, steps=1)
    with pytest.raises(InputError, match="steps"):
        sweep(9, 1000.0, 1e5, steps=2.5)
    with pytest.raises(InputError, match="load"):
        sweep(9, [1000.0, 2000.0], 1e5)
    with pytest.raises(InputError, match="clearance"):
        sweep(9, 1000.0, 1e5, float("nan"))


def test_compensating_clearances_solved_back():
    """The summary lists every G_r with x(0) = x(180/z) (z = 9, 1 kN, 1e5 N/mm^1.5: six, three of
    them preload); swept at each, the ring sits at the same x with a ball under the load and with
    the load between two balls, and x(0) - x(180/z) changes sign across it."""
    z, load, k = 9, 1000.0, 1e5
    roots = sweep(z, load, k, 0.01, steps=3).compensating_clearance
    assert len(roots) == 6 and sum(g < 0 for g in roots) == 3
    scale = (load / k) ** (1 / 1.5)
    for g in roots:
        s = sweep(z, load, k, g, steps=3)  # cage angles 0, 180/z, 360/z
        assert abs(s.x[0] - s.x[1]) <= 1e-9 * (scale + abs(g))
        below, above = (sweep(z, load, k, g * f, steps=3) for f in (1 - 1e-4, 1 + 1e-4))
        assert (below.x[0] - below.x[1]) * (above.x[0] - above.x[1]) < 0


@pytest.mark.parametrize("g", [-0.02, -0.005, 0.0, 0.0125])
def test_life_sees_the_engines_ball_loads_also_under_preload(g):
    """The ball loads handed to ``life`` are the engine's at each cage position: their largest
    is Q_max and they balance the load (preload included: the balls beyond the load zone carry
    too), as solve's LoadDistribution.ball_loads gives them."""
    z, f, k = 9, 1000.0, 274868.876
    seen = []

    def life(q):
        seen.append(q)
        return q.max(axis=1)

    s = sweep(z, f, k, g, steps=5, life=life)
    (q,) = seen
    assert np.allclose(s.reference_rating_life, s.q_max, rtol=1e-12)
    phi = np.deg2rad(s.cage_angle)[:, None] + 2.0 * np.pi * np.arange(z) / z
    assert np.allclose((q * np.cos(phi)).sum(axis=1), f, rtol=1e-9)
    assert np.allclose((q * np.sin(phi)).sum(axis=1), 0.0, atol=1e-9 * f)
    for i, angle in enumerate(s.cage_angle):
        one = solve(z, f, k, g, float(angle), 1.5)
        assert np.allclose(q[i], one.ball_loads, rtol=1e-12, atol=1e-12 * f)


def test_the_mean_of_huge_values_does_not_overflow():
    """L10rh at a speed of 1e-300 rpm is ~4e307 h at every cage position: their sum overflows,
    the mean must not (it gave numpy's 'overflow encountered in reduce', an infinite mean and,
    in JSON, an internal error)."""
    import warnings

    from bearingload.studies.sweep import spread_of

    v = np.array([3.9e307, 3.7e307, 3.8e307, 3.9e307] * 10)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        s = spread_of(v)
    assert s.mean == pytest.approx(np.mean(v[:-1] / 1e307) * 1e307, rel=1e-15)
    assert (s.min, s.max) == (3.7e307, 3.9e307)
    tiny = spread_of(np.array([2e-320, 3e-320, 2e-320]))  # subnormal: scaling must not lose them
    assert tiny.mean == pytest.approx(2.5e-320, rel=1e-3)


def test_both_sweeps_convert_lives_to_hours_by_one_function(monkeypatch):
    """The radial and the combined cage sweep give their lives in hours through the one
    ``hours_at`` (it was written twice): L 10^6/(60 n), None without a speed or a life, and
    the speed's refusal of ``life_hours`` where the hours overflow."""
    import dataclasses

    from bearingload.bearings.resolve import resolve_bearing
    from bearingload.studies import combined_sweep as combined_module
    from bearingload.studies import sweep as sweep_module
    from bearingload.studies.combined_sweep import combined_sweep

    life = np.array([60.0, 120.0])
    assert np.allclose(sweep_module.hours_at(life, 1000.0), [1000.0, 2000.0], rtol=1e-15)
    assert sweep_module.hours_at(None, 1000.0) is None
    assert sweep_module.hours_at(life, None) is None
    with pytest.raises(InputError, match="speed"):
        sweep_module.hours_at(np.array([1e300]), 1e-300)
    radial = dataclasses.replace(sweep(9, 1000.0, 274868.876, steps=3), speed=3000.0)
    combined = dataclasses.replace(
        combined_sweep(resolve_bearing("6205"), 1000.0, 200.0, steps=3), speed=3000.0
    )
    calls = []
    monkeypatch.setattr(combined_module, "hours_at", lambda lf, n: calls.append((lf, n)) or 1.0)
    monkeypatch.setattr(sweep_module, "hours_at", lambda lf, n: calls.append((lf, n)) or 2.0)
    assert (radial.hours(life), combined.hours(life)) == (2.0, 1.0)
    assert [n for _, n in calls] == [3000.0, 3000.0]
