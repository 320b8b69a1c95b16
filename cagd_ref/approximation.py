"""Approximation: best constants, least-squares B-spline fitting, parametrization, fairing. Chapter 11 of the notes.

Samples are points Q_k, an (M, d) array (`points`), each with a parameter τ_k
(`params`, (M,)); the approximating curve P(t) = Σ_j P_j N_j(t) is a degree-n
B-spline with control points P_j, (c, d), and knots in the notes' convention
(c + n - 1 knots, domain [t_(n-1), t_(c-1)]; see `cagd_ref.bspline`). Every
parameter must lie in the domain. The fit minimises the sum of squared distances

    Lsq(P_0, ..., P_(c-1)) = Σ_k ‖Q_k - Σ_j P_j N_j(τ_k)‖²          (11.1)

whose stationary points solve the normal equations NᵀN P = NᵀQ with the
collocation matrix N[k, j] = N_j(τ_k) (M_fit = NᵀN, (11.3)); they have one
solution exactly when the parameters satisfy the Schoenberg-Whitney condition
(`schoenberg_whitney`). Fairing adds a weight λ (the argument `weight`) times the
bending energy ∫‖P''(t)‖² dt over the domain, which is Σ_ij M_fair[i, j] P_i·P_j
(11.6, 11.7). Only n + 1 basis functions are nonzero at a parameter, so M_fit and
M_fair are banded: the fast solvers assemble and factor the band (O(M n² + c n²));
`normal_equations` and `fairing_matrix_plain` build the same matrices densely, the
plain forms the chapter shows. Parameter correction (`project_parameters`,
`parameter_correction`) moves each τ_k to the foot point of Q_k on the fit and
refits. Fairing within boxes around the samples is a small quadratic programme,
which `box_programme` solves by an interior-point method; the module needs NumPy only.
"""

from __future__ import annotations

import math

import numpy as np

from ._validation import as_count, as_float_array, as_parameter, as_points, as_scalar
from .bspline import (
    _in_domain,
    _nonzero_spans,
    _spans,
    basis_matrix,
    checked_bspline,
    checked_knots,
    de_boor,
    derivative,
    domain,
    greville,
)
from .polynomials import BLOCK

__all__ = [
    "best_constant",
    "uniform_parameters",
    "chord_length_parameters",
    "centripetal_parameters",
    "fitting_knots",
    "fit_inputs",
    "checked_params",
    "schoenberg_whitney",
    "normal_equations",
    "least_squares_fit",
    "fit_error",
    "project_parameters",
    "parameter_correction",
    "fairing_matrix",
    "fairing_matrix_plain",
    "fairing_energy",
    "faired_fit",
    "constrained_fit",
    "fit_within_tolerance",
    "estimate_frames",
    "box_faired_fit",
    "box_programme",
    "spline_curvature",
]

# A Cholesky pivot below this fraction of its diagonal entry means the system has lost rank.
SINGULAR = 1e-13
# fit_within_tolerance searches weights within this factor either side of the balanced weight.
WEIGHT_RANGE = 1e10


# --- 11.1, 11.2: the best constant ------------------------------------------------------------


def best_constant(values, norm: str = "l2") -> tuple[float, float]:
    """The best approximation of numbers by one constant A, and its error: (A, e(A)). Notes §11.1, §11.2.

    values: (m,), m >= 1. norm "l2": e(A) = Σ (A - g)², minimised by the mean;
    "linf": e(A) = max |A - g|, minimised by the midrange (max + min) / 2.

    >>> best_constant([2, 3, 3, 5, 7])
    (4.0, 16.0)
    >>> best_constant([2, 3, 3, 5, 7], norm="linf")
    (4.5, 2.5)
    """
    g = as_float_array(values, "values")
    if g.ndim != 1 or len(g) == 0:
        raise ValueError(f"values: expected a 1-D array of at least one number, got shape {g.shape}")
    if norm == "l2":
        best = float(np.mean(g))
        return best, float(np.sum((g - best) ** 2))
    if norm == "linf":
        low, high = float(g.min()), float(g.max())
        return (low + high) / 2, (high - low) / 2
    raise ValueError(f"norm: expected 'l2' or 'linf', got {norm!r}")


# --- 11.3.1: parametrization ------------------------------------------------------------------


def _samples(points, name: str = "points", min_count: int = 2) -> np.ndarray:
    pts = as_points(points, name)
    if len(pts) < min_count:
        raise ValueError(f"{name}: expected at least {min_count} sample points, got {len(pts)}")
    return pts


def _cumulative_parameters(pts: np.ndarray, exponent: float) -> np.ndarray:
    """τ_0 = 0, τ_j = Σ_(i<=j) ‖Q_i - Q_(i-1)‖^exponent, divided by the total; the last is exactly 1."""
    steps = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    total_length = steps.sum()
    if total_length == 0:
        raise ValueError("points: every sample is the same point, so the polygon has no length to measure")
    # A repeated sample contributes a zero step whatever the exponent (0**0 would count it as 1).
    steps = np.where(steps > 0, steps**exponent, 0.0)
    sums = np.concatenate([[0.0], np.cumsum(steps)])
    return sums / sums[-1]


def uniform_parameters(points) -> np.ndarray:
    """Evenly spaced parameters τ_j = j / (M - 1) for M samples (M >= 2): (M,). Notes §11.3.1, (11.4)."""
    pts = _samples(points)
    return np.linspace(0.0, 1.0, len(pts))


def chord_length_parameters(points) -> np.ndarray:
    """Normalised chord-length parameters: τ_j = length of the polygon Q_0..Q_j / its whole length. Notes §11.3.1.

    points: (M, d), M >= 2 -> (M,) from 0 to 1. The notes call it "arc length";
    it is the arc length of the polygon through the samples. Repeated
    neighbours get equal parameters; if all samples coincide there is no
    length and a ValueError says so.

    >>> chord_length_parameters([[0, 0], [3, 4], [3, 10]]).tolist() == [0.0, 5 / 11, 1.0]
    True
    """
    return _cumulative_parameters(_samples(points), 1.0)


def centripetal_parameters(points, exponent: float = 0.5) -> np.ndarray:
    """Parameters from chord lengths raised to `exponent` (0.5: centripetal, 1: chord length). Not in the notes.

    points: (M, d), M >= 2; exponent in [0, 1] (0 spaces distinct samples evenly) -> (M,) from 0 to 1.
    Ref: E. T. Y. Lee, Choosing nodes in parametric curve interpolation, CAD 21(6), 1989.
    """
    pts = _samples(points)
    power = as_scalar(exponent, "exponent")
    if not 0 <= power <= 1:
        raise ValueError(f"exponent: expected a number in [0, 1], got {power}")
    return _cumulative_parameters(pts, power)


