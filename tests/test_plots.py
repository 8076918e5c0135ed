"""--plot: the figures hold the computed data with labelled units; PNGs are real images, written
whole; without matplotlib one clear error line."""

from __future__ import annotations

import json
import sys

# matplotlib is installed by `make` (extra 'plot'): these tests need it, none is skipped
import matplotlib.image
import numpy as np
import pytest

from bearingload.models.equilibrium import solve
from bearingload.reports import plots
from bearingload.studies.sweep import sweep

from .cli_helpers import drawn, invoke, run_entry, run_process

CASE = ("-z", "9", "-F", "1kN", "-K", "1e5", "-G", "10um")


def test_sweep_figure_holds_the_sweep():
    s = sweep(9, 1000.0, 1e5, 0.01, steps=13)
    fig = plots.sweep_figure(s)
    axes = fig.get_axes()
    assert len(axes) == 4
    expected = [s.x * 1e3, s.y * 1e3, s.q_max, s.stiffness_radial]
    units = ["[µm]", "[µm]", "[N]", "[N/mm]"]
    for ax, values, unit in zip(axes, expected, units, strict=True):
        (line,) = ax.get_lines()
        np.testing.assert_array_equal(line.get_xdata(), s.cage_angle)
        np.testing.assert_array_equal(line.get_ydata(), values)
        assert unit in ax.get_ylabel()
    assert "[°]" in axes[-1].get_xlabel()
    assert fig.get_suptitle().startswith("Cage sweep over one pitch: z = 9,")
    assert plots.sweep_figure(s, "306").get_suptitle().startswith("306: Cage sweep")


def test_ball_loads_figure_holds_the_loads():
    r = solve(9, 1000.0, 1e5, 0.01, 7.0)
    fig = plots.ball_loads_figure([("", r.ball_angles, r.ball_loads)], "title")
    (ax,) = fig.get_axes()
    heights = [p.get_height() for p in ax.patches]
    np.testing.assert_allclose(heights, r.ball_loads, rtol=1e-15)
    assert "[N]" in ax.get_ylabel() and "[°]" in ax.get_xlabel()


def test_sweep_plot_png(tmp_path):
    png = tmp_path / "sweep.png"
    out = invoke("sweep", *CASE, "--steps", "19", "--plot", str(png))
    assert out.exit_code == 0 and out.output.startswith("Over one ball pitch")
    image = matplotlib.image.imread(str(png))
    assert image.shape[:2] == (800, 700)  # 7 x 8 in at 100 dpi
    assert image[..., :3].std() > 0.05  # not a blank canvas
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sweep.png"]  # no temporary left


def test_solve_plot_png_and_range(tmp_path):
    png = tmp_path / "loads.png"
    out = invoke("solve", *CASE, "--cage-angle", "7", "--plot", str(png))
    assert out.exit_code == 0 and "Ball loads" in out.output
    image = matplotlib.image.imread(str(png))
    assert image.shape[:2] == (650, 650)
    assert image[..., :3].std() > 0.05
    out = invoke(
        "solve", "306", "-F", "300kgf", "-G", "C3", "--clearance-pick", "range", "--plot", str(png)
    )
    assert out.exit_code == 0
    assert matplotlib.image.imread(str(png)).shape[:2] == (650, 650)


def test_solve_plot_figure_of_the_range(monkeypatch, tmp_path):
    figures = drawn(monkeypatch)
    out = invoke("solve", "306", "-F", "300kgf", "-G", "C3", "--clearance-pick", "range",
                 "--format", "json", "--plot", str(tmp_path / "p.png"))  # fmt: skip
    (fig,) = figures
    (ax,) = fig.get_axes()
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert [lab.split("(")[-1] for lab in labels] == ["min)", "mean)", "max)"]
    assert len(ax.patches) == 3 * 8
    cases = json.loads(out.stdout)["cases"]
    heights = [p.get_height() for p in ax.patches]
    expected = [q for c in cases for q in c["ball_loads"]]  # the command's own solution
    assert heights == pytest.approx(expected, rel=1e-9, abs=1e-9)
    # the title names every clearance drawn, not the middle one alone (it said G_r = 20.5 µm)
    assert "G_r = 13, 20.5, 28 µm," in fig.get_axes()[0].get_title().replace("\n", " ")


