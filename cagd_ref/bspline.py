"""B-spline curves in polar form: chapter 6 of the notes.

Knot vectors follow the notes, not the usual textbook convention: a degree-n
B-spline with c control points has c + n - 1 knots t_0 ... t_{c+n-2} and no
dummy end knots. Control point i is the polar value P(t_i, ..., t_{i+n-1}),
the curve is defined over the domain [t_{n-1}, t_{c-1}], and the degree is
len(knots) - len(points) + 1. `to_scipy` / `from_scipy` convert to the
c + n + 1 convention of SciPy and most software.

Knots must not decrease and no knot value may appear more than n times, so
the curve is at least C0. Points are (c, d) float arrays; a parameter t is a
number (one point (d,) comes back) or a 1-D array of k values ((k, d)).

Evaluation at a knot uses the span to its right (the curve is continuous, but
derivatives at a knot of reduced continuity are right-hand ones), except at
the end of the domain, where the last span is used.
"""

from __future__ import annotations

from math import comb

import numpy as np

from ._validation import as_count, as_float_array, as_parameter, as_points, as_scalar
from .bezier import hodograph as bezier_hodograph
from .polynomials import BLOCK

__all__ = [
    "de_boor",
    "de_boor_plain",
    "checked_bspline",
    "checked_knots",
    "knot_span",
    "de_boor_triangle",
    "insert_knot",
    "insert_knots",
    "bezier_segments",
    "bezier_segment_intervals",
    "blossom",
    "bezier_blossom",
    "power_blossom",
    "bspline_basis",
    "basis_matrix",
    "greville",
    "explicit_bspline",
    "to_scipy",
    "from_scipy",
    "degree",
    "domain",
    "knot_multiplicities",
    "continuity_at_knots",
    "hodograph",
    "derivative",
    "elevate",
    "polar_values",
    "elevated_polar_values",
    "bezier_end_knots",
    "periodic_closed",
    "circle_approximation",
    "combine_bezier",
]


# --- input checking ---------------------------------------------------------------------


def _as_knots(knots, name: str = "knots") -> np.ndarray:
    kn = as_float_array(knots, name)
    if kn.ndim != 1:
        raise ValueError(f"{name}: expected a 1-D knot vector, got shape {kn.shape}")
    if (kn[1:] < kn[:-1]).any():
        raise ValueError(f"{name}: expected a non-decreasing sequence, got {kn.tolist()}")
    return kn


def _check_knots(kn: np.ndarray, n: int, name: str = "knots") -> None:
    """Enough knots for one segment, a domain of positive length, multiplicities at most n."""
    if len(kn) < 2 * n:
        raise ValueError(
            f"{name}: a degree-{n} B-spline needs at least {2 * n} knots (n + 1 control points), got {len(kn)}"
        )
    c = len(kn) - n + 1
    if not kn[n - 1] < kn[c - 1]:
        raise ValueError(f"{name}: the domain [{kn[n - 1]}, {kn[c - 1]}] = [t_(n-1), t_(c-1)] is empty")
    # Sorted knots: a value appears more than n times exactly when t_i = t_(i+n) for some i (one pass, no sort).
    repeated = kn[n:] == kn[:-n]
    if np.any(repeated):
        bad = kn[n:][repeated][0]
        raise ValueError(
            f"{name}: the knot {bad} appears {np.count_nonzero(kn == bad)} times, more than the degree {n}"
        )


def checked_bspline(points, knots) -> tuple[np.ndarray, np.ndarray, int]:
    """A B-spline's arrays, checked: (points (c, d), knots (c+n-1,), degree n) in the notes' convention. Notes §6.2.

    Fresh float copies; a clear ValueError for too few knots, decreasing knots,
    an empty domain or a knot repeated more than n times.
    """
    pts = as_points(points)
    kn = _as_knots(knots)
    n = len(kn) - len(pts) + 1
    if n < 1:
        raise ValueError(
            f"knots: {len(pts)} control points need len(points) + n - 1 knots for a degree n >= 1, "
            f"i.e. at least {len(pts)}, got {len(kn)}"
        )
    _check_knots(kn, n)
    return pts, kn, n


def checked_knots(knots, degree) -> tuple[np.ndarray, int]:
    """A knot vector for the given degree, checked as `checked_bspline` does: (knots (m,), degree n). Notes §6.2."""
    kn = _as_knots(knots)
    n = as_count(degree, "degree", minimum=1)
    _check_knots(kn, n)
    return kn, n


def domain(knots, degree: int) -> tuple[float, float]:
    """The parameter interval [t_(n-1), t_(c-1)] over which the B-spline is defined. Notes §6.2, §6.14."""
    kn, n = checked_knots(knots, degree)
    return float(kn[n - 1]), float(kn[len(kn) - n])


def _in_domain(ts: np.ndarray, kn: np.ndarray, n: int, name: str = "t") -> None:
    a, b = kn[n - 1], kn[len(kn) - n]
    outside = (ts < a) | (ts > b)
    if np.any(outside):
        raise ValueError(f"{name}: expected values in the domain [{a}, {b}], got {ts[outside][:5].tolist()}")


# --- knot spans and the de Boor triangle ------------------------------------------------


