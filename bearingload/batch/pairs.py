"""The rows of a file of bearing pairs (a column ``arrangement``, ``preload`` or ``width``: the
options of ``solve 7205BDB --preload 500N`` ...): each row a pair solved by the plan
(:mod:`bearingload.plan.many_pairs`), written as solve's csv rows of the pair (one per bearing,
``bearing_number`` 1 and 2; :func:`bearingload.reports.pair.csv_rows`)."""

from __future__ import annotations

from typing import Any

from bearingload.batch.read import row_message
from bearingload.errors import BearingloadError


def pair_columns(service: set[str] | None) -> list[Any]:
    """The output columns of a file of pairs: ``row``, then those ``solve 7205BDB --format
    csv`` writes with the service options the file's columns give (``service``: the service
    keys they make, :func:`bearingload.batch.report.batch_columns`; None: every one), the
    pair's as ``pair_...`` (the pair's cross moment in ``pair_moment_cross``; a bearing's
    record has no ``moment_cross``)."""
    from bearingload.bearings.mounting import RESULT_KEYS
    from bearingload.reports.pair import OWN_KEYS, PAIR_SERVICE, csv_columns
    from bearingload.reports.quantities import SERVICE_KEYS
    from bearingload.reports.solve import column

    unused = {*SERVICE_KEYS, "ball_density", "rating_life_hours", "reference_rating_life_hours"}
    # a pair takes no mounting (bearings.mounting refuses it): no operating clearance
    unused = {"moment_cross", *RESULT_KEYS} | (set() if service is None else unused - service)
    pair = [k for k in PAIR_SERVICE if service is None or k in service]
    return [column("row"), *csv_columns(pair, [k for k in OWN_KEYS if k not in unused])]


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
        for j, row in enumerate(csv_rows(pc, pair, records, keys)):
            rows.append(numbers[i])
            for k in keys:
                values[k].append(row[k])
            for k in oil:
                values[k].append(cols[k][i])
            values["warnings"].append(
                tuple(printed_warnings(pc.warnings, lives.bearings) if j == 0 else ())
            )
            held = contact_values(pc.bearings[j].result, pc.bearing.contact_angle)
            for k, v in held.items():
                values.setdefault(k, []).append(v)
    return rows, values
