"""Designation + overrides + clearance -> geometry, K, G_r and sources (bearingload.bearings.resolve),
and one bearing reproduced end to end against a peer calculation."""

from __future__ import annotations

import csv
import io

import pytest

from bearingload.bearings.resolve import parse_clearance, resolve_bearing
from bearingload.contact.hertz import ball_stiffness
from bearingload.errors import InputError
from bearingload.models.equilibrium import solve
from bearingload.studies.loaded_bearing import solve_bearing
from bearingload.units import KGF

from .cli_helpers import committed

# NSK Rolling Bearings catalogue, Table 9.9 (ISO 5753-1), deep groove ball bearings, bore over
# 24 incl 30 mm: C3 = 13-28 µm, CN = 5-20 µm; bore over 30 incl 40: C4 = 28-46 µm.
NSK_C3_BORE_30_UM = (13.0, 28.0)
NSK_CN_BORE_30_UM = (5.0, 20.0)
NSK_C4_BORE_40_UM = (28.0, 46.0)
# Radial load of the worked example of Kuzmenko (2010), §3.3: 300 kgf. [N]
PAPER_LOAD = 300.0 * KGF

# Peer calculation: GitHub minzhun/ISO16281, Test_BallBearing.py (the version whose examples use
# BallBearing(1, 7, 11.5, 43.5, 0.0, 0.0, 1), "Test with 6305" in BallBearing.py), comments of
# Example 1 and Example 3: deep groove ball bearing, one row, Z = 7, D_w = 11.5 mm,
# D_pw = 43.5 mm, r_i = 0.52 D_w, r_e = 0.53 D_w, contact angle 0, ball 1 on the load line,
# E = 210000 MPa, nu = 0.3, F_r = 1000 N. Reference radial displacement of the inner ring
# ("Delta"): 15.1101 µm at zero clearance (Example 1), 21.223 µm at radial operating clearance
# s_r = 0.01 mm (Example 3). The reference values are comments of the test script; the code
# names its axial output "Delta_a_MASTA", so they appear to come from SMT MASTA.
PEER_6305 = {"balls": 7, "ball_diameter": 11.5, "modulus": 210000.0, "poisson": 0.3}
PEER_LOAD = 1000.0
PEER_DELTA_R_UM = {0.0: 15.1101, 0.01: 21.223}


@pytest.mark.parametrize(("clearance", "delta_um"), sorted(PEER_DELTA_R_UM.items()))
def test_peer_6305_end_to_end(clearance, delta_um):
    """Catalogue row 6305 (d 25, D 62 -> d_m 43.5 mm, default f_i 0.52, f_o 0.53) with the peer's
    ball set: geometry -> exact Hertz K -> ring equilibrium -> inner-ring displacement."""
    b = resolve_bearing("6305", clearance=clearance, **PEER_6305)
    assert b.pitch_diameter == 43.5 and (b.f_i, b.f_o) == (0.52, 0.53)
    (case,) = solve_bearing([b], PEER_LOAD)
    # measured: 15.11020 and 21.22281 µm, i.e. 7 ppm above and 4 ppm below the reference
    assert float(case.result.x) * 1e3 == pytest.approx(delta_um, rel=1e-5)
    assert int(case.result.loaded_balls) == 3


def test_306_defaults_catalogue_hertz_and_cn():
    b = resolve_bearing("306")
    assert (b.balls, b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o) == (
        8,
        12.3,
        51.0,
        0.515,
        0.515,
    )
    k = ball_stiffness(12.3, 51.0, 0.515, 0.515, 208000.0, 0.3)
    assert b.stiffness == pytest.approx(float(k.ball), rel=1e-15)
    assert (b.stiffness_inner, b.stiffness_outer) == (float(k.inner), float(k.outer))
    assert not b.stiffness_given
    # no class marked in '306': the normal group CN, mean of its range at d = 30 mm
    assert b.clearance_class == "CN"
    assert b.clearance * 1e3 == pytest.approx(sum(NSK_CN_BORE_30_UM) / 2)
    assert b.C == pytest.approx(2200 * KGF)
    src = {p.key: p.source for p in b.provenance}
    assert src["balls"] == "catalogue" and src["pitch_diameter"] == "(d + D)/2"
    assert src["stiffness"].startswith("Hertz, exact")
    assert "no class marked in the designation: CN" in src["clearance"]
    assert any("Kuzmenko 2010" in s for s in b.sources)


@pytest.mark.parametrize(("pick", "index"), [("min", 0), ("max", 1)])
def test_clearance_class_by_bore(pick, index):
    b = resolve_bearing("6306", clearance="C3", clearance_pick=pick)
    assert b.clearance * 1e3 == pytest.approx(NSK_C3_BORE_30_UM[index])
    assert b.clearance_range == pytest.approx(tuple(v / 1e3 for v in NSK_C3_BORE_30_UM))
    mean = b.with_clearance("mean")
    assert mean.clearance * 1e3 == pytest.approx(20.5)
    assert "C3 13-28 µm at d = 30 mm, mean" in next(
        p.source for p in mean.provenance if p.key == "clearance"
    )


def test_class_from_the_designation_and_gost_group():
    assert resolve_bearing("6308-2RS/C4").clearance_class == "C4"
    b = resolve_bearing("86-308")  # GOST prefix, read leftwards: accuracy 6, clearance group 8
    assert b.clearance_class == "C4"
    assert b.clearance * 1e3 == pytest.approx(sum(NSK_C4_BORE_40_UM) / 2)
    assert resolve_bearing("306", clearance="G7").clearance_class == "C3"


