"""Unit tests of cagd_ref.surfaces: tensor-product patches and the O(n²) points and tangents of chapter 16.

The course's examples of chapter 16 (the notes state only operation counts) come from
cagd_course/examples/ch16.toml and are checked here with exact fractions. Every function is also
checked against independent peers: SymPy derivatives, `bezier.derivative` and the tensor de Casteljau
algorithm, central finite differences, `scipy.interpolate.NdBSpline` (a Bézier patch is a B-spline
patch with Bézier end knots), geomdl, and analytic surfaces (a paraboloid, a saddle, a rational
cylinder and a torus patch). The operation counts are measured by running the algorithms on numbers
that tally their own arithmetic, as the tests of chapter 3 do.
"""

from __future__ import annotations

from math import comb

import numpy as np
import pytest
import sympy as sp
from scipy.interpolate import NdBSpline

from cagd_course.examples import notes_example
from cagd_ref import bezier, bspline
from cagd_ref import surfaces as su
from cagd_ref.polynomials import bernstein_horner

CUBIC = notes_example("16.rational_cubic")
CIRCLE = notes_example("16.quarter_circle")
PATCH = notes_example("16.rational_patch")
TORUS = notes_example("16.torus")
COSTS = notes_example("16.costs")
NEAR_ONE = notes_example("16.near_one")
COPLANAR = notes_example("16.coplanar")

SADDLE = np.array([[(0.0, 0.0, 0.0), (0.0, 1.0, 0.0)], [(1.0, 0.0, 0.0), (1.0, 1.0, 1.0)]])  # z = s t


def random_patch(seed: int, m: int, n: int, rational: bool = True, d: int = 3):
    rng = np.random.default_rng(seed)
    points = rng.uniform(-2, 2, (m + 1, n + 1, d))
    return points, (rng.uniform(0.4, 2.5, (m + 1, n + 1)) if rational else None)


def parameter_pairs(seed: int, count: int = 40):
    """Random pairs in the unit square, with the corners, the edges' midpoints and (1/2, 1/2) first."""
    rng = np.random.default_rng(seed)
    fixed = np.array([(0, 0), (1, 0), (0, 1), (1, 1), (0.5, 0.5), (0.5, 0), (1, 0.5), (0.999999, 0.3)])
    pairs = np.vstack([fixed, rng.uniform(0, 1, (count, 2))])
    return pairs[:, 0], pairs[:, 1]


def homogeneous_net(points, weights):
    points = np.asarray(points, float)
    w = np.ones(points.shape[:2]) if weights is None else np.asarray(weights, float)
    return np.concatenate([points * w[..., None], w[..., None]], axis=2)


# --- the course's examples ------------------------------------------------------------------------


def test_split_qr_of_the_rational_cubic():
    q, r = su.split_qr(*CUBIC.args("points", "weights"))
    np.testing.assert_array_equal(q, CUBIC.results["q_points"])
    np.testing.assert_array_equal(r, CUBIC.results["r_points"])
    np.testing.assert_allclose(su.pseudo_power(q), CUBIC.results["q_hat"])
    # Q̂(u) at t = 1/4, u = 1/3, is Q(1/4) / (3/4)²: the pseudo-power form before its scale factor.
    q_hat = np.polynomial.polynomial.polyval(1 / 3, su.pseudo_power(q))
    np.testing.assert_allclose(q_hat, CUBIC.results["q_hat_quarter"])


def test_split_qr_of_a_polynomial_curve_has_unit_weights():
    q, r = su.split_qr([(0.0, 1.0), (2.0, 3.0)])
    assert q.tolist() == [[0.0, 1.0, 1.0]] and r.tolist() == [[2.0, 3.0, 1.0]]


def test_curve_point_tangent_and_derivative_of_the_rational_cubic():
    points, weights, ts = CUBIC.args("points", "weights", "ts")
    p, q, r = su.curve_point_tangent(points, ts, weights)
    for name, value in (("p", p), ("q", q), ("r", r)):
        np.testing.assert_allclose(value, CUBIC.results[name], rtol=1e-14, atol=1e-15, err_msg=name)
    p2, dp = su.curve_point_derivative(points, ts, weights)
    np.testing.assert_allclose(p2, CUBIC.results["p"], rtol=1e-14, atol=1e-15)
    np.testing.assert_allclose(dp, CUBIC.results["derivative"], rtol=1e-14, atol=1e-14)
    # The length of p' is n Q_w R_w / P_w² times |r - q|, not n |r - q|.
    np.testing.assert_allclose(dp, CUBIC.results["factor"][:, None] * (r - q), rtol=1e-13, atol=1e-14)


def test_the_quarter_circle():
    points, weights, t, ts = CIRCLE.args("points", "weights", "t", "ts")
    p, q, r = su.curve_point_tangent(points, t, weights)
    for name, value in (("p", p), ("q", q), ("r", r)):
        np.testing.assert_allclose(value, CIRCLE.results[name], rtol=1e-15, atol=1e-16)
    _, dp = su.curve_point_derivative(points, t, weights)
    np.testing.assert_allclose(dp, CIRCLE.results["derivative"], rtol=1e-14)
    p, dp = su.curve_point_derivative(points, ts, weights)
    np.testing.assert_allclose(np.linalg.norm(dp, axis=1), CIRCLE.results["speeds"], rtol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(p, axis=1), 1.0, rtol=1e-15)
    np.testing.assert_allclose(np.einsum("ij,ij->i", p, dp), 0.0, atol=1e-15)


def test_the_rational_patch_of_degree_two_one():
    points, weights, s, t = PATCH.args("points", "weights", "s", "t")
    p, p_s, p_t = su.patch_point_tangents(points, s, t, weights)
    for name, value in (("p", p), ("p_s", p_s), ("p_t", p_t)):
        np.testing.assert_allclose(value, PATCH.results[name], rtol=1e-14, atol=1e-15, err_msg=name)
    np.testing.assert_allclose(su.patch_normal(points, s, t, weights), PATCH.results["normal"], atol=5e-9)
    np.testing.assert_allclose(su.patch_point(points, s, t, weights), PATCH.results["p"], rtol=1e-14)
    assert su.point_tangent_cost(2, 1)["sub_patches"] == (PATCH.results["operations"],) * 2


def test_the_rational_patch_exactly_with_sympy():
    points, weights = PATCH.args("points", "weights")
    s, t = sp.symbols("s t")
    h = homogeneous_net(points, weights)
    basis_s = [sp.binomial(2, i) * s**i * (1 - s) ** (2 - i) for i in range(3)]
    basis_t = [1 - t, t]
    value = [sum(sp.Rational(int(h[i, j, c])) * basis_s[i] * basis_t[j] for i in range(3) for j in range(2))
             for c in range(4)]
    point = [sp.simplify(x / value[3]) for x in value[:3]]
    for k, (a, b) in enumerate(zip(PATCH.inputs["s"], PATCH.inputs["t"])):
        at = {s: sp.nsimplify(a), t: sp.nsimplify(b)}
        exact_s = [float(sp.diff(x, s).subs(at)) for x in point]
        exact_t = [float(sp.diff(x, t).subs(at)) for x in point]
        np.testing.assert_allclose(PATCH.results["p_s"][k], exact_s, rtol=1e-14, atol=1e-15)
        np.testing.assert_allclose(PATCH.results["p_t"][k], exact_t, rtol=1e-14, atol=1e-15)


