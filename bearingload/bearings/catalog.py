"""Catalogue of single-row deep groove ball bearings: boundary dimensions, balls, ratings.

Two data files, every row with a ``source`` column naming where its numbers came from and a
``notes`` column flagging what is derived or doubtful:

``data/bearings.csv``: one row per designation, boundary dimensions and load ratings.

* GOST 8338-75 rows (``204`` ... ``316``): d, D, B, D_w and the ratings from the table of
  GOST 8338-75 in [1]_; that table gives no ball count, so z is derived from the old GOST
  static-capacity rule C0 = 1.25 z D_w^2 [kgf, mm] (exact for the seeds' 306 and 208;
  ambiguous for 209 and 307, see their notes). Rows 306 and 208 carry the numbers of the
  source papers instead: Kuzmenko (2010, Table 2) and Kuzmenko & Sabadash (2014, section 2.1), with their ratings in kgf converted at 9.80665 N/kgf.
* ISO rows (``6000`` ... ``6416``): ratings and boundary dimensions from the NSK [2]_ (60xx,
  62xx, 63xx) and FBJ (64xx) catalogues; the ball set comes from ``ball_sets.csv``.

``data/ball_sets.csv``: the ball sets z x D_w on d_m of the ISO designations, one row per maker
(column ``maker``), each marked ``read`` (printed by the maker or a published test rig: GMN
catalogue, CWRU, PRONOSTIA, Paderborn) or ``derived`` (found by inverting the maker's ISO 281 /
ISO 76 ratings, :mod:`bearingload.bearings.ratings`; the ratings used are in the row and a
test re-derives every derived set from them). Where makers use different ball sets for the
same designation (6208: NSK/NTN/GMN 9 x 15/32", SKF 9 x 31/64", GOST 9 x 1/2") each is its own
row, selected with ``maker=`` (CLI ``--maker``); the GOST 8338 set of a 62xx/63xx is the
maker ``GOST``.

Default maker: **NSK** (:data:`DEFAULT_MAKER`). Its inversion has three constraints per row
(C_r, C_0r and the printed f0) instead of two, so it is the best determined; it reproduces
15 of the 16 ball sets GMN prints and every published test-rig set of the same designation
(CWRU 6203/6205, Paderborn 6203, PRONOSTIA 61804), and NSK lists every designation of the
60, 62, 63, 618, 619 and 160 series to 100 mm bore. Designations NSK does not list (64xx) or
whose NSK inversion is inconclusive (6302) have no default set: where one maker alone gives a
set (6405, 6407 ... 6416: NTN) that set is used and said so (``only_maker``); where several
do (6302, 6403, 6404, 6406: NTN and SKF) name a maker.

* Pitch diameter d_m = (d + D) / 2 for derived sets; read sets carry the published d_m.
* Groove conformities f = r / D_w default to f_i = 0.52, f_o = 0.53 (the ISO/TS 16281
  convention for deep groove ball bearings); GOST 306 uses the paper's groove radius
  1.03 D_w / 2, i.e. f_i = f_o = 0.515 (section 3.4).

References
----------
.. [1] О.А. Чихачева, А.С. Лукьянов, Л.А. Дмитриева, *Подшипники качения*, Московский
   Политех, 2023, Table П2 "Подшипники шариковые радиальные однорядные (из ГОСТ 8338-75)", p. 96.
.. [2] NSK, *Rolling Bearings* catalogue, single-row deep groove ball bearing tables, B10-B13.

>>> b = lookup("306")
>>> b.balls, b.ball_diameter, b.pitch_diameter, b.f_i
(8, 12.3, 51.0, 0.515)
>>> lookup("6306-2RS1/C3").parsed.clearance_class
'C3'
"""

from __future__ import annotations

import dataclasses
import functools
import math
import re
from collections.abc import Container

from bearingload.bearings.designation import Designation, UnmodelledBearing, parse
from bearingload.errors import InputError
from bearingload.lazy_dataclass import dataclass

#: Default inner-groove conformity r_i / D_w (ISO/TS 16281 convention). [-]
DEFAULT_F_I = 0.52
#: Default outer-groove conformity r_o / D_w (ISO/TS 16281 convention). [-]
DEFAULT_F_O = 0.53

