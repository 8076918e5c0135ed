"""The service lives of a bearing pair (``solve 7205BDB --speed ... --viscosity ...``): each
bearing's values are a single bearing's from its own loads, the pair's hours are its L10 and
L10r at the speed, its modified lives the bearings' combined by the system rule, an unloaded
bearing dropping out. Before these were coded every service option but --static-rating was
refused for a pair ('not coded yet'). At --speed the pair takes the ball dynamics
(tests/test_pair_speed.py); --quasi-static the static pair."""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np
import pytest

from bearingload.bearings import lubrication as lub
from bearingload.bearings import modified_life as ml
from bearingload.bearings.service_life import LifeBasis, Operating, service_values
from bearingload.reports.quantities import SERVICE_KEYS

from .cli_helpers import run_entry

#: The operating conditions given (3000 rpm, 20 cSt, 99 %, sigma 0.2 um).
SERVICE = ["--speed", "3000", "--viscosity", "20cSt", "--reliability", "99",
           "--roughness", "0.2um"]  # fmt: skip
PAIR = ["7205BDB", "--preload", "500N", "-F", "2kN", "-A", "1kN"]
#: Every life key of a single bearing's solve.
LIFE_KEYS = ("rating_life", "reference_rating_life", "rating_life_hours",
             "reference_rating_life_hours", "static_rating", *SERVICE_KEYS)  # fmt: skip
#: The geometry of a bearing the life basis takes (from the JSON's ``bearing``).
GEOMETRY = ("ball_diameter", "pitch_diameter", "f_i", "f_o", "modulus", "poisson")
#: The system exponent e of ball bearings (ISO/TS 16281 4.3: -9/10 = -1/e). [-]
E = 10.0 / 9.0


def _json(capsys, *args: str) -> dict:
    code, out, err = run_entry(capsys, "solve", *args, "--format", "json", "--quiet")
    assert code == 0, err
    return json.loads(out)


def _system(a: float, b: float) -> float:
    """(a^-e + b^-e)^(-1/e), written out here (not the project's pair_life)."""
    return (a ** (-E) + b ** (-E)) ** (-1.0 / E)


@pytest.mark.parametrize("static", [["--quasi-static"], []])
def test_each_bearing_has_the_service_values_of_its_single_bearing_solve(capsys, static):
    # the loads each bearing carries (its F_r, F_a and moment, from the pair's JSON) solved as
    # one bearing give the same ball loads, lives, a_ISO and film: with the static model
    # (--quasi-static both), and with the ball dynamics (the pair's at speed, the single
    # bearing's models.high_speed under its own loads)
    case = _json(capsys, *PAIR, *SERVICE, *static)["cases"][0]
    for doc in case["bearings"]:
        assert doc["loaded_balls"] > 0
        single = _json(capsys, "7205B", "-F", f"{doc['load']!r}N", "-A",
                       f"{doc['axial_load']!r}N", "--moment", f"{doc['moment']!r}Nmm",
                       *static, *SERVICE)["cases"][0]  # fmt: skip
        for key in ("ball_loads_inner", "ball_loads_outer", "contact_angles_outer"):
            assert np.allclose(doc[key], single[key], rtol=1e-7, atol=1e-9), key
        assert doc["model"] == single["model"]
        mine = {k for k in LIFE_KEYS if doc.get(k) is not None}
        theirs = {k for k in LIFE_KEYS if single.get(k) is not None}
        assert mine == theirs and "modified_reference_rating_life_hours" in mine
        for key in sorted(mine):  # the JSON's 10 digits of the loads: equal to 1e-7
            assert doc[key] == pytest.approx(single[key], rel=1e-7), key


def test_each_bearing_service_values_follow_from_its_ball_loads(capsys):
    # each bearing through the library function its values are built from, fed with its own
    # equivalent load, lives and heaviest ball; and by hand: hours, a_ISO, L_nm, the film
    document = _json(capsys, *PAIR, *SERVICE)
    case, bearing = document["cases"][0], document["bearing"]
    row = {k: bearing["geometry"][k]["value"] for k in GEOMETRY}
    op = Operating(speed=3000.0, reliability=99.0, viscosity=20.0, roughness=2e-4)
    for doc in case["bearings"]:
        heaviest = int(np.argmax(doc["ball_loads"]))
        basis = LifeBasis(
            C=bearing["C"], C0=bearing["C0"], equivalent_load=doc["equivalent_load"],
            rating_life=doc["rating_life"], reference_rating_life=doc["reference_rating_life"],
            q_max=doc["ball_loads"][heaviest], contact_angle=doc["contact_angles"][heaviest],
            **row,
        )  # fmt: skip
        lib = service_values(op, basis).values
        for key, value in lib.items():
            assert doc[key] == pytest.approx(value, rel=1e-8), key
        hours = doc["rating_life"] * 1e6 / (60.0 * 3000.0)
        assert doc["rating_life_hours"] == pytest.approx(hours, rel=1e-9)
        nu1 = float(lub.rated_viscosity(3000.0, row["pitch_diameter"]))
        assert doc["kappa"] == pytest.approx(20.0 / nu1, rel=1e-9)
        x = doc["contamination_factor"] * (bearing["C0"] / 22.0) / doc["equivalent_load"]
        a_iso = float(ml.life_modification_factor(doc["kappa"], x, "ball"))
        assert doc["a_iso"] == pytest.approx(a_iso, rel=1e-8)
        l_nm = doc["reliability_factor"] * a_iso * doc["rating_life"]
        assert doc["modified_rating_life"] == pytest.approx(l_nm, rel=1e-8)
        assert doc["film_ratio"] == pytest.approx(doc["film_thickness"] / 2e-4, rel=1e-9)


