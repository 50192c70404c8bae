"""Solving one problem: body, kind, answers in the units asked for."""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING, Any

from ..core import units
from ..core.alternatives import alternatives_of, step_tree
from ..core.body import build_body
from ..core.errors import InputError
from ..core.expr import Add, Call, Const, Div, Expr, Let, Mul, Neg, Num, Pow, Sub, Sym
from ..core.given import Given
from ..core.params import MISSING_KEY
from ..core.prose import names, q, rel
from ..core.record import record
from ..core.spec import Kind
from .problem import Problem, load, params_by_name

if TYPE_CHECKING:
    from collections.abc import Iterable
from ..core.work import GivenLine, Solution, Work, num


@record
class Reported:
    """An answer as asked for: values in ``unit`` (None for words)."""

    name: str
    symbol: str
    values: list
    unit: str | None
    si_values: list
    si_unit: str | None
    labels: list[str]
    symbol_expr: Expr | None = None  # a symbol that is not one name, as a tree
    signs: list | None = None  # the words that sign its sizes, where the kind's do not hold


@record
class Result:
    problem: Problem
    solution: Solution
    answers: dict[str, Reported]


def solve_file(path: str) -> Result:
    return solve(load(path))


def asking(problem: Problem, names: Iterable[str]) -> Problem:
    """The problem asking also for the answers ``names`` (in SI, after its own ``find``);
    the problem itself when it asks for them all already."""
    more = [name for name in names if name not in problem.find]
    if not more:
        return problem
    import dataclasses  # here: a solve that asks for nothing more never imports it

    return dataclasses.replace(problem, find=problem.find | dict.fromkeys(more))


def solve_asking(problem: Problem, names: Iterable[str]) -> Result:
    """`solve` of the problem asking also for ``names`` (an answer key's, a sheet's)."""
    return solve(asking(problem, names))


def solve(problem: Problem, overrides: dict[str, float] | None = None) -> Result:
    """Solve a loaded problem; InputError (located in the file) if it cannot be.

    ``overrides``: step symbol -> SI value taking the place of the first step of that
    symbol, the kind working on from it (errors carried forward, solving/deps.py)."""
    try:
        return _solve(problem, overrides)
    except InputError as err:
        if re.search(_NOT_FINITE, re.sub(r"'[^'\n]*'", "''", err.message)):
            # A kind's check whose message would print inf or nan (m l^2 = inf kg m^2):
            # the data are past what double precision holds, and that is the message.
            err.message = ("these data overflow double precision (a value past 1e308 in "
                           "checking them); check the magnitudes and units")
        raise err.located(file=problem.file, line=problem.line(err.key)) from None


def _declared_keys(kind: Kind, given: Given) -> None:
    """Refuse a problem without a key its kind requires, or not one of a group it declares."""
    for param in kind.params:
        if param.required and param.name not in given:
            message = param.required if isinstance(param.required, str) else MISSING_KEY
            raise InputError(message, key=f"given.{param.name}")
    for group in kind.one_of:
        refused = group.refusal([k for k in group.keys if k in given])
        if refused is not None:
            raise InputError(refused[0], key=f"given.{refused[1]}")


