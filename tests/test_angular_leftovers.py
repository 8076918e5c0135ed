"""Angular-contact bearings: loads beyond the model refused (not a ConvergenceError), the tilt
warning of an angular-contact bearing, batch's ``contact_angle`` column and angular designations
in its ``bearing`` column, ``sweep`` of an angular designation."""

from __future__ import annotations

import csv
import inspect
import io
import json

import numpy as np
import pytest

from bearingload.batch.read import COLUMNS
from bearingload.errors import InputError
from bearingload.models.combined import ANGULAR_RATIO_MIN, solve_combined
from bearingload.plan.case import LOAD_PARAMS as LOAD_COLUMNS

from .cli_helpers import besides_tilt, run_entry, solved_csv, without_count

RING = {"ball_diameter": 8.7312, "pitch_diameter": 38.5}  # the 7205B row's ball set


def test_a_huge_thrust_on_7205b_is_one_error_line_naming_the_axial_load(capsys):
    """solve 7205B -F 0 -A 1e20N ended in a ConvergenceError (6205 gives an answer)."""
    code, out, err = run_entry(capsys, "solve", "7205B", "-F", "0", "-A", "1e20N")
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and "Traceback" not in err
    assert lines[0].startswith("Error: Invalid value for '--axial-load': too large")
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "0", "-A", "1e20N")
    assert code == 0 and "Q_max" in out  # the deep-groove path is unchanged


@pytest.mark.parametrize("alpha", [10.0, 25.0, 40.0, 55.0])
@pytest.mark.parametrize(("fr", "fa"), [(1e13, 1e13), (1e13, 3e12), (0.0, 1e19)])
def test_loads_that_did_not_converge_are_refused(alpha, fr, fa):
    """F_r = F_a = 1e13 N (and F_a = 0.3 F_r) on a 12-ball ring did not converge at any of
    these angles, nor a pure thrust of 1e19 N: now an InputError naming the larger load."""
    with pytest.raises(InputError, match="too large for the angular-contact model") as info:
        solve_combined(12, fr, fa, contact_angle=alpha, **RING)
    assert info.value.parameter == ("axial_load" if fa > fr else "radial_load")


@pytest.mark.parametrize("alpha", [10.0, 40.0])
def test_a_thrust_just_below_the_bound_is_solved_and_balanced(alpha):
    """Pure thrust at half the largest load taken, K_ref (A / ratio)^1.5: every ball equal, F_a
    balanced; twice the bound is refused."""
    from bearingload.models.combined import angular_geometry, hertz_setup

    one = np.ones(1)
    geo = angular_geometry(RING["ball_diameter"] * one, RING["pitch_diameter"] * one,
                            0.52 * one, 0.53 * one, alpha * one)  # fmt: skip
    k_ref, _ = hertz_setup(geo, 208000.0 * one, 0.3 * one)
    f_max = float(k_ref[0] * (geo.A[0] / ANGULAR_RATIO_MIN) ** 1.5)
    r = solve_combined(12, 0.0, 0.5 * f_max, contact_angle=alpha, **RING)
    q = np.asarray(r.ball_loads).ravel()
    sin = np.sin(np.radians(np.asarray(r.contact_angles).ravel()))
    assert np.ptp(q) <= 1e-9 * q.max()
    assert float(np.sum(q * sin)) == pytest.approx(0.5 * f_max, rel=1e-9)
    with pytest.raises(InputError, match="too large"):
        solve_combined(12, 0.0, 2.0 * f_max, contact_angle=alpha, **RING)


def test_an_angular_bearing_tilted_is_warned_without_the_deep_groove_limit(capsys):
    """The warning quoted the 10 arcmin of a deep-groove bearing for an angular one."""
    code, out, err = run_entry(capsys, "solve", "7205B", "-F", "2kN", "-A", "1kN",
                               "--misalignment", "5arcmin")  # fmt: skip
    assert code == 0
    (line,) = [w for w in err.splitlines() if "tilts" in w]
    assert "angular-contact" in line and "SKF gives no tolerable value" in line
    assert "5 arcmin" in line and "the 10 arcmin" not in line
    code, out, err = run_entry(capsys, "solve", "7205B", "-F", "2kN", "-A", "1kN",
                               "--misalignment", "0")  # fmt: skip
    assert code == 0 and "tilt" not in err
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "2kN", "-A", "1kN",
                               "--misalignment", "5arcmin")  # fmt: skip
    assert code == 0 and "tilt" not in err  # within the 2-10 arcmin of a deep-groove bearing
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "2kN", "-A", "1kN",
                               "--misalignment", "15arcmin")  # fmt: skip
    assert "more than the 10 arcmin" in err


