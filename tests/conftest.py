"""Shared fixtures of the test suite.

Sections are owned by the tests that use them; add new fixtures in a section of
their own rather than changing one that other test files rely on.
"""

from __future__ import annotations

from math import comb

import numpy as np
import pytest
from numpy.polynomial import Polynomial

# ---------------------------------------------------------------------------
# Core reference modules (test_geometry, test_bezier, test_polynomials,
# test_continuity): independent peers (the contract test checks inputs are not modified).
# ---------------------------------------------------------------------------


def _bezier_polynomials(points, interval=(0.0, 1.0)) -> list[Polynomial]:
    """The coordinates of a Bézier curve as numpy Polynomials in the global parameter t.

    Built directly from the definition B_i^n(s) = C(n, i) (1-s)^(n-i) s^i with
    s = (t - t0) / (t1 - t0), without touching `cagd_ref`, so it can check it.
    """
    pts = np.asarray(points, dtype=float)
    n = len(pts) - 1
    t0, t1 = interval
    s = Polynomial([-t0 / (t1 - t0), 1.0 / (t1 - t0)])
    basis = [comb(n, i) * (1 - s) ** (n - i) * s**i for i in range(n + 1)]
    return [sum((pts[i, k] * basis[i] for i in range(n + 1)), Polynomial([0.0])) for k in range(pts.shape[1])]


@pytest.fixture
def bezier_polynomials():
    """`_bezier_polynomials(points, interval=(0, 1))`: one numpy Polynomial per coordinate."""
    return _bezier_polynomials


@pytest.fixture
def notes_cubic() -> np.ndarray:
    """The control points (4, 2) of the cubic of the notes' hodograph table (§2.7), defined over [0, 1/2].

    A fresh copy of the kept example 02.hodograph_table, so a test may change it.
    """
    from cagd_course.examples import notes_example

    return notes_example("02.hodograph_table").args("points")[0]
