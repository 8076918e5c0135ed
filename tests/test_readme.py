"""The README's console examples are real: each ``$ bearingload ...`` block is run and compared."""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest
from click.testing import CliRunner

from bearingload.cli import main

README = Path(__file__).resolve().parents[1] / "README.md"


def console_examples() -> list[tuple[str, str]]:
    """(command, expected output) for every ``$ bearingload`` line in a ```console block."""
    examples = []
    for block in re.findall(r"```console\n(.*?)```", README.read_text(encoding="utf-8"), re.S):
        parts = re.split(r"^\$ ", block, flags=re.M)
        for part in parts[1:]:
            command, _, output = part.partition("\n")
            examples.append((command, output))
    return examples


def test_readme_has_console_examples():
    assert len(console_examples()) >= 3


@pytest.mark.parametrize("command, expected", console_examples())
def test_readme_console_example(command, expected, monkeypatch):
    monkeypatch.chdir(README.parent)  # example files are named relative to the repository
    args = shlex.split(command)
    assert args[0] == "bearingload"
    result = CliRunner().invoke(main, args[1:], catch_exceptions=False)
    got = [line.rstrip() for line in result.output.rstrip("\n").splitlines()]
    want = [line.rstrip() for line in expected.rstrip("\n").splitlines()]
    assert got == want
