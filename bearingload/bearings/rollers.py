"""Single-row cylindrical roller bearings NU/N 2xx and 3xx: rollers, length, line contact.

The rows live in ``data/rollers.csv``. SKF prints, for each size of its ECP design, the inner
raceway diameter F (of the NU type) and the outer raceway diameter E (of the N type) [1]_, so

* roller diameter D_w = (E - F)/2 and pitch diameter d_m = (E + F)/2 are exact;
* the product z L_we follows from the static rating, ISO 76:2006 clause 6.1.2 (radial roller
  bearings, alpha = 0, i = 1): C_0r = 44 (1 - D_w/d_m) z L_we D_w, if SKF's C_0 is ISO based;
* the roller count z is read where a dataset states it (N204: 11; NU205E and NU2205-E: 13;
  NU206E: 13; see the rows' notes); elsewhere it is **derived and flagged**: among the counts
  that give L_we/D_w in 0.95 ... 1.07 and leave z D_w <= 0.92 pi d_m, the one with L_we/D_w
  nearest :data:`LENGTH_RATIO` = 1.017, the mean of the three published sizes (1.036, 1.039,
  0.977). The effective length L_we = (z L_we)/z is derived for every row.

NU, N, NJ and NUP of one size share the rollers and are the row ``NU...``.

Line contact (Johnson, *Contact Mechanics*, 1985, eq. 4.45): a roller pressed with Q on a
raceway over the length L has the maximum pressure p_0 = sqrt(Q E* / (pi L R)), 1/R the
curvature sum across the roller (inner: 2/D_w + 2/(d_m - D_w); outer: 2/D_w - 2/(d_m + D_w)).
The roller stiffness is Palmgren's, :func:`bearingload.contact.hertz.roller_stiffness`.

References
----------
.. [1] SKF General Catalogue (Russian edition), single-row cylindrical roller bearings,
   pp. 521-545; rows' lines in ``data/rollers.csv``.

>>> r = lookup("NU206")
>>> r.rollers, r.roller_diameter, r.pitch_diameter, round(r.roller_length, 3)
(13, 9.0, 46.5, 8.792)
"""

from __future__ import annotations

import dataclasses
import functools
import math
from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload.bearings._data import read_rows
from bearingload.bearings.designation import Designation, parse
from bearingload.constants import STEEL_MODULUS, STEEL_POISSON
from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass
from bearingload.numerics import scalar_out

if TYPE_CHECKING:
    from numpy.typing import ArrayLike

#: L_we/D_w of the derived roller counts: mean of the published NU204, NU205, NU206. [-]
LENGTH_RATIO = 1.017
#: Range of L_we/D_w accepted for a derived roller count. [-]
LENGTH_RATIO_RANGE = (0.95, 1.07)
#: Largest fill z D_w / (pi d_m) accepted for a derived roller count. [-]
MAX_FILL = 0.92


@dataclass(frozen=True)
class RollerGeometry:
    """One cylindrical roller bearing of the catalogue (with user overrides applied).

    Attributes
    ----------
    designation : str
        Catalogue row (``"NU206"``).
    d, D, B : float
        Bore, outside diameter, width. [mm]
    F, E : float
        Inner (NU) and outer (N) raceway diameters. [mm]
    roller_diameter, pitch_diameter : float
        D_w = (E - F)/2 and d_m = (E + F)/2. [mm]
    rollers : int
        z (read or derived, see ``method``).
    roller_length : float
        Effective length L_we (derived from C0). [mm]
    C, C0 : float
        SKF ratings. [N]
    method : str
        ``"read z"`` or ``"derived z"``.
    source, notes : str
        Where the numbers come from; how z and L_we were derived.
    parsed : Designation
        The designation as typed.
    overrides : tuple of str
        Fields set by the user.
    """

    designation: str
    d: float
    D: float
    B: float
    F: float
    E: float
    roller_diameter: float
    pitch_diameter: float
    rollers: int
    roller_length: float
    C: float
    C0: float
    method: str
    source: str
    notes: str
    parsed: Designation
    overrides: tuple[str, ...] = ()


