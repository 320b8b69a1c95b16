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

A third run, `--only scale`, shows that grading grows linearly with the class: 1,000 and 10,000 correct
chapter-1 notebooks (`--scale 1000 --scale 10000`), each graded with `--jobs` (default 2) into a new grades
folder by a fresh interpreter, which reports its wall time and peak memory (the grading process's, and the
largest of its children's). Target: the larger class within 12x the time of the smaller (10x is linear).
Results go to `benchmarks/results/grading-scale.md`.

    .venv/bin/python benchmarks/grading.py                # 300 submissions per run, as in the targets
    .venv/bin/python benchmarks/grading.py --copies 40 --jobs 2
    .venv/bin/python benchmarks/grading.py --only scale   # 1,000 and 10,000 correct chapter-1 notebooks
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import shutil
import subprocess
import sys
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
SCALE_RESULTS = Path(__file__).parent / "results" / "grading-scale.md"
SCALE_CLASSES = (1_000, 10_000)
SCALE_TARGET = 12.0  # the time of a class ten times larger, at most this multiple
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


def scale_run(copies: int, jobs: int) -> dict:
    """Grade `copies` correct chapter-1 notebooks in this (fresh) process; its seconds, rows and peak memory."""
    folder = Path(tempfile.mkdtemp(prefix="cagd-bench-scale-"))
    out = Path(tempfile.mkdtemp(prefix="cagd-bench-scale-out-"))
    try:
        make_class(folder, copies, ("correct",))
        limits = Limits(exercise_seconds=10, submission_seconds=60)
        before = os.times()
        started = time.perf_counter()
        summary = grade_class([folder], out, jobs=jobs, limits=limits, progress=False, chapters=[1])
        seconds = time.perf_counter() - started
        cpu = sum(os.times()[:4]) - sum(before[:4])
        rows = read_gradebook(out / "gradebook.csv")
        full = sum(1 for row in rows.values() if row[1] == row[2])
        report = (out / "report.html").stat().st_size
    finally:
        shutil.rmtree(folder, ignore_errors=True)
        shutil.rmtree(out, ignore_errors=True)
    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    children = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    return {"copies": copies, "jobs": jobs, "seconds": seconds, "cpu": cpu, "rows": len(rows), "full": full,
            "grader_mb": own, "child_mb": children, "report_bytes": report, "confinement": summary.confinement}


def scale(classes: list[int], jobs: int) -> list[str]:
    """Each class size graded by a fresh interpreter (so its peak memory is its own); the table of results."""
    runs = []
    for copies in classes:
        command = [sys.executable, __file__, "--scale-run", str(copies), "--jobs", str(jobs)]
        done = subprocess.run(command, capture_output=True, text=True, check=True)
        runs.append(json.loads(done.stdout.strip().splitlines()[-1]))
        print(f"{copies} notebooks: {runs[-1]['seconds']:.1f} s", flush=True)
    lines = [
        "# Grading at class scale",
        "",
        f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}; load average "
        f"{os.getloadavg()[0]:.1f} after the runs (other work shares these cores). Command: "
        "`.venv/bin/python benchmarks/grading.py --only scale`. Each class of correct chapter-1 notebooks is graded "
        f"with {jobs} job(s) into a new grades folder (gradebook, feedback, class report with its similarity pass), "
        "by a fresh interpreter.",
        "",
        "| notebooks | seconds | CPU s | per notebook ms | full marks | grader peak MB | largest child peak MB "
        "| report KB |",
        "|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for run in runs:
        assert run["rows"] == run["copies"] == run["full"], run
        lines.append(f"| {run['copies']:,} | {run['seconds']:.1f} | {run['cpu']:.1f} | "
                     f"{1000 * run['seconds'] / run['copies']:.1f} | {run['full']:,} | {run['grader_mb']:.0f} | "
                     f"{run['child_mb']:.0f} | {run['report_bytes'] / 1024:.0f} |")
    if len(runs) >= 2:
        small, large = runs[0], runs[-1]
        size, ratio = large["copies"] / small["copies"], large["seconds"] / small["seconds"]
        bound = SCALE_TARGET * size / 10
        lines += ["", f"{large['copies']:,} notebooks took {ratio:.2f}x the time of {small['copies']:,} "
                  f"({size:g}x the notebooks; {large['cpu'] / small['cpu']:.2f}x the CPU time); target at most "
                  f"{bound:g}x the time: {'met' if ratio <= bound else 'missed'}. Memory: the peaks above (the "
                  "grading process holds every record of the class; each grading process one submission)."]
    lines.append(f"Confinement of the graded code: {runs[-1]['confinement']}.")
    SCALE_RESULTS.parent.mkdir(exist_ok=True)
    SCALE_RESULTS.write_text("\n".join(lines) + "\n")
    return lines


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
    parser.add_argument("--only", choices=("throughput", "scale"), help="run only the throughput and mixed runs, "
                        "or only the class-scale runs (default: both)")
    parser.add_argument("--scale", type=int, action="append", metavar="N",
                        help="class sizes of the scale runs (repeatable; default 1000 and 10000)")
    parser.add_argument("--scale-run", type=int, metavar="N", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.scale_run:
        print(json.dumps(scale_run(args.scale_run, (args.jobs or [2])[-1])))
        return
    if args.only != "throughput":
        print("\n".join(scale(args.scale or list(SCALE_CLASSES), (args.jobs or [2])[-1])))
        if args.only == "scale":
            return
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
