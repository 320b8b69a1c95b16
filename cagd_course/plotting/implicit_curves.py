"""Figures of chapter 17: implicit equations of rational curves with their sign regions, curves beyond [0, 1],
the intersection polynomial of two curves with its Bernstein polygon, and polynomials with their roots."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.colors import ListedColormap
from matplotlib.ticker import FuncFormatter, NullLocator
from numpy.polynomial import polynomial as P

from cagd_ref import bezier
from cagd_ref._validation import as_float_array, as_interval

from ._style import check_axes, finish_planar
from .algebraic import plot_implicit
from .curves import bezier_samples

__all__ = [
    "plot_sign_regions",
    "plot_extended_curve",
    "plot_intersection_polynomial",
    "plot_polynomial_window",
    "plot_polynomials",
]

# Light colours of the two sides of an implicit curve: f < 0 and f > 0.
SIGN_COLOURS = ListedColormap(["#dbe7f5", "#f8e3d0"])


def _implicit(coeffs) -> np.ndarray:
    c = as_float_array(coeffs, "coeffs")
    if c.ndim != 2:
        raise ValueError(f"coeffs: expected a 2-D array c[i, j] of x^i y^j, got shape {c.shape}")
    return c


def plot_sign_regions(ax, coeffs, xlim, ylim, resolution: int = 240, label: str | None = "f(x, y) = 0",
                      **style) -> Axes:
    """Shade where f(x, y) < 0 (blue) and > 0 (orange) over xlim × ylim and draw f = 0. Notes §17.1.

    coeffs: c[i, j] of xⁱ yʲ (as `cagd_ref.algebra.implicitize` returns). The
    zero set is drawn by `plotting.algebraic.plot_implicit`; `style` goes to it.
    """
    check_axes(ax)
    c = _implicit(coeffs)
    x0, x1 = as_interval(xlim, "xlim")
    y0, y1 = as_interval(ylim, "ylim")
    x, y = np.meshgrid(np.linspace(x0, x1, resolution), np.linspace(y0, y1, resolution))
    values = P.polyval2d(x, y, c)
    ax.imshow(np.sign(values), extent=(x0, x1, y0, y1), origin="lower", cmap=SIGN_COLOURS, vmin=-1, vmax=1,
              interpolation="nearest", aspect="auto")
    options = {"colors": "C3", "linewidths": 1.6, **style}
    plot_implicit(ax, lambda u, v: P.polyval2d(u, v, c), xlim, ylim, resolution=resolution, label=label, **options)
    return ax


def plot_extended_curve(ax, points, weights=None, interval=(-1.0, 2.0), samples: int = 400, label: str = "P(t)",
                        extension_label: str | None = None, **style) -> Axes:
    """The curve for t in [0, 1] (solid) and beyond it over `interval` (dashed). Notes §17.1.

    A rational curve may run off to infinity outside [0, 1] (where its weight
    polynomial vanishes); `curves.bezier_samples` breaks the line there.
    `extension_label` names the dashed part in a legend (None: no entry).
    """
    check_axes(ax)
    lo, hi = as_interval(interval, "interval")
    options = {"color": "C0", "linewidth": 2.2, **style}
    named = False
    for a, b in ((lo, min(0.0, hi)), (max(1.0, lo), hi)):
        if b > a:
            # each dashed piece gets samples in proportion to its length (at least a quarter of them)
            count = max(samples // 4, int(samples * (b - a)))
            ax.plot(*bezier_samples(points, weights, (a, b), count).T,
                    **{**options, "linestyle": "--", "linewidth": 1.0,
                       "label": None if named else extension_label})
            named = True
    ax.plot(*bezier_samples(points, weights, (0.0, 1.0), samples).T, label=label, **options)
    return finish_planar(ax)


def plot_intersection_polynomial(ax, coeffs, roots=(), **style) -> Axes:
    """g(u) = Σ g_i B_i^N(u) on [0, 1] with its Bernstein control polygon and the roots marked. Notes §17.8, §9.

    The coefficients are divided by their largest magnitude (a degree-9
    polynomial's may be near 10⁸). The polygon can dwarf the graph (cancellation),
    so the value axis is signed-logarithmic (linear near 0): graph and polygon
    both stay on the panel and every sign change of either can be seen.
    """
    check_axes(ax)
    g = as_float_array(coeffs, "coeffs")
    scale = np.abs(g).max() or 1.0
    us = np.linspace(0.0, 1.0, 400)
    values = bezier.evaluate((g / scale)[:, None], us)[:, 0]
    ax.axhline(0.0, color="0.6", linewidth=0.8)
    ax.plot(np.linspace(0, 1, len(g)), g / scale, "o--", color="0.55", linewidth=0.9, markersize=3.5,
            label="Bernstein polygon")
    ax.plot(us, values, **{"color": "C2", "linewidth": 2.0, "label": "g(u) / max |gᵢ|", **style})
    roots = np.asarray(roots, dtype=float)
    if roots.size:
        ax.plot(roots, np.zeros_like(roots), "o", color="C3", markersize=5, label="roots in [0, 1]")
    ax.set_xlim(0, 1)
    # Linear within a small band around 0 (where the graph crosses), logarithmic beyond it.
    reach = np.abs(values).max()
    if reach > 0:
        band = reach / 30
        ax.set_yscale("symlog", linthresh=band, linscale=0.6)
        ax.set_ylim(-1.6, 1.6)
        ticks = [-1.0, -0.1, -0.01, 0.0, 0.01, 0.1, 1.0]
        ax.set_yticks([v for v in ticks if v == 0 or abs(v) > 3 * band], minor=False)
        ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
        ax.yaxis.set_minor_locator(NullLocator())
    ax.set_xlabel("u")
    return ax


def plot_polynomial_window(ax, coeffs, window, roots=(), **style) -> Axes:
    """g(u) = Σ g_i B_i^N(u) / max |g_i| over a part `window` of [0, 1], on a linear scale, roots marked. §17.8.

    The close-up of `plot_intersection_polynomial`: where two roots lie too close
    together to be told apart on [0, 1], this shows the graph between them.
    """
    check_axes(ax)
    g = as_float_array(coeffs, "coeffs")
    u0, u1 = as_interval(window, "window")
    scale = np.abs(g).max() or 1.0
    us = np.linspace(u0, u1, 300)
    ax.axhline(0.0, color="0.6", linewidth=0.8)
    ax.plot(us, bezier.evaluate((g / scale)[:, None], us)[:, 0], **{"color": "C2", "linewidth": 2.0, **style})
    roots = np.asarray(roots, dtype=float)
    roots = roots[(roots >= u0) & (roots <= u1)]
    ax.plot(roots, np.zeros_like(roots), "o", color="C3", markersize=5)
    ax.set_xlim(u0, u1)
    ax.set_xlabel("u")
    return ax


def plot_polynomials(ax, polys, window=(-3.5, 3.5), labels=("f", "g"), common=()) -> Axes:
    """Graphs of polynomials (ascending coefficients) over `window`, their real roots, common roots ringed. §17.3."""
    check_axes(ax)
    lo, hi = as_interval(window, "window")
    ts = np.linspace(lo, hi, 400)
    for k, (c, name) in enumerate(zip(polys, labels)):
        c = as_float_array(c, name)
        values = P.polyval(ts, c)
        ax.plot(ts, values, color=f"C{k}", linewidth=2, label=name)
        roots = P.polyroots(c) if np.count_nonzero(c[1:]) else np.zeros(0)
        real = roots[np.abs(roots.imag) < 1e-9].real
        real = real[(real >= lo) & (real <= hi)]
        ax.plot(real, np.zeros_like(real), "o", color=f"C{k}", markersize=6)
    common = np.asarray(common, dtype=float)
    if common.size:
        ax.plot(common, np.zeros_like(common), "o", markersize=14, markerfacecolor="none", markeredgecolor="C3",
                markeredgewidth=2, label="common root")
    ax.axhline(0.0, color="0.6", linewidth=0.8)
    ax.set_xlim(lo, hi)
    ax.set_xlabel("t")
    return ax
