"""The committed tables of the papers checked (:mod:`bearingload.papers`): the printed cells of
Kurochkin (1973) that differ and his Example 1, the varying-compliance abstract's fits and the
crane paper's (2009) stiffness procedure, each against the exact model. The papers' modules
return the rows; the layout, titles and notes are here."""

from __future__ import annotations

from bearingload.papers import compliance, crane_stiffness, kurochkin_errata
from bearingload.reports.render import Column, Table


def kurochkin1973_differences_table() -> Table:
    """Committed table ``kurochkin1973_differences``: every printed cell that is not confirmed."""
    rows = kurochkin_errata.differences_rows()
    return Table(
        title="Kurochkin (1973), Tables 1-4 and Example 1: printed cells that differ from the "
        "exact model beyond their printed rounding",
        columns=[
            Column("cell", "cell", align="left"),
            Column("printed", "printed", align="left"),
            Column("computed", "computed", "-", 5),
            Column("difference", "printed - computed", "-", 3),
            Column("cause", "likely cause", align="left"),
        ],
        rows=[
            {**r, "difference": "" if r["difference"] is None else r["difference"]} for r in rows
        ],
        notes=(
            f"{len(rows)} of {len(kurochkin_errata.read_cells())} printed cells; the others agree within their "
            "printed rounding. Units: T, F0'·10³, F0j'·10³ [-]; ψ [°]; e [µm] (gap per side).",
            "Exact: the ring equilibrium with P = K = 1 and clearance 2e from eq. (1.13); F0j' by "
            "Gauss-Legendre quadrature over each smooth piece of the half pitch (error < 1e-12).",
        ),
    )


def kurochkin1973_example1_table(steps: int = 15) -> Table:
    """Committed table ``kurochkin1973_example1``: M(φ1) = w P y0 over one pitch (his Fig. 2),
    from :func:`bearingload.papers.kurochkin_errata.example1_moments`. M in N·mm."""
    data = kurochkin_errata.example1_moments(steps)
    gaps_um = kurochkin_errata.EXAMPLE1_GAPS_UM
    keys = [f"M_e{i}" for i in range(len(gaps_um) + len(data["nulls"]))]
    labels = [f"M, e = {e:g} µm" for e in gaps_um]
    labels += [f"M, e = {e:.4f} µm (no harmonic {j})" for j, e in enumerate(data["nulls"], start=1)]
    t_values = ", ".join(
        f"{e:g} µm: {t:.4f}" for e, t in zip(gaps_um, data["parameters"], strict=True)
    )
    return Table(
        title="Kurochkin (1973), Example 1: conservative moment M = w P y0 over one pitch, "
        "bearing A640018, rotating inner ring",
        columns=[Column("cage_angle", "cage angle", "°", 5)]
        + [Column(k, lab, "N·mm", 5) for k, lab in zip(keys, labels, strict=True)],
        rows=data["rows"],
        notes=(
            f"n = 7, D = 10.731 mm, d = 3.969 mm, K = 0.45 kgf/µm^1.5, P = 2.5 kgf; "
            f"w = D/(2(D + d)) = {data['moment_arm']:.5f}. T (eq. 1.13) at e = {t_values}.",
            "The last three columns use the exact gaps at which F01', F02', F03' vanish; the paper "
            "prints 4.164, 4.476, 4.611 µm, read from its Table 3 (kurochkin1973_differences).",
        ),
    )


