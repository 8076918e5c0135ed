"""``bearingload.analyse_many``: many cases as ``analyse`` takes one, solved together on arrays
by the plan of many cases (batch's engine): each case's answer is that of ``analyse`` alone
(an independent path: one case, one call), each refusal kept by the case's index."""

from __future__ import annotations

import pytest

from bearingload import analyse, analyse_many
from bearingload.errors import InputError

#: Radial and combined cases of one bearing, a ring by hand, a ball bearing at a speed (the
#: ball dynamics), a roller bearing with its lives, and units written in the arguments.
CASES = [
    {"bearing": "6205", "load": "1kN"},
    {"bearing": "6205", "load": 2500.0, "clearance": "C3"},
    {"bearing": "6205", "load": "1.4kN", "axial_load": 700, "clearance": "C3"},
    {"bearing": "6205", "load": "1kN", "speed": 3000},
    {"bearing": "NU206", "load": "5kN", "speed": "2000", "viscosity": 12},
    {"bearing": "6306", "load": "3kN", "moment": "5Nm"},
]


@pytest.mark.parametrize("key", ["q_max", "loaded_balls", "rating_life"])
def test_every_case_is_the_answer_of_analyse_alone(key):
    many = analyse_many(CASES)
    assert many.rows == list(range(len(CASES))) and many.errors == {}
    for i, case in enumerate(CASES):
        alone = getattr(analyse(**case), key)
        assert many.values[key][i] == pytest.approx(alone, rel=1e-12), (case, key)


def test_a_ring_by_hand_and_a_method_as_analyse():
    cases = [
        {"balls": 8, "stiffness": 1e5, "load": 1000, "method": "stribeck"},
        {"balls": 12, "stiffness": "4700kgf/mm^1.5", "load": "300kgf", "clearance": "20um"},
    ]
    many = analyse_many(cases)
    for i, case in enumerate(cases):
        options = {k: v for k, v in case.items() if k != "method"}
        alone = analyse(None, method=case.get("method", "exact"), **options)
        assert many.values["q_max"][i] == pytest.approx(alone.q_max, rel=1e-12)


def test_a_bad_case_is_named_by_its_index_and_the_others_solved():
    cases = [
        {"bearing": "6205", "load": "1kN"},
        {"bearing": "6205", "load": "1kN", "speed": 0},
        {"bearing": "6205", "load": "1kN", "clearance_pick": "range"},
        {"bearing": "6205", "load": "1kN", "lode": 3},
        {"bearing": "6205", "load": "-1kN"},
    ]
    many = analyse_many(cases)
    assert many.rows == [0] and sorted(many.errors) == [1, 2, 3, 4]
    assert all(isinstance(e, InputError) for e in many.errors.values())
    assert [many.errors[i].parameter for i in (1, 2, 3, 4)] == [
        "speed",
        "clearance_pick",
        "lode",
        "load",
    ]
    for i in (1, 4):  # the refusal analyse gives the case alone
        with pytest.raises(InputError) as alone:
            analyse(**cases[i])
        assert str(many.errors[i]) == str(alone.value)


def test_pairs_are_solved_with_their_lives():
    cases = [
        {"bearing": "7205BDB", "load": "1kN", "axial_load": "500N"},
        {"bearing": "7205B", "arrangement": "DF", "load": "2kN", "preload": "200N"},
    ]
    many = analyse_many(cases)
    assert many.rows == [0, 1]
    for pc, case in zip(many.values["pair"], cases, strict=True):
        alone = analyse(**case).cases[0]
        assert pc.bearings[0].result.q_max == pytest.approx(alone.bearings[0].result.q_max)


#: A matched pair by its designation, the inputs of a single bearing but its load.
PAIR_BY_NAME = {"bearing": "7205BDB", "load": "1kN", "axial_load": "500N"}
PRELOADED = {"bearing": "7205BDB", "load": "1kN", "preload": "100N"}
SINGLE = {"bearing": "6205", "load": "1kN"}


def _q_max(many, i):
    """The heaviest ball load of case ``i`` of ``many``: a single bearing's, or a pair's
    (its bearings' largest)."""
    row = many.rows.index(i)
    pair = many.values.get("pair", [None] * len(many.rows))[row]
    if pair is None:
        return many.values["q_max"][row]
    return max(b.result.q_max for b in pair.bearings)


def _q_max_alone(case):
    solution = analyse(**case)
    if solution.engine == "pair":
        return max(b.result.q_max for b in solution.cases[0].bearings)
    return solution.q_max


@pytest.mark.parametrize(
    "cases",
    [
        [PAIR_BY_NAME],
        [PAIR_BY_NAME, PRELOADED],
        [SINGLE, PRELOADED],
        [PRELOADED, SINGLE, PAIR_BY_NAME],
    ],
)
def test_a_case_is_a_pair_or_a_single_bearing_by_its_own_inputs(cases):
    """A designation that names a pair makes its case a pair, alone or beside other cases; a
    single bearing stays one beside pairs: each case the answer of analyse alone."""
    many = analyse_many(cases)
    assert many.errors == {} and many.rows == list(range(len(cases)))
    for i, case in enumerate(cases):
        assert _q_max(many, i) == pytest.approx(_q_max_alone(case), rel=1e-12), case


