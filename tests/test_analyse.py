"""The library's one entry point ``analyse``: the same decisions and the same document as
``bearingload solve --format json``, the same refusals, typed errors with fields."""

from __future__ import annotations

import json

import pytest

import bearingload
from bearingload.errors import ConflictError, InputError, MissingError, UnusedError
from bearingload.plan.analyse import analyse
from bearingload.reports.render import render

from .cli_helpers import invoke

#: (solve's arguments, analyse's arguments) of the same case, one per engine and path.
SAME_CASES = [
    (
        ["6205", "-F", "1.4kN", "-A", "700N", "-G", "C3"],
        {"bearing": "6205", "load": "1.4kN", "axial_load": 700, "clearance": "C3"},
    ),
    (
        ["-z", "8", "-F", "300kgf", "-K", "4700kgf/mm^1.5", "-G", "20um"],
        {"balls": 8, "load": "300kgf", "stiffness": "4700kgf/mm^1.5", "clearance": "20um"},
    ),
    (
        ["6306", "-F", "3kN", "-G", "C3", "--clearance-pick", "range"],
        {"bearing": "6306", "load": 3000, "clearance": "C3", "clearance_pick": "range"},
    ),
    (
        ["7205BDB", "--preload", "300N", "-F", "1kN", "-A", "500N", "--speed", "10000"],
        {"bearing": "7205BDB", "preload": 300, "load": 1000, "axial_load": 500, "speed": 10000},
    ),
    (
        ["6205", "-F", "1.4kN", "--speed", "3000", "--viscosity", "20cSt", "--reliability", "99"],
        {"bearing": "6205", "load": 1400, "speed": 3000, "viscosity": 20, "reliability": 99},
    ),
    (["NU206", "-F", "5kN"], {"bearing": "NU206", "load": "5kN"}),
]


@pytest.mark.parametrize("cli, library", SAME_CASES)
def test_analyse_gives_the_document_solve_prints_as_json(cli, library):
    printed = invoke("solve", *cli, "--format", "json")
    assert printed.exit_code == 0, printed.output
    document = analyse(**library).to_dict()
    assert render([], "json", document=document) == printed.stdout
    assert set(document) >= {"cases", "units", "warnings"}


def test_analyse_keeps_full_precision_where_json_rounds_to_ten_digits():
    document = analyse("6205", load=1400, axial_load=700).to_dict()
    q = document["cases"][0]["q_max"]
    printed = json.loads(render([], "json", document=document))
    assert isinstance(q, float) and printed["cases"][0]["q_max"] == float(f"{q:.10g}")


def test_a_solution_has_every_key_of_its_cases_as_an_attribute():
    one = analyse("6205", load="1.4kN", axial_load="700N")
    case = one.to_dict()["cases"][0]
    assert one.q_max == case["q_max"] and one.stiffness_matrix == case["stiffness_matrix"]
    assert one.engine == "combined" and one.units["q_max"] == "N"
    three = analyse("6306", load=3000, clearance="C3", clearance_pick="range")
    assert len(three.q_max) == 3 and three.q_max[0] < three.q_max[2]
    with pytest.raises(AttributeError, match="no quantity 'q_maximum'"):
        _ = one.q_maximum


def test_analyse_is_at_the_top_level_beside_the_solvers():
    assert bearingload.analyse is analyse
    for name in ("solve_pair", "solve_high_speed", "solve_pair_high_speed"):
        assert callable(getattr(bearingload, name))


def test_the_engine_follows_the_inputs_as_in_solve():
    assert analyse("6306", load=3000).engine == "radial"
    assert analyse("6306", load=3000, speed=1500).engine == "combined"  # the ball dynamics
    assert analyse("6306", load=3000, speed=1500, quasi_static=True).engine == "radial"
    assert analyse("7205B", load=1000).engine == "combined"
    assert analyse("7205B", arrangement="DB", preload=300, load=1000).engine == "pair"


def test_an_unknown_input_is_refused_naming_the_near_one():
    with pytest.raises(InputError, match="did you mean 'load'") as caught:
        analyse("6205", lod=1000)
    assert caught.value.parameter == "lod"


