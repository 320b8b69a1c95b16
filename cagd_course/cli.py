"""The `cagd` command: list the course, self-check a notebook, validate suites, grade a class, export its
grades, release the course to a class, write a Gradescope autograder, build the book."""

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
    ids = _exercise_ids(args.exercise, args.chapter)
    if args.mutants:
        return _validate_mutants(args, ids)
    from .grading.validate import format_verdicts, validate

    verdicts = validate(seed=args.seed, ids=ids)
    print(format_verdicts(verdicts))
    return 0 if not any(v.problems for v in verdicts) else 1


def _exercise_ids(exercises: list[str] | None, chapters: list[int] | None) -> list[str] | None:
    """The exercise ids named on the command line, with every exercise of the chapters named; None for all."""
    if not exercises and not chapters:
        return None
    from .manifest import load_course

    course = load_course()
    known = {c.number: c for c in course.chapters}
    unknown = [n for n in chapters or () if n not in known]
    if unknown:
        raise SystemExit(f"cagd validate: no chapter {unknown} in book.toml (chapters {min(known)}-{max(known)})")
    ids = list(exercises or ())
    for number in chapters or ():
        ids += [eid for eid in known[number].exercise_points if eid not in ids]
    return ids


def _validate_mutants(args, ids: list[str] | None) -> int:
    from .grading.mutation import format_mutation_reports, run_mutants, survivors_toml

    reports = run_mutants(ids=ids, seed=args.seed, workers=args.workers)
    print(format_mutation_reports(reports, show=args.show))
    if args.survivors:
        args.survivors.write_text(survivors_toml(reports), encoding="utf-8")
        print(f"survivors written to {args.survivors} as [[accepted]] entries with an empty reason")
    return 0 if all(r.ok for r in reports) else 1


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
            students=args.student,
        )
    except (UnconfinedError, RuntimeError) as err:
        print(f"cagd grade: {err}", file=sys.stderr)
        return 2
    print(summary)
    out = Path(args.out)
    print(f"gradebook: {out / 'gradebook.csv'}; class report: {out / 'report.html'}; "
          f"feedback: {out}/<student>/feedback.html and {out}/<student>/chNN/")
    return 0


def _cmd_export(args) -> int:
    from .grading.lms import export
    from .manifest import load_course

    if args.canvas is None and args.long is None:
        print("cagd export: say what to write: --canvas FILE and/or --long FILE", file=sys.stderr)
        return 2
    written, unmatched = export(args.grades, load_course(), args.canvas, args.long, args.roster)
    for path in written:
        print(f"wrote {path}")
    if unmatched:
        print(f"cagd export: {len(unmatched)} student(s) not in the roster, exported with their own names: "
              + ", ".join(unmatched[:20]), file=sys.stderr)
    return 0


def _cmd_report(args) -> int:
    from .grading.class_report import write_report
    from .manifest import load_course

    if not any(Path(args.grades).glob("*/ch[0-9][0-9]/record.json")):
        print(f"cagd report: {args.grades} holds no graded notebooks", file=sys.stderr)
        return 2
    print(f"class report: {write_report(args.grades, load_course())}")
    return 0


def _cmd_release(args) -> int:
    from .grading.release import release

    try:
        made = release(args.out, args.chapter, book=args.book, force=args.force, live=args.live,
                       execute=not args.no_outputs, timeout=args.timeout)
    except (FileExistsError, RuntimeError) as err:
        print(f"cagd release: {err}", file=sys.stderr)
        return 2
    print(f"release written to {made.out}: {len(made.exercises)} exercise notebook(s) with a self-check of "
          f"{len(made.checked)} exercise(s), {len(made.chapters)} chapter notebook(s) "
          f"({made.dropped_cells} reference-source cell(s) dropped; {len(made.executed)} with their outputs)"
          + (f", the book in {made.book}" if made.book else ""))
    if made.live:
        print("live: chapters/cagd_ref and chapters/cagd_course let every chapter run; they hold the reference "
              "implementation, so this release does not keep the no-reference promise (its README says so)")
        print("checked: no hidden case in it")
    else:
        print("checked: no reference implementation of a graded function and no hidden case in it")
    for problem in made.problems:
        print(f"cagd release: {problem}", file=sys.stderr)
    return 1 if made.problems else 0


