"""Defect frequencies (bearingload.bearings.frequencies) against published orders, against an
independent derivation in mpmath (the no-slip conditions of the ball's velocity vectors solved
numerically), against the ball dynamics' own orbit and spin speeds, and on the command line
(single bearing, pair per bearing, quasi-static and with the ball dynamics, the rotating ring)."""

from __future__ import annotations

import json
import math

import mpmath
import numpy as np
import pytest

from bearingload.bearings.frequencies import defect_frequencies
from bearingload.errors import InputError
from tests.cli_helpers import run_entry

KEYS = (
    "cage_frequency",
    "ball_pass_frequency_outer",
    "ball_pass_frequency_inner",
    "ball_spin_frequency",
)

# Case Western Reserve University Bearing Data Center, "Bearing Information" page
# (engineering.case.edu/bearingdatacenter/bearing-information), SKF deep-groove bearings: z,
# D_w, d_m [in -> mm at 25.4] and the defect frequencies as multiples of the shaft frequency,
# (BPFI, BPFO, FTF, 2 BSF) as printed ("rolling element" is twice the ball spin).
CWRU = {
    "6205-2RS JEM": (9, 0.3126 * 25.4, 1.537 * 25.4, (5.4152, 3.5848, 0.39828, 4.7135)),
    "6203-2RS JEM": (8, 0.2656 * 25.4, 1.122 * 25.4, (4.9469, 3.0530, 0.3817, 3.9874)),
}


@pytest.mark.parametrize("name", sorted(CWRU))
def test_published_orders_of_the_cwru_bearings(name):
    z, dw, dm, (bpfi, bpfo, ftf, two_bsf) = CWRU[name]
    f = defect_frequencies(z, dw, dm, 60.0, 0.0)  # 1 Hz shaft: the orders themselves
    # the page's orders carry 5 digits from diameters rounded to 4 decimals of an inch
    assert f.ball_pass_frequency_inner == pytest.approx(bpfi, rel=2e-4)
    assert f.ball_pass_frequency_outer == pytest.approx(bpfo, rel=2e-4)
    assert f.cage_frequency == pytest.approx(ftf, rel=2e-4)
    assert 2 * f.ball_spin_frequency == pytest.approx(two_bsf, rel=2e-4)


def _no_slip(z, dw, dm, n, a_i, a_o, rotating, outer_control):
    """FTF, BPFO, BPFI, BSF from the velocity vectors, solved by mpmath (40 digits).

    Frame of the cage (axis e_x, radial e_r, tangential e_t = e_x x e_r); the ball's angular
    velocity relative to the cage w_R (cos b e_x - sin b e_r); contacts at rho_o = +D/2 (sin a_o
    e_x + cos a_o e_r), rho_i = -D/2 (sin a_i e_x + cos a_i e_r). Rolling without slip: the
    ball's surface velocity w x rho equals the ring's (w_ring - w_c) r e_t at both contacts;
    outer-raceway control: no spin at the outer contact (the ball's and the ring's angular
    velocities agree along its normal); pure rolling with one angle: the axis at b = a."""
    mpmath.mp.dps = 40
    dw, dm, a_i, a_o = (mpmath.mpf(x) for x in (dw, dm, a_i, a_o))
    a_i, a_o = mpmath.radians(a_i), mpmath.radians(a_o)
    w = 2 * mpmath.pi * mpmath.mpf(n) / 60
    w_i, w_o = (w, 0) if rotating == "inner" else (0, w)
    r_o, r_i = dm / 2 + dw / 2 * mpmath.cos(a_o), dm / 2 - dw / 2 * mpmath.cos(a_i)

    def equations(w_c, w_r, b):
        roll_o = w_r * dw / 2 * mpmath.cos(a_o - b) - (w_o - w_c) * r_o
        roll_i = -w_r * dw / 2 * mpmath.cos(a_i - b) - (w_i - w_c) * r_i
        if outer_control:
            spin = w_r * mpmath.sin(a_o - b) - (w_o - w_c) * mpmath.sin(a_o)
        else:
            spin = b - a_o
        return roll_o, roll_i, spin

    w_c, w_r, _ = mpmath.findroot(equations, (w / 2, -w * dm / (2 * dw), a_o))
    f_c, f_r, f_i, f_o = (x / (2 * mpmath.pi) for x in (w_c, w_r, w_i, w_o))
    return (float(f_c), float(z * abs(f_o - f_c)), float(z * abs(f_i - f_c)), float(abs(f_r)))


