"""Hidden grading suite of chapter 12: interval arithmetic, interval Bézier curves and interval enclosures.

The fixed cases are the notes' Examples 1 and 2 and the quarter circle, and the
course's examples (cagd_course/examples/ch12.toml): Moore's identities, the
cubic with boxes of centres (0, 0), (1, 2), (3, 2), (4, 0), the unit-error
cubic subdivided at τ = 2, the quintic whose fourth derivative lies in
[-180, 390]. Edge cases probe degree 0 and 1, boxes of zero width, t outside
[0, 1] (where running de Casteljau on lo and hi separately, or dropping the
absolute values, goes wrong), one- and three-dimensional boxes. Random cases
come from the generator the grader passes in.

`Interval` is a class, and only plain data travels between the grader and the
student's process. Its exercise therefore calls `interval_expression`, the
small evaluator the exercise notebook ships beside the class (the very source
of `cagd_ref.interval_bezier.interval_expression`): it builds intervals with the
student's `Interval`, applies the operations and returns end points.
"""

from __future__ import annotations

import math

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close
from cagd_ref import interval_bezier as ib

EXAMPLE = "notes examples"
COURSE = "course examples"
EDGE = "edge cases"
OUTSIDE = "t outside [0, 1]"
SHAPES = "scalar vs array t"
INTERVALS = "other intervals"
RANDOM = "random"
BAD = "bad input"

ARITHMETIC = notes_example("12.arithmetic")
CUBIC = notes_example("12.cubic")
BALLOONING = notes_example("12.ballooning")
CUBIC_BOXES = ib.boxes_from_center(*CUBIC.args("centers", "errors")).tolist()
CUBIC_ERRORS = CUBIC.inputs["errors"].tolist()
UNIT = [[[-1.0, 1.0]]] * 4
TS = np.linspace(0.0, 1.0, 9)
WIDE = np.array([-1.5, -0.5, -0.1, 0.0, 0.3, 0.5, 1.0, 1.2, 2.0, 3.0])


class ClassExercise(Exercise):
    """An exercise on a class: the worker calls the evaluator that the notebook ships with it (the reference's name)."""

    @property
    def function(self) -> str:
        return self.reference.__name__


def _random_boxes(rng, low=0, high=6, dims=(1, 2, 3)) -> np.ndarray:
    n = int(rng.integers(low, high + 1))
    d = int(rng.choice(dims))
    errors = rng.uniform(0, 0.6, (n + 1, d)) * (rng.uniform(size=(n + 1, d)) < 0.85)
    return ib.boxes_from_center(rng.uniform(-4, 4, (n + 1, d)), errors)


# --- 12.Interval ---------------------------------------------------------------------------------------


def _pair(rng) -> list[float]:
    lo = float(np.round(rng.uniform(-5, 5), 3))
    return [lo, lo + float(np.round(rng.exponential(2.0), 3))]


def _operand(rng, depth: int):
    roll = rng.uniform()
    if depth and roll < 0.35:
        return _expression(rng, depth - 1)
    if roll < 0.55:
        return float(np.round(rng.uniform(-5, 5), 3))
    return _pair(rng)


def _expression(rng, depth: int = 1):
    """A random expression of + - * / whose divisors keep away from 0 (bad input has its own category)."""
    while True:
        op = str(rng.choice(["+", "-", "*", "/"]))
        expr = (op, _operand(rng, depth), _operand(rng, depth))
        if not any(isinstance(x, (list, tuple)) for x in expr[1:]):
            continue
        try:
            value = ib.interval_expression(expr)
        except ValueError:
            continue
        if abs(value[0]) < 1e6 and abs(value[1]) < 1e6:
            return expr


