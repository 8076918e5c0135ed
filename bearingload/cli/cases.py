"""From a command's :class:`~bearingload.cli.case_options.CaseOptions` to what the engines take:
the resolved bearings, or a ring given by z and K; the options a case would ignore, refused."""

from __future__ import annotations

from collections.abc import Collection
from typing import Any

import click

from bearingload.cli.case_options import BEARING_ONLY, CaseOptions

#: What the options a ring given by z and K ignores need.
NEED_BEARING = (
    "a BEARING or the ball geometry (--ball-diameter and --pitch-diameter): with --balls and "
    "--stiffness alone"
)


def refuse_unused(
    case: CaseOptions, names: Collection[str] = BEARING_ONLY, need: str = NEED_BEARING
) -> None:
    """Refuse the options ``names`` given (a value) and --clearance-pick given on the command
    line: ``need`` says what they need, without which they would be ignored (a batch file's
    clearance_pick column is refused alike)."""
    unused = [f"--{n.replace('_', '-')}" for n in names if getattr(case, n) is not None]
    if "clearance_pick" in case.given:
        unused.append("--clearance-pick")
    if unused:
        one = len(unused) == 1
        raise click.UsageError(
            f"{', '.join(unused)} {'needs' if one else 'need'} {need} "
            f"{'it' if one else 'they'} would be ignored"
        )


def refuse_range(case: CaseOptions, where: str) -> None:
    """Refuse --clearance-pick range where the command solves one clearance."""
    from bearingload.bearings.clearance import RANGE

    if case.clearance_pick == RANGE:
        raise click.UsageError(
            f"Invalid value for '--clearance-pick': {RANGE!r} (min, mean and max side by side) is "
            f"solve's; {where} takes min, mean or max"
        )


def refuse_tilt_radius(case: CaseOptions) -> None:
    """Refuse --tilt-radius where the radial engine solves the case: it has no tilt."""
    if case.tilt_radius is not None:
        raise click.UsageError(
            "Invalid value for '--tilt-radius': it is the lever of the inner ring's tilt, and "
            "only the combined load (--axial-load, --moment, --moment-cross, --misalignment) "
            "tilts the ring"
        )


def ring_by_hand(case: CaseOptions, stiffness: float | None) -> tuple[int, float]:
    """(z, K [N/mm^m]) of a ring given by hand, both required."""
    if case.balls is None:
        raise click.UsageError("Missing option '--balls' / '-z' (or give a BEARING designation)")
    if stiffness is None:
        raise click.UsageError(
            "Missing option '--stiffness' / '-K' (or give a BEARING designation, or "
            "--ball-diameter and --pitch-diameter)"
        )
    return case.balls, stiffness


def resolve_case(case: CaseOptions) -> tuple[int, float, float, float, str]:
    """(z, K [N/mm^m], G_r [mm], m, context note) of one ring from a BEARING or hand-given balls,
    as solve resolves it."""
    k_given = case.stiffness_value()
    if case.by_hand:
        from bearingload.bearings.clearance import clearance_length

        z, k = ring_by_hand(case, k_given)
        refuse_unused(case)
        return z, k, clearance_length(case.clearance), case.exponent_or(1.5), ""
    b = resolve_bearings(case, k_given)[0]
    return b.balls, float(b.stiffness), b.clearance, b.exponent, bearing_context(b)


def resolve_bearings(case: CaseOptions, stiffness: float | None, **override: Any) -> list[Any]:
    """The resolved bearing, or the same bearing at the min, mean and max of its class
    (--clearance-pick range): :func:`bearingload.bearings.resolve.resolve_bearings` of the
    case's arguments (``stiffness`` in N/mm^m; ``override`` replaces arguments)."""
    from bearingload.bearings.plausible import BEARING_SCALE, refuse_implausible_bare
    from bearingload.bearings.resolve import resolve_bearings as resolve

    arguments = case.bearing_arguments(stiffness) | override
    found = resolve(arguments.pop("designation"), **arguments)
    bare = {n: float(getattr(case, n)) for n in case.bare if n in BEARING_SCALE}
    refuse_implausible_bare(found[0], bare)
    if "clearance_pick" in case.given and found[0].clearance_class is None:
        raise click.UsageError(
            "Invalid value for '--clearance-pick': it picks the min, mean or max of a clearance "
            f"class (-G CN, C3 ... of a catalogue bearing); {_no_class(found[0])}, so it would "
            "be ignored"
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


def check_rotating(case: CaseOptions, b: Any, methods: list[str]) -> None:
    """Refuse --rotating where neither a reference rating life L10r (a roller bearing, no ball
    geometry, no C_r, or no exact ball loads) nor defect frequencies (no --speed, no ball
    geometry) are computed for it to select the ring of."""
    if case.rotating is None:
        return
    if case.speed is not None and b.kind == "ball" and b.has_geometry:
        return  # it names the ring of the defect frequencies at the speed
    from bearingload.studies.reference_life import rotating_refusal

    why = rotating_refusal(b, case.dynamic_rating, "exact" if "exact" in methods else methods[0])
    if why is not None:
        raise click.UsageError(
            "Invalid value for '--rotating': it names the rotating ring for the reference rating "
            f"life L10r (ISO/TS 16281) and, with --speed, the defect frequencies, and {why}"
        )


def combined_cases(bearings: list[Any], case: CaseOptions) -> list[Any]:
    """Solve the resolved ``bearings`` (one per clearance) under the case's combined load: one
    :class:`bearingload.studies.combined_bearing.CombinedCase` each."""
    from bearingload.studies.combined_bearing import solve_combined_bearing

    if case.contact_angle is not None:  # an angular-contact ring given by hand
        import dataclasses

        why = "the design contact angle fixes the geometry of an angular-contact bearing"
        case.refuse(("clearance",), "--contact-angle", why + " (no clearance)")
        if case.bearing is not None:
            raise click.UsageError(
                "--contact-angle cannot be used with a bearing designation: give the "
                "angular-contact ring by hand (--balls, --ball-diameter, --pitch-diameter)"
            )
        bearings = [dataclasses.replace(b, contact_angle=case.contact_angle, clearance=0.0)
                    for b in bearings]  # fmt: skip
    return solve_combined_bearing(
        bearings,
        case.radial_load,
        cage_angle=case.cage_angle_deg(bearings[0].balls),
        **case.combined_arguments(),
        **case.dynamics_arguments(),
    )
