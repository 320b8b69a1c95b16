"""`cagd validate --mutants`: prove that each hidden suite notices a small wrong change in the reference.

A *mutant* is the reference implementation with one small change, of the kind a
student's slip makes: an arithmetic operator swapped (``+`` ↔ ``-``, ``*`` ↔ ``/``),
a comparison loosened or flipped (``<`` ↔ ``<=``, ``==`` ↔ ``!=``), an integer off
by one, ``min`` ↔ ``max`` (also ``floor``/``ceil``, ``any``/``all``, ``argmin``/
``argmax``), ``abs`` or a unary minus or ``not`` dropped, ``and`` ↔ ``or``, or a
``raise`` turned into ``pass``. Mutants are made in every function of ``cagd_ref``
that the graded function reaches (its own body, its helpers, the input checks it
calls), one site at a time, by swapping the function's code object: every caller
sees the change, whatever name it imported the function under.

Each mutant plays the student: it runs the exercise's cases in a child process
(with a time budget and a memory cap) and the answers are judged in this process
by the suite's own comparison, exactly as a submission's are. A mutant is
*caught* when it scores less than full marks. A surviving mutant either shows a
gap in the suite (add a case) or computes the same thing by another route
(equivalent); equivalent ones are listed, each with a one-line reason, in
``tests/hidden/mutants/chNN.toml``, and the run checks that every listed mutant
still exists and still survives.
"""

from __future__ import annotations

import ast
import copy
import inspect
import json
import os
import resource
import signal
import sys
import textwrap
import time
import types
from collections import Counter
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field
from pathlib import Path

import tomllib
from tqdm import tqdm

from ..manifest import Course, load_course
from .engine import Prepared, _judge, load_exercises, prepare, score
from .worker import decode, encode, error_record

__all__ = [
    "Mutant",
    "MutationReport",
    "mutants_of",
    "run_mutants",
    "accepted_file",
    "format_mutation_reports",
]

PACKAGE = "cagd_ref"
# Seconds a mutant may take beyond the reference's own time on the same cases (a mutant that loops is caught).
TIME_FLOOR = 3.0
TIME_FACTOR = 20.0
MEMORY_MB = 2048

_BINARY_SWAPS = {
    ast.Add: ast.Sub,
    ast.Sub: ast.Add,
    ast.Mult: ast.Div,
    ast.Div: ast.Mult,
    ast.FloorDiv: ast.Div,
    ast.Pow: ast.Mult,
    ast.Mod: ast.FloorDiv,
}
_COMPARE_SWAPS = {
    ast.Lt: ast.LtE,
    ast.LtE: ast.Lt,
    ast.Gt: ast.GtE,
    ast.GtE: ast.Gt,
    ast.Eq: ast.NotEq,
    ast.NotEq: ast.Eq,
    ast.Is: ast.IsNot,
    ast.IsNot: ast.Is,
    ast.In: ast.NotIn,
    ast.NotIn: ast.In,
}
_NAME_SWAPS = {
    "min": "max",
    "max": "min",
    "amin": "amax",
    "amax": "amin",
    "nanmin": "nanmax",
    "nanmax": "nanmin",
    "minimum": "maximum",
    "maximum": "minimum",
    "argmin": "argmax",
    "argmax": "argmin",
    "floor": "ceil",
    "ceil": "floor",
    "any": "all",
    "all": "any",
}
_ABS = {"abs", "fabs", "absolute"}
_SYMBOLS = {
    ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.FloorDiv: "//", ast.Pow: "**", ast.Mod: "%",
    ast.Lt: "<", ast.LtE: "<=", ast.Gt: ">", ast.GtE: ">=", ast.Eq: "==", ast.NotEq: "!=",
    ast.Is: "is", ast.IsNot: "is not", ast.In: "in", ast.NotIn: "not in", ast.And: "and", ast.Or: "or",
}


@dataclass(frozen=True)
class Mutant:
    """One small change in one function: `key` names it stably (function, change, occurrence)."""

    module: str
    qualname: str
    site: int  # index of the changed node in `ast.walk` order of the function's tree
    change: str  # e.g. "`a < b` -> `a <= b`"
    occurrence: int  # the same change text earlier in the same function

    @property
    def key(self) -> str:
        number = f" #{self.occurrence + 1}" if self.occurrence else ""
        return f"{self.module.removeprefix(PACKAGE + '.')}.{self.qualname}: {self.change}{number}"


