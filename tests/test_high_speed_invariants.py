"""The ball dynamics' answers on a stored random set (tests/fixtures/high_speed_invariants.json,
written by benchmarks/make_speed_invariants.py with the code of 2026-11-28 before the one-case
speed-ups): a change meant to leave the numbers alone keeps them to 1e-12 relative. Each case
alone and the set as one array (no case's answer depends on the others)."""

from __future__ import annotations

import json
import pathlib

import numpy as np
import pytest

from bearingload.models.high_speed import solve_high_speed

DATA = json.loads(
    (pathlib.Path(__file__).parent / "fixtures" / "high_speed_invariants.json").read_text()
)
CASES = DATA["cases"]
TOL = 1e-12


def check(case: dict, got: dict) -> None:
    """Positions to 1e-12 of the largest, loads of the largest load, angles of 90°."""
    scale = max(abs(case["x"][0]), abs(case["axial"][0]))
    for key in ("x", "axial", "tilt"):
        assert abs(float(np.ravel(got[key])[0]) - case[key][0]) <= TOL * scale, key
    q = max(case["ball_loads_outer"])
    for key in ("ball_loads_inner", "ball_loads_outer"):
        np.testing.assert_allclose(got[key], case[key], rtol=0, atol=TOL * q, err_msg=key)
    for key in ("contact_angles_inner", "contact_angles_outer"):
        np.testing.assert_allclose(got[key], case[key], rtol=0, atol=TOL * 90.0, err_msg=key)


@pytest.mark.parametrize("k", range(len(CASES)))
def test_each_case_alone_keeps_its_stored_answer(k):
    case = CASES[k]
    r = solve_high_speed(case["z"], case["fr"], case["fa"], **case["kw"])
    check(
        case, {key: np.ravel(getattr(r, key)) for key in case if key not in ("z", "fr", "fa", "kw")}
    )


def test_the_set_as_one_array_keeps_the_stored_answers():
    for z in (9, 13):
        rows = [c for c in CASES if c["z"] == z]
        keys = sorted(rows[0]["kw"])
        kw = {k: np.array([c["kw"][k] for c in rows]) for k in keys}
        fr, fa = (np.array([c[k] for c in rows]) for k in ("fr", "fa"))
        r = solve_high_speed(z, fr, fa, **kw)
        for i, case in enumerate(rows):
            check(case, {key: np.atleast_1d(getattr(r, key)[i]) for key in
                         ("x", "axial", "tilt", "ball_loads_inner", "ball_loads_outer",
                          "contact_angles_inner", "contact_angles_outer")})  # fmt: skip
