"""The ball-bearing models refuse the clearance, the misalignment and the ball size the command
line refuses, by one rule each (bearingload.validate): |G_r| < D_w/2, a misalignment within ±2°
and D_w >= 1e-3 d_m; their
one-case fast path and their checked path refuse alike, in the same order."""

from __future__ import annotations

import numpy as np
import pytest

from bearingload import validate
from bearingload.errors import InputError
from bearingload.models.combined import groove_geometry, solve_combined
from bearingload.models.high_speed import solve_high_speed
from bearingload.models.pair import solve_pair
from tests.cli_helpers import error_line

RING = {"ball_diameter": 7.938, "pitch_diameter": 38.5}


def _combined(**kw):
    return solve_combined(9, 3000.0, 500.0, **RING, **kw)


def _combined_k(**kw):
    return solve_combined(9, 3000.0, 500.0, stiffness=5.9e5, **RING, **kw)


def _high_speed(**kw):
    return solve_high_speed(9, 3000.0, 500.0, speed=3000.0, **RING, **kw)


MODELS = pytest.mark.parametrize(
    "model", [_combined, _combined_k, _high_speed], ids=["combined", "K given", "high speed"]
)


@MODELS
@pytest.mark.parametrize("clearance", [-1e300, -1000.0, -3.969, 3.969, 1e300, -4])
def test_a_clearance_of_half_the_ball_diameter_is_refused_naming_it(model, clearance):
    """-1e300 ended in a ConvergenceError (relative residual nan) and -1000 mm (a preload of 1 m
    on a 7.9 mm ball) was solved (Q_max 3e9 N); the command line refuses |G_r| >= D_w/2."""
    with pytest.raises(InputError) as info:
        model(clearance=clearance)
    assert info.value.parameter == "clearance"
    assert info.value.message == (
        f"G_r = {clearance:g} mm is at least half the ball diameter (7.938 mm): no bearing has "
        "such a play or preload"
    )


@MODELS
def test_a_clearance_just_inside_half_the_ball_diameter_is_not_refused_by_it(model):
    try:
        model(clearance=-3.968)
    except InputError as exc:  # (the model's other rules may refuse such a preload)
        assert "half the ball diameter" not in str(exc)


@MODELS
def test_an_array_of_clearances_names_the_first_beyond_half_the_ball(model):
    with pytest.raises(InputError) as info:
        model(clearance=np.array([0.01, -1000.0, -2000.0]))
    assert str(info.value).startswith("clearance[1] = -1000 mm: G_r = -1000 mm is at least half")


def test_a_clearance_beside_an_array_of_ball_diameters_is_named_by_its_own_element():
    with pytest.raises(InputError) as info:
        solve_combined(
            9, 3000.0, clearance=[0.01, -4.0], ball_diameter=[7.938, 7.0], pitch_diameter=38.5
        )
    assert str(info.value).startswith(
        "clearance[1] = -4 mm: G_r = -4 mm is at least half the ball diameter (7 mm)"
    )


@MODELS
@pytest.mark.parametrize(("misalignment", "shown"), [(1e300, "1e+300"), (3.0, "3"), (-2.5, "-2.5")])
def test_a_misalignment_beyond_two_degrees_is_refused_naming_it(model, misalignment, shown):
    """1e300° ended in a ConvergenceError after 0 iterations and 3° was solved; the command
    line refuses a misalignment beyond ±2°."""
    with pytest.raises(InputError) as info:
        model(misalignment=misalignment)
    assert info.value.parameter == "misalignment"
    assert info.value.message.startswith(f"must be within ±2° (got {shown}°): ball bearings")


@MODELS
def test_an_array_of_misalignments_names_the_first_beyond_two_degrees(model):
    with pytest.raises(InputError) as info:
        model(misalignment=np.array([0.05, -2.0, 2.5, 7.0]))
    assert str(info.value).startswith("misalignment[2] = 2.5 °: must be within ±2° (got 2.5°)")


@MODELS
def test_a_misalignment_of_two_degrees_is_not_refused_by_the_rule(model):
    try:
        model(misalignment=np.array([2.0, -2.0]))
    except InputError as exc:
        assert exc.parameter != "misalignment", exc


