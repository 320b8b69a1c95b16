"""Tests of cagd_course.manifest (the book.toml manifest) and of the exercise contract it points to."""

from __future__ import annotations

import importlib
import inspect
import re
from pathlib import Path

import pytest

from cagd_course import manifest as course

# The exercise contract of DESIGN.md for the modules of the chapters landed so far: the reference must keep
# these names and (leading) parameters, because student versions are graded against them.
CONTRACT = {
    "cagd_ref.geometry": {
        "rotate_about_axis": ["point", "axis_point", "axis_direction", "angle"],
        "rotation_matrix": ["axis_point", "axis_direction", "angle"],
        "projection": ["p", "q"],
        "triangle_area": ["p1", "p2", "p3"],
        "conic_type": ["a", "b", "c", "d", "e", "f"],
    },
    "cagd_ref.bezier": {
        "bernstein": ["i", "n", "t"],
        "de_casteljau": ["points", "t"],
        "subdivide": ["points", "t"],
        "elevate": ["points"],
        "hodograph": ["points", "interval"],
        "evaluate": ["points", "t", "weights"],
        "curvature": ["points", "t", "weights"],
        "to_homogeneous": ["points", "weights"],
        "from_homogeneous": ["homogeneous"],
    },
    "cagd_ref.polynomials": {
        "horner": ["coeffs", "t"],
        "bernstein_horner": ["coeffs", "t"],
        "power_to_bernstein": ["coeffs"],
        "bernstein_to_power": ["coeffs"],
        "bernstein_multiply": ["f", "g"],
        "bernstein_integral": ["coeffs"],
    },
    "cagd_ref.forward_differencing": {
        "forward_difference_table": ["values"],
        "forward_difference_eval": ["coeffs", "t0", "delta", "count"],
    },
    "cagd_ref.blending": {
        "timmer_basis": ["t"],
        "ball_basis": ["t"],
        "overhauser_point": ["points", "t"],
        "timmer_to_bezier": ["points"],
    },
    "cagd_ref.bspline": {
        "de_boor": ["points", "knots", "t"],
        "insert_knot": ["points", "knots", "t"],
        "bezier_segments": ["points", "knots"],
        "blossom": ["points", "knots", "args"],
        "bspline_basis": ["knots", "degree", "i", "t"],
        "greville": ["knots", "degree"],
    },
    "cagd_ref.intersection": {
        "line_intersection": ["l1", "l2"],
        "fat_line": ["points"],
        "clip_range": ["coeffs", "dmin", "dmax"],
        "intersect_curves": ["p", "q", "tol"],
    },
    "cagd_ref.offsets": {
        "offset_point": ["points", "t", "rho", "weights"],
        "offset_cusps": ["points", "rho", "weights"],
        "ph_cubic": ["p0", "u", "v"],
        "ph_offset": ["points", "rho"],
    },
    "cagd_ref.roots": {
        "bernstein_roots": ["coeffs", "interval", "tol"],
        "hull_march": ["coeffs", "interval", "tol"],
        "deflate": ["coeffs"],
        "bernstein_from_roots": ["roots", "interval", "leading"],
        "line_curve_intersection": ["points", "line", "weights"],
    },
    "cagd_ref.interpolation": {
        "lagrange_eval": ["ts", "points", "t"],
        "divided_differences": ["ts", "values"],
        "newton_eval": ["ts", "coeffs", "t"],
        "neville": ["ts", "points", "t"],
        "chebyshev_nodes": ["a", "b", "n"],
        "hermite_to_bezier": ["p0", "p1", "d0", "d1"],
    },
    "cagd_ref.approximation": {
        "chord_length_parameters": ["points"],
        "least_squares_fit": ["points", "params", "knots", "degree"],
        "fairing_matrix": ["knots", "degree"],
        "faired_fit": ["points", "params", "knots", "degree", "weight"],
    },
    "cagd_ref.interval_bezier": {
        "interval_de_casteljau": ["boxes", "t"],
    },
    "cagd_ref.floating": {
        "decode_float": ["bits"],
        "round_to_bits": ["x", "d"],
        "affine_roundoff": ["p0", "p1", "t", "eta"],
        "rounded_de_casteljau": ["points", "t", "eta"],
    },
}


@pytest.mark.parametrize("module, name, parameters", [
    (module, name, parameters) for module, functions in CONTRACT.items() for name, parameters in functions.items()
])
def test_reference_keeps_the_contract_signatures(module, name, parameters):
    function = getattr(importlib.import_module(module), name)
    assert name in importlib.import_module(module).__all__
    signature = inspect.signature(function)
    assert list(signature.parameters)[: len(parameters)] == parameters
    # Anything after the contract's parameters is optional, so the contract call works.
    extra = list(signature.parameters.values())[len(parameters):]
    assert all(p.default is not inspect.Parameter.empty for p in extra)
    defaults = {"hodograph": {"interval": (0, 1)}, "evaluate": {"weights": None}, "curvature": {"weights": None}}
    for parameter, default in defaults.get(name, {}).items():
        assert signature.parameters[parameter].default == default


