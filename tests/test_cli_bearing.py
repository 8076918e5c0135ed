"""The command line with bearing numbers: solve 306, table --bearing, catalog, their errors."""

from __future__ import annotations

import csv
import io
import json
import re

import pytest
from click.testing import CliRunner

from bearingload.bearings.resolve import resolve_bearing
from bearingload.cli import main, run
from bearingload.models.equilibrium import solve
from bearingload.units import KGF


def invoke(*args: str) -> str:
    out = CliRunner().invoke(main, list(args), catch_exceptions=False)
    assert out.exit_code == 0, out.output
    return out.output


def error_of(capsys, *args: str) -> str:
    """The one stderr line of a failing run, checked to exit with status 2."""
    with pytest.raises(SystemExit) as info:
        run(list(args))
    assert info.value.code == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err.count("\n") == 1 and captured.err.startswith("Error: ")
    return captured.err.strip()


def test_solve_306_with_clearance_class():
    text = invoke("solve", "306", "--load", "300kgf", "--clearance", "C3")
    lines = text.splitlines()
    squeezed = {" ".join(x.split()) for x in lines}
    assert lines[0] == (
        "Bearing 306, z = 8, F_r = 2941.99 N (300 kgf), K = 404566 N/mm^1.5, G_r = 20.5 µm "
        "(gap per side 10.25 µm), cage angle 0°, m = 1.5"
    )
    for line in (
        "heaviest ball load Q_max                  1783.27  N",
        "heaviest ball load Q_max                  181.843  kgf",
        "max contact pressure, inner               2252.76  MPa",
        "basic rating life L10 = (C/P)^p           394.370  10^6 rev",
        "life L of the allowable load              36.0000  10^6 rev",
        "allowable load C/L^(1/p)                  666.278  kgf",
        "G_r: class C3; ISO 5753-1 C3 13-28 µm at d = 30 mm, mean (clearance table).",
    ):
        assert " ".join(line.split()) in squeezed, line
    assert "balls z" not in text  # the geometry block only when asked for
    geometry = invoke("solve", "306", "--load", "300kgf", "--clearance", "C3", "--show-geometry")
    lines = geometry.splitlines()
    squeezed = {" ".join(x.split()) for x in lines}
    assert lines[0] == "Bearing 306 (GOST): geometry and stiffness used"
    for line in (
        "balls z                                   8            catalogue",
        "pitch diameter d_m                  51.0000  mm        (d + D)/2",
        "inner contact K_i               1.10744e+06  N/mm^1.5  Hertz, exact",
        "ball stiffness K (series)            404566  N/mm^1.5  Hertz, exact: (K_i^-2/3 + K_o^-2/3)^-3/2",
    ):
        assert " ".join(line.split()) in squeezed, line
    assert geometry.endswith(text)  # the same report after the geometry block
    b = resolve_bearing("306", clearance="C3")
    r = solve(8, 300 * KGF, b.stiffness, 0.0205)
    assert f"{float(r.q_max) / KGF:.6g}" == "181.843"


def test_solve_range_side_by_side():
    lines = invoke("solve", "306", "-F", "300kgf", "-G", "C3", "--clearance-pick", "range")
    cells = [re.split(r"\s{2,}", line.strip()) for line in lines.splitlines()]
    assert ["quantity", "G_r min", "G_r mean", "G_r max", "unit"] in cells
    assert ["radial clearance G_r", "13.0000", "20.5000", "28.0000", "µm"] in cells
    assert ["heaviest ball load Q_max", "174.961", "181.843", "188.687", "kgf"] in cells


def test_solve_json_of_a_bearing():
    doc = json.loads(invoke("solve", "306", "-F", "300kgf", "-G", "20um", "--format", "json"))
    b = resolve_bearing("306", clearance="20um")
    case = doc["cases"][0]
    assert case["stiffness"] == pytest.approx(b.stiffness, rel=1e-9)
    assert doc["bearing"]["stiffness_inner"] == pytest.approx(b.stiffness_inner, rel=1e-9)
    assert case["clearance"] == 0.02 and case["balls"] == 8 and case["bearing"] == "306"
    for key in ("p_max_inner", "p_max_outer", "rating_life", "allowable_load", "q_max"):
        assert case[key] > 0 and key in doc["units"]
    assert case["rating_life"] == pytest.approx((2200 / 300) ** 3, rel=1e-9)
    assert case["allowable_load"] == pytest.approx(2200 * KGF / 36 ** (1 / 3), rel=1e-9)
    assert doc["bearing"]["geometry"]["clearance"]["source"] == "given"
    ranged = json.loads(
        invoke("solve", "6306", "-F", "3kN", "-G", "C4", "--clearance-pick", "range", "--format", "json")
    )  # fmt: skip
    assert [c["clearance_pick"] for c in ranged["cases"]] == ["min", "mean", "max"]
    assert [c["clearance"] for c in ranged["cases"]] == pytest.approx([0.023, 0.032, 0.041])
    assert ranged["bearing"]["clearance_range"] == pytest.approx([0.023, 0.041])


def test_solve_overrides_and_paper_modulus():
    text = invoke(
        "solve", "306", "-F", "300kgf", "-G", "20um", "--modulus", "2.1e4kgf/mm^2",
        "--inner-conformity", "0.52", "--balls", "9", "--show-geometry",
    )  # fmt: skip
    squeezed = {" ".join(line.split()) for line in text.splitlines()}
    assert "Young's modulus E 205940 MPa given" in squeezed
    assert "inner conformity f_i = r_i/D_w 0.520000 given (override)" in squeezed
    assert "outer conformity f_o = r_o/D_w 0.515000 catalogue" in squeezed
    assert "balls z 9 given (override)" in squeezed


