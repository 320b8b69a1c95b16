"""Figures of vectors: arrows in the plane and in space (Notes chapter 1)."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.patches import FancyArrowPatch

from cagd_ref._validation import as_vector

from ._style import check_axes, finish_planar

__all__ = ["plot_vector"]


def plot_vector(ax, tail, vector, label: str | None = None, **style) -> Axes:
    """Draw the vector `vector` as an arrow from point `tail` (both (2,) on 2-D axes, (3,) on 3-D). Notes §1.1.

    `label` (mathtext allowed, e.g. "$\\mathbf{v}$") is written next to the arrow's head.
    """
    check_axes(ax)
    three_d = ax.name == "3d"
    dim = 3 if three_d else 2
    start = as_vector(tail, "tail", dim=dim)
    direction = as_vector(vector, "vector", dim=dim)
    head = start + direction
    color = style.pop("color", "C1")
    if three_d:
        ax.quiver(*start, *direction, color=color, arrow_length_ratio=0.12, **style)
    else:
        defaults = {"arrowstyle": "-|>", "mutation_scale": 15, "color": color, "linewidth": 1.5}
        arrow = FancyArrowPatch(start, head, **{**defaults, **style})
        ax.add_patch(arrow)
        ax.update_datalim(np.vstack([start, head]))
        ax.autoscale_view()
    if label is not None:
        # Nudge the label a little past the head so it does not sit on the arrow.
        offset = 0.06 * direction
        ax.text(*(head + offset), label, color=color, fontsize=11)
    return ax if three_d else finish_planar(ax)
