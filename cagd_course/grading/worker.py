"""The student-side process of the grader: runs submitted functions on cases and reports the outputs.

On Linux the grader starts this file once per grading process as a *zygote*
(``python -I -S worker.py --zygote FD PARENT OWNER``): a clean interpreter that
imports NumPy and never runs submitted code. For each submission it forks a
*keeper*, which moves into new user, PID, IPC and network namespaces and forks
the *worker*: the init of its PID namespace. When the worker exits or is
killed, the kernel kills everything in the namespace, so nothing a submission
starts outlives it; where namespaces are refused, the keeper tracks the
process tree instead (a subreaper) and kills what is left. Elsewhere the
grader starts ``python -I -S worker.py FD`` per submission. The worker
confines itself (`apply_sandbox`) before any submitted code runs.

This file must not import `cagd_ref` or `cagd_course`: the reference solutions
and the grader are out of reach of the code it runs, and the zygote's memory,
which every worker inherits, holds nothing but this module and NumPy (the
grader passes it file descriptors, never a submission). The grader sends one
JSON request on the worker's stdin (the submission's source as top-level
statements, the allowed ``sys.path``, the sandbox policy, the cases of each
exercise). The worker sends JSON lines back on file descriptor FD (3 when
forked): what confinement it applied, before any submitted code runs; one
event per loaded submission, per exercise start, per case and per exercise
end. Everything the student's code prints goes to stdout/stderr, which the
grader captures separately.

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
    kind = type(value)
    # The common exact types first: both processes encode thousands of these per submission.
    if kind is float:
        return value if value - value == 0.0 else {"__float__": repr(value)}
    if kind is int:
        return value if -(2**63) < value < 2**63 else float(value)
    if depth > MAX_DEPTH:
        return {"__unsupported__": "a value nested too deeply"}
    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, int):
        return value if abs(value) < 2**63 else float(value)
    if isinstance(value, float):
        # NumPy's float64 is a float whose repr is np.float64(nan): send the plain float's.
        return float(value) if math.isfinite(value) else {"__float__": repr(float(value))}
    np = sys.modules.get("numpy")
    if np is not None:
        if isinstance(value, np.generic):
            return encode(value.item(), depth + 1)
        if isinstance(value, np.ndarray):
            return _encode_array(value, depth)
    if isinstance(value, (list, tuple)):
        # Finite floats and small ints stand for themselves: no call per number of a long list.
        items = [
            v
            if (type(v) is float and v - v == 0.0) or (type(v) is int and -(2**63) < v < 2**63)
            else encode(v, depth + 1)
            for v in value[:MAX_ARRAY_SIZE]
        ]
        return items if isinstance(value, list) else {"__tuple__": items}
    if isinstance(value, dict) and all(isinstance(k, str) for k in value):
        return {"__dict__": {k: encode(v, depth + 1) for k, v in value.items()}}
    return {"__unsupported__": f"a {type(value).__name__} object"}


def _encode_array(array, depth: int):
    if array.size > MAX_ARRAY_SIZE:
        return {"__unsupported__": f"an array of {array.size} entries (too large)"}
    if array.dtype.kind in "biuf":
        flat = array.ravel().tolist()
        if array.dtype.kind == "f" and not sys.modules["numpy"].isfinite(array).all():
            flat = [encode(x) for x in flat]
        return {"__ndarray__": flat, "dtype": array.dtype.kind, "shape": list(array.shape)}
    if array.dtype.kind == "O":
        return {"__objects__": [encode(v, depth + 1) for v in array.ravel().tolist()], "shape": list(array.shape)}
    return {"__unsupported__": f"an array of dtype {array.dtype}"}


# What JSON gives back unchanged: decoding leaves these as they are.
_PLAIN = frozenset({float, int, str, bool, type(None)})


def decode(data):
    """Inverse of `encode` (NumPy is imported lazily so the codec costs nothing until arrays appear)."""
    if isinstance(data, list):
        return [v if type(v) in _PLAIN else decode(v) for v in data]
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
        values = data["__ndarray__"]
        if not all(type(v) in _PLAIN for v in values):
            values = [decode(v) for v in values]
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
            # dont_inherit: this file's `from __future__ import annotations` must not turn the submission's
            # annotations into strings (dataclasses of a submission would then fail to build).
            code = compile(statement["source"], f"<{statement['where']}>", "exec", dont_inherit=True)
            exec(code, namespace)
        except BaseException as err:  # noqa: BLE001 - anything a submission raises is reported, not fatal
            record = error_record(err)
            problems.append(f"{statement['where']}: {record['type']}: {record['message']}")
    return problems


def run_case(function, case: dict) -> dict:
    """Call the student's function on one case; report its value (or exception), and the inputs if it changed them."""
    args = decode(case["args"])
    kwargs = decode(case["kwargs"])
    try:
        outcome = {"value": encode(function(*args, **kwargs))}
    except BaseException as err:  # noqa: BLE001 - SystemExit and friends count as failures of this case
        outcome = {"raised": error_record(err)}
    after = encode(list(args))
    if after != case["args"]:
        outcome["args_after"] = after
    return outcome


