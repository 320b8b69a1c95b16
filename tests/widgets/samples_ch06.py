"""Sample updates of the chapter 6 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "knot_vector_editor": ({"u2": 2.5}, {"knots", "continuity", "segments", "basis"}),
    "de_boor_explorer": ({"t": 3.3}, {"point", "levels", "span", "labels"}),
    "knot_insertion_explorer": ({"t": 2.6}, {"points", "knots", "new", "deviation"}),
    "knot_interval_explorer": ({"fraction": 0.5}, {"points", "intervals", "construction", "deviation"}),
    "local_control_explorer": ({"dx": 1.0}, {"points", "segments", "changed", "support"}),
}
