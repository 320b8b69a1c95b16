"""`GRADES/report.html`: the class at a glance, on one self-contained page (no script, no network).

Score histograms per chapter and per exercise; the hidden case categories failed most often (by
category name only, never their inputs); the slowest exercises; the notebooks that did not run
cleanly and why, and those not graded at all; and the submissions whose graded functions are the
same code as another student's or as the reference implementation (`similarity`), flagged for a
person to look at, never as a verdict.
"""

from __future__ import annotations

import html
import json
import statistics
from pathlib import Path

from .gradebook import atomic_write, load_records, read_unassigned
from .similarity import fingerprint, flag_pairs, source_fingerprint

__all__ = ["write_report", "report_html", "REPORT"]

REPORT = "report.html"
# Rows of the similarity table shown; a class copying one solution wholesale would otherwise fill the page.
SHOWN_FLAGS = 1000
EXERCISE_BINS = ("0", "< 25 %", "< 50 %", "< 75 %", "< 100 %", "100 %")
esc = html.escape


def _chapter_bins(scores: list[float], top: float, bins: int = 10) -> list[int]:
    counts = [0] * bins
    for score in scores:
        index = bins - 1 if top <= 0 or score >= top else int(bins * max(score, 0.0) / top)
        counts[min(index, bins - 1)] += 1
    return counts


def _exercise_bins(fractions: list[float]) -> list[int]:
    counts = [0] * len(EXERCISE_BINS)
    for f in fractions:
        index = 0 if f <= 0 else 5 if f >= 1 else 1 + min(int(f * 4), 3)
        counts[index] += 1
    return counts


def _svg_histogram(counts: list[int], labels: list[str], title: str, width: int = 420, height: int = 150) -> str:
    """Bars with their counts above and labels below: an inline SVG, readable without scripts."""
    top = max(counts) or 1
    gap, left, bottom = 4, 6, 34
    bar = (width - 2 * left) / len(counts)
    parts = [f"<svg role='img' aria-label='{esc(title)}' viewBox='0 0 {width} {height}' width='{width}' "
             f"height='{height}' xmlns='http://www.w3.org/2000/svg'>"]
    for i, (count, label) in enumerate(zip(counts, labels)):
        h = (height - bottom - 16) * count / top
        x, y = left + i * bar, height - bottom - h
        parts.append(f"<rect x='{x + gap / 2:.1f}' y='{y:.1f}' width='{bar - gap:.1f}' height='{h:.1f}' fill='#4a78b5'>"
                     f"<title>{esc(label)}: {count}</title></rect>")
        parts.append(f"<text x='{x + bar / 2:.1f}' y='{y - 3:.1f}' font-size='11' text-anchor='middle'>{count}</text>")
        parts.append(f"<text x='{x + bar / 2:.1f}' y='{height - bottom + 14:.1f}' font-size='9' "
                     f"text-anchor='middle'>{esc(label)}</text>")
    parts.append(f"<line x1='{left}' y1='{height - bottom}' x2='{width - left}' y2='{height - bottom}' stroke='#555'/>")
    parts.append("</svg>")
    return "".join(parts)


def _figure(kind: str, key: str, counts: list[int], labels: list[str], caption: str) -> str:
    return (f"<figure class='histogram' data-kind='{kind}' data-key='{esc(key)}' "
            f"data-counts='{','.join(map(str, counts))}'>{_svg_histogram(counts, labels, caption)}"
            f"<figcaption>{esc(caption)}</figcaption></figure>")


