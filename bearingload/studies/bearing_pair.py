"""``bearingload solve`` of a pair of angular-contact ball bearings (DB, DF, DT): the pair's
equilibrium (:func:`bearingload.models.pair.solve_pair`), each bearing as a single combined
case (its lives, contact pressures, P0, s0 and checks, :mod:`bearingload.studies.
combined_bearing`) and the pair's lives combined (:func:`bearingload.models.pair.pair_life`).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from bearingload.bearings.preload import Preload
from bearingload.bearings.resolved import ResolvedBearing
from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.models.pair import PairDistribution
from bearingload.studies.combined_bearing import CombinedCase

#: The arrangements in words.
ARRANGEMENT_NAMES = {"DB": "back-to-back", "DF": "face-to-face", "DT": "tandem"}


@dataclass(frozen=True)
class PairCase:
    """One solved pair: the bearing (both alike), the pair's solution, each bearing as a
    combined case, the pair's lives [10^6 rev] (None where a bearing's is unknown) and the
    findings."""

    bearing: ResolvedBearing
    result: PairDistribution
    bearings: tuple[CombinedCase, CombinedCase]
    reference_rating_life: float | None
    rating_life: float | None
    rotating: str
    warnings: tuple[str, ...]
    #: The preload class the pair was solved at, its force and source (None: a force given).
    preload_class: Preload | None = None


def bearing_width(b: ResolvedBearing, width: float | None) -> float:
    """The width B of one bearing: the one given, else the catalogue's. [mm]"""
    if width is not None:
        return float(width)
    if b.geometry is not None and b.geometry.B:
        return float(b.geometry.B)
    raise InputError(
        "width",
        "a bearing pair needs the width B of one bearing (the axial distance of the two "
        "bearings' centres): give it (e.g. 15mm) or a catalogue designation that has it",
    )


def solve_bearing_pair(
    b: ResolvedBearing,
    load: float,
    axial_load: float = 0.0,
    *,
    arrangement: str,
    preload: float = 0.0,
    width: float | None = None,
    cage_angle: float = 0.0,
    moment: float | None = None,
    moment_cross: float | None = None,
    tilt_radius: Any = None,
    rotating: str = "inner",
    dynamic_rating: float | None = None,
    speed: float | None = None,
    ball_density: float | None = None,
) -> PairCase:
    """Solve the pair of two bearings ``b`` (angular contact, with its ball geometry).

    Parameters
    ----------
    b : ResolvedBearing
        One bearing of the pair, with ``contact_angle`` and the ball geometry.
    load, axial_load : float
        F_r >= 0 and F_a on the shaft at the pair's centre. [N]
    arrangement : {"DB", "DF", "DT"}
    preload : float or str
        F_p, DB and DF [N]; or a preload class (``"EL"``, ``"L"``, ``"M"``, ``"H"``), the force
        of the bearing's class table (:func:`bearingload.bearings.preload.resolve_preload`).
    width : float, optional
        B of one bearing; default the catalogue's. [mm]
    cage_angle, moment, moment_cross, tilt_radius, rotating, dynamic_rating
        As :func:`bearingload.studies.combined_bearing.solve_combined_bearing`. [°, N mm, mm, N]
    speed, ball_density : float, optional
        Shaft speed [rpm]: every ball's centrifugal force and gyroscopic moment are included
        (:mod:`bearingload.models.pair_speed`); None: the static model. Ball density
        [kg/m^3], default bearing steel.
    """
    return solve_bearing_pairs(
        b, load, axial_load, arrangement=arrangement, preload=preload, width=width,
        cage_angle=cage_angle, moment=moment, moment_cross=moment_cross,
        tilt_radius=tilt_radius, rotating=rotating, dynamic_rating=dynamic_rating,
        speed=speed, ball_density=ball_density,
    )[0]  # fmt: skip