STANDARDS: tuple[str, ...] = ("GOST", "ISO")

#: Maker whose ball set an ISO designation gets unless another is chosen (see the module text).
DEFAULT_MAKER = "NSK"

#: Dimension series of the catalogue (ISO codes).
SERIES: tuple[str, ...] = ("60", "62", "63", "64", "618", "619", "160")

_BY_HAND = (
    "give the geometry by hand: 'balls', 'ball_diameter' and 'pitch_diameter' "
    "(run 'bearingload catalog' to list the known bearings)"
)


@dataclass(frozen=True)
class BearingGeometry:
    """One bearing of the catalogue, possibly with user overrides applied.

    Attributes
    ----------
    designation : str
        Catalogue designation (``"306"``, ``"6306"``).
    standard : str
        ``"GOST"`` or ``"ISO"``.
    d, D : float
        Bore, outside diameter. [mm]
    B : float or None
        Width; None where the sources used give none (618, 619, 160 series). [mm]
    ball_diameter : float or None
        Ball diameter D_w; None when unknown. [mm]
    balls : int or None
        Number of balls z; None when unknown.
    pitch_diameter : float or None
        Pitch diameter d_m; None when the ball set is unknown. [mm]
    C, C0 : float or None
        Basic dynamic and static radial load ratings. [N]
    f_i, f_o : float
        Inner and outer groove conformity r / D_w. [-]
    source : str
        Where the row's numbers come from.
    notes : str
        Flags: derived values, ambiguities.
    parsed : Designation
        The parsed designation (as the user typed it for :func:`lookup`, suffixes included).
    f0 : float or None
        Catalogue factor f0 of C0r = f0 z D_w^2 (NSK rows). [N/mm^2]
    overrides : tuple of str
        Names of fields set by the user rather than the catalogue.
    maker : str or None
        Whose ball set this is (``"NSK"``, ``"NTN"``, ``"SKF"``, ``"GMN"``, ``"GOST"``,
        ``"CWRU"`` ...); None when the row has no ball set.
    method : str or None
        ``"read"`` (printed by the source) or ``"derived"`` (inverted from ratings; GOST: D_w
        read, z derived).
    confidence : str or None
        Of a derived set: ``"high"`` or ``"medium"`` (see ``ball_sets.csv``); ``"published"``
        for a read set.
    makers : tuple of str
        Every maker with a ball set for this designation (choose with ``maker=``).
    only_maker : bool
        True when the ball set is that of the one maker who gives a set for this designation
        (``6408``: NTN), used without ``maker=`` because there is nothing to choose between.
    limiting_speed_grease, limiting_speed_oil : float or None
        The limiting speeds a maker prints for this designation, with grease and with oil
        lubrication; None where none was read. [r/min]
    limiting_speed_source : str
        Where they come from (empty where none was read).
    """

    designation: str
    standard: str
    d: float
    D: float
    B: float | None
    ball_diameter: float | None
    balls: int | None
    pitch_diameter: float | None
    C: float | None
    C0: float | None
    f_i: float
    f_o: float
    source: str
    notes: str
    parsed: Designation
    f0: float | None = None
    overrides: tuple[str, ...] = ()
    maker: str | None = None
    method: str | None = None
    confidence: str | None = None
    makers: tuple[str, ...] = ()
    only_maker: bool = False
    limiting_speed_grease: float | None = None
    limiting_speed_oil: float | None = None
    limiting_speed_source: str = ""

    @property
    def has_geometry(self) -> bool:
        """True when z, D_w and d_m are all known."""
        return None not in (self.balls, self.ball_diameter, self.pitch_diameter)

    @property
    def limiting_speeds(self) -> LimitingSpeeds | None:
        """The limiting speeds of this bearing as designated, or None: none read, or a seal
        marked in the designation (the catalogue holds the open bearing's, which a seal lowers:
        :func:`sealed`)."""
        if sealed(self.parsed.suffixes):
            return None
        return self.open_limiting_speeds

    @property
    def open_limiting_speeds(self) -> LimitingSpeeds | None:
        """The limiting speeds of the row, those of the open bearing whatever seal the
        designation marks (a sealed bearing's are lower: :func:`sealed`), or None: none read."""
        grease, oil = self.limiting_speed_grease, self.limiting_speed_oil
        if grease is None or oil is None:
            return None
        return LimitingSpeeds(grease, oil, self.limiting_speed_source)

    @property
    def series(self) -> str:
        """ISO dimension-series code (``"62"``, ``"63"`` ...) as written in the designation."""
        return self.parsed.series

    @property
    def catalogue_series(self) -> str:
        """Series of the catalogue row (``"618"`` for a row looked up as ``6806``)."""
        return {"68": "618", "69": "619"}.get(self.parsed.series, self.parsed.series)


