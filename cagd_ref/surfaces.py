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

from ._validation import as_count, as_float_array, as_interval, as_parameter, as_points, as_scalar, as_tolerance
from .bezier import bernstein_matrix, elevate, subdivide, to_homogeneous
from .bspline import basis_matrix, bezier_segments, de_boor, insert_knot
from .continuity import continuity
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
    # chapter 15
    "control_curves",
    "iso_curve",
    "de_casteljau_patch",
    "patch_subdivide",
    "subpatch",
    "patch_elevate",
    "corner_derivatives",
    "second_difference_bounds",
    "curve_tessellation_steps",
    "tessellation_deltas",
    "tessellation_steps",
    "tessellate",
    "tessellation_error",
    "patch_continuity",
    "nurbs_point",
    "nurbs_insert_knot",
    "nurbs_to_bezier",
    "corner_curvatures",
    "corner_fundamental_forms",
    "principal_curvatures",
    "surface_curvatures",
    "triangle_corner_curvatures",
]

# Numbers in one block of working arrays: small enough to stay in the processor's cache.
CACHE_ENTRIES = 1 << 16
# |P_s × P_t| below this fraction of (degree × size of the net)² counts as zero: no normal there.
ZERO_NORMAL = 1e-12


# --- input checking -----------------------------------------------------------------------


