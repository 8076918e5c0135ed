"""GOST 831 single-row angular-contact rows (types 36000 12°, 46000 26°, 66000 36°): the EPK
rows against the printed EPK General Catalogue 2011 lines copied in the fixture, which printed
lines become rows (the rule re-applied here), their derived ball sets re-derived from the
ratings (ISO 281 / ISO 76 at the printed angle, written out here), and ``solve`` of a GOST
designation at its contact angle."""

from __future__ import annotations

import json
import math
import re

import pytest

from bearingload.bearings.angular import AngularRow, angular_rows, parse_angular
from bearingload.bearings.ratings import B_M, f_0, f_c, standard_ball_sizes
from bearingload.bearings.resolve import resolve_bearing

from .cli_helpers import besides_tilt, run_entry
from .fixtures.angular_factors import EPK_2011

#: GOST 831-75 type digit -> nominal contact angle, as EPK's p. 279 prints it. [°]
TYPE_ANGLE = {"3": 12, "4": 26, "6": 36}


def _epk_rows() -> dict[str, AngularRow]:
    return {r.designation: r for r in angular_rows() if r.maker == "EPK"}


def _printed_at_nominal() -> dict[str, list[tuple[str, tuple[float, ...]]]]:
    """The printed lines of each base designation at its type's nominal angle, K variants
    (a different design, not read by the parser) left out."""
    groups: dict[str, list[tuple[str, tuple[float, ...]]]] = {}
    for name, (d, big_d, b, alpha, c, c0) in EPK_2011.items():
        m = re.match(r"^([346])6([1-4])(\d{2})(.*)$", name)
        assert m is not None, name
        if m.group(4)[:1] in ("K", "К") or alpha != TYPE_ANGLE[m.group(1)]:
            continue
        groups.setdefault(name[:5], []).append((name, (d, big_d, b, alpha, c, c0)))
    return groups


def _iso_ratings(z: int, dw: float, dm: float, alpha: float) -> tuple[float, float]:
    """ISO 281:2007 6.1.1 C_r = b_m f_c (cos a)^0.7 z^(2/3) D_w^1.8 (3.647 D_w^1.4 above
    25.4 mm) and ISO 76:2006 6.1.1 C_0r = f_0 z D_w^2 cos a, at gamma = D_w cos a / d_m."""
    ca = math.cos(math.radians(alpha))
    power = dw**1.8 if dw <= 25.4 else 3.647 * dw**1.4
    cr = B_M * float(f_c(dw * ca, dm)) * ca**0.7 * z ** (2 / 3) * power
    return cr, float(f_0(dw * ca, dm)) * z * dw**2 * ca


def _ranges() -> tuple[float, float, float, float]:
    """D_w / ((D - d)/2) and the fill z D_w / (pi d_m) over the NSK 40° (BEA) and Koyo angular
    sets, those there were when the EPK rows were derived (NSK's 25° rows came later)."""
    rows = [
        r
        for r in angular_rows()
        if r.maker in ("NSK", "KOYO") and r.contact_angle != 25.0 and r.designation[:2] != "79"
    ]
    ratio = [r.ball_diameter / ((r.D - r.d) / 2) for r in rows]
    fill = [r.balls * r.ball_diameter / (math.pi * r.pitch_diameter) for r in rows]
    return min(ratio), max(ratio), min(fill), max(fill)


def _best_sets(d: float, big_d: float, alpha: float, c: float, c0: float):
    """Standard ball sets within the ranges, scored by the worse of the two ISO residuals."""
    lo, hi, flo, fhi = _ranges()
    dm, section = (d + big_d) / 2, (big_d - d) / 2
    return sorted(
        (max(abs(cr / c - 1), abs(c0r / c0 - 1)), z, float(dw))
        for z in range(5, 40)
        for dw in standard_ball_sizes()
        if lo <= dw / section <= hi and flo <= z * dw / (math.pi * dm) <= fhi
        for cr, c0r in [_iso_ratings(z, float(dw), dm, alpha)]
    )


def test_the_fixture_holds_every_printed_line_once():
    assert len(EPK_2011) == 158
    assert {v[3] for v in EPK_2011.values()} == {12, 15, 18, 26, 36, 40}


def test_rows_are_the_printed_lines_where_the_variants_agree_and_a_set_fits():
    """A base designation has a row when its printed variants at the nominal angle agree on
    d, D, B, C_r, C_0r and a standard set reproduces both ratings within 2 %; else none
    (36206, 46206, 36208 ... disagree; 46205, 36215 ... fit no set)."""
    expected = set()
    for base, lines in _printed_at_nominal().items():
        values = {v for _, v in lines}
        if len(values) != 1:
            continue
        d, big_d, _b, alpha, c, c0 = values.pop()
        if _best_sets(d, big_d, alpha, c, c0)[0][0] <= 0.02:
            expected.add(base)
    assert set(_epk_rows()) == expected
    assert {"36206", "46206", "36208", "36210", "36212", "36213", "46213"}.isdisjoint(expected)
    assert {"36205", "46208", "66211"} <= expected and "46205" not in expected