class Channel:
    """JSON lines to the grader on a file descriptor the submission's prints never touch."""

    def __init__(self, fd: int):
        self.fd = fd
        self.owner = os.getpid()

    def send(self, event: dict) -> None:
        if os.getpid() != self.owner:
            # A process forked by graded code that returned into this loop never reports; it just ends.
            os._exit(0)
        line = json.dumps(event, allow_nan=True)
        if len(line) > MAX_EVENT_BYTES:
            event = {k: v for k, v in event.items() if k not in ("value", "args_after")}
            event["value"] = {"__unsupported__": "a result too large to send back"}
            line = json.dumps(event)
        data = (line + "\n").encode()
        while data:
            written = os.write(self.fd, data)
            data = data[written:]


# --- confinement ---

_LIBC = []
_TYPES = {}


def _libc():
    if not _LIBC:
        import ctypes

        _LIBC.append(ctypes.CDLL(None, use_errno=True))
    return _LIBC[0]


def _types() -> dict:
    """The kernel structures the confinement passes, built once (in the zygote, before it forks)."""
    if not _TYPES:
        import ctypes

        class RulesetAttr(ctypes.Structure):
            _fields_ = [("fs", ctypes.c_uint64), ("net", ctypes.c_uint64), ("scoped", ctypes.c_uint64)]

        class PathBeneath(ctypes.Structure):
            _pack_ = 1
            _fields_ = [("allowed", ctypes.c_uint64), ("parent_fd", ctypes.c_int32)]

        class Instruction(ctypes.Structure):
            _fields_ = [
                ("code", ctypes.c_uint16), ("jt", ctypes.c_uint8), ("jf", ctypes.c_uint8), ("k", ctypes.c_uint32)
            ]

        class Program(ctypes.Structure):
            _fields_ = [("len", ctypes.c_ushort), ("filter", ctypes.POINTER(Instruction))]

        class CapHeader(ctypes.Structure):
            _fields_ = [("version", ctypes.c_uint32), ("pid", ctypes.c_int)]

        class CapData(ctypes.Structure):
            _fields_ = [
                ("effective", ctypes.c_uint32), ("permitted", ctypes.c_uint32), ("inheritable", ctypes.c_uint32)
            ]

        syscall = _libc().syscall
        syscall.restype = ctypes.c_long
        structures = (RulesetAttr, PathBeneath, Instruction, Program, CapHeader, CapData)
        _TYPES.update({cls.__name__: cls for cls in structures})
        _TYPES["syscall"] = syscall
    return _TYPES


# Landlock (Linux >= 5.13) filesystem rights, by the ABI version that introduced them.
_FS_EXECUTE, _FS_WRITE_FILE, _FS_READ_FILE, _FS_READ_DIR = 1 << 0, 1 << 1, 1 << 2, 1 << 3
_FS_RIGHTS_BY_ABI = {1: (1 << 13) - 1, 2: 1 << 13, 3: 1 << 14, 5: 1 << 15}
_SYS_CREATE_RULESET, _SYS_ADD_RULE, _SYS_RESTRICT_SELF = 444, 445, 446  # the same on every architecture
_PR_SET_PDEATHSIG, _PR_SET_NAME, _PR_SET_SECCOMP, _PR_SET_CHILD_SUBREAPER, _PR_SET_NO_NEW_PRIVS = 1, 15, 22, 36, 38


