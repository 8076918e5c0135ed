"""Cylindrical roller bearings NU/N 2xx, 3xx: rows re-derived, line contact, resolve and solve."""

from __future__ import annotations

import math

import mpmath
import pytest
from click.testing import CliRunner

from bearingload.bearings.designation import parse
from bearingload.bearings.resolve import resolve_bearing
from bearingload.bearings.rollers import (
    LENGTH_RATIO,
    RollerGeometry,
    entries,
    line_contact_pressure,
    lookup,
    roller_count,
    total_length,
)
from bearingload.cli import main
from bearingload.contact.hertz import roller_stiffness
from bearingload.errors import InputError
from bearingload.models.equilibrium import solve

ROWS = entries()


def _id(r: RollerGeometry) -> str:
    return r.designation


def test_rows() -> None:
    names = [r.designation for r in ROWS]
    assert names == [f"NU2{i:02d}" for i in range(3, 21)] + [f"NU3{i:02d}" for i in range(3, 21)]
    assert sum(r.method == "read z" for r in ROWS) == 3


@pytest.mark.parametrize("row", ROWS, ids=_id)
def test_row_rederived(row: RollerGeometry) -> None:
    assert row.source.strip() and "SKF" in row.source and row.notes.strip()
    assert row.method in ("read z", "derived z")
    assert ("z derived" if row.method == "derived z" else f"z {row.rollers} read") in row.notes
    # D_w and d_m exact from the raceway diameters F (NU) and E (N)
    assert row.roller_diameter == pytest.approx((row.E - row.F) / 2, abs=1e-12)
    assert row.pitch_diameter == pytest.approx((row.E + row.F) / 2, abs=1e-12)
    assert parse(row.designation).bore == row.d
    # L_we from C0 by ISO 76: C0r = 44 (1 - D_w/d_m) z L_we D_w
    zl = total_length(row.C0, row.roller_diameter, row.pitch_diameter)
    assert row.rollers * row.roller_length == pytest.approx(zl, rel=1e-4)
    best, admitted = roller_count(row.C0, row.roller_diameter, row.pitch_diameter)
    assert row.rollers in admitted
    if row.method == "derived z":
        assert row.rollers == best
    assert row.rollers * row.roller_diameter < math.pi * row.pitch_diameter


def test_published_roller_counts() -> None:
    # N204 (Seoul dataset): 11; NU205E, FAG NU2205-E: 13; NU206E (Kaeser field table): 13
    assert [lookup(n).rollers for n in ("N204", "NU205", "NU206E")] == [11, 13, 13]
    # their L_we/D_w calibrate the rule for the derived counts
    ratios = [
        lookup(n).roller_length / lookup(n).roller_diameter for n in ("NU204", "NU205", "NU206")
    ]
    assert sum(ratios) / 3 == pytest.approx(LENGTH_RATIO, abs=1e-3)  # rounded to 1.017


def test_types_share_the_row() -> None:
    rows = {lookup(n).designation for n in ("NU206", "N206", "NJ 206 ECP", "NUP206/C3")}
    assert rows == {"NU206"}
    with pytest.raises(InputError, match="not in the catalogue"):
        lookup("NU230")
    with pytest.raises(InputError, match="not a cylindrical roller"):
        lookup("6206")
    with pytest.raises(InputError) as info:
        lookup("NU206", rollers=40)
    assert info.value.parameter == "rollers"  # the library's name; the CLI's --balls


def _p_ref(q: float, le: float, dw: float, dm: float, e: float, nu: float) -> tuple[float, float]:
    mpmath.mp.dps = 40
    q, le, dw, dm, e, nu = (mpmath.mpf(x) for x in (q, le, dw, dm, e, nu))
    e_star = 1 / (2 * (1 - nu**2) / e)  # Johnson 1985 eq. 3.37 for two equal bodies
    r_i = 1 / (1 / (dw / 2) + 1 / ((dm - dw) / 2))  # roller on the convex inner race
    r_o = 1 / (1 / (dw / 2) - 1 / ((dm + dw) / 2))  # roller in the concave outer race
    return tuple(float(mpmath.sqrt(q / le * e_star / (mpmath.pi * r))) for r in (r_i, r_o))


@pytest.mark.parametrize("q", [0.0, 1.0, 5000.0, 3e5])
def test_line_contact_pressure_against_mpmath(q: float) -> None:
    got = line_contact_pressure(q, 8.792, 9.0, 46.5, 208000.0, 0.3)
    ref = _p_ref(q, 8.792, 9.0, 46.5, 208000.0, 0.3)
    assert [float(x) for x in got] == pytest.approx(ref, rel=1e-13, abs=1e-9)


def test_line_contact_pressure_takes_the_package_spelling() -> None:
    by_name = line_contact_pressure(
        5000.0, 8.792, roller_diameter=9.0, pitch_diameter=46.5, modulus=2.1e5, poisson=0.28
    )
    ref = _p_ref(5000.0, 8.792, 9.0, 46.5, 2.1e5, 0.28)
    assert [float(x) for x in by_name] == pytest.approx(ref, rel=1e-13)
    assert all(type(x) is float for x in by_name)


