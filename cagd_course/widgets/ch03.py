"""Explorers of chapter 3 of the notes: changing between the power and Bernstein bases with the
difference table, and how accurately each basis evaluates a polynomial with many roots in [0, 1]."""

from __future__ import annotations

import html
from fractions import Fraction
from math import comb

import ipywidgets as widgets
import numpy as np
from matplotlib.axes import Axes
from numpy.typing import ArrayLike

from cagd_ref._validation import as_coefficients, as_count
from cagd_ref.bezier import bernstein_matrix
from cagd_ref.polynomials import bernstein_horner, bernstein_to_power, difference_table, horner

from ..examples import notes_example
from ..plotting.curves import plot_control_polygon
from ._base import CURVE_SAMPLES, Explorer, _slider, _swatch

__all__ = [
    "basis_conversion_explorer",
    "accuracy_explorer",
    "evenly_spaced_roots",
    "draw_difference_table",
    "draw_backward_fill",
    "difference_table_html",
    "power_text",
    "BasisConversionExplorer",
    "AccuracyExplorer",
]

# The weights of the notes' rational cubic (§3.3), the W column of its difference table.
DEFAULT_BERNSTEIN = tuple(notes_example("03.rational_cubic").results["weights"].tolist())
MAX_EXPLORED_DEGREE = 6
COEFFICIENT_RANGE = (-15.0, 15.0)
SUPERSCRIPTS = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")
# Evenly spaced roots k/(m+1), k = 1..m: the explorer's range, and its parameters j/SAMPLES (SAMPLES prime,
# so that no parameter is a root and every value has a logarithm).
ROOT_COUNTS = (2, 20)
SAMPLES = 397
UNIT_ROUNDOFF = 2.0**-53
ERROR_FLOOR = 1e-30  # the log axis starts here; errors that are exactly 0 are not drawn
LABEL = " style='padding-right:1em'"  # a readout label cell, kept clear of its number

CURVE_STYLE = {"color": "C0", "linewidth": 3, "alpha": 0.5}
POWER_STYLE = {"color": "C1", "marker": ".", "linestyle": "none"}
TOP_ROW_STYLE = {"boxstyle": "round,pad=0.3", "facecolor": "#d6e6f5", "edgecolor": "C0"}
LEFT_COLUMN_STYLE = {"boxstyle": "round,pad=0.3", "facecolor": "#fde3c8", "edgecolor": "C1"}
CORNER_STYLE = {"boxstyle": "round,pad=0.3", "facecolor": "#d6e6f5", "edgecolor": "C1", "linewidth": 2}
INNER_STYLE = {"boxstyle": "round,pad=0.3", "facecolor": "white", "edgecolor": "0.6"}


def _entry(value) -> str:
    """One table entry: a number, or a tuple for a row of several coordinates, written compactly: (1,-2,3)."""
    value = np.asarray(value)
    if value.ndim == 0:
        return f"{float(value):.4g}"
    return "(" + ",".join(f"{v:.4g}" for v in np.ravel(value)) + ")"


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


FRESH_STYLE = {"boxstyle": "round,pad=0.3", "facecolor": "#fde3c8", "edgecolor": "C1", "linewidth": 1.5}
# The given left column in neutral grey, so that orange means "new in this step" only; its first entry is
# also the top row's b_0 (blue, framed grey).
GIVEN_STYLE = {"boxstyle": "round,pad=0.3", "facecolor": "#e6e6e6", "edgecolor": "0.35"}
GIVEN_CORNER_STYLE = {"boxstyle": "round,pad=0.3", "facecolor": "#d6e6f5", "edgecolor": "0.35", "linewidth": 2}
EMPTY_STYLE = {"boxstyle": "round,pad=0.3", "facecolor": "white", "edgecolor": "0.85"}


