"""One walk of a worked answer, for every write-up format (Markdown, LaTeX, HTML).

`walk` visits a solved problem once, in the order every format shows it (title,
notes, Given, the sections and their steps, the checks, the answers, the
warnings), and a format's `Writer` turns each part into its lines. What the
formats share is here too: the file's keys written as words (`Keys`), a step's
typeset pieces, the chapter's equation number a step cites, an answer's symbol,
and the width of a typeset formula with the one routine that breaks a wide one
into rows (`pack`).

Rendering is re-entrant: everything a render needs travels with its writer (no
module state), so threads may render at once.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from typing import Any, TypeVar

from ..core import expr as E
from ..core import prose as P
from ..core.work import num
from .conventions import unit_spelling
from .mathprint import (
    formula_node,
    grouped,
    is_list,
    is_quantity,
    op_of,
    quantity_node,
    quantity_unit,
    quantity_value,
    shown_name,
    sign_of,
    sin_power,
    substitution_node,
    symbol_node,
)

#: a tree as `mathprint.Lowering` sets it: core nodes
Node = E.Expr

__all__ = ["Keys", "Writer", "walk", "step_pieces", "equation_tag", "answer_symbol",
           "answer_lhs", "width", "pack", "unbracketed"]

#: a line ending in the chapter's equation number: "udot^2 = f(u) = ...    (Eq. 11.19)"
_EQ = re.compile(r"^Eq\. (\d+\.\d+)(?:, (.+))?$")

_T = TypeVar("_T")


# ---- the file's keys in prose -------------------------------------------------

class Keys:
    """The given and answer names of a kind that are words, not symbols (psi_rate,
    bearing_forces, engine_sense): in prose they are written as words, "psi rate"."""

    def __init__(self, pattern: re.Pattern[str] | None = None) -> None:
        self.pattern = pattern

    @classmethod
    def of(cls, kind: Any) -> Keys:
        return cls(file_keys(kind))

    def split(self, text: str) -> list[tuple[bool, str]]:
        """``text`` as (is_key, piece): a key comes out as words, ``psi rate``."""
        pattern = self.pattern
        if pattern is None or not pattern.search(text):
            return [(False, text)]
        out, pos = [], 0
        for m in pattern.finditer(text):
            out += [(False, text[pos:m.start()]), (True, m.group().replace("_", " "))]
            pos = m.end()
        return out + [(False, text[pos:])]

    def words(self, text: str, escape: Callable[[str], str]) -> str:
        """Words escaped, a key of the file as words."""
        return "".join(escape(piece) for _, piece in self.split(text))


NO_KEYS = Keys()


def file_keys(kind: Any) -> re.Pattern[str] | None:
    """A pattern matching the kind's given and answer names that are words, not symbols."""
    from ..core.body import BODY_PARAMS

    params = list(kind.params) + (list(BODY_PARAMS) if kind.uses_body else [])
    names = {p.name for p in params} | {a.name for a in kind.answers}
    symbols = {p.symbol for p in params} | {a.symbol for a in kind.answers}
    words = {p.name for p in params if p.dimension == "word"}  # engine_sense
    keys = sorted((n for n in names if "_" in n and (n not in symbols or n in words)),
                  key=len, reverse=True)
    if not keys:
        return None
    return re.compile(r"(?<![\w.])(" + "|".join(map(re.escape, keys)) + r")(?!\w)")


# ---- what every format shows of a step and an answer ------------------------------

def step_pieces(step: Any) -> tuple[Node, list[Node]]:
    """A step's symbol and the right-hand sides it shows: its formula and substitution
    (typeset from its tree, nothing parsed) and its value."""
    lhs = symbol_node(step.symbol, getattr(step, "symbol_expr", None)) or P.Words(step.symbol)
    pieces: list[Node] = []
    tree = getattr(step, "shown", None)
    if tree is not None:
        if step.formula:
            pieces.append(formula_node(tree))
        if step.substitution:
            pieces.append(substitution_node(tree))
    elif step.formula or step.substitution:  # Work.step takes a formula as a tree only
        raise TypeError(f"the step {step.symbol} has a formula but no tree")
    if step.value is not None:
        unit = unit_spelling(step.unit)
        pieces.append(quantity_node(num(step.value), unit))
    return lhs, pieces


def equation_tag(step: Any) -> tuple[str, str]:
    """The chapter's equation number a step cites, and the rest of its reference."""
    m = _EQ.match(step.ref or "")
    return (m.group(1), m.group(2) or "") if m else ("", step.ref or "")


def answer_symbol(answer: Any) -> Node | None:
    """An answer's symbol as set (its tree, or its one name)."""
    return symbol_node(answer.symbol, getattr(answer, "symbol_expr", None))


def answer_lhs(answer: Any) -> Node | None:
    """The symbol set as ``symbol = `` before an answer's values; None when the symbol is
    the name in words (``motion: retrograde``) or a triple before each of its values."""
    tree = answer_symbol(answer)
    if tree is None or answer.symbol == answer.name \
            and not (answer.values and not isinstance(answer.values[0], str)) \
            and answer.symbol.isalpha() and len(answer.symbol) > 2:
        return None
    if is_list(tree) and len(answer.values) > 1:
        return None  # (I_1, I_2, I_3): one symbol per value, not the triple before each
    return tree


# ---- width and breaking -----------------------------------------------------

