"""The seams of ``bearingload solve``'s combined-load path: the plot draws the command's own
solution in the format its extension names, designations of unmodelled bearing types are
refused, a lone maker's ball set is used and said so, --rotating changes no load, the combined
report gives what an engineer expects (contact pressures at both contacts, s0, L10, L10r)."""

from __future__ import annotations

import json
import math
import sys

import mpmath as mp
import pytest

from .cli_helpers import drawn, invoke, run_entry
from .fixtures.published import PEER_ISO16281_BEARING, PEER_ISO16281_MASTA
from .test_hertz import mp_contact

PEER = ("-z", "7", "--ball-diameter", "11.5", "--pitch-diameter", "43.5", "--modulus", "210000",
        "-C", "23.4kN")  # fmt: skip


def _json(*args: str) -> dict:
    out = invoke("solve", *args, "--format", "json")
    assert out.exit_code == 0, out.output
    return json.loads(out.stdout)


# --- 1. --plot: the command's own solution, in the format of the extension --------------------
def test_plot_draws_the_combined_solution_it_printed(monkeypatch, tmp_path):
    """solve 6205 -F 5kN -A 2kN --plot drew the radial-only solution (Q_max 3286 N at ball 1,
    the table 2815 N); now the bars are the table's ball loads, the line its contact angles."""
    figures = drawn(monkeypatch)
    args = ("6205", "-F", "5kN", "-A", "2kN", "--plot", str(tmp_path / "x.png"))
    case = _json(*args)["cases"][0]
    (fig,) = figures
    polar, *lower = fig.get_axes()
    heights = [p.get_height() for p in polar.patches]
    assert heights == pytest.approx(case["ball_loads"], rel=1e-9)
    (line,) = lower[0].get_lines()
    assert list(line.get_ydata()) == pytest.approx(case["contact_angles"], rel=1e-9)
    assert list(line.get_xdata()) == pytest.approx(case["ball_angles"], rel=1e-9, abs=1e-12)
    title = " ".join(polar.get_title().split())  # wrapped at 70 characters
    assert "[°]" in lower[0].get_ylabel() and "F_a = 2000 N" in title


def test_plot_draws_the_radial_solution_it_printed(monkeypatch, tmp_path):
    figures = drawn(monkeypatch)
    case = _json(*PEER, "-F", "1kN", "-G", "10um", "--cage-angle", "7",
                 "--plot", str(tmp_path / "x.png"))["cases"][0]  # fmt: skip
    (ax,) = figures[0].get_axes()
    assert [p.get_height() for p in ax.patches] == pytest.approx(case["ball_loads"], rel=1e-9)


@pytest.mark.parametrize(("name", "magic"), [("x.pdf", b"%PDF"), ("x.svg", b"<?xml"),
                                             ("x.PNG", b"\x89PNG"), ("x.jpg", b"\xff\xd8\xff")])  # fmt: skip
def test_plot_is_written_in_the_format_of_its_extension(tmp_path, name, magic):
    out = invoke("solve", "6205", "-F", "5kN", "-A", "2kN", "--plot", str(tmp_path / name))
    assert out.exit_code == 0, out.output
    assert (tmp_path / name).read_bytes().startswith(magic)
    assert [p.name for p in tmp_path.iterdir()] == [name]  # no temporary file left


@pytest.mark.parametrize("name", ["x.jpgx", "x.docx", "x"])
def test_plot_refuses_an_extension_it_cannot_write(capsys, tmp_path, name):
    code, out, err = run_entry(
        capsys, "solve", "6205", "-F", "5kN", "-A", "2kN", "--plot", str(tmp_path / name)
    )
    assert code == 2 and out == "" and err.count("\n") == 1 and err.startswith("Error: ")
    assert "Invalid value for '--plot'" in err and "allowed extensions: " in err
    assert ".png" in err and ".pdf" in err and ".svg" in err
    assert list(tmp_path.iterdir()) == []  # nothing written, not even half


def test_plot_refuses_jpg_where_pillow_cannot_write_it(capsys, tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "PIL", None)  # import PIL -> ImportError
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "5kN", "--plot",
                               str(tmp_path / "x.jpg"))  # fmt: skip
    assert code == 2 and out == "" and err.count("\n") == 1
    allowed = err.split("allowed extensions: ")[1].split(", ")
    assert ".jpg" not in allowed and ".png" in allowed and ".pdf" in allowed
    assert list(tmp_path.iterdir()) == []


