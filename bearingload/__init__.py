"""bearingload: load distribution among the balls and rollers of a radial rolling bearing.

The main entry points, importable from here (each is loaded on first use, so that a terminal
calculation does not pay for the whole package at start-up)::

    from bearingload import analyse            # a designation and its loads: what solve prints
    from bearingload import analyse_many       # many cases at once, on arrays (batch's way)
    from bearingload import solve              # exact ring equilibrium, degrees in and out
    from bearingload import ring_forces        # the forward problem: force for a displacement
    from bearingload import solve_continuum    # the continuum model (Kuzmenko 2010, §4-5)
    from bearingload import solve_combined     # radial, axial, tilt of a deep-groove bearing
    from bearingload import solve_pair         # a preloaded pair of angular-contact bearings
    from bearingload import solve_high_speed   # one ball bearing at speed (ball dynamics)
    from bearingload import solve_pair_high_speed  # a pair at speed
    from bearingload import compute, list_methods   # any registered model by name
"""

from __future__ import annotations

from typing import Any

__version__ = "0.1.0"

#: public name -> module that defines it
_API = {
    "analyse": "bearingload.plan.analyse",
    "analyse_many": "bearingload.plan.many_cases",
    "Solution": "bearingload.plan.solution",
    "solve": "bearingload.models.equilibrium",
    "LoadDistribution": "bearingload.models.equilibrium",
    "ring_forces": "bearingload.models.forces",
    "RingForces": "bearingload.models.forces",
    "solve_continuum": "bearingload.models.continuum",
    "solve_combined": "bearingload.models.combined",
    "solve_pair": "bearingload.models.pair",
    "solve_high_speed": "bearingload.models.high_speed",
    "solve_pair_high_speed": "bearingload.models.pair_speed",
    "compute": "bearingload.models.registry",
    "compute_all": "bearingload.models.registry",
    "list_methods": "bearingload.models.registry",
    "METHODS": "bearingload.models.registry",
    "InputError": "bearingload.errors",
    "ConflictError": "bearingload.errors",
    "MissingError": "bearingload.errors",
    "UnusedError": "bearingload.errors",
    "ConvergenceError": "bearingload.errors",
    "BearingloadError": "bearingload.errors",
}

__all__ = ["__version__", *_API]


def __getattr__(name: str) -> Any:
    if name in _API:
        import importlib

        value = getattr(importlib.import_module(_API[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'bearingload' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)
