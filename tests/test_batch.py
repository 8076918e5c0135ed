"""``bearingload batch``: exact output, units, stdin, bad rows, --strict, -o, chunks, solve parity."""

from __future__ import annotations

import csv
import io
import json
import os
import re

import numpy as np
import pytest
from click.testing import CliRunner

from bearingload.cli import main
from bearingload.reports.render import Column, _machine_text, csv_block

from .cli_helpers import SolvedRows, run_entry, solved_csv

SMALL = """\
balls,load [kgf],stiffness,clearance,cage_angle
8,300,4700kgf/mm^1.5,20um,0
12,5000N,3.8e5,-50um,half
"""

SMALL_CSV = """\
row,method,balls,load [N],stiffness [N/mm^1.5],clearance [mm],cage_angle [°],exponent,q_max [N],k,K_Q,loaded_balls,load_zone [°],x [mm],y [mm],stiffness_radial [N/mm],approach_max [mm],valid,stiffness_matrix_11 [N/mm],stiffness_matrix_12 [N/mm],stiffness_matrix_13 [N/mm],stiffness_matrix_14 [N/rad],stiffness_matrix_15 [N/rad],stiffness_matrix_21 [N/mm],stiffness_matrix_22 [N/mm],stiffness_matrix_23 [N/mm],stiffness_matrix_24 [N/rad],stiffness_matrix_25 [N/rad],stiffness_matrix_31 [N/mm],stiffness_matrix_32 [N/mm],stiffness_matrix_33 [N/mm],stiffness_matrix_34 [N/rad],stiffness_matrix_35 [N/rad],stiffness_matrix_41 [N mm/mm],stiffness_matrix_42 [N mm/mm],stiffness_matrix_43 [N mm/mm],stiffness_matrix_44 [N mm/rad],stiffness_matrix_45 [N mm/rad],stiffness_matrix_51 [N mm/mm],stiffness_matrix_52 [N mm/mm],stiffness_matrix_53 [N mm/mm],stiffness_matrix_54 [N mm/rad],stiffness_matrix_55 [N mm/rad]
2,exact,8,2941.995,46091.255,0.02,0.0,1.5,1640.74899,0.5576994489,2.230797796,3,85.14740553,0.1182137403,0.0,41498.22827,0.1082137403,True,41498.22827,0.0,,,,0.0,18755.05832,,,,,,,,,,,,,,,,,,
3,exact,12,5000.0,380000.0,-0.05,15.0,1.5,2379.275159,0.4758550318,2.855130191,12,180.0,0.009287385775,0.0,533484.305,0.03397092578,True,533484.305,0.0,,,,0.0,538364.629,,,,,,,,,,,,,,,,,,
"""

SMALL_MARKDOWN = """\
### 2 cases (row: the input file's row, the header is row 1)

| row | method | balls | load [N] | stiffness [N/mm^1.5] | clearance [mm] | cage_angle [°] | exponent [-] | q_max [N] |    k [-] | K_Q [-] | loaded_balls | load_zone [°] |     x [mm] | y [mm] | stiffness_radial [N/mm] | approach_max [mm] | valid | stiffness_matrix_11 [N/mm] | stiffness_matrix_12 [N/mm] | stiffness_matrix_13 [N/mm] | stiffness_matrix_14 [N/rad] | stiffness_matrix_15 [N/rad] | stiffness_matrix_21 [N/mm] | stiffness_matrix_22 [N/mm] | stiffness_matrix_23 [N/mm] | stiffness_matrix_24 [N/rad] | stiffness_matrix_25 [N/rad] | stiffness_matrix_31 [N/mm] | stiffness_matrix_32 [N/mm] | stiffness_matrix_33 [N/mm] | stiffness_matrix_34 [N/rad] | stiffness_matrix_35 [N/rad] | stiffness_matrix_41 [N mm/mm] | stiffness_matrix_42 [N mm/mm] | stiffness_matrix_43 [N mm/mm] | stiffness_matrix_44 [N mm/rad] | stiffness_matrix_45 [N mm/rad] | stiffness_matrix_51 [N mm/mm] | stiffness_matrix_52 [N mm/mm] | stiffness_matrix_53 [N mm/mm] | stiffness_matrix_54 [N mm/rad] | stiffness_matrix_55 [N mm/rad] |
|----:|:-------|------:|---------:|---------------------:|---------------:|---------------:|-------------:|----------:|---------:|--------:|-------------:|--------------:|-----------:|-------:|------------------------:|------------------:|:------|---------------------------:|---------------------------:|---------------------------:|----------------------------:|----------------------------:|---------------------------:|---------------------------:|---------------------------:|----------------------------:|----------------------------:|---------------------------:|---------------------------:|---------------------------:|----------------------------:|----------------------------:|------------------------------:|------------------------------:|------------------------------:|-------------------------------:|-------------------------------:|------------------------------:|------------------------------:|------------------------------:|-------------------------------:|-------------------------------:|
|   2 | exact  |     8 |  2941.99 |              46091.3 |      0.0200000 |              0 |      1.50000 |   1640.75 | 0.557699 | 2.23080 |            3 |       85.1474 |   0.118214 |      0 |                 41498.2 |          0.108214 | True  |                    41498.2 |                          0 |                            |                             |                             |                          0 |                    18755.1 |                            |                             |                             |                            |                            |                            |                             |                             |                               |                               |                               |                                |                                |                               |                               |                               |                                |                                |
|   3 | exact  |    12 |  5000.00 |               380000 |     -0.0500000 |        15.0000 |      1.50000 |   2379.28 | 0.475855 | 2.85513 |           12 |       180.000 | 0.00928739 |      0 |                  533484 |         0.0339709 | True  |                     533484 |                          0 |                            |                             |                             |                          0 |                     538365 |                            |                             |                             |                            |                            |                            |                             |                             |                               |                               |                               |                                |                                |                               |                               |                               |                                |                                |
"""


