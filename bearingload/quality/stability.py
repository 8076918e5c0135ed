"""Numerical stability on stiff and extreme cases: a grid of families, each summarised in one row.

Each family walks one parameter (the load ratio ``F/(K e^1.5)``, the clearance, the number of
balls, the cage angle ...) through its extreme range in one or more series. Per family:

* ``cases``: cases run; ``refused``: cases refused up front with an ``InputError`` (allowed only
  where the family probes the edge of the domain); ``failures``: any other exception;
* ``nan``: cases with a NaN or infinity in any output; ``warnings_raised``: numpy/Python warnings;
* ``max_residual``: the largest equilibrium residual, recomputed here from the returned ball loads
  and angles (not the solver's own number): ``|sum_i Q_i (cos phi_i, sin phi_i) - (F_r, 0)|``
  relative to ``max(F_r, sum_i Q_i)`` (under preload the ball forces dwarf the load and cancel;
  no floating-point sum resolves less). The continuum model's residual is that of its forward
  load at the returned displacement; Hertz's that of the ellipticity equation evaluated with scipy;
* ``max_jump``: continuity along the family's parameter ``t`` (``log10`` of it, or the value
  itself for a parameter that crosses zero): the largest ``max(|dk|/k, |dd|/|d|)/|dt|`` between
  neighbouring cases, ``k = Q_max/F_r`` and ``d = (x, y)`` the ring displacement. A smooth family
  shows a number of order 1 however fine its steps; a jump shows as the size of the jump divided
  by the step (1e10 for a jump at a step of 1e-10);
* ``batch_dependence``: the largest relative difference between a case solved alone and in its
  family's batch (``Q_max``, ``x``, ``y``, stiffness, loaded balls); must be 0 up to rounding;
* ``max_iterations``; ``check`` / ``check_value`` / ``check_limit``: the family's own test (the
  displacement against an independent formula, memory per case, ...).

The families: clearance through zero and huge, load ratios, ball counts, preload, one loaded ball,
cage angles at load-zone edges, rollers and m = 1, the continuum model and Hertz contact, and the
hard corners (heavy preload against an independent formula, stiffness extremes, preload with
m = 3, memory of large batches, cage angles near symmetry, batch independence, the load zone of
many balls, bad inputs). The combined-load solver has its own families
(:mod:`bearingload.quality.stability_combined`). :func:`run` with ``size="quick"`` is the reduced grid of the test suite; ``"full"`` the
grid of ``make bench``.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import field
from typing import Any

import numpy as np

from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass

SIZES = ("quick", "full")


@dataclass(frozen=True)
class Series:
    """Cases along one parameter: ``parameter`` (ascending), ``log`` scale or linear, and the
    solver's inputs (arrays of the same length)."""

    parameter: np.ndarray
    log: bool
    inputs: dict[str, np.ndarray]


@dataclass
class Outcome:
    """Per-case results of one series (NaN where a case failed)."""

    k: np.ndarray
    d: np.ndarray  # (n, 2) displacement [mm]
    residual: np.ndarray
    iterations: np.ndarray
    compare: np.ndarray  # (n, c) quantities compared between batch and alone
    finite: np.ndarray
    refused: int = 0
    failures: int = 0
    result: Any = None


@dataclass
class Family:
    """A family: its name, parameter, series builder, solver kind, jump limit and own check."""

    name: str
    parameter: str
    build: Callable[[str], list[Series]]
    kind: str = "engine"  # engine | continuum | hertz
    may_refuse: bool = False
    check: Callable[[list[Series], list[Outcome], str], tuple[str, float, float]] | None = None
    jump_limit: float = 10.0
    extra: dict[str, Any] = field(default_factory=dict)


def _inputs(n: int, **kw: Any) -> dict[str, np.ndarray]:
    base = {"balls": 8, "load": 1.0, "stiffness": 1.0, "clearance": 0.0, "cage_angle": 0.0}
    base.update({"exponent": 1.5})
    base.update(kw)
    return {k: np.broadcast_to(np.asarray(v), (n,)).copy() for k, v in base.items()}


