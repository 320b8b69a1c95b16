"""Valid calls of cagd_ref.ffd for the contract test: the course's box (0, 0)-(3, 2) and a bent 3 x 3 lattice."""

from . import Call

BOX = [[0.0, 0.0], [3.0, 2.0]]
# The identity lattice of BOX for m = n = 2 with its centre moved to (2.5, 2), as in the course's example A.
LATTICE = [
    [[0.0, 0.0], [0.0, 1.0], [0.0, 2.0]],
    [[1.5, 0.0], [2.5, 2.0], [1.5, 2.0]],
    [[3.0, 0.0], [3.0, 1.0], [3.0, 2.0]],
]
WEIGHTS = [[1.0, 1.0, 1.0], [1.0, 2.0, 1.0], [1.0, 1.0, 0.5]]
POINTS = [[0.75, 0.5], [1.5, 1.0], [3.4, 1.0]]

CALLS = {
    "ffd_parameters": Call(([[3.4, 0.1], [0.0, 5.0]], [[1.0, -2.0], [5.0, 1.0]])),
    "identity_lattice": Call((BOX, 3, 2)),
    "ffd": [Call((POINTS, LATTICE, BOX)), Call((POINTS, LATTICE, BOX), dict(weights=WEIGHTS))],
    "isoline_image": [Call((LATTICE, 0.6), parameter="value"),
                      Call((LATTICE, 0.3, "t", WEIGHTS), parameter="value")],
    "freeze": [Call((LATTICE, BOX, "bottom", 1)), Call((LATTICE, BOX, "right", 0, WEIGHTS))],
    "edge_continuity": [Call((LATTICE, BOX, "top")), Call((LATTICE, BOX, "left", WEIGHTS), dict(tol=1e-9))],
    "ffd_curve": [Call(([[0.0, 1.0], [1.0, 2.0], [3.0, 1.0]], LATTICE, BOX)),
                  Call(([[0.0, 1.0], [1.0, 2.0], [3.0, 1.0]], LATTICE, BOX, WEIGHTS, [1.0, 2.0, 1.0]))],
}