def compliance_fits_table() -> Table:
    """Committed table ``compliance_fits``: the paper's fits (7), (8) against the exact model."""
    cols = [Column("balls", "z"), Column("pbar_z", "P̄/z", "-", 3)]
    for key, label in (
        ("alpha_ball", "α/S0 at φ1=0"),
        ("alpha_half", "α/S0 at φ1=π/z"),
        ("delta_alpha", "δα/S0"),
    ):
        cols += [
            Column(f"{key}_exact", f"{label} exact", "-", 4),
            Column(f"{key}_fit", f"{label} fit", "-", 4),
            Column(f"{key}_error", f"{label} fit error", "%", 3),
        ]
    return Table(
        title="The compliance abstract fits (7) α/S0 = a (P̄/z)^0.6 (a = 2.855 at φ1 = 0, 2.773 at φ1 = π/z) "
        "and (8) δα/S0 = 0.076 (P̄/z)^0.6 against the exact ring equilibrium",
        columns=cols,
        rows=compliance.fit_rows(),
        notes=(
            "S0 = e = G_r/2 (gap per side); P̄/z = P/(z K S0^1.5); α = (Q_max/K)^(2/3), the elastic "
            "approach of the most loaded ball; δα = α(0) - α(π/z). Error = (fit - exact)/|exact|.",
            "Fit (7) at φ1 = 0 holds within 5 % for 0.1 <= P̄/z <= 3 and any z here (10 % at "
            "P̄/z = 10, 22 % at 100: the exact exponent tends to 2/3). At φ1 = π/z the exact "
            "coefficient depends on z (fit error +22 % at z = 8 against 1 % at z = 16, P̄/z = 0.1).",
            "Fit (8) does not hold: over 0.1 <= P̄/z <= 10 it misses the exact δα/S0 by -89 % to "
            "+21 % and the exact value depends on z; the paper's own coefficients (7) give "
            "2.855 - 2.773 = 0.082, not 0.076.",
        ),
    )


def crane_stiffness_table() -> Table:
    """Committed table ``crane2009_stiffness``: the crane paper's (2009) procedure against the
    exact equilibrium."""
    cols = [
        Column("case", "case", align="left"),
        Column("load", "F_r", "N", 5),
        Column("stiffness", "K", "N/mm^m", 5),
        Column("exponent", "m", "-", 4),
        Column("q0_paper", "Q0 crane paper (20)", "N", 5),
        Column("q_max", "Q_max exact", "N", 5),
        Column("c_paper", "c crane paper (21)", "N/mm", 5),
        Column("tangent", "tangent exact", "N/mm", 5),
        Column("secant", "secant exact", "N/mm", 5),
        Column("paper_over_tangent", "(21)/tangent", "-", 4),
        Column("paper_over_secant", "(21)/secant", "-", 4),
    ]
    return Table(
        title="Radial bearing stiffness: the crane paper's (2009) procedure against the exact equilibrium "
        "(zero clearance, a ball or roller under the load)",
        columns=cols,
        rows=crane_stiffness.comparison_rows(),
        notes=(
            "The crane paper (2009): Q0 = 5 F_r/(i z cos α) (20), Q_j = Q0 cos^m(jγ) (19), c_j = Q_j/δ_j (18), "
            "c = i cos α [c_0 + 2 Σ c_j cos(jγ)] (21), γ = 2π/z (22). Exact: each row carries "
            "F_r/i with radial element stiffness K cos^(m+1) α; tangent dF_r/dx, secant F_r/x.",
            "Why they differ: (a) the factor 5 in (20) is Stribeck's allowance for clearance; at "
            "zero clearance the exact z Q_max/F_r is 4.37 (balls) or 4.08 (rollers) for many "
            "elements, so Q0 is high and every c_j with it; (b) (21) projects each element once "
            "(cos jγ, cos α) where the radial stiffness needs the square of each projection; "
            "(c) (18) is a secant element stiffness, the tangent one is m times larger; (d) the "
            "loads (19) do not balance F_r. The errors partly cancel: for balls with α = 0 (21) "
            "lies between the exact secant and tangent (0.83 of the tangent); at α = 40° and for "
            "rollers it exceeds even the tangent (1.08 and 1.16 times). At zero clearance every "
            "stiffness scales as F_r^((m-1)/m), so the ratios do not depend on the load.",
            "Rollers: Palmgren's line contact per contact, both contacts in series "
            "(bearingload.contact.hertz.roller_stiffness); the roller set is illustrative.",
        ),
    )
