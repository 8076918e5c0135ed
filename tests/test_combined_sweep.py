"""``bearingload sweep`` under a combined load: the vectorised sweep against single solves, the
radial sweep as its special case, every format and the errors."""

from __future__ import annotations

import csv
import io
import json

import numpy as np
import pytest

from bearingload.bearings.iso16281 import contact_ratings, reference_rating_life
from bearingload.bearings.resolve import resolve_bearing
from bearingload.models.combined import solve_combined
from bearingload.reports.quantities import QUANTITIES
from bearingload.studies.combined_sweep import combined_sweep
from bearingload.studies.sweep import sweep

from .cli_helpers import invoke, run_entry

PEER = {"ball_diameter": 11.5, "pitch_diameter": 43.5, "modulus": 210000.0}
CASES = {
    "axial": dict(load=1400.0, axial_load=700.0),
    "pure axial": dict(load=0.0, axial_load=1000.0),
    "moment": dict(load=1000.0, axial_load=-300.0, moment=5000.0),
    "misalignment": dict(load=1000.0, axial_load=0.0, misalignment=0.1),
    "outer rotating": dict(load=2000.0, axial_load=500.0, rotating="outer"),
}


@pytest.mark.parametrize("clearance", ["C3", -0.005])
@pytest.mark.parametrize("name", list(CASES))
def test_each_row_is_a_single_solve_at_that_cage_angle(name, clearance):
    """Every cage position of the one vectorised call equals an independent solve_combined call
    at that angle alone (bit for bit: no case depends on its batch), and its L10r the ISO/TS
    16281 life of that call's ball loads."""
    kw = CASES[name]
    b = resolve_bearing("6205", clearance=clearance)
    s = combined_sweep(b, steps=11, **kw)
    q_ci, q_ce = contact_ratings(14000.0, 9, b.ball_diameter, b.pitch_diameter, 0.52, 0.53)
    for i, angle in enumerate(s.cage_angle):
        r = solve_combined(9, kw["load"], kw["axial_load"], ball_diameter=b.ball_diameter,
                           pitch_diameter=b.pitch_diameter, f_i=b.f_i, f_o=b.f_o,
                           clearance=b.clearance, cage_angle=float(angle),
                           moment=kw.get("moment"), misalignment=kw.get("misalignment"),
                           modulus=b.modulus, poisson=b.poisson)  # fmt: skip
        for key in ("x", "y", "axial", "tilt", "tilt_cross", "moment", "q_max", "loaded_balls"):
            assert np.asarray(getattr(s.result, key))[i] == getattr(r, key), (key, angle)
        np.testing.assert_array_equal(s.result.ball_loads[i], r.ball_loads)
        life = reference_rating_life(r.ball_loads, q_ci, q_ce, kw.get("rotating", "inner"))
        assert s.reference_rating_life[i] == pytest.approx(float(life), rel=1e-14)
        loaded = r.ball_loads > 0
        largest = r.contact_angles[loaded][np.argmax(np.abs(r.contact_angles[loaded]))]
        assert s.contact_angle_max[i] == largest
        heaviest = np.flatnonzero(r.ball_loads >= r.q_max * (1 - 1e-9))[0] + 1
        assert s.q_max_ball[i] == heaviest


@pytest.mark.parametrize("clearance", [0.0, 0.0205, -0.01, 0.08])
def test_radial_load_alone_is_the_radial_sweep(clearance):
    """F_a = 0, free tilt: no axial displacement, no tilt, and x, y, Q_max, its ball and the
    loaded balls of the radial sweep (same K: the Hertz value at contact angle 0) within 1e-9."""
    b = resolve_bearing("6205", clearance=clearance)
    s = combined_sweep(b, 1400.0, 0.0, steps=37)
    r = sweep(9, 1400.0, b.stiffness, clearance, steps=37)
    np.testing.assert_allclose(s.result.x, r.x, rtol=1e-9, atol=0)
    np.testing.assert_allclose(s.result.q_max, r.q_max, rtol=1e-9, atol=0)
    np.testing.assert_allclose(s.result.y, r.y, rtol=0, atol=1e-9 * float(np.max(r.x)))
    np.testing.assert_array_equal(s.q_max_ball, r.q_max_ball)
    np.testing.assert_array_equal(s.result.loaded_balls, r.loaded_balls)
    assert not np.any(s.result.axial) and not np.any(s.result.tilt)


