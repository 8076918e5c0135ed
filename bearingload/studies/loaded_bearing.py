"""A bearing under load: a registered model's load distribution, plus what a catalogue bearing
adds (Hertz contact pressures at the heaviest ball, the basic rating life, the allowable load).

This is the computation behind ``bearingload solve``: one :class:`LoadedCase` per model and per
clearance (a class taken at its min, mean and max gives three). The reports only print it.
"""

from __future__ import annotations

from collections.abc import Sequence
from types import SimpleNamespace
from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload.bearings.life import (
    BALL_LIFE_EXPONENT,
    ROLLER_LIFE_EXPONENT,
    allowable_load,
    rating_life,
)
from bearingload.bearings.mounting import result_fields
from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.models.case import Case, Result
from bearingload.models.registry import get_method
from bearingload.numerics import scalar_out

if TYPE_CHECKING:  # the catalogue is imported only where a bearing is resolved
    from bearingload.bearings.resolve import ResolvedBearing

#: Life for the allowable load when none is given: Kuzmenko (2010) §3.2, 36e6 revolutions. [rev]
DEFAULT_REVOLUTIONS = 36e6


@dataclass(frozen=True)
class LoadedCase:
    """One solved case, or many solved at once (one bearing or ring, one method: inputs given as
    arrays); then each number below is an array (a list for ``static_safety``) over the cases,
    and ``warnings`` holds one tuple per case.

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
    p_max_inner: Any = None
    p_max_outer: Any = None
    rating_life: Any = None
    allowable_load: Any = None
    revolutions: Any = None
    warnings: tuple[Any, ...] = ()
    static_safety: Any = None
    reference_rating_life: Any = None
    rotating: str | None = None

    @property
    def clearance_pick(self) -> str | None:
        return None if self.bearing is None else self.bearing.clearance_pick


def solve_ring(
    methods: Sequence[str],
    balls: Any,
    load: Any,
    stiffness: Any,
    clearance: Any = 0.0,
    cage_angle: Any = 0.0,
    exponent: Any = 1.5,
) -> list[LoadedCase]:
    """Solve one ring given by z and K by each of ``methods`` (registry names); arrays of inputs
    solve many rings in one call of each model (one :class:`LoadedCase` per method, its fields
    arrays over the rings).

    Units: N, N/mm^m, mm (G_r), degrees. The inputs are checked once.
    """
    from bearingload.bearings.checks import element_warnings

    case = Case.of(balls, load, stiffness, clearance, cage_angle, exponent)
    z = np.broadcast_to(np.asarray(balls), case.shape).ravel().tolist()
    out = []
    for m in methods:
        r = get_method(m).run(case)
        loaded = _per_case(r.loaded_balls, case.shape)
        seen: dict[tuple[Any, int], tuple[str, ...]] = {}  # the finding of each (loaded, z)
        found = []
        for key in zip(loaded, z, strict=True):
            if key not in seen:
                seen[key] = tuple(element_warnings(SimpleNamespace(loaded_balls=key[0]), key[1]))
            found.append(seen[key])
        out.append(LoadedCase(r, warnings=found[0] if r.case.shape == () else tuple(found)))
    return out


def solve_bearing(
    bearings: Sequence[ResolvedBearing],
    load: Any,
    cage_angle: Any = 0.0,
    methods: Sequence[str] = ("exact",),
    revolutions: Any = DEFAULT_REVOLUTIONS,
) -> list[LoadedCase]:
    """Solve each resolved bearing (one per clearance) by each of ``methods``.

    Parameters
    ----------
    bearings : sequence of ResolvedBearing
        From :func:`bearingload.bearings.resolve.resolve_bearing` (and ``with_clearance``).
    load : float or array_like
        Radial load F_r; an array solves every load in one call of each model. [N]
    cage_angle : float or array_like
        Angle of ball 1 from the load line. [°]
    methods : sequence of str
        Registered model names.
    revolutions : float or array_like
        Life L for the allowable load ``C/(L/10^6)^(1/3)``. [rev]

    Returns
    -------
    list of LoadedCase
        Bearing by bearing, model by model (with array inputs, each holds arrays over the
        cases). Contact pressures at each model's heaviest ball load where the geometry is
        known; life and allowable load where C is known.
    """
    out = []
    for b in bearings:
        if b.contact_angle is not None:  # the radial engine has every ball at 0°
            raise InputError(
                "bearing",
                f"{b.designation or 'the ring'} is an angular-contact bearing (contact angle "
                f"{b.contact_angle:g}°): it is solved by the combined engine only (give an axial "
                "load, 0 allowed)",
            )
        case = Case.of(b.balls, load, b.stiffness, b.clearance, cage_angle, b.exponent)
        for m in methods:
            out.append(_with_bearing(get_method(m).run(case), b, load, revolutions))
    return out


def _with_bearing(r: Result, b: ResolvedBearing, load: Any, revolutions: Any) -> LoadedCase:
    """What the bearing adds to the solved case(s) ``r``: contact pressures, L10, allowable
    load, s0 (one case: floats; many: arrays) and the checks of every case."""
    from bearingload.bearings.checks import case_warnings, contact_pressures, static_safety

    q = r.q_max
    pressures = contact_pressures(b, q)  # balls: Hertz; rollers: line contact
    p_i, p_o = pressures if pressures is not None else (None, None)
    life = allow = revs = None
    if b.C:
        p = ROLLER_LIFE_EXPONENT if b.kind == "roller" else BALL_LIFE_EXPONENT
        life = scalar_out(rating_life(b.C, load, p))
        allow = scalar_out(allowable_load(b.C, np.asarray(revolutions) / 1e6, p))
        revs = revolutions
    shape = r.case.shape
    loads = np.broadcast_to(load, shape).ravel().tolist()
    inner = None if p_i is None else np.broadcast_to(p_i, shape).ravel().tolist()
    outer = None if p_o is None else np.broadcast_to(p_o, shape).ravel().tolist()
    found = [tuple(case_warnings(b, loads[i], one, None if inner is None or outer is None
                                 else (inner[i], outer[i])))
             for i, one in enumerate(_each_case(r))]  # fmt: skip
    s0 = [static_safety(b.C0, f) for f in loads]
    if shape == ():
        return LoadedCase(r, b, p_i, p_o, life, allow, revs, found[0], s0[0])
    return LoadedCase(r, b, p_i, p_o, life, allow, revs, tuple(found), s0)


def _each_case(r: Result) -> list[Any]:
    """Each case of ``r`` as the checks read it (``q_max`` [N], ``loaded_balls``)."""
    q = _per_case(r.q_max, r.case.shape)
    loaded = _per_case(r.loaded_balls, r.case.shape)
    return [SimpleNamespace(q_max=a, loaded_balls=b) for a, b in zip(q, loaded, strict=True)]


def _per_case(value: Any, shape: tuple[int, ...]) -> list[Any]:
    """A quantity of every case as a list (None for each where not given)."""
    if value is None:
        return [None] * int(np.prod(shape))
    return np.broadcast_to(value, shape).ravel().tolist()


def collect_warnings(cases: Sequence[LoadedCase]) -> list[str]:
    """The warnings of several cases (models, clearances), each once, in order.

    A warning every case shares is given as it is; one that only some cases carry is prefixed
    with the case's method and clearance pick (``"palmgren, G_r max: ..."``).
    """
    methods = len({c.result.method for c in cases}) > 1
    picks = len({c.clearance_pick for c in cases}) > 1
    labels = [
        ", ".join(
            ([c.result.method] if methods else []) + ([f"G_r {c.clearance_pick}"] if picks else [])
        )
        for c in cases
    ]
    return labelled_warnings([c.warnings for c in cases], labels)


def labelled_warnings(found: Sequence[Sequence[str]], labels: Sequence[str]) -> list[str]:
    """The warnings ``found`` of several cases, each once, in order: one that only some cases
    carry is prefixed with its case's label (where it has one), ``"G_r max: ..."``."""
    seen: list[str] = []
    for own, label in zip(found, labels, strict=True):
        for w in own:
            if label and not all(w in other for other in found):
                w = f"{label}: {w}"
            if w not in seen:
                seen.append(w)
    return seen


