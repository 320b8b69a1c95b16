"""`cagd book`: the book Sphinx, MyST-NB and the book theme build from book.toml, tried on a tiny course of its own.

The course here has two chapters (one with an explorer and math, one plain) and an exercise notebook whose stub
raises, so the tests are quick and say exactly what the builder does: pages and navigation from book.toml,
static explorer figures instead of dead widgets, nothing loaded from outside, a cache that runs only what changed,
and a failing chapter named with its cell. The real course in a real browser: tests/browser/.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import ipywidgets
import nbformat
import pytest
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

from cagd_course import widgets
from cagd_course.book import build_book
from cagd_course.cli import main
from cagd_course.widgets._static import STATIC_FRAMES_ENV, _sweep

# Sphinx 9 warns about its own API in the book theme and MyST; nothing the course can change.
pytestmark = pytest.mark.filterwarnings("ignore:.*Check CHANGES for Sphinx API modifications")

MANIFEST = """
[book]
title = "A tiny course"
subtitle = "for the builder's tests"

[[chapters]]
number = 1
title = "First steps"
notebook = "chapters/01-first.ipynb"
exercises = "exercises/01-first.ipynb"

[chapters.exercise_points]
"01.double" = 1

[[chapters]]
number = 2
title = "Second steps"
notebook = "chapters/02-second.ipynb"
"""


def _write(path: Path, *cells) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    notebook = new_notebook(cells=list(cells))
    notebook.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(notebook, path)


def _course(root: Path, second_chapter_code: str = "x = 6 * 7\nx") -> Path:
    (root / "book.toml").write_text(MANIFEST, encoding="utf-8")
    _write(
        root / "chapters" / "01-first.ipynb",
        new_markdown_cell(
            "# Chapter 1 — First steps\n\nA first sentence about $t^2$, by T. W. Someone. A second one.\n\n"
            "## 1.1 A formula\n\n$$\\int_0^1 t\\,dt = \\frac{1}{2}$$\n\n"
            "See [the exercises](../exercises/01-first.ipynb)."
        ),
        new_code_cell("from cagd_course import widgets\n\nwidgets.de_casteljau_explorer()"),
        new_markdown_cell(
            "## 1.2 Printing\n\nSome text.\n\n```{exercise}\n:label: q-first\nWhy?\n```\n\n"
            "```{solution} q-first\n:class: dropdown\nBecause.\n```"
        ),
        new_code_cell("print('printed by chapter one')"),
    )
    _write(
        root / "chapters" / "02-second.ipynb",
        new_markdown_cell("# Chapter 2 — Second steps\n\nNothing but arithmetic."),
        new_code_cell("y = 1"),
        new_code_cell(second_chapter_code),
    )
    _write(
        root / "exercises" / "01-first.ipynb",
        new_markdown_cell("# Exercises: chapter 1\n\nWrite `double`."),
        new_code_cell("def double(x):\n    raise NotImplementedError\n\n\ndouble(2)"),
    )
    return root


def _build(root: Path, monkeypatch) -> list:
    monkeypatch.setenv("CAGD_COURSE", str(root))
    return build_book(root / "out", frames=3, progress=False)


@pytest.fixture(scope="module")
def book(tmp_path_factory):
    """The tiny course, built once: (its folder, the HTML folder, the reported pages)."""
    root = _course(tmp_path_factory.mktemp("course"))
    with pytest.MonkeyPatch.context() as monkeypatch:
        pages = _build(root, monkeypatch)
    return root, root / "out", pages


def _html(out: Path, page: str) -> str:
    return (out / page).read_text(encoding="utf-8")


def _text(html: str) -> str:
    """What a reader sees of some HTML: tags dropped (Sphinx wraps each word of inline code in its own span)."""
    return re.sub(r"<[^>]+>", "", html)


def test_the_build_reports_every_page_with_its_seconds(book):
    _, out, pages = book
    assert [(p.file, p.kind) for p in pages] == [
        ("chapters/01-first.html", "chapter"),
        ("exercises/01-first.html", "exercises"),
        ("chapters/02-second.html", "chapter"),
    ]
    chapters = [p for p in pages if p.kind == "chapter"]
    assert all(p.executed and p.seconds > 0 and not p.error for p in chapters)
    assert all((out / p.file).is_file() for p in pages)


def test_the_landing_page_and_the_sidebar_come_from_book_toml(book):
    _, out, _ = book
    index = _html(out, "index.html")
    assert "A tiny course" in index and "for the builder’s tests" in index
    # One line per chapter: its title, the first sentence of its notebook, its exercises.
    assert re.search(r'href="chapters/01-first.html".*First steps', index)
    assert "by T. W. Someone." in index and "A second one" not in index
    assert 'href="exercises/01-first.html"' in index and "1 exercise" in index
    page = _html(out, "chapters/02-second.html")
    sidebar = page.split('class="bd-links bd-docs-nav"', 1)[1].split("</nav>", 1)[0]
    for target in ("01-first.html", "../exercises/01-first.html", "#"):
        assert f'href="{target}"' in sidebar


def test_understanding_questions_read_question_not_exercise(book):
    _, out, _ = book
    page = _text(_html(out, "chapters/01-first.html"))
    # Not "Exercise 1", which a student would take for a graded exercise; the answer is just "Solution".
    assert re.search(r"Question \d", page) and not re.search(r"Exercise \d", page)


def test_the_notation_table_is_the_front_matter_of_every_book(book):
    _, out, _ = book
    notation = _text(_html(out, "notation.html"))
    # The course's table, rendered: its Bernstein and B-spline rows with their formulas typeset by MathJax.
    assert "One symbol has one meaning" in notation and "B-spline basis function" in notation
    assert r"\binom{n}{i}" in _html(out, "notation.html")
    index = _html(out, "index.html")
    assert 'href="notation.html"' in index
    sidebar = _html(out, "chapters/01-first.html").split('class="bd-links bd-docs-nav"', 1)[1]
    assert sidebar.index('href="../notation.html"') < sidebar.index('href="#"')


def test_a_chapter_page_has_navigation_contents_download_and_a_run_box(book):
    _, out, _ = book
    page = _html(out, "chapters/01-first.html")
    assert 'class="left-prev"' in page and 'class="right-next"' in page
    assert 'class="page-toc"' in page and "1.1 A formula" in page
    assert "../_sources/chapters/01-first.ipynb" in page
    assert (out / "_sources" / "chapters" / "01-first.ipynb").is_file()
    box = page.split("cagd-run-box", 1)[1].split("</div>", 1)[0]
    assert "./course lab" in _text(box) and "chapters/01-first.ipynb" in _text(box)
    assert 'href="../exercises/01-first.html"' in box
    assert "./course cagd check exercises/01-first.ipynb" in _text(_html(out, "exercises/01-first.html"))


def test_an_explorer_shows_a_static_figure_and_no_dead_widget(book):
    _, out, _ = book
    page = _html(out, "chapters/01-first.html")
    assert page.count("class='cagd-static-explorer'") == 1
    assert "widget-view+json" not in page and "widget-state+json" not in page
    data = json.loads(re.search(r"<script type='application/json' class='cagd-sx-data'>(.*?)</script>", page).group(1))
    assert data["labels"] == ["0.00", "0.50", "1.00"]
    assert len(set(data["frames"])) == 3 and "P(1.00)" in data["readouts"][2]
    # Each frame's text alternative is its own title (the script sets it with the frame).
    assert data["alts"] == [f"de Casteljau's algorithm at t = {t}" for t in ("0.00", "0.50", "1.00")]
    assert "printed by chapter one" in page


def test_math_and_every_script_come_from_the_book_folder(book):
    _, out, _ = book
    mathjax = out / "_static" / "mathjax"
    assert (mathjax / "tex-chtml.js").is_file()
    assert (mathjax / "output" / "chtml" / "fonts" / "woff-v2" / "MathJax_Main-Regular.woff").is_file()
    page = _html(out, "chapters/01-first.html")
    assert 'src="../_static/mathjax/tex-chtml.js' in page
    for html in out.rglob("*.html"):
        text = html.read_text(encoding="utf-8")
        assert not re.findall(r"""<(?:script|link|img|iframe)[^>]+(?:src|href)=["']?(?:https?:)?//""", text), html


