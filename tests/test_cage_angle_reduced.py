"""A cage angle is reduced to [0, 360°) and echoed so: a negative angle within rounding of 0
(-1e-320°, which ``np.mod`` takes to 360; -1e-13°, which it takes to 359.9999999999999, printed
360) is 0°, in every engine and front door."""

import csv
import json
import re

import numpy as np
import pytest

from bearingload.validate import reduced_angle

from .cli_helpers import invoke


@pytest.mark.parametrize(
    ("angle", "reduced"),
    [
        (-1e-320, 0.0),
        (-1e-17, 0.0),
        (-1e-13, 0.0),
        (-3e-13, 0.0),
        (-1e-12, 359.999999999999),
        (-0.0, 0.0),
        (-1e-6, 359.999999),
        (-10.0, 350.0),
        (725.0, 5.0),
        (360.0, 0.0),
    ],
)
def test_an_angle_is_reduced_to_one_turn(angle, reduced):
    for got in (reduced_angle(angle), reduced_angle(np.array([angle]))[0]):
        assert got == reduced and np.copysign(1.0, got) == 1.0  # no 360, no -0


@pytest.mark.parametrize(
    "args",
    [
        ("6205", "-F", "1kN"),
        ("6205", "-F", "1kN", "-A", "10N"),
        ("6205", "-F", "1kN", "--speed", "3000"),
        ("7205BDB", "-F", "1kN", "-A", "10N", "--preload", "100N"),
        ("7205BDB", "-F", "1kN", "-A", "10N", "--preload", "100N", "--speed", "3000"),
    ],
)
@pytest.mark.parametrize("angle", ["-1e-320", "-1e-13"])
def test_solve_echoes_a_cage_angle_just_below_0_as_0(args, angle):
    text = invoke("solve", *args, f"--cage-angle={angle}").output
    assert "cage angle 0°" in text and "360" not in text
    doc = json.loads(invoke("solve", *args, f"--cage-angle={angle}", "--format", "json").stdout)
    angles = [c["cage_angle"] for c in doc["cases"]]
    angles += [b["cage_angle"] for c in doc["cases"] for b in c.get("bearings", [])]
    assert angles and all(a == 0.0 for a in angles)
    docs = doc["cases"] + [b for c in doc["cases"] for b in c.get("bearings", [])]
    balls = [d["ball_angles"][0] for d in docs if "ball_angles" in d]
    assert balls and all(a == 0.0 for a in balls)


@pytest.mark.parametrize(
    "args",
    [
        ("6205", "-F", "1kN"),
        ("6205", "-F", "1kN", "-A", "10N"),
        ("NU206", "-F", "5kN"),
        ("7205BDB", "-F", "1kN", "-A", "10N", "--preload", "100N"),
    ],
)
@pytest.mark.parametrize("angle", ["-1e-12", "-1e-9"])
def test_a_turn_angle_that_rounds_to_360_is_printed_0_in_every_format(args, angle):
    """-1e-12° reduces to 359.999999999999° (kept: not within rounding of 0), which 10 digits
    (json, csv) and 6 (table, markdown) round to 360: a turn angle is printed 0 there."""

    def out(*more):
        return invoke("solve", *args, f"--cage-angle={angle}", *more).stdout

    doc = json.loads(out("--format", "json"))
    docs = doc["cases"] + [b for c in doc["cases"] for b in c.get("bearings", [])]
    assert all(d["cage_angle"] == 0.0 for d in docs)
    assert all(d["ball_angles"][0] == 0.0 for d in docs if "ball_angles" in d)
    for fmt in ("table", "markdown"):
        text = out("--format", fmt)
        assert "cage angle 0°" in text and "cage angle 360" not in text
        assert not re.search(r"^\|? *1 +\|? *360", text, re.M), text
    if args[0] != "7205BDB":  # (a pair's csv is its bearings' rows, without ball angles)
        rows = list(csv.DictReader(out("--format", "csv", "--per-ball").splitlines()))
        assert rows[0]["cage_angle [°]"] == rows[0]["ball_angles [°]"] == "0.0"


