"""Explorers of chapter 19 of the notes (plane algebraic curves): a double-point classifier that deforms a cubic
through crunode, cusp and acnode, the parametrization of a unicursal curve by a pencil of lines through a point of
multiplicity n - 1, and a curve's discriminant drawn under its silhouette.

The classifier is Figures 19.2-19.4 in one family, x³ + k x² - 3y² = 0: its
tangent cone k x² - 3y² at the origin has two real lines for k > 0, one double
line for k = 0 (Figure 19.3 exactly) and two complex ones for k < 0 (k = -3 is
Figure 19.4). The pencil explorer is Figures 19.6 and 19.7 with a t slider: the
line of slope t through the pencil's centre (a point of multiplicity n - 1) and
the one more point where it meets the curve. The silhouette explorer turns a curve and shows that the real roots of
Res_y(f, f_y) are where its outline, seen along y, has vertical tangents or
crosses itself.
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np
from numpy.polynomial import polynomial as P

from cagd_ref import plane_curves

from ..plotting.pencils import set_box
from ..plotting.singular_points import (
    SINGULAR_STYLE,
    fill_equal,
    plot_curve,
    plot_discriminant,
    plot_parametrization,
    plot_pencil_ray,
    plot_tangent_cone,
)
from ._base import Explorer, TwoPanels, _fmt, _slider, bare_axes

__all__ = [
    "double_point_kind_explorer",
    "pencil_parametrization_explorer",
    "silhouette_explorer",
    "DoublePointClassifier",
    "PencilParametrizationExplorer",
    "SilhouetteExplorer",
]


def _family(k: float) -> np.ndarray:
    """x³ + k x² - 3y²."""
    return np.array([[0.0, 0.0, -3.0], [0.0, 0.0, 0.0], [k, 0.0, 0.0], [1.0, 0.0, 0.0]])


SUPERSCRIPTS = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def _power(variable: str, k: int) -> str:
    """x, x², x³, ...; the empty string for k = 0."""
    return "" if k == 0 else variable if k == 1 else variable + str(k).translate(SUPERSCRIPTS)


def _sum(terms: list[tuple[float, str]]) -> str:
    """Coefficients with their monomials as a readable sum: 3a² − 3b², 1 + t², −5 − 6t; 0 when every one is 0."""
    text = ""
    for v, monomial in terms:
        if abs(v) <= 1e-12:
            continue
        size = f"{abs(v):.4g}"
        body = monomial if monomial and size == "1" else size + monomial
        sign = "−" if v < 0 else "+"
        text += (sign if sign == "−" else "") + body if not text else f" {sign} {body}"
    return text or "0"


def _polynomial(p, variable: str = "t") -> str:
    """Ascending coefficients p[k] of t^k as 1 + 2t + 3t²."""
    return _sum([(float(v), _power(variable, k)) for k, v in enumerate(np.ravel(p))])


def _quotient(p, w) -> str:
    """p(t)/w(t) as text: 3t² for w = 1, (−5 − 6t)/(1 + 2t), a sum in parentheses only where it needs them."""
    top, bottom = _polynomial(p), _polynomial(w)
    w = np.trim_zeros(np.ravel(np.asarray(w, dtype=float)), "b")
    if len(w) == 1 and w[0] == 1.0:
        return top
    wrap = [f"({text})" if " " in text else text for text in (top, bottom)]
    return f"{wrap[0]} / {wrap[1]}"


def _equation(c: np.ndarray) -> str:
    """c[i, j] of x^i y^j as x³ + 3x² − 3y² = 0, the highest degree first."""
    order = sorted(np.ndenumerate(c), key=lambda item: (-(item[0][0] + item[0][1]), -item[0][0]))
    return _sum([(float(v), _power("x", i) + _power("y", j)) for (i, j), v in order]) + " = 0"


# ---------------------------------------------------------------- crunode, cusp, acnode


class DoublePointClassifier(Explorer):
    """The cubic x³ + k x² - 3y² = 0 and its tangent cone at the origin, classified. Notes §19.2, Figs. 19.2-19.4."""

    BOX = ((-5.0, 4.0), (-4.5, 4.5))

    def __init__(self, k: float = 3.0):
        controls = {"k": _slider(widgets.FloatSlider, "k", value=k, min=-4.0, max=6.0, step=0.25,
                                 readout_format=".2f")}
        super().__init__(controls)

    def compute(self, k: float) -> dict:
        k = round(float(k), 10) + 0.0
        c = _family(k)
        cone = plane_curves.tangent_cone(c, (0.0, 0.0))
        a, b, cc = cone
        return {
            "k": k,
            "c": c,
            "tangent_cone": cone,
            "discriminant": float(b * b - 4 * a * cc),
            "kind": plane_curves.classify_double_point(c, (0.0, 0.0)),
            "directions": plane_curves.tangent_directions(c, (0.0, 0.0)),
        }

    def draw(self, ax, state: dict) -> None:
        box = self.BOX
        plot_curve(ax, state["c"], *box, label="x³ + k x² − 3y² = 0")
        plot_tangent_cone(ax, state["c"], (0.0, 0.0), *box)
        set_box(ax, *box)
        ax.legend(fontsize=8, loc="lower left")
        ax.set_title(f"k = {state['k']:g}: a {state['kind']} at the origin", fontsize=10)
        bare_axes(ax)

    def describe(self, state: dict) -> str:
        a, b, c = state["tangent_cone"]
        lines = {"crunode": "two real tangent lines (dashed)", "cusp": "one double tangent line, y = 0",
                 "acnode": "two complex tangent lines: an isolated real point"}[state["kind"]]
        return "<br>".join([
            f"tangent cone f̂₂(a, b) = {_sum([(a, 'a²'), (b, 'ab'), (c, 'b²')])} (the lowest part at the origin)",
            f"B² − 4AC = {_minus(format(state['discriminant'], '.3g'))}: {state['kind']}, {lines}",
        ])


def double_point_kind_explorer(k: float = 3.0) -> DoublePointClassifier:
    """Slider `k` of the cubic x³ + k x² - 3y² = 0: crunode (k > 0), cusp (k = 0), acnode (k < 0). Notes §19.2.

    `update` returns {"k", "c" the curve, "tangent_cone" (A, B, C), "discriminant" B² - 4AC,
    "kind", "directions" the unit directions of the real tangents}.
    """
    return DoublePointClassifier(k)


# ---------------------------------------------------------------- the pencil parametrization


CURVES = {
    "circle x² − 2x + y² (Fig. 19.6)": (np.array([[0.0, 0.0, 1.0], [-2.0, 0.0, 0.0], [1.0, 0.0, 0.0]]),
                                         (0.0, 0.0), ((-0.8, 2.8), (-1.6, 1.6))),
    "cubic x³ − 9x² − 3xy + 6y² (Fig. 19.7)": (np.array([[0, 0, 6, 0], [0, -3, 0, 0], [-9, 0, 0, 0], [1, 0, 0, 0]],
                                                          dtype=float), (0.0, 0.0), ((-4.5, 11.0), (-7.0, 8.0))),
    "cubic with double point (2, 3) (§19.5)": (np.array([[-21, 25, -9, 1], [46, -23, 3, 0], [-13, 3, 0, 0],
                                                          [1, 0, 0, 0]], dtype=float), (2.0, 3.0),
                                                ((-3.0, 7.0), (-2.0, 8.0))),
    "cubic with coefficients 1…7 (§19.5)": (np.array([[0, 0, 7, 4], [0, 6, 3, 0], [5, 2, 0, 0], [1, 0, 0, 0]],
                                                      dtype=float), (0.0, 0.0), ((-6.0, 3.0), (-4.0, 4.0))),
    "cusp x³ − 3y² (Fig. 19.3)": (np.array([[0, 0, -3], [0, 0, 0], [0, 0, 0], [1, 0, 0]], dtype=float),
                                  (0.0, 0.0), ((-1.5, 6.0), (-5.0, 5.0))),
    "acnode x³ − 3x² − 3y² (Fig. 19.4)": (np.array([[0, 0, -3], [0, 0, 0], [-3, 0, 0], [1, 0, 0]], dtype=float),
                                          (0.0, 0.0), ((-1.5, 9.0), (-8.0, 8.0))),
}


class PencilParametrizationExplorer(Explorer):
    """The line of slope t through the pencil's centre and the one more point where it meets the curve. §19.5."""

    def __init__(self, curve: str = "circle x² − 2x + y² (Fig. 19.6)", t: float = 0.5):
        controls = {
            "t": _slider(widgets.FloatSlider, "t = slope", value=t, min=-3.0, max=3.0, step=0.05,
                         readout_format=".2f"),
            "curve": widgets.Dropdown(description="curve", options=list(CURVES), value=curve),
        }
        super().__init__(controls)

    def compute(self, t: float, curve: str) -> dict:
        c, point, box = CURVES[curve]
        xyw = plane_curves.parametrize_by_pencil(c, point)
        try:
            xy = plane_curves.pencil_point(xyw, t)
        except ValueError:
            xy = None  # the line of slope t meets the curve only at infinity besides the point
        residual = None if xy is None else float(P.polyval2d(xy[0], xy[1], c) / np.abs(c).sum())
        return {"curve": curve, "c": c, "point": np.array(point), "t": float(t), "xyw": xyw, "xy": xy,
                "residual": residual, "box": box}

    def draw(self, ax, state: dict) -> None:
        box = state["box"]
        plot_curve(ax, state["c"], *box, colors="0.75", linewidths=5.0)
        # every t, t = ∞ included: a finite range of t would leave a gap in the curve next to the centre
        plot_parametrization(ax, state["xyw"], None, samples=2400, label="(X(t)/W(t), Y(t)/W(t))")
        plot_pencil_ray(ax, state["point"], state["t"], *box, label=_minus(f"y − y0 = {state['t']:.2f}(x − x0)"))
        ax.plot(*state["point"], **SINGULAR_STYLE)
        if state["xy"] is not None:
            ax.plot(*state["xy"], "o", color="C2", markersize=9, markeredgecolor="black")
        set_box(ax, *box)
        ax.legend(fontsize=8, loc="lower left")
        ax.set_title("one more intersection with each line of the pencil", fontsize=10)
        bare_axes(ax)

    def describe(self, state: dict) -> str:
        x, y, w = state["xyw"]
        where = "at infinity" if state["xy"] is None else f"{_fmt(state['xy'])}, f there {state['residual']:.1e}"
        centre = _minus(_fmt(state["point"]))
        return "<br>".join([
            f"{_equation(state['c'])}; the lines turn about the pencil's centre (x0, y0) = {centre}, "
            "a point of multiplicity n − 1",
            f"x(t) = {_quotient(x, w)},  y(t) = {_quotient(y, w)}",
            _minus(f"t = {state['t']:.2f}: the green point {where}"),
            f"the parametrization reaches (x0, y0) itself at {_through(state['xyw'], state['point'])}",
        ])


