"""The stability reports: one table per kind of family (:mod:`bearingload.quality.stability`,
:mod:`bearingload.quality.stability_combined`), each study giving its rows, ``TITLE``, ``KEYS``
and ``NOTES``."""

from __future__ import annotations

from types import ModuleType
from typing import Any

from bearingload.reports.quantities import column
from bearingload.reports.render import Table, table_document


def stability_table(study: ModuleType, rows: list[dict[str, Any]]) -> Table:
    """The summary of ``study``'s families, one row per family."""
    return Table(study.TITLE, tuple(column(k) for k in study.KEYS), rows, study.NOTES)


def stability_document(tables: dict[str, Table]) -> dict[str, Any]:
    """The one JSON document of a run: each kind's table (``radial``, ``combined``, those run)
    under its name."""
    return {kind: table_document(t) for kind, t in tables.items()}