def test_the_command_line_refuses_the_clearance_with_the_library_message(capsys):
    line = error_line(capsys, "solve", "6205", "-F", "1kN", "-G", "-5mm")
    with pytest.raises(InputError) as info:
        solve_combined(9, 1000.0, clearance=-5.0, **RING)
    assert line == f"Error: Invalid value for '--clearance': {info.value.message}"


def test_the_command_line_refuses_the_misalignment_with_the_library_message(capsys):
    line = error_line(capsys, "solve", "6205", "-F", "1kN", "-A", "100N", "--misalignment", "3deg")
    with pytest.raises(InputError) as info:
        solve_combined(9, 1000.0, 100.0, misalignment=3.0, **RING)
    assert line == f"Error: Invalid value for '--misalignment': {info.value.message}"


#: One case breaking one rule of solve_combined's inputs each (with the rest valid), in the
#: order the rules are checked, and the parameter refused.
ONE_RULE_BROKEN = [
    ({"radial_load": -1.0}, "radial_load"),
    ({"contact_angle": 70.0}, "contact_angle"),
    ({"contact_angle": 25.0, "clearance": 0.01}, "clearance"),
    ({"contact_angle": 25.0, "axial_load": -5.0}, "axial_load"),
    ({"misalignment": 3.0}, "misalignment"),
    ({"modulus": -1.0}, "modulus"),
    ({"stiffness": 0.0}, "stiffness"),
    ({"f_i": 0.5}, "f_i"),
    ({"f_o": 1.0}, "f_o"),
    ({"clearance": -4.0}, "clearance"),
]


def _case(**given):
    kw = {"radial_load": 3000.0, "axial_load": 500.0, **RING, **given}
    return kw.pop("radial_load"), kw.pop("axial_load"), kw


@pytest.mark.parametrize(("given", "parameter"), ONE_RULE_BROKEN)
def test_one_case_of_plain_numbers_is_refused_as_an_array_of_it(given, parameter):
    """The one-case fast path (plain floats) and the checked path (arrays) take the same rules:
    one broken rule is refused with the same message either way."""
    fr, fa, kw = _case(**given)
    with pytest.raises(InputError) as plain:
        solve_combined(9, fr, fa, **kw)
    as_arrays = {k: np.array([v]) for k, v in kw.items()}
    with pytest.raises(InputError) as checked:
        solve_combined(9, np.array([fr]), np.array([fa]), **as_arrays)
    assert plain.value.parameter == checked.value.parameter == parameter
    assert str(plain.value) == str(checked.value)


def test_the_rules_are_checked_in_their_order():
    """Of two broken rules the first in the order is named, on either path."""
    for (first, name), (second, _) in zip(ONE_RULE_BROKEN, ONE_RULE_BROKEN[1:], strict=False):
        if any(first[k] != second[k] for k in set(first) & set(second)):
            continue  # (two contact angles)
        fr, fa, kw = _case(**{**second, **first})
        for args in ((fr, fa, kw), (np.array([fr]), np.array([fa]), kw)):
            with pytest.raises(InputError) as info:
                solve_combined(9, args[0], args[1], **args[2])
            assert info.value.parameter == name, (first, second, info.value)


@pytest.mark.parametrize(
    ("rule", "args", "fits"),
    [
        (validate.clearance_fits, (-3.968, 7.938), True),
        (validate.clearance_fits, (3.969, 7.938), False),
        (validate.clearance_fits, (-3.969, 7.938), False),
        (validate.misalignment_fits, (2.0,), True),
        (validate.misalignment_fits, (-2.0000000000000004,), False),
    ],
)
def test_a_rule_tests_one_number_as_an_array_of_it(rule, args, fits):
    """The one-case fast path tests plain floats with the rule the checked path uses on arrays."""
    assert rule(*args) is fits
    assert rule(*(np.array([a]) for a in args)).tolist() == [fits]


