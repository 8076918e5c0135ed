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

from typing import Any

import numpy as np

from bearingload.bearings import lubrication as lub
from bearingload.bearings import modified_life as ml
from bearingload.constants import BALL_LIFE_EXPONENT, ROLLER_LIFE_EXPONENT
from bearingload.errors import InputError


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
    pressure_viscosity : float or None
        alpha of the lubricant; None: :data:`bearingload.bearings.lubrication.PRESSURE_VISCOSITY`
        (a mineral oil; see :attr:`alpha`). [1/Pa]
    viscosity_note : str or None
        Where the viscosity comes from (an oil at its temperature), for the notes.

    (A plain class, read by attribute only: no dataclass to build on every solve.)
    """

    __slots__ = (
        "speed",
        "reliability",
        "viscosity",
        "contamination",
        "e_c",
        "fatigue_load_limit",
        "roughness",
        "pressure_viscosity",
        "viscosity_note",
    )

    def __init__(
        self,
        speed: float | None = None,
        reliability: float | None = None,
        viscosity: float | None = None,
        contamination: str | None = None,
        e_c: float | None = None,
        fatigue_load_limit: float | None = None,
        roughness: float | None = None,
        pressure_viscosity: float | None = None,
        viscosity_note: str | None = None,
    ) -> None:
        self.speed = speed
        self.reliability = reliability
        self.viscosity = viscosity
        self.contamination = contamination
        self.e_c = e_c
        self.fatigue_load_limit = fatigue_load_limit
        self.roughness = roughness
        self.pressure_viscosity = pressure_viscosity
        self.viscosity_note = viscosity_note

    @property
    def alpha(self) -> Any:
        """The pressure-viscosity coefficient used: the one given, or a mineral oil's. [1/Pa]"""
        given = self.pressure_viscosity
        return lub.PRESSURE_VISCOSITY if given is None else given


class LifeBasis:
    """What one solved case (or the cases of one bearing) knows for its lives: ``kind``, the
    ratings and the geometry are the bearing's; ``equivalent_load``, the lives, ``q_max`` and
    ``contact_angle`` a float, or an array over cases (NaN: none). ``contact_angle`` is the
    heaviest ball's (its inner contact's at speed, ``contact_angle_outer`` its outer one there,
    None: the same), ``balls`` the number of balls (None: no defect frequencies) and
    ``rotating`` the ring turning at the speed. [N, mm, MPa, °, 10^6 rev]

    (A plain class, read by attribute only: no dataclass to build on every solve.)
    """

    __slots__ = (
        "kind",
        "C",
        "C0",
        "equivalent_load",
        "rating_life",
        "reference_rating_life",
        "pitch_diameter",
        "ball_diameter",
        "f_i",
        "f_o",
        "modulus",
        "poisson",
        "roller_length",
        "q_max",
        "contact_angle",
        "balls",
        "contact_angle_outer",
        "rotating",
    )

    def __init__(
        self,
        kind: str = "ball",
        C: float | None = None,
        C0: float | None = None,
        equivalent_load: Any = None,
        rating_life: Any = None,
        reference_rating_life: Any = None,
        pitch_diameter: float | None = None,
        ball_diameter: float | None = None,
        f_i: float | None = None,
        f_o: float | None = None,
        modulus: float | None = None,
        poisson: float | None = None,
        roller_length: float | None = None,
        q_max: Any = None,
        contact_angle: Any = 0.0,
        balls: int | None = None,
        contact_angle_outer: Any = None,
        rotating: str = "inner",
    ) -> None:
        self.kind = kind
        self.C = C
        self.C0 = C0
        self.equivalent_load = equivalent_load
        self.rating_life = rating_life
        self.reference_rating_life = reference_rating_life
        self.pitch_diameter = pitch_diameter
        self.ball_diameter = ball_diameter
        self.f_i = f_i
        self.f_o = f_o
        self.modulus = modulus
        self.poisson = poisson
        self.roller_length = roller_length
        self.q_max = q_max
        self.contact_angle = contact_angle
        self.balls = balls
        self.contact_angle_outer = contact_angle_outer
        self.rotating = rotating


