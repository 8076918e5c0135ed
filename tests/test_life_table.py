"""``bearingload table life``: L10r against the clearance for any deep-groove ball bearing; the
committed 6205 table from the same code; table k and kq refuse the combined options."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import numpy as np
import pytest

from bearingload.bearings.iso16281 import contact_ratings, reference_rating_life
from bearingload.bearings.resolve import resolve_bearing
from bearingload.models.combined import solve_combined
from bearingload.studies.life_clearance import (
    CLEARANCES_UM,
    default_clearances,
    life_against_clearance,
)

from .cli_helpers import invoke, run_entry

COMMITTED = Path(__file__).resolve().parents[1] / "tables" / "life_vs_clearance_6205.csv"


def _csv(*args: str) -> list[dict[str, str]]:
    out = invoke("table", "life", *args, "--format", "csv")
    assert out.exit_code == 0, out.output
    return list(csv.DictReader(io.StringIO(out.stdout)))


def _committed() -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO(COMMITTED.read_text(encoding="utf-8"))))


@pytest.mark.parametrize(
    ("extra", "tag"), [((), "r"), (("--axial-load", "700N"), "c")], ids=["radial", "combined"]
)
def test_table_life_6205_reproduces_the_committed_rows(extra, tag):
    """The default rows at 6205 are the committed table's; every value agrees to its 10 digits."""
    rows = _csv("--bearing", "6205", "--load", "1.4kN", *extra)
    ref = _committed()
    assert len(rows) == len(ref) == len(CLEARANCES_UM)
    for got, want in zip(rows, ref, strict=True):
        assert float(got["clearance [mm]"]) * 1e3 == pytest.approx(float(want["clearance_um [um]"]))
        assert int(got["loaded_balls"]) == int(want[f"loaded_{tag}"])
        pairs = [("q_max [N]", f"q_max_{tag} [N]"),
                 ("reference_rating_life [10^6 rev]", f"life_{tag} [10^6 rev]"),
                 ("relative_life", f"ratio_{tag}")]  # fmt: skip
        if tag == "r":
            pairs.append(("free_contact_angle [°]", "free_contact_angle [°]"))
        else:
            pairs.append(("contact_angle_max [°]", f"alpha_max_{tag} [°]"))
        for mine, theirs in pairs:
            assert float(got[mine]) == pytest.approx(float(want[theirs]), rel=2e-10, abs=1e-12)


def test_rows_are_independent_solves():
    """Each row is solve_combined at that clearance alone, with ISO/TS 16281's life of it; the
    ratio is against an explicit zero-clearance solve when 0 is not among the rows."""
    b = resolve_bearing("6208")
    g = [-0.004, 0.012, 0.05]
    t = life_against_clearance(b, 3000.0, 1000.0, clearances=g, rotating="outer")
    q_ci, q_ce = contact_ratings(b.C, b.balls, b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o)
    geo = dict(ball_diameter=b.ball_diameter, pitch_diameter=b.pitch_diameter, f_i=b.f_i,
               f_o=b.f_o, modulus=b.modulus, poisson=b.poisson)  # fmt: skip
    zero = solve_combined(b.balls, 3000.0, 1000.0, clearance=0.0, **geo)
    l_zero = float(reference_rating_life(zero.ball_loads, q_ci, q_ce, "outer"))
    for i, gr in enumerate(g):
        r = solve_combined(b.balls, 3000.0, 1000.0, clearance=gr, **geo)
        life = float(reference_rating_life(r.ball_loads, q_ci, q_ce, "outer"))
        assert t.q_max[i] == float(r.q_max) and t.loaded_balls[i] == int(r.loaded_balls)
        assert t.reference_rating_life[i] == pytest.approx(life, rel=1e-14)
        assert t.relative_life[i] == pytest.approx(life / l_zero, rel=1e-14)
        assert t.free_contact_angle[i] == float(r.free_contact_angle)


def test_default_rows_scale_with_the_bore():
    np.testing.assert_array_equal(default_clearances(resolve_bearing("6205")) * 1e3,
                                  np.asarray(CLEARANCES_UM, float))  # fmt: skip
    big = default_clearances(resolve_bearing("6220"))  # d = 100 mm: C5 max 120 um
    assert big[0] == pytest.approx(-20 * 120 / 53 * 1e-3, abs=1e-4) and big.max() > 0.18
    hand = resolve_bearing(None, balls=7, ball_diameter=11.5, pitch_diameter=43.5)
    assert default_clearances(hand)[-1] == pytest.approx(0.080, abs=1e-4)  # bore ~26 mm


