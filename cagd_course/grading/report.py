"""How results are told: the one-screen self-check text, the student's HTML feedback, Gradescope JSON."""

from __future__ import annotations

import html

import numpy as np

from .engine import CaseResult, ExerciseResult
from .suite import Raises

__all__ = ["exercise_summary", "check_text", "failure_hint", "feedback_html", "gradescope_results", "status_of"]


def _format_value(value, limit: int = 400) -> str:
    if isinstance(value, Raises):
        return f"raises {value.name}"
    if isinstance(value, np.ndarray):
        with np.printoptions(precision=6, suppress=True, threshold=40):
            text = repr(value)
    else:
        text = repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _format_call(function: str, result: CaseResult) -> str:
    case = result.case
    parts = [_format_value(a, 200) for a in case.args]
    parts += [f"{k}={_format_value(v, 200)}" for k, v in case.kwargs.items()]
    return f"{function}({', '.join(parts)})"


def exercise_summary(result: ExerciseResult) -> list[tuple[str, int, int, CaseResult | None]]:
    """Per category: name, cases passed, cases in all, and the first failing case (None if all pass)."""
    rows = []
    for category, cases in result.categories().items():
        failing = next((c for c in cases if not c.passed), None)
        rows.append((category, sum(c.passed for c in cases), len(cases), failing))
    return rows


def _format_expected(value) -> str:
    if isinstance(value, Raises):
        # A visible case: the reference's own message names the argument and the rule it breaks.
        return f"a ValueError or TypeError (the reference raises {value.name}: {_format_value(value.message, 200)})"
    return _format_value(value)


def _failure_detail(result: ExerciseResult, failing: CaseResult) -> list[str]:
    lines = [f"      {failing.message}"]
    if failing.visible and failing.case is not None:
        function = result.id.split(".", 1)[1]
        lines.append(f"      call:     {_format_call(function, failing)}")
        lines.append(f"      expected: {_format_expected(failing.expected)}")
        if failing.received is not None:
            lines.append(f"      received: {_format_value(failing.received)}")
    if failing.rule:
        lines.append(f"      rule:     {failing.rule}")
    return lines


# Errors graded code meets when it tries what the sandbox forbids (a process, a file outside its folder, a socket).
_REFUSED = ("PermissionError", "BlockingIOError", "OSError")

# What to look at, by kind of failure (see `suite.Mismatch`). Only wrong values get the exercise's own
# hint, which may speak of the algorithm: the other failures have nothing to do with it.
_HINTS = {
    "accepted_bad_input": (
        "This input breaks a rule of the statement{rule}: check the inputs before computing and raise a "
        "ValueError (or TypeError) whose message starts with the argument's name."
    ),
    "wrong_error": (
        "The function failed with {error} on an input it must reject{rule}: test the input first and raise a "
        "ValueError (or TypeError) naming the argument, before the computation trips over it."
    ),
    "refused": (
        "The function was refused something graded code may not do ({error}): it runs confined, without "
        "starting processes, writing outside its own folder or using the network. Compute the result directly."
    ),
    "raised": (
        "The function raised an error on an input it must accept{rule}: re-read which inputs the statement "
        "allows (a number or an array, lists as well as arrays, edge values such as t = 0 and t = 1)."
    ),
    "type": (
        "Return the kind of value the statement asks for (a number, an array, a tuple); a function that ends "
        "without `return` gives None."
    ),
    "shape": (
        "Check the shape of what you return against the statement: it says which shape each kind of input gives "
        "(one parameter or an array of them, one point or several)."
    ),
    "nan": (
        "Your result holds NaN where a number belongs: look for 0/0, a division by a length, a weight or a "
        "difference that is zero for this input."
    ),
    "tolerance": (
        "Your values are close but outside the tolerance{tolerance}: look for lost precision, such as a rounded "
        "constant, float32, a fixed number of iterations, or subtracting nearly equal numbers."
    ),
    "mutation": (
        "Work on a copy of the input: np.array(x, dtype=float) copies, while np.asarray(x) and slices share memory "
        "with the caller's array."
    ),
    "missing": "Define a function named {function} at the top level of a code cell.",
}


