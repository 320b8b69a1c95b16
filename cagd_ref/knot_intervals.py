"""B-splines labelled with knot intervals instead of knots: notes §6.13 and §6.14.1-6.14.2.

A knot interval is the difference of two consecutive knots; the intervals keep
everything about the knots except their origin, which never changes a curve's
shape. Two kinds of curve are handled, chosen by the keyword `degree`:

* open curves (``degree=None``): `intervals` = np.diff(knots) of a B-spline in
  the notes' knot convention, c + n - 2 of them, and the degree follows from
  the counts. For odd degree intervals[i + (n-1)//2] belongs to the polygon
  edge P_i P_(i+1), for even degree to the vertex P_i; the (n-1)//2 intervals
  at each end hang past the end points ("end-condition" intervals).
* closed periodic curves (``degree=n``): one interval per control point,
  d_i on the edge P_i P_(i+1) (odd n) or on the vertex P_i (even n), indices
  taken cyclically. With the knot origin at the start of d_0, control point i
  has the polar label P(t_(i+s), ..., t_(i+s+n-1)) where s = -((n-1)//2).

Points are (c, d) float arrays, as everywhere in `cagd_ref`.
"""

from __future__ import annotations

import numpy as np

from . import bspline
from ._validation import as_count, as_float_array, as_parameter, as_points, as_scalar

__all__ = [
    "intervals_from_knots",
    "knots_from_intervals",
    "closed_to_open",
    "split_interval",
    "expose_bezier",
    "halve_intervals",
    "quadratic_bezier_points",
    "hodograph_intervals",
    "elevate_intervals",
    "cubic_basis_from_intervals",
    "refine_basis",
]


# --- conversions ------------------------------------------------------------------------


def _as_intervals(intervals, name: str = "intervals") -> np.ndarray:
    d = as_float_array(intervals, name)
    if d.ndim != 1 or len(d) == 0:
        raise ValueError(f"{name}: expected a 1-D array of knot intervals, got shape {d.shape}")
    if np.any(d < 0):
        raise ValueError(f"{name}: knot intervals cannot be negative, got {d.tolist()}")
    return d


def intervals_from_knots(knots) -> np.ndarray:
    """Knot intervals d_i = t_(i+1) - t_i of a knot vector: (m,) -> (m-1,). Notes §6.13."""
    kn = as_float_array(knots, "knots")
    if kn.ndim != 1 or len(kn) < 2:
        raise ValueError(f"knots: expected a 1-D knot vector of at least 2 knots, got shape {kn.shape}")
    d = np.diff(kn)
    if np.any(d < 0):
        raise ValueError(f"knots: expected a non-decreasing sequence, got {kn.tolist()}")
    return d


def knots_from_intervals(intervals, start: float = 0.0) -> np.ndarray:
    """The knot vector start, start + d_0, start + d_0 + d_1, ...: (m,) -> (m+1,). Notes §6.13."""
    d = _as_intervals(intervals)
    return as_scalar(start, "start") + np.concatenate([[0.0], np.cumsum(d)])