def test_json_and_markdown_with_units():
    out = invoke("table", "life", "-b", "6205", "-F", "1.4kN", "-A", "700N", "--clearances",
                 "0,20um", "--format", "json")  # fmt: skip
    doc = json.loads(out.stdout)
    assert [r["clearance"] for r in doc["rows"]] == [0.0, 0.02]
    assert doc["rows"][0]["relative_life"] == 1.0 and doc["rows"][1]["relative_life"] > 1.0
    assert doc["units"]["clearance"] == "mm" and doc["units"]["reference_rating_life"] == "10^6 rev"
    assert doc["equivalent_load"] == pytest.approx(1827.101911, rel=1e-9)
    md = invoke("table", "life", "-b", "6205", "-F", "1.4kN", "--format", "markdown").output
    assert "| G_r [µm] |" in md and "L10 ISO 281 [10^6 rev]" in md


def test_hand_geometry_with_a_rating():
    rows = _csv("-z", "7", "--ball-diameter", "11.5", "--pitch-diameter", "43.5", "--modulus",
                "210000", "-C", "23.4kN", "-F", "1kN", "--clearances", "0,10um")  # fmt: skip
    # the peer's MASTA-labelled L10r at G_r = 0 and 10 um, radial 1000 N (tests/fixtures):
    # ours with the Hertz K at each contact angle within 2.2e-4
    from .fixtures.published import PEER_ISO16281_MASTA

    lives = [float(r["reference_rating_life [10^6 rev]"]) for r in rows]
    masta = [v[7] for v in sorted(PEER_ISO16281_MASTA.values()) if v[1:4] == (1000.0, 0, 0)]
    assert len(masta) == 2  # examples 1 and 3: G_r = 0 and 10 um
    for got, want in zip(lives, masta, strict=True):
        assert got == pytest.approx(want, rel=2.2e-4)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("table", "k", "--axial-load", "1kN"),
         "Error: --axial-load cannot be used with table k: table k and kq are the papers' radial"),
        (("table", "kq", "--moment", "1Nm"), "Error: --moment cannot be used with table kq"),
        (("table", "k", "--misalignment", "0.1"), "'table life', 'solve' or 'sweep'"),
        (("table", "k", "--clearances", "0,10um"), "Error: --clearances cannot be used with"),
        (("table", "life", "-b", "6205"), "Error: Missing option '--load' / '-F'"),
        (("table", "life", "-F", "1kN"), "Error: Missing option '--bearing' / '-b' (table life needs a bearing"),
        (("table", "life", "-b", "6205", "-F", "1kN", "-G", "10um"),
         "Error: --clearance cannot be used with table life"),
        (("table", "life", "-b", "6205", "-F", "1kN", "--method", "all"),
         "Error: --method cannot be used with table life"),
        (("table", "life", "-b", "NU206", "-F", "1kN"),
         "Error: Invalid value for '--bearing': NU206 is a roller bearing"),
        (("table", "life", "-z", "7", "--ball-diameter", "11.5", "--pitch-diameter", "43.5",
          "-F", "1kN"), "Error: Invalid value for '--dynamic-rating'"),
        (("table", "life", "-b", "6205", "-F", "1kN", "--clearances", "0,C3"),
         "Error: Invalid value for '--clearances'"),
        (("table", "life", "-b", "6205", "-F", "1kN", "--clearances", "0,1mm"),
         "Error: Invalid value for '--clearances': must be smaller"),
    ],
)  # fmt: skip
def test_errors_are_one_line_exit_2(capsys, tmp_path, args, message):
    target = tmp_path / "t.csv"
    code, out, err = run_entry(capsys, *args, "-o", str(target))
    assert code == 2 and out == "" and not target.exists()
    assert message in err and err.startswith("Error: ") and err.count("\n") == 1, err


def test_help_lists_life_with_examples():
    out = invoke("table", "--help").output
    assert "life  reference rating life L10r" in out
    assert "bearingload table life --bearing 6205 --load 1.4kN" in out
    for option in ("--clearances", "--axial-load", "--dynamic-rating", "--rotating", "--balls"):
        assert option in out


def test_a_clearance_beyond_the_groove_names_the_list_option(capsys):
    code, out, err = run_entry(capsys, "table", "life", "-b", "6205", "-F", "1kN",
                               "--clearances", "0,0.9mm")  # fmt: skip
    assert code == 2 and out == ""
    assert err.startswith("Error: Invalid value for '--clearances': must be smaller than")


def test_one_loaded_ball_is_named_by_its_rows():
    hand = resolve_bearing(None, balls=7, ball_diameter=11.5, pitch_diameter=43.5)
    t = life_against_clearance(hand, 1000.0, clearances=[0.0, 0.08], dynamic_rating=23400.0,
                               misalignment=np.degrees(2e-3), rotating="outer")  # fmt: skip
    assert list(t.loaded_balls) == [3, 1]
    assert any("only one ball carries the load at G_r = 80 µm" in w for w in t.warnings)
