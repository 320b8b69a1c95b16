"""cagd_course: the machinery of the CAGD course around the mathematics of `cagd_ref`.

`manifest` reads `book.toml`; `book` builds the HTML book; `cli` is the `cagd`
command; `plotting` draws the figures and `widgets` builds the explorers of the
chapters; `grading` runs the hidden suites on students' code. Exercise notebooks
use `check`, the self-check cell. `cagd_ref` never imports this package.
"""

from .grading import check

__all__ = ["check"]
__version__ = "0.1.0"
