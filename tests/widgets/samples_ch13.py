"""Sample updates of the chapter 13 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "band_explorer": ({"bits": 11}, {"t", "values", "exact", "radius", "bound", "sign_changes"}),
    "affine_roundoff_explorer": ({"t": 1.6}, {"exact_centre", "exact_radius", "centre", "radius", "widening"}),
    "number_line_explorer": ({"bits": 4}, {"neighbours", "rounded", "interval", "encoded"}),
}
