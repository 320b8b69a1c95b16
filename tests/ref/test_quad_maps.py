"""Unit tests of cagd_ref.quad_maps: bilinear, birational and projective maps of quadrilaterals (chapter 21).

The notes' examples come from cagd_course/examples/ch21.toml. Exact claims are
checked with SymPy (the pre-images of E, the lost weight condition (21.6) as
the concurrency of the iso-lines, the base point, the rational inverse);
inverses are checked by round trips on seeded random quads (convex,
trapezoids, non-convex, twisted) and against scipy.optimize.root; the
projective map against a homography found by the direct linear transform;
the concave quad's region with matplotlib's Path.contains_points.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from matplotlib.path import Path
from scipy.optimize import root

from cagd_course.examples import notes_example
from cagd_ref import quad_maps as qm
from cagd_ref.surfaces import patch_point

BILINEAR = notes_example("21.bilinear")
BIRATIONAL = notes_example("21.birational")
BASE = notes_example("21.base_point")
CONCAVE = notes_example("21.concave")
TWISTED = notes_example("21.twisted")
COLLINEAR = notes_example("21.collinear")
PROJECTIVE = notes_example("21.projective")
QUAD = BILINEAR.inputs["quad"]
W53 = BIRATIONAL.inputs["weights"]
UNIT = np.ones((2, 2))


def cartesian(h) -> np.ndarray:
    h = np.asarray(h, dtype=float)
    return h[..., :2] / h[..., 2:]


def random_quad(rng, kind: str) -> np.ndarray:
    """A random quad [[P00, P01], [P10, P11]] of a kind: convex, trapezoid, parallelogram, nonconvex, twisted."""
    while True:
        if kind == "trapezoid":  # edges t = 0 and t = 1 parallel
            p00, p10, p01 = rng.uniform(-5, 5, (3, 2))
            p11 = p01 + rng.uniform(0.3, 1.5) * (p10 - p00)
        elif kind == "parallelogram":
            p00, p10, p01 = rng.uniform(-5, 5, (3, 2))
            p11 = p10 + p01 - p00
        else:
            p00, p10, p01, p11 = rng.uniform(-5, 5, (4, 2))
        quad = np.array([[p00, p01], [p10, p11]])
        c = qm.corner_determinants(quad)
        negative = int((c < 0).sum())
        if np.abs(c).min() < 2.0:
            continue
        if kind in ("convex", "trapezoid", "parallelogram") and negative == 0:
            return quad
        if kind == "nonconvex" and negative == 1:
            return quad
        if kind == "twisted" and negative == 2:
            return quad


# --- the bilinear map and its inverse ----------------------------------------------------------------


def test_quad_map_is_the_degree_one_patch_and_reaches_the_corners():
    corners = qm.quad_map(QUAD, [0.0, 1.0, 0.0, 1.0], [0.0, 0.0, 1.0, 1.0])
    np.testing.assert_array_equal(corners, QUAD[[0, 1, 0, 1], [0, 0, 1, 1]])
    s, t = np.random.default_rng(0).uniform(-1, 2, (2, 50))
    x, y = 12 * s + 8 * t - 8 * s * t, 6 * t - 2 * s * t  # the notes' map, expanded
    np.testing.assert_allclose(qm.quad_map(QUAD, s, t), np.column_stack([x, y]), atol=1e-12)
    np.testing.assert_allclose(qm.quad_map(QUAD, s, t, UNIT), qm.quad_map(QUAD, s, t), atol=1e-12)


def test_the_notes_bilinear_example_two_preimages_of_e():
    quad, point = BILINEAR.args("quad", "point")
    np.testing.assert_allclose(qm.bilinear_inverse(quad, point), BILINEAR.results["preimages"], atol=1e-14)
    x, y = point
    f = x * x - 8 * x * y + 16 * y * y - 72 * x - 96 * y + 1296
    assert f == BILINEAR.results["f_at_point"]
    root_f = np.sqrt(f)
    closed = [((x - 4 * y + 36 + sign * root_f) / 24, (-x + 4 * y + 36 + sign * root_f) / 32) for sign in (-1, 1)]
    np.testing.assert_allclose(closed, BILINEAR.results["preimages"])


def test_the_closed_form_of_the_notes_everywhere():
    """s = (x - 4y + 36 ± √f)/24 and t = (-x + 4y + 36 ± √f)/32, the same sign in both."""
    rng = np.random.default_rng(1)
    for s, t in rng.uniform(-1, 2, (40, 2)):
        x, y = qm.quad_map(QUAD, s, t)
        f = x * x - 8 * x * y + 16 * y * y - 72 * x - 96 * y + 1296
        r = np.sqrt(f)
        closed = sorted(((x - 4 * y + 36 + g * r) / 24, (-x + 4 * y + 36 + g * r) / 32) for g in (-1, 1))
        np.testing.assert_allclose(qm.bilinear_inverse(QUAD, (x, y)), closed, atol=1e-9)


def test_the_preimages_of_e_exactly_with_sympy():
    s, t = sp.symbols("s t")
    q = [[sp.Matrix(p) for p in row] for row in BILINEAR.inputs["quad"].astype(int).tolist()]
    patch = q[0][0] * (1 - s) * (1 - t) + q[1][0] * s * (1 - t) + q[0][1] * (1 - s) * t + q[1][1] * s * t
    solutions = sp.solve(list(patch - sp.Matrix([8, 4])), [s, t], dict=True)
    assert sorted((sol[s], sol[t]) for sol in solutions) == [(sp.Rational(1, 3), sp.Rational(3, 4)), (2, 2)]
    # The quadratic in s at E: -8 (3s² - 7s + 2).
    e, f, g, h = (q[1][0] - q[0][0]), (q[0][1] - q[0][0]), (q[0][0] - q[1][0] - q[0][1] + q[1][1]), sp.Matrix([8, 4])

    def cross(a, b):
        return a[0] * b[1] - a[1] * b[0]

    quadratic = sp.Poly(cross(e, g) * s**2 + (cross(e, f) - cross(h, g)) * s - cross(h, f), s)
    assert [int(c / -8) for c in reversed(quadratic.all_coeffs())] == BILINEAR.results["s_quadratic"].tolist()


@pytest.mark.parametrize("kind", ["convex", "trapezoid", "parallelogram", "nonconvex", "twisted"])
def test_round_trips_of_the_bilinear_inverse(kind):
    rng = np.random.default_rng(["convex", "trapezoid", "parallelogram", "nonconvex", "twisted"].index(kind))
    for _ in range(20):
        quad = random_quad(rng, kind)
        params = rng.uniform(-0.5, 1.5, (6, 2))
        for (s, t), x in zip(params, qm.quad_map(quad, params[:, 0], params[:, 1])):
            pre = qm.bilinear_inverse(quad, x)
            assert len(pre) == (1 if kind in ("trapezoid", "parallelogram") else 2) or len(pre) == 1
            assert np.all(np.diff(pre[:, 0]) >= 0)
            np.testing.assert_allclose(qm.quad_map(quad, pre[:, 0], pre[:, 1]), np.broadcast_to(x, pre.shape),
                                       atol=1e-9)
            assert np.abs(pre - (s, t)).max(axis=1).min() < 1e-8


def test_trapezoids_and_parallelograms_have_one_preimage():
    rng = np.random.default_rng(7)
    for kind in ("trapezoid", "parallelogram"):
        quad = random_quad(rng, kind)
        for x in rng.uniform(-10, 10, (30, 2)):
            assert len(qm.bilinear_inverse(quad, x)) <= 1
    # Parallel edges s = 0 and s = 1 (the other pair): still one, solved through t.
    sideways = np.array([[(0.0, 0.0), (0.0, 1.0)], [(2.0, 0.0), (2.0, 3.0)]])
    np.testing.assert_allclose(qm.bilinear_inverse(sideways, (1.0, 1.0)), [[0.5, 0.5]])


def test_scipy_finds_no_preimage_the_inverse_misses():
    rng = np.random.default_rng(3)
    for _ in range(15):
        quad = random_quad(rng, "convex")
        x = rng.uniform(-6, 6, 2)
        ours = qm.bilinear_inverse(quad, x)
        for start in rng.uniform(-3, 4, (8, 2)):
            found = root(lambda p, q=quad, x=x: qm.quad_map(q, p[0], p[1]) - x, start, tol=1e-13)
            if found.success and np.abs(found.fun).max() < 1e-10:
                assert len(ours) and np.abs(ours - found.x).max(axis=1).min() < 1e-6


def test_points_without_and_with_one_double_preimage():
    assert qm.bilinear_inverse(QUAD, (20.0, 5.0)).shape == (0, 2)  # f(20, 5) = -624 < 0
    # On the fold (f = 0) the two pre-images meet: f(x, 0) = (x - 36)² - 0 at x = 36.
    np.testing.assert_allclose(qm.bilinear_inverse(QUAD, (36.0, 0.0)), [[3.0, 0.0]], atol=1e-12)


def test_the_vertex_of_a_trapezoids_pencil_has_infinitely_many_preimages():
    trapezoid = np.array([[(0.0, 0.0), (1.0, 2.0)], [(4.0, 0.0), (3.0, 2.0)]])  # s = 0, s = 1 meet at (2, 4)
    with pytest.raises(ValueError, match="^point: .*infinitely many"):
        qm.bilinear_inverse(trapezoid, (2.0, 4.0))
    np.testing.assert_allclose(qm.bilinear_inverse(trapezoid, (2.0, 3.0)), [[0.5, 1.5]])
    assert len(qm.bilinear_inverse(trapezoid, (5.0, 4.0))) == 0  # on the line through it parallel to t = 0


# --- the weight condition (21.6) --------------------------------------------------------------------


def test_the_weight_condition_is_the_concurrency_of_the_iso_lines():
    """As · (Q̃00 × Q̃11 + Q̃10 × Q̃01) = w00 w11 C10 C01 - w10 w01 C00 C11, identically, and the same for At."""
    xy = sp.symbols("x00 y00 x10 y10 x01 y01 x11 y11")
    w = dict(zip([(0, 0), (1, 0), (0, 1), (1, 1)], sp.symbols("w00 w10 w01 w11")))
    q = {key: sp.Matrix([xy[2 * k], xy[2 * k + 1], 1]) for k, key in enumerate([(0, 0), (1, 0), (0, 1), (1, 1)])}
    qt = {key: w[key] * q[key] for key in q}

    def det(a, b, c):
        return sp.Matrix.hstack(a, b, c).det()

    c00, c10 = det(q[0, 1], q[0, 0], q[1, 0]), det(q[0, 0], q[1, 0], q[1, 1])
    c11, c01 = det(q[1, 0], q[1, 1], q[0, 1]), det(q[1, 1], q[0, 1], q[0, 0])
    condition = w[0, 0] * w[1, 1] * c10 * c01 - w[1, 0] * w[0, 1] * c00 * c11
    a_s = q[0, 0].cross(q[0, 1]).cross(q[1, 0].cross(q[1, 1]))
    a_t = q[0, 0].cross(q[1, 0]).cross(q[0, 1].cross(q[1, 1]))
    assert sp.expand(a_s.dot(qt[0, 0].cross(qt[1, 1]) + qt[1, 0].cross(qt[0, 1])) - condition) == 0
    assert sp.expand(a_t.dot(qt[0, 0].cross(qt[1, 1]) + qt[0, 1].cross(qt[1, 0])) - condition) == 0


def test_the_four_numeric_weights_of_the_chapter():
    quad = BIRATIONAL.inputs["quad"]
    np.testing.assert_allclose(qm.corner_determinants(quad), BILINEAR.results["corner_determinants"])
    # 5/3: with w01 = 5/3 the weight of corner (1, 1) must stay 1.
    assert qm.birational_weight(quad, W53) == pytest.approx(1.0, abs=1e-14)
    assert qm.birational_weight(quad, UNIT) == pytest.approx(1 / BIRATIONAL.results["w01"])
    assert qm.birational_weight(CONCAVE.inputs["quad"], UNIT) == pytest.approx(CONCAVE.results["w11"], abs=1e-13)
    np.testing.assert_allclose(qm.corner_determinants(CONCAVE.inputs["quad"]), CONCAVE.results["corner_determinants"])
    twisted = TWISTED.inputs["quad"]
    np.testing.assert_allclose(qm.corner_determinants(twisted), TWISTED.results["corner_determinants"])
    w10 = TWISTED.results["w10_with_unit_others"]
    assert qm.birational_weight(twisted, [[1.0, 1.0], [w10, 0.0]]) == pytest.approx(1.0, abs=1e-14)
    assert qm.is_birational(twisted, TWISTED.inputs["weights"])
    assert qm.birational_weight(COLLINEAR.inputs["quad"], UNIT) == COLLINEAR.results["w11"]


def test_the_notes_minus_two_weights_are_not_birational_but_minus_four_are():
    twisted = TWISTED.inputs["quad"]
    minus_two = [[1.0, -2.0], [-2.0, 1.0]]
    assert not qm.is_birational(twisted, minus_two)
    with pytest.raises(ValueError, match="^weights: .*birational"):
        qm.birational_inverse(twisted, minus_two, (5.0, 2.0))
    # The two forms (21.8) and (21.9) of s disagree for those weights, at a point of the quad.
    h = qm.homogeneous_quad(twisted, minus_two)
    a_s, _ = qm.pencil_axes(twisted)
    p = np.array([5.0, 2.0, 1.0])

    def form(first, second):
        return np.linalg.det([a_s, first, p]) / (np.linalg.det([a_s, first, p]) - np.linalg.det([a_s, second, p]))

    assert abs(form(h[0, 1], h[1, 1]) - form(h[0, 0], h[1, 0])) > 1
    minus_four = TWISTED.results["negative_weights"]
    assert qm.is_birational(twisted, minus_four)
    inside = twisted_points(400)
    s = qm.birational_inverse(twisted, minus_four, inside)[:, 0]
    assert (s < -1e-9).any() or (s > 1 + 1e-9).any()


def twisted_points(count: int) -> np.ndarray:
    """Random points inside the twisted quad's two triangles (its boundary Q00 Q10 Q11 Q01 crosses itself)."""
    quad = TWISTED.inputs["quad"]
    boundary = Path(quad[[0, 1, 1, 0], [0, 0, 1, 1]])
    rng = np.random.default_rng(5)
    candidates = rng.uniform(0, 12, (20 * count, 2))
    return candidates[boundary.contains_points(candidates)][:count]


