"""``bearingload batch``: how the rows of a file are read, refused and named, the same whatever the
chunk size and the other rows (bare-number columns, underscores, quotes, empty cells, a row
failing alone, the order of the warnings, a roller row's stiffness)."""

from __future__ import annotations

import csv
import io

import pytest
from click.testing import CliRunner

from bearingload.cli import main

from .cli_helpers import SolvedRows


def _run(*args: str, stdin: str | None = None):
    return CliRunner().invoke(main, list(args), input=stdin)


def _batch(text: str, *args: str):
    return SolvedRows(_run("batch", "-", "--format", "csv", *args, stdin=text))


def _csv_values(text: str, line: int = 1) -> dict[str, str]:
    """The non-blank cells of one csv data line by column, stiffness units as 'N/mm^m'."""
    import csv
    import io
    import re

    row = list(csv.DictReader(io.StringIO(text)))[line - 1]
    return {re.sub(r"N/mm\^[0-9.()/]+", "N/mm^m", k): v for k, v in row.items() if v != ""}


def _solved_in(batch_text: str, solve_text: str, line: int = 1) -> bool:
    """Every value of solve's csv row is in batch's row ``line`` (the same column)."""
    got, expected = _csv_values(batch_text, line), _csv_values(solve_text)
    return all(got.get(k) == v for k, v in expected.items())


def test_an_exponent_column_of_bare_numbers_is_read():
    """A file of bare numbers with an 'exponent' column went through the numbers-only reader,
    which looked up the exponent column before it had read it: 'internal error (KeyError:
    'exponent')', exit 1, for the simplest such file."""
    text = "balls,load,stiffness,exponent\n8,1000,46000,1.5\n8,1000,46000,10/9\n"
    for chunk in ("1", "100"):
        r = _batch(text, "--chunk-size", chunk)
        assert r.exit_code == 0, r.output
        assert "internal error" not in r.output
    alone = _run("solve", "-z", "8", "-F", "1000", "-K", "46000", "--exponent", "1.5",
                 "--format", "csv")  # fmt: skip
    rows = _batch(text).stdout.splitlines()
    assert _solved_in(_batch(text).stdout, alone.stdout)
    assert rows[1].split(",")[0] == "2"
    # a header unit of another exponent: that row named, not the whole run ended (exit 2)
    mixed = "balls,load,stiffness [N/mm^(10/9)],exponent\n8,1000,46000,1.5\n8,1000,46000,10/9\n"
    for chunk in ("1", "100"):
        r = _batch(mixed, "--chunk-size", chunk)
        assert r.exit_code == 1, r.output
        assert r.stderr.startswith("Skipped: row 2: stiffness: the unit 'N/mm^(10/9)'")
        assert [line.split(",")[0] for line in r.stdout.splitlines()[1:]] == ["3"]


@pytest.mark.parametrize("chunk", ["1", "3", "100"])
def test_a_number_with_underscores_is_refused_whatever_the_other_rows(chunk):
    """'1_000' is refused by solve (--load 1_000: unknown unit '_000'); batch accepted it as
    1000 N when every other load cell of its chunk was a bare number (numpy, like Python's
    float, reads underscores) and refused it otherwise, so the output hung on --chunk-size."""
    text = "balls,load,stiffness\n8,1_000,46000\n8,1kN,46000\n8,2000,46000\n"
    r = _batch(text, "--chunk-size", chunk)
    assert r.exit_code == 1
    assert "row 2: load" in r.stderr
    assert [line.split(",")[0] for line in r.stdout.splitlines()[1:]] == ["3", "4"]
    with_unit = "balls,load [kN],stiffness,cage_angle [deg]\n8,1_0,46000,0\n8,1,46000,1_0\n"
    r = _batch(with_unit, "--chunk-size", chunk)
    assert "row 2: load" in r.stderr and "row 3: cage_angle" in r.stderr
    assert r.stdout.splitlines()[1:] == []


