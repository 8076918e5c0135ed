"""Angular-contact ball bearings in the combined solve (``contact_angle``).

Proof: an independent mpmath reference (40 digits) written in the angular-contact geometry
itself (groove centres A cos(alpha_0) apart radially and A sin(alpha_0) axially at zero load,
one-sided contact), not through the deep-groove mapping the module uses; its Jacobian against
the 5x5 stiffness matrix; the closed form under pure thrust (every ball alike, Harris &
Kotzalas, *Rolling Bearing Analysis*, 5th ed., §8.3: ``F_a = z K (A (cos a0/cos a - 1))^1.5
sin a``); the radial engine under pure radial load (the balls at the groove bottom, 0°); the
deep-groove path untouched; the refusals.
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from bearingload.errors import InputError
from bearingload.models.combined import solve_combined
from bearingload.models.equilibrium import solve

from .cli_helpers import besides_tilt
from .test_combined import mp_ball_stiffness

B7205 = {"ball_diameter": 7.938, "pitch_diameter": 38.5, "f_i": 0.52, "f_o": 0.53}
CASES = {
    "40°, F_a > F_r, free tilt": dict(balls=13, radial_load=2000.0, axial_load=1000.0,
                                      contact_angle=40.0),
    "15°, moment, cage off the line": dict(balls=13, radial_load=2000.0, axial_load=600.0,
                                           contact_angle=15.0, moment=3000.0, cage_angle=7.0),
    "25°, F_r >> F_a: balls at 0° beside balls lifted": dict(
        balls=13, radial_load=3000.0, axial_load=10.0, contact_angle=25.0
    ),
    "30°, misalignment imposed": dict(balls=12, radial_load=1500.0, axial_load=800.0,
                                      contact_angle=30.0, misalignment=0.02),
}  # fmt: skip


def _mp_balls(case: dict, v: list) -> list:
    """(Q, alpha, phi) of every ball at v = (x, y, a [mm], theta, theta_c [rad]), ``a`` from the
    zero-load position; one-sided: a ball sees max(u, 0). 40 digits."""
    mp.mp.dps = 40
    dw, dm = mp.mpf(B7205["ball_diameter"]), mp.mpf(B7205["pitch_diameter"])
    fi, fo = mp.mpf(B7205["f_i"]), mp.mpf(B7205["f_o"])
    big_a = (fi + fo - 1) * dw
    a0 = mp.radians(case["contact_angle"])
    radius = dm / 2 + (fi - mp.mpf("0.5")) * dw * mp.cos(a0)
    x, y, a, th, thc = v
    out = []
    for j in range(case["balls"]):
        phi = mp.radians(case.get("cage_angle", 0.0)) + 2 * mp.pi * j / case["balls"]
        rho = big_a * mp.cos(a0) + x * mp.cos(phi) + y * mp.sin(phi)
        u = max(big_a * mp.sin(a0) + a + radius * (th * mp.cos(phi) + thc * mp.sin(phi)), 0)
        delta = mp.sqrt(rho**2 + u**2) - big_a
        alpha = mp.atan2(u, rho)
        if delta <= 0 or rho <= 0:
            out.append((mp.mpf(0), alpha, phi, radius))
            continue
        k = mp_ball_stiffness(alpha, dw, dm, fi, fo, mp.mpf(208000), mp.mpf("0.3"))
        out.append((k * delta**1.5, alpha, phi, radius))
    return out


def _mp_forces(case: dict, v: list) -> list:
    b = _mp_balls(case, v)
    return [
        sum(q * mp.cos(al) * mp.cos(ph) for q, al, ph, _ in b),
        sum(q * mp.cos(al) * mp.sin(ph) for q, al, ph, _ in b),
        sum(q * mp.sin(al) for q, al, ph, _ in b),
        sum(r * q * mp.sin(al) * mp.cos(ph) for q, al, ph, r in b),
        sum(r * q * mp.sin(al) * mp.sin(ph) for q, al, ph, r in b),
    ]


def _solve(case: dict):
    kw = {k: v for k, v in case.items() if k != "balls"}
    return solve_combined(case["balls"], **kw, **B7205)


@pytest.mark.parametrize("name", CASES)
def test_equilibrium_matches_independent_mpmath(name):
    case = CASES[name]
    r = _solve(case)
    fixed = case.get("misalignment")
    applied = [case["radial_load"], 0, case["axial_load"], case.get("moment", 0), 0]
    v0 = [mp.mpf(float(r.x)) * (1 + mp.mpf("1e-4")), mp.mpf(float(r.y)), mp.mpf(float(r.axial)),
          mp.radians(float(r.tilt)), mp.radians(float(r.tilt_cross))]  # fmt: skip
    free = [0, 1, 2, 4] if fixed is not None else [0, 1, 2, 3, 4]

    def eqs(*w):
        v = list(v0)
        for i, value in zip(free, w, strict=True):
            v[i] = value
        if fixed is not None:
            v[3] = mp.radians(fixed)
        f = _mp_forces(case, v)
        return [f[i] - applied[i] for i in free]

    sol = mp.findroot(eqs, [v0[i] for i in free], tol=mp.mpf(10) ** -28)
    v = list(v0)
    for i, value in zip(free, sol, strict=True):
        v[i] = value
    if fixed is not None:
        v[3] = mp.radians(fixed)
    balls = _mp_balls(case, v)
    q_ref = np.array([float(q) for q, *_ in balls])
    angle_ref = np.array([float(mp.degrees(al)) if q > 0 else 0.0 for q, al, *_ in balls])
    assert np.allclose(r.ball_loads, q_ref, rtol=1e-10, atol=1e-10 * q_ref.max())
    loaded = q_ref > 0
    assert np.allclose(r.contact_angles[loaded], angle_ref[loaded], rtol=1e-9, atol=1e-9)
    assert np.array_equal(r.ball_loads > 0, loaded)
    assert math.isclose(float(r.axial), float(v[2]), rel_tol=1e-9, abs_tol=1e-12)
    assert math.isclose(float(r.x), float(v[0]), rel_tol=1e-9, abs_tol=1e-12)


@pytest.mark.parametrize("name", CASES)
def test_stiffness_matrix_matches_mpmath_jacobian(name):
    """The 5x5 matrix of an angular-contact bearing against the symmetric part of the
    mpmath Jacobian of the five ring forces at the solver's equilibrium (central differences at
    40 digits; the last column/row in N mm per rad)."""
    case = CASES[name]
    r = _solve(case)
    v = [mp.mpf(float(r.x)), mp.mpf(float(r.y)), mp.mpf(float(r.axial)),
         mp.radians(float(r.tilt)), mp.radians(float(r.tilt_cross))]  # fmt: skip
    h = mp.mpf("1e-15")
    jac = np.zeros((5, 5))
    for k in range(5):
        up, down = list(v), list(v)
        up[k] += h
        down[k] -= h
        fu, fd = _mp_forces(case, up), _mp_forces(case, down)
        jac[:, k] = [float((a - b) / (2 * h)) for a, b in zip(fu, fd, strict=True)]
    sym = 0.5 * (jac + jac.T)
    scale = np.abs(sym).max()
    # the matrix is the true tangent (dK/d(alpha) included); its symmetric part beside it
    assert np.allclose(r.stiffness_matrix, jac, rtol=1e-6, atol=1e-7 * scale)
    assert np.allclose(r.stiffness_matrix_symmetric, sym, rtol=1e-6, atol=1e-7 * scale)
    assert np.array_equal(r.stiffness_matrix_symmetric, r.stiffness_matrix_symmetric.T)


def test_pure_thrust_closed_form():
    """Every ball alike: F_a = z K (A (cos a0 / cos a - 1))^1.5 sin a (constant K)."""
    k, z, a0 = 7.0e5, 13, 25.0
    r = solve_combined(z, 0.0, 3000.0, contact_angle=a0, stiffness=k, **B7205)
    big_a = 0.05 * B7205["ball_diameter"]
    alpha = np.radians(r.contact_angles)
    assert np.ptp(alpha) == 0.0
    delta = big_a * (math.cos(math.radians(a0)) / np.cos(alpha[0]) - 1.0)
    assert math.isclose(z * k * delta**1.5 * math.sin(alpha[0]), 3000.0, rel_tol=1e-12)
    assert r.contact_angles[0] > a0
    # the ring moves by A (sin a - cos a0 tan a)... measured from the zero-load position
    shift = big_a * (math.cos(math.radians(a0)) * math.tan(alpha[0]) - math.sin(math.radians(a0)))
    assert math.isclose(float(r.axial), shift, rel_tol=1e-10)


def test_pure_radial_load_balls_at_groove_bottom_as_radial_engine():
    """F_a = 0: no ball can push the ring axially without a thrust to balance it, so the loaded
    balls sit at 0° (the groove bottom) and carry as in a radial bearing of clearance
    G_r = 2A (1 - cos a0); the ring has slid the other way by A sin a0."""
    k, a0 = 7.0e5, 40.0
    big_a = 0.05 * B7205["ball_diameter"]
    r = solve_combined(13, 2000.0, 0.0, contact_angle=a0, stiffness=k, **B7205)
    g_r = 2.0 * big_a * (1.0 - math.cos(math.radians(a0)))
    ref = solve(13, 2000.0, k, g_r)
    assert np.allclose(r.ball_loads, ref.ball_loads, rtol=1e-12, atol=1e-9)
    assert np.all(r.contact_angles == 0.0)
    assert math.isclose(float(r.axial), -big_a * math.sin(math.radians(a0)), rel_tol=1e-12)


def test_one_sided_contact_far_balls_lift_off_where_deep_groove_presses_them():
    """A 1° misalignment: a deep-groove bearing of the same geometry (G_r = 2A (1 - cos a0))
    presses the far balls at negative contact angles; the angular-contact bearing's far balls
    leave the groove (no load, angle 0), never a negative load."""
    big_a = 0.05 * B7205["ball_diameter"]
    g_r = 2.0 * big_a * (1.0 - math.cos(math.radians(25.0)))
    dg = solve_combined(13, 500.0, 200.0, clearance=g_r, misalignment=1.0, **B7205)
    far = np.cos(np.radians(dg.ball_angles)) < -0.5
    assert np.all(dg.ball_loads[far] > 0) and np.all(dg.contact_angles[far] < 0)
    r = solve_combined(13, 500.0, 200.0, contact_angle=25.0, misalignment=1.0, **B7205)
    assert np.all(r.ball_loads[far] == 0) and np.all(r.contact_angles[far] == 0)
    assert np.all(r.ball_loads >= 0) and np.all(r.contact_angles >= 0)
    assert math.isclose(float(np.sum(r.ball_loads * np.sin(np.radians(r.contact_angles)))),
                        200.0, rel_tol=1e-12)  # fmt: skip


def test_deep_groove_unchanged_by_a_none_contact_angle():
    kw = dict(clearance=0.01, moment=2000.0, cage_angle=5.0, **B7205)
    a = solve_combined(9, 1400.0, 700.0, **kw)
    b = solve_combined(9, 1400.0, 700.0, contact_angle=None, **kw)
    assert np.array_equal(a.ball_loads, b.ball_loads)
    assert np.array_equal(a.stiffness_matrix, b.stiffness_matrix)


@pytest.mark.parametrize(
    ("kw", "name", "text"),
    [
        (dict(contact_angle=-1.0), "contact_angle", "0 to 60"),
        (dict(contact_angle=61.0), "contact_angle", "0 to 60"),
        (dict(contact_angle=25.0, axial_load=-100.0), "axial_load", ">= 0"),
        (dict(contact_angle=25.0, clearance=0.01), "clearance", "must be 0"),
        (dict(contact_angle=float("nan")), "contact_angle", ""),
        (dict(contact_angle=25.0, moment=20000.0), "moment", "F_a R_i"),
        (dict(contact_angle=25.0, axial_load=0.0, moment=1.0), "moment", "F_a R_i"),
    ],
)
def test_refusals(kw, name, text):
    args = dict(radial_load=1000.0, axial_load=500.0, **B7205)
    args.update(kw)
    with pytest.raises(InputError) as info:
        solve_combined(13, **args)
    assert info.value.parameter == name
    assert text in str(info.value)


def test_batch_cases_alone():
    """Each case of an array call equals that case solved alone (bits)."""
    fr = np.array([2000.0, 3000.0, 0.0])
    fa = np.array([1000.0, 10.0, 500.0])
    alpha = np.array([40.0, 25.0, 15.0])
    r = solve_combined(13, fr, fa, contact_angle=alpha, **B7205)
    for i in range(3):
        one = solve_combined(13, fr[i], fa[i], contact_angle=alpha[i], **B7205)
        assert np.array_equal(r.ball_loads[i], one.ball_loads)


# ------------------------------------------------------------------------------ command line

HAND = ("solve", "--balls", "13", "--ball-diameter", "7.938", "--pitch-diameter", "38.5",
        "-F", "2kN")  # fmt: skip


def test_cli_contact_angle_solves_and_reports_it(capsys):
    import json

    from tests.cli_helpers import run_entry

    code, out, err = run_entry(capsys, *HAND, "-A", "1kN", "--contact-angle", "40",
                               "--format", "json")  # fmt: skip
    assert code == 0 and besides_tilt(err) == []
    case = json.loads(out)["cases"][0]
    assert case["contact_angle"] == 40.0 and case["axial_play"] == 0.0
    r = solve_combined(13, 2000.0, 1000.0, contact_angle=40.0, **B7205)
    assert math.isclose(case["q_max"], r.q_max, rel_tol=1e-9)
    assert case["static_equivalent_load"] == 2000.0  # ISO 76 at 40°: max(F_r, 0.5 F_r + 0.26 F_a)


@pytest.mark.parametrize(
    ("extra", "option", "allowed"),
    [
        (("-A", "1kN", "--contact-angle", "61"), "--contact-angle", "0 to 60"),
        (("-A", "1kN", "--contact-angle", "-5"), "--contact-angle", "0 to 60"),
        (("-A", "-1kN", "--contact-angle", "25"), "--axial-load", ">= 0 N"),
        (("-A", "1kN", "--contact-angle", "25", "--clearance", "10um"), "--clearance", "no clear"),
        (("-A", "1kN", "--contact-angle", "25", "--moment", "1e5"), "--moment", "F_a R_i"),
    ],
)
def test_cli_bad_input_is_one_error_line(capsys, extra, option, allowed):
    from tests.cli_helpers import run_entry

    code, out, err = run_entry(capsys, *HAND, *extra)
    lines = err.strip().splitlines()
    assert code == 2 and out == ""
    assert len(lines) == 1 and lines[0].startswith("Error:") and option in lines[0]
    assert allowed in lines[0]
    assert "Traceback" not in err


@pytest.mark.parametrize(
    ("case", "words"),
    [
        (("6205", "-F", "3kN", "-A", "1kN", "-G", "C3"), "a tilt of the inner ring of 0.2855°"),
        (("7205B", "-F", "1kN", "-A", "500N"), "the inner ring tilts by 0.444°"),
    ],
)
def test_one_tilt_rule_whether_or_not_a_zero_moment_is_given(capsys, case, words):
    """solve 6205 -F 3kN -A 1kN -G C3 --moment 0 warned of its 0.2855° tilt, the same case
    without --moment (the same numbers) did not; 7205B -F 1kN -A 500N tilted 0.444° with no
    warning. The tilt weighed is the ring's, whatever gives it: both warn, alike."""
    from .cli_helpers import run_entry, warnings_of

    code, out, err = run_entry(capsys, "solve", *case)
    assert code == 0 and any(words in w for w in warnings_of(err)), err
    code, out_zero, err_zero = run_entry(capsys, "solve", *case, "--moment", "0")
    assert code == 0 and warnings_of(err_zero) == warnings_of(err)
