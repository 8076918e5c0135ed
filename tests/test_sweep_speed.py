"""``bearingload sweep --speed``: a ball bearing swept as ``solve --speed`` solves it, every cage
position with the ball dynamics (docs/speed.md). Before, the sweep solved the static model at
any speed and said so in a note. Checked: every position equals solve at that cage angle with
the same options; a radial load is the 3-D engine at F_a = 0, byte for byte as ``-A 0``; ceramic
balls; --quasi-static the static sweep; chunks of positions give the same bits; the 90° inner
contact is warned of; the refusals name the way out."""

from __future__ import annotations

import json

import numpy as np
import pytest

from bearingload.bearings.resolve import resolve_bearing
from bearingload.studies import combined_sweep as cs

from .cli_helpers import invoke, run_entry

#: (sweep options, solve options beside the cage angle).
CASES = [
    (("6205", "-F", "1kN", "-A", "300N", "--speed", "10000"),),
    (("6205", "-F", "2kN", "-G", "C3", "--speed", "12000", "--ball-density", "3200"),),
    (("7205B", "-F", "800N", "-A", "1.5kN", "--speed", "20000"),),
    (("6306", "-F", "3kN", "-A", "500N", "--moment", "5Nm", "--speed", "8000"),),
]


def _json(*args: str) -> dict:
    out = invoke(*args, "--format", "json")
    assert out.exit_code == 0, out.stderr
    return json.loads(out.stdout)


@pytest.mark.parametrize(("options",), CASES)
def test_every_position_is_solve_at_that_cage_angle(options):
    """x, y, the axial displacement, the tilts, Q_max, the loaded balls and L10r (also in hours)
    of each position equal solve's at that cage angle to 1e-9 (solve's one case takes the
    scalar path: rounding apart); the json names the ball dynamics."""
    sweep = _json("sweep", *options, "--steps", "4")
    assert "ball dynamics" in sweep["model"] and "ball_dynamics" not in sweep
    for row in sweep["rows"]:
        (case,) = _json("solve", *options, "--cage-angle", repr(row["cage_angle"]))["cases"]
        assert "ball dynamics" in case["model"]
        for key in ("x", "y", "axial", "tilt", "tilt_cross", "q_max", "loaded_balls",
                    "reference_rating_life", "reference_rating_life_hours"):  # fmt: skip
            scale = max(abs(case[k]) for k in ("x", "axial")) if key in ("x", "y", "axial") \
                else max(abs(case["tilt"]), abs(case["tilt_cross"]), 1e-300) \
                if key.startswith("tilt") else abs(case[key])  # fmt: skip
            assert row[key] == pytest.approx(case[key], rel=0, abs=1e-9 * scale), (key, row)


def test_a_radial_load_at_speed_is_the_sweep_at_an_axial_load_of_0():
    base = ("sweep", "6205", "-F", "1kN", "--speed", "10000", "--steps", "5")
    for fmt in ("json", "csv", "table"):
        radial = invoke(*base, "--format", fmt)
        axial = invoke(*base, "-A", "0", "--format", fmt)
        assert radial.exit_code == 0 and radial.stdout == axial.stdout
    static = _json("sweep", "6205", "-F", "1kN", "-A", "0", "--steps", "5")
    fast = _json(*base)
    q_static = [r["q_max"] for r in static["rows"]]
    q_fast = [r["q_max"] for r in fast["rows"]]
    assert q_fast != q_static and np.allclose(q_fast, q_static, rtol=0.05)


def test_quasi_static_is_the_static_sweep_with_the_hours():
    quasi = _json("sweep", "6205", "-F", "1kN", "-A", "300N", "--speed", "10000",
                  "--quasi-static", "--steps", "5")  # fmt: skip
    static = _json("sweep", "6205", "-F", "1kN", "-A", "300N", "--steps", "5")
    assert quasi["model"] == static["model"] and "ball dynamics" not in quasi["model"]
    assert quasi["ball_dynamics"].startswith("Ball dynamics left out")
    for r, s in zip(quasi["rows"], static["rows"], strict=True):
        assert {k: v for k, v in r.items() if k in s} == s


def test_ceramic_balls_carry_less_centrifugal_force():
    steel = _json("sweep", "7205B", "-F", "800N", "-A", "1.5kN", "--speed", "20000", "--steps", "3")
    light = _json("sweep", "7205B", "-F", "800N", "-A", "1.5kN", "--speed", "20000",
                  "--ball-density", "3200", "--steps", "3")  # fmt: skip
    static = _json("sweep", "7205B", "-F", "800N", "-A", "1.5kN", "--steps", "3")
    for s, c, r in zip(steel["rows"], light["rows"], static["rows"], strict=True):
        # the inner contacts unload as the balls are thrown out: less so for lighter balls
        assert s["q_max"] < c["q_max"] < r["q_max"] * 1.001


