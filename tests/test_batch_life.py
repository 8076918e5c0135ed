"""``bearingload batch`` with the life columns (speed, reliability, viscosity, contamination, eC,
fatigue_load_limit, roughness, pressure_viscosity, static_rating): every row equals
``bearingload solve`` with the same options, rows are independent of their group, bad cells are
named. C_0 (static_rating) is written for every bearing row, as solve prints it."""

from __future__ import annotations

import csv
import io

from click.testing import CliRunner

from bearingload.cli import main

from .cli_helpers import SolvedRows, besides_tilt

#: (batch cells, solve options) of one case each: radial and combined rows, each with another
#: subset of the life columns, units in the cells, a roller bearing, kappa above 4 and below 0.1.
CASES = [
    ({"bearing": "6205", "load": "1.4kN", "speed": "3000", "viscosity": "20cSt",
      "reliability": "99", "roughness": "0.15um"},
     ["6205", "-F", "1.4kN", "--speed", "3000", "--viscosity", "20cSt", "--reliability", "99",
      "--roughness", "0.15um"]),
    ({"bearing": "6205", "load": "1.4kN", "axial_load": "700N", "speed": "1500rpm",
      "viscosity": "30", "contamination": "typical", "fatigue_load_limit": "335N"},
     ["6205", "-F", "1.4kN", "-A", "700N", "--speed", "1500rpm", "--viscosity", "30",
      "--contamination", "typical", "--fatigue-load-limit", "335N"]),
    ({"bearing": "6306", "load": "3kN", "clearance": "C3", "speed": "50rad/s"},
     ["6306", "-F", "3kN", "-G", "C3", "--speed", "50rad/s"]),
    ({"bearing": "6205", "load": "2kN", "reliability": "96.5"},
     ["6205", "-F", "2kN", "--reliability", "96.5"]),
    ({"bearing": "NU206", "load": "5kN", "speed": "2000", "viscosity": "12", "ec": "0.3",
      "pressure_viscosity": "18", "static_rating": "30kN"},
     ["NU206", "-F", "5kN", "--speed", "2000", "--viscosity", "12", "--eC", "0.3",
      "--pressure-viscosity", "18", "--static-rating", "30kN"]),
    ({"bearing": "6205", "load": "1kN", "speed": "10000", "viscosity": "400"},
     ["6205", "-F", "1kN", "--speed", "10000", "--viscosity", "400"]),
    ({"bearing": "6205", "load": "1kN", "axial_load": "200N", "speed": "300", "viscosity": "2",
      "clearance": "C4"},
     ["6205", "-F", "1kN", "-A", "200N", "--speed", "300", "--viscosity", "2", "-G", "C4"]),
    ({"bearing": "6205", "load": "1kN", "axial_load": "500N", "static_rating": "8kN"},
     ["6205", "-F", "1kN", "-A", "500N", "--static-rating", "8kN"]),
    ({"balls": "7", "ball_diameter": "11.5", "pitch_diameter": "43.5", "load": "1kN",
      "clearance": "10um", "speed": "1800", "viscosity": "25", "dynamic_rating": "22.5kN"},
     ["-z", "7", "--ball-diameter", "11.5", "--pitch-diameter", "43.5", "-F", "1kN", "-G",
      "10um", "--speed", "1800", "--viscosity", "25", "--dynamic-rating", "22.5kN"]),
    ({"bearing": "6205", "load": "1.4kN"}, ["6205", "-F", "1.4kN"]),
]  # fmt: skip
HEAD = ("bearing", "balls", "ball_diameter", "pitch_diameter", "load", "axial_load",
        "clearance", "dynamic_rating", "static_rating", "speed", "reliability", "viscosity",
        "contamination", "eC", "fatigue_load_limit", "roughness", "pressure_viscosity")  # fmt: skip


def _file(cases: list[dict[str, str]], every_column: bool = False) -> str:
    """A file of ``cases``: a combined-load file when one of them has an axial load (or
    ``every_column``)."""
    head = [k for k in HEAD if k != "axial_load" or every_column
            or any("axial_load" in c for c in cases)]  # fmt: skip
    lines = [",".join(head)]
    lines += [",".join(c.get(k.lower(), "") for k in head) for c in cases]
    return "\n".join(lines) + "\n"


def _batch(text: str, *args: str):
    return SolvedRows(
        CliRunner().invoke(main, ["batch", "-", *args], input=text, catch_exceptions=False)
    )


def _rows(text: str) -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO(text)))


def _solve(args: list[str]):
    return CliRunner().invoke(main, ["solve", *args, "--format", "csv"], catch_exceptions=False)


