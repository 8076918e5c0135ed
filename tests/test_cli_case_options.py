"""One set of case options (declared once for solve, sweep and table, read once into a
CaseOptions) and the general load: --moment-cross (MASTA's M_x) and --tilt-radius."""

from __future__ import annotations

import json
import math

import click
import pytest

from bearingload.bearings.clearance import picks_of
from bearingload.bearings.resolve import check_exponent, resolve_bearing, resolve_bearings
from bearingload.bearings.tilt import parse_tilt_radius, tilt_lever
from bearingload.cli import main
from bearingload.contact.hertz import ball_stiffness
from bearingload.errors import InputError
from bearingload.models.combined import solve_combined

from .cli_helpers import invoke, run_entry
from .fixtures.published import PEER_ISO16281_BEARING, PEER_ISO16281_MASTA

PEER = ("-z", "7", "--ball-diameter", "11.5", "--pitch-diameter", "43.5", "--modulus", "210000",
        "-C", "23.4kN")  # fmt: skip


def _case(*args: str) -> dict:
    out = invoke("solve", *args, "--format", "json")
    assert out.exit_code == 0, out.output
    (case,) = json.loads(out.stdout)["cases"]
    return case


# --- one set of case options -----------------------------------------------------------------
def _params(name: str) -> dict[str, click.Parameter]:
    command = main.get_command(click.Context(main), name)
    assert command is not None
    return {p.name: p for p in command.params if p.name}


def test_every_case_option_has_one_help_text_in_every_command():
    """solve, sweep and table declared --balls, --load, --stiffness, --clearance ... each on its
    own, with help texts that drifted apart (--balls '1 to' vs '3 to', --dynamic-rating's
    units); now one declaration serves all three."""
    from bearingload.cli.case_options import DECLARATIONS
    from bearingload.plan.case import DYNAMICS_PARAMS, SERVICE_PARAMS

    commands = {name: _params(name) for name in ("solve", "sweep", "table")}
    for name in DECLARATIONS:
        helps = {c: getattr(p[name], "help", None) for c, p in commands.items() if name in p}
        assert len(helps) >= 2 and len(set(helps.values())) == 1, (name, helps)
    # the cage turns; a_ISO, the modified lives and the film are solve's and table life's: sweep
    # declares them hidden to refuse them saying why (--speed gives its hours and, with
    # --ball-density and --quasi-static, shown, the ball dynamics)
    assert set(DECLARATIONS) - set(commands["sweep"]) == {"cage_angle"}
    hidden = {n for n, p in commands["sweep"].items() if getattr(p, "hidden", False)}
    assert hidden == set(SERVICE_PARAMS) - {"speed"}
    assert set(DYNAMICS_PARAMS) <= set(commands["sweep"])
    assert set(DECLARATIONS) <= set(commands["solve"]) and set(DECLARATIONS) <= set(
        commands["table"]
    )
    assert {"moment_cross", "tilt_radius"} <= set(commands["solve"]) & set(commands["sweep"])


def test_sweep_takes_the_maker_of_solve():
    """sweep had no --maker: SKF's ball set of a 6208 could be solved but not swept."""
    out = invoke("sweep", "6208", "-F", "5kN", "--maker", "SKF", "--steps", "2", "--format", "json")
    assert out.exit_code == 0, out.output
    skf = resolve_bearing("6208", maker="SKF")
    assert json.loads(out.stdout)["stiffness"] == pytest.approx(skf.stiffness, rel=1e-9)
    assert skf.stiffness != pytest.approx(resolve_bearing("6208").stiffness, rel=1e-3)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("sweep", "306", "-F", "1kN", "-G", "C3", "--clearance-pick", "range"),
         "Invalid value for '--clearance-pick': 'range'"),
        (("table", "life", "-b", "6205", "-F", "1kN", "--clearance-pick", "range"),
         "--clearance-pick cannot be used with table life"),
        (("sweep", "-z", "8", "-K", "1e5", "-F", "1kN", "--maker", "SKF"), "--maker needs"),
        (("table", "k", "--maker", "SKF"), "--maker needs '--bearing'"),
        (("table", "k", "--moment-cross", "1Nm"), "--moment-cross cannot be used with table k"),
        (("table", "kq", "--tilt-radius", "pitch"), "--tilt-radius cannot be used with table kq"),
        (("sweep", "-z", "7", "--kurochkin-T", "0.5", "--moment-cross", "1"),
         "--moment-cross cannot be used with --kurochkin-T"),
        (("solve", "NU206", "-F", "1kN", "-m", "1.1"),
         "Invalid value for '--exponent': a roller bearing (line contact) has m = 10/9"),
    ],
)  # fmt: skip
def test_options_a_command_does_not_take_are_refused_in_one_line(capsys, args, message):
    code, out, err = run_entry(capsys, *args)
    assert code == 2 and out == "" and err.count("\n") == 1 and err.startswith("Error: ")
    assert message in err, err


