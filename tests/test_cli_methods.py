"""``solve --method`` and ``table --method``: the methods of the registry side by side."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import mpmath as mp
import pytest

from bearingload.models.continuum import solve_continuum
from bearingload.models.equilibrium import solve
from bearingload.models.registry import list_methods
from bearingload.units import KGF

from .cli_helpers import committed, invoke
from .cli_helpers import run_entry as run_cli

ROOT = Path(__file__).resolve().parents[1]
# Bearing 306 of Kuzmenko (2010), §3: z = 8, F_r = 300 kgf, K = 4700 kgf/mm^1.5, G_r = 20 um.
CASE_306 = ["-z", "8", "-F", "300kgf", "-K", "4700kgf/mm^1.5", "-G", "20um"]


def rows_of(text: str) -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO(text)))


# --------------------------------------------------------------------------- solve --method


def test_default_method_is_exact():
    assert (
        invoke("solve", *CASE_306).output == invoke("solve", *CASE_306, "--method", "exact").output
    )
    assert "Ball loads" in invoke("solve", *CASE_306).output


def test_solve_all_side_by_side():
    text = invoke("solve", *CASE_306, "--method", "all").output
    assert text.startswith("z = 8, F_r = 2941.99 N (300 kgf), K = 46091.3")
    lines = text.splitlines()
    squeezed = {" ".join(x.split()) for x in lines}
    for line in (
        "quantity                                    exact  continuum  stribeck  palmgren  unit",
        "heaviest ball load Q_max                  1640.75    1655.01   1607.06   1838.75  N",
        "heaviest ball load Q_max                  167.310    168.764   163.875   187.500  kgf",
        "load factor k = Q_max/F_r                0.557699   0.562547  0.546250  0.625000  -",
        "load concentration K_Q = k z/2            2.23080    2.25019   2.18500   2.50000  -",
        "load zone half-angle                      85.1474    85.1730         -         -  °",
        "Q_max/Q_max,exact - 1                           0   0.869193  -2.05298   12.0675  %",
    ):
        assert " ".join(line.split()) in squeezed, line
    assert "continuum: continuum model, each ball's load smeared over its pitch (Kuzmenko 2010, §4-5); ignores cage angle." in lines  # fmt: skip
    assert "stribeck: Stribeck (1901): Q_max = 4.37 F_r/z; ignores stiffness, clearance, cage angle, exponent." in lines  # fmt: skip
    # Stribeck's constant is for zero clearance: the case is outside its range, and it says so
    assert any(x.startswith("Warning: stribeck: the case is outside") for x in lines)


def test_solve_all_json_relative_errors():
    doc = json.loads(invoke("solve", *CASE_306, "--method", "all", "--format", "json").output)
    by = {c["method"]: c for c in doc["cases"]}
    assert list(by) == list_methods()
    r = solve(8, 300 * KGF, 4700 * KGF, 0.02)
    exact = by["exact"]
    assert exact["q_max"] == pytest.approx(float(r.q_max), rel=1e-9)
    assert exact["relative_error"] == 0.0
    stribeck = by["stribeck"]
    assert stribeck["q_max"] == pytest.approx(4.37 * 300 * KGF / 8, rel=1e-9)
    assert stribeck["relative_error"] == pytest.approx(
        stribeck["q_max"] / exact["q_max"] - 1, abs=1e-9
    )
    assert stribeck["load_zone"] is None and "clearance" in stribeck["ignores"]
    assert stribeck["valid"] is False and by["palmgren"]["valid"] is True
    assert by["continuum"]["ignores"] == ["cage_angle"]
    assert doc["units"]["relative_error"] == "-" if "relative_error" in doc["units"] else True


def test_solve_continuum_same_keys_as_exact():
    exact = json.loads(invoke("solve", *CASE_306, "--format", "json").output)["cases"][0]
    cont = json.loads(
        invoke("solve", *CASE_306, "--method", "continuum", "--format", "json").output
    )["cases"][0]
    # one key per quantity in every model: the same set of keys, None where a model gives none
    assert set(exact) - {"ball_angles", "ball_approaches", "ball_loads", "stiffness_matrix"} == set(cont)  # fmt: skip
    shared = {"k", "q_max", "load_zone", "K_Q", "x", "stiffness_radial", "balls",
              "load", "stiffness", "clearance", "cage_angle", "exponent"}  # fmt: skip
    assert all(cont[k] is not None and exact[k] is not None for k in shared)
    r = solve_continuum(8, 300 * KGF, 4700 * KGF, 0.02)
    assert cont["k"] == pytest.approx(float(r.k), rel=1e-9)
    assert cont["K_Q"] == pytest.approx(float(r.K_Q), rel=1e-9)
    assert cont["load_zone"] == pytest.approx(float(r.load_zone), rel=1e-9)
    assert cont["x"] == pytest.approx(float(r.x), rel=1e-9)
    assert cont["approach_max"] == pytest.approx(float(r.approach_max), rel=1e-9)
    assert cont["epsilon"] == pytest.approx(float(r.epsilon), rel=1e-9)
    assert cont["method"] == "continuum"
    # the two models agree to 0.9 % on bearing 306 (and to 0.03 deg on the load zone)
    assert cont["q_max"] / exact["q_max"] - 1 == pytest.approx(0.00869, abs=5e-5)
    assert abs(cont["load_zone"] - exact["load_zone"]) < 0.03


def test_solve_continuum_table_lines():
    text = invoke("solve", *CASE_306, "--method", "continuum").output
    for line in (
        "load factor k = Q_max/F_r                0.562547  -",
        "heaviest ball load Q_max                  168.764  kgf",
        "load zone half-angle                      85.1730  °",
        "heaviest ball approach delta_max          108.840  µm",
        "load-zone parameter epsilon              0.457927  -",
    ):
        assert " ".join(line.split()) in {" ".join(x.split()) for x in text.splitlines()}, line
    assert "ignores cage angle." in text


@pytest.mark.parametrize(
    "method, constant, kgf", [("stribeck", 4.37, "163.875"), ("palmgren", 5.0, "187.500")]
)
def test_solve_one_line_estimates(method, constant, kgf):
    text = invoke("solve", *CASE_306, "--method", method).output
    assert f"heaviest ball load Q_max         {kgf}  kgf" in text.splitlines()  # 4.37 (5) x 300/8
    assert "ignores stiffness, clearance, cage angle, exponent." in text
    doc = json.loads(invoke("solve", *CASE_306, "--method", method, "--format", "json").output)
    case = doc["cases"][0]
    assert case["k"] == constant / 8 and case["load_zone"] is None
    assert {"k", "q_max", "K_Q", "load_zone"} <= set(case)


def test_solve_method_with_a_bearing_designation():
    text = invoke("solve", "306", "-F", "300kgf", "-G", "20um", "--method", "all").output
    assert text.startswith("Bearing 306, z = 8, F_r = 2941.99 N (300 kgf), K = 404566 N/mm^1.5")
    doc = json.loads(
        invoke("solve", "306", "-F", "300kgf", "-G", "20um", "--method", "continuum", "--format", "json").output
    )  # fmt: skip
    case = doc["cases"][0]
    assert case["balls"] == 8 and case["clearance"] == 0.02 and case["method"] == "continuum"
    assert doc["bearing"]["designation"] == "306"


@pytest.mark.parametrize(
    "args, message",
    [
        (["--method", "hertz"], "Error: Invalid value for '--method': 'hertz' is not one of 'exact', 'continuum', 'stribeck', 'palmgren', 'all'."),
        (["--method", "continuum", "-F", "-1"], "Error: Invalid value for '--load'"),
        (["--method", "stribeck", "-K", "-5"], "Error: Invalid value for '--stiffness'"),
        (["--method", "all", "-m", "0.5"], "Error: Invalid value for '--exponent'"),
    ],
)  # fmt: skip
def test_method_errors_are_one_line(capsys, args, message):
    code, out, err = run_cli(capsys, "solve", *CASE_306, *args)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith(message), err


def test_range_pick_with_every_method():
    """A clearance range by every model: one column (json: one case) per clearance and model."""
    doc = json.loads(invoke("solve", "306", "-F", "300kgf", "-G", "C3", "--clearance-pick", "range",
                            "--method", "all", "--format", "json").output)  # fmt: skip
    cases = doc["cases"]
    assert [(c["clearance_pick"], c["method"]) for c in cases] == [
        (p, m) for p in ("min", "mean", "max") for m in list_methods()
    ]
    for c in cases:
        ref = next(x for x in cases if x["method"] == "exact" and x["clearance"] == c["clearance"])
        assert c["relative_error"] == pytest.approx(c["q_max"] / ref["q_max"] - 1, abs=1e-9)


# --------------------------------------------------------------------------- table --method


def test_table_k_per_method():
    for method, constant in (("stribeck", 4.37), ("palmgren", 5.0)):
        rows = rows_of(invoke("table", "k", "--method", method, "--format", "csv").output)
        assert [int(r["balls"]) for r in rows] == list(range(1, 31))
        assert all(
            float(r["k"]) == pytest.approx(constant / int(r["balls"]), rel=1e-9) for r in rows
        )
    rows = rows_of(invoke("table", "kq", "--method", "continuum", "--format", "csv").output)
    with mp.workdps(30):
        kq = float(mp.pi / (2 * mp.quad(lambda p: mp.cos(p) ** 2.5, [0, mp.pi / 2])))
    assert all(float(r["K_Q"]) == pytest.approx(kq, rel=1e-9) for r in rows)  # 2.185048
    exact = invoke("table", "k", "--method", "exact").output
    assert exact == invoke("table", "k").output


def test_table_compare_z_1_to_30():
    text = invoke("table", "k", "--method", "all").output
    lines = text.splitlines()
    assert (
        lines[0]
        == "Load factor k = Q_max/F_r by every method (zero clearance, a ball under the load, m = 1.5)"
    )
    assert (
        " 8   3       0.5432           0.5463          0.5463          0.6250                   0.561                  0.559                   15.1"
        in lines
    )
    assert (
        "30  15       0.1457           0.1457          0.1457          0.1667                -0.00413               -0.00633                   14.4"
        in lines
    )
    rows = rows_of(invoke("table", "kq", "--method", "all", "--format", "csv").output)
    assert len(rows) == 30
    for r in rows:
        z = int(r["balls"])
        ref = solve(z, 1000.0, 1e5)
        assert float(r["K_Q_exact"]) == pytest.approx(float(ref.K_Q), rel=1e-9)
        assert int(r["loaded_balls"]) == int(ref.loaded_balls)
        assert float(r["error_palmgren [%]"]) == pytest.approx(
            100 * (5 / (z * float(ref.k)) - 1), rel=1e-8
        )


def test_table_compare_half_pitch_starts_at_three():
    rows = rows_of(
        invoke("table", "k", "--method", "all", "--cage-angle", "half", "--format", "csv").output
    )
    assert [int(r["balls"]) for r in rows] == list(range(3, 31))


def test_table_shows_discrete_approaching_continuum():
    """The comparison table for z up to 320: |continuum vs exact| falls at every doubling of z
    (zero clearance, a ball under the load), to 1.3e-6 % at z = 320; Stribeck's 4.37 settles at
    -0.0022 %, its rounding of pi/I_3/2 = 4.370096."""
    rows = rows_of(
        invoke("table", "k", "--method", "all", "--z-max", "320", "--format", "csv").output
    )
    by_z = {int(r["balls"]): r for r in rows}
    errors = [abs(float(by_z[z]["error_continuum [%]"])) for z in (5, 10, 20, 40, 80, 160, 320)]
    assert all(b < a for a, b in zip(errors, errors[1:], strict=False)), errors
    assert errors[0] == pytest.approx(3.319, abs=1e-3) and errors[-1] < 2e-6
    assert float(by_z[320]["error_stribeck [%]"]) == pytest.approx(
        100 * (4.37 / 4.370095923820 - 1), abs=2e-5
    )


def test_table_method_with_bearing_and_clearance():
    text = invoke("table", "k", "--method", "continuum", "--bearing", "306", "--load", "300kgf",
                  "--clearance", "20um", "--z-max", "8").output  # fmt: skip
    assert "Ball and raceways of bearing 306 (8 balls in the bearing itself)" in text
    rows = rows_of(invoke("table", "k", "--method", "continuum", "--clearance", "20um", "--load",
                          "300kgf", "--stiffness", "4700kgf/mm^1.5", "--format", "csv").output)  # fmt: skip
    r = solve_continuum(8, 300 * KGF, 4700 * KGF, 0.02)
    assert float(rows[7]["k"]) == pytest.approx(float(r.k), rel=1e-9)


def test_table_method_error(capsys):
    code, _, err = run_cli(capsys, "table", "k", "--method", "nope")
    assert code == 2 and err.count("\n") == 1
    assert err.startswith("Error: Invalid value for '--method': 'nope' is not one of")


def test_committed_method_comparison_matches_the_code():
    for name in ("k_methods_zero_clearance.csv", "k_methods_zero_clearance.md"):
        printed, on_disk = committed(name)
        assert printed == on_disk, name