def _table(headers: list[str], rows: list[list[str]], css: str) -> str:
    if not rows:
        return "<p class='none'>None.</p>"
    head = "".join(f"<th>{esc(h)}</th>" for h in headers)
    body = "".join("<tr>" + "".join(f"<td>{esc(str(c))}</td>" for c in row) + "</tr>" for row in rows)
    return f"<table class='{css}'><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _stub_fingerprints(course) -> dict[str, set[str]]:
    """Fingerprints of the untouched exercise notebooks' functions: a stub handed in twice is no copy."""
    import ast

    found: dict[str, set[str]] = {}
    for chapter in course.chapters:
        if chapter.exercises is None or not chapter.exercises.is_file():
            continue
        names = {eid.split(".", 1)[1]: eid for eid in chapter.exercise_points}
        try:
            cells = json.loads(chapter.exercises.read_text(encoding="utf-8"))["cells"]
        except (OSError, ValueError, KeyError):
            continue
        for cell in cells:
            if cell.get("cell_type") != "code":
                continue
            try:
                body = ast.parse("".join(cell.get("source", ""))).body
            except SyntaxError:
                continue
            for node in body:
                if isinstance(node, (ast.FunctionDef, ast.ClassDef)) and node.name in names:
                    found.setdefault(names[node.name], set()).add(fingerprint(node)[0])
    return found


def _reference_fingerprints(course, chapters: set[int]) -> dict[str, str]:
    from .engine import load_exercises

    found = {}
    for chapter in course.chapters:
        if chapter.number not in chapters:
            continue
        try:
            exercises = load_exercises(course, list(chapter.exercise_points))
        except Exception:  # noqa: BLE001 - a chapter whose suite does not load is compared with students only
            continue
        for eid, (exercise, _) in exercises.items():
            printed = source_fingerprint(exercise.reference)
            if printed is not None:
                found[eid] = printed[0]
    return found


