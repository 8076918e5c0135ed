"""Every number the papers print that the project recomputes: printed, computed, verdict, cause.

One row per printed number. The printed values of Kuzmenko (2010) and Kuzmenko & Sabadash (2014)
come from the shipped data files (:mod:`bearingload.papers.published`); each is recomputed here
with the package's own models and procedures (never fitted to the printed number) and compared
within its printed rounding. Other papers add their rows through :data:`ROW_SOURCES`.

A row is a dict with the keys ``source`` (paper), ``table`` (table, equation or section),
``cell``, ``printed`` (text, as printed), ``computed``, ``difference`` (printed - computed),
``verdict`` (:data:`AGREES`, :data:`DIFFERS`, or another word such as "lost in print" for a cell
that cannot be compared) and ``cause``; rows built here also carry ``unit`` and
``relative_difference`` (difference / computed); :func:`errata_rows` fills those in for the other sources.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Iterable
from typing import Any

from bearingload.papers.published import FILES, Published, load

AGREES = "agrees"
DIFFERS = "differs"

#: Where the rows come from: (module, function) of :mod:`bearingload.studies`, in listing order.
#: Each function takes no argument and returns a list of row dicts (see the module docstring).
ROW_SOURCES: list[tuple[str, str]] = [
    ("bearingload.papers.errata", "kuzmenko2010_rows"),
    ("bearingload.papers.errata", "kuzmenko_sabadash2014_rows"),
    ("bearingload.papers.kurochkin_errata", "kurochkin1973_rows"),
    ("bearingload.papers.compliance", "compliance_rows"),
    ("bearingload.papers.crane_stiffness", "crane2009_rows"),
]

#: Quantities the registered methods return (``kz`` is ``k`` times the number of balls).
METHOD_QUANTITIES = ("k", "K_Q", "q_max", "load_zone", "loaded_balls", "kz")

#: Defaults of a case whose answer does not depend on them (k at zero clearance). [N, N/mm^m]
DEFAULT_LOAD = 1000.0
DEFAULT_STIFFNESS = 1e5


def case(row: Published) -> dict[str, Any]:
    """The arguments of :func:`bearingload.models.registry.compute` for a row's ``inputs``.

    Lengths, forces and stiffnesses are parsed with their units (``300kgf``, ``20um``,
    ``4700kgf/mm^1.5``); a missing load or stiffness takes :data:`DEFAULT_LOAD` /
    :data:`DEFAULT_STIFFNESS` (used only where the answer does not depend on it).
    """
    from bearingload.units import parse_quantity, parse_stiffness

    inp = row.inputs
    exponent = float(inp.get("exponent", 1.5))
    return {
        "balls": int(inp["balls"]),
        "load": parse_quantity(inp.get("load", str(DEFAULT_LOAD)), "force"),
        "stiffness": parse_stiffness(inp.get("stiffness", str(DEFAULT_STIFFNESS)), exponent),
        "clearance": parse_quantity(inp.get("clearance", "0"), "length"),
        "exponent": exponent,
    }


def method_value(row: Published, method: str | None = None) -> float:
    """A row's quantity from a registered method (default: the row's ``model``), in its unit."""
    from bearingload.models.registry import compute
    from bearingload.units import KGF

    args = case(row)
    result = compute(method or row.model, **args)
    if row.quantity == "kz":
        return float(result.k) * args["balls"]
    value = float(getattr(result, row.quantity))
    return value / KGF if row.unit == "kgf" else value


def _floats(row: Published, *names: str) -> list[float]:
    return [float(row.inputs[n]) for n in names]


def _resolving_lhs(row: Published) -> float:
    """Left side of Kuzmenko (2010) eq. 3.4, ``F_r/(c Delta^1.5)`` with ``Delta = G_r/2``."""
    args = case(row)
    return float(args["load"] / (args["stiffness"] * (args["clearance"] / 2) ** 1.5))


def _resolving_rhs(row: Published) -> float:
    """Right side of Kuzmenko (2010) eq. 3.4 at a trial angle ``phi0`` (a ball under the load).

    ``sum over the loaded balls of cos psi_i (cos psi_i/cos phi0 - 1)^1.5``, ``psi_i = 360° i/z``;
    ``part`` picks the ball at 0° (``centre``), the others (``sides``) or both (``all``).
    """
    import math

    z = int(row.inputs["balls"])
    c0 = math.cos(math.radians(float(row.inputs["phi0"])))
    part = row.inputs.get("part", "all")
    total = 0.0
    for i in range(z):
        c = math.cos(2 * math.pi * i / z)
        if c > c0 and (part == "all" or (part == "centre") == (i == 0)):
            total += c * (c / c0 - 1.0) ** 1.5
    return total


def _q_max_change(row: Published) -> float:
    """Change of the heaviest ball load between ``reference_clearance`` and ``clearance``:
    in the printed unit (``q_max_increase``) or in percent (``q_max_increase_percent``)."""
    import dataclasses

    base = _with_quantity(row, "q_max")
    ref_inputs = dict(row.inputs, clearance=row.inputs["reference_clearance"])
    ref = dataclasses.replace(base, inputs=ref_inputs, unit="kgf")
    q, q_ref = method_value(dataclasses.replace(base, unit="kgf")), method_value(ref)
    if row.quantity == "q_max_increase_percent":
        return 100.0 * (q / q_ref - 1.0)
    return q - q_ref


def _hertz(row: Published) -> float:
    """One step of the §3.4.2 stiffness chain of Kuzmenko (2010), done right."""
    from bearingload.contact.hertz import (
        ball_stiffness,
        hertz_coefficients,
        kuzmenko2010_ball_constant,
    )

    q = row.quantity
    if q == "n_delta":  # Harris's delta* at the A/B the paper read its table with
        return float(hertz_coefficients(float(row.inputs["A_over_B"]), 1.0).delta_star)
    r1, r2, r3, e, nu = _floats(row, "R1", "R2", "R3", "E", "nu")
    n_delta = float(row.inputs.get("n_delta", 0.55))
    paper = kuzmenko2010_ball_constant(r1, r2, r3, e, nu, n_delta)
    b_hertz = paper.sum_rho / 2 - paper.A  # = (1/R1 + 1/R3)/2
    if q == "ball_stiffness":  # exact Hertz, both contacts in series, kgf and mm
        return float(
            ball_stiffness(
                2 * r1, 2 * (r1 + r3), r2 / (2 * r1), r2 / (2 * r1), modulus=e, poisson=nu
            ).ball
        )
    values = {
        "e_star": paper.e_star,
        "sum_rho": paper.sum_rho,
        "A": paper.A,
        "B": b_hertz,
        "A_over_B": paper.A / b_hertz,
        "c1": paper.c1,
        "k_contact": paper.k_contact,
    }
    return float(values[q])


def _fit(row: Published) -> float:
    """Eqs. 2.1-2.6 and Table 2.1 of Kuzmenko & Sabadash (2014), loads in kgf, u in mm."""
    from bearingload.studies.fit import fit_two_point, normalized_distribution

    q = row.quantity
    if q == "u_over_umax":
        u, u_max = _floats(row, "u", "u_max")
        return u / u_max
    if q == "sigma_bar":
        u, u_max, n1 = _floats(row, "u", "u_max", "exponent")
        return float(normalized_distribution(u, 1.0 + n1, u_max))
    q1, u1, q2, u2 = _floats(row, "Q1", "u1", "Q2", "u2")
    fit = fit_two_point([q1, q2], [u1, u2])
    values = {
        "fit_exponent": fit.exponent,
        "fit_coefficient": fit.coefficient,
        "fit_exponent_minus_1": fit.exponent - 1.0,
    }
    return float(values[q])


def _kq_minus_n(row: Published) -> float:
    """The gap behind the "K_Q = n" claim: exact K_Q(z) minus the exact two-point n."""
    from bearingload.models.registry import compute

    args = case(row)
    kq = float(compute("exact", args["balls"], args["load"], args["stiffness"]).K_Q)
    return abs(kq - _fit(_with_quantity(row, "fit_exponent")))


def _with_quantity(row: Published, quantity: str) -> Published:
    import dataclasses

    return dataclasses.replace(row, quantity=quantity)


def _allowable_load(row: Published) -> float:
    from bearingload.bearings.life import allowable_load

    capacity, revolutions = _floats(row, "capacity", "revolutions")
    return float(allowable_load(capacity, revolutions))


def _gamma(row: Published) -> float:
    """A value of the gamma function the paper read from a table."""
    import math

    return math.gamma(float(row.inputs["x"]))


def _integral(row: Published) -> float:
    from bearingload.models.continuum import zero_clearance_integral

    return float(zero_clearance_integral(float(row.inputs["exponent"])))


#: (model, quantity) -> how a printed value that is not a method's output is recomputed.
DERIVATIONS: dict[tuple[str, str], Callable[[Published], float]] = {
    ("exact", "kq_minus_n"): _kq_minus_n,
    ("formula", "resolving_lhs"): _resolving_lhs,
    ("formula", "resolving_rhs"): _resolving_rhs,
    ("formula", "gamma"): _gamma,
    ("exact", "q_max_increase"): _q_max_change,
    ("exact", "q_max_increase_percent"): _q_max_change,
    ("continuum", "integral_I"): _integral,
    ("life", "allowable_load"): _allowable_load,
    **{
        ("hertz", q): _hertz
        for q in ("e_star", "sum_rho", "A", "B", "A_over_B", "n_delta", "c1", "k_contact")
    },
    ("hertz", "ball_stiffness"): _hertz,
    **{
        ("fit", q): _fit
        for q in (
            "fit_exponent",
            "fit_coefficient",
            "fit_exponent_minus_1",
            "u_over_umax",
            "sigma_bar",
        )
    },
}


def computed_value(row: Published) -> float:
    """The project's value of a printed number, in the printed unit."""
    if row.quantity in METHOD_QUANTITIES and (row.model, row.quantity) not in DERIVATIONS:
        return method_value(row)
    try:
        derive = DERIVATIONS[(row.model, row.quantity)]
    except KeyError:
        raise ValueError(f"no way to recompute {row.key}: {row.model}/{row.quantity}") from None
    return derive(row)


