"""`cagd autograder --chapter N OUT.zip`: one chapter's Gradescope autograder, and what runs inside it.

Gradescope's autograder specification: the zip is unpacked into ``/autograder/source``; ``setup.sh``
(at the zip's root) runs once, as root, while Gradescope builds the image; for every submission
``/autograder/run_autograder`` runs, as root, in ``/autograder``, with the student's files in
``/autograder/submission``, and must write ``/autograder/results/results.json``. The zip holds

* ``setup.sh``: a virtual environment in ``/autograder/venv`` with the grading runtime
  (``requirements.txt``: only what this chapter's reference and suite import) and the course's own
  wheel (``wheels/``), installed without its other dependencies; the unprivileged user graded code
  runs as (``cagd-student``, created if missing); ``/autograder/source`` and the installed course
  packages made root's alone (mode 0700);
* ``run_autograder``: runs `run` below with that environment's Python, isolated (``-I``);
* ``course/``: ``book.toml`` and the chapter's hidden suite; ``autograder.json``: the chapter, its
  exercises and points, the seed, the limits, the user and what a hidden group's test shows.

`run` grades the one notebook of the submission as `cagd grade` grades a class's: top-level
definitions only, in the grader's worker process (the time and memory limits, Landlock, namespaces
and seccomp where the container allows them), as that unprivileged user, so that it can read
neither ``/autograder/source`` nor the installed reference and cannot write ``results.json``;
values are compared in the grader's process. ``results.json`` has one test per exercise with its
score and the feedback of its visible groups, one test per hidden group shown after grades are
published, the overall score, and ``stdout_visibility: hidden`` (the log is the instructor's). A
notebook of another chapter gets 0 and a message saying which notebook to hand in; nothing a
submission does makes `run` end without writing ``results.json``.

``CAGD_AUTOGRADER_ROOT`` relocates ``/autograder`` (tests); ``setup.sh`` reads a few more variables,
listed at its top, for machines without network.
"""

from __future__ import annotations

import dataclasses
import importlib.metadata
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import traceback
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

from ..manifest import COURSE_ENV, Course, load_course, tomllib
from . import runner
from .engine import grade_statements, load_exercises, prepare, submission_seed
from .extract import SubmissionError, extract_notebook
from .gradebook import atomic_write
from .layouts import Found, _notebooks_below, _resolve
from .report import VISIBILITIES, gradescope_results, status_of
from .runner import Limits

__all__ = ["Autograder", "build_autograder", "build_wheel", "runtime_requirements", "run", "main", "ROOT_ENV",
           "USER_ENV", "DEFAULT_USER", "CONFIG"]

ROOT_ENV = "CAGD_AUTOGRADER_ROOT"
USER_ENV = "CAGD_AUTOGRADER_USER"
DEFAULT_ROOT = "/autograder"
DEFAULT_USER = "cagd-student"
CONFIG = "autograder.json"
RUN_AS_FILE = "run_as"
HIDDEN_VISIBILITY = "after_published"