@dataclass(frozen=True)
class LimitingSpeeds:
    """The limiting speeds a maker prints for one bearing: ``grease`` and ``oil`` lubrication
    [r/min] (oil the higher), and their ``source``."""

    grease: float
    oil: float
    source: str


#: Suffixes of a sealed bearing (contact or non-contact seals: RS, 2RS, 2RS1, RSR, RZ, 2RZ, RU,
#: RD, LLU, LLB, DDU, VV ...); shields (Z, ZZ, 2Z) are not seals. Koyo's table of sealed deep
#: groove bearings (CAT. No. B2001RUS p. 20) prints the open bearing's grease limit for ZZ and
#: lower ones for its seals, so the open bearing's limits are not those of a sealed one.
_SEAL = r"^(2?R[SDUZ]\w*|LL\w*|DD\w*|VV\w*|2?RSR\w*)$"  # compiled at first use


def sealed(suffixes: tuple[str, ...]) -> bool:
    """True when a designation's suffixes mark a seal (:data:`_SEAL`).

    >>> sealed(("2RS1", "C3")), sealed(("ZZ",)), sealed(("C3",))
    (True, False, False)
    """
    return any(re.match(_SEAL, s.upper()) for s in suffixes)


def _float(text: str) -> float | None:
    return float(text) if text.strip() else None


@dataclass(frozen=True)
class BallSet:
    """One row of ``data/ball_sets.csv``: a maker's ball set of one designation."""

    designation: str
    maker: str
    d: float
    D: float
    balls: int
    ball_diameter: float
    pitch_diameter: float
    C: float | None
    C0: float | None
    f0: float | None
    method: str
    inversion: str
    confidence: str
    source: str
    notes: str


@functools.lru_cache(maxsize=2)
def _read(name: str) -> tuple[dict[str, str], ...]:
    """The rows of ``data/<name>``, read once (treat as read-only)."""
    from bearingload.bearings._data import read_rows

    return tuple(read_rows(name))


def _ball_set(rec: dict[str, str]) -> BallSet:
    return BallSet(
        designation=rec["designation"],
        maker=rec["maker"],
        d=float(rec["d"]),
        D=float(rec["D"]),
        balls=int(rec["balls"]),
        ball_diameter=float(rec["ball_diameter"]),
        pitch_diameter=float(rec["pitch_diameter"]),
        C=_float(rec["C"]),
        C0=_float(rec["C0"]),
        f0=_float(rec["f0"]),
        method=rec["method"],
        inversion=rec["inversion"],
        confidence=rec["confidence"],
        source=rec["source"],
        notes=rec["notes"],
    )


@functools.lru_cache(maxsize=1)
def ball_sets() -> tuple[BallSet, ...]:
    """Every row of ``data/ball_sets.csv`` (all makers), in file order.

    Returns
    -------
    tuple of BallSet
        Diameters [mm], ratings [N], f0 [N/mm^2].
    """
    return tuple(_ball_set(rec) for rec in _read("ball_sets.csv"))


def _with_set(row: BearingGeometry, bs: BallSet) -> BearingGeometry:
    """``row`` with the ball set (and the ratings it belongs to) of ``bs``."""
    return dataclasses.replace(
        row,
        balls=bs.balls,
        ball_diameter=bs.ball_diameter,
        pitch_diameter=bs.pitch_diameter,
        C=bs.C,
        C0=bs.C0,
        f0=bs.f0,
        maker=bs.maker,
        method=bs.method,
        confidence=bs.confidence,
        source=f"{bs.maker} ball set ({bs.method}): {bs.source}",
        notes=bs.notes,
    )