def test_a_skipped_row_names_the_column_not_the_library_parameter():
    """A combined row without any load was skipped as 'radial_load: give a radial load ...':
    a batch file has no column radial_load (its column is load), as solve names --load."""
    r = _batch("bearing,load,axial_load\n6205,0,0\n6205,1kN,0\n")
    assert r.exit_code == 1
    assert r.stderr.startswith(
        "Skipped: row 2: load: give a radial load, an axial load or a moment"
    )


@pytest.mark.parametrize("chunk", ["1", "2", "100"])
def test_a_quote_never_closed_is_named_where_it_opens(chunk):
    """An unclosed quote made the csv reader take every line to the end of the file into one
    cell; batch then named the LAST line, 'row 6: malformed line: 2 cells', and rows 4 and 5
    vanished without a word. Now the row where the quote opens is named, with the span."""
    text = 'balls,load,stiffness\n8,1000,46000\n8,"1000,46000\n8,1000,46000\n8,1000,46000\n'
    r = _batch(text, "--chunk-size", chunk)
    assert r.exit_code == 1
    assert r.stderr.startswith(
        "Skipped: row 3: a quote opened in this row is never closed: rows 3 to 5 (the end of "
        "the file) were read as one cell"
    )
    assert [line.split(",")[0] for line in r.stdout.splitlines()[1:]] == ["2"]


@pytest.mark.parametrize("end", ["\n", ""])
def test_a_quote_never_closed_on_the_last_line_is_refused(end):
    """A quote opened on the file's last line and never closed was solved as if closed
    ('6205,"1000' as 1000 N); the row is refused, as csv's strict mode refuses the data."""
    r = _batch(f'bearing,load\n6205,1kN\n6205,"1000{end}')
    assert r.exit_code == 1
    assert r.stderr.startswith(
        "Skipped: row 3: a quote opened in this row is never closed: the file ends in its cell"
    )
    assert [line.split(",")[0] for line in r.stdout.splitlines()[1:]] == ["2"]


@pytest.mark.parametrize("chunk", ["1", "2", "100"])
def test_a_record_over_several_lines_is_named_by_its_first_line(chunk):
    """A quoted cell holding a line break makes one record of two lines. It was named by its
    LAST line (row 3 below), where an engineer looking for it in an editor or a spreadsheet
    finds the next case; it is named by the line where it starts, and the rows after it keep
    their line numbers (docs/batch.md)."""
    bad = 'balls,load,stiffness\n8,"10\n00",46000\n8,"2000",46000\n'
    r = _batch(bad, "--chunk-size", chunk)
    assert r.stderr.startswith("Skipped: row 2: load: unknown unit '00'")
    assert [row[0] for row in list(csv.reader(io.StringIO(r.result.stdout)))[1:]] == ["2", "4"]
    good = 'balls,load,stiffness\n8,1000,46000\n8,1000,"46000\n"\n\n8,2000,46000\n'
    r = _batch(good, "--chunk-size", chunk)  # a solved record of lines 3-4, a blank line 5
    assert r.exit_code == 0, r.stderr
    assert [row[0] for row in list(csv.reader(io.StringIO(r.result.stdout)))[1:]] == ["2", "3", "6"]


def test_an_empty_load_cell_says_the_load_is_missing():
    """An empty load cell of rings given by z and K was skipped as 'load: missing (give balls
    and stiffness, or a bearing)', advice that does not fit; rows of bearings said 'load:
    missing: every row needs a load'. Both now say the latter."""
    for text in ("balls,load,stiffness\n8,,46000\n", "bearing,load\n306,\n"):
        r = _batch(text)
        assert r.stderr.startswith("Skipped: row 2: load: missing: every row needs a load\n")


