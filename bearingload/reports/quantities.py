"""The one table of quantities: key, label, unit, display digits, JSON key.

Every report names a quantity through this table, so one quantity has one label, one unit and one
JSON key (and csv column) in every command, model and format. Machine formats (csv, json) carry
the machine ``unit``; the terminal may show a quantity in its ``display`` unit (µm instead of mm)
and add an ``also`` line in a second unit (kgf beside N).

Adding a quantity: one line in :data:`QUANTITIES`; the key is also the JSON key and the csv
column stem (``q_max [N]``). Imports nothing heavy: the command line reads it at start-up.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from bearingload.constants import KGF, ROLLER_EXPONENT
from bearingload.reports.render import Column


class Quantity:
    """One quantity (a plain class, read by attribute only: some two hundred are built at
    import, where a dataclass would also compile its methods).

    Attributes
    ----------
    key : str
        JSON key and csv column stem; the name of the attribute in the library results.
    label : str
        What people read in the terminal and Markdown tables.
    unit : str
        Unit of the value in the library and in csv/json (``-`` dimensionless, ``""`` a count
        or text).
    digits : int or None
        Significant digits in the human formats (``None``: integers and text).
    display : tuple of (unit, factor) or None
        Unit shown in the human formats and the factor from ``unit`` to it.
    also : tuple of (unit, factor) or None
        A second unit shown on an extra line of the human summary (``Q_max`` in kgf).
    """

    __slots__ = ("key", "label", "unit", "digits", "display", "also")

    def __init__(
        self,
        key: str,
        label: str,
        unit: str = "-",
        digits: int | None = 6,
        display: tuple[str, float] | None = None,
        also: tuple[str, float] | None = None,
    ) -> None:
        self.key = key
        self.label = label
        self.unit = unit
        self.digits = digits
        self.display = display
        self.also = also

    def shown(self) -> tuple[str, float]:
        """(unit, factor) of the human formats."""
        return self.display if self.display is not None else (self.unit, 1.0)


_UM = ("µm", 1e3)
#: Relative errors and differences: a fraction [-] in csv and json, % in the human formats.
_PERCENT = ("%", 100.0)
_MRAD = ("mrad", 1000.0 * 3.141592653589793 / 180.0)

#: Every quantity a report prints, in the order columns appear.
QUANTITIES: dict[str, Quantity] = {
    q.key: q
    for q in (
        # the case: inputs
        Quantity("bearing", "bearing", "", None),
        Quantity("method", "method", "", None),
        Quantity("balls", "balls z", "", None),
        Quantity("load", "radial load F_r", "N", also=("kgf", 1 / KGF)),
        Quantity("stiffness", "ball stiffness K", "N/mm^m"),
        Quantity("clearance", "radial clearance G_r", "mm", display=_UM),
        Quantity("operating_clearance", "operating clearance G_op (solved)", "mm", display=_UM),
        Quantity(
            "clearance_reduction_inner_fit", "clearance taken by the shaft fit", "mm", display=_UM
        ),
        Quantity(
            "clearance_reduction_outer_fit", "clearance taken by the housing fit", "mm", display=_UM
        ),
        Quantity(
            "clearance_reduction_temperature",
            "clearance taken by the temperatures",
            "mm",
            display=_UM,
        ),
        Quantity("clearance_pick", "clearance pick", "", None),
        Quantity("cage_angle", "cage angle", "°"),
        Quantity("exponent", "load-deflection exponent m", "-"),
        # the load distribution
        Quantity("k", "load factor k = Q_max/F_r", "-"),
        Quantity("K_Q", "load concentration K_Q = k z/2", "-"),
        Quantity("q_max", "heaviest ball load Q_max", "N", also=("kgf", 1 / KGF)),
        Quantity("loaded_balls", "balls carrying load", "", None),
        Quantity("load_zone", "load zone half-angle", "°"),
        Quantity("x", "ring displacement along the load x", "mm", display=_UM),
        Quantity("y", "ring displacement across the load y", "mm", display=_UM),
        Quantity("stiffness_radial", "radial stiffness dF_r/dx", "N/mm"),
        Quantity("approach_max", "heaviest ball approach delta_max", "mm", display=_UM),
        Quantity("stiffness_axial", "axial stiffness dF_a/d(axial)", "N/mm"),
        Quantity("stiffness_tilt", "tilting stiffness dM/d(tilt)", "N mm/rad"),
        Quantity("stiffness_matrix", "tangent stiffness matrix", "N/mm"),
        Quantity("stiffness_matrix_symmetric", "symmetric part of the stiffness matrix", "N/mm"),
        Quantity("q_max_ball", "ball carrying Q_max", "", None),
        Quantity("epsilon", "load-zone parameter epsilon", "-"),
        Quantity("iterations", "solver iterations", "", None),
        Quantity("relative_error", "Q_max/Q_max,exact - 1", "-", 3, display=_PERCENT),
        Quantity("valid", "inside the model's range", "", None),
        Quantity("warnings", "warnings (bearingload.bearings.checks)", "", None),
        # a cage sweep (bearingload sweep)
        Quantity("steps", "cage positions over one pitch", "", None),
        Quantity("ripple_per_cage_revolution", "ripple frequency", "1/rev", None),
        Quantity("compensating_clearance", "compensating clearance G_r", "mm", display=_UM),
        # Kurochkin's dimensionless sweep (bearingload sweep --kurochkin-T), P = K = 1
        Quantity("kurochkin_T", "generalised parameter T (Kurochkin eq. 1.13)", "-"),
        Quantity("F0", "F0 = x0 (K/P)^(2/3)", "-"),
        Quantity("F0_prime", "F0' = -y0 (K/P)^(2/3)", "-"),
        Quantity("contact_sequence", "contact sequence (loaded balls over a pitch)", "", None),
        Quantity("exit_angle", "exit angle psi", "°"),
        Quantity("F0j_prime", "Fourier sine coefficients F0j' (j = 1-5)", "-"),
        # contact and life (a catalogue bearing)
        Quantity("p_max_inner", "max contact pressure, inner", "MPa"),
        Quantity("p_max_outer", "max contact pressure, outer", "MPa"),
        Quantity("static_equivalent_load", "static equivalent load P0 (ISO 76)", "N"),
        Quantity("static_safety", "static safety factor s0 = C0/P0 (ISO 76)", "-"),
        Quantity("rating_life", "basic rating life L10 = (C/P)^p", "10^6 rev"),
        Quantity("allowable_load", "allowable load C/L^(1/p)", "N", also=("kgf", 1 / KGF)),
        Quantity("revolutions", "life L of the allowable load", "10^6 rev"),
        # published vs computed (bearingload errata); "computed" and "difference" are in the unit
        # of the row ("unit"), the printed value is text as printed
        Quantity("source", "paper", "", None),
        Quantity("table", "table / eq. / section", "", None),
        Quantity("cell", "cell", "", None),
        Quantity("unit", "unit", "", None),
        Quantity("printed", "printed", "", None),
        Quantity("computed", "computed", "", 6),
        Quantity("difference", "difference (printed - computed)", "", 3),
        Quantity("relative_difference", "relative difference", "-", 3, display=_PERCENT),
        Quantity("verdict", "verdict", "", None),
        Quantity("cause", "cause", "", None),
        Quantity("checked", "printed numbers checked", "", None),
        Quantity("agree", "agree", "", None),
        Quantity("differ", "differ", "", None),
        # combined load of a deep-groove ball bearing (models.combined, bearings.iso16281)
        Quantity("axial_load", "axial load F_a", "N", also=("kgf", 1 / KGF)),
        Quantity("moment", "moment M in the load plane", "N mm"),
        Quantity("moment_cross", "moment M_cross about the load line", "N mm"),
        Quantity("misalignment", "imposed misalignment", "°", also=_MRAD),
        Quantity("tilt_radius", "lever of the tilt (radius of the tilted groove centres)", "mm"),
        Quantity("rotating", "rotating ring", "", None),
        Quantity("contact_angle", "design contact angle (angular contact)", "°"),
        # a pair of angular-contact bearings (docs/angular_contact.md)
        Quantity("arrangement", "arrangement of the pair (DB, DF, DT)", "", None),
        Quantity("preload", "preload F_p (each bearing, no external load)", "N"),
        Quantity("width", "width B of one bearing", "mm"),
        Quantity("bearing_number", "bearing of the pair", "", None),
        Quantity("lift_off_axial_load", "lift-off: axial load unloading a bearing", "N"),
        Quantity("preload_at_speed", "preload at the speed (each bearing, no external load)", "N"),
        Quantity("unloaded_bearings", "bearings carrying no load", "", None),
        Quantity("free_contact_angle", "free contact angle alpha_0", "°"),
        Quantity("axial_play", "axial play", "mm", display=_UM),
        Quantity("axial", "axial displacement from centred rings", "mm", display=_UM),
        Quantity("tilt", "tilt about the axis across the load", "°", also=_MRAD),
        Quantity("tilt_cross", "tilt about the load line", "°", also=_MRAD),
        Quantity("contact_angle_max", "largest contact angle of a loaded ball", "°"),
        Quantity("dynamic_rating", "dynamic load rating C_r", "N"),
        Quantity("equivalent_load", "equivalent load P = X F_r + Y F_a (ISO 281)", "N"),
        Quantity("reference_rating_life", "reference rating life L10r (ISO/TS 16281)", "10^6 rev"),
        Quantity("relative_life", "L10r over L10r at G_r = 0", "-", 4),
        # lives as engineers use them (bearings.service_life: ISO 281, ISO/TS 16281, EHL film)
        Quantity("static_rating", "basic static load rating C_0", "N"),
        Quantity("speed", "shaft speed n", "rpm"),
        # defect frequencies at the speed (bearings.frequencies), heaviest ball's contact angles
        Quantity("cage_frequency", "cage frequency FTF", "Hz"),
        Quantity("ball_pass_frequency_outer", "ball pass frequency, outer ring BPFO", "Hz"),
        Quantity("ball_pass_frequency_inner", "ball pass frequency, inner ring BPFI", "Hz"),
        Quantity("ball_spin_frequency", "ball spin frequency BSF", "Hz"),
        Quantity("ball_density", "ball density rho (ball dynamics at speed)", "kg/m^3"),
        Quantity("rating_life_hours", "basic rating life L10h", "h"),
        Quantity("reference_rating_life_hours", "reference rating life L10rh", "h"),
        Quantity("reliability", "reliability", "%", 4),
        Quantity("reliability_factor", "life factor for reliability a_1 (ISO 281)", "-", 4),
        # the oil that gives nu at its temperature (bearings.oil; batch writes them as given)
        Quantity("oil", "ISO 3448 grade of the oil", "", None),
        Quantity("viscosity_40", "viscosity of the oil at 40 °C nu_40", "mm^2/s"),
        Quantity("viscosity_100", "viscosity of the oil at 100 °C nu_100", "mm^2/s"),
        Quantity("viscosity_index", "viscosity index VI of the oil (ASTM D2270)", "-", 4),
        Quantity("temperature", "operating temperature of the oil", "°C", 4),
        Quantity("viscosity", "operating viscosity nu", "mm^2/s"),
        Quantity("rated_viscosity", "rated viscosity nu_1 (ISO 281)", "mm^2/s"),
        Quantity("kappa", "viscosity ratio kappa = nu/nu_1", "-", 4),
        Quantity("contamination_factor", "contamination factor e_C (ISO 281)", "-", 3),
        Quantity("fatigue_load_limit", "fatigue load limit C_u", "N"),
        Quantity("a_iso", "life modification factor a_ISO (ISO 281)", "-", 4),
        Quantity("modified_rating_life", "modified rating life L_nm = a_1 a_ISO L10", "10^6 rev"),
        Quantity("modified_rating_life_hours", "modified rating life L_nmh", "h"),
        Quantity(
            "reference_equivalent_load", "reference equivalent load P_ref = C/L10r^(1/p)", "N"
        ),
        Quantity("a_iso_reference", "a_ISO at P_ref (ISO/TS 16281)", "-", 4),
        Quantity(
            "modified_reference_rating_life",
            "modified reference rating life L_nmr = a_1 a_ISO L10r",
            "10^6 rev",
        ),
        Quantity("modified_reference_rating_life_hours", "modified reference life L_nmrh", "h"),
        Quantity(
            "film_thickness", "minimum film thickness h_min, heaviest contact", "mm", display=_UM
        ),  # fmt: skip
        Quantity("roughness", "composite roughness sigma", "mm", display=_UM),
        Quantity("film_ratio", "film ratio h_min/sigma", "-", 4),
        # per ball
        Quantity("ball", "ball", "", None),
        Quantity("row", "row", "", None),  # bearingload batch: the input file's row (header: 1)
        Quantity("ball_angles", "angle", "°"),
        Quantity("ball_approaches", "approach delta", "mm", display=_UM),
        Quantity("ball_loads", "load Q", "N"),
        Quantity("contact_angles", "contact angle", "°"),
        # per ball, inner and outer contact (they differ with the ball dynamics at speed)
        Quantity("contact_angles_inner", "inner contact angle", "°"),
        Quantity("contact_angles_outer", "outer contact angle", "°"),
        Quantity("ball_loads_inner", "inner load Q_i", "N"),
        Quantity("ball_loads_outer", "outer load Q_o", "N"),
        # studies: work-precision (bearingload accuracy) and stability (bearingload stability)
        Quantity("setting", "setting", "", None),
        Quantity("cases", "cases", "", None),
        Quantity("error_median", "median error", "-", 2, display=_PERCENT),
        Quantity("error_max", "largest error", "-", 2, display=_PERCENT),
        Quantity("seconds_per_case", "time per case, one per call", "s", 3),
        Quantity("seconds_per_case_vectorised", "time per case, vectorised", "s", 3),
        Quantity("family", "family", "", None),
        Quantity("parameter", "parameter", "", None),
        Quantity("max_residual", "max residual", "-", 2),
        Quantity("max_jump", "max jump", "-", 2),
        Quantity("jump_at", "jump at", "-", 2),
        Quantity("batch_dependence", "batch dep.", "-", 2),
        Quantity("max_iterations", "max it.", "", None),
        Quantity("nan", "NaN/inf", "", None),
        Quantity("warnings_raised", "warnings raised", "", None),
        Quantity("refused", "refused", "", None),
        Quantity("failures", "failures", "", None),
        Quantity("check_value", "check", "-", 3),
        Quantity("check_limit", "limit", "-", 3),
        Quantity("check", "check", "", None),
        Quantity("residual_radial", "residual F_r", "-", 2),
        Quantity("residual_cross", "residual F_y", "-", 2),
        Quantity("residual_axial", "residual F_a", "-", 2),
        Quantity("residual_moment", "residual M", "-", 2),
        Quantity("residual_moment_cross", "residual M_c", "-", 2),
        Quantity("refusal_reasons", "refusal reasons", "", None),
        Quantity("failure_reasons", "failure reasons", "", None),
    )
}


#: The life quantities of :func:`bearingload.bearings.service_life.service_values` after the
#: basic lives, in the order the reports show them.
SERVICE_KEYS = (
    "speed",
    "cage_frequency",
    "ball_pass_frequency_outer",
    "ball_pass_frequency_inner",
    "ball_spin_frequency",
    "reliability",
    "reliability_factor",
    "viscosity",
    "rated_viscosity",
    "kappa",
    "contamination_factor",
    "fatigue_load_limit",
    "a_iso",
    "modified_rating_life",
    "modified_rating_life_hours",
    "reference_equivalent_load",
    "a_iso_reference",
    "modified_reference_rating_life",
    "modified_reference_rating_life_hours",
    "film_thickness",
    "roughness",
    "film_ratio",
)


#: The units of the 5x5 ``stiffness_matrix`` (json's ``units`` of it in every engine's document).
MATRIX_UNITS = (
    "rows F_x, F_y, F_a [N], M, M_c [N mm]; columns x, y, axial [mm], tilt, tilt_cross [rad]: "
    "N/mm, N/rad, N mm/mm, N mm/rad"
)


def _matrix_quantities() -> list[Quantity]:
    from bearingload.studies.matrix import MATRIX_COLUMNS, MATRIX_ROWS, matrix_key

    out = []
    for i, (force, f_unit) in enumerate(MATRIX_ROWS):
        for j, (move, m_unit) in enumerate(MATRIX_COLUMNS):
            label = f"stiffness d{force}/d({move})"
            out.append(Quantity(matrix_key(i, j), label, f"{f_unit}/{m_unit}"))
    return out


QUANTITIES |= {q.key: q for q in _matrix_quantities()}


#: Quantities without a unit or digits that are numbers all the same (counts, a ball's number,
#: a number as printed): set to the right as every number is; the other ones are text (left).
COUNTS = frozenset(
    "balls loaded_balls ball q_max_ball iterations row cases max_iterations nan warnings_raised "
    "refused failures printed checked agree differ".split()
)


def column(
    key: str,
    exponent: float | None = None,
    header: str | None = None,
    *,
    name: str | None = None,
    shown: bool = False,
) -> Column:
    """The renderer column of quantity ``key``: its label (or ``header``), machine unit
    (``N/mm^m`` with the ``exponent``) and digits, text to the left, numbers to the right;
    ``name`` the rows' key (default ``key``); ``shown``: the human formats show the number in
    the quantity's display unit (µm, %), csv and json keep the machine unit."""
    q = QUANTITIES[key]
    unit = q.unit.replace("^m", f"^{exponent:g}") if exponent is not None else q.unit
    text = q.digits is None and q.unit == "" and key not in COUNTS
    display = q.display if shown else None
    return Column(
        name or key, header or q.label, unit, q.digits, "left" if text else "right", display
    )


