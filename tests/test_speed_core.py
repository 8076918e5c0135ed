"""The compiled ball dynamics (bearingload/models/_core.pyx, the sections at speed): the analytic
derivatives of each ball's equations against central differences of its values, and the solver's
limits taken from bearingload.models.high_speed at each call (with the Newton and the
continuation taken away a case is a ConvergenceError naming its inputs)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingload.errors import ConvergenceError
from bearingload.models import _core, high_speed
from bearingload.models.combined import NODE_W, NODE_X, angular_geometry
from bearingload.models.high_speed import solve_high_speed

GEO = {"ball_diameter": 7.938, "pitch_diameter": 38.5}


def _balls(n: int, seed: int) -> tuple[np.ndarray, ...]:
    """n balls of a 7205-sized 40° bearing at 0-30 000 rpm near contact: (rho, u, do, ao, row,
    consts, ki, ko)."""
    rng = np.random.default_rng(seed)
    one = np.ones(1)
    geo = angular_geometry(7.938 * one, 38.5 * one, 0.52 * one, 0.53 * one, 40.0 * one)
    ki, ko = high_speed.stiffness_nodes(geo, 208000.0 * one, 0.3 * one)
    a = float(geo.A[0])
    omega = rng.uniform(0.0, 30000.0, n) * math.pi / 30.0
    mass = 7.85e-6 * math.pi / 6.0 * 7.938**3
    consts = np.stack(
        [
            np.full(n, 0.02 * 7.938),
            np.full(n, 0.03 * 7.938),
            np.full(n, 7.938),
            np.full(n, 38.5),
            omega,
            np.full(n, mass),
        ],
        axis=1,
    )
    rho = a * math.cos(math.radians(40.0)) + rng.uniform(-0.01, 0.03, n)
    u = a * math.sin(math.radians(40.0)) + rng.uniform(-0.01, 0.03, n)
    do = rng.uniform(1e-4, 0.01, n)
    ao = np.radians(rng.uniform(20.0, 60.0, n))
    row = np.arange(n, dtype=np.int64)
    ki_n, ko_n = (np.repeat(k.reshape(1, -1), n, axis=0) for k in (ki, ko))
    return rho, u, do, ao, row, consts, ki_n, ko_n


def _terms(rho, u, do, ao, rest, partials: bool) -> tuple[np.ndarray, np.ndarray]:
    n = rho.size
    terms, part = np.empty((14, n)), np.empty((16 if partials else 0, n))
    _core.speed_balls(rho, u, do, ao, *rest, NODE_X, NODE_W, terms, part)
    return terms, part


def test_the_analytic_derivatives_are_those_of_the_values():
    """Rows g1, g2, F_a, F_r; columns delta_o, alpha_o, rho, u': each derivative equals the
    central difference of the values to 1e-6 of its row's largest entry (the differences'
    truncation and rounding; a wrong term in the chain rule is off by its size)."""
    rho, u, do, ao, *rest = _balls(60, 1)
    # the balls in inner contact by more than the steps (the smooth branch)
    keep = np.flatnonzero(_terms(rho, u, do, ao, rest, False)[0][11] > 1e-5)
    assert keep.size >= 30
    rho, u, do, ao = (a[keep].copy() for a in (rho, u, do, ao))
    rest = [rest[0][keep].copy()] + [np.ascontiguousarray(a[keep]) for a in rest[1:]]
    rest[0] = np.arange(keep.size, dtype=np.int64)
    part = _terms(rho, u, do, ao, rest, True)[1]
    part = part.reshape(4, 4, -1)
    x = [do, ao, rho, u]
    for col, h in enumerate((1e-7, 1e-7, 1e-7, 1e-7)):
        up, down = [a.copy() for a in x], [a.copy() for a in x]
        up[col] += h
        down[col] -= h
        t_up = _terms(up[2], up[3], up[0], up[1], rest, False)[0]
        t_dn = _terms(down[2], down[3], down[0], down[1], rest, False)[0]
        for row, term in enumerate((0, 1, 12, 13)):
            diff = (t_up[term] - t_dn[term]) / (2.0 * h)
            scale = np.abs(part[row]).max(axis=0)
            assert np.all(np.abs(part[row, col] - diff) <= 1e-6 * scale), (row, col)


def test_the_values_are_the_model_s_equations():
    """g1 and g2 from the returned loads, angles and speed terms, as the model states them."""
    rho, u, do, ao, *rest = _balls(10, 2)
    t = _terms(rho, u, do, ao, rest, False)[0]
    qi, qo, si, ci, fc, mg = t[2], t[3], t[4], t[5], t[6], t[7]
    fr = 2.0 * mg / 7.938
    g1 = qi * si - qo * np.sin(ao) + fr * np.cos(ao)
    g2 = qi * ci - qo * np.cos(ao) - fr * np.sin(ao) + fc
    size = qi + qo + fc + np.abs(fr)
    assert np.all(np.abs(t[0] - g1) <= 1e-14 * size)
    assert np.all(np.abs(t[1] - g2) <= 1e-14 * size)
    assert np.allclose(t[12], qi * si, rtol=1e-15) and np.allclose(t[13], qi * ci, rtol=1e-15)


def test_without_newton_and_continuation_a_case_is_a_convergence_error(monkeypatch):
    """The limits are the module's at each call: none left, the case at speed is unbalanced
    and the error names its inputs."""
    monkeypatch.setattr(high_speed, "RING_ITERATIONS", 0)
    monkeypatch.setattr(high_speed, "CONTINUATION_STAGES", 0)
    with pytest.raises(ConvergenceError, match="speed"):
        solve_high_speed(13, 800.0, 1500.0, speed=20000.0, contact_angle=40.0, **GEO)
    monkeypatch.undo()
    r = solve_high_speed(13, 800.0, 1500.0, speed=20000.0, contact_angle=40.0, **GEO)
    assert np.all(r.ball_loads_outer > 0)
