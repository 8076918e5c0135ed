"""Review of the last merges (sp, ld, sm): reproductions of the defects found, each failing
before its fix."""

from __future__ import annotations

import math

import numpy as np
import pytest
from click.testing import CliRunner

from bearingload.cli import main
from bearingload.models.high_speed import NOISE_MAX, solve_high_speed
from tests.campaign_speed import ball_residual

#: 7205B as the catalogue resolves it (bearings.resolve: NSK 40°, z x D_w derived, 0.52/0.53).
B7205B = dict(ball_diameter=8.7312, pitch_diameter=38.5, f_i=0.52, f_o=0.53, modulus=208000.0,
              contact_angle=40.0)  # fmt: skip


@pytest.mark.parametrize("fa", [5e-6, 1e-5, 2e-5])
def test_light_axial_load_of_an_angular_contact_bearing_at_speed_is_answered(fa):
    """``solve 7205B -F 0 -A 1e-5N --speed 3000`` (also 5e-6 N, 2e-5 N) ended on a
    ConvergenceError (ring residual 1.6e-9, 2.4e-9, 1.2e-9 of the load: above ACCEPT), while
    1e-6 N and 3e-5 N answered: the balls are balanced to BALL_TOLERANCE of their forces (about
    1.2 N with the centrifugal force, 1e5 times the load), and their residuals move the inner
    ring forces by up to 2e-6 of the load (measured), so the ring Newton stalls there. Checked
    from the returned balls: the axial sum of Q_i sin alpha_i (math.fsum) is the load to
    NOISE_MAX of it, the sums across it vanish to that, every ball's equations hold to 1e-11."""
    r = solve_high_speed(12, 0.0, fa, speed=3000.0, **B7205B)
    q, ai = r.ball_loads_inner, np.radians(r.contact_angles_inner)
    phi = np.radians(r.ball_angles)
    axial = math.fsum((q * np.sin(ai)).tolist())
    assert abs(axial - fa) <= NOISE_MAX * fa, (axial - fa) / fa
    for w in (np.cos(phi), np.sin(phi)):
        assert abs(math.fsum((q * np.cos(ai) * w).tolist())) <= NOISE_MAX * fa
    assert ball_residual({"kw": {"ball_diameter": B7205B["ball_diameter"]}}, r) <= 1e-11
    assert np.all(r.ball_loads_outer >= r.centrifugal_forces * (1 - 1e-12))
    out = CliRunner().invoke(main, ["solve", "7205B", "-F", "0", "-A", f"{fa}N", "--speed",
                                    "3000", "--format", "json"])  # fmt: skip
    assert out.exit_code == 0, out.output


def test_overlap_refusal_shows_the_digits_that_differ_and_an_accepted_maximum(capsys):
    """``solve -z 20 --ball-diameter 6.022728 --pitch-diameter 38.5 -F 1kN`` said '20 balls of
    6.02273 mm overlap ... the ball diameter D_w must be at most 6.02273 mm': the given and the
    largest diameter printed alike (6 digits), the largest rounded up (d_m sin(pi/20) =
    6.0227269...). The digits now go as far as they differ, the largest rounded down: it is
    accepted, and the given diameter is above it."""
    import re

    from tests.cli_helpers import run_entry

    args = ["solve", "-z", "20", "--pitch-diameter", "38.5", "-F", "1kN"]
    code, _, err = run_entry(capsys, *args, "--ball-diameter", "6.022728")
    assert code != 0 and len(err.strip().splitlines()) == 1, err
    given = re.search(r"20 balls of ([0-9.]+) mm overlap", err).group(1)
    most = re.search(r"must be at most ([0-9.]+) mm", err).group(1)
    assert float(given) == 6.022728 and float(most) < float(given), err
    assert float(most) <= 38.5 * math.sin(math.pi / 20)
    code, _, err = run_entry(capsys, *args, "--ball-diameter", most)
    assert code == 0, err


def test_table_life_conditions_give_the_speed_as_given(capsys):
    """``table life --bearing 6205 -F 1kN --speed 12345`` printed 'shaft speed n = 1.234e+04
    rpm' (4 digits: 12340, not the 12345 given; solve prints 12345); the conditions line now
    keeps 6 digits, as solve's tables."""
    from tests.cli_helpers import run_entry

    code, out, err = run_entry(capsys, "table", "life", "--bearing", "6205", "-F", "1kN",
                               "--speed", "12345", "--viscosity", "20.25")  # fmt: skip
    assert code == 0, err
    assert "shaft speed n = 12345 rpm" in out, out
    assert "operating viscosity nu = 20.25 mm^2/s" in out, out
