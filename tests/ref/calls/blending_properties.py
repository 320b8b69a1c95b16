"""Valid calls of cagd_ref.blending_properties for the contract test."""

import numpy as np
import sympy as sp

from cagd_ref.blending import ball_basis

from . import Call

T = sp.Symbol("t")
ZIGZAG = [[0.0, -1.0], [1.0, 1.0], [2.0, -1.0], [3.0, 1.0]]

CALLS = {
    "Verdict": Call((True, "a reason")),
    "line_crossings": Call((ZIGZAG, [0.0, 2.0, 0.0])),
    "convex_hull": Call(([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 1.0]],)),
    "distance_outside_hull": Call((ZIGZAG, [[1.0, 0.0], [5.0, 0.0]])),
    "variation_diminishing": Call((ball_basis(np.linspace(0.0, 1.0, 9)),), dict(probes=30, seed=1)),
    "check_properties": Call((ball_basis,), dict(domain=(0.0, 1.0), samples=17, probes=30, tol=1e-9)),
    "symbolic_basis": Call(("ball",)),
    "exact_minimum": Call((T * (1 - T), T), dict(domain=(0.0, 1.0))),
    "symbolic_properties": Call(([1 - T, T], T), dict(domain=(0.0, 1.0))),
}