def test_spread_is_over_one_period():
    b = resolve_bearing("6205", clearance="C3")
    s = combined_sweep(b, 1400.0, 700.0, steps=9)
    q = np.asarray(s.result.q_max)
    sp = s.spread("q_max")
    assert (sp.min, sp.max) == (q.min(), q.max())
    assert sp.mean == pytest.approx(q[:-1].mean(), rel=1e-15)
    assert s.spread("y").mean == 0.0  # odd in the cage angle
    assert s.rating_life == pytest.approx((14000 / s.equivalent_load) ** 3, rel=1e-12)


def test_without_a_rating_no_life():
    b = resolve_bearing(None, balls=7, **PEER, clearance=0.01)
    s = combined_sweep(b, 1000.0, 200.0, steps=3)
    assert s.reference_rating_life is None and s.rating_life is None
    assert s.spread("reference_rating_life") is None


CLI = ("sweep", "6205", "-F", "1.4kN", "-A", "700N", "-G", "C3", "--steps", "5")


def test_csv_is_one_rectangular_table_inputs_first():
    out = invoke(*CLI, "--format", "csv")
    assert out.exit_code == 0
    rows = list(csv.reader(io.StringIO(out.stdout)))
    assert len(rows) == 6 and len({len(r) for r in rows}) == 1
    head = rows[0]
    assert head[:9] == ["bearing", "balls", "load [N]", "axial_load [N]", "moment [N mm]",
                        "rotating", "stiffness [N/mm^1.5]", "clearance [mm]",
                        "clearance_pick"]  # fmt: skip
    assert head[9] == "cage_angle [°]" and "reference_rating_life [10^6 rev]" in head
    for name in head:  # every column is a quantity of the one table, with its unit
        key, _, unit = name.partition(" [")
        assert key in QUANTITIES and unit.rstrip("]") == QUANTITIES[key].unit.replace("^m", "^1.5")


def test_json_keys_are_solves_keys():
    doc = json.loads(invoke(*CLI, "--format", "json").stdout)
    solved = json.loads(invoke("solve", *CLI[1:8], "--format", "json").stdout)["cases"][0]
    first = doc["rows"][0]  # cage angle 0: solve's default
    for key in ("x", "y", "axial", "tilt", "tilt_cross", "q_max",
                "loaded_balls", "contact_angle_max", "reference_rating_life"):  # fmt: skip
        assert first[key] == pytest.approx(solved[key], rel=1e-12, abs=1e-15), key
    for key in ("free_contact_angle", "axial_play", "equivalent_load", "rating_life"):
        assert doc["summary"][key] == pytest.approx(solved[key], rel=1e-12), key
    for key in ("bearing", "load", "axial_load", "clearance", "rotating"):
        assert doc[key] == solved[key]
    assert doc["summary"]["q_max"]["max"] == max(r["q_max"] for r in doc["rows"])
    assert doc["units"]["axial"] == "mm" and doc["units"]["tilt"] == "°"
    assert doc["units"]["reference_rating_life"] == "10^6 rev"
    assert doc["steps"] == 5 and doc["geometry"]["designation"] == "6205"


def test_table_and_markdown_have_units():
    out = invoke(*CLI).stdout
    assert "reference rating life L10r (ISO/TS 16281)" in out and "10^6 rev" in out
    assert "axial [µm]" in out and "tilt [°]" in out and "L10r [10^6 rev]" in out
    md = invoke(*CLI, "--format", "markdown").stdout
    assert md.startswith("### Over one ball pitch (bearing 6205, z = 9, F_r = 1400 N")


def test_misalignment_gives_the_moment_per_row():
    out = invoke("sweep", "-z", "7", "--ball-diameter", "11.5", "--pitch-diameter", "43.5",
                 "-F", "1kN", "-G", "10um", "-C", "23.4kN", "--misalignment", "2mrad",
                 "--steps", "3", "--format", "json")  # fmt: skip
    doc = json.loads(out.stdout)
    assert "moment" not in doc and doc["misalignment"] == pytest.approx(np.degrees(2e-3))
    assert all(r["moment"] > 0 for r in doc["rows"]) and doc["units"]["moment"] == "N mm"


def test_plot_is_written(tmp_path):
    pytest.importorskip("matplotlib")
    from bearingload.reports.plots import combined_sweep_figure

    target = tmp_path / "c.png"
    out = invoke(*CLI, "--plot", str(target))
    assert out.exit_code == 0 and target.read_bytes()[:4] == b"\x89PNG"
    s = combined_sweep(resolve_bearing("6205", clearance="C3"), 1400.0, 700.0, steps=5)
    fig = combined_sweep_figure(s, "6205")
    assert fig.get_suptitle().startswith("6205: Cage sweep over one pitch: z = 9,")
    assert combined_sweep_figure(s).get_suptitle().startswith("Cage sweep")
    lines = [ax.get_lines()[0].get_ydata() for ax in fig.axes]
    np.testing.assert_allclose(lines[4], s.result.q_max)
    np.testing.assert_allclose(lines[5], s.reference_rating_life)