SETUP_SH = r"""#!/usr/bin/env bash
# Gradescope runs this once, as root, while it builds the autograder's image (written by `cagd autograder`).
# It installs the grading runtime and the course into ROOT/venv, creates the user graded code runs as, and
# makes the hidden suite and the installed reference root's alone. Variables (Gradescope sets none of them;
# they are for tests and for machines without network):
#   CAGD_AUTOGRADER_ROOT          the autograder folder (default /autograder)
#   CAGD_AUTOGRADER_PYTHON        the Python that makes ROOT/venv (default python3; apt installs it if needed)
#   CAGD_AUTOGRADER_VENV_OPTIONS  more options of `python -m venv` (e.g. --system-site-packages)
#   CAGD_AUTOGRADER_PIP_OPTIONS   more options of `pip install` (e.g. --no-index)
#   CAGD_AUTOGRADER_USER          the unprivileged user graded code runs as (default @USER@; created if missing)
set -euo pipefail
ROOT="${CAGD_AUTOGRADER_ROOT:-/autograder}"
SOURCE="$ROOT/source"
PYTHON="${CAGD_AUTOGRADER_PYTHON:-python3}"
RUN_AS="${CAGD_AUTOGRADER_USER:-@USER@}"

if ! "$PYTHON" -c 'import sys, venv, ensurepip; sys.exit(sys.version_info < (3, 10))' 2>/dev/null; then
    export DEBIAN_FRONTEND=noninteractive
    apt-get update
    apt-get install -y --no-install-recommends python3 python3-venv python3-pip
    PYTHON=python3
fi
read -r -a VENV_OPTIONS <<< "${CAGD_AUTOGRADER_VENV_OPTIONS:-}"
read -r -a PIP_OPTIONS <<< "${CAGD_AUTOGRADER_PIP_OPTIONS:-}"
"$PYTHON" -m venv "${VENV_OPTIONS[@]}" "$ROOT/venv"
PIP=("$ROOT/venv/bin/python" -m pip install --disable-pip-version-check --no-input "${PIP_OPTIONS[@]}")
"${PIP[@]}" -r "$SOURCE/requirements.txt"
"${PIP[@]}" --no-deps "$SOURCE"/wheels/*.whl
"$ROOT/venv/bin/python" -I -c 'import cagd_course.grading.autograder'

if [ "$(id -u)" = 0 ]; then
    if ! id -u "$RUN_AS" > /dev/null 2>&1; then
        useradd --system --no-create-home --home-dir /nonexistent --shell /usr/sbin/nologin "$RUN_AS"
    fi
    SITE="$("$ROOT/venv/bin/python" -I -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
    # The hidden suite, the wheel and the installed course (the reference among it): root's alone.
    printf '%s\n' "$RUN_AS" > "$SOURCE/run_as"
    chown -R root:root "$SOURCE" "$SITE/cagd_ref" "$SITE/cagd_course"
    chmod -R go-rwx "$SOURCE" "$SITE/cagd_ref" "$SITE/cagd_course"
    chmod 0755 "$ROOT"
    echo "setup.sh: graded code will run as $RUN_AS ($(id -u "$RUN_AS"))"
else
    echo "setup.sh: not root: graded code will run as $(id -un), confined, but without a user of its own"
fi
"""

RUN_AUTOGRADER = r"""#!/usr/bin/env bash
# Gradescope runs this for every submission, as root, in /autograder (written by `cagd autograder`).
ROOT="${CAGD_AUTOGRADER_ROOT:-/autograder}"
export CAGD_COURSE="$ROOT/source/course"
mkdir -p "$ROOT/results"
chmod 0755 "$ROOT/results"
"$ROOT/venv/bin/python" -I -c 'import sys; from cagd_course.grading.autograder import main; sys.exit(main())' \
    run "$ROOT"
status=$?
if [ ! -s "$ROOT/results/results.json" ]; then
    # Only if the grader itself could not start (setup.sh failed): a result all the same.
    message="The autograder could not run; your instructor can see why in its log."
    printf '{"score": 0.0, "stdout_visibility": "hidden", "tests": [], "output": "%s"}\n' "$message" \
        > "$ROOT/results/results.json"
fi
exit "$status"
"""

README = """# Gradescope autograder: chapter {chapter}, {title}

Written by `cagd autograder --chapter {chapter}` of the course "{course}". Upload this zip as the
autograder of a Gradescope programming assignment; students submit their exercise notebook
`{notebook}` (any name will do; a notebook of another chapter gets 0 and says so).

Exercises and points: {exercises}.
Limits per submission: {limits}. Graded code runs as the user `{user}`.
"""


@dataclass
class Autograder:
    """What `build_autograder` wrote: the zip, the chapter's exercises, the runtime it needs."""

    path: Path
    chapter: int
    exercises: dict[str, float]
    requirements: list[str] = field(default_factory=list)
    wheel: str = ""


# --- building the zip ---


def _requirement_specs(course: Course) -> dict[str, str]:
    """The version constraints pyproject.toml gives each dependency (its test extras included), by name."""
    path = course.root / "pyproject.toml"
    if not path.is_file():
        return {}
    project = tomllib.loads(path.read_text(encoding="utf-8")).get("project", {})
    entries = list(project.get("dependencies", []))
    for extra in project.get("optional-dependencies", {}).values():
        entries += extra
    specs = {}
    for entry in entries:
        name = re.split(r"[<>=!~;\[ ]", entry, maxsplit=1)[0]
        specs.setdefault(_normalise(name), entry)
    return specs


def _normalise(name: str) -> str:
    return re.sub(r"[-_.]+", "-", name).lower()


