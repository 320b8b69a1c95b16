"""Forward differencing: many equally spaced values of a polynomial for n additions each. Notes chapter 4.

A polynomial f of degree n sampled at t_i = t0 + i δ has forward differences
Δ⁰ = f, Δʲ(t_i) = Δʲ⁻¹(t_{i+1}) - Δʲ⁻¹(t_i); the n-th one is the constant
n! a_n δⁿ. Once the n+1 differences at t0 are known, every next value follows
by additions alone. Arrays of values or coefficients are (n+1,) for one
polynomial or (n+1, d) for d of them at once (the columns, e.g. the
coordinates of a curve), as in `cagd_ref.polynomials`.
"""

from __future__ import annotations

from math import comb, factorial

import numpy as np

from ._validation import as_coefficients, as_count, as_points, as_scalar
from .polynomials import bernstein_to_power, difference_table, horner, substitute_affine

__all__ = [
    "forward_difference_table",
    "initial_differences",
    "power_differences",
    "forward_difference_steps",
    "forward_difference_eval",
    "missing_value",
    "bezier_by_differences",
    "raster_delta",
    "pixels_along",
    "rasterize",
    "find_gaps",
    "double_step",
    "halve_step",
    "adaptive_march",
    "drift",
    "float32_drift",
]

# Below this step a rasterisation would march more than ten million points.
MIN_RASTER_DELTA = 1e-7
# An adaptive march halves its step at most this often (a step of 2⁻⁴⁰ is far below any screen's needs).
MAX_HALVINGS = 40


def forward_difference_table(values) -> list[np.ndarray]:
    """The difference table of n+1 values f(t0), ..., f(t0 + n δ). Notes §4.

    values: (n+1,) or (n+1, d). Returns a list of n+1 arrays; row j holds
    Δʲ(t_i) for i = 0..n-j, shape (n+1-j,) or (n+1-j, d). Row 0 is a copy of
    the values, the last row is the single n-th difference. The notes' cubic
    at t = 1, ..., 5, with its missing value 8 put in, has constant third
    differences and a vanishing fourth one:

    >>> from cagd_ref.forward_differencing import forward_difference_table
    >>> [row.tolist() for row in forward_difference_table([1, 2, 4, 8, 15])]
    [[1.0, 2.0, 4.0, 8.0, 15.0], [1.0, 2.0, 4.0, 7.0], [1.0, 2.0, 3.0], [1.0, 1.0], [0.0]]
    """
    return difference_table(as_coefficients(values, "values"))


def initial_differences(values) -> np.ndarray:
    """The left column of the difference table: f(t0), Δ¹(t0), ..., Δⁿ(t0), shape (n+1,) or (n+1, d). Notes §4."""
    return np.array([row[0] for row in forward_difference_table(values)])


def _stirling_differences(n: int) -> np.ndarray:
    """(n+1, n+1) matrix D with D[j, k] = j! S(k, j): the j-th difference at 0, step 1, of the monomial uᵏ.

    S(k, j) are the Stirling numbers of the second kind, built row by row from
    S(k, j) = j S(k-1, j) + S(k-1, j-1); j! S(k, j) is the number of maps of k
    objects onto j. With S(2, 2) = S(3, 3) = 1 this gives the 2 a₂ δ² and 6 a₃ δ³ of the notes.
    """
    stirling = np.zeros((n + 1, n + 1))
    stirling[0, 0] = 1.0
    for k in range(1, n + 1):
        for j in range(1, k + 1):
            stirling[k, j] = j * stirling[k - 1, j] + stirling[k - 1, j - 1]
    factorials = np.array([factorial(j) for j in range(n + 1)], dtype=float)
    return factorials[:, None] * stirling.T


