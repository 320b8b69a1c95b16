"""Returns the half-width as the width.

The evaluator below is the one the exercise notebook ships, unchanged."""
import math


def _as_interval(x):
    return x if isinstance(x, Interval) else Interval(x, x)


class Interval:
    __slots__ = ("lo", "hi")

    def __init__(self, lo, hi):
        lo, hi = float(lo), float(hi)
        if not (math.isfinite(lo) and math.isfinite(hi)):
            raise ValueError("lo, hi: expected finite numbers")
        if lo > hi:
            raise ValueError("lo: expected lo <= hi")
        object.__setattr__(self, "lo", lo)
        object.__setattr__(self, "hi", hi)

    def __setattr__(self, name, value):
        raise AttributeError("an Interval cannot be changed")

    @property
    def width(self):
        return (self.hi - self.lo) / 2

    def __add__(self, other):
        other = _as_interval(other)
        return Interval(self.lo + other.lo, self.hi + other.hi)

    __radd__ = __add__

    def __sub__(self, other):
        other = _as_interval(other)
        return Interval(self.lo - other.hi, self.hi - other.lo)

    def __rsub__(self, other):
        return _as_interval(other) - self

    def __mul__(self, other):
        other = _as_interval(other)
        products = [self.lo * other.lo, self.lo * other.hi, self.hi * other.lo, self.hi * other.hi]
        return Interval(min(products), max(products))

    __rmul__ = __mul__

    def __truediv__(self, other):
        other = _as_interval(other)
        if other.lo <= 0 <= other.hi:
            raise ValueError("divisor contains 0")
        return self * Interval(1 / other.hi, 1 / other.lo)

    def __rtruediv__(self, other):
        return _as_interval(other) / self


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
