"""Input checks shared by every model: one place that says what each parameter allows."""

from __future__ import annotations

import math
import sys
from collections.abc import Sequence
from typing import Any

import numpy as np

from bearingload.errors import InputError


def finite(name: str, value: object) -> np.ndarray:
    """Return ``value`` as a float array, raising :class:`InputError` on NaN or infinity and on
    what is not a number (:func:`numbers`)."""
    arr = numbers(name, value)
    if not np.all(np.isfinite(arr)):
        raise InputError(
            name,
            "must be a finite number (got NaN or infinity)",
            element=element(arr, ~np.isfinite(arr)),
        )
    return arr


def numbers(name: str, value: object) -> np.ndarray:
    """Return ``value`` as a float array (NaN and infinity included), raising
    :class:`InputError` on text (units belong to the command line: the library takes N, mm,
    N/mm^m, degrees), on booleans and on dates or time spans (:func:`not_real`), alone or as
    elements of a list."""
    number = plain(value)
    if number is not None:
        return np.array(number)
    if type(value) is int:
        raise InputError(name, "must be a finite number (got an integer beyond 1.8e308)")
    masked = sys.modules.get("numpy.ma")  # (not imported at start-up: no masked array then)
    if masked is not None and isinstance(value, masked.MaskedArray):
        _refuse_masked(name, value)
    try:
        raw = np.asarray(value)
    except ValueError:  # lists of unequal lengths
        raise InputError(
            name, "must be a number or an array of numbers (got lists of unequal lengths)"
        ) from None
    if not isinstance(value, np.ndarray) and raw.ndim:  # a list: its own elements, not
        raw = np.asarray(value, dtype=object)  # numpy's common type (True read as 1)
    try:
        if raw.dtype.kind not in "iuf" and _any_not_real(raw):
            raise ValueError  # (numpy would read them as numbers: not_real)
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError, OverflowError):
        bad = _not_numbers(raw)
        first = _item(raw[bad].flat[0] if bad.any() else value)
        raise InputError(
            name,
            f"must be a number, not a boolean (got {first!r})"
            if isinstance(first, bool)
            else f"must be a number (got {first!r}); the library takes N, mm, N/mm^m and "
            "degrees (bearingload.units.parse_quantity reads text with a unit)",
            element=element(raw, bad),
        ) from None
    return arr


def _refuse_masked(name: str, value: np.ma.MaskedArray) -> None:
    """Raise :class:`InputError` where a masked array (numpy.ma) has a masked element, naming
    the first (``load[1]: masked``): numpy would read its hidden value as a number."""
    hidden = np.ma.getmaskarray(value)
    if not hidden.any():
        return
    where = _indexed(first_index(hidden)) if hidden.size > 1 else ""
    raise InputError(name, "masked", way_out="give the numbers without a mask", element=where)


def cage_angle(value: object, name: str = "cage_angle") -> np.ndarray:
    """Return a cage angle [°] as a float array (:func:`finite`) reduced to [0, 360)
    (:func:`reduced_angle`)."""
    return np.asarray(reduced_angle(finite(name, value)))


#: The rounding of reducing an angle to one turn: 4 eps times 360° (3.2e-13°, 5.6 ulps of 360:
#: the doubles 1 to 6 ulps below 360 are within it). An angle within it below a whole turn is
#: the turn, 0 (-1e-13° reduces to 359.9999999999999°, which every output printed as 360°); the
#: solvers take a cage angle within it of a symmetric position as that position
#: (models._ring.SYMMETRY_SNAP_DEG); the core's result_case reduces the ball angles by it. [°]
TURN_ROUNDING = 4.0 * float(np.finfo(float).eps) * 360.0


