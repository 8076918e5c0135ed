"""``--speed`` on a plain radial solve: a ball bearing is solved with the ball dynamics (the
combined engine at F_a = 0, exactly as ``--axial-load 0``) unless ``--quasi-static``, which gives
the static radial engine; a roller bearing stays radial; batch follows solve row by row;
sweep --quasi-static and table life stay static and say so (docs/speed.md; sweep at speed:
tests/test_sweep_speed.py)."""

from __future__ import annotations

import json
from typing import Any

import numpy as np
import pytest
from click.testing import CliRunner

from bearingload.cli import main

from .cli_helpers import run_entry


def _run(*args: str) -> Any:
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


def _ok(*args: str) -> str:
    out = _run(*args)
    assert out.exit_code == 0, out.output
    return out.stdout


def _error(capsys: Any, *args: str) -> str:
    """The one ``Error:`` line of a refused command line (exit 2, nothing on stdout)."""
    code, out, err = run_entry(capsys, *args)
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and lines[0].startswith("Error:"), err
    return lines[0]


@pytest.mark.parametrize(
    "case",
    [
        ("6205", "-F", "1kN", "--speed", "3000"),
        ("6205", "-F", "2kN", "-G", "C3", "--speed", "12000", "--ball-density", "3200"),
        ("-z", "9", "--ball-diameter", "7.938", "--pitch-diameter", "38.5", "-F", "1kN",
         "-G", "10um", "--speed", "10000", "--viscosity", "20cSt"),
        ("6306", "-F", "3kN", "-G", "C3", "--clearance-pick", "range", "--speed", "500rad/s"),
    ],
)  # fmt: skip
def test_a_ball_bearing_at_speed_is_solve_with_an_axial_load_of_0(case):
    """Every format of the radial case at speed equals the same case with -A 0, byte for
    byte, and names the ball dynamics (the inner and outer contacts differ)."""
    for fmt in ("json", "csv", "table"):
        plain = _ok("solve", *case, "--format", fmt)
        assert plain == _ok("solve", *case, "-A", "0", "--format", fmt), fmt
    doc = json.loads(_ok("solve", *case, "--format", "json"))
    for c in doc["cases"]:
        assert "ball dynamics" in c["model"] and c["axial_load"] == 0.0
        inner, outer = np.array(c["ball_loads_inner"]), np.array(c["ball_loads_outer"])
        assert np.all(outer[inner > 0] > inner[inner > 0])


#: What a speed adds besides the hours: the defect frequencies (tests/test_frequencies.py).
FREQUENCIES = (
    "cage_frequency",
    "ball_pass_frequency_outer",
    "ball_pass_frequency_inner",
    "ball_spin_frequency",
)


def test_quasi_static_is_the_static_radial_engine_bit_for_bit():
    """--quasi-static: the radial engine's answer, every key of the json without --speed equal
    bit for bit, the hours at the speed and the defect frequencies added (L 10^6/(60 n))."""
    static = json.loads(_ok("solve", "6205", "-F", "1kN", "--format", "json"))["cases"][0]
    quasi = json.loads(_ok("solve", "6205", "-F", "1kN", "--speed", "3000", "--quasi-static",
                           "--format", "json"))["cases"][0]  # fmt: skip
    assert "Kurochkin" in quasi["model"] and "ball dynamics" not in quasi["model"]
    assert {k: v for k, v in quasi.items() if k in static} == static
    for life in ("rating_life", "reference_rating_life"):
        assert quasi[f"{life}_hours"] == pytest.approx(static[life] * 1e6 / (60 * 3000), 1e-9)
    assert set(quasi) - set(static) == {"speed", "rating_life_hours",
                                        "reference_rating_life_hours", *FREQUENCIES}  # fmt: skip
    # the closed-form methods with the static model
    text = _ok("solve", "6205", "-F", "1kN", "--speed", "3000", "--quasi-static", "--method", "all")
    assert "stribeck" in text.lower()


