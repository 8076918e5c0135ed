"""Angular contact at light loads: every load above the stated least load converges.

Before the continuation in the load (:func:`bearingload.models.combined._light_start`) a thrust
of a few thousandths of the radial load, on a ring free to tilt, ended in a ConvergenceError
(relative residual 70.4 after 2000 steps) once the groove-centre distance A was some thousands
of one-ball approaches (F/K)^(2/3) or more: the reproduction below, 28 of a 504-case scan of a
9-ball ring (docs/angular_contact.md). Each answer is checked by a plain computation of its own:
the sums of the returned ball loads along the returned angles (math.fsum), and each ball's load
recomputed from the returned ring position by the angular-contact kinematics and the Hertz
stiffness at its angle.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingload.errors import InputError
from bearingload.models.combined import GEOMETRY_RATIO_MAX, ball_stiffness_at, solve_combined

RING = {"ball_diameter": 7.938, "pitch_diameter": 38.5}


def _plain_balance(r, fr: float, fa: float, moment: float | None) -> None:
    """F_r, F_a (and the moment where one is applied; 0 under a free tilt) from the returned
    ball loads and angles, summed exactly: within 1e-12 of the applied value beyond 4 eps of the
    sum of the terms' magnitudes (the rounding of the terms themselves)."""
    q = np.asarray(r.ball_loads, dtype=float)
    al, ph = np.radians(r.contact_angles), np.radians(r.ball_angles)
    arm = float(r.tilt_radius)
    sums = [
        (q * np.cos(al) * np.cos(ph), fr),
        (q * np.cos(al) * np.sin(ph), 0.0),
        (q * np.sin(al), fa),
    ]
    if moment is not None:
        sums.append((arm * q * np.sin(al) * np.cos(ph), moment))
    for terms, wanted in sums:
        size = float(np.abs(terms).sum())
        err = abs(math.fsum(terms.tolist()) - wanted) - 4.4e-16 * size
        assert err <= 1e-12 * max(abs(wanted), 64 * 2.2e-16 / 1e-12 * size, 1e-6 * max(fr, fa))


def _plain_loads(r, z: int, alpha0: float, dw: float, dm: float) -> None:
    """Every ball's load from the returned x, y, axial, tilts: ``rho = A cos a0 + x cos phi + y
    sin phi``, ``u = A sin a0 + axial + R (tilt cos phi + tilt_cross sin phi)``, ``delta =
    |(max(rho, 0), max(u, 0))| - A``, ``Q = K(alpha) delta^1.5`` (positions of 1e6 approaches
    in doubles: the loads to 1e-6 of the largest)."""
    big_a = 0.05 * dw
    a0 = math.radians(alpha0)
    phi = np.radians(r.ball_angles)
    tilt, cross = math.radians(float(r.tilt)), math.radians(float(r.tilt_cross))
    rho = big_a * math.cos(a0) + float(r.x) * np.cos(phi) + float(r.y) * np.sin(phi)
    u = big_a * math.sin(a0) + float(r.axial)
    u = u + float(r.tilt_radius) * (tilt * np.cos(phi) + cross * np.sin(phi))
    rp, up = np.maximum(rho, 0.0), np.maximum(u, 0.0)
    delta = np.hypot(rp, up) - big_a
    angle = np.degrees(np.arctan2(up, rp))
    k = ball_stiffness_at(angle, dw, dm, 0.52, 0.53)
    q = k * np.maximum(delta, 0.0) ** 1.5
    q_max = float(np.max(r.ball_loads))
    np.testing.assert_allclose(r.ball_loads, q, rtol=0, atol=1e-6 * q_max)
    loaded = np.asarray(r.ball_loads) > 1e-3 * q_max
    np.testing.assert_allclose(np.asarray(r.contact_angles)[loaded], angle[loaded], atol=1e-6)


def test_the_reported_light_case_converges():
    """9 balls at 25°, F_r = 2.93e-6 N, F_a/F_r = 0.004 (A/(F/K)^(2/3) = 8.2e6, below the
    stated 2e7): was 'did not converge after 2016 iterations (relative residual 70.4)'. The
    ball on the load line near 0°, the two far ones at 35° holding the tilt."""
    r = solve_combined(9, 2.92709e-6, 1.15831e-8, contact_angle=25, **RING)
    _plain_balance(r, 2.92709e-6, 1.15831e-8, 0.0)
    _plain_loads(r, 9, 25.0, 7.938, 38.5)
    angles = np.asarray(r.contact_angles)
    assert angles[0] < 1.0 and angles[4] == pytest.approx(35.09, abs=0.01)
    assert int(r.loaded_balls) == 3
    # nearly the same ring position in mm as at 1000 times the load (the balls as good as rigid)
    heavy = solve_combined(9, 2.92709e-3, 1.15831e-5, contact_angle=25, **RING)
    assert float(r.tilt) == pytest.approx(float(heavy.tilt), rel=1e-4)


