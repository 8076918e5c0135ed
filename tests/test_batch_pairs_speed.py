"""``bearingload batch`` of bearing pairs with the service columns (speed, reliability, the
viscosity or an oil, roughness ...) and the ball dynamics (speed, ball_density, quasi_static):
each row writes exactly the csv rows ``solve`` writes for the same pair with those options,
its json rows each bearing's model and contacts as solve's json, its warnings solve's; a row
alone gives the bits it gives among others; the cells the dynamics cannot take are refused
row by row, as solve refuses the options. Before, a file of pairs with any service column was
refused whole ("not yet given by batch")."""

from __future__ import annotations

import csv
import json

from click.testing import CliRunner

from bearingload.cli import main

from .cli_helpers import SolvedRows, besides_tilt

#: (batch cells, solve options): the dynamics with the lives in hours, reliability, a_ISO
#: (viscosity, roughness), an oil at a temperature, ceramic balls, the static pair at a speed
#: (quasi_static), no speed at all, a DF pair with a moment, a tandem pair lifted off.
CASES = [
    ({"bearing": "7205BDB", "preload": "500N", "load": "1kN", "axial_load": "300N",
      "speed": "10000", "viscosity": "20", "reliability": "95", "roughness": "0.0002mm"},
     ["7205BDB", "--preload", "500N", "-F", "1kN", "-A", "300N", "--speed", "10000",
      "--viscosity", "20", "--reliability", "95", "--roughness", "0.0002mm"]),
    ({"bearing": "7205BDB", "preload": "300N", "load": "2kN", "axial_load": "500N",
      "speed": "6000", "oil": "VG68", "temperature": "70"},
     ["7205BDB", "--preload", "300N", "-F", "2kN", "-A", "500N", "--speed", "6000", "--oil",
      "VG68", "--temperature", "70"]),
    ({"bearing": "7206CDB", "preload": "200N", "load": "1kN", "axial_load": "100N",
      "speed": "20000", "ball_density": "3200"},
     ["7206CDB", "--preload", "200N", "-F", "1kN", "-A", "100N", "--speed", "20000",
      "--ball-density", "3200"]),
    ({"bearing": "7205BDB", "preload": "500N", "load": "1kN", "axial_load": "300N",
      "speed": "10000", "quasi_static": "true"},
     ["7205BDB", "--preload", "500N", "-F", "1kN", "-A", "300N", "--speed", "10000",
      "--quasi-static"]),
    ({"bearing": "7205BDB", "preload": "500N", "load": "1kN", "axial_load": "300N"},
     ["7205BDB", "--preload", "500N", "-F", "1kN", "-A", "300N"]),
    ({"bearing": "7205B", "arrangement": "DF", "preload": "400N", "load": "1kN",
      "moment": "3Nm", "speed": "12000", "reliability": "99"},
     ["7205B", "--arrangement", "DF", "--preload", "400N", "-F", "1kN", "--moment", "3Nm",
      "--speed", "12000", "--reliability", "99"]),
    ({"bearing": "7205BDB", "preload": "100N", "load": "0", "axial_load": "2kN",
      "speed": "8000"},
     ["7205BDB", "--preload", "100N", "-F", "0", "-A", "2kN", "--speed", "8000"]),
]  # fmt: skip
HEAD = ("bearing", "arrangement", "preload", "load", "axial_load", "moment", "speed",
        "reliability", "viscosity", "oil", "temperature", "roughness", "ball_density",
        "quasi_static")  # fmt: skip


def _file(cases: list[dict[str, str]], head: tuple[str, ...] = HEAD) -> str:
    lines = [",".join(head)] + [",".join(c.get(k, "") for k in head) for c in cases]
    return "\n".join(lines) + "\n"


def _batch(text: str, *args: str):
    return SolvedRows(
        CliRunner().invoke(main, ["batch", "-", *args], input=text, catch_exceptions=False)
    )


def _solve(options: list[str], fmt: str) -> str:
    out = CliRunner().invoke(main, ["solve", *options, "--format", fmt], catch_exceptions=False)
    assert out.exit_code == 0, out.stderr
    return out.stdout


def _rows(text: str) -> list[list[str]]:
    return list(csv.reader(text.splitlines()))


def test_every_row_writes_the_csv_rows_solve_writes_with_those_options():
    out = _batch(_file([c for c, _ in CASES]), "--format", "csv")
    assert out.exit_code == 0, out.stderr
    lines = _rows(out.stdout)
    assert len(lines) == 1 + 2 * len(CASES)
    head = lines[0][1:]
    for k, (_, options) in enumerate(CASES):
        solved = _rows(_solve(options, "csv"))
        for j in (1, 2):
            got = dict(zip(head, lines[2 * k + j][1:], strict=True))
            want = dict(zip(solved[0], solved[j], strict=True))
            assert lines[2 * k + j][0] == str(k + 2)
            assert {h: got[h] for h in want} == want, (k, j)
            oil = {"oil", "temperature [°C]"}  # the oil's cells, written as given
            assert all(got[h] == "" for h in head if h not in want and h not in oil), (k, j)
    at_speed = dict(zip(head, lines[1][1:], strict=True))
    assert float(at_speed["pair_modified_rating_life_hours [h]"]) > 0  # a_ISO of both bearings
    assert at_speed["ball_density [kg/m^3]"] == "7850.0"