def interval_cases(rng):
    u, v, factor, divisor = (ARITHMETIC.inputs[k].tolist() for k in ("u", "v", "factor", "divisor"))
    w = ARITHMETIC.inputs["w"]
    unit = [-1.0, 1.0]
    cases = [
        Case(COURSE, (("-", u, u),), visible=True),  # not 0
        Case(COURSE, (("*", u, factor),), visible=True),
        Case(COURSE, (("/", u, divisor),), visible=True),
        Case(COURSE, (("*", u, ("+", v, w)),), visible=True),  # subdistributivity: [0, 2] ...
        Case(COURSE, (("+", ("*", u, v), ("*", u, w)),), visible=True),  # ... inside [-1, 2]
        Case(COURSE, (("+", ("*", 1.0, unit), ("*", -1.0, unit)),), visible=True),  # (12.24): [-2, 2]
        Case(COURSE, (("width", ("-", u, u)),), visible=True),
        Case(EDGE, (("+", [1.0, 2.0], [-3.0, 0.5]),), visible=True),
        Case(EDGE, (("-", [1.0, 2.0], [-3.0, 0.5]),), visible=True),
        Case(EDGE, (("*", [-3.0, -1.0], [-2.0, 4.0]),), visible=True),  # mixed signs: the min/max of four products
        Case(EDGE, (("*", [-3.0, -1.0], [-4.0, -2.0]),), visible=True),  # both negative
        Case(EDGE, (("*", [-1.0, 2.0], [-3.0, 1.0]),), visible=True),  # both straddle 0
        Case(EDGE, (("/", [1.0, 2.0], [-4.0, -0.5]),), visible=True),
        Case(EDGE, (("/", [-1.0, 3.0], [2.0, 4.0]),), visible=True),
        Case(EDGE, (("width", [2.5, 4.0]),), visible=True),
        Case(EDGE, (("width", [3.0, 3.0]),), visible=True),
        Case(EDGE, (("-", [3.0, 3.0], [3.0, 3.0]),), visible=True),  # a degenerate interval minus itself is 0
        Case(EDGE, (("frozen", [1.0, 2.0]),), visible=True),
        Case(EDGE, ([2, 3],), visible=True),  # integers are numbers too
        Case("numbers on either side", (("-", 2.0, u),), visible=True),
        Case("numbers on either side", (("-", u, 2.0),), visible=True),
        Case("numbers on either side", (("+", 3.0, u),), visible=True),
        Case("numbers on either side", (("*", -2.0, u),), visible=True),
        Case("numbers on either side", (("*", u, -2.0),), visible=True),
        Case("numbers on either side", (("/", 1.0, [2.0, 4.0]),), visible=True),
        Case("numbers on either side", (("/", u, -4.0),), visible=True),
        Case("numbers on either side", (("*", 0.5, ("-", 1.0, [-1.0, 3.0])),), visible=True),
    ]
    cases += [Case(RANDOM, (_expression(rng, depth=int(rng.integers(0, 3))),)) for _ in range(16)]
    cases += [
        Case(BAD, (("/", u, [-1.0, 1.0]),)),  # 0 inside the divisor
        Case(BAD, (("/", u, [0.0, 2.0]),)),  # 0 at an end of it
        Case(BAD, (("/", u, [-3.0, 0.0]),)),
        Case(BAD, (("/", 1.0, [-0.5, 0.5]),)),  # a number divided by such an interval
        Case(BAD, (("/", u, 0.0),)),  # the number 0 is the interval [0, 0]
        Case(BAD, ([2.0, 1.0],)),  # lo > hi
    ]
    return cases


# --- 12.interval_de_casteljau ------------------------------------------------------------------------


def _parameters(rng, low=-1.5, high=2.5):
    if rng.uniform() < 0.3:
        return float(rng.uniform(low, high))
    return np.sort(rng.uniform(low, high, int(rng.integers(2, 9))))