def runtime_requirements(ids: list[str], course: Course | None = None) -> list[str]:
    """The distributions the grader needs for these exercises: what loading their suites and drawing their cases
    imports, in a fresh interpreter, apart from the standard library and the course, with pyproject's bounds."""
    course = course or load_course()
    code = (
        "import sys, json\n"
        "import cagd_course.grading.autograder\n"
        "from cagd_course.grading.engine import load_exercises, prepare\n"
        "prepare(load_exercises(ids=json.loads(sys.argv[1])), 0)\n"
        "print(json.dumps(sorted({m.partition('.')[0] for m in list(sys.modules)})))\n"
    )
    env = {**os.environ, COURSE_ENV: str(course.root)}
    done = subprocess.run([sys.executable, "-c", code, json.dumps(ids)], capture_output=True, text=True, env=env,
                          cwd=course.root, timeout=300)
    if done.returncode != 0:
        raise RuntimeError(f"the suites of {ids} do not load:\n{done.stderr[-2000:]}")
    modules = json.loads(done.stdout.strip().splitlines()[-1])
    providers = importlib.metadata.packages_distributions()
    ours = {"cagd-course"}
    names = set()
    for module in modules:
        if module in sys.stdlib_module_names or module.startswith("_"):
            continue
        for dist in providers.get(module, []):
            if _normalise(dist) not in ours:
                names.add(_normalise(dist))
    specs = _requirement_specs(course)
    found = sorted(specs.get(name, name) for name in names)
    # Python 3.10 (Ubuntu 22.04's) reads book.toml with tomli.
    return found + ['tomli>=2.0; python_version < "3.11"']