def compare(row: Published) -> dict[str, Any]:
    """The errata row of one printed value."""
    computed = computed_value(row)
    agrees = row.agrees(computed)
    difference = row.value - computed
    return {
        "source": row.source,
        "table": row.table,
        "cell": row.cell,
        "unit": row.unit,
        "printed": row.printed,
        "computed": computed,
        "difference": difference,
        "relative_difference": difference / computed if computed else None,
        "verdict": AGREES if agrees else DIFFERS,
        "cause": "" if agrees else (row.cause or "unknown"),
    }


def paper_rows(paper: str) -> list[dict[str, Any]]:
    """The errata rows of one shipped data file (a key of :data:`FILES`)."""
    return [compare(r) for r in load(paper)]


def kuzmenko2010_rows() -> list[dict[str, Any]]:
    """Kuzmenko (2010): Table 1, §3.2 life, §3.3-3.5 worked example, §3.4.2 stiffness, §4."""
    return paper_rows("kuzmenko2010")


def kuzmenko_sabadash2014_rows() -> list[dict[str, Any]]:
    """Kuzmenko & Sabadash (2014): Tables 2.1 and 2.2, eqs. 2.1-2.7, the K_Q claims of §3."""
    return paper_rows("kuzmenko_sabadash2014")


def errata_rows(sources: Iterable[tuple[str, str]] | None = None) -> list[dict[str, Any]]:
    """Every row of every source in :data:`ROW_SOURCES` (or ``sources``), in order."""
    rows: list[dict[str, Any]] = []
    for module, function in ROW_SOURCES if sources is None else sources:
        build = getattr(importlib.import_module(module), function)
        rows.extend(_normalised(r) for r in build())
    return rows


