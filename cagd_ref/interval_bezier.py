"""Interval arithmetic and interval Bézier curves: approximations that carry their error. Chapter 12 of the notes.

When one CAD system hands a curve to another that only accepts polynomials of
a low degree, the curve must be approximated; an interval Bézier curve passes
the approximation on together with a guaranteed bound on its error. Its
control points are boxes, and every Bézier curve whose control points lie in
the boxes lies in the region the interval curve sweeps.

`Interval` is a closed real interval [lo, hi] with Moore's arithmetic (the
rules of §12.1): a frozen value, combined with other intervals or with plain
numbers on either side. Its operations round each end point once, so
``(x op y).outward()`` widens the floating-point result by one unit in the last
place at each end and then holds the exact result of the operation on the end
points; `round_outward` does the same for arrays (chapter 13 builds on it).

Vector intervals are axis-aligned boxes. A curve's interval control points are
a float array ``boxes`` of shape (n+1, d, 2): ``boxes[k, j] = (lo, hi)`` of
coordinate j of control point k. A scalar interval polynomial has coefficients
(n+1, 2). In centred form a box is a centre c plus an error e >= 0 times
[-1, 1] (`center_error`, `boxes_from_center`); the affine map (1-t)[P0] + t[P1]
then has centre (1-t)c0 + t c1 and error |1-t| e0 + |t| e1 for every real t
(12.25), and the de Casteljau algorithm on boxes gives, at any t,

    [P](t) = Σ c_k B_k^n(t) + (Σ e_k |B_k^n(t)|) [-1, 1]        (12.27)-(12.29),

the exact set of points of all the curves with control points in the boxes.

The second half builds enclosures: an interpolant plus its Cauchy remainder
with bounds on the derivative (Lagrange, §12.3, and symmetric Hermite, where
only the middle coefficient becomes an interval), bounds on the derivatives of
a Bernstein polynomial from its forward differences (12.69), and with them the
degree reduction of a Bézier curve to quartic interval pieces with a
guaranteed bound (§12.3-12.4).
"""

from __future__ import annotations

import math
import numbers
import operator
from dataclasses import dataclass

import numpy as np

from ._validation import as_coefficients, as_count, as_float_array, as_interval, as_parameter, as_scalar
from .bezier import de_casteljau, elevate, hodograph, subdivide
from .forward_differencing import forward_difference_table
from .interpolation import bernstein_interpolation
from .roots import bernstein_from_roots, bernstein_roots

__all__ = [
    "Interval",
    "round_outward",
    "interval_expression",
    "boxes_from_center",
    "center_error",
    "interval_affine",
    "interval_de_casteljau",
    "interval_de_casteljau_plain",
    "interval_de_casteljau_triangle",
    "error_curve",
    "interval_subdivide",
    "interval_elevate",
    "interval_polynomial_width",
    "corner_curves",
    "envelope_pieces",
    "lagrange_interval",
    "hermite_bezier",
    "hermite_interval",
    "derivative_bounds",
    "interval_degree_reduce",
]

# The corners of a planar box, named as the notes name them: (x side, y side), 0 = lo and 1 = hi.
CORNERS = {"TL": (0, 1), "TR": (1, 1), "BL": (0, 0), "BR": (1, 0)}


# ---------------------------------------------------------------- §12.1 interval arithmetic