def reduced_angle(angle: Any) -> Any:
    """An angle [°] (a float or an array) reduced to [0, 360): ``np.mod`` and ``%`` leave 360
    or just below it for a negative angle within rounding of 0 (-1e-320, -1e-17: 360 - 1e-17 is
    360 in a double; -1e-13: 359.9999999999999), which is 0 here (:data:`TURN_ROUNDING`), as
    -0 is 0.

    >>> reduced_angle(-1e-320), reduced_angle(-1e-13), reduced_angle(-0.0), reduced_angle(-10.0)
    (0.0, 0.0, 0.0, 350.0)
    >>> reduced_angle(np.array([-1e-17, 725.0])).tolist()
    [0.0, 5.0]
    """
    below = 360.0 - TURN_ROUNDING
    if type(angle) is float:  # one case: no array machinery
        reduced = angle % 360.0
        return (reduced if reduced < below else 0.0) + 0.0
    reduced = np.mod(angle, 360.0)
    return np.where(reduced < below, reduced, 0.0) + 0.0  # (+ 0.0: -0 is 0)


def plain(value: object) -> float | None:
    """One plain Python number (``float`` or ``int``, not a bool) that is finite, as a float;
    None for anything else, which the array checks then take (and refuse with the reason). Each
    rule below checks such a number as a float first: no array machinery for one case."""
    if type(value) is float or type(value) is int:
        try:
            number = float(value)
        except OverflowError:
            return None
        if math.isfinite(number):
            return number
    return None


def each_finite(**values: object) -> list[np.ndarray]:
    """:func:`finite` of each named value, in the order given."""
    return [finite(name, value) for name, value in values.items()]


def require(name: str, value: Any, rule: str, ok: Any) -> None:
    """Raise :class:`InputError` ``<name>: must be <rule>; got <value>`` unless every ``ok``."""
    if not np.all(ok):
        bad = np.logical_not(ok)
        shown = _worst(value, bad) if np.shape(value) == np.shape(bad) else repr(value)
        raise InputError(name, f"must be {rule}; got {shown}", element=element(value, bad))


def positive_number(name: str, value: object) -> np.ndarray:
    """Return ``value`` as a float array: finite (:func:`finite`) and > 0 (``must be positive``)."""
    arr = finite(name, value)
    require(name, value, "positive", arr > 0)
    return arr


def non_negative(name: str, value: object) -> np.ndarray:
    """Return ``value`` as a float array: finite (:func:`finite`) and >= 0."""
    arr = finite(name, value)
    require(name, value, "zero or positive", arr >= 0)
    return arr


def positive(name: str, value: object, unit: str) -> np.ndarray:
    """Return ``value`` as a float array, raising unless every element is finite and > 0."""
    number = plain(value)
    if number is not None and number > 0:
        return np.array(number)
    arr = finite(name, value)
    if np.any(arr <= 0):
        raise not_positive(name, arr, arr <= 0, unit)
    return arr


def not_positive(name: str, arr: np.ndarray, bad: Any, unit: str) -> InputError:
    """The refusal of :func:`positive`: ``arr`` [``unit``] not > 0 where ``bad``."""
    return InputError(
        name,
        f"must be greater than 0 {unit} (got {_worst(arr, bad)})",
        element=element(arr, bad, unit),
    )


def at_least(name: str, value: object, lowest: float, unit: str) -> np.ndarray:
    """Return ``value`` as a float array, raising unless every element is finite and
    >= ``lowest`` [``unit``] (``radial_load: must be >= 0 N``)."""
    number = plain(value)
    if number is not None and number >= lowest:
        return np.array(number)
    arr = finite(name, value)
    if np.any(arr < lowest):
        raise below(name, arr, arr < lowest, lowest, unit)
    return arr


def below(name: str, arr: np.ndarray, bad: Any, lowest: float, unit: str) -> InputError:
    """The refusal of :func:`at_least`: ``arr`` [``unit``] below ``lowest`` where ``bad``."""
    return InputError(name, f"must be >= {lowest:g} {unit}", element=element(arr, bad, unit))


#: Groove conformity f = r/D_w, inner (``f_i``) or outer (``f_o``): the groove's radius r lies
#: between the ball's radius (f = 0.5: no room to roll) and its diameter (f = 1), both
#: excluded. The one rule of the command line, the catalogue and every model. [-]
CONFORMITY_RANGE = (0.5, 1.0)