def test_the_torus_patch():
    points, weights, s, t = TORUS.args("points", "weights", "s", "t")
    big, small = TORUS.inputs["major"], TORUS.inputs["minor"]
    p, p_s, p_t = su.patch_point_tangents(points, s, t, weights)
    normal = su.patch_normal(points, s, t, weights)
    np.testing.assert_allclose(p, TORUS.results["p"], atol=1e-10)
    np.testing.assert_allclose(p_s[:3], TORUS.results["p_s"], atol=1e-10)
    np.testing.assert_allclose(p_t[:3], TORUS.results["p_t"], atol=1e-10)
    np.testing.assert_allclose(normal, TORUS.results["normal"], atol=1e-10)
    np.testing.assert_allclose([np.linalg.norm(p_s[0]), np.linalg.norm(p_t[0])], TORUS.results["speeds"], rtol=1e-14)
    # On a 7 × 7 grid: points on the torus, normals along the tube's radius, pointing out.
    grid = np.linspace(0, 1, 7)
    gs, gt = (g.ravel() for g in np.meshgrid(grid, grid, indexing="ij"))
    p = su.patch_point(points, gs, gt, weights)
    rho = np.hypot(p[:, 0], p[:, 1])
    np.testing.assert_allclose((rho - big) ** 2 + p[:, 2] ** 2, small**2, atol=1e-14)
    centre = np.column_stack([p[:, :2] * (big / rho)[:, None], np.zeros(len(p))])
    np.testing.assert_allclose(su.patch_normal(points, gs, gt, weights), (p - centre) / small, atol=1e-14)


def test_the_operation_counts_of_the_notes():
    for (m, n), horner, casteljau in zip(COSTS.inputs["degrees"].astype(int), COSTS.results["sub_patch_horner"],
                                         COSTS.results["de_casteljau_interpolations"]):
        costs = su.point_tangent_cost(int(m), int(n))
        assert costs["sub_patches"] == (horner, horner) == (16 * (m * n - 1),) * 2
        assert costs["de_casteljau"] == (2 * casteljau, casteljau)
    for n in range(1, 12):
        assert su.point_tangent_cost(n, n)["sub_patches"][0] == 16 * n * n - 16


# --- counting the operations --------------------------------------------------------------------


class Tally:
    """A number that counts the floating-point multiplies and adds done with it (a test-only peer)."""

    def __init__(self, value, counts):
        self.value, self.counts = float(value), counts

    def _counted(self, kind, result):
        self.counts[kind] += 1
        return Tally(result, self.counts)

    def __mul__(self, other):
        return self._counted("multiplies", self.value * float(other))

    __rmul__ = __mul__

    def __add__(self, other):
        return self._counted("adds", self.value + float(other))

    __radd__ = __add__

    def __float__(self):
        return self.value


def _sub_patches_by_hand(h, u, v):
    """The four sub-patches' pseudo-power Horner by hand, every component: n rows in u, then one pass in v."""
    m, n = len(h) - 1, len(h[0]) - 1
    values = {}
    for i0 in (0, 1):
        for j0 in (0, 1):
            for c in range(len(h[0][0])):
                hat = [[comb(m - 1, a) * comb(n - 1, b) * h[i0 + a][j0 + b][c] for b in range(n)] for a in range(m)]
                rows = []
                for b in range(n):
                    value = hat[m - 1][b]
                    for a in range(m - 2, -1, -1):
                        value = value * u + hat[a][b]
                    rows.append(value)
                value = rows[n - 1]
                for b in range(n - 2, -1, -1):
                    value = value * v + rows[b]
                values[i0, j0, c] = value
    return values


def _de_casteljau_by_hand(h, s, t, one_minus_s, one_minus_t):
    """Tensor de Casteljau by hand down to the 2 × 2 net: rounds in s on every column, then in t on two rows."""
    m, n = len(h) - 1, len(h[0]) - 1
    values = {}
    for c in range(len(h[0][0])):
        columns = [[h[i][j][c] for i in range(m + 1)] for j in range(n + 1)]
        for j in range(n + 1):
            while len(columns[j]) > 2:
                columns[j] = [one_minus_s * a + s * b for a, b in zip(columns[j], columns[j][1:])]
        for k in (0, 1):
            row = [columns[j][k] for j in range(n + 1)]
            while len(row) > 2:
                row = [one_minus_t * a + t * b for a, b in zip(row, row[1:])]
            values[k, 0, c], values[k, 1, c] = row
    return values


@pytest.mark.parametrize("m, n", [(1, 1), (2, 1), (1, 3), (3, 3), (2, 4), (4, 2), (5, 6)])
def test_point_tangent_cost_counts_what_the_algorithms_do(m, n):
    points, weights = random_patch(m * 10 + n, m, n)
    h = homogeneous_net(points, weights)
    costs = su.point_tangent_cost(m, n)
    s, t = 0.3, 0.2  # both below 1/2: the forms in u = s/(1-s), v = t/(1-t)
    exact = su._sub_patch_values(h, np.array([s]), np.array([t]))[0]
    counts = {"multiplies": 0, "adds": 0}
    values = _sub_patches_by_hand(h.tolist(), Tally(s / (1 - s), counts), Tally(t / (1 - t), counts))
    assert costs["sub_patches"] == (counts["multiplies"], counts["adds"])
    for (i0, j0, c), value in values.items():
        assert float(value) == pytest.approx(exact[i0, j0, c], rel=1e-13, abs=1e-13)
    counts = {"multiplies": 0, "adds": 0}
    values = _de_casteljau_by_hand(h.tolist(), Tally(s, counts), Tally(t, counts), Tally(1 - s, counts),
                                   Tally(1 - t, counts))
    assert costs["de_casteljau"] == (counts["multiplies"], counts["adds"])
    net = su._de_casteljau_net(h, np.array([s]), np.array([t]))[0]
    scale = (1 - s) ** (m - 1) * (1 - t) ** (n - 1)
    for (i0, j0, c), value in values.items():
        assert float(value) == pytest.approx(net[i0, j0, c], rel=1e-13, abs=1e-13)
        assert float(value) == pytest.approx(exact[i0, j0, c] * scale, rel=1e-12, abs=1e-13)  # the same, scaled


# --- curves: Q, R and the pseudo-power form --------------------------------------------------------


