"""Tensor-product Bézier patches, polynomial and rational: points, tangents, normals. Chapters 15 and 16 of the notes.

A patch of degree (m, n) has a control net `points` of shape (m+1, n+1, d):
points[i, j] = P_ij, the first index along s, the second along t, and

    P(s, t) = Σ_i Σ_j P_ij B_i^m(s) B_j^n(t).

A rational patch takes `weights` (m+1, n+1), none of them zero, and lives in
homogeneous coordinates, w_ij (P_ij, 1), as rational curves do
(`cagd_ref.bezier.to_homogeneous`); its points are projected, Π(x, w) = x / w.

Parameters: s and t are numbers or 1-D arrays that broadcast together; two
numbers give one result (d,), k pairs (k, d).

Chapter 16 computes a point and both tangents in O(mn) operations instead of
de Casteljau's O(n³). For a curve, P = (1 - t) Q + t R, with Q and R the two
degree-(n-1) curves on the first and the last n control points (`split_qr`);
the line through Π(Q(t)) and Π(R(t)) is the tangent, and the length of the
derivative follows from their weights (`curve_point_derivative`). Q and R are
evaluated in a pseudo-power basis, u = t / (1 - t), by Horner's rule, switching
to u = (1 - t) / t for t >= 1/2 (`pseudo_horner`). A patch is the bilinear blend
of four sub-patches of degree (m-1, n-1) (`sub_patches`); blending their values
one way gives the point and the s-tangent, the other way the t-tangent
(`patch_point_tangents`). Their values are exactly the 2 × 2 net that de
Casteljau's algorithm reaches one step before the point
(`de_casteljau_point_tangents`, the O(n³) peer), which is why they carry the
tangents. On a regular grid the sub-patches can be forward-differenced instead
(`grid_point_tangents`).
"""

from __future__ import annotations

import numpy as np

from ._validation import as_count, as_float_array, as_parameter, as_points
from .bezier import bernstein_matrix, elevate, to_homogeneous
from .forward_differencing import forward_difference_eval
from .polynomials import BLOCK, _binomials, bernstein_horner, bernstein_to_power, horner

__all__ = [
    "patch_point",
    "patch_normal",
    "patch_point_tangents",
    "de_casteljau_point_tangents",
    "grid_point_tangents",
    "split_qr",
    "pseudo_power",
    "pseudo_horner",
    "curve_point_tangent",
    "curve_point_derivative",
    "sub_patches",
    "point_tangent_cost",
]

# Numbers in one block of working arrays: small enough to stay in the processor's cache.
CACHE_ENTRIES = 1 << 16
# |P_s × P_t| below this fraction of (degree × size of the net)² counts as zero: no normal there.
ZERO_NORMAL = 1e-12


# --- input checking -----------------------------------------------------------------------


def _net(points, weights) -> tuple[np.ndarray, np.ndarray | None]:
    """The control net (m+1, n+1, d) as floats, and the weights (m+1, n+1) or None."""
    net = as_float_array(points, "points")
    if net.ndim != 3 or min(net.shape) < 1:
        raise ValueError(
            f"points: expected a control net of shape (m+1, n+1, d), points[i, j] = P_ij, got shape {net.shape}"
        )
    if weights is None:
        return net, None
    w = as_float_array(weights, "weights")
    if w.shape != net.shape[:2]:
        raise ValueError(f"weights: expected one weight per control point, shape {net.shape[:2]}, got shape {w.shape}")
    if np.any(w == 0):
        raise ValueError("weights: weights must be nonzero (a zero weight is a control point at infinity)")
    return net, w


def _homogeneous(net: np.ndarray, w: np.ndarray | None) -> np.ndarray:
    """The net in homogeneous coordinates w_ij (P_ij, 1), (m+1, n+1, d+1); weight 1 everywhere when w is None."""
    rows, cols, d = net.shape
    flat_w = np.ones(rows * cols) if w is None else w.ravel()
    return to_homogeneous(net.reshape(-1, d), flat_w).reshape(rows, cols, d + 1)


