"""Sphinx configuration of the course book: MyST-NB and the book theme, the engine of Jupyter Book 1.

`cagd book` (cagd_course.book.build) runs Sphinx with this folder as its
configuration folder and passes what depends on the course and the run as
overrides: the title, the pages of book.toml (`include_patterns`,
`cagd_pages`), the cache and the notebooks not to execute. Everything else is
the libraries' own machinery: navigation, search, numbering, cross-references,
math and cached notebook execution.
"""

extensions = [
    "myst_nb",
    # MathJax 3 from a PyPI package, copied into the book: formulas render without a network.
    "sphinx-mathjax-offline",
    # Mathematical environments (definition, theorem, proof, algorithm) and questions with folded answers,
    # written as MyST directives in the chapters; JupyterLab renders the same with jupyterlab-myst.
    "sphinx_proof",
    "sphinx_exercise",
    "sphinx_togglebutton",
    "cagd_course.book.extension",
]

# "Check your understanding" questions are sphinx-exercise's {exercise}: they read "Question 1, 2, ...",
# so that they are not mistaken for the graded exercises of the exercise notebooks ("exercise 4.3").
numfig_format = {"exercise": "Question %s"}
# Each answer follows its question, folded: its title is "Solution" (not "Solution to Exercise 1").
exercise_style = "solution_follow_exercise"

# Set by the build from book.toml.
project = "CAGD"
author = ""
root_doc = "index"
include_patterns = ["index.md"]
exclude_patterns = ["**.ipynb_checkpoints"]

# -- MyST: the notebooks' Markdown as Jupyter writes it (dollar math, raw HTML), headings as link targets.
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist", "html_image"]
myst_heading_anchors = 3
myst_dmath_double_inline = True

# -- MyST-NB: execute with jupyter-cache (only notebooks whose code changed run again).
nb_execution_mode = "cache"
nb_execution_timeout = 300
nb_execution_allow_errors = False
# The build reports a failing chapter itself (chapter, cell, error) and fails at the end.
nb_execution_raise_on_error = False
nb_execution_show_tb = True
nb_merge_streams = True
# Markdown outputs (tables of the notes' worked examples) are read as MyST, so their tables render.
nb_render_markdown_format = "myst"
# Explorers give a live widget, a PNG and (in the book's kernels) a self-contained HTML figure whose slider works
# without a kernel. A static page cannot run a widget, so the book drops the widget view and shows that figure.
nb_mime_priority_overrides = [
    (builder, "application/vnd.jupyter.widget-view+json", None) for builder in ("html", "dirhtml", "singlehtml")
]
# No widget manager from a CDN: nothing on a page is loaded from outside the book.
nb_ipywidgets_js = {}

# -- MathJax from the book's own _static folder (sphinx-mathjax-offline copies it there).
mathjax_path = "mathjax/tex-chtml.js"

# -- HTML: the book theme (sidebar with the whole course, previous/next, page contents, downloads, search).
html_theme = "sphinx_book_theme"
html_title = project
html_static_path = ["_static"]
html_css_files = ["cagd-book.css"]
html_copy_source = True
html_sourcelink_suffix = ""
html_show_sphinx = False
html_show_copyright = False
html_last_updated_fmt = None
# A page opened from file:// has no stored theme choice; say which one to start with.
html_context = {"default_mode": "light"}
html_theme_options = {
    "home_page_in_toc": True,
    "show_navbar_depth": 1,
    "show_toc_level": 2,
    "use_download_button": True,
    "use_fullscreen_button": True,
    "use_repository_button": False,
    "search_bar_text": "Search the course...",
}
