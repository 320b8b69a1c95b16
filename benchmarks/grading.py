"""Grading throughput: `cagd grade` on a class of mixed submissions, with one and two jobs.

The class cycles through four kinds of notebook — a correct solution of
chapters 1-2, a partly wrong one, the untouched stub and one whose
`de_casteljau` never returns — and is graded with the command line's code
path (`grade_class`). Results go to `benchmarks/results/grading.md`.

    .venv/bin/python benchmarks/grading.py            # 300 submissions, as in the issue
    .venv/bin/python benchmarks/grading.py --copies 40
"""

from __future__ import annotations

import argparse
import platform
import shutil
import tempfile
import time
from pathlib import Path

from cagd_course.grading.classroom import grade_class, read_gradebook
from cagd_course.grading.runner import Limits

ROOT = Path(__file__).resolve().parent.parent
SOLUTION = ROOT / "tests" / "grading" / "fixtures" / "submissions" / "complete.ipynb"
STUB = ROOT / "exercises" / "02-bezier-curves.ipynb"
RESULTS = Path(__file__).parent / "results" / "grading.md"


def make_class(folder: Path, copies: int) -> None:
    """Write `copies` notebooks cycling through correct, partly wrong, stub and looping."""
    solution = SOLUTION.read_text()
    kinds = {
        "correct": solution,
        "partly_wrong": solution.replace(
            "(1 - t) * levels[-1][:-1] + t * levels[-1][1:]", "t * levels[-1][:-1] + (1 - t) * levels[-1][1:]"
        ),
        "stub": STUB.read_text(),
        "looping": solution.replace(
            "def de_casteljau(points, t):\\n", "def de_casteljau(points, t):\\n    while True:\\n        pass\\n", 1
        ),
    }
    assert kinds["partly_wrong"] != solution and kinds["looping"] != solution
    names = list(kinds)
    for i in range(copies):
        kind = names[i % len(names)]
        (folder / f"{kind}_{i:04d}.ipynb").write_text(kinds[kind])


def time_grading(folder: Path, jobs: int, limits: Limits) -> tuple[float, dict]:
    out = Path(tempfile.mkdtemp(prefix=f"cagd-bench-{jobs}-"))
    started = time.perf_counter()
    grade_class([folder], out, jobs=jobs, limits=limits, progress=True, chapters=[1, 2])
    seconds = time.perf_counter() - started
    rows = read_gradebook(out / "gradebook.csv")
    shutil.rmtree(out)
    return seconds, rows


def one_correct_submission(limits: Limits) -> float:
    folder = Path(tempfile.mkdtemp(prefix="cagd-bench-one-"))
    shutil.copy(SOLUTION, folder / "correct.ipynb")
    seconds, rows = time_grading(folder, 1, limits)
    assert rows["correct"][1] == rows["correct"][2], "the reference solution must get full marks"
    shutil.rmtree(folder)
    return seconds


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--copies", type=int, default=300, help="submissions in the class (default 300)")
    parser.add_argument("--timeout", type=float, default=2.0, help="per-exercise time limit in seconds (default 2)")
    args = parser.parse_args()
    limits = Limits(exercise_seconds=args.timeout, submission_seconds=60)
    single = one_correct_submission(limits)
    folder = Path(tempfile.mkdtemp(prefix="cagd-bench-class-"))
    make_class(folder, args.copies)
    lines = [
        "# Grading throughput",
        "",
        f"Machine: {platform.machine()}, Python {platform.python_version()}; per-exercise limit {args.timeout:g} s.",
        f"Class: {args.copies} notebooks cycling correct / partly wrong / stub / endless loop in `de_casteljau`;",
        "every notebook graded on the 15 exercises of chapters 1-2 (`--chapter 1 --chapter 2`).",
        "Command: `.venv/bin/python benchmarks/grading.py"
        + (f" --copies {args.copies}" if args.copies != 300 else "")
        + "`",
        "",
        f"One correct submission of chapters 1-2, graded alone: **{single:.2f} s** (target: under 5 s).",
        "",
        "| jobs | seconds | submissions per second | rows in gradebook |",
        "|---:|---:|---:|---:|",
    ]
    for jobs in (1, 2):
        seconds, rows = time_grading(folder, jobs, limits)
        lines.append(f"| {jobs} | {seconds:.1f} | {args.copies / seconds:.2f} | {len(rows)} |")
    shutil.rmtree(folder)
    RESULTS.parent.mkdir(exist_ok=True)
    RESULTS.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