def _through(xyw: np.ndarray, point: np.ndarray) -> str:
    """The t at which the parametrization passes through the pencil's centre: the roots of f̂_(n-1)(1, t)."""
    low = point[0] * xyw[2] - xyw[0]  # f̂_(n-1)(1, t), padded
    nonzero = np.flatnonzero(np.abs(low) > 1e-12 * np.abs(xyw).max())
    if nonzero.size == 0 or nonzero[-1] == 0:
        return "t = ∞ only (the vertical line)"
    roots = np.polynomial.polynomial.polyroots(low[: nonzero[-1] + 1])
    texts = []
    for r in roots:
        if abs(r.imag) <= 1e-9 * max(1.0, abs(r)):
            text = f"{r.real:.3g}"
        else:
            text = f"{r.real:.3g} {'+' if r.imag > 0 else '−'} {abs(r.imag):.3g}i".replace("0 − ", "−").replace(
                "0 + ", "")
        texts.append(text)
    texts = [f"{text} (twice)" if texts.count(text) > 1 else text for text in dict.fromkeys(texts)]
    extra = ", and t = ∞" if nonzero[-1] < len(low) - 2 else ""
    return _minus("t = " + ", ".join(texts)) + extra + (" (complex: an isolated point)" if any(
        abs(r.imag) > 1e-9 * max(1.0, abs(r)) for r in roots) else "")


