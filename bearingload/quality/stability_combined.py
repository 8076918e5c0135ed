"""Numerical stability of the combined-load solver on extreme cases, one row per family.

The families walk the 3-D ring equilibrium of :func:`bearingload.models.combined.solve_combined`
(radial and axial load, moments, an imposed misalignment; Hertz ``K(alpha)``) through its range:
preload, clearance up to the groove limit ``G_r -> 2A``, axial loads and moments of both signs,
a misalignment of exactly 0 and nonzero, load ratios ``F_a/F_r`` 1e-9 to 1e9, 3 to 1000 balls.
A deep-groove bearing of the 6305 size is used throughout (``D_w = 11.5``, ``d_m = 43.5`` mm,
``f_i = 0.52``, ``f_o = 0.53``: ``A = 0.575`` mm), 7 balls unless the family changes ``z`` (then
``d_m`` grows so that the balls fit). Per family:

* ``cases``; ``refused``: cases refused with an :class:`~bearingload.errors.InputError`, counted
  with their reason (``refusal_reasons``); ``failures``: any other exception (a
  ``ConvergenceError`` included), with theirs (``failure_reasons``);
* ``nan``: solved cases with a NaN or infinity in any output; ``warnings_raised``;
* ``residual_*``: the largest relative residual of each component of the ring's equilibrium,
  recomputed here from the returned ball loads ``Q_j``, contact angles ``alpha_j`` and ball angles
  ``phi_j`` (not the solver's own figure): ``sum Q_j cos(alpha_j) cos(phi_j) - F_r`` (radial),
  ``sum Q_j cos(alpha_j) sin(phi_j)`` (across the load line), ``sum Q_j sin(alpha_j) - F_a``
  (axial), ``R sum Q_j sin(alpha_j) cos(phi_j) - M`` (moment, ``M`` the applied one, or the one
  reported as needed under an imposed misalignment) and ``R sum Q_j sin(alpha_j) sin(phi_j) - M_c``
  (moment about the load line), ``R = d_m/2 + (f_i - 1/2) D_w cos(alpha_0)`` the radius of the
  inner groove centres (ISO/TS 16281; the model's ``tilt_radius``). Each is relative to the
  larger of the applied component and the sum of the magnitudes of the ball terms (what a
  floating-point sum can resolve): a component 1e-9 of the load is measured against itself;
* ``batch_dependence``: the largest relative difference between a case solved alone and within
  its series' array (``Q_max``, ``x``, ``y``, axial, both tilts, the moment, the loaded balls);
  infinite if a case solved alone fails in the array;
* ``max_iterations``; ``check`` / ``check_value`` / ``check_limit``: the family's own test.

:func:`run` with ``size="quick"`` is the reduced grid of the test suite; ``"full"`` that of
``make bench``.
"""

from __future__ import annotations

import math
import re
import warnings
from collections import Counter
from collections.abc import Callable
from typing import Any

import numpy as np

from bearingload.errors import ConvergenceError, InputError
from bearingload.lazy_dataclass import dataclass

#: The bearing of every family: a deep-groove ball bearing of the 6305 size. [mm], [-]
GEOMETRY = {"ball_diameter": 11.5, "pitch_diameter": 43.5, "f_i": 0.52, "f_o": 0.53}
BALLS = 7
#: (f_i + f_o - 1) D_w: the clearance must stay below 2 A. [mm]
GROOVE_A = (GEOMETRY["f_i"] + GEOMETRY["f_o"] - 1.0) * GEOMETRY["ball_diameter"]
#: The compared outputs of batch dependence.
COMPARED = ("q_max", "x", "y", "axial", "tilt", "tilt_cross", "moment", "loaded_balls")
COMPONENTS = ("radial", "cross", "axial", "moment", "moment_cross")


@dataclass(frozen=True)
class Series:
    """Cases of one call of the solver: ``balls``, the family's ``parameter`` per case and the
    keyword arguments of :func:`~bearingload.models.combined.solve_combined` (arrays of the
    parameter's length; ``misalignment`` imposed when present)."""

    parameter: np.ndarray
    balls: int
    inputs: dict[str, np.ndarray]


