"""Constants with one home: unit factors, the default material, exponents, clearance picks.

Imports nothing, so every module (and the command line at start-up) can use it.
"""

from __future__ import annotations

#: Standard gravity, exact by definition (CGPM 1901): 1 kgf = 9.80665 N. [N]
KGF = 9.80665
#: International avoirdupois pound-force: 0.45359237 kg x standard gravity. [N]
LBF = 0.45359237 * KGF
#: One inch. [mm]
INCH = 25.4

#: Young's modulus of bearing steel used when none is given (NSK: 208 000 MPa). [MPa]
STEEL_MODULUS = 208_000.0
#: Poisson's ratio of bearing steel used when none is given. [-]
STEEL_POISSON = 0.3

#: Load-deflection exponent m of a ball, Hertz point contact: Q = K delta^(3/2). [-]
BALL_EXPONENT = 1.5
#: Load-deflection exponent m of a roller, line contact (Palmgren 1959): Q = K delta^(10/9). [-]
ROLLER_EXPONENT = 10.0 / 9.0

#: Life exponent p of ball bearings, L10 = (C/P)^p (ISO 281:2007, 5.3). [-]
BALL_LIFE_EXPONENT = 3.0
#: Life exponent p of roller bearings (ISO 281:2007). [-]
ROLLER_LIFE_EXPONENT = 10.0 / 3.0

#: Contamination levels of ISO 281:2007 Table 13, cleanest first (e_C in
#: :data:`bearingload.bearings.modified_life.CONTAMINATION_RANGES`).
CONTAMINATION_LEVELS = ("extreme", "high", "normal", "slight", "typical", "severe", "very-severe")

#: Where in a clearance class's range G_r is taken.
CLEARANCE_PICKS = ("min", "mean", "max")
