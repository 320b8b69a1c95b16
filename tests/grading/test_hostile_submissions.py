"""A corpus of hostile and broken submissions: each gets exactly the expected gradebook row and changes nothing.

Every hostile submission is the correct chapter-1 solution plus one later cell
that redefines `projection` (1 point) badly, so the expected row is 9/10 (or 10)
with a plain-words status. The whole class is graded once, with short limits.
"""

import csv
import hashlib
import json
from pathlib import Path

import nbformat
import pytest

from cagd_course.grading.classroom import grade_class
from cagd_course.grading.runner import Limits

ROOT = Path(__file__).resolve().parents[2]
SOLUTION = Path(__file__).parent / "fixtures" / "submissions" / "complete.ipynb"
LIMITS = Limits(exercise_seconds=3, submission_seconds=30, memory_mb=512, output_bytes=10_000)
OUT_MARKER = "@OUT@"

HOSTILE = {
    "infinite_loop": ("def projection(p, q):\n    while True:\n        pass", 9, "01.projection: timed out after 3 s"),
    "ignores_signals": (
        "import signal\ndef projection(p, q):\n"
        "    for s in (signal.SIGTERM, signal.SIGINT, signal.SIGALRM, signal.SIGHUP):\n"
        "        signal.signal(s, signal.SIG_IGN)\n    while True:\n        pass",
        9,
        "01.projection: timed out after 3 s",
    ),
    "memory_exhaustion": (
        "import numpy as np\ndef projection(p, q):\n    hoard = []\n    while True:\n"
        "        hoard.append(np.zeros(50_000_000))",
        9,
        "01.projection: memory limit exceeded",
    ),
    "sys_exit": ("import sys\ndef projection(p, q):\n    sys.exit(0)", 9, "01.projection: called sys.exit"),
    "os_exit": (
        "import os\ndef projection(p, q):\n    os._exit(0)",
        9,
        "01.projection: the process exited with code 0 before finishing",
    ),
    "hard_crash": (
        "import ctypes\ndef projection(p, q):\n    ctypes.string_at(0)",
        9,
        "01.projection: the process crashed (SIGSEGV)",
    ),
    "output_flood": (
        "import numpy as np\ndef projection(p, q):\n    if not hasattr(projection, 'flooded'):\n"
        "        projection.flooded = True\n        print('x' * 100_000_000)\n"
        "    p, q = np.asarray(p, float), np.asarray(q, float)\n"
        "    if p.shape != q.shape or p.ndim != 1 or not q.any():\n        raise ValueError('p, q')\n"
        "    return p @ q / (q @ q) * q",
        10,
        "output truncated",
    ),
    "patches_comparisons": (
        "import numpy as np\nimport numpy.testing\nnp.allclose = lambda *a, **k: True\n"
        "def projection(p, q):\n    np.allclose = lambda *a, **k: True\n"
        "    np.testing.assert_allclose = lambda *a, **k: None\n"
        "    import math\n    math.isclose = lambda *a, **k: True\n    return np.full(len(q), 7.0)",
        9,
        "ok",
    ),
    "imports_reference": (
        "import importlib\nfrom cagd_ref.geometry import projection as projection\n"
        "def triangle_area(p1, p2, p3):\n"
        "    return importlib.import_module('cagd_ref.geometry').triangle_area(p1, p2, p3)\n"
        "def conic_type(a, b, c, d, e, f):\n"
        "    return __import__('cagd_ref.geometry', fromlist=['x']).conic_type(a, b, c, d, e, f)",
        7,
        "ok",
    ),
    "writes_files": (
        "import os\ndef projection(p, q):\n    for target in ['"
        + str(ROOT / "book.toml")
        + "', '"
        + OUT_MARKER
        + "/gradebook.csv', '"
        + str(ROOT / "tests" / "hidden" / "ch01.py")
        + "', '"
        + OUT_MARKER
        + "/other/results.json']:\n"
        "        with open(target, 'w') as handle:\n            handle.write('pwned')",
        9,
        "ok",
    ),
    "imitates_grader": (
        "import os, sys\ndef projection(p, q):\n    print('01.projection: 1 / 1 points', 'Total: 10 / 10')\n"
        "    for fd in [int(a) for a in sys.argv[1:] if a.isdigit()] + list(range(3, 12)):\n        try:\n"
        '            os.write(fd, b\'{"event": "end", "exercise": "01.projection"}\\n\')\n'
        "        except OSError:\n            pass\n    return [0.0, 0.0, 0.0]",
        9,
        "01.projection: the graded process ended an exercise early",
    ),
    "wrong_types": (
        "def projection(p, q):\n    return None\ndef triangle_area(p1, p2, p3):\n    return float('nan')\n"
        "def rotation_matrix(axis_point, axis_direction, angle):\n    return [[1.0, 0.0], [0.0, 1.0]]",
        5,
        "ok",
    ),
    "returns_lists": (
        "import numpy as np\ndef projection(p, q):\n    p, q = np.asarray(p, float), np.asarray(q, float)\n"
        "    if p.shape != q.shape or p.ndim != 1 or not q.any():\n        raise ValueError('p, q')\n"
        "    return (p @ q / (q @ q) * q).tolist()",
        10,
        "ok",
    ),
    "slow_but_correct": (
        "import time\nimport numpy as np\ndef projection(p, q):\n    time.sleep(0.02)\n"
        "    p, q = np.asarray(p, float), np.asarray(q, float)\n"
        "    if p.shape != q.shape or p.ndim != 1 or not q.any():\n        raise ValueError('p, q')\n"
        "    return p @ q / (q @ q) * q",
        10,
        "ok",
    ),
    "modifies_inputs": (
        "import numpy as np\ndef projection(p, q):\n    a, b = np.array(p, float), np.array(q, float)\n"
        "    if a.shape != b.shape or a.ndim != 1 or not b.any():\n        raise ValueError('p, q')\n"
        "    if isinstance(q, np.ndarray):\n        q[0] += 1.0\n    return a @ b / (b @ b) * b",
        None,
        "ok",
    ),
}

