"""A pair of identical angular-contact ball bearings on one shaft: back-to-back (DB), face-to-face
(DF) or tandem (DT), with an axial preload.

The model (each bearing as :mod:`bearingload.models.combined`, one-sided, on one rigid shaft),
the preload, the lift-off load and the numerics: docs/angular_contact.md, "Pairs: DB, DF, DT".
Each case is solved alone in the compiled core (:func:`bearingload.models._core.pair_call`,
which also sets it up and gives its results). This module keeps the checks and the refusals: a
call the core answers whole is one core call; one with a case it flags (a width or geometry to
refuse, a Hertz set-up it cannot make, loads it cannot scale, a case unbalanced, a ball at the
groove edge, a stiffness that overflows) takes :func:`_general`, which refuses in the order of
the checks.
"""

from __future__ import annotations

import dataclasses
import functools
import itertools
import math
import operator
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from bearingload import numerics, validate
from bearingload.constants import STEEL_MODULUS
from bearingload.errors import ConvergenceError, InputError
from bearingload.models import _core
from bearingload.models import combined as _comb
from bearingload.models._combined_ring import ACCEPT
from bearingload.models._ring import SYMMETRY_SNAP_DEG
from bearingload.models.combined import CombinedDistribution, StiffnessViews

__all__ = [
    "ARRANGEMENTS",
    "LIFE_EXPONENT",
    "PairDistribution",
    "solve_pair",
    "pair_life",
    "signs",
    "levers",
    "shaft_maps",
    "held_components",
]

#: The arrangements: back-to-back, face-to-face, tandem.
ARRANGEMENTS = ("DB", "DF", "DT")
#: Weibull exponent e of a ball bearing's life, combining the lives of its parts: ISO/TS
#: 16281:2008, 4.3 (the rings' lives, ``L = (L_i^-e + L_e^-e)^(-1/e)``, written there as the
#: exponent -9/10 = -1/e) and ISO 281:2007's system rule (Lundberg-Palmgren). [-]
LIFE_EXPONENT = 10.0 / 9.0


@dataclass(frozen=True)
class PairDistribution(StiffnessViews):
    """Solution of a bearing pair; arrays of the case shape.

    Attributes
    ----------
    arrangement : str
        "DB", "DF" or "DT".
    bearings : tuple of two CombinedDistribution
        Each bearing in its own frame (bearing 2 of DB/DF mirrored): ``load``, ``axial_load``
        and ``moment`` are the forces its balls carry (the size of its radial force, F_a >= 0
        its thrust, M its own moment), ``x``..``tilt_cross`` its local displacement, ``axial``
        from its zero-load position (the preload offset included). [N, N mm, mm, °]
    load, axial_load, moment, moment_cross : ndarray
        The loads applied to the shaft. [N, N mm]
    preload : ndarray
        F_p, the axial force each bearing of DB/DF carries with no external load. [N]
    preload_offset : ndarray
        The axial approach of each bearing at the preload. [mm]
    width : ndarray
        B; the bearings' centres lie B/2 either side of the pair's centre. [mm]
    x, y, axial, tilt, tilt_cross : ndarray
        The shaft's displacement at the pair's centre. [mm, °]
    stiffness_matrix : ndarray (..., 5, 5)
        d(F_x, F_y, F_a, M, M_c)/d(x, y, axial, tilt, tilt_cross) of the shaft at the pair's
        centre, the true tangent (its symmetric part: ``stiffness_matrix_symmetric``). [N/mm,
        N/rad, N mm/mm, N mm/rad]
    unloaded : ndarray (..., 2) of bool
        Whether each bearing carries no load.
    lift_off_axial_load : ndarray or None
        DB/DF: the external axial load alone (the sign of the given one, + if 0) at which the
        opposite bearing carries nothing (0 without preload). None for DT. [N]
    residual : ndarray
        The largest residual of the pair's equilibrium over its applied load (or the rounding
        of its terms). [-]
    iterations : ndarray of int
        Newton steps. [-]
    """

    arrangement: str
    bearings: tuple[CombinedDistribution, CombinedDistribution]
    load: Any
    axial_load: Any
    moment: Any
    moment_cross: Any
    preload: Any
    preload_offset: Any
    width: Any
    x: Any
    y: Any
    axial: Any
    tilt: Any
    tilt_cross: Any
    stiffness_matrix: np.ndarray
    unloaded: np.ndarray
    lift_off_axial_load: Any
    residual: Any
    iterations: Any


