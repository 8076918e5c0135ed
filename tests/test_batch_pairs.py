"""``bearingload batch`` with bearing pairs (an ``arrangement``, ``preload`` or ``width``
column): each row writes exactly the csv rows ``solve`` writes for the same pair (one per
bearing), rows of one group are one vectorised call whose answer is each row's alone, bad rows
are skipped with their reason, and a header a pair cannot take is refused."""

from __future__ import annotations

import csv
import json

import pytest
from click.testing import CliRunner

from bearingload.cli import main

from .cli_helpers import SolvedRows, besides_tilt

#: (batch cells, solve options) of one pair each: the suffix or the column, DB, DF, DT, a
#: reversed thrust, no preload (a bearing lifted off), a moment, a cross moment, 'half', C_r,
#: a tilt radius, a ring given by hand with its width, the outer ring rotating.
CASES = [
    ({"bearing": "7205BDB", "preload": "500N", "load": "2kN", "axial_load": "1kN"},
     ["7205BDB", "--preload", "500N", "-F", "2kN", "-A", "1kN"]),
    ({"bearing": "7205B", "arrangement": "DB", "preload": "500N", "load": "1kN",
      "axial_load": "200N"},
     ["7205B", "--arrangement", "DB", "--preload", "500N", "-F", "1kN", "-A", "200N"]),
    ({"bearing": "7205B", "arrangement": "df", "preload": "300N", "load": "1kN",
      "axial_load": "-200N", "cage_angle": "half"},
     ["7205B", "--arrangement", "DF", "--preload", "300N", "-F", "1kN", "-A", "-200N",
      "--cage-angle", "half"]),
    ({"bearing": "7205BDT", "load": "1kN", "axial_load": "500N", "rotating": "outer"},
     ["7205BDT", "-F", "1kN", "-A", "500N", "--rotating", "outer"]),
    ({"bearing": "7205BDB", "load": "3kN", "axial_load": "2kN"},
     ["7205BDB", "-F", "3kN", "-A", "2kN"]),
    ({"bearing": "7205BDB", "preload": "100N", "load": "0", "axial_load": "1kN"},
     ["7205BDB", "--preload", "100N", "-F", "0", "-A", "1kN"]),
    ({"bearing": "7205BDB", "preload": "200N", "load": "1kN", "moment": "5Nm",
      "tilt_radius": "pitch"},
     ["7205BDB", "--preload", "200N", "-F", "1kN", "--moment", "5Nm", "--tilt-radius", "pitch"]),
    ({"bearing": "7205BDB", "preload": "200N", "load": "1kN", "moment_cross": "2Nm",
      "dynamic_rating": "15kN"},
     ["7205BDB", "--preload", "200N", "-F", "1kN", "--moment-cross", "2Nm",
      "--dynamic-rating", "15kN"]),
    ({"balls": "13", "ball_diameter": "7.938", "pitch_diameter": "38.5", "contact_angle": "25",
      "arrangement": "DB", "preload": "400N", "width": "15mm", "load": "2kN", "axial_load": "500N"},
     ["-z", "13", "--ball-diameter", "7.938", "--pitch-diameter", "38.5", "--contact-angle",
      "25", "--arrangement", "DB", "--preload", "400N", "--width", "15mm", "-F", "2kN", "-A",
      "500N"]),
    ({"bearing": "7205BDB", "preload": "500N", "load": "0", "axial_load": "0"},
     ["7205BDB", "--preload", "500N", "-F", "0", "-A", "0"]),
]  # fmt: skip
HEAD = ("bearing", "balls", "ball_diameter", "pitch_diameter", "contact_angle", "arrangement",
        "preload", "width", "load", "axial_load", "moment", "moment_cross", "tilt_radius",
        "dynamic_rating", "cage_angle", "rotating")  # fmt: skip


def _file(cases: list[dict[str, str]], head: tuple[str, ...] = HEAD) -> str:
    lines = [",".join(head)] + [",".join(c.get(k, "") for k in head) for c in cases]
    return "\n".join(lines) + "\n"


def _batch(text: str, *args: str):
    return SolvedRows(
        CliRunner().invoke(main, ["batch", "-", *args], input=text, catch_exceptions=False)
    )


def _solve_csv(options: list[str]) -> list[str]:
    out = CliRunner().invoke(main, ["solve", *options, "--format", "csv"],
                             catch_exceptions=False)  # fmt: skip
    assert out.exit_code == 0, out.stderr
    return out.stdout.splitlines()