def _nonzero_spans(kn: np.ndarray, n: int) -> np.ndarray:
    """Indices j of the spans [t_j, t_(j+1)] of positive length inside the domain."""
    j = np.arange(n - 1, len(kn) - n)
    return j[kn[j] < kn[j + 1]]


def _spans(kn: np.ndarray, n: int, ts: np.ndarray) -> np.ndarray:
    """For each t, the span j with t_j <= t < t_(j+1); the end of the domain takes the last span."""
    last = _nonzero_spans(kn, n)[-1]
    return np.minimum(np.searchsorted(kn, ts, side="right") - 1, last)


def knot_span(knots, degree: int, t, name: str = "t"):
    """The span j with t_j <= t < t_(j+1) of each t in the domain (the last span takes its right end). Notes §6.8.

    t: a number -> an int, or k numbers -> (k,) ints; a t outside the domain is a ValueError.
    """
    kn, n = checked_knots(knots, degree)
    ts, scalar = as_parameter(t, name)
    _in_domain(ts, kn, n, name)
    spans = _spans(kn, n, ts)
    return int(spans[0]) if scalar else spans


def _gather(pts: np.ndarray, kn: np.ndarray, n: int, spans: np.ndarray):
    """Control points (k, n+1, d) of each span and the 2n knots t_(j-n+1) ... t_(j+n) around it."""
    first = spans[:, None] - n + 1
    return pts[first + np.arange(n + 1)], kn[first + np.arange(2 * n)]


def _triangle(local_points: np.ndarray, local_knots: np.ndarray, values: np.ndarray) -> list[np.ndarray]:
    """All levels of the (polar) de Boor triangle, one per row: level r has shape (k, n+1-r, d).

    values (k, n) holds the argument used at each level: the same t throughout
    for the de Boor algorithm, the n polar arguments for a blossom. The point of
    level r with polar label P(u_1..u_r, t_i..t_(i+n-r-1)) is the affine
    combination of its two parents that replaces knot t_(i-1) (or t_(i+n-r)) by u_r.
    """
    n = local_points.shape[1] - 1
    levels = [local_points]
    for r in range(1, n + 1):
        lower = local_knots[:, r - 1 : n]
        upper = local_knots[:, n : 2 * n - r + 1]
        alpha = ((values[:, r - 1 : r] - lower) / (upper - lower))[..., None]
        previous = levels[-1]
        levels.append((1 - alpha) * previous[:, :-1] + alpha * previous[:, 1:])
    return levels


def de_boor(points, knots, t) -> np.ndarray:
    """Point(s) of a B-spline curve by the de Boor algorithm, all parameters at once. Notes §6.8.

    points: (c, d); knots: (c+n-1,) in the notes' convention. t: a number in
    the domain -> (d,), or k numbers -> (k, d). Each t's span is found with a
    binary search; then, a block of parameters at a time, the n+1 control
    points of each span are gathered coordinate by coordinate and the triangle
    of affine combinations runs on all of them together. It computes what
    `de_boor_plain` computes (the teaching form), tuned for many parameters.

    >>> from cagd_ref.bspline import de_boor
    >>> quartic = [(1, 1), (1, 4), (4, 7), (7, 4), (7, 1)]   # the quartic Bézier curve of §6.7, over [1, 5]
    >>> de_boor(quartic, [1, 1, 1, 1, 5, 5, 5, 5], [1.0, 3.0, 5.0]).tolist()
    [[1.0, 1.0], [4.0, 4.75], [7.0, 1.0]]

    Ref: C. de Boor, On calculating with B-splines, J. Approx. Theory 6, 1972.
    """
    pts, kn, n = checked_bspline(points, knots)
    ts, scalar = as_parameter(t)
    _in_domain(ts, kn, n)
    first = _spans(kn, n, ts) - n + 1  # index of the first control point of each t's span
    # Coordinate-major storage makes every pass run over contiguous parameters, and
    # blocks keep a block's arrays in cache through all n levels.
    coordinates = np.ascontiguousarray(pts.T)  # (d, c)
    result = np.empty((pts.shape[1], len(ts)))
    for start in range(0, len(ts), BLOCK):
        block = slice(start, start + BLOCK)
        tau, offset = ts[block], first[block]
        level = np.take(coordinates, offset + np.arange(n + 1)[:, None], axis=1)  # (d, n+1, m)
        local_knots = np.take(kn, offset + np.arange(2 * n)[:, None])  # (2n, m)
        for r in range(1, n + 1):
            lower, upper = local_knots[r - 1 : n], local_knots[n : 2 * n - r + 1]
            alpha = (tau - lower) / (upper - lower)
            count = n + 1 - r  # points on level r
            level[:, :count] = (1 - alpha) * level[:, :count] + alpha * level[:, 1 : count + 1]
        result[:, block] = level[:, 0]
    return result[:, 0] if scalar else result.T


