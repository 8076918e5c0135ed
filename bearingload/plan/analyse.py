"""``analyse``: one library call from a designation (or a ring given by hand) and its loads to
what ``bearingload solve`` prints: the loads of every ball, the stiffness, the lives."""

from __future__ import annotations

from typing import Any

from bearingload.errors import InputError
from bearingload.plan.solution import Solution


def analyse(
    bearing: str | None = None,
    *,
    method: str = "exact",
    revolutions: float | str | None = None,
    **options: Any,
) -> Solution:
    """Analyse one bearing as ``bearingload solve`` does, with the same decisions.

    Parameters
    ----------
    bearing : str, optional
        A catalogue designation (``"6205"``, ``"6306-2RS/C3"``, ``"7205BDB"``, ``"NU206"``); None
        for a ring given by hand (``balls=`` with ``stiffness=`` or ``ball_diameter=`` and
        ``pitch_diameter=``).
    method : str
        The radial engine's method: ``exact`` (default), ``continuum``, ``stribeck``,
        ``palmgren`` or ``all``.
    revolutions : float or str, optional
        Life L of the radial engine's allowable load C/(L/10^6)^(1/3) [rev]; default 36e6.
    **options
        The options of ``bearingload solve`` by their snake_case names (``load``,
        ``axial_load``, ``clearance``, ``speed``, ``preload``, ``viscosity`` ...): numbers in the
        command line's default units (N, mm, N mm, °, rpm, mm^2/s, °C), or strings with units
        (``load="1kN"``, ``clearance="C3"``, ``clearance="20um"``).

    Returns
    -------
    Solution
        ``to_dict()`` is what ``bearingload solve --format json`` prints (at full precision);
        every key of a case is an attribute (``solution.q_max``); ``report(fmt)``
        renders it as the command line does.

    Raises
    ------
    InputError
        An input outside its domain, or inputs that cannot be given together; ``parameter``
        names the argument.
    ConvergenceError
        A solver did not converge (never expected inside the stated domain).

    Examples
    --------
    >>> from bearingload import analyse
    >>> s = analyse("6205", load="1.4kN", axial_load=700, clearance="C3")
    >>> round(s.q_max, 1), s.engine
    (889.6, 'combined')
    """
    try:
        return _analyse(bearing, method, revolutions, options)
    except InputError as exc:  # a model's name of an input, as the caller calls it
        called = as_called(exc)
        if called is exc:
            raise
        raise called from None


def as_called(exc: Exception, case: Any = None) -> Exception:
    """The error ``exc`` as :func:`analyse` raises it: an input a model names by its own name
    named by its argument (``radial_load`` -> ``load``, :func:`bearingload.plan.inputs.
    argument_of`); a :class:`~bearingload.errors.ConvergenceError` of the
    :class:`~bearingload.plan.case.Case` ``case`` naming its inputs as the case does
    (:func:`bearingload.plan.solve.in_case_terms`); ``exc`` itself where nothing changes."""
    from bearingload.errors import ConvergenceError
    from bearingload.plan.inputs import argument_of

    if isinstance(exc, InputError):
        name = argument_of(exc.parameter)
        return exc if name == exc.parameter else exc.named(name)
    if isinstance(exc, ConvergenceError) and case is not None:
        from bearingload.plan.solve import in_case_terms

        return in_case_terms(exc, case)
    return exc


def read_arguments(
    bearing: Any, revolutions: Any, options: dict[str, Any]
) -> tuple[dict[str, Any], set[str], float | None]:
    """(the inputs of a case, None where not given; the names of those given as bare numbers;
    the life ``revolutions`` [rev] or None) read from :func:`analyse`'s arguments: each option
    by its reader (:data:`bearingload.plan.inputs.READERS`), the load required as solve
    requires ``--load``."""
    from bearingload.errors import MissingError
    from bearingload.plan.case import LOAD_NEEDED
    from bearingload.plan.inputs import quantity, read_inputs, text
    from bearingload.units import is_bare

    values = read_inputs(options)
    if values.get("load") is None:  # as solve requires --load
        raise MissingError("load", LOAD_NEEDED)
    if bearing is not None:
        values["bearing"] = text(bearing, "bearing")
    bare = {
        n for n, v in options.items() if v is not None and not isinstance(v, bool) and is_bare(v)
    }
    revolutions_of = quantity("revolutions", positive=True)
    life = None if revolutions is None else revolutions_of(revolutions, "revolutions")
    return values, bare, life


def _analyse(
    bearing: str | None, method: str, revolutions: float | str | None, options: dict[str, Any]
) -> Solution:
    from bearingload.plan.case import Case
    from bearingload.plan.solve import solve_case

    values, bare, life = read_arguments(bearing, revolutions, options)
    given = {n for n, v in values.items() if v is not None}
    case = Case.of(values, given=given, bare=bare, typed=typed_texts(options))
    return solve_case(case, method=method, revolutions=life)


def typed_texts(options: dict[str, Any]) -> dict[str, str]:
    """The text of each option given as a string with a unit (``"0.1kN"``), by its name."""
    from bearingload.units import is_bare

    return {n: v.strip() for n, v in options.items() if isinstance(v, str) and not is_bare(v)}
