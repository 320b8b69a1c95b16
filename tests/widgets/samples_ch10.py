"""Sample updates of the chapter 10 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "interpolation_explorer": ({"t1": 0.4}, {"curve", "ts", "bezier", "basis"}),
    "runge_explorer": ({"spacing": "Chebyshev"}, {"nodes", "omega_max", "error", "lebesgue"}),
    "neville_explorer": ({"tau": 2.5}, {"triangle", "point", "row"}),
    "flattening_explorer": ({"tol": 0.01}, {"segments", "bound", "deviation", "fewest"}),
    "hermite_explorer": ({"d0y": 5.0}, {"bezier", "curve", "d0", "d1"}),
}
