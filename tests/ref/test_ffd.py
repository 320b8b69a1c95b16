"""Unit tests of cagd_ref.ffd: free-form deformation in the plane (chapter 14).

The notes' surviving numbers (Figure 14.3's s = .6, t = .7, the m = 3, n = 2
lattice with the lines s = .6 and t = .3) and the course's lattices built
around them come from cagd_course/examples/ch14.toml. The map is cross-checked
against a tensor-product Bernstein sum written out here, against
`cagd_ref.surfaces.patch_point`, SciPy's `NdBSpline` on the homogeneous
lattice and geomdl's NURBS surface; freezing by the observed contact order of
F - id across the edge; images of curves by sampling.
"""

from __future__ import annotations

from math import comb

import numpy as np
import pytest

from cagd_course.examples import notes_example
from cagd_ref import bezier
from cagd_ref import ffd as f
from cagd_ref.surfaces import patch_point

LOCAL = notes_example("14.local_coordinates")
IDENTITY = notes_example("14.identity")
EXAMPLE_A = notes_example("14.example_a")
EXAMPLE_B = notes_example("14.example_b")
FREEZING = notes_example("14.freezing")
OUTSIDE = notes_example("14.outside")
BOX = np.array([[1.0, -2.0], [5.0, 1.0]])  # a box away from the origin, to catch forgotten offsets


def built(example):
    """The identity lattice of an example with its moved points."""
    box, m, n = example.args("box", "m", "n")
    lattice = f.identity_lattice(box, int(m), int(n))
    moved = np.atleast_2d(example.inputs["moved"]).astype(int)
    lattice[tuple(moved.T)] = example.inputs["to"]
    return box, lattice


def random_lattice(rng, m: int, n: int, box=BOX, spread=0.25):
    size = box[1] - box[0]
    lattice = f.identity_lattice(box, m, n) + rng.normal(0, spread, (m + 1, n + 1, 2)) * size
    return lattice, rng.uniform(0.3, 3.0, (m + 1, n + 1))


def inside(rng, count: int, box=BOX) -> np.ndarray:
    return box[0] + rng.uniform(0, 1, (count, 2)) * (box[1] - box[0])


def bernstein_sum(points, lattice, box, weights) -> np.ndarray:
    """(14.2) written out term by term: Σ_j Σ_i B_i^m(s) B_j^n(t) w_ij (x_ij, y_ij, 1), then divided by W."""
    m, n = lattice.shape[0] - 1, lattice.shape[1] - 1
    s = (points[:, 0] - box[0, 0]) / (box[1, 0] - box[0, 0])
    t = (points[:, 1] - box[0, 1]) / (box[1, 1] - box[0, 1])
    total = np.zeros((len(points), 3))
    for i in range(m + 1):
        for j in range(n + 1):
            b = comb(m, i) * s**i * (1 - s) ** (m - i) * comb(n, j) * t**j * (1 - t) ** (n - j) * weights[i, j]
            total += b[:, None] * np.append(lattice[i, j], 1.0)
    return total[:, :2] / total[:, 2:]


# ---------------------------------------------------------------- local coordinates and the identity


def test_local_coordinates_of_figure_14_3():
    box, point = LOCAL.args("box", "point")
    np.testing.assert_allclose(f.ffd_parameters(point, box), LOCAL.results["st"], atol=1e-15)
    corners = f.ffd_parameters(box, box)
    np.testing.assert_allclose(corners, [[0, 0], [1, 1]], atol=0)
    # Outside the box the coordinates leave [0, 1] (s = -1/4: a quarter of the width to the left).
    np.testing.assert_allclose(f.ffd_parameters([[0.0, 2.5]], box), [[-0.25, 1.5]])


def test_the_identity_lattice_of_the_example_box():
    box, m, n = IDENTITY.args("box", "m", "n")
    lattice = f.identity_lattice(box, int(m), int(n))
    assert lattice.shape == (4, 3, 2)
    np.testing.assert_array_equal(lattice[[0, 3, 0, 3], [0, 0, 2, 2]], IDENTITY.results["corner_points"])
    np.testing.assert_array_equal(lattice[1, 2], IDENTITY.results["point_12"])
    np.testing.assert_allclose(np.diff(lattice[..., 0], axis=0), 1.0)  # evenly spaced columns ...
    np.testing.assert_allclose(np.diff(lattice[..., 1], axis=1), 1.0)  # ... and rows


