"""Valid calls of cagd_ref.knot_intervals for the contract test: open curves (degree=None) and closed ones."""

from . import Call

OPEN = [[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [5.0, 2.5], [7.0, 0.5], [8.0, -1.0]]
OPEN_INTERVALS = [0.5, 1.0, 1.5, 2.0, 1.0, 1.0, 0.5]  # a cubic: c + n - 2 = 7 intervals
QUADRATIC_INTERVALS = [1.0, 2.0, 0.5, 1.5, 1.0, 1.0]  # the same six points as a quadratic
PENTAGON = [[0.0, 2.0], [2.0, 0.5], [1.5, -2.0], [-1.5, -2.0], [-2.0, 0.5]]
PENTAGON_INTERVALS = [2.0, 1.0, 0.5, 1.5, 1.0]  # one per point of a closed curve

CALLS = {
    "intervals_from_knots": Call(([1.0, 2.0, 3.0, 4.0, 6.0],)),
    "knots_from_intervals": Call((OPEN_INTERVALS,), dict(start=1.0)),
    "closed_to_open": Call((PENTAGON, PENTAGON_INTERVALS, 3)),
    "split_interval": [
        Call((OPEN, OPEN_INTERVALS, 4, 0.25)),
        Call((PENTAGON, PENTAGON_INTERVALS, 0, 0.25), dict(degree=3)),
    ],
    "expose_bezier": [Call((OPEN, OPEN_INTERVALS)), Call((PENTAGON, PENTAGON_INTERVALS), dict(degree=3))],
    "halve_intervals": [Call((OPEN, OPEN_INTERVALS)), Call((PENTAGON, PENTAGON_INTERVALS), dict(degree=3))],
    "quadratic_bezier_points": [
        Call((OPEN, QUADRATIC_INTERVALS)),
        Call((PENTAGON, PENTAGON_INTERVALS), dict(degree=2)),
    ],
    "hodograph_intervals": [Call((OPEN, OPEN_INTERVALS)), Call((PENTAGON, PENTAGON_INTERVALS), dict(degree=3))],
    "elevate_intervals": [Call((OPEN, OPEN_INTERVALS)), Call((PENTAGON, PENTAGON_INTERVALS), dict(degree=2))],
    "cubic_basis_from_intervals": Call(([1.0, 2.0, 0.5, 3.0], 2.5), parameter="t"),
    "refine_basis": Call(([0.0, 1.0, 2.5, 4.0, 6.0], 2.2)),
}