def report_html(records: dict, unassigned: list[dict], course, flags: list[dict]) -> str:
    """The class report as one HTML page."""
    titles = {c.number: c.title for c in course.chapters}
    order = {c.number: i for i, c in enumerate(course.chapters)}
    by_chapter: dict[int, list[dict]] = {}
    for (_, chapter), record in sorted(records.items()):
        by_chapter.setdefault(chapter, []).append(record)
    chapters = sorted(by_chapter, key=lambda c: order.get(c, 100 + c))
    students = {s for s, _ in records}
    out = [f"<h1>Class report: {esc(course.title)}</h1>",
           f"<p class='lead'>{len(students)} student(s), {len(records)} graded notebook(s) in "
           f"{len(chapters)} chapter(s); {len(unassigned)} notebook(s) not graded.</p>"]
    # Scores.
    out.append("<h2 id='scores'>Scores</h2>")
    summary_rows = []
    for chapter in chapters:
        mine = by_chapter[chapter]
        scores = [float(r["score"]) for r in mine]
        top = max(float(r["max_score"]) for r in mine)
        summary_rows.append([f"{chapter}. {titles.get(chapter, '')}", len(mine), f"{statistics.mean(scores):.2f}",
                             f"{statistics.median(scores):.2f}", f"{top:g}",
                             sum(1 for r in mine if r["status"] != "ok")])
    out.append(_table(["chapter", "notebooks", "mean", "median", "points", "did not run cleanly"], summary_rows,
                      "summary"))
    for chapter in chapters:
        mine = by_chapter[chapter]
        top = max(float(r["max_score"]) for r in mine)
        counts = _chapter_bins([float(r["score"]) for r in mine], top)
        labels = [f"{top * i / 10:g}-" for i in range(10)]
        out.append(f"<section class='chapter' id='ch{chapter:02d}'><h3>Chapter {chapter}: "
                   f"{esc(titles.get(chapter, ''))}</h3><div class='figures'>")
        out.append(_figure("chapter", str(chapter), counts, labels, f"chapter {chapter}: total score of {top:g}"))
        listed = list(course.exercise_points())
        ids = sorted({eid for r in mine for eid in r["exercises"]},
                     key=lambda e: (listed.index(e) if e in listed else len(listed), e))
        for eid in ids:
            fractions = [r["exercises"][eid]["score"] / r["exercises"][eid]["points"]
                         for r in mine if eid in r["exercises"] and r["exercises"][eid]["points"]]
            points = next(r["exercises"][eid]["points"] for r in mine if eid in r["exercises"])
            out.append(_figure("exercise", eid, _exercise_bins(fractions), list(EXERCISE_BINS),
                               f"{eid} ({points:g} pt): share of the points"))
        out.append("</div></section>")
    # Hidden categories failed most often.
    failures: dict[tuple[str, str], list[int]] = {}
    for record in records.values():
        for eid, result in record["exercises"].items():
            for category, (passed, total, visible) in result.get("categories", {}).items():
                if visible:
                    continue
                tally = failures.setdefault((eid, category), [0, 0])
                tally[1] += 1
                tally[0] += passed < total
    worst = sorted(((f, n, eid, cat) for (eid, cat), (f, n) in failures.items() if f), key=lambda t: (-t[0], t[2]))
    out.append("<h2 id='hidden'>Hidden case categories failed most often</h2>"
               "<p>By category name only; the hidden inputs are never shown.</p>")
    out.append(_table(["exercise", "hidden category", "failed by", "of"],
                      [[eid, cat, f, n] for f, n, eid, cat in worst[:25]], "hidden"))
    # Slowest exercises.
    seconds: dict[str, list[float]] = {}
    for record in records.values():
        for eid, result in record["exercises"].items():
            seconds.setdefault(eid, []).append(float(result.get("seconds", 0.0)))
    slow = sorted(seconds.items(), key=lambda kv: -statistics.mean(kv[1]))[:15]
    out.append("<h2 id='slowest'>Slowest exercises</h2>")
    out.append(_table(["exercise", "mean seconds", "slowest seconds", "notebooks"],
                      [[eid, f"{statistics.mean(v):.3f}", f"{max(v):.3f}", len(v)] for eid, v in slow], "slowest"))
    # Not clean.
    unclean = [[r["student"], r["chapter"], r["status"], "; ".join(r.get("notes", [])[:3])[:300]]
               for r in records.values() if r["status"] != "ok"]
    out.append("<h2 id='unclean'>Notebooks that did not run cleanly</h2>")
    out.append(_table(["student", "chapter", "why", "notes"], sorted(unclean, key=lambda r: (r[1], r[0])), "unclean"))
    out.append("<h2 id='unassigned'>Notebooks not graded</h2>")
    out.append(_table(["submission", "file", "why"], [[u["submission"], u["file"], u["reason"]] for u in unassigned],
                      "unassigned"))
    # Similarity.
    names = {s: r["student"] for (s, _), r in records.items()}
    out.append("<h2 id='similar'>Graded functions with the same code</h2>"
               "<p>Identical after renaming every variable and ignoring formatting, comments and docstrings "
               "(short functions and untouched stubs are left out); each group of equal functions is listed as its "
               "first member beside each of the others. A flag for a person to look at, "
               "not a verdict: honest students do sometimes write the same code.</p>")
    out.append(_table(["chapter", "submission", "same code as", "exercises"],
                      [[f["chapter"], names.get(f["first"], f["first"]), names.get(f["second"], f["second"]),
                        ", ".join(f["exercises"])] for f in flags[:SHOWN_FLAGS]], "similar"))
    if len(flags) > SHOWN_FLAGS:
        out.append(f"<p class='more'>... and {len(flags) - SHOWN_FLAGS} more; every record's fingerprints are in "
                   "its <code>record.json</code>.</p>")
    style = (
        "body{font-family:system-ui,sans-serif;max-width:72rem;margin:2rem auto;padding:0 1rem;line-height:1.4}"
        "table{border-collapse:collapse;margin:.5rem 0 1.5rem}td,th{border:1px solid #ccc;padding:.25rem .5rem;"
        "text-align:left;vertical-align:top}th{background:#f3f3f3}.figures{display:flex;flex-wrap:wrap;gap:1rem}"
        "figure{margin:0}figcaption{font-size:.85rem;color:#444}.none{color:#777}"
    )
    return ("<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>Class report</title>"
            f"<style>{style}</style></head><body>" + "\n".join(out) + "</body></html>\n")


def write_report(out: Path, course) -> Path:
    """Write GRADES/report.html from the records and the last run's unassigned notebooks; return its path."""
    out = Path(out)
    records = load_records(out)
    chapters = {chapter for _, chapter in records}
    flags = flag_pairs(list(records.values()), _reference_fingerprints(course, chapters), _stub_fingerprints(course))
    path = out / REPORT
    atomic_write(path, report_html(records, read_unassigned(out), course, flags))
    return path
