"""``bearingload solve`` with a combined load: options, JSON keys and units, errors."""

from __future__ import annotations

import json
import math

import pytest

from bearingload.bearings.iso16281 import contact_ratings, reference_rating_life
from bearingload.models.combined import solve_combined

from .cli_helpers import invoke, run_process
from .fixtures.published import PEER_ISO16281_MASTA

PEER_ARGS = ("-z", "7", "--ball-diameter", "11.5", "--pitch-diameter", "43.5",
             "--modulus", "210000", "--dynamic-rating", "23.4kN")  # fmt: skip


def _document(*args: str) -> dict:
    result = invoke("solve", *args, "--format", "json")
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)  # warnings go to stderr


def _json(*args: str) -> dict:
    """The one case of the JSON document, with the document's units."""
    doc = _document(*args)
    assert len(doc["cases"]) == 1
    return doc["cases"][0] | {"units": doc["units"]}


def test_json_keys_match_the_library():
    doc = _json(*PEER_ARGS, "-F", "1kN", "--axial-load", "1kN", "-G", "10um")
    r = solve_combined(7, 1000.0, 1000.0, ball_diameter=11.5, pitch_diameter=43.5,
                       clearance=0.01, modulus=210000.0)  # fmt: skip
    assert doc["axial"] == pytest.approx(float(r.axial), rel=1e-9)
    assert doc["tilt"] == pytest.approx(float(r.tilt), rel=1e-9)
    assert doc["contact_angles"] == pytest.approx(list(r.contact_angles), rel=1e-9)
    q_ci, q_ce = contact_ratings(23400.0, 7, 11.5, 43.5, 0.52, 0.53)
    life = float(reference_rating_life(r.ball_loads, q_ci, q_ce))
    assert doc["reference_rating_life"] == pytest.approx(life, rel=1e-9)
    assert doc["units"]["axial"] == "mm" and doc["units"]["tilt"] == "°"
    assert doc["units"]["contact_angles"] == "°"
    assert doc["units"]["reference_rating_life"] == doc["units"]["rating_life"] == "10^6 rev"
    # Example 5 of the peer (MASTA): L10r 1630.5367, ours with the Hertz K(alpha) -0.0033 %
    assert doc["reference_rating_life"] == pytest.approx(PEER_ISO16281_MASTA[5][7], rel=1e-4)
    assert doc["rating_life"] is None  # ISO 281 P needs C0r and f0: not given for this ball set


def test_catalogue_bearing_gets_both_lives():
    doc = _json("6205", "-F", "1.4kN", "-A", "700N", "-G", "0")
    # ISO 281:2007 Table 3 at f0 F_a/C0r = 13.9 * 700/7850 = 1.2395: Y = 1.4930
    y = 1.55 + (13.9 * 700 / 7850 - 1.03) / (1.38 - 1.03) * (1.45 - 1.55)
    assert doc["equivalent_load"] == pytest.approx(0.56 * 1400 + y * 700, rel=1e-9)
    assert doc["rating_life"] == pytest.approx((14000 / doc["equivalent_load"]) ** 3)
    assert doc["reference_rating_life"] > 0 and len(doc["contact_angles"]) == 9


def test_misalignment_and_moment_units():
    a = _json(*PEER_ARGS, "-F", "1kN", "--misalignment", "2mrad", "-G", "10um")
    assert a["tilt"] == pytest.approx(math.degrees(2e-3), rel=1e-9)
    assert a["misalignment"] == pytest.approx(math.degrees(2e-3), rel=1e-9)
    b = _json(*PEER_ARGS, "-F", "1kN", "--moment", "1Nm", "-G", "10um")
    c = _json(*PEER_ARGS, "-F", "1kN", "--moment", "1000", "-G", "10um")
    assert b["tilt"] == c["tilt"] != 0


def test_outer_ring_rotating_changes_the_life():
    inner = _json(*PEER_ARGS, "-F", "1kN", "-A", "200N", "-G", "10um")
    outer = _json(*PEER_ARGS, "-F", "1kN", "-A", "200N", "-G", "10um", "--rotating", "outer")
    assert inner["ball_loads"] == outer["ball_loads"]
    assert inner["reference_rating_life"] != outer["reference_rating_life"]