# --- 11.3.2: the knot vector (the notes' section is lost) ---------------------------------------


def fitting_knots(params, count: int, degree: int, method: str = "uniform") -> np.ndarray:
    """Knots for fitting `count` control points to samples at `params`: (count + n - 1,). Notes §11.3.2 (reconstructed).

    n-fold end knots at min(params) and max(params), so the curve starts and
    ends near the first and last samples, and count - n - 1 interior knots:
    "uniform" spaces them evenly; "averaging" places them among the sorted
    parameters (Piegl and Tiller's (9.68)-(9.69)) so that every knot span holds
    a parameter and the knots follow the data; it needs count <= len(params).
    Ref: L. Piegl and W. Tiller, The NURBS Book, 2nd ed., Springer, 1997, §9.4.1.
    """
    s = np.sort(_parameters(params, "params"))
    n = as_count(degree, "degree", minimum=1)
    c = as_count(count, "count", minimum=n + 1)
    if not s[0] < s[-1]:
        raise ValueError(f"params: expected at least two different parameters, got {s.tolist()[:5]}")
    if method == "uniform":
        inner = np.linspace(s[0], s[-1], c - n + 1)[1:-1]
    elif method == "averaging":
        if c > len(s):
            raise ValueError(f"count: averaging needs at most one control point per sample ({len(s)}), got {c}")
        spacing = len(s) / (c - n)
        j = np.arange(1, c - n)
        i = np.floor(j * spacing).astype(int)
        alpha = j * spacing - i
        inner = (1 - alpha) * s[i - 1] + alpha * s[i]
    else:
        raise ValueError(f"method: expected 'uniform' or 'averaging', got {method!r}")
    knots = np.concatenate([np.full(n, s[0]), inner, np.full(n, s[-1])])
    checked_knots(knots, n)  # many equal parameters could pile up more than n equal knots
    return knots


def checked_params(params, knots, degree: int) -> np.ndarray:
    """Parameters checked to be a 1-D array of numbers in the domain [t_(n-1), t_(c-1)] of the knots: (M,). Notes §11.3.

    A ValueError names `params` (or `knots`, `degree`) and says what is wrong.
    """
    knot_vector, n = checked_knots(knots, degree)
    taus = _parameters(params, "params")
    _in_domain(taus, knot_vector, n, "params")
    return taus


def schoenberg_whitney(params, knots, degree: int) -> np.ndarray:
    """The parameter each basis function gets in the Schoenberg-Whitney test: (c,), NaN from the first failure on.

    The collocation matrix N[k, j] = N_j(τ_k) has full rank c (so the normal
    equations have one solution) exactly when some parameters
    τ_(k_0) < τ_(k_1) < ... < τ_(k_(c-1)) satisfy N_j(τ_(k_j)) != 0 for every j
    (Schoenberg and Whitney 1953; de Boor, A Practical Guide to Splines, ch. XIII).
    The greedy choice finds such parameters whenever they exist: N_0, N_1, ... in
    turn take the smallest distinct parameter beyond the previous choice where they
    are nonzero. Returns the choice; entries from the first basis function that
    finds none are NaN, so the condition holds iff no entry is NaN. Notes §11.3.2.

    A quadratic with knots [0, 0, 0.5, 1, 1] (c = 4): N_3 lives on (0.5, 1], where
    the first four parameters leave it nothing; the fifth serves it.

    >>> schoenberg_whitney([0.1, 0.2, 0.3, 0.4], [0, 0, 0.5, 1, 1], 2).tolist()
    [0.1, 0.2, 0.3, nan]
    >>> schoenberg_whitney([0.1, 0.2, 0.3, 0.4, 0.9], [0, 0, 0.5, 1, 1], 2).tolist()
    [0.1, 0.2, 0.3, 0.9]
    """
    values = np.unique(checked_params(params, knots, degree))  # sorted, each value once
    nonzero = basis_matrix(knots, degree, values) != 0  # nonzero[k, j]: N_j(values[k]) != 0
    chosen = np.full(nonzero.shape[1], np.nan)
    k = 0  # the first value not yet passed
    for j in range(len(chosen)):
        while k < len(values) and not nonzero[k, j]:
            k += 1
        if k == len(values):
            break  # N_j finds no value of its own: the condition fails
        chosen[j] = values[k]
        k += 1
    return chosen


# --- input checking and the banded kernels ------------------------------------------------------


def _parameters(params, name: str) -> np.ndarray:
    u = as_float_array(params, name)
    if u.ndim != 1 or len(u) == 0:
        raise ValueError(f"{name}: expected a 1-D array of parameters, got shape {u.shape}")
    return u


def fit_inputs(points, params, knots, degree) -> tuple[np.ndarray, np.ndarray, np.ndarray, int]:
    """The checked inputs of a fitting problem: (samples (M, d), params (M,), knots, degree n). Notes §11.3.

    points (M, d); params (M,), one per sample, each in the domain
    [t_(n-1), t_(c-1)] of the knots (notes' convention); a ValueError names the
    argument that is wrong.
    """
    pts = as_points(points)
    u = _parameters(params, "params")
    if len(u) != len(pts):
        raise ValueError(f"params: expected one parameter per sample ({len(pts)}), got {len(u)}")
    kn, n = checked_knots(knots, degree)
    return pts, checked_params(u, kn, n), kn, n


def _fit_inputs(points, params, knots, degree):
    """`fit_inputs` and the number of control points c."""
    pts, u, kn, n = fit_inputs(points, params, knots, degree)
    return pts, u, kn, n, len(kn) - n + 1


def _local_basis(kn: np.ndarray, n: int, ts: np.ndarray, spans: np.ndarray, order: int = 0) -> np.ndarray:
    """The order-th derivatives of the n+1 basis functions N_(j-n+1) .. N_(j+1) that live on each t's span j: (n+1, k).

    The triangle of the Cox-de Boor recurrence on the span's knots, one column
    of parameters at a time: degree p comes from degree p-1 by
    N_a^p = (t - u_a) / (u_(a+p) - u_a) N_a^(p-1) + (u_(a+p+1) - t) / (u_(a+p+1) - u_(a+1)) N_(a+1)^(p-1),
    and its top `order` steps use the derivative rule
    N_a^p' = p (N_a^(p-1) / (u_(a+p) - u_a) - N_(a+1)^(p-1) / (u_(a+p+1) - u_(a+1))) instead.
    Every denominator spans the span itself, so none is zero.
    """
    values = np.zeros((n + 1, len(ts)))
    if order > n:
        return values
    for start in range(0, len(ts), BLOCK):
        block = slice(start, start + BLOCK)
        t, j = ts[block], spans[block]
        # left[r] = t - t_(j+1-r), right[r] = t_(j+r) - t, r = 1..n (index 0 unused).
        left = [None] + [t - kn[j + 1 - r] for r in range(1, n + 1)]
        right = [None] + [kn[j + r] - t for r in range(1, n + 1)]
        level = [np.ones_like(t)]
        for p in range(1, n + 1):
            slope = p > n - order
            carried, new = 0.0, []
            for a in range(p):
                share = level[a] / (right[a + 1] + left[p - a])
                if slope:
                    new.append(carried - p * share)
                    carried = p * share
                else:
                    new.append(carried + right[a + 1] * share)
                    carried = left[p - a] * share
            new.append(carried)
            level = new
        values[:, block] = level
    return values


