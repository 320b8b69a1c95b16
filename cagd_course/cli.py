"""The `cagd` command: list the course, self-check a notebook, validate suites, grade a class, build the book."""

from __future__ import annotations

import argparse
import os
import sys
from importlib.util import find_spec
from pathlib import Path

__all__ = ["main", "build_parser"]


def _cmd_list(args) -> int:
    from .manifest import load_course

    course = load_course()
    if args.notebooks:
        for chapter in course.chapters:
            print(chapter.notebook.relative_to(course.root))
            if chapter.exercises is not None:
                print(chapter.exercises.relative_to(course.root))
        return 0
    print(course.title)
    for chapter in course.chapters:
        print(f"\n{chapter.number:2d}. {chapter.title}")
        print(f"    chapter:   {chapter.notebook.relative_to(course.root)}")
        if chapter.exercises is not None:
            print(f"    exercises: {chapter.exercises.relative_to(course.root)}")
        for exercise_id, points in chapter.exercise_points.items():
            print(f"      {exercise_id:28} {points:g} pt")
    return 0


def _limits(args):
    from .grading.runner import Limits

    return Limits(
        exercise_seconds=args.timeout,
        submission_seconds=max(args.timeout, args.submission_timeout),
        memory_mb=args.memory,
    )


def _cmd_check(args) -> int:
    from .grading.engine import grade_statements, load_exercises, prepare
    from .grading.extract import SubmissionError, extract_notebook
    from .grading.report import check_text

    try:
        submission = extract_notebook(args.notebook)
    except SubmissionError as err:
        print(f"{args.notebook}: {err.status}: {err.detail}", file=sys.stderr)
        return 2
    exercises = load_exercises(ids=args.exercise or None)
    if not args.exercise:
        defined = submission.defined_names()
        exercises = {eid: ex for eid, ex in exercises.items() if ex[0].function in defined} or exercises
    outcome = grade_statements(submission.statements, prepare(exercises, args.seed), _limits(args))
    for result in outcome.exercises:
        print(check_text(result, outcome.run.load_problems, submission.skipped), end="\n\n")
    print(f"Total: {outcome.score:g} / {outcome.max_score:g}")
    if not outcome.run.confined:
        # A self-check may run unconfined (a student's laptop); grading a class may not.
        print(f"note: the checked code ran unconfined ({outcome.run.sandbox})", file=sys.stderr)
    return 0


def _cmd_validate(args) -> int:
    from .grading.validate import format_verdicts, validate

    verdicts = validate(seed=args.seed, ids=args.exercise or None)
    print(format_verdicts(verdicts))
    return 0 if not any(v.problems for v in verdicts) else 1


def _cmd_grade(args) -> int:
    from .grading.classroom import UnconfinedError, grade_class

    try:
        summary = grade_class(
            args.paths,
            args.out,
            args.jobs,
            _limits(args),
            args.seed,
            args.force,
            chapters=args.chapter,
            allow_unconfined=args.allow_unconfined,
        )
    except UnconfinedError as err:
        print(f"cagd grade: {err}", file=sys.stderr)
        return 2
    print(summary)
    print(f"gradebook: {Path(args.out) / 'gradebook.csv'}; feedback: {Path(args.out)}/<submission>/feedback.html")
    return 0


def _cmd_book(args) -> int:
    import time

    from .book import BookError, build_book
    from .manifest import load_course

    if args.pdf:
        from .book.browser import HOW_TO_GET_IT, chromium_executable

        # Say so before executing the chapters, not after.
        if chromium_executable() is None or find_spec("playwright") is None:
            print(f"cagd book --pdf: printing needs Chromium and playwright: {HOW_TO_GET_IT}", file=sys.stderr)
            return 2
    started = time.monotonic()
    out = args.out if args.out is not None else load_course().root / "_build" / "html"
    try:
        pages = build_book(out, args.chapter or None, args.timeout, frames=args.frames)
    except BookError as err:
        print(f"cagd book: {err}", file=sys.stderr)
        return 1
    for page in pages:
        print(f"  {page.file:45} {page.state}")
    failed = [page for page in pages if page.error]
    print(f"book written to {out / 'index.html'} in {time.monotonic() - started:.0f} s")
    if args.pdf and not failed:
        from .book.pdf import PdfError, print_pdf

        try:
            pdf = print_pdf(out, pages)
        except PdfError as err:
            print(f"cagd book --pdf: {err}", file=sys.stderr)
            return 1
        print(f"PDF written to {pdf}")
    print(f"read it offline: open {out / 'index.html'}, or serve it: python -m http.server -d {out}")
    for page in failed:
        print(f"cagd book: {page.error}", file=sys.stderr)
    return 1 if failed else 0