def test_table_output_names_the_conventions():
    out = invoke("solve", *PEER_ARGS, "-F", "0", "-A", "1kN").output
    assert "axial displacement from centred rings" in out
    assert "half the axial play included" in out
    assert "contact angle [°]" in out


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("-z", "7", "-K", "3e5", "-F", "1kN", "-A", "1kN"), "ball geometry"),
        ((*PEER_ARGS, "-F", "1kN", "--moment", "1Nm", "--misalignment", "0.1"), "'--moment'"),
        ((*PEER_ARGS, "-F", "0"), "'--load'"),
        ((*PEER_ARGS, "-F", "1kN", "-A", "1kN", "--method", "all"), "'--method'"),
        ((*PEER_ARGS, "-F", "1kN", "--misalignment", "2 parsecs"), "'--misalignment'"),
    ],
)
def test_errors_are_one_line(args, message):
    p = run_process("solve", *args)
    assert p.returncode == 2, p.stderr
    lines = [line for line in p.stderr.splitlines() if line.startswith("Error:")]
    assert len(lines) == 1 and message in lines[0], p.stderr
    assert "Traceback" not in p.stderr and p.stdout == ""


def test_help_lists_the_combined_options():
    out = invoke("solve", "--help").output
    for option in ("--axial-load", "--moment", "--misalignment", "--dynamic-rating", "--rotating"):
        assert option in out


def test_clearance_range_side_by_side():
    doc = _document("6205", "-F", "1.4kN", "-A", "700N", "-G", "C3", "--clearance-pick", "range")
    picks = [c["clearance_pick"] for c in doc["cases"]]
    assert picks == ["min", "mean", "max"]
    lives = [c["reference_rating_life"] for c in doc["cases"]]
    assert lives == sorted(lives)  # more clearance, larger contact angles, longer life here


def test_the_normal_clearance_caveat_of_iso281_only_where_p_and_l10_are_given():
    """With C3 and an axial load ISO 281's P and L10 use the factors for normal clearance, which
    a warning says; bearing 306 (GOST ball set, no f0) has no P and no L10 under an axial load,
    so nothing to warn about."""
    caveat = "factors of Table 3 for normal clearance"
    doc = _document("6205", "-F", "1kN", "--axial-load", "300N", "-G", "C3")
    assert doc["cases"][0]["rating_life"] > 0
    assert any(caveat in w for w in doc["warnings"])
    doc = _document("306", "-F", "1kN", "--axial-load", "300N", "-G", "C4")
    assert doc["cases"][0]["rating_life"] is None
    assert doc["cases"][0]["equivalent_load"] is None
    assert not any(caveat in w for w in doc["warnings"])


@pytest.mark.parametrize(("clearance", "finding"), [("250um", "above the largest class"),
                                                    ("-80um", "deeper than")])  # fmt: skip
def test_clearance_beyond_the_iso_classes_is_flagged_under_a_combined_load(clearance, finding):
    """A clearance the radial path flags (beyond C5 of ISO 5753-1 for the bore, or a preload
    deeper than the package's bound) is flagged as well with an axial load, solve and batch."""
    radial = _document("6205", "-F", "1kN", "-G", clearance)
    combined = _document("6205", "-F", "1kN", "--axial-load", "100N", "-G", clearance)
    assert any(finding in w for w in radial["warnings"])
    assert [w for w in combined["warnings"] if finding in w] == [
        w for w in radial["warnings"] if finding in w
    ]
    from click.testing import CliRunner

    from bearingload.cli import main

    text = f"bearing,load,axial_load,clearance\n6205,1kN,100N,{clearance}\n"
    row = CliRunner().invoke(main, ["batch", "-", "--format", "json"], input=text)
    assert any(finding in w for w in json.loads(row.stdout)["cases"][0]["warnings"])


def test_a_tilt_lever_far_from_the_pitch_radius_is_warned_of():
    """``--tilt-radius 1e9`` (a unit slip) was used without a word; a lever outside 0.5-2 times
    d_m/2 now warns, naming the lever and the pitch radius; one near d_m/2 does not."""
    far = invoke("solve", "6205", "-F", "1.4kN", "-A", "700N", "--tilt-radius", "1e9")
    assert far.exit_code == 0
    assert "Warning: tilt lever 1e+09 mm is 5.19e+07 times the pitch radius" in far.output
    near = invoke("solve", "6205", "-F", "1.4kN", "-A", "700N", "--tilt-radius", "20mm")
    assert near.exit_code == 0 and "Warning: tilt lever" not in near.output


