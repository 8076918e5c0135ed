"""The compiled core's Newton solve over the free components (``solve_held``) gives the bits
of its full 5 x 5 Gaussian elimination (``solve5``) on the Newton matrices it is used for
(held components unit rows and columns, 0 on the right-hand side) and falls back to it on any
other system: random systems with zeros of either sign, singular, overflowing and NaN
entries, compared bit for bit (NaN with NaN)."""

from __future__ import annotations

import numpy as np

from bearingload.models import _core


def _systems(rng: np.random.Generator, n: int) -> tuple[np.ndarray, ...]:
    """n Newton-like systems (a (n, 25), b (n, 5), held (n, 5) uint8)."""
    held = (rng.random((n, 5)) < 0.4).astype(np.uint8)
    m = rng.normal(size=(n, 5, 5))
    a = m @ m.transpose(0, 2, 1) * 10.0 ** rng.integers(-3, 3, (n, 1, 1))
    a[rng.random((n, 5, 5)) < 0.15] = 0.0
    singular = rng.random(n) < 0.02
    a[singular, 0, :] = 0.0
    a[singular, :, 0] = 0.0
    a[rng.random(n) < 0.01] *= 1e300  # (products overflow)
    a[rng.random(n) < 0.005, 1, 1] = np.nan
    b = rng.normal(size=(n, 5))
    b[rng.random((n, 5)) < 0.3] = 0.0
    b[rng.random((n, 5)) < 0.3] = -0.0
    blocks = rng.random(n) < 0.3  # (free x exactly 0: zeros of either sign come out)
    a[blocks, :2, 2:] = 0.0
    a[blocks, 2:, :2] = 0.0
    b[blocks, 2:] = rng.choice([0.0, -0.0], (int(blocks.sum()), 3))
    rows, cols = np.nonzero(held)
    a[rows, cols, :] = 0.0
    a[rows, :, cols] = 0.0
    a[rows, cols, cols] = 1.0 + 1e-13 * rng.random(rows.size)
    b[rows, cols] = -0.0
    other = rng.random(n) < 0.05  # not the Newton matrix's form: solve5 itself
    a[other, 0, 1] = -0.0
    return np.ascontiguousarray(a.reshape(n, 25)), b, held


def test_held_solve_gives_solve5_bits() -> None:
    with np.errstate(all="ignore"):
        a, b, held = _systems(np.random.default_rng(20261129), 100_000)
    full, free = _core.held_solves(a, b, held)
    same = (full.view(np.uint64) == free.view(np.uint64)) | (np.isnan(full) & np.isnan(free))
    assert same.all()
    # the test sees the cases that matter: exact zeros of both signs, held and free
    zero = (full == 0) & ~np.isnan(full)
    assert (zero & np.signbit(full) & (held == 0)).sum() > 1000
    assert (zero & ~np.signbit(full) & (held == 0)).sum() > 1000
    assert (zero & np.signbit(full) & (held == 1)).sum() > 1000
    assert np.isnan(full).any(axis=1).sum() > 100