def test_every_row_writes_the_csv_rows_of_solve():
    out = _batch(_file([c for c, _ in CASES]), "--format", "csv")
    assert out.exit_code == 0, out.stderr
    lines = out.stdout.splitlines()
    assert len(lines) == 1 + 2 * len(CASES)
    for k, (_, options) in enumerate(CASES):
        solved = _solve_csv(options)
        head = [h for h in csv.reader([lines[0]])][0][1:]
        for j in (1, 2):
            got = dict(zip(head, next(csv.reader([lines[2 * k + j]]))[1:], strict=True))
            want = dict(zip(next(csv.reader([solved[0]])), next(csv.reader([solved[j]])),
                            strict=True))  # fmt: skip
            assert next(csv.reader([lines[2 * k + j]]))[0] == str(k + 2)
            assert {h: got[h] for h in want} == want, (k, j)
            assert all(got[h] == "" for h in head if h not in want), (k, j)


def test_a_file_without_moment_cross_has_exactly_solves_header():
    cases = [CASES[0][0], CASES[2][0]]
    head = tuple(h for h in HEAD if h != "moment_cross")
    out = _batch(_file(cases, head), "--format", "csv")
    assert out.exit_code == 0, out.stderr
    lines = out.stdout.splitlines()
    solved = _solve_csv(CASES[0][1])
    assert lines[0] == "row," + solved[0]
    assert lines[1:3] == ["2," + line for line in solved[1:]]


def test_a_file_with_moment_cross_has_exactly_solves_header():
    """A file with a moment_cross column wrote a bearing's 'moment_cross [N mm]' column, blank
    in every row, which solve 7205BDB --moment-cross does not write (the pair's cross moment is
    pair_moment_cross): the header differed from solve's for the same pair."""
    cross = next(c for c in CASES if "moment_cross" in c[0])
    out = _batch(_file([CASES[0][0], cross[0]]), "--format", "csv")
    assert out.exit_code == 0, out.stderr
    lines = out.stdout.splitlines()
    solved = _solve_csv(cross[1])
    assert lines[0] == "row," + solved[0]
    assert lines[3:5] == ["3," + line for line in solved[1:]]


def test_a_row_alone_reversed_and_in_chunks_of_one_gives_the_same_bits():
    many = [dict(CASES[0][0], load=f"{100 + 37 * i}N", axial_load=f"{50 + 11 * i}N",
                 cage_angle=str(3 * i)) for i in range(12)]  # fmt: skip
    whole = _batch(_file(many), "--format", "csv").stdout.splitlines()
    assert len(whole) == 1 + 2 * len(many)
    for i, case in enumerate(many):
        alone = _batch(_file([case]), "--format", "csv").stdout.splitlines()
        assert [line.split(",", 1)[1] for line in alone[1:]] == [
            line.split(",", 1)[1] for line in whole[1 + 2 * i : 3 + 2 * i]
        ]
    chunks = _batch(_file(many), "--format", "csv", "--chunk-size", "1").stdout.splitlines()
    assert chunks == whole
    back = _batch(_file(many[::-1]), "--format", "csv").stdout.splitlines()
    body = [line.split(",", 1)[1] for line in back[1:]]
    want = [line.split(",", 1)[1] for line in whole[1:]]
    assert sorted(body) == sorted(want)


