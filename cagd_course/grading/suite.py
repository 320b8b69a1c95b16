"""What a hidden suite is made of: exercises, cases and the comparisons that grade them.

A hidden suite file (``tests/hidden/chNN.py``) defines ``EXERCISES``, a list of
`Exercise`. Each exercise names the student function, the reference function,
a case generator (fixed cases plus random ones drawn from the seeded generator
it receives) and a comparison. Expected values are computed in the grader's
process from the reference; student results come back as data and are
compared here, never in the student's process.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

__all__ = ["Case", "Exercise", "Mismatch", "Raises", "close", "exact", "expected_value", "same_up_to_scale"]

# Bad input must be rejected with one of these (the contract of cagd_ref).
INPUT_ERRORS = ("ValueError", "TypeError")
# A value off by at most this many times the tolerance is a near miss (precision), not a wrong formula.
NEAR_MISS = 1e4


@dataclass(frozen=True)
class Case:
    """One call of the student's function: positional and keyword arguments, and its category.

    Cases of a `visible` category show their input, the expected and the
    received value in the student's feedback; hidden ones only say pass/fail.
    `rule` is the rule of the exercise's statement the case tests, in the
    statement's words (e.g. "q must not be the zero vector"); the feedback
    shows it when the case fails, visible or not.
    """

    category: str
    args: tuple
    kwargs: dict = field(default_factory=dict)
    visible: bool = False
    rule: str = ""


@dataclass(frozen=True)
class Raises:
    """The expected outcome of a bad-input case: the reference raised `name` (ValueError or TypeError)."""

    name: str
    message: str


Comparison = Callable[[Any, Any], "str | None"]


@dataclass(frozen=True)
class Exercise:
    """One graded exercise: ``id`` is ``NN.function_name`` as listed in book.toml.

    `hint` is shown when values come out wrong (it may speak of the algorithm); `rules` gives the
    statement's rule for every case of a category (``{"bad input": "..."}``) unless a case names
    its own `Case.rule`.
    """

    id: str
    reference: Callable
    cases: Callable[[np.random.Generator], list[Case]]
    compare: Comparison | None = None
    hint: str = ""
    rules: dict[str, str] = field(default_factory=dict, hash=False)

    @property
    def function(self) -> str:
        return self.id.split(".", 1)[1]

    def comparison(self) -> Comparison:
        return self.compare or close()

    def rule_for(self, case: Case) -> str:
        """The statement's rule a case tests, if the suite names one."""
        return case.rule or self.rules.get(case.category, "")


class Mismatch(str):
    """A comparison's message, with the kind of failure it reports (feedback picks its hint by kind).

    Kinds: ``accepted_bad_input``, ``wrong_error``, ``raised``, ``type``, ``shape``, ``nan``,
    ``tolerance`` (close, but not within it), ``value``; the engine adds ``mutation``, ``missing``
    and ``stopped``. A custom comparison may return a plain string: it counts as ``value``.
    """

    kind: str

    def __new__(cls, text: str, kind: str):
        made = super().__new__(cls, text)
        made.kind = kind
        return made


def expected_value(exercise: Exercise, case: Case):
    """The reference's answer to a case, or `Raises` when the reference rejects the input."""
    import copy

    try:
        return exercise.reference(*copy.deepcopy(case.args), **copy.deepcopy(case.kwargs))
    except (ValueError, TypeError) as err:
        return Raises(type(err).__name__, str(err))


def _describe(value) -> str:
    if isinstance(value, np.ndarray):
        return f"an array of shape {value.shape}"
    text = repr(value)
    return f"{type(value).__name__} {text[:80]}"


def close(rtol: float = 1e-9, atol: float = 1e-9) -> Comparison:
    """Numbers, arrays, tuples and strings equal within tolerance; array-likes must have the expected shape."""

    def compare(expected, received) -> str | None:
        return _compare(expected, received, rtol, atol, "")

    # Read by the feedback, which quotes the tolerance a result missed.
    compare.rtol, compare.atol = rtol, atol
    return compare


def exact() -> Comparison:
    """Equality with no tolerance (strings, integers, booleans)."""
    return close(0.0, 0.0)


