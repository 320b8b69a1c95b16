"""Unit tests of cagd_ref.continuity: parametric and geometric continuity, curvature combs (notes §2.10, §2.11)."""

from __future__ import annotations

import numpy as np
import pytest

from cagd_course.examples import notes_example
from cagd_ref import bezier as b
from cagd_ref import continuity as c


def random_cubic(seed: int, dim: int = 2) -> np.ndarray:
    return np.random.default_rng(seed).uniform(-4, 4, size=(4, dim))


def test_every_public_name_is_tested():
    assert set(c.__all__) == {"Continuity", "continuity", "curvature_vector", "curvature_comb"}


# --- continuity at a joint (Notes §2.10) ---------------------------------------------------------


@pytest.mark.parametrize("split", [0.3, 0.5, 0.8])
@pytest.mark.parametrize("dim", [2, 3])
def test_halves_of_a_subdivided_curve_are_smooth(split, dim):
    points = random_cubic(int(split * 10) + dim, dim)
    left, right = b.subdivide(points, split)
    result = c.continuity(left, right, (0, split), (split, 1))
    # A polynomial is smooth to every order; C3 and G2 are the highest orders checked.
    assert result == c.Continuity(3, 2)
    assert str(result) == "C3, G2"
    # Run at a different speed on the right, the same joint is only geometrically smooth.
    assert c.continuity(left, right, (0, split), (split, split + 2 * (1 - split))) == c.Continuity(0, 2)


def test_halves_of_a_subdivided_rational_curve():
    rng = np.random.default_rng(4)
    points, weights = rng.normal(size=(5, 2)), rng.uniform(0.5, 2, 5)
    left, right = (b.from_homogeneous(half) for half in b.subdivide(b.to_homogeneous(points, weights), 0.4))
    result = c.continuity(left[0], right[0], (0, 0.4), (0.4, 1), left[1], right[1])
    assert result == c.Continuity(3, 2)


def test_the_chapters_c2_joint_and_its_stretched_copy():
    joint = notes_example("02.c2_joint")
    p, q, p_interval, q_interval = joint.args("p", "q", "p_interval", "q_interval")
    result = c.continuity(p, q, p_interval, q_interval)
    assert (result.parametric, result.geometric) == (joint.results["parametric"], joint.results["geometric"])
    # The notes' conditions hold on the control points: C1 and C2 with interval lengths h1 and h2.
    h1, h2 = np.diff(p_interval)[0], np.diff(q_interval)[0]
    np.testing.assert_allclose(3 / h1 * (p[3] - p[2]), 3 / h2 * (q[1] - q[0]))
    np.testing.assert_allclose(6 / h1**2 * (p[3] - 2 * p[2] + p[1]), 6 / h2**2 * (q[2] - 2 * q[1] + q[0]))
    # Run over an interval of another length, Q keeps its shape (G2) but no longer matches P's speed.
    assert c.continuity(p, q, p_interval, (q_interval[0], q_interval[0] + 1)) == c.Continuity(0, 2)


@pytest.mark.parametrize("seed", range(4))
def test_constructed_joints(seed):
    """Joints built from the notes' conditions on the control points, over [0, 1] and [1, 1 + h]."""
    rng = np.random.default_rng(seed)
    p = random_cubic(seed)
    h = rng.uniform(0.5, 2.0)  # length of Q's interval
    q_interval = (1, 1 + h)
    q = np.empty_like(p)
    q[0] = p[3]
    q[1] = p[3] + h * (p[3] - p[2])  # 3 (p3 - p2) / 1 = 3 (q1 - q0) / h: C1
    q[2], q[3] = rng.uniform(-4, 4, size=(2, 2))
    assert c.continuity(p, q, (0, 1), q_interval) == c.Continuity(1, 1)
    # 6 (p3 - 2 p2 + p1) / 1 = 6 (q2 - 2 q1 + q0) / h²: C2 (and so G2), but a random q3 breaks C3.
    q[2] = h * h * (p[3] - 2 * p[2] + p[1]) + 2 * q[1] - q[0]
    assert c.continuity(p, q, (0, 1), q_interval) == c.Continuity(2, 2)
    # Collinear legs of unequal length: G1 but not C1.
    g1 = q.copy()
    g1[1] = p[3] + 0.6 * h * (p[3] - p[2])
    assert c.continuity(p, g1, (0, 1), q_interval) == c.Continuity(0, 1)
    # A corner, a reversal of direction, and a gap.
    corner = q.copy()
    corner[1] = p[3] + (p[3] - p[2])[::-1] * (1, -1)
    assert c.continuity(p, corner, (0, 1), q_interval) == c.Continuity(0, 0)
    reverse = q.copy()
    reverse[1] = p[2]
    assert c.continuity(p, reverse, (0, 1), q_interval) == c.Continuity(0, 0)
    gap = c.continuity(p, q + 0.01, (0, 1), q_interval)
    assert gap == c.Continuity(-1, -1)
    assert str(gap) == "not joined (gap between the curves)"