def interval_de_casteljau_cases(rng):
    cases = [
        Case(COURSE, (CUBIC_BOXES, CUBIC.inputs["t"]), visible=True),
        Case(COURSE, (CUBIC_BOXES, 0.5), visible=True),
        Case(COURSE, (CUBIC_BOXES, TS), visible=True),
        Case(EDGE, ([[[1.0, 2.0], [-1.0, 0.0]]], WIDE), visible=True),  # degree 0: the box itself, for every t
        Case(EDGE, ([[[0.0, 1.0]], [[2.0, 4.0]]], WIDE), visible=True),  # degree 1: the affine map of Fig. 12.3
        Case(EDGE, ([[[0.0, 0.0], [1.0, 1.0]], [[2.0, 2.0], [0.0, 0.0]], [[3.0, 3.0], [3.0, 3.0]]], WIDE),
             visible=True),  # boxes of zero width: the ordinary de Casteljau algorithm
        Case(EDGE, (UNIT, [0.0, 0.5, 1.0]), visible=True),
        Case(EDGE, (ib.boxes_from_center([[0, 0, 0], [1, 2, 3], [2, -1, 1]], [[0.1, 0, 0.2]] * 3).tolist(), TS),
             visible=True),  # three dimensions
        Case(OUTSIDE, (CUBIC_BOXES, [2.0, -0.5]), visible=True),
        Case(OUTSIDE, (CUBIC_BOXES, 2.0), visible=True),
        Case(OUTSIDE, (UNIT, [-1.0, 1.5, 2.0, 3.0]), visible=True),
        Case(OUTSIDE, (CUBIC_BOXES, WIDE), visible=True),
        Case(SHAPES, (CUBIC_BOXES, np.array([0.3]))),
        Case(SHAPES, (CUBIC_BOXES, np.array(0.3))),
        Case(SHAPES, (CUBIC_BOXES, 1)),
        Case(SHAPES, (CUBIC_BOXES, np.array([]))),
    ]
    cases += [Case(RANDOM, (_random_boxes(rng), _parameters(rng))) for _ in range(16)]
    cases += [
        Case(BAD, ([[[1.0, 0.0]], [[0.0, 1.0]]], 0.5)),  # lo > hi
        Case(BAD, (np.zeros((3, 2, 3)), 0.5)),  # the last axis is (lo, hi)
        Case(BAD, (np.zeros((0, 2, 2)), 0.5)),  # no control points
        Case(BAD, (CUBIC_BOXES, [[0.5]])),
        Case(BAD, (CUBIC_BOXES, float("nan"))),
    ]
    return cases


# --- 12.error_curve ----------------------------------------------------------------------------------


def error_curve_cases(rng):
    cases = [
        Case(COURSE, (CUBIC_ERRORS, 0.5), visible=True),
        Case(COURSE, (CUBIC_ERRORS, TS), visible=True),
        Case(OUTSIDE, (BALLOONING.inputs["errors"].tolist(), [2.0, 3.0, -0.5, -1.0]), visible=True),  # (|1-t|+|t|)³
        Case(OUTSIDE, (CUBIC_ERRORS, WIDE), visible=True),
        Case(OUTSIDE, (CUBIC_ERRORS, -0.5), visible=True),
        Case(EDGE, ([[0.3, 0.1]], WIDE), visible=True),  # degree 0
        Case(EDGE, ([[0.0, 0.0], [0.0, 0.0]], WIDE), visible=True),  # no error at all
        Case(EDGE, ([[1.0], [0.0], [0.0], [0.0], [0.0]], WIDE), visible=True),  # one box only: |B_0^4(t)|
        Case(EDGE, ([0.2, 0.5, 0.1], [0.25, 1.5]), visible=True),  # scalar errors (n+1,): (k,)
        Case(EDGE, ([0.2, 0.5, 0.1], 1.5), visible=True),
        Case(SHAPES, (CUBIC_ERRORS, np.array([0.3]))),
        Case(SHAPES, (CUBIC_ERRORS, np.array([]))),
    ]
    for _ in range(14):
        errors = ib.center_error(_random_boxes(rng))[1]
        cases.append(Case(RANDOM, (errors, _parameters(rng))))
    cases += [
        Case(BAD, ([[0.1, -0.2], [0.1, 0.1]], 0.5)),  # errors are half-widths: never negative
        Case(BAD, ([0.1, -0.01], [0.5, 2.0])),
        Case(BAD, (CUBIC_ERRORS, [[0.5]])),
        Case(BAD, ([[0.1, float("nan")]], 0.5)),
    ]
    return cases


# --- 12.interval_subdivide ---------------------------------------------------------------------------


