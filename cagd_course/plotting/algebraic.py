"""Figures of implicit curves f(x, y) = 0: conics now, the algebraic curves of chapters 17-19 later."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes

from cagd_ref._validation import as_count, as_interval

from ._style import check_axes, finish_planar

__all__ = ["plot_implicit"]


def plot_implicit(ax, f, xlim, ylim, resolution: int = 300, **style) -> Axes:
    """Draw the zero set f(x, y) = 0 over the box xlim × ylim as a contour line. Notes §1.5.2, §1.6.

    `f` takes two arrays of equal shape and returns the values elementwise (it
    is called once, on a resolution × resolution grid). Pass `label=` for a
    legend entry and `colors=` / `linewidths=` as for `Axes.contour`.
    """
    check_axes(ax)
    if not callable(f):
        raise TypeError(f"f: expected a function f(x, y), got {type(f).__name__}")
    x0, x1 = as_interval(xlim, "xlim")
    y0, y1 = as_interval(ylim, "ylim")
    resolution = as_count(resolution, "resolution", minimum=2)
    x, y = np.meshgrid(np.linspace(x0, x1, resolution), np.linspace(y0, y1, resolution))
    values = np.broadcast_to(np.asarray(f(x, y), dtype=float), x.shape)
    legend = style.pop("label", None)
    options = {"colors": "C0", "linewidths": 2.0, **style}
    # A zero set that misses the box is an empty picture, not an error.
    if np.nanmin(values) <= 0 <= np.nanmax(values):
        ax.contour(x, y, values, levels=[0.0], **options)
    if legend is not None:
        # Contour sets carry no legend entry, so a line with no points stands in for it.
        ax.plot(
            [],
            [],
            color=np.atleast_1d(options["colors"])[0],
            linewidth=np.atleast_1d(options["linewidths"])[0],
            label=legend,
        )
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    return finish_planar(ax, adjustable="box")
