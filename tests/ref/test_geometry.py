"""Unit tests of cagd_ref.geometry: vectors, rotations, lines and conics (chapter 1 of the notes)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from cagd_course.examples import notes_example
from cagd_ref import geometry as g

PROJECTION = notes_example("01.projection")
TRIANGLE = notes_example("01.triangle_area")
ROTATION = notes_example("01.rotation")
AFFINE = notes_example("01.affine_line")


def random_axes(seed: int, count: int):
    """`count` random (point, axis point, direction, angle) rotations."""
    rng = np.random.default_rng(seed)
    for _ in range(count):
        yield rng.normal(size=3) * 4, rng.normal(size=3) * 3, rng.normal(size=3), rng.uniform(-2 * np.pi, 2 * np.pi)


def test_every_public_name_is_tested():
    tested = {
        "projection", "triangle_area", "rotate_about_axis", "rotation_matrix", "apply_transform",
        "affine_point", "implicit_line", "normalize_line", "signed_distance", "join", "meet",
        "conic_type", "conic_discriminant", "parametric_conic_type",
    }
    assert set(g.__all__) == tested


# --- projection and triangle area (Notes §1.2) ------------------------------------------


def test_projection_notes_example():
    p, q = PROJECTION.args("p", "q")
    assert p @ q == PROJECTION.results["p_dot_q"] and q @ q == PROJECTION.results["q_dot_q"]
    np.testing.assert_allclose(g.projection(p, q), PROJECTION.results["projection"], atol=1e-14)


@pytest.mark.parametrize("dim", [2, 3, 5])
def test_projection_leaves_a_perpendicular_residual(dim):
    rng = np.random.default_rng(dim)
    p, q = rng.normal(size=dim), rng.normal(size=dim)
    r = g.projection(p, q)
    assert r.shape == (dim,)
    assert abs((p - r) @ q) < 1e-12
    np.testing.assert_allclose(np.cross(r, q) if dim == 3 else 0.0, 0.0, atol=1e-12)
    np.testing.assert_allclose(g.projection(q, q), q)
    # The projection onto q only depends on q's direction.
    np.testing.assert_allclose(g.projection(p, -3.5 * q), r)


def test_triangle_area_notes_example():
    p1, p2, p3 = TRIANGLE.args("p1", "p2", "p3")
    np.testing.assert_array_equal([p2 - p1, p3 - p1], TRIANGLE.results["edges"])
    np.testing.assert_array_equal(np.cross(p2 - p1, p3 - p1), TRIANGLE.results["cross"])
    area = g.triangle_area(p1, p2, p3)
    assert area == pytest.approx(TRIANGLE.results["area"], rel=1e-14)
    assert round(area, 3) == TRIANGLE.results["area_rounded"]


def test_triangle_area_matches_heron_and_shoelace():
    rng = np.random.default_rng(7)
    for _ in range(20):
        a, b, c = rng.normal(size=(3, 3))
        x, y, z = np.linalg.norm(b - c), np.linalg.norm(a - c), np.linalg.norm(a - b)
        s = (x + y + z) / 2
        heron = np.sqrt(max(s * (s - x) * (s - y) * (s - z), 0.0))
        assert g.triangle_area(a, b, c) == pytest.approx(heron, rel=1e-9, abs=1e-12)
        a2, b2, c2 = a[:2], b[:2], c[:2]
        shoelace = abs((b2[0] - a2[0]) * (c2[1] - a2[1]) - (c2[0] - a2[0]) * (b2[1] - a2[1])) / 2
        assert g.triangle_area(a2, b2, c2) == pytest.approx(shoelace, rel=1e-12, abs=1e-14)


def test_triangle_area_of_collinear_points_is_zero():
    assert g.triangle_area((0, 0), (1, 1), (3, 3)) == 0.0


# --- rotation about an arbitrary axis (Notes §1.3) ---------------------------------------


def test_rotation_notes_example():
    expected = ROTATION.results["rotated"]
    np.testing.assert_allclose(g.rotate_about_axis(*ROTATION.args("point", "axis_point", "axis_direction", "angle")),
                               expected, rtol=1e-14)
    matrix = g.rotation_matrix(*ROTATION.args("axis_point", "axis_direction", "angle"))
    point, axis_point, angle = ROTATION.args("point", "axis_point", "angle")
    np.testing.assert_allclose(g.apply_transform(matrix, point), expected, rtol=1e-14)
    # The unit axis n of the notes gives the same rotation as the unnormalised direction.
    np.testing.assert_allclose(g.rotate_about_axis(point, axis_point, ROTATION.results["n"], angle), expected)


def test_rotation_notes_intermediate_values():
    # The worked example goes through the foot C, the radius u and its quarter turn v;
    # a quarter turn takes P to C + v, half a turn to C - u.
    c, u, v = (ROTATION.results[key] for key in ("foot", "u", "v"))
    point, axis_point, direction, angle = ROTATION.args("point", "axis_point", "axis_direction", "angle")
    np.testing.assert_allclose(g.rotate_about_axis(point, axis_point, direction, angle), c + v)
    np.testing.assert_allclose(g.rotate_about_axis(point, axis_point, direction, 2 * angle), c - u)


@pytest.mark.parametrize("point, axis_point, direction, angle", list(random_axes(seed=1, count=8)))
def test_rotation_agrees_with_scipy(point, axis_point, direction, angle):
    rotvec = angle * direction / np.linalg.norm(direction)
    expected = axis_point + Rotation.from_rotvec(rotvec).apply(point - axis_point)
    np.testing.assert_allclose(g.rotate_about_axis(point, axis_point, direction, angle), expected, atol=1e-12)
    matrix = g.rotation_matrix(axis_point, direction, angle)
    np.testing.assert_allclose(g.apply_transform(matrix, point), expected, atol=1e-12)


def test_rotation_matrix_matches_the_notes_closed_form():
    # Matrix (1.27) with translation column T1, T2, T3, written out entry by entry.
    for _, b, n, theta in random_axes(seed=2, count=5):
        n = n / np.linalg.norm(n)
        nx, ny, nz = n
        c, s = np.cos(theta), np.sin(theta)
        bn = b @ n
        expected = np.array([
            [nx * nx + (ny * ny + nz * nz) * c, nx * ny * (1 - c) - nz * s, nx * nz * (1 - c) + ny * s,
             (b[0] - bn * nx) * (1 - c) + (nz * b[1] - ny * b[2]) * s],
            [nx * ny * (1 - c) + nz * s, ny * ny + (nx * nx + nz * nz) * c, ny * nz * (1 - c) - nx * s,
             (b[1] - bn * ny) * (1 - c) + (nx * b[2] - nz * b[0]) * s],
            [nx * nz * (1 - c) - ny * s, ny * nz * (1 - c) + nx * s, nz * nz + (nx * nx + ny * ny) * c,
             (b[2] - bn * nz) * (1 - c) + (ny * b[0] - nx * b[1]) * s],
            [0, 0, 0, 1],
        ])
        np.testing.assert_allclose(g.rotation_matrix(b, n, theta), expected, atol=1e-12)


def test_rotation_properties():
    rng = np.random.default_rng(3)
    b, n = rng.normal(size=3), rng.normal(size=3)
    points = rng.normal(size=(6, 3))
    rotated = g.rotate_about_axis(points, b, n, 0.8)
    assert rotated.shape == (6, 3)
    # Row by row the same as one point at a time.
    np.testing.assert_allclose(rotated, [g.rotate_about_axis(p, b, n, 0.8) for p in points])
    # Points on the axis stay put; distances to the axis point and between points are kept.
    np.testing.assert_allclose(g.rotate_about_axis(b + 2.5 * n, b, n, 0.8), b + 2.5 * n, atol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(rotated - b, axis=1), np.linalg.norm(points - b, axis=1))
    np.testing.assert_allclose(np.linalg.norm(rotated[1:] - rotated[0], axis=1),
                               np.linalg.norm(points[1:] - points[0], axis=1))
    # Composition adds angles; a full turn is the identity; the length of n does not matter.
    np.testing.assert_allclose(g.rotate_about_axis(rotated, b, n, 0.5), g.rotate_about_axis(points, b, n, 1.3))
    np.testing.assert_allclose(g.rotate_about_axis(points, b, n, 2 * np.pi), points, atol=1e-12)
    np.testing.assert_allclose(g.rotate_about_axis(points, b, 7 * n, 0.8), rotated)
    # Reversing the axis reverses the sense of rotation.
    np.testing.assert_allclose(g.rotate_about_axis(points, b, -n, -0.8), rotated)
    matrix = g.rotation_matrix(b, n, 0.8)
    np.testing.assert_allclose(matrix[:3, :3] @ matrix[:3, :3].T, np.eye(3), atol=1e-14)
    assert np.linalg.det(matrix[:3, :3]) == pytest.approx(1.0)
    np.testing.assert_array_equal(matrix[3], [0, 0, 0, 1])
    np.testing.assert_allclose(g.apply_transform(matrix, points), rotated, atol=1e-12)


def test_apply_transform_divides_by_w():
    translate_and_scale = np.diag([1.0, 1.0, 1.0, 2.0])
    translate_and_scale[:3, 3] = (2, 4, 6)
    np.testing.assert_allclose(g.apply_transform(translate_and_scale, (2, 0, 0)), (2, 2, 3))
    out = g.apply_transform(np.eye(4), [[1, 2, 3], [4, 5, 6]])
    assert out.shape == (2, 3)


# --- lines (Notes §1.5) -------------------------------------------------------------------


def test_affine_point_parameter_values():
    p0, p1 = np.array([1.0, 2.0]), np.array([4.0, 8.0])
    t0, t1, t = AFFINE.args("t0", "t1", "t")
    np.testing.assert_allclose(g.affine_point(p0, p1, t0, t1, t0), p0)
    np.testing.assert_allclose(g.affine_point(p0, p1, t0, t1, t1), p1)
    # Figure 1.8: t = 2 sits a third of the way from P(1) to P(4), with weights 2/3 and 1/3.
    np.testing.assert_allclose(g.affine_point(p0, p1, t0, t1, t), p0 + AFFINE.results["fraction"] * (p1 - p0))
    np.testing.assert_allclose(g.affine_point(p0, p1, t0, t1, t), AFFINE.results["weights"] @ [p0, p1])
    many = g.affine_point(p0, p1, t0, t1, np.array([0.0, 1, 2, 7]))
    np.testing.assert_allclose(many[-1], p0 + 2 * (p1 - p0))


def test_implicit_line_and_signed_distance():
    rng = np.random.default_rng(4)
    for _ in range(10):
        p0, p1, q = rng.normal(size=(3, 2))
        line = g.implicit_line(p0, p1)
        assert line.shape == (3,)
        np.testing.assert_allclose([line @ [*p0, 1], line @ [*p1, 1]], 0.0, atol=1e-12)
        d = p1 - p0
        cross = d[0] * (q - p0)[1] - d[1] * (q - p0)[0]
        # Positive on the left of the direction p0 -> p1.
        assert g.signed_distance(line, q) == pytest.approx(cross / np.linalg.norm(d))
    unit = g.normalize_line((3.0, 4.0, 10.0))
    np.testing.assert_allclose(unit, (0.6, 0.8, 2.0))
    # |c| of the normalised line is the distance of the origin.
    assert g.signed_distance((3.0, 4.0, 10.0), (0.0, 0.0)) == pytest.approx(2.0)
    distances = g.signed_distance((0.0, 2.0, -2.0), [[0, 1], [5, 3], [1, -1]])
    assert isinstance(g.signed_distance((0.0, 2.0, -2.0), (0, 1)), float)
    np.testing.assert_allclose(distances, [0.0, 2.0, -2.0])


def test_join_and_meet():
    # x = 1 and y = 2 meet at (1, 2); the parallel lines x = 1, x = 3 meet at infinity.
    point = g.meet((1, 0, -1), (0, 1, -2))
    np.testing.assert_allclose(point[:2] / point[2], (1, 2))
    assert g.meet((1, 0, -1), (1, 0, -3))[2] == 0
    line = g.join((1, 2, 1), (3, 4, 1))
    np.testing.assert_allclose(line @ np.array([5, 6, 1]), 0.0)  # (5, 6) is on the same line
    np.testing.assert_allclose(line / line[0], g.implicit_line((1, 2), (3, 4)) / line[0])
    # Homogeneous points are defined up to scale.
    np.testing.assert_allclose(np.cross(g.join((2, 4, 2), (3, 4, 1)), line), 0.0, atol=1e-12)


# --- conics (Notes §1.6) ------------------------------------------------------------------


@pytest.mark.parametrize(
    "coefficients, expected",
    [
        ((1, 0, 1, 0, 0, -1), "ellipse"),  # unit circle
        ((4, 0, 1, 3, 0, -7), "ellipse"),
        ((1, 1, 1, 0, 0, -1), "ellipse"),  # b² - 4ac = -3
        ((1, 0, 0, 0, -1, 0), "parabola"),  # y = x²
        ((1, 2, 1, 1, 0, 0), "parabola"),  # (x + y)² + x = 0
        ((0, 1, 0, 0, 0, -1), "hyperbola"),  # xy = 1
        ((1, 0, -1, 0, 0, -1), "hyperbola"),
        ((1, 3, 1, 0, 0, -1), "hyperbola"),  # b² - 4ac = 5
    ],
)
def test_conic_type(coefficients, expected):
    a, b, c = coefficients[:3]
    assert g.conic_discriminant(a, b, c) == b * b - 4 * a * c
    assert g.conic_type(*coefficients) == expected
    # The equation can be scaled by any nonzero factor, tiny or huge.
    for factor in (1e-9, -3.0, 1e9):
        assert g.conic_type(*(factor * v for v in coefficients)) == expected


@pytest.mark.parametrize("angle", [0.1, 0.3, 0.7, 1.1])
def test_rounded_parabolas_are_still_parabolas(angle):
    # (x cos θ + y sin θ)² + x = 0 is a parabola; in floating point b² - 4ac is only ~1e-16.
    a, b, c = np.cos(angle) ** 2, 2 * np.cos(angle) * np.sin(angle), np.sin(angle) ** 2
    assert g.conic_type(a, b, c, 1.0, 0.0, 0.0) == "parabola"
    # A genuinely small discriminant relative to the coefficients is not rounded away.
    assert g.conic_type(a, b, c + 1e-6, 1.0, 0.0, 0.0) == "ellipse"
    assert g.conic_type(a, b, c - 1e-6, 1.0, 0.0, 0.0) == "hyperbola"


@pytest.mark.parametrize(
    "denominator, implicit, expected",
    [
        # circle ((1 - t²), 2t) / (1 + t²): x² + y² = 1
        ((1, 0, 1), (1, 0, 1, 0, 0, -1), "ellipse"),
        # parabola (t, t²) / 1: y = x²
        ((1, 0, 0), (1, 0, 0, 0, -1, 0), "parabola"),
        # hyperbola ((1 + t²), 2t) / (1 - t²): x² - y² = 1
        ((1, 0, -1), (1, 0, -1, 0, 0, -1), "hyperbola"),
    ],
)
def test_parametric_conic_type_agrees_with_the_implicit_equation(denominator, implicit, expected):
    assert g.parametric_conic_type(denominator) == expected
    assert g.conic_type(*implicit) == expected


def test_parametric_conic_type_of_the_quarter_circle():
    # The denominator of the rational quadratic with weights (1, √2/2, 1), in the power basis.
    r = np.sqrt(2)
    assert g.parametric_conic_type((1, r - 2, 2 - r)) == "ellipse"


# --- bad input --------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "call, error, name",
    [
        (lambda: g.projection((1, 2, 3), (0, 0, 0)), ValueError, "q"),
        (lambda: g.projection((1, 2, 3), (1, 2)), ValueError, "q"),
        (lambda: g.projection([[1, 2, 3]], (1, 2, 3)), ValueError, "p"),
        (lambda: g.projection("abc", (1, 2, 3)), TypeError, "p"),
        (lambda: g.triangle_area((1, 2, 3, 4), (1, 2, 3, 4), (1, 2, 3, 4)), ValueError, "p1"),
        (lambda: g.triangle_area((1, 2), (1, 2, 3), (1, 2)), ValueError, "p2"),
        (lambda: g.rotate_about_axis((1, 2, 3), (0, 0, 0), (0, 0, 0), 1.0), ValueError, "axis_direction"),
        (lambda: g.rotate_about_axis((1, 2), (0, 0, 0), (0, 0, 1), 1.0), ValueError, "point"),
        (lambda: g.rotate_about_axis(np.ones((2, 2, 3)), (0, 0, 0), (0, 0, 1), 1.0), ValueError, "point"),
        (lambda: g.rotate_about_axis((1, 2, 3), (0, 0), (0, 0, 1), 1.0), ValueError, "axis_point"),
        (lambda: g.rotate_about_axis((1, 2, 3), (0, 0, 0), (0, 0, 1), [1.0, 2.0]), ValueError, "angle"),
        (lambda: g.rotate_about_axis((1, 2, 3), (0, 0, 0), (0, 0, 1), None), TypeError, "angle"),
        (lambda: g.rotation_matrix((0, 0, 0), (0, 0, 0), 1.0), ValueError, "axis_direction"),
        (lambda: g.apply_transform(np.eye(3), (1, 2, 3)), ValueError, "matrix"),
        (lambda: g.apply_transform(np.diag([1.0, 1, 1, 0]), (1, 2, 3)), ValueError, "matrix"),
        (lambda: g.apply_transform(np.eye(4), (1, 2)), ValueError, "points"),
        (lambda: g.affine_point((0, 0), (1, 1), 1, 1, 0.5), ValueError, "t0, t1"),
        (lambda: g.affine_point((0, 0), (1, 1, 1), 0, 1, 0.5), ValueError, "p1"),
        (lambda: g.affine_point((0, 0), (1, 1), 0, 1, [[0.5]]), ValueError, "t"),
        (lambda: g.implicit_line((1, 1), (1, 1)), ValueError, "p0, p1"),
        (lambda: g.implicit_line((1, 1, 1), (1, 2, 1)), ValueError, "p0"),
        (lambda: g.normalize_line((0, 0, 1)), ValueError, "line"),
        (lambda: g.signed_distance((1, 0, 0), (1, 2, 3)), ValueError, "points"),
        (lambda: g.join((1, 2), (1, 2, 1)), ValueError, "p"),
        (lambda: g.conic_type(0, 0, 0, 1, 1, 1), ValueError, "a, b, c"),
        (lambda: g.conic_type("1", 0, 1, 0, 0, 0), TypeError, "a"),
        (lambda: g.conic_discriminant(1, [1, 2], 1), ValueError, "b"),
        (lambda: g.parametric_conic_type((0, 0, 0)), ValueError, "denominator"),
        (lambda: g.parametric_conic_type((0, 1)), ValueError, "denominator"),
    ],
)
def test_bad_input_names_the_argument(call, error, name):
    with pytest.raises(error, match=rf"^{name}:"):
        call()

