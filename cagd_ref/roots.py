"""Real roots of polynomials in Bernstein form by convex-hull clipping: notes chapter 9.

A polynomial y(t) = Σ y_i B_i^n(t) on [t0, t1] is the explicit Bézier curve with
control points (t0 + i/n (t1 - t0), y_i). Its graph lies in the convex hull of
those points, so no root lies where the hull misses the t axis. Clipping the
interval to where the hull meets the axis (and halving when a clip gains too
little) closes in on every real root without ever stepping over one.
"""

from __future__ import annotations

import numpy as np

from ._validation import as_interval, as_scalar, as_vector

__all__ = ["bernstein_roots", "hull_crossing"]

# A clip that keeps more than this fraction of the interval is not converging
# fast enough (several roots inside, or a multiple root): halve instead.
HALVE_ABOVE = 0.7
MAX_STEPS = 200_000
SLACK = 4 * np.finfo(float).eps


def hull_crossing(coeffs) -> tuple[float, float] | None:
    """Sub-interval (lo, hi) of [0, 1] where the hull of the points (i/n, y_i) meets y = 0, or None. Notes §9.1.

    coeffs: (n+1,). Every crossing of a hull edge is a crossing of some segment
    between two control points of opposite sign (or a control point on the axis),
    so the extreme such crossings bound the hull's intersection with the axis.
    """
    y = as_vector(coeffs, "coeffs")
    n = len(y) - 1
    if n == 0:
        return (0.0, 1.0) if y[0] == 0 else None
    t = np.arange(n + 1) / n
    on_axis = t[y == 0]
    i, j = np.nonzero((y[:, None] < 0) & (y[None, :] > 0))
    crossings = t[i] - y[i] * (t[j] - t[i]) / (y[j] - y[i])
    found = np.concatenate([on_axis, crossings])
    if found.size == 0:
        return None
    return float(found.min()), float(found.max())


def bernstein_roots(coeffs, interval=(0, 1), tol: float = 1e-12) -> np.ndarray:
    """Sorted real roots in `interval` of Σ y_i B_i^n, for (n+1,) Bernstein coefficients on that interval. Notes ch. 9.

    Each root is located to within `tol` (relative to the interval's length).
    A multiple root, or roots closer than the accuracy floating point allows
    there, comes back once: regions that cannot be told apart are merged.
    An identically zero polynomial has no isolated roots and is rejected.
    """
    y = as_vector(coeffs, "coeffs")
    t0, t1 = as_interval(interval)
    tol = as_scalar(tol, "tol")
    if not 0 < tol < 1:
        raise ValueError(f"tol: expected a number in (0, 1), got {tol}")
    if not np.any(y):
        raise ValueError("coeffs: the zero polynomial vanishes everywhere; its roots are not isolated")
    found = _root_intervals(y, tol)
    clusters = _merge_touching(sorted(found), tol)
    return t0 + (t1 - t0) * np.array([(a + b) / 2 for a, b in clusters])


def _root_intervals(y: np.ndarray, tol: float) -> list[tuple[float, float]]:
    """Intervals of [0, 1] no wider than tol that may hold a root; every root is in one of them."""
    pending = [(y, 0.0, 1.0)]
    found = []
    for _ in range(MAX_STEPS):
        if not pending:
            return found
        c, a, b = pending.pop()
        clip = hull_crossing(c)
        if clip is None:
            continue
        if b - a <= tol:
            found.append((a, b))
            continue
        lo, hi = clip
        if hi - lo > HALVE_ABOVE:
            left, right = _split(c, 0.5)
            middle = (a + b) / 2
            pending += [(right, middle, b), (left, a, middle)]
            continue
        pending.append((_restrict(c, lo, hi), a + (b - a) * lo, a + (b - a) * hi))
    raise RuntimeError("bernstein_roots: too many subdivision steps; is the polynomial badly scaled?")


def _restrict(c: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """Bernstein coefficients of the same polynomial on [lo, hi] ⊂ [0, 1], widened by a few ulps.

    The widening keeps a root that rounding placed a hair outside the clip, and
    gives a hull that only touches the axis a non-empty interval.
    """
    lo, hi = max(lo - SLACK, 0.0), min(hi + SLACK, 1.0)
    _, right = _split(c, lo)
    left, _ = _split(right, (hi - lo) / (1 - lo))
    return left


def _split(c: np.ndarray, t: float) -> tuple[np.ndarray, np.ndarray]:
    """De Casteljau subdivision of scalar coefficients (n+1,) at t: the inner loop, without re-validation."""
    n = len(c) - 1
    left, right = np.empty(n + 1), np.empty(n + 1)
    level = c
    for j in range(n + 1):
        left[j], right[n - j] = level[0], level[-1]
        level = level[:-1] + t * (level[1:] - level[:-1])
    return left, right


def _merge_touching(intervals: list[tuple[float, float]], tol: float) -> list[tuple[float, float]]:
    merged: list[list[float]] = []
    for a, b in intervals:
        if merged and a <= merged[-1][1] + tol:
            merged[-1][1] = max(merged[-1][1], b)
        else:
            merged.append([a, b])
    return [(a, b) for a, b in merged]