def batch(*args: str, stdin: str | None = None):
    return SolvedRows(
        CliRunner().invoke(main, ["batch", *args], input=stdin, catch_exceptions=False)
    )


@pytest.fixture
def small(tmp_path):
    path = tmp_path / "cases.csv"
    path.write_text(SMALL, encoding="utf-8")
    return str(path)


def test_csv_exact(small):
    out = batch(small, "--format", "csv")
    assert out.exit_code == 0
    assert out.stdout == SMALL_CSV
    assert out.stderr == ""


def test_markdown_exact(small):
    out = batch(small, "--format", "markdown")
    assert out.exit_code == 0
    assert out.stdout == SMALL_MARKDOWN


def test_table_exact(small):
    out = batch(small)
    assert out.exit_code == 0
    lines = out.stdout.splitlines()
    assert lines[0] == "2 cases (row: the input file's row, the header is row 1)"
    assert lines[2].split()[:4] == ["row", "method", "balls", "load"]
    assert [line.split()[0] for line in lines[4:]] == ["2", "3"]
    assert lines[4].split()[8] == "1640.75" and lines[5].split()[8] == "2379.28"


def test_json_exact(small):
    out = batch(small, "--format", "json")
    assert out.exit_code == 0
    doc = json.loads(out.stdout)
    assert [c["row"] for c in doc["cases"]] == [2, 3]
    assert doc["cases"][0]["q_max"] == 1640.74899
    assert doc["cases"][1]["cage_angle"] == 15.0
    assert doc["skipped"] == []
    assert doc["units"]["q_max"] == "N" and doc["units"]["stiffness"] == "N/mm^1.5"
    # the same numbers as the csv, key for key (null as an empty cell)
    rows = list(csv.DictReader(io.StringIO(SMALL_CSV)))
    for case, row in zip(doc["cases"], rows, strict=True):
        for head, text in row.items():
            value = case[head.split(" [")[0]]
            assert ("" if value is None else _machine_text(value)) == text


def test_units_in_headers_and_in_values(tmp_path):
    a = tmp_path / "a.csv"
    a.write_text("balls,load [kN],stiffness [kgf/mm^1.5],clearance [um]\n8,2.941995,4700,20\n")
    b = tmp_path / "b.csv"
    b.write_text("balls,load,stiffness,clearance\n8,300kgf,4700kgf/mm^1.5,0.02mm\n")
    c = tmp_path / "c.csv"  # a cell's own unit wins over the header's
    c.write_text("balls,load [kN],stiffness,clearance [um]\n8,300kgf,46091.255,0.02mm\n")
    outs = [batch(str(p), "--format", "csv") for p in (a, b, c)]
    assert all(o.exit_code == 0 for o in outs)
    assert outs[0].stdout == outs[1].stdout == outs[2].stdout
    assert outs[0].stdout.splitlines()[1] == SMALL_CSV.splitlines()[1]


