"""The plan of ``table`` (bearingload.plan.table): its refusals are the library's typed errors,
naming the inputs as the library calls them; the command line only parses and renders."""

from __future__ import annotations

import pytest

from bearingload.errors import ConflictError, InputError, MissingError, UnusedError
from bearingload.plan.case import Case
from bearingload.plan.table import table_case


def _case(**values):
    return Case.of({"cage_angle": 0.0, **values})


@pytest.mark.parametrize(
    ("name", "values", "options", "kind", "parameter"),
    [
        ("life", {"bearing": "6205", "load": 1000.0}, {"method": "all"}, ConflictError, "method"),
        ("life", {"bearing": "6205", "load": 1000.0}, {"z_max": 12}, ConflictError, "z_max"),
        (
            "life",
            {"bearing": "6205", "load": 1000.0, "clearance": 0.01},
            {},
            ConflictError,
            "clearance",
        ),
        ("life", {"bearing": "6205"}, {}, MissingError, "load"),
        ("life", {"load": 1000.0}, {}, MissingError, "bearing"),
        ("k", {"load": 1000.0, "balls": 8}, {}, ConflictError, "balls"),
        ("k", {"load": 1000.0}, {"clearances": [0.0]}, ConflictError, "clearances"),
        ("k", {"load": 1000.0, "ball_diameter": 11.5}, {}, UnusedError, "ball_diameter"),
        ("k", {"load": 1000.0, "bearing": "NU206"}, {}, InputError, "bearing"),
        ("k", {"load": 1000.0, "bearing": "7205B"}, {}, InputError, "bearing"),
        ("k", {"load": 1000.0, "bearing": "7205BDB"}, {}, ConflictError, "bearing"),
        ("life", {"load": 1000.0, "bearing": "6205"}, {"preloads": [0.0]}, UnusedError, "preloads"),
        ("life", {"load": 1000.0, "bearing": "7205BDB"}, {}, MissingError, "preloads"),
        (
            "life",
            {"load": 1000.0, "bearing": "7205BDB"},
            {"preloads": [0.0], "method": "exact"},
            ConflictError,
            "method",
        ),
    ],
)
def test_table_refusals_are_typed_errors_of_the_plan(name, values, options, kind, parameter):
    with pytest.raises(kind) as info:
        table_case(name, _case(**values), **options)
    assert type(info.value) is kind
    assert info.value.parameter == parameter


def test_table_k_plans_the_conditions_of_a_ring_given_by_its_stiffness():
    from bearingload.bearings.clearance import parse_clearance

    clearance = parse_clearance("10um")
    tabled = table_case("k", _case(load=1000.0, stiffness="2e5", clearance=clearance))
    assert tabled.kind == "design"
    cond = tabled.result
    assert (cond.load, cond.stiffness, cond.clearance) == (1000.0, 2e5, 0.01)
