"""Conformance: every registered model on every printed value it applies to, and the errata.

The printed values are the shipped data files (bearingload/papers/data/published/*.csv). A row
applies to a registered method when its ``model`` column names the method and its ``quantity`` is
one the methods return. The printed numbers that differ from the computation beyond their printed
rounding are listed here by (paper, table, cell): a change in either direction (a new
disagreement, or a listed one that now agrees) fails.
"""

from __future__ import annotations

import pytest

from bearingload.models.registry import METHODS, compute
from bearingload.papers.errata import (
    DERIVATIONS,
    DIFFERS,
    METHOD_QUANTITIES,
    case,
    errata_rows,
    kuzmenko2010_rows,
    kuzmenko_sabadash2014_rows,
)
from bearingload.papers.published import FILES, all_published
from bearingload.units import KGF

K10, K14 = "Kuzmenko 2010", "Kuzmenko & Sabadash 2014"

#: Printed cells that a registered method contradicts beyond the printed rounding.
METHOD_ERRATA = {
    *((K10, "Table 1", f"z = {z}, k") for z in (5, 7, 8, 9, 11, 17, 19, 21, 24, 27, 30)),
    (K10, "§3.3", "k, zero clearance"),
    (K10, "§3.4", "phi0, Delta = 10 um"),
    (K10, "§3.4", "Q0, Delta = 10 um"),
    (K10, "§3.4", "k, Delta = 10 um"),
    (K10, "§3.5", "phi0, Delta = 50 um"),
    (K10, "§3.5", "Q0, Delta = 50 um"),
    (K10, "§3.5", "conclusion: Q0 at Delta = 10 um"),
    (K10, "§3.5", "conclusion: Q0 at Delta = 50 um"),
    (K10, "§4", "k z, zero clearance (eq. 4.20)"),
    (K10, "§4", "k, z = 8, zero clearance"),
    *(
        (K14, "Table 2.2", f"z = {z}, K_Q")
        for z in (1, 3, 4, 5, 7, 8, 10, 11, 17, 18, 19, 21, 22, 24, 27, 30)
    ),
    (K14, "§3.1 item 4", "K_Q, z = 9 (theory, by Table 2.2)"),
}

#: The other printed numbers that differ (procedures that are not a registered method).
PROCEDURE_ERRATA = {
    (K10, "§3.4", "left side of eq. 3.4, Delta = 10 um"),
    (K10, "§3.4", "right side of eq. 3.4 at phi0 = 85°, sum"),
    (K10, "§3.4", "right side of eq. 3.4 at phi0 = 85.2°, ball at 0°"),
    (K10, "§3.4", "right side of eq. 3.4 at phi0 = 85.2°, balls at ±45°"),
    (K10, "§3.4", "right side of eq. 3.4 at phi0 = 85.2°, sum"),
    (K10, "§3.4", "increase of Q0 over zero clearance, Delta = 10 um"),
    (K10, "§3.5", "right side of eq. 3.4 at phi0 = 70°, sum"),
    (K10, "§3.5", "right side of eq. 3.4 at phi0 = 72.5°, sum"),
    (K10, "§3.5", "conclusion: increase of Q0 from Delta = 10 to 50 um"),
    (K10, "§3.4.2", "B"),
    (K10, "§3.4.2", "A/B"),
    (K10, "§3.4.2", "n_delta at A/B = 0.0219"),
    (K10, "§3.4.2", "c_v, stiffness of the inner contact"),
    (K10, "§3.4.2", "c, ball stiffness (both contacts)"),
    (K10, "§4", "I = integral of cos^(5/2) over 0..pi/2"),
    (K14, "eq. 2.1", "n"),
    (K14, "eq. 2.5", "sigma_bar(0.8)"),
    (K14, "eq. 2.7", "K_Q = n"),
    (K14, "Table 2.1", "row 2, u/u_max"),
    (K14, "Table 2.1", "row 2, sigma_bar"),
    (K14, "Table 2.1", "row 5, u/u_max"),
    (K14, "Table 2.1", "row 5, sigma_bar"),
    (K14, "Table 2.1", "row 9, sigma_bar"),
    (K14, "§3.1 item 4", "K_Q(theory) - n(experiment), z = 9"),
}


def _method_rows():
    return [r for r in all_published() if r.model in METHODS and r.quantity in METHOD_QUANTITIES]


def _run(method, row):
    """The row's quantity from ``compute(method, ...)``, in the printed unit."""
    args = case(row)
    result = compute(method, **args)
    if row.quantity == "kz":
        return result.k * args["balls"]
    value = getattr(result, row.quantity)
    return value / KGF if row.unit == "kgf" else value


def test_every_registered_model_on_every_row_it_applies_to():
    disagree = set()
    ran = set()
    for name in METHODS:
        for row in (r for r in _method_rows() if r.model == name):
            value = _run(name, row)
            assert isinstance(value, (int, float)) and not isinstance(value, bool), row.key
            ran.add(name)
            if abs(value - row.value) > row.tolerance * (1 + 1e-9):
                disagree.add(row.key)
    assert ran == {"exact", "continuum"}  # the one-line estimates have no printed rows
    assert disagree == METHOD_ERRATA


def test_every_row_names_a_model_and_a_way_to_recompute_it():
    rows = all_published()
    assert len(rows) == 188
    assert len({r.key for r in rows}) == len(rows)
    for r in rows:
        assert r.source in (K10, K14)
        recomputable = (r.model in METHODS and r.quantity in METHOD_QUANTITIES) or (
            (r.model, r.quantity) in DERIVATIONS
        )
        assert recomputable, r.key
        assert r.tolerance > 0 and r.printed == r.printed.strip()
        assert "," not in r.printed  # decimal point normalised


def test_errata_rows_are_exactly_the_known_disagreements():
    rows = kuzmenko2010_rows() + kuzmenko_sabadash2014_rows()
    differ = {(r["source"], r["table"], r["cell"]) for r in rows if r["verdict"] == DIFFERS}
    assert differ == METHOD_ERRATA | PROCEDURE_ERRATA
    for r in rows:
        assert r["difference"] == pytest.approx(float(r["printed"]) - r["computed"], abs=1e-12)
        assert bool(r["cause"]) == (r["verdict"] == DIFFERS)
    assert len(rows) == 188 and len(differ) == 62


@pytest.mark.parametrize("paper", list(FILES))
def test_causes_only_where_a_cell_differs(paper):
    """The data files give a cause only for a cell that differs (for some the cause is unknown)."""
    by_key = {(r["source"], r["table"], r["cell"]): r for r in errata_rows()}
    from bearingload.papers.published import load

    for row in load(paper):
        if row.cause:
            assert by_key[row.key]["verdict"] == DIFFERS, row.key
