"""Variational-experimental method: fit ``Q = C u^n`` to a measured load-displacement curve.

Kuzmenko & Sabadash (2014) press a shaft into a pair of bearings, record the load ``Q`` against the
displacement ``u_0`` of the shaft, fit the power law ``Q = C u_0^n`` (eq. 1.1) and, treating the ring
on its balls as a shaft in a continuous elastic bed, obtain the normalised distribution of the
contact pressure over the displacement (eqs. 1.9-1.13)

    sigma_bar(u) = (u / u_max)^(n - 1),

and claim that the load-concentration factor is ``K_Q = Q_max/Q_mean = n`` (eq. 1.10).

Three fits are offered, each over arrays (:func:`fit_two_point`, :func:`fit_loglog`,
:func:`fit_least_squares`, or the dispatcher :func:`fit_power_law`); :func:`read_measurements`
reads the pairs from a CSV file, separately.

* ``two_point``: the paper's method, the power law through two base points (eq. 2.1),
  ``n = lg(Q_1/Q_2) / lg(u_1/u_2)``, ``C = Q_1 / u_1^n``.
* ``loglog``: linear least squares of ``ln Q = ln C + n ln u`` (numpy).
* ``least_squares``: nonlinear least squares on ``Q`` itself (``scipy.optimize.curve_fit``),
  started from the log-log fit.

Units: loads in newtons [N], displacements in millimetres [mm], so ``C`` is in [N/mm^n].

References
----------
.. [1] Kuzmenko A.G., Sabadash B.M. Load distribution between the balls of a radial rolling bearing.
   Part 2: solution by the variational-experimental method (in Russian). Problems of Tribology,
   2014, eqs. 1.1-1.13, 2.1-2.7, Table 2.1.
"""

from __future__ import annotations

import csv
import io
import math
import os
import warnings
from typing import Any, NamedTuple

import numpy as np

from bearingload.errors import ConvergenceError, InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.units import parse_quantity
from bearingload.validate import separator_slip

#: Fitting methods accepted by :func:`fit_power_law`, with a one-line description.
METHODS = {
    "two_point": "power law through two base points (Kuzmenko & Sabadash 2014, eq. 2.1)",
    "loglog": "linear least squares on ln Q = ln C + n ln u",
    "least_squares": "nonlinear least squares on Q (scipy curve_fit, started from loglog)",
}


@dataclass(frozen=True)
class PowerLawFit:
    """A fitted power law ``Q = C u^n``.

    Attributes
    ----------
    coefficient : float
        ``C``. [N/mm^n]
    exponent : float
        ``n``. [-]
    r_squared : float
        Coefficient of determination on ``Q``: ``1 - sum(res^2)/sum((Q - mean Q)^2)``. [-]
    r_squared_log : float
        The same on ``ln Q``. [-]
    residuals : ndarray
        ``Q_measured - C u^n`` for every point. [N]
    method : str
        Name of the method (a key of :data:`METHODS`).
    """

    coefficient: float
    exponent: float
    r_squared: float
    r_squared_log: float
    residuals: np.ndarray
    method: str

    def load(self, displacement: Any) -> Any:
        """Load ``C u^n`` at a displacement ``u`` [mm]; returns [N]."""
        u = np.asanyarray(displacement, dtype=float)
        return self.coefficient * u**self.exponent


class Measurements(NamedTuple):
    """Load-displacement pairs read by :func:`read_measurements`.

    Attributes
    ----------
    load : ndarray
        Loads. [N]
    displacement : ndarray
        Displacements. [mm]
    rows : ndarray of int
        Line number of each pair in the file (the header is row 1).
    """

    load: np.ndarray
    displacement: np.ndarray
    rows: np.ndarray


