"""The bearing of a case: the resolved catalogue bearing (or the same bearing at the min, mean
and max of its clearance class), or a ring given by its balls and stiffness; the inputs a case
would ignore, refused."""

from __future__ import annotations

from collections.abc import Collection
from typing import Any

from bearingload.errors import ConflictError, InputError, MissingError, UnusedError
from bearingload.plan.case import BEARING_ONLY, Case

#: What the inputs a ring given by z and K ignores need.
NEED_BEARING = (
    "a bearing designation or the ball geometry ('ball_diameter' and 'pitch_diameter'): with "
    "'balls' and 'stiffness' alone"
)


def refuse_unused(
    case: Case, names: Collection[str] = BEARING_ONLY, need: str = NEED_BEARING
) -> None:
    """Refuse the inputs ``names`` given (a value) and a clearance pick given: ``need`` says
    what they need, without which they would be ignored."""
    unused = [n for n in names if getattr(case, n) is not None]
    if "clearance_pick" in case.given:
        unused.append("clearance_pick")
    if unused:
        raise UnusedError(tuple(unused), need)


def refuse_range(case: Case, where: str) -> None:
    """Refuse the clearance pick 'range' where the command solves one clearance."""
    from bearingload.bearings.clearance import RANGE

    if case.clearance_pick == RANGE:
        raise InputError(
            "clearance_pick",
            f"{RANGE!r} (min, mean and max side by side) is solve's; {where} takes min, mean or "
            "max",
        )


def refuse_tilt_radius(case: Case) -> None:
    """Refuse a tilt radius where the radial engine solves the case: it has no tilt."""
    if case.tilt_radius is not None:
        raise InputError(
            "tilt_radius",
            "it is the lever of the inner ring's tilt, and only the combined load "
            "('axial_load', 'moment', 'moment_cross', 'misalignment') tilts the ring",
        )


def ring_by_hand(case: Case, stiffness: float | None) -> tuple[int, float]:
    """(z, K [N/mm^m]) of a ring given by hand, both required."""
    if case.balls is None:
        raise MissingError("balls", "or give a 'bearing' designation")
    if stiffness is None:
        raise MissingError(
            "stiffness",
            "or give a 'bearing' designation, or 'ball_diameter' and 'pitch_diameter'",
        )
    return case.balls, stiffness


def resolve_case(case: Case) -> tuple[int, float, float, float, str]:
    """(z, K [N/mm^m], G_r [mm], m, context note) of one ring from a bearing or hand-given
    balls, as solve resolves it."""
    k_given = case.stiffness_value()
    if case.by_hand:
        from bearingload.bearings.clearance import clearance_length

        z, k = ring_by_hand(case, k_given)
        refuse_unused(case)
        return z, k, clearance_length(case.clearance), case.exponent_or(1.5), ""
    b = resolve_bearings(case, k_given)[0]
    return b.balls, float(b.stiffness), b.clearance, b.exponent, bearing_context(b)


def resolve_bearings(case: Case, stiffness: float | None, **override: Any) -> list[Any]:
    """The resolved bearing, or the same bearing at the min, mean and max of its class (the
    clearance pick 'range'): :func:`bearingload.bearings.resolve.resolve_bearings` of the case's
    arguments (``stiffness`` in N/mm^m; ``override`` replaces arguments)."""
    from bearingload.bearings.plausible import BEARING_SCALE, refuse_implausible_bare
    from bearingload.bearings.resolve import resolve_bearings as resolve

    arguments = case.bearing_arguments(stiffness) | override
    found = resolve(arguments.pop("designation"), **arguments)
    bare = {n: float(getattr(case, n)) for n in case.bare if n in BEARING_SCALE}
    refuse_implausible_bare(found[0], bare)
    if "clearance_pick" in case.given and found[0].clearance_class is None:
        raise InputError(
            "clearance_pick",
            "it picks the min, mean or max of a clearance class ('clearance' CN, C3 ... of a "
            f"catalogue bearing); {_no_class(found[0])}, so it would be ignored",
        )
    return found


