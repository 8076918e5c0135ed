"""Warnings on solved cases: static safety, load above C0, contact pressure, one element, clearance."""

from __future__ import annotations

import pytest

from bearingload.bearings.checks import (
    P_MAX_BALL,
    P_MAX_ROLLER,
    case_warnings,
    max_contact_pressures,
)
from bearingload.bearings.resolve import resolve_bearing
from bearingload.contact.hertz import ball_contacts
from bearingload.models.equilibrium import solve


def _warn(designation: str | None, load: float, **kwargs: object) -> list[str]:
    b = resolve_bearing(designation, **kwargs)  # type: ignore[arg-type]
    r = solve(b.balls, load, b.stiffness, b.clearance, 0.0, b.exponent)
    return case_warnings(b, load, r)


@pytest.mark.parametrize(
    ("designation", "load", "kwargs"),
    [
        ("6205", 5000.0, {"clearance": "C3"}),
        ("306", 300 * 9.80665, {"clearance": "20um"}),
        ("6004", 1000.0, {}),
        ("61806", 500.0, {}),
        ("16005", 1000.0, {}),
        ("NU206", 5000.0, {}),
        ("6205", 5000.0, {"clearance": "-20um"}),  # light preload
        (None, 1000.0, {"balls": 9, "stiffness": 3e5, "clearance": "10um"}),
    ],
)
def test_sane_cases_carry_no_warning(designation, load, kwargs) -> None:
    assert _warn(designation, load, **kwargs) == []


def test_overload_6205() -> None:
    w = _warn("6205", 500e3)
    assert len(w) == 3
    assert w[0].startswith("static safety factor s0 = C0/P0 = 0.0157 is below 1")
    assert w[1] == "the load F_r = 500000 N is above the basic static rating C0 = 7850 N"
    assert w[2].startswith("maximum contact pressure 16133 MPa (inner contact")
    assert "above 4200 MPa" in w[2]


def test_pressure_threshold_ball_and_roller() -> None:
    b = resolve_bearing("6205", clearance="C3")
    # a load whose heaviest ball sits between the roller and the ball limits: no warning
    load = 7700.0
    r = solve(b.balls, load, b.stiffness, b.clearance)
    p = max(max_contact_pressures(b, float(r.q_max)) or (0.0,))
    assert P_MAX_ROLLER < p < P_MAX_BALL
    assert case_warnings(b, load, r) == []
    # the same pressure check uses Hertz exactly
    c = ball_contacts(float(r.q_max), b.ball_diameter, b.pitch_diameter, b.f_i, b.f_o)
    assert p == pytest.approx(float(c.inner.p_max), rel=1e-15)
    w = _warn("NU206", 60e3)
    assert any("above 4000 MPa" in x and "roller" in x for x in w)


def test_one_ball() -> None:
    w = _warn(None, 10.0, balls=9, stiffness=3e5, clearance="50um")
    assert w == [
        "only one ball carries the load: the result hangs on a single contact (large clearance "
        "or few elements); check the clearance"
    ]
    assert _warn(None, 10.0, balls=1, stiffness=3e5) == []  # one ball is all there is


def test_clearance_range() -> None:
    w = _warn("6205", 5000.0, clearance="0.2mm")
    assert w == [
        "radial clearance G_r = 200 µm is above the largest class of ISO 5753-1 (C5 max 53 µm "
        "at d = 25 mm): no deep groove ball bearing of this bore has so much play"
    ]
    assert _warn("6205", 5000.0, clearance="53um") == []  # C5 max itself
    w = _warn("6205", 5000.0, clearance="-60um")
    assert w == [
        "preload G_r = -60 µm is deeper than 53 µm (the C5 maximum of ISO 5753-1 at d = 25 mm, "
        "this package's bound): check the fits"
    ]
    assert _warn("6205", 5000.0, clearance="-53um") == []