@pytest.mark.parametrize("chunk", ["1", "100"])
def test_a_row_failing_alone_in_its_method_or_chunk_is_named_not_fatal(chunk):
    """A row whose solve fails (a load too small for the rating life, a one-ball approach out
    of range) ended the whole run with 'Error: Invalid value for '--load': ...' (exit 2, the
    csv header already written) when it was the only row of its method or of its chunk: the
    row-by-row fallback re-raised for a single row. It is a skipped row like any other."""
    for text in (
        "load,bearing,method\n1e-300,306,stribeck\n1000,306,exact\n",
        "load,bearing\n1e-300,NU206\n1000,306\n",
    ):
        r = _batch(text, "--chunk-size", chunk)
        assert r.exit_code == 1, r.output
        assert r.stderr.startswith("Skipped: row 2: load: ")
        assert [line.split(",")[0] for line in r.stdout.splitlines()[1:]] == ["3"]


def test_stderr_is_in_row_order_whatever_the_chunk_size():
    """Within a chunk the skipped rows were printed before the checks' warnings, so with the
    default chunk 'row 4: ...' came before 'row 3: only one ball carries the load', and with
    --chunk-size 1 after it: standard error hung on --chunk-size."""
    text = "balls,bearing,load\n8,306,1000\n3,306,3\n0,306,-5\n"
    found = {c: _batch(text, "--chunk-size", c).stderr for c in ("1", "2", "100")}
    assert found["1"] == found["2"] == found["100"]
    assert found["1"].index("row 3:") < found["1"].index("row 4:")


def test_a_row_with_two_errors_names_the_same_one_whatever_the_chunk():
    """A balls cell of 8.5 was read by numpy without the whole-number check when its column
    was all bare numbers, so a row with two errors was named by one or the other depending
    on its neighbours ('stiffness: missing' or 'balls: must be a whole number'); and the
    row checks overwrote the parser's first error."""
    text = "load,balls,cage_angle\n0,9.5,0\n300kgf,,-400\n"  # (a load of 0: a row check)
    out = {c: _batch(text, "--chunk-size", c).stderr for c in ("1", "2")}
    assert out["1"] == out["2"]
    assert out["1"].startswith("Skipped: row 2: balls: must be a whole number, got '9.5'")


def test_batch_reads_a_roller_rows_stiffness_in_its_own_unit_beside_an_exponent_column():
    """With an 'exponent' column in the file, a roller row whose exponent cell is blank had its
    stiffness read in N/mm^1.5: '4700kgf/mm^1.5' was taken (as kgf/mm^(10/9)) where solve
    refuses it, and '3e5N/mm^(10/9)' refused where solve takes it."""
    text = (
        "bearing,load,stiffness,exponent\n"
        "NU204,5kN,3e5N/mm^(10/9),\n"
        "NU204,5kN,4700kgf/mm^1.5,\n"
        "306,5kN,4e5N/mm^1.5,\n"
    )
    solved = _run("solve", "NU204", "-F", "5kN", "-K", "3e5N/mm^(10/9)", "--format", "csv")
    assert solved.exit_code == 0
    refused = _run("solve", "NU204", "-F", "5kN", "-K", "4700kgf/mm^1.5")
    assert refused.exit_code == 2
    for chunk in ("1", "100"):
        r = _batch(text, "--chunk-size", chunk)
        assert r.exit_code == 1, r.output
        assert [line.split(",")[0] for line in r.stdout.splitlines()[1:]] == ["2", "4"]
        assert r.stderr.startswith("Skipped: row 3: stiffness: the unit 'kgf/mm^1.5'")
        assert _csv_values(r.stdout)["q_max [N]"] == _csv_values(solved.stdout)["q_max [N]"]


@pytest.mark.parametrize("chunk", ["1", "100"])
def test_a_trailing_comma_in_the_header_is_an_empty_column_that_rows_may_leave_empty(chunk):
    """A spreadsheet's export 'balls,load,clearance,' (a trailing comma on every line) was
    refused as an unknown column ''. Its empty trailing column is accepted with its empty cells
    (with or without the trailing comma on a row); a value in it skips that row, named."""
    plain = _batch("balls,load,stiffness,clearance\n9,1000,1e5,0.01\n8,500,1e5,0\n", "--chunk-size",
                   chunk)  # fmt: skip
    trailing = _batch("balls,load,stiffness,clearance,\n9,1000,1e5,0.01,\n8,500,1e5,0\n",
                      "--chunk-size", chunk)  # fmt: skip
    assert plain.exit_code == trailing.exit_code == 0, trailing.output
    assert trailing.stdout == plain.stdout
    filled = _batch("balls,load,stiffness,clearance,,\n9,1000,1e5,0.01,,\n8,500,1e5,0, ,7\n",
                    "--chunk-size", chunk)  # fmt: skip
    assert filled.exit_code == 1
    assert filled.stderr.startswith(
        "Skipped: row 3: a value ('7') in a column the header gives no name (after its last "
        "column 'clearance')"
    )
    assert [line.split(",")[0] for line in filled.stdout.splitlines()[1:]] == ["2"]


