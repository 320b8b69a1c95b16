"""Explorers of chapter 3 of the notes: changing between the power and Bernstein bases with the
difference table, and what evaluating a polynomial costs by each method."""

from __future__ import annotations

import html
from math import comb

import ipywidgets as widgets
import numpy as np
from matplotlib.axes import Axes
from numpy.typing import ArrayLike

from cagd_ref._validation import as_coefficients, as_count
from cagd_ref.polynomials import bernstein_horner, bernstein_to_power, difference_table, evaluation_cost, horner

from ..examples import notes_example
from ..plotting.curves import plot_control_polygon
from ._base import CURVE_SAMPLES, Explorer, _fmt, _slider, _swatch

__all__ = [
    "basis_conversion_explorer",
    "evaluation_cost_explorer",
    "draw_difference_table",
    "difference_table_html",
    "power_text",
    "BasisConversionExplorer",
    "EvaluationCostExplorer",
]

# The weights of the notes' rational cubic (§3.3), the W column of its difference table.
DEFAULT_BERNSTEIN = tuple(notes_example("03.rational_cubic").results["weights"].tolist())
MAX_EXPLORED_DEGREE = 6
COEFFICIENT_RANGE = (-15.0, 15.0)
SUPERSCRIPTS = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")
METHOD_NAMES = {
    "horner": "Horner (power form)",
    "bernstein_horner": "nested Bernstein form",
    "de_casteljau": "de Casteljau",
}

CURVE_STYLE = {"color": "C0", "linewidth": 3, "alpha": 0.5}
POWER_STYLE = {"color": "C1", "marker": ".", "linestyle": "none"}
TOP_ROW_STYLE = {"boxstyle": "round,pad=0.3", "facecolor": "#d6e6f5", "edgecolor": "C0"}
LEFT_COLUMN_STYLE = {"boxstyle": "round,pad=0.3", "facecolor": "#fde3c8", "edgecolor": "C1"}
CORNER_STYLE = {"boxstyle": "round,pad=0.3", "facecolor": "#d6e6f5", "edgecolor": "C1", "linewidth": 2}
INNER_STYLE = {"boxstyle": "round,pad=0.3", "facecolor": "white", "edgecolor": "0.6"}


def _entry(value) -> str:
    """One table entry: a number, or a tuple for a row of several coordinates."""
    value = np.asarray(value)
    return f"{float(value):.4g}" if value.ndim == 0 else _fmt(value)


def _cell_style(i: int, j: int) -> dict:
    """Box of table entry Δʲ b_i: top row blue, left column framed orange, the corner both."""
    if i == j == 0:
        return CORNER_STYLE
    if j == 0:
        return TOP_ROW_STYLE
    return LEFT_COLUMN_STYLE if i == 0 else INNER_STYLE


def _superscript(k: int) -> str:
    """The digits of k as superscripts, for exponents and orders of differences."""
    return str(k).translate(SUPERSCRIPTS)


def power_text(coeffs: ArrayLike, variable: str = "t") -> str:
    """Ascending power coefficients (n+1,) as readable text, e.g. "1 + 6t − 12t² + 7t³". Notes §3.3."""
    a = as_coefficients(coeffs)
    if a.ndim != 1:
        raise ValueError(f"coeffs: expected one polynomial, shape (n+1,), got shape {a.shape}")
    terms = []
    for k, value in enumerate(a):
        if value == 0:
            continue
        magnitude = f"{abs(value):.4g}"
        monomial = "" if k == 0 else variable + (_superscript(k) if k > 1 else "")
        body = monomial if monomial and magnitude == "1" else magnitude + monomial
        terms.append((value < 0, body))
    if not terms:
        return "0"
    text = ("−" if terms[0][0] else "") + terms[0][1]
    for negative, body in terms[1:]:
        text += (" − " if negative else " + ") + body
    return text


