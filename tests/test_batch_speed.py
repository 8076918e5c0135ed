"""``bearingload batch`` with a ``speed`` column on the combined engine: the ball dynamics
(centrifugal force, gyroscopic moment; docs/speed.md) exactly as ``bearingload solve --speed``,
the columns ``quasi_static`` and ``ball_density`` as its options, every row independent of the
others, and the rows solve refuses skipped with the reason."""

from __future__ import annotations

import json
import math
from typing import Any

import pytest
from click.testing import CliRunner

from bearingload.bearings.resolve import resolve_bearing
from bearingload.cli import main
from bearingload.errors import InputError
from bearingload.studies.combined_bearing import solve_combined_bearing

from .cli_helpers import run_entry

HEAD = ("bearing", "load", "axial_load", "clearance", "speed", "quasi_static", "ball_density")
#: (batch cells, solve options) of one case each: deep groove with an axial load at speed (C3,
#: rad/s), the 7205B of docs/speed.md at 20 000 rpm, ceramic balls, a row without a speed, a
#: quasi_static row, an angular-contact designation without an axial load cell, and a radial row
#: of a ball bearing at a speed (no combined cell: the combined engine at F_a = 0 with the ball
#: dynamics, as solve).
CASES = [
    ({"bearing": "6205", "load": "1.4kN", "axial_load": "700N", "speed": "15000"},
     ["6205", "-F", "1.4kN", "-A", "700N", "--speed", "15000"]),
    ({"bearing": "6205", "load": "2kN", "axial_load": "500N", "clearance": "C3",
      "speed": "1000rad/s"},
     ["6205", "-F", "2kN", "-A", "500N", "-G", "C3", "--speed", "1000rad/s"]),
    ({"bearing": "7205B", "load": "800N", "axial_load": "1.5kN", "speed": "20000"},
     ["7205B", "-F", "800N", "-A", "1.5kN", "--speed", "20000"]),
    ({"bearing": "7205B", "load": "800N", "axial_load": "1.5kN", "speed": "20000",
      "ball_density": "3200"},
     ["7205B", "-F", "800N", "-A", "1.5kN", "--speed", "20000", "--ball-density", "3200"]),
    ({"bearing": "6205", "load": "1kN", "axial_load": "200N"},
     ["6205", "-F", "1kN", "-A", "200N"]),
    ({"bearing": "6205", "load": "1.4kN", "axial_load": "700N", "speed": "15000",
      "quasi_static": "true"},
     ["6205", "-F", "1.4kN", "-A", "700N", "--speed", "15000", "--quasi-static"]),
    ({"bearing": "6205", "load": "1.4kN", "axial_load": "700N", "speed": "15000",
      "quasi_static": "False"},
     ["6205", "-F", "1.4kN", "-A", "700N", "--speed", "15000"]),
    ({"bearing": "6205", "load": "1kN", "speed": "3000"}, ["6205", "-F", "1kN", "--speed", "3000"]),
]  # fmt: skip
#: What solve's json names beyond the columns (json only), as batch must carry it.
HELD = ("model", "contact_angles_inner", "contact_angles_outer", "ball_loads_inner",
        "ball_loads_outer")  # fmt: skip


def _file(cases: list[dict[str, str]], head: tuple[str, ...] = HEAD) -> str:
    return (
        "\n".join([",".join(head)] + [",".join(c.get(k, "") for k in head) for c in cases]) + "\n"
    )


def _batch(text: str, *args: str):
    return CliRunner().invoke(main, ["batch", "-", *args], input=text, catch_exceptions=False)


def _batch_json(text: str, *args: str) -> dict[str, Any]:
    out = _batch(text, "--format", "json", *args)
    return json.loads(out.stdout)


def _solve_json(args: list[str]) -> dict[str, Any]:
    out = CliRunner().invoke(main, ["solve", *args, "--format", "json"], catch_exceptions=False)
    assert out.exit_code == 0, out.output
    (case,) = json.loads(out.stdout)["cases"]
    return case


def _close(a: Any, b: Any, key: str) -> None:
    """Equal numbers to 1e-12 (relative), lists element by element, the rest equal."""
    if isinstance(b, list) and b and not isinstance(b[0], str):
        assert isinstance(a, list) and len(a) == len(b), key
        for x, y in zip(a, b, strict=True):
            _close(x, y, key)
    elif isinstance(b, float) and not isinstance(a, (bool, str, type(None))):
        assert abs(a - b) <= 1e-12 * max(abs(a), abs(b)), (key, a, b)
    else:
        assert a == b, (key, a, b)