# --- the real manifest ---------------------------------------------------------------------------


@pytest.fixture(scope="module")
def book() -> course.Course:
    return course.load_course()


def test_manifest_is_found_from_the_working_directory(book, tmp_path, monkeypatch):
    root = Path(__file__).resolve().parents[2]
    assert book.root == root
    monkeypatch.delenv(course.COURSE_ENV, raising=False)
    # From a notebook's folder the search goes upward; an explicit folder wins over it.
    monkeypatch.chdir(root / "chapters")
    assert course.find_course_root() == root
    (tmp_path / "book.toml").write_text("", encoding="utf-8")
    monkeypatch.setenv(course.COURSE_ENV, str(tmp_path))
    assert course.find_course_root() == tmp_path.resolve()
    assert book.title and book.chapters
    numbers = [chapter.number for chapter in book.chapters]
    assert numbers == sorted(set(numbers))
    assert {1, 2} <= set(numbers)


def test_chapter_paths_follow_the_layout(book):
    for chapter in book.chapters:
        assert chapter.notebook.parent == book.root / "chapters"
        assert re.fullmatch(rf"{chapter.number:02d}-[a-z0-9-]+", chapter.slug), chapter.slug
        assert chapter.notebook.suffix == ".ipynb"
        if chapter.exercises is not None:
            assert chapter.exercises == book.root / "exercises" / chapter.notebook.name
        if chapter.hidden is not None:
            assert chapter.hidden == book.root / "tests" / "hidden" / f"ch{chapter.number:02d}.py"


def test_every_exercise_names_a_reference_function(book):
    for chapter in book.chapters:
        modules = [importlib.import_module(name) for name in chapter.modules]
        for exercise_id, points in chapter.exercise_points.items():
            number, _, function = exercise_id.partition(".")
            assert number == f"{chapter.number:02d}", exercise_id
            assert points > 0, exercise_id
            assert any(callable(getattr(module, function, None)) for module in modules), (
                f"{exercise_id}: no function {function!r} in {chapter.modules}"
            )


def test_chapter_two_grades_the_core_contract(book):
    chapter = next(ch for ch in book.chapters if ch.number == 2)
    assert {"cagd_ref.bezier", "cagd_ref.polynomials"} <= set(chapter.modules)
    assert {"02.de_casteljau", "02.subdivide", "02.evaluate"} <= set(chapter.exercise_points)


def test_exercise_points_and_lookup(book):
    points = book.exercise_points()
    per_chapter = [eid for ch in book.chapters for eid in ch.exercise_points]
    assert list(points) == per_chapter  # manifest order, no duplicates lost
    assert len(set(per_chapter)) == len(per_chapter)
    for exercise_id in points:
        assert exercise_id in book.chapter_of(exercise_id).exercise_points
    with pytest.raises(KeyError, match="99.nothing"):
        book.chapter_of("99.nothing")


# --- manifests written for the test ------------------------------------------------------------------


def write_manifest(root: Path, text: str) -> Path:
    (root / "book.toml").write_text(text, encoding="utf-8")
    return root


def test_load_a_small_manifest(tmp_path):
    root = write_manifest(tmp_path, """
[book]
title = "Tiny"
subtitle = "a test"

[[chapters]]
number = 3
title = "Three"
notebook = "chapters/03-three.ipynb"
exercises = "exercises/03-three.ipynb"
hidden = "tests/hidden/ch03.py"
modules = ["cagd_ref.polynomials"]

[chapters.exercise_points]
"03.horner" = 2
"03.bernstein_horner" = 1.5

[[chapters]]
number = 4
title = "Four, no exercises"
notebook = "chapters/04-four.ipynb"
""")
    book = course.load_course(str(root))
    assert (book.title, book.subtitle, book.root) == ("Tiny", "a test", root)
    three, four = book.chapters
    assert three.number == 3 and three.slug == "03-three"
    assert three.notebook == root / "chapters/03-three.ipynb"
    assert three.exercises == root / "exercises/03-three.ipynb"
    assert three.hidden == root / "tests/hidden/ch03.py"
    assert three.modules == ("cagd_ref.polynomials",)
    assert (four.exercises, four.hidden, four.modules, four.exercise_points) == (None, None, (), {})
    assert book.exercise_points() == {"03.horner": 2, "03.bernstein_horner": 1.5}
    assert book.chapter_of("03.bernstein_horner") is three
    with pytest.raises(AttributeError):
        three.number = 5  # frozen


def test_manifest_defaults_and_missing_file(tmp_path):
    book = course.load_course(write_manifest(tmp_path, ""))
    assert (book.title, book.subtitle, book.chapters) == ("CAGD", "", ())
    with pytest.raises(FileNotFoundError, match="book.toml"):
        course.load_course(tmp_path / "elsewhere")