def _landlock(readable: list[str], writable: list[str]) -> tuple[int, str]:
    """Allow reading only beneath `readable`, writing only beneath `writable`; no TCP, no signals out.

    Returns the ABI enforced (0 if none) and a note for the record.
    """
    import ctypes

    types = _types()
    syscall, RulesetAttr, PathBeneath = types["syscall"], types["RulesetAttr"], types["PathBeneath"]
    abi = syscall(_SYS_CREATE_RULESET, None, ctypes.c_size_t(0), ctypes.c_uint32(1))
    if abi < 1:
        return 0, "landlock unavailable"
    fs_rights = sum(bits for version, bits in _FS_RIGHTS_BY_ABI.items() if abi >= version)

    # ABI 4 added TCP bind/connect rights, ABI 6 signal and abstract-socket scoping.
    size = 8 if abi < 4 else 16 if abi < 6 else 24
    attr = RulesetAttr(fs_rights, 0b11 if abi >= 4 else 0, 0b11 if abi >= 6 else 0)
    ruleset = syscall(_SYS_CREATE_RULESET, ctypes.byref(attr), ctypes.c_size_t(size), ctypes.c_uint32(0))
    if ruleset < 0:
        return 0, "landlock refused the ruleset"
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
    _libc().prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)
    if syscall(_SYS_RESTRICT_SELF, ctypes.c_int(ruleset), ctypes.c_uint32(0)) != 0:
        return 0, "landlock could not be enforced"
    os.close(ruleset)
    return int(abi), f"landlock ABI {abi}"


# Seccomp: graded code may start threads but no process (no fork bomb, no daemon, no child outliving it),
# so one address space, bounded by RLIMIT_AS, is all the memory a submission can hold; nor System V or
# POSIX message-queue IPC objects, which would outlive it where no IPC namespace ends with it.
_AUDIT_ARCH = {"x86_64": 0xC000003E, "aarch64": 0xC00000B7}
_REFUSED_SYSCALLS = {
    # fork, vfork; shmget, shmat, shmctl, semget, semop, semctl, shmdt, msgget, msgsnd, msgrcv, msgctl,
    # semtimedop; mq_open
    "x86_64": (57, 58, 29, 30, 31, 64, 65, 66, 67, 68, 69, 70, 71, 220, 240),
    "aarch64": (186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 180),
}
_SYS_CLONE = {"x86_64": 56, "aarch64": 220}
_SYS_CLONE3 = 435
_CLONE_THREAD = 0x00010000


def _no_new_processes() -> bool:
    """Install a seccomp filter refusing new processes (fork, vfork, clone without CLONE_THREAD) and IPC objects.

    Returns True if installed.
    """
    import ctypes

    machine = os.uname().machine
    if machine not in _AUDIT_ARCH:
        return False
    load, equal, at_least, has_bits, give = 0x20, 0x15, 0x35, 0x45, 0x06
    allow, refuse = 0x7FFF0000, 0x00050000 | 1  # SECCOMP_RET_ALLOW, SECCOMP_RET_ERRNO | EPERM
    deny = (give, 0, 0, refuse)
    program = [(load, 0, 0, 4), (equal, 1, 0, _AUDIT_ARCH[machine]), deny, (load, 0, 0, 0)]
    if machine == "x86_64":
        program += [(at_least, 0, 1, 0x40000000), deny]  # the x32 system-call numbers
    for number in _REFUSED_SYSCALLS[machine]:
        program += [(equal, 0, 1, number), deny]
    # clone3 passes its flags in memory a filter cannot read: ENOSYS makes the C library fall back to clone.
    program += [(equal, 0, 1, _SYS_CLONE3), (give, 0, 0, 0x00050000 | 38)]
    program += [(equal, 0, 3, _SYS_CLONE[machine]), (load, 0, 0, 16), (has_bits, 1, 0, _CLONE_THREAD), deny]
    program.append((give, 0, 0, allow))
    Instruction, Program = _types()["Instruction"], _types()["Program"]
    code = (Instruction * len(program))(*(Instruction(*i) for i in program))
    libc = _libc()
    libc.prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)
    return libc.prctl(_PR_SET_SECCOMP, 2, ctypes.byref(Program(len(program), code)), 0, 0) == 0


def _drop_capabilities() -> None:
    """Give up every capability, so a grader running as root cannot lend its powers (e.g. raising limits)."""
    import ctypes

    header, data = _types()["CapHeader"], _types()["CapData"]
    _libc().capset(ctypes.byref(header(0x20080522, 0)), ctypes.byref((data * 2)()))


def _write_sysctl(path: str, value: int) -> bool:
    try:
        with open(path, "w") as handle:
            handle.write(str(value))
        return True
    except OSError:
        return False


