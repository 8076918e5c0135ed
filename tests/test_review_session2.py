"""Defects found by the second-session review of ``bearingload batch`` and the combined load, each
reproduced as a user meets it (through the command line)."""

from __future__ import annotations

from click.testing import CliRunner

from bearingload.cli import main


def _run(*args: str, stdin: str | None = None):
    return CliRunner().invoke(main, list(args), input=stdin)


def _batch(text: str, *args: str):
    return _run("batch", "-", "--format", "csv", *args, stdin=text)


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
    assert rows[1].split(",")[8:] == alone.stdout.splitlines()[1].split(",")[7:]
    # a header unit of another exponent: that row named, not the whole run ended (exit 2)
    mixed = "balls,load,stiffness [N/mm^(10/9)],exponent\n8,1000,46000,1.5\n8,1000,46000,10/9\n"
    for chunk in ("1", "100"):
        r = _batch(mixed, "--chunk-size", chunk)
        assert r.exit_code == 1, r.output
        assert r.stderr.startswith("Warning: row 2: stiffness: the unit 'N/mm^(10/9)'")
        assert [line.split(",")[0] for line in r.stdout.splitlines()[1:]] == ["3"]
