"""Unit tests of cagd_ref.tsplines: T-meshes, Rule 1, the T-spline equation and local refinement (notes §15.7).

The notes' numerical example (Fig. 15.17) is checked entry by entry: the knot vectors of all 28 control
points, the blending functions at (3, 4) as exact fractions (B10 = 23/100 also by the notes' own method,
polar labels of an explicit B-spline) and their sum 12869/12600. The Rule-1 examples of Fig. 15.15 and
the local refinement of Fig. 15.20 run on designed meshes that reproduce the notes' statements. Peers:
`scipy.interpolate.BSpline.basis_element` for the univariate functions, `bspline.bspline_basis`,
`scipy.interpolate.NdBSpline` for a T-mesh that is a full grid (a tensor-product B-spline), exact
fractions for the refinement coefficients, and dense sampling for "the surface is unchanged".
"""

from __future__ import annotations

import copy
from fractions import Fraction

import numpy as np
import pytest
from scipy.interpolate import BSpline, NdBSpline

from cagd_course.examples import notes_example
from cagd_ref import bspline
from cagd_ref import tsplines as ts

E2 = notes_example("15.tmesh")
E3 = notes_example("15.rule1")
E4 = notes_example("15.refinement")
REFINE = notes_example("15.refine_blending")
MESH = E2.inputs["mesh"]
POINTS = np.column_stack([MESH["vertices"], E2.inputs["heights"]])
GRID = [a.ravel() for a in np.meshgrid(np.linspace(0, 8, 33), np.linspace(0, 7, 29))]


def _fraction(x: float) -> Fraction:
    return Fraction(x).limit_denominator(100_000)


# --------------------------------------------------------------------------- the mesh as data


def test_the_example_mesh_is_the_consecutive_joining_of_its_rows_and_columns():
    built = ts.tmesh(MESH["vertices"], frame=MESH["frame"])
    assert sorted(map(tuple, built["edges"])) == sorted(map(tuple, MESH["edges"].astype(int).tolist()))
    assert ts.mesh_domain(MESH) == ((0.0, 8.0), (0.0, 7.0))
    np.testing.assert_array_equal(ts.frame_knots({"vertices": MESH["vertices"], "edges": []}), MESH["frame"])


def test_knot_intervals_give_back_the_knot_coordinates_of_fig_15_17():
    inputs = E2.inputs
    coords = ts.knot_coordinates(inputs["h_edges"].astype(int), inputs["h_intervals"],
                                 inputs["v_edges"].astype(int), inputs["v_intervals"])
    np.testing.assert_array_equal(coords, MESH["vertices"])
    form = ts.mesh_intervals(MESH)
    np.testing.assert_array_equal(form["h_edges"], inputs["h_edges"])
    np.testing.assert_array_equal(form["h_intervals"], inputs["h_intervals"])
    np.testing.assert_array_equal(form["v_intervals"], inputs["v_intervals"])
    # Another origin shifts every coordinate by the same vector.
    shifted = ts.knot_coordinates(inputs["h_edges"].astype(int), inputs["h_intervals"],
                                  inputs["v_edges"].astype(int), inputs["v_intervals"], origin=10)
    np.testing.assert_array_equal(shifted, coords - coords[10])


def test_a_face_whose_opposite_sides_differ_breaks_t_mesh_rule_1():
    h_intervals = E2.inputs["h_intervals"].copy()
    h_intervals[8] += 1  # P10-P11: the face above P6-P7 no longer closes
    with pytest.raises(ValueError, match="rule 1"):
        ts.knot_coordinates(E2.inputs["h_edges"].astype(int), h_intervals, E2.inputs["v_edges"].astype(int),
                            E2.inputs["v_intervals"])
    with pytest.raises(ValueError, match="not connected"):
        ts.knot_coordinates([[0, 1]], [1.0], [[2, 3]], [1.0])


