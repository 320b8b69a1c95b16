"""The student-side process of the grader: runs submitted functions on cases and reports the outputs.

This file runs as a standalone script (``python -I -S worker.py FD``) in a fresh
temporary folder, with a scrubbed environment, and must not import `cagd_ref`
or `cagd_course`: the reference solutions and the grader are out of reach of the
code it runs. The grader sends
one JSON request on stdin (the submission's source as top-level statements,
the allowed ``sys.path``, limits, and the cases of each exercise). The worker
sends JSON lines back on file descriptor FD: one event per loaded submission,
per exercise start, per case and per exercise end. Everything the student's
code prints goes to stdout/stderr, which the grader captures separately.

Only inputs travel to this process, never expected values; the grader compares
the returned data in its own process, so nothing done here can raise a grade.
The value codec below is shared with the grader, which imports this module.
"""

from __future__ import annotations

import builtins
import json
import math
import os
import sys

# The course's own packages: the reference solutions and the grader. Submissions import neither.
PACKAGES = ("cagd_ref", "cagd_course")

# Caps on what one returned value may cost the grader to read.
MAX_ARRAY_SIZE = 1_000_000
MAX_DEPTH = 16
MAX_EVENT_BYTES = 8_000_000


# --- value codec (plain JSON, never pickle: the grader must not unpickle student data) ---


class Unsupported:
    """A value the codec cannot carry (an object, a complex number, something huge): compared as wrong."""

    def __init__(self, description: str):
        self.description = description

    def __repr__(self) -> str:
        return self.description


def encode(value, depth: int = 0):
    """Turn numbers, strings, lists, tuples, dicts and NumPy arrays into JSON-ready data."""
    if depth > MAX_DEPTH:
        return {"__unsupported__": "a value nested too deeply"}
    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, int):
        return value if abs(value) < 2**63 else float(value)
    if isinstance(value, float):
        return value if math.isfinite(value) else {"__float__": repr(value)}
    np = sys.modules.get("numpy")
    if np is not None:
        if isinstance(value, np.generic):
            return encode(value.item(), depth + 1)
        if isinstance(value, np.ndarray):
            return _encode_array(value, depth)
    if isinstance(value, list):
        return [encode(v, depth + 1) for v in value[:MAX_ARRAY_SIZE]]
    if isinstance(value, tuple):
        return {"__tuple__": [encode(v, depth + 1) for v in value[:MAX_ARRAY_SIZE]]}
    if isinstance(value, dict) and all(isinstance(k, str) for k in value):
        return {"__dict__": {k: encode(v, depth + 1) for k, v in value.items()}}
    return {"__unsupported__": f"a {type(value).__name__} object"}


def _encode_array(array, depth: int):
    if array.size > MAX_ARRAY_SIZE:
        return {"__unsupported__": f"an array of {array.size} entries (too large)"}
    if array.dtype.kind in "biuf":
        flat = [encode(float(x)) if array.dtype.kind == "f" else x for x in array.ravel().tolist()]
        return {"__ndarray__": flat, "dtype": array.dtype.kind, "shape": list(array.shape)}
    if array.dtype.kind == "O":
        return {"__objects__": [encode(v, depth + 1) for v in array.ravel().tolist()], "shape": list(array.shape)}
    return {"__unsupported__": f"an array of dtype {array.dtype}"}


def decode(data):
    """Inverse of `encode` (NumPy is imported lazily so the codec costs nothing until arrays appear)."""
    if isinstance(data, list):
        return [decode(v) for v in data]
    if not isinstance(data, dict):
        return data
    if "__float__" in data:
        return float(data["__float__"])
    if "__tuple__" in data:
        return tuple(decode(v) for v in data["__tuple__"])
    if "__dict__" in data:
        return {k: decode(v) for k, v in data["__dict__"].items()}
    if "__ndarray__" in data:
        import numpy as np

        dtype = {"b": bool, "i": np.int64, "u": np.uint64, "f": float}.get(data.get("dtype"), float)
        values = [decode(v) for v in data["__ndarray__"]]
        return np.array(values, dtype=dtype).reshape(data["shape"])
    if "__objects__" in data:
        import numpy as np

        values = np.empty(len(data["__objects__"]), dtype=object)
        values[:] = [decode(v) for v in data["__objects__"]]
        return values.reshape(data["shape"])
    if "__unsupported__" in data:
        return Unsupported(str(data["__unsupported__"]))
    return Unsupported("an unrecognised value")


