"""`check(exercise_id, function)` of a class release: the visible cases, their answers shipped as data.

`cagd release` copies this file into the release as ``cagd_course/check.py``, next to
``_support.py`` (the grader's value codec and comparisons), ``_checks/chNN.py`` (each chapter's
comparisons) and ``cases/chNN.json`` (the visible cases with the expected answers). It needs
nothing but the standard library and NumPy: no reference implementation and no hidden suite is
in the release. The hidden groups of cases are named and reported as checked at grading time.
Here the function runs in the notebook's own process, stopped after `SECONDS` where the
platform allows (SIGALRM); the grader runs it confined, in a separate process, on every case.

In the course itself this module is only a template: it is never imported there.
"""

from __future__ import annotations

import importlib
import inspect
import json
import signal
import threading
from pathlib import Path

__all__ = ["check", "SECONDS"]

HERE = Path(__file__).resolve().parent
SECONDS = 10.0
LATER = "checked when your work is graded"


class _TimeUp(BaseException):
    """Raised in the checked function when its time is up (a BaseException: `except Exception` keeps it)."""


def _support():
    return importlib.import_module(f"{__package__}._support")


def _load(exercise_id: str):
    chapter, _, _ = str(exercise_id).partition(".")
    path = HERE / "cases" / f"ch{chapter}.json"
    data = json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {"exercises": {}}
    if exercise_id not in data["exercises"]:
        known = sorted(data["exercises"]) or "none of this chapter's"
        raise KeyError(f"check: unknown exercise {exercise_id!r} (this release checks {known})")
    compare = importlib.import_module(f"{__package__}._checks.ch{chapter}").COMPARE.get(exercise_id)
    return data["exercises"][exercise_id], compare, data.get("hints", {})


def _expected(data):
    S = _support()
    if isinstance(data, dict) and "__raises__" in data:
        return S.Raises(*data["__raises__"])
    if isinstance(data, dict) and "__number__" in data:
        number = _Number(data["__number__"])
        for key, value in data.get("attrs", {}).items():
            setattr(number, key, S.decode(value))
        return number
    return S.decode(data)


class _Number(float):
    """A float with the attributes the reference's answer carried (an area with its error bound, say)."""


def _builtin_name(err: BaseException) -> str:
    for cls in type(err).__mro__:
        if cls.__module__ == "builtins":
            return cls.__name__
    return type(err).__name__


def _format(value, limit: int = 400) -> str:
    import numpy as np

    S = _support()
    if isinstance(value, S.Raises):
        return f"raises {value.name}"
    if isinstance(value, np.ndarray):
        with np.printoptions(precision=6, suppress=True, threshold=40):
            text = repr(value)
    else:
        text = repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


class _Timer:
    """Interrupt the checked function after `seconds` (main thread, platforms with SIGALRM); else no limit."""

    def __init__(self, seconds: float):
        self.seconds = seconds
        self.active = hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()

    def __enter__(self):
        if self.active:
            self.previous = signal.signal(signal.SIGALRM, self._ring)
            signal.setitimer(signal.ITIMER_REAL, self.seconds)
        return self

    def _ring(self, *_):
        raise _TimeUp()

    def __exit__(self, *exc):
        if self.active:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, self.previous)
        return False


def _run(function, case: dict, compare, seconds: float):
    """(passed, message, kind, received) of one case; raises _TimeUp when the time limit runs out."""
    S = _support()
    args, kwargs = S.decode(case["args"]), S.decode(case["kwargs"])
    expected = _expected(case["expected"])
    try:
        with _Timer(seconds):
            value = function(*args, **kwargs)
        received = S.decode(S.encode(value))  # what the grader receives from its worker
    except _TimeUp:
        raise
    except Exception as err:  # noqa: BLE001 - every error of the checked code is reported, as the grader does
        try:
            message = str(err)[:500]
        except Exception:  # noqa: BLE001
            message = "(message could not be shown)"
        received = S.Raises(_builtin_name(err), message)
    problem = compare(expected, received)
    if problem is None and S.encode(list(args)) != case["args"]:
        problem = S.Mismatch("the function changed one of its arguments in place (inputs must be left unchanged)",
                             "mutation")
    kind = getattr(problem, "kind", "value") if problem else ""
    return problem is None, str(problem or ""), kind, received, expected