def interval_subdivide_cases(rng):
    cases = [
        Case(COURSE, (CUBIC_BOXES, 0.5), visible=True),
        Case(COURSE, (CUBIC_BOXES, 0.25), visible=True),
        Case(COURSE, (CUBIC_BOXES,), visible=True),  # t = 1/2 by default
        Case(OUTSIDE, (UNIT, float(BALLOONING.inputs["tau"][0])), visible=True),  # errors 1, 3, 9, 27
        Case(OUTSIDE, (UNIT, float(BALLOONING.inputs["tau"][1])), visible=True),
        Case(OUTSIDE, (CUBIC_BOXES, -0.5), visible=True),
        Case(OUTSIDE, (CUBIC_BOXES, 1.5), visible=True),
        Case(EDGE, ([[[1.0, 2.0], [-1.0, 0.0]]], 0.3), visible=True),  # degree 0
        Case(EDGE, ([[[0.0, 1.0]], [[2.0, 4.0]]], 0.5), visible=True),
        Case(EDGE, (CUBIC_BOXES, 0.0), visible=True),
        Case(EDGE, (CUBIC_BOXES, 1.0), visible=True),
    ]
    for _ in range(14):
        tau = float(rng.uniform(0, 1)) if rng.uniform() < 0.7 else float(rng.uniform(-1.5, 2.5))
        cases.append(Case(RANDOM, (_random_boxes(rng, low=1), tau)))
    cases += [
        Case(BAD, ([[[1.0, 0.0]], [[0.0, 1.0]]], 0.5)),
        Case(BAD, (CUBIC_BOXES, [0.25, 0.5])),  # one parameter
        Case(BAD, (np.zeros((3, 2, 1)), 0.5)),
    ]
    return cases


# --- 12.hermite_interval -----------------------------------------------------------------------------


def _hermite_args(name):
    return tuple(a.tolist() for a in notes_example(f"12.{name}").args("derivs0", "derivs1", "bound"))


def hermite_interval_cases(rng):
    e = math.e
    cases = [
        Case(EXAMPLE, _hermite_args("hermite_exp"), visible=True),  # Example 1 (12.65)
        Case(EXAMPLE, _hermite_args("hermite_sin"), visible=True),  # Example 2 (12.66)
        Case(EXAMPLE, _hermite_args("quarter_circle"), visible=True),  # a curve: boxes (5, 2, 2)
        Case(COURSE, _hermite_args("hermite_linear_exp"), visible=True),  # m = 1: -[f'']/4 swaps the ends
        Case(COURSE, _hermite_args("hermite_quintic_exp"), visible=True),  # m = 3: / 14400
        Case(EDGE, ([0.0, 1.0], [1.0, 1.0], [0.0, 0.0]), visible=True),  # f = t: no error at all
        Case(EDGE, ([2.0], [-1.0], [-3.0, 5.0]), visible=True),
        Case(EDGE, ([0.5, -1.0, 2.0, 0.0], [1.0, 0.0, -3.0, 1.0], [-10.0, 40.0]), visible=True),  # m = 4
        Case(EDGE, ([[1.0, 0.0, 2.0]], [[0.0, 1.0, 2.0]], [[-1.0, 1.0], [0.0, 2.0], [0.0, 0.0]]), visible=True),
        Case(INTERVALS, ([e, e], [e * e, e * e], [e, e * e]), {"interval": (1.0, 2.0)}, visible=True),  # eᵗ on [1, 2]
        Case(INTERVALS, ([0.0, 1.0], [0.0, -1.0], [-1.0, 1.0]), {"interval": (0.0, math.pi)}, visible=True),  # sin t
        Case(INTERVALS, ([1.0, 2.0, 0.5], [0.0, -1.0, 3.0], [-2.0, 6.0]), {"interval": (-1.0, 0.5)}, visible=True),
    ]
    for _ in range(14):
        m = int(rng.integers(1, 5))
        shape = (m,) if rng.uniform() < 0.6 else (m, int(rng.integers(1, 4)))
        lows = rng.uniform(-20, 20, shape[1:] or (1,))
        bound = np.column_stack([lows, lows + rng.exponential(10, lows.shape)])
        args = (rng.uniform(-3, 3, shape), rng.uniform(-3, 3, shape), bound[0] if len(shape) == 1 else bound)
        kwargs = {"interval": tuple(np.sort(rng.uniform(-2, 2, 2)))} if rng.uniform() < 0.3 else {}
        cases.append(Case(RANDOM, args, kwargs))
    cases += [
        Case(BAD, ([1.0, 1.0], [e], [1.0, e])),  # as many derivatives at each end
        Case(BAD, ([1.0, 1.0], [e, e], [e, 1.0])),  # lo > hi
        Case(BAD, ([[1.0, 0.0]], [[0.0, 1.0]], [0.0, 1.0])),  # a curve needs one bound per coordinate
        Case(BAD, ([], [], [0.0, 1.0])),
        Case(BAD, ([1.0, 1.0], [e, e], [1.0, e]), {"interval": (1.0, 0.0)}),
    ]
    return cases