def test_chunks_of_positions_give_the_same_bits(monkeypatch):
    b = resolve_bearing("6205", clearance=0.0205)
    whole = cs.combined_sweep(b, 1400.0, 700.0, steps=9, speed=10000.0)
    monkeypatch.setattr(cs, "CHUNK_BALLS", 2 * 9)
    parts = cs.combined_sweep(b, 1400.0, 700.0, steps=9, speed=10000.0)
    assert type(parts.result).__name__ == "HighSpeedDistribution"
    for name in ("ball_loads", "ball_loads_outer", "contact_angles_outer", "x", "axial"):
        assert np.array_equal(getattr(parts.result, name), getattr(whole.result, name)), name
    assert np.array_equal(parts.reference_rating_life, whole.reference_rating_life)


def test_an_inner_contact_on_the_groove_side_is_warned_of(capsys):
    code, _, err = run_entry(capsys, "sweep", "7205B", "-F", "1kN", "-A", "1kN", "--speed",
                             "50000", "--steps", "3")  # fmt: skip
    assert code == 0
    assert "Warning: at 3 of 3 cage angles (0° to 30°) the loaded inner contact of a ball sits " \
           "at 90°, on the side of the inner groove" in err  # fmt: skip


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("6205", "-F", "1e-7N", "--speed", "10000"),
         "Error: Invalid value for '--load': the loads are too small for the combined solver (the "
         "largest of F_r, |F_a| and M/R_i is 1e-07 N; it takes at least 7.7e-07 N for this "
         "bearing); at '--speed' a ball bearing is solved by the combined engine (the ball "
         "dynamics); '--quasi-static' gives the static radial engine, which takes any load"),
        (("NU205", "-F", "1kN", "--speed", "3000", "--ball-density", "3200"),
         "Error: --ball-density cannot be used with a roller bearing (NU205): the radial engine "
         "solves it by the static model at any speed: the ball dynamics at '--speed' are coded "
         "for ball bearings"),
        (("6205", "-F", "1kN", "--ball-density", "3200"),
         "Error: Invalid value for '--ball-density': it enters the ball dynamics at '--speed', "
         "which '--quasi-static' or a missing '--speed' leave out"),
        (("7205BDB", "--preload", "300N", "-F", "1kN", "--ball-density", "3200"),
         "Error: Invalid value for '--ball-density': it enters the ball dynamics at '--speed', "
         "which '--quasi-static' or a missing '--speed' leave out"),
        (("7205BDB", "--preload", "0", "-F", "0", "-A", "1e-6N", "--speed", "30000"),
         None),
        (("6205", "-F", "1kN", "--speed", "51948.06"),
         "Error: Invalid value for '--speed': n d_m must be at most 2e+06 mm/min for the "
         "ball-dynamics model (n = 51948.06 rpm with d_m = 38.5 mm: at most 51948.05195 rpm; "
         "beyond, ring expansion, cage and lubricant forces it leaves out matter); '--quasi-static' "
         "gives the static model at any speed (the lives in hours)"),
        (("7205BDB", "--preload", "300N", "-F", "1kN", "--speed", "51948.06"),
         "Error: Invalid value for '--speed': n d_m must be at most 2e+06 mm/min for the "
         "ball-dynamics model (n = 51948.06 rpm with d_m = 38.5 mm: at most 51948.05195 rpm; "
         "beyond, ring expansion, cage and lubricant forces it leaves out matter); '--quasi-static' "
         "gives the static model at any speed (the lives in hours)"),
        (("6205", "-F", "1kN", "--speed", "3000", "--rotating", "outer"),
         "Error: Invalid value for '--rotating': the ball dynamics at '--speed' are coded for the "
         "inner ring turning (docs/speed.md); give '--quasi-static' for the static model with the "
         "outer ring's lives"),
    ],
)  # fmt: skip
def test_refusals_name_the_option_and_the_way(capsys, args, message):
    code, out, err = run_entry(capsys, "sweep", *args, "--steps", "3")
    assert code != 0 and out == ""
    if message is None:  # as solve refuses the case, naming --quasi-static
        code, _, said = run_entry(capsys, "solve", *args)
        assert code != 0 and "'--quasi-static' gives the static model" in said
        message = said.strip()
    assert err.strip().splitlines() == [message]