@pytest.mark.parametrize(
    ("kwargs", "parameter"),
    [
        ({"modulus": 0.0}, "modulus"),
        ({"modulus": float("inf")}, "modulus"),
        ({"poisson": 0.6}, "poisson"),
        ({"poisson": -1.0}, "poisson"),
        ({"poisson": float("nan")}, "poisson"),
    ],
)
def test_line_contact_pressure_names_a_bad_material(
    kwargs: dict[str, float], parameter: str
) -> None:
    with pytest.raises(InputError) as info:
        line_contact_pressure(5000.0, 8.792, 9.0, 46.5, **kwargs)
    assert info.value.parameter == parameter


def test_resolve_and_solve_nu206() -> None:
    b = resolve_bearing("NU206")
    assert (b.kind, b.exponent, b.balls, b.ball_diameter) == ("roller", 10 / 9, 13, 9.0)
    assert b.stiffness == pytest.approx(float(roller_stiffness(b.roller_length)), rel=1e-15)
    assert (b.C, b.C0) == (44000.0, 36500.0)
    sources = {p.key: p.source for p in b.provenance}
    assert "read" in sources["balls"] and "derived" in sources["roller_length"]
    assert (
        "derived, flagged"
        in {p.key: p.source for p in resolve_bearing("NU210").provenance}["balls"]
    )
    r = solve(b.balls, 5000.0, b.stiffness, b.clearance, 0.0, b.exponent)
    assert float(r.q_max) == pytest.approx(float(r.q_max))  # finite
    assert 0 < float(r.q_max) < 5000.0
    assert resolve_bearing("NU206", clearance="20um").clearance == pytest.approx(0.02)


@pytest.mark.parametrize(
    ("kwargs", "parameter"),
    [
        ({"maker": "NSK"}, "maker"),
        ({"clearance": "5mm"}, "clearance"),
    ],
)
def test_roller_errors(kwargs: dict[str, str], parameter: str) -> None:
    with pytest.raises(InputError) as info:
        resolve_bearing("NU206", **kwargs)  # type: ignore[arg-type]
    assert info.value.parameter == parameter


#: ISO 5753-1 radial internal clearance of cylindrical roller bearings with a cylindrical bore,
#: µm, (bore over, incl): C2, CN, C3, C4, C5 (min, max), as printed by original-bearing.com
#: ("Radial internal clearance of cylindrical roller bearings with a cylindrical bore"); C2-C4
#: the same at ahrinternational.com/bearing_clearance.htm. Rows covering the catalogue's bores.
ROLLER_CLEARANCE_PRINTED = {
    (0, 24): ((0, 25), (20, 45), (35, 60), (50, 75), (65, 90)),
    (24, 30): ((0, 25), (20, 45), (35, 60), (50, 75), (70, 95)),
    (30, 40): ((5, 30), (25, 50), (45, 70), (60, 85), (80, 105)),
    (50, 65): ((10, 40), (40, 70), (60, 90), (80, 110), (110, 140)),
    (80, 100): ((15, 50), (50, 85), (75, 110), (105, 140), (155, 190)),
}


@pytest.mark.parametrize("row", sorted(ROLLER_CLEARANCE_PRINTED))
def test_roller_clearance_table_is_the_printed_one(row: tuple[int, int]) -> None:
    from bearingload.bearings.clearance import CLASSES, clearance_range

    bore = row[1]  # 'over / incl': the upper bore belongs to the row
    for cls, (low, high) in zip(CLASSES, ROLLER_CLEARANCE_PRINTED[row], strict=True):
        got = clearance_range(bore, cls, kind="roller")
        assert got == pytest.approx((low / 1e3, high / 1e3), abs=1e-12), (row, cls)


def test_roller_default_clearance_is_cn_of_the_roller_table() -> None:
    """NU206 (d = 30 mm) used G_r = 0 although the help said 'the class the designation marks,
    else CN': CN of cylindrical roller bearings at 24-30 mm is 20-45 µm."""
    b = resolve_bearing("NU206")
    assert (b.clearance_class, b.clearance_pick) == ("CN", "mean")
    assert b.clearance == pytest.approx(0.0325, abs=1e-15)
    assert b.clearance_range == pytest.approx((0.020, 0.045), abs=1e-15)
    c3 = resolve_bearing("NU206", clearance="C3", clearance_pick="max")
    assert (c3.clearance_class, c3.clearance) == ("C3", pytest.approx(0.060, abs=1e-15))
    marked = resolve_bearing("NU210 C4")  # d = 50: C4 70-100 µm
    assert marked.clearance_class == "C4" and marked.clearance == pytest.approx(0.085, abs=1e-15)
    source = {p.key: p.source for p in b.provenance}["clearance"]
    assert "cylindrical roller" in source and "CN 20-45 µm at d = 30 mm" in source


