"""Figures of interval Bézier curves: control boxes, swept regions, corner curves, interval bands of functions.

Notes chapter 12. A planar interval Bézier curve is drawn as its control boxes
and the region its boxes [P](t) sweep (the union of many sampled boxes, which
needs no assumption about the shape of the region), with the centre curve and,
where asked, the corner curves that bound it (`envelope_pieces`). A scalar
interval polynomial is drawn as a band between p_min and p_max over t. Every
function draws into the matplotlib Axes `ax` it is given and returns it.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import PolyCollection
from matplotlib.patches import Rectangle

from cagd_ref import bezier
from cagd_ref import interval_bezier as ib
from cagd_ref._validation import as_count

from ._style import check_axes, finish_planar

__all__ = [
    "BOX_STYLE",
    "REGION_COLOR",
    "CORNER_COLORS",
    "box_patch",
    "plot_boxes",
    "plot_swept_region",
    "plot_corner_curves",
    "plot_interval_curve",
    "plot_interval_band",
]

BOX_STYLE = {"facecolor": "C1", "edgecolor": "C1", "alpha": 0.35, "linewidth": 1.2}
REGION_COLOR = "#c6dbef"
CORNER_COLORS = {"TL": "C3", "BR": "C3", "TR": "C2", "BL": "C2"}


def _planar(boxes) -> np.ndarray:
    array = np.asarray(boxes, dtype=float)
    if array.ndim != 3 or array.shape[1:] != (2, 2):
        raise ValueError(f"boxes: expected planar boxes of shape (n+1, 2, 2), got shape {array.shape}")
    return array


def box_patch(box, **style) -> Rectangle:
    """A matplotlib Rectangle for one planar box (2, 2): rows x and y, each (lo, hi)."""
    (x0, x1), (y0, y1) = np.asarray(box, dtype=float)
    return Rectangle((x0, y0), x1 - x0, y1 - y0, **{**BOX_STYLE, **style})


def plot_boxes(ax, boxes, labels: bool = True, label: str = "P", **style) -> Axes:
    """The control boxes (n+1, 2, 2) as rectangles joined by the dashed polygon of their centres, labelled [P_k]."""
    check_axes(ax)
    array = _planar(boxes)
    centres = array.mean(axis=2)
    ax.plot(centres[:, 0], centres[:, 1], "--", color="0.45", linewidth=1.0, zorder=2)
    for k, box in enumerate(array):
        ax.add_patch(box_patch(box, zorder=3, **style))
        ax.plot(*centres[k], ".", color="0.3", markersize=3, zorder=4)
        if labels:
            ax.annotate(f"[{label}$_{k}$]", box[:, 1], textcoords="offset points", xytext=(3, 3), fontsize=9)
    return finish_planar(ax)


def plot_swept_region(ax, boxes, interval=(0.0, 1.0), samples: int = 400, color: str = REGION_COLOR,
                      label: str | None = "swept region") -> Axes:
    """The region swept by [P](t) for t in `interval`: the union of `samples` boxes, filled in one colour."""
    check_axes(ax)
    samples = as_count(samples, "samples", minimum=2)
    t0, t1 = interval
    box = ib.interval_de_casteljau(_planar(boxes), np.linspace(t0, t1, samples))
    (x0, x1), (y0, y1) = box[:, 0].T, box[:, 1].T
    corners = np.stack([np.column_stack(c) for c in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))], axis=1)
    ax.add_collection(PolyCollection(corners, facecolors=color, edgecolors=color, linewidths=0.6, zorder=1,
                                     label=label))
    ax.update_datalim(corners.reshape(-1, 2))
    ax.autoscale_view()
    return ax


def plot_corner_curves(ax, boxes, samples: int = 120) -> Axes:
    """The two corner curves that bound the swept region on each piece of `envelope_pieces` (notes §12.2)."""
    check_axes(ax)
    array = _planar(boxes)
    corners = ib.corner_curves(array)
    shown = set()
    for t0, t1, pair in ib.envelope_pieces(array):
        ts = np.linspace(t0, t1, samples)
        for name in pair:
            xy = bezier.de_casteljau(corners[name], ts)
            legend = f"corner curves {pair[0]}/{pair[1]}" if pair not in shown else None
            ax.plot(xy[:, 0], xy[:, 1], color=CORNER_COLORS[name], linewidth=1.4, zorder=5, label=legend)
            shown.add(pair)
    return ax


def plot_interval_curve(ax, boxes, samples: int = 400, labels: bool = True, corners: bool = False) -> Axes:
    """A planar interval Bézier curve: its swept region, the centre curve and the control boxes (Fig. 12.1)."""
    array = _planar(boxes)
    plot_swept_region(ax, array, samples=samples)
    centre = bezier.de_casteljau(array.mean(axis=2), np.linspace(0, 1, 200))
    ax.plot(centre[:, 0], centre[:, 1], color="C0", linewidth=1.8, zorder=4, label="centre curve")
    if corners:
        plot_corner_curves(ax, array)
    return plot_boxes(ax, array, labels=labels)


def plot_interval_band(ax, coeffs, interval=(0.0, 1.0), samples: int = 300, f=None, relative_to=None,
                       color: str = "C0", label: str = "interval polynomial") -> Axes:
    """The band p_min(t) <= p(t) <= p_max(t) of a scalar interval polynomial (n+1, 2) over t in `interval`.

    f: optionally the function the band encloses, drawn on top. relative_to: a
    function subtracted from everything drawn (to see a band too thin to show
    at full scale, plot it relative to f itself).
    """
    check_axes(ax)
    a, b = interval
    t = np.linspace(a, b, as_count(samples, "samples", minimum=2))
    band = ib.interval_de_casteljau(coeffs, (t - a) / (b - a))
    shift = np.zeros_like(t) if relative_to is None else relative_to(t)
    ax.fill_between(t, band[:, 0] - shift, band[:, 1] - shift, color=color, alpha=0.3, linewidth=0, label=label)
    ax.plot(t, band[:, 0] - shift, color=color, linewidth=1.0)
    ax.plot(t, band[:, 1] - shift, color=color, linewidth=1.0)
    if f is not None:
        # Relative to f the function itself is the zero line: say so in its label.
        name = "f(t)" if relative_to is None else "f(t) itself (at 0)"
        ax.plot(t, f(t) - shift, color="black", linewidth=1.4, label=name)
    ax.set_xlabel("t")
    return ax
