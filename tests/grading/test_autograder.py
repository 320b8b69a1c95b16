"""`cagd autograder`: one chapter's Gradescope autograder, built, installed and run as Gradescope does.

The zip of chapter 1 is unpacked into a temporary root laid out as Gradescope lays out /autograder
(CAGD_AUTOGRADER_ROOT relocates it), setup.sh installs the course's own wheel into ROOT/venv without
network (a venv that sees this Python's NumPy; pip offline), and run_autograder grades one submission
at a time: the reference solution, the stub, a recorded mistake, a hostile notebook, another chapter's.
Each results.json is checked against the fields of Gradescope's autograder specification. As root, the
graded code runs as the unprivileged user `nobody` (setup.sh's own user is for real containers).
"""

from __future__ import annotations

import importlib.util
import json
import os
import pwd
import shutil
import stat
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

import pytest

from cagd_course.cli import main
from cagd_course.grading.autograder import ROOT_ENV, USER_ENV, build_autograder
from cagd_course.grading.runner import Limits

HERE = Path(__file__).parent
ROOT = HERE.parents[1]
spec = importlib.util.spec_from_file_location("semester", HERE / "fixtures" / "semester.py")
semester = importlib.util.module_from_spec(spec)
spec.loader.exec_module(semester)

LIMITS = Limits(exercise_seconds=5, submission_seconds=60, memory_mb=512)
AS_ROOT = os.geteuid() == 0
TEST_USER = "nobody"
# Gradescope's results.json (autograder specification): the fields a result and a test may carry.
TOP_FIELDS = {"score", "execution_time", "output", "output_format", "test_output_format", "test_name_format",
              "visibility", "stdout_visibility", "extra_data", "tests", "leaderboard"}
TEST_FIELDS = {"score", "max_score", "status", "name", "name_format", "number", "output", "output_format", "tags",
               "visibility", "extra_data"}
VISIBILITIES = {"visible", "hidden", "after_due_date", "after_published"}
BASE_PYTHON = getattr(sys, "_base_executable", sys.executable)


def validate(results: dict) -> None:
    """results.json as Gradescope's specification describes it."""
    assert set(results) <= TOP_FIELDS, set(results) - TOP_FIELDS
    assert isinstance(results["score"], (int, float)) and results["score"] >= 0
    assert isinstance(results["execution_time"], int) and isinstance(results.get("output", ""), str)
    assert results["stdout_visibility"] == "hidden"
    assert isinstance(results["tests"], list)
    for test in results["tests"]:
        assert set(test) <= TEST_FIELDS, set(test) - TEST_FIELDS
        assert isinstance(test["name"], str) and isinstance(test["output"], str)
        assert test["visibility"] in VISIBILITIES and test.get("status", "passed") in ("passed", "failed")
        if "max_score" in test:
            assert 0 <= test["score"] <= test["max_score"]
    scored = [t for t in results["tests"] if "max_score" in t]
    assert abs(sum(t["score"] for t in scored) - results["score"]) < 1e-9


@pytest.fixture(scope="module")
def autograder(tmp_path_factory):
    return build_autograder(1, tmp_path_factory.mktemp("autograder") / "ch01.zip", LIMITS)


