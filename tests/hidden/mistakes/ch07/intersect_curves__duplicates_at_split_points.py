"""Keeps every found piece: an intersection on a split point comes out twice."""
import numpy as np


def _band(c, low, high):
    n = len(c) - 1
    if n == 0:
        return (0.0, 1.0) if low <= c[0] <= high else None
    t = np.arange(n + 1) / n
    found = list(t[(c >= low) & (c <= high)])
    for level in (low, high):
        if not np.isfinite(level):
            continue
        for a in range(n + 1):
            for b in range(n + 1):
                if c[a] < level < c[b]:
                    found.append(t[a] + (t[b] - t[a]) * (level - c[a]) / (c[b] - c[a]))
    if not found:
        return None
    return max(min(found), 0.0), min(max(found), 1.0)


def _split(h, s):
    left, right = [h[0]], [h[-1]]
    level = h
    while len(level) > 1:
        level = (1 - s) * level[:-1] + s * level[1:]
        left.append(level[0])
        right.append(level[-1])
    return np.array(left), np.array(right[::-1])


def _restrict(h, lo, hi):
    if lo > 0:
        h = _split(h, lo)[1]
    if hi < 1:
        h = _split(h, (hi - lo) / (1 - lo))[0]
    return h


def _bands(h, pad):
    P = h[:, :2] / h[:, 2:]
    chord = P[-1] - P[0]
    if np.hypot(*chord) <= pad:
        far = P[np.argmax(np.hypot(*(P - P[0]).T))] - P[0]
        chord = far if np.hypot(*far) > pad else np.array([1.0, 0.0])
    u = chord / np.hypot(*chord)
    bands = []
    for a, b in ((-u[1], u[0]), (u[0], u[1])):
        line = np.array([a, b, -(a * P[0, 0] + b * P[0, 1])])
        d = P @ line[:2] + line[2]
        bands.append((line, min(d.min(), 0.0) - pad, max(d.max(), 0.0) + pad))
    return bands


def _clip(h, other, pad):
    kept = (0.0, 1.0)
    for line, low, high in _bands(other, pad):
        v = h @ line
        a = _band(v - low * h[:, 2], 0.0, np.inf)
        b = _band(high * h[:, 2] - v, 0.0, np.inf)
        if a is None or b is None:
            return None
        kept = (max(kept[0], a[0], b[0]), min(kept[1], a[1], b[1]))
        if kept[0] > kept[1]:
            return None
    return kept


def _homogeneous(points, weights, name):
    P = np.asarray(points, dtype=float)
    if P.ndim != 2 or P.shape[1] != 2 or len(P) < 2:
        raise ValueError(f"{name} must be (n+1, 2) with n >= 1")
    w = np.ones(len(P)) if weights is None else np.asarray(weights, dtype=float)
    if w.shape != (len(P),) or np.any(w <= 0):
        raise ValueError(f"{name}: weights must be positive")
    return np.column_stack([P * w[:, None], w])


def intersect_curves(p, q, tol=1e-9, p_weights=None, q_weights=None):
    hp = _homogeneous(p, p_weights, "p")
    hq = _homogeneous(q, q_weights, "q")
    if not 0 < tol < 1:
        raise ValueError("tol must be in (0, 1)")
    scale = max(np.abs(hp[:, :2] / hp[:, 2:]).max(), np.abs(hq[:, :2] / hq[:, 2:]).max())
    pad = 1e-12 * scale
    stack = [(hp, 0.0, 1.0, hq, 0.0, 1.0)]
    found = []
    steps = 0
    while stack:
        a, a0, a1, b, b0, b1 = stack.pop()
        while True:
            steps += 1
            if steps > 10000:
                raise RuntimeError("too many steps: do the curves overlap?")
            if a1 - a0 <= tol and b1 - b0 <= tol:
                found.append((a0, a1, b0, b1))
                break
            before = (a1 - a0, b1 - b0)
            r = _clip(a, b, pad)
            if r is None:
                break
            a, a0, a1 = _restrict(a, *r), a0 + (a1 - a0) * r[0], a0 + (a1 - a0) * r[1]
            r = _clip(b, a, pad)
            if r is None:
                break
            b, b0, b1 = _restrict(b, *r), b0 + (b1 - b0) * r[0], b0 + (b1 - b0) * r[1]
            if a1 - a0 > 0.8 * before[0] and b1 - b0 > 0.8 * before[1]:
                size = max(np.ptp(a[:, :2] / a[:, 2:], axis=0).max(), np.ptp(b[:, :2] / b[:, 2:], axis=0).max())
                if size < 1e-6 * scale:
                    found.append((a0, a1, b0, b1))  # a tangency: the pieces cannot be told apart
                elif a1 - a0 >= b1 - b0:
                    left, right = _split(a, 0.5)
                    m = (a0 + a1) / 2
                    stack += [(right, m, a1, b, b0, b1), (left, a0, m, b, b0, b1)]
                else:
                    left, right = _split(b, 0.5)
                    m = (b0 + b1) / 2
                    stack += [(a, a0, a1, right, m, b1), (a, a0, a1, left, b0, m)]
                break
    found.sort()
    merged = []
    for box in found:
        if merged and box == merged[-1] and abs((box[2] + box[3]) - (merged[-1][2] + merged[-1][3])) < 2e-6:
            last = merged[-1]
            merged[-1] = (last[0], max(last[1], box[1]), min(last[2], box[2]), max(last[3], box[3]))
        else:
            merged.append(box)
    result = np.array([((t0 + t1) / 2, (u0 + u1) / 2) for t0, t1, u0, u1 in merged]).reshape(-1, 2)
    return result[np.lexsort((result[:, 1], result[:, 0]))]
