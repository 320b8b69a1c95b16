"""cagd_ref is the mathematics alone: its docstring indexes every module by chapter, as book.toml does,
and it imports none of the course's machinery."""

from __future__ import annotations

import ast
import pkgutil
import re
from collections import defaultdict
from pathlib import Path

import cagd_ref
from cagd_course.manifest import load_course

ROOT = Path(__file__).resolve().parents[2]
ENTRY = re.compile(r"^    (?P<module>[a-z_]+) +(?P<chapters>\d+(?:, \d+)*) {2,}\S")
MACHINERY = {"matplotlib", "ipywidgets", "IPython", "nbclient", "nbformat", "nbconvert", "cagd_course", "tqdm"}


def index() -> dict[str, list[int]]:
    """Module -> chapters, read from the docstring of cagd_ref."""
    found = {}
    for line in cagd_ref.__doc__.splitlines():
        match = ENTRY.match(line)
        if match:
            assert match["module"] not in found, f"{match['module']} is listed twice"
            found[match["module"]] = [int(c) for c in match["chapters"].split(", ")]
    return found


def test_the_index_lists_every_module_exactly_once():
    modules = {m.name for m in pkgutil.iter_modules(cagd_ref.__path__) if not m.name.startswith("_")}
    assert set(index()) == modules


def test_the_index_agrees_with_book_toml():
    by_chapter = defaultdict(set)
    for module, chapters in index().items():
        for number in chapters:
            by_chapter[number].add(f"cagd_ref.{module}")
    for chapter in load_course(ROOT).chapters:
        assert set(chapter.modules) == by_chapter[chapter.number], f"chapter {chapter.number}"


def test_the_index_follows_the_order_of_the_course():
    first_chapters = [chapters[0] for chapters in index().values()]
    assert first_chapters == sorted(first_chapters)


def test_the_mathematics_imports_no_course_machinery():
    for path in Path(cagd_ref.__file__).parent.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                names = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom) and not node.level:
                names = [node.module]
            else:
                continue
            leaked = {name.partition(".")[0] for name in names} & MACHINERY
            assert not leaked, f"{path.name} imports {leaked}"
