"""Explorers of chapter 17 of the notes (algebraic geometry): implicit curves, common roots, intersections.

The implicit-curve explorer edits a rational cubic (its inner control points
and weights) and draws its implicit equation over the plane, the two sign
regions shaded, with a probe point whose value f(x, y) and parameter
t = num/den are read out. The common-root detector builds two cubics from
their roots and shows the Bézout matrix, its rank, the resultant both ways and
the GCD. The intersection explorer implicitizes one rational cubic, substitutes
the other and shows the degree-9 polynomial with its roots beside the curves.
"""

from __future__ import annotations

import html

import ipywidgets as widgets
import numpy as np

from cagd_ref import algebra, bezier
from cagd_ref.roots import bernstein_roots

from ..plotting.curves import plot_bezier, plot_control_polygon
from ..plotting.implicit_curves import (
    plot_extended_curve,
    plot_intersection_polynomial,
    plot_polynomials,
    plot_sign_regions,
)
from ._base import Explorer, TwoPanels, _fmt, _slider

__all__ = [
    "implicit_curve_explorer",
    "common_root_explorer",
    "implicit_intersection_explorer",
    "ImplicitCurveExplorer",
    "CommonRootExplorer",
    "ImplicitIntersectionExplorer",
]

# The loop cubic of §17.6 (double point (1, 0) at t = 0 and t = 2) and the two rational cubics of §17.8.
LOOP = np.array([[1.0, 0.0], [5.0, 0.0], [5.0, 2.0], [4.0, 3.0]])
CURVE_1 = np.array([[4.0, 1.0], [5.0, 6.0], [5.0, 0.0], [6.0, 4.0]])
CURVE_2 = np.array([[7.0, 4.0], [1.0, 2.0], [9.0, 2.0], [3.0, 4.0]])
WEIGHTS = np.array([1.0, 2.0, 2.0, 1.0])
COORDINATE = {"min": -2.0, "max": 8.0, "step": 0.1, "readout_format": ".1f"}
WEIGHT = {"min": 0.2, "max": 4.0, "step": 0.1, "readout_format": ".1f"}
ROOT = {"min": -3.0, "max": 3.0, "step": 0.25, "readout_format": ".2f"}


def _matrix_html(matrix: np.ndarray) -> str:
    rows = "".join("<tr>" + "".join(f"<td style='padding:0 6px;text-align:right'>{v:.4g}</td>" for v in row)
                   + "</tr>" for row in matrix)
    return f"<table style='border-left:1px solid;border-right:1px solid'>{rows}</table>"


def _polynomial_text(c: np.ndarray, var: str = "t") -> str:
    terms = [f"{v:+.4g}" + (f" {var}" if k == 1 else f" {var}^{k}" if k else "")
             for k, v in enumerate(c) if abs(v) > 1e-12][::-1]
    return " ".join(terms).lstrip("+") if terms else "0"


# ---------------------------------------------------------------- implicit curve and inversion