@pytest.mark.parametrize(
    "mesh, match",
    [
        ("not a mesh", "^mesh"),
        ({"vertices": [[0, 0]]}, "^mesh: expected the keys"),
        ({"vertices": [[0, 0], [1, 1]], "edges": [[0, 1]]}, "neither horizontal"),
        ({"vertices": [[0, 0], [0, 0]], "edges": []}, "same knot coordinates"),
        ({"vertices": [[0, 0], [1, 0]], "edges": [[0, 2]]}, "0..1"),
        ({"vertices": [[0, 0], [1, 0]], "edges": [[0, 0.5]]}, "whole numbers"),
        ({"vertices": [[0, 0], [1, 0]], "edges": [[0, 1]], "frame": [[-2, 0, 2, 3], [-2, -1, 1, 2]]}, "frame"),
        ({"vertices": [[0, 0], [1, 0]], "edges": [[0, 1]], "weights": [1, 1]}, "unknown"),
        ({"vertices": [[0, 0, 0]], "edges": []}, "shape"),
    ],
)
def test_bad_meshes_are_rejected_by_name(mesh, match):
    with pytest.raises((ValueError, TypeError), match=match):
        ts.infer_knot_vectors(mesh, 0)


# --------------------------------------------------------------------------- Rule 1


def test_rule_1_gives_every_knot_vector_of_the_numerical_example():
    s_knots, t_knots = ts.all_knot_vectors(MESH)
    np.testing.assert_array_equal(s_knots, E2.results["s_knots"])
    np.testing.assert_array_equal(t_knots, E2.results["t_knots"])
    for i in range(28):
        single = ts.infer_knot_vectors(MESH, i)
        np.testing.assert_array_equal(single[0], s_knots[i])
        np.testing.assert_array_equal(single[1], t_knots[i])


def test_the_knot_vectors_the_notes_print():
    for vertex, name in ((10, "b10"), (15, "b15")):
        s_knots, t_knots = ts.infer_knot_vectors(MESH, vertex)
        np.testing.assert_array_equal([s_knots, t_knots], E2.results[name])
    s0, t0 = ts.infer_knot_vectors(MESH, 0)
    np.testing.assert_array_equal([s0[2:], t0[2:]], E2.results["b0_inner"])
    s27, t27 = ts.infer_knot_vectors(MESH, 27)
    np.testing.assert_array_equal([s27[:3], t27[:3]], E2.results["b27_inner"])


def test_a_t_junction_on_the_ray_counts_and_the_own_edges_do_not():
    # P10 = (2, 3) has no vertex to its left on t = 3, yet the columns s = 1 and s = 0 cross that line.
    s_knots, _ = ts.infer_knot_vectors(MESH, 10)
    assert s_knots[:2].tolist() == [0.0, 1.0]
    # P2 = (7, 0): going up, the column s = 7 is its own; the rows t = 1 and t = 3 are met.
    _, t_knots = ts.infer_knot_vectors(MESH, 2)
    assert t_knots[3:].tolist() == [1.0, 3.0]


def test_rule_1_examples_of_fig_15_15():
    mesh = E3.inputs["mesh"]
    for k, vertex in enumerate(E3.inputs["vertices"].astype(int)):
        s_knots, t_knots = ts.infer_knot_vectors(mesh, int(vertex))
        np.testing.assert_array_equal(s_knots, E3.results["s_knots"][k])
        np.testing.assert_array_equal(t_knots, E3.results["t_knots"][k])


def test_the_frame_supplies_the_knots_beyond_the_mesh():
    framed = dict(MESH, frame=[[-5, -3, 11, 12], [-0.5, -0.25, 7.5, 10]])
    s_knots, t_knots = ts.infer_knot_vectors(framed, 0)
    assert s_knots.tolist()[:2] == [-5.0, -3.0] and t_knots.tolist()[:2] == [-0.5, -0.25]
    s_knots, t_knots = ts.infer_knot_vectors(framed, 27)
    assert s_knots.tolist()[3:] == [11.0, 12.0] and t_knots.tolist()[3:] == [7.5, 10.0]
    unframed = {"vertices": MESH["vertices"], "edges": MESH["edges"]}
    np.testing.assert_array_equal(ts.infer_knot_vectors(unframed, 0)[0], [-2, -1, 0, 1, 7])


