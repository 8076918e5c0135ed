"""The json ``warnings`` hold every warning solve prints on standard error for the case,
those of the lives included (a kappa outside ISO 281's a_ISO range was printed but missing
from the json, for one bearing, the combined engine and a pair)."""

from __future__ import annotations

import json

import pytest

from .cli_helpers import run_entry

LIFE = ("--speed", "3000", "--viscosity", "1")


@pytest.mark.parametrize(
    "case",
    [
        ("6205", "-F", "1kN"),
        ("6205", "-F", "1kN", "-A", "100N"),
        ("7205BDB", "--preload", "500N", "-F", "2kN", "-A", "1kN"),
    ],
)
def test_json_warnings_are_the_printed_ones(capsys, case):
    code, text, err = run_entry(capsys, "solve", *case, *LIFE, "--format", "json")
    assert code == 0, err
    printed = [line.removeprefix("Warning: ") for line in err.splitlines()]
    assert any("kappa" in w for w in printed)
    doc = json.loads(text)
    assert doc["warnings"] == printed
    assert set(doc["cases"][0]["warnings"]) <= set(printed)
    assert any("kappa" in w for w in doc["cases"][0]["warnings"])


@pytest.mark.parametrize("axial", [(), ("-A", "100N")])
def test_json_document_warnings_of_several_cases_are_the_printed_ones(capsys, axial):
    """Three clearances of a class (--clearance-pick range) under an overload and a film too thin:
    the document's warnings are the printed lines, in their order, each once (the radial json listed
    each case's pressure warning twice, with and without its clearance's label)."""
    case = ("6205", "-F", "500kN", "-G", "C3", "--clearance-pick", "range", *axial, *LIFE)
    code, text, err = run_entry(capsys, "solve", *case, "--format", "json")
    assert code == 0, err
    printed = [line.removeprefix("Warning: ") for line in err.splitlines()]
    assert any("kappa" in w for w in printed) and any("pressure" in w for w in printed)
    doc = json.loads(text)
    assert doc["warnings"] == printed == list(dict.fromkeys(printed))
    assert len(doc["cases"]) == 3