class ServiceLife:
    """The values (quantity key -> value), notes (sources, choices) and warnings of one case,
    filled by :func:`service_values` (a plain class: no dataclass to build at import)."""

    def __init__(self) -> None:
        self.values: dict[str, Any] = {}
        self.notes: list[str] = []
        self.warnings: list[str] = []


def service_values(op: Operating, b: LifeBasis) -> ServiceLife:
    """Every life quantity the inputs make meaningful (see the module); C_0 always where known.

    The values are those of :func:`service_columns` (one case: floats; a key without a value is
    left out), with the notes (sources, choices) and warnings of the case."""
    out = ServiceLife()
    columns = service_columns(op, b)
    out.values = {
        k: float(x) for k, x in columns.items() if np.ndim(x) == 0 and np.isfinite(float(x))
    }
    out.warnings = life_warnings(op, b, out.values.get("kappa"))[0]
    if "cage_frequency" in out.values:
        out.notes.append(frequency_note(b))
    if op.reliability is not None:
        out.notes.append(
            "a_1: ISO 281:2007 Table 12 (between its rows 0.95 (ln(100/R)/ln(100/90))^(2/3) "
            "+ 0.05, the Weibull law the table is drawn from)."
        )
    if op.viscosity is not None:
        assert op.speed is not None and b.pitch_diameter is not None
        out.notes += [op.viscosity_note] if op.viscosity_note else []
        v = out.values
        used = float(ml.clamp_kappa(v["kappa"])[0])
        e_c_note = _contamination(op, b.pitch_diameter)[1]
        cu_note = _fatigue_limit(op, b)[1]
        out.notes.append(
            f"nu_1: ISO 281:2007, 9.3.3, at n = {op.speed:.6g} r/min and D_pw = "
            f"{b.pitch_diameter:.6g} mm; kappa = nu/nu_1{_used(v['kappa'], used)}. {e_c_note} "
            f"{cu_note}"
        )
        out.notes += _film_note(op, b) if "film_thickness" in v else []
        if "fatigue_load_limit" in v and "modified_reference_rating_life" in v:
            out.notes.append(
                "L_nmr: ISO/TS 16281 modified reference rating life a_1 a_ISO L10r, a_ISO at the "
                "dynamic equivalent reference load P_ref = C L10r^(-1/p) of the ball loads."
            )
        if "fatigue_load_limit" in v:
            out.notes.append(
                "a_ISO: ISO 281:2007, 9.3.3 (radial "
                + ("ball" if b.kind == "ball" else "roller")
                + " bearings, at most 50); L_nm = a_1 a_ISO L10."
            )
    return out


def life_warnings(op: Operating, b: LifeBasis, kappa: Any) -> list[list[str]]:
    """The warnings of the lives of each case (one case, or many of one bearing: ``kappa`` a
    float or an array over them, None or NaN: none), in the order solve prints them: kappa
    outside ISO 281's 0.1 ... 4 (:func:`~bearingload.bearings.modified_life.clamp_kappa`),
    then a viscosity without C_u (:func:`missing_fatigue_limit`)."""
    common = missing_fatigue_limit(op, b)
    low, high = ml.KAPPA_RANGE
    ks = np.atleast_1d(np.asarray(np.nan if kappa is None else kappa, dtype=float)).tolist()
    return [(ml.clamp_kappa(k)[1] if not low <= k <= high and k == k else []) + common for k in ks]


def missing_fatigue_limit(op: Operating, b: LifeBasis) -> list[str]:
    """The warning of a case with a viscosity but no C_u (no C_0 to estimate it from)."""
    if op.viscosity is None or _fatigue_limit(op, b)[0] is not None:
        return []
    return [
        "a_ISO needs the fatigue load limit C_u: give --fatigue-load-limit, or C_0 "
        "(--static-rating) for ISO 281's estimate"
    ]


