"""``bearingload tables``: a folder of tables checked and updated against its manifest.toml."""

from __future__ import annotations

import csv
import io
import json
import os
import shutil
import sys
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearingload.errors import InputError
from bearingload.tables_ci import tableset
from bearingload.tables_ci.cells import compare, numbers_agree
from bearingload.tables_ci.manifest import (
    MANIFEST,
    ManifestError,
    entry_text,
    parse_manifest,
    read_manifest,
    toml_string,
)

from .cli_helpers import invoke, run_entry

ROOT = Path(__file__).resolve().parents[1]
TABLES = ROOT / "tables"
K306 = "table1_k_306_300kgf_gr20um"

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib


def folder(tmp_path: Path, *names: str) -> Path:
    """A copy of the named files of tables/ with their entries of tables/manifest.toml."""
    d = tmp_path / "tables"
    d.mkdir()
    text = ""
    for e in read_manifest(str(TABLES)).entries:
        if e.file in names:
            shutil.copy(TABLES / e.file, d / e.file)
            text += entry_text(e.file, e.command, e.format, e.rtol, e.atol) + "\n"
    (d / MANIFEST).write_text(text, encoding="utf-8")
    assert len(read_manifest(str(d)).entries) == len(names)
    return d


def write_manifest(d: Path, text: str) -> None:
    d.mkdir(exist_ok=True)
    (d / MANIFEST).write_text(text, encoding="utf-8")


def rows(path: Path) -> list[list[str]]:
    return list(csv.reader(io.StringIO(path.read_text(encoding="utf-8"))))


def scale_cell(path: Path, row: int, column: str, factor: float) -> tuple[str, str]:
    """Multiply one number of a csv file by ``factor``: (old text, new text)."""
    table = rows(path)
    j = table[0].index(column)
    old = table[row][j]
    table[row][j] = repr(float(old) * factor)
    out = io.StringIO()
    csv.writer(out, lineterminator="\n").writerows(table)
    path.write_text(out.getvalue().removesuffix("\n"), encoding="utf-8")
    return old, table[row][j]


def test_the_project_manifest_lists_every_committed_file():
    listed = {e.file for e in read_manifest(str(TABLES)).entries}
    on_disk = {p.name for p in TABLES.iterdir()} - {MANIFEST}
    assert listed == on_disk and len(listed) == 28


def test_check_names_a_cell_moved_by_1e_6_and_passes_1e_12(tmp_path, capsys):
    d = folder(tmp_path, f"{K306}.csv", f"{K306}.md")
    code, out, _ = run_entry(capsys, "tables", "check", str(d))
    assert code == 0 and out == f"2 listed files of {d} agree with their commands\n"
    pristine = (d / f"{K306}.csv").read_text(encoding="utf-8")
    old, new = scale_cell(d / f"{K306}.csv", 8, "k", 1 + 1e-6)
    code, out, err = run_entry(capsys, "tables", "check", str(d))
    assert code == 1 and err == ""
    lines = out.splitlines()
    assert lines[0] == f"{d / K306}.csv: 1 cell differs"
    assert lines[1].startswith(f"  row 8, column 'k': committed {new}, regenerated {old}, ")
    assert float(lines[1].rsplit(" ", 1)[1]) == pytest.approx(1e-6, rel=1e-3)
    assert lines[-1] == "2 listed files: 1 agree, 1 differ (1 cell), 0 missing; 0 unlisted"
    (d / f"{K306}.csv").write_text(pristine, encoding="utf-8")
    scale_cell(d / f"{K306}.csv", 8, "k", 1 + 1e-12)
    assert (d / f"{K306}.csv").read_text(encoding="utf-8") != pristine
    assert run_entry(capsys, "tables", "check", str(d))[0] == 0