def _cmd_autograder(args) -> int:
    from .grading.autograder import build_autograder

    try:
        made = build_autograder(args.chapter, args.out, _limits(args), args.seed, args.user, args.allow_unconfined)
    except RuntimeError as err:
        print(f"cagd autograder: {err}", file=sys.stderr)
        return 2
    print(f"Gradescope autograder of chapter {made.chapter} written to {made.path}: "
          f"{len(made.exercises)} exercise(s), {sum(made.exercises.values()):g} point(s); the course's wheel "
          f"{made.wheel}; runtime: {', '.join(r.split(';')[0] for r in made.requirements)}")
    print("upload it as the autograder of a programming assignment (see the README, section Gradescope)")
    return 0


def _cmd_stamp(args) -> int:
    from .grading.layouts import stamp_exercise_notebooks
    from .manifest import load_course

    course = load_course()
    changed = stamp_exercise_notebooks(course, check=args.check)
    for path in changed:
        print(("lacks metadata.cagd.chapter: " if args.check else "stamped ") + str(path.relative_to(course.root)))
    if not changed:
        print("every exercise notebook carries metadata.cagd.chapter")
    return 1 if args.check and changed else 0


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
        description="The CAGD course: list chapters, check and grade exercise notebooks, export grades, release "
        "the course to a class, build the HTML book.",
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
    p.add_argument(
        "--chapter", action="append", type=int, metavar="N", help="only this chapter's exercises (repeatable)"
    )
    p.add_argument("--seed", type=int, default=0, help="seed of the random cases (default 0)")
    p.add_argument(
        "--mutants",
        action="store_true",
        help="instead: change the reference of each exercise one small slip at a time (operator, comparison, "
        "integer, min/max, a dropped raise, ...) and report the changes its suite does not catch; equivalent "
        "ones are listed with a reason in tests/hidden/mutants/chNN.toml",
    )
    p.add_argument("--show", type=int, default=20, metavar="K", help="with --mutants: survivors listed per exercise "
                   "(0: all; default 20)")
    p.add_argument("--survivors", type=Path, metavar="FILE", help="with --mutants: also write the survivors to FILE "
                   "as [[accepted]] entries to fill in")
    p.add_argument("--workers", type=int, metavar="K", help="with --mutants: processes (default: one per core)")
    p.set_defaults(run=_cmd_validate)

    p = sub.add_parser(
        "grade",
        help="grade a class's notebooks, each on its own chapter, into the semester's gradebook",
        description="Grade every notebook under the paths on its own chapter (from metadata.cagd.chapter, else "
        "the file name, else its title) into GRADES: gradebook.csv (one row per student, a column per exercise "
        "graded so far, a total per chapter and overall), report.html (the class at a glance), and per student "
        "feedback.html and results.json (Gradescope), per chapter in <student>/chNN/. Layouts: a folder per "
        "student (SUBMISSIONS/<student>/<NN-slug>.ipynb, as nbgrader collects them) or flat files of an LMS "
        "download (Canvas: <name>_<userid>_<submissionid>_<original>.ipynb, LATE kept). Run it again as "
        "work comes in: graded, unchanged notebooks are skipped, the others added.",
    )
    p.add_argument("paths", nargs="+", type=Path, metavar="PATH", help="notebooks, or folders of either layout")
    p.add_argument("--out", type=Path, required=True, metavar="GRADES", help="the grades folder (kept all semester)")
    p.add_argument("--jobs", type=int, default=1, help="submissions graded in parallel (default 1)")
    p.add_argument(
        "--allow-unconfined",
        action="store_true",
        help="grade even where graded code cannot be confined (it could then read the reference and the hidden "
        "suites and write your files); without it such grading is refused",
    )
    p.add_argument("--force", action="store_true", help="regrade notebooks already graded, even unchanged")
    p.add_argument(
        "--chapter",
        type=int,
        action="append",
        metavar="N",
        help="grade only chapter N's notebooks (repeatable; default all). A single --chapter also names the "
        "chapter of notebooks whose own chapter is unclear",
    )
    p.add_argument(
        "--student",
        action="append",
        metavar="NAME",
        help="grade only this student (folder name, Canvas name or key; repeatable): with --force, a re-grade "
        "that changes only their cells",
    )
    _add_limits(p)
    p.set_defaults(run=_cmd_grade)

    p = sub.add_parser(
        "export",
        help="write the gradebook for an LMS: Canvas's import CSV and/or a plain long CSV",
        description="Canvas: Student, ID, SIS User ID, SIS Login ID, Section, then one column per chapter with "
        "its points possible in the second row; import it in Canvas's Gradebook (Import). Long: student, "
        "chapter, exercise, score, max, status, one line each.",
    )
    p.add_argument("grades", type=Path, metavar="GRADES", help="the grades folder of `cagd grade --out`")
    p.add_argument("--canvas", type=Path, metavar="FILE", help="write Canvas's gradebook import CSV here")
    p.add_argument("--long", type=Path, metavar="FILE", help="write the long CSV here")
    p.add_argument(
        "--roster",
        type=Path,
        metavar="CSV",
        help="Canvas's own gradebook export: its students (matched by ID, SIS login, SIS id or name) and "
        "assignment columns named 'Chapter N...' are used as they are",
    )
    p.set_defaults(run=_cmd_export)

    p = sub.add_parser("report", help="rewrite GRADES/report.html from the graded notebooks")
    p.add_argument("grades", type=Path, metavar="GRADES", help="the grades folder of `cagd grade --out`")
    p.set_defaults(run=_cmd_report)

    p = sub.add_parser(
        "release",
        help="write what a class's students get: exercises, chapters and an offline self-check without answers",
        description="OUT/exercises: the exercise notebooks and beside them a small cagd_course package whose "
        "check() runs the visible cases (answers bundled as data) and names the hidden groups; no reference "
        "implementation of a graded function and no hidden case is in OUT (checked before it is written). "
        "OUT/chapters: the chapter notebooks without their reference-source cells, each with its executed outputs "
        "(figures, tables, the static frames of its explorers) from the book's execution cache: chapters "
        "`cagd book` executed are not run again, the others are (minutes for all 21). With --live also the "
        "runtime the chapters need (the reference among it), with --book also OUT/book. OUT/README.md says "
        "which mode it is.",
    )
    p.add_argument("out", type=Path, metavar="OUT", help="a new (or empty) folder outside the course")
    p.add_argument("--chapter", type=int, action="append", metavar="N", help="only chapter N (repeatable)")
    p.add_argument("--book", action="store_true", help="also build the HTML book of the released chapters")
    p.add_argument(
        "--live",
        action="store_true",
        help="also ship what the chapters run (cagd_ref, the reference implementation, and the course's explorers) "
        "so every chapter and explorer runs in the students' Jupyter; the release then holds the reference "
        "solutions of the exercises (the class report flags submissions that are the reference's code)",
    )
    p.add_argument("--no-outputs", action="store_true",
                   help="write the chapter notebooks without executing them (seconds; they show no figures)")
    p.add_argument("--timeout", type=int, default=300, help="seconds allowed per notebook cell (default 300)")
    p.add_argument("--force", action="store_true", help="replace OUT if it is not empty")
    p.set_defaults(run=_cmd_release)

    p = sub.add_parser(
        "autograder",
        help="write one chapter's Gradescope autograder (a zip to upload)",
        description="Write OUT.zip, the autograder of a Gradescope programming assignment for one chapter's "
        "exercise notebook: setup.sh and run_autograder at its root (Gradescope's autograder specification), the "
        "course's own wheel, the runtime it needs and the chapter's hidden suite. Each submission is graded as "
        "`cagd grade` grades a notebook: in the grader's confined worker, as an unprivileged user that setup.sh "
        "creates, which can read neither the hidden suite nor the reference nor write results.json. results.json: "
        "one test per exercise with its score, one per hidden group of cases shown after grades are published.",
    )
    p.add_argument("out", type=Path, metavar="OUT.zip", help="the zip to write")
    p.add_argument("--chapter", type=int, required=True, metavar="N", help="the chapter whose exercises it grades")
    p.add_argument("--user", default="cagd-student",
                   help="the unprivileged user graded code runs as in the container (default cagd-student)")
    p.add_argument(
        "--allow-unconfined",
        action="store_true",
        help="grade even where the container cannot confine graded code (it could then read the hidden suite); "
        "without it such submissions score 0 and the log says why",
    )
    _add_limits(p)
    p.set_defaults(run=_cmd_autograder)

    p = sub.add_parser("stamp", help="write metadata.cagd.chapter into every exercise notebook of book.toml")
    p.add_argument("--check", action="store_true", help="change nothing; fail if a notebook lacks it")
    p.set_defaults(run=_cmd_stamp)

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
