"""The viscosity of an oil at its operating temperature: ISO 3448 grades and ASTM D341 (Walther).

* ISO 3448 viscosity grades (ISO VG): the grade's number is the mid-point kinematic viscosity at
  40 °C in mm^2/s, within +-10 % (ISO 3448:1992, Table 1; reproduced e.g. in AIMS Industrial's
  "Oil viscosity chart", VG 22 = 19.8-24.2 ... VG 460 = 414-506 cSt at 40 °C). The mid-points of
  the 20 grades are :data:`ISO_VG`.
* ASTM D341 viscosity-temperature relation (Walther's equation), for kinematic viscosities of
  2 mm^2/s and more::

      log10 log10(nu + 0.7) = A - B log10 T        (nu in mm^2/s, T in K = °C + 273.15)

  A and B from two known points (nu_1, T_1), (nu_2, T_2)::

      B = (log log(nu_1 + 0.7) - log log(nu_2 + 0.7)) / (log T_2 - log T_1)
      A = log log(nu_1 + 0.7) + B log T_1

  The form and this solution are as ASTM D341 prints them (and as a published worked example:
  nu = 32 cSt at 40 °C, 5.4 cSt at 100 °C, T = °C + 273: A = 9.5259, B = 3.7449, 8.5 cSt at
  80 °C; the tests check it).

* ASTM D2270 viscosity index (VI) from nu_40 = U and nu_100 = Y: L and H, the viscosities at
  40 °C of the reference oils of VI 0 and 100 with the same nu_100, from the standard's Table 1
  for 2 <= Y <= 70 mm^2/s (linear interpolation between its rows, as 5.1.1 says) and above 70
  from its formulas L = 0.8353 Y^2 + 14.67 Y - 216, H = 0.1684 Y^2 + 11.85 Y - 97. Procedure A
  (VI <= 100, U >= H): VI = 100 (L - U)/(L - H); Procedure B (VI >= 100, U <= H):
  N = (log H - log U)/log Y, VI = (10^N - 1)/0.00715 + 100. The standard's worked examples
  (73.30 and 8.86 mm^2/s: L = 119.94, H = 69.48, VI 92; 22.83 and 5.05: H = 28.97, VI 156) are
  checked by the tests. Table 1 (311 rows, nu_100 = 2.0 ... 70.0 mm^2/s) is
  ``data/astm_d2270_table1.csv``: ASTM D2270-10 Table 1 as carried by two independent open
  transcriptions (sherzodr/libvisc ``libvisc.h``, CalebBell/chemicals ``viscosity.py``), which
  agree in every one of the 933 numbers and reproduce the standard's interpolated L and H.
  :func:`viscosity_100_of_index` inverts it for nu_100 (an oil given by its grade and VI).

>>> round(viscosity_at(68.0, 8.6, 70.0), 2)  # VG68, nu_100 = 8.6 mm^2/s, at 70 °C
19.97
"""

from __future__ import annotations

import functools
import re
from typing import TYPE_CHECKING, Any

import numpy as np

from bearingload.errors import InputError
from bearingload.numerics import scalar_out

if TYPE_CHECKING:
    from numpy.typing import ArrayLike

