"""Figures of root finding in Bernstein form: explicit curves with their hulls, marching steps, conditioning.

Notes chapter 9. A polynomial y(t) = Σ y_i B_i^n on [t0, t1] is drawn as its
explicit Bézier curve (t across, y up) with the control points
(t0 + i/n (t1 - t0), y_i) and their convex hull, which is where the root finders
look. Every function draws into the matplotlib Axes `ax` it is given and returns
it; the axes keep their natural (unequal) aspect, since t and y have different
units.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.patches import Polygon

from cagd_ref._validation import as_float_array, as_interval, as_vector
from cagd_ref.bezier import explicit_bezier
from cagd_ref.blending_properties import convex_hull
from cagd_ref.polynomials import bernstein_horner

from ._style import POLYGON_STYLE, check_axes

__all__ = [
    "plot_explicit",
    "mark_roots",
    "plot_march_step",
    "plot_derivative_look",
    "derivative_name",
    "plot_root_errors",
    "plot_conditioning",
]

HULL_COLOR = "C2"
ROOT_STYLE = {"marker": "*", "markersize": 13, "color": "C3", "linestyle": "none", "zorder": 5}
AXIS_STYLE = {"color": "0.55", "linewidth": 0.9}
METHOD_STYLES = ({"color": "C0", "marker": "o"}, {"color": "C3", "marker": "s"}, {"color": "C1", "marker": "^"})


def plot_explicit(ax, coeffs, interval=(0, 1), hull: bool = True, polygon: bool = True, curve: bool = True,
                  color: str = "C0", label: str | None = None, samples: int = 200, alpha: float = 1.0,
                  polygon_color: str | None = None, polygon_label: str | None = None) -> Axes:
    """The explicit Bézier curve y = Σ y_i B_i^n on `interval`, its control points and their convex hull. Notes §2.15.

    coeffs: (n+1,). `label` names the curve in a legend; the hull is shaded
    lightly (the region where the graph, and so every root, must lie) and the
    t axis is drawn so that the crossings show. `polygon_color` and
    `polygon_label` colour and name the control polygon (grey and unnamed by default).
    """
    check_axes(ax)
    y = as_vector(coeffs, "coeffs")
    t0, t1 = as_interval(interval)
    points = explicit_bezier(y, (t0, t1))
    ax.axhline(0.0, **AXIS_STYLE)
    if hull and len(y) >= 2 and np.ptp(points[:, 1]) > 0:
        ax.add_patch(Polygon(convex_hull(points), closed=True, facecolor=HULL_COLOR, alpha=0.14 * alpha,
                             edgecolor=HULL_COLOR, linewidth=0.9))
    if polygon:
        style = {**POLYGON_STYLE, "markersize": 4, "alpha": alpha, "label": polygon_label}
        if polygon_color is not None:
            style["color"] = polygon_color
        ax.plot(*points.T, **style)
    if curve:
        s = np.linspace(0.0, 1.0, samples)
        ax.plot(t0 + (t1 - t0) * s, bernstein_horner(y, s), color=color, linewidth=2.0, alpha=alpha, label=label)
    ax.set_xlabel("t")
    return ax


def mark_roots(ax, ts, label: str | None = "roots", **style) -> Axes:
    """Stars on the t axis at the parameters `ts` (k,)."""
    check_axes(ax)
    t = as_float_array(ts, "ts").reshape(-1)
    ax.plot(t, np.zeros_like(t), **{**ROOT_STYLE, "label": label if t.size else None, **style})
    return ax


def plot_march_step(ax, steps, k: int, coeffs=None, interval=(0, 1)) -> Axes:
    """Convex hull marching after k steps (a panel of Figure 9.1): the piece f_[t_k, t1], its hull, t_(k+1). Notes §9.1.

    steps: the list from `cagd_ref.roots.hull_march_steps`; coeffs: the whole
    polynomial on `interval`, drawn faintly for reference. Earlier starts t_0 ..
    t_(k-1) are ticks on the axis; the roots found so far are stars; the
    crossing the step moves to is marked and labelled.
    """
    check_axes(ax)
    t0, t1 = as_interval(interval)
    step = steps[k]
    if coeffs is not None:
        plot_explicit(ax, coeffs, (t0, t1), hull=False, polygon=False, color="0.6", alpha=0.6,
                      label="f on the interval")
    plot_explicit(ax, step.coeffs, (step.start, t1), label=f"$f_{{[t_{{{k}}}, {t1:g}]}}$")
    starts = [s.start for s in steps[: k + 1]]
    ax.plot(starts, np.zeros(len(starts)), "|", color="0.25", markersize=12, label="$t_0, \\dots, t_k$")
    found = [s.root for s in steps[: k + 1] if s.root is not None]
    mark_roots(ax, found, label="roots so far")
    if step.crossing is not None:
        ax.axvline(step.crossing, color="C1", linewidth=1.2, linestyle=":")
        # left of the line, on the side of the axis the piece does not reach before t_(k+1)
        above = step.coeffs[0] > 0
        ax.annotate(f"$t_{{{k + 1}}}$ = {step.crossing:.6g}", (step.crossing, 0), xytext=(-4, -8 if above else 8),
                    textcoords="offset points", fontsize=8, color="C1", ha="right",
                    va="top" if above else "bottom")
    return ax


def plot_derivative_look(ax, step, coeffs=None, interval=(0, 1)) -> Axes:
    """One look of the §9.2 reconstruction (a panel like those of Figure 9.2): a derivative on a piece. Notes §9.2.

    step: a `cagd_ref.roots.BcomStep`. The piece's control polygon and hull are
    drawn over its interval; the roots found there are stars; the title says
    which derivative, where, its count of sign changes and the conclusion.
    coeffs, when given, is f^(order) on the whole interval, drawn faintly.
    """
    check_axes(ax)
    if coeffs is not None:
        plot_explicit(ax, coeffs, interval, hull=False, polygon=False, color="0.65", alpha=0.6)
    plot_explicit(ax, step.coeffs, step.interval, color=f"C{step.order}")
    mark_roots(ax, step.roots, label=None)
    name = derivative_name(step.order)
    a, b = step.interval
    following = derivative_name(step.order + 1)
    if step.action.startswith("split"):
        action = f"split at the roots of {following}"
    elif step.action == "monotone piece":  # monotone because the roots of the derivative cut it off
        action = f"cut at the roots of {following}: monotone"
    else:
        action = step.action
    found = ""
    if len(step.roots) == 1:
        found = f", at {step.roots[0]:.4g}" if step.action == "one root" else f", root {step.roots[0]:.4g}"
    ax.set_title(f"{name} on [{a:.3g}, {b:.3g}], V = {step.variations}:\n{action}{found}", fontsize=9)
    return ax


def derivative_name(order: int) -> str:
    """f, f′, f″, f‴, then f^(4), ...: the name of a derivative in titles and legends."""
    return "f" + "′" * order if order <= 3 else f"f^({order})"


def plot_root_errors(ax, exact, found: dict) -> Axes:
    """Each exact root's distance to the nearest computed one, per method, on a log scale. Notes ch. 9 ([FR87]).

    exact: (n,) real roots; found: {method name: computed roots (real or complex)}.
    """
    check_axes(ax)
    exact = as_vector(exact, "exact")
    for index, (name, roots) in enumerate(found.items()):
        roots = np.asarray(roots, dtype=complex).reshape(-1)
        errors = np.abs(roots[None, :] - exact[:, None]).min(axis=1) if roots.size else np.full(len(exact), np.nan)
        ax.plot(exact, np.maximum(errors, 1e-17), linestyle="-", linewidth=1.0, markersize=5,
                label=name, **METHOD_STYLES[index % len(METHOD_STYLES)])
    ax.set_yscale("log")
    ax.set_xlabel("exact root")
    ax.set_ylabel("error")
    return ax


def plot_conditioning(ax, degrees, errors: dict, highlight: int | None = None) -> Axes:
    """The largest root error against the degree, one line per method, log scale. Notes ch. 9 ([FR87]).

    degrees: (m,); errors: {method name: (m,) largest errors}; `highlight` marks one degree.
    """
    check_axes(ax)
    degrees = as_vector(degrees, "degrees")
    for index, (name, values) in enumerate(errors.items()):
        ax.plot(degrees, np.maximum(np.asarray(values, dtype=float), 1e-17), linewidth=1.2, markersize=4,
                label=name, **METHOD_STYLES[index % len(METHOD_STYLES)])
    if highlight is not None:
        ax.axvline(highlight, color="0.4", linewidth=1.0, linestyle="--")
    ax.set_yscale("log")
    ax.set_xlabel("degree n")
    ax.set_ylabel("largest root error")
    return ax
