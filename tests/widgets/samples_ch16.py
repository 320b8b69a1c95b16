"""Sample updates of the chapter 16 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "qr_tangent_explorer": ({"t": 0.8}, {"p", "q", "r", "derivative", "ratio", "factor"}),
    "pseudo_switch_explorer": ({"gap": 1e-4}, {"values", "errors", "error_at_t", "broken"}),
    "sub_patch_explorer": ({"s": 0.7}, {"p", "p_s", "p_t", "normal", "corners", "ends", "volume", "costs"}),
}