def pair_life(life_1: Any, life_2: Any, exponent: float = LIFE_EXPONENT) -> Any:
    """The life of two bearings that both must survive: ``(L1^-e + L2^-e)^(-1/e)`` (ISO/TS
    16281:2008, 4.3, the same rule for the rings of one bearing; Lundberg-Palmgren's system
    life, e = 10/9 for ball bearings). An infinite life (an unloaded bearing) drops out.
    [the unit of the lives]

    >>> round(float(pair_life(1000.0, 1000.0)), 3)
    535.887
    """
    a = np.asarray(life_1, dtype=float)
    b = np.asarray(life_2, dtype=float)
    with np.errstate(divide="ignore", over="ignore"):
        total = a ** (-exponent) + b ** (-exponent)
        out = np.where(total > 0, total ** (-1.0 / exponent), np.inf)
    out = np.where(np.isinf(a), b, np.where(np.isinf(b), a, out))  # exactly the other one
    return numerics.scalar_out(out)


def signs(kind: str) -> np.ndarray:
    """sigma_k (2,): +1, or -1 for bearing 2 of DB and DF, mirrored."""
    return np.array([1.0, 1.0 if kind == "DT" else -1.0])


def halves(kind: str) -> np.ndarray:
    """z_k / B (2,): each bearing's centre from the pair's over the width B of one bearing:
    bearing 1 at -B/2 in DB and DT, at +B/2 in DF."""
    first = -0.5 if kind in ("DB", "DT") else 0.5
    return np.array([first, -first])


def levers(kind: str, width: np.ndarray, radius: np.ndarray) -> np.ndarray:
    """z_k / R_i (n, 2): each bearing's centre from the pair's (:func:`halves`, ``width`` B),
    over the tilt lever ``radius``."""
    return halves(kind) * width[:, None] / radius[:, None]


def shaft_maps(sigma: np.ndarray, lever: np.ndarray) -> np.ndarray:
    """L_k (n, 2, 5, 5): each bearing's local displacement per shaft displacement (x, y, a,
    t, t_c), t the tilt times the lever; ``sigma`` (2,) +1, or -1 for a mirrored bearing;
    ``lever`` (n, 2) z_k over the tilt lever (:func:`levers`)."""
    diagonal = np.ones((2, 5))
    diagonal[:, 2:] = sigma[:, None]
    m = np.zeros((lever.shape[0], 2, 5, 5))
    m.reshape(-1, 2, 25)[:, :, ::6] = diagonal  # (the diagonal: every sixth of the 25)
    m[:, :, 0, 3] = m[:, :, 1, 4] = -lever
    return m


def held_components(kind: str, mirror: np.ndarray, loads: tuple[np.ndarray, ...]) -> np.ndarray:
    """(n, 5) bool: the components of the shaft's (x, y, a, t, t_c) 0 by a symmetry of the case,
    exactly: y and t_c where the balls are symmetric about the load line (``mirror``) and no
    moment acts across it; the z-fold symmetry (z >= 3) without a radial load or moment; the
    bearings' mirror image across the pair's mid-plane (not DT's) without a thrust or moment.
    ``loads`` = (F_r, F_a, M, M_c) (n,) each. The rule is the compiled core's (``locks``, of
    its ``symmetry_locks``, which its ``pair_call`` applies; a pair's z >= 3)."""
    mirrored = np.ascontiguousarray(mirror, dtype=bool).view(np.uint8)
    return _core.locks(3, mirrored, np.array(loads, dtype=float), False, kind == "DT")


