"""Pairs of angular-contact ball bearings (``bearingload.models.pair``).

Proof: an independent mpmath reference (40 digits) of the shaft's equilibrium written here from
the rigid-shaft kinematics (each bearing's inner groove centres moved by the shaft's translation
and tilt about the pair's centre, bearing 2 of DB/DF facing the other way, one-sided contact,
the preload offset from the single bearing's pure-thrust equation solved again here); its
Jacobian against the pair's 5x5 stiffness matrix; finite differences of the solve itself; the
symmetries (DB at no load, DT under thrust, DB against DF); the lift-off load against the
Hertz limit 2^1.5 F_p; the refusals.
"""

from __future__ import annotations

import itertools
import math

import mpmath as mp
import numpy as np
import pytest

from bearingload.errors import InputError
from bearingload.models.combined import solve_combined
from bearingload.models.pair import pair_life, solve_pair

from .test_combined import mp_ball_stiffness

#: 7205B as derived in the catalogue: z = 12, D_w = 11/32" (8.7312 mm), d_m = 38.5, B = 15 mm.
B7205 = {"ball_diameter": 8.7312, "pitch_diameter": 38.5, "f_i": 0.52, "f_o": 0.53}
Z = 12
WIDTH = 15.0

CASES = {
    "DB, preload, F_r + F_a + moment, Hertz K": dict(
        arrangement="DB", radial_load=2000.0, axial_load=1000.0, preload=500.0, moment=20000.0,
        contact_angle=40.0, hertz=True),
    "DF, preload, F_r + reversed F_a, cage off the line": dict(
        arrangement="DF", radial_load=1500.0, axial_load=-800.0, preload=300.0,
        contact_angle=25.0, cage_angle=7.0, stiffness=6.0e5),
    "DT, F_r + F_a + moment_cross": dict(
        arrangement="DT", radial_load=2000.0, axial_load=1500.0, moment_cross=5000.0,
        contact_angle=15.0, stiffness=6.0e5),
    "DB, no preload, one bearing lifted off": dict(
        arrangement="DB", radial_load=500.0, axial_load=3000.0, contact_angle=30.0,
        stiffness=6.0e5),
}  # fmt: skip


def _kw(case: dict) -> dict:
    return {k: v for k, v in case.items() if k != "hertz"}


def _solve(case: dict):
    return solve_pair(Z, **_kw(case), width=WIDTH, **B7205)