def test_batch_contact_angle_column_is_the_cli_and_library_name():
    """The batch column, solve's option and the library parameter are spelt alike."""
    from bearingload.plan.case import LOAD_PARAMS

    assert "contact_angle" in COLUMNS and "contact_angle" in LOAD_COLUMNS
    assert "contact_angle" in LOAD_PARAMS  # solve --contact-angle
    assert "contact_angle" in inspect.signature(solve_combined).parameters


def _batch(capsys, tmp_path, text: str) -> tuple[int, list[dict], str]:
    path = tmp_path / "cases.csv"
    path.write_text(text, encoding="utf-8")
    code, out, err = run_entry(capsys, "batch", str(path), "--format", "json")
    return code, json.loads(out)["cases"], without_count(err)


_KEYS = ("q_max", "x", "axial", "tilt", "loaded_balls", "reference_rating_life", "rating_life",
         "equivalent_load", "static_equivalent_load", "contact_angle_max", "stiffness_axial")  # fmt: skip


def _solve(capsys, *args: str) -> dict:
    code, out, err = run_entry(capsys, "solve", *args, "--format", "json")
    assert code == 0, err
    return json.loads(out)["cases"][0]


def test_batch_contact_angle_rows_equal_solve(capsys, tmp_path):
    code, rows, err = _batch(capsys, tmp_path, (
        "balls,ball_diameter,pitch_diameter,load,axial_load,contact_angle,dynamic_rating\n"
        "13,7.938,38.5,2kN,1kN,40,16.7kN\n13,7.938,38.5,1kN,3kN,25,16.7kN\n"
        "13,7.938,38.5,2kN,,15,\n"))  # fmt: skip
    assert code == 0 and besides_tilt(err) == [] and [r["row"] for r in rows] == [2, 3, 4]
    for r, (fr, fa, alpha, c) in zip(rows, [("2kN", "1kN", "40", True),
                                            ("1kN", "3kN", "25", True),
                                            ("2kN", "0", "15", False)], strict=True):  # fmt: skip
        args = ["--balls", "13", "--ball-diameter", "7.938", "--pitch-diameter", "38.5", "-F", fr,
                "-A", fa, "--contact-angle", alpha, *(["-C", "16.7kN"] if c else [])]  # fmt: skip
        one = _solve(capsys, *args)
        assert r["contact_angle"] == float(alpha) and r["clearance"] == 0.0
        for key in _KEYS:
            assert r[key] == (None if one[key] is None else pytest.approx(one[key], rel=1e-9)), key


@pytest.mark.parametrize(
    ("cells", "reason"),
    [("13,7.938,38.5,2kN,1kN,70,", "contact_angle: must be from 0 to 60°"),
     ("13,7.938,38.5,2kN,-1kN,40,", "axial_load: must be >= 0 N for an angular-contact"),
     ("13,7.938,38.5,2kN,1kN,40,10um", "clearance: cannot be used with 'contact_angle'")],
)  # fmt: skip
def test_batch_contact_angle_refusals_skip_the_row_with_its_reason(capsys, tmp_path, cells, reason):
    path = tmp_path / "cases.csv"
    path.write_text("balls,ball_diameter,pitch_diameter,load,axial_load,contact_angle,clearance\n"
                    f"13,7.938,38.5,2kN,1kN,40,\n{cells}\n", encoding="utf-8")  # fmt: skip
    code, out, err = run_entry(capsys, "batch", str(path), "--format", "csv")
    assert code == 1 and f"row 3: {reason}" in err and "Traceback" not in err
    assert [r["row"] for r in csv.DictReader(io.StringIO(solved_csv(out)))] == ["2"]


def test_batch_refuses_a_contact_angle_beside_a_designation(capsys, tmp_path):
    code, out, err = run_entry(capsys, "batch", str(_file(tmp_path, (
        "bearing,load,axial_load,contact_angle\n7205B,2kN,1kN,40\n"))), "--format", "csv")  # fmt: skip
    assert code == 1 and "contact_angle: cannot be used with a bearing designation" in err


def _file(tmp_path, text: str):
    path = tmp_path / "cases.csv"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("name", ["7205B", "7205C", "7205A", "7305C", "7010B"])
