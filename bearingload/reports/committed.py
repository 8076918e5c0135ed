"""The tables committed under ``tables/``: one registry, written by ``make tables``, checked by tests.

Each entry maps a file stem to a function returning the :class:`~bearingload.reports.render.Table`;
every table is written as CSV (for diffs and scripts) and Markdown (for people).

Run ``python -m bearingload.reports.committed DIR [--errata docs/errata.md]`` to (re)write them
(and the generated errata block of that page, :func:`bearingload.reports.errata.errata_block`).
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable

from bearingload.reports.render import Table, render, write_atomic


def _registry() -> dict[str, Callable[[], Table]]:
    from bearingload.reports.errata import errata_table
    from bearingload.reports.tables import design_table, kuzmenko2010_306_table, table_k, table_kq
    from bearingload.studies.accuracy import accuracy_table
    from bearingload.studies.compliance import fit_table
    from bearingload.studies.errata import errata_rows
    from bearingload.studies.kurochkin_errata import differences_table, example1_moment_table
    from bearingload.studies.life_clearance import life_vs_clearance_table
    from bearingload.studies.stiffness import stiffness_table

    return {
        "table1_k_zero_clearance": lambda: table_k(30),
        "table2_kq_zero_clearance": lambda: table_kq(30),
        # bearing 306 at the conditions of Kuzmenko (2010) with the exact Hertz stiffness
        "table1_k_306_300kgf_gr20um": lambda: kuzmenko2010_306_table("k", 0.020),
        "table2_kq_306_300kgf_gr20um": lambda: kuzmenko2010_306_table("kq", 0.020),
        "table1_k_306_300kgf_gr100um": lambda: kuzmenko2010_306_table("k", 0.100),
        "table2_kq_306_300kgf_gr100um": lambda: kuzmenko2010_306_table("kq", 0.100),
        # exact, continuum, Stribeck and Palmgren side by side, Table 1 conditions
        "k_methods_zero_clearance": lambda: design_table("k", 30, method="all"),
        # the papers of the turning cage: Kurochkin 1973 cells that differ, the compliance abstract fits, the crane paper (2009) stiffness
        "kurochkin1973_differences": differences_table,
        "kurochkin1973_example1": example1_moment_table,
        "compliance_fits": fit_table,
        "stiffness_crane2009": stiffness_table,
        # every printed number the project recomputes (bearingload errata)
        "errata": lambda: errata_table(errata_rows()),
        # ISO/TS 16281 L10r against clearance, 6205, radial and combined load
        "life_vs_clearance_6205": life_vs_clearance_table,
        # work-precision of every method: errors and iterations, no times
        "accuracy": accuracy_table,
    }


def generate() -> dict[str, str]:
    """File name -> content of every committed table."""
    files = {}
    for stem, build in _registry().items():
        table = build()
        files[f"{stem}.csv"] = render([table], "csv")
        files[f"{stem}.md"] = render([table], "markdown")
    return files


def write_all(directory: str) -> list[str]:
    """Write every committed table into ``directory``; returns the file names written."""
    os.makedirs(directory, exist_ok=True)
    files = generate()
    for name, text in files.items():
        write_atomic(text, os.path.join(directory, name))
    return sorted(files)


def update_errata_page(path: str) -> bool:
    """Rewrite the generated errata block of the page at ``path``; whether it changed."""
    from bearingload.reports.errata import replace_errata_block

    with open(path, encoding="utf-8") as fh:
        text = fh.read()
    new = replace_errata_block(text)
    if new != text:
        write_atomic(new, path)
    return new != text


if __name__ == "__main__":  # pragma: no cover - exercised by `make tables`
    args = sys.argv[1:]
    page = None
    if "--errata" in args:
        at = args.index("--errata")
        page = args[at + 1]
        del args[at : at + 2]
    target = args[0] if args else "tables"
    for name in write_all(target):
        print(f"wrote {os.path.join(target, name)}")
    if page is not None:
        print(f"{'rewrote' if update_errata_page(page) else 'unchanged'} errata block of {page}")