# --- which functions a graded function reaches ---


def _unwrap(obj):
    while hasattr(obj, "__wrapped__"):
        obj = obj.__wrapped__
    return obj


def _ours(obj) -> bool:
    module = getattr(obj, "__module__", "") or ""
    return module == PACKAGE or module.startswith(PACKAGE + ".")


def _code_names(code: types.CodeType) -> set[str]:
    names = set(code.co_names)
    for const in code.co_consts:
        if isinstance(const, types.CodeType):
            names |= _code_names(const)
    return names


def _members(obj) -> list:
    """The plain functions a reachable name stands for: a function, a class's methods, a module's functions."""
    obj = _unwrap(obj)
    if isinstance(obj, types.FunctionType):
        return [obj] if _ours(obj) else []
    if isinstance(obj, type) and _ours(obj):
        found = []
        for value in vars(obj).values():
            if isinstance(value, (staticmethod, classmethod)):
                value = value.__func__
            if isinstance(value, property):
                found += [value.fget] if value.fget is not None else []
                continue
            value = _unwrap(value)
            if isinstance(value, types.FunctionType) and value.__qualname__.startswith(obj.__qualname__ + "."):
                found.append(value)
        return found
    return []


def reached_functions(function) -> list:
    """Every function of `cagd_ref` that `function` may call, itself first (found through the names its code uses)."""
    start = _unwrap(function)
    seen, order, todo = set(), [], [start]
    while todo:
        current = todo.pop()
        if current in seen or not _ours(current):
            continue
        seen.add(current)
        order.append(current)
        scope = current.__globals__
        for name in sorted(_code_names(current.__code__)):
            candidates = []
            if name in scope:
                candidates.append(scope[name])
            for value in list(scope.values()):
                # `module.function` and `Class.method`: the attribute's name is in co_names too.
                if isinstance(value, types.ModuleType) and _ours(value) and hasattr(value, name):
                    candidates.append(getattr(value, name))
            for candidate in candidates:
                todo.extend(f for f in _members(candidate) if f not in seen)
    return sorted(order, key=lambda f: (f is not start, f.__module__, f.__qualname__))


# --- making mutants ---


def _function_tree(function) -> ast.FunctionDef:
    source = textwrap.dedent(inspect.getsource(function))
    tree = ast.parse(source).body[0]
    if not isinstance(tree, (ast.FunctionDef, ast.AsyncFunctionDef)):
        raise TypeError(f"{function.__qualname__} is not defined by a def statement")
    return tree


def _skipped_nodes(tree: ast.FunctionDef) -> set[int]:
    """Nodes not to mutate: the signature (defaults, annotations), decorators and the docstring."""
    skip = set()
    parts = [tree.args, *tree.decorator_list]
    if tree.returns is not None:
        parts.append(tree.returns)
    body = tree.body
    if body and isinstance(body[0], ast.Expr) and isinstance(getattr(body[0], "value", None), ast.Constant):
        if isinstance(body[0].value.value, str):
            parts.append(body[0])
    for node in ast.walk(tree):
        if isinstance(node, (ast.AnnAssign, ast.arg)) and getattr(node, "annotation", None) is not None:
            parts.append(node.annotation)
        if isinstance(node, ast.JoinedStr):
            parts.append(node)  # an error message's wording: never graded
    for part in parts:
        skip |= {id(n) for n in ast.walk(part)}
    return skip


def _called_name(node: ast.Call) -> str | None:
    if isinstance(node.func, ast.Name):
        return node.func.id
    if isinstance(node.func, ast.Attribute):
        return node.func.attr
    return None


def _segment(node) -> str:
    text = ast.unparse(node)
    return text if len(text) <= 60 else text[:57] + "..."


