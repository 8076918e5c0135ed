"""Edge cases: output files, extreme but finite inputs, huge angles, units."""

from __future__ import annotations

import itertools
import math
import os
import re
import stat
import subprocess
import tracemalloc
import warnings

import mpmath as mp
import numpy as np
import pytest
from click.testing import CliRunner

from bearingload.cli import main
from bearingload.errors import InputError
from bearingload.models.equilibrium import solve
from bearingload.reports.render import write_atomic
from bearingload.units import parse_stiffness

from .cli_helpers import run_process as run_cli


def test_write_follows_a_symlink(tmp_path):
    target = tmp_path / "target.txt"
    target.write_text("old")
    link = tmp_path / "link.txt"
    link.symlink_to(target)
    write_atomic("new\n", str(link))
    assert link.is_symlink()
    assert target.read_text() == "new\n"


def test_write_keeps_or_derives_permissions(tmp_path):
    new = tmp_path / "new.txt"
    old_umask = os.umask(0o022)
    try:
        write_atomic("a\n", str(new))
    finally:
        os.umask(old_umask)
    assert stat.S_IMODE(new.stat().st_mode) == 0o644
    new.chmod(0o640)
    write_atomic("b\n", str(new))
    assert stat.S_IMODE(new.stat().st_mode) == 0o640
    assert new.read_text() == "b\n"


def test_write_into_a_fifo_writes_through(tmp_path):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    reader = subprocess.Popen(["cat", str(fifo)], stdout=subprocess.PIPE, text=True)
    write_atomic("through\n", str(fifo))
    out, _ = reader.communicate(timeout=10)
    assert out == "through\n"
    assert stat.S_ISFIFO(fifo.stat().st_mode)


def test_dash_is_standard_output_and_empty_name_is_an_error(tmp_path):
    r = run_cli("table", "k", "--z-max", "2", "--format", "csv", "-o", "-", cwd=tmp_path)
    assert r.returncode == 0 and r.stdout.startswith(
        "method,load [N],stiffness [N/mm^1.5],clearance [mm],cage_angle [°],exponent,balls,loaded_balls,k\n"
    )
    assert list(tmp_path.iterdir()) == []
    r = run_cli("table", "k", "-o", "")
    assert r.returncode == 2 and r.stderr.startswith("Error: ") and r.stderr.count("\n") == 1


@pytest.mark.parametrize(
    "args, option",
    [
        (["solve", "-z", "8", "-F", "1e300", "-K", "1e-300"], "--load"),
        (["solve", "-z", "8", "-F", "1e-300", "-K", "1e300"], "--load"),
        (["solve", "-z", "8", "-K", "4e5", "-F", "1e300"], "--load"),
        (["solve", "-z", "8", "-K", "4e5", "-F", "100", "-G", "1e308"], "--clearance"),
        (["solve", "-z", "8", "-K", "4e5", "-F", "100", "-G", "-1e308"], "--clearance"),
        (["solve", "306", "-F", "1e-300"], "--load"),
        (["table", "k", "-G", "1e308"], "--clearance"),
        (["solve", "-z", "8", "-K", "4e5", "-F", "100", "--revolutions", "nan"], "--revolutions"),
        (["solve", "-z", "10", "-F", "5kN", "-K", "10N/um^1.5", "-m", "10/9"], "--stiffness"),
        (["solve", "-z", "10", "-F", "5kN", "-K", "10", "-m", "10/0"], "--exponent"),
    ],
)
def test_extreme_inputs_are_one_error_line(args, option):
    r = run_cli(*args)
    assert r.returncode == 2, r.stderr
    assert r.stderr.startswith(f"Error: Invalid value for '{option}'"), r.stderr
    assert r.stderr.count("\n") == 1, r.stderr
    assert r.stdout == ""


