"""A pair of angular-contact ball bearings (DB, DF, DT) at speed: the rigid shaft of
:mod:`bearingload.models.pair` with every ball of both bearings in dynamic equilibrium
(centrifugal force and gyroscopic moment, outer-raceway control: Jones 1960; Harris & Kotzalas,
*Rolling Bearing Analysis*, 5th ed., vol. 2, ch. 2-3), each bearing in its local frame the
one-sided angular-contact bearing of :mod:`bearingload.models.high_speed`.

Units: N, mm, kg, s (the shaft speed in rpm at the input, rad/s inside); ball density in kg/m^3.
The model (the pair's maps and forces by virtual work) and the numerics (the compiled core's
``solve_speed`` on the shaft's five unknowns from the static pair's answer) are stated in
docs/speed.md ("Pairs (DB, DF, DT)").
"""

from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from bearingload import validate
from bearingload.constants import STEEL_MODULUS
from bearingload.errors import ConvergenceError, InputError
from bearingload.models import combined as _comb
from bearingload.models import high_speed as _hs
from bearingload.models.pair import NAMED as NAMED_AT_REST
from bearingload.models.pair import (
    PairDistribution,
    held_components,
    levers,
    shaft_maps,
    signs,
    solve_pair,
)

__all__ = ["PairHighSpeedDistribution", "solve_pair_high_speed", "MODEL"]

#: The model, as the outputs name it.
MODEL = _hs.MODEL
#: Shaft Newton steps (the trials of each: the single bearing's, the core's trial_step). [-]
ITERATIONS = 200
#: Stages of the continuation in omega^2. [-]
CONTINUATION_STAGES = 200

#: The inputs a failure of a pair at speed names (their units: combined.INPUT_UNITS).
NAMED = (*NAMED_AT_REST, "speed")


@dataclass(frozen=True)
class PairHighSpeedDistribution(PairDistribution):
    """The pair's answer at speed: the fields of :class:`~bearingload.models.pair.
    PairDistribution`, each of ``bearings`` a :class:`~bearingload.models.high_speed.
    HighSpeedDistribution` in its own frame (``contact_angles_inner``/``_outer`` [°],
    ``ball_loads_inner``/``_outer`` [N], each ball's F_c, M_g and speeds), and:

    Attributes
    ----------
    speed : ndarray
        Shaft (inner rings) speed n. [rpm]
    ball_density : ndarray
        [kg/m^3]
    model : str
        :data:`MODEL`.
    preload_at_speed : ndarray or None
        DB/DF: the thrust each bearing carries with no external load at the speed (the
        centrifugal forces raise it: the preload ``preload`` is ground in at rest); None for
        DT. [N]

    ``stiffness_matrix`` is the tangent of the shaft forces with the ball equations eliminated
    (not symmetric at speed; at speed 0 the static pair's, its symmetric part);
    ``lift_off_axial_load`` and ``preload_offset`` are the pair's at rest (:func:`_at_speed`
    says why the lift-off is not given at the speed). ``residual`` is the shaft's over the
    largest of the applied loads and the preload.
    """

    speed: Any = None
    ball_density: Any = None
    model: str = MODEL
    preload_at_speed: Any = None


@dataclass
class _Shaft:
    """The pair problem of n cases in physical units (tilts as R_i theta [mm])."""

    ring: _hs.Ring  # either bearing, in its local frame
    maps: np.ndarray  # (n, 2, 5, 5): local position per shaft position
    offset: np.ndarray  # (n, 2, 5): local position at v = 0 (the preloaded groove centres)
    f: np.ndarray  # (n, 5) applied [N]
    f_ref: np.ndarray  # (n,) [N]
    held: np.ndarray  # (n, 5) bool


def _local(sh: _Shaft, k: int, v: np.ndarray) -> np.ndarray:
    """Bearing k's local position ``L_k v`` + its offset (n, 5). [mm]"""
    return (sh.maps[:, k] @ v[:, :, None])[:, :, 0] + sh.offset[:, k]


