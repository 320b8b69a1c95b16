"""Valid calls of cagd_ref.hybrid for the contract test (planar curves; rational ones with positive weights)."""

from cagd_ref.hybrid import hybrid_curve

from . import Call

SEMICIRCLE = [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]]
WEIGHTS = [3.0, 1.0, 1.0, 3.0]
CUBIC = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]]
QUARTIC_HYBRID = hybrid_curve(SEMICIRCLE, WEIGHTS, 4)

CALLS = {
    # The result types are plain records: they take whatever they are given.
    "HybridCurve": Call(tuple(QUARTIC_HYBRID), finite_only=("*",)),
    "Integral": Call((0.5, 1e-9, 3, 5), finite_only=("*",)),
    "Area": Call((0.5, 1e-10, 1e-9), finite_only=("*",)),
    "hybrid_curve": [Call((SEMICIRCLE, WEIGHTS, 4)), Call((CUBIC, WEIGHTS, 3), dict(m=2))],
    "hybrid_point": Call((QUARTIC_HYBRID, 0.3), parameter="t"),
    "moving_box": Call((QUARTIC_HYBRID,)),
    "polynomial_approximation": Call((SEMICIRCLE, WEIGHTS, 4)),
    "max_bernstein": Call((4, 2)),
    "area_matrix": Call((3,)),
    "moment_tensor": Call((3,)),
    "polynomial_area": Call((CUBIC,)),
    "sector_area": Call((CUBIC,)),
    "first_moments": Call((CUBIC,)),
    "revolution_volume": Call((CUBIC,)),
    "polynomial_integral": [Call((CUBIC,), dict(kind="sector")), Call((CUBIC,), dict(kind="volume"))],
    "integral_error_bounds": Call((SEMICIRCLE, WEIGHTS), dict(degree=4)),
    "adaptive_integral": [Call((SEMICIRCLE, WEIGHTS), dict(tol=1e-6)),
                          Call((CUBIC, WEIGHTS), dict(tol=1e-6, kind="volume"))],
    "adaptive_area_plain": Call((SEMICIRCLE, WEIGHTS), dict(tol=1e-6)),
    "bezier_area": [Call((SEMICIRCLE, WEIGHTS), dict(tol=1e-6)), Call((CUBIC,), dict(tol=1e-6))],
    "trapezoid_area": Call((SEMICIRCLE, WEIGHTS), dict(tol=1e-4)),
    "simpson_area": Call((SEMICIRCLE, WEIGHTS), dict(tol=1e-6)),
}