def _solve(problem: Problem, overrides: dict[str, float] | None = None) -> Result:
    unfinite = Sym.unfinite  # symbols made so far with a value that is not finite
    work = Work(overrides)
    work.given.extend(_given_lines(problem))
    kind = problem.kind
    _data_as_stated(problem, work)
    if kind.uses_body:
        problem.given.body = build_body(problem.given.values, problem.us_customary, work,
                                        sizeless_ok=kind.size_free,
                                        gravity=kind.gravity)
        _scaled_data_refused(problem)
        if not kind.gravity and "weight" not in problem.given.values:
            pass  # gravity plays no part in this kind (and no weight to turn into a mass)
        elif problem.us_customary and "g" not in problem.given.values:
            work.given.append(GivenLine("g", "g", "32.2 ft/s^2 (default)", problem.given.body.g,
                                        "m/s^2", "US customary data: textbook g",
                                        shown=("32.2", "ft/s^2")))
            if not {"mass", "weight"} & set(problem.given.values):  # US by its lengths alone
                g = names("g")[0]
                textbook = rel(g, "=", q(32.2, "ft/s^2", exact=True))
                work.warn("no g given: the lengths are in US customary units and no mass is "
                          "given, so the US textbook ", textbook, " is used; give g to use "
                          "another")
        elif "g" not in problem.given.values:
            work.given.append(GivenLine("g", "g", "9.81 m/s^2 (default)", problem.given.body.g,
                                        "m/s^2", shown=("9.81", "m/s^2")))
    _declared_keys(kind, problem.given)
    try:
        kind.solve(problem.given, frozenset(problem.find), work)
    except (ArithmeticError, ValueError) as err:
        # Last line of defence: extreme data (1e300 kg, a 1e9 m radius of gyration) that
        # overflow or degenerate in floating point. Say so rather than print a traceback.
        raise InputError(f"these data are outside what {kind.name} can compute reliably in "
                         f"double precision ({type(err).__name__}: {err}); check the magnitudes "
                         "and units", key="given") from None
    # a heading with nothing under it (the Body of a kind given J and I directly) is left out
    work.sections[:] = [section for section in work.sections if section.steps]
    solution = work.solution()
    body = problem.given.body
    if body is not None and (body.per_kg or body.per_size):  # worked per kilogram or per
        _drop_mass_answers(solution, problem.find, body.per_size)  # unit r^2: rates only
    _all_finite(solution, trees=Sym.unfinite != unfinite)
    answers = {}
    for name, unit in problem.find.items():
        answer = solution.answers.get(name)
        if answer is None:
            raise InputError(f"{kind.name} could not give {name!r} from the data given",
                             key=f"find.{name}")
        if not all(isinstance(v, str) or math.isfinite(v) for v in answer.si_values):
            raise InputError(f"{name} is not a finite number for these data (overflow or a "
                             "degenerate case); check the magnitudes and units",
                             key=f"find.{name}")
        if answer.dimension is None:
            values, unit = list(answer.si_values), None
        else:
            unit = unit or answer.si_unit
            assert unit is not None, f"{name} has a dimension but no SI unit"
            values = [units.convert(v, answer.dimension, unit) for v in answer.si_values]
            if not all(math.isfinite(v) for v in values):
                big = max(answer.si_values, key=abs)
                raise InputError(f"{name} = {num(big)} {answer.si_unit} is too large to "
                                 f"express in {unit}; ask for a larger unit",
                                 key=f"find.{name}")
        answers[name] = Reported(name, _symbol_in(answer.symbol, answer.dimension, unit),
                                 values, unit, list(answer.si_values), answer.si_unit,
                                 answer.labels, answer.symbol_expr, answer.signs)
    return Result(problem, solution, answers)


def _symbol_in(symbol: str, dimension: str | None, unit: str | None) -> str:
    """The symbol for the unit asked: an angular frequency omega_n asked in Hz is the
    frequency f_n = omega_n / (2 pi), and is printed so (89.44 rad/s is 14.24 Hz)."""
    if dimension == "rate" and unit and unit.strip().lower() in ("hz", "hertz", "khz") \
            and symbol.startswith("omega"):
        return "f" + symbol[len("omega"):]
    return symbol


# Answers proportional to the mass (a per-kilogram solution cannot give them).
MASS_DIMENSIONS = {"mass", "force", "moment", "inertia", "angular_momentum", "energy",
                   "mass_length"}


def _drop_mass_answers(solution, find, per_size: bool = False) -> None:
    """Refuse (if asked) and drop answers that scale with a mass (or, ``per_size``, a
    size) no key gave."""
    for name, answer in list(solution.answers.items()):
        if answer.dimension in MASS_DIMENSIONS:
            if name in find:
                raise _scale_missing(name, per_size)
            del solution.answers[name]


def _scale_missing(name: str, per_size: bool) -> InputError:
    """The refusal of a quantity that needs the mass or size the rates did without."""
    if per_size:
        return InputError(f"{name} depends on the body's size, which the rates do not need: "
                          "give radius or diameter", key="given.radius")
    return InputError(f"{name} depends on the mass, which the rates do not need: give mass "
                      "or weight", key="given.mass")


