"""``analyse_many``: many cases as :func:`bearingload.analyse` takes one, read by the same
readers (:data:`bearingload.plan.inputs.READERS`), solved together on arrays by the plan of
many cases (:class:`bearingload.plan.many.Planner`), as ``bearingload batch`` solves a file."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from bearingload.errors import BearingloadError
from bearingload.plan.case import Case
from bearingload.plan.many import Many, Planner

#: Arguments of a case that are no input of a :class:`~bearingload.plan.case.Case`.
_NOT_CASE = ("bearing", "method", "revolutions")


def analyse_many(cases: Sequence[Mapping[str, Any]]) -> Many:
    """Analyse many cases as :func:`bearingload.analyse` analyses one, the cases that share a
    bearing and an engine solved together on arrays (batch's way).

    Parameters
    ----------
    cases : sequence of mappings
        Each case's arguments of :func:`bearingload.analyse` (``bearing``, ``load``,
        ``axial_load``, ``speed`` ..., ``method``, ``revolutions``): numbers in the command
        line's default units or strings with units. A case with an input of a pair
        (``arrangement``, ``preload``, ``width``) makes every case a pair.

    Returns
    -------
    Many
        ``rows`` the indices of the cases solved; ``values`` the columns of
        ``bearingload batch`` over them (of a pair: ``pair``, the solved pairs, and ``lives``,
        their :class:`~bearingload.studies.bearing_pair.PairLives`); ``errors`` the refusal of each case not solved, by index.

    Examples
    --------
    >>> from bearingload import analyse_many
    >>> many = analyse_many([{"bearing": "6205", "load": "1kN"}, {"bearing": "6205", "load": -1e3}])
    >>> many.rows, [round(float(q), 1) for q in many.values["q_max"]], str(many.errors[1])
    ([0], [541.7], 'load: must be greater than 0 N (got -1000)')
    """
    names = list(dict.fromkeys(k for c in cases for k, v in c.items() if v is not None))
    cols: dict[str, list[Any]] = {k: [None] * len(cases) for k in names}
    bare: dict[str, list[bool]] = {}
    bad: dict[int, Exception] = {}
    for i, given in enumerate(cases):
        try:
            values = _read_case(given)
        except BearingloadError as exc:
            bad[i] = exc
            continue
        for k, x in values.items():
            cols[k][i] = x
        for k in _bare(given):
            bare.setdefault(k, [False] * len(cases))[i] = True
    planner = Planner(names)
    if planner.pairs:
        from bearingload.plan.many_pairs import solve_pair_cases

        return solve_pair_cases(planner, cols, len(cases), bad, bare)
    return planner.solve(cols, len(cases), bad, bare)


def _read_case(given: Mapping[str, Any]) -> dict[str, Any]:
    """One case's arguments read by the plan's readers (``stiffness`` into N/mm^m)."""
    from bearingload.plan.bearing import refuse_range
    from bearingload.plan.inputs import quantity, read_inputs, text

    options = {k: v for k, v in given.items() if k not in _NOT_CASE}
    values = {k: v for k, v in read_inputs(options).items() if v is not None}
    if given.get("bearing") is not None:
        values["bearing"] = text(given["bearing"], "bearing")
    if given.get("method") is not None:
        values["method"] = text(given["method"], "method")
    if given.get("revolutions") is not None:
        read = quantity("revolutions", positive=True)  # as analyse reads it
        values["revolutions"] = read(given["revolutions"], "revolutions")
    case = Case.of({k: v for k, v in values.items() if k not in _NOT_CASE[1:]})
    refuse_range(case, "analyse_many")
    if "stiffness" in values:
        values["stiffness"] = case.stiffness_value()
    return values


def _bare(given: Mapping[str, Any]) -> list[str]:
    """The inputs given as a bare number that the bearing's size judges."""
    from bearingload.bearings.plausible import BEARING_SCALE
    from bearingload.units import is_bare

    return [
        k
        for k, v in given.items()
        if k in BEARING_SCALE and v is not None and not isinstance(v, bool) and is_bare(v)
    ]
