"""Sample updates of the chapter 12 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "interval_curve_explorer": ({"t": 1.6}, {"boxes", "box", "error", "growth", "pieces"}),
    "hermite_interval_explorer": ({"order": 3}, {"pieces", "bound", "error", "middle_widths"}),
    "degree_reduction_explorer": ({"depth": 2}, {"pieces", "bound", "deviation", "bounds", "deviations"}),
}