def _no_class(b: Any) -> str:
    """Why the resolved bearing ``b`` has no clearance class to pick in."""
    if b.contact_angle is not None:
        return "an angular-contact bearing has no radial clearance"
    return f"this case's clearance is one value, no class (G_r = {b.clearance * 1000:g} µm)"


def bearing_context(b: Any) -> str:
    """One note naming where z, K and G_r of a resolved bearing come from."""
    label = f"bearing {b.designation}" if b.designation else "the given ball set"
    k_src = "given" if b.stiffness_given else ("Palmgren" if b.kind == "roller" else "exact Hertz")
    g_src = next(p.source for p in b.provenance if p.key == "clearance")
    return f"z and K ({k_src}) of {label}; G_r: {g_src}."


def check_rotating(case: Case, b: Any, methods: list[str]) -> None:
    """Refuse a rotating ring named where neither a reference rating life L10r (a roller
    bearing, no ball geometry, no C_r, or no exact ball loads) nor defect frequencies (no speed,
    no ball geometry) are computed for it to select the ring of."""
    if case.rotating is None:
        return
    if case.speed is not None and b.kind == "ball" and b.has_geometry:
        return  # it names the ring of the defect frequencies at the speed
    method = "exact" if "exact" in methods else methods[0]
    if b.kind != "ball":
        why = f"L10r is computed for ball bearings only ({b.designation} is a {b.kind} bearing)"
    elif not b.has_geometry:
        why = "L10r needs the ball geometry (a bearing, or 'ball_diameter' and 'pitch_diameter')"
    elif not (case.dynamic_rating or b.C):
        why = "L10r needs the dynamic load rating C_r: give 'dynamic_rating'"
    elif method != "exact":
        why = f"L10r needs the exact ball loads ('method' {method} gives none)"
    else:
        return
    raise InputError(
        "rotating",
        "it names the rotating ring for the reference rating life L10r (ISO/TS 16281) and, "
        f"with 'speed', the defect frequencies, and {why}",
    )


def with_ratings(bearings: list[Any], case: Case) -> list[Any]:
    """The resolved bearings with C_0 replaced by the static rating given; the dynamic rating
    checked for its range (the combined engines take it as an argument)."""
    if case.dynamic_rating is not None:
        bearings[0].with_dynamic_rating(case.dynamic_rating)
    if case.static_rating is None:
        return bearings
    return [b.with_static_rating(case.static_rating) for b in bearings]


def with_contact_angle(bearings: list[Any], case: Case, where: str) -> list[Any]:
    """The bearings with the design contact angle given by hand (no clearance), refused beside
    a clearance or a designation (``where``: what the angle is given with)."""
    import dataclasses

    if case.contact_angle is None:
        return bearings
    why = "the design contact angle fixes the geometry of an angular-contact bearing"
    case.refuse(("clearance",), where, why + " (no clearance)")
    if case.bearing is not None:
        raise ConflictError(
            "contact_angle",
            "a bearing designation",
            "give the angular-contact ring by hand ('balls', 'ball_diameter', 'pitch_diameter')",
        )
    return [
        dataclasses.replace(b, contact_angle=case.contact_angle, clearance=0.0) for b in bearings
    ]


def pair_bearing(case: Case) -> Any:
    """One bearing of a pair (resolved, with its ratings); refused unless it is an
    angular-contact bearing."""
    b = with_ratings(resolve_bearings(case, case.stiffness_value()), case)[0]
    b = with_contact_angle([b], case, "a bearing pair")[0]
    if b.contact_angle is None:
        raise InputError(
            "arrangement",
            f"a pair {case.arrangement} is two angular-contact ball bearings; give an "
            "angular-contact designation (7205B, 7205BDB) or a ring by hand with "
            "'contact_angle'",
        )
    return b
