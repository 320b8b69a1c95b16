"""Figures of lines as triples: pencils, parameter lines, moving lines and the points where they meet.

Notes chapter 18. A line is a triple (a, b, c), a x + b y + c = 0, and a point a
triple (X, Y, W); these helpers draw them inside a fixed box (a line is
infinite, so the box says how much of it to show). Every function draws into
the matplotlib Axes `ax` it is given and returns it.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection

from cagd_ref import moving_lines
from cagd_ref._validation import as_float_array, as_interval, as_vector

from ._style import check_axes, finish_planar

__all__ = [
    "LINE_STYLE",
    "AXIS_STYLE",
    "line_segments",
    "plot_line",
    "plot_lines",
    "plot_pencil",
    "plot_parameter_line",
    "plot_points",
    "set_box",
]

LINE_STYLE = {"color": "C0", "linewidth": 1.0, "alpha": 0.6}
AXIS_STYLE = {"color": "C3", "marker": "*", "markersize": 13, "linestyle": "none", "zorder": 5}


def _box(xlim, ylim) -> tuple[float, float, float, float]:
    x0, x1 = as_interval(xlim, "xlim")
    y0, y1 = as_interval(ylim, "ylim")
    return x0, x1, y0, y1


def line_segments(lines, xlim, ylim) -> np.ndarray:
    """The pieces (k, 2, 2) of lines (k, 3) that a box reaches, from far outside it to far outside it.

    A line with a = b = 0 (the line at infinity) or a zero triple has no
    piece in the plane: its row is NaN, so nothing is drawn for it.
    """
    array = as_float_array(lines, "lines").reshape(-1, 3)
    x0, x1, y0, y1 = _box(xlim, ylim)
    centre = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
    reach = 2 * np.hypot(x1 - x0, y1 - y0)
    normals = array[:, :2]
    sizes = np.linalg.norm(normals, axis=1)
    out = np.full((len(array), 2, 2), np.nan)
    ok = sizes > 1e-12 * np.abs(array).max(axis=1, initial=0.0)
    unit = normals[ok] / sizes[ok, None]
    offset = (array[ok, 2] / sizes[ok] + unit @ centre)[:, None]
    foot = centre - offset * unit  # the point of the line nearest to the box's centre
    along = np.column_stack([-unit[:, 1], unit[:, 0]])
    out[ok, 0], out[ok, 1] = foot - reach * along, foot + reach * along
    return out


def set_box(ax, xlim, ylim) -> Axes:
    """Fix the view to the box (lines reach beyond it), with equal aspect."""
    check_axes(ax)
    x0, x1, y0, y1 = _box(xlim, ylim)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    return finish_planar(ax, adjustable="box")


def plot_line(ax, line, xlim, ylim, label: str | None = None, **style) -> Axes:
    """Draw the line (a, b, c) across the box xlim × ylim. Notes §18.1."""
    check_axes(ax)
    segment = line_segments(as_vector(line, "line", dim=3), xlim, ylim)[0]
    ax.plot(*segment.T, **{**LINE_STYLE, "alpha": 1.0, "linewidth": 1.6, **style}, label=label)
    return set_box(ax, xlim, ylim)


def plot_lines(ax, lines, xlim, ylim, cmap: str | None = None, label: str | None = None, **style) -> Axes:
    """Draw many lines (k, 3) at once, optionally coloured in order along a colormap. Notes §18.2."""
    check_axes(ax)
    segments = line_segments(lines, xlim, ylim)
    options = {**LINE_STYLE, **style}
    color = options.pop("color")
    collection = LineCollection(segments, label=label, **options)
    if cmap is not None:
        collection.set_array(np.linspace(0.0, 1.0, len(segments)))
        collection.set_cmap(cmap)
    else:
        collection.set_color(color)
    ax.add_collection(collection)
    return set_box(ax, xlim, ylim)


def plot_pencil(ax, l0, l1, xlim, ylim, ts=None, cmap: str = "viridis", **style) -> Axes:
    """Draw the members (1-t) l0 + t l1 of a pencil at `ts` (default 0, 0.1, ..., 1) and its axis. Notes §18.2.1."""
    l0, l1 = as_vector(l0, "l0", dim=3), as_vector(l1, "l1", dim=3)
    ts = np.linspace(0.0, 1.0, 11) if ts is None else as_float_array(ts, "ts").ravel()
    plot_lines(ax, moving_lines.moving_line_eval([l0, l1], ts), xlim, ylim, cmap=cmap, **style)
    axis = np.cross(l0, l1)
    if abs(axis[2]) > 1e-12 * np.linalg.norm(axis):
        ax.plot(*(axis[:2] / axis[2]), **AXIS_STYLE)
    return set_box(ax, xlim, ylim)


def plot_parameter_line(ax, ends, ticks=None, label: str | None = "parameter line", offset=(5, 4),
                        **style) -> Axes:
    """Draw a parameter line P0 -> P1 (ends (2, 2)) with evenly spaced ticks labelled by t. Notes §18.2.1, Fig. 18.3.

    `offset` places the tick labels (points, from each mark); `label` names the line in a legend.
    """
    check_axes(ax)
    ends = as_float_array(ends, "ends")
    if ends.shape != (2, 2):
        raise ValueError(f"ends: expected the two end points (2, 2), got shape {ends.shape}")
    ticks = np.linspace(0.0, 1.0, 5) if ticks is None else as_float_array(ticks, "ticks").ravel()
    options = {"color": "C2", "linewidth": 2.0, **style}
    ax.plot(*ends.T, **options, label=label)
    marks = (1 - ticks)[:, None] * ends[0] + ticks[:, None] * ends[1]
    ax.plot(*marks.T, "|" if abs(ends[1, 1] - ends[0, 1]) < abs(ends[1, 0] - ends[0, 0]) else "_",
            color=options["color"], markersize=9)
    for t, mark in zip(ticks, marks):
        ax.annotate(f"{t:g}", mark, textcoords="offset points", xytext=tuple(offset), fontsize=8,
                    color=options["color"])
    return ax


def plot_points(ax, points, labels=None, offsets=None, **style) -> Axes:
    """Mark homogeneous points (k, 3) (those at infinity are skipped), with optional labels. Notes §18.1.

    `offsets`: one (dx, dy) in points per point, placing its label (default (6, 5) for all).
    """
    check_axes(ax)
    array = as_float_array(points, "points").reshape(-1, 3)
    finite = np.abs(array[:, 2]) > 1e-12 * np.abs(array).max(axis=1, initial=0.0)
    xy = array[finite, :2] / array[finite, 2:]
    ax.plot(*xy.T, **{"color": "black", "marker": "o", "markersize": 5, "linestyle": "none", **style})
    if labels is not None:
        shifts = [(6, 5)] * len(array) if offsets is None else [tuple(o) for o in offsets]
        kept = [shift for shift, keep in zip(shifts, finite) if keep]
        for text, point, shift in zip(np.asarray(labels, dtype=object)[finite], xy, kept):
            ax.annotate(str(text), point, textcoords="offset points", xytext=shift, fontsize=9)
    return ax
