"""Valid calls of cagd_ref.geometry for the contract test."""

import numpy as np

from . import Call

AXIS = dict(axis_point=[1.0, 0.0, 0.0], axis_direction=[0.0, 0.0, 2.0])

CALLS = {
    "projection": Call(([1.0, 2.0, 3.0], [0.0, 0.0, 2.0])),
    "triangle_area": Call(([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])),
    "rotate_about_axis": Call(([[1.0, 1.0, 0.0], [2.0, 0.0, 1.0]],), dict(AXIS, angle=0.5)),
    "rotation_matrix": Call((), dict(AXIS, angle=0.5)),
    "apply_transform": Call((np.diag([1.0, 2.0, 3.0, 1.0]), [[1.0, 1.0, 1.0], [0.0, 2.0, 0.5]])),
    "affine_point": Call(([0.0, 0.0], [2.0, 4.0], 1.0, 3.0, 2.5), parameter="t"),
    "implicit_line": Call(([0.0, 1.0], [2.0, 3.0])),
    "normalize_line": Call(([3.0, 4.0, 5.0],)),
    "signed_distance": Call(([3.0, 4.0, 5.0], [[1.0, 1.0], [0.0, 0.0]])),
    "join": Call(([0.0, 1.0, 1.0], [2.0, 3.0, 1.0])),
    "meet": Call(([1.0, -1.0, 0.0], [1.0, 1.0, -2.0])),
    "conic_type": Call((1.0, 0.5, 2.0, -1.0, 0.0, -3.0)),
    "conic_discriminant": Call((1.0, 0.5, 2.0)),
    "parametric_conic_type": Call(([1.0, -2.0, 2.0],)),
}
