"""Figures of free-form deformation (chapter 14): boxes, lattices, deformed grids, circles and text.

Shapes are polylines of shape (k, 2) with rows of NaN between their pieces
(one matplotlib line draws them all, which keeps explorers fast); FFD itself
refuses NaN, so `deform_polyline` moves the finite rows and keeps the breaks.
Glyph outlines come from matplotlib's `TextPath`: TrueType outlines are
quadratic Bézier curves (with straight pieces), so `glyph_segments` hands back
Bézier control polygons of degree 1 and 2, the curves of chapter 2.
"""

from __future__ import annotations

import numpy as np
from matplotlib.font_manager import FontProperties
from matplotlib.patches import Rectangle
from matplotlib.path import Path
from matplotlib.textpath import TextPath

from cagd_ref.bezier import evaluate
from cagd_ref.ffd import ffd, isoline_image

from ._style import check_axes, finish_planar

__all__ = [
    "BREAK",
    "grid_polyline",
    "circle_polyline",
    "glyph_segments",
    "glyph_polyline",
    "segments_polyline",
    "deform_polyline",
    "plot_box",
    "plot_lattice",
    "plot_polyline",
    "plot_deformed_grid",
    "plot_isoline_construction",
]

BREAK = np.full((1, 2), np.nan)
LATTICE_STYLE = {"color": "C3", "linewidth": 1.0, "linestyle": "--", "alpha": 0.7}
GRID_STYLE = {"color": "0.55", "linewidth": 0.7}
FONT = FontProperties(family="DejaVu Sans", weight="bold")


def _box(box) -> np.ndarray:
    corners = np.asarray(box, dtype=float)
    if corners.shape != (2, 2) or not np.all(corners[0] < corners[1]):
        raise ValueError(f"box: expected [[xmin, ymin], [xmax, ymax]] with xmin < xmax, ymin < ymax, got {box!r}")
    return corners


def _joined(pieces: list[np.ndarray]) -> np.ndarray:
    """Pieces (k_i, 2) as one polyline with a NaN row between consecutive pieces."""
    if not pieces:
        return np.zeros((0, 2))
    out = [pieces[0]]
    for piece in pieces[1:]:
        out += [BREAK, piece]
    return np.vstack(out)


# ---------------------------------------------------------------- shapes


def grid_polyline(box, columns: int = 8, rows: int = 6, samples: int = 60) -> np.ndarray:
    """The lines s = i/columns and t = j/rows of the box, each sampled at `samples` points, NaN between them."""
    (x0, y0), (x1, y1) = _box(box)
    u = np.linspace(0.0, 1.0, samples)
    verticals = [np.column_stack([np.full(samples, x0 + a * (x1 - x0)), y0 + u * (y1 - y0)])
                 for a in np.linspace(0.0, 1.0, columns + 1)]
    horizontals = [np.column_stack([x0 + u * (x1 - x0), np.full(samples, y0 + b * (y1 - y0))])
                   for b in np.linspace(0.0, 1.0, rows + 1)]
    return _joined(verticals + horizontals)


def circle_polyline(center, radius: float, samples: int = 200) -> np.ndarray:
    """A closed circle as a polyline of `samples` points."""
    angles = np.linspace(0.0, 2 * np.pi, samples)
    return np.asarray(center, dtype=float) + radius * np.column_stack([np.cos(angles), np.sin(angles)])


def glyph_segments(text: str, box, margin: float = 0.12) -> list[list[np.ndarray]]:
    """The outline of `text` fitted into the box: per contour, its Bézier control polygons (degree 1 or 2).

    The text is scaled uniformly to fill the box less a `margin` (a fraction of
    its width and height on each side) and centred in it.
    """
    corners = _box(box)
    path = TextPath((0, 0), text, size=1.0, prop=FONT)
    low, high = path.vertices.min(axis=0), path.vertices.max(axis=0)
    room = (corners[1] - corners[0]) * (1 - 2 * margin)
    scale = float(np.min(room / np.maximum(high - low, 1e-12)))
    offset = (corners[0] + corners[1]) / 2 - scale * (low + high) / 2
    contours: list[list[np.ndarray]] = []
    for segment, code in path.iter_bezier():
        if code == Path.MOVETO:
            contours.append([])
        elif segment.degree >= 1:
            contours[-1].append(offset + scale * np.asarray(segment.control_points, dtype=float))
    return [contour for contour in contours if contour]


def segments_polyline(contours: list[list[np.ndarray]], samples: int = 16) -> np.ndarray:
    """Contours of Bézier segments sampled at `samples` parameters per curved segment (2 per line), NaN between."""
    curved, straight = np.linspace(0.0, 1.0, samples), np.array([0.0, 1.0])
    pieces = []
    for contour in contours:
        parts = [evaluate(segment, curved if len(segment) > 2 else straight)[:-1] for segment in contour]
        parts.append(contour[-1][-1:])
        pieces.append(np.vstack(parts))
    return _joined(pieces)


def glyph_polyline(text: str, box, samples: int = 16, margin: float = 0.12) -> np.ndarray:
    """The outline of `text` in the box as one polyline (see `glyph_segments`, `segments_polyline`)."""
    return segments_polyline(glyph_segments(text, box, margin), samples)


