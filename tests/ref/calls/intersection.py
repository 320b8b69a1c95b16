"""Valid calls of cagd_ref.intersection for the contract test."""

from . import Call

CUBIC = [[0.0, 0.0], [2.0, 1.0], [6.0, -2.0], [12.0, 0.0]]
OTHER = [[2.0, -5.0], [3.0, -1.0], [10.0, 2.0], [4.0, 3.0]]
QUARTER = [[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
QUARTER_W = [1.0, 0.7071067811865476, 1.0]
CIRCLE = [[-1.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
QUARTIC = [[2.0, 3.0], [4.0, 6.0], [4.0, 8.0], [8.0, 5.0], [10.0, 9.0]]
QUARTIC_W = [1.0, 3.0, 1.0, 4.0, 1.0]
RATIONAL_PAIR = {"tol": 1e-9, "p_weights": QUARTER_W, "q_weights": [1.0, 2.0, 1.0, 1.0]}

CALLS = {
    "homogeneous_circle_point": Call(([0.0, 0.5, 1.0], 1.0)),
    "circle_conic": Call(([1.0, 2.0], 3.0)),
    "line_intersection": Call(([2.0, 1.0, -7.0], [-1.0, -1.0, 5.0])),
    "project": Call(([-2.0, -3.0, -1.0],)),
    "implicit_polynomial": [
        Call((CIRCLE, [-1.0, 2.0], [1.0, -9.0, 8.0])),
        Call(([[1.0, 1.0], [2.0, 0.0], [1.0, 0.0]], [0.0, 1.0, 1.0], [0.0, 2.0], [1.0, 0.0, 1.0])),
    ],
    "curve_implicit_bernstein": Call((CIRCLE, QUARTER, QUARTER_W)),
    "curve_implicit_intersection": Call((CIRCLE, [[-1.0, 1.0], [0.0, -3.5], [1.0, 0.0]]), {"tol": 1e-12}),
    "osculating_circle_curvature": Call(([[0.0, 0.0], [2.0, 0.0], [3.0, 1.5], [5.0, 4.0]], [1.5, 0.7, 2.0, 1.0])),
    "flatness": Call((CUBIC,)),
    "intersect_by_subdivision": Call((OTHER, CUBIC), {"tol": 1e-9}),
    "monotone_breaks": Call((CUBIC,)),
    "intersect_by_intervals": Call((OTHER, CUBIC), {"tol": 1e-9}),
    "implicit_by_nullspace": Call((QUARTER, QUARTER_W)),
    "intersect_by_implicitization": Call((QUARTER, OTHER), RATIONAL_PAIR),
    "fat_line": Call((CUBIC,)),
    "perpendicular_fat_line": Call((CUBIC,)),
    "clip_range": Call(([-5.0, -1.0, 2.0, 3.0], -2.0, 1.0)),
    "clip_curve": Call((QUARTER, [0.0, 1.0, -0.5], -0.1, 0.1), {"weights": QUARTER_W}),
    "homogeneous_fat_line": Call((QUARTIC, QUARTIC_W)),
    "explicit_meets": Call(([-40.0, -56.0, -20.0, 96.0, 294.0],)),
    "clip_one_sided": Call(([6.0, -8.0, 40.0], QUARTIC, QUARTIC_W)),
    "clip_trace": Call((QUARTER, OTHER), RATIONAL_PAIR),
    "search_steps": Call((OTHER, CUBIC, "intervals"), {"tol": 1e-9}),
    "curve_piece": Call((QUARTER, [0.25, 0.75]), {"weights": QUARTER_W}),
    "intersect_curves": Call((QUARTER, OTHER), RATIONAL_PAIR),
    "bezier_clipping": Call((QUARTER, OTHER), RATIONAL_PAIR),
    "merge_touching": Call(([((0.25, 0.5), (0.0, 0.25)), ((0.5, 0.75), (0.25, 0.5))],), {"gap": 1e-6}),
}