def de_boor_plain(points, knots, t) -> np.ndarray:
    """The de Boor algorithm in its plain textbook form (the teaching form the chapter shows). Notes §6.8.

    points: (c, d); knots: (c+n-1,). t: a number in the domain -> (d,), or k
    numbers -> (k, d). For t in the span [t_j, t_(j+1)) the triangle starts from
    P_(j-n+1) ... P_(j+1); level r replaces, in the label of point i, the knot
    t_(i-1) by t: P^r_i = ((t_(i+n-r) - t) P^(r-1)_(i-1) + (t - t_(i-1)) P^(r-1)_i) / (t_(i+n-r) - t_(i-1)),
    for every parameter at once. `de_boor` computes the same points, tuned for
    very many parameters.

    >>> from cagd_ref.bspline import de_boor_plain
    >>> quartic = [(1, 1), (1, 4), (4, 7), (7, 4), (7, 1)]   # the quartic Bézier curve of §6.7, over [1, 5]
    >>> de_boor_plain(quartic, [1, 1, 1, 1, 5, 5, 5, 5], 3.0).tolist()
    [4.0, 4.75]

    Ref: C. de Boor, On calculating with B-splines, J. Approx. Theory 6, 1972.
    """
    pts, kn, n = checked_bspline(points, knots)
    ts, scalar = as_parameter(t)
    j = knot_span(kn, n, ts)[:, None]  # (k, 1): t_j <= t < t_(j+1)
    tau = ts[:, None]
    level = pts[j - n + 1 + np.arange(n + 1)]  # (k, n+1, d): the span's control points
    for r in range(1, n + 1):
        i = j - n + 1 + r + np.arange(n + 1 - r)  # the indices of the points of level r
        alpha = ((tau - kn[i - 1]) / (kn[i + n - r] - kn[i - 1]))[..., None]
        level = (1 - alpha) * level[:, :-1] + alpha * level[:, 1:]
    result = level[:, 0]
    return result[0] if scalar else result


def de_boor_triangle(points, knots, t) -> tuple[list[np.ndarray], int]:
    """Every level of the de Boor triangle at a number t, and the span index j. Notes §6.8.

    Level r has shape (n+1-r, d): level 0 holds the control points
    P_(j-n+1) ... P_(j+1) of the span [t_j, t_(j+1)] containing t, the last
    level the single point P(t).
    """
    pts, kn, n = checked_bspline(points, knots)
    tau = np.array([as_scalar(t, "t")])
    _in_domain(tau, kn, n)
    span = _spans(kn, n, tau)
    local_points, local_knots = _gather(pts, kn, n, span)
    levels = _triangle(local_points, local_knots, np.repeat(tau[:, None], n, axis=1))
    return [level[0] for level in levels], int(span[0])


# --- knot insertion and Bézier extraction ----------------------------------------------


def insert_knot(points, knots, t) -> tuple[np.ndarray, np.ndarray]:
    """Insert one knot t by Boehm's algorithm: (c+1, d) points and c+n knots, same curve. Notes §6.7.

    With t in the span [t_j, t_(j+1)], the n-1 points P_(j-n+2) ... P_j are
    replaced by n new ones; new point m (label containing t) is
    ((t_(m+n-1) - t) P_(m-1) + (t - t_(m-1)) P_m) / (t_(m+n-1) - t_(m-1)).

    >>> from cagd_ref.bspline import insert_knot
    >>> quartic = [(1, 1), (1, 4), (4, 7), (7, 4), (7, 1)]   # the notes' example: knots [1111 5555], insert 3
    >>> points, knots = insert_knot(quartic, [1, 1, 1, 1, 5, 5, 5, 5], 3.0)
    >>> points.tolist()
    [[1.0, 1.0], [1.0, 2.5], [2.5, 5.5], [5.5, 5.5], [7.0, 2.5], [7.0, 1.0]]
    >>> knots.tolist()
    [1.0, 1.0, 1.0, 1.0, 3.0, 5.0, 5.0, 5.0, 5.0]

    Ref: W. Boehm, Inserting new knots into B-spline curves, CAD 12(4), 1980.
    """
    pts, kn, n = checked_bspline(points, knots)
    tau = as_scalar(t, "t")
    a, b = kn[n - 1], kn[len(kn) - n]
    if not a <= tau <= b:
        raise ValueError(f"t: expected values in the domain [{a}, {b}], got [{tau}]")
    if np.count_nonzero(kn == tau) >= n:
        raise ValueError(f"t: the knot {tau} already has multiplicity {n} = degree, the most allowed")
    # the span [t_j, t_(j+1)) holding t; at the end of the domain, the last span of positive length
    j = int(np.searchsorted(kn, tau, side="left" if tau == b else "right")) - 1
    m = np.arange(j - n + 2, j + 2)
    alpha = ((tau - kn[m - 1]) / (kn[m + n - 1] - kn[m - 1]))[:, None]
    new_points = (1 - alpha) * pts[m - 1] + alpha * pts[m]
    points_out = np.concatenate([pts[: j - n + 2], new_points, pts[j + 1 :]])
    knots_out = np.concatenate([kn[: j + 1], [tau], kn[j + 1 :]])
    return points_out, knots_out


def insert_knots(points, knots, ts) -> tuple[np.ndarray, np.ndarray]:
    """Insert several knots one after another (in any order): Notes §6.7. ts: a number or (m,)."""
    values, _ = as_parameter(ts, "ts")
    pts, kn, _ = checked_bspline(points, knots)
    for tau in values:
        pts, kn = insert_knot(pts, kn, tau)
    return pts, kn


