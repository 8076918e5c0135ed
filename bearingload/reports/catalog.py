"""Rows of the bearing catalogue for people and scripts: the list, and one entry with sources.

Units: diameters and widths [mm], load ratings [kN] in the list and [N] in one entry.
"""

from __future__ import annotations

from typing import Any

from bearingload.bearings.catalog import BearingGeometry, entries, find, sealed, variant
from bearingload.errors import InputError
from bearingload.reports.render import Column, Table, render


def catalog_list(
    fmt: str,
    series: str | None = None,
    standard: str | None = None,
    bore: float | None = None,
) -> str:
    """The catalogue rows, filtered as :func:`bearingload.bearings.catalog.entries`, rendered in ``fmt``."""
    rows = [_row(b) for b in entries(series=series, standard=standard, bore=bore)]
    filters = [
        f"{k} {v:g}" if isinstance(v, float) else f"{k} {v}"
        for k, v in (("series", series), ("standard", standard), ("bore", bore))
        if v is not None
    ]
    title = "Deep groove ball bearings in the catalogue"
    if filters:
        title += f" ({', '.join(filters)})"
    table = Table(
        title=title,
        columns=[
            Column("designation", "bearing", align="left"),
            Column("standard", "std", align="left"),
            *_ring_columns(),
            Column("f_i", "f_i", "-", 3),
            Column("f_o", "f_o", "-", 3),
            *_rating_columns(),
            Column("maker", "ball set", align="left"),
        ],
        rows=rows,
        notes=[
            f"{len(rows)} bearings; '-': ball set unknown (give --balls and --ball-diameter, "
            "or --maker). Sources of each row and the makers' sets: bearingload catalog show "
            "DESIGNATION. Cylindrical roller bearings NU/N 203-220, 303-320: catalog show NU206. "
            "Angular-contact ball bearings: catalog --type angular."
        ],
    )
    return render([table], fmt)


def _ring_columns() -> list[Column]:
    """d, D, B, z, D_w and d_m: the columns of a catalogue row's rings and ball set."""
    return [Column("d", "d", "mm", 5), Column("D", "D", "mm", 5), Column("B", "B", "mm", 5),
            Column("balls", "z"), Column("ball_diameter", "D_w", "mm", 5),
            Column("pitch_diameter", "d_m", "mm", 5)]  # fmt: skip


def _rating_columns() -> list[Column]:
    """C and C0: the basic load ratings of a catalogue row."""
    return [Column("C", "C", "N", 5), Column("C0", "C0", "N", 5)]


def angular_list(fmt: str, bore: float | None = None) -> str:
    """The angular-contact rows (:func:`bearingload.bearings.angular.angular_rows`), those of
    bore ``bore`` [mm] where given, rendered in ``fmt``."""
    from bearingload.bearings.angular import angular_rows
    from bearingload.bearings.catalog import checked_bore

    bore = None if bore is None else checked_bore(bore)
    rows = [
        {"designation": r.designation, "contact_angle": r.contact_angle, "d": r.d, "D": r.D,
         "B": r.B, "balls": r.balls, "ball_diameter": r.ball_diameter,
         "pitch_diameter": r.pitch_diameter, "C": r.C, "C0": r.C0,
         "maker": f"{r.maker} ({r.method})"}
        for r in angular_rows()
        if bore is None or abs(r.d - bore) < 1e-9
    ]  # fmt: skip
    title = "Single-row angular-contact ball bearings in the catalogue"
    if bore is not None:
        title += f" (bore {bore:g})"
    table = Table(
        title=title,
        columns=[
            Column("designation", "bearing", align="left"),
            Column("contact_angle", "alpha_0", "°", 3),
            *_ring_columns(),
            *_rating_columns(),
            Column("maker", "ratings, ball set", align="left"),
        ],
        rows=rows,
        notes=[
            f"{len(rows)} bearings; f_i = 0.52, f_o = 0.53 assumed (not printed by the source). "
            "Sources: bearingload catalog show DESIGNATION (where NSK and Koyo both have a row, "
            "NSK's is used unless --maker KOYO). GOST 36xxx (12°), 46xxx (26°), 66xxx (36°): "
            "EPK's rows where a ball set fits the printed ratings (ZAP's for sizes EPK does not "
            "print, and 46205). 25° (AC, A5): NSK's 79, 70 and 72 rows (7205AC finds 7205A5); "
            "none of the 73 series: give the ring by hand with solve --contact-angle "
            "(docs/angular_contact.md). The 79 series (15° and 25°): NSK's rows only."
        ],
    )
    return render([table], fmt)


