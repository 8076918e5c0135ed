"""The case of one analysis: every input of a bearing, its loads and its operating conditions,
in the package's units, and the refusals that depend only on which inputs are given together.

A :class:`Case` is what ``bearingload solve`` reads from its options, what a row of ``batch``
holds and what :func:`bearingload.plan.analyse.analyse` builds from its keyword arguments; it
converts itself into the arguments of the studies and models below. Its refusals are typed
errors (:mod:`bearingload.errors`) naming the parameter by its library name; the command line
writes it as the option typed.

Imports nothing heavy: the command line reads it at start-up.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Sequence
from typing import Any

from bearingload.bearings.mounting import MOUNTING_PARAMS
from bearingload.errors import ConflictError, InputError
from bearingload.lazy_dataclass import dataclass

#: The load options: any of them given, the combined engine solves the case.
LOAD_PARAMS = ("axial_load", "moment", "moment_cross", "misalignment", "contact_angle")
#: The options of the combined engine that are not loads: the lever of the tilt.
TILT_PARAMS = ("tilt_radius",)
#: The operating conditions of the lives in hours, the modified life and the film
#: (:class:`bearingload.bearings.service_life.Operating`); they change no load.
SERVICE_PARAMS = (
    "static_rating",
    "speed",
    "reliability",
    "viscosity",
    "oil",
    "viscosity_40",
    "viscosity_100",
    "viscosity_index",
    "temperature",
    "contamination",
    "e_c",
    "fatigue_load_limit",
    "roughness",
    "pressure_viscosity",
)
#: What a speed of 0 means (a shaft at rest) and how to ask for it.
AT_REST = (
    "a shaft at rest is the case without 'speed': the static model (the answer of the ball "
    "dynamics at 0 rpm), its lives in 10^6 revolutions, none in hours"
)
#: The inputs of the ball dynamics at a speed (a ball bearing's combined engine).
DYNAMICS_PARAMS = ("ball_density", "quasi_static")
#: The inputs that give the operating viscosity from the oil (instead of the viscosity).
OIL_PARAMS = ("oil", "viscosity_40", "viscosity_100", "viscosity_index", "temperature")
#: The options that feed only the lives.
LIFE_PARAMS = ("dynamic_rating", "rotating", *SERVICE_PARAMS)
#: The radial load's rule where the radial engine solves the case (:meth:`Case.check_load`).
LOAD_RULE = "greater than 0 N"
#: The rule where the command and the bearing take an axial load or a moment (a ball bearing).
COMBINED_LOAD_RULE = f"{LOAD_RULE}, or 0 with an axial load or a moment"
#: What a case without a load misses (the load is required; F_r may be 0 beside others).
LOAD_NEEDED = "the radial load F_r; 0 with an axial load or a moment"
#: The combined-load options, in the order a refusal names the first one given.
COMBINED_PARAMS = LOAD_PARAMS + TILT_PARAMS + LIFE_PARAMS
#: Why sweep and table refuse the mounting options (solve and batch take them).
MOUNTING_REFUSAL = (
    "the operating clearance of a mounted bearing is solve's and batch's (docs/mounting.md); "
    "'bearingload solve' prints it (operating_clearance): give that length here"
)
#: The options only a bearing or its ball geometry uses, refused for a ring given by z and K.
BEARING_ONLY = (
    "inner_conformity",
    "outer_conformity",
    "modulus",
    "poisson",
    "ball_material",
    *MOUNTING_PARAMS,
    "maker",
    "dynamic_rating",
    "rotating",
    *SERVICE_PARAMS,
)


def load_refusal(load: float, typed: str, combined: bool) -> InputError:
    """The refusal of a radial load of 0 or less, named as ``typed`` (``-1kN``: ``-1 kN``; a bare
    number in N; -0 as 0), by :data:`COMBINED_LOAD_RULE` where the command and the bearing
    take an axial load or a moment (``combined``), else by :data:`LOAD_RULE`."""
    from bearingload.units import as_written

    written = as_written(typed, "force").removeprefix("-" if load == 0 else "")
    return InputError(
        "load", f"must be {COMBINED_LOAD_RULE if combined else LOAD_RULE} (got {written})"
    )


def negative_load(texts: dict[str, str], load: float, unit: str = "") -> InputError:
    """The refusal of a ``load`` below 0 of a row of cases (its cells' ``texts`` by library
    name; ``unit``: the unit of a bare number, its column's) by its bearing's rule."""
    names = ("bearing", "ball_diameter", "pitch_diameter")
    case = Case.of({k: texts.get(k, "").strip() or None for k in names})
    return load_refusal(load, typed_cell(texts["load"], unit), case.takes_combined)


def typed_cells(cells: dict[str, str], units: dict[str, str]) -> dict[str, str]:
    """A row's cells typed with a unit (a bare number in a column with a unit: with it), by
    column: a :class:`Case`'s ``typed``."""
    from bearingload.units import is_bare

    return {
        n: typed_cell(t, units.get(n, ""))
        for n, t in cells.items()
        if t.strip() and (n in units or not is_bare(t))
    }


class TypedRows(Sequence[dict[str, str]]):
    """The :func:`typed_cells` of rows of cells (``names`` the columns, ``units`` theirs), each
    made when it is read: a batch names a few rows of many."""

    def __init__(self, names: Sequence[str], rows: Sequence[Sequence[str]], units: dict) -> None:
        self.names, self.rows, self.units = names, rows, units

    def __len__(self) -> int:
        return len(self.rows)

    def __getitem__(self, i: Any) -> Any:
        return typed_cells(dict(zip(self.names, self.rows[i], strict=True)), self.units)


def typed_cell(text: str, unit: str = "") -> str:
    """A cell's text as typed with its unit: a bare number with its column's ``unit``."""
    from bearingload.units import is_bare

    return text.strip() + (unit if is_bare(text) else "")


@dataclass(frozen=True)
class Case:
    """The case as the command line gave it, in the package's units (N, mm, N mm, °, MPa).

    ``stiffness`` stays the text typed (its unit is checked against the exponent by
    :meth:`stiffness_value`); ``exponent`` is None unless given (the bearing's own m: 10/9 for a
    cylindrical roller bearing, else 1.5); ``given`` names the options given on the command
    line (not left at a default).
    """

    bearing: str | None = None
    balls: int | None = None
    load: float | None = None
    axial_load: float | None = None
    moment: float | None = None
    moment_cross: float | None = None
    misalignment: float | None = None
    contact_angle: float | None = None
    arrangement: str | None = None
    preload: float | str | None = None
    width: float | None = None
    tilt_radius: str | float | None = None
    stiffness: str | None = None
    clearance: Any = None
    clearance_pick: str = "mean"
    shaft_fit: str | None = None
    housing_fit: str | None = None
    shaft_bore: float | None = None
    housing_diameter: float | None = None
    inner_ring_temperature: float | None = None
    outer_ring_temperature: float | None = None
    ball_diameter: float | None = None
    pitch_diameter: float | None = None
    inner_conformity: float | None = None
    outer_conformity: float | None = None
    modulus: float | None = None
    poisson: float | None = None
    ball_material: str | None = None
    maker: str | None = None
    cage_angle: float | str = 0.0
    exponent: float | None = None
    dynamic_rating: float | None = None
    rotating: str | None = None
    static_rating: float | None = None
    speed: float | None = None
    ball_density: float | None = None
    quasi_static: bool | None = None
    reliability: float | None = None
    viscosity: float | None = None
    oil: str | None = None
    viscosity_40: float | None = None
    viscosity_100: float | None = None
    viscosity_index: float | None = None
    temperature: float | None = None
    contamination: str | None = None
    e_c: float | None = None
    fatigue_load_limit: float | None = None
    roughness: float | None = None
    pressure_viscosity: float | None = None
    given: frozenset[str] = frozenset()
    bare: frozenset[str] = frozenset()  # options typed as a bare number (no unit)
    typed: tuple[tuple[str, str], ...] = ()  # (name, text) of the inputs given with a unit

    @classmethod
    def of(
        cls,
        values: dict[str, Any],
        given: Collection[str] | None = None,
        bare: Collection[str] = (),
        typed: dict[str, str] | None = None,
    ) -> Case:
        """The case of converted ``values`` (parameter name -> value; None: not given);
        ``given`` names the inputs given (default: those with a value), ``bare`` those typed as
        a bare number (no unit), ``typed`` the text of those given with a unit (``"0.1kN"``),
        which a failure names them by."""
        named = frozenset(n for n, v in values.items() if v is not None)
        given = named if given is None else frozenset(given)
        values = {k: v for k, v in values.items() if v is not None}
        if "exponent" not in given:
            values.pop("exponent", None)
        texts = tuple(sorted((typed or {}).items()))
        if values.get("load") == 0:
            values["load"] = 0.0  # -0 is 0, echoed as 0
        return cls(**values, given=given, bare=frozenset(bare), typed=texts)

    @property
    def radial_load(self) -> float:
        """F_r, 0 where none is given (sweep --kurochkin-T; solve and table always have one). [N]"""
        return 0.0 if self.load is None else self.load

    @property
    def by_hand(self) -> bool:
        """True for a ring given by its balls and stiffness: no designation, no ball geometry."""
        return self.bearing is None and self.ball_diameter is None and self.pitch_diameter is None

    @property
    def takes_combined(self) -> bool:
        """True for a ball bearing (a designation or the ball geometry), which takes an axial
        load or a moment; False for a roller bearing and a ring given by its balls and stiffness."""
        from bearingload.bearings.designation import contact_exponent
        from bearingload.constants import ROLLER_EXPONENT

        return not self.by_hand and contact_exponent(self.bearing) != ROLLER_EXPONENT

    def check_load(self, radial: bool, combined: bool) -> None:
        """Refuse a radial load below 0, or of 0 where the radial engine solves the case
        (``radial``), naming it as typed, by the rule of a command and a bearing that take an
        axial load or a moment (``combined``) or of one that does not (:func:`load_refusal`)."""
        if self.load is None or self.load > 0 or (self.load == 0 and not radial):
            return
        typed = dict(self.typed).get("load", f"{self.load:.10g}")  # a bare number: in N
        raise load_refusal(self.load, typed, combined)

    @property
    def wants_combined(self) -> bool:
        """True when a load option (:data:`LOAD_PARAMS`) was given: the load alone chooses the
        engine; an angular-contact designation (``7205B``) always takes the combined engine,
        its balls at the contact angle."""
        if any(getattr(self, k) is not None for k in LOAD_PARAMS):
            return True
        from bearingload.bearings.angular import parse_angular

        return self.bearing is not None and parse_angular(self.bearing) is not None

    @property
    def lives_given(self) -> bool:
        """True when an option that feeds only the lives (:data:`LIFE_PARAMS`) was given."""
        return any(getattr(self, k) is not None for k in LIFE_PARAMS)

    def first_given(self, names: Collection[str]) -> str | None:
        """The first of ``names`` with a value (``axial_load``), else None."""
        return next((n for n in names if getattr(self, n) is not None), None)

    def refuse(self, names: Collection[str], where: str, why: str) -> None:
        """One :class:`~bearingload.errors.ConflictError` naming the first of ``names`` given,
        ``where`` it was given and ``why`` it is refused there."""
        name = self.first_given(names)
        if name is not None:
            raise ConflictError(name, where, why)

    def exponent_or(self, default: float = 1.5) -> float:
        """The exponent given, else ``default``. [-]"""
        return default if self.exponent is None else self.exponent

    def stiffness_value(self) -> float | None:
        """The stiffness in N/mm^m, its unit checked against the exponent m: the exponent given,
        else that of the designation's contact (:func:`bearingload.bearings.designation.
        contact_exponent`: 10/9 for a cylindrical roller bearing, else 1.5)."""
        from bearingload.bearings.designation import contact_exponent
        from bearingload.units import parse_stiffness
        from bearingload.validate import exponent as valid_exponent

        m = self.exponent if self.exponent is not None else contact_exponent(self.bearing)
        valid_exponent(m)  # the exponent's own error comes first, also without a stiffness
        return None if self.stiffness is None else parse_stiffness(self.stiffness, m)

    def cage_angle_deg(self, balls: int) -> float:
        """The cage angle in degrees; ``"half"`` is half a pitch, 180/z. [°]"""
        return 180.0 / balls if self.cage_angle == "half" else float(self.cage_angle)

    def bearing_arguments(self, stiffness: float | None = None) -> dict[str, Any]:
        """The keyword arguments of :func:`bearingload.bearings.resolve.resolve_bearings` (the
        designation first), ``stiffness`` the converted --stiffness [N/mm^m]."""
        return {
            "designation": self.bearing,
            "balls": self.balls,
            "ball_diameter": self.ball_diameter,
            "pitch_diameter": self.pitch_diameter,
            "f_i": self.inner_conformity,
            "f_o": self.outer_conformity,
            "modulus": self.modulus,
            "poisson": self.poisson,
            "ball_material": self.ball_material,
            "maker": self.maker,
            "stiffness": stiffness,
            "clearance": self.clearance,
            "clearance_pick": self.clearance_pick,
            "exponent": self.exponent,
            **{name: getattr(self, name) for name in MOUNTING_PARAMS},
        }

    def operating(self, spell: Callable[[str], str] = str) -> Any:
        """The operating conditions of the lives
        (:class:`bearingload.bearings.service_life.Operating`; alpha in 1/Pa); ``spell`` writes
        the inputs a note names as the user typed them (default: their library names)."""
        from bearingload.bearings.service_life import Operating

        alpha = None if self.pressure_viscosity is None else self.pressure_viscosity * 1e-9
        viscosity, note = self.oil_viscosity()
        note = None if note is None else spell(note)
        return Operating(
            speed=self.speed,
            reliability=self.reliability,
            viscosity=viscosity,
            viscosity_note=note,
            contamination=self.contamination,
            e_c=self.e_c,
            fatigue_load_limit=self.fatigue_load_limit,
            roughness=self.roughness,
            pressure_viscosity=alpha,
        )

    def oil_viscosity(self) -> tuple[float | None, str | None]:
        """The operating viscosity [mm^2/s] and a note saying how, by the one rule of the oil
        options and batch's columns (:func:`bearingload.bearings.oil.operating_viscosity`):
        --viscosity, or that of the oil (--oil or --viscosity-40, --viscosity-100 or
        --viscosity-index) at --temperature by ASTM D341."""
        oil = {n: getattr(self, n) for n in OIL_PARAMS}
        if all(v is None for v in oil.values()):
            return self.viscosity, None  # no oil: the viscosity given, if any
        from bearingload.bearings.oil import operating_viscosity

        nu, note = operating_viscosity(self.viscosity, **oil)
        given = next((n for n in OIL_PARAMS if oil[n] is not None), None)
        if given is not None and self.speed is None:  # name the input given, not viscosity
            from bearingload.bearings.lubrication import speed_needed

            raise speed_needed(given)
        return nu, note

    def dynamics_arguments(self) -> dict[str, Any]:
        """The ball dynamics of :func:`bearingload.studies.combined_bearing.solve_combined_bearing`:
        the speed [rpm] (None: the static model, also under --quasi-static) and the ball density
        [kg/m^3] (None: steel)."""
        self.check_dynamics_flags()
        if self.rotating == "outer" and self.speed is not None and not self.quasi_static:
            raise InputError(
                "rotating",
                "the ball dynamics at 'speed' are coded for the inner ring turning (docs/speed.md)",
                way_out="give 'quasi_static' for the static model with the outer ring's lives",
            )
        if self.stiffness is not None and self.speed is not None and not self.quasi_static:
            raise InputError(
                "stiffness",
                "the ball dynamics at 'speed' need each contact's Hertz stiffness from the ball "
                "geometry",
                way_out="leave out 'stiffness', or give 'quasi_static' for the static model",
            )
        return {
            "speed": None if self.quasi_static else self.speed,
            "ball_density": self.ball_density,
        }

    def check_dynamics_flags(self) -> None:
        """Refuse a ball density without the ball dynamics (no speed, or quasi-static) and
        quasi-static without a speed."""
        if self.ball_density is not None and (self.speed is None or self.quasi_static):
            raise InputError(
                "ball_density",
                "it enters the ball dynamics at 'speed', which 'quasi_static' or a missing "
                "'speed' leave out",
            )
        if self.quasi_static and self.speed is None:
            raise InputError("quasi_static", "it needs 'speed'")

    def combined_arguments(self) -> dict[str, Any]:
        """The combined load as the keyword arguments of the combined studies
        (:func:`bearingload.studies.combined_bearing.solve_combined_bearing`,
        :func:`bearingload.studies.combined_sweep.combined_sweep`,
        :func:`bearingload.studies.life_clearance.life_against_clearance`): F_a 0 when not
        given, the inner ring rotating by default, the lever as given (None: groove)."""
        return {
            "axial_load": self.axial_load or 0.0,
            "moment": self.moment,
            "moment_cross": self.moment_cross,
            "misalignment": self.misalignment,
            "tilt_radius": self.tilt_radius,
            "rotating": self.rotating or "inner",
            "dynamic_rating": self.dynamic_rating,
        }

    def as_pair(self) -> Case | None:
        """The case of a bearing pair (a designation's suffix, ``7205BDB``, read as the
        arrangement and taken off the designation: :func:`pair_of`), or None for one bearing;
        a preload or a width without a pair is refused."""
        import dataclasses

        single, arrangement, preload = pair_of(self.bearing, self.arrangement, self.preload)
        if arrangement is None:
            if self.preload is not None or self.width is not None:
                _readable(self.bearing)  # a designation not read: that error, not the pair's
            for name in ("preload", "width"):
                if getattr(self, name) is not None:
                    raise InputError(
                        name,
                        "it belongs to a bearing pair; give 'arrangement' DB, DF or DT (or a "
                        "designation with the suffix, 7205BDB); a single bearing is preloaded "
                        "against another one",
                    )
            return None
        return dataclasses.replace(self, bearing=single, arrangement=arrangement, preload=preload)

    def pair_arguments(self, balls: int) -> dict[str, Any]:
        """The pair as the keyword arguments of
        :func:`bearingload.studies.bearing_pair.solve_bearing_pair` (``balls``: z, for the cage
        angle 'half'): the arrangement upper-cased, no preload 0."""
        return {
            "arrangement": (self.arrangement or "").upper(),
            "preload": self.preload or 0.0,
            "width": self.width,
            "cage_angle": self.cage_angle_deg(balls),
            "moment": self.moment,
            "moment_cross": self.moment_cross,
            "tilt_radius": self.tilt_radius,
            "rotating": self.rotating or "inner",
            "dynamic_rating": self.dynamic_rating,
        }


def _readable(bearing: str | None) -> None:
    """Refuse a designation that is neither an angular-contact one nor one the catalogue reads
    (its own error, :func:`bearingload.bearings.designation.parse`)."""
    from bearingload.bearings.angular import parse_angular
    from bearingload.bearings.designation import parse

    if bearing is not None and parse_angular(bearing) is None:
        parse(bearing)


def pair_of(
    bearing: str | None, arrangement: str | None, preload: Any
) -> tuple[str | None, str | None, Any]:
    """(the single bearing's designation, the arrangement, the preload) of a case whose
    designation may carry a pair's suffix (``7205BDB``, ``7205CDBL``: arrangement DB, preload
    class L) beside an ``arrangement`` and ``preload`` given; the one rule of solve's options,
    batch's cells and the library's arguments: what contradicts the designation is refused."""
    from bearingload.bearings.angular import split_pair

    if arrangement is not None:
        arrangement = arrangement.strip().upper()
    if bearing is None:
        return None, arrangement, preload
    single, kind, cls = split_pair(bearing)
    if kind is None:
        return bearing, arrangement, preload
    if arrangement is not None and arrangement != kind:
        raise InputError(
            "arrangement",
            f"{arrangement} contradicts the designation {bearing.strip()!r} (a {kind} pair)",
        )
    if cls is not None and preload is not None and str(preload).strip().upper() != cls:
        given = f"{preload:g} N" if isinstance(preload, (int, float)) else str(preload)
        raise InputError(
            "preload",
            f"{given} contradicts the designation {bearing.strip()!r} (preload class {cls}); "
            "give the preload class or the force, not both",
        )
    return single, kind, cls or preload


#: The inputs of a :class:`Case` (its fields but the bookkeeping of what was given).
#: (read from the class's annotations: the class is built at its first use, not at import)
CASE_FIELDS = tuple(n for n in Case.__annotations__ if n not in ("given", "bare", "typed"))