def _changes(node) -> list[tuple[str, str]]:
    """(kind, description) of each mutation possible at one node."""
    found = []
    if isinstance(node, (ast.BinOp, ast.AugAssign)) and type(node.op) in _BINARY_SWAPS:
        found.append(("binop", f"{_SYMBOLS[type(node.op)]} -> {_SYMBOLS[_BINARY_SWAPS[type(node.op)]]}"))
    elif isinstance(node, ast.Compare):
        for i, op in enumerate(node.ops):
            if type(op) in _COMPARE_SWAPS:
                found.append((f"compare{i}", f"{_SYMBOLS[type(op)]} -> {_SYMBOLS[_COMPARE_SWAPS[type(op)]]}"))
    elif isinstance(node, ast.Constant) and type(node.value) is int:
        found += [("plus1", f"{node.value} -> {node.value + 1}"), ("minus1", f"{node.value} -> {node.value - 1}")]
    elif isinstance(node, ast.BoolOp):
        found.append(("boolop", "and -> or" if isinstance(node.op, ast.And) else "or -> and"))
    elif isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.Not, ast.USub)):
        found.append(("unary", "drop `not`" if isinstance(node.op, ast.Not) else "drop unary minus"))
    elif isinstance(node, ast.Call):
        name = _called_name(node)
        if name in _NAME_SWAPS:
            found.append(("swapname", f"{name} -> {_NAME_SWAPS[name]}"))
        elif name in _ABS and len(node.args) == 1 and not node.keywords:
            found.append(("dropcall", f"drop {name}()"))
    elif isinstance(node, ast.Raise):
        found.append(("raise", "raise -> pass"))
    return found


def _sites(tree: ast.FunctionDef) -> list[tuple[int, str, str]]:
    """(walk index, kind, description) of every mutation of a function's tree."""
    skip = _skipped_nodes(tree)
    return [
        (index, kind, f"`{_segment(node)}`: {text}")
        for index, node in enumerate(ast.walk(tree))
        if id(node) not in skip
        for kind, text in _changes(node)
    ]


def mutants_of(function) -> list[Mutant]:
    """The mutants of every function `function` reaches, in a stable order."""
    made = []
    for reached in reached_functions(function):
        if reached.__code__.co_freevars:
            continue  # its code cannot be swapped on its own (a closure)
        try:
            tree = _function_tree(reached)
        except (OSError, TypeError, SyntaxError):
            continue
        seen = Counter()
        for index, kind, text in _sites(tree):
            change = f"{text} ({kind})" if kind.startswith("compare") and text.count("`") > 2 else text
            made.append(Mutant(reached.__module__, reached.__qualname__, index * 100 + _kind_rank(kind), change,
                               seen[change]))
            seen[change] += 1
    return made


_KINDS = ("binop", "plus1", "minus1", "boolop", "unary", "swapname", "dropcall", "raise")


def _kind_rank(kind: str) -> int:
    return 50 + int(kind[7:]) if kind.startswith("compare") else _KINDS.index(kind)


def _mutated_tree(tree: ast.FunctionDef, site: int) -> ast.FunctionDef:
    tree = copy.deepcopy(tree)
    index, rank = divmod(site, 100)
    parents = {id(child): parent for parent in ast.walk(tree) for child in ast.iter_child_nodes(parent)}
    node = list(ast.walk(tree))[index]
    kind = f"compare{rank - 50}" if rank >= 50 else _KINDS[rank]
    if kind == "binop":
        node.op = _BINARY_SWAPS[type(node.op)]()
    elif kind.startswith("compare"):
        i = int(kind[7:])
        node.ops[i] = _COMPARE_SWAPS[type(node.ops[i])]()
    elif kind in ("plus1", "minus1"):
        node.value += 1 if kind == "plus1" else -1
    elif kind == "boolop":
        node.op = ast.Or() if isinstance(node.op, ast.And) else ast.And()
    elif kind == "unary":
        _replace(parents[id(node)], node, node.operand)
    elif kind == "swapname":
        if isinstance(node.func, ast.Name):
            node.func.id = _NAME_SWAPS[node.func.id]
        else:
            node.func.attr = _NAME_SWAPS[node.func.attr]
    elif kind == "dropcall":
        _replace(parents[id(node)], node, node.args[0])
    elif kind == "raise":
        _replace(parents[id(node)], node, ast.Pass())
    tree.decorator_list = []
    return ast.fix_missing_locations(tree)


def _replace(parent, old, new) -> None:
    for name, value in ast.iter_fields(parent):
        if value is old:
            setattr(parent, name, new)
            return
        if isinstance(value, list) and any(v is old for v in value):
            value[[i for i, v in enumerate(value) if v is old][0]] = new
            return
    raise ValueError("node not found under its parent")


