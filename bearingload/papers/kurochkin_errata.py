"""Every printed number of Kurochkin (1973), Tables 1-4 and Example 1, against the exact model.

The printed cells are copied, as printed, into ``data/kurochkin1973.csv`` (one row per cell, with
the table, row, column, inputs and the printed resolution). :func:`kurochkin1973_rows` recomputes
each one with :mod:`bearingload.papers.kurochkin` and says whether it agrees within its printed
rounding and, if not, the likely cause. Causes are classified by rules (a lost sign, a single
digit added, dropped or changed, an off-by-one last digit), never written per cell.

Two rows of the OCR text lost one cell (Table 2, T = 0.700, phi1 = 27°; Table 4, T = 0.195,
phi1 = 15°45'): the cells after it sit one place to the left, found by comparing the whole row
with the exact values; the data file records the alignment in its ``note`` column.
"""

from __future__ import annotations

import csv
import functools
import math
import os
from typing import Any

import numpy as np

from bearingload.constants import KGF
from bearingload.papers import kurochkin as ku

DATA = os.path.join(os.path.dirname(__file__), "data", "kurochkin1973.csv")

#: Kurochkin (1973), Example 1: bearing A640018. K [kgf/µm^1.5], P [kgf], D, d [mm]
EXAMPLE1 = {"balls": 7, "K_kgf_um": 0.45, "P_kgf": 2.5, "D": 10.731, "d": 3.969}


def read_cells() -> list[dict[str, str]]:
    """The printed cells of ``data/kurochkin1973.csv`` as text, in file order."""
    with open(DATA, encoding="utf-8", newline="") as fh:
        return list(csv.DictReader(fh))


def parse_printed(text: str, quantity: str) -> float | None:
    """A printed cell as a number (``None`` when the cell is empty); ψ as "73°23'" -> 73.383°."""
    text = text.strip()
    if not text:
        return None
    if quantity == "psi_deg":
        deg, _, rest = text.partition("°")
        minutes = rest.rstrip("'").strip()
        return float(deg) + (float(minutes) / 60.0 if minutes else 0.0)
    return float(text)


def example1_load_stiffness() -> tuple[float, float]:
    """``P`` [N] and ``K`` [N/mm^1.5] of Example 1 (0.45 kgf/µm^1.5 = 0.45 kgf/(1e-3 mm)^1.5)."""
    return EXAMPLE1["P_kgf"] * KGF, EXAMPLE1["K_kgf_um"] * KGF * 1e3**1.5


@functools.cache
def _row_values(balls: int, T: float) -> dict[str, Any]:
    angles = np.arange(1, 10) * 18.0 / balls
    _, f0p = ku.displacement(balls, T, angles)
    return {
        "psi": ku.exit_angle(balls, T),
        "f0p": 1e3 * np.asarray(f0p),
        "f0j": 1e3 * ku.fourier_sine(balls, T, 5),
    }


@functools.cache
def example1_nulls() -> tuple[float, ...]:
    """The T at which F01', F02', F03' vanish for n = 7 (Kurochkin 1973, Example 1, part 2). [-]

    Each is the zero nearest T = 1, the one he interpolates in Table 3 (bracket 0.70-1; F02'
    has a second zero near T = 0.44).
    """
    lo, hi = 0.70, 1.0
    return tuple(ku.harmonic_null_parameter(7, j, lo, hi) for j in (1, 2, 3))


def computed_value(cell: dict[str, str]) -> float:
    """The exact value of one printed cell, in the printed quantity's unit."""
    q = cell["quantity"]
    if cell["table"] == "Example 1":
        load, stiffness = example1_load_stiffness()
        if q == "T":
            g_r = 2.0 * float(cell["e_um"]) * 1e-3
            return float(ku.generalised_parameter(g_r, load, stiffness, 7))
        t_null = example1_nulls()[int(cell["harmonic"]) - 1]
        if q == "T_null":
            return t_null
        return float(ku.clearance_from_parameter(t_null, 7, load, stiffness)) / 2.0 * 1e3
    n, T = int(cell["balls"]), float(cell["T"])
    if q == "T":
        return T
    values = _row_values(n, T)
    if q == "psi_deg":
        return float(values["psi"])
    if q == "F0_prime_e3":
        return float(values["f0p"][int(cell["column"][3:]) - 1])
    return float(values["f0j"][int(cell["harmonic"]) - 1])


