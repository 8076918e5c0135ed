"""``analyse_many``: many cases as :func:`bearingload.analyse` takes one, read by the same
reader (:func:`bearingload.plan.analyse.read_arguments`), solved together on arrays by the plan
of many cases (:class:`bearingload.plan.many.Planner`), as ``bearingload batch`` solves a file.

Each case is planned by its own inputs only: a pair or a single bearing as the plan of one case
decides (:meth:`bearingload.plan.case.Case.as_pair`), the pairs and the single bearings solved
as two groups by their planners, their answers merged by the cases' indices; every refusal is
the error :func:`bearingload.analyse` raises for the case alone."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

from bearingload.errors import BearingloadError, InputError
from bearingload.plan.analyse import as_called
from bearingload.plan.case import Case
from bearingload.plan.many import PAIR_PARAMS, Many, Planner, merged

#: Arguments of a case that are no input of a :class:`~bearingload.plan.case.Case`.
_NOT_CASE = ("bearing", "method", "revolutions")

#: One case as read: (its inputs, those given as bare numbers the bearing's size judges, its
#: :class:`~bearingload.plan.case.Case`).
Read = tuple[dict[str, Any], list[str], Case]


def analyse_many(cases: Iterable[Mapping[str, Any]]) -> Many:
    """Analyse many cases as :func:`bearingload.analyse` analyses one, the cases that share a
    bearing and an engine solved together on arrays (batch's way); each case's answer and
    refusal depend on its own arguments only.

    Parameters
    ----------
    cases : iterable of mappings
        Each case's arguments of :func:`bearingload.analyse` (``bearing``, ``load``,
        ``axial_load``, ``speed`` ..., ``method``, ``revolutions``): numbers in the command
        line's default units or strings with units. A case is a pair as ``analyse`` takes one:
        with an input of a pair (``arrangement``, ``preload``, ``width``) or a designation that
        names a pair (``7205BDB``).

    Returns
    -------
    Many
        ``rows`` the indices of the cases solved, in order; ``values`` the quantities of
        ``bearingload batch`` over them (key -> array or list, aligned with ``rows``): of a
        single bearing its columns (``q_max``, ``rating_life`` ...), of a pair ``pair`` (the
        solved :class:`~bearingload.studies.bearing_pair.PairCase`) and ``lives`` (its
        :class:`~bearingload.studies.bearing_pair.PairLives`); a list with None where a
        quantity does not apply to a row's kind (a pair's ``q_max``, a single bearing's
        ``pair``). ``errors`` the refusal of each case not solved, by index: the error
        ``analyse`` raises for the case alone.

    Raises
    ------
    InputError
        ``cases`` a single mapping, or not iterable; a case that is no mapping is refused in
        ``errors`` (``cases[1]: must be a mapping of analyse's arguments, by their names``).

    Examples
    --------
    >>> from bearingload import analyse_many
    >>> many = analyse_many([{"bearing": "6205", "load": "1kN"}, {"bearing": "6205", "load": -1e3}])
    >>> many.rows, [round(float(q), 1) for q in many.values["q_max"]], many.errors[1].parameter
    ([0], [541.7], 'load')
    """
    if isinstance(cases, Mapping) or not isinstance(cases, Iterable):
        raise InputError(
            "cases", "must be an iterable of mappings of analyse's arguments (one case: [case])"
        )
    read: dict[int, Read] = {}
    errors: dict[int, Exception] = {}
    pairs: list[int] = []
    singles: list[int] = []
    for i, given in enumerate(cases):
        if not isinstance(given, Mapping) or not all(isinstance(k, str) for k in given):
            why = "must be a mapping of analyse's arguments, by their names"
            errors[i] = InputError("cases", why, element=f"[{i}]")
            continue
        try:
            read[i] = _read_case(given)
        except BearingloadError as exc:
            errors[i] = as_called(exc, None)
            continue
        (pairs if _is_pair(read[i][2]) else singles).append(i)
    parts = []
    if singles:
        parts.append(_solve_group(singles, read, pairs=False))
    if pairs:
        parts.append(_solve_group(pairs, read, pairs=True))
    many = parts[0] if len(parts) == 1 else merged([(p.rows, p.values) for p in parts])
    for part in parts:
        errors |= part.errors
    many.errors = dict(sorted(errors.items()))
    return many


def _is_pair(case: Case) -> bool:
    """Whether a case is a pair, as the plan of one case takes it
    (:meth:`~bearingload.plan.case.Case.as_pair`): an input of a pair given, or a designation
    that names a pair; a designation not read is left to the plan of a single bearing, which
    refuses it as one case's plan does."""
    if any(getattr(case, n) is not None for n in PAIR_PARAMS):
        return True
    try:
        return case.as_pair() is not None
    except InputError:
        return False


def _solve_group(idx: list[int], read: dict[int, Read], *, pairs: bool) -> Many:
    """The cases ``idx`` (all pairs, or all single bearings) solved by their planner; rows and
    errors by the cases' indices, each error as ``analyse`` raises it."""
    names = list(dict.fromkeys(k for i in idx for k in read[i][0]))
    cols = {k: [read[i][0].get(k) for i in idx] for k in names}
    bare: dict[str, list[bool]] = {}
    for j, i in enumerate(idx):
        for k in read[i][1]:
            bare.setdefault(k, [False] * len(idx))[j] = True
    planner = Planner(names, per_case=True)
    if pairs:
        from bearingload.plan.many_pairs import solve_pair_cases

        solved = solve_pair_cases(planner, cols, len(idx), {}, bare)
    else:
        typed = [dict(read[i][2].typed) for i in idx]
        solved = planner.solve(cols, len(idx), {}, bare, typed)
    errors = {idx[j]: as_called(exc, read[idx[j]][2]) for j, exc in solved.errors.items()}
    return Many([idx[j] for j in solved.rows], solved.values, errors)


def _read_case(given: Mapping[str, Any]) -> Read:
    """One case's arguments read as :func:`bearingload.analyse` reads them
    (:func:`~bearingload.plan.analyse.read_arguments`; ``method`` by
    :func:`~bearingload.plan.solve.check_method`), ``stiffness`` into N/mm^m; what one call on
    arrays cannot give (the clearance pick 'range', ``method`` 'all') refused."""
    from bearingload.bearings.plausible import BEARING_SCALE
    from bearingload.plan.analyse import read_arguments, typed_texts
    from bearingload.plan.bearing import refuse_range
    from bearingload.plan.solve import check_method

    options = {k: v for k, v in given.items() if k not in _NOT_CASE}
    values, bare, life = read_arguments(given.get("bearing"), given.get("revolutions"), options)
    values = {k: v for k, v in values.items() if v is not None}
    case = Case.of(values, typed=typed_texts(options))
    case.check_load(radial=False, combined=case.takes_combined)  # below 0: as analyse refuses it
    method = given.get("method")
    pair = _is_pair(case)  # a pair's own refusals (the exact model only ...) come first
    if "method" in given:
        check_method(method)
        if method == "all" and not pair:
            raise InputError(
                "method",
                "'all' (every method side by side) is analyse's; analyse_many takes one method "
                "per case",
            )
        values["method"] = method
    if life is not None:
        values["revolutions"] = life
    if not pair:
        refuse_range(case, "analyse_many")
    if "stiffness" in values:
        values["stiffness"] = case.stiffness_value()
    return values, sorted(n for n in bare if n in BEARING_SCALE), case
