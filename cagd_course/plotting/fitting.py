"""Figures of approximation: samples and fitted B-splines, residuals, tolerance boxes, error and curvature plots.

Notes chapter 11. The notes draw the control polygon in red and the samples in
blue; these helpers keep that colour scheme. Every function draws into the
matplotlib Axes `ax` it is given and returns it. B-splines use the notes' knot
convention (c + n - 1 knots).
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection, PolyCollection

from cagd_ref._validation import as_count, as_float_array, as_points
from cagd_ref.approximation import estimate_frames, spline_curvature
from cagd_ref.bspline import de_boor, degree, domain

from ._style import CURVE_STYLE, check_axes, finish_planar, planar_points

__all__ = [
    "SAMPLE_STYLE",
    "FIT_POLYGON_STYLE",
    "fit_samples",
    "plot_samples",
    "plot_fit",
    "plot_residuals",
    "box_corners",
    "plot_boxes",
    "plot_error_measures",
    "plot_curvature",
]

SAMPLE_STYLE = {"color": "C0", "marker": "o", "markersize": 4, "linestyle": "none"}
FIT_POLYGON_STYLE = {"color": "C3", "linestyle": "-", "linewidth": 0.9, "marker": "s", "markersize": 3.5, "alpha": 0.8}
FIT_CURVE_STYLE = {**CURVE_STYLE, "color": "k", "linewidth": 1.8}


def fit_samples(control_points, knots, count: int = 200) -> tuple[np.ndarray, np.ndarray]:
    """(parameters (count,), points (count, d)) spread evenly over the domain of a B-spline, for drawing."""
    pts = as_points(control_points, "control_points")
    n = degree(pts, knots)
    a, b = domain(knots, n)
    ts = np.linspace(a, b, as_count(count, "count", minimum=2))
    return ts, de_boor(pts, knots, ts)


def plot_samples(ax, points, label: str | None = "samples", **style) -> Axes:
    """Draw planar sample points (M, 2) as blue dots, the notes' style. Notes §11.3."""
    check_axes(ax)
    pts = planar_points(points)
    ax.plot(pts[:, 0], pts[:, 1], **{**SAMPLE_STYLE, "label": label, **style})
    return finish_planar(ax)


def plot_fit(ax, control_points, knots, polygon: bool = True, label: str | None = "fitted curve",
             polygon_label: str | None = "control polygon", samples: int = 200, **style) -> Axes:
    """Draw a fitted planar B-spline: the curve (black) and, with `polygon`, its control polygon in red. Notes §11.3.

    control_points: (c, 2), knots: (c + n - 1,). `style` goes to the curve.
    """
    check_axes(ax)
    ctrl = planar_points(control_points, "control_points")
    _, curve = fit_samples(ctrl, knots, samples)
    ax.plot(curve[:, 0], curve[:, 1], **{**FIT_CURVE_STYLE, "label": label, **style})
    if polygon:
        ax.plot(ctrl[:, 0], ctrl[:, 1], **{**FIT_POLYGON_STYLE, "label": polygon_label})
    return finish_planar(ax)


def plot_residuals(ax, points, fitted, scale: float = 1.0, **style) -> Axes:
    """Draw the residual of every sample: a segment from Q_k to its curve point P(τ_k), stretched by `scale`.

    The segments lie on top of the curves and samples drawn so far, so that residuals along the curve stay visible.
    """
    check_axes(ax)
    pts = planar_points(points)
    on_curve = planar_points(fitted, "fitted")
    if on_curve.shape != pts.shape:
        raise ValueError(f"fitted: expected one curve point per sample, shape {pts.shape}, got {on_curve.shape}")
    ends = pts + scale * (on_curve - pts)
    style = {"colors": "C1", "linewidths": 1.2, "zorder": 2.5, **style}
    segments = LineCollection(np.stack([pts, ends], axis=1), **style)
    ax.add_collection(segments)
    ax.update_datalim(np.vstack([pts, ends]))
    ax.autoscale_view()
    return finish_planar(ax)


