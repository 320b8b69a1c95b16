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

__all__ = ["Case", "Exercise", "Raises", "close", "exact", "expected_value"]

# Bad input must be rejected with one of these (the contract of cagd_ref).
INPUT_ERRORS = ("ValueError", "TypeError")


@dataclass(frozen=True)
class Case:
    """One call of the student's function: positional and keyword arguments, and its category.

    Cases of a `visible` category show their input, the expected and the
    received value in the student's feedback; hidden ones only say pass/fail.
    """

    category: str
    args: tuple
    kwargs: dict = field(default_factory=dict)
    visible: bool = False


@dataclass(frozen=True)
class Raises:
    """The expected outcome of a bad-input case: the reference raised `name` (ValueError or TypeError)."""

    name: str
    message: str


Comparison = Callable[[Any, Any], "str | None"]


@dataclass(frozen=True)
class Exercise:
    """One graded exercise: ``id`` is ``NN.function_name`` as listed in book.toml."""

    id: str
    reference: Callable
    cases: Callable[[np.random.Generator], list[Case]]
    compare: Comparison | None = None
    hint: str = ""

    @property
    def function(self) -> str:
        return self.id.split(".", 1)[1]

    def comparison(self) -> Comparison:
        return self.compare or close()


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

    return compare


def exact() -> Comparison:
    """Equality with no tolerance (strings, integers, booleans)."""
    return close(0.0, 0.0)


def _compare(expected, received, rtol, atol, where: str) -> str | None:
    at = f" at {where}" if where else ""
    if isinstance(expected, Raises):
        if isinstance(received, Raises) and received.name in INPUT_ERRORS:
            return None
        got = f"raised {received.name}" if isinstance(received, Raises) else f"returned {_describe(received)}"
        return f"expected a ValueError or TypeError for this bad input, but the function {got}"
    if isinstance(received, Raises):
        return f"raised {received.name}: {received.message}"[:300]
    if isinstance(expected, str):
        if expected != received:
            return f"expected {expected!r}{at}, got {_describe(received)}"
        return None
    if isinstance(expected, tuple):
        if not isinstance(received, (tuple, list)) or len(received) != len(expected):
            return f"expected a tuple of {len(expected)} values{at}, got {_describe(received)}"
        for i, (e, r) in enumerate(zip(expected, received)):
            problem = _compare(e, r, rtol, atol, f"{where}[{i}]")
            if problem:
                return problem
        return None
    return _compare_numbers(np.asarray(expected, dtype=float), received, rtol, atol, at)


def _compare_numbers(expected: np.ndarray, received, rtol, atol, at: str) -> str | None:
    if isinstance(received, (str, bytes)) or received is None:
        wanted = "a number" if expected.ndim == 0 else f"an array of shape {expected.shape}"
        return f"expected {wanted}{at}, got {_describe(received)}"
    try:
        got = np.asarray(received, dtype=float)
    except (TypeError, ValueError):
        return f"expected numbers{at}, got {_describe(received)}"
    if got.shape != expected.shape:
        return f"expected shape {expected.shape}{at}, got shape {got.shape}"
    if np.isnan(got).any() and not np.isnan(expected).any():
        return f"got NaN{at} where a number was expected"
    if not np.allclose(got, expected, rtol=rtol, atol=atol, equal_nan=True):
        diff = np.abs(got - expected)
        worst = np.unravel_index(int(np.nanargmax(np.where(np.isnan(diff), np.inf, diff))), diff.shape)
        index = f" (entry {tuple(int(i) for i in worst)})" if expected.ndim else ""
        return f"wrong value{at}{index}: expected {_short(expected[worst])}, got {_short(got[worst])}"
    return None


def _short(x) -> str:
    x = float(x)
    return repr(x) if math.isfinite(x) else str(x)