CASES = [  # z, D_w, d_m, n [rpm], alpha_i, alpha_o [°], rotating
    (12, 7.938, 38.5, 10000.0, 40.0, 40.0, "inner"),
    (12, 7.938, 38.5, 10000.0, 43.2, 36.7, "inner"),
    (9, 11.112, 53.5, 25000.0, 18.0, 11.5, "inner"),
    (25, 6.35, 61.0, 3000.0, 25.0, 21.0, "outer"),
    (7, 11.5, 43.5, 1000.0, 0.0, 0.0, "outer"),
    (9, 7.94, 39.04, 3000.0, -0.0158, 0.012, "inner"),  # a deep-groove ball's, near 0° at speed
]


@pytest.mark.parametrize("case", CASES)
def test_two_angles_agree_with_the_velocity_vectors(case):
    z, dw, dm, n, a_i, a_o, rotating = case
    got = defect_frequencies(z, dw, dm, n, a_i, a_o, rotating).values()
    want = _no_slip(z, dw, dm, n, a_i, a_o, rotating, outer_control=True)
    for key, value in zip(KEYS, want, strict=True):
        assert got[key] == pytest.approx(value, rel=1e-12, abs=1e-9), key


@pytest.mark.parametrize("case", CASES)
def test_one_angle_agrees_with_the_velocity_vectors(case):
    z, dw, dm, n, a_i, _, rotating = case
    got = defect_frequencies(z, dw, dm, n, a_i, rotating=rotating).values()
    want = _no_slip(z, dw, dm, n, a_i, a_i, rotating, outer_control=False)
    for key, value in zip(KEYS, want, strict=True):
        assert got[key] == pytest.approx(value, rel=1e-12, abs=1e-9), key


@pytest.mark.parametrize("case", CASES)
def test_the_other_flank_is_the_mirror_image(case):
    """A ball on the groove's other flank (a deep-groove ball under a thrust the other way, or
    a hair below 0° under a radial load) has the frequencies of the mirrored angles."""
    z, dw, dm, n, a_i, a_o, rotating = case
    plus = defect_frequencies(z, dw, dm, n, a_i, a_o, rotating).values()
    minus = defect_frequencies(z, dw, dm, n, -a_i, -a_o, rotating).values()
    one = defect_frequencies(z, dw, dm, n, -a_i, rotating=rotating).values()
    for key in KEYS:
        assert minus[key] == pytest.approx(plus[key], rel=1e-14), key
        assert one[key] == pytest.approx(
            defect_frequencies(z, dw, dm, n, a_i, rotating=rotating).values()[key], rel=1e-14
        )


def test_equal_angles_give_the_one_angle_cage_and_the_rotating_ring_moves_the_cage():
    one = defect_frequencies(12, 7.938, 38.5, 6000.0, 40.0)
    two = defect_frequencies(12, 7.938, 38.5, 6000.0, 40.0, 40.0)
    assert two.cage_frequency == pytest.approx(one.cage_frequency, rel=1e-14)
    assert two.ball_pass_frequency_outer == pytest.approx(one.ball_pass_frequency_outer, rel=1e-14)
    outer = defect_frequencies(12, 7.938, 38.5, 6000.0, 40.0, rotating="outer")
    # the cages of the two cases turn at n/60 together; the ball passes on each ring alike
    assert one.cage_frequency + outer.cage_frequency == pytest.approx(100.0, rel=1e-14)
    assert outer.ball_pass_frequency_inner == pytest.approx(one.ball_pass_frequency_inner)
    gamma = 7.938 * math.cos(math.radians(40.0)) / 38.5
    assert outer.cage_frequency == pytest.approx(100.0 * (1 + gamma) / 2, rel=1e-14)


@pytest.mark.parametrize(
    ("args", "name"),
    [
        ((0, 7.9, 38.5, 1000.0, 0.0), "balls"),
        ((9, 38.5, 38.5, 1000.0, 0.0), "ball_diameter"),
        ((9, 7.9, -1.0, 1000.0, 0.0), "pitch_diameter"),
        ((9, 7.9, 38.5, -1.0, 0.0), "speed"),
        ((9, 7.9, 38.5, 1000.0, 95.0), "contact_angle"),
        ((9, 7.9, 38.5, 1000.0, 20.0, float("nan")), "contact_angle_outer"),
    ],
)
def test_bad_input_is_refused_naming_the_parameter(args, name):
    with pytest.raises(InputError, match=name):
        defect_frequencies(*args)
    with pytest.raises(InputError, match="rotating"):
        defect_frequencies(9, 7.9, 38.5, 1000.0, 0.0, rotating="both")


def _json(capsys, *args):
    code, out, err = run_entry(capsys, "solve", *args, "--format", "json")
    assert code == 0, err
    return json.loads(out)


HAND_6205 = (
    "-z",
    "9",
    "--ball-diameter",
    f"{0.3126 * 25.4}",
    "--pitch-diameter",
    f"{1.537 * 25.4}",
    "-F",
    "1kN",
)


