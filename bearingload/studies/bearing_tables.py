"""Design tables (k, K_Q for z = 1..30) for the ball and raceways of one bearing.

The tables of :mod:`bearingload.studies.tables` depend, with clearance, on the load and the ball
stiffness; here the stiffness is the exact Hertz value of a resolved bearing's ball and
raceways, and the title and notes say which bearing, clearance and sources were used.

The committed tables for bearing 306 use the conditions of Kuzmenko (2010, seed 000, §3):
F_r = 300 kgf, G_r = 20 µm (Delta = 10 µm per side) and 100 µm (worn, Delta = 50 µm), the
paper's geometry D_w 12.3 mm, d_m 51 mm, f_i = f_o = 0.515 (groove radius 1.03 D_w/2) and
material E = 2.1e4 kgf/mm^2, nu = 0.3 -- but the exact Hertz stiffness of that geometry
(about 4.0e5 N/mm^1.5), not the paper's 4700 kgf/mm^1.5 (see
:func:`bearingload.contact.hertz.kuzmenko2010_ball_constant`).
"""

from __future__ import annotations

import dataclasses

from bearingload.bearings.resolve import Provenance, ResolvedBearing, resolve_bearing
from bearingload.reports.render import Table
from bearingload.units import KGF

#: Young's modulus of Kuzmenko (2010), §3.4: 2.1e4 kgf/mm^2. [MPa]
KUZMENKO2010_MODULUS = 2.1e4 * KGF
#: Radial load of the worked example of Kuzmenko (2010), §3.3: 300 kgf. [N]
KUZMENKO2010_LOAD = 300.0 * KGF


def bearing_table(
    name: str,
    bearing: ResolvedBearing,
    load: float,
    z_max: int = 30,
    cage_angle: float | str = 0.0,
) -> Table:
    """Table ``"k"`` (Table 1) or ``"kq"`` (Table 2.2) for the ball and raceways of ``bearing``.

    Parameters
    ----------
    name : {"k", "kq"}
        Which table.
    bearing : ResolvedBearing
        Gives the ball stiffness K [N/mm^1.5] and the clearance G_r [mm]; its own z is ignored,
        the table runs over z = 1..z_max.
    load : float
        Radial load F_r. [N]
    z_max : int
        Largest number of balls.
    cage_angle : float or "half"
        Cage angle [°].
    """
    from bearingload.studies.tables import Conditions, table_k, table_kq

    cond = Conditions(load, bearing.stiffness, bearing.clearance, cage_angle, 1.5)
    table = {"k": table_k, "kq": table_kq}[name](z_max, cond)
    label = f"bearing {bearing.designation}" if bearing.designation else "the given ball"
    k_src = "given" if bearing.stiffness_given else "exact Hertz"
    notes = list(table.notes) + [
        f"Ball and raceways of {label} ({bearing.balls} balls in the bearing itself; here "
        f"z = 1..{z_max}): K = {bearing.stiffness:.6g} N/mm^1.5 "
        f"({bearing.stiffness / KGF:.6g} kgf/mm^1.5, {k_src}); "
        f"F_r = {load:.6g} N ({load / KGF:.6g} kgf); G_r = {bearing.clearance * 1e3:.6g} µm.",
    ]
    notes += [
        f"{p.label}: {p.value:.6g}{' ' + p.unit if p.unit else ''} ({p.source})"
        for p in _inputs(bearing)
    ]
    return dataclasses.replace(
        table, title=f"Bearing {bearing.designation}: {table.title}", notes=notes
    )


def _inputs(bearing: ResolvedBearing) -> list[Provenance]:
    keys = ("ball_diameter", "pitch_diameter", "f_i", "f_o", "modulus", "poisson", "clearance")
    return [p for p in bearing.provenance if p.key in keys and isinstance(p.value, (int, float))]


def kuzmenko2010_306(clearance: float) -> ResolvedBearing:
    """Bearing 306 under the conditions of Kuzmenko (2010): catalogue geometry (= the paper's),
    E = 2.1e4 kgf/mm^2, nu = 0.3, exact Hertz stiffness, radial clearance G_r [mm]."""
    return resolve_bearing("306", modulus=KUZMENKO2010_MODULUS, poisson=0.3, clearance=clearance)


def kuzmenko2010_306_table(name: str, clearance: float) -> Table:
    """Table 1 (``"k"``) or 2.2 (``"kq"``) for bearing 306 at 300 kgf and G_r [mm]."""
    table = bearing_table(name, kuzmenko2010_306(clearance), KUZMENKO2010_LOAD)
    note = (
        "Conditions of Kuzmenko (2010) §3: F_r = 300 kgf, E = 2.1e4 kgf/mm^2, nu = 0.3, the "
        "paper's geometry (= catalogue row 306); stiffness exact Hertz, not the paper's 4700 "
        "kgf/mm^1.5."
    )
    return dataclasses.replace(table, notes=[*table.notes, note])
