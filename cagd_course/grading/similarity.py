"""Graded functions that are the same code: after renaming every name and dropping docstrings and formatting.

A function's *fingerprint* is a hash of its syntax tree with each identifier replaced by its order
of first appearance (builtins keep their names), every string (messages) made empty, docstrings,
annotations and comments gone. Two
students whose graded function has the same fingerprint wrote, or copied, the same code; so did a
student whose fingerprint is the reference implementation's. The class report lists such pairs
for a person to look at: it is a flag, never a verdict. Stubs (the untouched exercise) and tiny
functions, which honest students write alike, are left out.
"""

from __future__ import annotations

import ast
import builtins
import hashlib
import inspect
import textwrap

__all__ = ["fingerprint", "function_fingerprints", "flag_pairs", "MIN_NODES"]

# Functions smaller than this (syntax-tree nodes) are too short to tell copying from agreement.
MIN_NODES = 40
_BUILTINS = frozenset(dir(builtins))


class _Canonical(ast.NodeTransformer):
    def __init__(self):
        self.names: dict[str, str] = {}

    def _rename(self, name: str) -> str:
        if name in _BUILTINS:
            return name
        return self.names.setdefault(name, f"n{len(self.names)}")

    def _strip_docstring(self, node):
        body = getattr(node, "body", None)
        if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
            if isinstance(body[0].value.value, str):
                node.body = body[1:] or [ast.Pass()]

    def visit_FunctionDef(self, node):
        self._strip_docstring(node)
        node.name = self._rename(node.name)
        node.returns = None
        node.decorator_list = [self.visit(d) for d in node.decorator_list]
        self.generic_visit(node)
        return node

    visit_AsyncFunctionDef = visit_FunctionDef

    def visit_ClassDef(self, node):
        self._strip_docstring(node)
        node.name = self._rename(node.name)
        self.generic_visit(node)
        return node

    def visit_arg(self, node):
        node.arg = self._rename(node.arg)
        node.annotation = None
        return node

    def visit_Name(self, node):
        node.id = self._rename(node.id)
        return node

    def visit_alias(self, node):
        node.asname = self._rename(node.asname or node.name.partition(".")[0])
        return node

    def visit_AnnAssign(self, node):
        if node.value is None:
            return None
        return ast.copy_location(ast.Assign(targets=[self.visit(node.target)], value=self.visit(node.value)), node)

    def visit_Constant(self, node):
        # Messages and docstrings are the first thing a copier rewords: every string counts as the same.
        return ast.copy_location(ast.Constant(""), node) if isinstance(node.value, str) else node

    def visit_JoinedStr(self, node):
        return ast.copy_location(ast.Constant(""), node)

    def visit_Global(self, node):
        node.names = [self._rename(n) for n in node.names]
        return node

    visit_Nonlocal = visit_Global


def fingerprint(node: ast.AST) -> tuple[str, int]:
    """(hash, size in nodes) of a function or class definition, independent of names and formatting."""
    tree = _Canonical().visit(ast.parse(ast.unparse(node)).body[0])
    text = ast.dump(tree, annotate_fields=False, include_attributes=False)
    return hashlib.sha256(text.encode()).hexdigest()[:20], sum(1 for _ in ast.walk(tree))


def function_fingerprints(statements: list[dict], names: dict[str, str]) -> dict[str, list]:
    """Fingerprints of the graded functions in a submission's statements: {exercise id: [hash, nodes]}.

    `names` maps each graded function's name to its exercise id; the last definition wins, as
    when the cells run top to bottom.
    """
    found = {}
    for statement in statements:
        try:
            body = ast.parse(statement["source"]).body
        except SyntaxError:
            continue
        for node in body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and node.name in names:
                found[names[node.name]] = list(fingerprint(node))
    return found


def source_fingerprint(function) -> tuple[str, int] | None:
    """The fingerprint of a Python function's own source (the reference's), if it can be read."""
    try:
        source = textwrap.dedent(inspect.getsource(function))
        node = ast.parse(source).body[0]
    except (OSError, TypeError, SyntaxError, IndexError):
        return None
    return fingerprint(node)


def flag_pairs(records: list[dict], reference: dict[str, str], ignore: dict[str, set[str]]) -> list[dict]:
    """Submissions of one chapter sharing graded functions, and submissions equal to the reference.

    records: gradebook records (with their ``fingerprints``); reference: {exercise id: hash};
    ignore: {exercise id: hashes never flagged (the stub)}. Each flag: chapter, the two names (the
    second "reference implementation" for the reference), and the exercise ids that are identical.

    Fingerprints are hashed into buckets, one per exercise and hash, and only submissions in one
    bucket are compared: the work grows with the class, not with its square. Each bucket is told
    as its first member (by name) paired with each other member, so a group of k identical
    functions gives k - 1 flags, not k(k - 1)/2; every member of a group is flagged with its first.
    """
    flags = []
    # (chapter, first, second) -> exercise ids, filled bucket by bucket
    pairs: dict[tuple[int, str, str], list[str]] = {}
    buckets: dict[tuple[int, str, str], list[str]] = {}
    for record in records:
        chapter, name = record["chapter"], record["submission"]
        for eid, (h, size) in record.get("fingerprints", {}).items():
            if size < MIN_NODES or h in ignore.get(eid, set()):
                continue
            buckets.setdefault((chapter, eid, h), []).append(name)
            if reference.get(eid) == h:
                pairs.setdefault((chapter, name, ""), []).append(eid)
    for (chapter, eid, _), members in buckets.items():
        if len(members) < 2:
            continue
        first, *others = sorted(set(members))
        for other in others:
            pairs.setdefault((chapter, first, other), []).append(eid)
    for (chapter, first, second), exercises in sorted(pairs.items(), key=lambda kv: (kv[0][0], kv[0][2] == "",
                                                                                      kv[0][1], kv[0][2])):
        flags.append({"chapter": chapter, "first": first, "second": second or "reference implementation",
                      "exercises": sorted(exercises)})
    return flags
