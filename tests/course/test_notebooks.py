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
from cagd_course.notebook import HIDDEN_ROLES, ROLES

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
        if cell.cell_type != "code":
            continue
        tagged = TAG in cell.metadata.get("tags", [])
        if SHOWS_SOURCE.search(cell.source):
            assert tagged, f"cell {cell.id} shows reference source: tag it {TAG!r}"
        if tagged:
            assert only_displays_source(cell.source), f"cell {cell.id} is tagged {TAG!r} but does more than display"


# ---------------------------------------------------------------- cell roles (the reading form)


def _role(cell) -> list[str]:
    return [tag for tag in cell.metadata.get("tags", []) if tag in ROLES]


@pytest.mark.parametrize("path", CHAPTERS)
def test_every_code_cell_has_one_role_and_is_collapsed_as_its_role_says(path):
    for index, cell in enumerate(nbformat.read(path, as_version=4).cells, start=1):
        if cell.cell_type != "code":
            continue
        roles = _role(cell)
        assert len(roles) == 1, f"cell {index} has roles {roles}: tag it with exactly one of {sorted(ROLES)}"
        hidden = cell.metadata.get("jupyter", {}).get("source_hidden", False)
        assert hidden == (roles[0] in HIDDEN_ROLES), (
            f"cell {index} ({roles[0]}): metadata.jupyter.source_hidden must be {roles[0] in HIDDEN_ROLES}"
        )


@pytest.mark.parametrize("path", CHAPTERS)
def test_check_cells_end_with_their_verdict_and_explorers_are_one_expression(path):
    for index, cell in enumerate(nbformat.read(path, as_version=4).cells, start=1):
        if cell.cell_type != "code":
            continue
        body = ast.parse(cell.source).body
        if _role(cell) == ["check"]:
            last = body[-1] if body else None
            call = last.value if isinstance(last, ast.Expr) and isinstance(last.value, ast.Call) else None
            assert getattr(getattr(call, "func", None), "id", None) == "verified", (
                f"check cell {index} must end with verified('what it proved')"
            )
            assert call.args and isinstance(call.args[0], (ast.Constant, ast.JoinedStr)), (
                f"check cell {index}: verified() takes the sentence saying what was proved"
            )
        if _role(cell) == ["explorer"]:
            assert len(body) == 1 and isinstance(body[0], ast.Expr), (
                f"explorer cell {index} must be the one expression that shows a widget"
            )


@pytest.mark.parametrize("path", CHAPTERS)
def test_chapters_use_the_shared_notebook_helpers_instead_of_their_own(path):
    for index, cell in enumerate(nbformat.read(path, as_version=4).cells, start=1):
        if cell.cell_type == "code":
            assert not re.search(r"^def (show_source|verified)\b", cell.source, re.M), (
                f"cell {index} defines its own helper: import it from cagd_course.notebook"
            )
