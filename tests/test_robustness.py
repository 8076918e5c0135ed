"""Edge cases found in review: output files, extreme but finite inputs, huge angles, units."""

from __future__ import annotations

import os
import stat
import subprocess

import numpy as np
import pytest
from click.testing import CliRunner

from bearingload.cli import main
from bearingload.errors import InputError
from bearingload.models.equilibrium import solve
from bearingload.reports.render import write_atomic
from bearingload.units import parse_stiffness

from .cli_helpers import run_process as run_cli


def test_write_follows_a_symlink(tmp_path):
    target = tmp_path / "target.txt"
    target.write_text("old")
    link = tmp_path / "link.txt"
    link.symlink_to(target)
    write_atomic("new\n", str(link))
    assert link.is_symlink()
    assert target.read_text() == "new\n"


def test_write_keeps_or_derives_permissions(tmp_path):
    new = tmp_path / "new.txt"
    old_umask = os.umask(0o022)
    try:
        write_atomic("a\n", str(new))
    finally:
        os.umask(old_umask)
    assert stat.S_IMODE(new.stat().st_mode) == 0o644
    new.chmod(0o640)
    write_atomic("b\n", str(new))
    assert stat.S_IMODE(new.stat().st_mode) == 0o640
    assert new.read_text() == "b\n"


def test_write_into_a_fifo_writes_through(tmp_path):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    reader = subprocess.Popen(["cat", str(fifo)], stdout=subprocess.PIPE, text=True)
    write_atomic("through\n", str(fifo))
    out, _ = reader.communicate(timeout=10)
    assert out == "through\n"
    assert stat.S_ISFIFO(fifo.stat().st_mode)


def test_dash_is_standard_output_and_empty_name_is_an_error(tmp_path):
    r = run_cli("table", "k", "--z-max", "2", "--format", "csv", "-o", "-", cwd=tmp_path)
    assert r.returncode == 0 and r.stdout.startswith("z,n,k\n")
    assert list(tmp_path.iterdir()) == []
    r = run_cli("table", "k", "-o", "")
    assert r.returncode == 2 and r.stderr.startswith("Error: ") and r.stderr.count("\n") == 1


@pytest.mark.parametrize(
    "args, option",
    [
        (["solve", "-z", "8", "-F", "1e300", "-K", "1e-300"], "--load"),
        (["solve", "-z", "8", "-F", "1e-300", "-K", "1e300"], "--load"),
        (["solve", "-z", "8", "-K", "4e5", "-F", "1e300"], "--load"),
        (["solve", "-z", "8", "-K", "4e5", "-F", "100", "-G", "1e308"], "--clearance"),
        (["solve", "-z", "8", "-K", "4e5", "-F", "100", "-G", "-1e308"], "--clearance"),
        (["solve", "306", "-F", "1e-300"], "--load"),
        (["table", "k", "-G", "1e308"], "--clearance"),
        (["solve", "-z", "8", "-K", "4e5", "-F", "100", "--revolutions", "nan"], "--revolutions"),
        (["solve", "-z", "10", "-F", "5kN", "-K", "10N/um^1.5", "-m", "10/9"], "--stiffness"),
        (["solve", "-z", "10", "-F", "5kN", "-K", "10", "-m", "10/0"], "--exponent"),
    ],
)
def test_extreme_inputs_are_one_error_line(args, option):
    r = run_cli(*args)
    assert r.returncode == 2, r.stderr
    assert r.stderr.startswith(f"Error: Invalid value for '{option}'"), r.stderr
    assert r.stderr.count("\n") == 1, r.stderr
    assert r.stdout == ""


def test_a_huge_cage_angle_keeps_its_position():
    """Reduced in degrees before radians: 1e16° is 280° exactly."""
    big = solve(8, 100.0, 4e5, 0.0, 1e16)
    same = solve(8, 100.0, 4e5, 0.0, 280.0)
    assert float(big.q_max) == pytest.approx(float(same.q_max), rel=1e-13)
    assert float(big.q_max) == pytest.approx(float(big.ball_loads().max()), rel=1e-13)
    assert np.all((big.ball_angles() >= 0) & (big.ball_angles() < 360.0))


def test_roller_stiffness_units():
    assert parse_stiffness("3e5N/mm^(10/9)", 10 / 9) == 3e5
    assert parse_stiffness("2N/um^(10/9)", 10 / 9) == pytest.approx(2 * 1000 ** (10 / 9))
    assert parse_stiffness("4700kgf/mm^3/2", 1.5) == pytest.approx(4700 * 9.80665)
    with pytest.raises(InputError, match="exponent 1.5"):
        parse_stiffness("10N/um^1.5", 10 / 9)


def test_csv_headers_carry_units():
    out = (
        CliRunner()
        .invoke(
            main, ["solve", "-z", "8", "-F", "300kgf", "-K", "4700kgf/mm^1.5", "--format", "csv"]
        )
        .output
    )
    header = out.splitlines()[0]
    assert header.startswith(
        "method,balls,load [N],stiffness [N/mm^1.5],clearance [mm],cage_angle_deg [°]"
    )
    assert (
        ",q_max [N]," in header and ",x [mm]," in header and ",stiffness_radial [N/mm]," in header
    )
    per_ball = CliRunner().invoke(
        main, ["solve", "-z", "8", "-F", "300kgf", "-K", "4700kgf/mm^1.5", "--format", "csv", "--per-ball"]
    ).output  # fmt: skip
    assert per_ball.splitlines()[0].endswith(
        ",ball,ball_angles_deg [°],ball_approaches [mm],ball_loads [N]"
    )


def test_table_at_a_general_cage_angle_leaves_out_one_and_two_balls():
    out = CliRunner().invoke(main, ["table", "k", "--cage-angle", "10", "--z-max", "5"])
    assert out.exit_code == 0
    assert "z = 1 and 2 left out" in out.output
    r = solve(np.arange(3, 6), 1000.0, 1e5, 0.0, 10.0)
    assert f"{float(r.k[0]):.4g}" in out.output


def test_fit_rejects_a_falling_curve(tmp_path):
    f = tmp_path / "decr.csv"
    f.write_text("load,displacement\n100,1.5\n200,0.8\n400,0.2\n")
    r = run_cli("fit", str(f))
    assert r.returncode == 2
    assert "n = -0.688 <= 0" in r.stderr and r.stderr.count("\n") == 1


def test_fit_of_data_spanning_many_decades(tmp_path):
    f = tmp_path / "wide.csv"
    f.write_text("load,displacement\n1e-200,1e-200\n1e200,1e200\n")
    r = run_cli("fit", str(f), "--format", "json")
    assert r.returncode == 0, r.stderr
    assert '"n": 1.0' in r.stdout


def test_a_bearing_outside_the_catalogue_with_its_ball_set_resolves_a_class():
    out = CliRunner().invoke(
        main,
        ["solve", "6330", "-F", "1kN", "-G", "C3", "-z", "8", "--ball-diameter", "30",
         "--pitch-diameter", "225", "--format", "json"],
    )  # fmt: skip
    assert out.exit_code == 0, out.output
    import json

    doc = json.loads(out.output)
    # ISO 5753-1 C3, bore 140-160 mm (NSK 9.9)
    assert doc["bearing"]["clearance_range"] == [0.046, 0.091]
    assert doc["cases"][0]["clearance"] == pytest.approx(0.0685)


def test_a_clearance_of_half_a_ball_is_refused():
    r = run_cli("solve", "306", "-F", "300kgf", "-G", "20")
    assert r.returncode == 2
    assert "did you mean 20um?" in r.stderr and r.stderr.count("\n") == 1
