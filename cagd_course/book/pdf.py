"""`cagd book --pdf`: print the built book with headless Chromium, page by page, into one PDF with bookmarks.

Each page is printed as a reader's browser would print it (the theme's print
styles drop the sidebars; an explorer's static figure shows the frame the page
opens with, without its controls), after MathJax has typeset it. The pages
follow the book's order: the landing page, the chapters, the exercises.
"""

from __future__ import annotations

import io
from pathlib import Path

from .build import BuiltPage

__all__ = ["PdfError", "print_pdf", "PDF_NAME"]

PDF_NAME = "cagd-course.pdf"


class PdfError(RuntimeError):
    """The PDF could not be printed; the message says why (and how to get what is missing)."""


def _bookmark(page: BuiltPage) -> str:
    return page.title if page.kind != "chapter" else f"{page.chapter}. {page.title}"


def _print(browser, ordered: list[tuple[str, Path]], out: Path):
    """Print the pages in order with `browser`; a PdfWriter holding them, one bookmark per page."""
    from pypdf import PdfReader, PdfWriter

    from .browser import keep_inside, wait_until_typeset

    writer = PdfWriter()
    context = browser.new_context()
    try:
        page = context.new_page()
        keep_inside(page, out)
        for title, html in ordered:
            page.goto(html.as_uri())
            wait_until_typeset(page)
            pdf = page.pdf(
                format="A4",
                print_background=True,
                outline=True,
                margin={"top": "15mm", "bottom": "15mm", "left": "12mm", "right": "12mm"},
            )
            writer.append(PdfReader(io.BytesIO(pdf)), outline_item=title)
    finally:
        context.close()
    writer.page_mode = "/UseOutlines"
    return writer


def print_pdf(out: Path | str, pages: list[BuiltPage], target: Path | str | None = None, browser=None) -> Path:
    """Print `out/index.html` and the built `pages` (chapters first, then exercises) into one PDF; its path.

    browser: a running Playwright Chromium to use (default: start one, see `browser.launch`).
    """
    try:
        import pypdf  # noqa: F401
        from playwright.sync_api import Error as PlaywrightError
        from playwright.sync_api import sync_playwright
    except ImportError as err:
        raise PdfError(f"printing needs playwright and pypdf ({err}); pip install 'cagd-course[test]'") from None

    from .browser import BrowserMissing, launch

    out = Path(out).resolve()
    target = Path(target) if target is not None else out / PDF_NAME
    ordered = [("About this course", out / "index.html")]
    ordered += [(_bookmark(p), out / p.file) for p in pages if p.kind == "chapter"]
    ordered += [(_bookmark(p), out / p.file) for p in pages if p.kind != "chapter"]
    try:
        if browser is not None:
            writer = _print(browser, ordered, out)
        else:
            with sync_playwright() as playwright:
                chromium = launch(playwright)
                try:
                    writer = _print(chromium, ordered, out)
                finally:
                    chromium.close()
    except BrowserMissing as err:
        raise PdfError(str(err)) from None
    except PlaywrightError as err:
        raise PdfError(f"Chromium failed while printing: {err}") from None
    with open(target, "wb") as stream:
        writer.write(stream)
    return target
