"""The report of ``bearingload fit``: a power law fitted to a measured load-displacement curve.

Kuzmenko & Sabadash (2014) fit ``Q = C u^n`` to the load ``Q`` and shaft displacement ``u`` of a
pressed bearing, claim that the load-concentration factor is ``K_Q = n`` (their eq. 1.10) and give
the normalised distribution ``sigma_bar = (u/u_max)^(n-1)`` (eq. 1.13). This module fits the law by
their two-point method and by least squares (:mod:`bearingload.studies.fit`), puts the claim next to the
theoretical ``K_Q(z)`` of the equilibrium and continuum models and next to the Hertz exponent 3/2
of an ideal clearance-free bearing, and renders all of it through :mod:`bearingload.reports.render`.

Rows are built once (:func:`build_fit_report`); :func:`fit_report` renders them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from bearingload.errors import InputError
from bearingload.reports.render import Column, Table, render
from bearingload.units import UNITS, parse_quantity

#: Exponent of the Hertz point contact, Q = K delta^(3/2): the exponent of the whole
#: load-displacement curve of an ideal clearance-free ball bearing. [-]
HERTZ_EXPONENT = 1.5

#: The fits of the report, in order: (key, method of :func:`bearingload.studies.fit.fit_power_law`, label).
FITS = (
    ("two_point", "two_point", "two base points (paper, eq. 2.1)"),
    ("loglog", "loglog", "least squares on ln Q (log-log)"),
    ("least_squares", "least_squares", "least squares on Q (direct)"),
)

EXPLANATION = (
    "The paper (Kuzmenko & Sabadash 2014, eq. 1.10) claims K_Q = n.",
    "An ideal clearance-free ball bearing has n = 3/2 exactly (every ball obeys Hertz, "
    "Q = K delta^(3/2), and the load zone stays at +-90°), while its K_Q(z) is about 2.19: "
    "in the models K_Q = n does not hold.",
    "A fitted n above 3/2 says the measured curve stiffens faster than Hertz allows (clearance "
    "closing, the load zone spreading, compliance of shaft, housing and fits); an agreement of "
    "the fitted n with K_Q(z) therefore does not confirm the claim.",
)


def parse_base_point(
    text: str, load_unit: str = "N", displacement_unit: str = "mm"
) -> tuple[float, float]:
    """Parse ``LOAD:DISPLACEMENT`` (e.g. ``200kgf:0.8mm``) into ``(N, mm)``.

    A bare number on either side is taken in the file's unit (``load_unit``, ``displacement_unit``).

    Raises
    ------
    InputError
        Parameter ``base``: not two quantities separated by one colon, or a bad number or unit.

    Examples
    --------
    >>> parse_base_point("200kgf:0.8mm")
    (1961.33, 0.8)
    >>> parse_base_point("200:800", "kgf", "um")
    (1961.33, 0.8)
    """
    parts = str(text).split(":")
    if len(parts) != 2 or not all(p.strip() for p in parts):
        raise InputError("base", f"{text!r} is not LOAD:DISPLACEMENT (write e.g. 200kgf:0.8mm)")
    values = []
    for part, kind, unit in zip(
        parts, ("force", "length"), (load_unit, displacement_unit), strict=True
    ):
        try:
            value = float(part) * UNITS[kind][unit]
        except ValueError:
            value = parse_quantity(part, kind, parameter="base")
        if not math.isfinite(value) or value <= 0:
            raise InputError("base", f"{text!r}: load and displacement must be finite and > 0")
        values.append(value)
    return values[0], values[1]


@dataclass(frozen=True)
class FitReport:
    """Everything the report shows, in file units where the user sees them.

    Attributes
    ----------
    path : str
        The CSV file.
    load_unit, displacement_unit : str
        Units of the file's columns.
    rows : ndarray of int
        Line number of each pair in the file.
    load, displacement : ndarray
        The pairs in the file's units.
    fits : dict
        key of :data:`FITS` -> :class:`bearingload.studies.fit.PowerLawFit` (internal units N, mm).
    base_points : tuple
        The two base points of the two-point fit, in the file's units.
    base_from_file : bool
        True when the base points are the rows of lowest and highest load (no ``--base``).
    balls : int or None
        Number of balls for the theoretical ``K_Q``.
    k_q : dict
        label -> (value or None, note): the claimed and theoretical ``K_Q`` and the Hertz exponent.
    """

    path: str
    load_unit: str
    displacement_unit: str
    rows: np.ndarray
    load: np.ndarray
    displacement: np.ndarray
    fits: dict[str, Any]
    base_points: tuple[tuple[float, float], tuple[float, float]]
    base_from_file: bool
    balls: int | None
    k_q: dict[str, tuple[float | None, str]] = field(default_factory=dict)

    def coefficient(self, key: str) -> float:
        """``C`` of fit ``key`` in the file's units [load_unit / displacement_unit^n]."""
        fit = self.fits[key]
        lf = UNITS["force"][self.load_unit]
        df = UNITS["length"][self.displacement_unit]
        return float(fit.coefficient * df**fit.exponent / lf)