def power_differences(coeffs, t0: float = 0.0, delta: float = 1.0) -> np.ndarray:
    """Starting differences f(t0), Δ¹(t0), ..., Δⁿ(t0) of a power-form polynomial for step δ. Notes §4.

    coeffs: ascending power coefficients (n+1,) or (n+1, d). The polynomial is
    first rewritten in the step count s, q(s) = f(t0 + δ s) = Σ q_k sᵏ with
    q_k = c_k δᵏ (c_k its coefficients about t0); then Δʲ(t0) = j! Σ_k S(k, j) q_k.
    For t0 = 0 and n = 3 this is the notes' Δ¹ = a₁δ + a₂δ² + a₃δ³,
    Δ² = 2a₂δ² + 6a₃δ³, Δ³ = 6a₃δ³. No differences of nearby values are taken,
    so the small high-order differences keep their full relative precision.
    Returns shape (n+1,) or (n+1, d).
    """
    a = as_coefficients(coeffs)
    t0 = as_scalar(t0, "t0")
    delta = as_scalar(delta, "delta")
    # Stepping f by δ from t0 is stepping q by 1 from 0, so unit-step differences of q are the ones wanted.
    q = substitute_affine(a, t0, delta)
    return np.tensordot(_stirling_differences(len(a) - 1), q, axes=1)


def _float_type(dtype) -> np.dtype:
    try:
        kind = np.dtype(dtype)
    except TypeError:
        raise TypeError(f"dtype: expected a floating-point type such as numpy.float32, got {dtype!r}") from None
    if kind.kind != "f":
        raise TypeError(f"dtype: expected a floating-point type such as numpy.float32, got {kind}")
    return kind


def forward_difference_steps(differences, count: int, dtype=np.float64) -> np.ndarray:
    """March the difference column `count` steps: the values f(t0), ..., f(t0 + (count-1) δ). Notes §4.

    differences: the column f(t0), Δ¹(t0), ..., Δⁿ(t0), shape (n+1,) or (n+1, d).
    Each step costs n additions per column and no multiplication. The
    arithmetic runs in `dtype` (float64 by default; float32 shows the drift).
    Returns shape (count,) or (count, d) in that dtype.
    """
    kind = _float_type(dtype)
    column = as_coefficients(differences, "differences").astype(kind)
    count = as_count(count, "count")
    values = np.empty((count,) + column.shape[1:], dtype=kind)
    for k in range(count):
        values[k] = column[0]
        # Every Δʲ moves one step right using the old Δʲ⁺¹ beneath it (the table's
        # rule R_right = R + R_down); the right side is built before anything is stored.
        column[:-1] = column[:-1] + column[1:]
    return values


def forward_difference_eval(coeffs, t0: float, delta: float, count: int, dtype=np.float64) -> np.ndarray:
    """Values of a power-form polynomial at t0 + i δ, i = 0..count-1, by forward differencing. Notes §4.

    coeffs: ascending power coefficients (n+1,) or (n+1, d); t0, delta:
    numbers (delta may be zero or negative); count: an integer >= 0. The
    starting differences come from `power_differences`; every further value
    costs n additions (`forward_difference_steps`), run in `dtype`. Returns
    shape (count,) or (count, d). The cubic of the notes' table in power form,
    (t³ - 3t² + 8t)/6, stepped from t0 = 1 by δ = 1 continues 1, 2, 4, 8, 15:

    >>> from cagd_ref.forward_differencing import forward_difference_eval
    >>> np.round(forward_difference_eval([0, 4 / 3, -1 / 2, 1 / 6], 1.0, 1.0, 7), 9).tolist()
    [1.0, 2.0, 4.0, 8.0, 15.0, 26.0, 42.0]

    Ref: J. D. Foley, A. van Dam, S. K. Feiner and J. F. Hughes, Computer Graphics: Principles and Practice,
    2nd ed., Addison-Wesley, 1990 (forward differences for drawing curves).
    """
    start = power_differences(coeffs, t0, delta)
    return forward_difference_steps(start, count, dtype)