def test_check_names_a_markdown_cell_and_a_changed_note(tmp_path):
    d = folder(tmp_path, f"{K306}.md")
    md = d / f"{K306}.md"
    text = md.read_text(encoding="utf-8")
    assert "|  30 |  11 | 0.1829 |" in text
    md.write_text(
        text.replace("|  30 |  11 | 0.1829 |", "|  30 |  11 | 0.1830 |").replace(
            "- z: balls;", "- Z: balls;"
        ),
        encoding="utf-8",
    )
    r = invoke("tables", "check", str(d))
    assert r.exit_code == 1
    lines = r.output.splitlines()
    assert lines[1] == (
        "  row 30, column 'k [-]': committed 0.1830, regenerated 0.1829, relative difference "
        "0.000546"
    )
    assert lines[2].startswith("  line 36, column '(text)': committed \"- Z: balls;")
    assert len(lines) == 4  # one changed line is one difference, not a shift of every note


def test_per_file_and_command_line_tolerances(tmp_path):
    d = folder(tmp_path, f"{K306}.csv")
    scale_cell(d / f"{K306}.csv", 20, "k", 1 + 1e-6)
    assert invoke("tables", "check", str(d)).exit_code == 1
    assert invoke("tables", "check", str(d), "--rtol", "1e-5").exit_code == 0
    text = (d / MANIFEST).read_text(encoding="utf-8")
    (d / MANIFEST).write_text(text.replace('format = "csv"', 'format = "csv"\nrtol = 1e-5'))
    assert invoke("tables", "check", str(d)).exit_code == 0


def test_report_is_at_most_a_screenful(tmp_path):
    d = folder(tmp_path, f"{K306}.csv")
    for row in range(1, 31):
        scale_cell(d / f"{K306}.csv", row, "k", 1.001)
    r = invoke("tables", "check", str(d))
    assert r.exit_code == 1
    lines = r.output.splitlines()
    assert len(lines) == 1 + tableset.SHOWN_CELLS + 2
    assert lines[-2] == "  ... and 10 more cells"
    assert lines[-1].endswith("1 differ (30 cells), 0 missing; 0 unlisted")


def test_missing_and_unlisted_files(tmp_path):
    d = folder(tmp_path, f"{K306}.csv", f"{K306}.md")
    (d / f"{K306}.md").unlink()
    (d / "extra.csv").write_text("a\n1\n")
    (d / ".hidden.csv").write_text("a\n1\n")  # hidden and non-table files are not tables
    (d / "notes.txt").write_text("x")
    r = invoke("tables", "check", str(d))
    assert r.exit_code == 1
    assert r.output.splitlines() == [
        f"{d / K306}.md: missing (listed in manifest.toml)",
        f"{d / 'extra.csv'}: not listed in manifest.toml",
        "2 listed files: 1 agree, 0 differ (0 cells), 1 missing; 1 unlisted",
    ]


def test_json_cells_are_named_by_row_and_key(tmp_path):
    d = tmp_path / "t"
    assert invoke("tables", "add", str(d), "--file", "k.json", "--", "table", "k", "--z-max", "6")
    doc = json.loads((d / "k.json").read_text(encoding="utf-8"))
    old = doc["rows"][4]["k"]
    doc["rows"][4]["k"] = old * (1 + 1e-6)
    doc["rows"][5]["loaded_balls"] = 7
    del doc["rows"][2]["k"]
    (d / "k.json").write_text(json.dumps(doc), encoding="utf-8")
    lines = invoke("tables", "check", str(d)).output.splitlines()
    fresh = json.loads(invoke("table", "k", "--z-max", "6", "--format", "json").output)
    assert lines[0].endswith("k.json: 3 cells differ")
    assert (
        lines[1]
        == f"  rows[2], column 'k': committed (absent), regenerated {fresh['rows'][2]['k']}"
    )
    assert lines[2].startswith(f"  rows[4], column 'k': committed {old * (1 + 1e-6)!r}, ")
    assert lines[3].startswith("  rows[5], column 'loaded_balls': committed 7, regenerated ")