@dataclass(frozen=True)
class Family:
    """A family: its name, parameter, series builder and own check."""

    name: str
    parameter: str
    build: Callable[[str], list[Series]]
    check: Callable[[list[Series], list[list[Any]]], tuple[str, float, float]] | None = None


def _series(param: Any, balls: int = BALLS, **kw: Any) -> Series:
    p = np.asarray(param, dtype=float)
    base: dict[str, Any] = {"radial_load": 1000.0, "axial_load": 0.0, "clearance": 0.01}
    base.update(GEOMETRY)
    base.update(kw)
    return Series(p, balls, {k: np.broadcast_to(np.asarray(v, float), p.shape).copy()
                             for k, v in base.items()})  # fmt: skip


def _steps(size: str, quick: Any, full: Any) -> Any:
    return quick if size == "quick" else full


# --------------------------------------------------------------------------- residuals


def moment_radius(result: Any, inputs: dict[str, np.ndarray]) -> np.ndarray:
    """R = d_m/2 + (f_i - 1/2) D_w cos(alpha_0), the arm of the tilt (ISO/TS 16281). [mm]"""
    cos0 = np.cos(np.deg2rad(np.asarray(result.free_contact_angle, float)))
    return inputs["pitch_diameter"] / 2.0 + (inputs["f_i"] - 0.5) * inputs["ball_diameter"] * cos0


def component_residuals(
    result: Any, inputs: dict[str, np.ndarray], *, absolute: bool = False
) -> np.ndarray:
    """Relative residual of each equilibrium component per case, shape (n, 5), in the order of
    :data:`COMPONENTS`, from the returned ball loads and angles (module notes); with
    ``absolute`` the misses themselves [N, N mm]. [-]"""
    q = np.asarray(result.ball_loads, float).reshape(-1, result.balls)
    alpha = np.deg2rad(np.asarray(result.contact_angles, float)).reshape(q.shape)
    phi = np.deg2rad(np.asarray(result.ball_angles, float)).reshape(q.shape)
    arm = np.reshape(moment_radius(result, inputs), (-1, 1))
    axial = q * np.sin(alpha)
    radial = q * np.cos(alpha)
    terms = (
        radial * np.cos(phi),
        radial * np.sin(phi),
        axial,
        arm * axial * np.cos(phi),
        arm * axial * np.sin(phi),
    )
    n = q.shape[0]
    applied = (
        np.reshape(result.load, n),
        np.zeros(n),
        np.reshape(result.axial_load, n),
        np.reshape(result.moment, n),
        np.broadcast_to(inputs.get("moment_cross", np.zeros(n)), n),
    )
    out = np.empty((n, len(COMPONENTS)))
    with np.errstate(all="ignore"):
        for i, (t, f) in enumerate(zip(terms, applied, strict=True)):
            scale = np.maximum(np.abs(f), np.abs(t).sum(-1))
            miss = np.abs(t.sum(-1) - f)
            if absolute:
                out[:, i] = miss
            else:
                out[:, i] = np.where(scale > 0, miss / np.where(scale > 0, scale, 1.0), miss)
    return out


def overall_residual(result: Any, inputs: dict[str, np.ndarray]) -> np.ndarray:
    """Largest miss of the five components per case relative to one scale, the largest of
    ``F_r``, ``|F_a|``, ``|M|/R``, ``|M_c|/R`` and ``sum Q_j`` (the radial families' measure).
    [-]"""
    q = np.asarray(result.ball_loads, float).reshape(-1, result.balls)
    n = q.shape[0]
    arm = np.reshape(moment_radius(result, inputs), n)
    miss = component_residuals(result, inputs, absolute=True)
    miss[:, 3:] /= arm[:, None]
    scale = np.max(
        [np.reshape(result.load, n), np.abs(np.reshape(result.axial_load, n)),
         np.abs(np.reshape(result.moment, n)) / arm,
         np.abs(np.broadcast_to(inputs.get("moment_cross", np.zeros(n)), n)) / arm, q.sum(-1)],
        axis=0,
    )  # fmt: skip
    return np.max(miss, axis=-1) / scale


