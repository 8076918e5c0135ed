"""GOST 831 rows from ZAP's catalogue (Samara, 2006; its table with ISO analogues as extracted in
reference/data/gost_36_46_66_ratings.csv of the reference notes): sizes EPK's 2011 catalogue
does not print at the type's angle, and 46205, whose 2011 ratings fit no ball set."""

from __future__ import annotations

import math

import pytest

from bearingload.bearings.angular import AngularRow, angular_rows
from bearingload.bearings.ratings import B_M, f_0, f_c
from bearingload.bearings.resolve import resolve_bearing

#: The table's printed values: D, B [mm], C_r, C_0r [N] (46205: B printed 25, a misprint). The
#: docs quote ZAP's 36205 16.7/9.1 kN and 46205 15.8/9.7 kN; the extraction has the same.
PRINTED = {
    "66203": (40, 12, 8680, 4700),
    "46303": (47, 14, 16100, 8000),
    "46204": (47, 14, 14800, 7640),
    "46304": (52, 15, 17800, 9500),
    "66406": (90, 23, 45700, 27300),
    "66408": (110, 27, 72200, 42300),
    "46316": (170, 39, 142160, 110600),
    "36236": (320, 52, 299000, 366900),
    "46205": (52, 25, 15800, 9700),
    "46305": (62, 17, 25800, 15470),
    "36206": (62, 16, 23200, 14900),
    "46206": (62, 16, 21900, 13900),
    "46114": (110, 20, 45258, 41000),
    "46120": (150, 24, 70890, 72400),
}
#: Sizes EPK's General Catalogue 2011 prints at the type's angle without a row there (its
#: variants disagree, or no set fits its ratings): ZAP's row is used and the notes say why.
EPK_WITHOUT_ROW = {"46205", "46305", "36206", "46206", "46114", "46120"}
TYPE_ANGLE = {"3": 12.0, "4": 26.0, "6": 36.0}


def _rows() -> dict[str, AngularRow]:
    return {r.designation: r for r in angular_rows() if r.maker == "ZAP"}


def test_rows_are_the_printed_values_with_the_bore_from_the_code():
    rows = _rows()
    assert set(rows) == set(PRINTED)
    for name, (big_d, b, c, c0) in PRINTED.items():
        r = rows[name]
        bore = {"03": 17.0, "04": 20.0}.get(name[-2:], 5.0 * int(name[-2:]))
        assert (r.d, r.D, r.C, r.C0) == (bore, big_d, c, c0)
        assert r.B == (15.0 if name == "46205" else b)
        assert r.contact_angle == TYPE_ANGLE[name[0]] and "not printed" not in r.source
        assert "no contact angle" in r.source and r.method == "derived"


def test_46205_says_which_values_it_takes_and_why():
    notes = _rows()["46205"].notes
    assert "B printed 25 mm, a misprint" in notes and "14500/10000" in notes


@pytest.mark.parametrize("name", sorted(EPK_WITHOUT_ROW))
def test_a_size_epk_prints_without_a_row_names_epks_values(name):
    assert name not in {r.designation for r in angular_rows() if r.maker == "EPK"}
    assert "EPK's General Catalogue 2011 prints" in _rows()[name].notes


@pytest.mark.parametrize("name", sorted(PRINTED))
def test_the_set_reproduces_both_ratings_within_two_percent(name):
    r = _rows()[name]
    ca = math.cos(math.radians(r.contact_angle))
    dw, dm, z = r.ball_diameter, r.pitch_diameter, r.balls
    power = dw**1.8 if dw <= 25.4 else 3.647 * dw**1.4  # ISO 281 6.1.1
    cr = B_M * float(f_c(dw * ca, dm)) * ca**0.7 * z ** (2 / 3) * power
    c0r = float(f_0(dw * ca, dm)) * z * dw**2 * ca  # ISO 76 6.1.1
    assert abs(cr / r.C - 1) <= 0.02 and abs(c0r / r.C0 - 1) <= 0.02
    assert dm == (r.d + r.D) / 2


def test_46205_has_the_ball_set_of_the_7205_rows():
    """An independent check: the set derived from this table's 46205 ratings at 26° is the
    12 x 5/16" of NSK's 7205A5 and Koyo's 7205 rows."""
    b = resolve_bearing("46205")
    assert (b.balls, b.ball_diameter, b.contact_angle) == (12, 7.9375, 26.0)
    assert (resolve_bearing("7205A5").balls, resolve_bearing("7205A5").ball_diameter) == (
        12,
        7.9375,
    )
