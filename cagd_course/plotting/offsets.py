"""Figures of offset curves: offsets with their backward arcs and cusps, the cusp condition, circles of curvature.

Notes chapter 8. An offset P = Q + ρN runs along its base curve where
1 + ρκ > 0 and backwards where 1 + ρκ < 0, between two cusps; these helpers
draw the two kinds of arc in different styles and mark the cusps. Every
function draws into the matplotlib Axes `ax` it is given and returns it.
"""

from __future__ import annotations

import numpy as np
from matplotlib import colormaps
from matplotlib.axes import Axes
from matplotlib.patches import Circle, ConnectionPatch, Rectangle

from cagd_ref import bezier, offsets
from cagd_ref._validation import as_count, as_scalar

from ._style import check_axes, finish_planar, planar_points

__all__ = [
    "OFFSET_STYLE",
    "BACKWARD_STYLE",
    "CUSP_STYLE",
    "offset_samples",
    "draw_offset",
    "plot_offset",
    "plot_offsets",
    "draw_cusp_condition",
    "plot_cusp_condition",
    "plot_osculating_circle",
    "plot_evolute",
    "zoom_into",
]

OFFSET_STYLE = {"color": "C3", "linewidth": 1.8}
BACKWARD_STYLE = {"color": "C1", "linewidth": 1.8, "linestyle": (0, (4, 2))}
CUSP_STYLE = {"color": "black", "marker": "v", "markersize": 7, "linestyle": "none"}
BACKWARD_LABEL = "runs backwards (1 + ρκ < 0)"


