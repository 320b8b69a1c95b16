"""The confinement the worker applies to itself before it runs any submitted code.

The grader describes the policy as data; `worker.apply_sandbox` enforces it in
the child process (so the grader needs no `preexec_fn`, which is unsafe with
the threads of `--jobs`). Limits set there cannot be raised again by the
submission.
"""

from __future__ import annotations

__all__ = ["policy"]

# Files a submission may write in its scratch folder (output floods go to the pipe, not here).
FILE_BYTES = 50 * 2**20


def policy(workdir: str, memory_mb: int, allow_reference: bool) -> dict:
    """Limits for one worker: address-space size, largest file, no core dumps, its scratch folder."""
    return {
        "memory_bytes": int(memory_mb) * 2**20,
        "file_bytes": FILE_BYTES,
        "workdir": workdir,
        "trusted": bool(allow_reference),
    }