def bezier_segments(points, knots) -> np.ndarray:
    """Bézier control points of every segment of positive length, in order: shape (s, n+1, d). Notes §6.3, §6.7.

    The Bézier control points of the span [a, b] are the polar values
    P(a, ..., a, b, ..., b) (n - i times a, i times b): what inserting every
    knot until it has multiplicity n would leave there (§6.7). All of them
    come from one polar de Boor triangle per span, evaluated for every span
    and label at once, instead of one insertion after another.

    >>> from cagd_ref.bspline import bezier_segments
    >>> refined = [(1, 1), (1, 2.5), (2.5, 5.5), (5.5, 5.5), (7, 2.5), (7, 1)]   # §6.7: the quartic with knot 3
    >>> halves = bezier_segments(refined, [1, 1, 1, 1, 3, 5, 5, 5, 5])
    >>> halves.shape                                   # two quartic Bézier curves, over [1, 3] and [3, 5]
    (2, 5, 2)
    >>> halves[0].tolist()
    [[1.0, 1.0], [1.0, 2.5], [1.75, 4.0], [2.875, 4.75], [4.0, 4.75]]

    Ref: W. Boehm, Inserting new knots into B-spline curves, CAD 12(4), 1980.
    """
    pts, kn, n = checked_bspline(points, knots)
    spans = _nonzero_spans(kn, n)
    # labels[r, i] = (a, ..., a, b, ..., b) with n - i copies of a = t_j and i of b = t_(j+1), j = spans[r]
    takes_b = np.arange(n)[None, :] >= (n - np.arange(n + 1))[:, None]
    labels = np.where(takes_b, kn[spans + 1][:, None, None], kn[spans][:, None, None])
    values = _segment_blossoms(pts, kn, n, np.repeat(spans, n + 1), labels.reshape(-1, n))
    return values.reshape(len(spans), n + 1, pts.shape[1])


def bezier_segment_intervals(knots, degree: int) -> np.ndarray:
    """Parameter intervals [t_j, t_(j+1)] of the segments of positive length, in order: (s, 2). Notes §6.3."""
    kn, n = checked_knots(knots, degree)
    spans = _nonzero_spans(kn, n)
    return np.column_stack([kn[spans], kn[spans + 1]])


# --- polar form (blossoms) --------------------------------------------------------------


def _as_arguments(args, n: int) -> np.ndarray:
    u = as_float_array(args, "args")
    if u.ndim != 1 or len(u) != n:
        raise ValueError(f"args: a degree-{n} blossom takes {n} arguments, got shape {u.shape}")
    return u


def _segment_blossoms(pts: np.ndarray, kn: np.ndarray, n: int, spans: np.ndarray, args: np.ndarray) -> np.ndarray:
    """Polar values f_j(args[r]) of the segment over span j = spans[r], one per row: (k, d).

    The polar de Boor triangle: level r uses the r-th argument instead of t.
    """
    local_points, local_knots = _gather(pts, kn, n, spans)
    return _triangle(local_points, local_knots, args)[-1][:, 0]


def _span_of_smallest(kn: np.ndarray, n: int, args: np.ndarray) -> np.ndarray:
    """For each row of arguments, the span containing its smallest one (clipped into the domain)."""
    a, b = kn[n - 1], kn[len(kn) - n]
    return _spans(kn, n, np.clip(args.min(axis=1), a, b))


def blossom(points, knots, args) -> np.ndarray:
    """The polar value P(u_1, ..., u_n) of a B-spline curve: shape (d,). Notes §6.1, §6.11.

    Each segment of a B-spline has its own blossom, so the arguments must say
    which one. Rule: the segment used is the one whose span contains the
    smallest argument (t_j <= min(args) < t_(j+1), the last span at the end of
    the domain, the first or last span beyond the domain). Every other segment
    whose open span meets [min(args), max(args)] must give the same value, or
    the polar value is ambiguous and a ValueError says so. The labels
    P(t_i, ..., t_(i+n-1)) = P_i of control points that act on the curve
    always pass, and so do arguments inside one span. Arguments outside [t_0, t_(c+n-2)] are rejected.

    >>> from cagd_ref.bspline import blossom
    >>> quartic = [(1, 1), (1, 4), (4, 7), (7, 4), (7, 1)]   # §6.7: the quartic over [1, 5]
    >>> blossom(quartic, [1, 1, 1, 1, 5, 5, 5, 5], [1, 1, 3, 5]).tolist()   # P(1, 1, 3, 5), the notes' f(1, 1, 3, 5)
    [2.5, 5.5]
    >>> blossom(quartic, [1, 1, 1, 1, 5, 5, 5, 5], [3, 5, 1, 1]).tolist()   # symmetric in its arguments
    [2.5, 5.5]

    Ref: L. Ramshaw (1989), Blossoms are polar forms, CAGD 6.
    """
    pts, kn, n = checked_bspline(points, knots)
    u = _as_arguments(args, n)
    if u.min() < kn[0] or u.max() > kn[-1]:
        raise ValueError(f"args: expected values within the knot vector [{kn[0]}, {kn[-1]}], got {u.tolist()}")
    spans = _nonzero_spans(kn, n)
    chosen = _span_of_smallest(kn, n, u[None, :])
    others = spans[(kn[spans] < u.max()) & (kn[spans + 1] > u.min())]
    rows = np.concatenate([chosen, others])
    values = _segment_blossoms(pts, kn, n, rows, np.repeat(u[None, :], len(rows), axis=0))
    scale = 1.0 + np.max(np.abs(pts))
    if np.max(np.abs(values - values[0])) > 1e-9 * scale:
        raise ValueError(
            f"args: {u.tolist()} reach over several segments (spans starting at {kn[others].tolist()}) "
            "whose blossoms differ there, so the polar value is ambiguous"
        )
    return values[0]