@pytest.fixture(scope="module")
def gradescope(autograder):
    """ROOT laid out as Gradescope lays out /autograder, after setup.sh: (root, setup's output)."""
    if subprocess.run([BASE_PYTHON, "-c", "import numpy"], capture_output=True).returncode != 0:
        pytest.skip(f"setup.sh is tested offline: it needs NumPy in {BASE_PYTHON} (a venv with system site packages)")
    root = Path(tempfile.mkdtemp(prefix="cagd-gradescope-"))
    root.chmod(0o755)  # its user must reach ROOT/venv, as in the container
    with zipfile.ZipFile(autograder.path) as archive:
        archive.extractall(root / "source")
        for info in archive.infolist():  # zipfile forgets the modes
            (root / "source" / info.filename).chmod((info.external_attr >> 16) & 0o777)
    shutil.copyfile(root / "source" / "run_autograder", root / "run_autograder")
    (root / "run_autograder").chmod(0o755)
    (root / "submission").mkdir()
    env = {**os.environ, ROOT_ENV: str(root), "CAGD_AUTOGRADER_PYTHON": BASE_PYTHON,
           "CAGD_AUTOGRADER_VENV_OPTIONS": "--system-site-packages", "CAGD_AUTOGRADER_PIP_OPTIONS": "--no-index",
           USER_ENV: TEST_USER}
    done = subprocess.run(["bash", str(root / "source" / "setup.sh")], env=env, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    yield root, done.stdout
    shutil.rmtree(root, ignore_errors=True)


def grade(root: Path, notebook, name: str = "homework.ipynb", **environment) -> tuple[dict, str]:
    """Hand in `notebook` as the only file of a submission and run run_autograder as Gradescope does."""
    shutil.rmtree(root / "submission")
    semester.write(root / "submission" / name, notebook)
    (root / "results" / "results.json").unlink(missing_ok=True)
    env = {**os.environ, ROOT_ENV: str(root), **environment}
    done = subprocess.run([str(root / "run_autograder")], cwd=root, env=env, capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    results = json.loads((root / "results" / "results.json").read_text())
    validate(results)
    return results, done.stdout


def _site(root: Path) -> Path:
    return next((root / "venv" / "lib").glob("python*/site-packages"))


def test_the_zip_holds_setup_and_run_autograder_at_its_root_and_the_course_wheel(autograder):
    with zipfile.ZipFile(autograder.path) as archive:
        infos = {i.filename: i for i in archive.infolist()}
        config = json.loads(archive.read("autograder.json"))
    assert {"setup.sh", "run_autograder", "autograder.json", "requirements.txt",
            "course/book.toml", "course/tests/hidden/ch01.py"} <= set(infos)
    assert all((infos[n].external_attr >> 16) & stat.S_IXUSR for n in ("setup.sh", "run_autograder"))
    assert [n for n in infos if n.startswith("wheels/")] == [f"wheels/{autograder.wheel}"]
    assert not [n for n in infos if "hidden/ch02" in n or "mistakes" in n]  # this chapter's suite only
    assert config["chapter"] == 1 and config["exercises"] == autograder.exercises and sum(autograder.exercises.values())
    assert config["hidden_visibility"] == "after_published" and config["limits"]["exercise_seconds"] == 5
    assert any(r.startswith("numpy") for r in autograder.requirements)
    assert not any(r.split(">")[0] in ("jupyterlab", "sphinx", "matplotlib") for r in autograder.requirements)


def test_setup_installs_the_wheel_and_leaves_the_hidden_suite_to_root(gradescope):
    root, log = gradescope
    site = _site(root)
    assert (site / "cagd_ref" / "geometry.py").is_file() and (site / "cagd_course" / "grading" / "worker.py").is_file()
    assert not list(site.glob("__editable__*cagd*"))  # the wheel, not a link to this checkout
    if AS_ROOT:
        assert f"graded code will run as {TEST_USER}" in log
        for path in (root / "source", site / "cagd_ref", site / "cagd_course"):
            assert stat.S_IMODE(path.stat().st_mode) & 0o077 == 0, path
        assert (root / "source" / "run_as").read_text().strip() == TEST_USER


def test_the_reference_solution_gets_full_marks_with_hidden_groups_shown_after_publication(gradescope):
    root, _ = gradescope
    results, log = grade(root, semester.chapter_notebook(1))
    assert results["score"] == 10
    scored = {t["name"]: t for t in results["tests"] if "max_score" in t}
    assert list(scored) == ["01.projection", "01.triangle_area", "01.rotate_about_axis", "01.rotation_matrix",
                            "01.conic_type"]
    assert all(t["score"] == t["max_score"] and t["visibility"] == "visible" for t in scored.values())
    hidden = [t for t in results["tests"] if "max_score" not in t]
    assert hidden and all(t["visibility"] == "after_published" and "hidden group" in t["name"] for t in hidden)
    assert "landlock" in log or "namespaces" in log or "seccomp" in log  # the confinement, for the instructor
    if AS_ROOT:
        assert f"graded code runs as {TEST_USER}" in log and f"user {pwd.getpwnam(TEST_USER).pw_uid} of its own" in log


def test_the_stub_gets_nothing_and_is_told_to_write_its_functions(gradescope):
    results, _ = grade(gradescope[0], semester.stub_notebook(1), "01-introduction.ipynb")
    assert results["score"] == 0
    assert all(t["score"] == 0 for t in results["tests"] if "max_score" in t)
    assert "NotImplementedError" in "".join(t["output"] for t in results["tests"])


def test_a_recorded_mistake_loses_points_with_the_graders_feedback(gradescope):
    mistake = (ROOT / "tests" / "hidden" / "mistakes" / "ch01" / "projection__swapped_roles.py").read_text()
    results, _ = grade(gradescope[0], semester.with_cell(semester.chapter_notebook(1), mistake))
    projection = next(t for t in results["tests"] if t["name"] == "01.projection")
    assert projection["score"] < projection["max_score"] and projection["status"] == "failed"
    assert 9 <= results["score"] < 10
    assert "expected:" in projection["output"] and "Hint:" in projection["output"]


HOSTILE = '''
import os
import time
import numpy as np

def _secrets():
    # (Only top-level definitions and imports are graded: the paths live in a function.)
    return ["@ROOT@/source/course/tests/hidden/ch01.py", "@ROOT@/source/autograder.json",
            "@SITE@/cagd_ref/geometry.py"]


def _works(action):
    try:
        action()
        return True
    except OSError:
        return False


def _forge():
    with open("@ROOT@/results/results.json", "w") as handle:
        handle.write('{"score": 1000, "tests": []}')
    with open("@ROOT@/results/forged.txt", "w") as handle:
        handle.write("forged")


def projection(p, q):
    if _works(_forge):
        return None  # a wrong answer tells the test the attack went through
    p, q = np.asarray(p, float), np.asarray(q, float)
    if p.shape != q.shape or p.ndim != 1 or not q.any():
        raise ValueError("p, q: vectors of one length, q not zero")
    return p @ q / (q @ q) * q


def triangle_area(p1, p2, p3):
    for secret in _secrets():
        if _works(lambda: open(secret).read()):
            return -1.0
    a, b, c = (np.asarray(v, float) for v in (p1, p2, p3))
    if a.shape != b.shape or a.shape != c.shape or a.ndim != 1 or a.shape[0] not in (2, 3):
        raise ValueError("p1, p2, p3: 2-D or 3-D points")
    u, v = b - a, c - a
    if a.shape[0] == 2:
        return abs(u[0] * v[1] - u[1] * v[0]) / 2
    return float(np.linalg.norm(np.cross(u, v))) / 2


def _stay():
    import ctypes
    ctypes.CDLL(None).prctl(15, b"hx-autograder", 0, 0, 0)
    time.sleep(600)
    os._exit(0)


def _fork():
    if os.fork() == 0:
        _stay()


def _spawn():
    os.posix_spawn("/bin/sleep", ["hx-autograder", "600"], {})
'''


def _hostile(root: Path) -> dict:
    text = HOSTILE.replace("@ROOT@", str(root)).replace("@SITE@", str(_site(root)))
    notebook = semester.with_cell(semester.chapter_notebook(1), text)
    # Its conic_type is the solution's, after trying to leave processes behind (a wrong answer if one starts).
    solution = next("".join(c["source"]) for c in notebook["cells"]
                    if c["cell_type"] == "code" and "def conic_type(" in "".join(c["source"]))
    return semester.with_cell(notebook, solution.replace("def conic_type(", "def _correct_conic_type(") + (
        "\ndef conic_type(a, b, c, d, e, f):\n"
        "    if _works(_fork) or _works(_spawn):\n"
        "        return 'a process was started'\n"
        "    return _correct_conic_type(a, b, c, d, e, f)\n"
    ))


def _assert_nothing_got_through(root: Path, results: dict, processes) -> None:
    assert results["score"] == 10, [(t["name"], t["output"]) for t in results["tests"] if t.get("status") == "failed"]
    assert not (root / "results" / "forged.txt").exists()
    assert sorted(p.name for p in (root / "results").iterdir()) == ["results.json"]
    assert processes.named("hx-autograder") == []


def test_a_hostile_notebook_cannot_write_results_read_the_suite_or_leave_a_process(gradescope, processes):
    root, _ = gradescope
    results, log = grade(root, _hostile(root))
    _assert_nothing_got_through(root, results, processes)


@pytest.mark.skipif(not AS_ROOT, reason="a user of its own needs a grader running as root")
def test_without_landlock_the_file_modes_alone_keep_the_suite_and_results_closed(gradescope, processes):
    root, _ = gradescope
    results, log = grade(root, _hostile(root), CAGD_SANDBOX_DISABLE="landlock")
    assert "landlock disabled" in log and "of its own" in log
    _assert_nothing_got_through(root, results, processes)


def test_a_notebook_of_another_chapter_gets_zero_and_a_clear_message(gradescope):
    results, log = grade(gradescope[0], semester.chapter_notebook(2, stamped=True), "02-bezier-curves.ipynb")
    assert results["score"] == 0 and len([t for t in results["tests"] if "max_score" in t]) == 5
    assert "chapter 1" in results["output"] and "02-bezier-curves.ipynb is chapter 2's" in results["output"]
    assert "01-introduction.ipynb" in results["output"]
    results, _ = grade(gradescope[0], "this is not a notebook", "01-introduction.ipynb")
    assert results["score"] == 0 and "not valid JSON" in results["output"]


def test_the_autograder_command_writes_the_zip_and_says_how_to_use_it(tmp_path, capsys):
    with pytest.raises(SystemExit):
        main(["autograder", "--help"])
    text = capsys.readouterr().out
    assert "Gradescope" in text and "--chapter" in text and "unprivileged user" in text
    assert main(["autograder", "--chapter", "99", str(tmp_path / "x.zip")]) == 2
    assert "no chapter 99" in capsys.readouterr().err