def units(keys: Iterable[str], exponent: float | None = None) -> dict[str, str]:
    """The JSON ``units`` object of ``keys``: the unit of every measured quantity, ``-`` for a
    dimensionless one (k, K_Q, epsilon, s0, m); counts (balls), text and flags (unit ``""``) are
    not listed. The one rule of every JSON document (as batch and the tables write their
    columns' units); ``N/mm^m`` gets ``exponent``."""
    out = {}
    for key in keys:
        q = QUANTITIES.get(key)
        if q is None or q.unit == "":
            continue
        unit = q.unit
        if unit == "N/mm^m" and exponent is not None:
            unit = f"N/mm^{exponent:g}"
        out[key] = unit
    return out


def element_words(text: str, exponent: float) -> str:
    """A human label written for the rolling elements of the exponent: under line contact
    (m = 10/9, cylindrical rollers) 'ball(s)' reads 'roller(s)'; otherwise ``text`` as it is.

    Labels only: csv columns and JSON keys (``q_max_ball``, ``loaded_balls``) stay the same for
    every bearing.

    Parameters
    ----------
    text : str
        A label, title or header.
    exponent : float
        Load-deflection exponent m of the case. [-]

    Examples
    --------
    >>> element_words("Ball loads (ball 1 at the cage angle)", 10 / 9)
    'Roller loads (roller 1 at the cage angle)'
    >>> element_words("balls carrying load", 1.5)
    'balls carrying load'
    """
    if abs(float(exponent) - ROLLER_EXPONENT) > 1e-12:
        return text
    import re

    return re.sub(
        r"\b([Bb])all(s?)\b", lambda m: f"{'Rr'[m.group(1) == 'b']}oller{m.group(2)}", text
    )


def for_elements(table: Any, exponent: float, notes: bool = False) -> Any:
    """A :class:`bearingload.reports.render.Table` with its title, column headers and
    ``quantity`` cells (and, with ``notes``, its notes) written by :func:`element_words`."""
    import dataclasses

    if abs(float(exponent) - ROLLER_EXPONENT) > 1e-12:
        return table

    def words(text: str) -> str:
        return element_words(text, exponent)

    rows = [
        r | {"quantity": words(r["quantity"])} if isinstance(r.get("quantity"), str) else r
        for r in table.rows
    ]
    return dataclasses.replace(
        table,
        title=words(table.title),
        columns=[dataclasses.replace(c, header=words(c.header)) for c in table.columns],
        rows=rows,
        notes=[words(n) for n in table.notes] if notes else table.notes,
    )