def test_only_a_turn_angle_is_printed_0_where_it_rounds_to_360():
    """The cage angle and the ball angles are turn angles; a load zone's half-angle or a
    contact angle is not (json, csv and the human formats alike)."""
    from bearingload.reports.render import Column, Table, render

    keys = ("cage_angle", "ball_angles", "load_zone", "contact_angles")
    table = Table("t", [Column(k, k, "°", 6) for k in keys], [dict.fromkeys(keys, 359.9999999999)])
    assert render([table], "csv").splitlines()[1] == "0.0,0.0,360.0,360.0"
    assert render([table], "table").splitlines()[4].split() == ["0", "0", "360.000", "360.000"]
    document = json.loads(render([], "json", document=dict.fromkeys(keys, [359.9999999999])))
    assert document == dict(zip(keys, [[0.0], [0.0], [360.0], [360.0]], strict=True))


def test_batch_echoes_a_cage_angle_just_below_0_as_0(tmp_path):
    path = tmp_path / "cases.csv"
    path.write_text(
        "bearing,load,axial_load,cage_angle\n6205,1000N,10N,-1e-320\n6205,1000N,,-1e-17\n"
        "6205,1000N,10N,-1e-13\n6205,1000N,,-1e-13\n",
        encoding="utf-8",
    )
    rows = invoke("batch", str(path), "--format", "json").stdout
    assert [r["cage_angle"] for r in json.loads(rows)["cases"]] == [0.0, 0.0, 0.0, 0.0]


def test_the_library_solvers_reduce_the_cage_angle():
    from bearingload import solve
    from bearingload.models.combined import solve_combined

    assert solve(9, 1000.0, 1e5, cage_angle=-1e-320).cage_angle == 0.0
    assert list(solve(9, np.array([1e3, 2e3]), 1e5, cage_angle=-1e-320).cage_angle) == [0, 0]
    combined = solve_combined(
        9, 1000.0, 10.0, ball_diameter=7.938, pitch_diameter=38.5, cage_angle=-1e-320
    )
    assert combined.cage_angle == 0.0
    assert solve(9, 1000.0, 1e5, cage_angle=-1e-13).cage_angle == 0.0


def test_the_tables_take_the_cage_angle_within_one_turn():
    """table k's header and json: -1e-320 and -0 are a ball under the load (0°, z = 1 kept,
    which needs its ball on the load line), -10 is 350° as solve gives it."""
    for angle in ("-1e-320", "-0"):
        text = invoke("table", "k", f"--cage-angle={angle}", "--z-max", "3").stdout
        assert "a ball under the load" in text.splitlines()[0]
        assert [line.split()[0] for line in text.splitlines()[4:7]] == ["1", "2", "3"]
        doc = invoke("table", "k", f"--cage-angle={angle}", "--z-max", "3", "--format", "json")
        assert '"cage_angle": -0.0' not in doc.stdout and '"cage_angle": 0.0' in doc.stdout
    head = invoke("table", "k", "--cage-angle=-10", "--z-max", "3").stdout.splitlines()[0]
    assert "cage angle 350°" in head
    # -1e-12: 359.999999999999°, printed at 6 and 10 digits as 0 (a turn angle)
    head = invoke("table", "k", "--cage-angle=-1e-12", "--z-max", "3").stdout.splitlines()[0]
    assert "cage angle 0°" in head
    doc = invoke("table", "k", "--cage-angle=-1e-12", "--z-max", "3", "--format", "json")
    assert '"cage_angle": 0.0' in doc.stdout and "360" not in doc.stdout


@pytest.mark.parametrize(
    "args",
    [
        ("6205", "-F", "1kN"),
        ("6205", "-F", "1kN", "-A", "10N"),
        ("6205", "-F", "1kN", "--speed", "3000"),
    ],
)
def test_a_ball_just_below_a_whole_turn_is_at_0(args):
    # a cage 1e-13° below a pitch (z = 9: 40°) puts ball 9 at 360° - 1e-13°, which was printed
    # at 360.000 (json 359.9999999999999): it is reduced as the cage angle is, to 0
    cage = f"--cage-angle={40.0 - 1e-13!r}"
    doc = json.loads(invoke("solve", *args, cage, "--format", "json").stdout)
    angles = doc["cases"][0]["ball_angles"]
    assert angles[-1] == 0.0 and angles[0] == pytest.approx(40.0, abs=1e-12)
    assert "360" not in invoke("solve", *args, cage).output