def polar_values(points, knots, labels) -> np.ndarray:
    """Polar values of a B-spline at many argument rows: labels (k, n) -> (k, d). Notes §6.1.

    Each row is evaluated on the segment whose span contains its smallest
    argument, as in `blossom`, but without the ambiguity check: use it for
    labels that are known to be consistent, such as those of refined or
    degree-raised control points.
    """
    pts, kn, n = checked_bspline(points, knots)
    u = as_float_array(labels, "labels")
    if u.ndim != 2 or u.shape[1] != n:
        raise ValueError(f"labels: expected shape (k, {n}), one row of {n} arguments per value, got {u.shape}")
    return _segment_blossoms(pts, kn, n, _span_of_smallest(kn, n, u), u)


def elevated_polar_values(points, knots, labels) -> np.ndarray:
    """Control points of the degree n+1 form at labels (k, n+1) -> (k, d). Notes §6.13.5.

    Each is the mean of the n+1 degree-n polar values of its label with one argument left out.
    """
    u = as_float_array(labels, "labels")
    if u.ndim != 2:
        raise ValueError(f"labels: expected shape (k, n+1), got {u.shape}")
    keep = ~np.eye(u.shape[1], dtype=bool)
    # Row (i, j) of `dropped` is label i without its j-th argument.
    dropped = np.stack([u[:, keep[j]] for j in range(u.shape[1])], axis=1)
    values = polar_values(points, knots, dropped.reshape(-1, u.shape[1] - 1))
    return values.reshape(len(u), u.shape[1], -1).mean(axis=1)


def bezier_blossom(points, args) -> np.ndarray:
    """Polar value P(u_1, ..., u_n) of a Bézier curve over [0, 1]: de Casteljau with a new u per level. Notes §6.1.

    points: (n+1, d), args: (n,) -> (d,). Degree 0 takes no arguments.
    """
    level = as_points(points)
    n = len(level) - 1
    u = as_float_array(args, "args")
    if u.shape != (n,):
        raise ValueError(f"args: a degree-{n} polar form takes {n} arguments, got shape {u.shape}")
    for u_r in u:  # level r: the de Casteljau step with the r-th argument
        level = (1 - u_r) * level[:-1] + u_r * level[1:]
    return level[0]


def _elementary_symmetric(u: np.ndarray) -> np.ndarray:
    """e_0 ... e_n of the numbers u, by multiplying out prod (1 + u_i x)."""
    e = np.zeros(len(u) + 1)
    e[0] = 1.0
    for value in u:
        e[1:] = e[1:] + value * e[:-1]
    return e


def power_blossom(coeffs, args):
    """Blossom p[u_1, ..., u_n] of p(t) = Σ a_i t^i (ascending) with n >= deg p arguments. Notes §6.11.

    p[u] = Σ_i a_i e_i(u) / C(n, i), with e_i the elementary symmetric
    polynomials: symmetric, affine in each u_j, and p[t, ..., t] = p(t).
    coeffs: (m+1,) -> float, or (m+1, d) -> (d,).
    """
    a = as_float_array(coeffs, "coeffs")
    if a.ndim not in (1, 2) or len(a) == 0:
        raise ValueError(f"coeffs: expected shape (m+1,) or (m+1, d), got {a.shape}")
    u = as_float_array(args, "args")
    if u.ndim != 1 or len(u) < len(a) - 1:
        raise ValueError(
            f"args: a degree-{len(a) - 1} polynomial needs at least {len(a) - 1} arguments, got shape {u.shape}"
        )
    n = len(u)
    e = _elementary_symmetric(u)[: len(a)]
    weights = e / np.array([comb(n, i) for i in range(len(a))], dtype=float)
    value = weights @ a
    return float(value) if a.ndim == 1 else value


# --- basis functions, Greville abscissae, explicit B-splines ---------------------------


def bspline_basis(knots, degree: int, i: int, t):
    """Values of the i-th basis function N_i^n: the explicit B-spline with coefficient 1 at i, 0 elsewhere. Notes §6.14.

    knots: (c+n-1,); 0 <= i < c. t in the domain: a number -> float, k numbers -> (k,).

    >>> from cagd_ref.bspline import bspline_basis
    >>> knots = [0, 0, 0, 2, 3, 4, 5, 5, 5]            # Figure 6.28's cubic, seven basis functions
    >>> [round(bspline_basis(knots, 3, 2, t), 6) for t in (0.0, 5 / 3, 2.0, 5.0)]   # the function of P(0, 2, 3)
    [0.0, 0.552984, 0.555556, 0.0]
    >>> round(sum(bspline_basis(knots, 3, i, 2.5) for i in range(7)), 12)         # a partition of unity
    1.0

    Ref: C. de Boor, On calculating with B-splines, J. Approx. Theory 6, 1972; M. G. Cox, The numerical
    evaluation of B-splines, J. Inst. Maths Applics 10, 1972.
    """
    kn, n = checked_knots(knots, degree)
    c = len(kn) - n + 1
    i = as_count(i, "i")
    if i >= c:
        raise ValueError(f"i: expected 0 <= i < {c} (one basis function per control point), got {i}")
    coefficients = np.zeros((c, 1))
    coefficients[i] = 1.0
    ts, scalar = as_parameter(t)
    values = de_boor(coefficients, kn, ts)[:, 0]
    return float(values[0]) if scalar else values


