"""The plan: one place for the decisions of an analysis (which engine solves a case, what is
refused, the warnings and the service lives), above the models and studies and below the front
doors (the command line, batch) that only parse and render. :func:`~bearingload.plan.analyse.
analyse` is its library entry point."""