@dataclass(frozen=True)
class Interval:
    """The closed interval [lo, hi] of real numbers, with Moore's interval arithmetic. Notes §12.1, (12.1)-(12.5).

    lo, hi: finite numbers with lo <= hi; ``Interval(a)`` is the degenerate
    interval [a, a] (12.4). ``+ - * /`` combine intervals with intervals or
    with numbers on either side, each result the smallest interval holding
    every x op y with x and y in the operands:

        [a, b] + [c, d] = [a + c, b + d]        [a, b] - [c, d] = [a - d, b - c]
        [a, b] · [c, d] = [min(ac, ad, bc, bd), max(ac, ad, bc, bd)]
        [a, b] / [c, d] = [min(a/c, a/d, b/c, b/d), max(...)]   (0 not in [c, d])

    Dividing by an interval that holds 0 raises a ValueError. ``width`` (hi - lo),
    ``mid`` and ``radius`` are properties. Every end point of a result is one
    rounded floating-point operation, so ``(x op y).outward()`` is guaranteed
    to hold the exact result of the operation on the end points.

    >>> from cagd_ref.interval_bezier import Interval
    >>> u = Interval(1, 2)
    >>> u - u                                  # not 0: the two u's vary independently
    Interval(lo=-1.0, hi=1.0)
    >>> u * Interval(-1, 3), u / Interval(1, 4), 2 - u, (u - u).width
    (Interval(lo=-2.0, hi=6.0), Interval(lo=0.25, hi=2.0), Interval(lo=0.0, hi=1.0), 2.0)
    >>> v, w = Interval(-1, 0), Interval(1)    # subdistributivity: u(v + w) is inside uv + uw
    >>> u * (v + w), u * v + u * w
    (Interval(lo=0.0, hi=2.0), Interval(lo=-1.0, hi=2.0))
    """

    lo: float
    hi: float | None = None

    # NumPy numbers on the left then defer to the reflected operations below instead of broadcasting.
    __array_ufunc__ = None

    def __post_init__(self):
        lo = as_scalar(self.lo, "lo")
        hi = lo if self.hi is None else as_scalar(self.hi, "hi")
        if lo > hi:
            raise ValueError(f"lo: expected lo <= hi, got [{lo!r}, {hi!r}]")
        object.__setattr__(self, "lo", lo)
        object.__setattr__(self, "hi", hi)

    @classmethod
    def from_center(cls, center: float, error: float) -> Interval:
        """The interval center + error·[-1, 1], error >= 0 (the centred form (12.21))."""
        error = as_scalar(error, "error")
        if error < 0:
            raise ValueError(f"error: expected a non-negative half-width, got {error!r}")
        center = as_scalar(center, "center")
        return cls(center - error, center + error)

    @property
    def width(self) -> float:
        """hi - lo."""
        return self.hi - self.lo

    @property
    def mid(self) -> float:
        """The centre (lo + hi) / 2."""
        return 0.5 * (self.lo + self.hi)

    @property
    def radius(self) -> float:
        """The half-width (hi - lo) / 2: the error of the centred form."""
        return 0.5 * (self.hi - self.lo)

    def contains(self, x) -> bool:
        """True when the number x, or every number of the interval x, lies in this interval."""
        other = _as_interval(x)
        if other is NotImplemented:
            raise TypeError(f"x: expected a number or an Interval, got {type(x).__name__}")
        return self.lo <= other.lo and other.hi <= self.hi

    __contains__ = contains

    def outward(self) -> Interval:
        """The interval widened by one unit in the last place at each end (numpy.nextafter): outward rounding."""
        return Interval(float(np.nextafter(self.lo, -np.inf)), float(np.nextafter(self.hi, np.inf)))

    def __str__(self) -> str:
        return f"[{self.lo:g}, {self.hi:g}]"

    def __neg__(self) -> Interval:
        return Interval(-self.hi, -self.lo)

    def __pos__(self) -> Interval:
        return self

    def __add__(self, other):
        other = _as_interval(other)
        if other is NotImplemented:
            return other
        return Interval(self.lo + other.lo, self.hi + other.hi)

    __radd__ = __add__

    def __sub__(self, other):
        other = _as_interval(other)
        if other is NotImplemented:
            return other
        return Interval(self.lo - other.hi, self.hi - other.lo)

    def __rsub__(self, other):
        other = _as_interval(other)
        return other if other is NotImplemented else other - self

    def __mul__(self, other):
        other = _as_interval(other)
        if other is NotImplemented:
            return other
        return _hull_of(operator.mul, self, other)

    __rmul__ = __mul__

    def __truediv__(self, other):
        other = _as_interval(other)
        if other is NotImplemented:
            return other
        if other.lo <= 0 <= other.hi:
            raise ValueError(f"divisor: the interval {other} contains 0, so the quotient is unbounded")
        # The quotients themselves, not a · (1/d): each end point is then one rounded operation.
        return _hull_of(operator.truediv, self, other)

    def __rtruediv__(self, other):
        other = _as_interval(other)
        return other if other is NotImplemented else other / self


def _as_interval(x):
    if isinstance(x, Interval):
        return x
    if isinstance(x, numbers.Real):
        return Interval(x)
    return NotImplemented


def _hull_of(op, x: Interval, y: Interval) -> Interval:
    values = [op(a, b) for a in (x.lo, x.hi) for b in (y.lo, y.hi)]
    return Interval(min(values), max(values))


def round_outward(lo, hi) -> tuple[np.ndarray, np.ndarray]:
    """Lower ends one unit in the last place down, upper ends one up (numpy.nextafter): (lo', hi'). Notes §12.1.

    lo, hi: numbers or arrays of one shape, lo <= hi. A floating-point result
    that is one rounded operation away from the exact value lies within one
    unit in the last place of it, so the widened interval holds the exact value.

    >>> from fractions import Fraction
    >>> from cagd_ref.interval_bezier import round_outward
    >>> third = 1 / 3                                  # rounded: not exactly one third
    >>> lo, hi = round_outward(third, third)
    >>> Fraction(third) == Fraction(1, 3), Fraction(float(lo)) < Fraction(1, 3) < Fraction(float(hi))
    (False, True)
    """
    low, high = as_float_array(lo, "lo"), as_float_array(hi, "hi")
    if low.shape != high.shape:
        raise ValueError(f"hi: expected the shape of lo {low.shape}, got {high.shape}")
    if np.any(low > high):
        raise ValueError("lo: expected lo <= hi everywhere")
    return np.nextafter(low, -np.inf), np.nextafter(high, np.inf)


