"""Figures of floating-point error: the d-bit number line, the chaotic band of an evaluation, boxes widened by roundoff.

Notes chapter 13. `plot_number_line` draws the d-bit numbers around a real x
with its neighbours and rounding interval; `plot_band` draws values computed
in floating point against the exact curve, with the guaranteed radius and
the a-priori bound as shaded bands (Figure 13.1); `plot_box` draws one
axis-parallel box centre ± radius (Figure 13.2). Every function draws into
the matplotlib Axes `ax` it is given and returns it.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.patches import Rectangle

from cagd_ref import floating
from cagd_ref._validation import as_count, as_float_array, as_scalar, as_vector

from ._style import check_axes

__all__ = ["COMPUTED_STYLE", "EXACT_STYLE", "plot_number_line", "plot_band", "plot_box", "box_limits"]

COMPUTED_STYLE = {"color": "C3", "marker": ".", "markersize": 3, "linewidth": 0.6}
EXACT_STYLE = {"color": "black", "linewidth": 1.6}
RADIUS_COLOR = "C0"
BOUND_COLOR = "C2"
# More d-bit numbers than this between the ends of a number line would merge into a grey bar.
MAX_TICKS = 400


def plot_number_line(ax, x, d: int, span: float = 3.0) -> Axes:
    """The d-bit numbers near x as ticks, x itself, its two neighbours and the interval of the one it rounds to.

    x: a nonzero number; d: 1..50 significant bits; span: how many spacings
    either side of x to show. The interval is the exact set of reals that
    round to fl(x) (`float_interval(..., exact=True)`). Notes §13.
    """
    check_axes(ax)
    value = as_scalar(x, "x")
    low, high = floating.neighbours(value, as_count(d, "d", 1))
    rounded = floating.round_to_bits(value, d)
    width = as_scalar(span, "span") * (high - low)
    left, right = min(low, value) - width, max(high, value) + width
    # Towards 0 the numbers crowd without end: stop at half of x.
    left, right = (max(left, value / 2), right) if value > 0 else (left, min(right, value / 2))
    grid = _grid(left, right, d)
    ax.axhline(0, color="0.3", linewidth=0.8)
    ax.vlines(grid, -0.25, 0.25, color="0.3", linewidth=1.0)
    lo, hi = floating.float_interval(rounded, d, exact=True)
    ax.add_patch(Rectangle((lo, -0.12), hi - lo, 0.24, color="C2", alpha=0.3, label="reals that round to fl(x)"))
    ax.plot([low, high], [0, 0], "o", color="C0", markersize=7, label="neighbours of x")
    ax.plot([rounded], [0], "s", color="C2", markersize=8, label="fl(x)")
    ax.plot([value], [0], "v", color="C3", markersize=10, label="x")
    ax.set_xlim(left, right)
    ax.set_ylim(-1, 1)
    ax.set_yticks([])
    ax.ticklabel_format(axis="x", useOffset=True)
    ax.set_xlabel(f"the {d}-bit numbers (ticks) near x")
    return ax


def _grid(left: float, right: float, d: int) -> np.ndarray:
    """The d-bit numbers in [left, right] (at most MAX_TICKS of them), walking from neighbour to neighbour."""
    ticks = []
    value = floating.round_to_bits(left, d)
    if value < left:
        value = floating.neighbours(left, d)[1]
    while value <= right and len(ticks) < MAX_TICKS:
        ticks.append(value)
        value = floating.neighbours(value, d)[1]
    return np.array(ticks)


def plot_band(ax, t, values, exact, radius=None, bound=None, centre: float = 0.0) -> Axes:
    """Values computed in floating point (dots) over the exact curve (line), the radius as a band, the bound as lines.

    t, values, exact: (k,) the parameters, computed and exact values; radius:
    None or (k,) the guaranteed radius around the computed values (shaded);
    bound: None or (k,) the a-priori bound around the exact values (dashed
    lines; when it is far wider than the band the frame keeps to the band and
    says so). The t axis is shown relative to `centre` (Figure 13.1 zooms in
    on t = 1/4). Notes §13.
    """
    check_axes(ax)
    ts = as_vector(t, "t")
    v, e = as_float_array(values, "values"), as_float_array(exact, "exact")
    if v.shape != ts.shape or e.shape != ts.shape:
        raise ValueError(f"values, exact: expected shape {ts.shape} like t, got {v.shape} and {e.shape}")
    x = ts - centre
    low, high = np.minimum(v, e), np.maximum(v, e)
    if radius is not None:
        r = as_float_array(radius, "radius")
        ax.fill_between(x, v - r, v + r, color=RADIUS_COLOR, alpha=0.25, linewidth=0, label="computed ± radius")
        low, high = np.minimum(low, v - r), np.maximum(high, v + r)
    ax.plot(x, v, label="computed", **COMPUTED_STYLE)
    ax.plot(x, e, label="exact", **EXACT_STYLE)
    ax.axhline(0, color="0.5", linewidth=0.6)
    bottom, top = float(low.min()), float(high.max())
    pad = 0.08 * (top - bottom) or 1.0
    if bound is not None:
        b = as_float_array(bound, "bound")
        ax.plot(x, e + b, "--", color=BOUND_COLOR, linewidth=1.2, label="exact ± a-priori bound")
        ax.plot(x, e - b, "--", color=BOUND_COLOR, linewidth=1.2)
        if np.nanmax(b) > 3 * max(abs(bottom), abs(top)):
            ax.annotate(f"a-priori bound ±{np.nanmax(b):.2g}: off the frame", (0.02, 0.03), xycoords="axes fraction",
                        fontsize=8, color=BOUND_COLOR)
        else:
            bottom, top = min(bottom, float(np.nanmin(e - b))), max(top, float(np.nanmax(e + b)))
    ax.set_ylim(bottom - pad, top + pad)
    ax.set_xlabel("t" if centre == 0 else f"t − {centre:g}")
    ax.ticklabel_format(axis="both", style="sci", scilimits=(-3, 3))
    return ax


def plot_box(ax, centre, radius, **style) -> Axes:
    """The axis-parallel box centre ± radius of a planar point, (2,) each (Figure 13.2). Notes §12, §13."""
    check_axes(ax)
    c, r = as_vector(centre, "centre", 2), as_vector(radius, "radius", 2)
    options = {"fill": False, "linewidth": 1.6, **style}
    ax.add_patch(Rectangle(tuple(c - r), *(2 * r), **options))
    ax.update_datalim([c - r, c + r])
    ax.autoscale_view()
    return ax


def box_limits(*boxes, margin: float = 0.15) -> tuple[tuple[float, float], tuple[float, float]]:
    """x and y limits holding every (centre, radius) box, with a relative margin."""
    lows = np.array([np.asarray(c) - np.asarray(r) for c, r in boxes])
    highs = np.array([np.asarray(c) + np.asarray(r) for c, r in boxes])
    low, high = lows.min(axis=0), highs.max(axis=0)
    pad = margin * (high - low).max()
    return (low[0] - pad, high[0] + pad), (low[1] - pad, high[1] + pad)
