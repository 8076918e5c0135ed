"""Numerical stability: every radial family of the reduced grid passes its figures; the
combined-load families are measured honestly (the harness is tested, and the figures that hold).

A family that fails here names the regression: its row says which figure broke (NaN, failures,
residual, a jump between neighbouring cases, batch dependence, or its own check).
"""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest

from bearingload.models.equilibrium import solve
from bearingload.quality import stability
from bearingload.quality import stability_combined as sc

from .cli_helpers import invoke, run_entry


@pytest.fixture(scope="module")
def rows():
    return {r["family"]: r for r in stability.run("quick")}


@pytest.mark.parametrize("family", stability.family_names())
def test_family_is_stable(rows, family):
    r = rows[family]
    name = f"{family} ({r['parameter']})"
    assert r["nan"] == 0, f"{name}: {r['nan']} cases with NaN/inf"
    assert r["failures"] == 0, f"{name}: {r['failures']} exceptions"
    assert r["warnings_raised"] == 0, f"{name}: {r['warnings_raised']} warnings"
    if not r["refusals_allowed"]:
        assert r["refused"] == 0, f"{name}: {r['refused']} cases refused"
    assert r["max_residual"] <= 1e-10, f"{name}: residual {r['max_residual']:.3g}"
    assert r["max_jump"] <= r["jump_limit"], (
        f"{name}: jump {r['max_jump']:.3g} per unit parameter from {r['jump_at']!r}"
    )
    assert r["batch_dependence"] <= 1e-12, f"{name}: batch dependence {r['batch_dependence']:.3g}"
    assert r["check_value"] <= r["check_limit"], (
        f"{name}: {r['check']} = {r['check_value']:.3g} > {r['check_limit']:.3g}"
    )


def test_every_family_runs_cases_or_its_check(rows):
    for r in rows.values():
        assert r["cases"] > 0 or r["check"] != "-"


def test_residual_is_recomputed_from_the_ball_loads():
    # a displaced solution must show a residual: the figure can fail
    r = solve(np.array([8, 8]), 1.0, 1.0, np.array([0.0, 2.0]), 7.0)
    good = stability._engine_residual(r)
    assert np.all(good < 1e-13)
    moved = dataclasses.replace(r, offset=r.offset * (1 + 1e-6))
    assert np.all(stability._engine_residual(moved) > 1e-7)


def test_jump_figure_sees_a_discontinuity():
    s = stability._series([0.0, 1e-10, 2e-10], False)
    k = np.array([1.0, 1.0, 1.5])
    out = stability.Outcome(
        k, np.ones((3, 2)), np.zeros(3), np.zeros(3, int), np.zeros((3, 1)), np.ones(3, bool)
    )
    assert stability._jump(s, out)[0] > 1e9 and stability._jump(s, out)[1] == 1e-10


def test_x_reference_of_heavy_preload():
    # solve(8, 1, 1, -2e12).x = 2 F/(z m K |e|^(m-1)) to first order (heavy preload)
    x = stability._x_reference(8, 1.0, 1.0, -2e12, 0.0, 1.5)
    assert x == pytest.approx(2.0 / (8 * 1.5 * 1e6), rel=1e-9)
    assert stability._x_reference(7, 1.0, 1.0, -6.14e82, 0.0, 1.0) == pytest.approx(2 / 7)


def test_stability_cli_json_rows(capsys):
    out = invoke("stability", "--family", "hertz_curvature", "--format", "json")
    assert out.exit_code == 0
    doc = json.loads(out.output)
    keys = {"family", "cases", "max_residual", "nan", "failures", "max_iterations"}
    assert list(doc) == ["radial"]
    assert [r["family"] for r in doc["radial"]["rows"]] == ["hertz_curvature"]
    assert keys <= set(doc["radial"]["rows"][0])
    code, _, err = run_entry(capsys, "stability", "--family", "nope")
    assert code == 2 and err.startswith("Error: Invalid value for '--family'")


# --------------------------------------------------------------------------- combined load


@pytest.fixture(scope="module")
def combined_rows():
    return {r["family"]: r for r in sc.run("quick")}


def _one(**kw):
    from bearingload.models.combined import solve_combined

    inputs = {k: np.atleast_1d(np.asarray(v, float)) for k, v in {**sc.GEOMETRY, **kw}.items()}
    return solve_combined(7, **inputs), inputs


def test_combined_families_run_and_report(combined_rows):
    assert list(combined_rows) == sc.family_names()
    for r in combined_rows.values():
        assert r["cases"] > 0 and r["warnings_raised"] == 0 and r["nan"] == 0
        # today every case is solved and meets the solver's tolerance on the largest load
        assert r["failures"] == 0, r["failure_reasons"]
        assert r["max_residual"] <= 1e-10 and r["residual_radial"] <= 1e-10
    assert set(combined_rows["combined_groove_limit"]) >= {"refusal_reasons", "check_value"}