def test_random_birational_weights_make_both_families_pencils():
    rng = np.random.default_rng(11)
    for kind in ("convex", "nonconvex", "twisted"):
        for _ in range(10):
            quad = random_quad(rng, kind)
            w = np.ones((2, 2))
            w[0, 0], w[1, 0], w[0, 1] = rng.uniform(0.3, 3, 3)
            w[1, 1] = qm.birational_weight(quad, w)
            assert abs(qm.weight_condition(quad, w)) < 1e-12
            a_s, a_t = qm.pencil_axes(quad)
            for axis, lines in ((a_s, qm.isoparameter_lines(quad, s=np.linspace(-1, 2, 7), weights=w)),
                                (a_t, qm.isoparameter_lines(quad, t=np.linspace(-1, 2, 7), weights=w))):
                unit = lines / np.linalg.norm(lines, axis=1)[:, None]
                assert np.abs(unit @ axis).max() < 1e-12
            w[1, 1] *= 1.5
            lines = qm.isoparameter_lines(quad, s=[0.2, 0.5, 0.8], weights=w)
            assert abs(np.linalg.det(lines / np.linalg.norm(lines, axis=1)[:, None])) > 1e-8  # no longer concurrent


# --- the birational inverse --------------------------------------------------------------------------


def test_the_notes_birational_example():
    quad, weights, point = BIRATIONAL.args("quad", "weights", "point")
    np.testing.assert_allclose(qm.birational_inverse(quad, weights, point), BIRATIONAL.results["preimage"], atol=1e-15)
    rng = np.random.default_rng(2)
    xy = rng.uniform(0, 12, (50, 2))
    r = BIRATIONAL.results
    h = np.column_stack([xy, np.ones(50)])
    s, t = (h @ r["s_numerator"]) / (h @ r["s_denominator"]), (h @ r["t_numerator"]) / (h @ r["t_denominator"])
    np.testing.assert_allclose(qm.birational_inverse(quad, weights, xy), np.column_stack([s, t]), atol=1e-12)
    # The misprinted denominator 26 - 4y gives s = 0.8 at E, and s != 1 on the edge x = 12.
    erratum = BIRATIONAL.errata["s_denominator"]
    assert erratum.correct == "36 - 4y" and (3 * 8 - 4 * 4) / (26 - 4 * 4) == 0.8
    # The denominator vanishes at As = (12, 9), as a pencil's must.
    assert np.array([12, 9, 1]) @ r["s_denominator"] == 0


