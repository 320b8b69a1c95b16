"""Valid calls of cagd_ref.surfaces for the contract test.

Patch functions take the pair (s, t); the contract test varies the parameter it is given, s, while t stays
a number, which broadcasts to every value of s: k values of s give k pairs and (k, d) results.
"""

from . import Call

PATCH = [[[0.0, 0.0, 0.0], [0.0, 2.0, 0.0]], [[1.0, 0.0, 1.0], [1.0, 2.0, 2.0]], [[2.0, 0.0, 0.0], [2.0, 2.0, 1.0]]]
PATCH_WEIGHTS = [[1.0, 1.0], [2.0, 3.0], [1.0, 1.0]]
CUBIC = [[0.0, 0.0, 0.0], [1.0, 2.0, 0.0], [3.0, 3.0, 1.0], [4.0, 0.0, 2.0]]
CUBIC_WEIGHTS = [1.0, 2.0, 0.5, 1.0]
# Chapter 15: the patch continued C^1 across s = 1, a NURBS surface of degree (2, 1) on 4 × 3 control points
# (the notes' convention, c + degree - 1 knots: 0..4 in s, 0 1 2 in t), a quadratic triangle.
PATCH_NEXT = [[[2.0, 0.0, 0.0], [2.0, 2.0, 1.0]], [[3.0, 0.0, -1.0], [3.0, 2.0, 0.0]],
              [[4.0, 0.0, 0.0], [4.0, 2.0, 0.0]]]
NURBS = [[[float(i), float(j), float((i * j) % 3)] for j in range(3)] for i in range(4)]
NURBS_WEIGHTS = [[1.0, 2.0, 1.0], [1.5, 1.0, 0.5], [1.0, 1.0, 2.0], [0.5, 1.0, 1.0]]
KNOTS_S = [0.0, 1.0, 2.0, 3.0, 4.0]
KNOTS_T = [0.0, 1.0, 2.0]
TRIANGLE = [[[0.0, 0.0, 0.0], [0.0, 1.0, 0.2], [0.0, 2.0, 1.0]], [[1.0, 0.0, 0.1], [1.0, 1.0, 0.5], [0.0, 0.0, 0.0]],
            [[2.0, 0.0, 1.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]]
TRIANGLE_WEIGHTS = [[1.0, 2.0, 1.0], [0.5, 1.0, 1.0], [1.0, 1.0, 1.0]]


def _patch_calls():
    return [Call((PATCH, 0.3, 0.6), parameter="s"), Call((PATCH, 0.3, 0.6, PATCH_WEIGHTS), parameter="s")]


CALLS = {
    "patch_point": _patch_calls(),
    "patch_normal": _patch_calls(),
    "patch_point_tangents": _patch_calls(),
    "de_casteljau_point_tangents": _patch_calls(),
    "grid_point_tangents": [Call((PATCH, 3, 4)), Call((PATCH, 3, 4, PATCH_WEIGHTS))],
    "split_qr": [Call((CUBIC,)), Call((CUBIC, CUBIC_WEIGHTS))],
    "pseudo_power": Call(([1.0, 2.0, 4.0, 8.0],)),
    "pseudo_horner": [Call(([1.0, 2.0, 4.0, 8.0], 0.3), parameter="t"), Call((CUBIC, 0.7), parameter="t")],
    "curve_point_tangent": [Call((CUBIC, 0.3), parameter="t"), Call((CUBIC, 0.7, CUBIC_WEIGHTS), parameter="t")],
    "curve_point_derivative": [Call((CUBIC, 0.3), parameter="t"), Call((CUBIC, 0.7, CUBIC_WEIGHTS), parameter="t")],
    "sub_patches": [Call((PATCH,)), Call((PATCH, PATCH_WEIGHTS))],
    "point_tangent_cost": Call((3, 2)),
    # chapter 15
    "control_curves": [Call((PATCH,)), Call((PATCH, "t"))],
    "iso_curve": [Call((PATCH, 0.3)), Call((PATCH, 0.6, "t", PATCH_WEIGHTS))],
    "de_casteljau_patch": [Call((PATCH, 0.3, 0.6), parameter="s"),
                           Call((PATCH, 0.3, 0.6, PATCH_WEIGHTS), {"first": "s"}, parameter="s")],
    "patch_subdivide": [Call((PATCH, 0.4)), Call((PATCH, 0.4, "t", PATCH_WEIGHTS))],
    "subpatch": [Call((PATCH, (0.2, 0.7), (0.1, 0.5))), Call((PATCH, (0.0, 0.5), (0.5, 1.0), PATCH_WEIGHTS))],
    "patch_elevate": [Call((PATCH,)), Call((PATCH, "t", 2, PATCH_WEIGHTS))],
    "corner_derivatives": [Call((PATCH,)), Call((PATCH, PATCH_WEIGHTS, ((0.0, 2.0), (1.0, 1.5))))],
    "second_difference_bounds": Call((PATCH,)),
    "curve_tessellation_steps": Call((CUBIC, 0.01)),
    "tessellation_deltas": Call((PATCH, 0.01)),
    "tessellation_steps": Call((PATCH, 0.01)),
    "tessellate": [Call((PATCH, 3, 2)), Call((PATCH, 2, 2, PATCH_WEIGHTS))],
    "tessellation_error": [Call((PATCH, 3, 2)), Call((PATCH, 2, 2, PATCH_WEIGHTS, 3))],
    "patch_continuity": Call((PATCH, PATCH_NEXT, (0.0, 1.0), (1.0, 2.0))),
    "nurbs_point": [Call((NURBS, KNOTS_S, KNOTS_T, 1.5, 0.5), parameter="s"),
                    Call((NURBS, KNOTS_S, KNOTS_T, 1.5, 0.5, NURBS_WEIGHTS), parameter="s")],
    "nurbs_insert_knot": [Call((NURBS, KNOTS_S, KNOTS_T, 1.5)),
                          Call((NURBS, KNOTS_S, KNOTS_T, 0.5, "t", NURBS_WEIGHTS))],
    "nurbs_to_bezier": [Call((NURBS, KNOTS_S, KNOTS_T)), Call((NURBS, KNOTS_S, KNOTS_T, NURBS_WEIGHTS))],
    "corner_curvatures": [Call((PATCH,)), Call((PATCH, PATCH_WEIGHTS))],
    "corner_fundamental_forms": [Call((PATCH,)), Call((PATCH, PATCH_WEIGHTS))],
    "principal_curvatures": [Call((PATCH,)), Call((PATCH, PATCH_WEIGHTS))],
    "surface_curvatures": [Call((PATCH, 0.3, 0.7)), Call((PATCH, 0.8, 0.2, PATCH_WEIGHTS))],
    "triangle_corner_curvatures": [Call((TRIANGLE,)), Call((TRIANGLE, TRIANGLE_WEIGHTS))],
}