def test_bad_rows_are_skipped_with_their_reason_the_others_written():
    cases = [
        {"bearing": "7205B", "load": "1kN", "axial_load": "1kN"},
        {"bearing": "6205", "arrangement": "DB", "load": "1kN"},
        {"bearing": "7205BDB", "arrangement": "DT", "load": "1kN", "axial_load": "1kN"},
        {"bearing": "7205B", "arrangement": "XX", "load": "1kN"},
        {"bearing": "7205BDT", "preload": "100N", "load": "1kN", "axial_load": "1kN"},
        {"bearing": "7205BDB", "preload": "-1N", "load": "1kN"},
        {"bearing": "7205BDB", "preload": "100N", "axial_load": "1kN"},
        CASES[0][0],
        {"bearing": "7205BDT", "load": "1kN", "axial_load": "0"},
        {"balls": "13", "ball_diameter": "7.938", "pitch_diameter": "38.5",
         "contact_angle": "25", "arrangement": "DB", "load": "1kN"},
    ]  # fmt: skip
    out = _batch(_file(cases), "--format", "csv")
    assert out.exit_code == 1
    assert [line.split(",", 1)[0] for line in out.stdout.splitlines()[1:]] == ["9", "9"]
    assert besides_tilt(out.stderr) == [
        "Skipped: row 2: arrangement: missing: a file of pairs gives each row's arrangement "
        "(DB, DF or DT) or a designation with it (7205BDB)",
        "Skipped: row 3: arrangement: a pair DB is two angular-contact ball bearings; give an "
        "angular-contact designation (7205B, 7205BDB) or a ring by hand with 'contact_angle'",
        "Skipped: row 4: arrangement: DT contradicts the designation '7205BDB' (a DB pair)",
        "Skipped: row 5: arrangement: 'XX' is not one of DB, DF, DT",
        "Skipped: row 6: preload: a tandem pair (DT) is not preloaded in itself: both bearings "
        "face the same way, so it is preloaded against another bearing; give 0, or use DB or DF",
        "Skipped: row 7: preload: must be 0 N or more (got -1 N)",
        "Skipped: row 8: load: missing: every row needs a (radial) load, 0 allowed",
        "Skipped: row 10: axial_load: must be > 0 N for a tandem pair (DT): both bearings take "
        "thrust towards +axial only (a reversed load lifts every ball; with none the axial "
        "position is held by another bearing)",
        "Skipped: row 11: width: a bearing pair needs the width B of one bearing (the axial "
        "distance of the two bearings' centres): give it (e.g. 15mm) or a catalogue designation "
        "that has it",
    ]


def test_strict_stops_at_the_first_bad_pair_and_writes_nothing():
    out = _batch(_file([CASES[0][0], {"bearing": "7205B", "load": "1kN"}]), "--strict")
    assert out.exit_code == 2
    assert out.stdout == ""
    assert out.stderr.splitlines()[-1] == (
        "Error: Invalid value in row 3: arrangement: missing: a file of pairs gives each row's "
        "arrangement (DB, DF or DT) or a designation with it (7205BDB)"
    )


def test_json_holds_the_csv_columns_and_each_pairs_warnings():
    out = _batch(_file([CASES[5][0], CASES[0][0]]), "--format", "json")
    assert out.exit_code == 0
    doc = json.loads(out.stdout)
    head = _batch(_file([CASES[0][0]]), "--format", "csv").stdout.splitlines()[0]
    keys = [h.split(" [")[0] for h in next(csv.reader([head]))]
    held = [
        "model",
        "contact_angles_inner",
        "contact_angles_outer",
        "ball_loads_inner",
        "ball_loads_outer",
    ]  # each bearing's, as a combined file's rows (json only)
    assert [list(c)[:-1] for c in doc["cases"]] == [keys + held] * 4
    assert [c["row"] for c in doc["cases"]] == [2, 2, 3, 3]
    assert [c["bearing_number"] for c in doc["cases"]] == [1, 2, 1, 2]
    lifted = besides_tilt(doc["cases"][0]["warnings"])
    assert lifted == [
        "bearing 2 of the back-to-back pair carries no load (lift-off: at an axial load alone "
        "beyond 284.846 N for the preload 100 N): its balls may skid; raise the preload"
    ]
    assert besides_tilt(doc["cases"][1]["warnings"]) == []
    assert besides_tilt(doc["cases"][2]["warnings"]) == []
    assert doc["skipped"] == []


def test_a_pair_in_a_file_without_pair_columns_names_the_way():
    out = _batch("bearing,load,axial_load\n7205BDB,2kN,1kN\n7205B,2kN,1kN\n", "--format", "csv")
    assert out.exit_code == 1
    assert [line.split(",", 1)[0] for line in out.stdout.splitlines()[1:]] == ["3"]
    assert out.stderr.splitlines()[0] == (
        "Skipped: row 2: bearing: '7205BDB' names a DB pair: a file of pairs has an "
        "'arrangement' column (or 'preload', 'width'; every row of it a pair, written as solve "
        "writes a pair); here give the single bearing with the load it carries"
    )


