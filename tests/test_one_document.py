"""One bearing, one load, one result: the same keys, units and titles in every output."""

from __future__ import annotations

import csv
import json
import re
import shlex

import pytest

from tests.cli_helpers import invoke

#: solve under every path: hand-given radial, catalogue radial, every method, a roller bearing,
#: combined (catalogue, hand-given geometry, an imposed misalignment), the service lives.
SOLVES = (
    "solve -z 8 -F 300kgf -K 4700kgf/mm^1.5 -G 20um",
    "solve -z 8 -F 300kgf -K 4700kgf/mm^1.5 -G 20um --method all",
    "solve 306 -F 300kgf -G C3 --clearance-pick range",
    "solve NU206 -F 5kN",
    "solve 6205 -F 1kN --speed 1500",
    "solve 6205 -F 1.4kN -A 700N -G C3",
    "solve 6205 -F 1kN --misalignment 1mrad --moment-cross 500",
    "solve -z 7 --ball-diameter 11.5 --pitch-diameter 43.5 --modulus 210000 -F 0 -A 1kN "
    "-G 10um -C 23.4kN --rotating outer",
)
#: What a JSON case holds beyond the csv row: the per-ball arrays, the stiffness matrix, and the
#: texts (the model's description, the methods it ignores, the warnings: on stderr with csv).
NOT_IN_CSV = {
    "ball_angles",
    "contact_angles",
    "ball_approaches",
    "ball_loads",
    "contact_angles_inner",
    "contact_angles_outer",
    "ball_loads_inner",
    "ball_loads_outer",
    "stiffness_matrix",
    "stiffness_matrix_symmetric",
    "model",
    "ignores",
    "warnings",
}


def _out(command: str) -> str:
    result = invoke(*shlex.split(command))
    assert result.exit_code == 0, result.output
    return result.stdout


def _csv_keys(text: str) -> list[str]:
    header = next(csv.reader([text.splitlines()[0]]))
    return [re.sub(r" \[.*\]$", "", h) for h in header]


@pytest.mark.parametrize("command", SOLVES)
def test_solve_csv_carries_the_keys_of_its_json(command):
    document = json.loads(_out(command + " --format json"))
    json_keys = {k for case in document["cases"] for k in case} - NOT_IN_CSV
    csv_keys = _csv_keys(_out(command + " --format csv"))
    assert len(csv_keys) == len(set(csv_keys))
    # csv writes json's 5x5 stiffness_matrix entry by entry: stiffness_matrix_ij is [i-1][j-1]
    entries = [k for k in csv_keys if re.fullmatch(r"stiffness_matrix_\d\d", k)]
    assert set(csv_keys) - set(entries) == json_keys
    has_matrix = any("stiffness_matrix" in case for case in document["cases"])
    assert len(entries) == (25 if has_matrix else 0)
    combined = "misalignment" in document["cases"][0]
    assert ("misalignment" if combined else "epsilon") in csv_keys  # null in the JSON


@pytest.mark.parametrize("command", SOLVES)
def test_solve_csv_table_and_markdown_carry_the_stiffness_matrix_of_its_json(command):
    """Every output gives json's ``stiffness_matrix``: csv entry by entry,
    ``stiffness_matrix_ij`` = json's [i-1][j-1], null (what the radial engine does not
    determine) an empty cell; table and markdown a 'tangent stiffness matrix' per case that
    has all 25 entries, their shared note once, and the radial engine's 2x2 block as rows of
    its summary (one note naming them); a case without one (an approximate method) '-'."""
    document = json.loads(_out(command + " --format json"))
    rows = list(csv.DictReader(_out(command + " --format csv").splitlines()))
    assert len(rows) == len(document["cases"])
    matrices = [case.get("stiffness_matrix") for case in document["cases"]]
    for matrix, row in zip(matrices, rows, strict=True):
        cells = {re.sub(r" \[.*\]$", "", k): v for k, v in row.items()}
        for i in range(5):
            for j in range(5):
                value = None if matrix is None else matrix[i][j]
                cell = cells[f"stiffness_matrix_{i + 1}{j + 1}"]
                assert cell == "" if value is None else float(cell) == value, (i, j)
    blocks = sum(m is not None and m[2][2] is not None for m in matrices)  # all 25 solved
    radial = any(m is not None and m[2][2] is None for m in matrices)  # the 2x2 block
    for fmt in ("table", "markdown"):
        text = _out(f"{command} --format {fmt}")
        assert text.count("tangent stiffness matrix") == blocks + radial, fmt
        notes = text.count("json: stiffness_matrix, csv: stiffness_matrix_11")
        assert notes == min(blocks + radial, 1), fmt
        assert ("stiffness dF_y/d(y)" in text) == radial, fmt


