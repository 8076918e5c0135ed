"""Review session 3: defects found by trying to break the recent changes (one test per defect)."""

from __future__ import annotations

import math

import pytest

from bearingload.errors import ConvergenceError
from bearingload.numerics import bracketed_root


def test_bracketed_root_does_not_return_a_far_bracket_end_silently():
    # a bracket of 1e300 around a root at 1 cannot be halved to 1e-12 in 400 evaluations: it
    # returned 0.0 (where f = -0.785) as the root; it must raise instead
    with pytest.raises(ConvergenceError):
        bracketed_root(lambda x: math.atan(x - 1.0), 0.0, 1e300)
    # a wide bracket that can be halved in time still gives the root
    assert abs(bracketed_root(lambda x: math.atan(x - 1.0), 0.0, 1e6) - 1.0) <= 4e-12


def _run(*args: str, stdin: str | None = None):
    from click.testing import CliRunner

    from bearingload.cli import main

    return CliRunner().invoke(main, list(args), input=stdin)


def _batch(text: str, *args: str):
    return _run("batch", "-", "--format", "csv", *args, stdin=text)


def test_batch_reads_a_roller_rows_stiffness_in_its_own_unit_beside_an_exponent_column():
    """With an 'exponent' column in the file, a roller row whose exponent cell is blank had its
    stiffness read in N/mm^1.5: '4700kgf/mm^1.5' was taken (as kgf/mm^(10/9)) where solve
    refuses it, and '3e5N/mm^(10/9)' refused where solve takes it."""
    text = (
        "bearing,load,stiffness,exponent\n"
        "NU204,5kN,3e5N/mm^(10/9),\n"
        "NU204,5kN,4700kgf/mm^1.5,\n"
        "306,5kN,4e5N/mm^1.5,\n"
    )
    solved = _run("solve", "NU204", "-F", "5kN", "-K", "3e5N/mm^(10/9)", "--format", "csv")
    assert solved.exit_code == 0
    refused = _run("solve", "NU204", "-F", "5kN", "-K", "4700kgf/mm^1.5")
    assert refused.exit_code == 2
    for chunk in ("1", "100"):
        r = _batch(text, "--chunk-size", chunk)
        assert r.exit_code == 1, r.output
        assert [line.split(",")[0] for line in r.stdout.splitlines()[1:]] == ["2", "4"]
        assert r.stderr.startswith("Warning: row 3: stiffness: the unit 'kgf/mm^1.5'")
        assert (
            r.stdout.splitlines()[1].split(",")[11] == solved.stdout.splitlines()[1].split(",")[9]
        )


def test_an_explicit_exponent_of_1_5_is_refused_for_a_roller_bearing():
    """--exponent 1.5 (the option's default written out) with a roller bearing read -K in
    N/mm^1.5 and then solved the rollers with m = 10/9, taking 3e5 N/mm^1.5 as 3e5 N/mm^(10/9):
    the explicit exponent was ignored. solve, sweep and a batch row's exponent cell now refuse it
    as they refuse --exponent 10/9 for a ball bearing."""
    for command in ("solve", "sweep"):
        r = _run(command, "NU204", "-F", "5kN", "-K", "3e5N/mm^1.5", "--exponent", "1.5")
        assert r.exit_code == 2, r.output
        assert "Error: Invalid value for '--exponent': a roller bearing" in r.output
    assert _run("solve", "306", "-F", "5kN", "--exponent", "1.5").exit_code == 0
    r = _batch("bearing,load,exponent\nNU204,5kN,1.5\n306,5kN,1.5\nNU204,5kN,\n")
    assert r.exit_code == 1, r.output
    assert r.stderr.startswith("Warning: row 2: exponent: a roller bearing (line contact)")
    assert [line.split(",")[0] for line in r.stdout.splitlines()[1:]] == ["3", "4"]


def test_combined_loads_near_the_smallest_accepted_converge():
    """Tiny loads with a clearance of the groove geometry's size (the review: 95 of 288 such
    loadings of a 6313 ended in ConvergenceError after 200 iterations; below the new limit they
    are refused by name): every loading from the smallest accepted load up converges."""
    import pytest

    from bearingload.bearings.resolve import resolve_bearing
    from bearingload.errors import InputError
    from bearingload.models.combined import GEOMETRY_RATIO_MAX, solve_combined

    b = resolve_bearing("6313")
    big_a = (b.f_i + b.f_o - 1.0) * b.ball_diameter
    f_min = b.stiffness * (big_a / GEOMETRY_RATIO_MAX) ** 1.5
    geometry = {"ball_diameter": b.ball_diameter, "pitch_diameter": b.pitch_diameter,
                "f_i": b.f_i, "f_o": b.f_o}  # fmt: skip
    for load in (1.01 * f_min, 30.0 * f_min):
        for tilt in ({"moment": 10.0 * load}, {"misalignment": 0.05}, {}):
            r = solve_combined(b.balls, load, 0.1 * load, clearance=big_a, cage_angle=3.0,
                               **geometry, **tilt)  # fmt: skip
            assert float(r.q_max) > 0
    with pytest.raises(InputError, match="too small for the combined solver"):
        solve_combined(b.balls, 0.5 * f_min, 0.0, clearance=big_a, **geometry)
