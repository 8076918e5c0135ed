"""Angular-contact designations and catalogue rows: the contact angle each form stands for, the
rows against the NSK BEA leaflet they cite, their derived ball sets re-derived from the ratings
(ISO 281 / ISO 76 at 40°, written out here), ``solve 7205B`` against the hand-given ring of the
same row, the refusals, ``catalog --type angular`` and ``catalog show``."""

from __future__ import annotations

import json
import math

import pytest

from bearingload.bearings.angular import AngularRow, angular_rows, find_angular, parse_angular
from bearingload.bearings.ratings import B_M, f_0, f_c, standard_ball_sizes
from bearingload.bearings.resolve import resolve_bearing
from bearingload.errors import InputError

from .cli_helpers import besides_tilt, run_entry
from .fixtures.angular_factors import DESIGNATION_ANGLES, KOYO_B2001, NSK_BEA_40
from .fixtures.nsk_precision_79 import NSK_PRECISION_79
from .fixtures.nsk_precision_a5 import NSK_PRECISION_A5


@pytest.mark.parametrize("text", sorted(DESIGNATION_ANGLES))
def test_designation_gives_the_contact_angle(text):
    parsed = parse_angular(text)
    assert parsed is not None and parsed.contact_angle == DESIGNATION_ANGLES[text]
    assert parsed.bore == 25.0


@pytest.mark.parametrize("text", ["6205", "205", "7205", "30205", "NU205", "71905CD", "46205K"])
def test_other_designations_are_not_read_as_angular(text):
    assert parse_angular(text) is None


def _rows(maker: str) -> dict[str, AngularRow]:
    return {r.designation: r for r in angular_rows() if r.maker == maker}


def test_rows_match_the_cited_leaflet():
    rows = {n: r for n, r in _rows("NSK").items() if r.contact_angle == 40.0}
    assert set(rows) == set(NSK_BEA_40)
    for name, (d, big_d, b, c, c0) in NSK_BEA_40.items():
        r = rows[name]
        assert (r.d, r.D, r.B, r.C, r.C0) == (d, big_d, b, c, c0)
        assert r.contact_angle == 40.0 and r.method == "derived" and "NSK" in r.source
        assert r.pitch_diameter == (d + big_d) / 2


def _stored(koyo_name: str) -> str:
    """Koyo's 30° bearing has no letter (7205); the catalogue stores it as 7205A."""
    return koyo_name if koyo_name[-1] in "BC" else koyo_name + "A"


def test_koyo_rows_match_the_cited_catalogue():
    rows = _rows("KOYO")
    assert set(rows) == {_stored(n) for n in KOYO_B2001}
    for name, (d, big_d, b, c, c0, _f0, _a) in KOYO_B2001.items():
        r = rows[_stored(name)]
        assert (r.d, r.D, r.B) == (d, big_d, b)
        assert r.C == pytest.approx(c * 1000, abs=1e-9)
        assert r.C0 == pytest.approx(c0 * 1000, abs=1e-9)
        parsed = parse_angular(r.designation)
        assert parsed is not None and r.contact_angle == parsed.contact_angle
        assert "Koyo" in r.source and r.pitch_diameter == (d + big_d) / 2


@pytest.mark.parametrize("name", sorted(KOYO_B2001))
def test_koyo_load_centre_fits_the_contact_angle(name):
    """The printed load centre a = B/2 + d_m tan(alpha)/2 at the contact angle the name
    stands for (to 1 mm), and at no other of 15°, 30°, 40°: each row sits beside its name."""
    d, big_d, b, *_, a = KOYO_B2001[name]
    parsed = parse_angular(_stored(name))
    assert parsed is not None

    def off(angle: float) -> float:
        return abs(b / 2 + (d + big_d) / 4 * math.tan(math.radians(angle)) - a)

    assert off(parsed.contact_angle) < 1.0
    assert all(off(other) > 1.5 for other in (15.0, 30.0, 40.0) if other != parsed.contact_angle)


def test_koyo_printed_f0_of_the_15_degree_rows_fits_the_ball_set():
    """ISO 76: C_0r = f0 z D_w^2 cos(alpha); Koyo prints f0 for the C rows (within 1.3 %)."""
    rows = _rows("KOYO")
    for name, (*_, c0, f0, _a) in KOYO_B2001.items():
        if f0 is not None:
            r = rows[name]
            fit = f0 * r.balls * r.ball_diameter**2 * math.cos(math.radians(15)) / (c0 * 1000)
            assert abs(fit - 1) < 0.013, name