def conformity(name: str, value: object) -> np.ndarray:
    """Return a groove conformity ``value`` (``f_i``, ``f_o``) as a float array, raising unless
    every element lies in :data:`CONFORMITY_RANGE` (excluded ends)."""
    number = plain(value)
    if number is not None and conforms(number):
        return np.array(number)
    arr = finite(name, value)
    bad = ~conforms(arr)
    if np.any(bad):
        raise nonconforming(name, arr, bad)
    return arr


def conforms(f: Any) -> Any:
    """Where a groove conformity (one float, or an array: the same test) lies in
    :data:`CONFORMITY_RANGE`."""
    low, high = CONFORMITY_RANGE
    return (low < f) & (f < high)


def nonconforming(name: str, arr: np.ndarray, bad: Any) -> InputError:
    """The refusal of :func:`conformity`: ``arr`` outside :data:`CONFORMITY_RANGE` where
    ``bad``."""
    low, high = CONFORMITY_RANGE
    return InputError(
        name,
        f"groove conformity r/D_w must lie in ({low:g}, {high:g}), the groove radius between "
        f"the ball's radius and its diameter; got {_worst(arr, bad)}",
        element=element(arr, bad),
    )


#: The largest imposed misalignment (tilt of the inner ring) the ball-bearing models take: a
#: deep-groove ball bearing tolerates 2-10 arcmin (an angular-contact one little), and a tilt of
#: a few degrees would push the balls over the groove shoulders, which the models do not
#: describe. [°]
MISALIGNMENT_MAX = 2.0


def misalignment_fits(tilt: Any) -> Any:
    """Where an imposed misalignment [°] (one float, or an array: the same test) lies within
    ±:data:`MISALIGNMENT_MAX`."""
    return abs(tilt) <= MISALIGNMENT_MAX


def misalignment_beyond(tilt: np.ndarray, bad: np.ndarray) -> InputError:
    """The refusal of the misalignments [°] ``tilt`` where ``bad`` (not
    :func:`misalignment_fits`), naming the first with its sign."""
    first = float(np.asarray(tilt)[np.asarray(bad)].flat[0])  # as given: -3° reads -3°
    return InputError(
        "misalignment",
        f"must be within ±{MISALIGNMENT_MAX:g}° (got {first:.10g}°): ball bearings tolerate "
        "minutes of arc at most (a deep-groove one 2-10 arcmin, an angular-contact one little), "
        "and a tilt of degrees would push the balls over the groove shoulders, which the model "
        "does not describe",
        element=element(tilt, bad, "°"),
    )


def misalignment(value: object) -> np.ndarray:
    """Return an imposed misalignment [°] as a float array: finite (:func:`finite`) and within
    ±:data:`MISALIGNMENT_MAX` (:func:`misalignment_fits`)."""
    arr = finite("misalignment", value)
    bad = np.logical_not(misalignment_fits(arr))
    if bad.any():
        raise misalignment_beyond(arr, bad)
    return arr


def clearance_fits(clearance: Any, ball_diameter: Any) -> Any:
    """Where a radial internal clearance G_r [mm] (negative: a preload) is one a ball bearing
    of balls of diameter D_w [mm] can have: |G_r| < D_w/2 (floats, or arrays broadcast
    together: the same test). A ball diameter not > 0 passes: its own rule refuses it."""
    return (ball_diameter <= 0.0) | (abs(clearance) < ball_diameter / 2)


def clearance_beyond_ball(clearance: float, ball_diameter: float, element: str = "") -> InputError:
    """The refusal of a clearance G_r [mm] not :func:`clearance_fits` to the balls of diameter
    ``ball_diameter`` [mm]; ``element``: of an array, its first such element."""
    return InputError(
        "clearance",
        f"G_r = {clearance:g} mm is at least half the ball diameter ({ball_diameter:g} mm): no "
        "bearing has such a play or preload",
        element=element,
    )


#: The smallest ball diameter D_w over the pitch diameter d_m taken: the catalogue's ball sets
#: (``bearings/data/ball_sets.csv``) span D_w/d_m = 0.062 to 0.33; a ball below a sixtieth of
#: the smallest is no bearing's (and one of 1e-300 mm overflows the Hertz contact). [-]
BALL_RATIO_MIN = 1e-3