def _pairs(s, t) -> tuple[np.ndarray, np.ndarray, bool]:
    """s and t broadcast to k pairs (two 1-D arrays), and whether both came as numbers."""
    ss, s_scalar = as_parameter(s, "s")
    ts, t_scalar = as_parameter(t, "t")
    try:
        ss, ts = np.broadcast_arrays(ss, ts)
    except ValueError:
        raise ValueError(
            f"s, t: expected parameters that broadcast together, got {len(ss)} values of s and {len(ts)} of t"
        ) from None
    return ss, ts, s_scalar and t_scalar


def _finish(values, scalar: bool):
    if isinstance(values, tuple):
        return tuple(_finish(v, scalar) for v in values)
    return values[0].copy() if scalar else values


def _project(h: np.ndarray, ss: np.ndarray, ts: np.ndarray) -> np.ndarray:
    """Homogeneous values (k, d+1) -> points (k, d), refusing a zero weight (the patch is at infinity there)."""
    w = h[:, -1]
    if np.any(w == 0):
        at = [(float(a), float(b)) for a, b in zip(ss[w == 0][:5], ts[w == 0][:5])]
        raise ValueError(f"s, t: the rational patch passes through infinity (zero weight) at (s, t) = {at}")
    return h[:, :-1] / w[:, None]


# --- points ---------------------------------------------------------------------------------


def _tensor_values(net: np.ndarray, ss: np.ndarray, ts: np.ndarray) -> np.ndarray:
    """Σ_i Σ_j net[i, j] B_i^m(s) B_j^n(t) at k pairs, (k, D): curves along t, then one curve along s per pair.

    The m+1 rows of the net are m+1 curves in t, evaluated at once by the nested
    Bernstein form (`bernstein_horner`, one column per coordinate of every
    row); each pair then has its own control polygon in s, the m+1 row points,
    summed with the Bernstein weights B_i^m(s). A block of pairs at a time, so
    the working arrays stay in the processor's cache.
    """
    rows, cols, dim = net.shape
    by_column = net.transpose(1, 0, 2).reshape(cols, rows * dim)  # column j: the j-th points of every row
    values = np.empty((len(ss), dim))
    for start in range(0, len(ss), BLOCK):
        s, t = ss[start : start + BLOCK], ts[start : start + BLOCK]
        row_points = bernstein_horner(by_column, t).reshape(len(t), rows, dim)
        values[start : start + BLOCK] = np.einsum("ki,kid->kd", bernstein_matrix(rows - 1, s), row_points)
    return values


def patch_point(points, s, t, weights=None) -> np.ndarray:
    """Point(s) of a polynomial or rational tensor-product Bézier patch. Notes §15.1, §16 (16.11)-(16.12).

    points: (m+1, n+1, d), points[i, j] = P_ij with i along s; weights: None
    or (m+1, n+1), nonzero. s, t: numbers -> (d,), or 1-D arrays that
    broadcast together (k pairs) -> (k, d); any real values (outside [0, 1]
    the patch is extended). A rational patch is evaluated on its homogeneous
    net and projected; a ValueError where its weight vanishes.

    >>> from cagd_ref.surfaces import patch_point
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]     # the bilinear patch z = s t
    >>> patch_point(saddle, 0.5, 0.25).tolist()
    [0.5, 0.25, 0.125]
    >>> patch_point(saddle, [0.0, 1.0], 1.0).tolist()               # two pairs: (0, 1) and (1, 1)
    [[0.0, 1.0, 0.0], [1.0, 1.0, 1.0]]
    """
    net, w = _net(points, weights)
    ss, ts, scalar = _pairs(s, t)
    if w is None:
        return _finish(_tensor_values(net, ss, ts), scalar)
    return _finish(_project(_tensor_values(_homogeneous(net, w), ss, ts), ss, ts), scalar)


# --- chapter 16: curves -----------------------------------------------------------------------


