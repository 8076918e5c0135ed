"""Ways the tests drive the command line: click's runner, the entry point, a fresh interpreter."""

from __future__ import annotations

import subprocess
import sys

from click.testing import CliRunner, Result

from bearingload.cli import main, run


def invoke(*args: str) -> Result:
    """The click group in-process; exceptions propagate (a traceback fails the test)."""
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


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