def test_combined_plot_title_names_every_clearance_of_a_range(monkeypatch, tmp_path):
    figures = drawn(monkeypatch)
    out = invoke("solve", "6205", "-F", "1.4kN", "-A", "700N", "-G", "C3", "--clearance-pick",
                 "range", "--plot", str(tmp_path / "p.png"))  # fmt: skip
    assert out.exit_code == 0, out.output
    (fig,) = figures
    title = fig.get_axes()[0].get_title().replace("\n", " ")
    assert "G_r = 13, 20.5, 28 µm," in title, title


def test_without_matplotlib_one_error_line_and_nothing_written(capsys, tmp_path, monkeypatch):
    for name in [m for m in sys.modules if m == "matplotlib" or m.startswith("matplotlib.")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib -> ImportError
    png, csv = tmp_path / "p.png", tmp_path / "o.csv"
    for command in ("sweep", "solve"):
        code, out, err = run_entry(
            capsys, command, *CASE, "--plot", str(png), "--format", "csv", "-o", str(csv)
        )
        assert code == 1 and out == ""
        assert err == "Error: --plot needs matplotlib: pip install matplotlib\n"
        assert list(tmp_path.iterdir()) == []


def test_plot_into_a_missing_folder_is_a_usage_error(capsys, tmp_path):
    code, out, err = run_entry(capsys, "sweep", *CASE, "--plot", str(tmp_path / "no" / "p.png"))
    assert code == 2 and out == ""
    assert err.startswith("Error: Invalid value for '--plot': cannot write")


def test_save_figure_is_atomic(tmp_path, monkeypatch):
    target = tmp_path / "p.png"
    target.write_bytes(b"old")
    fig = plots.sweep_figure(sweep(9, 1000.0, 1e5, 0.01, steps=3))

    def broken(*args, **kwargs):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(fig, "savefig", broken)
    with pytest.raises(OSError):
        plots.save_figure(fig, str(target))
    assert target.read_bytes() == b"old"
    assert [p.name for p in tmp_path.iterdir()] == ["p.png"]


@pytest.mark.parametrize("extension", ["eps", "ps"])
def test_postscript_plot_prints_nothing_on_the_terminal(tmp_path, extension):
    """PostScript has no transparency (the grid lines are drawn opaque): matplotlib's log line
    about it is not for the user's terminal; the file is written, stderr stays empty."""
    path = tmp_path / f"loads.{extension}"
    out = run_process("solve", *CASE, "--plot", str(path))
    assert out.returncode == 0 and out.stderr == ""
    assert path.read_bytes().startswith(b"%!PS")


def test_solve_plot_at_speed_names_the_speed_and_the_inner_contacts(monkeypatch, tmp_path):
    """solve --speed --plot draws each ball's inner contact (load and angle, as the ball table
    shows them): its title says so, with the speed; it read as the static figure (the outer
    loads, larger by the centrifugal force, are not those drawn)."""
    figures = drawn(monkeypatch)
    out = invoke("solve", "7205B", "-F", "1kN", "-A", "500N", "--speed", "20000", "--format",
                 "json", "--plot", str(tmp_path / "p.png"))  # fmt: skip
    assert out.exit_code == 0, out.output
    (fig,) = figures
    title = fig.get_axes()[0].get_title().replace("\n", " ")
    assert "n = 20000 rpm, ball dynamics: the inner contacts" in title, title
    heights = [p.get_height() for p in fig.get_axes()[0].patches]
    case = json.loads(out.stdout)["cases"][0]
    assert heights == pytest.approx(case["ball_loads_inner"], rel=1e-9, abs=1e-9)
    figures.clear()
    invoke("solve", "7205B", "-F", "1kN", "-A", "500N", "--speed", "20000", "--quasi-static",
           "--plot", str(tmp_path / "q.png"))  # fmt: skip
    assert "ball dynamics" not in figures[0].get_axes()[0].get_title().replace("\n", " ")