def split_qr(points, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """The homogeneous control points of Q (P_0..P_{n-1}) and R (P_1..P_n), each (n, d+1). Notes §16 (16.4)-(16.5).

    points: (n+1, d) with n >= 1; weights: None (all 1) or (n+1,), nonzero.
    P(t) = (1 - t) Q(t) + t R(t) holds for the homogeneous curves, so Q and R
    are made of the homogeneous points w_i (P_i, 1), not of the P_i themselves.
    A course example (the notes print none): the rational cubic of weights 1, 2, 1/2, 1.

    >>> from cagd_ref.surfaces import split_qr
    >>> q, r = split_qr([(0, 0, 0), (1, 2, 0), (3, 3, 1), (4, 0, 2)], [1, 2, 0.5, 1])
    >>> q.tolist()
    [[0.0, 0.0, 0.0, 1.0], [2.0, 4.0, 0.0, 2.0], [1.5, 1.5, 0.5, 0.5]]
    >>> r.tolist()
    [[2.0, 4.0, 0.0, 2.0], [1.5, 1.5, 0.5, 0.5], [4.0, 0.0, 2.0, 1.0]]
    """
    pts = as_points(points, min_count=2)
    h = to_homogeneous(pts, np.ones(len(pts)) if weights is None else weights)
    return h[:-1].copy(), h[1:].copy()


def pseudo_power(coeffs) -> np.ndarray:
    """The pseudo-power coefficients C(N, i) c_i of Σ c_i B_i^N, same shape (N+1,) or (N+1, d). Notes §16 (16.7).

    Σ c_i B_i^N(t) = (1 - t)^N Σ C(N, i) c_i u^i with u = t / (1 - t): a power
    series in u whose coefficients are computed once per polynomial.

    >>> from cagd_ref.surfaces import pseudo_power
    >>> pseudo_power([1, 1, 1, 1]).tolist()
    [1.0, 3.0, 3.0, 1.0]
    """
    c = as_float_array(coeffs, "coeffs")
    if c.ndim not in (1, 2) or len(c) == 0:
        raise ValueError(f"coeffs: expected coefficients of shape (N+1,) or (N+1, d), got shape {c.shape}")
    return c * _binomials(len(c) - 1).reshape((-1,) + (1,) * (c.ndim - 1))


def _pseudo_values(hat: np.ndarray, ts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Horner's rule on pseudo-power coefficients `hat` with the switch at 1/2: (V (k, ...), scale (k,)).

    Σ c_i B_i^N(t) = scale · V: for t < 1/2, V = Σ hat_i u^i with u = t/(1-t) and
    scale = (1-t)^N; for t >= 1/2, V = Σ hat_(N-i) u^i with u = (1-t)/t and
    scale = t^N. Either way |u| <= 1 for every real t, so V cannot overflow.
    """
    N = len(hat) - 1
    low = ts < 0.5
    values = np.empty((len(ts),) + hat.shape[1:])
    scale = np.empty(len(ts))
    for part, coefficients, near, far in ((low, hat, ts, 1 - ts), (~low, hat[::-1], 1 - ts, ts)):
        if part.any():
            values[part] = horner(coefficients, near[part] / far[part])
            scale[part] = far[part] ** N
    return values, scale


def pseudo_horner(coeffs, t):
    """Σ c_i B_i^N(t) by Horner's rule in the pseudo-power basis, switching form at t = 1/2. Notes §16 (16.7)-(16.10).

    coeffs: Bernstein coefficients (N+1,) or (N+1, d). t: a number -> float
    or (d,); a 1-D array of k values -> (k,) or (k, d); any real t. For t < 1/2
    the sum is (1 - t)^N Σ C(N, i) c_i u^i with u = t / (1 - t); for t >= 1/2 it
    is t^N Σ C(N, i) c_(N-i) u^i with u = (1 - t) / t, so u never leaves [-1, 1]
    (the first form alone divides by zero at t = 1 and overflows near it).
    N multiplies and adds per coordinate, plus the scale factor.

    >>> from cagd_ref.surfaces import pseudo_horner
    >>> pseudo_horner([1, 9, 4, 6], 0.5)                 # X of the notes' rational cubic of §3.3
    5.75
    >>> pseudo_horner([1, 2, 4, 8], [0.0, 0.25, 1.0]).tolist()   # (1 + t)³ in Bernstein form
    [1.0, 1.953125, 8.0]
    """
    hat = pseudo_power(coeffs)
    ts, scalar = as_parameter(t)
    values, scale = _pseudo_values(hat, ts)
    values = values * scale.reshape((-1,) + (1,) * (values.ndim - 1))
    if scalar:
        return float(values[0]) if values.ndim == 1 else values[0].copy()
    return values


def _curve(points, weights) -> np.ndarray:
    """Homogeneous control points (n+1, d+1) of a curve, a constant raised to degree 1."""
    pts = as_points(points)
    h = to_homogeneous(pts, np.ones(len(pts)) if weights is None else weights)
    return elevate(h) if len(h) == 1 else h


def _curve_qr(h: np.ndarray, ts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The values of Q and R at ts, (k, D) each, sharing one positive scale factor (which projection ignores)."""
    both = np.concatenate([h[:-1], h[1:]], axis=1)  # Q's and R's coordinates side by side
    values, _ = _pseudo_values(pseudo_power(both), ts)
    dim = h.shape[1]
    return values[:, :dim], values[:, dim:]


def _weighted_difference(a: np.ndarray, b: np.ndarray, w: np.ndarray) -> np.ndarray:
    """(a_w b - b_w a) / w² in Cartesian coordinates: a_w b_w (Π(b) - Π(a)) / w², with no division by a_w or b_w."""
    return (a[:, -1:] * b[:, :-1] - b[:, -1:] * a[:, :-1]) / (w * w)[:, None]


def _curve_point(q: np.ndarray, r: np.ndarray, ts: np.ndarray) -> np.ndarray:
    """The homogeneous point (1 - t) Q + t R, checked for a zero weight."""
    h = (1 - ts)[:, None] * q + ts[:, None] * r
    if np.any(h[:, -1] == 0):
        raise ValueError(f"t: the rational curve passes through infinity (zero weight) at t = {ts[h[:, -1] == 0]}")
    return h


def curve_point_tangent(points, t, weights=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(p, q, r) = (Π(P(t)), Π(Q(t)), Π(R(t))): the point and the two ends of its tangent segment. Notes §16, Fig. 16.1.

    points: (n+1, d) with n >= 1; weights: None or (n+1,), nonzero. t: a number
    -> three (d,), k values -> three (k, d). p lies on the segment q r, which
    is tangent to the curve at p, at the fraction t R_w / P_w of the way from q.
    q and r are the two points of de Casteljau's last-but-one level.

    >>> from cagd_ref.surfaces import curve_point_tangent
    >>> p, q, r = curve_point_tangent([(1, 0), (1, 1), (0, 1)], 0.5, [1, np.sqrt(2) / 2, 1])   # quarter circle
    >>> [np.round(v, 6).tolist() for v in (p, q, r)]
    [[0.707107, 0.707107], [1.0, 0.414214], [0.414214, 1.0]]
    """
    as_points(points, min_count=2)
    h = _curve(points, weights)
    ts, scalar = as_parameter(t)
    q, r = _curve_qr(h, ts)
    p = _curve_point(q, r, ts)
    if np.any(q[:, -1] == 0) or np.any(r[:, -1] == 0):
        raise ValueError("weights: Q or R passes through infinity here (a zero weight), so q or r does not exist")
    return _finish((p[:, :-1] / p[:, -1:], q[:, :-1] / q[:, -1:], r[:, :-1] / r[:, -1:]), scalar)


def curve_point_derivative(points, t, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """(p, p') of a polynomial or rational Bézier curve from Q and R, O(n) per point. Notes §16 (16.6).

    p' = n Q_w R_w / P_w² (r - q) with q = Π(Q), r = Π(R), the weights Q_w, R_w
    and P_w = (1 - t) Q_w + t R_w; for a polynomial curve it is n (R - Q). Q and
    R come from `pseudo_horner`'s switched Horner form and share its scale
    factor, which cancels. points: (n+1, d); weights: None or (n+1,), nonzero.
    t: a number -> two (d,), k values -> two (k, d); any real t.
    A course example (the notes print none): the quarter circle at t = 1/2,
    where |p'| = 4(√2 - 1).

    >>> from cagd_ref.surfaces import curve_point_derivative
    >>> p, dp = curve_point_derivative([(1, 0), (1, 1), (0, 1)], 0.5, [1, np.sqrt(2) / 2, 1])
    >>> np.round(dp, 9).tolist(), round(float(np.linalg.norm(dp)), 9)
    ([-1.171572875, 1.171572875], 1.656854249)
    """
    h = _curve(points, weights)
    ts, scalar = as_parameter(t)
    q, r = _curve_qr(h, ts)
    p = _curve_point(q, r, ts)
    n = len(h) - 1
    return _finish((p[:, :-1] / p[:, -1:], n * _weighted_difference(q, r, p[:, -1])), scalar)


# --- chapter 16: patches ----------------------------------------------------------------------


def sub_patches(points, weights=None) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The four homogeneous sub-patches P^00, P^10, P^01, P^11 of degree (m-1, n-1), each (m, n, d+1). Notes §16.

    P^kl is the net of the homogeneous points w_ij (P_ij, 1) with i = k..k+m-1
    and j = l..l+n-1 (16.14)-(16.17): k = 1 drops the first row in s, l = 1 the
    first column in t. The patch is their bilinear blend (16.13),
    P = (1-s)(1-t) P^00 + s(1-t) P^10 + (1-s)t P^01 + st P^11.
    points: (m+1, n+1, d) with m, n >= 1; weights: None (all 1) or (m+1, n+1).

    >>> from cagd_ref.surfaces import sub_patches
    >>> net = [[(0, 0, 0), (0, 2, 0)], [(1, 0, 1), (1, 2, 2)], [(2, 0, 0), (2, 2, 1)]]   # degree (2, 1)
    >>> p00, p10, p01, p11 = sub_patches(net, [[1, 1], [2, 3], [1, 1]])
    >>> p10.shape, p10[:, 0].tolist()
    ((2, 1, 4), [[2.0, 0.0, 2.0, 2.0], [2.0, 0.0, 0.0, 1.0]])
    """
    net, w = _net(points, weights)
    if min(net.shape[:2]) < 2:
        raise ValueError(f"points: sub-patches need degree >= 1 in s and in t, got a net of shape {net.shape}")
    h = _homogeneous(net, w)
    m, n = h.shape[0] - 1, h.shape[1] - 1
    return tuple(h[i0 : i0 + m, j0 : j0 + n].copy() for i0, j0 in ((0, 0), (1, 0), (0, 1), (1, 1)))


def _patch(points, weights) -> np.ndarray:
    """The homogeneous net (m+1, n+1, D), a direction of degree 0 raised to degree 1 (its tangent is then zero)."""
    net, w = _net(points, weights)
    h = _homogeneous(net, w)
    rows, cols, dim = h.shape
    if rows == 1:
        h = elevate(h.reshape(1, -1)).reshape(2, cols, dim)
    if cols == 1:
        h = elevate(h.transpose(1, 0, 2).reshape(1, -1)).reshape(2, h.shape[0], dim).transpose(1, 0, 2)
    return h


def _block_size(entries_per_pair: int) -> int:
    """Pairs per block so that one block's working array holds about CACHE_ENTRIES numbers."""
    return max(CACHE_ENTRIES // entries_per_pair, 64)


def _stacked_sub_patches(h: np.ndarray) -> np.ndarray:
    """The four sub-patch nets side by side, (m, n, 2, 2, D): [..., k, l, :] is P^kl."""
    m, n = h.shape[0] - 1, h.shape[1] - 1
    return np.stack([np.stack([h[i0 : i0 + m, j0 : j0 + n] for j0 in (0, 1)], axis=2) for i0 in (0, 1)], axis=2)


def _sub_patch_tables(h: np.ndarray) -> dict[tuple[bool, bool], np.ndarray]:
    """The pseudo-power coefficients of the four sub-patches (16.18), one table (m, n·4·D) per quadrant of (s, t).

    Column block (j, k, l) of a table holds the coefficients in u of row j of
    sub-patch P^kl; the quadrants past 1/2 in s or in t read them reversed.
    """
    m, n = h.shape[0] - 1, h.shape[1] - 1
    sub = _stacked_sub_patches(h)
    hat = sub * (_binomials(m - 1)[:, None] * _binomials(n - 1)[None, :])[:, :, None, None, None]
    tables = {}
    for flip_s in (False, True):
        for flip_t in (False, True):
            table = hat[::-1] if flip_s else hat
            table = table[:, ::-1] if flip_t else table
            tables[flip_s, flip_t] = np.ascontiguousarray(table).reshape(m, -1)
    return tables


def _sub_patch_values(h: np.ndarray, ss: np.ndarray, ts: np.ndarray) -> np.ndarray:
    """The four sub-patches at k pairs by pseudo-power Horner rows, then columns: (k, 2, 2, D), one common scale.

    S[:, k, l] is P^kl(s, t) times (1-s)^(m-1) (1-t)^(n-1), with s^(m-1) or
    t^(n-1) instead past 1/2. Within a quadrant of the (s, t) square the n rows
    cost m - 1 multiplies and adds each (Horner in u, `polynomials.horner`) and
    the pass in v n - 1, per component and sub-patch (16.18).
    """
    n, dim = h.shape[1] - 1, h.shape[2]
    tables = _sub_patch_tables(h)
    values = np.empty((len(ss), 2, 2, dim))
    low_s, low_t = ss < 0.5, ts < 0.5
    block = _block_size(tables[False, False].size)
    for (flip_s, flip_t), table in tables.items():
        chosen = np.flatnonzero((low_s != flip_s) & (low_t != flip_t))
        for start in range(0, len(chosen), block):
            at = chosen[start : start + block]
            s, t = ss[at], ts[at]
            u = (1 - s) / s if flip_s else s / (1 - s)
            v = (1 - t) / t if flip_t else t / (1 - t)
            rows = horner(table, u).reshape(len(at), n, 4 * dim)  # n rows of every sub-patch, Horner in u
            value = rows[:, -1].copy()
            for b in range(n - 2, -1, -1):  # ... then one pass in v
                value *= v[:, None]
                value += rows[:, b]
            values[at] = value.reshape(len(at), 2, 2, dim)
    return values


def _blend(values: np.ndarray, ss: np.ndarray, ts: np.ndarray, m: int, n: int):
    """(p, p_s, p_t) from the four sub-patch values (k, 2, 2, D) of a patch of degree (m, n).

    Blending in t gives A (k = 0) and B (k = 1), the Q and R of the iso-curve
    in s through the point; blending in s gives C and D for the iso-curve in t.
    Then P = (1-s) A + s B = (1-t) C + t D, p = Π(P),
    p_s = m A_w B_w / P_w² (Π(B) - Π(A)) and p_t = n C_w D_w / P_w² (Π(D) - Π(C)).
    """
    s, t = ss[:, None], ts[:, None]
    v00, v10, v01, v11 = values[:, 0, 0], values[:, 1, 0], values[:, 0, 1], values[:, 1, 1]
    a, b = (1 - t) * v00 + t * v01, (1 - t) * v10 + t * v11  # Q and R of the iso-curve in s
    c, d = (1 - s) * v00 + s * v10, (1 - s) * v01 + s * v11  # Q and R of the iso-curve in t
    point = (1 - s) * a + s * b
    p = _project(point, ss, ts)
    w = point[:, -1]
    return p, m * _weighted_difference(a, b, w), n * _weighted_difference(c, d, w)


def patch_point_tangents(points, s, t, weights=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(p, p_s, p_t): the point and both partial derivatives from the four sub-patches, O(mn). Notes §16.

    points: (m+1, n+1, d); weights: None or (m+1, n+1), nonzero. s, t: numbers
    -> three (d,), or broadcasting 1-D arrays (k pairs) -> three (k, d); any
    real values. The four sub-patches (`sub_patches`) are evaluated by
    pseudo-power Horner rows and columns, switched at 1/2 in s and in t
    independently (all four share one scale factor, which cancels); their
    bilinear blend in t gives the Q and R of the iso-curve in s, hence p and
    p_s as in `curve_point_derivative`, and the blend in s gives p_t. A
    direction of degree 0 has a zero tangent. The four projected sub-patch
    points are not coplanar in general: the tangent plane comes from the
    blends, never from three of them.
    A course example (the notes print none): a rational patch of degree (2, 1).

    >>> from cagd_ref.surfaces import patch_point_tangents
    >>> net = [[(0, 0, 0), (0, 2, 0)], [(1, 0, 1), (1, 2, 2)], [(2, 0, 0), (2, 2, 1)]]
    >>> p, p_s, p_t = patch_point_tangents(net, 0.5, 0.5, [[1, 1], [2, 3], [1, 1]])
    >>> [np.round(v * 49, 9).tolist() for v in (p, p_s, p_t)]      # (1, 8/7, 17/14), (8/7, 0, 2/7), (0, 96/49, 46/49)
    [[49.0, 56.0, 59.5], [56.0, 0.0, 14.0], [0.0, 96.0, 46.0]]
    """
    h = _patch(points, weights)
    ss, ts, scalar = _pairs(s, t)
    m, n = h.shape[0] - 1, h.shape[1] - 1
    result = _blend(_sub_patch_values(h, ss, ts), ss, ts, m, n)
    return _finish(_degree_zero_tangents(result, points), scalar)


def _degree_zero_tangents(result, points):
    """Exact zeros for the tangent of a direction of degree 0 (its raised net gives them only to rounding)."""
    p, p_s, p_t = result
    shape = np.shape(points)
    if shape[0] == 1:
        p_s = np.zeros_like(p_s)
    if shape[1] == 1:
        p_t = np.zeros_like(p_t)
    return p, p_s, p_t


def _de_casteljau_net(h: np.ndarray, ss: np.ndarray, ts: np.ndarray) -> np.ndarray:
    """Tensor de Casteljau at k pairs down to the 2 × 2 net: m-1 rounds in s, then n-1 in t, (k, 2, 2, D)."""
    values = np.empty((len(ss), 2, 2, h.shape[2]))
    block = _block_size(h.size)
    for start in range(0, len(ss), block):
        s = ss[start : start + block, None, None, None]
        t = ts[start : start + block, None, None, None]
        level = np.broadcast_to(h, (len(s),) + h.shape)
        while level.shape[1] > 2:
            level = (1 - s) * level[:, :-1] + s * level[:, 1:]
        while level.shape[2] > 2:
            level = (1 - t) * level[:, :, :-1] + t * level[:, :, 1:]
        values[start : start + len(s)] = level
    return values


def de_casteljau_point_tangents(points, s, t, weights=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(p, p_s, p_t) by the tensor de Casteljau algorithm, O(n³): the peer of `patch_point_tangents`. Notes §15.3, §16.

    m - 1 rounds of linear interpolation in s on every column of the
    homogeneous net, then n - 1 in t, leave a 2 × 2 net: the four sub-patch
    values at (s, t) at their true scale. The last bilinear step and the
    tangents are then the same as in `patch_point_tangents`. Shapes as there.

    >>> from cagd_ref.surfaces import de_casteljau_point_tangents
    >>> net = [[(0, 0, 0), (0, 2, 0)], [(1, 0, 1), (1, 2, 2)], [(2, 0, 0), (2, 2, 1)]]
    >>> p, p_s, p_t = de_casteljau_point_tangents(net, 0.5, 0.5, [[1, 1], [2, 3], [1, 1]])
    >>> np.round(p_s * 7, 9).tolist()
    [8.0, 0.0, 2.0]
    """
    h = _patch(points, weights)
    ss, ts, scalar = _pairs(s, t)
    m, n = h.shape[0] - 1, h.shape[1] - 1
    result = _blend(_de_casteljau_net(h, ss, ts), ss, ts, m, n)
    return _finish(_degree_zero_tangents(result, points), scalar)


def patch_normal(points, s, t, weights=None) -> np.ndarray:
    """The unit normal P_s × P_t / |P_s × P_t| of a patch in space (d = 3). Notes §15.3, §16.

    points: (m+1, n+1, 3); weights: None or (m+1, n+1). s, t: numbers -> (3,),
    broadcasting arrays (k pairs) -> (k, 3). The tangents come from
    `patch_point_tangents`. A ValueError where P_s × P_t vanishes (a collapsed
    edge, a singular point): the normal is not defined there.

    >>> from cagd_ref.surfaces import patch_normal
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]     # z = s t: normal (-t, -s, 1) / |...|
    >>> np.round(patch_normal(saddle, 0.0, 0.0), 12).tolist()
    [0.0, 0.0, 1.0]
    """
    net, _ = _net(points, weights)
    if net.shape[2] != 3:
        raise ValueError(f"points: normals exist for patches in space, expected shape (m+1, n+1, 3), got {net.shape}")
    ss, ts, scalar = _pairs(s, t)
    _, p_s, p_t = patch_point_tangents(points, ss, ts, weights)
    normal = np.cross(p_s, p_t)
    length = np.linalg.norm(normal, axis=1)
    size = max(net.shape[0] - 1, net.shape[1] - 1, 1) * float(np.ptp(net.reshape(-1, 3), axis=0).max())
    flat = length <= ZERO_NORMAL * size**2
    if np.any(flat):
        at = [(float(a), float(b)) for a, b in zip(ss[flat][:5], ts[flat][:5])]
        raise ValueError(f"s, t: P_s × P_t vanishes at (s, t) = {at}, so the patch has no normal there")
    return _finish(normal / length[:, None], scalar)


def grid_point_tangents(points, s_count: int, t_count: int, weights=None):
    """(p, p_s, p_t) on the regular grid s_i = i/(s_count-1), t_j = j/(t_count-1) by forward differencing. Notes §16.

    Each sub-patch is turned into power form, in s then in t
    (`polynomials.bernstein_to_power`), and stepped across the grid by
    forward differences (`forward_differencing.forward_difference_eval`): n
    additions per step instead of Horner's multiplies. The pseudo-power forms
    cannot be differenced this way, since equal steps in t are unequal steps
    in u = t/(1-t). Returns three arrays (s_count, t_count, d); counts >= 2.

    >>> from cagd_ref.surfaces import grid_point_tangents
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]
    >>> p, p_s, p_t = grid_point_tangents(saddle, 3, 2)
    >>> p[1, 1].tolist(), p_s[1, 1].tolist()
    ([0.5, 1.0, 0.5], [1.0, 0.0, 1.0])
    """
    h = _patch(points, weights)
    s_count = as_count(s_count, "s_count", minimum=2)
    t_count = as_count(t_count, "t_count", minimum=2)
    m, n, dim = h.shape[0] - 1, h.shape[1] - 1, h.shape[2]
    sub = _stacked_sub_patches(h)
    # In s: every column of every sub-patch at once (the columns of a coefficient array are separate polynomials).
    in_s = forward_difference_eval(bernstein_to_power(sub.reshape(m, -1)), 0.0, 1 / (s_count - 1), s_count)
    columns = in_s.reshape(s_count, n, -1).transpose(1, 0, 2).reshape(n, -1)  # row s_i's Bernstein coefficients in t
    in_t = forward_difference_eval(bernstein_to_power(columns), 0.0, 1 / (t_count - 1), t_count)
    values = in_t.reshape(t_count, s_count, 2, 2, dim).transpose(1, 0, 2, 3, 4).reshape(-1, 2, 2, dim)
    grid_s, grid_t = (g.ravel() for g in np.meshgrid(np.linspace(0, 1, s_count), np.linspace(0, 1, t_count),
                                                     indexing="ij"))
    p, p_s, p_t = _degree_zero_tangents(_blend(values, grid_s, grid_t, m, n), points)
    return tuple(v.reshape(s_count, t_count, -1) for v in (p, p_s, p_t))


def point_tangent_cost(m: int, n: int, components: int = 4) -> dict[str, tuple[int, int]]:
    """(multiplies, adds) per point for a point and both tangents on a degree-(m, n) patch, by method. Notes §16.

    "sub_patches": the notes' count, four sub-patches of degree (m-1, n-1) by
    pseudo-power Horner, n rows of m - 1 steps and one pass of n - 1, each
    step one multiply and one add per component: 4 (mn - 1) per component,
    16(mn - 1) for the four components x, y, z, w. "de_casteljau": the tensor
    de Casteljau algorithm down to the same 2 × 2 net, (n+1)(m(m+1)/2 - 1) +
    2(n(n+1)/2 - 1) interpolations (1-s)a + s b per component, 2 multiplies
    and 1 add each. Neither counts the work both share: 1 - s, u and v, the
    bilinear blends and the projections (a constant per point). m, n >= 1.

    >>> from cagd_ref.surfaces import point_tangent_cost
    >>> point_tangent_cost(3, 3)                      # the notes: 16n² - 16 multiplies and as many adds
    {'sub_patches': (128, 128), 'de_casteljau': (240, 120)}
    """
    m = as_count(m, "m", minimum=1)
    n = as_count(n, "n", minimum=1)
    d = as_count(components, "components", minimum=1)
    horner_steps = 4 * d * (m * n - 1)
    interpolations = d * ((n + 1) * (m * (m + 1) // 2 - 1) + 2 * (n * (n + 1) // 2 - 1))
    return {"sub_patches": (horner_steps, horner_steps), "de_casteljau": (2 * interpolations, interpolations)}
