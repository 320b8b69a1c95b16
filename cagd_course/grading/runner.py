"""Run a submission's functions in a separate, limited process and collect what they return.

The grader never executes student code itself. `run_tasks` starts
`worker.py` under a fresh interpreter (``-I -S``: no user site, no ``.pth``
files, so the editable reference package is not on its path), in a new
temporary folder with a scrubbed environment, and supervises it from outside:
a wall-clock deadline per exercise and per submission enforced with SIGKILL on
the whole process group, a memory limit, and captured, truncated output. When
the process hangs or dies, the exercise it was on is marked and a fresh worker
carries on with the remaining exercises.
"""

from __future__ import annotations

import importlib.util
import json
import os
import selectors
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from ..manifest import find_course_root
from . import sandbox
from .worker import PACKAGES

__all__ = ["Limits", "Task", "RunResult", "run_tasks", "worker_path"]

WORKER = Path(__file__).with_name("worker.py")


@dataclass(frozen=True)
class Limits:
    """Resource limits for one submission's process."""

    exercise_seconds: float = 10.0
    submission_seconds: float = 120.0
    memory_mb: int = 1024
    output_bytes: int = 20_000


@dataclass(frozen=True)
class Task:
    """One exercise to run: the student function's name and its encoded cases."""

    exercise: str
    function: str
    cases: list


@dataclass
class RunResult:
    """What came back: case events per exercise, and why an exercise stopped early, if it did."""

    load_problems: list[str] = field(default_factory=list)
    events: dict[str, list[dict]] = field(default_factory=dict)
    stopped: dict[str, str] = field(default_factory=dict)
    output: str = ""
    output_truncated: bool = False
    seconds: dict[str, float] = field(default_factory=dict)
    sandbox: str = ""


def worker_path() -> Path:
    return WORKER


def _package_home(name: str) -> Path:
    """The folder on the import path that holds package `name` (without importing it)."""
    spec = importlib.util.find_spec(name)
    return Path(next(iter(spec.submodule_search_locations))).resolve().parent


def _allowed_path(allow_reference: bool) -> list[str]:
    """The grader's import path minus every folder that would expose the course's packages or files.

    Untrusted runs keep the interpreter's own environment (NumPy lives there, and so does a normal,
    non-editable install of the course, whose packages the worker refuses to import by name) and
    lose every other entry that holds `cagd_ref` or `cagd_course` or lies inside the course folder
    (the checkout with its reference and hidden suites). Trusted runs (validating the reference
    itself) get the reference's folder first.
    """
    entries = [entry for entry in sys.path if entry and os.path.isdir(entry)]
    if allow_reference:
        return [str(_package_home("cagd_ref"))] + entries
    hidden = {_package_home(name) for name in PACKAGES}
    try:
        hidden.add(find_course_root())
    except FileNotFoundError:
        pass
    environment = Path(sys.prefix).resolve()
    allowed = []
    for entry in entries:
        folder = Path(entry).resolve()
        exposes = any(folder.is_relative_to(h) for h in hidden) or any((folder / n).exists() for n in PACKAGES)
        if folder.is_relative_to(environment) or not exposes:
            allowed.append(entry)
    return allowed


def _environment(workdir: str) -> dict[str, str]:
    return {
        "PATH": os.defpath,
        "HOME": workdir,
        "TMPDIR": workdir,
        "MPLCONFIGDIR": workdir,
        "LANG": "C.UTF-8",
        "MPLBACKEND": "Agg",
        "PYTHONDONTWRITEBYTECODE": "1",
        "PYTHONHASHSEED": "0",
        # One BLAS thread keeps memory and timing per submission predictable.
        "OPENBLAS_NUM_THREADS": "1",
        "OMP_NUM_THREADS": "1",
        "MKL_NUM_THREADS": "1",
    }


def _describe_exit(code: int | None) -> str:
    if code is None:
        return "the process stopped responding"
    if code < 0:
        try:
            name = signal.Signals(-code).name
        except ValueError:
            name = f"signal {-code}"
        if name == "SIGKILL":
            return "the process was killed (SIGKILL; often the memory limit)"
        return f"the process crashed ({name})"
    return f"the process exited with code {code} before finishing"


