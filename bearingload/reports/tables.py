"""The design tables laid out: Table 1 (k), Table 2.2 (K_Q), per model and every model side by side.

The numbers come from :func:`bearingload.studies.tables.over_z`; this module only arranges them.
Every table carries its conditions: in the title for people, as leading columns in csv and as
fields in json.

``design_table(name, z_max, cond, method)``: k (K_Q) and loaded balls n over z (Kuzmenko 2010,
Table 1; Kuzmenko & Sabadash 2014, Table 2.2) by any registered model, or by every model side by
side with its error against the exact answer (``method="all"``).
"""

from __future__ import annotations

from typing import Any

from bearingload.models.registry import METHODS, list_methods
from bearingload.reports.render import Column, Table
from bearingload.studies.tables import Conditions, column_of, omitted, over_z
from bearingload.units import KGF

#: table name -> (result attribute, header, display digits, description, note of the exact table)
TABLES = {
    "k": (
        "k",
        "k",
        4,
        "Load factor k = Q_max/F_r",
        "z: balls; n: balls carrying load; k: heaviest ball load over the radial load.",
    ),
    "kq": (
        "K_Q",
        "K_Q",
        5,
        "Load-concentration factor K_Q = k z/2",
        "K_Q: heaviest ball load over the mean load F_r/(z/2).",
    ),
}


def design_table(
    name: str, z_max: int = 30, cond: Conditions | None = None, method: str = "exact"
) -> Table:
    """Table ``name`` (``k`` or ``kq``) over z = 1..z_max by ``method`` (a registered model or
    ``all``) under ``cond`` (default: zero clearance, a ball under the load, m = 1.5)."""
    cond = cond or Conditions()
    if method == "all":
        table = _compare(name, z_max, cond)
    elif method == "exact":
        table = _exact(name, z_max, cond)
    else:
        table = _one_method(name, method, z_max, cond)
    return table


def _conditions(cond: Conditions, method: str | None) -> list[tuple[Column, Any]]:
    out: list[tuple[Column, Any]] = []
    if cond.bearing is not None:
        out.append((Column("bearing", "bearing"), cond.bearing.designation or "given by hand"))
    if method is not None:
        out.append((Column("method", "method"), method))
    out += [
        (Column("load", "load", "N"), cond.load),
        (Column("stiffness", "stiffness", f"N/mm^{cond.exponent:g}"), cond.stiffness),
        (Column("clearance", "clearance", "mm"), cond.clearance),
    ]
    if cond.cage_angle == "half":
        out.append((Column("cage_angle_pitch", "cage angle", "pitch"), 0.5))
    else:
        out.append((Column("cage_angle", "cage angle", "°"), float(cond.cage_angle)))
    out.append((Column("exponent", "exponent", "-"), cond.exponent))
    return out


def _omitted_note(z_max: int, cond: Conditions) -> list[str]:
    missing = omitted(z_max, cond.cage_angle)
    if not missing:
        return []
    listed = " and ".join(str(v) for v in missing)
    return [
        f"z = {listed} left out: with one or two balls equilibrium needs a ball on the load line "
        "(cage angle 0)."
    ]


def _exact(name: str, z_max: int, cond: Conditions) -> Table:
    attr, header, digits, what, note = TABLES[name]
    z, results = over_z(z_max, cond)
    r = results["exact"]
    rows = [
        {"balls": int(zi), "loaded_balls": int(n), attr: float(v)}
        for zi, n, v in zip(z, column_of(r, "loaded_balls", z), column_of(r, attr, z), strict=True)
    ]
    title = f"{what} (exact discrete model; {cond.describe()})"
    notes = [note, *_omitted_note(z_max, cond)]
    if cond.bearing is not None:
        title = f"Bearing {cond.bearing.designation}: {title}"
        notes += _bearing_notes(cond, z_max)
    columns = [Column("balls", "z"), Column("loaded_balls", "n"), Column(attr, attr, "-", digits)]
    return Table(title, columns, rows, notes, _conditions(cond, "exact"))


