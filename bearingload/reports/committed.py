"""The generated errata block of ``docs/errata.md``, rewritten by ``make tables``.

The tables committed under ``tables/`` are not listed here: ``tables/manifest.toml`` names the
``bearingload`` command of each file, ``bearingload tables update tables`` writes them and
``bearingload tables check tables`` (a test) compares them with the code
(:mod:`bearingload.tables_ci`). This module rewrites only the page's marked block
(:func:`bearingload.reports.errata.errata_block`).

Run ``python -m bearingload.reports.committed docs/errata.md``.
"""

from __future__ import annotations

import sys

from bearingload.reports.render import write_atomic


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
    page = sys.argv[1] if len(sys.argv) > 1 else "docs/errata.md"
    print(f"{'rewrote' if update_errata_page(page) else 'unchanged'} errata block of {page}")