def test_the_birational_inverse_exactly_with_sympy():
    """Rational corners and weights: s(x(s, t), y(s, t)) = s and t(...) = t identically."""
    s, t, x, y = sp.symbols("s t x y")
    quad = [[(0, 0), (1, 5)], [(7, 1), (6, 4)]]
    w = [[sp.Integer(1), sp.Rational(3, 2)], [sp.Rational(1, 2), None]]
    q = {(i, j): sp.Matrix([*quad[i][j], 1]) for i in (0, 1) for j in (0, 1)}

    def det(a, b, c):
        return sp.Matrix.hstack(a, b, c).det()

    c00, c10 = det(q[0, 1], q[0, 0], q[1, 0]), det(q[0, 0], q[1, 0], q[1, 1])
    c11, c01 = det(q[1, 0], q[1, 1], q[0, 1]), det(q[1, 1], q[0, 1], q[0, 0])
    w[1][1] = w[1][0] * w[0][1] * c00 * c11 / (w[0][0] * c10 * c01)
    assert float(w[1][1]) == pytest.approx(qm.birational_weight(quad, [[1.0, 1.5], [0.5, 0.0]]))
    qt = {key: w[key[0]][key[1]] * q[key] for key in q}
    a_s = q[0, 0].cross(q[0, 1]).cross(q[1, 0].cross(q[1, 1]))
    a_t = q[0, 0].cross(q[1, 0]).cross(q[0, 1].cross(q[1, 1]))
    p = sp.Matrix([x, y, 1])
    s_of = det(a_s, qt[0, 1], p) / (det(a_s, qt[0, 1], p) - det(a_s, qt[1, 1], p))
    t_of = det(a_t, qt[1, 0], p) / (det(a_t, qt[1, 0], p) - det(a_t, qt[1, 1], p))
    image = qt[0, 0] * (1 - s) * (1 - t) + qt[1, 0] * s * (1 - t) + qt[0, 1] * (1 - s) * t + qt[1, 1] * s * t
    back = {x: image[0] / image[2], y: image[1] / image[2]}
    assert sp.simplify(s_of.subs(back) - s) == 0 and sp.simplify(t_of.subs(back) - t) == 0
    numeric = qm.birational_inverse(quad, [[1.0, 1.5], [0.5, float(w[1][1])]], [[2.0, 3.0]])
    exact = [float(s_of.subs({x: 2, y: 3})), float(t_of.subs({x: 2, y: 3}))]
    np.testing.assert_allclose(numeric[0], exact, atol=1e-13)