def test_the_static_answer_is_the_library_radial_engine():
    """The --quasi-static Q_max and ball loads are those of the radial library call."""
    from bearingload.bearings.resolve import resolve_bearing
    from bearingload.studies.loaded_bearing import solve_bearing

    quasi = json.loads(_ok("solve", "6205", "-F", "1kN", "--speed", "3000", "--quasi-static",
                           "--format", "json"))["cases"][0]  # fmt: skip
    (lc,) = solve_bearing([resolve_bearing("6205")], 1000.0, 0.0, ["exact"], 36e6)
    assert quasi["q_max"] == float(f"{lc.result.q_max:.10g}")  # json: 10 significant digits
    assert quasi["x"] == float(f"{lc.result.x:.10g}")


def test_a_roller_bearing_stays_radial_at_speed(capsys):
    """NU205 at speed: the radial engine, the loads of the case without a speed bit for bit;
    --ball-density refused for it, --quasi-static accepted (the same answer)."""
    static = json.loads(_ok("solve", "NU205", "-F", "5kN", "--format", "json"))["cases"][0]
    for extra in ((), ("--quasi-static",)):
        fast = json.loads(_ok("solve", "NU205", "-F", "5kN", "--speed", "3000", *extra,
                              "--format", "json"))["cases"][0]  # fmt: skip
        assert "ball dynamics" not in fast["model"] and "contact_angles_outer" not in fast
        assert {k: v for k, v in fast.items() if k in static} == static
    line = _error(
        capsys, "solve", "NU205", "-F", "5kN", "--speed", "3000", "--ball-density", "3200"
    )
    assert "--ball-density" in line and "roller bearing" in line


@pytest.mark.parametrize(
    ("extra", "words"),
    [
        (("--method", "stribeck"), ("--method", "--quasi-static")),
        (("--method", "all"), ("--method", "--quasi-static")),
        (("--method", "continuum", "--plot", "x.pdf"), ("--method", "--quasi-static")),
        (("--revolutions", "1e6"), ("--revolutions", "--quasi-static")),
        (("--stiffness", "3e5"), ("--stiffness", "--quasi-static")),
        (("--rotating", "outer"), ("--rotating", "--quasi-static")),
        (("--quasi-static", "--ball-density", "3200"), ("--ball-density",)),
    ],
)
def test_what_the_dynamics_cannot_honour_is_refused(capsys, extra, words):
    """One Error line naming the option and the way out (--quasi-static), for a ball bearing
    at speed; each accepted with --quasi-static where it belongs to the static model."""
    line = _error(capsys, "solve", "6205", "-F", "1kN", "--speed", "3000", *extra)
    assert all(w in line for w in words), line
    if "--ball-density" not in extra and "--plot" not in extra:
        _ok("solve", "6205", "-F", "1kN", "--speed", "3000", "--quasi-static", *extra)


def test_a_ring_without_its_geometry_is_refused_at_speed(capsys):
    """--balls and --stiffness alone: no geometry for the dynamics, no C for the hours."""
    for extra in ((), ("--quasi-static",)):
        line = _error(
            capsys, "solve", "-z", "8", "-F", "1kN", "-K", "3e5", "--speed", "3000", *extra
        )
        assert "--speed" in line and "--ball-diameter" in line


def _batch_json(text: str) -> dict[str, Any]:
    out = CliRunner().invoke(main, ["batch", "-", "--format", "json"], input=text,
                             catch_exceptions=False)  # fmt: skip
    return json.loads(out.stdout)


ROWS = [
    ("6205,1kN,,3000,", ["6205", "-F", "1kN", "--speed", "3000"]),
    ("6306,3kN,C3,8000,", ["6306", "-F", "3kN", "-G", "C3", "--speed", "8000"]),
    ("6205,1kN,,3000,true", ["6205", "-F", "1kN", "--speed", "3000", "--quasi-static"]),
    ("NU205,5kN,,3000,", ["NU205", "-F", "5kN", "--speed", "3000"]),
    ("6205,1kN,,,", ["6205", "-F", "1kN"]),
]