def test_vertex_must_be_an_index():
    for bad, error in ((28, ValueError), (-1, ValueError), (2.0, TypeError), (True, TypeError)):
        with pytest.raises(error, match="^vertex"):
            ts.infer_knot_vectors(MESH, bad)


# --------------------------------------------------------------------------- blending functions


def test_the_blending_functions_at_3_4_as_fractions():
    values = ts.blending_values(MESH, 3, 4)
    np.testing.assert_allclose(values, E2.results["blending"], rtol=1e-13, atol=1e-15)
    assert _fraction(values[10]) == Fraction(23, 100)
    assert _fraction(values[15]) == Fraction(77, 300)
    assert np.flatnonzero(values == 0).tolist() == E2.results["zero"].astype(int).tolist()
    assert _fraction(values.sum()) == Fraction(12869, 12600)  # not a partition of unity
    assert set(E2.errata["zero_list"].correct) - set(E2.errata["zero_list"].notes) == {4}


def test_only_the_boundary_functions_depend_on_the_frame():
    other = ts.blending_values(dict(MESH, frame=[[-4, -1.5, 8.5, 11], [-3, -0.5, 9, 10]]), 3, 4)
    values = ts.blending_values(MESH, 3, 4)
    changed = np.flatnonzero(~np.isclose(other, values, rtol=1e-12, atol=0))
    assert changed.tolist() == E2.results["frame_dependent"].astype(int).tolist()


def test_b10_by_polar_labels_as_the_notes_compute_it():
    # N[0,1,2,5,7](s) is the explicit B-spline on 0 0 0 1 2 5 7 7 7 with only f(1,2,5) = 1 (control point 3).
    s_factor = bspline.bspline_basis([0, 0, 0, 1, 2, 5, 7, 7, 7], 3, 3, 3.0)
    t_factor = bspline.bspline_basis([0, 0, 0, 1, 3, 5, 6, 6, 6], 3, 3, 4.0)
    np.testing.assert_allclose([s_factor, t_factor], E2.results["b10_factors"], rtol=1e-14)
    labels_s = [(1, 2, 3), (2, 3, 5), (3, 5, 7), (2, 3, 3), (3, 3, 5)]
    coefficients = np.array([[0.0], [0.0], [0.0], [1.0], [0.0], [0.0], [0.0]])
    polar = bspline.polar_values(coefficients, [0, 0, 0, 1, 2, 5, 7, 7, 7], labels_s)[:, 0]
    np.testing.assert_allclose(polar, E2.results["b10_polar_s"], atol=1e-14)
    labels_t = [(1, 3, 4), (3, 4, 5), (4, 5, 6), (3, 4, 4), (4, 4, 5)]
    polar = bspline.polar_values(coefficients, [0, 0, 0, 1, 3, 5, 6, 6, 6], labels_t)[:, 0]
    np.testing.assert_allclose(polar, E2.results["b10_polar_t"], atol=1e-14)
    assert ts.blending_function([0, 1, 2, 5, 7], [0, 1, 3, 5, 6], 3, 4) == pytest.approx(0.23, rel=1e-14)


def test_cubic_blending_agrees_with_scipy_and_chapter_6():
    rng = np.random.default_rng(15)
    for _ in range(20):
        knots = np.sort(rng.uniform(-3, 3, 5))
        x = np.linspace(knots[0] - 0.5, knots[4] + 0.5, 41)
        expected = np.nan_to_num(BSpline.basis_element(knots, extrapolate=False)(x))
        np.testing.assert_allclose(ts.cubic_blending(knots, x), expected, atol=1e-13)
    padded = [0, 0, 0, 1, 2, 5, 7, 7, 7]  # N[0,1,2,5,7] is basis function 3 there (the notes' convention)
    x = np.linspace(0, 7, 15)
    np.testing.assert_allclose(ts.cubic_blending([0, 1, 2, 5, 7], x), bspline.bspline_basis(padded, 3, 3, x),
                               atol=1e-14)
    assert ts.cubic_blending([0, 1, 2, 5, 7], 3) == pytest.approx(0.6)
    assert ts.cubic_blending([0, 1, 3, 5, 6], 4) == pytest.approx(23 / 60)