class ImplicitCurveExplorer(Explorer):
    """A rational cubic, its implicit curve f = 0 with the sign regions, a probe point inverted. Notes §17.6-17.7."""

    figsize = (6.6, 5.2)

    def __init__(self, points=None, probe=(4.375, 1.125)):
        base = LOOP if points is None else np.asarray(points, dtype=float)
        if base.shape != (4, 2):
            raise ValueError(f"points: the explorer edits a cubic, expected shape (4, 2), got {base.shape}")
        self.ends = base[[0, 3]].copy()
        controls = {
            "x1": _slider(widgets.FloatSlider, "x₁", value=float(base[1, 0]), **COORDINATE),
            "y1": _slider(widgets.FloatSlider, "y₁", value=float(base[1, 1]), **COORDINATE),
            "x2": _slider(widgets.FloatSlider, "x₂", value=float(base[2, 0]), **COORDINATE),
            "y2": _slider(widgets.FloatSlider, "y₂", value=float(base[2, 1]), **COORDINATE),
            "w1": _slider(widgets.FloatSlider, "w₁", value=1.0, **WEIGHT),
            "w2": _slider(widgets.FloatSlider, "w₂", value=1.0, **WEIGHT),
            "px": _slider(widgets.FloatSlider, "probe x", value=float(probe[0]), **COORDINATE),
            "py": _slider(widgets.FloatSlider, "probe y", value=float(probe[1]), **COORDINATE),
        }
        super().__init__(controls)

    static_control = "w1"

    def compute(self, x1, y1, x2, y2, w1, w2, px, py) -> dict:
        points = np.array([self.ends[0], [x1, y1], [x2, y2], self.ends[1]])
        weights = np.array([1.0, w1, w2, 1.0])
        try:
            f = algebra.implicitize(points, weights)
            num, den = algebra.inversion(points, weights)
        except ValueError as err:
            raise ValueError(f"x1, y1, x2, y2: {err}") from None
        probe = np.array([px, py])
        value = algebra.implicit_eval(f, probe)
        # |f| against the size of its terms there: zero to rounding means the probe is on the curve.
        size = np.polynomial.polynomial.polyval2d(*np.maximum(np.abs(probe), 1.0), np.abs(f))
        try:
            t, singular = algebra.invert(points, probe, weights), False
        except ValueError:
            t, singular = None, True
        back = None
        if t is not None and np.isfinite(t):
            try:
                back = bezier.evaluate(points, t, weights)
            except ValueError:
                back = None
        return {"points": points, "weights": weights, "implicit": f, "num": num, "den": den, "probe": probe,
                "value": float(value), "relative_value": float(abs(value) / size), "t": t, "singular": singular,
                "back": back}

    def draw(self, ax, state: dict) -> None:
        points = state["points"]
        low = np.minimum(points.min(axis=0), state["probe"])
        high = np.maximum(points.max(axis=0), state["probe"])
        # A square window around the polygon and the probe, so that equal axes need no change of limits.
        half = (high - low).max() / 2 + 1.5
        lo, hi = (low + high) / 2 - half, (low + high) / 2 + half
        plot_sign_regions(ax, state["implicit"], (lo[0], hi[0]), (lo[1], hi[1]), resolution=100)
        plot_control_polygon(ax, points, labels=True, alpha=0.7)
        plot_extended_curve(ax, points, state["weights"], interval=(-1.0, 2.0), label="P(t), t in [0, 1]")
        ax.plot(*state["probe"], "s", color="black", markersize=7, label="probe (x, y)")
        if state["back"] is not None:
            ax.plot(*state["back"], "o", color="C2", markersize=6, label="P(num/den)")
        ax.set_xlim(lo[0], hi[0])
        ax.set_ylim(lo[1], hi[1])
        ax.set_aspect("equal", adjustable="box")
        ax.set_title("implicit cubic: f < 0 blue, f > 0 orange", fontsize=10)
        ax.legend(fontsize=8, loc="upper left")

    def describe(self, state: dict) -> str:
        lines = [f"f(probe) = {state['value']:.4g} (relative {state['relative_value']:.1e}: "
                 + ("on the curve" if state["relative_value"] < 1e-9 else "off the curve") + ")"]
        if state["singular"]:
            lines.append("inversion: num = den = 0, a double point (two parameters reach it)")
        else:
            lines.append(f"inversion: t = num/den = {state['t']:.6g}"
                         + ("" if state["back"] is None else f", and P(t) = {_fmt(state['back'])}"))
        num, den = state["num"], state["den"]
        lines.append(f"t = ({num[1, 0]:.4g} x {num[0, 1]:+.4g} y {num[0, 0]:+.4g}) / "
                     f"({den[1, 0]:.4g} x {den[0, 1]:+.4g} y {den[0, 0]:+.4g})")
        return "<br>".join(lines)


def implicit_curve_explorer(points=None, probe=(4.375, 1.125)) -> ImplicitCurveExplorer:
    """Sliders for the inner control points and weights of a cubic and a probe point: its implicit curve. §17.6.

    points: (4, 2), the cubic to start from (default: the loop cubic of §17.6,
    whose ends stay fixed). `update` returns {"points" (4, 2), "weights" (4,),
    "implicit" (4, 4) c[i, j] of xⁱ yʲ, "num", "den" (2, 2) of t = num/den,
    "probe" (2,), "value" f(probe), "relative_value", "t" (None at a double
    point), "singular", "back" P(t) or None}.
    """
    return ImplicitCurveExplorer(points, probe)


