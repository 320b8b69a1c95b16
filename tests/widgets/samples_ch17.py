"""Sample updates of the chapter 17 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "implicit_curve_explorer": ({"w1": 1.5}, {"implicit", "num", "den", "value", "t", "singular"}),
    "common_root_explorer": ({"g2": 3.0}, {"bezout", "resultant", "rank", "gcd", "common_roots"}),
    "implicit_intersection_explorer": ({"dy": 0.3}, {"polynomial", "u_roots", "hits", "points"}),
}