def deform_polyline(polyline, lattice, box, weights=None) -> np.ndarray:
    """`ffd` of a polyline's points, its NaN breaks kept."""
    line = np.asarray(polyline, dtype=float)
    finite = np.all(np.isfinite(line), axis=1)
    moved = line.copy()
    moved[finite] = ffd(line[finite], lattice, box, weights)
    return moved


# ---------------------------------------------------------------- drawing


def plot_box(ax, box, label: str | None = "box", corners: bool = False, **style):
    """The deformation box as a thin rectangle; `corners` labels (Xmin, Ymin) and (Xmax, Ymax)."""
    check_axes(ax)
    (x0, y0), (x1, y1) = _box(box)
    options = {"fill": False, "edgecolor": "0.2", "linewidth": 1.2, "linestyle": ":"} | style
    ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, label=label, **options))
    if corners:
        ax.annotate("$(X_{\\min}, Y_{\\min})$", (x0, y0), xytext=(-6, -6), textcoords="offset points",
                    ha="right", va="top", fontsize=9)
        ax.annotate("$(X_{\\max}, Y_{\\max})$", (x1, y1), xytext=(6, 6), textcoords="offset points",
                    ha="left", va="bottom", fontsize=9)
    ax.update_datalim([(x0, y0), (x1, y1)])
    ax.autoscale_view()
    return finish_planar(ax)


def plot_lattice(ax, lattice, weights=None, labels: bool = False, highlight=None, legend: str | None = "lattice",
                 **style):
    """The lattice's rows and columns as dashed lines and its points as dots (sized by weight).

    labels: write P_ij next to every point; highlight: (i, j) of a point to ring.
    """
    check_axes(ax)
    grid = np.asarray(lattice, dtype=float)
    options = LATTICE_STYLE | style
    color = options["color"]
    lines = _joined([grid[i] for i in range(grid.shape[0])] + [grid[:, j] for j in range(grid.shape[1])])
    ax.plot(*lines.T, label=legend, **options)
    w = np.ones(grid.shape[:2]) if weights is None else np.asarray(weights, dtype=float)
    ax.scatter(*grid.reshape(-1, 2).T, s=18 * np.sqrt(w.ravel()) + 8, color=color, zorder=4)
    if labels:
        for i, j in np.ndindex(*grid.shape[:2]):
            ax.annotate(f"$P_{{{i}{j}}}$", grid[i, j], xytext=(4, 4), textcoords="offset points", fontsize=8,
                        color=color)
    if highlight is not None:
        ax.scatter(*grid[tuple(highlight)], s=160, facecolors="none", edgecolors="black", linewidths=1.5, zorder=5)
    return finish_planar(ax)


def plot_polyline(ax, polyline, **style):
    """A polyline with NaN breaks (a grid, a glyph outline) as one line."""
    check_axes(ax)
    ax.plot(*np.asarray(polyline, dtype=float).T, **({"color": "C0", "linewidth": 1.5} | style))
    return finish_planar(ax)


def plot_deformed_grid(ax, lattice, box, weights=None, columns: int = 8, rows: int = 6, samples: int = 60,
                       **style):
    """The images of the grid lines of the box under the FFD."""
    grid = deform_polyline(grid_polyline(box, columns, rows, samples), lattice, box, weights)
    return plot_polyline(ax, grid, **(GRID_STYLE | style))


def plot_isoline_construction(ax, lattice, value: float, direction: str = "s", weights=None,
                              samples: int = 100):
    """Figures 14.7 and 14.9: the row (or column) curves, their points at `value`, and the image curve they control.

    direction "s": the n+1 row curves H_j(s) (degree m) with H_j(value) marked, and
    the degree-n image of the line s = value; "t": the column curves V_i(t).
    """
    check_axes(ax)
    grid = np.asarray(lattice, dtype=float)
    w = np.ones(grid.shape[:2]) if weights is None else np.asarray(weights, dtype=float)
    if direction == "t":
        grid, w = grid.transpose(1, 0, 2), w.T
    name = "H" if direction == "s" else "V"
    u = np.linspace(0.0, 1.0, samples)
    kind = "row" if direction == "s" else "column"
    for j in range(grid.shape[1]):
        label = f"{kind} curves ${name}_{'j' if direction == 's' else 'i'}({direction})$" if j == 0 else None
        ax.plot(*evaluate(grid[:, j], u, w[:, j]).T, color="C2", linewidth=1.2, label=label)
    points, curve_weights = isoline_image(lattice, value, direction, weights)
    for j, point in enumerate(points):
        ax.annotate(f"${name}_{j}({value:g})$", point, xytext=(6, -4), textcoords="offset points", fontsize=8,
                    ha="left", va="top")
    ax.plot(*points.T, "s--", color="C1", markersize=6, linewidth=1, label="their points: control polygon")
    ax.plot(*evaluate(points, u, curve_weights).T, color="C1", linewidth=2.4,
            label=f"image of {direction} = {value:g} (degree {len(points) - 1})")
    return finish_planar(ax)
