"""From the bearing and condition options of ``solve`` and ``sweep`` to one case of the engine."""

from __future__ import annotations

from typing import Any

import click

from bearingload.cli.options import stiffness_value


def resolve_case(
    bearing: str | None,
    balls: int | None,
    stiffness: str | None,
    clearance: Any,
    pick: str,
    exponent: float,
    geometry: dict[str, Any],
) -> tuple[int, float, float, float, str]:
    """(z, K [N/mm^m], G_r [mm], m, context note) from a BEARING or hand-given balls, as solve."""
    k_given = stiffness_value(stiffness, exponent)
    if bearing is None and geometry["ball_diameter"] is None and geometry["pitch_diameter"] is None:
        from bearingload.bearings.clearance import clearance_length

        if balls is None:
            raise click.UsageError(
                "Missing option '--balls' / '-z' (or give a BEARING designation)"
            )
        if k_given is None:
            raise click.UsageError(
                "Missing option '--stiffness' / '-K' (or give a BEARING designation, or "
                "--ball-diameter and --pitch-diameter)"
            )
        return balls, k_given, clearance_length(clearance), exponent, ""
    from bearingload.bearings.resolve import resolve_bearing

    b = resolve_bearing(
        bearing,
        balls=balls,
        stiffness=k_given,
        clearance=clearance,
        clearance_pick=pick,
        **geometry,
    )
    if exponent not in (1.5, b.exponent):  # 1.5, the option's default, also for rollers
        contact = (
            "a roller bearing (line contact) has m = 10/9"
            if b.kind == "roller"
            else "a ball bearing (Hertz point contact) has m = 1.5"
        )
        raise click.UsageError(
            f"Invalid value for '--exponent': {contact}; "
            "other exponents need --balls and --stiffness without a BEARING"
        )
    label = f"bearing {b.designation}" if b.designation else "the given ball set"
    k_src = "given" if b.stiffness_given else ("Palmgren" if b.kind == "roller" else "exact Hertz")
    g_src = next(p.source for p in b.provenance if p.key == "clearance")
    context = f"z and K ({k_src}) of {label}; G_r: {g_src}."
    return b.balls, float(b.stiffness), b.clearance, b.exponent, context
