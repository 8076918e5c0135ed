"""One case of a radial bearing under load, and the one result every model returns.

A :class:`Case` holds the validated, broadcast inputs common to every load-distribution model;
a :class:`Result` holds what a model computed, under one name per quantity (the names of
:mod:`bearingload.reports.quantities`), with ``None`` for what the model does not give.
Scalar inputs give Python scalars; array inputs give arrays of the broadcast shape.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import fields
from functools import partial
from typing import Any

import numpy as np

from bearingload import validate
from bearingload.lazy_dataclass import dataclass
from bearingload.numerics import scalar_out
from bearingload.validate import broadcast_shape

#: The inputs of a case, in the order of every model's signature.
INPUTS = ("balls", "load", "stiffness", "clearance", "cage_angle", "exponent")


@dataclass(frozen=True)
class Case:
    """Validated inputs of one case or an array of cases.

    The inputs are kept as given (not broadcast), so that a model computes each distinct input
    once and its answer for a case never depends on the inputs it ignores; ``shape`` is the
    broadcast shape of the cases. An input given as a scalar is a Python ``int``/``float``
    (the scalar contract), one given as an array an ndarray.

    Attributes
    ----------
    balls : int or ndarray of int
        Number of rolling elements ``z``, 1 to 100 000. [-]
    load : float or ndarray
        Radial load ``F_r`` > 0. [N]
    stiffness : float or ndarray
        Rolling-element stiffness ``K`` of both contacts in series, ``Q = K delta^m``. [N/mm^m]
    clearance : float or ndarray
        Radial internal clearance ``G_r`` (total play; negative = preload). [mm]
    cage_angle : float or ndarray
        Angle of ball 1 from the load line, reduced to [0, 360). [°]
    exponent : float or ndarray
        Load-deflection exponent ``m`` (3/2 balls, 10/9 rollers). [-]
    """

    balls: Any
    load: Any
    stiffness: Any
    clearance: Any
    cage_angle: Any
    exponent: Any
    shape: tuple[int, ...]

    @classmethod
    def of(
        cls,
        balls: Any,
        load: Any,
        stiffness: Any,
        clearance: Any = 0.0,
        cage_angle: Any = 0.0,
        exponent: Any = 1.5,
    ) -> Case:
        """Check every input (:class:`~bearingload.errors.InputError` names the parameter) and
        find their broadcast shape; each input kept as a Python scalar when given as one (the
        scalar contract, :func:`bearingload.numerics.scalar_out`)."""
        arrays = checked(
            balls=balls,
            load=load,
            stiffness=stiffness,
            clearance=clearance,
            cage_angle=cage_angle,
            exponent=exponent,
        )
        arrays[4] = validate.cage_angle(arrays[4])
        shape = broadcast_shape(dict(zip(INPUTS, arrays, strict=True)))
        balls, load, stiffness, clearance, cage_angle, exponent = (scalar_out(a) for a in arrays)
        return cls(balls, load, stiffness, clearance, cage_angle, exponent, shape)

    def inputs(self, names: tuple[str, ...] = INPUTS) -> dict[str, Any]:
        """The inputs named ``names`` as keyword arguments (Python scalars for one case)."""
        return {name: scalar_out(getattr(self, name)) for name in names}


#: The rule of each case input (:mod:`bearingload.validate`), by name.
_RULES: dict[str, Callable[[Any], np.ndarray]] = {
    "balls": validate.ball_count,
    "load": partial(validate.positive, "load", unit="N"),
    "stiffness": partial(validate.positive, "stiffness", unit="N/mm^m"),
    "clearance": partial(validate.finite, "clearance"),
    "cage_angle": partial(validate.finite, "cage_angle"),
    "exponent": validate.exponent,
}


def checked(**inputs: Any) -> list[np.ndarray]:
    """The case inputs given by name (any of :data:`INPUTS`), each checked by its rule in the
    order given (an :class:`~bearingload.errors.InputError` names the first refused), as
    arrays, not broadcast."""
    return [_RULES[name](value) for name, value in inputs.items()]


@dataclass(frozen=True)
class Result:
    """What a registered model computed for a :class:`Case`.

    Attributes are Python scalars for a scalar case and arrays of the case's shape otherwise;
    ``None`` where the model does not give the quantity.

    Attributes
    ----------
    method : str
        Registry name of the model.
    case : Case
        The inputs.
    k : float or ndarray
        Load factor ``Q_max/F_r`` (Kuzmenko 2010, eq. 1.17). [-]
    q_max : float or ndarray
        Load of the most heavily loaded ball. [N]
    loaded_balls : int, ndarray or None
        Number of balls carrying load. [-]
    load_zone : float, ndarray or None
        Half-angle of the load zone. [°]
    x, y : float, ndarray or None
        Inner-ring displacement along and across the load. [mm]
    stiffness_radial : float, ndarray or None
        Tangent radial stiffness ``dF_r/dx`` of the bearing. [N/mm]
    valid : bool or ndarray
        Whether the case lies inside the model's range of validity (see the registry entry's
        ``validity``).
    model : object
        The model's own result (e.g. :class:`~bearingload.models.equilibrium.LoadDistribution`),
        with everything else it computed.
    """

    method: str
    case: Case
    k: Any
    q_max: Any
    loaded_balls: Any = None
    load_zone: Any = None
    x: Any = None
    y: Any = None
    stiffness_radial: Any = None
    valid: Any = True
    model: Any = None

    def quantities(self) -> dict[str, Any]:
        """The computed quantities by name (``k`` ... ``stiffness_radial``; None: not given)."""
        return {name: getattr(self, name) for name in RESULT_QUANTITIES}

    @property
    def K_Q(self) -> Any:
        """Load-concentration factor ``K_Q = Q_max/(F_r/(z/2)) = k z/2`` (Kuzmenko & Sabadash 2014). [-]"""
        return scalar_out(np.asarray(self.k) * self.case.balls / 2.0)


#: The quantities a :class:`Result` may carry, besides ``method``, ``case`` and ``model``.
RESULT_QUANTITIES = tuple(
    f.name for f in fields(Result) if f.name not in ("method", "case", "model", "valid")
)
