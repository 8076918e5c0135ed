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


def spy_forces(seen: dict[str, Any]) -> None:
    """Record in ``seen`` the last solved case's generalised forces ``gen``, the applied ``f``,
    the sums of the terms' magnitudes ``size`` and the ``imposed`` components: from the checks
    of the general path (``combined._checked``) or, for a call the core answers whole (it never
    reaches them), from ``_core.combined_call``'s outputs."""
    import numpy as np

    from bearingload.models import _core, combined

    original = combined._checked

    def spy(p: Any, end: Any, its: Any, given: Any) -> Any:
        out = original(p, end, its, given)
        seen["gen"], seen["f"], seen["size"] = out[1][0], p.f[0], end.size[0]
        seen["imposed"] = p.imposed[0]
        return out

    real_call = _core.combined_call

    def call_spy(*args: Any) -> Any:
        out = real_call(*args)
        if out[0] == _core.CallState.ANSWERED:
            forces = out[1][1]  # (the solve's forces and their terms' sizes: answers_arrays)
            seen["gen"], seen["f"], seen["size"] = forces[0, 0], out[6][0], forces[1, 0]
        seen["imposed"] = np.array([False, False, False, bool(args[3]), False])
        return out

    combined._checked = spy
    _core.combined_call = call_spy
