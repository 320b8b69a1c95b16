"""Unit tests of cagd_ref.knot_intervals: B-splines labelled with knot intervals (notes §6.13-6.14.2).

Open curves are checked against the knot-vector functions of cagd_ref.bspline
(and through them SciPy); closed curves against their unrolled open form and
the formulas the notes give for uniform and non-uniform cases.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.interpolate import BSpline

from cagd_course.examples import notes_example
from cagd_ref import bezier
from cagd_ref import bspline as b
from cagd_ref import knot_intervals as ki

DEGREES = range(1, 6)


def closed_curve(seed: int, n: int, count: int = 7, zeros: bool = False):
    rng = np.random.default_rng(100 * n + seed)
    d = rng.uniform(0.3, 3.0, count)
    if zeros:
        d[int(rng.integers(count))] = 0.0  # a double knot
    return rng.uniform(-5, 5, (count, 2)), d


def open_curve(seed: int, n: int):
    rng = np.random.default_rng(200 * n + seed)
    c = int(rng.integers(n + 2, n + 8))
    d = rng.uniform(0.3, 3.0, c + n - 2)
    return rng.uniform(-5, 5, (c, 2)), d


def trace(points, intervals, n, count=301):
    """Points of a closed curve over one period starting at knot 0 (same parameter for any representation)."""
    open_points, knots = ki.closed_to_open(points, intervals, n)
    a, z = b.domain(knots, n)
    period = z - a
    t = np.linspace(0, period, count, endpoint=False)
    return b.de_boor(open_points, knots, a + np.mod(t - a, period))


def test_every_public_name_is_tested():
    tested = {
        "intervals_from_knots", "knots_from_intervals", "closed_to_open", "split_interval", "expose_bezier",
        "halve_intervals", "quadratic_bezier_points", "hodograph_intervals", "elevate_intervals",
        "cubic_basis_from_intervals", "refine_basis",
    }
    assert set(ki.__all__) == tested


# --- the notes' labelling ------------------------------------------------------------------


def test_figure_6_11_intervals():
    # A cubic with knots [1,2,3,4,6,9,10,11]: d_-1 ... d_5 = 1, 1, 1, 2, 3, 1, 1.
    figure = notes_example("06.figure_6_11")
    knots, intervals = figure.inputs["knots"], figure.results["intervals"]
    np.testing.assert_array_equal(ki.intervals_from_knots(knots), intervals)
    np.testing.assert_array_equal(ki.knots_from_intervals(intervals, start=knots[0]), knots)


def test_periodic_knot_vector_of_figure_6_6():
    # Figure 6.6.a: five points and intervals (1, 1, 2, 1, 2) give, once unrolled and shifted by 3,
    # the figure's knot vector, which runs from 1 to 14; P_0 = P(1,3,4) and the first three points come back at the end.
    periodic = notes_example("06.periodic")
    polygon = np.random.default_rng(0).uniform(-3, 3, (5, 2))
    points, knots = ki.closed_to_open(polygon, periodic.results["intervals"], 3)
    figure_knots = periodic.inputs["knots"]
    np.testing.assert_array_equal(knots + 3, figure_knots)
    np.testing.assert_array_equal(points, np.vstack([polygon, polygon[:3]]))
    assert periodic.results["intervals"].sum() == periodic.results["period"]


def test_polar_labels_of_figure_6_14():
    # With the origin at the start of d_0: P_0 = f(-d4, 0, d0), P_1 = f(0, d0, d0+d1), P_2 = f(d0, d0+d1, d0+d1+d2).
    labels = notes_example("06.polar_labels_from_intervals").results["labels"]
    polygon, d = closed_curve(1, 3, count=5)
    points, knots = ki.closed_to_open(polygon, d, 3)
    np.testing.assert_allclose(knots[:3], labels[0] @ d, atol=1e-14)
    np.testing.assert_allclose(knots[1:4], labels[1] @ d, atol=1e-14)
    for label, point in zip(labels, polygon):
        np.testing.assert_allclose(b.blossom(points, knots, label @ d), point, atol=1e-12)


# --- splitting intervals -------------------------------------------------------------------


SPLITTING = notes_example("06.interval_splitting")


@pytest.mark.parametrize("fraction", ["one_and_two", "halves"])
def test_the_notes_splitting_example(fraction):
    # Figures 6.15-6.17: the interval 3 of the closed cubic with intervals 3, 1, 2, 2, 1 split into 1 + 2, 1.5 + 1.5.
    d, q = SPLITTING.args("intervals", "index")
    polygon, _ = closed_curve(2, 3, count=len(d))
    new_points, new_d = ki.split_interval(polygon, d, q, SPLITTING.inputs[fraction], degree=3)
    np.testing.assert_allclose(new_d, SPLITTING.results[fraction])
    np.testing.assert_allclose(trace(new_points, new_d, 3), trace(polygon, d, 3), atol=1e-10)


def test_the_notes_zero_intervals_expose_the_bezier_points():
    # Figure 6.18: split 3 into 3 + 0 and the zeros again until two zeros flank it on both sides.
    d, q = SPLITTING.args("intervals", "index")
    polygon, _ = closed_curve(3, 3, count=len(d))
    points, intervals = polygon, d
    for index, fraction in [(q, 1.0), (q + 1, 0.5), (q, 0.0), (q, 0.5)]:
        points, intervals = ki.split_interval(points, intervals, index, fraction, degree=3)
    np.testing.assert_array_equal(intervals, SPLITTING.results["bezier_exposed"])
    np.testing.assert_allclose(points[1:5], ki.expose_bezier(polygon, d, degree=3)[q], atol=1e-12)


def test_split_interval_three_into_one_and_two_by_the_construction():
    # Figure 6.16: to split interval d_q, divide the three edges around it into thirds proportional
    # to their neighbouring intervals, then cut the pieces labelled d_q in the ratio f : (1-f).
    polygon, d = closed_curve(2, 3)
    q = 3
    d[q] = 3.0
    fraction = SPLITTING.inputs["one_and_two"]
    new_points, new_d = ki.split_interval(polygon, d, q, fraction, degree=3)
    np.testing.assert_allclose(new_d, np.concatenate([d[:q], [1.0, 2.0], d[q + 1 :]]))
    c = len(d)
    knot = lambda k: ki.knots_from_intervals(np.tile(d, 3))[k + c]  # noqa: E731  (t_k, any sign of k)
    u = knot(q) + fraction * d[q]
    expected = []
    for i in (q, q + 1, q + 2):
        # Edge P_(i-1) P_i carries the polar values f(x, t_(i-1), t_i), x from t_(i-2) to t_(i+1).
        start, end = polygon[(i - 1) % c], polygon[i % c]
        expected.append(start + (u - knot(i - 2)) / (knot(i + 1) - knot(i - 2)) * (end - start))
    np.testing.assert_allclose(new_points[q : q + 3], expected)
    np.testing.assert_allclose(np.delete(new_points, [q, q + 1, q + 2], axis=0), np.delete(polygon, [q, q + 1], axis=0))


def longest_zero_run(intervals) -> int:
    """The most consecutive zero intervals around a closed polygon (a knot of multiplicity run + 1)."""
    doubled = np.concatenate([intervals, intervals]) == 0
    run = best = 0
    for zero in doubled:
        run = run + 1 if zero else 0
        best = max(best, run)
    return min(best, len(intervals))


@pytest.mark.parametrize("n", DEGREES)
def test_split_interval_keeps_a_closed_curve(n):
    polygon, d = closed_curve(3, n, zeros=n > 2)
    reference = trace(polygon, d, n)
    for q in range(len(d)):
        for f in (0.0, 0.3, 1.0):
            new_d = np.concatenate([d[:q], [f * d[q], (1 - f) * d[q]], d[q + 1 :]])
            if longest_zero_run(new_d) >= n:
                # The split would make a knot of multiplicity above n: rejected.
                with pytest.raises(ValueError, match="^fraction:"):
                    ki.split_interval(polygon, d, q, f, degree=n)
                continue
            new_points, split_d = ki.split_interval(polygon, d, q, f, degree=n)
            np.testing.assert_array_equal(split_d, new_d)
            assert len(new_points) == len(polygon) + 1
            np.testing.assert_allclose(trace(new_points, new_d, n), reference, atol=1e-10)


@pytest.mark.parametrize("n", DEGREES)
def test_split_interval_of_an_open_curve_is_knot_insertion(n):
    points, d = open_curve(1, n)
    knots = ki.knots_from_intervals(d)
    for q in range(n - 1, len(d) - n + 1):
        new_points, new_d = ki.split_interval(points, d, q, 0.25)
        expected_points, expected_knots = b.insert_knot(points, knots, knots[q] + 0.25 * d[q])
        np.testing.assert_allclose(new_points, expected_points)
        np.testing.assert_allclose(new_d, np.diff(expected_knots), atol=1e-14)
    with pytest.raises(ValueError, match="^index:"):
        ki.split_interval(points, d, len(d) - 1 if n > 1 else len(d), 0.5)


def test_zero_intervals_expose_bezier_points():
    # Figure 6.18: splitting off zero intervals until two zeros flank an interval uncovers that
    # segment's Bézier control points.
    polygon, d = closed_curve(4, 3)
    points, intervals = polygon, d
    for q, f in [(2, 1.0), (2, 1.0), (2, 0.0), (2, 0.0)]:
        points, intervals = ki.split_interval(points, intervals, q, f, degree=3)
    # Interval 2 (now at index 4) has zeros at 2, 3 and 5, 6: its control points are 3 ... 6.
    np.testing.assert_allclose(intervals[[2, 3, 5, 6]], 0)
    np.testing.assert_allclose(points[3:7], ki.expose_bezier(polygon, d, degree=3)[2], atol=1e-12)


@pytest.mark.parametrize("n", DEGREES)
def test_expose_bezier_closed_in_interval_order(n):
    polygon, d = closed_curve(5, n, zeros=n > 1)
    segments = ki.expose_bezier(polygon, d, degree=n)
    positive = np.flatnonzero(d > 0)
    assert segments.shape == (len(positive), n + 1, 2)
    open_points, knots = ki.closed_to_open(polygon, d, n)
    starts = ki.knots_from_intervals(d)[positive]
    period = d.sum()
    a, _ = b.domain(knots, n)
    for segment, q, t0 in zip(segments, positive, starts):
        # The segment's start and inner points (its end may wrap past the period to the domain's start).
        t = np.linspace(t0, t0 + d[q], 5)[:-1]
        on_curve = b.de_boor(open_points, knots, a + np.mod(t - a, period))
        np.testing.assert_allclose(bezier.evaluate(segment, t, interval=(t0, t0 + d[q])), on_curve, atol=1e-10)


def test_expose_bezier_open_matches_bspline():
    points, d = open_curve(2, 3)
    np.testing.assert_allclose(ki.expose_bezier(points, d), b.bezier_segments(points, ki.knots_from_intervals(d)))


# --- halving and quadratics -----------------------------------------------------------------


def test_halving_a_uniform_cubic_gives_the_subdivision_masks():
    polygon = np.random.default_rng(6).uniform(-3, 3, (6, 2))
    new_points, new_d = ki.halve_intervals(polygon, np.ones(6), degree=3)
    np.testing.assert_allclose(new_d, 0.5)
    previous, following = np.roll(polygon, 1, axis=0), np.roll(polygon, -1, axis=0)
    np.testing.assert_allclose(new_points[0::2], (previous + 6 * polygon + following) / 8)
    np.testing.assert_allclose(new_points[1::2], (polygon + following) / 2)


@pytest.mark.parametrize("n", DEGREES)
def test_halving_keeps_the_curve(n):
    polygon, d = closed_curve(7, n, zeros=n > 2)
    new_points, new_d = ki.halve_intervals(polygon, d, degree=n)
    assert len(new_points) == len(polygon) + np.count_nonzero(d)
    np.testing.assert_allclose(trace(new_points, new_d, n), trace(polygon, d, n), atol=1e-10)
    points, intervals = open_curve(3, n)
    refined, refined_d = ki.halve_intervals(points, intervals)
    knots = ki.knots_from_intervals(intervals)
    t = np.linspace(*b.domain(knots, n), 17)
    expected = BSpline(*b.to_scipy(points, knots))(t)
    np.testing.assert_allclose(BSpline(*b.to_scipy(refined, ki.knots_from_intervals(refined_d)))(t), expected)


def test_halving_converges_to_the_curve():
    polygon, d = closed_curve(8, 3)
    points, intervals = polygon, d
    distances = []
    curve = trace(polygon, d, 3, 4000)
    for _ in range(3):
        points, intervals = ki.halve_intervals(points, intervals, degree=3)
        gaps = np.linalg.norm(points[:, None, :] - curve[None, :, :], axis=2).min(axis=1)
        distances.append(gaps.max())
    assert all(later < earlier / 2 for earlier, later in zip(distances, distances[1:]))


def test_quadratic_bezier_points():
    polygon, d = closed_curve(9, 2, zeros=True)
    np.testing.assert_allclose(ki.quadratic_bezier_points(polygon, d, degree=2), ki.expose_bezier(polygon, d, degree=2))
    points, intervals = open_curve(4, 2)
    np.testing.assert_allclose(ki.quadratic_bezier_points(points, intervals), ki.expose_bezier(points, intervals))
    # Uniform intervals: the segment runs between edge midpoints with the vertex as its middle point.
    square = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
    segments = ki.quadratic_bezier_points(square, np.ones(4), degree=2)
    np.testing.assert_allclose(segments[1], [[1, 0], [2, 0], [2, 1]])
    with pytest.raises(ValueError, match="^degree:"):
        ki.quadratic_bezier_points(square, np.ones(4), degree=3)


# --- hodographs and degree elevation --------------------------------------------------------


@pytest.mark.parametrize("n", range(2, 6))
def test_hodograph_closed_is_the_derivative(n):
    polygon, d = closed_curve(10, n)
    hodo, hodo_d = ki.hodograph_intervals(polygon, d, degree=n)
    np.testing.assert_array_equal(hodo_d, d)
    open_points, knots = ki.closed_to_open(polygon, d, n)
    a, z = b.domain(knots, n)
    t = np.linspace(0, d.sum(), 50, endpoint=False)
    expected = b.derivative(open_points, knots, a + np.mod(t - a, d.sum()))
    np.testing.assert_allclose(trace(hodo, hodo_d, n - 1, 50), expected, atol=1e-10)


@pytest.mark.parametrize("n", range(2, 6))
def test_hodograph_scale_factors_of_equation_6_6(n):
    # c_i = n / (d_(i-m+1) + ... + d_(i+m)) for n = 2m, n / (d_(i-m) + ... + d_(i+m)) for n = 2m + 1.
    polygon, d = closed_curve(11, n)
    hodo, _ = ki.hodograph_intervals(polygon, d, degree=n)
    c, m = len(d), n // 2
    offsets = range(-m + 1, m + 1) if n % 2 == 0 else range(-m, m + 1)
    i = np.arange(c)
    scale = n / sum(d[(i + k) % c] for k in offsets)
    expected = scale[:, None] * (np.roll(polygon, -1, axis=0) - polygon)
    # The notes number Q_i like the cubic case; for even degree the hodograph's labels start one later.
    shift = 0 if n % 2 else 1
    np.testing.assert_allclose(np.roll(hodo, -shift, axis=0), expected)


def test_hodograph_scale_factors_of_the_notes_figure():
    # Figure 6.25: Q = 3 V / (1 + 2 + 3) and 3 V / (2 + 3 + 1) for the edges with those neighbouring intervals.
    example = notes_example("06.hodograph_scale")
    d = example.inputs["intervals"]
    polygon, _ = closed_curve(19, 3, count=len(d))
    hodo, _ = ki.hodograph_intervals(polygon, d, degree=3)
    for i, scale in zip(example.results["edges"].astype(int), example.results["scales"]):
        np.testing.assert_allclose(hodo[i], scale * (polygon[i + 1] - polygon[i]))


def test_hodograph_open_matches_bspline():
    points, d = open_curve(5, 3)
    hodo, hodo_d = ki.hodograph_intervals(points, d)
    expected, knots = b.hodograph(points, ki.knots_from_intervals(d))
    np.testing.assert_allclose(hodo, expected)
    np.testing.assert_allclose(hodo_d, d[1:-1])
    with pytest.raises(ValueError, match="^degree:"):
        ki.hodograph_intervals(*closed_curve(1, 1), degree=1)


def test_elevating_degree_one_inserts_midpoints():
    polygon, d = closed_curve(12, 1)
    new_points, new_d = ki.elevate_intervals(polygon, d, degree=1)
    np.testing.assert_allclose(new_points[0::2], polygon)
    np.testing.assert_allclose(new_points[1::2], (polygon + np.roll(polygon, -1, axis=0)) / 2)
    np.testing.assert_allclose(new_d[1::2], d)
    np.testing.assert_allclose(new_d[0::2], 0)


def test_elevating_degree_two_by_equation_6_9():
    # P_(i,j) = ((2 d_i + 3 d_j) P_i + d_i P_j) / (3 d_i + 3 d_j): the new point next to P_i towards P_j.
    polygon, d = closed_curve(13, 2)
    new_points, _ = ki.elevate_intervals(polygon, d, degree=2)
    c = len(d)
    i, j = np.arange(c), (np.arange(c) + 1) % c
    across = (3 * (d[i] + d[j]))[:, None]
    toward_next = ((2 * d[i] + 3 * d[j])[:, None] * polygon[i] + d[i][:, None] * polygon[j]) / across
    toward_previous = ((2 * d[j] + 3 * d[i])[:, None] * polygon[j] + d[j][:, None] * polygon[i]) / across
    # New points in order: ..., P_(0,c-1), P_(0,1), P_(1,0), P_(1,2), ...: two next to each old vertex.
    np.testing.assert_allclose(np.roll(new_points, -2, axis=0)[0::2], toward_next)
    np.testing.assert_allclose(np.roll(new_points, -2, axis=0)[1::2], toward_previous)


def test_elevating_degree_three_by_the_notes_formulas():
    # Figure 6.27: an edge point and a vertex point per old control point.
    polygon, d = closed_curve(14, 3)
    new_points, new_d = ki.elevate_intervals(polygon, d, degree=3)
    np.testing.assert_allclose(new_d[1::2], d)
    c = len(d)
    dd = lambda k: d[np.mod(k, c)]  # noqa: E731
    pp = lambda k: polygon[np.mod(k, c)]  # noqa: E731
    i = np.arange(c)
    edge = ((dd(i) + 2 * dd(i + 1))[:, None] * pp(i) + (2 * dd(i - 1) + dd(i))[:, None] * pp(i + 1)) / (
        2 * (dd(i - 1) + dd(i) + dd(i + 1))
    )[:, None]
    left, right = 4 * (dd(i - 2) + dd(i - 1) + dd(i)), 4 * (dd(i - 1) + dd(i) + dd(i + 1))
    vertex = (
        (dd(i) / left)[:, None] * pp(i - 1)
        + ((dd(i - 2) + dd(i - 1)) / left + (dd(i) + dd(i + 1)) / right + 0.5)[:, None] * pp(i)
        + (dd(i - 1) / right)[:, None] * pp(i + 1)
    )
    np.testing.assert_allclose(new_points[0::2], vertex)
    np.testing.assert_allclose(new_points[1::2], edge)
    # Uniform intervals: (P_(i-1) + 10 P_i + P_(i+1)) / 12 and midpoints.
    uniform, _ = ki.elevate_intervals(polygon, np.ones(c), degree=3)
    np.testing.assert_allclose(uniform[1::2], (polygon + np.roll(polygon, -1, axis=0)) / 2)
    vertex_mask = (np.roll(polygon, 1, axis=0) + 10 * polygon + np.roll(polygon, -1, axis=0)) / 12
    np.testing.assert_allclose(uniform[0::2], vertex_mask)


@pytest.mark.parametrize("n", DEGREES)
def test_elevation_keeps_the_curve(n):
    polygon, d = closed_curve(15, n, zeros=n > 1)
    new_points, new_d = ki.elevate_intervals(polygon, d, degree=n)
    assert len(new_d) == len(d) + np.count_nonzero(d)
    np.testing.assert_allclose(trace(new_points, new_d, n + 1), trace(polygon, d, n), atol=1e-10)
    points, intervals = open_curve(6, n)
    raised, raised_d = ki.elevate_intervals(points, intervals)
    knots = ki.knots_from_intervals(intervals)
    t = np.linspace(*b.domain(knots, n), 17)
    expected = BSpline(*b.to_scipy(points, knots))(t)
    np.testing.assert_allclose(BSpline(*b.to_scipy(raised, ki.knots_from_intervals(raised_d)))(t), expected)


# --- basis functions from intervals ---------------------------------------------------------


def test_cubic_basis_from_intervals_matches_scipy():
    rng = np.random.default_rng(16)
    for _ in range(10):
        d = rng.uniform(0.2, 3.0, 4)
        d[rng.uniform(size=4) < 0.25] = 0.0
        if d.sum() == 0 or np.count_nonzero(d == 0) > 2:
            continue
        knots = ki.knots_from_intervals(d)
        t = np.linspace(-0.5, knots[-1] + 0.5, 101)
        expected = np.nan_to_num(BSpline.basis_element(knots, extrapolate=False)(t))
        np.testing.assert_allclose(ki.cubic_basis_from_intervals(d, t), expected, atol=1e-12)


def test_cubic_basis_end_derivatives():
    # B'(t_2) = 3 (t_2 - t_1) / ((t_3 - t_1)(t_4 - t_1)), B''(t_2) = 6 / ((t_3 - t_1)(t_4 - t_1)); B is C2.
    d = np.array([1.0, 2.0, 0.5, 1.5])
    t1, t2, t3, t4, _ = ki.knots_from_intervals(d)
    h = 1e-4
    f = lambda x: ki.cubic_basis_from_intervals(d, x)  # noqa: E731
    assert (f(t2 + h) - f(t2 - h)) / (2 * h) == pytest.approx(3 * (t2 - t1) / ((t3 - t1) * (t4 - t1)), rel=1e-6)
    assert (f(t2 + h) - 2 * f(t2) + f(t2 - h)) / h**2 == pytest.approx(6 / ((t3 - t1) * (t4 - t1)), rel=1e-4)
    assert isinstance(f(1.0), float)
    assert f(t1) == 0.0 and f(6.0) == 0.0


def test_cubic_basis_equals_bspline_basis_in_a_uniform_spline():
    knots = np.arange(10.0)
    t = np.linspace(3, 6, 31)
    np.testing.assert_allclose(ki.cubic_basis_from_intervals(np.ones(4), t - 2), b.bspline_basis(knots, 3, 3, t))


def test_refine_basis_corrects_the_notes_denominator():
    # §6.14.2: the left weight is (k - s0)/(s_n - s0); the notes print s_(n+1) - s0, which breaks the identity.
    erratum = notes_example("06.basis_refinement").errata["a"]
    assert "s_n - s0" in erratum.correct and "s_(n+1) - s0" in erratum.notes
    local, k = np.array([0.0, 1.0, 3.0, 4.0, 7.0]), 2.2
    (a, left), (c, right) = ki.refine_basis(local, k)
    assert a == pytest.approx((k - local[0]) / (local[-2] - local[0]))
    t = np.linspace(0, 7, 141)[:-1]
    element = lambda knots: np.nan_to_num(BSpline.basis_element(knots, extrapolate=False)(t))  # noqa: E731
    np.testing.assert_allclose(a * element(left) + c * element(right), element(local), atol=1e-12)
    printed = (k - local[0]) / (local[-1] - local[0])
    assert not np.allclose(printed * element(left) + c * element(right), element(local), atol=1e-3)


def test_the_closed_curves_of_figures_6_12_and_6_13():
    variants = notes_example("06.closed_intervals").inputs
    polygon, _ = closed_curve(20, 3, count=5)
    # A triple knot (d0 = d1 = 0) puts P1 = f(0, 0, 0) on the curve; a double knot (d0 = 0) only brings it closer.
    points, knots = ki.closed_to_open(polygon, variants["triple_knot"], 3)
    np.testing.assert_allclose(b.de_boor(points, knots, 0.0), polygon[1], atol=1e-12)
    gaps = {name: np.linalg.norm(trace(polygon, variants[name], 3) - polygon[1], axis=1).min()
            for name in ("uniform", "double_knot", "triple_knot")}
    assert gaps["triple_knot"] < 1e-9 < gaps["double_knot"] < gaps["uniform"]
    # On a regular pentagon, raising d1 to 3 makes the segment of edge P1 P2 the longest, longer than before.
    pentagon = np.column_stack([np.cos(0.4 * np.pi * np.arange(5)), np.sin(0.4 * np.pi * np.arange(5))])
    lengths = {}
    for name in ("uniform", "longer"):
        segments = ki.expose_bezier(pentagon, variants[name], degree=3)
        lengths[name] = [np.linalg.norm(np.diff(bezier.evaluate(seg, np.linspace(0, 1, 200)), axis=0), axis=1).sum()
                         for seg in segments]
    assert np.argmax(lengths["longer"]) == np.argmax(variants["longer"]) == 1
    assert lengths["longer"][1] > 1.2 * lengths["uniform"][1]


@pytest.mark.parametrize("n", range(1, 5))
def test_refine_basis_splits_a_basis_function(n):
    rng = np.random.default_rng(n)
    local = np.sort(rng.uniform(0, 5, n + 2))
    t = np.linspace(local[0], local[-1], 51)[:-1]
    whole = BSpline.basis_element(local, extrapolate=False)(t)
    for k in [rng.uniform(local[0], local[-1]), local[1], local[-2], local[0]]:
        (a, left), (c, right) = ki.refine_basis(local, k)
        parts = [np.nan_to_num(BSpline.basis_element(knots, extrapolate=False)(t)) if knots[0] < knots[-1] else 0 * t
                 for knots in (left, right)]
        np.testing.assert_allclose(a * parts[0] + c * parts[1], whole, atol=1e-12)


# --- bad input ---------------------------------------------------------------------------------

SQUARE = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])


@pytest.mark.parametrize(
    "call, error, name",
    [
        (lambda: ki.intervals_from_knots([2.0, 1.0]), ValueError, "knots"),
        (lambda: ki.intervals_from_knots([[1.0, 2.0]]), ValueError, "knots"),
        (lambda: ki.knots_from_intervals([1.0, -1.0]), ValueError, "intervals"),
        (lambda: ki.closed_to_open(SQUARE, [1.0, 1.0, 1.0], 2), ValueError, "intervals"),
        (lambda: ki.closed_to_open(SQUARE, [0.0, 0.0, 0.0, 0.0], 2), ValueError, "intervals"),
        (lambda: ki.closed_to_open(SQUARE, np.ones(4), 4), ValueError, "points"),
        (lambda: ki.closed_to_open(SQUARE, np.ones(4), 0), ValueError, "degree"),
        (lambda: ki.split_interval(SQUARE, np.ones(4), 4, 0.5, degree=2), ValueError, "index"),
        (lambda: ki.split_interval(SQUARE, np.ones(4), 1, 1.5, degree=2), ValueError, "fraction"),
        (lambda: ki.split_interval(SQUARE, np.ones(4), 1.0, 0.5, degree=2), TypeError, "index"),
        (lambda: ki.split_interval(SQUARE, np.ones(5), 0, 0.5), ValueError, "index"),  # end-condition interval
        (lambda: ki.split_interval(SQUARE, np.ones(2), 0, 0.5), ValueError, "intervals"),  # degree 0
        (lambda: ki.halve_intervals(SQUARE, np.ones(3), degree=3), ValueError, "intervals"),
        (lambda: ki.hodograph_intervals(SQUARE, np.ones(4), degree=1), ValueError, "degree"),
        (lambda: ki.elevate_intervals([1.0, 2.0], np.ones(2), degree=1), ValueError, "points"),
        (lambda: ki.cubic_basis_from_intervals([1.0, 1.0, 1.0], 0.5), ValueError, "intervals"),
        (lambda: ki.cubic_basis_from_intervals([1.0, 1.0, 1.0, 1.0], [[0.5]]), ValueError, "t"),
        (lambda: ki.refine_basis([0.0, 1.0, 2.0], 3.0), ValueError, "knot"),
        (lambda: ki.refine_basis([2.0, 1.0, 0.0], 1.0), ValueError, "local_knots"),
    ],
)
def test_bad_input_names_the_argument(call, error, name):
    with pytest.raises(error, match=rf"^{name}:"):
        call()


@pytest.mark.parametrize("n", DEGREES)
def test_closed_to_open_closes_with_full_smoothness_in_scipy(n):
    polygon, d = closed_curve(18, n, zeros=n > 2)
    spline = BSpline(*b.to_scipy(*ki.closed_to_open(polygon, d, n)))
    a, z = b.domain(ki.closed_to_open(polygon, d, n)[1], n)
    assert z - a == pytest.approx(d.sum())
    for order in range(n - int(np.any(d == 0))):
        scale = 1 + np.abs(spline(a, nu=order)).max()
        np.testing.assert_allclose(spline(a, nu=order), spline(z, nu=order), atol=1e-8 * scale)
