"""Reference rating life L10r against the radial internal clearance, from preload to large play.

The question of Oswald, Zaretsky & Poplawski (*Effect of Internal Clearance on Load Distribution
and Life of Radially Loaded Ball and Roller Bearings*, NASA TM-2012-217115, 2012): which
clearance gives the longest life, and how a slight preload compares with a clearance. Here for
the catalogue bearing 6205 (z = 9, D_w = 7.938 mm, d_m = 38.5 mm, groove radii 0.52/0.53 D_w,
C_r = 14 000 N, C0r = 7850 N, f0 = 13.9; see bearings.csv for the sources), inner ring rotating,
ISO/TS 16281 life from the load distribution of :func:`bearingload.models.combined.solve_combined`
(exact Hertz stiffness at each contact angle, ring free to tilt), under a radial load alone and
under the same radial load with an axial load. ISO 281's basic life (C_r/P)^3 with
P = X F_r + Y F_a (normal clearance) does not see the clearance; it is given beside.
"""

from __future__ import annotations

import numpy as np

from bearingload.reports.render import Column, Table

#: The study's bearing and loads. [N]
DESIGNATION = "6205"
RADIAL_LOAD = 1400.0  # C_r / 10
AXIAL_LOAD = 700.0
#: Radial internal clearances G_r of the rows, from preload to large play. [um]
CLEARANCES_UM = (-20, -15, -10, -8, -6, -4, -2, 0, 2, 4, 6, 8, 10, 15, 20, 30, 40, 60, 80)


def life_vs_clearance(
    designation: str = DESIGNATION,
    radial_load: float = RADIAL_LOAD,
    axial_load: float = AXIAL_LOAD,
    clearances_um: tuple[float, ...] = CLEARANCES_UM,
) -> list[dict[str, float]]:
    """Rows of G_r [um], alpha_0 [°], loaded balls, Q_max [N], L10r [10^6 rev] for F_r alone and
    for F_r with F_a, and L10r relative to zero clearance."""
    from bearingload.bearings.iso16281 import contact_ratings, reference_rating_life
    from bearingload.bearings.resolve import resolve_bearing
    from bearingload.models.combined import solve_combined

    b = resolve_bearing(designation, clearance=0.0)
    assert b.C is not None and b.ball_diameter is not None and b.pitch_diameter is not None
    assert b.f_i is not None and b.f_o is not None
    geometry = {
        "ball_diameter": b.ball_diameter,
        "pitch_diameter": b.pitch_diameter,
        "f_i": b.f_i,
        "f_o": b.f_o,
        "modulus": b.modulus,
        "poisson": b.poisson,
    }
    g = np.asarray(clearances_um, dtype=float) * 1e-3
    q_ci, q_ce = contact_ratings(b.C, b.balls, b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o)
    out: dict[str, np.ndarray] = {}
    for tag, fa in (("r", 0.0), ("c", axial_load)):
        r = solve_combined(b.balls, radial_load, fa, clearance=g, **geometry)
        out[f"life_{tag}"] = reference_rating_life(r.ball_loads, q_ci, q_ce, "inner")
        out[f"q_{tag}"] = r.q_max
        out[f"n_{tag}"] = r.loaded_balls
        out["alpha0"] = r.free_contact_angle
        out[f"alpha_{tag}"] = r.contact_angles.max(axis=-1)
    zero = int(np.argmin(np.abs(g)))
    rows = []
    for i, gr in enumerate(clearances_um):
        rows.append(
            {
                "clearance_um": float(gr),
                "free_contact_angle_deg": float(out["alpha0"][i]),
                "loaded_r": int(out["n_r"][i]),
                "q_max_r": float(out["q_r"][i]),
                "life_r": float(out["life_r"][i]),
                "ratio_r": float(out["life_r"][i] / out["life_r"][zero]),
                "loaded_c": int(out["n_c"][i]),
                "alpha_max_c": float(out["alpha_c"][i]),
                "q_max_c": float(out["q_c"][i]),
                "life_c": float(out["life_c"][i]),
                "ratio_c": float(out["life_c"][i] / out["life_c"][zero]),
            }
        )
    return rows


def life_vs_clearance_table() -> Table:
    """The committed table ``tables/life_vs_clearance_6205``."""
    from bearingload.bearings.life import equivalent_load_deep_groove, rating_life
    from bearingload.bearings.resolve import resolve_bearing

    rows = life_vs_clearance()
    b = resolve_bearing(DESIGNATION, clearance=0.0)
    assert b.C is not None and b.C0 is not None and b.geometry is not None
    f0 = b.geometry.f0
    assert f0 is not None
    p = float(equivalent_load_deep_groove(RADIAL_LOAD, AXIAL_LOAD, b.C0, f0))
    best_r = max(rows, key=lambda r: r["life_r"])
    best_c = max(rows, key=lambda r: r["life_c"])
    columns = [
        Column("clearance_um", "G_r", "um", 3),
        Column("free_contact_angle_deg", "alpha_0", "°", 4),
        Column("loaded_r", "n (F_r)"),
        Column("q_max_r", "Q_max (F_r)", "N", 5),
        Column("life_r", "L10r (F_r)", "10^6 rev", 5),
        Column("ratio_r", "L10r/L10r(0) (F_r)", "-", 4),
        Column("loaded_c", "n (F_r+F_a)"),
        Column("alpha_max_c", "alpha_max (F_r+F_a)", "°", 4),
        Column("q_max_c", "Q_max (F_r+F_a)", "N", 5),
        Column("life_c", "L10r (F_r+F_a)", "10^6 rev", 5),
        Column("ratio_c", "L10r/L10r(0) (F_r+F_a)", "-", 4),
    ]
    notes = [
        f"Bearing {DESIGNATION}: z = {b.balls}, D_w = {b.ball_diameter} mm, "
        f"d_m = {b.pitch_diameter} mm, f_i = {b.f_i}, f_o = {b.f_o}, E = {b.modulus:g} MPa, "
        f"C_r = {b.C:g} N; F_r = {RADIAL_LOAD:g} N, F_a = {AXIAL_LOAD:g} N; inner ring rotating; "
        "negative G_r = preload.",
        "L10r: ISO/TS 16281:2008 clause 4.3 from the ball loads of the 3-D ring equilibrium "
        "(exact Hertz stiffness at each contact angle, ring free to tilt).",
        f"Longest life: F_r alone at G_r = {best_r['clearance_um']:g} um, "
        f"F_r + F_a at G_r = {best_c['clearance_um']:g} um (of the rows).",
        f"ISO 281:2007 basic life, blind to clearance: F_r alone (C_r/F_r)^3 = "
        f"{float(rating_life(b.C, RADIAL_LOAD)):.5g}; F_r + F_a: P = X F_r + Y F_a = "
        f"{p:.5g} N (5.2, Table 3, f0 = {f0:g}, C0r = {b.C0:g} N), "
        f"(C_r/P)^3 = {float(rating_life(b.C, p)):.5g} (10^6 rev).",
        "Question after Oswald, Zaretsky & Poplawski, NASA TM-2012-217115 (2012).",
    ]
    return Table("L10r against radial internal clearance, 6205", columns, rows, notes)