@pytest.mark.parametrize(
    ("manifest", "message"),
    [
        ("[[table]\nfile = 'x.csv'\n", "manifest.toml: not valid TOML: "),
        ('[[table]]\nfile = "x.csv"\ncommand = "tables check"\n',
         "manifest.toml, entry 1 (\"x.csv\"): 'tables check' is not a command that prints a "
         "table (those are: solve, sweep, table, catalog, catalog show, "),
        ('[[table]]\nfile = "x.csv"\ncommand = "nope k"\n',
         "manifest.toml, entry 1 (\"x.csv\"): 'nope' is not a command of bearingload"),
        ('[[table]]\nfile = "x.csv"\ncommand = "table k --bogus 3"\n',
         "manifest.toml, entry 1 (\"x.csv\"): No such option '--bogus'"),
        ('[[table]]\nfile = "x.csv"\ncommand = "table k --z-max 0"\n',
         "manifest.toml, entry 1 (\"x.csv\"): Invalid value for '--z-max': 0 is not in the range"),
        ('[[table]]\nfile = "x.csv"\ncommand = "table k --format json"\n',
         "manifest.toml, entry 1 (\"x.csv\"): --format in the command: the entry's 'format' "),
        ('[[table]]\nfile = "x.csv"\ncommand = "table k -o k.csv"\n',
         "manifest.toml, entry 1 (\"x.csv\"): --output writes a file"),
        ('[[table]]\nfile = "x.csv"\ncommand = "accuracy --no-timing --plot a.png"\n',
         "manifest.toml, entry 1 (\"x.csv\"): --plot writes a file"),
        ('[[table]]\nfile = "x.csv"\ncommand = "solve -z 8 -F 1kN -K 1e5 --plot p.png"\n',
         "manifest.toml, entry 1 (\"x.csv\"): --plot writes a file"),
        ('[[table]]\nfile = "x.csv"\ncommand = "sweep -z 8 -F 1kN -K 1e5 --steps 3 --plot p.png"\n',
         "manifest.toml, entry 1 (\"x.csv\"): --plot writes a file"),
        ('[[table]]\nfile = "x.csv"\ncommand = "table k --help"\n',
         "manifest.toml, entry 1 (\"x.csv\"): the command prints help or a version"),
        ('[[table]]\nfile = "x.csv"\ncommand = "table life -b 6205"\n',
         "manifest.toml, entry 1 (\"x.csv\"): Missing option '--load'"),
        ('[[table]]\nfile = "x.csv"\ncomand = "table k"\n',
         "manifest.toml, entry 1 (\"x.csv\"): unknown key 'comand' (allowed: file, command, "),
        ('[[table]]\nfile = "x.csv"\ncommand = "table k"\nformat = "xlsx"\n',
         "manifest.toml, entry 1 (\"x.csv\"): 'format' must be one of csv, markdown, json"),
        ('[[table]]\nfile = "x.md"\ncommand = "table k"\nformat = "csv"\n',
         "manifest.toml, entry 1 (\"x.md\"): format 'csv' does not fit the file's extension"),
        ('[[table]]\nfile = "../x.csv"\ncommand = "table k"\n',
         "manifest.toml, entry 1 (\"../x.csv\"): 'file' must be a file name in the folder"),
        ('[[table]]\nfile = "a\\u0000b.csv"\ncommand = "table k"\n',
         "manifest.toml, entry 1 (\"a\\x00b.csv\"): 'file' cannot hold a control character"),
        ('[[table]]\nfile = "x.csv"\ncommand = "table k"\nrtol = -1\n',
         "manifest.toml, entry 1 (\"x.csv\"): 'rtol' must be finite and >= 0"),
        ('[[table]]\nfile = "x.csv"\ncommand = "table k"\n[[table]]\nfile = "x.csv"\n'
         'command = "table kq"\n',
         "manifest.toml, entry 2 (\"x.csv\"): file listed twice (also entry 1 (\"x.csv\"))"),
        ('[[table]]\nfile = "x.csv"\ncommand = "table k \'--z-max"\n',
         "manifest.toml, entry 1 (\"x.csv\"): 'command' cannot be split into words"),
    ],
)  # fmt: skip
def test_bad_manifest_is_one_error_line_and_nothing_written(tmp_path, capsys, manifest, message):
    d = tmp_path / "t"
    write_manifest(d, manifest)
    (d / "x.csv").write_text("old\n")
    (d / "x.md").write_text("old\n")
    for command in ("check", "update"):
        code, out, err = run_entry(capsys, "tables", command, str(d))
        assert (code, out) == (2, "")
        assert err.startswith(f"Error: {d / message}"), err
        assert err.count("\n") == 1
    assert (d / "x.csv").read_text() == "old\n" and (d / "x.md").read_text() == "old\n"
    assert sorted(p.name for p in d.iterdir()) == [MANIFEST, "x.csv", "x.md"]


