"""``bearingload tables``: a folder of tables, its manifest, and the commands that make them.

``check`` regenerates every table its ``manifest.toml`` lists and compares cell by cell, ``update``
rewrites the files, ``add`` appends an entry. The library part is :mod:`bearingload.tables_ci`;
this module runs an entry's command line in memory through the ``bearingload`` group itself.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any

import click

from bearingload.cli.options import CONTEXT

if TYPE_CHECKING:
    from bearingload.tables_ci.manifest import Entry, Manifest

#: Exit status of a manifest or entry that cannot be used (bad input), as for a usage error.
BAD_MANIFEST = 2


class ManifestProblem(click.ClickException):
    """One ``Error:`` line naming the manifest, the entry and what is wrong; exit status 2."""

    exit_code = BAD_MANIFEST


def manifest_errors(func: Callable[..., Any]) -> Callable[..., Any]:
    """Turn a :class:`~bearingload.tables_ci.manifest.ManifestError` into one ``Error:`` line."""

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        from bearingload.tables_ci.manifest import ManifestError

        try:
            return func(*args, **kwargs)
        except ManifestError as exc:
            raise ManifestProblem(str(exc)) from exc

    return wrapper


@contextmanager
def _captured(directory: str) -> Iterator[tuple[Any, Any]]:
    """Standard output and error in memory, the working directory ``directory``, for one
    entry; both restored after."""
    import io
    from contextlib import redirect_stderr, redirect_stdout

    out, err = io.StringIO(), io.StringIO()
    here = os.getcwd()
    os.chdir(directory)
    try:
        with redirect_stdout(out), redirect_stderr(err):
            yield out, err
    finally:
        os.chdir(here)


def _table_commands(root: click.Group) -> list[str]:
    """The command lines (``table``, ``catalog list`` ...) that print a table."""
    ctx = click.Context(root, info_name="bearingload")
    out = []
    for name in root.list_commands(ctx):
        cmd = root.get_command(ctx, name)
        if isinstance(cmd, click.Group):
            out += [name] if _prints_table(cmd) else []
            sub = click.Context(cmd, info_name=name, parent=ctx)
            out += [f"{name} {s}" for s in cmd.list_commands(sub)
                    if _prints_table(cmd.get_command(sub, s))]  # fmt: skip
        elif _prints_table(cmd):
            out.append(name)
    return out


def _prints_table(cmd: click.Command | None) -> bool:
    names = {p.name for p in cmd.params} if cmd is not None else set()
    return {"fmt", "output"} <= names


def check_entry(root: click.Group, manifest: Manifest, entry: Entry) -> None:
    """Refuse, as a ManifestError naming the entry, a command that is not one that prints a
    table, an option it does not have or a value it refuses, and --format, -o or another
    option that writes a file (the entry names its file and format)."""
    from bearingload.tables_ci.manifest import ManifestError

    def refuse(message: str) -> ManifestError:
        return ManifestError(manifest.path, message, entry)

    ctx = click.Context(root, info_name="bearingload")
    cmd: click.Command = root
    words = list(entry.args)
    while isinstance(cmd, click.Group) and words and not words[0].startswith("-"):
        sub = cmd.get_command(ctx, words[0])
        if sub is None:
            path = " ".join([*ctx.command_path.split()[1:], words[0]])
            raise refuse(f"'{path}' is not a command of bearingload")
        ctx = click.Context(sub, info_name=words[0], parent=ctx)
        cmd, words = sub, words[1:]
    if cmd is root:
        raise refuse("the command names no command of bearingload (e.g. 'table k')")
    if not _prints_table(cmd):
        raise refuse(
            f"'{ctx.command_path.removeprefix('bearingload ')}' is not a command that prints a "
            f"table (those are: {', '.join(_table_commands(root))})"
        )
    try:
        with _captured(manifest.directory):
            parsed = cmd.make_context(str(ctx.info_name), words, parent=ctx.parent)
    except click.exceptions.Exit:
        raise refuse("the command prints help or a version, not a table") from None
    except click.ClickException as exc:
        raise refuse(exc.format_message()) from None
    for param in cmd.params:
        source = parsed.get_parameter_source(str(param.name))
        if source is None or source.name != "COMMANDLINE":
            continue
        shown = param.opts[-1] if isinstance(param, click.Option) else str(param.name)
        if param.name == "fmt":
            raise refuse(f"{shown} in the command: the entry's 'format' names the format")
        # a path given to an option is a file the command writes (-o, --plot; solve's and
        # sweep's --plot are not marked writable): the folder would change under 'check'
        kind = param.type
        if isinstance(kind, click.Path) and (isinstance(param, click.Option) or kind.writable):
            raise refuse(f"{shown} writes a file: the entry's 'file' names the one it makes")


def producer(root: click.Group, manifest: Manifest) -> Callable[[Entry], str]:
    """A function running an entry's command line in memory (in the manifest's folder) and
    returning what it prints; a refusal or failure becomes a ManifestError naming the entry."""
    from bearingload.tables_ci.manifest import ManifestError

    directory = os.path.abspath(manifest.directory)

    def produce(entry: Entry) -> str:
        args = [*entry.args, "--format", entry.format]
        try:
            with _captured(directory) as (out, err):
                status = root.main(args=args, prog_name="bearingload", standalone_mode=False)
        except click.ClickException as exc:
            raise ManifestError(manifest.path, exc.format_message(), entry) from None
        except click.exceptions.Abort:
            raise ManifestError(manifest.path, "the command was aborted", entry) from None
        if isinstance(status, int) and status:
            said = err.getvalue().strip().splitlines()
            why = f": {said[-1]}" if said else ""
            raise ManifestError(manifest.path, f"the command exited with status {status}{why}",
                                entry)  # fmt: skip
        return str(out.getvalue())

    return produce


def _checked(directory: str) -> tuple[Manifest, Callable[[Entry], str]]:
    """The folder's manifest with every entry checked, and its producer."""
    from bearingload.cli import main
    from bearingload.tables_ci.manifest import read_manifest

    manifest = read_manifest(directory)
    for entry in manifest.entries:
        check_entry(main, manifest, entry)
    return manifest, producer(main, manifest)


