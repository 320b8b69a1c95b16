"""Blending functions, their properties, and the classic cubic forms: chapter 5 of the notes.

A curve P(t) = Σ f_i(t) P_i is fixed by its blending functions f_i. Here a set
of blending functions (a "basis" in the loose sense) is any callable that maps
a 1-D array of k parameters to their values, shape (k, n+1). The module gives
the sets the notes discuss (cubic Bézier, Timmer's parametric cubic, Ball's
cubic, the Overhauser / Catmull-Rom segment and the notes' rational example),
evaluates curves from them and converts the cubic forms to Bézier control
points; `cagd_ref.blending_properties` tests a set for the six properties of
the chapter. It also holds the course's extensions of the notes: Catmull-Rom curves through points
at parameters of one's choice (the non-uniform form of Overhauser's construction), and the
crossing counts that test a set of blending functions for variation diminishing.

Every cubic form is stored once, as a 4x4 table of power coefficients
(row j holds the coefficients of t^j, column i is f_i); evaluation and the
conversion to Bézier form are both derived from that table.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ._validation import as_count, as_float_array, as_parameter, as_points, as_vector
from .bezier import bernstein_matrix
from .polynomials import horner, power_to_bernstein

# `Basis` is a type alias for annotations, not a function: it stays out of __all__, whose names the contract test calls.
__all__ = [
    "POWER_COEFFICIENTS",
    "basis_values",
    "FORMS",
    "bezier_basis",
    "timmer_basis",
    "ball_basis",
    "overhauser_basis",
    "rational_example_basis",
    "blend",
    "overhauser_point",
    "catmull_rom_parameters",
    "catmull_rom_point",
    "sign_changes",
    "crossing_counts",
    "conversion_matrix",
    "to_bezier",
    "from_bezier",
    "timmer_to_bezier",
    "ball_to_bezier",
    "overhauser_to_bezier",
]

Basis = Callable[[np.ndarray], np.ndarray]

# Power coefficients of each cubic form: row j multiplies t**j, column i is the blending function f_i.
POWER_COEFFICIENTS: dict[str, np.ndarray] = {
    # f0 = (1-t)²(1-2t), f1 = 4t(1-t)², f2 = 4t²(1-t), f3 = t²(2t-1)
    "timmer": np.array([[1, 0, 0, 0], [-4, 4, 0, 0], [5, -8, 4, -1], [-2, 4, -4, 2]], dtype=float),
    # f0 = (1-t)², f1 = 2t(1-t)², f2 = 2t²(1-t), f3 = t²
    "ball": np.array([[1, 0, 0, 0], [-2, 2, 0, 0], [1, -4, 2, 1], [0, 2, -2, 0]], dtype=float),
    # f0 = -t(1-t)²/2, f1 = (2 - 5t² + 3t³)/2, f2 = (t + 4t² - 3t³)/2, f3 = -t²(1-t)/2
    "overhauser": 0.5 * np.array([[0, 2, 0, 0], [-1, 0, 1, 0], [2, -5, 4, -1], [-1, 3, -3, 1]], dtype=float),
}

# ---------------------------------------------------------------- blending functions


def _cubic_basis(form: str, t):
    """Values of the four blending functions of a cubic form: (4,) for a number t, (k, 4) for k values."""
    return horner(POWER_COEFFICIENTS[form], t)


def bezier_basis(t, degree: int = 3) -> np.ndarray:
    """The Bernstein polynomials B_0^n..B_n^n at t: (n+1,) for a number, (k, n+1) for k values. Notes §2.1, §5.

    The reference set the other blending functions of the chapter are compared with.
    """
    ts, scalar = as_parameter(t)
    values = bernstein_matrix(as_count(degree, "degree"), ts)
    return values[0] if scalar else values


def timmer_basis(t) -> np.ndarray:
    """Timmer's parametric cubic blending functions at t: (4,) for a number, (k, 4) for k values. Notes §5.1.

    f0 = (1-t)²(1-2t), f1 = 4t(1-t)², f2 = 4t²(1-t), f3 = t²(2t-1). At t = 1/2
    the values are (0, 1/2, 1/2, 0): the curve passes through the midpoint of P1 P2.

    >>> from cagd_ref.blending import timmer_basis
    >>> timmer_basis(0.5).tolist()                     # the notes' midpoint condition
    [0.0, 0.5, 0.5, 0.0]
    >>> timmer_basis([0.0, 1.0]).tolist()              # and the end points, like a Bézier cubic
    [[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]]

    Ref: H. G. Timmer (1980), Alternative representation for parametric cubic curves and surfaces, CAD 12(1).
    """
    return _cubic_basis("timmer", t)


def ball_basis(t) -> np.ndarray:
    """Ball's cubic blending functions at t: (4,) for a number, (k, 4) for k values. Notes §5.2.

    f0 = (1-t)², f1 = 2t(1-t)², f2 = 2t²(1-t), f3 = t²; all four are
    non-negative on [0, 1] and sum to one.

    >>> from cagd_ref.blending import ball_basis
    >>> ball_basis(0.5).tolist()                       # the middle of the curve is the centroid of the points
    [0.25, 0.25, 0.25, 0.25]
    >>> f = ball_basis(0.3)                            # with P1 = P2 the middle terms merge into 2t(1-t)
    >>> round(float(f[1] + f[2]), 12), round(2 * 0.3 * 0.7, 12)
    (0.42, 0.42)

    Ref: A. A. Ball (1974), CONSURF, part 1: introduction to the conic lofting tile, CAD 6(4).
    """
    return _cubic_basis("ball", t)


def overhauser_basis(t) -> np.ndarray:
    """Blending functions of one Overhauser (uniform Catmull-Rom) segment: (4,) or (k, 4). Notes §5.3.

    f0 = -t(1-t)²/2, f1 = (2 - 5t² + 3t³)/2, f2 = (t + 4t² - 3t³)/2,
    f3 = -t²(1-t)/2. The segment runs from P1 (t = 0) to P2 (t = 1) with
    end tangents (P2 - P0)/2 and (P3 - P1)/2.
    """
    return _cubic_basis("overhauser", t)


def rational_example_basis(t) -> np.ndarray:
    """The notes' rational example ((1-t)², 2t(1-t), 2t²) / (1+t²): (3,) or (k, 3). Notes §5, Example.

    The denominator 1 + t² never vanishes, so every real t is allowed.
    """
    ts, scalar = as_parameter(t)
    numerators = np.column_stack([(1 - ts) ** 2, 2 * ts * (1 - ts), 2 * ts**2])
    values = numerators / (1 + ts**2)[:, None]
    return values[0] if scalar else values


FORMS: dict[str, Basis] = {
    "bezier": bezier_basis,
    "timmer": timmer_basis,
    "ball": ball_basis,
    "overhauser": overhauser_basis,
}


def basis_values(basis, ts) -> np.ndarray:
    """Call a blending-function set on the 1-D parameters ts (k,) and check it answers with shape (k, n+1). Notes §5."""
    if not callable(basis):
        raise TypeError(f"basis: expected a function t -> values of shape (k, n+1), got {type(basis).__name__}")
    ts, _ = as_parameter(ts, "ts")
    values = as_float_array(basis(ts), "basis")
    if values.ndim != 2 or values.shape[0] != len(ts) or values.shape[1] == 0:
        raise ValueError(
            f"basis: expected values of shape ({len(ts)}, n+1) for {len(ts)} parameters, got shape {values.shape}"
        )
    return values


def blend(basis: Basis, points, t) -> np.ndarray:
    """The curve Σ f_i(t) P_i of a blending-function set: (d,) for a number t, (k, d) for k values. Notes §5.

    basis: a callable, 1-D array of k parameters -> values (k, n+1), such as
    `timmer_basis`; points: (n+1, d).
    """
    pts = as_points(points)
    ts, scalar = as_parameter(t)
    values = basis_values(basis, ts)
    if values.shape[1] != len(pts):
        raise ValueError(f"points: the basis has {values.shape[1]} functions but {len(pts)} points were given")
    curve = values @ pts
    return curve[0] if scalar else curve


def overhauser_point(points, t) -> np.ndarray:
    """Point(s) of the Overhauser (Catmull-Rom) curve through points[1..c-2]: (d,) or (k, d). Notes §5.3.

    points: (c, d) with c >= 4. One global parameter t in [0, c-3]: segment
    j = 0..c-4 covers [j, j+1], is built from points j..j+3 and runs from
    points[j+1] to points[j+2], so P(j) = points[j+1]. At an integer t the two
    neighbouring segments agree (the curve is C1 there).

    >>> from cagd_ref.blending import overhauser_point
    >>> row = [(0, 0), (1, 2), (2, 0), (3, 2), (4, 0), (5, 2)]
    >>> overhauser_point(row, [0.0, 1.0, 3.0]).tolist()   # through P1, P2 and, at the very end, P4
    [[1.0, 2.0], [2.0, 0.0], [4.0, 0.0]]
    >>> overhauser_point(row, 1.5).tolist()               # (-P1 + 9 P2 + 9 P3 - P4) / 16 at a midpoint
    [2.5, 1.0]

    Ref: E. Catmull and R. Rom (1974), A class of local interpolating splines, in: Computer Aided
    Geometric Design (R. E. Barnhill, R. F. Riesenfeld, eds.), Academic Press.
    """
    pts = as_points(points, min_count=4)
    ts, scalar = as_parameter(t)
    last = len(pts) - 3
    if np.any((ts < 0) | (ts > last)):
        outside = ts[(ts < 0) | (ts > last)][:3].tolist()
        raise ValueError(f"t: expected values in [0, {last}] for {len(pts)} points, got {outside}")
    # t = c-3 belongs to the last segment, not to a segment c-3 that does not exist.
    segment = np.minimum(np.floor(ts), last - 1).astype(int)
    local = overhauser_basis(ts - segment)
    window = pts[segment[:, None] + np.arange(4)]  # (k, 4, d): the four points of each t's segment
    curve = np.einsum("ki,kid->kd", local, window)
    return curve[0] if scalar else curve


# ---------------------------------------------------------------- Catmull-Rom curves with parameters


def catmull_rom_parameters(points, alpha: float = 0.5) -> np.ndarray:
    """Parameters (c,) for a Catmull-Rom curve through points (c, d): t_0 = 0, t_i+1 - t_i = |P_i+1 - P_i|^alpha.

    alpha = 0 gives the uniform parameters 0, 1, 2, ... of the notes' Overhauser curve, alpha = 1/2 the
    centripetal and alpha = 1 the chord-length parameters. Consecutive points must differ when alpha > 0.
    Course extension of Notes §5.3.

    >>> from cagd_ref.blending import catmull_rom_parameters
    >>> catmull_rom_parameters([(0, 0), (4, 0), (4, 1), (4, 10)], alpha=0.5).tolist()
    [0.0, 2.0, 3.0, 6.0]

    Ref: C. Yuksel, S. Schaefer and J. Keyser (2011), Parameterization and applications of Catmull-Rom curves,
    CAD 43(7).
    """
    pts = as_points(points, min_count=2)
    if isinstance(alpha, bool) or not isinstance(alpha, (int, float, np.integer, np.floating)) or not (
        0.0 <= float(alpha) <= 1.0
    ):
        raise ValueError(f"alpha: expected a number in [0, 1], got {alpha!r}")
    chords = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    if alpha > 0 and np.any(chords == 0):
        raise ValueError(f"points: consecutive points coincide (at index {int(np.argmin(chords))}), "
                         "so their parameters would coincide too")
    return np.concatenate([[0.0], np.cumsum(chords ** float(alpha))])


def catmull_rom_point(points, params, t) -> np.ndarray:
    """Point(s) of the Catmull-Rom curve through points[1..c-2] with parameters params: (d,) or (k, d).

    points: (c, d) with c >= 4; params: (c,) strictly increasing, point i sits at params[i]; t: a number
    or a 1-D array in [params[1], params[c-2]]. Segment j (j = 0..c-4) covers [params[j+1], params[j+2]]
    and is Overhauser's construction with these parameters: the parabola Pi_j through points j..j+2 and
    the parabola Pi_j+1 through points j+1..j+3, each at its points' parameters, blended linearly across
    the middle interval,

        C(t) = ((t_j+2 - t) Pi_j(t) + (t - t_j+1) Pi_j+1(t)) / (t_j+2 - t_j+1).

    Each parabola is evaluated by two rounds of linear interpolation (Neville), so the whole segment is
    three rounds, the pyramid of Barry and Goldman. The curve is C1; with params 0, 1, ..., c-1 it is the
    uniform curve of `overhauser_point`, shifted by one in t. Course extension of Notes §5.3.

    >>> from cagd_ref.blending import catmull_rom_point
    >>> row = [(0, 0), (1, 2), (2, 0), (3, 2)]
    >>> catmull_rom_point(row, [-1, 0, 1, 2], 0.5).tolist()          # uniform: overhauser_point(row, 0.5)
    [1.5, 1.0]
    >>> catmull_rom_point(row, [0, 1, 3, 4], [1.0, 3.0]).tolist()    # through points 1 and 2
    [[1.0, 2.0], [2.0, 0.0]]

    Ref: P. J. Barry and R. N. Goldman (1988), A recursive evaluation algorithm for a class of
    Catmull-Rom splines, SIGGRAPH '88, 199-204.
    """
    pts = as_points(points, min_count=4)
    knots = as_float_array(params, "params")
    if knots.shape != (len(pts),):
        raise ValueError(f"params: expected one parameter per point, shape ({len(pts)},), got shape {knots.shape}")
    if np.any(np.diff(knots) <= 0):
        raise ValueError(f"params: expected strictly increasing parameters, got {knots.tolist()}")
    ts, scalar = as_parameter(t)
    low, high = knots[1], knots[-2]
    if np.any((ts < low) | (ts > high)):
        outside = ts[(ts < low) | (ts > high)][:3].tolist()
        raise ValueError(f"t: expected values in [params[1], params[c-2]] = [{low:g}, {high:g}], got {outside}")
    # Segment j has params[j+1] <= t < params[j+2]; the right end params[c-2] belongs to the last segment.
    segment = np.clip(np.searchsorted(knots, ts, side="right") - 2, 0, len(pts) - 4)
    index = segment[:, None] + np.arange(4)
    tk, window = knots[index], pts[index]  # (k, 4) parameters and (k, 4, d) points of each t's segment
    u = ts[:, None]

    def lerp(level, a, b):
        """Interpolate level[:, i] and level[:, i+1] linearly between the parameters tk[:, a] and tk[:, b]."""
        left, right = tk[:, a : a + level.shape[1] - 1], tk[:, b : b + level.shape[1] - 1]
        share = ((u - left) / (right - left))[:, :, None]
        return (1 - share) * level[:, :-1] + share * level[:, 1:]

    lines = lerp(window, 0, 1)  # the chords P_i P_i+1, i = j..j+2, at their own parameters
    parabolas = lerp(lines, 0, 2)  # Pi_j and Pi_j+1 (Neville's second round)
    curve = lerp(parabolas, 1, 2)[:, 0]  # their blend over [t_j+1, t_j+2]
    return curve[0] if scalar else curve


# ---------------------------------------------------------------- testing variation diminishing


def sign_changes(values, tol: float = 1e-12) -> int:
    """How often the sign changes along values (m,), entries with |x| <= tol skipped: S^-(values). Notes §5.

    (1, 0, -1) has one change, (1, 0, 1) none: a zero is passed over, not counted as a sign.
    """
    heights = as_float_array(values, "values")
    if heights.ndim != 1:
        raise ValueError(f"values: expected a 1-D array of numbers, got shape {heights.shape}")
    signs = np.sign(heights[np.abs(heights) > tol])
    return int(np.count_nonzero(signs[1:] != signs[:-1]))


def crossing_counts(values, points, line) -> tuple[int, int]:
    """(p, c): how often a line crosses a control polygon (p) and its sampled curve (c). Notes §5, property 4.

    values: (k, n+1), blending functions at k increasing parameters (row r holds f_0..f_n at the r-th
    parameter); points: planar control points (n+1, 2); line: (a, b, h), the line a x + b y + h = 0 with
    (a, b) != (0, 0). The heights a x + b y + h of the control points and of the k curve points
    values @ points are counted with `sign_changes` (heights with |x| <= 1e-12 count as zero and are
    skipped). Samples can miss crossings but never invent one, so c > p is a true counterexample to
    variation diminishing.

    >>> import numpy as np
    >>> from cagd_ref.blending import crossing_counts, timmer_basis
    >>> flat = [(0, 0), (1.5, 0), (3, 0), (4, 3)]                  # three points on the x-axis
    >>> crossing_counts(timmer_basis(np.linspace(0, 1, 401)), flat, (0, 1, 0.05))   # the line y = -0.05
    (0, 2)
    """
    table = as_float_array(values, "values")
    if table.ndim != 2 or table.shape[1] == 0:
        raise ValueError(f"values: expected blending-function values of shape (k, n+1), got shape {table.shape}")
    pts = as_points(points)
    if pts.shape != (table.shape[1], 2):
        raise ValueError(f"points: expected {table.shape[1]} planar points, shape ({table.shape[1]}, 2), "
                         f"one per column of values, got shape {pts.shape}")
    a, b, h = as_vector(line, "line", dim=3)
    if a == 0 and b == 0:
        raise ValueError(f"line: (a, b) must not both be zero, got {(a, b, h)}")
    normal = np.array([a, b])
    return sign_changes(pts @ normal + h), sign_changes((table @ pts) @ normal + h)


# ---------------------------------------------------------------- conversions to Bézier form


def conversion_matrix(form: str) -> np.ndarray:
    """The (4, 4) matrix M with Bézier control points = M @ the control points of `form`. Notes §5.1-§5.3.

    Column i holds the Bernstein coefficients of the form's f_i: if
    f_i = Σ_j m_ji B_j^3, then Σ_i f_i Q_i = Σ_j B_j^3 (Σ_i m_ji Q_i).
    form: "bezier" (the identity), "timmer", "ball" or "overhauser".
    """
    if not isinstance(form, str) or form not in FORMS:
        raise ValueError(f"form: expected one of {sorted(FORMS)}, got {form!r}")
    if form == "bezier":
        return np.eye(4)
    return power_to_bernstein(POWER_COEFFICIENTS[form])


def _four_points(points, form: str) -> np.ndarray:
    pts = as_points(points)
    if len(pts) != 4:
        raise ValueError(
            f"points: the {form} form of a cubic has exactly 4 control points, expected shape (4, d), got {pts.shape}"
        )
    return pts


def to_bezier(form: str, points) -> np.ndarray:
    """The 4 Bézier control points (4, d) of the cubic of `form` with control points (4, d). Notes §5.1-§5.3.

    form: "bezier", "timmer", "ball" or "overhauser" (one segment). Both
    curves are the same polynomial, so they agree at every t.
    """
    matrix = conversion_matrix(form)
    return matrix @ _four_points(points, form)


def from_bezier(form: str, points) -> np.ndarray:
    """The inverse of `to_bezier`: control points (4, d) of `form` for a Bézier cubic (4, d). Notes §5.1-§5.3."""
    matrix = conversion_matrix(form)
    return np.linalg.solve(matrix, _four_points(points, form))


def timmer_to_bezier(points) -> np.ndarray:
    """Bézier control points (4, d) of Timmer's cubic with control points Q (4, d). Notes §5.1, Example.

    Matching the ends and the end derivatives Q'(0) = 4(Q1 - Q0), Q'(1) = 4(Q3 - Q2)
    gives P0 = Q0, P1 = (4 Q1 - Q0)/3, P2 = (4 Q2 - Q3)/3, P3 = Q3.

    >>> from cagd_ref.blending import timmer_to_bezier
    >>> bezier_points = timmer_to_bezier([(0, 0), (3, 3), (6, 3), (9, 0)])   # a course example
    >>> (bezier_points.round(12) + 0.0).tolist()       # + 0.0 turns a rounded -0.0 into 0.0
    [[0.0, 0.0], [4.0, 4.0], [5.0, 4.0], [9.0, 0.0]]

    Read back, Q1 = (P0 + 3 P1)/4 = (3, 3) and Q2 = (P3 + 3 P2)/4 = (6, 3), as in the notes' example.
    """
    return to_bezier("timmer", points)


def ball_to_bezier(points) -> np.ndarray:
    """Bézier control points (4, d) of Ball's cubic with control points Q (4, d). Notes §5.2.

    P0 = Q0, P1 = (Q0 + 2 Q1)/3, P2 = (2 Q2 + Q3)/3, P3 = Q3: each Bézier point
    is a convex combination of neighbouring Ball points.
    """
    return to_bezier("ball", points)


def overhauser_to_bezier(points) -> np.ndarray:
    """Each segment of an Overhauser curve through points (c, d) as a Bézier cubic: (c-3, 4, d). Notes §5.3.

    Segment j has P_j+1, P_j+1 + (P_j+2 - P_j)/6, P_j+2 - (P_j+3 - P_j+1)/6, P_j+2
    and covers the global parameters [j, j+1] of `overhauser_point`.
    """
    pts = as_points(points, min_count=4)
    windows = pts[np.arange(len(pts) - 3)[:, None] + np.arange(4)]  # (c-3, 4, d): each segment's four points
    return np.einsum("ij,sjd->sid", conversion_matrix("overhauser"), windows)