def test_solve_per_ball_csv_names_the_same_inputs_for_every_case():
    """Per ball: the inputs the JSON carries (None ones blank), then the ball's values."""
    command = SOLVES[0] + " --per-ball"
    document = json.loads(_out(command + " --format json"))
    keys = _csv_keys(_out(command + " --format csv"))
    for key in ("bearing", "clearance_pick", "rotating"):
        assert key in document["cases"][0] and key in keys


#: Every JSON document of solve, sweep, table, batch and catalog the golden outputs hold.
JSON_COMMANDS = sorted(
    command
    for name, command in __import__("tests.golden_outputs", fromlist=["COMMANDS"]).COMMANDS.items()
    if name.split("_")[0] in ("solve", "sweep", "table", "batch", "catalog")
)


def _numbers(value) -> bool:
    if isinstance(value, bool) or value is None:
        return False
    if isinstance(value, int | float):
        return True
    return isinstance(value, list) and bool(value) and all(_numbers(v) for v in value)


def _has_float(value) -> bool:
    return isinstance(value, float) or (isinstance(value, list) and any(map(_has_float, value)))


def _unitless(obj, units: dict, parent: str = "") -> list[str]:
    """The numeric keys of ``obj`` without a unit: a float (or array) needs its key (or, in a
    spread like ``summary.q_max.min``, its parent's key) in the nearest ``units``, unless its
    object names its own ``unit`` (the bearing's geometry entries); an integer without a unit
    must be a count (a quantity whose unit is "")."""
    from bearingload.reports.quantities import QUANTITIES

    missing = []
    if isinstance(obj, list):
        for item in obj:
            missing += _unitless(item, units, parent)
    elif isinstance(obj, dict):
        units = obj["units"] if isinstance(obj.get("units"), dict) else units
        for key, value in obj.items():
            if key == "units":
                continue
            if not _numbers(value):
                missing += _unitless(value, units, key)
            elif key in units or parent in units or "unit" in obj:
                continue
            elif QUANTITIES.get(parent, QUANTITIES["load"]).unit == "":
                continue  # the spread of a count (loaded balls: mean 7.4)
            elif _has_float(value) or QUANTITIES.get(key, QUANTITIES["load"]).unit != "":
                missing.append(key)
    return missing


def _units_maps(obj):
    if isinstance(obj, dict):
        if isinstance(obj.get("units"), dict):
            yield obj["units"]
        for value in obj.values():
            yield from _units_maps(value)
    elif isinstance(obj, list):
        for item in obj:
            yield from _units_maps(item)


@pytest.mark.parametrize("command", JSON_COMMANDS)
def test_every_number_of_every_json_document_has_its_unit(command):
    """One rule: the unit of every measured quantity, '-' for a dimensionless one; counts
    (balls, loaded balls, rows) are not listed. The unit is the quantity's own (but the
    combined stiffness matrix's, spelled out, and those of Kurochkin's P = K = 1 sweep)."""
    from bearingload.reports.quantities import QUANTITIES

    document = json.loads(_out(command + " --format json"))
    assert _unitless(document, {}) == []
    for unit_map in _units_maps(document):
        for key, unit in unit_map.items():
            matrix = key in ("stiffness_matrix", "stiffness_matrix_symmetric")
            if matrix or key == "clearance" or "kurochkin" in command:
                continue
            if key in QUANTITIES and "^m" not in QUANTITIES[key].unit:
                assert unit == QUANTITIES[key].unit, (key, unit)


