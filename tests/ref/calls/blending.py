"""Valid calls of cagd_ref.blending for the contract test."""

from cagd_ref.blending import ball_basis, timmer_basis

from . import Call

CUBIC = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]]
ROW = [[0.0, 0.0], [1.0, 2.0], [2.0, 0.0], [3.0, 2.0], [4.0, 0.0], [5.0, 2.0]]  # six points, parameters [0, 3]

CALLS = {
    "basis_values": Call((ball_basis, [0.0, 0.5, 1.0])),
    "bezier_basis": Call((0.3,), dict(degree=4), parameter="t"),
    "timmer_basis": Call((0.3,), parameter="t"),
    "ball_basis": Call((0.3,), parameter="t"),
    "overhauser_basis": Call((0.3,), parameter="t"),
    "rational_example_basis": Call((0.3,), parameter="t"),
    "blend": Call((timmer_basis, CUBIC, 0.3), parameter="t"),
    "overhauser_point": Call((ROW, 1.5), parameter="t"),
    "catmull_rom_parameters": Call((ROW,), dict(alpha=0.5)),
    "catmull_rom_point": Call((ROW, [0.0, 1.0, 3.0, 4.0, 4.5, 6.0], 2.0), parameter="t"),
    "sign_changes": Call(([1.0, 0.0, -2.0, 3.0],)),
    "crossing_counts": Call((ball_basis([0.0, 0.25, 0.5, 0.75, 1.0]), CUBIC, [0.0, 1.0, -1.0])),
    "conversion_matrix": Call(("overhauser",)),
    "to_bezier": Call(("ball", CUBIC)),
    "from_bezier": Call(("timmer", CUBIC)),
    "timmer_to_bezier": Call((CUBIC,)),
    "ball_to_bezier": Call((CUBIC,)),
    "overhauser_to_bezier": Call((ROW,)),
}
