"""The console examples of the README and docs/ are real: each ``$ bearingload ...`` is run and
compared with the output the page shows."""

from __future__ import annotations

import re
import shlex

import pytest
from click.testing import CliRunner

from bearingload.cli import main

from .golden_outputs import README, doc_pages


def console_examples(page=README) -> list[tuple[str, str]]:
    """(command, expected output) for every ``$ bearingload`` line in a ```console block."""
    examples = []
    for block in re.findall(r"```console\n(.*?)```", page.read_text(encoding="utf-8"), re.S):
        parts = re.split(r"^\$ ", block, flags=re.M)
        for part in parts[1:]:
            command, _, output = part.partition("\n")
            examples.append((command, output))
    return examples


def all_examples() -> list[tuple[str, str, str]]:
    return [(p.name, c, o) for p in doc_pages() for c, o in console_examples(p)]


def test_readme_has_console_examples():
    assert len(console_examples()) >= 9  # the ten tasks but the Python one (a doctest)


def test_guide_has_console_examples():
    assert len(console_examples(README.parent / "docs" / "guide.md")) >= 10


@pytest.mark.parametrize("page, command, expected", all_examples())
def test_console_example(page, command, expected, monkeypatch):
    monkeypatch.chdir(README.parent)  # example files are named relative to the repository
    args = shlex.split(command)
    assert args[0] == "bearingload"
    result = CliRunner().invoke(main, args[1:], catch_exceptions=False)
    got = [line.rstrip() for line in result.output.rstrip("\n").splitlines()]
    want = [line.rstrip() for line in expected.rstrip("\n").splitlines()]
    assert got == want


def test_install_instructions_name_no_package_index():
    """The README's CI step said 'pip install bearingload', a package no index serves: every
    page installs from the repository (a checkout, or git+URL) or names matplotlib alone."""
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    pages = [README, *doc_pages(), *sorted((root / "bearingload").rglob("*.py"))]
    from_index = re.compile(r"pip install\s+['\"]?bearingload(?!\s*@)")
    found = [p.name for p in pages if from_index.search(p.read_text(encoding="utf-8"))]
    assert found == []
    assert "git+URL" in README.read_text(encoding="utf-8")