@functools.lru_cache(maxsize=1)
def entries() -> tuple[RollerGeometry, ...]:
    """Every row of ``data/rollers.csv`` (NU203-NU220, NU303-NU320), in file order."""
    rows = []
    for rec in read_rows("rollers.csv"):
        rows.append(
            RollerGeometry(
                designation=rec["designation"],
                d=float(rec["d"]),
                D=float(rec["D"]),
                B=float(rec["B"]),
                F=float(rec["F"]),
                E=float(rec["E"]),
                roller_diameter=float(rec["roller_diameter"]),
                pitch_diameter=float(rec["pitch_diameter"]),
                rollers=int(rec["rollers"]),
                roller_length=float(rec["roller_length"]),
                C=float(rec["C"]),
                C0=float(rec["C0"]),
                method=rec["method"],
                source=rec["source"],
                notes=rec["notes"],
                parsed=parse(rec["designation"]),
            )
        )
    return tuple(rows)


def total_length(C0: float, roller_diameter: float, pitch_diameter: float) -> float:
    """z L_we from the static rating, ISO 76:2006 6.1.2: C_0r / (44 (1 - D_w/d_m) D_w). [mm]

    Parameters
    ----------
    C0 : float
        Basic static radial load rating. [N]
    roller_diameter, pitch_diameter : float
        D_w and d_m. [mm]

    >>> round(total_length(36500.0, 9.0, 46.5), 2)  # NU206
    114.3
    """
    return C0 / (44.0 * (1.0 - roller_diameter / pitch_diameter) * roller_diameter)


def roller_count(C0: float, roller_diameter: float, pitch_diameter: float) -> tuple[int, list[int]]:
    """The derived roller count and every count the rule admits (see the module text).

    Returns
    -------
    (int, list of int)
        The count with L_we/D_w nearest :data:`LENGTH_RATIO`, and all admitted counts.

    Raises
    ------
    InputError
        (parameter ``rollers``) when no count is admitted.
    """
    zl = total_length(C0, roller_diameter, pitch_diameter)
    low, high = LENGTH_RATIO_RANGE
    admitted = [
        z
        for z in range(3, 200)
        if low <= zl / z / roller_diameter <= high
        and z * roller_diameter <= MAX_FILL * math.pi * pitch_diameter
    ]
    if not admitted:
        raise InputError("rollers", "no roller count fits the rating; give 'balls'")
    best = min(admitted, key=lambda z: abs(zl / z / roller_diameter - LENGTH_RATIO))
    return best, admitted