@pytest.mark.parametrize("kind", ["convex", "trapezoid", "parallelogram", "nonconvex", "twisted"])
def test_round_trips_of_the_birational_inverse(kind):
    rng = np.random.default_rng(100 + ["convex", "trapezoid", "parallelogram", "nonconvex", "twisted"].index(kind))
    for _ in range(20):
        quad = random_quad(rng, kind)
        w = np.ones((2, 2))
        w[0, 0], w[1, 0], w[0, 1] = rng.uniform(0.3, 3, 3) * rng.choice([-1, 1], 3)
        w[1, 1] = qm.birational_weight(quad, w)
        params = rng.uniform(-0.5, 1.5, (30, 2))
        h = patch_point(qm.homogeneous_quad(quad, w), params[:, 0], params[:, 1])
        keep = np.abs(h[:, 2]) > 0.05 * np.abs(h).max()
        points = qm.quad_map(quad, params[keep, 0], params[keep, 1], w)
        np.testing.assert_allclose(qm.birational_inverse(quad, w, points), params[keep], atol=1e-8)


def test_the_concave_quad_region_with_preimages_in_the_square():
    quad, weights = CONCAVE.args("quad", "weights")
    weights[1, 1] = CONCAVE.results["w11"]
    a_s, a_t = qm.pencil_axes(quad)
    np.testing.assert_allclose(cartesian(a_s), CONCAVE.results["axis_s"])
    np.testing.assert_allclose(cartesian(a_t), CONCAVE.results["axis_t"], atol=1e-14)
    rng = np.random.default_rng(8)
    xy = rng.uniform([0, 0], [12, 6], (4000, 2))
    in_quad = Path(quad[[0, 1, 1, 0], [0, 0, 1, 1]]).contains_points(xy)
    region = Path(np.array([quad[0, 0], cartesian(a_t), quad[1, 1], cartesian(a_s)])).contains_points(xy)
    params, inside = qm.square_preimages(quad, xy, weights)
    np.testing.assert_array_equal(inside[in_quad], region[in_quad])
    assert inside[~in_quad].any()  # the erratum: the image of the square runs through infinity, beyond the quad
    np.testing.assert_allclose(qm.quad_map(quad, params[inside, 0], params[inside, 1], weights), xy[inside], atol=1e-9)


