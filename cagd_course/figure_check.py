"""Is a figure legible where the book shows it? Text collisions, text off the canvas, missing legends, tiny text.

`figure_findings(fig)` draws the figure once, records every text element the renderer actually drew (titles,
labels, tick labels, annotations, legend entries) and returns one readable sentence per problem:

- two text elements overlap (by more than `TOLERANCE_PX` each way);
- a text element is cut off: clipped by its box, or (for explorers, drawn on a fixed canvas) beyond the canvas;
- two or more labelled series share an axes and no legend shows them;
- a text is smaller than `MIN_POINTS` at the size the book shows the figure: a figure wider than the book's
  column (`BOOK_COLUMN_PX`) is scaled down to it, and its text with it.

`install(shell, report)` makes a running IPython kernel check every figure it displays and append the findings,
with the cell that drew them, as JSON lines to `report`; the notebook tests (the root `conftest.py`) turn
them into a failure of the cell that drew the figure.
"""

from __future__ import annotations

import json
from pathlib import Path

from matplotlib.figure import Figure
from matplotlib.text import Text
from matplotlib.transforms import Bbox

__all__ = [
    "figure_findings",
    "report_findings",
    "install",
    "check_notebook",
    "checking_environment",
    "BOOK_COLUMN_PX",
    "MIN_POINTS",
]

# Width of a figure's output in the book's column (sphinx-book-theme, 1280-px window), in CSS pixels.
BOOK_COLUMN_PX = 688
# A CSS pixel is 1/96 inch; the smallest text a reader should have to read, in points.
MIN_POINTS = 8.0
CSS_PX_PER_INCH = 96.0
TOLERANCE_PX = 1.5
REPORT_ENV = "CAGD_FIGURE_REPORT"


def _drawn_texts(fig: Figure) -> list[tuple[Text, object]]:
    """Every non-empty text the renderer draws, with its window extent (display pixels)."""
    canvas = fig.canvas
    if not hasattr(canvas, "get_renderer"):  # e.g. a figure not yet attached to an Agg canvas
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        canvas = FigureCanvasAgg(fig)
    renderer = canvas.get_renderer()
    drawn: dict[Text, object] = {}
    original = renderer.draw_text

    def record(gc, x, y, s, prop, angle, ismath=False, mtext=None):
        # The extent is taken while the text is drawn: a 3-D text (Text3D) has its projected position only then.
        if mtext is not None and str(s).strip() and mtext not in drawn:
            drawn[mtext] = mtext.get_window_extent(renderer)
        return original(gc, x, y, s, prop, angle, ismath=ismath, mtext=mtext)

    renderer.draw_text = record
    try:
        fig.draw(renderer)
    finally:
        del renderer.draw_text
    return list(drawn.items())


def _label(text: Text) -> str:
    return repr(" ".join(text.get_text().split())[:40])


def _where(text: Text, fig: Figure) -> str:
    axes = text.axes
    if axes is None:
        return "figure"
    title = axes.get_title() or axes.get_title(loc="left")
    index = fig.axes.index(axes) + 1 if axes in fig.axes else 0
    return f"panel {index}" + (f" ({title[:30]!r})" if title else "")


def _overlaps(texts, fig: Figure) -> list[str]:
    findings = []
    for i, (a, box_a) in enumerate(texts):
        for b, box_b in texts[i + 1 :]:
            dx = min(box_a.x1, box_b.x1) - max(box_a.x0, box_b.x0)
            dy = min(box_a.y1, box_b.y1) - max(box_a.y0, box_b.y0)
            if dx <= TOLERANCE_PX or dy <= TOLERANCE_PX:
                continue
            if a.get_text() == b.get_text() and abs(box_a.x0 - box_b.x0) < 1 and abs(box_a.y0 - box_b.y0) < 1:
                continue  # the same string drawn twice in one place reads as one
            findings.append(f"text {_label(a)} overlaps {_label(b)} in {_where(a, fig)}")
    return findings


def _off_canvas(texts, fig: Figure, tight: bool) -> list[str]:
    """Texts cut off: beyond the canvas (unless the figure is shown cropped to its contents), or beyond the box
    they are clipped to."""
    width, height = fig.canvas.get_width_height()
    canvas = Bbox.from_bounds(0, 0, width, height)
    findings = []
    for text, box in texts:
        clip = text.get_clip_box() if text.get_clip_on() else None
        limits = [clip] if clip is not None else []
        if not tight:
            limits.append(canvas)
        if any(_beyond(box, limit) for limit in limits):
            findings.append(f"text {_label(text)} is cut off in {_where(text, fig)}")
    return findings


