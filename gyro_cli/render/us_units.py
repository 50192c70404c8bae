"""A worked answer in US customary units (slug, ft, lbf), as US textbooks work it.

The kinds compute in SI floats and write their steps in SI. `gyro solve
--units us` converts at the edge: each symbol's value inside a step's tree and
each quantity inside a sentence's trees (`core.prose`), each step's value, the
Given table's second column, and answers for which the file names no unit, are
re-expressed in the slug-ft-lbf system and written again to 4 significant
figures; nothing is read back from text. Units that are the same in both
systems (s, rad/s, rpm, deg) are left as they are.
"""

from __future__ import annotations

import dataclasses

from ..core.expr import Sym, map_syms, substitution
from ..core.prose import Quantity as Quantity_
from ..core.prose import map_values
from ..core.work import GivenLine, Section, Solution, Step
from ..solving.solve import Reported, Result

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


def _us_symbol(sym: Sym) -> Sym:
    value, unit = convert(sym.si, sym.unit)
    return Sym(sym.name, value, unit)


def _us_quantity(quantity: Quantity_) -> Quantity_:
    value, unit = convert(float(quantity.si.real), quantity.unit)  # a quantity is real
    if unit == quantity.unit:  # a unit of both systems: as written (label, digits and all)
        return quantity
    return Quantity_(value, unit)  # converted: to 4 figures, as every converted value


def _si_of(step: Step) -> tuple[float, str] | None:
    """The step's SI value and unit, kept beside its US view (None for no value)."""
    return None if step.value is None else (step.value, step.unit)


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
                                   text=step.text,
                                   view=view, si=step.si or _si_of(step))
    return dataclasses.replace(step, value=value, unit=unit)  # a value step: no tree


def _warnings(solution: Solution) -> tuple[list[str], dict]:
    """The warnings in US units, and those written as words and trees by their new text."""
    texts, proses = [], {}
    for text in solution.warnings:
        prose = solution.warning_prose.get(text)
        if prose is None:  # words only
            texts.append(text)
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


def _section(section: Section) -> Section:
    """The section with its steps converted, and the quantities of a title of words and
    trees (``At v = 5 m/s: ...``)."""
    steps = [_step(step) for step in section.steps]
    if section.prose is None:
        return Section(section.title, steps)
    prose = section.prose.map(lambda tree: map_values(tree, _us_symbol, _us_quantity))
    return Section(prose.text, steps, prose=prose)


def to_us(result: Result, given: bool = True) -> Result:
    """The result with its worked answer in slug, ft and lbf; ``given=False`` keeps the
    Given lines in SI (JSON's ``si_value`` is SI by contract)."""
    solution = result.solution
    warnings, warning_prose = _warnings(solution)
    converted = Solution(
        given=[_given(g) for g in solution.given] if given else list(solution.given),
        sections=[_section(s) for s in solution.sections],
        answers=solution.answers,
        warnings=warnings,
        checks=[_step(step) for step in solution.checks],
        system="US", warning_prose=warning_prose)
    # an answer is converted only where the file asked for no unit (SI by default)
    answers = {name: _answer(a) if result.problem.find.get(name) is None else a
               for name, a in result.answers.items()}
    return dataclasses.replace(result, solution=converted, answers=answers)