def missing_value(values, index: int):
    """The entry `values[index]` that makes n+1 values those of a polynomial of degree n-1. Notes §4 (example).

    values: (n+1,) or (n+1, d), n >= 1, the values f(t0 + i δ) at equally spaced
    parameters; whatever stands at `index` is ignored (it may be NaN, a common
    placeholder). Values of a polynomial of degree n-1 have
    Δⁿ f(t0) = Σ_i (-1)ⁿ⁻ⁱ C(n, i) f_i = 0 (expand Δⁿ = (E - I)ⁿ with the shift E),
    an equation linear in the unknown entry. Returns a float, or shape (d,).
    The notes' cubic with f(1), ..., f(5) = 1, 2, 4, x, 15:

    >>> from cagd_ref.forward_differencing import missing_value
    >>> missing_value([1, 2, 4, float("nan"), 15], 3)
    8.0
    """
    index = as_count(index, "index")
    if values is None or isinstance(values, (str, bytes, dict, set)):
        raise TypeError(f"values: expected numbers, got {type(values).__name__}")
    try:
        f = np.array(values, dtype=float)
    except (TypeError, ValueError) as err:
        raise TypeError(f"values: expected numbers ({err})") from None
    if f.ndim not in (1, 2) or len(f) < 2:
        raise ValueError(f"values: expected shape (n+1,) or (n+1, d) with at least two values, got shape {f.shape}")
    n = len(f) - 1
    if index > n:
        raise ValueError(f"index: expected 0 <= index <= {n}, got {index}")
    known = np.arange(n + 1) != index
    if not np.all(np.isfinite(f[known])):
        raise ValueError("values: expected finite numbers away from `index`, got NaN or infinity")
    signs = np.array([(-1) ** (n - i) * comb(n, i) for i in range(n + 1)], dtype=float)
    rest = np.tensordot(signs[known], f[known], axes=1)
    found = -rest / signs[index]
    return float(found) if f.ndim == 1 else found


def bezier_by_differences(points, steps: int) -> np.ndarray:
    """Points P(i / steps), i = 0..steps, of a Bézier curve by forward differencing, shape (steps+1, d). Notes §4.

    points: control points (n+1, d); steps: an integer >= 1. The power
    coefficients of P(t) = Σ B_iⁿ(t) P_i are a_k = C(n, k) Δᵏ P_0, forward
    differences of the control points (`bernstein_to_power`); the curve is then
    marched from t = 0 with δ = 1 / steps, started from the closed form. The
    course's cubic in pixel units at t = 0, 1/2, 1:

    >>> from cagd_ref.forward_differencing import bezier_by_differences
    >>> np.round(bezier_by_differences([[2, 3], [10, 26], [30, 28], [37, 5]], 2), 9).tolist()
    [[2.0, 3.0], [19.875, 21.25], [37.0, 5.0]]
    """
    pts = as_points(points)
    steps = as_count(steps, "steps", minimum=1)
    return forward_difference_eval(bernstein_to_power(pts), 0.0, 1.0 / steps, steps + 1)


def raster_delta(points) -> float:
    """A step δ that rasterises a Bézier curve in pixel coordinates without gaps: δ = 1 / (n d). Notes §4.1.

    points: (n+1, 2) in pixel units (any number of columns works alike). d is
    the largest |coordinate difference| of neighbouring control points, over
    all coordinates. The hodograph has control points
    n (P_{i+1} - P_i), so no coordinate of P' exceeds n d in size, and a step
    of δ moves every coordinate by at most δ n d = 1 pixel. Capped at 1 (one
    step for a curve inside one pixel's width, or a single point). The
    course's cubic moves 23 pixels in y along its first leg, so n d = 69:

    >>> from cagd_ref.forward_differencing import raster_delta
    >>> round(1 / raster_delta([[2, 3], [10, 26], [30, 28], [37, 5]]))
    69
    """
    pts = as_points(points)
    n = len(pts) - 1
    largest = float(np.abs(np.diff(pts, axis=0)).max()) if n else 0.0
    return 1.0 / max(n * largest, 1.0)


def rasterize(points, delta: float | None = None) -> np.ndarray:
    """The pixels of a planar Bézier curve, in order along it, shape (m, 2) of ints. Notes §4.1.

    points: (n+1, 2) in pixel units; pixel (i, j) is the square [i, i+1) x [j, j+1).
    The curve is forward differenced with ceil(1 / δ) equal steps (so the step
    used is at most δ; default `raster_delta(points)`) and each point paints
    its pixel (`pixels_along`).
    """
    pts = as_points(points)
    if pts.shape[1] != 2:
        raise ValueError(f"points: expected planar points of shape (n+1, 2), got shape {pts.shape}")
    delta = raster_delta(pts) if delta is None else as_scalar(delta, "delta")
    if not MIN_RASTER_DELTA <= delta <= 1:
        raise ValueError(f"delta: expected {MIN_RASTER_DELTA:g} <= delta <= 1, got {delta}")
    return pixels_along(bezier_by_differences(pts, int(np.ceil(1.0 / delta))))