def _agrees(printed: float, computed: float, resolution: float) -> bool:
    return abs(printed - computed) <= 0.5 * resolution * (1.0 + 1e-9)


def _digit_variants(text: str) -> list[tuple[str, str]]:
    """Texts one digit away from ``text`` (digit dropped, added, changed, sign flipped)."""
    out = []
    body = text.lstrip("-")
    sign = text[: len(text) - len(body)]
    for i, ch in enumerate(body):
        if ch.isdigit():
            out.append((sign + body[:i] + body[i + 1 :], f"digit {ch} added in print"))
            for d in "0123456789":
                if d != ch:
                    out.append((sign + body[:i] + d + body[i + 1 :], f"digit {d} printed as {ch}"))
    for i in range(len(body) + 1):
        for d in "0123456789":
            out.append((sign + body[:i] + d + body[i:], f"digit {d} lost in print"))
    return out


def _interpolated_null(harmonic: int) -> float:
    """T where the printed F0j' of Table 3 change sign nearest T = 1, by linear interpolation."""
    pts = [
        (float(c["T_printed"]), float(c["printed"]))
        for c in read_cells()
        if c["table"] == "Table 3" and c["harmonic"] == str(harmonic)
    ]
    for (t0, f0), (t1, f1) in zip(pts[:-1], pts[1:], strict=True):
        if f0 > 0 >= f1:
            return t0 + (t1 - t0) * f0 / (f0 - f1)
    return math.nan


def _example1_cause(cell: dict[str, str], printed: float, computed: float) -> str | None:
    res, j = float(cell["resolution"]), int(cell["harmonic"] or 0)
    if cell["quantity"] == "T_null" and _agrees(printed, _interpolated_null(j), res):
        return "read by linear interpolation of the printed Table 3, whose F0j' are off"
    if cell["quantity"] == "e_null_um":
        t_printed = next(
            float(c["printed"])
            for c in read_cells()
            if c["quantity"] == "T_null" and c["harmonic"] == cell["harmonic"]
        )
        load, stiffness = example1_load_stiffness()
        e_from_t = float(ku.clearance_from_parameter(t_printed, 7, load, stiffness)) * 500.0
        if abs(printed - e_from_t) <= 2.5 * res:
            return f"follows from the printed T = {t_printed:g} by eq. (1.13)"
    return None


def _digit_cause(cell: dict[str, str], computed: float, last_digit: bool) -> str | None:
    q, res, text = cell["quantity"], float(cell["resolution"]), cell["printed"].strip()
    for variant, cause in _digit_variants(text):
        if not last_digit and len(variant) == len(text) and variant[:-1] == text[:-1]:
            continue  # a changed last digit is no evidence of a misprint for F0j'
        try:
            value = parse_printed(variant, q)
        except ValueError:
            continue
        if value is not None and variant.strip("-") and _agrees(value, computed, res):
            return cause
    return None


def likely_cause(cell: dict[str, str], printed: float, computed: float) -> str:
    """The most likely cause of a difference, by rule (see the module docstring)."""
    q, res = cell["quantity"], float(cell["resolution"])
    if computed != 0 and _agrees(-printed, computed, res):
        return "sign lost in print"
    if cell["table"] == "Example 1":
        cause = _example1_cause(cell, printed, computed)
        if cause:
            return cause
    fourier = q == "F0j_prime_e3"
    if fourier and abs(printed - computed) > 1.5 * res:
        cause = _digit_cause(cell, computed, last_digit=False)
        if cause:
            return cause
    if abs(printed - computed) <= 1.5 * res:
        return "last digit off by one: rounding or accuracy of the 1973 computation"
    if fourier:
        return "error of the 1973 Fourier integration (larger than the printed rounding)"
    generic = "misprint or error of the 1973 computation"
    return _digit_cause(cell, computed, last_digit=True) or generic


