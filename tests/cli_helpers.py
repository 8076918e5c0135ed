"""Ways the tests drive the command line: click's runner, the entry point, a fresh interpreter."""

from __future__ import annotations

import subprocess
import sys

from click.testing import CliRunner, Result

from bearingload.cli import main, run


def invoke(*args: str) -> Result:
    """The click group in-process; exceptions propagate (a traceback fails the test)."""
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


def committed(name: str) -> tuple[str, str]:
    """A file of tables/: the text its command in tables/manifest.toml prints now, and the
    text committed."""
    from pathlib import Path

    from bearingload.tables_ci.manifest import read_manifest

    folder = Path(__file__).resolve().parents[1] / "tables"
    entry = next(e for e in read_manifest(str(folder)).entries if e.file == name)
    printed = invoke(*entry.args, "--format", entry.format)
    assert printed.exit_code == 0, printed.output
    return printed.output, (folder / name).read_text(encoding="utf-8")


def run_entry(capsys, *args: str) -> tuple[int, str, str]:
    """The console entry point in-process: (exit status, stdout, stderr)."""
    try:
        run(list(args))
        code = 0
    except SystemExit as exc:
        code = int(exc.code or 0)
    out, err = capsys.readouterr()
    return code, out, err


def run_process(*args: str, cwd=None) -> subprocess.CompletedProcess:
    """``python -m bearingload ARGS`` in a fresh interpreter, as a user runs it."""
    return subprocess.run(
        [sys.executable, "-m", "bearingload", *args],
        capture_output=True,
        text=True,
        timeout=60,
        cwd=cwd,
    )


def drawn(monkeypatch) -> list:
    """Every Figure saved while the test runs (whatever draws it), saved as it would be."""
    from matplotlib.figure import Figure

    figures: list = []
    save = Figure.savefig

    def recording(self, *args, **kwargs):
        figures.append(self)
        return save(self, *args, **kwargs)

    monkeypatch.setattr(Figure, "savefig", recording)
    return figures


def error_line(capsys, *args: str) -> str:
    """The one ``Error:`` line of a refused command line (exit 2, nothing on stdout)."""
    code, out, err = run_entry(capsys, *args)
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and lines[0].startswith("Error:"), err
    return lines[0]


def warnings_of(err: str) -> list[str]:
    """The ``Warning:`` lines of a command's stderr, without the prefix."""
    return [w.removeprefix("Warning: ") for w in err.splitlines() if w.startswith("Warning:")]


def skipped_of(err: str) -> list[str]:
    """The ``Skipped:`` lines of a batch run's stderr (its skipped rows), without the prefix."""
    return [w.removeprefix("Skipped: ") for w in err.splitlines() if w.startswith("Skipped:")]


def besides_tilt(err) -> list[str]:
    """The lines of ``err`` (a text or a list of warnings) other than the warning on the inner
    ring's tilt (bearings.checks.misalignment_findings), which every case whose ring tilts gives:
    an angular-contact bearing under a radial load, free to tilt, does at any tilt."""
    lines = err.splitlines() if isinstance(err, str) else list(err)
    tilt = ("the inner ring tilts by", "a tilt of the inner ring of")
    return [w for w in lines if not any(t in w for t in tilt)]


def solved_csv(text: str) -> str:
    """A batch csv without its skipped rows and its last column (``skipped``): the rows solved,
    as before skipped rows were written; any other text as it is."""
    lines = text.splitlines(keepends=True)
    if not lines or not lines[0].rstrip("\r\n").endswith(",skipped"):
        return text
    head = lines[0].rstrip("\r\n").removesuffix(",skipped") + "\n"
    rows = [line.rstrip("\r\n") for line in lines[1:]]
    return "".join([head, *(row[:-1] + "\n" for row in rows if row.endswith(","))])


def without_count(err: str) -> str:
    """A batch run's stderr without its closing line (the rows solved and skipped, the
    warnings)."""
    import re

    lines = err.splitlines(keepends=True)
    if lines and re.match(r"\d+ of \d+ rows solved, ", lines[-1]):
        lines = lines[:-1]
    return "".join(lines)


class SolvedRows:
    """A ``batch`` run as the tests of its solved rows read it: a csv without its skipped rows
    and without its last column (``skipped``), stderr without its closing count line. What
    those hold is tested apart (tests/test_batch_skipped.py)."""

    def __init__(self, result) -> None:
        self.result = result
        self.exit_code = result.exit_code
        self.stdout = solved_csv(result.stdout)
        self.stderr = without_count(result.stderr)
        self.output = self.stdout + self.stderr

    def __getattr__(self, name: str):
        return getattr(self.result, name)