def test_the_twisted_quad_with_weights_four_inverts_into_the_square():
    quad, weights = TWISTED.args("quad", "weights")
    points = twisted_points(1000)
    params = qm.birational_inverse(quad, weights, points)
    assert np.all((params > -1e-12) & (params < 1 + 1e-12))
    np.testing.assert_allclose(qm.quad_map(quad, params[:, 0], params[:, 1], weights), points, atol=1e-9)


def test_the_collinear_case_uses_the_second_forms():
    quad, weights, params = COLLINEAR.args("quad", "weights", "parameters")
    weights[1, 1] = qm.birational_weight(quad, weights)
    a_s, a_t = qm.pencil_axes(quad)
    np.testing.assert_allclose(cartesian(a_s), COLLINEAR.results["axis_s"], atol=1e-12)
    np.testing.assert_allclose(cartesian(a_t), COLLINEAR.results["axis_t"], atol=1e-12)
    points = qm.quad_map(quad, params[:, 0], params[:, 1], weights)
    np.testing.assert_allclose(qm.birational_inverse(quad, weights, points), params, atol=1e-14)
    h = qm.homogeneous_quad(quad, weights)
    assert np.allclose(np.cross(a_s, h[0, 1]), 0) and np.allclose(np.cross(a_s, h[1, 1]), 0)  # (21.8) is 0/0
    base = qm.base_point(quad, weights)
    assert (base.s, base.t) == pytest.approx(tuple(COLLINEAR.results["base_point"]))
    with pytest.raises(ValueError, match="^s, t: .*infinity"):
        qm.quad_map(quad, 1.0, 1.0, weights)  # Q̃(1, 1) = 0: the base point


