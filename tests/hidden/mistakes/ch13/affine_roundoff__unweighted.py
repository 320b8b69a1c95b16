"""Adds |p0| + |p1| without the weights |1-t| and |t|."""
import numpy as np


def affine_roundoff(p0, p1, t, eta):
    a, b = np.asarray(p0, dtype=float), np.asarray(p1, dtype=float)
    ts = np.asarray(t, dtype=float)
    if a.shape != b.shape or a.ndim > 1 or ts.ndim > 1:
        raise ValueError("p0 and p1 must have one shape, t a number or 1-D")
    if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b)) and np.all(np.isfinite(ts))) or eta < 0:
        raise ValueError("finite numbers and eta >= 0 please")
    tt = ts.reshape(ts.shape + (1,) * a.ndim)
    result = (1 - tt) * a + tt * b
    return eta * (np.abs(a) + np.abs(b) + np.abs(result))
