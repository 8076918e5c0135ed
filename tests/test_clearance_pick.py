"""--clearance-pick picks within a clearance class; where the case has none it is refused
instead of silently ignored (a review found 'solve 6205 -F 1kN -G 10um --clearance-pick max'
and every angular-contact solve accepting it and printing the same answer)."""

from __future__ import annotations

import pytest

from .cli_helpers import run_entry


@pytest.mark.parametrize(
    "args, why",
    [
        (["solve", "6205", "-F", "1kN", "-G", "10um"], "one value, no class (G_r = 10 µm)"),
        (["solve", "-z", "9", "--ball-diameter", "7.938", "--pitch-diameter", "38.5", "-F", "1kN"],
         "one value, no class (G_r = 0 µm)"),
        (["solve", "7205B", "-F", "1kN", "-A", "1kN"], "angular-contact bearing has no radial"),
        (["solve", "7205BDB", "-F", "1kN"], "angular-contact bearing has no radial"),
        (["sweep", "6205", "-F", "1kN", "-G", "10um"], "one value, no class"),
    ],
)  # fmt: skip
def test_clearance_pick_without_a_class_is_refused(capsys, args, why):
    code, out, err = run_entry(capsys, *args, "--clearance-pick", "max")
    assert code == 2 and out == "", err
    assert err.startswith("Error: Invalid value for '--clearance-pick'"), err
    assert why in err and err.count("\n") == 1


def test_clearance_pick_within_a_class_still_picks(capsys):
    code, mean, _ = run_entry(capsys, "solve", "6205", "-F", "1kN", "-G", "C3", "--format", "csv")
    high = run_entry(capsys, "solve", "6205", "-F", "1kN", "-G", "C3", "--clearance-pick", "max",
                     "--format", "csv")  # fmt: skip
    assert code == 0 and high[0] == 0 and high[1] != mean


@pytest.mark.parametrize("designation", ["7205B/C3", "7205B C3", "7205BEPC3", "7205C/CN"])
def test_a_clearance_suffix_on_an_angular_bearing_is_refused(capsys, designation):
    """'7205B/C3' was read past its C3 and solved as 7205B: a clearance class the bearing does
    not have, silently dropped."""
    code, out, err = run_entry(capsys, "solve", designation, "-F", "1kN", "-A", "1kN")
    assert code == 2 and out == "" and err.count("\n") == 1, err
    assert "is a radial clearance class" in err


@pytest.mark.parametrize("designation", ["7205BECBP", "7205B-TVP", "7205CN"])
def test_maker_suffixes_are_still_read_past(capsys, designation):
    code, _, err = run_entry(capsys, "solve", designation, "-F", "1kN", "-A", "1kN")
    assert code == 0, err