def _lookup(module_name: str, qualname: str):
    obj = sys.modules[module_name]
    for part in qualname.split("."):
        obj = vars(obj)[part] if isinstance(obj, type) else getattr(obj, part)
        if isinstance(obj, (staticmethod, classmethod)):
            obj = obj.__func__
        if isinstance(obj, property):
            obj = obj.fget  # a setter has the getter's qualified name; only getters are mutated
    return _unwrap(obj)


def _mutated_code(function, mutant: Mutant) -> types.CodeType:
    import __future__

    tree = _mutated_tree(_function_tree(function), mutant.site)
    module = ast.Module(body=[tree], type_ignores=[])
    ast.increment_lineno(module, function.__code__.co_firstlineno - 1)
    code = compile(module, inspect.getsourcefile(function) or "<mutant>", "exec",
                   flags=__future__.annotations.compiler_flag, dont_inherit=True)
    namespace = dict(function.__globals__)
    exec(code, namespace)
    made = namespace[tree.name]
    return made.__code__


# --- running mutants (child processes) ---


class _OutOfTime(BaseException):
    """Raised by the alarm inside a mutant that runs past its budget."""


def _alarm(signum, frame):
    raise _OutOfTime


def _clear_caches() -> None:
    for name, module in list(sys.modules.items()):
        if name == PACKAGE or name.startswith(PACKAGE + "."):
            for value in list(vars(module).values()):
                if callable(getattr(value, "cache_clear", None)):
                    value.cache_clear()


def _run_cases(function, cases: list[dict], budget: float) -> tuple[list[dict], str]:
    """Each case's event as the worker would send it; stops at the first case past the time budget."""
    events = []
    signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, budget)
    try:
        for case in cases:
            args, kwargs = decode(case["args"]), decode(case["kwargs"])
            try:
                event = {"value": encode(function(*args, **kwargs))}
            except _OutOfTime:
                raise
            except BaseException as err:  # noqa: BLE001 - a mutant's crash is that case's answer
                event = {"raised": error_record(err)}
            after = encode(list(args))
            if after != case["args"]:
                event["args_after"] = after
            events.append(event)
    except _OutOfTime:
        return events, f"stopped after {budget:.1f} s"
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
    return events, ""


def _child_setup() -> None:
    limit = MEMORY_MB * 1024 * 1024
    try:
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    except (ValueError, OSError):
        pass
    import warnings

    import numpy as np

    warnings.simplefilter("ignore")
    np.seterr(all="ignore")


def _run_exercise(module_name: str, qualname: str, cases_json: str, mutants: list[Mutant]) -> dict:
    """In a child: the reference's events and time, then each mutant's events."""
    import importlib

    importlib.import_module(module_name)
    function = _lookup(module_name, qualname)
    cases = json.loads(cases_json)
    start = time.perf_counter()
    reference, stopped = _run_cases(function, cases, 600.0)
    budget = TIME_FLOOR + TIME_FACTOR * (time.perf_counter() - start)
    results = {"reference": reference, "reference_stopped": stopped, "mutants": {}}
    for mutant in mutants:
        try:
            importlib.import_module(mutant.module)
            target = _lookup(mutant.module, mutant.qualname)
            original = target.__code__
            target.__code__ = _mutated_code(target, mutant)
        except Exception as err:  # noqa: BLE001 - a change that cannot even be built counts as caught
            results["mutants"][mutant.key] = {"invalid": f"{type(err).__name__}: {err}"}
            continue
        _clear_caches()
        try:
            events, stopped = _run_cases(function, cases, budget)
        except MemoryError:
            events, stopped = [], "ran out of memory"
        finally:
            target.__code__ = original
            _clear_caches()
        results["mutants"][mutant.key] = {"events": events, "stopped": stopped}
    return results


# --- the report ---


@dataclass
class MutationReport:
    """One exercise: how many mutants were made, caught, accepted as equivalent, and the survivors' keys."""

    exercise: str
    mutants: int = 0
    caught: int = 0
    accepted: int = 0
    survivors: list[str] = field(default_factory=list)
    stale: list[str] = field(default_factory=list)  # accepted entries that no longer exist or now get caught
    problems: list[str] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not (self.survivors or self.stale or self.problems)

    @property
    def caught_share(self) -> float:
        judged = self.mutants - self.accepted
        return self.caught / judged if judged else 1.0


# The file of mutants equivalent for every exercise (in shared helpers: an error message's length, say),
# next to the chapters' files; its entries name the exercise "*".
COMMON = "common"


