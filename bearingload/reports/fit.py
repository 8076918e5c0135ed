"""The report of ``bearingload fit``: a power law fitted to a measured load-displacement curve.

Kuzmenko & Sabadash (2014) fit ``Q = C u^n`` to the load ``Q`` and shaft displacement ``u`` of a
pressed bearing, claim that the load-concentration factor is ``K_Q = n`` (their eq. 1.10) and give
the normalised distribution ``sigma_bar = (u/u_max)^(n-1)`` (eq. 1.13). This module fits the law by
their two-point method and by least squares (:mod:`bearingload.studies.fit`), puts the claim next to the
theoretical ``K_Q(z)`` of the equilibrium and continuum models and next to the Hertz exponent 3/2
of an ideal clearance-free bearing, and renders all of it through :mod:`bearingload.reports.render`.

The fits and the comparison are computed in :mod:`bearingload.studies.fit_comparison`;
:func:`fit_report` renders them.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from bearingload.reports.render import Column, Table, render
from bearingload.studies.fit_comparison import (
    FITS,
    HERTZ_EXPONENT,
    FitReport,
    build_fit_report,
)
from bearingload.units import UNITS

EXPLANATION = (
    "The paper (Kuzmenko & Sabadash 2014, eq. 1.10) claims K_Q = n.",
    "An ideal clearance-free ball bearing has n = 3/2 exactly (every ball obeys Hertz, "
    "Q = K delta^(3/2), and the load zone stays at +-90°), while its K_Q(z) is about 2.19: "
    "in the models K_Q = n does not hold.",
    "A fitted n above 3/2 says the measured curve stiffens faster than Hertz allows (clearance "
    "closing, the load zone spreading, compliance of shaft, housing and fits); an agreement of "
    "the fitted n with K_Q(z) therefore does not confirm the claim.",
)


def _fit_json(report: FitReport, key: str) -> dict[str, Any]:
    fit = report.fits[key]
    lf = UNITS["force"][report.load_unit]
    doc: dict[str, Any] = {
        "C": report.coefficient(key),
        "n": fit.exponent,
        "C_unit": f"{report.load_unit}/{report.displacement_unit}^n",
        "C_N_mm": fit.coefficient,
        "r_squared": fit.r_squared,
        "r_squared_log": fit.r_squared_log,
        "residuals": fit.residuals / lf,
    }
    if key == "two_point":
        doc["base_points"] = [list(p) for p in report.base_points]
    return doc


def _json_units(load_unit: str, displacement_unit: str) -> dict[str, str]:
    """The ``units`` object of fit's JSON, the rule of every JSON of the tool: the unit of every
    measured number in the file's units, ``-`` for a dimensionless one; counts (``points``,
    ``balls``, ``row``) and text are not listed. ``base_points`` are (load, displacement) pairs."""
    lu, du = load_unit, displacement_unit
    dimensionless = ("n", "r_squared", "r_squared_log", "K_Q", "hertz_exponent", "u_over_umax",
                     "sigma_bar_two_point", "sigma_bar_least_squares")  # fmt: skip
    return {
        "C": f"{lu}/{du}^n",
        "C_N_mm": "N/mm^n",
        "residuals": lu,
        "base_points": f"{lu}, {du}",
        "load": lu,
        "displacement": du,
        "fit_two_point": lu,
        "residual_two_point": lu,
        "residual_least_squares": lu,
    } | dict.fromkeys(dimensionless, "-")


def fit_report(
    path: str,
    *,
    base: list[tuple[float, float]] | None = None,
    balls: int | None = None,
    load_unit: str = "N",
    displacement_unit: str = "mm",
    fmt: str = "table",
    points: bool = False,
) -> str:
    """Fit, compare and render in ``fmt`` (see :func:`build_fit_report` for the parameters).

    csv is one table: the fits (one row per method), or with ``points`` the measured points."""
    r = build_fit_report(
        path, base=base, balls=balls, load_unit=load_unit, displacement_unit=displacement_unit
    )
    point_rows = _point_rows(r)
    if fmt == "json":
        doc: dict[str, Any] = {
            "file": r.path,
            "load_unit": r.load_unit,
            "displacement_unit": r.displacement_unit,
            "points": len(point_rows),
            "balls": r.balls,
        }
        for key, _, _ in FITS:
            doc[key] = _fit_json(r, key)
        doc["K_Q"] = {k: v for k, (v, _) in r.k_q.items() if k != "hertz_exponent"}
        doc["hertz_exponent"] = HERTZ_EXPONENT
        doc["rows"] = point_rows
        doc["units"] = _json_units(r.load_unit, r.displacement_unit)
        return render([], "json", document=doc)
    fits_table, points_table = _fits_table(r, len(point_rows)), _points_table(r, point_rows)
    if fmt == "csv":
        return render([points_table if points else fits_table], fmt)
    kq_table = Table(
        title="Load concentration: the paper's claim K_Q = n against the theory",
        columns=[Column("value", "value", "-", 5), Column("what", "what", align="left")],
        rows=[{"value": "n/a" if v is None else v, "what": note} for v, note in r.k_q.values()],
        notes=list(EXPLANATION)
        + ([] if r.balls is not None else ["Give --balls Z for the theoretical K_Q(z)."]),
    )
    return render([fits_table, points_table, kq_table], fmt)


def _point_rows(r: FitReport) -> list[dict[str, Any]]:
    """Each measured point with the fitted values and sigma_bar, in the file's units."""
    from bearingload.studies.fit import normalized_distribution

    n2, nls = r.fits["two_point"].exponent, r.fits["least_squares"].exponent
    u_max = float(np.max(r.displacement))
    sigma_2 = normalized_distribution(r.displacement, n2, u_max)
    sigma_ls = normalized_distribution(r.displacement, nls, u_max)
    lf = UNITS["force"][r.load_unit]
    return [
        {
            "row": int(row),
            "load": float(q),
            "displacement": float(u),
            "fit_two_point": float(q - res2 / lf),
            "residual_two_point": float(res2 / lf),
            "residual_least_squares": float(resls / lf),
            "u_over_umax": float(u / u_max),
            "sigma_bar_two_point": float(s2),
            "sigma_bar_least_squares": float(sls),
        }
        for row, q, u, res2, resls, s2, sls in zip(
            r.rows,
            r.load,
            r.displacement,
            r.fits["two_point"].residuals,
            r.fits["least_squares"].residuals,
            sigma_2,
            sigma_ls,
            strict=True,
        )
    ]


