"""--ball-density (batch: ball_density) at speed: reported in solve's table and json and in
batch's csv, absent from a static answer, and a blank cell on a roller row read as absent."""

from __future__ import annotations

import json

import pytest

from .cli_helpers import run_entry, skipped_of


def test_ball_density_is_reported_at_speed(capsys):
    """--ball-density changed the answer but appeared nowhere in it: a ceramic-ball run could
    not be told from a steel one. json has ball_density [kg/m^3] (the batch column's key and
    unit), the terminal a row; a static solve has neither."""
    import json

    args = ("solve", "6205", "-F", "1kN", "--speed", "3000")
    for extra, rho in (((), 7850.0), (("--ball-density", "3200"), 3200.0)):
        code, out, err = run_entry(capsys, *args, *extra, "--format", "json")
        assert code == 0, err
        doc = json.loads(out)
        assert doc["cases"][0]["ball_density"] == pytest.approx(rho, rel=1e-12)
        assert doc["units"]["ball_density"] == "kg/m^3"
        code, out, err = run_entry(capsys, *args, *extra)
        row = [line for line in out.splitlines() if line.startswith("ball density")]
        assert len(row) == 1 and row[0].split()[-2:] == [f"{rho:.2f}", "kg/m^3"], row
    code, out, _ = run_entry(capsys, "solve", "6205", "-F", "1kN", "--format", "json")
    assert "ball_density" not in out
    code, out, _ = run_entry(capsys, *args, "--quasi-static")
    assert code == 0 and "ball density" not in out


def test_batch_writes_the_ball_density_of_its_rows_at_speed(capsys, tmp_path):
    """solve's csv at speed has ball_density [kg/m^3]: a combined-load file with a speed column
    writes it too (the value used: the cell, else steel; blank where quasi_static is true), and
    a file without a speed column has no such column."""
    import csv
    import io

    path = tmp_path / "rows.csv"
    path.write_text(
        "bearing,load,axial_load,speed,ball_density,quasi_static\n"
        "6205,1000,0,3000,3200,\n6205,1000,0,3000,,\n6205,1000,0,3000,,true\n",
        encoding="utf-8",
    )
    code, out, err = run_entry(capsys, "batch", str(path), "--format", "csv")
    assert code == 0, err
    rows = list(csv.DictReader(io.StringIO(out)))
    assert [float(r["ball_density [kg/m^3]"] or "nan") for r in rows[:2]] == [3200.0, 7850.0]
    assert rows[2]["ball_density [kg/m^3]"] == ""
    path.write_text("bearing,load,axial_load\n6205,1000,0\n", encoding="utf-8")
    code, out, err = run_entry(capsys, "batch", str(path), "--format", "csv")
    assert code == 0 and "ball_density" not in out, err


def test_a_roller_row_quasi_static_with_a_blank_ball_density_is_solved(capsys, tmp_path):
    """A roller bearing's row with quasi_static true was skipped ('ball_density: a roller
    bearing ...') whenever the file had a ball_density column, its own cell blank: solve
    NU205 --speed 3000 --quasi-static is accepted. The row equals solve's; a ball_density
    given on a roller row is still refused."""
    path = tmp_path / "rows.csv"
    path.write_text(
        "bearing,load,speed,quasi_static,ball_density\nNU205,1kN,3000,true,\n"
        "NU205,1kN,3000,,3200\n",
        encoding="utf-8",
    )
    code, out, err = run_entry(capsys, "batch", str(path), "--format", "json")
    reasons = skipped_of(err)
    assert code == 1 and len(reasons) == 1 and reasons[0].startswith("row 3: ball_density: ")
    (row,) = json.loads(out)["cases"]
    _, solved, _ = run_entry(
        capsys,
        "solve",
        "NU205",
        "-F",
        "1kN",
        "--speed",
        "3000",
        "--quasi-static",
        "--format",
        "json",
    )
    want = json.loads(solved)["cases"][0]
    assert row["row"] == 2 and row["q_max"] == want["q_max"] and row["speed"] == 3000.0