def _angular_entry(designation: str, fmt: str, maker: str | None) -> str | None:
    """The entry of an angular-contact designation, or None when ``designation`` is not one."""
    from bearingload.bearings.angular import find_angular, parse_angular, refuse_gost_suffix

    parsed = parse_angular(designation)
    if parsed is None:
        refuse_gost_suffix(designation)  # 36205K: the type is modelled, the suffix is not read
        return None
    r = find_angular(parsed, maker)  # as solve 7205B --maker
    fields: list[tuple[str, str, Any, str]] = [
        ("designation", "designation", r.designation, ""),
        ("as_typed", "as typed", parsed.text, ""),
        ("contact_angle", "nominal contact angle alpha_0", r.contact_angle, "°"),
        ("d", "bore d", r.d, "mm"),
        ("D", "outside diameter D", r.D, "mm"),
        ("B", "width B", r.B, "mm"),
        ("balls", "balls z", r.balls, ""),
        ("ball_diameter", "ball diameter D_w", r.ball_diameter, "mm"),
        ("pitch_diameter", "pitch diameter d_m", r.pitch_diameter, "mm"),
        ("C", "dynamic load rating C", r.C, "N"),
        ("C0", "static load rating C0", r.C0, "N"),
        *([("f0", "factor f0 (C0 = f0 z D_w^2 cos alpha_0)", r.f0, "")] if r.f0 else []),
        ("maker", "ratings of maker", r.maker, ""),
        ("method", "ball set read/derived", r.method, ""),
        ("confidence", "ball set confidence", r.confidence, ""),
        *_speed_fields(r.limiting_speed_grease, r.limiting_speed_oil),
    ]
    title = f"Angular-contact ball bearing {r.designation}, contact angle {r.contact_angle:g}°"
    speeds = _speed_source(r.limiting_speed_grease, r.limiting_speed_source, False)
    return _entry(title, fields, r.source, r.notes, fmt, speeds)


def _row(b: BearingGeometry) -> dict[str, Any]:
    return {
        "designation": b.designation,
        "standard": b.standard,
        "d": b.d,
        "D": b.D,
        "B": _or_dash(b.B),
        "balls": b.balls if b.balls is not None else "-",
        "ball_diameter": b.ball_diameter if b.ball_diameter is not None else "-",
        "pitch_diameter": b.pitch_diameter if b.pitch_diameter is not None else "-",
        "f_i": b.f_i,
        "f_o": b.f_o,
        "C": b.C if b.C is not None else "-",
        "C0": b.C0 if b.C0 is not None else "-",
        "maker": f"{b.maker} ({b.method})" if b.maker else "-",
    }


def catalog_entry(designation: str, fmt: str, maker: str | None = None) -> str:
    """One catalogue entry with its sources and notes, rendered in ``fmt``.

    ``maker`` shows that maker's ball set and ratings instead of the default.

    Raises
    ------
    InputError
        (parameter ``bearing``) unknown or unreadable designation; (``maker``) no such set.
    """
    from bearingload.bearings.designation import parse

    angular = _angular_entry(designation, fmt, maker)
    if angular is not None:
        return angular
    try:
        roller = parse(designation).kind == "roller"
    except InputError:
        roller = False  # find() raises with the full hint
    if roller:
        return _roller_entry(designation, fmt, maker)
    b = find(designation) if maker is None else variant(designation, maker)
    p = b.parsed
    fields: list[tuple[str, str, Any, str]] = [
        ("designation", "designation", b.designation, ""),
        ("standard", "standard", b.standard, ""),
        ("iso_name", "ISO name", p.iso_name, ""),
        ("gost_name", "GOST name", p.gost_name or "-", ""),
        ("series", "dimension series", b.series, ""),
        ("d", "bore d", b.d, "mm"),
        ("D", "outside diameter D", b.D, "mm"),
        ("B", "width B", _or_dash(b.B), "mm"),
        ("balls", "balls z", b.balls if b.balls is not None else "-", ""),
        ("ball_diameter", "ball diameter D_w", _or_dash(b.ball_diameter), "mm"),
        ("pitch_diameter", "pitch diameter d_m", _or_dash(b.pitch_diameter), "mm"),
        ("f_i", "inner conformity f_i", b.f_i, "-"),
        ("f_o", "outer conformity f_o", b.f_o, "-"),
        ("C", "dynamic load rating C", _or_dash(b.C), "N"),
        ("C0", "static load rating C0", _or_dash(b.C0), "N"),
        ("f0", "factor f0 (C0 = f0 z D_w^2)", _or_dash(b.f0), "N/mm^2"),
        ("maker", "ball set of maker", b.maker or "-", ""),
        ("method", "ball set read/derived", b.method or "-", ""),
        ("makers", "makers (--maker)", ", ".join(b.makers) or "-", ""),
        ("clearance_class", "clearance class marked", p.clearance_class or "none (CN)", ""),
        *_speed_fields(b.limiting_speed_grease, b.limiting_speed_oil),
    ]
    title = f"Bearing {b.designation} ({b.standard})"
    speeds = _speed_source(b.limiting_speed_grease, b.limiting_speed_source, sealed(p.suffixes))
    return _entry(title, fields, b.source, b.notes, fmt, speeds)


