"""Sample updates of the chapter 4 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "raster_explorer": ({"delta": 0.1}, {"pixels", "gaps", "gap_count", "bound", "steps", "end_error"}),
    "drift_explorer": ({"steps": 300, "precision": "float64"}, {"forward_error", "horner_error", "final_forward"}),
}
