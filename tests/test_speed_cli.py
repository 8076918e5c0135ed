"""``bearingload solve --speed`` with the ball dynamics: options that the dynamics cannot honour
are refused with one ``Error:`` line naming them, never silently ignored."""

from __future__ import annotations

import json

from .cli_helpers import run_entry

BASE = ("solve", "7205B", "-F", "500N", "-A", "1kN", "--speed", "20000")


def _error_line(capsys, *args: str) -> str:
    code, out, err = run_entry(capsys, *args)
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and lines[0].startswith("Error:"), err
    return lines[0]


def test_outer_ring_rotating_is_refused_with_the_ball_dynamics(capsys):
    # the dynamics are coded for the inner ring turning; --rotating outer was accepted and the
    # cage speed and centrifugal forces of the inner ring turning silently used
    line = _error_line(capsys, *BASE, "--rotating", "outer")
    assert "--rotating" in line and "--quasi-static" in line
    code, out, _ = run_entry(capsys, *BASE, "--rotating", "outer", "--quasi-static",
                             "--format", "json")  # fmt: skip
    assert code == 0 and json.loads(out)["cases"][0]["rotating"] == "outer"


def test_given_stiffness_is_refused_in_the_words_of_the_command_line(capsys):
    # the refusal named the library's argument: 'ask for the static model (speed None)'
    line = _error_line(capsys, *BASE, "--stiffness", "3e5")
    assert "--stiffness" in line and "--quasi-static" in line and "None" not in line
    code, _, _ = run_entry(capsys, *BASE, "--stiffness", "3e5", "--quasi-static")
    assert code == 0


def test_outer_contact_pressure_is_that_of_the_outer_loads(capsys):
    # at speed the outer contacts carry the centrifugal force (Q_o > Q_i), but p_max_outer was
    # computed from the inner loads at the inner angles: 1086.5 MPa for 7205B under 1 kN thrust
    # at 20 000 rpm, below the static 1111.3 MPa, while its outer contacts carry 148.9 N
    # against 127.3 N static
    import numpy as np

    from bearingload.bearings.checks import contact_pressures
    from bearingload.bearings.resolve import resolve_bearing

    code, out, err = run_entry(capsys, "solve", "7205B", "-F", "0", "-A", "1kN", "--speed",
                               "20000", "--format", "json")  # fmt: skip
    assert code == 0, err
    case = json.loads(out)["cases"][0]
    b = resolve_bearing("7205B")
    q_o, a_o = np.array(case["ball_loads_outer"]), np.array(case["contact_angles_outer"])
    q_i, a_i = np.array(case["ball_loads_inner"]), np.array(case["contact_angles_inner"])
    assert np.all(q_o > q_i)
    p_o = float(np.max(contact_pressures(b, q_o, a_o)[1]))
    p_i = float(np.max(contact_pressures(b, q_i, a_i)[0]))
    assert abs(case["p_max_outer"] - p_o) <= 1e-8 * p_o
    assert abs(case["p_max_inner"] - p_i) <= 1e-8 * p_i
    code, out, _ = run_entry(capsys, "solve", "7205B", "-F", "0", "-A", "1kN", "--format", "json")
    assert case["p_max_outer"] > json.loads(out)["cases"][0]["p_max_outer"]


def test_per_ball_csv_carries_the_inner_and_outer_contacts(capsys):
    """--per-ball csv at speed has each ball's inner and outer contact angle and load, the json
    arrays of the same names (they were in the json only); one rectangular table."""
    import csv
    import io

    args = ("solve", "7205B", "-F", "1kN", "-A", "1kN", "--speed", "20000")
    code, text, err = run_entry(capsys, *args, "--per-ball", "--format", "csv")
    assert code == 0, err
    rows = list(csv.reader(io.StringIO(text)))
    assert len({len(r) for r in rows}) == 1 and len(rows) == 13
    head = [h.split(" [")[0] for h in rows[0]]
    code, doc, err = run_entry(capsys, *args, "--format", "json")
    case = json.loads(doc)["cases"][0]
    for key in ("contact_angles_inner", "contact_angles_outer", "ball_loads_inner",
                "ball_loads_outer"):  # fmt: skip
        got = [float(r[head.index(key)]) for r in rows[1:]]
        assert got == case[key], key
    assert case["ball_loads_outer"] != case["ball_loads_inner"]


