"""The lever of the inner ring's tilt under a combined load: ``groove``, ``pitch`` or a length.

A tilt theta of the inner ring moves each inner groove curvature centre axially by
``r theta`` at the radius ``r`` of that centre, and a moment M about an axis of the bearing's
plane acts on the ring through the same arm (in :func:`bearingload.models.combined.solve_combined`
M is the generalised force of theta, ``tilt_radius`` sets ``r``):

* ``groove``: ``R_i = d_m/2 + (r_i - D_w/2) cos(alpha_0)``, the radius of the inner groove
  curvature centres, as ISO/TS 16281:2008 (4.2) writes the small-tilt kinematics; the solver's
  default.
* ``pitch``: ``d_m/2``, the lever the tilts MASTA reports fit (the published MASTA example
  values of :mod:`bearingload.models.combined`'s tests).
* a length given by the user. [mm]

Imports nothing heavy: the command line reads an option with it.
"""

from __future__ import annotations

import math

from bearingload.errors import InputError

#: The named levers; any other value is a length.
TILT_RADII = ("groove", "pitch")

_ALLOWED = "groove, pitch or a length greater than 0 (bare number: mm; e.g. 21.75mm)"


def parse_tilt_radius(value: str | float | None) -> str | float | None:
    """Read a tilt lever: ``"groove"``, ``"pitch"`` (any case) or a length > 0 [mm].

    Parameters
    ----------
    value : str, float or None
        ``"groove"``, ``"pitch"``, a bare number [mm] or a number with a length unit
        (``"21.75mm"``, ``"0.9in"``); None: not given (the solver's default, ``groove``).

    Returns
    -------
    str, float or None
        The name, or the length. [mm]

    Raises
    ------
    InputError
        (parameter ``tilt_radius``) for anything else, 0 and negative lengths included.

    >>> parse_tilt_radius("Pitch"), parse_tilt_radius("25mm")
    ('pitch', 25.0)
    """
    if value is None:
        return None
    if isinstance(value, str) and value.strip().lower() in TILT_RADII:
        return value.strip().lower()
    from bearingload.units import parse_quantity

    try:
        length = parse_quantity(value, "length", parameter="tilt_radius")
    except InputError:
        length = math.nan
    if not length > 0 or not math.isfinite(length):
        raise InputError("tilt_radius", f"must be {_ALLOWED}; got {value!r}")
    return length


def tilt_lever(spec: str | float | None, pitch_diameter: float | None) -> float | None:
    """The ``tilt_radius`` argument of :func:`bearingload.models.combined.solve_combined` for a
    lever read by :func:`parse_tilt_radius`: None for ``groove`` (and None; the solver's R_i),
    ``d_m/2`` for ``pitch``, a length as it is. [mm]

    >>> tilt_lever("pitch", 43.5), tilt_lever("groove", 43.5), tilt_lever(20.0, 43.5)
    (21.75, None, 20.0)
    """
    spec = parse_tilt_radius(spec)
    if spec is None or spec == "groove":
        return None
    if spec == "pitch":
        if pitch_diameter is None:
            raise InputError("tilt_radius", "'pitch' needs the pitch diameter of the bearing")
        return 0.5 * float(pitch_diameter)
    return float(spec)


#: A lever given as a length outside these multiples of the pitch radius d_m/2 is warned of: the
#: radius at which the inner groove centres move lies between the bore and the groove bottom,
#: within a few tens of percent of d_m/2 for every deep-groove bearing. [-]
LEVER_RANGE = (0.5, 2.0)


def lever_warning(lever: float | None, pitch_diameter: float | None) -> str | None:
    """A sentence when a lever given as a length is far from the bearing's pitch radius (a unit
    slip: ``--tilt-radius 1e9`` or ``0.02`` meant in metres), None otherwise. [mm]

    >>> lever_warning(21.0, 43.5) is None, lever_warning(1e9, 43.5)[:24]
    (True, 'tilt lever 1e+09 mm is 4')
    """
    if lever is None or not pitch_diameter:
        return None
    ratio = lever / (0.5 * float(pitch_diameter))
    if LEVER_RANGE[0] <= ratio <= LEVER_RANGE[1]:
        return None
    return (
        f"tilt lever {lever:.6g} mm is {ratio:.3g} times the pitch radius d_m/2 = "
        f"{0.5 * float(pitch_diameter):.6g} mm: the lever is the radius at which the inner groove "
        "centres move axially (ISO/TS 16281: that of the groove centres, near d_m/2); the tilt "
        "and the moment's arm scale with it (check --tilt-radius and its unit)"
    )