#: Largest width B of one bearing (the distance of the two bearings' centres) over the pitch
#: diameter d_m that a pair takes; measured: 1e8 mm on a 38.5 mm pitch solves, 1e9 mm did not
#: converge. [-]
WIDTH_MAX = 1000.0


def solve_pair(
    balls: int,
    radial_load: Any,
    axial_load: Any = 0.0,
    *,
    arrangement: str = "DB",
    preload: Any = 0.0,
    contact_angle: Any,
    ball_diameter: Any,
    pitch_diameter: Any,
    width: Any,
    f_i: Any = 0.52,
    f_o: Any = 0.53,
    cage_angle: Any = 0.0,
    moment: Any = 0.0,
    moment_cross: Any = 0.0,
    modulus: Any = STEEL_MODULUS,
    poisson: Any = 0.3,
    stiffness: Any = None,
    tilt_radius: Any = None,
) -> PairDistribution:
    """Equilibrium of the shaft in a pair of identical angular-contact ball bearings.

    Model and conventions: docs/angular_contact.md, "Pairs: DB, DF, DT". Arrays broadcast
    over cases.

    Parameters
    ----------
    balls : int
        Balls per bearing z, 3 to 1000. [-]
    radial_load : array_like
        F_r >= 0 on the shaft at the pair's centre, along the load line. [N]
    axial_load : array_like, default 0
        F_a on the shaft, towards +axial (bearing 1's thrust); DT: > 0. [N]
    arrangement : {"DB", "DF", "DT"}
        Back-to-back, face-to-face, tandem.
    preload : array_like, default 0
        F_p >= 0, the axial force each bearing carries with no external load (DB, DF). [N]
    contact_angle : array_like
        Design contact angle alpha_0, above 0 to 60. [°]
    ball_diameter, pitch_diameter : array_like
        D_w and d_m; the z balls must fit on the pitch circle, D_w <= d_m sin(180°/z)
        (:func:`bearingload.validate.ball_spacing`, as the command line checks). [mm]
    width : array_like
        B of one bearing, at least D_w and at most :data:`WIDTH_MAX` times d_m: their centres
        lie B/2 either side of the pair's centre. [mm]
    f_i, f_o : array_like, default 0.52, 0.53
        Groove conformities. [-]
    cage_angle : array_like, default 0
        Angle of ball 1 from the load line (both bearings). [°]
    moment, moment_cross : array_like, default 0
        Moments on the shaft in and across the plane of the load line. [N mm]
    modulus, poisson : array_like
        E [MPa] and nu [-].
    stiffness : array_like, optional
        A constant ball stiffness K instead of the Hertz K(alpha). [N/mm^1.5]
    tilt_radius : array_like, optional
        The lever of the tilt at each bearing (default R_i). [mm]

    Returns
    -------
    PairDistribution

    >>> r = solve_pair(12, 0.0, 0.0, preload=500.0, contact_angle=40.0, ball_diameter=8.7312,
    ...                pitch_diameter=38.5, width=15.0)
    >>> [round(float(b.axial_load), 6) for b in r.bearings]
    [500.0, 500.0]
    """
    kind = _arrangement(arrangement)
    z = _comb.call_balls(balls)
    if z < 3:
        raise InputError(
            "balls",
            "must be at least 3 per bearing of a pair: 1 or 2 balls leave the shaft free to "
            "turn about their line (a real bearing has many more)",
        )
    # every parameter by name, in the order the checks take them
    named = dict(radial_load=radial_load, axial_load=axial_load, preload=preload)
    named |= dict(contact_angle=contact_angle, ball_diameter=ball_diameter)
    named |= dict(pitch_diameter=pitch_diameter, width=width, f_i=f_i, f_o=f_o)
    named |= dict(cage_angle=cage_angle, moment=moment, moment_cross=moment_cross)
    named |= dict(modulus=modulus, poisson=poisson)
    if stiffness is not None:
        named["stiffness"] = stiffness
    if tilt_radius is not None:
        named["tilt_radius"] = tilt_radius
    if _plain(kind, named):  # one case of plain numbers, every check passed
        shape: tuple[int, ...] = ()
        plain = _NOT_GIVEN | named | {"cage_angle": validate.reduced_angle(named["cage_angle"])}
        cols = np.array(_ROWS_OF(plain)).reshape(-1, 1)
    else:
        shape, c = _checked(kind, named)
        c["cage_angle"] = validate.cage_angle(c["cage_angle"])
        n = c["cage_angle"].shape[0]
        cols = np.array(_ROWS_OF({k: np.zeros(n) for k in _NOT_GIVEN} | c))
    hertz = stiffness is None
    key = cols[_HERTZ_ROWS].tobytes() if hertz and cols.shape[1] == 1 else None
    known = _comb.known_setup(key)
    out = _call(z, kind, cols, hertz, known)
    if key is not None and not known.size and not out[1][0] & _NOT_SET_UP:
        _comb.remember_setup(key, np.concatenate((out[4], out[5][0])))
    if out[0]:  # the common path: every case answered by the one core call
        return _distribution(kind, z, shape, cols, out)
    with np.errstate(all="ignore"):
        return _general(z, kind, (shape, named), cols, (hertz, known), out)