# --- 12.derivative_bounds ----------------------------------------------------------------------------


def derivative_bounds_cases(rng):
    example = notes_example("12.derivative_bounds")
    quintic = example.inputs["coeffs"].tolist()
    cases = [
        Case(COURSE, (quintic, 4), visible=True),  # [-180, 390]
        Case(COURSE, (quintic, 1), visible=True),
        Case(COURSE, (quintic, 5), visible=True),  # the n-th derivative is a constant
        Case(EDGE, (quintic, 0), visible=True),  # the convex hull: [min, max] of the coefficients
        Case(EDGE, (quintic, 6), visible=True),  # beyond the degree: [0, 0]
        Case(EDGE, ([2.5], 0), visible=True),
        Case(EDGE, ([2.5], 1), visible=True),
        Case(EDGE, ([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]], 2), visible=True),  # a curve: (d, 2)
        Case(EDGE, ([[0.0, 0.0, 1.0], [1.0, -2.0, 1.0], [3.0, 2.0, 1.0]], 1), visible=True),
    ]
    for _ in range(14):
        n = int(rng.integers(1, 8))
        shape = (n + 1,) if rng.uniform() < 0.6 else (n + 1, int(rng.integers(1, 4)))
        cases.append(Case(RANDOM, (rng.uniform(-3, 3, shape), int(rng.integers(0, n + 2)))))
    cases += [
        Case(BAD, (quintic, -1)),
        Case(BAD, (quintic, 1.5)),  # an order is an integer
        Case(BAD, ([], 1)),
        Case(BAD, ([0.0, float("inf")], 1)),
    ]
    return cases


