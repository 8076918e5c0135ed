"""Figures (optional extra ``bearingload[plot]``): a cage sweep (radial or combined load), and the
ball loads around a ring.

matplotlib is imported inside these functions only, with its Agg (file) backend and no pyplot,
so nothing global changes and a terminal calculation without ``--plot`` never pays for it.
Each function returns the Figure, so its data can be checked; :func:`save_figure` writes it whole
or not at all, in the format its extension names (:func:`plot_formats`).
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import Any

import numpy as np

from bearingload.errors import BearingloadError

INSTALL_HINT = "--plot needs matplotlib: pip install matplotlib"


class PlotUnavailable(BearingloadError):
    """matplotlib is not installed."""

    def __init__(self) -> None:
        super().__init__(INSTALL_HINT)


def require_matplotlib() -> None:
    """Raise :class:`PlotUnavailable` unless matplotlib can be imported."""
    try:
        import matplotlib  # noqa: F401
    except ImportError as exc:
        raise PlotUnavailable() from exc


def _figure(width: float, height: float) -> Any:
    require_matplotlib()
    from matplotlib.figure import Figure

    return Figure(figsize=(width, height), dpi=100, layout="constrained")


def sweep_figure(s: Any, name: str | None = None) -> Any:
    """x, y [µm], Q_max [N] and radial stiffness [N/mm] over the cage angle [°] of a CageSweep
    (``name``: the bearing's designation, in the title).

    One panel each, in that order; each panel's one line holds the sweep's values.
    """
    panels = [
        (s.x * 1e3, "x, along load [µm]", "ring displacement along the load"),
        (s.y * 1e3, "y, across load [µm]", "ring displacement across the load"),
        (s.q_max, "Q_max [N]", "heaviest ball load"),
        (s.stiffness_radial, "K_r [N/mm]", "radial stiffness dF_r/dx (F_y held 0)"),
    ]
    return _sweep_panels(
        s.cage_angle,
        panels,
        f"{_named(name)}Cage sweep over one pitch: z = {s.balls}, F_r = {s.load:.4g} N, "
        f"K = {s.stiffness:.4g} N/mm^{s.exponent:g}, G_r = {s.clearance * 1e3:.4g} µm",
        height=8.0,
    )


def combined_sweep_figure(s: Any, name: str | None = None) -> Any:
    """x, y, axial displacement [µm], tilt [°], Q_max [N] and L10r [10^6 rev] over the cage
    angle [°] of a CombinedSweep (L10r only where C_r is known; ``name``: the bearing's
    designation, in the title).

    One panel each, in that order; each panel's one line holds the sweep's values.
    """
    r = s.result
    panels = [
        (r.x * 1e3, "x [µm]", "ring displacement along the load"),
        (r.y * 1e3, "y [µm]", "ring displacement across the load"),
        (r.axial * 1e3, "axial [µm]", "axial displacement from the centred rings"),
        (r.tilt, "tilt [°]", "tilt about the axis across the load"),
        (r.q_max, "Q_max [N]", "heaviest ball load"),
    ]
    if s.reference_rating_life is not None:
        panels.append((s.reference_rating_life, "L10r [10^6 rev]", "ISO/TS 16281 L10r"))
    return _sweep_panels(
        s.cage_angle,
        panels,
        f"{_named(name)}Cage sweep over one pitch: z = {s.balls}, "
        f"F_r = {float(r.load[0]):.4g} N, "
        f"F_a = {float(r.axial_load[0]):.4g} N, G_r = {float(r.clearance[0]) * 1e3:.4g} µm"
        + ("" if s.speed is None else f"\nn = {s.speed:.6g} rpm")
        + (" (ball dynamics)" if getattr(r, "model", None) is not None else ""),
        height=1.8 * len(panels) + 0.8,
    )


def _sweep_panels(angle: Any, panels: list[Any], title: str, height: float) -> Any:
    """A figure of one panel per (values, axis label, panel title) of ``panels`` over the cage
    ``angle`` [°], one line of the sweep's values in each, under ``title``."""
    fig = _figure(7.0, height)
    axes = fig.subplots(len(panels), 1, sharex=True)
    for ax, (values, label, name) in zip(axes, panels, strict=True):
        ax.plot(np.asarray(angle), values, marker=".")
        ax.set_ylabel(label)
        ax.set_title(name, fontsize="small", loc="left")
        ax.grid(True, alpha=0.3)
        ax.ticklabel_format(axis="y", useOffset=False)
    axes[-1].set_xlabel("cage angle (ball 1 from the load line) [°]")
    fig.suptitle(title, fontsize="medium")
    return fig


def _named(name: str | None) -> str:
    return f"{name}: " if name else ""


def _designation(case: Any) -> str | None:
    """The designation of a solved case's bearing; None when given by hand."""
    bearing = getattr(case, "bearing", None)
    return None if bearing is None else bearing.designation


def ball_loads_figure(
    cases: Sequence[tuple[str, Any, Any]],
    title: str,
    contact_angles: Sequence[Any] | None = None,
) -> Any:
    """Ball loads [N] around the ring, one bar per ball at its angle [°], for solved cases; with
    ``contact_angles`` a second panel: every ball's contact angle [°] over its angle.

    ``cases``: (label, ball angles [°], ball loads [N]) triples, drawn side by side (e.g. the
    clearance class at its min, mean and max); ``contact_angles``: one array per case [°]. The
    load line points down, as in the papers' figures.
    """
    import textwrap

    fig = _figure(6.5, 6.5 if contact_angles is None else 9.0)
    if contact_angles is None:
        ax = fig.add_subplot(projection="polar")
    else:
        ax = fig.add_subplot(3, 1, (1, 2), projection="polar")
    ax.set_theta_zero_location("S")
    n = len(cases)
    for j, (label, angles, loads) in enumerate(cases):
        z = len(loads)
        width = np.deg2rad(360.0 / z) * 0.8 / n
        shift = (j - (n - 1) / 2) * width
        ax.bar(np.deg2rad(np.asarray(angles)) + shift, loads, width=width, label=label, alpha=0.8)
    ax.set_xlabel("ball angle from the load line [°]; load F_r along 0° (down)")
    ax.set_ylabel("ball load Q [N]", labelpad=28)
    ax.set_title("\n".join(textwrap.wrap(title, 70)), fontsize="small")
    if n > 1 or cases[0][0]:
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=n, fontsize="small")
    if contact_angles is not None:
        low = fig.add_subplot(3, 1, 3)
        for (label, angles, _), alpha in zip(cases, contact_angles, strict=True):
            low.plot(angles, alpha, marker="o", label=label or None)
        low.set_xlabel("ball angle from the load line [°]")
        low.set_ylabel("contact angle [°]")
        low.grid(True, alpha=0.3)
    return fig