def ball_size_fits(ball_diameter: Any, pitch_diameter: Any) -> Any:
    """Where a ball of diameter D_w [mm] is one a bearing of pitch diameter d_m [mm] has: D_w >=
    :data:`BALL_RATIO_MIN` d_m (floats, or arrays broadcast together). A diameter not > 0 passes:
    its own rule refuses it."""
    return (
        (ball_diameter <= 0.0)
        | (pitch_diameter <= 0.0)
        | (ball_diameter >= BALL_RATIO_MIN * pitch_diameter)
    )


def first_refused(bad: Any, *values: Any) -> list[float]:
    """The ``values`` (arrays broadcast to ``bad``'s shape) of the first case where ``bad``, as
    floats: what a refusal of several inputs of one case shows."""
    bad = np.asarray(bad)
    i = first_index(bad)
    return [float(np.broadcast_to(v, bad.shape)[i]) for v in values]


def ball_too_small(ball_diameter: float, pitch_diameter: float, element: str = "") -> InputError:
    """The refusal of a ball diameter not :func:`ball_size_fits` to its pitch diameter [mm];
    ``element``: of an array, its first such element."""
    return InputError(
        "ball_diameter",
        f"D_w = {_shown(ball_diameter)} mm is below {BALL_RATIO_MIN:g} of the pitch diameter "
        f"({pitch_diameter:g} mm): no ball bearing has such small balls (the catalogue's have "
        f"0.06 to 0.33 d_m); give at least {BALL_RATIO_MIN * pitch_diameter:g} mm",
        element=element,
    )


def finite_positive(name: str, value: object) -> np.ndarray:
    """Return ``value`` as a float array; every element must be a finite number > 0 (and a
    number: :func:`numbers`)."""
    arr = numbers(name, value)
    good = np.isfinite(arr) & (arr > 0)
    if not np.all(good):  # the first offending value, not the repr of an array
        raise InputError(
            name,
            f"must be a finite number greater than 0; got {_worst(arr, ~good)}",
            element=element(arr, ~good),
        )
    return arr


def ball_count(value: object, *, name: str = "balls", maximum: int = 100_000) -> np.ndarray:
    """Return the number of balls as an int array; each must be a whole number 1 <= z <= maximum."""
    arr = finite(name, value)
    if np.any(arr != np.round(arr)):
        bad = arr != np.round(arr)
        raise InputError(
            name, f"must be a whole number (got {_worst(arr, bad)})", element=element(arr, bad)
        )
    if np.any(arr < 1) or np.any(arr > maximum):
        bad = (arr < 1) | (arr > maximum)
        raise InputError(
            name,
            f"must be between 1 and {maximum} (got {_worst(arr, bad)})",
            element=element(arr, bad),
        )
    return arr.astype(np.int64)


def exponent(value: object, *, name: str = "exponent") -> np.ndarray:
    """Return the load-deflection exponent; 1 <= m <= 3 (3/2 balls, 10/9 rollers)."""
    arr = finite(name, value)
    if np.any((arr < 1) | (arr > 3)):
        bad = (arr < 1) | (arr > 3)
        raise InputError(
            name,
            f"must be between 1 and 3 (1.5 for balls, 10/9 for rollers; got {_worst(arr, bad)})",
            element=element(arr, bad),
        )
    return arr


def broadcast_shape(arrays: dict[str, Any]) -> tuple[int, ...]:
    """The shape the named arrays broadcast to; :class:`InputError` names them when they do not
    fit together or when there is no case at all (an empty array)."""
    try:
        shape = np.broadcast_shapes(*(np.shape(a) for a in arrays.values()))
    except ValueError:
        shapes = ", ".join(f"{k} {np.shape(v)}" for k, v in arrays.items() if np.ndim(v))
        raise InputError(
            ", ".join(k for k, v in arrays.items() if np.ndim(v)),
            f"the array shapes do not broadcast together ({shapes})",
        ) from None
    if 0 in shape:
        empty = [k for k, v in arrays.items() if np.size(v) == 0] or list(arrays)
        raise InputError(", ".join(empty), "no case to solve: the array is empty")
    return tuple(shape)