@pytest.mark.parametrize("m, n", [(1, 1), (2, 2), (3, 2), (2, 5), (6, 1)])
def test_the_identity_lattice_leaves_every_point_in_place(m, n):
    rng = np.random.default_rng(m * 10 + n)
    points = inside(rng, 200)
    lattice = f.identity_lattice(BOX, m, n)
    np.testing.assert_allclose(f.ffd(points, lattice, BOX), points, atol=1e-13)
    # Equal weights are enough: the common factor cancels. One different weight is not.
    np.testing.assert_allclose(f.ffd(points, lattice, BOX, np.full((m + 1, n + 1), 2.5)), points, atol=1e-13)
    if m >= 2 and n >= 2:
        weights = np.ones((m + 1, n + 1))
        weights[1, 1] = 3.0
        assert np.abs(f.ffd(points, lattice, BOX, weights) - points).max() > 0.05


# ---------------------------------------------------------------- the map


def test_example_a_moves_the_centre_of_a_3_by_3_lattice():
    box, lattice = built(EXAMPLE_A)
    points = EXAMPLE_A.inputs["points"]
    np.testing.assert_allclose(f.ffd(points, lattice, box), EXAMPLE_A.results["deformed"], atol=1e-14)
    weights = np.ones((3, 3))
    weights[1, 1] = EXAMPLE_A.inputs["weight"]
    np.testing.assert_allclose(f.ffd(points[:2], lattice, box, weights), EXAMPLE_A.results["deformed_weighted"],
                               atol=1e-14)


def test_example_b_crossing_point():
    box, lattice = built(EXAMPLE_B)
    s, t = EXAMPLE_B.args("s", "t")
    point = box[0] + np.array([s, t]) * (box[1] - box[0])
    np.testing.assert_allclose(f.ffd(point, lattice, box), EXAMPLE_B.results["crossing"], atol=1e-14)
    weights = np.ones((4, 3))
    weights[tuple(EXAMPLE_B.inputs["heavy"].astype(int))] = EXAMPLE_B.inputs["heavy_weight"]
    np.testing.assert_allclose(f.ffd(point, lattice, box, weights), EXAMPLE_B.results["heavy_crossing"], atol=1e-12)


@pytest.mark.parametrize("seed", range(6))
def test_ffd_is_the_tensor_product_bernstein_sum_and_the_patch(seed):
    rng = np.random.default_rng(seed)
    m, n = (int(k) for k in rng.integers(1, 6, 2))
    lattice, weights = random_lattice(rng, m, n)
    points = inside(rng, 300)
    moved = f.ffd(points, lattice, BOX, weights)
    np.testing.assert_allclose(moved, bernstein_sum(points, lattice, BOX, weights), atol=1e-12)
    st = f.ffd_parameters(points, BOX)
    np.testing.assert_allclose(moved, patch_point(lattice, st[:, 0], st[:, 1], weights), atol=1e-13)
    unit = np.ones((m + 1, n + 1))
    np.testing.assert_allclose(f.ffd(points, lattice, BOX), bernstein_sum(points, lattice, BOX, unit), atol=1e-12)


def test_ffd_agrees_with_scipy_and_geomdl():
    from geomdl import NURBS
    from scipy.interpolate import NdBSpline

    rng = np.random.default_rng(14)
    m, n = 3, 2
    lattice, weights = random_lattice(rng, m, n)
    points = inside(rng, 50)
    st = f.ffd_parameters(points, BOX)
    moved = f.ffd(points, lattice, BOX, weights)
    homogeneous = np.concatenate([lattice * weights[..., None], weights[..., None]], axis=2)
    knots = ([0.0] * (m + 1) + [1.0] * (m + 1), [0.0] * (n + 1) + [1.0] * (n + 1))
    values = NdBSpline(knots, homogeneous, (m, n))(st)
    np.testing.assert_allclose(moved, values[:, :2] / values[:, 2:], atol=1e-13)

    surface = NURBS.Surface()
    surface.degree_u, surface.degree_v = m, n
    surface.ctrlpts_size_u, surface.ctrlpts_size_v = m + 1, n + 1
    surface.ctrlptsw = [[*(lattice[i, j] * weights[i, j]), 0.0, weights[i, j]]
                        for i in range(m + 1) for j in range(n + 1)]
    surface.knotvector_u, surface.knotvector_v = knots
    theirs = np.array([surface.evaluate_single((float(s), float(t)))[:2] for s, t in st])
    np.testing.assert_allclose(moved, theirs, atol=1e-12)