def test_two_quarter_circles_are_c1_and_g2():
    (p, wp), (q, wq) = b.circular_arc((0, 0), 1, 0, np.pi / 2), b.circular_arc((0, 0), 1, np.pi / 2, np.pi / 2)
    assert c.continuity(p, q, p_weights=wp, q_weights=wq) == c.Continuity(1, 2)
    # A circle of another radius, tangent at the joint, shares the tangent only.
    (r, wr) = b.circular_arc((0, -1), 2, np.pi / 2, np.pi / 2)
    assert c.continuity(p, r, p_weights=wp, q_weights=wr).geometric == 1
    # An S-joint of two unit circles: equal curvature, but the centres lie on opposite sides.
    (s1, w1), (s2, w2) = b.circular_arc((0, 0), 1, -np.pi / 2, np.pi / 2), b.circular_arc((2, 0), 1, np.pi, -np.pi / 2)
    assert c.continuity(s1, s2, p_weights=w1, q_weights=w2) == c.Continuity(1, 1)


def test_continuity_tolerance_and_defaults():
    p = random_cubic(9)
    q = random_cubic(10)
    q = q - q[0] + p[3]  # joined at a corner
    assert c.continuity(p, q) == c.Continuity(0, 0)
    assert str(c.continuity(p, q)) == "C0, G0"
    nearly = q + 1e-6
    assert c.continuity(p, nearly) == c.Continuity(-1, -1)
    assert c.continuity(p, nearly, tol=1e-3).parametric >= 0
    assert str(c.Continuity(-1, 2)) == "G2"


# --- curvature vectors and combs (Notes §2.11) --------------------------------------------------------


def test_curvature_vector():
    # On a circle of radius 2 the curvature vector points to the centre and has length 1/2,
    # whatever the tangential part of the acceleration.
    velocity = np.array([[0.0, 3.0], [0.0, 3.0]])
    acceleration = np.array([[-9.0 / 2, 0.0], [-9.0 / 2, 5.0]])
    np.testing.assert_allclose(c.curvature_vector(velocity, acceleration), [[-0.5, 0.0], [-0.5, 0.0]])
    assert c.curvature_vector([1.0, 0.0, 0.0], [0.0, 0.0, 2.0]).shape == (1, 3)
    points = np.random.default_rng(1).normal(size=(5, 3))
    t = np.linspace(0, 1, 7)
    k = c.curvature_vector(b.derivative(points, t, 1), b.derivative(points, t, 2))
    assert k.shape == (7, 3)
    np.testing.assert_allclose(np.linalg.norm(k, axis=1), b.curvature(points, t), rtol=1e-9)
    np.testing.assert_allclose(np.einsum("ij,ij->i", k, b.derivative(points, t, 1)), 0.0, atol=1e-9)


def test_comb_of_a_circle_points_outward():
    points, weights = b.circular_arc((0, 0), 1, 0.3, 2.0)
    bases, tips = c.curvature_comb(points, count=9, length=0.25, weights=weights)
    assert bases.shape == tips.shape == (9, 2)
    np.testing.assert_allclose(bases, b.evaluate(points, np.linspace(0, 1, 9), weights), atol=1e-14)
    np.testing.assert_allclose(tips, 1.25 * bases, atol=1e-12)  # radial, outward, all equally long


@pytest.mark.parametrize("seed", range(4))
def test_comb_teeth_follow_the_curvature(seed):
    rng = np.random.default_rng(seed)
    points = rng.uniform(-3, 3, size=(4 + seed % 2, 2))
    weights = rng.uniform(0.5, 2, len(points)) if seed % 2 else None
    count, length = 31, 1.5
    bases, tips = c.curvature_comb(points, count, length, weights)
    t = np.linspace(0, 1, count)
    teeth = tips - bases
    kappa = b.signed_curvature(points, t, weights)
    # Lengths proportional to |κ|, the longest equal to `length`.
    np.testing.assert_allclose(np.linalg.norm(teeth, axis=1), length * np.abs(kappa) / np.abs(kappa).max(), rtol=1e-9,
                               atol=1e-12)
    # Perpendicular to the curve, on the side away from the centre of curvature.
    first, second = b.derivative(points, t, 1, weights), b.derivative(points, t, 2, weights)
    np.testing.assert_allclose(np.einsum("ij,ij->i", teeth, first), 0.0, atol=1e-9 * np.abs(first).max())
    towards_centre = c.curvature_vector(first, second)
    assert np.all(np.einsum("ij,ij->i", teeth, towards_centre) <= 1e-12)


