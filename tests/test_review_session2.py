"""Defects found by the second-session review of ``bearingload batch`` and the combined load, each
reproduced as a user meets it (through the command line)."""

from __future__ import annotations

import pytest
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