def solve_pair_high_speed(
    balls: int,
    radial_load: Any,
    axial_load: Any = 0.0,
    *,
    speed: Any,
    ball_density: Any = _hs.STEEL_DENSITY,
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
    tilt_radius: Any = None,
) -> PairHighSpeedDistribution:
    """Equilibrium of the shaft in a pair of identical angular-contact ball bearings turning at
    ``speed``, every ball with its centrifugal force and gyroscopic moment (docs/speed.md).

    Parameters as :func:`bearingload.models.pair.solve_pair` (a constant ``stiffness`` is not
    taken: the two contacts of a ball need their own Hertz stiffness), and

    speed : array_like
        Shaft (inner rings) speed n, >= 0, n d_m <= 2e6 mm/min. [rpm]
    ball_density : array_like, default steel 7850
        Density of the balls. [kg/m^3]

    Raises
    ------
    InputError
        As solve_pair; a speed or density outside its range; loads too small against the ball
        forces at this speed to be balanced in doubles.
    ConvergenceError
        A case left unbalanced; the message names its inputs.

    At speed the outer contacts carry the centrifugal force:

    >>> r = solve_pair_high_speed(12, 1000.0, 300.0, speed=10000.0, preload=500.0,
    ...                           contact_angle=40.0, ball_diameter=7.938, pitch_diameter=38.5,
    ...                           width=15.0)
    >>> bool((r.bearings[1].ball_loads_outer > r.bearings[1].ball_loads_inner).all())
    True
    """
    n_rpm, density = _hs.check_speed(speed, ball_density, pitch_diameter)
    wide = np.broadcast_shapes(np.shape(radial_load), n_rpm.shape, density.shape)
    if wide != np.shape(radial_load):
        radial_load = np.broadcast_to(np.asarray(radial_load, dtype=float), wide)
    static = solve_pair(
        balls, radial_load, axial_load, arrangement=arrangement, preload=preload,
        contact_angle=contact_angle, ball_diameter=ball_diameter, pitch_diameter=pitch_diameter,
        width=width, f_i=f_i, f_o=f_o, cage_angle=cage_angle, moment=moment,
        moment_cross=moment_cross, modulus=modulus, poisson=poisson, tilt_radius=tilt_radius,
    )  # fmt: skip
    shape = np.shape(static.x)
    given = dict(radial_load=radial_load, axial_load=axial_load, moment=moment,
                 moment_cross=moment_cross, preload=preload, contact_angle=contact_angle,
                 width=width, cage_angle=cage_angle, speed=n_rpm, ball_diameter=ball_diameter,
                 pitch_diameter=pitch_diameter, f_i=f_i, f_o=f_o, modulus=modulus,
                 poisson=poisson, ball_density=density)  # fmt: skip
    flat = dict(zip(given, _hs.flat_columns(shape, *given.values()), strict=True))
    flat["cage_angle"] = validate.cage_angle(flat["cage_angle"])
    sh, geo, v_static = _setup(static, flat, shape)
    named = {k: (given[k], "rpm" if k == "speed" else "N") for k in _LOADS + ("speed",)}
    refused = functools.partial(_hs.refused_case, named, shape)
    with np.errstate(all="ignore"):
        v, parts, jac, its, rest = _solve(sh, v_static, flat, static.arrangement != "DT", refused)
        extra = _at_speed(static, rest, shape)
    return _result(static, sh, geo, flat, shape, (v, parts, jac, its, extra))


def _at_speed(static: PairDistribution, rest: np.ndarray, shape: tuple[int, ...]) -> dict[str, Any]:
    """``preload_at_speed`` of a DB/DF pair: each bearing's thrust at the shaft's centred
    position (with no external load the mirrored pair keeps the shaft there at any speed, each
    ball solved at that speed: ``rest`` (n, 2), bearing 1's thrust there and whether every
    ball is balanced, from the core's ``at_rest``); none for DT. [N]

    The lift-off load stays the one at rest: at speed the model keeps the inner contacts of the
    bearing being unloaded far beyond it, the balls held between both rings by their
    centrifugal force and gyroscopic couple and riding up an inner groove without a shoulder
    (``solve 7205BDB --preload 300N -F 0 --speed 1000``: 2.73 N on bearing 2 at a thrust of
    1 kN, 0.56 N at 10 kN, its inner contact angle 57.8°), so no finite thrust unloads it
    exactly (docs/speed.md)."""
    from bearingload import numerics

    if static.arrangement == "DT":
        return {}
    if not np.all(rest[:, 1]):
        raise ConvergenceError("preload of the pair at speed", 0, math.nan, {})
    thrust = np.asarray(rest[:, 0], dtype=float).reshape(shape)
    return {"preload_at_speed": numerics.scalar_out(thrust)}


