"""Valid calls of cagd_ref.polynomials for the contract test."""

from . import Call

SCALAR = [1.0, 9.0, 4.0, 6.0]
COLUMNS = [[1.0, 2.0, 1.0], [9.0, 12.0, 3.0], [4.0, 3.0, 1.0], [6.0, 2.0, 2.0]]

CALLS = {
    "horner": [Call((SCALAR, 0.3), parameter="t"), Call((COLUMNS, 1.5), parameter="t")],
    "horner_with_derivative": [Call((SCALAR, 0.3), parameter="t"), Call((COLUMNS, -1.5), parameter="t")],
    "bernstein_horner": [
        Call((SCALAR, 0.3), parameter="t"),
        Call((COLUMNS, 2.5), dict(interval=(2.0, 4.0)), parameter="t"),
    ],
    "bernstein_horner_plain": [Call((SCALAR, 0.3), parameter="t"), Call((COLUMNS, -0.5), parameter="t")],
    "evaluation_cost": Call((4,)),
    "difference_table": Call((COLUMNS,)),
    "substitute_affine": Call((COLUMNS, 1.0, 2.0)),
    "bernstein_to_power": Call((COLUMNS,), dict(interval=(1.0, 3.0))),
    "power_to_bernstein": Call((COLUMNS,), dict(interval=(-1.0, 0.5))),
    "power_to_bernstein_interval": Call((COLUMNS, (2.0, 4.0))),
    "power_to_rational_bezier": Call((COLUMNS,)),
    "bernstein_multiply": Call((COLUMNS, [[1.0, 0.0, 2.0], [3.0, 1.0, 1.0]])),
    "bernstein_integral": Call((SCALAR,), dict(interval=(0.0, 2.0))),
    "bernstein_area": Call((COLUMNS,), dict(interval=(0.0, 2.0))),
}
