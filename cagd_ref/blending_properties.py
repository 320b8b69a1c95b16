"""Which of the notes' six properties a set of blending functions has: chapter 5 of the notes.

A set of blending functions is any callable mapping k parameters to values of
shape (k, n+1) (see `cagd_ref.blending`). `check_properties` decides each
property numerically, with the evidence in a short reason; `symbolic_properties`
decides them exactly with SymPy where the functions are polynomial or rational.
The geometric helpers (line crossings of a polyline, convex hulls) serve the
variation-diminishing and convex-hull tests.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ._validation import as_count, as_float_array, as_interval, as_points, as_scalar
from .blending import FORMS, POWER_COEFFICIENTS, Basis, basis_values
from .geometry import normalize_line

__all__ = [
    "Verdict",
    "PROPERTIES",
    "line_crossings",
    "convex_hull",
    "distance_outside_hull",
    "variation_diminishing",
    "check_properties",
    "symbolic_basis",
    "exact_minimum",
    "symbolic_properties",
]

PROPERTIES = (
    "coordinate_independence",
    "convex_hull",
    "symmetry",
    "variation_diminishing",
    "linear_independence",
    "endpoint_interpolation",
)


class Verdict(NamedTuple):
    """Whether a property holds (None: not decided by this test) and a short reason with the evidence."""

    holds: bool | None
    reason: str



# ---------------------------------------------------------------- lines, crossings and hulls


def _filled_signs(values: np.ndarray, tol: float) -> tuple[np.ndarray, np.ndarray]:
    """Signs along the last axis with values within tol of 0 replaced by the last nonzero sign before them.

    Also returns, per entry, the index of that last nonzero entry. Zeros are
    touching points, not crossings, so a sign change is counted only between
    two strictly signed entries.
    """
    signs = np.sign(values) * (np.abs(values) > tol)
    index = np.where(signs != 0, np.arange(values.shape[-1]), 0)
    last = np.maximum.accumulate(index, axis=-1)
    return np.take_along_axis(signs, last, axis=-1), last


def _sign_changes(values: np.ndarray, tol: float) -> np.ndarray:
    """Strict sign changes along the last axis, ignoring entries within tol of zero: shape values.shape[:-1]."""
    filled, _ = _filled_signs(values, tol)
    return np.sum(filled[..., 1:] * filled[..., :-1] < 0, axis=-1)


def line_crossings(polyline, line) -> np.ndarray:
    """Points (m, 2) where a planar polyline (k, 2) crosses the line a x + b y + c = 0, in order. Notes §5, property 4.

    A vertex that only touches the line (neighbours on the same side) is not a
    crossing. A sampled curve has at most as many crossings as the curve
    itself, never more, because a sign change between samples needs a root.
    """
    pts = as_points(polyline, "polyline")
    if pts.shape[1] != 2:
        raise ValueError(f"polyline: expected planar points of shape (k, 2), got shape {pts.shape}")
    a, b, c = normalize_line(line)
    distance = pts @ np.array([a, b]) + c
    tol = 1e-12 * max(1.0, float(np.abs(pts).max()), abs(c))
    filled, last = _filled_signs(distance, tol)
    after = np.flatnonzero(filled[1:] * filled[:-1] < 0) + 1
    before = last[after - 1]
    # Adjacent strictly signed samples: interpolate; a run of on-line vertices between them: the first one.
    direct = before == after - 1
    share = np.where(direct, distance[before] / np.where(direct, distance[before] - distance[after], 1.0), 0.0)
    start = np.where(direct, before, before + 1)
    return pts[start] + share[:, None] * (pts[after] - pts[start])


def _cross(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """z-component of the cross product of planar vectors (..., 2): positive when v turns left of u."""
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def convex_hull(points) -> np.ndarray:
    """Vertices of the convex hull of planar points (k, 2), counter-clockwise: (h, 2). Notes §2.5, §5.

    Andrew's monotone chain on the sorted points; collinear points are left out,
    so a hull of collinear points is its two extreme points.
    """
    pts = as_points(points)
    if pts.shape[1] != 2:
        raise ValueError(f"points: expected planar points of shape (k, 2), got shape {pts.shape}")
    ordered = np.unique(pts, axis=0)  # sorted by x, then y

    def half(sequence):
        chain: list[np.ndarray] = []
        for p in sequence:
            while len(chain) >= 2 and _cross(chain[-1] - chain[-2], p - chain[-2]) <= 0:
                chain.pop()
            chain.append(p)
        return chain[:-1]

    if len(ordered) < 3:
        return ordered
    return np.array(half(ordered) + half(ordered[::-1]))


def distance_outside_hull(points, query) -> np.ndarray:
    """Distance from each query point (k, 2) to the convex hull of planar points (n+1, 2); 0 inside: (k,). Notes §5.

    A positive value is a place where a curve leaves the hull of its control
    points, i.e. where the convex hull property fails.
    """
    hull = convex_hull(points)
    q = as_points(query, "query")
    if q.shape[1] != 2:
        raise ValueError(f"query: expected planar points of shape (k, 2), got shape {q.shape}")
    start, edge = hull, np.roll(hull, -1, axis=0) - hull
    offset = q[:, None, :] - start[None]  # (k, h, 2)
    lengths = np.einsum("hd,hd->h", edge, edge)
    along = np.clip(np.einsum("khd,hd->kh", offset, edge) / np.where(lengths > 0, lengths, 1.0), 0.0, 1.0)
    to_edges = np.linalg.norm(offset - along[..., None] * edge, axis=2).min(axis=1)
    if len(hull) < 3:
        return to_edges  # a point or a segment has no inside
    left_of_every_edge = np.all(_cross(edge[None], offset) >= 0, axis=1)
    return np.where(left_of_every_edge, 0.0, to_edges)


# ---------------------------------------------------------------- numerical property checks


def _partition_of_unity(values: np.ndarray, tol: float) -> Verdict:
    error = float(np.abs(values.sum(axis=1) - 1).max())
    if error <= tol:
        return Verdict(True, f"the functions sum to 1 (largest deviation {error:.1e} on the samples)")
    return Verdict(False, f"the functions do not sum to 1: the sum is off by up to {error:.3g}")


def _convex_hull_verdict(values: np.ndarray, ts: np.ndarray, unity: Verdict, tol: float) -> Verdict:
    lowest = np.unravel_index(np.argmin(values), values.shape)
    minimum = float(values[lowest])
    if minimum < -tol:
        return Verdict(False, f"f{lowest[1]}({ts[lowest[0]]:.4g}) = {minimum:.4g} is negative")
    if not unity.holds:
        return Verdict(False, "the functions are non-negative but do not sum to 1")
    return Verdict(True, f"non-negative (smallest value {minimum:.2g}) and a partition of unity")


def _symmetry(values: np.ndarray, mirrored: np.ndarray, ts: np.ndarray, tol: float) -> Verdict:
    gap = np.abs(values - mirrored[:, ::-1])
    worst = np.unravel_index(np.argmax(gap), gap.shape)
    if gap[worst] <= tol:
        return Verdict(True, f"f_i(t) = f_(n-i)(tmin + tmax - t) on the samples (deviation {gap[worst]:.1e})")
    i, n = worst[1], values.shape[1] - 1
    return Verdict(False, f"f{i} and the mirrored f{n - i} differ by {gap[worst]:.3g} at t = {ts[worst[0]]:.4g}")


def _linear_independence(values: np.ndarray) -> Verdict:
    singular = np.linalg.svd(values, compute_uv=False)
    rank = int(np.linalg.matrix_rank(values))
    size = values.shape[1]
    ratio = singular[-1] / singular[0]
    if rank == size:
        return Verdict(True, f"the {len(values)} x {size} collocation matrix has full rank (σ_min/σ_max = {ratio:.2g})")
    return Verdict(False, f"the collocation matrix has rank {rank} < {size}: some combination vanishes on every sample")


def _endpoint_interpolation(values: np.ndarray, tol: float) -> Verdict:
    unit = np.eye(values.shape[1])
    start = float(np.abs(values[0] - unit[0]).max())
    end = float(np.abs(values[-1] - unit[-1]).max())
    if max(start, end) <= tol:
        return Verdict(True, "f(tmin) = (1, 0, ..., 0) and f(tmax) = (0, ..., 0, 1)")
    return Verdict(False, f"f(tmin) = {np.round(values[0], 4).tolist()}, f(tmax) = {np.round(values[-1], 4).tolist()}")


def _probe_heights(rng: np.random.Generator, count: int, size: int) -> np.ndarray:
    """Random signed heights (count, size) of control points above a line.

    A third are plain Gaussian, a third keep all but one point close to the line
    (where a negative blending function shows first), a third alternate in sign
    with magnitudes spread over four orders.
    """
    third = count // 3
    plain = rng.normal(size=(count - 2 * third, size))
    near = rng.normal(size=(third, size)) * 10.0 ** rng.uniform(-3, -1, (third, 1))
    near[np.arange(third), rng.integers(0, size, third)] = rng.choice([-1.0, 1.0], third)
    signs = (-1.0) ** np.arange(size) * rng.choice([-1, 1], (third, 1))
    alternating = signs * 10.0 ** rng.uniform(-2, 2, (third, size))
    return np.vstack([plain, near, alternating])


def _placed_probes(rng: np.random.Generator, count: int, size: int) -> tuple[np.ndarray, np.ndarray]:
    """Random planar polygons (count, size, 2) and a line (a, b, c) for each, shape (count, 3).

    Each polygon is drawn around the line y = 0, then polygon and line are
    moved together by a random rotation and shift. For a partition of unity the
    motion changes nothing; for other sets it tests the placement as well.
    """
    local = np.stack([rng.normal(size=(count, size)), _probe_heights(rng, count, size)], axis=-1)
    angle = rng.uniform(0, 2 * np.pi, count)
    cos, sin = np.cos(angle), np.sin(angle)
    rotation = np.stack([np.stack([cos, -sin], -1), np.stack([sin, cos], -1)], 1)  # (count, 2, 2)
    shift = rng.normal(scale=3.0, size=(count, 2))
    polygons = np.einsum("pij,pkj->pki", rotation, local) + shift[:, None]
    normals = rotation[:, :, 1]  # where the normal (0, 1) of y = 0 is turned to
    return polygons, np.column_stack([normals, -np.einsum("pi,pi->p", normals, shift)])


def variation_diminishing(values, probes: int = 600, seed: int = 0) -> Verdict:
    """Look for a line that crosses a curve more often than its control polygon: Notes §5, property 4.

    values: (k, n+1), the n+1 blending functions at k increasing parameters
    (a collocation matrix, as `basis_values` gives it). `probes` random planar
    polygons (seeded), each with a line of its own, are blended into sampled
    curves; the sign changes of the signed distances to the line count the
    crossings. A failure is a real counterexample (samples can only miss
    crossings, never invent them); a pass is evidence, not a proof.

    >>> from cagd_ref.blending import bezier_basis, timmer_basis
    >>> from cagd_ref.blending_properties import variation_diminishing
    >>> ts = np.linspace(0, 1, 257)
    >>> variation_diminishing(bezier_basis(ts)).holds, variation_diminishing(timmer_basis(ts)).holds
    (True, False)
    """
    values = as_float_array(values, "values")
    if values.ndim != 2 or values.shape[0] < 2 or values.shape[1] < 1:
        raise ValueError(f"values: expected blending-function values of shape (k, n+1) with k >= 2, got {values.shape}")
    probes = as_count(probes, "probes", minimum=3)
    rng = np.random.default_rng(as_count(seed, "seed"))
    polygons, lines = _placed_probes(rng, probes, values.shape[1])
    curves = np.einsum("si,pid->psd", values, polygons)

    def side(points):  # signed distances (probes, m) of points (probes, m, 2) from each probe's line
        scale = np.maximum(1.0, np.abs(polygons).max(axis=(1, 2)))[:, None]
        return (np.einsum("pmd,pd->pm", points, lines[:, :2]) + lines[:, 2:]) / scale

    p, c = _sign_changes(side(polygons), 1e-12), _sign_changes(side(curves), 1e-12)
    bad = np.flatnonzero(c > p)
    if bad.size:
        k = bad[0]
        heights = np.round(side(polygons)[k], 4).tolist()
        return Verdict(False, f"a line crosses the curve {c[k]} times but its control polygon only {p[k]} times "
                              f"(signed heights of the control points above the line, scaled: {heights})")
    return Verdict(True, f"no counterexample in {probes} random polygon/line pairs, each curve sampled at "
                         f"{len(values)} parameters (evidence, not proof)")


def check_properties(basis: Basis, domain=(0.0, 1.0), samples: int = 257, probes: int = 600,
                     seed: int = 0, tol: float = 1e-9) -> dict[str, Verdict]:
    """Test a set of blending functions numerically for the six properties of the notes' chapter 5.

    basis: callable, 1-D array of k parameters -> values (k, n+1); domain (t0, t1).
    Returns {name: Verdict} for the names in `PROPERTIES`, each from values
    at `samples` evenly spaced parameters, compared with absolute tolerance tol:

    * coordinate_independence: Σ f_i = 1 (partition of unity);
    * convex_hull: partition of unity and every f_i >= 0;
    * symmetry: f_i(t) = f_(n-i)(t0 + t1 - t);
    * variation_diminishing: `probes` random control polygons (seeded) and a
      line each; the property fails if the sampled curve crosses the line
      more often than the polygon. A failure is a real counterexample
      (sampling can only miss crossings); a pass is evidence, not a proof;
    * linear_independence: the (samples, n+1) collocation matrix has full
      rank, which is exact for polynomials of degree < samples;
    * endpoint_interpolation: f(t0) = (1, 0, ..., 0), f(t1) = (0, ..., 0, 1).
    """
    t0, t1 = as_interval(domain, "domain")
    samples = as_count(samples, "samples", minimum=2)
    probes = as_count(probes, "probes", minimum=3)
    seed = as_count(seed, "seed")
    tol = as_scalar(tol, "tol")
    if tol < 0:
        raise ValueError(f"tol: expected a tolerance >= 0, got {tol}")
    ts = np.linspace(t0, t1, samples)
    values = basis_values(basis, ts)
    mirrored = basis_values(basis, t0 + t1 - ts)
    unity = _partition_of_unity(values, tol)
    return {
        "coordinate_independence": unity,
        "convex_hull": _convex_hull_verdict(values, ts, unity, tol),
        "symmetry": _symmetry(values, mirrored, ts, tol),
        "variation_diminishing": variation_diminishing(values, probes, seed),
        "linear_independence": _linear_independence(values),
        "endpoint_interpolation": _endpoint_interpolation(values, tol),
    }


# ---------------------------------------------------------------- exact checks with SymPy


def _sympy():
    """SymPy, imported on first use: only the exact checks need it, and it is slow to load."""
    import sympy

    return sympy


def symbolic_basis(form: str, t=None) -> list:
    """The blending functions of `form` as SymPy expressions in the symbol t (default Symbol("t")). Notes §5.

    form: one of `FORMS` (Bézier means the cubic Bernstein polynomials) or
    "rational_example". The cubic forms come from the same power
    coefficients the numerical functions use, converted to exact rationals.
    """
    sp = _sympy()
    t = sp.Symbol("t") if t is None else t
    if not isinstance(form, str) or form not in {*FORMS, "rational_example"}:
        raise ValueError(f"form: expected one of {sorted(FORMS) + ['rational_example']}, got {form!r}")
    if form == "rational_example":
        return [(1 - t) ** 2 / (1 + t**2), 2 * t * (1 - t) / (1 + t**2), 2 * t**2 / (1 + t**2)]
    if form == "bezier":
        return [sp.binomial(3, i) * (1 - t) ** (3 - i) * t**i for i in range(4)]
    table = sp.Matrix(POWER_COEFFICIENTS[form]).applyfunc(sp.nsimplify)
    return [sp.expand(sum(table[j, i] * t**j for j in range(4))) for i in range(4)]


def _exact_functions(functions, t, t0, t1, name: str = "functions") -> list:
    """The functions as cancelled SymPy rational functions of t, checked to be finite on [t0, t1]."""
    sp = _sympy()
    if isinstance(functions, (str, bytes)) or not hasattr(functions, "__len__") or len(functions) == 0:
        raise ValueError(f"{name}: expected a non-empty sequence of SymPy expressions, got {functions!r}"[:160])
    f = [sp.cancel(sp.sympify(e)) for e in functions]
    for i, e in enumerate(f):
        if not e.free_symbols <= {t} or not e.is_rational_function(t):
            raise ValueError(f"{name}: f{i} = {e} is not a rational function of {t} alone")
        poles = [r for r in sp.Poly(sp.fraction(e)[1], t).real_roots() if t0 <= r <= t1]
        if poles:
            raise ValueError(f"{name}: f{i} = {e} has a pole at t = {poles[0]} inside [{t0}, {t1}]")
    return f


def _symbol_and_domain(t, domain) -> tuple:
    """The checked SymPy symbol t and the domain (t0, t1) as exact SymPy numbers."""
    sp = _sympy()
    if not isinstance(t, sp.Symbol):
        raise TypeError(f"t: expected a SymPy Symbol, got {type(t).__name__}")
    t0, t1 = (sp.nsimplify(v) for v in as_interval(domain, "domain"))
    return t0, t1


def exact_minimum(expression, t, domain=(0, 1)):
    """The exact smallest value of a rational function of t on the domain [t0, t1]: Notes §5, property 2.

    expression: a SymPy expression, rational in the Symbol t and without poles
    on the domain. The minimum of a function that is smooth on [t0, t1] sits at
    an end of the interval or where its derivative vanishes; for e = p/q that
    is a root of p' q - p q', found exactly by SymPy.

    >>> import sympy as sp
    >>> from cagd_ref.blending_properties import exact_minimum, symbolic_basis
    >>> t = sp.Symbol("t")
    >>> [exact_minimum(f, t) for f in symbolic_basis("timmer", t)]   # Timmer's f0 and f3 dip to -1/27
    [-1/27, 0, 0, -1/27]
    """
    sp = _sympy()
    t0, t1 = _symbol_and_domain(t, domain)
    (e,) = _exact_functions([expression], t, t0, t1, name="expression")
    numerator, denominator = sp.fraction(e)
    slope = sp.Poly(sp.diff(numerator, t) * denominator - numerator * sp.diff(denominator, t), t)
    inside = [r for r in (slope.real_roots() if not slope.is_zero else []) if t0 < r < t1]
    return min(e.subs(t, x) for x in [t0, t1, *inside])


def _exact_hull(f, t, t0, t1, unity: Verdict) -> Verdict:
    minima = [exact_minimum(e, t, (t0, t1)) for e in f]
    negative = [i for i, m in enumerate(minima) if m < 0]
    if negative:
        return Verdict(False, f"f{negative[0]} reaches {minima[negative[0]]} < 0 on [{t0}, {t1}]")
    if not unity.holds:
        return Verdict(False, "non-negative on the domain, but Σ f_i ≠ 1")
    return Verdict(True, "non-negative on the domain and a partition of unity")


def _exact_symmetry(f, t, t0, t1) -> Verdict:
    sp, n = _sympy(), len(f) - 1
    mirror = [sp.cancel(f[i] - f[n - i].subs(t, t0 + t1 - t)) for i in range(n + 1)]
    odd = [i for i, d in enumerate(mirror) if d != 0]
    if not odd:
        return Verdict(True, "f_i(t) = f_(n-i)(tmin + tmax - t) exactly")
    return Verdict(False, f"f{odd[0]}(t) - f{n - odd[0]}(tmin + tmax - t) = {sp.factor(mirror[odd[0]])}")


def _exact_independence(f, t) -> Verdict:
    """The notes' method: over a common denominator, Σ c_i f_i ≡ 0 is a linear system in the c_i."""
    sp = _sympy()
    common = sp.lcm_list([sp.fraction(e)[1] for e in f])
    numerators = [sp.Poly(sp.cancel(e * common), t) for e in f]
    degree = max(p.degree() for p in numerators)
    rank = sp.Matrix([[p.coeff_monomial(t**j) for j in range(degree + 1)] for p in numerators]).rank()
    reason = (f"the numerators over the common denominator {common} have a coefficient matrix of rank {rank} "
              f"(of {len(f)})")
    return Verdict(rank == len(f), reason)


