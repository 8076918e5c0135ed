"""``bearingload batch`` with combined-load columns: every row equals ``bearingload solve`` with
the same options, rows are independent of their group, bad rows and bad headers are named."""

from __future__ import annotations

import csv
import io
import json
import random

from click.testing import CliRunner

from bearingload.cli import main

from .cli_helpers import SolvedRows, besides_tilt, invoke, run_entry

#: (batch cells, solve options) of one case each: catalogue and hand geometry, preload to C4,
#: F_r 0, both rings rotating, a moment, an imposed misalignment, C_r given, 'half'.
CASES = [
    ({"bearing": "6205", "load": "1.4kN", "axial_load": "700N", "clearance": "C3"},
     ["6205", "-F", "1.4kN", "--axial-load", "700N", "-G", "C3"]),
    ({"bearing": "6205", "load": "0", "axial_load": "700N"},
     ["6205", "-F", "0", "--axial-load", "700N"]),
    ({"bearing": "6306", "load": "3kN", "axial_load": "1kN", "clearance": "-5um",
      "cage_angle": "10", "rotating": "outer"},
     ["6306", "-F", "3kN", "--axial-load", "1kN", "-G", "-5um", "--cage-angle", "10",
      "--rotating", "outer"]),
    ({"bearing": "6205", "load": "1kN", "moment": "2Nm"},
     ["6205", "-F", "1kN", "--moment", "2Nm"]),
    ({"bearing": "6205", "load": "1kN", "misalignment": "0.05", "clearance": "C4",
      "cage_angle": "half"},
     ["6205", "-F", "1kN", "--misalignment", "0.05", "-G", "C4", "--cage-angle", "half"]),
    ({"balls": "7", "ball_diameter": "11.5", "pitch_diameter": "43.5", "load": "1kN",
      "axial_load": "300N", "dynamic_rating": "22.5kN", "clearance": "10um"},
     ["-z", "7", "--ball-diameter", "11.5", "--pitch-diameter", "43.5", "-F", "1kN",
      "--axial-load", "300N", "--dynamic-rating", "22.5kN", "-G", "10um"]),
    ({"bearing": "6205", "load": "2kN", "axial_load": "-400N", "clearance": "C3"},
     ["6205", "-F", "2kN", "--axial-load", "-400N", "-G", "C3"]),
]  # fmt: skip
HEAD = ("bearing", "balls", "ball_diameter", "pitch_diameter", "load", "axial_load", "moment",
        "misalignment", "dynamic_rating", "clearance", "cage_angle", "rotating")  # fmt: skip


def _file(cases: list[dict[str, str]]) -> str:
    lines = [",".join(HEAD)] + [",".join(c.get(k, "") for k in HEAD) for c in cases]
    return "\n".join(lines) + "\n"


def _batch(text: str, *args: str):
    return SolvedRows(
        CliRunner().invoke(main, ["batch", "-", *args], input=text, catch_exceptions=False)
    )


def _rows(text: str) -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO(text)))


def test_every_row_equals_solve():
    out = _batch(_file([c for c, _ in CASES]), "--format", "csv")
    assert out.exit_code == 0, out.stderr
    rows = _rows(out.stdout)
    assert [r["row"] for r in rows] == [str(i) for i in range(2, 2 + len(CASES))]
    for row, (_, args) in zip(rows, CASES, strict=True):
        solved = CliRunner().invoke(main, ["solve", *args, "--format", "csv"])
        assert solved.exit_code == 0, solved.stderr
        expected = _rows(solved.stdout)[0]
        for key, value in expected.items():
            assert row[key] == value, (args, key)
        assert all(row[k] == "" for k in row if k not in expected and k != "row")


def test_rows_do_not_depend_on_their_group():
    """The same cases repeated and shuffled (groups of one bearing solved together) give the
    bytes each row gives alone."""
    cells = [c for c, _ in CASES] * 3
    order = list(range(len(cells)))
    random.Random(5).shuffle(order)
    together = _rows(_batch(_file([cells[i] for i in order]), "--format", "csv").stdout)
    for position, i in enumerate(order):
        alone = _rows(_batch(_file([cells[i]]), "--format", "csv").stdout)[0]
        got = dict(together[position])
        assert got.pop("row") == str(position + 2)
        alone.pop("row")
        assert got == alone