def _add_limits(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--timeout", type=float, default=10.0, help="seconds allowed per exercise (default 10)")
    parser.add_argument(
        "--submission-timeout", type=float, default=120.0, help="seconds allowed per submission in all (default 120)"
    )
    parser.add_argument(
        "--memory", type=int, default=1024, help="memory limit of the graded process in MB (default 1024)"
    )
    parser.add_argument("--seed", type=int, default=0, help="seed of the random cases (default 0)")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="cagd",
        description="The CAGD course: list chapters, check and grade exercise notebooks, build the HTML book.",
    )
    parser.add_argument(
        "--course",
        type=Path,
        metavar="DIR",
        help="the course folder holding book.toml (default: the working directory or its parents)",
    )
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    p = sub.add_parser("list", help="print the chapters and exercises of book.toml")
    p.add_argument("--notebooks", action="store_true", help="print only the notebook paths, one per line")
    p.set_defaults(run=_cmd_list)

    p = sub.add_parser("check", help="self-check one student notebook (isolated, same suites as grading)")
    p.add_argument("notebook", type=Path, help="the exercise notebook to check")
    p.add_argument("--exercise", action="append", metavar="ID", help="only this exercise id (repeatable)")
    _add_limits(p)
    p.set_defaults(run=_cmd_check)

    p = sub.add_parser(
        "validate", help="prove every hidden suite: reference 100%%, stub 0%%, recorded mistakes < 100%%"
    )
    p.add_argument("--exercise", action="append", metavar="ID", help="only this exercise id (repeatable)")
    p.add_argument("--seed", type=int, default=0, help="seed of the random cases (default 0)")
    p.set_defaults(run=_cmd_validate)

    p = sub.add_parser("grade", help="grade submissions into a gradebook, feedback pages and results.json")
    p.add_argument("paths", nargs="+", type=Path, metavar="PATH", help="notebooks or folders of notebooks")
    p.add_argument("--out", type=Path, required=True, help="output folder (gradebook.csv, <submission>/...)")
    p.add_argument("--jobs", type=int, default=1, help="submissions graded in parallel (default 1)")
    p.add_argument(
        "--allow-unconfined",
        action="store_true",
        help="grade even where graded code cannot be confined (it could then read the reference and the hidden "
        "suites and write your files); without it such grading is refused",
    )
    p.add_argument("--force", action="store_true", help="regrade submissions already in the gradebook")
    p.add_argument(
        "--chapter",
        type=int,
        action="append",
        metavar="N",
        help="grade only chapter N's exercises (repeatable; default all)",
    )
    _add_limits(p)
    p.set_defaults(run=_cmd_grade)

    p = sub.add_parser("book", help="execute every chapter and write the HTML book (and with --pdf, a PDF of it)")
    p.add_argument(
        "--out", type=Path, default=None, help="output folder (default: _build/html in the course folder)"
    )
    p.add_argument("--chapter", type=int, action="append", metavar="N", help="only chapter N (repeatable)")
    p.add_argument("--timeout", type=int, default=300, help="seconds allowed per notebook cell (default 300)")
    p.add_argument(
        "--frames",
        type=int,
        default=21,
        help="frames of each explorer's main slider in the book (default 21; 0: a still picture)",
    )
    p.add_argument(
        "--pdf", action="store_true", help="also print the whole book to OUT/cagd-course.pdf (headless Chromium)"
    )
    p.set_defaults(run=_cmd_book)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if args.course is not None:
        from .manifest import COURSE_ENV

        # Through the environment the folder reaches every part of the run, notebook kernels included.
        os.environ[COURSE_ENV] = str(args.course.resolve())
    try:
        return args.run(args)
    except (FileNotFoundError, KeyError, ValueError) as err:
        print(f"cagd {args.command}: {err}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