def test_a_header_a_pair_cannot_take_is_refused():
    for head, message in [
        ("bearing,preload,load,clearance",
         "clearance: not used in a file of bearing pairs (preload): a pair is solved by the "
         "exact model of its angular-contact bearings, no clearance (the contact angle "
         "fixes the geometry), no misalignment (give the moment)"),
        ("balls,stiffness,width,load",
         "width: a file of bearing pairs needs angular-contact ball bearings: add a 'bearing' "
         "column (7205B, 7205BDB) or 'ball_diameter', 'pitch_diameter' and 'contact_angle'"),
    ]:  # fmt: skip
        out = _batch(head + "\n")
        assert out.exit_code == 2
        assert out.stdout == ""
        lines = out.stderr.splitlines()
        assert lines[-1] == f"Error: Invalid value for 'CASES.csv': {message}"
        assert [line for line in lines if line.startswith("Error")] == lines[-1:]


def test_a_call_that_fails_is_split_until_the_failing_row_stands_alone():
    from bearingload.plan.many import Planner
    from bearingload.plan.many_pairs import solve_pair_cases

    planner = Planner(["bearing", "arrangement", "load", "axial_load"])
    cols = {"bearing": ["7205BDT"] * 3, "arrangement": [None] * 3,
            "load": [1000.0, 1000.0, 500.0], "axial_load": [100.0, 0.0, 200.0]}  # fmt: skip
    solved = solve_pair_cases(planner, cols, 3, {})  # one group: the library refuses the call
    assert solved.rows == [0, 2]
    assert list(solved.errors) == [1]
    assert str(solved.errors[1]).startswith("axial_load: must be > 0 N for a tandem pair (DT)")


def test_the_vectorised_call_gives_each_case_as_alone():
    """solve_bearing_pairs on arrays (one tilt kind: the bearings' lives and checks on the
    arrays; mixed: case by case) gives every case's records and warnings as a call alone: the
    equilibrium bit for bit, L10r to its last bits (its sum over the balls runs on the arrays:
    measured within 6e-16 relative, far below the csv's ten digits)."""
    from bearingload.bearings.resolve import resolve_bearing
    from bearingload.reports.pair import pair_records
    from bearingload.studies.bearing_pair import solve_bearing_pair, solve_bearing_pairs

    b = resolve_bearing("7205B")
    loads, axial = [1000.0, 0.0, 2500.0], [200.0, 900.0, -300.0]
    preload, cage = [300.0, 50.0, 0.0], [0.0, 7.0, 15.0]
    for cross in ([0.0, 0.0, 0.0], [0.0, 2000.0, 0.0], [1500.0, 2000.0, 500.0]):
        many = solve_bearing_pairs(b, loads, axial, arrangement="DB", preload=preload,
                                   cage_angle=cage, moment_cross=cross)  # fmt: skip
        for i, pc in enumerate(many):
            one = solve_bearing_pair(b, loads[i], axial[i], arrangement="DB",
                                     preload=preload[i], cage_angle=cage[i],
                                     moment_cross=cross[i])  # fmt: skip
            (pair, records), (pair1, records1) = pair_records(pc), pair_records(one)
            for mine, theirs in [(pair, pair1), *zip(records, records1, strict=True)]:
                assert mine.keys() == theirs.keys()
                for key, value in mine.items():
                    if key.startswith("reference_rating_life") and value is not None:
                        assert value == pytest.approx(theirs[key], rel=2e-15, abs=0), key
                    else:
                        assert value == theirs[key], key
            assert pc.warnings == one.warnings
            assert pc.result.x == one.result.x and pc.result.axial == one.result.axial


def test_a_preload_contradicting_the_designations_class_is_refused_in_any_row_order():
    """A row's plan is kept for the rows that differ from it only in their numbers; a preload
    is no such number: the class the designation carries (7205CDBL) refuses a force beside it
    whichever row comes first."""
    head = "bearing,load,axial_load,preload\n"
    good, bad = "7205CDBL,1kN,300N,L\n", "7205CDBL,1kN,300N,500N\n"
    for rows, refused in (((good, bad), "3"), ((bad, good), "2")):
        found = CliRunner().invoke(
            main, ["batch", "-", "--format", "json"], input=head + "".join(rows)
        )
        doc = json.loads(found.stdout)
        ((skipped),) = doc["skipped"]
        assert str(skipped["row"]) == refused
        assert skipped["reason"].startswith("preload: 500 N contradicts the designation")
        assert len(doc["cases"]) == 2  # the good row's two bearings