def test_plot_of_a_method_without_ball_loads_is_refused_before_any_work(capsys, tmp_path):
    code, out, err = run_entry(capsys, *("solve", "6205", "-F", "5kN", "--method", "stribeck"),
                               "--plot", str(tmp_path / "x.png"))  # fmt: skip
    assert code == 2 and out == "" and "--method stribeck gives none" in err
    assert list(tmp_path.iterdir()) == []


# --- 2. bearing types the tool does not model --------------------------------------------------
@pytest.mark.parametrize(
    ("designation", "kind"),
    [
        ("30205", "tapered roller bearing"),
        ("30305 J2/Q", "tapered roller bearing"),
        ("32206", "tapered roller bearing"),
        ("22205 E", "spherical roller bearing"),
        ("23005", "spherical roller bearing"),
        ("1205", "self-aligning ball bearing"),
        ("2306", "self-aligning ball bearing"),
        ("51205", "thrust ball bearing"),
        ("NA4905", "needle roller bearing"),
        ("HK1516", "needle roller bearing"),
        ("71905CD", "angular contact ball bearing"),
        ("6-30205", "tapered roller bearing"),
    ],
)
def test_unmodelled_bearing_types_are_refused(capsys, designation, kind):
    """30205 was solved as the GOST ball bearing 205 (design variant 3)."""
    code, out, err = run_entry(capsys, "solve", designation, "-F", "1kN")
    assert code == 2 and out == "" and err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith("Error: Invalid value for 'BEARING': ")
    assert kind in err and "which bearingload does not model" in err
    assert "it models single-row deep groove ball bearings" in err and "NUP" in err
    assert "by hand" not in err  # a geometry given by hand would not make it a deep-groove one


def test_an_unmodelled_type_with_a_hand_ball_set_is_refused_too(capsys):
    code, _, err = run_entry(capsys, "solve", "30205", "-F", "1kN", *PEER[:4])
    assert code == 2 and "tapered roller bearing" in err


# --- 3. one maker's ball set ------------------------------------------------------------------
def test_the_one_makers_set_is_used_and_said_so():
    """6408 needed --maker NTN, the only maker with a set for it."""
    out = invoke("solve", "6408", "-F", "5kN")
    assert out.exit_code == 0, out.output
    assert "Ball set: NTN (derived, high confidence); the only maker with a ball set for 6408" in (
        out.stdout
    )
    doc = _json("6408", "-F", "5kN")
    ntn = _json("6408", "-F", "5kN", "--maker", "NTN")
    assert doc["cases"][0]["ball_loads"] == ntn["cases"][0]["ball_loads"]
    assert doc["bearing"]["maker"] == "NTN"
    assert any("the only maker with a ball set for 6408" in s for s in doc["bearing"]["sources"])
    assert "the only maker" in doc["bearing"]["geometry"]["ball_diameter"]["source"]
    combined = invoke("solve", "6408", "-F", "5kN", "-A", "1kN")
    assert combined.exit_code == 0 and "the only maker with a ball set for 6408" in combined.stdout


def test_makers_that_differ_still_need_a_choice(capsys):
    code, _, err = run_entry(capsys, "solve", "6404", "-F", "1kN")
    assert code == 2 and "choose a maker's set with '--maker': NTN | SKF" in err


# --- 4. --rotating feeds the life only --------------------------------------------------------
def _l10r(ball_loads: list[float], rotating: str) -> float:
    """ISO/TS 16281:2008, 4.3, written out here: the peer's ball set (f 0.52/0.53, C_r 23.4 kN),
    one ball per load."""
    b = PEER_ISO16281_BEARING
    dw, dpw, c, z = b["ball_diameter"], b["pitch_diameter"], b["dynamic_rating"], len(ball_loads)
    ri, re = b["f_i"] * dw, b["f_o"] * dw
    g = dw / dpw
    x = ((1 - g) / (1 + g)) ** 1.72 * (ri * (2 * re - dw) / (re * (2 * ri - dw))) ** 0.41
    q_ci = c / (0.407 * z) * (1 + (1.044 * x) ** (10 / 3)) ** 0.3
    q_ce = c / (0.389 * z) * (1 + (1.044 * x) ** (-10 / 3)) ** 0.3
    cubic = (sum(q**3 for q in ball_loads) / z) ** (1 / 3)
    ten = (sum(q ** (10 / 3) for q in ball_loads) / z) ** 0.3
    q_ei, q_ee = (cubic, ten) if rotating == "inner" else (ten, cubic)
    return ((q_ei / q_ci) ** (10 / 3) + (q_ee / q_ce) ** (10 / 3)) ** -0.9


