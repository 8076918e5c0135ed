"""``bearingload table life`` of a bearing pair (7205BDB --preloads ...): every row is the pair
``solve --preload`` gives at that preload (csv line for line, json key for key), the note names
the preload of the longest L10r, and what it cannot take is one Error line; a single
angular-contact bearing is refused with the way to the pair's table."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from bearingload.cli import main

PAIR = ["-b", "7205BDB", "-F", "1kN", "-A", "200N"]
PRELOADS = ["0", "100N", "300N", "1kN"]


def _run(*args: str):
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


def _solve(preload: str, *extra: str):
    out = _run("solve", "7205BDB", "-F", "1kN", "-A", "200N", "--preload", preload, *extra)
    assert out.exit_code == 0
    return out.stdout


@pytest.mark.parametrize("args", [PAIR, ["-b", "7205B", "--arrangement", "DF", "-F", "1kN", "-A",
                                         "200N"]])  # fmt: skip
def test_every_row_is_solves_pair_at_that_preload(args):
    out = _run("table", "life", *args, "--preloads", ",".join(PRELOADS), "--format", "csv")
    assert out.exit_code == 0, out.stderr
    lines = out.stdout.splitlines()
    assert len(lines) == 1 + 2 * len(PRELOADS)
    for k, fp in enumerate(PRELOADS):
        solved = _run("solve", *args[1:], "--preload", fp, "--format", "csv")
        assert solved.stdout.splitlines() == [lines[0], *lines[1 + 2 * k : 3 + 2 * k]]


def test_json_rows_and_the_table_show_solves_values_and_name_the_longest_life():
    doc = json.loads(_run("table", "life", *PAIR, "--preloads", ",".join(PRELOADS), "--format",
                          "json").stdout)  # fmt: skip
    lives = []
    for fp, row in zip(PRELOADS, doc["rows"], strict=True):
        case = json.loads(_solve(fp, "--format", "json"))["cases"][0]
        assert {k: v for k, v in row.items() if k != "bearings"} == {k: case[k] for k in row
                                                                     if k != "bearings"}  # fmt: skip
        for mine, theirs in zip(row["bearings"], case["bearings"], strict=True):
            assert mine == {k: theirs[k] for k in mine}
        lives.append(row["reference_rating_life"])
    assert [r["preload"] for r in doc["rows"]] == [0.0, 100.0, 300.0, 1000.0]
    assert lives.index(max(lives)) == 2
    text = _run("table", "life", *PAIR, "--preloads", ",".join(PRELOADS)).stdout
    lines = text.splitlines()
    assert lines[0] == (
        "Life against the preload: bearings 7205B, pair DB (back-to-back), z = 12 per bearing, "
        "F_r = 1000 N, F_a = 200 N, inner ring rotating"
    )
    assert lines[2].split() == ["F_p", "[N]", "Q_max", "1", "[N]", "Q_max", "2", "[N]", "n",
                                "1", "n", "2", "k_a", "[N/mm]", "k_r", "[N/mm]", "lift-off",
                                "[N]", "L10r", "[10^6", "rev]", "L10", "ISO", "281", "[10^6",
                                "rev]"]  # fmt: skip
    row = lines[6].split()
    r = doc["rows"][2]
    assert [float(x) for x in row] == pytest.approx(
        [300.0, r["bearings"][0]["q_max"], r["bearings"][1]["q_max"],
         r["bearings"][0]["loaded_balls"], r["bearings"][1]["loaded_balls"],
         r["stiffness_axial"], r["stiffness_radial"], r["lift_off_axial_load"],
         r["reference_rating_life"], r["rating_life"]], rel=5e-6)  # fmt: skip
    assert lines[-1] == (
        f"Among these rows the pair's L10r is longest at F_p = 300 N ({max(lives):.6g} 10^6 "
        "rev): too little preload lets a bearing unload (its balls may skid), too much loads "
        "both; the stiffness grows with the preload."
    )


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["-b", "7205B", "-F", "1kN"],
         "Invalid value for '--bearing': '7205B' is an angular-contact bearing, solved by "
         "'solve', 'sweep' and 'batch', not by 'table life': its rows are radial clearances, "
         "and the contact angle fixes an angular-contact bearing's geometry (no clearance); "
         "for a pair, 'table life -b 7205BDB --preloads 0,100N,300N' gives L10r against the "
         "preload (docs/angular_contact.md)"),
        (PAIR,
         "Missing option '--preloads' (table life of a pair runs over the preload; give the "
         "rows, e.g. '--preloads' 0,100N,300N,1kN)"),
        (["-b", "7205BDT", "-F", "1kN", "-A", "1kN", "--preloads", "0,100N"],
         "Invalid value for '--bearing': a tandem pair (DT) is not preloaded in itself (it "
         "is preloaded against another bearing): table life of a pair runs over the preload of "
         "DB or DF"),
        # a tandem pair is refused before the rows are asked for: no preload would do
        (["-b", "7205BDT", "-F", "1kN", "-A", "100N"],
         "Invalid value for '--bearing': a tandem pair (DT) is not preloaded in itself (it "
         "is preloaded against another bearing): table life of a pair runs over the preload of "
         "DB or DF"),
        (["-b", "7205B", "--arrangement", "DT", "-F", "1kN", "-A", "100N"],
         "Invalid value for '--arrangement': a tandem pair (DT) is not preloaded in itself (it "
         "is preloaded against another bearing): table life of a pair runs over the preload of "
         "DB or DF"),
        (["-b", "6205", "-F", "1kN", "--preloads", "0,1kN"],
         "--preloads needs a bearing pair ('--bearing' 7205BDB, or '--arrangement' DB or DF), "
         "whose table life runs over them; without one it would be ignored"),
        (["-b", "6205", "--arrangement", "DB", "-F", "1kN", "--preloads", "0,1kN"],
         "Invalid value for '--arrangement': a pair DB is two angular-contact ball bearings; "
         "give an angular-contact designation (7205B, 7205BDB) or a ring by hand with "
         "'--contact-angle'"),
        ([*PAIR, "--preloads", "0,-5N"],
         "Invalid value for '--preloads': each must be 0 N or more (got -5 N)"),
        ([*PAIR, "--preloads", "0,100N", "--preload", "100N"],
         "--preload cannot be used with table life of a pair: its rows are preloads "
         "('--preloads')"),
        ([*PAIR, "--preloads", "0,100N", "--clearances", "0,10um"],
         "--clearances cannot be used with table life of a pair: a pair's rows are preloads "
         "('--preloads')"),
        ([*PAIR, "--preloads", "0,100N", "--speed", "3000", "--viscosity", "20cSt"],
         "--viscosity cannot be used with table life of a pair: its service lives beyond the "
         "hours are not yet tabulated; 'bearingload solve 7205BDB --preload ...' gives them for "
         "one preload"),
        ([*PAIR, "--preloads", "0,100N", "--misalignment", "1mrad"],
         "--misalignment cannot be used with a bearing pair: the shaft's tilt follows from the "
         "loads; give '--moment'"),
    ],
)  # fmt: skip
def test_what_table_life_of_a_pair_cannot_take_is_one_error_line(args, message):
    out = _run("table", "life", *args)
    assert out.exit_code == 2
    assert out.stdout == ""
    assert out.stderr.splitlines()[-1] == f"Error: {message}"


def test_table_k_refuses_a_pair():
    out = _run("table", "k", "-b", "7205BDB")
    assert out.exit_code == 2
    assert out.stderr.splitlines()[-1].startswith(
        "Error: --bearing cannot be used with table k: a bearing pair has no table over z; "
        "table k and kq are the papers' radial"
    )
