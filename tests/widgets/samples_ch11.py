"""Sample updates of the chapter 11 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "best_constant_explorer": ({"g4": 9.0}, {"values", "l2", "linf", "linf_at_mean"}),
    "fitting_explorer": ({"count": 12, "corrections": 2},
                         {"points", "params", "knots", "control", "history", "residuals", "curvature"}),
    "fairing_weight_explorer": ({"weight": 0.5}, {"control", "lsq", "energy", "height", "family", "curve_lsq"}),
    "box_fit_explorer": ({"half_width": 0.2}, {"control", "sizes", "active", "energy", "energy_lsq"}),
}
