"""Tests of bearingload.bearings.clearance: the ISO 5753-1 table for deep groove ball bearings."""

from __future__ import annotations

import pytest

from bearingload.bearings.clearance import (
    CLASSES,
    ClearanceRow,
    clearance_range,
    looks_like_class,
    parse_class,
    radial_clearance,
    table,
)
from bearingload.errors import InputError

# Cells copied from NSK "Rolling Bearings", Table 9.9 "Radial Internal Clearances in Deep
# Groove Ball Bearings" (ISO 5753-1 values), micrometres: (bore inside the row, class, min, max).
NSK_TABLE_9_9_CELLS = [
    (10, "CN", 2, 13),  # row "10 only" (pti.eu: over 6 incl 10)
    (8, "C5", 20, 37),
    (15, "C3", 11, 25),  # row 10-18
    (20, "C2", 0, 10),  # row 18-24
    (30, "C4", 23, 41),  # row 24-30, bore exactly 30 belongs here
    (35, "CN", 6, 20),  # row 30-40
    (45, "C3", 18, 36),  # row 40-50
    (60, "C5", 55, 90),  # row 50-65 (two web pages misprint 55-60; NSK and pti.eu: 55-90)
    (70, "C4", 46, 71),  # row 65-80
    (90, "C3", 30, 58),  # row 80-100
    (110, "C3", 36, 66),  # row 100-120
    (130, "C3", 41, 81),  # row 120-140
    (300, "CN", 40, 115),  # row 280-315
    (480, "C5", 390, 570),  # row 450-500
    (800, "C2", 20, 140),  # row 710-800
]


@pytest.mark.parametrize(("bore", "cls", "low", "high"), NSK_TABLE_9_9_CELLS)
def test_table_cells(bore: float, cls: str, low: int, high: int) -> None:
    assert clearance_range(bore, cls) == pytest.approx((low / 1000, high / 1000), abs=1e-12)


def test_table_shape() -> None:
    rows = table()
    assert len(rows) == 27
    assert (rows[0].bore_over, rows[-1].bore_incl) == (2.5, 800.0)
    for prev, row in zip(rows, rows[1:], strict=False):
        assert row.bore_over == prev.bore_incl  # contiguous ranges
    assert all("Table 9.9" in row.source for row in rows[1:])
    assert "ktaiballbearing.com" in rows[0].source and "bmzbearings.com" in rows[0].source


@pytest.mark.parametrize("row", table(), ids=lambda r: f"{r.bore_over:g}-{r.bore_incl:g}")
def test_classes_increase(row: ClearanceRow) -> None:
    given = [c for c in CLASSES if c in row.limits]
    assert given == list(CLASSES[: len(given)]) and len(given) >= 3  # from C2, none skipped
    for cls in given:
        low, high = row.limits[cls]
        assert 0 <= low < high
    for smaller, larger in zip(given, given[1:], strict=False):
        assert row.limits[smaller][0] < row.limits[larger][0]
        assert row.limits[smaller][1] < row.limits[larger][1]


@pytest.mark.parametrize(
    ("bore", "expected_c4"),
    [
        (24.0, (0.020, 0.036)),  # incl 24: row 18-24
        (24.001, (0.023, 0.041)),  # over 24: row 24-30
        (30.0, (0.023, 0.041)),  # incl 30: row 24-30
        (30.001, (0.028, 0.046)),  # over 30: row 30-40
        (10.0, (0.014, 0.029)),
        (10.5, (0.018, 0.033)),
    ],
)
def test_boundary_bores(bore: float, expected_c4: tuple[float, float]) -> None:
    assert clearance_range(bore, "C4") == pytest.approx(expected_c4, abs=1e-12)


@pytest.mark.parametrize("bore", [0.0, 2.5, 800.5, 1000.0, -30.0])
def test_bore_outside_table(bore: float) -> None:
    with pytest.raises(InputError, match="outside the clearance table") as info:
        clearance_range(bore, "CN")
    assert info.value.parameter == "bore"