@pytest.mark.parametrize("rotating", ["inner", "outer"])
def test_cli_quasi_static_reproduces_cwru_at_the_shaft_frequency(capsys, rotating):
    doc = _json(capsys, *HAND_6205, "--speed", "1800", "--quasi-static", "--rotating", rotating)
    case = doc["cases"][0]
    assert all(doc["units"][k] == "Hz" for k in KEYS)
    _, _, _, (bpfi, bpfo, ftf, two_bsf) = CWRU["6205-2RS JEM"]
    cage = ftf if rotating == "inner" else 1 - ftf  # orders of the rotating ring's frequency
    assert case["cage_frequency"] == pytest.approx(30.0 * cage, rel=2e-4)
    assert case["ball_pass_frequency_outer"] == pytest.approx(30.0 * bpfo, rel=2e-4)
    assert case["ball_pass_frequency_inner"] == pytest.approx(30.0 * bpfi, rel=2e-4)
    assert case["ball_spin_frequency"] == pytest.approx(15.0 * two_bsf, rel=2e-4)


def test_cli_without_speed_gives_no_frequencies(capsys):
    case = _json(capsys, *HAND_6205)["cases"][0]
    assert not any(k in case for k in KEYS)


def _heaviest(values):
    return int(np.argmax(values))


def test_cli_ball_dynamics_take_the_heaviest_balls_two_angles_and_match_its_orbit(capsys):
    from bearingload.bearings.resolve import resolve_bearing
    from bearingload.models.high_speed import solve_high_speed

    case = _json(capsys, "7205B", "-F", "2kN", "-A", "3kN", "--speed", "12000")["cases"][0]
    h = _heaviest(case["ball_loads"])
    a_i, a_o = case["contact_angles_inner"][h], case["contact_angles_outer"][h]
    assert a_i != a_o  # the ball dynamics part the two contacts
    b = resolve_bearing("7205B")
    want = defect_frequencies(b.balls, b.ball_diameter, b.pitch_diameter, 12000.0, a_i, a_o)
    for key in KEYS:
        assert case[key] == pytest.approx(want.values()[key], rel=1e-9), key
    # the model's own orbit and spin speed of that ball (its public result) agree
    r = solve_high_speed(
        b.balls,
        2000.0,
        3000.0,
        speed=12000.0,
        ball_diameter=b.ball_diameter,
        pitch_diameter=b.pitch_diameter,
        f_i=b.f_i,
        f_o=b.f_o,
        contact_angle=b.contact_angle,
        modulus=b.modulus,
        poisson=b.poisson,
        tilt_radius=case["tilt_radius"],
    )
    k = _heaviest(r.ball_loads)
    assert k == h
    assert case["cage_frequency"] == pytest.approx(r.orbit_speeds[k] / (2 * math.pi), rel=1e-9)
    assert case["ball_spin_frequency"] == pytest.approx(
        abs(r.spin_speeds[k]) / (2 * math.pi), rel=1e-9
    )


@pytest.mark.parametrize("quasi", [False, True])
def test_cli_pair_gives_each_bearing_its_own_frequencies(capsys, quasi):
    from bearingload.bearings.resolve import resolve_bearing

    extra = ("--quasi-static",) if quasi else ()
    doc = _json(
        capsys, "7205BDB", "-F", "2kN", "-A", "1kN", "--preload", "500N", "--speed", "10000", *extra
    )
    b = resolve_bearing("7205B")
    got = []
    for bearing in doc["cases"][0]["bearings"]:
        h = _heaviest(bearing["ball_loads"])
        if quasi:
            want = defect_frequencies(
                b.balls,
                b.ball_diameter,
                b.pitch_diameter,
                10000.0,
                abs(bearing["contact_angles"][h]),
            )
        else:
            want = defect_frequencies(
                b.balls,
                b.ball_diameter,
                b.pitch_diameter,
                10000.0,
                bearing["contact_angles_inner"][h],
                bearing["contact_angles_outer"][h],
            )
        for key in KEYS:
            assert bearing[key] == pytest.approx(want.values()[key], rel=1e-9), key
        got.append(bearing["cage_frequency"])
    assert got[0] != got[1]  # the two bearings carry different loads, at different angles


def test_cli_table_shows_the_frequencies_with_units(capsys):
    code, out, err = run_entry(capsys, "solve", *HAND_6205, "--speed", "1800", "--quasi-static")
    assert code == 0, err
    for label in (
        "cage frequency FTF",
        "ball pass frequency, outer ring BPFO",
        "ball pass frequency, inner ring BPFI",
        "ball spin frequency BSF",
    ):
        line = next(x for x in out.splitlines() if x.startswith(label))
        assert line.rstrip().endswith("Hz")
