"""Figures of chapter 21: quads, their iso-lines (bilinear or rational), the pencils' axes, the fold, warped images.

Every function draws into the Axes it is given and returns it. Iso-lines are
sampled in homogeneous coordinates, so a line of a weighted map that runs
through infinity (W changes sign) is drawn as the two rays it really is.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes

from cagd_ref import quad_maps
from cagd_ref.surfaces import patch_point

from ._style import check_axes, finish_planar

__all__ = [
    "isoline_samples",
    "plot_quad",
    "plot_isolines",
    "plot_axes_points",
    "plot_fold",
    "course_image",
    "plot_warped",
]

CORNER_NAMES = {(0, 0): "Q00", (1, 0): "Q10", (1, 1): "Q11", (0, 1): "Q01"}
QUAD_STYLE = {"color": "black", "linewidth": 1.8}
S_COLOR, T_COLOR = "C0", "C3"


def isoline_samples(quad, weights=None, s=None, t=None, span=(0.0, 1.0), samples: int = 121) -> np.ndarray:
    """Points of iso-lines, (k, samples, 2), NaN where the line passes through infinity (a break in the drawing).

    Give the fixed values of exactly one parameter (`s` or `t`, a 1-D array);
    the other runs over `span`.
    """
    h = quad_maps.homogeneous_quad(quad, weights)
    run = np.linspace(*span, samples)
    fixed = np.atleast_1d(np.asarray(s if s is not None else t, dtype=float))
    grid_fixed, grid_run = np.repeat(fixed, samples), np.tile(run, len(fixed))
    pairs = (grid_fixed, grid_run) if s is not None else (grid_run, grid_fixed)
    hom = patch_point(h, *pairs).reshape(len(fixed), samples, 3)
    w = hom[:, :, 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        points = hom[:, :, :2] / w[:, :, None]
    # Where W changes sign the line runs through infinity: break it there.
    jump = np.zeros_like(w, dtype=bool)
    jump[:, 1:] = np.sign(w[:, 1:]) != np.sign(w[:, :-1])
    points[jump | (np.abs(w) < 1e-12)] = np.nan
    return points


def plot_quad(ax: Axes, quad, labels: bool = True, **style) -> Axes:
    """The quad's boundary Q00 -> Q10 -> Q11 -> Q01 and its corners, labelled Qij."""
    check_axes(ax)
    q = np.asarray(quad, dtype=float)
    cycle = [(0, 0), (1, 0), (1, 1), (0, 1), (0, 0)]
    ax.plot(*np.array([q[c] for c in cycle]).T, "o-", **{**QUAD_STYLE, "markersize": 4, **style})
    if labels:
        centre = q.reshape(4, 2).mean(axis=0)
        for key, name in CORNER_NAMES.items():
            away = q[key] - centre
            away = away / (np.linalg.norm(away) or 1.0)
            ax.annotate(name, q[key], xytext=tuple(10 * away), textcoords="offset points", ha="center",
                        va="center", fontsize=9)
    return finish_planar(ax, adjustable="box")


def plot_isolines(ax: Axes, quad, weights=None, values=(0.0, 0.25, 0.5, 0.75, 1.0), family: str = "t",
                  span=(0.0, 1.0), label: bool = True, **style) -> Axes:
    """The s- or t-iso-lines of the (weighted) map at `values`, the other parameter running over `span`."""
    check_axes(ax)
    if family not in ("s", "t"):
        raise ValueError(f"family: expected 's' or 't', got {family!r}")
    color = S_COLOR if family == "s" else T_COLOR
    lines = isoline_samples(quad, weights, **{family: values}, span=span)
    for k, line in enumerate(lines):
        ax.plot(*line.T, **{"color": color, "linewidth": 1.0, "alpha": 0.8, **style},
                label=f"{family}-iso-lines" if label and k == 0 else None)
    return ax


def plot_axes_points(ax: Axes, quad, names=("$A_s$", "$A_t$")) -> Axes:
    """The pencils' axes As and At where they are finite, labelled."""
    check_axes(ax)
    for axis, name, color in zip(quad_maps.pencil_axes(quad), names, (S_COLOR, T_COLOR)):
        if abs(axis[2]) > 1e-9 * np.abs(axis).max():
            point = axis[:2] / axis[2]
            ax.plot(*point, "*", color=color, markersize=12)
            ax.annotate(name, point, xytext=(6, 6), textcoords="offset points", color=color, fontsize=11)
    return ax


def plot_fold(ax: Axes, quad, span=(-1.0, 2.0), **style) -> Axes:
    """The fold of the bilinear map: the image of the line in (s, t) where its Jacobian vanishes (a conic's arc).

    The Jacobian (e + g t) × (f + g s) = e×f + (e×g) s + (g×f) t is linear in
    (s, t); its zero line is mapped onto the envelope of the iso-lines.
    """
    check_axes(ax)
    q = np.asarray(quad, dtype=float)
    e, f, g = q[1, 0] - q[0, 0], q[0, 1] - q[0, 0], q[0, 0] - q[1, 0] - q[0, 1] + q[1, 1]

    def cross(a, b):
        return a[0] * b[1] - a[1] * b[0]

    c0, cs, ct = cross(e, f), cross(e, g), cross(g, f)
    run = np.linspace(*span, 400)
    if abs(ct) >= abs(cs) and ct != 0:
        s, t = run, -(c0 + cs * run) / ct
    elif cs != 0:
        s, t = -(c0 + ct * run) / cs, run
    else:
        return ax  # a parallelogram: no fold
    ax.plot(*quad_maps.quad_map(q, s, t).T, **{"color": "C2", "linewidth": 2.0, "linestyle": "--",
                                              "label": "fold (Jacobian = 0)", **style})
    return ax


def course_image(size: int = 48) -> np.ndarray:
    """A small RGB test picture for warping, (size, size, 3): a checkerboard under a red "F" (its orientation shows).

    Row 0 is t = 0 and column 0 is s = 0, the layout of `cagd_ref.quad_maps.warp_image`.
    """
    n = int(size)
    if n < 8:
        raise ValueError(f"size: expected at least 8 pixels, got {size}")
    i, j = np.mgrid[0:n, 0:n] * 8 // n
    image = np.where(((i + j) % 2 == 0)[:, :, None], [0.93, 0.93, 0.98], [0.55, 0.7, 0.9])
    row, col = np.mgrid[0:n, 0:n] / n
    stem = (col > 0.25) & (col < 0.37) & (row > 0.15) & (row < 0.85)
    top = (row > 0.73) & (row < 0.85) & (col > 0.25) & (col < 0.75)
    middle = (row > 0.47) & (row < 0.58) & (col > 0.25) & (col < 0.6)
    image[stem | top | middle] = [0.8, 0.1, 0.1]
    return image


def plot_warped(ax: Axes, raster, covered, window, quad=None) -> Axes:
    """A raster from `warp_image` in its window (pixels without a pre-image left white), with the quad's outline."""
    check_axes(ax)
    picture = np.array(raster, dtype=float)
    mask = np.asarray(covered, dtype=bool)
    picture[~mask] = 1.0
    (x0, y0), (x1, y1) = np.asarray(window, dtype=float)
    ax.imshow(np.clip(picture, 0, 1), origin="lower", extent=(x0, x1, y0, y1), interpolation="nearest")
    if quad is not None:
        plot_quad(ax, quad, labels=False, linewidth=1.0, markersize=2)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    return finish_planar(ax, adjustable="box")
