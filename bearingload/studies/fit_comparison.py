"""The fits of ``bearingload fit`` and the theory they are compared with.

Kuzmenko & Sabadash (2014) fit ``Q = C u^n`` to the load ``Q`` and shaft displacement ``u`` of a
pressed bearing and claim that the load-concentration factor is ``K_Q = n`` (their eq. 1.10).
:func:`build_fit_report` fits the law by their two-point method and by least squares
(:mod:`bearingload.studies.fit`) and puts the claim next to the theoretical ``K_Q(z)`` of the
equilibrium and continuum models and next to the Hertz exponent 3/2 of an ideal clearance-free
bearing. :mod:`bearingload.reports.fit` renders it.
"""

from __future__ import annotations

import math
from dataclasses import field
from typing import Any

import numpy as np

from bearingload.constants import BALL_EXPONENT
from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.units import UNITS, parse_quantity

#: Exponent of the Hertz point contact, Q = K delta^(3/2): the exponent of the whole
#: load-displacement curve of an ideal clearance-free ball bearing. [-]
HERTZ_EXPONENT = BALL_EXPONENT

#: The fits of the report, in order: (key, method of :func:`bearingload.studies.fit.fit_power_law`, label).
FITS = (
    ("two_point", "two_point", "two base points (paper, eq. 2.1)"),
    ("loglog", "loglog", "least squares on ln Q (log-log)"),
    ("least_squares", "least_squares", "least squares on Q (direct)"),
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