def test_a_huge_cage_angle_keeps_its_position():
    """Reduced in degrees before radians: 1e16° is 280° exactly."""
    big = solve(8, 100.0, 4e5, 0.0, 1e16)
    same = solve(8, 100.0, 4e5, 0.0, 280.0)
    assert float(big.q_max) == pytest.approx(float(same.q_max), rel=1e-13)
    assert float(big.q_max) == pytest.approx(float(big.ball_loads.max()), rel=1e-13)
    assert np.all((big.ball_angles >= 0) & (big.ball_angles < 360.0))


def test_roller_stiffness_units():
    assert parse_stiffness("3e5N/mm^(10/9)", 10 / 9) == 3e5
    assert parse_stiffness("2N/um^(10/9)", 10 / 9) == pytest.approx(2 * 1000 ** (10 / 9))
    assert parse_stiffness("4700kgf/mm^3/2", 1.5) == pytest.approx(4700 * 9.80665)
    with pytest.raises(InputError, match="exponent 1.5"):
        parse_stiffness("10N/um^1.5", 10 / 9)


def test_csv_headers_carry_units():
    out = (
        CliRunner()
        .invoke(
            main, ["solve", "-z", "8", "-F", "300kgf", "-K", "4700kgf/mm^1.5", "--format", "csv"]
        )
        .output
    )
    header = out.splitlines()[0]
    assert header.startswith(
        "bearing,method,balls,load [N],stiffness [N/mm^1.5],clearance [mm],clearance_pick,"
        "cage_angle [°]"
    )  # every key of the JSON case; bearing and clearance_pick blank for a ring given by hand
    assert (
        ",q_max [N]," in header and ",x [mm]," in header and ",stiffness_radial [N/mm]," in header
    )
    per_ball = CliRunner().invoke(
        main, ["solve", "-z", "8", "-F", "300kgf", "-K", "4700kgf/mm^1.5", "--format", "csv", "--per-ball"]
    ).output  # fmt: skip
    assert per_ball.splitlines()[0].endswith(
        ",ball,ball_angles [°],ball_approaches [mm],ball_loads [N]"
    )


def test_table_at_a_general_cage_angle_leaves_out_one_and_two_balls():
    out = CliRunner().invoke(main, ["table", "k", "--cage-angle", "10", "--z-max", "5"])
    assert out.exit_code == 0
    assert "z = 1 and 2 left out" in out.output
    r = solve(np.arange(3, 6), 1000.0, 1e5, 0.0, 10.0)
    assert f"{float(r.k[0]):.4g}" in out.output


def test_fit_rejects_a_falling_curve(tmp_path):
    f = tmp_path / "decr.csv"
    f.write_text("load,displacement\n100,1.5\n200,0.8\n400,0.2\n")
    r = run_cli("fit", str(f))
    assert r.returncode == 2
    assert "n = -0.688 <= 0" in r.stderr and r.stderr.count("\n") == 1


def test_fit_of_data_spanning_many_decades(tmp_path):
    f = tmp_path / "wide.csv"
    f.write_text("load,displacement\n1e-200,1e-200\n1e200,1e200\n")
    r = run_cli("fit", str(f), "--format", "json")
    assert r.returncode == 0, r.stderr
    assert '"n": 1.0' in r.stdout


def test_a_bearing_outside_the_catalogue_with_its_ball_set_resolves_a_class():
    out = CliRunner().invoke(
        main,
        ["solve", "6330", "-F", "1kN", "-G", "C3", "-z", "8", "--ball-diameter", "30",
         "--pitch-diameter", "225", "--format", "json"],
    )  # fmt: skip
    assert out.exit_code == 0, out.output
    import json

    doc = json.loads(out.output)
    # ISO 5753-1 C3, bore 140-160 mm (NSK 9.9)
    assert doc["bearing"]["clearance_range"] == [0.046, 0.091]
    assert doc["cases"][0]["clearance"] == pytest.approx(0.0685)


def test_a_clearance_of_half_a_ball_is_refused():
    r = run_cli("solve", "306", "-F", "300kgf", "-G", "20")
    assert r.returncode == 2
    assert "did you mean 20um?" in r.stderr and r.stderr.count("\n") == 1