def fit_two_point(load: Any, displacement: Any, base_points: Any = None) -> PowerLawFit:
    """Fit ``Q = C u^n`` through two base points (Kuzmenko & Sabadash 2014, eq. 2.1).

    ``n = lg(Q_1/Q_2) / lg(u_1/u_2)``, ``C = Q_1 / u_1^n``. The paper reads its base points
    (200 kgf, 0.8 mm) and (1000 kgf, 1.67 mm) off the averaged curve.

    Parameters
    ----------
    load : array_like
        Measured loads ``Q > 0`` (at least two). [N]
    displacement : array_like
        Measured displacements ``u > 0``, same length. [mm]
    base_points : ((Q1, u1), (Q2, u2)), optional
        The two points the law passes through [N, mm]; default: the rows of lowest and highest
        load.

    Returns
    -------
    PowerLawFit
        ``C`` [N/mm^n], ``n`` [-], R^2 and residuals over all points.

    Examples
    --------
    >>> fit = fit_two_point([1.0, 8.0], [1.0, 4.0])
    >>> round(fit.exponent, 12), round(fit.coefficient, 12)
    (1.5, 1.0)
    """
    q, u = _pairs(load, displacement)
    if base_points is None:
        i1, i2 = int(np.argmin(q)), int(np.argmax(q))
        (q1, u1), (q2, u2) = (q[i1], u[i1]), (q[i2], u[i2])
    else:
        pts = np.asarray(base_points, dtype=float)
        if pts.shape != (2, 2):
            raise InputError("base_points", "must be two (load, displacement) pairs")
        if not np.all(np.isfinite(pts)) or np.any(pts <= 0):
            raise InputError("base_points", "loads and displacements must be finite and > 0")
        (q1, u1), (q2, u2) = pts
    if u1 == u2:
        raise InputError(
            "base_points",
            f"the two base points have the same displacement ({u1:g} mm); "
            "the exponent n = lg(Q1/Q2)/lg(u1/u2) is undefined",
        )
    n = (math.log(q1) - math.log(q2)) / (math.log(u1) - math.log(u2))  # no under/overflow
    with np.errstate(over="ignore", under="ignore"):
        c = float(q1 / np.float64(u1) ** n)  # exact through the first base point
        if not (math.isfinite(c) and c > 0):  # extreme data: the same C through logarithms
            c = float(np.exp(math.log(q1) - n * math.log(u1)))
    return _result(q, u, c, n, "two_point")


def fit_loglog(load: Any, displacement: Any) -> PowerLawFit:
    """Fit ``Q = C u^n`` by linear least squares of ``ln Q`` on ``ln u``.

    Parameters
    ----------
    load : array_like
        Measured loads ``Q > 0`` (at least two). [N]
    displacement : array_like
        Measured displacements ``u > 0`` (at least two different). [mm]

    Returns
    -------
    PowerLawFit
        ``C`` [N/mm^n], ``n`` [-], R^2 and residuals.
    """
    q, u = _pairs(load, displacement)
    lu, lq = np.log(u), np.log(q)
    lu_mean = lu.mean()
    dx = lu - lu_mean
    n = float(dx @ (lq - lq.mean()) / (dx @ dx))
    c = float(np.exp(lq.mean() - n * lu_mean))
    return _result(q, u, c, n, "loglog")


def fit_least_squares(load: Any, displacement: Any) -> PowerLawFit:
    """Fit ``Q = C u^n`` by nonlinear least squares on ``Q`` (``scipy.optimize.curve_fit``).

    Started from :func:`fit_loglog`; solved in the scaled form ``Q/Q_ref = a (u/u_ref)^n`` with the
    geometric means as references, so that the problem is well conditioned in any units.

    Parameters
    ----------
    load : array_like
        Measured loads ``Q > 0`` (at least two). [N]
    displacement : array_like
        Measured displacements ``u > 0`` (at least two different). [mm]

    Returns
    -------
    PowerLawFit
        ``C`` [N/mm^n], ``n`` [-], R^2 and residuals.

    Raises
    ------
    ConvergenceError
        When ``curve_fit`` does not converge.
    """
    from scipy.optimize import OptimizeWarning, curve_fit

    q, u = _pairs(load, displacement)
    start = fit_loglog(q, u)
    q_ref = float(np.exp(np.log(q).mean()))
    u_ref = float(np.exp(np.log(u).mean()))
    us, qs = u / u_ref, q / q_ref
    a0 = start.coefficient * u_ref**start.exponent / q_ref

    def model(x: np.ndarray, a: float, n: float) -> np.ndarray:
        return a * x**n

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", OptimizeWarning)
            popt, _ = curve_fit(model, us, qs, p0=(a0, start.exponent), maxfev=2000)
    except RuntimeError as exc:  # curve_fit's "Optimal parameters not found"
        raise ConvergenceError(
            "curve_fit", 2000, float("nan"), {"load": q, "displacement": u}
        ) from exc
    a, n = float(popt[0]), float(popt[1])
    c = q_ref * a / u_ref**n
    return _result(q, u, c, n, "least_squares")