# What the keeper set up around this worker, inherited through fork: the namespaces it entered,
# whether it tracks the process tree instead, the user it runs as outside, and whether that is a
# user of its own (the grader's `run_as`: the grader's files are then closed to it by their modes).
_CONTAINMENT = {"namespaces": [], "tracking": False, "uid": None, "own_user": False}


def apply_sandbox(policy: dict) -> dict:
    """Confine this process before any submitted code runs.

    Returns a note of what was applied, whether that counts as confined, and the gaps
    (``files``, ``processes``, ``process_count``, ``ipc``, ``signals``, ``network``) left open.
    """
    import resource

    notes, gaps = [], []
    limits = (("RLIMIT_AS", policy["memory_bytes"]), ("RLIMIT_FSIZE", policy["file_bytes"]), ("RLIMIT_CORE", 0))
    for name, value in limits:
        try:
            resource.setrlimit(getattr(resource, name), (value, value))
        except (AttributeError, ValueError, OSError):
            # Some systems (macOS for the address space) refuse a limit; grade without it, and say so.
            notes.append(f"{name} unavailable")
    if policy.get("trusted"):
        return {"note": "; ".join(["trusted run: limits only"] + notes), "confined": False, "gaps": []}
    if not sys.platform.startswith("linux"):
        notes.append("no confinement on this platform")
        gaps = ["files", "processes", "process_count", "ipc", "signals", "network"]
        return {"note": "; ".join(notes), "confined": False, "gaps": gaps}
    off = set(policy.get("disable", ()))
    spaces = _CONTAINMENT["namespaces"]
    tasks_bounded = False
    if "pid" in spaces:
        # Both need this namespace's capabilities, so before they are dropped; pid_max is per PID
        # namespace since Linux 6.14, and no nested user namespace can hand the capabilities back.
        tasks_bounded = _write_sysctl("/proc/sys/kernel/pid_max", policy["pid_max"])
        _write_sysctl("/proc/sys/user/max_user_namespaces", 0)
        notes.append("+".join(spaces) + " namespaces")
    elif _CONTAINMENT["tracking"]:
        notes.append("process-tree tracking")
    abi = 0
    if "landlock" in off:
        notes.append("landlock disabled")
    else:
        abi, note = _landlock(policy["readable"], [policy["workdir"]])
        notes.append(note)
    if _CONTAINMENT["own_user"]:
        notes.append(f"user {os.getuid()} of its own")
    if abi < 1 and not _closed_by_modes(policy.get("protected", ())):
        gaps.append("files")
    if abi < 6 and "pid" not in spaces:
        gaps.append("signals")
    if abi < 4 and "net" not in spaces:
        gaps.append("network")
    _drop_capabilities()
    forks_refused = "seccomp" not in off and _no_new_processes()
    if forks_refused:
        notes.append("no new processes (seccomp)")
    if tasks_bounded:
        notes.append(f"at most {policy['pid_max'] - 1} tasks (pid_max)")
    if not (forks_refused or "pid" in spaces or _CONTAINMENT["tracking"]):
        gaps.append("processes")
    if not (forks_refused or tasks_bounded):
        # Root's processes are exempt from RLIMIT_NPROC, even inside a user namespace.
        if _CONTAINMENT["uid"] not in (0, None) and _limit_processes(policy["processes"]):
            notes.append(f"at most {policy['processes']} processes (RLIMIT_NPROC)")
        else:
            gaps.append("process_count")
    if not (forks_refused or "ipc" in spaces):
        gaps.append("ipc")
    confined = not {"files", "processes", "process_count", "ipc"} & set(gaps)
    return {"note": "; ".join(notes), "confined": confined, "gaps": gaps}


def _closed_by_modes(protected) -> bool:
    """True when this process runs as a user of its own that can read none of the `protected` folders.

    Without Landlock, file ownership and modes are what keep graded code from the hidden suites,
    the reference and the grader's output: that holds for a separate, unprivileged user only.
    """
    if not _CONTAINMENT["own_user"] or not protected:
        return False
    return not any(os.access(path, os.R_OK) or os.access(path, os.X_OK) for path in protected)


def _limit_processes(count: int) -> bool:
    import resource

    try:
        resource.setrlimit(resource.RLIMIT_NPROC, (count, count))
        return True
    except (ValueError, OSError):
        return False