def test_help_of_speed_says_which_command_solves_the_ball_dynamics(capsys):
    """--speed's help (one text for solve, sweep and table) says that solve, sweep and table
    life include the ball dynamics (it said 'a combined or angular-contact solve includes' them
    in all three; then that sweep and table solve the static model); all three list
    --quasi-static and --ball-density (table life takes them)."""

    def options(command: str) -> dict[str, str]:
        code, out, _ = run_entry(capsys, *command.split(), "--help")
        assert code == 0
        found: dict[str, str] = {}
        for line in out.split("Options:", 1)[1].splitlines():
            if line.startswith("  -"):  # an option's first line; its text goes on indented
                name = next(w for w in line.split() if w.startswith("--")).rstrip(",")
                found[name] = line
            elif found:
                found[name] += ("" if found[name].endswith("-") else " ") + line.strip()
        return found

    for command in ("solve", "sweep", "table k"):
        found = options(command)
        assert "In 'solve', 'sweep' and 'table life' a ball bearing includes" in found["--speed"]
        assert "solves the static model" not in found["--speed"], command
        assert "--quasi-static" in found and "--ball-density" in found, command


def test_a_loaded_inner_contact_at_90_degrees_is_warned(capsys):
    """solve 7205B -F 1kN -A 1kN --speed 50000 held balls 6-8 loaded (115-125 N) on the side of
    the inner groove (inner contact angle 90°) without a word: the model's known limit (Jones's
    relations there overstate the orbit speed); it now warns, naming the balls, in a pair too;
    none where every loaded inner contact is below 90°."""
    code, out, err = run_entry(capsys, "solve", "7205B", "-F", "1kN", "-A", "1kN", "--speed",
                               "50000", "--format", "json")  # fmt: skip
    assert code == 0
    case = json.loads(out)["cases"][0]
    side = [j + 1 for j, (a, q) in enumerate(zip(case["contact_angles_inner"],
            case["ball_loads_inner"], strict=True)) if q > 0 and a >= 90.0 - 1e-9]  # fmt: skip
    assert side == [6, 7, 8]
    assert "Warning: ball(s) 6, 7, 8: the loaded inner contact sits at 90°" in err
    code, _, err = run_entry(capsys, "solve", "7205BDT", "-F", "10N", "-A", "10N", "--speed",
                             "51948")  # fmt: skip
    assert (
        code == 0 and "Warning: bearing 2: ball(s) 7: the loaded inner contact sits at 90°" in err
    )
    code, _, err = run_entry(capsys, "solve", "7205B", "-F", "1kN", "-A", "1kN", "--speed", "5000")
    assert code == 0 and "inner contact sits at 90°" not in err


def test_a_speed_of_0_says_what_a_shaft_at_rest_is(capsys):
    """--speed 0 was refused as 'must be greater than 0 rpm' alone: the user means a shaft at
    rest, which is the case without --speed (the ball dynamics at 0 rpm are the static model,
    tests/test_high_speed.py); the message says so (batch: a blank cell)."""
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--speed", "0")
    assert code == 2 and out == ""
    assert err.strip().splitlines()[-1] == (
        "Error: Invalid value for '--speed': must be greater than 0 rpm (got 0): a shaft at rest "
        "is the case without '--speed': the static model (the answer of the ball dynamics at 0 "
        "rpm), its lives in 10^6 revolutions, none in hours"
    )
    code, _, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--speed", "-5")
    assert err.strip().splitlines()[-1].endswith("must be greater than 0 rpm (got -5)")
    from click.testing import CliRunner

    from bearingload.cli import main

    batch = CliRunner().invoke(main, ["batch", "-", "--format", "csv"],
                               input="bearing,load,speed\n6205,1kN,0\n")  # fmt: skip
    assert batch.exit_code == 1
    assert batch.stderr.splitlines()[0] == (
        "Skipped: row 2: speed: must be greater than 0 rpm (got 0): a shaft at rest is the case "
        "without 'speed': the static model (the answer of the ball dynamics at 0 rpm), its lives "
        "in 10^6 revolutions, none in hours"
    )


def test_unloaded_ball_note_at_speed_names_the_inner_contact(capsys):
    """At speed a '-' ball's outer contact carries its centrifugal force (json: ball_loads_outer
    > 0 where ball_loads_inner is 0); the note said 'the ball carries no load'. It now says the
    inner contact carries none; the static note is unchanged."""
    import json

    args = ("solve", "6205", "-F", "1kN")
    code, out, _ = run_entry(capsys, *args, "--speed", "3000", "--format", "json")
    case = json.loads(out)["cases"][0]
    loose = [i for i, q in enumerate(case["ball_loads_inner"]) if q == 0.0]
    assert loose and all(case["ball_loads_outer"][i] > 0.0 for i in loose)
    code, out, _ = run_entry(capsys, *args, "--speed", "3000")
    assert code == 0 and "the ball carries no load" not in out
    assert "Contact angle '-': the ball's inner contact carries no load" in out
    assert "outer contact still carries the centrifugal force" in out
    code, out, _ = run_entry(capsys, *args, "-A", "0")
    assert code == 0 and "Contact angle '-': the ball carries no load" in out
    assert "inner contact" not in out
