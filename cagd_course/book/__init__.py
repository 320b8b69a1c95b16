"""`cagd book`: the course as a book, built by Sphinx with MyST-NB and the book theme (Jupyter Book 1's engine).

`book.toml` stays the one manifest: the landing page and the table of
contents are generated from it. Chapters are executed through jupyter-cache
(only what changed runs again) with every explorer adding a static figure
whose main slider works without a kernel; exercise notebooks are shown as
shipped. MathJax and search are served from the book folder, so it reads
offline. `print_pdf` prints the built pages with headless Chromium into one PDF.
"""

from .build import DEFAULT_FRAMES, BookError, BuiltPage, build_book

__all__ = ["BuiltPage", "BookError", "build_book", "DEFAULT_FRAMES"]