def _beyond(box, limit) -> bool:
    return (
        box.x0 < limit.x0 - TOLERANCE_PX
        or box.y0 < limit.y0 - TOLERANCE_PX
        or box.x1 > limit.x1 + TOLERANCE_PX
        or box.y1 > limit.y1 + TOLERANCE_PX
    )


def _shown_scale(fig: Figure) -> float:
    """Points on the page per point of the figure: the PNG is drawn at fig.dpi and shrunk to the column."""
    width_px = fig.get_figwidth() * fig.dpi
    return fig.dpi / CSS_PX_PER_INCH * min(1.0, BOOK_COLUMN_PX / width_px)


def _tiny(texts, fig: Figure) -> list[str]:
    """One finding per figure: how many texts are shown below MIN_POINTS, the smallest first."""
    scale = _shown_scale(fig)
    sizes = [(text.get_fontsize() * scale, text) for text, _box in texts]
    small = sorted(((shown, text) for shown, text in sizes if shown < MIN_POINTS - 1e-9), key=lambda item: item[0])
    if not small:
        return []
    examples = ", ".join(f"{_label(text)} {shown:.1f} pt" for shown, text in small[:3])
    return [
        f"{len(small)} texts are shown below {MIN_POINTS:g} pt ({examples}, ...): the figure is "
        f"{fig.get_figwidth():g} in wide and the book's column {BOOK_COLUMN_PX / CSS_PX_PER_INCH:.2f} in, so "
        f"its text is shown at {scale:.2f} of its size"
    ]


def _unexplained_series(fig: Figure) -> list[str]:
    """Axes with two or more labelled series and no legend (on the axes or the figure) showing them."""
    figure_legend = bool(fig.legends)
    findings = []
    for index, axes in enumerate(fig.axes, start=1):
        handles, labels = axes.get_legend_handles_labels()
        if len(labels) >= 2 and axes.get_legend() is None and not figure_legend:
            title = axes.get_title()
            findings.append(
                f"panel {index}{f' ({title[:30]!r})' if title else ''} has {len(labels)} labelled series "
                f"({', '.join(map(repr, labels[:4]))}) and no legend"
            )
    return findings


def figure_findings(fig: Figure, tight: bool = True) -> list[str]:
    """One sentence per legibility problem of `fig` (empty: legible). Draws the figure once.

    `tight`: the figure is shown cropped to what it draws, as the inline backend shows it (see `report_findings`).
    """
    texts = _drawn_texts(fig)
    return _overlaps(texts, fig) + _off_canvas(texts, fig, tight) + _unexplained_series(fig) + _tiny(texts, fig)


# Where a kernel with the check installed writes its findings, and which cell is running.
_session: dict = {"report": None, "cell": None}


def report_findings(fig: Figure, tight: bool = True) -> None:
    """Check `fig` and append its findings to the kernel's report; nothing when the check is not installed.

    `tight`: the figure is shown cropped to what it draws (the inline backend's `bbox_inches="tight"`), so only
    clipped text is cut off; explorers draw onto their whole canvas (`tight=False`), where text beyond it is lost.
    """
    if _session["report"] is None:
        return
    findings = figure_findings(fig, tight=tight)
    if findings:
        with Path(_session["report"]).open("a", encoding="utf-8") as out:
            out.write(json.dumps({"cell": _session["cell"], "findings": findings}) + "\n")