def test_a_bare_number_is_a_length_not_a_group():
    # never group 7: a bare 7 is 7 mm, refused as implausible with both readings offered
    with pytest.raises(InputError, match=r"did you mean 7um\?.*group 7 is written G7"):
        parse_clearance("7")
    assert parse_clearance("7mm").length == 7.0
    assert parse_clearance("0.7").length == 0.7
    assert parse_clearance("G7").cls == "C3"
    assert parse_clearance(0.02).length == 0.02
    assert resolve_bearing("306", clearance="-10um").clearance == pytest.approx(-0.01)


def test_overrides_are_marked_and_used():
    b = resolve_bearing("306", ball_diameter=12.0, f_i=0.52, modulus=2.1e5, stiffness=None)
    src = {p.key: p.source for p in b.provenance}
    assert src["ball_diameter"] == src["f_i"] == "given (override)"
    assert src["f_o"] == "catalogue" and src["modulus"] == "given"
    k = ball_stiffness(12.0, 51.0, 0.52, 0.515, 2.1e5, 0.3)
    assert b.stiffness == pytest.approx(float(k.ball), rel=1e-15)
    given = resolve_bearing("306", stiffness=4700 * KGF)
    assert given.stiffness_given and given.stiffness == 4700 * KGF
    assert given.stiffness_inner is not None  # still known from the geometry, for p_max


def test_without_designation():
    b = resolve_bearing(balls=9, stiffness=3.8e5, clearance="15um")
    assert (b.balls, b.stiffness, b.clearance) == (9, 3.8e5, 0.015)
    assert not b.has_geometry and b.C is None
    assert resolve_bearing(balls=9, stiffness=3.8e5).clearance == 0.0
    g = resolve_bearing(balls=9, ball_diameter=12.7, pitch_diameter=60.0)
    assert (g.f_i, g.f_o) == (0.52, 0.53)
    assert g.stiffness == pytest.approx(float(ball_stiffness(12.7, 60.0, 0.52, 0.53).ball))


@pytest.mark.parametrize(
    ("kwargs", "parameter", "message"),
    [
        ({"designation": "9999"}, "bearing", "cannot read '9999'"),
        ({"designation": "6302"}, "bearing", "ball set is unknown"),
        ({"balls": 8, "stiffness": 1e5, "clearance": "C3"}, "clearance", "resolved by the bore"),
        ({"balls": 8}, "stiffness", "the ball stiffness"),
        ({"balls": 8, "ball_diameter": 10.0}, "pitch_diameter", "beside 'ball_diameter'"),
        ({"balls": 8, "pitch_diameter": 40.0}, "ball_diameter", "beside 'pitch_diameter'"),
        ({"stiffness": 1e5}, "balls", "number of balls"),
        ({"designation": "306", "poisson": 0.7}, "poisson", r"\(-1, 0.5\]"),
        ({"designation": "306", "modulus": -1.0}, "modulus", "greater than 0"),
        (
            {"designation": "306", "clearance": "C9"},
            "clearance",
            "cannot read 'C9'.*or a clearance class",
        ),
        ({"designation": "306", "clearance": "5 furlong"}, "clearance", "unknown unit"),
        ({"designation": "306", "f_o": 0.45}, "f_o", r"\(0.5, 1\)"),
        ({"designation": "306", "clearance_pick": "median"}, "pick", "unknown pick"),
    ],
)
def test_bad_input(kwargs, parameter, message):
    with pytest.raises(InputError, match=message) as info:
        resolve_bearing(**kwargs)
    assert info.value.parameter == parameter


def test_range_needs_a_class():
    with pytest.raises(InputError, match="needs a clearance class") as info:
        resolve_bearing("306", clearance="20um").with_clearance("min")
    assert info.value.parameter == "pick"


def test_pressures_life_and_allowable_load_of_a_case():
    b = resolve_bearing("306", clearance=0.02)
    (case,) = solve_bearing([b], 300 * KGF, revolutions=36e6)
    from bearingload.contact.hertz import ball_contacts

    c = ball_contacts(float(case.result.q_max), 12.3, 51.0, 0.515, 0.515, 208000.0, 0.3)
    assert case.p_max_inner == float(c.inner.p_max) and case.p_max_outer == float(c.outer.p_max)
    assert case.rating_life == pytest.approx((2200 / 300) ** 3, rel=1e-12)
    assert case.allowable_load / KGF == pytest.approx(2200 / 36 ** (1 / 3), rel=1e-12)


def test_committed_306_tables_use_the_papers_conditions():
    """tables/table1_k_306_300kgf_gr20um: E = 2.1e4 kgf/mm^2 (Kuzmenko 2010 §3.4), exact K."""
    # bearing 306 as Kuzmenko (2010) §3 takes it: catalogue geometry, E = 2.1e4 kgf/mm^2, nu = 0.3
    b = resolve_bearing("306", modulus=2.1e4 * KGF, poisson=0.3, clearance=0.02)
    k = ball_stiffness(12.3, 51.0, 0.515, 0.515, 2.1e4 * KGF, 0.3)
    assert b.stiffness == pytest.approx(float(k.ball), rel=1e-15)
    text, on_disk = committed("table1_k_306_300kgf_gr20um.csv")
    assert text == on_disk
    rows = list(csv.DictReader(io.StringIO(text)))
    row8 = next(row for row in rows if row["balls"] == "8")
    r = solve(8, PAPER_LOAD, b.stiffness, 0.02)
    assert (row8["loaded_balls"], row8["k"]) == ("3", repr(float(f"{float(r.k):.10g}")))
    # the conditions travel with the numbers: one rectangular csv
    assert row8["bearing"] == "306" and row8["clearance [mm]"] == "0.02"
    assert float(row8["load [N]"]) == pytest.approx(PAPER_LOAD, rel=1e-9)