def pencil_parametrization_explorer(curve: str = "circle x² − 2x + y² (Fig. 19.6)",
                                    t: float = 0.5) -> PencilParametrizationExplorer:
    """Slider `t` (the slope of the line through the pencil's centre) and dropdown `curve`. Notes §19.5.

    `update` returns {"curve", "c", "point" the pencil's centre (multiplicity n - 1), "t", "xyw" (3, n+1)
    the parametrization, "xy" the curve's point on the line (None at infinity),
    "residual" f(xy) relative to the coefficients, "box"}.
    """
    return PencilParametrizationExplorer(curve, t)


# ---------------------------------------------------------------- discriminant and silhouette


SILHOUETTES = {
    # name: (the curve, the point it turns about, the box of the whole view, its double point or None, the half
    # width of the zoom about the double point). The boxes have the aspect of the upper panel (fill_equal).
    "cubic of §19.5": (np.array([[-21, 25, -9, 1], [46, -23, 3, 0], [-13, 3, 0, 0], [1, 0, 0, 0]], dtype=float),
                       (2.0, 3.0), ((-3.0, 7.0), (-0.6, 6.6)), (2.0, 3.0), 0.75),
    "crunode x³ + 9x² − 12y² (Fig. 19.2)": (np.array([[0, 0, -12], [0, 0, 0], [9, 0, 0], [1, 0, 0]], dtype=float),
                                            (-4.0, 0.0), ((-13.0, 5.0), (-6.5, 6.5)), (0.0, 0.0), 5.0),
    "circle of Fig. 19.5": (np.array([[-4, -15, 6], [-2, 0, 0], [6, 0, 0]], dtype=float), (1 / 6, 1.25),
                            ((-2.0, 2.4), (-0.3, 2.8)), None, None),
}
VIEWS = ("whole curve", "zoom on the double point")