def service_columns(op: Operating, b: LifeBasis) -> dict[str, Any]:
    """The values of every life quantity the given inputs make meaningful, for one case or many.

    The operating conditions and the case's lives, loads and heaviest contact may be arrays
    over cases (one bearing: ``kind``, C, C_0 and the geometry are shared); a field None is not
    given for any case. Returns quantity key -> value (a float, or an array over the cases),
    NaN where a case has no value (a load of 0, no L10r). Each case's values depend on its own
    inputs only: ``batch`` calls this with arrays, ``solve`` with one case. [units as the keys]

    Raises
    ------
    InputError
        For a viscosity without speed or pitch diameter, or e_C outside 0 to 1.
    """
    _check_needs(op)
    v: dict[str, Any] = {}
    if b.C0:
        v["static_rating"] = float(b.C0)
    if op.speed is not None:
        v["speed"] = _arr(op.speed)
        v |= _frequencies(op.speed, b)
        for key in ("rating_life", "reference_rating_life"):
            life = getattr(b, key)
            if life is not None:
                v[f"{key}_hours"] = ml.life_hours(_arr(life), op.speed)
    a1: Any = 1.0
    if op.reliability is not None:
        a1 = _arr(ml.reliability_factor(op.reliability))
        v["reliability"] = _arr(op.reliability)
        v["reliability_factor"] = a1
    if op.viscosity is not None:
        _modified(op, b, a1, v)
    return v


#: The composite rms roughness taken: from below an atom's size to a rough turned surface. [mm]
ROUGHNESS = (1e-7, 0.1)
#: Inputs that feed only the modified life or the film, both of which need the viscosity. [-]
NEED_VISCOSITY = ("contamination", "e_c", "fatigue_load_limit", "roughness", "pressure_viscosity")


def _check_needs(op: Operating) -> None:
    """Refuse an input that would be ignored: one of NEED_VISCOSITY without a viscosity, and a
    contamination level together with e_C (one of the two gives e_C)."""
    if op.viscosity is None:
        for name in NEED_VISCOSITY:
            if getattr(op, name) is not None:
                fed = "the film, which needs" if name == "pressure_viscosity" else (
                    "the modified life (a_ISO) or the film, which need")  # fmt: skip
                raise InputError(
                    name,
                    f"feeds {fed} the operating viscosity ('viscosity', with 'speed'): without "
                    "it, it would be ignored",
                )
    if op.roughness is not None and not np.all(
        (np.asarray(op.roughness, dtype=float) >= ROUGHNESS[0])
        & (np.asarray(op.roughness, dtype=float) <= ROUGHNESS[1])
    ):
        raise InputError(
            "roughness",
            f"must lie between {ROUGHNESS[0]:g} and {ROUGHNESS[1]:g} mm (0.1 nm to 100 um: a "
            "composite rms roughness of machined surfaces)",
        )
    if op.contamination is not None and op.e_c is not None:
        raise InputError("e_c", "give a contamination level or e_C, not both (each gives e_C)")


def frequency_note(b: LifeBasis) -> str:
    """Where the defect frequencies come from: the heaviest ball's angle(s), the rotating ring
    (the same words for every bearing of a pair)."""
    angles = (
        "its contact angle, pure rolling"
        if b.contact_angle_outer is None
        else "its inner and outer contact angles, outer-raceway control"
    )
    return (
        f"FTF, BPFO, BPFI, BSF: kinematics of the heaviest ball at {angles} (Harris & Kotzalas; "
        f"docs/speed.md), the {b.rotating} ring turning at n, the other still; no slip."
    )