def interval_expression(expr):
    """Evaluate an expression of intervals and numbers with `Interval`, plain data in
    and out. Notes §12.1.

    expr: a number; a list [lo, hi] (the interval Interval(lo, hi)); or a
    tuple (op, operand, ...) with op one of "+", "-", "*", "/" (two operands),
    "neg", "width", "mid", "radius" (one) or "frozen" (one: whether assigning to
    its ``lo`` is refused). Operands are expressions themselves. Returns
    (lo, hi) for an interval, a float for a number, a string for "frozen".
    It is self-contained on purpose: the exercise notebook ships this very
    source, and the grader of the `Interval` exercise calls it on the student's
    class, so the class is tested with numbers going in and out.

    >>> from cagd_ref.interval_bezier import interval_expression
    >>> interval_expression(("-", [1, 2], [1, 2]))
    (-1.0, 1.0)
    >>> interval_expression(
    ...     ("*", [1, 2], ("+", [-1, 0], 1))
    ... )  # [u]([v] + [w]) of the notes
    (0.0, 2.0)
    >>> interval_expression(("width", ("/", 1, [2, 4])))
    0.25
    """

    operations = {
        "+": lambda x, y: x + y,
        "-": lambda x, y: x - y,
        "*": lambda x, y: x * y,
        "/": lambda x, y: x / y,
        "neg": lambda x: -x,
    }

    def value(e):
        if isinstance(e, list):
            return Interval(*e)
        if not isinstance(e, tuple):
            return e
        op, *operands = e
        args = [value(a) for a in operands]
        if op in operations:
            return operations[op](*args)
        if op == "frozen":
            try:
                args[0].lo = args[0].hi + 1.0
            except AttributeError:
                return "frozen"
            return "mutable"
        return getattr(args[0], op)

    result = value(expr)
    if isinstance(result, Interval):
        return (float(result.lo), float(result.hi))
    return result if isinstance(result, str) else float(result)


# ---------------------------------------------------------------- §12.2 boxes, centred form, affine maps


def _boxes(boxes, name: str = "boxes", min_count: int = 1) -> tuple[np.ndarray, bool]:
    """Boxes as a float array (n+1, d, 2) with lo <= hi, and whether scalar coefficients (n+1, 2) came in."""
    array = as_float_array(boxes, name)
    scalar = array.ndim == 2
    if scalar:
        array = array[:, None, :]
    if array.ndim != 3 or array.shape[2] != 2 or array.shape[0] < min_count or array.shape[1] < 1:
        raise ValueError(
            f"{name}: expected interval control points of shape (n+1, d, 2) (or (n+1, 2) for a scalar "
            f"polynomial), last axis (lo, hi), at least {min_count} of them, got shape {array.shape}"
        )
    bad = np.argwhere(array[..., 0] > array[..., 1])
    if bad.size:
        k, j = bad[0]
        raise ValueError(f"{name}: lo > hi at control point {k}, coordinate {j}: {array[k, j].tolist()}")
    return array, scalar