def _worst(arr: np.ndarray, bad: np.ndarray) -> str:
    """The first offending value, unrounded (shortest repr: 8.0000000001 stays 8.0000000001)."""
    return _shown(np.asarray(arr)[np.asarray(bad)].flat[0])


def _shown(value: Any) -> str:
    """One value as a message shows it: a whole number without ``.0``, else its shortest repr."""
    item = _item(value)
    if isinstance(item, bool) or not isinstance(item, (int, float)):
        return repr(item)
    if isinstance(item, int) and not -1e308 < item < 1e308:
        return repr(item)  # beyond a double
    v = float(item)
    return repr(int(v)) if v.is_integer() and abs(v) < 1e16 else repr(v)


def element(value: object, bad: Any, unit: str = "") -> str:
    """``[3] = -1 N``: the index and value of the first element of an array input where ``bad``
    holds, for :class:`InputError` (``radial_load[3] = -1 N: must be >= 0 N``); empty for one
    number (an array of one too), or where ``bad`` is not of the input's shape (the input
    broadcast with others).
    Computed only on the way to an error: a valid input pays nothing for it."""
    arr = np.asarray(value)
    flags = np.asarray(bad)
    if arr.size < 2 or flags.shape != arr.shape or not flags.any():
        return ""
    index = first_index(flags)
    return f"{_indexed(index)} = {_shown(arr[index])}" + (f" {unit}" if unit else "")


def element_at(value: object, bad: Any, shape: tuple[int, ...], unit: str = "") -> str:
    """:func:`element` of an input broadcast with others to the case ``shape``: ``bad`` holds
    over the cases (of ``shape``, or flat); the input's own element of the first bad case, by
    its own index (``clearance[1] = 5 mm`` of a clearance given as ``[0.01, 5]`` beside one
    load); empty for one number."""
    arr = np.asarray(value)
    flags = np.asarray(bad).reshape(-1)
    if arr.size < 2 or not flags.any() or flags.size != int(np.prod(shape)):
        return ""
    case = first_index(flags.reshape(shape))
    own = tuple(
        0 if n == 1 else i for i, n in zip(case[len(case) - arr.ndim :], arr.shape, strict=True)
    )
    return f"{_indexed(own)} = {_shown(arr[own])}" + (f" {unit}" if unit else "")


def first_index(flags: np.ndarray) -> tuple[int, ...]:
    """The index (of ``flags``' shape) of its first True element, as ints."""
    return tuple(int(i) for i in np.unravel_index(int(np.flatnonzero(flags)[0]), flags.shape))


def _indexed(index: tuple[int, ...]) -> str:
    """``[1, 2]``: an element's index as a message names it."""
    return "[" + ", ".join(map(str, index)) + "]"


#: The types of :func:`not_real` (besides None).
_NOT_REAL = (str, bytes, complex, np.complexfloating, bool, np.bool_, np.datetime64, np.timedelta64)


def not_real(v: object) -> bool:
    """Whether one value (an element) is text, None, a complex number, a boolean, a date or a
    time span: what numpy would read as a real number ("1000" as 1000.0, None as NaN, 1+0j as
    1.0, True as 1, the year 2020 as 50) but the library refuses; an array of no dimension
    (an element of a list as ``np.array(True)``) by the value it holds."""
    if isinstance(v, np.ndarray) and v.ndim == 0:
        v = v[()]
    return v is None or isinstance(v, _NOT_REAL)


