"""Sample updates of the chapter 3 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "basis_conversion_explorer": ({"b1": 4.5}, {"bernstein", "power", "table", "text"}),
    "accuracy_explorer": ({"roots": 16}, {"roots", "power_error", "bernstein_error", "exact", "t"}),
}