# --------------------------------------------------------------------------- the T-spline equation


def _homogeneous_sum(mesh, points, weights, s, t):
    values = ts.blending_values(mesh, s, t)
    numerator = (values * weights) @ points
    return numerator / (values @ weights)[:, None]


def test_tspline_point_is_the_weighted_average_of_the_equation():
    weights = np.random.default_rng(1).uniform(0.5, 2.0, 28)
    s, t = GRID
    np.testing.assert_allclose(ts.tspline_point(MESH, POINTS, s, t, weights),
                               _homogeneous_sum(MESH, POINTS, weights, s, t), rtol=1e-13)
    # Without the denominator the unit-weight point at (3, 4) would be off by the factor 12869/12600.
    values = ts.blending_values(MESH, 3, 4)
    assert not np.allclose(values @ POINTS, ts.tspline_point(MESH, POINTS, 3, 4))
    # Equal weights cancel.
    np.testing.assert_allclose(ts.tspline_point(MESH, POINTS, s, t, np.full(28, 3.0)),
                               ts.tspline_point(MESH, POINTS, s, t), rtol=1e-13)


def test_tspline_point_shapes():
    assert ts.tspline_point(MESH, POINTS, 3, 4).shape == (3,)
    assert ts.tspline_point(MESH, POINTS, [3, 5], 4).shape == (2, 3)
    assert ts.tspline_point(MESH, POINTS[:, :2], [3, 5, 0], [4, 1, 7]).shape == (3, 2)
    assert ts.tspline_point(MESH, POINTS, [], 4).shape == (0, 3)
    # Without clamped end knots the surface does not pass through its corner control point.
    assert np.linalg.norm(ts.tspline_point(MESH, POINTS, 0, 0) - POINTS[0]) > 0.05


def test_a_full_grid_t_mesh_is_a_tensor_product_b_spline():
    s_lines, t_lines = np.array([0.0, 1.0, 2.5, 3.0, 5.0, 6.0]), np.array([0.0, 2.0, 3.0, 4.5, 6.0])
    vertices = [(s, t) for t in t_lines for s in s_lines]
    mesh = ts.tmesh(vertices)
    rng = np.random.default_rng(3)
    points = rng.uniform(-1, 1, (len(vertices), 3))
    weights = rng.uniform(0.5, 2.0, len(vertices))
    frame = ts.frame_knots(mesh)
    knots_s = np.concatenate([frame[0, :2], s_lines, frame[0, 2:]])
    knots_t = np.concatenate([frame[1, :2], t_lines, frame[1, 2:]])
    grid = lambda a: a.reshape(len(t_lines), len(s_lines), -1).transpose(1, 0, 2)  # noqa: E731
    homogeneous = grid(np.column_stack([points * weights[:, None], weights]))
    surface = NdBSpline((knots_s, knots_t), homogeneous, 3)
    # The tensor-product functions sum to one where a full set of them is active: [s_1, s_(c-2)] × [t_1, t_(r-2)].
    s = rng.uniform(s_lines[1], s_lines[-2], 50)
    t = rng.uniform(t_lines[1], t_lines[-2], 50)
    expected = surface(np.column_stack([s, t]))
    np.testing.assert_allclose(ts.tspline_point(mesh, points, s, t, weights), expected[:, :3] / expected[:, 3:],
                               rtol=1e-12, atol=1e-12)


def test_tspline_point_rejects_bad_input():
    with pytest.raises(ValueError, match="^points"):
        ts.tspline_point(MESH, POINTS[:27], 3, 4)
    with pytest.raises(ValueError, match="^weights"):
        ts.tspline_point(MESH, POINTS, 3, 4, np.ones(27))
    with pytest.raises(ValueError, match="^weights"):
        ts.tspline_point(MESH, POINTS, 3, 4, np.r_[0.0, np.ones(27)])
    with pytest.raises(ValueError, match="outside the domain"):
        ts.tspline_point(MESH, POINTS, 8.5, 4)
    with pytest.raises(ValueError, match="^s"):
        ts.tspline_point(MESH, POINTS, [1, 2], [1, 2, 3])
    with pytest.raises(TypeError, match="^mesh"):
        ts.tspline_point([MESH], POINTS, 3, 4)


