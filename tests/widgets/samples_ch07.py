"""Sample updates of the chapter 7 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "bezout_explorer": ({"offset": 0.5}, {"count", "finite", "real", "at_infinity"}),
    "clip_lab_explorer": ({"d1": -6.0}, {"hull", "polygon", "v_rule", "lost"}),
    "clipping_explorer": ({"step": 3}, {"event", "history", "before", "after", "found"}),
    "subdivision_comparison_explorer": ({"depth": 5}, {"steps", "counts", "totals", "found"}),
}