# ---------------------------------------------------------------------------------------------
# Defects once found in the equilibrium engine, each against an independent
# mpmath solution written here (no code shared with bearingload.models).
# ---------------------------------------------------------------------------------------------
def _mp_ring(z, phi1_deg):
    phi1 = mp.radians(mp.mpf(phi1_deg))
    return [(mp.cos(phi1 + 2 * mp.pi * i / z), mp.sin(phi1 + 2 * mp.pi * i / z)) for i in range(z)]


def _mp_forces(ring, e, m, x, y):
    fx = fy = mp.mpf(0)
    for c, s in ring:
        d = x * c + y * s - e
        if d > 0:
            q = d**m
            fx, fy = fx + q * c, fy + q * s
    return fx, fy


def _mp_solve(z, e, m, phi1_deg, start, dps):
    """(x, y) at unit load and stiffness: mpmath Newton in ``dps`` digits from ``start``."""
    with mp.workdps(dps):
        ring = _mp_ring(z, phi1_deg)
        e, m = mp.mpf(e), mp.mpf(m)

        def eqs(x, y):
            fx, fy = _mp_forces(ring, e, m, x, y)
            return [fx - 1, fy]

        x, y = mp.findroot(eqs, (mp.mpf(start[0]), mp.mpf(start[1])), tol=mp.mpf(10) ** -50)
        return +x, +y


def _mp_stiffness(z, e, m, phi1_deg, x, y, dps):
    """Radial stiffness K_xx - K_xy^2/K_yy at unit stiffness, from the loaded balls, in mpmath."""
    with mp.workdps(dps):
        kxx = kxy = kyy = mp.mpf(0)
        for c, s in _mp_ring(z, phi1_deg):
            d = x * c + y * s - mp.mpf(e)
            if d > 0:
                dq = mp.mpf(m) * d ** (mp.mpf(m) - 1)
                kxx, kxy, kyy = kxx + dq * c * c, kxy + dq * c * s, kyy + dq * s * s
        return kxx - (kxy**2 / kyy if kyy > 0 else 0)


@pytest.mark.parametrize("ratio", [10.0**k for k in range(-12, 13, 2)] + [1e30, 1e60])
@pytest.mark.parametrize("cage", [0.0, 7.0])
def test_defect1_displacement_under_heavy_preload(ratio, cage):
    """x keeps ~1e-13 relative from e/s = -1e-12 to -1e60 (z = 12, m = 1.5): no cancellation."""
    r = solve(12, 1.0, 1.0, -2.0 * ratio, cage)
    dps = 60 + int(1.5 * max(0.0, math.log10(ratio)))
    x, y = _mp_solve(12, -ratio, 1.5, cage, (float(r.x), float(r.y)), dps)
    assert float(r.x) == pytest.approx(float(x), rel=2e-13)
    assert abs(float(r.y) - float(y)) <= 1e-13 * abs(float(x))


def test_defect1_reproductions():
    """solve(8, 1, 1, -2e12).x is +1.667e-7 (was -1.22e-4); m = 1 at e/s = 3e82: x = 2/7."""
    r = solve(8, 1.0, 1.0, -2e12)
    x, _ = _mp_solve(8, -1e12, 1.5, 0.0, (float(r.x), 0.0), 80)
    assert float(r.x) == pytest.approx(float(x), rel=1e-13)
    assert float(r.x) == pytest.approx(1.667e-7, rel=1e-3)
    assert float(solve(7, 1.0, 1.0, -6.14e82, 0, 1.0).x) == pytest.approx(2 / 7, rel=1e-14)