def _net(points, weights, name: str = "points") -> tuple[np.ndarray, np.ndarray | None]:
    """The control net (m+1, n+1, d) as floats, and the weights (m+1, n+1) or None."""
    net = as_float_array(points, name)
    if net.ndim != 3 or min(net.shape) < 1:
        raise ValueError(
            f"{name}: expected a control net of shape (m+1, n+1, d), points[i, j] = P_ij, got shape {net.shape}"
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


# === chapter 15: tensor-product surfaces ========================================================


def _direction(direction) -> str:
    if direction not in ("s", "t"):
        raise ValueError(f"direction: expected 's' or 't', got {direction!r}")
    return direction


def _lift(points, weights) -> tuple[np.ndarray, bool]:
    """The homogeneous net (m+1, n+1, d+1) and whether the patch came rational."""
    net, w = _net(points, weights)
    return _homogeneous(net, w), w is not None


def _drop(h: np.ndarray, rational: bool) -> tuple[np.ndarray, np.ndarray | None]:
    """A homogeneous net back to (points, weights); weights None for a polynomial patch."""
    w = h[..., -1]
    return h[..., :-1] / w[..., None], (w.copy() if rational else None)


def _along(h: np.ndarray, direction: str, operation):
    """Apply a curve operation to every s-control curve (direction "s") or every t-control curve ("t").

    The curves of one direction are one curve with many coordinates: the net
    (m+1, n+1, D) is read as m+1 points of (n+1)·D coordinates for "s", so
    `bezier.subdivide` or `bezier.elevate` handle all of them in one call.
    """
    if direction == "t":
        h = h.transpose(1, 0, 2)
    rows, cols, dim = h.shape
    result = operation(h.reshape(rows, cols * dim))
    shaped = [r.reshape(len(r), cols, dim) for r in (result if isinstance(result, tuple) else (result,))]
    if direction == "t":
        shaped = [r.transpose(1, 0, 2) for r in shaped]
    return tuple(np.ascontiguousarray(r) for r in shaped) if isinstance(result, tuple) else shaped[0].copy()


def control_curves(points, direction: str = "s") -> np.ndarray:
    """The control polygons of the s-control curves (columns) or t-control curves (rows). Notes §15.1.

    points: (m+1, n+1, d). "s": the n+1 curves P_0j, ..., P_mj with parameter
    s, shape (n+1, m+1, d); "t": the m+1 curves P_i0, ..., P_in with parameter
    t, shape (m+1, n+1, d).

    >>> from cagd_ref.surfaces import control_curves
    >>> net = np.arange(12.0).reshape(2, 3, 2)                 # degree (1, 2) in the plane
    >>> control_curves(net, "s").shape, control_curves(net, "s")[2].tolist()
    ((3, 2, 2), [[4.0, 5.0], [10.0, 11.0]])
    """
    net, _ = _net(points, None)
    return np.ascontiguousarray(net.transpose(1, 0, 2) if _direction(direction) == "s" else net)


def iso_curve(points, value, direction: str = "s", weights=None) -> tuple[np.ndarray, np.ndarray | None]:
    """Control points and weights of an iso-parameter curve, P(c, t) ("s") or P(s, c) ("t"). Notes §15.1 (15.5).

    For "s" the beads Q_j(c), the points at s = c of the n+1 s-control curves
    (de Casteljau on the homogeneous columns), are the control points of the
    degree-n curve P(c, t) = Σ_j Q_j(c) B_j^n(t); for "t" the beads on the m+1
    t-control curves give P(s, c). points: (m+1, n+1, d); weights None or
    (m+1, n+1). Returns (curve points (n+1, d) or (m+1, d), weights of the
    curve, None for a polynomial patch).

    >>> from cagd_ref.surfaces import iso_curve
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]
    >>> iso_curve(saddle, 0.5, "s")[0].tolist()                   # the beads at s = 1/2
    [[0.5, 0.0, 0.0], [0.5, 1.0, 0.5]]
    """
    h, rational = _lift(points, weights)
    c = as_scalar(value, "value")
    curves = h if _direction(direction) == "s" else h.transpose(1, 0, 2)
    beads = np.einsum("i,ijd->jd", bernstein_matrix(curves.shape[0] - 1, c), curves)
    if np.any(beads[:, -1] == 0):
        raise ValueError(f"value: a bead of the iso-curve at {c} has weight zero (a point at infinity)")
    return _drop(beads, rational)


def _reduce(level: np.ndarray, ts: np.ndarray) -> np.ndarray:
    """De Casteljau along axis 1 of (k, N+1, ...) with one parameter per row: (k, ...)."""
    tt = ts.reshape((-1,) + (1,) * (level.ndim - 1))
    while level.shape[1] > 1:
        level = (1 - tt) * level[:, :-1] + tt * level[:, 1:]
    return level[:, 0]


def de_casteljau_patch(points, s, t, weights=None, first: str = "t") -> np.ndarray:
    """A patch point by de Casteljau's algorithm, along t first (rows, then the beads) or s first. Notes §15.2.

    first="t": every t-control curve (row) is evaluated at t, and the m+1
    beads are the control points of the t-iso-curve P(s, t) in s, which is
    evaluated at s; first="s": the beads on the s-control curves at s, then
    the s-iso-curve at t. Both give `patch_point`. Shapes as in `patch_point`.

    >>> from cagd_ref.surfaces import de_casteljau_patch
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]
    >>> de_casteljau_patch(saddle, 0.5, 0.25, first="s").tolist()
    [0.5, 0.25, 0.125]
    """
    h, _ = _lift(points, weights)
    ss, ts, scalar = _pairs(s, t)
    if first not in ("s", "t"):
        raise ValueError(f"first: expected 's' or 't', got {first!r}")
    k = len(ss)
    if first == "t":
        beads = _reduce(np.broadcast_to(h.transpose(1, 0, 2), (k,) + h.transpose(1, 0, 2).shape), ts)
        values = _reduce(beads, ss)
    else:
        values = _reduce(_reduce(np.broadcast_to(h, (k,) + h.shape), ss), ts)
    return _finish(_project(values, ss, ts), scalar)


def patch_subdivide(points, value=0.5, direction: str = "s", weights=None):
    """Split a patch at s = value ("s") or t = value ("t") into two patches of the same degree. Notes §15.2.

    Every s-control curve (for "s") or t-control curve (for "t") of the
    homogeneous net is split by `bezier.subdivide`. Returns ((left, left
    weights), (right, right weights)), nets (m+1, n+1, d) over [0, value] and
    [value, 1] of the split direction; the weights are None for a polynomial patch.

    >>> from cagd_ref.surfaces import patch_subdivide
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]
    >>> (left, _), (right, _) = patch_subdivide(saddle, 0.5, "s")
    >>> left[1].tolist()
    [[0.5, 0.0, 0.0], [0.5, 1.0, 0.5]]
    """
    h, rational = _lift(points, weights)
    c = as_scalar(value, "value")
    left, right = _along(h, _direction(direction), lambda curves: subdivide(curves, c))
    for part in (left, right):
        if np.any(part[..., -1] == 0):
            raise ValueError(f"value: splitting at {c} gives a control point of weight zero")
    return _drop(left, rational), _drop(right, rational)


def _keep(h: np.ndarray, low: float, high: float, direction: str) -> np.ndarray:
    """The homogeneous net of [low, high] in one direction (the other untouched), by two splits."""
    if (low, high) == (0.0, 1.0):
        return h
    if high != 0:
        part = _along(h, direction, lambda c: subdivide(c, high))[0]  # [0, high]
        return _along(part, direction, lambda c: subdivide(c, low / high))[1]
    part = _along(h, direction, lambda c: subdivide(c, low))[1]  # [low, 1], 1 - low > 0
    return _along(part, direction, lambda c: subdivide(c, (high - low) / (1 - low)))[0]


def subpatch(points, s_range=(0, 1), t_range=(0, 1), weights=None) -> tuple[np.ndarray, np.ndarray | None]:
    """The net of the piece of the patch over [s0, s1] × [t0, t1], reparametrised to [0, 1]². Notes §15.2, Fig. 15.3.

    Two splits per direction (`patch_subdivide`); the ranges may reach beyond
    [0, 1] (the patch extended). Returns (points (m+1, n+1, d), weights or None).

    >>> from cagd_ref.surfaces import subpatch, patch_point
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]
    >>> quarter, _ = subpatch(saddle, (0, 0.5), (0, 0.5))         # P_[0,1/2]×[0,1/2]
    >>> quarter[1, 1].tolist()
    [0.5, 0.5, 0.25]
    """
    h, rational = _lift(points, weights)
    s0, s1 = as_interval(s_range, "s_range")
    t0, t1 = as_interval(t_range, "t_range")
    h = _keep(_keep(h, s0, s1, "s"), t0, t1, "t")
    if np.any(h[..., -1] == 0):
        raise ValueError("s_range, t_range: the piece has a control point of weight zero")
    return _drop(h, rational)


def patch_elevate(points, direction: str = "s", times: int = 1, weights=None) -> tuple[np.ndarray, np.ndarray | None]:
    """Raise the degree in s (every s-control curve) or in t, `times` times; the surface stays. Notes §15.2.

    Returns (points, weights or None): (m+1+times, n+1, d) for "s", (m+1, n+1+times, d) for "t".

    >>> from cagd_ref.surfaces import patch_elevate
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]
    >>> patch_elevate(saddle, "t")[0][1].tolist()
    [[1.0, 0.0, 0.0], [1.0, 0.5, 0.5], [1.0, 1.0, 1.0]]
    """
    h, rational = _lift(points, weights)
    times = as_count(times, "times")
    return _drop(_along(h, _direction(direction), lambda curves: elevate(curves, times)), rational)


def corner_derivatives(points, weights=None, domain=((0, 1), (0, 1))) -> dict[str, np.ndarray]:
    """P_s, P_t, P_ss, P_st, P_tt at the corner (s0, t0) from the six control points there. Notes §15.3.

    For a patch of degree (m, n) over [s0, s1] × [t0, t1], with Δs = s1 - s0 and Δt = t1 - t0:

        P_s  = m/Δs (w10/w00)(P10 - P00),       P_t = n/Δt (w01/w00)(P01 - P00),
        P_ss = [m(m-1)(w20/w00)(P20 - P00) - 2m (w10/w00)((m w10 - w00)/w00)(P10 - P00)] / Δs²,
        P_st = mn/(Δs Δt) [(w11/w00)(P11 - P00) - (w10 w01/w00²)((P10 - P00) + (P01 - P00))],
        P_tt as P_ss with n, w01, w02, P01, P02.

    The notes print "n w10 - w00" in P_ss (the degree in s is m), and their
    P_st and P_tt were lost; these are rebuilt (and checked by SymPy). A
    direction of degree 0 has zero derivatives, degree 1 a zero second one.
    points: (m+1, n+1, d); weights None or (m+1, n+1). Returns a dict of (d,) arrays.

    >>> from cagd_ref.surfaces import corner_derivatives
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]
    >>> derivatives = corner_derivatives(saddle)
    >>> derivatives["P_s"].tolist(), derivatives["P_st"].tolist(), derivatives["P_tt"].tolist()
    ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, 0.0])
    """
    net, w = _net(points, weights)
    w = np.ones(net.shape[:2]) if w is None else w
    (s0, s1), (t0, t1) = _domain(domain)
    ds, dt = s1 - s0, t1 - t0
    m, n = net.shape[0] - 1, net.shape[1] - 1
    zero = np.zeros(net.shape[2])

    def leg(i, j):  # w_ij / w00 (P_ij - P00), zero where the net has no such point
        return w[i, j] / w[0, 0] * (net[i, j] - net[0, 0]) if i <= m and j <= n else zero

    def second(k, a1, a2, w1, h):  # P_ss (or P_tt) of the end of a degree-k curve
        if k < 2:
            return zero.copy()
        return (k * (k - 1) * a2 - 2 * k * ((k * w1 - w[0, 0]) / w[0, 0]) * a1) / h**2

    out = {
        "P_s": m / ds * leg(1, 0),
        "P_t": n / dt * leg(0, 1),
        "P_ss": second(m, leg(1, 0), leg(2, 0), w[min(1, m), 0], ds),
        "P_st": zero.copy(),
        "P_tt": second(n, leg(0, 1), leg(0, 2), w[0, min(1, n)], dt),
    }
    if m >= 1 and n >= 1:
        out["P_st"] = m * n / (ds * dt) * (leg(1, 1) - w[0, 1] / w[0, 0] * leg(1, 0) - w[1, 0] / w[0, 0] * leg(0, 1))
    return out


def _domain(domain) -> tuple[tuple[float, float], tuple[float, float]]:
    try:
        s_range, t_range = domain
    except (TypeError, ValueError):
        raise ValueError(f"domain: expected ((s0, s1), (t0, t1)), got {domain!r}") from None
    return as_interval(s_range, "domain"), as_interval(t_range, "domain")


# --- §15.4 tessellation -------------------------------------------------------------------------


def _polynomial_net(points) -> np.ndarray:
    net, _ = _net(points, None)
    return net


def second_difference_bounds(points) -> tuple[float, float, float]:
    """(M1, M2, M3): bounds on |P_ss|, |P_st|, |P_tt| of a polynomial patch from its control net. Notes §15.4 (15.6).

    M1 = m(m-1) max |P_(i+2)j - 2P_(i+1)j + P_ij|, M2 = mn max |P_(i+1)(j+1) -
    P_(i+1)j - P_i(j+1) + P_ij|, M3 = n(n-1) max |P_i(j+2) - 2P_i(j+1) + P_ij|:
    the hodographs' control points, whose convex hulls hold the derivatives
    (0 where the degree is too low). Euclidean norms. points: (m+1, n+1, d).

    >>> from cagd_ref.surfaces import second_difference_bounds
    >>> second_difference_bounds([[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]])    # z = s t
    (0.0, 1.0, 0.0)
    """
    net = _polynomial_net(points)
    m, n = net.shape[0] - 1, net.shape[1] - 1

    def biggest(differences):
        return float(np.linalg.norm(differences, axis=-1).max()) if differences.size else 0.0

    m1 = m * (m - 1) * biggest(np.diff(net, 2, axis=0)) if m >= 2 else 0.0
    m2 = m * n * biggest(np.diff(np.diff(net, axis=0), axis=1)) if m >= 1 and n >= 1 else 0.0
    m3 = n * (n - 1) * biggest(np.diff(net, 2, axis=1)) if n >= 2 else 0.0
    return float(m1), float(m2), float(m3)


def curve_tessellation_steps(points, tol) -> tuple[float, int]:
    """(δ, n): the step δ = sqrt(8 tol / M) and n = ⌈1/δ⌉ segments that keep a polyline within tol. Notes §15.4.

    M = n(n-1) max |P_(i+2) - 2P_(i+1) + P_i| bounds |P''|, and a chord over
    a parameter step δ strays at most M δ²/8 from the curve. δ is at most 1
    (M = 0: a line needs one segment). points: (n+1, d), polynomial; tol > 0.
    A course example (the notes give none):

    >>> from cagd_ref.surfaces import curve_tessellation_steps
    >>> delta, n = curve_tessellation_steps([(0, 0), (1, 2), (3, 2), (4, 0)], 0.01)
    >>> round(delta, 7), n
    (0.0772195, 13)
    """
    pts = as_points(points)
    eps = as_tolerance(tol)
    degree = len(pts) - 1
    bound = degree * (degree - 1) * float(np.linalg.norm(np.diff(pts, 2, axis=0), axis=1).max()) if degree >= 2 else 0.0
    delta = 1.0 if bound == 0 else min(1.0, float(np.sqrt(8 * eps / bound)))
    return delta, int(np.ceil(1 / delta))


def tessellation_deltas(points, tol) -> tuple[float, float]:
    """(δs, δt): parameter steps with M1 δs² + 2 M2 δs δt + M3 δt² <= 8 tol and fewest triangles. Notes §15.4.

    The three cases of the notes, with (M1, M2, M3) = `second_difference_bounds`:
    M1 = 0 (straight in s): δs = 1, δt = (sqrt(M2² + 8 tol M3) - M2) / M3,
    computed as 8 tol / (sqrt(M2² + 8 tol M3) + M2), whose limit for M3 = 0 (a
    bilinear patch) is 4 tol / M2; M3 = 0: the same with s and t exchanged;
    otherwise δs = k δt with k = sqrt(M3/M1), which maximises the cell area
    δs δt, and δt = sqrt(8 tol / (M1 k² + 2 M2 k + M3)). Each step is then at
    most 1 (the literal formula: a δs clipped to 1 does not enlarge δt). All
    three zero (a plane): (1, 1). "Zero" means exactly 0. points: (m+1, n+1, d), polynomial; tol > 0.

    >>> from cagd_ref.surfaces import tessellation_deltas
    >>> z = [[0, 0, 2, 0], [4, 6, 6, 4], [4, 6, 6, 0], [0, 2, 2, 0]]       # the notes' bicubic (Fig. 15.5)
    >>> net = [[(i, j, z[i][j]) for j in range(4)] for i in range(4)]
    >>> [round(d, 8) for d in tessellation_deltas(net, 0.001)]
    [0.00668268, 0.00771649]
    """
    m1, m2, m3 = second_difference_bounds(points)
    eps = as_tolerance(tol)
    if m1 == 0 and m2 == 0 and m3 == 0:
        return 1.0, 1.0
    if m1 == 0:
        ds, dt = 1.0, 8 * eps / (np.sqrt(m2 * m2 + 8 * eps * m3) + m2)
    elif m3 == 0:
        ds, dt = 8 * eps / (np.sqrt(m2 * m2 + 8 * eps * m1) + m2), 1.0
    else:
        k = np.sqrt(m3 / m1)
        dt = np.sqrt(8 * eps / (m1 * k * k + 2 * m2 * k + m3))
        ds = k * dt
    return min(1.0, float(ds)), min(1.0, float(dt))


def tessellation_steps(points, tol) -> tuple[int, int]:
    """(n_s, n_t) = (⌈1/δs⌉, ⌈1/δt⌉): rows and columns of cells that tessellate the patch within tol. Notes §15.4.

    With δs, δt from `tessellation_deltas`; the grid has (n_s+1)(n_t+1)
    points and 2 n_s n_t triangles. points: (m+1, n+1, d), a polynomial patch
    (the bound does not cover rational ones); tol > 0. The notes' example: the
    bicubic of Fig. 15.5 with tol = 0.001 needs 150 × 130 steps, 39 000 triangles.

    >>> from cagd_ref.surfaces import tessellation_steps
    >>> z = [[0, 0, 2, 0], [4, 6, 6, 4], [4, 6, 6, 0], [0, 2, 2, 0]]
    >>> tessellation_steps([[(i, j, z[i][j]) for j in range(4)] for i in range(4)], 0.001)
    (150, 130)
    """
    ds, dt = tessellation_deltas(points, tol)
    return int(np.ceil(1 / ds)), int(np.ceil(1 / dt))


def tessellate(points, n_s: int, n_t: int, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """Triangles of the patch on the uniform n_s × n_t grid of cells: (vertices, triangles). Notes §15.4.

    vertices ((n_s+1)(n_t+1), d): P(i/n_s, j/n_t) at row i (n_t+1) + j;
    triangles (2 n_s n_t, 3) of vertex indices, each cell cut along its
    diagonal from (i+1, j) to (i, j+1), both counterclockwise in (s, t).

    >>> from cagd_ref.surfaces import tessellate
    >>> vertices, triangles = tessellate([[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]], 1, 1)
    >>> vertices.tolist(), triangles.tolist()
    ([[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 1.0]], [[0, 2, 1], [3, 1, 2]])
    """
    n_s = as_count(n_s, "n_s", minimum=1)
    n_t = as_count(n_t, "n_t", minimum=1)
    s, t = np.meshgrid(np.arange(n_s + 1) / n_s, np.arange(n_t + 1) / n_t, indexing="ij")
    vertices = patch_point(points, s.ravel(), t.ravel(), weights)
    index = np.arange((n_s + 1) * (n_t + 1)).reshape(n_s + 1, n_t + 1)
    v00, v10, v01, v11 = (index[i : i + n_s, j : j + n_t].ravel() for i, j in ((0, 0), (1, 0), (0, 1), (1, 1)))
    lower = np.column_stack([v00, v10, v01])
    upper = np.column_stack([v11, v01, v10])
    return vertices, np.stack([lower, upper], axis=1).reshape(-1, 3)


def tessellation_error(points, n_s: int, n_t: int, weights=None, samples: int = 6,
                       max_cells: int | None = None) -> float:
    """The largest distance, at sample points, between the patch and its triangles of `tessellate`. Notes §15.4.

    In every triangle the linear interpolant of its three vertices is
    compared with the patch at the same (s, t), at `samples` (>= 2) points
    per cell edge on a barycentric grid (vertices included): a measured
    lower estimate of the true maximum, to set beside the bound tol.
    `max_cells` (None: all) measures only a regular sub-lattice of about
    that many cells, for a quick estimate on fine grids.

    >>> from cagd_ref.surfaces import tessellation_error
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]      # z = s t: 1/4 off at the centre
    >>> tessellation_error(saddle, 1, 1, samples=3)
    0.25
    """
    n_s = as_count(n_s, "n_s", minimum=1)
    n_t = as_count(n_t, "n_t", minimum=1)
    samples = as_count(samples, "samples", minimum=2)
    grid = np.linspace(0.0, 1.0, samples)
    u, v = (g.ravel() for g in np.meshgrid(grid, grid, indexing="ij"))
    lower = u + v <= 1 + 1e-12
    local = np.concatenate([np.column_stack([u[lower], v[lower]]), 1 - np.column_stack([u[lower], v[lower]])])
    lo = np.repeat([True, False], lower.sum())
    rows, columns = np.arange(n_s), np.arange(n_t)
    if max_cells is not None:
        stride = max(1, int(np.ceil(np.sqrt(n_s * n_t / as_count(max_cells, "max_cells", minimum=1)))))
        rows, columns = (r[min(stride // 2, len(r) - 1) :: min(stride, len(r))] for r in (rows, columns))
    cells_i, cells_j = (c.ravel() for c in np.meshgrid(rows, columns, indexing="ij"))
    i = np.repeat(cells_i, len(local))
    j = np.repeat(cells_j, len(local))
    uu, vv = np.tile(local[:, 0], len(cells_i)), np.tile(local[:, 1], len(cells_i))
    is_low = np.tile(lo, len(cells_i))
    s, t = (i + uu) / n_s, (j + vv) / n_t
    corners = {key: patch_point(points, (i + a) / n_s, (j + b) / n_t, weights)
               for key, (a, b) in {"00": (0, 0), "10": (1, 0), "01": (0, 1), "11": (1, 1)}.items()}
    low = corners["00"] + uu[:, None] * (corners["10"] - corners["00"]) + vv[:, None] * (corners["01"] - corners["00"])
    high = corners["11"] + (1 - uu)[:, None] * (corners["01"] - corners["11"]) + (1 - vv)[:, None] * (
        corners["10"] - corners["11"])
    linear = np.where(is_low[:, None], low, high)
    return float(np.linalg.norm(patch_point(points, s, t, weights) - linear, axis=1).max())


# --- §15.5 C^n patches ----------------------------------------------------------------------------


def patch_continuity(a, b, a_interval=(0, 1), b_interval=(1, 2), direction: str = "s", tol: float = 1e-9) -> int:
    """The order k of C^k continuity (-1: apart; at most 3) of two patches across a common boundary. Notes §15.5.

    direction "s": patch a ends at s = a_interval[1] where patch b starts at
    s = b_interval[0], and the j-th s-control curves of a and b are the
    matching pair crossing the boundary; "t": the rows. The surfaces meet C^k
    exactly when every matching pair meets C^k as curves
    (`continuity.continuity` on each pair); the result is the smallest order.
    a, b: (m+1, n+1, d) and (m'+1, n+1, d) for "s" (the same number of curves).

    >>> from cagd_ref.surfaces import patch_continuity
    >>> a = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]
    >>> b = [[(1, 0, 0), (1, 1, 1)], [(2, 0, 0), (2, 1, 2)]]       # z = s t on [1, 2]: the same surface
    >>> patch_continuity(a, b)
    3
    """
    na, _ = _net(a, None, "a")
    nb, _ = _net(b, None, "b")
    a_interval, b_interval = as_interval(a_interval, "a_interval"), as_interval(b_interval, "b_interval")
    tol = as_scalar(tol, "tol")
    if _direction(direction) == "t":
        na, nb = na.transpose(1, 0, 2), nb.transpose(1, 0, 2)
    if na.shape[1:] != nb.shape[1:]:
        raise ValueError(
            f"a, b: expected the same number of matching control curves, got shapes {na.shape}, {nb.shape}")
    orders = [continuity(na[:, j], nb[:, j], a_interval, b_interval, tol=tol).parametric for j in range(na.shape[1])]
    return int(min(orders))


# --- §15.6 NURBS surfaces ---------------------------------------------------------------------------


def _nurbs(points, knots_s, knots_t, weights):
    h, rational = _lift(points, weights)
    cs, ct = h.shape[:2]
    ks, kt = as_float_array(knots_s, "knots_s"), as_float_array(knots_t, "knots_t")
    for name, kn, count in (("knots_s", ks, cs), ("knots_t", kt, ct)):
        if kn.ndim != 1 or len(kn) < count or np.any(np.diff(kn) < 0):
            raise ValueError(f"{name}: expected a non-decreasing knot vector of at least {count} knots "
                             f"(c + degree - 1 in the notes' convention), got {kn.tolist()}")
    return h, rational, ks, kt


def nurbs_point(points, knots_s, knots_t, s, t, weights=None) -> np.ndarray:
    """Point(s) of a NURBS surface: de Boor on every s-control curve, then across in t. Notes §15.6.

    points (c_s, c_t, d), weights None or (c_s, c_t); knots in the notes'
    convention for each direction (c + degree - 1 knots, so the degree in s
    is len(knots_s) - c_s + 1), domain [knots_s[m-1], knots_s[c_s-1]] × ...
    s, t as in `patch_point`, inside the domain.

    >>> from cagd_ref.surfaces import nurbs_point
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]   # degree (1, 1): the bilinear patch again
    >>> nurbs_point(saddle, [0, 1], [0, 1], 0.5, 0.25).tolist()
    [0.5, 0.25, 0.125]
    """
    h, _, ks, kt = _nurbs(points, knots_s, knots_t, weights)
    ss, ts, scalar = _pairs(s, t)
    cs, ct, dim = h.shape
    beads = de_boor(h.reshape(cs, ct * dim), ks, ss).reshape(len(ss), ct, dim)
    basis = basis_matrix(kt, len(kt) - ct + 1, ts)
    return _finish(_project(np.einsum("kj,kjd->kd", basis, beads), ss, ts), scalar)


def nurbs_insert_knot(points, knots_s, knots_t, value, direction: str = "s", weights=None):
    """Insert one knot in s (into every s-control curve) or in t (every t-control curve). Notes §15.6.

    Returns (points, knots_s, knots_t, weights or None); one more row of
    control points for "s", one more column for "t"; the surface is unchanged.

    >>> from cagd_ref.surfaces import nurbs_insert_knot
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]
    >>> points, ks, kt, _ = nurbs_insert_knot(saddle, [0, 1], [0, 1], 0.5, "t")
    >>> points.shape, kt.tolist(), points[1, 1].tolist()
    ((2, 3, 3), [0.0, 0.5, 1.0], [1.0, 0.5, 0.5])
    """
    h, rational, ks, kt = _nurbs(points, knots_s, knots_t, weights)
    c = as_scalar(value, "value")
    knots = ks if _direction(direction) == "s" else kt
    holder = {}

    def insert(curves):
        new_points, holder["knots"] = insert_knot(curves, knots, c)
        return new_points

    h = _along(h, direction, insert)
    ks, kt = (holder["knots"], kt.copy()) if direction == "s" else (ks.copy(), holder["knots"])
    pts, w = _drop(h, rational)
    return pts, ks, kt, w


def nurbs_to_bezier(points, knots_s, knots_t, weights=None) -> tuple[np.ndarray, np.ndarray | None]:
    """Split a NURBS surface into Bézier patches: each knot raised to multiplicity = degree. Notes §15.6.

    First every s-control curve, then every t-control curve of the pieces, is
    split into Bézier curves (`bspline.bezier_segments`). Returns (patches
    (p_s, p_t, m+1, n+1, d), weights (p_s, p_t, m+1, n+1) or None): patch
    [a, b] covers the a-th knot span in s and the b-th in t of positive length.

    >>> from cagd_ref.surfaces import nurbs_to_bezier
    >>> net = [[(i, j, 0) for j in range(3)] for i in range(3)]      # degree (1, 1), knots 0 1 2: four bilinear pieces
    >>> patches, _ = nurbs_to_bezier(net, [0, 1, 2], [0, 1, 2])
    >>> patches.shape, patches[1, 0, 0, 1].tolist()
    ((2, 2, 2, 2, 3), [1.0, 1.0, 0.0])
    """
    h, rational, ks, kt = _nurbs(points, knots_s, knots_t, weights)
    cs, ct, dim = h.shape
    m, n = len(ks) - cs + 1, len(kt) - ct + 1
    in_s = bezier_segments(h.reshape(cs, ct * dim), ks).reshape(-1, m + 1, ct, dim)  # (p_s, m+1, c_t, D)
    ps = len(in_s)
    columns = in_s.transpose(2, 0, 1, 3).reshape(ct, ps * (m + 1) * dim)
    in_t = bezier_segments(columns, kt).reshape(-1, n + 1, ps, m + 1, dim)  # (p_t, n+1, p_s, m+1, D)
    patches = np.ascontiguousarray(in_t.transpose(2, 0, 3, 1, 4))
    return _drop(patches, rational)


# --- §15.9 curvature at a corner --------------------------------------------------------------------


def _corner_frame(net: np.ndarray):
    if net.shape[2] != 3:
        raise ValueError(f"points: curvature needs a patch in space, shape (m+1, n+1, 3), got {net.shape}")
    if min(net.shape[:2]) < 2:
        raise ValueError(f"points: expected degree >= 1 in s and in t, got a net of shape {net.shape}")
    a, b = net[1, 0] - net[0, 0], net[0, 1] - net[0, 0]
    cross = np.cross(a, b)
    area2 = float(cross @ cross)
    size = float(np.ptp(net.reshape(-1, 3), axis=0).max())
    if area2 <= (ZERO_NORMAL * size**2) ** 2:
        raise ValueError("points: P00, P10, P01 are collinear (a degenerate corner), so the normal is not defined")
    return a, b, cross, area2


def corner_curvatures(points, weights=None) -> tuple[float, float]:
    """(Gaussian, mean) curvature at the corner (0, 0) from six control points. Notes §15.9 (15.54)-(15.55).

    With a = P10 - P00, b = P01 - P00, the signed heights h_ij of P20, P11,
    P02 above the plane P00 P10 P01 (positive on the side of a × b, the normal
    P_s × P_t), p the degree of the first index (s) and q of the second (t):

        K = w00² [((p-1)/p)((q-1)/q) w20 w02 h20 h02 - w11² h11²] / (w10² w01² |a × b|²),
        H = w00 [((p-1)/p) w01² |b|² w20 h20 - 2 w10 w01 (a·b) w11 h11 + ((q-1)/q) w10² |a|² w02 h02]
            / (2 w10² w01² |a × b|²).

    (The notes' §15.9 calls the first-index degree n and the second m.) A
    degree-1 direction drops its h term. points: (p+1, q+1, 3), p, q >= 1;
    weights None or (p+1, q+1). A ValueError if P00, P10, P01 are collinear.

    >>> from cagd_ref.surfaces import corner_curvatures
    >>> c = (0, 0, 1)
    >>> paraboloid = [[(i / 2, j / 2, (c[i] + c[j]) / 2) for j in range(3)] for i in range(3)]   # z = (x² + y²)/2
    >>> corner_curvatures(paraboloid)
    (1.0, 1.0)
    """
    net, w = _net(points, weights)
    w = np.ones(net.shape[:2]) if w is None else w
    a, b, cross, area2 = _corner_frame(net)
    unit = cross / np.sqrt(area2)
    p, q = net.shape[0] - 1, net.shape[1] - 1
    height = {key: float((net[key] - net[0, 0]) @ unit) if key[0] <= p and key[1] <= q else 0.0
              for key in ((2, 0), (1, 1), (0, 2))}
    weight = {key: (w[key] if key[0] <= p and key[1] <= q else 0.0) for key in ((2, 0), (1, 1), (0, 2))}
    fs, ft = (p - 1) / p, (q - 1) / q
    w00, w10, w01 = w[0, 0], w[1, 0], w[0, 1]
    h20, h11, h02 = weight[2, 0] * height[2, 0], weight[1, 1] * height[1, 1], weight[0, 2] * height[0, 2]
    denominator = w10**2 * w01**2 * area2
    gaussian = w00**2 * (fs * ft * h20 * h02 - h11**2) / denominator
    mean = w00 * (fs * w01**2 * (b @ b) * h20 - 2 * w10 * w01 * (a @ b) * h11 + ft * w10**2 * (a @ a) * h02) / (
        2 * denominator)
    return float(gaussian), float(mean)


def corner_fundamental_forms(points, weights=None) -> tuple[float, float, float, float, float, float]:
    """(E, F, G, L, M, N) at the corner (0, 0), from `corner_derivatives`. Notes §15.9 (15.48)-(15.49).

    E = P_s·P_s, F = P_s·P_t, G = P_t·P_t; L = P_ss·n, M = P_st·n, N = P_tt·n
    with n the unit normal. Then K = (LN - M²)/(EG - F²) and
    H = (NE - 2MF + LG) / (2(EG - F²)): an independent route to `corner_curvatures`.

    >>> from cagd_ref.surfaces import corner_fundamental_forms
    >>> corner_fundamental_forms([[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]])
    (1.0, 0.0, 1.0, 0.0, 1.0, 0.0)
    """
    net, _ = _net(points, weights)
    _corner_frame(net)
    d = corner_derivatives(net, weights)
    normal = np.cross(d["P_s"], d["P_t"])
    normal /= np.linalg.norm(normal)
    values = (d["P_s"] @ d["P_s"], d["P_s"] @ d["P_t"], d["P_t"] @ d["P_t"],
              d["P_ss"] @ normal, d["P_st"] @ normal, d["P_tt"] @ normal)
    return tuple(float(v) for v in values)


def principal_curvatures(points, weights=None) -> tuple[float, float]:
    """(k1, k2), k1 >= k2: the principal curvatures H ± sqrt(H² - K) at the corner (0, 0). Notes §15.9.

    >>> from cagd_ref.surfaces import principal_curvatures
    >>> principal_curvatures([[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]])      # z = s t: saddle
    (1.0, -1.0)
    """
    gaussian, mean = corner_curvatures(points, weights)
    root = float(np.sqrt(max(mean * mean - gaussian, 0.0)))
    return mean + root, mean - root


def surface_curvatures(points, s, t, weights=None) -> tuple[float, float]:
    """(Gaussian, mean) curvature at one point (s, t) in [0, 1]²: subdivide until it is a corner. Notes §15.9.

    The sub-patch [s, 1] (or [0, s], reversed, for s > 1/2) times the same in t
    has the point at its corner (0, 0); each reversal flips the normal, so the
    mean curvature is turned back to the orientation of P_s × P_t. s, t: numbers.

    >>> from cagd_ref.surfaces import surface_curvatures
    >>> saddle = [[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]]
    >>> [round(v, 12) for v in surface_curvatures(saddle, 1.0, 1.0)]        # z = st at (1, 1): K = -1/9, H = -1/3^(3/2)
    [-0.111111111111, -0.19245008973]
    """
    h, rational = _lift(points, weights)
    sigma, tau = as_scalar(s, "s"), as_scalar(t, "t")
    for name, value in (("s", sigma), ("t", tau)):
        if not 0 <= value <= 1:
            raise ValueError(f"{name}: expected a value in [0, 1], got {value}")
    sign = 1.0
    for value, axis, direction in ((sigma, 0, "s"), (tau, 1, "t")):
        if value > 0.5:
            h = np.flip(_keep(h, 0.0, value, direction), axis=axis)
            sign = -sign
        else:
            h = _keep(h, value, 1.0, direction)
    pts, w = _drop(h, rational)
    gaussian, mean = corner_curvatures(pts, w)
    return gaussian, sign * mean


def triangle_corner_curvatures(tri_points, weights=None) -> tuple[float, float]:
    """(Gaussian, mean) curvature at the corner P_00n of a triangular patch. Notes §15.9 (15.59)-(15.60).

    tri_points (n+1, n+1, 3) with entry [i, j] = P_(i, j, n-i-j) for i + j <= n
    (the rest is ignored); weights the same layout or None. With a = P_10(n-1)
    - P_00n, b = P_01(n-1) - P_00n and h_ij the signed heights of P_ij(n-i-j)
    over their plane (positive along a × b), writing w_ij for w_(i, j, n-i-j):

        K = ((n-1)/n)² w00² [w20 w02 h20 h02 - w11² h11²] / (w10² w01² |a × b|²),
        H = ((n-1)/n) w00 [w01² |b|² w20 h20 - 2 w10 w01 (a·b) w11 h11 + w10² |a|² w02 h02] / (2 w10² w01² |a × b|²).

    >>> from cagd_ref.surfaces import triangle_corner_curvatures
    >>> o = (0, 0, 0)                                                # entries with i + j > n are ignored
    >>> tri = [[o, (0, 0.5, 0), (0, 1, 0.5)], [(0.5, 0, 0), (0.5, 0.5, 0), o], [(1, 0, 0.5), o, o]]
    >>> triangle_corner_curvatures(tri)                              # z = (x² + y²)/2 as a quadratic triangle
    (1.0, 1.0)
    """
    net, w = _net(tri_points, weights, "tri_points")
    if net.shape[0] != net.shape[1] or net.shape[0] < 2:
        raise ValueError(f"tri_points: expected shape (n+1, n+1, 3) with n >= 1, entry [i, j] = P_(i,j,n-i-j), "
                         f"got {net.shape}")
    n = net.shape[0] - 1
    w = np.ones(net.shape[:2]) if w is None else w
    if n == 1:
        _corner_frame(net)
        return 0.0, 0.0
    a, b, cross, area2 = _corner_frame(net)
    unit = cross / np.sqrt(area2)
    h20, h11, h02 = (w[k] * float((net[k] - net[0, 0]) @ unit) for k in ((2, 0), (1, 1), (0, 2)))
    f = (n - 1) / n
    w00, w10, w01 = w[0, 0], w[1, 0], w[0, 1]
    denominator = w10**2 * w01**2 * area2
    gaussian = f * f * w00**2 * (h20 * h02 - h11**2) / denominator
    mean = f * w00 * (w01**2 * (b @ b) * h20 - 2 * w10 * w01 * (a @ b) * h11 + w10**2 * (a @ a) * h02) / (
        2 * denominator)
    return float(gaussian), float(mean)