def test_a_misalignment_just_beyond_the_limit_is_shown_with_its_digits():
    """``--misalignment 2.0000001`` was refused with "got 2°", the limit itself."""
    out = invoke("solve", "6205", "-F", "1.4kN", "-A", "700N", "--misalignment", "2.0000001")
    assert out.exit_code != 0 and "(got 2.0000001°)" in out.output


def test_the_default_tilt_lever_is_reported_as_a_number():
    """With the default lever (``groove``) the output named no lever at all; now the radius of
    the inner groove centres R_i = d_m/2 + (f_i - 1/2) D_w cos(alpha_0) is in the title and in
    the JSON as ``tilt_radius`` [mm], as a given lever is."""
    out = json.loads(
        invoke("solve", "6205", "-F", "1.4kN", "-A", "700N", "--format", "json").stdout
    )
    case = out["cases"][0] if "cases" in out else out
    lever = case["tilt_radius"]
    r = solve_combined(9, 1400.0, 700.0, ball_diameter=7.938, pitch_diameter=38.5,
                       clearance=0.0125)  # fmt: skip
    assert lever == pytest.approx(r.tilt_radius, rel=1e-6)
    assert 19.25 < lever < 19.25 + 0.02 * 7.938
    assert "tilt lever 19.4" in invoke("solve", "6205", "-F", "1.4kN", "-A", "700N").output


@pytest.mark.parametrize(
    ("args", "where"),
    [
        (["6205", "-F", "1kN", "-A", "300N"], "the combined engine"),
        (["7205B", "-F", "1kN"], "the combined engine"),
        (["-z", "9", "-F", "1000", "-K", "1e5"], "a ring given by its balls and stiffness"),
        (["-z", "9", "--ball-diameter", "7.938", "--pitch-diameter", "38.5", "-F", "1kN"],
         "a bearing without a dynamic load rating C"),
    ],
)  # fmt: skip
def test_revolutions_where_no_allowable_load_is_printed_is_refused(args, where, capsys):
    """--revolutions sets L of the radial engine's allowable load C/(L/10^6)^(1/3); with an
    axial load (the combined engine) or a ring without C (by its stiffness, or by its ball
    geometry without --dynamic-rating) it was silently ignored."""
    from .cli_helpers import run_entry

    code, out, err = run_entry(capsys, "solve", *args, "--revolutions", "1e8")
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1, lines
    assert lines[0].startswith(f"Error: --revolutions cannot be used with {where}")
    assert "C/(L/10^6)^(1/3)" in lines[0]
    # the default (not given) is no refusal; the radial engine of a bearing uses it
    assert run_entry(capsys, "solve", *args)[0] == 0
    code, out, _ = run_entry(capsys, "solve", "6205", "-F", "1kN", "--revolutions", "1e8")
    assert code == 0 and "100.000  10^6 rev" in out


def test_stiffness_matrix_is_the_5x5_of_every_engine():
    """json's ``stiffness_matrix`` has one layout and meaning, d(F_x, F_y, F_a, M, M_c)/d(x,
    y, axial, tilt, tilt_cross): the radial engine gives its x, y block and null for what it
    does not determine (it holds the ring axially, untilted); the 3-D solve of the same case
    (-A 0) gives every entry, its x, y block the radial one."""
    import json

    from .cli_helpers import invoke

    docs = [
        json.loads(invoke("solve", "6205", "-F", "1kN", *extra, "--format", "json").output)
        for extra in ((), ("-A", "0"))
    ]
    radial, full = (d["cases"][0]["stiffness_matrix"] for d in docs)
    assert len(radial) == len(full) == 5 and all(len(r) == 5 for r in radial + full)
    assert [[v is None for v in r] for r in radial] == [
        [i > 1 or j > 1 for j in range(5)] for i in range(5)
    ]
    for i in range(2):
        for j in range(2):
            assert radial[i][j] == pytest.approx(full[i][j], rel=1e-9, abs=1e-6)
    assert docs[0]["units"]["stiffness_matrix"] == docs[1]["units"]["stiffness_matrix"]


