"""``bearingload batch``: many cases from a csv file, one output row per case.

:mod:`~bearingload.batch.read` reads the file (the ``csv`` module, in chunks) and each cell by
its input's reader (:data:`bearingload.plan.inputs.READERS`); :mod:`~bearingload.batch.solve`
gives a chunk's columns to the plan of many cases (:mod:`bearingload.plan.many`);
:mod:`~bearingload.batch.report` writes them in solve's columns (through
:mod:`bearingload.reports.render`).
"""
