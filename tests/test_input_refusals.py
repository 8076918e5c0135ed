"""Refused input, in the library and on the command line: one error naming the parameter and what
is allowed (bad arrays and types, options a hand-given ring would ignore, a zero rating, a tilt
in degrees, loads too small, a thousands separator), and a bug told apart by its exit status."""

from __future__ import annotations

import re

import numpy as np
import pytest

from bearingload import InputError, analyse, ring_forces, solve, solve_pair
from bearingload.models.combined import solve_combined
from bearingload.models.high_speed import solve_high_speed

from .cli_helpers import error_line, run_entry, run_process

GEOMETRY = {"ball_diameter": 7.938, "pitch_diameter": 38.5}


@pytest.mark.parametrize(
    "call, parameter",
    [
        (lambda: ring_forces(9, [0.01, 0.02], [0.0, 0.0, 0.0], 1e5), "x, y"),
        (lambda: ring_forces(9, np.array([]), np.array([]), 1e5), "x, y"),
        (lambda: solve(8, "1kN", 1e5), "load"),
        (lambda: solve(True, 1000.0, 1e5), "balls"),
        (lambda: solve_combined(9, [1000.0, 2000.0], [500.0, 1, 2], **GEOMETRY), "radial_load, axial_load"),
        (lambda: solve_combined(9, np.array([]), 500.0, **GEOMETRY), "radial_load"),
    ],
)  # fmt: skip
def test_bad_arrays_and_types_are_input_errors(call, parameter):
    with pytest.raises(InputError) as exc:
        call()
    assert exc.value.parameter == parameter


def test_library_errors_name_a_number_not_the_repr_of_an_array():
    """validate.finite_positive wrote 'got array([ 1., -2.])' (numpy's repr) into messages
    that reach the terminal; it names the first offending value, as validate.positive does."""
    import numpy as np

    from bearingload.bearings.life import rating_life
    from bearingload.errors import InputError

    for value, shown in ((np.array(0.0), "got 0"), (np.array([1.0, -2.0]), "got -2")):
        with pytest.raises(InputError, match=f"{shown}$") as info:
            rating_life(1000.0, value)
        assert "array" not in str(info.value)


def test_a_zero_dynamic_rating_is_refused(capsys):
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "-C", "0")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "--dynamic-rating" in err and "must be greater than 0 N" in err


def test_a_tilt_of_degrees_is_refused(capsys):
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--misalignment", "90")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "Invalid value for '--misalignment': must be within ±2°" in err


def test_a_negative_misalignment_is_refused_showing_its_sign(capsys):
    """-3° was refused as 'got 3°' (its magnitude), on the command line and in the library."""
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--misalignment", "-3")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "must be within ±2° (got -3°)" in err
    with pytest.raises(InputError) as info:
        solve_combined(9, 1000.0, 0.0, **GEOMETRY, misalignment=-3.0)
    assert info.value.message.startswith("must be within ±2° (got -3°)")


def test_loads_too_small_for_the_combined_solver_are_refused(capsys):
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1e-9N", "-A", "1e-9N")
    assert code == 2 and err.count("\n") == 1 and "RuntimeWarning" not in err
    assert "the loads are too small for the combined solver" in err


@pytest.mark.parametrize(
    "extra, message",
    [
        (
            ["--modulus", "210GPa"],
            "Error: --modulus needs a bearing designation or the ball geometry",
        ),
        (["--clearance-pick", "range"], "Error: --clearance-pick needs a bearing designation"),
        (
            ["--poisson", "0.3", "--maker", "SKF"],
            "Error: --poisson, --maker need a bearing designation",
        ),
    ],
)
def test_options_a_hand_given_ring_would_ignore_are_refused(capsys, extra, message):
    code, out, err = run_entry(capsys, "solve", "-z", "8", "-F", "1kN", "-K", "1e5", *extra)
    assert code == 2 and out == "" and err.count("\n") == 1 and err.startswith(message), err