def test_combined_refusals_are_counted_with_their_reason(combined_rows):
    r = combined_rows["combined_groove_limit"]
    # G_r = 2A and 2.2 A in each of the three series; with 500 N axial beside 1000 N radial and
    # a free tilt, clearances from 0.6 (2A) up drive a ball of the far side past the groove edge
    assert r["refused"] == 13
    text = r["refusal_reasons"]
    assert text.startswith("axial_load: the loads and the clearance drive a ball to a contact")
    # (a free ring: the refusal names the ways that solve it, the imposed tilt among them)
    edge_ways = "or impose the tilt with a misalignment (0: aligned) (x7); "
    assert edge_ways + "clearance: must be smaller than 2 (f_i + f_o - 1) D_w" in text
    assert text.endswith("leave the grooves axially (x6)")
    assert combined_rows["combined_preload"]["refusal_reasons"] == "-"


def test_combined_residuals_are_recomputed_from_the_ball_loads():
    for kw in (
        {"axial_load": 500.0},
        {"axial_load": 300.0, "moment": -2e4},
        {"axial_load": 200.0, "misalignment": 0.05},
    ):
        r, inputs = _one(radial_load=1000.0, clearance=0.01, **kw)
        assert np.all(sc.component_residuals(r, inputs) < 1e-10)
        assert np.all(sc.overall_residual(r, inputs) < 1e-10)
        # a displaced answer shows in every component it touches: the figure can fail
        moved = dataclasses.replace(r, ball_loads=r.ball_loads * (1 + 1e-6))
        res = sc.component_residuals(moved, inputs)[0]
        assert res[0] > 1e-7 and res[2] > 1e-7 and sc.overall_residual(moved, inputs)[0] > 1e-7
        tilted = dataclasses.replace(r, contact_angles=r.contact_angles + 1e-4)
        assert sc.component_residuals(tilted, inputs)[0, 2] > 1e-7


def test_combined_moment_residual_uses_the_reported_moment():
    r, inputs = _one(radial_load=1000.0, axial_load=500.0, clearance=0.01, misalignment=0.05)
    assert abs(float(r.moment[0])) > 1e3  # the moment the imposed tilt needs
    wrong = dataclasses.replace(r, moment=r.moment * 1.001)
    assert sc.component_residuals(wrong, inputs)[0, 3] > 1e-4


def test_combined_batch_dependence_is_seen(monkeypatch):
    """A solver whose array answer differs from its single answer shows in the figure."""
    real = sc._solve

    def skewed(series, index):
        out = real(series, index)
        if isinstance(index, np.ndarray):  # the array call
            out = dataclasses.replace(out, x=out.x * (1 + 1e-9))
        return out

    monkeypatch.setattr(sc, "_solve", skewed)
    row = sc.run("quick", ["combined_axial_both_ways"])[0]
    assert row["batch_dependence"] == pytest.approx(1e-9, rel=1e-3)


def test_combined_checks_see_what_they_test():
    class Fake:
        def __init__(self, tilt, angles):
            self.tilt = np.array([tilt])
            self.contact_angles = np.array([angles])

    series = [sc._series([0.0, 0.1], misalignment=np.array([0.0, 0.1]))]
    name, value, limit = sc._misalignment_check(series, [[Fake(0.2, [0.0]), None]])
    assert value == pytest.approx(0.2) and limit == 1e-12 and "misalignment" in name
    assert sc._angle_check(series, [[Fake(0.0, [10.0, 90.0, -95.0]), None]])[1] == 2.0


def test_stability_cli_both_tables_and_csv(capsys):
    out = invoke("stability", "--family", "hertz_curvature", "--family", "combined_preload",
                 "--format", "json")  # fmt: skip
    assert out.exit_code == 0
    doc = json.loads(out.output)
    assert isinstance(doc, dict) and list(doc) == ["radial", "combined"]  # one document
    assert [d["rows"][0]["family"] for d in doc.values()] == ["hertz_curvature", "combined_preload"]
    assert {"residual_axial", "residual_moment", "refusal_reasons"} <= set(
        doc["combined"]["rows"][0]
    )
    code, _, err = run_entry(capsys, "stability", "--family", "preload", "--family",
                             "combined_preload", "--format", "csv")  # fmt: skip
    assert code == 2 and err.startswith("Error: Invalid value for '--format': csv holds one table")
    help_text = invoke("stability", "--help").output
    assert "issue" not in help_text and "d1" not in help_text