def test_domain_rules_live_in_the_bearings_package():
    """The exponent a bearing's contact needs and the picks of a clearance class were decided
    in the command line; the library now refuses them with its own InputError."""
    assert picks_of("range") == ("min", "mean", "max") and picks_of("min") == ("min",)
    low, mean, high = resolve_bearings("306", clearance="C3", clearance_pick="range")
    assert (low.clearance, high.clearance) == resolve_bearing("306", clearance="C3").clearance_range
    assert mean.clearance == pytest.approx(0.5 * (low.clearance + high.clearance))
    with pytest.raises(InputError, match="needs a clearance class") as info:
        resolve_bearings("306", clearance="20um", clearance_pick="range")
    assert info.value.parameter == "pick"
    with pytest.raises(InputError, match="has m = 10/9") as info:
        resolve_bearings("NU206", exponent=1.5)
    assert info.value.parameter == "exponent"
    check_exponent(resolve_bearing("NU206"), 10 / 9)  # its own exponent passes
    check_exponent(resolve_bearing("306"), None)  # not given: the bearing's own


# --- --tilt-radius -----------------------------------------------------------------------------
def test_tilt_radius_is_read_as_groove_pitch_or_a_length():
    assert parse_tilt_radius("groove") == "groove" and parse_tilt_radius(" PITCH ") == "pitch"
    assert parse_tilt_radius("20mm") == 20.0 and parse_tilt_radius("0.5in") == pytest.approx(12.7)
    assert parse_tilt_radius(None) is None
    assert tilt_lever("pitch", 43.5) == 21.75 and tilt_lever("groove", 43.5) is None
    for bad in ("0", "-1mm", "foo", "nan", "inf", "1e400", "20kN", 0.0, -3.0):
        with pytest.raises(InputError, match="must be groove, pitch or a length") as info:
            parse_tilt_radius(bad)
        assert info.value.parameter == "tilt_radius"


@pytest.mark.parametrize("value", ["0", "foo", "-2mm", "nan", "3kgf"])
def test_bad_tilt_radius_is_one_error_line(capsys, value):
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "-A", "1kN",
                               "--tilt-radius", value)  # fmt: skip
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith("Error: Invalid value for '--tilt-radius': must be groove, pitch or a")
    assert "Traceback" not in err


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("solve", "6205", "-F", "1kN", "--tilt-radius", "pitch"), "only the combined load"),
        (("sweep", "6205", "-F", "1kN", "--tilt-radius", "pitch"), "only the combined load"),
        (("solve", "6205", "-F", "1kN", "--moment-cross", "1e7Nm"),
         "Invalid value for '--moment-cross': tilts the inner ring by"),
        (("solve", "6205", "-F", "1kN", "-A", "500N", "--tilt-radius", "1um"),
         "Invalid value for '--tilt-radius': tilts the inner ring by"),
        (("solve", "6205", "-F", "1kN", "--moment-cross", "2kgf"), "Invalid value for '--moment-cross'"),
        (("solve", "6205", "-F", "1kN", "--moment-cross", "1Nm", "--method", "stribeck"),
         "exact model only"),
    ],
)  # fmt: skip
def test_tilt_options_where_they_mean_nothing_are_refused(capsys, args, message):
    code, out, err = run_entry(capsys, *args)
    assert code == 2 and out == "" and err.count("\n") == 1 and message in err, err