def _series(param: Any, log: bool, **kw: Any) -> Series:
    p = np.asarray(param, dtype=float)
    return Series(p, log, _inputs(p.size, **kw))


# --------------------------------------------------------------------------- solvers


def _engine_residual(result: Any) -> np.ndarray:
    out = np.empty(np.size(result.q_max))
    for i in range(out.size):
        one = result[i]
        q = one.ball_loads
        phi = np.deg2rad(one.ball_angles)
        fx, fy = float(q @ np.cos(phi)), float(q @ np.sin(phi))
        f = float(one.load)
        out[i] = math.hypot(fx - f, fy) / max(f, float(q.sum()))
    return out


def _engine(inp: dict[str, np.ndarray]) -> Outcome:
    from bearingload.models.equilibrium import solve

    r = solve(
        inp["balls"],
        inp["load"],
        inp["stiffness"],
        inp["clearance"],
        inp["cage_angle"],
        inp["exponent"],
    )
    d = np.stack([r.x, r.y], axis=-1)
    compare = np.stack([r.q_max, r.x, r.y, r.stiffness_radial, r.loaded_balls], axis=-1)
    arrays = (r.q_max, r.x, r.y, r.load_zone, r.stiffness_radial)
    finite = np.all([np.isfinite(a) for a in arrays], axis=0)
    finite &= np.all(np.isfinite(r.stiffness_matrix), axis=(-2, -1))
    with np.errstate(all="ignore"):
        residual = np.where(finite, _engine_residual(r), np.nan)
    return Outcome(
        np.asarray(r.k), d, residual, np.asarray(r.iterations), compare, finite, result=r
    )


def _continuum(inp: dict[str, np.ndarray]) -> Outcome:
    from bearingload.models.continuum import load_zone_integral, solve_continuum

    args = (inp["balls"], inp["load"], inp["stiffness"], inp["clearance"], inp["exponent"])
    r = solve_continuum(*args)
    # forward load z K delta_max^m J_r(eps) at the returned state; (x - e from the returned x
    # would cancel at huge clearance, so the returned delta_max and eps are used)
    jr = load_zone_integral(r.epsilon, inp["exponent"])
    forward = inp["balls"] * inp["stiffness"] * r.approach_max ** inp["exponent"] * jr
    residual = np.abs(forward / inp["load"] - 1.0)
    # and the returned x must be delta_max/(2 eps)
    residual = np.maximum(residual, np.abs(r.x * 2 * r.epsilon / r.approach_max - 1))
    d = np.stack([r.x, np.zeros_like(r.x)], axis=-1)
    compare = np.stack([r.q_max, r.x, r.stiffness_radial, r.epsilon], axis=-1)
    finite = np.all(np.isfinite(compare), axis=-1) & np.isfinite(r.load_zone)
    return Outcome(
        np.asarray(r.k), d, residual, np.asarray(r.iterations), compare, finite, result=r
    )


def _hertz(inp: dict[str, np.ndarray]) -> Outcome:
    from scipy.special import ellipe, ellipkm1

    from bearingload.contact.hertz import hertz_coefficients

    rx, ry = inp["rho_x"], inp["rho_y"]
    c = hertz_coefficients(rx, ry)
    kappa = np.asarray(c.kappa, dtype=float)
    p = 1.0 / kappa**2
    k_int, e_int = ellipkm1(p), ellipe(1.0 - p)
    given = np.abs(rx - ry) / (rx + ry)
    with np.errstate(all="ignore"):
        model = ((kappa**2 + 1) * e_int - 2 * k_int) / ((kappa**2 - 1) * e_int)
    # near the circle (kappa < 1.001) the check itself cancels; those cases are not checked
    residual = np.where(kappa < 1.001, 0.0, np.abs(model - given))
    values = np.stack([kappa, c.a_star, c.b_star, c.delta_star], axis=-1)
    finite = np.all(np.isfinite(values), axis=-1)
    d = np.stack([np.asarray(c.delta_star, dtype=float), np.zeros_like(kappa)], axis=-1)
    return Outcome(kappa, d, residual, np.zeros(kappa.size, np.int64), values, finite)


