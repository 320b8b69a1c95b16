"""Writing one run's results: a Markdown report with every number, and one figure with the trends."""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np

from .common import Case, Measurement, format_count, format_seconds
from .evaluation import (
    BEZIER_DE_CASTELJAU,
    BEZIER_EVALUATE,
    BEZIER_GEOMDL,
    BEZIER_MATRIX,
    BEZIER_PACKAGE,
    DE_BOOR,
    GEOMDL_BSPLINE,
    SCIPY_BSPLINE,
)
from .health import CHAPTER_LIMIT, WIDGET_LIMIT
from .knots import EXTRACT, GEOMDL_EXTRACT, GEOMDL_INSERT, INSERT, SCIPY_EXTRACT, SCIPY_INSERT
from .rootfinding import BERNSTEIN, NUMPY_ROOTS, POLYNOMIAL_ROOTS
from .targets import Verdict, verdict_line


def _cell(m: Measurement | None, ratio: bool = True) -> str:
    """'12.3 ms ×1.5' — the time, and how it compares with the case's cagd_ref method."""
    if m is None or m.seconds is None:
        return "—" if m is None or not m.note else f"— ({m.note})"
    text = format_seconds(m.seconds)
    if ratio and m.ratio is not None:
        text += f" ×{m.ratio:.3g}"
    if m.extrapolated_from:
        text += f" (extrapolated from {format_count(m.extrapolated_from)})"
    return text


def _difference(case: Case, methods: list[str]) -> str:
    values = [(m, case.get(m).difference) for m in methods if case.get(m) and case.get(m).difference is not None]
    if not values:
        return "—"
    return ", ".join(f"{_short(m)} {d:.1e}" for m, d in values)


SHORT_NAMES = {
    BEZIER_DE_CASTELJAU: "de_casteljau", BEZIER_PACKAGE: "bezier", BEZIER_GEOMDL: "geomdl", BEZIER_MATRIX: "matrix",
    SCIPY_BSPLINE: "SciPy", GEOMDL_BSPLINE: "geomdl",
    SCIPY_INSERT: "SciPy", GEOMDL_INSERT: "geomdl", SCIPY_EXTRACT: "SciPy", GEOMDL_EXTRACT: "geomdl",
}


def _short(method: str) -> str:
    return SHORT_NAMES.get(method, method)


def _samples(case: Case, methods: list[str]) -> str:
    """Samples behind each best time, in the table's column order ('-' where not measured)."""
    found = [case.get(m) for m in methods]
    return "/".join(str(m.samples) if m and m.seconds is not None else "-" for m in found)


def _table(header: list[str], rows: list[list[str]]) -> list[str]:
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return lines


def _verdicts(found: list[Verdict]) -> list[str]:
    return _table(["target", "measured", "verdict", "detail"],
                  [[v.target, v.measured, v.label, v.detail] for v in found])


def _bezier(cases: list[Case]) -> list[str]:
    methods = [BEZIER_EVALUATE, BEZIER_DE_CASTELJAU, BEZIER_PACKAGE, BEZIER_GEOMDL, BEZIER_MATRIX]
    rows = [
        [str(c.params["degree"]), format_count(c.params["values"])]
        + [_cell(c.get(m), m != BEZIER_EVALUATE) for m in methods]
        + [_difference(c, methods[1:]), _samples(c, methods)]
        for c in cases
    ]
    return _table(
        [
            "degree",
            "values",
            "`evaluate`",
            "`de_casteljau`",
            "`bezier` evaluate_multi",
            "geomdl",
            "NumPy Bernstein matrix",
            "max abs difference to `evaluate`",
            "samples",
        ],
        rows,
    )


def _bspline(cases: list[Case]) -> list[str]:
    methods = [DE_BOOR, SCIPY_BSPLINE, GEOMDL_BSPLINE]
    rows = []
    for c in cases:
        scipy = c.get(SCIPY_BSPLINE)
        versus = f"{c.get(DE_BOOR).seconds / scipy.seconds:.2f}" if scipy and scipy.seconds else "—"
        rows.append(
            [str(c.params["degree"]), str(c.params["control points"]), format_count(c.params["values"])]
            + [_cell(c.get(m), m != DE_BOOR) for m in methods]
            + [versus, _difference(c, methods[1:]), _samples(c, methods)]
        )
    return _table(
        [
            "degree",
            "control points",
            "values",
            "`de_boor`",
            "SciPy `BSpline`",
            "geomdl",
            "`de_boor` / SciPy",
            "max abs difference to `de_boor`",
            "samples",
        ],
        rows,
    )