def test_points_outside_the_box_are_not_moved_and_the_box_is_closed():
    box, lattice = built(EXAMPLE_A)
    outside = OUTSIDE.inputs["points"]
    np.testing.assert_array_equal(f.ffd(outside, lattice, box), outside)
    # On the boundary a point is inside: the top edge follows the lattice's top row (here it stays put, since
    # only the centre moved), and just above it nothing moves.
    edge = np.column_stack([np.linspace(0, 3, 7), np.full(7, 2.0)])
    np.testing.assert_allclose(f.ffd(edge, lattice, box), bezier.evaluate(lattice[:, 2], np.linspace(0, 1, 7)))
    bent = lattice.copy()
    bent[1, 2] = (1.5, 2.6)
    on_edge = f.ffd([1.5, 2.0], bent, box)
    assert on_edge[1] == pytest.approx(2.0 + 0.6 / 2)  # the top row is a quadratic: its middle rises by half
    np.testing.assert_array_equal(f.ffd([1.5, 2.0 + 1e-12], bent, box), [1.5, 2.0 + 1e-12])  # a tear


def test_shapes_of_ffd():
    box, lattice = built(EXAMPLE_A)
    assert f.ffd([1.0, 1.0], lattice, box).shape == (2,)
    assert f.ffd([[1.0, 1.0]], lattice, box).shape == (1, 2)
    assert f.ffd(np.zeros((0, 2)), lattice, box).shape == (0, 2)
    assert f.ffd_parameters([1.0, 1.0], box).shape == (2,)


# ---------------------------------------------------------------- images of grid lines


def test_example_b_isolines_through_the_row_and_column_curves():
    box, lattice = built(EXAMPLE_B)
    s, t = EXAMPLE_B.args("s", "t")
    rows, row_weights = f.isoline_image(lattice, s, "s")
    assert len(rows) - 1 == EXAMPLE_B.results["isoline_s_degree"]
    np.testing.assert_allclose(rows, EXAMPLE_B.results["row_points"], atol=1e-14)
    np.testing.assert_array_equal(row_weights, 1.0)
    # H_j(s) is the cubic with the j-th row of the lattice as its control polygon.
    for j in range(3):
        np.testing.assert_allclose(rows[j], bezier.de_casteljau(lattice[:, j], s), atol=1e-15)
    columns, _ = f.isoline_image(lattice, t, "t")
    assert len(columns) - 1 == EXAMPLE_B.results["isoline_t_degree"]
    np.testing.assert_allclose(columns, EXAMPLE_B.results["column_points"], atol=1e-14)
    # Both curves pass through the image of the crossing point (s, t).
    crossing = EXAMPLE_B.results["crossing"]
    np.testing.assert_allclose(bezier.evaluate(rows, t), crossing, atol=1e-14)
    np.testing.assert_allclose(bezier.evaluate(columns, s), crossing, atol=1e-14)


def test_example_b_rational_isoline():
    box, lattice = built(EXAMPLE_B)
    weights = np.ones((4, 3))
    weights[1, 1] = EXAMPLE_B.inputs["heavy_weight"]
    rows, row_weights = f.isoline_image(lattice, EXAMPLE_B.inputs["s"], weights=weights)
    homogeneous = EXAMPLE_B.results["heavy_row_homogeneous"]
    np.testing.assert_allclose(row_weights, EXAMPLE_B.results["heavy_row_weights"], atol=1e-14)
    np.testing.assert_allclose(rows, homogeneous[:, :2] / homogeneous[:, 2:], atol=1e-14)
    np.testing.assert_allclose(bezier.evaluate(rows, EXAMPLE_B.inputs["t"], row_weights),
                               EXAMPLE_B.results["heavy_crossing"], atol=1e-12)


@pytest.mark.parametrize("seed", range(4))
def test_isoline_images_are_the_deformed_lines(seed):
    rng = np.random.default_rng(seed + 20)
    m, n = (int(k) for k in rng.integers(1, 6, 2))
    lattice, weights = random_lattice(rng, m, n)
    ts = np.linspace(0, 1, 17)
    values = rng.uniform(0, 1, 3)
    points, curve_weights = f.isoline_image(lattice, values, "s", weights)
    assert points.shape == (3, n + 1, 2) and curve_weights.shape == (3, n + 1)
    for value, pts, w in zip(values, points, curve_weights):
        line = np.column_stack([np.full(17, BOX[0, 0] + value * 4.0), BOX[0, 1] + ts * 3.0])
        np.testing.assert_allclose(bezier.evaluate(pts, ts, w), f.ffd(line, lattice, BOX, weights), atol=1e-12)
    points, curve_weights = f.isoline_image(lattice, values[0], "t", weights)
    assert points.shape == (m + 1, 2)
    line = np.column_stack([BOX[0, 0] + ts * 4.0, np.full(17, BOX[0, 1] + values[0] * 3.0)])
    np.testing.assert_allclose(bezier.evaluate(points, ts, curve_weights), f.ffd(line, lattice, BOX, weights),
                               atol=1e-12)


