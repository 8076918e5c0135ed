"""The oil's viscosity at its operating temperature: ISO 3448 grades and ASTM D341 (Walther),
against published worked examples and an independent mpmath implementation; the CLI options."""

from __future__ import annotations

import csv
import io
import random

import mpmath
import pytest
from click.testing import CliRunner

from bearingload.bearings.oil import (
    ISO_VG,
    iso_grade,
    viscosity_at,
    walther_constants,
    walther_viscosity,
)
from bearingload.cli import main
from bearingload.errors import InputError

from .cli_helpers import run_entry


def test_walther_reproduces_the_worked_example_of_a_published_d341_calculator():
    """'Viscosity vs Temperature Calculator' (scribd 361017004, from ASTM D341): 32 cSt at 40 °C,
    5.4 cSt at 100 °C with T = t + 273: A = 9.5259, B = 3.7449, 8.5 cSt at 80 °C."""
    a, b = walther_constants(32.0, 313.0, 5.4, 373.0)
    assert round(a, 4) == 9.5259 and round(b, 4) == 3.7449
    assert round(walther_viscosity(a, b, 353.0), 1) == 8.5


def test_walther_reproduces_olezols_d341_examples():
    """olezol.com, 'Viscosity-temperature extrapolation ASTM D341': SAE 140 gear oil, 404 cSt at
    40 °C and 28 cSt at 100 °C: 132.126 cSt at 60 °C; an oil of 68 cSt at 40 °C and 14.85 cSt
    at 80 °C: 8.8 cSt at 100 °C (T = t + 273.15)."""
    assert round(viscosity_at(404.0, 28.0, 60.0), 3) == 132.126
    a, b = walther_constants(68.0, 313.15, 14.85, 353.15)
    assert round(walther_viscosity(a, b, 373.15), 1) == 8.8


def _walther_mp(nu40: float, nu100: float, t: float) -> float:
    """Independent: solve log log(nu + 0.7) = A - B log T for A, B by mpmath's linear solver."""
    mpmath.mp.dps = 40
    ll = [mpmath.log10(mpmath.log10(mpmath.mpf(n) + mpmath.mpf("0.7"))) for n in (nu40, nu100)]
    k = [mpmath.log10(mpmath.mpf(c) + mpmath.mpf("273.15")) for c in (40, 100)]
    a, b = mpmath.lu_solve(mpmath.matrix([[1, -k[0]], [1, -k[1]]]), mpmath.matrix(ll))
    y = a - b * mpmath.log10(mpmath.mpf(t) + mpmath.mpf("273.15"))
    return float(mpmath.power(10, mpmath.power(10, y)) - mpmath.mpf("0.7"))


def test_walther_against_mpmath_and_through_its_two_points():
    rng = random.Random(20)
    for _ in range(300):
        nu40 = 10 ** rng.uniform(0.7, 3.5)
        nu100 = max(2.0, nu40 / rng.uniform(2.0, 15.0))
        t = rng.uniform(-20.0, 150.0)
        assert viscosity_at(nu40, nu100, 40.0) == pytest.approx(nu40, rel=1e-12)
        assert viscosity_at(nu40, nu100, 100.0) == pytest.approx(nu100, rel=1e-12)
        if _walther_mp(nu40, nu100, t + 1.0) < 2.0:  # beyond the form's range: refused
            with pytest.raises(InputError, match="2 mm\\^2/s or more"):
                viscosity_at(nu40, nu100, t + 1.0)
            continue
        assert viscosity_at(nu40, nu100, t) == pytest.approx(_walther_mp(nu40, nu100, t), rel=1e-9)
        assert viscosity_at(nu40, nu100, t + 1.0) < viscosity_at(nu40, nu100, t)


def test_iso_grades():
    """ISO 3448: the grade's number is its mid-point viscosity at 40 °C (2.2 ... 3200)."""
    assert len(ISO_VG) == 20
    assert iso_grade("VG68") == iso_grade("ISO VG 68") == iso_grade("68") == 68.0
    assert iso_grade("vg2") == 2.2 and iso_grade("VG5") == 4.6
    with pytest.raises(InputError, match="unknown ISO 3448 grade 'VG67'"):
        iso_grade("VG67")


def test_refusals():
    with pytest.raises(InputError, match="below the viscosity at 40"):
        viscosity_at(68.0, 80.0, 70.0)
    with pytest.raises(InputError, match="2 mm\\^2/s or more"):
        viscosity_at(68.0, 1.5, 70.0)


@pytest.mark.parametrize(
    ("nu_40", "nu_100", "celsius"),
    [(68.0, 8.5, 200.0), (68.0, 2.0, 250.0), (9e5, 2.0, -60.0)],
)
def test_a_temperature_where_walther_leaves_its_range_is_refused(nu_40, nu_100, celsius):
    """VG68 with nu_100 = 8.5 at 200 °C gives 1.83 mm^2/s, below the 2 mm^2/s the plain
    Walther form covers (was returned silently); nu_40 = 9e5 at -60 °C overflowed to infinity,
    refused later as a bad --viscosity the user never gave."""
    with pytest.raises(InputError) as info:
        viscosity_at(nu_40, nu_100, celsius)
    assert info.value.parameter == "temperature" and "2 mm^2/s" in str(info.value)


def _csv(*args: str) -> dict[str, str]:
    out = CliRunner().invoke(main, ["solve", *args, "--format", "csv"], catch_exceptions=False)
    assert out.exit_code == 0, out.output
    return next(csv.DictReader(io.StringIO(out.stdout)))


def test_solve_with_the_oil_equals_solve_with_its_viscosity():
    base = ["6205", "-F", "1.4kN", "--speed", "3000"]
    nu = viscosity_at(68.0, 8.6, 70.0)
    by_grade = _csv(*base, "--oil", "VG68", "--viscosity-100", "8.6cSt", "--temperature", "70C")
    by_value = _csv(*base, "--viscosity-40", "68", "--viscosity-100", "8.6", "--temperature",
                    "343.15K")  # fmt: skip
    given = _csv(*base, "--viscosity", repr(nu))
    assert by_grade == by_value == given
    assert float(given["viscosity [mm^2/s]"]) == pytest.approx(19.966, abs=1e-3)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--oil", "VG68", "--viscosity-100", "8.6"], "Missing option '--temperature'"),
        (["--oil", "VG68", "--temperature", "70"], "Missing option '--viscosity-100'"),
        (["--oil", "VG67", "--viscosity-100", "8.6", "--temperature", "70"], "'--oil'"),
        (["--viscosity", "20", "--oil", "VG68"], "--oil cannot be used with --viscosity"),
        (["--oil", "VG68", "--viscosity-40", "60", "--viscosity-100", "8", "--temperature", "70"],
         "'--oil' / '--viscosity-40'"),
        (["--oil", "VG68", "--viscosity-100", "80", "--temperature", "70"], "'--viscosity-100'"),
        (["--oil", "VG68", "--viscosity-100", "8.6", "--temperature", "400"], "'--temperature'"),
    ],
)  # fmt: skip
def test_bad_oil_options_are_one_error_line(args, message, capsys):
    code, out, err = run_entry(capsys, "solve", "6205", "-F", "1kN", "--speed", "3000", *args)
    assert code == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("Error: ") and message in lines[0], lines