def test_pair_hours_are_its_lives_at_the_speed(capsys):
    case = _json(capsys, *PAIR, "--speed", "1500")["cases"][0]
    assert case["speed"] == 1500.0
    for key in ("rating_life", "reference_rating_life"):
        assert case[f"{key}_hours"] == pytest.approx(case[key] * 1e6 / (60.0 * 1500), rel=1e-9)
        a, b = (doc[key] for doc in case["bearings"])
        assert case[key] == pytest.approx(_system(a, b), rel=1e-9)
    assert "modified_rating_life" not in case  # no viscosity, no modified life
    assert "ball dynamics" in case["model"] and "in both bearings" in case["model"]
    static = _json(capsys, *PAIR, "--speed", "1500", "--quasi-static")["cases"][0]
    assert static["model"].endswith(
        "the static model at the speed given (the ball dynamics left out)"
    )
    code, out, _ = run_entry(capsys, "solve", *PAIR, "--speed", "1500")
    assert code == 0 and "ball dynamics" in out and "basic rating life L10h" in out
    code, out, _ = run_entry(capsys, "solve", *PAIR, "--speed", "1500", "--quasi-static")
    assert code == 0 and "--quasi-static: the pair is solved by the static model" in out


def test_pair_modified_lives_combine_the_bearings_by_the_system_rule(capsys):
    case = _json(capsys, *PAIR, *SERVICE)["cases"][0]
    assert case["reliability"] == 99.0
    for key in ("modified_rating_life", "modified_reference_rating_life"):
        a, b = (doc[key] for doc in case["bearings"])
        assert case[key] == pytest.approx(_system(a, b), rel=1e-9)
        assert case[key] < min(a, b)
        hours = case[key] * 1e6 / (60.0 * 3000.0)
        assert case[f"{key}_hours"] == pytest.approx(hours, rel=1e-9)


def test_an_unloaded_bearing_drops_out_of_the_pair_lives(capsys):
    # --quasi-static: at 3000 rpm the centrifugal forces load the lifted bearing again
    case = _json(capsys, "7205BDB", "--preload", "100N", "-F", "0", "-A", "3kN",
                 *SERVICE, "--quasi-static")["cases"][0]  # fmt: skip
    loaded, lifted = case["bearings"]
    assert case["unloaded_bearings"] == "2" and lifted["loaded_balls"] == 0
    for key in ("rating_life", "reference_rating_life", "modified_rating_life",
                "modified_reference_rating_life"):  # fmt: skip
        assert lifted.get(key) is None and lifted.get(f"{key}_hours") is None
        assert case[key] == pytest.approx(loaded[key], rel=1e-12)
        assert case[f"{key}_hours"] == pytest.approx(loaded[f"{key}_hours"], rel=1e-12)
    assert lifted["kappa"] == loaded["kappa"] and lifted.get("film_thickness") is None


def test_csv_carries_the_pair_service_columns(capsys):
    doc = _json(capsys, *PAIR, *SERVICE)["cases"][0]
    code, out, _ = run_entry(capsys, "solve", *PAIR, *SERVICE, "--format", "csv")
    assert code == 0
    rows = list(csv.DictReader(io.StringIO(out)))
    assert len(rows) == 2
    for row, bearing in zip(rows, doc["bearings"], strict=True):
        for key, unit in (("rating_life_hours", "h"), ("modified_rating_life", "10^6 rev"),
                          ("modified_reference_rating_life_hours", "h")):  # fmt: skip
            assert math.isclose(float(row[f"pair_{key} [{unit}]"]), doc[key], rel_tol=1e-9)
            assert math.isclose(float(row[f"{key} [{unit}]"]), bearing[key], rel_tol=1e-9)


@pytest.mark.parametrize(
    ("args", "option"),
    [
        (["--ball-density", "7800"], "--ball-density"),  # without --speed
        (["--speed", "3000", "--quasi-static", "--ball-density", "7800"], "--ball-density"),
        (["--quasi-static"], "--quasi-static"),
        (["--speed", "3000", "--rotating", "outer"], "--rotating"),
        (["--viscosity", "20cSt"], "--viscosity"),  # nu_1 needs the speed
        (["--speed", "3000", "--contamination", "high"], "--contamination"),
    ],
)
def test_what_a_pair_still_refuses(capsys, args, option):
    code, out, err = run_entry(capsys, "solve", *PAIR, *args)
    lines = err.strip().splitlines()
    assert code == 2 and out == ""
    assert len(lines) == 1 and lines[0].startswith("Error:") and option in lines[0]
