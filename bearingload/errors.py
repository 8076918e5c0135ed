"""Exceptions raised by the library.

The library raises these; the command-line interface turns them into one ``Error:`` line
and a non-zero exit status.
"""

from __future__ import annotations

from typing import Any


class BearingloadError(Exception):
    """Base class of every error this package raises on purpose. Its errors copy and pickle
    with their fields (a worker process hands them back whole)."""

    def __reduce__(self) -> tuple[Any, ...]:
        return (_restore, (type(self), dict(self.__dict__), self.args))

    def _copy(self) -> Any:
        """The same error, its fields copied (a caller then changes some)."""
        return _restore(type(self), dict(self.__dict__), self.args)


def _restore(cls: type[Exception], state: dict[str, Any], args: tuple[Any, ...]) -> Any:
    """An error of ``cls`` with the fields ``state`` and the exception arguments ``args``."""
    error = cls.__new__(cls)
    error.__dict__.update(state)
    Exception.__init__(error, *args)
    return error


class InputError(BearingloadError, ValueError):
    """A parameter is outside its allowed domain.

    The fields say what is wrong and what to do; a caller rewording an error (the command line
    naming an option, a plan offering another engine) works on the fields, never on the text.
    Other inputs are named in quotes in ``message`` and ``way_out`` (``'speed'``), so that a
    front door can write them as the user types them.

    Parameters
    ----------
    parameter : str
        Name of the offending parameter, as the user knows it (``load``, ``balls`` ...).
    message : str
        What was wrong and what is allowed.
    way_out : str, optional
        What the user can do instead, appended to the message after ``; ``.
    reason : str, optional
        A stable tag of the refusal (``"too_fast"``, ``"too_light"`` ...) a caller may act on.
    element : str, optional
        Of an array input, the first offending element and its value (``[3] = -1 N``): the
        text reads ``radial_load[3] = -1 N: must be >= 0 N``; empty for one number.
    """

    def __init__(
        self,
        parameter: str,
        message: str,
        *,
        way_out: str | None = None,
        reason: str | None = None,
        element: str = "",
    ) -> None:
        self.parameter = parameter
        self.problem = message  # without the way out
        self.way_out = way_out
        self.reason = reason
        self.element = element
        self.message = message if way_out is None else f"{message}; {way_out}"
        super().__init__(f"{parameter}{element}: {self.message}")

    def named(self, parameter: str) -> InputError:
        """The same refusal (its kind and fields) naming its parameter as the caller calls it."""
        new = self._copy()
        new.parameter = parameter
        if isinstance(getattr(new, "parameters", None), tuple):
            new.parameters = (parameter, *new.parameters[1:])
        Exception.__init__(new, f"{parameter}{new.element}: {new.message}")
        return new

    def with_way_out(self, way_out: str) -> InputError:
        """The same refusal (its kind and fields) with another way out."""
        new = self._copy()
        new.way_out = way_out
        new.message = f"{new.problem}; {way_out}"
        Exception.__init__(new, f"{new.parameter}{new.element}: {new.message}")
        return new


class ConflictError(InputError):
    """A parameter that cannot be used with something else given: ``parameter`` cannot be used
    with ``where`` (other inputs named in quotes), ``why``."""

    def __init__(self, parameter: str, where: str, why: str) -> None:
        self.where, self.why = where, why
        super().__init__(parameter, f"cannot be used with {where}: {why}")


class MissingError(InputError):
    """A parameter that is required and was not given; ``message`` says what else would do."""

    def __init__(self, parameter: str, message: str) -> None:
        super().__init__(parameter, f"missing ({message})")
        self.instead = message


class UnusedError(InputError):
    """Parameters given that the case would ignore: ``parameters`` need ``need``."""

    def __init__(self, parameters: tuple[str, ...], need: str) -> None:
        self.parameters, self.need = parameters, need
        one = len(parameters) == 1
        super().__init__(
            parameters[0],
            f"{'needs' if one else 'need'} {need} {'it' if one else 'they'} would be ignored",
        )


