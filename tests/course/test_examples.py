"""cagd_course.examples: the notes' worked examples load, exact numbers parse, and bad files are refused."""

from __future__ import annotations

import math

import numpy as np
import pytest

from cagd_course import examples
from cagd_course.manifest import load_course


def test_every_chapter_file_loads_with_sections():
    files = sorted(examples.FOLDER.glob("ch*.toml"))
    assert files
    for path in files:
        chapter = int(path.stem[2:])
        found = examples.notes_examples(chapter)
        assert found, path.name
        for name, example in found.items():
            assert example.id == f"{chapter:02d}.{name}"
            assert example.section.split(".")[0] == str(chapter), f"{example.id} sits in §{example.section}"
            assert example.summary


def test_every_chapter_of_the_manifest_keeps_its_examples():
    for chapter in load_course().chapters:
        assert examples.notes_examples(chapter.number)


def test_exact_numbers_and_arrays():
    rotation = examples.notes_example("01.rotation")
    assert rotation.inputs["angle"] == math.pi / 2
    np.testing.assert_array_equal(rotation.results["rotated"], [5 / 3, 13 / 3, 23 / 3])
    assert examples.notes_example("01.triangle_area").results["area"] == math.sqrt(155) / 2
    point, angle = rotation.args("point", "angle")
    point[0] = 99.0  # args are copies: the kept example is unchanged
    assert rotation.inputs["point"][0] == 5.0
    assert examples._value("hyperbola") == "hyperbola"
    assert examples._value("__import__('os')") == "__import__('os')"  # never evaluated


def test_unknown_examples_and_keys_are_refused(tmp_path, monkeypatch):
    with pytest.raises(KeyError, match="01.nothing"):
        examples.notes_example("01.nothing")
    with pytest.raises(KeyError, match="rotation"):
        examples.notes_example("01.rotation").args("rotation_axis")
    with pytest.raises(ValueError, match="section"):
        examples._example(1, "broken", {"summary": "no section", "answer": 3})


def test_notebooks_show_an_example_as_a_table():
    text = examples.notes_example("01.rotation")._repr_markdown_()
    assert text.startswith("**Notes §1.3**")
    assert "| input | `angle` | `1.5708` |" in text


def test_notebooks_show_an_example_as_an_html_table_that_renders_everywhere():
    html = examples.notes_example("01.rotation")._repr_html_()
    assert html.startswith("<p><strong>Notes §1.3</strong>")
    assert '<table class="cagd-example">' in html and html.count("<tr>") == 1 + 9
    # the digits that matter: whole numbers without a decimal point, others to six significant digits
    assert "<td><code>angle</code></td><td><code>1.5708</code></td>" in html
    assert "<code>[5, 3, 5]</code>" in html and "<code>[1.66667, 4.33333, 7.66667]</code>" in html
    assert "|" not in html