def _gram_band(first: np.ndarray, values: np.ndarray, c: int, weights=None) -> np.ndarray:
    """Band (n+1, c) of G = Σ_k w_k b(τ_k) b(τ_k)ᵀ, b = (N_0, ..., N_(c-1)): band[r, i] = G[i, i+r] (0 past the end)."""
    n = len(values) - 1
    band = np.zeros((n + 1, c))
    scaled = values if weights is None else values * weights
    for r in range(n + 1):
        for a in range(n + 1 - r):
            band[r] += np.bincount(first + a, weights=scaled[a] * values[a + r], minlength=c)
    return band


def _project(first: np.ndarray, values: np.ndarray, pts: np.ndarray, c: int) -> np.ndarray:
    """NᵀQ: (c, d), row i = Σ_k N_i(τ_k) Q_k."""
    columns = np.ascontiguousarray(pts.T)
    out = np.zeros((pts.shape[1], c))
    for a in range(len(values)):
        for dim, column in enumerate(columns):
            out[dim] += np.bincount(first + a, weights=values[a] * column, minlength=c)
    return out.T


def _band_to_dense(band: np.ndarray) -> np.ndarray:
    c = band.shape[1]
    dense = np.diag(band[0])
    for r in range(1, len(band)):
        off = np.diag(band[r, : c - r], r)
        dense += off + off.T
    return dense


class _Singular(ValueError):
    """A banded system lost rank at `column` during its Cholesky factorisation."""

    def __init__(self, column: int):
        super().__init__(column)
        self.column = column