def lookup(
    designation: str,
    *,
    rollers: int | None = None,
    roller_diameter: float | None = None,
    pitch_diameter: float | None = None,
    roller_length: float | None = None,
) -> RollerGeometry:
    """The catalogue row of a cylindrical roller bearing, with optional overrides.

    Parameters
    ----------
    designation : str
        ``NU206``, ``N 306 ECP/C3``, ``NJ210`` ...
    rollers : int, optional
        z, replacing the catalogue's.
    roller_diameter, pitch_diameter, roller_length : float, optional
        D_w, d_m, L_we replacing the catalogue's. [mm]

    Raises
    ------
    InputError
        (parameter ``bearing``) not a cylindrical roller designation or not in the catalogue;
        (``rollers``, ``roller_diameter``, ``pitch_diameter``, ``roller_length``) impossible
        overrides.
    """
    parsed = parse(designation)
    if parsed.kind != "roller":
        raise InputError("bearing", f"{designation!r} is not a cylindrical roller bearing")
    row = next((r for r in entries() if r.designation == parsed.catalogue_name), None)
    if row is None:
        raise InputError(
            "bearing",
            f"{parsed.catalogue_name!r} is not in the catalogue (NU/N 203-220 and 303-320)",
        )
    given = {
        "rollers": rollers,
        "roller_diameter": roller_diameter,
        "pitch_diameter": pitch_diameter,
        "roller_length": roller_length,
    }
    changes = {k: v for k, v in given.items() if v is not None}
    new = dataclasses.replace(row, parsed=parsed, overrides=tuple(changes), **changes)  # type: ignore[arg-type]
    z, dw, dm, le = new.rollers, new.roller_diameter, new.pitch_diameter, new.roller_length
    if isinstance(z, bool) or not float(z).is_integer() or z < 1:
        raise InputError("rollers", f"must be a whole number >= 1, not {z!r}")
    if not 0 < dw < (new.D - new.d) / 2:
        raise InputError("roller_diameter", f"{dw:g} mm does not fit the rings")
    if not new.d + dw < dm < new.D - dw:
        raise InputError("pitch_diameter", f"{dm:g} mm puts the rollers outside the rings")
    if z > 1 and not dw < dm * math.sin(math.pi / z):
        raise InputError("rollers", f"{z} rollers of {dw:g} mm overlap on d_m {dm:g} mm")
    if not (math.isfinite(le) and le > 0):
        raise InputError("roller_length", f"must be > 0 mm, not {le!r}")
    return dataclasses.replace(new, rollers=int(z))


def line_contact_pressure(
    load: ArrayLike,
    length: ArrayLike,
    roller_diameter: float,
    pitch_diameter: float,
    modulus: float = STEEL_MODULUS,
    poisson: float = STEEL_POISSON,
) -> tuple[Any, Any]:
    """Maximum Hertz pressure of a roller's inner and outer line contacts. [MPa]

    p_0 = sqrt(Q E* sum_rho / (pi L)), E* = E / (2 (1 - nu^2)) for two equal bodies (Johnson,
    *Contact Mechanics*, 1985, eq. 4.45, with 1/R = sum_rho).

    Parameters
    ----------
    load : array_like
        Roller load Q >= 0. [N]
    length : array_like
        Effective contact length L_we > 0. [mm]
    roller_diameter, pitch_diameter : float
        D_w, d_m. [mm]
    modulus : float
        Young's modulus E of rollers and rings, > 0. [MPa]
    poisson : float
        Poisson's ratio nu, in (-1, 0.5]. [-]

    Returns
    -------
    (p_inner, p_outer)
        [MPa]

    >>> p_i, p_o = line_contact_pressure(5000.0, 8.792, 9.0, 46.5)
    >>> round(float(p_i)), round(float(p_o))
    (2388, 1963)
    """
    q = np.asarray(load, dtype=float)
    le = np.asarray(length, dtype=float)
    if np.any(~np.isfinite(q)) or np.any(q < 0):
        raise InputError("load", f"must be finite and >= 0 N, not {load!r}")
    if np.any(~np.isfinite(le)) or np.any(le <= 0):
        raise InputError("roller_length", f"must be finite and > 0 mm, not {length!r}")
    e, nu = float(modulus), float(poisson)
    if not (math.isfinite(e) and e > 0):
        raise InputError("modulus", f"must be finite and > 0 MPa, not {modulus!r}")
    if not -1.0 < nu <= 0.5:
        raise InputError("poisson", f"must lie in (-1, 0.5], not {poisson!r}")
    dw, dm = float(roller_diameter), float(pitch_diameter)
    e_star = e / (2.0 * (1.0 - nu * nu))
    rho_i = 2.0 / dw + 2.0 / (dm - dw)
    rho_o = 2.0 / dw - 2.0 / (dm + dw)
    p_i = np.sqrt(q * e_star * rho_i / (math.pi * le))
    p_o = np.sqrt(q * e_star * rho_o / (math.pi * le))
    return scalar_out(p_i), scalar_out(p_o)