@pytest.mark.parametrize(
    "args, message",
    [
        (["solve", "-z", "8", "-F", "1kN", "-K", "1e5", "--clearance-pick", "mean"],
         "Error: --clearance-pick needs a bearing designation"),
        (["sweep", "-z", "8", "-F", "1kN", "-K", "1e5", "--modulus", "210GPa"],
         "Error: --modulus needs a bearing designation or the ball geometry"),
        (["sweep", "-z", "8", "-F", "1kN", "-K", "1e5", "--clearance-pick", "max"],
         "Error: --clearance-pick needs a bearing designation"),
        (["table", "k", "--clearance-pick", "min"], "Error: --clearance-pick needs '--bearing'"),
    ],
)  # fmt: skip
def test_sweep_and_table_refuse_what_a_hand_given_ring_would_ignore(capsys, args, message):
    """sweep and table k took --modulus or --clearance-pick without a bearing and ignored them;
    solve let an explicit --clearance-pick mean pass (a batch file's clearance_pick cell is
    refused): all refuse them now, as solve refused the others."""
    code, out, err = run_entry(capsys, *args)
    assert code == 2 and out == "" and err.count("\n") == 1 and err.startswith(message), err


def test_a_moment_tilting_the_ring_beyond_its_groove_is_refused(capsys):
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--moment", "1e9Nmm")
    assert code == 2 and "Invalid value for '--moment': tilts the inner ring by 39" in err


def test_a_thousands_separator_is_refused(capsys):
    code, out, err = run_entry(capsys, "solve", "-z", "8", "-F", "3,000", "-K", "1e5")
    assert code == 2 and "write no thousands separator (3000) or a decimal point (3.000)" in err


def test_an_internal_error_is_one_line_and_exit_status_3(capsys, monkeypatch):
    """A bug is told apart from skipped rows (1) and bad input (2) by its exit status."""
    import bearingload.reports.solve as report

    from .cli_helpers import run_entry

    def broken(*args, **kwargs):
        raise RuntimeError("boom")

    monkeypatch.setattr(report, "solve_report", broken)
    code, out, err = run_entry(capsys, "solve", "-z", "8", "-F", "1kN", "-K", "1e5")
    assert code == 3 and out == ""
    assert err.splitlines() == [
        "Error: internal error (RuntimeError: boom); please report it with the command line "
        "that caused it"
    ]


@pytest.mark.parametrize(
    ("args", "names"),
    [(["study"], "'NAME'. Choose from: kurochkin1973-differences, kurochkin1973-example1"),
     (["table"], "Choose from: k, kq, life")],
)  # fmt: skip
def test_a_missing_choice_argument_is_one_error_line(capsys, args, names):
    """click words a missing argument with choices over several lines ('Choose from:' then one
    tab-indented line per choice): 'bearingload study' printed six lines."""
    code, out, err = run_entry(capsys, *args)
    assert (code, out) == (2, "")
    assert err.count("\n") == 1 and err.startswith("Error: Missing argument "), err
    assert names in err


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["16005", "-F", "1kN", "--misalignment", "1e-9", "--modulus", "1e-300Pa"],
         "Invalid value for '--load': the loads and the ball stiffness give a one-ball approach"),
        (["16005", "-F", "0", "-A", "1kN", "--modulus", "1e-300Pa"],
         "Invalid value for '--load': the loads and the ball stiffness give a one-ball approach"),
        (["16005", "-F", "1kN", "--moment-cross", "1e30", "--tilt-radius", "1e-300"],
         "Invalid value for '--moment-cross': over the tilt lever (tilt_radius) it is a force"),
        (["6205", "-F", "1kN", "--moment", "0", "--tilt-radius", "1e300"],
         "Invalid value for '--tilt-radius': is so large that the tilting stiffness"),
    ],
)  # fmt: skip
def test_combined_inputs_beyond_the_numbers_are_one_error_line(args, message):
    """Absurd but accepted values (a modulus of 1e-300 Pa, a lever of 1e-300 or 1e300 mm) gave
    numpy's 'RuntimeWarning: overflow encountered in divide' before the error, 'did not converge
    after 0 iterations (relative residual nan)' (exit 1), or 'internal error (OverflowError:
    cannot convert float infinity to integer)' (exit 3: an infinite tilting stiffness)."""
    done = run_process("solve", *args)  # a fresh interpreter shows numpy's warnings
    assert (done.returncode, done.stdout) == (2, ""), done.stderr
    assert done.stderr.count("\n") == 1 and done.stderr.startswith(f"Error: {message}"), done.stderr


