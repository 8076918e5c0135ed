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