#: The inputs of a pair packed, a row each (the cases along it), as the compiled core's
#: ``pair_call`` takes them: the loads (F_r, F_a, M, M_c, a misalignment, 0, and the preload:
#: ``combined_problem``'s), the cage angle, E and nu, the groove's five (D_w, d_m, f_i, f_o and
#: the design contact angle: ``groove``), the width, and the stiffness and the tilt radius (0
#: where not given).
INPUT_ROWS = (
    "radial_load",
    "axial_load",
    "moment",
    "moment_cross",
    "misalignment",
    "preload",
    "cage_angle",
    "modulus",
    "poisson",
    "ball_diameter",
    "pitch_diameter",
    "f_i",
    "f_o",
    "contact_angle",
    "width",
    "stiffness",
    "tilt_radius",
)
_ROWS_OF = operator.itemgetter(*INPUT_ROWS)
_NOT_GIVEN = {"misalignment": 0.0, "stiffness": 0.0, "tilt_radius": 0.0}
#: The rows of the Hertz set-up (E, nu, D_w, d_m, f_i, f_o: the order of the single bearing's
#: cache, :func:`bearingload.models.combined.known_setup`).
_HERTZ_ROWS = slice(7, 13)
_CAGE_ROW = INPUT_ROWS.index("cage_angle")
#: The core's flags of a case it could not set up (its general path sets it up or refuses).
_NOT_SET_UP = int(_core.PairFlag.BAD_WIDTH | _core.PairFlag.NO_GROOVE | _core.PairFlag.NO_CURVE)


def _call(z: int, kind: str, cols: np.ndarray, hertz: bool, known: np.ndarray) -> tuple:
    """The compiled core's ``pair_call`` of the packed inputs ``cols`` (its docstring), the
    Hertz set-up ``known`` of every case (or empty)."""
    low, high = validate.CONFORMITY_RANGE
    ratios = (_comb.GEOMETRY_RATIO_MAX, _comb.ANGULAR_RATIO_MIN)
    limits = (SYMMETRY_SNAP_DEG, *ratios, low, high, ACCEPT)
    limits += (1.0, -1.0 if kind != "DT" else 1.0, *halves(kind).tolist(), WIDTH_MAX, _chord(z))
    return _core.pair_call(z, cols, hertz, known, np.array(limits), _comb.NODE_X, _comb.NODE_W)


@functools.lru_cache(maxsize=64)
def _chord(z: int) -> float:
    """sin(180°/z), as :func:`bearingload.validate.ball_spacing` takes it: z balls of D_w above
    d_m times it overlap on the pitch circle (the core's ``pair_call`` flags them)."""
    return float(np.sin(np.pi / z))