class _MpPair:
    """The pair's equations at 40 digits, written from the geometry (not from the module)."""

    def __init__(self, case: dict) -> None:
        mp.mp.dps = 40
        self.case = case
        self.dw, self.dm = mp.mpf(B7205["ball_diameter"]), mp.mpf(B7205["pitch_diameter"])
        self.fi, self.fo = mp.mpf(B7205["f_i"]), mp.mpf(B7205["f_o"])
        self.big_a = (self.fi + self.fo - 1) * self.dw
        self.a0 = mp.radians(case["contact_angle"])
        self.radius = self.dm / 2 + (self.fi - mp.mpf("0.5")) * self.dw * mp.cos(self.a0)
        kind = case["arrangement"]
        half = mp.mpf(WIDTH) / 2
        # (axial position, facing) of bearing 1 (takes +axial thrust) and bearing 2
        self.rows = {"DB": [(-half, 1), (half, -1)], "DF": [(half, 1), (-half, -1)],
                     "DT": [(-half, 1), (half, 1)]}[kind]  # fmt: skip
        self.offset = self._preload_offset(mp.mpf(case.get("preload", 0.0)))

    def stiffness(self, alpha):
        if self.case.get("hertz"):
            return mp_ball_stiffness(alpha, self.dw, self.dm, self.fi, self.fo, mp.mpf(208000),
                                     mp.mpf("0.3"))  # fmt: skip
        return mp.mpf(self.case["stiffness"])

    def _preload_offset(self, fp):
        """The axial approach u - A sin(a0) at which one bearing alone carries the thrust F_p."""
        if fp == 0:
            return mp.mpf(0)
        c = self.big_a * mp.cos(self.a0)

        def thrust(u):
            d = mp.sqrt(c**2 + u**2)
            alpha = mp.atan2(u, c)
            return Z * self.stiffness(alpha) * (d - self.big_a) ** 1.5 * mp.sin(alpha) - fp

        s0 = self.big_a * mp.sin(self.a0)
        u = mp.findroot(thrust, s0 * (1 + mp.mpf("1e-3")) + mp.mpf("1e-3"), tol=mp.mpf(10) ** -30)
        return u - s0

    def balls(self, v):
        """Per bearing, (Q, alpha, phi) of every ball at the shaft position v = (x, y, a [mm],
        theta, theta_c [rad])."""
        x, y, a, th, thc = v
        out = []
        for zk, sk in self.rows:
            bearing = []
            for j in range(Z):
                phi = mp.radians(self.case.get("cage_angle", 0.0)) + 2 * mp.pi * j / Z
                # the inner groove centre of this ball: moved by the shaft's rigid motion
                dx, dy = x - zk * th, y - zk * thc
                dz = a + self.radius * (th * mp.cos(phi) + thc * mp.sin(phi))
                rho = self.big_a * mp.cos(self.a0) + dx * mp.cos(phi) + dy * mp.sin(phi)
                u = max(self.big_a * mp.sin(self.a0) + self.offset + sk * dz, 0)
                delta = mp.sqrt(max(rho, 0) ** 2 + u**2) - self.big_a
                alpha = mp.atan2(u, rho)
                q = self.stiffness(alpha) * delta**1.5 if delta > 0 and rho > 0 else mp.mpf(0)
                bearing.append((q, alpha, phi))
            out.append(bearing)
        return out

    def forces(self, v):
        """The generalised forces of the balls on the shaft (F_x, F_y, F_a, M, M_c) by virtual
        work: radial force times the lever -z_k, axial force times R_i."""
        f = [mp.mpf(0)] * 5
        for (zk, sk), bearing in zip(self.rows, self.balls(v), strict=True):
            for q, al, ph in bearing:
                fr, fz = q * mp.cos(al), sk * q * mp.sin(al)
                f[0] += fr * mp.cos(ph)
                f[1] += fr * mp.sin(ph)
                f[2] += fz
                f[3] += fz * self.radius * mp.cos(ph) - zk * fr * mp.cos(ph)
                f[4] += fz * self.radius * mp.sin(ph) - zk * fr * mp.sin(ph)
        return f


def _position(r) -> list:
    return [mp.mpf(float(r.x)), mp.mpf(float(r.y)), mp.mpf(float(r.axial)),
            mp.radians(float(r.tilt)), mp.radians(float(r.tilt_cross))]  # fmt: skip


@pytest.mark.parametrize("name", CASES)
def test_pair_equilibrium_matches_independent_mpmath(name):
    case = CASES[name]
    r = _solve(case)
    ref = _MpPair(case)
    applied = [case["radial_load"], 0, case["axial_load"], case.get("moment", 0.0),
               case.get("moment_cross", 0.0)]  # fmt: skip
    v0 = _position(r)
    v0[0] *= 1 + mp.mpf("1e-4")

    def eqs(*v):
        return [f - a for f, a in zip(ref.forces(list(v)), applied, strict=True)]

    v = list(mp.findroot(eqs, v0, tol=mp.mpf(10) ** -26))
    assert r.residual <= 1e-12
    for got, want in zip(_position(r), v, strict=True):
        assert abs(float(got - want)) <= 1e-9 * max(abs(float(want)), 1e-4)
    for k, bearing in enumerate(ref.balls(v)):
        q_ref = np.array([float(q) for q, *_ in bearing])
        b = r.bearings[k]
        assert np.allclose(b.ball_loads, q_ref, rtol=1e-9, atol=1e-9 * max(q_ref.max(), 1.0))
        assert np.array_equal(b.ball_loads > 0, q_ref > 0)
        loaded = q_ref > 0
        angles = np.array([float(mp.degrees(al)) for _, al, _ in bearing])
        assert np.allclose(b.contact_angles[loaded], angles[loaded], rtol=1e-9, atol=1e-9)
        assert math.isclose(float(b.axial_load), float(sum(q * mp.sin(al) for q, al, _ in bearing)),
                            rel_tol=1e-9, abs_tol=1e-9)  # fmt: skip