SOLVERS: dict[str, Callable[[dict[str, np.ndarray]], Outcome]] = {
    "engine": _engine,
    "continuum": _continuum,
    "hertz": _hertz,
}


def _one_by_one(solver: Callable[..., Outcome], series: Series) -> tuple[Outcome, list[Outcome]]:
    """Every case alone; a case that raises is counted (refused or failed) and left as NaN."""
    n = series.parameter.size
    alone: list[Outcome] = []
    refused = failures = 0
    for i in range(n):
        try:
            alone.append(solver({k: v[i : i + 1] for k, v in series.inputs.items()}))
        except InputError:
            refused += 1
            alone.append(_failed(1))
        except Exception:  # noqa: BLE001 - every other exception is a failure to count
            failures += 1
            alone.append(_failed(1))
    joined = Outcome(
        np.concatenate([o.k for o in alone]),
        np.concatenate([o.d for o in alone]),
        np.concatenate([o.residual for o in alone]),
        np.concatenate([o.iterations for o in alone]),
        np.concatenate([_pad(o.compare, alone) for o in alone]),
        np.concatenate([o.finite for o in alone]),
        refused,
        failures,
    )
    return joined, alone


def _pad(compare: np.ndarray, alone: list[Outcome]) -> np.ndarray:
    width = max(o.compare.shape[1] for o in alone)
    if compare.shape[1] == width:
        return compare
    return np.full((compare.shape[0], width), np.nan)


def _failed(n: int) -> Outcome:
    nan = np.full(n, np.nan)
    return Outcome(
        nan, np.full((n, 2), np.nan), nan, np.zeros(n, np.int64), np.full((n, 1), np.nan), nan > 0
    )


def _relative_difference(a: np.ndarray, b: np.ndarray) -> float:
    if a.shape != b.shape:
        return math.inf
    ok = np.isfinite(a) & np.isfinite(b)
    if not ok.any():
        return 0.0
    a, b = a[ok], b[ok]
    scale = np.maximum(np.abs(a), np.abs(b))
    with np.errstate(all="ignore"):
        rel = np.where(scale > 0, np.abs(a - b) / scale, 0.0)
    return float(rel.max())


def _jump(series: Series, out: Outcome) -> tuple[float, float]:
    """Largest relative change of k and d between neighbours per unit of the parameter, and the
    parameter value where it starts."""
    t = series.parameter
    t = np.log10(np.abs(t)) if series.log else t
    ok = out.finite
    worst, where = 0.0, float(series.parameter[0])
    for i in range(t.size - 1):
        if not (ok[i] and ok[i + 1]) or t[i + 1] == t[i]:
            continue
        k0, k1 = out.k[i], out.k[i + 1]
        dk = abs(k1 - k0) / max(abs(k0), abs(k1), 1e-300)
        d0, d1 = out.d[i], out.d[i + 1]
        dd = float(np.hypot(*(d1 - d0))) / max(float(np.hypot(*d0)), float(np.hypot(*d1)), 1e-300)
        rate = max(dk, dd) / abs(t[i + 1] - t[i])
        if rate > worst:
            worst, where = rate, float(series.parameter[i])
    return worst, where


def _run_family(family: Family, size: str) -> tuple[dict[str, Any], list[Outcome]]:
    solver = SOLVERS[family.kind]
    all_series = family.build(size)
    row: dict[str, Any] = {"cases": 0, "refused": 0, "failures": 0, "nan": 0, "warnings_raised": 0}
    residual, jump, jump_at, batch, iterations = 0.0, 0.0, 0.0, 0.0, 0
    outcomes = []
    for series in all_series:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                out = solver(series.inputs)
                single, _ = _one_by_one(solver, series)
                batch = max(batch, _relative_difference(out.compare, single.compare))
            except Exception:  # noqa: BLE001 - a batch that raises: count its cases one by one
                out, _ = _one_by_one(solver, series)
        row["warnings_raised"] += len(caught)
        n = series.parameter.size
        row["cases"] += n
        row["refused"] += out.refused
        row["failures"] += out.failures
        row["nan"] += int(n - out.refused - out.failures - np.count_nonzero(out.finite))
        good = out.finite & np.isfinite(out.residual)
        if good.any():
            residual = max(residual, float(np.max(out.residual[good])))
            iterations = max(iterations, int(np.max(out.iterations[good])))
        rate, where = _jump(series, out)
        if rate > jump:
            jump, jump_at = rate, where
        outcomes.append(out)
    row.update(
        max_residual=residual,
        max_jump=jump,
        jump_at=jump_at,
        batch_dependence=batch,
        max_iterations=iterations,
    )
    return row, outcomes