def test_the_base_point_of_the_notes_example():
    quad, weights = BASE.args("quad", "weights")
    base = qm.base_point(quad, weights)
    assert (base.s, base.t) == pytest.approx((BASE.results["s"], BASE.results["t"]), abs=1e-14)
    line = base.line / base.line[0] * BASE.results["line"][0]
    np.testing.assert_allclose(line, BASE.results["line"], atol=1e-12)
    # Exactly: Q̃(5/3, 9/4) = 0; t = 9/4 maps to As for every s, s = 5/3 to At for every t.
    s, t = sp.symbols("s t")
    q = [[sp.Matrix([0, 0, 1]), sp.Rational(5, 3) * sp.Matrix([8, 6, 1])],
         [sp.Matrix([12, 0, 1]), sp.Matrix([12, 4, 1])]]
    image = q[0][0] * (1 - s) * (1 - t) + q[1][0] * s * (1 - t) + q[0][1] * (1 - s) * t + q[1][1] * s * t
    assert sp.simplify(image.subs({s: sp.Rational(5, 3), t: sp.Rational(9, 4)})) == sp.zeros(3, 1)
    on_t = image.subs(t, sp.Rational(9, 4))
    assert sp.simplify(on_t[0] / on_t[2]) == 12 and sp.simplify(on_t[1] / on_t[2]) == 9
    on_s = image.subs(s, sp.Rational(5, 3))
    assert sp.simplify(on_s[0] / on_s[2]) == 20 and sp.simplify(on_s[1] / on_s[2]) == 0
    # Points of the line 9x + 8y = 180 all share that pre-image.
    xs = np.array([4.0, 8.0, 16.0])
    np.testing.assert_allclose(qm.birational_inverse(quad, weights, np.column_stack([xs, (180 - 9 * xs) / 8])),
                               [[5 / 3, 9 / 4]] * 3, atol=1e-12)