#: ISO 3448 grades: VG number -> mid-point kinematic viscosity at 40 °C. [mm^2/s]
ISO_VG: dict[int, float] = {
    2: 2.2, 3: 3.2, 5: 4.6, 7: 6.8, 10: 10.0, 15: 15.0, 22: 22.0, 32: 32.0, 46: 46.0, 68: 68.0,
    100: 100.0, 150: 150.0, 220: 220.0, 320: 320.0, 460: 460.0, 680: 680.0, 1000: 1000.0,
    1500: 1500.0, 2200: 2200.0, 3200: 3200.0,
}  # fmt: skip
#: The tolerance of a grade's viscosity at 40 °C about its mid-point (ISO 3448). [-]
ISO_VG_TOLERANCE = 0.10
#: 0 °C in kelvin (ASTM D341 takes T = t + 273.15). [K]
ZERO_CELSIUS = 273.15
#: The smallest kinematic viscosity the plain Walther form (the constant 0.7) covers. [mm^2/s]
WALTHER_MIN = 2.0
#: The viscosity index taken for an oil given by its grade alone: a mineral oil of VI 95, the
#: VI SKF's viscosity-temperature diagram of the ISO grades is drawn for and the least SKF
#: recommends for rolling bearings (skf.com, "Selecting lubricating oils"). [-]
DEFAULT_VISCOSITY_INDEX = 95.0
#: ASTM D2270's smallest nu_100 with a viscosity index (Table 1's first row). [mm^2/s]
D2270_MIN = 2.0
#: The nu_100 above which ASTM D2270 takes L and H from its formulas, not Table 1. [mm^2/s]
D2270_TABLE_MAX = 70.0
#: The least nu_40 (rounded up) from which the VI of D2270 rises with nu_100 over all of
#: [2 mm^2/s, nu_40], the step at nu_100 = 70 apart; below it the VI falls with nu_100 (for nu_40
#: up to 2.14) or falls and rises (2.15 to 2.226 mm^2/s, measured on a grid of 2e5 nu_100 per
#: oil; tests/test_oil.py checks it), so a VI does not fix nu_100 there. [mm^2/s]
D2270_RISING_FROM = 2.23


def iso_grade(text: str) -> float:
    """The mid-point viscosity at 40 °C of an ISO 3448 grade written VG68, ISO VG 68 or 68.
    [mm^2/s]

    >>> iso_grade("VG68"), iso_grade("iso vg 1000")
    (68.0, 1000.0)
    """
    match = re.fullmatch(r"\s*(?:iso\s*)?(?:vg\s*)?(\d+)\s*", str(text), flags=re.IGNORECASE)
    grade = int(match.group(1)) if match else None
    if grade not in ISO_VG:
        raise InputError(
            "oil",
            f"unknown ISO 3448 grade {text!r}; allowed: " + ", ".join(f"VG{g}" for g in ISO_VG),
        )
    return ISO_VG[grade]


def walther_constants(
    nu_1: ArrayLike, t_1: ArrayLike, nu_2: ArrayLike, t_2: ArrayLike
) -> tuple[Any, Any]:
    """(A, B) of ASTM D341's log log(nu + 0.7) = A - B log T through two points. [-]

    Parameters
    ----------
    nu_1, nu_2 : array_like
        Kinematic viscosities at T_1 and T_2, at least 2. [mm^2/s]
    t_1, t_2 : array_like
        Absolute temperatures, T_1 != T_2. [K]

    >>> [round(v, 4) for v in walther_constants(32.0, 313.0, 5.4, 373.0)]
    [9.5259, 3.7449]
    """
    n1, n2 = np.asarray(nu_1, dtype=float), np.asarray(nu_2, dtype=float)
    k1, k2 = np.asarray(t_1, dtype=float), np.asarray(t_2, dtype=float)
    if not np.all(np.isfinite(n1) & np.isfinite(n2) & (n1 >= WALTHER_MIN) & (n2 >= WALTHER_MIN)):
        raise InputError(
            "viscosity_100",
            f"ASTM D341's Walther form needs viscosities of {WALTHER_MIN:g} mm^2/s or more; got "
            f"{n1} and {n2}",
        )
    if not np.all(np.isfinite(k1) & np.isfinite(k2) & (k1 > 0) & (k2 > 0) & (k1 != k2)):
        raise InputError("temperature", "needs two different absolute temperatures > 0 K")
    y1, y2 = np.log10(np.log10(n1 + 0.7)), np.log10(np.log10(n2 + 0.7))
    b = (y1 - y2) / (np.log10(k2) - np.log10(k1))
    return scalar_out(y1 + b * np.log10(k1)), scalar_out(b)


