"""The plan of ``table``: which table a case asks for (the design tables k and kq over z, one
bearing's life against its clearance, a pair's life against its preload), what each refuses
(typed errors naming the inputs as the library calls them; one copy of each rule) and the
table solved. The command line only parses the options and renders what this returns."""

from __future__ import annotations

from typing import Any, NamedTuple

from bearingload.bearings.mounting import MOUNTING_PARAMS
from bearingload.errors import (
    ConflictError,
    ConvergenceError,
    InputError,
    MissingError,
    UnusedError,
)
from bearingload.plan.case import COMBINED_PARAMS, DYNAMICS_PARAMS, MOUNTING_REFUSAL, Case
from bearingload.plan.solve import in_case_terms

#: The tables: k and kq over z (Kuzmenko 2010, Kuzmenko & Sabadash 2014), life over G_r.
TABLES = ("k", "kq", "life")
#: Why table k and kq refuse the options of the ball dynamics.
DYNAMICS_REFUSAL = (
    "table k and kq are the papers' static design tables (no speed); the ball dynamics at "
    "'speed' are solved by 'table life', 'solve' and 'sweep' (docs/speed.md)"
)
#: Why table k and kq refuse the combined-load options.
RADIAL_ONLY = (
    "table k and kq are the papers' radial, dimensionless design tables (k = Q_max/F_r over "
    "z; no axial load, no tilt, no life); for a combined load or the life use 'table life', "
    "'solve' or 'sweep'"
)
#: The ball geometry and material inputs, which only a catalogue bearing's table takes.
GEOMETRY = (
    "ball_diameter",
    "pitch_diameter",
    "inner_conformity",
    "outer_conformity",
    "modulus",
    "poisson",
    "ball_material",
)


class Tabled(NamedTuple):
    """A planned or solved table: ``kind`` (``design``: table k or kq, ``result`` the
    :class:`~bearingload.studies.tables.Conditions` its rows are computed under; ``life``: one
    bearing over its clearance, ``service`` its rows' service lives or None; ``pair``: a pair
    over its preload, ``service`` its rows' :class:`bearingload.studies.bearing_pair.
    PairLives`) and the study's ``result``."""

    kind: str
    result: Any
    service: Any = None


def table_case(
    name: str,
    case: Case,
    *,
    z_max: int | None = None,
    method: str | None = None,
    clearances: list[float] | None = None,
    preloads: list[float] | None = None,
    spell: Any = str,
) -> Tabled:
    """The table ``name`` of ``case``: ``z_max`` and ``method`` given (None: not given; table
    life refuses them), ``clearances`` [mm] the rows of table life,
    ``preloads`` [N] those of a pair's. ``spell`` writes the quoted inputs of a warning as the
    caller's user types them.

    Raises
    ------
    InputError
        An input the table cannot take, or one it needs and lacks (ConflictError,
        MissingError, UnusedError: the fields name the inputs).
    """
    if name not in TABLES:
        raise InputError("name", f"{name!r} is not a table; give one of {', '.join(TABLES)}")
    where = f"table {name}"
    case.refuse(
        ("contact_angle",),
        where,
        "a ring given by hand with its contact angle is solved by 'solve' only; an "
        "angular-contact designation (7205B) by 'solve', 'sweep' and 'batch' "
        "(docs/angular_contact.md)",
    )
    case.refuse(MOUNTING_PARAMS, where, MOUNTING_REFUSAL)
    life = name == "life"  # table k and kq: the radial engine, no axial load, no moment
    case.check_load(radial=not case.wants_combined, combined=life and case.takes_combined)
    if name != "life":
        case.refuse(DYNAMICS_PARAMS, where, DYNAMICS_REFUSAL)
    pair = case.as_pair()
    try:
        if pair is not None or preloads is not None:
            return _pair_life(name, pair, z_max, method, clearances, preloads)
        _refuse_angular(name, case)
        if name == "life":
            return _life(case, z_max, method, clearances, spell)
    except ConvergenceError as exc:
        raise in_case_terms(exc, case) from exc
    return Tabled("design", _design(name, case, clearances))


def _refuse_angular(name: str, case: Case) -> None:
    """An angular-contact designation (as ``contact_angle``) has no table of its own."""
    from bearingload.bearings.angular import parse_angular

    if case.bearing is None or parse_angular(case.bearing) is None:
        return
    bearing = case.bearing.strip()
    rows = (
        ": its rows are radial clearances, and the contact angle fixes an angular-contact "
        "bearing's geometry (no clearance); for a pair, 'table life -b "
        f"{bearing}DB --preloads 0,100N,300N' gives L10r against the preload"
        if name == "life"
        else ""
    )
    raise InputError(
        "bearing",
        f"{bearing!r} is an angular-contact bearing, solved by 'solve', 'sweep' and 'batch', "
        f"not by 'table {name}'{rows} (docs/angular_contact.md)",
    )


def _design(name: str, case: Case, clearances: Any) -> Any:
    """The conditions of table k or kq (the case's load, stiffness, clearance, cage angle)."""
    from bearingload.plan.bearing import refuse_range

    refuse_range(case, f"table {name}")
    case.refuse(COMBINED_PARAMS, f"table {name}", RADIAL_ONLY)
    life_only = (
        "it is an option of table life (table k and kq run over z = 1..'z_max' at one clearance)"
    )
    for param, value in (("balls", case.balls), ("clearances", clearances)):
        if value is not None:
            raise ConflictError(param, f"table {name}", life_only)
    k_given = case.stiffness_value()  # N/mm^m
    if case.bearing is not None:
        return _bearing_conditions(case, k_given)
    return _ring_conditions(case, k_given)