def fit_power_law(
    load: Any, displacement: Any, method: str = "two_point", **kwargs: Any
) -> PowerLawFit:
    """Fit ``Q = C u^n`` with the named method (see :data:`METHODS`).

    Parameters
    ----------
    load : array_like
        Measured loads. [N]
    displacement : array_like
        Measured displacements. [mm]
    method : {'two_point', 'loglog', 'least_squares'}, default 'two_point'
        The paper's two-point method, log-log least squares or least squares on ``Q``.
    **kwargs
        Passed to the method (``base_points`` for ``two_point``).

    Returns
    -------
    PowerLawFit
    """
    functions = {
        "two_point": fit_two_point,
        "loglog": fit_loglog,
        "least_squares": fit_least_squares,
    }
    if method not in functions:
        raise InputError("method", f"unknown method {method!r}; valid: {', '.join(functions)}")
    result: PowerLawFit = functions[method](load, displacement, **kwargs)
    return result


def normalized_distribution(displacement: Any, exponent: Any, u_max: Any = None) -> Any:
    """Normalised pressure (load) distribution ``sigma_bar = (u/u_max)^(n-1)``.

    Kuzmenko & Sabadash (2014), eqs. 1.12-1.13 and 2.4.

    Parameters
    ----------
    displacement : float or array_like
        Displacement ``u >= 0``. [mm]
    exponent : float or array_like
        Fitted exponent ``n``. [-]
    u_max : float or array_like, optional
        Reference (largest) displacement; default: the largest of ``displacement``. [mm]

    Returns
    -------
    float or ndarray
        ``sigma_bar``. [-]

    Examples
    --------
    >>> round(normalized_distribution(0.8, 2.19, 1.67), 4)
    0.4165
    """
    u = np.asanyarray(displacement, dtype=float)
    n = np.asanyarray(exponent, dtype=float)
    if not np.all(np.isfinite(u)) or np.any(u < 0):
        raise InputError("displacement", "must be finite and >= 0 mm")
    if not np.all(np.isfinite(n)):
        raise InputError("exponent", "must be a finite number")
    top = np.max(u) if u_max is None else np.asanyarray(u_max, dtype=float)
    if not np.all(np.isfinite(top)) or np.any(top <= 0):
        raise InputError("u_max", "must be finite and > 0 mm")
    out = (u / top) ** (n - 1.0)
    return float(out) if np.ndim(out) == 0 else out