def test_every_row_equals_solve_every_column():
    """A file of radial rows and one of combined rows (its radial rows fill the columns the two
    engines share, as tests/test_batch_combined.py checks)."""
    for combined in (False, True):
        cases = [c for c in CASES if ("axial_load" in c[0]) == combined]
        _equal_solve(cases)


def _equal_solve(cases: list[tuple[dict[str, str], list[str]]]) -> None:
    out = _batch(_file([c for c, _ in cases]), "--format", "csv")
    assert out.exit_code == 0, out.stderr
    rows = _rows(out.stdout)
    assert len(rows) == len(cases)
    for row, (_, args) in zip(rows, cases, strict=True):
        solved = _solve(args)
        assert solved.exit_code == 0, solved.output
        expected = _rows(solved.stdout)[0]
        # a ball bearing at a speed in a file without a load column: solve's combined engine at
        # F_a = 0 (the ball dynamics), filling the file's radial columns it shares
        at_speed = "axial_load [N]" in expected and "axial_load [N]" not in row
        for key, value in expected.items():  # a file of bearings: stiffness in N/mm^m
            if key not in row and (value == "" or at_speed):
                continue  # a column solve leaves blank that this file has not (epsilon)
            key_here = (
                key if key in row or not key.startswith("stiffness [") else "stiffness [N/mm^m]"
            )
            assert row[key_here] == value, (args, key)
        others = [k for k in row if k not in expected and k not in ("row", "stiffness [N/mm^m]")]
        assert all(row[k] == "" for k in others), (args, [(k, row[k]) for k in others if row[k]])


def test_the_life_columns_are_written_and_c0_always():
    """The columns of the lives the file's life columns give, C_0 for every bearing row."""
    out = _batch(_file([c for c, _ in CASES]), "--format", "csv")
    head = out.stdout.splitlines()[0].split(",")
    for key in ("static_rating [N]", "speed [rpm]", "rating_life_hours [h]",
                "reference_rating_life_hours [h]", "kappa", "a_iso", "modified_rating_life [10^6 rev]",
                "modified_reference_rating_life_hours [h]", "film_thickness [mm]", "film_ratio"):  # fmt: skip
        assert key in head, key
    rows = _rows(out.stdout)
    assert all(r["static_rating [N]"] for r in rows if r["bearing"] != "given by hand")
    assert rows[7]["static_rating [N]"] == "8000.0"
    plain = _batch("bearing,load\n6205,1.4kN\nNU206,5kN\n", "--format", "csv")
    head = plain.stdout.splitlines()[0].split(",")
    assert "static_rating [N]" in head and "speed [rpm]" not in head and "kappa" not in head


def test_warnings_equal_solves():
    """kappa above 4 and below 0.1: the row's warning is solve's."""
    for cells, args in (CASES[5], CASES[6]):
        out = _batch(_file([cells]), "--format", "csv")
        solved = CliRunner().invoke(main, ["solve", *args, "--format", "csv"])
        wanted = [w.removeprefix("Warning: ") for w in solved.stderr.splitlines()]
        found = [w.split(": ", 2)[2] for w in out.stderr.splitlines()]
        assert any("kappa" in w for w in wanted)
        assert found == wanted


def test_a_row_does_not_depend_on_its_group():
    """Each row alone gives the same line as in the file with the others."""
    text = _file([c for c, _ in CASES])
    together = out_lines = _batch(text, "--format", "csv").stdout.splitlines()
    for i, (cells, _) in enumerate(CASES):
        alone = _batch(_file([cells], True), "--format", "csv").stdout.splitlines()
        assert alone[0] == out_lines[0]
        assert alone[1].split(",", 1)[1] == together[i + 1].split(",", 1)[1], i


def test_bad_life_cells_are_named_rows():
    text = (
        "bearing,load,speed,viscosity,reliability,eC,contamination,pressure_viscosity,roughness\n"
        "6205,1kN,,20,,,,,\n"
        "6205,1kN,3000,20,80,,,,\n"
        "6205,1kN,3000,20,,1.5,,,\n"
        "6205,1kN,3000,20,,,dirty,,\n"
        "6205,1kN,3000,20,,,,500,\n"
        "6205,1kN,3000,20,,,,,0.2\n"
        "6205,1kN,-5,,,,,,\n"
        "6205,1kN,3000,20,,,,,\n"
    )
    out = _batch(text, "--format", "csv")
    assert out.exit_code == 1
    errors = out.stderr.splitlines()
    assert errors[0].startswith("Skipped: row 2: viscosity: needs the shaft speed")
    assert errors[1].startswith("Skipped: row 3: reliability: must be in [90, 99.95]")
    assert errors[2].startswith("Skipped: row 4: eC: must be in [0, 1]")
    assert errors[3].startswith("Skipped: row 5: contamination: 'dirty' is not one of")
    assert errors[4].startswith("Skipped: row 6: pressure_viscosity: must be in [1, 100]")
    assert errors[5].startswith("Skipped: row 7: roughness: a bare 0.2 is 0.2 mm, implausible")
    assert errors[6].startswith("Skipped: row 8: speed: must be greater than 0 rpm")
    assert [r["row"] for r in _rows(out.stdout)] == ["9"]


