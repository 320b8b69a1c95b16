"""Valid calls of cagd_ref.bezier for the contract test."""

from . import Call

CUBIC = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]]
WEIGHTS = [1.0, 2.0, 0.5, 1.5]
SPACE = [[0.0, 0.0, 0.0], [1.0, 2.0, 0.5], [3.0, -1.0, 2.0], [4.0, 1.0, -1.0]]
QUADRATIC = [[0.0, 0.0], [5.0, 0.0], [8.0, 4.0]]

CALLS = {
    "bernstein": Call((1, 3, 0.3), parameter="t"),
    "bernstein_matrix": Call((3, 0.3), parameter="t"),
    "de_casteljau": [Call((CUBIC, 0.3), parameter="t"), Call((SPACE, 1.5), parameter="t")],
    "de_casteljau_plain": [Call((CUBIC, 0.3), parameter="t"), Call((SPACE, -0.5), parameter="t")],
    "de_casteljau_triangle": Call((CUBIC, 0.3)),
    "subdivide": Call((CUBIC, 0.3)),
    "elevate": Call((CUBIC,), dict(times=2)),
    "hodograph": Call((CUBIC, (0.0, 0.5))),
    "evaluate": [
        Call((CUBIC, 0.3), parameter="t"),
        Call((CUBIC, 0.7), dict(weights=WEIGHTS, interval=(0.0, 2.0)), parameter="t"),
    ],
    "derivative": [
        Call((CUBIC, 0.3), dict(order=2, interval=(-1.0, 1.0)), parameter="t"),
        Call((SPACE, 0.3), dict(order=1, weights=WEIGHTS), parameter="t"),
    ],
    "curvature": [Call((CUBIC, 0.3), parameter="t"), Call((SPACE, 0.6), dict(weights=WEIGHTS), parameter="t")],
    "signed_curvature": Call((CUBIC, 0.3), dict(weights=WEIGHTS), parameter="t"),
    "to_homogeneous": Call((CUBIC, WEIGHTS)),
    "from_homogeneous": Call(([[0.0, 0.0, 1.0], [2.0, 4.0, 2.0], [1.5, 1.25, 0.5]],)),
    "endpoint_derivatives": Call((CUBIC,), dict(weights=WEIGHTS, interval=(1.0, 3.0))),
    "endpoint_curvature": Call((QUADRATIC,), dict(weights=[1.0, 2.0, 4.0])),
    "circular_arc": Call(([1.0, 2.0], 1.5, 0.25, 1.0), dict(degree=3)),
    "reparametrize_weights": Call((WEIGHTS, 2.0)),
    "change_interval": Call((0.25, (0.0, 1.0), (5.0, 9.0)), parameter="t"),
    "explicit_bezier": Call(([1.0, -2.0, 0.5],), dict(interval=(-1.0, 3.0))),
    "explicit_rational_bezier": Call(([1.0, -2.0, 0.5], [1.0, 2.0, 1.5])),
    "difference_bound": Call((CUBIC, QUADRATIC)),
    "hausdorff_distance": Call((CUBIC, QUADRATIC), dict(samples=51)),
    "directed_hausdorff": Call((CUBIC, QUADRATIC), dict(samples=51)),
    "extreme_parameters": Call((CUBIC,), dict(weights=WEIGHTS)),
    "bounding_box": [Call((CUBIC,)), Call((SPACE,), dict(weights=WEIGHTS))],
    "arc_length": Call((CUBIC,), dict(weights=WEIGHTS, tol=1e-10)),
}
