"""The clearance that compensates the varying compliance: the ring position between "a ball
under the load" and "the load between two balls", and every clearance at which they coincide.

The conference abstract on clearance, cage position and vibration (DOMAIN.md §6)
compares the cage angles ``phi_1 = 0`` and ``phi_1 = 180/z``: the ring moves elastically (``δα``)
and kinematically (``δS``) between them, and a clearance exists at which the two cancel so the
ring keeps its place. Here that condition, ``x(0) = x(180/z)``, is solved exactly for every
such clearance (through the ratio gap/displacement, in which the load and the stiffness drop
out: :func:`compensating_clearances`). ``bearingload sweep`` reports them; the paper's own
fits are checked in :mod:`bearingload.papers.compliance`.

"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from bearingload import validate
from bearingload.errors import InputError
from bearingload.models.equilibrium import solve

#: Rounding margin of a computed sum of ``h`` terms, per term, in ulp of its absolute sum (a
#: few for ``c - t``, the power and the products, one per addition, and room to spare). [-]
ROUNDING_ULPS = 16
#: Narrowest interval in ``t = e/x`` the search splits. [-]
RESOLUTION = 1e-13
#: Order of the Taylor polynomial of the smooth terms in the enclosures. [-]
TAYLOR_ORDER = 3


def position_difference(
    balls: Any, load: Any, stiffness: Any, clearance: Any, exponent: Any = 1.5
) -> Any:
    """``x(0) - x(180/z)``: ring displacement along the load, ball under it minus half pitch. [mm]

    Parameters
    ----------
    balls : int or array_like
        Number of rolling elements ``z`` >= 3. [-]
    load : float or array_like
        Radial load ``F_r``. [N]
    stiffness : float or array_like
        Rolling-element stiffness ``K``. [N/mm^m]
    clearance : float or array_like
        Radial internal clearance ``G_r`` (negative = preload). [mm]
    exponent : float or array_like
        Load-deflection exponent ``m``. [-]
    """
    z = np.asarray(balls)
    at_ball = solve(z, load, stiffness, clearance, 0.0, exponent).x
    at_half = solve(z, load, stiffness, clearance, 180.0 / z, exponent).x
    out = at_ball - at_half
    return float(out) if np.ndim(out) == 0 else out


def ring_cosines(balls: int) -> tuple[np.ndarray, np.ndarray]:
    """``cos(phi_j)`` of the ``z`` balls with a ball under the load and at half pitch. [-]"""
    j = np.arange(balls)
    return np.cos(2 * np.pi * j / balls), np.cos(2 * np.pi * (j + 0.5) / balls)


def _signed_cosines(balls: int) -> tuple[np.ndarray, np.ndarray]:
    """The cosines of both cage positions in one array and the sign of their terms in ``h``."""
    c, d = ring_cosines(balls)
    return np.concatenate([c, d]), np.concatenate([np.ones(balls), -np.ones(balls)])


def _terms(t: Any, cosines: np.ndarray, m: float) -> tuple[np.ndarray, np.ndarray]:
    """``(c - t)_+^m c`` and its t-derivative ``-m (c - t)_+^(m-1) c`` per ball, along a last
    axis; both monotone in ``t`` (the power taken as 1 at ``c = t`` when m = 1). [-]"""
    gap = cosines - np.asarray(t, float)[..., None]
    on = gap >= 0.0
    base = np.where(on, gap, 0.0)
    return base**m * cosines, np.where(on, -m * base ** (m - 1.0) * cosines, 0.0)


def balance_difference(t: Any, balls: int, exponent: float = 1.5) -> Any:
    """``h(t) = sum (c_j - t)_+^m c_j - sum (d_j - t)_+^m d_j``, ball under the load minus half
    pitch (``c_j``, ``d_j`` from :func:`ring_cosines`); ``K x^m h(e/x)`` is the force difference of
    the two cage positions at ring displacement ``x`` and gap ``e``. [-]"""
    cos, sign = _signed_cosines(balls)
    out = (sign * _terms(t, cos, exponent)[0]).sum(-1)
    return float(out) if np.ndim(out) == 0 else out


def _signs(t: np.ndarray, balls: int, m: float) -> np.ndarray:
    """The sign of ``h`` at each ``t``: +1, -1, or 0 within the rounding margin. [-]"""
    cos, sign = _signed_cosines(balls)
    terms = sign * _terms(t, cos, m)[0]
    margin = ROUNDING_ULPS * (cos.size + 8) * np.finfo(float).eps * np.abs(terms).sum(-1)
    h = terms.sum(-1)
    return np.where(np.abs(h) <= margin, 0, np.sign(h)).astype(int)


def _binom(m: float, k: int) -> float:
    """The binomial coefficient ``C(m, k)`` of a real ``m``. [-]"""
    out = 1.0
    for i in range(k):
        out *= (m - i) / (i + 1)
    return out


def _enclosure(a: np.ndarray, b: np.ndarray, balls: int, m: float) -> tuple[np.ndarray, ...]:
    """Bounds of ``h`` and of ``h'`` on every ``[a, b]`` and the rounding margin of ``h``:
    ``low, high, dlow, dhigh, margin``, each of the shape of ``a``. [-]

    A ball whose contact stays at least the interval's width ``w`` away (``c >= b + w``) is
    smooth on it: its term is its Taylor polynomial of order ``p`` = :data:`TAYLOR_ORDER` at the
    midpoint plus the remainder ``|C(m, p+1)| |c| (c - b)^(m-p-1) (w/2)^(p+1)`` (``m - p - 1 <
    0``: largest at ``t = b``). The coefficients are summed over the balls first, so the
    cancellation of the two cage positions is kept. Any other ball loaded on the interval
    (``a < c < b + w``) adds the range of its term and of its slope between their values at the
    ends, both monotone in ``t`` (:func:`_terms`). Each bound is widened by its rounding margin
    (:data:`ROUNDING_ULPS`).
    """
    cos, sign = _signed_cosines(balls)
    w, p = (b - a)[:, None], TAYLOR_ORDER
    half = w[:, 0] / 2.0
    far = cos >= b[:, None] + w
    near = ~far & (cos > a[:, None])
    gap = np.where(far, cos - 0.5 * (a + b)[:, None], 1.0)
    top = np.where(far, sign * cos * gap**m, 0.0)  # each term at the midpoint
    coef = [top] + [(-1) ** k * _binom(m, k) * top / gap**k for k in range(1, p + 1)]
    near_gap = np.where(far, cos - b[:, None], 1.0) ** (m - p - 1)
    rest = abs(_binom(m, p + 1)) * np.where(far, np.abs(cos) * near_gap, 0.0).sum(-1)
    sums = [k.sum(-1) for k in coef]
    spread = (
        sum(abs(sums[k]) * half**k for k in range(1, p + 1)) + rest * half ** (p + 1),
        sum(k * abs(sums[k]) * half ** (k - 1) for k in range(2, p + 1)) + (p + 1) * rest * half**p,
    )
    ends = [tuple(np.where(near, sign * part, 0.0) for part in _terms(t, cos, m)) for t in (a, b)]
    tol = ROUNDING_ULPS * (cos.size + 8) * np.finfo(float).eps
    absolute = [np.abs(k).sum(-1) for k in coef]
    size = (
        sum(absolute[i] * half**i for i in range(p + 1)),
        sum(i * absolute[i] * half ** (i - 1) for i in range(1, p + 1)),
    )
    out = []
    for part in (0, 1):
        va, vb = ends[0][part], ends[1][part]
        margin = tol * (size[part] + (np.abs(va) + np.abs(vb)).sum(-1))
        out += [
            sums[part] - spread[part] + np.minimum(va, vb).sum(-1) - margin,
            sums[part] + spread[part] + np.maximum(va, vb).sum(-1) + margin,
        ]
    return (*out, tol * (size[0] + (np.abs(ends[0][0]) + np.abs(ends[1][0])).sum(-1)))


def _settle(balls: int, m: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Split ``-1 <= t <= cos(π/z)`` until every piece is settled; its ends (sorted, contiguous)
    and whether ``h`` is within its rounding margin on it.

    The search starts from the intervals between the ball cosines (where a ball enters or leaves
    contact at one of the cage positions: the kinks of ``h``) and halves an interval until the
    enclosures (:func:`_enclosure`) show ``h`` without a zero, ``h`` strictly monotone, ``h``
    within its rounding margin on the whole interval, or the interval is narrower than
    :data:`RESOLUTION`.
    """
    c, d = ring_cosines(balls)
    top = math.cos(math.pi / balls)
    cuts = np.unique(np.clip(np.concatenate([c, d, [-1.0, top]]), -1.0, top))
    a, b = cuts[:-1], cuts[1:]
    done_a, done_b, done_noise = [], [], []
    while a.size:
        low, high, dlow, dhigh, margin = _enclosure(a, b, balls, m)
        noise = (low >= -3.0 * margin) & (high <= 3.0 * margin)
        done = (low > 0) | (high < 0) | (dlow > 0) | (dhigh < 0) | noise | (b - a <= RESOLUTION)
        done_a.append(a[done])
        done_b.append(b[done])
        done_noise.append(noise[done])
        a, b = a[~done], b[~done]
        mid = 0.5 * (a + b)
        a, b = np.concatenate([a, mid]), np.concatenate([mid, b])
    ends_a, ends_b = np.concatenate(done_a), np.concatenate(done_b)
    order = np.argsort(ends_a)
    return ends_a[order], ends_b[order], np.concatenate(done_noise)[order]