def _column(r: Any, name: str, shape: tuple[int, ...]) -> np.ndarray:
    return np.broadcast_to(np.asarray(getattr(r, name), dtype=float), shape).ravel()


def _setup(static: PairDistribution, c: dict, shape: tuple[int, ...]) -> tuple[Any, ...]:
    """The shaft problem at the static pair's answer: (shaft, geometry, its position)."""
    z = int(static.bearings[0].balls)
    geo = _comb.angular_geometry(c["ball_diameter"], c["pitch_diameter"], c["f_i"], c["f_o"],
                                  c["contact_angle"])  # fmt: skip
    radius = _column(static.bearings[0], "tilt_radius", shape)
    geo = dataclasses.replace(geo, R_i=radius)
    n = radius.size
    b = _hs.ball_set(geo, c["modulus"], c["poisson"], c["speed"], c["ball_density"])
    cos_, sin_, mirror = _comb.ball_directions(z, c["cage_angle"])
    fr, fa, mm, mc, fp = (c[k] for k in ("radial_load", "axial_load", "moment", "moment_cross",
                                         "preload"))  # fmt: skip
    f_ref = np.maximum(_comb.reference_force(fr, fa, mm, mc, radius), fp)
    ring = _hs.ring(b, (cos_, sin_), geo, f_ref, np.ones(n, dtype=bool))
    kind = static.arrangement
    maps = shaft_maps(signs(kind), levers(kind, c["width"], radius))
    offset = np.zeros((n, 2, 5))
    at_rest = geo.A * np.sin(geo.alpha0) + _column(static, "preload_offset", shape)
    offset[:, :, 2] = at_rest[:, None]
    held = held_components(kind, mirror, (fr, fa, mm, mc))  # the static pair's symmetries
    f = np.stack([fr, np.zeros(n), fa, mm / radius, mc / radius], axis=1)
    sh = _Shaft(ring, maps, offset, f, f_ref, held)
    pos = [_column(static, k, shape) for k in ("x", "y", "axial", "tilt", "tilt_cross")]
    v_static = np.stack(pos[:3] + [radius * np.deg2rad(t) for t in pos[3:]], axis=1)
    return sh, geo, v_static


#: The end of the refusal of loads too small for the pair's ball dynamics: the library's way
#: out; the command line names its option (--quasi-static) instead.
STATIC_WAY = "the static model of the pair (solve_pair) leaves the ball forces out"
#: The reason of that refusal, on which a caller offering the static pair acts.
TOO_LIGHT_PAIR = "too_light_pair_dynamics"


#: The loads of which the largest names a case too light for the pair's ball dynamics.
_LOADS = ("radial_load", "axial_load", "preload")


