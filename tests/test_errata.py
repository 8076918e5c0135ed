"""``bearingload errata``: the rows, the command, the committed tables and the README block."""

from __future__ import annotations

import csv
import io
import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

from bearingload.papers import errata
from bearingload.papers.errata import AGREES, DIFFERS, ROW_SOURCES, errata_rows
from bearingload.reports.errata import BLOCK_END, BLOCK_START, errata_block

from .cli_helpers import committed, invoke, run_entry

ROOT = Path(__file__).resolve().parents[1]
KUROCHKIN = "Kurochkin 1973, Izv. AN SSSR MTT"
COMPLIANCE = "Varying-compliance abstract, eqs. (7)-(9)"
STIFFNESS = "Crane-bearing stiffness (2009), eqs. (19)-(22)"
KEYS = {"source", "table", "cell", "printed", "computed", "difference", "verdict", "cause"}


def test_rows_have_every_column_and_a_verdict():
    rows = errata_rows()
    assert len(rows) == 916
    for r in rows:
        assert KEYS <= set(r) and isinstance(r["printed"], str)
        assert r["verdict"] in (AGREES, DIFFERS, "lost in print")
        assert math.isfinite(r["computed"])
        if r["verdict"] != "lost in print":
            assert math.isfinite(r["difference"])
            assert r["relative_difference"] == pytest.approx(
                r["difference"] / r["computed"], rel=1e-12
            )
    papers = {r["source"] for r in rows}
    assert papers == {"Kuzmenko 2010", "Kuzmenko & Sabadash 2014", KUROCHKIN, COMPLIANCE, STIFFNESS}


def test_counts_per_paper():
    """Rows and disagreements per paper (the report's headline numbers)."""
    counts = {}
    for r in errata_rows():
        n, d = counts.get(r["source"], (0, 0))
        counts[r["source"]] = (n + 1, d + (r["verdict"] == DIFFERS))
    assert counts == {
        "Kuzmenko 2010": (99, 36),
        "Kuzmenko & Sabadash 2014": (89, 26),
        KUROCHKIN: (714, 168),
        COMPLIANCE: (8, 8),
        STIFFNESS: (6, 5),
    }


def test_row_sources_is_the_one_list(monkeypatch):
    """A new paper is one more (module, function) entry in ROW_SOURCES."""
    extra = [{"source": "X 1999", "table": "T", "cell": "c", "printed": 1.5, "computed": 1.0,
              "difference": 0.5, "verdict": DIFFERS, "cause": "test"}]  # fmt: skip
    monkeypatch.setattr(errata, "_extra_rows_for_test", lambda: extra, raising=False)
    monkeypatch.setattr(
        errata,
        "ROW_SOURCES",
        [*ROW_SOURCES, ("bearingload.papers.errata", "_extra_rows_for_test")],
    )
    rows = errata.errata_rows()
    assert len(rows) == 917
    assert rows[-1]["printed"] == "1.5" and rows[-1]["relative_difference"] == 0.5


def test_only_differing_and_summary_agree():
    rows = errata_rows()
    out = invoke("errata", "--only-differing", "--format", "json").output
    table = json.loads(out)["rows"]
    assert len(table) == sum(r["verdict"] == DIFFERS for r in rows) == 243
    summary = json.loads(invoke("errata", "--summary", "--format", "json").output)
    counts = summary["rows"]
    assert sum(c["checked"] for c in counts) == 916 and sum(c["differ"] for c in counts) == 243


def test_summary_with_only_differing_keeps_the_tables_where_some_differ():
    """--summary --only-differing used to ignore the filter and list every table."""
    every = json.loads(invoke("errata", "--summary", "--format", "json").output)["rows"]
    r = invoke("errata", "--summary", "--only-differing", "--format", "json")
    assert r.exit_code == 0
    doc = json.loads(r.output)
    kept = doc["rows"]
    assert "only those where a printed number differs" in doc["title"]
    assert kept == [c for c in every if c["differ"] > 0]
    assert len(kept) < len(every)  # e.g. Kuzmenko 2010 §3.2: 2 checked, none differ
    assert sum(c["differ"] for c in kept) == sum(c["differ"] for c in every)


@pytest.mark.parametrize("fmt", ["table", "csv", "markdown", "json"])
def test_every_format(fmt):
    r = invoke("errata", "--format", fmt)
    assert r.exit_code == 0
    assert "Table 2.2" in r.output and "differs" in r.output
    assert r.output == invoke("errata", "--format", fmt).output  # identical from run to run