@pytest.mark.parametrize("name", [n for n in CASES if not CASES[n].get("hertz")])
def test_pair_stiffness_matches_mpmath_jacobian(name):
    """Constant K: the tangent is symmetric as it is; against central differences at 40
    digits of the mpmath forces at the solver's equilibrium."""
    case = CASES[name]
    r = _solve(case)
    ref = _MpPair(case)
    v = _position(r)
    h = mp.mpf("1e-15")
    jac = np.zeros((5, 5))
    for k in range(5):
        up, down = list(v), list(v)
        up[k] += h
        down[k] -= h
        fu, fd = ref.forces(up), ref.forces(down)
        jac[:, k] = [float((a - b) / (2 * h)) for a, b in zip(fu, fd, strict=True)]
    assert np.allclose(r.stiffness_matrix, jac, rtol=1e-7, atol=1e-8 * np.abs(jac).max())
    assert np.array_equal(r.stiffness_matrix_symmetric, r.stiffness_matrix_symmetric.T)


def test_pair_stiffness_matches_finite_differences_of_the_solve():
    """Hertz K: the matrix against central differences of the solve itself (each load
    component moved by 1e-4 of the loads, the displacements read)."""
    base = dict(radial_load=2000.0, axial_load=700.0, moment=10000.0, moment_cross=3000.0)
    kw = dict(arrangement="DB", preload=400.0, contact_angle=25.0, width=WIDTH, **B7205)
    step = np.array([0.2, 0.2, 0.2, 2.0, 2.0])
    keys = ["radial_load", "y", "axial_load", "moment", "moment_cross"]
    compliance = np.zeros((5, 5))
    for j, key in enumerate(keys):
        if key == "y":  # no F_y input: turn the radial load by a small angle instead
            continue
        sides = []
        for sign in (1.0, -1.0):
            loads = dict(base)
            loads[key] += sign * step[j]
            r = solve_pair(Z, **loads, **kw)
            sides.append([r.x, r.y, r.axial, math.radians(r.tilt), math.radians(r.tilt_cross)])
        compliance[:, j] = (np.array(sides[0]) - np.array(sides[1])) / (2 * step[j])
    r = solve_pair(Z, **base, **kw)
    k = r.stiffness_matrix
    flex = np.linalg.inv(k)
    cols = [0, 2, 3, 4]
    for j in cols:
        assert np.allclose(compliance[:, j], flex[:, j], rtol=1e-5,
                           atol=1e-5 * np.abs(flex[:, j]).max())  # fmt: skip


def test_db_at_no_external_load_each_bearing_carries_the_preload():
    for angle, fp in ((40.0, 500.0), (15.0, 50.0), (25.0, 3000.0)):
        for kind in ("DB", "DF"):
            r = solve_pair(Z, 0.0, 0.0, arrangement=kind, preload=fp, contact_angle=angle,
                           width=WIDTH, **B7205)  # fmt: skip
            for b in r.bearings:
                assert math.isclose(b.axial_load, fp, rel_tol=1e-12)
                assert np.ptp(b.ball_loads) <= 1e-12 * b.ball_loads.max()
            assert r.x == 0.0 and r.y == 0.0 and abs(r.axial) <= 1e-15 * r.preload_offset
            # the preload offset is the single bearing's axial approach under the thrust F_p
            single = solve_combined(Z, 0.0, fp, contact_angle=angle, **B7205)
            assert math.isclose(r.preload_offset, single.axial, rel_tol=1e-10)


def test_dt_shares_a_thrust_equally():
    r = solve_pair(Z, 0.0, 1800.0, arrangement="DT", contact_angle=25.0, width=WIDTH, **B7205)
    one = solve_combined(Z, 0.0, 900.0, contact_angle=25.0, **B7205)
    for b in r.bearings:
        assert math.isclose(b.axial_load, 900.0, rel_tol=1e-12)
        assert np.allclose(b.ball_loads, one.ball_loads, rtol=1e-11)
    assert math.isclose(r.axial, one.axial, rel_tol=1e-10)
    # axial stiffness of the tandem pair: twice one bearing's
    assert math.isclose(r.stiffness_axial, 2 * one.stiffness_axial, rel_tol=1e-9)


