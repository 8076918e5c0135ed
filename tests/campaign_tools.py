"""What the random campaigns (tests/campaign_*.py; not part of the test suite) share: one case
solved with numpy's warnings as errors, its refusal or non-convergence counted."""

from __future__ import annotations

import warnings
from collections.abc import Callable
from typing import Any

from bearingload.errors import ConvergenceError, InputError


def attempt(
    solve: Callable[..., Any], case: dict[str, Any], counts: dict[str, int], refused: dict[str, int]
) -> Any:
    """``solve(z, fr, fa, **kw)`` of ``case``, or None: a refusal counted (in ``refused`` by its
    parameter), a ConvergenceError counted and printed with the case, and, where ``counts`` has a
    "crash" entry, any other exception too."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            return solve(case["z"], case["fr"], case["fa"], **case["kw"])
    except InputError as err:
        counts["refused"] += 1
        refused[err.parameter] = refused.get(err.parameter, 0) + 1
    except ConvergenceError as err:
        counts["ConvergenceError"] += 1
        print("ConvergenceError:", case, err)
    except Exception as err:  # a campaign counts every failure
        if "crash" not in counts:
            raise
        counts["crash"] += 1
        print("crash:", case, repr(err))
    return None
