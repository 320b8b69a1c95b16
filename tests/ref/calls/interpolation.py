"""Valid calls of cagd_ref.interpolation for the contract test."""

from . import Call

NOTES_TS = [0.0, 0.25, 0.75, 1.0]  # §10.1: the running cubic
NOTES_POINTS = [[0.0, 0.0], [2.0, 2.0], [0.0, 3.0], [2.0, 4.0]]
NEWTON_TS = [0.0, 1.0, 3.0, 4.0]  # §10.3-10.4
NEWTON_POINTS = [[0.0, 0.0], [3.0, 3.0], [5.0, 3.0], [7.0, 0.0]]
NEWTON_COEFFS = [[0.0, 0.0], [3.0, 3.0], [-2.0 / 3.0, -1.0], [0.25, 0.0]]
BOTTOM_ROW = [[7.0, 0.0], [2.0, -3.0], [1.0 / 3.0, -1.0], [0.25, 0.0]]
CUBIC = [[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.0]]
HERMITE = ([0.0, 0.0], [4.0, 0.0], [3.0, 9.0], [3.0, -9.0])

CALLS = {
    "checked_nodes": Call((NOTES_TS,)),
    "checked_data": Call((NOTES_TS, NOTES_POINTS)),
    "checked_hermite_data": Call(HERMITE),
    "power_interpolation": Call((NOTES_TS, NOTES_POINTS)),
    "bernstein_interpolation": Call((NOTES_TS, NOTES_POINTS), {"interval": (0.0, 1.0)}),
    "undetermined_coefficients": Call(([0.0, 1.0, 0.0, 1.0], [0, 0, 1, 1], list(HERMITE))),
    "lagrange_basis": Call((NOTES_TS, 0.5), parameter="t"),
    "lagrange_eval": Call((NOTES_TS, NOTES_POINTS, 0.5), parameter="t"),
    "lagrange_eval_plain": Call((NOTES_TS, NOTES_POINTS, 0.5), parameter="t"),
    "barycentric_weights": Call((NOTES_TS,)),
    "barycentric_eval": [
        Call((NOTES_TS, NOTES_POINTS, 0.5), parameter="t"),
        Call((NOTES_TS, NOTES_POINTS, 0.5), {"weights": [-1.0, 3.0, -3.0, 1.0]}, parameter="t"),
    ],
    "lebesgue_function": Call((NOTES_TS, 0.5), parameter="x"),
    "divided_differences": Call((NEWTON_TS, NEWTON_POINTS)),
    "divided_difference_table": Call((NEWTON_TS, NEWTON_POINTS)),
    "next_table_row": Call((NEWTON_TS, BOTTOM_ROW, 2.0)),
    "newton_eval": Call((NEWTON_TS, NEWTON_COEFFS, 2.0), parameter="t"),
    "newton_eval_plain": Call((NEWTON_TS, NEWTON_COEFFS, 2.0), parameter="t"),
    "confluent_divided_differences": Call(([0.0, 0.0, 1.0, 1.0], [HERMITE[0], HERMITE[2], HERMITE[1], HERMITE[3]])),
    "newton_to_power": Call((NEWTON_TS, NEWTON_COEFFS)),
    "neville": Call((NEWTON_TS, NEWTON_POINTS, 2.0), parameter="t"),
    "neville_plain": Call((NEWTON_TS, NEWTON_POINTS, 2.0), parameter="t"),
    "neville_triangle": Call((NEWTON_TS, NEWTON_POINTS, 2.0)),
    "node_polynomial": Call((NOTES_TS, 0.3), parameter="x"),
    "node_polynomial_max": Call((NOTES_TS, 0.0, 1.0)),
    "chebyshev_nodes": Call((0.0, 1.0, 9)),
    "interpolation_error_bound": Call((NOTES_TS, 2.0, 0.3), parameter="x"),
    "linear_segments_needed": Call((0.0, 3.0, 1.0, 1e-3)),
    "second_derivative_bounds": Call((CUBIC,)),
    "bezier_segments_needed": Call((CUBIC, 0.01)),
    "flatten": Call((CUBIC, 0.1)),
    "chord_gaps": Call((CUBIC, 5)),
    "chord_deviation": Call((CUBIC, 5)),
    "hermite_basis": Call((0.3,), parameter="t"),
    "hermite_eval": Call(HERMITE + (0.3,), parameter="t"),
    "hermite_to_bezier": Call(HERMITE),
}