def test_db_and_df_same_axial_stiffness_different_tilt_stiffness():
    """The same balls, the same loads under thrust: DB and DF differ only in where the
    pressure centres are. DB: apart (lever B/2 + R_i tan a), DF: between the bearings."""
    kw = dict(preload=500.0, contact_angle=40.0, width=WIDTH, **B7205)
    db = solve_pair(Z, 0.0, 1000.0, arrangement="DB", **kw)
    df = solve_pair(Z, 0.0, 1000.0, arrangement="DF", **kw)
    assert math.isclose(db.stiffness_axial, df.stiffness_axial, rel_tol=1e-12)
    assert math.isclose(db.stiffness_radial, df.stiffness_radial, rel_tol=1e-12)
    assert db.stiffness_tilt > 4.0 * df.stiffness_tilt
    # rough lever check: a pressure centre R_i tan(40°) = 16.3 mm from each ball row
    lever_db = WIDTH / 2 + 19.36 * math.tan(math.radians(40.0))
    lever_df = abs(WIDTH / 2 - 19.36 * math.tan(math.radians(40.0)))
    ratio = db.stiffness_tilt / df.stiffness_tilt
    assert 0.5 * (lever_db / lever_df) ** 2 < ratio < 2.0 * (lever_db / lever_df) ** 2


def test_lift_off_load_tends_to_the_hertz_limit():
    """Under thrust alone the unloaded bearing lifts off when the loaded one sits at twice the
    preload offset: with Q ~ delta^1.5 at a constant angle, F = 2^1.5 F_p (the limit of a light
    preload, where the angle hardly moves; Harris & Kotzalas, preloading: see
    docs/angular_contact.md for what was read)."""
    fp = np.array([1e-3, 10.0, 500.0])
    r = solve_pair(Z, 0.0, 0.0, preload=fp, contact_angle=40.0, width=WIDTH, **B7205)
    ratio = r.lift_off_axial_load / fp
    assert abs(ratio[0] - 2**1.5) < 1e-4
    assert np.all(np.diff(ratio) > 0)  # the contact angle grows: a little more
    lift = float(r.lift_off_axial_load[2])
    below = solve_pair(Z, 0.0, lift * (1 - 1e-3), preload=500.0, contact_angle=40.0,
                       width=WIDTH, **B7205)  # fmt: skip
    above = solve_pair(Z, 0.0, lift * (1 + 1e-3), preload=500.0, contact_angle=40.0,
                       width=WIDTH, **B7205)  # fmt: skip
    assert not below.unloaded.any() and below.bearings[1].axial_load > 0
    assert list(above.unloaded) == [False, True]
    at = solve_pair(Z, 0.0, lift, preload=500.0, contact_angle=40.0, width=WIDTH, **B7205)
    assert at.bearings[1].axial_load <= 1e-6 * lift
    rev = solve_pair(Z, 0.0, -lift * 1.001, preload=500.0, contact_angle=40.0, width=WIDTH,
                     **B7205)  # fmt: skip
    assert list(rev.unloaded) == [True, False]


def test_a_case_alone_equals_it_in_a_batch():
    fr = np.array([10.0, 2000.0, 5000.0, 0.0])
    fa = np.array([3000.0, -200.0, 100.0, 50.0])
    kw = dict(preload=300.0, contact_angle=25.0, width=WIDTH, moment=4000.0, **B7205)
    batch = solve_pair(Z, fr, fa, **kw)
    for i in range(fr.size):
        one = solve_pair(Z, fr[i], fa[i], **kw)
        assert one.x == batch.x[i] and one.tilt == batch.tilt[i]
        assert np.array_equal(one.bearings[1].ball_loads, batch.bearings[1].ball_loads[i])
    assert np.all(batch.residual <= 1e-12)


