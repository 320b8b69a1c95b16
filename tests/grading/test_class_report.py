"""What an instructor takes away from the grades folder: the LMS files, the class report and the similarity flags."""

import csv
import importlib.util
import inspect
import io
import re
from html.parser import HTMLParser
from pathlib import Path

import pytest

from cagd_course.cli import main
from cagd_course.grading.classroom import grade_class
from cagd_course.grading.runner import Limits
from cagd_course.grading.similarity import MIN_NODES, fingerprint
from cagd_course.manifest import load_course

HERE = Path(__file__).parent
spec = importlib.util.spec_from_file_location("semester", HERE / "fixtures" / "semester.py")
semester = importlib.util.module_from_spec(spec)
spec.loader.exec_module(semester)
LIMITS = Limits(exercise_seconds=5, submission_seconds=60)

# ada's rotate_about_axis, with every name changed, reformatted, a comment and a docstring added.
RENAMED = '''
def rotate_about_axis(pt, base, direction, theta):
    """Turn pt about the axis."""
    p = np.array(pt, dtype=float)
    b = np.array(base, dtype=float)
    d = np.array(direction, dtype=float)
    if p.shape[-1:] != (3,) or p.ndim > 2 or b.shape != (3,) or d.shape != (3,):
        raise ValueError("three dimensions")
    size = np.linalg.norm(d)   # length of the axis
    if size == 0:
        raise ValueError("no axis")
    d = d / size
    centre = b + ((p - b) @ d)[..., None] * d
    radial = p - centre
    side = np.cross(d, radial)
    return centre + radial * np.cos(theta) + side * np.sin(theta)
'''
# An honest solution of the same exercise (Rodrigues' formula).
HONEST = '''
def rotate_about_axis(point, axis_point, axis_direction, angle):
    p = np.asarray(point, dtype=float)
    b = np.asarray(axis_point, dtype=float)
    k = np.asarray(axis_direction, dtype=float)
    if p.shape[-1] != 3 or b.shape != (3,) or k.shape != (3,) or p.ndim > 2:
        raise ValueError("point, axis_point, axis_direction: 3-D vectors")
    length = np.sqrt(k @ k)
    if length == 0:
        raise ValueError("axis_direction must not be zero")
    k = k / length
    x = p - b
    c, s = np.cos(angle), np.sin(angle)
    along = (x @ k)[..., None] * k
    return b + x * c + np.cross(k, x) * s + along * (1 - c)
'''


@pytest.fixture(scope="module")
def grades(tmp_path_factory):
    root = tmp_path_factory.mktemp("class")
    stub = semester.stub_notebook(1)
    semester.write(root / "ada" / "01-introduction.ipynb", semester.chapter_notebook(1))
    semester.write(root / "ada" / "02-bezier-curves.ipynb", semester.chapter_notebook(2))
    semester.write(root / "eve" / "01-introduction.ipynb", semester.with_cell(stub, "import numpy as np\n" + RENAMED))
    semester.write(root / "hal" / "01-introduction.ipynb", semester.with_cell(stub, "import numpy as np\n" + HONEST))
    import cagd_ref.geometry as geometry

    copied = "import numpy as np\n" + inspect.getsource(geometry.projection)
    semester.write(root / "ref" / "01-introduction.ipynb", semester.with_cell(stub, copied))
    semester.write(root / "zoe" / "01-introduction.ipynb", semester.with_cell(
        semester.chapter_notebook(1), "def conic_type(a, b, c, d, e, f):\n    while True:\n        pass\n"))
    semester.write(root / "zoe" / "02-bezier-curves.ipynb", "not a notebook")
    semester.write(root / "amb" / "both.ipynb", semester.COMPLETE)
    out = tmp_path_factory.mktemp("grades")
    summary = grade_class([root], out, limits=Limits(exercise_seconds=2, submission_seconds=60), progress=False)
    return out, summary


# --- similarity -----------------------------------------------------------------------------------------------


