"""The worked examples of the notes, kept once, as data: one TOML file per chapter (`chNN.toml`).

Unit tests, hidden suites, chapters and exercise notebooks all read the notes'
numbers from here, so a number is typed once and a correction made once. Each
table of a file is one example::

    [rotation]                          # the example's name: notes_example("01.rotation")
    section = "1.3"                     # where it stands in the notes
    summary = "P = (5, 7, 3) turned a quarter turn about the axis through (1, 1, 1) along (2, 1, 2)"
    [rotation.inputs]
    point = [5, 7, 3]
    angle = "pi/2"
    [rotation.results]                  # what the notes state, checked
    rotated = ["5/3", "13/3", "23/3"]
    [rotation.errata.some_value]        # only where the notes print a wrong value
    notes = 1.0
    correct = 2.0
    why = "one sentence saying what went wrong"

Numbers may be written exactly as strings of arithmetic with `pi` and `sqrt`
("5/3", "sqrt(155)/2"); lists of numbers become float arrays. Other strings
stay strings.
"""

from __future__ import annotations

import ast
import math
import operator
import sys
from dataclasses import dataclass, field
from functools import cache
from html import escape
from pathlib import Path

import numpy as np

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

__all__ = ["NotesExample", "Erratum", "notes_example", "notes_examples"]

FOLDER = Path(__file__).parent
_OPERATORS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
              ast.Pow: operator.pow, ast.USub: operator.neg, ast.UAdd: operator.pos}
_NAMES = {"pi": math.pi}
_FUNCTIONS = {"sqrt": math.sqrt}


@dataclass(frozen=True)
class Erratum:
    """A value the notes print wrongly: what they print, the corrected value, and why."""

    notes: object
    correct: object
    why: str


@dataclass(frozen=True)
class NotesExample:
    """One worked example of the notes: where it is, its inputs, its stated results, its errata."""

    id: str
    section: str
    summary: str
    inputs: dict = field(default_factory=dict)
    results: dict = field(default_factory=dict)
    errata: dict = field(default_factory=dict)

    def args(self, *names: str) -> tuple:
        """The inputs `names`, in that order, as a tuple of fresh copies (ready to pass to a function)."""
        missing = [name for name in names if name not in self.inputs]
        if missing:
            raise KeyError(f"{self.id} has no inputs {missing}; it has {sorted(self.inputs)}")
        return tuple(np.copy(self.inputs[name]) if isinstance(self.inputs[name], np.ndarray) else self.inputs[name]
                     for name in names)

    def _rows(self) -> list[tuple[str, str, str]]:
        rows = [("input", k, v) for k, v in self.inputs.items()] + [("result", k, v) for k, v in self.results.items()]
        return [(kind, name, _shown(value)) for kind, name, value in rows]

    def _repr_markdown_(self) -> str:
        """How a notebook shows the example: where it is, what goes in, what the notes state, what they got wrong."""
        lines = [f"**Notes §{self.section}**: {self.summary}", ""]
        rows = self._rows()
        if rows:
            lines += ["| | name | value |", "|---|---|---|"]
            lines += [f"| {kind} | `{name}` | `{value}` |" for kind, name, value in rows]
        for name, erratum in self.errata.items():
            lines += ["", f"*Erratum* `{name}`: the notes print `{_shown(erratum.notes)}`, "
                          f"the correct value is `{_shown(erratum.correct)}` ({erratum.why})."]
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        """The same as an HTML table: it renders alike in JupyterLab, the book and its PDF."""
        parts = [f"<p><strong>Notes §{escape(self.section)}</strong>: {escape(self.summary)}</p>"]
        rows = self._rows()
        if rows:
            body = "".join(
                f"<tr><td>{kind}</td><td><code>{escape(name)}</code></td><td><code>{escape(value)}</code></td></tr>"
                for kind, name, value in rows
            )
            parts.append(
                '<table class="cagd-example"><thead><tr><th></th><th>name</th><th>value</th></tr></thead>'
                f"<tbody>{body}</tbody></table>"
            )
        for name, erratum in self.errata.items():
            parts.append(
                f"<p><em>Erratum</em> <code>{escape(name)}</code>: the notes print "
                f"<code>{escape(_shown(erratum.notes))}</code>, the correct value is "
                f"<code>{escape(_shown(erratum.correct))}</code> ({escape(erratum.why)}).</p>"
            )
        return "\n".join(parts)