def test_a_failure_names_the_inputs_as_typed(monkeypatch, capsys):
    """A ConvergenceError names its case's inputs by the options the user typed and the cage
    angle as given (the solver reduces -10° to 350°); the library's plan by its argument names
    (load, not the solver's radial_load)."""
    import bearingload.models.combined as combined
    from bearingload import analyse
    from bearingload.errors import ConvergenceError

    from .cli_helpers import run_entry

    monkeypatch.setattr(combined, "ACCEPT", -1.0)  # no residual is accepted: every case fails
    code, out, err = run_entry(
        capsys, "solve", "6205", "-F", "1kN", "-A", "100N", "--cage-angle", "-10"
    )
    assert code == 1 and out == ""
    # the inputs typed only: not the catalogue's 9 balls, not a moment of 0 nobody gave
    assert "for the case --load = 1 kN, --axial-load = 100 N, --cage-angle = -10 °" in err
    assert "--cage-angle = -10 °" in err and "350" not in err and "radial_load" not in err
    with pytest.raises(ConvergenceError) as info:
        analyse("6205", load=1000, axial_load=100, cage_angle=-10)
    assert set(info.value.cases) >= {"load", "axial_load", "cage_angle"}
    assert "radial_load" not in info.value.cases and info.value.cases["cage_angle"] == -10


def test_a_failure_writes_each_input_as_typed(monkeypatch, capsys):
    """A ConvergenceError writes an input given with a unit as the user typed it (0.1kN: 0.1 kN, not
    100 N), on the command line and in the library (whose cases keep the numbers in N); a bare
    number keeps the default unit."""
    import bearingload.models.combined as combined
    from bearingload import analyse
    from bearingload.errors import ConvergenceError

    from .cli_helpers import run_entry

    monkeypatch.setattr(combined, "ACCEPT", -1.0)  # no residual is accepted: every case fails
    code, _, err = run_entry(
        capsys, "solve", "6205", "-F", "0.1kN", "-A", "30", "-G", "20um", "--cage-angle", "0.1rad"
    )
    assert code == 1
    assert (
        "--load = 0.1 kN, --axial-load = 30 N, --clearance = 20 um, --cage-angle = 0.1 rad" in err
    )
    assert "100 N" not in err
    with pytest.raises(ConvergenceError) as info:
        analyse("6205", load="0.1 kN", axial_load=30)
    assert "load = 0.1 kN, axial_load = 30 N" in str(info.value)
    assert info.value.cases["load"] == 100.0 and info.value.units["load"] == "N"


def test_a_radial_case_solved_in_3d_keeps_the_load_zone_row(capsys):
    """solve -A 0 (the 3-D engine) prints the load zone half-angle the same case prints
    without -A: one report per bearing."""
    from .cli_helpers import run_entry

    rows = []
    for extra in ((), ("-A", "0")):
        code, out, _ = run_entry(capsys, "solve", "6205", "-F", "1kN", *extra)
        assert code == 0
        rows.append(next(line for line in out.splitlines() if "load zone half-angle" in line))
    assert rows[0].split()[-2:] == rows[1].split()[-2:] == ["73.4720", "°"]


@pytest.mark.parametrize("clearance", [0.0125, 0.05, 0.0, -0.005])
def test_the_3d_load_zone_is_the_radial_engines_under_a_radial_load(clearance):
    """Under a radial load alone the 3-D kinematics close the clearance where x cos(phi) >
    G_r/2: the zone is arccos(G_r/(2x)) (Harris & Kotzalas's load zone), 90° at zero clearance,
    beyond 90° under a preload, as the radial engine gives it."""
    import math

    from bearingload import solve
    from bearingload.models.combined import load_zone

    dw, f = 7.938, (0.52, 0.53)
    r = solve_combined(
        9,
        1000.0,
        0.0,
        ball_diameter=dw,
        pitch_diameter=38.5,
        f_i=f[0],
        f_o=f[1],
        clearance=clearance,
    )
    zone = load_zone(r, (sum(f) - 1.0) * dw)
    radial = solve(9, 1000.0, float(r.ball_stiffnesses[0]), clearance=clearance)
    assert zone == pytest.approx(float(radial.load_zone), rel=1e-12)
    if clearance >= 0:
        assert zone == pytest.approx(math.degrees(math.acos(clearance / 2 / r.x)), rel=1e-12)
    thrust = solve_combined(
        9, 1000.0, 100.0, ball_diameter=dw, pitch_diameter=38.5, clearance=clearance
    )
    assert zone < load_zone(thrust, (sum(f) - 1.0) * dw) <= 180.0  # a thrust widens it