def _csv_row(rec: dict[str, str]) -> BearingGeometry:
    f_i, f_o = _float(rec["f_i"]), _float(rec["f_o"])
    gost = rec["standard"] == "GOST"
    return BearingGeometry(
        designation=rec["designation"],
        standard=rec["standard"],
        d=float(rec["d"]),
        D=float(rec["D"]),
        B=_float(rec["B"]),
        ball_diameter=_float(rec["ball_diameter"]),
        balls=int(rec["balls"]) if rec["balls"].strip() else None,
        pitch_diameter=_float(rec["pitch_diameter"]),
        C=_float(rec["C"]),
        C0=_float(rec["C0"]),
        f_i=DEFAULT_F_I if f_i is None else f_i,
        f_o=DEFAULT_F_O if f_o is None else f_o,
        source=rec["source"],
        notes=rec["notes"],
        parsed=parse(rec["designation"]),
        f0=_float(rec["f0"]),
        maker="GOST" if gost else None,
        method=("read" if "Kuzmenko" in rec["source"] else "D_w read, z derived") if gost else None,
        confidence="published" if gost else None,
        limiting_speed_grease=_float(rec["limiting_speed_grease"]),
        limiting_speed_oil=_float(rec["limiting_speed_oil"]),
        limiting_speed_source=rec["limiting_speed_source"],
    )


def _set_row(name: str, first: BallSet) -> BearingGeometry:
    """The row of a designation found only in the ball sets (618, 619, 160 series)."""
    return BearingGeometry(
        designation=name,
        standard="ISO",
        d=first.d,
        D=first.D,
        B=None,
        ball_diameter=None,
        balls=None,
        pitch_diameter=None,
        C=None,
        C0=None,
        f_i=DEFAULT_F_I,
        f_o=DEFAULT_F_O,
        source="",
        notes="width B: not in the sources used",
        parsed=parse(name),
    )


def _complete(row: BearingGeometry, sets: list[BallSet], gost: Container[str]) -> BearingGeometry:
    """A catalogue row with its makers and its default ball set; ``sets``: the ball sets of its
    designation in file order, ``gost``: the ISO names of the GOST rows with a ball set."""
    if row.standard == "GOST":
        return dataclasses.replace(row, makers=("GOST",))
    makers = tuple(bs.maker for bs in sets) + (("GOST",) if row.designation in gost else ())
    default = next((bs for bs in sets if bs.maker == DEFAULT_MAKER), None)
    if default is not None:
        row = _with_set(row, default)
    elif len(makers) == 1 and sets:  # one maker gives a set: nothing to choose between
        row = dataclasses.replace(_with_set(row, sets[0]), only_maker=True)
    elif sets:
        others = ", ".join(f"{bs.maker} {bs.balls} x {bs.ball_diameter:g} mm" for bs in sets)
        row = dataclasses.replace(row, notes=f"{row.notes}; maker ball sets: {others}")
    return dataclasses.replace(row, makers=makers)


@functools.lru_cache(maxsize=1)
def _rows() -> tuple[BearingGeometry, ...]:
    by_name: dict[str, list[BallSet]] = {}
    for bs in ball_sets():
        by_name.setdefault(bs.designation, []).append(bs)
    rows = [_csv_row(rec) for rec in _read("bearings.csv")]
    gost = {r.parsed.iso_name for r in rows if r.standard == "GOST" and r.has_geometry}
    known = {r.designation for r in rows if r.standard == "ISO"}
    for name, sets in by_name.items():
        if name not in known:  # 618, 619, 160 series: the row is the default maker's
            rows.append(_set_row(name, sets[0]))
    return tuple(_complete(row, by_name.get(row.designation, []), gost) for row in rows)


@functools.lru_cache(maxsize=1)
def _gost_iso_names() -> frozenset[str]:
    """ISO names of the GOST rows that have a ball set."""
    rows = (_csv_row(rec) for rec in _read("bearings.csv") if rec["standard"] == "GOST")
    return frozenset(r.parsed.iso_name for r in rows if r.has_geometry)


