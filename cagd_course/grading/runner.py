"""Run a submission's functions in separate, confined processes and collect what they return.

The grader never executes student code itself. On Linux `run_tasks` asks a
zygote (`worker.py --zygote`, started once per grading process, NumPy already
imported) to fork a worker for the submission, contained in its own user, PID,
IPC and network namespaces; elsewhere it starts `worker.py` under a fresh
interpreter. Either way the interpreter runs ``-I -S`` (no user site, no
``.pth`` files, so the editable reference package is not on its path) with a
scrubbed environment in a new temporary folder, confines itself before any
submitted code runs, and is supervised from outside: a wall-clock deadline per
exercise and per submission enforced with SIGKILL, a memory limit, and
captured, truncated output. When the worker hangs or dies, the exercise it was
on is marked and a fresh worker carries on with the remaining exercises,
started while the old one is being killed. `run_tasks` returns only once every
process of the submission has ended and its folder is gone.
"""

from __future__ import annotations

import atexit
import functools
import importlib.util
import json
import os
import selectors
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

from ..manifest import COURSE_ENV, find_course_root
from . import sandbox
from .worker import PACKAGES

__all__ = ["Limits", "Task", "RunResult", "run_tasks", "probe", "shutdown", "worker_path", "run_as"]

WORKER = Path(__file__).with_name("worker.py")
# A zygote's start is an interpreter importing NumPy, on a machine that may be busy grading.
START_SECONDS = 60.0
# How long the keeper may take to report the worker it forked, and a killed worker to be gone.
SPAWN_SECONDS = 10.0
REAP_SECONDS = 10.0


@dataclass(frozen=True)
class Limits:
    """Resource limits for one submission's process."""

    exercise_seconds: float = 10.0
    submission_seconds: float = 120.0
    memory_mb: int = 1024
    output_bytes: int = 20_000


@dataclass(frozen=True)
class Task:
    """One exercise to run: the student function's name and its encoded cases (and their JSON, if at hand)."""

    exercise: str
    function: str
    cases: list
    cases_json: str = ""

    def request_json(self) -> str:
        cases = self.cases_json or json.dumps(self.cases)
        return f'{{"exercise": {json.dumps(self.exercise)}, "function": {json.dumps(self.function)}, "cases": {cases}}}'


@dataclass
class RunResult:
    """What came back: case events per exercise, why an exercise stopped early, and the confinement.

    `sandbox` is the worker's note of what it applied, `confined` whether that holds graded code
    (files, processes and their number), `gaps` what was left open (keys of `sandbox.RISKS`).
    """

    load_problems: list[str] = field(default_factory=list)
    events: dict[str, list[dict]] = field(default_factory=dict)
    stopped: dict[str, str] = field(default_factory=dict)
    output: str = ""
    output_truncated: bool = False
    seconds: dict[str, float] = field(default_factory=dict)
    sandbox: str = ""
    confined: bool = False
    gaps: list[str] = field(default_factory=list)

    def record_sandbox(self, note: str, confined: bool, gaps: list[str]) -> None:
        """Keep the weakest confinement any worker of this run reported."""
        if not self.sandbox or (self.confined and not confined):
            self.sandbox, self.confined = note, confined
        self.gaps = sorted(set(self.gaps) | set(gaps))


def worker_path() -> Path:
    return WORKER


def _package_home(name: str) -> Path:
    """The folder on the import path that holds package `name` (without importing it)."""
    spec = importlib.util.find_spec(name)
    return Path(next(iter(spec.submodule_search_locations))).resolve().parent


def _hidden_folders() -> tuple[tuple[str, ...], str | None]:
    """What graded code must not read, wherever the course is installed: its packages, and its checkout."""
    return _hidden_folders_for(tuple(sys.path), os.environ.get(COURSE_ENV), os.getcwd())