def pixels_along(samples) -> np.ndarray:
    """The pixels that points along a curve fall in, repeats in a row dropped, shape (m, d) of ints. Notes §4.1.

    samples: (k, d) points in pixel units, in order; pixel (i, j) is the square
    [i, i+1) x [j, j+1), so a point's pixel is its coordinates rounded down.
    """
    pixels = np.floor(as_points(samples, "samples")).astype(int)
    moved = np.ones(len(pixels), dtype=bool)
    moved[1:] = np.any(pixels[1:] != pixels[:-1], axis=1)
    return pixels[moved]


def find_gaps(pixels) -> np.ndarray:
    """Positions i where pixel i+1 does not touch pixel i (not even at a corner), shape (g,) of ints. Notes §4.1.

    pixels: (m, 2) integer pixel coordinates in order along a curve. A drawing
    without gaps has every pair of consecutive pixels at most one apart in x and in y.
    """
    p = as_points(pixels, "pixels")
    jumps = np.abs(np.diff(p, axis=0)).max(axis=1) if len(p) > 1 else np.zeros(0)
    return np.flatnonzero(jumps > 1)


def _power_series(series: np.ndarray, j: int) -> np.ndarray:
    """Coefficients of (Σ_r series[r] Δʳ)ʲ in powers of Δ, cut after Δⁿ (n + 1 = len(series))."""
    out = np.zeros(len(series))
    out[0] = 1.0
    for _ in range(j):
        out = np.convolve(out, series)[: len(series)]
    return out


def _step_map(series: np.ndarray) -> np.ndarray:
    """(n+1, n+1) matrix taking the column f, Δ, ..., Δⁿ to the column of the operator Σ_r series[r] Δʳ."""
    return np.array([_power_series(series, j) for j in range(len(series))])


def double_step(differences) -> np.ndarray:
    """The column f(t), Δ¹(t), ..., Δⁿ(t) for step 2δ from the column for step δ. Notes §4 (Lien, Shantz, Pratt).

    differences: shape (n+1,) or (n+1, d). With the shift E f(t) = f(t + δ) and
    Δ = E - I, the difference for step 2δ is E² - I = 2Δ + Δ², so its j-th
    power is (2Δ + Δ²)ʲ = Σ_l C(j, l) 2ʲ⁻ˡ Δʲ⁺ˡ (Δⁿ⁺¹ = 0): integer weights.
    For a cubic: Δ¹ ← 2Δ¹ + Δ², Δ² ← 4Δ² + 4Δ³, Δ³ ← 8Δ³. Same shape back.

    Ref: S.-L. Lien, M. Shantz and V. Pratt, Adaptive forward differencing for rendering curves and
    surfaces, Computer Graphics (SIGGRAPH '87) 21(4), 111-118, 1987.
    """
    column = as_coefficients(differences, "differences")
    series = np.zeros(len(column))
    series[1 : min(3, len(column))] = [2.0, 1.0][: max(0, min(2, len(column) - 1))]
    return np.tensordot(_step_map(series), column, axes=1)


def halve_step(differences) -> np.ndarray:
    """The column f(t), Δ¹(t), ..., Δⁿ(t) for step δ/2 from the column for step δ. Notes §4 (Lien, Shantz, Pratt).

    differences: shape (n+1,) or (n+1, d). The difference for step δ/2 is
    E^(1/2) - I = (I + Δ)^(1/2) - I = Σ_(r>=1) C(1/2, r) Δʳ, a finite sum since
    Δⁿ⁺¹ = 0; its j-th power gives Δʲ for the half step. The inverse of
    `double_step`. For a cubic: Δ¹ ← Δ¹/2 - Δ²/8 + Δ³/16, Δ² ← Δ²/4 - Δ³/8,
    Δ³ ← Δ³/8. Same shape back.
    """
    column = as_coefficients(differences, "differences")
    series = np.zeros(len(column))
    for r in range(1, len(column)):
        series[r] = np.prod([(0.5 - s) / (s + 1) for s in range(r)])  # the binomial coefficient C(1/2, r)
    return np.tensordot(_step_map(series), column, axes=1)