@pytest.mark.parametrize("seed", range(6))
def test_curve_point_derivative_agrees_with_the_quotient_rule(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 9))
    points = rng.uniform(-3, 3, (n + 1, 3))
    weights = rng.uniform(0.3, 3, n + 1) if seed % 2 else None
    ts = np.concatenate([[0.0, 0.5, 1.0], rng.uniform(-0.5, 1.5, 20)])
    p, dp = su.curve_point_derivative(points, ts, weights)
    np.testing.assert_allclose(p, bezier.evaluate(points, ts, weights), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(dp, bezier.derivative(points, ts, 1, weights), rtol=1e-11, atol=1e-11)


def test_the_derivative_at_the_ends_is_the_endpoint_formula():
    points, weights = CUBIC.args("points", "weights")
    _, dp = su.curve_point_derivative(points, [0.0, 1.0], weights)
    np.testing.assert_allclose(dp[0], 3 * weights[1] / weights[0] * (points[1] - points[0]))
    np.testing.assert_allclose(dp[1], 3 * weights[2] / weights[3] * (points[3] - points[2]))


def test_p_divides_the_tangent_segment_at_t_r_w_over_p_w():
    points, weights = CUBIC.args("points", "weights")
    q_points, r_points = su.split_qr(points, weights)
    for t in (0.1, 0.31, 0.5, 0.77):
        p, q, r = su.curve_point_tangent(points, t, weights)
        r_w, q_w = bernstein_horner(r_points[:, -1], t), bernstein_horner(q_points[:, -1], t)
        np.testing.assert_allclose(p, q + t * r_w / ((1 - t) * q_w + t * r_w) * (r - q), rtol=1e-14)
        # q and r are the last-but-one level of de Casteljau's triangle, projected.
        level = bezier.de_casteljau_triangle(bezier.to_homogeneous(points, weights), t)[-2]
        np.testing.assert_allclose(np.vstack([q, r]), level[:, :-1] / level[:, -1:], rtol=1e-13)


def test_a_constant_curve_has_a_zero_derivative():
    p, dp = su.curve_point_derivative([(1.0, 2.0)], [0.0, 0.4])
    assert p.tolist() == [[1.0, 2.0], [1.0, 2.0]] and not dp.any()


@pytest.mark.parametrize("degree", [0, 1, 3, 8, 25])
def test_pseudo_horner_agrees_with_the_nested_bernstein_form_for_any_t(degree):
    coeffs = np.random.default_rng(degree).normal(size=(degree + 1, 2))
    ts = np.concatenate([np.linspace(-3, 4, 29), [0.5, 0.5 - 1e-12, 1 - 1e-12, 1.0]])
    np.testing.assert_allclose(su.pseudo_horner(coeffs, ts), bezier.de_casteljau(coeffs, ts), rtol=1e-11, atol=1e-11)
    np.testing.assert_allclose(su.pseudo_horner(coeffs[:, 0], ts), bernstein_horner(coeffs[:, 0], ts),
                               rtol=1e-11, atol=1e-11)
    assert su.pseudo_horner(coeffs, 1.0).tolist() == coeffs[-1].tolist()
    assert su.pseudo_horner(coeffs, 0.0).tolist() == coeffs[0].tolist()


def test_the_switch_keeps_the_form_finite_and_accurate_near_one():
    high = NEAR_ONE.inputs["degree_high"]
    coeffs = float(NEAR_ONE.inputs["coefficient_base"]) ** np.arange(high + 1)  # (1 + t)^N
    gap = NEAR_ONE.results["overflow_gap_high"]
    ts = np.array([0.0, 0.3, 0.5, 1 - gap, 1 - 1e-15, 1.0])
    np.testing.assert_allclose(su.pseudo_horner(coeffs, ts), (1 + ts) ** high, rtol=1e-13)
    # The first form alone: u^N overflows at 1 - t = 1e-8 for degree 40 ...
    with np.errstate(over="ignore", invalid="ignore"):
        u = (1 - gap) / gap
        assert not np.isfinite(np.polynomial.polynomial.polyval(u, su.pseudo_power(coeffs)) * gap**high)
    # ... while degree 7 is still accurate at 1 - t = 1e-15 (and divides by zero at t = 1 only).
    low = NEAR_ONE.inputs["degree_moderate"]
    t = 1 - NEAR_ONE.results["accurate_gap_moderate"]
    c = 2.0 ** np.arange(low + 1)
    unswitched = np.polynomial.polynomial.polyval(t / (1 - t), su.pseudo_power(c)) * (1 - t) ** low
    assert unswitched == pytest.approx((1 + t) ** low, rel=1e-14)


def test_pseudo_power_scales_by_binomials():
    np.testing.assert_array_equal(su.pseudo_power([[1.0, 2.0], [1.0, 2.0], [1.0, 2.0]]), [[1, 2], [2, 4], [1, 2]])


# --- patches: points ----------------------------------------------------------------------------


def _scipy_patch(points, weights):
    """A Bézier patch as a SciPy tensor-product B-spline on its homogeneous net, knots in the notes' convention."""
    h = homogeneous_net(points, weights)
    m, n = h.shape[0] - 1, h.shape[1] - 1
    ks, _, _ = bspline.to_scipy(h[:, 0], bspline.bezier_end_knots(m + 1, m, 0.0, 1.0)) if m else (None,) * 3
    kt, _, _ = bspline.to_scipy(h[0], bspline.bezier_end_knots(n + 1, n, 0.0, 1.0)) if n else (None,) * 3
    return NdBSpline((ks, kt), h, (m, n))


@pytest.mark.parametrize("m, n, rational", [(3, 3, False), (2, 5, True), (5, 5, True), (1, 4, False), (6, 2, True)])
def test_patch_point_agrees_with_scipy_ndbspline(m, n, rational):
    points, weights = random_patch(m + 7 * n, m, n, rational)
    s, t = parameter_pairs(m * n)
    h = _scipy_patch(points, weights)(np.column_stack([s, t]))
    np.testing.assert_allclose(su.patch_point(points, s, t, weights), h[:, :-1] / h[:, -1:], rtol=1e-12, atol=1e-13)


def test_patch_point_is_curve_evaluation_along_t_then_s():
    points, weights = random_patch(3, 3, 4)
    h = homogeneous_net(points, weights)
    for s, t in [(0.2, 0.9), (0.75, 0.1), (1.3, -0.2)]:
        rows = np.array([bezier.de_casteljau(h[i], t) for i in range(4)])
        expected = bezier.de_casteljau(rows, s)
        np.testing.assert_allclose(su.patch_point(points, s, t, weights), expected[:-1] / expected[-1], rtol=1e-12)


def test_patch_point_reproduces_analytic_surfaces():
    s, t = parameter_pairs(1)
    # z = x² + y² over [-1, 1]²: degree (2, 2) with the middle control point at z = -1 on every edge.
    paraboloid = np.array([[(-1 + i, -1 + j, 0.0) for j in range(3)] for i in range(3)])
    paraboloid[..., 2] = [[2, 0, 2], [0, -2, 0], [2, 0, 2]]
    p = su.patch_point(paraboloid, s, t)
    np.testing.assert_allclose(p[:, :2], np.column_stack([2 * s - 1, 2 * t - 1]), atol=1e-15)
    np.testing.assert_allclose(p[:, 2], p[:, 0] ** 2 + p[:, 1] ** 2, atol=1e-14)
    np.testing.assert_allclose(su.patch_point(SADDLE, s, t), np.column_stack([s, t, s * t]), atol=1e-15)
    # A quarter of the unit cylinder x² + y² = 1, 0 <= z <= 2: degree (2, 1), rational in s.
    c = np.sqrt(2) / 2
    arc = [(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    cylinder = np.array([[(x, y, 0.0), (x, y, 2.0)] for x, y in arc])
    weights = np.array([[1.0, 1.0], [c, c], [1.0, 1.0]])
    p = su.patch_point(cylinder, s, t, weights)
    np.testing.assert_allclose(p[:, 0] ** 2 + p[:, 1] ** 2, 1.0, atol=1e-15)
    np.testing.assert_allclose(p[:, 2], 2 * t, atol=1e-15)
    normal = su.patch_normal(cylinder, s, t, weights)
    np.testing.assert_allclose(normal, np.column_stack([p[:, 0], p[:, 1], np.zeros(len(p))]), atol=1e-14)


def test_parameters_broadcast_together():
    points, weights = random_patch(4, 2, 3)
    ts = np.linspace(0, 1, 5)
    together = su.patch_point(points, 0.4, ts, weights)
    assert together.shape == (5, 3)
    np.testing.assert_allclose(together, su.patch_point(points, np.full(5, 0.4), ts, weights))
    assert su.patch_point(points, 0.4, 0.6, weights).shape == (3,)
    assert su.patch_point(points, [0.4], 0.6, weights).shape == (1, 3)
    assert su.patch_point(points, [], 0.6).shape == (0, 3)
    with pytest.raises(ValueError, match="^s, t"):
        su.patch_point(points, [0.1, 0.2], [0.1, 0.2, 0.3])


def test_many_pairs_are_evaluated_a_block_at_a_time():
    points, weights = random_patch(5, 3, 3)
    rng = np.random.default_rng(5)
    s, t = rng.uniform(0, 1, (2, 70_000))
    many = su.patch_point(points, s, t, weights)
    np.testing.assert_allclose(many[-5:], su.patch_point(points, s[-5:], t[-5:], weights), rtol=1e-14)
    p, p_s, p_t = su.patch_point_tangents(points, s, t, weights)
    np.testing.assert_allclose(p, many, rtol=1e-12, atol=1e-13)


# --- patches: the four sub-patches and the tangents ------------------------------------------------


@pytest.mark.parametrize("m, n", [(1, 1), (2, 1), (1, 3), (3, 2), (4, 4)])
def test_the_bilinear_blend_of_the_sub_patches_is_the_patch(m, n):
    points, weights = random_patch(m * 5 + n, m, n)
    subs = su.sub_patches(points, weights)
    assert all(sub.shape == (m, n, 4) for sub in subs)
    h = homogeneous_net(points, weights)
    np.testing.assert_array_equal(subs[1], h[1:, :n])  # P^10 drops the first row in s
    np.testing.assert_array_equal(subs[2], h[:m, 1:])  # P^01 the first column in t
    s, t = parameter_pairs(m + n)
    a, b = np.column_stack([1 - s, s]), np.column_stack([1 - t, t])
    blend = sum(a[:, i0, None] * b[:, j0, None] * su.patch_point(sub, s, t)
                for sub, (i0, j0) in zip(subs, [(0, 0), (1, 0), (0, 1), (1, 1)]))
    np.testing.assert_allclose(blend, su.patch_point(h, s, t), rtol=1e-12, atol=1e-13)
    # Their values at (s, t) are the 2 × 2 net de Casteljau leaves before its last step.
    values = su._sub_patch_values(h, s, t)
    net = su._de_casteljau_net(h, s, t)
    for sub, (i0, j0) in zip(subs, [(0, 0), (1, 0), (0, 1), (1, 1)]):
        np.testing.assert_allclose(net[:, i0, j0], su.patch_point(sub, s, t), rtol=1e-12, atol=1e-13)
        ours, theirs = values[:, i0, j0], net[:, i0, j0]
        np.testing.assert_allclose(ours[:, :-1] / ours[:, -1:], theirs[:, :-1] / theirs[:, -1:], rtol=1e-11, atol=1e-12)


@pytest.mark.parametrize("m, n, rational", [(3, 3, True), (2, 4, True), (4, 2, False), (1, 1, True), (1, 3, False),
                                            (7, 5, True), (10, 10, True)])
def test_tangents_agree_with_de_casteljau_and_finite_differences(m, n, rational):
    points, weights = random_patch(m * 3 + n, m, n, rational)
    s, t = parameter_pairs(m + 2 * n)
    p, p_s, p_t = su.patch_point_tangents(points, s, t, weights)
    for ours, theirs in zip((p, p_s, p_t), su.de_casteljau_point_tangents(points, s, t, weights)):
        np.testing.assert_allclose(ours, theirs, rtol=1e-10, atol=1e-10 * np.abs(theirs).max())
    np.testing.assert_allclose(p, su.patch_point(points, s, t, weights), rtol=1e-12, atol=1e-12)
    inner = (s > 1e-3) & (s < 1 - 1e-3) & (t > 1e-3) & (t < 1 - 1e-3)
    h = 1e-6
    for k, (ds, dt) in enumerate([(h, 0.0), (0.0, h)]):
        numeric = (su.patch_point(points, s[inner] + ds, t[inner] + dt, weights)
                   - su.patch_point(points, s[inner] - ds, t[inner] - dt, weights)) / (2 * h)
        np.testing.assert_allclose((p_s, p_t)[k][inner], numeric, rtol=1e-6, atol=1e-6 * np.abs(numeric).max())


def test_tangents_agree_with_scipy_derivatives_of_the_homogeneous_patch():
    points, weights = random_patch(11, 3, 4)
    s, t = parameter_pairs(11)
    spline, xi = _scipy_patch(points, weights), np.column_stack([s, t])
    h, h_s, h_t = (spline(xi, nu=nu) for nu in ((0, 0), (1, 0), (0, 1)))
    p = h[:, :-1] / h[:, -1:]
    _, p_s, p_t = su.patch_point_tangents(points, s, t, weights)
    np.testing.assert_allclose(p_s, (h_s[:, :-1] - h_s[:, -1:] * p) / h[:, -1:], rtol=1e-11, atol=1e-11)
    np.testing.assert_allclose(p_t, (h_t[:, :-1] - h_t[:, -1:] * p) / h[:, -1:], rtol=1e-11, atol=1e-11)


def test_the_paraboloid_and_the_saddle_have_their_analytic_tangents_and_normals():
    s, t = parameter_pairs(2)
    _, p_s, p_t = su.patch_point_tangents(SADDLE, s, t)
    np.testing.assert_allclose(p_s, np.column_stack([np.ones_like(s), 0 * s, t]), atol=1e-15)
    np.testing.assert_allclose(p_t, np.column_stack([0 * s, np.ones_like(s), s]), atol=1e-15)
    normal = np.column_stack([-t, -s, np.ones_like(s)]) / np.sqrt(1 + s * s + t * t)[:, None]
    np.testing.assert_allclose(su.patch_normal(SADDLE, s, t), normal, atol=1e-15)


def test_the_four_sub_patch_points_are_not_coplanar():
    net = np.random.default_rng(int(COPLANAR.inputs["seed"])).normal(size=(4, 4, 3))
    s, t = COPLANAR.inputs["s"], COPLANAR.inputs["t"]
    subs = su.sub_patches(net)
    corners = np.array([su.patch_point(sub[..., :3], s, t) for sub in subs])  # Π(S^00), Π(S^10), Π(S^01), Π(S^11)
    order = corners[[0, 2, 1, 3]]  # 00, 01, 10, 11
    volume = np.linalg.det(order[1:] - order[0]) / 6
    assert volume == pytest.approx(COPLANAR.results["volume"], rel=1e-9)
    three = np.cross(order[2] - order[0], order[1] - order[0])
    cosine = abs(three @ su.patch_normal(net, s, t)) / np.linalg.norm(three)
    assert np.degrees(np.arccos(cosine)) == pytest.approx(COPLANAR.results["angle_degrees"], rel=1e-9)


def test_a_direction_of_degree_zero_has_a_zero_tangent():
    curve = np.array([[(0.0, 0.0, 0.0), (1.0, 2.0, 0.0), (3.0, 1.0, 1.0)]])  # (1, 3, 3): a curve in t
    p, p_s, p_t = su.patch_point_tangents(curve, [0.2, 0.9], [0.3, 0.6])
    assert not p_s.any()
    np.testing.assert_allclose(p_t, bezier.derivative(curve[0], [0.3, 0.6]), rtol=1e-13)
    _, p_s, p_t = su.patch_point_tangents(curve.transpose(1, 0, 2), [0.3, 0.6], 0.5)
    assert not p_t.any()
    np.testing.assert_allclose(p_s, bezier.derivative(curve[0], [0.3, 0.6]), rtol=1e-13)


def test_geomdl_agrees_on_points_and_tangents():
    nurbs = pytest.importorskip("geomdl.NURBS")
    points, weights = random_patch(21, 3, 2)
    surface = nurbs.Surface()
    surface.degree_u, surface.degree_v = 3, 2
    surface.ctrlpts_size_u, surface.ctrlpts_size_v = 4, 3
    surface.ctrlptsw = homogeneous_net(points, weights).reshape(-1, 4).tolist()
    surface.knotvector_u = [0.0] * 4 + [1.0] * 4
    surface.knotvector_v = [0.0] * 3 + [1.0] * 3
    s, t = parameter_pairs(21, 10)
    p, p_s, p_t = su.patch_point_tangents(points, s, t, weights)
    for k in range(len(s)):
        derivatives = surface.derivatives(float(s[k]), float(t[k]), order=1)
        np.testing.assert_allclose(derivatives[0][0], p[k], rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(derivatives[1][0], p_s[k], rtol=1e-11, atol=1e-11)
        np.testing.assert_allclose(derivatives[0][1], p_t[k], rtol=1e-11, atol=1e-11)


def test_grid_point_tangents_by_forward_differencing():
    points, weights = random_patch(31, 3, 4)
    p, p_s, p_t = su.grid_point_tangents(points, 9, 6, weights)
    assert p.shape == p_s.shape == p_t.shape == (9, 6, 3)
    gs, gt = (g.ravel() for g in np.meshgrid(np.linspace(0, 1, 9), np.linspace(0, 1, 6), indexing="ij"))
    for ours, theirs in zip((p, p_s, p_t), su.patch_point_tangents(points, gs, gt, weights)):
        np.testing.assert_allclose(ours.reshape(-1, 3), theirs, rtol=1e-11, atol=1e-11)
    p, p_s, _ = su.grid_point_tangents([[(0.0, 0.0), (1.0, 1.0)]], 2, 3)
    assert p.shape == (2, 3, 2) and not p_s.any()


# --- normals and bad input -------------------------------------------------------------------------


def test_patch_normal_is_unit_and_oriented_p_s_cross_p_t():
    points, weights = random_patch(8, 3, 3)
    s, t = parameter_pairs(8)
    normal = su.patch_normal(points, s, t, weights)
    _, p_s, p_t = su.patch_point_tangents(points, s, t, weights)
    np.testing.assert_allclose(np.linalg.norm(normal, axis=1), 1.0, rtol=1e-14)
    assert np.all(np.einsum("ij,ij->i", normal, np.cross(p_s, p_t)) > 0)
    flipped = su.patch_normal(points[:, ::-1], s, 1 - t, weights[:, ::-1])  # t reversed: the normal turns over
    np.testing.assert_allclose(flipped, -normal, atol=1e-12)


def test_patch_normal_refuses_collapsed_edges_and_planar_nets():
    collapsed = np.array([[(0.0, 0.0, 1.0)] * 3, [(1.0, 0.0, 0.5), (1.0, 1.0, 0.5), (0.0, 1.0, 0.5)]])
    with pytest.raises(ValueError, match=r"^s, t: P_s × P_t vanishes"):
        su.patch_normal(collapsed, 0.0, 0.5)
    assert su.patch_normal(collapsed, 0.5, 0.5).shape == (3,)
    with pytest.raises(ValueError, match="^points"):
        su.patch_normal(SADDLE[..., :2], 0.5, 0.5)


@pytest.mark.parametrize("function", [su.patch_point, su.patch_point_tangents, su.de_casteljau_point_tangents])
def test_bad_nets_and_weights_are_refused_by_name(function):
    with pytest.raises(ValueError, match="^points"):
        function([(0.0, 0.0), (1.0, 1.0)], 0.5, 0.5)
    with pytest.raises(ValueError, match="^weights"):
        function(SADDLE, 0.5, 0.5, [[1.0, 1.0], [1.0, 0.0]])
    with pytest.raises(ValueError, match="^weights"):
        function(SADDLE, 0.5, 0.5, [1.0, 1.0, 1.0, 1.0])
    with pytest.raises(ValueError, match=r"^s, t: the rational patch passes through infinity"):
        function(SADDLE, 0.5, 0.5, [[1.0, 1.0], [-1.0, -1.0]])


def test_bad_curves_are_refused_by_name():
    with pytest.raises(ValueError, match="^points"):
        su.split_qr([(1.0, 2.0)])
    with pytest.raises(ValueError, match="^points"):
        su.curve_point_tangent([(1.0, 2.0)], 0.5)
    with pytest.raises(ValueError, match="^weights"):
        su.curve_point_derivative([(0.0, 0.0), (1.0, 1.0)], 0.5, [1.0, 0.0])
    with pytest.raises(ValueError, match="^t: the rational curve passes through infinity"):
        su.curve_point_derivative([(0.0, 0.0), (1.0, 1.0)], 0.5, [1.0, -1.0])
    with pytest.raises(ValueError, match="^points"):
        su.sub_patches([[(0.0, 0.0, 0.0), (1.0, 0.0, 0.0)]])
    with pytest.raises(ValueError, match="^coeffs"):
        su.pseudo_horner([[[1.0]]], 0.5)


# === chapter 15: tensor-product surfaces ==========================================================

FIG15 = notes_example("15.patch")
TESS = notes_example("15.tessellation")
CURVE_TESS = notes_example("15.curve_tessellation")
SPECIAL = notes_example("15.special_tessellations")
CURV = notes_example("15.corner_curvatures")
DERIV = notes_example("15.corner_derivatives")


def lattice(z, dx=1.0, dy=1.0):
    z = np.asarray(z, float)
    i, j = np.meshgrid(np.arange(z.shape[0]), np.arange(z.shape[1]), indexing="ij")
    return np.stack([dx * i, dy * j, z], axis=2)


FIG_NET = lattice(FIG15.inputs["z"], 1.0, 1.5)
TESS_NET = lattice(TESS.inputs["z"])


def sympy_patch(points, weights, domain=((0, 1), (0, 1))):
    """The rational patch as SymPy expressions in s, t over `domain`, and the symbols."""
    s, t = sp.symbols("s t")
    (s0, s1), (t0, t1) = domain
    u, v = (s - s0) / (s1 - s0), (t - t0) / (t1 - t0)
    h = homogeneous_net(points, weights)
    m, n = h.shape[0] - 1, h.shape[1] - 1
    basis = [[sp.binomial(m, i) * u**i * (1 - u) ** (m - i) * sp.binomial(n, j) * v**j * (1 - v) ** (n - j)
              for j in range(n + 1)] for i in range(m + 1)]
    coords = [sum(sp.Float(h[i, j, c], 30) * basis[i][j] for i in range(m + 1) for j in range(n + 1))
              for c in range(h.shape[2])]
    return [c / coords[-1] for c in coords[:-1]], s, t


def test_control_curves_iso_curves_and_both_de_casteljau_orders_agree():
    points, weights = random_patch(151, 3, 2)
    assert su.control_curves(points, "s").shape == (3, 4, 3) and su.control_curves(points, "t").shape == (4, 3, 3)
    s, t = parameter_pairs(151, 12)
    expected = su.patch_point(points, s, t, weights)
    for first in ("s", "t"):
        np.testing.assert_allclose(su.de_casteljau_patch(points, s, t, weights, first=first), expected, atol=1e-13)
    for c in FIG15.inputs["iso_values"]:
        beads, bead_weights = su.iso_curve(points, c, "s", weights)  # P(c, t), a rational curve in t
        np.testing.assert_allclose(bezier.evaluate(beads, t, bead_weights), su.patch_point(points, c, t, weights),
                                   atol=1e-13)
        beads, bead_weights = su.iso_curve(points, c, "t", weights)
        np.testing.assert_allclose(bezier.evaluate(beads, s, bead_weights), su.patch_point(points, s, c, weights),
                                   atol=1e-13)
    assert su.iso_curve(points, 0.3, "s")[1] is None
    with pytest.raises(ValueError, match="^direction"):
        su.iso_curve(points, 0.3, "u")


def test_the_corners_interpolate_and_the_boundary_curves_are_rows_and_columns():
    net = FIG_NET
    np.testing.assert_allclose(su.patch_point(net, [0, 1, 0, 1], [0, 0, 1, 1]), net[[0, 3, 0, 3], [0, 0, 2, 2]])
    t = np.linspace(0, 1, 9)
    # The notes' erratum: P(s, 0) (not P(0, t)) is the cubic on P00, P10, P20, P30; P(1, t) the quadratic P30, P31, P32.
    np.testing.assert_allclose(su.patch_point(net, t, 0.0), bezier.evaluate(net[:, 0], t), atol=1e-14)
    np.testing.assert_allclose(su.patch_point(net, 1.0, t), bezier.evaluate(net[3], t), atol=1e-14)
    assert "P(s,0)" in FIG15.errata["boundary_curves"].correct


def test_subdivision_sub_patches_and_elevation_keep_the_surface():
    points, weights = random_patch(152, 3, 2)
    quarter, qw = su.subpatch(points, (0, 0.5), (0, 0.5), weights)  # P_[0,½]×[0,½], Fig. 15.3c
    np.testing.assert_allclose(su.patch_point(quarter, 0.4, 0.8, qw), su.patch_point(points, 0.2, 0.4, weights),
                               atol=1e-13)
    piece, pw = su.subpatch(points, (0.2, 0.7), (0.3, 0.9), weights)
    np.testing.assert_allclose(su.patch_point(piece, 0.5, 0.5, pw), su.patch_point(points, 0.45, 0.6, weights),
                               atol=1e-13)
    for direction in ("s", "t"):
        (left, lw), (right, rw) = su.patch_subdivide(points, 0.3, direction, weights)
        a = (0.3 * 0.5, 0.6) if direction == "s" else (0.6, 0.3 * 0.5)
        np.testing.assert_allclose(su.patch_point(left, 0.5, 0.6, lw) if direction == "s" else
                                   su.patch_point(left, 0.6, 0.5, lw), su.patch_point(points, *a, weights), atol=1e-13)
        assert right.shape == points.shape
        raised, raised_w = su.patch_elevate(points, direction, 2, weights)
        assert raised.shape == ((6, 3, 3) if direction == "s" else (4, 5, 3))
        s, t = parameter_pairs(152, 8)
        np.testing.assert_allclose(su.patch_point(raised, s, t, raised_w), su.patch_point(points, s, t, weights),
                                   atol=1e-13)
    copy = points.copy()
    su.subpatch(points, (0.1, 0.2), (0.3, 0.4), weights)
    assert np.array_equal(copy, points)


def test_corner_derivatives_over_a_general_domain_against_sympy():
    rng = np.random.default_rng(int(DERIV.inputs["seed"]))
    points, weights = rng.uniform(-2, 2, (4, 3, 3)), rng.uniform(0.5, 2, (4, 3))
    domain = tuple(tuple(r) for r in DERIV.inputs["domain"].tolist())
    (s0, _), (t0, _) = domain
    expr, s, t = sympy_patch(points, weights, domain)
    d = su.corner_derivatives(points, weights, domain)
    for name, (ks, kt) in {"P_s": (1, 0), "P_t": (0, 1), "P_ss": (2, 0), "P_st": (1, 1), "P_tt": (0, 2)}.items():
        exact = [float(sp.diff(c, s, ks, t, kt).subs({s: s0, t: t0})) if ks and kt else
                 float(sp.diff(c, s, ks).subs({s: s0, t: t0})) if ks else float(sp.diff(c, t, kt).subs({s: s0, t: t0}))
                 for c in expr]
        np.testing.assert_allclose(d[name], exact, rtol=1e-10, atol=1e-10)
    # The notes' typo, n w10 - w00 in P_ss, is off whenever the degrees differ (here m = 3, n = 2).
    m, n, w = 3, 2, weights
    a1, a2 = w[1, 0] / w[0, 0] * (points[1, 0] - points[0, 0]), w[2, 0] / w[0, 0] * (points[2, 0] - points[0, 0])
    typo = (m * (m - 1) * a2 - 2 * m * ((n * w[1, 0] - w[0, 0]) / w[0, 0]) * a1) / (domain[0][1] - s0) ** 2
    assert np.linalg.norm(typo - d["P_ss"]) > 1e-3
    assert "m w10" in DERIV.errata["p_ss"].correct


def test_normals_by_subdivision_and_by_finite_differences():
    points, weights = random_patch(153, 3, 2)
    s, t = parameter_pairs(153, 10)
    normals = su.patch_normal(points, s, t, weights)
    h = 1e-6
    for k in range(len(s)):
        sk, tk = float(np.clip(s[k], h, 1 - h)), float(np.clip(t[k], h, 1 - h))
        p_s = (su.patch_point(points, sk + h, tk, weights) - su.patch_point(points, sk - h, tk, weights)) / (2 * h)
        p_t = (su.patch_point(points, sk, tk + h, weights) - su.patch_point(points, sk, tk - h, weights)) / (2 * h)
        fd = np.cross(p_s, p_t)
        np.testing.assert_allclose(su.patch_normal(points, sk, tk, weights), fd / np.linalg.norm(fd), atol=1e-6)
        if s[k] < 1 and t[k] < 1:  # §15.3: subdivide so that the point is the corner (0, 0) of [s, 1] × [t, 1]
            sub, sw = su.subpatch(points, (s[k], 1), (t[k], 1), weights)
            d = su.corner_derivatives(sub, sw)
            corner = np.cross(d["P_s"], d["P_t"])
            np.testing.assert_allclose(corner / np.linalg.norm(corner), normals[k], atol=1e-10)
    # Ignoring the weights at an interior point turns the normal.
    wrong = su.patch_normal(points, 0.4, 0.6)
    assert np.degrees(np.arccos(np.clip(wrong @ su.patch_normal(points, 0.4, 0.6, weights), -1, 1))) > 1


def test_the_notes_tessellation_example():
    assert su.second_difference_bounds(TESS_NET) == tuple(TESS.results["bounds"])
    # The untangled hodograph arrays of the notes (rows from the largest j down).
    z = TESS.inputs["z"]
    p_ss = [[6 * (z[i + 2, j] - 2 * z[i + 1, j] + z[i, j]) for i in range(2)] for j in range(3, -1, -1)]
    p_st = [[9 * (z[i + 1, j + 1] - z[i + 1, j] - z[i, j + 1] + z[i, j]) for i in range(3)] for j in range(2, -1, -1)]
    p_tt = [[6 * (z[i, j + 2] - 2 * z[i, j + 1] + z[i, j]) for i in range(4)] for j in range(1, -1, -1)]
    for ours, notes in ((p_ss, "p_ss"), (p_st, "p_st"), (p_tt, "p_tt")):
        np.testing.assert_array_equal(ours, TESS.results[notes])
    delta_s, delta_t = su.tessellation_deltas(TESS_NET, TESS.inputs["tol"])
    assert delta_s / delta_t == pytest.approx(TESS.results["k"], rel=1e-14)
    assert delta_s == pytest.approx(TESS.results["delta_s"], abs=5e-9)
    assert delta_t == pytest.approx(TESS.results["delta_t"], abs=5e-11)
    n_s, n_t = su.tessellation_steps(TESS_NET, TESS.inputs["tol"])
    assert (n_s, n_t) == (TESS.results["n_s"], TESS.results["n_t"]) and 2 * n_s * n_t == TESS.results["triangles"]
    # k = 1 instead: 140 × 140, 39 200 triangles.
    m1, m2, m3 = TESS.results["bounds"]
    equal = int(np.ceil(1 / np.sqrt(8 * TESS.inputs["tol"] / (m1 + 2 * m2 + m3))))
    assert equal == TESS.results["n_equal"] and 2 * equal**2 == TESS.results["triangles_equal"]
    vertices, triangles = su.tessellate(TESS_NET, n_s, n_t)
    assert vertices.shape == ((n_s + 1) * (n_t + 1), 3) and triangles.shape == (39000, 3)
    error = su.tessellation_error(TESS_NET, n_s, n_t)
    assert error == pytest.approx(TESS.results["measured_error"], rel=1e-5) and error < TESS.inputs["tol"]


def test_the_bound_is_a_bound_and_the_optimal_k_gives_the_fewest_triangles():
    rng = np.random.default_rng(154)
    for _ in range(6):
        points = rng.uniform(-1, 1, (int(rng.integers(2, 5)), int(rng.integers(2, 5)), 3))
        tol = float(10 ** rng.uniform(-2.5, -1))
        n_s, n_t = su.tessellation_steps(points, tol)
        assert su.tessellation_error(points, n_s, n_t, samples=5) <= tol
        m1, m2, m3 = su.second_difference_bounds(points)
        for k in np.linspace(0.2, 3, 15):  # any other k: at least as many triangles before rounding
            dt = np.sqrt(8 * tol / (m1 * k * k + 2 * m2 * k + m3))
            if k * dt < 1 and dt < 1:
                ds0, dt0 = su.tessellation_deltas(points, tol)
                assert ds0 * dt0 >= k * dt * dt * (1 - 1e-12)


def test_the_cases_the_notes_leave_open():
    tol = SPECIAL.inputs["tol"]
    assert su.tessellation_steps(SPECIAL.inputs["ruled"], tol) == tuple(SPECIAL.results["ruled_steps"])
    assert su.tessellation_steps(np.transpose(SPECIAL.inputs["ruled"], (1, 0, 2)), tol) == tuple(
        SPECIAL.results["ruled_steps"][::-1])
    assert su.tessellation_steps(SPECIAL.inputs["bilinear"], tol) == tuple(SPECIAL.results["bilinear_steps"])
    assert su.tessellation_steps(SPECIAL.inputs["plane"], tol) == (1, 1)
    assert su.tessellation_steps(TESS_NET, 100.0) == (1, 1)
    # The stable form of Case 1 agrees with the notes' (sqrt(M2² + 8 ε M3) - M2) / M3.
    _, m2, m3 = su.second_difference_bounds(SPECIAL.inputs["ruled"])
    assert su.tessellation_deltas(SPECIAL.inputs["ruled"], tol)[1] == pytest.approx(
        (np.sqrt(m2**2 + 8 * tol * m3) - m2) / m3, rel=1e-9)
    for bad in (0.0, -1.0):
        with pytest.raises(ValueError, match="^tol"):
            su.tessellation_steps(TESS_NET, bad)


def test_curve_tessellation_course_example():
    delta, n = su.curve_tessellation_steps(CURVE_TESS.inputs["points"], CURVE_TESS.inputs["tol"])
    assert delta == pytest.approx(CURVE_TESS.results["delta"], abs=5e-8) and n == CURVE_TESS.results["segments"]
    points = CURVE_TESS.inputs["points"]
    t = np.linspace(0, 1, 20001)
    curve = bezier.evaluate(points, t)
    for segments, key in ((13, "error_13"), (12, "error_12")):
        knots = np.linspace(0, 1, segments + 1)
        chords = np.column_stack([np.interp(t, knots, c) for c in bezier.evaluate(points, knots).T])
        assert np.linalg.norm(curve - chords, axis=1).max() == pytest.approx(CURVE_TESS.results[key], abs=2e-6)


def test_cn_patches_from_matching_control_curves():
    rng = np.random.default_rng(155)
    a = rng.uniform(-1, 1, (4, 3, 3))
    # Continue every s-control curve of a (on [0, 1]) C^2 onto [1, 3] by its blossom: b_k = a(1, .., 1, 3, .., 3).
    b = np.empty_like(a)
    for j in range(3):
        for k in range(4):
            b[k, j] = bspline.bezier_blossom(a[:, j], [1.0] * (3 - k) + [3.0] * k)
    assert su.patch_continuity(a, b, (0, 1), (1, 3)) == 3  # the same cubic: every order matches
    b2 = b.copy()
    b2[3] += 0.5  # only the last row moves: C^2 stays
    assert su.patch_continuity(a, b2, (0, 1), (1, 3)) == 2
    b1 = b.copy()
    b1[2, 1] += 0.3  # one curve loses C^2: the surface is only C^1
    assert su.patch_continuity(a, b1, (0, 1), (1, 3)) == 1
    assert su.patch_continuity(a, b1 + 1, (0, 1), (1, 3)) == -1
    assert su.patch_continuity(np.transpose(a, (1, 0, 2)), np.transpose(b1, (1, 0, 2)), (0, 1), (1, 3), "t") == 1


def nurbs_example(seed=156):
    rng = np.random.default_rng(seed)
    points, weights = rng.uniform(-2, 2, (6, 5, 3)), rng.uniform(0.5, 2, (6, 5))
    knots_s, knots_t = np.array([0, 0, 0, 1, 2, 4, 4, 4.0]), np.array([0, 0, 1, 2, 3, 3.0])  # cubic × quadratic
    return points, weights, knots_s, knots_t


def test_nurbs_points_against_scipy_ndbspline():
    points, weights, knots_s, knots_t = nurbs_example()
    h = homogeneous_net(points, weights)
    spline = NdBSpline((np.r_[knots_s[0], knots_s, knots_s[-1]], np.r_[knots_t[0], knots_t, knots_t[-1]]), h, (3, 2))
    rng = np.random.default_rng(157)
    s, t = rng.uniform(0, 4, 30), rng.uniform(0, 3, 30)
    expected = spline(np.column_stack([s, t]))
    np.testing.assert_allclose(su.nurbs_point(points, knots_s, knots_t, s, t, weights),
                               expected[:, :3] / expected[:, 3:], atol=1e-12)
    # A Bézier patch is a NURBS surface with Bézier end knots.
    patch, w = random_patch(158, 3, 2)
    np.testing.assert_allclose(su.nurbs_point(patch, [0, 0, 0, 1, 1, 1], [0, 0, 1, 1], s / 4, t / 3, w),
                               su.patch_point(patch, s / 4, t / 3, w), atol=1e-13)


def test_nurbs_knot_insertion_and_bezier_extraction_keep_the_surface():
    points, weights, knots_s, knots_t = nurbs_example()
    rng = np.random.default_rng(159)
    s, t = rng.uniform(0, 4, 25), rng.uniform(0, 3, 25)
    before = su.nurbs_point(points, knots_s, knots_t, s, t, weights)
    for value, direction in ((1.5, "s"), (2.0, "t"), (1.0, "s")):
        p2, ks, kt, w2 = su.nurbs_insert_knot(points, knots_s, knots_t, value, direction, weights)
        assert p2.shape == ((7, 5, 3) if direction == "s" else (6, 6, 3))
        np.testing.assert_allclose(su.nurbs_point(p2, ks, kt, s, t, w2), before, atol=1e-12)
    patches, pw = su.nurbs_to_bezier(points, knots_s, knots_t, weights)
    assert patches.shape == (3, 3, 4, 3, 3) and pw.shape == (3, 3, 4, 3)
    spans_s, spans_t = bspline.bezier_segment_intervals(knots_s, 3), bspline.bezier_segment_intervals(knots_t, 2)
    for a, (s0, s1) in enumerate(spans_s):
        for b, (t0, t1) in enumerate(spans_t):
            u, v = rng.uniform(0, 1, 5), rng.uniform(0, 1, 5)
            np.testing.assert_allclose(su.patch_point(patches[a, b], u, v, pw[a, b]),
                                       su.nurbs_point(points, knots_s, knots_t, s0 + u * (s1 - s0),
                                                      t0 + v * (t1 - t0), weights), atol=1e-12)


def test_geomdl_agrees_on_nurbs_surfaces_normals_and_knot_insertion():
    nurbs = pytest.importorskip("geomdl.NURBS")
    operations = pytest.importorskip("geomdl.operations")
    points, weights, knots_s, knots_t = nurbs_example(160)
    surface = nurbs.Surface(normalize_kv=False)  # geomdl rescales knots to [0, 1] by default
    surface.degree_u, surface.degree_v = 3, 2
    surface.ctrlpts_size_u, surface.ctrlpts_size_v = 6, 5
    surface.ctrlptsw = homogeneous_net(points, weights).reshape(-1, 4).tolist()
    surface.knotvector_u = np.r_[0, knots_s, 4].tolist()
    surface.knotvector_v = np.r_[0, knots_t, 3].tolist()
    for s, t in ((0.5, 0.7), (2.5, 1.2), (3.9, 2.9)):
        np.testing.assert_allclose(surface.evaluate_single((s, t)), su.nurbs_point(points, knots_s, knots_t, s, t,
                                                                                     weights), atol=1e-12)
        d = surface.derivatives(s, t, order=1)
        normal = np.cross(d[1][0], d[0][1])
        patches, pw = su.nurbs_to_bezier(points, knots_s, knots_t, weights)
        a = int(np.searchsorted([1, 2], s, side="right"))
        b = int(np.searchsorted([1, 2], t, side="right"))
        (s0, s1), (t0, t1) = bspline.bezier_segment_intervals(knots_s, 3)[a], bspline.bezier_segment_intervals(
            knots_t, 2)[b]
        ours = su.patch_normal(patches[a, b], (s - s0) / (s1 - s0), (t - t0) / (t1 - t0), pw[a, b])
        np.testing.assert_allclose(ours, normal / np.linalg.norm(normal), atol=1e-10)
    operations.insert_knot(surface, [1.5, None], [1, 0])
    p2, ks, _, w2 = su.nurbs_insert_knot(points, knots_s, knots_t, 1.5, "s", weights)
    np.testing.assert_allclose(np.array(surface.ctrlptsw).reshape(7, 5, 4), homogeneous_net(p2, w2), atol=1e-12)


def test_corner_curvatures_of_analytic_surfaces():
    par = lattice(CURV.inputs["paraboloid_z"], 0.5, 0.5)
    saddle = lattice(CURV.inputs["saddle_z"], 0.5, 0.5)
    assert su.corner_curvatures(par) == pytest.approx(tuple(CURV.results["paraboloid"]))
    assert su.corner_curvatures(saddle) == pytest.approx(tuple(CURV.results["saddle"]), abs=1e-15)
    cylinder = su.corner_curvatures(CURV.inputs["cylinder"], CURV.inputs["cylinder_weights"])
    assert cylinder == pytest.approx(tuple(CURV.results["cylinder"]), abs=1e-14)
    # Reversing one direction flips the normal: H changes sign, K does not.
    assert su.corner_curvatures(np.transpose(par, (1, 0, 2))) == pytest.approx((1.0, -1.0))
    assert su.principal_curvatures(saddle) == pytest.approx((1.0, -1.0))
    # The torus patch of chapter 16 at (0, 0): the outer equator, principal curvatures 1/r and 1/(R + r),
    # negative along the outward normal.
    torus, tw = TORUS.args("points", "weights")
    R, r = TORUS.inputs["major"], TORUS.inputs["minor"]
    assert su.corner_curvatures(torus, tw) == pytest.approx((1 / (r * (R + r)), -(1 / r + 1 / (R + r)) / 2))
    # Anywhere on the torus by subdivision: K = cos v / (r (R + r cos v)) with v the angle on the tube.
    for s, t in ((0.3, 0.4), (0.8, 0.9), (1.0, 1.0)):
        x = su.patch_point(torus, s, t, tw)
        cos_v = (np.hypot(x[0], x[1]) - R) / r
        gaussian, _ = su.surface_curvatures(torus, s, t, tw)
        assert gaussian == pytest.approx(cos_v / (r * (R + r * cos_v)), abs=1e-10)


@pytest.mark.parametrize("shape", [(3, 2), (2, 3), (4, 4), (1, 3)])
def test_corner_curvatures_against_sympy_fundamental_forms(shape):
    points, weights = random_patch(161 + shape[0], *shape)
    expr, s, t = sympy_patch(points, weights)
    at = {s: 0, t: 0}
    r_s = sp.Matrix([sp.diff(c, s) for c in expr]).subs(at)
    r_t = sp.Matrix([sp.diff(c, t) for c in expr]).subs(at)
    normal = r_s.cross(r_t)
    normal = normal / normal.norm()
    second = [sp.Matrix([sp.diff(c, *v) for c in expr]).subs(at).dot(normal) for v in ((s, s), (s, t), (t, t))]
    e, f, g = r_s.dot(r_s), r_s.dot(r_t), r_t.dot(r_t)
    big_l, big_m, big_n = second
    gaussian = float((big_l * big_n - big_m**2) / (e * g - f**2))
    mean = float((big_n * e - 2 * big_m * f + big_l * g) / (2 * (e * g - f**2)))
    assert su.corner_curvatures(points, weights) == pytest.approx((gaussian, mean), rel=1e-9, abs=1e-12)
    forms = su.corner_fundamental_forms(points, weights)
    assert forms == pytest.approx(tuple(float(v) for v in (e, f, g, big_l, big_m, big_n)), rel=1e-9, abs=1e-12)
    k1, k2 = su.principal_curvatures(points, weights)
    assert k1 + k2 == pytest.approx(2 * mean, abs=1e-10) and k1 * k2 == pytest.approx(gaussian, abs=1e-10)


def test_triangle_corner_curvatures_against_sympy():
    rng = np.random.default_rng(162)
    n = 3
    tri, w = rng.uniform(-1, 1, (n + 1, n + 1, 3)), rng.uniform(0.5, 2, (n + 1, n + 1))
    tri[..., :2] += np.stack(np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="ij"), axis=2)
    u, v = sp.symbols("u v")
    num, den = [0, 0, 0], 0
    for i in range(n + 1):
        for j in range(n + 1 - i):
            k = n - i - j
            b = sp.factorial(n) / (sp.factorial(i) * sp.factorial(j) * sp.factorial(k)) * u**i * v**j * (1 - u - v)**k
            den += sp.Float(w[i, j], 30) * b
            for c in range(3):
                num[c] += sp.Float(w[i, j] * tri[i, j, c], 30) * b
    expr = [c / den for c in num]
    at = {u: 0, v: 0}
    r_u = sp.Matrix([sp.diff(c, u) for c in expr]).subs(at)
    r_v = sp.Matrix([sp.diff(c, v) for c in expr]).subs(at)
    normal = r_u.cross(r_v) / r_u.cross(r_v).norm()
    big_l, big_m, big_n = (sp.Matrix([sp.diff(c, *x) for c in expr]).subs(at).dot(normal)
                           for x in ((u, u), (u, v), (v, v)))
    e, f, g = r_u.dot(r_u), r_u.dot(r_v), r_v.dot(r_v)
    gaussian = float((big_l * big_n - big_m**2) / (e * g - f**2))
    mean = float((big_n * e - 2 * big_m * f + big_l * g) / (2 * (e * g - f**2)))
    assert su.triangle_corner_curvatures(tri, w) == pytest.approx((gaussian, mean), rel=1e-9)


def test_chapter_15_bad_input():
    with pytest.raises(ValueError, match="^points"):
        su.corner_curvatures([[(0, 0, 0), (0, 1, 0)], [(0, 2, 0), (1, 1, 1)]])  # P00, P10, P01 collinear
    with pytest.raises(ValueError, match="^points"):
        su.corner_curvatures([[(0, 0, 0), (0, 1, 0), (0, 2, 1)]])
    with pytest.raises(ValueError, match="^knots_s"):
        su.nurbs_point(np.zeros((4, 3, 3)), [0, 1], [0, 1], 0.5, 0.5)
    with pytest.raises(ValueError, match="^s_range"):
        su.subpatch(SADDLE, (0.5, 0.5), (0, 1))
    with pytest.raises(ValueError, match="^s"):
        su.surface_curvatures(SADDLE, 1.5, 0.5)
