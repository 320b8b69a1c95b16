"""Valid calls of cagd_ref.approximation for the contract test (knots in the notes' convention)."""

from . import Call

# Six samples of a planar arc at chord-length-like parameters, fitted by a cubic with 5 control points.
SAMPLES = [[0.0, 0.0], [1.0, 1.2], [2.0, 1.8], [3.0, 1.9], [4.0, 1.3], [5.0, 0.1]]
PARAMS = [0.0, 0.2, 0.4, 0.6, 0.8, 1.0]
KNOTS = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]
CONTROL = [[0.0, 0.0], [1.5, 2.0], [2.5, 2.2], [3.5, 2.0], [5.0, 0.0]]
FIT = (SAMPLES, PARAMS, KNOTS, 3)

CALLS = {
    "best_constant": Call(([2.0, 3.0, 3.0, 5.0, 7.0],), dict(norm="linf")),
    "uniform_parameters": Call((SAMPLES,)),
    "chord_length_parameters": Call((SAMPLES,)),
    "centripetal_parameters": Call((SAMPLES,), dict(exponent=0.5)),
    "fitting_knots": Call((PARAMS, 5, 3), dict(method="averaging")),
    "fit_inputs": Call(FIT),
    "checked_params": Call((PARAMS, KNOTS, 3)),
    "schoenberg_whitney": Call((PARAMS, KNOTS, 3)),
    "normal_equations": Call(FIT),
    "least_squares_fit": Call(FIT),
    "fit_error": Call((SAMPLES, PARAMS, CONTROL, KNOTS)),
    "project_parameters": Call((SAMPLES, PARAMS, CONTROL, KNOTS)),
    "parameter_correction": Call(FIT, dict(iterations=2)),
    "fairing_matrix": Call((KNOTS, 3)),
    "fairing_matrix_plain": Call((KNOTS, 3)),
    "fairing_energy": Call((CONTROL, KNOTS)),
    "faired_fit": Call(FIT + (0.01,)),
    "constrained_fit": Call(FIT + (0.01, [[2.0, 1.8]], [0.4])),
    "fit_within_tolerance": Call(FIT + (0.5,)),
    "estimate_frames": Call((SAMPLES,)),
    "box_faired_fit": Call(FIT + (0.3,), dict(frame="curve")),
    "box_programme": Call(([[2.0, 0.5], [0.5, 1.0]], [1.0, -1.0], [[1.0, 0.0], [1.0, 1.0]], [-0.5, 0.0],
                           [0.5, 2.0])),
    "spline_curvature": Call((CONTROL, KNOTS, 0.3), parameter="t"),
}