def install(shell, report: Path | str) -> None:
    """Check every figure `shell` (an IPython shell) displays; append findings to the file `report`.

    Each line is JSON: {"cell": <the cell's id, or its first line>, "findings": [...]}. Figures shown by the
    inline backend are checked as they are turned into PNG (which is made as before); explorers check theirs
    when they are displayed (`cagd_course.widgets`).
    """
    _session["report"] = Path(report)

    def note_cell(info=None):
        # Which cell runs: its id (nbclient and nbval send it), else its first line.
        cell_id = getattr(info, "cell_id", None)
        first = (getattr(info, "raw_cell", "") or "").strip().splitlines()[:1]
        _session["cell"] = cell_id or (first[0] if first else None)

    def wrap(*_args):
        formatter = shell.display_formatter.formatters["image/png"]
        try:
            original = formatter.lookup_by_type(Figure)
        except KeyError:
            return
        if getattr(original, "cagd_checked", False):
            return

        def checked_png(fig):
            report_findings(fig, tight=True)
            return original(fig)

        checked_png.cagd_checked = True
        formatter.for_type(Figure, checked_png)

    # The inline backend now, so that its formatter exists before the first figure (a cell that makes the first
    # figure and shows it would otherwise escape); again before each cell and each flush, in case a cell
    # registered the formatter anew (`%matplotlib inline`). Registered first, this runs before the flush.
    shell.run_line_magic("matplotlib", "inline")
    wrap()
    shell.events.register("pre_run_cell", note_cell)
    shell.events.register("pre_run_cell", wrap)
    shell.events.register("post_execute", wrap)


# ---------------------------------------------------------------- running notebooks with the check


STARTUP = """\
# Written by cagd_course.figure_check: check every figure this kernel displays.
import os

try:
    from cagd_course.figure_check import REPORT_ENV, install
except ImportError:  # a kernel that cannot see the course (e.g. a confined grader) draws unchecked
    pass
else:
    if os.environ.get(REPORT_ENV):
        install(get_ipython(), os.environ[REPORT_ENV])
"""


def checking_environment(folder: Path | str, report: Path | str) -> dict[str, str]:
    """Environment variables under which every IPython kernel started checks its figures into `report`.

    `folder` becomes the kernels' IPYTHONDIR: a profile whose start-up file installs the check.
    """
    startup = Path(folder) / "profile_default" / "startup"
    startup.mkdir(parents=True, exist_ok=True)
    (startup / "00-cagd-figure-check.py").write_text(STARTUP, encoding="utf-8")
    return {"IPYTHONDIR": str(folder), REPORT_ENV: str(report), "MPLBACKEND": INLINE_BACKEND}


INLINE_BACKEND = "module://matplotlib_inline.backend_inline"


def read_report(report: Path | str) -> list[dict]:
    path = Path(report)
    if not path.is_file():
        return []
    return [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines() if line.strip()]


def cell_number(notebook, cell: str | None) -> str:
    """The 1-based position of a cell in `notebook` from its id or first line, as text ("?" if unknown)."""
    for index, candidate in enumerate(notebook.cells, start=1):
        first = candidate.source.strip().splitlines()[:1]
        if cell is not None and (candidate.get("id") == cell or first == [cell]):
            return str(index)
    return "?"


def check_notebook(path: Path | str, timeout: int = 300) -> list[str]:
    """Execute a notebook with every figure checked; one line per finding, naming the cell (1-based)."""
    import os
    import tempfile

    import nbformat
    from nbclient import NotebookClient

    path = Path(path)
    notebook = nbformat.read(path, as_version=4)
    with tempfile.TemporaryDirectory() as folder:
        report = Path(folder) / "report.jsonl"
        saved = dict(os.environ)
        os.environ.update(checking_environment(Path(folder) / "ipython", report))
        try:
            NotebookClient(notebook, timeout=timeout, resources={"metadata": {"path": str(path.parent)}}).execute()
        finally:
            os.environ.clear()
            os.environ.update(saved)
        lines = []
        for record in read_report(report):
            cell = cell_number(notebook, record["cell"])
            lines += [f"{path.name} cell {cell}: {finding}" for finding in record["findings"]]
        return lines


def main(argv: list[str] | None = None) -> int:
    import argparse

    parser = argparse.ArgumentParser(
        prog="python -m cagd_course.figure_check",
        description="Execute notebooks and list every figure problem a reader of the book would see "
        "(overlapping or off-canvas text, missing legends, text under 8 pt), by notebook and cell.",
    )
    parser.add_argument("notebooks", nargs="+", type=Path)
    args = parser.parse_args(argv)
    total = 0
    for notebook in args.notebooks:
        lines = check_notebook(notebook)
        total += len(lines)
        print("\n".join(lines) if lines else f"{notebook.name}: every figure legible")
    return 1 if total else 0


if __name__ == "__main__":
    raise SystemExit(main())