EXERCISES = [
    ClassExercise(
        id="12.Interval",
        reference=ib.interval_expression,
        cases=interval_cases,
        compare=close(1e-12, 1e-12),
        hint="[a, b] - [c, d] = [a - d, b - c]; a product is the min and max of the four products ac, ad, bc, bd; "
        "a quotient the min and max of a/c, a/d, b/c, b/d, refused with a ValueError when c <= 0 <= d. Numbers "
        "are degenerate intervals [x, x], on either side (__radd__, __rsub__, __rmul__, __rtruediv__).",
        rules={
            EDGE: "`+`, `-`, `*`, `/` combine an `Interval` with another `Interval`",
            "numbers on either side": "**or with a number on either side**: a number $x$ is the degenerate interval "
                "$[x,x]$",
            BAD: "Dividing by an interval that contains 0 (also as an end, and the number 0) raises a `ValueError`.",
        },
    ),
    Exercise(
        id="12.interval_de_casteljau",
        reference=ib.interval_de_casteljau,
        cases=interval_de_casteljau_cases,
        compare=close(1e-9, 1e-9),
        hint="In centred form the affine map (1-t)[P0] + t[P1] has centre (1-t)c0 + t c1 and error "
        "|1-t| e0 + |t| e1 for every real t: run the triangle on centres and errors, then lo = c - e, hi = c + e.",
        rules={
            EDGE: "`boxes`: shape `(n+1, d, 2)`, any degree $n\\ge0$ and dimension $d\\ge1$; `boxes[k, j] = (lo, "
                "hi)`.",
            OUTSIDE: "Any real `t`: the tests use values from $-1.5$ to $3$.",
            SHAPES: "`t`: a number, giving shape `(d, 2)`, or a 1-D array of k numbers, giving `(k, d, 2)` (also "
                "for k = 1 and k = 0).",
            BAD: "Raise a `ValueError` if a box has `lo > hi`, if `boxes` does not have the shape `(n+1, d, 2)` "
                "with at least one control point, if `t` has two or more dimensions, or if an input is NaN or "
                "infinite.",
        },
    ),
    Exercise(
        id="12.error_curve",
        reference=ib.error_curve,
        cases=error_curve_cases,
        compare=close(1e-9, 1e-9),
        hint="Σ e_k |B_k^n(t)|: the absolute value matters outside [0, 1], where the B_k^n(t) change sign "
        "with k. Reject negative errors with a ValueError.",
        rules={
            OUTSIDE: "Any real `t`.",
            EDGE: "The value is the **half**-width of the box $[\\mathbf P](t)$, not its width.",
            SHAPES: "`errors`: shape `(n+1, d)`, giving `(d,)` for a number t and `(k, d)` for k values, or shape "
                "`(n+1,)`, giving a number (a `float`) for a number t and `(k,)` for k values.",
            BAD: "Raise a `ValueError` if an error is negative, if `errors` is not of shape `(n+1,)` or `(n+1, d)`, "
                "if `t` has two or more dimensions, or for NaN and infinities.",
        },
    ),
    Exercise(
        id="12.interval_subdivide",
        reference=ib.interval_subdivide,
        cases=interval_subdivide_cases,
        compare=close(1e-9, 1e-9),
        hint="The left piece is the left edge of the interval de Casteljau triangle from the top, the right "
        "piece the right edge from the bottom up (starting at [P](t)); errors combine as |1-t| e_i + |t| e_(i+1).",
        rules={
            OUTSIDE: "`t`: one real number (any, also outside $[0,1]$).",
            EDGE: "`boxes`: shape `(n+1, d, 2)`, $n\\ge0$",
            BAD: "Raise a `ValueError` for boxes with lo > hi or of the wrong shape, and if `t` is not a single "
                "number.",
        },
    ),
    Exercise(
        id="12.hermite_interval",
        reference=ib.hermite_interval,
        cases=hermite_interval_cases,
        compare=close(1e-9, 1e-9),
        hint="Raise the Hermite interpolant of degree 2m-1 to degree 2m, then add (-1)^m [f_min, f_max] / "
        "((2m)! C(2m, m)) to the middle coefficient only (swap the ends when the factor is negative). On [a, b] "
        "the i-th derivatives scale by (b-a)^i and the bound by (b-a)^(2m).",
        rules={
            EDGE: "`derivs0`, `derivs1`: $f,f',\\dots,f^{(m-1)}$ at the two ends, shape `(m,)` ($m\\ge1$) for a "
                "function, or `(m, d)` for a curve (one column per coordinate).",
            INTERVALS: "`interval=(a, b)`: the data are derivatives with respect to $t$ at $t=a$ and $t=b$, and the "
                "result is in the Bernstein basis of $[a,b]$.",
            BAD: "Raise a `ValueError` if `derivs0` and `derivs1` differ in shape or are empty, if `bound` has the "
                "wrong shape or lo > hi, if `interval` is not `(a, b)` with `a < b`, and for NaN and infinities.",
        },
    ),
    Exercise(
        id="12.derivative_bounds",
        reference=ib.derivative_bounds,
        cases=derivative_bounds_cases,
        compare=close(1e-9, 1e-9),
        hint="f^(r) = n!/(n-r)! Σ Δ^r p_k B_k^(n-r): its bounds are n!/(n-r)! times the min and max of the r-th "
        "forward differences, per coordinate (columns). For r > n the derivative is 0.",
        rules={
            EDGE: "`r`: an integer $\\ge0$; `r = 0` bounds $f$ itself, and for `r > n` the derivative is $0$: `[0, "
                "0]`.",
            BAD: "Raise a `ValueError` (or `TypeError`) if `r` is negative or not an integer, if `coeffs` is empty "
                "or of the wrong shape, and for NaN and infinities.",
        },
    ),
]
