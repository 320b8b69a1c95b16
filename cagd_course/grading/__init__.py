"""Grading students' versions of the reference functions, safely.

`check` is the exercise notebooks' self-check; `cagd validate` and `cagd grade`
(see `cagd_course.cli`) prove the hidden suites and grade a class; `release`
writes what a class's students get, `autograder` a chapter's Gradescope
autograder. Student code only ever runs in the separate worker process of
`runner`; comparisons happen in the grader's process (`engine`).
"""

from .check import check

__all__ = ["check"]
