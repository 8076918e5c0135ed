"""The library refuses what the command line refuses, each rule written once (bearingload.validate),
and an array input names its first bad element by index."""

from __future__ import annotations

import numpy as np
import pytest

import bearingload
from bearingload import validate
from bearingload.bearings.clearance import ClearanceSpec, parse_clearance
from bearingload.bearings.resolve import resolve_bearing
from bearingload.contact.hertz import ball_stiffness
from bearingload.errors import InputError
from tests.cli_helpers import error_line

RING = {"ball_diameter": 7.938, "pitch_diameter": 38.5}


def test_resolve_bearing_reads_a_number_as_its_designation():
    by_number, by_text = resolve_bearing(6205), resolve_bearing("6205")
    assert by_number.designation == "6205"
    assert (by_number.balls, by_number.stiffness, by_number.clearance) == (
        by_text.balls,
        by_text.stiffness,
        by_text.clearance,
    )


@pytest.mark.parametrize("value", [float("nan"), float("inf"), -float("inf")])
@pytest.mark.parametrize(
    "call",
    [
        lambda g: resolve_bearing("6205", clearance=g),
        lambda g: resolve_bearing("NU206", clearance=g),
        lambda g: resolve_bearing(balls=8, stiffness=1e5, clearance=g),
        lambda g: resolve_bearing("6205", clearance=ClearanceSpec(length=g)),
        lambda g: parse_clearance(g),
        lambda g: bearingload.solve(8, 1000.0, 1e5, clearance=g),
        lambda g: bearingload.solve_combined(9, 3000.0, 500.0, clearance=g, **RING),
    ],
    ids=["designation", "roller", "by hand", "spec", "parse", "solve", "solve_combined"],
)
def test_a_clearance_that_is_not_finite_is_refused_naming_it(call, value):
    with pytest.raises(InputError, match="must be a finite number") as info:
        call(value)
    assert info.value.parameter == "clearance"


@pytest.mark.parametrize(
    "call",
    [
        lambda f: bearingload.solve_combined(9, 3000.0, 500.0, f_i=f, **RING),
        lambda f: bearingload.solve_combined(9, 3000.0, 500.0, f_i=f, stiffness=1e5, **RING),
        lambda f: resolve_bearing("6205", f_i=f),
        lambda f: resolve_bearing(balls=9, stiffness=1e5, f_i=f, **RING),
        lambda f: resolve_bearing(balls=9, f_i=f, **RING),
        lambda f: ball_stiffness(7.938, 38.5, f, 0.53),
    ],
    ids=["combined", "combined, K given", "catalogue", "by hand, K given", "by hand", "Hertz"],
)
@pytest.mark.parametrize(
    ("conformity", "shown"), [(52.0, "52"), (1.0, "1"), (0.5, "0.5"), (0.3, "0.3")]
)
def test_every_entry_point_refuses_a_conformity_outside_the_one_range(call, conformity, shown):
    with pytest.raises(InputError) as info:
        call(conformity)
    assert (info.value.parameter, info.value.message) == (
        "f_i",
        "groove conformity r/D_w must lie in (0.5, 1), the groove radius between the ball's "
        f"radius and its diameter; got {shown}",
    )


@pytest.mark.parametrize(
    "ring",
    [["6205"], ["--balls", "9", "--ball-diameter", "7.938", "--pitch-diameter", "38.5"]],
    ids=["catalogue", "by hand"],
)
def test_the_command_line_refuses_a_conformity_with_the_library_rule(capsys, ring):
    with pytest.raises(InputError) as library:
        validate.conformity("f_i", 52.0)
    line = error_line(capsys, "solve", *ring, "-F", "3kN", "--inner-conformity", "52")
    assert line == f"Error: Invalid value for '--inner-conformity': {library.value.message}"


def test_a_conformity_inside_the_range_is_taken():
    b = resolve_bearing(balls=9, f_i=0.999, f_o=0.501, **RING)
    assert (b.f_i, b.f_o) == (0.999, 0.501)


@pytest.mark.parametrize(
    ("call", "text"),
    [
        (
            lambda: bearingload.solve_combined(9, np.array([1.0, 2.0, 3.0, -1.0]), 500.0, **RING),
            "radial_load[3] = -1 N: must be >= 0 N",
        ),
        (
            lambda: bearingload.solve(8, np.array([[1.0, 2.0], [3.0, np.nan]]), 1e5),
            "load[1, 1] = nan: must be a finite number (got NaN or infinity)",
        ),
        (
            lambda: bearingload.solve(8, [1000.0, -5.0], 1e5),
            "load[1] = -5 N: must be greater than 0 N (got -5)",
        ),
        (
            lambda: bearingload.solve([8, 8.5], 1000.0, 1e5),
            "balls[1] = 8.5: must be a whole number (got 8.5)",
        ),
        (
            lambda: bearingload.solve_combined(9, 3000.0, 500.0, f_i=[0.52, 0.515, 0.5], **RING),
            "f_i[2] = 0.5: groove conformity r/D_w must lie in (0.5, 1)",
        ),
    ],
    ids=["at least", "finite", "positive", "whole", "conformity"],
)
def test_an_array_input_names_its_first_bad_element(call, text):
    with pytest.raises(InputError) as info:
        call()
    assert str(info.value).startswith(text)


def test_one_number_is_named_without_an_index():
    with pytest.raises(InputError) as info:
        bearingload.solve_combined(9, -1.0, 500.0, **RING)
    assert str(info.value) == "radial_load: must be >= 0 N"
    assert info.value.element == ""


def test_a_valid_input_never_looks_for_a_bad_element(monkeypatch):
    """The index is found on the way to an error only: valid numbers and arrays skip it."""

    def refuse(*args, **kwargs):
        raise AssertionError("element() called for a valid input")

    monkeypatch.setattr(validate, "element", refuse)
    for value in (1000.0, 3, np.float64(2.0), np.array([1.0, 2.0])):
        validate.finite("load", value)
        validate.positive("load", value, "N")
        validate.at_least("load", value, 0.0, "N")
    validate.conformity("f_i", [0.52, 0.53])
    validate.ball_count([8, 9])


@pytest.mark.parametrize(
    ("call", "text"),
    [
        (
            lambda: bearingload.solve(8, np.ma.masked_array([1000, 2000], [0, 1]), 1e5),
            "load[1]: masked; give the numbers without a mask",
        ),
        (
            lambda: bearingload.solve_combined(
                9, np.ma.masked_array([[1e3, 2e3], [3e3, 4e3]], [[0, 0], [1, 0]]), 500.0, **RING
            ),
            "radial_load[1, 0]: masked; give the numbers without a mask",
        ),
        (
            lambda: bearingload.solve(8, 1000.0, np.ma.masked),
            "stiffness: masked; give the numbers without a mask",
        ),
    ],
    ids=["radial", "combined, 2-D", "one masked number"],
)
def test_a_masked_element_is_refused_naming_it(call, text):
    """numpy reads a masked array's hidden values as numbers (2000 N solved as given): a
    masked element is refused, the first named by its index, not used."""
    with pytest.raises(InputError) as info:
        call()
    assert str(info.value) == text


def test_a_masked_array_without_masked_elements_is_its_numbers():
    given = np.ma.masked_array([1000.0, 2000.0], [0, 0])
    assert list(bearingload.solve(8, given, 1e5).q_max) == list(
        bearingload.solve(8, np.array([1000.0, 2000.0]), 1e5).q_max
    )
