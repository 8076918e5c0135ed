"""The exact full output of every command in every format against the stored golden files, and the
README's console examples against what the code prints (regenerate both with ``make golden``)."""

from __future__ import annotations

import pytest

from .golden_outputs import COMMANDS, FORMATS, GOLDEN, README, readme_text, run


@pytest.mark.parametrize("name", sorted(COMMANDS))
@pytest.mark.parametrize("fmt", FORMATS)
def test_golden_output(name, fmt, monkeypatch):
    monkeypatch.chdir(README.parent)
    stored = (GOLDEN / f"{name}.{fmt}.txt").read_text(encoding="utf-8")
    assert run(f"{COMMANDS[name]} --format {fmt}") == stored, f"make golden, then review {name}"


def test_every_golden_file_has_a_command():
    names = {f"{n}.{f}.txt" for n in COMMANDS for f in FORMATS}
    assert {p.name for p in GOLDEN.glob("*.txt")} == names


def test_readme_console_examples_are_current(monkeypatch):
    monkeypatch.chdir(README.parent)
    assert readme_text() == README.read_text(encoding="utf-8"), "make golden rewrites them"