@functools.lru_cache(maxsize=16)
def _hidden_folders_for(path: tuple[str, ...], course: str | None, cwd: str) -> tuple[tuple[str, ...], str | None]:
    found = set()
    for name in PACKAGES:
        try:
            found.add(str(_package_home(name) / name))
        except (ImportError, AttributeError, TypeError, StopIteration):
            continue
    try:
        root = str(find_course_root())
    except FileNotFoundError:
        root = None
    return tuple(sorted(found)), root


def _allowed_path(allow_reference: bool) -> list[str]:
    """The grader's import path minus every folder that would expose the course's packages or files.

    Computed once per import path, course and environment: it looks at every entry on disk.
    """
    key = (tuple(sys.path), sys.prefix, os.environ.get(COURSE_ENV), os.getcwd(), allow_reference)
    return list(_allowed_path_for(*key))


@functools.lru_cache(maxsize=16)
def _allowed_path_for(path: tuple[str, ...], prefix: str, course, cwd: str, allow_reference: bool) -> tuple[str, ...]:
    """What `_allowed_path` returns, for the import path `path` of the environment at `prefix`.

    Untrusted runs keep the interpreter's own environment (NumPy lives there, and so does a normal,
    non-editable install of the course, whose packages the worker refuses to import by name and
    whose folders it cannot read) and lose every other entry that holds `cagd_ref` or `cagd_course`
    or lies inside the course folder (the checkout with its reference and hidden suites). Trusted
    runs (validating the reference itself) get the reference's folder first.
    """
    entries = [entry for entry in path if entry and os.path.isdir(entry)]
    if allow_reference:
        return (str(_package_home("cagd_ref")), *entries)
    hidden = {_package_home(name) for name in PACKAGES}
    try:
        hidden.add(find_course_root())
    except FileNotFoundError:
        pass
    environment = Path(prefix).resolve()
    allowed = []
    for entry in entries:
        folder = Path(entry).resolve()
        exposes = any(folder.is_relative_to(h) for h in hidden) or any((folder / n).exists() for n in PACKAGES)
        if folder.is_relative_to(environment) or not exposes:
            allowed.append(entry)
    return tuple(allowed)


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


class _StartError(Exception):
    """No worker could be started (the zygote did not come up or did not fork)."""


class _ForkedWorker:
    """A worker forked by the zygote: pipes to it, a pidfd to kill it, and its keeper's report of its end."""

    def __init__(self, request, events: int, output: int, status: socket.socket, pidfd: int):
        self.request, self.events, self.output, self.status, self.pidfd = request, events, output, status, pidfd
        self.code: int | None = None
        self.ended = False

    def kill(self) -> None:
        try:
            signal.pidfd_send_signal(self.pidfd, signal.SIGKILL)
        except OSError:  # it has already ended
            pass

    def exit_code(self, timeout: float) -> int | None:
        """The worker's exit code (negative: the signal), once its keeper has reaped it; None if unknown."""
        if not self.ended:
            self.status.settimeout(timeout)
            try:
                data = self.status.recv(4096)
                event = json.loads(data) if data else {}
            except (OSError, ValueError):
                return None
            self.ended = True
            if event.get("event") == "exit" and isinstance(event.get("code"), int):
                self.code = event["code"]
        return self.code

    def close(self) -> None:
        self.kill()
        # The keeper reports only after reaping the worker, whose PID namespace died with it, and then
        # exits: the end of its socket says it is gone too.
        self.exit_code(REAP_SECONDS)
        try:
            while self.status.recv(4096):
                pass
        except OSError:
            pass
        for fd in (self.events, self.output, self.pidfd):
            os.close(fd)
        self.status.close()
        if not self.request.closed:
            self.request.close()


