"""A bearing pair at speed (bearingload.models.pair_speed): every ball of both bearings against
an independent 40-digit mpmath solution of its two equations (Jones 1960; Harris & Kotzalas vol.
2, ch. 2-3, written in tests/test_high_speed.py), its groove centres placed here in mpmath from
the shaft's displacement by the pair's rigid-shaft kinematics (not from the bearing's reported
local position); the shaft's five forces summed in mpmath against the applied loads; speed 0 =
the static pair; the known effects of speed; no silent non-convergence.
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest

from bearingload.contact.hertz import ball_stiffness
from bearingload.errors import ConvergenceError, InputError
from bearingload.models import pair_speed
from bearingload.models.pair import solve_pair
from bearingload.models.pair_speed import solve_pair_high_speed
from tests.test_high_speed import _reference_ball

mp.mp.dps = 40

#: 7205B (NSK: z 12, D_w 8.7312 mm, d_m 38.5 mm, B 15 mm, 40°).
B7205 = dict(contact_angle=40.0, ball_diameter=8.7312, pitch_diameter=38.5, width=15.0,
             f_i=0.52, f_o=0.53, modulus=208000.0)  # fmt: skip
#: A 15° bearing of the same size, 14 balls of 7.938 mm.
B15 = dict(contact_angle=15.0, ball_diameter=7.938, pitch_diameter=38.5, width=15.0, f_i=0.52,
           f_o=0.53, modulus=208000.0)  # fmt: skip


def _mpmath_pair(r, z, fr, fa, geometry, kind, moment=0.0, moment_cross=0.0):
    """Every ball of both bearings against mpmath from the shaft's position; the shaft's forces
    in mpmath against the applied ones. Returns the worst ball and shaft errors."""
    dw, dm, fi, fo = (geometry[k] for k in ("ball_diameter", "pitch_diameter", "f_i", "f_o"))
    big_a = (mp.mpf(fi) + mp.mpf(fo) - 1) * mp.mpf(dw)
    a0 = mp.radians(geometry["contact_angle"])
    width = mp.mpf(geometry["width"])
    omega = mp.mpf(float(r.speed)) * mp.pi / 30
    lever = mp.mpf(float(r.bearings[0].tilt_radius))
    x, y, a = (mp.mpf(float(getattr(r, k))) for k in ("x", "y", "axial"))
    th, tc = (mp.radians(mp.mpf(float(getattr(r, k)))) for k in ("tilt", "tilt_cross"))
    first = mp.mpf(-0.5) if kind in ("DB", "DT") else mp.mpf(0.5)
    u_p = big_a * mp.sin(a0) + mp.mpf(float(r.preload_offset))
    forces = [mp.mpf(0)] * 5
    worst_ball = 0.0
    for k, b in enumerate(r.bearings):
        zk = (first if k == 0 else -first) * width
        sigma = 1 if (k == 0 or kind == "DT") else -1
        for j in range(z):
            phi = mp.radians(mp.mpf(float(b.ball_angles[j])))
            rho = big_a * mp.cos(a0) + (x - zk * th) * mp.cos(phi) + (y - zk * tc) * mp.sin(phi)
            u = sigma * (a + lever * (th * mp.cos(phi) + tc * mp.sin(phi))) + u_p
            u = max(u, mp.mpf(0))
            cos_i = max(np.cos(np.deg2rad(b.contact_angles_inner[j])), 0.05)
            cos_o = max(np.cos(np.deg2rad(b.contact_angles_outer[j])), 0.05)
            k_i = ball_stiffness(dw, dm / cos_i, fi, fo, geometry["modulus"]).inner
            k_o = ball_stiffness(dw, dm / cos_o, fi, fo, geometry["modulus"]).outer
            ref = _reference_ball(rho, u, k_i, k_o, dw, dm, fi, fo, omega,
                                  (b.approaches_outer[j], np.deg2rad(b.contact_angles_outer[j])))  # fmt: skip
            scale = float(ref["qo"])
            for ours, theirs in (
                (b.ball_loads_inner[j], ref["qi"]), (b.ball_loads_outer[j], ref["qo"]),
                (b.centrifugal_forces[j], ref["fc"]),
                (2 * b.gyroscopic_moments[j] / dw, 2 * ref["mg"] / dw),
            ):  # fmt: skip
                worst_ball = max(worst_ball, abs(float(ours - theirs)) / scale)
            if ref["qi"] > 0:
                assert abs(float(mp.degrees(ref["ai"])) - b.contact_angles_inner[j]) < 1e-9
            assert abs(float(mp.degrees(ref["ao"])) - b.contact_angles_outer[j]) < 1e-9
            f_r, f_a = ref["qi"] * mp.cos(ref["ai"]), ref["qi"] * mp.sin(ref["ai"])
            forces[0] += f_r * mp.cos(phi)
            forces[1] += f_r * mp.sin(phi)
            forces[2] += sigma * f_a
            forces[3] += sigma * lever * f_a * mp.cos(phi) - zk * f_r * mp.cos(phi)
            forces[4] += sigma * lever * f_a * mp.sin(phi) - zk * f_r * mp.sin(phi)
    applied = [fr, 0.0, fa, moment, moment_cross]
    f_ref = max(fr, abs(fa), float(r.preload), abs(moment) / float(lever),
                abs(moment_cross) / float(lever))  # fmt: skip
    shaft = max(abs(float(forces[i]) - applied[i]) / (float(lever) if i >= 3 else 1.0)
                for i in range(5)) / f_ref  # fmt: skip
    return worst_ball, shaft


CASES = [
    # (kind, z, F_r, F_a, speed, geometry, extra)
    ("DB", 12, 1000.0, 300.0, 10000.0, B7205, dict(preload=500.0)),
    ("DB", 12, 2000.0, 1000.0, 25000.0, B7205, dict(preload=200.0, moment=5000.0)),
    ("DF", 12, 800.0, -1500.0, 20000.0, B7205, dict(preload=300.0, cage_angle=7.0)),
    ("DT", 14, 500.0, 2000.0, 15000.0, B15, dict(moment_cross=3000.0, cage_angle=3.0)),
    ("DB", 14, 0.0, 0.0, 30000.0, B15, dict(preload=100.0)),
    ("DB", 12, 0.0, 2500.0, 20000.0, B7205, dict(preload=300.0)),  # bearing 2 lifted off
]


@pytest.mark.parametrize("kind, z, fr, fa, n, geometry, extra", CASES)
def test_every_ball_of_both_bearings_against_mpmath(kind, z, fr, fa, n, geometry, extra):
    r = solve_pair_high_speed(z, fr, fa, speed=n, arrangement=kind, **geometry, **extra)
    worst_ball, shaft = _mpmath_pair(r, z, fr, fa, geometry, kind, extra.get("moment", 0.0),
                                     extra.get("moment_cross", 0.0))  # fmt: skip
    assert worst_ball < 1e-9, worst_ball
    assert shaft < 1e-9, shaft
    assert r.residual <= 1e-12  # the solver's own measure: balanced to its tolerance
    assert np.all(np.isfinite(r.stiffness_matrix))
    for b in r.bearings:
        assert np.all(b.ball_loads_outer >= b.centrifugal_forces * (1 - 1e-12))
        assert np.all(np.asarray(b.speed) == n)


def test_the_centrifugal_forces_load_the_lifted_bearing_again():
    """A thrust beyond the lift-off load unloads bearing 2 at rest; at speed its balls, pushed
    out by F_c to a lower outer contact angle, move towards its inner groove and close the gap:
    it carries thrust again, its outer contacts more than its inner (Harris & Kotzalas vol. 2
    ch. 3: the centrifugal forces raise the preload of a rigidly preloaded pair)."""
    kind, z, fr, fa, n, geometry, extra = CASES[-1]
    rest = solve_pair_high_speed(z, fr, fa, speed=0.0, arrangement=kind, **geometry, **extra)
    assert rest.unloaded.tolist() == [False, True]
    assert fa > rest.lift_off_axial_load
    r = solve_pair_high_speed(z, fr, fa, speed=n, arrangement=kind, **geometry, **extra)
    b2 = r.bearings[1]
    assert r.unloaded.tolist() == [False, False] and b2.axial_load > 0.1 * fa
    assert np.all(b2.ball_loads_outer > b2.ball_loads_inner)
    assert np.all(b2.contact_angles_outer < b2.contact_angles_inner)


@pytest.mark.parametrize("kind, z, fr, fa, n, geometry, extra", CASES)
def test_speed_zero_is_the_static_pair(kind, z, fr, fa, n, geometry, extra):
    s = solve_pair(z, fr, fa, arrangement=kind, **geometry, **extra)
    r = solve_pair_high_speed(z, fr, fa, speed=0.0, arrangement=kind, **geometry, **extra)
    for name in ("x", "y", "axial", "tilt", "tilt_cross"):
        assert abs(getattr(r, name) - getattr(s, name)) <= 1e-12 * max(
            abs(getattr(s, name)), 1e-3
        ), name
    q = max(float(b.ball_loads.max()) for b in s.bearings)
    for ours, theirs in zip(r.bearings, s.bearings, strict=True):
        for loads in (ours.ball_loads_inner, ours.ball_loads_outer, ours.ball_loads):
            assert np.max(np.abs(loads - theirs.ball_loads)) <= 1e-12 * q
        loaded = theirs.ball_loads > 0
        for angles in (ours.contact_angles_inner, ours.contact_angles_outer):
            assert np.max(np.abs(angles - theirs.contact_angles)[loaded], initial=0) <= 1e-10
        assert abs(ours.axial_load - theirs.axial_load) <= 1e-12 * q * z
        assert abs(ours.load - theirs.load) <= 1e-12 * q * z
        assert np.all(ours.centrifugal_forces == 0) and np.all(ours.gyroscopic_moments == 0)
    assert np.array_equal(r.unloaded, s.unloaded)
    scale = np.abs(s.stiffness_matrix).max()
    assert np.max(np.abs(r.stiffness_matrix - s.stiffness_matrix)) <= 1e-7 * scale


def test_preloaded_pair_at_speed_outer_angles_fall_inner_rise_thrust_shared():
    """Harris & Kotzalas vol. 2 ch. 3: with speed the outer contact angle falls below the static
    one and the inner rises; the outer contact carries F_c more; the thrust of a rigidly
    preloaded pair grows. A DB pair under its preload alone stays symmetric: both bearings carry
    the same thrust (the mirror across the mid-plane)."""
    static = solve_pair(12, 0.0, 0.0, preload=500.0, **B7205)
    alpha = float(static.bearings[0].contact_angles[0])
    previous, thrust = 0.0, 500.0
    for n in (5000.0, 15000.0, 25000.0):
        r = solve_pair_high_speed(12, 0.0, 0.0, speed=n, preload=500.0, **B7205)
        assert r.axial == 0.0 and r.x == 0.0
        b1, b2 = r.bearings
        assert b1.axial_load == pytest.approx(b2.axial_load, rel=1e-12)
        assert np.all(b1.contact_angles_outer < alpha) and np.all(b1.contact_angles_inner > alpha)
        gap = float(np.max(b1.ball_loads_outer - b1.ball_loads_inner))
        assert gap > previous and b1.axial_load > thrust  # the preload grows with the speed
        previous, thrust = gap, b1.axial_load


def test_a_batch_equals_its_cases_one_by_one():
    fr = np.array([500.0, 1500.0, 0.0])
    fa = np.array([300.0, -800.0, 100.0])
    n = np.array([5000.0, 20000.0, 12000.0])
    r = solve_pair_high_speed(12, fr, fa, speed=n, preload=300.0, **B7205)
    for i in range(3):
        one = solve_pair_high_speed(12, fr[i], fa[i], speed=n[i], preload=300.0, **B7205)
        assert abs(r.x[i] - one.x) <= 1e-12 * 1e-2 and abs(r.axial[i] - one.axial) <= 1e-14
        for k in range(2):
            q = r.bearings[k].ball_loads_inner[i]
            assert np.max(np.abs(q - one.bearings[k].ball_loads_inner)) <= 1e-10 * q.max()


def test_refusals():
    with pytest.raises(InputError, match="speed"):
        solve_pair_high_speed(12, 1000.0, 300.0, speed=60000.0, preload=500.0, **B7205)
    with pytest.raises(InputError, match="speed"):
        solve_pair_high_speed(12, 1000.0, 300.0, speed=-1.0, preload=500.0, **B7205)
    with pytest.raises(InputError, match="preload"):  # the static pair's own refusals
        solve_pair_high_speed(12, 1000.0, 300.0, speed=1000.0, arrangement="DT",
                              preload=500.0, **B7205)  # fmt: skip
    with pytest.raises(TypeError):  # no constant K: each contact needs its Hertz stiffness
        solve_pair_high_speed(12, 1000.0, 300.0, speed=1000.0, stiffness=1e5, **B7205)


def test_a_case_left_unbalanced_is_a_convergence_error_naming_its_inputs(monkeypatch):
    """Never a silent answer: with the Newton steps and the continuation taken away, the case
    is a ConvergenceError naming its loads and speed."""
    monkeypatch.setattr(pair_speed, "ITERATIONS", 0)
    monkeypatch.setattr(pair_speed, "CONTINUATION_STAGES", 0)
    with pytest.raises(ConvergenceError) as err:
        solve_pair_high_speed(12, 1000.0, 300.0, speed=20000.0, preload=500.0, **B7205)
    text = str(err.value)
    assert "speed = 20000 rpm" in text and "radial_load = 1000 N" in text


# the command line ---------------------------------------------------------------------------

PAIR_CLI = ["solve", "7205BDB", "--preload", "500N", "-F", "1kN", "-A", "300N"]


def _json(capsys, *args):
    import json

    from tests.cli_helpers import run_entry

    code, out, err = run_entry(capsys, *args, "--format", "json", "--quiet")
    assert code == 0, err
    return json.loads(out)["cases"][0]


def test_cli_pair_at_speed_is_the_library_pair_with_the_ball_dynamics(capsys):
    case = _json(capsys, *PAIR_CLI, "--speed", "10000")
    assert "ball dynamics" in case["model"] and case["speed"] == 10000.0
    r = solve_pair_high_speed(12, 1000.0, 300.0, speed=10000.0, preload=500.0, **B7205)
    for key in ("x", "axial", "tilt"):
        assert case[key] == pytest.approx(float(getattr(r, key)), rel=1e-9), key
    for doc, b in zip(case["bearings"], r.bearings, strict=True):
        assert "ball dynamics" in doc["model"]
        for key in ("ball_loads_inner", "ball_loads_outer", "contact_angles_inner",
                    "contact_angles_outer"):  # fmt: skip
            assert np.allclose(doc[key], getattr(b, key), rtol=1e-9), key
        assert np.all(np.array(doc["ball_loads_outer"]) > np.array(doc["ball_loads_inner"]))


def test_cli_quasi_static_is_the_static_pair(capsys):
    static = _json(capsys, *PAIR_CLI)
    quasi = _json(capsys, *PAIR_CLI, "--speed", "10000", "--quasi-static")
    assert quasi["model"].endswith(
        "the static model at the speed given (the ball dynamics left out)"
    )
    for key in ("x", "axial", "tilt", "reference_rating_life", "rating_life"):
        assert quasi[key] == static[key], key
    for a, b in zip(quasi["bearings"], static["bearings"], strict=True):
        assert a["ball_loads"] == b["ball_loads"] and a["ball_loads_outer"] == b["ball_loads"]


def test_cli_table_says_the_ball_dynamics_are_included(capsys):
    from tests.cli_helpers import run_entry

    code, out, _ = run_entry(capsys, *PAIR_CLI, "--speed", "10000")
    assert code == 0
    assert "Speed: ball dynamics: centrifugal force and gyroscopic moment" in out
    assert "in both bearings" in out and "not coded" not in out


def test_cli_a_convergence_error_names_quasi_static(capsys, monkeypatch):
    from tests.cli_helpers import run_entry

    monkeypatch.setattr(pair_speed, "ITERATIONS", 0)
    monkeypatch.setattr(pair_speed, "CONTINUATION_STAGES", 0)
    code, out, err = run_entry(capsys, *PAIR_CLI, "--speed", "20000")
    assert code == 1 and out == ""
    assert "'--quasi-static' gives the static model" in err and "speed = 20000 rpm" in err


def test_a_light_load_against_the_centrifugal_forces_is_balanced_or_refused():
    """As the single bearing: a thrust of 1e-5 N on a tandem pair at 3000 rpm (balls of about
    1 N) is accepted within the change of the shaft forces over the balls' own residuals (it was
    a ConvergenceError at 2.4e-9 before that measure was carried to the pair); 1e-6 N on a DB
    pair at 20 000 rpm, whose rounding level is above 1e-5 of it, is refused naming the axial
    load and the static model (solve_pair; the CLI names --quasi-static: one Error line, exit
    2)."""
    r = solve_pair_high_speed(12, 0.0, 1e-5, speed=3000.0, arrangement="DT", **B7205)
    assert r.residual <= 1e-6
    with pytest.raises(InputError, match=r"static model of the pair \(solve_pair\)") as err:
        solve_pair_high_speed(12, 0.0, 1e-6, speed=20000.0, **B7205)
    assert err.value.parameter == "axial_load"


def test_cli_a_load_too_light_at_speed_names_quasi_static(capsys):
    from tests.cli_helpers import run_entry

    code, out, err = run_entry(capsys, "solve", "7205BDB", "-F", "0", "-A", "1e-6N", "--speed",
                               "20000")  # fmt: skip
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1
    assert lines[0].startswith("Error:") and "--axial-load" in lines[0]
    assert "--quasi-static" in lines[0]


def test_the_stiffness_matrix_at_speed_is_the_tangent_of_the_solve():
    """The shaft's 5x5 matrix at speed (the ball equations eliminated; not symmetric): its
    in-plane block (x, axial, tilt) inverted against central differences of the solve's
    displacement over the applied F_r, F_a and M (1e-4 of the loads)."""
    base = dict(speed=20000.0, preload=300.0, **B7205)
    f0 = np.array([1000.0, 300.0, 2000.0])  # F_r, F_a [N], M [N mm]

    def position(f):
        r = solve_pair_high_speed(12, f[0], f[1], moment=f[2], **base)
        return np.array([r.x, r.axial, np.deg2rad(r.tilt)]), r

    _, r0 = position(f0)
    plane = np.ix_([0, 2, 3], [0, 2, 3])
    compliance = np.linalg.inv(np.asarray(r0.stiffness_matrix)[plane])
    assert not np.allclose(r0.stiffness_matrix, np.transpose(r0.stiffness_matrix), rtol=1e-9)
    steps = np.array([0.1, 0.1, 0.1 * float(r0.bearings[0].tilt_radius)])
    for j in range(3):
        e = np.zeros(3)
        e[j] = steps[j]
        column = (position(f0 + e)[0] - position(f0 - e)[0]) / (2 * steps[j])
        scale = np.abs(compliance[:, j]).max()
        assert np.max(np.abs(column - compliance[:, j])) <= 1e-5 * scale, j


def test_the_preload_at_speed_is_each_bearings_thrust_with_no_external_load(capsys):
    """preload_at_speed: the thrust each bearing of DB/DF carries with no external load at the
    speed (the preload is ground in at rest: a rigidly preloaded pair carries more as the balls
    are thrown out). At speed 0 it is the preload; at speed it is each bearing's thrust of a
    solve under a thrust of 1e-3 N (the two bearings differ by that thrust, shared); it grows
    with the speed; none for DT; in the json and csv at speed with the ball dynamics only."""
    kw = dict(preload=300.0, **B7205)
    rest = solve_pair_high_speed(12, 1000.0, 200.0, speed=0.0, **kw)
    assert float(rest.preload_at_speed) == pytest.approx(300.0, rel=1e-12)
    thrust = []
    for n in (5000.0, 20000.0, 40000.0):
        r = solve_pair_high_speed(12, 1000.0, 200.0, speed=n, **kw)
        tiny = solve_pair_high_speed(12, 0.0, 1e-3, speed=n, **kw)
        pair = [float(b.axial_load) for b in tiny.bearings]
        assert float(r.preload_at_speed) == pytest.approx(0.5 * sum(pair), rel=1e-9)
        assert pair[0] - pair[1] == pytest.approx(1e-3, rel=1e-3)
        thrust.append(float(r.preload_at_speed))
    assert 300.0 < thrust[0] < thrust[1] < thrust[2]
    df = solve_pair_high_speed(12, 1000.0, -200.0, speed=20000.0, **dict(kw, arrangement="DF"))
    assert float(df.preload_at_speed) > 300.0
    dt = dict(B7205, arrangement="DT")
    assert solve_pair_high_speed(12, 1000.0, 200.0, speed=5000.0, **dt).preload_at_speed is None
    case = _json(capsys, *PAIR_CLI, "--speed", "20000")
    r = solve_pair_high_speed(12, 1000.0, 300.0, speed=20000.0, preload=500.0, **B7205)
    assert case["preload_at_speed"] == pytest.approx(float(r.preload_at_speed), rel=1e-9)
    assert case["lift_off_axial_load"] == _json(capsys, *PAIR_CLI)["lift_off_axial_load"]
    assert "preload_at_speed" not in _json(capsys, *PAIR_CLI, "--speed", "20000", "--quasi-static")