def test_no_manifest(tmp_path, capsys):
    code, _, err = run_entry(capsys, "tables", "check", str(tmp_path))
    assert code == 2 and err == (
        f"Error: {tmp_path / MANIFEST}: no such file (start one with 'bearingload tables add "
        "DIR -- COMMAND')\n"
    )


def test_update_is_whole_or_nothing_when_an_entry_fails(tmp_path, capsys):
    d = folder(tmp_path, f"{K306}.csv", f"{K306}.md")
    scale_cell(d / f"{K306}.csv", 8, "k", 2.0)
    (d / f"{K306}.md").unlink()
    before = (d / f"{K306}.csv").read_text(encoding="utf-8")
    with open(d / MANIFEST, "a", encoding="utf-8") as fh:  # runs, and refuses at run time
        fh.write('\n[[table]]\nfile = "life.csv"\ncommand = "table life --bearing 6205"\n')
    code, out, err = run_entry(capsys, "tables", "update", str(d))
    assert (code, out) == (2, "")
    assert err.startswith(f'Error: {d / MANIFEST}, entry 3 ("life.csv"): Missing option')
    assert (d / f"{K306}.csv").read_text(encoding="utf-8") == before
    assert sorted(p.name for p in d.iterdir()) == [MANIFEST, f"{K306}.csv"]


def test_files_are_written_all_or_none(tmp_path):
    """A file that cannot be written (here a folder in its place) leaves every other as it was
    and no temporary file behind."""
    (tmp_path / "a.csv").write_text("old a\n")
    (tmp_path / "b.csv").mkdir()
    with pytest.raises(IsADirectoryError):
        tableset.write_whole(str(tmp_path), {"a.csv": "new a\n", "b.csv": "new b\n"})
    assert (tmp_path / "a.csv").read_text() == "old a\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.csv", "b.csv"]
    tableset.write_whole(str(tmp_path), {"a.csv": "new a\n", "c.csv": "c\n"})
    assert (tmp_path / "a.csv").read_text() == "new a\n" and (
        tmp_path / "c.csv"
    ).read_text() == "c\n"


def test_update_rewrites_what_moved_and_says_so(tmp_path, capsys):
    d = folder(tmp_path, f"{K306}.csv", f"{K306}.md", "table1_k_zero_clearance.csv")
    pristine = {p.name: p.read_text(encoding="utf-8") for p in d.iterdir()}
    scale_cell(d / f"{K306}.csv", 8, "k", 2.0)
    (d / f"{K306}.md").unlink()
    zero = d / "table1_k_zero_clearance.csv"
    zero.write_text(pristine[zero.name].replace(",1.0\n", ",1\n"), encoding="utf-8")  # same numbers
    (d / "extra.csv").write_text("a\n")
    code, out, err = run_entry(capsys, "tables", "update", str(d))
    assert code == 0
    assert out.splitlines() == [
        f"kept {zero}: its text differs only within the tolerance (--exact rewrites it)",
        f"wrote {d / K306}.csv (1 cell moved)",
        f"wrote {d / K306}.md (new)",
        "2 of 3 listed files written",
    ]
    assert err == f"Warning: {d / 'extra.csv'} is not listed in the manifest; left as it is\n"
    assert zero.read_text(encoding="utf-8") != pristine[zero.name]
    code, out, _ = run_entry(capsys, "tables", "update", "--exact", str(d))
    assert out.splitlines() == [f"wrote {zero} (text differs)", "1 of 3 listed files written"]
    (d / "extra.csv").unlink()
    assert {p.name: p.read_text(encoding="utf-8") for p in d.iterdir()} == pristine
    assert run_entry(capsys, "tables", "update", str(d))[1] == "0 of 3 listed files written\n"


