"""The rows of a file of bearing pairs (a column ``arrangement``, ``preload`` or ``width``: the
options of ``solve 7205BDB --preload 500N`` ...): each row a pair solved by the plan
(:mod:`bearingload.plan.many_pairs`), written as solve's csv rows of the pair (one per bearing,
``bearing_number`` 1 and 2; :func:`bearingload.reports.pair.csv_rows`)."""

from __future__ import annotations

from typing import Any

from bearingload.batch.read import row_message
from bearingload.batch.report import pair_columns
from bearingload.errors import BearingloadError


def pair_rows(
    header: Any, many: Any, numbers: list[int], cols: dict[str, list[Any]], errors: dict[int, str]
) -> tuple[list[int], dict[str, list[Any]]]:
    """The output rows of the solved pairs (two per pair: its row number twice) with the values
    of the file's columns, as solve gives the pair with the row's service cells as its options;
    ``warnings`` (the pair's, its speed's and its lives') on the first row of each pair; each
    bearing's model and contacts (json: :data:`bearingload.batch.report.HELD_KEYS`). A pair
    whose records solve would refuse is a skipped row with its reason (in ``errors``)."""
    from bearingload.bearings.oil import OIL_INPUTS
    from bearingload.reports.combined import contact_values
    from bearingload.reports.pair import csv_rows, pair_records
    from bearingload.reports.solve import printed_warnings

    keys = [c.key for c in pair_columns(None) if c.key != "row"]
    oil = [k for k in OIL_INPUTS if k in header.names]  # written as given (nu is the oil's)
    rows: list[int] = []
    values: dict[str, list[Any]] = {k: [] for k in [*keys, *oil, "warnings"]}
    solved = many.values.get("pair", []), many.values.get("lives", [])
    for i, pc, lives in zip(many.rows, *solved, strict=True):
        try:
            pair, records = pair_records(pc, lives)
        except BearingloadError as exc:
            errors[numbers[i]] = row_message(exc)
            continue
        warned = tuple(printed_warnings(pc.warnings, lives.bearings))
        for j, row in enumerate(csv_rows(pc, pair, records, keys)):
            rows.append(numbers[i])
            row |= {k: cols[k][i] for k in oil} | {"warnings": () if j else warned}
            row |= contact_values(pc.bearings[j].result, pc.bearing.contact_angle)
            for k, v in row.items():
                values.setdefault(k, []).append(v)
    return rows, values
