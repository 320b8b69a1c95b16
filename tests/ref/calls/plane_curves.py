"""Valid calls of cagd_ref.plane_curves for the contract test (the notes' curves of chapter 19)."""

from . import Call

NODE = [[0.0, 0.0, 3.0], [0.0, 1.0, -2.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]  # x³ - 2xy² + xy + 3y², §19.2
CUBIC = [[-21.0, 25.0, -9.0, 1.0], [46.0, -23.0, 3.0, 0.0], [-13.0, 3.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]]  # §19.5
CIRCLE = [[-4.0, -15.0, 6.0], [-2.0, 0.0, 0.0], [6.0, 0.0, 0.0]]  # Figure 19.5
HYPERBOLA = [[-1.0, 0.0, -1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
UNIT_CIRCLE = [[0.0, 0.0, 1.0], [-2.0, 0.0, 0.0], [1.0, 0.0, 0.0]]  # x² - 2x + y², Figure 19.6
PENCIL = [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [1.0, 0.0, 1.0]]  # x = 2/(1 + t²), y = 2t/(1 + t²)

CALLS = {
    "genus": [Call((3, [2])), Call((4,), dict(multiplicities=(3,)))],
    "implicit_degree": Call((NODE,)),
    "transform_implicit": Call((NODE, [[0.6, 0.8], [-0.8, 0.6]], [1.0, -2.0])),
    "translate_implicit": Call((CUBIC, 2.0, 3.0)),
    "homogeneous_parts": Call((NODE,)),
    "multiplicity": Call((CUBIC, [2.0, 3.0]), dict(tol=1e-9)),
    "tangent_cone": Call((CUBIC, [2.0, 3.0]), dict(tol=1e-9)),
    "tangent_directions": Call((NODE, [0.0, 0.0]), dict(tol=1e-9)),
    "classify_double_point": [Call((NODE, [0.0, 0.0])), Call((CUBIC, [2.0, 3.0]), dict(tol=1e-9))],
    "discriminant": Call(([-5.0, 3.0, 2.0],)),
    "curve_resultant": [Call((CIRCLE, HYPERBOLA)), Call((CIRCLE, HYPERBOLA), dict(eliminate="x"))],
    "curve_discriminant": Call((CUBIC,)),
    "implicit_intersections": Call((CIRCLE, HYPERBOLA), dict(tol=1e-9)),
    "singular_points": Call((CUBIC,), dict(tol=1e-9)),
    "parametrize_by_pencil": [Call((UNIT_CIRCLE, [0.0, 0.0])), Call((CUBIC, [2.0, 3.0]), dict(tol=1e-9))],
    "pencil_point": Call((PENCIL, 0.5), parameter="t"),
    "pencil_bezier": Call((PENCIL, (0.0, 1.0))),
    "conic_through_points": Call(([[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0], [0.6, 0.8]],)),
    "circle_through_points": Call(([1.0, 2.0], [4.0, 6.0], [5.0, -1.0])),
}
