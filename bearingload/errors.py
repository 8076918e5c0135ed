"""Exceptions raised by the library.

The library raises these; the command-line interface turns them into one ``Error:`` line
and a non-zero exit status.
"""

from __future__ import annotations

from typing import Any


class BearingloadError(Exception):
    """Base class of every error this package raises on purpose."""


class InputError(BearingloadError, ValueError):
    """A parameter is outside its allowed domain.

    Parameters
    ----------
    parameter : str
        Name of the offending parameter, as the user knows it (``load``, ``balls`` ...).
    message : str
        What was wrong and what is allowed.
    """

    def __init__(self, parameter: str, message: str) -> None:
        self.parameter = parameter
        super().__init__(f"{parameter}: {message}")


class ConvergenceError(BearingloadError, ArithmeticError):
    """An iterative solver did not converge; carries the data needed to reproduce it.

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
    """

    def __init__(
        self, solver: str, iterations: int, residual: float, cases: dict[str, Any]
    ) -> None:
        self.solver = solver
        self.iterations = iterations
        self.residual = residual
        self.cases = cases
        super().__init__(
            f"{solver} did not converge after {iterations} iterations "
            f"(relative residual {residual:.3g}) for the cases {cases}"
        )
