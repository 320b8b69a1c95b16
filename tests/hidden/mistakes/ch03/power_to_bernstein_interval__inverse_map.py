"""Substitutes the inverse map u = (t - t0) / (t1 - t0) into p, instead of t = t0 + (t1 - t0) u."""
from math import comb

import numpy as np


def _power_to_bernstein(a):
    n = len(a) - 1
    scale = np.array([comb(n, j) for j in range(n + 1)], dtype=float)
    column = a / scale.reshape((-1,) + (1,) * (a.ndim - 1))
    top = [column[0]]
    while len(column) > 1:
        column = column[:-1] + column[1:]
        top.append(column[0])
    return np.array(top)


def _substitute(a, shift, scale):
    q = a[-1:].copy()
    for coefficient in a[-2::-1]:
        wider = np.zeros((len(q) + 1,) + q.shape[1:])
        wider[:-1] += shift * q
        wider[1:] += scale * q
        wider[0] += coefficient
        q = wider
    return q


def _checked(coeffs, interval):
    a = np.array(coeffs, dtype=float)
    if a.ndim not in (1, 2) or len(a) == 0 or not np.all(np.isfinite(a)):
        raise ValueError("coeffs must be finite numbers of shape (n+1,) or (n+1, d)")
    t0, t1 = np.array(interval, dtype=float)
    if not t0 < t1:
        raise ValueError("interval must be (t0, t1) with t0 < t1")
    return a, t0, t1


def power_to_bernstein_interval(coeffs, interval):
    a, t0, t1 = _checked(coeffs, interval)
    return _power_to_bernstein(_substitute(a, -t0 / (t1 - t0), 1 / (t1 - t0)))