def _knots(cases: list[Case]) -> list[str]:
    rows = []
    for c in cases:
        methods = (
            (INSERT, SCIPY_INSERT, GEOMDL_INSERT)
            if c.params["operation"] == "insertion"
            else (EXTRACT, SCIPY_EXTRACT, GEOMDL_EXTRACT)
        )
        rows.append(
            [c.params["operation"], str(c.params["control points"])]
            + [_cell(c.get(m), m != methods[0]) for m in methods]
            + [_difference(c, list(methods[1:])), _samples(c, list(methods))]
        )
    return _table(["operation", "control points", "cagd_ref", "SciPy", "geomdl", "max abs difference", "samples"], rows)


def _roots(cases: list[Case]) -> list[str]:
    methods = [BERNSTEIN, NUMPY_ROOTS, POLYNOMIAL_ROOTS]
    rows = []
    for c in cases:
        errors = [f"{c.get(m).difference:.1e}" + (f" ({c.get(m).note})" if c.get(m).note else "") for m in methods]
        rows.append(
            [str(c.params["degree"])]
            + [_cell(c.get(m), m != BERNSTEIN) for m in methods]
            + errors
            + [f"{c.extra['error ratio']:.1e}", _samples(c, methods)]
        )
    return _table(
        [
            "degree",
            "`bernstein_roots`",
            "`numpy.roots`",
            "`Polynomial.roots`",
            "error Bernstein",
            "error `numpy.roots`",
            "error `Polynomial.roots`",
            "error ratio numpy.roots / Bernstein",
            "samples",
        ],
        rows,
    )


def _health(results: dict) -> list[str]:
    lines = []
    chapters = results.get("chapters", [])
    if chapters:
        lines += ["", "**Chapters** (`nbclient`, fresh kernel, kernel start included; limit 30 s):", ""]
        lines += _table(
            ["notebook", "seconds", "under 30 s"],
            [
                [
                    c.notebook,
                    f"{c.seconds:.1f}",
                    ("yes" if c.seconds < CHAPTER_LIMIT else "**no**") + (f" — failed: {c.error}" if c.error else ""),
                ]
                for c in chapters
            ],
        )
    widgets = results.get("widgets", [])
    if widgets:
        lines += [
            "",
            "**Widgets** (median over the slider moves of `update(**controls)`, limit 100 ms; of it, "
            "`compute` is the `cagd_ref` part and `png()` matplotlib's rendering and PNG encoding, each timed "
            "on its own after the update; the rest is creating the artists):",
            "",
        ]
        lines += _table(
            ["explorer", "slider moved", "update (median)", "compute", "png()", "build", "moves", "under 100 ms"],
            [
                [
                    f"`{w.factory}`",
                    w.control,
                    format_seconds(w.update),
                    format_seconds(w.compute),
                    format_seconds(w.render),
                    format_seconds(w.build),
                    str(w.updates),
                    ("yes" if w.update < WIDGET_LIMIT else "**no**") if not w.error else f"failed: {w.error}",
                ]
                for w in widgets
            ],
        )
    grading = results.get("grading")
    if grading:
        lines += [
            "",
            f"**Grading**: one submission (the complete chapter 1-2 solution of the test fixtures, graded on "
            f"all {grading.exercises} exercises of the course, score {grading.score}) takes "
            f"**{grading.seconds:.2f} s** (median of {grading.runs}), sandboxed worker process included.",
        ]
    return lines


