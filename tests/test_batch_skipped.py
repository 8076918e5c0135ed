"""``batch``'s skipped rows and its closing line: a skipped row is in the output (csv: its number
and its reason in the last column, ``skipped``; json: ``skipped``; table and markdown: the
notes), standard error names it on a ``Skipped:`` line apart from the ``Warning:`` lines of
the solved rows and ends on one line counting the rows solved and skipped and the
warnings, and ``-q`` leaves that line alone. Before, skip reasons and advisories shared one
``Warning:`` stream that a long file cut short ('3616 more warnings not shown'), and a csv
held the solved rows only."""

from __future__ import annotations

import csv
import io
import json

from .cli_helpers import run_entry

#: Row 2 solved, row 3 refused (z = 0), row 4 refused (a negative load), row 5 solved with a
#: warning (one loaded ball: a large clearance).
TEXT = "balls,stiffness,load,clearance\n8,1e5,1000,\n0,1e5,1000,\n8,1e5,-5,\n3,1e5,1000,0.5\n"


def _batch(capsys, tmp_path, *args: str) -> tuple[int, str, str]:
    path = tmp_path / "cases.csv"
    path.write_text(TEXT, encoding="utf-8")
    return run_entry(capsys, "batch", str(path), *args)


def test_a_csv_keeps_every_row_in_order_the_skipped_ones_with_their_reason(capsys, tmp_path):
    code, out, err = _batch(capsys, tmp_path, "--format", "csv")
    rows = list(csv.DictReader(io.StringIO(out)))
    assert code == 1 and [r["row"] for r in rows] == ["2", "3", "4", "5"]
    assert [r["skipped"] for r in rows] == [
        "",
        "balls: must be between 1 and 100000 (got 0)",
        "load: must be greater than 0 N (got -5 N)",
        "",
    ]
    assert all(v == "" for r in rows[1:3] for k, v in r.items() if k not in ("row", "skipped"))
    assert rows[0]["q_max [N]"] != "" and rows[3]["q_max [N]"] != ""
    assert err.splitlines()[-1] == (
        "2 of 4 rows solved, 2 skipped (exit status 1), 1 warning; the output names each "
        "skipped row and its reason"
    )


def test_json_table_and_markdown_name_the_skipped_rows(capsys, tmp_path):
    code, out, _ = _batch(capsys, tmp_path, "--format", "json")
    assert code == 1 and [s["row"] for s in json.loads(out)["skipped"]] == [3, 4]
    for fmt in ("table", "markdown"):
        code, out, _ = _batch(capsys, tmp_path, "--format", fmt)
        assert "Row 3 skipped: balls: must be between 1 and 100000 (got 0)" in out


def test_quiet_keeps_the_closing_line_only(capsys, tmp_path):
    code, out, err = _batch(capsys, tmp_path, "--format", "csv", "-q")
    assert code == 1 and len(list(csv.DictReader(io.StringIO(out)))) == 4
    assert err.splitlines() == [
        "2 of 4 rows solved, 2 skipped (exit status 1), 1 warning; the output names each "
        "skipped row and its reason"
    ]


def test_stderr_says_skipped_rows_apart_from_the_warnings(capsys, tmp_path):
    """A skipped row is a ``Skipped:`` line, a solved row's advisory a ``Warning:`` line: the
    closing line's count of warnings counts the ``Warning:`` lines."""
    code, _, err = _batch(capsys, tmp_path, "--format", "csv")
    lines = err.splitlines()
    assert lines[:2] == [
        "Skipped: row 3: balls: must be between 1 and 100000 (got 0)",
        "Skipped: row 4: load: must be greater than 0 N (got -5 N)",
    ]
    assert lines[2].startswith("Warning: row 5: ")
    assert sum(line.startswith("Warning: ") for line in lines) == 1


def test_a_file_of_skipped_rows_only_counts_no_warning(capsys, tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("balls,stiffness,load\n0,1e5,1000\n8,1e5,-5\n", encoding="utf-8")
    code, _, err = run_entry(capsys, "batch", str(path), "--format", "csv")
    assert code == 1 and not any(line.startswith("Warning:") for line in err.splitlines())
    assert err.splitlines()[-1] == (
        "0 of 2 rows solved, 2 skipped (exit status 1), 0 warnings; the output names each "
        "skipped row and its reason"
    )


def test_a_file_solved_whole_without_warnings_says_nothing(capsys, tmp_path):
    path = tmp_path / "good.csv"
    path.write_text("balls,stiffness,load\n8,1e5,1000\n", encoding="utf-8")
    code, out, err = run_entry(capsys, "batch", str(path), "--format", "csv")
    assert code == 0 and err == "" and out.splitlines()[0].endswith(",skipped")


def test_a_header_only_file_says_it_solved_no_row_with_or_without_quiet(capsys, tmp_path):
    """A file with its header and no data row wrote an empty report and said nothing, as if
    every row had been solved; it ends on the closing line, -q or not (the line -q keeps),
    with exit status 0."""
    path = tmp_path / "empty.csv"
    path.write_text("balls,stiffness,load\n\n", encoding="utf-8")
    line = "0 of 0 rows solved, 0 skipped, 0 warnings; the file has no data rows"
    for quiet in ((), ("-q",)):
        code, out, err = run_entry(capsys, "batch", str(path), "--format", "csv", *quiet)
        assert code == 0 and out.splitlines()[0].endswith(",skipped") and len(out.splitlines()) == 1
        assert err.splitlines() == [line]


def test_quiet_changes_the_warning_lines_only_never_the_closing_line(capsys, tmp_path):
    """-q leaves out the Skipped: and Warning: lines; the closing line is the same with it and
    without it, and so are the output and the exit status."""
    loud = _batch(capsys, tmp_path, "--format", "csv")
    quiet = _batch(capsys, tmp_path, "--format", "csv", "-q")
    assert quiet[:2] == loud[:2] and quiet[2].splitlines() == loud[2].splitlines()[-1:]
