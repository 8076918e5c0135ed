"""Angular contact under F_r with a thrust of some thousandths of it: every case converges.

Before the continuation in the thrust (:func:`bearingload.models.combined._thrust_retry`) some
such cases, at normal loads and at no particular cage angle, ended in a ConvergenceError
(relative residual 70.4, or some tens, after 2000 or 4000 steps): the minimisation stalled where
two or three balls carry the load, one at the kink of the one-sided contact, the Newton matrix
near-singular along a tilt (docs/angular_contact.md). The reproduction below, 28 of a 10 000-case
scan (``python -m tests.scan_angular_light thrust 10000``). Each answer is checked by plain
sums of the returned ball loads along the returned angles and by every ball load recomputed
from the returned ring position (helpers of tests/test_angular_light.py).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingload.models import combined
from bearingload.models.combined import solve_combined
from tests.scan_angular_light import thrust_case
from tests.test_angular_light import _plain_loads

REPRO = {"contact_angle": 14.439055688105743, "ball_diameter": 11.5, "pitch_diameter": 43.5}
FR, FA, CAGE = 2260.7821711195566, 2.958912605199692, 222.70139354956578


def _solve(case: dict, **kw):
    return solve_combined(
        case["z"], case["fr"], case["fa"], contact_angle=case["alpha"], cage_angle=case["cage"],
        ball_diameter=case["dw"], pitch_diameter=case["dm"], moment=case.get("moment"), **kw,
    )  # fmt: skip


def _plain_balance(r, fr: float, fa: float, moment: float) -> None:
    """F_r, F_y = 0, F_a and the moment (0 under a free tilt) from the returned ball loads and
    angles, summed exactly (math.fsum): within 1e-12 of the applied value, or of the solver's
    measure of a sum's rounding (64 eps of its terms' magnitudes, over 1e-12), beyond this
    sum's own rounding: 4 eps of its terms' magnitudes, and the angles returned in degrees
    (the ball angles up to 360°: 2 pi eps rad, times each ball's load, 8 times over). The
    latter matters for F_y, whose terms are small beside the loads (loaded balls near 0°)."""
    q = np.asarray(r.ball_loads, dtype=float)
    al, ph = np.radians(r.contact_angles), np.radians(r.ball_angles)
    arm = float(r.tilt_radius)
    sums = [
        (q * np.cos(al) * np.cos(ph), fr, 1.0),
        (q * np.cos(al) * np.sin(ph), 0.0, 1.0),
        (q * np.sin(al), fa, 1.0),
        (arm * q * np.sin(al) * np.cos(ph), moment, arm),
    ]
    for terms, wanted, unit in sums:
        size = float(np.abs(terms).sum())
        own = 4.4e-16 * size + 8 * 2 * math.pi * 2.2e-16 * unit * float(q.sum())
        err = abs(math.fsum(terms.tolist()) - wanted) - own
        assert err <= 1e-12 * max(abs(wanted), 64 * 2.2e-16 / 1e-12 * size)


def _check(case: dict, r) -> None:
    _plain_balance(r, case["fr"], case["fa"], case.get("moment", 0.0))
    _plain_loads(r, case["z"], case["alpha"], case["dw"], case["dm"])


def test_the_reported_case_converges():
    """5 balls at 14.4°, F_a/F_r = 0.0013, cage at 222.7°: was 'did not converge after 2016
    iterations (relative residual 70.4)'; F_a 0.5, 10 and 50 N solved."""
    r = solve_combined(5, FR, FA, cage_angle=CAGE, **REPRO)
    case = {"z": 5, "fr": FR, "fa": FA, "alpha": REPRO["contact_angle"], "dw": 11.5, "dm": 43.5}
    _check(case, r)
    assert int(r.loaded_balls) == 4 and float(np.min(r.contact_angles)) == 0.0
    # a neighbour that converged at once: its answer is close (the same balls carry the load)
    near = solve_combined(5, FR, 10.0, cage_angle=CAGE, **REPRO)
    np.testing.assert_allclose(r.ball_loads, near.ball_loads, rtol=0, atol=0.05 * FR)


def test_a_stage_that_stalls_is_halved():
    """6 balls at 19°, F_a/F_r = 8.1e-4, a tiny moment: 4000 steps at residual 27.9 before;
    with stages of 3 the one at 2.4e-3 stalled too, so the continuation must shorten its stage."""
    case = {"z": 6, "dw": 20.537162126852976, "dm": 68.45720708950992,
            "alpha": 18.985894544284932, "fr": 9228.95006624571, "fa": 7.490958855662277,
            "cage": 207.26248555495638, "moment": 0.06070396579916542}  # fmt: skip
    _check(case, _solve(case))


#: The 35 seeds of the ``thrust`` scan (tests/scan_angular_light.py, 10 000 cases) that raised
#: a ConvergenceError before the continuation (32 at residual 70.4, two 70.2, one 27.9).
FAILED_BEFORE = (
    495, 871, 925, 1436, 1815, 2053, 2313, 2324, 2771, 3117, 3481, 3782, 3976, 4191, 4324, 4632,
    4648, 5078, 5321, 5359, 5561, 5592, 5620, 5812, 6042, 6238, 6478, 7880, 8602, 8760, 9303,
    9436, 9536, 9697, 9790,
)  # fmt: skip


@pytest.mark.parametrize("seed", FAILED_BEFORE + tuple(range(1, 21)))
def test_a_grid_of_small_thrusts_converges(seed):
    """The cases that failed before and the first 20 of the scan (which did not)."""
    case = thrust_case(np.random.default_rng(seed))
    _check(case, _solve(case))


def test_a_retried_case_in_a_batch_is_the_case_alone():
    """The reproduction among cases that converge at once (and another retried one): each
    answer bit for bit that of the case alone."""
    fr = np.array([1000.0, FR, 500.0, FR, FR])
    fa = np.array([10.0, FA, 0.3, FA * 1.7, FA])
    cage = np.array([10.0, CAGE, 100.0, CAGE, 0.0])
    both = solve_combined(5, fr, fa, cage_angle=cage, **REPRO)
    for i in range(fr.size):
        alone = solve_combined(5, fr[i], fa[i], cage_angle=cage[i], **REPRO)
        for name in ("ball_loads", "contact_angles", "x", "y", "axial", "tilt", "tilt_cross"):
            assert np.array_equal(np.asarray(getattr(both, name))[i], getattr(alone, name))


def test_a_case_that_converges_at_once_is_not_retried(monkeypatch):
    """The continuation runs only for the cases whose first attempt does not converge."""
    calls = []
    original = combined._thrust_path
    monkeypatch.setattr(combined, "_thrust_path", lambda *a: calls.append(1) or original(*a))
    solve_combined(5, FR, 10.0, cage_angle=CAGE, **REPRO)
    assert not calls
    solve_combined(5, FR, FA, cage_angle=CAGE, **REPRO)
    assert len(calls) == 1