def markdown(results: dict, found: list[Verdict], context: dict) -> str:
    lines = [
        "# Benchmarks: `cagd_ref` against the libraries CAGD users know",
        "",
        f"Written by `{context['command']}` ({context['plan']} run, {context['date']}, {context['minutes']:.1f} min).",
        "",
        f"**Verdict: {verdict_line(found)}.**",
        "",
        f"Machine: {context['machine']}. Load average (1 min): {context['load_before']} at the start, "
        f"{context['load_after']} at the end of the run; the benchmark itself accounts for about 1, and anything "
        "above that is other work sharing the machine. Absolute times move with that load; ratios much less, "
        "because the methods of a case are sampled in turns within seconds of each other.",
        "",
        f"Versions: {context['versions']}.",
        "",
        "How it is measured: the same inputs for every library, built before any clock starts (peer objects such as "
        "a `bezier.Curve` or a SciPy `BSpline` too, whereas our functions check their inputs inside the clock); "
        "`time.perf_counter`; calls repeated until a sample lasts long enough; samples of all methods of a case "
        "taken in turns; the best sample reported ('samples' column: how many, per method in column order). "
        "×r after a time is that method's time divided by the time of the case's `cagd_ref` method, so ×r > 1 "
        "means `cagd_ref` is faster. Every output is compared with ours (max abs difference). geomdl is pure "
        f"Python: above {format_count(context['geomdl_max'])} values it runs on an evenly spaced subset of the "
        "same parameters and its time is scaled linearly, marked *extrapolated*.",
        "",
        "## Targets",
        "",
    ]
    lines += _verdicts(found)
    sections = [
        ("bezier", "Bézier evaluation", "Random planar curves, evenly spaced parameters on [0, 1].", _bezier),
        (
            "bspline",
            "B-spline evaluation",
            "Random planar control points, uniform interior knots on [0, 1] with Bézier end conditions, evenly spaced "
            "parameters over the domain.",
            _bspline,
        ),
        (
            "knots",
            "Knot insertion and Bézier extraction",
            "B-splines as above (cubic). Insertion of one knot at 0.618…: `insert_knot` against SciPy's "
            "`BSpline.insert_knot` and geomdl's `operations.insert_knot` (on a copy made off the clock, since it "
            "changes its input). Extraction of every segment's Bézier points: `bezier_segments` against geomdl's "
            "`operations.decompose_curve` and, as SciPy has no such routine, `BSpline.insert_knot(x, m)` raising each "
            "interior knot to multiplicity n.",
            _knots,
        ),
        (
            "roots",
            "Root finding on Wilkinson-type polynomials",
            "Roots k/(n+1), k = 1..n; coefficients exact in each basis, then rounded once to doubles. Error: largest "
            "distance between an exact root and the matching computed one.",
            _roots,
        ),
    ]
    from .topics import TOPICS, table, topic

    sections += [(key, topic(key).TITLE, topic(key).ABOUT, table) for key in TOPICS]
    for key, title, about, render in sections:
        if results.get(key):
            lines += ["", f"## {title}", "", about, ""] + render(results[key])
    health = _health(results)
    if health:
        lines += ["", "## Course health"] + health
    if context.get("figure"):
        lines += ["", f"![benchmark plots]({context['figure']})"]
    return "\n".join(lines) + "\n"


# --- the figure ---------------------------------------------------------------------------


def _line(ax, xs, ys, label, style="-o", extrapolated=None):
    points = [(x, y) for x, y in zip(xs, ys) if y is not None and math.isfinite(y)]
    if not points:
        return
    ax.plot(*zip(*points), style, label=label, markersize=4)
    if extrapolated:
        marked = [(x, y) for x, y, e in zip(xs, ys, extrapolated) if e and y is not None]
        if marked:
            ax.plot(*zip(*marked), "o", markerfacecolor="white", color=ax.lines[-1].get_color(), markersize=6)


def _timing_line(ax, xs, cases: list[Case], method: str, style: str = "-o") -> None:
    """One method's best times over the given cases, extrapolated ones drawn open."""
    measured = [c.get(method) for c in cases]
    _line(
        ax,
        xs,
        [m.seconds if m else None for m in measured],
        method,
        style,
        extrapolated=[bool(m and m.extrapolated_from) for m in measured],
    )