def test_json_rows_carry_each_bearings_model_contacts_and_solves_warnings():
    out = _batch(_file([c for c, _ in CASES]), "--format", "json")
    assert out.exit_code == 0, out.stderr
    rows = json.loads(out.stdout)["cases"]
    for k, (_, options) in enumerate(CASES):
        doc = json.loads(_solve(options, "json"))
        (case,) = doc["cases"]
        assert rows[2 * k]["warnings"] == doc["warnings"], k
        assert rows[2 * k + 1]["warnings"] == [], k
        for j, bearing in enumerate(case["bearings"]):
            row = rows[2 * k + j]
            for key in ("model", "contact_angles_inner", "contact_angles_outer",
                        "ball_loads_inner", "ball_loads_outer"):  # fmt: skip
                assert row[key] == bearing[key], (k, j, key)
    dynamics = rows[0]["model"]
    assert "ball dynamics" in dynamics and "ball dynamics" not in rows[6]["model"]
    assert rows[0]["ball_loads_inner"] != rows[0]["ball_loads_outer"]  # the centrifugal force
    assert rows[6]["ball_loads_inner"] == rows[6]["ball_loads_outer"]  # quasi_static true


def test_a_row_at_speed_alone_and_in_chunks_of_one_gives_the_same_bits():
    many = [dict(CASES[0][0], load=f"{300 + 97 * i}N", speed=str(4000 + 1500 * i))
            for i in range(6)]  # fmt: skip
    whole = _batch(_file(many), "--format", "csv").stdout.splitlines()
    assert len(whole) == 1 + 2 * len(many)
    for i, case in enumerate(many):
        alone = _batch(_file([case]), "--format", "csv").stdout.splitlines()
        assert [line.split(",", 1)[1] for line in alone[1:]] == [
            line.split(",", 1)[1] for line in whole[1 + 2 * i : 3 + 2 * i]
        ]
    assert _batch(_file(many), "--format", "csv", "--chunk-size", "1").stdout.splitlines() == whole


def test_cells_the_dynamics_cannot_take_skip_their_row_with_solves_reason():
    good = CASES[0][0]
    bad = [
        (dict(good, speed="", viscosity="", reliability="", roughness="", ball_density="3200"),
         "ball_density: it enters the ball dynamics at 'speed', which 'quasi_static' or a "
         "missing 'speed' leave out"),
        (dict(good, speed="", viscosity="", reliability="", roughness="", quasi_static="true"),
         "quasi_static: it needs 'speed'"),
        (dict(good, speed="90000"),
         "speed: n d_m must be at most 2e+06 mm/min for the ball-dynamics model (n = 90000 rpm "
         "with d_m = 38.5 mm: at most 51948.05195 rpm; beyond, ring expansion, cage and "
         "lubricant forces it leaves out matter); 'quasi_static' gives the static model at "
         "any speed (the lives in hours)"),
    ]  # fmt: skip
    out = _batch(_file([good, *(c for c, _ in bad)]), "--format", "csv")
    assert out.exit_code == 1
    assert [line.split(",", 1)[0] for line in out.stdout.splitlines()[1:]] == ["2", "2"]
    said = out.stderr.splitlines()
    for r, (_, reason) in enumerate(bad, start=3):
        assert f"Skipped: row {r}: {reason}" in said


def test_outer_ring_turning_at_speed_is_refused_and_quasi_static_gives_its_lives():
    cells = {"bearing": "7205BDB", "preload": "500N", "load": "1kN", "axial_load": "300N",
             "speed": "10000", "rotating": "outer"}  # fmt: skip
    head = (*HEAD, "rotating")
    out = _batch(_file([cells], head), "--format", "csv")
    assert out.exit_code == 1
    assert out.stderr.splitlines()[0] == (
        "Skipped: row 2: rotating: the ball dynamics at 'speed' are coded for the inner ring "
        "turning (docs/speed.md); give 'quasi_static' for the static model with the outer "
        "ring's lives"
    )
    quasi = _batch(_file([dict(cells, quasi_static="true")], head), "--format", "csv")
    assert quasi.exit_code == 0, quasi.stderr
    solved = _rows(_solve(["7205BDB", "--preload", "500N", "-F", "1kN", "-A", "300N", "--speed",
                           "10000", "--rotating", "outer", "--quasi-static"], "csv"))  # fmt: skip
    lines = _rows(quasi.stdout)
    got = dict(zip(lines[0][1:], lines[1][1:], strict=True))
    assert {h: got[h] for h in solved[0]} == dict(zip(solved[0], solved[1], strict=True))


def test_a_row_whose_lives_overflow_is_skipped_the_others_written():
    """A speed so small that the life in hours overflows ended the whole file of pairs (exit 2,
    the good rows lost); it is now that row's reason, as in a file of single bearings."""
    text = ("bearing,load,axial_load,preload,speed\n7205BDB,1kN,300N,500N,10000\n"
            "7205BDB,1kN,300N,500N,1e-307\n")  # fmt: skip
    out = _batch(text, "--format", "csv")
    assert out.exit_code == 1
    assert [line.split(",", 1)[0] for line in out.stdout.splitlines()[1:]] == ["2", "2"]
    assert besides_tilt(out.stderr)[0] == (
        "Skipped: row 3: speed: is so small that the life in hours L 10^6/(60 n) overflows"
    )
