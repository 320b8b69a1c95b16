"""Nothing a submission starts outlives it, its processes are bounded, and unconfined grading needs a flag.

The layers are tested one at a time: with seccomp switched off (`CAGD_SANDBOX_DISABLE`), graded
code really forks, and the PID namespace (or, with namespaces switched off too, the keeper's
process-tree tracking) must still kill everything; with Landlock switched off, `cagd grade`
refuses unless told otherwise, and then says what the submissions could do.
"""

import csv
import sys
import tempfile
from pathlib import Path

import pytest

from cagd_course.cli import main
from cagd_course.grading import runner, sandbox
from cagd_course.grading.classroom import UnconfinedError, grade_class
from cagd_course.grading.engine import grade_statements, prepare
from cagd_course.grading.extract import extract_source
from cagd_course.grading.runner import Limits
from cagd_course.grading.suite import Case, Exercise
from cagd_ref import geometry

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the containment is Linux's")

ROOT = Path(__file__).resolve().parents[2]
SOLUTION = Path(__file__).parent / "fixtures" / "submissions" / "complete.ipynb"
FAST = Limits(exercise_seconds=3, submission_seconds=30, memory_mb=512)
EXERCISES = {
    "01.projection": (
        Exercise("01.projection", geometry.projection, lambda rng: [Case("one", ((3.0, 1.0, 2.0), (1.0, 1.0, 0.0)))]),
        1.0,
    ),
    "01.triangle_area": (
        Exercise("01.triangle_area", geometry.triangle_area, lambda rng: [Case("one", ((0, 0), (4, 0), (0, 3)))]),
        1.0,
    ),
}
PROJECTION = (
    "    p, q = np.asarray(p, float), np.asarray(q, float)\n"
    "    return p @ q / (q @ q) * q\n"
)
TRIANGLE = "def triangle_area(p1, p2, p3):\n    return 6.0\n"
NAME = "import ctypes\ndef _name(label):\n    ctypes.CDLL(None).prctl(15, label, 0, 0, 0)\n"


def _grade(source: str, exercises=EXERCISES, **options):
    statements = extract_source([source]).statements
    return grade_statements(statements, prepare(exercises, 0), FAST, **options)


@pytest.fixture(scope="module")
def confinement():
    probe = runner.probe(FAST)
    if "pid" not in probe.sandbox:
        pytest.skip(f"this kernel gives graded code no PID namespace: {probe.sandbox}")
    return probe


@pytest.fixture
def forks_allowed(monkeypatch):
    monkeypatch.setenv(sandbox.DISABLE_ENV, "seccomp")


def test_a_worker_runs_in_namespaces_without_new_processes(confinement):
    assert confinement.confined and confinement.gaps == []
    for layer in ("user+pid+ipc", "landlock ABI", "no new processes (seccomp)"):
        assert layer in confinement.sandbox


DAEMON = (
    NAME + "import os, time\n"
    "def projection(p, q):\n"
    "    ready, told = os.pipe()\n"
    "    if os.fork() == 0:\n"
    "        os.setsid()\n"
    "        if os.fork() == 0:\n"
    "            _name(b'hx-daemon')\n"
    "            os.write(told, b'x')\n"
    "            time.sleep(120)\n"
    "        os._exit(0)\n"
    "    os.read(ready, 1)  # the grandchild is up, in its own session, before the function returns\n"
    "    return q\n"
)


def test_a_daemonised_grandchild_dies_with_its_submission(confinement, forks_allowed, processes):
    outcome = _grade(DAEMON)
    assert "namespaces" in outcome.run.sandbox and "seccomp" not in outcome.run.sandbox
    assert outcome.exercises[0].cases[0].kind == "value"  # it forked, and came back with its answer
    assert processes.named("hx-daemon") == []


def test_process_tree_tracking_kills_it_where_namespaces_are_refused(monkeypatch, processes):
    monkeypatch.setenv(sandbox.DISABLE_ENV, "namespaces,seccomp")
    outcome = _grade(DAEMON)
    assert "process-tree tracking" in outcome.run.sandbox
    assert outcome.exercises[0].cases[0].kind == "value"
    assert processes.named("hx-daemon") == []


def test_a_fork_flood_is_bounded_by_the_namespaces_pid_max(confinement, forks_allowed, processes):
    if "pid_max" not in confinement.sandbox:
        pytest.skip("pid_max is per PID namespace from Linux 6.14 on")
    source = (
        NAME + "import os, signal\n"
        "def projection(p, q):\n"
        "    count = 0\n"
        "    while True:\n"
        "        try:\n"
        "            pid = os.fork()\n"
        "        except OSError as err:\n"
        "            return [float(count), float(err.errno), 0.0]\n"
        "        if pid == 0:\n"
        "            _name(b'hx-flood')\n"
        "            signal.pause()\n"
        "        count += 1\n"
    )
    outcome = _grade(source)
    count, error, _ = outcome.exercises[0].cases[0].received
    assert 0 < count < sandbox.PID_MAX and error == 11  # EAGAIN: the namespace has no PID left
    assert processes.named("hx-flood") == []