def basis_matrix(knots, degree: int, t) -> np.ndarray:
    """All c basis functions at k parameters by the Cox-de Boor recurrence: (k, c), rows sum to 1. Notes §6.14.3.

    N_i^m = ω_i^m N_i^(m-1) + (1 - ω_(i+1)^m) N_(i+1)^(m-1) for m = 1, ..., n with
    ω_i^m(t) = (t - t_(i-1)) / (t_(i+m-1) - t_(i-1)), or 0 where the two knots are equal,
    starting from the step functions N_i^0 = 1 on [t_(i-1), t_i). The knots t_0 ... t_(c+n-2)
    get one dummy knot at each end, t_(-1) = t_0 and t_(c+n-1) = t_(c+n-2) (the c + n + 1
    convention): `padded[k]` is t_(k-1), and the loop variable p is the degree m.
    A number t gives one row, (1, c).

    Ref: C. de Boor, On calculating with B-splines, J. Approx. Theory 6, 1972; M. G. Cox, The numerical
    evaluation of B-splines, J. Inst. Maths Applics 10, 1972.
    """
    kn, n = checked_knots(knots, degree)
    ts, _ = as_parameter(t)
    padded = np.concatenate([kn[:1], kn, kn[-1:]])
    # Degree 0: one 1 per row, in the span that contains t (which handles the right end).
    basis = np.zeros((len(ts), len(padded) - 1))
    basis[np.arange(len(ts)), knot_span(kn, n, ts) + 1] = 1.0
    tt = ts[:, None]
    for p in range(1, n + 1):
        count = len(padded) - p
        rise, run = tt - padded[:count], padded[p : p + count] - padded[:count]
        omega = np.divide(rise, run, out=np.zeros_like(rise), where=run != 0)  # 0/0 = 0 at repeated knots
        basis = omega[:, :-1] * basis[:, :-1] + (1 - omega[:, 1:]) * basis[:, 1:]
    return basis


def greville(knots, degree: int) -> np.ndarray:
    """Greville abscissae (t_i + ... + t_(i+n-1)) / n, one per control point: shape (c,). Notes §6.9, §6.14.

    >>> from cagd_ref.bspline import greville
    >>> np.round(greville([0, 0, 0, 2, 3, 4, 5, 5, 5], 3), 6).tolist()   # Figure 6.28: 0, 2/3, 5/3, 3, 4, 14/3, 5
    [0.0, 0.666667, 1.666667, 3.0, 4.0, 4.666667, 5.0]
    """
    kn, n = checked_knots(knots, degree)
    sums = np.convolve(kn, np.ones(n), mode="valid")
    return sums / n


def explicit_bspline(coeffs, knots) -> np.ndarray:
    """Planar control points (greville_i, coeffs_i) of the explicit B-spline y = Σ coeffs_i N_i(t): (c, 2). Notes §6.9.

    Because the Greville abscissae reproduce x = t, the curve's x-coordinate is the parameter.
    """
    y = as_float_array(coeffs, "coeffs")
    if y.ndim != 1:
        raise ValueError(f"coeffs: expected a 1-D array of c coefficients, got shape {y.shape}")
    pts, kn, n = checked_bspline(y[:, None], knots)
    return np.column_stack([greville(kn, n), pts[:, 0]])


# --- conversions and bookkeeping -------------------------------------------------------


def to_scipy(points, knots) -> tuple[np.ndarray, np.ndarray, int]:
    """(t, c, k) for scipy.interpolate.BSpline: c + n + 1 knots. Notes §6.2.

    The usual convention has one more knot at each end, which never affects the
    curve on its domain; we repeat the first and last knot.
    """
    pts, kn, n = checked_bspline(points, knots)
    return np.concatenate([kn[:1], kn, kn[-1:]]), pts, n


def from_scipy(t, c, k) -> tuple[np.ndarray, np.ndarray]:
    """(points (c, d), knots (c+n-1,)) from a SciPy-style (t, c, k): drop the first and last knot. Notes §6.2.

    c may be (c,) for a scalar spline; it becomes (c, 1).
    """
    coefficients = as_float_array(c, "c")
    if coefficients.ndim == 1:
        coefficients = coefficients[:, None]
    pts = as_points(coefficients, "c")
    kn = _as_knots(t, "t")
    k = as_count(k, "k", minimum=1)
    if len(kn) != len(pts) + k + 1:
        raise ValueError(f"t: expected len(c) + k + 1 = {len(pts) + k + 1} knots, got {len(kn)}")
    inner = kn[1:-1]
    _check_knots(inner, k, "t")
    return pts, inner


def degree(points, knots) -> int:
    """The degree len(knots) - len(points) + 1 of a B-spline, after checking it. Notes §6.4.1."""
    return checked_bspline(points, knots)[2]


def knot_multiplicities(knots) -> tuple[np.ndarray, np.ndarray]:
    """Distinct knot values and how often each occurs: ((m,), (m,) ints). Notes §6.4."""
    values, counts = np.unique(_as_knots(knots), return_counts=True)
    return values, counts


