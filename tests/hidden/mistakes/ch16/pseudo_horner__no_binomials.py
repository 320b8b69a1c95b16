"""Forgets the binomial factors C(N, i): Horner on the Bernstein coefficients themselves."""
import numpy as np
from math import comb


def _prepare(coeffs, t):
    c = np.array(coeffs, dtype=float)
    if c.ndim not in (1, 2) or len(c) == 0:
        raise ValueError("coeffs: expected shape (N+1,) or (N+1, d)")
    ts = np.array(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t: expected a number or a 1-D array")
    return c, np.atleast_1d(ts), ts.ndim == 0


def _horner(c, u):
    value = np.broadcast_to(c[-1], (len(u),) + c.shape[1:]).copy()
    uu = u.reshape((-1,) + (1,) * (c.ndim - 1))
    for ci in c[-2::-1]:
        value = value * uu + ci
    return value


def _finish(values, scalar):
    return (values[0] if values.ndim > 1 else float(values[0])) if scalar else values


def pseudo_horner(coeffs, t):
    c, ts, scalar = _prepare(coeffs, t)
    N = len(c) - 1
    hat = c * np.array([comb(N, i) for i in range(N + 1)], dtype=float).reshape((-1,) + (1,) * (c.ndim - 1))

    def scale_of(x):
        return x.reshape((-1,) + (1,) * (c.ndim - 1))

    hat = c
    low = ts < 0.5
    u = np.where(low, ts, 1 - ts) / np.where(low, 1 - ts, ts)
    values = np.where(scale_of(low), _horner(hat, u), _horner(hat[::-1], u)) * scale_of(np.where(low, 1 - ts, ts) ** N)
    return _finish(values, scalar)