# --------------------------------------------------------------------------- families


def _steps(size: str, quick: float, full: float) -> Any:
    return quick if size == "quick" else full


def _clearance_to_zero(size: str) -> list[Series]:
    p = np.arange(14, 0, -_steps(size, 3, 1))
    e = np.concatenate([-(10.0 ** -p[::-1]), [0.0], 10.0**-p])
    e = np.sort(e)
    return [_series(e, False, clearance=2 * e, cage_angle=c) for c in (0.0, 22.5, 7.0)]


def _huge_clearance(size: str) -> list[Series]:
    e = 10.0 ** np.arange(0, 12.01, _steps(size, 2, 0.5))
    return [_series(e, True, clearance=2 * e, cage_angle=c) for c in (0.0, 22.5, 7.0)]


def _load_ratio(size: str) -> list[Series]:
    f = 10.0 ** np.arange(-12, 12.01, _steps(size, 2, 0.25))
    return [_series(f, True, load=f, clearance=2.0, cage_angle=c) for c in (0.0, 22.5, 7.0)]


def _ball_count(size: str) -> list[Series]:
    z = np.unique(np.round(np.logspace(0, 3, _steps(size, 12, 60))).astype(int))
    out = [_series(z, True, balls=z, clearance=g) for g in (0.0, 2.0, -2.0)]
    big = np.array([99_998, 99_999, 100_000])
    out.append(_series(big, True, balls=big, clearance=2.0))
    return out


def _preload(size: str) -> list[Series]:
    e = 10.0 ** np.arange(-3, 3.01, _steps(size, 1, 0.25))
    return [_series(e, True, balls=12, clearance=-2 * e, cage_angle=c) for c in (0.0, 15.0, 5.0)]


def _one_ball(size: str) -> list[Series]:
    z = np.unique(np.round(np.logspace(np.log10(3), 3, _steps(size, 8, 40))).astype(int))
    c = np.cos(2 * np.pi / z)
    e = 2.0 * c / (1.0 - c) + 1.0  # beyond e = s cos(gamma)/(1 - cos(gamma)): one ball carries
    return [_series(z, True, balls=z, clearance=2 * e)]


def _one_ball_check(
    series: list[Series], outs: list[Outcome], size: str
) -> tuple[str, float, float]:
    wrong = sum(int(np.count_nonzero(o.result.loaded_balls != 1)) for o in outs if o.result)
    return "cases with other than one loaded ball", float(wrong), 0.0


def _boundaries(z: int, e: float, steps: int) -> list[float]:
    """Cage angles (in (0, 360/z)) where a ball reaches the edge of the load zone, by bisection."""
    from bearingload.models.equilibrium import solve

    pitch = 360.0 / z
    grid = np.linspace(pitch * 1e-3, pitch * (1 - 1e-3), steps)
    n = solve(z, 1.0, 1.0, 2 * e, grid).loaded_balls
    found = []
    for i in np.nonzero(np.diff(n))[0]:
        lo, hi = float(grid[i]), float(grid[i + 1])
        n_lo = int(n[i])
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            if int(solve(z, 1.0, 1.0, 2 * e, mid).loaded_balls) == n_lo:
                lo = mid
            else:
                hi = mid
        found.append(hi)
    return found


