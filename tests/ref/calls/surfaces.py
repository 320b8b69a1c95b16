"""Valid calls of cagd_ref.surfaces for the contract test.

Patch functions take the pair (s, t); the contract test varies the parameter it is given, s, while t stays
a number, which broadcasts to every value of s: k values of s give k pairs and (k, d) results.
"""

from . import Call

PATCH = [[[0.0, 0.0, 0.0], [0.0, 2.0, 0.0]], [[1.0, 0.0, 1.0], [1.0, 2.0, 2.0]], [[2.0, 0.0, 0.0], [2.0, 2.0, 1.0]]]
PATCH_WEIGHTS = [[1.0, 1.0], [2.0, 3.0], [1.0, 1.0]]
CUBIC = [[0.0, 0.0, 0.0], [1.0, 2.0, 0.0], [3.0, 3.0, 1.0], [4.0, 0.0, 2.0]]
CUBIC_WEIGHTS = [1.0, 2.0, 0.5, 1.0]


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
}