def test_add_appends_an_entry_and_writes_the_file(tmp_path, capsys):
    d = tmp_path / "mine"
    code, out, _ = run_entry(capsys, "tables", "add", str(d), "--", "table", "k", "--bearing",
                             "6205", "--load", "1kN", "--z-max", "9")  # fmt: skip
    name = "table_k_bearing_6205_load_1kN_z-max_9.csv"
    assert code == 0 and out == f'added entry 1 ("{name}") to {d / MANIFEST} and wrote {d / name}\n'
    printed = invoke("table", "k", "--bearing", "6205", "--load", "1kN", "--z-max", "9",
                     "--format", "csv").output  # fmt: skip
    assert (d / name).read_text(encoding="utf-8") == printed
    code, out, _ = run_entry(capsys, "tables", "add", str(d), "--file", "kq.md", "--rtol", "1e-6",
                             "--", "bearingload", "table", "kq", "--z-max", "4")  # fmt: skip
    assert code == 0 and (d / "kq.md").read_text(encoding="utf-8").startswith("### Load-conc")
    entries = read_manifest(str(d)).entries
    assert [(e.file, e.command, e.format, e.rtol) for e in entries] == [
        (name, "table k --bearing 6205 --load 1kN --z-max 9", "csv", None),
        ("kq.md", "table kq --z-max 4", "markdown", 1e-6),
    ]
    assert run_entry(capsys, "tables", "check", str(d))[0] == 0
    manifest = (d / MANIFEST).read_text(encoding="utf-8")
    for args in (["--file", "kq.md", "--", "table", "k"], ["--", "table", "k", "--nope"],
                 ["--file", "x.csv", "--", "tables", "check"]):  # fmt: skip
        code, out, err = run_entry(capsys, "tables", "add", str(d), *args)
        assert code == 2 and out == "" and err.count("\n") == 1 and err.startswith("Error: ")
    assert (d / MANIFEST).read_text(encoding="utf-8") == manifest
    assert sorted(p.name for p in d.iterdir()) == sorted([MANIFEST, name, "kq.md"])


def test_add_into_a_new_folder_refused_leaves_no_folder(tmp_path, capsys):
    code, _, err = run_entry(capsys, "tables", "add", str(tmp_path / "new"), "--", "errata",
                             "--bogus")  # fmt: skip
    assert code == 2 and "No such option '--bogus'" in err
    assert not (tmp_path / "new").exists()


def test_paths_are_relative_to_the_folder_from_any_working_directory(tmp_path, monkeypatch):
    """A command reading a file: its path is the folder's, quoted as a shell quotes it (a
    space, quotes and a backslash in the name survive TOML and the shell words)."""
    d = tmp_path / "t"
    (d / "inputs").mkdir(parents=True)  # a subfolder: its files are not tables of the folder
    data = 'inputs/bearing 208 "Kuzmenko" \\ 2014.csv'
    shutil.copy(ROOT / "examples" / "bearing208_kuzmenko2014.csv", d / data)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    r = invoke("tables", "add", str(d), "--file", "fit.json", "--", "fit", data,
               "--load-unit", "kgf", "--balls", "9")  # fmt: skip
    assert r.exit_code == 0, r.output
    assert read_manifest(str(d)).entries[0].args == (
        "fit",
        data,
        "--load-unit",
        "kgf",
        "--balls",
        "9",
    )
    assert invoke("tables", "check", str(d)).exit_code == 0
    monkeypatch.chdir(ROOT / "bearingload")
    assert invoke("tables", "check", str(d)).exit_code == 0
    assert invoke("tables", "check", str(TABLES)).exit_code == 0  # the project's, from elsewhere
    assert os.getcwd() == str(ROOT / "bearingload")