def test_every_position_of_a_pair_is_solve_at_that_cage_angle():
    """A pair at speed: both bearings' ball dynamics at every position (before: the static
    pair, the speed giving the hours only), each position solve 7205BDB --cage-angle there."""
    options = ("7205BDB", "--preload", "300N", "-F", "1kN", "-A", "200N", "--speed", "20000")
    sweep = _json("sweep", *options, "--steps", "3")
    assert sweep["model"].endswith("outer-raceway control in both bearings")
    quasi = _json("sweep", *options, "--quasi-static", "--steps", "3")
    assert "the static model at the speed given" in quasi["model"]
    for row, static in zip(sweep["rows"], quasi["rows"], strict=True):
        (case,) = _json("solve", *options, "--cage-angle", repr(row["cage_angle"]))["cases"]
        for key in ("x", "axial", "tilt", "stiffness_radial", "reference_rating_life_hours"):
            assert row[key] == pytest.approx(case[key], rel=1e-9), key
        for k in (0, 1):
            assert row["bearings"][k]["q_max"] == pytest.approx(
                case["bearings"][k]["q_max"], rel=1e-9
            )
        assert row["x"] != static["x"]  # the dynamics move the shaft


def test_the_ball_density_and_the_static_note_are_said(capsys):
    """Review: a sweep at speed gave no ball density anywhere (steel and ceramic looked alike);
    --quasi-static's note said 'bearingload solve gives them' though sweep does."""
    doc = _json("sweep", "6205", "-F", "1kN", "--speed", "10000", "--ball-density", "3200",
                "--steps", "3")  # fmt: skip
    assert doc["summary"]["ball_density"] == 3200.0 and doc["units"]["ball_density"] == "kg/m^3"
    text = invoke("sweep", "6205", "-F", "1kN", "--speed", "10000", "--ball-density", "3200",
                  "--steps", "3").stdout  # fmt: skip
    assert "balls of 3200 kg/m^3" in text
    quasi = _json("sweep", "6205", "-F", "1kN", "--speed", "10000", "--quasi-static", "--steps",
                  "3")  # fmt: skip
    assert "ball_density" not in quasi["summary"]
    assert quasi["ball_dynamics"] == (
        "Ball dynamics left out: the static model (--quasi-static; --speed gives the lives in "
        "hours only); without --quasi-static a ball bearing is solved with each ball's "
        "centrifugal force and gyroscopic moment, as 'bearingload solve --speed' solves it "
        "(docs/speed.md)."
    )


def test_a_pairs_groove_side_warning_is_said_once_per_bearing_with_its_cage_angles(capsys):
    """Review: a pair's sweep repeated the 90° warning of every position, each naming balls
    without the cage angle; now once per bearing, as one bearing's sweep says it."""
    code, out, err = run_entry(capsys, "sweep", "7205BDT", "-F", "2kN", "-A", "2kN", "--speed",
                               "51000", "--steps", "3")  # fmt: skip
    assert code == 0
    side = [w for w in err.splitlines() if "90°" in w]
    assert [w.split(" the loaded")[0] for w in side] == [
        "Warning: bearing 1: at 3 of 3 cage angles (0° to 30°)",
        "Warning: bearing 2: at 3 of 3 cage angles (0° to 30°)",
    ]
    assert "preload at the speed" not in out  # DT: no preload
    code, out, _ = run_entry(capsys, "sweep", "7205BDB", "--preload", "300N", "-F", "1kN",
                             "--speed", "20000", "--steps", "3")  # fmt: skip
    assert "preload at the speed 666.898 N each bearing (F_p 300 N ground in at rest); " \
           "lift-off 860.801 N at rest." in out  # fmt: skip


def test_the_sweep_figure_at_speed_names_the_speed_and_the_model():
    """The figure of a sweep at speed said nothing of the speed: a user could not tell it from
    the static one. Its title now ends with a line of n and '(ball dynamics)'; --quasi-static
    with n only."""
    import dataclasses

    from bearingload.reports.plots import combined_sweep_figure

    b = resolve_bearing("6205", clearance=0.0125)
    fast = cs.combined_sweep(b, 1000.0, 300.0, steps=3, speed=10000.0)
    title = combined_sweep_figure(fast, "6205").get_suptitle()
    assert title.endswith("G_r = 12.5 µm\nn = 10000 rpm (ball dynamics)"), title
    static = dataclasses.replace(cs.combined_sweep(b, 1000.0, 300.0, steps=3), speed=10000.0)
    assert combined_sweep_figure(static, "6205").get_suptitle().endswith("µm\nn = 10000 rpm")
    plain = cs.combined_sweep(b, 1000.0, 300.0, steps=3)
    assert combined_sweep_figure(plain, "6205").get_suptitle().endswith("G_r = 12.5 µm")