def serve(request: dict, channel: Channel) -> None:
    """Confine this process, load the submission and run every task of the request, reporting as it goes."""
    os.chdir(request["workdir"])
    os.environ.update(request["environment"])
    tempfile = sys.modules.get("tempfile")
    if tempfile is not None:
        tempfile.tempdir = None  # a forked worker must not reuse the zygote's temporary folder
    sys.path[:] = request["path"]
    # NumPy is imported before the limits so its start-up cost is not the student's,
    # and before any submitted code so the codec uses the real module.
    import numpy  # noqa: F401

    report = apply_sandbox(request["sandbox"])
    # Sent before any submitted code runs, so graded code cannot forge it.
    channel.send({"event": "sandbox", **report})
    if request["sandbox"].get("required") and not report["confined"]:
        return
    if not request.get("allow_reference"):
        sys.meta_path.insert(0, _ReferenceBlocker())
    namespace = {"__name__": "__submission__", "__builtins__": builtins}
    problems = load_submission(request["statements"], namespace)
    channel.send({"event": "loaded", "problems": problems})
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
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except Exception:  # noqa: BLE001 - a submission may have replaced or closed the streams
            pass
    channel.send({"event": "done"})


def _read_all(fd: int) -> bytes:
    chunks = []
    while chunk := os.read(fd, 1 << 20):
        chunks.append(chunk)
    return b"".join(chunks)


def _serve_stdin(channel: Channel) -> None:
    request = json.loads(_read_all(0))
    serve(request, channel)
    # Skip interpreter teardown: a submission's atexit hooks or finalizers must not run after reporting.
    os._exit(0)


# --- the zygote, the keeper and the forked worker (Linux) ---

# Namespaces a keeper tries, most complete first; a network namespace is welcome but not required.
_NAMESPACE_SETS = (("user", "pid", "ipc", "net"), ("user", "pid", "ipc"))
_CLONE_FLAGS = {"user": 0x10000000, "pid": 0x20000000, "ipc": 0x08000000, "net": 0x40000000}
# The worker's descriptors, in this order: its request (stdin), its events, its output (stdout and stderr).
_WORKER_FDS = (0, 3, 1)


def _name_process(name: bytes) -> None:
    _libc().prctl(_PR_SET_NAME, name, 0, 0, 0)


def _die_with(parent: int) -> None:
    """SIGKILL this process when `parent` ends (at once, if it already has)."""
    _libc().prctl(_PR_SET_PDEATHSIG, 9, 0, 0, 0)
    if os.getppid() != parent:
        os._exit(1)


def _renumber(fds: list[int], targets) -> None:
    """Move `fds` onto the descriptor numbers `targets` and close every other descriptor above 2."""
    import fcntl

    high = [fcntl.fcntl(fd, fcntl.F_DUPFD, 64) for fd in fds]
    for fd in set(fds):
        os.close(fd)
    for fd, target in zip(high, targets):
        os.dup2(fd, target)
    os.closerange(max(targets) + 1, os.sysconf("SC_OPEN_MAX"))
    for fd in range(3, max(targets)):
        if fd not in targets:
            try:
                os.close(fd)
            except OSError:
                pass


def zygote(control: int, parent: int) -> None:
    """Fork one keeper per spawn request received on the socket `control`, until it closes."""
    import socket

    _name_process(b"cagd-zygote")
    _die_with(parent)
    config = json.loads(_read_all(0))
    null = os.open(os.devnull, os.O_RDWR)
    os.dup2(null, 0)
    os.close(null)
    sys.path[:] = config["path"]
    import fcntl  # noqa: F401 - imported here, once, for every keeper and worker
    import gc
    import resource  # noqa: F401

    import numpy  # noqa: F401 - the import every worker would otherwise pay for

    _types()
    # Kept out of every worker's garbage collections, which would otherwise touch, and so copy, every page.
    gc.freeze()
    me = os.getpid()
    channel = socket.socket(fileno=control)
    channel.sendall(b"ready")
    keepers: set[int] = set()
    while True:
        message, fds, _, _ = socket.recv_fds(channel, 4096, 4)
        if not message:
            break
        _reap(keepers)
        if len(fds) != 4:
            for fd in fds:
                os.close(fd)
            continue
        try:
            pid = os.fork()
        except OSError as err:
            _tell(fds[3], {"event": "failed", "error": f"fork: {err}"})
            pid = None
        if pid == 0:
            channel.close()
            _keeper(fds, json.loads(message), me)
        if pid:
            keepers.add(pid)
        for fd in fds:
            os.close(fd)
    for pid in keepers:
        try:
            os.kill(pid, 9)
        except ProcessLookupError:
            pass
    while True:
        try:
            os.waitpid(-1, 0)
        except ChildProcessError:
            break
    os._exit(0)