def test_an_empty_column_name_inside_the_header_is_named(tmp_path, capsys):
    from .cli_helpers import run_entry

    path = tmp_path / "cases.csv"
    path.write_text("balls,,load\n9,1,1000\n", encoding="utf-8")
    code, out, err = run_entry(capsys, "batch", str(path))
    assert code == 2 and out == ""
    assert err.strip().splitlines() == [
        "Error: Invalid value for 'CASES.csv': the header's column 2 has no name (only empty "
        "columns at the end of the header are allowed, and their cells must be empty)"
    ]


def test_a_revolutions_cell_of_a_ball_set_without_c_skips_its_row_as_solve_refuses_it():
    """A ball set by its geometry without a dynamic_rating has no allowable load: its
    revolutions cell was ignored (empty revolutions and allowable_load, exit 0); solve refuses
    --revolutions there. With a dynamic_rating cell the row gives the allowable load."""
    head = "balls,ball_diameter,pitch_diameter,load,dynamic_rating,revolutions\n"
    r = _batch(head + "9,7.938,38.5,1000,,1e6\n9,7.938,38.5,1000,14kN,1e6\n")
    assert r.exit_code == 1, r.output
    assert r.stderr.startswith("Skipped: row 2: revolutions: "), r.stderr
    assert "dynamic_rating" in r.stderr.splitlines()[0]
    rows = _csv_values(r.stdout)
    assert rows["row"] == "3" and float(rows["allowable_load [N]"]) == pytest.approx(14000.0)


def test_a_revolutions_cell_is_read_as_solve_reads_revolutions():
    """A bare revolutions cell is revolutions, refused where implausible (a bare 36 meant 36
    million: solve says 'did you mean 36Mrev?'; 1e-308 gave an allowable load of 6.5e108 N) and
    its row skipped; '36Mrev' and a header unit '[Mrev]' give solve's allowable load."""
    import json

    bad = _run("batch", "-", stdin="bearing,load,revolutions\n6205,1kN,36\n6205,1kN,1e-308\n")
    assert bad.exit_code == 1
    assert "row 2: revolutions" in bad.stderr and "did you mean 36Mrev?" in bad.stderr
    assert "row 3: revolutions" in bad.stderr and "implausible" in bad.stderr
    want = json.loads(_run("solve", "6205", "-F", "1kN", "--revolutions", "36Mrev",
                           "--format", "json").stdout)["cases"][0]["allowable_load"]  # fmt: skip
    for text in ("bearing,load,revolutions\n6205,1kN,36Mrev\n",
                 "bearing,load,revolutions [Mrev]\n6205,1kN,36\n"):  # fmt: skip
        out = _run("batch", "-", "--format", "json", stdin=text)
        assert out.exit_code == 0, out.output
        assert json.loads(out.stdout)["cases"][0]["allowable_load"] == want