def test_markdown_a_line_added_is_one_difference():
    a = "### T\n\n| x | y |\n|--:|--:|\n| 1 | 2.5 |\n\n- note a\n- note b\n"
    b = a.replace("- note a\n", "- note a\n- new\n").replace("2.5", "2.5000000000001")
    cells = compare(a, b, "markdown", 1e-9, 0.0)
    assert [(c.row, c.column, c.committed, c.regenerated) for c in cells] == [
        ("after line 7", "(text)", "(absent)", "- new")
    ]
    c = compare(a, a.replace("| 1 | 2.5 |", "| 1 | 2.6 | 9 |"), "markdown", 1e-9, 0.0)
    assert [(x.row, x.column, x.committed, x.regenerated) for x in c] == [
        ("row 1", "y", "2.5", "2.6"),
        ("row 1", "column 3", "(absent)", "9"),
    ]


def test_csv_header_rows_and_text_cells():
    a = "name,x [mm]\nball,1.0\nroller,2\n"
    b = "name,x [um]\nBall,1\n"
    cells = compare(a, b, "csv", 1e-9, 0.0)
    assert [(c.row, c.column, c.committed, c.regenerated, c.relative) for c in cells] == [
        ("header", "column 2", "x [mm]", "x [um]", None),
        ("row 1", "name", "ball", "Ball", None),
        ("row 2", "(whole row)", "roller,2", "(absent)", None),
    ]


@pytest.mark.parametrize(
    ("a", "b", "rtol", "atol", "agree"),
    [
        (1.0, 1.0 + 2e-16, 0.0, 0.0, False),
        (1.0, 1.0 + 1e-10, 1e-9, 0.0, True),
        (1.0, 1.0 + 1e-8, 1e-9, 0.0, False),
        (-3.0, -3.0 * (1 + 5e-10), 1e-9, 0.0, True),
        (0.0, 1e-13, 1e-9, 1e-12, True),
        (0.0, 1e-11, 1e-9, 1e-12, False),
        (float("nan"), float("nan"), 1e-9, 0.0, True),
        (float("nan"), 1.0, 1e-9, 1.0, False),
        (float("inf"), float("inf"), 0.0, 0.0, True),
        (float("inf"), 1e308, 1e-9, 0.0, False),
    ],
)
def test_numbers_agree(a, b, rtol, atol, agree):
    assert numbers_agree(a, b, rtol, atol)[0] is agree
    assert numbers_agree(b, a, rtol, atol)[0] is agree


@given(st.text(max_size=40))
def test_toml_string_reads_back(text):
    assert tomllib.loads(f"x = {toml_string(text)}")["x"] == text


def test_entry_text_reads_back():
    text = entry_text('a "b".csv', "fit 'x y.csv' --balls 9", "csv", 1e-7, 0.0)
    (e,) = parse_manifest(text, "d").entries
    assert (e.file, e.args, e.format, e.rtol, e.atol) == (
        'a "b".csv', ("fit", "x y.csv", "--balls", "9"), "csv", 1e-7, 0.0
    )  # fmt: skip
    with pytest.raises(ManifestError, match=r"unknown key 'tables' at the top"):
        parse_manifest("tables = 1\n", "d")


def test_study_command(capsys):
    out = invoke("study", "--help").output
    assert "kurochkin1973-differences" in out and "Examples:" in out
    code, _, err = run_entry(capsys, "study", "nope")
    assert code == 2 and err.startswith("Error: Invalid value for 'NAME'") and err.count("\n") == 1


def test_one_listed_file_is_said_in_the_singular(tmp_path):
    """'1 listed files of DIR agree with their commands' read wrongly; one file is singular."""
    d = tmp_path / "one"
    assert invoke("tables", "add", str(d), "--", "table", "k", "--z-max", "5").exit_code == 0
    out = invoke("tables", "check", str(d)).output
    assert out == f"1 listed file of {d} agrees with its command\n"


