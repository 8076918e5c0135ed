"""Folders of committed tables kept in step with the code, for CI.

A folder holds a ``manifest.toml`` naming, per file, the ``bearingload`` command line that makes it
and its format (:mod:`.manifest`); the files are regenerated in memory and compared with the
committed ones cell by cell, numbers within a relative tolerance (:mod:`.cells`); a check reports
the cells that moved, an update rewrites the files whole or not at all (:mod:`.tableset`).

This package runs no command itself: the caller (``bearingload tables``, :mod:`bearingload.cli`)
hands it a function that produces an entry's text, so it sits below the command line and above
:mod:`bearingload.reports` (whose atomic writer it uses).
"""
