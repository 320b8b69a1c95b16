"""Sample updates of the chapter 9 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "hull_march_explorer": ({"step": 4}, {"steps", "start", "crossing", "roots", "ratio", "rule"}),
    "conditioning_explorer": ({"degree": 12}, {"exact", "found", "errors", "condition", "ratio"}),
    "line_curve_explorer": ({"offset": 7.0}, {"line", "values", "ts", "points"}),
}