#: Angles about the edges of one turn: -1e-13° and the doubles 1 to 8 ulps below 360° (the
#: rule's TURN_ROUNDING, 4 eps 360°, is 5.6 ulps of 360: at 6 ulps and nearer, 0), 360° and
#: the first double above, 0 and -0, a tiny negative, a whole number of turns.
EDGE_ANGLES = [-1e-13, -1e-17, -1e-320, -0.0, 0.0, 360.0, 720.0, -360.0, 1e-300, -3e-13]
EDGE_ANGLES += [float(360.0 - k * np.spacing(360.0, dtype=float)) for k in range(1, 9)]
EDGE_ANGLES += [float(np.nextafter(360.0, 400.0)), 359.9999999999999, -1e-12]


def _core_ball_angles(angles: np.ndarray) -> np.ndarray:
    """The angle of the one ball (z = 1) of cases whose cage is at ``angles``, as the core's
    result_case writes it (``combined_result``; the other rows are not read here)."""
    from bearingload.models import _core

    n = angles.size
    case_in = np.zeros((11, n))
    case_in[1] = case_in[2] = case_in[4] = case_in[6] = case_in[10] = 1.0  # s, R_i, A, F, K_0
    case_in[8] = angles
    position, forces, kappa = np.zeros((n, 5)), np.zeros((n, 5)), np.zeros((n, 1))
    at_balls, tangent, mirrored = np.zeros((13, n, 1)), np.zeros((n, 5, 5)), np.zeros(n, np.uint8)
    _, balls, _ = _core.combined_result(
        position, case_in, forces, at_balls, kappa, False, tangent, mirrored
    )
    return balls[0, :, 0]


def test_the_core_reduces_a_ball_angle_as_validate_reduces_an_angle():
    """The ball angles were reduced in Python (validate.reduced_angle in combined.distribution_
    of, 2 us of a 22 us call); the core's result_case reduces them where it makes them, to the
    same bits: random angles of many turns either way and the edges of a turn."""
    rng = np.random.default_rng(5)
    turns = 360.0 * rng.integers(-5, 6, 500) - rng.uniform(0.0, 1e-12, 500)
    random = (rng.uniform(-1e4, 1e4, 2000), rng.uniform(-1.0, 1.0, 500), turns)
    angles = np.concatenate((np.array(EDGE_ANGLES), *random))
    got = _core_ball_angles(angles)
    want = reduced_angle(angles)
    assert np.all((0.0 <= got) & (got < 360.0))
    assert got.view(np.int64).tolist() == want.view(np.int64).tolist()  # bits: no -0
    assert got[0] == got[EDGE_ANGLES.index(360.0 - np.spacing(360.0))] == 0.0  # -1e-13°, 1 ulp


@pytest.mark.parametrize("z", [3, 4, 7, 9, 12, 16])
def test_the_ball_angles_of_every_solver_are_the_reduced_angles_of_the_balls(z):
    """Ball j at the cage plus 360° j/z, reduced to one turn by validate.reduced_angle (as
    combined.distribution_of did): the same bits, one case or many, single bearing and pair;
    cages a rounding below a ball's pitch included (a ball just below 360°: 0)."""
    from bearingload.models.combined import solve_combined
    from bearingload.models.pair import solve_pair

    rng = np.random.default_rng(z)
    pitch = 360.0 / z
    below = [pitch * k - np.spacing(pitch * k) * j for k in (1, z) for j in range(1, 6)]
    cages = np.concatenate((rng.uniform(0.0, 360.0, 8), pitch * np.arange(1, z + 1) - 1e-13, below))
    geometry = {"ball_diameter": 7.938 if z <= 12 else 4.0, "pitch_diameter": 38.5}
    one = [solve_combined(z, 1000.0, 100.0, cage_angle=float(c), **geometry) for c in cages]
    kw = {"preload": 100.0, "contact_angle": 40.0, "width": 15.0, **geometry}
    pair = solve_pair(z, 1000.0, 100.0, cage_angle=cages, **kw)
    solved = {
        "combined": solve_combined(z, 1000.0, 100.0, cage_angle=cages, **geometry).ball_angles,
        "combined, one case": np.array([r.ball_angles for r in one]),
        "pair, bearing 1": pair.bearings[0].ball_angles,
        "pair, bearing 2": pair.bearings[1].ball_angles,
    }
    cage = reduced_angle(cages)
    want = reduced_angle(np.mod(cage[:, None] + 360.0 * np.arange(z) / z, 360.0))
    for name, got in solved.items():
        got = np.asarray(got, dtype=float).reshape(want.shape)
        assert got.view(np.int64).tolist() == want.view(np.int64).tolist(), name
