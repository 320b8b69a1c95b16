"""Continuity of joined curves and curvature combs: notes §2.10 and §2.11."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._validation import as_count, as_float_array, as_interval, as_points, as_scalar, as_weights
from .bezier import derivative, evaluate, signed_curvature

__all__ = ["Continuity", "continuity", "curvature_vector", "curvature_comb"]


@dataclass(frozen=True)
class Continuity:
    """Highest orders of parametric (C) and geometric (G) continuity found at a joint; -1 means not joined."""

    parametric: int
    geometric: int

    def __str__(self) -> str:
        if self.geometric < 0:
            return "not joined (gap between the curves)"
        return f"C{self.parametric}, G{self.geometric}" if self.parametric >= 0 else f"G{self.geometric}"


def curvature_vector(first, second) -> np.ndarray:
    """Curvature vector κN = (a |v|² - (a·v) v) / |v|⁴ from velocity v and acceleration a. Notes §2.10, §2.11.

    first, second: (k, d) or (d,) each. The result is (k, d) (one row for a
    single pair); it points to the centre of curvature, whose agreement is G2.
    The velocity must not vanish.
    """
    v = np.atleast_2d(as_float_array(first, "first"))
    a = np.atleast_2d(as_float_array(second, "second"))
    if v.ndim != 2 or v.shape[1] == 0:
        raise ValueError(f"first: expected velocities of shape (k, d) or (d,), got shape {v.shape}")
    if a.shape != v.shape:
        raise ValueError(f"second: expected the shape {v.shape} of first, got shape {a.shape}")
    if np.any(np.all(v == 0, axis=1)):
        raise ValueError("first: a zero velocity has no curvature vector (the curve has a cusp there)")
    vv = np.einsum("ij,ij->i", v, v)[:, None]
    av = np.einsum("ij,ij->i", a, v)[:, None]
    return (a * vv - av * v) / vv**2


def _close(x: np.ndarray, y: np.ndarray, scale: float, tol: float) -> bool:
    """|x - y| small relative to the larger of the two vectors and to a length scale."""
    size = max(np.linalg.norm(x), np.linalg.norm(y), scale, 1e-300)
    return bool(np.linalg.norm(x - y) <= tol * size)


def continuity(
    p, q, p_interval=(0, 1), q_interval=(1, 2), p_weights=None, q_weights=None, tol: float = 1e-9
) -> Continuity:
    """Parametric order C0..C3 and geometric order G0..G2 at the joint P(end) = Q(start). Notes §2.10.

    p, q: control points (m+1, d), (n+1, d), each over its own parameter interval
    (by default P on [0, 1] and Q on [1, 2]). Ck compares the derivative vectors
    up to order k; G1 asks for tangents in the same direction, G2 in addition for
    the same curvature vector (same centre of curvature). A zero velocity on either
    side of the joint (a degenerate end leg) is reported as G0: the geometric orders
    are defined for non-zero velocities. Tolerance is relative to the size of the
    control polygons.
    """
    p = as_points(p, "p")
    q = as_points(q, "q")
    tol = as_scalar(tol, "tol")
    if p.shape[1] != q.shape[1]:
        raise ValueError(f"p, q: curves of different dimension {p.shape[1]} and {q.shape[1]}")
    p_interval = as_interval(p_interval, "p_interval")
    q_interval = as_interval(q_interval, "q_interval")
    if p_weights is not None:
        p_weights = as_weights(p_weights, len(p), "p_weights")
    if q_weights is not None:
        q_weights = as_weights(q_weights, len(q), "q_weights")
    end, start = p_interval[1], q_interval[0]
    scale = float(max(np.ptp(p, axis=0).max(), np.ptp(q, axis=0).max()))
    dp = [evaluate(p, end, p_weights, p_interval)] + [
        derivative(p, end, k, p_weights, p_interval) for k in (1, 2, 3)
    ]
    dq = [evaluate(q, start, q_weights, q_interval)] + [
        derivative(q, start, k, q_weights, q_interval) for k in (1, 2, 3)
    ]
    if not _close(dp[0], dq[0], scale, tol):
        return Continuity(-1, -1)
    parametric = 0
    for k in (1, 2, 3):
        if not _close(dp[k], dq[k], 0.0, tol):
            break
        parametric = k
    return Continuity(parametric, _geometric_order(dp, dq, tol))


def _geometric_order(dp, dq, tol: float) -> int:
    vp, vq = dp[1], dq[1]
    speed_p, speed_q = np.linalg.norm(vp), np.linalg.norm(vq)
    if speed_p == 0 or speed_q == 0:
        return 0
    if not _close(vp / speed_p, vq / speed_q, 1.0, tol):
        return 0
    kp = curvature_vector(vp, dp[2])[0]
    kq = curvature_vector(vq, dq[2])[0]
    return 2 if _close(kp, kq, 0.0, tol) else 1


def curvature_comb(points, count: int = 50, length: float = 1.0, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """Teeth of a curvature comb of a planar Bézier curve: (bases (count, 2), tips (count, 2)). Notes §2.11.

    Tooth i sits at P(t_i) for `count` evenly spaced t_i, points away from the
    centre of curvature and has length `length` * |κ_i| / max|κ|; the tips
    trace the comb curve.
    """
    pts = as_points(points)
    if pts.shape[1] != 2:
        raise ValueError(f"points: a curvature comb needs planar points of shape (n+1, 2), got shape {pts.shape}")
    count = as_count(count, "count", minimum=2)
    length = as_scalar(length, "length")
    ts = np.linspace(0, 1, count)
    bases = evaluate(pts, ts, weights)
    tangent = derivative(pts, ts, 1, weights)
    speed = np.linalg.norm(tangent, axis=1, keepdims=True)
    normal = np.column_stack([-tangent[:, 1], tangent[:, 0]]) / np.where(speed > 0, speed, 1)
    kappa = signed_curvature(pts, ts, weights)
    kappa = np.where(np.isfinite(kappa), kappa, 0.0)
    largest = np.abs(kappa).max()
    scale = length / largest if largest > 0 else 0.0
    # The centre of curvature is on the +normal side when κ > 0, so -κ N points away from it.
    return bases, bases - scale * kappa[:, None] * normal