def _frequencies(speed: Any, b: LifeBasis) -> dict[str, Any]:
    """FTF, BPFO, BPFI and BSF of a ball bearing at its heaviest ball's contact angle(s)
    (:func:`bearingload.bearings.frequencies.defect_frequencies`); none without the ball set.
    Over many cases, a case with no outer angle (NaN: the static model) takes the one-angle
    kinematics, a case with no angle at all (NaN) no frequencies. [Hz]"""
    from bearingload.bearings.frequencies import defect_frequencies

    if b.kind != "ball" or not (b.balls and b.ball_diameter and b.pitch_diameter):
        return {}
    geometry = (b.balls, b.ball_diameter, b.pitch_diameter, speed)
    inner = np.asarray(b.contact_angle, dtype=float)
    known = np.isfinite(inner)
    one = defect_frequencies(*geometry, np.where(known, inner, 0.0), rotating=b.rotating)
    found = one.values()
    outer = np.asarray(np.nan if b.contact_angle_outer is None else b.contact_angle_outer, float)
    two = known & np.isfinite(outer)
    if two.any():
        both = defect_frequencies(
            *geometry, np.where(two, inner, 0.0), np.where(two, outer, 0.0), b.rotating
        ).values()
        found = {k: np.where(two, both[k], v) for k, v in found.items()}
    return {k: _arr(np.where(known, v, np.nan)) for k, v in found.items()}


def _arr(value: Any) -> Any:
    """A float or a float array, None (no value) as NaN."""
    if isinstance(value, list):
        return np.array([np.nan if x is None else x for x in value], dtype=float)
    x = np.asarray(np.nan if value is None else value, dtype=float)
    return float(x) if x.ndim == 0 else x


def _modified(op: Operating, b: LifeBasis, a1: Any, v: dict[str, Any]) -> None:
    """nu_1, kappa, e_C, C_u, a_ISO, the modified lives and the film, into ``v``."""
    if op.speed is None:
        raise lub.speed_needed("viscosity")
    if b.pitch_diameter is None:
        raise InputError("viscosity", "needs the pitch diameter (a bearing or 'pitch_diameter')")
    assert op.viscosity is not None
    nu1 = _arr(lub.rated_viscosity(op.speed, b.pitch_diameter))
    kappa = _arr(op.viscosity) / nu1
    used = ml.clamp_kappa(kappa)[0]
    v |= {"viscosity": _arr(op.viscosity), "rated_viscosity": nu1, "kappa": kappa}
    v["contamination_factor"] = e_c = _contamination(op, b.pitch_diameter)[0]
    film = _film(op, b)
    if film is not None:
        v["film_thickness"] = film
        if op.roughness is not None:
            v["roughness"] = _arr(op.roughness)
            v["film_ratio"] = film / v["roughness"]
    cu = _fatigue_limit(op, b)[0]
    if cu is None:
        return
    v["fatigue_load_limit"] = cu = _arr(cu)
    p = life_exponent(b.kind)
    _modified_life(v, "", b.equivalent_load, b.rating_life, used, e_c, cu, a1, b.kind, op)
    if b.reference_rating_life is not None and b.C:
        l10r = _arr(b.reference_rating_life)
        with np.errstate(divide="ignore", invalid="ignore"):
            p_ref = np.where(l10r > 0, b.C * np.where(l10r > 0, l10r, 1.0) ** (-1.0 / p), np.nan)
        v["reference_equivalent_load"] = _arr(p_ref)
        _modified_life(v, "reference_", p_ref, l10r, used, e_c, cu, a1, b.kind, op)


def _film_note(op: Operating, b: LifeBasis) -> list[str]:
    return [
        "Film: minimum film thickness at the heaviest contact (the thinner of inner and "
        + (
            "outer), Hamrock-Dowson (1977) point contact"
            if b.kind == "ball"
            else "outer), Dowson-Higginson (1977) line contact"
        )
        + f", alpha = {op.alpha:.3g} 1/Pa, rho = {lub.OIL_DENSITY:g} kg/m^3; "
        "film ratio = h_min/sigma (--roughness, composite rms): information beside kappa."
    ]


def _used(kappa: float, used: float) -> str:
    return "" if used == kappa else f" = {kappa:.4g}, a_ISO taken at kappa = {used:g}"