def test_bad_rows_are_named_and_the_others_solved():
    bad = [
        {"bearing": "6205", "load": "1kN", "rotating": "sideways"},
        {"bearing": "NU206", "load": "1kN", "axial_load": "100N"},
        {"bearing": "6205", "load": "-5", "axial_load": "1kN"},
        {"bearing": "6205", "load": "1kN", "misalignment": "3"},
        {"bearing": "6205", "load": "1kN", "misalignment": "0.05", "moment": "2Nm"},
        {"bearing": "6205", "load": "1kN", "dynamic_rating": "-1kN"},
        {"balls": "9", "load": "1kN", "axial_load": "1kN"},
        {"bearing": "6205", "load": "1kN", "axial_load": "300N"},
    ]
    out = _batch(_file(bad), "--format", "csv")
    assert out.exit_code == 1
    assert [r["row"] for r in _rows(out.stdout)] == ["9"]
    named = [line.split(":", 2)[1].strip() for line in out.stderr.splitlines()[:7]]
    assert named == [f"row {i}" for i in range(2, 9)]
    assert "'sideways' is not one of inner, outer" in out.stderr
    assert "NU206 is a roller bearing" in out.stderr
    assert (
        "load: must be greater than 0 N, or 0 with an axial load or a moment (got -5 N)"
        in out.stderr
    )
    assert "must be within ±2°" in out.stderr
    assert "not both" in out.stderr
    assert "needs a bearing or its ball geometry" in out.stderr


def test_headers_that_cannot_be_combined_are_refused(capsys, tmp_path):
    for head, word in (("load,axial_load", "combined load needs ball bearings"),
                       ("bearing,load,axial_load,method", "method: not used"),
                       ("bearing,load,moment,exponent", "exponent: not used")):  # fmt: skip
        path = tmp_path / "cases.csv"
        path.write_text(head + "\n1,2,3\n")
        code, out, err = run_entry(capsys, "batch", str(path), "--format", "csv")
        assert code == 2 and out == "" and len(err.splitlines()) == 1, err
        assert err.startswith("Error: ") and word in err


def test_json_keys_are_solves():
    out = _batch(_file([CASES[0][0]]), "--format", "json")
    doc = __import__("json").loads(out.stdout)
    solved = CliRunner().invoke(main, ["solve", *CASES[0][1], "--format", "json"])
    case = __import__("json").loads(solved.stdout)["cases"][0]
    for key, value in case.items():
        if not isinstance(value, (list, dict)) and key != "model":  # model: solve's prose
            assert doc["cases"][0][key] == value, key
    assert doc["units"]["reference_rating_life"] == "10^6 rev"


def test_a_moment_alone_converges_and_has_no_iso281_life():
    """F_r = F_a = 0 with a moment: the ring tilts until balls touch (the start may touch none:
    the solver then moves along the load to the first contact), L10r from the ball loads, and
    no ISO 281 life (P = 0)."""
    import json

    for designation in ("75-313", "6313", "6205"):
        for cage in ("0", "half"):
            out = CliRunner().invoke(
                main,
                ["solve", designation, "-F", "0", "--moment", "2Nm", "--cage-angle", cage,
                 "--format", "json"],
            )  # fmt: skip
            assert out.exit_code == 0, (designation, cage, out.output)
            case = json.loads(out.stdout)["cases"][0]
            assert case["rating_life"] is None and case["equivalent_load"] == 0.0
            assert case["reference_rating_life"] > 0 and case["tilt"] > 0
            assert abs(case["tilt_cross"]) < 1e-12  # balls symmetric about the load plane
    row = _rows(_batch("bearing,load,moment\n6205,0,2Nm\n", "--format", "csv").stdout)[0]
    assert row["rating_life [10^6 rev]"] == "" and float(row["reference_rating_life [10^6 rev]"])


