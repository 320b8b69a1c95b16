"""Valid calls of cagd_ref.continuity for the contract test."""

from . import Call

P = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [5.0, 2.0]]
Q = [[5.0, 2.0], [9.0, 1.0], [13.0, -4.0], [16.0, -2.0]]

CALLS = {
    "Continuity": Call((3, 2)),
    "continuity": Call(
        (P, Q),
        dict(p_interval=(0.0, 1.0), q_interval=(1.0, 3.0), p_weights=[1.0, 2.0, 1.0, 1.0],
             q_weights=[1.0, 1.5, 0.5, 2.0], tol=1e-9),
    ),
    "curvature_vector": Call(([[0.0, 3.0], [1.0, 1.0]], [[-4.5, 0.0], [0.5, 2.0]])),
    "curvature_comb": Call((P,), dict(count=7, length=0.5, weights=[1.0, 2.0, 1.0, 1.5])),
}