def case_values(lc: LoadedCase) -> dict[str, Any]:
    """Every quantity of one case under its key of :mod:`bearingload.reports.quantities`.

    Inputs first, then the answer; ``None`` where the model or the bearing does not give it.
    """
    if np.ndim(lc.result.k) != 0:
        raise ValueError("case_values describes one case; solve one case per LoadedCase")
    return {k: v if v is None or isinstance(v, str) else _one(v)
            for k, v in case_columns(lc).items()}  # fmt: skip


def _one(v: Any) -> Any:
    return v[0] if isinstance(v, list) else np.asarray(v).reshape(-1)[0].item()


def case_columns(lc: LoadedCase) -> dict[str, Any]:
    """The quantities of :func:`case_values` of every case of ``lc`` (one case or many solved
    at once): a numpy array or a list over the cases, text, or None where not given."""
    r, c = lc.result, lc.result.case
    b = lc.bearing
    n = int(np.prod(c.shape))

    def col(value: Any, dtype: Any = float) -> Any:
        if value is None or isinstance(value, (str, list)):
            return value
        return np.broadcast_to(np.asarray(value, dtype=dtype), c.shape).ravel()

    return {
        "bearing": None if b is None else (b.designation or "given by hand"),
        "method": r.method,
        "balls": col(c.balls, np.int64),
        "load": col(c.load),
        "stiffness": col(c.stiffness),
        "clearance": col(c.clearance),
        "clearance_pick": lc.clearance_pick,
        "cage_angle": col(c.cage_angle),
        "exponent": col(c.exponent),
        "q_max": col(r.q_max),
        "k": col(r.k),
        "K_Q": col(r.K_Q),
        "loaded_balls": col(r.loaded_balls, np.int64),
        "load_zone": col(r.load_zone),
        "x": col(r.x),
        "y": col(r.y),
        "stiffness_radial": col(r.stiffness_radial),
        "approach_max": None
        if r.x is None
        else col((np.asarray(r.q_max) / c.stiffness) ** (1.0 / np.asarray(c.exponent))),
        "epsilon": col(getattr(r.model, "epsilon", None)),
        "valid": col(r.valid, bool),
        "p_max_inner": col(lc.p_max_inner),
        "p_max_outer": col(lc.p_max_outer),
        "rating_life": col(lc.rating_life),
        "allowable_load": col(lc.allowable_load),
        "revolutions": None if lc.revolutions is None else col(np.asarray(lc.revolutions) / 1e6),
        "static_safety": lc.static_safety
        if isinstance(lc.static_safety, list)
        else [lc.static_safety] * n,
        "reference_rating_life": col(lc.reference_rating_life),
        "rotating": lc.rotating,
        **{k: col(v) for k, v in result_fields(b).items()},
        **_matrix_columns(r),
    }


def _matrix_columns(r: Result) -> dict[str, Any]:
    """The 5x5 ``stiffness_matrix`` of the exact model under its csv columns
    (:func:`bearingload.studies.matrix.radial_matrix_columns`); none for the other methods,
    which give no matrix."""
    if r.method != "exact":
        return {}
    from bearingload.studies.matrix import radial_matrix_columns

    return radial_matrix_columns(r.model.stiffness_matrix)


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