def figure(results: dict, found: list[Verdict], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    fig = Figure(figsize=(15, 9), dpi=100)
    axes = fig.subplots(2, 3)
    fig.suptitle(textwrap.fill("cagd_ref benchmarks: " + verdict_line(found), 170), fontsize=9)

    ax = axes[0, 0]
    cases = results.get("bezier", [])
    if cases:
        size = max(c.params["values"] for c in cases)
        chosen = [c for c in cases if c.params["values"] == size]
        degrees = [c.params["degree"] for c in chosen]
        for method in (BEZIER_EVALUATE, BEZIER_DE_CASTELJAU, BEZIER_PACKAGE, BEZIER_GEOMDL, BEZIER_MATRIX):
            _timing_line(ax, degrees, chosen, method)
        ax.set(
            title=f"Bézier evaluation, {format_count(size)} values (open: extrapolated)",
            xlabel="degree",
            ylabel="seconds",
            yscale="log",
            xticks=degrees,
        )

    ax = axes[0, 1]
    cases = results.get("bspline", [])
    if cases:
        size = max(c.params["values"] for c in cases)
        counts = sorted({c.params["control points"] for c in cases})
        count = counts[len(counts) // 2]
        chosen = [c for c in cases if c.params["values"] == size and c.params["control points"] == count]
        degrees = [c.params["degree"] for c in chosen]
        for method in (DE_BOOR, SCIPY_BSPLINE, GEOMDL_BSPLINE):
            _timing_line(ax, degrees, chosen, method)
        ax.set(
            title=f"B-spline evaluation, {count} control points, {format_count(size)} values",
            xlabel="degree",
            ylabel="seconds",
            yscale="log",
            xticks=degrees,
        )

    ax = axes[0, 2]
    cases = results.get("knots", [])
    if cases:
        for operation, methods in (
            ("insertion", (INSERT, SCIPY_INSERT, GEOMDL_INSERT)),
            ("extraction", (EXTRACT, SCIPY_EXTRACT, GEOMDL_EXTRACT)),
        ):
            chosen = [c for c in cases if c.params["operation"] == operation]
            counts = [c.params["control points"] for c in chosen]
            for method in methods:
                _timing_line(ax, counts, chosen, method, "-o" if operation == "extraction" else "--s")
        ax.set(
            title="Knot insertion (dashed), extraction (solid)",
            xlabel="control points",
            ylabel="seconds",
            xscale="log",
            yscale="log",
        )

    ax = axes[1, 0]
    cases = results.get("roots", [])
    if cases:
        degrees = [c.params["degree"] for c in cases]
        for method in (BERNSTEIN, NUMPY_ROOTS, POLYNOMIAL_ROOTS):
            _line(ax, degrees, [max(c.get(method).difference, 1e-17) for c in cases], method)
        ax.set(
            title="Largest root error, Wilkinson-type polynomials",
            xlabel="degree",
            ylabel="error",
            yscale="log",
            xticks=degrees,
        )

    ax = axes[1, 1]
    widgets = [w for w in results.get("widgets", []) if not w.error]
    if widgets:
        y = np.arange(len(widgets))
        ax.barh(y, [w.update * 1e3 for w in widgets], color="C0", label="update (median)")
        ax.barh(y, [w.render * 1e3 for w in widgets], color="C9", label="png(): render + encode")
        ax.barh(y, [w.compute * 1e3 for w in widgets], color="C1", label="compute (cagd_ref)")
        ax.axvline(WIDGET_LIMIT * 1e3, color="k", linestyle="--", linewidth=1, label="target")
        ax.set_yticks(y, [w.factory for w in widgets], fontsize=7)
        ax.invert_yaxis()
        ax.set(title="Widget update latency (medians, timed separately)", xlabel="milliseconds")

    ax = axes[1, 2]
    chapters = results.get("chapters", [])
    if chapters:
        y = np.arange(len(chapters))
        ax.barh(y, [c.seconds for c in chapters], color=["C3" if c.error else "C2" for c in chapters])
        ax.axvline(CHAPTER_LIMIT, color="k", linestyle="--", linewidth=1, label="target")
        ax.set_yticks(y, [c.notebook for c in chapters], fontsize=7)
        ax.invert_yaxis()
        ax.set(title="Chapter execution time", xlabel="seconds")

    for ax in axes.flat:
        if ax.has_data():
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=7)
        else:
            ax.set_axis_off()
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    fig.savefig(path)