class _ExecWorker:
    """A worker started as a fresh interpreter (platforms without the zygote): a process group to kill."""

    def __init__(self, workdir: str):
        read_fd, write_fd = os.pipe()
        user = {} if _RUN_AS[0] is None else {"user": _RUN_AS[0][0], "group": _RUN_AS[0][1], "extra_groups": []}
        self.proc = subprocess.Popen(
            [sys.executable, "-I", "-S", str(WORKER), str(write_fd)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            cwd=workdir,
            env=_environment(workdir),
            pass_fds=(write_fd,),
            start_new_session=True,
            **user,
        )
        os.close(write_fd)
        self.request, self.events, self.output = self.proc.stdin, read_fd, self.proc.stdout.fileno()

    def kill(self) -> None:
        try:
            os.killpg(self.proc.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass

    def exit_code(self, timeout: float) -> int | None:
        try:
            return self.proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            return None

    def close(self) -> None:
        self.kill()
        self.proc.wait()
        os.close(self.events)
        self.proc.stdout.close()
        if not self.request.closed:
            self.request.close()


class _Zygote:
    """A clean interpreter with NumPy imported that forks one contained worker per request."""

    def __init__(self, path: list[str]):
        ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        folder = tempfile.gettempdir()
        command = [sys.executable, "-I", "-S", str(WORKER), "--zygote", str(theirs.fileno()), str(os.getpid())]
        try:
            self.proc = subprocess.Popen(
                [*command, str(_OWNER[0] or os.getpid())],
                stdin=subprocess.PIPE,
                stdout=subprocess.DEVNULL,
                cwd=folder,
                env=_environment(folder),
                pass_fds=(theirs.fileno(),),
                # Not in the terminal's process group: Ctrl-C stops the grader, which then stops the zygote.
                start_new_session=True,
            )
        except OSError as err:
            ours.close()
            raise _StartError(f"the zygote could not be started ({err})") from None
        finally:
            theirs.close()
        self.control = ours
        self.lock = threading.Lock()
        try:
            self.proc.stdin.write(json.dumps({"path": path}).encode())
            self.proc.stdin.close()
            ours.settimeout(START_SECONDS)
            ready = ours.recv(16)
        except OSError as err:
            ready = str(err).encode()
        if ready != b"ready":
            self.close()
            raise _StartError(f"the zygote did not start ({ready.decode(errors='replace') or 'it exited'})")
        ours.settimeout(None)

    def alive(self) -> bool:
        return self.proc.poll() is None

    def spawn(self, options: dict) -> _ForkedWorker:
        request_r, request_w = os.pipe()
        events_r, events_w = os.pipe()
        output_r, output_w = os.pipe()
        status, keeper_end = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        mine = (request_w, events_r, output_r)
        try:
            with self.lock:
                socket.send_fds(
                    self.control, [json.dumps(options).encode()], [request_r, events_w, output_w, keeper_end.fileno()]
                )
            status.settimeout(SPAWN_SECONDS)
            message, fds, _, _ = socket.recv_fds(status, 4096, 1)
            event = json.loads(message) if message else {}
        except (OSError, ValueError) as err:
            event, fds = {"error": str(err)}, []
        finally:
            for fd in (request_r, events_w, output_w):
                os.close(fd)
            keeper_end.close()
        if event.get("event") != "started" or len(fds) != 1:
            for fd in (*mine, *fds):
                os.close(fd)
            status.close()
            raise _StartError(event.get("error") or "the zygote did not fork a worker")
        status.settimeout(None)
        return _ForkedWorker(os.fdopen(request_w, "wb"), events_r, output_r, status, fds[0])

    def close(self) -> None:
        # The zygote ends when its socket closes, killing any keeper still running.
        self.control.close()
        try:
            self.proc.wait(timeout=REAP_SECONDS)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


_LOCK = [threading.Lock()]
_ZYGOTE: list[_Zygote] = []
# The process that started the grading run (a `--jobs` process's parent), shown in the zygote's command line.
_OWNER: list[int | None] = [None]


def _forks_workers() -> bool:
    return sys.platform.startswith("linux") and hasattr(os, "pidfd_open") and hasattr(socket, "send_fds")


def _zygote() -> _Zygote:
    with _LOCK[0]:
        if _ZYGOTE and not _ZYGOTE[0].alive():
            _ZYGOTE.pop().close()
        if not _ZYGOTE:
            _ZYGOTE.append(_Zygote(_allowed_path(allow_reference=False)))
        return _ZYGOTE[0]


def _spawn(workdir: str):
    if not _forks_workers():
        return _ExecWorker(workdir)
    options = {"disable": sandbox.disabled()}
    if _RUN_AS[0] is not None:
        options["user"] = list(_RUN_AS[0])
    try:
        return _zygote().spawn(options)
    except _StartError:
        # One retry with a fresh zygote: the old one may have been killed from outside.
        shutdown()
        return _zygote().spawn(options)


def shutdown() -> None:
    """Stop this process's zygote and every worker it still has (it also stops when this process ends)."""
    with _LOCK[0]:
        while _ZYGOTE:
            _ZYGOTE.pop().close()


def set_owner(pid: int) -> None:
    """Name `pid` as the grading run's process in the zygote's command line (for `ps`, and tests)."""
    _OWNER[0] = pid


# The unprivileged user (uid, gid) graded code runs as, when the grader runs as root (`run_as`).
_RUN_AS: list[tuple[int, int] | None] = [None]


def run_as(user: str | int | None) -> tuple[int, int] | None:
    """Run graded code as `user` (a name or uid; None: as the grader) from now on; returns its (uid, gid).

    Only root can hand its workers to another user (Gradescope runs its autograders as root); the
    user must exist and must not be root. Each worker's scratch folder is given to that user, and
    everything else of the grader stays out of its reach by ownership and modes as well as Landlock.
    """
    if user is None or user == "":
        _RUN_AS[0] = None
        return None
    import pwd

    try:
        entry = pwd.getpwuid(user) if isinstance(user, int) else pwd.getpwnam(str(user))
    except KeyError:
        raise ValueError(f"run_as: no user {user!r} on this machine") from None
    if entry.pw_uid == 0:
        raise ValueError("run_as: graded code must not run as root")
    if os.geteuid() != 0:
        raise PermissionError(f"run_as: only root can run graded code as {entry.pw_name}")
    _RUN_AS[0] = (entry.pw_uid, entry.pw_gid)
    return _RUN_AS[0]


def _forget_after_fork() -> None:
    # A forked copy of the grader starts its own zygote instead of sharing this process's socket.
    for zygote in _ZYGOTE:
        zygote.control.close()
    _ZYGOTE.clear()
    _LOCK[0] = threading.Lock()


atexit.register(shutdown)
os.register_at_fork(after_in_child=_forget_after_fork)


class _Session:
    """One worker process working through a list of tasks."""

    def __init__(self, statements, tasks, limits, allow_reference, required, result, started):
        self.tasks = tasks
        self.limits = limits
        self.result = result
        self.started = started
        self.required = required
        self.current: str | None = None
        self.done = False
        self.sandboxed = False
        self.loaded = False
        self.workdir = tempfile.mkdtemp(prefix="cagd-grade-")
        if _RUN_AS[0] is not None:
            os.chown(self.workdir, *_RUN_AS[0])
        path = _allowed_path(allow_reference)
        hidden, checkout = _hidden_folders()
        policy = sandbox.policy(self.workdir, limits.memory_mb, path, allow_reference, hidden, checkout, required)
        request = {
            "statements": statements,
            "path": path,
            "allow_reference": allow_reference,
            "workdir": self.workdir,
            "environment": _environment(self.workdir),
            "sandbox": policy,
        }
        try:
            self.worker = _spawn(self.workdir)
        except BaseException:
            shutil.rmtree(self.workdir, ignore_errors=True)
            raise
        # The cases go in as the JSON text the grader already made of them.
        text = json.dumps(request)[:-1] + ', "tasks": [' + ",".join(t.request_json() for t in tasks) + "]}"
        try:
            self.worker.request.write(text.encode())
            self.worker.request.close()
        except OSError:  # the worker is already gone; its exit is reported below
            pass
        self.exercise_started = time.monotonic()

    def deadline(self) -> float:
        """When the exercise in progress (or the loading) and the submission as a whole run out of time."""
        return min(self.exercise_started + self.limits.exercise_seconds, self.started + self.limits.submission_seconds)

    def run(self) -> list[Task]:
        """Drive the worker until it finishes, dies or overruns; return the tasks still to do.

        The worker is killed on the way out; `finish` waits for it to be gone.
        """
        selector = selectors.DefaultSelector()
        selector.register(self.worker.events, selectors.EVENT_READ, "events")
        selector.register(self.worker.output, selectors.EVENT_READ, "output")
        buffer = b""
        open_streams = 2
        try:
            while open_streams and not self.done:
                timeout = self.deadline() - time.monotonic()
                if timeout <= 0:
                    return self._overrun()
                for key, _ in selector.select(timeout):
                    chunk = os.read(key.fd, 65536)
                    if not chunk:
                        selector.unregister(key.fd)
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
            self.worker.kill()

    def finish(self) -> None:
        """Wait until the worker and everything it started are gone, and remove its folder."""
        self.worker.close()
        shutil.rmtree(self.workdir, ignore_errors=True)

    def _handle(self, line: bytes) -> None:
        """Process one event from the worker, checking it is the one the protocol allows next."""
        try:
            event = json.loads(line)
            kind = event["event"]
        except (ValueError, KeyError, TypeError):
            raise _ProtocolError("the graded process wrote something that is not a grader event") from None
        if not self.sandboxed:
            # The worker reports its confinement before any submitted code runs: nothing can forge it.
            if kind != "sandbox":
                raise _ProtocolError("the graded process did not report its confinement first")
            self._sandbox(event)
        elif kind == "sandbox":
            raise _ProtocolError("the graded process reported its confinement twice")
        elif kind == "loaded":
            self.loaded = True
            self.result.load_problems = [str(p) for p in event.get("problems", [])][:50]
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

    def _sandbox(self, event: dict) -> None:
        self.sandboxed = True
        gaps = [str(g) for g in event.get("gaps", [])][:10]
        self.result.record_sandbox(str(event.get("note", ""))[:300], event.get("confined") is True, gaps)
        if self.required and event.get("confined") is not True:
            # The worker refuses too; nothing of the submission has run.
            reason = "not graded: graded code cannot be confined here (" + ", ".join(gaps) + ")"
            for task in self.tasks:
                self.result.stopped[task.exercise] = reason
            self.tasks = []
            self.done = True

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
        return self._stop_current(_describe_exit(self.worker.exit_code(timeout=2)))


class _ProtocolError(Exception):
    pass


def run_tasks(
    statements: list[dict],
    tasks: list[Task],
    limits: Limits = Limits(),
    allow_reference: bool = False,
    require_confinement: bool = False,
) -> RunResult:
    """Run every task in contained worker processes, restarting after a hang or crash.

    With `require_confinement` a worker that cannot confine itself runs nothing: every task is
    marked "not graded". Returns once every process of the submission has ended.
    """
    result = RunResult()
    started = time.monotonic()
    remaining = list(tasks)
    previous = None
    try:
        while True:
            try:
                session = _Session(statements, remaining, limits, allow_reference, require_confinement, result, started)
            except _StartError as err:
                for task in remaining:
                    result.stopped.setdefault(task.exercise, f"not run: the grader could not start a worker ({err})")
                break
            if previous is not None:
                previous.finish()  # the replacement is already starting while the old worker is reaped
            previous = session
            try:
                remaining = session.run()
            except _ProtocolError as err:
                remaining = session._stop_current(str(err))
            if not remaining:
                break
    finally:
        if previous is not None:
            previous.finish()
    return result


def probe(limits: Limits = Limits()) -> RunResult:
    """Start one worker with nothing to grade: the confinement graded code gets on this machine."""
    return run_tasks([], [], limits)
