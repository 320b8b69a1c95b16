"""The built book as a reader opens it: from file://, with no network, in headless Chromium.

The whole course is built once (into a temporary folder, with the execution cache of `./course build`, so a
built course makes this quick), then every page is opened with every request outside the book folder blocked.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from cagd_course.book import build_book
from cagd_course.book.browser import keep_inside, wait_until_typeset
from cagd_course.book.pdf import print_pdf
from cagd_course.manifest import load_course

expect = pytest.importorskip("playwright.sync_api").expect
# Sphinx 9 warns about its own API in the book theme and MyST; nothing the course can change.
pytestmark = pytest.mark.filterwarnings("ignore:.*Check CHANGES for Sphinx API modifications")

COURSE = load_course(Path(__file__).resolve().parents[2])
CHAPTER_2 = next(c for c in COURSE.chapters if c.number == 2)

# Text nodes of the page body outside code, scripts and typeset math: where raw TeX delimiters would show.
RAW_TEX = """() => {
  const skip = "PRE, CODE, SCRIPT, STYLE, TEXTAREA, MJX-CONTAINER";
  const walker = document.createTreeWalker(document.querySelector("main") || document.body, NodeFilter.SHOW_TEXT);
  const found = [];
  while (walker.nextNode()) {
    const node = walker.currentNode;
    if (node.parentElement.closest(skip)) continue;
    if (/\\$|\\\\\\(|\\\\\\[/.test(node.textContent)) found.push(node.textContent.trim().slice(0, 80));
  }
  return found;
}"""


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> tuple[Path, list]:
    """The whole course built into a temporary folder: (the folder, the pages `build_book` reports)."""
    out = tmp_path_factory.mktemp("book") / "html"
    pages = build_book(out, progress=False)
    assert not [p.error for p in pages if p.error]
    return out, pages


@pytest.fixture(scope="module")
def book(built) -> Path:
    return built[0]


def _open(page, book: Path, relative: str) -> list[str]:
    """Open a page of the book with everything outside the book folder blocked; the blocked URLs."""
    outside = keep_inside(page, book)
    page.goto((book / relative).as_uri())
    wait_until_typeset(page)
    return outside


def _doc(path: Path) -> str:
    return path.relative_to(COURSE.root).with_suffix(".html").as_posix()


def test_every_page_loads_offline_and_requests_nothing_outside_the_book(book, page):
    failed = []
    page.on("requestfailed", lambda request: failed.append(request.url))
    outside = keep_inside(page, book)
    pages = ["index.html", "search.html", "genindex.html"]
    pages += [_doc(p) for c in COURSE.chapters for p in (c.notebook, c.exercises) if p is not None]
    for relative in pages:
        response = page.goto((book / relative).as_uri())
        assert response is None or response.ok, relative
        wait_until_typeset(page)
        assert page.locator("main h1").count() >= 1, relative
    assert outside == []
    assert failed == []
    assert page.errors == []


def test_math_of_chapter_2_is_typeset_and_no_raw_delimiter_is_left(book, page):
    assert _open(page, book, _doc(CHAPTER_2.notebook)) == []
    assert page.locator("mjx-container").count() > 100
    # MathJax put its fonts in from the book folder too: the formulas are drawn, not empty boxes.
    assert page.evaluate("() => document.querySelector('mjx-container').getBoundingClientRect().width") > 0
    assert page.evaluate(RAW_TEX) == []


def test_the_sidebar_lists_every_chapter_and_exercise_notebook_of_book_toml(book, page):
    _open(page, book, "index.html")
    links = page.locator("nav.bd-docs-nav a").evaluate_all("links => links.map(a => a.href)")
    for chapter in COURSE.chapters:
        for path in (chapter.notebook, chapter.exercises):
            if path is not None:
                assert any(link.endswith(_doc(path)) for link in links), path
    _open(page, book, _doc(CHAPTER_2.notebook))
    assert page.locator("nav.bd-docs-nav a").count() == len(links)
    # Previous / next, the page's own contents, the notebook download and the box that says how to run it.
    assert page.locator("a.left-prev").count() == 1 and page.locator("a.right-next").count() == 1
    assert page.locator("nav.page-toc a").count() > 10
    download = page.locator("a[href$='_sources/chapters/02-bezier-curves.ipynb']")
    assert download.count() == 1
    assert (book / "_sources" / "chapters" / "02-bezier-curves.ipynb").is_file()
    box = page.locator(".cagd-run-box")
    assert "./course lab" in box.inner_text() and "chapters/02-bezier-curves.ipynb" in box.inner_text()


def test_search_for_de_casteljau_finds_chapter_2(book, page):
    outside = keep_inside(page, book)
    page.goto((book / "search.html").as_uri() + "?q=de+Casteljau")
    page.wait_for_selector("#search-results ul.search li a", timeout=30_000)
    hits = page.locator("#search-results ul.search li a").evaluate_all("links => links.map(a => a.href)")
    assert any(_doc(CHAPTER_2.notebook) in hit for hit in hits)
    assert outside == []


def test_moving_a_static_slider_shows_another_frame(book, page, artefacts):
    _open(page, book, _doc(CHAPTER_2.notebook))
    figure = page.locator(".cagd-static-explorer:has(img[alt^='de Casteljau'])").first
    figure.scroll_into_view_if_needed()
    image, readout = figure.locator("img.cagd-sx-frame"), figure.locator(".cagd-sx-readout")
    before, readout_before = image.get_attribute("src"), readout.inner_text()
    figure.locator("input[type=range]").focus()
    page.keyboard.press("ArrowRight")
    expect(image).not_to_have_attribute("src", before)
    assert readout.inner_text() != readout_before
    # The play button runs through the frames by itself.
    shown = image.get_attribute("src")
    figure.locator("button.cagd-sx-play").click()
    expect(image).not_to_have_attribute("src", shown)
    page.screenshot(path=artefacts / "book-chapter-02.png")
    assert (artefacts / "book-chapter-02.png").stat().st_size > 10_000


def test_the_pdf_prints_the_pages_with_their_math_and_the_figures_first_frame(built, browser, tmp_path):
    out, pages = built
    chapter_2 = [p for p in pages if p.chapter == 2]
    pdf = print_pdf(out, chapter_2, tmp_path / "chapter-2.pdf", browser=browser)
    from pypdf import PdfReader

    reader = PdfReader(pdf)
    assert [item.title for item in reader.outline if not isinstance(item, list)][:2] == [
        "About this course",
        f"2. {CHAPTER_2.title}",
    ]
    text = "\n".join(page.extract_text() for page in reader.pages)
    assert len(reader.pages) > 20 and "de Casteljau" in text
    # The static de Casteljau figure prints the frame the page opens with, without its slider.
    assert re.search(r"P\(0\.50\) = \(", text) and "precomputed frames" not in text
    # MathJax typeset the formulas before printing: no TeX source is left in the text.
    assert "\\frac" not in text and "$$" not in text


# ---------------------------------------------------------------- the reading form, on every chapter page

# Lines a reader sees on a page: visible code (cell inputs and code blocks in the prose; outputs excluded) against
# prose, headings and displayed math, each counted as rendered lines (height / line height).
READING_LINES = """() => {
  const article = document.querySelector("article") || document.querySelector("main");
  const shown = (el) => el.checkVisibility() && !el.closest(".cell_output");
  const rendered = (el) => {
    const style = getComputedStyle(el);
    const line = parseFloat(style.lineHeight) || 1.5 * parseFloat(style.fontSize);
    return Math.max(1, Math.round(el.getBoundingClientRect().height / line));
  };
  let code = 0, prose = 0;
  for (const pre of article.querySelectorAll("pre")) {
    if (shown(pre)) code += pre.innerText.replace(/\\n+$/, "").split("\\n").length;
  }
  const blocks = "p, h1, h2, h3, h4, h5, dt, li:not(:has(p)), mjx-container[display='true']";
  for (const el of article.querySelectorAll(blocks)) {
    if (shown(el) && !el.closest("pre") && !el.closest("li:has(p) > p ~ *")) prose += rendered(el);
  }
  return {code, prose};
}"""

# Every code block (folded ones opened first; reference listings included) wider than its box: its end is cut off.
OVERFLOWING_CODE = """() => {
  const article = document.querySelector("article") || document.querySelector("main");
  for (const details of article.querySelectorAll("details")) details.open = true;
  const wide = [...article.querySelectorAll("div.cell_input pre, div.highlight pre")]
    .filter((pre) => pre.checkVisibility() && pre.scrollWidth > pre.clientWidth + 1)
    .map((pre) => pre.innerText.split("\\n").find((line) => line.length > 88) || pre.innerText.slice(0, 60));
  for (const details of article.querySelectorAll("details")) details.open = false;
  return wide;
}"""

# Markdown tables that were printed as text instead of rendered: "| a | b |" rows outside code.
RAW_TABLES = """() => {
  const article = document.querySelector("article") || document.querySelector("main");
  const walker = document.createTreeWalker(article, NodeFilter.SHOW_TEXT);
  const found = [];
  while (walker.nextNode()) {
    const node = walker.currentNode;
    if (node.parentElement.closest("pre, code, script, style")) continue;
    if (/\\|\\s*(-{3,}|\u2014+)\\s*\\|/.test(node.textContent)) found.push(node.textContent.trim().slice(0, 80));
  }
  return found;
}"""

# Displayed formulas wider than the column (cut off, or, when numbered, a box that MathJax widened past it), and
# formulas MathJax could not typeset (its error boxes).
CLIPPED_MATH = """() => [...document.querySelectorAll("mjx-container[display='true']")]
  .filter((math) => math.checkVisibility() && (math.scrollWidth > math.clientWidth + 1
    || math.getBoundingClientRect().width > math.parentElement.clientWidth + 1))
  .map((math) => math.textContent.slice(0, 60))"""
MATH_ERRORS = """() => [...document.querySelectorAll("mjx-merror")].map((error) =>
  (error.getAttribute("data-mjx-error") || error.textContent).slice(0, 80))"""

MAX_VISIBLE_CODE = 0.25


def test_every_chapter_page_reads_as_a_textbook(book, page, artefacts):
    """Visible code at most a quarter of the lines; no code block or formula cut off; no table or TeX left raw."""
    rows, problems = [], []
    for chapter in COURSE.chapters:
        _open(page, book, _doc(chapter.notebook))
        lines = page.evaluate(READING_LINES)
        share = lines["code"] / max(1, lines["code"] + lines["prose"])
        wide, raw = page.evaluate(OVERFLOWING_CODE), page.evaluate(RAW_TABLES)
        tex, clipped = page.evaluate(RAW_TEX) + page.evaluate(MATH_ERRORS), page.evaluate(CLIPPED_MATH)
        rows.append(f"{chapter.number:>2} {share:6.1%}  code {lines['code']:>4}  prose {lines['prose']:>5}  "
                    f"wide code blocks {len(wide):>2}  raw tables {len(raw):>2}  raw TeX {len(tex):>2}  "
                    f"clipped formulas {len(clipped):>2}")
        if share > MAX_VISIBLE_CODE:
            problems.append(f"chapter {chapter.number}: visible code is {share:.0%} of the page's lines")
        problems += [f"chapter {chapter.number}: code block wider than its box: {line!r}" for line in wide]
        problems += [f"chapter {chapter.number}: table shown as raw text: {text!r}" for text in raw]
        problems += [f"chapter {chapter.number}: TeX left untypeset or in error: {text!r}" for text in tex]
        problems += [f"chapter {chapter.number}: formula wider than its box: {text!r}" for text in clipped]
    report = "chapter  visible code share (target <= 25 %)\n" + "\n".join(rows)
    (artefacts / "reading-form.txt").write_text(report + "\n", encoding="utf-8")
    print(report)
    assert not problems, "\n".join(problems) + "\n\n" + report


def test_every_static_slider_of_every_chapter_shows_another_frame(book, page):
    dead = []
    for chapter in COURSE.chapters:
        _open(page, book, _doc(chapter.notebook))
        figures = page.locator(".cagd-static-explorer")
        for index in range(figures.count()):
            figure = figures.nth(index)
            slider = figure.locator("input[type=range]")
            if slider.count() == 0:
                continue  # a still picture (an explorer without a slider to sweep)
            figure.scroll_into_view_if_needed()
            image = figure.locator("img.cagd-sx-frame")
            before = image.get_attribute("src")
            slider.focus()
            # One step, else the far end (a sweep may come back to its first picture: a line turned by 180°).
            moved = False
            for key in ("ArrowRight", "ArrowLeft", "End", "Home"):
                page.keyboard.press(key)
                if image.get_attribute("src") != before:
                    moved = True
                    break
            if not moved:
                dead.append(f"chapter {chapter.number}, explorer {index + 1}")
    assert dead == []