@functools.lru_cache(maxsize=256)
def _row(standard: str, name: str) -> BearingGeometry | None:
    """The first row of :func:`_rows` with this standard and designation (None: there is none),
    built alone from its own lines of the files: a terminal command that looks up one bearing
    does not parse or build the other 400 rows and ball sets (about 7 ms of its start-up)."""
    from bearingload.bearings._data import read_rows

    rec = next((r for r in read_rows("bearings.csv", name) if r["standard"] == standard), None)
    row = None if rec is None else _csv_row(rec)
    if standard != "ISO":
        return None if row is None else _complete(row, [], ())
    sets = [_ball_set(r) for r in read_rows("ball_sets.csv", name)]
    if row is None:
        if not sets:
            return None
        row = _set_row(name, sets[0])
    return _complete(row, sets, _gost_iso_names())


def variant(designation: str, maker: str) -> BearingGeometry:
    """The catalogue row of ``designation`` with the ball set (and ratings) of ``maker``.

    Parameters
    ----------
    designation : str
        ISO designation (``6208``, ``61806-2RS``) or GOST (then only ``GOST`` is a maker).
    maker : str
        ``NSK``, ``NTN``, ``SKF``, ``GMN``, ``GOST``, ``CWRU``, ``PRONOSTIA``, ``PADERBORN``
        (any case), where the designation has one; see ``BearingGeometry.makers``.

    Returns
    -------
    BearingGeometry

    Raises
    ------
    InputError
        (parameter ``maker``) no ball set of that maker for this designation, listing those
        that exist.

    >>> b = variant("6208", "gost")
    >>> b.balls, b.ball_diameter, b.maker
    (9, 12.7, 'GOST')
    """
    row = find(designation)
    key = str(maker).strip().upper()
    if key == "GOST" and key in row.makers:
        if row.standard == "GOST":
            return row
        g = next(
            r for r in _rows() if r.standard == "GOST" and r.parsed.iso_name == row.designation
        )
        return dataclasses.replace(
            g,
            designation=row.designation,
            standard=row.standard,
            parsed=row.parsed,
            makers=row.makers,
            source=f"GOST ball set ({g.method}) of GOST {g.designation}: {g.source}",
            limiting_speed_grease=row.limiting_speed_grease,
            limiting_speed_oil=row.limiting_speed_oil,
            limiting_speed_source=row.limiting_speed_source,
        )
    for bs in ball_sets():
        if bs.designation == row.designation and bs.maker == key:
            return dataclasses.replace(_with_set(row, bs), only_maker=False)
    have = ", ".join(row.makers) or "none"
    raise InputError(
        "maker",
        f"no {maker} ball set for {row.designation} in the catalogue; makers with one: {have}",
    )


def _normalise_series(series: str) -> str:
    s = str(series).strip().upper().rstrip("X")
    if len(s) == 1 and s in "0234":
        s = "6" + s
    s = {"68": "618", "69": "619"}.get(s, s)
    if s not in SERIES:
        raise InputError(
            "series",
            f"unknown series {series!r}; allowed: {', '.join(SERIES)} (or 2, 3, 4 as in GOST)",
        )
    return s


def entries(
    series: str | None = None, standard: str | None = None, bore: float | None = None
) -> list[BearingGeometry]:
    """List catalogue rows, optionally filtered.

    Parameters
    ----------
    series : str, optional
        Dimension series: ``"60"``, ``"62"``, ``"63"``, ``"64"``, ``"618"`` (or ``"68"``),
        ``"619"`` (``"69"``), ``"160"``, or GOST style ``"2"``,
        ``"3"``, ``"4"`` (``"62xx"`` also works).
    standard : str, optional
        ``"GOST"`` or ``"ISO"`` (any case).
    bore : float, optional
        Bore diameter d. [mm]

    Returns
    -------
    list of BearingGeometry
        In catalogue order (GOST rows first, then ISO: 60 ... 64, 618, 619, 160), each with
        its default ball set (:data:`DEFAULT_MAKER`).

    Raises
    ------
    InputError
        Unknown series or standard; a bore that is not a number > 0.

    Examples
    --------
    >>> [b.designation for b in entries(bore=30)]
    ['206', '306', '6006', '6206', '6306', '6406', '61806', '61906', '16006']
    """
    rows = list(_rows())
    if series is not None:
        s = _normalise_series(series)
        rows = [r for r in rows if r.catalogue_series == s]
    if standard is not None:
        std = str(standard).strip().upper()
        if std not in STANDARDS:
            raise InputError(
                "standard", f"unknown standard {standard!r}; allowed: {', '.join(STANDARDS)}"
            )
        rows = [r for r in rows if r.standard == std]
    if bore is not None:
        d = checked_bore(bore)
        rows = [r for r in rows if math.isclose(r.d, d)]
    return rows