def test_pair_life_combines_with_the_weibull_exponent():
    e = 10 / 9
    assert math.isclose(pair_life(1000.0, 2000.0), (1000.0**-e + 2000.0**-e) ** (-1 / e))
    assert pair_life(1000.0, math.inf) == 1000.0
    assert math.isclose(pair_life(1000.0, 1000.0), 1000.0 * 2 ** (-9 / 10))


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        (dict(arrangement="DX"), "arrangement"),
        (dict(arrangement="DT", preload=100.0, axial_load=100.0), "preload"),
        (dict(arrangement="DT", axial_load=-100.0), "axial_load"),
        (dict(arrangement="DT", axial_load=0.0), "axial_load"),
        (dict(preload=-5.0), "preload"),
        (dict(contact_angle=0.0), "contact_angle"),
        (dict(contact_angle=70.0), "contact_angle"),
        (dict(radial_load=0.0, axial_load=0.0), "radial_load"),
        (dict(width=0.0), "width"),
        # narrower than a ball (8.7312 mm): was accepted, and a DT pair under a moment with
        # B of a few % of D_w ended in ConvergenceError (21 of 1500 random cases)
        (dict(width=8.7, arrangement="DT", moment=5000.0), "width"),
        (dict(balls=2), "balls"),
        (dict(radial_load=1e6, axial_load=1e6), "axial_load"),  # a ball over the groove edge
        # a pitch diameter not > 0 was refused as a width beyond 1000 d_m
        (dict(pitch_diameter=0.0), "pitch_diameter"),
        (dict(pitch_diameter=-38.5), "pitch_diameter"),
    ],
)
def test_refusals_name_the_parameter(kwargs, name):
    args = dict(radial_load=1000.0, axial_load=500.0, contact_angle=40.0, width=WIDTH, **B7205)
    args.update(kwargs)
    z = args.pop("balls", Z)
    with pytest.raises(InputError) as err:
        solve_pair(z, **args)
    assert err.value.parameter == name


def test_a_case_among_others_gives_the_bits_of_the_case_alone_preload_secant():
    """The preload approach's secant kept stepping a case that had stopped while another case of
    the call moved: its bits then depended on the other cases (this DB case alone and beside a
    lightly loaded one differed in the last bits of x, axial and the tilts; 1 and 3 of 150
    random cases of seeds 11 and 12). Once stopped, a case stops for good. The pair at speed
    starts from these positions and differed the same way."""
    from bearingload.models.pair_speed import solve_pair_high_speed

    ring = {"contact_angle": 40.0, "ball_diameter": 7.9375, "pitch_diameter": 38.5,
            "width": 15.0}  # fmt: skip
    fr = np.array([163.92566498986972, 33.804561546536966])
    fa = np.array([118.24301349167608, -2.737824557000332])
    fp = np.array([569.7203193480565, 422.5617030234025])
    cage = np.array([3.2019603340144442, 2.737802810447322])
    both = solve_pair(12, fr, fa, preload=fp, cage_angle=cage, **ring)
    alone = solve_pair(12, fr[:1], fa[:1], preload=fp[:1], cage_angle=cage[:1], **ring)
    for name in ("x", "y", "axial", "tilt", "tilt_cross"):
        assert getattr(both, name)[0] == getattr(alone, name)[0], name
    speed = np.array([12590.715610132422, 29627.610938463367])
    both = solve_pair_high_speed(12, fr, fa, speed=speed, preload=fp, cage_angle=cage, **ring)
    alone = solve_pair_high_speed(12, fr[:1], fa[:1], speed=speed[:1], preload=fp[:1],
                                  cage_angle=cage[:1], **ring)  # fmt: skip
    for name in ("x", "axial", "tilt"):
        assert getattr(both, name)[0] == getattr(alone, name)[0], name
    rng = np.random.default_rng(12)
    n = 150
    fr, fa = 10 ** rng.uniform(0, 3.5, n), 10 ** rng.uniform(0, 3.5, n) * rng.choice([1, -1, 0], n)
    fp, mm = 10 ** rng.uniform(0, 3, n), np.where(rng.random(n) < 0.3, rng.uniform(-2e4, 2e4, n), 0)
    rng.uniform(1000, 50000, n)  # the speeds of the seed's cases, not used here
    cage = rng.uniform(0, 30, n)
    every = solve_pair(12, fr, fa, preload=fp, cage_angle=cage, moment=mm, **ring)
    for i in range(n):
        one = solve_pair(12, fr[i : i + 1], fa[i : i + 1], preload=fp[i : i + 1],
                         cage_angle=cage[i : i + 1], moment=mm[i : i + 1], **ring)  # fmt: skip
        assert all(
            getattr(every, k)[i] == getattr(one, k)[0]
            for k in ("x", "y", "axial", "tilt", "tilt_cross")
        ), i


