"""The ball materials of a bearing: steel (the default) and silicon nitride (hybrid bearings).

A hybrid bearing has steel rings and silicon-nitride balls: the ball's modulus and Poisson's
ratio change the Hertz contact (through E*, :func:`bearingload.contact.hertz.
equivalent_material`) and its density the ball's centrifugal force and gyroscopic moment at
speed. The rings keep --modulus and --poisson (default bearing steel).

Sources:

* steel: the package's bearing steel, E = 208 000 MPa (NSK, bearingload.constants), nu = 0.3,
  rho = 7850 kg/m^3 (100Cr6; bearingload.models.high_speed.STEEL_DENSITY).
* si3n4: SKF, Super-precision bearings, "Materials for bearing rings and rolling elements",
  table 1 (bearing-grade silicon nitride: E = 310 GPa, nu = 0.26, rho = 3200 kg/m^3); the
  ceramic ball maker's table of Lily Bearing, "Ceramic materials and their properties"
  (GPS-/HP-Si3N4: E = 310 GPa, nu 0.24/0.27, rho 3.27/3.29 g/cm^3; a ball grade >= 3.20 g/cm^3)
  brackets nu and rho.
"""

from __future__ import annotations

from bearingload.constants import STEEL_MODULUS, STEEL_POISSON
from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass

__all__ = ["BALL_MATERIALS", "BallMaterial", "ball_material"]


@dataclass(frozen=True)
class BallMaterial:
    """A ball material: its name, Young's modulus [MPa], Poisson's ratio [-], density
    [kg/m^3] and the source of the three."""

    name: str
    title: str
    modulus: float
    poisson: float
    density: float
    source: str


#: The ball materials by their option name (--ball-material, ball_material).
BALL_MATERIALS: dict[str, BallMaterial] = {
    "steel": BallMaterial(
        "steel",
        "bearing steel",
        STEEL_MODULUS,
        STEEL_POISSON,
        7850.0,
        "bearing steel: E as NSK (208 000 MPa), nu 0.3, rho 7850 kg/m^3 (100Cr6)",
    ),  # fmt: skip
    "si3n4": BallMaterial(
        "si3n4",
        "silicon nitride Si3N4",
        310_000.0,
        0.26,
        3200.0,
        "silicon nitride: SKF super-precision bearings, materials table 1 (E 310 GPa, "
        "nu 0.26, rho 3.2 g/cm^3)",
    ),  # fmt: skip
}


def ball_material(name: str) -> BallMaterial:
    """The ball material called ``name`` (any case), refused with the known names listed.

    >>> ball_material("Si3N4").modulus
    310000.0

    Raises
    ------
    InputError
        (parameter ``ball_material``) for an unknown name.
    """
    key = str(name).strip().lower()
    if key not in BALL_MATERIALS:
        known = ", ".join(BALL_MATERIALS)
        raise InputError("ball_material", f"unknown ball material {name!r}; known: {known}")
    return BALL_MATERIALS[key]