def checked_bore(bore: object) -> float:
    """The bore diameter a catalogue list is filtered by [mm]: one finite number > 0, else
    :class:`InputError` (a bore of -5 or NaN listed no bearing, as if none had it)."""
    from bearingload.validate import positive

    d = positive("bore", bore, "mm")
    if d.ndim:
        raise InputError("bore", f"must be one number [mm] (got an array of shape {d.shape})")
    return float(d)


def find(designation: str) -> BearingGeometry:
    """The catalogue row of a designation, with or without a known ball set.

    GOST designations (``306``, ``75-313``) resolve to GOST rows and ISO designations
    (``6306-2RS``) to ISO rows; suffixes and prefixes do not change the row.

    Parameters
    ----------
    designation : str
        Bearing designation, see :func:`bearingload.bearings.designation.parse`.

    Returns
    -------
    BearingGeometry
        The row, with ``parsed`` set to the parsed ``designation``.

    Raises
    ------
    InputError
        (parameter ``bearing``) unreadable or not in the catalogue; the message says how to
        give the geometry by hand.
    """
    try:
        parsed = parse(designation)
    except UnmodelledBearing:
        raise  # another bearing type: no geometry given by hand makes it a deep-groove one
    except InputError as exc:
        ways = f"or {_BY_HAND}" if exc.way_out is None else f"{exc.way_out}; or {_BY_HAND}"
        raise InputError("bearing", exc.problem, way_out=ways) from None
    if parsed.kind == "roller":
        raise InputError(
            "bearing",
            f"{parsed.base!r} is a cylindrical roller bearing; "
            "see bearingload.bearings.rollers (resolve_bearing handles both)",
        )
    row = _row(parsed.standard, parsed.catalogue_name)
    if row is not None:
        return dataclasses.replace(row, parsed=parsed)
    hint = ""
    other = _counterpart(parsed)
    if other is not None:
        hint = f"; the {other.standard} designation {other.designation!r} is in the catalogue"
    raise InputError(
        "bearing", f"{parsed.base!r} ({parsed.standard}) is not in the catalogue{hint}; {_BY_HAND}"
    )


def _counterpart(parsed: Designation) -> BearingGeometry | None:
    """The row of the same bearing under the other standard, if any."""
    name = parsed.iso_name if parsed.standard == "GOST" else parsed.gost_name
    std = "ISO" if parsed.standard == "GOST" else "GOST"
    for row in _rows():
        if row.standard == std and row.designation == name:
            return row
    return None


def check_geometry(
    d: float,
    D: float,
    balls: int,
    ball_diameter: float,
    pitch_diameter: float,
    f_i: float = DEFAULT_F_I,
    f_o: float = DEFAULT_F_O,
) -> None:
    """Raise InputError when a ball set cannot fit the rings.

    Parameters
    ----------
    d, D : float
        Bore and outside diameter. [mm]
    balls : int
        Number of balls z, at least 1.
    ball_diameter : float
        Ball diameter D_w. [mm]
    pitch_diameter : float
        Pitch diameter d_m. [mm]
    f_i, f_o : float
        Groove conformities r / D_w; must lie in (0.5, 1). [-]

    Raises
    ------
    InputError
        Naming the offending parameter: z not a positive integer; D_w <= 0 or
        D_w >= (D - d) / 2; d_m outside (d, D) or the balls not fitting on the ring; adjacent balls
        overlapping (D_w >= d_m sin(pi / z)); f outside (0.5, 1)
        (:func:`bearingload.validate.conformity`).
    """
    if isinstance(balls, bool) or not float(balls).is_integer() or balls < 1:
        raise InputError("balls", f"the number of balls must be a whole number >= 1, not {balls!r}")
    if not ball_diameter > 0:
        raise InputError("ball_diameter", f"must be > 0 mm, not {ball_diameter!r}")
    if not ball_diameter < (D - d) / 2:
        raise InputError(
            "ball_diameter",
            f"{ball_diameter:g} mm does not fit between the rings: it must be below "
            f"(D - d)/2 = {(D - d) / 2:g} mm",
        )
    if not d + ball_diameter < pitch_diameter < D - ball_diameter:
        raise InputError(
            "pitch_diameter",
            f"{pitch_diameter:g} mm puts the balls outside the rings: it must lie between "
            f"d + Dw = {d + ball_diameter:g} and D - Dw = {D - ball_diameter:g} mm",
        )
    if balls > 1 and not ball_diameter < pitch_diameter * math.sin(math.pi / balls):
        raise InputError(
            "balls",
            f"{int(balls)} balls of {ball_diameter:g} mm overlap on a pitch circle of "
            f"{pitch_diameter:g} mm (need Dw < d_m sin(pi/z) = "
            f"{pitch_diameter * math.sin(math.pi / balls):.4g} mm)",
        )
    from bearingload.validate import conformity  # the one rule (numpy: only when checked)

    conformity("f_i", f_i)
    conformity("f_o", f_o)


