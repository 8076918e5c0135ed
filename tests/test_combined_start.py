"""Cases the compiled core's first versions failed where the numpy solver it replaced solved
them (found by the seeded campaigns): each must solve, balanced.

* The standard start for F_r: the core's own 2-D Newton on the radial model stopped at y = 0
  where the ring rested on one ball (its matrix singular across the load line), short of the
  radial engine's position: a 3-ball angular-contact case then ran 2007 steps to a residual of
  563 (tests.campaign_speed 1000 1). The start is regularised as the radial engine's now.
* A ring touching no ball at the start: the second-order correction of its line search is
  1e300 long; the approaches overflowed to NaN, which counted as no contact, and the move was
  taken (tests.campaign_combined 10000 1, two cases).
"""

from __future__ import annotations

import numpy as np
import pytest

from bearingload.models.combined import solve_combined


def _balanced(r, fr: float, fa: float, tol: float = 1e-10) -> None:
    q = np.asarray(r.ball_loads)
    al, ph = np.radians(r.contact_angles), np.radians(r.ball_angles)
    size = max(fr, abs(fa), float(q.sum()) * 1e-3)
    assert abs(float(np.sum(q * np.cos(al) * np.cos(ph))) - fr) <= tol * size
    assert abs(float(np.sum(q * np.sin(al))) - fa) <= tol * size
    assert np.all(np.isfinite(q)) and np.all(q >= 0)


def test_a_radial_start_on_one_ball_moves_across_to_the_equilibrium():
    fr, fa = 24.42751831817877, 3.0492195408853155
    r = solve_combined(
        3,
        fr,
        fa,
        ball_diameter=23.812,
        pitch_diameter=102.5,
        contact_angle=21.417134937218357,
        cage_angle=286.4198376859827,
    )
    _balanced(r, fr, fa)
    assert int(r.iterations) < 100


def test_a_ring_touching_no_ball_at_the_start_is_solved():
    for z, fa, g, moment, cross in [
        (
            3,
            -6.652022554627573e-09,
            0.024529646004166954,
            8.643019970619082e-08,
            6.164842382796672e-4,
        ),
        (6, 3.745607474620071e-12, 0.08481520002944597, 0.0, 2.39538725799815e-05),
    ]:
        r = solve_combined(
            z,
            0.0,
            fa,
            clearance=g,
            ball_diameter=3.0,
            pitch_diameter=14.0,
            moment=moment,
            moment_cross=cross,
        )
        q = np.asarray(r.ball_loads)
        assert np.all(np.isfinite(q)) and q.max() > 0
        assert abs(float(r.axial)) < 1.0 and abs(float(r.tilt_cross)) < 10.0


def test_a_case_whose_stiffness_updates_run_out_is_named(monkeypatch):
    """The error named nobody ('relative residual nan'); it names the failing case's inputs,
    and only that case of an array."""
    from bearingload.errors import ConvergenceError
    from bearingload.models import _core

    real = _core.combined_call  # (set-up, solve and results in one core call)

    def second_fails(*args, **kwargs):
        out = list(real(*args, **kwargs))
        status = out[1][7]  # (the solve's status among its answers_arrays)
        if status.size == 3:  # the second case's stiffness updates ran out
            status[1] = _core.Status.NOT_CONVERGED
            out[0] = _core.CallState.SOLVED
        return tuple(out)

    monkeypatch.setattr(_core, "combined_call", second_fails)
    try:
        solve_combined(9, [1000.0, 2000.0, 3000.0], 300.0, ball_diameter=7.938, pitch_diameter=38.5)
    except ConvergenceError as exc:
        message = str(exc)
    assert "radial_load = 2000 N" in message and "1000" not in message and "nan" not in message


def test_a_cross_moment_an_angular_bearing_cannot_hold_is_refused_with_the_tilt_imposed():
    import pytest

    from bearingload.errors import InputError

    kw = dict(ball_diameter=7.938, pitch_diameter=38.5, contact_angle=40.0)
    with pytest.raises(InputError) as info:
        solve_combined(12, 1000.0, 1.0, misalignment=0.0, moment_cross=500.0, **kw)
    assert info.value.parameter == "moment_cross"
    with pytest.raises(InputError) as info:
        solve_combined(12, 1000.0, 1.0, moment_cross=500.0, **kw)
    assert info.value.parameter == "moment_cross"
    r = solve_combined(12, 1000.0, 500.0, misalignment=0.0, moment_cross=500.0, **kw)
    assert np.all(np.asarray(r.ball_loads) >= 0)


