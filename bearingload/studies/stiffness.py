"""Radial stiffness of ball and roller bearings: the exact equilibrium against the crane paper's (2009) procedure.

The crane paper (radial stiffness of rolling bearings for crane dynamics, 2009) estimates a bearing's
stiffness in four steps (its conclusions): (20) the load of the most loaded element
``Q0 = 5 F_r/(i z cos α)``; (19) the other loads from it, ``Q_j = Q0 cos^m(j γ)`` with ``γ = 2π/z``
(22); (18) each element's stiffness ``c_j = Q_j/δ_j`` (its eq. 6, a secant); (21) the bearing's
stiffness as the sum ``c = cos α [c_0 + 2 Σ c_j cos(j γ)]`` over the loaded elements, times the
rows ``i``. The OCR of (19) and (21) lost their exponents; they are read here with the powers
that survive in the text (``cos^m`` in (19), single cosines in (21)).

The exact model (Kurochkin 1973; DOMAIN.md §1, §7): each row carries ``F_r/i``; an element at
angle ``φ`` with contact angle ``α`` is compressed normally by ``(x cos φ - e) cos α`` and pushes
radially with ``Q cos α cos φ``, so a row is the engine's ring with the radial element stiffness
``K cos^(m+1) α`` (axial displacement held zero, as in a double-row or paired bearing). Tangent
stiffness ``dF_r/dx`` comes from the engine's analytic stiffness matrix, secant ``F_r/x``.
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np

from bearingload import validate
from bearingload.constants import KGF
from bearingload.contact.hertz import LINE_EXPONENT, roller_stiffness
from bearingload.errors import InputError
from bearingload.models.equilibrium import solve
from bearingload.reports.render import Column, Table

SOURCE = "Crane-bearing stiffness (2009), eqs. (19)-(22)"


class RadialStiffness(NamedTuple):
    """Radial stiffness of a bearing from the exact equilibrium."""

    tangent: Any
    """dF_r/dx, F_y held 0. [N/mm]"""
    secant: Any
    """F_r/x. [N/mm]"""
    displacement: Any
    """Radial displacement x of the inner ring along the load. [mm]"""
    q_max: Any
    """Normal load of the most loaded element. [N]"""


def _angle(contact_angle: Any) -> np.ndarray:
    a = np.asarray(validate.finite("contact_angle", contact_angle), float)
    if np.any((a < 0) | (a >= 90)):
        raise InputError("contact_angle", "must be in [0, 90) degrees")
    return np.deg2rad(a)


def radial_stiffness(
    balls: Any,
    load: Any,
    stiffness: Any,
    clearance: Any = 0.0,
    cage_angle: Any = 0.0,
    exponent: Any = 1.5,
    rows: Any = 1,
    contact_angle: Any = 0.0,
) -> RadialStiffness:
    """Tangent and secant radial stiffness of a bearing from the exact equilibrium, vectorised.

    Parameters
    ----------
    balls : int or array_like
        Rolling elements per row ``z``. [-]
    load : float or array_like
        Radial load ``F_r`` on the whole bearing, > 0. [N]
    stiffness : float or array_like
        Element stiffness along the contact normal, both contacts, ``Q = K δ^m``. [N/mm^m]
    clearance : float or array_like
        Radial internal clearance ``G_r`` (negative = preload). [mm]
    cage_angle : float or array_like
        Angle of element 1 from the load line. [°]
    exponent : float or array_like
        ``m``: 3/2 balls, 10/9 rollers. [-]
    rows : int or array_like
        Number of rows ``i``. [-]
    contact_angle : float or array_like
        Contact angle ``α`` in [0, 90). [°]

    Examples
    --------
    Bearing 306 of Kuzmenko (2010): z = 8, K = 4700 kgf/mm^1.5, F_r = 300 kgf, zero clearance:

    >>> r = radial_stiffness(8, 300 * 9.80665, 4700 * 9.80665)
    >>> round(float(r.tangent)), round(float(r.secant))
    (41502, 27668)
    """
    i = np.asarray(validate.ball_count(rows))
    a = _angle(contact_angle)
    m = np.asarray(validate.exponent(exponent), float)
    k = np.asarray(validate.positive("stiffness", stiffness, "N/mm^m"), float)
    f = np.asarray(validate.positive("load", load, "N"), float)
    r = solve(balls, f / i, k * np.cos(a) ** (m + 1), clearance, cage_angle, m)
    out = RadialStiffness(
        tangent=i * r.stiffness_radial,
        secant=f / r.x,
        displacement=r.x,
        q_max=r.q_max / np.cos(a),
    )
    if np.ndim(out.tangent) == 0:
        return RadialStiffness(*(float(v) for v in out))
    return out


def roller_element_stiffness(roller_diameter: Any, effective_length: Any) -> Any:
    """Stiffness of one roller between two raceways from its geometry. [N/mm^(10/9)]

    Palmgren's line contact (``δ = 3.84e-5 Q^0.9/l^0.8`` per contact, both contacts in series;
    :func:`bearingload.contact.hertz.roller_stiffness`). Palmgren's formula has no diameter: the
    roller diameter is checked (> 0, [mm]) but does not enter; ``effective_length`` [mm].
    """
    validate.positive("roller_diameter", roller_diameter, "mm")
    return roller_stiffness(effective_length)


class Seed003Result(NamedTuple):
    """The crane paper's (2009) procedure, step by step."""

    q0: float
    """(20) Q0 = 5 F_r/(i z cos α). [N]"""
    loads: np.ndarray
    """(19) Q_j = Q0 cos^m(j γ), j = 0, 1, ... while j γ < 90°. [N]"""
    element_stiffness: np.ndarray
    """(6), (18) c_j = Q_j/δ_j, secant. [N/mm]"""
    stiffness: float
    """(21) i cos α [c_0 + 2 Σ_{j>=1} c_j cos(j γ)]. [N/mm]"""