class Tolerance(click.ParamType):
    """--rtol/--atol: a number the manifest would take (``tables_ci.manifest.tolerance``)."""

    name = "float"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        from bearingload.errors import InputError
        from bearingload.tables_ci.manifest import tolerance

        try:
            number = value if isinstance(value, float) else float(value)
            return tolerance(param.name if param and param.name else "tolerance", number)
        except ValueError as exc:
            message = exc.message if isinstance(exc, InputError) else f"not a number: {value!r}"
            self.fail(message, param, ctx)


TOLERANCE = Tolerance()


def _tolerance_options(func: Callable[..., Any]) -> Callable[..., Any]:
    from bearingload.tables_ci.tableset import ATOL, RTOL

    func = click.option(
        "--atol",
        type=TOLERANCE,
        default=ATOL,
        show_default=True,
        help="Absolute floor: numbers closer than this agree (zeros).",
    )(func)
    return click.option(
        "--rtol",
        type=TOLERANCE,
        default=RTOL,
        show_default=True,
        help="Relative tolerance of a number, |a - b| <= rtol max(|a|, |b|); an entry's own "
        "rtol/atol take precedence.",
    )(func)


FOLDER = click.Path(file_okay=False)


@click.group(context_settings=CONTEXT)
def tables() -> None:
    """Keep a folder of tables in step with the commands that make them (for CI).

    The folder's manifest.toml names, per file, the bearingload command line that makes it and
    its format (csv, markdown, json), optionally a tolerance. 'check' regenerates every table in
    memory and compares it cell by cell (numbers within --rtol, text exactly); 'update' rewrites
    the files that moved; 'add' appends an entry and writes its file. Paths in a command are
    relative to the folder. See docs/tables.md.

    \b
    Examples:
      bearingload tables add mytables --file k_6205.csv -- table k --bearing 6205 --load 1kN
      bearingload tables check examples/tables
      bearingload tables update examples/tables
    """


@tables.command(context_settings=CONTEXT)
@click.argument("directory", metavar="[DIR]", type=FOLDER, default="tables")
@_tolerance_options
@click.pass_context
@manifest_errors
def check(ctx: click.Context, directory: str, rtol: float, atol: float) -> None:
    """Regenerate every table of DIR (default: tables) and compare it with its file.

    Exit status 0 when every listed file agrees; 1 when a cell moved (each file's moved cells
    are listed: row, column, committed, regenerated, relative difference; at most 20 in all),
    list; 2 when the manifest or an entry cannot be used. Input files of the commands belong
    in a subfolder (or outside DIR): only DIR's own files are tables.

    \b
    Examples:
      bearingload tables check examples/tables
      bearingload tables check examples/tables --rtol 1e-6
    """
    from bearingload.tables_ci.tableset import check_report, compare_folder, regenerate

    manifest, produce = _checked(directory)
    states = compare_folder(manifest, regenerate(manifest, produce), rtol, atol)
    if all(s.state == "agrees" for s in states):
        n = len(states)
        said = (
            "file of {} agrees with its command"
            if n == 1
            else "files of {} agree with their commands"
        )
        click.echo(f"{n} listed {said.format(directory)}")
        return
    click.echo(check_report(directory, states), nl=False)
    ctx.exit(1)


