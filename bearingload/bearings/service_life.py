"""The lives an engineer asks for, from one solved case: hours, reliability, a_ISO, the film.

:func:`service_values` takes the operating conditions (:class:`Operating`: speed, reliability,
lubricant, contamination, roughness) and what a solved case knows (:class:`LifeBasis`: ratings,
equivalent load, L10, L10r, the heaviest contact and its geometry) and gives every quantity the
given inputs make meaningful, under the keys of :mod:`bearingload.reports.quantities`: no hours
without a speed, no a_ISO without a viscosity. The formulas are those of
:mod:`bearingload.bearings.modified_life` (ISO 281:2007) and
:mod:`bearingload.bearings.lubrication` (ISO 281 nu_1; Hamrock-Dowson, Dowson-Higginson).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from bearingload.bearings import lubrication as lub
from bearingload.bearings import modified_life as ml
from bearingload.constants import BALL_LIFE_EXPONENT, ROLLER_LIFE_EXPONENT
from bearingload.errors import InputError


@dataclass(frozen=True)
class Operating:
    """Operating conditions; None where not given.

    Attributes
    ----------
    speed : float or None
        Shaft speed n of the rotating ring. [r/min]
    reliability : float or None
        Wanted reliability R, 90 ... 99.95. [%]
    viscosity : float or None
        Operating kinematic viscosity nu of the lubricant. [mm^2/s]
    contamination : str or None
        Level of ISO 281 Table 13 (:data:`bearingload.bearings.modified_life.CONTAMINATION_RANGES`).
    e_c : float or None
        Contamination factor e_C, 0 ... 1, instead of a level. [-]
    fatigue_load_limit : float or None
        C_u, instead of ISO 281's estimate from C_0. [N]
    roughness : float or None
        Composite rms roughness sigma = sqrt(sigma_1^2 + sigma_2^2) of the surfaces. [mm]
    pressure_viscosity : float
        alpha of the lubricant. [1/Pa]
    """

    speed: float | None = None
    reliability: float | None = None
    viscosity: float | None = None
    contamination: str | None = None
    e_c: float | None = None
    fatigue_load_limit: float | None = None
    roughness: float | None = None
    pressure_viscosity: float = lub.PRESSURE_VISCOSITY


@dataclass(frozen=True)
class LifeBasis:
    """What one solved case knows for its lives. [N, mm, MPa, °, 10^6 rev]"""

    kind: str = "ball"
    C: float | None = None
    C0: float | None = None
    equivalent_load: float | None = None
    rating_life: float | None = None
    reference_rating_life: float | None = None
    pitch_diameter: float | None = None
    ball_diameter: float | None = None
    f_i: float | None = None
    f_o: float | None = None
    modulus: float | None = None
    poisson: float | None = None
    roller_length: float | None = None
    q_max: float | None = None
    contact_angle: float = 0.0


@dataclass
class ServiceLife:
    """The values (quantity key -> value), notes (sources, choices) and warnings of one case."""

    values: dict[str, Any] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)


def service_values(op: Operating, b: LifeBasis) -> ServiceLife:
    """Every life quantity the inputs make meaningful (see the module); C_0 always where known."""
    out = ServiceLife()
    v = out.values
    if b.C0:
        v["static_rating"] = float(b.C0)
    if op.speed is not None:
        v["speed"] = op.speed
        for key in ("rating_life", "reference_rating_life"):
            life = getattr(b, key)
            if life is not None:
                v[f"{key}_hours"] = float(ml.life_hours(life, op.speed))
    a1 = 1.0
    if op.reliability is not None:
        a1 = float(ml.reliability_factor(op.reliability))
        v["reliability"] = op.reliability
        v["reliability_factor"] = a1
        out.notes.append(
            "a_1: ISO 281:2007 Table 12 (between its rows 0.95 (ln(100/R)/ln(100/90))^(2/3) "
            "+ 0.05, the Weibull law the table is drawn from)."
        )
    if op.viscosity is not None:
        _modified(op, b, a1, out)
    return out


def _modified(op: Operating, b: LifeBasis, a1: float, out: ServiceLife) -> None:
    """nu_1, kappa, e_C, C_u, a_ISO, the modified lives and the film, into ``out``."""
    v = out.values
    if op.speed is None:
        raise InputError("viscosity", "needs the shaft speed ('speed') for the rated viscosity")
    if b.pitch_diameter is None:
        raise InputError("viscosity", "needs the pitch diameter (a bearing or 'pitch_diameter')")
    assert op.viscosity is not None
    nu1 = float(lub.rated_viscosity(op.speed, b.pitch_diameter))
    kappa = op.viscosity / nu1
    used, found = ml.clamp_kappa(kappa)
    out.warnings += found
    v |= {"viscosity": op.viscosity, "rated_viscosity": nu1, "kappa": kappa}
    e_c, e_c_note = _contamination(op, b.pitch_diameter)
    v["contamination_factor"] = e_c
    cu, cu_note = _fatigue_limit(op, b)
    out.notes.append(
        f"nu_1: ISO 281:2007, 9.3.3, at n = {op.speed:.6g} r/min and D_pw = "
        f"{b.pitch_diameter:.6g} mm; kappa = nu/nu_1{_used(kappa, float(used))}. {e_c_note} "
        f"{cu_note}"
    )
    film = _film(op, b)
    if film is not None:
        v["film_thickness"] = film
        if op.roughness is not None:
            v["roughness"] = op.roughness
            v["film_ratio"] = film / op.roughness
        out.notes.append(
            "Film: minimum film thickness at the heaviest contact (the thinner of inner and "
            + (
                "outer), Hamrock-Dowson (1977) point contact"
                if b.kind == "ball"
                else "outer), Dowson-Higginson (1977) line contact"
            )
            + f", alpha = {op.pressure_viscosity:.3g} 1/Pa, rho = {lub.OIL_DENSITY:g} kg/m^3; "
            "film ratio = h_min/sigma (--roughness, composite rms): information beside kappa."
        )
    if cu is None:
        out.warnings.append(
            "a_ISO needs the fatigue load limit C_u: give --fatigue-load-limit, or C_0 "
            "(--static-rating) for ISO 281's estimate"
        )
        return
    v["fatigue_load_limit"] = cu
    p = life_exponent(b.kind)
    _modified_life(v, "", b.equivalent_load, b.rating_life, used, e_c, cu, a1, b.kind, op)
    if b.reference_rating_life is not None and b.C:
        p_ref = b.C * b.reference_rating_life ** (-1.0 / p) if b.reference_rating_life else None
        v["reference_equivalent_load"] = p_ref
        _modified_life(
            v, "reference_", p_ref, b.reference_rating_life, used, e_c, cu, a1, b.kind, op
        )
        out.notes.append(
            "L_nmr: ISO/TS 16281 modified reference rating life a_1 a_ISO L10r, a_ISO at the "
            "dynamic equivalent reference load P_ref = C L10r^(-1/p) of the ball loads."
        )
    out.notes.append(
        "a_ISO: ISO 281:2007, 9.3.3 (radial "
        + ("ball" if b.kind == "ball" else "roller")
        + " bearings, at most 50); L_nm = a_1 a_ISO L10."
    )


def _used(kappa: float, used: float) -> str:
    return "" if used == kappa else f" = {kappa:.4g}, a_ISO taken at kappa = {used:g}"


def _modified_life(
    v: dict[str, Any],
    prefix: str,
    load: float | None,
    life: float | None,
    kappa: float,
    e_c: float,
    cu: float,
    a1: float,
    kind: str,
    op: Operating,
) -> None:
    """a_ISO at ``load`` and a_1 a_ISO ``life`` (and in hours) under ``prefix`` keys."""
    if load is None or life is None or not load > 0:
        return
    a_iso = float(ml.life_modification_factor(kappa, e_c * cu / load, kind))
    v[f"a_iso{'_reference' if prefix else ''}"] = a_iso
    v[f"modified_{prefix}rating_life"] = a1 * a_iso * life
    if op.speed is not None:
        v[f"modified_{prefix}rating_life_hours"] = float(ml.life_hours(a1 * a_iso * life, op.speed))


def _contamination(op: Operating, pitch_diameter: float) -> tuple[float, str]:
    """(e_C, a note saying where it comes from)."""
    if op.e_c is not None:
        if not 0.0 <= op.e_c <= 1.0:
            raise InputError("eC", f"must lie between 0 and 1; got {op.e_c}")
        return op.e_c, "e_C: given (--eC)."
    level = op.contamination or "normal"
    e_c = float(ml.contamination_factor(level, pitch_diameter))
    low, high = ml.CONTAMINATION_RANGES[level][0 if pitch_diameter < 100 else 1]
    given = "" if op.contamination else " (default; --contamination or --eC to change it)"
    return e_c, (
        f"e_C = {e_c:.3g}: {ml.CONTAMINATION_WORDS[level]}{given}, the middle of ISO 281:2007 "
        f"Table 13's {low:g}-{high:g} for D_pw {'<' if pitch_diameter < 100 else '>='} 100 mm."
    )


def _fatigue_limit(op: Operating, b: LifeBasis) -> tuple[float | None, str]:
    """(C_u or None, a note saying where it comes from)."""
    if op.fatigue_load_limit is not None:
        return op.fatigue_load_limit, "C_u: given (--fatigue-load-limit)."
    if not b.C0 or b.pitch_diameter is None:
        return None, ""
    cu = float(ml.fatigue_load_limit(b.C0, b.pitch_diameter, b.kind))
    div = "22" if b.kind == "ball" else "8.2"
    return cu, f"C_u: ISO 281:2007 Annex B estimate C_0/{div} (no maker's value used)."


def _film(op: Operating, b: LifeBasis) -> float | None:
    """The minimum film thickness at the heaviest contact, or None without its geometry. [mm]"""
    geometry = (b.ball_diameter, b.pitch_diameter, b.modulus, b.poisson, b.q_max)
    if any(g is None for g in geometry) or not (b.q_max and b.q_max > 0):
        return None
    assert b.ball_diameter is not None and b.pitch_diameter is not None
    assert op.speed is not None and op.viscosity is not None
    assert b.modulus is not None and b.poisson is not None and b.q_max is not None
    u = lub.entraining_speed(op.speed, b.ball_diameter, b.pitch_diameter, b.contact_angle)
    e_prime = lub.reduced_modulus(b.modulus, b.poisson)
    if b.kind == "ball":
        if b.f_i is None or b.f_o is None:
            return None
        radii = lub.ball_radii(b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o, b.contact_angle)
        films = [
            lub.film_point(b.q_max, rx, ry, e_prime, op.viscosity, u, op.pressure_viscosity)
            for rx, ry in radii
        ]
    else:
        if b.roller_length is None:
            return None
        films = [
            lub.film_line(
                b.q_max, b.roller_length, rx, e_prime, op.viscosity, u, op.pressure_viscosity
            )
            for rx in lub.rolling_radii(b.ball_diameter, b.pitch_diameter, b.contact_angle)
        ]
    return float(min(films))


def life_exponent(kind: str) -> float:
    """p of L10 = (C/P)^p: 3 for balls, 10/3 for rollers. [-]"""
    return ROLLER_LIFE_EXPONENT if kind == "roller" else BALL_LIFE_EXPONENT