def test_iso281_life_of_a_row_without_f0_does_not_depend_on_its_group():
    """Bearing 306 (GOST ball set: C0r known, f0 not): a row without an axial load has P = F_r
    and L10 = (C_r/P)^3 as solve gives them, whether or not another row of its bearing has an
    axial load (which has no ISO 281 P without f0)."""
    alone = _rows(_batch("bearing,load,axial_load\n306,1kN,0\n", "--format", "csv").stdout)
    mixed = _rows(
        _batch("bearing,load,axial_load\n306,1kN,0\n306,1kN,100N\n", "--format", "csv").stdout
    )
    solved = _rows(
        CliRunner().invoke(main, ["solve", "306", "-F", "1kN", "-A", "0", "--format", "csv"]).stdout
    )[0]
    for key in ("equivalent_load [N]", "rating_life [10^6 rev]"):
        assert alone[0][key] == mixed[0][key] == solved[key] != "", key
        assert mixed[1][key] == "", key


def test_row_warnings_weigh_the_pressures_solve_reports():
    """The contact pressure warning of a row is solve's: every ball at its contact angle (near
    41°, the largest inner pressure 4155 MPa, below ISO 76's 4200), not the heaviest ball at
    the groove's radial section (4276 MPa, which warned)."""
    args = ["6205", "-F", "0", "--axial-load", "27kN", "-G", "0.1mm", "--format", "json"]
    solved = json.loads(CliRunner().invoke(main, ["solve", *args]).stdout)
    out = _batch("bearing,load,axial_load,clearance\n6205,0,27kN,0.1mm\n", "--format", "json")
    row = json.loads(out.stdout)["cases"][0]
    assert row["warnings"] == solved["cases"][0]["warnings"] == solved["warnings"]
    assert not any("contact pressure" in w for w in row["warnings"])
    assert solved["cases"][0]["p_max_inner"] < 4200.0


#: The columns solve adds to a solved combined case that batch computes per group.
STATIC_KEYS = ("p_max_inner", "p_max_outer", "static_equivalent_load", "static_safety")


def _random_rows(seed: int, n: int) -> list[tuple[dict[str, str], list[str]]]:
    """``n`` random combined cases (batch cells, solve options): catalogue bearings with and
    without C0 and f0 (306: a GOST ball set), hand geometry (no C0), F_r 0 to 5 kN, F_a of
    both signs, a moment, a cross moment, a misalignment, a lever, clearances, cage angles."""
    rng = random.Random(seed)
    out = []
    for _ in range(n):
        cells: dict[str, str] = {}
        args: list[str] = []

        def put(key: str, option: str, value: str, cells=cells, args=args) -> None:
            cells[key] = value
            args.extend([option, value])

        if rng.random() < 0.2:
            put("balls", "-z", str(rng.choice((7, 9, 12))))
            put("ball_diameter", "--ball-diameter", "11.5")
            put("pitch_diameter", "--pitch-diameter", "43.5")
        else:
            cells["bearing"] = rng.choice(("6205", "6306", "306", "6013"))
            args.append(cells["bearing"])
        put("load", "-F", f"{rng.choice((0, 0.3, 1, 2.5, 5))}kN")
        axial = rng.choice((0, 150, 700, -400, 2000)) or (700 if cells["load"] == "0kN" else 0)
        put("axial_load", "--axial-load", f"{axial}N")
        tilt = rng.choice(("", "moment", "misalignment", "moment_cross"))
        if tilt == "moment":
            put("moment", "--moment", f"{rng.choice((1, 3))}Nm")
        elif tilt == "misalignment":
            put("misalignment", "--misalignment", str(rng.choice((0.02, 0.08))))
        elif tilt == "moment_cross":
            put("moment_cross", "--moment-cross", "2Nm")
        if rng.random() < 0.3:
            put("tilt_radius", "--tilt-radius", rng.choice(("pitch", "groove", "25mm")))
        classes = ("C3", "CN") if "bearing" in cells else ()
        put("clearance", "-G", rng.choice((*classes, "10um", "-3um")))
        put("cage_angle", "--cage-angle", rng.choice(("0", "half", "7")))
        out.append((cells, args))
    return out