def _fits_table(r: FitReport, points: int) -> Table:
    lu, du = r.load_unit, r.displacement_unit
    lf = UNITS["force"][lu]
    base_text = ", ".join(f"({q:.6g} {lu}, {u:.6g} {du})" for q, u in r.base_points)
    base_note = "rows of lowest and highest load" if r.base_from_file else "from --base"
    return Table(
        title=f"Power law Q = C u^n fitted to {r.path} ({points} points)",
        columns=[
            Column("method", "method", align="left"),
            Column("C", "C", f"{lu}/{du}^n", 6),
            Column("n", "n", "-", 6),
            Column("r_squared", "R²", "-", 4),
            Column("r_squared_log", "R² of ln Q", "-", 4),
            Column("rms", "rms residual", lu, 4),
        ],
        rows=[
            {
                "method": label,
                "C": r.coefficient(key),
                "n": r.fits[key].exponent,
                "r_squared": r.fits[key].r_squared,
                "r_squared_log": r.fits[key].r_squared_log,
                "rms": float(np.sqrt(np.mean((r.fits[key].residuals / lf) ** 2))),
            }
            for key, _, label in FITS
        ],
        notes=[f"Two-point base points: {base_text} ({base_note})."],
    )


def _points_table(r: FitReport, point_rows: list[dict[str, Any]]) -> Table:
    lu, du = r.load_unit, r.displacement_unit
    u_max = float(np.max(r.displacement))
    return Table(
        title=f"Measured points and the normalised distribution sigma_bar = (u/u_max)^(n-1), "
        f"u_max = {u_max:.6g} {du}",
        columns=[
            Column("row", "row"),
            Column("load", "Q", lu, 4),
            Column("displacement", "u", du, 4),
            Column("fit_two_point", "C u^n (2-point)", lu, 5),
            Column("residual_two_point", "residual (2-point)", lu, 4),
            Column("residual_least_squares", "residual (LSQ)", lu, 4),
            Column("u_over_umax", "u/u_max", "-", 3),
            Column("sigma_bar_two_point", "sigma_bar (2-point n)", "-", 3),
            Column("sigma_bar_least_squares", "sigma_bar (LSQ n)", "-", 3),
        ],
        rows=point_rows,
        notes=["row: line in the file (the header is row 1); residual = measured - fitted."],
    )
