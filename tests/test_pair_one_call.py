"""One call of the pair solver: one core call (``_core.pair_call``) on the common path, the
general path (``pair._general``) for a call with a case the core flags; a case's answer has
the same bits alone and in a batch, whichever path the batch takes, and the components held
by a symmetry are those the rule of ``held_components`` states."""

import itertools

import numpy as np

from bearingload.models.pair import held_components, solve_pair

#: 7205B as the catalogue resolves it (NSK 40°, 12 balls of 8.7312 mm on 38.5 mm, 0.52/0.53).
GEOMETRY = dict(
    arrangement="DT",
    contact_angle=40.0,
    ball_diameter=8.7312,
    pitch_diameter=38.5,
    width=15.0,
    f_i=0.52,
    f_o=0.53,
    modulus=208000.0,
)
FIELDS = ("x", "y", "axial", "tilt", "tilt_cross", "residual", "iterations", "stiffness_matrix")


def test_a_case_has_the_same_bits_alone_and_in_a_batch_that_takes_the_general_path():
    """The first case (its cage 1e-12° off the symmetric position) is left unbalanced: the
    general path solves the batch again at the snapped cage (test_pair_near_symmetric); every
    case keeps the bits it has alone (where the core answers it in one call)."""
    fr, fa, cage = [1000.0, 1500.0, 300.0], [10.0, 200.0, 50.0], [1e-12, 7.0, 0.0]
    batch = solve_pair(12, fr, fa, cage_angle=cage, **GEOMETRY)
    assert float(batch.bearings[0].cage_angle[0]) == 0.0  # (snapped: the general path)
    for i in range(3):
        one = solve_pair(12, fr[i], fa[i], cage_angle=cage[i], **GEOMETRY)
        for name in FIELDS:
            assert np.array_equal(np.asarray(getattr(batch, name))[i], getattr(one, name)), name
        for b_batch, b_one in zip(batch.bearings, one.bearings, strict=True):
            assert np.array_equal(b_batch.ball_loads[i], b_one.ball_loads)
            assert np.array_equal(b_batch.stiffness_matrix[i], b_one.stiffness_matrix)


def test_a_preloaded_batch_has_the_bits_of_its_cases_alone():
    """DB with preload, Hertz and a constant K: the batch answered in one core call."""
    fr, fa, fp = [0.0, 800.0, 2000.0], [-300.0, 0.0, 1200.0], [200.0, 500.0, 50.0]
    for extra in ({}, {"stiffness": 7.0e5}):
        kw = GEOMETRY | {"arrangement": "DB"} | extra
        batch = solve_pair(12, fr, fa, preload=fp, moment=[0.0, 3000.0, 0.0], **kw)
        for i in range(3):
            one = solve_pair(12, fr[i], fa[i], preload=fp[i], moment=[0.0, 3000.0, 0.0][i], **kw)
            for name in (*FIELDS, "preload_offset", "lift_off_axial_load"):
                assert np.array_equal(np.asarray(getattr(batch, name))[i], getattr(one, name))
            assert np.array_equal(batch.unloaded[i], one.unloaded)


def test_the_held_components_are_those_of_the_symmetries():
    """Every combination of zero and nonzero loads, mirrored balls or not, DB and DT: y and t_c
    held by the mirror about the load line without a cross moment; x, y, t, t_c by the z-fold
    symmetry without a radial load or moment; a, t, t_c by the mirror across the mid-plane
    (not DT) without a thrust or moment."""
    cases = list(itertools.product((0.0, 1.0), repeat=5))  # F_r, F_a, M, M_c, mirror
    loads = tuple(np.array([c[i] for c in cases]) for i in range(4))
    mirror = np.array([c[4] == 1.0 for c in cases])
    for kind in ("DB", "DT"):
        held = held_components(kind, mirror, loads)
        for (fr, fa, mm, mc, mirrored), row in zip(cases, held, strict=True):
            no_moment = mm == 0 and mc == 0
            across = bool(mirrored) and mc == 0
            z_fold = fr == 0 and no_moment
            mid_plane = kind != "DT" and fa == 0 and no_moment
            expected = [z_fold, across or z_fold, mid_plane, z_fold or mid_plane]
            expected.append(across or z_fold or mid_plane)
            assert row.tolist() == expected, (kind, fr, fa, mm, mc, mirrored)
