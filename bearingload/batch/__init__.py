"""``bearingload batch``: many cases from a csv file, one output row per case.

:mod:`~bearingload.batch.read` reads the file (the ``csv`` module, in chunks) and turns each
column's cells into values; :mod:`~bearingload.batch.solve` solves the rows of a chunk by the
functions ``bearingload solve`` calls for one case, given arrays; :mod:`~bearingload.batch.report`
writes them in solve's columns (through :mod:`bearingload.reports.render`).
"""
