"""The work-precision study: references, hand methods, the combined solver, figures and the command."""

from __future__ import annotations

import json

import mpmath as mp
import numpy as np
import pytest

from bearingload.models.equilibrium import solve
from bearingload.models.hand import (
    TABLE_EPSILON,
    TABLE_JR,
    kuzmenko2010_trial,
    load_zone_table_k,
)
from bearingload.quality import accuracy
from bearingload.quality.accuracy import measure, reference_cases

from .cli_helpers import invoke, run_entry


def _mp_k(z: int, load: float, stiffness: float, clearance: float, cage_deg: float) -> mp.mpf:
    """k of the symmetric ring by mpmath's bracketing Anderson-Bjorck solver at 40 digits
    (written here, independent of benchmarks/make_reference.py and of the package)."""
    with mp.workdps(40):
        e = mp.mpf(clearance) / 2
        phis = [mp.radians(mp.mpf(cage_deg)) + 2 * mp.pi * i / z for i in range(z)]
        cos = [mp.cos(p) for p in phis]

        def force(x):
            return sum(
                (mp.mpf(stiffness) * (x * c - e) ** mp.mpf(1.5) * c for c in cos if x * c > e),
                mp.mpf(0),
            ) - mp.mpf(load)

        lo = max(e, mp.mpf(0))
        hi = lo + 1
        while force(hi) < 0:
            hi *= 2
        x = mp.findroot(force, (lo, hi), solver="anderson", tol=mp.mpf(10) ** -38)
        return mp.mpf(stiffness) * (x * max(cos) - e) ** mp.mpf(1.5) / mp.mpf(load)


def test_reference_fixture_rechecked_with_mpmath():
    cases = reference_cases()
    assert len(cases) == 50
    for i in (0, 7, 14, 23, 36, 49):  # every clearance and both cage angles among them
        k = _mp_k(
            int(cases.balls[i]),
            float(cases.load[i]),
            float(cases.stiffness[i]),
            float(cases.clearance[i]),
            float(cases.cage_angle[i]),
        )
        assert abs(cases.k_reference[i] / float(k) - 1.0) < 1e-15


def test_reference_cases_are_the_documented_grid():
    c = reference_cases()
    assert sorted(set(c.balls.tolist())) == [6, 8, 12, 20, 40]
    assert sorted(set(c.clearance.tolist())) == [-0.02, 0.0, 0.02, 0.1, 0.4]
    assert set(np.round(c.cage_angle * c.balls, 9).tolist()) == {0.0, 180.0}
    assert np.all(c.load == 300 * 9.80665) and np.all(c.stiffness == 4700 * 9.80665)


def test_exact_solver_agrees_with_the_reference():
    c = reference_cases()
    r = solve(c.balls, c.load, c.stiffness, c.clearance, c.cage_angle)
    assert np.max(np.abs(r.k / c.k_reference - 1.0)) < 1e-12


def test_printed_jr_table_is_the_integral_rounded():
    # J_r(eps) = 1/pi int_0^psi_l (1 - (1 - cos psi)/(2 eps))^(3/2) cos psi dpsi (Harris eq. 7.22)
    with mp.workdps(30):
        for eps, printed in zip(TABLE_EPSILON[1:], TABLE_JR[1:], strict=True):
            e = mp.mpf(eps)
            limit = mp.acos(1 - 2 * e) if e <= 1 else mp.pi

            def integrand(p, e=e):
                return max(1 - (1 - mp.cos(p)) / (2 * e), 0) ** 1.5 * mp.cos(p)

            jr = mp.quad(integrand, [0, limit]) / mp.pi
            assert abs(float(jr) - printed) <= 0.5e-4 + 1e-12


def test_trial_reproduces_the_paper_and_converges_with_the_step():
    # Kuzmenko (2010, §3.4): phi0 = 85.2 deg accepted, Q0 = 170.3 kgf
    r = kuzmenko2010_trial(8, 300.0, 4700.0, 0.02, step=0.1, rounding="up")
    assert r.angle == pytest.approx(85.2) and round(r.q_max, 1) == 170.3
    exact = float(solve(8, 300.0, 4700.0, 0.02).k)
    errors = [
        abs(kuzmenko2010_trial(8, 300.0, 4700.0, 0.02, step=s).k / exact - 1)
        for s in (1, 0.1, 0.01)
    ]
    assert errors[0] > errors[1] > errors[2] and errors[2] < 1e-3
    assert kuzmenko2010_trial(8, 300.0, 4700.0, 0.02, step=1e-6).k == pytest.approx(exact, rel=1e-6)