class SilhouetteExplorer(TwoPanels, Explorer):
    """A curve turned about a point, with vertical lines at the real roots of Res_y(f, f_y). Notes §19.4.

    The two panels share their x axis column for column: the upper one keeps its equal aspect by widening its y
    range (`fill_equal`), never by narrowing its box. The lower panel draws Res_y(f, f_y) on a symmetric log
    scale.
    """

    figsize = (6.2, 6.6)

    def __init__(self, curve: str = "cubic of §19.5", angle: float = 0.0, view: str = "whole curve"):
        controls = {
            "angle": _slider(widgets.FloatSlider, "turn (°)", value=angle, min=-90.0, max=90.0, step=2.0,
                             readout_format=".0f"),
            "curve": widgets.Dropdown(description="curve", options=list(SILHOUETTES), value=curve),
            "view": widgets.Dropdown(description="view", options=list(VIEWS), value=view),
        }
        super().__init__(controls)

    def lower_axes(self):
        if getattr(self, "lower", None) is None:
            self.ax.set_position([0.1, 0.38, 0.86, 0.54])
            self.lower = self.figure.add_axes([0.1, 0.07, 0.86, 0.22])
        return self.lower

    def compute(self, angle: float, curve: str, view: str) -> dict:
        base, centre, box, double_point, half = SILHOUETTES[curve]
        phi = np.radians(angle)
        inverse = np.array([[np.cos(phi), np.sin(phi)], [-np.sin(phi), np.cos(phi)]])
        centre = np.asarray(centre)
        c = plane_curves.transform_implicit(base, inverse, centre - inverse @ centre)
        d = _without_noise(plane_curves.curve_discriminant(c))
        point = None
        if double_point is not None:  # where the turn takes it: p -> centre + R (p - centre)
            point = centre + inverse.T @ (np.asarray(double_point) - centre)
        roots, multiplicities = _real_roots(d, None if point is None else point[0])
        zoom = view == VIEWS[1] and point is not None
        if zoom:
            box = ((point[0] - half, point[0] + half), (point[1] - half, point[1] + half))
        return {"curve": curve, "angle": float(angle), "view": view, "c": c, "discriminant": d, "roots": roots,
                "multiplicities": multiplicities, "double_point": point, "zoom": zoom, "box": box}

    def draw(self, ax, state: dict) -> None:
        lower = self.lower_axes()  # first: the upper panel's box is final before its limits are fitted to it
        xlim, ylim = fill_equal(ax, *state["box"])
        plot_curve(ax, state["c"], xlim, ylim, resolution=480 if state["zoom"] else 360, label="f(x, y) = 0")
        ax.set_xlim(*xlim)
        ax.set_ylim(*ylim)
        ax.set_aspect("equal", adjustable="datalim")
        shown = [x for x in state["roots"] if xlim[0] <= x <= xlim[1]]
        for x in shown:
            ax.axvline(x, color="C3", linewidth=0.9, linestyle="--")
        if state["double_point"] is not None:
            ax.plot(*state["double_point"], **SINGULAR_STYLE)
        ax.legend(fontsize=8, loc=_quiet_corner(ax, shown))
        ax.set_title("vertical tangents and crossings are roots of Res_y(f, f_y)", fontsize=10)
        bare_axes(ax)
        plot_discriminant(lower, state["discriminant"], xlim, state["roots"], scale="symlog")
        for x in shown:
            lower.axvline(x, color="C3", linewidth=0.9, linestyle="--")
        lower.set_ylabel("Res_y(f, f_y)", fontsize=8)  # the readout names the scale
        lower.tick_params(labelsize=8)

    def describe(self, state: dict) -> str:
        roots = ", ".join(_minus(f"{x:.4g}") + ("" if m == 1 else f" ({MULTIPLE.get(m, f'{m}-fold')})")
                          for x, m in zip(state["roots"], state["multiplicities"])) or "none"
        return "<br>".join([
            f"Res_y(f, ∂f/∂y), a polynomial in x of degree {len(state['discriminant']) - 1}; real roots x = {roots}",
            "a simple root: a vertical tangent; a root of multiplicity 2 or more: a singular point (a double root at "
            "a crunode without a vertical tangent, a triple one at a cusp) or two vertical tangents over one x",
            "lower panel: Res_y(f, f_y) on a symmetric log scale (linear near 0), where a simple root is a crossing "
            "and a double root a touch",
        ])


