"""Design tables per method and one table comparing the methods, for z = 1..z_max.

``bearingload table k --method NAME`` prints ``k = Q_max/F_r`` by one registered method of
:mod:`bearingload.models.registry` (``exact`` is Table 1 of Kuzmenko 2010, :func:`bearingload.studies.tables.table_k`);
``--method all`` prints :func:`table_compare`: every method side by side with its relative error
against the exact discrete answer. The same for ``kq`` (``K_Q = k z/2``, Kuzmenko & Sabadash 2014).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from bearingload.models.registry import METHODS, compute
from bearingload.reports.render import Column, Table
from bearingload.studies.tables import balls_and_angles, omitted_note

#: The quantity of each table name: (result attribute, header, display digits, description).
QUANTITIES = {
    "k": ("k", "k", 4, "Load factor k = Q_max/F_r"),
    "kq": ("K_Q", "K_Q", 5, "Load-concentration factor K_Q = k z/2"),
}


def _solve(method: str, z_max: int, cond: Any) -> tuple[np.ndarray, Any]:
    z, angle = balls_and_angles(z_max, cond.cage_angle)
    return z, compute(method, z, cond.load, cond.stiffness, cond.clearance, angle, cond.exponent)


def _ignored(method: str) -> list[str]:
    ignored = METHODS[method].ignores
    if not ignored:
        return []
    return [f"{method} ignores: {', '.join(ignored)}."]


def table_method(name: str, method: str, z_max: int = 30, cond: Any = None) -> Table:
    """Table ``name`` (``k`` or ``kq``) by one method for z = 1..z_max.

    Parameters
    ----------
    name : {'k', 'kq'}
        The quantity.
    method : str
        A registered method (:func:`bearingload.models.registry.list_methods`).
    z_max : int
        Largest number of balls. [-]
    cond : bearingload.studies.tables.Conditions, optional
        Load [N], stiffness [N/mm^m], clearance [mm], cage angle [°] or ``"half"``, exponent.
    """
    from bearingload.studies.tables import Conditions, table_k, table_kq

    cond = cond or Conditions()
    if method == "exact":
        return (table_k if name == "k" else table_kq)(z_max, cond)
    attr, header, digits, what = QUANTITIES[name]
    z, r = _solve(method, z_max, cond)
    values = np.broadcast_to(getattr(r, attr), z.shape)
    return Table(
        title=f"{what}, {method} method ({cond.describe()})",
        columns=[Column("z", "z"), Column(attr, header, "-", digits)],
        rows=[{"z": int(zi), attr: float(v)} for zi, v in zip(z, values, strict=True)],
        notes=[f"{method}: {METHODS[method].title}."]
        + _ignored(method)
        + omitted_note(z_max, cond.cage_angle),
    )


def table_compare(name: str, z_max: int = 30, cond: Any = None) -> Table:
    """Every method side by side for z = 1..z_max, with its error against the exact answer.

    Columns: ``z``, ``n`` (balls carrying load, exact model), the quantity by each method, and
    ``Q_max/Q_max,exact - 1`` in percent for every other method (the same for ``k`` and ``K_Q``).
    """
    from bearingload.studies.tables import Conditions

    cond = cond or Conditions()
    attr, header, digits, what = QUANTITIES[name]
    from bearingload.models.equilibrium import solve

    results = {m: _solve(m, z_max, cond)[1] for m in METHODS}
    z, angle = balls_and_angles(z_max, cond.cage_angle)
    exact = results["exact"]
    loaded = solve(z, cond.load, cond.stiffness, cond.clearance, angle, cond.exponent).loaded_balls
    columns = [Column("z", "z"), Column("n", "n")]
    values = {m: np.broadcast_to(getattr(r, attr), z.shape) for m, r in results.items()}
    errors = {
        m: np.broadcast_to(np.asarray(r.q_max) / np.asarray(exact.q_max) - 1.0, z.shape)
        for m, r in results.items()
        if m != "exact"
    }
    columns += [Column(f"{attr}_{m}", f"{header} {m}", "-", digits) for m in values]
    columns += [Column(f"error_{m}", f"{m} vs exact", "%", 3) for m in errors]
    rows = []
    for i, zi in enumerate(z):
        row: dict[str, Any] = {"z": int(zi), "n": int(loaded[i])}
        row.update({f"{attr}_{m}": float(v[i]) for m, v in values.items()})
        row.update({f"error_{m}": 100.0 * float(e[i]) for m, e in errors.items()})
        rows.append(row)
    return Table(
        title=f"{what} by every method ({cond.describe()})",
        columns=columns,
        rows=rows,
        notes=[f"{m}: {spec.title}." for m, spec in METHODS.items()]
        + [
            "vs exact: Q_max/Q_max,exact - 1 (the same for k and K_Q). Stribeck and Palmgren "
            "ignore stiffness, clearance, cage angle and exponent; the continuum ignores the cage "
            "angle.",
            "The smeared models assume many balls: for z <= 4 they give k = 4.37/z or 5/z above 1, "
            "a heaviest ball carrying more than the whole load.",
        ]
        + omitted_note(z_max, cond.cage_angle),
    )


def bearing_note(bearing: Any) -> str:
    """One note line naming the bearing whose ball stiffness and clearance a table uses.

    ``bearing`` is a :class:`bearingload.bearings.resolve.ResolvedBearing`.
    """
    label = f"bearing {bearing.designation}" if bearing.designation else "the given ball"
    k_src = "given" if bearing.stiffness_given else "exact Hertz"
    return (
        f"Ball and raceways of {label} ({bearing.balls} balls in the bearing itself): "
        f"K = {bearing.stiffness:.6g} N/mm^1.5 ({k_src}), G_r = {bearing.clearance * 1e3:.6g} µm."
    )