def _preload_sign(balls: int, m: float) -> int:
    """The sign of ``h`` just below ``t = -1``, every ball loaded at both cage positions. [-]

    Then ``h(t) = |t|^m sum_k C(m, k) (-1/t)^k D_(k+1)`` with ``D_n = sum c_j^n - sum d_j^n =
    2^(1-n) z sum C(n, i)`` over ``(n - 2i)/z`` odd: ``D_n > 0`` for ``n >= z`` of the parity of
    ``z``, else 0, so only ``k >= z - 1`` of the parity of ``z - 1`` count. ``C(m, k) > 0`` for
    ``k <= m``, and all ``C(m, k)`` with ``k > m`` and one parity of ``k`` share the sign of
    ``C(m, z - 1)``: if ``z - 1 > m`` every term has that sign and ``h`` never vanishes below
    ``-1`` (with an integer ``m < z - 1``, ``h = 0`` there). Otherwise (``z = 3``, ``m >= 2``;
    ``z = 4``, ``m = 3``) the leading term is positive and :func:`_preload_bracket` decides.
    """
    if balls - 1 > m:
        return 0 if m == int(m) else int(np.sign(_binom(m, balls - 1)))
    return int(np.sign(balance_difference(-1.0, balls, m)))


def _preload_bracket(balls: int, m: float) -> tuple[float, float] | None:
    """A bracket of the root of ``h`` below ``t = -1`` (every ball loaded), if there is one.

    Only for ``z = 3``, ``2 < m < 3`` can there be one (:func:`_preload_sign`): there the terms
    with ``k >= 4`` are negative, ``h/(|t|^m t^-2)`` falls from ``C(m, 2) D_3 > 0`` at
    ``t = -inf`` to ``h(-1)``, and has one root exactly when ``h(-1) < 0``; ``h(-1e4) > 0`` then
    brackets it (the terms with ``k >= 4`` are below 1e-8 of the leading one there).
    """
    if not (balls == 3 and 2.0 < m < 3.0) or balance_difference(-1.0, balls, m) > 0:
        return None
    return -1.0e4, -1.0