def test_random_rows_have_solves_pressures_and_static_safety():
    """Each row of a file of random mixed cases (rows of one bearing solved together) carries
    the contact pressures, P0 and s0 solve's json gives for that case alone, to the bit; s0
    blank where C0 is not known (hand geometry), P0 = max(F_r, 0.6 F_r + 0.5 |F_a|)."""
    cases = _random_rows(11, 24)
    head = ("bearing", "balls", "ball_diameter", "pitch_diameter", "load", "axial_load",
            "moment", "moment_cross", "misalignment", "tilt_radius", "clearance", "cage_angle")  # fmt: skip
    text = "\n".join([",".join(head)] + [",".join(c.get(k, "") for k in head) for c, _ in cases])
    out = _batch(text + "\n", "--format", "json")
    assert out.exit_code == 0, out.stderr
    rows = json.loads(out.stdout)["cases"]
    assert len(rows) == len(cases)
    blank_s0 = 0
    for row, (cells, args) in zip(rows, cases, strict=True):
        solved = CliRunner().invoke(main, ["solve", *args, "--format", "json"])
        assert solved.exit_code == 0, (args, solved.stderr)
        case = json.loads(solved.stdout)["cases"][0]
        for key in STATIC_KEYS:
            assert row[key] == case[key], (args, key)
        fr, fa = row["load"], abs(row["axial_load"])
        assert row["static_equivalent_load"] == max(fr, 0.6 * fr + 0.5 * fa)
        assert row["p_max_inner"] > 0 and row["p_max_outer"] > 0 or row["q_max"] == 0
        if "bearing" not in cells:
            assert row["static_safety"] is None
            blank_s0 += 1
        elif row["static_equivalent_load"] > 0:
            assert row["static_safety"] > 0
    assert blank_s0 > 0 and blank_s0 < len(cases)


def test_csv_columns_are_solves_in_its_order():
    """The csv header of a combined file is solve's (moment_cross, tilt_radius given)."""
    args = ["6205", "-F", "1kN", "-A", "300N", "--moment-cross", "2Nm", "--tilt-radius", "pitch",
            "--misalignment", "0.05", "--format", "csv"]  # fmt: skip
    solve_head = CliRunner().invoke(main, ["solve", *args]).stdout.splitlines()[0]
    text = "bearing,load,axial_load,moment_cross,tilt_radius,misalignment\n6205,1kN,300N,2Nm,pitch,0.05\n"
    out = _batch(text, "--format", "csv")
    assert out.stdout.splitlines()[0] == "row," + solve_head
    assert (
        out.stdout.splitlines()[1].split(",", 1)[1]
        == CliRunner().invoke(main, ["solve", *args]).stdout.splitlines()[1]
    )


def test_a_tilt_radius_without_a_combined_load_is_refused_for_its_row():
    """solve refuses --tilt-radius without a combined load (the radial engine has no tilt);
    batch refused nothing and solved the row under the lever of no tilt. Now that row is
    skipped with solve's reason, the others (a lever with F_a = 0, a moment) solved."""
    solved = CliRunner().invoke(main, ["solve", "6205", "-F", "1kN", "--tilt-radius", "pitch"])
    assert solved.exit_code == 2
    reason = "it is the lever of the inner ring's tilt, and only the combined load ("
    assert reason in solved.output
    text = ("bearing,load,axial_load,moment,tilt_radius,rotating\n6205,1kN,0,,pitch,\n"
            "6205,1kN,,,pitch,outer\n6205,1kN,,1Nm,20mm,\n6205,1kN,,,,\n")  # fmt: skip
    out = _batch(text, "--format", "csv")
    assert out.exit_code == 1
    assert [r["row"] for r in _rows(out.stdout)] == ["2", "4", "5"]
    lines = [x for x in out.stderr.splitlines() if "row 3" in x]
    assert len(lines) == 1 and f"row 3: tilt_radius: {reason}" in lines[0], out.stderr
    assert "('axial_load', 'moment', 'moment_cross', 'misalignment') tilts the ring" in lines[0]
    strict = _batch(text, "--format", "csv", "--strict")
    assert strict.exit_code == 2 and "tilt_radius" in strict.stderr


