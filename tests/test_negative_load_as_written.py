"""A negative radial load is refused naming the value as the user wrote it (``-1 kN``, also a
``-1`` in a ``[kN]`` column of a batch file), not converted to N (``-1000.0 N``), by the one
rule of the command line, the library and batch (plan.case.LOAD_RULE)."""

import pytest

from bearingload import analyse
from bearingload.errors import InputError

from .cli_helpers import invoke, run_entry

RULE = "must be greater than 0 N, or 0 with an axial load or a moment"


@pytest.mark.parametrize(
    ("text", "written"),
    [
        ("bearing,load [kN],axial_load [kN]\n6205,-1,0.1\n6205,1,0.1\n", "-1 kN"),
        ("bearing,load,axial_load\n6205,-1kN,100N\n6205,1kN,100N\n", "-1 kN"),
        ("bearing,load,axial_load\n6205,-5,100N\n6205,1kN,100N\n", "-5 N"),
    ],
)
def test_batch_names_a_negative_load_as_written(tmp_path, text, written):
    path = tmp_path / "cases.csv"
    path.write_text(text, encoding="utf-8")
    out = invoke("batch", str(path), "--format", "csv")
    assert f"Skipped: row 2: load: {RULE} (got {written})" in out.stderr
    assert "1000" not in out.stderr.splitlines()[0]


def test_solve_and_analyse_name_a_negative_load_as_written(capsys):
    code, _, err = run_entry(capsys, "solve", "6205", "-F", "-1kN")
    assert code == 2 and f"'--load': {RULE} (got -1 kN)" in err
    with pytest.raises(InputError) as info:
        analyse("6205", load="-1kN", axial_load="300N")
    assert str(info.value) == f"load: {RULE} (got -1 kN)"
    with pytest.raises(InputError) as info:
        analyse("6205", load=-5)
    assert str(info.value) == f"load: {RULE} (got -5 N)"


def test_a_load_of_0_is_refused_only_without_an_axial_load():
    """0 is the radial load of a pure thrust; alone it is refused by the radial engine."""
    assert analyse("6205", load=0, axial_load="300N").engine == "combined"
    with pytest.raises(InputError, match="must be greater than 0 N"):
        analyse("6205", load=0)


def test_a_negative_preload_is_refused_as_written(tmp_path):
    """A pair's preload in a '[kN]' column (or -0.1kN on the command line): as written too."""
    path = tmp_path / "pairs.csv"
    path.write_text("bearing,load,axial_load,preload [kN]\n7205BDB,1kN,100N,-1\n", encoding="utf-8")
    out = invoke("batch", str(path), "--format", "csv")
    assert "Skipped: row 2: preload: must be 0 N or more (got -1 kN)" in out.stderr
    err = invoke("solve", "7205BDB", "-F", "1kN", "--preload=-0.1kN").stderr
    assert err.strip().endswith("must be 0 N or more (got -0.1 kN)")


PLAIN = "must be greater than 0 N (got"


@pytest.mark.parametrize(
    "args",
    [
        ("table", "k", "-F", "-1kN"),
        ("table", "kq", "-F", "-1kN", "--bearing", "6205"),
        ("solve", "NU206", "-F", "-1kN"),
        ("solve", "-z", "9", "-K", "1e5", "-F", "-1kN"),
        ("sweep", "-z", "9", "-K", "1e5", "-F", "-1kN"),
    ],
)
def test_no_way_out_by_an_axial_load_where_none_can_be_given(capsys, args):
    """table k and kq take no axial load or moment, nor does a roller bearing or a ring given
    by z and K: a negative load is refused by 'greater than 0 N' alone."""
    code, _, err = run_entry(capsys, *args)
    assert code == 2 and err.strip().endswith(f"'--load': {PLAIN} -1 kN)"), err
    assert "axial" not in err