def test_exercise_notebooks_are_shown_as_shipped(book):
    _, out, _ = book
    page = _html(out, "exercises/01-first.html")
    assert "raise" in page and "NotImplementedError" in page
    assert "Traceback" not in page and "cell_output" not in page


def test_a_second_build_executes_only_the_chapter_that_changed(tmp_path, monkeypatch):
    root = _course(tmp_path)
    assert [p.chapter for p in _build(root, monkeypatch) if p.executed] == [1, 2]
    assert [p.chapter for p in _build(root, monkeypatch) if p.executed] == []
    _course(root, second_chapter_code="x = 6 * 9\nx")
    pages = _build(root, monkeypatch)
    assert [p.chapter for p in pages if p.executed] == [2]
    assert "54" in _html(root / "out", "chapters/02-second.html")
    assert pages[0].seconds > 0 and "from the cache" in pages[0].state


def test_a_failing_chapter_is_named_with_its_cell_and_fails_the_build(tmp_path, monkeypatch, capsys):
    root = _course(tmp_path, second_chapter_code="1 / 0")
    monkeypatch.setenv("CAGD_COURSE", str(root))
    assert main(["--course", str(root), "book", "--out", str(root / "out"), "--frames", "2"]) == 1
    captured = capsys.readouterr()
    assert "chapter 2 (chapters/02-second.ipynb): cell 3 ('1 / 0') raised ZeroDivisionError" in captured.err
    assert re.search(r"chapters/01-first.html\s+executed in \d+\.\d s", captured.out)
    # The other pages are built; the failed one says why instead of showing half its outputs.
    assert (root / "out" / "chapters" / "01-first.html").is_file()
    assert "This chapter failed to execute" in _html(root / "out", "chapters/02-second.html")


