"""The chapter benchmarks beyond the core sections: one module per topic, registered here by name.

A topic module defines `TITLE` (its heading in the report), `ABOUT` (one paragraph:
what is measured and against whom), `cases(plan)` -> list of `Case` and
`verdicts(cases)` -> list of `Verdict` (its targets, judged on one run). run.py
runs every topic as a section of its own, targets.py collects their verdicts and
report.py writes one table per topic, so a new chapter's benchmark is one module
and one line below.
"""

from __future__ import annotations

import importlib

from .common import Case, format_count

TOPICS = {
    "intersection": "benchmarks.intersection",
    "interpolation": "benchmarks.interpolation",
    "fitting": "benchmarks.approximation",
    "interval": "benchmarks.interval_bezier",
    "ffd": "benchmarks.ffd",
    "surfaces": "benchmarks.surfaces",
    "algebra": "benchmarks.algebra",
    "hybrid": "benchmarks.hybrid",
}


def topic(section: str):
    """The module measuring `section` (imported on first use: some pull in SciPy or the peers)."""
    return importlib.import_module(TOPICS[section])


def _value(value) -> str:
    return format_count(value) if isinstance(value, int) and value >= 1000 else str(value)


def table(cases: list[Case]) -> list[str]:
    """One table per kind of case (`Case.section`), in the order they came."""
    kinds = list(dict.fromkeys(case.section for case in cases))
    lines = []
    for kind in kinds:
        lines += ([""] if lines else []) + _kind_table([case for case in cases if case.section == kind])
    return lines


def _kind_table(cases: list[Case]) -> list[str]:
    """One row per case: its parameters, every method's best time (×ratio to ours) and difference, its extras."""
    from .report import _cell, _table

    params = list(dict.fromkeys(key for case in cases for key in case.params))
    methods = list(dict.fromkeys(m.method for case in cases for m in case.measurements))
    extras = list(dict.fromkeys(key for case in cases for key in case.extra))
    rows = []
    for case in cases:
        first = case.measurements[0].method if case.measurements else None
        cells = [_value(case.params.get(key, "")) for key in params]
        cells += [_cell(case.get(m), m != first) for m in methods]
        differences = [f"{m.difference:.1e}" for m in case.measurements[1:] if m.difference is not None]
        cells.append(", ".join(differences) or "—")
        cells += [f"{case.extra[k]:.3g}" if isinstance(case.extra.get(k), float) else str(case.extra.get(k, ""))
                  for k in extras]
        rows.append(cells)
    return _table(params + methods + ["max abs difference"] + extras, rows)