def test_every_row_equals_solve_json():
    """Every row of one file, with a speed or not, quasi_static or not, equals solve's json of
    the same case: every key the two share (the held per-ball contacts and model included)."""
    doc = _batch_json(_file([c for c, _ in CASES]))
    assert doc["skipped"] == []
    assert [r["row"] for r in doc["cases"]] == list(range(2, len(CASES) + 2))
    for record, (_, args) in zip(doc["cases"], CASES, strict=True):
        expected = _solve_json(args)
        shared = [k for k in expected if k in record]
        combined = "-A" in args or "--speed" in args
        assert ("q_max" in shared) and (set(HELD) <= set(shared) or not combined), args
        for key in shared:
            _close(record[key], expected[key], key)
    for unit, key in (("°", "contact_angles_outer"), ("N", "ball_loads_inner")):
        assert doc["units"][key] == unit


def test_the_speed_rows_are_the_ball_dynamics():
    """The rows at speed name the ball dynamics and carry different inner and outer contacts
    (the centrifugal force loads the outer ring); the quasi_static row and the row without a
    speed are the static model (inner = outer); the radial row at a speed has the dynamics too."""
    cases = _batch_json(_file([c for c, _ in CASES]))["cases"]
    for record, (cells, _) in zip(cases, CASES, strict=True):
        dynamic = "speed" in cells and cells.get("quasi_static") != "true"
        assert ("ball dynamics" in record["model"]) == dynamic
        outer, inner = record["ball_loads_outer"], record["ball_loads_inner"]
        assert (outer != inner) == dynamic
        if dynamic:
            assert all(o > i for o, i in zip(outer, inner, strict=True)), cells
    static, quasi = cases[0], cases[5]
    assert quasi["q_max"] != static["q_max"]  # quasi_static changes the answer...
    assert quasi["speed"] == static["speed"]  # ...not the speed of the lives in hours


def test_a_row_does_not_depend_on_the_other_rows():
    """Each row at speed alone, among the others in another order, and in chunks of one: the same
    json record, bit for bit (a vectorised call solves each case on its own)."""
    cells = [c for c, _ in CASES]
    together = _batch_json(_file(cells))["cases"]
    backwards = _batch_json(_file(cells[::-1]))["cases"][::-1]
    chunked = _batch_json(_file(cells), "--chunk-size", "1")["cases"]
    for i, cell in enumerate(cells):
        (alone,) = _batch_json(_file([cell]))["cases"]
        for other in (together[i], backwards[i], chunked[i]):
            assert {k: v for k, v in other.items() if k != "row"} == {
                k: v for k, v in alone.items() if k != "row"
            }, cell


def test_a_row_the_dynamics_cannot_balance_is_skipped_not_the_batch(monkeypatch):
    """A row whose ball dynamics do not converge is skipped with the solver's reason; the others
    of its call are written, equal to their rows alone; no NaN anywhere."""
    from bearingload.errors import ConvergenceError
    from bearingload.models import high_speed

    real = high_speed.solve_high_speed

    def failing(*args: Any, **kwargs: Any) -> Any:
        if 12345.0 in kwargs["speed"].ravel().tolist():
            raise ConvergenceError("ball-dynamics ring and ball equilibrium", 7, 1e-3,
                                   {"speed": kwargs["speed"]})  # fmt: skip
        return real(*args, **kwargs)

    monkeypatch.setattr(high_speed, "solve_high_speed", failing)
    rows = [dict(CASES[0][0], speed=s) for s in ("9000", "12345", "15000", "20000")]
    out = _batch(_file(rows), "--format", "json")
    assert out.exit_code == 1
    doc = json.loads(out.stdout)
    assert [r["row"] for r in doc["cases"]] == [2, 4, 5]
    ((row, reason),) = [(s["row"], s["reason"]) for s in doc["skipped"]]
    assert row == 3 and "did not converge" in reason and "12345" in reason
    assert "nan" not in out.stdout.lower()
    for record, cell in zip(doc["cases"], [rows[0], *rows[2:]], strict=True):
        (alone,) = _batch_json(_file([cell]))["cases"]
        assert {k: v for k, v in record.items() if k != "row"} == {
            k: v for k, v in alone.items() if k != "row"
        }


