"""Sample updates of the chapter 8 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "offset_explorer": ({"rho": 2.5}, {"offset", "factor", "cusps", "interval", "tightest"}),
    "ph_offset_explorer": ({"rho": -0.5}, {"points", "weights", "deviation", "sigma"}),
    "gouging_explorer": ({"t": 0.3}, {"gouged", "depth", "tool", "reverse", "kind", "trimmed", "kept_paths"}),
}
