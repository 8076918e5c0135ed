"""A bearing under load: a registered model's load distribution, plus what a catalogue bearing
adds (Hertz contact pressures at the heaviest ball, the basic rating life, the allowable load).

This is the computation behind ``bearingload solve``: one :class:`LoadedCase` per model and per
clearance (a class taken at its min, mean and max gives three). The reports only print it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload.bearings.life import (
    BALL_LIFE_EXPONENT,
    ROLLER_LIFE_EXPONENT,
    allowable_load,
    rating_life,
)
from bearingload.models.case import Case, Result, scalar
from bearingload.models.registry import get_method

if TYPE_CHECKING:  # the catalogue is imported only where a bearing is resolved
    from bearingload.bearings.resolve import ResolvedBearing

#: Life for the allowable load when none is given: Kuzmenko (2010) §3.2, 36e6 revolutions. [rev]
DEFAULT_REVOLUTIONS = 36e6


@dataclass(frozen=True)
class LoadedCase:
    """One solved case.

    Attributes
    ----------
    result : Result
        The model's answer (``result.case`` holds the inputs; ``result.model`` the model's own
        result, e.g. every ball's load for the exact model).
    bearing : ResolvedBearing or None
        The bearing at this case's clearance; None for a ring given by z and K alone.
    p_max_inner, p_max_outer : float or None
        Maximum Hertz contact pressure at the heaviest ball load (known geometry only). [MPa]
    rating_life : float or None
        Basic rating life ``(C/P)^p`` (p = 3 balls, 10/3 rollers; known C only). [10^6 rev]
    allowable_load : float or None
        ``C/(L/10^6)^(1/3)`` for ``revolutions`` (known C only). [N]
    revolutions : float or None
        The life L of the allowable load. [rev]
    warnings : tuple of str
        Findings of :func:`bearingload.bearings.checks.case_warnings` (static safety, load above
        C0, contact pressure, one loaded element, clearance range); empty when all is well.
    static_safety : float or None
        s0 = C0/P0 with P0 = F_r (ISO 76; known C0 only). [-]
    reference_rating_life : float or None
        ISO/TS 16281 L10r from the exact ball loads (set by
        :func:`bearingload.studies.reference_life.with_reference_lives`). [10^6 rev]
    rotating : str or None
        The ring rotating relative to the load for ``reference_rating_life``.
    """

    result: Result
    bearing: ResolvedBearing | None = None
    p_max_inner: float | None = None
    p_max_outer: float | None = None
    rating_life: float | None = None
    allowable_load: float | None = None
    revolutions: float | None = None
    warnings: tuple[str, ...] = ()
    static_safety: float | None = None
    reference_rating_life: float | None = None
    rotating: str | None = None

    @property
    def clearance_pick(self) -> str | None:
        return None if self.bearing is None else self.bearing.clearance_pick


def solve_ring(
    methods: Sequence[str],
    balls: int,
    load: float,
    stiffness: float,
    clearance: float = 0.0,
    cage_angle: float = 0.0,
    exponent: float = 1.5,
) -> list[LoadedCase]:
    """Solve one ring given by z and K by each of ``methods`` (registry names).

    Units: N, N/mm^m, mm (G_r), degrees. The inputs are checked once.
    """
    from bearingload.bearings.checks import element_warnings

    case = Case.of(balls, load, stiffness, clearance, cage_angle, exponent)
    out = []
    for m in methods:
        r = get_method(m).run(case)
        out.append(LoadedCase(r, warnings=tuple(element_warnings(r, balls))))
    return out


def solve_bearing(
    bearings: Sequence[ResolvedBearing],
    load: float,
    cage_angle: float = 0.0,
    methods: Sequence[str] = ("exact",),
    revolutions: float = DEFAULT_REVOLUTIONS,
) -> list[LoadedCase]:
    """Solve each resolved bearing (one per clearance) by each of ``methods``.

    Parameters
    ----------
    bearings : sequence of ResolvedBearing
        From :func:`bearingload.bearings.resolve.resolve_bearing` (and ``with_clearance``).
    load : float
        Radial load F_r. [N]
    cage_angle : float
        Angle of ball 1 from the load line. [°]
    methods : sequence of str
        Registered model names.
    revolutions : float
        Life L for the allowable load ``C/(L/10^6)^(1/3)``. [rev]

    Returns
    -------
    list of LoadedCase
        Bearing by bearing, model by model. Contact pressures at each model's heaviest ball load
        where the geometry is known; life and allowable load where C is known.
    """
    out = []
    for b in bearings:
        case = Case.of(b.balls, load, b.stiffness, b.clearance, cage_angle, b.exponent)
        for m in methods:
            out.append(_with_bearing(get_method(m).run(case), b, load, revolutions))
    return out


def _with_bearing(r: Result, b: ResolvedBearing, load: float, revolutions: float) -> LoadedCase:
    from bearingload.bearings.checks import case_warnings, max_contact_pressures, static_safety

    pressures = max_contact_pressures(b, float(r.q_max))  # balls: Hertz; rollers: line contact
    p_i, p_o = pressures if pressures is not None else (None, None)
    life = allow = None
    if b.C:
        p = ROLLER_LIFE_EXPONENT if b.kind == "roller" else BALL_LIFE_EXPONENT
        life = float(rating_life(b.C, load, p))
        allow = float(allowable_load(b.C, revolutions / 1e6, p))
    warnings = tuple(case_warnings(b, load, r))
    return LoadedCase(r, b, p_i, p_o, life, allow, revolutions if b.C else None, warnings,
                      static_safety(b.C0, load))  # fmt: skip


def collect_warnings(cases: Sequence[LoadedCase]) -> list[str]:
    """The warnings of several cases (models, clearances), each once, in order.

    A warning every case shares is given as it is; one that only some cases carry is prefixed
    with the case's method and clearance pick (``"palmgren, G_r max: ..."``).
    """
    seen: list[str] = []
    methods = len({c.result.method for c in cases}) > 1
    picks = len({c.clearance_pick for c in cases}) > 1
    for c in cases:
        for w in c.warnings:
            if not all(w in other.warnings for other in cases):
                parts = ([c.result.method] if methods else []) + (
                    [f"G_r {c.clearance_pick}"] if picks else []
                )
                w = f"{', '.join(parts)}: {w}"
            if w not in seen:
                seen.append(w)
    return seen


def case_values(lc: LoadedCase) -> dict[str, Any]:
    """Every quantity of one case under its key of :mod:`bearingload.reports.quantities`.

    Inputs first, then the answer; ``None`` where the model or the bearing does not give it.
    """
    r, c = lc.result, lc.result.case
    b = lc.bearing
    if np.ndim(r.k) != 0:
        raise ValueError("case_values describes one case; solve one case per LoadedCase")
    return {
        "bearing": None if b is None else (b.designation or "given by hand"),
        "method": r.method,
        "balls": int(c.balls),
        "load": float(c.load),
        "stiffness": float(c.stiffness),
        "clearance": float(c.clearance),
        "clearance_pick": lc.clearance_pick,
        "cage_angle": float(c.cage_angle),
        "exponent": float(c.exponent),
        "q_max": r.q_max,
        "k": r.k,
        "K_Q": r.K_Q,
        "loaded_balls": r.loaded_balls,
        "load_zone": r.load_zone,
        "x": r.x,
        "y": r.y,
        "stiffness_radial": r.stiffness_radial,
        "approach_max": None if r.x is None else (r.q_max / c.stiffness) ** (1.0 / c.exponent),
        "epsilon": scalar(getattr(r.model, "epsilon", None)),
        "valid": r.valid,
        "p_max_inner": lc.p_max_inner,
        "p_max_outer": lc.p_max_outer,
        "rating_life": lc.rating_life,
        "allowable_load": lc.allowable_load,
        "revolutions": None if lc.revolutions is None else lc.revolutions / 1e6,
        "static_safety": lc.static_safety,
        "reference_rating_life": lc.reference_rating_life,
        "rotating": lc.rotating,
    }


def with_relative_errors(records: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Add ``relative_error = Q_max/Q_max,exact - 1`` [-] to every record that has an exact
    record at the same bearing and clearance (the exact one gets 0); others get ``None``."""
    exact = {
        (r["bearing"], r["clearance"], r["clearance_pick"]): r["q_max"]
        for r in records
        if r["method"] == "exact"
    }
    out = []
    for r in records:
        ref = exact.get((r["bearing"], r["clearance"], r["clearance_pick"]))
        out.append(r | {"relative_error": None if ref is None else r["q_max"] / ref - 1.0})
    return out
