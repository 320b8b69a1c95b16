"""The benchmark machinery (benchmarks/run.py) runs end to end on tiny sizes.

Nothing here asserts how fast anything is: timings depend on the machine and
its load. The tests check that one run writes the report and the figure, that
every measured ratio is a finite positive number, that every library agrees
with ours, and that a missing peer library (bezier, geomdl) leaves an empty
column instead of an error, so they pass with or without the bench extra.
"""

from __future__ import annotations

import math
import sys
from dataclasses import replace
from pathlib import Path

import nbformat
import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
if str(ROOT) not in sys.path:  # benchmarks/ is a folder of the checkout, not an installed package
    sys.path.insert(0, str(ROOT))

from benchmarks import peers  # noqa: E402
from benchmarks import run as bench  # noqa: E402
from benchmarks.common import compare, quick_plan  # noqa: E402
from benchmarks.rootfinding import root_error, wilkinson  # noqa: E402
from benchmarks.topics import TOPICS, topic  # noqa: E402

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def tiny_plan(tmp_path: Path):
    """Every section on the smallest sizes; geomdl capped below the largest size, so extrapolation runs too."""
    notebook = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("total = sum(range(10))")])
    path = tmp_path / "tiny.ipynb"
    nbformat.write(notebook, path)
    return replace(
        quick_plan(),
        name="tiny",
        bezier_degrees=(3,),
        bezier_sizes=(50, 400),
        bspline_degrees=(2,),
        bspline_counts=(8,),
        bspline_sizes=(50, 400),
        geomdl_max_points=100,
        knot_counts=(8,),
        root_degrees=(5, 20),
        repeats=1,
        min_sample=0.0,
        budget=0.05,
        chapters=(path,),
        widgets=("de_casteljau_explorer",),
        widget_updates=2,
        grade_runs=1,
    )


@pytest.fixture(scope="module")
def tiny_run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("bench")
    return bench.run(tiny_plan(folder), out=folder / "results", command="tests/test_benchmarks.py")


def _measurements(outcome):
    for section in ("bezier", "bspline", "knots", "roots"):
        for case in outcome["results"][section]:
            for m in case.measurements:
                yield section, case, m


def test_one_run_writes_the_report_and_the_figure(tiny_run):
    text = tiny_run["markdown"].read_text(encoding="utf-8")
    for heading in ("## Targets", "## Bézier evaluation", "## B-spline evaluation", "## Knot insertion",
                    "## Root finding", "## Course health", "**Verdict:"):
        assert heading in text
    assert "benchmarks.png" in text
    assert tiny_run["figure"].read_bytes()[:8] == PNG_SIGNATURE
    # The six core targets, the roots speed, and each chapter topic's own (with its section in the report).
    assert len(tiny_run["verdicts"]) >= 7 + len(TOPICS)
    # Knot insertion and extraction are judged against SciPy, each on its own.
    knots = [v for v in tiny_run["verdicts"] if v.target.startswith("knot ")]
    assert [v.target.split()[1] for v in knots] == ["insertion", "extraction"]
    assert all(v.met is not None and "×" in v.measured for v in knots)
    for section in TOPICS:
        assert f"## {topic(section).TITLE}" in text
        assert tiny_run["results"][section], section


def test_every_ratio_is_finite_and_every_library_agrees_with_ours(tiny_run):
    measured = 0
    for section, case, m in _measurements(tiny_run):
        if m.seconds is None:  # a peer that is not installed
            assert "not installed" in m.note
            continue
        measured += 1
        assert math.isfinite(m.seconds) and m.seconds > 0
        assert m.ratio is not None and math.isfinite(m.ratio) and m.ratio > 0, (section, case.params, m.method)
        if section != "roots":  # for root finding the 'difference' is the error against the exact roots
            assert m.difference is not None and m.difference < 1e-9, (section, case.params, m.method)
    assert measured >= 12
    for case in tiny_run["results"]["roots"]:
        assert math.isfinite(case.extra["error ratio"])


def test_course_health_is_measured(tiny_run):
    (chapter,) = tiny_run["results"]["chapters"]
    assert chapter.notebook == "tiny.ipynb" and not chapter.error and chapter.seconds > 0
    (widget,) = tiny_run["results"]["widgets"]
    assert not widget.error and widget.control != "(no slider)"
    assert 0 < widget.compute and 0 < widget.render and 0 < widget.update
    assert tiny_run["results"]["grading"].seconds > 0


@pytest.mark.skipif(not peers.available("geomdl"), reason="geomdl is not installed")
def test_geomdl_beyond_its_cap_is_extrapolated_and_says_so(tiny_run):
    large = [c for c in tiny_run["results"]["bspline"] if c.params["values"] == 400]
    assert large and all(c.get("geomdl evaluate_list").extrapolated_from == 100 for c in large)
    assert "extrapolated from" in tiny_run["markdown"].read_text(encoding="utf-8")


def test_missing_peers_leave_empty_columns(tmp_path, monkeypatch):
    monkeypatch.setattr(peers, "available", lambda name: name == "scipy")
    plan = replace(tiny_plan(tmp_path), bezier_sizes=(50,), bspline_sizes=(50,))
    outcome = bench.run(plan, ("bezier", "bspline", "knots"), tmp_path / "results")
    bezier_case = outcome["results"]["bezier"][0]
    assert bezier_case.get("bezier evaluate_multi").seconds is None
    assert bezier_case.get("geomdl evaluate_list").note == "geomdl not installed"
    verdicts = {v.target.split()[0]: v for v in outcome["verdicts"]}
    assert verdicts["Bézier"].met is None
    assert "not installed" in outcome["markdown"].read_text(encoding="utf-8")


def test_the_command_line_runs_one_section(tmp_path, capsys):
    bench.main(["--quick", "--only", "roots", "--out", str(tmp_path)])
    assert "Verdict:" in capsys.readouterr().out
    assert (tmp_path / "benchmarks.md").is_file() and (tmp_path / "benchmarks.png").is_file()
    with pytest.raises(SystemExit):
        bench.main(["--only", "nonsense"])


def test_compare_interleaves_and_keeps_the_first_output():
    calls = []
    plan = replace(quick_plan(), repeats=3, min_sample=0.0, budget=10.0)
    timings = compare({"a": lambda: calls.append("a") or 1, "b": lambda: calls.append("b") or 2}, plan)
    assert timings["a"].output == 1 and timings["b"].output == 2
    assert timings["a"].samples == 3 and calls == ["a", "b"] + ["a", "b"] * 2


def test_wilkinson_coefficients_and_the_root_error():
    power, bernstein, exact = wilkinson(4)
    np.testing.assert_allclose(np.polynomial.polynomial.polyval(exact, power), 0, atol=1e-15)
    np.testing.assert_allclose(exact, [0.2, 0.4, 0.6, 0.8])
    assert bernstein[0] == pytest.approx(np.prod(-exact)) and bernstein[-1] == pytest.approx(np.prod(1 - exact))
    assert root_error([0.8, 0.2, 0.4, 0.6 + 1e-3j], exact) == pytest.approx(1e-3)
    assert root_error([0.2, 0.8], exact) == pytest.approx(0.2)