class ConvergenceError(BearingloadError, ArithmeticError):
    """An iterative solver did not converge; carries the data needed to reproduce it.

    The message names the failing cases' inputs as numbers (with their units where the solver
    gives them), never as numpy arrays: ``... for the case radial_load = 1000 N, clearance =
    0.02 mm``; see :func:`format_cases`.

    Attributes
    ----------
    solver : str
        Name of the solver.
    iterations : int
        Iterations spent.
    residual : float
        Largest relative residual left when the solver gave up. [-]
    cases : dict
        The input values of the failing cases (arrays), keyed by parameter name.
    units : dict or None
        The unit of each input's values in ``cases``.
    typed : dict or None
        Of an input whose failing cases all have the value the user gave it with a unit, the
        text as given (``"0.1kN"``), which the message writes instead of the number in its
        unit (``cases`` keeps the number).
    rows : array of int or None
        Of an array call, the failing cases by their flat index among the call's cases (the
        inputs broadcast together, C order), where the solver knows them; None otherwise.
    """

    def __init__(
        self,
        solver: str,
        iterations: int,
        residual: float,
        cases: dict[str, Any],
        units: dict[str, str] | None = None,
        way_out: str | None = None,
        typed: dict[str, str] | None = None,
        rows: Any = None,
    ) -> None:
        self.solver = solver
        self.rows = rows
        self.iterations = iterations
        self.residual = residual
        self.cases = cases
        self.units = units
        self.way_out = way_out
        self.typed = typed
        import numpy as np  # here: importing the errors must stay light (no numpy)

        count = max((int(np.size(v)) for v in cases.values()), default=1)
        what = "" if not cases else " for " + ("the case " if count == 1 else f"{count} cases: ")
        what += format_cases(cases, units, typed)
        super().__init__(
            f"{solver} did not converge after {iterations} iterations "
            f"(relative residual {residual:.3g}){what}"
            + ("" if way_out is None else f"; {way_out}")
        )

    def with_way_out(self, way_out: str) -> ConvergenceError:
        """The same failure with what the user can do instead."""
        return ConvergenceError(
            self.solver,
            self.iterations,
            self.residual,
            self.cases,
            self.units,
            way_out,
            self.typed,
            self.rows,
        )


#: At most this many values of one input are written into a message. [-]
SHOWN_VALUES = 4


def format_cases(
    cases: dict[str, Any],
    units: dict[str, str] | None = None,
    typed: dict[str, str] | None = None,
) -> str:
    """``name = value unit, ...`` of the inputs of some cases, for a message.

    Values are written with 6 significant digits (no ``array(...)``); of several cases, the
    first :data:`SHOWN_VALUES` and how many there are (one value where all are equal). An input
    in ``typed`` is written as that text (as the user gave it: ``load = 0.1kN``).

    >>> import numpy as np
    >>> format_cases({"balls": 8, "load": np.array([1.0, 2.5e-7]), "clearance": np.float64(0.02)},
    ...              {"load": "N", "clearance": "mm"})
    'balls = 8, load = 1 and 2.5e-07 N, clearance = 0.02 mm'
    >>> format_cases({"load": np.arange(6.0)}, {"load": "N"})
    'load = 0, 1, 2, 3, ... (6 values) N'
    >>> format_cases({"load": 100.0, "speed": 3000.0}, {"load": "N", "speed": "rpm"},
    ...              {"load": "0.1kN"})
    'load = 0.1kN, speed = 3000 rpm'
    """
    import numpy as np

    units, typed = units or {}, typed or {}
    parts = []
    for name, value in cases.items():
        if name in typed:
            parts.append(f"{name} = {typed[name]}")
            continue
        flat = np.asarray(value).reshape(-1)
        if flat.size > 1 and np.all(flat == flat[0]):
            flat = flat[:1]  # the same value for every case: once
        if flat.dtype.kind in "fciub" and flat.size:
            numbers = [format(x.item(), ".6g") for x in flat[:SHOWN_VALUES]]
            if flat.size > SHOWN_VALUES:
                text = ", ".join(numbers) + f", ... ({flat.size} values)"
            elif len(numbers) > 1:
                text = ", ".join(numbers[:-1]) + " and " + numbers[-1]
            else:
                text = numbers[0]
        else:
            text = ", ".join(str(x) for x in flat[:SHOWN_VALUES]) or "none"
        unit = units.get(name)
        parts.append(f"{name} = {text}" + (f" {unit}" if unit else ""))
    return ", ".join(parts)