def draw_backward_fill(ax: Axes, left_column: ArrayLike, step: int, fontsize: float = 9) -> Axes:
    """The difference table filled from its left column, after `step` columns. Notes §3.3.

    left_column: (n+1,) the entries Δʲ b_0 = a_j / C(n, j). Entry Δʲ b_i sits at
    (i, -j). Columns 0..step are filled: the given column 0 in grey (its top
    entry, b_0, blue framed grey), the top row blue, and the newest column
    (`step`) orange, with arrows from the two entries that sum to each of its
    entries, Δʲ b_k = Δʲ b_(k-1) + Δʲ⁺¹ b_(k-1); later slots are empty boxes.
    Returns `ax`, with its axes switched off.
    """
    column = as_coefficients(left_column, "left_column")
    if column.ndim != 1:
        raise ValueError(f"left_column: expected one column, shape (n+1,), got shape {column.shape}")
    n = len(column) - 1
    step = as_count(step, "step")
    if step > n:
        raise ValueError(f"step: expected an integer in [0, {n}], got {step}")
    columns = [column]
    while len(columns[-1]) > 1:
        columns.append(columns[-1][:-1] + columns[-1][1:])  # the next column to the right
    for i in range(n + 1):
        for j in range(n + 1 - i):
            if i > step:
                ax.text(i, -j, " · ", ha="center", va="center", fontsize=fontsize, color="0.7", bbox=EMPTY_STYLE)
                continue
            style = FRESH_STYLE if i == step and step > 0 else (TOP_ROW_STYLE if j == 0 else INNER_STYLE)
            if i == 0:
                style = GIVEN_STYLE if j else GIVEN_CORNER_STYLE
            ax.text(i, -j, f"{columns[i][j]:g}", ha="center", va="center", fontsize=fontsize, bbox=style)
            if i == step and step > 0:
                for source in (j, j + 1):
                    ax.annotate("", (i - 0.28, -j), (i - 0.72, -source),
                                arrowprops={"arrowstyle": "->", "color": "C1", "linewidth": 0.9})
    for j in range(n + 1):
        ax.text(-0.6, -j, f"Δ{_superscript(j)}", ha="right", va="center", fontsize=fontsize, color="0.4")
    ax.set_xlim(-1.2, n + 0.5)
    ax.set_ylim(-n - 0.6, 0.6)
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


# ---------------------------------------------------------------- accuracy of the two bases


def evenly_spaced_roots(count: int, samples: int = SAMPLES) -> dict:
    """p(t) = (t - 1/(m+1)) (t - 2/(m+1)) ... (t - m/(m+1)) with m = `count`, exactly. Notes ch. 3 and 13.

    Returns {"power" (m+1,), "bernstein" (m+1,): the exact coefficients of p
    in both bases (fractions) rounded to doubles, the only rounding either
    form starts with; "t" (samples-1,): the doubles nearest j/samples,
    j = 1..samples-1; "exact" (samples-1,): p at each of those doubles,
    computed exactly and rounded once}. The test polynomial of Farouki and
    Rajan (CAGD 4, 1987) for m = 20.
    """
    m = as_count(count, "count", minimum=1)
    samples = as_count(samples, "samples", minimum=2)
    roots = [Fraction(k, m + 1) for k in range(1, m + 1)]
    power = [Fraction(1)]  # multiply out the factors (t - r), lowest degree first
    for r in roots:
        power = [Fraction(0)] + power
        for k in range(len(power) - 1):
            power[k] -= r * power[k + 1]
    # b_j = sum over i <= j of C(j, i) / C(m, i) a_i, exactly
    bernstein = [sum(Fraction(comb(j, i), comb(m, i)) * power[i] for i in range(j + 1)) for j in range(m + 1)]
    t = np.arange(1, samples) / samples
    exact = []
    for x in t.tolist():
        # x is exactly num/den (den a power of 2), so x - k/(m+1) = (num (m+1) - k den) / (den (m+1)):
        # the product is one integer over another, and Python divides integers correctly rounded.
        num, den = x.as_integer_ratio()
        product = 1
        for k in range(1, m + 1):
            product *= num * (m + 1) - k * den
        exact.append(product / (den * (m + 1)) ** m)
    return {
        "power": np.array([float(a) for a in power]),
        "bernstein": np.array([float(b) for b in bernstein]),
        "t": t,
        "exact": np.array(exact),
    }