def seed003_stiffness(
    balls: int,
    load: float,
    stiffness: float,
    exponent: float = 1.5,
    rows: int = 1,
    contact_angle: float = 0.0,
) -> Seed003Result:
    """The bearing stiffness by the crane paper's (2009) procedure (module docstring). Units as
    :func:`radial_stiffness`; zero clearance is implied by (19)."""
    z = int(validate.ball_count(balls))
    a = float(_angle(contact_angle))
    m = float(validate.exponent(exponent))
    k = float(validate.positive("stiffness", stiffness, "N/mm^m"))
    f = float(validate.positive("load", load, "N"))
    gamma = 2.0 * math.pi / z
    j = np.arange(0, int(math.ceil(z / 4.0)) + 1)
    j = j[j * gamma < math.pi / 2 - 1e-12]
    q0 = 5.0 * f / (int(rows) * z * math.cos(a))
    loads = q0 * np.cos(j * gamma) ** m
    delta = (loads / k) ** (1.0 / m)
    c = loads / delta
    total = int(rows) * math.cos(a) * (c[0] + 2.0 * float(np.sum(c[1:] * np.cos(j[1:] * gamma))))
    return Seed003Result(q0, loads, c, float(total))


#: The cases of the committed table: (label, z, load [N], K [N/mm^m], m, rows, α [°])
_K306 = 4700.0 * KGF  # Kuzmenko (2010), bearing 306, c = 4700 kgf/mm^1.5
_ROLLER = ("rollers z = 14, D_w = 10 mm, l_eff = 10 mm (illustrative)", 14, 10.0, 10.0)
CASES: tuple[tuple[str, int, float, float, float, int, float], ...] = (
    ("306, 100 kgf", 8, 100 * KGF, _K306, 1.5, 1, 0.0),
    ("306, 300 kgf", 8, 300 * KGF, _K306, 1.5, 1, 0.0),
    ("306, 1000 kgf", 8, 1000 * KGF, _K306, 1.5, 1, 0.0),
    ("306 balls, 2 rows, α = 15°, 600 kgf", 8, 600 * KGF, _K306, 1.5, 2, 15.0),
    ("306 balls, 2 rows, α = 40°, 600 kgf", 8, 600 * KGF, _K306, 1.5, 2, 40.0),
)


def _cases() -> list[tuple[str, int, float, float, float, int, float]]:
    label, z, d_w, length = _ROLLER
    k_roller = float(roller_element_stiffness(d_w, length))
    rollers = [
        (f"{label}, {load / 1e3:g} kN", z, load, k_roller, LINE_EXPONENT, 1, 0.0)
        for load in (5e3, 20e3, 50e3)
    ]
    return [*CASES, *rollers]