def viscosity_at(nu_40: ArrayLike, nu_100: ArrayLike, temperature: ArrayLike) -> Any:
    """Kinematic viscosity at ``temperature`` from those at 40 and 100 °C (ASTM D341). [mm^2/s]

    Parameters
    ----------
    nu_40, nu_100 : array_like
        Kinematic viscosities at 40 °C and 100 °C, nu_40 > nu_100 >= 2. [mm^2/s]
    temperature : array_like
        Operating temperature. [°C]

    >>> round(viscosity_at(32.0, 5.4, 40.0), 9), round(viscosity_at(32.0, 5.4, 100.0), 9)
    (32.0, 5.4)
    """
    n40, n100 = np.asarray(nu_40, dtype=float), np.asarray(nu_100, dtype=float)
    if not np.all(n40 > n100):
        raise InputError(
            "viscosity_100",
            f"must be below the viscosity at 40 °C (an oil thins as it warms); got {n100} "
            f"against {n40} mm^2/s",
        )
    for name, nu, celsius in (("viscosity_40", n40, 40), ("viscosity_100", n100, 100)):
        if not np.all(np.isfinite(nu) & (nu >= WALTHER_MIN)):  # named for what it is
            raise InputError(
                name,
                f"ASTM D341's Walther form needs the oil's viscosity at {celsius} °C to be "
                f"{WALTHER_MIN:g} mm^2/s or more; got {_shown(nu)} mm^2/s",
            )
    t = np.asarray(temperature, dtype=float) + ZERO_CELSIUS
    a, b = walther_constants(n40, 40.0 + ZERO_CELSIUS, n100, 100.0 + ZERO_CELSIUS)
    nu = np.asarray(walther_viscosity(a, b, t), dtype=float)
    # the form's range, as for its inputs (a rounding below nu_100 = 2 itself is kept)
    if not np.all(np.isfinite(nu) & (nu >= WALTHER_MIN * (1.0 - 1e-12))):
        raise InputError(
            "temperature",
            f"ASTM D341's Walther form covers {WALTHER_MIN:g} mm^2/s or more and finite; at "
            f"{_shown(temperature)} °C it gives {_shown(nu)} mm^2/s for this oil: give a "
            "temperature where it stays in that range, or the operating viscosity itself",
        )
    return scalar_out(nu)


def _shown(values: ArrayLike) -> str:
    """One value to 6 digits, or the array as numpy prints it (a message's number)."""
    v = np.asarray(values, dtype=float)
    return f"{float(v):.6g}" if v.size == 1 else str(v)


def walther_viscosity(a: ArrayLike, b: ArrayLike, temperature: ArrayLike) -> Any:
    """nu = 10^(10^(A - B log10 T)) - 0.7 of ASTM D341 at the absolute ``temperature`` [K].
    [mm^2/s]

    >>> round(walther_viscosity(9.5259, 3.7449, 353.0), 1)  # 80 °C of the worked example
    8.5
    """
    t = np.asarray(temperature, dtype=float)
    if not np.all(np.isfinite(t) & (t > 0)):
        raise InputError("temperature", f"must be an absolute temperature > 0 K; got {t}")
    with np.errstate(over="ignore"):
        nu = 10.0 ** (
            10.0 ** (np.asarray(a, dtype=float) - np.asarray(b, dtype=float) * np.log10(t))
        )
    return scalar_out(nu - 0.7)


@functools.lru_cache(maxsize=1)
def d2270_table() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """ASTM D2270 Table 1: nu_100 and the L and H of its 311 rows (``data/astm_d2270_table1.csv``,
    source in the module docstring). [mm^2/s]"""
    from bearingload.bearings._data import read_rows

    rows = read_rows("astm_d2270_table1.csv")
    columns = (np.array([float(r[k]) for r in rows]) for k in ("nu_100", "L", "H"))
    nu, low, high = columns
    for a in (nu, low, high):
        a.setflags(write=False)
    return nu, low, high


def reference_viscosities(nu_100: ArrayLike) -> tuple[Any, Any]:
    """(L, H) of ASTM D2270: the viscosities at 40 °C of the reference oils of VI 0 and VI 100
    whose viscosity at 100 °C is ``nu_100`` (Table 1 interpolated up to 70 mm^2/s, the
    standard's formulas above). [mm^2/s]

    >>> [round(float(v), 2) for v in reference_viscosities(8.86)]  # D2270's example, 5.1.4
    [119.94, 69.48]
    """
    y = np.asarray(nu_100, dtype=float)
    if not np.all(np.isfinite(y) & (y >= D2270_MIN)):
        raise InputError(
            "viscosity_100",
            f"ASTM D2270 defines a viscosity index for a viscosity at 100 °C of "
            f"{D2270_MIN:g} mm^2/s or more; got {y}",
        )
    nu, low, high = d2270_table()
    table = y <= nu[-1]
    l_ref = np.where(table, np.interp(y, nu, low), 0.8353 * y**2 + 14.67 * y - 216.0)
    h_ref = np.where(table, np.interp(y, nu, high), 0.1684 * y**2 + 11.85 * y - 97.0)
    return scalar_out(l_ref), scalar_out(h_ref)