@pytest.mark.parametrize(
    "args, message",
    [
        (("-z", "7", "--kurochkin-T", "0.5", "-A", "1kN"),
         "Error: --axial-load cannot be used with --kurochkin-T"),
        (("-z", "7", "--kurochkin-T", "0.5", "--rotating", "outer"),
         "Error: --rotating cannot be used with --kurochkin-T"),
        (("NU206", "-F", "5kN", "-A", "1kN"),
         "Error: Invalid value for 'BEARING': NU206 is a roller bearing"),
        (("-z", "7", "-K", "3e5", "-F", "1kN", "-A", "1kN"),
         "Error: Invalid value for '--ball-diameter': the combined load needs the ball geometry"),
        (("6205", "-F", "1kN", "--misalignment", "3"),
         "Error: Invalid value for '--misalignment': must be within ±2°"),
        (("6205", "-F", "1kN", "--moment", "1Nm", "--misalignment", "0.1"),
         "Error: Invalid value for '--moment': give a moment or a misalignment"),
        (("6205", "-F", "0", "--rotating", "outer"), "Error: Invalid value for '--load'"),
        (("6205", "-F", "1kN", "-A", "1kN", "--steps", "1"),
         "Error: Invalid value for '--steps': must be between 2 (both ends of the pitch) and"),
        (("6205", "-F", "1kN", "-A", "1 parsec"), "Error: Invalid value for '--axial-load'"),
    ],
)  # fmt: skip
def test_errors_are_one_line_exit_2(capsys, tmp_path, args, message):
    target = tmp_path / "out.csv"
    code, out, err = run_entry(capsys, "sweep", *args, "-o", str(target))
    assert code == 2 and out == "" and not target.exists()
    assert err.startswith(message) and err.count("\n") == 1, err


def test_help_shows_the_combined_options_with_examples():
    out = invoke("sweep", "--help").output
    for option in ("--axial-load", "--moment", "--misalignment", "--dynamic-rating", "--rotating"):
        assert option in out
    assert "bearingload sweep 6205 -F 1.4kN --axial-load 700N" in out
    assert "N mm" in out and "(bare number: N)" in out


def test_every_json_key_is_a_quantity():
    doc = json.loads(invoke(*CLI, "--format", "json").stdout)
    structure = {"model", "steps", "rows", "summary", "units", "geometry", "warnings"}
    assert set(doc) - structure <= set(QUANTITIES)
    assert set(doc["rows"][0]) <= set(QUANTITIES) and set(doc["summary"]) <= set(QUANTITIES)
    assert set(doc["units"]) <= set(QUANTITIES)


@pytest.mark.parametrize("command", ["sweep", "table"])
def test_help_examples_with_combined_options_run(command):
    """Every example of --help that uses a combined-load option (or table life) runs."""
    import shlex

    text = invoke(command, "--help").output
    examples = [ln.strip() for ln in text.split("Examples:")[1].split("Options:")[0].splitlines()]
    chosen = [
        shlex.split(ln)[1:]
        for ln in examples
        if ln.startswith("bearingload ")
        and any(w in ln for w in ("--axial-load", "--misalignment", "--moment", " life "))
    ]
    assert len(chosen) >= 3
    for args in chosen:
        out = invoke(*args)
        assert out.exit_code == 0, (args, out.output)


def test_long_sweeps_run_in_chunks_with_the_same_answer(monkeypatch):
    import bearingload.studies.combined_sweep as module

    b = resolve_bearing("6205", clearance="C3")
    whole = combined_sweep(b, 1400.0, 700.0, steps=50)
    monkeypatch.setattr(module, "CHUNK_BALLS", 9 * 7)  # 7 positions a call: 8 calls
    chunked = combined_sweep(b, 1400.0, 700.0, steps=50)
    for key in ("x", "y", "axial", "tilt", "tilt_cross", "ball_loads", "contact_angles"):
        np.testing.assert_array_equal(getattr(whole.result, key), getattr(chunked.result, key))
    np.testing.assert_array_equal(whole.reference_rating_life, chunked.reference_rating_life)
    np.testing.assert_array_equal(whole.q_max_ball, chunked.q_max_ball)