def _flags(out):
    table = re.search(r"<table class='similar'>.*?</table>", (out / "report.html").read_text(), re.S)
    if table is None:
        return []
    rows = [[re.sub(r"<.*?>", "", c) for c in re.findall(r"<td>(.*?)</td>", row)]
            for row in re.findall(r"<tr>(.*?)</tr>", table.group(0))]
    return [row for row in rows if row]


def test_a_renamed_reformatted_copy_is_flagged_and_an_honest_solution_is_not(grades):
    flags = _flags(grades[0])
    assert ["1", "ada", "eve", "01.rotate_about_axis"] in flags
    assert not any("hal" in row for row in flags)
    # the stubs every one of them left untouched, and zoe's complete copy of the fixture, are what ada shares
    assert all(row[1:3] in (["ada", "eve"], ["ada", "zoe"], ["eve", "zoe"], ["ref", "reference implementation"])
               for row in flags), flags


def test_a_copy_of_the_reference_implementation_is_flagged(grades):
    assert ["1", "ref", "reference implementation", "01.projection"] in _flags(grades[0])


def test_fingerprints_ignore_names_formatting_and_docstrings_but_not_structure():
    import ast

    a = ast.parse("def f(x, y):\n    '''doc'''\n    z = x + y  # sum\n    return z * 2\n").body[0]
    b = ast.parse("def g(p, q):\n    r = (p\n         + q)\n    return r * 2\n").body[0]
    c = ast.parse("def f(x, y):\n    z = y + x\n    return z * 2\n").body[0]
    assert fingerprint(a)[0] == fingerprint(b)[0] != fingerprint(c)[0]
    assert fingerprint(a)[1] < MIN_NODES  # too small to flag at all


# --- the class report ---------------------------------------------------------------------------------------


class _Figures(HTMLParser):
    def __init__(self):
        super().__init__()
        self.figures, self.external = [], []

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "figure":
            self.figures.append(attrs)
        for key in ("src", "href"):
            if attrs.get(key, "").startswith(("http:", "https:", "//")):
                self.external.append(attrs[key])
        if tag in ("script", "link", "img", "iframe"):
            self.external.append(tag)


def test_the_report_has_a_histogram_per_chapter_and_per_exercise(grades):
    out, _ = grades
    page = (out / "report.html").read_text()
    parser = _Figures()
    parser.feed(page)
    assert parser.external == []  # self-contained: no script, no stylesheet or image from anywhere
    chapters = {f["data-key"]: f for f in parser.figures if f["data-kind"] == "chapter"}
    exercises = {f["data-key"]: f for f in parser.figures if f["data-kind"] == "exercise"}
    assert sorted(chapters) == ["1", "2"]
    assert sum(map(int, chapters["1"]["data-counts"].split(","))) == 5  # ada eve hal ref zoe (amb's is unclear)
    assert sum(map(int, chapters["2"]["data-counts"].split(","))) == 2
    course = load_course()
    assert set(exercises) == set(course.chapters[0].exercise_points) | set(course.chapters[1].exercise_points)
    # ada and zoe in full; eve and hal left the stub, ref's copy needs the reference's helpers: 0
    assert exercises["01.projection"]["data-counts"] == "3,0,0,0,0,2"


def test_the_report_names_hidden_categories_never_their_inputs(grades):
    out, _ = grades
    page = (out / "report.html").read_text()
    table = re.search(r"<table class='hidden'>.*?</table>", page, re.S).group(0)
    rows = [re.findall(r"<td>(.*?)</td>", r) for r in re.findall(r"<tr>(.*?)</tr>", table)][1:]
    assert rows and all(len(r) == 4 for r in rows)
    assert all(r[1] in ("random", "bad input", "several points", "random rotations", "random conics") or r[1]
               for r in rows)
    assert not re.search(r"\d\.\d{4,}", table)  # no numbers of any input