def test_a_fork_bomb_costs_its_exercise_and_nothing_more(confinement, forks_allowed, processes):
    bomb = "import os\ndef projection(p, q):\n    while True:\n        os.fork()\n"
    outcome = _grade(bomb + TRIANGLE)
    bombed, other = outcome.exercises
    assert bombed.score == 0 and other.score == other.points
    assert processes.grading() == [runner._ZYGOTE[0].proc.pid]


def test_a_child_sleeping_past_the_deadline_does_not_hold_the_grader(confinement, forks_allowed, processes):
    source = (
        NAME + "import os, time\nimport numpy as np\n"
        "def projection(p, q):\n"
        "    if os.fork() == 0:\n"
        "        _name(b'hx-sleeper')\n"
        "        time.sleep(120)\n"
        "        os._exit(0)\n" + PROJECTION
    )
    outcome = _grade(source + TRIANGLE)
    assert [e.score for e in outcome.exercises] == [1.0, 1.0] and not outcome.run.stopped
    assert processes.named("hx-sleeper") == []


def test_graded_code_cannot_write_into_another_submissions_folder(confinement):
    decoy = Path(tempfile.mkdtemp(prefix="cagd-grade-decoy-"))
    (decoy / "results.json").write_text("{}")
    source = (
        "import glob, os\n"
        "def projection(p, q):\n"
        "    written = 0\n"
        f"    for folder in glob.glob({tempfile.gettempdir()!r} + '/cagd-grade-*') + [{str(decoy)!r}]:\n"
        "        for name in ('results.json', 'pwned.txt'):\n"
        "            try:\n"
        "                with open(os.path.join(folder, name), 'w') as handle:\n"
        "                    written += handle.write('pwned') > 0\n"
        "            except OSError:\n"
        "                pass\n"
        "    return [float(written), 0.0, 0.0]\n"
    )
    try:
        outcome = _grade(source)
        assert outcome.exercises[0].cases[0].received[0] == 0
        assert sorted(p.name for p in decoy.iterdir()) == ["results.json"]
        assert (decoy / "results.json").read_text() == "{}"
    finally:
        for path in decoy.iterdir():
            path.unlink()
        decoy.rmdir()


def test_the_confinement_report_cannot_be_forged_by_graded_code(confinement):
    # A class body runs while the submission loads, the earliest graded code can run.
    forged = (
        "import os\n"
        "class Forger:\n"
        "    os.write(3, b'{\"event\": \"sandbox\", \"note\": \"forged\", \"confined\": true, \"gaps\": []}\\n')\n"
        "def projection(p, q):\n    return q\n"
    )
    outcome = _grade(forged)
    assert outcome.run.sandbox != "forged" and outcome.score == 0
    assert "confinement twice" in outcome.exercises[0].stopped


def test_a_fresh_interpreter_without_the_zygote_is_confined_by_landlock_and_seccomp(monkeypatch):
    monkeypatch.setattr(runner, "_forks_workers", lambda: False)
    good = "import numpy as np\ndef projection(p, q):\n" + PROJECTION
    outcome = _grade(good)
    assert outcome.score == 1 and outcome.run.confined and "namespaces" not in outcome.run.sandbox
    # Without seccomp either, nothing would stop its processes or IPC objects from outliving it.
    monkeypatch.setenv(sandbox.DISABLE_ENV, "seccomp")
    outcome = _grade(good)
    assert outcome.score == 1 and not outcome.run.confined and {"processes", "ipc"} <= set(outcome.run.gaps)
    refused = _grade(good, require_confinement=True)
    assert refused.score == 0 and refused.exercises[0].stopped.startswith("not graded: graded code cannot be confined")


SHARED_MEMORY = (
    "import ctypes\n"
    "def projection(p, q):\n"
    "    libc = ctypes.CDLL(None, use_errno=True)\n"
    "    made = libc.shmget(0x0CA6D, 1 << 20, 0o1600)  # IPC_CREAT | 0600, a megabyte\n"
    "    return [float(made), float(ctypes.get_errno()), 0.0]\n"
)


def _host_segments() -> str:
    return Path("/proc/sysvipc/shm").read_text()


def test_graded_code_cannot_leave_shared_memory_behind(confinement):
    made, error, _ = _grade(SHARED_MEMORY).exercises[0].cases[0].received
    assert made == -1 and error == 1  # EPERM: seccomp refuses System V IPC


def test_shared_memory_made_in_the_workers_ipc_namespace_is_not_the_machines(confinement, forks_allowed):
    made, _, _ = _grade(SHARED_MEMORY).exercises[0].cases[0].received
    # Made in the worker's own IPC namespace, which ends with it; the machine's never saw it.
    assert made >= 0 and f"{0x0CA6D:10d}" not in _host_segments()