@pytest.mark.parametrize("size", [1e155, 1e-300, 1.0])
def test_defect2_radial_stiffness_in_scaled_units(size):
    """solve(9, 1e155, 1e155, 6, 13).stiffness_radial = 2.0438e155 (was -inf); 1e-300 exact too."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = solve(9, size, size, 6.0, 13.0)
    x, y = _mp_solve(9, 3.0, 1.5, 13.0, (float(r.x), float(r.y)), 40)
    k = _mp_stiffness(9, 3.0, 1.5, 13.0, x, y, 40) * mp.mpf(size)
    assert float(r.stiffness_radial) == pytest.approx(float(k), rel=1e-12)
    if size == 1e155:
        assert float(r.stiffness_radial) == pytest.approx(2.0438e155, rel=1e-4)


def test_defect3_heavy_preload_is_solved_or_refused():
    """solve(8, 1, 1, -2e62, 10, 3.0) is solved (was ConvergenceError); 1e397 N is refused."""
    r = solve(8, 1.0, 1.0, -2e62, 10.0, 3.0)
    x, y = _mp_solve(8, -1e62, 3, 10.0, (float(r.x), float(r.y)), 260)
    assert float(r.x) == pytest.approx(float(x), rel=1e-12)
    with mp.workdps(260):
        ring = _mp_ring(8, 10.0)
        q = max((x * c + y * s + mp.mpf(10) ** 62) ** 3 for c, s in ring)
    assert float(r.q_max) == pytest.approx(float(q), rel=1e-12)
    with pytest.raises(InputError, match="clearance") as err:
        solve(8, 1e100, 1e100, -2e99, 0, 3.0)
    assert "1e397 N" in str(err.value)


def test_defect3_extreme_grid_never_inf_nan_or_a_convergence_error():
    """Every accepted extreme case is finite; every refused one is an InputError."""
    refused = solved = 0
    for f, k, g, cage, m in itertools.product(
        [1e-300, 1e-50, 1.0, 1e100, 1e300],
        [1e-300, 1.0, 1e300],
        [-1e200, -1e60, -1e-10, 0.0, 1e-10, 1e60],
        [0.0, 10.0],
        [1.0, 1.5, 3.0],
    ):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                r = solve(8, f, k, g, cage, m)
        except InputError:
            refused += 1
            continue
        solved += 1
        for name in ("x", "y", "q_max", "load_zone", "stiffness_radial"):
            assert np.isfinite(float(getattr(r, name))), (f, k, g, cage, m, name)
        assert float(r.q_max) > 0 and float(r.stiffness_radial) > 0
    assert solved > 100 and refused > 50


def test_defect4_memory_is_bounded_by_chunks():
    """20 000 symmetric cases at z = 2000 stay under 64 MB of numpy temporaries (chunked)."""
    n = 20_000
    load = np.geomspace(1.0, 1e4, n)
    tracemalloc.start()
    try:
        r = solve(2000, load, 1e5, 0.001)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 64e6
    assert np.all(np.isfinite(r.q_max))


def test_defect4_a_case_gives_the_same_bits_alone_or_in_a_batch():
    """The engine is a C loop over cases, each from its own data: a case's answer alone is the
    same bits as in a batch of mixed ball counts, cage kinds and preloads (it was chunked)."""
    z = np.array([9, 9, 40, 40, 7, 7, 200])
    g = np.array([0.0, -0.01, 0.02, 0.0, -1e-3, 0.05, 0.001])
    cage = np.array([0.0, 20.0, 4.5, 0.0, 11.0, 25.0, 0.9])
    whole = solve(z, 1000.0, 1e5, g, cage)
    for i in range(z.size):
        one = solve(np.array([z[i]]), 1000.0, 1e5, g[i], cage[i])
        alone = solve(int(z[i]), 1000.0, 1e5, float(g[i]), float(cage[i]))
        for name in ("x", "y", "q_max", "loaded_balls", "stiffness_matrix", "iterations"):
            assert np.array_equal(getattr(whole, name)[i], getattr(one, name)[0])
            assert np.array_equal(getattr(whole, name)[i], getattr(alone, name))


def _mp_two_balls(z, e, m, eps_deg):
    """Cage at eps: balls 1 (eps) and z (eps - pitch) carry. Closed form in mpmath: (x, y, Q1)."""
    a, b = mp.radians(mp.mpf(eps_deg)), mp.radians(mp.mpf(eps_deg)) - 2 * mp.pi / z
    # Q1 (cos a, sin a) + Q2 (cos b, sin b) = (1, 0)
    det = mp.cos(a) * mp.sin(b) - mp.cos(b) * mp.sin(a)
    q1, q2 = mp.sin(b) / det, -mp.sin(a) / det
    d1, d2 = q1 ** (1 / mp.mpf(m)), q2 ** (1 / mp.mpf(m))
    # x cos + y sin = d + e for both balls
    det2 = mp.cos(a) * mp.sin(b) - mp.sin(a) * mp.cos(b)
    x = ((d1 + e) * mp.sin(b) - (d2 + e) * mp.sin(a)) / det2
    y = (mp.cos(a) * (d2 + e) - mp.cos(b) * (d1 + e)) / det2
    # transverse stiffness: y is known only to (rounding of the forces)/k_yy
    k_yy = 1.5 * (mp.sqrt(d1) * mp.sin(a) ** 2 + mp.sqrt(d2) * mp.sin(b) ** 2)
    return x, y, q1, k_yy


@pytest.mark.parametrize("eps", [1e-12, 1e-11, 1e-9, 1e-6, 1e-3])
def test_defect5_near_symmetry_continuous_from_both_sides(eps):
    """One ball loaded at cage 0 (z = 8, G = 20, F = K = 1): off symmetry by eps (either side)
    the general solution is solved (not snapped): y -> -+Y, x and Q_max continuous.

    Near the end of the segment the second ball carries ~eps of the load and the transverse
    stiffness k_yy -> 0, so y is determined only to (force rounding)/k_yy: that is its bound.
    """
    with mp.workdps(50):
        x, y, q1, k_yy = _mp_two_balls(8, mp.mpf(10), 1.5, eps)
    y_tol = 64 * 2.2e-16 / float(k_yy) + 1e-13 * abs(float(y))
    for sign in (1, -1):
        r = solve(8, 1.0, 1.0, 20.0, sign * eps)
        assert float(r.x) == pytest.approx(float(x), rel=1e-13)
        assert abs(float(r.y) - sign * float(y)) <= y_tol
        assert float(r.q_max) == pytest.approx(float(q1), rel=1e-12)
        assert int(r.loaded_balls) == 2
    at0 = solve(8, 1.0, 1.0, 20.0, 0.0)
    assert float(at0.y) == 0.0 and int(at0.loaded_balls) == 1
    assert float(at0.x) == pytest.approx(float(x), rel=1e-9 if eps < 1e-8 else 1e-3)


def test_defect5_rounding_of_a_symmetric_angle_is_symmetric():
    """180/7 and 3*360/7 computed in floating point are the symmetric positions."""
    for z, cage in ((7, 180 / 7), (7, 3 * 360 / 7), (9, -360 / 9), (8, 1e-13), (8, -1e-13)):
        assert float(solve(z, 1.0, 1.0, 20.0, cage).y) == 0.0


def test_defect6_a_case_does_not_depend_on_its_batch():
    """Each case alone (as a 1-element array) and in shuffled batches: bit-identical results."""
    rng = np.random.default_rng(7)
    n = 60
    z = np.concatenate([[2000], rng.integers(3, 60, n - 1)])
    load = np.concatenate([[23.839033635393225], 10 ** rng.uniform(-2, 4, n - 1)])
    g = np.concatenate([[2.0], rng.choice([0.0, 1e-3, -1e-3, 0.02, -1e3], n - 1)])
    cage = np.concatenate(
        [[0.0], np.where(rng.random(n - 1) < 0.5, 0.0, rng.uniform(0, 360, n - 1))]
    )
    m = np.concatenate([[1.0], rng.choice([1.0, 1.5, 10 / 9], n - 1)])
    stiffness = np.where(np.arange(n) == 0, 1.0, 1e5)
    names = ("x", "y", "q_max", "loaded_balls", "stiffness_radial", "load_zone", "iterations")
    alone = [solve(z[i : i + 1], load[i], stiffness[i], g[i], cage[i], m[i]) for i in range(n)]
    for seed in range(3):
        perm = np.random.default_rng(seed).permutation(n)
        batch = solve(z[perm], load[perm], stiffness[perm], g[perm], cage[perm], m[perm])
        for j, i in enumerate(perm):
            for name in names:
                assert getattr(batch, name)[j] == getattr(alone[i], name)[0], (i, name)
    # 299 balls carry (mpmath: the next pair misses by 1.7e-18)
    assert int(alone[0].loaded_balls[0]) == 299
    assert float(alone[0].stiffness_radial[0]) == pytest.approx(277.96473747, rel=1e-9)


def test_defect7_load_zone_at_huge_clearance_and_many_balls():
    """z = 100 000, e/s = 1e12: the load zone to ~1e-13 (was 1.5e-7), ball under or between."""
    with mp.workdps(50):
        e = mp.mpf(10) ** 12
        zone0 = mp.degrees(mp.acos(e / (e + 1)))  # one ball carries: x = e + s
        h = mp.pi / 100_000
        x_half = (e + (1 / (2 * mp.cos(h))) ** (mp.mpf(2) / 3)) / mp.cos(h)
        zone_half = mp.degrees(mp.acos(e / x_half))
    r = solve(100_000, 1.0, 1.0, 2e12, [0.0, 180 / 100_000])
    assert float(r.load_zone[0]) == pytest.approx(float(zone0), rel=1e-13)
    assert float(r.load_zone[1]) == pytest.approx(float(zone_half), rel=1e-13)


@pytest.mark.parametrize(
    "args, name",
    [
        (([], 1.0, 1.0), "balls"),
        ((8, np.array([]), 1.0), "load"),
        ((8, 1.0, 1.0, np.zeros((0, 2))), "clearance"),
        (([8, 9], [1.0, 2.0, 3.0], 1.0), "load"),
        (([8, 9], 1.0, 1.0, 0.0, [0.0, 1.0, 2.0]), "cage_angle"),
    ],
)
def test_defect8_empty_and_mismatched_inputs_are_input_errors(args, name):
    with pytest.raises(InputError) as err:
        solve(*args)
    assert err.value.parameter == name


@pytest.mark.parametrize(
    "args, text",
    [
        ((8.0000000001, 1.0, 1.0), "8.0000000001"),
        ((8, -1.25e-7, 1.0), "-1.25e-07"),
        ((8, 1.0, 1.0, 0.0, 0.0, 3.0000001), "3.0000001"),
        ((100_001, 1.0, 1.0), "100001"),
    ],
)
def test_defect8_messages_show_the_value_unrounded(args, text):
    with pytest.raises(InputError, match=re.escape(text)):
        solve(*args)


def test_scalar_path_agrees_with_the_vectorised_path():
    """One case from Python (a batch of one in the core) and the same case in an array: the
    same bits (the one-case path was pure Python and agreed to ~1e-14)."""
    rng = np.random.default_rng(11)
    for _ in range(400):
        z = int(rng.integers(1, 60))
        f, k = 10 ** rng.uniform(-2, 4), 10 ** rng.uniform(3, 6)
        g = float(rng.choice([0.0, 10 ** rng.uniform(-6, 0), -(10 ** rng.uniform(-7, 0))]))
        cage = float(rng.choice([0.0, 180 / z, rng.uniform(-400, 400)])) if z >= 3 else 0.0
        m = float(rng.choice([1.5, 10 / 9, 1.0, 3.0]))
        a, b = solve(z, f, k, g, cage, m), solve(np.array([z]), f, k, g, cage, m)
        assert type(a.x) is float and type(a.loaded_balls) is int  # scalar in, scalar out
        assert int(a.loaded_balls) == int(b.loaded_balls[0])
        for name in ("x", "y", "q_max", "stiffness_radial", "load_zone", "iterations"):
            assert float(getattr(a, name)) == float(getattr(b, name)[0]), name
        np.testing.assert_array_equal(a.stiffness_matrix, b.stiffness_matrix[0])
        np.testing.assert_array_equal(a.ball_loads, b[0].ball_loads)