def offset_samples(points, rho, weights=None, samples: int = 400) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The offset at `samples` even parameters: (ts (s,), points (s, 2), 1 + ρκ (s,)). Notes §8.

    Where the base curve stops (Q' = 0) the offset has no point: those rows
    are NaN, so a plot breaks the line there instead of failing.
    """
    pts = planar_points(points)
    rho = as_scalar(rho, "rho")
    samples = as_count(samples, "samples", minimum=2)
    ts = np.linspace(0.0, 1.0, samples)
    speed = np.linalg.norm(bezier.derivative(pts, ts, 1, weights), axis=1)
    moving = speed > offsets.ZERO_SPEED * max(speed.max(), 1.0)
    curve = np.full((samples, 2), np.nan)
    factor = np.full(samples, np.nan)
    if np.any(moving):
        curve[moving] = offsets.offset_point(pts, ts[moving], rho, weights)
        factor[moving] = 1 + rho * bezier.signed_curvature(pts, ts[moving], weights)
    return ts, curve, factor


def draw_offset(ax, curve, factor, cusp_points=None, legend: str | None = "offset", **style) -> Axes:
    """Draw sampled offset points (s, 2): solid where `factor` = 1 + ρκ >= 0, dashed where it is negative. Notes §8.

    `cusp_points` (k, 2) are marked with CUSP_STYLE. `legend` names the
    forward arcs (None: no legend entries at all); the backward arcs and the
    cusps get entries of their own when they appear, once per Axes.
    """
    check_axes(ax)
    shown = set(ax.get_legend_handles_labels()[1])
    curve = np.asarray(curve, dtype=float)
    factor = np.asarray(factor, dtype=float)
    forward = np.where((factor >= 0)[:, None], curve, np.nan)
    # A backward arc takes the samples on either side too, so that it meets the forward arcs at the cusps.
    backward = factor < 0
    backward[1:] |= factor[:-1] < 0
    backward[:-1] |= factor[1:] < 0
    ax.plot(*forward.T, **{**OFFSET_STYLE, "label": legend, **style})
    layer = {"zorder": style["zorder"]} if "zorder" in style else {}  # the backward arcs and cusps on the same layer

    def entry(text):
        return text if legend and text not in shown else None

    if np.any(factor < 0):
        ax.plot(*np.where(backward[:, None], curve, np.nan).T, **BACKWARD_STYLE, **layer, label=entry(BACKWARD_LABEL))
    if cusp_points is not None and len(cusp_points):
        ax.plot(*np.asarray(cusp_points).T, **CUSP_STYLE, **layer, label=entry("cusps"))
    return finish_planar(ax)


def plot_offset(ax, points, rho, weights=None, samples: int = 400, cusps: bool = True, legend: bool = True,
                **style) -> Axes:
    """Draw the offset at radius ρ: forward arcs solid, backward arcs (1 + ρκ < 0) dashed, cusps marked. Notes §8.

    `style` overrides the forward arcs' style (OFFSET_STYLE, e.g. `label=`);
    the backward arcs keep BACKWARD_STYLE and the cusps CUSP_STYLE.
    """
    pts = planar_points(points)
    _, curve, factor = offset_samples(pts, rho, weights, samples)
    found = offsets.offset_cusps(pts, rho, weights) if cusps else np.zeros(0)
    marks = offsets.offset_point(pts, found, rho, weights) if found.size else None
    name = style.pop("label", f"offset ρ = {float(rho):.3g}") if legend else None
    return draw_offset(ax, curve, factor, marks, legend=name, **style)


def plot_offsets(ax, points, radii, weights=None, samples: int = 300, cmap: str = "Reds", **style) -> Axes:
    """Draw a family of offsets, one per radius in `radii`, a darker red the larger |ρ|. Notes §8, Fig. 8.1."""
    check_axes(ax)
    radii = np.atleast_1d(np.asarray(radii, dtype=float))
    largest = np.abs(radii).max(initial=0.0) or 1.0
    colours = colormaps[cmap]
    for rho in radii:
        colour = colours(0.35 + 0.6 * abs(rho) / largest)
        plot_offset(ax, points, rho, weights, samples, legend=False, **{"color": colour, "linewidth": 1.3, **style})
    return ax


def draw_cusp_condition(ax, ts, factor, cusps=(), **style) -> Axes:
    """Draw the graph of 1 + ρκ sampled at ts, shaded where negative, with the cusps `cusps` on the t axis. Notes §8."""
    check_axes(ax)
    ts, factor = np.asarray(ts, dtype=float), np.asarray(factor, dtype=float)
    ax.plot(ts, factor, **{"color": "C3", "linewidth": 1.5, "label": "1 + ρκ(t)", **style})
    ax.axhline(0.0, color="0.4", linewidth=0.8)
    ax.fill_between(ts, factor, 0.0, where=factor < 0, color="C1", alpha=0.3, linewidth=0)
    ax.plot(np.asarray(cusps, dtype=float), np.zeros(len(cusps)), **CUSP_STYLE)
    ax.set_xlim(ts.min(initial=0.0), ts.max(initial=1.0))
    ax.set_xlabel("t")
    return ax


def plot_cusp_condition(ax, points, rho, weights=None, samples: int = 400, **style) -> Axes:
    """Graph of 1 + ρκ(t) on [0, 1]: the offset runs backwards where it is negative, its zeros are cusps. Notes §8."""
    pts = planar_points(points)
    ts, _, factor = offset_samples(pts, rho, weights, samples)
    return draw_cusp_condition(ax, ts, factor, offsets.offset_cusps(pts, rho, weights), **style)


def plot_osculating_circle(ax, points, t, weights=None, **style) -> Axes:
    """Draw the circle of curvature at t (radius 1/|κ|, centre on the concave side) and its centre. Notes §8."""
    check_axes(ax)
    pts = planar_points(points)
    t = as_scalar(t, "t")
    kappa = bezier.signed_curvature(pts, t, weights)
    if kappa == 0 or not np.isfinite(kappa):
        return ax  # a straight point (or a stop) has no circle of curvature to draw
    # The centre is on the left (-N) where κ > 0 and on the right where κ < 0: Q - N / κ in both cases.
    centre = bezier.evaluate(pts, t, weights) - offsets.offset_normal(pts, t, weights) / kappa
    circle = {"fill": False, "color": "C2", "linestyle": ":", "linewidth": 1.2, **style}
    ax.add_patch(Circle(tuple(centre), 1 / abs(kappa), **circle))
    ax.plot(*centre, "+", color=circle["color"], markersize=9)
    ax.update_datalim([centre - 1 / abs(kappa), centre + 1 / abs(kappa)])
    ax.autoscale_view()
    return ax


def plot_evolute(ax, points, t_range=(0.0, 1.0), weights=None, samples: int = 400, **style) -> Axes:
    """Draw the evolute, the curve of the centres of curvature Q - N/κ, over `t_range`: every cusp lies on it. Notes §8.

    Parameters where the curve hardly bends (the centre far away, |κ| below
    1e-6 of its largest value) are left out, so an inflection breaks the line.
    """
    check_axes(ax)
    pts = planar_points(points)
    t0, t1 = (as_scalar(v, "t_range") for v in t_range)
    samples = as_count(samples, "samples", minimum=2)
    ts = np.linspace(t0, t1, samples)
    kappa = bezier.signed_curvature(pts, ts, weights)
    bends = np.abs(kappa) > 1e-6 * np.abs(kappa).max(initial=0.0)
    centres = np.full((samples, 2), np.nan)
    if np.any(bends):
        centres[bends] = offsets.centre_of_curvature(pts, ts[bends], weights)
    ax.plot(*centres.T, **{"color": "C2", "linestyle": ":", "linewidth": 1.5, "label": "evolute (centres of curvature)",
                           **style})
    return ax


def zoom_into(ax, zoom, limits, **style) -> Axes:
    """Frame the region `limits` = ((x0, x1), (y0, y1)) on `ax` and show it, enlarged, in the Axes `zoom`.

    Draws the frame on `ax`, sets the limits of `zoom` (equal aspect: the panel
    shrinks to the frame's proportions) and joins the frame's corners to the
    zoom's nearest corners; returns `zoom`.
    """
    check_axes(ax)
    check_axes(zoom)
    (x0, x1), (y0, y1) = limits
    frame = {"edgecolor": "0.35", "linewidth": 1.0, **style}
    ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, **frame))
    zoom.set(xlim=(x0, x1), ylim=(y0, y1))
    zoom.set_aspect("equal", adjustable="box")
    for spine in zoom.spines.values():
        spine.set_edgecolor(frame["edgecolor"])
    # Join the two corners of the frame that face the zoom panel to the zoom panel's matching corners.
    right = zoom.get_position().x0 > ax.get_position().x1 - 1e-9
    corners = [(x1, y0), (x1, y1)] if right else [(x0, y0), (x1, y0)]
    targets = [(0, 0), (0, 1)] if right else [(0, 1), (1, 1)]
    for corner, target in zip(corners, targets):
        zoom.add_artist(ConnectionPatch(xyA=corner, coordsA=ax.transData, xyB=target, coordsB=zoom.transAxes,
                                        color=frame["edgecolor"], linewidth=0.8))
    return zoom