@pytest.mark.parametrize(
    "options, parameter",
    [
        ({"load": "3 parsecs"}, "load"),
        ({"load": 1000, "reliability": 80}, "reliability"),
        ({"load": 1000, "rotating": "both"}, "rotating"),
        ({"load": 1000, "e_c": 2}, "e_c"),
        ({"load": 1000, "balls": 8.5}, "balls"),
        ({"load": 1000, "quasi_static": True}, "quasi_static"),
        ({"load": 1000, "contamination": "dusty"}, "contamination"),
    ],
)
def test_analyse_refuses_what_solve_refuses_naming_the_argument(options, parameter):
    with pytest.raises(InputError) as caught:
        analyse("6205", **options)
    assert caught.value.parameter == parameter


def test_a_refusal_of_inputs_given_together_is_a_conflict_with_its_fields():
    with pytest.raises(ConflictError) as caught:
        analyse("7205BDB", load=1000, misalignment=0.1)
    assert caught.value.parameter == "misalignment"
    assert caught.value.where == "a bearing pair" and "'moment'" in caught.value.why


def test_a_ring_by_hand_names_what_is_missing_and_what_it_would_ignore():
    with pytest.raises(MissingError) as caught:
        analyse(load=1000, stiffness=1e5)
    assert caught.value.parameter == "balls"
    with pytest.raises(UnusedError) as unused:
        analyse(balls=8, load=1000, stiffness=1e5, poisson=0.3, maker="SKF")
    assert unused.value.parameters == ("poisson", "maker")


def test_the_way_out_of_a_refusal_at_speed_names_the_static_model_by_its_argument():
    with pytest.raises(InputError) as caught:
        analyse("6205", load=1000, speed="1e6rpm")
    assert caught.value.reason == "too_fast"
    assert "'quasi_static'" in caught.value.way_out


def test_a_refusal_by_a_model_names_the_argument_analyse_takes():
    with pytest.raises(InputError) as caught:
        analyse("6205", load=3000, axial_load=500, inner_conformity=52)
    assert caught.value.parameter == "inner_conformity"
    assert str(caught.value).startswith("inner_conformity: ")


def test_a_radial_case_at_speed_keeps_the_radial_engines_load_factors():
    """One report per bearing: with a speed the radial case moves to the ball dynamics and
    keeps k = Q_max/F_r and K_Q = k z/2 from its inner contacts; near rest they are the radial
    engine's."""
    static = analyse("6306", load=3000, clearance="C3")
    moving = analyse("6306", load=3000, clearance="C3", speed=1500)
    slow = analyse("6306", load=3000, clearance="C3", speed=1e-3)
    assert moving.engine == "combined" and static.engine == "radial"
    assert moving.k == pytest.approx(max(moving.ball_loads_inner) / 3000, rel=1e-12)
    assert moving.K_Q == pytest.approx(moving.k * 8 / 2, rel=1e-12)
    assert slow.k == pytest.approx(static.k, rel=1e-9) and moving.k > static.k
    assert analyse("6306", load=3000, axial_load=100, speed=1500).to_dict()["cases"][0]["k"] is None


@pytest.mark.parametrize(
    "options, parameter, words",
    [
        ({"load": 3000, "modulus": 210}, "modulus", "implausible"),
        ({"load": 3000, "clearance": 2}, "clearance", "did you mean 2um"),
        ({"load": 1000, "speed": 3000, "viscosity": 6.8e-5}, "viscosity", "implausible"),
        ({"load": 1000, "revolutions": True}, "revolutions", "must be a number"),
        ({"load": 10**400}, "load", "too large"),
        ({"load": float("nan")}, "load", "finite"),
        ({"load": [1000.0, 2000.0]}, "load", "must be a number"),
        ({"load": 1000, "method": "bogus"}, "method", "unknown method 'bogus'"),
        ({"load": 1000, "speed": 3000, "method": "bogus"}, "method", "unknown method"),
        ({"load": 1000, "maker": ""}, "maker", "must not be empty"),
    ],
)
def test_analyse_reads_numbers_as_the_command_line_reads_bare_ones(options, parameter, words):
    """A number is read as a bare number of solve's option: its plausibility for the quantity
    is judged the same way; bools, huge integers, NaN and sequences are refused by name."""
    with pytest.raises(InputError, match=words) as caught:
        analyse("6205", **options)
    assert caught.value.parameter == parameter