def symbolic_properties(functions, t, domain=(0, 1)) -> dict[str, Verdict]:
    """Decide the properties of rational blending functions exactly with SymPy. Notes §5 and its Example.

    functions: a sequence of n+1 SymPy expressions in the symbol t, rational
    in t and without poles on the domain (t0, t1). Returns {name: Verdict}
    for `PROPERTIES`; variation diminishing is not decided (holds None), as in
    the notes. Linear independence follows the notes' Example: clear the
    denominators and ask whether the numerators' coefficient vectors are independent.
    """
    sp = _sympy()
    t0, t1 = _symbol_and_domain(t, domain)
    f = _exact_functions(functions, t, t0, t1)
    n = len(f) - 1
    total = sp.cancel(sum(f) - 1)
    unity = Verdict(total == 0, "Σ f_i simplifies to 1" if total == 0 else f"Σ f_i - 1 = {sp.factor(total)}")
    start, end = [e.subs(t, t0) for e in f], [e.subs(t, t1) for e in f]
    endpoints = Verdict(start == [1] + [0] * n and end == [0] * n + [1], f"f(tmin) = {start}, f(tmax) = {end}")
    return {
        "coordinate_independence": unity,
        "convex_hull": _exact_hull(f, t, t0, t1, unity),
        "symmetry": _exact_symmetry(f, t, t0, t1),
        "variation_diminishing": Verdict(None, "not decided symbolically (see check_properties for a numeric probe)"),
        "linear_independence": _exact_independence(f, t),
        "endpoint_interpolation": endpoints,
    }
