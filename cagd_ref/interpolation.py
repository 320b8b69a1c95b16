"""Polynomial interpolation: chapter 10 of the notes.

The degree-n polynomial through n+1 data values at distinct nodes t_0..t_n is
unique; this module finds it in every form the notes teach: coefficients by
solving linear systems (power and Bernstein bases, and conditions on
derivatives), Lagrange's basis, Newton's divided differences (and the
row-by-row extension of their table), Neville's triangle of two-point
interpolations, the cubic Hermite curve and its Bézier points. Beyond the
notes: the barycentric formula, confluent divided differences (repeated
nodes carry derivatives), and the Lebesgue function. It also bounds the
interpolation error: Cauchy's remainder, Chebyshev nodes, and how many chords
flatten a Bézier curve to within a tolerance.

The graded functions are tuned for many parameters; `lagrange_eval_plain`,
`newton_eval_plain` and `neville_plain` are the plain textbook forms the
chapter shows, and the tests prove that they agree.

Nodes `ts` are a 1-D array (n+1,). Data are `points` (n+1, d) or scalar
values (n+1,), as coefficient arrays are in `cagd_ref.polynomials`. A
parameter t is a number (one point (d,), or a float for scalar values) or a
1-D array of k values ((k, d) or (k,)). Everything evaluates at all k
parameters at once.
"""

from __future__ import annotations

from collections import deque
from math import factorial

import numpy as np
from numpy.typing import ArrayLike

from ._validation import (
    as_coefficients,
    as_count,
    as_float_array,
    as_interval,
    as_parameter,
    as_points,
    as_scalar,
    as_tolerance,
    as_vector,
)
from .bezier import bernstein_matrix, de_casteljau
from .polynomials import _finish

__all__ = [
    "checked_nodes",
    "checked_data",
    "checked_hermite_data",
    "power_interpolation",
    "bernstein_interpolation",
    "undetermined_coefficients",
    "lagrange_basis",
    "lagrange_eval",
    "lagrange_eval_plain",
    "barycentric_weights",
    "barycentric_eval",
    "lebesgue_function",
    "divided_differences",
    "divided_difference_table",
    "next_table_row",
    "newton_eval",
    "newton_eval_plain",
    "confluent_divided_differences",
    "newton_to_power",
    "neville",
    "neville_plain",
    "neville_triangle",
    "node_polynomial",
    "node_polynomial_max",
    "chebyshev_nodes",
    "interpolation_error_bound",
    "linear_segments_needed",
    "second_derivative_bounds",
    "bezier_segments_needed",
    "flatten",
    "chord_gaps",
    "chord_deviation",
    "hermite_basis",
    "hermite_eval",
    "hermite_to_bezier",
]

# Above this condition number a system of interpolation conditions is treated as singular:
# its solution would carry fewer than four correct digits.
SINGULAR_CONDITION = 1e12
# Numbers in one working array of a block of parameters (1 MB of doubles): small enough to stay in the
# processor's cache through all n steps, large enough that NumPy's per-call overhead does not matter.
CACHE_NUMBERS = 2**17