def viscosity_index(nu_40: ArrayLike, nu_100: ArrayLike) -> Any:
    """The viscosity index of ASTM D2270 (unrounded; the standard reports it rounded to a whole
    number): Procedure A where nu_40 >= H (VI <= 100), else Procedure B. [-]

    Parameters
    ----------
    nu_40, nu_100 : array_like
        Kinematic viscosities at 40 °C (> 0) and 100 °C (>= 2). [mm^2/s]

    >>> round(viscosity_index(73.30, 8.86)), round(viscosity_index(22.83, 5.05))
    (92, 156)
    """
    u = np.asarray(nu_40, dtype=float)
    y = np.asarray(nu_100, dtype=float)
    if not np.all(np.isfinite(u) & (u > 0)):
        raise InputError("viscosity_40", f"must be a finite viscosity > 0 mm^2/s; got {u}")
    l_ref, h_ref = (np.asarray(v, dtype=float) for v in reference_viscosities(y))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        by_a = 100.0 * (l_ref - u) / (l_ref - h_ref)
        n = (np.log10(h_ref) - np.log10(u)) / np.log10(y)
        by_b = (10.0**n - 1.0) / 0.00715 + 100.0
    return scalar_out(np.where(u >= h_ref, by_a, by_b))


def _top(nu_40: np.ndarray) -> np.ndarray:
    """The nu_100 of the largest VI an oil of ``nu_40`` has: nu_40 itself (excluded: the oil
    must thin), or 70 mm^2/s where the step down of the VI at 70 (Table 1 to the formulas)
    leaves the VI at nu_40 below that at 70, for nu_40 just above 70. [mm^2/s]"""
    top = nu_40.copy()
    above = nu_40 > D2270_TABLE_MAX
    if np.any(above):
        at_70 = np.asarray(viscosity_index(nu_40[above], D2270_TABLE_MAX))
        at_top = np.asarray(viscosity_index(nu_40[above], nu_40[above]))
        top[above] = np.where(at_70 > at_top, D2270_TABLE_MAX, nu_40[above])
    return top


