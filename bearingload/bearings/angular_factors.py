"""ISO 281 (X, Y, e) and ISO 76 (X0, Y0) factors of single-row angular-contact ball bearings: the
one table, single bearing (or tandem) and pair (back-to-back or face-to-face, the pair as one
bearing), every row with the sources that print it.

ISO 281:2007, 5.2, Table 3 and ISO 76:2006, 7.1 restated by makers (the standards themselves
were not at hand; docs/angular_contact.md lists every source and every disagreement):

* single bearing or tandem: ``P = F_r`` for ``F_a/F_r <= e``, else ``P = X F_r + Y F_a``;
  ``P0 = max(F_r, X0 F_r + Y0 F_a)`` with X0 = 0.5;
* pair (DB, DF) as one bearing: ``P = F_r + Y1 F_a`` for ``F_a/F_r <= e``, else
  ``P = X2 F_r + Y2 F_a``; ``P0 = F_r + Y0 F_a`` (X0 = 1).

At 15° e, Y, Y1 and Y2 depend on the relative axial load ``i f0 F_a / C0r`` (i = 1 for a single
bearing, 2 for the pair with C0r the pair's rating; or ``F_a / C0r`` in the column of ISO
281:1990), read by linear interpolation along that load as the standard's note says.

Sources (named in :attr:`AngularFactors.sources`):

* ``PBF``: PBF (Poland) general catalogue, "Chart 43" (15° to 45°, single and pair, Y0);
* ``NSK``: NSK general catalogue pp. B51-52 (15°, 25°, 30°, 40°) and NSK super-precision
  catalogue Table 1.1 (15°, 25°, 30°, 40°, and the 20° row printed as "18°");
* ``KOYO``: JTEKT/Koyo technical section 3.1 and general catalogue p. B20 (15°, 30°, 40°);
* ``LYC``: LYC Bearing, "Equivalent dynamic load / static load - angular contact ball
  bearings", Tables 2, 3, 4 (15°, 25°, 40°);
* ``SKF``: SKF S71910 ACD/P4A data sheet (25°);
* ``FGFA``: a 7206 B product page (fgfa.com.cn, the SKF/FAG layout: e 1.14, X 0.35, Y 0.57,
  Y0 0.26).

Where the sources disagree (docs/angular_contact.md, "Factors"): PBF prints e = 0.63 at 25°
(NSK, SKF, LYC: 0.68; 0.68 is the one at which ``X + Y e = 1``, the two branches meeting): 0.68
is taken. KOYO prints the pair Y2 = 2.21 at i f0 F_a/C0r = 0.714 (NSK, PBF: 2.11; 2.11 meets
the first branch at e, ``(1 - X2)/(Y2 - Y1) = 0.43``, 2.21 at 0.37): 2.11 is taken. PBF's 45°
pair Y2 = 0.91 is the only print of it and fails the same check (0.46/0.44 = 1.05, not e =
1.34) and the ratio Y2/Y = 1.62-1.63 of every other angle (0.81 would meet both): it is not
coded, and the 45° pair is refused beyond e rather than computed with a misprint.

Angles between the rows (GOST 831's 12°, 26°, 36°) and below 15° (the standard's 5° and 10°
rows were found in no public source) are refused with the covered angles named: the standard's
note on linear interpolation was found restated only along the relative axial load, not across
contact angles.
"""

from __future__ import annotations

from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass


@dataclass(frozen=True)
class AngularFactors:
    """One fixed-angle row of the table (20° ... 45°). [-]

    ``e``, ``x``, ``y``: single bearing or tandem, ``F_a/F_r > e``; ``pair_y1`` (``F_a/F_r <=
    e``), ``pair_x2``, ``pair_y2`` (beyond e; None where no trustworthy print exists): the pair as
    one bearing; ``y0``, ``pair_y0``: ISO 76's Y0 of one bearing and of the pair; ``sources``:
    who prints the row (module docstring)."""

    e: float
    x: float
    y: float
    pair_y1: float
    pair_x2: float
    pair_y2: float | None
    y0: float
    pair_y0: float
    sources: str


#: Contact angle [°] -> its row. Sources per row as printed (module docstring).
ANGULAR_FACTORS: dict[float, AngularFactors] = {
    # PBF Chart 43; NSK's super-precision Table 1.1 prints the same numbers as its "18°" row.
    20.0: AngularFactors(0.57, 0.43, 1.00, 1.09, 0.70, 1.63, 0.42, 0.84, "PBF; NSK (as 18°)"),
    # NSK general pp. B51-52, NSK super-precision Table 1.1, SKF S71910 ACD/P4A, LYC Tables 2, 4;
    # PBF prints e = 0.63 (not taken, see the module docstring).
    25.0: AngularFactors(0.68, 0.41, 0.87, 0.92, 0.67, 1.41, 0.38, 0.76, "NSK; SKF; LYC; PBF"),
    # NSK general and super-precision, KOYO 3.1 and p. B20, PBF.
    30.0: AngularFactors(0.80, 0.39, 0.76, 0.78, 0.63, 1.24, 0.33, 0.66, "NSK; KOYO; PBF"),
    # PBF Chart 43 only.
    35.0: AngularFactors(0.95, 0.37, 0.66, 0.66, 0.60, 1.07, 0.29, 0.58, "PBF"),
    # NSK general and super-precision, KOYO, PBF, LYC, FGFA.
    40.0: AngularFactors(1.14, 0.35, 0.57, 0.55, 0.57, 0.93, 0.26, 0.52, "NSK; KOYO; PBF; LYC"),
    # PBF Chart 43 only; its pair Y2 = 0.91 is a misprint (module docstring): not coded.
    45.0: AngularFactors(1.34, 0.33, 0.50, 0.47, 0.54, None, 0.22, 0.44, "PBF"),
}