def test_bad_header_unit_and_unknown_column_are_errors(tmp_path):
    p = tmp_path / "x.csv"
    p.write_text("balls,load [furlong],stiffness\n8,1,1\n")
    out = batch(str(p), "--format", "csv")
    assert out.exit_code == 2 and "furlong" in out.stderr and out.stdout == ""
    p.write_text("balls,load,stiffnes,colour\n8,1,1,red\n")
    out = batch(str(p), "--format", "csv")
    assert out.exit_code == 2
    assert "'stiffnes', 'colour'" in out.stderr and out.stdout == ""


def test_stdin(small):
    with open(small, encoding="utf-8") as fh:
        text = fh.read()
    out = batch("-", "--format", "csv", stdin=text)
    assert out.exit_code == 0 and out.stdout == SMALL_CSV


BAD = """\
balls,load,stiffness,clearance
8,300kgf,4700kgf/mm^1.5,20um
8,-5,4700kgf/mm^1.5,20um
0,300kgf,4700kgf/mm^1.5,20um
8,300kgf,4700kgf/mm^1.5,20furlong
8,300kgf,4700kgf/mm^1.5
12,5kN,3.8e5,-50um
"""


def test_bad_rows_named_and_good_rows_written(capsys, tmp_path):
    p = tmp_path / "bad.csv"
    p.write_text(BAD)
    code, out, err = run_entry(capsys, "batch", str(p), "--format", "csv")
    assert code == 1
    # every row in the output, the skipped ones with their reason in the last column
    assert [line.split(",")[0] for line in out.splitlines()] == [
        "row",
        "2",
        "3",
        "4",
        "5",
        "6",
        "7",
    ]
    assert out.splitlines()[2].endswith(",load: must be greater than 0 N (got -5 N)")
    assert err.splitlines() == [
        "Skipped: row 3: load: must be greater than 0 N (got -5 N)",
        "Skipped: row 4: balls: must be between 1 and 100000 (got 0)",
        "Skipped: row 5: clearance: unknown unit 'furlong' in '20furlong'; allowed: mm, um, µm, "
        "μm, in, m (a bare number is mm); or a clearance class C2, CN, C3, C4, C5 (GOST groups "
        "G6, G7, G8, G9)",
        "Skipped: row 6: malformed line: 3 cells, the header names 4 columns",
        "2 of 6 rows solved, 4 skipped (exit status 1), 0 warnings; the output names each "
        "skipped row and its reason",
    ]


def test_unknown_bearing_named(tmp_path):
    p = tmp_path / "b.csv"
    p.write_text("bearing,load\n306,300kgf\n9999,300kgf\n")
    out = batch(str(p), "--format", "csv")
    assert out.exit_code == 1
    assert out.stderr.startswith("Skipped: row 3: bearing: cannot read '9999'")
    assert [line.split(",")[0] for line in out.stdout.splitlines()] == ["row", "2"]


def test_strict_writes_nothing(tmp_path):
    p = tmp_path / "bad.csv"
    p.write_text(BAD)
    target = tmp_path / "out.csv"
    out = batch(str(p), "--strict", "--format", "csv", "-o", str(target))
    assert out.exit_code == 2
    assert "row 3: load: must be greater than 0 N (got -5 N)" in out.stderr
    assert not target.exists()
    assert os.listdir(tmp_path) == ["bad.csv"]  # no temporary file left behind
    out = batch(str(p), "--strict", "--format", "csv")
    assert out.exit_code == 2 and out.stdout == ""


