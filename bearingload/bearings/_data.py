"""The catalogue's csv files (``bearingload/bearings/data``), read from beside this module.

They are read by path rather than through :mod:`importlib.resources`, whose import (pathlib,
tempfile, shutil, zipfile) costs about 10 ms of every catalogue command's start-up; the package is
installed as files (a wheel or an editable install), never imported from a zip.
"""

from __future__ import annotations

import csv
import os

_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")


def read_rows(name: str) -> list[dict[str, str]]:
    """Every row of ``data/<name>`` as a dict keyed by the header, in file order.

    Parameters
    ----------
    name : str
        File name inside ``bearingload/bearings/data``, e.g. ``"bearings.csv"``.

    Returns
    -------
    list of dict
        One ``{column: cell text}`` per data row.
    """
    with open(os.path.join(_DIR, name), encoding="utf-8", newline="") as handle:
        return list(csv.DictReader(handle))