def test_solve_json_lists_the_dimensionless_quantities_batch_lists():
    document = json.loads(_out(SOLVES[2] + " --format json"))
    for key in ("k", "K_Q", "epsilon", "static_safety", "exponent", "relative_error"):
        assert document["units"].get(key, "-") == "-"
    for key in ("k", "K_Q", "static_safety", "exponent"):
        assert document["units"][key] == "-"


def test_stability_json_is_one_document_with_both_kinds_under_keys():
    text = _out("stability --family preload --family combined_preload --format json")
    document = json.loads(text)
    assert isinstance(document, dict) and list(document) == ["radial", "combined"]
    assert document["radial"]["rows"][0]["family"] == "preload"
    assert document["combined"]["rows"][0]["family"] == "combined_preload"
    assert document["radial"]["units"]["max_residual"] == "-"
    only = json.loads(_out("stability --family preload --format json"))
    assert list(only) == ["radial"]


@pytest.mark.parametrize(
    "command",
    ["solve 6205 -F 1.4kN -A 700N -G C3", "solve 6205 -F 1.4kN -G C3", "solve NU206 -F 5kN"],
)
def test_solve_plot_titles_name_the_bearing(command, monkeypatch, tmp_path):
    from tests.cli_helpers import drawn

    figures = drawn(monkeypatch)
    _out(f"{command} --plot {tmp_path / 'p.png'}")
    (fig,) = figures
    title = fig.get_axes()[0].get_title()
    name = command.split()[1]
    assert title.startswith(f"{name}: Ball loads"), title


def test_hand_given_plot_title_names_no_bearing(monkeypatch, tmp_path):
    from tests.cli_helpers import drawn

    figures = drawn(monkeypatch)
    _out(f"{SOLVES[-1]} --plot {tmp_path / 'p.png'}")
    assert figures[0].get_axes()[0].get_title().startswith("Ball loads, 3-D ring equilibrium")


def _library_error_texts():
    """(file, parameter, texts) of every ``InputError(...)`` of the modules below cli/: the
    parameter given and every string the call's arguments hold (module constants included)."""
    import ast
    from pathlib import Path

    package = Path(__file__).resolve().parents[1] / "bearingload"
    for path in sorted(package.rglob("*.py")):
        if "cli" in path.relative_to(package).parts:
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        constants = {
            t.id: node.value
            for node in tree.body
            if isinstance(node, ast.Assign)
            for t in node.targets
            if isinstance(t, ast.Name)
        }
        for call in ast.walk(tree):
            name = getattr(call, "func", None)
            if not (isinstance(call, ast.Call) and getattr(name, "id", "") == "InputError"):
                continue
            nodes = [n for a in call.args for n in ast.walk(a)]
            nodes += [n for n in nodes if isinstance(n, ast.Name) for n in [constants.get(n.id)]]
            texts = [
                n.value
                for m in nodes
                if m is not None
                for n in ast.walk(m)
                if isinstance(n, ast.Constant) and isinstance(n.value, str)
            ]
            first = call.args[0] if call.args else None
            parameter = first.value if isinstance(first, ast.Constant) else None
            yield path.name, parameter, texts


def test_library_errors_name_library_parameters_not_options():
    found = list(_library_error_texts())
    assert len(found) > 100  # the scan sees the package's errors
    for where, parameter, texts in found:
        if isinstance(parameter, str):
            assert re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", parameter), (where, parameter)
        assert not [t for t in texts if re.search(r"--[a-z]", t)], (where, texts)


def test_roller_errors_name_the_library_parameters_and_the_cli_its_options():
    from bearingload.bearings.rollers import line_contact_pressure, lookup
    from bearingload.errors import InputError

    for kwargs, parameter in (
        ({"roller_length": -1.0}, "roller_length"),
        ({"roller_diameter": 100.0}, "roller_diameter"),
        ({"rollers": 40}, "rollers"),
        ({"pitch_diameter": 10.0}, "pitch_diameter"),
    ):
        with pytest.raises(InputError) as caught:
            lookup("NU206", **kwargs)
        assert caught.value.parameter == parameter
    with pytest.raises(InputError) as caught:
        line_contact_pressure(100.0, 0.0, 9.0, 46.5)
    assert caught.value.parameter == "roller_length"
    for option, value in (("--ball-diameter", "100"), ("--balls", "40")):
        result = invoke("solve", "NU206", "-F", "5kN", option, value)
        assert result.exit_code == 2
        assert f"Invalid value for '{option}'" in result.output, result.output


