"""Reports of ``bearingload solve --method continuum|stribeck|palmgren|all``.

The exact method keeps its own report (:mod:`bearingload.reports.solve`, every ball's load); this
module renders the other methods of :mod:`bearingload.models.registry` and the side-by-side comparison,
with each method's relative error against the exact discrete answer. Rows are built once and
printed by :mod:`bearingload.reports.render`.
"""

from __future__ import annotations

from typing import Any

from bearingload.models.registry import METHODS, MethodResult, compute, compute_all, relative_error
from bearingload.reports.parts import cage_angle_deg, inputs_json, inputs_text, summary_table
from bearingload.reports.render import Column, Table, render
from bearingload.units import KGF

#: How the CLI names the inputs a method ignores.
OPTION_OF = {
    "stiffness": "--stiffness",
    "clearance": "--clearance",
    "cage_angle": "--cage-angle",
    "exponent": "--exponent",
}


def _ignores_text(name: str) -> str:
    ignored = [OPTION_OF[p] for p in METHODS[name].ignores]
    return "nothing" if not ignored else ", ".join(ignored)


def _zone_deg(result: MethodResult) -> float | None:
    return None if result.load_zone is None else float(result.load_zone)


def _units(exponent: float) -> dict[str, str]:
    return {
        "load": "N",
        "stiffness": f"N/mm^{exponent:g}",
        "clearance": "mm (G_r, total radial play)",
        "q_max": "N",
        "load_zone_deg": "°",
        "deflection": "mm",
        "max_deflection": "mm",
        "stiffness_radial": "N/mm",
    }


def method_report(
    method: str,
    balls: int,
    load: float,
    stiffness: float,
    clearance: float,
    cage_angle: float | str,
    exponent: float,
    fmt: str,
    *,
    context: str | None = None,
) -> str:
    """Solve one case by ``method`` (a registered name other than ``exact``, or ``all``) and render it.

    Inputs in N, N/mm^m, mm, degrees or ``"half"`` (half a pitch), as ``bearingload solve``;
    ``context`` is one more note line (where the inputs came from), and ``"context"`` in JSON.
    """
    angle = cage_angle_deg(cage_angle, balls)
    args = (balls, load, stiffness, clearance, angle, exponent)
    extra = [context] if context else []
    if method == "all":
        return _comparison(args, fmt, extra)
    if method == "continuum":
        return _continuum(args, fmt, extra)
    return _one_line(method, args, fmt, extra)


def _continuum(args: tuple[Any, ...], fmt: str, extra: list[str]) -> str:
    from bearingload.models.continuum import solve_continuum

    balls, load, stiffness, clearance, angle, exponent = args
    compute("continuum", *args)  # the registry's input checks, cage angle included
    r = solve_continuum(balls, load, stiffness, clearance, exponent)
    k, kq, q = float(r.k), float(r.K_Q), float(r.q_max)
    zone = float(r.load_zone)
    note = f"{METHODS['continuum'].title}. The continuum has no cage position: --cage-angle is ignored."
    if fmt == "json":
        doc = (
            inputs_json(*args)
            | {
                "method": "continuum",
                "k": k,
                "K_Q": kq,
                "q_max": q,
                "load_zone_deg": zone,
                "deflection": float(r.deflection),
                "max_deflection": float(r.max_deflection),
                "stiffness_radial": float(r.stiffness_radial),
                "epsilon": float(r.epsilon),
                "ignores": list(METHODS["continuum"].ignores),
                "units": _units(exponent),
            }
            | ({"context": extra[0]} if extra else {})
        )
        return render([], "json", document=doc)
    rows = [
        ("load factor k = Q_max/F_r", k, "-"),
        ("load concentration K_Q = k z/2", kq, "-"),
        ("heaviest ball load Q_max", q, "N"),
        ("heaviest ball load Q_max", q / KGF, "kgf"),
        ("load zone half-angle", zone, "°"),
        ("ring displacement along the load x", float(r.deflection) * 1e3, "µm"),
        ("approach on the load line x - G_r/2", float(r.max_deflection) * 1e3, "µm"),
        ("radial stiffness dF_r/dx", float(r.stiffness_radial), "N/mm"),
        ("load-zone parameter epsilon", float(r.epsilon), "-"),
    ]
    return render(
        [summary_table(f"Continuum model ({inputs_text(*args)})", rows, [note, *extra])], fmt
    )