def _modified_life(
    v: dict[str, Any],
    prefix: str,
    load: Any,
    life: Any,
    kappa: Any,
    e_c: Any,
    cu: Any,
    a1: Any,
    kind: str,
    op: Operating,
) -> None:
    """a_ISO at ``load`` and a_1 a_ISO ``life`` (and in hours) under ``prefix`` keys; NaN for a
    case without a load > 0 or a life."""
    if load is None or life is None:
        return
    p, life = _arr(load), _arr(life)
    good = np.isfinite(p) & (p > 0) & np.isfinite(life)
    if not np.any(good):
        return
    x = e_c * cu / np.where(good, p, 1.0)
    a_iso = np.where(good, ml.life_modification_factor(kappa, x, kind), np.nan)
    v[f"a_iso{'_reference' if prefix else ''}"] = _arr(a_iso)
    v[f"modified_{prefix}rating_life"] = modified = _arr(a1 * a_iso * life)
    if op.speed is not None:
        v[f"modified_{prefix}rating_life_hours"] = _arr(ml.life_hours(modified, op.speed))


def _contamination(op: Operating, pitch_diameter: float) -> tuple[Any, str]:
    """(e_C, a note saying where it comes from)."""
    if op.e_c is not None:
        e_c = _arr(op.e_c)
        if not np.all((e_c >= 0.0) & (e_c <= 1.0)):
            raise InputError("eC", f"must lie between 0 and 1; got {op.e_c}")
        return e_c, "e_C: given (--eC)."
    level = op.contamination or "normal"
    e_c = float(ml.contamination_factor(level, pitch_diameter))
    low, high = ml.CONTAMINATION_RANGES[level][0 if pitch_diameter < 100 else 1]
    given = "" if op.contamination else " (default; --contamination or --eC to change it)"
    return e_c, (
        f"e_C = {e_c:.3g}: {ml.CONTAMINATION_WORDS[level]}{given}, the middle of ISO 281:2007 "
        f"Table 13's {low:g}-{high:g} for D_pw {'<' if pitch_diameter < 100 else '>='} 100 mm."
    )


def _fatigue_limit(op: Operating, b: LifeBasis) -> tuple[Any, str]:
    """(C_u or None, a note saying where it comes from)."""
    if op.fatigue_load_limit is not None:
        return op.fatigue_load_limit, "C_u: given (--fatigue-load-limit)."
    if not b.C0 or b.pitch_diameter is None:
        return None, ""
    cu = float(ml.fatigue_load_limit(b.C0, b.pitch_diameter, b.kind))
    div = "22" if b.kind == "ball" else "8.2"
    return cu, f"C_u: ISO 281:2007 Annex B estimate C_0/{div} (no maker's value used)."


def _film(op: Operating, b: LifeBasis) -> Any:
    """The minimum film thickness at the heaviest contact (NaN for a case without a loaded
    element), or None without the geometry. [mm]"""
    geometry = (b.ball_diameter, b.pitch_diameter, b.modulus, b.poisson, b.q_max)
    if any(g is None for g in geometry):
        return None
    assert b.ball_diameter is not None and b.pitch_diameter is not None
    assert op.speed is not None and op.viscosity is not None
    assert b.modulus is not None and b.poisson is not None
    q = _arr(b.q_max)
    loaded = np.isfinite(q) & (q > 0)
    if not np.any(loaded):
        return None
    q = np.where(loaded, q, 1.0)
    u = lub.entraining_speed(op.speed, b.ball_diameter, b.pitch_diameter, b.contact_angle)
    e_prime = lub.reduced_modulus(b.modulus, b.poisson)
    if b.kind == "ball":
        if b.f_i is None or b.f_o is None:
            return None
        radii = lub.ball_radii(b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o, b.contact_angle)
        films = [lub.film_point(q, rx, ry, e_prime, op.viscosity, u, op.alpha) for rx, ry in radii]
    else:
        if b.roller_length is None:
            return None
        films = [
            lub.film_line(q, b.roller_length, rx, e_prime, op.viscosity, u, op.alpha)
            for rx in lub.rolling_radii(b.ball_diameter, b.pitch_diameter, b.contact_angle)
        ]
    return _arr(np.where(loaded, np.minimum(*films), np.nan))


def life_exponent(kind: str) -> float:
    """p of L10 = (C/P)^p: 3 for balls, 10/3 for rollers. [-]"""
    return ROLLER_LIFE_EXPONENT if kind == "roller" else BALL_LIFE_EXPONENT