def comparison_rows() -> list[dict[str, Any]]:
    """Exact tangent/secant stiffness and Q_max against the crane paper's (2009) procedure for :data:`CASES`."""
    out = []
    for label, z, load, k, m, rows, alpha in _cases():
        exact = radial_stiffness(z, load, k, 0.0, 0.0, m, rows, alpha)
        paper = seed003_stiffness(z, load, k, m, rows, alpha)
        out.append(
            {
                "case": label,
                "load": load,
                "stiffness": k,
                "exponent": m,
                "q0_paper": paper.q0,
                "q_max": exact.q_max,
                "c_paper": paper.stiffness,
                "tangent": exact.tangent,
                "secant": exact.secant,
                "paper_over_tangent": float(paper.stiffness / exact.tangent),
                "paper_over_secant": float(paper.stiffness / exact.secant),
            }
        )
    return out


def stiffness_table() -> Table:
    """Committed table ``stiffness_crane2009``."""
    cols = [
        Column("case", "case", align="left"),
        Column("load", "F_r", "N", 5),
        Column("stiffness", "K", "N/mm^m", 5),
        Column("exponent", "m", "-", 4),
        Column("q0_paper", "Q0 crane paper (20)", "N", 5),
        Column("q_max", "Q_max exact", "N", 5),
        Column("c_paper", "c crane paper (21)", "N/mm", 5),
        Column("tangent", "tangent exact", "N/mm", 5),
        Column("secant", "secant exact", "N/mm", 5),
        Column("paper_over_tangent", "(21)/tangent", "-", 4),
        Column("paper_over_secant", "(21)/secant", "-", 4),
    ]
    return Table(
        title="Radial bearing stiffness: the crane paper's (2009) procedure against the exact equilibrium "
        "(zero clearance, a ball or roller under the load)",
        columns=cols,
        rows=comparison_rows(),
        notes=(
            "The crane paper (2009): Q0 = 5 F_r/(i z cos α) (20), Q_j = Q0 cos^m(jγ) (19), c_j = Q_j/δ_j (18), "
            "c = i cos α [c_0 + 2 Σ c_j cos(jγ)] (21), γ = 2π/z (22). Exact: each row carries "
            "F_r/i with radial element stiffness K cos^(m+1) α; tangent dF_r/dx, secant F_r/x.",
            "Why they differ: (a) the factor 5 in (20) is Stribeck's allowance for clearance; at "
            "zero clearance the exact z Q_max/F_r is 4.37 (balls) or 4.08 (rollers) for many "
            "elements, so Q0 is high and every c_j with it; (b) (21) projects each element once "
            "(cos jγ, cos α) where the radial stiffness needs the square of each projection; "
            "(c) (18) is a secant element stiffness, the tangent one is m times larger; (d) the "
            "loads (19) do not balance F_r. The errors partly cancel: for balls with α = 0 (21) "
            "lies between the exact secant and tangent (0.83 of the tangent); at α = 40° and for "
            "rollers it exceeds even the tangent (1.08 and 1.16 times). At zero clearance every "
            "stiffness scales as F_r^((m-1)/m), so the ratios do not depend on the load.",
            "Rollers: Palmgren's line contact per contact, both contacts in series "
            "(bearingload.contact.hertz.roller_stiffness); the roller set is illustrative.",
        ),
    )


def stiffness_rows() -> list[dict[str, Any]]:
    """The crane paper's (2009) printed constants against exact values (keys as ``kurochkin1973_rows``)."""
    rows = []
    for z, m in ((8, 1.5), (12, 1.5), (1000, 1.5), (14, LINE_EXPONENT), (1000, LINE_EXPONENT)):
        r = solve(z, 1.0, 1.0, 0.0, 0.0, m)
        computed = float(z * r.q_max)
        kind = "balls" if m == 1.5 else "rollers"
        rows.append(
            _row(
                f"eq. (20), factor 5 in Q0 = 5 F_r/(i z cos α), {kind}, z = {z}, zero clearance",
                "5",
                computed,
                1.0,
                "Stribeck's factor 5 allows for clearance and is not the zero-clearance value "
                f"z Q_max/F_r = {computed:.4g}",
            )
        )
    rows.append(
        _row(
            "eq. (8)-(9), elliptic integral J = 1.571 (circular contact)",
            "1.571",
            math.pi / 2,
            0.001,
            "",
        )
    )
    return rows


def _row(cell: str, printed: str, computed: float, resolution: float, cause: str) -> dict[str, Any]:
    from bearingload.studies.published import printed_row

    return printed_row(SOURCE, "procedure (19)-(22)", cell, printed, computed, resolution, cause)
