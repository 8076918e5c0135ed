"""The exact full output of every command in every format against the stored golden files, and the
console examples of the README and docs/ against what the code prints (regenerate both with
``make golden``)."""

from __future__ import annotations

import pytest

from .golden_outputs import COMMANDS, FORMATS, GOLDEN, README, doc_pages, page_text, run


@pytest.mark.parametrize("name", sorted(COMMANDS))
@pytest.mark.parametrize("fmt", FORMATS)
def test_golden_output(name, fmt, monkeypatch):
    monkeypatch.chdir(README.parent)
    stored = (GOLDEN / f"{name}.{fmt}.txt").read_text(encoding="utf-8")
    assert run(f"{COMMANDS[name]} --format {fmt}") == stored, f"make golden, then review {name}"


def test_every_golden_file_has_a_command():
    names = {f"{n}.{f}.txt" for n in COMMANDS for f in FORMATS}
    assert {p.name for p in GOLDEN.glob("*.txt")} == names


@pytest.mark.parametrize("page", doc_pages(), ids=lambda p: p.name)
def test_console_examples_are_current(page, monkeypatch):
    monkeypatch.chdir(README.parent)
    assert page_text(page) == page.read_text(encoding="utf-8"), "make golden rewrites them"
