"""Hidden grading suite of chapter 6: B-spline curves in the notes' knot convention.

A degree-n B-spline with c control points has c + n - 1 knots (no dummy end
knots) and the domain [t_(n-1), t_(c-1)]. Fixed cases reuse the notes'
examples, read from cagd_course/examples/ch06.toml: the quartic Bézier curve
over [1, 5] with a knot inserted at 3, the cubic with knots 1 ... 8 and the
labels of its extraction, the Bézier end conditions [0,0,0,1,3,4,4,4], the
knots [0,0,0,2,3,4,5,5,5] with their Greville abscissae, the knot intervals of Figures 6.11-6.13
and the splitting of the interval 3 of Figures 6.15-6.17 (the figures' control
points are lost; the points are ours).
Edge cases probe t at knots and at both ends of the domain, multiple knots,
degree 1, non-uniform knots and closed curves; the random cases come from the
generator the grader passes in.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close
from cagd_ref import bspline, knot_intervals

NOTES = "notes example"
EDGE = "edge cases"
SHAPES = "scalar vs array t"
CLOSED = "closed curves"
ZERO_SPANS = "zero-length end spans"
RANDOM = "random"
BAD = "bad input"

# The notes' examples (cagd_course/examples/ch06.toml); the figures' control points are lost, SIX and SEVEN are ours.
QUARTIC_EXAMPLE = notes_example("06.quartic_insertion")  # §6.7, over [1, 5], with the knot 3 inserted
QUARTIC, QUARTIC_KNOTS, QUARTIC_T = QUARTIC_EXAMPLE.args("points", "knots", "t")
ONE_TO_EIGHT = notes_example("06.bspline_polar_labels").inputs["knots"]  # Figure 6.2.b: a cubic over [3, 6]
SIX = [(0.0, 0.0), (1.0, 3.0), (3.0, 4.0), (5.0, 3.5), (7.0, 1.0), (8.0, 0.0)]
END_CONDITIONS = notes_example("06.bezier_end_conditions").inputs["knots"]  # Figure 6.6.b: Bézier end conditions
END_INSERTION = notes_example("06.knot_insertion").inputs["t"]  # §6.7: the knot 2 goes into END_CONDITIONS
GREVILLE_KNOTS = notes_example("06.basis_functions").inputs["knots"]  # Figure 6.28
EXTRACTION = notes_example("06.bezier_extraction").results  # §6.3: the polar labels met on the way to [3, 4]
SEVEN = [(0.0, 0.0), (1.0, 2.0), (2.0, 3.0), (3.0, 1.0), (4.0, 2.0), (5.0, 4.0), (6.0, 1.0)]
DOUBLE = [0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 3.0, 3.0, 3.0]  # a cubic with a double knot at 2 (C1 there)
POLYLINE = [(0.0, 0.0), (2.0, 1.0), (3.0, 4.0), (1.0, 5.0)]  # degree 1 with knots 0, 1, 3, 4
LATE_END = [0.0, 0.0, 1.0, 2.0, 2.0, 3.0]  # quadratic, domain [0, 2]; the span after 2 lies outside
SPACE = [(0.0, 0.0, 0.0), (1.0, 2.0, 0.5), (3.0, -1.0, 2.0), (4.0, 1.0, -1.0), (2.0, 2.0, 2.0)]


def _spline(rng, low_degree=1, high_degree=5, dims=(1, 2, 3), zero_chance=0.25):
    """Random points (c, d) and knots with some multiple knots (at most n-fold, none at the domain's ends)."""
    n = int(rng.integers(low_degree, high_degree + 1))
    c = int(rng.integers(n + 1, n + 7))
    intervals = rng.uniform(0.25, 2.0, c + n - 2)
    run = 0
    for k in range(len(intervals)):
        protected = k in (n - 1, c - 2)
        run = run + 1 if rng.uniform() < zero_chance and run < n - 1 and not protected else 0
        intervals[k] = 0.0 if run else intervals[k]
    knots = float(rng.uniform(-3, 3)) + np.concatenate([[0.0], np.cumsum(intervals)])
    d = int(rng.choice(dims))
    return rng.uniform(-10, 10, (c, d)), knots, n


def _domain(knots, n):
    return knots[n - 1], knots[len(knots) - n]


def _inside(rng, knots, n, k=None):
    a, b = _domain(knots, n)
    k = int(rng.integers(1, 8)) if k is None else k
    return np.sort(rng.uniform(a, b, k))


# --- 06.de_boor ---------------------------------------------------------------------------


def de_boor_cases(rng):
    cases = [
        Case(NOTES, (QUARTIC, QUARTIC_KNOTS, QUARTIC_T), visible=True),
        Case(NOTES, (QUARTIC, QUARTIC_KNOTS, [1.0, 2.0, 3.0, 4.0, 5.0]), visible=True),
        # The quartic after the insertion is the same curve.
        Case(NOTES, (QUARTIC_EXAMPLE.results["points"], QUARTIC_EXAMPLE.results["knots"], np.linspace(1.0, 5.0, 9))),
        Case(NOTES, (SIX, ONE_TO_EIGHT, [3.0, 3.5, 4.0, 5.5, 6.0]), visible=True),
        Case(NOTES, (SIX, END_CONDITIONS, [0.0, 1.0, 2.0, 3.0, 4.0]), visible=True),
        Case(EDGE, (SIX, ONE_TO_EIGHT, 3.0), visible=True),  # the start of the domain
        Case(EDGE, (SIX, ONE_TO_EIGHT, 6.0), visible=True),  # the end of the domain
        Case(EDGE, (SIX, ONE_TO_EIGHT, 4.0), visible=True),  # an interior knot
        Case(EDGE, (SEVEN, DOUBLE, [1.5, 2.0, 2.5, 3.0]), visible=True),
        Case(EDGE, (POLYLINE, [0.0, 1.0, 3.0, 4.0], [0.0, 0.5, 1.0, 2.0, 3.0, 4.0]), visible=True),
        Case(EDGE, (SIX[:5], LATE_END, [0.0, 1.0, 1.5, 2.0]), visible=True),
        Case(EDGE, (SPACE, [0.0, 0.5, 2.0, 2.5, 4.0, 7.0], [0.5, 1.0, 4.0]), visible=True),
        Case(EDGE, ([[1.0], [5.0], [2.0], [4.0]], [0.0, 1.0, 1.0, 2.0, 3.0], 1.0), visible=True),
        Case(SHAPES, (SIX, ONE_TO_EIGHT, np.array([4.5]))),
        Case(SHAPES, (SIX, ONE_TO_EIGHT, np.array(4.5))),
        Case(SHAPES, (QUARTIC, QUARTIC_KNOTS, np.linspace(1, 5, 9))),
    ]
    for _ in range(14):
        points, knots, n = _spline(rng)
        t = float(_inside(rng, knots, n, 1)[0]) if rng.uniform() < 0.3 else _inside(rng, knots, n)
        cases.append(Case(RANDOM, (points, knots, t)))
    cases += [
        Case(BAD, (SIX, [1.0, 2.0, 3.0, 5.0, 4.0, 6.0, 7.0, 8.0], 4.5)),  # decreasing knots
        Case(BAD, (SIX, [1.0, 2.0, 3.0, 4.0, 5.0], 3.0)),  # fewer knots than points: degree < 1
        Case(BAD, (SIX, ONE_TO_EIGHT, 2.5)),  # before the domain
        Case(BAD, (SIX, ONE_TO_EIGHT, [4.0, 6.5])),  # after the domain
        Case(BAD, (SIX, ONE_TO_EIGHT, [[4.0]])),
        Case(BAD, ([1.0, 2.0, 3.0], [0.0, 1.0, 2.0, 3.0], 1.5)),
    ]
    return cases


# --- 06.insert_knot -----------------------------------------------------------------------


def insert_knot_cases(rng):
    cases = [
        Case(NOTES, (QUARTIC, QUARTIC_KNOTS, QUARTIC_T), visible=True),
        Case(NOTES, (SIX, END_CONDITIONS, END_INSERTION), visible=True),
        Case(NOTES, (SIX, ONE_TO_EIGHT, 4.5), visible=True),
        Case(NOTES, (SIX, ONE_TO_EIGHT, 4.0), visible=True),  # an existing knot becomes double
        Case(EDGE, (SIX, ONE_TO_EIGHT, 3.0), visible=True),  # the start of the domain
        Case(EDGE, (SIX, ONE_TO_EIGHT, 6.0), visible=True),  # the end of the domain
        Case(EDGE, (SEVEN, DOUBLE, 2.0), visible=True),  # double -> triple knot
        Case(EDGE, (SEVEN, DOUBLE, 0.25), visible=True),
        Case(EDGE, (POLYLINE, [0.0, 1.0, 3.0, 4.0], 2.0), visible=True),
        Case(EDGE, (SPACE, [0.0, 0.5, 2.0, 2.5, 4.0, 7.0], 3.0), visible=True),
        Case(EDGE, ([[1.0], [5.0], [2.0], [4.0]], [0.0, 1.0, 1.0, 2.0, 3.0], 1.5), visible=True),
    ]
    for _ in range(14):
        points, knots, n = _spline(rng)
        values, counts = np.unique(knots, return_counts=True)
        a, b = _domain(knots, n)
        existing = values[(counts < n) & (values >= a) & (values <= b)]
        use_knot = len(existing) and rng.uniform() < 0.3
        t = float(rng.choice(existing)) if use_knot else float(rng.uniform(a, b))
        cases.append(Case(RANDOM, (points, knots, t)))
    cases += [
        Case(BAD, (SIX, ONE_TO_EIGHT, 2.0)),  # outside the domain
        Case(BAD, (SIX, ONE_TO_EIGHT, [4.0, 5.0])),  # not one number
        Case(BAD, (SIX, [1.0, 2.0, 3.0, 5.0, 4.0, 6.0, 7.0, 8.0], 4.5)),
        Case(BAD, (SIX, [1.0, 2.0, 3.0, 4.0, 5.0], 3.0)),
        Case(BAD, (QUARTIC, QUARTIC_KNOTS, 5.0)),  # 5 already has multiplicity 4 = n
    ]
    return cases


# --- 06.bezier_segments ---------------------------------------------------------------------


def bezier_segments_cases(rng):
    cases = [
        Case(NOTES, (SIX, ONE_TO_EIGHT), visible=True),
        Case(NOTES, (SIX, END_CONDITIONS), visible=True),
        Case(NOTES, (QUARTIC, QUARTIC_KNOTS), visible=True),  # a Bézier curve is its own segment
        Case(NOTES, (QUARTIC_EXAMPLE.results["points"], QUARTIC_EXAMPLE.results["knots"]), visible=True),  # two halves
        Case(NOTES, (SEVEN, GREVILLE_KNOTS), visible=True),
        Case(EDGE, (SEVEN, DOUBLE), visible=True),  # a double knot
        Case(EDGE, (SEVEN, [0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 3.0, 3.0, 3.0]), visible=True),  # a triple knot (C0)
        Case(EDGE, (POLYLINE, [0.0, 1.0, 3.0, 4.0]), visible=True),  # degree 1: the edges
        Case(EDGE, (SIX[:5], LATE_END), visible=True),
        Case(EDGE, (SPACE, [0.0, 0.5, 2.0, 2.5, 4.0, 7.0]), visible=True),
        Case(EDGE, ([[1.0], [5.0], [2.0], [4.0]], [0.0, 1.0, 1.0, 2.0, 3.0]), visible=True),
    ]
    for _ in range(14):
        points, knots, _ = _spline(rng)
        cases.append(Case(RANDOM, (points, knots)))
    cases += [
        Case(BAD, (SIX, [1.0, 2.0, 3.0, 5.0, 4.0, 6.0, 7.0, 8.0])),
        Case(BAD, (SIX, [1.0, 2.0, 3.0, 4.0, 5.0])),
        Case(BAD, ([1.0, 2.0, 3.0], [0.0, 1.0, 2.0, 3.0])),
    ]
    return cases


# --- 06.blossom ---------------------------------------------------------------------------------


def _labels(points, knots, n):
    """The polar labels of the control points that act on a segment of positive length."""
    spans = bspline.bezier_segment_intervals(knots, n)
    a, b = _domain(knots, n)
    labels = [np.asarray(knots[i : i + n]) for i in range(len(points))]
    single = [u.min() == u.max() and a <= u.min() <= b for u in labels]
    return [u for u, one in zip(labels, single) if one or np.any((spans[:, 1] > u.min()) & (spans[:, 0] < u.max()))]


def blossom_cases(rng):
    cases = [
        Case(NOTES, (SIX, ONE_TO_EIGHT, EXTRACTION["acting_labels"][0]), visible=True),  # a control point's own label
        Case(NOTES, (SIX, ONE_TO_EIGHT, EXTRACTION["helper_labels"][0]), visible=True),  # the helpers of §6.3
        Case(NOTES, (SIX, ONE_TO_EIGHT, EXTRACTION["helper_labels"][1]), visible=True),
        Case(NOTES, (SIX, ONE_TO_EIGHT, EXTRACTION["bezier_labels"][2]), visible=True),  # Bézier points of [3, 4]
        Case(NOTES, (SIX, ONE_TO_EIGHT, EXTRACTION["bezier_labels"][0]), visible=True),
        Case(NOTES, (QUARTIC, QUARTIC_KNOTS, QUARTIC_EXAMPLE.results["new_labels"][2]), visible=True),
        Case(NOTES, (SIX, END_CONDITIONS, notes_example("06.knot_insertion").results["labels"][3]), visible=True),
        Case(EDGE, (SIX, ONE_TO_EIGHT, [3.75, 3.25, 3.5]), visible=True),  # unsorted, inside one span
        Case(EDGE, (SIX, ONE_TO_EIGHT, [3.5, 4.0, 4.5]), visible=True),  # over a shared simple knot
        Case(EDGE, (SIX, ONE_TO_EIGHT, [1.0, 2.0, 2.5]), visible=True),  # before the domain: the first segment
        Case(EDGE, (SIX, ONE_TO_EIGHT, [6.5, 7.0, 8.0]), visible=True),  # after it: the last segment
        Case(EDGE, (SEVEN, DOUBLE, [1.25, 1.75, 2.0]), visible=True),  # only one 2 at a double knot: the left span
        Case(EDGE, (SEVEN, DOUBLE, [2.0, 2.0, 2.5]), visible=True),
        Case(EDGE, (POLYLINE, [0.0, 1.0, 3.0, 4.0], [2.0]), visible=True),  # degree 1: a point on the polyline
        Case(EDGE, (SPACE, [0.0, 0.5, 2.0, 2.5, 4.0, 7.0], [2.5, 3.0]), visible=True),
        # A zero-length end span: the outermost control point belongs to no segment of positive length, and its
        # label, evaluated on the first (last) segment of positive length, is not that point.
        Case(ZERO_SPANS, (SIX, [0.0, 1.0, 2.0, 2.0, 3.0, 4.0, 5.0, 6.0], [0.0, 1.0, 2.0]), visible=True),
        Case(ZERO_SPANS, (SEVEN[:6], [0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 5.0, 6.0], [4.0, 5.0, 6.0]), visible=True),
        Case(ZERO_SPANS, (SEVEN[:6], [0.0, 1.0, 2.0, 2.0, 3.0, 4.0, 5.0, 6.0], [1.0, 2.0, 2.0]), visible=True),
    ]
    for _ in range(12):
        points, knots, n = _spline(rng)
        if rng.uniform() < 0.5:
            labels = _labels(points, knots, n)
            args = labels[int(rng.integers(len(labels)))]
        else:
            spans = bspline.bezier_segment_intervals(knots, n)
            lo, hi = spans[int(rng.integers(len(spans)))]
            args = rng.uniform(lo, hi, n)
        cases.append(Case(RANDOM, (points, knots, args)))
    cases += [
        Case(BAD, (SIX, ONE_TO_EIGHT, [3.5, 4.5])),  # a cubic blossom takes three arguments
        Case(BAD, (SIX, ONE_TO_EIGHT, [3.5, 4.5, 5.5])),  # three segments with no common knot: ambiguous
        Case(BAD, (SIX, ONE_TO_EIGHT, [0.0, 3.0, 4.0])),  # outside the knot vector
        Case(BAD, (SIX, [1.0, 2.0, 3.0, 5.0, 4.0, 6.0, 7.0, 8.0], [3.0, 4.0, 5.0])),
    ]
    return cases


# --- 06.bspline_basis ---------------------------------------------------------------------------


def bspline_basis_cases(rng):
    ts = np.linspace(0.0, 5.0, 11)
    cases = [
        Case(NOTES, (GREVILLE_KNOTS, 3, 3, ts), visible=True),
        Case(NOTES, (GREVILLE_KNOTS, 3, 1, ts), visible=True),
        Case(NOTES, (GREVILLE_KNOTS, 3, 0, 0.0), visible=True),
        Case(NOTES, (GREVILLE_KNOTS, 3, 6, 5.0), visible=True),  # the end of the domain
        Case(NOTES, (ONE_TO_EIGHT, 3, 2, np.linspace(3.0, 6.0, 7)), visible=True),
        Case(EDGE, ([0.0, 1.0, 3.0, 4.0], 1, 1, [0.0, 0.5, 1.0, 2.0, 3.0, 4.0]), visible=True),  # a hat
        Case(EDGE, (DOUBLE, 3, 3, np.linspace(0.0, 3.0, 13)), visible=True),
        Case(EDGE, (DOUBLE, 3, 4, 2.0), visible=True),
        Case(EDGE, (LATE_END, 2, 3, [0.0, 1.0, 2.0]), visible=True),
        Case(EDGE, (QUARTIC_KNOTS, 4, 2, [1.0, 3.0, 5.0]), visible=True),  # a Bernstein polynomial on [1, 5]
        Case(SHAPES, (GREVILLE_KNOTS, 3, 2, np.array([2.5]))),
        Case(SHAPES, (GREVILLE_KNOTS, 3, 2, np.array(2.5))),
        Case(SHAPES, (GREVILLE_KNOTS, 3, 2, 2.5)),
    ]
    for _ in range(14):
        points, knots, n = _spline(rng)
        i = int(rng.integers(len(points)))
        t = float(_inside(rng, knots, n, 1)[0]) if rng.uniform() < 0.3 else _inside(rng, knots, n)
        cases.append(Case(RANDOM, (knots, n, i, t)))
    cases += [
        Case(BAD, (GREVILLE_KNOTS, 3, 7, 1.0)),  # only 7 basis functions
        Case(BAD, (GREVILLE_KNOTS, 3, -1, 1.0)),
        Case(BAD, (GREVILLE_KNOTS, 3, 2, 5.5)),  # outside the domain
        Case(BAD, (GREVILLE_KNOTS, 0, 2, 1.0)),
        Case(BAD, ([0.0, 2.0, 1.0, 3.0, 4.0, 5.0], 2, 1, 2.5)),
    ]
    return cases


# --- 06.greville ----------------------------------------------------------------------------------


def greville_cases(rng):
    cases = [
        Case(NOTES, (GREVILLE_KNOTS, 3), visible=True),
        Case(NOTES, (ONE_TO_EIGHT, 3), visible=True),
        Case(NOTES, (END_CONDITIONS, 3), visible=True),
        Case(NOTES, (QUARTIC_KNOTS, 4), visible=True),
        Case(EDGE, ([0.0, 1.0, 3.0, 4.0], 1), visible=True),  # degree 1: the knots themselves
        Case(EDGE, (LATE_END, 2), visible=True),
        Case(EDGE, (DOUBLE, 3), visible=True),
        Case(EDGE, (ONE_TO_EIGHT, 2), visible=True),
        Case(EDGE, (ONE_TO_EIGHT, 4), visible=True),
    ]
    for _ in range(12):
        _, knots, n = _spline(rng)
        cases.append(Case(RANDOM, (knots, n)))
    cases += [
        Case(BAD, (GREVILLE_KNOTS, 0)),
        Case(BAD, ([0.0, 2.0, 1.0, 3.0, 4.0, 5.0], 2)),
        Case(BAD, ([0.0, 1.0, 2.0], 2)),  # fewer than 2n knots: not even one segment
    ]
    return cases


# --- 06.split_interval ------------------------------------------------------------------------------

FIGURE_6_11 = [(0.0, 0.0), (1.0, 2.0), (3.0, 3.0), (5.0, 2.5), (7.0, 0.5), (8.0, -1.0)]  # our points
FIGURE_6_11_INTERVALS = notes_example("06.figure_6_11").results["intervals"]
PENTAGON = [(0.0, 2.0), (2.0, 0.5), (1.5, -2.0), (-1.5, -2.0), (-2.0, 0.5)]  # our points
CLOSED_INTERVALS = notes_example("06.closed_intervals").inputs  # Figures 6.12 and 6.13
SPLITTING = notes_example("06.interval_splitting")  # Figures 6.15-6.17: split the interval 3 of 3, 1, 2, 2, 1


def _closed(rng):
    n = int(rng.integers(1, 4))
    c = int(rng.integers(n + 1, n + 6))
    return rng.uniform(-10, 10, (c, 2)), rng.uniform(0.25, 3.0, c), n


def split_interval_cases(rng):
    cases = [
        # Figure 6.11: split the interval 3 (between P3 and P4) into 1 and 2, and into halves.
        Case(NOTES, (FIGURE_6_11, FIGURE_6_11_INTERVALS, 4, SPLITTING.inputs["one_and_two"]), visible=True),
        Case(NOTES, (FIGURE_6_11, FIGURE_6_11_INTERVALS, 4, SPLITTING.inputs["halves"]), visible=True),
        # Figures 6.15-6.17: the same splits of the interval 3 of a closed cubic.
        Case(NOTES, (PENTAGON, *SPLITTING.args("intervals", "index", "one_and_two")), {"degree": 3}, visible=True),
        Case(NOTES, (PENTAGON, *SPLITTING.args("intervals", "index", "halves")), {"degree": 3}, visible=True),
        Case(EDGE, (FIGURE_6_11, FIGURE_6_11_INTERVALS, 2, 0.25), visible=True),  # the first splittable interval
        Case(EDGE, (FIGURE_6_11, FIGURE_6_11_INTERVALS, 3, 0.75), visible=True),
        Case(EDGE, (FIGURE_6_11, FIGURE_6_11_INTERVALS, 4, 0.9), visible=True),  # the last splittable interval
        Case(EDGE, (FIGURE_6_11, FIGURE_6_11_INTERVALS, 4, 0.0), visible=True),  # a zero interval (double knot)
        Case(EDGE, (FIGURE_6_11, FIGURE_6_11_INTERVALS, 4, 1.0), visible=True),
        Case(EDGE, (POLYLINE, [1.0, 2.0, 1.0], 1, 0.5), visible=True),  # degree 1: a new vertex on an edge
        Case(EDGE, (SIX[:5], [1.0, 2.0, 1.0, 3.0, 1.0], 2, 0.4), visible=True),  # quadratic
        Case(EDGE, (SPACE, [0.5, 1.5, 0.5, 1.5, 3.0], 2, 0.5), visible=True),
        Case(CLOSED, (PENTAGON, CLOSED_INTERVALS["longer"], 1, 1 / 3), {"degree": 3}, visible=True),
        Case(CLOSED, (PENTAGON, CLOSED_INTERVALS["longer"], 0, 0.5), {"degree": 3}, visible=True),
        Case(CLOSED, (PENTAGON, CLOSED_INTERVALS["longer"], 4, 0.5), {"degree": 3}, visible=True),  # wraps around
        Case(CLOSED, (PENTAGON, CLOSED_INTERVALS["uniform"], 2, 0.5), {"degree": 2}, visible=True),
        Case(CLOSED, (PENTAGON, CLOSED_INTERVALS["double_knot"], 1, 0.5), {"degree": 3}, visible=True),
        Case(CLOSED, (PENTAGON, [1.0, 2.0, 1.0, 2.0, 1.0], 3, 0.25), {"degree": 1}, visible=True),
    ]
    for _ in range(8):
        points, knots, n = _spline(rng, high_degree=4, zero_chance=0.0)
        intervals = np.diff(knots)
        index = int(rng.integers(n - 1, len(knots) - n))
        cases.append(Case(RANDOM, (points, intervals, index, float(rng.uniform(0.05, 0.95)))))
    for _ in range(6):
        points, intervals, n = _closed(rng)
        index = int(rng.integers(len(intervals)))
        cases.append(Case(RANDOM, (points, intervals, index, float(rng.uniform(0.05, 0.95))), {"degree": n}))
    cases += [
        Case(BAD, (FIGURE_6_11, FIGURE_6_11_INTERVALS, 0, 0.5)),  # an end-condition interval
        Case(BAD, (FIGURE_6_11, FIGURE_6_11_INTERVALS, 5, 0.5)),  # the other end's
        Case(BAD, (FIGURE_6_11, FIGURE_6_11_INTERVALS, 7, 0.5)),  # no such interval
        Case(BAD, (FIGURE_6_11, FIGURE_6_11_INTERVALS, 4, 1.5)),
        Case(BAD, (FIGURE_6_11, [1.0, 1.0, -1.0, 2.0, 3.0, 1.0, 1.0], 4, 0.5)),
        Case(BAD, (PENTAGON, CLOSED_INTERVALS["longer"][:4], 1, 0.5), {"degree": 3}),  # closed: one per point
        Case(BAD, (PENTAGON, CLOSED_INTERVALS["longer"], 5, 0.5), {"degree": 3}),
        Case(BAD, (PENTAGON, CLOSED_INTERVALS["longer"], -1, 0.5), {"degree": 3}),  # index does not wrap
        Case(BAD, (PENTAGON, CLOSED_INTERVALS["triple_knot"], 0, 0.0), {"degree": 3}),  # a fourfold knot
    ]
    return cases


EXERCISES = [
    Exercise(
        id="06.de_boor",
        reference=bspline.de_boor,
        cases=de_boor_cases,
        compare=close(1e-9, 1e-9),
        hint="The degree is len(knots) - len(points) + 1 and the domain [t_(n-1), t_(c-1)]. For t in the span "
        "[t_j, t_(j+1)) use P_(j-n+1) ... P_(j+1); at level r the point with index i is "
        "((t_(i+n-r) - t) P_(i-1) + (t - t_(i-1)) P_i) / (t_(i+n-r) - t_(i-1)). At the end of the domain use the "
        "last span of positive length.",
        rules={
            EDGE: "At a knot use the span to its right; at the end of the domain $t=t_{c-1}$ use the last span of "
                "positive length that ends there.",
            SHAPES: "`t`: a number in the domain $[t_{n-1},t_{c-1}]$, giving shape `(d,)`, or a 1-D array of k such "
                "numbers, giving `(k, d)`.",
            BAD: "Raise a `ValueError` if `points` is not two-dimensional, the knots decrease, there are fewer "
                "knots than points (degree below 1), `t` lies outside the domain, or `t` has two or more "
                "dimensions.",
        },
    ),
    Exercise(
        id="06.insert_knot",
        reference=bspline.insert_knot,
        cases=insert_knot_cases,
        compare=close(1e-9, 1e-9),
        hint="With t_j <= t < t_(j+1), the n-1 points P_(j-n+2) ... P_j are replaced by n new ones, "
        "Q_m = ((t_(m+n-1) - t) P_(m-1) + (t - t_(m-1)) P_m) / (t_(m+n-1) - t_(m-1)) for m = j-n+2 ... j+1; "
        "return (c+1 points, c+n knots).",
        rules={
            EDGE: "`t` may be anywhere in the domain, its two ends included, and may equal an existing knot.",
            BAD: "Raise a `ValueError` for `points` that are not two-dimensional, decreasing knots, or fewer knots "
                "than points (degree below 1), for a `t` outside the domain or not a single number, and when $t$ "
                "already appears $n$ times among the knots.",
        },
    ),
    Exercise(
        id="06.bezier_segments",
        reference=bspline.bezier_segments,
        cases=bezier_segments_cases,
        compare=close(1e-9, 1e-9),
        hint="Insert every distinct knot value of the domain [t_(n-1), t_(c-1)], its two ends included, until it "
        "appears n times; then each span [t_j, t_(j+1)] of positive length has the Bézier points P_(j-n+1) ... "
        "P_(j+1). Skip spans of length zero.",
        rules={
            EDGE: "Return an array of shape `(s, n+1, d)`, one Bézier curve per span of positive length, in order.",
            BAD: "Raise a `ValueError` for `points` that are not two-dimensional, decreasing knots, or fewer knots "
                "than points (degree below 1).",
        },
    ),
    Exercise(
        id="06.blossom",
        reference=bspline.blossom,
        cases=blossom_cases,
        compare=close(1e-9, 1e-9),
        hint="Pick the span of min(args) (as de_boor would for t = min(args), clipped into the domain) and run "
        "the de Boor triangle with the r-th argument at level r. Then compare with the other spans whose "
        "open interval meets [min(args), max(args)]: if their values differ, raise a ValueError.",
        rules={
            EDGE: "`args`: $n$ numbers, in any order, within $[t_0, t_{c+n-2}]$.",
            ZERO_SPANS: "the result is not that control point (the tests include this case)",
            BAD: "Raise a `ValueError` for `points` that are not two-dimensional, decreasing knots, or fewer knots "
                "than points (degree below 1), for a wrong number of arguments, for arguments outside "
                "$[t_0,t_{c+n-2}]$, and for ambiguous arguments.",
        },
    ),
    Exercise(
        id="06.bspline_basis",
        reference=bspline.bspline_basis,
        cases=bspline_basis_cases,
        compare=close(1e-9, 1e-12),
        hint="N_i is the B-spline with coefficient 1 at i and 0 elsewhere: run de_boor on those 1-D "
        "'points'. Or use Cox-de Boor on the knots padded with one extra end knot on each side, with 0/0 = 0. "
        "A number t gives a float, an array (k,).",
        rules={
            EDGE: "`knots`: the knot vector of a degree-`degree` spline, so there are `c = len(knots) - degree + 1` "
                "basis functions and $0\\le i<c$.",
            SHAPES: "a number gives a float, a 1-D array of k numbers an array of shape `(k,)`. A 0-d array counts "
                "as a number.",
            BAD: "Raise a `ValueError` for `degree < 1`, decreasing knots, fewer than `2 * degree` knots, `i` out "
                "of range and `t` outside the domain.",
        },
    ),
    Exercise(
        id="06.greville",
        reference=bspline.greville,
        cases=greville_cases,
        compare=close(1e-12, 1e-12),
        hint="One abscissa per control point: the average of the n knots of its polar label, "
        "(t_i + ... + t_(i+n-1)) / n, for i = 0 ... len(knots) - n.",
        rules={
            EDGE: "Repeated knots are allowed.",
            BAD: "Raise a `ValueError` for `degree < 1`, decreasing knots, or fewer than `2 * degree` knots.",
        },
    ),
    Exercise(
        id="06.split_interval",
        reference=knot_intervals.split_interval,
        cases=split_interval_cases,
        compare=close(1e-9, 1e-9),
        hint="Open curve: knots = cumulative sums of the intervals; insert the knot t_q + fraction d_q and "
        "return the differences of the new knots. Closed curve of degree n: P_i has the label "
        "P(t_(i+s), ..., t_(i+s+n-1)) with s = -((n-1)//2) on the periodic knots; only the n-1 points whose "
        "labels contain both ends of interval q are replaced (by n new ones).",
        rules={
            EDGE: "Only intervals of the domain can be split, $n-1\\le q\\le c-2$; the others hang past the ends of "
                "the polygon.",
            CLOSED: "one interval per control point; the knots and labels below run cyclically through the intervals",
            BAD: "Raise a `ValueError` for a negative interval, a wrong number of intervals, an `index` out of "
                "range (for closed curves $0\\le q<c$; for open curves, outside the domain), a `fraction` outside "
                "$[0,1]$, and a split that would make a knot appear more than $n$ times (for instance `fraction=0` "
                "next to a knot that already appears $n$ times).",
        },
    ),
]