def _shown(value) -> str:
    """A value on one line: numbers to the six significant digits that matter (whole numbers without a
    decimal point, rounding noise below 1e-12 as 0), arrays and lists (ragged tables) item by item."""
    if isinstance(value, np.ndarray):
        return _shown(value.tolist()) if value.ndim else _shown(value.item())
    if isinstance(value, float):
        return f"{0.0 if abs(value) < 1e-12 else value:.6g}"
    if isinstance(value, list):
        return "[" + ", ".join(_shown(item) for item in value) + "]"
    return str(value)


def _arithmetic(node):
    if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) and not isinstance(node.value, bool):
        return node.value
    if isinstance(node, ast.Name) and node.id in _NAMES:
        return _NAMES[node.id]
    if isinstance(node, ast.BinOp) and type(node.op) in _OPERATORS:
        return _OPERATORS[type(node.op)](_arithmetic(node.left), _arithmetic(node.right))
    if isinstance(node, ast.UnaryOp) and type(node.op) in _OPERATORS:
        return _OPERATORS[type(node.op)](_arithmetic(node.operand))
    if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in _FUNCTIONS
            and len(node.args) == 1 and not node.keywords):
        return _FUNCTIONS[node.func.id](_arithmetic(node.args[0]))
    raise ValueError("not arithmetic")


def _number(text: str):
    """The value of an exact number written as a string ("5/3", "sqrt(2)/2", "-pi/4"), or the string itself."""
    try:
        return float(_arithmetic(ast.parse(text, mode="eval").body))
    except (SyntaxError, ValueError, ZeroDivisionError):
        return text


def _value(data):
    """TOML data -> course values: numbers, float arrays for lists of numbers, dicts, strings."""
    if isinstance(data, dict):
        return {key: _value(item) for key, item in data.items()}
    if isinstance(data, str):
        return _number(data)
    if isinstance(data, list):
        items = [_value(item) for item in data]
        try:
            array = np.array(items, dtype=float)
        except (TypeError, ValueError):
            return items
        return array
    return data


def _example(chapter: int, name: str, table: dict) -> NotesExample:
    known = {"section", "summary", "inputs", "results", "errata"}
    unknown = set(table) - known
    if unknown or "section" not in table:
        raise ValueError(
            f"ch{chapter:02d}.toml [{name}]: needs a section; allowed keys {sorted(known)}, got {sorted(table)}"
        )
    errata = {
        key: Erratum(_value(e["notes"]), _value(e["correct"]), e["why"]) for key, e in table.get("errata", {}).items()
    }
    return NotesExample(
        f"{chapter:02d}.{name}",
        str(table["section"]),
        table.get("summary", ""),
        _value(table.get("inputs", {})),
        _value(table.get("results", {})),
        errata,
    )


@cache
def _chapter(chapter: int) -> dict[str, NotesExample]:
    path = FOLDER / f"ch{chapter:02d}.toml"
    if not path.is_file():
        raise KeyError(f"chapter {chapter} keeps no worked examples (no {path.name})")
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    return {name: _example(chapter, name, table) for name, table in data.items()}


def notes_examples(chapter: int) -> dict[str, NotesExample]:
    """Every worked example of a chapter, by name, in the order of the file."""
    return dict(_chapter(int(chapter)))


def notes_example(example_id: str) -> NotesExample:
    """The worked example "NN.name" (e.g. "01.rotation")."""
    number, _, name = example_id.partition(".")
    examples = _chapter(int(number))
    if name not in examples:
        raise KeyError(f"no worked example {example_id!r}; chapter {int(number)} has {sorted(examples)}")
    return examples[name]
