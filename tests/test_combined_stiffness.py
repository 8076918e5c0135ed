"""The 5x5 stiffness matrix of a combined-load solve (``CombinedDistribution.stiffness_matrix``).

Proved two ways: (a) against an independent mpmath Jacobian of the five ring forces (40 digits,
its own geometry and, for the Hertz stiffness, its own elliptic-integral contact stiffness) at
the solver's equilibrium; (b) against finite differences of the solve itself: the compliance
(the matrix's inverse) times a small change of each applied load is the change of the
displacements the solver returns.
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from bearingload.models.combined import solve_combined

from .test_combined import mp_ball_stiffness

G6205 = {"ball_diameter": 7.938, "pitch_diameter": 38.5}  # the catalogue 6205 (NSK ball set)
CASES = {
    "clearance, free tilt": dict(radial_load=1400.0, axial_load=700.0, clearance=0.0125),
    "preload, moments both ways, cage off the load line": dict(
        radial_load=500.0,
        axial_load=200.0,
        clearance=-0.01,
        moment=5000.0,
        moment_cross=-3000.0,
        cage_angle=7.0,
    ),  # fmt: skip
    "imposed misalignment": dict(
        radial_load=2000.0, axial_load=-300.0, clearance=0.02, misalignment=0.05
    ),  # fmt: skip
}


def _mp_forces(case: dict, v: list, stiffness: float | None) -> list:
    """(F_x, F_y, F_a [N], M, M_c [N mm]) the balls exert on the inner ring at v = (x, y, a [mm],
    theta, theta_c [rad]), at 40 digits (ISO/TS 16281 kinematics, the module's conventions)."""
    mp.mp.dps = 40
    dw, dm = mp.mpf(G6205["ball_diameter"]), mp.mpf(G6205["pitch_diameter"])
    fi, fo = mp.mpf("0.52"), mp.mpf("0.53")
    big_a = (fi + fo - 1) * dw
    g = mp.mpf(case["clearance"]) / 2
    alpha0 = mp.acos(1 - g / big_a) if g > 0 else mp.mpf(0)
    radius = dm / 2 + (fi - mp.mpf("0.5")) * dw * mp.cos(alpha0)
    z = 9
    out = [mp.mpf(0)] * 5
    x, y, a, th, thc = v
    for j in range(z):
        phi = mp.radians(case.get("cage_angle", 0.0)) + 2 * mp.pi * j / z
        rho = big_a - g + x * mp.cos(phi) + y * mp.sin(phi)
        u = a + radius * (th * mp.cos(phi) + thc * mp.sin(phi))
        delta = mp.sqrt(rho**2 + u**2) - big_a
        if delta <= 0 or rho <= 0:
            continue
        alpha = mp.atan2(u, rho)
        k = mp.mpf(stiffness) if stiffness else mp_ball_stiffness(
            alpha, dw, dm, fi, fo, mp.mpf(208000), mp.mpf("0.3"))  # fmt: skip
        q = k * delta**1.5
        arms = (mp.cos(alpha) * mp.cos(phi), mp.cos(alpha) * mp.sin(phi), mp.sin(alpha),
                radius * mp.sin(alpha) * mp.cos(phi), radius * mp.sin(alpha) * mp.sin(phi))  # fmt: skip
        out = [o + q * arm for o, arm in zip(out, arms, strict=True)]
    return out


def _mp_jacobian(case: dict, r, stiffness: float | None) -> np.ndarray:
    """d(forces)/d(v) at the solver's equilibrium, central differences at 40 digits (step 1e-15
    of the lengths: the truncation error is 1e-30 of the entries)."""
    mp.mp.dps = 40
    v0 = [mp.mpf(r.x), mp.mpf(r.y), mp.mpf(r.axial), mp.radians(mp.mpf(r.tilt)),
          mp.radians(mp.mpf(r.tilt_cross))]  # fmt: skip
    jac = np.zeros((5, 5))
    for col in range(5):
        h = mp.mpf("1e-15") / (20 if col >= 3 else 1)  # (a tilt of 1 rad moves R_i ~ 20 mm)
        up, down = list(v0), list(v0)
        up[col] += h
        down[col] -= h
        f_up, f_down = _mp_forces(case, up, stiffness), _mp_forces(case, down, stiffness)
        jac[:, col] = [float((a - b) / (2 * h)) for a, b in zip(f_up, f_down, strict=True)]
    return jac


@pytest.mark.parametrize("name", list(CASES))
@pytest.mark.parametrize("stiffness", [3.0e5, None], ids=["constant K", "Hertz K(alpha)"])
def test_the_matrix_is_the_jacobian_of_the_ring_forces(name, stiffness):
    """The matrix is the mpmath Jacobian to 1e-12 of its largest entry, with a constant K and
    with the Hertz K(alpha), whose change with the contact angle makes it not quite symmetric
    (the skew part below 1e-4 of the largest entry; measured 6e-6 to 9e-6); its symmetric part
    ``stiffness_matrix_symmetric`` is the Jacobian's to 1e-12."""
    case = CASES[name]
    r = solve_combined(9, stiffness=stiffness, **G6205, **case)
    jac = _mp_jacobian(case, r, stiffness)
    mat = np.asarray(r.stiffness_matrix)
    half = np.asarray(r.stiffness_matrix_symmetric)
    assert np.array_equal(half, half.T)
    # entries scaled to a common size: forces per mm, moments per rad over R_i
    scale = np.diag([1.0, 1.0, 1.0, 1.0 / r.tilt_radius, 1.0 / r.tilt_radius])
    jac_s, mat_s, half_s = scale @ jac @ scale, scale @ mat @ scale, scale @ half @ scale
    size = np.abs(jac_s).max()
    assert np.abs(mat_s - jac_s).max() <= 1e-12 * size
    assert np.abs(half_s - 0.5 * (jac_s + jac_s.T)).max() <= 1e-12 * size
    skew = np.abs(jac_s - jac_s.T).max() / 2
    assert skew <= (1e-12 if stiffness else 1e-4) * size
    if stiffness:
        assert np.array_equal(mat, mat.T)
    assert np.all(np.linalg.eigvalsh(half_s) > 0)  # stable: every direction pushes back


def test_the_static_matrix_is_the_matrix_at_speed_zero():
    """One tangent at rest and at speed: the static solve's matrix equals the ball dynamics' at
    1e-3 rpm to 1e-9 of its largest entry, for one bearing and a preloaded pair (the static
    matrix was the symmetric part: 4.8e-6 apart, and a pair's matrix jumped between 0 and
    1e-3 rpm)."""
    from bearingload.models.high_speed import solve_high_speed
    from bearingload.models.pair import solve_pair
    from bearingload.models.pair_speed import solve_pair_high_speed

    one = dict(clearance=0.01, **G6205)
    still = solve_combined(9, 3000.0, 500.0, **one).stiffness_matrix
    slow = solve_high_speed(9, 3000.0, 500.0, speed=1e-3, **one).stiffness_matrix
    assert np.abs(slow - still).max() <= 1e-9 * np.abs(still).max()
    pair = dict(
        preload=300.0,
        moment=2000.0,
        contact_angle=40.0,
        ball_diameter=8.7312,
        pitch_diameter=38.5,
        width=15.0,
    )
    still = np.asarray(solve_pair(12, 1000.0, 300.0, **pair).stiffness_matrix)
    slow = np.asarray(solve_pair_high_speed(12, 1000.0, 300.0, speed=1e-3, **pair).stiffness_matrix)
    assert np.abs(slow - still).max() <= 1e-9 * np.abs(still).max()


@pytest.mark.parametrize("name", list(CASES))
def test_the_compliance_moves_the_solve_as_the_loads_change(name):
    """The inverse of the matrix (constant K) predicts how the solve's displacements move when
    F_r, F_a, M or M_c change by 1e-5 of the largest load (central differences of the solve,
    error ~1e-10 from the step, 1e-7 from the 1e-12 equilibrium over the 1e-5 step): to 1e-6.
    The tilt is held where a misalignment is imposed: there its column is not an input."""
    case = dict(CASES[name])
    k = 3.0e5
    r = solve_combined(9, stiffness=k, **G6205, **case)
    lever = r.tilt_radius
    held = "misalignment" in case
    free = [0, 1, 2, 4] if held else [0, 1, 2, 3, 4]
    comp = np.linalg.inv(np.asarray(r.stiffness_matrix)[np.ix_(free, free)])
    f_ref = max(case["radial_load"], abs(case["axial_load"]))
    inputs = {0: "radial_load", 2: "axial_load", 3: "moment", 4: "moment_cross"}
    if held:
        del inputs[3]
    for row, key in inputs.items():
        h = 1e-5 * f_ref * (lever if row >= 3 else 1.0)
        moved = []
        for sign in (1.0, -1.0):
            c = dict(case)
            c[key] = c.get(key, 0.0) + sign * h
            s = solve_combined(9, stiffness=k, **G6205, **c)
            moved.append(np.array([s.x, s.y, s.axial, math.radians(s.tilt),
                                   math.radians(s.tilt_cross)])[free])  # fmt: skip
        got = (moved[0] - moved[1]) / (2 * h)
        want = comp[:, free.index(row)]
        assert np.allclose(got, want, rtol=1e-6, atol=1e-6 * np.abs(want).max()), key


def test_the_named_stiffnesses_are_the_diagonal():
    r = solve_combined(9, 1400.0, 700.0, clearance=0.0125, **G6205)
    m = r.stiffness_matrix
    assert (r.stiffness_radial, r.stiffness_axial, r.stiffness_tilt) == (m[0, 0], m[2, 2], m[3, 3])
    assert isinstance(r.stiffness_radial, float) and m.shape == (5, 5)
    many = solve_combined(9, [1400.0, 100.0], 700.0, clearance=0.0125, **G6205)
    assert many.stiffness_matrix.shape == (2, 5, 5)
    np.testing.assert_array_equal(many.stiffness_matrix[0], m)  # no case depends on the others


def test_a_coupling_below_rounding_is_zero_whatever_the_order_of_the_sum():
    """Under a pure axial load every ball carries the same load: the couplings of the axial and
    tilt rows with x vanish in exact arithmetic (sum_j cos phi_j = 0). Summed in floating point
    they were rounding (6.5e-12 N/mm beside 1.1e6, in the order the balls were summed); they are
    reported as 0, while a real coupling (x with tilt) stays."""
    r = solve_combined(
        7, 0.0, 1000.0, ball_diameter=11.5, pitch_diameter=43.5, clearance=0.01, modulus=210000.0
    )
    k = np.asarray(r.stiffness_matrix)
    assert k[0, 2] == 0.0 and k[2, 0] == 0.0 and k[2, 3] == 0.0
    assert k[0, 3] > 1e-3 * math.sqrt(k[0, 0] * k[3, 3])


@pytest.mark.parametrize("lever", [1e160, 1e300])
def test_an_overflowing_tilting_stiffness_is_refused_not_zeroed(lever):
    """A lever whose square times K overflows gives an infinite tilting stiffness: refused
    naming tilt_radius. The rounding threshold (4 z eps sqrt(K_aa K_bb)) is itself infinite in
    that row and had set the infinite entries to 0: a tilting stiffness of 0 N mm/rad, printed
    with exit 0."""
    from bearingload.errors import InputError

    with pytest.raises(InputError, match="tilt_radius"):
        solve_combined(9, 1400.0, 700.0, clearance=0.0125, tilt_radius=lever, **G6205)


def test_the_stiffness_matrix_is_in_every_format_of_solve(capsys):
    """The 5x5 tangent stiffness matrix of a combined case was in json only: csv has its 25
    entries (stiffness_matrix_ij = json's stiffness_matrix[i-1][j-1], with their units), the
    table and markdown a block of the matrix, each equal to json's at the printed digits; a
    pair's terminal output shows the shaft's."""
    import csv as csv_module
    import io
    import json as json_module

    from .cli_helpers import run_entry

    case = ("solve", "6205", "-F", "3kN", "-A", "1kN")
    matrix = json_module.loads(run_entry(capsys, *case, "--format", "json")[1])["cases"][0][
        "stiffness_matrix"
    ]
    (row,) = csv_module.DictReader(io.StringIO(run_entry(capsys, *case, "--format", "csv")[1]))
    units = {"14": "N/rad", "41": "N mm/mm", "45": "N mm/rad", "22": "N/mm"}
    for ij, unit in units.items():
        assert (
            float(row[f"stiffness_matrix_{ij} [{unit}]"]) == matrix[int(ij[0]) - 1][int(ij[1]) - 1]
        )
    assert sum(k.startswith("stiffness_matrix_") for k in row) == 25
    for fmt in ("table", "markdown"):
        out = run_entry(capsys, *case, "--format", fmt)[1]
        assert "tangent stiffness matrix" in out
        lines = [line for line in out.splitlines() if "M_c [N mm]" in line]
        cells = [c for c in lines[0].replace("|", " ").split()[3:]]
        assert [float(c) for c in cells] == pytest.approx(matrix[4], rel=1e-5, abs=1e-6)
    out = run_entry(capsys, "solve", "7205BDB", "-F", "1kN", "-A", "300N")[1]
    assert "tangent stiffness matrix of the shaft" in out


def test_a_pairs_stiffness_matrices_are_in_every_format_of_solve(capsys):
    """A pair's json gives the shaft's matrix and each bearing's: csv carries them too, the
    shaft's as pair_stiffness_matrix_ij on both rows, each bearing's as stiffness_matrix_ij
    on its own row; the table and markdown show the three; sweep's json rows (whose csv rows
    are solve's) give them as solve's json does."""
    import csv as csv_module
    import io
    import json as json_module
    import re

    from .cli_helpers import run_entry

    case = ("solve", "7205BDB", "-F", "1kN", "-A", "300N")
    doc = json_module.loads(run_entry(capsys, *case, "--format", "json")[1])["cases"][0]
    rows = list(csv_module.DictReader(io.StringIO(run_entry(capsys, *case, "--format", "csv")[1])))
    assert len(rows) == 2
    for n, row in enumerate(rows):
        cells = {re.sub(r" \[.*\]$", "", k): v for k, v in row.items()}
        for i in range(5):
            for j in range(5):
                shaft = cells[f"pair_stiffness_matrix_{i + 1}{j + 1}"]
                own = cells[f"stiffness_matrix_{i + 1}{j + 1}"]
                assert float(shaft) == doc["stiffness_matrix"][i][j]
                assert float(own) == doc["bearings"][n]["stiffness_matrix"][i][j]
    for fmt in ("table", "markdown"):
        out = run_entry(capsys, *case, "--format", fmt)[1]
        assert out.count("tangent stiffness matrix") == 3
        assert "of the shaft" in out and "of bearing 1" in out and "of bearing 2" in out
    sweep = ("sweep", "7205BDB", "-F", "1kN", "-A", "300N", "--steps", "2", "--format", "json")
    first = json_module.loads(run_entry(capsys, *sweep)[1])["rows"][0]
    assert first["stiffness_matrix"] == doc["stiffness_matrix"]
    assert [b["stiffness_matrix"] for b in first["bearings"]] == [
        b["stiffness_matrix"] for b in doc["bearings"]
    ]


def test_radial_stiffness_is_one_quantity_in_both_engines():
    """stiffness_radial is dF_r/dx with F_y held at zero in the radial engine and in the 3-D
    one: off the symmetric cage (K_xy != 0) the same case with '-A 0' gives the same number
    (it gave K_xx, 0.18 % stiffer, before)."""
    import bearingload

    radial = bearingload.analyse("6205", load="1kN", clearance="C3", cage_angle=5)
    combined = bearingload.analyse("6205", load="1kN", clearance="C3", cage_angle=5, axial_load=0)
    assert (radial.engine, combined.engine) == ("radial", "combined")
    assert combined.stiffness_radial == pytest.approx(radial.stiffness_radial, rel=1e-9)
    kxx = combined.stiffness_matrix[0][0]
    assert kxx > combined.stiffness_radial * 1.001


def test_radial_stiffness_with_y_left_free_is_k_xx():
    """One ball on the load line leaves y free: a rounding-level K_yy (5e-23 against K_xx
    1.7e4) must not cancel K_xx in the Schur complement (it printed 0 or -3.6e-12 N/mm)."""
    from bearingload.numerics import radial_stiffness

    assert radial_stiffness(16706.9, 9e-10, 9e-10, 5e-23) == 16706.9
    assert radial_stiffness(4.0, 1.0, 1.0, 2.0) == 3.5
    from bearingload.models.high_speed import solve_high_speed

    r = solve_high_speed(
        9,
        10.0,
        ball_diameter=7.938,
        pitch_diameter=38.5,
        clearance=0.05,
        speed=20000.0,
        cage_angle=1e-11,
    )
    at_zero = solve_high_speed(
        9, 10.0, ball_diameter=7.938, pitch_diameter=38.5, clearance=0.05, speed=20000.0
    )
    assert float(r.stiffness_radial) == pytest.approx(float(at_zero.stiffness_radial), rel=1e-6)


def test_the_core_decides_a_load_too_small():
    """At the limit numpy's power and libm's pow may judge a load apart: the core's flag is the
    decision, the Python check only words it (this case was solved silently)."""
    from bearingload.errors import InputError
    from bearingload.models.combined import solve_combined

    with pytest.raises(InputError, match="too small for the combined solver"):
        solve_combined(
            9,
            1.844013100972762e-08,
            ball_diameter=6.015005001667222,
            pitch_diameter=38.5,
            clearance=0.0,
            stiffness=1e4,
        )