# Rounding noise in Res_y(f, f_y): a turned curve's resultant has leading coefficients of about 1e-15 of its largest
# one where the exact ones are zero (the cubic of §19.5 has degree 4 at every angle, its f₃ being (x + y)³).
NEGLIGIBLE = 1e-10
# Exercise 19.4's rule 1: a root is real when |Im x| <= IMAGINARY max(1, |x|), and real roots closer than
# MERGE max(1, |x|) are one root (their mean), whose multiplicity is the number merged.
IMAGINARY, MERGE = 1e-5, 1e-7
# The curve's double point must make Res_y and its derivative this small (relative to the sizes of their terms) to
# be divided out as a double root.
DOUBLE_ROOT = 1e-9
MULTIPLE = {2: "double", 3: "triple"}


def _minus(text: str) -> str:
    """A number as text with the minus sign − instead of the hyphen."""
    return text.replace("-", "−")


def _without_noise(d: np.ndarray) -> np.ndarray:
    """d without the leading coefficients below NEGLIGIBLE times its largest: those are rounding, not degree."""
    d = np.asarray(d, dtype=float)
    kept = np.flatnonzero(np.abs(d) > NEGLIGIBLE * np.abs(d).max()) if d.size else np.zeros(0, dtype=int)
    return d[: kept[-1] + 1] if kept.size else d[:1]


