"""A worked answer under construction: sections of steps, answers, warnings.

Kinds write into a Work; reports (text, JSON, ...) read the finished Solution.
Values are SI floats; text is formatted to 4 significant figures here, once.
"""

from __future__ import annotations

from typing import overload

from .expr import SHOWN, SIG, Expr, num
from .expr import formula as tree_formula
from .expr import substitution as tree_substitution
from .prose import Prose
from .prose import text as prose_text
from .record import field, record
from .units import si_text

__all__ = ["SIG", "num", "qty", "vec", "Step", "Section", "Answer", "GivenLine", "Solution",
           "Work"]


def qty(x: float, unit: str) -> str:
    """A number with its unit, for substitutions: ``0.8340 N``."""
    unit = {"kg*m^2": "kg m^2", "N*m": "N m", "kg*m^2/s": "kg m^2/s"}.get(unit, unit)
    return f"{num(x)} {unit}".rstrip()


def vec(components, unit: str) -> str:
    """A vector by components with its unit: ``(0, 1.200, -3.000) N m``."""
    return "(" + ", ".join(num(c) if c else "0" for c in components) + f") {unit}".rstrip()


@record
class Step:
    """One line: ``symbol = formula = substitution = value unit  (ref)``.

    A step with only ``text`` is a line of prose or a bare equation. A step built from an
    expression tree keeps it in ``expr`` (SI); ``formula`` and ``substitution`` are its
    prints. ``--units us`` sets ``view``, the tree with its symbols in US units, and keeps
    the SI value and unit in ``si``.
    """

    symbol: str = ""
    formula: str = ""
    substitution: str = ""
    value: float | None = None
    unit: str = ""
    ref: str = ""
    text: str = ""
    expr: Expr | None = None
    view: Expr | None = None
    si: tuple[float, str] | None = None
    prose: Prose | None = None  # a line (or a step's note) written as words and trees
    symbol_expr: Expr | None = None  # a symbol that is not one name: ``H / c``, ``|F|``

    @property
    def shown(self) -> Expr | None:
        """The tree as printed (in US units under ``--units us``), if the step has one."""
        return self.view if self.view is not None else self.expr

    def as_text(self) -> str:
        if not self.symbol:
            return self.text
        parts = [self.symbol]
        parts += [p for p in (self.formula, self.substitution) if p]
        if self.value is not None:
            parts.append(qty(self.value, self.unit))
        line = " = ".join(parts)
        if self.ref:
            line += f"    ({self.ref})"
        if self.text:
            line += f"    {self.text}"
        return line


# A tree step's formula and substitution are printed from its tree when first read, not
# when the step is made: `gyro check` compares answers and never reads them, and printing
# was a sixth of its time per file. The tree's symbols are not changed after a step is
# made, so the text is the same whenever it is printed.
class _PRINT:
    """A field's value until it is read: print it from the tree (a class, so a copied or
    pickled step still knows it)."""


#: _PRINT where a field typed str is given it: the properties below print it when read,
#: which the checker cannot follow
_LATER: str = _PRINT  # type: ignore[assignment]


def _printed(name: str, printer) -> property:  # type: ignore[no-untyped-def]
    """The field ``name``, printed by ``printer(obj)`` when first read if it was set to
    _PRINT (a tree step's formula, a sentence's text, a title)."""
    slot = "_" + name

    def get(self) -> str:  # type: ignore[no-untyped-def]
        text = self.__dict__[slot]
        if text is _PRINT:
            text = self.__dict__[slot] = printer(self)
        return text

    def set_(self, text: str) -> None:  # type: ignore[no-untyped-def]
        self.__dict__[slot] = text

    return property(get, set_)


Step.formula = _printed("formula", lambda s: tree_formula(s.expr))  # type: ignore[method-assign, assignment]
Step.substitution = _printed("substitution", lambda s: tree_substitution(s.expr))  # type: ignore[method-assign, assignment]
Step.text = _printed("text", lambda s: s.prose.text)  # type: ignore[method-assign, assignment]


