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
from dataclasses import dataclass

KGF = 9.80665  # N; the same constant as bearingload.units.KGF (kept here to import nothing)


@dataclass(frozen=True)
class Quantity:
    """One quantity.

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

    key: str
    label: str
    unit: str = "-"
    digits: int | None = 6
    display: tuple[str, float] | None = None
    also: tuple[str, float] | None = None

    @property
    def json_key(self) -> str:
        return self.key

    def shown(self) -> tuple[str, float]:
        """(unit, factor) of the human formats."""
        return self.display if self.display is not None else (self.unit, 1.0)


_UM = ("µm", 1e3)

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
        Quantity("clearance_pick", "clearance pick", "", None),
        Quantity("cage_angle_deg", "cage angle", "°"),
        Quantity("exponent", "load-deflection exponent m", "-"),
        # the load distribution
        Quantity("k", "load factor k = Q_max/F_r", "-"),
        Quantity("K_Q", "load concentration K_Q = k z/2", "-"),
        Quantity("q_max", "heaviest ball load Q_max", "N", also=("kgf", 1 / KGF)),
        Quantity("loaded_balls", "balls carrying load", "", None),
        Quantity("load_zone_deg", "load zone half-angle", "°"),
        Quantity("x", "ring displacement along the load x", "mm", display=_UM),
        Quantity("y", "ring displacement across the load y", "mm", display=_UM),
        Quantity("stiffness_radial", "radial stiffness dF_r/dx", "N/mm"),
        Quantity("approach_max", "heaviest ball approach delta_max", "mm", display=_UM),
        Quantity("stiffness_matrix", "tangent stiffness matrix", "N/mm"),
        Quantity("epsilon", "load-zone parameter epsilon", "-"),
        Quantity("iterations", "solver iterations", "", None),
        Quantity("relative_error", "Q_max/Q_max,exact - 1", "-", 3, display=("%", 100.0)),
        Quantity("valid", "inside the model's range", "", None),
        # contact and life (a catalogue bearing)
        Quantity("p_max_inner", "max contact pressure, inner", "MPa"),
        Quantity("p_max_outer", "max contact pressure, outer", "MPa"),
        Quantity("rating_life", "basic rating life L10 = (C/F_r)^3", "10^6 rev"),
        Quantity("allowable_load", "allowable load C/L^(1/3)", "N", also=("kgf", 1 / KGF)),
        Quantity("revolutions", "life L of the allowable load", "10^6 rev"),
        # per ball
        Quantity("ball", "ball", "", None),
        Quantity("ball_angles_deg", "angle", "°"),
        Quantity("ball_approaches", "approach delta", "mm", display=_UM),
        Quantity("ball_loads", "load Q", "N"),
        # studies: work-precision (bearingload accuracy) and stability (bearingload stability)
        Quantity("setting", "setting", "", None),
        Quantity("cases", "cases", "", None),
        Quantity("error_median", "median error", "-", 2),
        Quantity("error_max", "largest error", "-", 2),
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
        Quantity("warnings", "warnings", "", None),
        Quantity("refused", "refused", "", None),
        Quantity("failures", "failures", "", None),
        Quantity("check_value", "check", "-", 3),
        Quantity("check_limit", "limit", "-", 3),
        Quantity("check", "check", "", None),
    )
}


def quantity(key: str) -> Quantity:
    """The quantity of ``key``; a KeyError names the known keys."""
    try:
        return QUANTITIES[key]
    except KeyError:
        raise KeyError(f"unknown quantity {key!r}; known: {', '.join(QUANTITIES)}") from None


def units(keys: Iterable[str], exponent: float | None = None) -> dict[str, str]:
    """The JSON ``units`` object of ``keys`` (those with a unit); ``N/mm^m`` gets ``exponent``."""
    out = {}
    for key in keys:
        q = QUANTITIES.get(key)
        if q is None or q.unit in ("", "-"):
            continue
        unit = q.unit
        if unit == "N/mm^m" and exponent is not None:
            unit = f"N/mm^{exponent:g}"
        out[key] = unit
    return out