def continuity_at_knots(knots, degree: int) -> tuple[np.ndarray, np.ndarray]:
    """The order of continuity C^(n-m) at each distinct knot strictly inside the domain. Notes §6.4.

    Returns (values (m,), orders (m,) ints); a knot of multiplicity m is C^(n-m).
    """
    kn, n = checked_knots(knots, degree)
    a, b = domain(kn, n)
    values, counts = np.unique(kn, return_counts=True)
    inside = (values > a) & (values < b)
    return values[inside], n - counts[inside]


# --- derivatives and degree elevation --------------------------------------------------


def hodograph(points, knots) -> tuple[np.ndarray, np.ndarray]:
    """The derivative curve as a degree n-1 B-spline: (points (c-1, d), knots (c+n-3,)). Notes §6.10, (6.2).

    Q_i = n (P_(i+1) - P_i) / (t_(i+n) - t_i) over the knots with the first and
    last removed. Needs degree n >= 2 and no knot of multiplicity n in the
    domain (the derivative jumps there); `derivative` handles both cases.
    """
    pts, kn, n = checked_bspline(points, knots)
    if n < 2:
        raise ValueError("knots: the hodograph of a degree-1 B-spline has degree 0; use derivative() instead")
    inner = kn[1:-1]
    values, counts = np.unique(inner, return_counts=True)
    if np.any(counts > n - 1):
        raise ValueError(
            f"knots: the derivative jumps at the knot {values[counts > n - 1][0]} of multiplicity {n}, "
            "so it is no continuous degree n-1 B-spline; use derivative() instead"
        )
    i = np.arange(len(pts) - 1)
    scale = n / (kn[i + n] - kn[i])
    return scale[:, None] * np.diff(pts, axis=0), inner


def _local_hodograph(local_points: np.ndarray, local_knots: np.ndarray):
    """Hodograph of each gathered segment: (k, n+1, d), (k, 2n) -> (k, n, d), (k, 2n-2).

    Within a segment every denominator t_(i+n) - t_i spans the segment's own
    knot span, so it is positive whatever the multiplicities.
    """
    n = local_points.shape[1] - 1
    spread = local_knots[:, n:] - local_knots[:, :n]
    return n / spread[..., None] * np.diff(local_points, axis=1), local_knots[:, 1:-1]


def derivative(points, knots, t, order: int = 1) -> np.ndarray:
    """The order-th derivative vector(s) of a B-spline curve: (d,) or (k, d). Notes §6.10.

    Each t's segment is gathered as in `de_boor`, differentiated `order` times
    by the hodograph rule (6.2) applied to its n+1 points, and evaluated.
    At a knot the right-hand derivative is returned (left-hand at the domain's end).
    """
    pts, kn, n = checked_bspline(points, knots)
    order = as_count(order, "order")
    ts, scalar = as_parameter(t)
    _in_domain(ts, kn, n)
    if order > n:
        result = np.zeros((len(ts), pts.shape[1]))
    else:
        local_points, local_knots = _gather(pts, kn, n, _spans(kn, n, ts))
        for _ in range(order):
            local_points, local_knots = _local_hodograph(local_points, local_knots)
        values = np.repeat(ts[:, None], n - order, axis=1)
        result = _triangle(local_points, local_knots, values)[-1][:, 0]
    return result[0] if scalar else result


def elevate(points, knots) -> tuple[np.ndarray, np.ndarray]:
    """Raise the degree by one, same curve: every knot value in the domain gains one multiplicity. Notes §6.13.5.

    The new control point with label (u_0, ..., u_n) is the degree n+1 polar
    value F(u_0..u_n), the mean of the n+1 old polar values P(u without u_j).
    Returns (points (c', d), knots) with c' = c + m - 1, m the number of distinct
    knot values in the domain, its two ends included (a Bézier curve: c + 1).
    """
    pts, kn, n = checked_bspline(points, knots)
    a, b = kn[n - 1], kn[len(kn) - n]
    values = np.unique(kn)
    new_knots = np.sort(np.concatenate([kn, values[(values >= a) & (values <= b)]]))
    labels = new_knots[np.arange(len(new_knots) - n)[:, None] + np.arange(n + 1)]
    return elevated_polar_values(pts, kn, labels), new_knots


# --- special knot vectors and curves ---------------------------------------------------


def bezier_end_knots(count: int, degree: int, start: float = 0.0, end: float | None = None) -> np.ndarray:
    """Knots with n-fold end knots (Bézier end conditions) and uniform interior: (count+n-1,). Notes §6.6.

    count control points give count - n segments of equal length over
    [start, end]; `end` defaults to start + count - n (unit spacing). The curve
    then starts at the first control point and ends at the last, tangent to the polygon.
    """
    n = as_count(degree, "degree", minimum=1)
    c = as_count(count, "count", minimum=n + 1)
    a = as_scalar(start, "start")
    b = a + (c - n) if end is None else as_scalar(end, "end")
    if not a < b:
        raise ValueError(f"end: expected end > start = {a}, got {b}")
    breaks = np.linspace(a, b, c - n + 1)
    return np.concatenate([np.full(n - 1, a), breaks, np.full(n - 1, b)])