def unbracketed(node: Node) -> Node:
    """The node inside round brackets that a stacked fraction makes redundant."""
    while isinstance(node, P.Bracket) and node.open[0] == "(" and grouped(node) is not None:
        node = node.items[0]
    return node


def _inner_width(node: Node) -> float:
    """The width of a fraction's part: a list in round brackets without them."""
    node = unbracketed(node)
    if is_list(node) and node.open[0] == "(":  # type: ignore[attr-defined]
        return width(node) - 2
    return width(node)


def width(node: Node | None) -> float:
    """Rough width of the typeset node in characters (a stacked fraction is as wide as
    its wider part)."""
    if node is None:
        return 0
    op = op_of(node)
    if op is not None:
        left, right = node.left, node.right  # type: ignore[attr-defined]
        if op == "/":
            return max(_inner_width(left), _inner_width(right)) + 1
        return width(left) + width(right) + (3 if op in "+-" else 1)
    if isinstance(node, E.Pow):
        if sin_power(node):  # sin^2(x): a function's name, its arguments, the power
            return _call_width(shown_name(node.left) or "", node.left.args, node.right)  # type: ignore[attr-defined]
        return width(node.left) + 0.7 * width(node.right)
    if is_quantity(node):
        return width(quantity_value(node)) + 0.9 * len(quantity_unit(node)) + 1
    if isinstance(node, E.Num):
        return len(node.text) + (4 if "e" in node.text.lower() else 0)
    if isinstance(node, E.Sym):
        return 1.2 + 0.7 * len(node.name.partition("_")[2])
    if isinstance(node, P.Rel):
        return width(node.first) + sum(3 + width(rhs) for _, rhs in node.rest)
    if isinstance(node, P.Words):
        return len(node.words)
    name = shown_name(node)
    if name is not None and not (isinstance(node, E.Call) and node.name == "abs"):
        return _call_width(name, node.args)  # type: ignore[attr-defined]
    total = 2.0
    if isinstance(node, P.Bracket) and is_list(node):
        total += 2.0 + sum(width(x) + 1 for x in node.items)
    elif isinstance(node, P.Mat):
        total += sum(width(row[1]) + 2 for row in node.rows)
    elif isinstance(node, P.Integral):
        total += width(node.lower)
        total += width(node.upper)
        total += width(node.body)
    else:  # a sign, brackets, |x|, a sum over particles, a prime: around one node
        inner = _held(node)
        total += width(inner)
    return total


def _held(node: Node) -> Node:
    """The one node a sign, brackets, |x|, a sum or a prime holds."""
    if sign_of(node) is not None or isinstance(node, P.Prime):
        return node.arg  # type: ignore[attr-defined, no-any-return]
    if isinstance(node, P.Bracket):
        return node.items[0]
    if isinstance(node, E.Call):  # |x|
        return node.args[0]
    if isinstance(node, P.Total):
        return node.body
    raise TypeError(f"no width for {type(node).__name__}")


def _call_width(name: str, args: tuple[Node, ...], power: Node | None = None) -> float:
    total = 2.0
    total += len(name) if name not in ("|", ",") else 0
    total += sum(width(x) + 1 for x in args)
    if power is not None:
        total += width(power)
    return total


def pack(items: Iterable[tuple[_T, float]], budget: float, used: float = 0.0,
         started: Callable[[list[_T]], bool] = bool) -> list[tuple[list[_T], float]]:
    """The one line-breaking routine: ``items`` (a piece and its width) in rows, left to
    right, a new row when the next would pass ``budget``; ``used``: the width already
    taken on the first row; ``started(row)``: whether a row holds enough to end it."""
    rows: list[tuple[list[_T], float]] = []
    row: list[_T] = []
    for item, w in items:
        if started(row) and used + w > budget:
            rows.append((row, used))
            row, used = [], 0.0
        row.append(item)
        used += w
    rows.append((row, used))
    return rows


# ---- the walk ---------------------------------------------------------------------

class Writer:
    """A format's hooks: each returns the lines (or HTML parts) of one part of a worked
    answer. ``keys``: the file's keys written as words in prose."""

    def __init__(self, keys: Keys = NO_KEYS) -> None:
        self.keys = keys

    def head(self, result: Any) -> list[str]:
        raise NotImplementedError

    def note(self, note: str) -> list[str]:
        raise NotImplementedError

    def given(self, result: Any) -> list[str]:
        raise NotImplementedError

    def section(self, section: Any) -> list[str]:
        raise NotImplementedError

    def checks(self) -> list[str]:
        raise NotImplementedError

    def step(self, step: Any) -> list[str]:
        raise NotImplementedError

    def answers(self, result: Any) -> list[str]:
        raise NotImplementedError

    def warnings(self, solution: Any) -> list[str]:
        raise NotImplementedError


def walk(result: Any, writer: Writer) -> list[str]:
    """A solved problem once through, in the order every format shows it."""
    problem, solution = result.problem, result.solution
    out = writer.head(result)
    for note in problem.notes:
        out += writer.note(note)
    out += writer.given(result)
    for section in solution.sections:
        out += writer.section(section)
        for step in section.steps:
            out += writer.step(step)
    if solution.checks:
        out += writer.checks()
        for step in solution.checks:
            out += writer.step(step)
    out += writer.answers(result)
    if solution.warnings:
        out += writer.warnings(solution)
    return out