def test_tilt_radius_pitch_is_the_library_at_half_the_pitch_diameter():
    b = resolve_bearing("6205", clearance="C3")
    case = _case("6205", "-F", "1.4kN", "-A", "700N", "--moment", "3Nm", "-G", "C3",
                 "--moment-cross", "-1Nm", "--tilt-radius", "pitch")  # fmt: skip
    r = solve_combined(9, 1400.0, 700.0, ball_diameter=b.ball_diameter,
                       pitch_diameter=b.pitch_diameter, f_i=b.f_i, f_o=b.f_o,
                       clearance=b.clearance, moment=3000.0, moment_cross=-1000.0,
                       tilt_radius=b.pitch_diameter / 2)  # fmt: skip
    assert case["tilt_radius"] == b.pitch_diameter / 2 == 19.25
    assert case["moment_cross"] == -1000.0 and case["moment"] == 3000.0
    assert case["ball_loads"] == pytest.approx(r.ball_loads.tolist(), rel=1e-9)
    assert case["tilt"] == pytest.approx(float(r.tilt), rel=1e-9)
    assert case["tilt_cross"] == pytest.approx(float(r.tilt_cross), rel=1e-9)
    groove = _case("6205", "-F", "1.4kN", "-A", "700N", "--moment", "3Nm", "-G", "C3",
                   "--moment-cross", "-1Nm", "--tilt-radius", "groove")  # fmt: skip
    # the default lever, R_i = d_m/2 + (f_i - 1/2) D_w cos(alpha_0), reported as a number
    alpha0 = math.radians(groove["free_contact_angle"])
    r_i = b.pitch_diameter / 2 + (b.f_i - 0.5) * b.ball_diameter * math.cos(alpha0)
    assert groove["tilt_radius"] == pytest.approx(r_i, rel=1e-12)
    assert groove["tilt"] != pytest.approx(case["tilt"], rel=1e-4)


def test_a_length_lever_is_the_library_at_that_length():
    case = _case(*PEER, "-F", "1kN", "-A", "1kN", "-G", "10um", "--moment", "2Nm",
                 "--tilt-radius", "0.8in")  # fmt: skip
    r = solve_combined(7, 1000.0, 1000.0, ball_diameter=11.5, pitch_diameter=43.5,
                       clearance=0.01, modulus=210000.0, moment=2000.0, tilt_radius=20.32)  # fmt: skip
    assert case["tilt_radius"] == pytest.approx(20.32, rel=1e-12)
    assert case["ball_loads"] == pytest.approx(r.ball_loads.tolist(), rel=1e-9)


# --- --moment-cross ----------------------------------------------------------------------------
@pytest.mark.parametrize("load", ["0", "1kN"])
def test_moment_cross_alone_tilts_about_the_load_line_only(load):
    """F_r along the load line, a ball on it (the ball set mirror-symmetric about it), no axial
    load: the problem is the same with (a, theta) -> (-a, -theta), so a moment about the load
    line tilts the ring about the load line only."""
    case = _case("6205", "-F", load, "--moment-cross", "2Nm", "-q")
    assert case["method"] == "combined" and case["moment_cross"] == 2000.0
    assert case["tilt_cross"] > 0.1
    assert case["tilt"] == pytest.approx(0.0, abs=1e-12 * case["tilt_cross"])
    assert case["axial"] == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize(
    ("bearing", "cage"),
    [(("6205", "-G", "C3"), 0.0), (("6205", "-G", "C3"), 13.0), (PEER + ("-G", "10um"), 25.0)],
)
def test_moment_cross_is_the_moment_with_the_load_line_turned_90_degrees(bearing, cage):
    """With no radial load the load line is only the frame: M_cross at cage angle c is M at
    c - 90° (ball j at the same place), the tilts swap (theta = -theta_c'), the radial
    displacement turns (x = -y', y = x')."""
    common = (*bearing, "-F", "0", "-A", "800N", "-q")
    cross = _case(*common, "--moment-cross", "3Nm", "--cage-angle", str(cage))
    turned = _case(*common, "--moment", "3Nm", "--cage-angle", str(cage - 90.0))
    scale = max(cross["ball_loads"])
    assert cross["ball_loads"] == pytest.approx(turned["ball_loads"], abs=1e-9 * scale)
    assert cross["contact_angles"] == pytest.approx(turned["contact_angles"], abs=1e-9)
    assert cross["tilt_cross"] == pytest.approx(turned["tilt"], rel=1e-9)
    assert cross["tilt"] == pytest.approx(-turned["tilt_cross"], abs=1e-9 * abs(cross["tilt_cross"]))  # fmt: skip
    size = math.hypot(cross["x"], cross["y"])
    assert cross["x"] == pytest.approx(-turned["y"], abs=1e-9 * size + 1e-15)
    assert cross["y"] == pytest.approx(turned["x"], abs=1e-9 * size + 1e-15)
    assert cross["axial"] == pytest.approx(turned["axial"], rel=1e-9)
    assert cross["reference_rating_life"] == pytest.approx(
        turned["reference_rating_life"], rel=1e-9
    )


