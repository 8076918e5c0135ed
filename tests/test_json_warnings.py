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
