"""Angular-contact designations and catalogue rows: the contact angle each form stands for, the
rows against the NSK BEA leaflet they cite, their derived ball sets re-derived from the ratings
(ISO 281 / ISO 76 at 40°, written out here), ``solve 7205B`` against the hand-given ring of the
same row, the refusals, ``catalog --type angular`` and ``catalog show``."""

from __future__ import annotations

import json
import math

import pytest

from bearingload.bearings.angular import angular_rows, find_angular, parse_angular
from bearingload.bearings.ratings import B_M, f_0, f_c, standard_ball_sizes
from bearingload.bearings.resolve import resolve_bearing
from bearingload.errors import InputError

from .cli_helpers import run_entry
from .fixtures.angular_factors import DESIGNATION_ANGLES, NSK_BEA_40


@pytest.mark.parametrize("text", sorted(DESIGNATION_ANGLES))
def test_designation_gives_the_contact_angle(text):
    parsed = parse_angular(text)
    assert parsed is not None and parsed.contact_angle == DESIGNATION_ANGLES[text]
    assert parsed.bore == 25.0


@pytest.mark.parametrize("text", ["6205", "205", "7205", "30205", "NU205", "71905CD", "46205K"])
def test_other_designations_are_not_read_as_angular(text):
    assert parse_angular(text) is None


def test_rows_match_the_cited_leaflet():
    rows = {r.designation: r for r in angular_rows()}
    assert set(rows) == set(NSK_BEA_40)
    for name, (d, big_d, b, c, c0) in NSK_BEA_40.items():
        r = rows[name]
        assert (r.d, r.D, r.B, r.C, r.C0) == (d, big_d, b, c, c0)
        assert r.contact_angle == 40.0 and r.method == "derived" and "NSK" in r.source
        assert r.pitch_diameter == (d + big_d) / 2


def _iso_ratings(z: int, dw: float, dm: float, alpha: float) -> tuple[float, float]:
    """ISO 281:2007 6.1.1 C_r = b_m f_c (cos a)^0.7 z^(2/3) D_w^1.8 and ISO 76:2006 6.1.1
    C_0r = f_0 z D_w^2 cos a, f_c and f_0 at gamma = D_w cos a / d_m (one row, D_w <= 25.4)."""
    ca = math.cos(math.radians(alpha))
    cr = B_M * float(f_c(dw * ca, dm)) * ca**0.7 * z ** (2 / 3) * dw**1.8
    return cr, float(f_0(dw * ca, dm)) * z * dw**2 * ca


@pytest.mark.parametrize("row", angular_rows(), ids=lambda r: r.designation)
def test_derived_ball_set_is_the_best_inversion_of_the_ratings(row):
    best = min(
        (max(abs(cr / row.C - 1), abs(c0 / row.C0 - 1)), z, dw)
        for z in range(5, 30)
        for dw in standard_ball_sizes()
        if z * dw < math.pi * row.pitch_diameter
        and 0.01 <= dw * math.cos(math.radians(40)) / row.pitch_diameter <= 0.4
        for cr, c0 in [_iso_ratings(z, float(dw), row.pitch_diameter, row.contact_angle)]
    )
    assert best[1] == row.balls and best[2] == pytest.approx(row.ball_diameter, abs=5e-5)
    assert best[0] < 0.005  # the ratings reproduced to 0.5 %


def test_resolve_gives_the_row_at_its_angle_without_clearance():
    b = resolve_bearing("7205 BEP")
    r = find_angular(parse_angular("7205B"))
    assert (b.balls, b.ball_diameter, b.pitch_diameter) == (r.balls, r.ball_diameter, 38.5)
    assert b.contact_angle == 40.0 and b.clearance == 0.0 and (b.C, b.C0) == (16700.0, 10200.0)
    with pytest.raises(InputError, match="clearance"):
        resolve_bearing("7205B", clearance="C3")
    with pytest.raises(InputError, match="NSK"):
        resolve_bearing("7205B", maker="SKF")
    assert resolve_bearing("7205B", maker="nsk").balls == 12


@pytest.mark.parametrize("text", ["7205AC", "7205C", "7205A", "46205", "36205", "66205", "7207B"])
def test_known_type_without_a_row_is_one_error_naming_the_rows(capsys, text):
    code, out, err = run_entry(capsys, "solve", text, "-F", "2kN", "-A", "1kN")
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and lines[0].startswith("Error:")
    assert "angular contact ball bearing" in err and "7205B" in err and "7305B" in err
    assert f"{DESIGNATION_ANGLES.get(text, 40.0):g}°" in err
    assert "Traceback" not in err