def draw_difference_table(ax: Axes, coeffs: ArrayLike, power: bool = True, fontsize: float | None = None) -> Axes:
    """Draw the forward-difference table of Bernstein coefficients (n+1,) or (n+1, d) as a staircase. Notes §3.3.

    Row j holds Δʲ b_0, ..., Δʲ b_(n-j); the top row (the Bernstein
    coefficients) is shaded blue and the left column (Δʲ b_0) framed orange.
    With `power`, a column on the left shows the power coefficients
    a_j = C(n, j) Δʲ b_0. Returns `ax`, with its axes switched off.
    """
    rows = difference_table(coeffs)
    n = len(rows) - 1
    cells = [[_entry(value) for value in row] for row in rows]
    powers = [_entry(value) for value in bernstein_to_power(coeffs)] if power else []
    first = 2 if power else 0  # the power column and a gap for the "× C(n, j)" labels
    columns = first + n + 1
    if fontsize is None:
        # Fit the widest entry into a column of the axes' printed width (an average character is about 0.55 em).
        widest = max(len(text) for text in [*powers, *(t for row in cells for t in row)]) + 1
        points = ax.get_position().width * ax.figure.get_figwidth() * 72
        fontsize = float(np.clip(points / (columns + 1.2) / (0.55 * widest), 5, 11))
    for j, row in enumerate(cells):
        for i, text in enumerate(row):
            ax.text(first + i, -j, text, ha="center", va="center", fontsize=fontsize, bbox=_cell_style(i, j))
        label = f"Δ{_superscript(j)}"
        ax.text(first + len(row) - 0.45, -j, label, ha="left", va="center", fontsize=fontsize, color="0.4")
    for j, text in enumerate(powers):
        ax.text(0, -j, text, ha="center", va="center", fontsize=fontsize, bbox=LEFT_COLUMN_STYLE)
        ax.text(1, -j, f"← ×{comb(n, j)}", ha="center", va="center", fontsize=fontsize, color="C1")
    if power:
        ax.text(0, 0.75, "$a_j$", ha="center", fontsize=fontsize + 1, color="C1")
    ax.text(first + n / 2, 0.75, "$b_i$ (Bernstein)", ha="center", fontsize=fontsize + 1, color="C0")
    ax.set_xlim(-0.8, columns + 0.4)
    ax.set_ylim(-n - 0.7, 1.2)
    ax.set_axis_off()
    return ax


def difference_table_html(coeffs: ArrayLike) -> str:
    """The difference table of `draw_difference_table` as an HTML table, for readouts. Notes §3.3.

    Row j: the power coefficient a_j = C(n, j) Δʲ b_0 (orange), "← ×C(n, j)", then
    Δʲ b_0 ... Δʲ b_(n-j); the top row (the Bernstein coefficients) is blue.
    """
    rows = difference_table(coeffs)
    n = len(rows) - 1
    powers = bernstein_to_power(coeffs)
    cell = "<td style='padding:1px 6px;text-align:center;{}'>{}</td>"
    top, left = "background:#d6e6f5", "background:#fde3c8"
    lines = ["<table style='border-collapse:collapse;font-size:90%'>",
             "<tr><th>a<sub>j</sub></th><th></th>"
             f"<th colspan='{n + 1}'>b<sub>i</sub> (Bernstein), then Δ, Δ², …</th></tr>"
             ]
    for j, row in enumerate(rows):
        entries = "".join(
            cell.format(top if j == 0 else (left if i == 0 else ""), html.escape(_entry(value)))
            for i, value in enumerate(row)
        )
        label = f"Δ{_superscript(j)}" if j else "b"
        lines.append(
            f"<tr>{cell.format(left, html.escape(_entry(powers[j])))}"
            f"<td style='color:#d62728;padding:1px 4px'>← ×{comb(n, j)}</td>{entries}"
            f"<td style='color:#888;padding:1px 4px'>{label}</td></tr>"
        )
    lines.append("</table>")
    return "".join(lines)


# ---------------------------------------------------------------- basis conversion


