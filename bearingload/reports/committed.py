"""The README's generated errata block, rewritten by ``make tables``.

The tables committed under ``tables/`` are no longer listed here: ``tables/manifest.toml`` names
the ``bearingload`` command of each file, ``bearingload tables update tables`` writes them and
``bearingload tables check tables`` (a test) compares them with the code (:mod:`bearingload.tables_ci`).
This module rewrites only the README's marked block (:func:`bearingload.reports.errata.readme_block`).

Run ``python -m bearingload.reports.committed README.md``.
"""

from __future__ import annotations

import sys

from bearingload.reports.render import write_atomic


def update_readme(path: str) -> bool:
    """Rewrite the generated errata block of the README at ``path``; whether it changed."""
    from bearingload.reports.errata import replace_readme_block

    with open(path, encoding="utf-8") as fh:
        text = fh.read()
    new = replace_readme_block(text)
    if new != text:
        write_atomic(new, path)
    return new != text


if __name__ == "__main__":  # pragma: no cover - exercised by `make tables`
    readme = sys.argv[1] if len(sys.argv) > 1 else "README.md"
    print(f"{'rewrote' if update_readme(readme) else 'unchanged'} errata block of {readme}")