def _step_init(self, symbol: str = "", formula: str = "", substitution: str = "",  # type: ignore[no-untyped-def]
               value: float | None = None, unit: str = "", ref: str = "", text: str = "",
               expr: Expr | None = None, view: Expr | None = None,
               si: tuple[float, str] | None = None, prose: Prose | None = None,
               symbol_expr: Expr | None = None) -> None:
    """The dataclass's __init__, storing the printed fields directly rather than through
    their properties' setters (a file's check makes some twenty steps)."""
    self.__dict__.update(symbol=symbol, _formula=formula, _substitution=substitution,
                         value=value, unit=unit, ref=ref, _text=text, expr=expr, view=view,
                         si=si, prose=prose, symbol_expr=symbol_expr)


Step.__init__ = _step_init  # type: ignore[method-assign]


@record
class Section:
    title: str
    steps: list[Step] = field(default_factory=list)
    prose: Prose | None = None  # a title written as words and trees


Section.title = _printed("title", lambda s: s.prose.text)  # type: ignore[method-assign, assignment]


@record
class Answer:
    """An answer in SI: a list of floats (roots ascending) or of words."""

    name: str
    symbol: str
    si_values: list
    dimension: str | None
    labels: list[str] = field(default_factory=list)
    symbol_expr: Expr | None = None  # a symbol that is not one name, as a tree
    # the words that sign its sizes in this problem, where the kind's do not hold (a wheel
    # drop's couple forces lie along the track: no up or down); None: the kind's
    signs: list[tuple[str, int]] | None = None

    @property
    def si_unit(self) -> str | None:
        return si_text(self.dimension) if self.dimension else None


@record
class GivenLine:
    """A given datum as written and in SI, for the report's first table."""

    key: str
    symbol: str
    text: str
    si_value: float | str
    si_unit: str
    note: str = ""
    note_prose: Prose | None = None  # a note written as words and trees
    symbol_expr: Expr | None = None  # a symbol that is not one name, as a tree
    shown: tuple[str, str] | None = None  # the quantity as read: its number and its unit


@record
class Solution:
    given: list[GivenLine]
    sections: list[Section]
    answers: dict[str, Answer]
    warnings: list[str]
    checks: list[Step] = field(default_factory=list)
    system: str = "SI"  # the units of the steps: "SI", or "US" (slug, ft, lbf) on request
    #: the warnings written as words and trees, by their text
    warning_prose: dict[str, Prose] = field(default_factory=dict)


def prose_step(pieces: tuple) -> Step:
    """A line of words only, or of words and trees (`core.prose.Prose`)."""
    if len(pieces) == 1 and isinstance(pieces[0], str):
        return Step(text=pieces[0])
    return Step(text=_LATER, prose=Prose(tuple(pieces)))