def test_batch_angular_designations_equal_solve(capsys, tmp_path, name):
    code, rows, err = _batch(capsys, tmp_path, f"bearing,load,axial_load\n{name},2kN,1.5kN\n")
    assert code == 0 and besides_tilt(err) == []
    one = _solve(capsys, name, "-F", "2kN", "-A", "1.5kN")
    for key in _KEYS:
        assert rows[0][key] == (None if one[key] is None else pytest.approx(one[key], rel=1e-9))


@pytest.mark.parametrize("name", ["7205B", "7205C"])
def test_sweep_of_an_angular_designation_equals_solve_at_each_cage_angle(capsys, name):
    code, out, err = run_entry(capsys, "sweep", name, "-F", "2kN", "-A", "1kN", "--steps", "3",
                               "--format", "json")  # fmt: skip
    assert code == 0 and besides_tilt(err) == []
    doc = json.loads(out)
    assert "angular-contact" in doc["model"]
    for row in doc["rows"]:
        one = _solve(capsys, name, "-F", "2kN", "-A", "1kN", "--cage-angle", f"{row['cage_angle']}")
        for key in ("q_max", "x", "axial", "tilt", "loaded_balls", "reference_rating_life",
                    "contact_angle_max"):  # fmt: skip
            assert row[key] == pytest.approx(one[key], rel=1e-9), key
    code, out, err = run_entry(capsys, "sweep", name, "-F", "2kN", "-A", "1kN", "--steps", "3")
    assert "axial: from the zero-load position" in out


HAND_25 = "-z 12 --ball-diameter 8.7 --pitch-diameter 38.5 --contact-angle 25".split()


@pytest.mark.parametrize(
    ("args", "kind"),
    [
        (["7205B"], "single-row angular-contact ball bearing, 40°"),
        (HAND_25, "single-row angular-contact ball bearing, 25°"),
        (["6205"], "deep-groove ball bearing"),
    ],
)
def test_json_model_names_the_bearing_type_as_sweep_does(capsys, args, kind):
    # solve's JSON called every combined case a 'deep-groove ball bearing', 7205B included
    code, out, err = run_entry(capsys, "solve", *args, "-F", "500N", "-A", "1kN", "--format",
                               "json", "--quiet")  # fmt: skip
    assert code == 0, err
    assert json.loads(out)["cases"][0]["model"] == f"3-D ring equilibrium, {kind} (ISO/TS 16281)"


@pytest.mark.parametrize(
    "args",
    [
        ["solve", "7205B", "-F", "2kN", "-A", "1kN"],
        ["solve", "7205BDB", "--preload", "200N", "-F", "2kN", "-A", "1kN"],
        ["sweep", "7205B", "-F", "2kN", "-A", "1kN", "--steps", "3"],
    ],
)
def test_angular_tables_name_the_axial_origin_of_angular_contact(capsys, args):
    # the row read 'axial displacement from centred rings' (the deep-groove origin), and the
    # sweep's note 'from the centred rings (half the axial play included ...)', beside the note
    # that the angular-contact axial displacement is measured from the zero-load position
    code, out, _ = run_entry(capsys, *args)
    assert code == 0
    assert "centred rings" not in out
    assert "axial displacement from zero-load position" in out


def test_sweep_refuses_a_contact_angle_without_denying_angular_designations(capsys):
    # the refusal said 'an angular-contact bearing is solved by 'solve' only', while
    # 'sweep 7205B ...' sweeps an angular-contact bearing
    code, _, err = run_entry(capsys, "sweep", *HAND_25, "-F", "1kN", "-A", "1kN")
    assert code == 2 and "--contact-angle" in err and "7205B" in err
    assert "an angular-contact bearing is solved by 'solve' only" not in err


@pytest.mark.parametrize("table", ["life", "k"])
def test_table_refuses_a_contact_angle_without_denying_sweep_and_batch(capsys, table):
    # the refusal said 'an angular-contact bearing is solved by 'solve' only', while 'sweep
    # 7205B' and a batch row of 7205B solve one (its own designation refusal names all three)
    code, _, err = run_entry(capsys, "table", table, *HAND_25, "-F", "1kN", "-A", "1kN")
    assert code == 2 and err.startswith("Error: ") and "--contact-angle" in err
    assert "an angular-contact bearing is solved by 'solve' only" not in err
    assert "'sweep'" in err and "'batch'" in err
