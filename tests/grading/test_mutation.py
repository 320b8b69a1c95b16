"""`cagd validate --mutants`: mutants are made, run as a student's code would be, and judged by the suite."""

from __future__ import annotations

import time

import numpy as np
import pytest

from cagd_course.grading import mutation
from cagd_course.grading.mutation import Mutant, mutants_of, reached_functions, run_mutants
from cagd_course.grading.worker import encode
from cagd_ref import geometry

PROJECTION = "01.projection"


def _find(mutants: list[Mutant], function: str, text: str) -> Mutant:
    found = [m for m in mutants if m.qualname == function and text in m.change]
    assert found, f"no mutant of {function} with {text!r} among {[m.key for m in mutants]}"
    return found[0]


def test_the_functions_reached_include_the_input_checks():
    names = [f"{f.__module__}.{f.__qualname__}" for f in reached_functions(geometry.projection)]
    assert names[0] == "cagd_ref.geometry.projection"
    assert "cagd_ref._validation.as_vector" in names


def test_mutants_cover_each_kind_of_slip_and_have_stable_unique_keys():
    mutants = mutants_of(geometry.projection)
    keys = [m.key for m in mutants]
    assert len(keys) == len(set(keys))
    changes = " ".join(m.change for m in mutants)
    for slip in ("raise -> pass", "== -> !=", "* -> /", "0 -> 1"):
        assert slip in changes
    assert keys == [m.key for m in mutants_of(geometry.projection)]


def test_a_mutant_changes_behaviour_and_is_undone():
    mutant = _find(mutants_of(geometry.projection), "projection", "raise -> pass")
    original = geometry.projection.__code__
    geometry.projection.__code__ = mutation._mutated_code(geometry.projection, mutant)
    try:
        with np.errstate(all="ignore"):
            value = geometry.projection([1.0, 2.0], [0.0, 0.0])  # no longer refused
        assert np.isnan(value).all()
    finally:
        geometry.projection.__code__ = original
    with pytest.raises(ValueError, match="zero vector"):
        geometry.projection([1.0, 2.0], [0.0, 0.0])


def test_a_mutant_that_runs_forever_is_stopped():
    def forever(x):
        while True:
            x += 1

    started = time.perf_counter()
    events, stopped = mutation._run_cases(forever, [{"args": encode([1]), "kwargs": encode({})}], 0.3)
    assert stopped and events == []
    assert time.perf_counter() - started < 5


def test_run_mutants_catches_wrong_formulas_and_lists_survivors():
    (report,) = run_mutants(ids=[PROJECTION], progress=False, workers=1)
    assert report.problems == []
    assert report.mutants == len(mutants_of(geometry.projection))
    assert report.caught + report.accepted + len(report.survivors) == report.mutants
    wrong_formula = _find(mutants_of(geometry.projection), "projection", "* -> /").key
    assert wrong_formula not in report.survivors
    refused = _find(mutants_of(geometry.projection), "projection", "raise -> pass").key
    assert refused not in report.survivors  # the suite asks for q = 0 to be refused


def test_accepted_entries_count_and_stale_ones_are_reported(tmp_path, monkeypatch):
    (plain,) = run_mutants(ids=[PROJECTION], progress=False, workers=1)
    assert plain.survivors, "the example needs one surviving mutant of projection"
    survivor = plain.survivors[0]
    caught = _find(mutants_of(geometry.projection), "projection", "* -> /").key
    listed = tmp_path / "ch01.toml"
    listed.write_text(
        "".join(
            f'[[accepted]]\nexercise = "{PROJECTION}"\nmutant = "{key}"\nreason = "test"\n\n'
            for key in (survivor, caught, "geometry.projection: no such change")
        ),
        encoding="utf-8",
    )
    monkeypatch.setattr(mutation, "accepted_file", lambda hidden: listed)
    (report,) = run_mutants(ids=[PROJECTION], progress=False, workers=1)
    assert report.accepted == 1 and survivor not in report.survivors
    assert len(report.stale) == 2 and not report.ok
    assert any("now catches" in s for s in report.stale) and any("no such mutant" in s for s in report.stale)


def test_an_accepted_entry_needs_a_reason(tmp_path):
    listed = tmp_path / "ch01.toml"
    listed.write_text('[[accepted]]\nexercise = "01.projection"\nmutant = "x"\nreason = ""\n', encoding="utf-8")
    with pytest.raises(ValueError, match="reason"):
        mutation._accepted(listed)


def test_the_course_lists_of_accepted_mutants_parse_and_give_reasons():
    from pathlib import Path

    folder = Path(__file__).resolve().parents[1] / "hidden" / "mutants"
    files = sorted(folder.glob("*.toml"))
    assert files, "tests/hidden/mutants/ holds the accepted equivalent mutants"
    for path in files:
        for exercise, entries in mutation._accepted(path).items():
            assert exercise == "*" if path.stem == mutation.COMMON else exercise.startswith(path.stem[2:] + ".")
            assert all(reason.strip() for reason in entries.values())
