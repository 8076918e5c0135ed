"""Check and update a folder of tables against its manifest.

Every function takes ``produce(entry) -> text``, the text the entry's command prints (the
command line runs it in memory); nothing here runs a command or imports the command line.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from dataclasses import field

from bearingload.lazy_dataclass import dataclass
from bearingload.tables_ci.cells import ABSENT, Cell, compare
from bearingload.tables_ci.manifest import (
    FORMATS,
    MANIFEST,
    Entry,
    Manifest,
    ManifestError,
    tolerance,
)

Produce = Callable[[Entry], str]

#: Default tolerances of a comparison: relative [-], and the absolute floor for zeros.
RTOL = 1e-9
ATOL = 1e-12
#: A report shows at most this many differing cells in all (a screenful), then a count.
SHOWN_CELLS = 20
#: ... and a text cell's first this many characters.
SHOWN_TEXT = 100


@dataclass(frozen=True)
class FileState:
    """One file of the folder: its ``name``, how it stands (``agrees``, ``differs``,
    ``missing``, ``unlisted``; after an update also ``written``), the cells that moved,
    whether its text differs at all (``changed``) and why it was written (``reason``)."""

    name: str
    state: str
    cells: Sequence[Cell] = field(default_factory=tuple)
    changed: bool = False
    reason: str = ""


def tolerances(entry: Entry, rtol: float, atol: float) -> tuple[float, float]:
    """The entry's own tolerances where it gives them, else the run's."""
    return (entry.rtol if entry.rtol is not None else rtol,
            entry.atol if entry.atol is not None else atol)  # fmt: skip


def regenerate(manifest: Manifest, produce: Produce) -> dict[str, str]:
    """File name -> the text its entry's command makes now, for every entry, in memory."""
    return {entry.file: produce(entry) for entry in manifest.entries}


def unlisted(manifest: Manifest) -> list[str]:
    """Files of the folder that look like tables (.csv, .md, .json, not hidden) and that the
    manifest does not list."""
    listed = {e.file for e in manifest.entries}
    names = sorted(os.listdir(manifest.directory))
    return [
        n
        for n in names
        if n not in listed
        and n != MANIFEST
        and not n.startswith(".")
        and os.path.splitext(n)[1].lower() in FORMATS.values()
        and os.path.isfile(os.path.join(manifest.directory, n))
    ]


def listed_path(manifest: Manifest, entry: Entry) -> str:
    """The path of a listed file, which must lie in the folder: a symbolic link leading out of
    it is refused (check would compare, and update overwrite, a file elsewhere)."""
    path = os.path.join(manifest.directory, entry.file)
    if os.path.islink(path):
        inside = os.path.realpath(manifest.directory)
        if os.path.dirname(os.path.realpath(path)) != inside:
            raise ManifestError(
                manifest.path, f"'file' is a symbolic link out of the folder ({path})", entry
            )
    return path


def _read(path: str) -> str | None:
    try:
        with open(path, encoding="utf-8", newline="") as fh:
            return fh.read()
    except FileNotFoundError:
        return None


def compare_folder(
    manifest: Manifest, texts: dict[str, str], rtol: float = RTOL, atol: float = ATOL
) -> list[FileState]:
    """How every listed file stands against its regenerated text, then the unlisted files."""
    rtol, atol = tolerance("rtol", rtol), tolerance("atol", atol)
    states = []
    for entry in manifest.entries:
        old = _read(listed_path(manifest, entry))
        new = texts[entry.file]
        if old is None:
            states.append(FileState(entry.file, "missing", changed=True))
            continue
        cells = compare(old, new, entry.format, *tolerances(entry, rtol, atol))
        states.append(FileState(entry.file, "differs" if cells else "agrees", cells, old != new))
    states += [FileState(name, "unlisted") for name in unlisted(manifest)]
    return states