def solve_bearing_pairs(
    b: ResolvedBearing,
    load: Any,
    axial_load: Any = 0.0,
    *,
    arrangement: str,
    preload: Any = 0.0,
    width: float | None = None,
    cage_angle: Any = 0.0,
    moment: Any = None,
    moment_cross: Any = None,
    tilt_radius: Any = None,
    rotating: str = "inner",
    dynamic_rating: float | None = None,
    speed: Any = None,
    ball_density: Any = None,
) -> list[PairCase]:
    """:func:`solve_bearing_pair` of several cases of one bearing ``b``, arrangement and width:
    the loads, preloads, moments and cage angles as arrays (broadcast), solved by one call of
    :func:`bearingload.models.pair.solve_pair` (each case on its own: a case alone gives the
    same bits), then each case's lives and checks. ``moment`` None: no moment given (the shaft
    free to tilt, no tilt warned of), as for one case. ``speed`` (not None): the ball dynamics
    (:func:`bearingload.models.pair_speed.solve_pair_high_speed`). One :class:`PairCase` per
    case, flat. ``preload`` a class: every case at the force of the bearing's table, which the
    cases' ``preload_class`` and the bearing's sources name."""
    from bearingload.bearings.tilt import tilt_lever
    from bearingload.models.pair import solve_pair

    _check_pair_bearing(b)
    setting = None
    if isinstance(preload, str):  # a class: the force of the bearing's table, with its source
        from bearingload.bearings.preload import resolve_preload

        setting = resolve_preload(preload, b)
        preload = setting.force
        b = dataclasses.replace(b, sources=(*b.sources, f"preload: {setting.source}"))
    lever = tilt_lever(tilt_radius, b.pitch_diameter)
    common: dict[str, Any] = dict(
        arrangement=arrangement, preload=preload,
        contact_angle=b.contact_angle, ball_diameter=b.ball_diameter,
        pitch_diameter=b.pitch_diameter, width=bearing_width(b, width), f_i=b.f_i, f_o=b.f_o,
        cage_angle=cage_angle, moment=0.0 if moment is None else moment,
        moment_cross=0.0 if moment_cross is None else moment_cross,
        modulus=b.modulus, poisson=b.poisson, tilt_radius=lever,
    )  # fmt: skip
    if speed is not None:  # the ball dynamics
        r: PairDistribution = _pair_at_speed(b, load, axial_load, speed, ball_density, rotating,
                                             common)  # fmt: skip
    else:
        r = solve_pair(b.balls, load, axial_load, **common,
                       stiffness=b.stiffness if b.stiffness_given else None)  # fmt: skip
    n = int(np.size(r.x))
    every = _singles(b, r, lever, rotating, dynamic_rating)  # on the arrays, once
    if np.ndim(r.x) == 0:  # one case
        cases = [_pair_case(b, r, every, rotating)]
    else:
        cases = [
            _pair_case(b, _case_at(r, i, n), [_single_at(c, i, n) for c in every], rotating)
            for i in range(n)
        ]
    if setting is None:
        return cases
    return [dataclasses.replace(c, preload_class=setting) for c in cases]


def _singles(
    b: ResolvedBearing, r: PairDistribution, lever: Any, rotating: str, dynamic_rating: Any
) -> list[CombinedCase]:
    """Each bearing of the case(s) ``r`` as a single combined case (its lives, pressures, P0,
    s0, checks; arrays over the cases); each bearing's tilt weighed as one bearing's is
    (:func:`bearingload.studies.combined_bearing.warned_tilt`)."""
    from bearingload.studies.combined_bearing import combined_case

    return [
        combined_case(b, rk, rk.load, rk.axial_load, None, None, lever, rotating, dynamic_rating)
        for rk in r.bearings
    ]