def _pair(dw):
    return solve_pair(
        12,
        100.0,
        0.0,
        preload=500.0,
        contact_angle=40.0,
        ball_diameter=dw,
        pitch_diameter=38.5,
        width=15.0,
    )


@pytest.mark.parametrize(
    "model",
    [
        lambda dw: solve_combined(9, 1000.0, ball_diameter=dw, pitch_diameter=38.5),
        lambda dw: solve_combined(
            9, 1000.0, 100.0, ball_diameter=dw, pitch_diameter=38.5, stiffness=5.9e5
        ),
        lambda dw: groove_geometry(dw, 38.5, 0.52, 0.53, 0.0),
        _pair,
    ],
    ids=["combined", "K given", "groove", "pair"],
)
@pytest.mark.parametrize("dw", [1e-300, 0.0385 * (1 - 1e-12), 1e-3])
def test_a_ball_below_a_thousandth_of_the_pitch_diameter_is_refused_naming_it(model, dw):
    """A ball of 1e-300 mm on a 38.5 mm pitch circle was solved to an x of about 2.9e98 mm (and
    the command line printed approaches of 1e101 µm): below 1e-3 d_m no bearing has balls."""
    with pytest.raises(InputError) as info:
        model(dw)
    assert info.value.parameter == "ball_diameter"
    assert "give at least 0.0385 mm" in str(info.value)


def test_a_ball_of_a_thousandth_of_the_pitch_diameter_is_solved():
    r = solve_combined(9, 1000.0, ball_diameter=0.0385, pitch_diameter=38.5)
    assert np.isfinite(r.q_max)


def test_a_ball_just_below_the_limit_is_shown_unrounded():
    """A ball one ulp below 1e-3 d_m was refused as 'D_w = 0.0385 mm is below ... give at least
    0.0385 mm' (both printed %g): the refused diameter is shown as given."""
    with pytest.raises(InputError) as info:
        solve_combined(9, 1000.0, ball_diameter=0.0385 * (1 - 1e-12), pitch_diameter=38.5)
    assert "D_w = 0.0384999999999615 mm is below" in str(info.value)


def test_an_array_names_its_too_small_ball_by_index():
    with pytest.raises(InputError, match=r"ball_diameter\[1\] = 1e-300 mm"):
        solve_combined(9, 1000.0, ball_diameter=np.array([7.938, 1e-300]), pitch_diameter=38.5)
    with pytest.raises(InputError, match=r"ball_diameter\[1\] = 1e-300 mm"):
        _pair([7.938, 1e-300])


def test_the_command_line_refuses_a_too_small_ball_with_the_library_message(capsys):
    args = ("--balls", "9", "--ball-diameter", "1e-300", "--pitch-diameter", "38.5", "-F", "1kN")
    line = error_line(capsys, "solve", *args)
    with pytest.raises(InputError) as info:
        solve_combined(9, 1000.0, ball_diameter=1e-300, pitch_diameter=38.5)
    assert line == f"Error: Invalid value for '--ball-diameter': {info.value.message}"


def test_an_angular_contact_misalignment_refusal_does_not_speak_of_a_deep_groove_bearing(capsys):
    """The refusal of a misalignment beyond ±2° gave a deep-groove ball bearing's 2-10 arcmin as
    the reason, also for an angular-contact bearing (which takes little misalignment)."""
    line = error_line(capsys, "solve", "7205B", "-F", "1kN", "--misalignment", "-3")
    assert "(got -3°): ball bearings tolerate minutes of arc at most" in line
    assert "an angular-contact one little" in line
    assert "a deep-groove ball bearing tolerates" not in line


def test_a_roller_bearing_under_a_combined_load_is_refused_naming_both_ball_kinds(capsys):
    """A roller bearing's refusal of the combined load said it is solved 'for deep-groove ball
    bearings only', while an angular-contact one (7205B -A 500N) is solved too."""
    line = error_line(capsys, "solve", "NU206", "-F", "1kN", "-A", "100N")
    assert "NU206 is a roller bearing" in line
    assert "deep-groove ball bearings only" not in line
    assert "ball bearings only (deep-groove and angular-contact)" in line