def accepted_file(hidden_suite: Path) -> Path:
    """The list of accepted equivalent mutants that goes with a hidden suite."""
    return hidden_suite.parent / "mutants" / f"{hidden_suite.stem}.toml"


def _accepted(path: Path) -> dict[str, dict[str, str]]:
    """{exercise: {mutant key: reason}} from a chapter's file (missing file: nothing accepted)."""
    if not path.is_file():
        return {}
    with path.open("rb") as handle:
        data = tomllib.load(handle)
    accepted: dict[str, dict[str, str]] = {}
    for entry in data.get("accepted", []):
        missing = {"exercise", "mutant", "reason"} - set(entry)
        if missing or not str(entry.get("reason", "")).strip():
            raise ValueError(f"{path}: every [[accepted]] entry needs exercise, mutant and a reason; got {entry}")
        accepted.setdefault(entry["exercise"], {})[entry["mutant"]] = entry["reason"]
    return accepted


def _caught(item: Prepared, outcome: dict) -> bool:
    events, stopped = outcome.get("events", []), outcome.get("stopped", "")
    compare = item.exercise.comparison()
    cases = [
        _judge(item, index, events[index] if index < len(events) else None, stopped, compare)
        for index in range(len(item.cases))
    ]
    return score(cases, item.points) < item.points


def _verdicts(item: Prepared, results: dict) -> tuple[bool, dict[str, bool]]:
    """Whether the reference scored full marks in the child, and for each mutant whether the suite caught it."""
    reference_ok = results["reference"] is None or not _caught(
        item, {"events": results["reference"], "stopped": results["reference_stopped"]}
    )
    return reference_ok, {
        key: "invalid" in outcome or _caught(item, outcome) for key, outcome in results["mutants"].items()
    }


def _report(exercise: str, mutants: list[Mutant], caught: dict[str, bool], reference_ok: bool,
            accepted: dict[str, str], everywhere: dict[str, str]) -> MutationReport:
    """`accepted`: this exercise's equivalent mutants; `everywhere`: those equivalent for every exercise."""
    report = MutationReport(exercise, mutants=len(mutants))
    if not reference_ok:
        report.problems.append("the unchanged reference does not score full marks in the mutation harness")
        return report
    keys = {m.key for m in mutants}
    for mutant in mutants:
        listed = mutant.key in accepted or mutant.key in everywhere
        if caught.get(mutant.key, True):  # a mutant that never reported back crashed its process: caught
            report.caught += 1
            if listed:
                report.stale.append(f"{mutant.key} (listed as equivalent, but the suite now catches it)")
        elif listed:
            report.accepted += 1
        else:
            report.survivors.append(mutant.key)
    report.stale += [f"{key} (listed as equivalent, no such mutant)" for key in accepted if key not in keys]
    return report


# Mutants per child task: a task's answers are held until judged, so batches keep memory bounded.
BATCH = 25