def _outputs(result: Any) -> np.ndarray:
    """The compared outputs per case, shape (n, len(COMPARED))."""
    return np.stack([np.ravel(getattr(result, k)).astype(float) for k in COMPARED], axis=-1)


def _finite(result: Any) -> np.ndarray:
    keys = ("x", "y", "axial", "tilt", "tilt_cross", "moment")
    ok = np.all([np.isfinite(np.ravel(getattr(result, k))) for k in keys], axis=0)
    for k in ("ball_loads", "contact_angles", "ball_approaches"):
        arr = np.asarray(getattr(result, k), float).reshape(ok.size, -1)
        ok &= np.all(np.isfinite(arr), axis=-1)
    return np.asarray(ok)


# --------------------------------------------------------------------------- running


def _solve(series: Series, index: Any) -> Any:
    from bearingload.models.combined import solve_combined

    kw = {k: v[index] for k, v in series.inputs.items()}
    return solve_combined(series.balls, **kw)


def _reason(exc: Exception) -> str:
    """The kind of a refusal or failure: the message without the case it names (the ball's
    number and the inputs), so that refusals of one kind count together."""
    if isinstance(exc, InputError):
        text = re.sub(r" \(balls = [^()]*\)$", "", str(exc))
        return re.sub(r"\bball \d+ ", "a ball ", text)
    if isinstance(exc, ConvergenceError):
        return f"ConvergenceError (residual {exc.residual:.2g})"
    return f"{type(exc).__name__}: {str(exc)[:70]}"


def _run_series(series: Series, row: dict[str, Any], reasons: dict[str, Counter[str]]) -> list[Any]:
    """Solve every case alone, then the ones solved alone in one array; fill the row's counts
    and residuals. Returns the per-case results alone (None where refused or failed)."""
    n = series.parameter.size
    alone: list[Any] = []
    for i in range(n):
        try:
            alone.append(_solve(series, slice(i, i + 1)))
        except InputError as exc:
            row["refused"] += 1
            reasons["refused"][_reason(exc)] += 1
            alone.append(None)
        except Exception as exc:  # noqa: BLE001 - every other exception is a failure to count
            row["failures"] += 1
            reasons["failures"][_reason(exc)] += 1
            alone.append(None)
    row["cases"] += n
    solved = [i for i in range(n) if alone[i] is not None]
    for i in solved:
        r, one = alone[i], {k: v[i : i + 1] for k, v in series.inputs.items()}
        if not _finite(r).all():
            row["nan"] += 1
            continue
        res = component_residuals(r, one)[0]
        row["max_residual"] = max(row["max_residual"], float(overall_residual(r, one)[0]))
        for name, value in zip(COMPONENTS, res, strict=True):
            row[f"residual_{name}"] = max(row[f"residual_{name}"], float(value))
        row["max_iterations"] = max(row["max_iterations"], int(np.max(r.iterations)))
    if len(solved) > 1:
        row["batch_dependence"] = max(row["batch_dependence"], _batch(series, solved, alone))
    return alone


def _batch(series: Series, solved: list[int], alone: list[Any]) -> float:
    """Largest relative difference of the solved cases between alone and in one array."""
    try:
        together = _outputs(_solve(series, np.array(solved)))
    except Exception:  # noqa: BLE001 - a case solved alone that fails in an array
        return math.inf
    single = np.concatenate([_outputs(alone[i]) for i in solved])
    scale = np.maximum(np.abs(together), np.abs(single))
    with np.errstate(all="ignore"):
        rel = np.where(scale > 0, np.abs(together - single) / scale, 0.0)
    rel = np.where(np.isnan(together) & np.isnan(single), 0.0, rel)
    return float(np.nanmax(np.where(np.isnan(rel), math.inf, rel)))


def _summary(counter: Counter[str]) -> str:
    return "; ".join(f"{text} (x{k})" for text, k in counter.most_common()) or "-"