class BasisConversionExplorer(Explorer):
    """Sliders for the Bernstein coefficients of an explicit polynomial; its power form and table. Notes §3.3.

    The figure holds the curve; the difference table and the colour key are
    HTML in the readout, where text is crisp and costs the redraw nothing.
    """

    def __init__(self, coeffs=None):
        b = as_coefficients(DEFAULT_BERNSTEIN if coeffs is None else coeffs)
        low, high = COEFFICIENT_RANGE
        if b.ndim != 1 or not 1 <= len(b) - 1 <= MAX_EXPLORED_DEGREE or not np.all((low <= b) & (b <= high)):
            raise ValueError(
                f"coeffs: expected 2 to {MAX_EXPLORED_DEGREE + 1} numbers in [{low:g}, {high:g}], shape (n+1,), "
                f"got {b.tolist()}"
            )
        controls = {
            f"b{i}": _slider(widgets.FloatSlider, f"b{i}", min=low, max=high, step=0.25, value=float(v))
            for i, v in enumerate(b)
        }
        super().__init__(controls)

    def compute(self, **values) -> dict:
        b = np.array([values[f"b{i}"] for i in range(len(values))], dtype=float)
        a = bernstein_to_power(b)
        t = np.linspace(0, 1, CURVE_SAMPLES)
        return {
            "bernstein": b,
            "power": a,
            "table": difference_table(b),
            "t": t,
            "bernstein_values": bernstein_horner(b, t),
            "power_values": horner(a, t),
            "text": power_text(a),
        }

    def draw(self, ax, state: dict) -> None:
        b, t = state["bernstein"], state["t"]
        n = len(b) - 1
        control = np.column_stack([np.arange(n + 1) / n, b])
        ax.axhline(0, color="0.85", linewidth=1)
        plot_control_polygon(ax, control, label="b")
        ax.plot(t, state["bernstein_values"], **CURVE_STYLE)
        ax.plot(t[::8], state["power_values"][::8], **POWER_STYLE)
        ax.set_aspect("auto")
        ax.set_xlabel("t")
        ax.set_ylabel("p(t)")
        ax.set_title(f"p(t) = {state['text']}", fontsize=9)

    def describe(self, state: dict) -> str:
        return (
            f"p(t) = {html.escape(state['text'])}<br>"
            f"{_swatch('0.4')} control points (i/n, b<sub>i</sub>) &nbsp; {_swatch('C0')} Bernstein form &nbsp; "
            f"{_swatch('C1')} power form (Horner)<br>{difference_table_html(state['bernstein'])}"
        )


def basis_conversion_explorer(coeffs: ArrayLike | None = None) -> BasisConversionExplorer:
    """Sliders `b0, b1, ...` (-15..15) for the Bernstein coefficients of an explicit polynomial on [0, 1]. Notes §3.3.

    coeffs: (n+1,) with 1 <= n <= 6, default (1, 3, 1, 2), the weights of the
    notes' rational example. Draws the explicit Bézier curve with both
    evaluations; the readout shows the difference table. `update` returns {"bernstein" (n+1,),
    "power" (n+1,), "table" (list of rows), "t" (200,), "bernstein_values"
    (200,), "power_values" (200,), "text" (the power form as text)}.
    """
    return BasisConversionExplorer(coeffs)


# ---------------------------------------------------------------- evaluation cost


class EvaluationCostExplorer(Explorer):
    """Operations per point of Horner, nested Bernstein evaluation and de Casteljau, by degree. Notes §3.1, §3.2."""

    def __init__(self, max_degree: int = 30):
        max_degree = as_count(max_degree, "max_degree", minimum=1)
        self.degrees = np.arange(max_degree + 1)
        costs = [evaluation_cost(int(n)) for n in self.degrees]
        self.totals = {method: np.array([sum(c[method]) for c in costs]) for method in METHOD_NAMES}
        degree = _slider(widgets.IntSlider, "degree", min=1, max=max_degree, value=3)
        super().__init__({"degree": degree})

    def compute(self, degree: int) -> dict:
        return {"degree": degree, "costs": evaluation_cost(degree), "degrees": self.degrees, "totals": self.totals}

    def draw(self, ax, state: dict) -> None:
        n = state["degree"]
        ax.figure.subplots_adjust(left=0.14)  # room for four-digit tick labels
        for k, (method, name) in enumerate(METHOD_NAMES.items()):
            total = state["totals"][method][n]
            # The counts at the chosen degree go into the legend: at low degrees the dots nearly coincide.
            ax.plot(state["degrees"], state["totals"][method], color=f"C{k}", label=f"{name}: {total}")
            ax.plot(n, total, "o", color=f"C{k}")
        ax.axvline(n, color="0.7", linestyle=":")
        ax.set_xlabel("degree n")
        ax.set_ylabel("multiplies + adds per point")
        ax.legend(fontsize=8, loc="upper left")
        ax.set_title(f"Cost of one evaluation at degree {n}", fontsize=10)

    def describe(self, state: dict) -> str:
        rows = "".join(
            f"<tr><td>{METHOD_NAMES[method]}</td><td>{multiplies}</td><td>{adds}</td></tr>"
            for method, (multiplies, adds) in state["costs"].items()
        )
        return f"<table><tr><th>method</th><th>×</th><th>+</th></tr>{rows}</table>"


def evaluation_cost_explorer(max_degree: int = 30) -> EvaluationCostExplorer:
    """Slider `degree` (1..max_degree): floating-point operations per point of each evaluation method. Notes §3.1, §3.2.

    `update` returns {"degree", "costs" (`polynomials.evaluation_cost` at that
    degree: method -> (multiplies, adds)), "degrees" (0..max_degree), "totals"
    (method -> multiplies + adds at every degree)}.
    """
    return EvaluationCostExplorer(max_degree)
