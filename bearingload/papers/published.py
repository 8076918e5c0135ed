"""Numbers printed in the papers, as shipped data: one CSV file per paper, one row per printed cell.

The files live in ``bearingload/papers/data/published/`` (``<paper>.csv``), in the manner of
pvlib's data fixtures; the tests, the conformance check and ``bearingload errata`` read them from
here, so each printed number is copied once, with its source.

Columns
-------
source          the paper (a key of :data:`SOURCES`)
table           table, equation or section of the paper ("Table 1", "eq. 2.1", "§3.4")
cell            the row/column identifier inside it ("z = 5", "row 2")
quantity        what the number is (``k``, ``K_Q``, ``loaded_balls``, ``q_max``, ``load_zone``,
                ``kz``, ... ; see :mod:`bearingload.papers.errata` for how each is recomputed)
model           the model family it concerns: a method of :mod:`bearingload.models.registry`
                (``exact``, ``continuum``) or the procedure that recomputes it (``hertz``,
                ``fit``, ``life``, ``formula``)
unit            unit of the printed value (``-`` dimensionless)
inputs          the case, ``key=value`` pairs separated by ``;`` (values with units as the
                command line takes them: ``load=300kgf;clearance=20um``)
printed         the value as printed (text, decimal comma made a point)
printed_digits  decimals printed (negative: rounded to tens, hundreds); with an exponent
                (``1.1538e4``) the decimals of the mantissa
exact           ``1`` where the printed number states an exact value (k = 1 for z <= 4): compared
                to 1e-9, not to its printed rounding
note            what else the printed cell needs to be read right
cause           for a cell that differs from the computation: why, where known

Importing this module imports no numpy.
"""

from __future__ import annotations

import csv
from dataclasses import field
from functools import cache
from importlib import resources
from typing import Any

from bearingload.lazy_dataclass import dataclass

#: Paper key (the ``source`` column) -> full citation.
SOURCES = {
    "Kuzmenko 2010": "Kuzmenko A.G. Load distribution between balls in a radial ball bearing. "
    "Problems of Tribology, 2010, no. 1, pp. 29-41.",
    "Kuzmenko & Sabadash 2014": "Kuzmenko A.G., Sabadash B.M. Load distribution between balls "
    "in a radial rolling bearing. Part 2. Variational-experimental method. Problems of "
    "Tribology, 2014.",
}

#: Data file stem -> paper key; the order in which the papers are listed.
FILES = {"kuzmenko2010": "Kuzmenko 2010", "kuzmenko_sabadash2014": "Kuzmenko & Sabadash 2014"}

COLUMNS = (
    "source",
    "table",
    "cell",
    "quantity",
    "model",
    "unit",
    "inputs",
    "printed",
    "printed_digits",
    "exact",
    "note",
    "cause",
)

#: Tolerance of a printed value that states an exact number (``exact`` = 1). [-]
EXACT_TOLERANCE = 1e-9


@dataclass(frozen=True)
class Published:
    """One printed number and what it is.

    Attributes are the CSV columns (see the module docstring); ``inputs`` is parsed into a dict of
    text values (units are converted by the code that uses them).
    """

    source: str
    table: str
    cell: str
    quantity: str
    model: str
    unit: str
    inputs: dict[str, str] = field(hash=False)
    printed: str
    printed_digits: int
    exact: bool
    note: str
    cause: str

    @property
    def value(self) -> float:
        """The printed number. [``unit``]"""
        return float(self.printed)

    @property
    def tolerance(self) -> float:
        """Half a unit of the last printed digit (1e-9 for an exact statement). [``unit``]"""
        if self.exact:
            return EXACT_TOLERANCE
        power = int(self.printed.lower().split("e")[1]) if "e" in self.printed.lower() else 0
        return 0.5 * 10.0 ** (power - self.printed_digits)

    @property
    def key(self) -> tuple[str, str, str]:
        """``(source, table, cell)``: names the row uniquely."""
        return (self.source, self.table, self.cell)

    def agrees(self, computed: float) -> bool:
        """Whether ``computed`` rounds to the printed value (within its printed rounding)."""
        return abs(computed - self.value) <= self.tolerance * (1 + 1e-9)


def parse_inputs(text: str) -> dict[str, str]:
    """``"balls=8;load=300kgf"`` -> ``{"balls": "8", "load": "300kgf"}``."""
    out: dict[str, str] = {}
    for part in filter(None, (p.strip() for p in text.split(";"))):
        name, sep, value = part.partition("=")
        if not sep or not name.strip():
            raise ValueError(f"inputs: {part!r} is not key=value")
        out[name.strip()] = value.strip()
    return out


@cache
def load(paper: str) -> tuple[Published, ...]:
    """The printed values of one paper (a key of :data:`FILES`), in file order."""
    if paper not in FILES:
        raise ValueError(f"unknown paper {paper!r}; known: {', '.join(FILES)}")
    text = (
        resources.files("bearingload.papers")
        .joinpath("data")
        .joinpath("published")
        .joinpath(f"{paper}.csv")
        .read_text(encoding="utf-8")
    )
    reader = csv.DictReader(text.splitlines())
    if tuple(reader.fieldnames or ()) != COLUMNS:
        raise ValueError(f"{paper}.csv: columns {reader.fieldnames}, expected {list(COLUMNS)}")
    rows = []
    for rec in reader:
        rows.append(
            Published(
                source=rec["source"],
                table=rec["table"],
                cell=rec["cell"],
                quantity=rec["quantity"],
                model=rec["model"],
                unit=rec["unit"],
                inputs=parse_inputs(rec["inputs"]),
                printed=rec["printed"],
                printed_digits=int(rec["printed_digits"]),
                exact=rec["exact"] == "1",
                note=rec["note"],
                cause=rec["cause"],
            )
        )
    return tuple(rows)


def all_published() -> tuple[Published, ...]:
    """Every printed value of every paper, papers in :data:`FILES` order."""
    return tuple(row for paper in FILES for row in load(paper))


def select(paper: str, table: str, quantity: str | None = None) -> tuple[Published, ...]:
    """The rows of one table (and quantity) of one paper, in file order."""
    return tuple(
        r for r in load(paper) if r.table == table and (quantity is None or r.quantity == quantity)
    )


def lookup(paper: str, table: str, cell: str) -> Published:
    """The one row ``(table, cell)`` of ``paper``; ``KeyError`` if there is none."""
    for r in load(paper):
        if r.table == table and r.cell == cell:
            return r
    raise KeyError((paper, table, cell))


def printed_row(
    source: str, table: str, cell: str, printed: str, computed: float, resolution: float, cause: str
) -> dict[str, Any]:
    """One errata row: a printed number against the project's value. It agrees when the
    difference is within half a unit of the last printed digit (``resolution``)."""
    diff = float(printed) - computed
    agrees = abs(diff) <= 0.5 * resolution * (1 + 1e-9)
    return {
        "source": source,
        "table": table,
        "cell": cell,
        "printed": printed,
        "computed": computed,
        "difference": diff,
        "verdict": "agrees within printed rounding" if agrees else "differs",
        "cause": "" if agrees else cause,
    }
