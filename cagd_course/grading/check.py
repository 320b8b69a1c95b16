"""`check(exercise_id, function)`: the self-check cell of the exercise notebooks.

It grades exactly as the instructor's grader does (same hidden suite, same
isolated worker process, same comparisons) on the definitions the student has
run so far, and prints one screen saying what passes and what to fix next.
"""

from __future__ import annotations

import inspect

from .engine import grade_statements, load_exercises, prepare
from .extract import extract_source
from .report import check_text
from .runner import Limits

__all__ = ["check", "session_cells"]

# The self-check always draws the same random cases, so a student sees stable results.
CHECK_SEED = 20170725


def session_cells(function=None) -> list[str]:
    """Sources of the code run so far: the notebook's executed cells, or the function's own source."""
    try:
        from IPython import get_ipython
    except ImportError:  # pragma: no cover - IPython ships with Jupyter
        get_ipython = None
    shell = get_ipython() if get_ipython else None
    if shell is not None and shell.user_ns.get("In"):
        return [cell for cell in shell.user_ns["In"] if cell]
    if function is None:
        return []
    # Outside Jupyter, the whole file the function lives in carries its imports and helpers.
    module = inspect.getmodule(function)
    try:
        return [inspect.getsource(module)] if module is not None else [inspect.getsource(function)]
    except (OSError, TypeError):
        raise ValueError(
            f"check: cannot find the source code of {getattr(function, '__name__', function)!r}; "
            "define it in a notebook cell or a .py file"
        ) from None


def check(exercise_id: str, function=None, limits: Limits | None = None) -> None:
    """Run the hidden suite of `exercise_id` on your function in a separate process and print a report.

    `function` is the function you wrote (its name may differ from the exercise's).
    Never raises because of your code: failures, crashes and endless loops are reported.
    """
    exercises = load_exercises(ids=[exercise_id])
    exercise, _ = exercises[exercise_id]
    submission = extract_source(session_cells(function))
    statements = list(submission.statements)
    name = getattr(function, "__name__", exercise.function)
    if function is not None and name != exercise.function:
        statements.append({"source": f"{exercise.function} = {name}", "where": "check()"})
    outcome = grade_statements(statements, prepare(exercises, CHECK_SEED), limits or Limits(exercise_seconds=10))
    print(check_text(outcome.exercises[0], outcome.run.load_problems, submission.skipped))
    if outcome.run.output.strip():
        print("\nYour code printed (first lines):\n" + "\n".join(outcome.run.output.splitlines()[:8]))