def _speed_fields(grease: float | None, oil: float | None) -> list[tuple[str, str, Any, str]]:
    """The limiting speeds of a catalogue row as entry fields (``-`` where none was read)."""
    return [
        ("limiting_speed_grease", "limiting speed, grease", _or_dash(grease), "rpm"),
        ("limiting_speed_oil", "limiting speed, oil", _or_dash(oil), "rpm"),
    ]


def _speed_source(grease: float | None, source: str, is_sealed: bool) -> str:
    """Where the limiting speeds come from, and whether solve warns on them."""
    if grease is None:
        return "none read for this row (solve --speed gives no limiting-speed warning)"
    if is_sealed:
        return (f"{source}; those of the open bearing: a seal lowers them, so solve --speed "
                "warns above them, where this sealed bearing's own limit is passed too")  # fmt: skip
    return source


def _roller_entry(designation: str, fmt: str, maker: str | None) -> str:
    from bearingload.bearings.rollers import lookup

    if maker is not None:
        raise InputError("maker", "the roller bearings have one design each (SKF ECP)")
    r = lookup(designation)
    fields: list[tuple[str, str, Any, str]] = [
        ("designation", "designation", r.designation, ""),
        ("iso_name", "as typed", r.parsed.iso_name, ""),
        ("d", "bore d", r.d, "mm"),
        ("D", "outside diameter D", r.D, "mm"),
        ("B", "width B", r.B, "mm"),
        ("F", "inner raceway diameter F", r.F, "mm"),
        ("E", "outer raceway diameter E", r.E, "mm"),
        ("rollers", "rollers z", r.rollers, ""),
        ("roller_diameter", "roller diameter D_w", r.roller_diameter, "mm"),
        ("pitch_diameter", "pitch diameter d_m", r.pitch_diameter, "mm"),
        ("roller_length", "effective length L_we", r.roller_length, "mm"),
        ("C", "dynamic load rating C", r.C, "N"),
        ("C0", "static load rating C0", r.C0, "N"),
        ("method", "roller count read/derived", r.method, ""),
    ]
    title = f"Cylindrical roller bearing {r.designation} (ISO)"
    return _entry(title, fields, r.source, r.notes, fmt)


def _entry(
    title: str, fields: list[tuple[str, str, Any, str]], source: str, notes: str, fmt: str,
    speeds: str | None = None,
) -> str:  # fmt: skip
    """One entry: ``fields`` (key, label, value, unit), its source and notes, and where its
    limiting speeds come from (``speeds``; None: the entry has none)."""
    if fmt == "json":
        doc: dict[str, Any] = {key: value for key, _, value, _ in fields}
        doc["source"] = source
        doc["notes"] = notes
        if speeds is not None:
            doc["limiting_speed_source"] = speeds
        doc["units"] = {key: unit for key, _, _, unit in fields if unit}
        return render([], "json", document=doc)
    table = Table(
        title=title,
        columns=[
            Column("quantity", "quantity", align="left"),
            Column("value", "value", digits=6, align="left"),
            Column("unit", "unit", align="left"),
        ],
        rows=[{"quantity": label, "value": v, "unit": u} for _, label, v, u in fields],
        notes=[f"source: {source}", f"notes: {notes or '-'}"]
        + ([] if speeds is None else [f"limiting speeds: {speeds}"]),
    )
    return render([table], fmt)


def _or_dash(value: float | None) -> float | str:
    return "-" if value is None else value
