"""``manifest.toml``: the command line and format of every table in a folder.

One ``[[table]]`` entry per file::

    [[table]]
    file = "k_306.csv"                      # a file name in the folder
    command = "table k --bearing 306 --load 300kgf --clearance 20um"
    format = "csv"                          # csv, markdown or json; default: from the extension
    rtol = 1e-6                             # optional: this file's relative tolerance
    atol = 1e-12                            # optional: this file's absolute floor

The command is a ``bearingload`` command line without ``bearingload``, ``--format`` and ``-o``
(the entry gives those); paths in it are relative to the folder of the manifest. Reading refuses,
naming the file and the entry, anything else: invalid TOML, an unknown key, a missing or
misspelled value, a file listed twice.
"""

from __future__ import annotations

import math
import os
import sys
from collections.abc import Sequence
from typing import Any

from bearingload.errors import BearingloadError, InputError
from bearingload.lazy_dataclass import dataclass

#: The manifest's file name inside a folder of tables.
MANIFEST = "manifest.toml"
#: Formats an entry may name, and the file extension of each.
FORMATS = {"csv": ".csv", "markdown": ".md", "json": ".json"}
#: Keys of an entry: required, then optional.
REQUIRED = ("file", "command")
OPTIONAL = ("format", "rtol", "atol")


class ManifestError(BearingloadError):
    """A manifest (or one of its entries) that cannot be used: ``path, entry N ("file"): what``."""

    def __init__(self, path: str, message: str, entry: Entry | int | None = None) -> None:
        self.path = path
        where = path
        if isinstance(entry, Entry):
            where += f", {entry.label()}"
        elif entry is not None:
            where += f", entry {entry}"
        super().__init__(f"{where}: {message}")


@dataclass(frozen=True)
class Entry:
    """One table of a manifest: its ``file`` (a name in the folder), the ``command`` as written
    and its words ``args``, the ``format`` and optional tolerances (``None``: the run's)."""

    index: int
    file: str
    command: str
    args: tuple[str, ...]
    format: str
    rtol: float | None = None
    atol: float | None = None

    def label(self) -> str:
        """``entry 3 ("k.csv")``, as messages name an entry."""
        return f'entry {self.index} ("{self.file}")'


@dataclass(frozen=True)
class Manifest:
    """The entries of ``path`` (the manifest file) in the folder ``directory``, and its text."""

    directory: str
    path: str
    entries: Sequence[Entry]
    text: str


def _load_toml(text: str) -> dict[str, Any]:
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover - Python 3.10 reads TOML with the tomli backport
        import tomli as tomllib
    return tomllib.loads(text)


def manifest_path(directory: str) -> str:
    return os.path.join(directory, MANIFEST)


def read_manifest(directory: str) -> Manifest:
    """The manifest of ``directory``; raises :class:`ManifestError` naming what is wrong."""
    path = manifest_path(directory)
    try:
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
    except FileNotFoundError:
        raise ManifestError(
            path, "no such file (start one with 'bearingload tables add DIR -- COMMAND')"
        ) from None
    except (OSError, UnicodeDecodeError) as exc:
        raise ManifestError(path, f"cannot read it ({exc})") from None
    return parse_manifest(text, directory)


def parse_manifest(text: str, directory: str) -> Manifest:
    """Read a manifest's ``text`` (of the folder ``directory``) into its entries."""
    path = manifest_path(directory)
    try:
        data = _load_toml(text)
    except ValueError as exc:  # tomllib.TOMLDecodeError is a ValueError
        raise ManifestError(path, f"not valid TOML: {exc}") from None
    unknown = sorted(set(data) - {"table"})
    if unknown:
        raise ManifestError(
            path, f"unknown key {unknown[0]!r} at the top (allowed: [[table]] entries)"
        )
    tables = data.get("table", [])
    if not isinstance(tables, list) or not all(isinstance(t, dict) for t in tables):
        raise ManifestError(path, "'table' must be a list of [[table]] entries")
    entries = [_entry(path, i, raw) for i, raw in enumerate(tables, start=1)]
    seen: dict[str, Entry] = {}
    for e in entries:
        if e.file in seen:
            raise ManifestError(path, f"file listed twice (also {seen[e.file].label()})", e)
        seen[e.file] = e
    return Manifest(directory, path, entries, text)


