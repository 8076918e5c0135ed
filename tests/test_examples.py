"""Every example a user is shown runs: the ``bearingload ...`` lines of every command's --help
(its ``\\b`` Examples block), and the bad-input examples of the README and docs/ with their stated
error lines. (The console examples of README and docs/ are checked, output and all, by
test_readme and test_golden.)"""

from __future__ import annotations

import importlib.util
import re
import shlex
import shutil
from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from bearingload.cli import main

from .cli_helpers import run_entry

ROOT = Path(__file__).resolve().parents[1]
#: matplotlib is an optional extra (``make test`` installs it): plot examples need it.
HAVE_MATPLOTLIB = importlib.util.find_spec("matplotlib") is not None


def _commands(cmd: click.Command, path: tuple[str, ...] = ()):
    """(path, command) of the group and every command and subcommand under it."""
    yield path, cmd
    if isinstance(cmd, click.Group):
        ctx = click.Context(cmd)
        for name in cmd.list_commands(ctx):
            sub = cmd.get_command(ctx, name)
            assert sub is not None, name
            yield from _commands(sub, (*path, name))


def help_examples() -> list[tuple[str, str]]:
    """(command, example line) for every ``bearingload ...`` line of every --help; a line
    continued with a backslash is joined to the next."""
    found = []
    for path, _ in _commands(main):
        out = CliRunner().invoke(main, [*path, "--help"]).output
        text = re.sub(r"\\\n\s*", " ", out)
        for line in text.splitlines():
            line = line.strip()
            if line.startswith("bearingload ") and (HAVE_MATPLOTLIB or "--plot" not in line):
                found.append((" ".join(path) or "bearingload", line))
    return found


EXAMPLES = help_examples()


def test_every_command_shows_examples():
    names = {name for name, _ in EXAMPLES}
    expected = {"bearingload", "solve", "sweep", "table", "catalog", "catalog show", "fit"}
    expected |= {"batch", "errata", "accuracy", "stability", "study", "tables", "tables check"}
    expected |= {"tables update", "tables add"}
    assert expected <= names, expected - names


@pytest.mark.parametrize(("command", "example"), EXAMPLES, ids=[e for _, e in EXAMPLES])
def test_help_example_runs(command, example, tmp_path, monkeypatch):
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)  # -o FILE and --plot FILE land in the temporary directory
    args = shlex.split(example)[1:]
    result = CliRunner().invoke(main, args, catch_exceptions=False)
    assert result.exit_code == 0, f"{command}: {example}\n{result.output}"
    for option in ("-o", "--plot"):
        if option in args:
            written = tmp_path / args[args.index(option) + 1]
            assert written.is_file() and written.stat().st_size > 0, written
    if "-o" not in args:
        assert result.output.strip(), example  # the answer went to standard output


def _readme_error_examples(page: Path = ROOT / "README.md") -> list[tuple[str, str]]:
    """(command line, stated output) of a page's ```text blocks that run bearingload and show
    its refusal (an ``Error:`` line; other text blocks illustrate outputs of made-up folders)."""
    text = page.read_text(encoding="utf-8")
    out = []
    for block in re.findall(r"```text\n(.*?)```", text, flags=re.S):
        command, _, stated = block.partition("\n")
        if command.startswith("$ bearingload ") and stated.startswith("Error:"):
            out.append((command[len("$ ") :], stated))
    return out


def test_readme_bad_input_example_prints_what_the_readme_says(capsys):
    examples = _readme_error_examples()
    assert examples, "the README's Bad input section lost its example"
    guide = _readme_error_examples(ROOT / "docs" / "guide.md")
    assert guide, "the guide's Bad input section lost its example"
    for page in sorted((ROOT / "docs").glob("*.md")):
        examples += _readme_error_examples(page)
    for command, stated in examples:
        code, out, err = run_entry(capsys, *shlex.split(command)[1:])
        assert code == 2 and out == "", command
        assert err == stated, (command, err)
