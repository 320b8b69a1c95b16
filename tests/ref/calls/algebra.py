"""Valid calls of cagd_ref.algebra for the contract test (ascending power coefficients, planar Bézier curves)."""

from . import Call

F = [1.0, 3.0, -2.0, 1.0]          # t³ - 2t² + 3t + 1
G = [4.0, -1.0, 3.0, 2.0]          # 2t³ + 3t² - t + 4
F_COMMON = [-4.0, -11.0, -1.0, 1.0]
G_COMMON = [4.0, -5.0, -7.0, 2.0]  # shares the root t = 4 with F_COMMON
PARABOLA = [[1.0, -2.0], [1.0, -1.0], [2.0, 1.0]]
CUBIC = [[4.0, 1.0], [5.0, 6.0], [5.0, 0.0], [6.0, 4.0]]
WEIGHTS = [1.0, 2.0, 2.0, 1.0]
QUARTIC = [[0.0, 0.0], [1.0, 2.0], [3.0, -1.0], [4.0, 2.0], [5.0, 0.0]]
OTHER = [[7.0, 4.0], [1.0, 2.0], [9.0, 2.0], [3.0, 4.0]]

CALLS = {
    "coefficients": [Call(([12.0, -7.0, 1.0, 0.0],)), Call(([0.0, 0.0],), dict(zero_ok=True))],
    "homogeneous_points": [Call((CUBIC,)), Call((CUBIC, WEIGHTS))],
    "sylvester_matrix": Call((F, [2.0, -3.0, 1.0])),
    "resultant": [Call((F, G)), Call(([12.0, -7.0, 1.0], [4.0, 2.0]))],
    "resultant_plain": [Call((F, G)), Call(([12.0, -7.0, 1.0], [4.0, 2.0]))],
    "root_product": Call(([3.0, 4.0], [2.0, 1.0]), dict(f_lead=2.0, g_lead=1.0)),
    "bezout_matrix": [Call((F, G)), Call((F, [1.0, 1.0]))],
    "bezout_from_brackets": [Call(([[0.0, -1.0, 2.0], [1.0, 0.0, 3.0], [-2.0, -3.0, 0.0]],)),
                             Call(([[[0.0, 0.0, 0.0], [1.0, 2.0, 3.0]], [[-1.0, -2.0, -3.0], [0.0, 0.0, 0.0]]],))],
    "bezout_matrix_plain": [Call((F, G)), Call((F, [1.0, 1.0]))],
    "fraction_free_eliminate": Call(([[7.0, -7.0, 2.0], [-7.0, -5.0, -11.0], [2.0, -11.0, 13.0]],)),
    "cramer_null_vector": Call(([[-5.0, 17.0, 12.0], [17.0, -60.0, -32.0]],)),
    "common_root_count": Call((F_COMMON, G_COMMON), dict(tol=1e-9)),
    "euclid_steps": Call((G_COMMON, F_COMMON), dict(tol=1e-9)),
    "poly_gcd": Call((F_COMMON, G_COMMON), dict(tol=1e-9)),
    "poly_gcd_plain": Call((F_COMMON, G_COMMON), dict(tol=1e-9)),
    "common_roots": Call((F_COMMON, G_COMMON), dict(tol=1e-9)),
    "l_lines": [Call((CUBIC,)), Call((CUBIC, WEIGHTS))],
    "bezout_lines": [Call((CUBIC,)), Call((CUBIC, WEIGHTS))],
    "power_bezout_lines": Call(([4.0, 18.0, -18.0, 2.0], [1.0, 33.0, -69.0, 39.0], [1.0, 3.0, -3.0])),
    "implicitize": [Call((PARABOLA,)), Call((CUBIC, WEIGHTS))],
    "line_determinant": Call(([[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], [[0.0, 1.0, 0.0], [1.0, 0.0, -1.0]]],)),
    "implicitize_plain": [Call((PARABOLA,)), Call((CUBIC, WEIGHTS))],
    "implicitize_power": Call(([4.0, 18.0, -18.0, 2.0], [1.0, 33.0, -69.0, 39.0], [1.0, 3.0, -3.0])),
    "implicit_eval": Call(([[-1.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]], [[0.6, 0.8], [1.0, 1.0]])),
    "cubic_inversion_lines": [Call((CUBIC,)), Call((CUBIC, WEIGHTS))],
    "inversion": [Call((PARABOLA,)), Call((CUBIC, WEIGHTS)), Call((QUARTIC,))],
    "invert": [Call((CUBIC, [5.0, 3.0], WEIGHTS)), Call((PARABOLA, [[5.0, -2.0], [1.0, -2.0]])),
               Call((QUARTIC, [2.5, 0.5]), dict(tol=1e-9))],
    "inversion_plain": [Call((PARABOLA,)), Call((CUBIC, WEIGHTS)), Call((QUARTIC,))],
    "invert_plain": [Call((CUBIC, [5.0, 3.0], WEIGHTS)), Call((PARABOLA, [[5.0, -2.0], [1.0, -2.0]]), dict(tol=1e-9))],
    "intersection_polynomial": Call((CUBIC, OTHER, WEIGHTS, WEIGHTS)),
    "intersect_implicit": Call((CUBIC, OTHER, WEIGHTS, WEIGHTS), dict(tol=1e-9)),
    "intersect_implicit_plain": Call((CUBIC, OTHER, WEIGHTS, WEIGHTS), dict(tol=1e-9)),
    # Degrees and exponents are counts (integers), not real numbers.
    "surface_implicit_degree": Call(("tensor", (3, 3)), dict(base_points=1), finite_only=("degree",)),
    "term_count": Call((18,)),
    "sort_terms": Call(([(2, 2, 1), (1, 3, 2), (3, 0, 1)],), dict(order="grlex"), finite_only=("exponents",)),
}
