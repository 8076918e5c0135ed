"""Hybrid bearings (--ball-material, ball_material): silicon-nitride balls on steel rings.

The contact of two materials depends on them only through 1/E* = (1 - nu1^2)/E1 +
(1 - nu2^2)/E2 (Johnson, Contact Mechanics, eq. 4.22; Harris & Kotzalas); the bearing carries
one equivalent (E, nu) pair with that E* (bearingload.contact.hertz.equivalent_material), so
the models, the pressures and the film see the hybrid's contact.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingload.bearings.checks import contact_pressures
from bearingload.bearings.materials import BALL_MATERIALS, ball_material
from bearingload.bearings.resolve import resolve_bearing
from bearingload.contact.hertz import equivalent_material, point_contact, reduced_modulus
from bearingload.errors import InputError
from tests.cli_helpers import invoke


@pytest.mark.parametrize(
    ("e_r", "nu_r", "e_b", "nu_b"),
    [(208000.0, 0.3, 310000.0, 0.26), (200000.0, 0.28, 90000.0, 0.2), (1e5, 0.0, 4e5, 0.5)],
)
def test_equivalent_pair_has_the_contact_modulus_of_the_two_materials(e_r, nu_r, e_b, nu_b):
    e, nu = equivalent_material(e_r, nu_r, e_b, nu_b)
    by_hand = 1.0 / ((1 - nu_r**2) / e_r + (1 - nu_b**2) / e_b)  # independent of the helper
    assert float(reduced_modulus(e, nu)) == pytest.approx(by_hand, rel=1e-14)
    # a contact of the equivalent pair equals the contact of the two bodies, field by field
    one = point_contact(0.2, 0.05, 500.0, e, nu)
    two = point_contact(0.2, 0.05, 500.0, e_star=by_hand)
    for a, b in zip(one, two, strict=True):
        assert float(a) == pytest.approx(float(b), rel=1e-13)


def test_balls_of_the_rings_material_keep_the_rings_pair_exactly():
    assert equivalent_material(208000.0, 0.3, 208000.0, 0.3) == (208000.0, 0.3)
    steel = resolve_bearing("6205", ball_material="steel")
    plain = resolve_bearing("6205")
    assert (steel.modulus, steel.poisson, steel.stiffness) == (
        plain.modulus, plain.poisson, plain.stiffness)  # fmt: skip


def test_silicon_nitride_raises_pressure_and_stiffness_by_the_hertz_scaling():
    """At the same ball load p_max scales as E*^(2/3) and the contact stiffness as E*
    (Hertz: a ~ (Q/E*)^(1/3), p_max ~ Q/a^2, delta ~ (Q/E*)^(2/3)): about 12 % more
    pressure for silicon nitride on steel."""
    steel, hybrid = resolve_bearing("6205"), resolve_bearing("6205", ball_material="si3n4")
    si = BALL_MATERIALS["si3n4"]
    ratio = (1 / (2 * (1 - 0.3**2) / 208000.0)) ** -1 * (
        (1 - 0.3**2) / 208000.0 + (1 - si.poisson**2) / si.modulus) ** -1  # fmt: skip
    p_steel = np.asarray(contact_pressures(steel, 1000.0))
    p_hybrid = np.asarray(contact_pressures(hybrid, 1000.0))
    assert p_hybrid / p_steel == pytest.approx(np.full(p_steel.shape, ratio ** (2 / 3)), rel=1e-10)
    assert 0.11 < ratio ** (2 / 3) - 1 < 0.13
    assert hybrid.stiffness / steel.stiffness == pytest.approx(ratio, rel=1e-10)


def test_the_hybrid_prints_its_material_and_the_rings_keep_their_modulus():
    b = resolve_bearing("6205", ball_material="si3n4", modulus=210000.0)
    values = {p.key: p.value for p in b.provenance}
    assert values["modulus"] == 210000.0 and values["ball_modulus"] == 310000.0
    assert values["ball_material"] == "silicon nitride Si3N4"
    out = invoke("solve", "6205", "-F", "2kN", "--ball-material", "si3n4")
    assert out.exit_code == 0, out.output
    assert (
        "Balls: silicon nitride Si3N4 (E = 310000 MPa, nu = 0.26, rho = 3200 kg/m^3)" in out.output
    )


def test_the_ball_dynamics_take_the_materials_density_unless_ball_density_is_given():
    from bearingload.studies.combined_bearing import solve_combined_bearing

    b = resolve_bearing("6205", ball_material="si3n4")
    r = solve_combined_bearing([b], 1000.0, 200.0, speed=10000.0)[0].result
    assert float(np.ravel(r.ball_density)[0]) == pytest.approx(3200.0)
    r = solve_combined_bearing([b], 1000.0, 200.0, speed=10000.0, ball_density=5000.0)[0].result
    assert float(np.ravel(r.ball_density)[0]) == pytest.approx(5000.0)
    steel = solve_combined_bearing([resolve_bearing("6205")], 1000.0, 200.0, speed=10000.0)
    assert float(np.ravel(steel[0].result.ball_density)[0]) == pytest.approx(7850.0)


def test_unknown_material_lists_the_known_in_library_cli_and_batch(tmp_path):
    with pytest.raises(InputError, match="known: steel, si3n4") as err:
        ball_material("glass")
    assert err.value.parameter == "ball_material"
    out = invoke("solve", "6205", "-F", "2kN", "--ball-material", "glass")
    assert out.exit_code == 2
    assert (
        "Error: Invalid value for '--ball-material': unknown ball material 'glass'; known: "
        "steel, si3n4" in out.output
    )
    cases = tmp_path / "c.csv"
    cases.write_text("bearing,load,ball_material\n6205,2000,glass\n", encoding="utf-8")
    out = invoke("batch", str(cases))
    assert "ball_material: unknown ball material 'glass'; known: steel, si3n4" in out.output


def test_a_roller_bearing_and_a_ring_by_hand_refuse_a_ball_material():
    with pytest.raises(InputError, match="ball bearings only") as err:
        resolve_bearing("NU206", ball_material="si3n4")
    assert err.value.parameter == "ball_material"
    out = invoke("solve", "-z", "9", "-K", "1e5", "-F", "1kN", "--ball-material", "si3n4")
    assert out.exit_code == 2 and "--ball-material" in out.output
    assert math.isfinite(resolve_bearing("7205B", ball_material="si3n4").stiffness)


def test_a_hybrid_pair_solves_with_the_hybrid_contact_and_prints_its_material():
    out = invoke("solve", "7205BDB", "-F", "2kN", "-A", "500N", "--ball-material", "si3n4")
    assert out.exit_code == 0, out.output
    assert "Balls: silicon nitride Si3N4" in out.output
    steel = invoke("solve", "7205BDB", "-F", "2kN", "-A", "500N")
    assert "Balls:" not in steel.output and steel.output != out.output
