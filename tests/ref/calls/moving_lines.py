"""Valid calls of cagd_ref.moving_lines for the contract test (the notes' cubic and quartic, a rational conic)."""

from . import Call

CUBIC = [[0.0, 0.0], [0.0, 1.0], [1.0, 2.0], [3.0, 0.0]]  # the notes' cubic of Figure 18.11
QUARTIC = [[0.0, 0.0], [0.0, 1.0], [1.0, 2.0], [3.0, 2.0], [2.0, 0.0]]  # Figure 18.12
WEIGHTS = [1.0, 2.0, 0.5, 1.5]
CONIC = [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]
PENCIL = [[0.0, 3.0, 0.0], [3.0, 3.0, -9.0]]
LINEAR = [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0]]
QUADRATIC = [[0.0, 1.0, 1.0], [1.0, 1.0, 1.0], [2.0, 0.0, 1.0]]
LA = [[0.0, 2.0, 0.0], [4.0, 4.0, -8.0], [4.0, -2.0, -8.0]]  # (18.69)
LB = [[8.0, 6.0, 0.0], [28.0, 4.0, -24.0], [20.0, -14.0, -40.0]]
ROWS = [[[-3.0, 0.0, 0.0], [-6.0, 3.0, 0.0], [0.0, 3.0, 0.0]],  # (18.62)
        [[-6.0, 3.0, 0.0], [-9.0, 12.0, -9.0], [3.0, 9.0, -9.0]],
        [[0.0, 3.0, 0.0], [3.0, 9.0, -9.0], [6.0, 6.0, -18.0]]]

CALLS = {
    "moving_line_eval": Call((PENCIL, 0.25), parameter="t"),
    "incidence": [Call((PENCIL, CUBIC)), Call((PENCIL, CUBIC, WEIGHTS))],
    "product_moving_line": Call((LINEAR, QUADRATIC)),
    "pencil_parameter_line": Call(([0.0, 1.0, 0.0], [-1.0, 1.0, 0.0]), dict(d0=1.5)),
    "conic_from_pencils": Call(([1.0, 0.0, 0.0], [1.0, -1.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.5, 1.0])),
    "pencils_implicit": Call(([1.0, 0.0, 0.0], [1.0, -1.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.5, 1.0])),
    "quadratic_pencils": [Call((CONIC,)), Call((CONIC, [1.0, 2.5, 0.7]))],
    "nomogram_parameter": [Call((CONIC, [1.5, 0.375])), Call((CONIC, [1.0, 0.5], [1.0, 1.0, 1.0]))],
    "axial_moving_line": Call(([3.0, 0.0, 1.0], CUBIC), dict(weights=WEIGHTS)),
    "bezout_moving_lines": [Call((CUBIC,)), Call((QUARTIC, [1.0, 2.0, 1.0, 0.5, 1.0]))],
    "unscaled_to_bernstein": Call((LA,)),
    "eliminate_leading": Call((ROWS,)),
    "cubic_pencil": [Call((CUBIC,)), Call((CUBIC, WEIGHTS))],
    "cubic_double_point": [Call((CUBIC,)), Call((CUBIC, WEIGHTS))],
    "moving_lines_of_degree": Call((QUARTIC, 2), dict(weights=[1.0, 2.0, 1.0, 0.5, 1.0])),
    "two_moving_lines": [Call((QUARTIC,)), Call((CUBIC, WEIGHTS))],
    "axial_combinations": Call((LA, LB)),
    "quartic_double_points": Call((QUARTIC, [1.0, 2.0, 1.0, 0.5, 1.0])),
    "moving_lines_implicit": Call((LA, LB)),
    "moving_line_implicit": [Call((CUBIC,)), Call((QUARTIC, [1.0, 2.0, 1.0, 0.5, 1.0]))],
    "tangent_moving_line": [Call((CUBIC,)), Call((CUBIC, WEIGHTS))],
    "envelope": Call(([[0.0, 1.0, 0.0], [1.0, 0.0, -1.0], [0.0, 1.0, -2.0]],)),
    "scaled_hodograph": [Call((CUBIC,)), Call((CUBIC, WEIGHTS))],
}
CALLS["double_point_parameters"] = [Call((CUBIC,)), Call((CUBIC, WEIGHTS))]
CALLS["product_moving_line_plain"] = Call((LINEAR, QUADRATIC))
CALLS["bezout_moving_lines_plain"] = [Call((CUBIC,)), Call((QUARTIC, [1.0, 2.0, 1.0, 0.5, 1.0]))]
CALLS["cubic_double_point_plain"] = [Call((CUBIC,)), Call((CUBIC, WEIGHTS))]
CALLS["tangent_moving_line_plain"] = [Call((CUBIC,)), Call((CUBIC, WEIGHTS))]
ROW2_BERNSTEIN = [[0.0, 3.0, 0.0], [1.5, 4.5, -4.5], [6.0, 6.0, -18.0]]  # row 2 of (18.62) = (1 + t) × the pencil
ROW0_BERNSTEIN = [[-3.0, 0.0, 0.0], [-3.0, 1.5, 0.0], [0.0, 3.0, 0.0]]
CALLS["mu_basis_coefficients"] = Call((ROW2_BERNSTEIN, PENCIL, ROW0_BERNSTEIN))
CALLS["axial_condition"] = Call((LA, LB))