def test_table_method_at_zero_clearance_and_its_range():
    assert load_zone_table_k(10, 1.0, 1.0).k == pytest.approx(1 / (10 * 0.2288))
    from bearingload.errors import InputError

    with pytest.raises(InputError, match="beyond the table"):
        load_zone_table_k(10, 1.0, 1.0, -100.0)


def test_work_precision_figures():
    rows = {(r["method"], r["setting"]): r for r in measure()}
    exact = [rows[("exact", f"tolerance {t:.0e}")]["error_max"] for t in (1e-2, 1e-6, 1e-10, 1e-14)]
    assert exact[0] > exact[1] > exact[2] > exact[3]
    for t in (1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-13, 1e-14):
        # the error of Q_max stays within a few times the residual tolerance (or rounding)
        assert rows[("exact", f"tolerance {t:.0e}")]["error_max"] <= max(3 * t, 1e-14)
    assert rows[("trial", "phi0 step 1 deg")]["cases"] == 30
    stribeck = rows[("stribeck", "4.37/z")]
    assert 0.01 < stribeck["error_median"] < stribeck["error_max"] < 1.0
    for r in rows.values():
        assert 0 <= r["error_median"] <= r["error_max"] and np.isfinite(r["error_max"])


def test_accuracy_json_rows_carry_the_keys():
    out = invoke("accuracy", "--format", "json", "--repeats", "1")
    assert out.exit_code == 0
    doc = json.loads(out.output)
    keys = {
        "method",
        "error_median",
        "error_max",
        "seconds_per_case",
        "seconds_per_case_vectorised",
        "iterations",
    }
    assert all(keys <= set(row) for row in doc["rows"])
    assert all(row["seconds_per_case"] > 0 for row in doc["rows"])


def test_accuracy_plot_or_a_clean_error(tmp_path, capsys):
    target = tmp_path / "wp.png"
    code, out, err = run_entry(capsys, "accuracy", "--repeats", "1", "--plot", str(target))
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        assert code == 2 and err.startswith("Error: ") and "matplotlib" in err
        assert not target.exists()
    else:
        assert code == 0 and target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_accuracy_bad_option_is_one_error_line(capsys):
    code, out, err = run_entry(capsys, "accuracy", "--no-timing", "--plot", "x.png")
    assert code == 2 and err.count("\n") == 1 and "--plot" in err


# --------------------------------------------------------------------------- combined load


def _mp_ball_stiffness(alpha, case):
    """K(alpha) of both Hertz contacts in series at 30 digits, written here from Johnson (1985,
    §4.2): the ellipticity k solves (B/A) = k^2 (E(m) - (1 - m) K(m))/(K(m) - E(m)), m = 1 - 1/k^2,
    and delta* = (2 K/pi) (pi/(2 k^2 E))^(1/3) (Harris & Kotzalas ch. 6)."""
    dw, fi, fo = (mp.mpf(case[k]) for k in ("ball_diameter", "f_i", "f_o"))
    dm = mp.mpf(case["pitch_diameter"]) / mp.cos(alpha)
    e_star = mp.mpf(case["modulus"]) / (2 * (1 - mp.mpf(case["poisson"]) ** 2))
    total_k = []
    for rho_x, rho_y in (
        (2 * dm / (dw * (dm - dw)), (2 * fi - 1) / (fi * dw)),
        (2 * dm / (dw * (dm + dw)), (2 * fo - 1) / (fo * dw)),
    ):
        ratio = max(rho_x, rho_y) / min(rho_x, rho_y)

        def johnson(t, ratio=ratio):
            k2 = mp.exp(2 * t)
            m = 1 - 1 / k2
            return (
                k2 * (mp.ellipe(m) - (1 - m) * mp.ellipk(m)) / (mp.ellipk(m) - mp.ellipe(m)) - ratio
            )

        t = mp.findroot(johnson, mp.log(ratio) / 3)
        k2 = mp.exp(2 * t)
        m = 1 - 1 / k2
        d_star = 2 * mp.ellipk(m) / mp.pi * mp.cbrt(mp.pi / (2 * k2 * mp.ellipe(m)))
        total_k.append(4 * mp.sqrt(2) / 3 * e_star / (d_star**1.5 * mp.sqrt(rho_x + rho_y)))
    return (total_k[0] ** (-mp.mpf(2) / 3) + total_k[1] ** (-mp.mpf(2) / 3)) ** (-mp.mpf(3) / 2)