# --- running the submission ---


def error_record(err: BaseException) -> dict:
    """Name and message of an exception; subclasses report the built-in they derive from."""
    name = type(err).__name__
    for cls in type(err).__mro__:
        if cls.__module__ == "builtins":
            name = cls.__name__
            break
    try:
        message = str(err)[:500]
    except Exception:  # a student exception whose __str__ fails
        message = "(message could not be shown)"
    return {"type": name, "message": message}


class _ReferenceBlocker:
    """Refuses imports of the course's packages, whatever route the import takes."""

    def find_spec(self, name, path=None, target=None):
        package = name.partition(".")[0]
        if package in PACKAGES:
            raise ImportError(f"the course package {package} is not available while grading")
        return None


def load_submission(statements: list[dict], namespace: dict) -> list[str]:
    """Execute each top-level statement on its own, so one broken import does not lose the rest."""
    problems = []
    for statement in statements:
        try:
            code = compile(statement["source"], f"<{statement['where']}>", "exec")
            exec(code, namespace)
        except BaseException as err:  # noqa: BLE001 - anything a submission raises is reported, not fatal
            record = error_record(err)
            problems.append(f"{statement['where']}: {record['type']}: {record['message']}")
    return problems


def run_case(function, case: dict) -> dict:
    """Call the student's function on one case; report its value (or exception) and the inputs afterwards."""
    args = decode(case["args"])
    kwargs = decode(case["kwargs"])
    try:
        outcome = {"value": encode(function(*args, **kwargs))}
    except BaseException as err:  # noqa: BLE001 - SystemExit and friends count as failures of this case
        outcome = {"raised": error_record(err)}
    outcome["args_after"] = encode(list(args))
    return outcome


class Channel:
    """JSON lines to the grader on a file descriptor the submission's prints never touch."""

    def __init__(self, fd: int):
        self.fd = fd

    def send(self, event: dict) -> None:
        line = json.dumps(event, allow_nan=True)
        if len(line) > MAX_EVENT_BYTES:
            event = {k: v for k, v in event.items() if k not in ("value", "args_after")}
            event["value"] = {"__unsupported__": "a result too large to send back"}
            line = json.dumps(event)
        data = (line + "\n").encode()
        while data:
            written = os.write(self.fd, data)
            data = data[written:]


# Landlock (Linux >= 5.13) filesystem rights, by the ABI version that introduced them.
_FS_EXECUTE, _FS_WRITE_FILE, _FS_READ_FILE, _FS_READ_DIR = 1 << 0, 1 << 1, 1 << 2, 1 << 3
_FS_RIGHTS_BY_ABI = {1: (1 << 13) - 1, 2: 1 << 13, 3: 1 << 14, 5: 1 << 15}
_SYS_CREATE_RULESET, _SYS_ADD_RULE, _SYS_RESTRICT_SELF = 444, 445, 446  # the same on every architecture
_PR_SET_NO_NEW_PRIVS = 38


def _landlock(readable: list[str], writable: list[str]) -> str:
    """Allow reading only beneath `readable`, writing only beneath `writable`; no TCP, no signals out.

    Returns what was applied, for the record; kernels without Landlock keep the rlimits only.
    """
    import ctypes

    libc = ctypes.CDLL(None, use_errno=True)
    syscall = libc.syscall
    syscall.restype = ctypes.c_long
    abi = syscall(_SYS_CREATE_RULESET, None, ctypes.c_size_t(0), ctypes.c_uint32(1))
    if abi < 1:
        return "landlock unavailable"
    fs_rights = sum(bits for version, bits in _FS_RIGHTS_BY_ABI.items() if abi >= version)

    class RulesetAttr(ctypes.Structure):
        _fields_ = [("fs", ctypes.c_uint64), ("net", ctypes.c_uint64), ("scoped", ctypes.c_uint64)]

    class PathBeneath(ctypes.Structure):
        _pack_ = 1
        _fields_ = [("allowed", ctypes.c_uint64), ("parent_fd", ctypes.c_int32)]

    # ABI 4 added TCP bind/connect rights, ABI 6 signal and abstract-socket scoping.
    size = 8 if abi < 4 else 16 if abi < 6 else 24
    attr = RulesetAttr(fs_rights, 0b11 if abi >= 4 else 0, 0b11 if abi >= 6 else 0)
    ruleset = syscall(_SYS_CREATE_RULESET, ctypes.byref(attr), ctypes.c_size_t(size), ctypes.c_uint32(0))
    if ruleset < 0:
        return "landlock refused the ruleset"
    rules = [(p, _FS_EXECUTE | _FS_READ_FILE | _FS_READ_DIR) for p in readable]
    rules += [(p, fs_rights) for p in writable]
    rules.append(("/dev/null", _FS_READ_FILE | _FS_WRITE_FILE))
    for path, rights in rules:
        try:
            fd = os.open(path, os.O_PATH | os.O_CLOEXEC)
        except OSError:
            continue
        if not os.path.isdir(path):
            rights &= _FS_EXECUTE | _FS_READ_FILE | _FS_WRITE_FILE | (1 << 14) | (1 << 15)
        rule = PathBeneath(rights & fs_rights, fd)
        syscall(_SYS_ADD_RULE, ctypes.c_int(ruleset), ctypes.c_int(1), ctypes.byref(rule), ctypes.c_uint32(0))
        os.close(fd)
    libc.prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)
    if syscall(_SYS_RESTRICT_SELF, ctypes.c_int(ruleset), ctypes.c_uint32(0)) != 0:
        return "landlock could not be enforced"
    os.close(ruleset)
    return f"landlock ABI {abi}"