def test_a_missing_notebook_is_a_clear_error(tmp_path, monkeypatch, capsys):
    root = _course(tmp_path)
    (root / "chapters" / "02-second.ipynb").unlink()
    monkeypatch.setenv("CAGD_COURSE", str(root))
    assert main(["--course", str(root), "book"]) == 2
    assert "chapter 2: book.toml names" in capsys.readouterr().err


# ---------------------------------------------------------------- the explorers' static figure


def test_the_static_figure_sweeps_the_main_slider_and_puts_everything_back():
    explorer = widgets.de_casteljau_explorer()
    values, picture = explorer.values, explorer.png()
    name, frames, start = explorer.static_frames(5)
    assert name == "t" and [f["label"] for f in frames] == ["0.00", "0.25", "0.50", "0.75", "1.00"]
    assert start == 2 and "P(0.50)" in frames[start]["readout"]
    assert all(f["png"][:8] == b"\x89PNG\r\n\x1a\n" for f in frames) and len({f["png"] for f in frames}) == 5
    assert explorer.values == values and explorer.state["t"] == 0.5 and explorer.png() == picture


def test_the_display_bundle_carries_the_static_figure_only_when_asked(monkeypatch):
    explorer = widgets.de_casteljau_explorer()
    monkeypatch.delenv(STATIC_FRAMES_ENV, raising=False)
    assert "text/html" not in explorer._repr_mimebundle_()
    monkeypatch.setenv(STATIC_FRAMES_ENV, "4")
    bundle = explorer._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle and bundle["image/png"][:4] == b"\x89PNG"
    assert bundle["text/html"].count("<input type='range' min='0' max='4'") == 1  # four frames and t = 0.5


def test_sweeps_cover_each_kind_of_control():
    assert _sweep(ipywidgets.IntSlider(value=2, min=1, max=4), 10) == [1, 2, 3, 4]
    assert _sweep(ipywidgets.FloatSlider(value=0.3, min=0, max=1, step=0.1), 3) == [0.0, 0.3, 0.5, 1.0]
    assert _sweep(ipywidgets.FloatLogSlider(value=10, min=0, max=2), 3) == [1.0, 10.0, 100.0]
    assert _sweep(ipywidgets.Dropdown(options=[("one", 1), ("two", 2)], value=1), 5) == [1, 2]
    assert _sweep(ipywidgets.Checkbox(value=True), 5) == [False, True]


# ---------------------------------------------------------------- the reading form: roles and figures


def _role_cell(source: str, role: str):
    cell = new_code_cell(source, metadata={"tags": [role]})
    if role not in ("compute", "explorer"):
        cell.metadata["jupyter"] = {"source_hidden": True}
    return cell