@tables.command(context_settings=CONTEXT)
@click.argument("directory", metavar="[DIR]", type=FOLDER, default="tables")
@_tolerance_options
@click.option(
    "--exact",
    is_flag=True,
    help="Rewrite every file whose text differs at all, not only those whose cells moved "
    "beyond the tolerance (e.g. after a change of number formatting).",
)
@manifest_errors
def update(directory: str, rtol: float, atol: float, exact: bool) -> None:
    """Rewrite the listed files of DIR (default: tables) whose cells moved, or that are missing.

    Every table is regenerated in memory first: an entry that fails writes nothing; the files
    are then written whole or not at all. Each file written is named with the reason; a file
    whose text differs only within the tolerance is kept (--exact rewrites it).

    \b
    Examples:
      bearingload tables update examples/tables
      bearingload tables update --exact examples/tables
    """
    from bearingload.tables_ci.tableset import update_folder

    manifest, produce = _checked(directory)
    states = update_folder(manifest, produce, rtol, atol, exact)
    for s in states:
        where = os.path.join(directory, s.name)
        if s.state == "written":
            click.echo(f"wrote {where} ({s.reason})")
        elif s.state == "agrees" and s.changed:
            click.echo(f"kept {where}: its text differs only within the tolerance (--exact "
                       "rewrites it)")  # fmt: skip
        elif s.state == "unlisted":
            click.echo(f"Warning: {where} is not listed in the manifest; left as it is", err=True)
    written = sum(1 for s in states if s.state == "written")
    listed = sum(1 for s in states if s.state != "unlisted")
    click.echo(f"{written} of {listed} listed files written")


def _file_name(words: tuple[str, ...], fmt: str) -> str:
    """A file name made of a command line's words: ``table k --bearing 6205`` ->
    ``table_k_bearing_6205.csv``."""
    import re

    from bearingload.tables_ci.manifest import FORMATS

    stem = re.sub(r"[^A-Za-z0-9.+-]+", "_", "_".join(w.lstrip("-") for w in words))
    return stem.strip("_.-")[:100] + FORMATS[fmt]


@tables.command(context_settings=CONTEXT)
@click.argument("directory", metavar="DIR", type=FOLDER)
@click.argument("command", nargs=-1, required=True, type=click.UNPROCESSED)
@click.option("--file", "file", help="The table's file name in DIR. Default: made of the command.")
@click.option(
    "--format",
    "fmt",
    type=click.Choice(["csv", "markdown", "json"]),
    help="The table's format. Default: from the file's extension, else csv.",
)
@click.option("--rtol", type=TOLERANCE, help="This file's relative tolerance (a number >= 0).")
@click.option("--atol", type=TOLERANCE, help="This file's absolute floor (a number >= 0).")
@manifest_errors
def add(
    directory: str,
    command: tuple[str, ...],
    file: str | None,
    fmt: str | None,
    rtol: float | None,
    atol: float | None,
) -> None:
    """Append an entry for COMMAND to DIR's manifest.toml and write its table.

    COMMAND is a bearingload command line that prints a table, after '--' (without --format and
    -o). DIR and its manifest are created when missing. The entry is checked and its table made
    before anything is written; then the table and the manifest are written whole or not at all.

    \b
    Examples:
      bearingload tables add mytables -- table k --bearing 6205 --load 1kN --clearance 10um
      bearingload tables add mytables --file life.md -- table life -b 6205 -F 1.4kN
    """
    import shlex

    from bearingload.cli import main
    from bearingload.tables_ci import manifest as mf
    from bearingload.tables_ci.tableset import write_whole

    words = tuple(command[1:] if command[0] == "bearingload" else command)
    fmt = fmt or (mf.format_of(file) if file else None) or "csv"
    file = file or _file_name(words, fmt)
    old = mf.read_manifest(directory) if os.path.exists(mf.manifest_path(directory)) else None
    entry_text = mf.entry_text(file, shlex.join(words), fmt, rtol, atol)
    text, manifest = mf.appended(old, directory, entry_text)
    entry = manifest.entries[-1]
    if (entry.file, entry.args, entry.format, entry.rtol, entry.atol) != (
        file, words, fmt, rtol, atol
    ):  # fmt: skip
        raise mf.ManifestError(manifest.path, "the entry does not read back as written", entry)
    target = os.path.join(directory, file)
    if os.path.lexists(target):
        raise mf.ManifestError(manifest.path, f"{target} exists and is not listed: remove it "
                               "or give another --file", entry)  # fmt: skip
    made = not os.path.isdir(directory)
    os.makedirs(directory, exist_ok=True)
    try:
        check_entry(main, manifest, entry)
        table = producer(main, manifest)(entry)
        write_whole(directory, {file: table, mf.MANIFEST: text})
    except BaseException:
        if made:
            os.rmdir(directory)  # the folder this command made, still empty
        raise
    click.echo(f"added {entry.label()} to {manifest.path} and wrote {target}")