def test_life_cells_solve_refuses_skip_their_row_only():
    """Each of these rows ended the whole batch (exit 2, nothing written): the check that
    refuses them in solve ran over the whole call."""
    text = (
        "bearing,load,speed,viscosity,eC,contamination,fatigue_load_limit,roughness\n"
        "6205,1kN,3000,,0.5,,,\n"
        "6205,1kN,3000,,,high,,\n"
        "6205,1kN,3000,,,,300N,\n"
        "6205,1kN,3000,,,,,0.2um\n"
        "6205,1kN,3000,20,0.5,high,,\n"
        "6205,1kN,3000,20,,,,1e-310mm\n"
        "6205,1kN,3000,20,,,,1mm\n"
        "6205,1kN,3000,20,,,,\n"
    )
    out = _batch(text, "--format", "csv")
    assert out.exit_code == 1
    errors = out.stderr.splitlines()
    for row, name in enumerate(("eC", "contamination", "fatigue_load_limit", "roughness"), 2):
        assert errors[row - 2].startswith(f"Skipped: row {row}: {name}: feeds the modified life")
    assert errors[4].startswith("Skipped: row 6: eC: give a contamination level or e_C, not both")
    assert errors[5].startswith("Skipped: row 7: roughness: must lie between 1e-07 and 0.1 mm")
    assert errors[6].startswith("Skipped: row 8: roughness: must lie between 1e-07 and 0.1 mm")
    assert [r["row"] for r in _rows(out.stdout)] == ["9"]
    for cells in (
        "--eC 0.5",
        "--contamination high",
        "--fatigue-load-limit 300N",
        "--roughness 0.2um",
    ):  # solve refuses each of them too
        assert _solve(["6205", "-F", "1kN", "--speed", "3000", *cells.split()]).exit_code == 2


def test_pressure_viscosity_without_a_viscosity_is_refused_as_in_solve():
    """alpha feeds only the film, which needs the viscosity: it was silently ignored by solve
    (--pressure-viscosity 5 without --viscosity printed no film and no error) and by batch."""
    out = _solve(["6205", "-F", "1kN", "--speed", "3000", "--pressure-viscosity", "5"])
    assert out.exit_code == 2
    assert "Invalid value for '--pressure-viscosity': feeds the film" in out.stderr
    text = "bearing,load,speed,viscosity,pressure_viscosity\n6205,1kN,3000,,5\n6205,1kN,3000,20,5\n"
    out = _batch(text, "--format", "csv")
    assert out.exit_code == 1
    assert out.stderr.startswith("Skipped: row 2: pressure_viscosity: feeds the film, which needs")
    assert [r["row"] for r in _rows(out.stdout)] == ["3"]


def test_a_ring_by_hand_refuses_life_cells():
    out = _batch("balls,stiffness,load,speed\n8,1e5,1kN,3000\n", "--format", "csv")
    assert out.exit_code == 1
    assert "speed: needs a bearing designation or the ball geometry" in out.stderr


def test_a_speed_whose_hours_overflow_skips_its_row_only():
    """solve refuses --speed 1e-310 (L 10^6/(60 n) overflows); in batch that refusal ended the
    whole file (exit 2, only the header written). Now the row is skipped with solve's reason and
    the others are written as without it, radial and combined."""
    for head, cells in (("bearing,load,speed,viscosity", "6205,2kN"),
                        ("bearing,load,axial_load,speed,viscosity", "7205B,2kN,1kN")):  # fmt: skip
        good = f"{cells},1500,20\n{cells},3000,\n"
        text = f"{head}\n{cells},1e-310,20\n{good}{cells},1e-310,\n"
        out = _batch(text, "--format", "csv")
        assert out.exit_code == 1
        errors = besides_tilt(out.stderr)
        assert errors[0] == "Skipped: row 2: speed: is so small that the life in hours " + (
            "L 10^6/(60 n) overflows"
        )
        assert errors[1].startswith("Skipped: row 5: speed: is so small")
        assert _solve(["6205", "-F", "1kN", "--speed", "1e-310"]).exit_code == 2
        alone = _rows(_batch(f"{head}\n{good}", "--format", "csv").stdout)
        got = _rows(out.stdout)
        assert [r["row"] for r in got] == ["3", "4"]
        assert [{k: v for k, v in r.items() if k != "row"} for r in got] == [
            {k: v for k, v in r.items() if k != "row"} for r in alone
        ]
