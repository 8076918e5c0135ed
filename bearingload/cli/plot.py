"""``--plot FILE.png`` of the commands: checks before any work, writing after, one error line.

matplotlib is an optional extra (``pip install 'bearingload[plot]'``), imported only when a plot
is asked for.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable
from typing import Any

import click

from bearingload.cli.options import library_errors


def check_plot(path: str) -> None:
    """Before any work: matplotlib is installed and the plot file can be written."""
    from bearingload.reports.plots import INSTALL_HINT, PlotUnavailable, require_matplotlib

    if path == "":
        raise click.UsageError("Invalid value for '--plot': the file name is empty")
    try:
        require_matplotlib()
    except PlotUnavailable as exc:
        raise click.ClickException(INSTALL_HINT) from exc
    real = os.path.realpath(path)
    folder = os.path.dirname(real)
    if os.path.isdir(real):
        raise click.UsageError(f"Invalid value for '--plot': {path!r} is a directory")
    if not os.path.isdir(folder) or not os.access(folder, os.W_OK):
        raise click.UsageError(
            f"Invalid value for '--plot': cannot write {path!r} (no writable folder {folder!r})"
        )


def write_plot(write: Callable[[], None], path: str) -> None:
    """Run ``write`` (which saves the figure to ``path``); an OSError becomes one usage error."""
    try:
        write()
    except OSError as exc:
        raise click.UsageError(
            f"Invalid value for '--plot': cannot write {path!r}: {exc.strerror or exc}"
        ) from exc


def ball_loads_plot_option(command: Callable[..., Any]) -> Callable[..., Any]:
    """``--plot FILE.png`` for ``solve``: the exact ball loads around the ring.

    The command runs as it is; with ``--plot`` the case is resolved from the same options (with
    ``--clearance-pick range``: min, mean and max side by side) and drawn before the command
    runs, and the PNG is written after it succeeded.
    """

    @click.option(
        "--plot",
        type=click.Path(dir_okay=False),
        help="Also draw the exact ball loads around the ring into FILE.png (needs matplotlib: "
        "pip install 'bearingload[plot]').",
    )
    @functools.wraps(command)
    def wrapper(*args: Any, plot: str | None = None, **kwargs: Any) -> Any:
        if plot is None:
            return command(*args, **kwargs)
        check_plot(plot)
        figure = library_errors(_ball_loads_figure)(kwargs)
        result = command(*args, **kwargs)
        from bearingload.reports.plots import save_png

        write_plot(lambda: save_png(figure, plot), plot)
        return result

    return wrapper


def _ball_loads_figure(options: dict[str, Any]) -> Any:
    """The ball-loads figure of the case(s) the ``solve`` options describe."""
    from bearingload.cli.cases import resolve_case
    from bearingload.cli.options import cage_angle_deg
    from bearingload.models.equilibrium import solve
    from bearingload.reports.plots import ball_loads_figure

    geometry = {
        "ball_diameter": options["ball_diameter"],
        "pitch_diameter": options["pitch_diameter"],
        "f_i": options["inner_conformity"],
        "f_o": options["outer_conformity"],
        "modulus": options["modulus"],
        "poisson": options["poisson"],
    }
    pick = options["clearance_pick"]
    picks = ["min", "mean", "max"] if pick == "range" else [pick]
    cases = []
    for p in picks:
        z, k, g, m, _ = resolve_case(
            options["bearing"],
            options["balls"],
            options["stiffness"],
            options["clearance"],
            p,
            options["exponent"],
            geometry,
        )
        angle = cage_angle_deg(options["cage_angle"], z)
        label = f"G_r = {g * 1e3:.4g} µm ({p})" if len(picks) > 1 else ""
        cases.append((label, solve(z, options["load"], k, g, angle, m)))
    r = cases[len(cases) // 2][1]
    title = (
        f"Ball loads, exact ring equilibrium: z = {int(r.balls)}, F_r = {float(r.load):.6g} N, "
        f"K = {float(r.stiffness):.6g} N/mm^{float(r.exponent):g}, "
        f"G_r = {float(r.clearance) * 1e3:.6g} µm, cage angle {float(r.cage_angle):.6g}°"
    )
    return ball_loads_figure(cases, title)