def test_resolve_picks_nsk_else_the_one_maker_and_takes_a_named_one():
    assert resolve_bearing("7205B").C == 16700.0  # NSK's BEA row (NSK and Koyo have one)
    assert resolve_bearing("7205B", maker="koyo").C == 14000.0
    koyo = resolve_bearing("7205C")  # Koyo's only
    assert (koyo.contact_angle, koyo.C, koyo.C0, koyo.balls) == (15.0, 16600.0, 10200.0, 12)
    assert resolve_bearing("7205A").contact_angle == 30.0
    with pytest.raises(InputError, match="KOYO only"):
        resolve_bearing("7205C", maker="NSK")


def _iso_ratings(z: int, dw: float, dm: float, alpha: float) -> tuple[float, float]:
    """ISO 281:2007 6.1.1 C_r = b_m f_c (cos a)^0.7 z^(2/3) D_w^1.8 and ISO 76:2006 6.1.1
    C_0r = f_0 z D_w^2 cos a, f_c and f_0 at gamma = D_w cos a / d_m (one row)."""
    ca = math.cos(math.radians(alpha))
    power = dw**1.8 if dw <= 25.4 else 3.647 * dw**1.4  # ISO 281 6.1.1, D_w above 25.4 mm
    cr = B_M * float(f_c(dw * ca, dm)) * ca**0.7 * z ** (2 / 3) * power
    return cr, float(f_0(dw * ca, dm)) * z * dw**2 * ca


def _best_sets(rows: list[AngularRow], dm: float) -> list[tuple[float, int, float]]:
    """Every standard ball set on d_m scored by its worst ISO rating residual over ``rows``."""
    return sorted(
        (max(max(abs(cr / r.C - 1), abs(c0 / r.C0 - 1))
             for r in rows for cr, c0 in [_iso_ratings(z, float(dw), dm, r.contact_angle)]),
         z, float(dw))
        for z in range(5, 40)
        for dw in standard_ball_sizes()
        if z * dw < math.pi * dm
        and all(0.01 <= dw * math.cos(math.radians(r.contact_angle)) / dm <= 0.4 for r in rows)
    )  # fmt: skip


@pytest.mark.parametrize(
    "row",
    [r for r in _rows("NSK").values() if r.contact_angle == 40.0],
    ids=lambda r: r.designation,
)
def test_derived_ball_set_is_the_best_inversion_of_the_ratings(row):
    best = _best_sets([row], row.pitch_diameter)[0]
    assert best[1] == row.balls and best[2] == pytest.approx(row.ball_diameter, abs=5e-5)
    assert best[0] < 0.005  # the ratings reproduced to 0.5 %


def _koyo_sizes() -> dict[str, list[AngularRow]]:
    sizes: dict[str, list[AngularRow]] = {}
    for r in _rows("KOYO").values():
        sizes.setdefault(r.designation[:4], []).append(r)
    return sizes


@pytest.mark.parametrize("size", sorted(_koyo_sizes()))
def test_koyo_ball_set_is_the_best_joint_inversion_of_the_size(size):
    """One set for the 15°, 30° and 40° bearings of a size, the best over all their ratings
    (each within 2 %); 'high' confidence: within 1 % and the next set 0.5 % further off."""
    rows = _koyo_sizes()[size]
    best, nxt = _best_sets(rows, rows[0].pitch_diameter)[:2]
    for r in rows:
        assert (r.balls, r.ball_diameter) == (best[1], pytest.approx(best[2], abs=5e-6))
    assert best[0] < 0.02
    high = best[0] <= 0.01 and nxt[0] - best[0] >= 0.005
    assert {r.confidence for r in rows} == {"high" if high else "medium"}


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


@pytest.mark.parametrize(
    ("text", "near"),
    [("7305AC", "no 25° row of series 73"), ("7305A5", "no 25° row of series 73"),
     ("46202", "the 26° rows of series 2 are 46204, 46205, 46206, 46207,"),
     ("66205", "the 36° rows of series 2 are 66203, 66211"), ("36405", "no 12° row of series 4"),
     ("7221B", "40° rows of series 72 are 7200B, 7201B,"), ("7321C", "7320C")],
)  # fmt: skip
def test_known_type_without_a_row_is_one_error_naming_the_rows(capsys, text, near):
    code, out, err = run_entry(capsys, "solve", text, "-F", "2kN", "-A", "1kN")
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and lines[0].startswith("Error:")
    assert "angular contact ball bearing" in err and near in err
    parsed = parse_angular(text)
    assert parsed is not None and f"{parsed.contact_angle:g}°" in err
    assert "Traceback" not in err


