"""Input checks shared by every model: one place that says what each parameter allows."""

from __future__ import annotations

import numpy as np

from bearingload.errors import InputError


def finite(name: str, value: object) -> np.ndarray:
    """Return ``value`` as a float array, raising :class:`InputError` on NaN or infinity."""
    arr = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(arr)):
        raise InputError(name, "must be a finite number (got NaN or infinity)")
    return arr


def positive(name: str, value: object, unit: str) -> np.ndarray:
    """Return ``value`` as a float array, raising unless every element is finite and > 0."""
    arr = finite(name, value)
    if np.any(arr <= 0):
        raise InputError(name, f"must be greater than 0 {unit} (got {_worst(arr, arr <= 0)})")
    return arr


def finite_positive(name: str, value: object) -> np.ndarray:
    """Return ``value`` as a float array; every element must be a finite number > 0."""
    arr = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(arr) & (arr > 0)):
        raise InputError(name, f"must be a finite number greater than 0; got {value!r}")
    return arr


def ball_count(value: object, *, name: str = "balls", maximum: int = 100_000) -> np.ndarray:
    """Return the number of balls as an int array; each must be a whole number 1 <= z <= maximum."""
    arr = finite(name, value)
    if np.any(arr != np.round(arr)):
        raise InputError(name, f"must be a whole number (got {_worst(arr, arr != np.round(arr))})")
    if np.any(arr < 1) or np.any(arr > maximum):
        bad = (arr < 1) | (arr > maximum)
        raise InputError(name, f"must be between 1 and {maximum} (got {_worst(arr, bad)})")
    return arr.astype(np.int64)


def exponent(value: object, *, name: str = "exponent") -> np.ndarray:
    """Return the load-deflection exponent; 1 <= m <= 3 (3/2 balls, 10/9 rollers)."""
    arr = finite(name, value)
    if np.any((arr < 1) | (arr > 3)):
        bad = (arr < 1) | (arr > 3)
        raise InputError(
            name,
            f"must be between 1 and 3 (1.5 for balls, 10/9 for rollers; got {_worst(arr, bad)})",
        )
    return arr


def broadcast(names: tuple[str, ...], arrays: list[np.ndarray]) -> tuple[int, ...]:
    """The common shape of checked input arrays; InputError for an empty or mismatched one."""
    for name, arr in zip(names, arrays, strict=True):
        if arr.size == 0:
            raise InputError(name, f"is an empty array (shape {arr.shape}); give at least one case")
    shape: tuple[int, ...] = ()
    for name, arr in zip(names, arrays, strict=True):
        try:
            shape = np.broadcast_shapes(shape, arr.shape)
        except ValueError:
            raise InputError(
                name,
                f"has shape {arr.shape}, which does not broadcast with the shape {shape} of the "
                "parameters before it; give arrays of one shape (or scalars)",
            ) from None
    return shape


def _worst(arr: np.ndarray, bad: np.ndarray) -> str:
    """The first offending value, unrounded (shortest repr: 8.0000000001 stays 8.0000000001)."""
    v = float(np.asarray(arr)[np.asarray(bad)].flat[0])
    return repr(int(v)) if v.is_integer() and abs(v) < 1e16 else repr(v)
