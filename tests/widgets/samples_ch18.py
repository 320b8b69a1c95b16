"""Sample updates of the chapter 18 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "pencil_explorer": ({"t": 0.7}, {"l0", "l1", "line", "ends", "mark", "d1", "incidence"}),
    "two_pencils_explorer": ({"t": 0.25}, {"control", "weights", "implicit", "kind", "point"}),
    "double_point_explorer": ({"dx2": 0.5}, {"points", "double_point", "pencil", "parameters", "kind"}),
    "tangent_explorer": ({"t": 0.7}, {"lines", "tangent", "reciprocal", "dual_point", "envelope_error"}),
}