class _Session:
    """One worker process working through a list of tasks."""

    def __init__(self, statements, tasks, limits, allow_reference, result, started):
        self.tasks = tasks
        self.limits = limits
        self.result = result
        self.started = started
        self.workdir = tempfile.mkdtemp(prefix="cagd-grade-")
        read_fd, write_fd = os.pipe()
        self.proc = subprocess.Popen(
            [sys.executable, "-I", "-S", str(WORKER), str(write_fd)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            cwd=self.workdir,
            env=_environment(self.workdir),
            pass_fds=(write_fd,),
            start_new_session=True,
        )
        os.close(write_fd)
        self.events = os.fdopen(read_fd, "rb", buffering=0)
        path = _allowed_path(allow_reference)
        request = {
            "statements": statements,
            "tasks": [{"exercise": t.exercise, "function": t.function, "cases": t.cases} for t in tasks],
            "path": path,
            "allow_reference": allow_reference,
            "sandbox": sandbox.policy(self.workdir, limits.memory_mb, path, allow_reference),
        }
        try:
            self.proc.stdin.write(json.dumps(request).encode())
            self.proc.stdin.close()
        except BrokenPipeError:
            pass
        self.current: str | None = None
        self.exercise_started = time.monotonic()
        self.done = False
        self.loaded = False

    def deadline(self) -> float:
        """When the exercise in progress (or the loading) and the submission as a whole run out of time."""
        return min(self.exercise_started + self.limits.exercise_seconds, self.started + self.limits.submission_seconds)

    def run(self) -> list[Task]:
        """Drive the worker until it finishes, dies or overruns; return the tasks still to do."""
        selector = selectors.DefaultSelector()
        selector.register(self.events, selectors.EVENT_READ, "events")
        selector.register(self.proc.stdout, selectors.EVENT_READ, "output")
        buffer = b""
        open_streams = 2
        try:
            while open_streams and not self.done:
                timeout = self.deadline() - time.monotonic()
                if timeout <= 0:
                    return self._overrun()
                for key, _ in selector.select(timeout):
                    chunk = os.read(key.fileobj.fileno(), 65536)
                    if not chunk:
                        selector.unregister(key.fileobj)
                        open_streams -= 1
                        continue
                    if key.data == "output":
                        self._capture(chunk)
                        continue
                    buffer += chunk
                    *lines, buffer = buffer.split(b"\n")
                    for line in lines:
                        self._handle(line)
            if self.done:
                return []
            return self._died()
        finally:
            selector.close()
            self._stop()

    def _handle(self, line: bytes) -> None:
        """Process one event from the worker, checking it is the one the protocol allows next."""
        try:
            event = json.loads(line)
            kind = event["event"]
        except (ValueError, KeyError, TypeError):
            raise _ProtocolError("the graded process wrote something that is not a grader event") from None
        if kind == "loaded":
            self.loaded = True
            self.result.load_problems = [str(p) for p in event.get("problems", [])][:50]
            self.result.sandbox = str(event.get("sandbox", ""))[:200]
        elif kind == "start":
            expected = self.tasks[0].exercise if self.tasks else None
            if event.get("exercise") != expected:
                raise _ProtocolError("the graded process reported an exercise out of order")
            self.current = expected
            self.result.events[expected] = []
            self.exercise_started = time.monotonic()
        elif kind == "case":
            cases = self.result.events.get(self.current)
            if cases is None or event.get("exercise") != self.current or event.get("index") != len(cases):
                raise _ProtocolError("the graded process reported a case out of order")
            if len(cases) >= len(self.tasks[0].cases):
                raise _ProtocolError("the graded process reported more cases than it was given")
            cases.append(event)
        elif kind == "end":
            finished = len(self.result.events[self.current]) == len(self.tasks[0].cases)
            if event.get("exercise") != self.current or not finished:
                raise _ProtocolError("the graded process ended an exercise early")
            self.result.seconds[self.current] = time.monotonic() - self.exercise_started
            self.tasks = self.tasks[1:]
            self.current = None
        elif kind == "done":
            self.done = not self.tasks

    def _capture(self, chunk: bytes) -> None:
        room = self.limits.output_bytes - len(self.result.output.encode())
        if room > 0:
            self.result.output += chunk[:room].decode("utf-8", errors="replace")
        if len(chunk) > room:
            self.result.output_truncated = True

    def _stop_current(self, reason: str) -> list[Task]:
        """Mark the exercise in progress (or all, if loading failed) as stopped; return what is left."""
        if not self.loaded:
            for task in self.tasks:
                self.result.stopped[task.exercise] = f"{reason} while loading the submission"
            return []
        if not self.tasks:
            return []
        current = self.tasks[0].exercise
        self.result.stopped[current] = reason
        if current == self.current:
            self.result.seconds[current] = time.monotonic() - self.exercise_started
        return self.tasks[1:]

    def _overrun(self) -> list[Task]:
        if time.monotonic() >= self.started + self.limits.submission_seconds:
            self._stop_current(f"stopped: the submission's time limit of {self.limits.submission_seconds:g} s ran out")
            for task in self.tasks[1:]:
                self.result.stopped.setdefault(task.exercise, "not run: the submission's time limit ran out")
            return []
        return self._stop_current(f"timed out after {self.limits.exercise_seconds:g} s")

    def _died(self) -> list[Task]:
        try:
            code = self.proc.wait(timeout=2)
        except subprocess.TimeoutExpired:
            code = None
        return self._stop_current(_describe_exit(code))

    def _stop(self) -> None:
        try:
            os.killpg(self.proc.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass
        self.proc.wait()
        self.events.close()
        self.proc.stdout.close()
        shutil.rmtree(self.workdir, ignore_errors=True)


class _ProtocolError(Exception):
    pass


def run_tasks(
    statements: list[dict], tasks: list[Task], limits: Limits = Limits(), allow_reference: bool = False
) -> RunResult:
    """Run every task in isolated worker processes, restarting after a hang or crash."""
    result = RunResult()
    started = time.monotonic()
    remaining = list(tasks)
    while remaining:
        session = _Session(statements, remaining, limits, allow_reference, result, started)
        try:
            remaining = session.run()
        except _ProtocolError as err:
            remaining = session._stop_current(str(err))
    return result