def test_nothing_is_modified():
    mesh, points = copy.deepcopy(MESH), POINTS.copy()
    ts.tspline_point(mesh, points, GRID[0], GRID[1])
    ts.local_refinement(mesh, points, [[4, 3]], [[28, 15]])
    np.testing.assert_array_equal(points, POINTS)
    for key in mesh:
        np.testing.assert_array_equal(mesh[key], MESH[key])


# --------------------------------------------------------------------------- refinement of blending functions


def test_the_four_cases_of_knot_insertion():
    knots = REFINE.inputs["knots"]
    for k, c, d in zip(REFINE.inputs["inserted"], REFINE.results["c"], REFINE.results["d"]):
        pieces = ts.refine_blending_function(knots, [0, 1, 2, 3, 4], k)
        coefficients = [p[0] for p in pieces] + ([0.0] if len(pieces) == 1 else [])
        assert coefficients == pytest.approx([c, d], rel=1e-14)
        x = np.linspace(-1, 8, 91)
        total = sum(coef * ts.cubic_blending(sk, x) for coef, sk, _ in pieces)
        np.testing.assert_allclose(total, ts.cubic_blending(knots, x), atol=1e-14)
    # Outside the support nothing changes.
    assert [p[0] for p in ts.refine_blending_function(knots, [0, 1, 2, 3, 4], 7.5)] == [1.0]


def test_refinement_in_both_directions_15_18():
    s_knots, t_knots = REFINE.inputs["b1"]
    k_s, k_t = REFINE.inputs["b1_knots"]
    pieces = []
    for c, sk, tk in ts.refine_blending_function(s_knots, t_knots, k_s, "s"):
        pieces += [(c * c2, sk2, tk2) for c2, sk2, tk2 in ts.refine_blending_function(sk, tk, k_t, "t")]
    np.testing.assert_allclose([p[0] for p in pieces], REFINE.results["b1_coefficients"], rtol=1e-14)
    np.testing.assert_array_equal([p[1] for p in pieces], REFINE.results["b1_s_knots"])
    np.testing.assert_array_equal([p[2] for p in pieces], REFINE.results["b1_t_knots"])
    s, t = np.random.default_rng(4).uniform(-0.5, 4.5, (2, 200))
    total = sum(c * ts.blending_function(sk, tk, s, t) for c, sk, tk in pieces)
    np.testing.assert_allclose(total, ts.blending_function(s_knots, t_knots, s, t), atol=1e-15)


# --------------------------------------------------------------------------- local refinement


def _refine_e4(weights=None):
    mesh = E4.inputs["mesh"]
    vertices = np.array(mesh["vertices"])
    points = np.column_stack([vertices, np.sin(vertices[:, 0]) * np.cos(vertices[:, 1] / 2)])
    result = ts.local_refinement(mesh, points, E4.inputs["new_vertices"], E4.inputs["new_edges"].astype(int),
                                 weights)
    return mesh, points, result


def test_the_refinement_of_fig_15_20_step_by_step():
    _, _, (refined, _, weights, log) = _refine_e4()
    assert [entry["action"] for entry in log] == E4.results["actions"]
    counts = [[len(v) for v in entry["violations"]] for entry in log]
    assert counts == E4.results["counts"].astype(int).tolist()
    inserted = log[1]
    centres = sorted((float(inserted["records"][r][0][2]), float(inserted["records"][r][1][2]))
                     for r in inserted["violations"][0])
    assert centres == [tuple(c) for c in E4.results["violation_1_centres"]]
    assert refined["vertices"][-1] == E4.results["added"].tolist()
    assert len(refined["vertices"]) == E4.results["vertices"]
    np.testing.assert_allclose(weights[-2:], E4.results["new_weights"], rtol=1e-14)
    np.testing.assert_allclose(weights[:-2], 1.0, rtol=1e-14)


