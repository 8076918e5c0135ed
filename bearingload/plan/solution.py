"""The answer of the plan: the solved cases of one analysis with their service lives, as the
json document of ``bearingload solve`` (:meth:`Solution.to_dict`), as attributes of the same
names, and rendered in any format of the command line (:meth:`Solution.report`)."""

from __future__ import annotations

import functools
from typing import Any

from bearingload.lazy_dataclass import dataclass


@dataclass(frozen=True, eq=False)
class Solution:
    """The solved cases of one analysis.

    Attributes
    ----------
    engine : {"radial", "combined", "pair"}
        The engine that solved them (:mod:`bearingload.plan.solve`).
    cases : tuple
        One solved case per clearance (three for the clearance pick 'range', else one; a
        pair: its one :class:`bearingload.studies.bearing_pair.PairCase`).
    service : tuple or None
        The service lives of each case, or of each bearing of a pair (None: a ring by hand).
    pair_lives : PairLives or None
        A pair's: its bearings' service lives and the pair's from them
        (:class:`bearingload.studies.bearing_pair.PairLives`); None for one bearing.

    Every key of a case of :meth:`to_dict` is an attribute too: ``solution.q_max`` is
    ``solution.to_dict()["cases"][0]["q_max"]`` for one case, the list of the cases' values for
    several; but ``engine``, ``cases``, ``service``, ``warnings`` and ``units`` are the
    solution's own (the cases' warnings are ``to_dict()["cases"][i]["warnings"]``). Two
    solutions compare by identity.
    """

    engine: str
    cases: tuple[Any, ...]
    service: tuple[Any, ...] | None = None
    pair_lives: Any = None

    @functools.cached_property
    def _document(self) -> dict[str, Any]:
        from bearingload.reports.render import plain_tree

        if self.engine == "pair":
            from bearingload.reports.pair import pair_document

            return dict(plain_tree(pair_document(self.cases[0], self.pair_lives)))
        if self.engine == "combined":
            from bearingload.reports.combined import combined_document

            return dict(plain_tree(combined_document(list(self.cases), self.service)))
        from bearingload.reports.solve import solve_document

        return dict(plain_tree(solve_document(list(self.cases), self.service)))

    def to_dict(self) -> dict[str, Any]:
        """What ``bearingload solve --format json`` prints, as a dict at full precision
        (``cases``, ``units``, ``warnings`` and, for a catalogue bearing, ``bearing``)."""
        import copy

        return copy.deepcopy(self._document)

    @property
    def warnings(self) -> list[str]:
        """The warnings of the analysis, each once, as the terminal prints them (json's
        ``warnings``)."""
        from bearingload.reports.solve import printed_warnings

        if self.engine == "pair":
            found = list(self.cases[0].warnings)
        elif self.engine == "combined":
            from bearingload.reports.combined import collect_combined_warnings

            found = collect_combined_warnings(list(self.cases))
        else:
            from bearingload.studies.loaded_bearing import collect_warnings

            found = collect_warnings(list(self.cases))
        return list(printed_warnings(found, self.service))

    @property
    def units(self) -> dict[str, str]:
        """The unit of every key of the cases."""
        return dict(self._document["units"])

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        found = [c[name] for c in self._document["cases"] if name in c]
        if not found:
            raise AttributeError(f"the solution has no quantity {name!r}")
        return found[0] if len(self._document["cases"]) == 1 else found

    def report(
        self, fmt: str = "table", *, per_ball: bool = False, show_geometry: bool = False
    ) -> str:
        """The solution rendered as ``bearingload solve`` prints it: ``fmt`` one of table, csv,
        markdown, json; ``per_ball``: csv one row per ball (the exact model's balls: an
        InputError where no case has them); ``show_geometry``: the geometry used, with the
        source of every value."""
        if (
            per_ball
            and self.engine == "radial"
            and all(c.result.method != "exact" for c in self.cases)
        ):
            from bearingload.errors import InputError

            method = self.cases[0].result.method
            raise InputError(
                "per_ball",
                f"the ball loads are the exact model's; 'method' {method} gives none (use "
                "'method' exact or all)",
            )
        options: dict[str, Any] = {"per_ball": per_ball, "show_geometry": show_geometry}
        if self.engine == "pair":
            from bearingload.reports.pair import pair_report

            return pair_report(self.cases[0], fmt, **options, lives=self.pair_lives)
        options["service"] = self.service
        if self.engine == "combined":
            from bearingload.reports.combined import combined_report

            return combined_report(list(self.cases), fmt, **options)
        from bearingload.reports.solve import solve_report

        return solve_report(list(self.cases), fmt, **options)

    def figure(self) -> Any:
        """The ball loads of this solution as a matplotlib figure (imported only here)."""
        from bearingload.reports import plots

        if self.engine == "pair":
            raise ValueError("the figure draws the ball loads of one bearing, not of a pair")
        if self.engine == "radial" and all(c.result.method != "exact" for c in self.cases):
            raise ValueError(
                "the figure draws the ball loads of the exact model; this method has none"
            )
        draw = plots.combined_loads_figure if self.engine == "combined" else plots.solve_figure
        return draw(list(self.cases))
