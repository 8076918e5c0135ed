"""``bearingload sweep`` of a bearing pair (7205BDB, --arrangement): every cage position is the
pair ``solve --cage-angle`` gives there (csv line for line, json key for key), the summary is
over those positions, and what a pair sweep cannot take is refused in one Error line."""

from __future__ import annotations

import csv
import json

import pytest
from click.testing import CliRunner

from bearingload.cli import main

from .cli_helpers import besides_tilt

PAIR = ["7205BDB", "--preload", "300N", "-F", "1kN", "-A", "200N"]


def _run(*args: str):
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


@pytest.mark.parametrize(
    "args",
    [
        PAIR,
        ["7205B", "--arrangement", "DF", "--preload", "100N", "-F", "2kN", "-A", "-300N",
         "--moment-cross", "3Nm"],
        ["7205BDT", "-F", "1kN", "-A", "500N", "--rotating", "outer"],
        ["7205BDB", "-F", "500N", "-A", "2kN"],
        [*PAIR, "--speed", "6000"],
        [*PAIR, "--speed", "20000", "--ball-density", "3200"],
        [*PAIR, "--speed", "6000", "--quasi-static"],
    ],
)  # fmt: skip
def test_every_position_is_solves_pair_at_that_cage_angle(args):
    out = _run("sweep", *args, "--steps", "5", "--format", "csv")
    assert out.exit_code == 0, out.stderr
    lines = out.stdout.splitlines()
    assert len(lines) == 1 + 2 * 5
    angles = []
    for k in range(5):
        cells = dict(zip(next(csv.reader([lines[0]])), next(csv.reader([lines[1 + 2 * k]])),
                         strict=True))  # fmt: skip
        angles.append(cells["cage_angle [°]"])
        solved = _run("solve", *args, "--cage-angle", cells["cage_angle [°]"], "--format",
                      "csv")  # fmt: skip
        assert solved.exit_code == 0
        assert solved.stdout.splitlines() == [lines[0], *lines[1 + 2 * k : 3 + 2 * k]]
    assert [float(a) for a in angles] == [0.0, 7.5, 15.0, 22.5, 30.0]


def test_json_rows_are_solves_keys_and_the_summary_is_over_them():
    out = _run("sweep", *PAIR, "--steps", "4", "--format", "json")
    assert out.exit_code == 0
    doc = json.loads(out.stdout)
    assert doc["steps"] == 4 and len(doc["rows"]) == 4
    for row in doc["rows"]:
        case = json.loads(
            _run("solve", *PAIR, "--cage-angle", repr(row["cage_angle"]), "--format",
                 "json").stdout
        )["cases"][0]  # fmt: skip
        for key, value in row.items():
            if key == "bearings":
                for mine, theirs in zip(value, case["bearings"], strict=True):
                    assert mine == {k: theirs[k] for k in mine}
            else:
                assert value == case[key], key
        assert {k: doc[k] for k in ("bearing", "arrangement", "preload", "load")} == {
            k: case[k] for k in ("bearing", "arrangement", "preload", "load")
        }
    xs = [r["x"] for r in doc["rows"]]
    assert doc["summary"]["x"]["min"] == min(xs) and doc["summary"]["x"]["max"] == max(xs)
    q2 = [r["bearings"][1]["q_max"] for r in doc["rows"]]
    assert doc["summary"]["bearings"][1]["q_max"]["max"] == max(q2)
    assert doc["summary"]["bearings"][1]["q_max"]["mean"] == pytest.approx(sum(q2[:-1]) / 3)
    assert doc["units"]["stiffness_axial"] == "N/mm"
    assert besides_tilt(doc["warnings"]) == []


def test_a_lifted_bearing_is_warned_once():
    out = _run("sweep", "7205BDB", "--preload", "100N", "-F", "0", "-A", "1kN", "--steps", "3")
    assert out.exit_code == 0
    assert out.stderr.splitlines() == [
        "Warning: bearing 2 of the back-to-back pair carries no load (lift-off: at an axial load "
        "alone beyond 284.846 N for the preload 100 N): its balls may skid; raise the preload"
    ]


@pytest.mark.parametrize(
    ("args", "message"),
    [
        ([*PAIR, "--plot", "p.png"],
         "Invalid value for '--plot': it draws one bearing's ripple, not a pair's; --format csv "
         "gives the pair at every cage position"),
        ([*PAIR, "--viscosity", "20cSt", "--speed", "3000"],
         "--viscosity cannot be used with sweep: the sweep shows how the ring position, Q_max "
         "and L10r (in hours with --speed) ripple over one ball pitch; C_0, a_1, a_ISO, the "
         "modified lives and the film are those of the case: give the same options to "
         "'bearingload solve' (or 'table life' against the clearance)"),
        ([*PAIR, "--clearance", "10um"],
         "--clearance cannot be used with a bearing pair: the design contact angle fixes the "
         "geometry of an angular-contact bearing (no clearance)"),
        ([*PAIR, "--misalignment", "1mrad"],
         "--misalignment cannot be used with a bearing pair: the shaft's tilt follows from the "
         "loads; give '--moment'"),
        (["6205", "--arrangement", "DB", "-F", "1kN"],
         "Invalid value for '--arrangement': a pair DB is two angular-contact ball bearings; "
         "give an angular-contact designation (7205B, 7205BDB) or a ring by hand with "
         "'--contact-angle'"),
        (["7205BDT", "--preload", "100N", "-F", "1kN", "-A", "1kN"],
         "Invalid value for '--preload': a tandem pair (DT) is not preloaded in itself: both "
         "bearings face the same way, so it is preloaded against another bearing; give 0, or "
         "use DB or DF"),
        (["7205B", "--preload", "100N", "-F", "1kN"],
         "Invalid value for '--preload': it belongs to a bearing pair; give '--arrangement' DB, DF "
         "or DT (or a designation with the suffix, 7205BDB); a single bearing is preloaded "
         "against another one"),
    ],
)  # fmt: skip
def test_what_a_pair_sweep_cannot_take_is_one_error_line(args, message):
    out = _run("sweep", *args)
    assert out.exit_code == 2
    assert out.stdout == ""
    assert out.stderr.splitlines()[-1] == f"Error: {message}"
    assert "Traceback" not in out.stderr


def test_speed_gives_the_pairs_l10r_in_hours_at_every_position():
    doc = json.loads(_run("sweep", *PAIR, "--steps", "3", "--speed", "6000", "--format",
                          "json").stdout)  # fmt: skip
    for row in doc["rows"]:
        assert row["speed"] == 6000.0
        assert row["reference_rating_life_hours"] == pytest.approx(
            row["reference_rating_life"] * 1e6 / (60 * 6000), rel=1e-9
        )
    hours = [r["reference_rating_life_hours"] for r in doc["rows"]]
    assert doc["summary"]["reference_rating_life_hours"]["min"] == min(hours)
    assert doc["model"].endswith("outer-raceway control in both bearings")  # the dynamics
    quasi = ("sweep", *PAIR, "--steps", "3", "--speed", "6000", "--quasi-static")
    model = json.loads(_run(*quasi, "--format", "json").stdout)["model"]
    assert model.endswith("the static model at the speed given (the ball dynamics left out)")
    assert (
        "Speed: --quasi-static: the pair is solved by the static model (the ball dynamics left "
        "out); the speed gives the lives in hours only."
    ) in _run(*quasi).stdout.splitlines()
