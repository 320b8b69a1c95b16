"""Grading throughput: `cagd grade` on a class of correct submissions, and on a mixed class, against targets.

Two runs, both through the command line's code path (`grade_class`):

* throughput: `--copies` correct submissions of one chapter (`--chapter`: chapters 1 and 2, the second
  with twice the cases) with two jobs; target: 300 of them in under 10 s on 2 cores.
* mixed: `--copies` notebooks cycling through a correct solution of chapters 1-2, a partly wrong one,
  the untouched stub and one whose `de_casteljau` never returns (three exercises call it, so each such
  notebook must spend three per-exercise timeouts). Its floor is the time those timeouts take: their
  number (read from the gradebook) times the limit, divided by the jobs. Target: within 1.1x the floor.

Results go to `benchmarks/results/grading.md`, with the CPU time the run took (grader and workers) and
the machine's load when it started: on a shared machine other work competes for the same cores.

    .venv/bin/python benchmarks/grading.py                # 300 submissions per run, as in the targets
    .venv/bin/python benchmarks/grading.py --copies 40 --jobs 2
"""

from __future__ import annotations

import argparse
import os
import platform
import shutil
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from cagd_course.grading.classroom import grade_class, read_gradebook
from cagd_course.grading.runner import Limits

ROOT = Path(__file__).resolve().parent.parent
SOLUTION = ROOT / "tests" / "grading" / "fixtures" / "submissions" / "complete.ipynb"
STUB = ROOT / "exercises" / "02-bezier-curves.ipynb"
RESULTS = Path(__file__).parent / "results" / "grading.md"
THROUGHPUT_TARGET = 10.0  # seconds for 300 correct single-chapter submissions with two jobs
THROUGHPUT_COPIES = 300
FLOOR_TARGET = 1.1  # a mixed batch may take at most this multiple of its timeout floor


def make_class(folder: Path, copies: int, kinds: tuple[str, ...]) -> None:
    """Write `copies` notebooks cycling through `kinds` (correct, partly wrong, stub, looping)."""
    solution = SOLUTION.read_text()
    texts = {
        "correct": solution,
        "partly_wrong": solution.replace(
            "(1 - t) * levels[-1][:-1] + t * levels[-1][1:]", "t * levels[-1][:-1] + (1 - t) * levels[-1][1:]"
        ),
        "stub": STUB.read_text(),
        "looping": solution.replace(
            "def de_casteljau(points, t):\\n", "def de_casteljau(points, t):\\n    while True:\\n        pass\\n", 1
        ),
    }
    assert texts["partly_wrong"] != solution and texts["looping"] != solution
    for i in range(copies):
        kind = kinds[i % len(kinds)]
        (folder / f"{kind}_{i:04d}.ipynb").write_text(texts[kind])


@dataclass
class Timing:
    seconds: float
    cpu: float
    rows: dict
    confinement: str


def time_grading(folder: Path, jobs: int, limits: Limits, chapters: list[int]) -> Timing:
    out = Path(tempfile.mkdtemp(prefix=f"cagd-bench-{jobs}-"))
    before = os.times()
    started = time.perf_counter()
    summary = grade_class([folder], out, jobs=jobs, limits=limits, progress=True, chapters=chapters)
    seconds = time.perf_counter() - started
    after = os.times()
    cpu = sum(after[:4]) - sum(before[:4])  # this process and every process it waited for
    rows = read_gradebook(out / "gradebook.csv")
    shutil.rmtree(out)
    return Timing(seconds, cpu, rows, summary.confinement)


def timeouts_spent(rows: dict) -> int:
    """How many per-exercise timeouts the gradebook's statuses record."""
    return sum(row[3].count("timed out after") for row in rows.values())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--copies", type=int, default=THROUGHPUT_COPIES, help="submissions per run (default 300)")
    parser.add_argument("--timeout", type=float, default=2.0, help="per-exercise time limit in seconds (default 2)")
    parser.add_argument(
        "--chapter", type=int, action="append", help="chapter of a throughput run (repeatable; default 1 and 2)"
    )
    parser.add_argument(
        "--jobs", type=int, action="append", help="jobs of the mixed run (repeatable; default 1 and 2)"
    )
    args = parser.parse_args()
    limits = Limits(exercise_seconds=args.timeout, submission_seconds=60)
    load = os.getloadavg()[0]
    lines = [
        "# Grading throughput",
        "",
        f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
        f"load average {load:.1f} when the runs started (other work shares these cores).",
        f"Per-exercise limit {args.timeout:g} s. Command: `.venv/bin/python benchmarks/grading.py"
        + (f" --copies {args.copies}" if args.copies != THROUGHPUT_COPIES else "")
        + "`. CPU: seconds of CPU the grader and its workers used.",
        "",
    ]
    rows = [
        "| run | jobs | submissions | seconds | CPU s | floor s | result | target | verdict |",
        "|---|---:|---:|---:|---:|---:|---:|---|---|",
    ]

    folder = Path(tempfile.mkdtemp(prefix="cagd-bench-correct-"))
    make_class(folder, args.copies, ("correct",))
    target = THROUGHPUT_TARGET * args.copies / THROUGHPUT_COPIES
    for chapter in args.chapter or (1, 2):
        correct = time_grading(folder, 2, limits, [chapter])
        assert all(row[1] == row[2] for row in correct.rows.values()), "every correct submission must get full marks"
        rows.append(
            f"| {args.copies} correct, chapter {chapter} | 2 | {len(correct.rows)} | {correct.seconds:.1f} | "
            f"{correct.cpu:.1f} | – | {correct.seconds:.1f} s | under {target:.3g} s | "
            f"{'met' if correct.seconds < target else 'missed'} |"
        )
    shutil.rmtree(folder)

    folder = Path(tempfile.mkdtemp(prefix="cagd-bench-mixed-"))
    make_class(folder, args.copies, ("correct", "partly_wrong", "stub", "looping"))
    for jobs in args.jobs or (1, 2):
        mixed = time_grading(folder, jobs, limits, [1, 2])
        floor = timeouts_spent(mixed.rows) * args.timeout / jobs
        ratio = mixed.seconds / floor if floor else float("nan")
        rows.append(
            f"| {args.copies} mixed, chapters 1-2 | {jobs} | {len(mixed.rows)} | {mixed.seconds:.1f} | "
            f"{mixed.cpu:.1f} | {floor:.1f} | {ratio:.3f}x floor | at most {FLOOR_TARGET:g}x | "
            f"{'met' if ratio <= FLOOR_TARGET else 'missed'} |"
        )
    shutil.rmtree(folder)
    lines += rows
    lines += [
        "",
        "The mixed class cycles correct / partly wrong / stub / endless loop in `de_casteljau`; its floor counts the "
        "timeouts recorded in the gradebook.",
        f"Confinement of the graded code: {correct.confinement}.",
    ]
    RESULTS.parent.mkdir(exist_ok=True)
    RESULTS.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