def _solve_band(band: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """Solve G X = rhs for symmetric positive definite G in band form (n+1, c) by Cholesky: X (c, d).

    G = L Lᵀ with L lower triangular of bandwidth n; then forward and back
    substitution, each coordinate of the right-hand side in turn. The loops
    run over c rows of n entries each, in plain floats: cheaper than NumPy
    calls on arrays this short. Raises `_Singular` when a pivot vanishes.
    """
    n, c = band.shape[0] - 1, band.shape[1]
    g = band.tolist()
    low = [[0.0] * c for _ in range(n + 1)]  # low[r][j] = L[j+r, j]
    diagonal = low[0]
    for j in range(c):
        s = g[0][j]
        for r in range(1, min(n, j) + 1):
            s -= low[r][j - r] ** 2
        if not s > SINGULAR * g[0][j]:
            raise _Singular(j)
        pivot = math.sqrt(s)
        diagonal[j] = pivot
        for r in range(1, min(n, c - 1 - j) + 1):
            s = g[r][j]
            for m in range(1, min(n - r, j) + 1):
                s -= low[r + m][j - m] * low[m][j - m]
            low[r][j] = s / pivot
    solution = []
    for column in np.asarray(rhs, dtype=float).T.tolist():
        x = column
        for i in range(c):
            s = x[i]
            for r in range(1, min(n, i) + 1):
                s -= low[r][i - r] * x[i - r]
            x[i] = s / diagonal[i]
        for i in range(c - 1, -1, -1):
            s = x[i]
            for r in range(1, min(n, c - 1 - i) + 1):
                s -= low[r][i] * x[i + r]
            x[i] = s / diagonal[i]
        solution.append(x)
    return np.array(solution).T


def _singular_message(u: np.ndarray, kn: np.ndarray, n: int, name: str = "params") -> str:
    """Why the normal equations are singular: the basis function the Schoenberg-Whitney test cannot serve."""
    chosen = schoenberg_whitney(u, kn, n)
    if not np.isnan(chosen).any():
        return (f"{name}: the normal equations are numerically singular: the Schoenberg-Whitney condition holds, "
                "but only barely (parameters very close to each other or to the ends of supports)")
    j = int(np.argmax(np.isnan(chosen)))
    c = len(kn) - n + 1
    a, b = kn[max(j - 1, 0)], kn[min(j + n, len(kn) - 1)]
    # N_j is nonzero inside its support (t_(j-1), t_(j+n)); only N_0 and N_(c-1) of clamped ends reach the end itself.
    left = "[" if j == 0 and kn[0] == kn[n - 1] else "("
    right = "]" if j == c - 1 and kn[-1] == kn[c - 1] else ")"
    after = "" if j == 0 else f" beyond the parameter {chosen[j - 1]:g} taken by N_{j - 1}"
    support = f"{left}{a:g}, {b:g}{right}"
    return (f"{name}: the normal equations are singular: the basis function N_{j}, nonzero on {support}, "
            f"finds no parameter of its own{after} (the Schoenberg-Whitney condition fails: no increasing choice of "
            "parameters with N_j(τ_(k_j)) != 0 for every j)")


def _fit_system(pts, u, kn, n, c):
    """Band of M_fit and NᵀQ of a fitting problem."""
    spans = _spans(kn, n, u)
    values = _local_basis(kn, n, u, spans)
    first = spans - n + 1
    return _gram_band(first, values, c), _project(first, values, pts, c)


def _fairing_band(kn: np.ndarray, n: int, order: int = 2) -> np.ndarray:
    """Band (n+1, c) of M_fair[i, j] = ∫ N_i^(order) N_j^(order) over the domain, by Gauss-Legendre per span.

    On each span of positive length the integrand is a polynomial of degree
    2(n - order), which n - order + 1 Gauss points integrate exactly.
    """
    c = len(kn) - n + 1
    spans = _nonzero_spans(kn, n)
    nodes, weights = np.polynomial.legendre.leggauss(n - order + 1)
    half = (kn[spans + 1] - kn[spans]) / 2
    ts = ((kn[spans] + half)[:, None] + half[:, None] * nodes).ravel()
    spans_of = np.repeat(spans, len(nodes))
    values = _local_basis(kn, n, ts, spans_of, order)
    return _gram_band(spans_of - n + 1, values, c, (half[:, None] * weights).ravel())


def _solve_fit(band, rhs, kn, n, u, faired: bool = False, name: str = "params") -> np.ndarray:
    try:
        return _solve_band(band, rhs)
    except _Singular:
        if faired:
            raise ValueError(f"{name}: the faired system is singular: the samples do not pin down the curves of zero "
                             "bending energy (fewer than two distinct parameters, or a knot of multiplicity n that "
                             "lets a straight piece turn unseen)") from None
        raise ValueError(_singular_message(u, kn, n, name)) from None


# --- 11.3: least squares ---------------------------------------------------------------------------


def normal_equations(points, params, knots, degree: int) -> tuple[np.ndarray, np.ndarray]:
    """The normal equations NᵀN P = NᵀQ of the least-squares fit, dense: (M_fit (c, c), NᵀQ (c, d)). Notes §11.3.

    M_fit[i, j] = Σ_k N_i(τ_k) N_j(τ_k) and (NᵀQ)_i = Σ_k N_i(τ_k) Q_k, with the
    collocation matrix N[k, j] = N_j(τ_k) of `bspline.basis_matrix`. The plain
    form of `least_squares_fit`, which assembles only the band.
    """
    samples, taus, knot_vector, n = fit_inputs(points, params, knots, degree)
    collocation = basis_matrix(knot_vector, n, taus)  # N[k, j] = N_j(τ_k), shape (M, c)
    return collocation.T @ collocation, collocation.T @ samples


def least_squares_fit(points, params, knots, degree: int) -> np.ndarray:
    """Control points (c, d) of the degree-n B-spline that minimises Σ_k ‖P(τ_k) - Q_k‖². Notes §11.3, (11.1)-(11.3).

    points: (M, d) samples Q_k; params: (M,) their parameters τ_k in the domain;
    knots: (c + n - 1,) in the notes' convention, so c = len(knots) - degree + 1.
    Solves NᵀN P = NᵀQ (`normal_equations`) in band form by Cholesky. When the
    system is singular (the parameters fail the Schoenberg-Whitney condition,
    `schoenberg_whitney`) a ValueError names the first basis function that finds
    no parameter of its own.

    Five samples of the parabola y = x² fitted by a quadratic Bézier curve over [0, 1]
    (knots [0, 0, 1, 1]) give back its control points exactly:

    >>> x = np.linspace(0, 1, 5)
    >>> least_squares_fit(np.column_stack([x, x**2]), x, [0, 0, 1, 1], 2).round(12).tolist()
    [[0.0, 0.0], [0.5, 0.0], [1.0, 1.0]]
    """
    pts, u, kn, n, c = _fit_inputs(points, params, knots, degree)
    band, rhs = _fit_system(pts, u, kn, n, c)
    return _solve_fit(band, rhs, kn, n, u)


def fit_error(points, params, control_points, knots) -> tuple[float, float]:
    """How well a B-spline fits samples: (Σ_k ‖P(τ_k) - Q_k‖², max_k ‖P(τ_k) - Q_k‖). Notes §11.3, (11.1).

    control_points: (c, d) with knots (c + n - 1,); points (M, d), params (M,) in the domain.
    """
    pts = as_points(points)
    u = _parameters(params, "params")
    ctrl = as_points(control_points, "control_points")
    if len(u) != len(pts):
        raise ValueError(f"params: expected one parameter per sample ({len(pts)}), got {len(u)}")
    if pts.shape[1] != ctrl.shape[1]:
        raise ValueError(f"control_points: expected dimension {pts.shape[1]} like the samples, got {ctrl.shape}")
    kn, n = _spline_knots(ctrl, knots)
    _in_domain(u, kn, n, "params")
    residuals = np.linalg.norm(_evaluate(ctrl, kn, n, u) - pts, axis=1)
    return float(np.sum(residuals**2)), float(residuals.max())


def project_parameters(points, params, control_points, knots, steps: int = 4) -> np.ndarray:
    """Move each τ_k towards the foot point of Q_k on the curve, by Newton's method: new params (M,). Notes §11.3.

    The parameter t closest to Q makes the offset P(t) - Q perpendicular to the
    curve, f(t) = (P(t) - Q)·P'(t) = 0, and f'(t) = P'·P' + (P(t) - Q)·P''.
    Where f' <= 0 (far from the curve, Newton would head for a maximum) the step
    uses ‖P'‖² instead of f', the first-order correction of Hoschek.
    Each of `steps` Newton steps t <- t - f/f' is clamped to the domain and kept
    only where it brings the curve point closer to its sample (else it is halved,
    up to five times, and finally dropped), so no distance grows. points (M, d);
    params (M,) in the domain; control_points (c, d) with knots (c + n - 1,).
    Ref: J. Hoschek, Intrinsic parametrization for approximation, CAGD 5, 1988;
    L. Piegl and W. Tiller, The NURBS Book, 2nd ed., 1997, §6.1 (point inversion).
    """
    samples = as_points(points)
    control, knot_vector, n = checked_bspline(as_points(control_points, "control_points"), knots)
    taus = checked_params(params, knot_vector, n)
    if len(taus) != len(samples):
        raise ValueError(f"params: expected one parameter per sample ({len(samples)}), got {len(taus)}")
    if control.shape[1] != samples.shape[1]:
        raise ValueError(f"control_points: expected dimension {samples.shape[1]} like the samples, got {control.shape}")
    start, end = domain(knot_vector, n)
    for _ in range(as_count(steps, "steps")):
        offset = de_boor(control, knot_vector, taus) - samples  # P(τ_k) - Q_k
        first = derivative(control, knot_vector, taus, 1)
        second = derivative(control, knot_vector, taus, 2)
        f = np.sum(offset * first, axis=1)
        speed = np.sum(first * first, axis=1)
        slope = speed + np.sum(offset * second, axis=1)
        slope = np.where(slope > 0, slope, speed)  # where Newton would climb, Hoschek's first-order step
        step = np.divide(f, slope, out=np.zeros_like(f), where=slope > 0)
        distance = np.linalg.norm(offset, axis=1)
        moved = taus.copy()
        waiting = np.ones(len(taus), dtype=bool)
        for _ in range(6):  # a step that does not bring Q_k closer is halved, at most 5 times
            trial = np.clip(taus - step, start, end)
            closer = waiting & (np.linalg.norm(de_boor(control, knot_vector, trial) - samples, axis=1) < distance)
            moved[closer] = trial[closer]
            waiting &= ~closer
            step = step / 2
        taus = moved
    return taus


def parameter_correction(points, params, knots, degree: int, iterations: int = 10,
                         weight: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Fit, move the parameters to the foot points, refit, `iterations` times: (control, params, lsq). Notes §11.3.

    The fit is `faired_fit` with λ = weight (0: least squares) and the same knots
    throughout; lsq (iterations + 1,) holds Σ_k ‖P(τ_k) - Q_k‖² after each fit.
    The samples with the smallest and the largest parameter keep theirs, so the
    curve keeps starting and ending at the data's ends (a curve end tied to no
    sample could run on past the last one). Neither half step can raise the
    objective (the projection shortens every distance, the refit is the best
    curve for the new parameters), so lsq never grows when λ = 0.
    Ref: J. Hoschek, Intrinsic parametrization for approximation, CAGD 5, 1988.
    """
    rounds = as_count(iterations, "iterations")
    control = faired_fit(points, params, knots, degree, weight)
    taus = _parameters(params, "params")
    ends = [int(np.argmin(taus)), int(np.argmax(taus))]
    history = [fit_error(points, taus, control, knots)[0]]
    for _ in range(rounds):
        moved = project_parameters(points, taus, control, knots)
        moved[ends] = taus[ends]  # the first and last samples keep the ends of the curve
        taus = moved
        control = faired_fit(points, taus, knots, degree, weight)
        history.append(fit_error(points, taus, control, knots)[0])
    return control, taus, np.array(history)


def _spline_knots(ctrl: np.ndarray, knots) -> tuple[np.ndarray, int]:
    """Checked knots and degree len(knots) - len(control_points) + 1 of a B-spline."""
    kn = as_float_array(knots, "knots")
    if kn.ndim != 1 or len(kn) < len(ctrl):
        raise ValueError(f"knots: {len(ctrl)} control points need at least {len(ctrl)} knots (degree >= 1), "
                         f"got shape {kn.shape}")
    return checked_knots(kn, len(kn) - len(ctrl) + 1)


def _evaluate(ctrl: np.ndarray, kn: np.ndarray, n: int, u: np.ndarray) -> np.ndarray:
    """Points (k, d) of the B-spline at parameters already checked to lie in the domain."""
    spans = _spans(kn, n, u)
    values = _local_basis(kn, n, u, spans)
    first = spans - n + 1
    return np.einsum("ak,kad->kd", values, ctrl[first[:, None] + np.arange(n + 1)])


# --- 11.4: fairing -------------------------------------------------------------------------------------


def fairing_matrix(knots, degree: int, order: int = 2) -> np.ndarray:
    """M_fair (c, c): M_fair[i, j] = ∫ N_i''(t) N_j''(t) dt over the domain, so ∫‖P''‖² = Σ M_ij P_i·P_j. Notes §11.4.

    knots: (c + n - 1,) in the notes' convention, degree n >= order. Each
    knot span of positive length inside the domain [t_(n-1), t_(c-1)] is
    integrated by Gauss-Legendre with n - 1 points (exact: the integrand has
    degree 2n - 4); spans of length zero contribute nothing. The matrix is
    symmetric, positive semidefinite, banded (|i - j| <= n), and M 1 = 0,
    M greville = 0: straight lines have no bending energy. `order` = 1 gives
    the first-derivative energy ∫‖P'‖² instead.

    >>> fairing_matrix([0, 0, 1, 1], 2).tolist()
    [[4.0, -8.0, 4.0], [-8.0, 16.0, -8.0], [4.0, -8.0, 4.0]]
    >>> fairing_matrix([0, 0, 0, 0.5, 1, 1, 1], 3).round(9)[0].tolist()
    [96.0, -132.0, 24.0, 12.0, 0.0]
    """
    kn, n, k = _fairing_inputs(knots, degree, order)
    return _band_to_dense(_fairing_band(kn, n, k))


def fairing_matrix_plain(knots, degree: int) -> np.ndarray:
    """M_fair (c, c) in its plain form: Gauss-Legendre span by span on the dense second derivatives. Notes §11.4.

    On a span [a, b] of positive length inside the domain every N_j'' is a
    polynomial of degree n - 2, so N_i'' N_j'' has degree 2n - 4 and n - 1
    Gauss-Legendre points integrate it exactly. The columns of
    derivative(I, knots, t, 2) are the N_j''(t): the curve whose control points
    are the unit vectors. `fairing_matrix` computes the same band directly.
    """
    knot_vector, n = checked_knots(knots, degree)
    if n < 2:
        raise ValueError(f"degree: a degree-{n} B-spline has no second derivative to fair; fairing needs degree >= 2")
    c = len(knot_vector) - n + 1
    nodes, weights = np.polynomial.legendre.leggauss(n - 1)
    matrix = np.zeros((c, c))
    for a, b in zip(knot_vector[n - 1 : c - 1], knot_vector[n:c]):  # the spans of the domain
        if b > a:
            t = (a + b) / 2 + (b - a) / 2 * nodes
            second = derivative(np.eye(c), knot_vector, t, 2)  # second[q, j] = N_j''(t_q)
            matrix += second.T @ (((b - a) / 2 * weights)[:, None] * second)
    return matrix


def _fairing_inputs(knots, degree, order=2):
    kn, n = checked_knots(knots, degree)
    k = as_count(order, "order", minimum=1)
    _check_fairing_degree(n, k)
    return kn, n, k


def _check_fairing_degree(n: int, order: int = 2) -> None:
    if n < order:
        raise ValueError(f"degree: the derivative of order {order} of a degree-{n} B-spline vanishes on every "
                         f"span; fairing needs degree >= {order}")


def fairing_energy(control_points, knots, order: int = 2) -> float:
    """The bending energy ∫‖P''(t)‖² dt of a B-spline over its domain (`order` = 1: ∫‖P'‖²). Notes §11.4."""
    ctrl = as_points(control_points, "control_points")
    kn, n = _spline_knots(ctrl, knots)
    k = as_count(order, "order", minimum=1)
    _check_fairing_degree(n, k)
    band = _fairing_band(kn, n, k)
    product = band[0][:, None] * ctrl
    for r in range(1, len(band)):
        product[:-r] += band[r, :-r, None] * ctrl[r:]
        product[r:] += band[r, :-r, None] * ctrl[:-r]
    return float(np.sum(product * ctrl))


def _weight(weight, name: str = "weight") -> float:
    w = as_scalar(weight, name)
    if w < 0:
        raise ValueError(f"{name}: expected a weight >= 0, got {w}")
    return w


def faired_fit(points, params, knots, degree: int, weight: float) -> np.ndarray:
    """Control points (c, d) minimising Σ_k ‖P(τ_k) - Q_k‖² + λ ∫‖P''(t)‖² dt, λ = weight. Notes §11.4, (11.6)-(11.7).

    Solves (M_fit + λ M_fair) P = NᵀQ. λ = 0 is `least_squares_fit`; as λ
    grows the curve flattens towards the least-squares straight line
    P(t) = a + b t (M_fair vanishes on lines), which is why large weights shrink
    it. With λ > 0 two distinct parameters already make the system nonsingular
    when no interior knot has multiplicity n (then the curves without bending
    energy are the straight lines). The weight's scale depends on the parameter
    range (the energy scales like length⁻³ of it).

    Scalar samples of y = x², faired with the weight 1 by a quadratic over [0, 1]:
    the bend is penalised, so the control points move from (0, 0, 1) towards the best line's.

    >>> x = np.linspace(0, 1, 5)
    >>> faired_fit(x[:, None]**2, x, [0, 0, 1, 1], 2, 1.0).round(6).ravel().tolist()
    [-0.123314, 0.369942, 0.876686]
    """
    pts, u, kn, n, c = _fit_inputs(points, params, knots, degree)
    band, rhs = _fit_system(pts, u, kn, n, c)
    w = _weight(weight)
    return _solve_fit(_faired_band(band, kn, n, w), rhs, kn, n, u, faired=w > 0)


def _faired_band(fit_band: np.ndarray, kn: np.ndarray, n: int, w: float) -> np.ndarray:
    """The band of M_fit + w M_fair (w = 0 leaves degree 1 allowed: there is nothing to fair)."""
    if not w:
        return fit_band
    _check_fairing_degree(n)
    return fit_band + w * _fairing_band(kn, n)


def constrained_fit(points, params, knots, degree: int, weight: float, targets, target_params) -> np.ndarray:
    """The faired fit through the targets R_i at target_params v_i exactly: control points (c, d). Notes §11.4.1.

    Minimises Σ_k ‖P(τ_k) - Q_k‖² + λ ∫‖P''‖² (λ = weight) subject to
    P(v_i) = R_i. Lagrange multipliers μ_i turn it into one linear system (the
    notes' block system, with their A = Cᵀ; their R_j = Q_j is the right-hand side R):

        [ M_fit + λ M_fair   Cᵀ ] [ P ]   [ NᵀQ ]
        [ C                  0  ] [ μ ] = [ R   ],    C[i, j] = N_j(v_i)  (I × c),

    of which only T is returned. targets: (I, d), 1 <= I <= c; target_params:
    (I,) in the domain. A ValueError reports a singular system (repeated
    target parameters, or too few samples and weight 0).

    A cubic Bézier fit of samples of y = x³, forced through (0.5, 0.5):

    >>> x = np.linspace(0, 1, 6)
    >>> pts = np.column_stack([x, x**3])
    >>> ctrl = constrained_fit(pts, x, [0, 0, 0, 1, 1, 1], 3, 0.0, [[0.5, 0.5]], [0.5])
    >>> np.round(ctrl, 6).tolist()
    [[0.0, -0.089109], [0.333333, 0.529703], [0.666667, 0.529703], [1.0, 0.910891]]
    """
    pts, u, kn, n, c = _fit_inputs(points, params, knots, degree)
    w = _weight(weight)
    q = as_points(targets, "targets")
    v = _parameters(target_params, "target_params")
    if len(v) != len(q):
        raise ValueError(f"target_params: expected one parameter per target ({len(q)}), got {len(v)}")
    if q.shape[1] != pts.shape[1]:
        raise ValueError(f"targets: expected points of dimension {pts.shape[1]} like the samples, got {q.shape}")
    if len(q) > c:
        raise ValueError(f"targets: {c} control points can meet at most {c} interpolation conditions, got {len(q)}")
    _in_domain(v, kn, n, "target_params")
    band, rhs = _fit_system(pts, u, kn, n, c)
    gram = _band_to_dense(_faired_band(band, kn, n, w))
    # Scaling the constraint rows like the energy rows (the multipliers absorb the factor) keeps
    # the singular values comparable, so the rank test below means what it says.
    scale = max(float(np.abs(gram).max()), 1.0)
    a = scale * basis_matrix(kn, n, v).T
    kkt = np.block([[gram, a], [a.T, np.zeros((len(v), len(v)))]])
    singular = np.linalg.svd(kkt, compute_uv=False)
    if not singular[-1] > 1e-12 * singular[0]:
        raise ValueError("target_params: the constrained system is singular: repeated target parameters, or "
                         "samples and targets that do not pin every control point down (try a weight > 0)")
    return np.linalg.solve(kkt, np.vstack([rhs, scale * q]))[:c]


def _line_fit(pts: np.ndarray, u: np.ndarray, kn: np.ndarray, n: int) -> np.ndarray:
    """Control points of the least-squares straight line P(t) = a + b t: (c, d), the limit of infinite weight."""
    design = np.column_stack([np.ones_like(u), u])
    (a, b), *_ = np.linalg.lstsq(design, pts, rcond=None)
    # The Greville abscissae reproduce t itself, so a line's control points sit at a + b g_j.
    return a + greville(kn, n)[:, None] * b


def fit_within_tolerance(points, params, knots, degree: int, tol: float) -> tuple[np.ndarray, float]:
    """The fairest B-spline with Σ‖P(τ_k) - Q_k‖² <= `tol`: (control points (c, d), weight). Notes §11.4.2.

    The notes' set L2ε = {f : Lsq(f) <= ε} (ε = tol) is empty below the least-squares
    error (a ValueError). Otherwise its fairest member is the faired fit whose
    weight makes Lsq equal to `tol` (Lsq grows with the weight), found by
    bisection on log(weight); when even the least-squares straight line is
    within `tol`, that line (energy 0) is returned with the weight inf.
    Weights are searched within 10^±10 of trace(M_fit) / trace(M_fair).
    Ref: C. H. Reinsch, Smoothing by spline functions, Numer. Math. 10, 1967.
    """
    pts, u, kn, n, c = _fit_inputs(points, params, knots, degree)
    limit = as_scalar(tol, "tol")
    _check_fairing_degree(n)
    fit_band, rhs = _fit_system(pts, u, kn, n, c)
    fair_band = _fairing_band(kn, n)

    def error(w: float) -> tuple[float, np.ndarray]:
        ctrl = _solve_fit(fit_band + w * fair_band, rhs, kn, n, u, faired=w > 0)
        return float(np.sum((_evaluate(ctrl, kn, n, u) - pts) ** 2)), ctrl

    lowest, best = error(0.0)
    if limit < lowest:
        raise ValueError(f"tol: no B-spline with these knots comes closer than Lsq = {lowest:.6g}, got {limit:.6g}")
    line = _line_fit(pts, u, kn, n)
    if limit >= np.sum((_evaluate(line, kn, n, u) - pts) ** 2):
        return line, math.inf
    balanced = fit_band[0].sum() / fair_band[0].sum()
    low, high = math.log(balanced / WEIGHT_RANGE), math.log(balanced * WEIGHT_RANGE)
    if error(math.exp(low))[0] > limit:
        return best, 0.0
    top_error, top_fit = error(math.exp(high))
    if top_error <= limit:
        return top_fit, math.exp(high)
    for _ in range(60):  # halves a range of 46 in log(weight) to below 1e-16
        middle = (low + high) / 2
        if error(math.exp(middle))[0] <= limit:
            low = middle
        else:
            high = middle
    return error(math.exp(low))[1], math.exp(low)


# --- 11.4.2: fairing within boxes ---------------------------------------------------------------------


def estimate_frames(points, control_points=None, knots=None, params=None) -> tuple[np.ndarray, np.ndarray]:
    """Unit tangents and normals (M, 2) of planar samples: e_k along Q_(k+1) - Q_(k-1), e_k⊥ turned left. Notes §11.4.2.

    As in the notes, Q_(-1) = Q_0 and Q_M = Q_(M-1) at the ends. This "very
    simple" estimate (the notes' words) is poor where neighbouring samples lie
    closer together than their noise. Given a first fit instead (control_points
    (c, 2) with knots (c + n - 1,), and the samples' params (M,)), the tangent
    e_k is the unit tangent P'(τ_k) of that curve.
    """
    pts = _samples(points)
    if pts.shape[1] != 2:
        raise ValueError(f"points: tangent and normal boxes are planar, expected shape (M, 2), got {pts.shape}")
    if control_points is None:
        padded = np.vstack([pts[:1], pts, pts[-1:]])
        chords = padded[2:] - padded[:-2]
        where = "its two neighbours coincide"
    else:
        control, knot_vector, n = checked_bspline(as_points(control_points, "control_points"), knots)
        if control.shape[1] != 2:
            raise ValueError(f"control_points: expected a planar curve (c, 2), got {control.shape}")
        taus = checked_params(params, knot_vector, n)
        if len(taus) != len(pts):
            raise ValueError(f"params: expected one parameter per sample ({len(pts)}), got {len(taus)}")
        chords = derivative(control, knot_vector, taus, 1)
        where = "the curve's tangent vanishes there"
    lengths = np.linalg.norm(chords, axis=1)
    if np.any(lengths == 0):
        raise ValueError(f"points: no tangent at sample {int(np.argmax(lengths == 0))}: {where}")
    tangents = chords / lengths[:, None]
    return tangents, np.column_stack([-tangents[:, 1], tangents[:, 0]])


def _half_widths(half_width, count: int, dim: int) -> np.ndarray:
    h = as_float_array(half_width, "half_width")
    if h.ndim == 0 or h.shape == (count,):
        h = np.broadcast_to(h.reshape(-1, 1) if h.ndim else h, (count, dim))
    if h.shape != (count, dim):
        raise ValueError(f"half_width: expected a number, ({count},) or ({count}, {dim}), got shape {h.shape}")
    if np.any(h <= 0):
        raise ValueError(f"half_width: box sizes must be positive, got a minimum of {h.min()}")
    return np.array(h)


def box_faired_fit(points, params, knots, degree: int, half_width, frame: str = "axes") -> np.ndarray:
    """The fairest B-spline with each P(τ_k) in a box around Q_k: control points (c, d). Notes §11.4.2, (11.9)-(11.11).

    Minimises ∫‖P''‖² subject to |(P(τ_k) - Q_k)·e| <= h for the box axes e:
    frame "axes" uses the coordinate axes (11.10), any dimension d, and
    half_width h is a number, (M,) or (M, d); frame "curve" (planar) uses the
    unit tangent and normal of `estimate_frames` (11.11), the notes' estimate
    from neighbouring samples, and frame "fit" those of the least-squares fit
    with the same parameters and knots (`estimate_frames` given that fit); then
    half_width is a number, (M,) or (M, 2) = (along the tangent, along the normal). The
    quadratic programme (one per coordinate for "axes", one in all 2c unknowns
    for "curve") is solved by `box_programme`; a 10⁻⁶-weighted least-squares
    term makes the answer unique (a line through all boxes would otherwise tie
    with every other such line). A ValueError says when the boxes are too small
    for the spline to reach.
    """
    pts, u, kn, n, c = _fit_inputs(points, params, knots, degree)
    _check_fairing_degree(n)
    collocation = basis_matrix(kn, n, u)
    fair = _band_to_dense(_fairing_band(kn, n))
    gram = collocation.T @ collocation
    tie = 1e-6 * np.trace(fair) / np.trace(gram)
    if frame == "axes":
        h = _half_widths(half_width, len(pts), pts.shape[1])
        # One programme per coordinate: rows, box centres, half sizes and the tie-break's linear term.
        blocks = [(collocation, pts[:, k], h[:, k], tie * collocation.T @ pts[:, k]) for k in range(pts.shape[1])]
    elif frame in ("curve", "fit"):
        if frame == "curve":
            tangents, normals = estimate_frames(pts)
        else:
            first_fit = _solve_fit(*_fit_system(pts, u, kn, n, c), kn, n, u)
            tangents, normals = estimate_frames(pts, first_fit, kn, u)
        h = _half_widths(half_width, len(pts), 2)
        # Rows k and M + k measure the deviation along t_k and n_k; the unknowns are all x's, then all y's.
        rows = np.vstack([np.hstack([collocation * e[:, :1], collocation * e[:, 1:]]) for e in (tangents, normals)])
        centres = np.concatenate([np.sum(pts * tangents, axis=1), np.sum(pts * normals, axis=1)])
        blocks = [(rows, centres, h.T.ravel(), tie * (collocation.T @ pts).T.ravel())]
        fair, gram = np.kron(np.eye(2), fair), np.kron(np.eye(2), gram)
    else:
        raise ValueError(f"frame: expected 'axes', 'curve' or 'fit', got {frame!r}")
    hessian = fair + tie * gram
    solutions = [_box_solution(hessian, *block) for block in blocks]
    return np.column_stack(solutions) if frame == "axes" else solutions[0].reshape(2, c).T


def _box_solution(hessian, rows, centres, sizes, linear) -> np.ndarray:
    """min ½ xᵀHx - linearᵀx subject to |rows x - centres| <= sizes, or a ValueError naming half_width."""
    try:
        return box_programme(hessian, -linear, rows, centres - sizes, centres + sizes)
    except ValueError as err:
        raise ValueError(f"half_width: {err}; use larger boxes or more control points") from None


def box_programme(hessian, linear, rows, lower, upper, tol: float = 1e-10) -> np.ndarray:
    """Solve min ½ xᵀHx + linearᵀx subject to lower <= rows x <= upper: x (k,). Notes §11.4.2.

    hessian: (k, k) symmetric positive semidefinite, and positive definite on the
    null space of rows (m, k); linear: (k,); lower, upper: (m,), lower <= upper.
    A primal-dual interior-point method with Mehrotra's predictor-corrector
    steps: the two-sided constraints become rows x - s = lower, rows x + r = upper
    with slacks s, r >= 0, and every Newton step solves one k × k system. The
    problem is first shifted to the least-squares point of the box centres and
    scaled to unit size, so the tolerance is relative. Raises a ValueError when
    no point satisfies every constraint (the iteration stalls with a residual
    violation).
    Ref: J. Nocedal and S. J. Wright, Numerical Optimization, 2nd ed., Springer, 2006, §16.6 (Algorithm 16.4).
    """
    g = as_float_array(hessian, "hessian")
    q = as_float_array(linear, "linear")
    a = as_float_array(rows, "rows")
    low, high = as_float_array(lower, "lower"), as_float_array(upper, "upper")
    k = len(q)
    if g.shape != (k, k) or a.ndim != 2 or a.shape[1] != k or low.shape != (len(a),) or high.shape != (len(a),):
        raise ValueError(f"rows: expected hessian (k, k), linear (k,), rows (m, k), lower and upper (m,); got "
                         f"{g.shape}, {q.shape}, {a.shape}, {low.shape}, {high.shape}")
    if np.any(low > high):
        raise ValueError(f"lower: expected lower <= upper, got lower - upper up to {np.max(low - high):.3g}")
    # Shift to the point that meets the box centres best, and scale lengths and the objective to about 1.
    centre = (low + high) / 2
    start = np.linalg.lstsq(a, centre, rcond=None)[0]
    length = max(float(np.max(high - low)) / 2, float(np.max(np.abs(a @ start - centre))), 1e-300)
    size = max(float(np.trace(g)) / k, 1e-300)
    g_s = g / size
    q_s = (g @ start + q) / (size * length)
    low_s, high_s = (low - a @ start) / length, (high - a @ start) / length
    z, converged = _interior_point(g_s, q_s, a, low_s, high_s, tol)
    x = start + length * z
    violation = float(max(np.max(low - a @ x), np.max(a @ x - high)))
    if not violation <= 1e-6 * length:
        raise ValueError("no point meets every constraint"
                         + (f" (the last iterate misses one by {violation:.3g})" if np.isfinite(violation) else ""))
    if not converged:
        raise ValueError("the interior-point iteration did not converge")
    return x


def _interior_point(g, q, a, low, high, tol: float, iterations: int = 200) -> tuple[np.ndarray, bool]:
    """The Mehrotra iteration of `box_programme` on the scaled problem: constraints [a; -a] x >= [low; -high].

    Returns the last iterate and whether it converged. Without a feasible
    point the multipliers grow without bound; the iteration stops there.
    """
    big_a = np.vstack([a, -a])
    b = np.concatenate([low, -high])
    m = len(b)
    x = np.zeros(len(q))
    y = np.maximum(big_a @ x - b, 1.0)  # slacks
    lam = np.ones(m)
    for _ in range(iterations):
        r_dual = g @ x - big_a.T @ lam + q
        r_primal = big_a @ x - y - b
        mu = float(y @ lam) / m
        if mu < tol and np.max(np.abs(r_primal)) < tol and np.max(np.abs(r_dual)) < tol:
            return x, True
        if lam.max() > 1e12:
            break
        system = (g, big_a, x, y, lam, r_dual, r_primal)
        try:
            dx, dy, dlam = _newton_step(system, np.zeros(m))
            step = _step_to_boundary(y, dy, lam, dlam, 1.0)
            sigma = (float((y + step * dy) @ (lam + step * dlam)) / m / mu) ** 3
            dx, dy, dlam = _newton_step(system, sigma * mu - dy * dlam)
        except np.linalg.LinAlgError:
            break
        step = _step_to_boundary(y, dy, lam, dlam, 0.995)
        x, y, lam = x + step * dx, y + step * dy, lam + step * dlam
    return x, False


def _newton_step(system, target) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Newton direction (dx, dy, dλ) for G x - Aᵀλ + q = 0, A x - y = b and y_i λ_i = target_i, reduced to k × k.

    target is σμ for a centring step, σμ - Δy Δλ for Mehrotra's corrector (0 for the affine predictor).
    """
    g, big_a, x, y, lam, r_dual, r_primal = system
    ratio = lam / y
    rhs = -r_dual + big_a.T @ (-lam + target / y - ratio * r_primal)
    dx = np.linalg.solve(g + big_a.T @ (ratio[:, None] * big_a), rhs)
    dy = big_a @ dx + r_primal
    return dx, dy, -lam + target / y - ratio * dy


def _step_to_boundary(y, dy, lam, dlam, fraction: float) -> float:
    """The largest step in [0, 1] that keeps the slacks and multipliers positive, times `fraction`."""
    ratios = np.concatenate([-y[dy < 0] / dy[dy < 0], -lam[dlam < 0] / dlam[dlam < 0]])
    return min(1.0, fraction * float(ratios.min())) if len(ratios) else 1.0


# --- judging fairness ---------------------------------------------------------------------------------


def spline_curvature(control_points, knots, t):
    """Curvature of a B-spline curve at t: signed (left turns positive) in the plane, unsigned in space. Notes §11.4.

    control_points: (c, 2) or (c, 3), knots (c + n - 1,) with n >= 2; t in the
    domain: a number -> float, k numbers -> (k,). A curvature plot is the
    usual way to judge how fair a fitted curve is.
    """
    ctrl = as_points(control_points, "control_points")
    if ctrl.shape[1] not in (2, 3):
        raise ValueError(f"control_points: curvature needs planar or spatial points, got shape {ctrl.shape}")
    ts, scalar = as_parameter(t)
    first, second = derivative(ctrl, knots, ts, 1), derivative(ctrl, knots, ts, 2)
    speed = np.linalg.norm(first, axis=1)
    if np.any(speed == 0):
        raise ValueError(f"t: the curve stops (P'(t) = 0) at t = {ts[speed == 0][0]}, where curvature is undefined")
    if ctrl.shape[1] == 2:
        turning = first[:, 0] * second[:, 1] - first[:, 1] * second[:, 0]
    else:
        turning = np.linalg.norm(np.cross(first, second), axis=1)
    kappa = turning / speed**3
    return float(kappa[0]) if scalar else kappa
