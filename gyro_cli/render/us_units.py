"""A worked answer in US customary units (slug, ft, lbf), as US textbooks work it.

The kinds compute in SI floats and write their steps in SI. `gyro solve
--units us` converts at the edge: each quantity in the steps (found by the
formula parser, `mathparse`), each step's value, the Given table's second
column, and answers for which the file names no unit, are re-expressed in the
slug-ft-lbf system and written again to 4 significant figures. Units that are
the same in both systems (s, rad/s, rpm, deg) are left as they are.
"""

from __future__ import annotations

import dataclasses

from ..core.expr import Sym, map_syms, substitution
from ..core.prose import Quantity as Quantity_, map_values
from ..core.work import GivenLine, Section, Solution, Step, num
from ..solving.solve import Reported, Result
from .mathparse import spans, try_parse
from .mathprint import TextPrinter
from .mathtree import Node, Num, Quantity

SLUG = 14.593902937206364      # kg (lbf s^2/ft)
FT = 0.3048                    # m
LBF = 4.4482216152605          # N
FT_LBF = LBF * FT              # N m and J
SLUG_FT2 = SLUG * FT * FT      # kg m^2

#: SI unit as the kinds write it -> (US unit, SI value of one US unit)
US = {
    "kg": ("slug", SLUG),
    "m": ("ft", FT),
    "m^2": ("ft^2", FT * FT),
    "N": ("lbf", LBF),
    "N m": ("lbf ft", FT_LBF), "N*m": ("lbf ft", FT_LBF),
    "J": ("ft lbf", FT_LBF),
    "kg m^2": ("slug ft^2", SLUG_FT2), "kg*m^2": ("slug ft^2", SLUG_FT2),
    "kg m^2/s": ("slug ft^2/s", SLUG_FT2), "kg*m^2/s": ("slug ft^2/s", SLUG_FT2),
    "m/s": ("ft/s", FT),
    "m/s^2": ("ft/s^2", FT),
    "kg m": ("slug ft", SLUG * FT),
    "N/m": ("lbf/ft", LBF / FT),
}


def convert(value: float, unit: str) -> tuple[float, str]:
    """An SI value in its US unit: (0.08498, "kg") -> (0.005823, "slug")."""
    us = US.get(unit.strip())
    if us is None:
        return value, unit
    return value / us[1], us[0]


class _Convert(TextPrinter):
    """The plain text of a tree with every SI quantity written in US units. A number that
    is the 4-figure print of a value the solution holds exactly (a given datum, a step's
    result) is converted from that value, so it is not rounded twice."""

    exact: dict = {}

    def _print_Quantity(self, node: Quantity) -> str:
        if isinstance(node.value, Num) and node.unit in US and not node.value.text.endswith("i"):
            unit = US[node.unit][0]
            si = self.exact.get((node.value.text, unit), float(node.value.text))
            return f"{num(convert(si, node.unit)[0])} {unit}"
        return super()._print_Quantity(node)


def _text(text: str) -> str:
    """A step's substitution or a line of prose with its quantities converted."""
    if not text or not any(u in text for u in ("kg", "m", "N", "J")):
        return text
    tree = try_parse(text)
    if tree is not None:
        return _Convert().doprint(tree) if _has_si(tree) else text
    out = []
    for is_math, part in spans(text):
        out.append(_Convert().doprint(part) if is_math and _has_si(part) else
                   TextPrinter().doprint(part) if is_math else part)
    return "".join(out) if any(is_math and _has_si(part) for is_math, part in spans(text)) \
        else text


def _has_si(node: Node) -> bool:
    if isinstance(node, Quantity):
        return node.unit in US
    for value in vars(node).values():
        if isinstance(value, Node) and _has_si(value):
            return True
        if isinstance(value, tuple):
            for item in value:
                if isinstance(item, Node) and _has_si(item):
                    return True
                if isinstance(item, tuple) and any(isinstance(x, Node) and _has_si(x)
                                                   for x in item):
                    return True
    return False


def _us_symbol(sym: Sym) -> Sym:
    value, unit = convert(sym.si, sym.unit)
    return Sym(sym.name, value, unit)


def _us_quantity(quantity: Quantity_) -> Quantity_:
    value, unit = convert(quantity.si, quantity.unit)
    if unit == quantity.unit:  # a unit of both systems: as written (label, digits and all)
        return quantity
    return Quantity_(value, unit)  # converted: to 4 figures, as every converted value


def _step(step: Step) -> Step:
    value, unit = (convert(step.value, step.unit) if step.value is not None
                   else (None, step.unit))
    if step.prose is not None:  # words and trees: the quantities inside converted
        prose = step.prose.map(lambda tree: map_values(tree, _us_symbol, _us_quantity))
        step = dataclasses.replace(step, prose=prose, text=prose.text)
        if not step.symbol:
            return step
    if step.expr is not None:  # the values inside the tree are converted, nothing parsed
        view = map_syms(step.expr, _us_symbol)
        return dataclasses.replace(step, substitution=substitution(view) if step.substitution
                                   else "", value=value, unit=unit,
                                   text=step.text if step.prose else _text(step.text),
                                   view=view, si=step.si or (step.value, step.unit))
    return dataclasses.replace(step, substitution=_text(step.substitution), value=value,
                               unit=unit, text=step.text if step.prose else _text(step.text))


def _warnings(solution: Solution) -> tuple[list[str], dict]:
    """The warnings in US units, and those written as words and trees by their new text."""
    texts, proses = [], {}
    for text in solution.warnings:
        prose = solution.warning_prose.get(text)
        if prose is None:
            texts.append(_text(text))
            continue
        prose = prose.map(lambda tree: map_values(tree, _us_symbol, _us_quantity))
        texts.append(prose.text)
        proses[prose.text] = prose
    return texts, proses


def _given(line: GivenLine) -> GivenLine:
    if isinstance(line.si_value, str):
        return line
    value, unit = convert(line.si_value, line.si_unit)
    return dataclasses.replace(line, si_value=value, si_unit=unit)


def _answer(answer: Reported) -> Reported:
    if answer.unit is None or answer.unit not in US:
        return answer
    values = [convert(v, answer.unit)[0] if isinstance(v, float) else v for v in answer.values]
    return dataclasses.replace(answer, values=values, unit=US[answer.unit][0])


def to_us(result: Result, given: bool = True) -> Result:
    """The result with its worked answer in slug, ft and lbf; ``given=False`` keeps the
    Given lines in SI (JSON's ``si_value`` is SI by contract)."""
    solution = result.solution
    exact = {}
    steps = [step for s in solution.sections for step in s.steps] + list(solution.checks)
    known = [(g.si_value, g.si_unit) for g in solution.given if not isinstance(g.si_value, str)]
    known += [(step.value, step.unit) for step in steps if step.value is not None]
    for value, unit in known:
        if unit in US:
            exact.setdefault((num(value), US[unit][0]), value)
    _Convert.exact = exact
    warnings, warning_prose = _warnings(solution)
    converted = Solution(
        given=[_given(g) for g in solution.given] if given else list(solution.given),
        sections=[Section(s.title, [_step(step) for step in s.steps], prose=s.prose)
                  for s in solution.sections],
        answers=solution.answers,
        warnings=warnings,
        checks=[_step(step) for step in solution.checks],
        system="US", warning_prose=warning_prose)
    # an answer is converted only where the file asked for no unit (SI by default)
    answers = {name: _answer(a) if result.problem.find.get(name) is None else a
               for name, a in result.answers.items()}
    return dataclasses.replace(result, solution=converted, answers=answers)