def write_whole(directory: str, texts: dict[str, str]) -> None:
    """Write every file of ``texts`` into ``directory``, all or none: each is first written
    whole to a temporary file beside it; only when all are written are they renamed over the
    old ones (a failure before that leaves every old file as it was)."""
    from contextlib import ExitStack

    from bearingload.reports.render import atomic_file

    with ExitStack() as stack:
        for name, text in texts.items():
            stack.enter_context(atomic_file(os.path.join(directory, name))).write(text)


def update_folder(
    manifest: Manifest,
    produce: Produce,
    rtol: float = RTOL,
    atol: float = ATOL,
    exact: bool = False,
) -> list[FileState]:
    """Regenerate every entry in memory, then write the files that are missing or whose cells
    moved beyond the tolerance (``exact``: whose text differs at all), all or none. Returns
    every file's state, ``written`` for those written."""
    texts = regenerate(manifest, produce)  # all first: a failing entry writes nothing
    states = compare_folder(manifest, texts, rtol, atol)
    chosen = {
        s.name
        for s in states
        if s.state in ("missing", "differs") or (exact and s.state == "agrees" and s.changed)
    }
    write_whole(manifest.directory, {name: texts[name] for name in texts if name in chosen})
    return [
        FileState(s.name, "written", s.cells, s.changed, _reason(s)) if s.name in chosen else s
        for s in states
    ]


def _reason(s: FileState) -> str:
    if s.state == "missing":
        return "new"
    return f"{_cells(len(s.cells))} moved" if s.cells else "text differs"


def _shown(cell: Cell, text: str) -> str:
    """A number as written; text (what does not read as a number) quoted (an empty cell shows as ``""``) and cut at
    :data:`SHOWN_TEXT` characters; absent as it says."""
    if cell.relative is not None or text == ABSENT or _is_number(text):
        return text
    if len(text) > SHOWN_TEXT:
        text = text[: SHOWN_TEXT - 3] + "..."
    return '"' + text.replace('"', '\\"') + '"'


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _number(value: float | None) -> str:
    return "" if value is None else f", relative difference {value:.3g}"


def check_report(directory: str, states: Sequence[FileState], shown: int = SHOWN_CELLS) -> str:
    """The lines of a failed check: each file that differs with its moved cells (at most
    ``shown`` cells in all), each missing or unlisted file, then the counts."""
    lines = []
    left = shown
    for s in states:
        where = os.path.join(directory, s.name)
        if s.state == "missing":
            lines.append(f"{where}: missing (listed in {MANIFEST})")
        elif s.state == "unlisted":
            lines.append(f"{where}: not listed in {MANIFEST}")
        elif s.state == "differs":
            verb = "differs" if len(s.cells) == 1 else "differ"
            lines.append(f"{where}: {_cells(len(s.cells))} {verb}")
            for c in s.cells[: max(left, 0)]:
                lines.append(
                    f"  {c.row}, column {c.column!r}: committed {_shown(c, c.committed)}, "
                    f"regenerated {_shown(c, c.regenerated)}{_number(c.relative)}"
                )
            if len(s.cells) > max(left, 0):
                more = len(s.cells) - max(left, 0)
                lines.append(f"  ... and {more} more cell{'s' if more != 1 else ''}")
            left -= len(s.cells)
    lines.append(summary(states))
    return "\n".join(lines) + "\n"


def _cells(n: int) -> str:
    return f"{n} cell{'s' if n != 1 else ''}"


def summary(states: Sequence[FileState]) -> str:
    """``28 files: 26 agree, 1 differs (3 cells), 1 missing, 0 unlisted``."""
    count = {k: sum(1 for s in states if s.state == k) for k in ("agrees", "differs", "missing")}
    moved = sum(len(s.cells) for s in states if s.state == "differs")
    extra = sum(1 for s in states if s.state == "unlisted")
    listed = len(states) - extra
    return (
        f"{listed} listed files: {count['agrees']} agree, {count['differs']} differ "
        f"({_cells(moved)}), {count['missing']} missing; {extra} unlisted"
    )
