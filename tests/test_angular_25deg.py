"""The 25° angular-contact rows (NSK's A5, SKF's AC) of the 70 and 72 series: the printed values,
the ball set derived from them, and the designations that find them."""

from __future__ import annotations

import math

import pytest

from bearingload.bearings.angular import AngularRow, angular_rows
from bearingload.bearings.ratings import B_M, f_0, f_c, invert_ball_set, standard_ball_sizes
from bearingload.bearings.resolve import resolve_bearing

from .fixtures.nsk_precision_a5 import NSK_PRECISION_A5


def _rows() -> dict[str, AngularRow]:
    """The 25° rows of the 70 and 72 series (the 79 series: test_angular_79.py)."""
    return {
        r.designation: r
        for r in angular_rows()
        if r.contact_angle == 25.0 and r.designation[:2] in ("70", "72")
    }


def test_rows_are_the_printed_ones():
    rows = _rows()
    assert set(rows) == set(NSK_PRECISION_A5)
    assert (
        sum(n.startswith("70") for n in rows) == 32 and sum(n.startswith("72") for n in rows) == 27
    )
    for name, (d, big_d, b, c, c0) in NSK_PRECISION_A5.items():
        r = rows[name]
        assert (r.d, r.D, r.B, r.maker) == (d, big_d, b, "NSK")
        assert (r.C, r.C0) == (pytest.approx(c * 1000), pytest.approx(c0 * 1000))
        assert r.pitch_diameter == (d + big_d) / 2 and r.method == "derived"


def _iso(z: int, dw: float, dm: float) -> tuple[float, float]:
    """ISO 281:2007 6.1.1 C_r = b_m f_c (cos a)^0.7 z^(2/3) D_w^1.8 (3.647 D_w^1.4 above 25.4 mm)
    and ISO 76:2006 6.1.1 C_0r = f_0 z D_w^2 cos a at a = 25°, written out here on their own."""
    ca = math.cos(math.radians(25.0))
    power = dw**1.8 if dw <= 25.4 else 3.647 * dw**1.4
    cr = B_M * float(f_c(dw * ca, dm)) * ca**0.7 * z ** (2 / 3) * power
    return cr, float(f_0(dw * ca, dm)) * z * dw**2 * ca


@pytest.mark.parametrize("row", _rows().values(), ids=lambda r: r.designation)
def test_ball_set_is_the_best_inversion_and_reproduces_the_ratings(row):
    best = invert_ball_set(row.pitch_diameter, row.C, row.C0, contact_angle=25.0)[0]
    assert (best.balls, best.ball_diameter) == (
        row.balls,
        pytest.approx(row.ball_diameter, abs=5e-5),
    )
    nearest = min(standard_ball_sizes(), key=lambda s: abs(s - row.ball_diameter))
    assert row.ball_diameter == pytest.approx(nearest, abs=5e-5)
    cr, c0r = _iso(row.balls, row.ball_diameter, row.pitch_diameter)
    assert abs(cr / row.C - 1) < 0.01 and abs(c0r / row.C0 - 1) < 0.01  # within 1 %
    assert f"within {best.score * 100:.2f} %" in row.notes


def test_most_sets_are_koyos_set_of_the_same_size():
    """An independent check: Koyo's catalogue (B2001RUS) prints other ratings of the same sizes
    at 15°, 30° and 40°, whose joint inversion gave the Koyo rows' ball set; the 25° set derived
    from NSK's ratings alone is the same set for most sizes."""
    koyo = {r.designation[:4]: r for r in angular_rows() if r.maker == "KOYO"}
    both = [(r, koyo[n[:4]]) for n, r in _rows().items() if n[:4] in koyo]
    same = [
        a for a, k in both if a.balls == k.balls and abs(a.ball_diameter - k.ball_diameter) < 1e-3
    ]
    assert len(both) == 42 and len(same) == 33


@pytest.mark.parametrize("text", ["7205AC", "7205ACD", "7205 AC", "7205A5", "7205-AC"])
def test_ac_and_a5_find_the_25_degree_row(text):
    b = resolve_bearing(text)
    assert b.contact_angle == 25.0 and (b.C, b.C0) == (15900.0, 9800.0)  # NSK 7205A5
    assert b.geometry is not None and b.geometry.designation == "7205A5"


def test_7008ac_is_found():
    b = resolve_bearing("7008AC")
    assert (b.contact_angle, b.C, b.C0) == (25.0, 19500.0, 15100.0)  # NSK 7008A5
