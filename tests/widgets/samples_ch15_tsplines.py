"""Sample updates of the §15.7 (T-spline) explorers for test_common.py: factory -> (one update, keys of its state)."""

SAMPLES = {
    "tmesh_explorer": ({"vertex": 15}, {"s_knots", "t_knots", "value", "values", "nonzero", "total"}),
    "refinement_stepper_explorer": ({"step": 3}, {"action", "detail", "v1", "v2", "v3", "change"}),
}
