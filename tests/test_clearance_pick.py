"""--clearance-pick picks within a clearance class; where the case has none it is refused
instead of silently ignored (a review found 'solve 6205 -F 1kN -G 10um --clearance-pick max'
and every angular-contact solve accepting it and printing the same answer)."""

from __future__ import annotations

import json

import pytest

from .cli_helpers import error_line, run_entry, warnings_of


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


def test_table_life_refuses_a_pick_its_rows_ignore(capsys):
    """table life runs over its own clearances (--clearances): --clearance-pick printed the
    same table as without it."""
    code, out, err = run_entry(capsys, "table", "life", "-b", "6205", "-F", "1kN",
                               "--clearance-pick", "max")  # fmt: skip
    assert code == 2 and out == "", err
    assert err == (
        "Error: --clearance-pick cannot be used with table life: its rows are clearances "
        "('--clearances'), no class to pick in\n"
    )


def test_batch_refuses_a_pick_without_a_class_as_solve_does(capsys):
    """A batch row whose clearance_pick has no class to pick in (a clearance given as a length,
    an angular-contact bearing) is skipped with solve's reason: it was silently ignored (the
    row written, clearance_pick blank); a row with a class still picks."""
    import json

    from click.testing import CliRunner

    from bearingload.cli import main

    rows = ("bearing,load,axial_load,clearance,clearance_pick\n6205,1kN,,10um,max\n"
            "7205B,1kN,0,,max\n6205,1kN,,C3,max\n6205,1kN,200N,10um,min\n")  # fmt: skip
    found = CliRunner().invoke(main, ["batch", "-", "--format", "json"], input=rows)
    code, out, err = found.exit_code, found.stdout, found.stderr
    assert code == 1
    doc = json.loads(out)
    assert [c["row"] for c in doc["cases"]] == [4]
    assert doc["cases"][0]["clearance"] == pytest.approx(0.028)
    skipped = [line for line in err.splitlines() if line.startswith("Skipped: row")]
    assert skipped == [
        "Skipped: row 2: clearance_pick: it picks the min, mean or max of a clearance class ('clear"
        "ance' CN, C3 ... of a catalogue bearing); this case's clearance is one value, no "
        "class (G_r = 10 µm), so it would be ignored",
        "Skipped: row 3: clearance_pick: it picks the min, mean or max of a clearance class ('clear"
        "ance' CN, C3 ... of a catalogue bearing); an angular-contact bearing has no "
        "radial clearance, so it would be ignored",
        "Skipped: row 5: clearance_pick: it picks the min, mean or max of a clearance class ('clear"
        "ance' CN, C3 ... of a catalogue bearing); this case's clearance is one value, no "
        "class (G_r = 10 µm), so it would be ignored",
    ]


def test_table_life_clearance_pick_range_is_refused_as_every_pick(capsys):
    """table life --clearance-pick range said 'table life takes min, mean or max', which it
    refuses too: it gets the one refusal of every pick."""
    line = error_line(
        capsys, "table", "life", "-b", "6205", "-F", "1kN", "--clearance-pick", "range"
    )
    assert line == error_line(
        capsys, "table", "life", "-b", "6205", "-F", "1kN", "--clearance-pick", "max"
    )
    assert "takes min, mean or max" not in line
    assert "takes min, mean or max" in error_line(capsys, "table", "k", "--clearance-pick", "range")


def test_the_warnings_of_a_clearance_range_at_speed_name_their_pick(capsys):
    """solve 6205 -F 30kN -G C3 --clearance-pick range --speed 20000 (the combined engine with
    the ball dynamics) printed the contact pressure warning of each pick three times unlabelled;
    the static radial solve of the same range labels them 'G_r min: ...'. They are labelled as
    there, a warning every pick shares given once; json lists the printed lines; -A 0 too."""
    case = ("solve", "6205", "-F", "30kN", "-G", "C3", "--clearance-pick", "range")
    _, _, static = run_entry(capsys, *case, "--speed", "20000", "--quasi-static")
    for extra in (("--speed", "20000"), ("-A", "0")):
        code, _, err = run_entry(capsys, *case, *extra)
        found = warnings_of(err)
        pressures = [w for w in found if "maximum contact pressure" in w]
        assert code == 0 and len(pressures) == 3, err
        assert [w.split(":", 1)[0] for w in pressures] == ["G_r min", "G_r mean", "G_r max"]
        labels = [w.split(":", 1)[0] for w in warnings_of(static) if "contact pressure" in w]
        assert labels == ["G_r min", "G_r mean", "G_r max"]
        assert len(set(found)) == len(found) and any(w.startswith("static safety") for w in found)
        code, out, err = run_entry(capsys, *case, *extra, "--format", "json")
        assert json.loads(out)["warnings"] == warnings_of(err) == found