def test_files_with_crlf_line_ends_agree_and_a_moved_cell_is_still_found(tmp_path, capsys):
    """A checkout with CR LF line ends (git's core.autocrlf on Windows runners): csv and json
    agreed, each Markdown table reported every line ending in CR as a differing text line
    ('committed "", regenerated ""'). Line ends are not cells, in every format."""
    d = folder(tmp_path, f"{K306}.csv", f"{K306}.md")
    for name in (f"{K306}.csv", f"{K306}.md"):
        path = d / name
        path.write_bytes(path.read_bytes().replace(b"\n", b"\r\n"))
    code, out, err = run_entry(capsys, "tables", "check", str(d))
    assert (code, err) == (0, ""), out
    md = d / f"{K306}.md"
    text = md.read_bytes().decode("utf-8")
    first = next(line for line in text.split("\r\n") if line.startswith("|  "))
    cells = first.split("|")
    cells[-2] = cells[-2].replace(cells[-2].strip(), "9.999")
    md.write_bytes(text.replace(first, "|".join(cells), 1).encode("utf-8"))
    code, out, _ = run_entry(capsys, "tables", "check", str(d))
    assert code == 1 and "1 cell differs" in out and "9.999" in out, out


@pytest.mark.parametrize("value", ["inf", "nan", "-1"])
@pytest.mark.parametrize("command", ["check", "update"])
def test_a_tolerance_the_manifest_refuses_is_refused_on_the_command_line(
    tmp_path, capsys, command, value
):
    """tables check --rtol inf (or nan) passed any change, while the manifest refuses such a
    tolerance: the option, the manifest and the library take one rule (finite, >= 0)."""
    d = folder(tmp_path, f"{K306}.csv")
    scale_cell(d / f"{K306}.csv", 20, "k", 2.0)
    before = (d / f"{K306}.csv").read_text(encoding="utf-8")
    for option in ("--rtol", "--atol"):
        code, out, err = run_entry(capsys, "tables", command, str(d), option, value)
        assert (code, out) == (2, ""), err
        assert err.startswith(f"Error: Invalid value for '{option}': must be finite and >= 0")
    assert (d / f"{K306}.csv").read_text(encoding="utf-8") == before
    code, _, err = run_entry(capsys, "tables", "add", str(d), "--rtol", value, "--", "table", "k")
    assert code == 2 and "Invalid value for '--rtol'" in err, err
    manifest = read_manifest(str(d))
    with pytest.raises(InputError, match="rtol"):
        tableset.compare_folder(manifest, {f"{K306}.csv": before}, rtol=float(value))


@pytest.mark.parametrize("command", ["check", "update"])
def test_a_listed_file_linked_out_of_the_folder_is_refused(tmp_path, capsys, command):
    """tables update wrote through a symbolic link to a file outside the folder: a listed file
    that links out of the folder is refused, naming it, and the file outside is left alone; a
    link within the folder is followed."""
    d = folder(tmp_path, f"{K306}.csv")
    outside = tmp_path / "outside.csv"
    outside.write_text("mine\n", encoding="utf-8")
    (d / f"{K306}.csv").unlink()
    (d / f"{K306}.csv").symlink_to(outside)
    code, out, err = run_entry(capsys, "tables", command, str(d))
    assert (code, out) == (2, "") and "symbolic link out of the folder" in err, err
    assert f'entry 1 ("{K306}.csv")' in err and err.count("\n") == 1
    assert outside.read_text(encoding="utf-8") == "mine\n"
    (d / f"{K306}.csv").unlink()
    shutil.copy(TABLES / f"{K306}.csv", d / ".real.csv")
    (d / f"{K306}.csv").symlink_to(".real.csv")
    code, _, err = run_entry(capsys, "tables", command, str(d))
    assert code == 0, err