def _scaled_data_refused(problem: Problem) -> None:
    """A given quantity that scales with the mass or size (an angular momentum, a moment)
    cannot go with a body worked per kilogram or per unit r^2: the rates from it would be
    per kilogram too. Refused, naming the key missing."""
    body = problem.given.body
    if body is None or not (body.per_kg or body.per_size):
        return
    for param in problem.kind.params:
        if param.dimension in MASS_DIMENSIONS and problem.given.given_explicitly(param.name):
            what = "size: give radius or diameter" if body.per_size else \
                "mass: give mass or weight"
            raise InputError(f"a given {param.name} goes with the body's own {what} (without "
                             "it the body is worked per kilogram or per unit radius, and "
                             f"rates from {param.name} would be wrong)",
                             key="given.radius" if body.per_size else "given.mass")
# compiled on first use (re keeps it): not at every start
_NOT_FINITE = r"(?i)(?<![\w.])[-+]?(?:nan|inf)(?![\w])"


def _all_finite(solution: Solution, trees: bool = True) -> None:
    """Every number in the worked answer is finite: an overflow in a step (1e200 rpm
    squared) is bad input for this kind, not a worked answer with inf in it.

    ``trees``: whether to walk the steps' trees for a symbol whose value is not finite;
    needless when the solve made no such symbol (`Sym.unfinite` did not change)."""
    finite: set[int] = set()  # the symbols found finite so far (the steps share many)
    for section in solution.sections:
        for step in section.steps:
            where = step.symbol or _Title(section)  # the title printed only for a message
            if step.value is not None and not math.isfinite(step.value):
                raise InputError(f"the step {where} is not a finite number for these data "
                                 "(overflow or a degenerate case); check the magnitudes and "
                                 "units", key="given")
            if trees and step.expr is not None:  # a tree: its symbols' values, no text
                if not _symbols_finite(step.expr, finite):
                    raise InputError(f"the step {where} overflows for these data; check "
                                     "the magnitudes and units", key="given")
            # a sentence's values were held to be finite as they were made (core/prose.py)
            texts = () if step.prose is not None else (step.text,) if step.expr is not None \
                else (step.formula, step.substitution, step.text)
            for text in texts:
                if text and _not_finite(text):
                    raise InputError(f"the step {where} overflows for these data; check "
                                     "the magnitudes and units", key="given")
    for check in solution.checks:
        if check.prose is None and _not_finite(check.text):
            raise InputError("a check of the answer overflows for these data; check the "
                             "magnitudes and units", key="given")
    for text in solution.warnings:
        if _not_finite(text):
            raise InputError("a check of the answer overflows for these data; check the "
                             "magnitudes and units", key="given")


class _Title:
    """A section's title, printed (from its words and trees) only when a message needs it."""

    def __init__(self, section) -> None:  # type: ignore[no-untyped-def]
        self.section = section

    def __str__(self) -> str:
        return self.section.title


def _not_finite(text: str) -> bool:
    """Whether the text prints an inf or a nan (_NOT_FINITE), the regular expression
    searched only in a text that holds those letters at all (most hold neither; a
    text beyond ASCII is always searched: İ and ı match i there)."""
    if text.isascii():
        lower = text.lower()
        if "inf" not in lower and "nan" not in lower:
            return False
    return re.search(_NOT_FINITE, text) is not None


def _symbols_finite(expr, finite: set[int] | None = None) -> bool:  # type: ignore[no-untyped-def]
    """Whether every symbol of ``symbols(expr)`` (the first of each name; of a `Let`, its
    symbol) holds a finite value: the same walk, without building the mapping.
    ``finite``: the ids of symbol objects already found finite (in other steps of the same
    solution, which holds them); each found now is added."""
    seen: set[str] = set()
    done = finite if finite is not None else set()
    todo = [expr]
    pop, push, isfinite = todo.pop, todo.append, math.isfinite
    while todo:
        node = pop()
        kind = node.__class__
        if kind is Sym or (kind not in _TREE_NODES and isinstance(node, Sym)):
            if node.name not in seen:
                seen.add(node.name)
                if id(node) in done:
                    continue
                if not isfinite(node.si):
                    return False
                done.add(id(node))
        elif kind is Let or (kind not in _TREE_NODES and isinstance(node, Let)):
            push(node.sym)
        elif kind in _BINARY:
            push(node.right)
            push(node.left)
        else:
            todo.extend(reversed(node.children()))
    return True


