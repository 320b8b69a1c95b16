"""Measure `cagd_ref` against bezier, geomdl, SciPy and NumPy, and the course's health, in one run.

    ./course bench                       # set up .venv with the bench extra, then the full run
    ./course bench --quick               # smoke run: small sizes, one chapter
    .venv/bin/python benchmarks/run.py --only bezier,roots --out /tmp/bench

Writes `benchmarks.md` (every number, the targets and their verdicts) and
`benchmarks.png` (the trends) to benchmarks/results/ or `--out`, printing a
line of progress per case on stderr and the verdict on stdout. The full run
takes five to ten minutes on a 2-core machine. A peer library that is not
installed leaves its column empty.
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import sys
import time
from pathlib import Path

if __package__ in (None, ""):
    # Run as a script: make the checkout, not this folder, the place imports start from.
    sys.path[0] = str(Path(__file__).resolve().parent.parent)

from benchmarks import peers  # noqa: E402
from benchmarks.common import RESULTS, Plan, full_plan, progress, quick_plan  # noqa: E402
from benchmarks.topics import TOPICS, topic  # noqa: E402

SECTIONS = ("bezier", "bspline", "knots", "roots", *TOPICS, "widgets", "grading", "chapters")


def _runner(section: str):
    """The function that measures one section (imported late: the health checks pull in the widgets)."""
    if section == "bezier":
        from benchmarks.evaluation import bezier_cases
        return bezier_cases
    if section == "bspline":
        from benchmarks.evaluation import bspline_cases
        return bspline_cases
    if section == "knots":
        from benchmarks.knots import knot_cases
        return knot_cases
    if section == "roots":
        from benchmarks.rootfinding import root_cases
        return root_cases
    if section in TOPICS:
        return topic(section).cases
    from benchmarks import health
    return {"widgets": health.widget_timings, "grading": health.grading_timing, "chapters": health.chapter_timings}[
        section
    ]


def _machine() -> str:
    model = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return (
        f"{model}, {os.cpu_count()} CPUs, {platform.system()} {platform.release()}, Python {platform.python_version()}"
    )


def _load() -> str:
    try:
        return f"{os.getloadavg()[0]:.2f}"
    except OSError:
        return "unknown"


def run(
    plan: Plan, sections: tuple[str, ...] = SECTIONS, out: Path = RESULTS, command: str = "benchmarks/run.py"
) -> dict:
    """Measure the chosen sections with `plan`, write benchmarks.md and benchmarks.png to `out`.

    Returns {"results": per-section results, "verdicts": [...], "markdown": Path, "figure": Path}.
    """
    import matplotlib

    matplotlib.use("Agg")
    from benchmarks.report import figure, markdown
    from benchmarks.targets import verdict_line, verdicts

    started, load_before = time.perf_counter(), _load()
    progress(
        f"benchmarks: {plan.name} run of {', '.join(sections)}; peers: "
        + ", ".join(f"{name} {peers.version(name)}" for name in peers.PEERS)
    )
    results = {}
    for section in sections:
        progress(f"--- {section}")
        results[section] = _runner(section)(plan)
    found = verdicts(results)
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    figure_path, markdown_path = out / "benchmarks.png", out / "benchmarks.md"
    figure(results, found, figure_path)
    context = {
        "command": command,
        "plan": plan.name,
        "date": datetime.date.today().isoformat(),
        "minutes": (time.perf_counter() - started) / 60,
        "machine": _machine(),
        "load_before": load_before,
        "load_after": _load(),
        "versions": ", ".join(f"{name} {peers.version(name)}" for name in ("numpy",) + peers.PEERS + ("matplotlib",)),
        "geomdl_max": plan.geomdl_max_points,
        "figure": figure_path.name,
    }
    markdown_path.write_text(markdown(results, found, context), encoding="utf-8")
    progress(f"benchmarks: wrote {markdown_path} and {figure_path} in {context['minutes']:.1f} min")
    print(f"Verdict: {verdict_line(found)}.")
    return {"results": results, "verdicts": found, "markdown": markdown_path, "figure": figure_path}


def main(argv: list[str] | None = None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small sizes and one chapter: a smoke run")
    parser.add_argument(
        "--only",
        default=",".join(SECTIONS),
        help=f"comma-separated sections to run (default all: {','.join(SECTIONS)})",
    )
    parser.add_argument(
        "--out", type=Path, default=RESULTS, help=f"folder for the report and figure (default {RESULTS})"
    )
    args = parser.parse_args(argv)
    sections = tuple(s.strip() for s in args.only.split(",") if s.strip())
    unknown = sorted(set(sections) - set(SECTIONS))
    if unknown:
        parser.error(f"unknown section(s) {', '.join(unknown)}; choose from {', '.join(SECTIONS)}")
    plan = quick_plan() if args.quick else full_plan()
    command = "benchmarks/run.py" + (" " + " ".join(argv if argv is not None else sys.argv[1:])).rstrip()
    return run(plan, sections, args.out, command)


if __name__ == "__main__":
    main()