def test_no_grading_process_outlives_grade_class(confinement, tmp_path, processes):
    folder = tmp_path / "class"
    folder.mkdir()
    for name in ("ann", "bob", "cy"):
        (folder / f"{name}.ipynb").write_bytes(SOLUTION.read_bytes())
    grade_class([folder], tmp_path / "out", jobs=2, limits=FAST, progress=False, chapters=[1])
    assert processes.grading() == []


# --- grading unconfined ---

STEALS = (
    "import importlib, importlib.util, sys\n"
    "def projection(p, q):\n"
    f"    root = {str(ROOT / 'cagd_ref')!r}\n"
    "    spec = importlib.util.spec_from_file_location('stolen', root + '/__init__.py', "
    "submodule_search_locations=[root])\n"
    "    module = importlib.util.module_from_spec(spec)\n"
    "    sys.modules['stolen'] = module\n"
    "    spec.loader.exec_module(module)\n"
    "    return importlib.import_module('stolen.geometry').projection(p, q)\n"
)


@pytest.fixture
def thief(tmp_path):
    import nbformat

    notebook = nbformat.read(SOLUTION, as_version=4)
    notebook.cells.append(nbformat.v4.new_code_cell(STEALS))
    folder = tmp_path / "class"
    folder.mkdir()
    nbformat.write(notebook, folder / "thief.ipynb")
    return folder


def test_grading_refuses_where_landlock_is_missing(thief, tmp_path, monkeypatch, capsys):
    monkeypatch.setenv(sandbox.DISABLE_ENV, "landlock")
    with pytest.raises(UnconfinedError) as refused:
        grade_class([thief], tmp_path / "out", limits=FAST, progress=False, chapters=[1])
    message = str(refused.value)
    assert message.startswith("refusing to grade: graded code cannot be confined: ")
    assert "the reference solutions (cagd_ref) and the hidden suites (tests/hidden)" in message
    assert "the gradebook" in message and "--allow-unconfined" in message
    assert not (tmp_path / "out").exists()
    assert main(["grade", str(thief), "--out", str(tmp_path / "cli"), "--chapter", "1"]) == 2
    assert "refusing to grade" in capsys.readouterr().err


def test_allowed_unconfined_grading_warns_precisely_and_the_warning_is_true(thief, tmp_path, monkeypatch):
    monkeypatch.setenv(sandbox.DISABLE_ENV, "landlock")
    out = tmp_path / "out"
    summary = grade_class([thief], out, limits=FAST, progress=False, chapters=[1], allow_unconfined=True)
    text = str(summary)
    assert "WARNING: graded unconfined (--allow-unconfined): " in text and "landlock disabled" in text
    assert "read every file you can read" in text
    with (out / "gradebook.csv").open() as handle:
        row = next(csv.DictReader(handle))
    # What the warning says: unconfined, running the reference read from its file scores full marks.
    assert row["01.projection"] == "1" and "landlock disabled" in row["confinement"]


def test_a_self_check_may_run_unconfined_but_says_so(monkeypatch, capsys):
    monkeypatch.setenv(sandbox.DISABLE_ENV, "landlock")
    assert main(["check", str(SOLUTION), "--exercise", "01.projection"]) == 0
    captured = capsys.readouterr()
    assert "01.projection: 1 / 1 points" in captured.out
    assert "note: the checked code ran unconfined (" in captured.err and "landlock disabled" in captured.err


def test_the_environment_switch_refuses_unknown_layers(monkeypatch):
    monkeypatch.setenv(sandbox.DISABLE_ENV, "landlock,firewall")
    with pytest.raises(ValueError, match="firewall"):
        sandbox.disabled()


def test_landlock_never_allows_a_folder_holding_the_course(tmp_path):
    site = tmp_path / "site-packages"
    for folder in (site / "numpy", site / "cagd_ref", site / "cagd_course", tmp_path / "other"):
        folder.mkdir(parents=True)
    (site / "six.py").write_text("")
    hidden = (str(site / "cagd_course"), str(site / "cagd_ref"))
    roots = (str(site), str(tmp_path / "other"), str(site / "cagd_ref" / "sub"))
    # A non-editable install: site-packages is allowed entry by entry, the course's packages left out.
    assert sandbox.readable_roots(roots, hidden) == (str(site / "numpy"), str(site / "six.py"), str(tmp_path / "other"))


def test_landlock_allows_a_checkouts_environment_but_nothing_else_of_it(tmp_path):
    checkout = tmp_path / "src" / "course"
    for folder in (checkout / ".venv" / "lib", checkout / "cagd_ref", checkout / "tests", tmp_path / "src" / "x"):
        folder.mkdir(parents=True)
    roots = (str(tmp_path / "src"), str(checkout / ".venv"), str(checkout / "tests"))
    allowed = sandbox.readable_roots(roots, (str(checkout / "cagd_ref"),), str(checkout), str(checkout / ".venv"))
    # /usr/src holding a checkout: its other entries stay readable; of the checkout, only its environment.
    assert allowed == (str(tmp_path / "src" / "x"), str(checkout / ".venv"))