def test_solve_without_bearing_is_unchanged():
    plain = invoke(
        "solve", "-z", "8", "--load", "300kgf", "--stiffness", "4700kgf/mm^1.5", "-G", "20um"
    )
    assert plain.startswith("z = 8, F_r = 2941.99 N (300 kgf)")
    assert "Bearing" not in plain


def test_table_k_for_bearing_306():
    text = invoke("table", "k", "--bearing", "306", "--load", "300kgf", "--clearance", "20um")
    lines = text.splitlines()
    assert lines[0] == (
        "Bearing 306: Load factor k = Q_max/F_r (exact discrete model; clearance G_r = 20 µm, "
        "a ball under the load, m = 1.5, F_r = 2941.99 N, K = 404566 N/mm^m)"
    )
    rows = list(csv.DictReader(io.StringIO(invoke(
        "table", "kq", "-b", "306", "-F", "300kgf", "-G", "20um", "--format", "csv"
    ))))  # fmt: skip
    assert [int(r["balls"]) for r in rows] == list(range(1, 31))
    b = resolve_bearing("306")
    r = solve(8, 300 * KGF, b.stiffness, 0.02)
    assert float(rows[7]["K_Q"]) == pytest.approx(float(r.K_Q), rel=1e-9)


def test_catalog_list_and_filters():
    lines = invoke("catalog", "--bore", "30").splitlines()
    assert lines[0] == "Deep groove ball bearings in the catalogue (bore 30)"
    assert lines[2].split() == [
        "bearing", "std", "d", "[mm]", "D", "[mm]", "B", "[mm]", "z", "D_w", "[mm]", "d_m", "[mm]",
        "f_i", "[-]", "f_o", "[-]", "C", "[N]", "C0", "[N]", "ball", "set",
    ]  # fmt: skip
    assert (
        "306      GOST  30.000  72.000  19.000   8    12.300    51.000    0.515    0.515   21575   14808  GOST (read)"
        in lines
    )
    rows = list(
        csv.DictReader(
            io.StringIO(invoke("catalog", "--series", "63", "--standard", "iso", "--format", "csv"))
        )
    )
    assert rows and all(r["designation"].startswith("63") and r["standard"] == "ISO" for r in rows)
    doc = json.loads(invoke("catalog", "--bore", "30", "--format", "json"))
    assert [r["designation"] for r in doc["rows"]] == [
        "206", "306", "6006", "6206", "6306", "6406", "61806", "61906", "16006"
    ]  # fmt: skip
    assert invoke("catalog", "--bore", "30", "--format", "markdown").startswith("### Deep groove")


def test_catalog_show_with_sources():
    text = invoke("catalog", "show", "306")
    assert text.startswith("Bearing 306 (GOST)\n")
    assert "ball diameter D_w            12.3000    mm" in text
    assert "source: Kuzmenko 2010 Table 2" in text
    doc = json.loads(invoke("catalog", "show", "6306-2RS/C3", "--format", "json"))
    assert doc["designation"] == "6306" and doc["clearance_class"] == "C3"
    assert doc["balls"] == 8 and "NSK" in doc["source"]


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["solve", "9999", "-F", "1kN"], "Error: Invalid value for 'BEARING': cannot read '9999'"),
        (["solve", "6302", "-F", "1kN"], "Error: Invalid value for 'BEARING': '6302' is in the catalogue"),
        (["table", "k", "--bearing", "9999"], "Error: Invalid value for '--bearing': cannot read '9999'"),
        (["catalog", "show", "123456789"], "Error: Invalid value for 'DESIGNATION'"),
        (
            ["solve", "-z", "8", "-F", "1kN", "-K", "1e5", "-G", "C3"],
            "Error: Invalid value for '--clearance': a clearance class (C3) is resolved by the bore",
        ),
        (["table", "k", "-G", "CN"], "Error: Invalid value for '--clearance': a clearance class (CN)"),
        (
            ["solve", "306", "-F", "1kN", "--modulus", "208GPx"],
            "Error: Invalid value for '--modulus': unknown unit 'GPx' in '208GPx'; allowed: MPa, "
            "N/mm^2, GPa, kgf/mm^2, Pa (a bare number is MPa)",
        ),
        (["solve", "306", "-F", "1kN", "--poisson", "0.6"], "Invalid value for '--poisson'"),
        (["solve", "306", "-F", "1kN", "--outer-conformity", "0.4"], "Invalid value for '--outer-conformity'"),
        (["solve", "306", "-F", "1kN", "--ball-diameter", "30"], "Invalid value for '--ball-diameter'"),
        (["solve", "306", "-F", "1kN", "-G", "20um", "--clearance-pick", "range"], "'range' needs a clearance class"),
        (["solve", "306", "-F", "1kN", "-m", "1.1"], "Invalid value for '--exponent'"),
        (["solve", "306", "-F", "1kN", "--revolutions", "0"], "Invalid value for '--revolutions'"),
        (["solve", "-F", "1kN", "-K", "1e5"], "Missing option '--balls'"),
        (["solve", "-z", "8", "-F", "1kN"], "Missing option '--stiffness'"),
        (["catalog", "--standard", "DIN"], "Invalid value for '--standard': unknown standard 'DIN'"),
        (["table", "k", "--modulus", "200GPa"], "--modulus needs a '--bearing'"),
    ],
)  # fmt: skip
def test_errors_are_one_line_exit_2(capsys, args, message):
    assert message in error_of(capsys, *args)
