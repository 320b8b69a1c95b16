"""Sample updates of the chapter 3 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "basis_conversion_explorer": ({"b1": 4.5}, {"bernstein", "power", "table", "text"}),
    "evaluation_cost_explorer": ({"degree": 7}, {"degree", "costs", "totals"}),
}
