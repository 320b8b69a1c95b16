"""The confinement the worker applies to itself before it runs any submitted code.

The grader describes the policy as data; `worker.apply_sandbox` enforces it in
the child process (so the grader needs no `preexec_fn`, which is unsafe with
threads). Limits set there cannot be raised again by the submission. The
worker reports what it applied and which gaps remain; `risks` says in plain
words what graded code can do through each gap, for the instructor who is
about to grade unconfined.
"""

from __future__ import annotations

import functools
import os
import sys
from pathlib import Path

__all__ = ["policy", "disabled", "risks", "readable_roots", "DISABLE_ENV"]

# Files a submission may write in its scratch folder (output floods go to the pipe, not here).
FILE_BYTES = 50 * 2**20

# pid_max of each worker's PID namespace: the kernel's smallest allowed value, so at most 300 tasks.
PID_MAX = 301
# RLIMIT_NPROC where neither seccomp nor a PID namespace bounds the processes (it binds non-root users only).
PROCESSES = 64

# System folders a Python process needs to read (shared libraries, locale, /dev/urandom, /proc/self).
SYSTEM_READABLE = ("/usr", "/lib", "/lib64", "/lib32", "/etc", "/proc", "/dev", "/sys")

# Turns layers of the confinement off, to test the grader's fallbacks and its refusal to grade
# unconfined: a comma-separated subset of LAYERS. Grading without a layer is refused or reported.
DISABLE_ENV = "CAGD_SANDBOX_DISABLE"
LAYERS = ("landlock", "namespaces", "seccomp")

# What graded code can do through each gap the worker reports.
RISKS = {
    "files": (
        "read every file you can read: the reference solutions (cagd_ref) and the hidden suites "
        "(tests/hidden), so a submission can run the reference and score full marks; and write or delete "
        "every file you can write, the gradebook, other submissions' feedback and the grader itself included"
    ),
    "processes": "start processes that keep running after grading ends",
    "process_count": "start processes without bound (a fork bomb can exhaust the machine)",
    "ipc": "leave shared memory and message queues behind, holding memory after grading ends",
    "signals": "send signals to your other processes, the grader included",
    "network": "open network connections",
}


def disabled() -> list[str]:
    """The layers the environment switch turns off (unknown names are refused, not ignored)."""
    names = [n.strip() for n in os.environ.get(DISABLE_ENV, "").split(",") if n.strip()]
    unknown = sorted(set(names) - set(LAYERS))
    if unknown:
        raise ValueError(f"{DISABLE_ENV}: unknown layer(s) {unknown}; known: {list(LAYERS)}")
    return names


def risks(gaps: list[str]) -> list[str]:
    """One sentence per gap: what graded code can do through it."""
    return [RISKS[gap] for gap in gaps if gap in RISKS]


@functools.lru_cache(maxsize=8)
def readable_roots(
    roots: tuple[str, ...], hidden: tuple[str, ...], checkout: str | None = None, environment: str | None = None
) -> tuple[str, ...]:
    """`roots` as folders Landlock may allow, none of which holds a folder of `hidden` or the `checkout`.

    Landlock only ever allows a whole tree, so a root that holds a hidden folder (a non-editable
    install of the course in site-packages, a checkout under /usr/src) is replaced by its entries,
    recursively, leaving the hidden folder out. A root inside a hidden folder is dropped, and so is
    a root inside the checkout unless it lies in the interpreter's `environment` (a virtual
    environment kept in the checkout): nothing else of the checkout is readable.
    """
    hidden_paths = [Path(h) for h in hidden]
    course = Path(checkout) if checkout else None
    own = Path(environment).resolve() if environment else None
    secret = hidden_paths + ([course] if course else [])
    allowed: list[str] = []

    def add(path: Path, named: bool) -> None:
        if any(path.is_relative_to(h) for h in hidden_paths):
            return
        in_environment = named and own is not None and path.is_relative_to(own)
        if course is not None and path.is_relative_to(course) and not in_environment:
            return
        if not any(s != path and s.is_relative_to(path) for s in secret):
            allowed.append(str(path))
            return
        try:
            entries = sorted(path.iterdir())
        except OSError:
            return
        for entry in entries:
            add(entry, named=False)

    for root in roots:
        try:
            add(Path(root).resolve(), named=True)
        except OSError:
            continue
    return tuple(dict.fromkeys(allowed))


def policy(
    workdir: str,
    memory_mb: int,
    import_path: list[str],
    allow_reference: bool,
    hidden: tuple[str, ...] = (),
    checkout: str | None = None,
    required: bool = False,
) -> dict:
    """Limits for one worker: address space, largest file, no core dumps; reading only the
    interpreter, the import path and system folders, never a folder of `hidden` (the course's
    packages, wherever they are installed) nor the course's `checkout` (its hidden suites, any
    copy of the reference); writing only `workdir`. `required`: the worker refuses to run
    submitted code unconfined."""
    roots = tuple(sorted({sys.base_prefix, sys.prefix, sys.exec_prefix, *import_path, *SYSTEM_READABLE}))
    return {
        "memory_bytes": int(memory_mb) * 2**20,
        "file_bytes": FILE_BYTES,
        "workdir": workdir,
        "readable": [*readable_roots(roots, tuple(sorted(hidden)), checkout, sys.prefix), workdir],
        # What a worker running as a user of its own must find closed by file modes where Landlock is missing.
        "protected": [*sorted(hidden), *([checkout] if checkout else [])],
        "trusted": bool(allow_reference),
        "required": bool(required) and not allow_reference,
        "disable": disabled(),
        "pid_max": PID_MAX,
        "processes": PROCESSES,
    }
