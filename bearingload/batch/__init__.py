"""``bearingload batch``: many cases from a csv file, one output row per case: read
(:mod:`~bearingload.batch.read`), solved by the plan of many cases (:mod:`~bearingload.batch.
solve`), written in solve's columns (:mod:`~bearingload.batch.report`); docs/batch.md."""
