"""Figures of polynomial interpolation: interpolants with their parameters, Lagrange bases, node polynomials,
Neville's triangle, flattened Bézier curves and Hermite curves. Notes chapter 10.

Every function draws into the matplotlib Axes `ax` it is given and returns it.
Chapter 10 and its explorers draw with them.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
from matplotlib.axes import Axes

from cagd_ref._validation import as_count, as_float_array, as_scalar
from cagd_ref.bezier import de_casteljau
from cagd_ref.interpolation import (
    flatten,
    hermite_eval,
    hermite_to_bezier,
    lagrange_basis,
    lagrange_eval,
    neville_triangle,
    node_polynomial,
    node_polynomial_max,
)

from ._style import check_axes, finish_planar, planar_points
from .curves import plot_bezier, plot_control_polygon
from .vectors import plot_vector

__all__ = [
    "parameter_label",
    "neville_label",
    "plot_interpolant",
    "plot_lagrange_basis",
    "plot_node_polynomial",
    "plot_neville",
    "plot_flattening",
    "plot_hermite",
]

DATA_STYLE = {"marker": "o", "markersize": 7, "linestyle": "none", "color": "C3", "zorder": 4}
BASIS_SAMPLES = 301
# Label offsets (points) of Neville's levels 1, 2, 3, ...: deeper levels crowd together, so each gets its own side.
NEVILLE_OFFSETS = ((6, 4), (6, -13), (-34, 6), (-34, -13))


def parameter_label(t: float, name: str = "t") -> str:
    """'t = 3/4' for a value that is a simple fraction (denominator up to 64), else 't = 0.317'."""
    value = as_scalar(t, "t")
    fraction = Fraction(value).limit_denominator(64)
    if abs(float(fraction) - value) < 1e-12:
        text = str(fraction)
    else:
        text = f"{value:.3g}"
    return f"{name} = {text}"


def neville_label(first: int, last: int, name: str = "P") -> str:
    """Mathtext for the Neville point p_(first..last): '$P_{012}$' (indices run together, as in the notes)."""
    indices = "".join(str(i) for i in range(first, last + 1))
    if last >= 10:
        indices = ",".join(str(i) for i in range(first, last + 1))
    return f"${name}_{{{indices}}}$"


def _parameter_interval(ts: np.ndarray, interval) -> tuple[float, float]:
    if interval is not None:
        a, b = (float(v) for v in interval)
        return a, b
    return float(ts.min()), float(ts.max())


def _label_directions(pts: np.ndarray) -> np.ndarray:
    """Unit directions (m, 2) for the labels of planar points: away from the points' centre, where curves through
    them rarely run, but straight up or down for the leftmost and rightmost points, so no label leaves the axes."""
    away = pts - pts.mean(axis=0)
    outer = (pts[:, 0] == pts[:, 0].min()) | (pts[:, 0] == pts[:, 0].max())
    away[outer, 0] = 0.0
    away[outer & (away[:, 1] == 0), 1] = -1.0
    lengths = np.linalg.norm(away, axis=1, keepdims=True)
    return np.where(lengths > 0, away / np.where(lengths > 0, lengths, 1), [[0.0, -1.0]])


def plot_interpolant(ax, ts, points, interval=None, samples: int = 200, labels: bool = True, **style) -> Axes:
    """Draw the planar curve through points (n+1, 2) at the nodes ts, and the data labelled 't = ...'. Notes §10.1.

    The curve is drawn for t in `interval` (default: from the smallest to the
    largest node); `style` goes to the curve (pass `label=` for a legend).
    """
    check_axes(ax)
    nodes = as_float_array(ts, "ts")
    pts = planar_points(points)
    a, b = _parameter_interval(nodes, interval)
    curve = lagrange_eval(nodes, pts, np.linspace(a, b, as_count(samples, "samples", minimum=2)))
    ax.plot(*curve.T, **{"color": "C0", "linewidth": 2.0, **style})
    ax.plot(*pts.T, **DATA_STYLE)
    if labels:
        for t, point, (dx, dy) in zip(nodes, pts, _label_directions(pts)):
            ax.annotate(parameter_label(t), point, xytext=(14 * dx, 14 * dy), textcoords="offset points", fontsize=9,
                        color="C3", ha="left" if dx > 0.1 else "right" if dx < -0.1 else "center", va="center")
    return finish_planar(ax)


def plot_lagrange_basis(ax, ts, interval=None, highlight: int | None = None, samples: int = BASIS_SAMPLES) -> Axes:
    """Draw the Lagrange basis functions L_i of the nodes ts over `interval`, the nodes marked. Notes §10.2.

    The function `highlight` (an index, or None) is drawn heavy with its
    negative part shaded: where any L_i < 0 the interpolant is no convex
    combination of its data.
    """
    check_axes(ax)
    nodes = as_float_array(ts, "ts")
    a, b = _parameter_interval(nodes, interval)
    t = np.linspace(a, b, as_count(samples, "samples", minimum=2))
    basis = lagrange_basis(nodes, t)
    for i, column in enumerate(basis.T):
        heavy, faded = i == highlight, highlight is not None and i != highlight
        ax.plot(t, column, color=f"C{i % 10}", linewidth=2.4 if heavy else 1.2, alpha=0.45 if faded else 1.0,
                label=f"$L_{{{i}}}$")
    if highlight is not None:
        column = basis[:, highlight]
        ax.fill_between(t, column, 0, where=column < 0, color=f"C{highlight % 10}", alpha=0.25)
    ax.axhline(0, color="0.6", linewidth=0.8)
    ax.axhline(1, color="0.8", linewidth=0.8, linestyle=":")
    ax.plot(nodes, np.zeros_like(nodes), "k|", markersize=12)
    ax.set_xlim(a, b)
    return ax


def plot_node_polynomial(ax, nodes, a: float, b: float, samples: int = 801, **style) -> Axes:
    """Draw ω(x) = Π (x - x_i) on [a, b], the nodes on the axis and dashed lines at ± max |ω|. Notes §10.6."""
    check_axes(ax)
    roots = as_float_array(nodes, "nodes")
    x = np.linspace(a, b, as_count(samples, "samples", minimum=2))
    color = style.pop("color", "C0")
    ax.plot(x, node_polynomial(roots, x), **{"color": color, "linewidth": 1.8, **style})
    peak = node_polynomial_max(roots, a, b)
    ax.axhline(peak, color=color, linestyle="--", linewidth=0.8)
    ax.axhline(-peak, color=color, linestyle="--", linewidth=0.8)
    ax.plot(roots, np.zeros_like(roots), "o", color=color, markersize=5, markerfacecolor="white")
    ax.axhline(0, color="0.6", linewidth=0.6)
    ax.set_xlim(a, b)
    return ax


def plot_neville(ax, ts, points, tau: float, level: int | None = None, curves: bool = True) -> Axes:
    """Draw Neville's triangle at τ up to `level` (default n): partial interpolants and their points. Notes §10.4.

    points: (n+1, 2). Level r shows, for each i, the curve through
    P_i..P_(i+r) (thin, if `curves`) and its point p_(i..i+r)(τ), labelled P_(i..i+r).
    The last level's point is the interpolant's P(τ).
    """
    check_axes(ax)
    nodes = as_float_array(ts, "ts")
    pts = planar_points(points)
    n = len(pts) - 1
    level = n if level is None else as_count(level, "level")
    triangle = neville_triangle(nodes, pts, tau)
    plot_interpolant(ax, nodes, pts, interval=(min(nodes.min(), tau), max(nodes.max(), tau)), color="0.8",
                     linewidth=4, zorder=0)
    for r in range(1, min(level, n) + 1):
        color = f"C{(r + 3) % 10}"
        offset = NEVILLE_OFFSETS[(r - 1) % len(NEVILLE_OFFSETS)]
        for i, point in enumerate(triangle[r]):
            if curves:
                # Each partial curve over its own nodes and τ: far beyond them it would only crowd the picture.
                own = nodes[i : i + r + 1]
                t = np.linspace(min(own.min(), tau), max(own.max(), tau), 60)
                ax.plot(*lagrange_eval(own, pts[i : i + r + 1], t).T, color=color, linewidth=0.9, alpha=0.6)
            ax.plot(*point, "s", color=color, markersize=6 + 3 * (r == n), zorder=5)
            ax.annotate(neville_label(i, i + r), point, xytext=offset, textcoords="offset points", fontsize=9,
                        color=color)
    return finish_planar(ax)


def plot_flattening(ax, points, tol: float | None = None, segments: int | None = None, polygon: bool = True) -> Axes:
    """Draw a planar Bézier curve and its polyline of m chords at equal steps in t. Notes §10.6.

    Give either `tol` (m from `bezier_segments_needed`) or `segments` = m.
    """
    check_axes(ax)
    pts = planar_points(points)
    if (tol is None) == (segments is None):
        raise ValueError("tol, segments: give exactly one of the two")
    if tol is not None:
        polyline = flatten(pts, tol)
    else:
        polyline = de_casteljau(pts, np.linspace(0.0, 1.0, as_count(segments, "segments", minimum=1) + 1))
    if polygon:
        plot_control_polygon(ax, pts, labels=False, alpha=0.6)
    plot_bezier(ax, pts, color="C0", linewidth=3, alpha=0.35)
    ax.plot(*polyline.T, "-", color="C3", linewidth=1.2, marker="o", markersize=3)
    return finish_planar(ax)


def plot_hermite(ax, p0, p1, d0, d1, polygon: bool = True, **style) -> Axes:
    """Draw the cubic Hermite curve with P(0) = p0, P(1) = p1, P'(0) = d0, P'(1) = d1 in the plane. Notes §10.7.

    The tangents are drawn a third of their length, from p0 forwards and into
    p1: those arrows are the first and last legs of the curve's Bézier polygon
    (drawn dashed with `polygon`).
    """
    check_axes(ax)
    control = hermite_to_bezier(p0, p1, d0, d1)
    if control.shape[1] != 2:
        raise ValueError(f"p0, p1, d0, d1: expected planar vectors (2,), got dimension {control.shape[1]}")
    curve = hermite_eval(p0, p1, d0, d1, np.linspace(0.0, 1.0, 200))
    ax.plot(*curve.T, **{"color": "C0", "linewidth": 2.0, **style})
    if polygon:
        plot_control_polygon(ax, control, labels=False)
    arrows = ((control[0], control[1], "$P'(0)/3$", "C1"), (control[2], control[3], "$P'(1)/3$", "C2"))
    for tail, head, text, color in arrows:
        plot_vector(ax, tail, head - tail, color=color)
        # The label beside the arrow's middle, on the side away from the curve's inner polygon.
        along = head - tail
        normal = np.array([along[1], -along[0]]) / max(np.linalg.norm(along), 1e-300)
        if normal @ (0.5 * (tail + head) - control.mean(axis=0)) < 0:
            normal = -normal
        ax.annotate(text, 0.5 * (tail + head), xytext=12 * normal, textcoords="offset points", color=color,
                    fontsize=10, ha="left" if normal[0] >= 0 else "right", va="center")
    return finish_planar(ax)