def _cage_boundaries(size: str) -> list[Series]:
    offsets = 10.0 ** -np.arange(2, 13, _steps(size, 5, 1))
    delta = np.concatenate([-offsets, [0.0], offsets[::-1]])
    out = []
    for z, e in ((8, 1.0), (8, 0.1)) if size == "quick" else ((8, 1.0), (8, 0.1), (12, 3.0)):
        for angle in _boundaries(z, e, 24):
            out.append(_series(delta, False, balls=z, clearance=2 * e, cage_angle=angle + delta))
    return out


def _rollers(size: str) -> list[Series]:
    e = np.linspace(-3, 3, _steps(size, 13, 61))
    return [
        _series(e, False, clearance=2 * e, cage_angle=c, exponent=m)
        for m in (10 / 9, 1.0)
        for c in (0.0, 22.5, 7.0)
    ]


def _continuum_eps(size: str) -> list[Series]:
    p = np.arange(-12, 12.01, _steps(size, 2, 0.5))
    e = 10.0**p
    near = np.linspace(-2.0, 2.0, _steps(size, 9, 41))
    return [
        _series(e, True, clearance=2 * e),  # eps -> 0
        _series(e, True, clearance=-2 * e),  # eps -> 1 and beyond, eps -> inf
        _series(near, False, clearance=2 * near),
        _series(e, True, clearance=-2 * e, exponent=10 / 9),
    ]


def _hertz_ratio(size: str) -> list[Series]:
    ratio = 10.0 ** np.arange(0, 15.01, _steps(size, 1, 0.125))
    n = ratio.size
    return [
        Series(ratio, True, {"rho_x": np.ones(n), "rho_y": 1.0 / ratio}),
        Series(ratio, True, {"rho_x": ratio * 1e-3, "rho_y": np.full(n, 1e-3)}),
    ]


# --- the hard corners: heavy preload, extreme scales, memory, symmetry, batches, bad inputs


def _x_reference(z: int, f: float, k: float, g: float, cage: float, m: float) -> float:
    """x of a symmetric preloaded ring (y = 0), written without cancellation: with ``t = x/|e|``,
    ``sum_i ((1 + t c_i)_+^m - 1) c_i = F/(K |e|^m)`` (``sum_i c_i = 0``), solved by bisection."""
    e = abs(g) / 2.0
    c = np.cos(np.deg2rad(cage) + 2 * np.pi * np.arange(z) / z)
    target = f / (k * e**m)

    def side(t: float) -> float:
        base = 1.0 + t * c
        with np.errstate(all="ignore"):
            excess = np.where(base > 0, np.expm1(m * np.log1p(np.maximum(t * c, -1.0))), -1.0)
        return float(excess @ c) - target

    lo, hi = 0.0, 1e-300
    while side(hi) < 0:
        lo, hi = hi, hi * 4.0
    for _ in range(3000):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        lo, hi = (mid, hi) if side(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi) * e


def _x_check(series: list[Series], outs: list[Outcome], size: str) -> tuple[str, float, float]:
    worst = 0.0
    for s, o in zip(series, outs, strict=True):
        inp = s.inputs
        for i in range(s.parameter.size):
            symmetric = math.isclose(float(inp["cage_angle"][i]) * int(inp["balls"][i]) % 180, 0)
            if inp["clearance"][i] >= 0 or not symmetric or not o.finite[i]:
                continue
            ref = _x_reference(
                int(inp["balls"][i]),
                float(inp["load"][i]),
                float(inp["stiffness"][i]),
                float(inp["clearance"][i]),
                float(inp["cage_angle"][i]),
                float(inp["exponent"][i]),
            )
            worst = max(worst, abs(o.d[i, 0] / ref - 1.0))
    return "x against an independent formula (relative)", worst, 1e-10


def _heavy_preload(size: str) -> list[Series]:
    e = 10.0 ** np.arange(0, 12.01, _steps(size, 1, 0.25))
    return [
        _series(e, True, balls=12, clearance=-2 * e),
        _series(e, True, balls=8, clearance=-2 * e, cage_angle=22.5),
        _series(e * 1e70, True, balls=7, clearance=-2 * e * 1e70, exponent=1.0),
    ]


