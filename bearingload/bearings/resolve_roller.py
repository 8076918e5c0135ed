"""Resolve a cylindrical roller bearing (``NU206``) for the load-distribution engine.

Geometry from :mod:`bearingload.bearings.rollers` (each value replaceable), the roller
stiffness of Palmgren's line contact (:func:`bearingload.contact.hertz.roller_stiffness`,
Q = K delta^(10/9), both contacts of the effective length L_we in series), exponent 10/9, and the
radial clearance G_r given as a length or an ISO 5753-1 class of cylindrical roller bearings with
a cylindrical bore (:func:`bearingload.bearings.clearance.clearance_range`, ``kind="roller"``);
by default the class the designation marks, else CN.

>>> b = resolve_roller("NU206")
>>> b.balls, b.exponent == 10 / 9, round(b.stiffness, -2)
(13, True, 257600.0)
>>> b.clearance_class, round(b.clearance * 1e3, 3)  # CN 20-45 µm at d = 30 mm, mean [µm]
('CN', 32.5)
"""

from __future__ import annotations

from bearingload.bearings.clearance import ClearanceSpec, parse_clearance
from bearingload.bearings.resolved import (
    DEFAULT_MODULUS,
    DEFAULT_POISSON,
    Provenance,
    ResolvedBearing,
    clearance_row_source,
    resolve_clearance,
)
from bearingload.bearings.rollers import RollerGeometry
from bearingload.errors import InputError
from bearingload.validate import finite_positive


def resolve_roller(
    designation: str,
    *,
    rollers: int | None = None,
    roller_diameter: float | None = None,
    pitch_diameter: float | None = None,
    roller_length: float | None = None,
    modulus: float | None = None,
    poisson: float | None = None,
    stiffness: float | None = None,
    clearance: str | float | ClearanceSpec | None = None,
    clearance_pick: str = "mean",
) -> ResolvedBearing:
    """Resolve a cylindrical roller bearing: rollers, K [N/mm^(10/9)], G_r and their sources.

    Parameters
    ----------
    designation : str
        ``NU206``, ``N 306 ECP``, ``NJ210`` ...
    rollers : int, optional
        z, replacing the catalogue's.
    roller_diameter, pitch_diameter, roller_length : float, optional
        D_w, d_m, L_we replacing the catalogue's. [mm]
    modulus : float, optional
        Young's modulus, used for the contact pressures only (Palmgren's stiffness is for
        steel); default 208 000. [MPa]
    poisson : float, optional
        Poisson's ratio; default 0.3. [-]
    stiffness : float, optional
        Roller stiffness K replacing Palmgren's. [N/mm^(10/9)]
    clearance : str, float or ClearanceSpec, optional
        G_r as a length (float [mm] or text with a unit) or a class ``C2 CN C3 C4 C5``; default
        the class the designation marks, else CN (ISO 5753-1, cylindrical roller bearings).
    clearance_pick : {"mean", "min", "max"}
        Where in a class's range G_r is taken. [-]

    Returns
    -------
    ResolvedBearing
        ``kind`` ``"roller"``, ``exponent`` 10/9, ``balls`` = z, ``ball_diameter`` = D_w,
        ``roller_length`` = L_we, ``f_i``/``f_o`` None.

    Raises
    ------
    InputError
        Unknown designation, impossible overrides, a bore outside the clearance table
        (``bore``), a clearance of half the roller diameter or more (``clearance``).
    """
    from bearingload.bearings.rollers import lookup
    from bearingload.contact.hertz import LINE_EXPONENT, palmgren_line_stiffness, roller_stiffness

    if stiffness is not None:
        finite_positive("stiffness", stiffness)
    row = lookup(
        designation,
        rollers=rollers,
        roller_diameter=roller_diameter,
        pitch_diameter=pitch_diameter,
        roller_length=roller_length,
    )
    spec = clearance if isinstance(clearance, ClearanceSpec) else parse_clearance(clearance)
    g_r, cls, rng, pick, g_src = resolve_clearance(spec, row, row.d, clearance_pick, "roller")
    if abs(g_r) >= row.roller_diameter / 2:
        raise InputError(
            "clearance",
            f"G_r = {g_r:g} mm is at least half the roller diameter; a bare number is mm",
        )
    k_contact = float(palmgren_line_stiffness(row.roller_length))
    k = float(stiffness) if stiffness is not None else float(roller_stiffness(row.roller_length))
    prov = _provenance(row, k_contact, k, stiffness is not None, g_src, g_r)
    sources = [f"catalogue row {row.designation}: {row.source}", f"catalogue notes: {row.notes}"]
    if rng is not None:
        sources.append(clearance_row_source(row.d, "roller"))
    return ResolvedBearing(
        designation=designation,
        geometry=None,
        balls=row.rollers,
        ball_diameter=row.roller_diameter,
        pitch_diameter=row.pitch_diameter,
        f_i=None,
        f_o=None,
        modulus=DEFAULT_MODULUS if modulus is None else float(modulus),
        poisson=DEFAULT_POISSON if poisson is None else float(poisson),
        stiffness=k,
        stiffness_inner=k_contact,
        stiffness_outer=k_contact,
        stiffness_given=stiffness is not None,
        clearance=g_r,
        clearance_class=cls,
        clearance_range=rng,
        clearance_pick=pick,
        C=row.C,
        C0=row.C0,
        provenance=prov,
        sources=tuple(sources),
        kind="roller",
        exponent=LINE_EXPONENT,
        roller_length=row.roller_length,
    )


def _provenance(
    row: RollerGeometry, k_contact: float, k: float, k_given: bool, g_src: str, g_r: float
) -> tuple[Provenance, ...]:
    """Every value of a resolved roller bearing with its unit and source."""
    over = set(row.overrides)

    def src(field: str, default: str) -> str:
        return "given (override)" if field in over else default

    z_src = "catalogue: " + ("read (dataset)" if row.method == "read z" else "derived, flagged")
    return (
        Provenance("d", "bore d", row.d, "mm", "catalogue"),
        Provenance("D", "outside diameter D", row.D, "mm", "catalogue"),
        Provenance("balls", "rollers z", row.rollers, "", src("rollers", z_src)),
        Provenance(
            "ball_diameter", "roller diameter D_w", row.roller_diameter, "mm",
            src("roller_diameter", "catalogue: (E - F)/2, exact"),
        ),
        Provenance(
            "pitch_diameter", "pitch diameter d_m", row.pitch_diameter, "mm",
            src("pitch_diameter", "catalogue: (E + F)/2, exact"),
        ),
        Provenance(
            "roller_length", "effective roller length L_we", row.roller_length, "mm",
            src("roller_length", "catalogue: derived from C0 (ISO 76), flagged"),
        ),
        Provenance("stiffness_inner", "inner contact K_i", k_contact, "N/mm^(10/9)", "Palmgren"),
        Provenance("stiffness_outer", "outer contact K_o", k_contact, "N/mm^(10/9)", "Palmgren"),
        Provenance(
            "stiffness", "roller stiffness K (series)", k, "N/mm^(10/9)",
            "given" if k_given else "Palmgren line contact, both contacts in series",
        ),
        Provenance(
            "clearance", "radial clearance G_r (total)", g_r * 1e3, "µm",
            g_src,
        ),
        Provenance("C", "dynamic load rating C", row.C, "N", "catalogue: SKF"),
        Provenance("C0", "static load rating C0", row.C0, "N", "catalogue: SKF"),
    )  # fmt: skip