@pytest.mark.parametrize(
    "loads, option",
    [
        (("-F", "0", "-A", "1e-9N"), "--axial-load"),
        (("-F", "1e-9N", "-A", "0"), "--load"),
        (("-F", "0", "--moment", "1e-9Nmm"), "--moment"),
        (("-F", "0", "--moment-cross", "1e-9Nmm"), "--moment-cross"),
        (("-F", "2e-9N", "-A", "1e-9N"), "--load"),
    ],
)
def test_loads_too_small_name_the_largest_load(capsys, loads, option):
    """The refusal of loads too small for the combined solver named '--load' whatever load was
    given: solve 6205 -F 0 -A 1e-9N said "Invalid value for '--load'" for an axial load. It names
    the option of the largest load (the moments over the tilt lever)."""
    code, out, err = run_entry(capsys, "solve", "6205", *loads)
    assert code == 2 and out == ""
    assert err.startswith(f"Error: Invalid value for '{option}': the loads are too small"), err
    with pytest.raises(InputError, match="^axial_load: the loads are too small"):
        solve_combined(9, 0.0, 1e-9, **GEOMETRY)


@pytest.mark.parametrize(
    "loads, option",
    [
        (("-F", "0", "-A", "1e-9N", "--preload", "0"), "--axial-load"),
        (("-F", "1e-9N", "-A", "0", "--preload", "0"), "--load"),
        (("-F", "0", "-A", "0", "--moment", "1e-9Nm", "--preload", "0"), "--moment"),
        (("-F", "0", "-A", "0", "--preload", "1e-9N"), "--preload"),
    ],
)
def test_loads_too_small_for_a_pair_name_the_largest_load(capsys, loads, option):
    """The static pair's refusal of loads too small named radial_load ('--load') whatever load
    was given (solve 7205BDB -F 0 -A 1e-9N --preload 0 said --load for an axial load), and
    'preload' for every case of a call when one case's preload was its largest load."""
    code, out, err = run_entry(capsys, "solve", "7205BDB", *loads)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith(f"Error: Invalid value for '{option}': the loads are too small"), err
    from bearingload.models.pair import solve_pair

    ring = {"contact_angle": 40.0, "ball_diameter": 7.9375, "pitch_diameter": 38.5, "width": 15.0}
    with pytest.raises(InputError, match="^axial_load: the loads are too small"):
        # case 0 is fine with its preload its largest load; case 1 is refused for its thrust
        solve_pair(12, np.array([0.0, 0.0]), np.array([0.0, 1e-9]),
                   preload=np.array([500.0, 0.0]), **ring)  # fmt: skip


def test_another_exponent_on_a_ball_geometry_does_not_blame_a_designation(capsys):
    """solve -z 9 --ball-diameter ... --pitch-diameter ... -m 10/9 (at --speed too) was
    refused with '... not a bearing designation', though none was given: it names the ball
    geometry; a designation keeps its words."""
    ring = ("-z", "9", "--ball-diameter", "7.938", "--pitch-diameter", "38.5", "-F", "1kN")
    for extra in ((), ("--speed", "3000")):
        line = error_line(capsys, "solve", *ring, "-m", "10/9", *extra)
        assert "'--exponent'" in line and line.endswith("not its ball geometry"), line
    line = error_line(capsys, "solve", "6205", "-F", "1kN", "-m", "10/9")
    assert line.endswith("not a bearing designation"), line


def test_an_integer_beyond_the_largest_float_is_refused_in_one_line():
    """10**400 as a load escaped as an OverflowError from numpy; it is an InputError."""
    from bearingload.errors import InputError
    from bearingload.validate import finite

    with pytest.raises(InputError, match="beyond 1.8e308"):
        finite("load", 10**400)


@pytest.mark.parametrize("name", ["ball_diameter", "pitch_diameter", "f_i", "f_o", "clearance"])
def test_the_combined_solver_refuses_text_for_its_geometry(name):
    """These five went to numpy unchecked: 'C3' raised numpy's ValueError and '0.01' was taken
    as a number, where radial_load='1000' is refused; each is an InputError naming itself."""
    from bearingload.errors import InputError
    from bearingload.models.combined import solve_combined

    kw = {"ball_diameter": 7.938, "pitch_diameter": 38.5} | {name: "0.01"}
    with pytest.raises(InputError) as info:
        solve_combined(9, 1000.0, 300.0, **kw)
    assert info.value.parameter == name


def test_the_pair_solver_refuses_text_for_its_geometry():
    from bearingload.errors import InputError
    from bearingload.models.pair import solve_pair

    with pytest.raises(InputError) as info:
        solve_pair(
            12,
            1000.0,
            300.0,
            preload=300.0,
            contact_angle="40",
            ball_diameter=8.7312,
            pitch_diameter=38.5,
            width=15.0,
        )
    assert info.value.parameter == "contact_angle"


