"""Hidden grading suite of chapter 10: polynomial interpolation.

Fixed cases reuse the notes' worked examples, read from
cagd_course/examples/ch10.toml: the cubic through (0, 0), (2, 2), (0, 3), (2, 4)
at t = 0, 1/4, 3/4, 1 (§10.1-10.2), the cubic with P(0), P(1), P(3), P(4) and
its value at 2 (§10.3-10.4), the nine nodes of Figure 10.5 (§10.6), and the
course's own flattening and Hermite examples (the Hermite cubic also in Newton
form on the repeated nodes 0, 0, 1, 1, §10.7.2). Edge cases probe one and two
nodes, unsorted and unit-spaced nodes, scalar values instead of points,
parameters at the nodes and outside their range, and several dimensions; the
random cases come from the generator the grader passes in.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close, exact
from cagd_ref import interpolation

NOTES = "notes example"
COURSE = "course example"
EDGE = "edge cases"
SHAPES = "scalar vs array t"
VALUES = "scalar values"
RANDOM = "random"
BAD = "bad input"

CUBIC = notes_example("10.cubic_power")  # §10.1: nodes 0, 1/4, 3/4, 1
NEWTON = notes_example("10.newton")  # §10.3: nodes 0, 1, 3, 4
FLATTENING = notes_example("10.flattening")
HERMITE = notes_example("10.hermite")
SPACE_TS = [2.0, -1.0, 0.5, 3.0, 1.0]  # unsorted on purpose
SPACE = [(0.0, 1.0, 2.0), (1.0, -1.0, 0.5), (2.0, 2.0, -1.0), (-1.0, 0.0, 1.0), (0.5, 3.0, 0.0)]
UNIT_TS = [0.0, 1.0, 2.0, 3.0]  # unit spacing: a wrong denominator t_(i+1) - t_i goes unnoticed here
UNIT_VALUES = [(1.0, 0.0), (2.0, 1.0), (4.0, 4.0), (8.0, 9.0)]


def _data(rng, low=1, high=8, dims=(1, 2, 3), scalar_chance=0.2):
    """Distinct nodes in random order, at least 0.15 apart, and random data (count, d) or (count,)."""
    count = int(rng.integers(low, high + 1))
    ts = rng.permutation(np.sort(rng.uniform(-2, 2, count)) + 0.15 * np.arange(count))
    shape = (count,) if rng.uniform() < scalar_chance else (count, int(rng.choice(dims)))
    return ts, rng.uniform(-5, 5, shape)


def _parameters(rng, ts, k=None):
    """One number (a third of the time) or k parameters over the nodes' range and a little beyond."""
    lo, hi = float(np.min(ts)) - 0.3, float(np.max(ts)) + 0.3
    if rng.uniform() < 1 / 3:
        return float(rng.uniform(lo, hi))
    return np.sort(rng.uniform(lo, hi, int(rng.integers(1, 9)) if k is None else k))


# --- 10.lagrange_eval and 10.neville: the same arguments, the same answers -----------------------------


