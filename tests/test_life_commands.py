"""The lives in the commands: C_0 wherever it is known, sweep's hours per cage position and its
refusal of the options of the modified life."""

from __future__ import annotations

import csv
import io
import json

import pytest
from click.testing import CliRunner

from bearingload.cli import main

from .cli_helpers import run_entry


def _run(*args: str):
    return CliRunner().invoke(main, list(args))


def _csv(*args: str) -> list[dict[str, str]]:
    out = _run(*args, "--format", "csv")
    assert out.exit_code == 0, out.output
    return list(csv.DictReader(io.StringIO(out.stdout)))


@pytest.mark.parametrize(
    ("args", "c0"),
    [
        (("6205", "-F", "1.4kN"), "7850.0"),  # NSK's C_0r of a 6205
        (("6205", "-F", "1.4kN", "-A", "500N"), "7850.0"),
        (("6205", "-F", "1.4kN", "--static-rating", "8kN"), "8000.0"),
        (("NU206", "-F", "5kN"), None),
    ],
)
def test_solve_prints_c0_without_a_life_option(args, c0):
    """static_rating C_0 beside s0 = C0/P0 for every bearing whose C_0 is known (ISO 76)."""
    (row,) = _csv("solve", *args)
    assert row["static_rating [N]"]
    if c0 is not None:
        assert row["static_rating [N]"] == c0
    s0 = float(row["static_safety"])
    p0 = float(row["static_equivalent_load [N]"]) if "static_equivalent_load [N]" in row else None
    p0 = p0 if p0 is not None else float(row["load [N]"])
    assert s0 == pytest.approx(float(row["static_rating [N]"]) / p0, rel=1e-9)


def test_a_ring_by_hand_has_no_c0():
    (row,) = _csv("solve", "-z", "8", "-F", "1kN", "-K", "1e5")
    assert "static_rating [N]" not in row


def test_table_life_names_c0_where_it_feeds_a_life():
    """table life has no s0: C_0 is among its conditions where it feeds a life (C_u of a_ISO)."""
    args = ("table", "life", "-b", "6205", "-F", "1.4kN", "--clearances", "0,10um")
    out = _run(*args, "--format", "json")
    assert out.exit_code == 0, out.output
    assert "static_rating" not in json.loads(out.stdout)
    out = _run(*args, "--speed", "3000", "--viscosity", "20", "--format", "json")
    assert json.loads(out.stdout)["static_rating"] == 7850.0


def test_sweep_gives_l10rh_per_cage_position_with_speed():
    """L10rh = L10r 10^6/(60 n) at every cage position, L10h once; under --quasi-static the
    loads do not change (without it the ball dynamics move them: tests/test_sweep_speed.py)."""
    base = ("sweep", "6205", "-F", "1kN", "-A", "300N", "--steps", "5")
    plain = _csv(*base)
    rows = _csv(*base, "--speed", "50rad/s", "--quasi-static")
    n = 50.0 * 60.0 / (2.0 * 3.141592653589793)
    for a, b in zip(plain, rows, strict=True):
        assert a["q_max [N]"] == b["q_max [N]"]
        life = float(b["reference_rating_life [10^6 rev]"])
        assert float(b["reference_rating_life_hours [h]"]) == pytest.approx(life * 1e6 / (60 * n))
        assert float(b["rating_life_hours [h]"]) == pytest.approx(
            float(b["rating_life [10^6 rev]"]) * 1e6 / (60 * n)
        )
        assert float(b["speed [rpm]"]) == pytest.approx(n)
    assert "speed [rpm]" not in plain[0]


@pytest.mark.parametrize(
    "option",
    [("--viscosity", "20"), ("--reliability", "99"), ("--static-rating", "8kN"),
     ("--eC", "0.5"), ("--roughness", "0.2um"), ("--contamination", "high")],
)  # fmt: skip
def test_sweep_refuses_the_modified_life_options_saying_why(option, capsys):
    code, stdout, stderr = run_entry(capsys, "sweep", "6205", "-F", "1kN", "-A", "300N", *option)
    assert code == 2 and stdout == ""
    lines = stderr.strip().splitlines()
    assert len(lines) == 1
    assert lines[0].startswith(f"Error: {option[0]} cannot be used with sweep: ")
    assert "bearingload solve" in lines[0]
    assert option[0] not in _run("sweep", "--help").output