def lookup(
    designation: str,
    *,
    balls: int | None = None,
    ball_diameter: float | None = None,
    pitch_diameter: float | None = None,
    f_i: float | None = None,
    f_o: float | None = None,
    maker: str | None = None,
) -> BearingGeometry:
    """Complete geometry of a catalogued bearing for a calculation, with optional overrides.

    Parameters
    ----------
    designation : str
        Bearing designation (``306``, ``6306-2RS1/C3``, ``75-313`` ...).
    balls : int, optional
        Number of balls z, replacing the catalogue's.
    ball_diameter : float, optional
        Ball diameter D_w, replacing the catalogue's. [mm]
    pitch_diameter : float, optional
        Pitch diameter d_m; default the catalogue's, else (d + D) / 2. [mm]
    f_i, f_o : float, optional
        Groove conformities r / D_w, replacing the catalogue's. [-]
    maker : str, optional
        Whose ball set to use (see :func:`variant`); default :data:`DEFAULT_MAKER`.

    Returns
    -------
    BearingGeometry
        With ``balls``, ``ball_diameter`` and ``pitch_diameter`` set and checked by
        :func:`check_geometry`; ``overrides`` names the fields the caller set.

    Raises
    ------
    InputError
        Unknown designation (parameter ``bearing``, saying how to give the geometry by hand);
        a catalogued bearing whose ball set is unknown and not given (asking for ``--balls``
        and ``--ball-diameter``); or an impossible geometry.
    """
    row = find(designation) if maker is None else variant(designation, maker)
    given = {
        "balls": balls,
        "ball_diameter": ball_diameter,
        "pitch_diameter": pitch_diameter,
        "f_i": f_i,
        "f_o": f_o,
    }
    changes = {k: v for k, v in given.items() if v is not None}
    new = dataclasses.replace(row, overrides=tuple(changes), **changes)  # type: ignore[arg-type]
    z, dw = new.balls, new.ball_diameter
    dm = (new.d + new.D) / 2.0 if new.pitch_diameter is None else new.pitch_diameter
    if z is None or dw is None:
        missing = [f"'{p}'" for p, v in (("balls", z), ("ball_diameter", dw)) if v is None]
        hint = ""
        other = _counterpart(row.parsed)
        if other is not None and other.has_geometry:
            hint = (
                f", or use the {other.standard} designation {other.designation!r}, "
                "whose ball set is known"
            )
        sets = (
            f" (choose a maker's set with 'maker': {' | '.join(row.makers)})" if row.makers else ""
        )
        raise InputError(
            "bearing",
            f"{row.designation!r} is in the catalogue (d {row.d:g}, D {row.D:g}"
            f"{'' if row.B is None else f', B {row.B:g}'} mm) "
            f"but its ball set is unknown{sets}; give {' and '.join(missing)}{hint}",
        )
    check_geometry(new.d, new.D, z, dw, dm, new.f_i, new.f_o)
    return dataclasses.replace(new, balls=int(z), pitch_diameter=dm)