@pytest.mark.parametrize("clearance", ["1.14mm", "10um", "0"])
def test_rotating_changes_no_ball_load(clearance):
    """'--rotating inner' switched to the combined engine: Q_max 459.6 N instead of 500 N at
    G_r = 1.14 mm. Now both rings give the radial engine's loads, and their own L10r."""
    args = (*PEER, "-z", "10", "-F", "500", "-G", clearance)
    plain = _json(*args)["cases"][0]
    for rotating in ("inner", "outer"):
        case = _json(*args, "--rotating", rotating)["cases"][0]
        assert case["ball_loads"] == plain["ball_loads"] and case["q_max"] == plain["q_max"]
        assert case["method"] == "exact" and case["rotating"] == rotating
        loads = case["ball_loads"]
        assert case["reference_rating_life"] == pytest.approx(_l10r(loads, rotating), rel=1e-9)
    assert plain["rotating"] == "inner"  # L10r by default for the inner ring, as ISO/TS 16281


@pytest.mark.parametrize("example", [1, 3])
def test_radial_reference_life_matches_masta(example):
    """The peer's MASTA values of a purely radial load (Examples 1 and 3): L10r within 1e-4."""
    s_r, f_r, _, _, delta_r, _, _, l10r = PEER_ISO16281_MASTA[example]
    case = _json(*PEER, "-F", f"{f_r}", "-G", f"{s_r}")["cases"][0]
    assert case["x"] * 1e3 == pytest.approx(delta_r, rel=1e-4)
    assert case["reference_rating_life"] == pytest.approx(l10r, rel=1e-4)


def test_dynamic_rating_replaces_c_on_the_radial_path():
    case = _json("6205", "-F", "1kN", "-C", "20kN")["cases"][0]
    assert case["method"] == "exact" and case["rating_life"] == pytest.approx(20.0**3)
    assert case["ball_loads"] == _json("6205", "-F", "1kN")["cases"][0]["ball_loads"]


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("-z", "10", "--ball-diameter", "11.5", "--pitch-diameter", "43.5", "-F", "500",
          "--rotating", "inner"), "give '--dynamic-rating'"),
        (("NU206", "-F", "5kN", "--rotating", "outer"), "ball bearings only"),
        (("-z", "8", "-K", "1e5", "-F", "1kN", "--rotating", "outer"), "would be ignored"),
        (("6205", "-F", "1kN", "--method", "stribeck", "--rotating", "outer"),
         "'--method' stribeck gives none"),
    ],
)  # fmt: skip
def test_rotating_without_a_reference_life_is_refused(capsys, args, message):
    code, out, err = run_entry(capsys, "solve", *args)
    assert code == 2 and out == "" and err.count("\n") == 1 and "--rotating" in err
    assert message in err, err


# --- 5. what an engineer expects of a combined load case --------------------------------------
def _mp_pressures(case: dict, bearing: dict) -> tuple[float, float]:
    """30-digit Hertz pressures of every ball at its load and contact angle, the largest of each
    contact: curvature in the rolling direction 2 cos(a)/(d_m -+ D_w cos(a))."""
    mp.mp.dps = 30
    g = {k: v["value"] for k, v in bearing["geometry"].items()}
    dw, dm, fi, fo = (mp.mpf(g[k]) for k in ("ball_diameter", "pitch_diameter", "f_i", "f_o"))
    e, nu = mp.mpf(g["modulus"]), mp.mpf(g["poisson"])
    e_star = e / (2 * (1 - nu**2))
    inner, outer = [], []
    for q, alpha in zip(case["ball_loads"], case["contact_angles"], strict=True):
        if q == 0:
            continue
        c = mp.cos(mp.radians(alpha))
        rho_i = (2 / dw + 2 * c / (dm - dw * c), 2 / dw - 1 / (fi * dw))
        rho_o = (2 / dw - 2 * c / (dm + dw * c), 2 / dw - 1 / (fo * dw))
        inner.append(mp_contact(*rho_i, q, e_star)[4])
        outer.append(mp_contact(*rho_o, q, e_star)[4])
    return float(max(inner)), float(max(outer))