def test_a_width_beyond_a_pair_is_refused_naming_the_limit():
    """A width of 1e9 mm (7205-sized balls on 38.5 mm) ended in 'did not converge' (found by the
    review); widths above WIDTH_MAX times d_m are refused naming it; at the limit it solves."""
    from bearingload.models.pair import WIDTH_MAX

    geo = {"contact_angle": 40.0, "ball_diameter": 7.9375, "pitch_diameter": 38.5}
    with pytest.raises(InputError, match=r"^width: must be at most 1000 times the pitch diam"):
        solve_pair(12, 1000.0, 300.0, preload=100.0, width=1e9, **geo)
    r = solve_pair(12, 1000.0, 300.0, preload=100.0, width=WIDTH_MAX * 38.5, **geo)
    assert np.isfinite(r.x) and r.residual <= 1e-12


def test_balls_that_overlap_on_the_pitch_circle_are_refused():
    """z balls of D_w fit on the pitch circle only where D_w <= d_m sin(180°/z)
    (validate.ball_spacing, the rule of the command line and of solve_combined): 14 balls of
    8.7312 mm on 38.5 mm (8.6 mm apart) were solved as a pair; one case or among others, it is
    refused naming the ball diameter. 13 fit (9.26 mm apart)."""
    args = dict(contact_angle=40.0, width=WIDTH, preload=100.0, **B7205)
    for fr in (1000.0, np.array([1000.0, 2000.0])):
        with pytest.raises(InputError, match=r"^ball_diameter: 14 balls of 8\.7312 mm overlap"):
            solve_pair(14, fr, 300.0, **args)
    r = solve_pair(13, 1000.0, 300.0, **args)
    assert r.residual <= 1e-12


def _angular_limit(message: str) -> str:
    """The largest load a refusal 'too large for the angular-contact model' names [N]."""
    return message.split("; above ")[1].split(" N on this bearing")[0]


@pytest.mark.parametrize(
    ("loads", "name"),
    [
        (dict(radial_load=1e11), "radial_load"),
        (dict(radial_load=1e3, axial_load=1e11), "axial_load"),
        (dict(radial_load=1e3, preload=1e11), "preload"),
    ],
)
def test_loads_beyond_the_angular_contact_scale_are_refused_as_for_one_bearing(loads, name):
    """A load of 1e11 N (10^7 C_0r) on a 7205B DB pair ended in a ConvergenceError; the single
    bearing refuses it (the one-ball approach beyond 10^4 A, combined.ANGULAR_RATIO_MIN): the
    pair refuses it by the same rule, naming its largest load and the same limit."""
    kw = dict(axial_load=0.0, preload=0.0) | loads
    with pytest.raises(InputError, match="too large for the angular-contact model") as info:
        solve_pair(Z, contact_angle=40.0, width=WIDTH, **kw, **B7205)
    assert info.value.parameter == name
    with pytest.raises(InputError) as one:
        solve_combined(Z, 1e11, 0.0, contact_angle=40.0, **B7205)
    assert _angular_limit(info.value.message) == _angular_limit(one.value.message) == "8.31e+10"


@pytest.mark.parametrize(
    ("moments", "name"),
    [
        (dict(moment=2e13), "moment"),
        (dict(moment_cross=2e13), "moment_cross"),
        (dict(moment=1e13, moment_cross=-2e13), "moment_cross"),
        (dict(moment=-2e13, moment_cross=1e13), "moment"),
    ],
)
def test_a_moment_beyond_the_angular_contact_scale_is_named_as_given(moments, name):
    """M/R_i is the size of both moments, hypot(M, M_c)/R_i: a moment across the load line too
    large for a 7205B pair was refused naming ``moment`` (the command line's --moment, which
    was not given). The larger of the two is named."""
    kw = dict(contact_angle=40.0, width=WIDTH, preload=100.0) | moments
    with pytest.raises(InputError, match="too large for the angular-contact model") as info:
        solve_pair(Z, 1000.0, 0.0, **kw, **B7205)
    assert info.value.parameter == name


def test_a_pair_under_a_radial_load_the_single_bearing_takes_is_balanced():
    """1e10 N, within the single bearing's scale (it answers): the pair's Newton capped every
    component of its step at A and ran out of steps (a ConvergenceError from 1e10 N on); its
    radial parts are free, as the single bearing's. Each bearing of DB carries half the load
    (the mirror symmetry), the radial forces sum to the load, the thrusts cancel."""
    r = solve_pair(Z, 1e10, 0.0, contact_angle=40.0, width=WIDTH, **B7205)
    assert r.residual <= 1e-12
    one, two = r.bearings
    assert one.load + two.load == pytest.approx(1e10, rel=1e-12)
    assert one.load == pytest.approx(two.load, rel=1e-12)
    assert one.axial_load == pytest.approx(two.axial_load, rel=1e-12)