def test_the_library_and_batch_offer_the_way_out_by_the_bearing(tmp_path):
    with pytest.raises(InputError) as info:
        analyse("NU206", load="-1kN")
    assert str(info.value) == f"load: {PLAIN} -1 kN)"
    with pytest.raises(InputError) as info:
        analyse(None, balls=9, stiffness=1e5, load=-2)
    assert str(info.value) == f"load: {PLAIN} -2 N)"
    path = tmp_path / "cases.csv"
    path.write_text(
        "bearing,balls,stiffness,load [kN]\nNU206,,,-1\n6206,,,-1\n,9,1e5,-1\n", encoding="utf-8"
    )
    err = invoke("batch", str(path), "--format", "csv").stderr
    assert f"row 2: load: {PLAIN} -1 kN)" in err and f"row 4: load: {PLAIN} -1 kN)" in err
    assert f"row 3: load: {RULE} (got -1 kN)" in err


@pytest.mark.parametrize(("load", "written"), [("-0kN", "0 kN"), ("-0", "0 N"), ("0", "0 N")])
def test_a_load_of_0_is_refused_as_a_negative_one_is(capsys, load, written):
    """-F -0kN (0 with no axial load) and -F -1kN: the same option name and the same rule, the
    value as typed (-0 as 0)."""
    _, _, negative = run_entry(capsys, "solve", "6205", "-F", "-1kN")
    code, _, zero = run_entry(capsys, "solve", "6205", "-F", load)
    assert code == 2 and zero == negative.replace("(got -1 kN)", f"(got {written})")


def test_a_load_of_minus_0_is_echoed_as_0(tmp_path):
    """-0 (with an axial load, a load of 0) is written 0, not -0: the text's F_r, csv's and
    json's load, a batch row's load, the library's case."""
    import json

    text = invoke("solve", "6206", "-F", "-0kN", "-A", "1kN").stdout
    assert "F_r = 0 N," in text and "-0" not in text.splitlines()[0]
    row = invoke("solve", "6206", "-F", "-0", "-A", "1kN", "--format", "csv").stdout
    assert row.splitlines()[1].split(",")[3] == "0.0"
    doc = json.loads(invoke("solve", "6206", "-F", "-0", "-A", "1kN", "--format", "json").stdout)
    assert str(doc["cases"][0]["load"]) == "0.0"
    path = tmp_path / "cases.csv"
    path.write_text("bearing,load,axial_load\n6206,-0,1kN\n6206,-0kN,1kN\n", encoding="utf-8")
    out = invoke("batch", str(path), "--format", "csv").stdout
    assert [line.split(",")[4] for line in out.splitlines()[1:]] == ["0.0", "0.0"]
    assert (
        str(analyse("6206", load="-0kN", axial_load="1kN").to_dict()["cases"][0]["load"]) == "0.0"
    )


def test_batch_and_analyse_many_refuse_a_load_of_0_as_solve_does(tmp_path, capsys):
    """A radial case's load of 0 is refused by the plan's check, as solve -F 0 refuses it and a
    negative load is refused (the option's rule, the value as typed), not by the solver."""
    from bearingload import analyse_many

    path = tmp_path / "cases.csv"
    path.write_text(
        "bearing,balls,stiffness,load\n6205,,,0\n6205,,,-1\n6205,,,0kN\n,9,1e5,-0\n",
        encoding="utf-8",
    )
    err = invoke("batch", str(path), "--format", "csv").stderr
    _, _, solve = run_entry(capsys, "solve", "6205", "-F", "0")
    assert solve.strip().endswith(f"'--load': {RULE} (got 0 N)")
    assert f"row 2: load: {RULE} (got 0 N)" in err and f"row 3: load: {RULE} (got -1 N)" in err
    assert f"row 4: load: {RULE} (got 0 kN)" in err and f"row 5: load: {PLAIN} 0 N)" in err
    many = analyse_many([{"bearing": "6205", "load": 0}, {"bearing": "6205", "load": "0kN"}])
    assert [str(e) for e in many.errors.values()] == [
        f"load: {RULE} (got 0 N)",
        f"load: {RULE} (got 0 kN)",
    ]
    assert not analyse_many([{"bearing": "6205", "load": 0, "axial_load": 100}]).errors
