"""Treats the Newton coefficients as power coefficients: Horner's scheme in t, ignoring the nodes."""
import numpy as np


def newton_eval(ts, coeffs, t):
    ts = np.array(ts, dtype=float)
    c = np.array(coeffs, dtype=float)
    if ts.ndim != 1 or c.ndim not in (1, 2) or len(c) == 0 or len(ts) not in (len(c), len(c) - 1):
        raise ValueError("ts: one node per coefficient")
    tau = np.array(t, dtype=float)
    if tau.ndim > 1:
        raise ValueError("t: a number or a 1-D array")
    u = np.atleast_1d(tau).reshape((-1,) + (1,) * (c.ndim - 1))
    value = np.broadcast_to(c[-1], (len(u),) + c.shape[1:]).copy()
    for k in range(len(c) - 2, -1, -1):
        value = c[k] + u * value
    return value[0] if tau.ndim == 0 else value
