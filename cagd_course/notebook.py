"""What the chapter notebooks share: showing reference source, and the one-line verdict of a `check` cell.

Every code cell of a chapter carries one role tag (see `ROLES`); the book and JupyterLab use the role to
decide what a reader sees. A `check` cell asserts what the notes print and ends with `verified(...)`, so
the reader sees what was proved without reading the asserts.
"""

from __future__ import annotations

import inspect

from IPython.display import Code

__all__ = ["ROLES", "HIDDEN_ROLES", "show_source", "verified"]

# role -> what the cell is, and how the book shows it
ROLES = {
    "setup": "imports, seeds and helpers: removed from the book, collapsed in JupyterLab",
    "compute": "code whose reading is the lesson: shown",
    "check": "asserts reproducing the notes' numbers: input folded, its one-line verdict shown",
    "figure": "code that only draws: input folded, the figure shown",
    "explorer": "the one line that shows a widget: shown",
    "reference-source": "the reference code of a graded function: folded, after the idea; dropped from a release",
}
# Roles whose source is collapsed in JupyterLab (`metadata.jupyter.source_hidden`) and folded in the book.
HIDDEN_ROLES = ("setup", "check", "figure", "reference-source")


def show_source(function) -> Code:
    """The source of a reference function, syntax highlighted (a `reference-source` cell displays it)."""
    return Code(inspect.getsource(function), language="python")


def verified(what: str) -> None:
    """Print the verdict of a `check` cell: one line saying what its asserts proved (call it last)."""
    print(f"\N{CHECK MARK} {what}")