def kurochkin1973_rows() -> list[dict[str, Any]]:
    """Every printed cell of Kurochkin (1973), Tables 1-4 and Example 1, against the exact model.

    Returns
    -------
    list of dict
        Keys ``source``, ``table``, ``cell`` (text), ``printed`` (as printed, text), ``computed``,
        ``difference`` (printed - computed, ``None`` for a lost cell), ``verdict`` ("agrees within
        printed rounding", "differs" or "lost in print") and ``cause`` (empty when it agrees).
        Units: as the cell's quantity (T [-], ψ [°], F0'·10³ [-], e [µm]).
    """
    rows = []
    for cell in read_cells():
        computed = computed_value(cell)
        printed = parse_printed(cell["printed"], cell["quantity"])
        if printed is None:
            verdict, diff, cause = "lost in print", None, "cell missing from the OCR text"
        else:
            diff = printed - computed
            if _agrees(printed, computed, float(cell["resolution"])):
                verdict, cause = "agrees within printed rounding", ""
            else:
                verdict, cause = "differs", likely_cause(cell, printed, computed)
        rows.append(
            {
                "source": cell["source"],
                "table": cell["table"],
                "cell": cell["cell"],
                "printed": cell["printed"],
                "computed": computed,
                "difference": diff,
                "verdict": verdict,
                "cause": cause,
            }
        )
    return rows


#: Example 1 clearances (gap per side e) whose moment the committed table shows. [µm]
EXAMPLE1_GAPS_UM = (3.0, 4.0, 5.0, 5.5)


def differences_rows() -> list[dict[str, Any]]:
    """The rows of :func:`kurochkin1973_rows` whose printed cell is not confirmed (it differs
    beyond its printed rounding, or it was lost in print)."""
    return [r for r in kurochkin1973_rows() if r["verdict"] != "agrees within printed rounding"]


def example1_moments(steps: int = 15) -> dict[str, Any]:
    """Kurochkin's Example 1: the conservative moment M(φ1) = w P y0 over one pitch (his Fig. 2).

    Bearing A640018 (n = 7, D = 10.731 mm, d = 3.969 mm, K = 0.45 kgf/µm^1.5, P = 2.5 kgf),
    rotating inner ring (w = D/(2(D + d))), gaps e = 3, 4, 5, 5.5 µm (:data:`EXAMPLE1_GAPS_UM`)
    and the three gaps that null the first, second and third harmonic of M (exact).

    Returns
    -------
    dict
        ``rows``: per cage angle [°] (``cage_angle``) the moments ``M_e0``, ``M_e1`` ... [N·mm]
        at the gaps in order; ``nulls``: the three nulling gaps [µm]; ``parameters``: T (eq.
        1.13) at each of :data:`EXAMPLE1_GAPS_UM` [-]; ``moment_arm``: w [-].
    """
    load, stiffness = example1_load_stiffness()
    d_in, d_b = EXAMPLE1["D"], EXAMPLE1["d"]
    angles = np.linspace(0.0, 360.0 / 7, steps)
    nulls = [
        float(ku.clearance_from_parameter(t, 7, load, stiffness)) * 500.0 for t in example1_nulls()
    ]
    gaps = [*EXAMPLE1_GAPS_UM, *nulls]
    keys = [f"M_e{i}" for i in range(len(gaps))]
    rows = []
    for a in angles:
        row: dict[str, Any] = {"cage_angle": float(a)}
        for key, e_um in zip(keys, gaps, strict=True):
            m = ku.conservative_moment(7, load, stiffness, 2 * e_um * 1e-3, a, d_in, d_b, "inner")
            row[key] = 0.0 + float(m)
        rows.append(row)
    return {
        "rows": rows,
        "nulls": nulls,
        "parameters": [
            float(ku.generalised_parameter(2 * e * 1e-3, load, stiffness, 7))
            for e in EXAMPLE1_GAPS_UM
        ],
        "moment_arm": float(ku.moment_arm(d_in, d_b)),
    }