# ---------------------------------------------------------------- the common-root detector


class CommonRootExplorer(Explorer):
    """Two cubics from their roots: the Bézout matrix, its rank, both resultants and the GCD. Notes §17.3-17.4."""

    figsize = (6.4, 4.2)

    def __init__(self, f_roots=(1.0, 2.0, 3.0), g_roots=(1.0, 2.0, -1.0), g_lead: float = 2.0):
        controls = {f"f{k}": _slider(widgets.FloatSlider, f"f root {k + 1}", value=float(v), **ROOT)
                    for k, v in enumerate(f_roots)}
        controls |= {f"g{k}": _slider(widgets.FloatSlider, f"g root {k + 1}", value=float(v), **ROOT)
                     for k, v in enumerate(g_roots)}
        controls["g_lead"] = _slider(widgets.FloatSlider, "g leading", value=float(g_lead), min=0.5, max=3.0,
                                     step=0.5, readout_format=".1f")
        super().__init__(controls)

    static_control = "g0"

    def compute(self, f0, f1, f2, g0, g1, g2, g_lead) -> dict:
        P = np.polynomial.polynomial
        f = P.polyfromroots([f0, f1, f2])
        g = g_lead * P.polyfromroots([g0, g1, g2])
        matrix = algebra.bezout_matrix(f, g)
        count = algebra.common_root_count(f, g)
        return {
            "f": f,
            "g": g,
            "bezout": matrix,
            "bezout_determinant": float(np.linalg.det(matrix)),
            "resultant": algebra.resultant(f, g),
            "root_product": algebra.root_product([f0, f1, f2], [g0, g1, g2], 1.0, g_lead),
            "rank": 3 - count,
            "common_count": count,
            "gcd": algebra.poly_gcd(f, g),
            "common_roots": algebra.common_roots(f, g),
        }

    def draw(self, ax, state: dict) -> None:
        plot_polynomials(ax, [state["f"], state["g"]], labels=("f", "g"), common=state["common_roots"])
        ax.set_ylim(-12, 12)
        count = state["common_count"]
        ax.set_title(f"{count} common root{'s' if count != 1 else ''}: rank of the Bézout matrix {state['rank']}",
                     fontsize=10)
        ax.legend(fontsize=8, loc="upper left")

    def describe(self, state: dict) -> str:
        return (
            f"f(t) = {html.escape(_polynomial_text(state['f']))}<br>g(t) = {html.escape(_polynomial_text(state['g']))}"
            f"<br>Bézout matrix:{_matrix_html(state['bezout'])}"
            f"det Bez = {state['bezout_determinant']:.6g} (Bézout's convention, the notes'; for two cubics -Res)<br>"
            f"Res(f, g) = {state['resultant']:.6g} (Sylvester) = a³b³ ∏(fᵢ − gⱼ) = {state['root_product']:.6g}<br>"
            f"rank {state['rank']}: {state['common_count']} common root(s); "
            f"gcd = {html.escape(_polynomial_text(state['gcd']))}"
        )


def common_root_explorer(f_roots=(1.0, 2.0, 3.0), g_roots=(1.0, 2.0, -1.0), g_lead: float = 2.0
                         ) -> CommonRootExplorer:
    """Sliders for the roots of two cubics (and g's leading coefficient): do they share a root? Notes §17.3-17.4.

    `update` returns {"f", "g" (4,) ascending, "bezout" (3, 3),
    "bezout_determinant", "resultant" (Sylvester), "root_product", "rank",
    "common_count" (3 - rank), "gcd" (monic), "common_roots" (real, sorted)}.
    """
    return CommonRootExplorer(f_roots, g_roots, g_lead)


# ---------------------------------------------------------------- intersection by implicitization


