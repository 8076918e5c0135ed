"""The Hertz set-up of the combined solver (K_0 and the stiffness curve's nodes, in the compiled
core for every case): the scalar Hertz stiffness at every node (K_0 to the bit), each case's own
whatever else its call holds, and the geometries the Hertz functions refuse refused alike."""

from __future__ import annotations

import dataclasses

import mpmath as mp
import numpy as np
import pytest

from bearingload.contact.hertz import ball_stiffness
from bearingload.errors import InputError
from bearingload.models import _core, combined
from bearingload.models.combined import solve_combined

GEOMETRY = {"ball_diameter": 7.938, "f_i": 0.52, "f_o": 0.53}


def _fields(r: combined.CombinedDistribution) -> dict:
    return {f.name: np.asarray(getattr(r, f.name)) for f in dataclasses.fields(r)}


def _case(pitch: object, load: object = 1500.0) -> combined.CombinedDistribution:
    return solve_combined(9, load, 700.0, pitch_diameter=pitch, clearance=0.012, **GEOMETRY)


def test_a_case_is_the_same_bits_alone_or_among_other_geometries() -> None:
    pitches = np.array([40.0, 38.5, 38.5, 52.0, 40.0])
    loads = np.array([200.0, 1500.0, 800.0, 3000.0, 900.0])
    mixed = _case(pitches, loads)
    for i in range(pitches.size):
        alone = _case(float(pitches[i]), float(loads[i]))
        for name, value in _fields(mixed).items():
            if name != "balls":
                assert value[i].tobytes() == _fields(alone)[name].tobytes(), (i, name)


def _mp_ratio(geometry: tuple, c: float) -> float:
    """K(c)/K(1) of both Hertz contacts in series at 30 digits (mpmath's elliptic integrals,
    the ellipticity from Johnson's equation by mpmath's root finder), d_m/c for d_m."""
    dw, dm, fi, fo = (mp.mpf(v) for v in geometry[:4])

    def stiffness(pitch: mp.mpf) -> mp.mpf:
        parts = []
        for rho_x, rho_y in (
            (2 * pitch / (dw * (pitch - dw)), (2 * fi - 1) / (fi * dw)),
            (2 * pitch / (dw * (pitch + dw)), (2 * fo - 1) / (fo * dw)),
        ):
            ratio = max(rho_x, rho_y) / min(rho_x, rho_y)

            def johnson(t: mp.mpf, ratio: mp.mpf = ratio) -> mp.mpf:
                m = 1 - mp.exp(-2 * t)
                k, e = mp.ellipk(m), mp.ellipe(m)
                return mp.exp(2 * t) * (e - (1 - m) * k) / (k - e) - ratio

            t = mp.findroot(johnson, 0.64 * mp.log(ratio))
            m = 1 - mp.exp(-2 * t)
            d_star = 2 * mp.ellipk(m) / mp.pi * mp.cbrt(mp.pi * (1 - m) / (2 * mp.ellipe(m)))
            parts.append(d_star * mp.cbrt(rho_x + rho_y))  # (K^(-2/3) but for a constant)
        return (parts[0] + parts[1]) ** (-mp.mpf(3) / 2)

    with mp.workdps(30):
        return float(stiffness(dm / mp.mpf(c)) / stiffness(dm))


@pytest.mark.parametrize(
    "geometry",
    [
        (7.938, 38.5, 0.52, 0.53, 208000.0, 0.3),
        (25.4, 260.0, 0.5005, 0.58, 1e5, -0.5),
        (1.0, 1.6, 0.57, 0.501, 3.1e5, 0.5),
    ],
)
def test_the_nodes_are_the_hertz_stiffness(geometry) -> None:
    """K_0 is ``ball_stiffness`` of plain floats (its scalar path) to the bit; K at every node,
    K_0 (1 + (c - 1) D(c)), is the scalar path's within its rounding (a few ulp each) and
    K(c)/K_0 that of a 30-digit evaluation within 8 ulp (the curve's nodes follow each
    contact's ellipticity from node to node: their own Newton starts, not the scalar path's
    bits)."""
    x = np.cos((2.0 * np.arange(24) + 1.0) * np.pi / 48.0)
    k0, values, bad = _core.hertz_curves(np.array([geometry]), x)
    dw, dm, fi, fo, e, nu = geometry
    k1 = ball_stiffness(dw, dm, fi, fo, e, nu).ball
    assert not bad[0] and k0[0] == k1
    for c, value in zip((x + 1.0) / 2.0, values[0], strict=True):
        ratio = 1.0 + (c - 1.0) * value
        k = ball_stiffness(dw, float(dm / c), fi, fo, e, nu).ball
        assert k0[0] * ratio == pytest.approx(k, rel=1e-14, abs=0)
        assert ratio == pytest.approx(_mp_ratio(geometry, float(c)), rel=8 * 2.2e-16, abs=0)


def test_a_geometry_the_hertz_functions_refuse_is_refused() -> None:
    """Poisson's ratio outside (-1, 0.5] comes back from the core as a status; the Hertz
    functions name it."""
    assert _core.hertz_curves(np.array([[7.938, 38.5, 0.52, 0.53, 2e5, 0.6]]), np.zeros(24))[2][0]
    with pytest.raises(InputError, match="poisson"):
        solve_combined(9, 1000.0, 300.0, pitch_diameter=38.5, poisson=0.6, **GEOMETRY)


def test_setup_matches_the_exact_stiffness() -> None:
    """K at every ball is the exact Hertz stiffness at its contact angle."""
    for load in (1e-3, 1500.0):
        r = _case(38.5, load)
        exact = combined.ball_stiffness_at(r.contact_angles, 7.938, 38.5, 0.52, 0.53)
        assert np.allclose(r.ball_stiffnesses, exact, rtol=1e-12, atol=0)


class _TakenFirst(dict):
    """A cache as a thread sees it when another has just dropped its oldest entry, once: its
    first key is one no longer held (the other thread's ``del`` came between)."""

    changed = False

    def __iter__(self):
        if not self.changed:
            self.changed = True
            return iter(["taken by another thread", *dict.__iter__(self)])
        return dict.__iter__(self)


class _ChangedMeanwhile(dict):
    """A cache another thread changes while this one looks for its oldest entry, once."""

    changed = False

    def __iter__(self):
        if not self.changed:
            self.changed = True
            raise RuntimeError("dictionary changed size during iteration")
        return dict.__iter__(self)


@pytest.mark.parametrize("kind", [_TakenFirst, _ChangedMeanwhile], ids=lambda k: k.__name__)
def test_a_cache_shared_by_threads_is_trimmed_whatever_another_did(kind, monkeypatch) -> None:
    """solve_combined in four threads raised KeyError or 'dictionary changed size during
    iteration' (3 of 6000 one-case calls of new geometries, sys.setswitchinterval(1e-6)): the
    cache's trim took the first key and dropped it, and another thread had dropped it or
    changed the cache in between. A trim meeting either looks again."""
    cache = kind({bytes([i]): np.zeros(1) for i in range(4)})
    monkeypatch.setattr(combined, "_SETUP_CACHE", cache)
    monkeypatch.setattr(combined, "SETUP_CACHE_SIZE", 2)
    _case(40.0)  # (a new geometry, remembered: the cache trimmed)
    assert len(cache) == 2 and bytes([3]) in cache