def _run_family(family: Family, size: str) -> dict[str, Any]:
    row: dict[str, Any] = {"cases": 0, "refused": 0, "failures": 0, "nan": 0, "max_residual": 0.0}
    row |= {f"residual_{c}": 0.0 for c in COMPONENTS}
    row |= {"batch_dependence": 0.0, "max_iterations": 0, "warnings_raised": 0}
    reasons: dict[str, Counter[str]] = {"refused": Counter(), "failures": Counter()}
    all_series = family.build(size)
    results = []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        for series in all_series:
            results.append(_run_series(series, row, reasons))
    row["warnings_raised"] = len(caught)
    row["refusal_reasons"] = _summary(reasons["refused"])
    row["failure_reasons"] = _summary(reasons["failures"])
    check, value, limit = ("-", 0.0, 0.0)
    if family.check is not None:
        check, value, limit = family.check(all_series, results)
    return {"family": family.name, "parameter": family.parameter, **row,
            "check": check, "check_value": value, "check_limit": limit}  # fmt: skip


# --------------------------------------------------------------------------- families


def _preload(size: str) -> list[Series]:
    g = np.linspace(-0.03, 0.0, _steps(size, 7, 31))
    g = np.union1d(g, [-1e-6, -1e-9])
    return [
        _series(g, clearance=g),
        _series(g, clearance=g, axial_load=500.0),
        _series(g, clearance=g, radial_load=0.0, axial_load=1000.0),
        _series(g, clearance=g, axial_load=300.0, moment=2.0e4),
    ]


def _groove_limit(size: str) -> list[Series]:
    """G_r from 0 to 2A (1 - 1e-12), then 2A and beyond (refused: the ball would leave)."""
    p = np.arange(1.0, 12.01, _steps(size, 2.0, 0.5))
    g = np.concatenate(
        [np.linspace(0.0, 1.8 * GROOVE_A, _steps(size, 4, 19)), 2 * GROOVE_A * (1 - 10.0**-p)]
    )
    g = np.concatenate([np.unique(g), [2 * GROOVE_A, 2.2 * GROOVE_A]])
    return [
        _series(g, clearance=g),
        _series(g, clearance=g, axial_load=500.0),
        _series(g, clearance=g, radial_load=0.0, axial_load=1000.0),
    ]


def _both_ways(size: str, low: float, high: float) -> np.ndarray:
    mag = 10.0 ** np.arange(low, high + 0.01, _steps(size, 2.0, 0.5))
    return np.concatenate([-mag[::-1], [0.0], mag])


def _axial(size: str) -> list[Series]:
    fa = _both_ways(size, -3.0, 4.0)  # [N]
    return [_series(fa, axial_load=fa, clearance=g) for g in (0.01, 0.0, -0.01)]


def _moment(size: str) -> list[Series]:
    m = _both_ways(size, 0.0, 5.0)  # [N mm]
    return [
        _series(m, axial_load=300.0, moment=m),
        _series(m, axial_load=300.0, moment=0.0 * m, moment_cross=m),
        _series(m, axial_load=0.0, moment=m, clearance=-0.01),
    ]


def _misalignment(size: str) -> list[Series]:
    t = _both_ways(size, -9.0, -1.0)  # [°], with exactly 0
    return [
        _series(t, axial_load=500.0, misalignment=t),
        _series(t, axial_load=0.0, misalignment=t),
        _series(t, axial_load=500.0, misalignment=t, clearance=-0.01),
    ]


def _misalignment_check(series: list[Series], results: list[list[Any]]) -> tuple[str, float, float]:
    worst = 0.0
    for s, res in zip(series, results, strict=True):
        for i, r in enumerate(res):
            if r is not None:
                worst = max(worst, abs(float(r.tilt[0]) - float(s.inputs["misalignment"][i])))
    return "largest |tilt - imposed misalignment| [deg]", worst, 1e-12