@pytest.mark.parametrize(
    "name", ["radial_load", "axial_load", "poisson", "cage_angle", "moment_cross", "clearance"]
)
def test_none_for_an_input_that_is_not_optional_is_refused_as_in_an_array(name):
    """None means "not given" only for moment, misalignment, contact_angle and stiffness; for
    any other input solve_combined refuses it, one case of plain numbers as an array of cases
    does (it was read as 0 on the one-case path)."""
    kw = dict(GEOMETRY, radial_load=1000.0, axial_load=100.0) | {name: None}
    with pytest.raises(InputError) as one:
        solve_combined(9, **kw)
    assert one.value.parameter == name
    other = "axial_load" if name == "radial_load" else "radial_load"
    with pytest.raises(InputError) as many:
        solve_combined(9, **(kw | {other: np.array([kw[other]])}))
    assert many.value.parameter == name


@pytest.mark.parametrize("name", ["radial_load", "axial_load", "cage_angle"])
def test_none_at_speed_is_refused_naming_its_input(name):
    """solve_high_speed passes these to solve_combined: a None read as 0 there met a NaN of
    its own later (radial_load=None blamed moment_cross, cage_angle=None a bare ValueError)."""
    kw = dict(GEOMETRY, radial_load=1000.0, axial_load=100.0, contact_angle=25.0) | {name: None}
    with pytest.raises(InputError) as exc:
        solve_high_speed(9, speed=5000.0, **kw)
    assert exc.value.parameter == name


def test_a_poisson_ratio_out_of_range_is_shown_as_a_number_not_an_array_repr():
    """The refusal read ``got array(-1.)`` for a 0-d array (validate.require took its repr)."""
    import numpy as np

    from bearingload.contact import hertz
    from bearingload.errors import InputError

    with pytest.raises(InputError) as info:
        hertz.reduced_modulus(2.08e5, np.asarray(-1.0))
    assert info.value.message == "must be between -1 and 0.5; got -1"


@pytest.mark.parametrize(
    "value, shown",
    [(1000 + 0j, "(1000+0j)"), (None, "None"), (np.array([1000.0, 1 + 1j]), "(1000+0j)")],
)
def test_a_complex_load_or_none_is_refused_as_not_a_number(value, shown):
    """A complex load was taken as its real part (with numpy's ComplexWarning) and None
    was read as NaN ("got NaN or infinity")."""
    with pytest.raises(
        InputError, match=rf"radial_load.*must be a number \(got {re.escape(shown)}\)"
    ):
        solve_combined(9, value, 100.0, ball_diameter=7.938, pitch_diameter=38.5)


@pytest.mark.parametrize(
    "value, shown",
    [
        (
            [1000.0, 2000 + 0j],
            r"radial_load\[1\] = \(2000\+0j\): must be a number \(got \(2000\+0j\)\)",
        ),
        ([1000.0, "2000"], r"radial_load\[1\] = '2000': must be a number \(got '2000'\)"),
        ([1000.0, 10**400], r"radial_load\[1\] = 1000+: must be a number"),
        ([[1000.0, 2000.0], [3000.0]], r"radial_load: must be a number or an array of numbers"),
    ],
)
def test_a_list_with_one_element_not_a_number_names_that_element(value, shown):
    """A list mixing floats with a complex number or text was read whole as complex or text:
    the refusal named its first element (1000.0, shown as '1000.0'), not the bad one; an
    integer beyond a double's range in a list, or lists of unequal lengths, raised numpy's
    OverflowError/ValueError instead of an InputError."""
    with pytest.raises(InputError, match=shown):
        solve_combined(9, value, 100.0, ball_diameter=7.938, pitch_diameter=38.5)


@pytest.mark.parametrize(
    "value, shown",
    [(np.array(1000 + 0j), "(1000+0j)"), (np.array("1000"), "'1000'"), (np.array(None), "None")],
)
def test_a_zero_dimensional_array_not_a_number_is_shown_as_its_value(value, shown):
    """A 0-d array of a complex number, text or None was refused showing numpy's repr
    (array(1000.+0.j)), not the value."""
    with pytest.raises(InputError) as info:
        solve_combined(9, value, 100.0, ball_diameter=7.938, pitch_diameter=38.5)
    assert f"must be a number (got {shown})" in str(info.value)
    assert "array(" not in str(info.value)


PAIR_GEOMETRY = {**GEOMETRY, "contact_angle": 40.0, "width": 15.0, "preload": 100.0}