def box_corners(points, half_width, frame="axes") -> np.ndarray:
    """Corners (M, 4, 2) of the tolerance boxes of planar samples: along the axes or tangent and normal. Notes §11.4.2.

    half_width: a number, (M,) or (M, 2): the half sizes along x and y ("axes"),
    or along the tangent and the normal of `approximation.estimate_frames` ("curve"),
    or along the unit tangents and normals (M, 2) of a given pair (tangents, normals).
    """
    pts = planar_points(points)
    h = as_float_array(half_width, "half_width")
    h = np.broadcast_to(h[:, None] if h.ndim == 1 else h, (len(pts), 2))
    if frame == "axes":
        first, second = np.array([[1.0, 0.0]]), np.array([[0.0, 1.0]])
    elif isinstance(frame, str) and frame == "curve":
        first, second = estimate_frames(pts)
    elif not isinstance(frame, str) and len(frame) == 2:
        first, second = (planar_points(e, "frame") for e in frame)
        if first.shape != pts.shape or second.shape != pts.shape:
            raise ValueError(f"frame: expected (tangents, normals) of shape {pts.shape}, got {first.shape} "
                             f"and {second.shape}")
    else:
        raise ValueError(f"frame: expected 'axes', 'curve' or a pair (tangents, normals), got {frame!r}")
    u, v = h[:, :1] * first, h[:, 1:] * second
    return np.stack([pts - u - v, pts + u - v, pts + u + v, pts - u + v], axis=1)


def plot_boxes(ax, points, half_width, frame="axes", active=None, **style) -> Axes:
    """Draw the tolerance box of every planar sample (see `box_corners`); boxes in `active` (indices) are shaded."""
    check_axes(ax)
    corners = box_corners(points, half_width, frame)
    faces = np.full(len(corners), "none", dtype=object)
    if active is not None:
        faces[np.asarray(active, dtype=int)] = "#f4c7a1"
    boxes = PolyCollection(corners, **{"facecolors": list(faces), "edgecolors": "C1", "linewidths": 0.8, **style})
    ax.add_collection(boxes)
    ax.update_datalim(corners.reshape(-1, 2))
    ax.autoscale_view()
    return finish_planar(ax)


def plot_error_measures(ax, values, grid=None) -> Axes:
    """Draw e(A) = Σ (A - g)² and e(A) = max |A - g| over A, each over its minimum, and the minimisers. Notes §11.1.

    Both errors are divided by their smallest value, so that the two curves share
    one axis and their minimisers (the mean and the midrange) stand side by side.
    """
    check_axes(ax)
    g = as_float_array(values, "values")
    if g.ndim != 1 or len(g) < 2 or np.ptp(g) == 0:
        raise ValueError(f"values: expected at least two different numbers, got {g.tolist()}")
    low, high = g.min() - 0.25 * np.ptp(g), g.max() + 0.25 * np.ptp(g)
    a = np.linspace(low, high, 401) if grid is None else as_float_array(grid, "grid")
    l2 = ((a[:, None] - g) ** 2).sum(axis=1)
    linf = np.abs(a[:, None] - g).max(axis=1)
    mean, midrange = g.mean(), (g.max() + g.min()) / 2
    l2_best, linf_best = ((mean - g) ** 2).sum(), np.ptp(g) / 2
    ax.plot(a, l2 / l2_best, color="C0", label=r"$\sum (A-g)^2$ / its minimum")
    ax.plot(a, linf / linf_best, color="C3", label=r"$\max |A-g|$ / its minimum")
    ax.plot([mean], [1.0], "o", color="C0")
    ax.plot([midrange], [1.0], "s", color="C3")
    # Both labels under the common minimum 1, where neither curve goes: the smaller minimiser's to the left.
    mean_left = mean <= midrange
    for value, text, color, on_left in ((mean, f"mean {mean:.3g}", "C0", mean_left),
                                        (midrange, f"midrange {midrange:.3g}", "C3", not mean_left)):
        ax.annotate(text, (value, 1.0), xytext=(-4 if on_left else 4, -13), textcoords="offset points", color=color,
                    fontsize=8, ha="right" if on_left else "left", va="center")
    ax.plot(g, np.full(len(g), 0.0), "|", color="0.3", markersize=12)
    ax.set_ylim(-0.2, 4.0)
    ax.set_xlabel("A")
    ax.set_ylabel("error / smallest error")
    return ax


def plot_curvature(ax, control_points, knots, samples: int = 300, **style) -> Axes:
    """Draw the curvature κ(t) of a planar B-spline over its domain (signed: positive turning left). Notes §11.4."""
    check_axes(ax)
    ctrl = planar_points(control_points, "control_points")
    n = degree(ctrl, knots)
    a, b = domain(knots, n)
    ts = np.linspace(a, b, as_count(samples, "samples", minimum=2))
    ax.plot(ts, spline_curvature(ctrl, knots, ts), **{"color": "C2", "linewidth": 1.3, **style})
    ax.axhline(0.0, color="0.8", linewidth=0.8, zorder=0)
    ax.set_xlabel("t")
    ax.set_ylabel("curvature κ(t)")
    return ax