def build_wheel(dest: Path, course: Course | None = None) -> Path:
    """The course's own wheel (cagd_ref and cagd_course as installed here), built from a staged copy into `dest`.

    The copy keeps the build's scratch files out of the course folder; pip builds it offline, without
    build isolation (setuptools comes from this environment).
    """
    import cagd_course
    import cagd_ref

    course = course or load_course()
    dest = Path(dest)
    dest.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="cagd-wheel-") as stage:
        stage = Path(stage)
        for name in ("pyproject.toml", "README.md"):
            if not (course.root / name).is_file():
                raise FileNotFoundError(f"building the course's wheel needs {course.root / name}")
            shutil.copyfile(course.root / name, stage / name)
        for package in (cagd_ref, cagd_course):
            folder = Path(package.__file__).parent
            shutil.copytree(folder, stage / folder.name, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        command = [sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "--no-index",
                   "--disable-pip-version-check", "-q", "-w", str(dest), str(stage)]
        done = subprocess.run(command, capture_output=True, text=True, timeout=600)
        if done.returncode != 0:
            raise RuntimeError(f"pip could not build the course's wheel:\n{done.stderr[-2000:]}")
    wheels = sorted(dest.glob("cagd_course-*.whl"), key=lambda p: p.stat().st_mtime)
    if not wheels:
        raise RuntimeError("pip built no wheel of the course")
    return wheels[-1]


def _add(archive: zipfile.ZipFile, name: str, data: bytes | str, executable: bool = False) -> None:
    info = zipfile.ZipInfo(name, date_time=time.localtime()[:6])
    info.compress_type = zipfile.ZIP_DEFLATED
    info.external_attr = ((0o100755 if executable else 0o100644) & 0xFFFF) << 16
    archive.writestr(info, data.encode() if isinstance(data, str) else data)


def build_autograder(
    chapter: int,
    out: Path | str,
    limits: Limits = Limits(),
    seed: int = 0,
    user: str = DEFAULT_USER,
    allow_unconfined: bool = False,
    hidden_visibility: str = HIDDEN_VISIBILITY,
) -> Autograder:
    """Write the Gradescope autograder of `chapter` to the zip `out`; return what went in."""
    course = load_course()
    entry = next((c for c in course.chapters if c.number == chapter), None)
    if entry is None:
        raise ValueError(f"no chapter {chapter} in book.toml (chapters: {[c.number for c in course.chapters]})")
    if not entry.exercise_points:
        raise ValueError(f"chapter {chapter} has no graded exercise in book.toml")
    if hidden_visibility not in VISIBILITIES:
        raise ValueError(f"hidden_visibility: one of {VISIBILITIES}")
    if not re.fullmatch(r"[a-z_][a-z0-9_-]{0,30}", user):
        raise ValueError(f"user {user!r}: a plain system user name (lower case letters, digits, - and _)")
    ids = list(entry.exercise_points)
    load_exercises(course, ids)  # the suite must load before it is shipped
    requirements = runtime_requirements(ids, course)
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    config = {
        "chapter": chapter,
        "title": entry.title,
        "notebook": entry.exercises.name if entry.exercises is not None else "",
        "course": course.title,
        "exercises": dict(entry.exercise_points),
        "seed": seed,
        "limits": dataclasses.asdict(limits),
        "user": user,
        "allow_unconfined": bool(allow_unconfined),
        "hidden_visibility": hidden_visibility,
    }
    with tempfile.TemporaryDirectory(prefix="cagd-autograder-") as folder:
        wheel = build_wheel(Path(folder), course)
        partial = out.with_name(f".{out.name}.partial")
        with zipfile.ZipFile(partial, "w") as archive:
            _add(archive, "setup.sh", SETUP_SH.replace("@USER@", user), executable=True)
            _add(archive, "run_autograder", RUN_AUTOGRADER, executable=True)
            _add(archive, CONFIG, json.dumps(config, indent=2) + "\n")
            _add(archive, "requirements.txt", "\n".join(requirements) + "\n")
            _add(archive, f"wheels/{wheel.name}", wheel.read_bytes())
            _add(archive, "course/book.toml", (course.root / "book.toml").read_bytes())
            _add(archive, f"course/{entry.hidden.relative_to(course.root).as_posix()}", entry.hidden.read_bytes())
            exercises = ", ".join(f"{eid} ({points:g})" for eid, points in entry.exercise_points.items())
            limit_text = (f"{limits.exercise_seconds:g} s per exercise, {limits.submission_seconds:g} s in all, "
                          f"{limits.memory_mb} MB")
            _add(archive, "README.md", README.format(chapter=chapter, title=entry.title, course=course.title,
                                                     notebook=config["notebook"], exercises=exercises,
                                                     limits=limit_text, user=user))
        os.replace(partial, out)
    return Autograder(out, chapter, dict(entry.exercise_points), requirements, wheel.name)


# --- inside the container ---


def _zero(exercises: dict[str, float], message: str) -> dict:
    """A result of 0 that says why, with each exercise's test (so the student sees what was at stake)."""
    tests = [{"name": eid, "score": 0.0, "max_score": float(points), "status": "failed", "output": message,
              "visibility": "visible"} for eid, points in exercises.items()]
    return {"score": 0.0, "output": message, "tests": tests}


def _student(root: Path) -> str:
    """Who handed in (Gradescope's submission_metadata.json): their random cases follow from it."""
    try:
        metadata = json.loads((root / "submission_metadata.json").read_text(encoding="utf-8"))
        users = metadata.get("users") or [{}]
        return str(users[0].get("id") or users[0].get("email") or metadata.get("id") or "submission")
    except (OSError, ValueError, AttributeError, IndexError, TypeError):
        return "submission"


def choose_notebook(folder: Path, course: Course, chapter: int, notebook: str) -> tuple[Path | None, list[str]]:
    """The notebook of the submission to grade and notes about the choice, or None and the message why none."""
    # A link could point the grader (root) at its own files: only the files handed in count.
    paths = [p for p in (_notebooks_below(folder) if folder.is_dir() else [])
             if not p.is_symlink() and p.resolve().is_relative_to(folder.resolve())]
    wanted = f"the exercise notebook of chapter {chapter}" + (f" ({notebook})" if notebook else "")
    if not paths:
        return None, [f"No notebook (.ipynb file) was found in your submission. Upload {wanted}."]
    found = []
    for path in paths:
        item = Found(path, "submission", "submission", original=path.name)
        _resolve(item, list(path.relative_to(folder).parts), course, None)
        found.append(item)
    mine = [f for f in found if f.chapter == chapter]
    unclear = [f for f in found if f.chapter is None]
    names = ", ".join(f.path.name for f in found)
    if mine or unclear:
        pick = (mine or unclear)[0]
        notes = [] if len(paths) == 1 else [f"Your submission holds {len(paths)} notebooks ({names}); "
                                            f"{pick.path.name} was graded."]
        if not mine:
            notes.append(f"{pick.path.name} does not say which chapter it answers ({pick.problem}); it was graded "
                         f"as chapter {chapter}.")
        return pick.path, notes
    others = "; ".join(f"{f.path.name} is chapter {f.chapter}'s (from its {f.how})" for f in found)
    return None, [f"This assignment grades the exercises of chapter {chapter}, but {others}. Nothing was graded: "
                  f"submit {wanted}."]


def _configured_user(root: Path) -> str:
    """The user setup.sh prepared (it writes source/run_as), if it ran as root."""
    try:
        return (root / "source" / RUN_AS_FILE).read_text(encoding="utf-8").strip()
    except OSError:
        return ""


def _grade(root: Path, config: dict) -> dict:
    course = load_course()
    chapter = int(config["chapter"])
    points = {eid: float(p) for eid, p in config["exercises"].items()}
    exercises = load_exercises(course, list(points))
    user = os.environ.get(USER_ENV) or _configured_user(root) or config.get("user") or ""
    if user and os.geteuid() == 0:
        uid, _ = runner.run_as(user)
        print(f"graded code runs as {user} (uid {uid})")
    else:
        print(f"graded code runs as the grader's user (uid {os.geteuid()}): not root, or no user configured")
    picked, notes = choose_notebook(root / "submission", course, chapter, config.get("notebook", ""))
    if picked is None:
        print("not graded: " + " ".join(notes))
        return _zero(points, " ".join(notes))
    print(f"grading {picked.relative_to(root)} on chapter {chapter}")
    seed = submission_seed(int(config.get("seed", 0)), f"{_student(root)}/ch{chapter:02d}")
    prepared = prepare(exercises, seed)  # cases and answers exist before any submitted code runs
    try:
        submission = extract_notebook(picked)
    except SubmissionError as err:
        message = f"{picked.name}: {err.status}: {err.detail}"
        print("not graded: " + message)
        return _zero(points, message)
    limits = Limits(**config.get("limits", {}))
    outcome = grade_statements(submission.statements, prepared, limits,
                               require_confinement=not config.get("allow_unconfined", False))
    notes += submission.skipped + outcome.run.load_problems
    if outcome.run.output_truncated:
        notes.append("Your code printed more than the grader keeps; the rest was cut off.")
    if not outcome.run.confined and not config.get("allow_unconfined", False):
        notes.append("Your code could not be graded: this machine cannot confine it. Your instructor can see why "
                     "in the autograder's log; nothing you can change.")
    results = gradescope_results(outcome.exercises, outcome.score, notes,
                                 hidden_visibility=config.get("hidden_visibility", HIDDEN_VISIBILITY))
    print(f"seed {seed}; confinement: {outcome.run.sandbox or 'none'}")
    print(f"score {outcome.score:g} / {outcome.max_score:g}; status: {status_of(outcome.exercises, [])}")
    if outcome.run.output.strip():
        print("the submission printed (first lines):\n" + "\n".join(outcome.run.output.splitlines()[:20]))
    return results


def run(root: Path | str | None = None) -> dict:
    """Grade the submission under `root` (default $CAGD_AUTOGRADER_ROOT, else /autograder) into results.json.

    Whatever happens, ``root/results/results.json`` is written, by this process, and returned.
    """
    root = Path(root or os.environ.get(ROOT_ENV) or DEFAULT_ROOT).resolve()
    os.environ.setdefault(COURSE_ENV, str(root / "source" / "course"))
    started = time.monotonic()
    try:
        config = json.loads((root / "source" / CONFIG).read_text(encoding="utf-8"))
        try:
            results = _grade(root, config)
        except Exception:  # noqa: BLE001 - told to the instructor's log; the student gets a result all the same
            traceback.print_exc(file=sys.stdout)
            results = _zero({eid: float(p) for eid, p in config.get("exercises", {}).items()},
                            "The autograder failed while grading; your instructor can see why in its log.")
    except Exception:  # noqa: BLE001 - not even the configuration could be read
        traceback.print_exc(file=sys.stdout)
        results = {"score": 0.0, "tests": [],
                   "output": "The autograder is not set up right; your instructor can see why in its log."}
    finally:
        runner.shutdown()
    results["execution_time"] = int(round(time.monotonic() - started))
    results["stdout_visibility"] = "hidden"
    path = root / "results" / "results.json"
    atomic_write(path, json.dumps(results, indent=2, allow_nan=False) + "\n")
    os.chmod(path, 0o644)
    sys.stdout.flush()
    return results


def main(argv: list[str] | None = None) -> int:
    """`python -m cagd_course.grading.autograder run [ROOT]`: what run_autograder calls."""
    argv = list(sys.argv[1:] if argv is None else argv)
    if not argv or argv[0] != "run" or len(argv) > 2:
        print("usage: python -m cagd_course.grading.autograder run [ROOT]", file=sys.stderr)
        return 2
    results = run(argv[1] if len(argv) > 1 else None)
    print(f"results.json written: score {results['score']:g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
