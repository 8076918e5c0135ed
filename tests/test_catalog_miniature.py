"""Deep groove ball bearings with a one-digit bore (608, 623 ... 699): NSK's printed rows, the ball
sets derived from them, and what solve does with them."""

from __future__ import annotations

import pytest

from bearingload.bearings.catalog import entries, find, lookup
from bearingload.bearings.designation import parse
from bearingload.bearings.ratings import dynamic_rating, static_rating
from bearingload.errors import InputError

from .cli_helpers import run_entry

#: NSK Rolling Bearings CAT. No. E1102e, pp. B34-B37 (metric extra small and miniature ball
#: bearings), as printed: d, D, B [mm], C_r, C_0r [N], limiting speeds grease, oil (open) [r/min].
NSK_E1102E = {
    "681": (1, 3, 1.0, 80, 23, 130000, 150000),
    "691": (1, 4, 1.6, 138, 35, 100000, 120000),
    "682": (2, 5, 1.5, 169, 50, 85000, 100000),
    "692": (2, 6, 2.3, 330, 98, 75000, 90000),
    "602": (2, 7, 2.8, 385, 127, 63000, 75000),
    "683": (3, 7, 2.0, 390, 130, 63000, 75000),
    "693": (3, 8, 3.0, 560, 179, 60000, 67000),
    "603": (3, 9, 3.0, 570, 187, 56000, 67000),
    "623": (3, 10, 4.0, 630, 218, 50000, 60000),
    "633": (3, 13, 5.0, 1300, 485, 40000, 48000),
    "684": (4, 9, 2.5, 640, 225, 53000, 63000),
    "694": (4, 11, 4.0, 960, 345, 48000, 56000),
    "604": (4, 12, 4.0, 960, 345, 48000, 56000),
    "624": (4, 13, 5.0, 1300, 485, 40000, 48000),
    "634": (4, 16, 5.0, 1730, 670, 36000, 43000),
    "685": (5, 11, 3.0, 715, 281, 45000, 53000),
    "695": (5, 13, 4.0, 1080, 430, 43000, 50000),
    "605": (5, 14, 5.0, 1330, 505, 40000, 50000),
    "625": (5, 16, 5.0, 1730, 670, 36000, 43000),
    "635": (5, 19, 6.0, 2340, 885, 32000, 40000),
    "686": (6, 13, 3.5, 1080, 440, 40000, 50000),
    "696": (6, 15, 5.0, 1730, 670, 40000, 45000),
    "606": (6, 17, 6.0, 2260, 835, 38000, 45000),
    "626": (6, 19, 6.0, 2340, 885, 32000, 40000),
    "636": (6, 22, 7.0, 3300, 1370, 30000, 36000),
    "687": (7, 14, 3.5, 1170, 510, 40000, 45000),
    "697": (7, 17, 5.0, 1610, 710, 36000, 43000),
    "607": (7, 19, 6.0, 2340, 885, 36000, 43000),
    "627": (7, 22, 7.0, 3300, 1370, 30000, 36000),
    "637": (7, 26, 9.0, 4550, 1970, 28000, 34000),
    "688": (8, 16, 4.0, 1610, 710, 36000, 43000),
    "698": (8, 19, 6.0, 2240, 910, 36000, 43000),
    "608": (8, 22, 7.0, 3300, 1370, 34000, 40000),
    "628": (8, 24, 8.0, 3350, 1430, 28000, 34000),
    "638": (8, 28, 9.0, 4550, 1970, 28000, 34000),
    "689": (9, 17, 4.0, 1330, 665, 36000, 43000),
    "699": (9, 20, 6.0, 1720, 840, 34000, 40000),
    "609": (9, 24, 7.0, 3350, 1430, 32000, 38000),
    "629": (9, 26, 8.0, 4550, 1970, 28000, 34000),
    "639": (9, 30, 10.0, 5100, 2390, 24000, 30000),
}

#: GMN (catalogue 4000 0813 EN, 2013) prints its ball sets: 608 (as 627/608) 7 x 3.969 mm and
#: 629 7 x 4.762 mm (reference/ball_sets.md §2.1); an independent check of the derived sets.
GMN_SETS = {"608": (7, 3.969), "629": (7, 4.762)}

SMALL = [r for r in entries() if r.d < 10]


def test_forty_rows_of_five_series():
    assert len(SMALL) == 40 and all(r.standard == "ISO" for r in SMALL)
    assert {r.designation[:2] for r in SMALL} == {"60", "62", "63", "68", "69"}
    assert sum(r.has_geometry for r in SMALL) == 32


@pytest.mark.parametrize("name", sorted(NSK_E1102E))
def test_rows_are_the_printed_values(name):
    d, big_d, b, c, c0, grease, oil = NSK_E1102E[name]
    row = find(name)
    assert (row.d, row.D, row.B, row.C, row.C0) == (d, big_d, b, c, c0)
    assert (row.limiting_speed_grease, row.limiting_speed_oil) == (grease, oil)
    assert "E1102e" in row.limiting_speed_source


@pytest.mark.parametrize("row", [r for r in SMALL if r.has_geometry], ids=lambda r: r.designation)
def test_derived_set_reproduces_the_ratings_within_two_percent(row):
    assert row.maker == "NSK" and row.method == "derived"
    assert row.pitch_diameter == (row.d + row.D) / 2
    cr = float(dynamic_rating(row.balls, row.ball_diameter, row.pitch_diameter))
    c0r = float(static_rating(row.balls, row.ball_diameter, row.pitch_diameter))
    assert abs(cr / row.C - 1) <= 0.02 and abs(c0r / row.C0 - 1) <= 0.02


@pytest.mark.parametrize("name", sorted(GMN_SETS))
def test_derived_set_is_the_one_gmn_prints(name):
    z, dw = GMN_SETS[name]
    b = lookup(name)
    assert b.balls == z and b.ball_diameter == pytest.approx(dw, abs=1e-3)


def test_a_row_no_set_fits_is_known_and_asks_for_the_set():
    row = find("623")
    assert not row.has_geometry and "--balls" in row.notes
    with pytest.raises(InputError, match="ball set is unknown"):
        lookup("623")
    assert lookup("623", balls=7, ball_diameter=1.5875).balls == 7


def test_688_is_its_own_row_not_6188():
    assert parse("688").catalogue_name == "688" and parse("6806").catalogue_name == "61806"
    assert find("688-2RS").d == 8.0 and find("688").catalogue_series == "618"


def test_solve_608_takes_its_row(capsys):
    code, out, err = run_entry(capsys, "solve", "608", "-F", "500N")
    assert code == 0 and err == ""
    assert out.startswith("Bearing 608, z = 7,") and "G_r = 7.5 µm" in out  # CN 2-13 µm, mean