# ---------------------------------------------------------------- freezing and continuity


def contact_orders(lattice, box, weights, hs=(0.01, 0.005, 0.0025, 0.00125)) -> np.ndarray:
    """Observed orders of |F(x, ymin + h) - (x, ymin + h)| as h halves, at three x: about k + 1 for a C^k join."""
    xs = box[0, 0] + np.array([0.3, 0.55, 0.8]) * (box[1, 0] - box[0, 0])
    gaps = []
    for h in hs:
        points = np.column_stack([xs, np.full(3, box[0, 1] + h * (box[1, 1] - box[0, 1]))])
        gaps.append(np.linalg.norm(f.ffd(points, lattice, box, weights) - points, axis=1).max())
    return np.log2(np.array(gaps[:-1]) / np.array(gaps[1:]))


def test_freezing_k_plus_1_rows_gives_contact_of_order_k_plus_1():
    rng = np.random.default_rng(5)
    lattice, weights = random_lattice(rng, 3, 4, spread=0.1)
    assert np.all(contact_orders(lattice, BOX, weights) < 0.2)  # the bottom edge itself moved: a tear
    for order, rows in zip(FREEZING.inputs["orders"], FREEZING.results["frozen_rows"]):
        frozen, frozen_weights = f.freeze(lattice, BOX, "bottom", int(order), weights)
        identity = f.identity_lattice(BOX, 3, 4)
        np.testing.assert_array_equal(frozen[:, : int(rows)], identity[:, : int(rows)])
        np.testing.assert_array_equal(frozen[:, int(rows):], lattice[:, int(rows):])
        np.testing.assert_array_equal(frozen_weights[:, : int(rows)], 1.0)
        np.testing.assert_array_equal(frozen_weights[:, int(rows):], weights[:, int(rows):])
        observed = contact_orders(frozen, BOX, frozen_weights)
        np.testing.assert_allclose(observed[-1], order + 1, atol=0.15)
        assert f.edge_continuity(frozen, BOX, "bottom", frozen_weights)[0] == order


def test_freezing_with_the_old_unequal_weights_loses_the_join():
    rng = np.random.default_rng(6)
    lattice, weights = random_lattice(rng, 3, 3, spread=0.1)
    frozen, _ = f.freeze(lattice, BOX, "bottom", 1, weights)
    assert f.edge_continuity(frozen, BOX, "bottom", weights)[0] == -1
    assert contact_orders(frozen, BOX, weights)[-1] < 0.2


@pytest.mark.parametrize("edge", f.EDGES)
def test_every_edge_freezes_to_the_requested_order(edge):
    rng = np.random.default_rng(len(edge))
    lattice, weights = random_lattice(rng, 4, 3)
    count = 3 if edge in ("bottom", "top") else 4
    for order in range(count + 1):
        frozen, frozen_weights = f.freeze(lattice, BOX, edge, order, weights)
        got, jumps = f.edge_continuity(frozen, BOX, edge, frozen_weights, max_order=5)
        assert got == (5 if order == count else order)  # every row frozen: the identity
        assert jumps.shape == (6,)
        if order < count:
            assert jumps[order + 1] > 1e-3
    assert f.edge_continuity(lattice, BOX, edge, weights)[0] == -1


def test_freezing_does_not_touch_the_other_side():
    box, lattice = built(EXAMPLE_B)
    frozen, weights = f.freeze(lattice, box, "top", 0)
    np.testing.assert_array_equal(frozen[:, :2], lattice[:, :2])
    np.testing.assert_array_equal(frozen[:, 2], f.identity_lattice(box, 3, 2)[:, 2])
    np.testing.assert_array_equal(weights, 1.0)
    assert f.edge_continuity(frozen, box, "top")[0] == 0
    # The point (3.5, -0.5) moved off the bottom edge: there the plane tears.
    assert f.edge_continuity(frozen, box, "bottom")[0] == -1


# ---------------------------------------------------------------- images of curves


