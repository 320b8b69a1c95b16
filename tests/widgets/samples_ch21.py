"""Sample updates of the chapter 21 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "quad_explorer": ({"x4": 6.0, "y4": 2.0}, {"quad", "preimages", "inside", "kind"}),
    "birational_explorer": ({"w10": 2.0}, {"weights", "axes", "residual", "birational", "base"}),
    "warp_explorer": ({"x2": 10.0}, {"quad", "maps", "window"}),
}