@pytest.mark.parametrize("method", ["exact", "continuum", "stribeck", "palmgren"])
def test_the_case_of_a_result_keeps_the_scalar_contract(method):
    import numpy as np

    from bearingload.models.registry import compute, compute_all

    case = compute(method, 8, 1000.0, 1e5, 0.01, 7.0).case
    for name in ("load", "stiffness", "clearance", "cage_angle", "exponent"):
        assert type(getattr(case, name)) is float, (name, type(getattr(case, name)))
    assert type(case.balls) is int and case.cage_angle == 7.0
    assert type(compute_all(8, 1000.0, 1e5, cage_angle=370.0)[method].case.cage_angle) is float
    many = compute(method, 8, [1000.0, 2000.0], 1e5, 0.0, [1.0, 2.0]).case
    assert isinstance(many.load, np.ndarray) and isinstance(many.cage_angle, np.ndarray)
    assert many.shape == (2,)


LOOSE = (
    "solve -z 9 --ball-diameter 7.938 --pitch-diameter 38.5 -F 1kN -A 10N -G 0.5mm --misalignment 0"
)


def test_a_loose_ball_shows_no_contact_angle_in_the_table_and_a_number_in_json():
    """Balls whose groove centres crossed carry nothing: the library's number for them is ±90°
    (their groove-centre line), which the table must not print as a contact angle."""
    import math

    document = json.loads(_out(LOOSE + " --format json"))["cases"][0]
    loads, alphas = document["ball_loads"], document["contact_angles"]
    assert all(isinstance(a, float) and math.isfinite(a) for a in alphas)  # never NaN
    assert any(q == 0.0 and abs(a) == 90.0 for q, a in zip(loads, alphas, strict=True))
    table = _out(LOOSE)
    rows = table.split("Ball loads (ball 1")[1].splitlines()[4:13]
    for line, q, a in zip(rows, loads, alphas, strict=True):
        shown = line.split()[2]
        assert shown == ("-" if q == 0.0 else f"{a:.6g}"), line
    assert "Contact angle '-': the ball carries no load" in table


def test_a_loose_ball_has_no_point_in_the_contact_angle_panel(monkeypatch, tmp_path):
    import numpy as np

    from tests.cli_helpers import drawn

    figures = drawn(monkeypatch)
    document = json.loads(_out(f"{LOOSE} --format json --plot {tmp_path / 'p.png'}"))["cases"][0]
    (line,) = figures[0].get_axes()[1].get_lines()
    loaded = np.asarray(document["ball_loads"]) > 0
    y = np.asarray(line.get_ydata(), dtype=float)
    assert np.isnan(y[~loaded]).all() and np.isfinite(y[loaded]).all()


def test_the_combined_reference_speaks_the_vocabulary():
    """Its columns are the quantities' keys with their units (``load [N]``, ``misalignment
    [°]``), the generator writes the header the file has, and the reader reads it."""
    import importlib.util
    from pathlib import Path

    from bearingload.quality import accuracy
    from bearingload.reports.quantities import QUANTITIES

    path = Path(__file__).resolve().parents[1] / "benchmarks" / "make_combined_reference.py"
    spec = importlib.util.spec_from_file_location("make_combined_reference", path)
    generator = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(generator)
    with open(accuracy.COMBINED_REFERENCE_FILE, encoding="utf-8") as fh:
        header = fh.readline().rstrip("\n")
    assert header == generator.HEADER
    named = 0
    for column in header.split(","):
        key, _, unit = column.partition(" [")
        assert key != "radial_load" and unit != "deg]", column
        if key in QUANTITIES:
            assert unit.rstrip("]") == QUANTITIES[key].unit, column
            named += 1
    assert named >= 12
    cases = accuracy.combined_cases()
    assert [c["misalignment"] for c in cases][-2:] == [0.05, 0.0]
    assert cases[0]["radial_load"] == 1000.0 and cases[3]["radial_load"] == 0.0