def _compare(expected, received, rtol, atol, where: str) -> str | None:
    at = f" at {where}" if where else ""
    if isinstance(expected, Raises):
        if isinstance(received, Raises) and received.name in INPUT_ERRORS:
            return None
        if isinstance(received, Raises):
            return Mismatch(
                f"expected a ValueError or TypeError for this bad input, but the function raised {received.name}",
                "wrong_error",
            )
        return Mismatch(
            f"expected a ValueError or TypeError for this bad input, but the function returned {_describe(received)}",
            "accepted_bad_input",
        )
    if isinstance(received, Raises):
        return Mismatch(f"raised {received.name}: {received.message}"[:300], "raised")
    if isinstance(expected, str):
        if expected != received:
            kind = "value" if isinstance(received, str) else "type"
            return Mismatch(f"expected {expected!r}{at}, got {_describe(received)}", kind)
        return None
    if isinstance(expected, tuple):
        if not isinstance(received, (tuple, list)) or len(received) != len(expected):
            return Mismatch(f"expected a tuple of {len(expected)} values{at}, got {_describe(received)}", "type")
        for i, (e, r) in enumerate(zip(expected, received)):
            problem = _compare(e, r, rtol, atol, f"{where}[{i}]")
            if problem:
                return problem
        return None
    return _compare_numbers(np.asarray(expected, dtype=float), received, rtol, atol, at)


def _compare_numbers(expected: np.ndarray, received, rtol, atol, at: str) -> str | None:
    if isinstance(received, (str, bytes)) or received is None:
        wanted = "a number" if expected.ndim == 0 else f"an array of shape {expected.shape}"
        return Mismatch(f"expected {wanted}{at}, got {_describe(received)}", "type")
    try:
        got = np.asarray(received, dtype=float)
    except (TypeError, ValueError):
        return Mismatch(f"expected numbers{at}, got {_describe(received)}", "type")
    if got.shape != expected.shape:
        return Mismatch(f"expected shape {expected.shape}{at}, got shape {got.shape}", "shape")
    # np.allclose(got, expected, rtol, atol, equal_nan=True), without its overhead on small arrays.
    with np.errstate(invalid="ignore", over="ignore"):
        diff = np.abs(got - expected)
        close_enough = (diff <= atol + rtol * np.abs(expected)) | (got == expected)
    if not close_enough.all():
        close_enough |= np.isnan(got) & np.isnan(expected)
    if not close_enough.all():
        if np.isnan(got).any() and not np.isnan(expected).any():
            return Mismatch(f"got NaN{at} where a number was expected", "nan")
        badness = np.where(close_enough, -1.0, np.where(np.isnan(diff), np.inf, diff))
        worst = np.unravel_index(int(np.argmax(badness)), diff.shape)
        index = f" (entry {tuple(int(i) for i in worst)})" if expected.ndim else ""
        wanted, off = float(expected[worst]), float(diff[worst])
        allowed = atol + rtol * abs(wanted)
        if 0 < allowed < math.inf and off <= NEAR_MISS * allowed:
            return Mismatch(
                f"value{at}{index} outside the tolerance: expected {_short(wanted)}, got {_short(got[worst])} "
                f"(off by {off:.2g}, allowed {allowed:.2g})",
                "tolerance",
            )
        return Mismatch(f"wrong value{at}{index}: expected {_short(wanted)}, got {_short(got[worst])}", "value")
    return None


def _short(x) -> str:
    x = float(x)
    return repr(x) if math.isfinite(x) else str(x)


def _unit(v) -> np.ndarray:
    v = np.asarray(v, dtype=float).ravel()
    return v / np.linalg.norm(v)


def same_up_to_scale(tol: float):
    """Arrays of the expected shape equal up to one nonzero factor: their unit vectors agree up to sign within tol."""

    def compare(expected, received) -> str | None:
        if isinstance(expected, Raises):
            return close()(expected, received)
        try:
            got = np.asarray(received, dtype=float)
        except (TypeError, ValueError):
            return f"expected an array of shape {np.shape(expected)}, got {type(received).__name__}"
        if got.shape != np.shape(expected):
            return f"expected shape {np.shape(expected)}, got shape {got.shape}"
        if not np.all(np.isfinite(got)):
            return "got NaN or infinity"
        if not np.any(got):
            return "got all zeros, which is no answer (defined up to a nonzero factor)"
        a, b = _unit(expected), _unit(got)
        off = min(np.abs(a - b).max(), np.abs(a + b).max())
        if off > tol:
            worst = int(np.argmax(np.abs(a - np.sign(a @ b) * b)))
            index = np.unravel_index(worst, np.shape(expected))
            return (f"not a multiple of the expected answer: after scaling both to unit length, entry "
                    f"{tuple(int(i) for i in index)} is {float(np.sign(a @ b) * b[worst]):.6g}, expected "
                    f"{float(a[worst]):.6g}")
        return None

    return compare
