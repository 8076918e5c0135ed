"""Numerical stability (issue 9): every family of the reduced grid passes its figures.

A family that fails here names the regression: its row says which figure broke (NaN, failures,
residual, a jump between neighbouring cases, batch dependence, or its own check).
"""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest

from bearingload.models.equilibrium import solve
from bearingload.studies import stability

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
    # solve(8, 1, 1, -2e12).x = 2 F/(z m K |e|^(m-1)) to first order (issue 9, defect 1)
    x = stability._x_reference(8, 1.0, 1.0, -2e12, 0.0, 1.5)
    assert x == pytest.approx(2.0 / (8 * 1.5 * 1e6), rel=1e-9)
    assert stability._x_reference(7, 1.0, 1.0, -6.14e82, 0.0, 1.0) == pytest.approx(2 / 7)


def test_stability_cli_json_rows(capsys):
    out = invoke("stability", "--family", "hertz_curvature", "--format", "json")
    assert out.exit_code == 0
    doc = json.loads(out.output)
    keys = {"family", "cases", "max_residual", "nan", "failures", "max_iterations"}
    assert [r["family"] for r in doc["rows"]] == ["hertz_curvature"]
    assert keys <= set(doc["rows"][0])
    code, _, err = run_entry(capsys, "stability", "--family", "nope")
    assert code == 2 and err.startswith("Error: Invalid value for '--family'")