def read_measurements(
    path: str | os.PathLike[str],
    *,
    load_unit: str = "N",
    displacement_unit: str = "mm",
    load_column: str = "load",
    displacement_column: str = "displacement",
) -> Measurements:
    """Read load-displacement pairs from a CSV file with a header row.

    The header must name the columns ``load`` and ``displacement`` (case-insensitive; other
    columns are ignored). Blank lines are skipped. Every error names the file, the row (the line
    number in the file; the header is row 1) and the column.

    Parameters
    ----------
    path : str or path-like
        The CSV file.
    load_unit : str, default 'N'
        Unit of the load column (``N``, ``kN``, ``kgf``, ``lbf``).
    displacement_unit : str, default 'mm'
        Unit of the displacement column (``mm``, ``um``, ``in``, ``m``).
    load_column, displacement_column : str
        Header names of the two columns.

    Returns
    -------
    Measurements
        ``load`` [N], ``displacement`` [mm] and the row number of each pair.

    Raises
    ------
    InputError
        Unreadable or empty file, missing column, missing or non-numeric value, a value that is
        not finite and > 0, fewer than two pairs, or fewer than two different displacements.
    """
    name = os.fspath(path)
    load_factor = parse_quantity("1" + load_unit, "force", parameter="load_unit")
    disp_factor = parse_quantity("1" + displacement_unit, "length", parameter="displacement_unit")
    try:
        with open(path, encoding="utf-8-sig", newline="") as handle:
            text = handle.read()
    except (OSError, UnicodeDecodeError) as exc:
        reason = getattr(exc, "strerror", None) or str(exc)
        raise InputError(name, f"cannot read the file: {reason}") from exc

    reader = csv.reader(io.StringIO(text))
    header: list[str] | None = None
    header_row = 0
    positions: dict[str, int] = {}
    columns = (load_column, displacement_column)
    values: list[tuple[float, float]] = []
    rows: list[int] = []
    try:
        for record in reader:
            row = reader.line_num
            if not record or all(not cell.strip() for cell in record):
                continue
            if header is None:
                header, header_row = [cell.strip().lower() for cell in record], row
                for col in columns:
                    if col.lower() not in header:
                        raise InputError(
                            f"{name} row {row}, column {col!r}",
                            separator_slip(record)
                            or f"the header has no column {col!r} (found: {', '.join(header)})",
                        )
                    positions[col] = header.index(col.lower())
                continue
            pair = tuple(_cell(record, positions[col], name, row, col) for col in columns)
            values.append((pair[0], pair[1]))
            rows.append(row)
    except csv.Error as exc:
        raise InputError(f"{name} row {reader.line_num}", f"malformed CSV: {exc}") from exc

    if header is None:
        raise InputError(
            f"{name} row 1",
            f"the file is empty; expected a header naming the columns {load_column!r} and "
            f"{displacement_column!r}",
        )
    if len(values) < 2:
        raise InputError(
            f"{name} row {rows[-1] + 1 if rows else header_row + 1}, column {load_column!r}",
            f"needs at least two load-displacement rows to fit a power law (found {len(values)})",
        )
    data = np.array(values)
    u = data[:, 1]
    if np.all(u == u[0]):
        raise InputError(
            f"{name} rows {rows[0]}-{rows[-1]}, column {displacement_column!r}",
            f"every displacement is {u[0]:g}; a power law needs at least two different "
            "displacements",
        )
    return Measurements(data[:, 0] * load_factor, u * disp_factor, np.array(rows))


# --------------------------------------------------------------------------- internals


def _cell(record: list[str], position: int, name: str, row: int, column: str) -> float:
    where = f"{name} row {row}, column {column!r}"
    if position >= len(record) or not record[position].strip():
        raise InputError(where, "missing value")
    text = record[position].strip()
    try:
        value = float(text)
    except ValueError:
        raise InputError(where, f"cannot read {text!r} as a number") from None
    if not math.isfinite(value) or value <= 0:
        raise InputError(where, f"must be a finite number > 0 (got {text!r})")
    return value


def _pairs(load: Any, displacement: Any) -> tuple[np.ndarray, np.ndarray]:
    q = np.asarray(load, dtype=float).ravel()
    u = np.asarray(displacement, dtype=float).ravel()
    if q.size != u.size:
        raise InputError("displacement", f"has {u.size} values but load has {q.size}")
    if q.size < 2:
        raise InputError("load", f"needs at least two points (got {q.size})")
    for label, arr, unit in (("load", q, "N"), ("displacement", u, "mm")):
        if not np.all(np.isfinite(arr)) or np.any(arr <= 0):
            raise InputError(label, f"every value must be finite and > 0 {unit}")
    if np.all(u == u[0]):
        raise InputError("displacement", "needs at least two different values; the fit is singular")
    return q, u


def _r_squared(observed: np.ndarray, fitted: np.ndarray) -> float:
    ss_res = float(np.sum((observed - fitted) ** 2))
    ss_tot = float(np.sum((observed - observed.mean()) ** 2))
    if ss_tot == 0.0:
        return 1.0 if ss_res == 0.0 else 0.0
    return 1.0 - ss_res / ss_tot


def _result(q: np.ndarray, u: np.ndarray, c: float, n: float, method: str) -> PowerLawFit:
    fitted = c * u**n
    return PowerLawFit(
        coefficient=float(c),
        exponent=float(n),
        r_squared=_r_squared(q, fitted),
        r_squared_log=_r_squared(np.log(q), np.log(fitted)),
        residuals=q - fitted,
        method=method,
    )
