"""Every docstring example of cagd_ref runs (doctest), and every graded function has one with the notes' section.

A graded function is one an exercise of book.toml asks students to write; its
docstring is the first thing a reader sees, so it carries a runnable example
with the notes' numbers and says where in the notes (and, where the algorithm
comes from elsewhere, in which paper: a ``Ref:`` line) it is taught.
"""

from __future__ import annotations

import doctest
import importlib
import importlib.util
import pkgutil
import re
from pathlib import Path

import numpy as np
import pytest

import cagd_ref
from cagd_course.manifest import load_course

ROOT = Path(__file__).resolve().parents[2]
MODULES = sorted(m.name for m in pkgutil.iter_modules(cagd_ref.__path__) if not m.name.startswith("_"))
FLAGS = doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS


def graded_functions():
    """(exercise id, function) for every exercise of the manifest."""
    found = []
    for chapter in load_course(ROOT).chapters:
        modules = [importlib.util.find_spec(name) and importlib.import_module(name) for name in chapter.modules]
        for exercise_id in chapter.exercise_points:
            name = exercise_id.partition(".")[2]
            function = next((getattr(m, name) for m in modules if m and hasattr(m, name)), None)
            found.append(pytest.param(function, id=exercise_id))
    return found


@pytest.mark.parametrize("module", MODULES)
def test_docstring_examples_run(module):
    finder = doctest.DocTestFinder(exclude_empty=True)
    runner = doctest.DocTestRunner(optionflags=FLAGS)
    module = importlib.import_module(f"cagd_ref.{module}")
    with np.printoptions(legacy=False):
        # Examples run in the module's own namespace (as pytest's doctest does): its functions and np are there.
        for test in finder.find(module):
            runner.run(test)
    assert runner.failures == 0, f"{runner.failures} docstring example(s) of {module.__name__} failed (output above)"


@pytest.mark.parametrize("function", graded_functions())
def test_graded_functions_show_an_example_and_their_section(function):
    assert function is not None, "no reference function of that name in the chapter's modules"
    text = function.__doc__ or ""
    assert ">>> " in text, "a runnable example with the notes' numbers"
    assert re.search(r"Notes (§\d|\(\d)", text), "the section (Notes §N.M) or equation (Notes (N.M)) it implements"