@pytest.mark.parametrize("fmt", ["table", "markdown"])
def test_roller_outputs_say_roller_in_human_formats(fmt: str) -> None:
    """solve and sweep of a roller bearing used to print 'heaviest ball load', 'balls carrying
    load', 'Ball loads', 'ball' (the element carrying Q_max) for the rollers."""
    import re

    from .cli_helpers import invoke

    out = invoke("solve", "NU206", "-F", "5kN", "--format", fmt).output
    for label in ("heaviest roller load Q_max", "rollers carrying load", "Roller loads (roller 1"):
        assert label in out
    sweep = invoke("sweep", "NU206", "-F", "5kN", "--steps", "3", "--format", fmt).output
    assert "Over one roller pitch" in sweep and "roller: the roller carrying Q_max" in sweep
    for text in (out, sweep):
        # 'ball' only where a note speaks of ball bearings or of a model's own description
        lines = [ln for ln in text.splitlines() if re.search(r"\b[Bb]alls?\b", ln)]
        assert all("ball bearings" in ln or "discrete balls" in ln or "each ball's" in ln
                   for ln in lines), lines  # fmt: skip
    ball = invoke("solve", "306", "-F", "300kgf", "--format", fmt).output
    assert "heaviest ball load Q_max" in ball and "roller" not in ball


def test_roller_machine_keys_stay_the_same() -> None:
    import json

    from .cli_helpers import invoke

    doc = json.loads(invoke("solve", "NU206", "-F", "5kN", "--format", "json").output)
    assert {"q_max", "loaded_balls", "ball_loads"} <= set(doc["cases"][0])
    csv_head = invoke("sweep", "NU206", "-F", "5kN", "--steps", "3", "--format", "csv").output
    assert "q_max_ball" in csv_head.splitlines()[0] and "roller" not in csv_head


def _run(*args: str, stdin: str | None = None):
    return CliRunner().invoke(main, list(args), input=stdin)


def _batch(text: str, *args: str):
    from .cli_helpers import SolvedRows

    return SolvedRows(_run("batch", "-", "--format", "csv", *args, stdin=text))


def test_a_roller_bearings_stiffness_is_read_in_its_own_unit():
    """-K of a cylindrical roller bearing is N/mm^(10/9) (its m) unless --exponent says
    otherwise: its unit is accepted, and N/mm^1.5 is refused instead of taken as N/mm^(10/9);
    batch reads a roller row's stiffness the same way."""
    from click.testing import CliRunner

    from bearingload.cli import main

    def run(*args):
        return CliRunner().invoke(main, list(args))

    given = run("solve", "NU206", "-F", "5kN", "-K", "3e5N/mm^(10/9)", "--format", "csv")
    bare = run("solve", "NU206", "-F", "5kN", "-K", "3e5", "--format", "csv")
    assert given.exit_code == 0 and given.stdout == bare.stdout
    wrong = run("solve", "NU206", "-F", "5kN", "-K", "3e5N/mm^1.5")
    assert wrong.exit_code == 2 and "exponent is 1.11111" in wrong.stderr
    ball = run("solve", "306", "-F", "5kN", "-K", "3e5N/mm^1.5", "--format", "csv")
    assert ball.exit_code == 0
    text = "bearing,load,stiffness\nNU206,5kN,3e5N/mm^(10/9)\n306,5kN,3e5N/mm^1.5\n"
    out = CliRunner().invoke(main, ["batch", "-", "--format", "csv"], input=text)
    assert out.exit_code == 0, out.stderr
    rows = out.stdout.splitlines()[1:]
    assert rows[0].split(",")[5] == "300000.0" and rows[1].split(",")[5] == "300000.0"


def test_an_explicit_exponent_of_1_5_is_refused_for_a_roller_bearing():
    """--exponent 1.5 (the option's default written out) with a roller bearing read -K in
    N/mm^1.5 and then solved the rollers with m = 10/9, taking 3e5 N/mm^1.5 as 3e5 N/mm^(10/9):
    the explicit exponent was ignored. solve, sweep and a batch row's exponent cell now refuse it
    as they refuse --exponent 10/9 for a ball bearing."""
    for command in ("solve", "sweep"):
        r = _run(command, "NU204", "-F", "5kN", "-K", "3e5N/mm^1.5", "--exponent", "1.5")
        assert r.exit_code == 2, r.output
        assert "Error: Invalid value for '--exponent': a roller bearing" in r.output
    assert _run("solve", "306", "-F", "5kN", "--exponent", "1.5").exit_code == 0
    r = _batch("bearing,load,exponent\nNU204,5kN,1.5\n306,5kN,1.5\nNU204,5kN,\n")
    assert r.exit_code == 1, r.output
    assert r.stderr.startswith("Skipped: row 2: exponent: a roller bearing (line contact)")
    assert [line.split(",")[0] for line in r.stdout.splitlines()[1:]] == ["3", "4"]
