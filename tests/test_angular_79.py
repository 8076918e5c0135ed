"""The 79 series (NSK's thin-section super-precision angular-contact bearings, C 15° and A5 25°):
the rows against the printed values, the ball sets derived from them, the designations that find
them, and the preload classes of their pairs."""

from __future__ import annotations

import json
import math

import pytest

from bearingload.bearings.angular import AngularRow, angular_rows, parse_angular, split_pair
from bearingload.bearings.preload import resolve_preload
from bearingload.bearings.ratings import B_M, f_0, f_c, invert_ball_set, standard_ball_sizes
from bearingload.bearings.resolve import resolve_bearing
from bearingload.errors import InputError

from .cli_helpers import besides_tilt, run_entry
from .fixtures.nsk_precision_79 import NSK_PRECISION_79, NSK_PRECISION_79_PRELOADS


def _rows() -> dict[str, AngularRow]:
    return {r.designation: r for r in angular_rows() if r.designation[:2] == "79"}


def test_rows_are_the_printed_ones():
    rows = _rows()
    assert list(rows) == list(NSK_PRECISION_79)  # 36 sizes, C and A5 each, no A (30°)
    assert sum(n.endswith("C") for n in rows) == 36 and sum(n.endswith("A5") for n in rows) == 36
    for name, (d, big_d, b, c, c0, f0) in NSK_PRECISION_79.items():
        r = rows[name]
        assert (r.d, r.D, r.B, r.maker, r.f0) == (d, big_d, b, "NSK", f0)
        assert r.contact_angle == (15.0 if name.endswith("C") else 25.0)
        assert (r.C, r.C0) == (pytest.approx(c * 1000), pytest.approx(c0 * 1000))
        assert r.pitch_diameter == (d + big_d) / 2 and r.method == "derived"
        assert "79 series" in r.source and "nsk_precision_70_72_79_ratings.csv" in r.source
        assert r.limiting_speed_grease is None and r.limiting_speed_oil is None


@pytest.mark.parametrize(
    ("name", "printed"),
    [
        # reference/data/nsk_precision_70_72_79_ratings.csv, row 7905C: d 25, D 42, B 9,
        # C_r 7.85 kN, C_0r 5.4 kN, f0 15.5
        ("7905C", (25.0, 42.0, 9.0, 7850.0, 5400.0, 15.5)),
        # row 7905A5: 25 x 42 x 9, C_r 7.45 kN, C_0r 5.15 kN, no f0 (A5 rows print none)
        ("7905A5", (25.0, 42.0, 9.0, 7450.0, 5150.0, None)),
        # row 7910C: 50 x 72 x 12, C_r 16.9 kN, C_0r 15.0 kN, f0 16.2
        ("7910C", (50.0, 72.0, 12.0, 16900.0, 15000.0, 16.2)),
        # row 7956A5: 280 x 380 x 46, C_r 256 kN, C_0r 390 kN
        ("7956A5", (280.0, 380.0, 46.0, 256000.0, 390000.0, None)),
    ],
)
def test_spot_rows_carry_the_printed_cells(name, printed):
    r = _rows()[name]
    assert (r.d, r.D, r.B, r.C, r.C0, r.f0) == printed


def _iso(z: int, dw: float, dm: float, alpha: float) -> tuple[float, float]:
    """ISO 281:2007 6.1.1 C_r = b_m f_c (cos a)^0.7 z^(2/3) D_w^1.8 (3.647 D_w^1.4 above 25.4 mm)
    and ISO 76:2006 6.1.1 C_0r = f_0 z D_w^2 cos a, written out here on their own."""
    ca = math.cos(math.radians(alpha))
    power = dw**1.8 if dw <= 25.4 else 3.647 * dw**1.4
    cr = B_M * float(f_c(dw * ca, dm)) * ca**0.7 * z ** (2 / 3) * power
    return cr, float(f_0(dw * ca, dm)) * z * dw**2 * ca


@pytest.mark.parametrize("row", _rows().values(), ids=lambda r: r.designation)
def test_ball_set_is_the_best_inversion_and_reproduces_the_ratings(row):
    fits = invert_ball_set(row.pitch_diameter, row.C, row.C0, contact_angle=row.contact_angle)
    best, after = fits[0], fits[1]
    assert (best.balls, best.ball_diameter) == (
        row.balls,
        pytest.approx(row.ball_diameter, abs=5e-5),
    )
    nearest = min(standard_ball_sizes(), key=lambda s: abs(s - row.ball_diameter))
    assert row.ball_diameter == pytest.approx(nearest, abs=5e-5)
    cr, c0r = _iso(row.balls, row.ball_diameter, row.pitch_diameter, row.contact_angle)
    worst = max(abs(cr / row.C - 1), abs(c0r / row.C0 - 1))
    assert worst < 0.02  # kept within 2 %, as the Koyo and GOST rows
    assert f"within {best.score * 100:.2f} %" in row.notes
    if row.confidence == "high":
        assert worst < 0.01 and after.score - best.score >= 0.005