#: Each model's call with its radial load given as ``v``.
LOAD_CALLS = {
    "solve": (lambda v: solve(8, v, 1e5), "load"),
    "solve_combined": (lambda v: solve_combined(9, v, 100.0, **GEOMETRY), "radial_load"),
    "solve_pair": (lambda v: solve_pair(12, v, 100.0, **PAIR_GEOMETRY), "radial_load"),
    "solve_high_speed": (
        lambda v: solve_high_speed(9, v, 100.0, speed=5000.0, contact_angle=25.0, **GEOMETRY),
        "radial_load",
    ),
    "analyse": (lambda v: analyse("6205", load=v), "load"),
    "analyse a pair": (lambda v: analyse("7205BDB", load=v), "load"),
}


@pytest.mark.parametrize("call", LOAD_CALLS, ids=str)
@pytest.mark.parametrize(
    "value",
    [
        np.datetime64("2020"),
        np.timedelta64(3, "s"),
        np.array(["2020-01-01"], dtype="datetime64[D]"),
        [1000.0, np.datetime64("2020")],
        True,
        np.True_,
        [1000, True],
        [1000.0, np.True_],
        np.array([1000, True], dtype=object),
    ],
    ids=repr,
)
def test_a_date_or_a_boolean_load_is_refused_as_not_a_number(call, value):
    """numpy reads a date as a number (np.datetime64('2020') as 50, years since 1970), a time
    span as its count (3 s as 3), and a boolean among numbers as 0 or 1 ([1000, True] as
    [1000, 1]): every model solved them (analyse took a time span to a TypeError, and a date
    as 'not an array'). A boolean alone was refused already; among numbers it is now too."""
    solve_with, name = LOAD_CALLS[call]
    with pytest.raises(InputError) as info:
        solve_with(value)
    assert info.value.parameter == name
    assert re.search("must be a number|give a number, not an array", info.value.message)


@pytest.mark.parametrize(
    "value, named",
    [
        ([1000, True], "radial_load[1] = True: must be a number, not a boolean (got True)"),
        (True, "radial_load: must be a number, not a boolean (got True)"),
        (
            [1000.0, np.datetime64("2020")],
            "radial_load[1] = np.datetime64('2020'): must be a number (got np.datetime64('2020'))",
        ),
    ],
)
def test_a_boolean_or_a_date_among_numbers_names_its_element(value, named):
    """A boolean is refused with the same words alone or in a list, its element named as any
    refused element is."""
    with pytest.raises(InputError) as info:
        solve_combined(9, value, 100.0, **GEOMETRY)
    assert str(info.value).startswith(named), str(info.value)


@pytest.mark.parametrize("value", [True, np.datetime64("2020"), "1000", [3000.0, True]], ids=repr)
def test_a_life_or_lubrication_input_that_is_not_a_number_is_refused(value):
    """The life and lubrication functions check their inputs with
    ``validate.finite_positive``, which read them with numpy alone: a boolean as 1, a date as
    its years since 1970, the text "1000" as 1000.0, and each gave a life."""
    from bearingload.bearings.life import rating_life
    from bearingload.bearings.lubrication import rated_viscosity

    with pytest.raises(InputError) as info:
        rating_life(value, 1000.0)
    assert info.value.parameter == "C"
    assert "must be a number" in info.value.message
    with pytest.raises(InputError, match="must be a number"):
        rated_viscosity(value, 38.5)


@pytest.mark.parametrize(
    "value, named",
    [
        ([np.array(1000.0), np.array(True)], "radial_load[1] = True: must be a number, not a bool"),
        ([np.array("1000"), 2000.0], "radial_load[0] = '1000': must be a number (got '1000')"),
        ([1000.0, np.array(1 + 0j)], "radial_load[1] = (1+0j): must be a number (got (1+0j))"),
        ([1000.0, np.array(None)], "radial_load[1] = None: must be a number (got None)"),
        ([np.array(np.datetime64("2020"))], "radial_load: must be a number (got np.datetime64("),
    ],
    ids=repr,
)
def test_an_array_of_no_dimension_in_a_list_is_judged_by_its_value(value, named):
    """numpy keeps a 0-d array in a list as the array (not its value), which
    ``validate.not_real`` did not look into: [np.array(1000.0), np.array(True)] was solved as
    [1000, 1], [np.array("1000")] as 1000, a date as 50, a complex number with numpy's
    ComplexWarning, None as a NaN. Each is now refused as the value it holds."""
    with pytest.raises(InputError) as info:
        solve_combined(9, value, 100.0, **GEOMETRY)
    assert str(info.value).startswith(named), str(info.value)