def _sign_brackets(balls: int, m: float) -> list[tuple[float, float]]:
    """Brackets ``[a, b]`` in ``t``, one per sign change of ``h`` above ``t = -1``.

    Along the settled pieces of :func:`_settle` the signs of ``h`` at their ends (0 within the
    rounding margin, and at the ends of a piece on which ``h`` is within it) are followed from
    the sign just below ``-1`` (:func:`_preload_sign`): a bracket runs from the last point of one
    sign to the next point of the other. A piece without a zero holds none, a monotone piece at
    most one, so every sign change is bracketed once.
    """
    a, b, noise = _settle(balls, m)
    points = np.append(a, b[-1])
    signs = _signs(points, balls, m)
    signs[np.append(noise, False) | np.append(False, noise)] = 0
    brackets = []
    last, where = _preload_sign(balls, m), -1.0
    for t, s in zip(points.tolist(), signs.tolist(), strict=True):
        if s == 0:
            continue
        if last not in (0, s):
            brackets.append((where, t))
        last, where = s, t
    return brackets


def _h_or_sign(t: float, balls: int, m: float, below: int) -> float:
    """``h(t)``, or at ``t = -1`` (a bracket's end from below) its proven sign just below. [-]"""
    if t == -1.0 and below:
        return below * 1e-300
    return float(balance_difference(t, balls, m))