def test_refinement_coefficients_15_16():
    # The knots s3 = 4 goes into N[s0, s1, s2, s4, s5] = N[0, 1, 3, 6, 7] and N[s1, s2, s4, s5, s6] = N[1, 3, 6, 7, 8].
    for knots, expected in zip(([0, 1, 3, 6, 7], [1, 3, 6, 7, 8]), E4.results["c2_d2"]):
        pieces = ts.refine_blending_function(knots, [0, 2, 3, 5, 6], 4.0)
        assert [p[0] for p in pieces] == pytest.approx(expected, rel=1e-14)


def test_refinement_keeps_the_surface_and_ends_with_rule_1():
    mesh, points, (refined, new_points, new_weights, log) = _refine_e4(np.linspace(0.5, 2.0, 37))
    s, t = [a.ravel() for a in np.meshgrid(np.linspace(0, 8, 23), np.linspace(0, 8, 21))]
    np.testing.assert_allclose(ts.tspline_point(refined, new_points, s, t, new_weights),
                               ts.tspline_point(mesh, points, s, t, np.linspace(0.5, 2.0, 37)), atol=1e-13)
    # The records of the last step are the Rule-1 functions of the refined mesh, one per vertex.
    final = log[-1]["records"]
    assert len(final) == len(refined["vertices"])
    assert ts.violations(refined, final) == ([], [], [])
    s_knots, t_knots = ts.all_knot_vectors(refined)
    centres = {(float(sk[2]), float(tk[2])): (sk, tk) for sk, tk, _ in final}
    for i, vertex in enumerate(refined["vertices"]):
        np.testing.assert_array_equal(centres[tuple(vertex)], (s_knots[i], t_knots[i]))


@pytest.mark.parametrize(
    "new_vertices, new_edges",
    [([[4, 3]], [[28, 15]]), ([[4, 1]], [[28, 15]]), ([[1, 3], [0, 3]], [[28, 29]]), ([[5, 6]], [[28, 16]]),
     ([[4, 3], [4, 1]], [[28, 29], [28, 15]])],
)
def test_refinements_of_the_numerical_example_keep_its_surface(new_vertices, new_edges):
    weights = np.random.default_rng(5).uniform(0.5, 2.0, 28)
    refined, points, new_weights, log = ts.local_refinement(MESH, POINTS, new_vertices, new_edges, weights)
    assert log[-1]["action"] == "done" and ts.violations(refined, log[-1]["records"]) == ([], [], [])
    np.testing.assert_allclose(ts.tspline_point(refined, points, *GRID, new_weights),
                               ts.tspline_point(MESH, POINTS, *GRID, weights), atol=1e-13)


def test_violations_of_records_that_do_not_fit_the_mesh():
    records = ts.blending_records(MESH, POINTS)
    assert ts.violations(MESH, records) == ([], [], [])
    s_knots, t_knots, h = records[10]
    missing = (np.array([0.0, 1.0, 2.0, 7.0, 8.0]), t_knots, h)  # lacks s = 5
    extra = (s_knots, np.array([0.0, 1.0, 3.0, 4.0, 5.0]), h)  # t = 4 is no knot line at s = 2
    orphan = (np.array([1.0, 2.0, 3.0, 5.0, 7.0]), t_knots, h)  # centred at (3, 3): no control point
    v1, v2, v3 = ts.violations(MESH, records[:10] + [missing, extra, orphan] + records[11:])
    assert (v1, v2, v3) == ([10], [11, 12], [])
    assert ts.violations(MESH, records[:10] + records[11:])[2] == [10]


def test_local_refinement_rejects_bad_insertions():
    with pytest.raises(ValueError, match="^new_edges"):  # on a row, but not joined along a column
        ts.local_refinement(MESH, POINTS, [[4, 3]])
    with pytest.raises(ValueError, match="^new_vertices"):
        ts.local_refinement(MESH, POINTS, [[9, 3]])
    with pytest.raises(ValueError, match="^new_vertices"):
        ts.local_refinement(MESH, POINTS, [[2, 3]])  # already a vertex