def _general(
    z: int,
    kind: str,
    given_as: tuple[tuple[int, ...], dict[str, Any]],
    cols: np.ndarray,
    hertz: tuple[bool, np.ndarray],
    out: tuple,
    snap: bool = True,
) -> PairDistribution:
    """:func:`solve_pair` of the packed inputs a step at a time, from the core's call ``out``:
    each refusal in its order; with ``snap``, the cases left unbalanced with a cage within
    :data:`~bearingload.models.combined.NEAR_SYMMETRIC_DEG` of a symmetric position and no
    moment across the load line solved at that position, as the single bearing solves them
    (the cages of the answer are then that position). ``given_as``: the case shape and the
    inputs by name; ``hertz``: whether the stiffness is Hertz's, and its set-up given."""
    shape, named = given_as
    c = dict(zip(INPUT_ROWS, cols, strict=True))
    groove = (c[k] for k in ("ball_diameter", "pitch_diameter", "f_i", "f_o", "contact_angle"))
    geo = _comb.angular_geometry(*groove)  # (before the width, which is weighed against it)
    validate.ball_spacing(z, geo.D_w, geo.d_m)  # (z balls must fit on the pitch circle)
    _check_width(c, named, shape)
    if "tilt_radius" in named:
        geo = dataclasses.replace(geo, R_i=c["tilt_radius"])
    if hertz[0] and np.count_nonzero(out[1] & _core.PairFlag.NO_CURVE):  # (the core could not)
        k0, values = _comb.hertz_setup(geo, c["modulus"], c["poisson"])
        hertz = (True, np.concatenate((k0[:, None], values), axis=1).reshape(-1))
        out = _call(z, kind, cols, *hertz)
    names = ("radial_load", "axial_load", "moment", "moment_cross", "preload")
    if np.count_nonzero(out[2]):
        _refuse_scale(geo, out[4], out[2], *(c[k] for k in names))
    flags, its, res = out[1], out[3], out[9][12]
    unbalanced = (flags & _core.PairFlag.UNBALANCED) != 0
    if snap and np.count_nonzero(unbalanced):
        near = _near_symmetric(z, c["cage_angle"], c["moment_cross"]) & unbalanced
        if np.count_nonzero(near):
            cols = cols.copy()
            cols[_CAGE_ROW] = _symmetric(z, c["cage_angle"], near)
            out = _call(z, kind, cols, *hertz)
            return _general(z, kind, given_as, cols, hertz, out, False)
    given = {k: c[k] for k in NAMED}
    _accepted(res, its, given)
    _check_edge(flags, given)
    if np.count_nonzero(flags & _core.PairFlag.STIFF_OVERFLOW):
        _comb.refuse_overflow()
    return _distribution(kind, z, shape, cols, out)


def _check_width(c: dict[str, np.ndarray], named: dict[str, Any], shape: tuple[int, ...]) -> None:
    """Refuse a width below the ball diameter or beyond :data:`WIDTH_MAX` times d_m."""
    narrow = c["width"] < c["ball_diameter"]
    if np.count_nonzero(narrow):  # no ring holds its balls so; the shaft's tilt then has no lever
        i = int(np.argmax(narrow))
        raise InputError(
            "width",
            f"must be at least the ball diameter D_w (a bearing is wider than its balls): "
            f"B = {c['width'][i]:.6g} mm, D_w = {c['ball_diameter'][i]:.6g} mm",
            element=validate.element_at(named["width"], narrow, shape, "mm"),
        )
    wide = c["width"] > WIDTH_MAX * c["pitch_diameter"]
    if np.count_nonzero(wide):  # a shaft between two supports, not a pair (1e9 mm diverged)
        i = int(np.argmax(wide))
        raise InputError(
            "width",
            f"must be at most {WIDTH_MAX:g} times the pitch diameter d_m (two bearings that far "
            "apart are two supports of a shaft, not one pair): B = "
            f"{c['width'][i]:.6g} mm, d_m = {c['pitch_diameter'][i]:.6g} mm",
            element=validate.element_at(named["width"], wide, shape, "mm"),
        )