def _centred(array: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return 0.5 * (array[..., 0] + array[..., 1]), 0.5 * (array[..., 1] - array[..., 0])


def _box_array(centres: np.ndarray, errors: np.ndarray) -> np.ndarray:
    return np.stack([centres - errors, centres + errors], axis=-1)


def _errors(errors, name: str = "errors") -> np.ndarray:
    e = as_coefficients(errors, name)
    if np.any(e < 0):
        raise ValueError(f"{name}: expected non-negative errors (half-widths of the boxes), got {e.tolist()}")
    return e


def boxes_from_center(centers, errors) -> np.ndarray:
    """Boxes (n+1, d, 2) c_k + e_k [-1, 1] from centres and errors (n+1, d), errors >= 0. Notes §12.2.

    >>> from cagd_ref.interval_bezier import boxes_from_center
    >>> boxes_from_center([(0, 0), (1, 2)], [(0.1, 0.1), (0.2, 0.1)]).tolist()
    [[[-0.1, 0.1], [-0.1, 0.1]], [[0.8, 1.2], [1.9, 2.1]]]
    """
    c = as_coefficients(centers, "centers")
    e = _errors(errors)
    if e.shape != c.shape:
        raise ValueError(f"errors: expected the shape of centers {c.shape}, got {e.shape}")
    return _box_array(c, e)


def center_error(boxes) -> tuple[np.ndarray, np.ndarray]:
    """The centred form of boxes (n+1, d, 2): centres (n+1, d) and errors (n+1, d), errors >= 0. Notes §12.2.

    Scalar coefficients (n+1, 2) give (n+1,) and (n+1,).

    >>> from cagd_ref.interval_bezier import center_error
    >>> [a.tolist() for a in center_error([[[-0.1, 0.1], [0.9, 1.3]]])]
    [[[0.0, 1.1]], [[0.1, 0.2]]]
    """
    array, scalar = _boxes(boxes)
    c, e = _centred(array)
    return (c[:, 0], e[:, 0]) if scalar else (c, e)


def _box(box, name: str) -> np.ndarray:
    """One box (d, 2) with lo <= hi."""
    array = as_float_array(box, name)
    if array.ndim != 2 or array.shape[1] != 2 or array.shape[0] < 1:
        raise ValueError(f"{name}: expected a box of shape (d, 2), rows (lo, hi), got shape {array.shape}")
    return _boxes(array[None], name)[0][0]


def _affine(c0, e0, c1, e1, tau):
    """(1-t)[P0] + t[P1] in centred form, for every real t: centre and error (12.25)."""
    return (1 - tau) * c0 + tau * c1, np.abs(1 - tau) * e0 + np.abs(tau) * e1


def interval_affine(box0, box1, t) -> np.ndarray:
    """The affine map (1-t)[P0] + t[P1] of two boxes (d, 2), any real t: (d, 2) or (k, d, 2). Notes §12.2.

    Its centre is the affine map of the centres, its error |1-t| e0 + |t| e1:
    between the two errors for t in [0, 1], growing without bound outside.

    >>> from cagd_ref.interval_bezier import interval_affine
    >>> interval_affine([[0, 1]], [[2, 4]], [0.5, 2.0]).tolist()      # [a, b] = [0, 1] and [c, d] = [2, 4]
    [[[1.0, 2.5]], [[3.0, 8.0]]]
    """
    first, second = _box(box0, "box0"), _box(box1, "box1")
    if first.shape != second.shape:
        raise ValueError(f"box1: expected a box of the shape of box0 {first.shape}, got {second.shape}")
    ts, scalar = as_parameter(t)
    c, e = _affine(*_centred(first), *_centred(second), ts[:, None])
    result = _box_array(c, e)
    return result[0] if scalar else result


# ---------------------------------------------------------------- §12.2 interval de Casteljau and subdivision


def interval_de_casteljau_plain(boxes, t) -> np.ndarray:
    """The interval de Casteljau algorithm in its plain form: repeated affine maps of boxes. Notes §12.2.

    boxes: (n+1, d, 2). t: a number -> (d, 2), k values -> (k, d, 2); any real t.
    Every parameter gets its own copy of the boxes in centred form, and each
    round replaces [P_i] by (1-t)[P_i] + t[P_(i+1)]: centres by the ordinary
    de Casteljau step, errors by |1-t| e_i + |t| e_(i+1). `interval_de_casteljau`
    computes the same boxes faster.

    >>> from cagd_ref.interval_bezier import interval_de_casteljau_plain
    >>> boxes = [[[-1, 1]], [[1, 3]], [[-1, 1]]]           # centres 0, 2, 0 and unit errors
    >>> interval_de_casteljau_plain(boxes, [0.5, 2.0]).tolist()   # at t = 2: -8 ± (|1-t| + |t|)²
    [[[0.0, 2.0]], [[-17.0, 1.0]]]
    """
    array, scalar_boxes = _boxes(boxes)
    ts, scalar = as_parameter(t)
    tau = ts[:, None, None]
    c, e = (np.broadcast_to(part, (len(ts),) + part.shape) for part in _centred(array))
    while c.shape[1] > 1:
        c, e = _affine(c[:, :-1], e[:, :-1], c[:, 1:], e[:, 1:], tau)
    return _finish_boxes(_box_array(c[:, 0], e[:, 0]), scalar, scalar_boxes)


def _finish_boxes(result: np.ndarray, scalar: bool, scalar_boxes: bool) -> np.ndarray:
    """(k, d, 2) boxes -> (d, 2) for one parameter, and without the d axis for scalar polynomials."""
    if scalar_boxes:
        result = result[:, 0]
    return result[0] if scalar else result


def _abs_bernstein_sum(e: np.ndarray, ts: np.ndarray) -> np.ndarray:
    """Σ e_k |B_k^n(t)| at k parameters, (k, d), by `cagd_ref.bezier.de_casteljau` at a folded parameter.

    |B_k^n(t)| = C(n, k) |1-t|^(n-k) |t|^k = (|1-t| + |t|)^n B_k^n(s) with
    s = |t| / (|1-t| + |t|) in [0, 1]: outside [0, 1] the error curve is the
    one inside, at s, magnified by (|1-t| + |t|)^n (= 1 on [0, 1]).
    """
    n = len(e) - 1
    if n == 0 or (ts.size and 0 <= ts.min() and ts.max() <= 1):
        return de_casteljau(e, ts)
    b = np.abs(ts)
    total = np.abs(1 - ts)
    total += b
    values = de_casteljau(e, b / total)
    values *= _power(total, n)[:, None]
    return values


def _power(x: np.ndarray, n: int) -> np.ndarray:
    """x**n for an integer n >= 1 by repeated squaring: a few multiplications instead of a pass of pow()."""
    result, square = None, x
    while n:
        if n & 1:
            result = square.copy() if result is None else result * square
        n >>= 1
        if n:
            square = square * square
    return result


def interval_de_casteljau(boxes, t) -> np.ndarray:
    """The box [P](t) of an interval Bézier curve, for any real t: (d, 2), or (k, d, 2) for k values. Notes §12.2.

    boxes: (n+1, d, 2), last axis (lo, hi) (or (n+1, 2) for a scalar interval
    polynomial: (2,) or (k, 2)). The result is the de Casteljau algorithm run
    in interval arithmetic, (12.19), which in centred form is

        [P](t) = Σ c_k B_k^n(t) + (Σ e_k |B_k^n(t)|) [-1, 1]      (12.27)-(12.29):

    the exact set of points P(t) of all the curves with P_k in [P_k], inside
    [0, 1] and outside it. It is computed so, with `cagd_ref.bezier.de_casteljau`
    on the centres and on the errors (at a folded parameter, see
    `_abs_bernstein_sum`); `interval_de_casteljau_plain` is the triangle of
    affine maps itself.

    The course's cubic with centres (0, 0), (1, 2), (3, 2), (4, 0):

    >>> from cagd_ref.interval_bezier import boxes_from_center, interval_de_casteljau
    >>> boxes = boxes_from_center([(0, 0), (1, 2), (3, 2), (4, 0)], [(0.1, 0.1), (0.2, 0.1), (0.1, 0.3), (0, 0.2)])
    >>> interval_de_casteljau(boxes, 0.5).round(6).tolist()
    [[1.875, 2.125], [1.3125, 1.6875]]
    >>> interval_de_casteljau(boxes, [2.0]).round(6).tolist()        # outside [0, 1] the box grows fast
    [[[-0.5, 4.5], [-17.9, -6.1]]]
    """
    array, scalar_boxes = _boxes(boxes)
    ts, scalar = as_parameter(t)
    centres, errors = _centred(array)
    c, e = de_casteljau(centres, ts), _abs_bernstein_sum(errors, ts)
    result = np.empty(c.shape + (2,))
    np.subtract(c, e, out=result[..., 0])
    np.add(c, e, out=result[..., 1])
    return _finish_boxes(result, scalar, scalar_boxes)


def error_curve(errors, t):
    """The error curve ẽ(t) = Σ e_k |B_k^n(t)| of an interval curve, any real t. Notes §12.2, (12.23), (12.28).

    errors: (n+1, d) (or (n+1,)), the non-negative half-widths e_k of the
    boxes; a negative one is a ValueError. t: a number -> (d,) (a float), k
    values -> (k, d) ((k,)). Inside [0, 1] this is the Bézier curve of the
    errors, Σ e_k B_k^n(t); outside it |B_k^n(t)| = (-1)^k B_k^n(t) for t < 0
    and (-1)^(n+k) B_k^n(t) for t > 1, so the error grows like |t|^n.

    >>> from cagd_ref.interval_bezier import error_curve
    >>> errors = [(0.1, 0.1), (0.2, 0.1), (0.1, 0.3), (0.0, 0.2)]     # the course's cubic
    >>> error_curve(errors, 0.5).round(6).tolist()
    [0.125, 0.1875]
    >>> error_curve([1, 1, 1, 1], [0.5, 2.0, -0.5]).tolist()          # unit errors: (|1-t| + |t|)³
    [1.0, 27.0, 8.0]
    """
    e = _errors(errors)
    ts, scalar = as_parameter(t)
    values = _abs_bernstein_sum(e.reshape(len(e), -1), ts)
    if e.ndim == 1:
        values = values[:, 0]
        return float(values[0]) if scalar else values
    return values[0] if scalar else values


def _triangle(centres: np.ndarray, errors: np.ndarray, tau: float) -> list[tuple[np.ndarray, np.ndarray]]:
    """Every level of the interval de Casteljau triangle at t, in centred form: level j has n+1-j boxes."""
    levels = [(centres, errors)]
    while len(levels[-1][0]) > 1:
        c, e = levels[-1]
        levels.append(_affine(c[:-1], e[:-1], c[1:], e[1:], tau))
    return levels


def interval_de_casteljau_triangle(boxes, t) -> list[np.ndarray]:
    """Every level of the interval de Casteljau triangle at a number t: level j is (n+1-j, d, 2). Notes §12.2.

    Level 0 holds the control boxes, the last level the single box [P](t).
    """
    array, _ = _boxes(boxes)
    return [_box_array(c, e) for c, e in _triangle(*_centred(array), as_scalar(t, "t"))]


def interval_subdivide(boxes, t=0.5) -> tuple[np.ndarray, np.ndarray]:
    """Split an interval Bézier curve at a number t into two of the same degree: (left, right). Notes §12.2.

    boxes: (n+1, d, 2). left holds [P_0^(0)], [P_1^(1)], ..., [P_n^(n)] and
    covers [0, t]; right holds [P_n^(n)], [P_n^(n-1)], ..., [P_n^(0)] and
    covers [t, 1]; both share the box [P](t). The errors follow the triangle
    of affine maps, e <- |1-t| e_i + |t| e_(i+1): for t in [0, 1] every
    piece's error curve is the original one, reparametrised (no ballooning);
    for t outside [0, 1] the boxes inflate (unit errors at t = 2: 1, 3, 9, 27).

    >>> from cagd_ref.interval_bezier import interval_subdivide
    >>> unit = [[[-1, 1]], [[-1, 1]], [[-1, 1]], [[-1, 1]]]
    >>> left, right = interval_subdivide(unit, 2.0)
    >>> (left[:, 0, 1] - left[:, 0, 0]).tolist()           # widths 2 e: e = 1, 3, 9, 27
    [2.0, 6.0, 18.0, 54.0]
    """
    array, _ = _boxes(boxes)
    levels = _triangle(*_centred(array), as_scalar(t, "t"))
    left = _box_array(np.array([c[0] for c, _ in levels]), np.array([e[0] for _, e in levels]))
    right = _box_array(np.array([c[-1] for c, _ in reversed(levels)]), np.array([e[-1] for _, e in reversed(levels)]))
    return left, right


def interval_elevate(boxes, times: int = 1) -> np.ndarray:
    """Raise the degree of an interval Bézier curve: (n+1, d, 2) -> (n+1+times, d, 2). Notes §12.2.

    The elevation weights are non-negative, so the lower and upper ends are
    elevated on their own; on [0, 1] the elevated curve sweeps the same boxes.

    >>> from cagd_ref.interval_bezier import interval_elevate
    >>> interval_elevate([[[0, 0]], [[1, 3]]]).tolist()
    [[[0.0, 0.0]], [[0.5, 1.5]], [[1.0, 3.0]]]
    """
    array, scalar = _boxes(boxes)
    times = as_count(times, "times")
    n1, d, _ = array.shape
    raised = elevate(array.reshape(n1, 2 * d), times).reshape(n1 + times, d, 2)
    return raised[:, 0] if scalar else raised


def interval_polynomial_width(coeffs):
    """The width ∫₀¹ (p_max - p_min) dt of an interval polynomial: the mean coefficient width. Notes §12.1.

    coeffs: (n+1, 2) -> a float; boxes (n+1, d, 2) -> (d,), one width per coordinate.

    >>> from cagd_ref.interval_bezier import interval_polynomial_width
    >>> round(interval_polynomial_width([[0, 0.2], [1, 1.6], [0.5, 0.6]]), 12)
    0.3
    """
    array, scalar = _boxes(coeffs, "coeffs")
    width = np.mean(array[..., 1] - array[..., 0], axis=0)
    return float(width[0]) if scalar else width


# ---------------------------------------------------------------- §12.2 the envelope


def _planar_boxes(boxes) -> np.ndarray:
    array, scalar = _boxes(boxes, min_count=2)
    if scalar or array.shape[1] != 2:
        raise ValueError(f"boxes: the envelope is drawn for planar curves, expected (n+1, 2, 2), got {array.shape}")
    return array


def corner_curves(boxes) -> dict[str, np.ndarray]:
    """The four corner curves of planar boxes (n+1, 2, 2): {"TL", "TR", "BL", "BR"} -> (n+1, 2). Notes §12.2.

    The curve "TL" has every control point at the top left corner of its box, and so on.

    >>> from cagd_ref.interval_bezier import corner_curves
    >>> corner_curves([[[0, 1], [0, 2]], [[3, 4], [1, 5]]])["TL"].tolist()
    [[0.0, 2.0], [3.0, 5.0]]
    """
    array = _planar_boxes(boxes)
    return {name: np.column_stack([array[:, 0, i], array[:, 1, j]]) for name, (i, j) in CORNERS.items()}


def envelope_pieces(boxes) -> list[tuple[float, float, tuple[str, str]]]:
    """Which two corner curves bound the region an interval curve sweeps: [(t0, t1, (a, b)), ...]. Notes §12.2.

    boxes: planar (n+1, 2, 2). [0, 1] is split where the centre curve has a
    horizontal or vertical tangent (roots of x' and y', `roots.bernstein_roots`
    on the hodograph). On a piece where the centre moves north-east or
    south-west the region lies between the corner curves TL and BR; where it
    moves north-west or south-east, between TR and BL. At the split points the
    boundary runs along an edge of the box [P](t), and the boxes at t = 0 and
    t = 1 close it. The rule holds when the corner curves move in the centre's
    quadrant too (errors that change slowly against the centre's motion).

    >>> from cagd_ref.interval_bezier import boxes_from_center, envelope_pieces
    >>> arch = boxes_from_center([(0, 0), (1, 2), (3, 2), (4, 0)], [(0.1, 0.1)] * 4)
    >>> [(round(a, 6), round(b, 6), pair) for a, b, pair in envelope_pieces(arch)]
    [(0.0, 0.5, ('TL', 'BR')), (0.5, 1.0, ('TR', 'BL'))]
    """
    centres, _ = _centred(_planar_boxes(boxes))
    velocity = hodograph(centres)
    splits = [0.0, 1.0]
    for column in velocity.T:
        if np.any(np.abs(column) > 1e-12 * max(1.0, np.abs(velocity).max())):
            splits += [float(r) for r in bernstein_roots(column) if 0 < r < 1]
    splits = np.unique(np.round(splits, 12))
    pieces = []
    for t0, t1 in zip(splits[:-1], splits[1:]):
        dx, dy = de_casteljau(velocity, 0.5 * (t0 + t1))
        pair = ("TL", "BR") if dx * dy >= 0 else ("TR", "BL")
        pieces.append((float(t0), float(t1), pair))
    return pieces


# ---------------------------------------------------------------- §12.3 approximation by interval polynomials


def _bound(bound, like: np.ndarray, name: str = "bound") -> np.ndarray:
    """A derivative bound [lo, hi]: (2,) for scalar data, (d, 2) for data (·, d); returned as (d, 2)."""
    b = as_float_array(bound, name)
    wanted = (2,) if like.ndim == 1 else (like.shape[1], 2)
    if b.shape != wanted:
        raise ValueError(f"{name}: expected [lo, hi] of shape {wanted} (one per coordinate), got shape {b.shape}")
    b = b.reshape(-1, 2)
    if np.any(b[:, 0] > b[:, 1]):
        raise ValueError(f"{name}: expected lo <= hi, got {b.tolist()}")
    return b


def _add_interval(coeffs: np.ndarray, factors: np.ndarray, bound: np.ndarray) -> np.ndarray:
    """Interval coefficients F_k + ω_k [lo, hi] per column: (m, d, 2) from F (m, d), ω (m,) and bound (d, 2)."""
    products = factors[:, None, None] * bound[None, :, :]  # (m, d, 2): ω_k lo and ω_k hi, swapped when ω_k < 0
    return coeffs[..., None] + np.stack([products.min(axis=2), products.max(axis=2)], axis=-1)


def _shaped(result: np.ndarray, scalar: bool) -> np.ndarray:
    return result[:, 0] if scalar else result


def lagrange_interval(nodes, values, bound, interval=(0, 1)) -> np.ndarray:
    """An interval polynomial of degree n+1 holding f: Lagrange interpolant plus Cauchy remainder. Notes §12.3.

    nodes: (n+1,) distinct, in `interval` = (a, b); values: f at the nodes,
    (n+1,) or (n+1, d); bound: [f_min, f_max] of the derivative f^(n+1) on
    [a, b], (2,) or (d, 2). Since f(t) = F_n(t) + f^(n+1)(ξ)/(n+1)! Π (t - t_k),
    the coefficients on [a, b] are those of F_n raised to degree n+1 plus
    ω_k [f_min, f_max], where ω_k are the Bernstein coefficients of
    Π (t - t_k)/(n+1)!. Returns (n+2, 2), or (n+2, d, 2).

    eᵗ on [0, 1] from the nodes 0, 1/2, 1, with e‴ in [1, e] (a course example):

    >>> import math
    >>> from cagd_ref.interval_bezier import lagrange_interval
    >>> lagrange_interval([0, 0.5, 1], [1, math.exp(0.5), math.e], [1, math.e]).round(6).tolist()
    [[1.0, 1.0], [1.319979, 1.367709], [1.789454, 1.837184], [2.718282, 2.718282]]
    """
    t = as_float_array(nodes, "nodes")
    data = as_coefficients(values, "values")
    if t.ndim != 1 or len(t) != len(data):
        raise ValueError(f"nodes: expected one node per value, shape ({len(data)},), got shape {t.shape}")
    a, b = as_interval(interval)
    if np.any(t < a) or np.any(t > b) or len(np.unique(t)) != len(t):
        raise ValueError(f"nodes: expected distinct nodes in [{a}, {b}], got {t.tolist()}")
    bounds = _bound(bound, data)
    scalar = data.ndim == 1
    columns = data.reshape(len(data), -1)
    centre = elevate(bernstein_interpolation(t, columns, (a, b)))
    omega = bernstein_from_roots(t, (a, b), leading=1.0 / math.factorial(len(t)))
    return _shaped(_add_interval(centre, omega, bounds), scalar)


def _hermite_data(derivs0, derivs1) -> tuple[np.ndarray, np.ndarray, bool]:
    d0 = as_coefficients(derivs0, "derivs0")
    d1 = as_coefficients(derivs1, "derivs1")
    if d0.shape != d1.shape:
        raise ValueError(f"derivs1: expected the shape of derivs0 {d0.shape}, got {d1.shape}")
    return d0.reshape(len(d0), -1), d1.reshape(len(d1), -1), d0.ndim == 1


def _hermite_points(d0: np.ndarray, d1: np.ndarray) -> np.ndarray:
    """Control points (2m, d) of the degree-(2m-1) Hermite interpolant of m derivatives at each end."""
    m = len(d0)
    n = 2 * m - 1
    # Δ^i P_0 = (n-i)!/n! f^(i)(0) and ∇^i P_n = (n-i)!/n! f^(i)(1); Newton's forward and backward formulas.
    scale = np.array([1.0 / math.perm(n, i) for i in range(m)])[:, None]
    forward, backward = scale * d0, scale * d1
    points = np.empty((n + 1, d0.shape[1]))
    for j in range(m):
        binomials = np.array([math.comb(j, i) for i in range(j + 1)], dtype=float)[:, None]
        points[j] = (binomials * forward[: j + 1]).sum(axis=0)
        signs = (-1.0) ** np.arange(j + 1)[:, None]
        points[n - j] = (binomials * signs * backward[: j + 1]).sum(axis=0)
    return points


def hermite_bezier(derivs0, derivs1) -> np.ndarray:
    """Bézier coefficients of the polynomial of degree 2m-1 with given f^(i)(0), f^(i)(1), i < m. Notes §12.3.

    derivs0, derivs1: (m,) or (m, d), the values and derivatives f, f', ...,
    f^(m-1) at 0 and at 1. Returns (2m,) or (2m, d): P_j = Σ_(i<=j) C(j, i)
    (n-i)!/n! f^(i)(0) and P_(n-j) = Σ_(i<=j) (-1)^i C(j, i) (n-i)!/n! f^(i)(1).
    For m = 2 these are f0, f0 + f0'/3, f1 - f1'/3, f1 (chapter 10's cubic).

    >>> from cagd_ref.interval_bezier import hermite_bezier
    >>> hermite_bezier([0, 3], [1, 3]).tolist()
    [0.0, 1.0, 0.0, 1.0]
    """
    d0, d1, scalar = _hermite_data(derivs0, derivs1)
    points = _hermite_points(d0, d1)
    return points[:, 0] if scalar else points


def hermite_interval(derivs0, derivs1, bound, interval=(0, 1)) -> np.ndarray:
    """Interval polynomial of degree 2m holding f, from m end derivatives and a bound on f^(2m). Notes §12.3.

    derivs0, derivs1: (m,) or (m, d), f, f', ..., f^(m-1) at the ends of
    `interval` = (a, b), derivatives with respect to t; bound: [f_min, f_max] of
    f^(2m) on [a, b], (2,) or (d, 2). The Hermite interpolant F_n of odd degree
    n = 2m-1 misses f by f^(2m)(ξ)/(2m)! (t-a)^m (t-b)^m, and
    t^m (t-1)^m = (-1)^m B_m^(2m)(t)/C(2m, m): so F_n raised to degree 2m plus
    (-1)^m [f_min, f_max]/((2m)! C(2m, m)) on its middle coefficient alone
    (width (f_max - f_min)/((2m)!/m!)², (12.64)). Returns the coefficients
    (2m+1, 2), or (2m+1, d, 2), in the Bernstein basis of [a, b].

    The notes' Example 1, f = eᵗ with f⁽⁴⁾ in [1, e]:

    >>> import math
    >>> from cagd_ref.interval_bezier import hermite_interval
    >>> hermite_interval([1, 1], [math.e, math.e], [1, math.e]).round(6).tolist()
    [[1.0, 1.0], [1.25, 1.25], [1.579705, 1.591638], [2.038711, 2.038711], [2.718282, 2.718282]]
    """
    d0, d1, scalar = _hermite_data(derivs0, derivs1)
    bounds = _bound(bound, as_coefficients(derivs0, "derivs0"))
    a, b = as_interval(interval)
    m = len(d0)
    h = b - a
    # On the local parameter s = (t - a)/h every derivative of order i carries a factor h^i.
    powers = (h ** np.arange(m))[:, None]
    centre = elevate(_hermite_points(powers * d0, powers * d1))
    middle = np.zeros(2 * m + 1)
    middle[m] = (-1.0) ** m * h ** (2 * m) / (math.factorial(2 * m) * math.comb(2 * m, m))
    return _shaped(_add_interval(centre, middle, bounds), scalar)


def derivative_bounds(coeffs, r: int) -> np.ndarray:
    """Bounds [lo, hi] on the r-th derivative of a Bernstein polynomial on [0, 1], by differences. Notes §12.3, (12.69).

    coeffs: (n+1,) -> (2,), or (n+1, d) -> (d, 2) (a curve: one bound per
    coordinate). f^(r)(t) = n!/(n-r)! Σ Δ^r p_k B_k^(n-r)(t) (12.68), and the
    Bernstein polynomials are non-negative and sum to one on [0, 1], so
    n!/(n-r)! min_k Δ^r p_k <= f^(r)(t) <= n!/(n-r)! max_k Δ^r p_k. For r > n
    the derivative vanishes: [0, 0].

    >>> from cagd_ref.interval_bezier import derivative_bounds
    >>> derivative_bounds([0, 0.25, 0.5, 1, 0.5, 1], 4).tolist()     # Δ⁴ = -1.5, 3.25 and 5!/1! = 120
    [-180.0, 390.0]
    """
    p = as_coefficients(coeffs)
    r = as_count(r, "r")
    n = len(p) - 1
    columns = p.reshape(len(p), -1)
    if r > n:
        bounds = np.zeros((columns.shape[1], 2))
    else:
        differences = math.perm(n, r) * forward_difference_table(columns)[r]
        bounds = np.column_stack([differences.min(axis=0), differences.max(axis=0)])
    return bounds[0] if p.ndim == 1 else bounds


def _end_derivatives(piece: np.ndarray, m: int) -> tuple[np.ndarray, np.ndarray]:
    """f^(i)(0) and f^(i)(1), i < m, of a Bézier polynomial (n+1, d): n!/(n-i)! Δ^i p_0 and ∇^i p_n."""
    n = len(piece) - 1
    table = forward_difference_table(piece)
    zeros = np.zeros(piece.shape[1])
    d0 = np.array([math.perm(n, i) * table[i][0] if i <= n else zeros for i in range(m)])
    d1 = np.array([math.perm(n, i) * table[i][-1] if i <= n else zeros for i in range(m)])
    return d0, d1


def interval_degree_reduce(coeffs, depth: int = 0, degree: int = 4) -> np.ndarray:
    """Enclose a Bézier polynomial or curve in interval pieces of a lower even degree: a guaranteed bound. Notes §12.3.

    coeffs: (n+1,) or (n+1, d). The curve is halved `depth` times (2^depth
    pieces, piece i over [i/2^depth, (i+1)/2^depth]); each piece is replaced
    by the Hermite interval polynomial of degree `degree` = 2m built from its
    end derivatives up to order m-1 and the bound on its derivative of order
    2m from forward differences (`derivative_bounds`). Returns
    (2^depth, degree+1, 2), or (2^depth, degree+1, d, 2), each piece in the
    Bernstein basis of [0, 1]. A halving divides the widths by about 2^(2m).

    The quintic [0, 1/4, 1/2, 1, 1/2, 1] in one quartic interval piece:

    >>> from cagd_ref.interval_bezier import interval_degree_reduce
    >>> interval_degree_reduce([0, 0.25, 0.5, 1, 0.5, 1])[0].round(6).tolist()
    [[0.0, 0.0], [0.3125, 0.3125], [-0.958333, 3.0], [0.375, 0.375], [1.0, 1.0]]
    """
    p = as_coefficients(coeffs)
    depth = as_count(depth, "depth")
    degree = as_count(degree, "degree", minimum=2)
    if degree % 2:
        raise ValueError(f"degree: the Hermite enclosure has an even degree 2m, got {degree}")
    m = degree // 2
    pieces = [p.reshape(len(p), -1)]
    for _ in range(depth):
        pieces = [half for piece in pieces for half in subdivide(piece, 0.5)]
    result = []
    for piece in pieces:
        d0, d1 = _end_derivatives(piece, m)
        result.append(hermite_interval(d0, d1, derivative_bounds(piece, degree)))
    result = np.array(result)
    return result[:, :, 0] if p.ndim == 1 else result