def test_comb_of_an_s_curve_changes_side_and_of_a_line_is_flat():
    s_curve = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, -2.0], [3.0, 0.0]])
    bases, tips = c.curvature_comb(s_curve, 21)
    side = np.sign((tips - bases)[:, 1])
    assert side[0] == -side[-1] != 0
    line = np.array([[0.0, 0.0], [1.0, 1.0], [3.0, 3.0]])
    bases, tips = c.curvature_comb(line, 5)
    np.testing.assert_array_equal(bases, tips)


def test_comb_past_a_cusp_stays_finite():
    cusp = np.array([[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]])  # P'(1/2) = 0
    bases, tips = c.curvature_comb(cusp, 11)
    assert np.all(np.isfinite(tips))


# --- bad input (NaN, inf and unmodified inputs are checked in test_contract.py) ------------------------------

P = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])


@pytest.mark.parametrize(
    "call, error, name",
    [
        (lambda: c.continuity(P, np.zeros((3, 3))), ValueError, "p, q"),
        (lambda: c.continuity([1.0, 2.0], P), ValueError, "p"),
        (lambda: c.continuity(P, P, (1, 0)), ValueError, "p_interval"),
        (lambda: c.continuity(P, P, (0, 1), "ab"), TypeError, "q_interval"),
        (lambda: c.continuity(P, P, (0, 1), (1, 2, 3)), ValueError, "q_interval"),
        (lambda: c.continuity(P, P, p_weights=[1, 0, 1, 1]), ValueError, "p_weights"),
        (lambda: c.continuity(P, P, q_weights=[1, 1]), ValueError, "q_weights"),
        (lambda: c.continuity(P, P, tol="small"), TypeError, "tol"),
        (lambda: c.curvature_vector([0.0, 0.0], [1.0, 1.0]), ValueError, "first"),
        (lambda: c.curvature_vector([[1.0, 0.0]], [[1.0, 0.0, 0.0]]), ValueError, "second"),
        (lambda: c.curvature_vector(np.ones((2, 2, 2)), np.ones((2, 2, 2))), ValueError, "first"),
        (lambda: c.curvature_comb([[0.0], [1.0], [2.0]]), ValueError, "points"),
        (lambda: c.curvature_comb(np.ones((3, 3))), ValueError, "points"),
        (lambda: c.curvature_comb(P, 1), ValueError, "count"),
        (lambda: c.curvature_comb(P, 5.0), TypeError, "count"),
        (lambda: c.curvature_comb(P, 5, 1.0, [1, 0, 1, 1]), ValueError, "weights"),
    ],
)
def test_bad_input_names_the_argument(call, error, name):
    with pytest.raises(error, match=rf"^{name}:"):
        call()


@pytest.mark.parametrize("seed", range(8))
def test_g2_is_the_height_condition_of_the_chapter(seed):
    # Chapter 2's theorem: at a G1 joint of two cubics, G2 holds exactly when h_P / a_P² = h_Q / a_Q²
    # with p1 and q2 on the same side of the common tangent.
    rng = np.random.default_rng(seed)
    p = random_cubic(40 + seed)
    leg = p[3] - p[2]
    a_p = np.linalg.norm(leg)
    u = leg / a_p
    normal = np.array([-u[1], u[0]])
    h_p = normal @ (p[1] - p[3])  # signed: the side of p1
    ratio = rng.uniform(0.3, 3.0)  # a_Q / a_P
    q = np.empty((4, 2))
    q[0] = p[3]
    q[1] = q[0] + ratio * leg
    q[2] = q[1] + rng.uniform(-2, 2) * u + ratio**2 * h_p * normal  # any slide along the tangent
    q[3] = q[2] + rng.uniform(-3, 3, 2)
    assert c.continuity(p, q).geometric == 2
    for wrong in (1.3 * ratio**2 * h_p, -(ratio**2) * h_p):  # another height, or the other side
        bent = q.copy()
        bent[2] = q[1] + wrong * normal
        assert c.continuity(p, bent).geometric == 1