def _stiffness_extremes(size: str) -> list[Series]:
    p = np.arange(-300, 155.01, _steps(size, 25, 5))
    v = 10.0**p
    return [_series(v, True, balls=9, load=v, stiffness=v, clearance=6.0, cage_angle=13.0)]


def _stiffness_check(
    series: list[Series], outs: list[Outcome], size: str
) -> tuple[str, float, float]:
    # with F = K the scaled problem is the same for every case: stiffness / F is constant
    o, s = outs[0], series[0]
    ratio = o.result.stiffness_radial / s.inputs["load"]
    ref = float(ratio[np.argmin(np.abs(np.log10(s.parameter)))])
    return (
        "stiffness_radial/F against F = K = 1 (relative)",
        float(np.max(np.abs(ratio / ref - 1))),
        1e-12,
    )


def _preload_m3(size: str) -> list[Series]:
    p = np.union1d(np.arange(0, 62.01, _steps(size, 4, 1)), [62.0])
    g = -2.0 * 10.0**p
    return [
        _series(10.0**p, True, clearance=g, cage_angle=10.0, exponent=3.0),
        _series(10.0**p, True, clearance=g, exponent=3.0),
        _series([1e100], True, load=1e100, stiffness=1e100, clearance=-2e99, exponent=3.0),
    ]


def _memory_sizes(size: str) -> tuple[int, int]:
    return (2_000, 8_000) if size == "quick" else (20_000, 200_000)


def _chunked(size: str) -> list[Series]:
    f = np.linspace(0.5, 2.0, 16)
    return [_series(f, True, balls=2000, load=f, clearance=g) for g in (0.0, 2.0)]


def _memory_check(series: list[Series], outs: list[Outcome], size: str) -> tuple[str, float, float]:
    import tracemalloc

    from bearingload.models.equilibrium import solve

    peaks: list[float] = []
    sizes = _memory_sizes(size)
    for n in sizes:
        load = np.linspace(0.5, 2.0, n)
        tracemalloc.start()
        try:
            solve(2000, load, 1.0, np.where(np.arange(n) % 2 == 0, 0.0, 2.0))
            peaks.append(tracemalloc.get_traced_memory()[1])
        except MemoryError:
            peaks.append(math.inf)
        finally:
            tracemalloc.stop()
    # marginal memory per case: what a bounded working set (chunks) does not add. An unchunked
    # engine needs more than z * 4 = 8000 bytes per case (a cases x half-ring array of doubles).
    marginal = (peaks[1] - peaks[0]) / (sizes[1] - sizes[0])
    return (
        f"peak memory per added case [bytes], {sizes[0]} to {sizes[1]} cases, z = 2000",
        marginal,
        2000.0,
    )


def _near_symmetric(size: str) -> list[Series]:
    """Cage angles approaching 0 from both sides. The engine answers angles within
    ``SYMMETRY_SNAP_DEG`` (3.2e-13°) of symmetry as symmetric (its documented rule: below that
    a negative angle loses its sign in the reduction to [0, 360)); with one ball loaded at
    exactly 0 the equilibrium is not unique, and y and the loaded-ball count jump there by the
    problem itself. So each side is a series outside the band, and the band (both signs, with
    0) is one series: each must be continuous."""
    from bearingload.models.equilibrium import SYMMETRY_SNAP_DEG

    a = 10.0 ** -np.arange(12, 0, -_steps(size, 2, 1))
    inside = np.array([-1e-13, -1e-14, -1e-15, 0.0, 1e-15, 1e-14, 1e-13])
    assert SYMMETRY_SNAP_DEG > 1e-13 and a.min() > SYMMETRY_SNAP_DEG
    return [
        _series(a, True, clearance=20.0, cage_angle=a),  # per decade of the angle
        _series(-a[::-1], True, clearance=20.0, cage_angle=-a[::-1]),
        _series(inside, False, clearance=20.0, cage_angle=inside),
    ]


def _batch_series(size: str) -> list[Series]:
    base = 23.839033635393225
    k = np.arange(-8, 9, _steps(size, 2, 1))
    f = base + k * np.spacing(base)
    return [_series(f, True, balls=2000, load=f, clearance=2.0, exponent=1.0)]