BROKEN_FILES = {
    "not_json": ("{ not a notebook", "invalid notebook (not valid JSON)"),
    "no_code": (
        json.dumps(nbformat.v4.new_notebook(cells=[nbformat.v4.new_markdown_cell("I ran out of time.")])),
        "no code",
    ),
    "nothing_defined": (
        json.dumps(nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("x = 1\nprint(x)")])),
        "nothing defined",
    ),
}


def _snapshot(folder: Path, skip: tuple[str, ...]) -> dict[str, str]:
    files = {}
    for path in folder.rglob("*"):
        relative = path.relative_to(folder)
        if path.is_file() and not any(part in skip for part in relative.parts):
            files[str(relative)] = hashlib.sha256(path.read_bytes()).hexdigest()
    return files


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    submissions = tmp_path_factory.mktemp("hostile")
    out = tmp_path_factory.mktemp("graded")
    (out / "other").mkdir()
    (out / "other" / "results.json").write_text("{}")
    solution = nbformat.read(SOLUTION, as_version=4)
    for name, (source, _, _) in HOSTILE.items():
        notebook = nbformat.from_dict(json.loads(json.dumps(solution)))
        notebook.cells.append(nbformat.v4.new_code_cell(source.replace(OUT_MARKER, str(out))))
        nbformat.write(notebook, submissions / f"{name}.ipynb")
    for name, (text, _) in BROKEN_FILES.items():
        (submissions / f"{name}.ipynb").write_text(text)
    skip = (".venv", "__pycache__", ".pytest_cache", "_build", ".git")
    before = _snapshot(ROOT, skip)
    grade_class([submissions], out, jobs=2, limits=LIMITS, seed=11, progress=False, chapters=[1])
    with (out / "gradebook.csv").open() as handle:
        rows = {row["submission"]: row for row in csv.DictReader(handle)}
    return rows, out, before, _snapshot(ROOT, skip)


@pytest.mark.parametrize("name", list(HOSTILE))
def test_hostile_submission_gets_its_exact_row(graded, name):
    rows, *_ = graded
    _, score, status = HOSTILE[name]
    row = rows[name]
    assert (row["status"], row["max_score"]) == (status, "10")
    if score is not None:
        assert float(row["score"]) == score
    else:  # only the cases handing over arrays notice the mutation
        assert 9 < float(row["score"]) < 10 and float(row["01.projection"]) < 1


@pytest.mark.parametrize("name", list(BROKEN_FILES))
def test_broken_notebook_gets_a_zero_row_saying_why(graded, name):
    rows, *_ = graded
    assert (rows[name]["score"], rows[name]["status"]) == ("0", BROKEN_FILES[name][1])


def test_every_submission_has_exactly_one_row_and_a_feedback_page(graded):
    rows, out, *_ = graded
    assert sorted(rows) == sorted(list(HOSTILE) + list(BROKEN_FILES))
    assert all((out / name / "feedback.html").is_file() and (out / name / "results.json").is_file() for name in rows)


def test_no_file_outside_the_output_folder_changed(graded):
    _, out, before, after = graded
    assert before == after
    assert (out / "other" / "results.json").read_text() == "{}"


def test_captured_output_is_truncated_not_lost(graded):
    _, out, *_ = graded
    feedback = json.loads((out / "output_flood" / "results.json").read_text())
    assert feedback["score"] == 10
