"""Figures of chapter 19: implicit curves with their singular points, tangent cones, pencil parametrizations
and silhouettes (the discriminant in x drawn under the curve).

Every function draws into the matplotlib Axes `ax` it is given and returns it. Curves are coefficient arrays
c[i, j] of xⁱ yʲ, as `cagd_ref.plane_curves` uses them.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from numpy.polynomial import polynomial as P

from cagd_ref import plane_curves
from cagd_ref._validation import as_float_array, as_interval, as_vector

from ._style import check_axes
from .algebraic import plot_implicit
from .pencils import plot_line, set_box

__all__ = ["plot_curve", "plot_tangent_cone", "plot_pencil_ray", "plot_parametrization", "plot_discriminant",
           "fill_equal"]

SINGULAR_STYLE = {"color": "C3", "marker": "o", "markersize": 7, "linestyle": "none", "zorder": 6}


def _coefficients(c) -> np.ndarray:
    array = as_float_array(c, "c")
    if array.ndim != 2:
        raise ValueError(f"c: expected a 2-D array c[i, j] of x^i y^j, got shape {array.shape}")
    return array


def plot_curve(ax, c, xlim, ylim, resolution: int = 360, **style) -> Axes:
    """Draw f(x, y) = 0 over the box xlim × ylim (a contour of the polynomial c). Notes §19.1.

    An isolated real point (an acnode) is no contour: mark it with `plot_tangent_cone` or by hand.
    `label=` adds a legend entry drawn in the curve's colour, width and line style (`linestyles=`).
    """
    check_axes(ax)
    coeffs = _coefficients(c)
    label = style.pop("label", None)
    options = {"colors": "C0", "linewidths": 2.0, **style}
    plot_implicit(ax, lambda u, v: P.polyval2d(u, v, coeffs), xlim, ylim, resolution=resolution, **options)
    if label is not None:
        # A contour set has no legend entry: an empty line in the same style stands in for it.
        dashes = options.get("linestyles", "-")
        ax.plot([], [], color=np.atleast_1d(options["colors"])[0], linewidth=np.atleast_1d(options["linewidths"])[0],
                linestyle=dashes[0] if isinstance(dashes, list) else dashes, label=label)
    return set_box(ax, xlim, ylim)


def plot_tangent_cone(ax, c, point, xlim, ylim, **style) -> Axes:
    """Mark the singular point and draw its real tangent lines (the factors of the tangent cone). Notes §19.2."""
    check_axes(ax)
    p = as_vector(point, "point", dim=2)
    for a, b in plane_curves.tangent_directions(c, p):
        plot_line(ax, [b, -a, a * p[1] - b * p[0]], xlim, ylim, **{"color": "C1", "linewidth": 1.3,
                                                                      "linestyle": "--", **style})
    ax.plot(*p, **SINGULAR_STYLE)
    return set_box(ax, xlim, ylim)


def plot_pencil_ray(ax, point, t, xlim, ylim, **style) -> Axes:
    """Draw the line y - y0 = t (x - x0) of the pencil through `point`. Notes §19.5, Figures 19.6 and 19.7."""
    p = as_vector(point, "point", dim=2)
    return plot_line(ax, [t, -1.0, p[1] - t * p[0]], xlim, ylim, **{"color": "C2", "linewidth": 1.4, **style})


def plot_parametrization(ax, xyw, interval=(-4.0, 4.0), samples: int = 600, **style) -> Axes:
    """Draw the rational curve (X/W, Y/W) of rows (3, n+1) over `interval`, broken where W changes sign. §19.5.

    interval=None draws it for every real t and t = ∞: the rows are evaluated in
    homogeneous form at (cos θ, sin θ), t = tan θ, for θ over [-π/2, π/2], so no
    arc of large |t| is left out.
    """
    check_axes(ax)
    rows = as_float_array(xyw, "xyw")
    if rows.ndim != 2 or rows.shape[0] != 3:
        raise ValueError(f"xyw: expected rows X, Y, W of shape (3, n+1), got shape {rows.shape}")
    if interval is None:
        theta = np.linspace(-np.pi / 2, np.pi / 2, samples)
        cos, sin = np.cos(theta), np.sin(theta)
        n = rows.shape[1] - 1
        powers = np.stack([sin**k * cos ** (n - k) for k in range(n + 1)], axis=-1)  # t^k cos^n θ
        values = powers @ rows.T
    else:
        lo, hi = as_interval(interval, "interval")
        ts = np.linspace(lo, hi, samples)
        values = np.stack([P.polyval(ts, rows[k]) for k in range(3)], axis=-1)
    w = values[:, 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        xy = values[:, :2] / w[:, None]
    xy[np.abs(w) < 1e-9 * np.abs(values).max()] = np.nan
    xy[1:][np.sign(w[1:]) != np.sign(w[:-1])] = np.nan
    ax.plot(*xy.T, **{"color": "C0", "linewidth": 2.0, **style})
    return ax


def plot_discriminant(ax, discriminant, xlim, roots=(), scale: str = "linear", **style) -> Axes:
    """The graph of Res_y(f, f_y) (ascending in x) over xlim, its real roots marked. Notes §19.4.

    The roots are the x of vertical tangents and of singular points (and of
    vertical asymptotes, or of a repeated complex y). scale="linear" draws
    R / max |R| over xlim, R = Res_y(f, f_y); scale="symlog" draws R itself on a
    symmetric logarithmic axis (linear within 10⁻⁵ max |R| of zero), where a
    simple root is a crossing and a double root a touch, however large R is
    elsewhere.
    """
    check_axes(ax)
    d = as_float_array(discriminant, "discriminant")
    x0, x1 = as_interval(xlim, "xlim")
    if scale not in ("linear", "symlog"):
        raise ValueError(f"scale: expected 'linear' or 'symlog', got {scale!r}")
    xs = np.linspace(x0, x1, 800)
    values = P.polyval(xs, d)
    size = np.abs(values).max() or 1.0
    ax.axhline(0.0, color="0.6", linewidth=0.8)
    if scale == "linear":
        ax.set_yscale("linear")
        ax.plot(xs, values / size, **{"color": "C4", "linewidth": 2.0, "label": "Res_y(f, f_y) / max |Res_y|", **style})
    else:
        threshold = 1e-5 * size
        ax.set_yscale("symlog", linthresh=threshold)
        ax.plot(xs, values, **{"color": "C4", "linewidth": 2.0, "label": "Res_y(f, f_y), symmetric log scale", **style})
        high = int(np.ceil(np.log10(size)))
        middle = (high + int(np.ceil(np.log10(threshold)))) // 2
        ax.set_ylim(-(10.0**high), 10.0**high)
        ticks = [-(10.0**high), -(10.0**middle), 0.0, 10.0**middle, 10.0**high]
        ax.set_yticks(ticks, [f"$-10^{{{high}}}$", f"$-10^{{{middle}}}$", "0", f"$10^{{{middle}}}$",
                              f"$10^{{{high}}}$"])
        ax.minorticks_off()
    roots = np.asarray(roots, dtype=float)
    roots = roots[(roots >= x0) & (roots <= x1)]
    ax.plot(roots, np.zeros_like(roots), "o", color="C3", markersize=6)
    ax.set_xlim(x0, x1)
    ax.set_xlabel("x")
    return ax


def fill_equal(ax, xlim, ylim) -> tuple[tuple[float, float], tuple[float, float]]:
    """Equal aspect without reshaping the axes box: widen the shorter side of the box xlim × ylim about its centre.

    A panel drawn under this one with the same x limits then lines up with it
    column for column (an equal aspect that reshaped the box would make the
    upper panel narrower than the lower). The axes must have their final
    position (a fixed layout, not a constrained one). Returns the limits set.
    """
    check_axes(ax)
    x0, x1 = as_interval(xlim, "xlim")
    y0, y1 = as_interval(ylim, "ylim")
    box = ax.get_position()
    width, height = ax.figure.get_size_inches()
    ratio = (box.height * height) / (box.width * width)  # height over width of the box, in inches
    if (y1 - y0) < ratio * (x1 - x0):
        grow = (ratio * (x1 - x0) - (y1 - y0)) / 2
        y0, y1 = y0 - grow, y1 + grow
    else:
        grow = ((y1 - y0) / ratio - (x1 - x0)) / 2
        x0, x1 = x0 - grow, x1 + grow
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal", adjustable="datalim")
    return (x0, x1), (y0, y1)
