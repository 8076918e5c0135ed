"""The README and the reference in docs/: short README, a current and complete command-line
reference, links that resolve, no working-note labels. (Console examples: test_readme and
test_golden; Python examples: doctest, README.md and docs/ are in pytest's testpaths.)"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from .cli_reference import CLI_DOC, commands, help_text, reference, title
from .golden_outputs import doc_pages

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"


def test_cli_reference_is_current():
    assert CLI_DOC.read_text(encoding="utf-8") == reference(), "make golden rewrites docs/cli.md"


def test_every_command_is_in_the_cli_reference():
    """Every command and subcommand of the click group has its section, with its own --help."""
    text = CLI_DOC.read_text(encoding="utf-8")
    headings = re.findall(r"^## (bearingload.*)$", text, flags=re.M)
    paths = list(commands())
    assert len(paths) >= 10 and ("catalog", "show") in paths
    assert headings == [title(p) for p in paths]
    for path in paths:
        section = text.split(f"## {title(path)}\n", 1)[1]
        assert section.split("\n```\n", 1)[0].startswith(f"\n```text\nUsage: {title(path)} ")
        assert help_text(path).splitlines()[0] in section


def test_every_command_is_documented_in_prose():
    """Each command is also named in the README or a docs page other than the generated one."""
    prose = "\n".join(p.read_text(encoding="utf-8") for p in doc_pages() if p != CLI_DOC)
    missing = [
        title(p)
        for p in commands()
        if p and not re.search(rf"{re.escape(title(p))}(?![\w-])", prose)
    ]
    assert not missing, missing


def test_readme_is_short_and_complete():
    text = README.read_text(encoding="utf-8")
    assert len(text.splitlines()) <= 400
    assert "make run" in text and "make test" in text
    tasks = re.split(
        r"^### \d+\. ", text.split("## Ten things", 1)[1].split("\n## ", 1)[0], flags=re.M
    )
    assert len(tasks) == 11  # the lead, then ten tasks
    for task in tasks[1:]:  # one example each, with its output (checked by test_readme / doctest)
        assert "```console\n$ bearingload " in task or "```python\n>>> " in task, task[:60]
    for page in ("guide", "cli", "library", "models", "errata", "accuracy", "benchmarks"):
        assert f"](docs/{page}.md)" in text


def test_docs_python_examples_are_doctested():
    config = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    testpaths = re.search(r"^testpaths = \[(.*)\]$", config, flags=re.M)
    assert testpaths and {'"README.md"', '"docs"'} <= set(testpaths.group(1).split(", "))
    assert "--doctest-glob='*.md'" in config


#: Labels of the project's working notes, which mean nothing to a reader of the documentation.
WORKING_NOTES = re.compile(r"\bissue\s*#?\d+|\bthe issue's\b|\bseed\s*0\d\d|\breview session", re.I)


@pytest.mark.parametrize("page", doc_pages(), ids=lambda p: p.name)
def test_no_working_note_labels(page):
    found = WORKING_NOTES.findall(page.read_text(encoding="utf-8"))
    assert not found, found


def test_no_working_note_labels_in_code_tables_or_examples():
    """Nor in the package, the tests, the benchmarks, the committed tables, the examples or the
    Makefile (names from the domain, not from the project's history)."""
    root = Path(__file__).resolve().parents[1]
    files = [root / "Makefile"]
    for folder in ("bearingload", "tests", "benchmarks", "tables", "examples"):
        files += [
            p for p in (root / folder).rglob("*") if p.suffix in (".py", ".csv", ".md", ".toml")
        ]
    here = Path(__file__).resolve()
    found = {
        str(p.relative_to(root)): hits
        for p in files
        if p.resolve() != here and (hits := WORKING_NOTES.findall(p.read_text(encoding="utf-8")))
    }
    assert not found, found


def _slug(heading: str) -> str:
    """GitHub's anchor of a Markdown heading."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def _anchors(page: Path) -> set[str]:
    text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
    return {_slug(h) for h in re.findall(r"^#+ (.*)$", text, flags=re.M)}


@pytest.mark.parametrize("page", doc_pages(), ids=lambda p: p.name)
def test_links_resolve(page):
    """Every relative link names an existing file, and every #anchor a heading of its page."""
    text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"[a-z]+:", target):
            continue
        path, _, anchor = target.partition("#")
        linked = (page.parent / path).resolve() if path else page
        assert linked.exists(), (page.name, target)
        if anchor:
            assert anchor in _anchors(linked), (page.name, target)
