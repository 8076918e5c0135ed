"""``--plot FILE`` of the commands: checks before any work, writing after, one error line.

matplotlib is an optional extra (``pip install matplotlib``), imported only when a plot
is asked for.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import Any

import click


def check_plot(path: str) -> None:
    """Before any work: matplotlib is installed, the plot file can be written, and in the format
    its extension names (one of :func:`bearingload.reports.plots.plot_formats`)."""
    from bearingload.reports.plots import (
        INSTALL_HINT,
        PlotUnavailable,
        plot_format,
        plot_formats,
        require_matplotlib,
    )

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
    fmt, allowed = plot_format(path), plot_formats()
    if fmt not in allowed:
        what = f"cannot write a .{fmt} file" if fmt else "the file name has no extension"
        raise click.UsageError(
            f"Invalid value for '--plot': {what} ({path!r}); allowed extensions: "
            f"{', '.join('.' + f for f in allowed)}"
        )
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


def save_plot(figure: Callable[[], Any], path: str) -> None:
    """Draw ``figure()`` and write it to ``path`` (checked by :func:`check_plot`) whole."""
    from bearingload.reports.plots import save_figure

    write_plot(lambda: save_figure(figure(), path), path)


def ball_loads_plot_option(command: Callable[..., Any]) -> Callable[..., Any]:
    """``--plot FILE`` of ``solve``: the command draws the ball loads of its own solution."""
    return click.option(
        "--plot",
        type=click.Path(dir_okay=False),
        help="Also draw the ball loads around the ring that the command solved (exact model; "
        "with a combined load also every ball's contact angle) into FILE; its extension gives "
        "the format (.png, .pdf, .svg ...). Needs matplotlib: pip install matplotlib.",
    )(command)
