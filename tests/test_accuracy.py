"""The work-precision study (issue 9): reference, hand methods, figures and the command."""

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
from bearingload.studies.accuracy import measure, reference_cases

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