def test_roles_remove_setup_fold_checks_figures_and_reference_code_and_agg_draws_inline(tmp_path, monkeypatch):
    root = _course(tmp_path)
    _write(
        root / "chapters" / "02-second.ipynb",
        new_markdown_cell(
            "# Chapter 2 — Second steps\n\nCells with roles.\n\n"
            "```{prf:algorithm} Doubling\n:label: ch02-alg-doubling\n\n**Input:** a number $x$.\n\n"
            "1. Return $2x$.\n```\n\n"
            "```{exercise}\n:label: ch02-q-double\n\nWhat is twice 21?\n```\n\n"
            "```{solution} ch02-q-double\n:class: dropdown\n\nForty-two.\n```"
        ),
        _role_cell(
            "import matplotlib.pyplot as plt\n\nfrom cagd_course.notebook import show_source, verified\n"
            "from cagd_ref.bezier import bernstein\n\nSCAFFOLDING = 1",
            "setup",
        ),
        _role_cell("answer = 6 * 7\nanswer", "compute"),
        _role_cell("assert answer == 42\nverified('the answer is 42')", "check"),
        _role_cell("fig, ax = plt.subplots(figsize=(3, 2))\nax.plot([0, 1], [0, 1])\nplt.show()", "figure"),
        _role_cell("display(show_source(bernstein))", "reference-source"),
    )
    # A server's environment: without the build's pinning, plt.show() would draw nothing.
    monkeypatch.setenv("MPLBACKEND", "Agg")
    pages = _build(root, monkeypatch)
    assert not [p.error for p in pages if p.error]
    page = _html(root / "out", "chapters/02-second.html")
    assert "SCAFFOLDING" not in page
    # The mathematical environments: an algorithm box, a question and its folded answer.
    assert re.search(r'class="[^"]*\bproof\b[^"]*\balgorithm\b', page) and "Algorithm 1" in _text(page)
    assert re.search(r"Question \d", _text(page)) and re.search(r'class="[^"]*solution[^"]*dropdown', page)
    assert "{prf:algorithm}" not in page and "{solution}" not in page
    assert "\N{CHECK MARK} the answer is 42" in page
    assert "Show the check" in page and "Show the code of this figure" in page
    # The tiny course grades no `bernstein`: its listing has no exercise to point to.
    assert "Reference implementation of bernstein" in page and "try exercise" not in page
    assert re.search(r'<img alt="_images/[^"]+\.png"|<img[^>]+\.png', page.split("Show the code of this figure")[1])
    # The notebook itself is unchanged: the roles are tags, the book's tags are added to the staged copy only.
    tags = [c.metadata.get("tags") for c in nbformat.read(root / "chapters" / "02-second.ipynb", 4).cells[1:]]
    assert tags == [["setup"], ["compute"], ["check"], ["figure"], ["reference-source"]]


def test_an_execution_whose_figure_cells_drew_nothing_is_run_again():
    from cagd_course.book.build import _drew_no_figure

    figure = _role_cell("plt.plot([0, 1])\nplt.show()", "figure")
    notebook = new_notebook(cells=[figure])
    assert _drew_no_figure(notebook)
    figure.outputs = [nbformat.v4.new_output("display_data", data={"image/png": "iVBORw0KGgo="})]
    assert not _drew_no_figure(notebook)
    assert not _drew_no_figure(new_notebook(cells=[_role_cell("x = 1", "compute")]))


def test_a_listing_of_a_graded_function_names_the_exercise_to_try_first():
    from cagd_course.book.build import _listing_label

    exercises = {"de_casteljau": "02.de_casteljau", "subdivide": "02.subdivide"}
    assert _listing_label("display(show_source(de_casteljau))", exercises) == (
        "Reference implementation of de_casteljau: try exercise 02.de_casteljau first"
    )
    assert _listing_label("show_source(bezier.de_casteljau_plain)", exercises) == (
        "Reference implementation of de_casteljau_plain: try exercise 02.de_casteljau first"
    )
    assert _listing_label("display(show_source(continuity.curvature_comb))", exercises) == (
        "Reference implementation of curvature_comb"
    )