class AccuracyExplorer(Explorer):
    """A polynomial with m evenly spaced roots in [0, 1], evaluated in both bases: errors and their scales.

    Notes ch. 3 (and ch. 13 on floating point). The errors are measured against
    exact values; the dashed lines are η (the unit round-off) times the condition numbers
    Σ |a_i| tⁱ and Σ |b_i| B_i^m(t) of the two forms, the scale of their errors.
    """

    key_in_readout = True

    def __init__(self, roots: int = 12):
        low, high = ROOT_COUNTS
        roots = as_count(roots, "roots")
        if not low <= roots <= high:
            raise ValueError(f"roots: expected an integer in [{low}, {high}], got {roots}")
        super().__init__({"roots": _slider(widgets.IntSlider, "roots", min=low, max=high, value=roots)})

    def compute(self, roots: int) -> dict:
        data = evenly_spaced_roots(roots)
        a, b, t, exact = data["power"], data["bernstein"], data["t"], data["exact"]
        return {
            **data,
            "roots": roots,
            "power_error": np.abs(horner(a, t) - exact),
            "bernstein_error": np.abs(bernstein_horner(b, t) - exact),
            "power_condition": horner(np.abs(a), t),
            "bernstein_condition": bernstein_matrix(roots, t) @ np.abs(b),
        }

    def draw(self, ax, state: dict) -> None:
        t = state["t"]
        ax.semilogy(t, np.abs(state["exact"]), color="0.55", linewidth=1.5)
        for name, color in (("power", "C3"), ("bernstein", "C0")):
            error = state[f"{name}_error"]
            shown = error > 0  # a log axis has no place for an exact result
            ax.semilogy(t[shown], error[shown], ".", color=color, markersize=2.5)
            ax.semilogy(t, UNIT_ROUNDOFF * state[f"{name}_condition"], "--", color=color, linewidth=1)
        ax.set_ylim(ERROR_FLOOR, 1e2)
        ax.set_xlim(0, 1)
        ax.set_xlabel("t")
        m = state["roots"]
        ax.set_title(f"p(t) = (t − 1/{m + 1}) ⋯ (t − {m}/{m + 1}), degree {m}", fontsize=10)

    def describe(self, state: dict) -> str:
        largest = {key: float(np.max(state[key])) for key in ("power_error", "bernstein_error")}
        ratio = largest["power_error"] / largest["bernstein_error"]
        return (
            f"{_swatch('0.55')} |p(t)| &nbsp; {_swatch('C3')} error of the power form (Horner) &nbsp; "
            f"{_swatch('C0')} error of the Bernstein form (nested)<br>dashed: η × condition number of each form"
            f"<table><tr><td{LABEL}>largest |p|</td><td>{np.abs(state['exact']).max():.2e}</td></tr>"
            f"<tr><td{LABEL}>largest error, power form</td><td>{largest['power_error']:.2e}</td></tr>"
            f"<tr><td{LABEL}>largest error, Bernstein form</td><td>{largest['bernstein_error']:.2e}</td></tr>"
            f"<tr><td{LABEL}>ratio of the two</td><td>{ratio:.1e}</td></tr></table>"
        )


def accuracy_explorer(roots: int = 12) -> AccuracyExplorer:
    """Slider `roots` (2..20): the error of both bases on a polynomial with that many roots in (0, 1). Notes ch. 3.

    `update` returns the keys of `evenly_spaced_roots` ("power", "bernstein",
    "t", "exact") and "roots", "power_error", "bernstein_error" (|computed -
    exact| at each t, Horner resp. the nested Bernstein form), "power_condition"
    Σ |a_i| tⁱ and "bernstein_condition" Σ |b_i| B_i^m(t).
    """
    return AccuracyExplorer(roots)