def test_the_report_lists_the_slowest_exercises_and_what_did_not_run_cleanly(grades):
    out, _ = grades
    page = (out / "report.html").read_text()
    slowest = re.search(r"<table class='slowest'>.*?</table>", page, re.S).group(0)
    assert "<td>01.conic_type</td>" in slowest.split("</tr>")[1]  # zoe's endless loop makes it the slowest
    unclean = re.search(r"<table class='unclean'>.*?</table>", page, re.S).group(0)
    assert "zoe" in unclean and "timed out after 2 s" in unclean and "invalid notebook (not valid JSON)" in unclean
    unassigned = re.search(r"<table class='unassigned'>.*?</table>", page, re.S).group(0)
    assert "both.ipynb" in unassigned and "several chapters" in unassigned


def test_the_report_command_rewrites_it(grades, capsys):
    out, _ = grades
    (out / "report.html").unlink()
    assert main(["report", str(out)]) == 0 and (out / "report.html").is_file()
    assert "class report:" in capsys.readouterr().out


# --- export for the LMS -------------------------------------------------------------------------------------


def _csv(text):
    return list(csv.reader(io.StringIO(text)))


def test_the_canvas_csv_has_canvas_columns_points_possible_and_the_chapter_totals(grades, tmp_path):
    out, _ = grades
    target = tmp_path / "canvas.csv"
    assert main(["export", str(out), "--canvas", str(target)]) == 0
    rows = _csv(target.read_text())
    course = load_course()
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section",
                       f"Chapter 1: {course.chapters[0].title}", f"Chapter 2: {course.chapters[1].title}"]
    assert rows[1] == ["    Points Possible", "", "", "", "", "10", "21"]
    body = {row[0]: row for row in rows[2:]}
    assert body["ada"] == ["ada", "", "", "ada", "", "10", "21"]
    assert body["eve"][5:] == [body["eve"][5], ""] and float(body["eve"][5]) < 10  # no chapter 2: left blank
    assert body["zoe"][6] == "0"


def test_a_roster_gives_canvas_ids_and_existing_assignment_columns(grades, tmp_path):
    out, _ = grades
    roster = tmp_path / "roster.csv"
    roster.write_text(
        "Student,ID,SIS User ID,SIS Login ID,Section,Chapter 1 exercises (5501),Notes\n"
        "    Points Possible,,,,,10,\n"
        '"Lovelace, Ada",101,S101,ada,Sec A,,\n'
        '"Eve, Evans",102,S102,eve,Sec A,,\n', encoding="utf-8")
    target = tmp_path / "canvas.csv"
    assert main(["export", str(out), "--canvas", str(target), "--roster", str(roster)]) == 0
    rows = _csv(target.read_text())
    assert rows[0][5] == "Chapter 1 exercises (5501)" and rows[0][6].startswith("Chapter 2: ")
    ada = next(r for r in rows if r[1] == "101")
    assert ada[:5] == ["Lovelace, Ada", "101", "S101", "ada", "Sec A"] and ada[5:] == ["10", "21"]


def test_the_long_csv_has_one_line_per_student_chapter_and_exercise(grades, tmp_path):
    out, _ = grades
    target = tmp_path / "long.csv"
    assert main(["export", str(out), "--long", str(target)]) == 0
    rows = _csv(target.read_text())
    assert rows[0] == ["student", "chapter", "exercise", "score", "max", "status"]
    assert ["ada", "2", "02.subdivide", "3", "3", "ok"] in rows
    assert ["zoe", "1", "01.conic_type", "0", "2", "timed out after 2 s"] in rows
    assert ["zoe", "2", "02.bernstein", "0", "1", "invalid notebook (not valid JSON)"] in rows
    assert len(rows) == 1 + 6 * 5 + 2 * 10 - 5  # six chapter-1 notebooks minus amb's, two of chapter 2


def test_export_without_a_target_or_grades_is_a_clear_error(tmp_path, capsys):
    assert main(["export", str(tmp_path)]) == 2
    assert "--canvas" in capsys.readouterr().err
    assert main(["export", str(tmp_path), "--long", str(tmp_path / "x.csv")]) == 2
    assert "no graded notebooks" in capsys.readouterr().err
