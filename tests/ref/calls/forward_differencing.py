"""Valid calls of cagd_ref.forward_differencing for the contract test."""

import numpy as np

from . import Call

CUBIC = [0.0, 4.0 / 3.0, -0.5, 1.0 / 6.0]  # (t³ - 3t² + 8t) / 6, the notes' table cubic in power form
CURVE = [[2.0, 3.0], [10.0, 26.0], [30.0, 28.0], [37.0, 5.0]]  # a cubic Bézier curve in pixel units

CALLS = {
    "forward_difference_table": Call(([1.0, 2.0, 4.0, 8.0, 15.0],)),
    "initial_differences": Call(([[1.0, 0.0], [2.0, 1.0], [4.0, 4.0]],)),
    "power_differences": Call((CUBIC, 1.0, 0.5)),
    "forward_difference_steps": Call(([1.0, 1.0, 1.0, 1.0], 5)),
    "forward_difference_eval": Call((CUBIC, 1.0, 1.0, 7)),
    # The entry at `index` is a placeholder and may be NaN; the poisoned first entry is a known value.
    "missing_value": Call(([1.0, 2.0, 4.0, 0.0, 15.0], 3)),
    "bezier_by_differences": Call((CURVE, 8)),
    "raster_delta": Call((CURVE,)),
    "pixels_along": Call(([[0.2, 0.9], [0.7, 0.95], [1.0, 1.0], [1.5, 2.0]],)),
    "rasterize": [Call((CURVE,)), Call((CURVE, 0.05))],
    # Pixel coordinates are integers, but any numbers may come in, so they are poisoned too.
    "find_gaps": Call((np.array([[0, 0], [1, 1], [3, 1], [3, 2]]),)),
    "double_step": Call(([1.0, 1.0, 1.0, 1.0],)),
    "halve_step": Call(([[1.0, 0.0], [2.0, 1.0], [4.0, 4.0]],)),
    "adaptive_march": Call((CURVE,), dict(limit=1.0)),
    "drift": Call((CUBIC, 0.0, 0.01, 20), dict(dtype=np.float32)),
    "float32_drift": Call((CUBIC, 0.01, 20)),
}
