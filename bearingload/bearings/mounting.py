"""The clearance in operation: the catalogue clearance less what the fits and the ring
temperatures take (the clearance every maker's calculator and ISO/TS 16281 solve with).

G_op = G_r - Delta_fit,inner - Delta_fit,outer - Delta_T, each reduction in mm:

* The fits. The interference of the inner ring on the shaft, I_i = shaft - bore, and of the
  outer ring in the housing, I_o = outside diameter - housing bore, from the ISO 286 class of
  each seat and the ISO 492 Normal-class tolerances of the bearing
  (:mod:`bearingload.bearings.tolerances`); a loose fit (I <= 0) changes nothing. Lamé's thick
  rings, all of steel (one modulus), give the growth of the inner raceway and the shrinking of
  the outer one (NSK Rolling Bearings CAT. E1102, section 9.2 "Internal clearance": Delta_fi =
  (d/D_i) Delta_d for a solid shaft; Harris & Kotzalas, Rolling Bearing Analysis, 5th ed.,
  vol. 1, ch. 8 with the hollow shaft):
      Delta_fit,inner = I_i k (1 - k0^2) / (1 - k^2 k0^2),  k = d/F,  k0 = d_0/d
      Delta_fit,outer = I_o h (1 - h0^2) / (1 - h^2 h0^2),  h = E/D,  h0 = D/D_h
  F = d_m - D_w and E = d_m + D_w are the raceway (groove-bottom) diameters, d_0 the bore of a
  hollow shaft (0: solid), D_h the outside diameter of the housing (none: a housing thick
  enough to count as infinite, h0 = 0). The interference is taken whole (no smoothing of the
  seats' roughness), the larger reduction.
* The temperatures. An inner ring (with the balls) warmer than the outer ring by
  Delta_t = t_i - t_o grows against it: Delta_T = alpha Delta_t E, alpha = 12.5e-6 1/K for
  bearing steel (IKO needle roller bearings catalogue, eq. (29): Delta_delta = alpha Delta_t E,
  E the bore diameter of the outer ring, i.e. its raceway). A warmer outer ring gives a
  negative reduction (more clearance). Shaft and housing are taken as steel at their rings'
  temperatures, so the temperatures change no fit.

min and max of the operating clearance are the worst-case stacks: the class minimum less the
largest interferences, the class maximum less the smallest; mean: the class mean less the
interferences of the mean sizes. --clearance-pick chooses one, as it chooses in the class.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass

__all__ = [
    "MOUNTING_PARAMS",
    "RESULT_KEYS",
    "STEEL_EXPANSION",
    "Mounting",
    "MountedClearance",
    "inner_fit_reduction",
    "mount",
    "mounted_clearance",
    "mounting_notes",
    "outer_fit_reduction",
    "result_fields",
    "thermal_reduction",
]

#: The library's (and batch's, and the options') names of the mounting, in help order.
MOUNTING_PARAMS = ("shaft_fit", "housing_fit", "shaft_bore", "housing_diameter",
                   "inner_ring_temperature", "outer_ring_temperature")  # fmt: skip
#: The result fields of a mounted bearing (:meth:`MountedClearance.values`), mm each.
RESULT_KEYS = ("operating_clearance", "clearance_reduction_inner_fit",
               "clearance_reduction_outer_fit", "clearance_reduction_temperature")  # fmt: skip
#: Linear expansion of bearing steel (IKO needle roller bearings catalogue, eq. (29)). [1/K]
STEEL_EXPANSION = 12.5e-6


@dataclass(frozen=True)
class Mounting:
    """How the bearing is mounted: the ISO 286 classes of the seats, a hollow shaft's bore
    [mm], the housing's outside diameter [mm], the rings' temperatures [°C]; None: not given."""

    shaft_fit: str | None = None
    housing_fit: str | None = None
    shaft_bore: float | None = None
    housing_diameter: float | None = None
    inner_ring_temperature: float | None = None
    outer_ring_temperature: float | None = None

    @property
    def given(self) -> bool:
        """True when any of the mounting was given."""
        return any(getattr(self, n) is not None for n in MOUNTING_PARAMS)


@dataclass(frozen=True)
class MountedClearance:
    """The operating clearance and what took it, all in mm (diametral, G_r's convention).

    ``clearance`` is the unmounted clearance (G_r of the class pick or as given);
    ``interference_inner``/``interference_outer`` the effective interferences used (0 for a
    loose fit); ``preloaded``: the mounting leaves no clearance."""

    mounting: Mounting
    pick: str
    clearance: float
    interference_inner: float
    interference_outer: float
    reduction_inner_fit: float
    reduction_outer_fit: float
    reduction_temperature: float
    operating_clearance: float
    sources: tuple[str, ...]

    @property
    def preloaded(self) -> bool:
        """True when the fits and temperatures leave a negative clearance (a preload)."""
        return self.operating_clearance < 0.0

    def values(self) -> dict[str, float]:
        """The result fields: ``operating_clearance`` and the three reductions. [mm]"""
        return {
            "operating_clearance": self.operating_clearance,
            "clearance_reduction_inner_fit": self.reduction_inner_fit,
            "clearance_reduction_outer_fit": self.reduction_outer_fit,
            "clearance_reduction_temperature": self.reduction_temperature,
        }

    def warning(self) -> str | None:
        """The warning of a mounting that leaves the bearing preloaded, else None."""
        if not self.preloaded:
            return None
        return (
            f"the fits and ring temperatures leave the bearing preloaded: operating clearance "
            f"{self.operating_clearance * 1e3:.3g} µm ({self.clearance * 1e3:.3g} µm less "
            f"{self.reduction_inner_fit * 1e3:.3g} µm by the shaft fit, "
            f"{self.reduction_outer_fit * 1e3:.3g} µm by the housing fit, "
            f"{self.reduction_temperature * 1e3:.3g} µm by the temperatures): a radial preload "
            f"of {-self.operating_clearance * 1e3:.3g} µm, solved as such"
        )


def inner_fit_reduction(
    interference: float, bore: float, raceway: float, shaft_bore: float | None = None
) -> float:
    """Growth of the inner raceway diameter F of a ring of bore d pressed on a (hollow) steel
    shaft with the diametral ``interference`` I: I k (1 - k0^2)/(1 - k^2 k0^2), k = d/F,
    k0 = d_0/d; 0 for a loose fit (I <= 0). [mm]

    >>> round(inner_fit_reduction(0.010, 25.0, 30.0), 6)  # solid shaft: I d/F
    0.008333
    """
    if interference <= 0.0:
        return 0.0
    k = bore / raceway
    k0 = 0.0 if shaft_bore is None else shaft_bore / bore
    return interference * k * (1.0 - k0**2) / (1.0 - k**2 * k0**2)


def outer_fit_reduction(
    interference: float, outside: float, raceway: float, housing_diameter: float | None = None
) -> float:
    """Shrinking of the outer raceway diameter E of a ring of outside diameter D pressed into
    a steel housing of outside diameter D_h (None: infinite) with the diametral
    ``interference`` I: I h (1 - h0^2)/(1 - h^2 h0^2), h = E/D, h0 = D/D_h; 0 when loose. [mm]
    """
    if interference <= 0.0:
        return 0.0
    h = raceway / outside
    h0 = 0.0 if housing_diameter is None else outside / housing_diameter
    return interference * h * (1.0 - h0**2) / (1.0 - h**2 * h0**2)


def thermal_reduction(inner: float, outer: float, raceway: float) -> float:
    """alpha (t_i - t_o) E: the clearance an inner ring warmer than the outer one takes, E the
    outer raceway diameter [mm]; temperatures in °C. [mm]

    >>> round(thermal_reduction(50.0, 40.0, 46.0), 6)
    0.00575
    """
    return STEEL_EXPANSION * (inner - outer) * raceway


def check_mounting(m: Mounting) -> Mounting:
    """Refuse what no bearing can be mounted with: a fit class not taken, one ring
    temperature without the other, a temperature outside -60 to 250 °C, a bore or diameter
    that is not a positive length, or given without its fit. Returns the mounting with its
    temperatures as numbers [°C] (a library caller may give them as text: "70C").

    Raises
    ------
    InputError
        Naming the parameter (:data:`MOUNTING_PARAMS`).
    """
    from bearingload.units import parse_temperature

    for name in ("shaft_fit", "housing_fit"):
        fit = getattr(m, name)
        if fit is None:
            continue
        from bearingload.bearings.tolerances import HOUSING_CLASSES, SHAFT_CLASSES

        allowed = SHAFT_CLASSES if name == "shaft_fit" else HOUSING_CLASSES
        if str(fit).strip() not in allowed:
            raise InputError(name, f"unknown ISO 286 class {fit!r}; allowed: {' '.join(allowed)}")
    for name in ("shaft_bore", "housing_diameter"):
        value = getattr(m, name)
        if value is not None and not (math.isfinite(value) and value > 0.0):
            raise InputError(name, f"must be a length greater than 0 mm (got {value!r})")
    for wall, fit in (("shaft_bore", "shaft_fit"), ("housing_diameter", "housing_fit")):
        if getattr(m, wall) is not None and getattr(m, fit) is None:
            raise InputError(wall, f"it changes what the {fit.replace('_', ' ')} takes; without "
                             "one (a loose seat) it would be ignored")  # fmt: skip
    temps = ("inner_ring_temperature", "outer_ring_temperature")
    parsed = {
        name: float(parse_temperature(getattr(m, name), parameter=name))
        for name in temps
        if getattr(m, name) is not None
    }
    given = [n for n in temps if getattr(m, n) is not None]
    if len(given) == 1:
        other = temps[1 - temps.index(given[0])]
        raise InputError(other, "missing: the clearance changes with the difference of the "
                         "rings' temperatures, so give the inner and the outer one together")  # fmt: skip
    return dataclasses.replace(m, **parsed)  # type: ignore[arg-type]


def _geometry(b: Any) -> tuple[float, float, float, float]:
    """(d, D, F, E) of a bearing that can be mounted [mm], else the refusal saying why."""
    if b.contact_angle is not None:
        raise InputError(
            "shaft_fit",
            "an angular-contact bearing has no radial clearance to reduce: its fits and "
            "temperatures change its contact angle, and in a pair its preload, which is not "
            "modelled; give the pair its mounted preload instead",
        )
    sizes = {p.key: p.value for p in b.provenance if p.key in ("d", "D")}
    if b.geometry is not None:
        sizes = {"d": b.geometry.d, "D": b.geometry.D}
    if len(sizes) < 2 or b.ball_diameter is None or b.pitch_diameter is None:
        raise InputError(
            "shaft_fit", "the mounting needs a catalogue bearing: its bore d, outside diameter "
            "D and raceway diameters (d_m -+ D_w)",
        )  # fmt: skip
    dm, dw = b.pitch_diameter, b.ball_diameter
    return float(sizes["d"]), float(sizes["D"]), dm - dw, dm + dw


def _interference(pick: str, low: float, high: float) -> float:
    """The interference of a pick [mm]: the largest for min (the clearance's worst low), the
    smallest for max, the mean sizes' for mean; the stacks of µm limits ``low``, ``high``."""
    return {"min": high, "max": low, "mean": 0.5 * (low + high)}[pick] * 1e-3


def mounted_clearance(b: Any, m: Mounting, clearance: float, pick: str) -> MountedClearance:
    """The operating clearance of bearing ``b`` (a :class:`bearingload.bearings.resolved.
    ResolvedBearing`) mounted as ``m`` from its unmounted ``clearance`` [mm] at ``pick``
    (min, mean, max). See the module for the formulas and sources."""
    m = check_mounting(m)
    d, D, F, E = _geometry(b)
    if m.shaft_bore is not None and not m.shaft_bore < d:
        raise InputError("shaft_bore", f"must be less than the bearing's bore d = {d:g} mm")
    if m.housing_diameter is not None and not m.housing_diameter > D:
        raise InputError("housing_diameter", f"must exceed the bearing's outside diameter D = "
                         f"{D:g} mm")  # fmt: skip
    from bearingload.bearings.tolerances import fit_limits, ring_limits  # only with a fit

    sources: list[str] = []
    i_in = i_out = 0.0
    if m.shaft_fit is not None:
        shaft, bore = fit_limits(m.shaft_fit, d, "shaft_fit"), ring_limits("inner", d)
        i_in = _interference(pick, shaft.lower - bore.upper, shaft.upper - bore.lower)
        sources += [shaft.source, f"bore: {bore.source}"]
    if m.housing_fit is not None:
        hole, od = fit_limits(m.housing_fit, D, "housing_fit"), ring_limits("outer", D)
        i_out = _interference(pick, od.lower - hole.upper, od.upper - hole.lower)
        sources += [hole.source, f"outside diameter: {od.source}"]
    r_in = inner_fit_reduction(i_in, d, F, m.shaft_bore)
    r_out = outer_fit_reduction(i_out, D, E, m.housing_diameter)
    r_t = 0.0
    if m.inner_ring_temperature is not None and m.outer_ring_temperature is not None:
        r_t = thermal_reduction(m.inner_ring_temperature, m.outer_ring_temperature, E)
    return MountedClearance(
        m, pick, clearance, max(i_in, 0.0), max(i_out, 0.0), r_in, r_out, r_t,
        clearance - r_in - r_out - r_t, tuple(sources),
    )  # fmt: skip


def mount(b: Any, m: Mounting | None) -> Any:
    """Bearing ``b`` at its operating clearance: ``clearance`` (what the models solve with)
    becomes the operating clearance, ``mounting`` the :class:`MountedClearance` that holds the
    unmounted one and the reductions; ``b`` itself where ``m`` is None or gives nothing."""
    if m is None or not m.given:
        return b
    unmounted = b.clearance if b.mounting is None else b.mounting.clearance
    mc = mounted_clearance(b, m, unmounted, b.clearance_pick or "mean")
    return dataclasses.replace(b, clearance=mc.operating_clearance, mounting=mc)


def result_fields(b: Any) -> dict[str, float]:
    """A mounted bearing's fields of a result: ``clearance`` the unmounted G_r (as -G gave
    it), ``operating_clearance`` what the solve used, the three reductions [mm]; nothing for a
    bearing as bought."""
    mc = getattr(b, "mounting", None)
    return {} if mc is None else {"clearance": mc.clearance, **mc.values()}


def mounting_notes(b: Any) -> list[str]:
    """The lines that say how the operating clearance was found, for a mounted bearing."""
    mc = getattr(b, "mounting", None)
    if mc is None:
        return []
    m, um = mc.mounting, 1e3
    seats = ", ".join(
        f"{what} {fit}" for what, fit in (("shaft", m.shaft_fit), ("housing", m.housing_fit)) if fit
    )
    temps = ""
    if m.inner_ring_temperature is not None:
        temps = (f"; rings at {m.inner_ring_temperature:g} °C (inner) and "
                 f"{m.outer_ring_temperature:g} °C (outer)")  # fmt: skip
    return [
        f"Operating clearance ({mc.pick}): G_r {mc.clearance * um:.4g} µm less "
        f"{mc.reduction_inner_fit * um:.4g} µm (inner fit, interference "
        f"{mc.interference_inner * um:.4g} µm), {mc.reduction_outer_fit * um:.4g} µm (outer fit, "
        f"interference {mc.interference_outer * um:.4g} µm), {mc.reduction_temperature * um:.4g} "
        f"µm (temperatures) = {mc.operating_clearance * um:.4g} µm, the clearance solved "
        f"({seats or 'no fit'}{temps}; ISO 492 Normal class; Lamé's thick steel rings, "
        "docs/mounting.md).",
    ]