def test_solve_7205b_equals_the_hand_given_ring_and_reports_l10_p0(capsys):
    code, out, err = run_entry(capsys, "solve", "7205B", "-F", "2kN", "-A", "3kN",
                               "--format", "json")  # fmt: skip
    assert code == 0 and err == ""
    case = json.loads(out)["cases"][0]
    code, out, _ = run_entry(capsys, "solve", "--balls", "12", "--ball-diameter", "8.7312",
                             "--pitch-diameter", "38.5", "-F", "2kN", "-A", "3kN",
                             "--contact-angle", "40", "--dynamic-rating", "16700",
                             "--static-rating", "10200", "--format", "json")  # fmt: skip
    hand = json.loads(out)["cases"][0]
    for key in ("q_max", "x", "axial", "tilt", "reference_rating_life", "rating_life",
                "equivalent_load", "static_equivalent_load", "static_safety", "contact_angle"):  # fmt: skip
        assert case[key] == pytest.approx(hand[key], rel=1e-12), key
    p = 0.35 * 2000 + 0.57 * 3000  # F_a/F_r = 1.5 > e = 1.14 (ISO 281, 40°)
    assert case["equivalent_load"] == pytest.approx(p, rel=1e-9)  # json: 10 digits
    assert case["rating_life"] == pytest.approx((16700 / p) ** 3, rel=1e-9)
    assert case["static_equivalent_load"] == pytest.approx(max(2000, 1000 + 0.26 * 3000))
    assert case["contact_angle"] == 40.0 and case["clearance"] == 0.0


def test_solve_7205b_radial_load_alone_takes_the_combined_engine(capsys):
    code, out, err = run_entry(capsys, "solve", "7205B", "-F", "2kN", "--format", "json")
    assert code == 0 and err == ""
    case = json.loads(out)["cases"][0]
    assert case["contact_angle"] == 40.0 and case["axial_load"] == 0.0
    assert case["equivalent_load"] == 2000.0  # F_a = 0: P = F_r


def test_radial_engine_refuses_an_angular_bearing():
    from bearingload.studies.loaded_bearing import solve_bearing

    with pytest.raises(InputError, match="combined engine"):
        solve_bearing([resolve_bearing("7205B")], 1000.0)


def test_catalog_lists_and_shows_angular_rows(capsys):
    code, out, err = run_entry(capsys, "catalog", "--type", "angular", "--format", "json")
    assert code == 0 and err == ""
    rows = json.loads(out)["rows"]
    assert [r["designation"] for r in rows] == list(NSK_BEA_40)
    code, out, _ = run_entry(capsys, "catalog", "show", "7205 BEP", "--format", "json")
    doc = json.loads(out)
    assert doc["contact_angle"] == 40.0 and doc["balls"] == 12 and doc["C"] == 16700.0
    assert "NSK" in doc["source"] and "derived" in doc["notes"]
    code, out, err = run_entry(capsys, "catalog", "--type", "angular", "--series", "72")
    assert code == 2 and err.startswith("Error:") and "--type" in err


@pytest.mark.parametrize("text", ["7205BDB", "7205BDF", "7205B/DT", "7205B DB", "7205AC/DBA"])
def test_a_matched_pair_is_refused_not_solved_as_one_bearing(text):
    """NSK's 7205BDB (back-to-back), DF, DT and the /DB forms name two bearings: they were
    read past as maker suffixes and solved as one single-row 7205B."""
    with pytest.raises(InputError, match="matched pair or set") as info:
        resolve_bearing(text)
    assert info.value.parameter == "bearing"


@pytest.mark.parametrize("text", ["7205BECBP", "7205 BEP", "7205-B-TVP", "7205BEGA", "7205BTN"])
def test_single_bearing_maker_suffixes_are_still_read(text):
    assert resolve_bearing(text).contact_angle == 40.0


@pytest.mark.parametrize("name", ["life", "k", "kq"])
def test_table_refuses_an_angular_designation_naming_it(capsys, name):
    """table life --bearing 7205B was refused for '--clearances' (never given: the default
    range), table k/kq for '--clearance'; --contact-angle is refused naming the bearing type."""
    code, out, err = run_entry(capsys, "table", name, "--bearing", "7205B", "-F", "2kN")
    assert code == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("Error: Invalid value for '--bearing'")
    assert "angular-contact" in lines[0] and "'solve'" in lines[0]


@pytest.mark.parametrize(
    ("override", "parameter"),
    [({"pitch_diameter": 10.0}, "pitch_diameter"), ({"ball_diameter": 20.0}, "ball_diameter"),
     ({"balls": 100}, "balls")],
)  # fmt: skip
def test_values_given_by_hand_must_fit_the_rows_rings(override, parameter):
    """7205B with d_m = 10 mm (bore 25 mm), D_w = 20 mm or 100 balls was solved (as a deep-groove
    row refuses them, the ring check of the catalogue applies)."""
    with pytest.raises(InputError) as info:
        resolve_bearing("7205B", **override)
    assert info.value.parameter == parameter


def test_catalog_show_takes_the_rows_maker_as_solve_does(capsys):
    """solve 7205B --maker NSK is accepted (the row is NSK's); catalog show refused any --maker."""
    code, out, err = run_entry(capsys, "catalog", "show", "7205B", "--maker", "NSK")
    assert code == 0 and "7205B" in out
    code, out, err = run_entry(capsys, "catalog", "show", "7205B", "--maker", "SKF")
    assert code == 2 and "Invalid value for '--maker'" in err and "NSK's only" in err
    code, out, err = run_entry(capsys, "solve", "7205B", "-F", "1kN", "--maker", "SKF")
    assert code == 2 and "NSK's only" in err