@pytest.mark.parametrize("alpha", [15.0, 25.0, 40.0])
def test_a_grid_of_light_loads_converges(alpha):
    """9 balls, F_r from 1e-6 to 0.1 N, F_a/F_r from 1e-3 to 1e-2 (before: 4, 10 and 9 of the
    25 cases at 15°, 25° and 40° ended in a ConvergenceError)."""
    for fr in np.logspace(-6, -1, 5):
        for ratio in (1e-3, 2e-3, 3e-3, 5e-3, 1e-2):
            fa = float(fr * ratio)
            r = solve_combined(9, float(fr), fa, contact_angle=alpha, **RING)
            _plain_balance(r, float(fr), fa, 0.0)
            _plain_loads(r, 9, alpha, 7.938, 38.5)


@pytest.mark.parametrize(
    ("z", "alpha", "extra"),
    [
        (3, 10.0, {}),
        (24, 13.25, {"cage_angle": 7.5}),
        (37, 27.4, {}),
        (28, 22.8, {"cage_angle": 6.43, "moment": 2e-6}),
        (12, 45.0, {"misalignment": 0.05}),
        (31, 30.9, {"cage_angle": 49.6, "misalignment": -0.01}),
    ],
)
def test_other_rings_moments_and_misalignments_at_light_loads(z, alpha, extra):
    """Ball counts 3 to 37, 10° to 45°, a moment or an imposed tilt, the cage off the line, from
    F_r = 1e-6 N up: solved and balanced (the balls 0.8 of the largest that fit; before, the
    first three rings ended in a ConvergenceError at one of these loads or more)."""
    dm = 50.0
    dw = 0.8 * min(dm * math.sin(math.pi / z), 0.3 * dm)
    for fr in (1e-6, 1e-4, 1e-2):
        for ratio in (1e-3, 4e-3):
            kw = dict(extra)
            if "moment" in kw:
                kw["moment"] = kw["moment"] * fr / 1e-4
            fa = fr * ratio
            try:
                r = solve_combined(z, fr, fa, contact_angle=alpha, ball_diameter=dw,
                                   pitch_diameter=dm, **kw)  # fmt: skip
            except InputError as exc:  # below the least load: that load must then solve
                assert "too small for the combined solver" in str(exc)
                continue
            moment = None if "misalignment" in kw else kw.get("moment", 0.0)
            _plain_balance(r, fr, fa, moment)
            _plain_loads(r, z, alpha, dw, dm)


def test_the_stated_least_load_solves():
    """Below A/(F/K)^(2/3) = GEOMETRY_RATIO_MAX the refusal names the least load; that load (all
    loads scaled together, F_a/F_r = 0.004) solves."""
    with pytest.raises(InputError, match="it takes at least") as info:
        solve_combined(9, 1e-7, 4e-10, contact_angle=25, **RING)
    least = float(str(info.value).split("at least ")[1].split(" N")[0])
    k0 = float(ball_stiffness_at(0.0, **RING, f_i=0.52, f_o=0.53))
    assert least == pytest.approx(k0 * (0.05 * 7.938 / GEOMETRY_RATIO_MAX) ** 1.5, rel=0.05)
    r = solve_combined(9, least, 0.004 * least, contact_angle=25, **RING)
    _plain_balance(r, least, 0.004 * least, 0.0)
    _plain_loads(r, 9, 25.0, 7.938, 38.5)


def test_overlapping_balls_are_refused_by_the_library():
    """As the command line and resolve_bearing do: z balls fit only if D_w <= d_m sin(180°/z)
    (validate.ball_spacing); 20 balls of 11.5 mm on 43.5 mm overlap (at most 6.80489 mm)."""
    with pytest.raises(InputError, match=r"^ball_diameter: 20 balls of 11\.5 mm overlap") as info:
        solve_combined(20, 1000.0, ball_diameter=11.5, pitch_diameter=43.5)
    assert "must be at most 6.80489 mm (or fewer balls)" in str(info.value)
    with pytest.raises(InputError, match="^ball_diameter: 16 balls"):
        solve_combined(16, 1000.0, 100.0, contact_angle=25, **RING)
    r = solve_combined(15, 1000.0, 100.0, contact_angle=25, **RING)  # 15 fit: 8.005 mm apart
    assert float(r.q_max) > 0


def test_a_light_case_in_a_batch_is_the_case_alone():
    """The heavier stages of the continuation are solved per case: a light case gives the same
    bits among heavier ones as alone."""
    fr = np.array([2.92709e-6, 1e-3, 5.0, 1e-5, 100.0])
    fa = fr * np.array([0.004, 0.003, 0.5, 0.01, 1e-3])
    many = solve_combined(9, fr, fa, contact_angle=25, **RING)
    for i in range(fr.size):
        one = solve_combined(9, float(fr[i]), float(fa[i]), contact_angle=25, **RING)
        assert np.array_equal(many.ball_loads[i], one.ball_loads)
        assert float(many.x[i]) == float(one.x) and float(many.tilt[i]) == float(one.tilt)