def _load_ratio(size: str) -> list[Series]:
    r = 10.0 ** np.arange(-9.0, 9.01, _steps(size, 2.0, 0.5))
    fr, fa = 1000.0 * np.minimum(1.0, 1.0 / r), 1000.0 * np.minimum(r, 1.0)
    out = [_series(r, radial_load=fr, axial_load=fa, clearance=g) for g in (0.01, 0.0, -0.01)]
    out.append(_series(r, radial_load=fr, axial_load=-fa))
    return out


def _ball_count(size: str) -> list[Series]:
    zs = np.unique(np.round(np.logspace(np.log10(3), 3, _steps(size, 6, 25))).astype(int))
    out = []
    for z in zs:
        dm = max(GEOMETRY["pitch_diameter"], 1.2 * z * GEOMETRY["ball_diameter"] / math.pi)
        fa = np.array([0.0, 500.0, -500.0])
        out.append(_series(np.full(3, float(z)), int(z), axial_load=fa, pitch_diameter=dm))
        out.append(_series(np.full(2, float(z)), int(z), axial_load=fa[:2], clearance=-0.01,
                           pitch_diameter=dm))  # fmt: skip
    return out


def _angle_check(series: list[Series], results: list[list[Any]]) -> tuple[str, float, float]:
    past = 0
    for res in results:
        for r in res:
            if r is not None:
                past += int(np.count_nonzero(np.abs(r.contact_angles) >= 90.0))
    return "loaded balls with a contact angle of 90 deg or more", float(past), 0.0


FAMILIES: tuple[Family, ...] = (
    Family("combined_preload", "G_r -30 .. 0 um", _preload, _angle_check),
    Family("combined_groove_limit", "G_r 0 .. 2A (1 - 1e-12), 2A", _groove_limit, _angle_check),
    Family("combined_axial_both_ways", "F_a -1e4 .. 1e4 N", _axial, _angle_check),
    Family("combined_moment_both_ways", "M, M_c -1e5 .. 1e5 N mm", _moment, _angle_check),
    Family("combined_misalignment", "tilt -0.1 .. 0.1 deg, 0", _misalignment, _misalignment_check),
    Family("combined_load_ratio", "F_a/F_r 1e-9 .. 1e9", _load_ratio, _angle_check),
    Family("combined_ball_count", "z 3 .. 1000", _ball_count, _angle_check),
)


def family_names() -> list[str]:
    """Names of the combined-load families, in report order."""
    return [f.name for f in FAMILIES]


def run(size: str = "quick", names: list[str] | None = None) -> list[dict[str, Any]]:
    """One row per combined-load family (module notes); ``size`` ``"quick"`` or ``"full"``."""
    from bearingload.quality.stability import check_selection

    check_selection(size, names, family_names())
    return [_run_family(f, size) for f in FAMILIES if not names or f.name in names]


#: Title and columns of the report (:mod:`bearingload.reports.stability`).
TITLE = "Numerical stability of the combined-load solver"
KEYS = (
    "family", "parameter", "cases", "refused", "failures", "nan", "max_residual",
    *(f"residual_{c}" for c in
    COMPONENTS), "batch_dependence", "max_iterations", "warnings_raised", "check_value",
    "check_limit", "check", "refusal_reasons", "failure_reasons",
)  # fmt: skip
NOTES = (
    "max residual: the largest miss of the five components over one scale, the largest of F_r, "
    "|F_a|, |M|/R, |M_c|/R and sum Q_j (the measure of the radial families).",
    "residual F_r, F_y, F_a, M, M_c: |sum of the ball terms - applied| / max(|applied|, sum of "
    "|ball terms|) per component, recomputed from the returned Q_j, alpha_j, phi_j; M is the "
    "applied moment or, under an imposed misalignment, the one reported as needed.",
    "refused: InputError (the reasons listed); failures: any other exception, ConvergenceError "
    "included. batch dep.: largest relative difference between a case alone and in its array.",
    "Bearing: D_w 11.5 mm, d_m 43.5 mm (more where z needs it), f_i 0.52, f_o 0.53 (A = 0.575 "
    "mm), z = 7 unless varied, Hertz K(alpha); F_r = 1000 N, G_r = 10 um unless varied.",
)