def _solve(
    sh: _Shaft, v_static: np.ndarray, flat: dict, rest: bool, refused: Any
) -> tuple[Any, ...]:
    """The core's solve (Newton from the static answer, continuation for the cases left; with
    ``rest`` the shaft centred too); the checks, ``refused(i, load)`` the input and element
    that name case ``i`` (:func:`bearingload.models.high_speed.refused_case`). Returns (v, both
    bearings' states (local), the shaft's tangent (n, 5, 5), iterations, rest (n, 2)); each
    bearing's state holds the shaft's measures (merit, score, level: the core's, over the
    largest applied load or preload)."""
    shaft = (sh.maps, sh.offset, sh.f, sh.held.view(np.uint8))
    limits = np.array([ITERATIONS, CONTINUATION_STAGES, 1, 1 if rest else 0], dtype=float)
    v, parts, out = _hs.core_solve(sh.ring, shaft, limits, v_static, v_static, True)
    st = parts[0]
    its = out[:, 38].astype(int)
    level = np.where(np.isfinite(st.level), st.level, 0.0)
    small = np.flatnonzero(level > _hs.LEVEL_MAX)
    if small.size:
        i = int(small[np.argmax(level[small])])
        sizes = {k: abs(float(flat[k][i])) for k in _LOADS}
        parameter, element = refused(i, max(sizes, key=lambda k: sizes[k]))  # the largest load
        raise InputError(
            parameter,
            f"the loads are too small against the ball forces at this speed for the ball "
            f"dynamics of the pair (the largest of F_r, |F_a|, M/R_i and the preload is "
            f"{float(sh.f_ref[i]):.3g} N; the rounding of the ball forces on the shaft is "
            f"{level[i] * float(sh.f_ref[i]):.2g} N, more than {_hs.LEVEL_MAX:.0e} of it)",
            way_out=STATIC_WAY,
            reason=TOO_LIGHT_PAIR,
            element=element,
        )
    named = {k: flat[k] for k in NAMED}
    _hs.check_balanced("bearing-pair shaft and ball-dynamics equilibrium", st, its, named)
    return v, parts, out[:, 5:30].reshape(-1, 5, 5), its, out[:, 40:42]


def _result(static: PairDistribution, sh: _Shaft, geo: Any, flat: dict, shape: tuple[int, ...],
            out: tuple[Any, ...]) -> PairHighSpeedDistribution:  # fmt: skip
    """The static pair's fields with the shaft's position, each bearing at speed, the tangent;
    ``out`` = (v, both bearings' states, the shaft's tangent, iterations, the extra fields)."""
    from bearingload import numerics

    v, parts, jac, its, extra = out
    z = int(static.bearings[0].balls)
    radius = geo.R_i
    one_sided = np.ones(radius.size, dtype=bool)

    def case(a: Any, dtype: Any = float) -> Any:
        return numerics.scalar_out(np.asarray(a, dtype=dtype).reshape(shape))

    bearings = []
    for k in range(2):
        p = parts[k]
        local = {"speed": flat["speed"], "moment": radius * p.gen[:, 3]}
        radial = np.where(sh.held[:, 0], 0.0, np.hypot(p.gen[:, 0], p.gen[:, 1]))
        # each bearing's own position is the shaft's: what the loads leave free is the pair's
        answer = (sh.ring, _local(sh, k, v), p, its, np.zeros(radius.size, dtype=bool))
        density = flat["ball_density"].reshape(shape)
        bearings.append(
            _hs.bearing_result(
                static.bearings[k],
                shape,
                z,
                geo,
                local,
                density,
                answer,
                one_sided,
                None,
                load=case(radial),
                axial_load=case(p.gen[:, 2]),
            )
        )
    lever = np.stack([np.ones_like(radius)] * 3 + [radius, radius], axis=1)
    tangent = jac * lever[:, :, None] * lever[:, None, :]
    # at speed 0 the static pair's matrix (the same tangent, from the static solve)
    rest = (flat["speed"] == 0)[:, None, None]
    tangent = np.where(rest, np.reshape(static.stiffness_matrix, tangent.shape), tangent)
    unloaded = np.stack([np.all(parts[k].terms[2] == 0, axis=1) for k in range(2)], axis=1)
    fields = {f.name: getattr(static, f.name) for f in dataclasses.fields(PairDistribution)}
    fields.update(
        bearings=(bearings[0], bearings[1]), x=case(v[:, 0]), y=case(v[:, 1]),
        axial=case(v[:, 2]), tilt=case(np.rad2deg(v[:, 3] / radius)),
        tilt_cross=case(np.rad2deg(v[:, 4] / radius)),
        stiffness_matrix=tangent.reshape(shape + (5, 5)), unloaded=unloaded.reshape(shape + (2,)),
        residual=case(parts[0].merit),
        iterations=case(np.asarray(static.iterations).ravel() + its, np.int64),
    )  # fmt: skip
    fields.update(speed=case(flat["speed"]), ball_density=case(flat["ball_density"]), **extra)
    return PairHighSpeedDistribution(**fields)