def _offset(n: int) -> int:
    """s with control point i of a closed curve labelled P(t_(i+s), ..., t_(i+s+n-1))."""
    return -((n - 1) // 2)


def _closed(points, intervals, degree) -> tuple[np.ndarray, np.ndarray, int]:
    pts = as_points(points)
    d = _as_intervals(intervals)
    n = as_count(degree, "degree", minimum=1)
    if len(d) != len(pts):
        raise ValueError(f"intervals: a closed curve has one interval per control point, {len(pts)}, got {len(d)}")
    if len(pts) < n + 1:
        raise ValueError(f"points: a closed degree-{n} curve needs at least {n + 1} control points, got {len(pts)}")
    if not d.sum() > 0:
        raise ValueError("intervals: at least one knot interval must be positive")
    return pts, d, n


def _open(points, intervals) -> tuple[np.ndarray, np.ndarray, int]:
    """(points, knots from 0, degree) of an open curve, checked by `bspline`."""
    pts = as_points(points)
    kn = knots_from_intervals(intervals)
    try:
        return pts, kn, bspline.degree(pts, kn)
    except ValueError as err:
        raise ValueError(f"intervals: as the differences of a knot vector, {err}") from None


def _periodic_knots(d: np.ndarray, indices) -> np.ndarray:
    """Knots t_k of the periodic extension (t_0 = 0, t_(k+1) - t_k = d_(k mod c)) at integer indices k.

    Each knot is summed outwards from t_0 one interval at a time, so a knot has
    the same floating-point value whatever else is asked for, knots never
    decrease, and zero intervals (which add exactly 0) give exactly equal knots.
    """
    k = np.asarray(indices)
    c, high, low = len(d), max(int(k.max()), 0), min(int(k.min()), 0)
    forward = np.concatenate([[0.0], np.cumsum(d[np.arange(high) % c])])
    backward = -np.concatenate([[0.0], np.cumsum(d[np.arange(-1, low - 1, -1) % c])])
    return np.where(k >= 0, forward[np.clip(k, 0, high)], backward[np.clip(-k, 0, -low)])


def _window(pts: np.ndarray, d: np.ndarray, n: int, first_label: int, count: int):
    """An open B-spline made of `count` consecutive control points of a closed one.

    Its point p is closed point (first_label + p - s) mod c, whose polar label
    starts at knot index first_label + p; over its domain it traces part of the closed curve.
    """
    labels = first_label + np.arange(count)
    knots = _periodic_knots(d, first_label + np.arange(count + n - 1))
    return pts[np.mod(labels - _offset(n), len(pts))], knots


def closed_to_open(points, intervals, degree: int) -> tuple[np.ndarray, np.ndarray]:
    """An open B-spline tracing a closed periodic curve once: (points (c+n, d), knots (c+2n-1,)). Notes §6.5, §6.13.

    The control polygon is walked once and its first n points repeated; the
    knots come from the intervals, so its domain is one full period.
    """
    pts, d, n = _closed(points, intervals, degree)
    return _window(pts, d, n, _offset(n), len(pts) + n)


# --- knot insertion (interval splitting) --------------------------------------------------


def split_interval(points, intervals, index: int, fraction: float, *, degree: int | None = None):
    """Split knot interval `index` into fraction*d and (1-fraction)*d: knot insertion. Notes §6.13.1.

    Returns (points, intervals) with one more of each; the curve does not change.
    Open curve (degree=None): the interval must lie inside the domain (not an
    end-condition interval). Closed curve (degree=n): any interval; new point
    positions follow the polar labels of the periodic knots.

    >>> from cagd_ref.knot_intervals import split_interval
    >>> pentagon = [(0, 0), (4, -0.5), (5.5, 2.5), (2.5, 5), (-1, 3)]   # a closed cubic, as in Figure 6.15
    >>> points, intervals = split_interval(pentagon, [3, 1, 2, 2, 1], 0, 1 / 3, degree=3)
    >>> intervals.tolist()                             # the interval 3 split into 1 and 2
    [1.0, 2.0, 1.0, 2.0, 2.0, 1.0]
    >>> len(points)
    6
    >>> figure_6_11 = [(0, 0), (1, 2), (3, 3), (5, 2.5), (7, 0.5), (8, -1)]   # an open cubic, knots 1, 2, 3, 4, 6, ...
    >>> split_interval(figure_6_11, [1, 1, 1, 2, 3, 1, 1], 4, 1 / 3)[1].tolist()
    [1.0, 1.0, 1.0, 2.0, 1.0, 2.0, 1.0, 1.0]
    """
    f = as_scalar(fraction, "fraction")
    if not 0 <= f <= 1:
        raise ValueError(f"fraction: expected a number in [0, 1], got {f}")
    if degree is None:
        return _split_open(points, intervals, index, f)
    return _split_closed(points, intervals, index, f, degree)


def _checked_index(index, count: int) -> int:
    q = as_count(index, "index")
    if q >= count:
        raise ValueError(f"index: expected 0 <= index < {count}, got {q}")
    return q


def _split_open(points, intervals, index, f):
    pts, kn, n = _open(points, intervals)
    q = _checked_index(index, len(kn) - 1)
    if not n - 1 <= q <= len(kn) - n - 1:
        raise ValueError(
            f"index: interval {q} is an end-condition interval outside the domain; "
            f"splittable are {n - 1} ... {len(kn) - n - 1}"
        )
    knot = kn[q] + f * (kn[q + 1] - kn[q])
    _check_room(kn, knot, n, q, f)
    new_points, new_knots = bspline.insert_knot(pts, kn, knot)
    return new_points, intervals_from_knots(new_knots)


def _check_room(knots: np.ndarray, knot: float, n: int, q: int, f: float) -> None:
    if np.count_nonzero(knots == knot) >= n:
        raise ValueError(
            f"fraction: splitting interval {q} at {f} adds a knot where {n} already coincide, "
            f"more than the degree {n} allows"
        )


def _split_closed(points, intervals, index, f, degree):
    pts, d, n = _closed(points, intervals, degree)
    c = len(pts)
    q = _checked_index(index, c)
    s = _offset(n)
    # An open window whose domain holds interval q, wide enough that every new
    # point's label (knot indices q-n+2 ... q+c+n) stays inside it.
    first = q - n - 1
    window_points, window_knots = _window(pts, d, n, first, c + 2 * n + 2)
    knot = window_knots[q - first] + f * d[q]
    _check_room(window_knots, knot, n, q, f)
    new_points, _ = bspline.insert_knot(window_points, window_knots, knot)
    new_intervals = np.concatenate([d[:q], [f * d[q], (1 - f) * d[q]], d[q + 1 :]])
    # New point i has its label starting at knot index i + s of the refined periodic knots,
    # which is window point i + s - first for the labels from q-n+2 to q-n+2+c.
    labels = np.arange(q - n + 2, q - n + 3 + c)
    order = np.argsort(np.mod(labels - s, c + 1))
    return new_points[labels - first][order], new_intervals


# --- Bézier extraction and refinement ---------------------------------------------------


def expose_bezier(points, intervals, *, degree: int | None = None) -> np.ndarray:
    """Bézier control points of every segment of positive length: (s, n+1, d). Notes §6.13.

    Splitting off zero intervals next to a segment until n-1 zeros separate it
    from its neighbours turns its control points into Bézier points. Segments
    come in the order of their intervals (for a closed curve starting with interval 0).
    """
    if degree is None:
        pts, kn, _ = _open(points, intervals)
        return bspline.bezier_segments(pts, kn)
    pts, d, n = _closed(points, intervals, degree)
    segments = bspline.bezier_segments(*closed_to_open(pts, d, n))
    # The unrolled curve's domain starts with interval s + n - 1; rotate so interval 0 leads.
    first = (_offset(n) + n - 1) % len(d)
    positive = np.flatnonzero(d > 0)
    return np.roll(segments, int(np.count_nonzero(positive < first)), axis=0)


def halve_intervals(points, intervals, *, degree: int | None = None):
    """Refine by splitting every positive interval (inside the domain) in half: (points, intervals). Notes §6.13.2.

    For a closed curve the control polygon roughly doubles and converges to the
    curve under repetition; for uniform cubics the new points are
    (P_(i-1) + 6 P_i + P_(i+1)) / 8 and (P_i + P_(i+1)) / 2.
    """
    if degree is None:
        pts, kn, n = _open(points, intervals)
        inner = kn[n - 1 : len(kn) - n + 1]
        middles = ((inner[:-1] + inner[1:]) / 2)[np.diff(inner) > 0]
        new_points, new_knots = bspline.insert_knots(pts, kn, middles)
        return new_points, intervals_from_knots(new_knots)
    pts, d, n = _closed(points, intervals, degree)
    # Split from the last interval backwards, so the indices still to do do not move.
    for q in np.flatnonzero(d > 0)[::-1]:
        pts, d = _split_closed(pts, d, int(q), 0.5, n)
    return pts, d


def quadratic_bezier_points(points, intervals, *, degree: int | None = None) -> np.ndarray:
    """Bézier points of each segment of a quadratic B-spline, straight from the intervals: (s, 3, d). Notes §6.13.3.

    The segment of vertex P_j (interval d_j > 0) runs from the point dividing
    P_(j-1) P_j in the ratio d_(j-1) : d_j, through P_j, to the point dividing
    P_j P_(j+1) in the ratio d_j : d_(j+1). Open curves have segments for the
    interior vertices only.
    """
    if degree is None:
        pts, kn, n = _open(points, intervals)
        d, j = np.diff(kn), np.arange(1, len(pts) - 1)
    else:
        pts, d, n = _closed(points, intervals, degree)
        j = np.arange(len(pts))
    if n != 2:
        raise ValueError(f"degree: expected a quadratic B-spline, got degree {n}")
    j = j[d[j] > 0]
    before, after = np.mod(j - 1, len(pts)), np.mod(j + 1, len(pts))
    dj, d_before, d_after = d[j][:, None], d[before][:, None], d[np.mod(j + 1, len(d))][:, None]
    start = (dj * pts[before] + d_before * pts[j]) / (d_before + dj)
    end = (d_after * pts[j] + dj * pts[after]) / (dj + d_after)
    return np.stack([start, pts[j], end], axis=1)


# --- hodograph and degree elevation -----------------------------------------------------


def hodograph_intervals(points, intervals, *, degree: int | None = None):
    """The derivative curve, degree n-1 with the same knot intervals: (points, intervals). Notes §6.13.4, (6.6).

    Its control points are the differences ν_i (P_(i+1) - P_i), where ν_i = n / (sum of the
    n intervals between the two points' labels): the inverse of the average of n neighbouring
    intervals. A closed hodograph is numbered like every closed degree-(n-1) curve here, so the
    same interval list goes with it: for odd n its point i is H_i = ν_i (P_(i+1) - P_i), for
    even n it is H_i = ν_(i-1) (P_i - P_(i-1)), one place later than the notes' (6.6) numbers it
    (numbered as there, the edge H_i H_(i+1) of an even-degree hodograph would carry d_(i+1), not d_i).
    Open curves drop the two outermost intervals (the knot vector loses its end knots).
    """
    if degree is None:
        pts, kn, _ = _open(points, intervals)
        new_points, new_knots = bspline.hodograph(pts, kn)
        return new_points, intervals_from_knots(new_knots)
    pts, d, n = _closed(points, intervals, degree)
    if n < 2:
        raise ValueError("degree: the hodograph of a degree-1 curve has degree 0, which has no control polygon here")
    c, s = len(pts), _offset(n)
    i = np.arange(c)
    # P_i and P_(i+1) differ in the knots t_(i+s) and t_(i+s+n), n intervals apart.
    spread = _periodic_knots(d, i + s + n) - _periodic_knots(d, i + s)
    if np.any(spread == 0):
        raise ValueError("intervals: n consecutive zero intervals make the curve discontinuous")
    q = (n / spread)[:, None] * (pts[np.mod(i + 1, c)] - pts)
    # q_i has the label starting at t_(i+s+1); the degree n-1 convention starts labels at i + s'
    # (s' = s + 1 for odd n, s' = s for even n): for even n, q_i is the hodograph's point i + 1.
    return np.roll(q, s + 1 - _offset(n - 1), axis=0), d.copy()


def elevate_intervals(points, intervals, *, degree: int | None = None):
    """Raise the degree by one: a zero interval joins every positive one. Notes §6.13.5, (6.9).

    Returns (points, intervals). A closed curve's intervals d_0, d_1, ...
    become 0, d_0, 0, d_1, ... For degree 1 the new points are the old ones
    and the edge midpoints; for degree 2 the point between P_i and P_j (on P_i's side) is
    ((2 d_i + 3 d_j) P_i + d_i P_j) / (3 d_i + 3 d_j). Each new point is the
    degree n+1 polar value at its label (the mean of n+1 old polar values).
    """
    if degree is None:
        pts, kn, _ = _open(points, intervals)
        new_points, new_knots = bspline.elevate(pts, kn)
        return new_points, intervals_from_knots(new_knots)
    pts, d, n = _closed(points, intervals, degree)
    new_d = np.concatenate([[0.0, value] if value > 0 else [value] for value in d])
    # Periodic knots of the refined sequence: each positive interval starts at a doubled knot.
    new_c, new_s = len(new_d), _offset(n + 1)
    labels = _periodic_knots(new_d, np.arange(new_c)[:, None] + new_s + np.arange(n + 1))
    window_points, window_knots = _window(pts, d, n, _offset(n) - n - 2, len(pts) + 2 * n + 4)
    return bspline.elevated_polar_values(window_points, window_knots, labels), new_d


# --- basis functions from knot intervals ------------------------------------------------


def cubic_basis_from_intervals(intervals, t):
    """The cubic basis function over the knots 0, d_0, d_0+d_1, ... by its four pieces. Notes §6.14.1, (6.10)-(6.13).

    intervals: the four knot intervals (d_0, d_1, d_2, d_3) of the support, t
    measured from its start t_1 = 0: a number -> float, k numbers -> (k,).
    Zero outside [t_1, t_5]. The first piece is (t - t_1)^3 / ((t_4-t_1)(t_3-t_1)(t_2-t_1)),
    the last (t_5 - t)^3 / ((t_5-t_2)(t_5-t_3)(t_5-t_4)); the middle two follow from the de Boor triangle.
    """
    d = _as_intervals(intervals)
    if len(d) != 4 or not d.sum() > 0:
        raise ValueError(f"intervals: expected four knot intervals, not all zero, got {d.tolist()}")
    ts, scalar = as_parameter(t)
    t1, t2, t3, t4, t5 = np.concatenate([[0.0], np.cumsum(d)])
    pieces = [
        lambda x: (x - t1) ** 3 / ((t4 - t1) * (t3 - t1) * (t2 - t1)),
        lambda x: (
            (x - t1) ** 2 * (t3 - x) / ((t4 - t1) * (t3 - t1) * (t3 - t2))
            + (x - t1) * (t4 - x) * (x - t2) / ((t4 - t1) * (t4 - t2) * (t3 - t2))
            + (t5 - x) * (x - t2) ** 2 / ((t5 - t2) * (t4 - t2) * (t3 - t2))
        ),
        lambda x: (
            (x - t1) * (t4 - x) ** 2 / ((t4 - t1) * (t4 - t2) * (t4 - t3))
            + (t5 - x) * (t4 - x) * (x - t2) / ((t5 - t2) * (t4 - t2) * (t4 - t3))
            + (t5 - x) ** 2 * (x - t3) / ((t5 - t2) * (t5 - t3) * (t4 - t3))
        ),
        lambda x: (t5 - x) ** 3 / ((t5 - t2) * (t5 - t3) * (t5 - t4)),
    ]
    breaks = np.array([t1, t2, t3, t4, t5])
    # Each t is handled by the piece of the span containing it (right-continuous, t_5 itself gives 0);
    # only spans of positive length are used, so no piece divides by zero.
    piece = np.searchsorted(breaks, ts, side="right") - 1
    values = np.zeros_like(ts)
    for k, formula in enumerate(pieces):
        here = (piece == k) & (breaks[k + 1] > breaks[k])
        values[here] = formula(ts[here])
    return float(values[0]) if scalar else values


def refine_basis(local_knots, knot: float):
    """Split one basis function N[s_0..s_(n+1)] at an inserted knot k into two: Notes §6.14.2.

    N[s_0, ..., s_(n+1)] = a N[s_0, ..., k, ..., s_n] + b N[s_1, ..., k, ..., s_(n+1)]
    with a = (k - s_0)/(s_n - s_0) if k < s_n else 1 and
    b = (s_(n+1) - k)/(s_(n+1) - s_1) if k > s_1 else 1.
    local_knots: the n+2 knots of the basis function's support, k in [s_0, s_(n+1)].
    Returns ((a, left knots (n+2,)), (b, right knots (n+2,))).
    """
    s = as_float_array(local_knots, "local_knots")
    if s.ndim != 1 or len(s) < 3 or np.any(np.diff(s) < 0) or not s[0] < s[-1]:
        raise ValueError(f"local_knots: expected n+2 >= 3 non-decreasing knots with s_0 < s_(n+1), got {s.tolist()}")
    k = as_scalar(knot, "knot")
    if not s[0] <= k <= s[-1]:
        raise ValueError(f"knot: expected a value in the support [{s[0]}, {s[-1]}], got {k}")
    refined = np.sort(np.concatenate([s, [k]]))
    a = (k - s[0]) / (s[-2] - s[0]) if k < s[-2] else 1.0
    b = (s[-1] - k) / (s[-1] - s[1]) if k > s[1] else 1.0
    return (a, refined[:-1]), (b, refined[1:])