def _drop_capabilities() -> None:
    """Give up every capability, so a grader running as root cannot lend its powers (e.g. raising limits)."""
    import ctypes

    class Header(ctypes.Structure):
        _fields_ = [("version", ctypes.c_uint32), ("pid", ctypes.c_int)]

    class Data(ctypes.Structure):
        _fields_ = [("effective", ctypes.c_uint32), ("permitted", ctypes.c_uint32), ("inheritable", ctypes.c_uint32)]

    libc = ctypes.CDLL(None, use_errno=True)
    libc.capset(ctypes.byref(Header(0x20080522, 0)), ctypes.byref((Data * 2)()))


def apply_sandbox(policy: dict) -> str:
    """Confine this process before any submitted code runs; return a note of what was applied."""
    import resource

    notes = []
    limits = (("RLIMIT_AS", policy["memory_bytes"]), ("RLIMIT_FSIZE", policy["file_bytes"]), ("RLIMIT_CORE", 0))
    for name, value in limits:
        try:
            resource.setrlimit(getattr(resource, name), (value, value))
        except (AttributeError, ValueError, OSError):
            # Some systems (macOS for the address space) refuse a limit; grade without it, and say so.
            notes.append(f"{name} unavailable")
    if policy.get("trusted"):
        return "; ".join(notes or ["rlimits"])
    if sys.platform.startswith("linux"):
        notes.append(_landlock(policy["readable"], [policy["workdir"]]))
        _drop_capabilities()
    else:
        notes.append("no file-system confinement on this platform")
    return "; ".join(notes)


def serve(request: dict, channel: Channel) -> None:
    """Load the submission and run every task of the request, reporting as it goes."""
    sys.path[:] = request["path"]
    # NumPy is imported before the limits so its start-up cost is not the student's,
    # and before any submitted code so the codec uses the real module.
    import numpy  # noqa: F401

    sandbox_note = apply_sandbox(request["sandbox"])
    if not request.get("allow_reference"):
        sys.meta_path.insert(0, _ReferenceBlocker())
    namespace = {"__name__": "__submission__", "__builtins__": builtins}
    problems = load_submission(request["statements"], namespace)
    channel.send({"event": "loaded", "problems": problems, "sandbox": sandbox_note})
    for task in request["tasks"]:
        channel.send({"event": "start", "exercise": task["exercise"]})
        function = namespace.get(task["function"])
        for index, case in enumerate(task["cases"]):
            if callable(function):
                outcome = run_case(function, case)
            else:
                outcome = {"missing": f"no function named {task['function']} is defined"}
            channel.send({"event": "case", "exercise": task["exercise"], "index": index, **outcome})
        channel.send({"event": "end", "exercise": task["exercise"]})
    channel.send({"event": "done"})


def main(argv: list[str]) -> int:
    channel = Channel(int(argv[1]))
    request = json.loads(sys.stdin.read())
    sys.stdin.close()
    serve(request, channel)
    # Skip interpreter teardown: a submission's atexit hooks or finalizers must not run after reporting.
    os._exit(0)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