def run_mutants(
    course: Course | None = None,
    ids: list[str] | None = None,
    seed: int = 0,
    workers: int | None = None,
    progress: bool = True,
) -> list[MutationReport]:
    """Make every mutant of the graded functions (all, or `ids`), grade each with its suite, report per exercise."""
    course = course or load_course()
    exercises = load_exercises(course, ids)
    prepared = prepare(exercises, seed)
    suites = [chapter.hidden for chapter in course.chapters if chapter.hidden is not None]
    accepted = {}
    for suite in suites:
        accepted.update(_accepted(accepted_file(suite)))
    everywhere = _accepted(accepted_file(suites[0]).with_name(f"{COMMON}.toml")).get("*", {}) if suites else {}
    made = {item.exercise.id: mutants_of(_unwrap(item.exercise.reference)) for item in prepared}
    caught: dict[str, dict[str, bool]] = {eid: {} for eid in made}
    reference_ok = dict.fromkeys(made, True)
    failures: dict[str, str] = {}
    workers = workers or os.cpu_count() or 1
    bar = tqdm(total=sum(map(len, made.values())), desc="grading mutants", unit="mutant",
               disable=None if progress else True)
    with ProcessPoolExecutor(max_workers=workers, initializer=_child_setup) as pool:
        futures = {}
        for item in prepared:
            reference = _unwrap(item.exercise.reference)
            cases = "[" + ",".join(item.sent) + "]"
            mutants = made[item.exercise.id]
            for start in range(0, max(len(mutants), 1), BATCH):
                batch = mutants[start:start + BATCH]
                future = pool.submit(_run_exercise, reference.__module__, reference.__qualname__, cases, batch)
                futures[future] = (item, batch)
        for future in as_completed(futures):
            item, batch = futures[future]
            try:
                results = future.result()
            except BrokenProcessPool:
                results = _one_by_one(item, batch)
            except Exception as err:  # noqa: BLE001 - the harness failed on this exercise: say so, go on
                failures.setdefault(item.exercise.id, f"the mutation harness failed: {type(err).__name__}: {err}")
                bar.update(len(batch))
                continue
            ok, verdicts = _verdicts(item, results)
            reference_ok[item.exercise.id] &= ok
            caught[item.exercise.id].update(verdicts)
            bar.update(len(batch))
    bar.close()
    reports = [
        _report(eid, made[eid], caught[eid], reference_ok[eid], accepted.get(eid, {}), everywhere) for eid in made
    ]
    if ids is None:
        made_anywhere = {m.key for mutants in made.values() for m in mutants}
        stale = [f"{key} (listed as equivalent everywhere, no such mutant)" for key in everywhere
                 if key not in made_anywhere]
        if stale and reports:
            reports[0].stale += stale
    for report in reports:
        if report.exercise in failures:
            report.problems.append(failures[report.exercise])
    return reports


def _one_by_one(item: Prepared, mutants: list[Mutant]) -> dict:
    """After a child died (a mutant crashed the interpreter): each mutant in a process of its own."""
    reference = _unwrap(item.exercise.reference)
    cases = "[" + ",".join(item.sent) + "]"
    merged = {"reference": None, "reference_stopped": "", "mutants": {}}
    for mutant in mutants:
        with ProcessPoolExecutor(max_workers=1, initializer=_child_setup) as pool:
            try:
                one = pool.submit(_run_exercise, reference.__module__, reference.__qualname__, cases, [mutant]).result()
            except BrokenProcessPool:
                continue  # never reports back: counted as caught
        merged["reference"], merged["reference_stopped"] = one["reference"], one["reference_stopped"]
        merged["mutants"].update(one["mutants"])
    return merged


def format_mutation_reports(reports: list[MutationReport], show: int = 20) -> str:
    """A table per exercise (mutants, caught, accepted, survivors, caught share), then survivors and stale entries."""
    lines = [f"{'exercise':32} {'mutants':>7} {'caught':>6} {'accepted':>8} {'survive':>7} {'caught %':>8}"]
    for r in reports:
        mark = "ok " if r.ok else "BAD"
        lines.append(f"{mark} {r.exercise:28} {r.mutants:7d} {r.caught:6d} {r.accepted:8d} {len(r.survivors):7d} "
                     f"{100 * r.caught_share:7.1f}%")
    total = Counter()
    for r in reports:
        total.update(mutants=r.mutants, caught=r.caught, accepted=r.accepted, survivors=len(r.survivors))
    judged = total["mutants"] - total["accepted"]
    share = 100 * total["caught"] / judged if judged else 100.0
    lines.append(f"{'all':32} {total['mutants']:7d} {total['caught']:6d} {total['accepted']:8d} "
                 f"{total['survivors']:7d} {share:7.1f}%")
    for r in reports:
        if r.ok:
            continue
        lines.append("")
        lines.append(f"{r.exercise}:")
        lines += [f"  problem: {p}" for p in r.problems]
        lines += [f"  stale: {s}" for s in r.stale]
        shown = r.survivors if show <= 0 else r.survivors[:show]
        lines += [f"  survives: {key}" for key in shown]
        if len(shown) < len(r.survivors):
            lines.append(f"  ... and {len(r.survivors) - len(shown)} more (--show 0 lists all)")
    return "\n".join(lines)


def survivors_toml(reports: list[MutationReport]) -> str:
    """The survivors as [[accepted]] entries with an empty reason, to fill in for those that are equivalent."""
    out = []
    for r in reports:
        for key in r.survivors:
            out.append(f'[[accepted]]\nexercise = "{r.exercise}"\nmutant = {json.dumps(key, ensure_ascii=False)}\n'
                       f'reason = ""\n')
    return "\n".join(out)