def _bearing_notes(cond: Conditions, z_max: int) -> list[str]:
    b = cond.bearing
    assert b is not None
    label = f"bearing {b.designation}" if b.designation else "the given ball"
    k_src = "given" if b.stiffness_given else "exact Hertz"
    keys = ("ball_diameter", "pitch_diameter", "f_i", "f_o", "modulus", "poisson", "clearance")
    inputs = [p for p in b.provenance if p.key in keys and isinstance(p.value, (int, float))]
    return [
        f"Ball and raceways of {label} ({b.balls} balls in the bearing itself; here "
        f"z = 1..{z_max}): K = {b.stiffness:.6g} N/mm^1.5 "
        f"({b.stiffness / KGF:.6g} kgf/mm^1.5, {k_src}); "
        f"F_r = {cond.load:.6g} N ({cond.load / KGF:.6g} kgf); G_r = {b.clearance * 1e3:.6g} µm.",
    ] + [f"{p.label}: {p.value:.6g}{' ' + p.unit if p.unit else ''} ({p.source})" for p in inputs]


def _method_bearing_note(cond: Conditions) -> list[str]:
    b = cond.bearing
    if b is None:
        return []
    label = f"bearing {b.designation}" if b.designation else "the given ball"
    k_src = "given" if b.stiffness_given else "exact Hertz"
    return [
        f"Ball and raceways of {label} ({b.balls} balls in the bearing itself): "
        f"K = {b.stiffness:.6g} N/mm^1.5 ({k_src}), G_r = {b.clearance * 1e3:.6g} µm."
    ]


def _one_method(name: str, method: str, z_max: int, cond: Conditions) -> Table:
    attr, header, digits, what, _ = TABLES[name]
    z, results = over_z(z_max, cond, [method])
    values = column_of(results[method], attr, z)
    ignored = METHODS[method].ignores
    notes = [f"{method}: {METHODS[method].title}."]
    notes += [f"{method} ignores: {', '.join(ignored)}."] if ignored else []
    return Table(
        title=f"{what}, {method} method ({cond.describe()})",
        columns=[Column("balls", "z"), Column(attr, header, "-", digits)],
        rows=[{"balls": int(zi), attr: float(v)} for zi, v in zip(z, values, strict=True)],
        notes=notes + _omitted_note(z_max, cond) + _method_bearing_note(cond),
        conditions=_conditions(cond, method),
    )


def _compare(name: str, z_max: int, cond: Conditions) -> Table:
    """Every model side by side, with ``Q_max/Q_max,exact - 1`` in percent for the others."""
    attr, header, digits, what, _ = TABLES[name]
    z, results = over_z(z_max, cond, list_methods())
    exact = results["exact"]
    loaded = column_of(exact, "loaded_balls", z)
    values = {m: column_of(r, attr, z) for m, r in results.items()}
    errors = {
        m: column_of(r, "q_max", z) / column_of(exact, "q_max", z) - 1.0
        for m, r in results.items()
        if m != "exact"
    }
    columns = [Column("balls", "z"), Column("loaded_balls", "n")]
    columns += [Column(f"{attr}_{m}", f"{header} {m}", "-", digits) for m in values]
    columns += [Column(f"error_{m}", f"{m} vs exact", "%", 3) for m in errors]
    rows = []
    for i, zi in enumerate(z):
        row: dict[str, Any] = {"balls": int(zi), "loaded_balls": int(loaded[i])}
        row.update({f"{attr}_{m}": float(v[i]) for m, v in values.items()})
        row.update({f"error_{m}": 100.0 * float(e[i]) for m, e in errors.items()})
        rows.append(row)
    notes = [f"{m}: {spec.title}." for m, spec in METHODS.items()] + [
        "vs exact: Q_max/Q_max,exact - 1 (the same for k and K_Q). Stribeck and Palmgren "
        "ignore stiffness, clearance, cage angle and exponent; the continuum ignores the cage "
        "angle.",
        "The smeared models assume many balls: for z <= 4 they give k = 4.37/z or 5/z above 1, "
        "a heaviest ball carrying more than the whole load.",
    ]
    return Table(
        title=f"{what} by every method ({cond.describe()})",
        columns=columns,
        rows=rows,
        notes=notes + _omitted_note(z_max, cond) + _method_bearing_note(cond),
        conditions=_conditions(cond, None),
    )