def failure_hint(result: ExerciseResult, failing: CaseResult) -> str:
    """What to look at for this failure: validation, types, shapes, precision, copies, or the algorithm."""
    error = failing.received.name if isinstance(failing.received, Raises) else "an error"
    kind = "refused" if failing.kind == "raised" and error in _REFUSED else failing.kind
    if kind not in _HINTS:
        return result.hint or "Work the visible example by hand and compare your intermediate values with it."
    tolerance = f" (rtol {result.tolerance[0]:g}, atol {result.tolerance[1]:g})" if result.tolerance else ""
    return _HINTS[kind].format(
        rule=f" ({failing.rule})" if failing.rule else "",
        error=error,
        tolerance=tolerance,
        function=result.id.split(".", 1)[1],
    )


def check_text(result: ExerciseResult, load_problems: list[str] = (), skipped: list[str] = ()) -> str:
    """The self-check report of one exercise: what passes, what fails, and what to fix next."""
    rows = exercise_summary(result)
    passed_groups = sum(1 for _, ok, total, _ in rows if ok == total)
    lines = [
        f"{result.id}: {result.score:g} / {result.points:g} points "
        f"({passed_groups} of {len(rows)} groups of cases pass)"
    ]
    for category, ok, total, failing in rows:
        mark = "PASS" if ok == total else "FAIL"
        lines.append(f"  [{mark}] {category}: {ok}/{total}")
        if failing is not None and failing is _first_failure(rows):
            lines.extend(_failure_detail(result, failing))
    lines.extend(f"  note: {p}" for p in list(load_problems) + list(skipped))
    lines.append("")
    lines.append(_next_step(result, rows))
    return "\n".join(lines)


def _first_failure(rows) -> CaseResult | None:
    return next((failing for *_, failing in rows if failing is not None), None)


def _next_step(result: ExerciseResult, rows) -> str:
    failing = _first_failure(rows)
    if failing is None:
        return "All cases pass. Well done!"
    if all(not c.passed and "NotImplementedError" in c.message for c in result.cases):
        return (
            "Not written yet: replace `raise NotImplementedError` in the function above, run that cell, "
            "then run this check again."
        )
    if result.stopped:
        return f"Next: {result.stopped}. Look for a loop that never ends or a very slow step."
    return f'Next: fix the first failing group, "{failing.category}".\nHint: {failure_hint(result, failing)}'


def status_of(results: list[ExerciseResult], problems: list[str]) -> str:
    """One plain phrase for the gradebook: 'ok' or what went wrong, exercise by exercise."""
    parts = []
    for result in results:
        if result.stopped:
            parts.append(f"{result.id}: {result.stopped}")
        elif any(c.message.startswith("raised MemoryError") for c in result.cases):
            parts.append(f"{result.id}: memory limit exceeded")
        elif any(c.message.startswith("raised SystemExit") for c in result.cases):
            parts.append(f"{result.id}: called sys.exit")
    parts.extend(problems)
    return "; ".join(parts) if parts else "ok"


def feedback_html(name: str, results: list[ExerciseResult], score: float, max_score: float, notes: list[str]) -> str:
    """A self-contained HTML page telling a student how each exercise went."""
    esc = html.escape
    body = [
        f"<h1>Feedback for {esc(name)}</h1>",
        f"<p class='total'>Score: <b>{score:g}</b> / {max_score:g}</p>",
    ]
    if notes:
        body.append("<h2>Notes</h2><ul>" + "".join(f"<li>{esc(n)}</li>" for n in notes) + "</ul>")
    for result in results:
        body.append(f"<h2>{esc(result.id)} &mdash; {result.score:g} / {result.points:g}</h2>")
        if result.stopped:
            body.append(f"<p class='stopped'>{esc(result.stopped)}</p>")
        body.append("<table><tr><th>cases</th><th>passed</th><th>first failure</th></tr>")
        for category, ok, total, failing in exercise_summary(result):
            detail = (
                "" if failing is None else "<pre>" + esc("\n".join(_failure_detail(result, failing)).strip()) + "</pre>"
            )
            css = "pass" if ok == total else "fail"
            body.append(f"<tr class='{css}'><td>{esc(category)}</td><td>{ok}/{total}</td><td>{detail}</td></tr>")
        body.append("</table>")
        failing = _first_failure(exercise_summary(result))
        if failing is not None and not result.stopped:
            body.append(f"<p class='hint'>Hint: {esc(failure_hint(result, failing))}</p>")
    style = (
        "body{font-family:system-ui,sans-serif;max-width:60rem;margin:2rem auto;line-height:1.4}"
        "table{border-collapse:collapse;width:100%}td,th{border:1px solid #ccc;padding:.3rem;vertical-align:top}"
        "tr.pass td:nth-child(2){color:#1a7f37}tr.fail td:nth-child(2){color:#c0392b}"
        "pre{white-space:pre-wrap;margin:0}.hint{color:#555}.stopped{color:#c0392b}"
    )
    return (
        "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>"
        f"<title>Feedback: {esc(name)}</title><style>{style}</style></head><body>"
        + "\n".join(body)
        + "</body></html>\n"
    )


