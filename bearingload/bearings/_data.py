"""The catalogue's csv files (``bearingload/bearings/data``), read from beside this module.

They are read by path rather than through :mod:`importlib.resources`, whose import (pathlib,
tempfile, shutil, zipfile) costs about 10 ms of every catalogue command's start-up; the package is
installed as files (a wheel or an editable install), never imported from a zip.
"""

from __future__ import annotations

import csv
import os

_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")


def read_rows(name: str, first: str | None = None) -> list[dict[str, str]]:
    """Every row of ``data/<name>`` as a dict keyed by the header, in file order; with
    ``first``, only the rows whose first cell is ``first``.

    A row is one line in these files (no cell holds a line break: a test checks it), so with
    ``first`` only the header and the lines that may hold it (starting with it and a comma, or
    with a quote) are parsed: one designation of the catalogue is read without parsing its
    other rows (about 0.6 ms of a terminal command; 1.5 ms for the ball sets).

    Parameters
    ----------
    name : str
        File name inside ``bearingload/bearings/data``, e.g. ``"bearings.csv"``.
    first : str, optional
        The first cell (the designation) of the rows wanted; None: every row.

    Returns
    -------
    list of dict
        One ``{column: cell text}`` per data row.
    """
    with open(os.path.join(_DIR, name), encoding="utf-8", newline="") as handle:
        if first is None:
            return list(csv.DictReader(handle))
        header = handle.readline()
        lines = [line for line in handle if line.startswith((f"{first},", '"'))]
    column = next(csv.reader([header]))[0]
    return [row for row in csv.DictReader([header, *lines]) if row[column] == first]
