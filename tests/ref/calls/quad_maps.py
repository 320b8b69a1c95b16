"""Valid calls of cagd_ref.quad_maps for the contract test (Figure 21.1's quad; weights in the quad's (2, 2) layout)."""

from . import Call

QUAD = [[[0.0, 0.0], [8.0, 6.0]], [[12.0, 0.0], [12.0, 4.0]]]  # [[P00, P01], [P10, P11]]
BIRATIONAL = [[1.0, 5.0 / 3.0], [1.0, 1.0]]
IMAGE = [[0.0, 1.0], [2.0, 3.0]]

CALLS = {
    "quad_map": [Call((QUAD, 0.3, 0.6), parameter="s"), Call((QUAD, 0.3, 0.6), dict(weights=BIRATIONAL), parameter="s"),
                 Call((QUAD, 0.3, 0.6), parameter="t")],
    "homogeneous_quad": Call((QUAD, BIRATIONAL)),
    "bilinear_inverse": Call((QUAD, [8.0, 4.0])),
    "corner_determinants": Call((QUAD,)),
    "pencil_axes": Call((QUAD,)),
    "isoparameter_lines": [Call((QUAD,), dict(s=0.3, weights=BIRATIONAL), parameter="s"),
                           Call((QUAD,), dict(t=0.3), parameter="t")],
    "weight_condition": Call((QUAD, [[1.0, 1.0], [1.0, 1.0]])),
    "is_birational": Call((QUAD, BIRATIONAL), dict(tol=1e-9)),
    "birational_weight": Call((QUAD, [[1.0, 5.0 / 3.0], [1.0, 0.0]])),
    "birational_inverse": Call((QUAD, BIRATIONAL, [[8.0, 4.0], [6.0, 1.0]])),
    "base_point": Call((QUAD, BIRATIONAL)),
    "BasePoint": Call((0.5, 0.25, [1.0, 1.0, -1.0]), finite_only=("*",)),  # a plain record of numbers
    "projective_weights": Call((QUAD,)),
    "homography": Call((QUAD,)),
    "square_preimages": [Call((QUAD, [[8.0, 4.0], [20.0, 20.0]])), Call((QUAD, [[8.0, 4.0]], BIRATIONAL))],
    "warp_image": Call((IMAGE, QUAD, [[0.0, 0.0], [12.0, 6.0]], (3, 4)), dict(weights=BIRATIONAL)),
}
