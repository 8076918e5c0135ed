"""The work-precision report of ``bearingload accuracy`` (committed as ``tables/accuracy``): the
rows of :func:`bearingload.quality.accuracy.measure` as a table."""

from __future__ import annotations

from typing import Any

from bearingload.quality import accuracy
from bearingload.reports.quantities import column
from bearingload.reports.render import Table

COLUMNS = tuple(
    column(k, shown=True) for k in ("method", "setting", "cases", "error_median", "error_max")
) + (column("iterations", header="iterations (max)", shown=True),)
TIME_COLUMNS = tuple(
    column(k, shown=True) for k in ("seconds_per_case", "seconds_per_case_vectorised")
)
NOTES = (
    "Error: |Q_max/Q_max,ref - 1| against the exact ring equilibrium at 50 digits (mpmath, "
    "benchmarks/make_reference.py), in % (a fraction in csv and json).",
    "Cases: bearing 306 (Kuzmenko 2010: 300 kgf, K = 4700 kgf/mm^1.5), z = 6, 8, 12, 20, 40, "
    "G_r = -20, 0, 20, 100, 400 um, cage angle 0 and 180/z: 50 cases (trial: the 30 with clearance).",
    "Iterations: Newton steps (exact, continuum), evaluations of the resolving equation (trial), "
    "bisection steps (jr_table), Newton steps over all stiffness updates (combined).",
    "combined: the 3-D ring equilibrium (ISO/TS 16281, Hertz K(alpha)) of a 6305-size bearing, "
    "z = 7, on 12 cases (radial, axial, combined, a moment, preload to -30 um, an imposed "
    "misalignment of 0.05 deg and of exactly 0) against the same model at 40 digits (mpmath, "
    "benchmarks/make_combined_reference.py).",
)


def accuracy_table(rows: list[dict[str, Any]] | None = None) -> Table:
    """The work-precision table; time columns when the rows carry them."""
    rows = accuracy.measure() if rows is None else rows
    columns = COLUMNS + (TIME_COLUMNS if rows and "seconds_per_case" in rows[0] else ())
    return Table("Work-precision of every method for Q_max (k = Q_max/F_r)", columns, rows, NOTES)