def _entry(path: str, index: int, raw: dict[str, Any]) -> Entry:
    """One ``[[table]]`` entry, checked."""
    # a control character in the name is shown escaped (the name is then refused)
    where: Any = (
        index if not isinstance(raw.get("file"), str) else f'{index} ("{_shown(raw["file"])}")'
    )
    unknown = sorted(set(raw) - set(REQUIRED) - set(OPTIONAL))
    if unknown:
        allowed = ", ".join((*REQUIRED, *OPTIONAL))
        raise ManifestError(path, f"unknown key {unknown[0]!r} (allowed: {allowed})", where)
    for key in REQUIRED:
        if not isinstance(raw.get(key), str) or not raw[key].strip():
            raise ManifestError(path, f"'{key}' must be a non-empty string", where)
    file = raw["file"]
    check_file_name(file, path, where)
    fmt = raw.get("format", format_of(file))
    if fmt not in FORMATS:
        raise ManifestError(
            path, f"'format' must be one of {', '.join(FORMATS)} (got {fmt!r})", where
        )
    if os.path.splitext(file)[1] in FORMATS.values() and not file.endswith(FORMATS[fmt]):
        raise ManifestError(path, f"format {fmt!r} does not fit the file's extension", where)
    tolerances = {key: _tolerance(path, where, key, raw.get(key)) for key in ("rtol", "atol")}
    return Entry(index, file, raw["command"], command_words(raw["command"], path, where), fmt,
                 **tolerances)  # fmt: skip


def _shown(file: str) -> str:
    """A file name as messages print it: control characters escaped."""
    return "".join(c if 32 <= ord(c) != 127 else repr(c)[1:-1] for c in file)


def check_file_name(file: str, path: str, where: Any) -> None:
    """A plain file name of the folder: no directory part, not hidden, not the manifest."""
    if os.path.basename(file) != file or file in (".", "..") or "\\" in file:
        raise ManifestError(path, f"'file' must be a file name in the folder (got {file!r})", where)
    if any(ord(c) < 32 or ord(c) == 127 for c in file):
        raise ManifestError(path, f"'file' cannot hold a control character (got {file!r})", where)
    if file.startswith(".") or file == MANIFEST:
        raise ManifestError(path, f"'file' cannot be {file!r} (hidden, or the manifest)", where)


def format_of(file: str) -> str | None:
    """The format a file's extension names (``.csv``, ``.md``, ``.json``), or None."""
    ext = os.path.splitext(file)[1].lower()
    return next((f for f, e in FORMATS.items() if e == ext), None)


def tolerance(key: str, value: Any) -> float:
    """A tolerance (``rtol``, ``atol``) as a float: a finite number >= 0, whether a manifest
    entry, ``tables check``/``update``/``add`` or a library call gives it (inf or nan would let
    any change pass). Raises InputError naming ``key``."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(key, f"must be a number (got {value!r})")
    if not (math.isfinite(value) and value >= 0):
        raise InputError(key, f"must be finite and >= 0 (got {value!r})")
    return float(value)


def _tolerance(path: str, where: Any, key: str, value: Any) -> float | None:
    if value is None:
        return None
    try:
        return tolerance(key, value)
    except InputError as exc:
        raise ManifestError(path, f"'{key}' {exc.message}", where) from exc


def command_words(command: str, path: str, where: Any) -> tuple[str, ...]:
    """The words of a command line as a POSIX shell splits them, without a leading
    ``bearingload``."""
    import shlex

    try:
        words = shlex.split(command)
    except ValueError as exc:
        raise ManifestError(path, f"'command' cannot be split into words ({exc})", where) from None
    if words and words[0] == "bearingload":
        words = words[1:]
    if not words:
        raise ManifestError(path, "'command' names no command", where)
    return tuple(words)


def toml_string(text: str) -> str:
    """``text`` as a TOML basic string (quoted, with backslash escapes).

    >>> print(toml_string('a "b" \\\\ c'))
    "a \\"b\\" \\\\ c"
    """
    escapes = {'"': '\\"', "\\": "\\\\", "\b": "\\b", "\t": "\\t", "\n": "\\n", "\f": "\\f",
               "\r": "\\r"}  # fmt: skip
    out = []
    for ch in text:
        if ch in escapes:
            out.append(escapes[ch])
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04X}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def entry_text(file: str, command: str, fmt: str, rtol: float | None, atol: float | None) -> str:
    """The TOML text of one ``[[table]]`` entry."""
    lines = ["[[table]]", f"file = {toml_string(file)}", f"command = {toml_string(command)}",
             f"format = {toml_string(fmt)}"]  # fmt: skip
    lines += [f"{key} = {value!r}" for key, value in (("rtol", rtol), ("atol", atol))
              if value is not None]  # fmt: skip
    return "\n".join(lines) + "\n"


def appended(manifest: Manifest | None, directory: str, text: str) -> tuple[str, Manifest]:
    """A manifest's text with one more entry (``text``), and that text read back: the new entry
    must come back as written (else :class:`ManifestError`)."""
    old = manifest.text if manifest is not None else ""
    header = "# Tables of this folder: 'bearingload tables check' compares, 'update' rewrites.\n"
    if not old.strip():
        new = header + "\n" + text
    else:
        new = old + ("" if old.endswith("\n") else "\n") + "\n" + text
    parsed = parse_manifest(new, directory)
    return new, parsed