def _reap(keepers: set[int]) -> None:
    while keepers:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            keepers.clear()
            return
        if pid == 0:
            return
        keepers.discard(pid)


def _tell(fd: int, event: dict) -> None:
    try:
        os.write(fd, json.dumps(event).encode())
    except OSError:
        pass


def _keeper(fds: list[int], options: dict, zygote_pid: int) -> None:
    """Contain one worker: new namespaces (or a tracked process tree), fork it, report how it ended."""
    import socket

    _name_process(b"cagd-keeper")
    _die_with(zygote_pid)
    _renumber(fds, (3, 4, 5, 6))
    status = socket.socket(fileno=6)
    if options.get("user"):
        # The grader's run_as: from here on this keeper, and the worker it forks, are that unprivileged user.
        uid, gid = (int(n) for n in options["user"])
        try:
            os.setgroups([])
            os.setresgid(gid, gid, gid)
            os.setresuid(uid, uid, uid)
        except OSError as err:
            status.send(json.dumps({"event": "failed", "error": f"cannot run as user {uid}: {err}"}).encode())
            os._exit(1)
        _CONTAINMENT["own_user"] = True
        _die_with(zygote_pid)  # a change of user clears the parent-death signal
    _CONTAINMENT["uid"] = os.getuid()
    if "namespaces" not in options.get("disable", ()):
        for names in _NAMESPACE_SETS:
            if _libc().unshare(sum(_CLONE_FLAGS[n] for n in names)) == 0:
                _CONTAINMENT["namespaces"] = list(names)
                break
    if not _CONTAINMENT["namespaces"]:
        # Orphans of the worker's tree become this process's children, so none escapes the kill below.
        _CONTAINMENT["tracking"] = _libc().prctl(_PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0
    me = os.getpid()
    try:
        child = os.fork()
    except OSError as err:
        status.send(json.dumps({"event": "failed", "error": f"fork: {err}"}).encode())
        os._exit(1)
    if child == 0:
        status.close()
        # Seen from a new PID namespace, the keeper outside it is parent 0.
        _worker(0 if "pid" in _CONTAINMENT["namespaces"] else me)
    for fd in (3, 4, 5):
        os.close(fd)
    pidfd = os.pidfd_open(child)
    socket.send_fds(status, [json.dumps({"event": "started", "pid": child}).encode()], [pidfd])
    os.close(pidfd)
    _, wait_status = os.waitpid(child, 0)
    if _CONTAINMENT["tracking"]:
        _kill_descendants(me)
    try:
        status.send(json.dumps({"event": "exit", "code": os.waitstatus_to_exitcode(wait_status)}).encode())
    except OSError:
        pass
    os._exit(0)


def _children(pid: int) -> list[int]:
    try:
        with open(f"/proc/{pid}/task/{pid}/children") as handle:
            return [int(p) for p in handle.read().split()]
    except OSError:
        found = []
        for entry in os.listdir("/proc"):
            try:
                with open(f"/proc/{entry}/stat") as handle:
                    if int(handle.read().rsplit(")", 1)[1].split()[1]) == pid:
                        found.append(int(entry))
            except (OSError, ValueError, IndexError):
                continue
        return found


def _kill_descendants(me: int) -> None:
    """Kill every process left in the worker's tree: as a subreaper, each orphan becomes a child of ours."""
    import time

    while True:
        for pid in _children(me):
            try:
                os.kill(pid, 9)
            except ProcessLookupError:
                pass
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            time.sleep(0.001)


def _worker(keeper: int) -> None:
    """The forked worker: the init of its PID namespace, with the request on stdin and events on fd 3."""
    _name_process(b"cagd-worker")
    _die_with(keeper)
    _renumber([3, 4, 5, 5], (0, 3, 1, 2))
    _serve_stdin(Channel(3))


def main(argv: list[str]) -> int:
    if argv[1] == "--zygote":
        zygote(int(argv[2]), int(argv[3]))
    _serve_stdin(Channel(int(argv[1])))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
