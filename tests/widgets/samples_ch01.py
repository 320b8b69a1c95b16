"""Sample updates of the chapter 1 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "rotation_explorer": ({"angle": 45.0, "axis_x": 1.0}, {"point", "matrix"}),
    "conic_explorer": ({"b": 3.0}, {"type", "discriminant"}),
}