@pytest.mark.parametrize("example", [6, 7])
def test_masta_moment_about_the_load_line(example):
    """The peer's MASTA Examples 6 (M_x = 1000 N mm alone) and 7 (F_r, F_a and M_x): MASTA's
    settings are the constant ball stiffness at the nominal contact angle (--stiffness) and
    the tilt at the pitch radius (--tilt-radius pitch); total tilt and L10r within the
    tolerances of the library's own test (tests/test_combined.py)."""
    s_r, fr, fa, mx, _, _, tilt, life = PEER_ISO16281_MASTA[example]
    g = PEER_ISO16281_BEARING
    k = float(ball_stiffness(g["ball_diameter"], g["pitch_diameter"], g["f_i"], g["f_o"],
                             g["modulus"], g["poisson"]).ball)  # fmt: skip
    case = _case(*PEER, "-F", f"{fr}N", "-A", f"{fa}N", "--moment-cross", f"{mx}Nmm",
                 "-G", f"{s_r}mm", "-K", f"{k!r}", "--tilt-radius", "pitch", "-q")  # fmt: skip
    total = math.radians(math.hypot(case["tilt"], case["tilt_cross"])) * 1e3
    assert total == pytest.approx(tilt, rel=4e-5)
    assert case["reference_rating_life"] == pytest.approx(life, rel=3e-4)


def test_sweep_and_table_life_pass_the_general_load_through():
    """Every cage position of the sweep is the solve at that cage angle; every row of table
    life is the solve at that clearance: the cross moment and the lever reach both."""
    load = ("-F", "1kN", "-A", "300N", "--moment-cross", "2Nm", "--tilt-radius", "20mm")
    out = invoke("sweep", "6205", *load, "-G", "10um", "--steps", "3", "--format", "json")
    assert out.exit_code == 0, out.output
    doc = json.loads(out.stdout)
    assert doc["moment_cross"] == 2000.0 and doc["tilt_radius"] == 20.0
    row = doc["rows"][1]
    one = _case("6205", *load, "-G", "10um", "--cage-angle", str(row["cage_angle"]))
    assert row["tilt_cross"] == pytest.approx(one["tilt_cross"], rel=1e-9)
    assert row["q_max"] == pytest.approx(one["q_max"], rel=1e-9)
    out = invoke("table", "life", "-b", "6205", *load, "--clearances", "0,10um", "--format", "json")
    assert out.exit_code == 0, out.output
    doc = json.loads(out.stdout)
    assert doc["moment_cross"] == 2000.0 and doc["tilt_radius"] == 20.0
    at_zero = _case("6205", *load, "-G", "10um")  # table life: ball 1 on the load line
    life = doc["rows"][1]["reference_rating_life"]
    assert life == pytest.approx(at_zero["reference_rating_life"], rel=1e-9)
    assert doc["rows"][1]["q_max"] == pytest.approx(at_zero["q_max"], rel=1e-9)


def test_the_help_teaches_the_general_load():
    for name in ("solve", "sweep"):
        text = invoke(name, "--help").output
        assert "--moment-cross" in text and "--tilt-radius" in text
        assert "--tilt-radius pitch" in text  # an example uses it