def _normalised(row: dict[str, Any]) -> dict[str, Any]:
    """A row from any source with every column of the report (``printed`` as text)."""
    out = dict(row)
    printed = out["printed"]
    out["printed"] = printed if isinstance(printed, str) else f"{printed:g}"
    out.setdefault("unit", "")
    if "relative_difference" not in out:
        computed, diff = out.get("computed"), out.get("difference")
        if isinstance(computed, (int, float)) and isinstance(diff, (int, float)) and computed:
            out["relative_difference"] = diff / computed
        else:
            out["relative_difference"] = None
    out["cause"] = out.get("cause") or ""
    if str(out["verdict"]).startswith("agrees"):  # "agrees within printed rounding"
        out["verdict"] = AGREES
    return out


def summary(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Per paper and table: how many printed numbers are checked, agree and differ (a cell that
    cannot be compared, such as one lost in print, counts as checked only)."""
    counts: dict[tuple[str, str], list[int]] = {}
    for r in rows:
        c = counts.setdefault((r["source"], r["table"]), [0, 0, 0])
        c[0] += 1
        c[1] += r["verdict"] == AGREES
        c[2] += r["verdict"] == DIFFERS
    return [
        {"source": s, "table": t, "checked": n, "agree": a, "differ": d}
        for (s, t), (n, a, d) in counts.items()
    ]


__all__ = ["AGREES", "DIFFERS", "FILES", "ROW_SOURCES", "errata_rows", "summary"]
