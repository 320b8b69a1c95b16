"""What every chapter notebook keeps to, whatever its chapter: cells that show reference source stand alone, tagged.

A class release drops the cells tagged `reference-source` (they display the reference implementation of what
students are asked to write), so such a cell must do nothing else, and no other cell may display source.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import nbformat
import pytest

from cagd_course.manifest import load_course

ROOT = Path(__file__).resolve().parents[2]
TAG = "reference-source"
SHOWS_SOURCE = re.compile(r"(?:show_source|getsource)\(")
CHAPTERS = [pytest.param(ch.notebook, id=ch.slug) for ch in load_course(ROOT).chapters if ch.notebook.is_file()]


def only_displays_source(source: str) -> bool:
    """True when every statement is `show_source(...)` or `display(show_source(...), ...)`."""
    for node in ast.parse(source).body:
        call = node.value if isinstance(node, ast.Expr) and isinstance(node.value, ast.Call) else None
        name = getattr(getattr(call, "func", None), "id", None)
        if name == "display" and all(getattr(getattr(a, "func", None), "id", None) == "show_source" for a in call.args):
            continue
        if name != "show_source":
            return False
    return True


@pytest.mark.parametrize("path", CHAPTERS)
def test_reference_source_is_shown_only_in_tagged_cells_of_its_own(path):
    for cell in nbformat.read(path, as_version=4).cells:
        if cell.cell_type != "code" or re.search(r"^\s*def show_source", cell.source, re.M):
            continue
        tagged = TAG in cell.metadata.get("tags", [])
        if SHOWS_SOURCE.search(cell.source):
            assert tagged, f"cell {cell.id} shows reference source: tag it {TAG!r}"
        if tagged:
            assert only_displays_source(cell.source), f"cell {cell.id} is tagged {TAG!r} but does more than display"