def _real_roots(d: np.ndarray, double: float | None = None) -> tuple[np.ndarray, list[int]]:
    """The distinct real roots of d, sorted, and their multiplicities.

    A double root is ill-conditioned: rounding splits it into two real roots or a complex pair up to 1e-4 apart
    near the turns where a second root comes close (a vertical tangent next to the double point), more than any
    rule for merging roots can tell from two distinct ones. The x of the curve's double point, `double`, is a root
    of multiplicity at least two (§19.4); once d and d' are checked to vanish there, (x - double)² is divided out
    and the rest found from the quotient, a polynomial whose roots are well separated from each other.
    """
    found = []
    if double is not None and len(d) >= 3:
        powers = max(1.0, abs(double)) ** np.arange(len(d))
        dd = P.polyder(d)
        if (abs(P.polyval(double, d)) <= DOUBLE_ROOT * (np.abs(d) @ powers)
                and abs(P.polyval(double, dd)) <= DOUBLE_ROOT * (np.abs(dd) @ powers[:-1])):
            d = P.polydiv(d, [double * double, -2.0 * double, 1.0])[0]
            found = [double, double]
    roots = P.polyroots(d) if len(d) > 1 else np.zeros(0)
    roots = roots[np.abs(roots.imag) <= IMAGINARY * np.maximum(1.0, np.abs(roots))].real
    groups: list[list[float]] = []
    for x in np.sort(np.concatenate([roots, found])):
        if groups and abs(x - groups[-1][-1]) <= MERGE * max(1.0, abs(x)):
            groups[-1].append(x)
        else:
            groups.append([x])
    # the double point's x stays exact when a root of the quotient joins it
    values = [double if double in g else float(np.mean(g)) for g in groups]
    return np.array(values), [len(g) for g in groups]


def _quiet_corner(ax, lines=()) -> str:
    """The corner of `ax` where the legend covers the least: the fewest curve vertices and dashed lines there.

    The curve is the contour drawn by `plot_curve`; `lines` are the x of the vertical dashed lines. Each corner is
    scored over a box the size of a one-entry legend (a third of the width, an eighth of the height).
    """
    to_axes = ax.transData + ax.transAxes.inverted()
    points = [to_axes.transform(path.vertices) for artist in ax.collections for path in artist.get_paths()
              if len(path.vertices)]
    points = np.concatenate(points) if points else np.zeros((0, 2))
    xs = to_axes.transform(np.column_stack([lines, np.zeros(len(lines))]))[:, 0] if len(lines) else np.zeros(0)
    scores = {}
    for corner, (left, bottom) in {"upper left": (0.0, 0.87), "upper right": (0.67, 0.87),
                                   "lower left": (0.0, 0.0), "lower right": (0.67, 0.0)}.items():
        inside = ((points[:, 0] >= left) & (points[:, 0] <= left + 0.33)
                  & (points[:, 1] >= bottom) & (points[:, 1] <= bottom + 0.13))
        crossing = (xs >= left) & (xs <= left + 0.33)
        scores[corner] = int(inside.sum()) + 25 * int(crossing.sum())
    return min(scores, key=scores.get)  # ties: the first, upper left


def silhouette_explorer(curve: str = "cubic of §19.5", angle: float = 0.0,
                        view: str = "whole curve") -> SilhouetteExplorer:
    """Slider `angle` (the curve turned about a point, degrees), dropdowns `curve` and `view`: Res_y(f, f_y) below.

    `update` returns {"curve", "angle", "view", "c" the turned curve, "discriminant" Res_y(f, f_y) (ascending in x),
    "roots" its distinct real roots, "multiplicities" theirs, "double_point" where the turn took it (None for a
    curve without one), "zoom" whether the view is the zoom about it, "box"}. Notes §19.4.
    """
    return SilhouetteExplorer(curve, angle, view)