def test_csv_is_the_committed_table(tmp_path):
    target = tmp_path / "e.csv"
    r = invoke("errata", "--format", "csv", "-o", str(target))
    assert r.exit_code == 0 and r.output == ""
    text = target.read_text(encoding="utf-8")
    assert text == (ROOT / "tables" / "errata.csv").read_text(encoding="utf-8")
    rows = list(csv.DictReader(io.StringIO(text)))
    assert len(rows) == 916
    z5 = next(r for r in rows if r["table"] == "Table 1" and r["cell"] == "z = 5, k")
    assert z5["printed"] == "0.9362" and z5["verdict"] == DIFFERS


def test_paper_filter_and_bad_paper(capsys):
    out = invoke("errata", "--paper", "sabadash", "--format", "csv").output
    lines = out.splitlines()[1:]
    assert len(lines) == 89 and all(line.startswith("Kuzmenko & Sabadash 2014,") for line in lines)
    code, out, err = run_entry(capsys, "errata", "--paper", "nobody")
    assert code == 2 and out == ""
    assert (
        err.startswith("Error: Invalid value for '--paper': no paper matches")
        and err.count("\n") == 1
    )


def test_help_has_examples():
    out = invoke("errata", "--help").output
    assert "Examples:" in out and "bearingload errata --only-differing" in out


def test_committed_errata_registered():
    for name in ("errata.csv", "errata.md"):
        printed, on_disk = committed(name)
        assert printed == on_disk


def test_errata_block_is_generated_from_the_rows():
    """docs/errata.md's tables of printed numbers are exactly what the code generates."""
    text = (ROOT / "docs" / "errata.md").read_text(encoding="utf-8")
    start, end = text.index(BLOCK_START), text.index(BLOCK_END) + len(BLOCK_END)
    assert text[start:end] == errata_block(), "run `make tables` and commit docs/errata.md"
    assert "z = 30, K_Q" in text[start:end]
    # no hand-kept copy of the printed tables outside the block (the ball-stiffness section
    # quotes the worked example's printed loads beside the exact ones, on purpose)
    stiffness = text.index("## What the paper's ball stiffness")
    following = text.find("\n## ", stiffness + 1)
    outside = text[:start] + text[end:stiffness] + (text[following:] if following > 0 else "")
    assert "## Published vs computed" in outside and "### Kurochkin (1973)" in outside
    for printed in ("0.9362", "2.341", "170.3", "0.7181", "2.1875", "0.416"):
        assert printed not in outside


def test_readme_has_no_errata_tables():
    """The README summarises the errata and links to docs/errata.md; the tables live there only."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    assert BLOCK_START not in text and "](docs/errata.md)" in text
    assert "z = 30, K_Q" not in text


def test_errata_command_is_lazy():
    code = (
        "import sys; from bearingload.cli import main; "
        "assert 'bearingload.papers.errata' not in sys.modules; "
        "import bearingload.papers.published; assert 'numpy' not in sys.modules"
    )
    assert subprocess.run([sys.executable, "-c", code], timeout=60).returncode == 0


def test_relative_errors_are_percent_in_human_formats_and_fractions_in_machine_ones():
    """errata printed its relative difference as a fraction [-] and the accuracy report its
    errors as fractions, while solve and table k --method all print %."""
    from bearingload.reports.accuracy import accuracy_table
    from bearingload.reports.quantities import QUANTITIES
    from bearingload.reports.render import render

    relative = [  # errors and differences, not ratios such as relative_life (L10r / L10r at 0)
        q for q in QUANTITIES.values() if "error" in q.key or q.key == "relative_difference"
    ]
    assert {q.key for q in relative} >= {"relative_error", "relative_difference", "error_max"}
    assert all(q.shown() == ("%", 100.0) and q.unit == "-" for q in relative)
    human = invoke("errata", "--paper", "sabadash", "--only-differing").output
    assert "relative difference [%]" in human and "relative difference [-]" not in human
    first = json.loads(invoke("errata", "--paper", "sabadash", "--only-differing", "--format", "json").output)["rows"][0]  # fmt: skip
    assert first["relative_difference"] == 1.0  # printed 1, computed 0.5: +100 %
    assert "100  differs" in human.splitlines()[4]
    row = {"method": "m", "setting": "s", "cases": 1, "error_median": 0.0012, "error_max": 0.5,
           "iterations": 3}  # fmt: skip
    text = render([accuracy_table([row])], "markdown")
    assert "median error [%]" in text
    cells = [c.strip() for c in text.splitlines()[4].split("|")]
    assert cells[4:6] == ["0.12", "50"], cells
    assert render([accuracy_table([row])], "csv").splitlines()[1] == "m,s,1,0.0012,0.5,3"


def test_errata_only_differing_title_says_the_filter():
    """errata --only-differing (without --summary) kept the title 'every printed number the
    project recomputes' over a table of the differing ones only (json 'title' too)."""
    r = invoke("errata", "--only-differing", "--format", "json")
    assert '"title": "Published vs computed: the printed numbers that differ' in r.stdout
