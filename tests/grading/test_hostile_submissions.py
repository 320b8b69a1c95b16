"""A corpus of hostile and broken submissions: each gets exactly the expected gradebook row and changes nothing.

Every hostile submission is the correct chapter-1 solution plus one later cell
that redefines `projection` (1 point) badly, so the expected row is 9/10 (or 10)
with a plain-words status. The whole class is graded once, with short limits,
and afterwards no process any of them started may be left: each hostile
process renames itself ``hx-...`` so the test can look for it.
"""

import csv
import hashlib
import json
import shutil
import tempfile
from pathlib import Path

import nbformat
import pytest
import tomllib

from cagd_course.grading import runner
from cagd_course.grading.classroom import grade_class
from cagd_course.grading.runner import Limits

ROOT = Path(__file__).resolve().parents[2]
SOLUTION = Path(__file__).parent / "fixtures" / "submissions" / "complete.ipynb"
LIMITS = Limits(exercise_seconds=3, submission_seconds=30, memory_mb=512, output_bytes=10_000)
OUT_MARKER = "@OUT@"
# Files of the checkout a submission tries to overwrite: the course's own, which no other test edits while this
# one runs (book.toml is edited by people, so it is checked for the attack's mark, not hashed), and a decoy.
HIDDEN_SUITE = ROOT / "tests" / "hidden" / "ch01.py"
DECOY = Path(__file__).parent / ".hostile-decoy.txt"
# Another submission's scratch folder, as graded code would find it next to its own.
OTHER_FOLDER_MARKER = "@OTHER@"
NAME = "import ctypes\ndef _name(label):\n    ctypes.CDLL(None).prctl(15, label, 0, 0, 0)\n"
CORRECT = (
    "    p, q = np.asarray(p, float), np.asarray(q, float)\n"
    "    if p.shape != q.shape or p.ndim != 1 or not q.any():\n        raise ValueError('p, q')\n"
    "    return p @ q / (q @ q) * q"
)

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
        + str(HIDDEN_SUITE)
        + "', '"
        + str(DECOY)
        + "', '"
        + OUT_MARKER
        + "/other/results.json']:\n"
        "        with open(target, 'w') as handle:\n            handle.write('pwned')",
        9,
        "ok",
    ),
    # Confined, the reference cannot even be read: 0 points for the exercise that tries.
    "reads_reference_by_path": (
        "import importlib, importlib.util, sys\n"
        "def projection(p, q):\n"
        f"    root = {str(ROOT / 'cagd_ref')!r}\n"
        "    spec = importlib.util.spec_from_file_location('stolen', root + '/__init__.py', "
        "submodule_search_locations=[root])\n"
        "    module = importlib.util.module_from_spec(spec)\n"
        "    sys.modules['stolen'] = module\n"
        "    spec.loader.exec_module(module)\n"
        "    return importlib.import_module('stolen.geometry').projection(p, q)",
        9,
        "ok",
    ),
    "daemonises": (
        NAME + "import os, time\n"
        "def projection(p, q):\n"
        "    if os.fork() == 0:\n"
        "        os.setsid()\n"
        "        if os.fork() == 0:\n"
        "            _name(b'hx-daemonises')\n"
        "            time.sleep(120)\n"
        "        os._exit(0)\n"
        "    return q",
        9,
        "ok",
    ),
    "fork_bomb": (
        NAME + "import os\ndef projection(p, q):\n    _name(b'hx-fork_bomb')\n    while True:\n        os.fork()",
        9,
        "ok",
    ),
    "writes_other_submission": (
        "import glob, os\nimport numpy as np\n"
        "def projection(p, q):\n"
        f"    for folder in glob.glob({tempfile.gettempdir()!r} + '/cagd-grade-*') + ['{OTHER_FOLDER_MARKER}']:\n"
        "        for name in ('results.json', 'pwned.txt'):\n"
        "            try:\n"
        "                with open(os.path.join(folder, name), 'w') as handle:\n"
        "                    handle.write('pwned')\n"
        "            except OSError:\n"
        "                pass\n" + CORRECT,
        10,
        "ok",
    ),
    "outlives_deadline": (
        NAME + "import os, time\nimport numpy as np\n"
        "def projection(p, q):\n"
        "    try:\n"
        "        if os.fork() == 0:\n"
        "            _name(b'hx-outlives_dea')\n"
        "            time.sleep(120)\n"
        "            os._exit(0)\n"
        "    except OSError:\n"
        "        pass\n" + CORRECT,
        10,
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


def _digests(paths) -> dict[str, str]:
    return {str(path): hashlib.sha256(path.read_bytes()).hexdigest() for path in paths}


@pytest.fixture(scope="module")
def graded(tmp_path_factory, processes):
    probe = runner.probe(LIMITS)
    if not probe.confined:
        # Unconfined, these submissions would really overwrite the course's files.
        pytest.skip(f"graded code cannot be confined here ({probe.sandbox}); the corpus is not run")
    submissions = tmp_path_factory.mktemp("hostile")
    out = tmp_path_factory.mktemp("graded")
    (out / "other").mkdir()
    (out / "other" / "results.json").write_text("{}")
    other = Path(tempfile.mkdtemp(prefix="cagd-grade-victim-"))
    (other / "results.json").write_text("{}")
    DECOY.write_text("a file of the checkout no submission may change\n")
    solution = nbformat.read(SOLUTION, as_version=4)
    for name, (source, _, _) in HOSTILE.items():
        notebook = nbformat.from_dict(json.loads(json.dumps(solution)))
        text = source.replace(OUT_MARKER, str(out)).replace(OTHER_FOLDER_MARKER, str(other))
        notebook.cells.append(nbformat.v4.new_code_cell(text))
        nbformat.write(notebook, submissions / f"{name}.ipynb")
    for name, (text, _) in BROKEN_FILES.items():
        (submissions / f"{name}.ipynb").write_text(text)
    targets = [HIDDEN_SUITE, DECOY, other / "results.json"]
    before = _digests(targets)
    try:
        grade_class([submissions], out, jobs=2, limits=LIMITS, seed=11, progress=False, chapters=[1])
        after = _digests(targets)
        leftovers = {name: processes.named(f"hx-{name}") for name in HOSTILE}
        leftovers["grader"] = processes.grading()
        others = sorted(p.name for p in other.iterdir())
    finally:
        DECOY.unlink()
        shutil.rmtree(other)
    with (out / "gradebook.csv").open() as handle:
        rows = {row["submission"]: row for row in csv.DictReader(handle)}
    return rows, out, before, after, leftovers, others


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
    _, out, before, after, _, others = graded
    assert before == after
    assert (out / "other" / "results.json").read_text() == "{}"
    assert others == ["results.json"]  # nothing added to another submission's folder either
    book = (ROOT / "book.toml").read_text(encoding="utf-8")
    assert "pwned" not in book and tomllib.loads(book)["chapters"]


@pytest.mark.parametrize("name", list(HOSTILE))
def test_no_process_a_submission_started_outlives_the_grading(graded, name):
    *_, leftovers, _ = graded
    assert leftovers[name] == []
    assert leftovers["grader"] == []


def test_reading_the_reference_by_path_scores_nothing_where_the_row_says_it_was_confined(graded):
    rows, *_ = graded
    row = rows["reads_reference_by_path"]
    assert "landlock ABI" in row["confinement"] and row["01.projection"] == "0"


def test_every_row_says_its_code_ran_confined(graded):
    rows, *_ = graded
    for name in HOSTILE:
        assert "landlock ABI" in rows[name]["confinement"], rows[name]
    assert all(rows[name]["confinement"] == "" for name in BROKEN_FILES)  # nothing of theirs ran


def test_captured_output_is_truncated_not_lost(graded):
    _, out, *_ = graded
    feedback = json.loads((out / "output_flood" / "results.json").read_text())
    assert feedback["score"] == 10