def _single_at(c: CombinedCase, i: int, n: int) -> CombinedCase:
    """Case ``i`` of the ``n`` cases of ``c``, as :func:`_singles` of that case alone gives it."""

    def at(v: Any) -> Any:
        return v if v is None else v[i] if isinstance(v, list) else float(np.reshape(v, -1)[i])

    life = at(c.rating_life)
    return dataclasses.replace(
        c, result=_case_at(c.result, i, n), equivalent_load=at(c.equivalent_load),
        rating_life=None if life is None or np.isnan(life) else life,
        reference_rating_life=at(c.reference_rating_life), warnings=c.warnings[i],
        p_max_inner=at(c.p_max_inner), p_max_outer=at(c.p_max_outer),
        static_equivalent_load=at(c.static_equivalent_load), static_safety=at(c.static_safety),
    )  # fmt: skip


def _check_pair_bearing(b: ResolvedBearing) -> None:
    """Refuse a bearing that cannot be one of a pair."""
    if b.kind == "ball" and b.contact_angle is not None and not b.has_geometry:  # z and K only
        raise InputError(
            "ball_diameter",
            "a bearing pair needs the ball geometry: give a bearing designation, or the ball "
            "and pitch diameters",
        )
    if b.kind != "ball" or not b.has_geometry or b.contact_angle is None:
        raise InputError(
            "arrangement",
            "a bearing pair is two angular-contact ball bearings: give an angular-contact "
            "designation (7205B) or a ring by hand with its contact angle",
        )


def _case_at(r: Any, i: int, n: int) -> Any:
    """Case ``i`` of the ``n`` flat cases of a solution (a pair's or a bearing's dataclass), as
    a call of that case alone returns it: its case quantities Python numbers, its ball arrays
    (z,), its matrices (5, 5)."""
    from bearingload import numerics

    out = {}
    for f in dataclasses.fields(r):
        v = getattr(r, f.name)
        if isinstance(v, tuple):
            v = tuple(_case_at(x, i, n) for x in v)
        elif isinstance(v, np.ndarray) and v.ndim >= 1 and v.shape[0] == n:
            v = numerics.scalar_out(v[i]) if v.ndim == 1 else v[i]
        out[f.name] = v
    return dataclasses.replace(r, **out)


def _pair_at_speed(
    b: ResolvedBearing, load: Any, axial_load: Any, speed: Any, density: Any, rotating: str,
    common: dict[str, Any],
) -> PairDistribution:  # fmt: skip
    """solve_bearing_pair with the ball dynamics (:func:`bearingload.models.pair_speed.
    solve_pair_high_speed`): the inner rings turning, each contact's Hertz stiffness."""
    from bearingload.models.pair_speed import solve_pair_high_speed
    from bearingload.studies.combined_bearing import dynamics_density, refuse_outer_at_speed

    refuse_outer_at_speed(speed, rotating)
    density = dynamics_density(b, density)
    return solve_pair_high_speed(b.balls, load, axial_load, speed=speed, ball_density=density,
                                 **common)  # fmt: skip


def _pair_case(
    b: ResolvedBearing, r: PairDistribution, singles: list[CombinedCase], rotating: str
) -> PairCase:
    """The pair's case of its solution ``r`` (one case) and each bearing's single case
    (:func:`_singles`): an unloaded bearing without lives, the pair's lives and findings."""
    cases = []
    for k, c in enumerate(singles):
        if r.unloaded[k]:  # no ball loaded: no life, no equivalent load
            c = dataclasses.replace(c, reference_rating_life=None, rating_life=None,
                                    equivalent_load=None)  # fmt: skip
        cases.append(c)
    lives = [math.inf if r.unloaded[k] else c.reference_rating_life for k, c in enumerate(cases)]
    basic = [math.inf if r.unloaded[k] else c.rating_life for k, c in enumerate(cases)]
    found: list[str] = []
    for k, c in enumerate(cases):
        found += [f"bearing {k + 1}: {w}" for w in c.warnings]
    if r.unloaded.any():
        k = int(np.flatnonzero(r.unloaded)[0])
        lift = r.lift_off_axial_load
        when = ("" if lift is None else
                f" (lift-off: at an axial load alone beyond {abs(lift):.6g} N for the preload "
                f"{r.preload:.6g} N{', at rest' if getattr(r, 'speed', None) is not None else ''})")  # fmt: skip
        found.append(
            f"bearing {k + 1} of the {ARRANGEMENT_NAMES[r.arrangement]} pair carries no load"
            f"{when}: its balls may skid; raise the preload"
        )
    return PairCase(b, r, (cases[0], cases[1]), _combined(lives), _combined(basic), rotating,
                    tuple(found))  # fmt: skip