def test_analyse_takes_numpy_scalars_and_refuses_arrays():
    import numpy as np

    one = analyse("6205", load=1000.0).q_max
    assert analyse("6205", load=np.int64(1000)).q_max == one
    assert analyse("6205", load=np.float32(1000.0)).q_max == one
    with pytest.raises(InputError, match="one case: give a number, not an array"):
        analyse("6205", load=np.array([1000.0, 2000.0]))


def test_analyse_needs_the_radial_load_as_solve_does():
    for bearing, options in (("7205B", {"axial_load": 100}), ("6205", {})):
        with pytest.raises(MissingError) as caught:
            analyse(bearing, **options)
        assert caught.value.parameter == "load"


def test_an_error_keeps_its_kind_and_fields_when_reworded_or_pickled():
    import pickle

    from bearingload.errors import ConvergenceError

    conflict = ConflictError("moment", "a pair", "why").with_way_out("give 'misalignment'")
    assert isinstance(conflict, ConflictError) and conflict.where == "a pair"
    assert conflict.way_out == "give 'misalignment'" and conflict.problem.endswith("why")
    unused = UnusedError(("f_i", "maker"), "a bearing").named("inner_conformity")
    assert unused.parameters == ("inner_conformity", "maker")
    for error in (
        conflict,
        unused,
        MissingError("load", "F_r"),
        ConvergenceError("ring", 3, 0.5, {"load": 1.0}, {"load": "N"}),
    ):
        again = pickle.loads(pickle.dumps(error))
        assert type(again) is type(error) and str(again) == str(error)
        assert again.__dict__.keys() == error.__dict__.keys()


def test_a_solution_compares_by_identity_and_draws_only_ball_loads():
    a = analyse("6205", load=1000)
    assert a != analyse("6205", load=1000) and a == a and hash(a) == hash(a)
    with pytest.raises(ValueError, match="exact model"):
        analyse("6205", load=1000, method="palmgren").figure()


def test_every_option_of_solve_is_read_by_the_plan_with_the_same_quantity_and_range():
    """One rule book: each case option of the command line has a reader of the same name in
    plan/inputs.py, a Quantity option the same kind and positivity, a range option the same
    bounds, a choice the same choices."""
    import click

    from bearingload.cli.case_options import DECLARATIONS, PAIR_DECLARATIONS
    from bearingload.cli.options import Quantity
    from bearingload.plan.inputs import READERS

    declared = DECLARATIONS | PAIR_DECLARATIONS
    assert set(declared) == set(READERS)
    for name, (_, attrs) in declared.items():
        kind, reader = attrs.get("type"), READERS[name]
        if isinstance(kind, Quantity) and kind.kind != "stiffness":
            assert (reader.kind, reader.positive) == (kind.kind, kind.positive), name
        elif isinstance(kind, click.FloatRange):
            low_open = bool(kind.min_open)
            assert reader.range == (kind.min, kind.max, low_open), name
        elif isinstance(kind, click.Choice):
            assert set(reader.choices) == set(kind.choices), name


@pytest.mark.parametrize("designation", ["foo", "79005CDB"])
def test_an_unreadable_designation_beside_a_preload_is_refused_as_a_designation(designation):
    """The designation's own error comes first, not the pair's ('a preload belongs to a pair'),
    which assumed a bearing it could not read."""
    with pytest.raises(InputError, match="cannot read") as caught:
        analyse(designation, load=1000, axial_load=200, preload="M")
    assert caught.value.parameter == "bearing"
    with pytest.raises(InputError, match="belongs to a bearing pair"):
        analyse("6205", load=1000, axial_load=200, preload="M")