#: The 15° row: e, Y (single), Y1, Y2 (pair) against the relative axial load, read by linear
#: interpolation, the end rows held outside. Knots of ``i f0 F_a / C0r`` (NSK, PBF, KOYO; KOYO
#: misprints the last knot 5.35 twice, NSK prints 7.14 with the same e, Y: beyond 5.35 the end
#: row holds) and of ``F_a / C0r`` (KOYO, LYC: the column of ISO 281:1990).
ANGULAR_15_F0FA_C0R = (0.178, 0.357, 0.714, 1.07, 1.43, 2.14, 3.57, 5.35)
ANGULAR_15_FA_C0R = (0.015, 0.029, 0.058, 0.087, 0.12, 0.17, 0.29, 0.44)
ANGULAR_15_E = (0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56)
ANGULAR_15_Y = (1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00)
#: Pair Y1 and Y2 at 15° (NSK, PBF; KOYO's 2.21 at 0.714 not taken, module docstring).
ANGULAR_15_PAIR_Y1 = (1.65, 1.57, 1.46, 1.38, 1.34, 1.26, 1.14, 1.12)
ANGULAR_15_PAIR_Y2 = (2.39, 2.28, 2.11, 2.00, 1.93, 1.82, 1.66, 1.63)
#: X of the single bearing and X2 of the pair at 15° (NSK, PBF, KOYO). [-]
ANGULAR_15_X, ANGULAR_15_PAIR_X2 = 0.44, 0.72
#: ISO 76 Y0 at 15°, single and pair (NSK, PBF, KOYO, LYC). [-]
ANGULAR_15_Y0, ANGULAR_15_PAIR_Y0 = 0.46, 0.92
#: ISO 76 X0: single bearing or tandem, and the pair (NSK, PBF, KOYO, LYC). [-]
X0_SINGLE, X0_PAIR = 0.5, 1.0

#: Every contact angle with coded factors. [°]
TABULATED_ANGLES = (15.0, *ANGULAR_FACTORS)


def _same(a: float, b: float) -> bool:
    return abs(a - b) < 1e-9


def tabulated(contact_angle: float) -> bool:
    """Whether the factors of this nominal contact angle are coded (:data:`TABULATED_ANGLES`).

    >>> tabulated(35.0), tabulated(36.0)
    (True, False)
    """
    return any(_same(contact_angle, a) for a in TABULATED_ANGLES)


def covered() -> str:
    """The coded angles in words, for a refusal.

    >>> covered()
    '15, 20, 25, 30, 35, 40 and 45°'
    """
    names = [f"{a:g}" for a in TABULATED_ANGLES]
    return f"{', '.join(names[:-1])} and {names[-1]}°"


def fixed_row(contact_angle: float) -> AngularFactors:
    """The row of a fixed-angle (20° ... 45°) contact angle; InputError naming the covered angles
    for any other angle (15° has no fixed row: its factors depend on the relative load).

    >>> fixed_row(45.0).y
    0.5
    """
    for a, row in ANGULAR_FACTORS.items():
        if _same(a, contact_angle):
            return row
    raise InputError("contact_angle", refusal(contact_angle))


def refusal(contact_angle: float) -> str:
    """Why an angle has no factors, naming those it has.

    >>> "got 26°" in refusal(26.0) and "15, 20, 25, 30, 35, 40 and 45°" in refusal(26.0)
    True
    """
    return (
        f"ISO 281's X, Y, e and ISO 76's Y0 are coded at {covered()} only; got "
        f"{contact_angle:g}° (no source found permits interpolating between contact angles)"
    )


def static_y0(contact_angle: float, pair: bool = False) -> float | None:
    """ISO 76's Y0 of one bearing (or tandem) or of the pair; None for an angle not coded.

    >>> static_y0(15.0), static_y0(20.0, pair=True), static_y0(12.0) is None
    (0.46, 0.84, True)
    """
    if _same(contact_angle, 15.0):
        return ANGULAR_15_PAIR_Y0 if pair else ANGULAR_15_Y0
    row = next((r for a, r in ANGULAR_FACTORS.items() if _same(a, contact_angle)), None)
    if row is None:
        return None
    return row.pair_y0 if pair else row.y0