def test_batch_columns_moment_cross_and_tilt_radius_are_the_options(tmp_path):
    """A batch row with moment_cross and tilt_radius is solve with --moment-cross and
    --tilt-radius (the same values); the columns are written only when the file has them; a
    bad lever skips its row naming the column."""
    path = tmp_path / "cases.csv"
    path.write_text(
        "bearing,load,axial_load,moment_cross,tilt_radius,clearance\n"
        "6205,1kN,500N,2Nm,pitch,C3\n6205,1kN,500N,,20mm,C3\n6205,1kN,500N,-1Nm,,C3\n"
        "6205,1kN,500N,2Nm,0,C3\n",
        encoding="utf-8",
    )
    out = invoke("batch", str(path), "--format", "json")
    assert out.exit_code == 1, out.output  # one row skipped
    doc = json.loads(out.stdout)
    assert [s["row"] for s in doc["skipped"]] == [5]
    assert doc["skipped"][0]["reason"].startswith("tilt_radius: must be groove, pitch or a length")
    options = [("--moment-cross", "2Nm", "--tilt-radius", "pitch"), ("--tilt-radius", "20mm"),
               ("--moment-cross", "-1Nm")]  # fmt: skip
    for row, extra in zip(doc["cases"], options, strict=True):
        one = _case("6205", "-F", "1kN", "-A", "500N", "-G", "C3", "-q", *extra)
        assert row["moment_cross"] == one.get("moment_cross")
        assert row["tilt_radius"] == one.get("tilt_radius")
        for key in ("q_max", "tilt", "tilt_cross", "reference_rating_life"):
            assert row[key] == pytest.approx(one[key], rel=1e-9, abs=1e-15), key
    plain = tmp_path / "plain.csv"
    plain.write_text("bearing,load,axial_load\n6205,1kN,500N\n", encoding="utf-8")
    head = invoke("batch", str(plain), "--format", "csv").stdout.splitlines()[0]
    assert "moment_cross" not in head and "tilt_radius [mm]" in head  # (the lever used)


@pytest.mark.parametrize(
    ("args", "refused", "named"),
    [
        (
            ("solve", "load", "-F", "1kN"),
            "cannot read 'load' as a bearing designation",
            "by hand: '--balls', '--ball-diameter'",
        ),
        (
            ("solve", "balls", "-F", "1kN"),
            "cannot read 'balls' as a bearing designation",
            "by hand: '--balls', '--ball-diameter'",
        ),
        (
            (
                "solve",
                "6205",
                "-F",
                "1kN",
                "--speed",
                "3000",
                "--oil",
                "balls",
                "--temperature",
                "70",
            ),
            "Invalid value for '--oil': unknown ISO 3448 grade 'balls'",
            "VG68",
        ),
    ],
)
def test_a_value_typed_that_is_a_parameter_name_is_quoted_as_typed(capsys, args, refused, named):
    """The library quotes the inputs it names and the value it refuses alike; the command line
    writes the names as options and leaves the value the user typed as it was typed."""
    code, out, err = run_entry(capsys, *args)
    assert code == 2 and out == ""
    assert refused in err
    assert named in err


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (
            ("solve", "-z", "8", "--ball-diameter", "10", "-F", "1kN"),
            "Missing option '--pitch-diameter' (the ball geometry needs it beside "
            "'--ball-diameter'; or give the ball stiffness '--stiffness' instead)",
        ),
        (
            ("solve", "--ball-diameter", "10", "--pitch-diameter", "40", "-F", "1kN"),
            "Missing option '--balls' / '-z' (the number of balls z; or give a 'BEARING' "
            "designation)",
        ),
        (
            ("solve", "6205", "-F", "1kN", "--speed", "3000", "--temperature", "70"),
            "Missing option '--oil' / '--viscosity-40': give the oil by its ISO 3448 grade",
        ),
        (
            ("solve", "6205", "-F", "1kN", "--oil", "VG68", "--temperature", "70"),
            "Invalid value for '--oil': needs the shaft speed ('--speed')",
        ),
        (
            ("table", "life", "-z", "7", "--ball-diameter", "11.5", "-F", "1kN"),
            "Missing option '--pitch-diameter'",
        ),
    ],
)
def test_a_missing_input_is_named_as_the_user_can_type_it(capsys, args, message):
    """A refusal for what is missing names that option, never one the user gave no reason to
    (--stiffness when half of the ball geometry is given, --viscosity beside an oil)."""
    code, out, err = run_entry(capsys, *args)
    assert code == 2 and out == ""
    assert err.startswith(f"Error: {message}"), err
    assert "'--viscosity'" not in err