def _combined(lives: list[Any]) -> float | None:
    """The pair's life of the bearings' lives (:func:`bearingload.models.pair.pair_life`; an
    unloaded bearing's infinite one drops out); None where a loaded bearing's is unknown."""
    from bearingload.models.pair import pair_life

    if any(x is None or math.isnan(float(x)) for x in lives):
        return None
    out = float(pair_life(float(lives[0]), float(lives[1])))
    return None if math.isinf(out) else out


@dataclass(frozen=True)
class PairLives:
    """A pair's service values: ``bearings``, each bearing's
    (:class:`bearingload.bearings.service_life.ServiceLife`, as a single bearing's solve gives
    them from that bearing's loads; empty for a ring by hand), and ``pair``, the pair's from
    them (:func:`pair_service_values`)."""

    bearings: tuple[Any, ...]
    pair: dict[str, float]


def pair_lives(c: PairCase, service: Sequence[Any] | None) -> PairLives:
    """The :class:`PairLives` of the solved pair ``c`` from its bearings' ``service``."""
    return PairLives(tuple(service or ()), pair_service_values(c, service))


#: The modified lives of a bearing combined into the pair's by :func:`pair_service_values`.
MODIFIED_LIVES = ("modified_rating_life", "modified_reference_rating_life")


def pair_service_values(c: PairCase, service: Sequence[Any] | None) -> dict[str, float]:
    """The pair's service values from each bearing's
    (:class:`bearingload.bearings.service_life.ServiceLife`, one per bearing, as a single
    bearing's solve gives them from that bearing's loads).

    * ``speed``, ``reliability``: the operating conditions (both bearings'), where given;
    * ``rating_life_hours``, ``reference_rating_life_hours``: the pair's L10 and L10r in hours,
      L 10^6 / (60 n); [h]
    * ``modified_rating_life``, ``modified_reference_rating_life`` (and ``..._hours``): the
      bearings' L_nm (L_nmr) combined by the pair's rule
      (:func:`bearingload.models.pair.pair_life`, e = 10/9), an unloaded bearing dropping out.
      The rule is Lundberg-Palmgren's system life of Weibull lives of one slope; applied to the
      modified lives (a_ISO a stress-based factor, a_1 of ISO 281 Table 12 drawn with another
      slope) it is an approximation. None of them where a loaded bearing has none. [10^6 rev]

    Keys without a value are left out (no speed: no hours; no viscosity: no modified life).
    """
    from bearingload.bearings.modified_life import life_hours

    if not service:
        return {}
    given = [s.values for s in service]
    out: dict[str, float] = {
        k: float(given[0][k]) for k in ("speed", "reliability") if k in given[0]
    }
    for key in MODIFIED_LIVES:
        if any(key in v for v in given):
            lives = [math.inf if c.result.unloaded[k] else v.get(key) for k, v in enumerate(given)]
            life = _combined(lives)
            if life is not None:
                out[key] = life
    speed = out.get("speed")
    if speed is not None:
        for key in ("rating_life", "reference_rating_life", *MODIFIED_LIVES):
            life = out.get(key, getattr(c, key, None))
            if life is not None:
                out[f"{key}_hours"] = float(life_hours(life, speed))
    return out