def test_a_derived_set_re_derived_by_hand():
    """7905C: 16 balls of 3/16" (4.7625 mm) on d_m = 33.5 mm at 15° give C_r and C_0r within
    0.4 % of the printed 7.85 and 5.4 kN; 18 x 4.5 mm, the next set, is off by about 3 %."""
    r = _rows()["7905C"]
    assert (r.balls, r.ball_diameter, r.pitch_diameter) == (16, 4.7625, 33.5)
    cr, c0r = _iso(16, 4.7625, 33.5, 15.0)
    assert abs(cr / 7850 - 1) < 0.004 and abs(c0r / 5400 - 1) < 0.004
    cr, c0r = _iso(18, 4.5, 33.5, 15.0)
    assert max(abs(cr / 7850 - 1), abs(c0r / 5400 - 1)) > 0.025


def test_high_confidence_only_where_the_other_angle_gives_the_same_set():
    rows = _rows()
    for size in {n[:4] for n in rows}:
        c, a5 = rows[f"{size}C"], rows[f"{size}A5"]
        same = (c.balls, c.ball_diameter) == (a5.balls, a5.ball_diameter)
        for r in (c, a5):
            assert ("gives the same set" in r.notes) == same
            if not same:
                assert r.confidence == "medium"
    assert sum(r.confidence == "high" for r in rows.values()) == 31


@pytest.mark.parametrize("row", [r for r in _rows().values() if r.f0], ids=lambda r: r.designation)
def test_printed_f0_agrees_with_the_set(row):
    """NSK's f0 of the C rows: C_0r = f0 z D_w^2 cos a within 3 % with the derived set."""
    c0 = row.f0 * row.balls * row.ball_diameter**2 * math.cos(math.radians(15.0))
    assert abs(c0 / row.C0 - 1) < 0.03


@pytest.mark.parametrize(
    ("text", "name", "alpha"),
    [
        ("7905C", "7905C", 15.0),
        ("7905A5", "7905A5", 25.0),
        ("7905AC", "7905A5", 25.0),
        ("7905 C", "7905C", 15.0),
        ("7956A5", "7956A5", 25.0),
    ],
)
def test_79_designations_parse_and_find_their_row(text, name, alpha):
    parsed = parse_angular(text)
    assert parsed is not None and (parsed.name, parsed.series, parsed.contact_angle) == (
        name,
        "79",
        alpha,
    )
    b = resolve_bearing(text)
    assert b.geometry is not None and b.geometry.designation == name and b.contact_angle == alpha


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("7905CDB", ("7905C", "DB", None)),
        ("7905CDBL", ("7905C", "DB", "L")),
        ("7905A5DFM", ("7905A5", "DF", "M")),
        ("7910C DBEL P4", ("7910CP4", "DB", "EL")),
    ],
)
def test_79_pair_suffixes_are_read(text, want):
    assert split_pair(text) == want


@pytest.mark.parametrize(
    ("text", "words"),
    [("7905A", "no 30° row of series 79"), ("7905B", "no 40° row of series 79")],
)
def test_a_79_row_the_source_does_not_print_is_refused(text, words):
    with pytest.raises(InputError) as info:
        resolve_bearing(text)
    assert words in info.value.message


@pytest.mark.parametrize(("key", "forces"), sorted(NSK_PRECISION_79_PRELOADS.items()))
def test_preload_classes_are_the_printed_ones(key, forces):
    series, code, bore = key
    alpha = "15" if code == "C" else "25"
    name = f"{series}{bore}{code}"
    b = resolve_bearing(name)
    got = tuple(resolve_preload(c, b).force for c in ("EL", "L", "M", "H"))
    assert got == forces
    assert f"series 79, contact angle code {code}" in resolve_preload("L", b).source
    assert f"({alpha}°)" in resolve_preload("L", b).source


def test_a_79_size_beyond_the_class_table_is_refused():
    """The preload table stops at bore code 40; 7944C has a row but no class table."""
    with pytest.raises(InputError, match="7944C \\(15°\\) has no preload-class table"):
        resolve_preload("L", resolve_bearing("7944C"))


def test_solve_7905cdbl_takes_the_l_class_force_and_prints_its_source(capsys):
    code, out, err = run_entry(capsys, "solve", "7905CDBL", "-F", "100N")
    assert code == 0 and besides_tilt(err) == []
    assert "preload 39 N (NSK class L)" in out.splitlines()[0]  # 79 C, bore code 05: L 39 N
    assert "Preload: preload class L of a 7905C pair (15°), 39 N as ground" in out
    assert "series 79, contact angle code C" in out
    _, by_force, _ = run_entry(capsys, "solve", "7905CDB", "--preload", "39N", "-F", "100N")
    body = [line for line in out.splitlines()[1:] if not line.startswith("Preload:")]
    assert body == by_force.splitlines()[1:]


def test_catalog_show_prints_a_79_row_and_its_source(capsys):
    code, out, err = run_entry(capsys, "catalog", "show", "7905A5", "--format", "json")
    assert code == 0 and err == ""
    doc = json.loads(out)
    assert doc["contact_angle"] == 25.0 and doc["maker"] == "NSK" and "79 series" in doc["source"]
