"""The failure of a solve or a sweep names the inputs as the case names them
(:func:`bearingload.plan.solve.in_case_terms`)."""

from bearingload.errors import ConvergenceError
from bearingload.plan.case import Case
from bearingload.plan.solve import in_case_terms


def _failure(cage: list[float]) -> ConvergenceError:
    cases = {"radial_load": [100.0] * len(cage), "cage_angle": cage}
    return ConvergenceError("combined", 50, 1e-8, cases, {"radial_load": "N", "cage_angle": "°"})


def test_a_solve_names_its_cage_angle_as_given():
    case = Case.of({"load": 100.0, "cage_angle": -10.0})
    out = in_case_terms(_failure([350.0]), case)
    assert out.cases["load"] == [100.0]
    assert out.cases["cage_angle"] == -10.0


def test_a_sweep_names_the_cage_angle_it_failed_at():
    """A sweep solves other cage angles than its case's (0): the failing one is named."""
    case = Case.of({"load": 100.0})
    out = in_case_terms(_failure([15.0]), case, cage_given=False)
    assert list(out.cases["cage_angle"]) == [15.0]


def test_a_failure_names_only_the_inputs_the_user_gave():
    """The solver's defaults (a moment of 0, a clearance of 0 it filled in) are not named."""
    cases = {"radial_load": [100.0], "moment": [0.0], "clearance": [0.0], "cage_angle": [0.0]}
    exc = ConvergenceError("combined", 50, 1e-8, cases, {"radial_load": "N", "moment": "N mm"})
    out = in_case_terms(exc, Case.of({"load": 100.0}))
    assert out.cases == {"load": [100.0]} and out.units == {"load": "N"}


def test_a_failure_at_speed_gives_the_units_of_its_inputs():
    """The ball dynamics' failure names its inputs with units, as the static solvers' do."""
    from types import SimpleNamespace

    import numpy as np
    import pytest

    from bearingload.models import high_speed

    state = SimpleNamespace(accepted=np.array([False]), merit=np.array([1e-8]))
    flat = {"radial_load": np.array([100.0]), "speed": np.array([3000.0])}
    with pytest.raises(ConvergenceError) as info:
        high_speed.check_balanced("ball dynamics", state, np.array([551]), flat)
    assert info.value.units["radial_load"] == "N" and info.value.units["speed"] == "rpm"


def test_an_input_given_with_a_unit_is_written_as_typed():
    """A failure writes a load given as 0.1kN as typed where every failing case has that load;
    its cases keep the number in N."""
    case = Case.of({"load": 100.0, "cage_angle": 15.0}, typed={"load": "0.1kN"})
    out = in_case_terms(_failure([15.0]), case)
    assert out.typed == {"load": "0.1 kN"} and out.cases["load"] == [100.0]
    assert "the case load = 0.1 kN, cage_angle = 15 °" in str(out)


def test_a_swept_input_keeps_its_numbers():
    """Where the failing cases' values are not the one typed, they are written as numbers."""
    case = Case.of({"load": 100.0}, typed={"load": "0.1kN", "cage_angle": "0.1rad"})
    out = in_case_terms(_failure([15.0]), case, cage_given=False)
    assert out.typed == {"load": "0.1 kN"} and "cage_angle = 15 °" in str(out)


def test_a_typed_value_is_written_number_space_unit():
    """'100N' and '0.1kN' as typed read '100 N', '0.1 kN', as the numbers the solver gives do."""
    case = Case.of({"load": 100.0, "cage_angle": 15.0}, typed={"load": "100N"})
    assert "the case load = 100 N, cage_angle = 15 °" in str(in_case_terms(_failure([15.0]), case))


def test_a_cage_angle_the_solver_read_as_0_is_written_0():
    """A bare -1e-320 is the solver's 0: written '0 °', not '-9.99989e-321 °'; an angle the
    solver reduced to another one (-10 to 350) stays as given."""
    out = in_case_terms(_failure([0.0]), Case.of({"load": 100.0, "cage_angle": -1e-320}))
    assert "cage_angle = 0 °" in str(out)
    out = in_case_terms(_failure([350.0]), Case.of({"load": 100.0, "cage_angle": -10.0}))
    assert "cage_angle = -10 °" in str(out)