@pytest.mark.parametrize("arrangement", ["DB", "DF"])
def test_a_heavy_thrust_on_a_pair_reaches_the_groove_edge_not_a_convergence_error(arrangement):
    """F_r = F_a = 1e10 N drives a ball to 90°, as the single bearing under these loads (its
    refusal): the pair's Newton, its axial steps capped at A = 4e-4 of the approach, stopped
    after 460 steps short of it (a ConvergenceError); capped at a tenth of the approach where
    A is less, it reaches the edge and refuses it."""
    with pytest.raises(InputError, match="to a contact angle of 90°"):
        solve_combined(Z, 1e10, 1e10, contact_angle=40.0, **B7205)
    with pytest.raises(InputError, match="to a contact angle of 90°"):
        solve_pair(Z, 1e10, 1e10, arrangement=arrangement, contact_angle=40.0, width=WIDTH, **B7205)


#: One case of a pair breaking one rule of its inputs each (the rest valid), in the order the
#: rules are checked, and the parameter refused.
ONE_PAIR_RULE_BROKEN = [
    ({"radial_load": -1.0}, "radial_load"),
    ({"contact_angle": 0.0}, "contact_angle"),
    ({"preload": -1.0}, "preload"),
    ({"arrangement": "DT", "preload": 100.0}, "preload"),
    ({"arrangement": "DT", "preload": 0.0, "axial_load": 0.0}, "axial_load"),
    ({"width": 0.0}, "width"),
    ({"f_i": 0.5}, "f_i"),
    ({"f_o": 1.0}, "f_o"),
    ({"modulus": -1.0}, "modulus"),
    ({"stiffness": 0.0}, "stiffness"),
    ({"tilt_radius": -2.0}, "tilt_radius"),
    ({"ball_diameter": 1e-3}, "ball_diameter"),
]


def _pair_case(**given):
    kw = dict(radial_load=2000.0, axial_load=1000.0, preload=300.0, contact_angle=40.0)
    return kw | dict(width=WIDTH, **B7205) | given


@pytest.mark.parametrize(("given", "parameter"), ONE_PAIR_RULE_BROKEN)
def test_one_pair_case_of_plain_numbers_is_refused_as_an_array_of_it(given, parameter):
    """The pair's one-case fast gate (plain floats) and its checked path (arrays) take the same
    rules: one broken rule is refused with the same message either way."""
    kw = _pair_case(**given)
    with pytest.raises(InputError) as plain:
        solve_pair(Z, **kw)
    arrays = {k: v if k == "arrangement" else np.array([v]) for k, v in kw.items()}
    with pytest.raises(InputError) as checked:
        solve_pair(Z, **arrays)
    assert plain.value.parameter == checked.value.parameter == parameter
    assert str(plain.value) == str(checked.value)


def test_the_pairs_rules_are_checked_in_their_order():
    """Of two broken rules the first in the order is named, on either path."""
    for (first, name), (second, _) in itertools.pairwise(ONE_PAIR_RULE_BROKEN):
        if any(first[k] != second[k] for k in set(first) & set(second)):
            continue  # (two preloads, two arrangements' rules)
        kw = _pair_case(**{**second, **first})
        arrays = {k: v if k == "arrangement" else np.array([v]) for k, v in kw.items()}
        for args in (kw, arrays):
            with pytest.raises(InputError) as info:
                solve_pair(Z, **args)
            assert info.value.parameter == name, (first, second, info.value)


def test_the_pairs_fast_gate_and_checked_path_read_one_table_of_rules():
    """pair._plain restated the conditions pair._checked tested (as combined's fast path did
    before its rules table): both now read pair's rules, the single bearing's where they are
    the same rule (F_r >= 0, the conformities, E and K > 0, the ball size)."""
    from bearingload.models import combined, pair

    rules = pair._INPUT_RULES + pair._CASE_RULES
    assert all(isinstance(rule, combined.Rule) for rule in rules)
    assert combined.RADIAL_LOAD_RULE in pair._INPUT_RULES
    assert pair._CASE_RULES == (combined.BALL_SIZE_RULE,)
    for gate in pair._GATES.values():
        assert set(gate) <= {rule.holds for rule in rules}