def evaluation_cases(rng):
    ts, points = CUBIC.args("ts", "points")
    nts, npoints, tau = NEWTON.args("ts", "points", "tau")
    cases = [
        Case(NOTES, (ts, points, 0.5), visible=True),
        Case(NOTES, (ts, points, np.linspace(0.0, 1.0, 9)), visible=True),
        Case(NOTES, (nts, npoints, tau), visible=True),
        Case(NOTES, (nts, npoints, [0.0, 1.0, 2.0, 3.0, 4.0]), visible=True),  # at the nodes: the data
        Case(EDGE, (nts, npoints, [-1.0, 5.0]), visible=True),  # outside the nodes' range
        Case(EDGE, ([0.0, 1.0], [(1.0, 2.0), (3.0, -2.0)], [0.25, 2.0]), visible=True),  # two nodes: a line
        Case(EDGE, ([1.5], [(4.0, 5.0)], [0.0, 1.5, 9.0]), visible=True),  # one node: a constant
        Case(EDGE, (SPACE_TS, SPACE, [0.0, 0.5, 2.5]), visible=True),  # unsorted nodes, 3-D
        Case(EDGE, ([10.0, 20.0, 40.0], [(1.0,), (3.0,), (2.0,)], 30.0), visible=True),  # nodes far from [0, 1]
        Case(SHAPES, (ts, points, np.array([0.3]))),
        Case(SHAPES, (ts, points, np.array(0.3))),
        Case(SHAPES, (nts, npoints, [2.0, 2.0])),
        Case(VALUES, ([0.0, 0.5, 2.0, 3.0], [1.0, -1.0, 2.0, 0.5], 1.3), visible=True),  # scalar values -> float
        Case(VALUES, ([0.0, 0.5, 2.0, 3.0], [1.0, -1.0, 2.0, 0.5], [1.3, 2.5]), visible=True),
    ]
    for _ in range(14):
        rts, rpoints = _data(rng)
        cases.append(Case(RANDOM, (rts, rpoints, _parameters(rng, rts))))
    cases += [
        Case(BAD, ([0.0, 1.0, 1.0], [(0.0,), (1.0,), (2.0,)], 0.5)),  # a repeated node
        Case(BAD, ([0.0, 1.0], [(0.0,), (1.0,), (2.0,)], 0.5)),  # fewer nodes than points
        Case(BAD, (ts, points, [[0.5]])),  # t must be a number or 1-D
        Case(BAD, ([[0.0, 1.0]], [(0.0,), (1.0,)], 0.5)),  # nodes must be 1-D
    ]
    return cases


# --- 10.divided_differences ------------------------------------------------------------------------------


def divided_differences_cases(rng):
    ts, points = CUBIC.args("ts", "points")
    cases = [
        Case(NOTES, NEWTON.args("ts", "points"), visible=True),
        Case(NOTES, (ts, points), visible=True),
        Case(NOTES, (NEWTON.inputs["ts"].copy(), NEWTON.inputs["points"][:, 0].copy()), visible=True),  # x alone
        Case(EDGE, (UNIT_TS, UNIT_VALUES), visible=True),
        Case(EDGE, ([4.0, 0.0, 3.0, 1.0], [(7.0, 0.0), (0.0, 0.0), (5.0, 3.0), (3.0, 3.0)]), visible=True),  # reordered
        Case(EDGE, (SPACE_TS, SPACE), visible=True),
        Case(EDGE, ([2.0], [(3.0, -1.0)]), visible=True),  # one node: the value itself
        Case(EDGE, ([1.0, 3.0], [5.0, 9.0]), visible=True),  # two nodes: value and slope
        Case(EDGE, ([0.0, 0.5, 1.5, 2.0, 4.0], [1.0, 1.0, 1.0, 1.0, 1.0]), visible=True),  # a constant
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, _data(rng)))
    cases += [
        Case(BAD, ([0.0, 1.0, 0.0], [1.0, 2.0, 3.0])),  # a repeated node divides by zero
        Case(BAD, ([0.0, 1.0, 2.0], [1.0, 2.0])),
        Case(BAD, ([], [])),
    ]
    return cases


# --- 10.newton_eval --------------------------------------------------------------------------------------------


def _newton(ts, values):
    return np.asarray(ts, dtype=float), interpolation.divided_differences(ts, values)


