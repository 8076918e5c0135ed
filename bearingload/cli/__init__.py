"""The ``bearingload`` command: a thin click layer over the library.

Commands live one per module; each builds its rows with the library and prints them through
:mod:`bearingload.reports.render`.
"""

from __future__ import annotations

import errno
import importlib

import click

from bearingload import __version__
from bearingload.cli.options import CONTEXT

#: Command name -> module of this package defining a command object of the same name.
COMMANDS = {
    "solve": "solve",
    "sweep": "sweep",
    "table": "table",
    "catalog": "catalog",
    "fit": "fit",
    "batch": "batch",
    "errata": "errata",
    "accuracy": "accuracy",
    "stability": "stability",
    "study": "study",
    "tables": "tables",
}


class LazyGroup(click.Group):
    """A group that imports a command's module only when that command runs (or help lists it),
    so a terminal calculation pays for the one command it uses."""

    def list_commands(self, ctx: click.Context) -> list[str]:
        return list(COMMANDS)

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        if cmd_name not in COMMANDS:
            return None
        module = importlib.import_module(f"{__name__}.{COMMANDS[cmd_name]}")
        command: click.Command = getattr(module, cmd_name)
        return command


@click.group(cls=LazyGroup, context_settings=CONTEXT)
@click.version_option(__version__, "--version", prog_name="bearingload")
def main() -> None:
    """Load distribution among the balls (and rollers) of a radial rolling bearing.

    Outer ring fixed, radial load on the inner ring, angles from the load line. Clearance is the
    radial internal clearance G_r (total play, ISO 5753-1); the gap per side is G_r/2; negative
    clearance is preload. Bare numbers are N, mm and N/mm^1.5; units may be written after a number
    (300kgf, 20um, 4700kgf/mm^1.5).

    \b
    Examples:
      bearingload solve --balls 8 --load 300kgf --stiffness 4700kgf/mm^1.5 --clearance 20um
      bearingload table k
      bearingload table kq --format csv -o kq.csv
      bearingload solve 306 --load 300kgf --clearance C3
      bearingload sweep -z 9 --load 1kN --stiffness 1e5 --clearance 10um --steps 19
      bearingload catalog show 306
      bearingload fit examples/bearing208_kuzmenko2014.csv --load-unit kgf --balls 9
      bearingload batch examples/cases.csv --format csv
      bearingload errata --only-differing
    """


def _refuse_detached_units(args: list[str]) -> None:
    """``-F 300 kgf``: a unit typed as its own word after a number. Say so, instead of an
    unrelated error about an extra argument or an unknown bearing."""
    from bearingload.units import unit_names

    units = unit_names()
    for i, (before, word) in enumerate(zip(args, args[1:], strict=False)):
        try:
            float(before)
        except ValueError:
            continue
        if word in units:
            option = args[i - 1] if i > 0 and args[i - 1].startswith("-") else None
            where = f"Invalid value for '{option}': " if option else ""
            raise click.UsageError(
                f"{where}'{before} {word}': write a number and its unit without a space, "
                f"e.g. {before}{word}"
            )


#: Exit status of an internal error (a bug), apart from 1 (batch: rows skipped) and 2 (usage).
INTERNAL_ERROR = 3
#: The errors of writing to a full device or past a size or quota limit.
OUTPUT_FULL = (errno.ENOSPC, errno.EFBIG, errno.EDQUOT)


def run(argv: list[str] | None = None) -> None:
    """The command line, run: every error is one ``Error:`` line on stderr, never a traceback.
    (The console command runs it through :func:`bearingload.__main__.main`, which also sets the
    process's collector.)

    Exit status: 0 success; 1 a failure of the computation (no convergence) or, for batch, rows
    skipped; 2 bad input (usage); 3 an internal error (a bug: please report it).
    """
    import sys

    try:
        _refuse_detached_units(sys.argv[1:] if argv is None else argv)
        status = main.main(args=argv, prog_name="bearingload", standalone_mode=False)
        if sys.stdout is not None:  # (None: standard output closed, '>&-')
            sys.stdout.flush()  # (a full disk refused here, not at the interpreter's exit)
        if isinstance(status, int) and status:  # ctx.exit(n) returns n without standalone mode
            sys.exit(status)
    except click.exceptions.Exit as exc:
        sys.exit(exc.exit_code)
    except click.ClickException as exc:
        # one line: click lists the choices of a missing argument on lines of their own
        message = " ".join(exc.format_message().replace("\n\t", " ").splitlines())
        click.echo(f"Error: {message}", err=True)
        sys.exit(exc.exit_code)
    except click.exceptions.Abort:
        click.echo("Error: aborted", err=True)
        sys.exit(1)
    except BrokenPipeError:
        sys.exit(1)
    except Exception as exc:  # a bug, not bad input: still one line, but say so
        if isinstance(exc, OSError) and exc.errno in OUTPUT_FULL:  # (not a bug: the disk)
            click.echo(f"Error: cannot write the output: {exc.strerror}", err=True)
            sys.exit(1)
        click.echo(
            f"Error: internal error ({type(exc).__name__}: {exc}); please report it with the "
            "command line that caused it",
            err=True,
        )
        sys.exit(INTERNAL_ERROR)
