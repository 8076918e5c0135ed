"""One registry of the load-distribution models, so that they can be listed, run and timed side by side.

The registry holds the cited model functions themselves (by module and name, imported on first
use), with their citation, the common inputs they ignore (read off their signatures) and their
range of validity. Every model is run the same way,

    compute(name, balls, load, stiffness, clearance=0.0, cage_angle=0.0, exponent=1.5) -> Result

with the package's units (N, mm, N/mm^m, degrees) and the conventions of
:mod:`bearingload.models.equilibrium` (outer ring fixed, radial load ``F_r`` on the inner ring,
angles from the load line; ``clearance`` is the radial internal clearance ``G_r``, total play;
negative = preload). The inputs are checked once, as a :class:`~bearingload.models.case.Case`
(a negative stiffness is an error for Stribeck too, so every model accepts and rejects the same
cases; the one exception is the exact model, which has no equilibrium with one or two balls when
no ball sits on the load line), and every model answers with one
:class:`~bearingload.models.case.Result`.

The models (exact, continuum, stribeck, palmgren: :func:`_build`), their sources and what each
ignores: docs/models.md; adding one: docs/architecture.md ("Adding a model").

Importing this module imports no numpy (the command line lists the models at start-up).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

from bearingload.errors import InputError

#: The default method of :func:`compute` and of ``bearingload solve``.
DEFAULT_METHOD = "exact"


class Method:
    """A registered model: its function and what to tell the user about it (a plain class,
    read by attribute only: no dataclass to build when the command line lists the methods).

    Attributes
    ----------
    name : str
        Registry key.
    module, function : str
        Where the model function lives (imported on first use).
    title : str
        One line: the model and its source.
    validity : str
        The range of validity in words ("" where the model applies to every case).
    is_valid : callable or None
        ``is_valid(case, result) -> bool array``: whether each case lies inside that range.
    """

    __slots__ = ("name", "module", "function", "title", "validity", "is_valid")

    def __init__(
        self,
        name: str,
        module: str,
        function: str,
        title: str,
        validity: str = "",
        is_valid: Callable[[Any, Any], Any] | None = None,
    ) -> None:
        self.name = name
        self.module = module
        self.function = function
        self.title = title
        self.validity = validity
        self.is_valid = is_valid

    def model(self) -> Callable[..., Any]:
        """The model function itself."""
        import importlib

        return getattr(importlib.import_module(self.module), self.function)

    @property
    def ignores(self) -> tuple[str, ...]:
        """The case inputs the model does not use (those missing from its signature)."""
        from bearingload.models.case import INPUTS

        params = _parameters(self.module, self.function)
        return tuple(name for name in INPUTS if name not in params)

    def __call__(
        self,
        balls: Any,
        load: Any,
        stiffness: Any,
        clearance: Any = 0.0,
        cage_angle: Any = 0.0,
        exponent: Any = 1.5,
    ) -> Any:
        from bearingload.models.case import Case

        return self.run(Case.of(balls, load, stiffness, clearance, cage_angle, exponent))

    def run(self, case: Any) -> Any:
        """Run the model on a :class:`~bearingload.models.case.Case`; a :class:`Result`."""
        import dataclasses

        import numpy as np

        from bearingload.models.case import RESULT_QUANTITIES, Result
        from bearingload.numerics import scalar_out

        params = _parameters(self.module, self.function)
        out = self.model()(**{k: v for k, v in case.inputs().items() if k in params})
        values = {}
        for name in RESULT_QUANTITIES:
            v = getattr(out, name, None)
            values[name] = None if v is None else scalar_out(np.broadcast_to(v, case.shape).copy())
        result = Result(self.name, case, model=out, **values)
        if self.is_valid is None:
            return result
        valid = np.broadcast_to(self.is_valid(case, result), case.shape)
        return dataclasses.replace(result, valid=scalar_out(valid.copy()))


@functools.cache
def _parameters(module: str, function: str) -> frozenset[str]:
    """The parameter names of a model function, read once per function."""
    import importlib
    import inspect

    model = getattr(importlib.import_module(module), function)
    return frozenset(inspect.signature(model).parameters)


def _continuum_valid(case: Any, result: Any) -> Any:
    """The load zone spans at least one pitch: 2 psi_l >= 360/z."""
    import numpy as np

    return 2.0 * np.asarray(result.load_zone) >= 360.0 / case.balls


def _ball_zero_clearance(case: Any, result: Any) -> Any:
    """Stribeck: point contact, zero clearance, and k = 4.37/z <= 1 (z >= 5)."""
    return (case.clearance == 0) & (case.exponent == 1.5) & (case.balls >= 5)


def _ball_bearing(case: Any, result: Any) -> Any:
    """Palmgren: point contact (normal clearance), and k = 5/z <= 1 (z >= 5)."""
    return (case.exponent == 1.5) & (case.balls >= 5)


def _build() -> dict[str, Method]:
    return {
        "exact": Method(
            "exact",
            "bearingload.models.equilibrium",
            "solve",
            "exact ring equilibrium of the discrete balls (Kurochkin 1973; Kuzmenko 2010, §1-3)",
        ),
        "continuum": Method(
            "continuum",
            "bearingload.models.continuum",
            "solve_continuum",
            "continuum model, each ball's load smeared over its pitch (Kuzmenko 2010, §4-5)",
            "a load zone at least one ball pitch wide (2 psi_l >= 360°/z)",
            _continuum_valid,
        ),
        "stribeck": Method(
            "stribeck",
            "bearingload.models.approximations",
            "stribeck",
            "Stribeck (1901): Q_max = 4.37 F_r/z",  # approximations.STRIBECK_CONSTANT
            "ball bearings (m = 1.5) with zero clearance and at least 5 balls",
            _ball_zero_clearance,
        ),
        "palmgren": Method(
            "palmgren",
            "bearingload.models.approximations",
            "palmgren",
            "Palmgren (1959): Q_max = 5 F_r/z",  # approximations.PALMGREN_CONSTANT
            "ball bearings (m = 1.5) with a normal clearance and at least 5 balls",
            _ball_bearing,
        ),
    }


#: The registered methods, in the order they are listed and compared.
METHODS: dict[str, Method] = _build()


def list_methods() -> list[str]:
    """Names of the registered methods, :data:`DEFAULT_METHOD` first.

    Examples
    --------
    >>> list_methods()
    ['exact', 'continuum', 'stribeck', 'palmgren']
    """
    return list(METHODS)


def get_method(name: str) -> Method:
    """The registered method ``name``; :class:`InputError` (parameter ``method``) names the valid ones."""
    try:
        return METHODS[name]
    except (KeyError, TypeError):
        raise InputError(
            "method", f"unknown method {name!r}; valid: {', '.join(METHODS)}"
        ) from None


def compute(
    method: str,
    balls: Any,
    load: Any,
    stiffness: Any,
    clearance: Any = 0.0,
    cage_angle: Any = 0.0,
    exponent: Any = 1.5,
) -> Any:
    """Run one registered model: a :class:`~bearingload.models.case.Result`.

    Parameters
    ----------
    method : {'exact', 'continuum', 'stribeck', 'palmgren'}
        Name of the method (see :func:`list_methods`).
    balls, load, stiffness, clearance, cage_angle, exponent : int, float or array_like
        The case, checked once as a :class:`~bearingload.models.case.Case` (its attributes give
        each input's meaning, range and unit: N, mm, N/mm^m, °); by default no clearance, cage
        angle 0 and exponent 1.5.

    Returns
    -------
    Result
        ``k``, ``q_max``, ``K_Q``, and where the model gives them ``loaded_balls``,
        ``load_zone`` [°], ``x``, ``y`` [mm], ``stiffness_radial`` [N/mm]; ``valid``; ``model``.

    Raises
    ------
    InputError
        Unknown method (parameter ``method``) or an input outside its domain.

    Examples
    --------
    >>> r = compute("stribeck", 8, 1000.0, 1e5)
    >>> r.k, r.q_max, r.load_zone
    (0.54625, 546.25, None)
    >>> round(compute("exact", 8, 1000.0, 1e5).k, 4)
    0.5432
    """
    return get_method(method)(balls, load, stiffness, clearance, cage_angle, exponent)


def compute_all(
    balls: Any,
    load: Any,
    stiffness: Any,
    clearance: Any = 0.0,
    cage_angle: Any = 0.0,
    exponent: Any = 1.5,
) -> dict[str, Any]:
    """Run every registered model on the same inputs (checked once); name -> Result, in registry
    order."""
    from bearingload.models.case import Case

    case = Case.of(balls, load, stiffness, clearance, cage_angle, exponent)
    return {name: m.run(case) for name, m in METHODS.items()}


def relative_error(result: Any, reference: Any) -> Any:
    """``Q_max / Q_max,reference - 1`` (the same as the ratio of the ``k``). [-]"""
    import numpy as np

    from bearingload.numerics import scalar_out

    return scalar_out(np.asarray(result.q_max) / np.asarray(reference.q_max) - 1.0)