def newton_eval_cases(rng):
    nts, coeffs = _newton(*NEWTON.args("ts", "points"))
    cts, ccoeffs = _newton(*CUBIC.args("ts", "points"))
    last_moved = nts.copy()
    last_moved[-1] = 99.0  # t_n never enters the Newton form
    cases = [
        Case(NOTES, (nts, coeffs, 2.0), visible=True),
        Case(NOTES, (nts, coeffs, [0.0, 1.0, 2.0, 3.0, 4.0]), visible=True),
        Case(NOTES, (cts, ccoeffs, np.linspace(0.0, 1.0, 5)), visible=True),
        Case(EDGE, (last_moved, coeffs, [2.0, 5.0]), visible=True),
        Case(EDGE, (nts[:-1], coeffs, [2.0, 5.0]), visible=True),  # only the n nodes that enter
        Case(EDGE, ([0.0, 0.0, 1.0, 1.0], [(1.0, 0.0), (2.0, 1.0), (-1.0, 3.0), (0.5, -2.0)], [0.0, 0.4, 1.0]),
             visible=True),  # repeated nodes are fine here
        # The chapter's Hermite cubic in Newton form (§10.7.2): nodes 0, 0, 1, 1 and its confluent differences.
        Case(COURSE, ([0.0, 0.0, 1.0, 1.0], [(0.0, 0.0), (3.0, 9.0), (1.0, -9.0), (-2.0, 0.0)], [0.0, 0.5, 1.0]),
             visible=True),
        Case(EDGE, ([3.0], [(4.0, -4.0)], [0.0, 7.0]), visible=True),  # degree 0
        Case(EDGE, (SPACE_TS, SPACE, [-2.0, 0.0, 4.0]), visible=True),
        Case(SHAPES, (nts, coeffs, np.array([2.0]))),
        Case(SHAPES, (nts, coeffs, np.array(2.0))),
        Case(VALUES, (nts, coeffs[:, 0].copy(), 2.0), visible=True),  # scalar coefficients -> float
        Case(VALUES, (nts, coeffs[:, 0].copy(), [1.5, 2.5]), visible=True),
    ]
    for _ in range(14):
        ts, values = _data(rng)
        ts, c = _newton(ts, values)
        if rng.uniform() < 0.25 and len(ts) > 1:
            ts = ts[:-1]
        cases.append(Case(RANDOM, (ts, c, _parameters(rng, ts))))
    cases += [
        Case(BAD, (nts[:2], coeffs, 2.0)),  # two nodes for four coefficients
        Case(BAD, (nts, coeffs, [[2.0]])),
        Case(BAD, (nts, np.zeros((4, 2, 2)), 2.0)),
    ]
    return cases


# --- 10.chebyshev_nodes ----------------------------------------------------------------------------------------


def chebyshev_cases(rng):
    figure = notes_example("10.node_polynomial")
    cases = [
        Case(NOTES, figure.args("a", "b", "count"), visible=True),  # Figure 10.5: nine nodes on [0, 1]
        Case(EDGE, (-1.0, 1.0, 1), visible=True),  # one node: the midpoint
        Case(EDGE, (-1.0, 1.0, 2), visible=True),
        Case(EDGE, (-1.0, 1.0, 3), visible=True),
        Case(EDGE, (-1.0, 1.0, 4), visible=True),
        Case(EDGE, (2.0, 7.0, 6), visible=True),
        Case(EDGE, (-3.0, -1.0, 5), visible=True),
        Case(EDGE, (0.0, 100.0, 30), visible=True),
    ]
    for _ in range(10):
        a = float(rng.uniform(-10, 10))
        cases.append(Case(RANDOM, (a, a + float(rng.uniform(0.1, 20)), int(rng.integers(1, 25)))))
    cases += [
        Case(BAD, (0.0, 1.0, 0)),
        Case(BAD, (1.0, 1.0, 3)),  # an empty interval
        Case(BAD, (2.0, 1.0, 3)),
        Case(BAD, (0.0, 1.0, 2.5)),  # a count must be an integer
        Case(BAD, (0.0, 1.0, 3.0)),  # ... and a float is no count, even a whole one
    ]
    return cases


# --- 10.bezier_segments_needed ----------------------------------------------------------------------------------


def segments_cases(rng):
    points, tolerances = FLATTENING.args("points", "tolerances")
    cases = [Case(NOTES, (points, float(tol)), visible=True) for tol in tolerances]
    cases += [
        Case(EDGE, (points, 10.0), visible=True),  # a loose tolerance: one chord is enough
        Case(EDGE, ([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (3.0, 3.0)], 1e-6), visible=True),  # a straight line
        Case(EDGE, ([(0.0, 0.0), (4.0, 1.0)], 1e-6), visible=True),  # degree 1
        Case(EDGE, ([(0.0, 0.0), (2.0, 4.0), (4.0, 0.0)], 0.05), visible=True),  # a parabola: L = (0, 16)
        Case(EDGE, ([(0.0, 0.0), (4.0, 2.0), (-1.0, 3.0), (5.0, -1.0), (2.0, 2.0)], 0.01), visible=True),  # degree 4
        Case(EDGE, ([(0.0, 0.0, 0.0), (1.0, 2.0, 3.0), (2.0, -1.0, 3.0), (3.0, 0.0, 0.0)], 0.02), visible=True),
        Case(EDGE, ([(0.0, 0.0), (0.0, 1.0), (1.0, 1.0), (-2.0, 0.0)], 0.001), visible=True),  # Δ²x = 1, -4: use |.|
    ]
    for _ in range(12):
        n = int(rng.integers(2, 7))
        curve = rng.uniform(-5, 5, (n + 1, int(rng.integers(2, 4))))
        cases.append(Case(RANDOM, (curve, float(10 ** rng.uniform(-4, 0)))))
    cases += [
        Case(BAD, (points, 0.0)),
        Case(BAD, (points, -0.1)),
        Case(BAD, ([0.0, 1.0, 2.0], 0.1)),  # points must be (n+1, d)
    ]
    return cases