def _ring_conditions(case: Case, k_given: float | None) -> Any:
    """The conditions of a ring given by its stiffness (default K = 1e5 N/mm^1.5)."""
    from bearingload.bearings.clearance import clearance_length
    from bearingload.plan.bearing import refuse_unused
    from bearingload.studies.tables import Conditions

    geometry = tuple(n for n in GEOMETRY if getattr(case, n) is not None)
    if geometry:
        raise UnusedError(geometry, "a 'bearing' (its ball and raceways); without one")
    refuse_unused(
        case,
        ("maker",),
        "'bearing' (a class and a maker's ball set are a catalogue bearing's); without one",
    )
    k = 1e5 if k_given is None else k_given
    return Conditions(
        case.radial_load,
        k,
        clearance_length(case.clearance),
        _cage(case),
        case.exponent_or(1.5),
    )


def _cage(case: Case) -> float | str:
    """The cage angle of the tables: ``half``, or the angle within one turn as the solvers take
    it (:func:`bearingload.validate.reduced_angle`: -10 is 350°, -1e-320 and -0 are 0)."""
    from bearingload.validate import reduced_angle

    return "half" if case.cage_angle == "half" else float(reduced_angle(float(case.cage_angle)))


def _bearing_conditions(case: Case, k_given: float | None) -> Any:
    """The conditions of a catalogue bearing's ball and raceways (Hertz K, its clearance)."""
    from bearingload.bearings.resolve import check_exponent
    from bearingload.plan.bearing import resolve_bearings
    from bearingload.studies.tables import for_bearing

    clearance = case.clearance if case.clearance is not None else 0.0
    resolved = resolve_bearings(case, k_given, clearance=clearance, exponent=None)[0]
    if resolved.kind != "ball":
        raise InputError(
            "bearing",
            "the tables take ball bearings; for a roller bearing use 'bearingload solve' or "
            "'exponent' 10/9 with 'stiffness'",
        )
    check_exponent(resolved, case.exponent)
    return for_bearing(resolved, case.radial_load, _cage(case))


def _life(case: Case, z_max: int | None, method: str | None, clearances: Any, spell: Any) -> Tabled:
    """Table life of one bearing: its rows are clearances."""
    from bearingload.plan.life_table import life_against_clearance_case

    rows = "its rows are clearances ('clearances')"
    for param, given, why in (
        ("z_max", z_max is not None, "it is one bearing, not a table over z"),
        ("method", method is not None, "the life comes from the exact 3-D model only"),
        ("clearance", case.clearance is not None, rows),
        ("clearance_pick", "clearance_pick" in case.given, f"{rows}, no class to pick in"),
    ):
        if given:
            raise ConflictError(param, "table life", why)
    if case.bearing is None and case.ball_diameter is None:
        raise MissingError(
            "bearing",
            "table life needs a bearing, or 'balls', 'ball_diameter', 'pitch_diameter' and "
            "'dynamic_rating'",
        )
    if "load" not in case.given:
        raise MissingError("load", "table life needs F_r (N)")
    result, service = life_against_clearance_case(case, clearances, spell)
    return Tabled("life", result, service)


def _pair_life(
    name: str,
    case: Case | None,
    z_max: int | None,
    method: str | None,
    clearances: Any,
    preloads: list[float] | None,
) -> Tabled:
    """Table life of a bearing pair: its rows are preloads."""
    from bearingload.plan.life_table import life_against_preload_case
    from bearingload.plan.solve import speed_pair_lives

    if case is None:
        raise UnusedError(
            ("preloads",),
            "a bearing pair ('bearing' 7205BDB, or 'arrangement' DB or DF), whose table life "
            "runs over them; without one",
        )
    if name != "life":
        param = "arrangement" if "arrangement" in case.given else "bearing"
        raise ConflictError(
            param, f"table {name}", f"a bearing pair has no table over z; {RADIAL_ONLY}"
        )
    rows = "its rows are preloads ('preloads')"
    for param, given, why in (
        ("preload", "preload" in case.given, rows),
        (
            "bearing",
            "preload" not in case.given and case.preload is not None,
            f"its preload class {case.preload}: {rows}; give the designation without the class",
        ),
        ("clearances", clearances is not None, "a pair's rows are preloads ('preloads')"),
        ("z_max", z_max is not None, "it is one pair, not a table over z"),
        ("method", method is not None, "the life comes from the exact model only"),
    ):
        if given:
            raise ConflictError(param, "table life of a pair", why)
    if (case.arrangement or "").upper() == "DT":  # before the rows: no preload would do
        param = "arrangement" if "arrangement" in case.given else "bearing"
        raise InputError(
            param,
            "a tandem pair (DT) is not preloaded in itself (it is preloaded against another "
            "bearing): table life of a pair runs over the preload of DB or DF",
        )
    if preloads is None:
        raise MissingError(
            "preloads",
            "table life of a pair runs over the preload; give the rows, e.g. 'preloads' "
            "0,100N,300N,1kN",
        )
    if "load" not in case.given:
        raise MissingError("load", "table life needs F_r (N)")
    result = life_against_preload_case(case, preloads)
    return Tabled("pair", result, speed_pair_lives(result.cases, case.speed))