def _arrangement(arrangement: Any) -> str:
    kind = str(arrangement).upper()
    if kind not in ARRANGEMENTS:
        raise InputError(
            "arrangement",
            f"must be DB (back-to-back), DF (face-to-face) or DT (tandem), not {arrangement!r}",
        )
    return kind


def _refuse_contact_angle(v: dict[str, Any], bad: Any, at: Callable[..., str]) -> InputError:
    return InputError(
        "contact_angle",
        f"must be above 0 and at most {_comb.CONTACT_ANGLE_MAX:g}° for a bearing pair",
        element=at("contact_angle", bad, "°"),
    )


def _refuse_tandem_preload(v: dict[str, Any], bad: Any, at: Callable[..., str]) -> InputError:
    return InputError(
        "preload",
        "a tandem pair (DT) is not preloaded in itself: both bearings face the same way, "
        "so it is preloaded against another bearing; give 0, or use DB or DF",
        element=at("preload", bad, "N"),
    )


def _refuse_tandem_thrust(v: dict[str, Any], bad: Any, at: Callable[..., str]) -> InputError:
    return InputError(
        "axial_load",
        "must be > 0 N for a tandem pair (DT): both bearings take thrust towards +axial only "
        "(a reversed load lifts every ball; with none the axial position is held by "
        "another bearing)",
        element=at("axial_load", bad, "N"),
    )


#: The rules of the inputs of :func:`solve_pair` in the order they are checked (the first
#: refused is named), the single bearing's where they are the same
#: (:class:`bearingload.models.combined.Rule`): :func:`_checked` checks them one at a time,
#: :func:`_plain` all at once on one case of plain floats. ``given``: "DT" (the rule of a
#: tandem pair), or the optional input (stiffness, tilt_radius).
_INPUT_RULES = (
    _comb.RADIAL_LOAD_RULE,
    _comb.Rule(("axial_load", "preload")),
    _comb.Rule(
        ("contact_angle",),
        lambda v: (0.0 < v["contact_angle"]) & (v["contact_angle"] <= _comb.CONTACT_ANGLE_MAX),
        _refuse_contact_angle,
    ),
    _comb.Rule(
        ("preload",),
        lambda v: v["preload"] >= 0.0,
        lambda v, bad, at: InputError("preload", "must be >= 0 N", element=at("preload", bad, "N")),
    ),
    _comb.Rule(("preload",), lambda v: v["preload"] == 0.0, _refuse_tandem_preload, "DT"),
    _comb.Rule(("axial_load",), lambda v: v["axial_load"] > 0.0, _refuse_tandem_thrust, "DT"),
    _comb.Rule(("ball_diameter", "pitch_diameter")),
    _comb.positive_rule("width", "mm"),
    _comb.conformity_rule("f_i"),
    _comb.conformity_rule("f_o"),
    _comb.Rule(("cage_angle", "moment", "moment_cross")),
    _comb.positive_rule("modulus", "MPa"),
    _comb.Rule(("poisson",)),
    _comb.positive_rule("stiffness", "N/mm^1.5", "stiffness"),
    _comb.positive_rule("tilt_radius", "mm", "tilt_radius"),
)
#: The rules of the cases (the inputs broadcast together).
_CASE_RULES = (_comb.BALL_SIZE_RULE,)


def _conditions(tandem: bool, stiffness: bool, tilt_radius: bool) -> set[str | None]:
    """The conditions of the rules (:class:`bearingload.models.combined.Rule`'s ``given``) that
    hold for a pair: a ``tandem`` one (DT), with a ``stiffness`` or a ``tilt_radius`` given."""
    given = {"DT": tandem, "stiffness": stiffness, "tilt_radius": tilt_radius}
    return {None, *(name for name, holds in given.items() if holds)}


