"""Which steps of a worked answer each step and answer uses (errors carried forward).

Two views of one graph:

- ``uses``: the earlier steps a step's tree names (its symbols, and the symbols of the
  definitions its `Let`s show), read from the trees: what a reader of the worked answer
  sees;
- ``depends``: the steps whose value, changed, changes a step or an answer when the
  problem is solved again with that value in its place (`solve(problem, overrides)`):
  what the solver works on from, through closed formulas and through roots,
  eigenvalues and integrations alike. Errors are carried forward along these.

A step is known by its symbol, from the first step of that symbol whose value is in an
SI unit (as `gyro check` grades ``expected: {steps: ...}``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from ..core.expr import FUNCTIONS, BinOp, Call, Chain, Expr, Let, Neg, SumOf, Sym

#: relative change of a value taken as "changed" when an earlier step is nudged
_CHANGED = 1e-9
#: the relative nudge given to a step to see what follows from it
_NUDGE = 1e-6


def graded_steps(solution: Any) -> dict[str, tuple[float, str, str]]:
    """Each step symbol -> (SI value, SI unit, dimension), from the first step of that
    symbol whose value is in an SI unit (a tree's, or one stated in SI)."""
    from ..core import units
    from ..core.expr import UNIT_TEXT

    dimensions: dict[str, str] = {}
    for dimension, (_, si, _) in units.DIMENSIONS.items():
        dimensions.setdefault(units.SI_TEXT.get(si, si), dimension)
    out: dict[str, tuple[float, str, str]] = {}
    for section in solution.sections:
        for step in section.steps:
            if not step.symbol or step.value is None or step.symbol in out:
                continue
            value, unit = step.si if step.si is not None else (step.value, step.unit)
            unit = UNIT_TEXT.get(unit, units.SI_TEXT.get(unit, unit))
            if unit in dimensions:
                out[step.symbol] = (value, unit, dimensions[unit])
    return out


def named(expr: Expr) -> set[str]:
    """Every symbol name a tree shows: its symbols, and a `Let`'s own and its
    definition's (``D`` for ``m g l`` names D, m, g and l)."""
    out: set[str] = set()
    todo = [expr]
    while todo:
        node = todo.pop()
        if isinstance(node, Sym):
            out.add(node.name)
        elif isinstance(node, Let):
            out.add(node.sym.name)
            todo.append(node.body)
        elif isinstance(node, Chain):
            todo.extend(node.forms)
        else:
            todo.extend(node.children())
    return out


def tree_uses(solution: Any) -> dict[str, list[str]]:
    """Each tree step's symbol -> the earlier steps its tree names, in the order written."""
    steps = graded_steps(solution)
    seen: list[str] = []
    out: dict[str, list[str]] = {}
    for section in solution.sections:
        for step in section.steps:
            if step.symbol not in steps or step.symbol in out or step.symbol in seen:
                continue
            if step.expr is not None:
                names = named(step.expr)
                out[step.symbol] = [s for s in seen if s in names]
            seen.append(step.symbol)
    return out


@dataclass
class Graph:
    """The steps of one solved problem and what follows from each."""

    steps: dict[str, tuple[float, str, str]]
    uses: dict[str, list[str]]
    #: answer name -> the step symbol whose value it is (a closed formula), or absent
    answer_step: dict[str, str]
    #: step symbol or ``answer:NAME`` -> the steps it depends on (transitively)
    depends: dict[str, list[str]] = field(default_factory=dict)
    #: step symbols that could not be nudged (the solve refused a nudged value)
    untried: list[str] = field(default_factory=list)
    #: the answers that are a step written as a formula (a tree), not a value found
    closed: set[str] = field(default_factory=set)

    def answer_depends(self, name: str) -> list[str]:
        return self.depends.get(f"answer:{name}", [])


def answer_steps(result: Any, steps: dict[str, tuple[float, str, str]]) -> dict[str, str]:
    """Each answer that is the value of a step (its symbol's, one value) -> that step."""
    out = {}
    for name, answer in result.answers.items():
        if answer.si_unit is None or len(answer.si_values) != 1:
            continue
        step = steps.get(answer.symbol)
        if step is not None and _same(step[0], answer.si_values[0]):
            out[name] = answer.symbol
    return out


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, str) or isinstance(b, str):
        return a == b
    return abs(a - b) <= _CHANGED * max(abs(a), abs(b)) or a == b


