"""Sample updates of the chapter 5 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "blending_forms_explorer": ({"x1": 1.5}, {"points", "curves", "midpoints", "bezier_points", "hull_escape"}),
    "variation_diminishing_explorer": (
        {"angle": 30.0},
        {"line", "p", "c", "holds", "polygon_crossings", "curve_crossings"},
    ),
}