def test_life_columns_do_not_choose_the_engine():
    """rotating and dynamic_rating feed the lives only (as solve's --rotating and
    --dynamic-rating): a file whose rows differ only by a rotating cell gives every row the load
    distribution of the radial engine, and each row's L10r and L10 are solve's for its options.
    A rotating or dynamic_rating column made every row of the file a combined-load case."""
    text = ("bearing,load,clearance,rotating,dynamic_rating\n6205,1.4kN,C3,,\n"
            "6205,1.4kN,C3,outer,\n6205,1.4kN,C3,inner,20kN\n")  # fmt: skip
    out = _batch(text, "--format", "csv")
    assert out.exit_code == 0, out.stderr
    rows = _rows(out.stdout)
    options = [[], ["--rotating", "outer"], ["--rotating", "inner", "--dynamic-rating", "20kN"]]
    radial = _rows(
        CliRunner()
        .invoke(main, ["solve", "6205", "-F", "1.4kN", "-G", "C3", "--format", "csv"])
        .stdout
    )[0]
    for row, extra in zip(rows, options, strict=True):
        assert row["method"] == "exact"
        for key in ("q_max [N]", "k", "loaded_balls", "load_zone [°]", "x [mm]", "y [mm]"):
            assert row[key] == radial[key], key
        args = ["solve", "6205", "-F", "1.4kN", "-G", "C3", *extra, "--format", "csv"]
        expected = _rows(CliRunner().invoke(main, args).stdout)[0]
        for key, value in expected.items():  # a file of bearings: stiffness in N/mm^m
            if value == "" and key not in row:
                continue  # solve's blank epsilon: batch writes it with a method column only
            assert row[key.replace("N/mm^1.5", "N/mm^m")] == value, (extra, key)
    assert (
        rows[1]["reference_rating_life [10^6 rev]"] != rows[0]["reference_rating_life [10^6 rev]"]
    )
    assert rows[2]["rating_life [10^6 rev]"] != rows[0]["rating_life [10^6 rev]"]


def test_the_load_of_each_row_chooses_its_engine():
    """In a file with an axial_load column, a row with an axial_load cell (0 included) is a
    combined-load case as solve -A solves it; a row without one is a radial case, as solve
    without -A, filling the columns the two engines share."""
    text = "bearing,load,axial_load,clearance\n6205,1kN,,C3\n6205,1kN,0,C3\n6205,1kN,300N,C3\n"
    out = _batch(text, "--format", "csv")
    assert out.exit_code == 0, out.stderr
    rows = _rows(out.stdout)
    assert [r["method"] for r in rows] == ["exact", "combined", "combined"]
    for row, extra in zip(rows, ([], ["-A", "0"], ["-A", "300N"]), strict=True):
        args = ["solve", "6205", "-F", "1kN", "-G", "C3", *extra, "--format", "csv"]
        expected = _rows(CliRunner().invoke(main, args).stdout)[0]
        shared = [k for k in expected if k in row]
        assert len(shared) > 12
        for key in shared:
            assert row[key] == expected[key], (extra, key)
    assert rows[0]["axial_load [N]"] == rows[0]["tilt [°]"] == ""


def test_a_rotating_cell_solve_refuses_is_a_skipped_row():
    """--rotating where no L10r is computed (a roller bearing, no C_r, another method) is
    refused by solve; a rotating cell there is a skipped row naming the reason, in column names."""
    text = ("bearing,balls,ball_diameter,pitch_diameter,load,rotating\nNU206,,,,5kN,outer\n"
            ",7,11.5,43.5,1kN,outer\n6205,,,,1kN,outer\n")  # fmt: skip
    out = _batch(text, "--format", "csv")
    assert out.exit_code == 1
    assert [r["row"] for r in _rows(out.stdout)] == ["4"]
    lines = out.stderr.splitlines()
    assert lines[0].startswith("Skipped: row 2: rotating: it names the rotating ring")
    assert "ball bearings only" in lines[0]
    assert lines[1].startswith("Skipped: row 3: rotating: ") and "give 'dynamic_rating'" in lines[1]