class Work:
    """Builder the kinds write into."""

    def __init__(self, overrides: dict[str, float] | None = None) -> None:
        self.given: list[GivenLine] = []
        #: step symbol -> SI value that replaces the first step of that symbol's value
        #: (a student's own value carried forward, checking/ecf.py); None: the solver's
        self.overrides = overrides
        self.overridden: set[str] = set()
        self.sections: list[Section] = []
        self.answers: dict[str, Answer] = {}
        self.warnings: list[str] = []
        self.checks: list[Step] = []
        self.warning_prose: dict[str, Prose] = {}

    def section(self, *pieces: str | Expr) -> Section:
        """Start a section; later steps go into it. Its title is words, or words and trees
        as `text` takes them."""
        if len(pieces) == 1 and isinstance(pieces[0], str):
            self.sections.append(Section(pieces[0]))
        else:  # its title printed when read (gyro check never reads it)
            self.sections.append(Section(_LATER, prose=Prose(tuple(pieces))))
        return self.sections[-1]

    def _current(self) -> Section:
        if not self.sections:
            self.section("Solution")
        return self.sections[-1]

    @overload
    def step(self, symbol: str | Expr, formula: Expr, *, unit: str = "", ref: str = "",
             note: str | tuple[str | Expr, ...] = "", substitute: bool = True,
             state: bool = True) -> float: ...

    @overload
    def step(self, symbol: str | Expr, formula: None = None, *, value: float, unit: str = "",
             ref: str = "", note: str | tuple[str | Expr, ...] = "",
             substitute: bool = True, state: bool = True) -> float: ...

    @overload
    def step(self, symbol: str | Expr, formula: Expr | None = None, *,
             value: float | None = None, unit: str = "", ref: str = "",
             note: str | tuple[str | Expr, ...] = "",
             substitute: bool = True, state: bool = True) -> float | None: ...

    def step(self, symbol: str | Expr, formula: Expr | None = None, *,
             value: float | None = None, unit: str = "", ref: str = "",
             note: str | tuple[str | Expr, ...] = "",
             substitute: bool = True, state: bool = True) -> float | None:
        """Add ``symbol = formula = substitution = value``; returns value.

        ``formula`` is an expression tree (`core.expr`): the formula and the substitution
        are printed from it and the value is its evaluation (``substitute=False`` shows
        no substitution, ``state=False`` no formula: the symbol is the formula). A unit
        of `expr.SHOWN` (``deg``, ``arcsec/yr``, ``yr``) shows the SI value converted, and
        returns it converted. Without a tree the step shows its value only (a root found
        numerically, a value read from physics): ``work.step("k", value=k, unit="1/s^2")``.
        A formula is never text: every format prints it from the tree.
        """
        symbol_expr = None
        if isinstance(symbol, Expr):  # a symbol that is not one name: H / c, |F|, K(m)
            symbol_expr, symbol = symbol, prose_text(symbol)
        prose = None
        if isinstance(note, tuple):  # a note of words and trees, as `text` takes them
            prose = Prose(note)
            note = _LATER  # printed when read
        if formula is not None:
            if not isinstance(formula, Expr):
                raise TypeError(f"the step {symbol}: a formula is a tree (core.expr), not "
                                f"{type(formula).__name__}")
            if value is not None:
                raise TypeError("a step built from a tree takes its value from the tree")
            tree = formula
            try:
                value = tree.value
            except (ZeroDivisionError, OverflowError, ValueError) as err:
                from .errors import InputError

                raise InputError(f"the step {symbol} = {tree_formula(tree)} cannot be evaluated "
                                 f"for these data ({err}): a degenerate case, or magnitudes "
                                 "beyond double precision; check the data and units",
                                 key="given") from None
            if self.overrides is not None:
                value = self._override(symbol, value)
            si = None
            if unit in SHOWN:
                si = (value, SHOWN[unit][1])
                value = value / SHOWN[unit][0]
            self._current().steps.append(Step(
                symbol, _LATER if state else "", _LATER if substitute else "", value, unit,
                ref, note, expr=tree, si=si, prose=prose, symbol_expr=symbol_expr))
            return value
        if self.overrides is not None and value is not None:
            factor = SHOWN[unit][0] if unit in SHOWN else 1.0
            value = self._override(symbol, value * factor) / factor
        self._current().steps.append(Step(symbol, "", "", value, unit, ref, note,
                                          prose=prose, symbol_expr=symbol_expr))
        return value

    def _override(self, symbol: str, si: float) -> float:
        """The SI value of the step ``symbol``: the override for its first step, if any
        (the kind then works on from it, as a student who carried it would)."""
        assert self.overrides is not None
        if symbol in self.overrides and symbol not in self.overridden:
            self.overridden.add(symbol)
            return self.overrides[symbol]
        self.overridden.add(symbol)
        return si

    def text(self, *pieces: str | Expr) -> None:
        """Add a line of prose to the current section: words (strings) and maths (trees,
        `core.prose`), printed by every format from the trees."""
        self._current().steps.append(prose_step(pieces))

    def check(self, *pieces: str | Expr) -> None:
        """An independent check of the answer (a residual, a balance), as `text` writes
        a line."""
        self.checks.append(prose_step(pieces))

    def answer(self, name: str, symbol: str | Expr, si_values: list, dimension: str | None,
               labels: list[str] | None = None,
               signs: list[tuple[str, int]] | None = None) -> None:
        """An answer; its symbol is one name (``phidot``) or a tree (``abs(F)``).
        ``signs``: the words that sign its sizes here, where the kind's do not hold."""
        tree: Expr | None = None
        if isinstance(symbol, Expr):
            tree, text = symbol, prose_text(symbol)
        else:
            text = symbol
        self.answers[name] = Answer(name, text, list(si_values), dimension, list(labels or []),
                                    symbol_expr=tree, signs=signs)

    def warn(self, *pieces: str | Expr) -> None:
        """A warning: words, or words and trees as `text` takes them."""
        step = prose_step(pieces)
        if step.text not in self.warnings:
            self.warnings.append(step.text)
            if step.prose is not None:
                self.warning_prose[step.text] = step.prose

    def solution(self) -> Solution:
        return Solution(self.given, self.sections, self.answers, self.warnings, self.checks,
                        warning_prose=self.warning_prose)
