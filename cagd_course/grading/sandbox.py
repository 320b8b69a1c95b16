"""The confinement the worker applies to itself before it runs any submitted code.

The grader describes the policy as data; `worker.apply_sandbox` enforces it in
the child process (so the grader needs no `preexec_fn`, which is unsafe with
the threads of `--jobs`). Limits set there cannot be raised again by the
submission.
"""

from __future__ import annotations

import sys

__all__ = ["policy"]

# Files a submission may write in its scratch folder (output floods go to the pipe, not here).
FILE_BYTES = 50 * 2**20


# System folders a Python process needs to read (shared libraries, locale, /dev/urandom, /proc/self).
SYSTEM_READABLE = ("/usr", "/lib", "/lib64", "/lib32", "/etc", "/proc", "/dev", "/sys")


def policy(workdir: str, memory_mb: int, import_path: list[str], allow_reference: bool) -> dict:
    """Limits for one worker: address space, largest file, no core dumps; reading only the
    interpreter, the import path and system folders (not the course checkout), writing only `workdir`."""
    readable = sorted({sys.base_prefix, sys.prefix, sys.exec_prefix, *import_path, *SYSTEM_READABLE, workdir})
    return {
        "memory_bytes": int(memory_mb) * 2**20,
        "file_bytes": FILE_BYTES,
        "workdir": workdir,
        "readable": readable,
        "trusted": bool(allow_reference),
    }