def viscosity_100_of_index(nu_40: ArrayLike, index: ArrayLike) -> Any:
    """The viscosity at 100 °C of an oil of viscosity ``nu_40`` at 40 °C and viscosity index
    ``index``: :func:`viscosity_index` inverted by bisection on nu_100 in [2, nu_40] (to
    machine precision). At a given nu_40 of :data:`D2270_RISING_FROM` or more the VI rises with
    nu_100, but for a step down at nu_100 = 70 mm^2/s (the standard's Table 1 gives L = 4905,
    H = 1558 there, its formulas 4903.87, 1557.66 just above): a VI within that step (0.01 to
    0.09 for nu_40 of 71 to 10^4 mm^2/s) is had by two nu_100 within 0.02 mm^2/s of 70, and
    the bisection returns one of them. Below :data:`D2270_RISING_FROM` the VI does not fix
    nu_100 and is refused. [mm^2/s]

    Parameters
    ----------
    nu_40 : array_like
        Kinematic viscosity at 40 °C, at least :data:`D2270_RISING_FROM`. [mm^2/s]
    index : array_like
        Viscosity index, from that of nu_100 = 2 mm^2/s (the least ASTM D2270 defines) to below
        that of nu_100 = nu_40 for this nu_40 (up to that at nu_100 = 70 where larger). [-]

    >>> round(viscosity_100_of_index(73.30, viscosity_index(73.30, 8.86)), 9)
    8.86
    """
    u, v = np.broadcast_arrays(np.asarray(nu_40, dtype=float), np.asarray(index, dtype=float))
    if not np.all(np.isfinite(v)):
        raise InputError("viscosity_index", f"must be a finite number; got {v}")
    if not np.all(np.isfinite(u) & (u > D2270_MIN)):
        raise InputError(
            "viscosity_40",
            f"an oil given by its viscosity index needs a viscosity at 40 °C above {D2270_MIN:g} "
            f"mm^2/s (ASTM D2270 defines no VI below {D2270_MIN:g} mm^2/s at 100 °C); got {u}",
        )
    if np.any(u < D2270_RISING_FROM):
        raise InputError(
            "viscosity_index",
            f"an oil of {u.flat[np.argmax(u < D2270_RISING_FROM)]:.10g} mm^2/s at 40 °C has by "
            f"ASTM D2270 a VI that does not rise steadily with nu_100 (it does from nu_40 = "
            f"{D2270_RISING_FROM:g} mm^2/s up), so its VI does not fix its viscosity at 100 °C",
        )
    lo, hi = np.full(u.shape, D2270_MIN), _top(u)
    least, most = np.asarray(viscosity_index(u, lo)), np.asarray(viscosity_index(u, hi))
    bad = ~((v >= least) & ((v <= most) & (hi < u) | (v < most)))
    if np.any(bad):
        i = np.flatnonzero(bad)[0]
        top = "to below" if hi.flat[i] == u.flat[i] else "to"
        raise InputError(
            "viscosity_index",
            f"an oil of {u.flat[i]:.10g} mm^2/s at 40 °C has by ASTM D2270 a VI from "
            f"{least.flat[i]:.6g} (nu_100 = {D2270_MIN:g} mm^2/s, the least the standard "
            f"defines) {top} {most.flat[i]:.6g} (nu_100 = {hi.flat[i]:.6g} mm^2/s); got "
            f"{v.flat[i]:g}",
        )
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        below = np.asarray(viscosity_index(u, mid)) < v
        lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
        if np.all(hi - lo <= 4.0 * np.finfo(float).eps * hi):
            break
    return scalar_out(0.5 * (lo + hi))


#: The inputs that give the operating viscosity from the oil instead of the viscosity itself:
#: ``solve``'s options and ``batch``'s columns of these names (:func:`operating_viscosity`).
OIL_INPUTS = ("oil", "viscosity_40", "viscosity_100", "viscosity_index", "temperature")


class OilInputError(InputError):
    """An oil input refused for what is given with it (:func:`operating_viscosity`).

    Attributes
    ----------
    kind : str
        ``"conflict"``: ``parameter`` cannot be used with ``other``; ``"missing"``:
        ``parameter`` (of several ``parameters``: one of them) is needed; ``"choice"``: one of
        ``parameters`` is needed, not both, and both are given.
    parameters : tuple of str
        The inputs named (``parameter`` is the first).
    other : str or None
        The input it conflicts with.
    why : str
        The reason; other inputs are named in quotes (``'temperature'``).
    """

    def __init__(
        self, kind: str, parameters: tuple[str, ...], why: str, other: str | None = None
    ) -> None:
        self.kind, self.parameters, self.other, self.why = kind, parameters, other, why
        text = {"conflict": f"cannot be used with '{other}': {why}", "missing": f"missing: {why}"}
        super().__init__(" / ".join(parameters), text.get(kind, why))
        self.parameter = parameters[0]


