"""The command-line reference ``docs/cli.md``: ``bearingload --help`` and every command's ``--help``.

``make golden`` (``python -m tests.golden_outputs``) writes it with :func:`reference`;
``tests/test_docs.py`` fails when the file differs from what the commands print now, and when a
command of the click group is missing from it or from the prose of the README and ``docs/``.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CLI_DOC = ROOT / "docs" / "cli.md"

#: Help is wrapped as a terminal of 100 columns or more shows it (the commands' max_content_width
#: is 100; click keeps 2 columns free), so that the file does not depend on the terminal that
#: generates it.
WIDTH = 98

HEAD = """# Command-line reference

Generated from `bearingload --help` and the `--help` of every command by `make golden`
(`tests/cli_reference.py`); a test fails when this file differs from what the commands print
now, or when a command is missing. Worked examples with their output: the [README](../README.md)
and the [user guide](guide.md).
"""


def commands() -> Iterator[tuple[str, ...]]:
    """The path of every command of ``bearingload``, groups first: ``()``, ``("solve",)``,
    ``("catalog",)``, ``("catalog", "show")`` ... (hidden commands left out)."""
    import click

    from bearingload.cli import main

    def walk(command: click.Command, path: tuple[str, ...]) -> Iterator[tuple[str, ...]]:
        yield path
        if isinstance(command, click.Group):
            ctx = click.Context(command, info_name=path[-1] if path else "bearingload")
            for name in command.list_commands(ctx):
                sub = command.get_command(ctx, name)
                if sub is not None and not sub.hidden:
                    yield from walk(sub, (*path, name))

    yield from walk(main, ())


def help_text(path: tuple[str, ...]) -> str:
    """``bearingload PATH --help`` as printed at :data:`WIDTH` columns."""
    from click.testing import CliRunner

    from bearingload.cli import main

    result = CliRunner().invoke(
        main, [*path, "--help"], prog_name="bearingload", terminal_width=WIDTH
    )
    if result.exit_code != 0:
        raise RuntimeError(f"bearingload {' '.join(path)} --help failed: {result.output}")
    return result.output


def title(path: tuple[str, ...]) -> str:
    return " ".join(("bearingload", *path))


def anchor(path: tuple[str, ...]) -> str:
    """The GitHub anchor of the heading ``## bearingload PATH``."""
    return "-".join(("bearingload", *path))


def reference() -> str:
    """The text of ``docs/cli.md``."""
    paths = list(commands())
    index = "\n".join(f"- [`{title(p)}`](#{anchor(p)})" for p in paths)
    sections = []
    for path in paths:
        body = "\n".join(line.rstrip() for line in help_text(path).rstrip("\n").splitlines())
        sections.append(f"## {title(path)}\n\n```text\n{body}\n```\n")
    return HEAD + "\n" + index + "\n\n" + "\n".join(sections)


def write() -> None:
    CLI_DOC.parent.mkdir(exist_ok=True)
    CLI_DOC.write_text(reference(), encoding="utf-8", newline="\n")