@pytest.mark.parametrize("name", sorted(_epk_rows()))
def test_row_matches_the_printed_lines(name):
    row = _epk_rows()[name]
    lines = dict(_printed_at_nominal()[name])
    for variant, (d, big_d, b, alpha, c, c0) in lines.items():
        assert (row.d, row.D, row.B, row.C, row.C0) == (d, big_d, b, c, c0), variant
        assert row.contact_angle == alpha == parse_angular(name).contact_angle
        assert variant in row.notes
    assert row.pitch_diameter == (row.d + row.D) / 2
    assert row.method == "derived" and "EPK" in row.source and "2011" in row.source
    assert row.limiting_speed_grease is None and row.limiting_speed_oil is None


@pytest.mark.parametrize("name", sorted(_epk_rows()))
def test_ball_set_is_the_best_inversion_and_the_confidence_follows_the_rule(name):
    row = _epk_rows()[name]
    best, nxt = _best_sets(row.d, row.D, row.contact_angle, row.C, row.C0)[:2]
    assert (row.balls, row.ball_diameter) == (best[1], pytest.approx(best[2], abs=5e-5))
    assert best[0] <= 0.02
    high = best[0] <= 0.01 and nxt[0] - best[0] >= 0.005
    assert row.confidence == ("high" if high else "medium")
    assert f"within {best[0] * 100:.2f} %" in row.notes


@pytest.mark.parametrize(("text", "alpha"), [("36205", 12.0), ("46208", 26.0), ("66211", 36.0)])
def test_gost_designation_resolves_to_its_row_at_the_type_angle(text, alpha):
    b = resolve_bearing(text)
    row = _epk_rows()[text]
    assert b.contact_angle == alpha == row.contact_angle
    assert (b.balls, b.ball_diameter, b.pitch_diameter) == (
        row.balls, row.ball_diameter, row.pitch_diameter)  # fmt: skip
    assert (b.C, b.C0, b.clearance) == (row.C, row.C0, 0.0)


def test_solve_36205_equals_the_hand_given_ring_with_l10r_and_no_l10(capsys):
    code, out, err = run_entry(capsys, "solve", "36205", "-F", "1kN", "-A", "500N",
                               "--format", "json")  # fmt: skip
    assert code == 0 and besides_tilt(err) == []
    case = json.loads(out)["cases"][0]
    row = _epk_rows()["36205"]
    code, out, _ = run_entry(
        capsys, "solve", "--balls", str(row.balls), "--ball-diameter", repr(row.ball_diameter),
        "--pitch-diameter", repr(row.pitch_diameter), "-F", "1kN", "-A", "500N",
        "--contact-angle", "12", "--dynamic-rating", "15600", "--static-rating", "9600",
        "--format", "json",
    )  # fmt: skip
    hand = json.loads(out)["cases"][0]
    for key in ("q_max", "x", "axial", "tilt", "reference_rating_life", "contact_angle"):
        assert case[key] == pytest.approx(hand[key], rel=1e-12), key
    assert case["contact_angle"] == 12.0 and case["reference_rating_life"] > 0
    # ISO 281 Table 3 has no 12° row: L10, P and P0 are left out, not guessed
    assert case.get("rating_life") is None and case.get("equivalent_load") is None


def test_gost_type_without_a_row_names_the_rows_of_its_type(capsys):
    code, out, err = run_entry(capsys, "solve", "46202", "-F", "2kN", "-A", "1kN")
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and lines[0].startswith("Error:")
    assert "26°" in err and "46208" in err and "36205" not in err


@pytest.mark.parametrize(
    ("text", "plain", "words"),
    [
        ("36205K", "36205", "the suffix K is not read"),
        ("36205 K6", "36205", "the suffix K6 is not read"),
        ("66211K", "66211", "the suffix K is not read"),
        ("46305DF", "46305", "give 46305 with the arrangement DF"),
        ("36205DB", "36205", "give 36205 with the arrangement DB"),
    ],
)
def test_gost_designation_with_a_suffix_names_the_plain_row(capsys, text, plain, words):
    """36205K and 36205DB said 'an angular contact ball bearing ... which bearingload does not
    model; it models single-row deep groove ... and cylindrical roller bearings' (false: 36205
    is modelled), 66211K 'cannot read'; the refusal names the plain designation."""
    with pytest.raises(Exception) as info:
        resolve_bearing(text)
    message = str(info.value)
    assert getattr(info.value, "parameter", None) == "bearing"
    assert "does not model" not in message and "--" not in message
    assert words in message and plain in message
    code, out, err = run_entry(capsys, "solve", text, "-F", "1kN", "-A", "300N")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith("Error: Invalid value for 'BEARING': ") and words in err
    code, out, err = run_entry(capsys, "catalog", "show", text)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith("Error: Invalid value for 'DESIGNATION': ") and words in err