def _batch_check(series: list[Series], outs: list[Outcome], size: str) -> tuple[str, float, float]:
    from bearingload.models.equilibrium import solve

    worst = 0.0
    for f in series[0].parameter:
        alone = solve(2000, f, 1.0, 2.0, 0.0, 1.0)
        for other in (f, 1.0, 100.0, float(np.nextafter(f, 0))):
            pair = solve(2000, np.array([f, other]), 1.0, 2.0, 0.0, 1.0)[0]
            for name in ("q_max", "x", "stiffness_radial", "loaded_balls"):
                a, b = float(getattr(alone, name)), float(getattr(pair, name))
                worst = max(worst, abs(a - b) / max(abs(a), abs(b), 1e-300))
    return "alone against in a batch of two (relative)", worst, 1e-12


def _load_zone(size: str) -> list[Series]:
    e = 10.0 ** np.arange(0, 12.01, _steps(size, 3, 1))
    zs = (1000, 100_000) if size == "quick" else (1000, 10_000, 100_000)
    return [
        _series(e, True, balls=z, clearance=2 * e, cage_angle=half * 180 / z)
        for z in zs
        for half in (0, 1)
    ]


def _load_zone_check(
    series: list[Series], outs: list[Outcome], size: str
) -> tuple[str, float, float]:
    """Half-angle of the load zone written without cancellation for a symmetric ring: the ball
    nearest the load line at ``h`` carries ``delta_max``, so ``x = (e + delta_max)/cos(h)`` and
    ``1 - e/x = (2 e sin^2(h/2) + delta_max)/(e + delta_max)``."""
    worst = 0.0
    for s, o in zip(series, outs, strict=True):
        r = o.result
        e = s.inputs["clearance"] / 2.0
        h = np.deg2rad(s.inputs["cage_angle"])
        delta = (r.q_max / s.inputs["stiffness"]) ** (1.0 / s.inputs["exponent"])
        one_minus = (2 * e * np.sin(h / 2) ** 2 + delta) / (e + delta)
        ref = np.rad2deg(2.0 * np.arcsin(np.sqrt(one_minus / 2.0)))
        worst = max(worst, float(np.max(np.abs(r.load_zone / ref - 1.0))))
    return "load_zone against a formula without cancellation (relative)", worst, 1e-11


#: Bad inputs: (call, text the message must contain).
def _bad_inputs() -> list[tuple[Callable[[], Any], str]]:
    from bearingload.models.continuum import solve_continuum
    from bearingload.models.equilibrium import solve

    return [
        (lambda: solve(np.array([]), 1.0, 1.0), "balls"),
        (lambda: solve(8, np.array([]), 1.0), "load"),
        (lambda: solve([8, 9], [1.0, 2.0, 3.0], 1.0), "shape"),
        (lambda: solve(8.0000000001, 1.0, 1.0), "8.0000000001"),
        (lambda: solve(8, 1.0, 1.0, 0.0, 0.0, 3.0000000001), "3.0000000001"),
        (lambda: solve(8, -1e-300, 1.0), "-1e-300"),
        (lambda: solve(8, 1.0, 1.0, float("nan")), "clearance"),
        (lambda: solve(8, 1.0, 1.0, 0.0, float("inf")), "cage_angle"),
        (lambda: solve_continuum([8, 9], [1.0, 2.0, 3.0], 1.0), "shape"),
        (lambda: solve_continuum(np.array([]), 1.0, 1.0), "balls"),
    ]


def _no_series(size: str) -> list[Series]:
    return []


def _input_check(series: list[Series], outs: list[Outcome], size: str) -> tuple[str, float, float]:
    wrong = 0
    for call, text in _bad_inputs():
        try:
            call()
            wrong += 1
        except InputError as exc:
            wrong += int(text not in str(exc))
        except Exception:  # noqa: BLE001 - a raw exception is what the check counts
            wrong += 1
    return f"of {len(_bad_inputs())} bad inputs not refused by name and exact value", wrong, 0.0


