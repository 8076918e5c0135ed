"""``bearingload batch`` with combined-load columns: every row equals ``bearingload solve`` with
the same options, rows are independent of their group, bad rows and bad headers are named."""

from __future__ import annotations

import csv
import io
import json
import random

from click.testing import CliRunner

from bearingload.cli import main
from bearingload.reports.combined import SOLVE_ONLY_KEYS

from .cli_helpers import run_entry

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
    return CliRunner().invoke(main, ["batch", "-", *args], input=text, catch_exceptions=False)


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
        expected = {k: v for k, v in expected.items() if k.split(" [")[0] not in SOLVE_ONLY_KEYS}
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
    assert "unknown ring 'sideways'" in out.stderr
    assert "NU206 is a roller bearing" in out.stderr
    assert "load: must be 0 N or more" in out.stderr
    assert "must be within ±2°" in out.stderr
    assert "not both" in out.stderr
    assert "needs a bearing or its ball geometry" in out.stderr


def test_headers_that_cannot_be_combined_are_refused(capsys, tmp_path):
    for head, word in (("load,axial_load", "needs deep-groove ball bearings"),
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
        if key in SOLVE_ONLY_KEYS:  # not computed by batch yet
            continue
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
