"""Sample updates of the chapter 20 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "hybrid_explorer": ({"degree": 6, "t": 0.7}, {"hybrid", "moving_point", "point", "gap", "delta", "bound"}),
    "moving_box_explorer": ({"depth": 3}, {"pieces", "delta", "deltas"}),
    "adaptive_area_explorer": ({"tol": 1e-9}, {"hybrid", "error", "simpson", "simpson_error", "trapezoid", "joints"}),
}