def test_pairs_and_single_bearings_merge_by_index_with_none_where_a_value_does_not_apply():
    cases = [PRELOADED, SINGLE, {"bearing": "6205", "load": -5}, PAIR_BY_NAME]
    many = analyse_many(cases)
    assert many.rows == [0, 1, 3] and list(many.errors) == [2]
    for key in ("pair", "lives", "q_max", "rating_life", "warnings"):
        assert len(many.values[key]) == len(many.rows), key
    assert [p is None for p in many.values["pair"]] == [False, True, False]
    assert [life is None for life in many.values["lives"]] == [False, True, False]
    assert [q is None for q in many.values["q_max"]] == [True, False, True]
    assert many.values["q_max"][1] == pytest.approx(analyse(**SINGLE).q_max, rel=1e-12)


def test_an_angular_designation_under_a_radial_load_only_is_solved_beside_any_case():
    """7205B with its radial load alone takes the combined engine, as analyse takes it, whether
    or not another case gives an axial load."""
    angular = {"bearing": "7205B", "load": "1kN"}
    expected = analyse(**angular).q_max
    for cases in ([angular], [angular, {"bearing": "6205", "load": "1kN", "axial_load": "100N"}]):
        many = analyse_many(cases)
        assert 0 in many.rows and 0 not in many.errors
        assert many.values["q_max"][0] == pytest.approx(expected, rel=1e-12)


#: Cases analyse refuses, each on its own and beside a case it solves.
REFUSED = [
    {"bearing": "6205", "load": 0, "axial_load": 0},
    {"bearing": "6205"},
    {"bearing": "7205BDB", "axial_load": "500N"},
    {"bearing": "6205", "load": "-1kN", "axial_load": "300N"},
    {"bearing": "7205BDB", "load": "-1kN"},
    {"bearing": "7205BDB", "load": 0},
    {"bearing": "6205", "load": "1kN", "preload": 100},
    {"bearing": "6205", "load": "1kN", "method": "foo"},
    {"bearing": "6205", "load": "1kN", "method": 3},
    {"balls": 8, "stiffness": 1e5, "load": 1000, "axial_load": 100},
    {"balls": 8, "stiffness": 1e5},
    {"bearing": "7205BDB", "load": "1kN", "method": "stribeck"},
    {"bearing": "7205BDB", "load": "1kN", "revolutions": 1e6},
    {"bearing": "7205B", "arrangement": "DB", "load": "1kN", "clearance": "C3"},
    {"bearing": "7205BDB", "load": "1kN", "misalignment": 0.05},
]


@pytest.mark.parametrize("case", REFUSED)
def test_a_refusal_is_the_error_analyse_raises_for_the_case_alone(case):
    with pytest.raises(InputError) as alone:
        analyse(**case)
    for cases in ([case], [SINGLE, case], [PRELOADED, case]):
        error = analyse_many(cases).errors[len(cases) - 1]
        assert type(error) is type(alone.value)
        assert (error.parameter, str(error)) == (alone.value.parameter, str(alone.value))
        assert "row" not in str(error) and "file" not in str(error)


def test_a_case_that_does_not_converge_is_named_by_its_arguments_as_analyse_names_it(
    monkeypatch,
):
    import numpy as np

    from bearingload.errors import ConvergenceError
    from bearingload.models import combined

    real = combined.solve_combined

    def failing(balls, radial_load, *args, **kwargs):
        if 100.0 in np.ravel(radial_load).tolist():
            cases, units = {"radial_load": radial_load}, {"radial_load": "N"}
            raise ConvergenceError("combined", 5, 0.1, cases, units)
        return real(balls, radial_load, *args, **kwargs)

    monkeypatch.setattr(combined, "solve_combined", failing)
    case = {"bearing": "6205", "load": 100, "axial_load": 300}
    with pytest.raises(ConvergenceError) as alone:
        analyse(**case)
    assert "load = 100 N" in str(alone.value) and "radial_load" not in str(alone.value)
    many = analyse_many([SINGLE | {"axial_load": 300}, case])
    assert many.rows == [0] and str(many.errors[1]) == str(alone.value)


def test_a_case_that_is_no_mapping_is_refused_by_its_index_and_any_iterable_is_taken():
    many = analyse_many([SINGLE, "6205"])
    assert many.rows == [0] and isinstance(many.errors[1], InputError)
    assert (
        str(many.errors[1]) == "cases[1]: must be a mapping of analyse's arguments, by their names"
    )
    assert analyse_many(c for c in [SINGLE, SINGLE]).rows == [0, 1]
    with pytest.raises(InputError, match="^cases: "):
        analyse_many(SINGLE)


def test_a_case_keyed_by_no_name_is_refused_by_its_index():
    """A key that is no text is refused for its case; the other cases are solved."""
    many = analyse_many([{"bearing": "6205", "load": "1kN"}, {1: 2, "bearing": "6205"}])
    assert many.rows == [0]
    assert many.errors[1].parameter == "cases" and "[1]" in str(many.errors[1])


@pytest.mark.parametrize(
    "case",
    [
        {"bearing": "7205BDB", "load": "1kN", "preload": "300N", "method": "all"},
        {"bearing": "7205BDB", "load": "1kN", "preload": "300N", "clearance_pick": "range"},
        {"bearing": "6205", "load": "1kN", "method": None},
    ],
)
def test_a_pair_or_a_method_is_refused_in_analyses_words(case):
    """A pair's own refusals come before those of the one-call arrays; a method given as None
    is refused as analyse refuses it."""
    with pytest.raises(InputError) as alone:
        analyse(**case)
    many = analyse_many([case])
    assert many.rows == [] and str(many.errors[0]) == str(alone.value)