def _mp_equilibrium_miss(case, state):
    """Largest miss of the five equilibrium equations at the stored state, over the load."""
    z, e = case["balls"], mp.mpf(case["clearance"]) / 2
    dw, fi = mp.mpf(case["ball_diameter"]), mp.mpf(case["f_i"])
    big_a = (fi + mp.mpf(case["f_o"]) - 1) * dw
    alpha0 = mp.acos(1 - e / big_a) if e > 0 else mp.mpf(0)
    arm = mp.mpf(case["pitch_diameter"]) / 2 + (fi - mp.mpf(1) / 2) * dw * mp.cos(alpha0)
    x, y, a = (mp.mpf(state[k]) for k in ("x [mm]", "y [mm]", "axial [mm]"))
    th, tc = (mp.radians(mp.mpf(state[k])) for k in ("tilt [°]", "tilt_cross [°]"))
    sums = [mp.mpf(0)] * 5
    q_max = mp.mpf(0)
    for j in range(z):
        phi = mp.radians(mp.mpf(case["cage_angle"])) + 2 * mp.pi * j / z
        rho = big_a - e + x * mp.cos(phi) + y * mp.sin(phi)
        u = a + arm * (th * mp.cos(phi) + tc * mp.sin(phi))
        delta = mp.sqrt(rho**2 + u**2) - big_a
        if delta <= 0:
            continue
        alpha = mp.atan2(u, rho)
        q = _mp_ball_stiffness(alpha, case) * delta**1.5
        q_max = max(q_max, q)
        axial = q * mp.sin(alpha)
        for i, term in enumerate(
            (q * mp.cos(alpha) * mp.cos(phi), q * mp.cos(alpha) * mp.sin(phi), axial,
             arm * axial * mp.cos(phi), arm * axial * mp.sin(phi))
        ):  # fmt: skip
            sums[i] += term
    applied = [case["radial_load"], 0, case["axial_load"], mp.mpf(state["moment_out [N mm]"]), 0]
    load = max(case["radial_load"], abs(case["axial_load"]))
    miss = [abs(s - mp.mpf(f)) / (load * (arm if i >= 3 else 1)) for i, (s, f) in
            enumerate(zip(sums, applied, strict=True))]  # fmt: skip
    return max(miss), q_max


def test_combined_reference_solves_the_model_at_30_digits():
    """Every stored state balances the loads to 1e-25 of the load in an mpmath evaluation of the
    model written here (Johnson's form of the ellipticity, not Harris's of the generator), and
    its Q_max is the stored one; with a moment given the stored moment is the applied one."""
    import csv

    with open(accuracy.COMBINED_REFERENCE_FILE, encoding="utf-8", newline="") as fh:
        stored = list(csv.DictReader(fh))
    cases = accuracy.combined_cases()
    assert len(cases) == len(stored) == 12
    with mp.workdps(34):
        for case, state in zip(cases, stored, strict=True):
            miss, q_max = _mp_equilibrium_miss(case, state)
            assert miss < 1e-25, case["label"]
            assert abs(q_max / mp.mpf(state["q_max [N]"]) - 1) < 1e-25, case["label"]
            if case["misalignment"] is None:
                assert float(state["moment_out [N mm]"]) == case["moment"]
            else:
                assert float(state["tilt [°]"]) == pytest.approx(case["misalignment"], abs=1e-15)


def test_combined_rows_of_the_report():
    rows = {r["setting"]: r for r in measure() if r["method"] == "combined"}
    assert list(rows) == list(accuracy.COMBINED_GROUPS)
    assert [r["cases"] for r in rows.values()] == [5, 5, 2]
    # with clearance and under preload the solver meets its reference (today: 2e-12, 3e-13)
    assert rows["Hertz K(alpha), with clearance"]["error_max"] < 1e-9
    assert rows["Hertz K(alpha), preload"]["error_max"] < 1e-9
    for r in rows.values():
        assert 0 <= r["error_median"] <= r["error_max"] and r["iterations"] > 0


def test_combined_error_counts_one_case_per_call(monkeypatch):
    """An answer that differs alone from in the group shows in the error."""
    real = accuracy._run_combined

    def alone_off(cases, copies=1):
        q, its = real(cases, copies)
        return (q * (1 + 1e-6) if len(cases) * copies == 1 else q), its

    monkeypatch.setattr(accuracy, "_run_combined", alone_off)
    rows = accuracy.measure_combined()
    assert min(r["error_max"] for r in rows) >= 0.9e-6
