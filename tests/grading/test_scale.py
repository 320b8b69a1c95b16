"""Grading costs time in proportion to the class: the gradebook is not rebuilt after every notebook, and similar
code is found bucket by bucket, not pair by pair. (`benchmarks/grading.py --only scale` measures whole runs.)"""

from __future__ import annotations

import time

from cagd_course.grading import classroom
from cagd_course.grading.gradebook import gradebook_text
from cagd_course.grading.similarity import MIN_NODES, flag_pairs
from cagd_course.manifest import load_course

COURSE = load_course()


def _record(name: str, chapter: int = 1, fingerprints: dict | None = None) -> dict:
    exercises = {eid: {"score": p, "points": p, "seconds": 0.01, "stopped": "", "categories": {}}
                 for eid, p in next(c for c in COURSE.chapters if c.number == chapter).exercise_points.items()}
    return {"submission": name, "student": name, "lms_id": "", "late": False, "chapter": chapter, "seed": 1,
            "score": sum(p["points"] for p in exercises.values()), "max_score": 10.0, "status": "ok",
            "exercises": exercises, "fingerprints": fingerprints or {}, "sandbox": "landlock"}


def test_a_run_rebuilds_the_gradebook_a_bounded_number_of_times(tmp_path, monkeypatch):
    calls = []
    monkeypatch.setattr(classroom, "gradebook_text", lambda records, course: calls.append(len(records)) or "x\n")
    records = {}
    book = classroom._Gradebook(tmp_path / "gradebook.csv", records, COURSE)
    started = time.monotonic()
    for i in range(3000):  # 3,000 notebooks graded in a blink: nowhere near 3,000 rebuilds
        records[(f"s{i:05d}", 1)] = {}
        book.changed()
    book.write()
    elapsed = time.monotonic() - started
    assert len(calls) <= 2 + elapsed / book.EVERY and calls[-1] == 3000
    assert (tmp_path / "gradebook.csv").read_text() == "x\n"


def test_the_gradebook_is_one_pass_over_the_records():
    small = {(f"s{i:05d}", 1): _record(f"s{i:05d}") for i in range(500)}
    large = {(f"s{i:05d}", 1): _record(f"s{i:05d}") for i in range(5000)}
    timings = []
    for records in (small, large):
        started = time.process_time()
        text = gradebook_text(records, COURSE)
        timings.append(time.process_time() - started)
        assert text.count("\n") == len(records) + 1
    # Linear: 10x the records in about 10x the time (the old rebuild scanned every record per row: 100x).
    assert timings[1] < 30 * max(timings[0], 1e-3), timings


def test_identical_functions_are_grouped_not_paired():
    same = {"01.projection": ["abc", MIN_NODES + 5], "01.conic_type": ["def", MIN_NODES + 9]}
    records = [_record(f"s{i:04d}", fingerprints=same) for i in range(2000)]
    records.append(_record("odd", fingerprints={"01.projection": ["zzz", MIN_NODES + 5]}))
    started = time.process_time()
    flags = flag_pairs(records, {"01.conic_type": "def"}, {})
    assert time.process_time() - started < 5
    pairs = [f for f in flags if f["second"] != "reference implementation"]
    # Each member beside the group's first: 1,999 flags, not 1,999,000 pairs.
    assert len(pairs) == 1999 and {f["first"] for f in pairs} == {"s0000"}
    assert all(f["exercises"] == ["01.conic_type", "01.projection"] for f in pairs)
    reference = [f for f in flags if f["second"] == "reference implementation"]
    assert len(reference) == 2000 and all(f["exercises"] == ["01.conic_type"] for f in reference)
    assert not [f for f in flags if "odd" in (f["first"], f["second"])]