def test_a_bare_number_implausible_for_the_rows_bearing_skips_the_row_as_solve_refuses_it():
    """A bare load, axial load, moment or ball stiffness is judged against the row's bearing
    (bearings.plausible, solve's rule for its options): the row is skipped with solve's reason;
    the same number with a unit, in the cell or the header, is used as it is."""
    text = (
        "bearing,load,axial_load,moment,stiffness\n6205,3,,,\n6205,3kN,5,,\n6205,3kN,1kN,5,\n"
        "6205,3kN,,,4700\n6205,3N,,,\n6205,3kN,0,0,\n"
    )
    out = _batch(text)
    said = [line for line in out.stderr.splitlines() if "bare" in line]
    for row, name in enumerate(("load", "axial_load", "moment", "stiffness"), start=2):
        (line,) = [s for s in said if s.startswith(f"Skipped: row {row}: {name}: a bare ")]
        option = "--" + name.replace("_", "-")
        cells = {"load": "3", "axial_load": "5", "moment": "5", "stiffness": "4700"}
        solved = _run("solve", "6205", "-F", "3kN", option, cells[name])
        assert solved.exit_code == 2 and line.split(": ", 3)[3] in solved.output, solved.output
    assert [line.split(",", 1)[0] for line in out.stdout.splitlines()[1:]] == ["6", "7"]
    header = _batch("bearing,load [N]\n6205,3\n")
    assert header.exit_code == 0 and "bare" not in header.stderr


def test_the_clearance_pick_range_is_refused_with_the_plans_reason():
    """'range' solves three clearances side by side, which is solve's: a batch row (one output
    row per case) is skipped with the plan's reason, as sweep and table refuse it."""
    out = _batch("bearing,load,clearance,clearance_pick\n6205,1kN,C3,range\n6205,1kN,C3,max\n")
    assert out.exit_code == 1
    assert out.stderr.splitlines()[0] == (
        "Skipped: row 2: clearance_pick: 'range' (min, mean and max side by side) is solve's; "
        "batch takes min, mean or max"
    )
    assert [line.split(",", 1)[0] for line in out.stdout.splitlines()[1:]] == ["3"]


@pytest.mark.parametrize(
    ("column", "cells", "implausible"),
    [("modulus", ("2.1e5", "210", "-1"), "210"), ("revolutions", ("1e6", "36", "0"), "36")],
)
def test_an_implausible_bare_number_between_accepted_ones_is_refused(column, cells, implausible):
    """A modulus or revolutions of 0 or less passes the reader (the model refuses it), but a bare
    210 (GPa meant) or 36 (10^6 rev meant) is implausible: the acceptance is not one range, so
    a column whose smallest and largest cells the reader takes may hold a refused cell between
    them. It is refused as in a column of its own, not read as 210 MPa or 36 rev."""
    for chunk in ("1", "100"):
        text = f"bearing,load,{column}\n" + "".join(f"6205,1kN,{c}\n" for c in cells)
        out = _batch(text, "--chunk-size", chunk)
        assert out.exit_code == 1, out.output
        said = [line for line in out.stderr.splitlines() if line.startswith("Skipped: row 3:")]
        assert len(said) == 1 and f"{column}: a bare {implausible} is" in said[0], out.stderr
        assert [line.split(",", 1)[0] for line in out.stdout.splitlines()[1:]] == ["2"]


@pytest.mark.parametrize(("sep", "why"), [(";", "decimal commas"), ("\t", ""), ("|", "")])
def test_a_file_of_another_separator_is_refused_naming_it(capsys, tmp_path, sep, why):
    """A csv saved by a spreadsheet set to decimal commas separates its columns by ';': the
    header read as one column was refused as "unknown column(s) 'balls;load;stiffness'". The
    refusal names the separator and what batch reads (fit's too); the file with commas solves."""
    from .cli_helpers import error_line

    path = tmp_path / "cases.csv"
    path.write_text(f"{sep.join(('balls', 'load', 'stiffness'))}\n8{sep}1000{sep}1e5\n")
    line = error_line(capsys, "batch", str(path))
    assert "is one column: the columns of a csv are separated by commas" in line, line
    assert f"separates them by {sep!r}" in line and why in line, line
    assert _batch("balls,load,stiffness\n8,1000,1e5\n").exit_code == 0
    path.write_text("bogus\n8\n")
    assert "unknown column(s) 'bogus'" in error_line(capsys, "batch", str(path))
    path.write_text(f"load{sep}displacement\n1{sep}1\n2{sep}2\n")
    assert f"separates them by {sep!r}" in error_line(capsys, "fit", str(path))