def test_a_batch_row_that_fails_is_named_by_its_columns_as_given(monkeypatch, tmp_path, capsys):
    """A batch row's failure named the solver's inputs ('balls = 9, radial_load = 889.644 N',
    the clearance and cage angle it filled in); it names the row's columns and cells as given,
    as solve names its options."""
    from .cli_helpers import run_entry

    _stiffness_updates_fail(monkeypatch)
    path = tmp_path / "cases.csv"
    path.write_text("bearing,load [lbf],axial_load\n6205,200,300N\n", encoding="utf-8")
    code, _, err = run_entry(capsys, "batch", str(path), "--format", "csv")
    assert code == 1 and "for the case load = 200 lbf, axial_load = 300 N\n" in err, err
    _, _, solve = run_entry(capsys, "solve", "6205", "-F", "200lbf", "-A", "300N")
    assert solve.strip().endswith("for the case --load = 200 lbf, --axial-load = 300 N")


def _stiffness_updates_fail(monkeypatch):
    """Every case of the core's combined solve left with its stiffness updates run out."""
    from bearingload.models import _core

    real = _core.combined_call

    def fails(*args, **kwargs):
        out = list(real(*args, **kwargs))
        out[1][7][:] = _core.Status.NOT_CONVERGED
        out[0] = _core.CallState.SOLVED
        return tuple(out)

    monkeypatch.setattr(_core, "combined_call", fails)


def test_a_failure_at_speed_names_the_speed_as_given(monkeypatch, tmp_path, capsys):
    """The static start of the ball dynamics failing named the loads only, not the speed the
    case was solved at; it names it as typed (--speed 50Hz: 50 Hz), in solve and batch."""
    from .cli_helpers import run_entry

    _stiffness_updates_fail(monkeypatch)
    _, _, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--speed", "50Hz")
    assert "for the case --load = 1 kN, --speed = 50 Hz;" in err, err
    path = tmp_path / "cases.csv"
    path.write_text("bearing,load,speed\n6205,1kN,50Hz\n6205,1kN,3000\n", encoding="utf-8")
    _, _, err = run_entry(capsys, "batch", str(path), "--format", "csv")
    assert "row 2: combined-load" in err and "load = 1 kN, speed = 50 Hz;" in err, err
    assert "load = 1 kN, speed = 3000 rpm;" in err, err


def test_a_failure_among_mixed_speeds_names_the_speed_of_each_failing_case(monkeypatch):
    """The static start failing in some cases of a call with an array of speeds named their
    loads only (the speeds differ, so no one speed was added); it names each failing case's
    speed, and the failure's ``rows`` its cases by index."""
    from bearingload.errors import ConvergenceError
    from bearingload.models import _core
    from bearingload.models.high_speed import solve_high_speed

    real = _core.combined_call

    def second_fails(*args, **kwargs):  # case 1 of each call left unconverged
        out = list(real(*args, **kwargs))
        if out[1][7].size > 1:
            out[1][7][1] = _core.Status.NOT_CONVERGED
            out[0] = _core.CallState.SOLVED
        return tuple(out)

    monkeypatch.setattr(_core, "combined_call", second_fails)
    speeds = np.array([1000.0, 3000.0, 5000.0])
    with pytest.raises(ConvergenceError) as info:
        solve_high_speed(9, 1000.0, 300.0, speed=speeds, ball_diameter=7.938, pitch_diameter=38.5)
    assert info.value.rows.tolist() == [1]
    assert info.value.cases["speed"].tolist() == [3000.0]
    message = str(info.value)
    assert message.endswith(
        "radial_load = 1000 N, axial_load = 300 N, clearance = 0 mm, "
        "cage_angle = 0 °, speed = 3000 rpm"
    )