def build_fit_report(
    path: str,
    *,
    base: list[tuple[float, float]] | None = None,
    balls: int | None = None,
    load_unit: str = "N",
    displacement_unit: str = "mm",
) -> FitReport:
    """Read ``path``, fit the power law three ways and compute the ``K_Q`` comparison.

    Parameters
    ----------
    path : str
        CSV with a header naming ``load`` and ``displacement``.
    base : list of two (load [N], displacement [mm]) pairs, optional
        Base points of the two-point fit; default: the rows of lowest and highest load.
    balls : int, optional
        Number of balls ``z`` for the theoretical ``K_Q(z)``. [-]
    load_unit, displacement_unit : str
        Units of the file's columns.
    """
    from bearingload.studies.fit import fit_power_law, read_measurements

    if load_unit not in UNITS["force"]:
        raise InputError(
            "load_unit", f"unknown unit {load_unit!r}; allowed: {', '.join(UNITS['force'])}"
        )
    if displacement_unit not in UNITS["length"]:
        raise InputError(
            "displacement_unit",
            f"unknown unit {displacement_unit!r}; allowed: {', '.join(UNITS['length'])}",
        )
    if base is not None and len(base) != 2:
        raise InputError("base", f"give the base points twice or not at all (got {len(base)})")
    m = read_measurements(path, load_unit=load_unit, displacement_unit=displacement_unit)
    lf = UNITS["force"][load_unit]
    df = UNITS["length"][displacement_unit]
    fits = {}
    for key, method, _ in FITS:
        kwargs = {"base_points": base} if method == "two_point" and base is not None else {}
        with np.errstate(all="ignore"):
            fit = fit_power_law(m.load, m.displacement, method, **kwargs)
        if not (np.isfinite(fit.coefficient) and np.isfinite(fit.exponent)):
            raise InputError(
                path,
                f"the {method.replace('_', ' ')} fit of Q = C u^n overflows double precision "
                f"(n = {fit.exponent:.4g}); the loads or displacements span too many decades",
            )
        if fit.exponent <= 0:
            raise InputError(
                path,
                f"the {method.replace('_', ' ')} fit gives n = {fit.exponent:.4g} <= 0: the load "
                "falls as the displacement grows; a bearing's load-displacement curve rises",
            )
        fits[key] = fit
    if base is None:
        i1, i2 = int(np.argmin(m.load)), int(np.argmax(m.load))
        pts = ((m.load[i1], m.displacement[i1]), (m.load[i2], m.displacement[i2]))
    else:
        pts = (base[0], base[1])
    base_file = (
        (float(pts[0][0] / lf), float(pts[0][1] / df)),
        (float(pts[1][0] / lf), float(pts[1][1] / df)),
    )
    report = FitReport(
        path=path,
        load_unit=load_unit,
        displacement_unit=displacement_unit,
        rows=m.rows,
        load=m.load / lf,
        displacement=m.displacement / df,
        fits=fits,
        base_points=base_file,
        base_from_file=base is None,
        balls=balls,
    )
    report.k_q.update(_k_q_comparison(fits, balls))
    return report