@pytest.mark.parametrize("seed", range(5))
def test_the_image_of_a_curve_has_degree_k_m_plus_n_and_is_the_deformed_curve(seed):
    rng = np.random.default_rng(seed + 40)
    m, n = (int(v) for v in rng.integers(1, 5, 2))
    k = int(rng.integers(1, 5))
    lattice, weights = random_lattice(rng, m, n)
    curve = inside(rng, k + 1)
    curve_weights = rng.uniform(0.5, 2.0, k + 1) if seed % 2 else None
    points, image_weights = f.ffd_curve(curve, lattice, BOX, weights, curve_weights)
    assert points.shape == (k * (m + n) + 1, 2) and np.all(image_weights > 0)
    us = np.linspace(0, 1, 41)
    np.testing.assert_allclose(bezier.evaluate(points, us, image_weights),
                               f.ffd(bezier.evaluate(curve, us, curve_weights), lattice, BOX, weights), atol=1e-12)


def test_deforming_the_control_points_is_not_deforming_the_curve():
    box, lattice = built(EXAMPLE_A)
    curve = np.array([[0.3, 0.2], [1.0, 1.9], [2.2, 0.1], [2.8, 1.6]])
    us = np.linspace(0, 1, 101)
    exact = f.ffd(bezier.evaluate(curve, us), lattice, box)
    naive = bezier.evaluate(f.ffd(curve, lattice, box), us)
    assert np.abs(naive - exact).max() > 0.05
    points, weights = f.ffd_curve(curve, lattice, box)
    np.testing.assert_allclose(bezier.evaluate(points, us, weights), exact, atol=1e-13)


def test_a_vertical_segment_maps_to_the_isoline_image_raised_in_degree():
    box, lattice = built(EXAMPLE_B)
    s = EXAMPLE_B.inputs["s"]
    x = box[0, 0] + s * (box[1, 0] - box[0, 0])
    points, weights = f.ffd_curve([[x, box[0, 1]], [x, box[1, 1]]], lattice, box)
    assert len(points) - 1 == 3 + 2  # k (m + n) with k = 1: the quadratic raised three times
    rows, _ = f.isoline_image(lattice, s)
    np.testing.assert_allclose(points, bezier.elevate(rows, 3), atol=1e-13)


# ---------------------------------------------------------------- bad input


LATTICE_A = built(EXAMPLE_A)[1]
BOX_A = EXAMPLE_A.inputs["box"]


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: f.ffd_parameters([1.0, 1.0], [0.0, 0.0, 3.0, 2.0]), "box"),  # a flat 4-tuple
        (lambda: f.ffd_parameters([1.0, 1.0], [[3.0, 0.0], [0.0, 2.0]]), "box"),  # corners swapped
        (lambda: f.ffd_parameters([1.0, 1.0], [[0.0, 1.0], [3.0, 1.0]]), "box"),  # no height
        (lambda: f.ffd_parameters([[1.0, 1.0, 1.0]], BOX_A), "points"),
        (lambda: f.identity_lattice(BOX_A, 0, 2), "m"),
        (lambda: f.identity_lattice(BOX_A, 2, 1.5), "n"),
        (lambda: f.ffd([1.0, 1.0], LATTICE_A[:, :1], BOX_A), "lattice"),  # n = 0
        (lambda: f.ffd([1.0, 1.0], LATTICE_A.reshape(9, 2), BOX_A), "lattice"),
        (lambda: f.ffd([1.0, 1.0], LATTICE_A, BOX_A, np.ones((3, 2))), "weights"),
        (lambda: f.ffd([1.0, 1.0], LATTICE_A, BOX_A, np.zeros((3, 3))), "weights"),
        (lambda: f.ffd([1.0, 1.0], LATTICE_A, BOX_A, -np.ones((3, 3))), "weights"),
        (lambda: f.isoline_image(LATTICE_A, 1.2), "value"),
        (lambda: f.isoline_image(LATTICE_A, [[0.5]]), "value"),
        (lambda: f.isoline_image(LATTICE_A, 0.5, "x"), "direction"),
        (lambda: f.freeze(LATTICE_A, BOX_A, "middle", 0), "edge"),
        (lambda: f.freeze(LATTICE_A, BOX_A, "bottom", 3), "order"),
        (lambda: f.freeze(LATTICE_A, BOX_A, "bottom", -1), "order"),
        (lambda: f.edge_continuity(LATTICE_A, BOX_A, "bottom", tol=0.0), "tol"),
        (lambda: f.ffd_curve([[0.0, 1.0], [3.5, 1.0]], LATTICE_A, BOX_A), "points"),  # leaves the box
        (lambda: f.ffd_curve([[0.0, 1.0], [3.0, 1.0]], LATTICE_A, BOX_A, None, [1.0, 0.0]), "curve_weights"),
    ],
)
def test_bad_input_is_refused_by_name(call, name):
    with pytest.raises((ValueError, TypeError), match=rf"^{name}\b"):
        call()