#: The gates of the rules (:func:`bearingload.models.combined.gate`) by :func:`_conditions`.
_GATES = {
    flags: _comb.gate(_INPUT_RULES + _CASE_RULES, _conditions(*flags))
    for flags in itertools.product((False, True), repeat=3)
}


def _plain(kind: str, named: dict[str, Any]) -> bool:
    """Whether every value is a plain float that passes every rule (:data:`_INPUT_RULES`,
    :data:`_CASE_RULES`; a case that does not is checked by :func:`_checked`, which names what
    it refuses)."""
    if not all(type(v) is float and math.isfinite(v) for v in named.values()):
        return False
    for holds in _GATES[kind == "DT", "stiffness" in named, "tilt_radius" in named]:
        if not holds(named):
            return False
    return True


def _checked(kind: str, named: dict[str, Any]) -> tuple[tuple[int, ...], dict[str, np.ndarray]]:
    """The values ``named`` checked (each rule of :data:`_INPUT_RULES` in its order, then of
    :data:`_CASE_RULES` on the cases), broadcast together: (the case shape, each flat)."""
    given = _conditions(kind == "DT", "stiffness" in named, "tilt_radius" in named)
    v = _comb.check_rules(_INPUT_RULES, given, named.__getitem__)
    arrays = {name: v[name] for name in named}
    validate.broadcast_shape(arrays)
    flat = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in arrays.values()))
    cases = dict(zip(arrays, (a.ravel() for a in flat), strict=True))
    shape = flat[0].shape

    def at(name: str, bad: Any, unit: str = "") -> str:  # the input's element of a bad case
        return validate.element_at(named[name], bad, shape, unit)

    _comb.check_cases(_CASE_RULES, cases, at)
    return shape, cases


#: The inputs a pair's refusal or failure names (their units: combined.INPUT_UNITS).
NAMED = (
    "radial_load",
    "axial_load",
    "moment",
    "moment_cross",
    "preload",
    "contact_angle",
    "width",
    "cage_angle",
)


def _refuse_scale(geo: Any, k_ref: np.ndarray, status: np.ndarray, *loads: np.ndarray) -> None:
    """InputError on the loads of a pair the core flags (``status``: its SetupStatus): none at
    all, too small for the groove geometry (the combined model's check words it, its advice
    replaced) or too large for it (the single angular-contact bearing's rule and words: each
    bearing of the pair is one); the core decides."""
    fr, fa, mm, mc, fp = loads
    f_ref = np.maximum(_comb.reference_force(fr, fa, mm, mc, geo.R_i), fp)
    if (f_ref <= 0).any():
        raise InputError(
            "radial_load",
            "give a radial load, an axial load, a moment or a preload",
            element=validate.element(fr, f_ref <= 0, "N"),
        )

    # the first case refused names the parameter of its largest load, the preload among them
    def sizes() -> dict[str, np.ndarray]:
        return {"preload": fp} | _comb.load_sizes(fr, fa, mm, mc, geo.R_i)

    light = status == _core.SetupStatus.TOO_LIGHT
    try:
        _comb.check_scale(f_ref, k_ref, geo.A, sizes=sizes, flagged=light)
    except InputError as exc:  # its advice (the radial solver) does not apply to a pair
        if exc.reason not in (_comb.TOO_LIGHT, _comb.TOO_LIGHT_ANGULAR):
            raise
        f_min = float(np.max(k_ref * (geo.A / _comb.GEOMETRY_RATIO_MAX) ** 1.5))
        raise InputError(
            exc.parameter,
            f"the loads are too small for the pair solver (the largest of F_r, |F_a|, M/R_i and "
            f"the preload is {float(np.min(f_ref)):.3g} N; it takes at least {f_min:.2g} N for "
            "this bearing)",
        ) from exc
    heavy = status == _core.SetupStatus.TOO_HEAVY
    moment = np.hypot(mm, mc) / geo.R_i
    named = {"radial_load": fr, "axial_load": np.abs(fa), "moment": moment, "preload": fp}
    _comb.check_angular_scale(f_ref, k_ref, geo.A, named, heavy, moments=(mm, mc))


