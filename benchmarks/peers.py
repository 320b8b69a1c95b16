"""The peer libraries, each optional: how to hand them our curves, and what their answers look like.

`cagd_ref` never imports any of these; only the benchmarks do, and a peer
that is not installed simply leaves its column empty. Install them with
`pip install -e '.[bench]'` (or `./course bench`, which does it).

Every adapter here builds the peer's own object once (outside the clock) and
returns a function of the parameters that gives points in our (k, d) layout.
"""

from __future__ import annotations

import copy
import importlib.metadata
import importlib.util
from math import comb

import numpy as np

PEERS = ("bezier", "geomdl", "scipy")


def available(name: str) -> bool:
    return importlib.util.find_spec(name) is not None


def version(name: str) -> str:
    try:
        return importlib.metadata.version(name)
    except importlib.metadata.PackageNotFoundError:
        return "not installed"


# --- Bézier curves ------------------------------------------------------------------------


def bezier_package_evaluator(points: np.ndarray):
    """`bezier.Curve(...).evaluate_multi` (compiled Fortran, a Horner-like scheme); (k, d) out."""
    import bezier

    curve = bezier.Curve(np.asfortranarray(points.T), degree=len(points) - 1, copy=True)
    # evaluate_multi answers (d, k); the transpose is a view and costs nothing.
    return lambda t: curve.evaluate_multi(t).T


def bernstein_matrix_baseline(points: np.ndarray, t: np.ndarray) -> np.ndarray:
    """What a NumPy user writes first: the (k, n+1) matrix of B_i^n(t_j), times the control points."""
    n = len(points) - 1
    i = np.arange(n + 1)
    binomials = np.array([comb(n, j) for j in i], dtype=float)
    basis = binomials * t[:, None] ** i * (1 - t[:, None]) ** (n - i)
    return basis @ points


# --- B-splines ----------------------------------------------------------------------------


def scipy_bspline(points: np.ndarray, full_knots: np.ndarray, degree: int):
    """A `scipy.interpolate.BSpline` on the usual c + n + 1 knots (coefficients (c, d))."""
    from scipy.interpolate import BSpline

    return BSpline(full_knots, points, degree)


def geomdl_curve(points: np.ndarray, full_knots: np.ndarray, degree: int):
    """A geomdl `BSpline.Curve`; geomdl wants Python lists and a knot vector on [0, 1]."""
    from geomdl import BSpline

    curve = BSpline.Curve()
    curve.degree = degree
    curve.ctrlpts = points.tolist()
    curve.knotvector = full_knots.tolist()
    return curve


def geomdl_evaluator(curve):
    """geomdl's evaluation at a list of parameters, as a (k, d) array."""
    return lambda t: np.array(curve.evaluate_list(t.tolist()))


def geomdl_bezier_evaluator(points: np.ndarray):
    """geomdl has no separate Bézier class: a Bézier curve is its B-spline with (n+1)-fold end knots."""
    n = len(points) - 1
    return geomdl_evaluator(geomdl_curve(points, np.repeat([0.0, 1.0], n + 1), n))


# --- knot insertion and Bézier extraction -------------------------------------------------


def scipy_insert(spline, u: float) -> np.ndarray:
    """Control points after inserting u once (`BSpline.insert_knot`, FITPACK's routine)."""
    return spline.insert_knot(u).c


def scipy_bezier_segments(spline) -> np.ndarray:
    """Bézier pieces from SciPy, which has no extraction routine: raise every interior knot to
    multiplicity n with `insert_knot(x, m)`; then piece j owns control points jn ... jn + n."""
    n = spline.k
    interior = spline.t[n + 1 : -n - 1]
    values, counts = np.unique(interior, return_counts=True)
    for value, count in zip(values, counts):
        if count < n:
            spline = spline.insert_knot(value, m=n - count)
    pieces = len(values) + 1
    return np.array([spline.c[j * n : j * n + n + 1] for j in range(pieces)])


def geomdl_insert(curve, u: float) -> np.ndarray:
    """geomdl's `operations.insert_knot` changes the curve it is given, so it gets a copy (made off the clock)."""
    from geomdl import operations

    operations.insert_knot(curve, [u], [1])
    return np.array(curve.ctrlpts)


def geomdl_bezier_segments(curve) -> np.ndarray:
    """geomdl's `operations.decompose_curve`: a list of Bézier curves (it copies the input itself)."""
    from geomdl import operations

    return np.array([piece.ctrlpts for piece in operations.decompose_curve(curve)])


def fresh_copy(curve):
    return copy.deepcopy(curve)
