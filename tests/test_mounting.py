"""The operating clearance: the fits (ISO 286 seats, ISO 492 Normal rings) and the ring
temperatures take clearance (bearingload.bearings.mounting, bearingload.bearings.tolerances)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from bearingload.bearings.mounting import (
    STEEL_EXPANSION,
    inner_fit_reduction,
    outer_fit_reduction,
    thermal_reduction,
)
from bearingload.bearings.resolve import resolve_bearing, resolve_bearings
from bearingload.bearings.tolerances import fit_limits, ring_limits
from bearingload.errors import InputError
from tests.cli_helpers import invoke

#: ISO 286-2 limits (µm) as the standard's tables print them, class -> size [mm] -> (upper,
#: lower); the package derives them from ISO 286-1's IT grades, fundamental deviations and the
#: Delta rule of the holes K to P, so these check the derivation.
PRINTED_ISO286 = {
    "k5": {25: (11, 2), 40: (13, 2), 60: (15, 2), 100: (18, 3)},
    "k6": {25: (15, 2), 60: (21, 2)},
    "m5": {25: (17, 8), 40: (20, 9)},
    "m6": {25: (21, 8), 60: (30, 11), 150: (40, 15)},
    "n6": {25: (28, 15), 60: (39, 20)},
    "p6": {25: (35, 22), 60: (51, 32)},
    "j5": {25: (5, -4), 60: (6, -7)},
    "H7": {52: (30, 0), 100: (35, 0)},
    "J7": {52: (18, -12), 40: (14, -11)},
    "K7": {52: (9, -21), 40: (7, -18), 100: (10, -25)},
    "M7": {52: (0, -30), 25: (0, -21)},
    "N7": {52: (-9, -39), 40: (-8, -33), 25: (-7, -28)},
    "P7": {52: (-21, -51), 25: (-14, -35)},
}


@pytest.mark.parametrize("fit", sorted(PRINTED_ISO286))
def test_iso286_limits_are_those_the_standard_prints(fit):
    param = "shaft_fit" if fit[0].islower() else "housing_fit"
    for size, (upper, lower) in PRINTED_ISO286[fit].items():
        limits = fit_limits(fit, float(size), param)
        assert (limits.upper, limits.lower) == (upper, lower), (fit, size)


#: A public fits table of radial bearings of the Normal class on j5 and j6 shafts (the Chinese
#: national standard's table of bearing-shaft fits, as reprinted by gbbco.cn "fits among the
#: bearing, the axle and the housing", Table 1): bore over, incl [mm] -> class -> (largest
#: clearance, largest interference) [µm]. It combines the ISO 492 bore tolerance and the ISO
#: 286 shaft class, an independent check of both tables.
PUBLIC_FITS = {
    (3, 6): {"j5": (2, 11), "j6": (2, 14)},
    (6, 10): {"j5": (2, 12), "j6": (2, 15)},
    (10, 18): {"j5": (3, 13), "j6": (3, 16)},
    (18, 30): {"j5": (4, 15), "j6": (4, 19)},
    (30, 50): {"j5": (5, 18), "j6": (5, 23)},
    (50, 80): {"j5": (7, 21), "j6": (7, 27)},
    (80, 120): {"j5": (9, 26), "j6": (9, 33)},
}


@pytest.mark.parametrize("span", sorted(PUBLIC_FITS))
def test_shaft_and_bore_tolerances_give_the_published_fits(span):
    d = 0.5 * (span[0] + span[1])
    bore = ring_limits("inner", d)
    for fit, (clearance, interference) in PUBLIC_FITS[span].items():
        shaft = fit_limits(fit, d, "shaft_fit")
        assert bore.upper - shaft.lower == clearance
        assert shaft.upper - bore.lower == interference


def _lame(interference, r_in, r_fit, r_out, inner_body_bore=0.0, nu=0.3, e=208000.0):
    """Two thick cylinders of one material pressed together with the diametral
    ``interference``, solved numerically (plane stress, u = A r + B/r in each body, four
    boundary conditions): the inner body spans (inner_body_bore, r_fit), the outer (r_fit,
    r_out). Returns (u of the inner body at r_in, u of the outer body at r_out) [mm]."""

    # unknowns: A1, B1 (inner body), A2, B2 (outer body); sigma_r = E/(1-nu^2) (A(1+nu) - B(1-nu)/r^2)
    def sr(r):
        return np.array([(1 + nu), -(1 - nu) / r**2]) * e / (1 - nu**2)

    rows, rhs = [], []
    z2 = np.zeros(2)
    if inner_body_bore > 0:
        rows.append(np.r_[sr(inner_body_bore), z2])
    else:
        rows.append(np.r_[0.0, 1.0, z2])  # a solid body: no 1/r term
    rhs.append(0.0)
    rows.append(np.r_[z2, sr(r_out)])  # free outside
    rhs.append(0.0)
    rows.append(np.r_[sr(r_fit), -sr(r_fit)])  # equal pressure at the fit
    rhs.append(0.0)
    rows.append(np.r_[-r_fit, -1 / r_fit, r_fit, 1 / r_fit])  # u_outer - u_inner = I/2
    rhs.append(interference / 2)
    a1, b1, a2, b2 = np.linalg.solve(np.array(rows), np.array(rhs))
    return a1 * r_in + b1 / r_in, a2 * r_out + b2 / r_out


@pytest.mark.parametrize("shaft_bore", [None, 10.0, 20.0])
def test_inner_ring_growth_is_lames_thick_rings(shaft_bore):
    """Ring of bore 25 and raceway 30.5 mm on a (hollow) shaft: the closed form against the
    numerical solution of the two cylinders."""
    d, f, i = 25.0, 30.5, 0.0115
    _, u_raceway = _lame(i, d / 2, d / 2, f / 2, 0.0 if shaft_bore is None else shaft_bore / 2)
    assert inner_fit_reduction(i, d, f, shaft_bore) == pytest.approx(2 * u_raceway, rel=1e-12)


@pytest.mark.parametrize("housing", [None, 80.0, 60.0])
def test_outer_ring_shrinking_is_lames_thick_rings(housing):
    d_out, e_race, i = 52.0, 46.4, 0.02
    r_h = 1e7 if housing is None else housing / 2  # a very thick housing stands for infinite
    u_raceway, _ = _lame(i, e_race / 2, d_out / 2, r_h, e_race / 2)
    expected = -2 * u_raceway
    assert outer_fit_reduction(i, d_out, e_race, housing) == pytest.approx(expected, rel=1e-9)


def test_loose_fits_and_equal_temperatures_take_nothing():
    assert inner_fit_reduction(-0.005, 25.0, 30.0) == 0.0
    assert outer_fit_reduction(0.0, 52.0, 46.0) == 0.0
    assert thermal_reduction(40.0, 40.0, 46.0) == 0.0
    assert thermal_reduction(30.0, 40.0, 46.0) < 0.0  # a warmer outer ring gives clearance


def test_c3_6205_on_k5_with_the_inner_ring_10k_warmer_by_hand():
    """The case of the issue that asked for the mounting: by the formulas, written out."""
    b = resolve_bearing("6205", clearance="C3", shaft_fit="k5", inner_ring_temperature=50.0,
                        outer_ring_temperature=40.0)  # fmt: skip
    f = b.pitch_diameter - b.ball_diameter
    e = b.pitch_diameter + b.ball_diameter
    # C3 at 25 mm: 13-28 µm; k5: +2/+11 µm; bore 0/-10 µm -> interference 2 .. 21, mean 11.5
    by_hand = 0.0205 - 0.0115 * 25.0 / f - STEEL_EXPANSION * 10.0 * e
    assert b.clearance == pytest.approx(by_hand, rel=1e-12)
    assert b.mounting.clearance == 0.0205
    low, mean, high = resolve_bearings("6205", clearance="C3", clearance_pick="range",
                                       shaft_fit="k5", inner_ring_temperature=50.0,
                                       outer_ring_temperature=40.0)  # fmt: skip
    assert low.clearance == pytest.approx(0.013 - 0.021 * 25.0 / f - 12.5e-5 * e, rel=1e-12)
    assert high.clearance == pytest.approx(0.028 - 0.002 * 25.0 / f - 12.5e-5 * e, rel=1e-12)
    assert mean.clearance == pytest.approx(by_hand, rel=1e-12)
    assert low.mounting.preloaded and not high.mounting.preloaded


def test_the_solve_runs_at_the_operating_clearance_and_prints_the_unmounted():
    args = ["solve", "6205", "-F", "2kN", "-G", "C3", "--shaft-fit", "k5", "--housing-fit",
            "K7", "--inner-ring-temperature", "50", "--outer-ring-temperature", "40"]  # fmt: skip
    out = invoke(*args, "--format", "json")
    assert out.exit_code == 0, out.output
    case = json.loads(out.output)["cases"][0]
    assert case["clearance"] == 0.0205
    g_op = case["operating_clearance"]
    parts = ("inner_fit", "outer_fit", "temperature")
    taken = sum(case[f"clearance_reduction_{p}"] for p in parts)
    assert g_op == pytest.approx(0.0205 - taken, abs=1e-12)
    same = json.loads(invoke("solve", "6205", "-F", "2kN", "-G", f"{g_op!r}mm", "--format",
                             "json").output)["cases"][0]  # fmt: skip
    assert case["q_max"] == pytest.approx(same["q_max"], rel=1e-9)
    unmounted = json.loads(invoke("solve", "6205", "-F", "2kN", "-G", "C3", "--format",
                                  "json").output)["cases"][0]  # fmt: skip
    assert "operating_clearance" not in unmounted


def test_a_mounting_that_preloads_warns_with_its_preload():
    out = invoke("solve", "6205", "-F", "2kN", "-G", "CN", "--shaft-fit", "p6",
                 "--housing-fit", "P7")  # fmt: skip
    assert out.exit_code == 0
    assert "leave the bearing preloaded: operating clearance -" in out.output
    assert "a radial preload of" in out.output


def test_hollow_shaft_and_thin_housing_take_less():
    solid = resolve_bearing("6205", shaft_fit="n6", housing_fit="N7")
    hollow = resolve_bearing("6205", shaft_fit="n6", housing_fit="N7", shaft_bore=18.0,
                             housing_diameter=60.0)  # fmt: skip
    assert hollow.mounting.reduction_inner_fit < solid.mounting.reduction_inner_fit
    assert hollow.mounting.reduction_outer_fit < solid.mounting.reduction_outer_fit
    assert hollow.clearance > solid.clearance


@pytest.mark.parametrize(
    ("kwargs", "parameter", "words"),
    [
        ({"shaft_fit": "k9"}, "shaft_fit", "allowed: j5 j6 k5 k6 m5 m6 n5 n6 p5 p6"),
        ({"housing_fit": "h7"}, "housing_fit", "allowed: H6 H7 J7 K6 K7 M6 M7 N6 N7 P6 P7"),
        ({"inner_ring_temperature": 300.0, "outer_ring_temperature": 20.0},
         "inner_ring_temperature", "-60 to 250 °C"),
        ({"inner_ring_temperature": 30.0}, "outer_ring_temperature", "together"),
        ({"shaft_fit": "k5", "shaft_bore": 30.0}, "shaft_bore", "less than the bearing's bore"),
        ({"shaft_bore": 10.0}, "shaft_bore", "without one"),
        ({"housing_diameter": 80.0}, "housing_diameter", "housing fit"),
    ],
)  # fmt: skip
def test_bad_mountings_are_refused_naming_what_is_allowed(kwargs, parameter, words):
    with pytest.raises(InputError, match=words) as err:
        resolve_bearing("6205", **kwargs)
    assert err.value.parameter == parameter


def test_a_size_outside_the_tables_names_the_diameters_covered():
    with pytest.raises(InputError, match="over 0 up to 500 mm, not 600 mm"):
        fit_limits("k5", 600.0, "shaft_fit")
    with pytest.raises(InputError, match="Normal class bore has a table for diameters over 0.6"):
        ring_limits("inner", 600.0)


def test_angular_contact_bearings_and_pairs_refuse_a_mounting_saying_why():
    for designation in ("7205B", "7205BDB"):
        out = invoke("solve", designation, "-F", "2kN", "--shaft-fit", "k5")
        assert out.exit_code == 2
        assert "angular-contact bearing has no radial clearance" in out.output
        assert "in a pair its preload" in out.output


def test_batch_takes_the_mounting_columns_by_the_same_names(tmp_path):
    cases = tmp_path / "c.csv"
    cases.write_text("bearing,load,clearance,shaft_fit,inner_ring_temperature,"
                     "outer_ring_temperature\n6205,2000,C3,k5,50,40\n6205,2000,C3,k9,,\n",
                     encoding="utf-8")  # fmt: skip
    out = invoke("batch", str(cases), "--format", "json")
    doc = json.loads(out.stdout)
    row = doc["cases"][0] if "cases" in doc else doc["rows"][0]
    b = resolve_bearing("6205", clearance="C3", shaft_fit="k5", inner_ring_temperature=50.0,
                        outer_ring_temperature=40.0)  # fmt: skip
    assert row["clearance"] == 0.0205
    assert row["operating_clearance"] == pytest.approx(b.clearance, rel=1e-9)
    assert "shaft_fit: unknown ISO 286 class 'k9'; allowed: j5" in out.stderr


def test_the_library_takes_ring_temperatures_as_text():
    """The library's temperatures as text ('70C') were checked but the raw text was used:
    TypeError. They are read with their unit, as the command line reads them."""
    from bearingload.bearings.resolve import resolve_bearing

    temps = {"inner_ring_temperature": "70C", "outer_ring_temperature": "50"}
    text = resolve_bearing("6205", shaft_fit="k5", **temps)
    temps = {"inner_ring_temperature": 70.0, "outer_ring_temperature": 50.0}
    assert text == resolve_bearing("6205", shaft_fit="k5", **temps)