# --- 10.hermite_to_bezier ------------------------------------------------------------------------------------


def hermite_cases(rng):
    cases = [
        Case(NOTES, HERMITE.args("p0", "p1", "d0", "d1"), visible=True),
        Case(EDGE, ([0.0, 0.0], [1.0, 0.0], [0.0, 0.0], [0.0, 0.0]), visible=True),  # no tangents
        Case(EDGE, ([0.0, 0.0], [3.0, 0.0], [3.0, 0.0], [3.0, 0.0]), visible=True),  # a line at unit speed
        Case(EDGE, ([1.0], [2.0], [6.0], [-3.0]), visible=True),  # one dimension
        Case(EDGE, ([0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [3.0, 0.0, 0.0], [0.0, 0.0, 3.0]), visible=True),
        Case(EDGE, ((1.0, 2.0), (1.0, 2.0), (6.0, 3.0), (-6.0, 3.0)), visible=True),  # a loop: same end points
    ]
    for _ in range(12):
        d = int(rng.integers(1, 4))
        cases.append(Case(RANDOM, tuple(rng.uniform(-5, 5, d) for _ in range(4))))
    cases += [
        Case(BAD, ([0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0], [1.0, 1.0])),  # dimensions differ
        Case(BAD, ([[0.0, 0.0]], [1.0, 0.0], [1.0, 1.0], [1.0, 1.0])),  # a point must be a vector
    ]
    return cases


# --- the suite ----------------------------------------------------------------------------------------------------


EXERCISES = [
    Exercise(
        id="10.lagrange_eval",
        reference=interpolation.lagrange_eval,
        cases=evaluation_cases,
        compare=close(1e-9, 1e-9),
        hint="P(t) = Σ P_i L_i(t) with L_i(t) = Π_{j≠i} (t - t_j)/(t_i - t_j). Build the (k, n+1) matrix of basis "
        "values (skip j = i, or the product is 0/0), then one matrix product with the points. A number t gives (d,), "
        "k values (k, d); scalar values (n+1,) give a float or (k,). Repeated nodes are a ValueError.",
        rules={
            EDGE: "One node gives the constant curve $\\mathbf P(t)=\\mathbf P_0$, two nodes the straight line "
                "through the two points.",
            SHAPES: "`t`: a number, giving shape `(d,)` (a `float` for scalar values), or a 1-D array of k numbers, "
                "giving `(k, d)` (or `(k,)`), also when k = 1.",
            VALUES: "`points`: shape `(n+1, d)`, or scalar values of shape `(n+1,)`.",
            BAD: "Raise a `ValueError` when a node repeats, when `ts` is not a non-empty 1-D array, when the number "
                "of points differs from the number of nodes, and when `t` has two or more dimensions.",
        },
    ),
    Exercise(
        id="10.divided_differences",
        reference=interpolation.divided_differences,
        cases=divided_differences_cases,
        compare=close(1e-9, 1e-9),
        hint="Column k of the table holds f[t_i..t_(i+k)] = (f[t_(i+1)..t_(i+k)] - f[t_i..t_(i+k-1)]) / "
        "(t_(i+k) - t_i): the denominator spans the whole range of k+1 nodes, not neighbouring ones. Return the "
        "first entry of every column, f[t_0], f[t_0,t_1], ..., f[t_0..t_n], in the shape of `values`.",
        rules={
            EDGE: "Return an array of the same shape as `values`: row $k$ is $f[t_0,\\dots,t_k]$ (row 0 is "
                "$\\mathbf P_0$).",
            BAD: "Raise a `ValueError` for a repeated node (the table would divide by zero), for an empty `ts`, and "
                "when the number of values differs from the number of nodes.",
        },
    ),
    Exercise(
        id="10.newton_eval",
        reference=interpolation.newton_eval,
        cases=newton_eval_cases,
        compare=close(1e-9, 1e-9),
        hint="Nest from the top: value = c_n, then value = c_k + (t - t_k) value for k = n-1 ... 0. The factor of "
        "level k uses t_k (t_n is never used, so ts may have n or n+1 entries, and nodes may repeat: nothing is "
        "divided by a difference of nodes).",
        rules={
            EDGE: "The last node $t_n$ never enters the formula, so accept both $n+1$ and $n$ nodes; the nodes need "
                "not be distinct here",
            SHAPES: "or a 1-D array of k numbers, giving `(k, d)` (or `(k,)`), also when k = 1.",
            VALUES: "a `float` for scalar coefficients of shape `(n+1,)`",
            BAD: "Raise a `ValueError` when `len(ts)` is neither `len(coeffs)` nor `len(coeffs) - 1`, when `coeffs` "
                "is not of shape `(n+1,)` or `(n+1, d)`, and when `t` has two or more dimensions.",
        },
    ),
    Exercise(
        id="10.neville",
        reference=interpolation.neville,
        cases=evaluation_cases,
        compare=close(1e-9, 1e-9),
        hint="Level r from level r-1: p_i = ((t_(i+r) - t) p_i + (t - t_i) p_(i+1)) / (t_(i+r) - t_i) for "
        "i = 0 ... n-r, where p_i on the right is the old value. After n levels one value is left: P(t). Work "
        "on an array (k, n+1, d) to handle k parameters at once.",
        rules={
            EDGE: "Parameters outside the nodes' range are allowed.",
            SHAPES: "`t` a number, giving shape `(d,)` (a `float` for scalar values), or a 1-D array of k numbers, "
                "giving `(k, d)` (or `(k,)`), also when k = 1.",
            VALUES: "`points` of shape `(n+1, d)`, or scalar values of shape `(n+1,)`",
            BAD: "Raise a `ValueError` when a node repeats, when `ts` is not a non-empty 1-D array, when the number "
                "of points differs from the number of nodes, and when `t` has two or more dimensions.",
        },
    ),
    Exercise(
        id="10.chebyshev_nodes",
        reference=interpolation.chebyshev_nodes,
        cases=chebyshev_cases,
        compare=close(1e-12, 1e-12),
        hint="N = n nodes (n counts nodes): (a+b)/2 + (b-a)/2 cos((2i+1)π/(2N)) for i = 0 ... N-1, in radians, "
        "returned in increasing order. n must be an integer >= 1 (an int or a NumPy integer; 3.0 is a float, "
        "not a count) and a < b.",
        rules={
            EDGE: "Return a 1-D array of shape `(n,)` in **increasing** order",
            BAD: "Raise a `ValueError` when $a\\ge b$ or `n` $<1$, and a `ValueError` or `TypeError` when `n` is not "
                "an integer (`3.0` included).",
        },
    ),
    Exercise(
        id="10.bezier_segments_needed",
        reference=interpolation.bezier_segments_needed,
        cases=segments_cases,
        compare=exact(),
        hint="L_c = n(n-1) max_i |c_(i+2) - 2c_(i+1) + c_i| for each coordinate c (absolute values of second "
        "differences); m = ceil(sqrt(L / (8 tol))) with L = sqrt(L_x² + L_y² + ...), the Euclidean length of "
        "(L_x, L_y, ...), and at least 1. Return an int.",
        rules={
            EDGE: "control points with zero second differences need one chord",
            BAD: "raise a `ValueError` for `tol <= 0` and for `points` that are not a 2-D array.",
        },
    ),
    Exercise(
        id="10.hermite_to_bezier",
        reference=interpolation.hermite_to_bezier,
        cases=hermite_cases,
        compare=close(1e-12, 1e-12),
        hint="A cubic Bézier curve has P'(0) = 3(P1 - P0) and P'(1) = 3(P3 - P2): return the rows p0, p0 + d0/3, "
        "p1 - d1/3, p1 as an array (4, d).",
        rules={
            EDGE: "Each is a vector of shape `(d,)` (a list or tuple is fine), all of one dimension d.",
            BAD: "Raise a `ValueError` when the four vectors differ in dimension or one of them is not 1-D.",
        },
    ),
]
