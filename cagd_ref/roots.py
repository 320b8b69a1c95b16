"""Real roots of polynomials in Bernstein form, and what builds them: notes chapter 9.

A polynomial y(t) = Σ y_i B_i^n(t) on [t0, t1] is the explicit Bézier curve with
control points (t0 + i/n (t1 - t0), y_i) (notes §2.15). Its graph lies in the
convex hull of those points, so no root lies where the hull misses the t axis,
and the number of sign changes of the y_i bounds the number of roots (Descartes'
rule of signs in the Bernstein basis). Three root finders build on that:

- `hull_march` (§9.1): the notes' convex hull marching, one root at a time from
  the left, with deflation (9.1) after each root (`hull_march_plain` is the
  same algorithm as one plain loop, the form the chapter shows);
- `bcom_roots` (§9.2, reconstructed): isolation between the roots of the
  derivative, found recursively the same way;
- `bernstein_roots`: the course's default, subdivision with the hull and the
  rule of signs to isolate every root, then bracketed Newton steps, all intervals
  at once (`bernstein_roots_plain` is the same algorithm one interval at a time).

Coefficients, positions and tolerances are in the local parameter of [0, 1]
inside the kernels; the public functions map to `interval` at the end.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache
from math import comb

import numpy as np

from ._validation import as_count, as_float_array, as_interval, as_points, as_scalar, as_vector
from .bezier import evaluate, subdivide, to_homogeneous
from .polynomials import bernstein_horner, bernstein_multiply

__all__ = [
    "hull_crossing",
    "polygon_crossing",
    "sign_variations",
    "deflate",
    "hull_march",
    "hull_march_plain",
    "hull_march_steps",
    "bcom_roots",
    "bcom_steps",
    "bernstein_roots",
    "bernstein_roots_plain",
    "bernstein_from_roots",
    "line_curve_intersection",
    "wilkinson_polynomial",
]

EPS = np.finfo(float).eps
# A value counts as zero "to rounding" when it is this small against the largest coefficient:
# far above what a few de Casteljau steps can get wrong, far below any value a caller means.
ZERO_TOL = 1e-12
# Half-width of the rounding band around y = 0, relative to the largest coefficient: subdivision
# and evaluation of a polynomial err by a few units of that size, so a piece whose whole polygon
# lies inside the band is zero to rounding (a double root, a tangency) and a value inside it has
# no trustworthy sign. Measured: 4 finds 300 of 300 random double roots once, 1 misses a few.
NOISE = 4 * EPS
# Steps of the march towards one root before it is declared stuck. A multiple root crawls (the
# error after k steps falls like 1/k); a simple root converges linearly, at a rate as poor as
# 0.97 per step when a far coefficient dwarfs the slope at the root (then about 900 steps).
MARCH_STEPS = 10_000  # (hull_march_plain repeats this default, as a literal the chapter shows)
# Interval pieces the subdivision may create in all: far beyond what any polynomial of degree
# <= 1000 needs, so reaching it means the input is not what the caller thinks (e.g. a huge range).
MAX_PIECES = 200_000
NEWTON_STEPS = 100  # (newton_in_bracket repeats this default)


# ---------------------------------------------------------------- shared pieces


def hull_crossing(coeffs) -> tuple[float, float] | None:
    """Sub-interval (lo, hi) of [0, 1] where the hull of the points (i/n, y_i) meets y = 0, or None. Notes §9.1.

    coeffs: (n+1,). Every crossing of a hull edge is a crossing of some segment
    between two control points of opposite sign (or a control point on the axis),
    so the extreme such crossings bound the hull's intersection with the axis.

    >>> [round(t, 6) for t in hull_crossing([1.0, 1.0, -3.0, -2.0, 4.0])]   # the left end: the edge E0 E2
    [0.125, 0.833333]
    >>> print(hull_crossing([1.0, 0.5, 2.0]))
    None
    """
    return _hull_crossing(as_vector(coeffs, "coeffs"))


def _hull_crossing(y: np.ndarray) -> tuple[float, float] | None:
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


def polygon_crossing(coeffs) -> float | None:
    """Leftmost point in [0, 1] where the control polygon of the points (i/n, y_i) meets y = 0, or None. Notes §9.1.

    coeffs: (n+1,). Only neighbouring control points are joined, so this is
    NOT a bound on the roots: the graph may cross the axis before its polygon
    does. The chapter uses it to show why convex hull marching steps to the
    hull's crossing (`hull_crossing`) instead.

    >>> polygon_crossing([1.0, -1.0, 2.0, -3.0])       # the leg from (0, 1) to (1/3, -1)
    0.16666666666666666
    >>> print(polygon_crossing([1.0, 0.5, 2.0]))
    None
    """
    y = as_vector(coeffs, "coeffs")
    n = len(y) - 1
    if n == 0:
        return 0.0 if y[0] == 0 else None
    for i in range(n + 1):
        if y[i] == 0:
            return i / n
        if i < n and y[i] * y[i + 1] < 0:  # this leg crosses: where the line through its ends is zero
            return float(i + y[i] / (y[i] - y[i + 1])) / n
    return None


def sign_variations(coeffs) -> int:
    """Number of sign changes in the coefficients, zeros skipped: a bound on the roots in (t0, t1). Notes ch. 9.

    Descartes' rule of signs holds in the Bernstein basis: the number of roots
    in the open interval is at most the count and has its parity, so a count of
    0 or 1 tells exactly how many roots there are.

    >>> sign_variations([1.0, 1.0, -3.0, -2.0, 4.0])   # two roots
    2
    >>> sign_variations([2.0, 0.0, 1.0])
    0
    """
    return _variations(as_vector(coeffs, "coeffs"))


def _variations(c: np.ndarray) -> int:
    signs = np.sign(c[c != 0])
    return int(np.count_nonzero(signs[1:] != signs[:-1]))


def _split(c: np.ndarray, t: float) -> tuple[np.ndarray, np.ndarray]:
    """De Casteljau subdivision of scalar coefficients (n+1,) at t: the inner loop, without re-validation."""
    n = len(c) - 1
    left, right = np.empty(n + 1), np.empty(n + 1)
    level = c
    for j in range(n + 1):
        left[j], right[n - j] = level[0], level[-1]
        level = level[:-1] + t * (level[1:] - level[:-1])
    return left, right


def _restrict(c: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """Coefficients of the same polynomial on [lo, hi] ⊂ [0, 1] (local parameter), by two subdivisions."""
    right = _split(c, lo)[1] if lo > 0 else c
    return _split(right, (hi - lo) / (1 - lo))[0] if hi < 1 else right


def _value(c: np.ndarray, t: float) -> float:
    return float(_split(c, t)[0][-1])


def zero_to_rounding(value: float, coeffs: np.ndarray) -> bool:
    """Whether `value` is zero to rounding against the coefficients (n+1,): |value| <= 1e-12 max |y_i| (ZERO_TOL)."""
    return bool(abs(value) <= ZERO_TOL * np.abs(coeffs).max())


def rounding_band(sizes: np.ndarray) -> float:
    """Half-width of the band around y = 0 inside which a coefficient has no trustworthy sign.

    sizes: the coefficients of Σ |y_i| B_i^n on the piece at hand (the scale of
    the rounding errors of subdividing and evaluating f there). The band is a
    few units of rounding of their largest value (NOISE = 4 eps): a piece whose
    whole polygon lies inside it is zero to rounding.
    """
    return float(NOISE * np.max(sizes))


def _deflate(c: np.ndarray) -> np.ndarray:
    """g with f(s) = s g(s) when c_0 = 0 (c_0 itself is dropped): g_i = n c_(i+1) / (i+1), (9.1)."""
    n = len(c) - 1
    return n * c[1:] / np.arange(1, n + 1)


def _deflate_right(c: np.ndarray) -> np.ndarray:
    """g with f(s) = (1 - s) g(s) when c_n = 0: the mirror image of (9.1), g_i = n c_i / (n - i)."""
    n = len(c) - 1
    return n * c[:-1] / np.arange(n, 0, -1)


def checked_coefficients(coeffs, interval, tol) -> tuple[np.ndarray, tuple[float, float], float]:
    """The validated inputs every root finder shares: coefficients (n+1,), (t0, t1), tol in (0, 1)."""
    y = as_vector(coeffs, "coeffs")
    t0, t1 = as_interval(interval)
    tol = as_scalar(tol, "tol")
    if not 0 < tol < 1:
        raise ValueError(f"tol: expected a number in (0, 1), got {tol}")
    if not np.any(y):
        raise ValueError("coeffs: the zero polynomial vanishes everywhere; its roots are not isolated")
    return y, (t0, t1), tol


def _to_interval(local, interval: tuple[float, float]) -> np.ndarray:
    t0, t1 = interval
    return t0 + (t1 - t0) * np.asarray(local, dtype=float)


def _merge(lo: np.ndarray, hi: np.ndarray, tol: float) -> np.ndarray:
    """One root per cluster of regions [lo_k, hi_k] (in [0, 1]) that overlap or lie within tol of each other.

    The root is the cluster's midpoint, or the end 0 or 1 of the interval when
    the cluster reaches it: f is zero to rounding there, and the end is exact.
    """
    if lo.size == 0:
        return np.empty(0)
    order = np.argsort(lo, kind="stable")
    lo, hi = lo[order], hi[order]
    reach = np.maximum.accumulate(hi)
    first = np.flatnonzero(np.concatenate([[True], lo[1:] > reach[:-1] + tol]))
    start, end = lo[first], np.maximum.reduceat(hi, first)
    return np.where(start <= 0, 0.0, np.where(end >= 1, 1.0, (start + end) / 2))


# ---------------------------------------------------------------- §9.1 convex hull marching


def deflate(coeffs) -> np.ndarray:
    """Divide out a root at the start: g (n,) with f(t) = t·g(t) for f = Σ y_i B_i^n on [0, 1]. Notes §9.1 (9.1).

    coeffs: (n+1,), n >= 1, with y_0 = f(0) zero to rounding (|y_0| <= 1e-12
    max|y_i|), else a ValueError. Since t B_(i+1)^n = ((i+1)/n) B_i^(n-1) t ...,
    the coefficients of g are g_i = n y_(i+1) / (i+1); on any interval [t0, t1]
    the same formula removes the factor (t - t0)/(t1 - t0).

    >>> deflate([0.0, 1.0, -1.0, 2.0]).tolist()
    [3.0, -1.5, 2.0]
    """
    y = as_vector(coeffs, "coeffs")
    if len(y) < 2:
        raise ValueError(f"coeffs: a constant has no factor t to divide out, got {y.tolist()}")
    if not zero_to_rounding(y[0], y):
        raise ValueError(f"coeffs: f(0) = y_0 = {y[0]:g} is not zero (to rounding), so t does not divide f")
    n = len(y) - 1
    return n * y[1:] / np.arange(1, n + 1)  # (9.1): g_i = n y_(i+1) / (i + 1), i = 0 .. n-1


@dataclass(frozen=True)
class MarchStep:
    """One step of convex hull marching (notes §9.1, Figure 9.1), in the parameter of the caller's interval.

    start: t_k, where the current polynomial begins; coeffs: its Bernstein
    coefficients on [t_k, t1] (after any deflations); crossing: t_(k+1), the
    hull's leftmost crossing of the axis (None when the hull misses it);
    root: the root declared at this step, or None; event: "step" (move on to the
    crossing), "root" (a root, deflated next), "end" (no more roots) or "stalled"
    (no convergence within the step limit: a multiple root or a tight cluster).
    """

    start: float
    coeffs: np.ndarray
    crossing: float | None
    root: float | None
    event: str


def _march(y: np.ndarray, tol: float, max_steps: int = MARCH_STEPS,
           rule: str = "hull") -> tuple[list[float], list[tuple], bool]:
    """Convex hull marching on [0, 1]: (roots, steps as (start, coeffs, crossing, root, event), finished).

    rule "polygon" steps to the control polygon's first crossing instead (the wrong rule, for comparison).
    """
    steps: list[tuple] = []
    at_end = 0
    while len(y) > 1 and zero_to_rounding(y[-1], y):  # roots at t = 1 first: the march never reaches them
        y, at_end = _deflate_right(y), at_end + 1
    roots: list[float] = []
    a, since_root = 0.0, 0
    while len(y) > 1:
        if zero_to_rounding(y[0], y):  # a root where this piece starts (at t0, or a repeated one)
            steps.append((a, y, None, a, "root"))
            roots.append(a)
            y, since_root = _deflate(y), 0
            continue
        if since_root >= max_steps:
            steps.append((a, y, None, None, "stalled"))
            return roots, steps, False
        if rule == "polygon":
            c = polygon_crossing(y)
            if c is None:
                break
        else:
            crossing = _hull_crossing(y)
            if crossing is None:
                break
            c = crossing[0]
        t = a + (1 - a) * c
        right = _split(y, c)[1]
        # A step shorter than tol is the notes' t_(k+1) = t_k. A value at rounding level is a root. A sign
        # change means rounding stepped over the root, which therefore lies within rounding of t (the hull
        # guarantees none in [a, t)): the root is t, not a as the notes have it.
        if t - a <= tol or zero_to_rounding(right[0], right) or np.sign(right[0]) != np.sign(y[0]):
            steps.append((a, y, t, t, "root"))
            roots.append(t)
            y, since_root = _deflate(right), 0
        else:
            steps.append((a, y, t, None, "step"))
            y, since_root = right, since_root + 1
        a = t
    steps.append((a, y, None, None, "end"))
    return roots + [1.0] * at_end, steps, True


def hull_march(coeffs, interval=(0, 1), tol: float = 1e-12) -> np.ndarray:
    """Real roots in `interval` by convex hull marching with deflation, ascending, one per deflation. Notes §9.1.

    coeffs: Bernstein coefficients (n+1,) on `interval`. Starting at t0, each
    step moves to t_(k+1), the leftmost point where the hull of the explicit
    curve f_[t_k, t1] meets the t axis: no root lies before it, so the march
    never passes one. A root is declared when a step is shorter than tol
    (relative to the interval), when f(t_(k+1)) is zero to rounding, or when the
    sign of f flips (then the root is t_(k+1)); it is divided out by (9.1) and
    the march goes on. Roots at t1 are divided out first. A multiple root in the
    interior makes the march crawl; after 10 000 steps towards one root it
    stops with a RuntimeError (use `bernstein_roots` or `bcom_roots` there).
    The zero polynomial is rejected.

    Ref: T. W. Sederberg and S. R. Parry, Comparison of three curve intersection algorithms,
    CAD 18(1), 1986 (the notes' [SP86a]).

    >>> [round(float(t), 10) for t in hull_march([1.0, 1.0, -3.0, -2.0, 4.0])]
    [0.2547033564, 0.7660291666]
    """
    y, interval, tol = checked_coefficients(coeffs, interval, tol)
    roots, steps, finished = _march(y, tol)
    if not finished:
        near = _to_interval(steps[-1][0], interval)
        raise RuntimeError(
            f"hull_march: no convergence after {MARCH_STEPS} steps towards a root near t = {near:.6g}: a multiple "
            "root, a tight cluster of roots or a very slow march; bernstein_roots or bcom_roots find those"
        )
    return _to_interval(roots, interval)


def hull_march_plain(coeffs, interval=(0, 1), tol: float = 1e-12, max_steps: int = 10_000) -> np.ndarray:
    """`hull_march` written as one plain loop, the teaching form the chapter shows. Notes §9.1.

    The same algorithm and the same tests for a root as `hull_march` (the tests
    check that the two agree); it records nothing for figures and takes the
    step limit as an argument (the default is `hull_march`'s, MARCH_STEPS).

    >>> [round(float(t), 10) for t in hull_march_plain([1.0, 1.0, -3.0, -2.0, 4.0])]
    [0.2547033564, 0.7660291666]
    """
    y, (a, b), tol = checked_coefficients(coeffs, interval, tol)
    at_right_end = []
    while len(y) > 1 and zero_to_rounding(y[-1], y):  # f(1) = 0: divide out 1 - s, g_i = n y_i / (n - i)
        n = len(y) - 1
        y = n * y[:-1] / np.arange(n, 0, -1)
        at_right_end.append(1.0)
    found = []
    t, steps = 0.0, 0  # y holds f on [t, 1], in its own parameter s in [0, 1]
    while len(y) > 1:
        if zero_to_rounding(y[0], y):  # a root where the piece starts
            found.append(t)
            y, steps = deflate(y), 0
            continue
        if steps == max_steps:
            raise RuntimeError(f"hull_march_plain: no convergence after {max_steps} steps towards a root near "
                               f"t = {a + (b - a) * t:.6g}: a multiple root or a tight cluster")
        crossing = hull_crossing(y)
        if crossing is None:  # the hull misses the axis: no roots are left
            break
        c = crossing[0]  # the hull's leftmost crossing, in the piece's own parameter
        t_next = t + (1 - t) * c
        right = subdivide(y[:, None], c)[1][:, 0]  # de Casteljau: f on [t_next, 1]
        if t_next - t <= tol or zero_to_rounding(right[0], right) or np.sign(right[0]) != np.sign(y[0]):
            found.append(t_next)  # a tiny step, a zero value, or rounding stepped over the root: it is t_next
            y, steps = deflate(np.concatenate([[0.0], right[1:]])), 0
        else:
            y, steps = right, steps + 1
        t = t_next
    return a + (b - a) * np.array(found + at_right_end)


def hull_march_steps(coeffs, interval=(0, 1), tol: float = 1e-12, max_steps: int = MARCH_STEPS,
                     rule: str = "hull") -> list[MarchStep]:
    """Every step of `hull_march` on the same input, for Figure 9.1 and the explorer. Notes §9.1.

    A list of `MarchStep`; the last one has event "end" (done) or "stalled"
    (`max_steps` steps towards one root: where `hull_march` raises, this reports).
    rule: "hull" (the algorithm) or "polygon", which steps to the control
    polygon's first crossing instead: the rule that can step over a root,
    kept to show how it fails.
    """
    y, interval, tol = checked_coefficients(coeffs, interval, tol)
    if rule not in ("hull", "polygon"):
        raise ValueError(f"rule: expected 'hull' or 'polygon', got {rule!r}")
    _, steps, _ = _march(y, tol, as_count(max_steps, "max_steps", minimum=1), rule)

    def mapped(t):
        return None if t is None else float(_to_interval(t, interval))

    return [MarchStep(mapped(a), c.copy(), mapped(t), mapped(r), event) for a, c, t, r, event in steps]


# ---------------------------------------------------------------- §9.2 combined subdivide & derivative


@dataclass(frozen=True)
class BcomStep:
    """One look at a polynomial in the §9.2 method, in the parameter of the caller's interval.

    order: which derivative of f (0 for f itself); interval: (a, b), the piece
    looked at; coeffs: that derivative's Bernstein coefficients on the piece
    (up to a positive factor); variations: their sign changes; action: what the
    method concluded ("no root", "one root", "split at the roots of the
    derivative", "monotone piece"); roots: the roots it found on the piece.
    """

    order: int
    interval: tuple[float, float]
    coeffs: np.ndarray
    variations: int
    action: str
    roots: tuple[float, ...]


def _bcom(c: np.ndarray, order: int, tol: float, steps: list) -> list[float]:
    """Distinct roots in [0, 1] of the `order`-th derivative, with coefficients c on [0, 1]; looks appended to steps."""
    noise = NOISE * np.abs(c).max()
    v = _variations(c)
    if len(c) == 1 or np.all(c > noise) or np.all(c < -noise):
        steps.append((order, (0.0, 1.0), c, v, "no root", ()))
        return []
    if abs(c[0]) > noise and abs(c[-1]) > noise and v <= 1 and (v == 1) == (np.sign(c[0]) != np.sign(c[-1])):
        found = [_monotone_root(c, tol)] if v else []
        steps.append((order, (0.0, 1.0), c, v, "one root" if v else "no root", tuple(found)))
        return found
    steps.append((order, (0.0, 1.0), c, v, "split at the roots of the derivative", ()))
    critical = _bcom((len(c) - 1) * np.diff(c), order + 1, tol, steps)
    cuts = [0.0] + [t for t in critical if 0 < t < 1] + [1.0]
    found = []
    for lo, hi in zip(cuts[:-1], cuts[1:]):
        # f is monotone between consecutive critical points: at most one root, where the end values differ in
        # sign, or at an end where f is zero to rounding (at a critical point: a multiple root).
        piece, scale = _restrict(c, lo, hi), _restrict(np.abs(c), lo, hi)
        here = [t for t, value, size in ((lo, piece[0], scale[0]), (hi, piece[-1], scale[-1]))
                if abs(value) <= NOISE * size]
        if not here and np.sign(piece[0]) != np.sign(piece[-1]):
            here = [lo + (hi - lo) * _monotone_root(piece, tol / (hi - lo))]
        steps.append((order, (lo, hi), piece, _variations(piece), "monotone piece", tuple(here)))
        found += here
    return sorted(set(found))


def _monotone_root(c: np.ndarray, tol: float) -> float:
    """The single root in (0, 1) of a piece whose end values differ in sign, by the bracketed Newton steps."""
    return float(_newton(c, np.zeros(1), np.ones(1), c[:1], c[-1:], tol)[0])


def _bcom_run(coeffs, interval, tol) -> tuple[np.ndarray, list[tuple], tuple[float, float]]:
    y, interval, tol = checked_coefficients(coeffs, interval, tol)
    steps: list[tuple] = []
    found = _bcom(y, 0, tol, steps)
    return _merge(np.array(found), np.array(found), tol), steps, interval


def bcom_roots(coeffs, interval=(0, 1), tol: float = 1e-12) -> np.ndarray:
    """Distinct real roots in `interval` by combining subdivision and derivatives (reconstruction). Notes §9.2.

    The notes' text of §9.2 is lost; this follows its title, the labels of its
    Figure 9.2 and the isolation scheme of the root finders it cites. When the
    coefficients change sign at most once (Descartes' rule) the root count is
    known. Otherwise [0, 1] is subdivided at the roots of the derivative, found
    recursively the same way: between them f is monotone, so each piece holds
    at most one root, where its end values differ in sign; single roots are
    refined by the bracketed Newton steps of `bernstein_roots`. A derivative
    root where f is zero to rounding is a multiple root of f, found as
    accurately as that (simple) root of f'.

    Ref: M. R. Spencer, PhD thesis on real roots of Bernstein polynomials, BYU, 1994 (the notes' [Spe94]).

    >>> [round(float(t), 10) for t in bcom_roots([1.0, 1.0, -3.0, -2.0, 4.0])]
    [0.2547033564, 0.7660291666]
    """
    roots, _, interval = _bcom_run(coeffs, interval, tol)
    return _to_interval(roots, interval)


def bcom_steps(coeffs, interval=(0, 1), tol: float = 1e-12) -> list[BcomStep]:
    """Every look of `bcom_roots` at f and its derivatives, in the order taken, for Figure 9.2. Notes §9.2."""
    _, steps, interval = _bcom_run(coeffs, interval, tol)

    def mapped(values):
        return tuple(float(t) for t in _to_interval(list(values), interval))

    return [BcomStep(order, mapped(piece), c.copy(), v, action, mapped(found))
            for order, piece, c, v, action, found in steps]


# ---------------------------------------------------------------- the default: subdivision, then Newton


def bernstein_roots(coeffs, interval=(0, 1), tol: float = 1e-12) -> np.ndarray:
    """Sorted distinct real roots in `interval` of Σ y_i B_i^n, for (n+1,) coefficients on it. Notes §9.1, §9.2.

    Subdivision isolates the roots: a piece whose control polygon keeps off a
    thin band around the axis (rounding level) has none; one whose coefficients
    change sign exactly once has exactly one (Descartes' rule); any other piece
    is halved. The isolated roots are then refined all at once by Newton steps
    kept inside their brackets, until a step is shorter than tol (relative to
    the interval) or the value is below its own rounding error. Roots closer
    together than that come back once: a double root, or a place where the
    polynomial touches zero to rounding, is one root (an end of the interval
    if it is there). The zero polynomial is rejected. All live pieces advance
    together, so a round costs a few NumPy operations; `bernstein_roots_plain`
    is the same algorithm one piece at a time.

    Ref: R. T. Farouki, V. T. Rajan, CAGD 4:191-216, 1987 (the notes' [FR87], on the condition of the Bernstein
    basis).

    >>> coeffs = [1.0, -9 / 2, 41 / 6, -1.0, 0.0]    # (2t-1)² + (8t²-9t+1)² - 1, §7.3
    >>> [round(float(t), 10) for t in bernstein_roots(coeffs)]
    [0.0611803043, 0.2814714866, 0.9073482091, 1.0]
    >>> bernstein_roots([-1.375, 3.25, -4.875, 1.25], interval=(2, 5)).round(12).tolist()
    [2.5, 3.0, 4.75]
    """
    y, interval, tol = checked_coefficients(coeffs, interval, tol)
    lo, hi, brackets = _isolate(y, tol)
    roots = _newton(y, *brackets, tol)
    return _to_interval(_merge(np.concatenate([lo, roots]), np.concatenate([hi, roots]), tol), interval)


@lru_cache(maxsize=64)
def _halving_matrix(n: int, times: int = 1) -> np.ndarray:
    """(n+1, 2^times (n+1)): a row of coefficients times it gives those of its 2^times equal pieces, side by side.

    Built by de Casteljau at 1/2 on the identity, so the product is subdivision itself.
    """
    if times == 1:
        left, right = subdivide(np.eye(n + 1), 0.5)
        matrix = np.hstack([left.T, right.T])
    else:  # row j holds the pieces of the polynomial e_j: halve each piece once more, in order
        matrix = (_halving_matrix(n, times - 1).reshape(-1, n + 1) @ _halving_matrix(n)).reshape(n + 1, -1)
    matrix.flags.writeable = False
    return matrix


def _isolate(y: np.ndarray, tol: float) -> tuple[np.ndarray, np.ndarray, tuple]:
    """Subdivide [0, 1] until every piece is root-free, a root region, or isolates one simple root.

    Returns (lo, hi) of the root regions (pieces zero to rounding, roots at
    piece ends, pieces narrower than tol that may hold a root) and the brackets
    (a, b, f(a), f(b)) of the isolated roots. All pieces of a round are the rows
    of one array, and halving them all is one matrix product. Each piece also
    carries the coefficients of Σ |y_i| B_i^n on it: the scale of the rounding
    errors there, which sets its band.
    """
    n = len(y) - 1
    # The first cut makes about as many pieces as there may be roots (the sign changes): the rounds of
    # halving it skips would only have split pieces too wide to decide anything.
    times = _variations(y).bit_length() if n else 0
    count = 2**times
    start = np.stack([y, np.abs(y)])
    c, m = (start @ _halving_matrix(n, times)).reshape(2, count, n + 1) if times else start[:, None, :]
    a, width = np.arange(count) / count, np.full(count, 1.0 / count)
    regions_lo, regions_hi, brackets = [], [], []
    created = count
    while len(c):
        noise = NOISE * m.max(axis=1, keepdims=True)
        above, below = c > noise, c < -noise
        inside = ~(above | below)
        flat = inside.all(axis=1)
        # One-signed but for ends inside the band: no roots other than those ends (hull-free pieces included).
        settled = ~flat & ((~below.any(axis=1) & above[:, 1:-1].all(axis=1))
                           | (~above.any(axis=1) & below[:, 1:-1].all(axis=1)))
        region = ~settled & (flat | (width <= tol))
        at_start, at_end = settled & inside[:, 0], settled & inside[:, -1]
        regions_lo += [a[at_start], a[at_end] + width[at_end], a[region]]
        regions_hi += [a[at_start], a[at_end] + width[at_end], a[region] + width[region]]
        # End values clear of the band with opposite signs, one sign change between: exactly one simple root.
        signs = np.sign(c)
        monotone = ((signs[:, 1:] - signs[:, :-1]) * signs[:, :1] <= 0).all(axis=1)
        opposite = (above[:, 0] & below[:, -1]) | (below[:, 0] & above[:, -1])
        isolated = ~settled & ~region & opposite & monotone
        brackets.append((a[isolated], a[isolated] + width[isolated], c[isolated, 0], c[isolated, -1]))
        halve = ~(settled | region | isolated)
        count = int(np.count_nonzero(halve))
        created += 2 * count
        if created > MAX_PIECES:
            raise RuntimeError("bernstein_roots: the subdivision does not settle; is the polynomial badly scaled?")
        halves = np.concatenate([c[halve], m[halve]]) @ _halving_matrix(n)
        c, m = halves[:count].reshape(2 * count, n + 1), halves[count:].reshape(2 * count, n + 1)
        half = width[halve] / 2
        a = (a[halve][:, None] + half[:, None] * [0.0, 1.0]).ravel()
        width = np.repeat(half, 2)
    bracket_arrays = tuple(np.concatenate(part) for part in zip(*brackets))
    return np.concatenate(regions_lo), np.concatenate(regions_hi), bracket_arrays


@lru_cache(maxsize=64)
def _basis_tables(n: int) -> tuple[np.ndarray, np.ndarray]:
    return np.array([comb(n, i) for i in range(n + 1)], dtype=float), np.arange(n + 1)


def _evaluation_columns(y: np.ndarray) -> np.ndarray:
    """(n, 4): y_0..y_(n-1), y_1..y_n and their absolute values, the inputs of `_values_and_slopes`."""
    magnitude = np.abs(y)
    return np.stack([y[:-1], y[1:], magnitude[:-1], magnitude[1:]], axis=1)


def _values_and_slopes(columns: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """f(x), f'(x) and Σ |y_i| B_i^n(x) (the scale of f's rounding error) at k points (k,).

    All three come from the last level of de Casteljau's triangle: the two
    degree n-1 polynomials with coefficients y_0..y_(n-1) and y_1..y_n at x.
    """
    n = len(columns)
    binomials, powers = _basis_tables(n - 1)
    basis = binomials * x[:, None] ** powers * (1 - x)[:, None] ** powers[::-1]
    first, second, first_size, second_size = (basis @ columns).T
    return first + x * (second - first), n * (second - first), first_size + x * (second_size - first_size)


def _newton(y: np.ndarray, a: np.ndarray, b: np.ndarray, fa: np.ndarray, fb: np.ndarray, tol: float) -> np.ndarray:
    """The root in each bracket [a_k, b_k] (f(a_k), f(b_k) of opposite signs, one root), all brackets together.

    Newton steps from the secant's root of the bracket; a step that would leave
    the bracket, or that shrinks too slowly (not below half the step before
    last), is replaced by bisection. A root is done when its step is shorter
    than tol, its bracket narrower than tol, or |f| is below the rounding error
    of its own evaluation (eps Σ |y_i| B_i^n(x)): further steps would follow noise.
    Done roots keep their value while the others go on.
    """
    lo, hi = a.copy(), b.copy()
    x = a + (b - a) * fa / (fa - fb)
    rising = fa < 0
    step_before, step = b - a, b - a
    columns = _evaluation_columns(y)
    active = np.ones(len(a), dtype=bool)
    with np.errstate(divide="ignore", invalid="ignore"):
        for _ in range(NEWTON_STEPS):
            f, slope, scale = _values_and_slopes(columns, x)
            below = (f < 0) == rising  # x lies on the side of a
            lo, hi = np.where(below, x, lo), np.where(below, hi, x)
            newton = x - f / slope
            stray = ~((newton > lo) & (newton < hi)) | (np.abs(2 * f) > np.abs(step_before * slope))
            resolved = np.abs(f) <= EPS * scale
            new = np.where(active & ~resolved, np.where(stray, (lo + hi) / 2, newton), x)
            step_before, step = step, np.abs(new - x)
            x = new
            active &= (step > tol) & (hi - lo > tol) & ~resolved
            if not active.any():
                break
    return x


def bernstein_roots_plain(coeffs, interval=(0, 1), tol: float = 1e-12) -> np.ndarray:
    """`bernstein_roots` written one piece at a time: the same subdivision, the same Newton steps. Notes §9.1, §9.2.

    The teaching form the chapter shows: each piece is looked at in turn,
    halved by de Casteljau at 1/2 when nothing can be decided yet, and each
    isolated root is refined on its own (`newton_in_bracket`). The tests check
    that it agrees with `bernstein_roots`.

    >>> [round(float(t), 10) for t in bernstein_roots_plain([1.0, -9 / 2, 41 / 6, -1.0, 0.0])]
    [0.0611803043, 0.2814714866, 0.9073482091, 1.0]
    """
    y, (t0, t1), tol = checked_coefficients(coeffs, interval, tol)
    regions = []  # pieces (lo, hi) of [0, 1] that hold a root, to within tol or to rounding
    pending = [(y, np.abs(y), 0.0, 1.0)]  # f and its rounding scale Σ |y_i| B_i^n, both on the piece [a, b]
    while pending:
        c, m, a, b = pending.pop()
        band = rounding_band(m)
        above, below = c > band, c < -band
        inside = ~above & ~below
        one_signed = (above[1:-1].all() and not below.any()) or (below[1:-1].all() and not above.any())
        signs = np.sign(c)
        if one_signed and not inside.all():  # no root inside; an end inside the band is a root there
            regions += [(end, end) for end, zero in ((a, inside[0]), (b, inside[-1])) if zero]
        elif inside.all() or b - a <= tol:  # zero to rounding all along, or too narrow to tell
            regions.append((a, b))
        elif (not inside[0] and not inside[-1] and signs[0] != signs[-1]
              and np.all(np.diff(signs) * signs[0] <= 0)):  # the signs change once: exactly one root
            root = newton_in_bracket(y, (a, b), (c[0], c[-1]), tol)
            regions.append((root, root))
        else:  # undecided: halve f and its scale together (de Casteljau at 1/2)
            left, right = subdivide(np.column_stack([c, m]), 0.5)
            middle = (a + b) / 2
            pending += [(right[:, 0], right[:, 1], middle, b), (left[:, 0], left[:, 1], a, middle)]
    return t0 + (t1 - t0) * one_root_per_cluster(regions, tol)


def newton_in_bracket(coeffs, bracket, end_values, tol: float, max_steps: int = 100) -> float:
    """The one root of f = Σ y_i B_i^n inside `bracket` = (a, b) ⊂ [0, 1], by Newton steps kept inside it.

    end_values: f(a) and f(b), of opposite signs. The first guess is the
    secant's root. A Newton step that would leave the bracket, or that is not
    shorter than half the step before last, is replaced by bisection. The root
    is done when a step is shorter than tol, the bracket narrower than tol, or
    |f| below the rounding error of its own evaluation, 2η Σ |y_i| B_i^n(x)
    (eps, the spacing of doubles at 1, times the rounding scale: further steps
    would follow rounding noise). `max_steps` is a safeguard
    (NEWTON_STEPS, as in `bernstein_roots`).
    """
    y = np.asarray(coeffs, dtype=float)
    slope_coeffs = (len(y) - 1) * np.diff(y)  # f' (the hodograph)
    (lo, hi), (fa, fb) = bracket, end_values
    x = lo + (hi - lo) * fa / (fa - fb)
    steps = [hi - lo, hi - lo]  # the lengths of the last two steps
    for _ in range(max_steps):
        f, slope = bernstein_horner(y, x), bernstein_horner(slope_coeffs, x)
        if abs(f) <= EPS * bernstein_horner(np.abs(y), x):
            break  # zero to the rounding of its own evaluation
        if (f < 0) == (fa < 0):  # x lies on the side of a: the root is right of it
            lo = x
        else:
            hi = x
        newton = x - f / slope if slope != 0 else np.inf
        if lo < newton < hi and abs(f / slope) <= steps[-2] / 2:
            x_next = newton
        else:  # out of the bracket, or converging too slowly: bisect
            x_next = (lo + hi) / 2
        steps.append(abs(x_next - x))
        x = x_next
        if steps[-1] <= tol or hi - lo <= tol:
            break
    return float(x)


def one_root_per_cluster(regions, tol: float) -> np.ndarray:
    """Sorted roots in [0, 1], one per cluster of regions (lo, hi) that overlap or lie within tol of each other.

    A cluster is a root seen more than once (from two pieces, or a double root
    zero to rounding over a stretch): its middle, or the end 0 or 1 of the
    interval when the cluster reaches it (f is zero to rounding there, and the
    end is exact).
    """
    clusters = []
    for lo, hi in sorted(regions):
        if clusters and lo <= clusters[-1][1] + tol:
            clusters[-1][1] = max(clusters[-1][1], hi)
        else:
            clusters.append([lo, hi])
    return np.array([0.0 if lo <= 0 else 1.0 if hi >= 1 else (lo + hi) / 2 for lo, hi in clusters])


# ---------------------------------------------------------------- §9.3 building polynomials, §9.4 line ∩ curve


def bernstein_from_roots(roots, interval=(0, 1), leading: float = 1.0) -> np.ndarray:
    """Bernstein coefficients on `interval` of leading·Π (t - r_k): a product of linear factors. Notes §9.3.

    roots: (k,) real numbers, inside the interval or not; returns (k+1,). On
    [t0, t1] the factor t - r is the linear polynomial <t0 - r, t1 - r>, and the
    product formula of §9.3 multiplies the factors one by one (with no roots
    the result is the constant `leading`). Built this way, a polynomial with
    prescribed roots is far more accurate than through the power basis.

    >>> bernstein_from_roots([2.5, 3.0, 4.75], interval=(2, 5)).tolist()
    [-1.375, 3.25, -4.875, 1.25]
    """
    r = as_float_array(roots, "roots")
    if r.ndim != 1:
        raise ValueError(f"roots: expected a 1-D array of numbers, got shape {r.shape}")
    t0, t1 = as_interval(interval)
    product = np.array([as_scalar(leading, "leading")])
    for root in r:
        product = bernstein_multiply(product, np.array([t0 - root, t1 - root]))
    return product


def line_curve_intersection(points, line, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """Parameters (k,) and points (k, 2) where a planar (rational) Bézier curve meets a line, by t. Notes §9.4.

    points: (n+1, 2); line: (a, b, c) of a x + b y + c w = 0, (a, b) not both 0;
    weights: None or (n+1,) nonzero. Substituting the curve into the line gives
    f(t) = Σ f_i B_i^n(t) with f_i = w_i (a x_i + b y_i + c), the line dotted
    with the homogeneous control point; its roots in [0, 1] (`bernstein_roots`)
    are the intersections. A curve lying on the line is rejected (ValueError).

    >>> points = [(0.0, 10.0), (0.0, 12.0), (5.0, 10.0), (8.0, 7.0), (11.0, 1.0)]
    >>> ts, pts = line_curve_intersection(points, (6.0, -8.0, 40.0), weights=[1.0, 1.0, 2.0, 3.0, 3.0])
    >>> ts.round(10).tolist(), pts.round(6).tolist()
    ([0.4369511019], [[5.157147, 8.86786]])
    """
    pts = as_points(points)
    if pts.shape[1] != 2:
        raise ValueError(f"points: expected planar control points of shape (n+1, 2), got shape {pts.shape}")
    homogeneous_line = as_vector(line, "line", dim=3)
    if not np.any(homogeneous_line[:2]):
        raise ValueError(f"line: (a, b) must not both be zero, got {homogeneous_line.tolist()}")
    h = to_homogeneous(pts, np.ones(len(pts)) if weights is None else weights)
    f = h @ homogeneous_line
    if not np.any(f):
        raise ValueError("line: the curve lies on the line, so every parameter is an intersection")
    ts = bernstein_roots(f)
    return ts, evaluate(pts, ts, weights)


def wilkinson_polynomial(degree: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(Bernstein coefficients on [0, 1], ascending power coefficients, roots) of Π_(k=1..n) (t - k/(n+1)). Notes ch. 9.

    Wilkinson's classic ill-conditioned example squeezed into (0, 1), the kind
    of test behind the conditioning claim of [FR87]. Both coefficient lists are
    computed exactly (fractions) and rounded once, so each basis starts from its
    own correctly rounded coefficients and root errors measure the conditioning.

    >>> [values.round(6).tolist() for values in wilkinson_polynomial(2)]   # (t - 1/3)(t - 2/3) = 2/9 - t + t²
    [[0.222222, -0.277778, 0.222222], [0.222222, -1.0, 1.0], [0.333333, 0.666667]]
    """
    n = as_count(degree, "degree", minimum=1)
    exact_roots = [Fraction(k, n + 1) for k in range(1, n + 1)]
    power = [Fraction(1)]
    for r in exact_roots:  # times (t - r)
        power = [(power[j - 1] if j else 0) - r * (power[j] if j < len(power) else 0) for j in range(len(power) + 1)]
    # b_i = Σ_(j<=i) C(i, j) / C(n, j) a_j turns ascending power coefficients into Bernstein ones.
    bernstein = [sum(Fraction(comb(i, j), comb(n, j)) * power[j] for j in range(i + 1)) for i in range(n + 1)]
    return tuple(np.array([float(v) for v in values]) for values in (bernstein, power, exact_roots))
