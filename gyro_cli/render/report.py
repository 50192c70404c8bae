"""Reports: a solved problem as text or JSON (the format page's contract)."""

from __future__ import annotations

from typing import Any

from ..core.errors import terminal_text
from ..core.expr import UNIT_TEXT, python, python_name, symbols
from ..core.work import Step, num
from ..solving.solve import Result
from .formats import Format

WIDTH = 78


def _answer_text(values: list, unit: str | None, labels: list[str]) -> str:
    if not values:
        return "none"
    parts = []
    for i, value in enumerate(values):
        text = str(value) if isinstance(value, str) else f"{num(value)} {unit or ''}".rstrip()
        if i < len(labels) and labels[i]:
            text += f" ({labels[i]})"
        parts.append(text)
    return "   ".join(parts)


def text(result: Result) -> str:
    """The worked answer, as the format page shows it."""
    problem, solution = result.problem, result.solution
    head = f"{problem.id}  {problem.title}".rstrip()
    tag = f"[{problem.kind.name}]"
    lines = [f"{head}{' ' * max(2, WIDTH - len(head) - len(tag))}{tag}"]
    if problem.source:
        lines.append(f"Source: {problem.source}")
    lines += [f"Note: {' '.join(note.splitlines())}" for note in problem.notes]
    symbol = max([7] + [len(g.symbol) for g in solution.given]) + 1
    text = max([21] + [len(g.text) for g in solution.given]) + 1
    lines += ["", f"{'Given':<{symbol + text + 2}}{solution.system}"]
    for g in solution.given:
        si = g.si_value if isinstance(g.si_value, str) else f"{num(g.si_value)} {g.si_unit}"
        row = f"  {g.symbol:<{symbol}}{g.text:<{text}}{si}"
        if g.note:
            row = f"{row:<{symbol + text + 20}}({g.note})"
        lines.append(row.rstrip())
    for section in solution.sections:
        lines += ["", section.title]
        lines += [f"  {step.as_text()}" for step in section.steps]
    if solution.checks:
        lines += ["", "Check"]
        lines += [f"  {step.as_text()}" for step in solution.checks]
    lines += ["", "Answer"]
    width = max(len(name) for name in result.answers) if result.answers else 0
    for name, answer in result.answers.items():
        lines.append(f"  {name:<{width}}  {answer.symbol} = "
                     f"{_answer_text(answer.values, answer.unit, answer.labels)}")
    if solution.warnings:
        lines += ["", "Warnings"]
        lines += [f"  ! {warning}" for warning in solution.warnings]
    # the id, title, source and notes come from the file: one line each, and no terminal
    # escape sequence reaches the terminal raw
    return "\n".join(terminal_text(line) for line in lines) + "\n"


def as_dict(result: Result) -> dict[str, Any]:
    """The JSON object of one solved problem (values in full precision)."""
    problem, solution = result.problem, result.solution
    return {
        "id": problem.id,
        "kind": problem.kind.name,
        "file": problem.file,
        "title": problem.title,
        "answers": {
            name: {"values": a.values, "unit": a.unit, "si_values": a.si_values,
                   "si_unit": a.si_unit, "symbol": a.symbol, "labels": a.labels}
            for name, a in result.answers.items()},
        "given": [{"key": g.key, "symbol": g.symbol, "text": g.text, "si_value": g.si_value,
                   "si_unit": g.si_unit} for g in solution.given],
        "steps": [{"title": s.title, "lines": [step.as_text() for step in s.steps],
                   "equations": [equation(step) for step in s.steps
                                 if step.symbol and (step.formula or step.expr)]}
                  for s in solution.sections],
        "checks": [step.as_text() for step in solution.checks],
        "warnings": list(solution.warnings),
    } | ({"units": solution.system.lower()} if solution.system != "SI" else {})


def equation(step: Step) -> dict[str, Any]:
    """One equation step as data (docs/steps.md): its value in SI at full precision and,
    for a step built from a tree, the formula as Python over its symbols' SI values."""
    value, unit = step.si if step.si is not None else (step.value, step.unit)
    out: dict[str, Any] = {"symbol": step.symbol, "value": value, "unit": UNIT_TEXT.get(unit, unit),
                           "ref": step.ref, "formula": step.formula,
                           "substitution": step.substitution}
    if step.expr is None:  # a step still written as text
        return out | {"formula_latex": None, "substitution_latex": None, "expr": None,
                      "symbols": None}
    from .mathprint import formula_latex as latex

    tree = step.shown
    assert tree is not None
    return out | {
        "formula_latex": latex(tree) if step.formula else "",
        "substitution_latex": latex(tree, values=True) if step.substitution else "",
        "expr": python(step.expr),
        "symbols": {python_name(name): sym.si for name, sym in symbols(step.expr).items()}}


def as_json(result: Result) -> str:
    import json  # only for --format json

    return json.dumps(as_dict(result), allow_nan=False)


def graph_data(result: Result) -> dict[str, Any]:
    """What each step and answer of a solve uses and depends on (`solving.deps`): the
    ``graph`` of ``gyro solve --format json``, which errors carried forward follow."""
    from ..solving.deps import as_data, graph

    return as_data(graph(result.problem, result), list(result.answers))


class _Text(Format):
    """``gyro solve``'s worked answer; files apart by a rule."""

    name = "text"
    separator = "\n" + "=" * WIDTH + "\n\n"

    def one(self, result: Any, level: int = 2) -> str:
        return text(result.solved)


class _Json(Format):
    """One JSON object per file, one per line (SI given values under ``--units us``)."""

    name = "json"

    def one(self, result: Any, level: int = 2) -> str:
        return str(result.to_json()) + "\n"


TEXT, JSON = _Text(), _Json()