def test_a_lever_far_from_the_pitch_radius_is_warned_on_its_own_row():
    """A tilt_radius cell far from d_m/2 (a unit slip) ended the whole batch: 'Error: internal
    error (TypeError: unsupported format string passed to numpy.ndarray.__format__)', exit 3:
    the lever warning was given the array of the group's levers. Each row is warned as solve
    warns its case, the rows between are not."""
    text = "bearing,load,axial_load,tilt_radius\n6205,1kN,300N,1e9\n6205,1kN,300N,20\n6205,1kN,300N,5\n"
    out = CliRunner().invoke(main, ["batch", "-", "--format", "csv"], input=text)
    assert out.exit_code == 0, out.output
    warned = [ln for ln in out.stderr.splitlines() if "tilt lever" in ln]
    assert [ln.split(": ")[1] for ln in warned] == ["row 2", "row 4"], warned
    solve = CliRunner().invoke(main, ["solve", "6205", "-F", "1kN", "-A", "300N",
                                      "--tilt-radius", "1e9"])  # fmt: skip
    assert warned[0].removeprefix("Warning: row 2: ") in solve.stderr
    assert len(out.stdout.splitlines()) == 4


def test_a_combined_rotating_cell_without_a_life_is_a_skipped_row(tmp_path):
    """solve refuses --rotating on a hand-given ring without C_r (no L10r to name the ring of);
    a combined batch row with the same cells was solved (found by the review): now skipped
    with solve's reason."""
    path = tmp_path / "rot.csv"
    path.write_text("balls,ball_diameter,pitch_diameter,load,axial_load,rotating\n"
                    "9,7.938,38.5,1000,500,outer\n", encoding="utf-8")  # fmt: skip
    out = invoke("batch", str(path), "--format", "json")
    doc = json.loads(out.stdout)
    assert doc["cases"] == [] and [s["row"] for s in doc["skipped"]] == [2]
    assert "L10r needs the dynamic load rating C_r" in doc["skipped"][0]["reason"]


def test_angular_rows_mixed_with_deep_groove_rows_equal_solve():
    """An angular-contact row with a blank axial_load cell takes solve's default (F_a = 0, the
    combined engine, as 'solve 7205B -F 2kN'); it was skipped ('solved by the combined engine
    only'). Each row equals solve's csv, column by column, beside deep-groove rows."""
    import csv as csv_module
    import io as io_module

    from click.testing import CliRunner

    from bearingload.cli import main

    rows = [("7205B", "2kN", "1kN"), ("6205", "2kN", "1kN"), ("7205B", "2kN", ""),
            ("7205 BEP", "0", "1kN"), ("7205B", "2kN", "-1kN")]  # fmt: skip
    text = "bearing,load,axial_load\n" + "".join(f"{b},{f},{a}\n" for b, f, a in rows)
    out = SolvedRows(CliRunner().invoke(main, ["batch", "-", "--format", "csv"], input=text))
    assert out.exit_code == 1  # the reversed thrust of the last row only
    assert besides_tilt(out.stderr)[0].startswith("Skipped: row 6: axial_load: must be >= 0 N")
    got = list(csv_module.DictReader(io_module.StringIO(out.stdout)))
    assert [r["row"] for r in got] == ["2", "3", "4", "5"]
    for row, (b, f, a) in zip(got, rows, strict=False):
        one = CliRunner().invoke(main, ["solve", b, "-F", f, *(["-A", a] if a else []),
                                        "--format", "csv"])  # fmt: skip
        assert one.exit_code == 0, one.output
        want = next(csv_module.DictReader(io_module.StringIO(one.stdout)))
        shared = [k for k in want if k in row and k != "axial_load [N]"]
        assert len(shared) > 25
        assert {k: row[k] for k in shared} == {k: want[k] for k in shared}
        assert float(row["axial_load [N]"]) == float(want["axial_load [N]"])