@pytest.mark.parametrize("bore", [3.0, 5.0, 6.0])
def test_the_smallest_bores_have_c2_to_c3(bore: float) -> None:
    """Over 2.5 up to 6 mm (the makers' pages of the data file): C2 0-7, CN 2-13, C3 8-23 µm;
    no C4 or C5, refused naming the classes there are."""
    assert clearance_range(bore, "C2") == pytest.approx((0.0, 0.007), abs=1e-12)
    assert clearance_range(bore, "CN") == pytest.approx((0.002, 0.013), abs=1e-12)
    assert clearance_range(bore, "C3") == pytest.approx((0.008, 0.023), abs=1e-12)
    for cls in ("C4", "C5"):
        with pytest.raises(InputError, match="not tabulated .* C2, CN, C3") as info:
            clearance_range(bore, cls)
        assert info.value.parameter == "clearance"


def test_bore_not_a_number() -> None:
    with pytest.raises(InputError, match="bore"):
        radial_clearance("thirty", "CN")  # type: ignore[arg-type]


def test_picks() -> None:
    # 40 mm, C3: 15-33 um (row 30-40).
    assert radial_clearance(40, "C3", pick="min") == pytest.approx(0.015)
    assert radial_clearance(40, "C3", pick="max") == pytest.approx(0.033)
    assert radial_clearance(40, "C3") == pytest.approx(0.024)
    # Kuzmenko (2010) takes G_r = 20 um for bearing 306 (d = 30): the CN maximum of row 24-30.
    assert radial_clearance(30, "CN", pick="max") == pytest.approx(0.020)


def test_unknown_pick() -> None:
    with pytest.raises(InputError, match="min, mean, max") as info:
        radial_clearance(30, "CN", pick="median")
    assert info.value.parameter == "pick"


@pytest.mark.parametrize(
    ("text", "cls"),
    [
        ("C2", "C2"),
        ("c3", "C3"),
        (" C4 ", "C4"),
        ("C5", "C5"),
        ("CN", "CN"),
        ("cn", "CN"),
        ("N", "CN"),
        ("normal", "CN"),
        ("Normal", "CN"),
        ("0", "CN"),
        ("M", "CN"),
        # GOST 24810-81 groups of single-row radial ball bearings, cylindrical bore
        # (aprom.by): 6 = C2, 7 = C3, 8 = C4, 9 = C5.
        ("6", "C2"),
        ("7", "C3"),
        ("8", "C4"),
        ("9", "C5"),
        ("G7", "C3"),
        ("group 8", "C4"),
        ("нормальная", "CN"),
    ],
)
def test_parse_class(text: str, cls: str) -> None:
    assert parse_class(text) == cls


@pytest.mark.parametrize("text", ["C1", "C6", "X", "", "5", "20um", "G5"])
def test_parse_class_rejects(text: str) -> None:
    with pytest.raises(InputError, match="allowed: C2, CN, C3, C4, C5") as info:
        parse_class(text)
    assert info.value.parameter == "clearance"


def test_c1_explained() -> None:
    with pytest.raises(InputError, match="C1 is not tabulated"):
        radial_clearance(30, "C1")


def test_gost_group_gives_iso_limits() -> None:
    assert clearance_range(65, "7") == clearance_range(65, "C3")
    assert clearance_range(65, "6") == clearance_range(65, "C2")


@pytest.mark.parametrize(
    ("text", "is_class"),
    [
        ("C3", True),
        ("c2", True),
        ("CN", True),
        ("normal", True),
        ("N", True),
        ("G7", True),
        ("group 9", True),
        ("C1", True),  # a class, rejected later by parse_class with a clear message
        ("20um", False),
        ("0.02", False),
        ("0.02mm", False),
        ("0", False),  # bare number = length (zero clearance), not CN
        ("7", False),  # bare number = length
        ("-5um", False),
        ("1e-3", False),
    ],
)
def test_looks_like_class(text: str, is_class: bool) -> None:
    assert looks_like_class(text) is is_class


def test_table_life_has_default_rows_for_the_smallest_bores() -> None:
    """The rows of table life scale with the largest class at the bore: C3 up to 6 mm."""
    from bearingload.bearings.resolve import resolve_bearing
    from bearingload.studies.life_clearance import default_clearances

    rows = default_clearances(resolve_bearing("625"))
    assert rows.size > 5 and rows.max() == pytest.approx(rows.max()) and rows.max() < 0.1