def _item(value: Any) -> Any:
    """A numpy scalar as the Python value a message shows (np.float64(2.0) as 2.0, np.True_ as
    True), an array of no dimension as its value; a date or a time span as numpy shows it (its
    ``item`` is a datetime)."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, np.generic) and not isinstance(value, (np.datetime64, np.timedelta64)):
        return value.item()
    return value


def _any_not_real(raw: np.ndarray) -> bool:
    """Whether an array (of objects, text, booleans, complex numbers or dates) holds an element
    :func:`not_real`: the first such element ends the search."""
    return any(not_real(v) for v in raw.flat)


def _not_numbers(raw: np.ndarray) -> np.ndarray:
    """Where an array holds an element that is not a number (:func:`not_real`, an object)."""
    out = np.zeros(raw.shape, dtype=bool)
    for i, v in np.ndenumerate(raw):
        try:
            out[i] = not_real(v) or float(v) is None  # float() refuses the rest
        except (TypeError, ValueError, OverflowError):
            out[i] = True
    return out


def ball_spacing(balls: object, ball_diameter: object, pitch_diameter: object) -> None:
    """Raise :class:`InputError` (``ball_diameter``) where adjacent balls would overlap.

    z equally spaced balls on the pitch circle of diameter d_m have adjacent centres a chord
    d_m sin(pi/z) apart, so balls of diameter D_w fit only if D_w <= d_m sin(pi/z) (touching
    allowed, a full complement; to a relative 1e-12 of the chord for rounding). No rule for
    z = 1. Source: plane geometry (the chord of the pitch circle between adjacent centres).

    Parameters
    ----------
    balls : array_like
        Number of balls z (whole numbers >= 1). [-]
    ball_diameter, pitch_diameter : array_like
        Ball diameter D_w and pitch diameter d_m, broadcast together. [mm]
    """
    z, dw, dm = (np.asarray(v, dtype=float) for v in (balls, ball_diameter, pitch_diameter))
    if type(balls) is int and balls >= 2:  # one count: its chord's factor as one number
        if (dw <= dm * np.sin(np.pi / balls) * (1.0 + 1e-12)).all():
            return
    chord = dm * np.sin(np.pi / np.maximum(z, 1.0))
    bad = (z >= 2) & ~(dw <= chord * (1.0 + 1e-12))
    if bad.any():  # (broadcast only on the way to the message)
        z, dw, dm, chord, bad = np.broadcast_arrays(z, dw, dm, chord, bad)
        i = np.flatnonzero(bad.ravel())[0]
        n, d, p, c = (float(a.ravel()[i]) for a in (z, dw, dm, chord))
        k = next((k for k in range(6, 17) if f"{d:.{k}g}" != f"{c:.{k}g}"), 17)  # as they differ
        step = 10.0 ** (math.floor(math.log10(c)) - k + 1)
        most = math.floor(c / step) * step  # rounded down: itself accepted
        raise InputError(
            "ball_diameter",
            f"{n:.0f} balls of {d:.{k}g} mm overlap on a pitch circle of {p:g} mm: adjacent ball "
            f"centres are d_m sin(pi/z) = {c:.{k}g} mm apart, so with z = {n:.0f} and d_m = {p:g} "
            f"mm the ball diameter D_w must be at most {most:.{k}g} mm (or fewer balls)",
        )


def known_columns(name: str, header: Sequence[str], allowed: Sequence[str]) -> None:
    """InputError ``name`` unless every column of a csv ``header`` is one of ``allowed``: the
    unknown ones named, or the separator of a file whose header reads as one column."""
    unknown = ", ".join(repr(n) for n in header if n not in allowed)
    if unknown:
        why = f"unknown column(s) {unknown}; allowed: {', '.join(allowed)}"
        raise InputError(name, separator_slip(header) or why)


def separator_slip(header: Sequence[str]) -> str | None:
    """Why a csv header of one cell is another separator's (``;``, a tab, ``|``: a spreadsheet
    set to decimal commas saves its csv with ``;``), for the refusal of its file; else None."""
    for sep in (";", "\t", "|"):
        if len(header) == 1 and sep in header[0]:
            why = " (as a spreadsheet set to decimal commas saves a csv)" if sep == ";" else ""
            return (
                f"the header {header[0].strip()!r} is one column: the columns of a csv are "
                f"separated by commas, and this file separates them by {sep!r}{why}; save it "
                "comma-separated"
            )
    return None
