"""Hidden grading suite of chapter 7: curve intersection.

Fixed cases reuse the notes' worked examples (read from
cagd_course/examples/ch07.toml): the meet of (2, 1, -7) and (-1, -1, 5), the
parallel lines 3x + 4y + 2 = 0 and 3x + 4y + 3 = 0, the curve and the circle of
§7.3, the rational curve and the parabola, the first clip (-5, -1, 2, 3) with
the band [-2, 1], the rational quartic of §7.7.7 and its clips against Lmin and
Lmax (20/167, 107/132), and the course's curves that reproduce the notes'
figures. Edge cases probe what the notes leave open (parallel lines, control
points inside or touching the band, arches, shared end points, split points,
tangencies, overlaps); random cases come from the generator the grader passes in.
A homogeneous point is compared up to its scale; a clip that keeps nothing is None.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, Raises, close
from cagd_ref import intersection

NOTES = "notes example"
EDGE = "edge cases"
PARALLEL = "parallel lines"
CURVES = "curves of the notes' figures"
ENDS = "shared end points and split points"
TANGENT = "tangencies"
RATIONAL = "rational curves"
RANDOM = "random"
BAD = "bad input"


def _example(name: str):
    return notes_example(f"07.{name}")


def _unit(rng, size):
    return rng.uniform(-1.0, 1.0, size)


# --- comparisons -----------------------------------------------------------------------------------


def projective(expected, received) -> str | None:
    """Homogeneous points: the same point up to a nonzero factor, and W exactly 0 (to rounding) at infinity."""
    if isinstance(expected, Raises) or isinstance(received, Raises):
        return close()(expected, received)
    try:
        got = np.asarray(received, dtype=float)
    except (TypeError, ValueError):
        return f"expected a homogeneous point (X, Y, W), got {type(received).__name__}"
    if got.shape != (3,):
        return f"expected a homogeneous point of shape (3,), got shape {got.shape}"
    if not np.all(np.isfinite(got)) or not np.any(got):
        return f"expected a finite nonzero homogeneous point, got {got.tolist()}"
    e = np.asarray(expected, dtype=float)
    if np.linalg.norm(np.cross(e, got)) > 1e-9 * np.linalg.norm(e) * np.linalg.norm(got):
        return f"expected the point {e.tolist()} (or any nonzero multiple), got {got.tolist()}"
    if e[2] == 0 and abs(got[2]) > 1e-12 * np.linalg.norm(got):
        return f"parallel lines meet at infinity, so W must be 0; got {got.tolist()}"
    return None


def range_or_none(tolerance: float = 1e-9):
    """A clip: a pair (t_lo, t_hi) within tolerance, or None when nothing is left."""
    numbers = close(tolerance, tolerance)

    def compare(expected, received) -> str | None:
        if expected is None:
            return None if received is None else f"expected None (the hull misses the band), got {received!r}"[:200]
        if received is None and not isinstance(expected, Raises):
            return f"expected the range {tuple(round(v, 10) for v in expected)}, got None"
        return numbers(tuple(expected) if not isinstance(expected, Raises) else expected,
                       tuple(received) if isinstance(received, (list, tuple, np.ndarray)) else received)

    return compare


def intersections(tolerance: float = 1e-6):
    """An array (k, 2) of (t, u) within tolerance; for curves that overlap, a ValueError or a RuntimeError."""
    numbers = close(0.0, tolerance)

    def compare(expected, received) -> str | None:
        if isinstance(expected, Raises) and isinstance(received, Raises) and received.name == "RuntimeError":
            return None
        if isinstance(expected, np.ndarray) and not isinstance(received, Raises):
            try:
                got = np.asarray(received, dtype=float)
            except (TypeError, ValueError):
                return f"expected an array of shape {expected.shape}, got {type(received).__name__}"
            if got.shape == expected.shape and len(got) > 1:
                order = np.lexsort((got[:, 1], got[:, 0]))
                if not np.array_equal(order, np.arange(len(got))):
                    return "the intersections must be sorted by t, then by u"
            if got.shape != expected.shape:
                return (f"expected {len(expected)} intersection(s), shape {expected.shape}, got shape {got.shape}: "
                        f"{np.round(got, 6).tolist()}"[:300])
        return numbers(expected, received)

    return compare


# --- 07.line_intersection ---------------------------------------------------------------------------


def line_intersection_cases(rng):
    meet, parallel = _example("meet"), _example("parallel")
    cases = [
        Case(NOTES, meet.args("l1", "l2"), visible=True),
        Case(NOTES, parallel.args("l1", "l2"), visible=True),
        Case(EDGE, ([1.0, 0.0, -2.0], [0.0, 1.0, -3.0]), visible=True),  # x = 2 and y = 3
        Case(EDGE, ([1.0, -1.0, 0.0], [1.0, 1.0, 0.0]), visible=True),  # through the origin: (0, 0, W)
        Case(EDGE, ([0.0, 0.0, 1.0], [3.0, 4.0, 2.0]), visible=True),  # the line at infinity
        Case(PARALLEL, ([1.0, 0.0, 0.0], [2.0, 0.0, 5.0]), visible=True),  # two vertical lines
        Case(PARALLEL, ([0.0, 3.0, 1.0], [0.0, -1.0, 7.0]), visible=True),
    ]
    for _ in range(6):
        direction = _unit(rng, 2)
        scale = float(rng.uniform(0.5, 3)) * rng.choice([-1, 1])
        cases.append(Case(PARALLEL, ([*direction, float(rng.uniform(-5, 5))],
                                     [*(scale * direction), float(rng.uniform(-5, 5))])))
    for _ in range(10):
        cases.append(Case(RANDOM, (rng.normal(size=3), rng.normal(size=3))))
    cases += [
        Case(BAD, ([1.0, 2.0, 3.0], [2.0, 4.0, 6.0])),  # the same line twice
        Case(BAD, ([0.1, 0.2, 0.3], [0.3, 0.6, 0.9])),  # the same line, up to rounding
        Case(BAD, ([0.0, 0.0, 0.0], [1.0, 2.0, 3.0])),
        Case(BAD, ([1.0, 2.0], [1.0, 2.0, 3.0])),
        Case(BAD, ([[1.0, 2.0, 3.0]], [1.0, 0.0, 0.0])),
    ]
    return cases


# --- 07.implicit_polynomial ------------------------------------------------------------------------------


def _implicit(rng, d):
    """Integer coefficients f[i, j] with i + j <= d, at least one of them of total degree d."""
    f = np.zeros((d + 1, d + 1))
    for i in range(d + 1):
        f[i, : d + 1 - i] = rng.integers(-4, 5, d + 1 - i)
    if not any(f[i, d - i] for i in range(d + 1)):
        f[d, 0] = 1.0
    return f


def implicit_polynomial_cases(rng):
    circle, parabola = _example("circle_curve"), _example("rational_parabola")
    cases = [
        Case(NOTES, circle.args("f", "x", "y"), visible=True),
        Case(NOTES, parabola.args("f", "x", "y", "w"), visible=True),
        Case(NOTES, parabola.args("f", "x", "y"), {"w": parabola.inputs["w"]}, visible=True),
        Case(EDGE, (circle.inputs["f"], [0.5], [0.5]), visible=True),  # a constant curve
        Case(EDGE, ([[0.0, 1.0], [1.0, 0.0]], [0.0, 1.0], [1.0, -1.0]), visible=True),  # a line: x + y
        Case(EDGE, ([[0.0, 0.0], [1.0, 0.0]], [1.0, 2.0, 3.0], [4.0]), visible=True),  # f = x, y unused
        Case(EDGE, ([[2.0, 0.0, 0.0]], [1.0, 1.0], [1.0, 1.0]), visible=True),  # a nonzero constant: degree 0
        Case(EDGE, ([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0]], [1.0, 1.0], [0.0, 1.0], [1.0, 1.0]), visible=True),  # y², W
        Case(EDGE, ([[0.0, 0.0], [0.0, 1.0]], [0.0, 1.0], [0.0, 0.0, 1.0], [2.0, 0.0, 1.0]), visible=True),  # xy
    ]
    for _ in range(14):
        d = int(rng.integers(1, 4))
        f = _implicit(rng, d)
        x, y = (rng.integers(-3, 4, int(rng.integers(1, 4))).astype(float) for _ in range(2))
        if rng.uniform() < 0.5:
            cases.append(Case(RANDOM, (f, x, y)))
        else:
            w = rng.integers(-3, 4, int(rng.integers(1, 4))).astype(float)
            w[0] = 1.0 + abs(w[0])
            cases.append(Case(RANDOM, (f, x, y, w)))
    cases += [
        Case(BAD, (np.zeros((3, 3)), [1.0, 2.0], [0.0, 1.0])),
        Case(BAD, ([1.0, 2.0, 3.0], [1.0, 2.0], [0.0, 1.0])),
        Case(BAD, (circle.inputs["f"], [[1.0, 2.0]], [0.0, 1.0])),
    ]
    return cases


# --- 07.fat_line -------------------------------------------------------------------------------------


def _curve(rng, low=1, high=6, scale=None):
    n = int(rng.integers(low, high + 1))
    return rng.uniform(-1, 1, (n + 1, 2)) * (scale if scale is not None else float(rng.uniform(0.1, 20)))


def fat_line_cases(rng):
    figure, quartic = _example("clip_curves"), _example("homogeneous_fat_line")
    cases = [
        Case(NOTES, (figure.inputs["q"],), visible=True),
        Case(NOTES, (quartic.inputs["points"],), visible=True),
        Case(NOTES, (figure.inputs["p"],), visible=True),
        Case(EDGE, ([(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)],), visible=True),  # an arch: [0, 2]
        Case(EDGE, ([(0.0, 0.0), (1.0, -2.0), (3.0, -2.0), (4.0, 0.0)],), visible=True),  # upside down: [-2, 0]
        Case(EDGE, ([(1.0, 1.0), (3.0, 2.0)],), visible=True),  # a segment: zero width
        Case(EDGE, ([(0.0, 0.0), (0.0, 5.0), (3.0, 5.0), (3.0, 0.0)],), visible=True),
        Case(EDGE, ([(0.0, 0.0), (2.0, 2.0), (4.0, 4.0)],), visible=True),  # a straight curve
        Case(EDGE, ([(5.0, 1.0), (0.0, 3.0), (-1.0, 0.0)],), visible=True),
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, (_curve(rng),)))
    cases += [
        Case(BAD, ([(0.0, 0.0), (1.0, 1.0), (0.0, 0.0)],)),  # P0 = Pn: no line through the end points
        Case(BAD, ([(1.0, 2.0)],)),
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)],)),
        Case(BAD, ([0.0, 1.0, 2.0],)),
    ]
    return cases


# --- 07.clip_range --------------------------------------------------------------------------------------


def clip_range_cases(rng):
    first = _example("first_clip")
    cases = [
        Case(NOTES, first.args("distances", "dmin", "dmax"), visible=True),
        Case(NOTES, ([-5.0, -1.0, 2.0, 3.0], -1.0, 2.0), visible=True),  # the labels read the other way round
        Case(EDGE, ([-5.0, -6.0, 3.0, 3.0], -2.0, 1.0), visible=True),  # the hull, not the polygon
        Case(EDGE, ([0.0, 5.0, 5.0, 5.0], -1.0, 1.0), visible=True),  # a control point inside the band
        Case(EDGE, ([-1.0, 1.0, -1.0], 1.0, 2.0), visible=True),  # a vertex touching the band
        Case(EDGE, ([4.0, 5.0, 3.0], -1.0, 1.0), visible=True),  # all above: None
        Case(EDGE, ([-4.0, -5.0, -3.0, -2.0], -1.0, 1.0), visible=True),  # all below: None
        Case(EDGE, ([0.5, -0.5, 0.2], -1.0, 1.0), visible=True),  # all inside
        Case(EDGE, ([0.5], -1.0, 1.0), visible=True),  # degree 0
        Case(EDGE, ([2.0], -1.0, 1.0), visible=True),
        Case(EDGE, ([-3.0, 3.0], -1.0, 1.0), visible=True),  # degree 1
        Case(EDGE, ([3.0, -3.0, 3.0, -3.0, 3.0], 0.0, 0.0), visible=True),  # a band of width zero
        Case(EDGE, ([-6.0, 2.0, -6.0, 2.0], -2.0, 1.0), visible=True),
    ]
    for _ in range(10):
        c = rng.integers(-6, 7, int(rng.integers(2, 7))).astype(float)
        low = float(rng.integers(-4, 3))
        cases.append(Case(RANDOM, (c, low, low + float(rng.integers(0, 4)))))
    for _ in range(10):
        c = rng.normal(size=int(rng.integers(2, 8))) * 3
        low, high = np.sort(rng.normal(size=2))
        cases.append(Case(RANDOM, (c, float(low), float(high))))
    cases += [
        Case(BAD, ([0.0, 1.0], 1.0, -1.0)),  # dmin > dmax
        Case(BAD, ([[0.0, 1.0], [1.0, 2.0]], -1.0, 1.0)),
        Case(BAD, ([], -1.0, 1.0)),
    ]
    return cases


# --- 07.clip_one_sided ----------------------------------------------------------------------------------


def _heights(values):
    """Points (i, e_i) with the line (0, 1, 0): the explicit points have exactly the heights e_i."""
    return ([0.0, 1.0, 0.0], np.column_stack([np.arange(len(values), dtype=float), values]))


def clip_one_sided_cases(rng):
    lmin, lmax, quartic = _example("clip_lmin"), _example("clip_lmax"), _example("homogeneous_fat_line")
    gap, figure = _example("v_rule_gap"), _example("clip_cases")
    points, weights = lmin.args("points", "weights")
    own_lmin, own_lmax = quartic.results["lmin"], quartic.results["lmax"]
    cases = [
        Case(NOTES, (lmin.inputs["line"], points, weights), visible=True),
        Case(NOTES, (lmax.inputs["line"], points, weights), visible=True),
        Case(NOTES, (own_lmin, *quartic.args("points", "weights")), visible=True),  # the curve in its own fat line
        Case(NOTES, (own_lmax, *quartic.args("points", "weights")), visible=True),
        Case(EDGE, _heights(gap.inputs["values"]), visible=True),  # the V rule stops short of the hull
        Case(EDGE, _heights(figure.inputs["everything"]), visible=True),
        Case(EDGE, _heights(figure.inputs["nothing"]), visible=True),
        Case(EDGE, _heights(figure.inputs["both_ends"]), visible=True),
        Case(EDGE, _heights([-1.0, 2.0]), visible=True),  # a line: one crossing
        Case(EDGE, _heights([0.0, -1.0, -1.0]), visible=True),  # E0 on the axis: no clip on the left
        Case(EDGE, _heights([-2.0, -1.0, 0.0]), visible=True),  # only the end point touches
        Case(EDGE, (lmin.inputs["line"], points), visible=True),  # weights None: a polynomial curve
    ]
    for _ in range(8):
        cases.append(Case(RANDOM, _heights(rng.normal(size=int(rng.integers(2, 7))))))
    for _ in range(8):
        pts = _curve(rng, 2, 5, scale=5.0)
        line = np.append(rng.normal(size=2), rng.normal() * 2)
        cases.append(Case(RANDOM, (line, pts, rng.uniform(0.2, 4.0, len(pts)))))
    cases += [
        Case(BAD, (lmin.inputs["line"], points, [1.0, -1.0, 2.0, 3.0, 3.0])),  # a negative weight
        Case(BAD, (lmin.inputs["line"], points, [1.0, 1.0, 2.0])),
        Case(BAD, ([0.0, 0.0, 0.0], points, weights)),
        Case(BAD, ([1.0, 2.0], points, weights)),
    ]
    return cases


# --- 07.intersect_curves ---------------------------------------------------------------------------------


def intersect_curves_cases(rng):
    figure, five, arc = _example("clip_curves"), _example("five_intersections"), _example("rational_clip")
    cubic = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)]
    loop = [(0.0, 0.0), (3.0, 3.0), (-3.0, 3.0), (0.0, 0.0)]
    cases = [
        Case(NOTES, figure.args("p", "q"), visible=True),
        Case(NOTES, five.args("p", "q"), visible=True),
        Case(NOTES, five.args("q", "p"), visible=True),
        Case(CURVES, _example("perpendicular").args("p", "q"), visible=True),
        Case(CURVES, ([(0.0, 0.0), (1.0, 1.0)], [(0.0, 1.0), (1.0, 0.0)]), visible=True),  # two lines
        Case(CURVES, ([(0.0, 0.0), (1.0, 0.0)], [(0.0, 1.0), (1.0, 1.0)]), visible=True),  # parallel: none
        Case(CURVES, (cubic, [(10.0, 0.0), (11.0, 1.0), (12.0, 0.0)]), visible=True),  # far apart: none
        Case(CURVES, (loop, [(-2.0, 1.0), (2.0, 1.5)]), visible=True),  # a closed loop, P0 = Pn
        Case(ENDS, (cubic, [(4.0, 0.0), (5.0, 3.0), (6.0, -1.0)]), visible=True),  # P(1) = Q(0)
        Case(ENDS, (cubic, [(6.0, 1.0), (5.0, -2.0), (0.0, 0.0)]), visible=True),  # P(0) = Q(1)
        Case(ENDS, (loop, [(0.0, 0.0), (1.0, -1.0)]), visible=True),  # both ends of the loop
        Case(ENDS, ([(0.0, 0.0), (2.0, 4.0), (4.0, 0.0)], [(0.0, 2.0), (4.0, 2.0)]), visible=True),  # at t = 1/4, 3/4
        Case(ENDS, ([(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)], [(1.0, -1.0), (1.0, 1.0)]), visible=True),  # at t = u = 1/2
        Case(TANGENT, ([(0.0, 1.0), (0.5, -1.0), (1.0, 1.0)], [(0.0, 0.0), (1.0, 0.0)]), visible=True),
        Case(TANGENT, ([(-1.0, 1.0), (0.0, -1.0), (1.0, 1.0)], [(-1.0, 2.0), (0.0, -2.0), (1.0, 2.0)]), visible=True),
        # Overlapping curves have no isolated intersections: refused (the statement says so), shown to students.
        Case(BAD, (cubic, cubic), visible=True),  # the same curve twice
        Case(BAD, ([(0.0, 0.0), (2.0, 0.0)], [(1.0, 0.0), (3.0, 0.0)]), visible=True),  # collinear overlap
        Case(RATIONAL, arc.args("p", "q"), {"p_weights": arc.inputs["p_weights"]}, visible=True),
        Case(RATIONAL, arc.args("q", "p"), {"q_weights": arc.inputs["p_weights"]}, visible=True),
        Case(RATIONAL, (arc.inputs["p"], [(0.0, 0.0), (1.5, 1.5)]),
             {"p_weights": arc.inputs["p_weights"]}, visible=True),
    ]
    for _ in range(3):
        q = rng.uniform(-0.2, 1.3, (4, 2))
        cases.append(Case(RATIONAL, (arc.inputs["p"], q), {"p_weights": arc.inputs["p_weights"],
                                                          "q_weights": rng.uniform(0.5, 2.0, 4)}))
    for _ in range(10):
        cases.append(Case(RANDOM, (rng.uniform(-1, 1, (4, 2)), rng.uniform(-1, 1, (4, 2)))))
    for _ in range(6):
        cases.append(Case(RANDOM, (_curve(rng, 1, 5), _curve(rng, 1, 5))))
    cases += [
        Case(BAD, ([(0.0, 0.0)], cubic)),  # a single point is no curve
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)], cubic)),
        Case(BAD, (cubic, [(0.0, 1.0), (1.0, 0.0)]), {"q_weights": [1.0, -1.0]}),
        Case(BAD, (cubic, [(0.0, 1.0), (1.0, 0.0)]), {"tol": 0.0}),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="07.line_intersection",
        reference=intersection.line_intersection,
        cases=line_intersection_cases,
        compare=projective,
        hint="Return the cross product l1 × l2 itself, without dividing by W: parallel lines give W = 0. "
        "Raise a ValueError when |l1 × l2| <= 1e-12 |l1| |l2| (the same line) or a line is (0, 0, 0).",
        rules={
            EDGE: "The line at infinity $(0, 0, c)$, $c\\neq0$, is a line like any other: it meets $(a, b, c')$ at "
                "that line's point at infinity.",
            PARALLEL: "for parallel lines $W$ must come out as exactly 0 (to rounding).",
            BAD: "Raise a `ValueError` if a line does not have shape `(3,)`, if a line is $(0,0,0)$, and if the two "
                "lines coincide",
        },
    ),
    Exercise(
        id="07.implicit_polynomial",
        reference=intersection.implicit_polynomial,
        cases=implicit_polynomial_cases,
        compare=close(1e-9, 1e-9),
        hint="d is the largest i + j with f[i, j] != 0 and n = max(len(x), len(y), len(w)) - 1; add "
        "f[i, j] X^i Y^j W^(d-i-j) with np.convolve for the products, into an array of length d·n + 1 "
        "(ascending powers). w=None means W = 1.",
        rules={
            EDGE: "Keep the zeros at the end when the true degree is lower.",
            BAD: "Raise a `ValueError` if `f` is not 2-D or all its coefficients are 0, or if `x`, `y` or `w` is "
                "not 1-D.",
        },
    ),
    Exercise(
        id="07.fat_line",
        reference=intersection.fat_line,
        cases=fat_line_cases,
        compare=close(1e-9, 1e-9),
        hint="line = (x0, y0, 1) × (xn, yn, 1), divided by sqrt(a² + b²); d_i = a x_i + b y_i + c for every "
        "control point, the end points included, so dmin = min(d_i) <= 0 <= dmax = max(d_i).",
        rules={
            EDGE: "so $d_{min}\\le 0\\le d_{max}$ always (for a segment both are 0).",
            BAD: "Raise a `ValueError` if `points` does not have shape `(n+1, 2)` with $n\\ge1$, and if $\\mathbf "
                "P_0=\\mathbf P_n$ (then there is no line through the end points).",
        },
    ),
    Exercise(
        id="07.clip_range",
        reference=intersection.clip_range,
        cases=clip_range_cases,
        compare=range_or_none(1e-9),
        hint="The extremes over: t_i = i/n of each control point with dmin <= c_i <= dmax, and the crossings "
        "with d = dmin and d = dmax of the segments between every pair of control points (not only "
        "neighbours: that is the polygon, not the hull). None if there are none.",
        rules={
            EDGE: "Touching counts: a single point of contact gives `t_lo == t_hi`.",
            BAD: "Raise a `ValueError` if `dmin > dmax`, or if `coeffs` is not a non-empty 1-D array.",
        },
    ),
    Exercise(
        id="07.clip_one_sided",
        reference=intersection.clip_one_sided,
        cases=clip_one_sided_cases,
        compare=range_or_none(1e-9),
        hint="e_i = line · w_i (x_i, y_i, 1). None if every e_i < 0. If e_0 < 0, t_lo is the smallest positive "
        "crossing of the lines through (0, e_0) and (i/n, e_i), i >= 1, with the axis; if e_n < 0, t_hi is the "
        "largest crossing below 1 of the lines through (1, e_n) and (i/n, e_i), i < n.",
        rules={
            EDGE: "implement the rule, not the exact hull.",
            BAD: "Raise a `ValueError` for a line of the wrong shape or $(0,0,0)$, points of the wrong shape, and "
                "weights of the wrong length or not all positive.",
        },
    ),
    Exercise(
        id="07.intersect_curves",
        reference=intersection.intersect_curves,
        cases=intersect_curves_cases,
        compare=intersections(1e-6),
        hint="Keep a stack of pairs (P piece, [a, b], Q piece, [c, d]); clip each against the other's fat line, "
        "map the local range back to [a, b]; when a round keeps more than 80 % of both ranges, split the longer "
        "one; merge results that touch (split points). Pad the fat lines a little, cap the steps, and raise a "
        "ValueError (or RuntimeError) for curves that overlap.",
        rules={
            CURVES: "All pairs $(t, u)\\in[0,1]^2$ with $\\mathbf P(t)=\\mathbf Q(u)$",
            ENDS: "Every intersection exactly once: also one that lies on a parameter where you split a curve, one "
                "at shared end points",
            TANGENT: "and a **tangential** one, where the curves touch without crossing (a parabola on its tangent "
                "line).",
            RATIONAL: "`p_weights`, `q_weights`: `None` or positive weights.",
            BAD: "Raise a `ValueError` for shapes like these not being met, weights that are not positive, and "
                "`tol` outside $(0, 1)$.",
        },
    ),
]
