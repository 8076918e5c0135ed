"""The work-precision diagram of ``bearingload accuracy``: log error against log time per case.

matplotlib (the ``plot`` extra) is imported here only, inside :func:`plot_work_precision`.
"""

from __future__ import annotations

from typing import Any

from bearingload.errors import InputError

#: Errors below this are drawn at it (an exact zero has no logarithm). [-]
ERROR_FLOOR = 1e-17


def plot_work_precision(rows: list[dict[str, Any]], path: str) -> None:
    """Draw the largest and median relative error of each method against its vectorised time per
    case, one line per method (its settings joined in order; the combined solver's groups of
    cases as points), and save it as PNG at ``path``.

    Parameters
    ----------
    rows : list of dict
        Rows of :func:`bearingload.quality.accuracy.measure` with timing.
    path : str
        Output file (PNG).

    Raises
    ------
    InputError
        matplotlib is not installed (parameter ``plot``).
    """
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise InputError("plot", "needs matplotlib: pip install matplotlib") from None
    fig, axes = plt.subplots(1, 2, figsize=(12, 6), sharey=True)
    methods = list(dict.fromkeys(r["method"] for r in rows))
    for ax, timing, title in (
        (axes[0], "seconds_per_case_vectorised", "vectorised (one call on many cases)"),
        (axes[1], "seconds_per_case", "one case per call"),
    ):
        for i, name in enumerate(methods):
            mine = [r for r in rows if r["method"] == name]
            t = [r[timing] for r in mine]
            color = f"C{i}"
            # the combined solver's rows are groups of cases, not settings: points, no line
            joined = name != "combined"
            for key, style, label in (
                ("error_max", "-o" if joined else "o", f"{name} (largest)"),
                ("error_median", ":s" if joined else "s", f"{name} (median)"),
            ):
                err = [100.0 * max(r[key], ERROR_FLOOR) for r in mine]  # in %
                ax.loglog(t, err, style, color=color, label=label, markersize=4)
        ax.set_xlabel("time per case [s]")
        ax.set_title(title)
        ax.grid(True, which="major", alpha=0.3)
    axes[0].set_ylabel("relative error of Q_max [%]")
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=7, loc="lower center", ncol=6)
    fig.suptitle(
        "bearingload accuracy: error against run time (50 cases, bearing 306 family; "
        "combined: 12 cases, 6305 size)"
    )
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    fig.savefig(path, dpi=110, format="png")
    plt.close(fig)
