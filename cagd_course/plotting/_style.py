"""What every figure of the course shares: default styles, the Axes check, equal aspect with x/y labels."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes

from cagd_ref._validation import as_points

POLYGON_STYLE = {"color": "0.45", "linestyle": "--", "linewidth": 1.0, "marker": "o", "markersize": 5}
CURVE_STYLE = {"color": "C0", "linewidth": 2.0}


def check_axes(ax) -> None:
    if not isinstance(ax, Axes):
        raise TypeError(f"ax: expected a matplotlib Axes, got {type(ax).__name__}")


def planar_points(points, name: str = "points") -> np.ndarray:
    pts = as_points(points, name)
    if pts.shape[1] != 2:
        raise ValueError(f"{name}: expected planar points of shape (n+1, 2), got shape {pts.shape}")
    return pts


def finish_planar(ax: Axes, adjustable: str = "datalim") -> Axes:
    """Equal aspect and x/y axis labels (kept if the caller already set some).

    "datalim" grows the limits to keep the axes box; "box" (for fixed limits)
    reshapes the box instead.
    """
    ax.set_aspect("equal", adjustable=adjustable)
    if not ax.get_xlabel():
        ax.set_xlabel("x")
    if not ax.get_ylabel():
        ax.set_ylabel("y")
    return ax


def hide_from_legend(ax: Axes) -> Axes:
    """Keep every series drawn so far on `ax` out of legends (matplotlib skips labels starting with "_").

    For a panel whose series an earlier legend of the same figure already names.
    """
    check_axes(ax)
    for artist in [*ax.lines, *ax.patches, *ax.collections]:
        label = artist.get_label()
        if label and not label.startswith("_"):  # legends skip empty labels already
            artist.set_label("_" + label)
    return ax
