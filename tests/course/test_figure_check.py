"""The figure check: what a reader of the book could not read is found, named, and nothing else is."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import nbformat  # noqa: E402
import pytest  # noqa: E402
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook  # noqa: E402

from cagd_course.figure_check import BOOK_COLUMN_PX, check_notebook, figure_findings  # noqa: E402


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def test_a_tidy_figure_has_no_findings():
    fig, ax = plt.subplots(figsize=(5, 3))
    ax.plot([0, 1], [0, 1], label="rising")
    ax.plot([0, 1], [1, 0], label="falling")
    ax.legend()
    ax.set_title("two lines")
    fig.tight_layout()
    assert figure_findings(fig) == []


def test_overlapping_texts_are_named():
    fig, ax = plt.subplots(figsize=(4, 3))
    ax.text(0.5, 0.5, "$P_3$")
    ax.text(0.51, 0.5, "$Q_0$")
    assert figure_findings(fig) == ["text '$P_3$' overlaps '$Q_0$' in panel 1"]


def test_cut_off_text_and_series_without_legend_are_found():
    fig, ax = plt.subplots(figsize=(4, 3))
    ax.text(1.4, 0.5, "outside", transform=ax.transAxes)
    ax.text(0.9, 0.2, "clipped by the axes", transform=ax.transAxes, clip_on=True)
    ax.plot([0, 1], label="a")
    ax.plot([1, 0], label="b")
    findings = figure_findings(fig)
    # Shown cropped to its contents (the inline backend), text beyond the canvas is still seen; clipped text is cut.
    assert "text 'clipped by the axes' is cut off in panel 1" in findings
    assert not [finding for finding in findings if "'outside'" in finding]
    assert "panel 1 has 2 labelled series ('a', 'b') and no legend" in findings
    # An explorer draws on its whole canvas: there, text beyond it is lost too.
    assert "text 'outside' is cut off in panel 1" in figure_findings(fig, tight=False)


def test_a_figure_wider_than_the_column_shrinks_its_text_below_8_pt():
    fig, ax = plt.subplots(figsize=(12, 3))
    ax.set_title("wide")
    fig.tight_layout()
    (finding,) = figure_findings(fig)
    # 12 in at 100 dpi is 1200 px, shown at 688 px: 10-pt tick labels read as 10 * 100/96 * 688/1200 = 6.0 pt.
    assert BOOK_COLUMN_PX == 688 and "shown below 8 pt" in finding and "6.0 pt" in finding
    fig.set_size_inches(6.5, 3)
    fig.tight_layout()
    assert figure_findings(fig) == []


def test_3d_texts_are_measured_where_they_are_drawn():
    fig = plt.figure(figsize=(5, 4))
    ax = fig.add_subplot(projection="3d")
    ax.plot([0, 1], [0, 1], [0, 1])
    ax.text(0.5, 0.5, 0.5, "middle")
    assert not [f for f in figure_findings(fig) if "middle" in f and "canvas" in f]


def test_a_notebook_run_names_the_cell_that_drew_an_illegible_figure(tmp_path):
    notebook = new_notebook(
        cells=[
            new_markdown_cell("# A figure"),
            new_code_cell("import matplotlib.pyplot as plt"),
            new_code_cell("fig, ax = plt.subplots(figsize=(3, 2))\nax.text(0.5, 0.5, 'ab')\nax.text(0.5, 0.5, 'cd')"),
        ]
    )
    notebook.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    path = tmp_path / "figures.ipynb"
    nbformat.write(notebook, path)
    assert check_notebook(path) == ["figures.ipynb cell 3: text 'ab' overlaps 'cd' in panel 1"]