def _k_q_comparison(fits: dict[str, Any], balls: int | None) -> dict[str, tuple[float | None, str]]:
    from bearingload.models.registry import compute

    out: dict[str, tuple[float | None, str]] = {
        "claim_two_point": (fits["two_point"].exponent, "the paper's claim K_Q = n, two-point n"),
        "claim_least_squares": (
            fits["least_squares"].exponent,
            "the same claim with n from least squares on Q",
        ),
    }
    if balls is not None:
        # K_Q at zero clearance does not depend on load or stiffness; any positive values do.
        exact = compute("exact", balls, 1000.0, 1e5, 0.0, 0.0)
        out["theory_exact"] = (
            float(exact.K_Q),
            f"K_Q(z = {balls}), exact discrete model, zero clearance, a ball under the load",
        )
        half = None
        if balls >= 3:
            half = float(compute("exact", balls, 1000.0, 1e5, 0.0, 180.0 / balls).K_Q)
        out["theory_exact_half_pitch"] = (
            half,
            f"K_Q(z = {balls}), the same with the load between two balls",
        )
    continuum = compute("continuum", balls or 1, 1000.0, 1e5)
    out["theory_continuum"] = (
        float(continuum.K_Q),
        "K_Q of the continuum model, zero clearance: pi/(2 I_3/2), the same for every z",
    )
    out["hertz_exponent"] = (
        HERTZ_EXPONENT,
        "n of an ideal clearance-free ball bearing (Hertz, F_r ~ x^(3/2))",
    )
    return out


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


def fit_report(
    path: str,
    *,
    base: list[tuple[float, float]] | None = None,
    balls: int | None = None,
    load_unit: str = "N",
    displacement_unit: str = "mm",
    fmt: str = "table",
) -> str:
    """Fit, compare and render in ``fmt`` (see :func:`build_fit_report` for the parameters)."""
    from bearingload.studies.fit import normalized_distribution

    r = build_fit_report(
        path, base=base, balls=balls, load_unit=load_unit, displacement_unit=displacement_unit
    )
    lu, du = r.load_unit, r.displacement_unit
    n2, nls = r.fits["two_point"].exponent, r.fits["least_squares"].exponent
    u_max = float(np.max(r.displacement))
    sigma_2 = normalized_distribution(r.displacement, n2, u_max)
    sigma_ls = normalized_distribution(r.displacement, nls, u_max)
    lf = UNITS["force"][lu]
    point_rows = [
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
    if fmt == "json":
        doc: dict[str, Any] = {
            "file": r.path,
            "load_unit": lu,
            "displacement_unit": du,
            "points": len(point_rows),
            "balls": r.balls,
        }
        for key, _, _ in FITS:
            doc[key] = _fit_json(r, key)
        doc["K_Q"] = {k: v for k, (v, _) in r.k_q.items() if k != "hertz_exponent"}
        doc["hertz_exponent"] = HERTZ_EXPONENT
        doc["rows"] = point_rows
        return render([], "json", document=doc)

    base_text = ", ".join(f"({q:.6g} {lu}, {u:.6g} {du})" for q, u in r.base_points)
    base_note = "rows of lowest and highest load" if r.base_from_file else "from --base"
    fits_table = Table(
        title=f"Power law Q = C u^n fitted to {r.path} ({len(point_rows)} points)",
        columns=[
            Column("method", "method", align="left"),
            Column("C", "C", f"{lu}/{du}^n", 6),
            Column("n", "n", "-", 6),
            Column("r2", "R²", "-", 4),
            Column("r2_log", "R² of ln Q", "-", 4),
            Column("rms", "rms residual", lu, 4),
        ],
        rows=[
            {
                "method": label,
                "C": r.coefficient(key),
                "n": r.fits[key].exponent,
                "r2": r.fits[key].r_squared,
                "r2_log": r.fits[key].r_squared_log,
                "rms": float(np.sqrt(np.mean((r.fits[key].residuals / lf) ** 2))),
            }
            for key, _, label in FITS
        ],
        notes=[f"Two-point base points: {base_text} ({base_note})."],
    )
    points_table = Table(
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
    kq_table = Table(
        title="Load concentration: the paper's claim K_Q = n against the theory",
        columns=[Column("value", "value", "-", 5), Column("what", "what", align="left")],
        rows=[{"value": "n/a" if v is None else v, "what": note} for v, note in r.k_q.values()],
        notes=list(EXPLANATION)
        + ([] if r.balls is not None else ["Give --balls Z for the theoretical K_Q(z)."]),
    )
    return render([fits_table, points_table, kq_table], fmt)
