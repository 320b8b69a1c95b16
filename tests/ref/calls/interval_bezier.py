"""Valid calls of cagd_ref.interval_bezier for the contract test (boxes (n+1, d, 2), last axis lo, hi).

`Interval` is a class in `__all__`: its call is the constructor, whose two end points are poisoned in turn.
"""

from . import Call

# The course's cubic: centres (0, 0), (1, 2), (3, 2), (4, 0) with errors (0.1, 0.1), (0.2, 0.1), (0.1, 0.3), (0, 0.2).
BOXES = [
    [[-0.1, 0.1], [-0.1, 0.1]],
    [[0.8, 1.2], [1.9, 2.1]],
    [[2.9, 3.1], [1.7, 2.3]],
    [[4.0, 4.0], [-0.2, 0.2]],
]
CENTERS = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]
ERRORS = [[0.1, 0.1], [0.2, 0.1], [0.1, 0.3], [0.0, 0.2]]
E = 2.718281828459045
QUINTIC = [0.0, 0.25, 0.5, 1.0, 0.5, 1.0]

CALLS = {
    "Interval": Call((1.0, 2.0)),
    "round_outward": Call(([0.1, 1.0], [0.2, 3.0])),
    "interval_expression": Call((("*", [1.0, 2.0], ("+", [-1.0, 0.0], 1.0)),)),
    "boxes_from_center": Call((CENTERS, ERRORS)),
    "center_error": Call((BOXES,)),
    "interval_affine": Call((BOXES[0], BOXES[1], 0.3), parameter="t"),
    "interval_de_casteljau": [Call((BOXES, 0.3), parameter="t"), Call((BOXES, 1.7), parameter="t")],
    "interval_de_casteljau_plain": Call((BOXES, -0.4), parameter="t"),
    "interval_de_casteljau_triangle": Call((BOXES, 0.5)),
    "error_curve": [Call((ERRORS, 0.3), parameter="t"), Call((ERRORS, 2.0), parameter="t")],
    "interval_subdivide": Call((BOXES, 0.4)),
    "interval_elevate": Call((BOXES,), dict(times=2)),
    "interval_polynomial_width": Call((BOXES,)),
    "corner_curves": Call((BOXES,)),
    "envelope_pieces": Call((BOXES,)),
    "lagrange_interval": Call(([0.0, 0.5, 1.0], [1.0, 1.6487212707, E], [1.0, E])),
    "hermite_bezier": Call(([1.0, 1.0], [E, E])),
    "hermite_interval": Call(([1.0, 1.0], [E, E], [1.0, E]), dict(interval=[0.0, 1.0])),
    "derivative_bounds": Call((QUINTIC, 4)),
    "interval_degree_reduce": Call((QUINTIC,), dict(depth=1)),
}