def test_output_file_written_whole(small, tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old\n")
    out = batch(small, "--format", "csv", "-o", str(target))
    assert out.exit_code == 0 and out.stdout == ""
    assert solved_csv(target.read_text()) == SMALL_CSV
    p = tmp_path / "bad.csv"
    p.write_text(BAD)
    batch(str(p), "--strict", "--format", "csv", "-o", str(target))
    assert solved_csv(target.read_text()) == SMALL_CSV  # a failed run leaves the old file as it was


def _long_file(tmp_path, n=53):
    lines = ["balls,load,stiffness,clearance [um],cage_angle,method"]
    for i in range(n):
        bad = i % 17 == 5
        load = "-1" if bad else f"{100 + 37 * i}N"
        method = ("exact", "continuum", "stribeck")[i % 3] if i % 4 else ""
        lines.append(
            f"{5 + i % 11},{load},{1e5 + 1e3 * i},{(i % 9) - 3},{'half' if i % 2 else i},{method}"
        )
    p = tmp_path / "long.csv"
    p.write_text("\n".join(lines) + "\n")
    return str(p)


@pytest.mark.parametrize("fmt", ["csv", "json"])
def test_chunk_boundaries_do_not_change_the_bytes(tmp_path, fmt):
    p = _long_file(tmp_path)
    one = batch(p, "--format", fmt)
    assert one.exit_code == 1  # rows 7, 24, 41 have a negative load
    for size in (1, 4, 10):
        other = batch(p, "--format", fmt, "--chunk-size", str(size))
        assert other.stdout == one.stdout
        assert other.stderr == one.stderr


def test_chunks_of_any_size_give_the_same_bytes(tmp_path):
    """A last line without its line end, quotes (a cell read by the csv module) and a line that
    is not UTF-8 change nothing, whatever the chunk size (one row at a time included)."""
    p = _long_file(tmp_path)
    text = open(p, "rb").read()
    lines = text.splitlines(keepends=True)
    lines[20] = lines[20].replace(b",", b'"",', 1)
    lines[30] = lines[30][:-1] + b"\xff\n"
    variants = {"plain": text, "no last line end": text[:-1], "quoted": b"".join(lines)}
    for name, data in variants.items():
        q = tmp_path / f"{name}.csv"
        q.write_bytes(data)
        whole = batch(str(q), "--format", "csv")
        for size in ("1", "3", "4", "50"):
            part = batch(str(q), "--format", "csv", "--chunk-size", size)
            assert (part.stdout, part.stderr) == (whole.stdout, whole.stderr), (name, size)


def test_a_chunk_reads_only_its_own_lines():
    """The file is read chunk by chunk (memory flat however long it is): the first chunk of 7
    rows is given before the lines after it are read."""
    from bearingload.batch.read import read_cases

    read = [0]

    def lines():
        yield b"balls,load,stiffness\n"
        for i in range(10_000):
            read[0] += 1
            yield b"%d,8,1e5\n" % (i + 1)

    header, blocks = read_cases(lines(), 7)  # type: ignore[arg-type]
    first = next(blocks)
    assert header.names == ("balls", "load", "stiffness")
    assert first.numbers == list(range(2, 9)) and read[0] <= 8
    assert sum(len(b.numbers) for b in blocks) == 10_000 - 7 and read[0] == 10_000


def test_answer_does_not_depend_on_neighbours(tmp_path):
    p = _long_file(tmp_path)
    whole = batch(p, "--format", "csv").stdout.splitlines()
    lines = open(p).read().splitlines()
    for i in (1, 8, 30, 52):  # each row alone in its own file
        single = tmp_path / f"one{i}.csv"
        single.write_text(lines[0] + "\n" + lines[i] + "\n")
        out = batch(str(single), "--format", "csv").stdout.splitlines()
        row = next(r for r in whole if r.startswith(f"{i + 1},"))
        assert out[1].split(",")[1:] == row.split(",")[1:]


def _solve_csv(args: list[str]) -> dict[str, str]:
    """solve's csv row, every column with a value (solve writes every key of its JSON case,
    blank where null: the bearing columns of a ring given by hand, which batch writes only
    when its file can name a bearing)."""
    out = CliRunner().invoke(main, ["solve", *args, "--format", "csv"], catch_exceptions=False)
    assert out.exit_code == 0
    row = next(csv.DictReader(io.StringIO(out.stdout)))
    return {k: v for k, v in row.items() if v != ""}


def test_results_equal_solve_row_for_row():
    """examples/cases.csv against 'bearingload solve' with the same options, every column."""
    root = os.path.dirname(os.path.dirname(__file__))
    out = batch(os.path.join(root, "examples", "cases.csv"), "--format", "csv")
    assert out.exit_code == 0
    rows = list(csv.DictReader(io.StringIO(out.stdout)))
    solve_args = [
        ["-z", "8", "-F", "300kgf", "-K", "4700kgf/mm^1.5", "-G", "20um"],
        ["-z", "8", "-F", "300kgf", "-K", "4700kgf/mm^1.5", "-G", "20um", "--cage-angle", "half"],
        ["-z", "8", "-F", "300kgf", "-K", "4700kgf/mm^1.5", "-G", "20um", "--method", "continuum"],
        ["306", "-F", "300kgf", "-G", "C3"],
        ["306", "-F", "500kgf", "-G", "C3", "--cage-angle", "half"],
        ["6306", "-F", "3kN", "-G", "C2"],
        ["-z", "12", "-F", "5kN", "-K", "3.8e5", "-G", "-50um", "--cage-angle", "half"],
    ]
    assert len(rows) == len(solve_args)
    for row, args in zip(rows, solve_args, strict=True):
        expected = _solve_csv(args)
        for key, value in expected.items():
            # a file of bearings may mix ball and roller rows: its stiffness column is N/mm^m
            key_here = "stiffness [N/mm^m]" if key.startswith("stiffness [") else key
            assert row[key_here] == value, (args, key)
        others = [k for k in row if k not in expected and k not in ("row", "stiffness [N/mm^m]")]
        assert all(row[k] == "" for k in others)


def test_csv_block_matches_render():
    """The chunked csv writer gives the renderer's cells for awkward numbers."""
    from bearingload.reports.render import Column, Table, render

    values = [0.0, -0.0, 1e10, 9999999999.5, 1e16, 123456789012.0, 100.0, 1e-5, 5e-324, 2 / 3]
    cols = [Column("v", "v", "N", 6), Column("n", "n")]
    rows = [{"v": v, "n": i} for i, v in enumerate(values)]
    whole = render([Table("t", cols, rows)], "csv")
    block = csv_block(cols, {"v": values, "n": list(range(len(values)))})
    assert whole == "v [N],n\n" + block


def test_render_csv_is_csv_block():
    """Small tables (render) and long streamed ones (csv_block) write the same bytes: floats at
    ten digits as machine_number keeps them, text quoted where it must be, blanks, booleans."""
    from bearingload.reports.render import Column, Table, render

    awkward = [0.0, -0.0, 1.0, -1.0, 0.1, 1 / 3, 1.5, 100.0, 1e-4, 1e-5, 9.99999999995e-5, 1e9,
               1e10, 9999999999.5, 12345678905.0, 1e15, 1e16, 9.9999999995e15, 1e22, 1e-13,
               1e300, -1e-300, 5e-324, 1.7976931348623157e308, 0.30000000000000004, 123.456]  # fmt: skip
    cols = [Column("v", "v", "N", 6), Column("n", "n"), Column("t", "t"), Column("o", "o")]
    values = {
        "v": awkward,
        "n": list(range(len(awkward))),
        "t": ["x,y", 'q"', "plain"] * 8 + ["µm", ""],
        "o": [None, True, 3, 2.5] * 6 + ["z", -0.0],
    }
    rows = [dict(zip(values, r, strict=True)) for r in zip(*values.values(), strict=True)]
    whole = render([Table("t", cols, rows)], "csv")
    assert whole == "v [N],n,t,o\n" + csv_block(cols, values)
    assert whole == "v [N],n,t,o\n" + csv_block(cols, {"v": np.array(awkward)} | {
        k: values[k] for k in "nto"})  # fmt: skip
    assert '"x,y"' in whole and '"q"""' in whole
    lines = whole.splitlines()[1:]
    assert [line.split(",")[0] for line in lines] == [_machine_text(v) for v in awkward]
    assert [float(line.split(",")[0]) for line in lines] == [float(f"{v:.10g}") for v in awkward]


def test_text_cells_read_back_as_written():
    """A text cell with a comma, a quote, LF or CR (an oil's name echoed as given) reads back
    whole: a CR was written unquoted, and a csv reader then ended the record there."""
    texts = ["ISO VG\r68", "a\r\nb", "x\ny", 'q"', "p,q", "plain"]
    block = csv_block([Column("t", "t"), Column("n", "n")], {"t": texts, "n": [1] * 6})
    assert list(csv.reader(io.StringIO(block, newline=""))) == [[t, "1"] for t in texts]


def test_integers_and_constant_columns():
    v = np.array([0, -1, 7, 10, 99, 100, -123456789, 9999999999, 2**62, -(2**62)])
    assert csv_block([Column("i", "i")], {"i": v}).splitlines() == [str(x) for x in v.tolist()]
    for constant in (np.full(3, 1.5), np.full(3, -0.0), np.array([0.0, -0.0, 0.0])):
        assert csv_block([Column("f", "f")], {"f": constant}).splitlines() == [
            _machine_text(x) for x in constant.tolist()
        ]


def test_non_finite_refused_with_its_column():
    cols = [Column("a", "a"), Column("b", "b")]
    with pytest.raises(ValueError, match="non-finite number in column 'b'"):
        csv_block(cols, {"a": [1.0, 2.0], "b": np.array([1.0, np.inf])})
    with pytest.raises(ValueError, match="non-finite number in column 'a'"):
        csv_block(cols, {"a": [1.0, float("nan")], "b": np.array([1.0, 2.0])})


def test_negative_zero_beside_a_blank_cell_keeps_its_sign():
    """A list column with a None beside -0.0 wrote 0.0 (the blank's filler was 'v or 0');
    the same column without the None writes -0.0, as the renderer does one value at a time."""
    cols = [Column("v", "v")]
    assert csv_block(cols, {"v": [-0.0, None, 1.5]}) == "-0.0\n\n1.5\n"
    assert csv_block(cols, {"v": [-0.0, 1.5]}) == f"{_machine_text(-0.0)}\n1.5\n"
    assert csv_block(cols, {"v": np.array([-0.0, 1.5])}) == "-0.0\n1.5\n"


def test_held_formats_refuse_above_their_limit(tmp_path, monkeypatch):
    import bearingload.batch.report as report

    monkeypatch.setattr(report, "MAX_HELD_ROWS", 10)
    p = _long_file(tmp_path, n=30)
    target = tmp_path / "out.json"
    out = batch(p, "--format", "json", "--chunk-size", "4", "-o", str(target))
    assert out.exit_code == 2 and "at most 10 rows" in out.stderr
    assert not target.exists()
    assert (
        batch(p, "--format", "csv", "--chunk-size", "4").stdout.count("\n") == 29
    )  # 28 rows + header


def test_header_only_file_writes_the_header(tmp_path):
    p = tmp_path / "empty.csv"
    p.write_text("balls,load,stiffness\n")
    out = batch(str(p), "--format", "csv")
    assert out.exit_code == 0
    assert out.stdout.startswith("row,method,balls,load [N]") and out.stdout.count("\n") == 1


def test_a_row_that_breaks_the_vectorised_solve_is_named_alone(tmp_path):
    """z = 2 with no ball on the load line passes the input checks but has no equilibrium: the
    chunk is solved row by row, that row is named, its neighbours are written unchanged."""
    p = tmp_path / "c.csv"
    p.write_text("balls,load,stiffness,cage_angle\n8,1kN,1e5,0\n2,1kN,1e5,45\n9,1kN,1e5,17\n")
    out = batch(str(p), "--format", "csv")
    assert out.exit_code == 1
    assert out.stderr.splitlines()[0].startswith("Skipped: row 3: cage_angle: with 1 or 2 balls")
    rows = out.stdout.splitlines()
    assert [r.split(",")[0] for r in rows] == ["row", "2", "4"]
    alone = tmp_path / "a.csv"
    alone.write_text("balls,load,stiffness,cage_angle\n9,1kN,1e5,17\n")
    assert batch(str(alone), "--format", "csv").stdout.splitlines()[1][1:] == rows[2][1:]


def test_geometry_and_overrides_equal_solve(tmp_path):
    """Ball geometry by hand, a catalogue bearing with overrides, clearance picks, a roller
    exponent: each row equals 'bearingload solve' with the same options."""
    p = tmp_path / "g.csv"
    p.write_text(
        "bearing,balls,load,stiffness,ball_diameter,pitch_diameter,inner_conformity,modulus,"
        "clearance,clearance_pick,cage_angle,exponent,revolutions\n"
        ",7,1kN,,11.5,43.5,,,10um,,0,,\n"
        "6205,,1.4kN,,,,0.515,2.1e4kgf/mm^2,C3,max,half,,1e8\n"
        "306,,300kgf,5e5,,,,,C4,min,7,,\n"
        ",14,10kN,8e5,,,,,-5um,,0,10/9,\n"
    )
    out = batch(str(p), "--format", "csv")
    assert out.exit_code == 0, out.stderr
    rows = list(csv.DictReader(io.StringIO(out.stdout)))
    solve_args = [
        ["-z", "7", "-F", "1kN", "--ball-diameter", "11.5", "--pitch-diameter", "43.5", "-G", "10um"],
        ["6205", "-F", "1.4kN", "--inner-conformity", "0.515", "--modulus", "2.1e4kgf/mm^2",
         "-G", "C3", "--clearance-pick", "max", "--cage-angle", "half", "--revolutions", "1e8"],
        ["306", "-F", "300kgf", "-K", "5e5", "-G", "C4", "--clearance-pick", "min",
         "--cage-angle", "7"],
        ["-z", "14", "-F", "10kN", "-K", "8e5", "-G", "-5um", "-m", "10/9"],
    ]  # fmt: skip
    for row, args in zip(rows, solve_args, strict=True):
        expected = _solve_csv(args)
        for key, value in expected.items():
            head = re.sub(r"N/mm\^[0-9.]+", "N/mm^m", key)
            assert row[head] == value, (args, key)


def test_static_safety_and_reference_life_equal_solve(tmp_path):
    """s0 = C0/F_r (ISO 76) and L10r (ISO/TS 16281) of radial rows equal solve's, blank where
    solve leaves them out: no C_r (geometry by hand), not the exact model, a roller bearing."""
    p = tmp_path / "s.csv"
    p.write_text(
        "bearing,load,ball_diameter,pitch_diameter,balls,clearance,cage_angle,method\n"
        "6205,1.4kN,,,,C3,,\n"
        "6205,2kN,,,,-5um,half,\n"
        "6205,1.4kN,,,,C3,,continuum\n"
        "6306,3kN,,,,C2,,\n"
        "NU206,5kN,,,,,,\n"
        ",1kN,11.5,43.5,7,10um,,\n"
    )
    out = batch(str(p), "--format", "csv")
    assert out.exit_code == 0, out.stderr
    rows = list(csv.DictReader(io.StringIO(out.stdout)))
    solve_args = [
        ["6205", "-F", "1.4kN", "-G", "C3"],
        ["6205", "-F", "2kN", "-G", "-5um", "--cage-angle", "half"],
        ["6205", "-F", "1.4kN", "-G", "C3", "--method", "continuum"],
        ["6306", "-F", "3kN", "-G", "C2"],
        ["NU206", "-F", "5kN"],
        ["-z", "7", "-F", "1kN", "--ball-diameter", "11.5", "--pitch-diameter", "43.5", "-G", "10um"],
    ]  # fmt: skip
    life, s0 = "reference_rating_life [10^6 rev]", "static_safety"
    for row, args in zip(rows, solve_args, strict=True):
        expected = _solve_csv(args)
        for key in (life, s0, "rotating"):
            assert row[key] == expected.get(key, ""), (args, key)
    assert [bool(r[life]) for r in rows] == [True, True, False, True, False, False]
    assert [r["rotating"] for r in rows] == ["inner", "inner", "", "inner", "", ""]
    assert [bool(r[s0]) for r in rows] == [True, True, True, True, True, False]


def test_a_line_not_utf8_is_a_bad_row_named_by_its_number(tmp_path):
    """A line that is not UTF-8 is skipped and named (row and byte), the others are solved;
    the same whichever path reads the block (bare numbers, units, quotes)."""
    for first, second in (("8,1000,1e5", "9,1000,1e5"), ("8,1kN,1e5", '"9",1kN,1e5')):
        p = tmp_path / "latin.csv"
        p.write_bytes(
            f"balls,load,stiffness\n{first}\n".encode() + b"8,1kN,1e5\xff\n"
            + f"{second}\n".encode()
        )  # fmt: skip
        out = batch(str(p), "--format", "csv", "--chunk-size", "2")
        assert out.exit_code == 1
        assert [line.split(",")[0] for line in out.stdout.splitlines()] == ["row", "2", "4"]
        assert out.stderr.splitlines()[0] == (
            "Skipped: row 3: not UTF-8 text (invalid start byte at byte 10 of the line)"
        )


def test_a_header_not_utf8_is_an_error_and_writes_nothing(tmp_path):
    p = tmp_path / "latin.csv"
    p.write_bytes(b"balls,load \xb5,stiffness\n8,1kN,1e5\n")
    target = tmp_path / "out.csv"
    out = batch(str(p), "--format", "csv", "-o", str(target))
    assert out.exit_code == 2 and "not UTF-8 text" in out.stderr
    assert not target.exists() and sorted(os.listdir(tmp_path)) == ["latin.csv"]


def test_line_ends_and_byte_order_mark(tmp_path):
    """CR LF line ends and a UTF-8 byte order mark read as LF; CR alone is refused."""
    expected = batch("-", "--format", "csv", stdin="balls,load,stiffness\n8,1kN,1e5\n").stdout
    p = tmp_path / "crlf.csv"
    p.write_bytes(b"\xef\xbb\xbfballs,load,stiffness\r\n8,1kN,1e5\r\n")
    assert batch(str(p), "--format", "csv").stdout == expected
    p.write_bytes(b"balls,load,stiffness\r8,1kN,1e5\r")
    out = batch(str(p), "--format", "csv")
    assert out.exit_code == 2 and "CR alone" in out.stderr


def test_roller_bearing_rows_are_solved_as_rollers(tmp_path):
    """A catalogue roller bearing in a batch is the same case as 'solve NU206': line contact
    (m = 10/9), line-contact pressures, the roller life exponent 10/3."""
    f = tmp_path / "rollers.csv"
    f.write_text("bearing,load\nNU206,5kN\n")
    out = batch(str(f), "--format", "csv")
    assert out.exit_code == 0
    (row,) = list(csv.DictReader(io.StringIO(out.stdout)))
    expected = _solve_csv(["NU206", "-F", "5kN"])
    for key in ("exponent", "q_max [N]", "x [mm]", "p_max_inner [MPa]", "rating_life [10^6 rev]"):
        assert row[key] == expected[key], key


def test_implausible_bare_numbers_are_refused_as_solve_refuses_them(tmp_path):
    f = tmp_path / "bare.csv"
    f.write_text("balls,load,stiffness,clearance\n8,300,1e5,20\n8,300,1e5,20um\n")
    out = batch(str(f), "--format", "csv")
    assert out.exit_code == 1
    assert "row 2: clearance: a bare 20 is 20 mm, implausible" in out.stderr
    assert len(list(csv.DictReader(io.StringIO(out.stdout)))) == 1


def test_rows_carry_the_checks_of_solve(tmp_path):
    """A catalogue row beyond its static rating and a ring with one loaded ball warn, on stderr
    and in json, as 'solve' does; a sane row carries no warning."""
    f = tmp_path / "checks.csv"
    f.write_text(
        "bearing,balls,load,stiffness,clearance\n306,,50kN,,\n,8,300,1e5,0.99mm\n306,,300kgf,,\n"
    )
    out = batch(str(f), "--format", "json")
    assert out.exit_code == 0
    cases = json.loads(out.stdout)["cases"]
    assert any("static safety factor" in w for w in cases[0]["warnings"])
    assert cases[1]["warnings"] == [
        "only one ball carries the load: the result hangs on a single contact (large clearance or "
        "few elements); check the clearance"
    ]
    assert cases[2]["warnings"] == []
    assert "Warning: row 2: static safety factor" in out.stderr
    assert "Warning: row 3: only one ball carries the load" in out.stderr


def test_bare_number_blocks_and_parsed_blocks_agree(tmp_path):
    """A block of bare numbers is read by numpy at once, a block with a unit, a quote or a
    blank line cell by cell: the same cases give the same bytes either way."""
    import numpy as np

    rng = np.random.default_rng(7)
    rows = [
        (int(rng.integers(3, 40)), float(rng.uniform(1, 1e4)), float(10 ** rng.uniform(4, 6)),
         float(rng.choice([0.0, rng.uniform(-0.01, 0.05)])), float(rng.uniform(0, 30)))
        for _ in range(40)
    ]  # fmt: skip
    head = "balls,load [N],stiffness,clearance [mm],cage_angle\n"
    plain = head + "".join(",".join(repr(v) for v in r) + "\n" for r in rows)
    lines = plain.splitlines(keepends=True)
    lines[1] = lines[1].replace(",", "N,", 2).replace("N,", ",", 1)  # load '...N': a unit
    lines[12] = '"' + lines[12].replace(",", '",', 1)  # a quoted cell from here on
    lines.insert(5, "\n")  # a blank line (row numbers move on)
    mixed = "".join(lines)
    a = batch("-", "--format", "csv", "--chunk-size", "10", stdin=plain)
    b = batch("-", "--format", "csv", "--chunk-size", "10", stdin=mixed)
    assert a.exit_code == b.exit_code == 0, (a.stderr, b.stderr)

    def cases(out: str) -> list[str]:
        return [line.split(",", 1)[1] for line in out.splitlines()[1:]]

    assert cases(a.stdout) == cases(b.stdout)
    numbers = [int(line.split(",")[0]) for line in b.stdout.splitlines()[1:]]
    assert numbers == [*range(2, 6), *range(7, 43)]


def test_a_maker_column_is_solve_maker():
    """Every input of a case is a column (the readers of plan.inputs): a ``maker`` cell picks
    that maker's ball set as ``solve --maker`` does (GMN's 6205 has another Hertz stiffness
    than NSK's); a maker without a ball set for the bearing is a skipped row naming it."""
    out = batch("-", "--format", "json", stdin="bearing,maker,load\n6205,GMN,1kN\n6205,,1kN\n")
    cases = json.loads(out.stdout)["cases"]
    for case, maker in zip(cases, ("GMN", "NSK"), strict=True):
        alone = CliRunner().invoke(
            main, ["solve", "6205", "--maker", maker, "-F", "1kN", "--format", "json"]
        )
        expected = json.loads(alone.output)["cases"][0]
        assert (case["stiffness"], case["q_max"]) == (expected["stiffness"], expected["q_max"])
    assert cases[0]["stiffness"] != cases[1]["stiffness"]
    out = batch("-", "--format", "csv", stdin="bearing,maker,load\n6205,skf,1kN\n")
    assert out.exit_code == 1 and "Skipped: row 2: maker: no skf ball set for 6205" in out.stderr
