"""Valid calls of cagd_ref.bspline for the contract test (knots in the notes' convention)."""

from . import Call

SIX = [[0.0, 0.0], [1.0, 3.0], [3.0, 4.0], [5.0, 3.5], [7.0, 1.0], [8.0, 0.0]]
KNOTS = [0.0, 0.5, 1.0, 2.0, 3.5, 4.0, 5.0, 6.0]  # a cubic over [1, 4]
END_KNOTS = [0.0, 0.0, 0.0, 1.5, 2.0, 3.0, 3.0, 3.0]  # Bézier end conditions over [0, 3]
SEGMENTS = [[[0.0, 0.0], [1.0, 2.0], [2.0, 2.0], [3.0, 1.0]], [[3.0, 1.0], [4.0, 0.0], [5.0, 1.0], [6.0, 3.0]]]

CALLS = {
    "de_boor": Call((SIX, KNOTS, 2.5), parameter="t"),
    "de_boor_plain": Call((SIX, END_KNOTS, 1.75), parameter="t"),
    "checked_bspline": Call((SIX, KNOTS)),
    "checked_knots": Call((KNOTS, 3)),
    "knot_span": Call((KNOTS, 3, [1.0, 2.5, 4.0])),
    "de_boor_triangle": Call((SIX, KNOTS, 2.5)),
    "insert_knot": Call((SIX, KNOTS, 2.5)),
    "insert_knots": Call((SIX, KNOTS, [1.5, 3.0])),
    "bezier_segments": Call((SIX, END_KNOTS)),
    "bezier_segment_intervals": Call((END_KNOTS, 3)),
    "blossom": Call((SIX, KNOTS, [2.25, 2.5, 3.0])),
    "bezier_blossom": Call((SIX[:4], [0.25, 0.5, 0.75])),
    "power_blossom": Call(([1.0, -2.0, 0.5, 2.0], [0.0, 0.5, 1.0])),
    "bspline_basis": Call((KNOTS, 3, 2, 2.5), parameter="t"),
    # A collocation matrix: one row per parameter, (k, c), for a number t as well (one row), so no shape check.
    "basis_matrix": Call((KNOTS, 3, [1.5, 2.5])),
    "greville": Call((KNOTS, 3)),
    "explicit_bspline": Call(([0.0, 1.0, 0.5, 2.0, 1.0, 0.0], KNOTS)),
    "to_scipy": Call((SIX, KNOTS)),
    "from_scipy": Call(([0.0] + KNOTS + [6.0], SIX, 3)),
    "degree": Call((SIX, KNOTS)),
    "domain": Call((KNOTS, 3)),
    "knot_multiplicities": Call((END_KNOTS,)),
    "continuity_at_knots": Call((END_KNOTS, 3)),
    "hodograph": Call((SIX, KNOTS)),
    "derivative": Call((SIX, KNOTS, 2.5), dict(order=2), parameter="t"),
    "elevate": Call((SIX, END_KNOTS)),
    "polar_values": Call((SIX, KNOTS, [[1.0, 2.0, 3.5], [2.5, 2.5, 3.0]])),
    "elevated_polar_values": Call((SIX, KNOTS, [[1.0, 2.0, 2.5, 3.5]])),
    "bezier_end_knots": Call((6, 3), dict(start=1.0, end=4.0)),
    "periodic_closed": Call((SIX[:5], 3)),
    "circle_approximation": Call((8,)),
    "combine_bezier": Call((SEGMENTS, [[0.0, 1.0], [1.0, 3.0]]), dict(tol=1e-9)),
}