def _one_line(method: str, args: tuple[Any, ...], fmt: str, extra: list[str]) -> str:
    r = compute(method, *args)
    spec = METHODS[method]
    note = (
        f"{spec.title}: a one-line estimate for a ball bearing; it ignores {_ignores_text(method)}."
    )
    if fmt == "json":
        doc = (
            inputs_json(*args)
            | {
                "method": method,
                "k": r.k,
                "K_Q": r.K_Q,
                "q_max": r.q_max,
                "load_zone_deg": None,
                "ignores": list(spec.ignores),
                "units": {"load": "N", "q_max": "N"},
            }
            | ({"context": extra[0]} if extra else {})
        )
        return render([], "json", document=doc)
    rows = [
        ("load factor k = Q_max/F_r", r.k, "-"),
        ("load concentration K_Q = k z/2", r.K_Q, "-"),
        ("heaviest ball load Q_max", r.q_max, "N"),
        ("heaviest ball load Q_max", r.q_max / KGF, "kgf"),
    ]
    title = f"{method.capitalize()} estimate ({inputs_text(*args)})"
    return render([summary_table(title, rows, [note, *extra])], fmt)


def comparison_rows(results: dict[str, MethodResult]) -> list[dict[str, Any]]:
    """One row per method: k, K_Q, Q_max, load zone and the relative error against ``exact``."""
    exact = results["exact"]
    return [
        {
            "method": name,
            "k": float(r.k),
            "K_Q": float(r.K_Q),
            "q_max": float(r.q_max),
            "q_max_kgf": float(r.q_max) / KGF,
            "load_zone_deg": _zone_deg(r),
            "error_percent": 100.0 * float(relative_error(r, exact)),
            "ignores": _ignores_text(name),
        }
        for name, r in results.items()
    ]


def _comparison(args: tuple[Any, ...], fmt: str, extra: list[str]) -> str:
    rows = comparison_rows(compute_all(*args))
    if fmt == "json":
        doc = (
            inputs_json(*args)
            | {
                "reference": "exact",
                "methods": {
                    row["method"]: {
                        "k": row["k"],
                        "K_Q": row["K_Q"],
                        "q_max": row["q_max"],
                        "load_zone_deg": row["load_zone_deg"],
                        "relative_error": row["error_percent"] / 100.0,
                        "ignores": list(METHODS[row["method"]].ignores),
                        "model": METHODS[row["method"]].title,
                    }
                    for row in rows
                },
                "units": {"load": "N", "q_max": "N", "load_zone_deg": "°", "relative_error": "-"},
            }
            | ({"context": extra[0]} if extra else {})
        )
        return render([], "json", document=doc)
    for row in rows:
        if row["load_zone_deg"] is None:
            row["load_zone_deg"] = "" if fmt == "csv" else "-"
    table = Table(
        title=f"Methods side by side ({inputs_text(*args)})",
        columns=[
            Column("method", "method", align="left"),
            Column("k", "k", "-", 5),
            Column("K_Q", "K_Q", "-", 5),
            Column("q_max", "Q_max", "N", 6),
            Column("q_max_kgf", "Q_max", "kgf", 6),
            Column("load_zone_deg", "load zone", "°", 5),
            Column("error_percent", "vs exact", "%", 3),
            Column("ignores", "ignores", align="left"),
        ],
        rows=rows,
        notes=[f"{name}: {m.title}" for name, m in METHODS.items()]
        + [
            "vs exact: Q_max/Q_max,exact - 1. Stribeck and Palmgren ignore stiffness, clearance, "
            "cage angle and exponent.",
            *extra,
        ],
    )
    return render([table], fmt)