def test_solve_7205b_equals_the_hand_given_ring_and_reports_l10_p0(capsys):
    code, out, err = run_entry(capsys, "solve", "7205B", "-F", "2kN", "-A", "3kN",
                               "--format", "json")  # fmt: skip
    assert code == 0 and besides_tilt(err) == []
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
    assert [r["designation"] for r in rows] == [r.designation for r in angular_rows()]
    # the 25° rows: test_angular_25deg.py; the 79 series: test_angular_79.py
    nsk = [*NSK_BEA_40, *NSK_PRECISION_A5, *NSK_PRECISION_79]
    assert [r["designation"] for r in rows if r["maker"].startswith("NSK")] == nsk
    epk = [r for r in rows if r["maker"].startswith("EPK")]  # GOST rows: test_angular_gost.py
    zap = [r for r in rows if r["maker"].startswith("ZAP")]  # test_angular_gost_table.py
    assert len(epk) == 53 and len(zap) == 14
    assert len(rows) == len(nsk) + len(KOYO_B2001) + len(epk) + len(zap)
    code, out, _ = run_entry(capsys, "catalog", "show", "36205", "--format", "json")
    doc = json.loads(out)
    assert doc["contact_angle"] == 12.0 and doc["maker"] == "EPK" and "2011" in doc["source"]
    code, out, _ = run_entry(capsys, "catalog", "show", "7205 BEP", "--format", "json")
    doc = json.loads(out)
    assert doc["contact_angle"] == 40.0 and doc["balls"] == 12 and doc["C"] == 16700.0
    assert "NSK" in doc["source"] and "derived" in doc["notes"]
    code, out, err = run_entry(capsys, "catalog", "--type", "angular", "--series", "72")
    assert code == 2 and err.startswith("Error:") and "--type" in err


@pytest.mark.parametrize(
    "text", ["7205BDB", "7205BDF", "7205B/DT", "7205B DB", "7205AC/DBA", "7205BDBL", "7205CDFEL"]
)
def test_a_matched_pair_is_refused_not_solved_as_one_bearing(text):
    """NSK's 7205BDB (back-to-back), DF, DT and the /DB forms name two bearings: they were
    read past as maker suffixes and solved as one single-row 7205B."""
    with pytest.raises(InputError, match="matched pair or set") as info:
        resolve_bearing(text)
    assert info.value.parameter == "bearing"


@pytest.mark.parametrize("text", ["7205BDBX", "7205B/DFT", "7205BDBLX"])
def test_a_set_suffix_with_letters_not_read_is_refused_not_solved_as_one_bearing(text):
    """A set suffix followed by letters other than a preload class was read past as a maker
    suffix and solved as one single-row 7205B, silently (7205BDBL, NSK's DB with a light
    preload, is a pair with its class: test_preload_classes.py)."""
    with pytest.raises(InputError, match="is not read") as info:
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
    assert code == 2 and "Invalid value for '--maker'" in err and "rows of NSK, KOYO only" in err
    code, out, err = run_entry(capsys, "solve", "7205B", "-F", "1kN", "--maker", "SKF")
    assert code == 2 and "rows of NSK, KOYO only" in err
    code, out, err = run_entry(capsys, "catalog", "show", "7205B", "--maker", "koyo", "--format",
                               "json")  # fmt: skip
    assert code == 0 and json.loads(out)["C"] == 14000.0


def test_solve_7205c_takes_koyos_printed_f0_for_the_15_degree_factors(capsys):
    """ISO 281 Table 3 at 15°: e, Y interpolated in i f0 F_a/C0r with the f0 Koyo prints (14.0);
    here f0 F_a/C0r = 1.3725, between the knots 1.07 (e 0.46, Y 1.23) and 1.43 (0.47, 1.19)."""
    code, out, err = run_entry(capsys, "solve", "7205C", "-F", "2kN", "-A", "1kN",
                               "--format", "json")  # fmt: skip
    assert code == 0 and besides_tilt(err) == []
    case = json.loads(out)["cases"][0]
    t = (14.0 * 1000 / 10200 - 1.07) / (1.43 - 1.07)
    assert 1000 / 2000 > 0.46 + t * 0.01  # F_a/F_r > e
    p = 0.44 * 2000 + (1.23 - t * 0.04) * 1000
    assert case["equivalent_load"] == pytest.approx(p, rel=1e-9)
    assert case["rating_life"] == pytest.approx((16600 / p) ** 3, rel=1e-9)
    assert case["static_equivalent_load"] == pytest.approx(max(2000, 1000 + 0.46 * 1000))