def _near_symmetric(z: int, cage: np.ndarray, mc: np.ndarray) -> np.ndarray:
    """Which cases have a cage [°] within NEAR_SYMMETRIC_DEG of a symmetric position and no
    moment across the load line (the core's symmetry rule, ``directions``, at that snap)."""
    near = _core.directions(z, np.ascontiguousarray(cage, dtype=float), _comb.NEAR_SYMMETRIC_DEG)
    return near[2] & (mc == 0)


def _symmetric(z: int, cage: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """``cage`` [°] with the ``rows`` moved to their nearest symmetric position."""
    half = 180.0 / z
    return np.where(rows, np.round(cage / half) * half, cage)


def _accepted(res: np.ndarray, its: np.ndarray, given: dict) -> None:
    bad = ~(res <= ACCEPT)
    if np.count_nonzero(bad):  # (np.count_nonzero: a fifth of .any()'s time on one case)
        known = res[bad][np.isfinite(res[bad])]
        cases = {k: v[bad] for k, v in given.items()}
        raise ConvergenceError(
            "bearing-pair shaft equilibrium", int(its[bad].max()),
            float(known.max()) if known.size else math.nan, cases, units=_comb.INPUT_UNITS,
        )  # fmt: skip


def _check_edge(flags: np.ndarray, given: dict) -> None:
    """Refuse a loaded ball at the groove edge (contact angle 90°), as the single bearing: the
    first case of bearing 1 the core flags, else of bearing 2."""
    for k, flag in enumerate((_core.PairFlag.EDGE_FIRST, _core.PairFlag.EDGE_SECOND)):
        edge = (flags & flag) != 0
        if np.count_nonzero(edge):
            from bearingload.errors import format_cases

            case = int(np.argmax(edge))
            one = {key: v[[case]] for key, v in given.items()}
            raise InputError(
                "axial_load",
                f"the loads drive a ball of bearing {k + 1} to a contact angle of 90°, the edge of "
                f"its groove, which the model does not describe ({format_cases(one, _comb.INPUT_UNITS)})",
            )


def _distribution(
    kind: str, z: int, shape: tuple[int, ...], cols: np.ndarray, out: tuple
) -> PairDistribution:
    """The answer of the core's ``pair_call`` ``out`` (its docstring) of the packed inputs
    ``cols``: each bearing as a CombinedDistribution, the pair's values."""
    n = cols.shape[1]
    its, rows, per_ball, tangents, pair_rows = out[3], out[6], out[7], out[8], out[9]
    bearings = []
    for k in range(2):
        part = slice(k * n, (k + 1) * n)
        answer = (rows[:8, part], per_ball[:, part], tangents[k], its)
        loads = (rows[8, part], rows[9, part], np.zeros(n), cols[_CAGE_ROW])
        bearings.append(_comb.distribution_of(shape, z, answer, loads, pair_rows[14], None))
    # one case of plain numbers: Python floats, as numerics.scalar_out gives them
    cases = pair_rows.reshape((15,) + shape) if shape else pair_rows[:, 0].tolist()
    load, axial_load, moment, moment_cross, preload, offset, width = cases[:7]
    x, y, axial, tilt, tilt_cross, residual, lift = cases[7:14]

    def case(a: Any) -> Any:
        return np.asarray(a).reshape(shape) if shape else np.asarray(a).item()

    return PairDistribution(
        arrangement=kind,
        bearings=(bearings[0], bearings[1]),
        load=load,
        axial_load=axial_load,
        moment=moment,
        moment_cross=moment_cross,
        preload=preload,
        preload_offset=offset,
        width=width,
        x=x,
        y=y,
        axial=axial,
        tilt=tilt,
        tilt_cross=tilt_cross,
        stiffness_matrix=out[10].reshape(shape + (5, 5)),
        unloaded=out[11].reshape(shape + (2,)),
        lift_off_axial_load=None if kind == "DT" else lift,
        residual=residual,
        iterations=case(its),
    )