def periodic_closed(points, degree: int) -> tuple[np.ndarray, np.ndarray]:
    """A closed periodic uniform B-spline through the polygon's points repeated: (c+n, d), knots 0, 1, ... Notes §6.5.

    The first n points are appended again, so the last n segments wrap around
    and the curve closes with C^(n-1) continuity; the domain is [n-1, n-1+c].
    """
    pts = as_points(points)
    n = as_count(degree, "degree", minimum=1)
    if len(pts) < n:
        raise ValueError(f"points: a closed degree-{n} B-spline needs at least {n} points, got {len(pts)}")
    wrapped = np.concatenate([pts, pts[:n]])
    return wrapped, np.arange(len(wrapped) + n - 1, dtype=float)


def circle_approximation(count: int) -> tuple[np.ndarray, np.ndarray, float]:
    """The periodic uniform cubic on a regular `count`-gon that best approximates the unit circle. Notes §6.14.4.

    With control points at radius R and angle step θ = 2π/count, the curve's
    radius is largest at the knots, R (2 + cos θ)/3, and smallest midway,
    R (23 cos(θ/2) + cos(3θ/2))/24. Choosing R so that these straddle 1
    symmetrically minimises the worst radial error, which is returned.
    Returns (points (count+3, 2), knots, error) in the form of `periodic_closed`.
    """
    c = as_count(count, "count", minimum=3)
    theta = 2 * np.pi / c
    at_knot = (2 + np.cos(theta)) / 3
    midway = (23 * np.cos(theta / 2) + np.cos(3 * theta / 2)) / 24
    radius = 2 / (at_knot + midway)
    angles = theta * np.arange(c)
    polygon = radius * np.column_stack([np.cos(angles), np.sin(angles)])
    points, knots = periodic_closed(polygon, 3)
    return points, knots, float(radius * at_knot - 1)


# --- combining Bézier curves ------------------------------------------------------------


def _as_segments(segments, intervals) -> tuple[np.ndarray, np.ndarray]:
    segs = as_float_array(segments, "segments")
    if segs.ndim != 3 or segs.shape[1] < 2:
        raise ValueError(f"segments: expected shape (s, n+1, d) with degree n >= 1, got {segs.shape}")
    spans = as_float_array(intervals, "intervals")
    if spans.shape != (len(segs), 2):
        raise ValueError(f"intervals: expected shape ({len(segs)}, 2), one [a, b] per segment, got {spans.shape}")
    if np.any(spans[:, 1] <= spans[:, 0]):
        raise ValueError(f"intervals: each interval needs a < b, got {spans.tolist()}")
    if np.any(spans[1:, 0] != spans[:-1, 1]):
        raise ValueError(f"intervals: each interval must start where the previous one ends, got {spans.tolist()}")
    return segs, spans


def _joint_continuity(left: np.ndarray, right: np.ndarray, left_span, right_span, tol: float) -> int:
    """Highest order r <= n-1 such that derivatives 0..r agree at the joint, or -1 if the ends differ."""
    n = len(left) - 1
    order = -1
    for r in range(n):
        end, start = left[-1], right[0]
        if np.linalg.norm(end - start) > tol * (1 + max(np.linalg.norm(end), np.linalg.norm(start))):
            break
        order = r
        left, right = bezier_hodograph(left, left_span), bezier_hodograph(right, right_span)
    return order


def combine_bezier(segments, intervals, tol: float = 1e-9) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """One B-spline from consecutive Bézier curves, with a knot of multiplicity n - r at a C^r joint. Notes §6.12.

    segments: (s, n+1, d), segment j defined over intervals[j] = (a_j, b_j) with
    b_j = a_(j+1). At each joint the continuity r (0 ... n-1) is detected by
    comparing derivatives within `tol` (relative); knots the smoothness makes
    redundant are left out and the control points are read off as polar
    values. Ends get n-fold knots (Bézier end conditions).
    Returns (points, knots, continuity (s-1,) ints). Raises if a joint is not even C0.
    """
    segs, spans = _as_segments(segments, intervals)
    tol = as_scalar(tol, "tol")
    n = segs.shape[1] - 1
    orders = np.array(
        [_joint_continuity(segs[j], segs[j + 1], spans[j], spans[j + 1], tol) for j in range(len(segs) - 1)],
        dtype=int,
    )
    if np.any(orders < 0):
        joint = int(np.argmax(orders < 0))
        raise ValueError(f"segments: segment {joint} ends at {segs[joint, -1].tolist()} but the next starts at "
                         f"{segs[joint + 1, 0].tolist()}, so they do not join")
    joints = spans[1:, 0]
    knots = np.concatenate([np.full(n, spans[0, 0]), np.repeat(joints, n - orders), np.full(n, spans[-1, 1])])
    labels = knots[np.arange(len(knots) - n + 1)[:, None] + np.arange(n)]
    # The segment of a label: the first one whose interval reaches past the label's smallest knot.
    owner = np.minimum(np.searchsorted(spans[:, 1], labels.min(axis=1), side="right"), len(segs) - 1)
    # A Bézier curve over [a, b] is the B-spline with knots (a, ..., a, b, ..., b): one triangle for all labels.
    local_knots = np.repeat(spans[owner], n, axis=1)
    points = _triangle(segs[owner], local_knots, labels)[-1][:, 0]
    return points, knots, orders