class ImplicitIntersectionExplorer(TwoPanels, Explorer):
    """Two rational cubics, their intersections numbered by t, and g(u) = f_P(Q(u)) with its roots. Notes §17.8."""

    def __init__(self, w1: float = 2.0, w2: float = 2.0, dx: float = 0.0, dy: float = 0.0):
        controls = {
            "w1": _slider(widgets.FloatSlider, "Q: w₁", value=w1, **WEIGHT),
            "w2": _slider(widgets.FloatSlider, "Q: w₂", value=w2, **WEIGHT),
            "dx": _slider(widgets.FloatSlider, "Q: shift x", value=dx, min=-2.0, max=2.0, step=0.05,
                          readout_format=".2f"),
            "dy": _slider(widgets.FloatSlider, "Q: shift y", value=dy, min=-2.0, max=2.0, step=0.05,
                          readout_format=".2f"),
        }
        super().__init__(controls)

    static_control = "dy"

    def compute(self, w1, w2, dx, dy) -> dict:
        q = CURVE_2 + [dx, dy]
        q_weights = np.array([1.0, w1, w2, 1.0])
        g = algebra.intersection_polynomial(CURVE_1, q, WEIGHTS, q_weights)
        hits = algebra.intersect_implicit(CURVE_1, q, WEIGHTS, q_weights)
        return {"p": CURVE_1, "q": q, "p_weights": WEIGHTS, "q_weights": q_weights, "polynomial": g,
                "u_roots": bernstein_roots(g), "hits": hits,
                "points": bezier.evaluate(CURVE_1, hits[:, 0], WEIGHTS) if len(hits) else np.zeros((0, 2))}

    def draw(self, ax, state: dict) -> None:
        plot_bezier(ax, state["p"], state["p_weights"], color="C0", linewidth=2, label="P (implicitized)")
        plot_bezier(ax, state["q"], state["q_weights"], color="C1", linewidth=2, label="Q (substituted)")
        for k, point in enumerate(state["points"], start=1):
            ax.plot(*point, "o", color="C3", markersize=5)
            # alternate above and below: neighbours along the curves may lie close together
            ax.annotate(str(k), point, xytext=(3, 4) if k % 2 else (3, -11), textcoords="offset points",
                        fontsize=8)
        ax.set_title(f"{len(state['hits'])} intersections with t, u in [0, 1]", fontsize=10)
        ax.legend(fontsize=8, loc="upper left")
        ax.set(xticks=[], yticks=[], xlabel="", ylabel="")
        lower = self.lower_axes()
        plot_intersection_polynomial(lower, state["polynomial"], state["u_roots"])
        # above the panel, in the gap under the curves, so that it hides no part of the graph or the polygon
        lower.legend(fontsize=8, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=3, frameon=False)

    def describe(self, state: dict) -> str:
        rows = "".join(f"<tr><td>{k}</td><td>{t:.4f}</td><td>{_fmt(p)}</td><td>{u:.4f}</td></tr>"
                       for k, ((t, u), p) in enumerate(zip(state["hits"], state["points"]), start=1))
        extra = len(state["u_roots"]) - len(state["hits"])
        return (f"g(u) has degree {len(state['polynomial']) - 1} and {len(state['u_roots'])} roots in [0, 1]"
                + (f" ({extra} of them on P beyond t in [0, 1])" if extra > 0 else "")
                + f"<table><tr><th>#</th><th>t on P</th><th>point</th><th>u on Q</th></tr>{rows}</table>")


def implicit_intersection_explorer(w1: float = 2.0, w2: float = 2.0, dx: float = 0.0, dy: float = 0.0
                                   ) -> ImplicitIntersectionExplorer:
    """Sliders for Q's inner weights and a shift of Q: the §17.8 cubics, their intersections and g(u). Notes §17.8.

    `update` returns {"p", "q" (4, 2), "p_weights", "q_weights" (4,),
    "polynomial" (10,) Bernstein coefficients of g, "u_roots", "hits" (k, 2)
    rows (t, u), "points" (k, 2)}.
    """
    return ImplicitIntersectionExplorer(w1, w2, dx, dy)