# Gradescope's visibilities of a test (its autograder specification).
VISIBILITIES = ("visible", "hidden", "after_due_date", "after_published")


def _hidden_category(cases: list[CaseResult]) -> bool:
    """A group of cases none of which is visible: its name is known, its inputs never shown."""
    return not any(c.visible for c in cases)


def _gradescope_split(results: list[ExerciseResult], score: float, notes: list[str], hidden: str) -> dict:
    """One test per exercise, holding its score and its visible groups; one test per hidden group, shown `hidden`."""
    tests = []
    for result in results:
        groups = result.categories()
        rows = [row for row in exercise_summary(result) if not _hidden_category(groups[row[0]])]
        hidden_rows = [row for row in exercise_summary(result) if _hidden_category(groups[row[0]])]
        lines = []
        for category, ok, total, failing in rows:
            lines.append(f"{category}: {ok}/{total}")
            if failing is not None:
                lines.extend("    " + line.strip() for line in _failure_detail(result, failing))
        if result.stopped:
            lines.append(result.stopped)
        failing = _first_failure(rows)
        if failing is not None and not result.stopped:
            lines.append(f"Hint: {failure_hint(result, failing)}")
        if hidden_rows:
            lines.append(f"Hidden groups ({', '.join(row[0] for row in hidden_rows)}): their results are shown "
                         "when grades are published; the score above counts them.")
        tests.append({
            "name": result.id,
            "score": result.score,
            "max_score": result.points,
            "status": "passed" if result.score >= result.points else "failed",
            "output": "\n".join(lines),
            "visibility": "visible",
        })
        for category, ok, total, failing in hidden_rows:
            lines = [f"{ok}/{total} cases pass"]
            if failing is not None:
                lines.extend(line.strip() for line in _failure_detail(result, failing))
                if not result.stopped:
                    lines.append(f"Hint: {failure_hint(result, failing)}")
            tests.append({
                "name": f"{result.id}: hidden group \"{category}\"",
                "status": "passed" if ok == total else "failed",
                "output": "\n".join(lines),
                "visibility": hidden,
            })
    return {"score": score, "output": "\n".join(notes), "tests": tests}


def gradescope_results(
    results: list[ExerciseResult], score: float, notes: list[str], hidden_visibility: str | None = None
) -> dict:
    """The Gradescope autograder `results.json` structure: one test per exercise.

    With `hidden_visibility` (one of `VISIBILITIES`, e.g. "after_published") the groups of hidden
    cases become tests of their own with that visibility, each with its first failure as the
    feedback page tells it (never the inputs); the exercise's test keeps its score and shows the
    visible groups, each with its first failure. Without it, every group is told in the exercise's test.
    """
    if hidden_visibility is not None:
        if hidden_visibility not in VISIBILITIES:
            raise ValueError(f"hidden_visibility: one of {VISIBILITIES}, not {hidden_visibility!r}")
        return _gradescope_split(results, score, notes, hidden_visibility)
    tests = []
    for result in results:
        lines = [f"{category}: {ok}/{total}" for category, ok, total, _ in exercise_summary(result)]
        if result.stopped:
            lines.append(result.stopped)
        failing = _first_failure(exercise_summary(result))
        if failing is not None:
            lines.extend(line.strip() for line in _failure_detail(result, failing))
            if not result.stopped:
                lines.append(f"Hint: {failure_hint(result, failing)}")
        tests.append(
            {
                "name": result.id,
                "score": result.score,
                "max_score": result.points,
                "output": "\n".join(lines),
                "visibility": "visible",
            }
        )
    return {"score": score, "output": "\n".join(notes), "tests": tests}
