"""The resolved bearing: the record the engine takes (:class:`ResolvedBearing`), the source of
each value (:class:`Provenance`) and the clearance a class resolves to.

Shared by :mod:`bearingload.bearings.resolve` (ball bearings) and
:mod:`bearingload.bearings.resolve_roller` (cylindrical roller bearings), which both build it.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

from bearingload.bearings.catalog import BearingGeometry, LimitingSpeeds
from bearingload.bearings.clearance import _NEEDS_BORE, PICKS, ClearanceSpec, clearance_range
from bearingload.constants import STEEL_MODULUS, STEEL_POISSON
from bearingload.errors import InputError

#: Young's modulus and Poisson's ratio used when none is given (bearingload.constants). [MPa], [-]
DEFAULT_MODULUS = STEEL_MODULUS
DEFAULT_POISSON = STEEL_POISSON


@dataclass(frozen=True)
class Provenance:
    """One input value as used, with its unit and where it came from."""

    key: str
    label: str
    value: float | int | str | None
    unit: str
    source: str


@dataclass(frozen=True)
class ResolvedBearing:
    """Everything the load-distribution engine needs for one bearing, and where it came from.

    Attributes
    ----------
    designation : str or None
        The designation as typed; None for a hand-given ball set.
    geometry : BearingGeometry or None
        The catalogue row with the overrides applied.
    balls : int
        Number of balls z.
    ball_diameter, pitch_diameter : float or None
        D_w and d_m; None when only the stiffness was given. [mm]
    f_i, f_o : float or None
        Groove conformities r / D_w. [-]
    modulus : float
        Young's modulus E of balls and rings; for a hybrid bearing (``ball_material``) the E of
        the one material whose contact with itself has the balls-on-rings E*
        (:func:`bearingload.contact.hertz.equivalent_material`), so every Hertz use of
        (modulus, poisson) is exact; the rings' and balls' own values are in ``provenance``.
        [MPa]
    poisson : float
        Poisson's ratio nu (of that equivalent material for a hybrid). [-]
    stiffness : float
        Ball stiffness K, both contacts in series, Q = K delta^1.5. [N/mm^1.5]
    stiffness_inner, stiffness_outer : float or None
        Hertz stiffness of the inner and outer contact (None without geometry). [N/mm^1.5]
    stiffness_given : bool
        True when K was given rather than computed.
    clearance : float
        Radial internal clearance G_r, total play. [mm]
    clearance_class : str or None
        ISO class the clearance was taken from (``"C3"``), None for a length.
    clearance_range : tuple of float or None
        (min, max) of that class at this bore. [mm]
    clearance_pick : str or None
        ``min``, ``mean`` or ``max`` for a class.
    C, C0 : float or None
        Basic dynamic and static load ratings. [N]
    kind : str
        ``"ball"`` or ``"roller"`` (cylindrical roller bearing).
    exponent : float
        Load-deflection exponent m of Q = K delta^m: 1.5 balls, 10/9 rollers. [-]
    roller_length : float or None
        Effective roller length L_we of a roller bearing. [mm]
    ball_material : str or None
        The balls' material given (``steel``, ``si3n4``; :mod:`bearingload.bearings.
        materials`); None: the balls are of the rings' material.
    ball_density : float or None
        Density of the balls of ``ball_material`` for the ball dynamics (None: bearing
        steel). [kg/m^3]
    provenance : tuple of Provenance
        Every value above with its source, in display order.
    sources : tuple of str
        The long source texts the provenance refers to as, [2] ...
    """

    designation: str | None
    geometry: BearingGeometry | None
    balls: int
    ball_diameter: float | None
    pitch_diameter: float | None
    f_i: float | None
    f_o: float | None
    modulus: float
    poisson: float
    stiffness: float
    stiffness_inner: float | None
    stiffness_outer: float | None
    stiffness_given: bool
    clearance: float
    clearance_class: str | None
    clearance_range: tuple[float, float] | None
    clearance_pick: str | None
    C: float | None
    C0: float | None
    provenance: tuple[Provenance, ...]
    sources: tuple[str, ...]
    kind: str = "ball"
    exponent: float = 1.5
    roller_length: float | None = None
    #: Design contact angle alpha_0 of an angular-contact ball bearing (None: deep groove). [°]
    contact_angle: float | None = None
    ball_material: str | None = None
    ball_density: float | None = None
    #: The mounting (:class:`bearingload.bearings.mounting.MountedClearance`): where given,
    #: ``clearance`` is the operating clearance and this holds the unmounted one. None: as bought.
    mounting: Any = None

    @property
    def has_geometry(self) -> bool:
        """True when D_w, d_m, f_i, f_o are known (Hertz pressures can be computed)."""
        return None not in (self.ball_diameter, self.pitch_diameter, self.f_i, self.f_o)

    @property
    def limiting_speeds(self) -> LimitingSpeeds | None:
        """The limiting speeds (grease, oil [r/min], source) of the catalogue row, None where
        the catalogue gives none (a ring given by hand, a row without them, a sealed bearing:
        above its open bearing's ``geometry.open_limiting_speeds`` it is past its own limit):
        :attr:`bearingload.bearings.catalog.BearingGeometry.limiting_speeds`."""
        return getattr(self.geometry, "limiting_speeds", None)

    def with_clearance(self, pick: str) -> ResolvedBearing:
        """The same bearing at the ``min``, ``mean`` or ``max`` of its clearance class.

        Raises
        ------
        InputError
            (parameter ``pick``) when the clearance was given as a length, or the pick is unknown.
        """
        if pick not in PICKS:
            raise InputError("pick", f"unknown pick {pick!r}; allowed: {', '.join(PICKS)}")
        if self.clearance_range is None:
            raise InputError(
                "pick",
                f"{pick!r} needs a clearance class (C2 CN C3 C4 C5), not a clearance length",
            )
        low, high = self.clearance_range
        value = {"min": low, "mean": 0.5 * (low + high), "max": high}[pick]
        prov = tuple(
            dataclasses.replace(p, value=value * 1e3, source=_class_source(self, pick))
            if p.key == "clearance"
            else p
            for p in self.provenance
        )
        b = dataclasses.replace(
            self, clearance=value, clearance_pick=pick, provenance=prov, mounting=None
        )
        if self.mounting is None:
            return b
        from bearingload.bearings.mounting import mount

        return mount(b, self.mounting.mounting)

    def with_dynamic_rating(self, rating: float) -> ResolvedBearing:
        """The same bearing with its basic dynamic load rating C replaced by a given one. [N]"""
        _check_rating("dynamic_rating", rating)
        given = Provenance("C", "dynamic load rating C", rating, "N", "given")
        prov = tuple(given if p.key == "C" else p for p in self.provenance)
        if given not in prov:
            prov += (given,)
        return dataclasses.replace(self, C=rating, provenance=prov)

    def with_static_rating(self, rating: float) -> ResolvedBearing:
        """The same bearing with its basic static load rating C0 replaced by a given one (the
        static safety and ISO 281's C_u estimate use it; no ball load changes). [N]"""
        _check_rating("static_rating", rating)
        given = Provenance("C0", "static load rating C0", rating, "N", "given")
        prov = tuple(given if p.key == "C0" else p for p in self.provenance)
        if given not in prov:
            prov += (given,)
        return dataclasses.replace(self, C0=rating, provenance=prov)


#: The largest load rating taken: beyond those of the largest slewing bearings made (about 1e8
#: N); a larger number is a unit slip, and a ratio of it would overflow. [N]
RATING_MAX = 1e9


def _check_rating(name: str, rating: float) -> None:
    if not 0.0 < rating <= RATING_MAX:
        raise InputError(name, f"must lie between 0 and {RATING_MAX:g} N (got {rating:g} N)")


def _class_source(b: ResolvedBearing, pick: str) -> str:
    """The clearance source text of ``b`` with its pick replaced."""
    old = next(p.source for p in b.provenance if p.key == "clearance")
    head, _, _ = old.rpartition(", ")
    return f"{head}, {pick} (clearance table)"


def resolve_clearance(
    spec: ClearanceSpec | None,
    geom: Any,
    bore: float | None,
    pick: str,
    kind: str = "ball",
) -> tuple[float, str | None, tuple[float, float] | None, str | None, str]:
    """G_r [mm], class, class range [mm], pick and a source text; ``geom``: a catalogue row
    with its ``parsed`` designation (ball or roller), or None; ``kind``: whose table."""
    if spec is not None and spec.length is not None:
        return spec.length, None, None, None, "given"
    if spec is None:
        if geom is None:
            return 0.0, None, None, None, "default: zero clearance (no catalogue row)"
        cls = geom.parsed.clearance_class or "CN"
        how = (
            f"class {cls} marked in the designation"
            if geom.parsed.clearance_class
            else "no class marked in the designation: CN (normal)"
        )
    else:
        cls = spec.cls or "CN"
        how = f"class {cls}"
    if bore is None:
        raise InputError("clearance", _NEEDS_BORE.format(spec.text if spec else cls))
    low, high = clearance_range(bore, cls, kind)
    value = {"min": low, "mean": 0.5 * (low + high), "max": high}[pick]
    from bearingload.bearings.clearance import table_name

    source = (
        f"{how}; {table_name(bore, kind)}{'' if kind == 'ball' else ' (cylindrical roller bearings)'} {cls} "
        f"{low * 1e3:g}-{high * 1e3:g} µm at d = {bore:g} mm, {pick} "
        "(clearance table)"
    )
    return value, cls, (low, high), pick, source


def clearance_row_source(bore: float | None, kind: str = "ball") -> str:
    from bearingload.bearings.clearance import table

    for row in table(kind):
        if bore is not None and row.bore_over < bore <= row.bore_incl:
            return f"clearance table (bore over {row.bore_over:g} incl {row.bore_incl:g} mm): {row.source}"
    return "clearance table"  # pragma: no cover - clearance_range raised before