def compensating_clearances(
    balls: int,
    load: float,
    stiffness: float,
    exponent: float = 1.5,
    *,
    lower: float | None = None,
    upper: float | None = None,
) -> list[float]:
    """Every clearance at which the ring sits at the same place for cage angles 0 and 180/z. [mm]

    Solves ``x(0) = x(180/z)`` for ``G_r`` exactly (the compliance abstract: "δα = δS", the
    clearance that removes the kinematic excitation at z times the cage frequency). There may
    be none, one or several: each ball entering or leaving contact at one of the two cage
    positions can flip the sign. The paper means a positive clearance with several balls loaded
    inside its range P̄/z >= 0.1: the smallest positive root (z = 9, F = 1000 N,
    K = 1e5 N/mm^1.5: 10.65 µm, P̄/z = 2.87; its eq. (9) would put it at 4.3 µm).

    Why the list is complete. At one cage position ``F = K x^m g(e/x)`` with
    ``g(t) = sum (cos(phi_j) - t)_+^m cos(phi_j)``, ``e = G_r/2``, ``x > 0``. Both positions
    share ``x`` and ``e`` exactly when ``h(t) = g_0(t) - g_half(t) = 0`` at ``t = e/x``
    (:func:`balance_difference`; F and K drop out), and ``t = e/x(e)`` rises strictly with
    ``e`` (``d(e/x)/de = F/(K x^2 sum m (x c - e)^(m-1) c^2) > 0``), so the roots in ``G_r``
    are those of ``h``, one to one: ``G_r = 2 t (F/(K g_0(t)))^(1/m)``. Above
    ``t = cos(π/z)`` only ``g_0 > 0``: no root. Below ``t = -1`` (every ball loaded at both
    positions) the binomial series of :func:`_preload_sign` gives ``h`` one sign, or rules
    on the one root :func:`_preload_bracket` can bracket. In between, :func:`_settle` splits
    the range, starting from the kinks (a ball entering or leaving contact at either cage
    position), until enclosures of ``h`` and ``h'`` (a Taylor polynomial with a bounded
    remainder for the smooth terms, the monotone range for a term near its kink, widened by
    the rounding margin) show on every piece no zero or a strictly monotone ``h``; following
    the signs at the piece ends from the sign below ``-1`` (:func:`_sign_brackets`) brackets
    every sign change once, and :func:`bearingload.numerics.bracketed_root` refines it to
    ``|Δt| <= 2 (1e-15 + 4.5e-16 |t|)``. What double precision cannot tell: where ``h`` stays
    within the rounding margin of its sums (:data:`ROUNDING_ULPS`) over a whole piece (it vanishes
    identically under a full preload for an integer ``m < z - 1``, and falls below rounding
    just above ``t = -1`` with many balls), a root inside is listed once if the signs on both
    sides differ; two roots closer than :data:`RESOLUTION` in ``t`` would show as none.

    Parameters
    ----------
    balls : int
        Number of rolling elements ``z`` >= 3. [-]
    load : float
        Radial load ``F_r`` > 0. [N]
    stiffness : float
        Rolling-element stiffness ``K`` > 0. [N/mm^m]
    exponent : float
        Load-deflection exponent ``m``. [-]
    lower, upper : float, optional
        Only the roots in this clearance range [mm]. Default: all.

    Returns
    -------
    list of float
        Radial internal clearances ``G_r`` in increasing order. [mm]

    Examples
    --------
    >>> roots = compensating_clearances(9, 1000.0, 1.0e5)
    >>> len(roots), [round(g, 5) for g in roots if g > 0]
    (6, [0.01065, 0.0843, 0.43572])
    """
    from bearingload.numerics import bracketed_root

    z = int(validate.ball_count(balls))
    if z < 3:
        raise InputError(
            "balls", "needs at least 3 balls (with fewer no cage angle but 0 is stable)"
        )
    f = float(validate.positive("load", load, "N"))
    k = float(validate.positive("stiffness", stiffness, "N/mm^m"))
    m = float(validate.exponent(exponent))
    lo = -math.inf if lower is None else float(validate.finite("lower", lower))
    hi = math.inf if upper is None else float(validate.finite("upper", upper))
    brackets = _sign_brackets(z, m)
    preload = _preload_bracket(z, m)
    if preload is not None:
        brackets.insert(0, preload)
    c = ring_cosines(z)[0]
    roots = []
    below = _preload_sign(z, m)
    for a, b in brackets:
        t = bracketed_root(lambda v: _h_or_sign(v, z, m, below), a, b, xtol=1e-15)
        x = (f / (k * float(_terms(t, c, m)[0].sum()))) ** (1.0 / m)
        if lo <= 2.0 * t * x <= hi:
            roots.append(2.0 * t * x)
    return sorted(roots)