def adaptive_march(points, limit: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """Points of a Bézier curve from t = 0 to 1 by forward differencing with a step that halves and doubles.

    points: (n+1, d); limit > 0 (pixels). The step stays a power of two,
    δ = 2⁻ˡ. Before each move the step is halved (`halve_step`) while some
    coordinate of the next increment Δ¹ exceeds `limit`; after the move it is
    doubled (`double_step`) while t is a multiple of 2δ and the doubled
    increment stays within `limit`. So consecutive points differ by at most
    `limit` in every coordinate, and the march lands on t = 1 exactly.
    Returns (params (k,), samples (k, d)). Notes §4.1, after Lien, Shantz and Pratt (1987).
    """
    pts = as_points(points)
    limit = as_scalar(limit, "limit")
    if limit <= 0:
        raise ValueError(f"limit: expected a positive number of pixels, got {limit}")
    column = power_differences(bernstein_to_power(pts), 0.0, 1.0)  # step δ = 1
    level, position = 0, 0  # t = position / 2**level
    params, samples = [], []
    while True:
        while np.abs(column[1:2]).max(initial=0.0) > limit:
            if level == MAX_HALVINGS:
                raise ValueError(f"points: the curve moves more than {limit} per step of 2^-{MAX_HALVINGS}")
            column, level, position = halve_step(column), level + 1, 2 * position
        params.append(position / 2**level)
        samples.append(column[0].copy())
        if position == 2**level:
            return np.array(params), np.array(samples)
        column[:-1] = column[:-1] + column[1:]
        position += 1
        while level > 0 and position % 2 == 0:
            doubled = double_step(column)
            if np.abs(doubled[1:2]).max(initial=0.0) > limit:
                break
            column, level, position = doubled, level - 1, position // 2


def drift(coeffs, t0: float, delta: float, count: int, dtype=np.float32) -> tuple[np.ndarray, np.ndarray]:
    """Rounding errors of forward differencing and of Horner's rule, both run in `dtype`, step by step.

    coeffs: ascending power coefficients (n+1,) or (n+1, d). Both methods
    evaluate at t0 + i δ, i = 0..count-1, with everything (coefficients,
    differences, parameters) rounded to `dtype`; each is compared with Horner's
    rule in float64 and the largest error over the columns is kept. Returns
    (forward_error, horner_error), each of shape (count,). For dtype float64
    the Horner error is zero by construction and the forward error is the
    drift against Horner. Notes §4.
    """
    a = as_coefficients(coeffs)
    kind = _float_type(dtype)
    t = as_scalar(t0, "t0") + as_scalar(delta, "delta") * np.arange(as_count(count, "count"))
    columns = (len(t), a[0].size)
    exact = np.reshape(horner(a, t), columns)
    forward = np.reshape(forward_difference_eval(a, t0, delta, len(t), kind), columns)
    # NumPy's polyval is Horner's rule and keeps the dtype of its inputs.
    low = np.polynomial.polynomial.polyval(t.astype(kind), a.astype(kind).reshape(len(a), -1), tensor=True).T
    forward_error = np.abs(forward.astype(float) - exact).max(axis=1, initial=0.0)
    horner_error = np.abs(low.astype(float) - exact).max(axis=1, initial=0.0)
    return forward_error, horner_error


def float32_drift(coeffs, delta: float, count: int) -> np.ndarray:
    """How far forward differencing in single precision drifts from the exact values, step by step. Notes §4.

    coeffs: ascending power coefficients (n+1,) or (n+1, d); delta: the step;
    count: an integer >= 0. The starting differences at t = 0 come from the
    closed form in double precision (`power_differences`) and are rounded to
    float32; the march runs in float32, every addition rounded to single
    precision. The exact values f(i δ) are taken from Horner's rule in float64
    (its own error, about 1e-16 relative, is negligible beside float32's 6e-8).
    Returns |march - exact| as float64, shape (count,) or (count, d). A step
    that float32 holds exactly leaves a line exact; 0.1 is no float32 number:

    >>> from cagd_ref.forward_differencing import float32_drift
    >>> float32_drift([0.0, 1.0], 0.5, 3).tolist()
    [0.0, 0.0, 0.0]
    >>> bool(float32_drift([0.0, 1.0], 0.1, 3)[-1] > 0)
    True
    """
    a = as_coefficients(coeffs)
    delta = as_scalar(delta, "delta")
    count = as_count(count, "count")
    start = power_differences(a, 0.0, delta).astype(np.float32)
    march = forward_difference_steps(start, count, np.float32).astype(float)
    exact = np.reshape(horner(a, delta * np.arange(count)), march.shape)
    return np.abs(march - exact)