_BINARY = {Add, Sub, Mul, Div, Pow}
_TREE_NODES = _BINARY | {Sym, Let, Neg, Num, Const, Call}  # exactly these classes


def _data_as_stated(problem: Problem, work: Work) -> None:
    """Each key the file stated another way (a diameter, an angle from the horizontal),
    turned into the key the kind reads: a step of the worked answer."""
    derived = problem.given.derived
    if not derived:
        return
    params = params_by_name(problem.kind)
    alternatives = alternatives_of(params)
    work.section("Data as given")
    for target, (key, si) in derived.items():
        alternative = alternatives[key]
        work.step(params[target].symbol, step_tree(alternative, si), unit=alternative.unit,
                  note=alternative.note)


def _given_lines(problem: Problem) -> list[GivenLine]:
    params = params_by_name(problem.kind)
    lines = []
    derived = problem.given.derived
    for key, value in problem.given.values.items():
        param = params[key]
        quantity = problem.quantities[key]
        if key in derived:  # stated another way: the given line is the key as written
            written, value = derived[key]
            param = alternatives_of(params)[written].param_for(param)
            key = written
        if isinstance(value, str):
            lines.append(GivenLine(key, param.symbol, str(quantity) if isinstance(quantity, str)
                                   else value, value, ""))
            continue
        if isinstance(value, tuple):  # particles, the one given that is not a number
            lines.append(GivenLine(key, param.symbol, f"{len(value)} particles",
                                   "listed under Inertia", ""))
            continue
        raw = problem.data.get("given", {}).get(key, param.default)
        text, si, note, shown = _written(param, key, raw, quantity,
                                         key in problem.given.defaulted)
        lines.append(GivenLine(key, param.symbol, text, value, si, note,
                               symbol_expr=param.symbol_tree, shown=shown))
    return lines


# A given line's words for a value written as a string, by (param, key, string, defaulted):
# the same for every variant of a set whose value is not varied (and a solve of the same
# file again). The param is kept to tell a reused id apart.
_Written = tuple[str, str, str, "tuple[str, str] | None"]  # text, SI unit, note, shown
_WRITTEN: dict[tuple[int, str, str, bool], tuple[_Written, Any]] = {}
_WRITTEN_MAX = 4096  # held while under this many: varied values are seldom seen twice


def _written(param: Any, key: str, raw: Any, quantity: Any, defaulted: bool) -> _Written:
    """`_written_line`, remembered in `_WRITTEN` for a string ``raw``."""
    if raw.__class__ is not str:
        return _written_line(param, key, raw, quantity, defaulted)
    memo = (id(param), key, raw, defaulted)
    known = _WRITTEN.get(memo)
    if known is not None and known[1] is param:
        return known[0]
    line = _written_line(param, key, raw, quantity, defaulted)
    if len(_WRITTEN) < _WRITTEN_MAX:
        _WRITTEN[memo] = (line, param)
    return line


def _written_line(param: Any, key: str, raw: Any, quantity: Any, defaulted: bool) -> _Written:
    """A given line's text, SI unit, note and the quantity as written (typeset as written,
    for a string), for ``raw`` as the file gives it, read as ``quantity``."""
    if isinstance(raw, str):
        text = " ".join(raw.split())
    elif isinstance(raw, (int, float)) and not isinstance(raw, bool):
        text = f"{raw:g} {units.unit_text(quantity)}".rstrip()  # a bare number as written
    else:
        text = f"{num(quantity.magnitude, 6)} {units.unit_text(quantity)}".rstrip()
    note = ""
    if key == "weight":
        note = "weight"
        if isinstance(raw, str) and set(raw.split()) & {"lb", "lbs", "oz", "pound", "ounce"}:
            note = f"weight: read as {units.unit_text(quantity)}"
    if defaulted:
        text += " (default)"
    shown = units.written(raw) if isinstance(raw, str) else None
    return text, units.si_text(param.dimension), note, shown