#: (cells of a combined file's row, reason's start, solve options refused alike): what solve
#: refuses, a row of its own.
REFUSED = [
    ({"axial_load": "500N", "ball_density": "3200"}, "ball_density: it enters the ball dynamics",
     ["-A", "500N", "--ball-density", "3200"]),
    ({"axial_load": "500N", "speed": "3000", "quasi_static": "true", "ball_density": "3200"},
     "ball_density: it enters the ball dynamics",
     ["-A", "500N", "--speed", "3000", "--quasi-static", "--ball-density", "3200"]),
    ({"axial_load": "500N", "quasi_static": "true"}, "quasi_static: it needs 'speed'",
     ["-A", "500N", "--quasi-static"]),
    ({"speed": "3000", "quasi_static": "true", "ball_density": "3200"},
     "ball_density: it enters the ball dynamics",
     ["--speed", "3000", "--quasi-static", "--ball-density", "3200"]),
    ({"ball_density": "3200"}, "ball_density: it enters the ball dynamics",
     ["--ball-density", "3200"]),
    ({"quasi_static": "TRUE"}, "quasi_static: it needs 'speed'", ["--quasi-static"]),
    ({"axial_load": "500N", "speed": "3000", "ball_density": "0"}, "ball_density: must be in (0, 100000]",
     ["-A", "500N", "--speed", "3000", "--ball-density", "0"]),
    ({"axial_load": "500N", "speed": "3000", "ball_density": "2e5"},
     "ball_density: must be in (0, 100000]", ["-A", "500N", "--speed", "3000", "--ball-density", "2e5"]),
    ({"axial_load": "500N", "speed": "3000", "ball_density": "3.2g/cm^3"},
     "ball_density: must be a number, got", ["-A", "500N", "--speed", "3000", "--ball-density", "3.2g/cm^3"]),
    ({"axial_load": "500N", "speed": "3000", "quasi_static": "1"}, "quasi_static: cannot read",
     ["-A", "500N", "--speed", "3000", "--quasi-static", "1"]),
    ({"axial_load": "500N", "speed": "60000"}, "speed: n d_m must be at most",
     ["-A", "500N", "--speed", "60000"]),
]  # fmt: skip


@pytest.mark.parametrize(("cells", "reason", "options"), REFUSED, ids=[r[1] for r in REFUSED])
def test_what_solve_refuses_is_a_skipped_row(cells, reason, options):
    """The refused row is skipped with its column and reason, the good rows around it are
    written, and solve refuses the same case (exit 2 with an Error line)."""
    good = {"bearing": "6205", "load": "1kN", "axial_load": "200N", "speed": "5000"}
    out = _batch(_file([good, {"bearing": "6205", "load": "1kN", **cells}, good]), "--format",
                 "json")  # fmt: skip
    assert out.exit_code == 1, out.output
    doc = json.loads(out.stdout)
    assert [r["row"] for r in doc["cases"]] == [2, 4]
    ((row, message),) = [(s["row"], s["reason"]) for s in doc["skipped"]]
    assert row == 3 and message.startswith(reason), message
    refused = CliRunner().invoke(main, ["solve", "6205", "-F", "1kN", *options])
    assert refused.exit_code != 0 and "Error:" in refused.output, refused.output
    assert "Traceback" not in refused.output + out.output


def test_a_given_stiffness_at_speed_is_refused_as_solve_refuses_it():
    """The ball dynamics need each contact's Hertz stiffness: a row giving the ball stiffness
    with a speed is skipped with the library's reason, the one solve prints."""
    head = ("balls", "ball_diameter", "pitch_diameter", "stiffness", "load", "axial_load",
            "speed")  # fmt: skip
    row = {"balls": "9", "ball_diameter": "7.938", "pitch_diameter": "38.5", "stiffness": "1e5",
           "load": "1kN", "axial_load": "200N", "speed": "3000"}  # fmt: skip
    out = _batch(_file([row], head), "--format", "json")
    ((skipped),) = json.loads(out.stdout)["skipped"]
    solved = CliRunner().invoke(main, ["solve", "-z", "9", "--ball-diameter", "7.938",
                                       "--pitch-diameter", "38.5", "-K", "1e5", "-F", "1kN",
                                       "-A", "200N", "--speed", "3000"])  # fmt: skip
    assert solved.exit_code == 2 and "Error: Invalid value for '--stiffness'" in solved.output
    assert skipped["reason"].startswith(
        "stiffness: the ball dynamics at 'speed' need each contact's Hertz"
    )
    assert "Hertz stiffness from the ball geometry" in solved.output
    quasi = _batch_json(_file([row | {"quasi_static": "true"}], (*head, "quasi_static")))
    assert quasi["skipped"] == [] and len(quasi["cases"]) == 1  # as solve --quasi-static