FAMILIES: tuple[Family, ...] = (
    Family("clearance_to_zero", "e/s through 0", _clearance_to_zero),
    Family("huge_clearance", "e/s 1 .. 1e12", _huge_clearance),
    Family("load_ratio", "F/(K e^1.5) 1e-12 .. 1e12", _load_ratio),
    Family("ball_count", "z 1 .. 1000, 1e5", _ball_count),
    Family("preload", "-e/s 1e-3 .. 1e3", _preload, check=_x_check),
    Family("one_loaded_ball", "z, one ball loaded", _one_ball, check=_one_ball_check),
    Family("cage_boundaries", "cage angle at a load-zone edge", _cage_boundaries),
    Family("rollers_and_m1", "e/s, m = 10/9 and 1", _rollers),
    Family("continuum_epsilon", "e/s: eps -> 0, 1, inf", _continuum_eps, kind="continuum"),
    Family("hertz_curvature", "curvature ratio 1 .. 1e15", _hertz_ratio, kind="hertz"),
    Family("heavy_preload_x", "-e/s 1 .. 1e12 (1e82)", _heavy_preload, check=_x_check),
    Family(
        "stiffness_extremes", "F = K 1e-300 .. 1e155", _stiffness_extremes, check=_stiffness_check
    ),
    Family("preload_m3", "-e/s 1 .. 1e62, m = 3", _preload_m3, may_refuse=True),
    Family("chunked_memory", "load, z = 2000", _chunked, check=_memory_check),
    Family("near_symmetric_cage", "cage angle -> 0 [deg]", _near_symmetric),
    Family("batch_independence", "load +- ulps, z = 2000", _batch_series, check=_batch_check),
    Family("load_zone_large_z", "e/s 1 .. 1e12, z to 1e5", _load_zone, check=_load_zone_check),
    Family("input_errors", "bad inputs", _no_series, check=_input_check),
)


def family_names() -> list[str]:
    """Names of the families, in report order."""
    return [f.name for f in FAMILIES]


def check_selection(size: str, names: list[str] | None, known: list[str]) -> None:
    """InputError unless ``size`` is one of :data:`SIZES` and every name is one of ``known``."""
    if size not in SIZES:
        raise InputError("size", f"must be one of {', '.join(SIZES)}; got {size!r}")
    unknown = sorted(set(names or ()) - set(known))
    if unknown:
        raise InputError("family", f"unknown {unknown[0]!r}; valid: {', '.join(known)}")


def run(size: str = "quick", names: list[str] | None = None) -> list[dict[str, Any]]:
    """One row per family (see the module notes); ``size`` is ``"quick"`` or ``"full"``."""
    check_selection(size, names, family_names())
    rows = []
    for family in FAMILIES:
        if names and family.name not in names:
            continue
        row, outs = _run_family(family, size)
        check, value, limit = ("-", 0.0, 0.0)
        if family.check is not None:
            check, value, limit = family.check(family.build(size), outs, size)
        rows.append(
            {
                "family": family.name,
                "parameter": family.parameter,
                **row,
                "jump_limit": family.jump_limit,
                "refusals_allowed": family.may_refuse,
                "check": check,
                "check_value": value,
                "check_limit": limit,
            }
        )
    return rows


#: Title and columns of the report (:mod:`bearingload.reports.stability`).
TITLE = "Numerical stability on stiff and extreme cases"
KEYS = (
    "family",
    "parameter",
    "cases",
    "max_residual",
    "max_jump",
    "jump_at",
    "batch_dependence",
    "max_iterations",
    "nan",
    "warnings_raised",
    "refused",
    "failures",
    "check_value",
    "check_limit",
    "check",
)
NOTES = (
    "max residual: |sum Q_i (cos, sin) - (F, 0)| / max(F, sum Q_i), from the returned ball loads.",
    "max jump: largest relative change of Q_max or (x, y) between neighbours per unit of the "
    "parameter (log10 of it, or itself through 0); order 1 for a smooth family, a limit of 10; "
    "jump at: the parameter value where it starts.",
    "batch dep.: largest relative difference between a case alone and in its family's batch.",
)
