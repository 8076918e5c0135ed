"""From the bearing and condition options of ``solve`` and ``sweep`` to one case of the engine."""

from __future__ import annotations

from typing import Any

import click

from bearingload.cli.options import exponent_given, stiffness_value


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
    k_given = stiffness_value(stiffness, exponent, bearing)
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
        refuse_unused({option: geometry[key] for key, option in _BEARING_ONLY.items()})
        return balls, k_given, clearance_length(clearance), exponent, ""
    b = resolve_bearings(bearing, k_given, clearance, pick, exponent, balls=balls, **geometry)[0]
    return b.balls, float(b.stiffness), b.clearance, b.exponent, bearing_context(b)


#: Options only a bearing or its ball geometry uses (resolve_case's geometry keys).
_BEARING_ONLY = {"f_i": "--inner-conformity", "f_o": "--outer-conformity",
                 "modulus": "--modulus", "poisson": "--poisson"}  # fmt: skip


def refuse_unused(
    given: dict[str, Any],
    need: str = "a BEARING or the ball geometry (--ball-diameter and --pitch-diameter): with "
    "--balls and --stiffness alone",
) -> None:
    """Refuse the options (name -> value, None: not given) that only a BEARING or the ball
    geometry uses when neither is given, and --clearance-pick when it is given on the command
    line: with --balls and --stiffness alone they would be ignored (a batch file's
    clearance_pick column is refused alike)."""
    from click.core import ParameterSource

    unused = [name for name, value in given.items() if value is not None]
    ctx = click.get_current_context(silent=True)
    if ctx is not None and ctx.get_parameter_source("clearance_pick") not in (
        None, ParameterSource.DEFAULT
    ):  # fmt: skip
        unused.append("--clearance-pick")
    if unused:
        one = len(unused) == 1
        raise click.UsageError(
            f"{', '.join(unused)} {'needs' if one else 'need'} {need} "
            f"{'it' if one else 'they'} would be ignored"
        )


def bearing_context(b: Any) -> str:
    """One note naming where z, K and G_r of a resolved bearing come from."""
    label = f"bearing {b.designation}" if b.designation else "the given ball set"
    k_src = "given" if b.stiffness_given else ("Palmgren" if b.kind == "roller" else "exact Hertz")
    g_src = next(p.source for p in b.provenance if p.key == "clearance")
    return f"z and K ({k_src}) of {label}; G_r: {g_src}."


def resolve_bearings(
    bearing: str | None,
    k_given: float | None,
    clearance: Any,
    clearance_pick: str,
    exponent: float,
    **geometry: Any,
) -> list[Any]:
    """The resolved bearing, or the same bearing at the min, mean and max of its class
    (``clearance_pick`` ``range``), as ``solve`` and ``sweep`` resolve it."""
    from bearingload.bearings.resolve import resolve_bearing

    resolved = resolve_bearing(
        bearing,
        stiffness=k_given,
        clearance=clearance,
        clearance_pick="mean" if clearance_pick == "range" else clearance_pick,
        **geometry,
    )
    if exponent != resolved.exponent and (exponent != 1.5 or exponent_given()):  # 1.5: default
        contact = (
            "a roller bearing (line contact) has m = 10/9"
            if resolved.kind == "roller"
            else "a ball bearing (Hertz point contact) has m = 1.5"
        )
        raise click.UsageError(
            f"Invalid value for '--exponent': {contact}; "
            "other exponents need --balls and --stiffness without a BEARING"
        )
    if clearance_pick == "range" and resolved.clearance_range is None:
        raise click.UsageError(
            "Invalid value for '--clearance-pick': 'range' needs a clearance class "
            "(C2 CN C3 C4 C5), not a clearance length"
        )
    picks = ["min", "mean", "max"] if clearance_pick == "range" else []
    return [resolved.with_clearance(p) for p in picks] or [resolved]