def test_combined_case_gives_pressures_safety_and_both_lives():
    doc = _json("6205", "-F", "5kN", "-A", "2kN")
    case, bearing = doc["cases"][0], doc["bearing"]
    p_i, p_o = _mp_pressures(case, bearing)
    assert case["p_max_inner"] == pytest.approx(p_i, rel=1e-9)
    assert case["p_max_outer"] == pytest.approx(p_o, rel=1e-9)
    # ISO 76:2006, 7.1: P0 = max(0.6 F_r + 0.5 F_a, F_r) = max(4000, 5000) N
    assert case["static_equivalent_load"] == 5000.0
    assert case["static_safety"] == pytest.approx(bearing["C0"] / 5000.0, rel=1e-12)
    assert case["rating_life"] > 0 and case["reference_rating_life"] > 0
    assert case["loaded_balls"] == 9 and case["q_max"] == max(case["ball_loads"])
    for key, unit in (("p_max_inner", "MPa"), ("p_max_outer", "MPa"),
                      ("static_equivalent_load", "N"), ("static_safety", "-")):  # fmt: skip
        assert doc["units"].get(key) == unit
    table = invoke("solve", "6205", "-F", "5kN", "-A", "2kN").stdout
    for label in ("max contact pressure, inner", "max contact pressure, outer",
                  "static safety factor s0 = C0/P0", "static equivalent load P0",
                  "basic rating life L10", "reference rating life L10r", "balls carrying load"):  # fmt: skip
        assert label in table, label
    head = invoke("solve", "6205", "-F", "5kN", "-A", "2kN", "--format", "csv").stdout
    for column in ("p_max_inner [MPa]", "p_max_outer [MPa]", "static_safety",
                   "static_equivalent_load [N]", "rating_life [10^6 rev]",
                   "reference_rating_life [10^6 rev]"):  # fmt: skip
        assert column in head.splitlines()[0].split(","), column


def test_the_axial_load_raises_p0_where_it_counts():
    case = _json("6205", "-F", "1kN", "-A", "3kN")["cases"][0]
    assert case["static_equivalent_load"] == pytest.approx(0.6 * 1000 + 0.5 * 3000)


def test_radial_path_names_the_same_quantities_alike():
    """The same key for the same quantity on both paths: s0 = C0/F_r on the radial one."""
    radial = _json("6205", "-F", "2kN")
    case = radial["cases"][0]
    assert case["static_safety"] == pytest.approx(radial["bearing"]["C0"] / 2000.0, rel=1e-12)
    combined = _json("6205", "-F", "2kN", "-A", "100N")["cases"][0]
    shared = ("q_max", "loaded_balls", "p_max_inner", "p_max_outer", "static_safety",
              "rating_life", "reference_rating_life", "rotating")  # fmt: skip
    for key in shared:
        assert case[key] is not None and combined[key] is not None, key


# --- 6. minutes and seconds of arc --------------------------------------------------------------
@pytest.mark.parametrize(("text", "degrees"), [("6arcmin", 0.1), ("6'", 0.1), ("360arcsec", 0.1),
                                               ('360"', 0.1), ("0.1deg", 0.1)])  # fmt: skip
def test_misalignment_in_arcmin(text, degrees):
    case = _json(*PEER, "-F", "1kN", "-G", "10um", "--misalignment", text)["cases"][0]
    assert case["misalignment"] == pytest.approx(degrees, rel=1e-12)
    assert case["tilt"] == pytest.approx(degrees, rel=1e-9)


def test_cage_angle_in_arcmin():
    a = _json(*PEER, "-F", "1kN", "--cage-angle", "450arcmin")["cases"][0]
    assert a["cage_angle"] == 7.5
    assert math.isclose(a["ball_angles"][1], 7.5 + 360 / 7, rel_tol=1e-9)  # 10 digits


@pytest.mark.parametrize(
    "args",
    [["solve", "7205B", "-F", "2kN", "-A", "1kN"], ["solve", "6205", "-F", "2kN", "-A", "1kN"],
     ["sweep", "7205B", "-F", "2kN", "-A", "1kN"], ["table", "life", "-b", "6205", "-F", "2kN"]],
)  # fmt: skip
def test_a_dynamic_rating_beyond_its_range_is_named_in_every_engine(capsys, args):
    """The radial engine refused -C 1e300N for its range; the combined engines overflowed L10 and
    refused it as a bad '--load'."""
    from tests.cli_helpers import run_entry

    code, out, err = run_entry(capsys, *args, "-C", "1e300N")
    assert code == 2 and out == ""
    assert err.strip() == (
        "Error: Invalid value for '--dynamic-rating': must lie between 0 and 1e+09 N (got 1e+300 N)"
    )