def _values(result: Any) -> dict[str, list[Any]]:
    """Every step's and answer's SI values of a solve, by graph name."""
    out: dict[str, list[Any]] = {s: [v[0]] for s, v in graded_steps(result.solution).items()}
    for name, answer in result.answers.items():
        out[f"answer:{name}"] = list(answer.si_values)
    return out


def graph(problem: Any, result: Any = None) -> Graph:
    """The graph of a problem: ``uses`` from the trees, ``depends`` by solving again with
    each step nudged. ``result``: its solve in SI, if the caller has it."""
    from ..core.errors import InputError
    from .solve import solve

    if result is None:
        result = solve(problem)
    steps = graded_steps(result.solution)
    out = Graph(steps, tree_uses(result.solution), answer_steps(result, steps))
    trees = {step.symbol for section in result.solution.sections for step in section.steps
             if step.expr is not None}
    out.closed = {name for name, symbol in out.answer_step.items() if symbol in trees}
    base = _values(result)
    for symbol, (value, _, _) in steps.items():
        nudged = value * (1 + _NUDGE) if value else _NUDGE
        try:
            again = _values(solve(problem, {symbol: nudged}))
        except (InputError, ArithmeticError, ValueError):
            out.untried.append(symbol)
            continue
        for name, values in base.items():
            if name == symbol:
                continue
            other = again.get(name)
            if other is None or len(other) != len(values) or \
                    not all(_same(a, b) for a, b in zip(values, other)):
                out.depends.setdefault(name, []).append(symbol)
    return out


def as_data(g: Graph, answers: list[str]) -> dict[str, Any]:
    """The graph as JSON: per step its tree's earlier steps (``uses``) and every step it
    depends on; per answer the same and the step it is (``step``, null if it is no closed
    formula: a root, an eigenvalue, an integration)."""
    return {
        "steps": {s: {"uses": g.uses.get(s, []), "depends": g.depends.get(s, [])}
                  for s in g.steps},
        "answers": {name: {"step": g.answer_step.get(name) if name in g.closed else None,
                           "uses": g.uses.get(g.answer_step[name], []) if name in
                           g.answer_step else [],
                           "depends": g.depends.get(f"answer:{name}", [])}
                    for name in answers},
        "untried": g.untried,
    }


_OPS = {"+": lambda a, b: a + b, "-": lambda a, b: a - b, "*": lambda a, b: a * b,
        "/": lambda a, b: a / b, "^": lambda a, b: a * a if b == 2 else a ** b}


def evaluate(node: Expr, env: dict[str, float]) -> float:
    """A tree's value with the symbols named in ``env`` taking its values; a `Let` whose
    definition names one of them is worked out again from its definition."""
    if isinstance(node, Sym):
        return env.get(node.name, node.si)
    if isinstance(node, Let):
        if node.sym.name in env:
            return env[node.sym.name]
        return evaluate(node.body, env) if named(node.body) & set(env) else node.sym.si
    if isinstance(node, Neg):
        return -evaluate(node.arg, env)
    if isinstance(node, BinOp):
        return _OPS[node.op](evaluate(node.left, env), evaluate(node.right, env))
    if isinstance(node, Call):
        return FUNCTIONS[node.name](*(evaluate(a, env) for a in node.args))
    if isinstance(node, Chain):
        return evaluate(node.forms[-1], env)
    if isinstance(node, SumOf):
        return math.fsum(evaluate(t, env) for t in node.terms)
    return node.value


def through_trees(solution: Any, overrides: dict[str, float]) -> dict[str, float]:
    """Each tree step's SI value worked out again from its tree, in order, with the
    ``overrides`` in place of those steps and every later step taking the new values:
    the closed formulas of the worked answer, where solving again is refused (a student's
    value for which the kind finds no motion)."""
    env = dict(overrides)
    steps = graded_steps(solution)
    done: set[str] = set()
    for section in solution.sections:
        for step in section.steps:
            symbol = step.symbol
            if symbol not in steps or symbol in done:
                continue
            done.add(symbol)
            if symbol in overrides or step.expr is None:
                continue
            if named(step.expr) & set(env):
                value = evaluate(step.expr, env)
                env[symbol] = value
    return env