def test_a_quasi_static_false_on_a_radial_row_is_solve_without_the_flag():
    """quasi_static false (or blank) is solve without --quasi-static: accepted on a radial row."""
    rows = [{"bearing": "6205", "load": "1kN", "speed": "3000", "quasi_static": q}
            for q in ("false", "FALSE", "")]  # fmt: skip
    doc = _batch_json(_file(rows, ("bearing", "load", "speed", "quasi_static")))
    assert doc["skipped"] == [] and len(doc["cases"]) == 3
    expected = _solve_json(["6205", "-F", "1kN", "--speed", "3000"])
    for record in doc["cases"]:
        _close(record["q_max"], expected["q_max"], "q_max")


def test_the_table_names_the_model_and_help_teaches_the_columns():
    """A table with rows at speed carries solve's model in a note; batch --help names the
    columns."""
    out = _batch(_file([CASES[0][0], CASES[4][0]]), "--format", "markdown")
    assert "ball dynamics: centrifugal force and gyroscopic moment" in out.stdout
    plain = _batch(_file([CASES[4][0]]), "--format", "markdown")
    assert "ball dynamics" not in plain.stdout
    text = " ".join(CliRunner().invoke(main, ["batch", "--help"]).output.split())
    for word in ("quasi_static (true or false", "ball_density (kg/m^3", "contact_angles_inner"):
        assert word in text, word
    assert math.isfinite(json.loads(_batch(_file([CASES[3][0]]), "--format", "json").stdout)[
        "cases"][0]["q_max"])  # fmt: skip


def test_a_batch_row_at_speed_with_the_outer_ring_rotating_is_skipped(capsys, tmp_path):
    """solve refuses --rotating outer with the ball dynamics (they are the inner ring's); a
    batch row of a ball bearing with a speed and rotating outer was solved (the radial row by
    the combined engine at F_a = 0, a combined row too), its L10r that of the outer ring. It is
    skipped naming quasi_static; with quasi_static true it is solved as solve --quasi-static
    solves it. The library refuses the pair of arguments too."""
    path = tmp_path / "rows.csv"
    path.write_text(
        "bearing,load,axial_load,speed,rotating,quasi_static\n6205,1kN,,3000,outer,\n"
        "6205,1kN,100,3000,outer,\n6205,1kN,,3000,outer,true\n",
        encoding="utf-8",
    )
    code, out, err = run_entry(capsys, "batch", str(path), "--format", "json")
    assert code == 1
    reasons = [w for w in err.splitlines() if w.startswith(("Skipped: row 2", "Skipped: row 3"))]
    assert len(reasons) == 2 and all("rotating: " in w and "quasi_static" in w for w in reasons)
    (row,) = json.loads(out)["cases"]
    _, solved, _ = run_entry(
        capsys,
        "solve",
        "6205",
        "-F",
        "1kN",
        "--speed",
        "3000",
        "--rotating",
        "outer",
        "--quasi-static",
        "--format",
        "json",
    )
    want = json.loads(solved)["cases"][0]
    assert row["row"] == 4 and row["reference_rating_life"] == want["reference_rating_life"]
    with pytest.raises(InputError, match="rotating"):
        solve_combined_bearing([resolve_bearing("6205")], 1000.0, speed=3000.0, rotating="outer")


def test_a_radial_file_with_speed_writes_the_ball_density_solve_prints(capsys, tmp_path):
    """A file of radial rows with a speed column solves a ball bearing's row by the ball
    dynamics, as solve does; solve's json names the ball density used (steel 7850 kg/m^3), so
    batch's json and csv carry it too; blank where no ball dynamics ran (quasi-static, rollers)."""
    path = tmp_path / "radial.csv"
    path.write_text(
        "bearing,load,speed,quasi_static\n6205,1kN,3000,\n6205,1kN,3000,true\nNU206,1kN,3000,\n",
        encoding="utf-8",
    )
    code, out, _ = run_entry(capsys, "batch", str(path), "--format", "json")
    doc = json.loads(out)
    assert code == 0 and doc["units"]["ball_density"] == "kg/m^3"
    assert [c["ball_density"] for c in doc["cases"]] == [7850.0, None, None]
    code, out, _ = run_entry(
        capsys, "solve", "6205", "-F", "1kN", "--speed", "3000", "--format", "json"
    )
    assert json.loads(out)["cases"][0]["ball_density"] == 7850.0
    code, out, _ = run_entry(capsys, "batch", str(path), "--format", "csv")
    assert "ball_density [kg/m^3]" in out.splitlines()[0].split(",")