def test_points_on_the_axes_are_refused():
    a_s, _ = qm.pencil_axes(QUAD)
    with pytest.raises(ValueError, match="^points: row"):
        qm.birational_inverse(QUAD, W53, [cartesian(a_s), [8.0, 4.0]])


# --- projective weights ---------------------------------------------------------------------------------


def test_the_notes_projective_weights():
    quad = PROJECTIVE.inputs["quad"]
    w = qm.projective_weights(quad)
    np.testing.assert_allclose(w, PROJECTIVE.results["weights"])
    np.testing.assert_allclose(w / w[0, 0] * 16, PROJECTIVE.results["determinants"])
    h = qm.homogeneous_quad(quad, w)
    np.testing.assert_allclose(h[0, 0] - h[1, 0] - h[0, 1] + h[1, 1], 0, atol=1e-12)
    assert qm.is_birational(quad, w)


def dlt_homography(source, target) -> np.ndarray:
    """The homography sending four points to four, by the direct linear transform (h33 = 1, an 8 × 8 solve)."""
    rows, rhs = [], []
    for (u, v), (x, y) in zip(source, target):
        rows += [[u, v, 1, 0, 0, 0, -u * x, -v * x], [0, 0, 0, u, v, 1, -u * y, -v * y]]
        rhs += [x, y]
    return np.append(np.linalg.solve(rows, rhs), 1.0).reshape(3, 3)