def _blocks(count: int, width: int):
    """Slices of `count` parameters, each so long that a (width, length) working array fits CACHE_NUMBERS."""
    length = max(256, CACHE_NUMBERS // max(width, 1))
    return (slice(start, start + length) for start in range(0, count, length))


# --- input checking ---------------------------------------------------------------------


def checked_nodes(ts: ArrayLike, distinct: bool = True, name: str = "ts", minimum: int = 1) -> np.ndarray:
    """Nodes as a fresh 1-D float array of at least `minimum` values, distinct unless told otherwise. Notes §10.1.

    A clear ValueError names the argument for the wrong shape, too few nodes, NaN
    or infinity, and (with `distinct`) for a node that appears twice.
    """
    nodes = as_float_array(ts, name)
    if nodes.ndim != 1 or len(nodes) < minimum:
        raise ValueError(f"{name}: expected a 1-D array of at least {minimum} node(s), got shape {nodes.shape}")
    if distinct:
        ordered = np.sort(nodes)
        repeated = ordered[1:][np.diff(ordered) == 0]
        if len(repeated):
            raise ValueError(f"{name}: the nodes must be distinct, but {repeated[0]:g} appears more than once")
    return nodes


def _data(values, count: int, name: str) -> np.ndarray:
    """Data (count,) or (count, d), one entry per node."""
    data = as_coefficients(values, name)
    if len(data) != count:
        raise ValueError(f"{name}: expected one entry per node ({count}), got {len(data)}")
    return data


def checked_data(ts: ArrayLike, points: ArrayLike, name: str = "points") -> tuple[np.ndarray, np.ndarray]:
    """Interpolation data, checked: distinct nodes (n+1,) and data (n+1, d) or (n+1,), one entry per node. Notes §10.1.

    Fresh float copies; `name` is the data's argument name in error messages.
    """
    nodes = checked_nodes(ts)
    return nodes, _data(points, len(nodes), name)


# --- undetermined coefficients (§10.1, §10.7) ------------------------------------------------


def _derivative_rows(ts: np.ndarray, orders: np.ndarray, size: int) -> np.ndarray:
    """Row i holds the orders[i]-th derivative of 1, t, ..., t^(size-1) at ts[i]: shape (len(ts), size)."""
    j = np.arange(size)
    k = orders[:, None]
    # d^k/dt^k t^j = j!/(j-k)! t^(j-k) for j >= k, and 0 below.
    falling = np.array([[factorial(a) // factorial(a - b) if a >= b else 0 for a in j] for b in orders], dtype=float)
    powers = np.where(j >= k, ts[:, None] ** np.maximum(j - k, 0), 0.0)
    return falling * powers


def power_interpolation(ts: ArrayLike, points: ArrayLike) -> np.ndarray:
    """Ascending power coefficients of the degree-n curve through points (n+1, d) at nodes ts (n+1,). Notes §10.1.

    Solves the Vandermonde system Σ_j a_j t_i^j = P_i for all coordinates at
    once. Returns (n+1, d), or (n+1,) for scalar values.

    >>> from cagd_ref.interpolation import power_interpolation
    >>> example = power_interpolation([0, 0.25, 0.75, 1], [(0, 0), (2, 2), (0, 3), (2, 4)])
    >>> (example * 3).round(9).tolist()   # x = 18t - 48t² + 32t³, y = 12t - (56/3)t² + (32/3)t³
    [[0.0, 0.0], [54.0, 36.0], [-144.0, -56.0], [96.0, 32.0]]
    """
    nodes, data = checked_data(ts, points, "points")
    return np.linalg.solve(np.vander(nodes, increasing=True), data)


def bernstein_interpolation(ts: ArrayLike, points: ArrayLike, interval: ArrayLike = (0, 1)) -> np.ndarray:
    """Bézier control points of the degree-n curve through points (n+1, d) at nodes ts on `interval`. Notes §10.1.

    Solves Σ_k B_k^n(u_i) c_k = P_i with u_i = (t_i - t0) / (t1 - t0): the
    same curve as `power_interpolation`, written in the Bernstein basis.
    Returns (n+1, d), or (n+1,) for scalar values.

    >>> from cagd_ref.interpolation import bernstein_interpolation
    >>> (bernstein_interpolation([0, 0.25, 0.75, 1], [(0, 0), (2, 2), (0, 3), (2, 4)]) * 9).round(9).tolist()
    [[0.0, 0.0], [54.0, 36.0], [-36.0, 16.0], [18.0, 36.0]]
    """
    nodes, data = checked_data(ts, points, "points")
    t0, t1 = as_interval(interval)
    return np.linalg.solve(bernstein_matrix(len(nodes) - 1, (nodes - t0) / (t1 - t0)), data)


def undetermined_coefficients(ts: ArrayLike, orders: ArrayLike, values: ArrayLike) -> np.ndarray:
    """Power coefficients of the degree-n polynomial with P^(orders[i])(ts[i]) = values[i], i = 0..n. Notes §10.7.

    ts: (n+1,) parameters, repeats allowed (a value and a slope at one t);
    orders: (n+1,) derivative orders (0 for a point, 1 for a tangent, ...);
    values: (n+1, d) or (n+1,). Raises a ValueError when the conditions do not
    determine one polynomial: points at a and b with slopes at c and d, for
    instance, fail whenever 2a² + 2ab + 2b² - 3(a + b)(c + d) + 6cd = 0
    (Birkhoff interpolation: P(0), P(1), P'(0), P'(2/3) is such a case).
    """
    params = checked_nodes(ts, distinct=False)
    order = np.asarray(orders)
    if order.shape != params.shape or order.dtype.kind not in "iu" or np.any(order < 0):
        raise ValueError(f"orders: expected {len(params)} non-negative integers, one per condition, got {orders!r}")
    data = _data(values, len(params), "values")
    matrix = _derivative_rows(params, order.astype(int), len(params))
    if np.linalg.cond(matrix) > SINGULAR_CONDITION:
        raise ValueError(
            "ts, orders: these conditions do not determine a unique polynomial of degree "
            f"{len(params) - 1} (the linear system is singular)"
        )
    return np.linalg.solve(matrix, data)


# --- Lagrange (§10.2) ---------------------------------------------------------------------


def _lagrange_matrix(nodes: np.ndarray, tau: np.ndarray) -> np.ndarray:
    """All L_i(tau_k) as a (k, n+1) matrix, O(n) per parameter.

    Π_{j≠i} (t - t_j) is the product of the factors left of i and the factors
    right of i, so running products from both ends give every numerator in
    2n multiplications; the denominators Π_{j≠i} (t_i - t_j) depend on the
    nodes only. The basis does not change under an affine change of variable,
    so nodes and parameters are first mapped to [-2, 2] (an interval of length
    4), which keeps the products near 1 in size instead of overflowing or
    underflowing at high degree.
    """
    low, high = nodes.min(), nodes.max()
    scale = 4.0 / (high - low) if high > low else 1.0
    centre = 0.5 * (low + high)
    u, v = (tau - centre) * scale, (nodes - centre) * scale
    factors = v[:, None] - v[None, :]
    np.fill_diagonal(factors, 1.0)
    weights = 1.0 / np.prod(factors, axis=1)
    diff = u[:, None] - v[None, :]
    left = np.ones_like(diff)
    right = np.ones_like(diff)
    np.cumprod(diff[:, :-1], axis=1, out=left[:, 1:])
    np.cumprod(diff[:, :0:-1], axis=1, out=right[:, -2::-1])
    return left * right * weights


def lagrange_basis(ts: ArrayLike, t: ArrayLike) -> np.ndarray:
    """The Lagrange basis L_0^n .. L_n^n of the nodes ts at t: (n+1,) for a number, (k, n+1) for k values. Notes §10.2.

    L_i^n(t) = Π_{j≠i} (t - t_j) / (t_i - t_j): one at t_i, zero at every other
    node. The functions sum to one (so the interpolant is affinely invariant)
    but are not all positive between the nodes (so there is no convex hull
    property).
    """
    nodes = checked_nodes(ts)
    tau, scalar = as_parameter(t)
    basis = _lagrange_matrix(nodes, tau)
    return basis[0] if scalar else basis


def lagrange_eval(ts: ArrayLike, points: ArrayLike, t: ArrayLike):
    """Point(s) of the interpolating polynomial in Lagrange form, P(t) = Σ P_i L_i^n(t). Notes §10.2.

    ts: (n+1,) distinct nodes, in any order; points: (n+1, d), or (n+1,) scalar
    values. t: a number -> (d,) (a float for scalar values); a 1-D array of k
    values -> (k, d) (or (k,)); t may lie outside the nodes' range. The basis
    matrix is built a block of parameters at a time (see `_lagrange_matrix`
    for its O(n) products; `lagrange_eval_plain` is the notes' O(n²) form).

    Ref: J.-P. Berrut and L. N. Trefethen, Barycentric Lagrange interpolation, SIAM Review 46(3), 2004
    (the node weights computed once, and the rescaling to an interval of length 4).

    >>> from cagd_ref.interpolation import lagrange_eval
    >>> ts, points = [0, 0.25, 0.75, 1], [(0, 0), (2, 2), (0, 3), (2, 4)]
    >>> (lagrange_eval(ts, points, 0.5) * 3).round(12).tolist()     # P(1/2) = (1, 8/3)
    [3.0, 8.0]
    >>> lagrange_eval([0, 1, 3, 4], [(0, 0), (3, 3), (5, 3), (7, 0)], [2.0]).round(12).tolist()
    [[4.166666666667, 4.0]]
    """
    nodes, data = checked_data(ts, points, "points")
    tau, scalar = as_parameter(t)
    columns = data.reshape(len(nodes), -1)
    values = np.empty((len(tau), columns.shape[1]))
    for block in _blocks(len(tau), len(nodes)):
        values[block] = _lagrange_matrix(nodes, tau[block]) @ columns
    return _finish(values if data.ndim == 2 else values[:, 0], scalar)


def lagrange_eval_plain(ts: ArrayLike, points: ArrayLike, t: ArrayLike):
    """The same as `lagrange_eval`, in its plain textbook form: n² factors per parameter. Notes §10.2.

    Column i of the (k, n+1) basis matrix multiplies the n factors
    (t - t_j) / (t_i - t_j), j ≠ i, for all k parameters at once; one matrix
    product with the points gives the curve. This is the O(n²) cost that §10.5
    counts; `lagrange_eval` gets the same values in O(n) per parameter.

    >>> from cagd_ref.interpolation import lagrange_eval_plain
    >>> (lagrange_eval_plain([0, 0.25, 0.75, 1], [(0, 0), (2, 2), (0, 3), (2, 4)], 0.5) * 3).round(12).tolist()
    [3.0, 8.0]
    """
    nodes, data = checked_data(ts, points, "points")
    tau, scalar = as_parameter(t)
    basis = np.ones((len(tau), len(nodes)))  # column i: L_i at every parameter
    for i, node in enumerate(nodes):
        for j, other in enumerate(nodes):
            if j != i:
                basis[:, i] *= (tau - other) / (node - other)
    values = basis @ data  # (k, d), or (k,) for scalar values
    if scalar:
        return values[0] if data.ndim == 2 else float(values[0])
    return values


def barycentric_weights(ts: ArrayLike) -> np.ndarray:
    """The weights γ_i = 1 / Π_{j≠i} (t_i - t_j) of barycentric interpolation, up to one common factor. Notes §10.5.

    ts: (n+1,) distinct nodes. A common factor of all weights cancels in the
    barycentric formula, so they are computed for the nodes mapped to an
    interval of length 4 (which multiplies every γ_i by the same power of the
    scale and keeps the products representable for many nodes) and divided by
    the largest |γ_i|. Returns (n+1,).

    Ref: J.-P. Berrut and L. N. Trefethen, Barycentric Lagrange interpolation, SIAM Review 46(3), 2004.

    >>> from cagd_ref.interpolation import barycentric_weights
    >>> barycentric_weights([0, 1, 2]).tolist()      # 1/2, -1, 1/2, scaled
    [0.5, -1.0, 0.5]
    """
    nodes = checked_nodes(ts)
    span = nodes.max() - nodes.min()
    scaled = nodes * (4.0 / span) if span > 0 else nodes
    differences = scaled[:, None] - scaled[None, :]
    np.fill_diagonal(differences, 1.0)
    weights = 1.0 / np.prod(differences, axis=1)
    return weights / np.abs(weights).max()


def barycentric_eval(ts: ArrayLike, points: ArrayLike, t: ArrayLike, weights: ArrayLike | None = None):
    """The interpolant by the barycentric formula (its second form): O(n) per parameter. Notes §10.5.

    P(t) = Σ_i γ_i P_i / (t - t_i)  /  Σ_i γ_i / (t - t_i), and P(t_i) = P_i at a
    node. ts: (n+1,) distinct nodes; points: (n+1, d) or (n+1,); weights: the
    γ_i of `barycentric_weights` (computed when not given; any common factor
    does not matter). Shapes of t and of the result as in `lagrange_eval`.
    Accurate between the smallest and the largest node for nodes with a small
    Lebesgue constant (Higham 2004); far outside it, prefer `lagrange_eval`.

    Ref: J.-P. Berrut and L. N. Trefethen, Barycentric Lagrange interpolation, SIAM Review 46(3), 2004;
    N. J. Higham, The numerical stability of barycentric Lagrange interpolation, IMA J. Numer. Anal. 24, 2004.

    >>> from cagd_ref.interpolation import barycentric_eval
    >>> (barycentric_eval([0, 1, 3, 4], [(0, 0), (3, 3), (5, 3), (7, 0)], 2.0) * 6).round(12).tolist()
    [25.0, 24.0]
    """
    nodes, data = checked_data(ts, points, "points")
    if weights is None:
        gamma = barycentric_weights(nodes)
    else:
        gamma = as_float_array(weights, "weights")
        if gamma.shape != nodes.shape or np.any(gamma == 0):
            raise ValueError(f"weights: expected {len(nodes)} non-zero weights, one per node, got {weights!r}")
    tau, scalar = as_parameter(t)
    differences = tau[:, None] - nodes[None, :]  # (k, n+1): t - t_i
    at_node = differences == 0
    differences[at_node] = 1.0  # those rows are replaced by the data below
    quotients = gamma / differences  # γ_i / (t - t_i)
    values = (quotients @ data) / quotients.sum(axis=1).reshape((-1,) + (1,) * (data.ndim - 1))
    rows, columns = np.nonzero(at_node)
    values[rows] = data[columns]  # at a node the formula is 0/0 in the limit: the datum itself
    if scalar:
        return values[0] if data.ndim == 2 else float(values[0])
    return values


def lebesgue_function(ts: ArrayLike, x: ArrayLike):
    """Λ(x) = Σ_i |L_i^n(x)|, the Lebesgue function of the nodes ts: float or (k,). Notes §10.6 (course).

    Data errors of at most δ change the interpolant at x by at most Λ(x) δ;
    its maximum over an interval is the Lebesgue constant. One at every node.

    Ref: L. N. Trefethen, Approximation Theory and Approximation Practice, SIAM 2013, ch. 15.
    """
    nodes = checked_nodes(ts)
    xs, scalar = as_parameter(x, "x")
    values = np.abs(_lagrange_matrix(nodes, xs)).sum(axis=1)
    return float(values[0]) if scalar else values


# --- Newton (§10.3) ---------------------------------------------------------------------------


def divided_difference_table(ts: ArrayLike, values: ArrayLike) -> list[np.ndarray]:
    """Every column of the divided-difference table: column k holds f[t_i..t_(i+k)] for i = 0..n-k. Notes §10.3.

    Column 0 is a copy of the values (n+1,) or (n+1, d); column k has n+1-k
    entries, each (f[t_(i+1)..t_(i+k)] - f[t_i..t_(i+k-1)]) / (t_(i+k) - t_i).
    The notes print the table by rows: row i holds t_i and the entries
    f[t_(i-k)..t_i], i.e. entry i-k of column k. The first entries of the
    columns are the Newton coefficients (`divided_differences`), the last
    entries the table's bottom row (see `next_table_row`).
    """
    nodes, data = checked_data(ts, values, "values")
    columns = [data]
    for k in range(1, len(nodes)):
        previous = columns[-1]
        step = (nodes[k:] - nodes[:-k]).reshape((-1,) + (1,) * (data.ndim - 1))
        columns.append((previous[1:] - previous[:-1]) / step)
    return columns


def divided_differences(ts: ArrayLike, values: ArrayLike) -> np.ndarray:
    """Newton coefficients f[t_0], f[t_0,t_1], ..., f[t_0..t_n] of the data: the top of the table. Notes §10.3.

    ts: (n+1,) distinct nodes in any order; values: (n+1,) or (n+1, d); the
    result has the shape of `values`. The recursion
    f[t_i..t_k] = (f[t_(i+1)..t_k] - f[t_i..t_(k-1)]) / (t_k - t_i) divides by
    the distance between the first and last node of each range.

    >>> from cagd_ref.interpolation import divided_differences
    >>> coeffs = divided_differences([0, 1, 3, 4], [(0, 0), (3, 3), (5, 3), (7, 0)])
    >>> (coeffs * 12).round(12).tolist()    # (0, 0), (3, 3), (-2/3, -1), (1/4, 0)
    [[0.0, 0.0], [36.0, 36.0], [-8.0, -12.0], [3.0, 0.0]]
    """
    return np.array([column[0] for column in divided_difference_table(ts, values)])


def next_table_row(ts: ArrayLike, row: ArrayLike, tau: float) -> np.ndarray:
    """The row a new node τ adds below a degree-n divided-difference table: (P(τ), ..., f[t_0..t_n]). Notes §10.3.

    ts: the n+1 nodes of the table in its order; row: its bottom row
    (f[t_n], f[t_(n-1),t_n], ..., f[t_0..t_n]), shape (n+1,) or (n+1, d).
    The n-th differences of a degree-n polynomial are constant, so the new
    row ends with f[t_0..t_n] again; each entry to its left follows from the
    entry above it, g_j = f[t_(n-j)..t_n] + (τ - t_(n-j)) g_(j+1), and the
    first is P(τ). The new row is the bottom row of the table with nodes
    t_1, ..., t_n, τ: repeating the step marches along at n multiply-adds a
    point, as forward differencing does, but to any parameters.
    """
    nodes = checked_nodes(ts, distinct=False)
    bottom = _data(row, len(nodes), "row")
    tau = as_scalar(tau, "tau")
    n = len(nodes) - 1
    new = np.empty_like(bottom)
    new[n] = bottom[n]
    for j in range(n - 1, -1, -1):
        new[j] = bottom[j] + (tau - nodes[n - j]) * new[j + 1]
    return new


def newton_eval(ts: ArrayLike, coeffs: ArrayLike, t: ArrayLike):
    """Point(s) of the Newton form Σ c_k (t - t_0)...(t - t_(k-1)), nested: n multiply-adds per parameter. Notes §10.3.

    ts: the nodes t_0..t_n (n+1 values; t_n never enters, so the n values
    t_0..t_(n-1) are accepted too; nodes may repeat); coeffs: (n+1,) or
    (n+1, d), e.g. from `divided_differences`. The nesting
    c_0 + (t - t_0)(c_1 + (t - t_1)(c_2 + ...)) is Horner's scheme with a new
    centre at each level. Shapes of t and of the result as in `lagrange_eval`.

    >>> from cagd_ref.interpolation import divided_differences, newton_eval
    >>> ts = [0, 1, 3, 4]
    >>> coeffs = divided_differences(ts, [(0, 0), (3, 3), (5, 3), (7, 0)])
    >>> (newton_eval(ts, coeffs, 2.0) * 6).round(12).tolist()   # P(2) = (25/6, 4)
    [25.0, 24.0]
    """
    nodes = checked_nodes(ts, distinct=False, minimum=0)
    c = as_coefficients(coeffs)
    if len(nodes) not in (len(c), len(c) - 1):
        raise ValueError(
            f"ts: {len(c)} coefficients need {len(c)} nodes (or {len(c) - 1}: the last is not used), got {len(nodes)}"
        )
    tau, scalar = as_parameter(t)
    columns = c.reshape(len(c), -1)
    # Coordinate-major results, a block of parameters at a time: every pass runs over contiguous numbers
    # that stay in the cache for all n levels (ten times faster than (k, d) rows at a million parameters).
    values = np.empty((columns.shape[1], len(tau)))
    for block in _blocks(len(tau), columns.shape[1]):
        value, u = values[:, block], tau[block]
        value[:] = columns[-1][:, None]
        for k in range(len(c) - 2, -1, -1):
            value *= u - nodes[k]
            value += columns[k][:, None]
    return _finish(values.T if c.ndim == 2 else values[0], scalar)


def newton_eval_plain(ts: ArrayLike, coeffs: ArrayLike, t: ArrayLike):
    """The same as `newton_eval`, in its plain textbook form: the nesting, all parameters at once. Notes §10.3.

    Start with v = c_n; then v = c_k + (t - t_k) v for k = n-1, ..., 0. Nodes,
    coefficients and shapes as in `newton_eval` (t_n is never used; nodes may
    repeat).

    >>> from cagd_ref.interpolation import newton_eval_plain
    >>> (newton_eval_plain([0, 1, 3, 4], [(0, 0), (3, 3), (-2/3, -1), (1/4, 0)], 2.0) * 6).round(12).tolist()
    [25.0, 24.0]
    """
    nodes = checked_nodes(ts, distinct=False, minimum=0)
    c = as_coefficients(coeffs)
    if len(nodes) not in (len(c), len(c) - 1):
        raise ValueError(f"ts: {len(c)} coefficients need {len(c)} or {len(c) - 1} nodes, got {len(nodes)}")
    tau, scalar = as_parameter(t)
    u = tau.reshape((-1,) + (1,) * (c.ndim - 1))  # (k, 1) for points, (k,) for scalar values
    value = np.repeat(c[-1:], len(tau), axis=0)  # v = c_n at every parameter
    for k in range(len(c) - 2, -1, -1):
        value = c[k] + (u - nodes[k]) * value
    if scalar:
        return value[0] if c.ndim == 2 else float(value[0])
    return value


def confluent_divided_differences(ts: ArrayLike, values: ArrayLike) -> np.ndarray:
    """Newton coefficients of Hermite data: a node repeated m times carries a value and m-1 derivatives. Notes §10.7.

    ts: (n+1,) nodes in which equal nodes stand next to each other; values:
    (n+1,) or (n+1, d), where the j-th copy of a node (j = 0, 1, ...) holds the
    j-th derivative there (SciPy's KroghInterpolator takes data the same way).
    The table is that of `divided_difference_table`, except that a range of
    k+1 equal nodes, where the quotient would be 0/0, takes its limit
    f[t_i, ..., t_i] = f^(k)(t_i) / k!. Returns the top diagonal, the shape of
    `values`; `newton_eval` evaluates the result with the same nodes.

    >>> from cagd_ref.interpolation import confluent_divided_differences
    >>> confluent_divided_differences([0, 0, 1, 1], [(0, 0), (3, 9), (4, 0), (3, -9)]).tolist()
    [[0.0, 0.0], [3.0, 9.0], [1.0, -9.0], [-2.0, 0.0]]
    """
    nodes = checked_nodes(ts, distinct=False)
    data = _data(values, len(nodes), "values")
    first = np.arange(len(nodes))  # index of the first copy of each node
    for i in range(1, len(nodes)):
        if nodes[i] == nodes[i - 1]:
            first[i] = first[i - 1]
    if len(np.unique(nodes)) != len(np.unique(first)):
        raise ValueError(f"ts: equal nodes must stand next to each other, got {nodes.tolist()}")
    column = data[first]  # f[t_i] = the value at t_i
    coefficients = [column[0]]
    for k in range(1, len(nodes)):
        span = nodes[k:] - nodes[:-k]
        equal = (span == 0).reshape((-1,) + (1,) * (data.ndim - 1))
        safe = np.where(span == 0, 1.0, span).reshape(equal.shape)
        derivative = data[np.minimum(first[:-k] + k, len(nodes) - 1)] / factorial(k)
        column = np.where(equal, derivative, (column[1:] - column[:-1]) / safe)
        coefficients.append(column[0])
    return np.array(coefficients)


def newton_to_power(ts: ArrayLike, coeffs: ArrayLike) -> np.ndarray:
    """Ascending power coefficients of the Newton form with nodes ts and coefficients (n+1,) or (n+1, d). Notes §10.3.

    The nesting of `newton_eval` carried out on polynomials: start from c_n,
    multiply by (t - t_k) and add c_k, for k = n-1 .. 0.
    """
    nodes = checked_nodes(ts, distinct=False, minimum=0)
    c = as_coefficients(coeffs)
    if len(nodes) not in (len(c), len(c) - 1):
        raise ValueError(f"ts: {len(c)} coefficients need {len(c)} or {len(c) - 1} nodes, got {len(nodes)}")
    power = c[-1:].copy()
    for k in range(len(c) - 2, -1, -1):
        widened = np.zeros((len(power) + 1,) + power.shape[1:])
        widened[1:] += power
        widened[:-1] -= nodes[k] * power
        widened[0] += c[k]
        power = widened
    return power


# --- Neville (§10.4) ----------------------------------------------------------------------------


def _neville_levels(nodes: np.ndarray, columns: np.ndarray, tau: np.ndarray):
    """Yield the levels of Neville's triangle for k parameters at once: level r as a view (d, n+1-r, k).

    Entry i of level r is p_(i..i+r)(τ), the value at τ of the polynomial
    through P_i..P_(i+r). The two-point step of the notes,
    ((t_(i+r) - τ) p_(i..i+r-1) + (τ - t_i) p_(i+1..i+r)) / (t_(i+r) - t_i),
    is carried out as p + α (p' - p) with α = (τ - t_i) / (t_(i+r) - t_i),
    in place: every level is a view of one working array (coordinates first,
    parameters last, so each pass runs over contiguous numbers) that the next
    level overwrites. Copy a level to keep it.
    """
    level = np.repeat(columns.T[:, :, None], len(tau), axis=2)
    yield level
    for r in range(1, len(nodes)):
        count = len(nodes) - r
        first, last = nodes[:count, None], nodes[r:, None]
        step = level[:, 1 : count + 1] - level[:, :count]
        step *= (tau - first) / (last - first)
        level[:, :count] += step
        yield level[:, :count]


def neville(ts: ArrayLike, points: ArrayLike, t: ArrayLike):
    """Point(s) of the interpolant by Neville's scheme: no coefficients, n(n+1)/2 two-point steps. Notes §10.4.

    p_(i..i+r)(τ) = ((t_(i+r) - τ) p_(i..i+r-1)(τ) + (τ - t_i) p_(i+1..i+r)(τ)) / (t_(i+r) - t_i),
    starting from p_i = P_i; the single entry of level n is P(τ). Nodes,
    points and shapes as in `lagrange_eval`; `neville_triangle` returns every level.

    Ref: E. H. Neville, Iterative interpolation, J. Indian Math. Soc. 20, 1934.

    >>> from cagd_ref.interpolation import neville
    >>> (neville([0, 1, 3, 4], [(0, 0), (3, 3), (5, 3), (7, 0)], 2.0) * 6).round(12).tolist()   # (25/6, 4)
    [25.0, 24.0]
    """
    nodes, data = checked_data(ts, points, "points")
    tau, scalar = as_parameter(t)
    columns = data.reshape(len(nodes), -1)
    values = np.empty((len(tau), columns.shape[1]))
    for block in _blocks(len(tau), columns.size):
        # Only the last level matters here; the working array is shared by all of them.
        (last,) = deque(_neville_levels(nodes, columns, tau[block]), maxlen=1)
        values[block] = last[:, 0].T
    return _finish(values if data.ndim == 2 else values[:, 0], scalar)


def neville_plain(ts: ArrayLike, points: ArrayLike, t: ArrayLike):
    """The same as `neville`, in its plain textbook form: a (k, n+1, d) array, one row less per level. Notes §10.4.

    Level r holds p_(i..i+r)(t) for i = 0..n-r, computed from level r-1 by
    ((t_(i+r) - t) p_(i..i+r-1) + (t - t_i) p_(i+1..i+r)) / (t_(i+r) - t_i);
    the single entry of level n is P(t). Nodes, points and shapes as in
    `lagrange_eval`.

    >>> from cagd_ref.interpolation import neville_plain
    >>> (neville_plain([0, 1, 3, 4], [(0, 0), (3, 3), (5, 3), (7, 0)], 2.0) * 6).round(12).tolist()
    [25.0, 24.0]
    """
    nodes, data = checked_data(ts, points, "points")
    tau, scalar = as_parameter(t)
    trailing = (1,) * (data.ndim - 1)  # one more axis for points than for scalar values
    u = tau.reshape((-1, 1) + trailing)  # (k, 1, 1)
    level = np.repeat(data[None], len(tau), axis=0)  # level 0: the points, (k, n+1, d)
    for r in range(1, len(nodes)):
        first = nodes[:-r].reshape((1, -1) + trailing)  # t_i
        last = nodes[r:].reshape((1, -1) + trailing)  # t_(i+r)
        level = ((last - u) * level[:, :-1] + (u - first) * level[:, 1:]) / (last - first)
    values = level[:, 0]
    if scalar:
        return values[0] if data.ndim == 2 else float(values[0])
    return values


def neville_triangle(ts: ArrayLike, points: ArrayLike, tau: float) -> list[np.ndarray]:
    """Every level of Neville's triangle at a number τ: level r holds p_(i..i+r)(τ), shape (n+1-r, d). Notes §10.4.

    Level 0 is a copy of the points ((n+1, d) or (n+1,)); the last level holds P(τ) alone.
    """
    nodes, data = checked_data(ts, points, "points")
    tau = np.array([as_scalar(tau, "tau")])
    columns = data.reshape(len(nodes), -1)
    levels = [level[:, :, 0].T.copy() for level in _neville_levels(nodes, columns, tau)]
    return levels if data.ndim == 2 else [level[:, 0] for level in levels]


# --- error bounds and Chebyshev nodes (§10.6) -------------------------------------------------------


def node_polynomial(nodes: ArrayLike, x: ArrayLike):
    """ω(x) = (x - x_0)(x - x_1)...(x - x_n), the node factor of the error (10.1): float or (k,). Notes §10.6."""
    roots = checked_nodes(nodes, distinct=False, name="nodes")
    xs, scalar = as_parameter(x, "x")
    values = np.prod(xs[:, None] - roots[None, :], axis=1)
    return float(values[0]) if scalar else values


def node_polynomial_max(nodes: ArrayLike, a: float, b: float) -> float:
    """max over [a, b] of |ω(x)| = |Π (x - x_i)|, found exactly (to rounding), not by sampling. Notes §10.6.

    Between two neighbouring nodes |ω| has a single peak, where the
    logarithmic derivative ω'/ω = Σ 1/(x - x_i) crosses zero; that sum falls
    strictly from +∞ to -∞ there, so bisection finds every peak. The largest
    of the peaks inside [a, b] and the values at a and b is the answer.
    """
    roots = np.sort(checked_nodes(nodes, distinct=False, name="nodes"))
    a, b = as_scalar(a, "a"), as_scalar(b, "b")
    if not a < b:
        raise ValueError(f"a, b: expected a < b, got a = {a}, b = {b}")
    distinct = np.unique(roots)
    lo, hi = distinct[:-1].copy(), distinct[1:].copy()
    for _ in range(200):
        middle = 0.5 * (lo + hi)
        if np.all((middle == lo) | (middle == hi)):
            break
        falling = np.sum(1.0 / (middle[:, None] - roots[None, :]), axis=1) > 0
        lo, hi = np.where(falling, middle, lo), np.where(falling, hi, middle)
    peaks = 0.5 * (lo + hi)
    candidates = np.concatenate([[a, b], peaks[(peaks > a) & (peaks < b)]])
    return float(np.max(np.abs(node_polynomial(roots, candidates))))


def chebyshev_nodes(a: float, b: float, n: int) -> np.ndarray:
    """The n Chebyshev nodes on [a, b], ascending: the zeros of the degree-n Chebyshev polynomial, mapped. Notes §10.6.

    x_i = (a + b)/2 + (b - a)/2 cos((2i + 1)π / (2n)), i = 0..n-1, returned in
    increasing order. Of all n nodes in [a, b] they make max |ω| smallest:
    2((b - a)/4)^n. Note that n counts nodes here: the interpolant through
    them has degree n - 1. (The notes' (10.6) mixes the two counts; its bound
    and Figure 10.5, "degree nine", are for nine nodes.)

    >>> from cagd_ref.interpolation import chebyshev_nodes, node_polynomial_max
    >>> chebyshev_nodes(0.0, 1.0, 9).round(8).tolist()
    [0.00759612, 0.0669873, 0.1786062, 0.32898993, 0.5, 0.67101007, 0.8213938, 0.9330127, 0.99240388]
    >>> round(node_polynomial_max(chebyshev_nodes(0.0, 1.0, 9), 0.0, 1.0) / (2 / 4**9), 12)
    1.0
    """
    a, b = as_scalar(a, "a"), as_scalar(b, "b")
    n = as_count(n, "n", minimum=1)
    if not a < b:
        raise ValueError(f"a, b: expected a < b, got a = {a}, b = {b}")
    # sin((2i + 1 - n)π / (2n)) = -cos((2i + 1)π / (2n)): increasing in i, and exactly symmetric about 0.
    return 0.5 * (a + b) + 0.5 * (b - a) * np.sin(np.pi * np.arange(1 - n, n, 2) / (2 * n))


def interpolation_error_bound(nodes: ArrayLike, derivative_bound: float, x: ArrayLike):
    """Cauchy's bound M |ω(x)| / (n+1)! on |f(x) - p(x)|, with M >= max |f^(n+1)|: float or (k,). Notes (10.1).

    nodes: the n+1 interpolation nodes; derivative_bound: M, a bound on the
    (n+1)-th derivative of f over the smallest interval holding x and the nodes.
    """
    roots = checked_nodes(nodes, distinct=False, name="nodes")
    bound = as_scalar(derivative_bound, "derivative_bound")
    if bound < 0:
        raise ValueError(f"derivative_bound: expected a bound >= 0, got {bound}")
    return bound * np.abs(node_polynomial(roots, x)) / factorial(len(roots))


def linear_segments_needed(a: float, b: float, second_derivative_bound: float, tol: float) -> int:
    """Equal chords that keep |f - polyline| <= tol on [a, b] if |f''| <= L: ceil((b - a) √(L / (8 tol))). Notes §10.6.

    One chord over an interval of length δ errs by at most L δ² / 8, the
    largest value of L |(x - x_0)(x - x_1)| / 2, reached at the midpoint. At
    least one chord.
    """
    a, b = as_scalar(a, "a"), as_scalar(b, "b")
    bound = as_scalar(second_derivative_bound, "second_derivative_bound")
    tol = as_tolerance(tol)
    if not a < b:
        raise ValueError(f"a, b: expected a < b, got a = {a}, b = {b}")
    if bound < 0:
        raise ValueError(f"second_derivative_bound: expected a bound >= 0, got {bound}")
    return max(1, int(np.ceil((b - a) * np.sqrt(bound / (8 * tol)))))


def second_derivative_bounds(points: ArrayLike) -> np.ndarray:
    """Bounds on each coordinate of |P''(t)|, t in [0, 1]: n(n-1) max_i |Δ²P_i|, shape (d,). Notes §10.6, (10.2)-(10.3).

    Δ²P_i = P_(i+2) - 2P_(i+1) + P_i. The second hodograph has the control
    points n(n-1) Δ²P_i, and each coordinate of P'' stays inside their convex
    hull. Zero below degree 2.
    """
    pts = as_points(points)
    n = len(pts) - 1
    if n < 2:
        return np.zeros(pts.shape[1])
    return n * (n - 1) * np.abs(np.diff(pts, n=2, axis=0)).max(axis=0)


def bezier_segments_needed(points: ArrayLike, tol: float) -> int:
    """How many chords at equal steps in t flatten a Bézier curve to within tol: ceil(√(‖L‖ / (8 tol))). Notes §10.6.

    points: (n+1, d); tol > 0. With m chords (δ = 1/m), coordinate c of the
    curve is within L_c / (8 m²) of its chord, where L = (L_x, L_y, ...) are the
    bounds (10.2)-(10.3) of `second_derivative_bounds`; by Pythagoras the
    point is within ‖L‖ / (8 m²). At least one segment (control points with zero second differences need no more).

    >>> from cagd_ref.interpolation import bezier_segments_needed
    >>> [bezier_segments_needed([(0, 0), (1, 3), (3, 3), (4, 0)], tol) for tol in (0.1, 0.01, 0.001)]
    [5, 16, 49]
    """
    bounds = second_derivative_bounds(points)
    tol = as_tolerance(tol)
    return max(1, int(np.ceil(np.sqrt(np.linalg.norm(bounds) / (8 * tol)))))


def flatten(points: ArrayLike, tol: float) -> np.ndarray:
    """The polyline through P(k/m), k = 0..m, m = bezier_segments_needed(points, tol): shape (m+1, d). Notes §10.6."""
    m = bezier_segments_needed(points, tol)
    return de_casteljau(points, np.linspace(0.0, 1.0, m + 1))


def chord_gaps(points: ArrayLike, segments: int, samples: int = 129) -> tuple[np.ndarray, np.ndarray]:
    """The gaps ‖P(t) - chord(t)‖ between a Bézier curve and its m chords at equal steps in t: (t, gaps). Notes §10.6.

    Each chord joins P(k/m) and P((k+1)/m) and is traversed at the same
    parameter as the curve; `samples` parameters per chord (ends included)
    are compared, so both arrays have shape (m * samples,). This parametric
    gap is at least the distance from the curve to the polyline, so the
    bound of `bezier_segments_needed` holds for both.
    """
    pts = as_points(points)
    m = as_count(segments, "segments", minimum=1)
    samples = as_count(samples, "samples", minimum=2)
    u = np.linspace(0.0, 1.0, samples)
    t = ((np.arange(m)[:, None] + u) / m).ravel()
    ends = de_casteljau(pts, np.arange(m + 1) / m)
    curve = de_casteljau(pts, t).reshape(m, samples, -1)
    chords = (1 - u)[None, :, None] * ends[:-1, None] + u[None, :, None] * ends[1:, None]
    return t, np.linalg.norm(curve - chords, axis=2).ravel()


def chord_deviation(points: ArrayLike, segments: int, samples: int = 129) -> float:
    """Measured max ‖P(t) - chord(t)‖ of a Bézier curve against its m chords, by `chord_gaps`. Notes §10.6."""
    return float(chord_gaps(points, segments, samples)[1].max())


# --- Hermite (§10.7) -----------------------------------------------------------------------------------


def hermite_basis(t: ArrayLike) -> np.ndarray:
    """The cubic Hermite functions at t, in the order of P(0), P(1), P'(0), P'(1): (4,) or (k, 4). Notes §10.7.

    H = (2t³ - 3t² + 1, -2t³ + 3t², t³ - 2t² + t, t³ - t²), the cubics with
    value or slope one at one end and all other end values and slopes zero.
    """
    tau, scalar = as_parameter(t)
    t2, t3 = tau**2, tau**3
    basis = np.column_stack([2 * t3 - 3 * t2 + 1, -2 * t3 + 3 * t2, t3 - 2 * t2 + tau, t3 - t2])
    return basis[0] if scalar else basis


def checked_hermite_data(p0: ArrayLike, p1: ArrayLike, d0: ArrayLike, d1: ArrayLike) -> np.ndarray:
    """The four Hermite vectors, checked, as rows (4, d), all of one dimension. Notes §10.7."""
    rows = [as_vector(value, name) for value, name in ((p0, "p0"), (p1, "p1"), (d0, "d0"), (d1, "d1"))]
    if len({len(row) for row in rows}) != 1:
        raise ValueError(f"p0, p1, d0, d1: expected vectors of one dimension, got lengths {[len(r) for r in rows]}")
    return np.array(rows)


def hermite_eval(p0: ArrayLike, p1: ArrayLike, d0: ArrayLike, d1: ArrayLike, t: ArrayLike) -> np.ndarray:
    """Point(s) of the cubic with P(0) = p0, P(1) = p1, P'(0) = d0, P'(1) = d1: (d,) or (k, d). Notes §10.7."""
    data = checked_hermite_data(p0, p1, d0, d1)
    return hermite_basis(t) @ data


def hermite_to_bezier(p0: ArrayLike, p1: ArrayLike, d0: ArrayLike, d1: ArrayLike) -> np.ndarray:
    """Bézier control points (4, d) of the cubic Hermite curve: p0, p0 + d0/3, p1 - d1/3, p1. Notes §10.7.

    A cubic Bézier curve has P'(0) = 3(P_1 - P_0) and P'(1) = 3(P_3 - P_2), so
    the inner control points sit a third of each end tangent inside the ends.
    Arguments are vectors of one dimension d, in the course's Hermite order:
    value at 0, value at 1, derivative at 0, derivative at 1.

    >>> from cagd_ref.interpolation import hermite_to_bezier
    >>> hermite_to_bezier([0, 0], [4, 0], [3, 9], [3, -9]).tolist()
    [[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.0]]
    """
    data = checked_hermite_data(p0, p1, d0, d1)
    return np.array([data[0], data[0] + data[2] / 3, data[1] - data[3] / 3, data[1]])
