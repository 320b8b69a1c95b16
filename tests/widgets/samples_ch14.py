"""Sample updates of the chapter 14 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "lattice_editor": ({"y": 1.8}, {"lattice", "weights", "selected", "deformed", "joins"}),
    "isoline_explorer": ({"value": 0.3}, {"points", "curve_weights", "degree", "deviation"}),
    "freeze_explorer": ({"order": 2}, {"inside", "curvature", "gap", "kink", "continuity"}),
    "curve_image_explorer": ({"strength": 0.8}, {"exact_points", "exact_weights", "naive_error", "exact_error"}),
}