@pytest.mark.parametrize("kind", ["convex", "nonconvex", "twisted"])
def test_projective_weights_agree_with_a_dlt_homography(kind):
    rng = np.random.default_rng(40 + ["convex", "nonconvex", "twisted"].index(kind))
    for _ in range(10):
        quad = random_quad(rng, kind)
        w = qm.projective_weights(quad)
        assert w[0, 0] == 1 and abs(qm.weight_condition(quad, w)) < 1e-12
        square = [(0, 0), (1, 0), (0, 1), (1, 1)]
        dlt = dlt_homography(square, [quad[i, j] for i, j in square])
        params = rng.uniform(0, 1, (20, 2))
        expected = cartesian(np.column_stack([params, np.ones(20)]) @ dlt.T)
        h = np.column_stack([params, np.ones(20)]) @ qm.homography(quad).T
        keep = np.abs(h[:, 2]) > 1e-3 * np.abs(h).max()
        np.testing.assert_allclose(cartesian(h)[keep], expected[keep], rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(qm.quad_map(quad, params[keep, 0], params[keep, 1], w), expected[keep],
                                   rtol=1e-9, atol=1e-9)


def test_projective_weights_need_no_three_collinear_corners():
    with pytest.raises(ValueError, match="^quad: three corners are collinear"):
        qm.projective_weights(COLLINEAR.inputs["quad"])


# --- axes, errors and the square ----------------------------------------------------------------------


def test_pencil_axes_of_the_notes_quad_and_of_a_parallelogram():
    a_s, a_t = qm.pencil_axes(QUAD)
    np.testing.assert_allclose(cartesian(a_s), BILINEAR.results["axis_s"])
    np.testing.assert_allclose(cartesian(a_t), BILINEAR.results["axis_t"], atol=1e-14)
    assert np.linalg.norm(a_s) == pytest.approx(1) and a_s[2] > 0
    a_s, a_t = qm.pencil_axes([[(0.0, 0.0), (1.0, 2.0)], [(3.0, 0.0), (4.0, 2.0)]])
    assert a_s[2] == 0 and a_t[2] == 0  # both at infinity, along the edges' directions
    assert abs(a_s[0] * 2.0 - a_s[1] * 1.0) < 1e-15 and abs(a_t[1]) < 1e-15


@pytest.mark.parametrize("quad, message", [
    ([[(0.0, 0.0)], [(2.0, 0.0)]], "^quad: expected shape"),
    ([[(0.0, 0.0), (0.0, 0.0)], [(2.0, 0.0), (1.0, 1.0)]], "^quad: corners Q00 and Q01 coincide"),
    ([[(0.0, 0.0), (1.0, 1.0)], [(2.0, 2.0), (3.0, 3.0)]], "^quad: the four corners lie on one line"),
    ([[(0.0, 0.0, 0.0), (1.0, 1.0, 0.0)], [(2.0, 0.0, 0.0), (1.0, 2.0, 0.0)]], "^quad: expected shape"),
])
def test_bad_quads_are_refused_by_name(quad, message):
    for call in (lambda: qm.bilinear_inverse(quad, (1.0, 1.0)), lambda: qm.pencil_axes(quad),
                 lambda: qm.birational_weight(quad, UNIT), lambda: qm.projective_weights(quad)):
        with pytest.raises(ValueError, match=message):
            call()


def test_bad_points_and_weights_are_refused_by_name():
    with pytest.raises(ValueError, match="^point: expected one point"):
        qm.bilinear_inverse(QUAD, [[1.0, 2.0]])
    with pytest.raises(ValueError, match="^points: expected"):
        qm.birational_inverse(QUAD, W53, [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="^weights: expected shape"):
        qm.birational_weight(QUAD, [1.0, 1.0, 1.0])
    with pytest.raises(ValueError, match="^weights: w00, w10 and w01 must be nonzero"):
        qm.birational_weight(QUAD, [[0.0, 1.0], [1.0, 1.0]])
    with pytest.raises(ValueError, match="^quad: Q00, Q10, Q11 are collinear"):
        qm.birational_weight([[(0.0, 0.0), (0.0, 2.0)], [(1.0, 0.0), (2.0, 0.0)]], UNIT)
    with pytest.raises(TypeError, match="^s, t: give exactly one"):
        qm.isoparameter_lines(QUAD)


def test_square_preimages_pick_the_root_in_the_square():
    rng = np.random.default_rng(9)
    params = rng.uniform(0, 1, (200, 2))
    points = qm.quad_map(QUAD, params[:, 0], params[:, 1])
    found, inside = qm.square_preimages(QUAD, points)
    assert inside.all()
    np.testing.assert_allclose(found, params, atol=1e-9)
    found, inside = qm.square_preimages(QUAD, qm.quad_map(QUAD, params[:, 0], params[:, 1], W53), W53)
    assert inside.all()
    np.testing.assert_allclose(found, params, atol=1e-12)
    _, inside = qm.square_preimages(QUAD, [(-1.0, 0.0), (13.0, 2.0)])
    assert not inside.any()


def test_warping_with_the_birational_map_is_undone_exactly():
    rng = np.random.default_rng(12)
    image = rng.uniform(0, 1, (16, 24))
    raster, covered = qm.warp_image(image, QUAD, ((0.0, 0.0), (12.0, 6.0)), (60, 120), W53)
    assert 0.4 < covered.mean() < 0.9
    # Every pixel centre of the square, mapped into the quad and back, lands on its own pixel.
    rows, cols = np.mgrid[0:16, 0:24]
    s, t = (cols.ravel() + 0.5) / 24, (rows.ravel() + 0.5) / 16
    back = qm.birational_inverse(QUAD, W53, qm.quad_map(QUAD, s, t, W53))
    np.testing.assert_allclose(back, np.column_stack([s, t]), atol=1e-14)
    restored = image[(back[:, 1] * 16).astype(int), (back[:, 0] * 24).astype(int)].reshape(16, 24)
    np.testing.assert_array_equal(restored, image)
    # The projective map through its weights and the bilinear map cover the same quad.
    _, bilinear = qm.warp_image(image, QUAD, ((0.0, 0.0), (12.0, 6.0)), (60, 120))
    _, projective = qm.warp_image(image, QUAD, ((0.0, 0.0), (12.0, 6.0)), (60, 120), qm.projective_weights(QUAD))
    assert (bilinear != covered).mean() < 0.02 and (projective != covered).mean() < 0.02


def test_warp_image_refuses_bad_arguments():
    with pytest.raises(ValueError, match="^image:"):
        qm.warp_image([1.0, 2.0], QUAD, ((0.0, 0.0), (1.0, 1.0)), (2, 2))
    with pytest.raises(ValueError, match="^window:"):
        qm.warp_image([[1.0]], QUAD, ((1.0, 0.0), (0.0, 1.0)), (2, 2))
    with pytest.raises(ValueError, match="^size:"):
        qm.warp_image([[1.0]], QUAD, ((0.0, 0.0), (1.0, 1.0)), (2, 0))
