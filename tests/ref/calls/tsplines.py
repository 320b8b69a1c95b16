"""Valid calls of cagd_ref.tsplines for the contract test.

The T-mesh is a dict (not poisoned by the contract test); the calls use a 3 × 3 grid with one T-junction,
small enough to read: vertices (0, 0) (1, 0) (3, 0) / (0, 1) (1, 1) (3, 1) / (0, 2) (3, 2), the row t = 2
lacking s = 1, so the column s = 1 ends at the T-junction (1, 1).
"""

from . import Call

VERTICES = [[0.0, 0.0], [1.0, 0.0], [3.0, 0.0], [0.0, 1.0], [1.0, 1.0], [3.0, 1.0], [0.0, 2.0], [3.0, 2.0]]
EDGES = [[0, 1], [1, 2], [3, 4], [4, 5], [6, 7], [0, 3], [3, 6], [1, 4], [2, 5], [5, 7]]
MESH = {"vertices": VERTICES, "edges": EDGES}
FRAMED = {"vertices": VERTICES, "edges": EDGES, "frame": [[-3.0, -1.0, 4.0, 6.0], [-1.0, -0.5, 2.5, 3.0]]}
POINTS = [[s, t, (s - 1.0) * t] for s, t in VERTICES]
WEIGHTS = [1.0, 2.0, 1.0, 0.5, 1.0, 1.0, 1.5, 1.0]
RECORDS = [([-2.0, -1.0, 0.0, 1.0, 3.0], [-2.0, -1.0, 0.0, 1.0, 2.0], [0.0, 0.0, 0.0, 1.0])]

CALLS = {
    "tmesh": [Call((VERTICES,)), Call((VERTICES, EDGES, [[-2.0, -1.0, 4.0, 5.0], [-2.0, -1.0, 3.0, 4.0]])),
              Call((VERTICES, None, None, [[1, 4]]))],
    "mesh_domain": Call((MESH,)),
    "frame_knots": [Call((MESH,)), Call((FRAMED,))],
    "knot_coordinates": Call(([[0, 1], [2, 3]], [2.0, 2.0], [[0, 2], [1, 3]], [1.0, 1.0])),
    "mesh_intervals": Call((MESH,)),
    "infer_knot_vectors": [Call((MESH, 4)), Call((FRAMED, 0))],
    "all_knot_vectors": Call((FRAMED,)),
    "cubic_blending": Call(([0.0, 1.0, 2.0, 5.0, 7.0], 3.0), parameter="x"),
    "blending_function": Call(([0.0, 1.0, 2.0, 5.0, 7.0], [0.0, 1.0, 3.0, 5.0, 6.0], 3.0, 4.0), parameter="s"),
    "blending_values": Call((MESH, 1.5, 0.5), parameter="s"),
    "tspline_point": [Call((MESH, POINTS, 1.5, 0.5), parameter="s"),
                      Call((FRAMED, POINTS, 2.0, 1.5, WEIGHTS), parameter="s")],
    "refine_blending_function": [Call(([0.0, 1.0, 2.0, 5.0, 7.0], [0.0, 1.0, 2.0, 3.0, 4.0], 3.0)),
                                 Call(([0.0, 1.0, 2.0, 5.0, 7.0], [0.0, 1.0, 2.0, 3.0, 4.0], 1.5, "t"))],
    "blending_records": [Call((MESH, POINTS)), Call((MESH, POINTS, WEIGHTS))],
    "violations": Call((MESH, RECORDS)),
    # (1, 2) on the top row, joined down to the T-junction (1, 1); (2, 1) and (2, 0) on two rows, joined.
    "local_refinement": [Call((MESH, POINTS, [[1.0, 2.0]], [[4, 8]])),
                         Call((MESH, POINTS, [[2.0, 1.0], [2.0, 0.0]], [[8, 9]], WEIGHTS))],
}