def test_a_radial_batch_row_at_speed_equals_solve():
    """A file without a load column: every row equals solve's json of the same case, the
    ball-bearing rows at speed with the ball dynamics (model and per-ball contacts held), the
    others radial; the rows share the file's columns (rectangular csv)."""
    text = "bearing,load,clearance,speed,quasi_static\n" + "\n".join(r for r, _ in ROWS) + "\n"
    doc = _batch_json(text)
    assert doc["skipped"] == []
    for record, (_, args) in zip(doc["cases"], ROWS, strict=True):
        (expected,) = json.loads(_ok("solve", *args, "--format", "json"))["cases"]
        shared = [k for k in expected if k in record and k != "warnings"]
        assert {"q_max", "model", "reference_rating_life"} <= set(shared), args
        dynamic = "ball dynamics" in expected["model"]
        assert dynamic == (
            args[0] != "NU205" and "--speed" in args and "--quasi-static" not in args
        )
        if dynamic:
            assert {"ball_loads_outer", "contact_angles_inner"} <= set(shared)
        for key in shared:
            assert record[key] == expected[key], (args, key)
    csv = CliRunner().invoke(main, ["batch", "-", "--format", "csv"], input=text)
    csv = csv.stdout.strip().splitlines()
    assert len({line.count(",") for line in csv}) == 1 and len(csv) == len(ROWS) + 1


def test_a_radial_batch_row_at_speed_is_refused_as_solve_refuses_it():
    """A method other than exact or a revolutions cell on a ball bearing's row at speed is
    skipped with the reason naming quasi_static; with quasi_static true it is solved."""
    head = "bearing,load,speed,quasi_static,method,revolutions\n"
    rows = ["6205,1kN,3000,,stribeck,", "6205,1kN,3000,,,1e6", "NU205,1kN,3000,,stribeck,",
            "6205,1kN,3000,true,stribeck,", "6205,1kN,,,,"]  # fmt: skip
    doc = _batch_json(head + "\n".join(rows) + "\n")
    reasons = {s["row"]: s["reason"] for s in doc["skipped"]}
    assert set(reasons) == {2, 3}
    assert reasons[2].startswith("method:") and "quasi_static" in reasons[2]
    assert reasons[3].startswith("revolutions:") and "quasi_static" in reasons[3]
    density = _batch_json("bearing,load,speed,ball_density\nNU205,1kN,3000,3200\n")
    ((skipped),) = density["skipped"]
    assert skipped["reason"].startswith("ball_density:") and "roller" in skipped["reason"]


@pytest.mark.parametrize(
    "args",
    [
        ("sweep", "6205", "-F", "1kN", "--steps", "3"),
        ("sweep", "6205", "-F", "1kN", "-A", "300N", "--steps", "3"),
    ],
)
def test_sweep_quasi_static_stays_static_and_says_so(args):
    """At --speed with --quasi-static the note (table, markdown) and the json key ball_dynamics
    say the static model was solved; without --speed neither; the numbers are those of the case
    without the speed (the static model). (table life: tests/test_life_table_speed.py.)"""
    note = "Ball dynamics left out: the static model"
    speed = ("--speed", "3000", "--quasi-static")
    for fmt in ("table", "markdown"):
        assert note in _ok(*args, *speed, "--format", fmt)
        assert note not in _ok(*args, "--format", fmt)
    fast = json.loads(_ok(*args, *speed, "--format", "json"))
    slow = json.loads(_ok(*args, "--format", "json"))
    assert fast["ball_dynamics"].startswith(note) and "ball_dynamics" not in slow
    for r, s in zip(fast["rows"], slow["rows"], strict=True):
        assert {k: v for k, v in r.items() if k in s} == s


def test_a_roller_sweep_at_speed_has_no_ball_dynamics_note():
    out = _ok("sweep", "NU205", "-F", "5kN", "--speed", "3000", "--steps", "3")
    assert "Ball dynamics" not in out