def _hint(kind: str, received, exercise: dict, hints: dict, rule: str, function: str) -> str:
    S = _support()
    error = received.name if isinstance(received, S.Raises) else "an error"
    if kind == "raised" and error in ("PermissionError", "BlockingIOError", "OSError"):
        kind = "refused"
    text = hints.get(kind)
    if text is None:
        return exercise.get("hint") or "Work the visible example by hand and compare your intermediate values with it."
    tolerance = exercise.get("tolerance")
    return text.format(
        rule=f" ({rule})" if rule else "",
        error=error,
        tolerance=f" (rtol {tolerance[0]:g}, atol {tolerance[1]:g})" if tolerance else "",
        function=function,
    )


def _call(function_name: str, case: dict) -> str:
    S = _support()
    parts = [_format(a, 200) for a in S.decode(case["args"])]
    parts += [f"{k}={_format(v, 200)}" for k, v in S.decode(case["kwargs"]).items()]
    return f"{function_name}({', '.join(parts)})"


def _caller_function(name: str):
    frame = inspect.currentframe()
    try:
        caller = frame.f_back.f_back
        return caller.f_globals.get(name) if caller is not None else None
    finally:
        del frame


def check(exercise_id: str, function=None, seconds: float = SECONDS) -> None:
    """Run the visible cases of `exercise_id` on your function and print what passes and what to fix next.

    `function` is the function (or class) you wrote; its name may differ from the exercise's. The
    hidden groups of cases are run only when your work is graded. Never raises because of your code.
    """
    exercise, compare, hints = _load(exercise_id)
    name = exercise["function"]
    if function is None:
        function = _caller_function(name)
    if not callable(function):
        print(f"{exercise_id}: define a function named {name} in a code cell and run it, then run this check again.")
        return
    groups: dict[str, list] = {}
    stopped = ""
    first = None
    for case in exercise["cases"] if compare is not None else []:
        try:
            passed, message, kind, received, expected = _run(function, case, compare, seconds)
        except _TimeUp:
            stopped = f"timed out after {seconds:g} s on a case of \"{case['category']}\""
            groups.setdefault(case["category"], []).append(False)
            break
        groups.setdefault(case["category"], []).append(passed)
        if not passed and first is None:
            first = (case, message, kind, received, expected)
    hidden = [
        (c, info["cases"]) for c, info in exercise["categories"].items() if not info["visible"] or compare is None
    ]
    total = sum(len(v) for v in groups.values())
    ok = sum(sum(v) for v in groups.values())
    lines = [f"{exercise_id}: {ok} of {total} visible cases pass ({exercise['points']:g} point(s) when graded)"]
    for category, results in groups.items():
        mark = "PASS" if all(results) else "FAIL"
        lines.append(f"  [{mark}] {category}: {sum(results)}/{len(results)}")
        if first is not None and first[0]["category"] == category and not all(results):
            case, message, kind, received, expected = first
            lines.append(f"      {message}")
            lines.append(f"      call:     {_call(name, case)}")
            shown = expected
            if isinstance(shown, _support().Raises):
                lines.append(f"      expected: a ValueError or TypeError (the reference raises {shown.name}: "
                             f"{_format(shown.message, 200)})")
            else:
                lines.append(f"      expected: {_format(shown)}")
            lines.append(f"      received: {_format(received)}")
            if case.get("rule"):
                lines.append(f"      rule:     {case['rule']}")
    for category, count in hidden:
        lines.append(f"  [hidden] {category}: {count} case(s), {LATER}")
    lines.append("")
    if stopped:
        lines.append(f"Next: {stopped}. Look for a loop that never ends or a very slow step.")
    elif first is None:
        lines.append("All visible cases pass." + (f" The hidden groups are {LATER}." if hidden else ""))
    elif all(not any(g) for g in groups.values()) and "NotImplementedError" in first[1]:
        lines.append("Not written yet: replace `raise NotImplementedError` in the function above, run that cell, "
                     "then run this check again.")
    else:
        case, message, kind, received, _ = first
        lines.append(f'Next: fix the first failing group, "{case["category"]}".')
        lines.append(f"Hint: {_hint(kind, received, exercise, hints, case.get('rule', ''), name)}")
    print("\n".join(lines))
