"""One registry of the load-distribution methods, so that they can be listed, run and timed side by side.

Every method is called the same way,

    method(balls, load, stiffness, clearance=0.0, cage_angle=0.0, exponent=1.5) -> MethodResult,

with the package's units (N, mm, N/mm^m, degrees) and the conventions of
:mod:`bearingload.models.equilibrium` (outer ring fixed, radial load ``F_r`` on the inner ring, angles from
the load line; ``clearance`` is the radial internal clearance ``G_r``, total play; negative =
preload). Inputs broadcast as in the underlying functions.

=========  ==============================================================  =======================
name       model                                                           ignores
=========  ==============================================================  =======================
exact      ring equilibrium of the discrete balls (Kurochkin 1973;         nothing
           Kuzmenko 2010, §1-3), :func:`bearingload.models.equilibrium.solve`
continuum  balls smeared over the raceway (Kuzmenko 2010, §4-5; Sjövall    cage angle
           load-zone integral), :func:`bearingload.models.continuum.solve_continuum`
stribeck   ``Q_max = 4.37 F_r/z`` (Stribeck 1901)                          stiffness, clearance,
                                                                           cage angle, exponent
palmgren   ``Q_max = 5 F_r/z`` (Palmgren 1959; seed 003, eq. 2)            stiffness, clearance,
                                                                           cage angle, exponent
=========  ==============================================================  =======================

Importing this module imports no numpy (the command line lists the methods at start-up); each
method imports what it needs when called.

Every method still checks every input (a negative stiffness is an error for Stribeck too), so the
methods accept and reject the same cases; the one exception is the exact model, which has no
equilibrium with one or two balls when no ball sits on the load line.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from bearingload.errors import InputError

#: The default method of :func:`compute` and of ``bearingload solve``.
DEFAULT_METHOD = "exact"


@dataclass(frozen=True)
class MethodResult:
    """What every method returns: the load factor and what follows from it.

    Attributes are floats for scalar input, arrays of the broadcast input shape otherwise.

    Attributes
    ----------
    method : str
        Name of the method (a key of :data:`METHODS`).
    k : float or ndarray
        Load factor ``Q_max/F_r``. [-]
    q_max : float or ndarray
        Load on the most loaded ball. [N]
    K_Q : float or ndarray
        Load-concentration factor ``K_Q = Q_max/(F_r/(z/2)) = k z/2`` (Kuzmenko & Sabadash 2014). [-]
    load_zone : float, ndarray or None
        Half-angle of the load zone; ``None`` for the one-line estimates, which have none. [°]
    """

    method: str
    k: Any
    q_max: Any
    K_Q: Any
    load_zone: Any = None


@dataclass(frozen=True)
class Method:
    """A registered method: its function and what to tell the user about it.

    Attributes
    ----------
    name : str
        Registry key.
    function : callable
        ``function(balls, load, stiffness, clearance, cage_angle, exponent) -> MethodResult``.
    title : str
        One line: the model and its source.
    ignores : tuple of str
        The common inputs the method does not use (``stiffness``, ``clearance``, ``cage_angle``,
        ``exponent``).
    """

    name: str
    function: Callable[..., MethodResult]
    title: str
    ignores: tuple[str, ...] = ()

    def __call__(
        self,
        balls: Any,
        load: Any,
        stiffness: Any,
        clearance: Any = 0.0,
        cage_angle: Any = 0.0,
        exponent: Any = 1.5,
    ) -> MethodResult:
        return self.function(balls, load, stiffness, clearance, cage_angle, exponent)


def _scalar(value: Any) -> Any:
    """Python float for a 0-d array, the array otherwise."""
    import numpy as np

    arr = np.asarray(value)
    return float(arr) if arr.ndim == 0 else arr


def _exact(
    balls: Any, load: Any, stiffness: Any, clearance: Any, cage_angle: Any, exponent: Any
) -> MethodResult:
    from bearingload.models.equilibrium import solve

    r = solve(balls, load, stiffness, clearance, cage_angle, exponent)
    return MethodResult(
        "exact", _scalar(r.k), _scalar(r.q_max), _scalar(r.K_Q), _scalar(r.load_zone)
    )


def _continuum(
    balls: Any, load: Any, stiffness: Any, clearance: Any, cage_angle: Any, exponent: Any
) -> MethodResult:
    import numpy as np

    from bearingload import validate
    from bearingload.models.continuum import solve_continuum

    angle = validate.finite("cage_angle", cage_angle)  # checked, then not used
    r = solve_continuum(balls, load, stiffness, clearance, exponent)
    shape = np.broadcast_shapes(np.shape(r.k), angle.shape)
    parts = (np.broadcast_to(a, shape) for a in (r.k, r.q_max, r.K_Q, r.load_zone))
    k, q, kq, zone = (_scalar(np.array(a)) for a in parts)
    return MethodResult("continuum", k, q, kq, zone)


def _one_line(name: str) -> Callable[..., MethodResult]:
    def estimate(
        balls: Any, load: Any, stiffness: Any, clearance: Any, cage_angle: Any, exponent: Any
    ) -> MethodResult:
        import numpy as np

        from bearingload import validate
        from bearingload.models.approximations import palmgren, stribeck

        z = validate.ball_count(balls)
        f = validate.positive("load", load, "N")
        kk = validate.positive("stiffness", stiffness, "N/mm^m")
        g = validate.finite("clearance", clearance)
        a = validate.finite("cage_angle", cage_angle)
        m = validate.exponent(exponent)
        z, f, *_ = np.broadcast_arrays(z, f, kk, g, a, m)
        r = (stribeck if name == "stribeck" else palmgren)(z, f)
        k, q = np.asarray(r.k), np.asarray(r.q_max)
        return MethodResult(name, _scalar(k), _scalar(q), _scalar(k * z / 2.0), None)

    return estimate


def _build() -> dict[str, Method]:
    fixed = ("stiffness", "clearance", "cage_angle", "exponent")
    return {
        "exact": Method(
            "exact",
            _exact,
            "exact ring equilibrium of the discrete balls (Kurochkin 1973; Kuzmenko 2010, §1-3)",
        ),
        "continuum": Method(
            "continuum",
            _continuum,
            "continuum model, each ball's load smeared over its pitch (Kuzmenko 2010, §4-5)",
            ("cage_angle",),
        ),
        "stribeck": Method(
            "stribeck",
            _one_line("stribeck"),
            "Stribeck (1901): Q_max = 4.37 F_r/z",  # approximations.STRIBECK_CONSTANT
            fixed,
        ),
        "palmgren": Method(
            "palmgren",
            _one_line("palmgren"),
            "Palmgren (1959): Q_max = 5 F_r/z",  # approximations.PALMGREN_CONSTANT
            fixed,
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
) -> MethodResult:
    """Run one registered method.

    Parameters
    ----------
    method : {'exact', 'continuum', 'stribeck', 'palmgren'}
        Name of the method (see :func:`list_methods`).
    balls : int or array_like
        Number of balls ``z``. [-]
    load : float or array_like
        Radial load ``F_r > 0``. [N]
    stiffness : float or array_like
        Ball stiffness ``K`` of both contacts in series, ``Q = K delta^m``. [N/mm^m]
    clearance : float or array_like, default 0
        Radial internal clearance ``G_r`` (total play; negative = preload). [mm]
    cage_angle : float or array_like, default 0
        Angle of ball 1 from the load line. [°]
    exponent : float or array_like, default 1.5
        Load-deflection exponent ``m``. [-]

    Returns
    -------
    MethodResult

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
) -> dict[str, MethodResult]:
    """Run every registered method on the same inputs; name -> result, in registry order."""
    return {
        name: m(balls, load, stiffness, clearance, cage_angle, exponent)
        for name, m in METHODS.items()
    }


def relative_error(result: MethodResult, reference: MethodResult) -> Any:
    """``Q_max / Q_max,reference - 1`` (the same as the ratio of the ``k``). [-]"""
    import numpy as np

    return _scalar(np.asarray(result.q_max) / np.asarray(reference.q_max) - 1.0)
