"""Review session 3: defects found by trying to break the recent changes (one test per defect)."""

from __future__ import annotations

import math

import pytest

from bearingload.errors import ConvergenceError
from bearingload.roots import bracketed_root


def test_bracketed_root_does_not_return_a_far_bracket_end_silently():
    # a bracket of 1e300 around a root at 1 cannot be halved to 1e-12 in 400 evaluations: it
    # returned 0.0 (where f = -0.785) as the root; it must raise instead
    with pytest.raises(ConvergenceError):
        bracketed_root(lambda x: math.atan(x - 1.0), 0.0, 1e300)
    # a wide bracket that can be halved in time still gives the root
    assert abs(bracketed_root(lambda x: math.atan(x - 1.0), 0.0, 1e6) - 1.0) <= 4e-12