def _clearances(values: Sequence[float]) -> str:
    """``G_r = 20.5 µm`` for one case; ``G_r = 13, 20.5, 28 µm`` for the curves of a range."""
    return "G_r = " + ", ".join(f"{g * 1e3:.6g}" for g in values) + " µm"


def solve_figure(cases: Sequence[Any]) -> Any:
    """The ball loads of ``bearingload solve``'s own radial cases (LoadedCase of
    :mod:`bearingload.studies.loaded_bearing`): those of the exact model, one set per clearance
    pick side by side; the title names the bearing (a catalogue one) and the middle case."""
    exact = [c for c in cases if c.result.method == "exact"]
    several = len(exact) > 1
    drawn = []
    for c in exact:
        model, case = c.result.model, c.result.case
        label = (
            f"G_r = {float(case.clearance) * 1e3:.4g} µm ({c.clearance_pick})" if several else ""
        )
        drawn.append((label, model.ball_angles, model.ball_loads))
    case = exact[len(exact) // 2].result.case
    title = (
        f"{_named(_designation(exact[0]))}Ball loads, exact ring equilibrium: "
        f"z = {int(case.balls)}, "
        f"F_r = {float(case.load):.6g} N, K = {float(case.stiffness):.6g} "
        f"N/mm^{float(case.exponent):g}, "
        f"{_clearances([float(c.result.case.clearance) for c in exact])}, "
        f"cage angle {float(case.cage_angle):.6g}°"
    )
    return ball_loads_figure(drawn, title)


def combined_loads_figure(cases: Sequence[Any]) -> Any:
    """The ball loads and contact angles of ``bearingload solve``'s own combined-load cases
    (CombinedCase of :mod:`bearingload.studies.combined_bearing`), one set per clearance pick;
    the title names the bearing (a catalogue one), as the radial figure's does."""
    several = len(cases) > 1
    drawn, alphas = [], []
    for c in cases:
        r = c.result
        g = float(np.asarray(r.clearance).reshape(-1)[0])
        label = f"G_r = {g * 1e3:.4g} µm ({c.bearing.clearance_pick})" if several else ""
        drawn.append(
            (label, np.asarray(r.ball_angles).reshape(-1), np.asarray(r.ball_loads).reshape(-1))
        )
        # a ball carrying no load has no contact angle: no point (a loose ball's ±90° would
        # read as a ball at the groove edge; the human table shows '-')
        loads = np.asarray(r.ball_loads).reshape(-1)
        alphas.append(np.where(loads > 0.0, np.asarray(r.contact_angles).reshape(-1), np.nan))
    r = cases[len(cases) // 2].result

    def one(v: Any) -> float:
        return float(np.asarray(v).reshape(-1)[0])

    title = (
        f"{_named(_designation(cases[0]))}Ball loads, 3-D ring equilibrium: z = {int(r.balls)}, "
        f"F_r = {one(r.load):.6g} N, "
        f"F_a = {one(r.axial_load):.6g} N, "
        f"{_clearances([one(c.result.clearance) for c in cases])}, "
        f"cage angle {one(r.cage_angle):.6g}°"
    )
    speed = getattr(r, "speed", None)  # the ball dynamics: loads and angles drawn are the inner
    if speed is not None:
        title += f", n = {one(speed):.6g} rpm, ball dynamics: the inner contacts"
    return ball_loads_figure(drawn, title, alphas)


#: Extensions matplotlib writes through Pillow: offered only where Pillow can write them.
PILLOW_FORMATS = frozenset({"avif", "gif", "jpeg", "jpg", "tif", "tiff", "webp"})


def plot_formats() -> list[str]:
    """The file extensions a figure can be written as here: those of matplotlib's canvas, less
    ``pgf`` (needs a LaTeX installation) and the Pillow formats Pillow cannot write."""
    require_matplotlib()
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    names = set(FigureCanvasAgg.get_supported_filetypes()) - {"pgf"}
    try:
        from PIL import Image

        Image.init()
        pillow = {
            ext.lstrip(".").lower()
            for ext, fmt in Image.registered_extensions().items()
            if fmt in Image.SAVE
        }
    except ImportError:
        pillow = set()
    return sorted(n for n in names if n not in PILLOW_FORMATS or n in pillow)


def plot_format(path: str) -> str:
    """The format of a figure file: its extension, lower case, without the dot ('' if none)."""
    return os.path.splitext(path)[1].lstrip(".").lower()


def save_figure(fig: Any, path: str) -> None:
    """Write ``fig`` to ``path`` in the format its extension names (:func:`plot_formats`), whole
    or not at all (temporary file, then rename)."""
    import logging
    import tempfile

    fmt = plot_format(path) or "png"
    real = os.path.realpath(path)
    if os.path.isdir(real):
        raise IsADirectoryError(21, "is a directory", path)
    fd, tmp = tempfile.mkstemp(prefix=".bearingload-", suffix=f".{fmt}", dir=os.path.dirname(real))
    # PostScript has no transparency: matplotlib logs that it draws the grid opaque, a line
    # for developers, not for the user's terminal
    ps_log = logging.getLogger("matplotlib.backends.backend_ps")
    level = ps_log.level
    try:
        ps_log.setLevel(logging.ERROR)
        with os.fdopen(fd, "wb") as fh:
            fig.savefig(fh, format=fmt)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, real)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    finally:
        ps_log.setLevel(level)