def operating_viscosity(
    viscosity: float | None = None,
    *,
    oil: str | None = None,
    viscosity_40: float | None = None,
    viscosity_100: float | None = None,
    viscosity_index: float | None = None,
    temperature: float | None = None,
) -> tuple[float | None, str | None]:
    """The operating viscosity of one case, given or from its oil, and a note saying how: the
    one rule of ``solve``'s options and ``batch``'s columns (:data:`OIL_INPUTS`). [mm^2/s]

    ``viscosity`` given, it is the answer (no oil input allowed beside it). Otherwise the oil is
    its ISO 3448 grade ``oil`` (nu_40 its mid-point) or its ``viscosity_40``, one of the two,
    at ``temperature`` [°C] (needed); nu_100 is ``viscosity_100``, else that of the viscosity
    index (``viscosity_index``, default :data:`DEFAULT_VISCOSITY_INDEX`) by ASTM D2270
    (:func:`viscosity_100_of_index`), not both; nu by ASTM D341 (:func:`viscosity_at`). No
    input at all: (None, None).

    >>> nu, note = operating_viscosity(oil="VG68", viscosity_100=8.6, temperature=70.0)
    >>> round(nu, 2)
    19.97

    Raises
    ------
    OilInputError
        A combination refused (``kind`` says how).
    InputError
        An oil input out of its domain (an unknown grade, a VI the oil cannot have ...).
    """
    given = {"oil": oil, "viscosity_40": viscosity_40, "viscosity_100": viscosity_100,
             "viscosity_index": viscosity_index, "temperature": temperature}  # fmt: skip
    first = next((n for n in OIL_INPUTS if given[n] is not None), None)
    if viscosity is not None or first is None:
        if first is not None:
            why = "give the viscosity at the operating temperature, or the oil and its temperature"
            raise OilInputError("conflict", (first,), why, other="viscosity")
        return viscosity, None
    if (oil is None) == (viscosity_40 is None):  # neither given: missing; both: a conflict
        raise OilInputError("missing" if oil is None else "choice", ("oil", "viscosity_40"), (
            "give the oil by its ISO 3448 grade ('oil' VG68) or by its viscosity at 40 °C "
            "('viscosity_40'), one of the two, with 'temperature'"))  # fmt: skip
    if temperature is None:
        raise OilInputError("missing", ("temperature",), "the oil's viscosity at the operating "
                            "temperature follows (ASTM D341) from its viscosities at 40 and 100 °C")  # fmt: skip
    if viscosity_100 is not None and viscosity_index is not None:
        why = "the viscosity index gives the viscosity at 100 °C; give one of the two"
        raise OilInputError("conflict", ("viscosity_index",), why, other="viscosity_100")
    nu40 = iso_grade(oil) if oil is not None else float(viscosity_40)  # type: ignore[arg-type]
    if viscosity_100 is not None:
        nu100, how = float(viscosity_100), ""
    else:
        index = DEFAULT_VISCOSITY_INDEX if viscosity_index is None else float(viscosity_index)
        nu100 = _viscosity_100_of(nu40, index, given=viscosity_index is not None)
        which = "given" if viscosity_index is not None else (
            "default, a mineral oil; 'viscosity_index' to give it")  # fmt: skip
        how = f" (derived by ASTM D2270 from VI {index:g}, {which})"
    nu = float(viscosity_at(nu40, nu100, temperature))
    if oil is not None:
        grade = oil.upper().replace("ISO", "").replace("VG", "").strip()
        source = f"ISO VG {grade} (nu_40 = {nu40:g} mm^2/s, the grade's mid-point; +-10 %)"
    else:
        source = f"nu_40 = {nu40:g} mm^2/s"
    return nu, (
        f"nu = {nu:.4g} mm^2/s at {temperature:g} °C: ASTM D341 (Walther, log log(nu + 0.7) = "
        f"A - B log T) through {source} and nu_100 = {nu100:.4g} mm^2/s{how}."
    )


@functools.lru_cache(maxsize=4096)
def _viscosity_100_of(nu_40: float, index: float, *, given: bool) -> float:
    """nu_100 of an oil of ``nu_40`` and VI ``index`` (:func:`viscosity_100_of_index`, one oil
    at a time, kept: a batch file repeats its oils); the default VI refused in words that say it
    was the default. [mm^2/s]"""
    try:
        return float(viscosity_100_of_index(nu_40, index))
    except InputError as exc:
        if given or exc.parameter != "viscosity_index":
            raise
        why = exc.problem
        # below D2270_RISING_FROM no VI fixes nu_100: only nu_100 itself helps
        give = "'viscosity_100'" + (" or 'viscosity_index'" if nu_40 >= D2270_RISING_FROM else "")
        raise InputError(
            "viscosity_index",
            f"the default VI {index:g} (a mineral oil) does not fit this oil: {why}",
            way_out=f"give its {give}",
        ) from exc
